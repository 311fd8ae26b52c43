"""The memory ceiling of `propulsor check` (policy.CHECK_MEMORY_CEILING).

The readers' limits (policy.READ_LIMIT_BYTES and the rest) keep a check below the ceiling; the
ceiling itself is enforced by lowering the process's address-space limit (RLIMIT_AS) while the checks
run, so that an allocation past it fails (MemoryError: that file is invalid) instead of exhausting
the machine.  It is restored afterwards.  Not applied where it cannot be (no ``resource`` module, a
lower limit already set, or a caller that already maps half the ceiling, e.g. a test runner).
"""

from __future__ import annotations

import os
from contextlib import contextmanager

from ..policy import CHECK_MEMORY_CEILING


def address_space() -> int | None:
    """Bytes of address space this process maps now (None where /proc is missing)."""
    try:
        with open("/proc/self/statm", "rb") as fh:
            return int(fh.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return None


@contextmanager
def memory_ceiling(ceiling: int = CHECK_MEMORY_CEILING):
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        yield
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    inf = resource.RLIM_INFINITY
    used = address_space()
    if (soft != inf and soft <= ceiling) or (hard != inf and hard < ceiling) or used is None or used > ceiling // 2:
        yield
        return
    resource.setrlimit(resource.RLIMIT_AS, (ceiling, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))
