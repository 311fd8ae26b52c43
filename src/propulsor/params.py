"""Validated part parameters: dataclass fields with units and limits, TOML in, errors out.

A part type declares its parameters as a dataclass whose fields carry metadata
made by `param(...)`: unit, description, limits.  `load_params` turns a mapping
(from a TOML file) into that dataclass, refusing unknown keys, wrong types, NaN
and values outside the limits with one-line `InputError`s; the dataclass's own
`validate()` then checks what involves several parameters.
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from pathlib import Path
from typing import Any, get_type_hints

from .errors import InputError


def param(default, unit: str = "", doc: str = "", *, min=None, max=None, min_exclusive=False,
          max_exclusive=False, choices=None, integer=False):
    """A dataclass field for a part parameter (unit, description, limits)."""
    meta = dict(unit=unit, doc=doc, min=min, max=max, min_exclusive=min_exclusive,
                max_exclusive=max_exclusive, choices=choices, integer=integer)
    if isinstance(default, (list, dict)):
        return dataclasses.field(default_factory=lambda d=default: type(d)(d), metadata=meta)
    return dataclasses.field(default=default, metadata=meta)


def _limit_text(meta) -> str:
    parts = []
    if meta.get("min") is not None:
        parts.append(f"{'>' if meta['min_exclusive'] else '>='} {meta['min']}")
    if meta.get("max") is not None:
        parts.append(f"{'<' if meta['max_exclusive'] else '<='} {meta['max']}")
    return " and ".join(parts)


def _check_number(name: str, value, meta, unit: str):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(name, value, "must be a number" + (f" in {unit}" if unit else ""))
    if not math.isfinite(float(value)):
        raise InputError(name, value, "must be a finite number")
    if meta.get("integer") and float(value) != int(value):
        raise InputError(name, value, "must be a whole number")
    lo, hi = meta.get("min"), meta.get("max")
    u = f" {unit}" if unit else ""
    if lo is not None and (value < lo or (meta["min_exclusive"] and value == lo)):
        raise InputError(name, value, f"must be {'>' if meta['min_exclusive'] else '>='} {lo}{u}")
    if hi is not None and (value > hi or (meta["max_exclusive"] and value == hi)):
        raise InputError(name, value, f"must be {'<' if meta['max_exclusive'] else '<='} {hi}{u}")


def load_params(cls, mapping: dict[str, Any]):
    """Build and validate the parameter dataclass `cls` from a mapping."""
    fields = {f.name: f for f in dataclasses.fields(cls)}
    hints = get_type_hints(cls)
    unknown = sorted(set(mapping) - set(fields))
    if unknown:
        raise InputError(unknown[0], mapping[unknown[0]], f"unknown parameter for this part (known: {', '.join(fields)})")
    kwargs = {}
    for name, value in mapping.items():
        meta = fields[name].metadata
        typ = hints[name]
        unit = meta.get("unit", "")
        if meta.get("choices") is not None:
            if value not in meta["choices"]:
                raise InputError(name, value, f"must be one of {', '.join(map(str, meta['choices']))}")
        elif typ is bool:
            if not isinstance(value, bool):
                raise InputError(name, value, "must be true or false")
        elif typ in (int, float):
            _check_number(name, value, meta, unit)
            value = int(value) if typ is int else float(value)
        elif typ is str:
            if not isinstance(value, str):
                raise InputError(name, value, "must be a string")
        kwargs[name] = value
    obj = cls(**kwargs)
    # defaults are checked too (a subclass may narrow limits)
    for name, f in fields.items():
        if name in mapping:
            continue
        v = getattr(obj, name)
        if hints[name] in (int, float) and v is not None and f.metadata.get("choices") is None:
            _check_number(name, v, f.metadata, f.metadata.get("unit", ""))
    validate = getattr(obj, "validate", None)
    if callable(validate):
        validate()
    return obj


def describe_params(cls) -> list[dict]:
    """Every parameter with unit, default, limits, description (for `propulsor params`)."""
    rows = []
    for f in dataclasses.fields(cls):
        m = f.metadata
        default = f.default if f.default is not dataclasses.MISSING else (
            f.default_factory() if f.default_factory is not dataclasses.MISSING else None)
        limits = _limit_text(m)
        if m.get("choices") is not None:
            limits = "one of " + ", ".join(map(str, m["choices"]))
        if m.get("integer"):
            limits = ("whole, " + limits) if limits else "whole"
        rows.append(dict(name=f.name, unit=m.get("unit", ""), default=default, limits=limits, doc=m.get("doc", "")))
    return rows


def read_part_file(path: str | Path) -> tuple[str, dict[str, Any]]:
    """Read a part TOML file: returns (part type, parameter mapping).

    The file names its part type with `type = "..."`; every other top-level key
    is a parameter.  An optional `[meta]` table (title, notes) is not a parameter.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("part file", str(path), "does not exist")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError("part file", str(path), f"is not valid TOML: {exc}") from None
    part_type = data.pop("type", None)
    if not isinstance(part_type, str):
        raise InputError("type", part_type, "the part file must name its part type, e.g. type = \"planetary_final_drive\"")
    data.pop("meta", None)
    return part_type, data


def params_to_dict(obj) -> dict[str, Any]:
    return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)}
