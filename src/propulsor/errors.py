"""Errors the command line turns into exit codes.

`InputError` (exit 2): the input is invalid; the message is one line naming the
parameter, its value and the limit.  `CheckFailed` (exit 1): a part built but a
check failed.
"""

from __future__ import annotations


#: longest value quoted in a message (the message stays one readable line)
MAX_VALUE_CHARS = 120


class InputError(ValueError):
    """Bad input: one line naming the parameter, its value and the limit."""

    def __init__(self, parameter: str, value, limit: str, hint: str = ""):
        self.parameter = parameter
        self.value = value
        self.limit = limit
        shown = repr(value)
        if len(shown) > MAX_VALUE_CHARS:
            shown = shown[:MAX_VALUE_CHARS] + "…"
        msg = f"{parameter} = {shown}: {limit}"
        if hint:
            msg += f" ({hint})"
        super().__init__(msg)


class CheckFailed(RuntimeError):
    """A built part failed one or more checks."""

    def __init__(self, failures: list[str]):
        self.failures = list(failures)
        super().__init__("; ".join(self.failures))


def require(cond: bool, parameter: str, value, limit: str, hint: str = "") -> None:
    """Raise InputError(parameter, value, limit) unless cond holds (NaN never holds)."""
    if not cond:
        raise InputError(parameter, value, limit, hint)


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
