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
import os
import tomllib
from pathlib import Path
from typing import Any, get_type_hints

from . import numbers
from .errors import InputError, did_you_mean

#: largest part file read (a part file is a few kB of TOML)
MAX_PART_FILE_BYTES = 1 << 20
#: longest string parameter (file names, law names)
MAX_STRING_CHARS = 4096
#: longest list parameter (wheel numbers)
MAX_LIST_ITEMS = 64
#: [meta] keys of a part file and their types
META_KEYS = {"title": "a string", "notes": "a string or a list of strings",
             "expected_failures": "a list of check names (strings)"}


def param(default, unit: str = "", doc: str = "", *, min=None, max=None, min_exclusive=False,
          max_exclusive=False, choices=None, integer=False, why: str = ""):
    """A dataclass field for a part parameter (unit, description, limits).

    `why`: the reason of the upper limit (what real part needs at most), shown by `propulsor params`."""
    meta = dict(unit=unit, doc=doc, min=min, max=max, min_exclusive=min_exclusive,
                max_exclusive=max_exclusive, choices=choices, integer=integer, why=why)
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


def _check_number(name: str, value, meta, unit: str, integer: bool = False):
    """`value` as a Python number within the field's limits (numbers.number: finite, within ±2**53, not
    subnormal; a numpy scalar taken as its Python value); InputError naming `name` otherwise."""
    if not isinstance(value, (bool, int, float)) and hasattr(value, "item"):
        value = numbers.number(value, name)  # numpy's integers and floats are numbers too
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(name, value, ("must be a whole number" if integer else "must be a number")
                         + (f" in {unit}" if unit else ""))
    if isinstance(value, float) and not math.isfinite(value):
        raise InputError(name, value, "must be a finite number")
    if (integer or meta.get("integer")) and isinstance(value, float):
        raise InputError(name, value, "must be a whole number, written without a decimal point"
                         if float(value).is_integer() else "must be a whole number")
    value = numbers.number(value, name)
    lo, hi = meta.get("min"), meta.get("max")
    u = f" {unit}" if unit else ""
    if lo is not None and (value < lo or (meta["min_exclusive"] and value == lo)):
        raise InputError(name, value, f"must be {'>' if meta['min_exclusive'] else '>='} {lo}{u}")
    if hi is not None and (value > hi or (meta["max_exclusive"] and value == hi)):
        raise InputError(name, value, f"must be {'<' if meta['max_exclusive'] else '<='} {hi}{u}")
    return value


def _check_type(name: str, value, typ) -> None:
    """The TOML value has the field's type (bool is not a number, a float is not an int)."""
    if typ is bool and not isinstance(value, bool):
        raise InputError(name, value, "must be true or false")
    if typ is int and (isinstance(value, bool) or not isinstance(value, int)):
        raise InputError(name, value, "must be a whole number")
    if typ is float and (isinstance(value, bool) or not isinstance(value, (int, float))):
        raise InputError(name, value, "must be a number")
    if typ is str and not isinstance(value, str):
        raise InputError(name, value, "must be a string")
    if typ is list and not isinstance(value, list):
        raise InputError(name, value, "must be a list")


def _check_field(f, typ, value):
    """One field's value checked (type, choices, limits, size); returns it normalised (an int given for a
    float parameter becomes a float); InputError naming the field otherwise."""
    name, meta = f.name, f.metadata
    unit = meta.get("unit", "")
    if meta.get("choices") is not None:
        _check_type(name, value, typ)
        if value not in meta["choices"]:
            raise InputError(name, value, f"must be one of {', '.join(map(str, meta['choices']))}",
                             did_you_mean(value, map(str, meta["choices"])) if isinstance(value, str) else "")
    elif typ is bool:
        _check_type(name, value, typ)
    elif typ in (int, float):
        if value is None and f.default is None:
            return value  # an optional number left out
        value = _check_number(name, value, meta, unit, integer=typ is int)
        value = int(value) if typ is int else float(value)
    elif typ is str:
        _check_type(name, value, typ)
        if len(value) > MAX_STRING_CHARS:
            raise InputError(name, value[:40] + "…", f"must be at most {MAX_STRING_CHARS} characters")
    elif typ is list:
        if isinstance(value, tuple):
            value = list(value)
        _check_type(name, value, typ)
        if len(value) > MAX_LIST_ITEMS:
            raise InputError(name, f"[{len(value)} items]", f"must have at most {MAX_LIST_ITEMS} items")
        numbers.nesting(value, name, 2)
        # the parameters' own copy (a caller's list changed afterwards changes nothing), its numbers checked
        value = [_list_item(name, k, x) for k, x in enumerate(value)]
    return value


