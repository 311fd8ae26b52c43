"""The study engine: the variants as tasks of a Dask distributed cluster — by default a LocalCluster of
worker processes on this machine's cores, or an existing cluster (``dask scheduler`` / ``dask worker``)
at --scheduler.  Rows are written as the variants finish; the scheduler re-runs the variant of a worker
that died on another worker, and each variant is one row of the table, whatever happened to it."""

from __future__ import annotations

import json
import logging
import math
import os
import signal
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from .evaluate import evaluate
from .folder import holding
from .results import plot_front, ranked, requirement_failure, write_front
from .spec import Study, variant_key
from .table import Table

#: the marker that says a folder holds a study propulsor wrote (it may be written over)
MARKER = "study.json"


@dataclass
class Outcome:
    rows: list
    ranked: list
    ran: int  # variants evaluated by this run (the others came from the table: --resume)
    seconds: float
    workers: int
    folder: Path


def connect(scheduler: str | None, workers: int | None, worker_wait: float | None = None, progress=lambda msg: None):
    """(client, cluster or None): a client of the scheduler at `scheduler`, or of a new LocalCluster of
    `workers` processes (the machine's cores when None).  InputError when the address is not tcp://HOST:PORT
    or no scheduler answers there within cluster.ANSWER_TIMEOUT_S (connection, handshake and answer);
    EnvironmentFailure when it has no worker after `worker_wait` s (cluster.WORKER_WAIT_S when None)."""
    from . import cluster as dask_cluster
    from .cluster import WORKER_WAIT_S, probe, scheduler_address, wait_for_workers

    for name in ("distributed", "distributed.worker", "distributed.scheduler", "distributed.nanny",
                 "distributed.core", "distributed.comm", "distributed.batched", "distributed.client", "tornado"):
        logging.getLogger(name).setLevel(logging.CRITICAL)
    from distributed import Client

    if scheduler is not None:
        address = scheduler_address(scheduler)
        probe(address)  # bounded: a listener that never answers is refused here, before any Client exists
        try:
            client = Client(address, timeout=dask_cluster.ANSWER_TIMEOUT_S, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError("--scheduler", scheduler, f"no Dask scheduler answers there ({type(exc).__name__}); "
                             "start one with `dask scheduler` and workers with `dask worker ADDRESS`") from None
        try:
            wait_for_workers(client, address, WORKER_WAIT_S if worker_wait is None else worker_wait, progress)
        except BaseException:
            client.close()
            raise
        return client, None
    import shutil
    import tempfile

    n = workers or os.cpu_count() or 1
    progress(f"starting a local Dask cluster of {n} worker process(es)")
    scratch = tempfile.mkdtemp(prefix="propulsor-dask-")
    try:
        cluster = local_cluster(n, scratch)
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise
    cluster.propulsor_scratch = scratch  # removed when the study lets the cluster go
    return Client(cluster, set_as_default=False), cluster


#: the Dask settings of the local cluster's workers (each key a Dask config path)
WORKER_CONFIG = {
    # a build forks its own workers (the solids' files and checks): the worker processes may not be daemons
    "distributed.worker.daemon": False,
    # the environment the nanny gives a worker before it starts: numpy's BLAS / OpenMP threads at 1 (a variant
    # a core), and NOT Dask's MALLOC_TRIM_THRESHOLD_ = 65536: setting it switches off glibc's dynamic mmap
    # threshold, so every array over 128 KiB is mapped and unmapped afresh; a variant's evaluation then
    # runs 4-6 % slower than the same call outside Dask (4 proof variants of the seed-002 pair: 30.8-31.1 CPU s
    # with it, 29.3-29.5 without)
    "distributed.nanny.pre-spawn-environ": {"OMP_NUM_THREADS": 1, "MKL_NUM_THREADS": 1, "OPENBLAS_NUM_THREADS": 1},
    # the worker's statistical profiler samples the evaluating thread's stack every 10 ms, and its event
    # loop wakes every 20-500 ms for ticks, system and memory monitors: nothing of it is read in a study
    # (no dashboard is looked at); once a second is enough to notice a stuck or swelling worker
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "1s",
    "distributed.worker.memory.monitor-interval": "1s",
}


def local_cluster(n: int, directory: str | None = None):
    """A LocalCluster of `n` worker processes of one thread each, with :data:`WORKER_CONFIG`; its HTTP
    server on any free port of 127.0.0.1; the workers' scratch space (their ``worker-*.dirlock`` files) in
    `directory` when given (the engine's own temporary folder, removed with the cluster even on Ctrl-C)."""
    import dask
    from distributed import LocalCluster

    extra = {"local_directory": directory} if directory else {}
    config = {**WORKER_CONFIG, "temporary-directory": directory} if directory else WORKER_CONFIG
    # the worker processes start with SIGINT ignored (kept across their exec): a Ctrl-C at the terminal reaches every
    # process of the group, and each worker would print its KeyboardInterrupt traceback (33 lines in the trial);
    # the study's own process handles it and stops the cluster
    held = threading.current_thread() is threading.main_thread()
    before = signal.signal(signal.SIGINT, signal.SIG_IGN) if held else None
    try:
        with dask.config.set(config):
            return LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address="127.0.0.1:0",
                                silence_logs=logging.CRITICAL, **extra)
    finally:
        if held:
            signal.signal(signal.SIGINT, before)


