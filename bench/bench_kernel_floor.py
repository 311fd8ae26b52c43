"""Benchmark (issue 40): the floor under a build's CPU seconds that no code of ours sets: the CAD kernel's and the
plotting library's own work on the build's outputs, and their imports.

    .venv/bin/python bench/bench_kernel_floor.py [--part parts/ncg_fourier_seed002.toml] [--repeat 3]

Issue 40 asks ``propulsor build parts/ncg_fourier_seed002.toml`` for at most 0.15 of the CPU seconds ncgears takes
to generate the 2D pair of the same law (bench/bench_vs_ncgears.py).  Part of our build is work only OCCT (through
OCP / CadQuery) and matplotlib do, on the solids and figures the build must deliver and prove on the exported files:
the solids' extrusion, the STEP files written, each wheel's STEP read back and its volume integrated (the round trip
that proves the file), OCCT's B-rep check, the meshes' triangulation (BRepMesh), the assembly STEP; the figures'
layout and rendering.  This measures that part.

Two fresh processes each round, both on one core (``PROPULSOR_JOBS=1``, every job inline: no work overlaps):

1. the imports: the interpreter alone, then the CAD kernel as the build imports it
   (:func:`propulsor.solids.cq_import.import_cadquery`), then ``matplotlib.pyplot`` (Agg), each timed by the
   process's CPU clock, the interpreter's own start-up timed by a process that imports nothing;
2. the build itself, in process, with each library entry point the build calls wrapped by a CPU-clock timer that
   counts only the outermost wrapped call (a volume inside a B-rep check is counted once, as the check's): the
   kernel's (``solids.build.extrude_profile``, ``export.step.write_step`` / ``write_assembly_step`` /
   ``read_step``, ``solids.kernel.volume``, ``checks.brep.brep_checks``, ``export.mesh.tessellate``) and
   matplotlib's (``Figure.savefig``, ``Figure.tight_layout``).  The wrapped functions hold a little of our own code
   (the extrusion's B-spline wires are built by us, in OCCT's calls): the floor is rounded down by nothing.

Printed: each share in CPU s, the floor (imports + kernel + plotting), the build's whole CPU s in that process, and
the issue's CPU budget against an ncgears time given by ``--ncgears-cpu`` (default: the last measured here).  Then
the peak resident memory of a process that does nothing but the kernel's work on one wheel's STEP file (``--wheel``),
step by step.

Measured 2026-12-05 (2 cores, idle; 8d65361; three rounds, the least of each share; ncgears 36.48 CPU s that hour):
imports 1.88 CPU s (the CAD kernel 0.95, scipy 0.29, matplotlib 0.23, trimesh 0.22, numba 0.13, numpy 0.05; ezdxf
and Pillow come with them), the kernel's work 2.01 (the STEP read back 0.59, the STEP files 0.30 + the assembly's
0.30, the triangulation 0.40, the B-rep check 0.19, the volumes 0.16, the extrusion 0.07), the other libraries' writing
0.38 (DXF 0.18, GIF 0.12, 3MF 0.08), matplotlib's layout and rendering 0.74: the floor 5.01 CPU s, 0.92 of the
issue's budget of 5.47 (0.15 x ncgears), which leaves 0.46 s for every computation of ours (the design, the proof, both
directions' as-built contact, the load per tooth, the mesh checks, the tables, the report; 3.0-3.7 CPU s today in one
process: the build 6.77-6.83 CPU s after the kernel's and matplotlib's imports, less the 3.13 of the libraries' work in
it).  The wall ratio's budget, 0.1 x ncgears' 34.79 s = 3.48 s, is less than the floor spread over both cores with our
computation at nothing (5.01 / 2 = 2.5 s, of which the kernel's import, 0.95 s, runs before any of the build's work
can be handed to a second process).  Memory (``driven.step``, 4.3 MiB): the kernel imported 346 MiB, the STEP read
back with its volume and B-rep check 385, the mesh export's modules (trimesh, scipy) 436, the STEP written and the
triangulation 464: the process that proves the driven wheel's files alone exceeds the issue's 400 MiB.  The same in a
fresh clone (the CI's, its venv just installed; f0e3d56): the kernel imported 403-404 MiB (three processes), then 442,
501, 529: the kernel's shared libraries are mapped further where their files are wholly in the page cache (the
resident pages of ``OCP.cpython-311-x86_64-linux-gnu.so`` 136 MiB there, 115 here; ``/proc/self/smaps``), and that
build's largest process peaked at 721 MiB (bench_vs_ncgears.py; 632-646 here).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: ncgears 0.3.1 on the Fourier seed-002 law, CPU s of the whole process (bench_vs_ncgears.py, 2026-12-05, idle)
NCGEARS_CPU_S = 36.07

_IMPORTS = r"""
import json, sys, time
out = {}
t = time.process_time()
def lap(name):
    global t
    now = time.process_time()
    out[name] = now - t
    t = now
import numpy
lap("numpy")
import scipy.interpolate, scipy.ndimage, scipy.optimize, scipy.spatial
lap("scipy")
import numba
lap("numba")
from propulsor.solids.cq_import import import_cadquery
import_cadquery()
lap("CAD kernel")
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot
lap("matplotlib")
import trimesh
lap("trimesh")
import ezdxf
lap("ezdxf")
import PIL.Image
lap("Pillow")
print(json.dumps(out))
"""

_BUILD = r"""
import json, os, sys, tempfile, time
os.environ["PROPULSOR_JOBS"] = "1"
part = sys.argv[1]
shares = {}
depth = [0]