def _list_item(name: str, k: int, x):
    """An item of a list parameter: a number checked (numbers.number), a list copied, text as it is."""
    if isinstance(x, (list, tuple)):
        return [_list_item(name, k, y) for y in x]
    if isinstance(x, str):
        return x
    return numbers.number(x, f"{name}[{k}]")


def check_fields(obj) -> None:
    """Every field of a parameter dataclass of its type and within its limits (the defaults too: a
    subclass may narrow limits); values normalised in place.  InputError at the first one that is not."""
    hints = get_type_hints(type(obj))
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        checked = _check_field(f, hints[f.name], value)
        if checked is not value:
            object.__setattr__(obj, f.name, checked)


#: the attribute in which ``parts.pipeline.design_of`` keeps the designs of a parameter object (outside its fields)
DESIGN_STORE = "_propulsor_designs"


class PartParams:
    """Base of the part types' parameter dataclasses: constructing one in any way (directly, from a dict,
    from a part file, with ``dataclasses.replace``) checks every field (:func:`check_fields`), so a value
    outside its limits can never reach a design.  The rules between parameters are the class's own
    ``validate()`` (run by :func:`load_params` and by the Python API)."""

    def __post_init__(self) -> None:
        check_fields(self)

    def __getstate__(self) -> dict:
        """The fields only (pickle, ``copy``): the designs computed from them (``pipeline.STORE``) stay behind."""
        return {k: v for k, v in self.__dict__.items() if k != DESIGN_STORE}

    def applies(self, name: str) -> bool:
        """Whether the input `name` applies to this design (is listed in the report and the manifest).
        Every field by default; a part type whose inputs depend on a choice (a law) narrows it."""
        return True

    def meaning(self, name: str) -> str:
        """The meaning of the input `name` for this design: its documented text by default."""
        return next(f.metadata.get("doc", "") for f in dataclasses.fields(self) if f.name == name)


def unknown_key_limit(key: str, known, type_name: str | None = None) -> str:
    """The refusal of an unknown key: the closest known names ("did you mean") where some are close (the whole list,
    57 names for a pair, made a line of 1 000 characters: ``propulsor params`` lists them), else all of them."""
    known = list(known)
    hint = did_you_mean(key, known)
    if hint:
        return (f"unknown parameter for this part ({hint} `propulsor params {type_name or '<part type>'}` lists all "
                f"{len(known)})")
    return f"unknown parameter for this part (known: {', '.join(known)})"


def load_params(cls, mapping: dict[str, Any], validate: bool = True, type_name: str | None = None):
    """Build the parameter dataclass `cls` from a mapping: every value of its type and within its
    limits; then, unless `validate` is False, the dataclass's own ``validate()`` (rules between
    parameters, the design).  `type_name`: the part type's name, for the refusal of an unknown key."""
    fields = {f.name: f for f in dataclasses.fields(cls)}
    hints = get_type_hints(cls)
    unknown = sorted(set(mapping) - set(fields))
    if unknown:
        raise InputError(unknown[0], mapping[unknown[0]], unknown_key_limit(unknown[0], fields, type_name))
    # the keys as the part file gives them first (the message names the first bad one it holds)
    kwargs = {name: _check_field(fields[name], hints[name], value) for name, value in mapping.items()}
    obj = cls(**kwargs)
    if not isinstance(obj, PartParams):
        check_fields(obj)
    if validate and callable(getattr(obj, "validate", None)):
        obj.validate()
    return obj


def describe_params(cls) -> list[dict]:
    """Every parameter with unit, default, limits, description (for `propulsor params`)."""
    rows = []
    first = tuple(getattr(cls, "params_order", ()))  # the names a class lists first (the rest in field order)
    fields = sorted(dataclasses.fields(cls), key=lambda f: first.index(f.name) if f.name in first else len(first))
    for f in fields:
        m = f.metadata
        default = f.default if f.default is not dataclasses.MISSING else (
            f.default_factory() if f.default_factory is not dataclasses.MISSING else None)
        limits = _limit_text(m)
        if m.get("choices") is not None:
            limits = "one of " + ", ".join(map(str, m["choices"]))
        if m.get("integer"):
            limits = ("whole, " + limits) if limits else "whole"
        doc = m.get("doc", "")
        if m.get("why"):
            doc += f" [upper limit: {m['why']}]"
        rows.append(dict(name=f.name, unit=m.get("unit", ""), default=default, limits=limits, doc=doc))
    return rows


def _is_str_list(v) -> bool:
    return isinstance(v, list) and all(isinstance(x, str) for x in v)


