"""A build's work side by side: the design computed in a forked process while the build imports and starts
its workers (pipeline.design_apart); each solid's files, and an assembly's GLB and picture, as two worker
jobs giving the checks and files of the work done in one process; a large gear's pieces fitted in two
processes; cadquery imported without VTK."""

from __future__ import annotations

import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from propulsor.errors import InputError
from propulsor.parts.pipeline import Pipeline, design_of

#: a small pair's part file, built whole in a subprocess by the tests below
ELLIPTICAL = str(Path(__file__).resolve().parents[1] / "parts" / "ncg_elliptical.toml")


@dataclass
class P:
    a: float = 1.0


class Writer:
    """What a design reads of the writer (source), and the warm-up the build runs meanwhile."""

    source = None

    def __init__(self):
        self.warmed = []

    def warm_up(self):
        self.warmed.append(os.getpid())


def inner(p):
    return {"pid": os.getpid(), "value": 2.0 * p.a}


def outer(p, w):
    return ("D", design_of(p, inner))


def run(pipeline, params, w):
    got = []
    Pipeline(pipeline.design, (lambda d, w_, built: got.append(d),), design_apart=pipeline.design_apart)(params, w)
    return got[0]


def test_the_design_runs_in_another_process_while_the_build_warms_up_and_its_designs_join_the_cache(monkeypatch):
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    p, w = P(3.0), Writer()
    d = run(Pipeline(outer, (), design_apart=True), p, w)
    assert d[0] == "D" and d[1]["value"] == 6.0
    assert d[1]["pid"] != os.getpid()  # computed in the forked process
    assert w.warmed == [os.getpid()]  # the build warmed up meanwhile, here
    # the inner design computed there is this process's cached design now: not computed again
    assert design_of(p, inner) is d[1]


def test_on_a_budget_of_one_process_the_design_runs_here_without_warm_up(monkeypatch):
    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    w = Writer()
    d = run(Pipeline(outer, (), design_apart=True), P(), w)
    assert d[1]["pid"] == os.getpid() and w.warmed == []
    # a part type that does not declare it keeps its design here too
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    d = run(Pipeline(outer, ()), P(), w)
    assert d[1]["pid"] == os.getpid() and w.warmed == []


def refuse(p, w):
    raise InputError("driver_shift", 0.5, "no catalogue cutter generates this law")


def test_a_design_refused_in_the_forked_process_is_refused_here_with_its_message(monkeypatch):
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    with pytest.raises(InputError, match="driver_shift = 0.5: no catalogue cutter generates this law"):
        run(Pipeline(refuse, (), design_apart=True), P(), Writer())


def test_a_solid_and_an_assembly_split_over_two_workers_give_the_checks_mesh_and_files_of_one_process(tmp_path, monkeypatch):
    import cadquery as cq
    import numpy as np

    from propulsor.parallel import as_if_sent
    from propulsor.export.glb import placement_matrix
    from propulsor.parts.writer import OutputWriter, assembly_model, solid_files_and_checks

    solid = cq.Workplane("XY").box(30.0, 20.0, 8.0).faces(">Z").workplane().hole(6.0).val()
    (tmp_path / "one" / "views").mkdir(parents=True)
    alone, (V, F) = solid_files_and_checks(str(tmp_path / "one"), "part", as_if_sent(solid), 1, solid.Volume(), True)
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    w = OutputWriter(tmp_path / "two", "test", None)
    try:
        w.add_solid("part", solid, expected_genus=1)
        assert w._pool is not None  # the work went to the workers
        w.add_assembly("asm", [("part", solid, (5.0, 0.0, 0.0), 0.3)])
        w.wait_solids()
        w._write_models()  # the GLB and the picture as two jobs
    finally:
        w.close()
    assembly_model(str(tmp_path / "one"), "asm", {"part": (V, F)},
                   [("part", "part", placement_matrix(("part", solid, (5.0, 0.0, 0.0), 0.3)))])
    assert [(c.name, c.passed, c.value) for c in w.checks] == [(c.name, c.passed, c.value) for c in alone]
    assert [c.name for c in w.checks][:2] == ["part: BRepCheck_Analyzer valid", "part: solids"]
    assert np.array_equal(w._meshes["part"][0], V) and np.array_equal(w._meshes["part"][1], F)
    for name in ("part.step", "part.stl", "part.3mf", "views/part.png", "asm.glb", "views/asm.png"):
        assert (tmp_path / "two" / name).read_bytes() == (tmp_path / "one" / name).read_bytes()


