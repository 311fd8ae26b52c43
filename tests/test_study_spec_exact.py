"""Study files (study/spec.py) with the whole of each answer: every refusal's parameter, value and text, the
variants of lists, ranges and samplers, requirements of each operator, the variant key.  The cases
`make mutation MODULE=study` found no test for (mutation/README.md)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from propulsor.errors import InputError
from propulsor.study.spec import (ALL_CHECKS, MAX_STUDY_BYTES, MAX_VARIANTS, Requirement, Study, _requirement, load_study,
                                  variant_key)

ROOT = Path(__file__).resolve().parents[1]
WHEEL = ROOT / "parts" / "road_wheel.toml"

BASE = {
    "study": f'part = "{WHEEL}"\ndepth = "design"',
    "vary": "tyre_width_mm = [70.0, 90.0]",
    "objectives": 'minimize = ["T_at_V_max_C"]',
}


def _text(**sections) -> str:
    parts = {**BASE, **sections}
    return "".join(f"[{k}]\n{v}\n\n" for k, v in parts.items() if v is not None)


def _load(tmp_path, text: str, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return load_study(p)


def _refused(tmp_path, text: str) -> tuple:
    with pytest.raises(InputError) as e:
        _load(tmp_path, text)
    return e.value.parameter, e.value.value, e.value.limit


def test_a_study_read_whole(tmp_path):
    s = _load(tmp_path, _text(study=f'part = "{WHEEL}"\ndepth = "design"\ntitle = "widths"',
                              vary="tyre_width_mm = [70.0, 90.0, 70.0]\nrow_gap_mm = { from = 10.0, to = 12.0, "
                                   "step = 1.0 }",
                              objectives='minimize = ["T_at_V_max_C"]\nmaximize = ["tyre_width_mm_out"]\n'
                                         'require = ["all_checks_passed", "T_at_V_max_C <= 125"]\nrecord = []'
                              .replace('maximize = ["tyre_width_mm_out"]\n', '')))
    assert s.title == "widths" and s.part_type == "road_wheel" and s.depth == "design"
    assert s.part_file == WHEEL.resolve() and s.varied == ("tyre_width_mm", "row_gap_mm")
    # a list keeps its first of each value; the grid is the product in the order written
    assert [tuple(v.values()) for v in s.variants] == [(70.0, 10.0), (70.0, 11.0), (70.0, 12.0), (90.0, 10.0),
                                                        (90.0, 11.0), (90.0, 12.0)]
    assert s.require == (Requirement(ALL_CHECKS), Requirement("T_at_V_max_C", "<=", 125.0))
    assert s.objectives == ("T_at_V_max_C",) and s.values == ("T_at_V_max_C",)
    # no title: the file's name
    assert _load(tmp_path, _text(), "wheel study.toml").title == "wheel study"


@pytest.mark.parametrize("sections, want", [
    (dict(extra="a = 1"), ("extra", {"a": 1}, "unknown section of a study file (study, vary, objectives)")),
    (dict(study=f'part = "{WHEEL}"\nspeed = 1'), ("study.speed", 1, "unknown key (known: depth, part, sample, seed, "
                                                                    "title)")),
    (dict(objectives='minimise = ["T_at_V_max_C"]'),
     ("objectives.minimise", ["T_at_V_max_C"], "unknown key (known: maximize, minimize, record, require)")),
    (dict(study='depth = "design"'), ("study.part", None, "must name the base part file (a path relative to the "
                                                          "study file)")),
    (dict(study='part = ""'), ("study.part", "", "must name the base part file (a path relative to the study file)")),
    (dict(study=f'part = "{WHEEL}"\ndepth = "full"'), ("study.depth", "full", "must be one of design, proof, build")),
    (dict(study=f'part = "{WHEEL}"\ntitle = 3'), ("study.title", 3, "must be a string")),
    (dict(study=f'part = "{WHEEL}"\nsample = 0'), ("study.sample", 0, f"must be a whole number of variants within "
                                                                      f"1 ... {MAX_VARIANTS}")),
    (dict(study=f'part = "{WHEEL}"\nsample = {MAX_VARIANTS + 1}'),
     ("study.sample", MAX_VARIANTS + 1, f"must be a whole number of variants within 1 ... {MAX_VARIANTS}")),
    (dict(study=f'part = "{WHEEL}"\nsample = true'),
     ("study.sample", True, f"must be a whole number of variants within 1 ... {MAX_VARIANTS}")),
    (dict(study=f'part = "{WHEEL}"\nsample = 2.0'),
     ("study.sample", 2.0, f"must be a whole number of variants within 1 ... {MAX_VARIANTS}")),
    (dict(study=f'part = "{WHEEL}"\nseed = 1.5'), ("study.seed", 1.5, "must be a whole number")),
    (dict(study=f'part = "{WHEEL}"\nseed = false'), ("study.seed", False, "must be a whole number")),
    (dict(vary=""), ("vary", {}, "must name at least one parameter to vary")),
    (dict(vary="type = [1]"), ("vary.type", [1], "unknown parameter of road_wheel (see `propulsor params "
                                                 "road_wheel`)")),
    (dict(vary="tyre_width_mm = []"), ("vary.tyre_width_mm", [], "must name at least one value")),
    (dict(vary="tyre_width_mm = 70.0"), ("vary.tyre_width_mm", 70.0, "must be a list of values or a range "
                                                                     "{ from = A, to = B, step = S }")),
    (dict(vary="tyre_width_mm = { from = 70.0, to = 90.0, stride = 1.0 }"),
     ("vary.tyre_width_mm.stride", 1.0, "unknown key (from, to, step)")),
    (dict(vary="tyre_width_mm = { from = 70.0, step = 1.0 }"),
     ("vary.tyre_width_mm", {"from": 70.0, "step": 1.0}, "a range needs from, to and step (step only without a "
                                                         "sampler)")),
    (dict(vary="tyre_width_mm = { to = 70.0, step = 1.0 }"),
     ("vary.tyre_width_mm", {"to": 70.0, "step": 1.0}, "a range needs from, to and step (step only without a "
                                                       "sampler)")),
    (dict(vary="tyre_width_mm = { from = 90.0, to = 70.0, step = 1.0 }"),
     ("vary.tyre_width_mm", {"from": 90.0, "to": 70.0, "step": 1.0}, "to must be >= from")),
    (dict(vary="tyre_width_mm = { from = 70.0, to = 90.0, step = -1.0 }"),
     ("vary.tyre_width_mm.step", -1.0, "must be a number > 0")),
    (dict(vary="tyre_width_mm = { from = 70.0, to = 170.0, step = 0.0001 }"),
     ("vary.tyre_width_mm", {"from": 70.0, "to": 170.0, "step": 0.0001}, f"names more than {MAX_VARIANTS} values")),
    (dict(objectives='minimize = "T_at_V_max_C"'),
     ("objectives.minimize", "T_at_V_max_C", "must be a list of names (strings)")),
    (dict(objectives='minimize = [1]'), ("objectives.minimize", [1], "must be a list of names (strings)")),
    (dict(objectives='record = ["nonsense_value"]'),
     ("objectives.record", "nonsense_value", "is not a derived value of a road_wheel manifest")),
    (dict(objectives='require = [3]'),
     ("objectives.require", 3, 'must be strings: "all_checks_passed" or "NAME >= NUMBER"')),
    (dict(objectives='require = ["T_at_V_max_C <= inf"]'),
     ("objectives.require", "T_at_V_max_C <= inf", 'must be "all_checks_passed" or "NAME OP NUMBER" (OP one of >=, '
                                                   '<=, >, <, ==, !=)')),
    (dict(objectives='require = ["T_at_V_max_C <= 1e999"]'),
     ("objectives.require", "T_at_V_max_C <= 1e999", "the bound must be a finite number")),
    (dict(objectives='record = ["T_at_V_max_C"]'),
     ("objectives", {"record": ["T_at_V_max_C"]}, "must name at least one value to minimize or maximize")),
])
def test_each_refusal_in_full(tmp_path, sections, want):
    assert _refused(tmp_path, _text(**sections)) == want


def test_a_whole_parameter_takes_whole_steps_and_ranges(tmp_path):
    s = _load(tmp_path, _text(vary="lightening_holes = { from = 1, to = 3, step = 1 }"))
    assert [v["lightening_holes"] for v in s.variants] == [1, 2, 3] and all(isinstance(v["lightening_holes"], int) for v in s.variants)
    assert _refused(tmp_path, _text(vary="lightening_holes = { from = 1, to = 3, step = 0.5 }")) == (
        "vary.lightening_holes.step", 0.5, "must be a whole number (the parameter is whole)")


def test_a_grid_too_large_is_refused_before_it_is_made(tmp_path):
    big = "tyre_width_mm = { from = 60.0, to = 99.999, step = 0.001 }\nrow_gap_mm = [10.0, 11.0, 12.0]"
    assert _refused(tmp_path, _text(vary=big)) == ("vary", "120000 variants",
                                                   f"a grid of at most {MAX_VARIANTS} variants (or a sampler)")


def test_a_sampler_draws_within_the_ranges_and_from_the_lists(tmp_path):
    text = _text(study=f'part = "{WHEEL}"\nsample = 40\nseed = 7',
                 vary="tyre_width_mm = { from = 70.0, to = 90.0 }\nlightening_holes = { from = 1, to = 3 }\n"
                      "row_gap_mm = [10.0, 12.0]")
    s = _load(tmp_path, text)
    assert 1 < len(s.variants) <= 40
    assert all(70.0 <= v["tyre_width_mm"] <= 90.0 and isinstance(v["tyre_width_mm"], float) for v in s.variants)
    assert {v["lightening_holes"] for v in s.variants} == {1, 2, 3}
    assert {v["row_gap_mm"] for v in s.variants} == {10.0, 12.0}
    assert len({tuple(sorted(v.items())) for v in s.variants}) == len(s.variants)  # each drawn once
    # the same seed draws the same; another seed others
    assert _load(tmp_path, text).variants == s.variants
    assert _load(tmp_path, text.replace("seed = 7", "seed = 8")).variants != s.variants
    # a sampler of one draw of a one-value grid: one variant
    one = _load(tmp_path, _text(study=f'part = "{WHEEL}"\nsample = 5', vary="row_gap_mm = [10.0]"))
    assert one.variants == ({"row_gap_mm": 10.0},)


@pytest.mark.parametrize("text, value, holds", [
    ("a >= 1", 1.0, True), ("a >= 1", 0.9, False), ("a > 1", 1.0, False), ("a > 1", 1.1, True),
    ("a <= 1", 1.0, True), ("a <= 1", 1.1, False), ("a < 1", 1.0, False), ("a < 1", 0.9, True),
    ("a == 1", 1.0, True), ("a == 1", 1.5, False), ("a != 1", 1.5, True), ("a != 1", 1.0, False),
    ("a >= -2.5e-1", -0.25, True), ("a == true", True, True), ("a == false", True, False),
    ("a >= 1", None, False), ("a >= 1", math.nan, False), ("a >= 1", "x", False),
])
def test_requirements_of_each_operator(text, value, holds):
    assert _requirement(text).holds(value) is holds


def test_requirement_text_and_the_checks_pseudo_value():
    r = _requirement("  S_H.min >= 1.2 ")
    assert (r.name, r.op, r.bound, str(r)) == ("S_H.min", ">=", 1.2, "S_H.min >= 1.2")
    a = _requirement(" all_checks_passed ")
    assert a == Requirement(ALL_CHECKS) and str(a) == ALL_CHECKS
    assert a.holds(True) and not a.holds(1) and not a.holds(None)


def test_variant_key_is_the_parameters_the_depth_and_the_version(tmp_path):
    s = _load(tmp_path, _text())
    k = variant_key(s, {"tyre_width_mm": 70.0}, "1.0")
    assert len(k) == 16 and int(k, 16) >= 0
    assert k == variant_key(s, {"tyre_width_mm": 70.0}, "1.0")
    assert k != variant_key(s, {"tyre_width_mm": 90.0}, "1.0")
    assert k != variant_key(s, {"tyre_width_mm": 70.0}, "1.1")


def test_a_study_file_too_large_or_not_text_is_refused(tmp_path):
    p = tmp_path / "big.toml"
    p.write_bytes(b"#" * (MAX_STUDY_BYTES + 1))
    with pytest.raises(InputError) as e:
        load_study(p)
    assert e.value.parameter == "STUDY"
    p.write_bytes(b"[study]\ntitle = \"\xff\"\n")
    with pytest.raises(InputError) as e:
        load_study(p)
    assert e.value.limit.startswith("is not UTF-8") and "at byte 17" in e.value.limit
    with pytest.raises(InputError) as e:
        load_study(tmp_path / "missing.toml")
    assert e.value.parameter == "STUDY"


@pytest.mark.parametrize("sections, want", [
    # a varied value checked as a part file's: its limit with its unit, a choice, a type
    (dict(vary="tyre_width_mm = [70.0, 500.0]"), ("tyre_width_mm", 500.0, "must be <= 400.0 mm")),
    (dict(vary="rows = [1, 3]"), ("rows", 3, "must be one of 1, 2")),
    (dict(vary='tyre_width_mm = ["wide"]'), ("tyre_width_mm", "wide", "must be a number")),
    # every objective name is checked, each list, every name of it (not only the first)
    (dict(objectives='minimize = ["T_at_V_max_C", "nonsense"]'),
     ("objectives.minimize", "nonsense", "is not a derived value of a road_wheel manifest")),
    (dict(objectives='maximize = ["nonsense"]'),
     ("objectives.maximize", "nonsense", "is not a derived value of a road_wheel manifest")),
    (dict(objectives='require = ["all_checks_passed", "nonsense >= 1"]'),
     ("objectives.require", "nonsense", "is not a derived value of a road_wheel manifest")),
    (dict(objectives='require = "nonsense >= 1"'),
     ("objectives.require", "nonsense", "is not a derived value of a road_wheel manifest")),
])
def test_each_refusal_of_a_value_or_name_in_full(tmp_path, sections, want):
    assert _refused(tmp_path, _text(**sections)) == want


def test_a_section_that_is_not_a_table_and_a_file_that_is_not_toml(tmp_path):
    assert _refused(tmp_path, "vary = 3\n" + _text(vary=None)) == ("vary", 3, "must be a table")
    p = tmp_path / "bad.toml"
    p.write_text("[study\n", encoding="utf-8")
    with pytest.raises(InputError) as e:
        load_study(p)
    assert (e.value.parameter, e.value.value) == ("STUDY", str(p)) and "line 1" in e.value.limit
    p.write_text(_text(vary="tyre_width_mm = [[[[[[70.0]]]]]]"), encoding="utf-8")
    with pytest.raises(InputError) as e:
        load_study(p)
    assert (e.value.parameter, e.value.value, e.value.limit) == (
        "STUDY", "<nested more than 4 deep>", "must nest arrays and tables at most 4 deep")
    p.write_text(_text(vary="tyre_width_mm = [[[70.0]]]"), encoding="utf-8")  # 4 deep: read, then refused as a value
    with pytest.raises(InputError) as e:
        load_study(p)
    assert e.value.parameter == "tyre_width_mm"
    p.write_text("[study]\n" + "x = [" * 2000 + "]" * 2000 + "\n", encoding="utf-8")
    with pytest.raises(InputError) as e:
        load_study(p)
    assert (e.value.parameter, e.value.value) == ("STUDY", str(p))
    assert e.value.limit in ("nests arrays or tables too deeply", "must nest arrays and tables at most 4 deep") \
        or "line" in e.value.limit
    with pytest.raises(InputError) as e:
        load_study(tmp_path)  # a folder
    assert (e.value.parameter, e.value.value) == ("STUDY", str(tmp_path)) and e.value.limit


def test_a_study_without_a_seed_draws_as_seed_zero(tmp_path):
    text = _text(study=f'part = "{WHEEL}"\nsample = 6', vary="tyre_width_mm = { from = 70.0, to = 90.0 }")
    assert _load(tmp_path, text).variants == _load(tmp_path, text.replace("sample = 6", "sample = 6\nseed = 0")).variants


def test_the_largest_sample_and_range_are_taken(tmp_path):
    s = _load(tmp_path, _text(study=f'part = "{WHEEL}"\nsample = {MAX_VARIANTS}', vary="rows = [1, 2]"))
    assert len(s.variants) == 2
    s = _load(tmp_path, _text(vary=f"tyre_width_mm = {{ from = 10.0, to = {10.0 + (MAX_VARIANTS - 1) * 0.001!r}, "
                                   "step = 0.001 }"))
    assert len(s.variants) == MAX_VARIANTS


def test_depth_proof_takes_values_the_design_does_not_give(tmp_path):
    # the wheel's mass comes from its solids (a build), not its design: refused at depth design, taken at depth proof
    objectives = 'minimize = ["T_at_V_max_C"]\nrecord = ["mass_wheel_kg"]'
    assert _refused(tmp_path, _text(objectives=objectives)) == (
        "objectives.record", "mass_wheel_kg", "is not computed at depth design for this road_wheel (its design gives "
        "19 values); depth proof or build may give it")
    s = _load(tmp_path, _text(study=f'part = "{WHEEL}"\ndepth = "proof"', objectives=objectives))
    assert s.record == ("mass_wheel_kg",) and s.depth == "proof"


def test_decimals_of_a_number():
    from propulsor.study.spec import _decimals

    assert [_decimals(x) for x in (0.25, 3, 70.1, 1e-05, 1.5e20, 2.0)] == [2, 1, 1, 12, 12, 1]


def test_the_variant_key_is_stable():
    """--resume finds its rows by this key: a change of its recipe makes every finished variant run again."""
    s = Study(Path("s.toml"), "t", WHEEL, "road_wheel", {"rows": 2}, "design", ("x",), (), (), (), (), ())
    import hashlib
    import json

    want = hashlib.sha256(json.dumps({"type": "road_wheel", "base": {"rows": 2}, "values": {"x": 1.5},
                                      "depth": "design", "version": "0.1.0"}, sort_keys=True).encode()).hexdigest()
    assert variant_key(s, {"x": 1.5}, "0.1.0") == want[:16]


def test_a_mistyped_name_is_answered_with_the_closest_ones(tmp_path):
    with pytest.raises(InputError) as e:
        _load(tmp_path, _text(objectives='minimize = ["T_at_V_max"]'))
    assert (e.value.parameter, e.value.hint) == ("objectives.minimize", "did you mean T_at_V_max_C or n_at_V_max_rpm or heat_at_V_max_Q_W?")
    with pytest.raises(InputError) as e:
        _load(tmp_path, _text(vary="tyre_widht_mm = [70.0]"))
    assert (e.value.parameter, e.value.hint) == ("vary.tyre_widht_mm", "did you mean tyre_width_mm or tyre_radius_mm or tyre_thickness_mm?")
    with pytest.raises(InputError) as e:
        _load(tmp_path, _text(objectives='minimize = ["qqqqqqqq"]'))
    assert e.value.hint == ""


def test_a_list_parameter_varies_by_whole_lists(tmp_path):
    """A list parameter's values are lists (was a TypeError traceback: a list cannot be a dict key)."""
    pair = ROOT / "parts" / "ncg_fourier_3lobe.toml"
    st = _load(tmp_path, f'[study]\npart = "{pair}"\ndepth = "design"\n[vary]\nfourier_sin = [[0.03, 0.006], '
                         '[0.05, 0.006], [0.03, 0.006]]\n[objectives]\nminimize = ["center_distance_mm"]\n')
    assert [v["fourier_sin"] for v in st.variants] == [[0.03, 0.006], [0.05, 0.006]]
