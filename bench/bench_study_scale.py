"""Benchmark (issue 40): a large study on a local cluster of two workers — does each variant cost what it costs
alone, and does the table's writing stay O(1) a variant?

    .venv/bin/python bench/bench_study_scale.py [N] [depth] [part file] [--workers W]

Default: 1 000 ``design``-depth variants of the final drive (parts/final_drive.toml, the planet's face width and
the module sampled; about 0.17 CPU s a variant: the cheapest variant of the gallery's studies, so that what the
engine adds around a variant weighs the most).  A study of ``proof``-depth seed-002 variants
(``1000 proof parts/ncg_seed002.toml``) costs about 6 s a variant: the same overhead is then 35 times smaller.
Needs both cores idle: run it alone.

What is measured (the engine's own local cluster, :func:`propulsor.study.engine.run`, one thread a worker):
- the variants' own cost: each row's ``seconds`` (measured on the worker around the evaluation), summed;
- the loop's wall (submit to the last row written: the engine's ``Outcome.seconds``) and the whole run's (the table
  sorted and rewritten, the front, the picture and the page after it);
- overhead a variant = (W x loop wall - own) / own: what a variant costs beyond its own evaluation with W workers
  busy (Dask's scheduling, the row's trip back, the table's writing, the idle tail of the last tasks);
- the table's writing in this process: the seconds of every ``Table.add`` (a row to results.csv, now and then
  results.parquet rewritten: at most a twentieth of the time), the mean of the first and the last tenth of the rows
  (O(1) a variant: the same), the rewrites of results.parquet;
- the workers' memory: each worker's RSS after its warm-up and after the study (a leak would grow it with N).

Warm-up before the clock starts: each worker imports the project and evaluates the base part file once.

Measured (2026-11-29, 2 cores, a mutation run stopped for the time of it; the default 1 000 final-drive variants):
before the designs were freed with their parameters (9c07cd9) the own cost was 143.2 CPU s (0.143 s a variant),
the loop 73.2 s of wall, overhead +2.26 % (3.2 ms a variant), the table 0.15 s in all (a row 0.06 ms in the first
tenth, 0.23 ms in the last: results.parquet rewritten 10 times), and each worker grew from 201 to 441 and 429 MB:
every design it made was kept (``parts/pipeline.py``).  After (9b70db3): own cost 120.9 CPU s (0.121 s a variant),
the loop 62.0 s, the whole run 63.0 s (1.0 s after the loop), overhead +2.62 % (3.2 ms a variant), the table 0.17 s
in all (0.07 / 0.27 ms a row, 9 rewrites of results.parquet), each worker 207 -> 258 MB (in one process, 300
variants one after the other: 195 MB after the first 50 and after all 300).
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS",
              "VECLIB_MAXIMUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # before numpy loads: this process and the workers it starts

import argparse  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TARGET_OVERHEAD = 0.05


def _study_file(folder: Path, n: int, depth: str, part: Path) -> Path:
    p = folder / "bench.toml"
    vary = ("face_width_mm = { from = 10.0, to = 30.0 }\nbacklash_mm = { from = 0.1, to = 0.2 }"
            if "ncg" in part.name else
            "width_planet_mm = { from = 55.0, to = 85.0 }\nmodule_mm = { from = 9.0, to = 11.0 }")
    objective = 'minimize = ["speed_ripple", "center_distance_mm"]' if "ncg" in part.name else \
        'minimize = ["ring_outer_d_mm"]\nmaximize = ["strength_sun_planet_S_H_pitting_sun"]'
    p.write_text(f'[study]\npart = "{part}"\ndepth = "{depth}"\ntitle = "bench"\nsample = {n}\nseed = 11\n\n'
                 f"[vary]\n{vary}\n\n[objectives]\n{objective}\n", encoding="utf-8")
    return p


def _rss_mb() -> float:
    """This worker's resident memory now (MB)."""
    with open("/proc/self/status", encoding="ascii") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def _warm(study) -> float:
    from propulsor.study.evaluate import evaluate

    evaluate(study.part_type, study.base, str(study.part_file), {}, study.depth, study.values)
    return _rss_mb()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", nargs="?", type=int, default=1000)
    ap.add_argument("depth", nargs="?", default="design")
    ap.add_argument("part", nargs="?", default="parts/final_drive.toml")
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args(argv)

    from distributed import Client

    from propulsor.study import load_study
    from propulsor.study import table as table_mod
    from propulsor.study.engine import local_cluster, run

    adds: list[float] = []
    rewrites = [0]
    add0, wp0 = table_mod.Table.add, table_mod.Table._write_parquet

    def add(self, row):
        t = time.perf_counter()
        add0(self, row)
        adds.append(time.perf_counter() - t)

    def write_parquet(self):
        rewrites[0] += 1
        wp0(self)

    table_mod.Table.add, table_mod.Table._write_parquet = add, write_parquet
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        study = load_study(_study_file(tmp, a.n, a.depth, (ROOT / a.part).resolve()))
        n = len(study.variants)
        cluster = local_cluster(a.workers)
        with cluster, Client(cluster, set_as_default=False) as client:
            rss0 = client.run(_warm, study)
            t0 = time.perf_counter()
            outcome = run(study, tmp / "out", client=client)
            whole = time.perf_counter() - t0
            rss1 = client.run(_rss_mb)
        sizes = {p.name: p.stat().st_size for p in (tmp / "out").iterdir() if p.is_file()}
    rows = outcome.rows
    own = sum(r["seconds"] or 0.0 for r in rows)
    loop = outcome.seconds
    over = (a.workers * loop - own) / own
    tenth = max(1, len(adds) // 10)
    first, last = sum(adds[:tenth]) / tenth, sum(adds[-tenth:]) / tenth
    not_ok = [r for r in rows if r["status"] != "ok"]
    mem = ", ".join(f"{rss0[w]:.0f} -> {rss1[w]:.0f}" for w in sorted(rss0))
    print(f"{n} {a.depth}-depth variants of {a.part} on {a.workers} workers ({len(not_ok)} not ok"
          f"{': ' + str(not_ok[0]['reason']) if not_ok else ''}):\n"
          f"  own cost {own:.1f} CPU s ({own / n:.3f} s a variant); loop wall {loop:.1f} s, whole run {whole:.1f} s "
          f"(after the loop: {whole - loop:.1f} s: the table sorted, the front, its picture, the page)\n"
          f"  overhead a variant (W x loop wall - own) / own: {over * 100:+.2f} % (target <= "
          f"{TARGET_OVERHEAD * 100:.0f} %); {(a.workers * loop - own) / n * 1e3:.1f} ms a variant\n"
          f"  the table in this process: {len(adds)} rows added, {sum(adds):.2f} s in all; a row "
          f"{first * 1e3:.2f} ms (first tenth) / {last * 1e3:.2f} ms (last tenth); results.parquet written "
          f"{rewrites[0]} times; files: " + ", ".join(f"{k} {v / 1e3:.0f} kB" for k, v in sorted(sizes.items())) + "\n"
          f"  worker memory after warm-up -> after the study (MB): {mem}\n"
          f"  load average before/after: {load_before:.1f}/{os.getloadavg()[0]:.1f}")
    return 0 if over <= TARGET_OVERHEAD and not not_ok else 1


if __name__ == "__main__":
    sys.exit(main())
