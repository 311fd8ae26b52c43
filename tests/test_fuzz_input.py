"""Fuzzing the part files: random TOML against the command line's contract for input.

Per part type, hypothesis writes part files with valid keys given hostile values, unknown keys,
hostile `[meta]` tables, or random bytes, and runs `propulsor build --dry-run` (validate and
estimate, no build) in this process.  The contract: exit 0 (valid, nothing written) or exit 2 with
exactly one line on stderr naming the problem — never an exception (a traceback), never another
exit code, never a file written, and within a time bound.  `make test` runs a few examples per
part type; `make check` (marker `sweep`) runs a few hundred.
"""

from __future__ import annotations

import dataclasses
import math
import shutil
import typing
from datetime import timedelta
from pathlib import Path

import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from propulsor.cli import main
from propulsor.parts import get_part_type, part_type_names

ROOT = Path(__file__).resolve().parents[1]
PART_TYPES = part_type_names()

#: values no parameter may take, and values at and past every kind of limit
HOSTILE_NUMBERS = [0, -1, 1, 2, 1e9, -1e9, 1e308, -1e308, 5e-324, 2**63 - 1, -(2**63), math.inf, -math.inf,
                   math.nan, 0.5, 2.0, -0.0, 1e-12]
HOSTILE_OTHER = [True, False, "", "x", "\x00\x7f", "é" * 5000, [], [1, 2, 3], [True], [1.5], ["a"], {"a": 1}, {}]


def _fields(part_type: str) -> dict[str, tuple[type, dict]]:
    cls = get_part_type(part_type).params_cls
    hints = typing.get_type_hints(cls)
    return {f.name: (hints[f.name], dict(f.metadata)) for f in dataclasses.fields(cls)}


def _value_for(typ, meta):
    """A strategy of values for one field: its own type confused (a bool for a number, an integral
    float for a whole number, a number for a string), values at and just past its limits, hostile
    values of every kind, and valid values."""
    lo, hi = meta.get("min"), meta.get("max")
    confused = {int: [True, False, 2.0, 1.0, "4"], float: [True, False, "1.0", [1.0]],
                bool: [0, 1, "true"], str: [1, True, ["x"]], list: [1, "1, 2", {"a": 1}]}.get(typ, [None])
    options = [st.sampled_from([v for v in confused if v is not None] or [0]),
               st.sampled_from(HOSTILE_NUMBERS), st.sampled_from(HOSTILE_OTHER), st.integers(), st.floats()]
    edges = [v for v in (lo, hi) if v is not None]
    edges += [v + d for v in edges for d in (-1, 1, -1e-9, 1e-9)]
    if typ in (int, float) and edges:
        options.append(st.sampled_from([int(v) if typ is int else float(v) for v in edges]))
    if typ in (int, float) and lo is not None and hi is not None:
        options.append(st.integers(int(math.ceil(lo)), int(hi)) if typ is int else st.floats(float(lo), float(hi)))
    if meta.get("choices"):
        choices = list(meta["choices"])
        options.append(st.sampled_from(choices + [float(c) for c in choices if type(c) is int]))
    return st.one_of(options)


def _valid_for(typ, meta, default):
    """A strategy of values within one field's type and limits (cross-field rules may still refuse)."""
    lo, hi = meta.get("min"), meta.get("max")
    if meta.get("choices"):
        return st.sampled_from(list(meta["choices"]))
    if typ is int and lo is not None and hi is not None:
        return st.integers(int(math.ceil(lo)), int(hi))
    if typ is float and lo is not None and hi is not None:
        return st.floats(float(lo), float(hi), exclude_min=bool(meta.get("min_exclusive")),
                         exclude_max=bool(meta.get("max_exclusive")))
    if typ is bool:
        return st.booleans()
    return st.just(default)


def _meta():
    text = st.text(max_size=30)
    return st.one_of(
        st.just(5), st.just("title"), st.just([1]),
        st.fixed_dictionaries({}, optional={"title": st.one_of(text, st.just({"a": 1}), st.integers()),
                                            "notes": st.one_of(text, st.lists(text, max_size=3), st.just([1])),
                                            "expected_failures": st.one_of(st.lists(text, max_size=3), text),
                                            "colour": text}))


@st.composite
def part_files(draw, part_type: str) -> bytes:
    """The bytes of one part file for `part_type`."""
    kind = draw(st.sampled_from(["hostile values"] * 6 + ["unknown keys", "meta", "bytes"]))
    if kind == "bytes":
        return draw(st.binary(max_size=200))
    fields = _fields(part_type)
    defaults = dataclasses.asdict(get_part_type(part_type).params_cls())
    doc: dict = {"type": part_type}
    names = draw(st.lists(st.sampled_from(sorted(fields)), min_size=1, max_size=6, unique=True))
    for k, name in enumerate(names):  # one hostile value, the others valid on their own
        typ, meta = fields[name]
        doc[name] = draw(_value_for(typ, meta) if k == 0 else _valid_for(typ, meta, defaults[name]))
    if kind == "unknown keys":
        doc[draw(st.from_regex(r"[a-z_]{1,12}", fullmatch=True))] = draw(st.sampled_from(HOSTILE_NUMBERS))
    if kind == "meta" or draw(st.booleans()):
        doc["meta"] = draw(_meta())
    try:
        return tomli_w.dumps(doc).encode("utf-8")
    except (TypeError, ValueError):  # a value TOML cannot hold: write it as text anyway
        return (f'type = "{part_type}"\n' + "\n".join(f"{k} = {v!r}" for k, v in doc.items()
                                                      if k not in ("type", "meta"))).encode("utf-8", "replace")


