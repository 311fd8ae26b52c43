"""The output folder of a build: refuse unsafe targets, one build at a time, atomic replacement.

A build never writes into ``--out`` directly.  It

1. vets the target (:func:`vet_target`): never the current folder, one of its parents, the home
   folder or ``/``; never a symbolic link or a file; a folder that exists may be replaced only when
   it is empty or holds nothing but what a propulsor build wrote (its ``manifest.json`` lists every
   file), unless ``force``;
2. takes the lock of the target (:class:`OutputLock`, ``fcntl.flock`` on ``.<name>.lock`` beside it,
   opened without following links and used only when it is this user's (or the folder owner's)
   regular file, holding the builder's process id, removed by its holder before it lets go), so two
   builds into one folder run in turn whatever their ``TMPDIR`` or user;
3. with the lock held, removes what killed builds left beside the target (:func:`clean_stale`):
   their temporary folders ``.<name>.tmp-XXXXXXXX`` and, after a crash between the two renames of
   the fallback replacement, puts the old output back;
4. builds into a fresh temporary folder beside the target (:func:`make_temp`, same file system);
5. checks that the finished folder is still the one it made and holds exactly the files its manifest
   lists, with their sizes and sha256 (:func:`verify_built`);
6. puts the finished folder in place in one step (:func:`replace`): Linux ``renameat2`` with
   ``RENAME_EXCHANGE`` swaps old and new, so a reader sees the old complete output or the new
   complete output, never none or a mix; where the call is missing, rename-aside then rename-in,
   recovered by step 3 of the next build.  The old output is compared with what was there when the
   lock was taken (:func:`snapshot`) before and after the swap: anything saved or changed there
   since then is not the previous build's own, so the swap is undone (nothing published, exit 3);
   the old output is then removed file by file, only what the snapshot holds, and a file that
   appears even then is kept (:func:`discard`).
"""

from __future__ import annotations

import ctypes
import errno
import fcntl
import json
import os
import re
import secrets
import shutil
import stat
import tempfile
from pathlib import Path

from .errors import EnvironmentFailure, InputError
from .policy import MANIFEST_MAX_BYTES
from .regular_file import read_regular, sha256_regular

MANIFEST = "manifest.json"
_TMP_SUFFIX_RE = r"[a-z0-9_]{8}"


def _tmp_prefix(out: Path) -> str:
    return f".{out.name}.tmp-"


def _old_prefix(out: Path) -> str:
    return f".{out.name}.old-"


def lock_path(out: Path) -> Path:
    """The lock file of output folder `out`: ``.<name>.lock`` beside it, in the real folder that holds it.

    Beside the output, so that every build of one folder takes the same lock whatever its ``TMPDIR``
    or user, and in a folder only those who may replace the output can write to.  It exists while a
    build holds it (the holder removes it before letting go)."""
    parent = Path(os.path.realpath(Path(os.path.abspath(out)).parent))
    return parent / f".{Path(os.path.abspath(out)).name}.lock"


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
    """The folder's propulsor manifest (a dict with part, files and versions.propulsor), or None (also for
    a manifest that is not a regular file of at most :data:`MANIFEST_MAX_BYTES`: never blocks on a FIFO)."""
    try:
        data = json.loads(read_regular(folder / MANIFEST, MANIFEST_MAX_BYTES))
    except (OSError, ValueError, RecursionError):
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


#: longest absolute path of an output folder (bytes): room below Linux's PATH_MAX (4096) for the files a
#: build writes in it (``tables/…``, ``anim/…``) and the temporary folder's longer name
OUT_PATH_MAX_BYTES = 3840
#: longest last component of an output folder (bytes): the temporary folder ``.<name>.tmp-XXXXXXXX`` and the
#: lock ``.<name>.lock`` must stay within the 255 bytes of a file name
OUT_NAME_MAX_BYTES = 240


def out_arg(text: str | None) -> Path | None:
    """The ``--out`` argument as a Path (None when not given); InputError for an empty one."""
    if text is None:
        return None
    if not text.strip():
        raise InputError("--out", text, "must name a folder (an empty --out would build into output/<name>)")
    return Path(text)


