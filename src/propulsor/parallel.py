"""Work beside the main process on the machine's second core (forked processes).

A part runs its long proof (a motion sweep) or the files and checks of its solids in forked
workers while it goes on; where `fork` is missing everything runs inline.  Forked children must
not use OCCT's thread pool (it does not survive a fork): they mesh with parallel=False.

How many: :func:`jobs_budget` (``PROPULSOR_JOBS``, or the cores shared among the builds of a
``make -jN``); on a budget of one process everything runs inline, so that ``make -j2`` on two cores
runs two processes.  The builds of several part files in one command run side by side and share
that budget as process slots (:func:`share_slots`): a build's own process holds one, and each
worker it forks takes one more when one is free (else the work runs inline), so the processes of
all the builds never outnumber the budget.  Under make's jobserver (:class:`Jobserver`, a recipe
marked ``+`` run by ``make -jN``) every slot beyond the one make started the command for also takes
one of make's tokens, so make's jobs and ours together stay within N.

Workers belong to the build that started them: a build runs inside :class:`Workers` (a context manager;
the current one is a context variable, so each thread, and each task of an event loop, has its own), every pool
forked while it is current is its own, and leaving it kills what is left of them — never another build's, so
builds in several threads of one process (a notebook, a Dask worker) neither see nor stop each other's
processes.  Workers never outlive the build either: each asks the kernel for SIGKILL when its parent dies
(``PR_SET_PDEATHSIG``, Linux) and leaves SIGINT to the parent; the command line, ending on a signal, stops every
worker of the process (:func:`kill_workers`).  The output locks of every build of the process
(:meth:`Workers.close_in_workers`) are closed in every worker forked, so a worker never holds a build's lock.
"""

from __future__ import annotations

import contextvars
import ctypes
import multiprocessing as mp
import os
import signal
import threading
import weakref
from concurrent.futures import ProcessPoolExecutor

_PR_SET_PDEATHSIG = 1
#: every pool of the process (for :func:`kill_workers`, the command line's end)
_POOLS: "weakref.WeakSet[ProcessPoolExecutor]" = weakref.WeakSet()
#: file descriptors closed in every worker forked: the output locks of the builds running in this process, each with
#: the (device, inode) of the file it was opened on, so that a worker closes it only while the number still names that
#: file (a lock closed before its build's block ends leaves a number that a pool's own pipe may take next: the worker
#: would close its call queue, "Bad file descriptor")
_CLOSE_IN_WORKERS: dict[int, tuple[int, int]] = {}
_CLOSE_LOCK = threading.Lock()
#: the Workers of the build running in this thread (context), or None outside a build
_CURRENT: "contextvars.ContextVar[Workers | None]" = contextvars.ContextVar("propulsor_workers", default=None)
#: the process slots shared by the builds of one command (a semaphore inherited through fork), or None
_SLOTS = None
_WORKERS_MAY = None  # an Event: set once the builds' workers may take free slots


class Done:
    """A finished computation with the interface of a Future."""

    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value


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


class Workers:
    """The worker processes of one build (a context manager): every pool forked while it is the current one
    belongs to it, and leaving the block kills what is left of them (with SIGINT / SIGTERM held off meanwhile)
    and forgets the descriptors it named with :meth:`close_in_workers`.  Nested blocks (a design computed
    inside a build) own their own pools; the outer one resumes after."""

    def __init__(self):
        self._pools: list[ProcessPoolExecutor] = []
        self._fds: list[int] = []
        self._lock = threading.Lock()
        self._token = None

    def open(self) -> "Workers":
        """Make this the current build's workers (in this thread / context); returns itself."""
        self._token = _CURRENT.set(self)
        return self

    def close(self) -> None:
        """Kill what is left of this build's workers, forget its descriptors, and stop being the current one
        (the caller holds off SIGINT / SIGTERM meanwhile: :meth:`__exit__` does)."""
        try:
            self.kill()
        finally:
            if self._token is not None:
                _CURRENT.reset(self._token)
                self._token = None
            with _CLOSE_LOCK:
                for fd in self._fds:
                    _CLOSE_IN_WORKERS.pop(fd, None)
            self._fds.clear()

    def __enter__(self) -> "Workers":
        return self.open()

    def __exit__(self, *exc) -> None:
        from .signals import held_signals

        with held_signals():
            self.close()

    def adopt(self, pool: ProcessPoolExecutor) -> None:
        with self._lock:
            self._pools.append(pool)

    def close_in_workers(self, fd: int) -> None:
        """Close file descriptor `fd` (this build's output lock) in every worker forked from now on, this build's
        and any other build's of the process, for as long as this block runs."""
        st = os.fstat(fd)
        with _CLOSE_LOCK:
            _CLOSE_IN_WORKERS[fd] = (st.st_dev, st.st_ino)
        self._fds.append(fd)

    def kill(self) -> None:
        """Kill this build's workers that are still running and drop its pools (their slots given back)."""
        with self._lock:
            pools, self._pools = self._pools, []
        _kill_pools(pools)


