"""The one way a number enters propulsor: from text (a CSV cell, a command-line value) or as a value (TOML
in a part file, a printer profile, a study file or ``--set``; a Python caller's int, float or numpy number).

Every number taken is

* written in plain ASCII: an optional sign, digits, an optional decimal point and digits, an optional
  exponent of at most three digits — no other script's digits (``١٨٠``), no ``_`` between digits (``1_8_0``),
  no ``inf`` / ``nan``, at most :data:`MAX_CHARS` characters (a 5 000-digit integer is never converted);
* finite, within ±:data:`MAGNITUDE_MAX` (an integer as large as ``10**400`` is refused before it meets a
  float), and not subnormal (0 < |x| < :data:`TINY`: no computation keeps its digits);
* a number, not a boolean (``true`` is not 1).

A refusal is InputError naming the key, one line (exit 2).  Containers of numbers (TOML tables and
arrays, ``--set`` values) are bounded in depth by :func:`nesting`.
"""

from __future__ import annotations

import math
import re

from .errors import InputError

#: the longest text of a number
MAX_CHARS = 40
#: the largest magnitude of a number (every parameter's limit is far below; 2**53: integers stay exact)
MAGNITUDE_MAX = float(2 ** 53)
#: the smallest non-zero magnitude (a subnormal float carries too few digits to compute with)
TINY = 2.2250738585072014e-308
#: the deepest nesting of arrays and tables a value may have (a part file's own limit is policy's)
NESTING_MAX = 16

_TEXT = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]{1,3})?")
_WHOLE = re.compile(r"[+-]?[0-9]+")


def number(value, key: str, *, whole: bool = False):
    """`value` (int, float, or a numpy integer or float) as a Python int or float, checked (module
    docstring); InputError naming `key` otherwise.  `whole`: an int is required (a float, even 2.0, is not)."""
    what = "a whole number" if whole else "a number"
    if isinstance(value, bool) or value is None:
        raise InputError(key, value, f"must be {what}, not {value!r}")
    if not isinstance(value, (int, float)):
        item = getattr(value, "item", None)  # numpy's scalars (np.int64, np.float32 …), never its bool
        kind = type(value).__name__
        if item is None or kind.startswith("bool") or getattr(value, "shape", None) not in ((), None):
            raise InputError(key, value, f"must be {what}")
        value = item()
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(key, value, f"must be {what}")
    if isinstance(value, int):
        if abs(value) > MAGNITUDE_MAX:
            raise InputError(key, f"{'-' if value < 0 else ''}a {_digits(value)}-digit number",
                             f"must be within ±{MAGNITUDE_MAX:.0f}")
        return int(value)
    value = float(value)
    if whole:
        raise InputError(key, value, "must be a whole number, written without a decimal point"
                         if math.isfinite(value) and value.is_integer() else "must be a whole number")
    if not math.isfinite(value):
        raise InputError(key, value, "must be a finite number")
    if abs(value) > MAGNITUDE_MAX:
        raise InputError(key, value, f"must be within ±{MAGNITUDE_MAX:.0f}")
    if value != 0.0 and abs(value) < TINY:
        raise InputError(key, value, f"is too small to compute with (0, or a magnitude of at least {TINY:.4g})")
    return value


def _digits(value: int) -> int:
    """Decimal digits of a large int, without converting it to text (which Python refuses past 4 300)."""
    return int(abs(value).bit_length() * 0.30103) + 1


def parse(text, key: str, *, whole: bool = False):
    """The number written as `text` (module docstring), as an int when it has no point or exponent (or
    `whole` asks for one), else a float; InputError naming `key` otherwise."""
    what = "a whole number" if whole else "a number"
    if not isinstance(text, str):
        raise InputError(key, text, f"must be {what}")
    s = text.strip(" \t")
    if len(s) > MAX_CHARS:
        raise InputError(key, f"{s[:20]}… ({len(s)} characters)", f"must be {what} of at most {MAX_CHARS} characters")
    if not _TEXT.fullmatch(s):
        raise InputError(key, s, f"must be {what} in plain digits (0-9, '.', an exponent e±NNN)")
    if _WHOLE.fullmatch(s):
        return number(int(s), key)
    if whole:
        raise InputError(key, s, "must be a whole number")
    return number(float(s), key)


def nesting(value, key: str, limit: int = NESTING_MAX) -> None:
    """InputError naming `key` when `value` nests lists and dicts deeper than `limit` (iterative: any depth)."""
    stack = [(value, 0)]
    while stack:
        v, depth = stack.pop()
        if depth > limit:
            raise InputError(key, f"<nested more than {limit} deep>", f"must nest arrays and tables at most {limit} deep")
        items = v.values() if isinstance(v, dict) else v if isinstance(v, (list, tuple)) else ()
        stack.extend((x, depth + 1) for x in items if isinstance(x, (dict, list, tuple)))
