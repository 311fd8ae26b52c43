"""Work beside the main process on the machine's second core (forked processes).

A part runs its long proof (a motion sweep) or the files and checks of its solids in forked
workers while it goes on; where `fork` is missing everything runs inline.  Forked children must
not use OCCT's thread pool (it does not survive a fork): they mesh with parallel=False.

Workers never outlive the build: each asks the kernel for SIGKILL when its parent dies
(``PR_SET_PDEATHSIG``, Linux) and leaves SIGINT to the parent, which stops them with
:func:`kill_workers` when it is interrupted.  Inherited file descriptors named by
:func:`close_in_workers` (the output lock) are closed in every worker, so a worker never holds
the build's lock.
"""

from __future__ import annotations

import ctypes
import multiprocessing as mp
import os
import signal
import weakref
from concurrent.futures import ProcessPoolExecutor

_PR_SET_PDEATHSIG = 1
_POOLS: "weakref.WeakSet[ProcessPoolExecutor]" = weakref.WeakSet()
_CLOSE_IN_WORKERS: set[int] = set()


class Done:
    """A finished computation with the interface of a Future."""

    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value


def can_fork() -> bool:
    return "fork" in mp.get_all_start_methods()


def close_in_workers(fd: int | None) -> None:
    """Close file descriptor `fd` in workers forked from now on (None: forget every one)."""
    if fd is None:
        _CLOSE_IN_WORKERS.clear()
    else:
        _CLOSE_IN_WORKERS.add(fd)


def _worker_init(parent_pid: int, close_fds: tuple[int, ...]) -> None:
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
    for fd in close_fds:
        try:
            os.close(fd)
        except OSError:
            pass


def fork_pool(workers: int) -> ProcessPoolExecutor | None:
    """A pool of forked workers, or None where fork is not available."""
    if not can_fork():
        return None
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("fork"),
                               initializer=_worker_init, initargs=(os.getpid(), tuple(sorted(_CLOSE_IN_WORKERS))))
    _POOLS.add(pool)
    return pool


def start(fn, *args):
    """Run fn(*args) in one forked process; returns a Future (a :class:`Done` when run inline)."""
    pool = fork_pool(1)
    if pool is None:
        return Done(fn(*args))
    fut = pool.submit(fn, *args)
    pool.shutdown(wait=False)
    return fut


def kill_workers() -> None:
    """Kill every worker process at once (the build was interrupted or failed) and drop the pools."""
    children = mp.active_children()
    for proc in children:
        proc.kill()
    for proc in children:
        proc.join(timeout=5)
    for pool in list(_POOLS):
        try:
            pool.shutdown(wait=False, cancel_futures=True)
        except Exception:  # noqa: BLE001 - a pool whose workers were killed is broken; that is the point
            pass
        _POOLS.discard(pool)
