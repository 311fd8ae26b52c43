"""Replacing a file in one step: written under a temporary name in the same folder, then renamed over it,
so that a reader (or a second writer) sees the old file or the new one, never a part of either."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable

__all__ = ["replace_atomically"]


def replace_atomically(path: str | Path, write: Callable[[str], None], mode: int = 0o644) -> Path:
    """Call ``write(tmp)`` with the name of a fresh temporary file beside `path`, give it `mode` and
    rename it to `path`; the temporary file is removed when anything fails.  Returns `path`."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        write(tmp)
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
