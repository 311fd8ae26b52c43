"""OutputWriter: the one place where a part's solids, profiles, tables and plots
become files, and where every shared check runs on them.

A part module computes; it hands results to the writer:

    w.derived.update(...)             derived values for manifest/report
    w.add_checks([...])               engineering checks of the part
    w.add_solid(name, solid, genus)   STEP + STL + 3MF, B-rep/STEP/mesh checks, views/<name>.png
    w.add_assembly(name, components)  assembly STEP with named, placed components; <name>.glb
                                      and views/<name>.png from the solids' meshes
    w.add_known_mesh(solid, V, F)     a mesh the part made anyway, for the assemblies' GLB and picture
    w.add_dxf(name, cut, ref)         DXF (CUT / REF layers, mm)
    w.add_table(name, columns, rows)  CSV under tables/
    w.add_plot(name, fig)             PNG under plots/
    w.add_note(text)                  a paragraph of the report
    w.add_media(kind, entry)          a gallery item (animation, model, picture) for the manifest
    w.add_motion(assembly, info, nodes) the proof's poses of an assembly's moving components (its GLB's animation)
    w.finish()                        report.md (+ report.html) + manifest.json; returns the failures
"""

from __future__ import annotations

import dataclasses
import errno
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..check import Check
from ..export.glossary import manifest_glossary
from ..export.report import md_text, unit_from_name  # noqa: F401  (unit_from_name: public here too)
from ..parallel import fork_pool, inline
from ..params import applying_inputs, read_part_meta
from ..write_root import prepare
from .solid_cache import solid_key
from .solid_files import (VIEWS, _import_solid_work, assembly_glb, assembly_model, assembly_picture,  # noqa: F401
                          mesh_of, solid_files_and_checks, solid_mesh_and_checks, solid_step_and_checks)


#: forked workers writing and checking solids (the machine has 2 cores)
SOLID_WORKERS = 2


#: the files being written beside the build, by token: (function, arguments).  A job forked at its start
#: (:func:`..parallel.start`) finds them here, the very objects of the build, not their pickled copies (a shape's
#: pickle round trip turns a -0.0 of a direction into 0.0: other bytes in an assembly's STEP)
_STASHED: dict[int, tuple] = {}
_TOKENS = iter(range(1, 1 << 62))


def stashed_job(token: int) -> list[str]:
    """Run the file writes stashed under ``token`` (:data:`_STASHED`: (function, arguments) each, in order; in a
    worker forked after they were stashed, or inline) and return what they return (paths)."""
    return [str(fn(*args)) for fn, args in _STASHED[token]]


class _Joined:
    """The two jobs of one solid as one: result() is (the checks, STEP's first, the mesh's after; the mesh)."""

    def __init__(self, step_job, mesh_job):
        self.step_job, self.mesh_job = step_job, mesh_job

    def result(self):
        checks = self.step_job.result()
        mesh_checks, mesh = self.mesh_job.result()
        return checks + mesh_checks, mesh


@dataclass
class SolidRecord:
    name: str
    volume_mm3: float
    files: dict = field(default_factory=dict)


