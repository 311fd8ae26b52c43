"""Progress as events: what a build reports while it runs, handed to a callback of its caller's.

The build service prints nothing (``building.py``); it calls ``progress(event)`` with an :class:`Event`.  An
event is its message (a ``str``: a callback that takes text works as it is) with a ``kind``:

* ``PROGRESS`` — a step of the work ("cam: STEP, STL, 3MF and their checks", "gallery: output/index.html");
  the command line shows it with the time since the start unless ``-q``;
* ``NOTICE`` — something the user must see even when quiet: a wait for another build's lock, a check that
  failed, a file kept aside, a page that could not be written.

A step that counts (``say.count(phase, done, total, unit)``: "proof: phase 120/400") is a ``PROGRESS`` event
whose ``phase`` is the step's own message and whose ``done`` / ``total`` are set (``None`` on a plain step):
the command line draws a bar with an estimate of the time left.  The counts of one Reporter are throttled to
:data:`COUNT_EVERY_S` (the first and the last of a phase always go), so a loop may report every turn.

The command line renders them (``render.Renderer``: a line per step on stderr, a live line on a terminal); the
Python API passes them to the caller's callback, or drops them.
"""

from __future__ import annotations

import time
from typing import Callable

PROGRESS, NOTICE = "progress", "notice"

#: the least time between two count events of one Reporter (the first and the last of a phase always go)
COUNT_EVERY_S = 0.1

__all__ = ["Event", "Reporter", "PROGRESS", "NOTICE", "COUNT_EVERY_S", "counter", "count_to", "count_shared",
           "event_line"]


class Event(str):
    """One thing a build reports: the message (the event is that text) and its kind (PROGRESS or NOTICE); a
    count also has its ``phase`` (the message without the count), ``done`` and ``total``."""

    kind: str
    phase: str
    done: int | None
    total: int | None

    def __new__(cls, message: str, kind: str = PROGRESS, phase: str | None = None, done: int | None = None,
                total: int | None = None) -> "Event":
        self = super().__new__(cls, message)
        self.kind = kind
        self.phase = str(message) if phase is None else phase
        self.done, self.total = done, total
        return self

    @property
    def counted(self) -> bool:
        """Whether the event is a count (``done`` of ``total``)."""
        return self.done is not None and self.total is not None

    def __reduce__(self):
        return (type(self), (str(self), self.kind, self.phase, self.done, self.total))


class Reporter:
    """The build's side of the callback: ``say(message)`` reports a step, ``say.notice(message)`` a notice;
    with no callback both do nothing."""

    def __init__(self, callback: Callable[[Event], object] | None = None):
        self.callback = callback
        #: each counting step's last count's time (several steps may count at once: a worker's, read by the pump's
        #: thread, beside the build's own)
        self._last: dict[str, float] = {}

    @classmethod
    def of(cls, progress) -> "Reporter":
        """`progress` as a Reporter (a Reporter as it is; a callback or None wrapped)."""
        return progress if isinstance(progress, Reporter) else cls(progress)

    def __call__(self, message: str) -> None:
        if self.callback is not None:
            self.callback(Event(message, PROGRESS))

    def count(self, phase: str, done: int, total: int, unit: str = "") -> None:
        """`done` of `total` (`unit`s: "phase", "sample") of the step `phase`: the event "phase: unit done/total",
        at most one each :data:`COUNT_EVERY_S` (the first of a phase and the last, done == total, always)."""
        if self.callback is None:
            return
        now = time.monotonic()
        last = self._last.get(phase)
        first = last is None
        if not (first or done >= total or now - last >= COUNT_EVERY_S):
            return
        self._last[phase] = now
        what = f"{unit} {done}/{total}" if unit else f"{done}/{total}"
        self.callback(Event(f"{phase}: {what}", PROGRESS, phase, int(done), int(total)))

    def counter(self, phase: str, total: int, unit: str = "") -> Callable[[int], None]:
        """``tick(done)`` reporting `done` of `total` of `phase` (:meth:`count`); reports 0 of `total` now."""
        self.count(phase, 0, total, unit)
        return lambda done: self.count(phase, done, total, unit)

    def notice(self, message: str) -> None:
        if self.callback is not None:
            self.callback(Event(message, NOTICE))


def counter(progress, phase: str, total: int, unit: str = "") -> Callable[[int], None]:
    """``tick(done)``: `done` of `total` of the step `phase` through `progress` when it is a :class:`Reporter`
    (which reports 0 of `total` now); with any other callback (text only) or none, a tick that does nothing."""
    if isinstance(progress, Reporter):
        return progress.counter(phase, total, unit)
    return lambda done: None


def count_to(progress, phase: str, unit: str = "") -> Callable[[int, int], None] | None:
    """``count(done, total)`` of the step `phase` through `progress` when it is a :class:`Reporter` (for work
    whose total is known as it runs: ``parallel.start``'s counter); None otherwise."""
    if isinstance(progress, Reporter):
        return lambda done, total: progress.count(phase, done, total, unit)
    return None


def count_shared(progress, phase: str, parts: int, unit: str = "") -> list:
    """`parts` ``count(done, total)`` callbacks (``parallel.start``'s counters of jobs that share one step, such as the
    two directions of a contact run side by side) reported as one count of the step `phase`: the sum of the parts'
    done of the sum of their totals; a part not yet heard from is taken as large as the mean of those heard from (its
    own total replaces that when it comes).  A list of `parts` Nones when `progress` is not a :class:`Reporter` or has
    no callback (a study's variant: a contact direction ticks some 10 000 times, each a few microseconds for nobody)."""
    if not isinstance(progress, Reporter) or progress.callback is None:
        return [None] * parts
    seen: dict[int, tuple[int, int]] = {}

    def part(k: int):
        def count(done: int, total: int) -> None:
            seen[k] = (int(done), int(total))
            done_sum = sum(d for d, _ in seen.values())
            known = sum(t for _, t in seen.values())
            total_sum = known + round(known / len(seen)) * (parts - len(seen))
            progress.count(phase, done_sum, total_sum, unit)
        return count

    return [part(k) for k in range(parts)]


def event_line(event) -> bytes:
    """One event as the JSON line a forked job or build sends up its pipe (kind, text, phase, done, total): what the
    reader (:mod:`.render`) parses back into an :class:`Event`."""
    import json

    record = dict(kind=getattr(event, "kind", "progress"), text=str(event),
                  phase=getattr(event, "phase", None) or str(event), done=getattr(event, "done", None),
                  total=getattr(event, "total", None))
    return (json.dumps(record) + "\n").encode()