def _mount_inside(real: Path) -> str | None:
    """A mount point at or below `real` (from /proc/self/mountinfo, or a device change below it), or None."""
    prefix = str(real).rstrip("/") + "/"
    try:
        with open("/proc/self/mountinfo", encoding="utf-8", errors="surrogateescape") as fh:
            for line in fh:
                fields = line.split()
                if len(fields) > 4:
                    point = re.sub(r"\\([0-7]{3})", lambda m: chr(int(m.group(1), 8)), fields[4])
                    if point == str(real) or point.startswith(prefix):
                        return point
        return None
    except OSError:
        pass
    dev = os.stat(real).st_dev
    for dirpath, dirnames, _ in os.walk(real):
        for d in dirnames:
            p = os.path.join(dirpath, d)
            if not os.path.islink(p) and os.stat(p).st_dev != dev:
                return p
    return None


def representable(out: Path) -> None:
    """InputError unless `out` is a path every writer of a build can use (UTF-8, within the length limits)."""
    raw = os.fsencode(out)
    try:
        raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError("--out", os.fsdecode(raw).encode("utf-8", "backslashreplace").decode("ascii", "replace"),
                         f"is not UTF-8 (byte 0x{raw[exc.start]:02x} at {exc.start}): the STEP and 3MF writers "
                         "need a UTF-8 path") from None
    if len(raw) > OUT_PATH_MAX_BYTES:
        raise InputError("--out", f"{os.fsdecode(raw[:60])}… ({len(raw)} bytes)", f"is longer than "
                         f"{OUT_PATH_MAX_BYTES} bytes: the files below it would pass the system's path limit")
    if len(os.fsencode(out.name)) > OUT_NAME_MAX_BYTES:
        raise InputError("--out", str(out), f"its last name is {len(os.fsencode(out.name))} bytes, more than "
                         f"{OUT_NAME_MAX_BYTES} (the build's temporary folder adds 14)")


def vet_target(out: Path, force: bool = False, keep: tuple[Path, ...] = ()) -> Path:
    """The absolute target folder, or InputError('--out', ...) saying why it may not be used.

    `keep`: files the build reads (the part file and the files it names) that must stay outside."""
    out = Path(os.path.abspath(out))
    representable(out)
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
        mount = _mount_inside(real)
        if mount is not None:
            raise InputError("--out", str(out), f"holds a mounted file system ({mount}); propulsor never "
                             "replaces a folder that does, even with --force")
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
        raise EnvironmentFailure.from_oserror(exc, "cannot make the folder of --out") from None


# -- the lock -------------------------------------------------------------------------------------

class Busy(Exception):
    """The output is locked by another build (holder's process id in `pid`)."""

    def __init__(self, pid: str):
        self.pid = pid
        super().__init__(pid)