def test_a_gear_fitted_in_two_processes_has_the_outline_fitted_in_one(monkeypatch):
    import numpy as np

    from propulsor.gears.noncircular import PitchCurves, centre_distance
    from propulsor.gears.noncircular_teeth import ToothSpec
    from propulsor.geometry import noncircular_outline as no
    from propulsor.laws.ratio_laws import FourierLaw
    from propulsor.parallel import start

    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    law = FourierLaw(2, (0.0, 0.01), (-0.03,))
    pc = PitchCurves(law, centre_distance(law, 2.0, 24))

    def outline():
        segs = no.generate_gear(pc, "driven", ToothSpec(m=2.0), start=start).profile.loops[0].segments
        return [(s.knots, s.poles) for s in segs]

    monkeypatch.setattr(no, "SPLIT_FIT_TEETH", 10**6)
    one = outline()
    monkeypatch.setattr(no, "SPLIT_FIT_TEETH", 2)
    two = outline()
    assert len(one) == len(two) > 24
    assert all(np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1]) for a, b in zip(one, two))


class _Witness:
    """An argument that says in which thread it was pickled and what it held then."""

    def __init__(self):
        self.items = {"a": 1}

    def __getstate__(self):
        import threading

        return {"items": dict(self.items), "pickled_in": threading.current_thread().name}


def _held(w):
    return w.pickled_in, sorted(w.items)


def test_a_forked_job_takes_its_arguments_as_they_stand_when_it_is_started(monkeypatch):
    """A job's arguments are pickled in the caller's thread at the start, not later by the executor's feeder thread
    while the caller goes on filling them (CI: "dictionary changed size during iteration", a pair's build failed)."""
    import threading

    from propulsor.parallel import Done, Workers, start

    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    with Workers():
        w = _Witness()
        job = start(_held, w)
        w.items["b"] = 2  # the caller goes on with its argument
        assert not isinstance(job, Done), "the job ran inline: no worker was forked"
        assert job.result() == (threading.current_thread().name, ["a"])
        bad = start(_held, lambda: None)  # a job that does not pickle: its error where the result is waited for
        with pytest.raises(Exception, match="pickle|lambda"):
            bad.result()


