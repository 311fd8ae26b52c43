"""`propulsor explore`: study files checked whole (exit 2, one line, nothing written), the variants run
on a real Dask cluster started here (a scheduler and two workers on 127.0.0.1), each row equal to the
variant evaluated alone, a worker killed mid-study, --resume running only the rest."""

from __future__ import annotations

import csv
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
WHEEL = ROOT / "parts" / "road_wheel.toml"
BIN = Path(sys.executable).parent

STUDY = f"""
[study]
part = "{WHEEL}"
depth = "design"
title = "road wheel: tyre width x load"

[vary]
tyre_width_mm = [70.0, 90.0]
load_N = {{ from = 30000.0, to = 50000.0, step = 10000.0 }}

[objectives]
minimize = ["T_at_V_max_C", "peak_pressure_q_m_MPa"]
require = ["all_checks_passed", "T_at_V_max_C <= 125"]
record = ["contact_length_l_mm"]
"""


def write(tmp_path: Path, text: str, name: str = "s.toml") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def read_rows(folder: Path) -> list[dict]:
    with open(folder / "results.csv", newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def parquet_is_csv(folder: Path) -> list[dict]:
    """results.parquet holds the rows of results.csv, each cell the CSV's value read as its column's type
    (floats to the last digit); returns the Parquet rows."""
    import math

    import pyarrow.parquet as pq

    table = pq.read_table(folder / "results.parquet")
    csv_rows = read_rows(folder)
    assert table.column_names == list(csv_rows[0]) if csv_rows else True
    kind = {f.name: str(f.type) for f in table.schema}
    read = {"int64": int, "double": float, "bool": lambda t: {"true": True, "false": False}[t], "string": str}
    pq_rows = table.to_pylist()
    assert len(pq_rows) == len(csv_rows)
    for p, c in zip(pq_rows, csv_rows):
        for name, text in c.items():
            want = None if text == "" else read[kind[name]](text)
            got = p[name]
            assert type(got) is type(want) and (got == want or (isinstance(got, float) and math.isnan(got)
                                                                and math.isnan(want))), (name, got, text)
    return pq_rows


# ---- study files checked whole: exit 2, one line naming it, nothing written -------------------------

@pytest.mark.parametrize("change, named", [
    (("tyre_width_mm = [70.0, 90.0]", "tyre_wdth_mm = [70.0, 90.0]"), "vary.tyre_wdth_mm"),
    (("tyre_width_mm = [70.0, 90.0]", "tyre_width_mm = { from = 300.0, to = 500.0, step = 100.0 }"),
     "tyre_width_mm = 500.0: must be <= 400.0"),
    (('minimize = ["T_at_V_max_C", "peak_pressure_q_m_MPa"]', 'minimize = ["T_at_V_max_C", "hub_speed_ripple"]'),
     "objectives.minimize = 'hub_speed_ripple'"),
    (('require = ["all_checks_passed", "T_at_V_max_C <= 125"]', 'require = ["T_at_V_max_C <== 125"]'),
     "objectives.require"),
])
def test_bad_study_file_exit_2_one_line_nothing_written(tmp_path, capsys, change, named):
    study = write(tmp_path, STUDY.replace(*change))
    out = tmp_path / "out"
    assert main(["explore", str(study), "--out", str(out), "-q"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("propulsor: error: ") and named in err[0], err
    assert not out.exists()


def test_unreachable_scheduler_exit_2_nothing_written(tmp_path, capsys, monkeypatch):
    from propulsor.study import cluster

    monkeypatch.setattr(cluster, "ANSWER_TIMEOUT_S", 2)
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    study = write(tmp_path, STUDY)
    out = tmp_path / "out"
    assert main(["explore", str(study), "--out", str(out), "--scheduler", f"tcp://127.0.0.1:{port}", "-q"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--scheduler = 'tcp://127.0.0.1:{port}': no Dask scheduler answers" in err[0], err
    assert not out.exists()


def test_grid_ranges_keep_the_decimals_and_both_ends(tmp_path):
    from propulsor.study.spec import load_study

    s = load_study(write(tmp_path, STUDY.replace("step = 10000.0", "step = 10000.0").replace(
        "tyre_width_mm = [70.0, 90.0]", "tyre_width_mm = { from = 70.1, to = 70.4, step = 0.1 }")))
    assert sorted({v["tyre_width_mm"] for v in s.variants}) == [70.1, 70.2, 70.3, 70.4]
    assert sorted({v["load_N"] for v in s.variants}) == [30000.0, 40000.0, 50000.0]
    assert len(s.variants) == 12


# ---- a real cluster: `dask scheduler` and two `dask worker` processes on 127.0.0.1 -------------------

class Cluster:
    def __init__(self, tmp: Path, nanny: bool = False):
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.address = f"tcp://127.0.0.1:{self.port}"
        env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
        self.log = open(tmp / "dask.log", "w")
        kw = dict(env=env, stdout=self.log, stderr=subprocess.STDOUT, cwd=tmp)
        self.scheduler = subprocess.Popen([str(BIN / "dask"), "scheduler", "--host", "127.0.0.1", "--port",
                                           str(self.port), "--no-dashboard"], **kw)
        self.workers = [subprocess.Popen([str(BIN / "dask"), "worker", self.address, "--nthreads", "1",
                                          "--no-dashboard", "--no-nanny", "--name", f"w{k}"], **kw)
                        for k in range(2)]
        self._wait(2)

    def _wait(self, n: int) -> None:
        from distributed import Client

        deadline = time.monotonic() + 120
        while True:
            try:
                with Client(self.address, timeout=5, set_as_default=False) as c:
                    c.wait_for_workers(n, timeout=max(1, deadline - time.monotonic()))
                    return
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.5)

    def stop(self) -> None:
        for p in [*self.workers, self.scheduler]:
            if p.poll() is None:
                p.terminate()
        for p in [*self.workers, self.scheduler]:
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.log.close()


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    c = Cluster(tmp_path_factory.mktemp("dask"))
    try:
        yield c
    finally:
        c.stop()
    assert all(p.poll() is not None for p in [*c.workers, c.scheduler])


def alone(values: dict) -> dict:
    """The same variant evaluated alone in this process (the Python API)."""
    import propulsor
    from propulsor.study.evaluate import design_values

    derived, checks = design_values(propulsor.part(WHEEL, **values))
    return derived


def test_study_on_a_real_scheduler_each_row_is_the_variant_alone(cluster, tmp_path, capsys):
    study = write(tmp_path, STUDY)
    out = tmp_path / "out"
    assert main(["explore", str(study), "--out", str(out), "--scheduler", cluster.address]) == 0
    err = capsys.readouterr().err
    assert "6/6 variants" in err and "per min" in err
    rows = read_rows(out)
    assert sorted(int(r["variant"]) for r in rows) == [1, 2, 3, 4, 5, 6]
    workers = {r["worker"] for r in rows}
    pids = {f":{p.pid}" for p in cluster.workers}
    assert all(any(w.endswith(pid) for pid in pids) for w in workers), (workers, pids)  # ran on the cluster
    for r in rows:
        values = {"tyre_width_mm": float(r["tyre_width_mm"]), "load_N": float(r["load_N"])}
        ref = alone(values)
        for name in ("T_at_V_max_C", "peak_pressure_q_m_MPa", "contact_length_l_mm"):
            assert r[name] == repr(ref[name]), (name, r[name], ref[name])  # to the last digit
        assert r["status"] in ("ok", "rejected")
        if r["status"] == "rejected":
            assert r["reason"].startswith(("all_checks_passed: failed ", "T_at_V_max_C <= 125 does not hold")), r
        else:
            assert r["all_checks_passed"] == "true" and float(r["T_at_V_max_C"]) <= 125
    # and the design depth gives the manifest's values: one variant built alone by `propulsor build`
    one = min(rows, key=lambda r: int(r["variant"]))
    part = write(tmp_path, WHEEL.read_text().replace("tyre_width_mm = 90.0", f"tyre_width_mm = {one['tyre_width_mm']}")
                 .replace("load_N = 31490.0", f"load_N = {one['load_N']}"), "wheel.toml")
    assert main(["build", str(part), "--out", str(tmp_path / "built"), "--keep-failed", "-q"]) in (0, 1)
    derived = json.loads((tmp_path / "built" / "manifest.json").read_text())["derived"]
    for name in ("T_at_V_max_C", "peak_pressure_q_m_MPa", "contact_length_l_mm"):
        assert one[name] == repr(derived[name]), (name, one[name], derived[name])
    # results.parquet: the same rows, typed columns
    pq_rows = parquet_is_csv(out)
    assert [type(pq_rows[0][c]) for c in ("variant", "key", "tyre_width_mm", "T_at_V_max_C", "all_checks_passed")] \
        == [int, str, float, float, bool]
    front = list(csv.DictReader(open(out / "front.csv", newline="")))
    assert front and front[0]["pareto_layer"] == "1"
    assert (out / "pareto_front.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_resume_runs_only_the_rest_and_a_failing_variant_is_a_row(cluster, tmp_path):
    from propulsor.study import load_study
    from propulsor.study.engine import run

    study = write(tmp_path, STUDY.replace("tyre_width_mm = [70.0, 90.0]", "hub_outer_d_mm = [210.0, 150.0]"))
    out = tmp_path / "out"
    seen = []

    def progress(msg):  # results.parquet: a table of the rows so far (written now and then, and at the end)
        if "variants," in msg:
            import pyarrow.parquet as pq

            seen.append(pq.read_table(out / "results.parquet").num_rows)

    first = run(load_study(study), out, scheduler=cluster.address, progress=progress)
    assert first.ran == 6 and len(seen) == 6 and seen == sorted(seen) and seen[-1] <= 6
    assert len(parquet_is_csv(out)) == 6
    bad = [r for r in first.rows if r["hub_outer_d_mm"] == 150.0]
    assert len(bad) == 3 and all(r["status"] == "input error" and r["reason"].startswith("hub_outer_d_mm = 150.0")
                                 for r in bad)
    lines = (out / "results.csv").read_text().splitlines(keepends=True)
    (out / "results.csv").write_text("".join(lines[:-2]))  # as if interrupted before the last two finished
    again = run(load_study(study), out, scheduler=cluster.address, resume=True)
    assert again.ran == 2
    rows = read_rows(out)
    assert sorted(int(r["variant"]) for r in rows) == [1, 2, 3, 4, 5, 6]
    assert sorted(r["variant"] for r in parquet_is_csv(out)) == [1, 2, 3, 4, 5, 6]
    # --build-best: the best variant built fully, with its own parameters
    from propulsor.study import build_best_variants

    layer, best = again.ranked[0]
    assert build_best_variants(load_study(study), again, 1) == [out / "best" / "1"]
    inputs = json.loads((out / "best" / "1" / "manifest.json").read_text())["inputs"]
    assert (inputs["load_N"], inputs["hub_outer_d_mm"]) == (best["load_N"], best["hub_outer_d_mm"]) == \
        (min(r["load_N"] for r in again.rows if r["status"] == "ok"), 210.0)


def test_a_worker_killed_mid_study_every_variant_exactly_once(tmp_path):
    from propulsor.study import load_study
    from propulsor.study.engine import run

    c = Cluster(tmp_path)
    killed = []

    def progress(msg):
        if "variants," in msg and not killed:  # the first variant finished: both workers are busy
            victim = c.workers[0]
            victim.send_signal(signal.SIGKILL)
            victim.wait()
            killed.append(victim.pid)

    try:
        study = write(tmp_path, STUDY.replace("tyre_width_mm = [70.0, 90.0]", "tyre_width_mm = [70.0, 80.0, 90.0]"))
        outcome = run(load_study(study), tmp_path / "out", scheduler=c.address, progress=progress)
    finally:
        c.stop()
    assert killed
    rows = read_rows(tmp_path / "out")
    assert sorted(int(r["variant"]) for r in rows) == list(range(1, 10))
    assert all(r["status"] in ("ok", "rejected") for r in rows), [r["reason"] for r in rows]
    assert len(outcome.rows) == 9
    survivor = f":{c.workers[1].pid}"
    assert any(r["worker"].endswith(survivor) for r in rows)


def test_study_page_escapes_the_study_text_and_links_built_variants(tmp_path):
    from propulsor.study.page import write_page
    from propulsor.study.results import ranked
    from propulsor.study.spec import load_study

    study = load_study(write(tmp_path, STUDY.replace('title = "road wheel: tyre width x load"',
                                                     'title = "<script>alert(1)</script> & co"')))
    rows = [{"variant": k, "key": f"k{k}", "tyre_width_mm": 70.0, "load_N": 30000.0 + k, "T_at_V_max_C": 100.0 + k,
             "peak_pressure_q_m_MPa": 3.0 - k, "contact_length_l_mm": 1.0, "all_checks_passed": True,
             "status": "ok", "reason": "", "failed_checks": '<img src=x onerror="alert(2)">', "seconds": 1.0,
             "worker": "w"} for k in (1, 2)]
    (tmp_path / "variants" / "k2").mkdir(parents=True)
    (tmp_path / "variants" / "k2" / "report.html").write_text("x")
    from propulsor.study.results import plot_front

    rank = ranked(study, rows)
    points = plot_front(tmp_path, study, rows, rank)
    page = write_page(tmp_path, study, rows, rank, points=points).read_text()
    # each point of the picture linked to its variant: its files, else its row of the table
    from PIL import Image

    w, h = Image.open(tmp_path / "pareto_front.png").size
    assert sorted(v for v, _, _ in points) == [1, 2] and all(0 < x < w and 0 < y < h for _, x, y in points)
    (x1, y1), (x2, y2) = [(x, y) for _, x, y in sorted(points)]
    assert x2 > x1 and y2 > y1  # variant 2: the larger T_at_V_max_C (x) and the smaller pressure (y, down)
    assert f'coords="{x2},{y2},6" href="variants/k2/report.html"' in page
    assert f'coords="{x1},{y1},6" href="#v1"' in page and '<tr id="v1" class="front">' in page
    assert 'usemap="#front"' in page and '<map name="front">' in page
    assert "<script>alert" not in page and "&lt;script&gt;alert(1)&lt;/script&gt; &amp; co" in page
    assert "<img src=x" not in page and "&lt;img src=x onerror=&quot;alert(2)&quot;&gt;" in page
    assert '<a href="variants/k2/report.html">2</a>' in page and 'href="variants/k1/' not in page
    assert page.count(' class="front">') == 2  # neither dominates the other


def test_interrupted_study_keeps_the_finished_rows_and_resume_runs_the_rest(tmp_path):
    import psutil

    study = write(tmp_path, STUDY.replace("tyre_width_mm = [70.0, 90.0]", "tyre_width_mm = [70.0, 80.0, 90.0]"))
    out = tmp_path / "out"
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    cmd = [str(BIN / "propulsor"), "explore", str(study), "--out", str(out), "--workers", "1"]
    # its own process group, signalled as a terminal's Ctrl-C signals the foreground group: every process of it
    proc = subprocess.Popen(cmd, env=env, stderr=subprocess.PIPE, text=True, cwd=tmp_path, start_new_session=True)
    children: set[int] = set()
    deadline = time.monotonic() + 240
    while time.monotonic() < deadline and proc.poll() is None:
        children |= {c.pid for c in psutil.Process(proc.pid).children(recursive=True)}
        if (out / "results.csv").is_file() and len((out / "results.csv").read_text().splitlines()) >= 2:
            break
        time.sleep(0.2)
    workers = [c for c in psutil.Process(proc.pid).children(recursive=True)
               if c.cmdline()[:1] and c.cmdline()[0].startswith("dask worker")]  # Dask's workers name themselves so
    ignored = [int(next(ln for ln in open(f"/proc/{w.pid}/status") if ln.startswith("SigIgn:")).split()[1], 16)
               >> (signal.SIGINT - 1) & 1 for w in workers]
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert workers and all(ignored), (workers, ignored)  # SIGINT ignored in every worker: the study's to handle
    assert proc.returncode == 130, err
    # the Dask workers ignore it (before: each printed its KeyboardInterrupt traceback, 33-71 lines)
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, err
    kept = read_rows(out)
    assert 1 <= len(kept) < 9
    n_rows = len((out / "results.csv").read_text().splitlines()) - 1
    assert err.strip().splitlines()[-1] == (f"propulsor: interrupted by SIGINT; {n_rows} finished variant"
                                             f"{'s' if n_rows != 1 else ''} in {out / 'results.csv'} (--resume runs "
                                             f"the rest)")
    # no worker left behind (multiprocessing's resource tracker leaves when it sees its parent gone)
    procs = []
    for pid in children:
        try:
            procs.append(psutil.Process(pid))
        except psutil.NoSuchProcess:
            pass
    gone, alive = psutil.wait_procs(procs, timeout=30)
    assert children and not alive, [p.cmdline() for p in alive]
    assert main(["explore", str(study), "--out", str(out), "--workers", "1", "--resume", "-q"]) == 0
    rows = read_rows(out)
    assert sorted(int(r["variant"]) for r in rows) == list(range(1, 10))
    assert rows[:len(kept)] == kept  # the finished rows kept as they were


def test_proof_depth_on_the_local_cluster_runs_the_whole_build(tmp_path):
    """The default engine (a LocalCluster): a proof is the whole build, run inside a Dask worker process
    (which forks the build's own workers), its solids' values in the row."""
    study = write(tmp_path, f"""
[study]
part = "{WHEEL}"
depth = "proof"
[vary]
tyre_width_mm = [90.0]
[objectives]
minimize = ["mass_wheel_kg"]
require = ["all_checks_passed"]
""")
    assert main(["explore", str(study), "--out", str(tmp_path / "out"), "--workers", "1", "-q"]) == 0
    (row,) = read_rows(tmp_path / "out")
    assert (row["status"], row["all_checks_passed"], row["reason"]) == ("ok", "true", "")
    assert 100.0 < float(row["mass_wheel_kg"]) < 150.0


def _worker_settings() -> tuple:
    import gc

    import dask

    return (os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OPENBLAS_NUM_THREADS"),
            dask.config.get("distributed.worker.profile.enabled"), dask.config.get("distributed.worker.daemon"),
            gc.get_threshold())


def test_the_local_cluster_workers_run_a_variant_as_this_process_would():
    """No MALLOC_TRIM_THRESHOLD_ in a worker's environment (Dask's nanny sets it by default: it switches
    off glibc's dynamic mmap threshold and a proof runs 4-6 % slower), BLAS at one thread, no statistical
    profiler sampling the evaluation, workers that may fork, and Python's own garbage collector thresholds (a worker
    evaluates variant after variant: policy.GC_THRESHOLDS' collector let 30 variants grow a process by 58 MiB)."""
    from distributed import Client

    from propulsor.study.engine import local_cluster

    with local_cluster(1) as cluster, Client(cluster, set_as_default=False) as client:
        (settings,) = client.run(_worker_settings).values()
    assert settings == (None, "1", False, False, (700, 10, 10))


def test_all_checks_passed_is_not_vacuously_true_where_no_check_ran():
    from propulsor.study.results import requirement_failure
    from propulsor.study.spec import Requirement

    class S:  # the two fields requirement_failure reads
        depth = "design"
        require = (Requirement("all_checks_passed"),)

    assert requirement_failure(S, {"all_checks_passed": True}) == ""
    assert requirement_failure(S, {"all_checks_passed": None}).startswith("all_checks_passed: no check runs at depth design")
    assert requirement_failure(S, {"all_checks_passed": False, "failed_checks": "a.b"}) == "all_checks_passed: failed a.b"


def test_a_sampler_draws_within_the_ranges_reproducibly(tmp_path):
    from propulsor.study.spec import load_study

    text = STUDY.replace('title = "road wheel: tyre width x load"', 'sample = 7\nseed = 3').replace(
        "tyre_width_mm = [70.0, 90.0]", "lightening_holes = { from = 2, to = 8 }").replace(", step = 10000.0", "")
    a, b = load_study(write(tmp_path, text)), load_study(write(tmp_path, text, "t.toml"))
    assert a.variants == b.variants and len(a.variants) == 7
    assert all(isinstance(v["lightening_holes"], int) and 2 <= v["lightening_holes"] <= 8 for v in a.variants)
    assert all(30000.0 <= v["load_N"] <= 50000.0 for v in a.variants)
    assert load_study(write(tmp_path, text.replace("seed = 3", "seed = 4"), "u.toml")).variants != a.variants


def _evaluate_in(queue, part_file: str, depth: str, wanted: tuple) -> None:
    from propulsor.params import read_part_file
    from propulsor.study.evaluate import evaluate

    type_name, base = read_part_file(part_file)
    queue.put(evaluate(type_name, base, part_file, {}, depth, wanted))


def test_a_variant_evaluates_in_a_daemonic_worker_process():
    """`dask worker` runs its tasks in a daemonic process under its nanny; the seed-002 design forks the
    tooth generation, which a daemonic process may not do unless the evaluation lifts the flag."""
    import multiprocessing as mp

    ctx = mp.get_context("fork")
    q = ctx.Queue()
    p = ctx.Process(target=_evaluate_in, args=(q, str(ROOT / "parts" / "ncg_seed002.toml"), "design",
                                               ("speed_ripple", "center_distance_mm")), daemon=True)
    p.start()
    row = q.get(timeout=300)
    p.join()
    assert (row["status"], row["reason"]) == ("ok", ""), row
    assert 0.0 < row["values"]["speed_ripple"] < 0.05


def test_the_table_read_back_for_resume_keeps_text_keys_and_drops_stale_and_cut_rows(tmp_path):
    """--resume reads results.csv back as typed columns (a key of digits and an e stays text), keeps only
    this study's variants, leaves out a line cut short, and writes both files anew with the same rows."""
    from propulsor.study import load_study
    from propulsor.study.table import Table

    study = load_study(write(tmp_path, STUDY))
    out = tmp_path / "out"
    out.mkdir()

    def row(k, key):
        return {"variant": k, "key": key, "tyre_width_mm": 70.0, "load_N": 30000.0, "T_at_V_max_C": 0.1 + k,
                "peak_pressure_q_m_MPa": 1 / 3, "contact_length_l_mm": None, "all_checks_passed": k == 1,
                "status": "ok", "reason": "", "failed_checks": "", "seconds": 1.5, "worker": "h:1"}

    t = Table(out, study, False)
    for k, key in enumerate(("1234e567", "0000000000000001", "abcdef"), 1):
        t.add(row(k, key))
    t.close()
    text = (out / "results.csv").read_text()
    (out / "results.csv").write_text(text[:-5])  # the last line cut short
    t = Table(out, study, True, keys=["1234e567", "abcdef"])  # the second row is another version's
    assert [r["key"] for r in t.rows] == ["1234e567"] and t.done_keys() == {"1234e567"}
    t.add(row(3, "abcdef"))
    t.close()
    rows = read_rows(out)
    assert [r["key"] for r in rows] == ["1234e567", "abcdef"] and rows[0]["T_at_V_max_C"] == repr(1.1)
    pq_rows = parquet_is_csv(out)
    assert pq_rows[0]["peak_pressure_q_m_MPa"] == 1 / 3 and pq_rows[0]["contact_length_l_mm"] is None
    # the rows come in the order the variants finish; a study done puts them in the variants' order
    t = Table(out, study, False)
    for k in (3, 1, 2):
        t.add(row(k, f"k{k}"))
    t.close()
    assert [r["variant"] for r in read_rows(out)] == ["3", "1", "2"]
    t.in_order()
    assert [r["variant"] for r in read_rows(out)] == ["1", "2", "3"]
    assert [r["variant"] for r in parquet_is_csv(out)] == [1, 2, 3]


def test_a_study_in_the_gallery_folder_is_linked_from_the_gallery(tmp_path, monkeypatch, capsys):
    """`propulsor explore --out output/X` (the gallery's folder) rewrites output/index.html with the study:
    its title (escaped), counts, front picture and page, whose points link to the variants;
    `propulsor gallery` of a folder holding only studies writes it too; a broken study.json is a note."""
    monkeypatch.chdir(tmp_path)
    study = write(tmp_path, STUDY.replace('title = "road wheel: tyre width x load"', 'title = "<b>wheel</b> & co"')
                  .replace("load_N = { from = 30000.0, to = 50000.0, step = 10000.0 }", "load_N = [30000.0]"))
    assert main(["explore", str(study), "--out", "output/wheel_study", "--workers", "1", "-q"]) == 0
    index = (tmp_path / "output" / "index.html").read_text()
    assert '<a href="wheel_study/study.html">&lt;b&gt;wheel&lt;/b&gt; &amp; co</a>' in index
    assert "<b>wheel" not in index and "depth design · 2 variants · " in index
    assert '<img src="wheel_study/pareto_front.png"' in index and 'href="wheel_study/results.parquet"' in index
    assert '<a href="#design-studies">design studies</a>' in index
    page = (tmp_path / "output" / "wheel_study" / "study.html").read_text()
    rows = read_rows(tmp_path / "output" / "wheel_study")
    met = [r for r in rows if r["status"] == "ok"]
    assert page.count("<area ") == len(met) + sum(r["status"] == "rejected" for r in rows) >= 1
    for r in met:
        assert f'href="#v{r["variant"]}"' in page and f'<tr id="v{r["variant"]}"' in page
    # the gallery command on a folder of studies only; a study.json that is not JSON is a note
    (tmp_path / "output" / "index.html").unlink()
    bad = tmp_path / "output" / "broken"
    bad.mkdir()
    (bad / "study.json").write_text("{<script>")
    (bad / "study.html").write_text("x")
    assert main(["gallery", "output", "-q"]) == 0
    index = (tmp_path / "output" / "index.html").read_text()
    assert "wheel_study/study.html" in index and "broken: study.json not readable: " in index


def test_a_variant_runs_on_one_core_and_the_longest_are_submitted_first(monkeypatch, tmp_path):
    """A variant's build runs inline (a budget of one process: no forked helpers, no OCCT threads) so the
    cluster's one-thread workers fill the cores; the variants go to the scheduler longest first by the
    part's size estimate."""
    import distributed

    from propulsor import parallel
    from propulsor.study import engine, load_study
    from propulsor.study import evaluate as ev

    monkeypatch.delenv("PROPULSOR_JOBS", raising=False)
    seen = []
    monkeypatch.setattr(ev, "_evaluate", lambda *a: seen.append(parallel.jobs_budget()) or {})
    ev.evaluate("road_wheel", {}, None, {}, "design", ())
    assert seen == [1] and "PROPULSOR_JOBS" not in os.environ

    study = load_study(write(tmp_path, f"""
[study]
part = "{ROOT / 'parts' / 'ncg_seed002.toml'}"
depth = "proof"
[vary]
driven_teeth = [64, 96, 80]
[objectives]
minimize = ["speed_ripple"]
"""))
    submitted = []

    class Client:
        loop = None

        def submit(self, fn, *args, key, priority, **kw):
            submitted.append((args[3]["driven_teeth"], priority))
            return key

    class Finished:  # as_completed of no future: nothing left to wait for
        def is_empty(self):
            return True

    monkeypatch.setattr(distributed, "as_completed", lambda futures, loop=None: Finished())
    todo = [(i, v, f"k{i}") for i, v in enumerate(study.variants, 1)]
    engine._evaluate_all(Client(), study, tmp_path, todo, None, None)
    assert submitted == [(96, 3), (80, 2), (64, 1)]


def test_an_interrupted_study_says_what_it_kept(tmp_path):
    """The trial's Ctrl-C before any variant finished was told "the finished variants are in results.csv" of a
    folder that did not exist: the line now counts the rows there are."""
    import argparse

    from propulsor.cli import _study_kept

    args = argparse.Namespace(out=str(tmp_path / "s"), study="x.toml")
    assert _study_kept(args) == "no variant had finished: nothing written"
    (tmp_path / "s").mkdir()
    (tmp_path / "s" / "results.csv").write_text("variant,ok\n")
    assert _study_kept(args) == "no variant had finished: nothing written"
    (tmp_path / "s" / "results.csv").write_text("variant,ok\n1,true\n2,true\n")
    assert _study_kept(args) == f"2 finished variants in {tmp_path / 's' / 'results.csv'} (--resume runs the rest)"


def test_a_balancer_study_orders_its_variants_by_the_estimate_a_build_makes(tmp_path):
    """The balancer's size estimate needs validated parameters (the suspension's travel): a study orders its
    variants by it as a build's own estimate is made (loading.early_estimate), not as if each were free."""
    from propulsor.loading import early_estimate
    from propulsor.study import engine, load_study

    study = load_study(write(tmp_path, f"""
[study]
part = "{ROOT / 'parts' / 'balancer.toml'}"
depth = "build"
[vary]
sweep_steps_per_deg = [1.0, 4.0, 2.0]
[objectives]
minimize = ["mass_balancer_kg"]
"""))
    seconds = {v["sweep_steps_per_deg"]: engine.expected_seconds(study, v) for v in study.variants}
    assert seconds[1.0] == early_estimate(ROOT / "parts" / "balancer.toml") > 0
    assert seconds[4.0] > seconds[2.0] > seconds[1.0]
