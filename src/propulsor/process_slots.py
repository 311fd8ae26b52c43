"""How many processes a build may keep busy, and the process slots the builds of one command share.

:func:`jobs_budget`: ``PROPULSOR_JOBS``, or the cores shared among the builds of a ``make -jN``; on a budget of one
process everything runs inline, so that ``make -j2`` on two cores runs two processes.  The builds of several part files
in one command run side by side and share that budget as process slots (:func:`share_slots`): a build's own process
holds one, and each worker it forks takes one more when one is free (else the work runs inline), so the processes of
all the builds never outnumber the budget.  Under make's jobserver (:class:`Jobserver`, a recipe marked ``+`` run by
``make -jN``) every slot beyond the one make started the command for also takes one of make's tokens, so make's jobs
and ours together stay within N.  The workers themselves: :mod:`.parallel`.
"""

from __future__ import annotations

import multiprocessing as mp
import os

#: the process slots shared by the builds of one command (a semaphore inherited through fork), or None
_SLOTS = None
_WORKERS_MAY = None  # an Event: set once the builds' workers may take free slots


def make_jobs(makeflags: str | None = None) -> int | None:
    """The -j of a make running this process (MAKEFLAGS): N for -jN / --jobs=N, 0 for an unlimited -j,
    None when not run by a parallel make."""
    import re

    flags = os.environ.get("MAKEFLAGS", "") if makeflags is None else makeflags
    m = re.search(r"(?:^|\s)(?:-j\s*|--jobs=)(\d*)", flags)
    if m is None:
        return None
    return int(m.group(1)) if m.group(1) else 0


def jobs_budget() -> int:
    """Processes one build may keep busy (itself and its forked workers).

    ``PROPULSOR_JOBS`` when set (>= 1); the slots shared by the builds of one command
    (:func:`share_slots`: the cores, under make's jobserver as many as make has tokens for); under
    ``make -jN`` without the jobserver (a recipe not marked ``+``) the machine's cores shared among
    the N builds make may run at once (an unlimited -j: 1 each); otherwise the cores."""
    cores = os.cpu_count() or 1
    env = os.environ.get("PROPULSOR_JOBS", "").strip()
    if env:
        try:
            return max(1, int(env))
        except ValueError:
            return 1
    if _SLOTS is not None:
        return _SLOTS.n
    n = make_jobs()
    if n is None or n == 1:
        return cores
    return max(1, cores // n) if n > 1 else 1


class Jobserver:
    """A client of GNU make's jobserver (``--jobserver-auth=R,W`` pipes, make 4.3; ``fifo:PATH``, make
    4.4), handed to a recipe marked ``+``: one byte read is one more process this command may run
    beside the one make started it for, written back when that process is done.  Reads never wait
    (the pipe is opened again without blocking, so make's own descriptor is left as it is)."""

    def __init__(self, read_fd: int, write_fd: int):
        self.read_fd, self.write_fd = read_fd, write_fd

    @classmethod
    def from_makeflags(cls, makeflags: str | None = None) -> "Jobserver | None":
        import re
        import stat

        flags = os.environ.get("MAKEFLAGS", "") if makeflags is None else makeflags
        m = re.findall(r"--jobserver-(?:auth|fds)=(\S+)", flags)
        if not m or make_jobs(flags) in (None, 1):
            return None
        auth = m[-1]
        try:
            if auth.startswith("fifo:"):
                fd = os.open(auth[5:], os.O_RDWR | os.O_NONBLOCK | os.O_CLOEXEC)
                return cls(fd, fd)
            r, w = (int(x) for x in auth.split(","))
            if r < 0 or w < 0 or not (stat.S_ISFIFO(os.fstat(r).st_mode) and stat.S_ISFIFO(os.fstat(w).st_mode)):
                return None  # a recipe not marked `+`: make closed them (the numbers may be other files now)
            fd = os.open(f"/proc/self/fd/{r}", os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
            return cls(fd, w)
        except (OSError, ValueError):
            return None

    def take(self) -> bytes | None:
        """A token, or None when make has none free now."""
        try:
            b = os.read(self.read_fd, 1)
        except (BlockingIOError, InterruptedError):
            return None
        return b or None

    def give(self, token: bytes) -> None:
        os.write(self.write_fd, token)


class _Slots:
    """Process slots shared through fork by the builds of one command and their workers: at most `n`
    processes at once; under a make jobserver every slot but the one make gave this command also
    takes a token of make's."""

    FREE = b""  # a slot that needs no token

    def __init__(self, n: int, jobserver: Jobserver | None):
        ctx = mp.get_context("fork")
        self.n = n
        self.cap = ctx.Semaphore(n)
        self.free = ctx.Semaphore(1 if jobserver is not None else n)
        self.jobserver = jobserver

    def take(self, timeout: float | None = None) -> bytes | None:
        """A slot (give it back with :meth:`give`), waiting up to `timeout` seconds for one; None if none."""
        import time

        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            if self.cap.acquire(block=False):
                if self.free.acquire(block=False):
                    return self.FREE
                token = self.jobserver.take() if self.jobserver is not None else None
                if token is not None:
                    return token
                self.cap.release()
            if deadline is not None and time.monotonic() >= deadline:
                return None
            time.sleep(0.02)

    def give(self, slot: bytes) -> None:
        if slot == self.FREE:
            self.free.release()
        else:
            self.jobserver.give(slot)
        self.cap.release()


def share_slots(n: int | None, jobserver: Jobserver | None = None) -> _Slots | None:
    """Make `n` process slots shared by every process forked from now on (None: stop sharing); returns
    them (the parent takes a slot for each build it forks and gives it back when the build has ended).
    Under make's `jobserver`, a slot beyond the first also takes one of make's tokens.  Workers take
    none until :func:`open_slots_to_workers`: while builds wait for a slot a worker would take it from
    them, and a build waiting for its worker's result leaves its own slot idle."""
    global _SLOTS, _WORKERS_MAY
    ctx = mp.get_context("fork")
    _SLOTS = None if n is None else _Slots(n, jobserver)
    _WORKERS_MAY = None if n is None else ctx.Event()
    return _SLOTS


def open_slots_to_workers() -> None:
    """Let the builds' workers take the free shared slots (the last build has been started)."""
    if _WORKERS_MAY is not None:
        _WORKERS_MAY.set()


def slots_shared() -> bool:
    return _SLOTS is not None


def _take_slots(wanted: int) -> list[bytes] | int:
    """Up to `wanted` free shared slots, without waiting (when none are shared: the number `wanted`)."""
    if _SLOTS is None:
        return wanted
    if not _WORKERS_MAY.is_set():
        return []
    got = []
    while len(got) < wanted:
        slot = _SLOTS.take(timeout=0)
        if slot is None:
            break
        got.append(slot)
    return got


def _give_slots(slots: list[bytes]) -> None:
    if _SLOTS is not None:
        for slot in slots:
            _SLOTS.give(slot)


def threads_ok() -> bool:
    """Whether this build may run OCCT's thread pool (BRepMesh in parallel): on a budget above one
    process, unless the budget's slots are shared with other builds."""
    return jobs_budget() > 1 and _SLOTS is None


def worker_cap(wanted: int) -> int:
    """Forked workers a build may start beside itself: none on a budget of one process, else up to
    the budget."""
    b = jobs_budget()
    return 0 if b <= 1 else min(wanted, b)


def can_fork() -> bool:
    return "fork" in mp.get_all_start_methods()
