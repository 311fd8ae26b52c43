"""Work beside the main process on the machine's second core (forked processes).

A part runs its long proof (a motion sweep) or the files and checks of its solids in forked
workers while it goes on; where `fork` is missing everything runs inline.  Forked children must
not use OCCT's thread pool (it does not survive a fork): they mesh with parallel=False.

How many: :mod:`.process_slots` (the budget of processes, the slots the builds of one command share, make's
jobserver).  A job's progress while it runs: :mod:`.job_ticks`.  Both are imported here under their names, the
interface the part modules use.

Workers belong to the build that started them: a build runs inside :class:`Workers` (a context manager;
the current one is a context variable, so each thread, and each task of an event loop, has its own), every pool
forked while it is current is its own, and leaving it kills what is left of them — never another build's, so
builds in several threads of one process (a notebook, a Dask worker) neither see nor stop each other's
processes.  Workers never outlive the build either: each asks the kernel for SIGKILL when its parent dies
(``PR_SET_PDEATHSIG``, Linux) and leaves SIGINT to the parent; the command line, ending on a signal, stops every
worker of the process (:func:`kill_workers`).  The output locks of every build of the process
(:meth:`Workers.close_in_workers`) are closed in every worker forked, so a worker never holds a build's lock.
"""

from __future__ import annotations

import contextvars
import ctypes
import multiprocessing as mp
import os
import signal
import threading
import weakref
from concurrent.futures import ProcessPoolExecutor

from . import job_ticks
from .job_ticks import callback_lock, event_pipe, forward_events, listening, result, tick  # noqa: F401  (the interface)
from .process_slots import (Jobserver, _give_slots, _take_slots, can_fork, jobs_budget, make_jobs,  # noqa: F401
                            open_slots_to_workers, share_slots, slots_shared, threads_ok, worker_cap)

_PR_SET_PDEATHSIG = 1
#: every pool of the process (for :func:`kill_workers`, the command line's end)
_POOLS: "weakref.WeakSet[ProcessPoolExecutor]" = weakref.WeakSet()
#: file descriptors closed in every worker forked: the output locks of the builds running in this process, each with
#: the (device, inode) of the file it was opened on, so that a worker closes it only while the number still names that
#: file (a lock closed before its build's block ends leaves a number that a pool's own pipe may take next: the worker
#: would close its call queue, "Bad file descriptor")
_CLOSE_IN_WORKERS: dict[int, tuple[int, int]] = {}
_CLOSE_LOCK = threading.Lock()
#: the Workers of the build running in this thread (context), or None outside a build
_CURRENT: "contextvars.ContextVar[Workers | None]" = contextvars.ContextVar("propulsor_workers", default=None)


class Done:
    """A finished computation with the interface of a Future."""

    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value


class Workers:
    """The worker processes of one build (a context manager): every pool forked while it is the current one
    belongs to it, and leaving the block kills what is left of them (with SIGINT / SIGTERM held off meanwhile)
    and forgets the descriptors it named with :meth:`close_in_workers`.  Nested blocks (a design computed
    inside a build) own their own pools; the outer one resumes after."""

    def __init__(self):
        self._pools: list[ProcessPoolExecutor] = []
        self._fds: list[int] = []
        self._lock = threading.Lock()
        self._token = None

    def open(self) -> "Workers":
        """Make this the current build's workers (in this thread / context); returns itself."""
        self._token = _CURRENT.set(self)
        return self

    def close(self) -> None:
        """Kill what is left of this build's workers, forget its descriptors, and stop being the current one
        (the caller holds off SIGINT / SIGTERM meanwhile: :meth:`__exit__` does)."""
        try:
            self.kill()
        finally:
            if self._token is not None:
                _CURRENT.reset(self._token)
                self._token = None
            with _CLOSE_LOCK:
                for fd in self._fds:
                    _CLOSE_IN_WORKERS.pop(fd, None)
            self._fds.clear()

    def __enter__(self) -> "Workers":
        return self.open()

    def __exit__(self, *exc) -> None:
        from .signals import held_signals

        with held_signals():
            self.close()

    def adopt(self, pool: ProcessPoolExecutor) -> None:
        with self._lock:
            self._pools.append(pool)

    def close_in_workers(self, fd: int) -> None:
        """Close file descriptor `fd` (this build's output lock) in every worker forked from now on, this build's
        and any other build's of the process, for as long as this block runs."""
        st = os.fstat(fd)
        with _CLOSE_LOCK:
            _CLOSE_IN_WORKERS[fd] = (st.st_dev, st.st_ino)
        self._fds.append(fd)

    def kill(self) -> None:
        """Kill this build's workers that are still running and drop its pools (their slots given back)."""
        with self._lock:
            pools, self._pools = self._pools, []
        _kill_pools(pools)


