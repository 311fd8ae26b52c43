"""The output folder of a build: refuse unsafe targets, one build at a time, atomic replacement.

A build never writes into ``--out`` directly.  It

1. vets the target (:func:`vet_target`): never the current folder, one of its parents, the home
   folder or ``/``; never a symbolic link or a file; a folder that exists may be replaced only when
   it is empty or holds nothing but what a propulsor build wrote (its ``manifest.json`` lists every
   file), unless ``force``;
2. takes the lock of the target (:class:`OutputLock`, ``fcntl.flock`` on a lock file named by the
   hash of the target's real path in ``$TMPDIR/propulsor-locks-<uid>/``, holding the builder's
   process id), so two builds into one folder run in turn;
3. with the lock held, removes what killed builds left beside the target (:func:`clean_stale`):
   their temporary folders ``.<name>.tmp-XXXXXXXX`` and, after a crash between the two renames of
   the fallback replacement, puts the old output back;
4. builds into a fresh temporary folder beside the target (:func:`make_temp`, same file system);
5. puts the finished folder in place in one step (:func:`replace`): Linux ``renameat2`` with
   ``RENAME_EXCHANGE`` swaps old and new, so a reader sees the old complete output or the new
   complete output, never none or a mix; where the call is missing, rename-aside then rename-in,
   recovered by step 3 of the next build.
"""

from __future__ import annotations

import ctypes
import hashlib
import errno
import fcntl
import json
import os
import re
import secrets
import shutil
import tempfile
from pathlib import Path

from .errors import InputError

MANIFEST = "manifest.json"
_TMP_SUFFIX_RE = r"[a-z0-9_]{8}"


def _tmp_prefix(out: Path) -> str:
    return f".{out.name}.tmp-"


def _old_prefix(out: Path) -> str:
    return f".{out.name}.old-"


def lock_dir() -> Path:
    """Where the output locks live: a folder of this user's in the system's temporary folder (nothing
    is written beside the output for a build that ends before it makes one)."""
    d = Path(tempfile.gettempdir()) / f"propulsor-locks-{os.getuid()}"
    d.mkdir(mode=0o700, exist_ok=True)
    return d


def lock_path(out: Path) -> Path:
    """The lock file of output folder `out`: named by the hash of its real absolute path."""
    real = os.path.realpath(out)
    return lock_dir() / f"{hashlib.sha256(os.fsencode(real)).hexdigest()[:32]}.lock"


# -- vetting --------------------------------------------------------------------------------------

def _protected(out: Path) -> str | None:
    """Why `out` may never be replaced (even with force), or None."""
    cwd = Path.cwd().resolve()
    if out == Path(out.anchor):
        return "is the root folder"
    if out == cwd:
        return "is the current folder"
    if out in cwd.parents:
        return "is a parent of the current folder"
    home = Path(os.path.expanduser("~")).resolve()
    if out == home or out in home.parents:
        return "is the home folder" if out == home else "is a parent of the home folder"
    return None


def read_manifest(folder: Path) -> dict | None:
    """The folder's propulsor manifest (a dict with part, files and versions.propulsor), or None."""
    try:
        data = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not (isinstance(data, dict) and isinstance(data.get("part"), str) and isinstance(data.get("files"), list)
            and isinstance(data.get("versions"), dict) and "propulsor" in data["versions"]):
        return None
    return data


def foreign_files(folder: Path) -> list[str] | None:
    """Files in `folder` that no propulsor build wrote; None when the folder has no propulsor manifest.

    An empty folder has none; otherwise every file must be the manifest or listed in it."""
    files = sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if not p.is_dir())
    if not files:
        return []
    manifest = read_manifest(folder)
    if manifest is None:
        return None
    listed = {e.get("path") for e in manifest["files"] if isinstance(e, dict)} | {MANIFEST}
    return [f for f in files if f not in listed]


def vet_target(out: Path, force: bool = False, keep: tuple[Path, ...] = ()) -> Path:
    """The absolute target folder, or InputError('--out', ...) saying why it may not be used.

    `keep`: files the build reads (the part file and the files it names) that must stay outside."""
    out = Path(os.path.abspath(out))
    if out.is_symlink():
        raise InputError("--out", str(out), "is a symbolic link; give the folder it points to")
    real = out.resolve()
    why = _protected(real)
    if why:
        raise InputError("--out", str(out), f"{why}; propulsor never replaces it")
    for f in keep:
        f = Path(f).resolve()
        if real in f.parents:
            raise InputError("--out", str(out), f"holds {f.name}, which this build reads; choose another folder")
    for parent in real.parents:
        if parent.exists() and not parent.is_dir():
            raise InputError("--out", str(out), f"lies below {parent}, which is a file, not a folder")
    if real.exists():
        if not real.is_dir():
            raise InputError("--out", str(out), "exists and is a file, not a folder")
        if not force:
            foreign = foreign_files(real)
            if foreign is None:
                raise InputError("--out", str(out), "exists and was not written by propulsor (no propulsor "
                                 "manifest.json); use --force to replace it")
            if foreign:
                raise InputError("--out", str(out), f"holds {len(foreign)} file(s) propulsor did not write "
                                 f"(first: {foreign[0]}); use --force to replace it")
    return out