def validate_meta(meta) -> dict[str, Any]:
    """The `[meta]` table of a part file, checked: title (string), notes (string or list of strings),
    expected_failures (list of strings); anything else is an InputError."""
    if not isinstance(meta, dict):
        raise InputError("meta", meta, "must be a table: [meta] with title, notes, expected_failures")
    for key, value in meta.items():
        if key not in META_KEYS:
            raise InputError(f"meta.{key}", value, f"unknown [meta] key (known: {', '.join(META_KEYS)})")
        ok = {"title": isinstance(value, str),
              "notes": isinstance(value, str) or _is_str_list(value),
              "expected_failures": _is_str_list(value)}[key]
        if not ok:
            raise InputError(f"meta.{key}", value, f"must be {META_KEYS[key]}")
    return meta


#: deepest nesting of tables and arrays a part file may have (the part types use 2)
MAX_PART_FILE_DEPTH = 16


def _first_too_deep(data, limit: int) -> str | None:
    """The dotted key of the first value nested deeper than `limit`, or None (iterative: any depth)."""
    stack = [(data, "", 0)]
    while stack:
        value, where, depth = stack.pop()
        if depth > limit:
            return where or "(top level)"
        items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
        for k, v in items:
            if isinstance(v, (dict, list)):
                stack.append((v, f"{where}.{k}" if where else str(k), depth + 1))
    return None


def toml_error(exc: ValueError) -> str:
    """The one-line reason a TOML text was refused (tomllib's, or Python's own limit on long integers)."""
    text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    if "digits" in text and "integer string conversion" in text:
        return "is not valid TOML: it holds an integer of more than 4300 digits"
    return f"is not valid TOML: {text[:160]}"


def read_part_toml(path: str | Path) -> dict[str, Any]:
    """The TOML table of a part file, read as bytes and decoded as UTF-8 (InputError otherwise): a regular
    file (never a FIFO or a device) of at most MAX_PART_FILE_BYTES, nested at most MAX_PART_FILE_DEPTH."""
    from .regular_file import read_regular

    path = Path(path)
    if not path.exists():
        raise InputError("part file", str(path), "does not exist")
    try:
        raw = read_regular(os.path.realpath(path), MAX_PART_FILE_BYTES)
    except ValueError as exc:
        raise InputError("part file", str(path), f"{exc}; a part file is a TOML file of at most "
                         f"{MAX_PART_FILE_BYTES} bytes") from None
    except OSError as exc:
        raise InputError("part file", str(path), f"cannot be read: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError("part file", str(path), f"is not UTF-8 text (byte 0x{raw[exc.start]:02x} at offset "
                         f"{exc.start}); a part file is TOML") from None
    try:
        data = tomllib.loads(text)
    except ValueError as exc:  # TOMLDecodeError, or an integer of more than 4 300 digits
        raise InputError("part file", str(path), toml_error(exc)) from None
    except RecursionError:
        raise InputError("part file", str(path), f"nests tables or arrays too deeply (at most "
                         f"{MAX_PART_FILE_DEPTH} levels)") from None
    deep = _first_too_deep(data, MAX_PART_FILE_DEPTH)
    if deep is not None:
        raise InputError("part file", str(path), f"nests tables or arrays deeper than {MAX_PART_FILE_DEPTH} "
                         f"levels (at {deep[:80]})")
    return data


def read_part_meta(path: str | Path) -> dict[str, Any]:
    """The validated `[meta]` table of a part file ({} when it has none)."""
    return validate_meta(read_part_toml(path).get("meta", {}))


def read_part_file(path: str | Path) -> tuple[str, dict[str, Any]]:
    """Read a part TOML file: returns (part type, parameter mapping).

    The file names its part type with `type = "..."`; every other top-level key
    is a parameter.  An optional `[meta]` table (title, notes, expected_failures) is not a
    parameter; it is validated here.
    """
    data = read_part_toml(path)
    part_type = data.pop("type", None)
    if not isinstance(part_type, str):
        raise InputError("type", part_type, "the part file must name its part type, e.g. type = \"planetary_final_drive\"")
    validate_meta(data.pop("meta", {}))
    return part_type, data


def params_to_dict(obj) -> dict[str, Any]:
    return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)}


def applying_inputs(obj) -> dict[str, Any]:
    """The inputs that apply to this design (``obj.applies``), in field order: what a report and a
    manifest list.  The others hold their defaults (setting them is refused), so nothing is lost."""
    applies = getattr(obj, "applies", lambda name: True)
    return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj) if applies(f.name)}