def current_workers() -> "Workers | None":
    """The Workers of the build running in this thread (context), or None."""
    return _CURRENT.get()


def _close_fds() -> tuple[tuple[int, int, int], ...]:
    """(fd, device, inode) of every descriptor a worker forked now closes (:data:`_CLOSE_IN_WORKERS`)."""
    with _CLOSE_LOCK:
        return tuple(sorted((fd, *key) for fd, key in _CLOSE_IN_WORKERS.items()))


def kill_pool(pool: ProcessPoolExecutor) -> None:
    """Kill the processes of `pool` at once (an interrupted build does not wait for its workers' jobs)."""
    _kill_pools([pool])


def _kill_pools(pools) -> None:
    """Kill the processes of `pools` at once, wait for them, drop the pools and give back their slots."""
    procs = [proc for pool in pools for proc in getattr(pool, "_procs", {}).values()]
    for proc in procs:
        try:
            proc.kill()
        except (OSError, ValueError):  # gone already, or closed
            pass
    for proc in procs:
        try:
            proc.join(timeout=5)
        except (AssertionError, ValueError):  # not ours to join (a fork of a fork) or closed
            pass
    for pool in pools:
        try:
            pool.shutdown(wait=False, cancel_futures=True)
        except Exception:  # noqa: BLE001 - a pool whose workers were killed is broken; that is the point
            pass
        if isinstance(pool, _SlotPool):
            pool.give_back()
        _POOLS.discard(pool)


