"""The study's tables and picture (study/results.py) with the whole of each answer: the columns, every kind of cell,
each requirement's failure text, front.csv in full, and where plot_front draws each variant (the page links the
points).  The cases `make mutation MODULE=study` found no test for (mutation/README.md)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from propulsor.study.results import (FRONT, FRONT_PNG, TAIL, _plain, cell, columns, plot_front, ranked,
                                     requirement_failure, write_front)
from propulsor.study.spec import ALL_CHECKS, Requirement, Study

WHEEL = Path(__file__).resolve().parents[1] / "parts" / "road_wheel.toml"


def _study(minimize=(), maximize=(), require=(), record=(), varied=("x",), title="t", depth="design"):
    return Study(Path("s.toml"), title, WHEEL, "road_wheel", {}, depth, tuple(varied), (), tuple(minimize),
                 tuple(maximize), tuple(require), tuple(record))


def test_columns_in_order():
    s = _study(minimize=["a"], maximize=["b"], require=[Requirement("c", ">=", 1.0), Requirement(ALL_CHECKS)],
               record=["d", "a"], varied=("x", "y"))
    assert columns(s) == ["variant", "key", "x", "y", "a", "b", "c", "d", *TAIL]
    assert TAIL == ("all_checks_passed", "status", "reason", "failed_checks", "seconds", "worker")


@pytest.mark.parametrize("value, text", [
    (None, ""), (True, "true"), (False, "false"), (0.1, "0.1"), (1 / 3, "0.3333333333333333"), (2.0, "2.0"),
    (7, "7"), ("a, b", "a, b"), (math.inf, "inf"),
])
def test_cell_writes_each_kind(value, text):
    assert cell(value) == text


def test_requirement_failure_names_the_first_unmet_requirement():
    req = (Requirement(ALL_CHECKS), Requirement("S_H", ">=", 1.2), Requirement("d_mm", "<", 100.0))
    s = _study(minimize=["d_mm"], require=req, depth="proof")
    ok = {"all_checks_passed": True, "S_H": 1.3, "d_mm": 90.0}
    assert requirement_failure(s, ok) == ""
    assert requirement_failure(s, {**ok, "S_H": 1.1}) == "S_H >= 1.2 does not hold (S_H = 1.1)"
    assert requirement_failure(s, {**ok, "S_H": None}) == "S_H >= 1.2 does not hold (S_H = none)"
    assert requirement_failure(s, {**ok, "d_mm": 100.0}) == "d_mm < 100.0 does not hold (d_mm = 100.0)"
    assert requirement_failure(s, {**ok, "all_checks_passed": False, "failed_checks": "mesh.genus"}) == \
        "all_checks_passed: failed mesh.genus"
    assert requirement_failure(s, {**ok, "all_checks_passed": False}) == "all_checks_passed: failed ?"
    assert requirement_failure(s, {**ok, "all_checks_passed": None}) == (
        "all_checks_passed: no check runs at depth proof for this part (depth proof runs the proofs' checks, "
        "build all)")
    # the requirement's own name is read, not the pseudo-value's
    assert requirement_failure(_study(require=(Requirement("S_H", ">=", 1.2),)),
                               {"S_H": 1.3, "all_checks_passed": False}) == ""


def _rows(*objs, names=("a", "b"), status="ok"):
    return [{"variant": k, "key": f"k{k}", "x": 0.5 * k, **dict(zip(names, o)), "status": status}
            for k, o in enumerate(objs, 1)]


def test_front_csv_in_full(tmp_path):
    s = _study(minimize=["a"], maximize=["b"], record=["c"])
    rows = _rows((1.0, 2.0), (2.0, 3.0), (3.0, 1.0))
    rows[0].update(c=True, all_checks_passed=True, seconds=1.25, worker="w1")
    rank = ranked(s, rows)
    write_front(tmp_path, s, rank)
    with open(tmp_path / FRONT, newline="", encoding="utf-8") as f:
        got = list(csv.reader(f))
    assert got[0] == ["rank", "pareto_layer", "variant", "key", "x", "a", "b", "c", *TAIL]
    assert got[1] == ["1", "1", "1", "k1", "0.5", "1.0", "2.0", "true", "true", "ok", "", "", "1.25", "w1"]
    assert [r[:3] for r in got[1:]] == [["1", "1", "1"], ["2", "1", "2"], ["3", "2", "3"]]


def test_rows_not_ok_or_without_a_number_are_not_ranked():
    s = _study(minimize=["a"])
    rows = _rows((1.0,), (2.0,), (0.5,), (0.7,), names=("a",))
    rows[2]["status"] = "failed"
    rows[3]["a"] = True  # a flag is not a number
    assert [(layer, r["variant"]) for layer, r in ranked(s, rows)] == [(1, 1), (2, 2)]
    rows[1]["a"] = "2.0"  # nor is text
    assert [(layer, r["variant"]) for layer, r in ranked(s, rows)] == [(1, 1)]


def _points(tmp_path, study, rows):
    rank = ranked(study, rows)
    pts = plot_front(tmp_path, study, rows, rank)
    assert (tmp_path / FRONT_PNG).stat().st_size > 1000
    return {v: (x, y) for v, x, y in pts}, rank


def test_plot_front_draws_each_variant_where_its_values_are(tmp_path):
    s = _study(minimize=["a", "b"], title="T $x$")
    rows = _rows((1.0, 4.0), (2.0, 2.0), (4.0, 1.0), (3.0, 3.0), (2.5, 5.0))
    rows[4]["status"] = "rejected"
    pts, rank = _points(tmp_path, s, rows)
    assert sorted(pts) == [1, 2, 3, 4, 5]  # the front, the one behind it and the refused one
    # pixels: x grows with a, y (from the top) falls as b grows
    assert pts[1][0] < pts[2][0] < pts[4][0] < pts[3][0]
    assert pts[5][1] < pts[1][1] < pts[4][1] < pts[2][1] < pts[3][1]
    # equal steps in a give equal steps in pixels (a linear axis)
    assert abs((pts[2][0] - pts[1][0]) - (pts[4][0] - pts[2][0])) <= 1
    assert all(0 <= x <= 700 and 0 <= y <= 500 for x, y in pts.values())


def test_plot_front_of_one_objective_is_against_the_variant(tmp_path):
    s = _study(maximize=["a"])
    rows = _rows((1.0,), (3.0,), (2.0,), names=("a",))
    pts, _ = _points(tmp_path, s, rows)
    assert pts[1][0] < pts[2][0] < pts[3][0]           # x: the variant number
    assert pts[2][1] < pts[3][1] < pts[1][1]           # y: a, larger higher up
    assert abs((pts[2][0] - pts[1][0]) - (pts[3][0] - pts[2][0])) <= 1


def test_plot_front_with_nothing_ranked_still_draws(tmp_path):
    s = _study(minimize=["a", "b"])
    rows = _rows((1.0, 2.0), names=("a", "b"), status="failed")
    assert plot_front(tmp_path, s, rows, ranked(s, rows)) == []
    assert (tmp_path / FRONT_PNG).exists()


def test_plain_text_for_the_picture():
    assert _plain("a $b$\tc\n") == r"a \$b\$ c "
