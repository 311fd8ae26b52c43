"""A batch's identical solids written and checked once: what one build's solid gave (its files and their checks) is
taken by another build of the same ``propulsor build`` (``make``) whose solid is the same B-rep under the same name.

The four cam part files of ``make`` share their carrier, leg and roller, the two final drives their carrier and sun:
eleven solids whose STEP, STL, 3MF and picture were written and checked again, each the same bytes as the first
(2.1 CPU s by their own times in a build's worker: the final drive's carrier 0.57, its sun 0.43, the cam's carrier
0.20 a build; make from clean, with and without in turn: 61.7 / 61.6 s wall against 63.4 / 62.8, 112.5 / 112.5 user
CPU s against 116.2 / 114.9, bench/bench_make_parts.py).  A solid is known by a digest of its binary
B-rep (:func:`propulsor.solids.kernel.brep_bytes`: every surface, tolerance and location to the bit) with its name,
its expected genus and its volume; its two halves (the STEP and its checks; the mesh's files, checks and arrays,
also by whether the mesh was made in threads) are kept apart, each as soon as its job has written it, so that a
later build's job finds it however the two builds overlap.  A job that finds its half copies the files into its own
build's folder and returns the checks it gave: the same bytes and values the job would have made (the files are
functions of that B-rep, name and genus alone: ``tests/test_solid_cache.py``).

The entries live in a private folder made for the batch (:func:`batch_scope`, removed at its end); a build alone has
none and computes everything.  An entry is made in a temporary folder and renamed into place whole, so a job never
sees half of one; an entry that cannot be written (a full disk) is not made, and its solid is computed again."""

from __future__ import annotations

import hashlib
import os
import pickle
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path

__all__ = ["batch_scope", "solid_key", "fetch", "store", "hits"]

#: what an entry's key starts with (a change of what the halves hold makes older entries unreachable)
FORMAT = b"propulsor solid files v1\n"

#: the batch's folder of entries, or None (a build alone); inherited by the forked builds and their workers
_ROOT: str | None = None
#: halves taken from an entry in this process (a test's and a benchmark's count)
hits = [0]


@contextmanager
def batch_scope():
    """The block's builds (forked within it) share their identical solids: a private temporary folder for the
    entries (``tempfile.mkdtemp``: this user's alone), removed at the end; None where none can be made (each build
    then makes its own solids' files).  Nested: the outer one's folder."""
    global _ROOT
    if _ROOT is not None:
        yield _ROOT
        return
    try:
        root = tempfile.mkdtemp(prefix="propulsor-solids-")
    except OSError:  # no temporary folder to be had (TMPDIR unwritable, full): every build computes its own
        yield None
        return
    _ROOT = root
    try:
        yield root
    finally:
        _ROOT = None
        shutil.rmtree(root, ignore_errors=True)


def solid_key(solid, name: str, expected_genus, volume: float) -> tuple[str, str] | None:
    """(the batch's folder, the digest) that the halves of this solid are kept under; None outside a batch."""
    if _ROOT is None:
        return None
    from ..solids.kernel import brep_bytes

    h = hashlib.sha256(FORMAT)
    h.update(repr((str(name), expected_genus, float(volume).hex())).encode())
    h.update(brep_bytes(solid))
    return _ROOT, h.hexdigest()


def _entry(key: tuple[str, str], half: str) -> Path:
    return Path(key[0]) / f"{key[1]}-{half}"


def fetch(key, half: str, folder: str | Path, files: tuple[str, ...]):
    """What the half ``half`` of the solid ``key`` gave, its files (relative paths) copied into ``folder``; None where
    no build of the batch has made it yet (or ``key`` is None), or where its files cannot be copied (the caller makes
    them, and meets the disk's refusal as any writer does)."""
    if key is None:
        return None
    entry = _entry(key, half)
    try:
        result = (entry / "result.pickle").read_bytes()
    except OSError:
        return None
    from ..write_root import prepare

    try:
        for rel in files:
            shutil.copyfile(entry / rel, prepare(Path(folder) / rel))
    except OSError:  # not copied (a full disk): made here, where a failure is told as the build tells it
        return None
    hits[0] += 1
    return pickle.loads(result)


def store(key, half: str, folder: str | Path, files: tuple[str, ...], result) -> None:
    """Keep the half ``half`` of the solid ``key``: its files (relative paths in ``folder``) and ``result``, for the
    batch's other builds.  Nothing where ``key`` is None, where another build has kept it already, or where it
    cannot be written."""
    if key is None or _entry(key, half).exists():
        return
    if not all(os.path.isfile(p) and not os.path.islink(p) for p in (Path(folder) / rel for rel in files)):
        return  # only the regular files a job wrote are kept (a link would be followed by the taking build's copy)
    tmp = None
    try:
        tmp = Path(tempfile.mkdtemp(prefix=".part-", dir=key[0]))
        for rel in files:
            dst = tmp / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            _link_or_copy(Path(folder) / rel, dst)
        (tmp / "result.pickle").write_bytes(pickle.dumps(result, protocol=pickle.HIGHEST_PROTOCOL))
        os.rename(tmp, _entry(key, half))  # whole or not at all; another build's first: this one dropped
        tmp = None
    except OSError:
        pass
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


def _link_or_copy(src: Path, dst: Path) -> None:
    """``dst`` made the file ``src`` is: a hard link where both lie on one file system (no data copied: most solids
    are kept for no other build), else a copy.  A build's file is complete when its job has made it and is not
    written again (a taking build gets a copy of it, never a link: two builds' outputs share no file)."""
    try:
        os.link(src, dst, follow_symlinks=False)
    except OSError:
        shutil.copyfile(src, dst)
