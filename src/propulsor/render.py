"""The command line's face of the build's events (:mod:`.progress`): what a running command shows on stderr.

* On a terminal (not under ``make -jN``, whose other jobs may draw on it too): each new step as a line ``[  t s] message`` (t: the time since the command started) and under
  them one live line (rich, transient: gone when the command ends) with a spinner, the step, its count and bar
  when it counts ("proof: phase 120/400") and the time left at its pace.
* Elsewhere (a pipe, a log file, make's output): plain lines only, one per step; a step that counts prints
  its first count, then at most one line each :data:`PLAIN_EVERY_S` with the time left, and its last.
* ``-q``: nothing but the notices.

A notice is ``propulsor: message`` either way, quiet or not.  Several builds side by side (``batch``) each send
their events to the command that forked them (:func:`forward_to`), which shows one live line per build
(:class:`Board`).
"""

from __future__ import annotations

import json
import os
import sys
import threading
import time

from .progress import event_line
from .signals import check_signalled

#: the least time between two plain lines of one counting step (not a terminal)
PLAIN_EVERY_S = 5.0
#: the live line's refreshes per second
REFRESH_PER_S = 5

__all__ = ["Renderer", "Board", "eta_text", "forward_to", "PLAIN_EVERY_S"]

#: the live displays running in this process (the fork hooks hold their locks across a fork)
_RUNNING: list = []
#: a pipe to the command that forked this build (batch.side_by_side), or None
_FORWARD_FD: int | None = None
#: the steps are printed by the Board of the command that forked this build: its Renderers print notices only
_SHOWN_THERE = False


def forward_to(fd: int | None, shown_there: bool = False) -> None:
    """Send every event of this process's Renderers also to `fd` (one JSON line each), for the Board of the
    command that forked this build; None stops it.  `shown_there`: the Board prints the steps (not a terminal),
    so the Renderers here print the notices only (the build's output, written out when it ends, would repeat
    them)."""
    global _FORWARD_FD, _SHOWN_THERE
    _FORWARD_FD, _SHOWN_THERE = fd, bool(shown_there and fd is not None)


def eta_text(seconds: float | None) -> str:
    """'about 12 s left', 'about 3 min left' ('' when unknown)."""
    if seconds is None or not seconds >= 0 or seconds == float("inf"):
        return ""
    if seconds < 100:
        return f"about {max(1, round(seconds))} s left"
    return f"about {seconds / 60:.0f} min left" if seconds < 5940 else f"about {seconds / 3600:.1f} h left"


def _eta(done, total, started: float, now: float, done0: int = 0) -> float | None:
    """The time left at the pace since the step's first count (`done0` done at `started`): (now - started) /
    (done - done0) * (total - done); None before more is done, and before a twentieth of the rest unless 30 s of it
    have passed (the first items of a step pay its start: a pace from them overstates the rest, "18 min left" for 2 s
    of work, "19 min" after 4 of 240 phases that took 19 s on a busy machine, with 2 s left)."""
    if done is None or total is None or done <= done0 or total <= 0:
        return None
    if (done - done0) < 0.05 * (total - done0) and now - started < 30.0:
        return None
    return (now - started) / (done - done0) * max(0, total - done)


def _pace(paces: dict, phase: str, done: int, now: float) -> list:
    """The pace of the counting step `phase` at this count, `[t, done0, printed, new, done]`: its first count's time
    and done, its last plain line's time, whether this count starts it (a first count, or a count that went back: the
    same step run again).  Counts of several steps may interleave (a worker's beside the build's own): each has its
    own.  `done`: the last count."""
    pace = paces.get(phase)
    if pace is None or done < pace[4] or (done == 0 and pace[4] > 0):
        pace = paces[phase] = [now, done, -float("inf"), True, done]
    else:
        pace[3], pace[4] = False, done
    return pace


def _with_eta(text: str, done, total, eta) -> str:
    """`text` of a count with the time left at its pace (not when done, unknown, or the text gives its own)."""
    left = eta_text(eta) if done is not None and total is not None and 0 < done < total else ""
    return f"{text}, {left}" if left and " left" not in text else text


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def _live_on(stream) -> bool:
    """Whether to draw live lines on `stream`: a terminal, and not under a parallel make (``make -jN`` may run
    other commands that draw on the same terminal at once: plain lines there)."""
    from .parallel import make_jobs

    return _isatty(stream) and make_jobs() in (None, 1)