def _worker_init(parent_pid: int, close_fds: tuple[tuple[int, int, int], ...]) -> None:
    """In a fresh worker: die with the parent, leave SIGINT to it, drop the parent's locks."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (AttributeError, OSError):  # not Linux: the pool's own watch of the parent remains
        pass
    if os.getppid() != parent_pid:  # the parent died before the request took effect
        os._exit(1)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    job_ticks._TICK = None  # a job's ticks are its own process's (:func:`_ticking` sets them), not a forking job's
    for fd, dev, ino in close_fds:
        try:
            st = os.fstat(fd)
            if (st.st_dev, st.st_ino) == (dev, ino):  # still the lock file, not a number taken since (a pipe)
                os.close(fd)
        except OSError:
            pass


class _SlotPool(ProcessPoolExecutor):
    """A pool of forked workers holding shared process slots until it is shut down (waiting) or, for a
    single job (:func:`start`), until that job is done."""

    def __init__(self, slots: list[bytes], **kw):
        super().__init__(**kw)
        self._slots = slots
        self._slot_lock = threading.Lock()
        self._procs: dict = {}  # pid -> Process: kept past shutdown(wait=False), which forgets them

    def submit(self, fn, /, *args, **kwargs):
        """The job, pickled here in the caller's thread as its arguments stand now (:func:`_sent`).  The executor
        would pickle it later, in its feeder thread, while the caller goes on: a cache the caller fills on an
        argument meanwhile (a design's outlines' grids) made the job fail ("dictionary changed size during
        iteration", a build in CI) or took it in whatever state it had reached.  A call that does not pickle gives a
        Future holding the error, as the executor's own feeder does."""
        from concurrent.futures import Future
        from multiprocessing.reduction import ForkingPickler

        try:
            payload = bytes(ForkingPickler.dumps((fn, args, kwargs)))
        except Exception as exc:  # noqa: BLE001 - the job's error, handed over where the caller waits for it
            failed = Future()
            failed.set_exception(exc)
            return failed
        fut = super().submit(_sent, payload)
        self._procs.update(self._processes or {})  # the fork context starts every worker at the first submit
        return fut

    def give_back(self) -> None:
        with self._slot_lock:
            slots, self._slots = self._slots, []
        _give_slots(slots)

    def shutdown(self, wait: bool = True, *, cancel_futures: bool = False) -> None:
        super().shutdown(wait=wait, cancel_futures=cancel_futures)
        if wait:
            self.give_back()


def _sent(payload: bytes):
    """A job pickled by :meth:`_SlotPool.submit`, run in the worker: fn(*args, **kwargs)."""
    import pickle

    fn, args, kwargs = pickle.loads(payload)
    return fn(*args, **kwargs)


def fork_pool(workers: int) -> ProcessPoolExecutor | None:
    """A pool of at most `workers` forked workers (:func:`worker_cap`, and no more than the shared slots
    free now), or None where fork is not available or the build's budget allows no worker (the work
    then runs inline)."""
    workers = worker_cap(workers)
    if not can_fork() or workers < 1:
        return None
    slots = _take_slots(workers)
    workers = len(slots) if isinstance(slots, list) else slots
    if workers < 1:
        return None
    pool = _SlotPool(slots if isinstance(slots, list) else [], max_workers=workers, mp_context=mp.get_context("fork"),
                     initializer=_worker_init, initargs=(os.getpid(), _close_fds()))
    _POOLS.add(pool)
    owner = _CURRENT.get()
    if owner is not None:  # the running build's: killed when it ends, whatever its thread
        owner.adopt(pool)
    return pool


def as_if_sent(obj):
    """`obj` after the pickle round trip a forked worker's arguments and results go through.  Work run
    inline gets the same copies, so that its files do not depend on where it ran (OCCT shapes are
    pickled through their B-rep text: a -0.0 in the original comes back as 0.0)."""
    import pickle

    return pickle.loads(pickle.dumps(obj))


def inline(fn, *args) -> Done:
    """fn(*args) in this process, its arguments and result passed as a worker's would be."""
    return Done(as_if_sent(fn(*as_if_sent(args))))


def start(fn, *args, counter=None, forked_only: bool = False):
    """Run fn(*args) in one forked process; returns a Future (a :class:`Done` when run inline).  `counter`:
    ``counter(done, total)`` told how far the job has come where it calls :func:`tick` — at once when run
    inline, while :func:`result` waits for it when forked (through a pipe).  ``forked_only``: None where no worker
    may be forked now, instead of the work run here (a job started ahead of the step that decides whether it is
    wanted: :func:`abandon` drops it)."""
    pool = fork_pool(1)
    if pool is None and forked_only:
        return None
    if pool is None:
        before, job_ticks._TICK = job_ticks._TICK, counter  # a job without a counter ticks to none (not to a job
        try:                                                 # it runs within)
            return inline(fn, *args)
        finally:
            job_ticks._TICK = before
    if counter is None:
        fut = pool.submit(fn, *args)
    else:
        r, w = os.pipe()
        os.set_blocking(r, False)
        os.set_blocking(w, False)  # a full pipe drops the worker's ticks, never holds its work
        try:
            fut = pool.submit(job_ticks._ticking, w, fn, *args)  # the fork context forks the worker here: it has `w`
        finally:
            os.close(w)
        fut.propulsor_ticks = job_ticks._Ticks(r, counter, fut)
        job_ticks._pump_add(fut.propulsor_ticks)
    fut.add_done_callback(lambda _f: pool.give_back())
    pool.shutdown(wait=False)
    fut.propulsor_pool = pool
    return fut


def abandon(job) -> None:
    """Drop a job :func:`start` forked whose result is not wanted after all: its worker killed if it still runs (its
    slot given back, its ticks drained to the end); nothing for a job run inline (done already) or None."""
    pool = getattr(job, "propulsor_pool", None)
    if pool is not None and not job.done():
        kill_pool(pool)


def kill_workers() -> None:
    """Kill every worker process of this process at once and drop every pool: the command line's end after a
    signal (the process is going; a build's own workers go with its :class:`Workers` block)."""
    _kill_pools(list(_POOLS))
    children = mp.active_children()
    for proc in children:
        proc.kill()
    for proc in children:
        proc.join(timeout=5)
