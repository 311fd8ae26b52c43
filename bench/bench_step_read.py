"""Benchmark (issue 40): the STEP round trip's read — OCCT's full shape healing against the read the checks use.

    .venv/bin/python bench/bench_step_read.py [OUTPUT_FOLDER]   (default: output, what ``make`` built)

Every ``*.step`` under the folder is read twice by :func:`propulsor.export.step.read_step`, each read timed whole
(parse, transfer, healing) by the process's CPU clock: once as ``propulsor check`` reads anyone's file (OCCT's
FixShape healing with every fix at its default), once as the round trip reads a file it wrote (:func:`propulsor.export.step.read_step` ``as_written``: the fixes of
``export.step.UNHEALED`` left out).  Each pair of shapes is
written as BREP text and compared byte for byte: the fixes left out must change nothing on the files the builds
write (a file where they would is read as written, and its round-trip check fails: tests/test_checks.py).

Measured (2026-12-01, 2 cores, the 78 STEP files of ``make``, each read once per way, in one process): with eight
fixes left out (570f1a4: the wires' orientation too) on an idle machine 24.29 -> 10.05 CPU s of transfer, every BREP
identical; but the wires' orientation fix is what makes a CadQuery union's STEP (examples/custom_flange.py) mesh at
all, so it is kept, and the read without the others is the round trip's alone (``propulsor check`` reads anyone's file
with the whole healing).  The seven left out, CI's tests running beside (all ways slower alike): OCCT's default read
29.64 CPU s, without the five searches for crossing edges and wires 22.58, also without the shells' face orientation
18.56, also without the same-parameter repair 15.39 (52 %); every BREP identical.  Before 570f1a4 the parameters
were set before ``ReadFile``, which makes the transfer's actor anew: they did nothing.  Those figures timed the
transfer alone, through a copy of the reader's steps; since 2026-12-01 (a later session) the benchmark times
``read_step`` itself, whole (parse, transfer, healing), both ways: on an idle machine 36.51 -> 24.76 CPU s (68 %),
every BREP identical.

2026-12-05 (2 cores; the 62 part STEP files of make, which the round trip reads): parse 3.7-4.1 CPU s, transfer
4.2-4.8 (perf: the lexer and parser 11 %, malloc / calloc / free 17 %).  OCCT's memory manager by environment
(MMGT_OPT=1 or 2, MMGT_CLEAR=0): no change (4.39-4.48 s).  Each further FixShape mode off, alone, on every third file
(21; transfer 1.53-1.58 s with the modes above off): the wires' orientation (FixOrientationMode) 1.24 s, BREP
identical, but a CadQuery union needs it; FixEdgeCurvesMode and FixShiftedMode change 18 files; the 24 others within
0.05-0.17 s of the spread, together 1.22 s with one file changed, the four cheapest together (FixNotchedEdgesMode,
FixAddPCurveMode, AutoCorrectPrecisionMode, FixConnectedMode) 1.38 s, none changed: about 0.3 CPU s of make's, not
taken (each mode left out is one more kind of defect the round trip reads as written, to be shown on a union).
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _timed_read(path: Path, as_written: bool):
    """:func:`propulsor.export.step.read_step` whole (parse, transfer and healing), timed by the CPU clock."""
    from propulsor.export.step import read_step

    t0 = time.process_time()
    shape = read_step(path, as_written)
    return shape, time.process_time() - t0


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
        a, ta = _timed_read(f, False)
        b, tb = _timed_read(f, True)
        t_default += ta
        t_ours += tb
        if _brep(a) != _brep(b):
            differ.append(f)
    print(f"{len(files)} STEP files under {folder}: read {t_default:.2f} CPU s with OCCT's whole healing, "
          f"{t_ours:.2f} s as the round trip reads them ({t_ours / t_default:.0%}); BREP text different: "
          f"{len(differ)}" + "".join(f"\n  {p}" for p in differ))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