def vet_folder(out: Path, build_best: int = 0) -> None:
    """`out` may hold the study: a UTF-8 path within the length limits, missing, empty, or a study folder
    propulsor wrote; the folders ``best/<rank>/`` that `build_best` writes empty or a propulsor build's
    (the rules of ``propulsor build --out`` without --force).  InputError otherwise."""
    from .. import output_folder as of

    of.representable(Path(os.path.abspath(out)))
    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise InputError("--out", str(out), "must be a folder (not a file or a link)")
    if out.is_dir() and any(out.iterdir()) and not (out / MARKER).is_file():
        raise InputError("--out", str(out), f"holds files but no {MARKER}: not a study folder; choose another")
    for rank in range(1, build_best + 1):
        best = out / "best" / str(rank)
        if os.path.lexists(best):
            try:
                of.vet_target(best)
            except InputError as exc:
                raise InputError("--build-best", build_best, f"{best}: {exc.limit}") from None


def write_marker(out: Path, study: Study, rows=None, rank=None) -> None:
    """study.json: what the folder holds (the gallery reads it); with the rows once the study is done."""
    from ..version import __version__
    from ..export.html import write_atomically

    info: dict = {"study": str(study.path), "title": study.title, "part": str(study.part_file), "depth": study.depth,
                  "version": __version__}
    if rows is not None:
        info.update({"variants": len(rows), "meeting_requirements": len(rank),
                     "front": [r["variant"] for layer, r in rank if layer == 1],
                     "objectives": {n: ("minimize" if n in study.minimize else "maximize") for n in study.objectives}})
    write_atomically(out / MARKER, json.dumps(info, indent=1) + "\n")


class Rate:
    """The progress of the variants: a count event (``progress.Event``: phase "variants", done, total) whose text
    gives the count, the rate, the time left and the variant that ended; "variants 0/N" when it starts."""

    PHASE = "variants"

    def __init__(self, total: int, before: int, progress):
        self.total, self.before, self.progress = total, before, progress
        self.t0 = time.perf_counter()
        self.n = 0
        self._say(f"{before}/{total} variants", before)

    def _say(self, text: str, done: int) -> None:
        from ..progress import PROGRESS, Event

        self.progress(Event(text, PROGRESS, self.PHASE, done, self.total))

    def tick(self, row: dict) -> None:
        self.n += 1
        dt = time.perf_counter() - self.t0
        rate = self.n / dt * 60 if dt > 0 else 0.0
        left = self.total - self.before - self.n
        eta = left / (self.n / dt) if self.n and dt > 0 else math.inf
        self._say(f"{self.before + self.n}/{self.total} variants, {rate:.1f} per min, "
                  f"{'about ' + _span(eta) + ' left' if left else 'done'}; variant {row['variant']}: "
                  f"{row['status']}", self.before + self.n)


def _span(s: float) -> str:
    if not math.isfinite(s):
        return "?"
    return f"{s:.0f} s" if s < 120 else f"{s / 60:.0f} min"


def run(study: Study, out: Path, *, scheduler: str | None = None, workers: int | None = None,
        resume: bool = False, progress=lambda msg: None, client=None, build_best: int = 0,
        wait: bool = True, worker_wait: float | None = None) -> Outcome:
    """Run the study into folder `out`: results.csv, results.parquet, front.csv, pareto_front.png, study.html
    (and variants/ at depth build; best/<rank>/ of the `build_best` best).  The folder is locked for all of it
    (:func:`holding`); nothing is written before the study file, the folder and the scheduler are known good."""
    with holding(out, wait=wait, progress=progress):
        vet_folder(out, build_best)  # as it is now, with the lock held
        outcome = _run(study, out, scheduler=scheduler, workers=workers, resume=resume, progress=progress,
                       client=client, worker_wait=worker_wait)
        if build_best:
            from .best import build_best as build_the_best

            build_the_best(study, outcome, build_best, progress=progress)
        return outcome