def timed(share, fn):
    def run(*a, **k):
        if depth[0]:
            return fn(*a, **k)
        depth[0] += 1
        t = time.process_time()
        try:
            return fn(*a, **k)
        finally:
            shares[share] = shares.get(share, 0.0) + time.process_time() - t
            depth[0] -= 1
    return run

from propulsor.solids.cq_import import import_cadquery
import_cadquery()
import matplotlib
matplotlib.use("Agg")
import matplotlib.figure
import propulsor.checks.brep as brep
import propulsor.export.mesh as emesh
import propulsor.export.step as step
import propulsor.solids.build as sbuild
import propulsor.solids.kernel as kernel

for mod, name, share in ((sbuild, "extrude_profile", "kernel: extrusion"),
                         (step, "write_step", "kernel: STEP written"),
                         (step, "write_assembly_step", "kernel: assembly STEP written"),
                         (step, "read_step", "kernel: STEP read back"),
                         (kernel, "volume", "kernel: volumes"),
                         (brep, "volume", "kernel: volumes"),
                         (brep, "brep_checks", "kernel: B-rep check"),
                         (emesh, "tessellate", "kernel: triangulation")):
    setattr(mod, name, timed(share, getattr(mod, name)))
import ezdxf.document
import trimesh.exchange.threemf as threemf
import propulsor.export.animation as anim
ezdxf.document.Drawing.saveas = timed("libraries: DXF written (ezdxf)", ezdxf.document.Drawing.saveas)
threemf.export_3MF = timed("libraries: 3MF written (trimesh)", threemf.export_3MF)
anim.encode_gif = timed("libraries: GIF encoded (Pillow)", anim.encode_gif)
for name, share in (("savefig", "plots: rendering"), ("tight_layout", "plots: layout")):
    setattr(matplotlib.figure.Figure, name, timed(share, getattr(matplotlib.figure.Figure, name)))

from propulsor.cli import main
out = tempfile.mkdtemp()
t0 = time.process_time()
try:
    main(["build", part, "--out", os.path.join(out, "b"), "--quiet"])
except SystemExit as exc:
    if exc.code:
        raise
whole = time.process_time() - t0
print(json.dumps({"shares": shares, "build": whole, "out": os.path.join(out, "b")}), flush=True)
os._exit(0)
"""


_MEMORY = r"""
import json, resource, sys, tempfile
from pathlib import Path
def peak():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
out = {}
from propulsor.solids.cq_import import import_cadquery
import_cadquery()
from propulsor.export.step import read_step_solids, write_step
from propulsor.solids.kernel import volume
from propulsor.checks.brep import brep_checks
out["the CAD kernel imported"] = peak()
s = read_step_solids(sys.argv[1], as_written=True)[0]
v = volume(s)
brep_checks(s, "wheel", cross_check_volume=False, volume_mm3=v)
out["... and the wheel's STEP read back, its volume and B-rep check"] = peak()
import cadquery as cq
from propulsor.export.mesh import tessellate
out["... and the mesh export's modules (trimesh) imported"] = peak()
shape = cq.Shape.cast(s)
write_step(shape, Path(tempfile.mkdtemp()) / "wheel.step", "wheel")
tessellate(shape, parallel=False)
out["... and its STEP written and its triangulation"] = peak()
print(json.dumps(out))
"""


def _run(code: str, *args: str) -> dict:
    env = dict(os.environ, PROPULSOR_JOBS="1", OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    r = subprocess.run([sys.executable, "-c", code, *args], cwd=ROOT, env=env, capture_output=True, text=True,
                       check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default="parts/ncg_fourier_seed002.toml")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--ncgears-cpu", type=float, default=NCGEARS_CPU_S)
    ap.add_argument("--wheel", default="driven.step", help="the part's STEP file the memory is measured on")
    a = ap.parse_args()
    bare = []
    for _ in range(3):
        r = subprocess.run([sys.executable, "-c", "import time; print(time.process_time())"], capture_output=True,
                           text=True, check=True)
        bare.append(float(r.stdout))
    best: dict[str, float] = {}
    builds = []
    for _ in range(a.repeat):
        imp = _run(_IMPORTS)
        b = _run(_BUILD, a.part)
        builds.append(b["build"])
        for k, v in (("imports: interpreter", min(bare)), *((f"imports: {m}", x) for m, x in imp.items()),
                     *b["shares"].items()):
            best[k] = min(best.get(k, float("inf")), v)
    floor = sum(best.values())
    wheel = Path(b["out"]) / a.wheel
    mem = _run(_MEMORY, str(wheel))
    budget = 0.15 * a.ncgears_cpu
    for k in sorted(best):
        print(f"{k:34s} {best[k]:6.2f} CPU s")
    print(f"{'floor (least of each)':34s} {floor:6.2f} CPU s")
    print(f"the build in one process: {' / '.join(f'{x:.2f}' for x in builds)} CPU s (after the imports above)")
    print(f"issue 40's CPU budget: 0.15 x ncgears {a.ncgears_cpu:.2f} = {budget:.2f} CPU s; the floor is "
          f"{floor / budget:.2f} of it")
    print(f"a process doing only the kernel's work on {wheel.name} ({wheel.stat().st_size / 2**20:.1f} MiB):")
    for k, v in mem.items():
        print(f"peak resident memory, {k}: {v:.0f} MiB")


if __name__ == "__main__":
    main()
