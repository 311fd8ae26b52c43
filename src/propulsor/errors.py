"""The errors of propulsor: what the build service raises and the command line turns into exit codes.

`InputError` (exit 2): the input is invalid; the message is one line naming the
parameter, its value and the limit (`FolderBusy`, an InputError: the output folder is held by another
build and the caller would not wait).  `CheckFailed` (exit 1): a part built but a
check failed.  `EnvironmentFailure` (exit 3): the machine refused (disk full, out of
inodes, read-only file system, permission, a folder vanished); one line naming the
path and the errno.
"""

from __future__ import annotations

from contextlib import contextmanager


#: longest value quoted in a message (the message stays one readable line)
MAX_VALUE_CHARS = 120


class InputError(ValueError):
    """Bad input: one line naming the parameter, its value and the limit."""

    def __init__(self, parameter: str, value, limit: str, hint: str = ""):
        self.parameter = parameter
        self.value = value
        self.limit = limit
        self.hint = hint
        try:
            shown = repr(value)
        except RecursionError:  # a value nested thousands deep (a crafted part file)
            shown = f"<{type(value).__name__} nested too deeply to show>"
        if len(shown) > MAX_VALUE_CHARS:
            shown = shown[:MAX_VALUE_CHARS] + "…"
        msg = f"{parameter} = {shown}: {limit}"
        if hint:
            msg += f" ({hint})"
        super().__init__(msg)

    def __reduce__(self):
        # pickled whole (a forked worker's error comes back to the build as it was raised)
        return (type(self), (self.parameter, self.value, self.limit, self.hint))


@contextmanager
def input_names(names: dict[str, str]):
    """Name part-file keys in the errors of a lower layer.

    The math and geometry layers name the quantities of their equations (``z_H``, ``m``,
    ``slot_width``); a part maps them to the keys of its part file around the call::

        with input_names({"z_H": "driven_teeth", "m": "module_mm"}):
            gear = generate_gear(...)

    An ``InputError`` whose parameter is in ``names`` is raised again with the part-file key
    (same value, limit and hint); any other error passes unchanged.
    """
    try:
        yield
    except InputError as exc:
        key = names.get(exc.parameter)
        if key is None:
            raise
        raise InputError(key, exc.value, exc.limit, exc.hint) from None


class CheckFailed(RuntimeError):
    """A built part failed one or more checks (exit 1): `failures` ("name: message"), `what` was built and,
    when the failed build was kept (``keep_failed``), the folder `out` it was put in and its `result`."""

    def __init__(self, failures: list[str], what: str = "", out=None, result=None):
        self.failures = list(failures)
        self.what = what
        self.out = out
        self.result = result
        super().__init__("; ".join(self.failures))

    def __reduce__(self):
        return (type(self), (self.failures, self.what, self.out, None))


class FolderBusy(InputError):
    """The folder is held by another build or study (its lock) and the caller would not wait (exit 2):
    `folder` and the holder's process id `pid`."""

    def __init__(self, folder: str, pid: str, doing: str = "is being built", key: str = "--out"):
        self.folder = folder
        self.pid = pid
        self.doing = doing
        super().__init__(key, folder, f"{doing} by process {pid} (--no-wait)")

    def __reduce__(self):
        return (type(self), (self.folder, self.pid, self.doing, self.parameter))


def require(cond: bool, parameter: str, value, limit: str, hint: str = "") -> None:
    """Raise InputError(parameter, value, limit) unless cond holds (NaN never holds)."""
    if not cond:
        raise InputError(parameter, value, limit, hint)


def did_you_mean(name, known) -> str:
    """The hint for a mistyped `name`: "did you mean a or b?" with up to three of `known` closest to it ('' when
    none is close), for every refusal of an unknown key (part files, studies, printer settings)."""
    import difflib

    close = difflib.get_close_matches(str(name), list(known), n=3, cutoff=0.6)
    return f"did you mean {' or '.join(close)}?" if close else ""


def require_finite(parameter: str, value: float) -> float:
    import math

    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(parameter, value, "must be a number") from None
    if not math.isfinite(v):
        raise InputError(parameter, value, "must be a finite number")
    return v


def require_positive(parameter: str, value: float, unit: str = "") -> float:
    v = require_finite(parameter, value)
    if not v > 0:
        raise InputError(parameter, value, f"must be > 0{(' ' + unit) if unit else ''}")
    return v


class EnvironmentFailure(RuntimeError):
    """The file system or the machine refused an operation (exit 3): one line naming the path, the
    errno and what was being done.  Raised for an ``OSError`` that no input could have prevented."""

    def __init__(self, path, errno_: int | None, doing: str, detail: str = ""):
        import errno as _errno
        import os as _os

        self.path = str(path)
        self.errno = errno_
        self.doing = doing
        self.detail = detail
        name = _errno.errorcode.get(errno_, "E?") if errno_ is not None else "E?"
        text = detail or (_os.strerror(errno_) if errno_ is not None else "failed")
        super().__init__(f"{doing} {self.path}: [{name}] {text}")

    @classmethod
    def from_oserror(cls, exc: OSError, doing: str = "cannot write") -> "EnvironmentFailure":
        path = exc.filename if exc.filename is not None else "?"
        return cls(path, exc.errno, doing, exc.strerror or "")

    def __reduce__(self):
        return (type(self), (self.path, self.errno, self.doing, self.detail))
