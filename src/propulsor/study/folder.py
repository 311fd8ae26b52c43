"""A study's folder held for the whole study (its build-best too): the lock of a build's output."""

from __future__ import annotations

import os
from contextlib import contextmanager
from pathlib import Path


__all__ = ["holding"]


@contextmanager
def holding(out: Path, wait: bool = True, progress=None):
    """The study's folder locked for the whole study (its build-best too): the lock of a build's output
    (output_folder.OutputLock, ``.<name>.lock`` beside it), so that one study or one build owns a folder at
    a time.  With `wait` False a held lock is FolderBusy (an InputError); else a notice to `progress` says whom it
    waits for."""
    from .. import output_folder as of
    from ..errors import FolderBusy
    from ..progress import Reporter

    of.representable(Path(os.path.abspath(out)))
    of.prepare_parent(out)
    lock = of.OutputLock(out)
    try:
        lock.acquire(wait=wait, on_wait=lambda pid: Reporter.of(progress).notice(f"{out} is in use by process {pid}; "
                                                                                 "waiting"))
    except of.Busy as busy:
        raise FolderBusy(str(out), busy.pid, doing="is in use") from None
    try:
        yield lock
    finally:
        lock.release()
