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

_FLAGS = (os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
          | getattr(os, "O_NOCTTY", 0))
CHUNK = 1 << 20


class NotRegular(ValueError):
    """The name is not a regular file one may read (a symbolic link, a FIFO, a device, a folder, ...)."""


def what_is(mode: int) -> str:
    """'a FIFO', 'a folder', ... for a file mode."""
    for test, name in ((stat.S_ISREG, "a regular file"), (stat.S_ISDIR, "a folder"), (stat.S_ISLNK, "a symbolic link"),
                       (stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return "not a regular file"


def open_regular(path: str | Path) -> tuple[int, os.stat_result]:
    """A descriptor (blocking again, for reading) and the ``fstat`` of the regular file `path`, opened
    without blocking and without following a final symbolic link; NotRegular saying why not (the
    descriptor closed), OSError as the system gives it."""
    try:
        fd = os.open(path, _FLAGS)
    except OSError as exc:
        if exc.errno == errno.ELOOP:  # the name is a symbolic link
            raise NotRegular("is a symbolic link (not followed)") from None
        raise
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode):
        os.close(fd)
        raise NotRegular(f"is {what_is(st.st_mode)}, not a regular file")
    os.set_blocking(fd, True)
    return fd, st


def hash_fd(fd: int, h=None) -> tuple[int, str]:
    """(bytes read, sha256 hex) of an open file from its start; OSError as the system gives it."""
    h = h or hashlib.sha256()
    n = 0
    os.lseek(fd, 0, os.SEEK_SET)
    while chunk := os.read(fd, CHUNK):
        n += len(chunk)
        h.update(chunk)
    return n, h.hexdigest()


def read_regular(path: str | Path, max_bytes: int) -> bytes:
    """The bytes of a regular file of at most `max_bytes`; ValueError saying why not (OSError as it comes)."""
    fd, st = open_regular(path)
    try:
        if st.st_size > max_bytes:
            raise ValueError(f"is {st.st_size} bytes, more than the {max_bytes} allowed")
        chunks, n = [], 0
        while chunk := os.read(fd, CHUNK):
            n += len(chunk)
            if n > max_bytes:
                raise ValueError(f"grew past {max_bytes} bytes while it was read")
            chunks.append(chunk)
        return b"".join(chunks)
    finally:
        os.close(fd)


def sha256_regular(path: str | Path) -> tuple[int, str]:
    """(size in bytes, sha256 hex) of a regular file; ValueError when it is not one."""
    fd, _ = open_regular(path)
    try:
        return hash_fd(fd)
    finally:
        os.close(fd)


def read_head(path: str | Path, n: int) -> bytes:
    """The first `n` bytes of a regular file (any size); ValueError when it is not one."""
    fd, _ = open_regular(path)
    try:
        return os.read(fd, n)
    finally:
        os.close(fd)
