"""A study's folder held for the whole study (its build-best too): the lock of a build's output."""

from __future__ import annotations

import os
from contextlib import contextmanager
from pathlib import Path

from ..errors import InputError

__all__ = ["holding"]


@contextmanager
def holding(out: Path, wait: bool = True):
    """The study's folder locked for the whole study (its build-best too): the lock of a build's output
    (output_folder.OutputLock, ``.<name>.lock`` beside it), so that one study or one build owns a folder at
    a time.  With `wait` False a held lock is InputError; else one line says whom it waits for."""
    import sys

    from .. import output_folder as of

    of.representable(Path(os.path.abspath(out)))
    of.prepare_parent(out)
    lock = of.OutputLock(out)
    try:
        lock.acquire(wait=wait, on_wait=lambda pid: print(f"propulsor: {out} is in use by process {pid}; waiting",
                                                          file=sys.stderr, flush=True))
    except of.Busy as busy:
        raise InputError("--out", str(out), f"is in use by process {busy.pid} (--no-wait)") from None
    try:
        yield lock
    finally:
        lock.release()