def _contract(data: bytes, part_type: str, tmp_path_factory, capsys) -> tuple[int, str]:
    folder = tmp_path_factory.mktemp(part_type)
    shutil.copy(ROOT / "parts" / "road_wheel.toml", folder / "road_wheel.toml")  # the balancer names it
    f = folder / "part.toml"
    f.write_bytes(data)
    before = sorted(p.name for p in folder.iterdir())
    out = folder / "out"
    capsys.readouterr()
    rc = main(["build", str(f), "--out", str(out), "--dry-run", "-q"])
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if line.strip()]
    assert rc in (0, 2), (rc, err)
    assert "Traceback" not in err
    if rc == 2:
        assert len(lines) == 1 and lines[0].startswith("propulsor: error: "), err
    else:
        assert lines == [], err
        _accepted_values_obey_the_schema(data, part_type)
    assert sorted(p.name for p in folder.iterdir()) == before, "a dry run wrote something"
    return rc, err


def _accepted_values_obey_the_schema(data: bytes, part_type: str) -> None:
    """A file the dry run accepted holds only known keys, each of its field's type (a bool is not a
    number, a float not a whole number) and within its limits; [meta] holds only its three keys."""
    import tomllib

    doc = tomllib.loads(data.decode("utf-8"))
    fields = _fields(part_type)
    meta = doc.pop("meta", {})
    assert isinstance(meta, dict) and set(meta) <= {"title", "notes", "expected_failures"}, meta
    assert doc.pop("type") == part_type
    for name, value in doc.items():
        typ, m = fields[name]
        if typ is float:
            assert isinstance(value, (int, float)) and not isinstance(value, bool), (name, value)
        else:
            assert type(value) is typ, (name, value)
        if m.get("choices") is not None:
            assert value in m["choices"], (name, value)
        if typ in (int, float):
            assert math.isfinite(value), (name, value)
            if m.get("min") is not None:
                assert value >= m["min"], (name, value)
            if m.get("max") is not None:
                assert value <= m["max"], (name, value)


def _fuzz(part_type: str, max_examples: int, tmp_path_factory, capsys) -> None:
    """`max_examples` random part files of `part_type` against the contract (derandomized: the same
    files every run)."""
    @settings(max_examples=max_examples, deadline=timedelta(seconds=60), derandomize=True,
              suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                     HealthCheck.data_too_large])
    @given(data=part_files(part_type))
    def run(data):
        _contract(data, part_type, tmp_path_factory, capsys)

    run()


@pytest.mark.parametrize("part_type", PART_TYPES)
def test_fuzz_part_file_contract(part_type, tmp_path_factory, capsys):
    _fuzz(part_type, 12, tmp_path_factory, capsys)


@pytest.mark.sweep
@pytest.mark.parametrize("part_type", PART_TYPES)
def test_fuzz_part_file_contract_long(part_type, tmp_path_factory, capsys):
    _fuzz(part_type, 300, tmp_path_factory, capsys)


@pytest.mark.parametrize("part_type", PART_TYPES)
def test_every_number_is_bounded_with_a_reason(part_type):
    """Each numeric parameter has an upper limit, and `propulsor params` says why."""
    for name, (typ, meta) in _fields(part_type).items():
        if typ in (int, float) and meta.get("choices") is None:
            assert meta.get("max") is not None, f"{part_type}.{name} has no upper limit"
            assert meta.get("min") is not None, f"{part_type}.{name} has no lower limit"
            assert meta.get("why"), f"{part_type}.{name}: the reason of its upper limit is missing"


@pytest.mark.parametrize("part_type", PART_TYPES)
def test_defaults_at_the_limits_are_refused_past_them(part_type, tmp_path_factory, capsys):
    """Past each upper limit by a little, the dry run exits 2 naming that parameter (the fuzzer's
    hostile values go far past; this pins the limits themselves)."""
    for name, (typ, meta) in _fields(part_type).items():
        hi = meta.get("max")
        if typ not in (int, float) or hi is None or meta.get("choices") is not None:
            continue
        over = hi + 1 if typ is int else hi * 1.01 + 1e-9 if hi > 0 else hi + 1e-3
        doc = {"type": part_type, name: int(over) if typ is int else float(over)}
        rc, err = _contract(tomli_w.dumps(doc).encode(), part_type, tmp_path_factory, capsys)
        assert rc == 2 and f"error: {name} = " in err, (name, err)
