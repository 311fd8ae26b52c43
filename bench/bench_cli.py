"""Whole-process wall time of the commands that need no CAD kernel, and of `import propulsor`.

Targets: `propulsor params noncircular_pair` and `propulsor list` ≤ 0.5 s, `import propulsor` ≤ 0.3 s
(best of 5 runs each, here)."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RUNS = 5
CASES = [
    ("import propulsor", [sys.executable, "-c", "import propulsor"], 0.3),
    ("propulsor --help", [sys.executable, "-m", "propulsor.cli", "--help"], 0.5),
    ("propulsor list", [sys.executable, "-m", "propulsor.cli", "list"], 0.5),
    ("propulsor params noncircular_pair", [sys.executable, "-m", "propulsor.cli", "params", "noncircular_pair"], 0.5),
    ("propulsor params cam_mover", [sys.executable, "-m", "propulsor.cli", "params", "cam_mover"], None),
    ("propulsor build parts/final_drive.toml --dry-run",
     [sys.executable, "-m", "propulsor.cli", "build", "parts/final_drive.toml", "--dry-run"], None),
]


def main() -> int:
    bad = 0
    for name, cmd, target in CASES:
        times = []
        for _ in range(RUNS):
            t0 = time.perf_counter()
            subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            times.append(time.perf_counter() - t0)
        best = min(times)
        verdict = "" if target is None else (" ok" if best <= target else f" OVER the {target} s target")
        bad += target is not None and best > target
        print(f"{name:48s} best {best:6.3f} s  median {sorted(times)[RUNS // 2]:6.3f} s"
              f"{'' if target is None else f'  (target ≤ {target} s)'}{verdict}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