def current_workers() -> "Workers | None":
    """The Workers of the build running in this thread (context), or None."""
    return _CURRENT.get()


def _close_fds() -> tuple[tuple[int, int, int], ...]:
    """(fd, device, inode) of every descriptor a worker forked now closes (:data:`_CLOSE_IN_WORKERS`)."""
    with _CLOSE_LOCK:
        return tuple(sorted((fd, *key) for fd, key in _CLOSE_IN_WORKERS.items()))


def kill_pool(pool: ProcessPoolExecutor) -> None:
    """Kill the processes of `pool` at once (an interrupted build does not wait for its workers' jobs)."""
    _kill_pools([pool])


def _kill_pools(pools) -> None:
    """Kill the processes of `pools` at once, wait for them, drop the pools and give back their slots."""
    procs = [proc for pool in pools for proc in getattr(pool, "_procs", {}).values()]
    for proc in procs:
        try:
            proc.kill()
        except (OSError, ValueError):  # gone already, or closed
            pass
    for proc in procs:
        try:
            proc.join(timeout=5)
        except (AssertionError, ValueError):  # not ours to join (a fork of a fork) or closed
            pass
    for pool in pools:
        try:
            pool.shutdown(wait=False, cancel_futures=True)
        except Exception:  # noqa: BLE001 - a pool whose workers were killed is broken; that is the point
            pass
        if isinstance(pool, _SlotPool):
            pool.give_back()
        _POOLS.discard(pool)


def _worker_init(parent_pid: int, close_fds: tuple[tuple[int, int, int], ...]) -> None:
    """In a fresh worker: die with the parent, leave SIGINT to it, drop the parent's locks."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (AttributeError, OSError):  # not Linux: the pool's own watch of the parent remains
        pass
    if os.getppid() != parent_pid:  # the parent died before the request took effect
        os._exit(1)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    global _TICK
    _TICK = None  # a job's ticks are its own process's (:func:`_ticking` sets them), not a forking job's
    for fd, dev, ino in close_fds:
        try:
            st = os.fstat(fd)
            if (st.st_dev, st.st_ino) == (dev, ino):  # still the lock file, not a number taken since (a pipe)
                os.close(fd)
        except OSError:
            pass


class _SlotPool(ProcessPoolExecutor):
    """A pool of forked workers holding shared process slots until it is shut down (waiting) or, for a
    single job (:func:`start`), until that job is done."""

    def __init__(self, slots: list[bytes], **kw):
        super().__init__(**kw)
        self._slots = slots
        self._slot_lock = threading.Lock()
        self._procs: dict = {}  # pid -> Process: kept past shutdown(wait=False), which forgets them

    def submit(self, fn, /, *args, **kwargs):
        fut = super().submit(fn, *args, **kwargs)
        self._procs.update(self._processes or {})  # the fork context starts every worker at the first submit
        return fut

    def give_back(self) -> None:
        with self._slot_lock:
            slots, self._slots = self._slots, []
        _give_slots(slots)

    def shutdown(self, wait: bool = True, *, cancel_futures: bool = False) -> None:
        super().shutdown(wait=wait, cancel_futures=cancel_futures)
        if wait:
            self.give_back()


def fork_pool(workers: int) -> ProcessPoolExecutor | None:
    """A pool of at most `workers` forked workers (:func:`worker_cap`, and no more than the shared slots
    free now), or None where fork is not available or the build's budget allows no worker (the work
    then runs inline)."""
    workers = worker_cap(workers)
    if not can_fork() or workers < 1:
        return None
    slots = _take_slots(workers)
    workers = len(slots) if isinstance(slots, list) else slots
    if workers < 1:
        return None
    pool = _SlotPool(slots if isinstance(slots, list) else [], max_workers=workers, mp_context=mp.get_context("fork"),
                     initializer=_worker_init, initargs=(os.getpid(), _close_fds()))
    _POOLS.add(pool)
    owner = _CURRENT.get()
    if owner is not None:  # the running build's: killed when it ends, whatever its thread
        owner.adopt(pool)
    return pool


def as_if_sent(obj):
    """`obj` after the pickle round trip a forked worker's arguments and results go through.  Work run
    inline gets the same copies, so that its files do not depend on where it ran (OCCT shapes are
    pickled through their B-rep text: a -0.0 in the original comes back as 0.0)."""
    import pickle

    return pickle.loads(pickle.dumps(obj))


def inline(fn, *args) -> Done:
    """fn(*args) in this process, its arguments and result passed as a worker's would be."""
    return Done(as_if_sent(fn(*as_if_sent(args))))


