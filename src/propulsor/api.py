"""The Python interface of propulsor: a part from its type or a part file, its design, its solids, its
proofs and its files — the same work and the same bytes as the command line.

    import propulsor

    gear = propulsor.part("noncircular_pair", module_mm=2.5, driven_teeth=80)   # defaults: seed 002
    gear = propulsor.part("parts/ncg_seed002.toml", face_width_mm=15.0)       # a part file, overridden
    gear.params.module_mm            # validated, frozen parameters (mm, rad inside)
    gear.design                      # computed once, frozen: what the build makes its geometry from
    gear.solids["driven"]            # cadquery Shapes (the design and the solid steps: no file; else the build)
    gear.assembly()                  # cq.Assembly with named, placed, coloured components
    gear.profiles["driven"]          # the DXF outlines as (N, 2) arrays in mm
    [c for c in gear.prove() if not c.passed]   # every check of the build (value, limit, pass/fail)
    gear.prove(depth="proof")        # the design's and the full-cycle proofs' checks only: no solid, no file
    gear.values.center_distance_mm   # the derived values of the proofs, with units: gear.values.unit("...")
    gear.write("out/gear")           # exactly the files `propulsor build` writes (the build made above, copied)
    gear.kit(printer="prusa_mk4")    # the print kit: pieces at print scale, rig, plates (not written)

Bad values raise :class:`~propulsor.errors.InputError` naming the key, the value and the limit — in
whatever way the parameters are made (keyword, part file, dict, the dataclass itself, ``replace``).
"""

from __future__ import annotations

import dataclasses
import html
import os
from collections.abc import Iterator, Mapping
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from .building import ProofResult as Proof  # what the design and the full-cycle proofs gave
from .building import as_path
from .errors import CheckFailed, InputError
from .solids.cq_import import import_cadquery

__all__ = ["Part", "Build", "Proof", "Values", "part", "part_types", "parameters", "as_path"]


def _shown(v: Any) -> str:
    """A value as the tables show it: a float to 6 significant digits, anything else as repr (cut at 60)."""
    if isinstance(v, float):
        return f"{v:.6g}"
    text = repr(v)
    return text if len(text) <= 60 else text[:57] + "..."


