"""The scale of a print kit (printing/scale.py) pinned where a one-line change went unnoticed: the
edges of the bed (a piece exactly as high as the printable height, a non-square bed either way round),
the piece each message names, the reason of a requested scale and the suggested scale."""

from __future__ import annotations

import pytest

from propulsor.errors import InputError
from propulsor.printing.scale import check_printable, choose_scale, fits

MK4 = (250.0, 210.0, 220.0)  # not square


def test_a_piece_exactly_at_the_bed_s_limits_fits():
    assert fits((250.0, 210.0, 220.0), MK4)
    assert not fits((250.0, 210.0, 220.001), MK4)


def test_a_non_square_bed_either_way_round():
    assert fits((240.0, 205.0, 10.0), MK4)      # as it lies
    assert fits((205.0, 240.0, 10.0), MK4)      # turned by 90 degrees
    assert not fits((240.0, 215.0, 10.0), MK4)  # 215 > 210 as it lies, 240 > 210 turned
    assert not fits((215.0, 240.0, 10.0), MK4)


def test_the_automatic_scale_names_the_piece_that_decided_it():
    pieces = {"small": (100.0, 100.0, 10.0), "wheel": (400.0, 380.0, 20.0), "arm": (300.0, 100.0, 10.0)}
    choice = choose_scale(pieces, MK4)
    assert choice.S == 2.0 and choice.label == "1:2"
    assert choice.reason.startswith("wheel is 400.0 × 380.0 × 20.0 mm; at 1:1.5 it does not fit")
    assert choose_scale({"small": (100.0, 100.0, 10.0)}, MK4).reason == "every piece fits the bed at full size"


def test_a_requested_scale_says_so_or_names_the_piece_that_does_not_fit():
    pieces = {"small": (100.0, 100.0, 10.0), "wheel": (400.0, 380.0, 20.0)}
    assert choose_scale(pieces, MK4, requested=2.5).reason == "as requested"
    with pytest.raises(InputError, match=r"wheel \(266\.7 × 253\.3 × 13\.3 mm\) does not fit"):
        choose_scale(pieces, MK4, requested=1.5)
    with pytest.raises(InputError, match="huge does not fit the bed even at 1:50"):
        choose_scale({"small": (1.0, 1.0, 1.0), "huge": (1e6, 1.0, 1.0)}, MK4)


def test_check_printable_suggests_the_scale_that_works():
    with pytest.raises(InputError, match=r"scaled module 0\.5 mm is below the printable 1 mm; print at 1:2\.5 or larger"):
        check_printable(5.0, 2.5, 1.0)
    check_printable(2.5, 2.5, 1.0)  # exactly the printable module


def test_check_printable_default_least_feature_is_two_line_widths():
    check_printable(1.0, None, 1.0, thinnest={"tip land": 0.8})
    with pytest.raises(InputError, match=r"tip land is 0\.79 mm at this scale, below two line widths \(0\.8 mm\)"):
        check_printable(1.0, None, 1.0, thinnest={"tip land": 0.79})


def test_the_automatic_scale_keeps_the_layout_s_margins():
    # a ring 690.4 mm across: 172.6 mm at 1:4 fits a 180 mm bed, not the 170 mm within its 5 mm margins
    ring = {"ring": (690.4, 690.4, 80.0)}
    bed = (180.0, 180.0, 180.0)
    assert choose_scale(ring, bed).S == 4.0
    c = choose_scale(ring, bed, margin=5.0)
    assert c.S == 5.0 and "at 1:4 it does not fit the 180 × 180 × 180 mm bed with 5 mm margins" in c.reason
    with pytest.raises(InputError, match=r"with 5 mm margins; every piece fits at 1:5"):
        choose_scale(ring, bed, requested=4.0, margin=5.0)


def test_refusals_name_the_standard_scale_that_works():
    from propulsor.printing.scale import larger

    # module 2.2 mm, printable 1 mm: 1:2.2 is no standard scale, 1:2 is
    with pytest.raises(InputError, match=r"print at 1:2 or larger"):
        check_printable(3.0, 2.2, 1.0)
    # a 2.2 mm web is 0.55 mm at 1:4; two line widths (0.8 mm) at 1:2.75, so 1:2.5
    with pytest.raises(InputError, match=r"web is 0\.55 mm at this scale.*it prints at 1:2\.5 or larger"):
        check_printable(4.0, None, 1.0, thinnest={"web": 2.2})
    assert larger(2.5) == "print at 1:2 (a larger bed)" and larger(1.5) == "print at 1:1 (a larger bed)"
