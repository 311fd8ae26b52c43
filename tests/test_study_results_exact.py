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


def _drawn(tmp_path, monkeypatch, study, rows):
    """plot_front's figure as drawn (its closing kept back), and the points it returns."""
    import matplotlib.pyplot as plt

    kept = []
    monkeypatch.setattr(plt, "close", lambda fig: kept.append(fig))
    pts = plot_front(tmp_path, study, rows, ranked(study, rows))
    assert len(kept) == 1
    return kept[0], pts


def test_the_picture_draws_what_it_says(tmp_path, monkeypatch):
    from matplotlib.colors import to_rgba

    s = _study(minimize=["a"], maximize=["b"], title="Wheel $x$")
    rows = _rows((1.0, 4.0), (2.0, 5.0), (4.0, 6.0), (3.0, 3.0), (2.5, 5.0))
    rows[4]["status"] = "rejected"
    fig, pts = _drawn(tmp_path, monkeypatch, s, rows)
    assert tuple(fig.get_size_inches()) == (7.0, 5.0) and fig.dpi == 100
    ax = fig.axes[0]
    assert ax.get_xlabel() == "a (min)" and ax.get_ylabel() == "b (max)"
    assert ax.get_title() == r"Wheel \$x\$: 4 of 5 variants meet the requirements"
    assert ax.title.get_fontsize() == 9
    refused, others = ax.collections
    assert refused.get_offsets().tolist() == [[2.5, 5.0]] and refused.get_label() == "refused by a requirement"
    assert tuple(refused.get_facecolor()[0]) == to_rgba("0.6") or tuple(refused.get_edgecolor()[0]) == to_rgba("0.6")
    assert others.get_offsets().tolist() == [[3.0, 3.0]] and others.get_label() == "meets the requirements"
    assert tuple(others.get_facecolor()[0]) == to_rgba("0.45") and others.get_sizes().tolist() == [18.0]
    # the front joined in the order of its first objective, red, round markers of 5 pt
    (line,) = ax.lines
    assert line.get_xdata().tolist() == [1.0, 2.0, 4.0] and line.get_ydata().tolist() == [4.0, 5.0, 6.0]
    assert line.get_label() == "Pareto front" and line.get_color() == "tab:red"
    assert (line.get_marker(), line.get_linestyle(), line.get_markersize()) == ("o", "-", 5.0)
    # each front variant named beside its point, 3 pt right and up, in 7 pt
    notes = [(t.get_text(), t.xy, t.get_fontsize(), t.xyann, t.anncoords) for t in ax.texts]
    assert notes == [("1", (1.0, 4.0), 7.0, (3, 3), "offset points"), ("2", (2.0, 5.0), 7.0, (3, 3), "offset points"),
                     ("3", (4.0, 6.0), 7.0, (3, 3), "offset points")]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "refused by a requirement", "meets the requirements", "Pareto front"]
    assert ax.get_legend().get_texts()[0].get_fontsize() == 8
    assert all(g.get_visible() for g in ax.get_xgridlines()) and ax.get_xgridlines()[0].get_alpha() == 0.3
    assert sorted(v for v, *_ in pts) == [1, 2, 3, 4, 5]
    import matplotlib
    assert matplotlib.get_backend().lower() == "agg"


def test_the_picture_of_three_objectives_and_of_one(tmp_path, monkeypatch):
    s3 = _study(minimize=["a", "b", "c"])
    rows = _rows((1.0, 2.0, 3.0), (2.0, 1.0, 3.0), (3.0, 3.0, "n/a"), names=("a", "b", "c"))
    rows[2]["status"] = "rejected"  # refused: drawn by its first two objectives, whatever the third is
    fig, pts = _drawn(tmp_path, monkeypatch, s3, rows)
    ax = fig.axes[0]
    assert ax.get_title() == "t: 2 of 3 variants meet the requirements; front over a, b, c"
    assert ax.get_xlabel() == "a (min)" and ax.get_ylabel() == "b (min)"
    assert ax.collections[0].get_offsets().tolist() == [[3.0, 3.0]]
    s1 = _study(maximize=["a"])
    fig, _ = _drawn(tmp_path, monkeypatch, s1, _rows((1.0,), (3.0,), names=("a",)))
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("variant", "a (max)")
    assert ax.get_title() == "t: 2 of 2 variants meet the requirements"
    fig, _ = _drawn(tmp_path, monkeypatch, _study(minimize=["a"]), _rows((1.0,), (3.0,), names=("a",)))
    assert fig.axes[0].get_ylabel() == "a (min)"
    # nothing to draw: no legend
    fig, _ = _drawn(tmp_path, monkeypatch, s3, _rows((1.0, 2.0, 3.0), names=("a", "b", "c"), status="failed"))
    assert fig.axes[0].get_legend() is None
    # only refused variants: a legend all the same
    fig, _ = _drawn(tmp_path, monkeypatch, s3, _rows((1.0, 2.0, 3.0), names=("a", "b", "c"), status="rejected"))
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == ["refused by a requirement"]


def test_points_off_the_axes_are_not_linked(tmp_path, monkeypatch):
    s = _study(minimize=["a", "b"])
    rows = _rows((1.0, 2.0), (2.0, 1.0), (3.0, math.inf))
    rows[2]["status"] = "rejected"
    fig, pts = _drawn(tmp_path, monkeypatch, s, rows)
    assert sorted(v for v, *_ in pts) == [1, 2]


def test_plain_keeps_the_space_and_what_follows():
    assert _plain(" ! ") == " ! "
