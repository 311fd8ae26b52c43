"""One variant of a study, evaluated where it runs (a Dask worker, or inline): a row of plain values.

Depths: ``design`` computes the part's design and the output steps that need no solid (derived values
and checks from the same code as a build, so the same numbers); ``proof`` adds the full-cycle proofs:
the design and the part type's proof steps (:attr:`propulsor.Part.proof_run`: their checks and derived
values, no solid and no file; a part type that declares none runs its whole build into a temporary
folder and keeps no file); ``build`` writes the variant's files (``propulsor build``'s) into a folder of
the study (one build: the values read from the build written).  The design is computed once and reused by
the proof (the part's design cache).  Only the row travels back: the arrays stay here.  At proof depth a
switch that only adds values the study does not read is off (:data:`ONLY_WHEN_READ`: the noncircular pair's
comparison with the other tooth method runs when an objective, constraint or report names a ``compare_`` value).
"""

from __future__ import annotations

import math
import os
import socket
import time
from contextlib import contextmanager
from functools import cached_property
from pathlib import Path

from ..errors import CheckFailed, InputError

#: part type -> the output steps (by name) that make derived values and checks from the design alone
DESIGN_STEPS = {
    "planetary_final_drive": ("sheet_and_conditions", "strength", "fatigue", "traction", "outline_checks"),
    "road_wheel": ("kozlov_proof",),
    "cam_mover": ("law_and_derived",),
}


#: part type -> (parameter, prefix): a switch that only adds derived values named with that prefix (and no check);
#: a proof-depth variant runs it only when the study reads one of them (the noncircular pair's comparison with the
#: other tooth method: a second design and proof, 3.5 CPU s of the seed-002 pair's 10)
ONLY_WHEN_READ = {
    "noncircular_pair": ("compare_methods", "compare_"),
}


def asked(part_type: str, params, depth: str, wanted) -> object:
    """`params` with the switches of :data:`ONLY_WHEN_READ` off at proof depth when no value the study reads
    comes from them (at build depth the files are the part file's, comparison included)."""
    import dataclasses

    rule = ONLY_WHEN_READ.get(part_type)
    if rule is None or depth != "proof" or not getattr(params, rule[0]):
        return params
    if any(str(n).startswith(rule[1]) for n in wanted):
        return params
    return dataclasses.replace(params, **{rule[0]: False})


def _plain(v):
    """A table cell: numbers, booleans and short text; anything else as its text."""
    if v is None or isinstance(v, (bool, int, str)):
        return v
    if isinstance(v, float):
        return v
    try:
        import numpy as np

        if isinstance(v, np.generic):
            return v.item()
    except ImportError:  # pragma: no cover
        pass
    return str(v)


def _smooth_law_design_values(part) -> tuple[dict, list]:
    """The design-only derived values of a pair whose law has no hub (elliptical, Fourier, table, pitch
    curve): the build's own (parts/noncircular_pair/law_outputs.py, law_design_values)."""
    from ..parts.noncircular_pair.law_outputs import law_design_values

    return law_design_values(part.design), []


def _noncircular_design_values(part) -> tuple[dict, list]:
    """The noncircular pair's derived values that come from its design alone (the build's names and
    expressions: parts/noncircular_pair/outputs.py, checks_and_derived; a law without a hub:
    :func:`_smooth_law_design_values`)."""
    from ..laws.law import is_walking

    dd = part.design
    d = dd.d
    if not is_walking(d.law):
        return _smooth_law_design_values(part)
    out = {"center_distance_mm": d.L, "mounting_distance_mm": dd.mount, "module_mm": d.m, "driver_teeth": d.z,
           "driven_teeth": d.z_H, "driver_turns": d.law.n, "method": d.method, "smoothing_deg": d.smoothing_deg,
           "speed_ripple": d.ripple.ripple, "speed_ripple_phi_min_deg": math.degrees(d.ripple.phi_min),
           "speed_ripple_phi_max_deg": math.degrees(d.ripple.phi_max), "hub_height_mm": d.law.A, "u": d.law.u,
           "hub_speed_mean_mm_per_rad": d.law.hub_speed_ratio, "closure_error_rad": d.closure_error}
    if d.method == "generated":
        g = d.smoothing.generability
        out.update({"smoothing_rad": d.smoothing.delta,
                    "driver_rho_min_mm": g.driver.rho_convex_min, "driver_rho_limit_mm": g.driver.rho_limit,
                    "driven_rho_min_mm": g.driven.rho_convex_min, "driven_rho_limit_mm": g.driven.rho_limit,
                    "driven_concave_rho_min_mm": g.driven.rho_concave_min, "shaper_r0_mm": g.driven.r0,
                    "tip_shortened_teeth": d.driver.shortened_teeth + d.driven.shortened_teeth,
                    "shaper_cut_teeth": d.driver.shaper_teeth + d.driven.shaper_teeth,
                    "undercut_teeth": d.driver.undercut_teeth + d.driven.undercut_teeth})
        if d.shaper is not None:
            out.update({"shaper_d0_mm": d.shaper.d0_mm, "shaper_z0": d.shaper.z0, "shaper_x0": d.shaper.x0})
    return out, []


def design_values(part) -> tuple[dict, list]:
    """(derived values, checks) of the part's design and of its output steps that need no solid."""
    if part.type == "noncircular_pair":
        return _noncircular_design_values(part)
    design = part.design
    names = DESIGN_STEPS.get(part.type, ())
    if not names:
        return {}, []
    from ..parts.proof_writer import ProofWriter

    steps = {getattr(s, "__name__", ""): s for s in part._pt.build.steps}
    w = ProofWriter(part.type, part.params, source=part.source)  # values only: no file, no folder
    try:
        built: dict = {}
        for name in names:
            steps[name](design, w, built)
    finally:
        w.close()
    return dict(w.derived), list(w.checks)


