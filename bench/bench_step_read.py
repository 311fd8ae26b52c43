"""Benchmark (issue 40): the STEP round trip's read — OCCT's full shape healing against the read the checks use.

    .venv/bin/python bench/bench_step_read.py [OUTPUT_FOLDER]   (default: output, what ``make`` built)

Every ``*.step`` under the folder is read twice, each read's transfer timed by the process's CPU clock: once as
OCCT's STEPControl_Reader reads it by default (its FixShape healing with every fix at its default), once as the
round trip reads a file it wrote (:func:`propulsor.export.step.read_step` ``as_written``: the fixes of
``export.step.UNHEALED`` left out).  Each pair of shapes is
written as BREP text and compared byte for byte: the fixes left out must change nothing on the files the builds
write (a file where they would is read as written, and its round-trip check fails: tests/test_checks.py).

Measured (2026-12-01, 2 cores, idle; the 78 STEP files of ``make`` at 570f1a4, each read once per way): OCCT's
default read 24.29 CPU s of transfer, ours 10.05 s (41 %); every BREP identical.  Which fixes cost: the five
searches for crossing edges and wires 24.3 -> 18.5 s, the shells' face orientation 18.5 -> 14.9 s, same-parameter
and wire orientation 14.9 -> 10.1 s; the fixes of solids, shells, faces, wires and edge curves do change the shapes
read (tolerances, and on some files the volume in the last digits) and are kept.  Before 570f1a4 the parameters
were set before ``ReadFile``, which makes the transfer's actor anew: they did nothing.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _default_read(path: Path):
    from OCP.STEPControl import STEPControl_Reader

    r = STEPControl_Reader()
    r.ReadFile(str(path))
    t0 = time.process_time()
    r.TransferRoots()
    return r.OneShape(), time.process_time() - t0


def _our_read(path: Path):
    from OCP.STEPControl import STEPControl_Reader

    from propulsor.export.step import _fix_parameters

    r = STEPControl_Reader()
    r.ReadFile(str(path))
    r.SetShapeFixParameters(_fix_parameters())  # as read_step sets them: after ReadFile
    t0 = time.process_time()
    r.TransferRoots()
    return r.OneShape(), time.process_time() - t0


def _brep(shape) -> bytes:
    from OCP.BRepTools import BRepTools

    with tempfile.NamedTemporaryFile(suffix=".brep") as f:
        BRepTools.Write_s(shape, f.name)
        return Path(f.name).read_bytes()


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    folder = Path(argv[0]) if argv else ROOT / "output"
    files = sorted(folder.rglob("*.step"))
    if not files:
        print(f"no STEP file under {folder}: run make first", file=sys.stderr)
        return 2
    t_default = t_ours = 0.0
    differ = []
    for f in files:
        a, ta = _default_read(f)
        b, tb = _our_read(f)
        t_default += ta
        t_ours += tb
        if _brep(a) != _brep(b):
            differ.append(f)
    print(f"{len(files)} STEP files under {folder}: transfer {t_default:.2f} CPU s with OCCT's default healing, "
          f"{t_ours:.2f} s as the round trip reads them ({t_ours / t_default:.0%}); BREP text different: "
          f"{len(differ)}" + "".join(f"\n  {p}" for p in differ))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
