"""Progress messages on stderr (for anything that takes over a second)."""

from __future__ import annotations

import sys
import time


class Progress:
    """Messages with the time since the start.  `check`, when given, runs before each message (the
    command line's test for a signal whose exception was swallowed: a safe point to stop)."""

    def __init__(self, enabled: bool = True, stream=None, check=None):
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.check = check
        self.t0 = time.perf_counter()

    def __call__(self, message: str) -> None:
        if self.check is not None:
            self.check()
        if self.enabled:
            print(f"[{time.perf_counter() - self.t0:6.1f} s] {message}", file=self.stream, flush=True)

    @property
    def elapsed(self) -> float:
        return time.perf_counter() - self.t0