class Renderer:
    """The events of one command on `stream` (default: sys.stderr at the time of each event): live on a
    terminal (`live` None: when `stream` is one), plain lines elsewhere, nothing but notices when `quiet`.
    Before each event it checks for a signal whose exception was swallowed: a safe point to stop.
    :meth:`close` ends the live line (the command line calls it when the command ends)."""

    def __init__(self, quiet: bool = False, stream=None, live: bool | None = None):
        self.quiet = quiet
        self.stream = stream
        self.t0 = time.perf_counter()
        self.live = (not quiet) and (_live_on(stream or sys.stderr) if live is None else bool(live))
        self._progress = None  # the rich Progress, started at the first event
        self._task = None
        self._phase: str | None = None  # the step in the live line
        #: each counting step's pace (its first count's time and done) and its last plain line's time: two counts
        #: running at once (a worker's beside the build's own) each keep their own
        self._paces: dict[str, list] = {}
        self._closed = False
        #: held while an event is shown: a worker's tick comes from the pump's thread (parallel.result)
        self._lock = threading.RLock()

    # -- the events
    def __call__(self, event) -> None:
        if threading.current_thread() is threading.main_thread():
            check_signalled()
        with self._lock:
            self._event(event)

    def _event(self, event) -> None:
        if _FORWARD_FD is not None:
            _forward(event)
        if getattr(event, "kind", "progress") == "notice":
            self._line(f"propulsor: {event}")
            return
        if self.quiet or _SHOWN_THERE:
            return
        now = time.perf_counter()
        phase = getattr(event, "phase", None) or str(event)
        done, total = getattr(event, "done", None), getattr(event, "total", None)
        counted = done is not None and total is not None
        pace = _pace(self._paces, phase, done, now) if counted else None
        new = pace[3] if counted else phase != self._phase
        eta = _eta(done, total, pace[0], now, pace[1]) if counted else None
        if self.live and not self._closed:
            if new:
                self._line(self._stamp(now, phase if counted and done == 0 else str(event)))
            self._show(phase, done, total, eta, phase != self._phase)
            self._phase = phase
            return
        self._phase = phase
        if counted and not new and done < total and now - pace[2] < PLAIN_EVERY_S:
            return
        if counted:
            pace[2] = now
        self._line(self._stamp(now, _with_eta(str(event), done, total, eta)))

    def _stamp(self, now: float, text: str) -> str:
        return f"[{now - self.t0:6.1f} s] {text}"

    def _line(self, text: str) -> None:
        """One permanent line: above the live line when there is one."""
        if self._progress is not None:
            self._progress.console.print(text, markup=False, highlight=False, soft_wrap=True)
        else:
            print(text, file=self.stream or sys.stderr, flush=True)

    # -- the live line (a terminal)
    def _show(self, phase: str, done, total, eta, new: bool) -> None:
        if self._progress is None:
            self._start()
        counted = done is not None and total is not None
        fields = dict(count=f"{done}/{total}" if counted else "", eta=eta_text(eta))
        if new:
            self._progress.reset(self._task, total=total if counted else None, completed=done or 0,
                                 description=phase, **fields)
        else:
            self._progress.update(self._task, total=total if counted else None, completed=done or 0,
                                  description=phase, **fields)

    def _start(self) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

        stream = self.stream or sys.stderr
        console = Console(file=stream, force_terminal=True, stderr=stream is sys.stderr, highlight=False)
        self._progress = Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False),
                                  BarColumn(bar_width=24), TextColumn("{task.fields[count]}", markup=False),
                                  TimeElapsedColumn(), TextColumn("{task.fields[eta]}", markup=False),
                                  console=console, transient=True, refresh_per_second=REFRESH_PER_S,
                                  redirect_stdout=stream is sys.stderr, redirect_stderr=stream is sys.stderr)
        self._task = self._progress.add_task("", total=None, count="", eta="")
        _hooks()
        _RUNNING.append(self._progress)
        self._progress.start()

    def close(self) -> None:
        """End the live line (the lines printed stay); later events print plain lines."""
        self._closed = True
        progress, self._progress = self._progress, None
        if progress is not None:
            if progress in _RUNNING:
                _RUNNING.remove(progress)
            progress.stop()

    def __enter__(self) -> "Renderer":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _forward(event) -> None:
    """One JSON line of `event` to the forking command's pipe (a full pipe or a gone reader: dropped)."""
    global _FORWARD_FD
    try:
        os.write(_FORWARD_FD, event_line(event))
    except BlockingIOError:
        pass
    except OSError:
        _FORWARD_FD = None


# -- a fork while the live line's thread draws would copy its held locks: the hooks hold them across it
_HOOKED = False


def _hooks() -> None:
    global _HOOKED
    if not _HOOKED and hasattr(os, "register_at_fork"):
        os.register_at_fork(before=_before_fork, after_in_parent=_after_in_parent, after_in_child=_after_in_child)
        _HOOKED = True


def _before_fork() -> None:
    from .parallel import callback_lock

    callback_lock().acquire()  # first: the workers' ticks are drawn holding it, then a live line's lock
    for p in _RUNNING:
        p.live._lock.acquire()


def _after_in_parent() -> None:
    from .parallel import callback_lock

    for p in reversed(_RUNNING):
        p.live._lock.release()
    callback_lock().release()