def test_cadquery_is_imported_without_vtk_and_its_vtk_functions_load_it_when_used():

    code = (
        "import sys\n"
        "from propulsor.solids.cq_import import import_cadquery\n"
        "cq = import_cadquery()\n"
        "loaded = sorted(m for m in sys.modules if m.startswith('vtkmodules') or m.startswith('OCP.IVtk'))\n"
        "s = cq.Workplane().box(10, 20, 30).val()\n"
        "print(loaded, round(s.Volume(), 6), s.toVtkPolyData(0.1).GetNumberOfPoints() > 0)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.split() == ["[]", "6000.0", "True"]


def test_every_solid_and_step_function_takes_cadquery_without_vtk(tmp_path):
    """A build of one part file (no batch preloading cadquery first) reaches cadquery through the solids and
    the STEP writers: each of them imports it with VTK deferred (VTK costs 0.8 CPU s a build and 127 MiB)."""

    code = (
        "import sys\n"
        "from propulsor.geometry.profile import Profile, circle_loop\n"
        "from propulsor.solids.{module} import {call}\n"
        "from propulsor.export.step import write_assembly_step\n"
        "from propulsor.solids.build import extrude_profile\n"
        "{call}({args})\n"
        "s = extrude_profile(Profile(circle_loop(10.0)), 5.0)\n"
        "write_assembly_step(sys.argv[1], [('a', s, (0, 0, 0))], 'pair')\n"
        "print(sorted(m for m in sys.modules if m.startswith('vtkmodules') or m.startswith('OCP.IVtk')))\n"
    )
    for module, call, args in (("build", "extrude_profile", "Profile(circle_loop(10.0)), 5.0"),
                               ("kernel", "box", "1.0, 2.0, 3.0"), ("kernel", "cylinder", "1.0, 0.0, 2.0")):
        r = subprocess.run([sys.executable, "-c", code.format(module=module, call=call, args=args),
                            str(tmp_path / f"{call}.step")], capture_output=True, text=True, check=True)
        assert r.stdout.split() == ["[]"], (call, r.stdout, r.stderr[-2000:])


def test_a_build_freezes_what_it_imported_and_a_dry_run_loads_no_cad_kernel(tmp_path):
    """Objects that live as long as the process are moved out of the garbage collector's sight (``gc.freeze``: a
    build's full collections scanned them again and again, 0.70 -> 0.45 CPU s of collections in a build of the
    Fourier pair): ``propulsor build`` freezes what it has loaded when the build starts (most objects then), and
    several builds' preload freezes the modules they share before they fork, and draws a figure then (the first
    figure's backend and font search done once for every build).  A dry run (validation only) imports no CAD
    kernel."""

    part = ELLIPTICAL
    code = (
        "import gc, sys\n"
        "import propulsor.cli as cli, propulsor.building as b\n"
        "seen = {}\n"
        "def build(*a, **k):\n"
        "    seen['frozen'], seen['live'] = gc.get_freeze_count(), len(gc.get_objects())\n"
        "    raise SystemExit(0)\n"
        "b.build = build\n"
        "try:\n"
        "    cli.main(['build', sys.argv[1], '--out', sys.argv[2]] + sys.argv[3:])\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(seen.get('frozen', 0), seen.get('live', 0), 'OCP.OCP' in sys.modules)\n"
    )
    r = subprocess.run([sys.executable, "-c", code, part, str(tmp_path / "out")], capture_output=True, text=True,
                       check=True)
    frozen, live, _ = r.stdout.split()
    assert int(frozen) > 50_000 and int(frozen) > 3 * int(live), r.stdout
    r = subprocess.run([sys.executable, "-c", code, part, str(tmp_path / "dry"), "--dry-run"], capture_output=True,
                       text=True, check=True)
    assert r.stdout.split()[-3:] == ["0", "0", "False"], r.stdout
    # the collector makes no collection while the modules load (at Python's own thresholds, as here, 891 before; 6
    # at the program's tuned ones, 0.12 of 2.4 CPU s on a batch's critical path), and is on again after
    r = subprocess.run([sys.executable, "-c", "import gc\nfrom propulsor.batch import preload\nruns = []\n"
                        "gc.callbacks.append(lambda phase, info: phase == 'start' and runs.append(info['generation']))\n"
                        "preload()\n"
                        "import sys\nfrom matplotlib import font_manager\n"
                        "print(gc.get_freeze_count(), len(gc.get_objects()), len(runs), gc.isenabled(),\n"
                        "      'matplotlib.backends.backend_agg' in sys.modules,\n"
                        "      font_manager.FontManager._findfont_cached.cache_info().currsize)"],
                       capture_output=True, text=True, check=True)
    frozen, live, runs, enabled, agg, fonts = r.stdout.split()
    assert int(frozen) > 200_000 and int(live) < 1000 and runs == "0" and enabled == "True", r.stdout
    # a figure drawn before the fork (plots.warm): pyplot's backend loaded and the font search cached for the builds'
    # font sizes, in every forked build and worker that draws
    assert agg == "True" and int(fonts) >= 5, r.stdout


def test_an_assembly_step_written_beside_the_build_has_the_bytes_of_one_written_in_its_process(tmp_path, monkeypatch):
    """OutputWriter.add_assembly writes the STEP (and add_dxf(beside=True) the DXF) in a worker forked as it is
    called (PROPULSOR_JOBS=2) or in the build's process (1): the same bytes.  A box mirrored in the YZ plane is a shape whose pickle round trip changes
    the file (a -0.0 of a direction written 0.0, as in the balancer's, the final drive's and the cam mover's
    assemblies): the job finds the build's own objects (writer._STASHED), never their pickled copies, and the
    pickled copies do give other bytes here."""
    import pickle

    import cadquery as cq

    from propulsor.export.dxf import write_dxf
    from propulsor.export.step import write_assembly_step
    from propulsor.geometry.profile import Profile, circle_loop, polygon_loop
    from propulsor.parts import writer as writer_mod
    from propulsor.parts.writer import OutputWriter

    plate = Profile(polygon_loop([(0.0, 0.0), (40.0, 0.0), (40.0, 25.0), (-0.0, 25.0)]), [circle_loop(4.0, (20.0, 12.5))])
    ref = [("point", {"p": (0.0, 0.0)})]
    write_dxf(tmp_path / "direct.dxf", [plate], ref)
    components = [("box", cq.Workplane().box(4.0, 3.0, 2.0).mirror("YZ").val(), (0.0, 0.0, 0.0), 0.0),
                  ("pin", cq.Workplane().cylinder(5.0, 1.0).val(), (12.0, 0.0, 0.0), 0.4)]
    write_assembly_step(tmp_path / "pickled.step", pickle.loads(pickle.dumps(components)), "asm")
    got = {}
    for jobs in ("1", "2"):
        monkeypatch.setenv("PROPULSOR_JOBS", jobs)
        w = OutputWriter(tmp_path / jobs, "test", None)
        try:
            w.add_assembly("asm", components)
            w.add_dxf("plate", [plate], ref, beside=True)
            assert not (tmp_path / jobs / "asm.step").exists() and not w._file_jobs  # held to the step's end
            w.flush_beside()  # both in one job
            kinds = [type(job).__name__ for _, job in w._file_jobs]
            w.wait_solids()
        finally:
            w.close()
        assert kinds == (["Done"] if jobs == "1" else ["Future"])  # inline, then in a worker
        got[jobs] = (tmp_path / jobs / "asm.step").read_bytes()
        assert (tmp_path / jobs / "plate.dxf").read_bytes() == (tmp_path / "direct.dxf").read_bytes()
    assert got["1"] == got["2"]
    assert got["1"] != (tmp_path / "pickled.step").read_bytes()
    assert not writer_mod._STASHED  # the jobs' arguments forgotten once collected


def _sleep_and_say(seconds: float, path: str) -> int:
    import time as _time

    _time.sleep(seconds)
    Path(path).write_text("done")
    return os.getpid()


def test_a_job_started_only_in_a_worker_is_none_without_one_and_an_abandoned_one_is_killed(tmp_path, monkeypatch):
    """``start(..., forked_only=True)``: a Future running in a forked worker where one may be forked, else None and
    nothing run (not the work run here); ``abandon`` kills a running job's worker at once (it never finishes its
    work), and leaves a finished job, a job run inline and None as they are."""
    import time as _time
    from concurrent.futures.process import BrokenProcessPool

    from propulsor.parallel import Done, Workers, abandon, start

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    with Workers():
        assert start(_sleep_and_say, 0.0, str(tmp_path / "one"), forked_only=True) is None
        assert not (tmp_path / "one").exists()
        inline = start(_sleep_and_say, 0.0, str(tmp_path / "inline"))
        assert isinstance(inline, Done) and inline.result() == os.getpid()
        abandon(inline)
        abandon(None)
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    with Workers():
        done = start(_sleep_and_say, 0.0, str(tmp_path / "quick"), forked_only=True)
        assert not isinstance(done, Done) and done.result() != os.getpid()
        abandon(done)
        assert done.result() != os.getpid()  # a finished job keeps its result
        slow = start(_sleep_and_say, 30.0, str(tmp_path / "slow"), forked_only=True)
        pid = next(iter(slow.propulsor_pool._procs))
        t0 = _time.monotonic()
        abandon(slow)
        with pytest.raises(ProcessLookupError):  # killed and reaped by the time abandon returns
            os.kill(pid, 0)
        with pytest.raises(BrokenProcessPool):
            slow.result(timeout=10)
        assert _time.monotonic() - t0 < 10.0
    assert not (tmp_path / "slow").exists()


def test_a_pairs_contact_jobs_fork_before_the_cad_kernel_loads_and_the_kernel_loads_said_once(tmp_path):
    """A pair's build (one part file, two processes allowed): the as-built contact's jobs, which need no CAD kernel,
    are forked as soon as the design is known, and the kernel loads beside them (``OutputWriter.load_kernel``, by the
    solids' step).  Loaded during the design instead (``warm_up``, until 2026-12-05), its second of import held the
    design's result back and a core idle: the contact of the Fourier pair started 0.8 s later, the build 0.37 s
    longer.  The kernel is still imported without VTK, and the progress says when it loads, once."""
    import json

    part = ELLIPTICAL
    code = (
        "import json, os, sys\n"
        "import propulsor.parallel as par\n"
        "import propulsor.cli as cli\n"
        "starts = []\n"
        "real = par.start\n"
        "def start(fn, *a, **k):\n"
        "    starts.append((fn.__name__, 'OCP' in sys.modules))\n"
        "    return real(fn, *a, **k)\n"
        "par.start = start\n"
        "rc = cli.main(['build', sys.argv[1], '--out', sys.argv[2]])\n"
        "vtk = sorted(m for m in sys.modules if m.startswith('vtkmodules') or m.startswith('OCP.IVtk'))\n"
        "print(json.dumps({'rc': rc, 'starts': starts, 'vtk': vtk}), flush=True)\n"
        "os._exit(0)\n"
    )
    env = dict(os.environ, PROPULSOR_JOBS="2")
    env.pop("MAKEFLAGS", None)
    r = subprocess.run([sys.executable, "-c", code, part, str(tmp_path / "b")], capture_output=True, text=True,
                       env=env, timeout=300)
    got = json.loads(r.stdout.strip().splitlines()[-1])
    assert got["rc"] == 0 and got["vtk"] == [], r.stderr[-2000:]
    contact = [ocp for name, ocp in got["starts"] if name in ("contact_direction", "contact_and_load")]
    assert len(contact) == 2 and contact == [False, False], got["starts"]
    assert (tmp_path / "b" / "driven.step").is_file()
    said = [line for line in r.stderr.splitlines() if "loading the CAD kernel" in line]
    assert len(said) == 1, said
    lines = [line.split("] ", 1)[-1] for line in r.stderr.splitlines() if line.startswith("[")]
    first = next(i for i, line in enumerate(lines) if "loading the CAD kernel" in line)
    assert any("as built: both directions' contact" in line for line in lines[:first]), lines