class OutputLock:
    """Exclusive lock of one output folder: ``fcntl.flock`` on its lock file (:func:`lock_path`).

    The file is opened without following a symbolic link and used only when it is a regular file with
    one link, owned by this user or by the owner of the folder holding it (who may replace the output
    anyway); anything else is refused with one line, never truncated or written.  It holds the process
    id of the build that has the lock; the holder removes it before it lets go, and a build that got
    the lock on a file that was meanwhile removed or replaced tries again (so no two builds ever hold
    locks on two different files of one output).  The kernel drops the lock when its holder dies."""

    #: longest process-id text read from a lock file
    _PID_BYTES = 32

    def __init__(self, out: Path):
        self.out = out
        self.path = lock_path(out)
        self.fd: int | None = None

    def holder(self) -> str:
        """The process id written in the lock file (digits only), or 'unknown'."""
        try:
            fd = os.open(self.path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
        except OSError:
            return "unknown"
        try:
            if not stat.S_ISREG(os.fstat(fd).st_mode):
                return "unknown"
            text = os.read(fd, self._PID_BYTES).decode("ascii", "replace").strip()
        except OSError:
            return "unknown"
        finally:
            os.close(fd)
        return text if text.isdigit() and len(text) < 12 else "unknown"

    def _refuse(self, why: str):
        raise InputError("--out", str(self.out), f"its lock file {self.path} {why}; propulsor does not "
                         "use it (remove it if no build is running)")

    def _open(self) -> int:
        try:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC, 0o600)
        except OSError as exc:
            if exc.errno == errno.ELOOP:
                self._refuse("is a symbolic link")
            if exc.errno in (errno.EACCES, errno.EPERM) and os.path.lexists(self.path):
                self._refuse(f"cannot be opened ({exc.strerror}: another user's file?)")
            raise EnvironmentFailure.from_oserror(exc, "cannot make the lock file") from None
        st = os.fstat(fd)
        why = None
        if not stat.S_ISREG(st.st_mode):
            why = "is not a regular file"
        elif st.st_nlink != 1:
            why = f"has {st.st_nlink} links (a hard link to another file?)"
        elif st.st_uid not in (os.geteuid(), os.stat(self.path.parent).st_uid):
            why = f"belongs to another user (uid {st.st_uid})"
        if why:
            os.close(fd)
            self._refuse(why)
        return fd

    def _still_there(self, fd: int) -> bool:
        try:
            here = os.stat(self.path, follow_symlinks=False)
        except FileNotFoundError:
            return False
        mine = os.fstat(fd)
        return (here.st_dev, here.st_ino) == (mine.st_dev, mine.st_ino)

    def acquire(self, wait: bool = True, on_wait=None) -> None:
        """Take the lock; with wait=False raise :class:`Busy` when held; `on_wait(pid)` before blocking."""
        told = False
        while True:
            fd = self._open()
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                if not wait:
                    os.close(fd)
                    raise Busy(self.holder()) from None
                if on_wait is not None and not told:
                    on_wait(self.holder())
                    told = True
                fcntl.flock(fd, fcntl.LOCK_EX)
            if self._still_there(fd):
                break
            os.close(fd)  # the holder removed (or someone replaced) the file while we waited: again
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode("ascii"), 0)
        self.fd = fd

    def release(self) -> None:
        """Remove the lock file (while still holding it) and let go."""
        if self.fd is not None:
            try:
                if self._still_there(self.fd):
                    os.unlink(self.path)
            except OSError:
                pass
            finally:
                fcntl.flock(self.fd, fcntl.LOCK_UN)
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
        if p.is_symlink() or not p.is_dir() or p.lstat().st_uid != os.geteuid():
            continue  # only real folders this user made (another user's are not ours to judge)
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
        raise EnvironmentFailure.from_oserror(exc, "cannot make the build's temporary folder beside --out") from None
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o777 & ~umask)
    return tmp


# -- what is published ---------------------------------------------------------------------------



def verify_built(tmp: Path, ident) -> None:
    """Before a build's folder is published: it is still the folder the build made, and it holds exactly
    the files its manifest lists, each with the listed size and sha256.  EnvironmentFailure otherwise
    (something removed, replaced or added files under the build)."""
    from .write_root import still_there

    still_there(ident)
    doing = "the built folder changed under the build:"
    try:
        data = json.loads(read_regular(tmp / MANIFEST, MANIFEST_MAX_BYTES))
        entries = {e["path"]: e for e in data["files"]}
    except (ValueError, KeyError, TypeError) as exc:
        raise EnvironmentFailure(tmp / MANIFEST, errno.EIO, doing, f"its manifest is not readable ({exc})") from None
    on_disk = set()
    for dirpath, dirnames, filenames in os.walk(tmp):
        for name in filenames:
            on_disk.add(os.path.relpath(os.path.join(dirpath, name), tmp).replace(os.sep, "/"))
    extra = sorted(on_disk - set(entries) - {MANIFEST})
    if extra:
        raise EnvironmentFailure(tmp / extra[0], errno.EEXIST, doing, f"{len(extra)} file(s) no writer of the "
                                 "build made")
    for rel, e in sorted(entries.items()):
        try:
            n, sha = sha256_regular(tmp / rel)
        except FileNotFoundError:
            raise EnvironmentFailure(tmp / rel, errno.ENOENT, doing, "a listed file is missing") from None
        except ValueError as exc:
            raise EnvironmentFailure(tmp / rel, errno.EIO, doing, f"a listed file {exc}") from None
        if n != e.get("bytes") or sha != e.get("sha256"):
            raise EnvironmentFailure(tmp / rel, errno.EIO, doing, f"{n} bytes, sha256 {sha[:12]}… against "
                                     f"{e.get('bytes')} bytes, {str(e.get('sha256'))[:12]}… listed")


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