def _after_in_child() -> None:
    """The child (a worker, a forked build) draws no live line: the locks let go, stdout and stderr its own."""
    for p in reversed(_RUNNING):
        p.live._lock.release()
    _RUNNING.clear()
    for name in ("stdout", "stderr"):
        proxied = getattr(getattr(sys, name), "rich_proxied_file", None)
        if proxied is not None:
            setattr(sys, name, proxied)


class Board:
    """The builds running side by side (``batch.side_by_side``), as their events come from each child's pipe:
    on a terminal one live line per build (its part file, step, count and time left), elsewhere one plain
    line per step of each (a counting step as :class:`Renderer` prints it), nothing when `quiet`."""

    def __init__(self, quiet: bool = False, stream=None, live: bool | None = None, t0: float | None = None):
        self.quiet = quiet
        self.stream = stream
        self.t0 = time.perf_counter() if t0 is None else t0  # the command's start (its Renderer's t0)
        self.live = (not quiet) and (_live_on(stream or sys.stderr) if live is None else bool(live))
        self._progress = None
        self._rows: dict[object, dict] = {}

    def start(self, key, name: str) -> None:
        """Build `key` (its part file `name`) started."""
        row = self._rows[key] = dict(name=name, phase=None, paces={}, task=None, buf=b"")
        if self.quiet:
            return
        if self.live:
            if self._progress is None:
                self._start()
            row["task"] = self._progress.add_task(name, total=None, count="", eta="")
        self.line(f"propulsor: building {name}")

    def feed(self, key, data: bytes) -> None:
        """Bytes read from build `key`'s pipe: its events, one JSON line each."""
        row = self._rows.get(key)
        if row is None:
            return
        row["buf"] += data
        *lines, row["buf"] = row["buf"].split(b"\n")
        for raw in lines:
            try:
                ev = json.loads(raw)
            except ValueError:
                continue
            if ev.get("kind") == "notice" or self.quiet:
                continue  # the build's own stderr (written out when it ends) holds its notices
            self._event(row, ev)

    def _event(self, row: dict, ev: dict) -> None:
        now = time.perf_counter()
        phase, done, total = ev.get("phase") or ev.get("text", ""), ev.get("done"), ev.get("total")
        counted = done is not None and total is not None
        pace = _pace(row["paces"], phase, done, now) if counted else None
        new = pace[3] if counted else phase != row["phase"]
        row["phase"] = phase
        eta = _eta(done, total, pace[0], now, pace[1]) if counted else None
        if self.live:
            self._progress.update(row["task"], description=f"{row['name']}: {phase}", total=total if counted else None,
                                  completed=done or 0, count=f"{done}/{total}" if counted else "",
                                  eta=eta_text(eta))
            return
        if counted and not new and done < total and now - pace[2] < PLAIN_EVERY_S:
            return
        if counted:
            pace[2] = now
        text = _with_eta(ev.get("text", phase), done, total, eta)
        if not text.startswith(f"{row['name']}: "):
            text = f"{row['name']}: {text}"
        self.line(f"[{now - self.t0:6.1f} s] {text}")

    def end(self, key) -> None:
        """Build `key` ended: its live line goes."""
        row = self._rows.pop(key, None)
        if row is not None and row["task"] is not None and self._progress is not None:
            self._progress.remove_task(row["task"])

    def line(self, text: str) -> None:
        if self._progress is not None:
            self._progress.console.print(text, markup=False, highlight=False, soft_wrap=True)
        else:
            print(text, file=self.stream or sys.stderr, flush=True)

    def write(self, stream, data: bytes) -> None:
        """A finished build's whole output (bytes) onto `stream` (sys.stdout or sys.stderr): above the live lines
        when `stream` is a terminal and they are drawn, else as it is."""
        if not data:
            return
        if self._progress is not None and _isatty(stream):
            self._progress.console.print(data.decode("utf-8", "replace"), markup=False, highlight=False, end="",
                                         soft_wrap=True)
            return
        stream.flush()
        os.write(stream.fileno(), data)

    def _start(self) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

        stream = self.stream or sys.stderr
        console = Console(file=stream, force_terminal=True, highlight=False)
        self._progress = Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False),
                                  BarColumn(bar_width=16), TextColumn("{task.fields[count]}", markup=False),
                                  TimeElapsedColumn(), TextColumn("{task.fields[eta]}", markup=False),
                                  console=console, transient=True, refresh_per_second=REFRESH_PER_S,
                                  redirect_stdout=False, redirect_stderr=False)
        _hooks()
        _RUNNING.append(self._progress)
        self._progress.start()

    def close(self) -> None:
        progress, self._progress = self._progress, None
        if progress is not None:
            if progress in _RUNNING:
                _RUNNING.remove(progress)
            progress.stop()
