"""A proof-depth variant runs the other tooth method's design and proof only when the study reads one of its
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