def snapshot(folder: Path) -> dict[str, tuple]:
    """What `folder` holds now, links not followed: relative path → (kind, inode, size, mtime in ns) of
    every entry (a folder's size and time left out: they change with its entries, which are listed).
    Empty when the folder does not exist."""
    out: dict[str, tuple] = {}
    if not os.path.isdir(folder) or os.path.islink(folder):
        return out
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in dirnames + filenames:
            full = os.path.join(dirpath, name)
            try:
                st = os.lstat(full)
            except FileNotFoundError:
                continue
            rel = os.path.relpath(full, folder).replace(os.sep, "/")
            kind = stat.S_IFMT(st.st_mode)
            out[rel] = (kind, st.st_ino) if kind == stat.S_IFDIR else (kind, st.st_ino, st.st_size, st.st_mtime_ns)
    return out


def not_own(folder: Path, before: dict[str, tuple]) -> list[str]:
    """Entries of `folder` that are not in its snapshot `before` (saved, replaced or changed since)."""
    now = snapshot(folder)
    return sorted(rel for rel, e in now.items() if before.get(rel) != e)


def _refuse_changed(out: Path, changed: list[str]):
    raise EnvironmentFailure(out / changed[0], errno.EEXIST, "the output folder changed during the build:",
                             f"{len(changed)} entr{'y' if len(changed) == 1 else 'ies'} saved or changed there since "
                             "the build began (not the previous build's own); nothing published, the old output "
                             "intact")


def discard(folder: Path, own: dict[str, tuple], out: Path) -> Path | None:
    """Remove from `folder` only the entries of `own` (its snapshot: same path and inode), deepest first,
    then the folder.  Anything else found there is kept: the folder is renamed ``<out>.kept-XXXXXXXX``
    beside `out` and that path returned (None when everything went)."""
    for rel in sorted((r for r, e in own.items() if e[0] != stat.S_IFDIR), key=lambda r: -r.count("/")):
        p = folder / rel
        try:
            st = os.lstat(p)
        except FileNotFoundError:
            continue
        if (stat.S_IFMT(st.st_mode), st.st_ino) == own[rel][:2]:
            os.unlink(p)
    for rel in sorted((r for r, e in own.items() if e[0] == stat.S_IFDIR), key=lambda r: -r.count("/")):
        try:
            os.rmdir(folder / rel)
        except OSError:
            pass
    try:
        os.rmdir(folder)
        return None
    except FileNotFoundError:
        return None
    except OSError:
        kept = out.parent / f"{out.name}.kept-{secrets.token_hex(4)}"
        os.rename(folder, kept)
        return kept


def replace(tmp: Path, out: Path, before: dict[str, tuple] | None = None, exchange=rename_exchange,
            notice=lambda message: None) -> Path | None:
    """Put the finished folder `tmp` in the place of `out` in one step, then remove the old output.

    `before`: the snapshot of `out` taken when the build began (with its lock held).  An entry of `out`
    not in it — a file saved there, or one changed, while the build ran — is not the previous build's
    own: checked before the swap and again on the swapped-out folder, which is swapped back (nothing
    published: EnvironmentFailure, exit 3).  The old output is then removed entry by entry (:func:`discard`);
    returns where anything that appeared even in that instant was kept (else None), also said to `notice`."""
    if before is None:
        before = snapshot(out)
    built = snapshot(tmp)
    changed = not_own(out, before)
    if changed:
        _refuse_changed(out, changed)
    if not out.exists():
        os.rename(tmp, out)
        return None
    if exchange(tmp, out):
        old = tmp
        changed = not_own(old, before)
        if changed:
            exchange(tmp, out)  # back: the old output (with what was saved there) in its place
            kept = discard(tmp, built, out)
            if kept is not None:
                notice(f"{kept}: kept what was saved into {out} while the build was swapped in")
            _refuse_changed(out, changed)
    else:
        old = out.parent / (_old_prefix(out) + secrets.token_hex(4))
        os.rename(out, old)
        changed = not_own(old, before)
        if changed:
            os.rename(old, out)
            _refuse_changed(out, changed)
        os.rename(tmp, out)
    kept = discard(old, before, out)
    if kept is not None:
        notice(f"{kept}: kept what was saved into {out} while its old output was removed")
    return kept
