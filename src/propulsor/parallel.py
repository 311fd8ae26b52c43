"""Work beside the main process on the machine's second core (forked processes).

A part runs its long proof (a motion sweep) or the files and checks of its solids in forked
workers while it goes on; where `fork` is missing everything runs inline.  Forked children must
not use OCCT's thread pool (it does not survive a fork): they mesh with parallel=False.
"""

from __future__ import annotations

import multiprocessing as mp
from concurrent.futures import ProcessPoolExecutor


class Done:
    """A finished computation with the interface of a Future."""

    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value


def can_fork() -> bool:
    return "fork" in mp.get_all_start_methods()


def fork_pool(workers: int) -> ProcessPoolExecutor | None:
    """A pool of forked workers, or None where fork is not available."""
    return ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("fork")) if can_fork() else None


def start(fn, *args):
    """Run fn(*args) in one forked process; returns a Future (a :class:`Done` when run inline)."""
    pool = fork_pool(1)
    if pool is None:
        return Done(fn(*args))
    fut = pool.submit(fn, *args)
    pool.shutdown(wait=False)
    return fut
