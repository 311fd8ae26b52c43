"""The study file's ranges, requirements and limits, and the ranking / front.csv of results.py, at the cases
the mutation run of 2026-11-28 found untested (TEST-GAPS.md Q*, S*)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from propulsor.errors import InputError
from propulsor.study.results import FRONT, ranked, write_front
from propulsor.study.spec import MAX_VARIANTS, Requirement, Study, _requirement, load_study

ROOT = Path(__file__).resolve().parents[1]
WHEEL = ROOT / "parts" / "road_wheel.toml"

STUDY = f"""
[study]
part = "{WHEEL}"
depth = "design"
SAMPLE

[vary]
VARY

[objectives]
minimize = ["T_at_V_max_C"]
"""


def _load(tmp_path, vary: str, sample: str = ""):
    p = tmp_path / "s.toml"
    p.write_text(STUDY.replace("VARY", vary).replace("SAMPLE", sample), encoding="utf-8")
    return load_study(p)


def _values(tmp_path, spec: str) -> list:
    return [v["row_gap_mm"] for v in _load(tmp_path, f"row_gap_mm = {spec}").variants]


# ---- spec.py ---------------------------------------------------------------------------------------------------

def test_requirement_not_equal_never_holds_for_nan():  # Q1
    r = _requirement("T_at_V_max_C != 100")
    assert r.holds(99.0) and not r.holds(100.0)
    assert not r.holds(math.nan)  # a value not computed meets no requirement


def test_requirement_at_least_holds_at_its_bound():  # Q2
    r = _requirement("strength_S_H >= 1.0")
    assert r.holds(1.0) and r.holds(1.2) and not r.holds(0.999)


def test_range_of_one_value(tmp_path):  # Q3
    assert _values(tmp_path, "{ from = 50.0, to = 50.0, step = 10.0 }") == [50.0]


def test_range_step_zero_is_refused(tmp_path):  # Q4
    with pytest.raises(InputError, match=r"vary\.row_gap_mm\.step.*must be a number > 0"):
        _values(tmp_path, "{ from = 0.0, to = 0.3, step = 0.0 }")


def test_range_whose_quotient_rounds_down_keeps_its_last_value(tmp_path):  # Q5
    assert 0.3 / 0.1 < 3  # 2.9999999999999996: the count must not lose the end
    assert _values(tmp_path, "{ from = 0.0, to = 0.3, step = 0.1 }") == [0.0, 0.1, 0.2, 0.3]


def test_range_keeps_the_most_decimals_written(tmp_path):  # Q6
    assert _values(tmp_path, "{ from = 0.25, to = 1.0, step = 0.25 }") == [0.25, 0.5, 0.75, 1.0]


def test_requirement_of_a_true_false_bound():  # Q7
    r = _requirement("all_checks_passed == true")
    assert r.bound is True and r.holds(True) and not r.holds(False)
    r = _requirement("x == false")
    assert r.bound is False and r.holds(False) and not r.holds(True)


def test_sample_of_one_variant(tmp_path):  # Q8
    s = _load(tmp_path, "row_gap_mm = { from = 0.0, to = 100.0 }", "sample = 1")
    assert len(s.variants) == 1 and 0.0 <= s.variants[0]["row_gap_mm"] <= 100.0


def test_grid_of_exactly_max_variants_is_accepted_and_more_refused(tmp_path):  # Q9
    assert MAX_VARIANTS == 100 * 1000
    wide = "tyre_width_mm = { from = 10.0, to = 109.0, step = 1.0 }\n"  # 100 values
    s = _load(tmp_path, wide + "row_gap_mm = { from = 0.0, to = 99.9, step = 0.1 }")  # 1000 values
    assert len(s.variants) == MAX_VARIANTS
    with pytest.raises(InputError, match=r"^vary = '100100 variants'"):
        _load(tmp_path, wide + "row_gap_mm = { from = 0.0, to = 100.0, step = 0.1 }")  # 1001 values


# ---- results.py ------------------------------------------------------------------------------------------------

def _study(minimize=(), maximize=()):
    return Study(Path("s.toml"), "t", WHEEL, "road_wheel", {}, "design", ("x",), (), tuple(minimize),
                 tuple(maximize), (), ())


def _rows(*objs, names=("a", "b")):
    return [{"variant": k, "key": f"k{k}", "x": 1.0, **dict(zip(names, o)), "status": "ok"}
            for k, o in enumerate(objs, 1)]


def _order(rank):
    return [(layer, r["variant"]) for layer, r in rank]


def test_maximize_ranks_the_larger_value_first():  # S1
    rows = _rows((1.0,), (3.0,), (2.0,), names=("a",))
    assert _order(ranked(_study(maximize=["a"]), rows)) == [(1, 2), (2, 3), (3, 1)]
    assert _order(ranked(_study(minimize=["a"]), rows)) == [(1, 1), (2, 3), (3, 2)]


def test_row_with_a_nan_or_inf_objective_is_left_out():  # S2
    rows = _rows((1.0, 5.0), (math.nan, 1.0), (2.0, math.inf), (3.0, 4.0))
    assert _order(ranked(_study(minimize=["a", "b"]), rows)) == [(1, 1), (1, 4)]


def test_row_tied_in_one_objective_and_worse_in_the_other_is_dominated():  # S3, S5
    # (1, 2) is at least as good as (1, 3) in both and better in b: (1, 3) is in the second layer
    rows = _rows((1.0, 3.0), (1.0, 2.0))
    assert _order(ranked(_study(minimize=["a", "b"]), rows)) == [(1, 2), (2, 1)]


def test_a_layer_is_ordered_by_the_first_objective_not_the_variant(tmp_path):  # S4, S8
    # a trade-off of three (none dominates another) and one dominated by all: variant numbers against a's order
    rows = _rows((3.0, 1.0), (2.0, 2.0), (1.0, 3.0), (4.0, 4.0))
    study = _study(minimize=["a", "b"])
    rank = ranked(study, rows)
    assert _order(rank) == [(1, 3), (1, 2), (1, 1), (2, 4)]
    write_front(tmp_path, study, rank)
    with open(tmp_path / FRONT, newline="", encoding="utf-8") as f:
        got = [(r["rank"], r["pareto_layer"], r["variant"], r["a"]) for r in csv.DictReader(f)]
    assert got == [("1", "1", "3", "1.0"), ("2", "1", "2", "2.0"), ("3", "1", "1", "3.0"), ("4", "2", "4", "4.0")]
