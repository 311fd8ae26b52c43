"""How the ``propulsor`` program ends (:func:`leave`): without the interpreter's teardown where nothing is left to
finish, after doing what the teardown would still do.  Used by :func:`.cli.run`.
"""

from __future__ import annotations

import os
import sys
import threading

from .signals import SIGNALLED

__all__ = ["leave"]


def leave(code: int) -> None:
    """End the process with `code` without the interpreter's teardown where nothing is left to finish: after a
    build the teardown is its garbage collector scanning every object the build and the imports made, once per
    stage of the modules' clearing (the Fourier pair's build: 1.3 s between the report written and the process
    gone, 0.12-0.18 s this way).  What the teardown would still do is done first: the streams and every file left open
    flushed, the exit functions run (temporary folders removed, loggers closed).  The normal exit where anything
    else runs on — a thread the teardown would wait for, a worker process — or after a signal (its finalisers run at
    exit)."""
    import _io
    import atexit
    import gc
    import multiprocessing as mp

    first = threading.main_thread()
    if SIGNALLED or mp.active_children() or any(t is not first and not t.daemon for t in threading.enumerate()):
        sys.exit(code)  # (a daemon thread the teardown would abandon too)
    try:
        objects = gc.get_objects()  # a file written through but not closed: its buffer, as a teardown would
        # every file object's class derives from the C base of io.IOBase (an ABC: its isinstance, half a second)
        files = {t for t in set(map(type, objects)) if issubclass(t, _io._IOBase)}
        for f in objects:
            if type(f) in files and not f.closed and f.writable():
                f.flush()
        del objects
        sys.stdout.flush()
        sys.stderr.flush()
        atexit._run_exitfuncs()
        sys.stdout.flush()
        sys.stderr.flush()
    except Exception:  # noqa: BLE001 - a stream gone (EPIPE) or a failing exit function: the normal exit reports it
        sys.exit(code)
    os._exit(code)
