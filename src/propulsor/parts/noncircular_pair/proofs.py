"""The non-circular pair's proofs: the full cycle on the finished outlines (:mod:`.pair_proof`),
the other tooth method for comparison, and the checks of closure, generability, teeth and mesh."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ... import policy
from ...check import Check
from ...errors import InputError
from ...gears.noncircular import PitchCurves
from ...laws.law import is_walking
from ...laws.walking import LEG_PERIOD
from .design import Design, PairDesign, design_generated, design_sectors
from .params import NoncircularPairParams

__all__ = ["prove", "compare", "checks_generated", "checks_common", "checks_sectors", "proofs", "other_method"]


def prove(d: Design, phases_per_tooth: int, legs: int = 4, progress=lambda s: None, mount: float | None = None,
          on_jam=None):
    """Proof of the pair over ``legs`` legs (4 = the whole driven turn) with
    ``phases_per_tooth`` phases per driven tooth (:mod:`.pair_proof`), the gears at the
    installed centre distance ``mount`` (default the design L); ``on_jam()``: called at the first phase found
    jammed (``prove_pair``'s).  Generated teeth over the whole turn: the first of the law's periods measured where
    both outlines repeat under its turns (``prove_pair``'s ``periods``: the wheels cut as one lobe and patterned)."""
    from .pair_proof import prove_pair

    N = phases_per_tooth * d.z_H * legs // 4
    phis = np.arange(N) * (legs * LEG_PERIOD / N)
    pc = PitchCurves(d.run_law, d.L)
    pitch = math.pi * d.m if d.method == "generated" else d.table.arc
    from ...progress import counter

    if is_walking(d.law):
        span = f"{legs} leg(s)"
    else:
        span = "the whole driven turn" if legs == 4 else f"{legs}/4 of the driven turn"
    phase = f"{d.method}: proof over {span}"
    progress(f"{phase}, {N} phases")
    from .as_built import period_span

    # the pair's period, as the as-built contact takes it (the law's, where its arc holds whole driven teeth)
    periods = round(2 * math.pi / period_span(d)) if d.method == "generated" and legs == 4 else 1
    return prove_pair(d.driver.profile, d.driven.profile, mount or d.L, d.run_law.theta, phis, pc.r_H,
                      name="mesh", pitch_mm=pitch, tick=counter(progress, phase, N, "phase"), on_jam=on_jam,
                      periods=periods)


def _other(d: Design) -> str:
    """The tooth method the comparison makes (the one `d` was not made by)."""
    return "sectors" if d.method == "generated" else "generated"


def compare(p: NoncircularPairParams, d: Design, prog=lambda s: None):
    """The other tooth method for the same law, module and teeth, proved over one leg (the pair
    repeats per leg) at its own design centre distance.  Returns (design, proof, note); (None,
    None, why) if it cannot be made."""
    alt = _other(d)
    if not is_walking(d.law):
        return None, None, f"The sector method exists for the walking law only (this pair's law: {d.law.kind})."
    try:
        q = dataclasses.replace(p, method=alt, module_mm=d.m, center_distance_mm=0.0)
        q.validate()
        other = design_sectors(q, prog) if alt == "sectors" else design_generated(q, prog)
        return other, prove(other, p.proof_phases_per_tooth, 1, prog), ""
    except InputError as exc:
        return None, None, f"The {alt} method is not possible for these parameters: {exc}"


def checks_generated(d: Design, pr, p) -> list[Check]:
    sm = d.smoothing
    g = sm.generability
    out = [
        Check.at_most("law.closure_error", d.closure_error, 1e-9, "rad",
                      f"|theta(2 pi) - 2 pi n| = {d.closure_error:.3g} rad: the driver makes exactly n = {d.law.n} turns"),
        Check.at_most("teeth.closure_error", abs(d.pc.perimeter_driven() - d.z_H * math.pi * d.m), 1e-9, "mm",
                      f"driven pitch perimeter vs z_H pi m = {d.z_H} x {math.pi * d.m:.6f} mm"),
        Check.at_least("generability.driver_rho_min", g.driver.rho_convex_min, g.driver.rho_limit, "mm",
                       f"driver convex rho_min {g.driver.rho_convex_min:.4f} mm vs rack undercut limit "
                       f"(h_a* - x) m / sin^2 alpha = {g.driver.rho_limit:.4f} mm"),
        Check.at_least("generability.driven_rho_min", g.driven.rho_convex_min, g.driven.rho_limit, "mm",
                       f"driven convex rho_min {g.driven.rho_convex_min:.4f} mm vs limit {g.driven.rho_limit:.4f} mm"),
    ]
    for chk in (g.driver, g.driven):
        if chk.concave:
            out.append(Check.greater_than(f"generability.{chk.curve}_concave_rho", chk.rho_concave_min, chk.r0, "mm",
                                          f"{chk.curve} concave |rho|_min {chk.rho_concave_min:.4f} mm vs shaper pitch "
                                          f"radius r0 = {chk.r0:.3f} mm" + (" (r0 + cutting offset e of the catalogue "
                                          "shaper's own x0)" if d.shaper is not None else "")))
    for gear in (d.driver, d.driven):
        out.append(Check.at_most(f"teeth.{gear.role}_undercut", gear.undercut_teeth, 0, "teeth",
                                 f"{gear.undercut_teeth} of {len(gear.teeth)} {gear.role} teeth undercut"))
        out.append(Check.at_least(f"teeth.{gear.role}_tip_land", gear.tip_thickness_min, p.tip_land_min_module * d.m - 1e-9,
                                  "mm", f"least tip land {gear.tip_thickness_min:.4f} mm; {gear.shortened_teeth} teeth "
                                        f"tip-shortened, {gear.shaper_teeth} cut by the shaper z0 = "
                                        f"{p.shaper_teeth if d.shaper is None else d.shaper.z0}"))
    s = pr.summary()
    tol = policy.OVERLAP_AREA_TOL_MM2
    out.append(Check.at_most("mesh.overlap_area", s["overlap_law_max_mm2"], tol, "mm^2",
                             f"max overlap {s['overlap_law_max_mm2']:.3g} mm^2 over {s['steps']} phases at the law's positions"))
    return out + checks_common(pr)


def checks_common(pr, prefix: str = "mesh") -> list[Check]:
    """Proof checks; ``prefix`` 'mesh' for generated teeth, 'sectors' for the papers' teeth (separate
    names, so that a part file can document the papers' jams as expected failures without masking
    a failure of generated teeth)."""
    s = pr.summary()
    return [
        Check.at_most(f"{prefix}.runs_without_jam", s["jams"], 0, "phases",
                      f"{s['jams']} of {s['steps']} phases have no free position of the driven wheel "
                      f"(least overlap up to {float(np.max(pr.least_overlap)):.4g} mm^2)"),
        Check.greater_than(f"{prefix}.backlash_min", s["backlash_min_mm"], 0.0, "mm",
                           f"backlash {s['backlash_min_mm']:.5f} .. {s['backlash_max_mm']:.5f} mm on the driven pitch curve "
                           f"at the proof's {s['steps']} phases (the least as built, between them too: the derived "
                           f"backlash_min_mm)"),
        Check.at_least(f"{prefix}.contact_continuity", s["contact_pairs_min"], 1, "pairs",
                       f"least tooth pairs in contact {s['contact_pairs_min']}, mean {s['contact_pairs_mean']:.4f}"),
    ]


def checks_sectors(d: Design, pr) -> list[Check]:
    return [Check.at_most("law.closure_error", d.closure_error, 1e-9, "rad",
                          f"|4 sum dtheta - 2 pi n| = {d.closure_error:.3g} rad (sector table, seed 000 eqs. 48-51)")] \
        + checks_common(pr, "sectors")



def _counted(job, tick, k: int):
    """`job` as it is; `tick(k)` when it is already done (run in this process: no worker was free)."""
    from ...parallel import Done

    if isinstance(job, Done):
        tick(k)
    return job


def proofs(dd: PairDesign, w, built: dict) -> None:
    """The built pair over the whole cycle, and its as-built contact started in workers (before the solids are
    made: the contact is the build's longest job, the solids' files run beside the rest).  Each direction whose worker
    may be forked now starts before the whole-cycle proof, which runs meanwhile here (a core would otherwise wait while
    it runs: the Fourier pair's build, 0.5-0.9 s); the proof drops them as it meets the first jammed phase (no
    transmission as built), and the other method's comparison (``compare_methods``) takes the worker so freed.  Where
    no worker is free, each direction runs here after the proof, as its start."""
    from ...parallel import abandon, start
    from ...progress import count_shared, counter
    from ...checks.motion.contact_events import DRIVE, REVERSE
    from .as_built import contact_direction
    from .pair_proof import _outer_only
    from .tooth_load_outputs import contact_and_load

    p, d, prog = dd.p, dd.d, w.progress
    # the two directions beside each other and beside the other method's proof; their sampled positions counted.
    # With a load case the drive direction's job goes on to the load per tooth on its contact
    # (tooth_load_outputs.contact_and_load)
    counts = count_shared(prog, "as built: contact in both directions", 2, "position")

    def direction(way, count, forked_only: bool):
        if way == DRIVE and p.load_given:
            return start(contact_and_load, d, dd.mount, way, p, counter=count, forked_only=forked_only)
        return start(contact_direction, d, dd.mount, way, counter=count, forked_only=forked_only)

    # the outer loops sampled once, here, at the tolerance the proof and the contact read them at: a job's design is
    # pickled as it starts, with its splines' samples (a job started before them samples both wheels again)
    _outer_only(d.driver.profile), _outer_only(d.driven.profile)
    ahead = [direction(way, count, True) for way, count in zip((DRIVE, REVERSE), counts)]

    def stop_ahead():
        # a jammed phase: no transmission as built (below), so the contact started ahead stops at once, not after the
        # whole proof (the sector tables' pairs, whose papers' teeth jam: 8-9 CPU s of contact thrown away each); the
        # other method's comparison takes a worker thus freed, beside the rest of the proof (other_method collects it)
        for job in ahead:
            abandon(job)
        if p.compare_methods:
            job = start(compare, p, d, forked_only=True)
            if job is not None:
                prog(f"{_other(d)}: the other tooth method over one leg, for comparison, in a second process beside "
                     f"the proof")
                built["other_job"] = job

    built["proof"] = prove(d, p.proof_phases_per_tooth, 4, prog, dd.mount, on_jam=stop_ahead)
    pr = built["proof"]
    if pr.jams or not np.all(np.isfinite(pr.phi_drive)):
        for job in ahead:
            abandon(job)
        built["as_built"] = ()  # no running position: no transmission as built
    else:
        prog("as built: both directions' contact on the finished outlines, resolved by contact events")
        built["as_built"] = tuple(job if job is not None else direction(way, count, False)
                                  for job, way, count in zip(ahead, (DRIVE, REVERSE), counts))
        if p.tolerance_grade:
            from .tolerance import iso1328, monte_carlo_cases, run_case, worst_cases

            tol = iso1328(d, dd.mount, p.tolerance_grade, math.radians(p.pressure_angle_deg))
            prog(f"as made: {4 + p.tolerance_samples} cases within {tol.source}")
            cases = worst_cases(tol) + monte_carlo_cases(tol, p.tolerance_samples, p.tolerance_seed)
            tick = counter(prog, "as made: tolerance cases", len(cases), "case")
            built["tolerance"] = (tol, [_counted(start(run_case, d, dd.mount, c), tick, k + 1)
                                        for k, c in enumerate(cases)])


def other_method(dd: PairDesign, w, built: dict) -> None:
    """The other tooth method over one leg when the part file asks for it (after the solids are handed to the
    writer: their files and checks run beside it), or its result where :func:`proofs` started it in a worker (a
    jammed pair's: beside the rest of the whole-cycle proof)."""
    from ...parallel import result

    p = dd.p
    job = built.pop("other_job", None)
    if job is not None:
        built["other"] = result(job)
    else:
        built["other"] = compare(p, dd.d, w.progress) if p.compare_methods else (None, None, "")
