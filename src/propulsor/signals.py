"""Exit codes, and SIGINT / SIGTERM turned into an exception a build can clean up after.

Exit codes: 0 built and every check passed; 1 built but a check failed (outputs kept only with
--keep-failed) or `check` found invalid files; 2 bad input (one line on stderr, nothing written);
3 the environment refused (disk full, out of inodes, read-only file system, permission denied, a
folder removed under the build: one line naming the path and the errno, nothing published);
130 / 143 interrupted by SIGINT / SIGTERM (one line, no temporary folder and no worker process left).
"""

from __future__ import annotations

import signal
import sys
import threading

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT, EXIT_ENVIRONMENT = 0, 1, 2, 3


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived; the exit code is 128 + the signal number."""

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
    there is remembered in SIGNALLED and acted on at the next safe point, not printed."""
    if isinstance(info.exc_value, Interrupted):
        return
    sys.__unraisablehook__(info)


def check_signalled() -> None:
    """Raise Interrupted when a signal arrived whose exception may have been swallowed."""
    if SIGNALLED:
        raise Interrupted(SIGNALLED[0])


def hold_signals() -> None:
    """Ignore further SIGINT / SIGTERM while cleaning up (a second Ctrl-C must not leave debris)."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)


def fail_input(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_BAD_INPUT


def fail_environment(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_ENVIRONMENT
