"""Reading a file under check without trusting it (`propulsor check`).

Every file a check reads is opened here: ``lstat`` first (a FIFO, device or socket is never
opened), then ``O_RDONLY | O_NONBLOCK | O_NOFOLLOW``, ``fstat`` of what was opened (regular files
only) and its size against its kind's limit (policy.READ_LIMIT_BYTES) before a byte is read.  A
file that fails raises :class:`Refused` with a one-line reason, which the check reports as that
file's failed check.  The machine refusing (permission, I/O error, out of descriptors) raises
errors.EnvironmentFailure (exit 3).

Libraries that want a file name (OCCT, ezdxf) get ``/proc/self/fd/N`` of the descriptor opened and
checked here, so the file they read is the one that was checked.
"""

from __future__ import annotations

import errno
import os
import stat
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from ..errors import EnvironmentFailure
from ..policy import HASH_LIMIT_BYTES, READ_LIMIT_BYTES
from ..regular_file import CHUNK, NotRegular, hash_fd, open_regular, what_is  # noqa: F401  (what_is: public here too)

#: errors of the machine, not of the file: the check stops with exit 3
_ENVIRONMENT_ERRNOS = {errno.EACCES, errno.EPERM, errno.EIO, errno.EMFILE, errno.ENFILE, errno.ENOMEM}
_CHUNK = CHUNK


class Refused(Exception):
    """A file the check will not read (or could not), with the one-line reason."""


def _os_error(exc: OSError, path, doing: str):
    if exc.errno in _ENVIRONMENT_ERRNOS:
        return EnvironmentFailure(path, exc.errno, doing, exc.strerror or "")
    if exc.errno == errno.ELOOP:
        return Refused("is a symbolic link (not followed)")
    if exc.errno == errno.ENOENT:
        return Refused("no such file")
    return Refused(f"cannot open: [{errno.errorcode.get(exc.errno, 'E?')}] {exc.strerror}")


@dataclass(frozen=True)
class SafeFile:
    """A regular file opened for reading, within its limit."""

    fd: int
    size: int
    path: Path

    @property
    def lib_path(self) -> str:
        """A name of the opened file for libraries that open by name."""
        proc = f"/proc/self/fd/{self.fd}"
        return proc if os.path.exists(proc) else str(self.path)

    def read(self) -> bytes:
        """The whole file (at most its size when opened)."""
        parts, left = [], self.size
        os.lseek(self.fd, 0, os.SEEK_SET)
        while left > 0:
            try:
                block = os.read(self.fd, min(_CHUNK, left))
            except OSError as exc:
                raise _os_error(exc, self.path, "cannot read") from None
            if not block:
                break
            parts.append(block)
            left -= len(block)
        return b"".join(parts)


def limit_of(kind: str) -> int:
    return READ_LIMIT_BYTES[kind]


@contextmanager
def opened(path, kind: str | None = None, limit: int | None = None):
    """A :class:`SafeFile` of `path`: a regular file (not a symbolic link) of at most `limit` bytes
    (default: the limit of `kind`).  Raises Refused or EnvironmentFailure."""
    path = Path(path)
    lim = limit if limit is not None else limit_of(kind)
    try:
        st = os.lstat(path)
    except OSError as exc:
        raise _os_error(exc, path, "cannot read") from None
    if not stat.S_ISREG(st.st_mode):
        raise Refused(f"is {what_is(st.st_mode)}, not a regular file (not opened)")
    if st.st_size > lim:
        raise Refused(_too_large(st.st_size, lim, kind))
    try:
        fd, st = open_regular(path)
    except NotRegular as exc:
        raise Refused(str(exc)) from None
    except OSError as exc:
        raise _os_error(exc, path, "cannot read") from None
    try:
        if st.st_size > lim:
            raise Refused(_too_large(st.st_size, lim, kind))
        yield SafeFile(fd, st.st_size, path)
    finally:
        os.close(fd)


def _too_large(size: int, lim: int, kind: str | None) -> str:
    what = f"a {kind.upper()} file" if kind and kind != "manifest" else "this file" if not kind else "a manifest"
    return f"{size} bytes: larger than the {lim} bytes {what} may have"


def read_bytes(path, kind: str) -> bytes:
    with opened(path, kind) as f:
        return f.read()


def sha256_and_size(path, expected_size: int | None = None) -> tuple[str, int]:
    """(sha256, size) of a regular file of at most policy.HASH_LIMIT_BYTES; a file whose size is not
    `expected_size` is not hashed ('' returned)."""
    with opened(path, limit=HASH_LIMIT_BYTES) as f:
        if expected_size is not None and f.size != expected_size:
            return "", f.size
        try:
            _, digest = hash_fd(f.fd)
        except OSError as exc:
            raise _os_error(exc, path, "cannot read") from None
        return digest, f.size


def walk(root) -> tuple[list[Path], dict[Path, str]]:
    """(regular files under `root`, sorted; {other entry: why it is invalid}).

    Symbolic links are not followed: one leading outside `root` (or nowhere) is invalid, one to a
    file inside is left to that file's own check.  FIFOs, devices and sockets are invalid (never
    opened).  Raises EnvironmentFailure when a folder cannot be listed."""
    root = Path(root)
    real_root = Path(os.path.realpath(root))
    files, bad = [], {}

    def onerror(exc: OSError):
        raise EnvironmentFailure.from_oserror(exc, "cannot list")

    for folder, dirs, names in os.walk(root, onerror=onerror, followlinks=False):
        for name in sorted(dirs + names):
            p = Path(folder) / name
            try:
                st = os.lstat(p)
            except FileNotFoundError:
                continue  # removed while listed
            except OSError as exc:
                raise EnvironmentFailure.from_oserror(exc, "cannot read") from None
            if stat.S_ISDIR(st.st_mode):
                continue
            if stat.S_ISREG(st.st_mode):
                files.append(p)
            elif stat.S_ISLNK(st.st_mode):
                target = Path(os.path.realpath(p))
                if not target.exists():
                    bad[p] = "is a symbolic link to nothing"
                elif target != real_root and real_root not in target.parents:
                    bad[p] = "is a symbolic link leading outside the folder checked"
            else:
                bad[p] = f"is {what_is(st.st_mode)}: an output folder holds regular files only"
    return sorted(files), bad