class Variant:
    """One variant as the build service knows it (``building.Loaded``): its design, proofs and build computed
    once each, by the service's own functions (``building.design``, ``prove``, ``build_in_memory``, ``build``)."""

    def __init__(self, part_type, params, source: Path | None = None):
        from ..building import Loaded

        self.type = part_type.name
        self._pt = part_type
        self.params = params
        self.source = source
        self.loaded = Loaded(part_type, params, source)

    @cached_property
    def design(self):
        from ..building import design

        return design(self.loaded)

    @cached_property
    def build(self):
        """The build's result (``building.BuildResult``): in memory, or the one :meth:`write` put in place."""
        from ..building import build_in_memory

        return build_in_memory(self.loaded)

    @cached_property
    def proof_run(self):
        """The design's and the proofs' checks and values (no solid, no file); the whole build where the part
        type declares no proof steps."""
        from ..building import ProofResult, prove, proves_alone

        if not proves_alone(self.loaded):
            b = self.build
            return ProofResult(b.failures, b.checks, b.derived, True)
        return prove(self.loaded)

    def write(self, out) -> None:
        """Build into `out` (``propulsor build``'s files and rules, a failed check kept); its result is the build."""
        from ..building import build

        try:
            self.__dict__["build"] = build(self.loaded, out, keep_failed=True)
        except CheckFailed as exc:
            self.__dict__["build"] = exc.result


def _failures(checks, expected) -> list[str]:
    return [c.name for c in checks if not c.passed and c.name not in expected]


def _may_fork() -> None:
    """A build (and a design) forks its own workers (solids' files and checks, proofs, teeth), which a daemonic process
    may not do; a Dask worker under a nanny is one unless started with DASK_DISTRIBUTED__WORKER__DAEMON=False.
    Those workers die with it (parallel.py: PR_SET_PDEATHSIG), so the flag is lifted for this process."""
    import multiprocessing

    proc = multiprocessing.current_process()
    if proc.daemon:
        proc._config["daemon"] = False


@contextmanager
def one_process():
    """The variant on one core: the build's own forked workers and OCCT's mesh threads off (a budget of
    one process, PROPULSOR_JOBS=1: the same values, computed inline), so that the cluster's workers — one
    thread each, one per core — fill the cores, not a variant's helpers competing with the next variant."""
    saved = os.environ.get("PROPULSOR_JOBS")
    os.environ["PROPULSOR_JOBS"] = "1"
    try:
        yield
    finally:
        if saved is None:
            os.environ.pop("PROPULSOR_JOBS", None)
        else:
            os.environ["PROPULSOR_JOBS"] = saved


def evaluate(part_type: str, base: dict, source: str | None, values: dict, depth: str, wanted: tuple,
             build_dir: str | None = None) -> dict:
    """The row of one variant: {"values": {name: value}, "all_checks_passed", "failed_checks", "status",
    "reason", "seconds", "worker"}.  Never raises for the variant's own trouble (bad values, a failed
    check, an exception of the build): the row says it.  Runs on one core (:func:`one_process`)."""
    with one_process():
        return _evaluate(part_type, base, source, values, depth, wanted, build_dir)


def _evaluate(part_type, base, source, values, depth, wanted, build_dir) -> dict:
    from ..params import load_params
    from ..parts import get_part_type

    t0 = time.perf_counter()
    row = {"values": {}, "all_checks_passed": None, "failed_checks": "", "status": "ok", "reason": "",
           "worker": f"{socket.gethostname()}:{os.getpid()}"}
    _may_fork()  # before the design: a design may fork too (the non-circular teeth)
    pt = None
    try:
        pt = get_part_type(part_type)
        params = asked(part_type, load_params(pt.params_cls, {**base, **values}), depth, wanted)
        part = Variant(pt, params, Path(source) if source else None)
        part.design  # computed once; the proof below reuses it
        if depth == "design":
            derived, checks = design_values(part)
        elif depth == "proof":
            run = part.proof_run  # the design's and the proofs' checks and values; no solid, no file
            derived, checks = run.derived, list(run.checks)
        else:
            if depth == "build" and build_dir:
                part.write(build_dir)  # a folder only a build wrote is replaced; a failed check is kept
            derived, checks = part.build.derived, list(part.build.checks)
        expected = set()
        if source:
            from ..params import read_part_meta

            if Path(source).is_file():
                expected = set(read_part_meta(source).get("expected_failures", []))
        failed = _failures(checks, expected)
        row["all_checks_passed"] = (not failed) if checks else None  # no check ran: not vacuously true
        row["failed_checks"] = "; ".join(failed)
        row["values"] = {n: _plain(derived[n]) for n in wanted if n in derived}
        missing = [n for n in wanted if n not in derived]
        if missing:
            row["status"] = "error"
            row["reason"] = f"{missing[0]}: not computed at depth {depth} for this variant" + (
                " (a deeper depth may compute it)" if depth != "build" else "")
    except InputError as exc:
        if pt is not None:  # a value the study's files never write is the part type's default: said, as the dry run
            from ..building import default_named

            exc = default_named(exc, {**base, **values}, pt.params_cls)
        row["status"], row["reason"] = "input error", str(exc)
    except Exception as exc:  # the variant's own failure is a row, never the end of the study
        row["status"], row["reason"] = "error", f"{type(exc).__name__}: {exc}"
    row["seconds"] = time.perf_counter() - t0
    return row
