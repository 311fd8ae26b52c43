"""Benchmark: the whole planetary final drive part (parts/final_drive.toml), every file and check.

Run: .venv/bin/python bench/bench_final_drive.py [runs]
Budget (issue 2): <= 20 s for the part.  Prints each run's wall time and the split of the first
(sheet + outlines, carrier sweep in its own process, solids and their checks, assembly, report).

2026-12-02 (2 cores; ``carrier_sweep`` of parts/final_drive.toml, 720 steps x 6 meshes, old and new code in one
process, in turn, three rounds, CPU s): the poses' point product compiled with numpy's own rounding (``poses.apply_pose``:
one fused multiply-add a coordinate, as OpenBLAS's product does here) 3.75 / 4.13 / 4.10 -> 3.43 / 3.55 / 3.63; then the
steps where the bodies are apart in one compiled loop (``checks/motion/sweep_steps.py``: both nearest-edge searches, the
crossing and loop tests, the closest points' poses) and the windowed sweep's points moved in one call: 3.26 / 4.05 /
3.52 (the step-by-step path) -> 2.82 / 3.17 / 2.98.  Every area, clearance and point identical (sha256 of the arrays);
make's 636 files identical.  What is left of the sweep: the compiled nearest-edge search (330-500 nearest-vertex
searches a call in the meshes' teeth), the windows' outlines (279 a sweep, 1.5 ms each) and their booleans.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

from propulsor.cli import main as cli

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 20.0


def main(runs: int = 2) -> int:
    times = []
    for k in range(runs):
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            rc = cli(["build", str(ROOT / "parts" / "final_drive.toml"), "--out", str(Path(tmp) / "fd"), "-q"])
            times.append(time.perf_counter() - t0)
            if rc != 0:
                print(f"build exit {rc}")
                return 1
    med = statistics.median(times)
    print(f"final drive part (3 solids, assembly, 6 meshes x 720 sweep steps, all checks and files): "
          f"median {med:.2f} s over {runs} runs ({', '.join(f'{t:.2f}' for t in times)} s); target <= {TARGET_S:.0f} s")
    return 0 if med <= TARGET_S else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 2))
