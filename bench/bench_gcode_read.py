"""Benchmark: reading where a plate's G-code lays filament (:func:`propulsor.printing.slicer.extrusion_extents`, the
check of every sliced plate that no extrusion leaves the bed).

    .venv/bin/python bench/bench_gcode_read.py [GCODE ...]

Without a file: the seed-002 kit (``propulsor print parts/ncg_seed002.toml --slice no``) is made in a temporary folder
and its plate of most bytes sliced by PrusaSlicer with the generic printer (skipped, exit 0, where PrusaSlicer is not
installed).  Each file is read three times, each timed by the process's CPU clock; the lines and moves are printed.

2026-12-02 (2 cores, idle; the seed-002 kit's plate 2, 13.8 MB, 476 000 G1 lines of which 461 751 extrude): the
line-by-line reading (a comment split, upper case, the word search, a dict of the words, every line) 2.29 / 2.36 CPU
s; with PrusaSlicer's own move line (``G1 X.. Y..`` with an E or an F or neither) matched whole first, 0.73 / 0.76
(3.1x).  The result identical (every key, value and line) on that file and on 3 300 random files of lines of every
kind the reader knows (moves, resets, mode changes, widths, lower case, comments, numbers of every form); the test
``tests/test_plates_slicer.py::test_the_printer_s_own_move_lines_read_as_any_line_with_the_same_words`` holds the
two readings of a line equal.  PrusaSlicer's slicing of the same plate takes 21 s wall (41 CPU s), and its G-code of
the same plate file is not the same from one run to the next (461 751, then 461 758 extruding moves: its threads).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _sliced_plate(work: Path) -> Path | None:
    from propulsor.printing.printers import load_printer
    from propulsor.printing.slicer import slicer_path

    exe = slicer_path()
    if exe is None:
        return None
    kit = work / "kit"
    subprocess.run([sys.executable, "-m", "propulsor.cli", "print", str(ROOT / "parts" / "ncg_seed002.toml"),
                    "--out", str(kit), "-q", "--slice", "no"], cwd=ROOT, check=True)
    plate = max(kit.glob("plate_*.3mf"), key=lambda p: p.stat().st_size)
    gcode = work / "plate.gcode"
    subprocess.run([exe, "--export-gcode", "--dont-arrange", *load_printer("generic").slicer_args(), "--output",
                    str(gcode), str(plate)], check=True, capture_output=True)
    return gcode


def main(argv=None) -> int:
    from propulsor.printing.slicer import extrusion_extents

    files = [Path(a) for a in (sys.argv[1:] if argv is None else argv)]
    work = Path(tempfile.mkdtemp(prefix="bench_gcode_"))
    try:
        if not files:
            g = _sliced_plate(work)
            if g is None:
                print("PrusaSlicer is not installed (apt-get install prusa-slicer): nothing to read")
                return 0
            files = [g]
        for f in files:
            times = []
            for _ in range(3):
                t0 = time.process_time()
                with open(f, encoding="utf-8", errors="replace") as fh:
                    e = extrusion_extents(fh)
                times.append(time.process_time() - t0)
            with open(f, "rb") as fh:
                lines = sum(1 for _ in fh)
            print(f"{f.name}: {f.stat().st_size / 1e6:.1f} MB, {lines} lines, {e['moves']} extruding moves; "
                  f"CPU s a reading {' / '.join(f'{t:.3f}' for t in times)}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
