"""Benchmark of the print kits (target: the seed-002 kit <= 30 s wall here on an idle machine, slicing
excluded: --slice no), and every other part type's kit.

Times `propulsor print` as a user runs it, in a fresh process (imports included), into a temporary
folder: wall time and CPU time (the process and its workers).  The seed-002 kit is timed twice: with
`--slice no` (the target) and with `--slice yes` (PrusaSlicer slicing every plate, what `make print` and
the default `--slice auto` do where PrusaSlicer is installed), the slicing's share stated apart.  The
kit's own stages are split in a warm process: the printed pair's design and full-cycle proof, the
pieces (solids with the bed-side chamfer), the files (STL + mesh checks, plates, pictures).

2026-12-02 (2 cores, idle; in one process, the seed-002 kit's 12 chamfers recorded and replayed, old and new in turn,
three rounds): the bed-side chamfers 2.14 / 1.83 / 1.97 -> 1.05 / 1.11 / 1.11 CPU s, every piece's vertices and faces
identical (the mesh's open edges found by numpy rather than a set of every edge; the bands' triangles indexed at once
rather than point by point).  The kit's 31 files identical to the old code's (``--slice no``).  Reading the sliced
plates' G-code 3.1x faster the same day (bench_gcode_read.py): the seed-002 kit's plate 2, 2.3 -> 0.75 CPU s.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 30.0


def _children_cpu() -> float:
    import resource

    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def cli_time(part: str, slice_: str = "no") -> tuple[float, float, int]:
    """(wall s, CPU s of the process and everything it ran, exit code) of `propulsor print PART --slice`."""
    with tempfile.TemporaryDirectory() as d:
        c0, t0 = _children_cpu(), time.perf_counter()
        r = subprocess.run([sys.executable, "-m", "propulsor.cli", "print", str(ROOT / "parts" / f"{part}.toml"),
                            "--out", str(Path(d) / "kit"), "-q", "--slice", slice_], cwd=ROOT)
        return time.perf_counter() - t0, _children_cpu() - c0, r.returncode


def stages(part: str) -> dict:
    from propulsor.params import load_params, read_part_file
    from propulsor.parts import get_kit, get_part_type
    from propulsor.parts.writer import OutputWriter
    from propulsor.printing.kit import write_kit
    from propulsor.printing.printers import load_printer

    name, mapping = read_part_file(ROOT / "parts" / f"{part}.toml")
    pt = get_part_type(name)
    p = load_params(pt.params_cls, mapping)
    t0 = time.perf_counter()
    kit = get_kit(name)(p, load_printer("generic"), None, source=ROOT / "parts" / f"{part}.toml")
    t1 = time.perf_counter()
    with tempfile.TemporaryDirectory() as d:
        w = OutputWriter(Path(d), name, p)
        write_kit(kit, w)
        w.finish()
    t2 = time.perf_counter()
    return {"kit (design, proof, pieces)": t1 - t0, "files (STL, checks, plates, pictures)": t2 - t1}


def main() -> int:
    rc = 0
    from propulsor.printing.slicer import slicer_path

    for part in ("ncg_seed002", "final_drive", "cam_mover", "balancer", "road_wheel", "polysector"):
        wall, cpu, code = cli_time(part)
        rc = rc or code
        split = stages(part) if part == "ncg_seed002" else {}
        verdict = "" if part != "ncg_seed002" else (" (target <= 30 s wall: " + ("met" if wall <= TARGET_S else "MISSED") + ")")
        print(f"{part} kit: propulsor print --slice no {wall:.1f} s wall, {cpu:.1f} s CPU, exit {code}{verdict}")
        for k, v in split.items():
            print(f"    {k}: {v:.1f} s")
        if part == "ncg_seed002":
            if slicer_path() is None:
                print("    --slice yes: not timed (PrusaSlicer is not installed)")
            else:
                w2, c2, code2 = cli_time(part, "yes")
                rc = rc or code2
                print(f"    --slice yes (the default --slice auto with PrusaSlicer installed): {w2:.1f} s wall, "
                      f"{c2:.1f} s CPU, exit {code2}; the slicing: {w2 - wall:.1f} s wall, {c2 - cpu:.1f} s CPU")
    return rc


if __name__ == "__main__":
    sys.exit(main())