class Values(Mapping[str, Any]):
    """The derived values of a run, read-only: ``values["center_distance_mm"]`` or
    ``values.center_distance_mm`` (the value as the manifest gives it: a float, or a dict / list for nested
    ones), ``values.unit(name)`` and ``values.meaning(name)`` from the glossary the build's manifest carries
    (a nested value by its path: ``"sigma_MPa.stop"``).  ``depth`` names the run: ``"proof"`` (the design and
    the full-cycle proofs) or ``"build"`` (a whole build: also the solids' volumes and every output step's
    values).  Printed, a table of name, value and unit; in Jupyter, an HTML table with the meanings."""

    __slots__ = ("_values", "_glossary", "depth")

    def __init__(self, values: Mapping[str, Any], glossary: Mapping[str, tuple[str, str]], depth: str):
        import copy
        import types

        object.__setattr__(self, "_values", types.MappingProxyType(copy.deepcopy(dict(values))))
        object.__setattr__(self, "_glossary", types.MappingProxyType(dict(glossary)))
        object.__setattr__(self, "depth", depth)

    def __getitem__(self, name: str) -> Any:
        return self._values[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(f"no derived value {name!r} at depth {self.depth} (see list(values))") from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("derived values are read-only")

    def __dir__(self) -> list[str]:
        return sorted(set(super().__dir__()) | {k for k in self._values if k.isidentifier()})

    def _entry(self, name: str) -> tuple[str, str]:
        if name not in self._glossary:
            raise KeyError(f"no derived value {name!r} at depth {self.depth}")
        return self._glossary[name]

    def unit(self, name: str) -> str:
        """The unit of derived value `name` (a path for a nested one); "" for a pure number."""
        return self._entry(name)[0]

    def meaning(self, name: str) -> str:
        """What derived value `name` (a path for a nested one) is, in words."""
        return self._entry(name)[1]

    def _rows(self) -> list[tuple[str, str, str, str]]:
        return [(k, _shown(v), *self._glossary.get(k, ("", ""))) for k, v in self._values.items()]

    def __repr__(self) -> str:
        rows = self._rows()
        w0 = max((len(r[0]) for r in rows), default=0)
        w1 = max((len(r[1]) for r in rows), default=0)
        lines = [f"<propulsor.Values: {len(rows)} derived values, depth {self.depth}>"]
        lines += [f"  {k:<{w0}}  {v:>{w1}}  {u}".rstrip() for k, v, u, _ in rows]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        e = html.escape
        body = "".join(f"<tr><td><code>{e(k)}</code></td><td style=\"text-align:right\">{e(v)}</td><td>{e(u)}</td>"
                       f"<td>{e(m)}</td></tr>" for k, v, u, m in self._rows())
        return (f"<table><caption>{len(self)} derived values (depth {e(self.depth)})</caption>"
                f"<thead><tr><th>name</th><th>value</th><th>unit</th><th>meaning</th></tr></thead>"
                f"<tbody>{body}</tbody></table>")


def part_types() -> list[str]:
    """The names of the part types (``noncircular_pair``, ``planetary_final_drive`` …)."""
    from .parts import part_type_names

    return part_type_names()


def parameters(part_type: str, /, **values: Any):
    """The validated, frozen parameters of `part_type` with `values` in place of the defaults (the same
    checks as a part file: types, limits, the rules between parameters).  InputError otherwise."""
    from .params import load_params
    from .parts import get_part_type, vet

    pt = get_part_type(part_type)
    params = load_params(pt.params_cls, values, validate=False, type_name=pt.name)
    vet(pt, params)
    return params


def part(source: "str | bytes | os.PathLike[str]", /, **overrides: Any) -> "Part":
    """A part from a part type name (its defaults) or a part file (``*.toml``), with `overrides` in place of
    the values there.  The parameters are validated at once (InputError naming the key)."""
    from .params import load_params, read_part_file
    from .parts import get_part_type, part_type_names, vet

    if isinstance(source, str) and source in part_type_names():
        return Part(source, parameters(source, **overrides), None)
    path = as_path(source, "source")
    if path.suffix != ".toml" and not path.exists():
        raise InputError("source", str(source), f"must be a part type ({', '.join(part_type_names())}) or a part "
                         "file (.toml)")
    type_name, mapping = read_part_file(path)
    pt = get_part_type(type_name)
    params = load_params(pt.params_cls, {**mapping, **overrides}, validate=False, type_name=pt.name)
    vet(pt, params, path)
    return Part(type_name, params, path)


@dataclasses.dataclass(frozen=True)
class Build:
    """What one real build of a part made (in memory; its files went to a temporary folder)."""

    failures: tuple[str, ...]  # unexpected failed checks, "name: message"
    checks: tuple  # every Check of the build, in order
    derived: dict  # every derived value the report and the manifest give
    solids: dict  # name -> cadquery Shape
    profiles: dict  # DXF name -> list of Profile (geometry.profile)
    assemblies: dict  # name -> [(component, solid, (x, y, z) mm, rotation about z rad)]
    glossary: dict = dataclasses.field(default_factory=dict)  # derived value's path -> (unit, meaning)
    #: the build service's result, with the build's files while they are kept (``building.KeptFiles``)
    result: Any = dataclasses.field(default=None, repr=False, compare=False)

    @classmethod
    def of(cls, result) -> "Build":
        """The in-memory side of the build service's result (``building.BuildResult``)."""
        return cls(tuple(result.failures), tuple(result.checks), dict(result.derived), dict(result.solids),
                   dict(result.profiles), dict(result.assemblies), dict(result.glossary), result)

    @property
    def values(self) -> Values:
        """The build's derived values with their units (:class:`Values`, depth ``"build"``)."""
        return Values(self.derived, self.glossary, "build")


class Part:
    """A part: its type, validated parameters and the part file they came from (None for a type's
    defaults).  The design is computed on first use and kept; the solids, profiles and proofs come from
    one real build (the build ``propulsor build`` runs, into a private temporary folder), run on first use
    (or the build :meth:`write` made) and kept with its files: :meth:`write` then copies them into its folder
    instead of building again;
    :attr:`proof_run` is the design and its proofs alone (no solid, no file), where the part type declares them,
    and :attr:`values` their derived values.  In Jupyter a part shows its 3D view (:meth:`_repr_html_`)."""

    def __init__(self, part_type: str, params, source: Path | None = None):
        from .parts import get_part_type

        self.type: str = part_type
        self.params = params
        self.source: Path | None = source
        self._pt = get_part_type(part_type)
        if not isinstance(params, self._pt.params_cls):
            raise InputError("params", type(params).__name__, f"must be {self._pt.params_cls.__name__}")
        from .building import Loaded

        self._loaded = Loaded(self._pt, params, source)  # what the build service builds
        #: a callback told the steps of the work this part starts (its design, proofs, build, solids): ``print``, or
        #: any callable taking a :class:`propulsor.progress.Event`; None (default): nothing is said
        self.progress = None

    def __repr__(self) -> str:
        where = f" from {self.source}" if self.source else ""
        return f"<propulsor.Part {self.type}{where}>"

    def _repr_html_(self) -> str:
        """The part in Jupyter: its name, its build's status and its 3D view — the gallery's viewer with the
        GLB of each assembly the build wrote and the vendored three.js inlined (no network; 0.7 MB of script
        and the GLB in base64: 4 MB for parts/ncg_elliptical.toml), in a sandboxed ``<iframe srcdoc>`` — then
        the key values.  Runs the build on first use (:attr:`build`; :meth:`write` then reuses it).  Every text from the part file is escaped."""
        from .export.html import view_page

        e = html.escape
        b = self.build
        status = (f"{len(b.failures)} check(s) failed: " + "; ".join(b.failures)) if b.failures else \
            f"all {len(b.checks)} checks passed"
        lead = f"<p><b>{e(self.type)}</b>{' — ' + e(str(self.source)) if self.source else ''}: {e(status)}</p>"
        folder = b.result.files.folder if b.result is not None and b.result.files is not None else \
            (b.result.out if b.result is not None else None)
        try:
            doc = view_page(folder) if folder is not None else None
        except (OSError, ValueError):  # a written folder changed since (the kept one is private)
            doc = None
        view = (f'<iframe title="{e(self.type)}" sandbox="allow-scripts" style="width: 100%; height: 640px; '
                f'border: 0" srcdoc="{e(doc, quote=True)}"></iframe>') if doc else \
            '<p>(no 3D view: no assembly of this build to show)</p>'
        from .parts import key_values_of

        keys = [k for k in key_values_of(self.type) if k in b.derived] or list(b.derived)
        table = Values({k: b.derived[k] for k in keys}, b.glossary, "build")._repr_html_()
        return f'<div class="propulsor-part">{lead}{view}{table}</div>'

    @cached_property
    def design(self):
        """The part's design (frozen), computed once: what the build makes its geometry from."""
        from .building import design

        return design(self._loaded, progress=self.progress)

    @cached_property
    def build(self) -> Build:
        """One real build of the part, run once: its files are written to a private temporary folder and
        kept there for :meth:`write` (removed with the part, or at exit)."""
        from .building import build_in_memory

        return Build.of(build_in_memory(self._loaded, progress=self.progress, keep_files=True))

    @property
    def values(self) -> Values:
        """The derived values of :attr:`proof_run` with their units and meanings (:class:`Values`):
        ``gear.values.center_distance_mm``, ``gear.values.unit("center_distance_mm")``.  Depth ``"proof"``
        (the design and the full-cycle proofs, no solid) where the part type declares proof steps, else
        ``"build"`` (its whole build's); the values a whole build adds (the solids' volumes, the output
        steps') are in ``part.build.values``.  The same numbers, to the last digit, as the manifest's."""
        run = self.proof_run
        return Values(run.derived, run.glossary, "build" if run.whole_build else "proof")

    @cached_property
    def shapes(self):
        """The solids, assemblies and DXF outlines alone (``building.SolidsResult``): where the part type
        declares the steps that make them (a non-circular pair), the design and those steps only — no file,
        no check, seconds —, else from its whole build (:attr:`build`); once a build was made, its own."""
        from .building import SolidsResult, solids, solids_alone

        if "build" in self.__dict__ or not solids_alone(self._loaded):
            b = self.build
            return SolidsResult(b.solids, b.profiles, b.assemblies,
                                {k: v for k, v in b.derived.items() if k.endswith("_volume_mm3")})
        return solids(self._loaded, progress=self.progress)

    @property
    def solids(self) -> dict:
        """name -> cadquery Shape of every solid the build writes (``<name>.step``), in mm (:attr:`shapes`:
        without the build's files where the part type allows)."""
        return self.shapes.solids

    @property
    def profiles(self) -> dict[str, list[np.ndarray]]:
        """DXF name -> the closed outlines of its CUT layer as (N, 2) arrays in mm (chord ≤ 0.005 mm)."""
        return {name: [pl for prof in profs for pl in prof.polylines()] for name, profs in self.shapes.profiles.items()}

    @cached_property
    def proof_run(self) -> Proof:
        """The design and the part type's proof steps only (the full-cycle proofs, their checks and derived
        values: no solid, no file), run once.  A part type that declares no proof steps runs its whole
        build (:attr:`build`) instead."""
        from .building import prove, proves_alone

        if not proves_alone(self._loaded):
            b = self.build
            return Proof(b.failures, b.checks, b.derived, True, b.glossary)
        return prove(self._loaded, progress=self.progress)

    def prove(self, raise_on_failure: bool = False, depth: str = "build") -> list:
        """The checks (:class:`propulsor.check.Check`: name, passed, value, limit, unit, message) of
        `depth` ``"build"``: every check of the build; ``"proof"``: those of the design and the full-cycle
        proofs only (:attr:`proof_run`: no solid, no file).  With `raise_on_failure`, CheckFailed for an
        unexpected failure among them."""
        if depth not in ("build", "proof"):
            raise InputError("depth", depth, "must be build or proof")
        run = self.build if depth == "build" else self.proof_run
        if raise_on_failure and run.failures:
            raise CheckFailed(list(run.failures))
        return list(run.checks)

    def assembly(self, name: str | None = None):
        """A ``cq.Assembly`` of the build's assembly `name` (the first one when None): named components
        placed as in ``<name>.step``, coloured as in the gallery."""
        cq = import_cadquery()

        from .export.render import palette_colour

        assemblies = self.shapes.assemblies
        if not assemblies:
            raise InputError("assembly", self.type, "this part has no assembly; see .solids")
        name = name or next(iter(assemblies))
        if name not in assemblies:
            raise InputError("assembly", name, f"must be one of {', '.join(assemblies)}")
        asm = cq.Assembly(name=name)
        for k, (comp, solid, xyz, rot) in enumerate(assemblies[name]):
            r, g, b = palette_colour(k)[:3]
            loc = cq.Location(cq.Vector(*map(float, xyz)), cq.Vector(0, 0, 1), float(np.degrees(rot)))
            asm.add(solid, name=str(comp), loc=loc, color=cq.Color(r / 255, g / 255, b / 255))
        return asm

    def write(self, out: "str | bytes | os.PathLike[str]", *, force: bool = False, keep_failed: bool = False,
              wait: bool = True, progress=None) -> Path:
        """Build into folder `out` exactly as ``propulsor build PART --out OUT`` does (the same files, the
        same bytes; the same folder rules, lock and atomic replacement), through the same build service
        (``building.build``).  When this part was built already in memory (:attr:`build`, :meth:`prove`,
        :attr:`solids` where they need the build, the notebook's view), the files of that build are copied into
        the folder instead of building again — unless the part file or a file it names changed since (then it
        builds).  Byte for byte as a build on its own is the first build of a process: after other builds in
        the same interpreter, OCCT's STEP writer may break the lines of an assembly's STEP elsewhere (the same
        entities and values).  `wait`: wait for another build holding the folder (False:
        ``FolderBusy``, an InputError); `progress`: a callback for the build's events
        (:class:`propulsor.progress.Event`, a str with a ``kind``).  Returns the folder; InputError for a folder
        that may not be used, CheckFailed when a check failed (outputs kept only with `keep_failed`),
        EnvironmentFailure when the file system refused.  Safe from several threads at once: each build
        owns its folder, lock and worker processes."""
        from .building import build

        made = self.__dict__.get("build")
        try:
            result = build(self._loaded, as_path(out, "out"), force=force, keep_failed=keep_failed, wait=wait,
                           progress=progress, reuse=made.result if made is not None else None)
        except CheckFailed as exc:
            if exc.result is not None:  # the build that was made: .build, .solids, .prove() reuse it
                self.__dict__["build"] = Build.of(exc.result)
            raise
        self.__dict__["build"] = Build.of(result)  # the build just written is this part's build
        return result.out

    def kit(self, printer: str = "generic", scale: float | None = None, **settings: Any):
        """The print kit (``propulsor print``'s model, not written): pieces at print scale with the FDM
        allowances, the rig and the plates.  `printer`: a profile name; `scale`: a reduction S (1:S) or None
        for the largest standard scale that fits; `settings`: printer settings to override
        (e.g. ``backlash_mm=0.35``)."""
        from .building import TURN
        from .parallel import Workers
        from .parts import get_kit
        from .printing.printers import load_printer

        make_kit = get_kit(self.type)
        profile = load_printer(printer, settings)
        with Workers(), TURN:  # the kit's own workers, ended with it
            return make_kit(self.params, profile, scale, source=self.source)
