"""Benchmark: a design study on the Dask engine with 1 worker and with 2 workers, against the same
evaluations called inline (one after the other in this process), in one run.

Run: .venv/bin/python bench/bench_study.py [variants] [depth] [part file] [inline count]
Default: 100 `proof`-depth variants of the seed-002 pair (parts/ncg_seed002.toml; face width and
backlash sampled, so every variant does about the same work).  A proof-depth variant is the pair's design
(law search, teeth) and its proof steps (the full-cycle proof, the other method's, the as-built speed, every
check and derived value of the report): no solid, no file (:attr:`propulsor.Part.proof_run`).  Needs both cores idle (the ratio is
the point): run it alone; a shared machine gives a smaller ratio.  A short check that it works:
``bench/bench_study.py 6``.

What is measured, and how (each the same for the three runs):
- inline: the N variants by :func:`propulsor.study.evaluate.evaluate`, one after the other, in this
  process — the baseline (with an inline count K < N, the first K of them, and the inline time of all N
  is K's scaled by what the N cost against those K on the 1-worker cluster: each row's own seconds);
- 1 worker / 2 workers: the same N variants through the engine (:func:`propulsor.study.engine.run`:
  submit, gather, the table written as each finishes, the front, the page) on a LocalCluster of that
  many worker processes, as the engine makes its own: one thread per worker, numpy's BLAS / OpenMP
  threads at 1 (set here before numpy loads, so this process and every worker inherits them; Dask's
  nanny sets the same), each variant on one core (the build's forked helpers and OCCT's threads off:
  evaluate.one_process), the longest submitted first, only the row travelling back;
- warm-up before each clock starts: this process, and each worker (``client.run`` on every worker),
  imports the project and evaluates the base part file once (not one of the N variants), so neither
  process start-up nor imports are timed;
- overhead = (1-worker wall − inline wall) / inline wall (target <= 5 %); beside it, the 1-worker wall
  against the sum of the evaluations' own times on that worker (what the engine adds around them); ratio = 1-worker wall /
  2-worker wall (target >= 1.8); variants per minute = N / wall; peak memory per worker = the worker
  process's max RSS (and that of any process it forked), read on the worker after the study.
The rows of the three runs are checked equal (the objectives, to the last digit).

Measured here with ``bench/bench_study.py 100`` on an idle machine (load 1.3 before, 2.2 after; the proof
depth of design + proof steps, no solid): inline 749.3 s (7.49 s a variant); 1 worker 780.8 s (7.68 per min),
2 workers 397.9 s (15.08 per min): ratio 1.96; overhead against inline +4.2 % (target 5 %), the 1-worker wall
+0.2 % over the evaluations' own time on the worker; peak memory 315 MB on the 1-worker cluster, 353 and
353 MB per worker on the 2-worker one (+61 MB forked); 0 rows differing from inline.  Before the engine's
worker settings (``study/engine.py`` WORKER_CONFIG: no MALLOC_TRIM_THRESHOLD_ from Dask's nanny, no statistical
profiler, health polled once a second) the same run gave +11.7 % (inline 750.5 s, 1 worker 838.5 s; peak
627-658 MB a worker).  With the nanny's trim threshold set, glibc's dynamic mmap threshold is off and every
array over 128 KiB is mapped afresh: 4 variants inline took 30.8-31.1 CPU s with it, 29.3-29.5 without.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS",
              "VECLIB_MAXIMUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # before numpy loads: this process and the workers it starts

import resource  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

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


def _worker_facts() -> dict:
    """On a worker: its peak memory (MB, itself and any process it forked) and its thread settings."""
    import threading

    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    kids = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
    return {"rss_mb": own, "children_rss_mb": kids, "OMP_NUM_THREADS": os.environ.get("OMP_NUM_THREADS"),
            "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS"), "threads": threading.active_count()}


def _warm(study) -> None:
    """Import the project and evaluate the base part once (not one of the study's variants)."""
    from propulsor.study.evaluate import evaluate

    evaluate(study.part_type, study.base, str(study.part_file), {}, study.depth, study.values)


def inline(study, k: int) -> tuple[float, dict]:
    """The first `k` variants evaluated one after the other in this process: (wall, rows by variant)."""
    from propulsor.study.evaluate import evaluate

    _warm(study)
    t0 = time.perf_counter()
    rows = {}
    for i, v in enumerate(study.variants[:k], 1):
        rows[i] = evaluate(study.part_type, study.base, str(study.part_file), v, study.depth, study.values)
    return time.perf_counter() - t0, rows


def on_cluster(study, out: Path, n_workers: int) -> tuple[float, dict, list[dict]]:
    from distributed import Client

    from propulsor.study.engine import local_cluster, run

    cluster = local_cluster(n_workers)  # the engine's own local cluster
    with cluster, Client(cluster, set_as_default=False) as client:
        info = client.scheduler_info()["workers"]
        assert len(info) == n_workers and all(w["nthreads"] == 1 for w in info.values()), info
        client.run(_warm, study)
        t0 = time.perf_counter()
        outcome = run(study, out, client=client)
        dt = time.perf_counter() - t0
        facts = list(client.run(_worker_facts).values())
    return dt, {r["variant"]: r for r in outcome.rows}, facts


def _same(rows_inline: dict, rows: dict, names) -> int:
    """How many variants differ from the inline run in a value asked for (0: the engine changes nothing)."""
    bad = 0
    for i, r in rows_inline.items():
        if any(repr(r["values"].get(n)) != repr(rows[i].get(n)) for n in names):
            bad += 1
    return bad


def main(n: int = 100, depth: str = "proof", part: str = "parts/ncg_seed002.toml", k: int | None = None) -> int:
    from propulsor.study import load_study

    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        study = load_study(_study_file(tmp, n, depth, (ROOT / part).resolve()))
        n = len(study.variants)
        k = n if k is None else max(1, min(k, n))
        t0, rows0 = inline(study, k)
        t1, rows1, facts1 = on_cluster(study, tmp / "w1", 1)
        t2, rows2, facts2 = on_cluster(study, tmp / "w2", 2)
    bad = [r["reason"] for r in rows1.values() if r["status"] != "ok"]
    ratio = t1 / t2
    # the evaluations' own time on the 1-worker cluster (each row's seconds, measured around the same call)
    s1 = sum(r["seconds"] for r in rows1.values())
    s1_k = sum(rows1[i]["seconds"] for i in rows0)
    # inline time of all N: measured when k = N; else the first k scaled by the variants' measured cost
    t0_all = t0 if k == n else t0 * s1 / s1_k
    overhead = (t1 - t0_all) / t0_all
    engine = (t1 - s1) / s1
    differ = _same(rows0, rows1, study.values) + _same(rows0, rows2, study.values)

    def mem(facts):
        return ", ".join(f"{f['rss_mb']:.0f}" + (f" (+{f['children_rss_mb']:.0f} forked)" if f["children_rss_mb"] else "")
                         for f in facts)

    print(f"{n} {depth}-depth variants of {part} ({len(bad)} not ok{': ' + bad[0] if bad else ''}):\n"
          f"  inline     {t0:8.1f} s  for {k} of the {n} ({t0 / k:.2f} s a variant; the same {k} took "
          f"{s1_k / k:.2f} s each on the worker){'' if k == n else f'; all {n} estimated {t0_all:.1f} s'}\n"
          f"  1 worker   {t1:8.1f} s  {n / t1 * 60:6.2f} per min  peak memory {mem(facts1)} MB\n"
          f"  2 workers  {t2:8.1f} s  {n / t2 * 60:6.2f} per min  peak memory {mem(facts2)} MB per worker\n"
          f"  ratio 1 worker / 2 workers {ratio:.2f} (target >= {TARGET_RATIO}); engine overhead "
          f"(1 worker - inline) / inline {overhead * 100:+.1f} % (target <= {TARGET_OVERHEAD * 100:.0f} %); "
          f"1-worker wall against the evaluations' own time on it {engine * 100:+.1f} %\n"
          f"  workers: 1 thread each, OMP_NUM_THREADS={facts2[0]['OMP_NUM_THREADS']}, "
          f"OPENBLAS_NUM_THREADS={facts2[0]['OPENBLAS_NUM_THREADS']}; rows differing from inline: {differ}; "
          f"load average before/after: {load_before:.1f}/{os.getloadavg()[0]:.1f}")
    return 0 if ratio >= TARGET_RATIO and overhead <= TARGET_OVERHEAD and not differ else 1


if __name__ == "__main__":
    a = sys.argv[1:]
    sys.exit(main(int(a[0]) if a else 100, a[1] if len(a) > 1 else "proof",
                  a[2] if len(a) > 2 else "parts/ncg_seed002.toml", int(a[3]) if len(a) > 3 else None))