def start(fn, *args, counter=None):
    """Run fn(*args) in one forked process; returns a Future (a :class:`Done` when run inline).  `counter`:
    ``counter(done, total)`` told how far the job has come where it calls :func:`tick` — at once when run
    inline, while :func:`result` waits for it when forked (through a pipe)."""
    global _TICK
    pool = fork_pool(1)
    if pool is None:
        before, _TICK = _TICK, counter  # a job without a counter ticks to none (not to a job it runs within)
        try:
            return inline(fn, *args)
        finally:
            _TICK = before
    if counter is None:
        fut = pool.submit(fn, *args)
    else:
        r, w = os.pipe()
        os.set_blocking(r, False)
        os.set_blocking(w, False)  # a full pipe drops the worker's ticks, never holds its work
        try:
            fut = pool.submit(_ticking, w, fn, *args)  # the fork context forks the worker here: it has `w`
        finally:
            os.close(w)
        fut.propulsor_ticks = _Ticks(r, counter, fut)
        _pump_add(fut.propulsor_ticks)
    fut.add_done_callback(lambda _f: pool.give_back())
    pool.shutdown(wait=False)
    return fut


#: where :func:`tick` goes in this process: a pipe's write end (a forked job started with a counter), the
#: counter itself (a job run inline), or None
_TICK = None
_TICK_LAST = [-float("inf")]


def tick(done: int, total: int) -> None:
    """A job's progress, `done` of `total`, to the build that started it with a counter (:func:`start`); from
    a worker at most ten a second (and the last).  Nothing otherwise."""
    t = _TICK
    if t is None:
        return
    if callable(t):
        t(done, total)
        return
    import time

    now = time.monotonic()
    if done < total and now - _TICK_LAST[0] < 0.1:
        return
    _TICK_LAST[0] = now
    try:
        os.write(t, f"{int(done)} {int(total)}\n".encode())
    except OSError:  # full (the build is not reading yet) or gone: dropped
        pass


def _ticking(fd: int, fn, *args):
    """In a worker: fn(*args) with :func:`tick` writing to `fd`."""
    global _TICK
    _TICK = fd
    try:
        return fn(*args)
    finally:
        _TICK = None
        os.close(fd)


class _Ticks:
    """The read end of a forked job's progress pipe, the counter its ticks go to and the job."""

    def __init__(self, fd: int, counter, job=None):
        self.fd, self.counter, self.job, self.buf = fd, counter, job, b""

    def _lines(self) -> list[bytes]:
        """The whole lines the pipe holds now (a line cut short waits in the buffer)."""
        out: list[bytes] = []
        while self.fd >= 0:
            try:
                data = os.read(self.fd, 65536)
            except (BlockingIOError, InterruptedError):
                break
            if not data:
                break
            self.buf += data
            *lines, self.buf = self.buf.split(b"\n")
            out += lines
        return out

    def drain(self) -> None:
        lines = [ln for ln in self._lines() if ln]
        if lines:
            done, total = (int(x) for x in lines[-1].split())
            self.counter(done, total)

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1

    def __del__(self):
        self.close()


class _Events(_Ticks):
    """The read end of a forked job's event pipe (:func:`forward_events`): every event passed to `counter` (the
    build's progress), in order."""

    def drain(self) -> None:
        import json

        from .progress import Event

        for raw in self._lines():
            try:
                ev = json.loads(raw)
            except ValueError:
                continue
            self.counter(Event(ev["text"], ev["kind"], ev["phase"], ev["done"], ev["total"]))


def event_pipe(progress, job_of):
    """``job_of(fd)`` — a call that forks a job holding `fd`, the write end of a pipe — with the job's events
    (written by :func:`forward_events` in the job) passed to `progress` while it runs (the pump's thread) and to
    the last before :func:`result` returns.  Returns the job."""
    r, w = os.pipe()
    os.set_blocking(r, False)
    os.set_blocking(w, False)
    try:
        job = job_of(w)
    finally:
        os.close(w)
    job.propulsor_ticks = _Events(r, progress, job)
    _pump_add(job.propulsor_ticks)
    return job


