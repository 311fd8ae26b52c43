"""The cyclic garbage collector of the program's own processes (``policy.GC_THRESHOLDS``).

Set by the program (``propulsor``, ``python -m propulsor``) before it imports anything large, so that its builds and
every process they fork inherit it: processes that end with their command.  A study (``propulsor explore``) puts
Python's own thresholds back (:func:`untune`) and its Dask workers keep them: processes that run variant after
variant for hours, whose cyclic garbage the tuned collector would leave to pile up.  Never set by the Python API: the
collector of a user's own process is the user's.  Pure standard library.
"""

from __future__ import annotations

import contextlib
import gc

from . import policy

__all__ = ["tune", "untune", "off_then_frozen"]

#: the thresholds the first :func:`tune` of this process replaced
_BEFORE: list = []


def tune() -> None:
    """Set the collector's thresholds to ``policy.GC_THRESHOLDS`` (those it had kept for :func:`untune`)."""
    if not _BEFORE:
        _BEFORE.append(gc.get_threshold())
    gc.set_threshold(*policy.GC_THRESHOLDS)


def untune() -> None:
    """The thresholds as they were before :func:`tune` (nothing where it was not called)."""
    if _BEFORE:
        gc.set_threshold(*_BEFORE[0])


@contextlib.contextmanager
def off_then_frozen():
    """The garbage collector off within (where it was on), and what was made there moved out of its sight
    (``gc.freeze``) as the block ends: loading modules adds objects that live on, and each collection scans the
    growing heap.  The program's tuned collector (``policy.GC_THRESHOLDS``) made 6 collections while a batch loaded,
    0.12 of its 2.4 CPU s (Python's own thresholds: 891, 0.4 s), on the critical path: the other core waits for the
    first fork.  What they would have freed (the imports' cycles) stays with the frozen rest: at most 2 MiB of the
    process's 593."""
    was_on = gc.isenabled()
    gc.disable()
    try:
        yield
        gc.freeze()
    finally:
        if was_on:
            gc.enable()
