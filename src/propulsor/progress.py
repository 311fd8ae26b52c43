"""Progress as events: what a build reports while it runs, handed to a callback of its caller's.

The build service prints nothing (``building.py``); it calls ``progress(event)`` with an :class:`Event`.  An
event is its message (a ``str``: a callback that takes text works as it is) with a ``kind``:

* ``PROGRESS`` — a step of the work ("cam: STEP, STL, 3MF and their checks", "gallery: output/index.html");
  the command line shows it with the time since the start unless ``-q``;
* ``NOTICE`` — something the user must see even when quiet: a wait for another build's lock, a check that
  failed, a file kept aside, a page that could not be written.

The command line renders them (``cli.Renderer``: one line each on stderr); the Python API passes them to the
caller's callback, or drops them.
"""

from __future__ import annotations

from typing import Callable

PROGRESS, NOTICE = "progress", "notice"

__all__ = ["Event", "Reporter", "PROGRESS", "NOTICE"]


class Event(str):
    """One thing a build reports: the message (the event is that text) and its kind (PROGRESS or NOTICE)."""

    kind: str

    def __new__(cls, message: str, kind: str = PROGRESS) -> "Event":
        self = super().__new__(cls, message)
        self.kind = kind
        return self

    def __reduce__(self):
        return (type(self), (str(self), self.kind))


class Reporter:
    """The build's side of the callback: ``say(message)`` reports a step, ``say.notice(message)`` a notice;
    with no callback both do nothing."""

    def __init__(self, callback: Callable[[Event], object] | None = None):
        self.callback = callback

    @classmethod
    def of(cls, progress) -> "Reporter":
        """`progress` as a Reporter (a Reporter as it is; a callback or None wrapped)."""
        return progress if isinstance(progress, Reporter) else cls(progress)

    def __call__(self, message: str) -> None:
        if self.callback is not None:
            self.callback(Event(message, PROGRESS))

    def notice(self, message: str) -> None:
        if self.callback is not None:
            self.callback(Event(message, NOTICE))
