"""The cyclic garbage collector of the program's own processes (``policy.GC_THRESHOLDS``).

Set by the program (``propulsor``, ``python -m propulsor``) before it imports anything large, so that its builds and
every process they fork inherit it: processes that end with their command.  A study (``propulsor explore``) puts
Python's own thresholds back (:func:`untune`) and its Dask workers keep them: processes that run variant after
variant for hours, whose cyclic garbage the tuned collector would leave to pile up.  Never set by the Python API: the
collector of a user's own process is the user's.  Pure standard library.
"""

from __future__ import annotations

import gc

from . import policy

__all__ = ["tune", "untune"]

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
