"""Benchmark of the print kits (target: the seed-002 kit <= 30 s here, slicing excluded: --slice no), and every other part type's kit.

Times `propulsor print` as a user runs it, in a fresh process (imports included), into a temporary
folder, and splits the kit's own stages in a warm process: the printed pair's design and full-cycle
proof, the pieces (solids with the bed-side chamfer), the files (STL + mesh checks, plates, pictures).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 30.0


def cli_time(part: str) -> tuple[float, int]:
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        r = subprocess.run([sys.executable, "-m", "propulsor.cli", "print", str(ROOT / "parts" / f"{part}.toml"),
                            "--out", str(Path(d) / "kit"), "-q", "--slice", "no"], cwd=ROOT)
        return time.perf_counter() - t0, r.returncode


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
    for part in ("ncg_seed002", "final_drive", "cam_mover", "balancer", "road_wheel", "polysector"):
        wall, code = cli_time(part)
        rc = rc or code
        split = stages(part) if part == "ncg_seed002" else {}
        verdict = "" if part != "ncg_seed002" else (" (target <= 30 s: " + ("met" if wall <= TARGET_S else "MISSED") + ")")
        print(f"{part} kit: propulsor print {wall:.1f} s, exit {code}{verdict}")
        for k, v in split.items():
            print(f"    {k}: {v:.1f} s")
    return rc


if __name__ == "__main__":
    sys.exit(main())
