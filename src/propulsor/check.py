"""One check result: what was measured, against which limit, pass or fail.

The one check type of every layer (engineering limits in laws/, B-rep, mesh, motion and file
checks in checks/, the parts' own checks): the report and the manifest print them unchanged
(docs/architecture.md, "The data flow of one build").  Depends on nothing but the standard library (numpy values
are converted when numpy is present), so every layer may import it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


def _plain(v):
    """numpy scalars / arrays -> plain Python values (JSON-safe)."""
    if v is None or isinstance(v, (bool, str)):
        return v
    try:
        import numpy as np

        if isinstance(v, np.bool_):
            return bool(v)
        if isinstance(v, np.integer):
            return int(v)
        if isinstance(v, np.floating):
            return float(v)
        if isinstance(v, np.ndarray):
            return [_plain(x) for x in v.tolist()]
    except ImportError:  # pragma: no cover - numpy is a hard dependency
        pass
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in v.items()}
    if isinstance(v, (int, float)):
        return v
    return str(v)


@dataclass(frozen=True)
class Check:
    """A named check: `value` measured, compared with `limit` (same `unit`)."""

    name: str
    passed: bool
    value: object = None
    limit: object = None
    unit: str = ""
    message: str = ""

    def __post_init__(self):
        object.__setattr__(self, "passed", bool(self.passed))
        object.__setattr__(self, "value", _plain(self.value))
        object.__setattr__(self, "limit", _plain(self.limit))

    # --- constructors -------------------------------------------------------
    @classmethod
    def at_most(cls, name: str, value: float, limit: float, unit: str = "", message: str = "") -> "Check":
        """Passes when value <= limit (NaN never passes)."""
        v = float(value)
        return cls(name, bool(v <= limit), v, limit, unit, message or f"{name} <= {limit} {unit}".strip())

    @classmethod
    def at_least(cls, name: str, value: float, limit: float, unit: str = "", message: str = "") -> "Check":
        """Passes when value >= limit (NaN never passes)."""
        v = float(value)
        return cls(name, bool(v >= limit), v, limit, unit, message or f"{name} >= {limit} {unit}".strip())

    @classmethod
    def greater_than(cls, name: str, value: float, limit: float, unit: str = "", message: str = "") -> "Check":
        """Passes when value > limit strictly (NaN never passes)."""
        v = float(value)
        return cls(name, bool(v > limit), v, limit, unit, message or f"{name} > {limit} {unit}".strip())

    @classmethod
    def equal_within(
        cls, name: str, value: float, expected: float, rel_tol: float = 0.0, abs_tol: float = 0.0, unit: str = "", message: str = ""
    ) -> "Check":
        """Passes when |value - expected| <= max(rel_tol*|expected|, abs_tol).

        `value` is the measured quantity, `limit` records the expected value and
        the tolerances; the relative deviation goes into the message.
        """
        v, e = float(value), float(expected)
        tol = max(rel_tol * abs(e), abs_tol)
        dev = abs(v - e)
        ok = math.isfinite(dev) and dev <= tol
        rel = dev / abs(e) if e != 0 else float("inf") if dev else 0.0
        lim = {"expected": e, "rel_tol": rel_tol, "abs_tol": abs_tol}
        msg = message or f"{name}: {v!r} vs expected {e!r} (deviation {dev:.3g} {unit}, relative {rel:.3g})".replace("  ", " ")
        return cls(name, ok, v, lim, unit, msg)

    @classmethod
    def equals(cls, name: str, value, expected, unit: str = "", message: str = "") -> "Check":
        """Passes when value == expected exactly (counts, flags)."""
        return cls(name, value == expected, value, expected, unit, message or f"{name} == {expected!r}")

    @classmethod
    def flag(cls, name: str, ok: bool, message: str = "") -> "Check":
        """A yes/no check: value is the flag, the limit is True."""
        return cls(name, bool(ok), bool(ok), True, "", message or name)

    # --- read-only mapping of the six fields (the form of a manifest record) -------------------------
    def keys(self):
        return ("name", "passed", "value", "limit", "unit", "message")

    def __iter__(self):
        return iter(self.keys())

    def __getitem__(self, key: str):
        if key not in self.keys():
            raise KeyError(key)
        return getattr(self, key)

    # --- output -------------------------------------------------------------
    @property
    def status(self) -> str:
        return "PASS" if self.passed else "FAIL"

    def to_dict(self) -> dict:
        return {
            "name": self.name,
            "passed": self.passed,
            "value": _json_float(self.value),
            "limit": _json_limit(self.limit),
            "unit": self.unit,
            "message": self.message,
        }

    def __str__(self) -> str:
        u = f" {self.unit}" if self.unit else ""
        return f"[{self.status}] {self.name}: value {_fmt(self.value)}{u}, limit {_fmt(self.limit)}{u} - {self.message}"


def _json_float(v):
    if isinstance(v, float) and not math.isfinite(v):
        return repr(v)  # 'nan', 'inf': JSON has no such numbers
    if isinstance(v, list):
        return [_json_float(x) for x in v]
    return v


def _json_limit(v):
    if isinstance(v, dict):
        return {k: _json_float(_plain(x)) for k, x in v.items()}
    return _json_float(v)


def _fmt(v) -> str:
    if isinstance(v, float):
        return f"{v:.9g}"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_fmt(x)}" for k, x in v.items()) + "}"
    return str(v)


def all_passed(checks) -> bool:
    return all(c.passed for c in checks)


def failures(checks) -> list[str]:
    """One line per failed check (for CheckFailed)."""
    return [str(c) for c in checks if not c.passed]
