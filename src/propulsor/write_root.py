"""The folder a build writes into, and the one way its writers make the folders of their files.

A build writes into a temporary folder (``output_folder.make_temp``) and registers it here
(:func:`writing_into`).  Every writer makes the folder of a file with :func:`prepare`: below the
registered folder it creates the missing sub-folders one level at a time and never the registered
folder itself or anything above it, and it first makes sure the registered folder is still the one the
build made (same device and inode).  So a temporary folder removed or replaced under a running build is
never silently made again by the next writer: the write fails with ``ENOENT`` / ``ESTALE`` and the
build ends with exit 3 instead of publishing what was left.  Forked workers inherit the registration.
Outside a build (a writer called from a script) :func:`prepare` makes the parents as ``mkdir -p``.
"""

from __future__ import annotations

import errno
import os
from contextlib import contextmanager
from pathlib import Path

#: (absolute path, st_dev, st_ino) of the folder the running build writes into, or None
_ROOT: tuple[str, int, int] | None = None


def identity(folder: str | Path) -> tuple[str, int, int]:
    """(absolute path, device, inode) of an existing folder, not following a final symbolic link."""
    folder = os.path.abspath(folder)
    st = os.stat(folder, follow_symlinks=False)
    return folder, st.st_dev, st.st_ino


def still_there(ident: tuple[str, int, int]) -> None:
    """Raise FileNotFoundError / OSError(ESTALE) unless the folder `ident` names is still the same folder."""
    folder, dev, ino = ident
    try:
        st = os.stat(folder, follow_symlinks=False)
    except FileNotFoundError:
        raise FileNotFoundError(errno.ENOENT, "the build's folder was removed while it was being written",
                                folder) from None
    if (st.st_dev, st.st_ino) != (dev, ino):
        raise OSError(errno.ESTALE, "the build's folder was replaced by another while it was being written", folder)


@contextmanager
def writing_into(folder: str | Path):
    """Register `folder` (existing) as the one the build writes into, for the block.  The folder is held
    open meanwhile, so that its inode cannot be given to another folder made in its place."""
    global _ROOT
    saved = _ROOT
    fd = os.open(folder, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    st = os.fstat(fd)
    _ROOT = (os.path.abspath(folder), st.st_dev, st.st_ino)
    try:
        yield _ROOT
    finally:
        _ROOT = saved
        os.close(fd)


def prepare(path: str | Path) -> Path:
    """Make the folder of file `path` exist (see the module docstring) and return `path` as a Path."""
    path = Path(path)
    parent = os.path.abspath(path.parent)
    if _ROOT is None:
        os.makedirs(parent, exist_ok=True)
        return path
    root = _ROOT[0]
    rel = os.path.relpath(parent, root)
    if rel == os.pardir or rel.startswith(os.pardir + os.sep) or os.path.isabs(rel):
        os.makedirs(parent, exist_ok=True)  # not the build's folder: a writer used for something else
        return path
    still_there(_ROOT)
    here = root
    for part in ([] if rel == os.curdir else rel.split(os.sep)):
        here = os.path.join(here, part)
        try:
            os.mkdir(here)
        except FileExistsError:
            if not os.path.isdir(here):
                raise NotADirectoryError(errno.ENOTDIR, "not a folder", here) from None
    return path
