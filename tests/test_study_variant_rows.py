"""A study variant's row.  A proof-depth variant runs the other tooth method's design and proof only when the study reads one of its
``compare_`` values (issue 40: the comparison only when asked); at build depth, and where the study reads one, the
part file's switch stands."""

from __future__ import annotations

from propulsor.params import load_params
from propulsor.parts import get_part_type
from propulsor.study.evaluate import ONLY_WHEN_READ, asked


def _pair(**kw):
    pt = get_part_type("noncircular_pair")
    return load_params(pt.params_cls, {"compare_methods": True, **kw})


def test_the_comparison_is_off_at_proof_depth_when_no_compare_value_is_read():
    p = _pair()
    q = asked("noncircular_pair", p, "proof", ("speed_ripple", "center_distance_mm"))
    assert q.compare_methods is False
    # nothing else changes
    assert {k: v for k, v in vars(q).items() if k != "compare_methods"} == \
        {k: v for k, v in vars(p).items() if k != "compare_methods"}


def test_the_comparison_stays_where_it_is_read_at_build_depth_or_off_already():
    p = _pair()
    assert asked("noncircular_pair", p, "proof", ("speed_ripple", "compare_sectors_speed_ripple")) is p
    assert asked("noncircular_pair", p, "build", ("speed_ripple",)) is p
    assert asked("noncircular_pair", p, "design", ("speed_ripple",)) is p
    off = _pair(compare_methods=False)
    assert asked("noncircular_pair", off, "proof", ("compare_sectors_te_pp_rad",)) is off
    assert asked("planetary_final_drive", p, "proof", ()) is p
    assert ONLY_WHEN_READ["noncircular_pair"] == ("compare_methods", "compare_")


def test_a_row_refused_for_a_default_says_it_is_the_default():
    """A variant refused for a value neither the part file nor the study writes: the row's reason says that it is the
    part type's default, as the dry run does (issue 39's trial: the study's rows left it out)."""
    from propulsor.study.evaluate import evaluate

    base = {"law": "elliptical", "eccentricity": 0.2, "compare_methods": False}
    row = evaluate("noncircular_pair", base, None, {"driver_turns": 3}, "design", ("center_distance_mm",))
    assert row["status"] == "input error"
    assert row["reason"] == ("driven_teeth = 80: must be a multiple of driver_turns = 3 (whole driver teeth) (nearest "
                             "valid: 78, 81; driven_teeth is not in the part file: 80 is its default)")
    written = evaluate("noncircular_pair", {**base, "driven_teeth": 80}, None, {"driver_turns": 3}, "design",
                       ("center_distance_mm",))
    assert written["reason"] == ("driven_teeth = 80: must be a multiple of driver_turns = 3 (whole driver teeth) "
                                 "(nearest valid: 78, 81)")
