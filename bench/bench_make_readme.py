"""The README's build, ``make`` from clean into ./output (the gallery and make's own steps included), an old revision
against the working tree, alternating (issue 40: <= 60 s wall on two idle cores).

    python bench/bench_make_readme.py OLD_REV [ROUNDS]      # e.g. a17bb8d 2

OLD_REV is checked out in a worktree in a temporary folder (git worktree, removed at the end) that uses this checkout's
venv (a link to .venv; its src/ first on PYTHONPATH, its compiled kernels made once before the first round, about a
minute; its pyproject.toml and constraints.txt dated back, so that make does not take the venv for out of date).  Each
round runs ``make`` from clean (output/ removed) in the new tree, then in the old one, each timed by GNU time: wall,
user and system CPU s, the largest resident set of any of its processes (MiB).  The machine's speed swings by a
quarter within minutes: compare the trees within a round.

2026-12-04 (2 cores; a17bb8d against the working tree of a6049be / 98f615d): the README's ``make`` wrote the
gallery, 38 MB with every part's 3D model, 19 times (each build rewrote it after its output was in place, under its
lock) and make then a 20th time; now a ``propulsor build`` of several part files writes it once after the last, in
pieces (its peak 150 -> 33 MB), and make's own gallery step only renews its time stamp when nothing but the builds
changed.  Rounds, new / old, wall (user) s: 64.10 (114.9) / 68.58 (119.9), 67.42 (121.4) / 73.06 (127.9) with the
gallery change; 69.70 (128.1) / 74.78 (131.2), 70.31 (130.1) / 76.05 (131.7) with the cap twins and the hub height
too (the machine slower by then): 4.5-5.7 s (7 %) less a round; largest process 649 / 647-659 MiB.  This script,
the machine slower still (0cd4c91): 81.93 / 81.23, 72.91 / 81.85, 75.22 / 81.12 s wall (149.0 / 142.4, 132.9 / 143.8,
138.7 / 142.4 user s; system 6.1-6.9 / 10.3-10.8 s, the pages not written); largest process 632-633 / 633-641 MiB.
678c73b, the machine 1.55 times slower than 2026-12-03's quiet minute (bench_variant.py's least 2.42 against 1.57):
92.35 / 104.63 s wall (162.4 / 174.6 user, 12.3 / 22.5 sys s); make alone on a fresh clone then 91.44 s (162.5 user).
2026-12-04, a new session, the machine at its quiet speed for once (bench_variant.py's least 1.60, 1.57 quiet): make
alone on the fresh clone of CI (006a1e5, its 636 files identical to bench/hashes) 64.2 s wall (117.4 user + 5.8 sys
s, largest process 746 MiB); the cores idle 4.2 core-s of it (/proc/stat every 0.25 s: 2.6 before the first build
forks, the imports and estimates of one process; 1.6 after the last); a minute later (least 1.71) 68.0 s (123.9 +
5.9).  So make is CPU-bound, wall = (CPU + 4 core-s idle) / 2: 60 s needs about 8 CPU s (7 %) less.  Again on
that clone (006a1e5, least 1.59), sampled every 0.05 s: 62.4 s wall; one core busy from 0 to 2.8 s (make, then the
batch's imports 2.2 s and estimates 0.2 s, which every build needs before it forks), both from 2.8 to 62.0 s, the
gallery's 0.3 s alone at the end: 3.2 core-s idle, so 60 s needs about 5 CPU s (4 %) less.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run(tree: Path, env: dict) -> tuple[float, float, float, float]:
    """(wall s, user s, system s, largest resident set MiB) of ``make`` from clean in `tree`."""
    shutil.rmtree(tree / "output", ignore_errors=True)
    times = tree / ".make-time"
    subprocess.run(["/usr/bin/time", "-f", "%e %U %S %M", "-o", str(times), "make"], cwd=tree, env=env, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall, user, system, rss_kb = map(float, times.read_text().split())
    times.unlink()
    return wall, user, system, rss_kb / 1024.0


def main(old_rev: str, rounds: int = 2) -> int:
    old = Path(tempfile.mkdtemp(prefix="bench-make-")) / old_rev
    subprocess.run(["git", "worktree", "add", "-f", "--detach", str(old), old_rev], cwd=ROOT, check=True,
                   capture_output=True)
    try:
        (old / ".venv").symlink_to(ROOT / ".venv")
        for name in ("pyproject.toml", "constraints.txt"):  # older than the venv's stamp: no reinstall
            os.utime(old / name, (0, 0))
        base = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "PYTHONPATH")}
        old_env = dict(base, PYTHONPATH=str(old / "src"))
        subprocess.run([str(ROOT / ".venv" / "bin" / "python"), "-c",
                        "from propulsor.checks.kernels import warm; warm()"], cwd=old, env=old_env, check=True)
        for k in range(rounds):
            for name, tree, env in (("new", ROOT, base), ("old", old, old_env)):
                wall, user, system, rss = run(tree, env)
                print(f"round {k + 1} {name}: {wall:.2f} s wall, {user:.1f} user + {system:.1f} sys s, "
                      f"largest process {rss:.0f} MiB", flush=True)
    finally:
        subprocess.run(["git", "worktree", "remove", "--force", str(old)], cwd=ROOT, capture_output=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 2))
