"""The cyclic garbage collector of the program's own processes (``policy.GC_THRESHOLDS``).

Set by the program (``propulsor``, ``python -m propulsor``) before it imports anything large, so that its builds and
every process they fork inherit it, and on a local study's workers when their cluster starts.  Never by the Python API:
the collector of a user's own process is the user's.  Pure standard library.
"""

from __future__ import annotations

import gc

from . import policy

__all__ = ["tune", "dask_setup"]


def tune() -> tuple[int, int, int]:
    """Set the collector's thresholds to ``policy.GC_THRESHOLDS``; return the ones it had (to restore them)."""
    before = gc.get_threshold()
    gc.set_threshold(*policy.GC_THRESHOLDS)
    return before


def dask_setup(worker=None) -> None:
    """A Dask worker's preload hook (``distributed.worker.preload``: this module, in the local cluster's
    ``study.engine.WORKER_CONFIG``): each worker process, a restarted one too, tunes its collector as it starts."""
    tune()