def _run(study: Study, out: Path, *, scheduler, workers, resume, progress, client, worker_wait) -> Outcome:
    from ..version import __version__
    from .cluster import WORKER_WAIT_S

    own = client is None
    cluster = None
    wait_s = WORKER_WAIT_S if worker_wait is None else worker_wait
    if own:
        client, cluster = connect(scheduler, workers, wait_s, progress)
    try:
        n_workers = len(client.scheduler_info().get("workers", {}))
        out.mkdir(parents=True, exist_ok=True)
        write_marker(out, study)
        keys = [variant_key(study, v, __version__) for v in study.variants]
        table = Table(out, study, resume, keys)
        try:
            done = table.done_keys()
            todo = [(i, v, k) for i, (v, k) in enumerate(zip(study.variants, keys), 1) if k not in done]
            before = len(study.variants) - len(todo)
            progress(f"{study.title}: {len(study.variants)} variants at depth {study.depth} on {n_workers} Dask "
                     f"worker(s)" + (f"; {before} already in {table.path}" if before else ""))
            t0 = time.perf_counter()
            _evaluate_all(client, study, out, todo, table, Rate(len(study.variants), before, progress),
                          scheduler or "the local cluster", wait_s)
            seconds = time.perf_counter() - t0
        finally:
            table.close()
        table.in_order()
        rows = list(table.rows)
        rank = ranked(study, rows)
        write_front(out, study, rank)
        try:
            points = plot_front(out, study, rows, rank)
        except OSError:
            raise
        except Exception as exc:  # noqa: BLE001 - the picture is not worth the study: the page without it
            (out / "pareto_front.png").unlink(missing_ok=True)
            progress(f"the Pareto front's picture was not drawn ({type(exc).__name__}: {exc})")
            points = None
        from .page import write_page

        write_page(out, study, rows, rank, points=points)
        write_marker(out, study, rows, rank)
        return Outcome(rows, rank, len(todo), seconds, n_workers, out)
    except OSError as exc:  # a write refused without a name (a full disk): the study's folder
        if exc.filename is None:
            exc.filename = str(out)
        raise
    finally:
        if own:
            client.close()
            if cluster is not None:
                cluster.close()
                import shutil

                shutil.rmtree(getattr(cluster, "propulsor_scratch", ""), ignore_errors=True)


def expected_seconds(study: Study, values: dict) -> float:
    """The variant's build time by the part type's size estimate (parts/size.py), as a build's is made before its
    design (parts.early_size: the values alone, or validated where the estimate needs it: the balancer's travel, a
    few ms); 0 where the values are refused (such a variant fails fast)."""
    from ..params import load_params
    from ..parts import early_size, get_part_type

    try:
        pt = get_part_type(study.part_type)
        params = load_params(pt.params_cls, {**study.base, **values}, validate=False)
        return float(early_size(pt, params, study.part_file).seconds)
    except Exception:  # noqa: BLE001 - the variant's own trouble is its row's, not the order's
        return 0.0


def _evaluate_all(client, study: Study, out: Path, todo, table: Table, rate: Rate, where: str = "",
                  worker_wait: float = 60.0) -> None:
    """Submit every variant, the longest first by the size estimate (the last tasks short, so that no
    worker idles at the end while another finishes a long one); a row as each finishes.  When the cluster
    has had no worker for `worker_wait` s, EnvironmentFailure (the finished rows are in the table)."""
    from distributed import as_completed

    from .cluster import no_worker

    wanted = study.values
    source = str(study.part_file)
    futures = {}
    order = sorted(todo, key=lambda t: (-expected_seconds(study, t[1]), t[0]))
    for j, (i, values, key) in enumerate(order):
        build_dir = str((out / "variants" / key).resolve()) if study.depth == "build" else None
        fut = client.submit(evaluate, study.part_type, study.base, source, values, study.depth, wanted, build_dir,
                            key=f"propulsor-variant-{key}", pure=False, retries=1, priority=len(order) - j)
        futures[fut] = (i, values, key)
    finished = as_completed(list(futures), loop=client.loop)
    looked = alone_since = None
    while not finished.is_empty():
        batch = finished.next_batch(block=False)
        if not batch:
            now = time.monotonic()
            if looked is None or now - looked >= 1.0:  # are there workers at all? (once a second)
                looked = now
                if client.nthreads():
                    alone_since = None
                elif alone_since is None:
                    alone_since = now
                elif now - alone_since > worker_wait:
                    raise no_worker(where, worker_wait, during=True)
            time.sleep(0.05)
            continue
        for fut in batch:
            _row(study, futures.pop(fut), fut, table, rate)


def _row(study: Study, which, fut, table: Table, rate: Rate) -> None:
    i, values, key = which
    try:
        res = fut.result()
    except Exception as exc:  # the task itself was lost (its workers kept dying): a row saying so
        res = {"values": {}, "all_checks_passed": None, "failed_checks": "", "status": "error",
               "reason": f"{type(exc).__name__}: {exc}", "seconds": None, "worker": ""}
    row = {"variant": i, "key": key, **values, **res.pop("values"), **res}
    if row["status"] == "ok":
        why = requirement_failure(study, row)
        if why:
            row["status"], row["reason"] = "rejected", why
    table.add(row)
    fut.release()
    rate.tick(row)
