"""Reading a file that may be anything: only a regular file, never blocking, never more than a limit.

A name in a folder can be a FIFO (``open`` blocks until a writer comes), a device (``/dev/zero`` never
ends), a symbolic link to either, or a sparse file of gigabytes.  These readers open without blocking
and without following a final symbolic link, look at the open file (``fstat``) before reading, and
read no more than they were told.
"""

from __future__ import annotations

import errno
import hashlib
import os
import stat
from pathlib import Path

_FLAGS = os.O_RDONLY | os.O_NONBLOCK | os.O_NOFOLLOW | os.O_CLOEXEC


def _open_regular(path: str | Path) -> tuple[int, os.stat_result]:
    try:
        fd = os.open(path, _FLAGS)
    except OSError as exc:
        if exc.errno == errno.ELOOP:  # the name is a symbolic link
            raise ValueError("is a symbolic link") from None
        raise
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode):
        os.close(fd)
        kind = ("a FIFO" if stat.S_ISFIFO(st.st_mode) else "a device" if stat.S_ISCHR(st.st_mode) or
                stat.S_ISBLK(st.st_mode) else "a socket" if stat.S_ISSOCK(st.st_mode) else
                "a folder" if stat.S_ISDIR(st.st_mode) else "not a regular file")
        raise ValueError(f"is {kind}, not a regular file")
    return fd, st


def read_regular(path: str | Path, max_bytes: int) -> bytes:
    """The bytes of a regular file of at most `max_bytes`; ValueError saying why not (OSError as it comes)."""
    fd, st = _open_regular(path)
    try:
        if st.st_size > max_bytes:
            raise ValueError(f"is {st.st_size} bytes, more than the {max_bytes} allowed")
        chunks, n = [], 0
        while chunk := os.read(fd, 1 << 20):
            n += len(chunk)
            if n > max_bytes:
                raise ValueError(f"grew past {max_bytes} bytes while it was read")
            chunks.append(chunk)
        return b"".join(chunks)
    finally:
        os.close(fd)


def sha256_regular(path: str | Path) -> tuple[int, str]:
    """(size in bytes, sha256 hex) of a regular file; ValueError when it is not one."""
    fd, _ = _open_regular(path)
    h = hashlib.sha256()
    n = 0
    try:
        while chunk := os.read(fd, 1 << 20):
            n += len(chunk)
            h.update(chunk)
        return n, h.hexdigest()
    finally:
        os.close(fd)


def read_head(path: str | Path, n: int) -> bytes:
    """The first `n` bytes of a regular file (any size); ValueError when it is not one."""
    fd, _ = _open_regular(path)
    try:
        return os.read(fd, n)
    finally:
        os.close(fd)