def forward_events(fd: int):
    """In a forked job: a progress callback writing each event to `fd` (:func:`event_pipe`) as one JSON line; a full
    pipe drops the event (never holds the work)."""
    import json

    def send(event) -> None:
        rec = dict(text=str(event), kind=getattr(event, "kind", "progress"),
                   phase=getattr(event, "phase", None) or str(event), done=getattr(event, "done", None),
                   total=getattr(event, "total", None))
        try:
            os.write(fd, (json.dumps(rec) + "\n").encode())
        except OSError:
            pass

    return send


# -- the pump: the ticks of the forked jobs passed to their counters while the build's own thread works on (before,
# a job's count was read only when the build waited for its result: silent seconds, then "7201/7201" at once)
#: the counters are called holding this lock (the pump's thread or a thread waiting in :func:`result`); a fork holds it
#: too (:func:`_before_fork`), so that no child is forked while a counter draws (a print's lock copied held)
_CALLBACK_LOCK = threading.RLock()
#: the ticks of the forked jobs still running, each drained by the pump every :data:`PUMP_EVERY_S`
_LIVE_TICKS: list[_Ticks] = []
_PUMP: list = [None]  # the pump's thread while there are live ticks
#: how often the pump reads the workers' ticks (the workers write at most ten a second)
PUMP_EVERY_S = 0.1


def _pump_add(ticks: _Ticks) -> None:
    with _CALLBACK_LOCK:
        _LIVE_TICKS.append(ticks)
        if _PUMP[0] is None:
            _PUMP[0] = threading.Thread(target=_pump, name="propulsor-ticks", daemon=True)
            _PUMP[0].start()


def _pump() -> None:
    """Drain every live job's ticks into its counter until none is left (then the thread ends); a job done is drained
    once more and dropped.  A counter's error (an interruption's, raised at the display's safe point) is the
    build's thread's to meet: here the job is only dropped."""
    import time

    from .signals import SIGNALLED

    while True:
        time.sleep(PUMP_EVERY_S)
        with _CALLBACK_LOCK:
            if SIGNALLED:  # interrupted: the build is ending, its workers' counts are not shown any more
                for t in _LIVE_TICKS:
                    t.close()
                _LIVE_TICKS.clear()
            for t in list(_LIVE_TICKS):
                done = t.job is None or t.job.done()
                try:
                    t.drain()
                except BaseException:  # noqa: BLE001 - the counter's own; the build's thread meets its cause
                    done = True
                if done:
                    _LIVE_TICKS.remove(t)
                    t.close()
            if not _LIVE_TICKS:
                _PUMP[0] = None
                return


def _before_fork() -> None:
    _CALLBACK_LOCK.acquire()


def _after_fork_in_parent() -> None:
    _CALLBACK_LOCK.release()


def _after_fork_in_child() -> None:
    """A child has no pump and none of its parent's jobs."""
    global _CALLBACK_LOCK
    _CALLBACK_LOCK = threading.RLock()
    _LIVE_TICKS.clear()
    _PUMP[0] = None


if hasattr(os, "register_at_fork"):
    os.register_at_fork(before=_before_fork, after_in_parent=_after_fork_in_parent,
                        after_in_child=_after_fork_in_child)


def callback_lock():
    """The lock held while a worker's tick is passed to its counter (render's fork hooks take it first)."""
    return _CALLBACK_LOCK


def result(job):
    """``job.result()``; for a job started with a counter (:func:`start`), its ticks passed to the counter while it
    runs (by the pump's thread, also while this thread works on), the last of them before this returns."""
    ticks = getattr(job, "propulsor_ticks", None)
    if ticks is None:
        return job.result()
    import concurrent.futures as cf

    while not job.done():  # in steps: a signal's handler runs between them
        cf.wait([job], timeout=0.1)
    with _CALLBACK_LOCK:
        if ticks in _LIVE_TICKS:
            _LIVE_TICKS.remove(ticks)
        try:
            ticks.drain()
        finally:
            ticks.close()
    return job.result()


def kill_workers() -> None:
    """Kill every worker process of this process at once and drop every pool: the command line's end after a
    signal (the process is going; a build's own workers go with its :class:`Workers` block)."""
    _kill_pools(list(_POOLS))
    children = mp.active_children()
    for proc in children:
        proc.kill()
    for proc in children:
        proc.join(timeout=5)
