"""The dry run's size estimate of every part file against the build it estimates (issue 39: "the size estimates
said 11.6 s for builds that took 34-76 s").

    python bench/bench_size_estimates.py [parts/*.toml ...]

Each part file is built as a user builds it (``propulsor build FILE --out TMP -q``, a fresh process), its CPU
seconds measured (the process and its forked workers: ``RUSAGE_CHILDREN``) with its wall time; the estimate is
the part type's model (``parts.size``) of the same parameters.  The model is calibrated in CPU seconds, which a
loaded machine changes little, and states its wall time on two idle cores as CPU / ``size._CORES_USED``.
Prints, and writes to bench/results/size_estimates.md, one row per part file: the estimate's CPU seconds, the
measured CPU seconds, their ratio, the measured wall and the machine's load meanwhile.  Target: every ratio
within 0.67 .. 1.5.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "bench" / "results" / "size_estimates.md"
RATIO_BAND = (0.67, 1.5)


def estimate_cpu(part_file: Path) -> tuple[float, str, str]:
    """(estimated CPU s, what it counts, part type) of a part file."""
    from propulsor.building import load
    from propulsor.parts import size

    loaded = load(part_file)
    est = loaded.estimate
    return est.seconds * size._CORES_USED, est.detail, loaded.part_type.name


def measure(part_file: Path) -> tuple[float, float, float]:
    """(CPU s, wall s, mean load) of one build in a fresh process."""
    with tempfile.TemporaryDirectory() as d:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        load0 = os.getloadavg()[0]
        t0 = time.perf_counter()
        r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", str(part_file), "--out",
                            str(Path(d) / part_file.stem), "-q"], cwd=ROOT, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if r.returncode != 0:
            raise SystemExit(f"{part_file}: build failed ({r.returncode}): {r.stderr[-500:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, 0.5 * (load0 + os.getloadavg()[0])


def main(argv: list[str]) -> int:
    files = [Path(a) for a in argv] or sorted((ROOT / "parts").glob("*.toml"))
    rows = []
    for f in files:
        est, detail, kind = estimate_cpu(f)
        cpu, wall, load = measure(f)
        ratio = est / cpu if cpu > 0 else float("nan")
        rows.append((f.name, kind, est, cpu, ratio, wall, load, detail))
        print(f"{f.name:34s} {kind:22s} estimate {est:6.1f} CPU s, measured {cpu:6.1f} CPU s ({wall:5.1f} s wall, "
              f"load {load:.1f}): ratio {ratio:.2f}", flush=True)
    lo, hi = RATIO_BAND
    bad = [r for r in rows if not lo <= r[4] <= hi]
    lines = ["# Size estimates against the builds (bench/bench_size_estimates.py)", "",
             f"Measured {time.strftime('%Y-%m-%d %H:%M')}; target: estimate / measured CPU within {lo:g} .. {hi:g}.", "",
             "| part file | type | estimate CPU s | measured CPU s | ratio | wall s | load | counts |",
             "|---|---|---|---|---|---|---|---|"]
    lines += [f"| {n} | {k} | {e:.1f} | {c:.1f} | {r:.2f} | {w:.1f} | {ld:.1f} | {d} |"
              for n, k, e, c, r, w, ld, d in rows]
    lines += ["", f"{len(rows) - len(bad)} of {len(rows)} within the band."]
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("\n".join(lines) + "\n")
    print(lines[-1])
    return 0 if not bad else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