def prepare_parent(out: Path) -> None:
    """Create the parent folders of `out`; InputError when that is impossible."""
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("--out", str(out), f"its folder cannot be created: {exc.strerror or exc}") from None


# -- the lock -------------------------------------------------------------------------------------

class Busy(Exception):
    """The output is locked by another build (holder's process id in `pid`)."""

    def __init__(self, pid: str):
        self.pid = pid
        super().__init__(pid)


class OutputLock:
    """Exclusive lock of one output folder: ``fcntl.flock`` on its lock file (:func:`lock_path`).

    The lock file stays (removing it would let two builds lock two different files); it holds the
    process id of the build that has the lock.  The kernel drops the lock when that process dies."""

    def __init__(self, out: Path):
        self.out = out
        self.path = lock_path(out)
        self.fd: int | None = None

    def holder(self) -> str:
        try:
            return self.path.read_text(encoding="ascii", errors="replace").strip() or "unknown"
        except OSError:
            return "unknown"

    def acquire(self, wait: bool = True, on_wait=None) -> None:
        """Take the lock; with wait=False raise :class:`Busy` when held; `on_wait(pid)` before blocking."""
        try:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o600)
        except OSError as exc:
            raise InputError("--out", str(self.out), f"its lock {self.path} cannot be made: {exc.strerror or exc}") from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            if not wait:
                os.close(fd)
                raise Busy(self.holder()) from None
            if on_wait is not None:
                on_wait(self.holder())
            fcntl.flock(fd, fcntl.LOCK_EX)
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode("ascii"), 0)
        self.fd = fd

    def release(self) -> None:
        if self.fd is not None:
            try:
                os.ftruncate(self.fd, 0)
                fcntl.flock(self.fd, fcntl.LOCK_UN)
            finally:
                os.close(self.fd)
                self.fd = None


# -- temporary folders ----------------------------------------------------------------------------

def clean_stale(out: Path) -> list[Path]:
    """Remove what killed builds of `out` left beside it (call with the lock held); returns the paths.

    Temporary folders ``.<name>.tmp-XXXXXXXX`` are removed.  An ``.<name>.old-XXXXXXXX`` folder is
    the old output of an interrupted fallback replacement: it goes back in place when `out` is
    missing, and is removed otherwise."""
    parent = out.parent
    tmp_re = re.compile(re.escape(_tmp_prefix(out)) + _TMP_SUFFIX_RE + "$")
    old_re = re.compile(re.escape(_old_prefix(out)) + _TMP_SUFFIX_RE + "$")
    removed = []
    try:
        entries = sorted(parent.iterdir())
    except OSError:
        return removed
    for p in entries:
        if p.is_symlink() or not p.is_dir():
            continue
        if old_re.match(p.name) and not out.exists():
            os.rename(p, out)
            continue
        if tmp_re.match(p.name) or old_re.match(p.name):
            shutil.rmtree(p, ignore_errors=True)
            removed.append(p)
    return removed


def make_temp(out: Path) -> Path:
    """A fresh folder beside `out` (same file system) with the permissions a new folder gets."""
    try:
        tmp = Path(tempfile.mkdtemp(prefix=_tmp_prefix(out), dir=out.parent))
    except OSError as exc:
        raise InputError("--out", str(out), f"its folder is not writable: {exc.strerror or exc}") from None
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o777 & ~umask)
    return tmp


# -- replacement ----------------------------------------------------------------------------------

_AT_FDCWD = -100
_RENAME_EXCHANGE = 2


def rename_exchange(a: Path, b: Path) -> bool:
    """Swap two paths in one step (Linux renameat2); False where the call is unavailable."""
    try:
        fn = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    if fn(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP):
        return False
    raise OSError(err, os.strerror(err), str(a))


def replace(tmp: Path, out: Path, exchange=rename_exchange) -> None:
    """Put the finished folder `tmp` in the place of `out` in one step, then delete the old output."""
    if not out.exists():
        os.rename(tmp, out)
        return
    if exchange(tmp, out):
        shutil.rmtree(tmp)  # now the old output
        return
    old = out.parent / (_old_prefix(out) + secrets.token_hex(4))
    os.rename(out, old)
    os.rename(tmp, out)
    shutil.rmtree(old)
