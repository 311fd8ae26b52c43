"""Per-stage profile of every part build (issue 13): each part file built as `make` builds it, in a fresh
process, its progress lines timed; written as a table to bench/results/build_stages.md and printed.

A stage is the time from one progress line to the next (the last one to the process's end); the
first rows are the interpreter with the CLI's imports and the part file's loading up to the first
progress line.  Stages
that run in forked workers beside the main process (STEP/STL/3MF and their checks, the balancer's
sweep) overlap the ones listed after them: the main process's line marks when it waits for them.
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "bench" / "results" / "build_stages.md"
#: a part build should take at most this long here (issue 13)
PART_TARGET_S = 20.0
LINE = re.compile(r"^\[\s*([0-9.]+) s\] (.*)$")


def profile(part_file: Path) -> tuple[float, int, list[tuple[str, float]]]:
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", str(part_file), "--out",
                            str(Path(d) / part_file.stem)], cwd=ROOT, capture_output=True, text=True)
        wall = time.perf_counter() - t0
    marks = [(float(m.group(1)), m.group(2)) for m in map(LINE.match, r.stderr.splitlines()) if m]
    stages = []
    if marks:
        # progress times count from the command's start (after the CLI's imports); the last line is
        # printed as the process ends
        stages.append(("start-up (interpreter, CLI imports, exit)", max(0.0, wall - marks[-1][0])))
        stages.append(("loading and validating the part file", marks[0][0]))
    for k, (t, msg) in enumerate(marks):
        t_next = marks[k + 1][0] if k + 1 < len(marks) else t
        stages.append((msg, t_next - t))
    return wall, r.returncode, stages


def main() -> int:
    rows = []
    rc = 0
    lines = ["# Build stages of every part file", "", f"Measured {time.strftime('%Y-%m-%d %H:%M')} on this machine "
             f"(`python bench/bench_build_stages.py`); target: every part <= {PART_TARGET_S:g} s.", ""]
    total = 0.0
    for f in sorted((ROOT / "parts").glob("*.toml")):
        wall, code, stages = profile(f)
        rc = rc or (code not in (0,))
        total += wall
        rows.append((f.stem, wall, code))
        lines += [f"## {f.stem}: {wall:.1f} s, exit {code}" + ("" if wall <= PART_TARGET_S else " (over target)"), "",
                  "| stage | s |", "|---|---:|"]
        lines += [f"| {msg.replace('|', '/')} | {dt:.2f} |" for msg, dt in sorted(stages, key=lambda s: -s[1])[:12]]
        lines.append("")
        print(f"{f.stem:24s} {wall:6.1f} s  exit {code}", flush=True)
    lines[3:3] = ["| part | s | exit |", "|---|---:|---:|"] + [f"| {n} | {w:.1f} | {c} |" for n, w, c in rows] + \
                 [f"| **total** | **{total:.1f}** | |", ""]
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("\n".join(lines) + "\n")
    print(f"total {total:.1f} s; table in {OUT.relative_to(ROOT)}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