class OutputWriter:
    #: whether :meth:`add_plot` keeps a figure (a writer of values only drops it: the steps then draw none)
    draws_plots = True

    def __init__(self, folder: Path, part: str, params, progress=None, source: Path | None = None):
        self.folder = Path(folder)
        self.part = part
        self.params = params
        self.progress = progress or (lambda msg: None)
        self.source = source
        self.title = part
        self.meta: dict[str, Any] = {}
        if source is not None and Path(source).is_file():
            self.meta = read_part_meta(source)
            self.title = self.meta.get("title", part)
        self.expected_failures = set(self.meta.get("expected_failures", []))
        self.derived: dict[str, Any] = {}
        self.described: dict[str, tuple[str, str]] = {}  # derived name -> (unit, meaning), see describe()
        self.checks: list[Check] = []
        notes = self.meta.get("notes", [])
        # the part file's notes are text (the report's own notes are Markdown)
        self.notes: list[str] = [md_text(n) for n in ([notes] if isinstance(notes, str) else notes)]
        self.solids: list[SolidRecord] = []
        self.tables: list[str] = []
        self.plots: list[str] = []
        self.extra_files: list[str] = []  # assemblies and DXF, named in the report
        self.media: dict[str, list[dict]] = {}  # kind -> entries ({path, ...}), the manifest's "media"
        self._pool = None
        self._solid_jobs: list = []
        self._meshes: dict[str, tuple] = {}  # solid key -> (vertices, faces) mm, for the assemblies
        self._mesh_jobs: list = []  # (key, job) meshes of assembly solids that have no files of their own
        self._file_jobs: list = []  # (token, job) files being written beside the build (assemblies' STEP, DXF)
        self._pending: list = []  # (function, arguments) of the files to write beside the build at the step's end
        self._solid_keys: dict[int, str] = {}  # id(solid) -> its key (the solid's name)
        self._keep: list = []  # the solids keyed by id, kept alive
        self._assemblies: list = []  # (name, [(component, solid key, 4×4 mm)], picture from below)
        self._motions: dict[str, list] = {}  # assembly name -> [(info, {component: (poses, reference)})]
        self.report_name = "report.md"  # a print kit's is print_report.md
        #: Markdown lines the report opens with (a kit's: what to print, then the assembly), and the inputs'
        #: heading, as an appendix at the end when inputs_last (a kit's inputs are the full-size design's)
        self.report_lead: list[str] = []
        self.inputs_heading = "Inputs"
        self.inputs_last = False
        self.intended: set[str] = set()  # files the build means to write (relative paths), besides the media
        # what the build made, by name, for the Python API (propulsor.api): solids, DXF profiles, assemblies
        self.built_solids: dict[str, Any] = {}
        self.built_profiles: dict[str, list] = {}
        self.built_assemblies: dict[str, list] = {}

    # -- helpers -----------------------------------------------------------------
    def path(self, rel: str) -> Path:
        self.intended.add(rel)
        return prepare(self.folder / rel)

    def describe(self, name: str, unit: str, meaning: str) -> None:
        """The unit and the meaning of derived value `name` (what the report's table and the manifest say
        of it); a name may be described before or after its value is set."""
        self.described[name] = (unit, meaning)

    def add_checks(self, checks) -> None:
        for c in checks:
            self.checks.append(c)

    def add_note(self, text: str) -> None:
        self.notes.append(text)

    def add_media(self, kind: str, entry: dict) -> None:
        """A gallery item of this build: kind 'animations', 'models' or 'pictures'; entry a dict with
        'path' (relative to the output folder, the file written by the caller) and what the gallery
        shows of it (title, frames, size...).  Listed in the manifest under ``media``."""
        self.media.setdefault(kind, []).append(dict(entry))

    # -- solids ------------------------------------------------------------------
    def add_solid(self, name: str, solid, expected_genus: int | None = None) -> SolidRecord:
        """Write STEP, STL and 3MF of one solid and run every shared check on them.

        The work runs in a forked worker (two at a time, the machine's cores) while the part goes
        on; :meth:`finish` collects the checks in the order the solids were added."""
        volume = float(solid.Volume())
        rec = SolidRecord(name, volume, {"step": f"{name}.step", "stl": f"{name}.stl", "3mf": f"{name}.3mf"})
        self.intended.update(rec.files.values())
        self.built_solids[name] = solid
        self.solids.append(rec)
        self._solid_keys[id(solid)] = name
        self._keep.append(solid)
        self.add_media("pictures", {"path": f"{VIEWS}/{name}.png", "title": f"{name} (solid)", "of": name})
        self.derived[f"{name}_volume_mm3"] = volume
        self.progress(f"{name}: STEP, STL, 3MF and their checks (B-rep, STEP round trip, mesh)")
        pool = self._solid_pool()
        folder = str(self.folder)
        key = solid_key(solid, name, expected_genus, volume)  # the same solid of another build of the batch
        if pool is None:  # in this process: the STEP and its checks, then the mesh (one copy of the solid)
            self._solid_jobs.append((name, inline(solid_files_and_checks, folder, name, solid, expected_genus,
                                                  volume, False, key)))
            return rec
        # two jobs, the longer (the mesh) first: the two workers share one large solid's work
        mesh_job = pool.submit(solid_mesh_and_checks, folder, name, solid, expected_genus, volume, True, key)
        step_job = pool.submit(solid_step_and_checks, folder, name, solid, volume, key)
        self._solid_jobs.append((name, _Joined(step_job, mesh_job)))
        return rec

    def warm_up(self) -> None:
        """While the design is computed in another process (:func:`propulsor.parts.pipeline.design_apart`): load the
        compiled kernels (before any worker forks: each inherits the compiled code) and import the plotting library
        the figures need.  Not the CAD kernel: the jobs a build starts as soon as its design is known (a pair's
        as-built contact) fork first, and the kernel loads beside them (:meth:`load_kernel`, by the first step that
        makes a solid).  Its import holds the interpreter's lock for about a second: loaded here, it held back the
        design's result (read by a thread of this process) and so the contact's start by as much, a core idle
        meanwhile (the Fourier pair's build: the design done 1.1 s in, the contact started at 1.9 s)."""
        from ..checks.kernels import warm_if_cold

        self.progress("loading the plotting library while the design is computed beside it")
        warm_if_cold(self.progress)
        if self.draws_plots:
            from ..export import plots  # noqa: F401  (matplotlib, Agg)

    def load_kernel(self) -> None:
        """Import the CAD kernel (cadquery without VTK: :func:`propulsor.solids.cq_import.import_cadquery`) where it
        is not loaded yet, said first (about a second); the solids' wrapper and the assembly STEP need it."""
        from ..solids.cq_import import import_cadquery

        if "cadquery" not in sys.modules:
            self.progress("loading the CAD kernel (OCCT)")
        import_cadquery()

    def _solid_pool(self):
        if self._pool is None:
            _import_solid_work()  # once here, not once in every forked worker
            self._pool = fork_pool(SOLID_WORKERS)
        return self._pool

    def wait_solids(self) -> None:
        """Collect the checks of every solid added so far (in the order they were added)."""
        self._count_solid_jobs()
        for name, job in self._solid_jobs:
            checks, self._meshes[name] = job.result()
            self.add_checks(checks)
            self.progress(f"{name}: files written and checked")
        self._solid_jobs = []
        for key, job in self._mesh_jobs:
            self._meshes[key] = job.result()
        self._mesh_jobs = []
        self.flush_beside()
        self._wait_files()

    def _beside(self, fn, *args) -> None:
        """``fn(*args)`` (a file written) beside the build: held until the build's step ends
        (:meth:`flush_beside`), then written with the step's other such files in one worker forked then."""
        self._pending.append((fn, args))

    def flush_beside(self) -> None:
        """Write the files held by :meth:`_beside` in one worker forked now, which has their arguments as they are
        (no pickled copies), or inline where no worker may start (:func:`..parallel.start`); collected by
        :meth:`wait_solids`.  The pipeline calls it after each step (one fork a step, not one a file)."""
        if not self._pending:
            return
        from ..parallel import start

        token = next(_TOKENS)
        _STASHED[token], self._pending = tuple(self._pending), []
        self._file_jobs.append((token, start(stashed_job, token)))

    def _wait_files(self, raising: bool = True) -> None:
        """Wait for the files written beside the build (their errors raised, in order, unless ``raising`` is
        False: a build already failing) and forget their arguments."""
        jobs, self._file_jobs = self._file_jobs, []
        try:
            for _, job in jobs:
                try:
                    job.result()
                except Exception:  # noqa: BLE001 - raised unless the build is failing already
                    if raising:
                        raise
        finally:
            for token, _ in jobs:
                _STASHED.pop(token, None)

    def _count_solid_jobs(self) -> None:
        """Wait for the solids' jobs still running in workers, counting them as they end (progress only: their
        results are collected in order after)."""
        import concurrent.futures as cf

        from ..progress import counter

        futures = [f for _, job in self._solid_jobs
                   for f in ((job.step_job, job.mesh_job) if isinstance(job, _Joined) else (job,))]
        pending = {f for f in futures if isinstance(f, cf.Future) and not f.done()}
        if not pending or len(futures) < 2:
            return
        tick = counter(self.progress, "solids: STEP, STL, 3MF and their checks", len(futures), "job")
        tick(len(futures) - len(pending))
        while pending:
            _, pending = cf.wait(pending, return_when=cf.FIRST_COMPLETED)
            tick(len(futures) - len(pending))

    def wait_for_files(self, *names: str) -> None:
        """Wait until the files of the named solids are written (their checks are still collected, in
        order, by :meth:`wait_solids`)."""
        for name, job in self._solid_jobs:
            if name in names:
                job.result()

    def close(self) -> None:
        """Stop the workers (after a failure: nothing may be written into the folder after this): their jobs finish
        first, unless a signal is ending the build (then they are killed at once)."""
        from ..signals import SIGNALLED

        if self._pool is not None:
            if SIGNALLED:
                from ..parallel import kill_pool

                kill_pool(self._pool)
            else:
                self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None
        self._pending = []  # not started: nothing is written after this
        if SIGNALLED:  # the build's Workers block kills their processes as it ends
            for token, _ in self._file_jobs:
                _STASHED.pop(token, None)
            self._file_jobs = []
        else:
            self._wait_files(raising=False)
        self._solid_jobs = []
        self._mesh_jobs = []
        self._assemblies = []
        self._motions = {}

    def add_assembly(self, name: str, components, picture_from_below: bool = False) -> Path:
        """components: list of (component name, solid, (x, y, z) mm, rotation about z in rad).
        picture_from_below: the assembly's picture is the isometric view from below (its main part
        would be hidden under the others seen from above).

        Beside the STEP: ``<name>.glb`` and the picture ``views/<name>.png``, made at
        :meth:`finish` from the meshes of the solids (a solid added with :meth:`add_solid` is not
        tessellated again; another is tessellated once in a worker)."""
        from ..export.glb import placement_matrix
        from ..export.step import write_assembly_step

        p = self.path(f"{name}.step")
        self.built_assemblies[name] = list(components)
        self.progress(f"{name}: assembly STEP ({len(components)} components)")
        # written beside the build: the same bytes in a worker or inline, the occurrences numbered per file
        # (export.step.fix_header)
        self._beside(write_assembly_step, p, list(components), name)
        self.extra_files.append(p.name)
        placed = []
        for comp in components:
            solid = comp[1]
            key = self._solid_keys.get(id(solid))
            if key is None:  # a solid with no files of its own: its mesh is made once, in a worker
                key = self._solid_keys[id(solid)] = f"{name}:{comp[0]}"
                self._keep.append(solid)
                pool = self._solid_pool()
                self._mesh_jobs.append((key, pool.submit(mesh_of, solid, True) if pool else inline(mesh_of, solid, False)))
            placed.append((str(comp[0]), key, placement_matrix(comp)))
        self._assemblies.append((name, placed, picture_from_below))
        self.extra_files += [f"{name}.glb"]
        self.intended.add(f"{name}.glb")
        model = {"path": f"{name}.glb", "title": name, "step": p.name,
                 "components": [c for c, _, _ in placed], "picture": f"{VIEWS}/{name}.png"}
        if picture_from_below:  # the 3D view's first direction too (the part's frame, z up)
            from ..export.render import VIEW_DIR_BELOW

            model["view_dir"] = [float(x) for x in VIEW_DIR_BELOW]
        self.add_media("models", model)
        self.add_media("pictures", {"path": f"{VIEWS}/{name}.png", "title": f"{name} (assembly)", "of": name})
        return p

    def add_known_mesh(self, solid, vertices, faces) -> None:
        """The mesh of a solid that the part made for its own work (a sweep's): an assembly holding the
        solid uses it for its GLB and picture instead of tessellating the solid again."""
        if id(solid) not in self._solid_keys:
            key = self._solid_keys[id(solid)] = f"mesh_{len(self._meshes) + len(self._keep)}"
            self._keep.append(solid)
            self._meshes[key] = (np.asarray(vertices, np.float64), np.asarray(faces, np.int64))

    def add_motion(self, assembly: str, info: dict, nodes: dict) -> None:
        """The poses of the components of `assembly` (added before :meth:`finish`) that move: its GLB gets
        them as an animation (one key per pose, shown by the 3D view's slider).  info: name, title,
        frame_ms, steps (the proof's step of each pose), poses (what they are); nodes: component name ->
        ((frames, 2, 3) poses in the assembly's x-y plane, (2, 3) the pose the assembly shows it at)."""
        self._motions.setdefault(assembly, []).append((dict(info), dict(nodes)))

    def _motion_placements(self, name: str, placed) -> list:
        """The animations of assembly `name`: (info, {component index: (frames, 4, 4) placements mm}); each
        moving component placed at pose · reference⁻¹ · its assembly placement."""
        from ..export.glb import lift_planar

        out = []
        for info, nodes in self._motions.get(name, []):
            index = {c: k for k, (c, _, _) in enumerate(placed)}
            unknown = sorted(set(nodes) - set(index))
            if unknown:
                raise ValueError(f"motion {info.get('name')!r} of {name}: no component {unknown[0]!r}")
            moves = {}
            for c, (poses, ref) in nodes.items():
                back = np.linalg.inv(lift_planar(ref))
                moves[index[c]] = np.einsum("kij,jl,lm->kim", lift_planar(poses), back, placed[index[c]][2])
            out.append((info, moves))
        return out

    def _write_models(self) -> None:
        """Every assembly's GLB and picture (after :meth:`wait_solids`: the meshes are in), two at a time."""
        if not self._assemblies:
            return
        self.progress(f"GLB and pictures of {len(self._assemblies)} assembl{'y' if len(self._assemblies) == 1 else 'ies'}")
        pool = self._solid_pool()
        jobs = []
        for name, placed, from_below in self._assemblies:
            meshes = {key: self._meshes[key] for key in dict.fromkeys(k for _, k, _ in placed)}
            folder, motions = str(self.folder), self._motion_placements(name, placed)
            if pool is None:
                jobs.append(inline(assembly_model, folder, name, meshes, placed, from_below, motions))
            else:  # the GLB and the picture side by side
                jobs.append(pool.submit(assembly_glb, folder, name, meshes, placed, motions))
                jobs.append(pool.submit(assembly_picture, folder, name, meshes, placed, from_below))
        for job in jobs:
            job.result()

    # -- 2D, tables, plots --------------------------------------------------------
    def add_dxf(self, name: str, cut_profiles, ref_curves=(), beside: bool = False) -> Path:
        """``<name>.dxf`` of the cut profiles and reference curves; ``beside``: written in a worker beside the
        build (the same bytes), for a part that does not read it back before :meth:`finish`."""
        from ..export.dxf import write_dxf

        p = self.path(f"{name}.dxf")
        self.built_profiles[name] = list(cut_profiles)
        if beside:
            self._beside(write_dxf, p, list(cut_profiles), list(ref_curves))
        else:
            write_dxf(p, cut_profiles, list(ref_curves))
        self.extra_files.append(p.name)
        return p

    def add_table(self, name: str, columns, rows) -> Path:
        from ..export.tables import write_csv

        p = self.path(f"tables/{name}.csv")
        write_csv(p, columns, rows)
        self.tables.append(f"tables/{name}.csv")
        return p

    def add_plot(self, name: str, fig) -> Path:
        from ..export.plots import save_plot

        p = self.path(f"plots/{name}.png")
        save_plot(p, fig)
        self.plots.append(f"plots/{name}.png")
        return p

    # -- the end -------------------------------------------------------------------
    def intended_files(self) -> set[str]:
        """Every file the build meant to write (relative paths): what its writers were asked for, the
        media it lists, the report and its twin and the manifest."""
        media = {e["path"] for entries in self.media.values() for e in entries if isinstance(e.get("path"), str)}
        twin = self.report_name[:-3] + ".html"
        return self.intended | media | {self.report_name, twin, "manifest.json"}

    def failures(self) -> list[str]:
        return [f"{c.name}: {c.message}" for c in self.checks
                if not c.passed and c.name not in self.expected_failures]

    def finish(self) -> list[str]:
        """Write report.md and manifest.json; return the unexpected check failures."""
        from ..export.html import write_report_html
        from ..export.manifest import write_manifest
        from ..export.report import write_report

        self.wait_solids()
        self._write_models()
        self.close()

        self.add_checks([self.explained_check()])
        inputs = applying_inputs(self.params)
        notes = list(self.notes)
        meaning = getattr(self.params, "meaning", lambda name: None)
        report_inputs = {f.name: (inputs[f.name], f.metadata.get("unit", ""),
                                  meaning(f.name) or f.metadata.get("doc", ""))
                         for f in dataclasses.fields(self.params) if f.name in inputs}
        explained = self.explained()
        by_path = {e.path: e for e in explained}
        report_derived = {k: (v, by_path[k].unit, by_path[k].meaning) if k in by_path else (v, unit_from_name(k), "")
                          for k, v in self.derived.items()}
        expected = [c for c in self.checks if not c.passed and c.name in self.expected_failures]
        if expected:
            notes.append("Checks that fail as documented in the part file ([meta] expected_failures): "
                         + ", ".join(c.name for c in expected) + ".")
        self.progress("report and manifest")
        built = [f"`{r.name}` ({', '.join(r.files.values())}; volume {r.volume_mm3:.6g} mm³)" for r in self.solids]
        built += [f"`{n}`" for n in self.extra_files]
        intro = ("Built: " + "; ".join(built) + ".") if built else ""
        views = [(e["path"], e["title"]) for e in self.media.get("pictures", [])]
        report = write_report(self.folder / self.report_name, title=self.title, part=self.part, intro=intro,
                              inputs=report_inputs, derived=report_derived, checks=self.checks, tables=self.tables,
                              plots=self.plots, notes=notes, views=views, key_values=self.key_values(),
                              lead=self.report_lead, inputs_heading=self.inputs_heading, inputs_last=self.inputs_last)
        write_report_html(report, self.media.get("models", ()))
        manifest = write_manifest(self.folder, part=self.part, inputs=inputs, derived=self.derived,
                                  checks=self.checks, expected_failures=self.expected_failures, media=self.media,
                                  title=self.title, glossary=manifest_glossary(explained))
        self.verify_written(manifest)
        return self.failures()

    # -- what the derived values mean ----------------------------------------------------
    def explained(self):
        """(entries, missing): every derived value's path with its unit and meaning, from the part type's
        glossary and :meth:`describe` (which wins), and the paths nobody explained."""
        from ..export.glossary import Glossary, explain
        from . import glossary_of

        entries, self._unexplained = explain(self.derived, Glossary(glossary_of(self.part), described=self.described))
        return entries

    def explained_check(self) -> Check:
        """Every derived value has a meaning (a value added without one fails the build)."""
        self.explained()
        missing = self._unexplained
        return Check("report: every derived value explained", not missing, len(missing), 0, "",
                     "every derived value has a unit and a meaning" if not missing else
                     "no meaning (add it to the part type's glossary or describe() it): " + ", ".join(missing[:5])
                     + (f" and {len(missing) - 5} more" if len(missing) > 5 else ""))

    def key_values(self) -> list[str]:
        """The derived values the report's summary shows."""
        from . import key_values_of

        return key_values_of(self.part)

    def verify_written(self, manifest: Path) -> None:
        """Every file the build meant to write is in the manifest it wrote (a file lost under the build,
        or a writer that wrote nothing, is an environment failure: nothing is published)."""
        import json

        from ..errors import EnvironmentFailure

        listed = {e["path"] for e in json.loads(manifest.read_text(encoding="utf-8"))["files"]} | {"manifest.json"}
        missing = sorted(self.intended_files() - listed)
        if missing:
            raise EnvironmentFailure(self.folder / missing[0], errno.ENOENT, "a file the build wrote is missing:",
                                     f"{len(missing)} of {len(self.intended_files())} missing, the folder was "
                                     "changed under the build")
