"""SIGINT and SIGTERM turned into an exception a build can clean up after.

The command line installs :func:`raise_interrupted` for both signals (``cli.main``): a signal then raises
:class:`Interrupted` wherever the build is, every ``finally`` of the build runs (workers killed, temporary
folder removed, lock let go) with further signals held off (:func:`held_signals`), and the command line ends
with 128 + the signal's number and one line.  Nothing here prints or knows an exit code.
"""

from __future__ import annotations

import signal
import sys
import threading

__all__ = ["Interrupted", "SIGNALLED", "raise_interrupted", "unraisable", "check_signalled", "hold_signals",
           "held_signals"]


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived; the exit code is 128 + the signal number.  On its way up it may be told what was
    kept: ``kept`` (the command line's one line says it) and, in a build of several, ``placed_before`` (the builds
    whose output was in place before the batch saw them end: batch._PlacedWord)."""

    placed_before = 0

    def __init__(self, signum: int):
        self.signum = signum
        super().__init__(signum)


#: signals received; the handler raises at once, but an exception raised inside a finaliser or a
#: weakref callback is swallowed by Python, so the build also stops at the next safe point
SIGNALLED: list[int] = []


def raise_interrupted(signum, frame):
    SIGNALLED.append(signum)
    raise Interrupted(signum)


def unraisable(info) -> None:
    """Python's hook for exceptions it cannot raise (in finalisers, weakref callbacks): an Interrupted
    there is remembered in SIGNALLED and acted on at the next safe point, not printed.  After a signal, the
    error of a multiprocessing finaliser whose construction the signal cut short (its weakref set, its key not:
    ``AttributeError: 'Finalize' object has no attribute '_key'`` when its object dies, as the process ends) is
    the signal's doing, not a fault to report: not printed either (the command line's one line stays one)."""
    if isinstance(info.exc_value, Interrupted):
        return
    if SIGNALLED and _half_built_finalizer(info):
        return
    sys.__unraisablehook__(info)


def _half_built_finalizer(info) -> bool:
    obj = getattr(info, "object", None)
    return (type(obj).__name__ == "Finalize" and type(obj).__module__ == "multiprocessing.util"
            and isinstance(info.exc_value, AttributeError) and not hasattr(obj, "_key"))


def check_signalled() -> None:
    """Raise Interrupted when a signal arrived whose exception may have been swallowed."""
    if SIGNALLED:
        raise Interrupted(SIGNALLED[0])


def hold_signals() -> None:
    """Ignore further SIGINT / SIGTERM from now on (the command line, ending after an interruption)."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)


class held_signals:
    """SIGINT / SIGTERM ignored for the block (a clean-up a second Ctrl-C must not cut short), then the
    handlers as they were — unless a signal has arrived (:data:`SIGNALLED`): the process is ending, and they stay
    ignored until the command line has said so.  Only the main thread can change handlers; elsewhere a no-op."""

    def __enter__(self):
        self.saved = {}
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGINT, signal.SIGTERM):
                self.saved[sig] = signal.signal(sig, signal.SIG_IGN)
        return self

    def __exit__(self, *exc) -> None:
        if SIGNALLED:
            return
        for sig, handler in self.saved.items():
            signal.signal(sig, handler if handler is not None else signal.SIG_DFL)
