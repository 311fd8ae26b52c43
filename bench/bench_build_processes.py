"""Benchmark (issue 40): where one build's wall goes among its processes.

    .venv/bin/python bench/bench_build_processes.py [part file] [--every S]

Builds the part file (default ``parts/ncg_fourier_seed002.toml``, the build compared with ncgears) into a temporary
folder, as ``propulsor build`` does on this machine's cores, and samples every ``--every`` seconds (0.03) the build's
process tree (``/proc``: each process's CPU time, when it was first and last seen) and the machine's busy cores
(``/proc/stat``).  It prints each process (the main one first, then the forked ones by start: the design, the
solids' files, the contact jobs, the files written beside the build ...), the CPU seconds of the main process and of
the workers, and the stretches where a core stood idle.  A build whose main process's CPU is near its wall less its
waits has the main process as its critical path: moving work out of it, or making that work cheaper, is what
shortens the wall; a build with both cores busy throughout is bound by its CPU alone.

Measured (2 cores, idle; the Fourier pair): 6fe32a6, the main process 5.99 CPU s of a 7.9 s wall, the workers 5.8
together, one core idle 0-1.1 s (the design's imports), 1.8-2.6 s (the solids made in the main process) and from 5.8 s
on (the main process alone); f1f6769 (the assembly STEP and the DXF beside the build, the contact jobs started before
the solids), the main process 4.99 CPU s of a 7.0 s wall.
2026-12-04, a new session (2 cores, idle; the Fourier pair): at c69f764 (the garbage collector tuned) the main process
6.33 CPU s of an 8.98 s wall, one core idle 0-1.25 s, 2.40-2.98 s (the design done, the main process still importing
what the solids' workers run before it could start the contact jobs) and from 7.57 s on; at 9764c52 (the contact jobs
started before the whole-cycle proof, the solids' workers by the first solid) 7.82 / 8.29 s wall, the stretch after
the design gone: a core idle 0-1.0 s and from 6.3-6.5 s on only.  What is left idle is the imports before the design
can fork (both processes need them) and the main process's own end (the as-built and load values, their plots, the
report).  Tried and not kept: the workers at a lower priority (``os.nice`` 5 / 10 in each forked worker), eight paired
rounds: mean wall 7.32 -> 7.20 s (6 of 8 faster, two much slower), the machine's swing as large; matplotlib imported in
the warm-up beside the design, eight paired rounds: 6.54 -> 6.55 s.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TICK = os.sysconf("SC_CLK_TCK")


def _children(pid: int) -> list[int]:
    out = []
    try:
        for t in os.listdir(f"/proc/{pid}/task"):
            with open(f"/proc/{pid}/task/{t}/children") as f:
                for c in f.read().split():
                    out.append(int(c))
                    out += _children(int(c))
    except OSError:
        pass
    return out


def _cpu(pid: int) -> float | None:
    """utime + stime of a process (s), None once it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            v = f.read().rsplit(")", 1)[1].split()
        return (int(v[11]) + int(v[12])) / TICK
    except (OSError, IndexError, ValueError):
        return None


def _busy() -> tuple[int, int]:
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    return sum(v), v[3] + v[4]


def sample(cmd: list[str], every: float):
    """(wall, {pid: [first seen, last seen, cpu]}, [(t, busy cores)]) of a command run to its end."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seen: dict[int, list] = {}
    cores = []
    last = _busy()
    while p.poll() is None:
        now = time.perf_counter() - t0
        for q in [p.pid] + _children(p.pid):
            c = _cpu(q)
            if c is None:
                continue
            row = seen.setdefault(q, [now, now, c])
            row[1], row[2] = now, c
        b = _busy()
        if b[0] > last[0]:
            cores.append((now, (os.cpu_count() or 1) * (1.0 - (b[1] - last[1]) / (b[0] - last[0]))))
        last = b
        time.sleep(every)
    return time.perf_counter() - t0, p.pid, p.returncode, seen, cores


def idle_stretches(cores, n_cores: int, every: float, min_len: float = 0.3):
    """Stretches of at least ``min_len`` s where fewer than all cores were busy (more than half a core idle)."""
    out, start = [], None
    for t, busy in cores:
        if busy < n_cores - 0.5:
            start = t if start is None else start
        else:
            if start is not None and t - start >= min_len:
                out.append((start, t))
            start = None
    if start is not None and cores and cores[-1][0] - start >= min_len:
        out.append((start, cores[-1][0]))
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("part", nargs="?", type=Path, default=ROOT / "parts" / "ncg_fourier_seed002.toml")
    ap.add_argument("--every", type=float, default=0.03, help="sampling interval, s")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [sys.executable, "-m", "propulsor", "build", str(a.part), "--out", str(Path(tmp) / "out")]
        wall, main_pid, code, seen, cores = sample(cmd, a.every)
    n = os.cpu_count() or 1
    main_cpu = seen.get(main_pid, [0, 0, 0.0])[2]
    workers = {q: r for q, r in seen.items() if q != main_pid}
    idle = sum(max(0.0, n - busy) * a.every for _, busy in cores)
    print(f"{a.part.name}: exit {code}, wall {wall:.2f} s on {n} cores; main process {main_cpu:.2f} CPU s, "
          f"{len(workers)} forked processes {sum(r[2] for r in workers.values()):.2f} CPU s; about {idle:.1f} "
          f"core-s idle")
    print(f"  main   {seen.get(main_pid, [0, 0])[0]:5.2f} -> {seen.get(main_pid, [0, 0])[1]:5.2f} s  "
          f"{main_cpu:5.2f} CPU s")
    for q, (first, last, c) in sorted(workers.items(), key=lambda kv: kv[1][0]):
        print(f"  forked {first:5.2f} -> {last:5.2f} s  {c:5.2f} CPU s")
    for s, e in idle_stretches(cores, n, a.every):
        print(f"  a core idle {s:5.2f} -> {e:5.2f} s")
    return code


if __name__ == "__main__":
    sys.exit(main())
