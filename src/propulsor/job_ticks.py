"""A forked job's progress and events, passed to the build that started it while the build works on.

A job calls :func:`tick` (done, total); in a worker that writes a line to a pipe, at most ten a second, and the pump's
thread (:func:`_pump`) passes the last line to the job's counter every :data:`PUMP_EVERY_S`; :func:`result` passes the
last one before it returns.  A whole build forked as a job sends its progress events the same way
(:func:`event_pipe`, :func:`forward_events`).  The jobs themselves: :mod:`.parallel`.
"""

from __future__ import annotations

import os
import threading


#: where :func:`tick` goes in this process: a pipe's write end (a forked job started with a counter), the
#: counter itself (a job run inline), or None
_TICK = None
_TICK_LAST = [-float("inf")]


def listening() -> bool:
    """Whether :func:`tick` goes anywhere in this process (a job started with a counter): a job that counts thousands
    of steps may skip the counting where it does not."""
    return _TICK is not None


def tick(done: int, total: int) -> None:
    """A job's progress, `done` of `total`, to the build that started it with a counter (:func:`.parallel.start`); from
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
    from .progress import event_line

    def send(event) -> None:
        try:
            os.write(fd, event_line(event))
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
    """``job.result()``; for a job started with a counter (:func:`.parallel.start`), its ticks passed to the counter
    while it runs (by the pump's thread, also while this thread works on), the last of them before this returns."""
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
