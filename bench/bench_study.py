"""Benchmark: a design study on the Dask engine with 1 worker and with 2 workers, against the same
evaluations called inline (one after the other in this process).

Run: .venv/bin/python bench/bench_study.py [variants] [depth] [part file]
Default: 100 `proof`-depth variants of the seed-002 pair (parts/ncg_seed002.toml; face width and
backlash sampled, so every variant does the same work).  Targets: time(1 worker) / time(2 workers)
>= 1.8 (the work scales with the cores) and the engine's overhead per variant <= 5 % against inline.
Prints variants per minute and the peak memory (max RSS) of each worker.  The workers are warmed up
(the project imported, one variant evaluated) before the clock starts, as the inline loop is.

Measured here (2 cores shared with other work, load average 5-10): 4 proof-depth seed-002 variants —
inline 31.1 s a variant; 1 worker 123.3 s (1.9 per min), 2 workers 79.6 s (3.0 per min): ratio 1.55; engine
overhead -0.9 % a variant; peak memory 0.9 GB per worker (max RSS; the build's forked workers beside it).
16 design-depth final-drive variants: 0.55 s inline, 140 per min on 1 worker, 179 per min on 2 (ratio 1.28
under load average 6; 0.7 GB per worker).  The inline time is the mean of the first 4 variants only, so the
overhead figure is within its noise (-22 % to -1 % measured).  The 100-variant run (about 50 min on one
worker here) was not made.
"""

from __future__ import annotations

import logging
import resource
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET_RATIO, TARGET_OVERHEAD = 1.8, 0.05


def _study_file(folder: Path, n: int, depth: str, part: Path) -> Path:
    p = folder / "bench.toml"
    p.write_text(f"""[study]
part = "{part}"
depth = "{depth}"
title = "bench"
sample = {n}
seed = 7

[vary]
face_width_mm = {{ from = 10.0, to = 30.0 }}
backlash_mm = {{ from = 0.1, to = 0.2 }}

[objectives]
minimize = ["speed_ripple", "center_distance_mm"]
""" if "ncg" in part.name else f"""[study]
part = "{part}"
depth = "{depth}"
title = "bench"
sample = {n}
seed = 7

[vary]
width_planet_mm = {{ from = 55.0, to = 85.0 }}

[objectives]
minimize = ["ring_outer_d_mm"]
""", encoding="utf-8")
    return p


def _maxrss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def _warm(study) -> None:
    from propulsor.study.evaluate import evaluate

    v = study.variants[0]
    evaluate(study.part_type, study.base, str(study.part_file), v, study.depth, study.values)


def on_cluster(study, out: Path, n_workers: int) -> tuple[float, list[float]]:
    from distributed import Client, LocalCluster

    from propulsor.study.engine import run

    import dask

    with dask.config.set({"distributed.worker.daemon": False}):  # as the engine's own local cluster
        cluster = LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address="127.0.0.1:0",
                               silence_logs=logging.CRITICAL)
    with cluster, Client(cluster, set_as_default=False) as client:
        client.run(_warm, study)
        t0 = time.perf_counter()
        outcome = run(study, out, client=client)
        dt = time.perf_counter() - t0
        rss = list(client.run(_maxrss_mb).values())
    bad = [r for r in outcome.rows if r["status"] not in ("ok", "rejected")]
    if bad:
        print(f"  {len(bad)} variants did not evaluate: {bad[0]['reason']}")
    return dt, rss


def main(n: int = 100, depth: str = "proof", part: str = "parts/ncg_seed002.toml") -> int:
    from propulsor.study import load_study
    from propulsor.study.evaluate import evaluate

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        study = load_study(_study_file(tmp, n, depth, (ROOT / part).resolve()))
        n = len(study.variants)
        _warm(study)
        k_inline = max(1, min(n, 4))
        t0 = time.perf_counter()
        for v in study.variants[:k_inline]:
            evaluate(study.part_type, study.base, str(study.part_file), v, study.depth, study.values)
        inline = (time.perf_counter() - t0) / k_inline
        t1, rss1 = on_cluster(study, tmp / "w1", 1)
        t2, rss2 = on_cluster(study, tmp / "w2", 2)
    ratio = t1 / t2
    overhead = t1 / (n * inline) - 1.0
    print(f"{n} {depth}-depth variants of {part}: inline {inline:.2f} s per variant (first {k_inline}); "
          f"1 worker {t1:.1f} s ({n / t1 * 60:.1f} per min), 2 workers {t2:.1f} s ({n / t2 * 60:.1f} per min); "
          f"ratio {ratio:.2f} (target >= {TARGET_RATIO}); engine overhead per variant {overhead * 100:+.1f} % "
          f"(target <= {TARGET_OVERHEAD * 100:.0f} %); peak memory per worker {max(rss1):.0f} MB (1 worker), "
          f"{', '.join(f'{x:.0f}' for x in rss2)} MB (2 workers)")
    return 0 if ratio >= TARGET_RATIO and overhead <= TARGET_OVERHEAD else 1


if __name__ == "__main__":
    a = sys.argv[1:]
    sys.exit(main(int(a[0]) if a else 100, a[1] if len(a) > 1 else "proof", a[2] if len(a) > 2 else "parts/ncg_seed002.toml"))
