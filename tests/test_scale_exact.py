"""The kit's scale (printing/scale.py) at its edges, with the whole of each answer: a piece exactly as large as the
bed either way round, margins on a bed that is not square, every refusal's parameter, value and text.  The cases
`make mutation MODULE=printing` found no test for (mutation/README.md)."""

from __future__ import annotations

import pytest

from propulsor.errors import InputError
from propulsor.printing.scale import (STANDARD_SCALES, ScaleChoice, check_printable, choose_scale, fits, larger,
                                      smallest_fitting)

BED = (250.0, 210.0, 220.0)  # x, y, z: not square, and z the largest


@pytest.mark.parametrize("extents, ok", [
    ((250.0, 210.0, 220.0), True),    # exactly the bed
    ((210.0, 250.0, 220.0), True),    # exactly the bed turned by 90 degrees
    ((250.0, 210.0, 220.01), False),
    ((250.01, 210.0, 1.0), False),
    ((210.0, 250.01, 1.0), False),
    ((211.0, 211.0, 1.0), False),     # neither way round
])
def test_fits_at_the_bed_exactly(extents, ok):
    assert fits(extents, BED) is ok


def test_margins_come_off_each_side_of_each_edge():
    # usable 240 x 200 with 5 mm margins: a 240 x 200 piece fits either way, 241 does not
    assert choose_scale({"p": (240.0, 200.0, 10.0)}, BED, margin=5.0).S == 1.0
    assert choose_scale({"p": (200.0, 240.0, 10.0)}, BED, margin=5.0).S == 1.0
    assert choose_scale({"p": (240.0, 200.0, 220.0)}, BED, margin=5.0).S == 1.0  # z keeps the bed's height
    assert choose_scale({"p": (241.0, 200.0, 10.0)}, BED, margin=5.0).S == 1.5
    assert choose_scale({"p": (240.0, 201.0, 10.0)}, BED, margin=5.0).S == 1.5
    assert smallest_fitting((240.0, 200.0, 10.0), BED, 5.0) == 1.0
    assert smallest_fitting((241.0, 200.0, 10.0), BED, 5.0) == 1.5
    assert smallest_fitting((480.0, 400.0, 10.0), BED, 5.0) == 2.0
    assert smallest_fitting((1e6, 1.0, 1.0), BED, 5.0) is None


def test_the_automatic_choice_names_the_piece_that_decided():
    pieces = {"hub": (100.0, 100.0, 30.0), "wheel": (300.0, 150.0, 20.0), "arm": (260.0, 40.0, 10.0)}
    c = choose_scale(pieces, BED, margin=5.0)
    assert c == ScaleChoice(1.5, "wheel is 300.0 × 150.0 × 20.0 mm; at 1:1 it does not fit the 250 × 210 × 220 mm "
                                 "bed with 5 mm margins, at 1:1.5 it does")
    assert c.label == "1:1.5"
    assert choose_scale({"hub": (100.0, 100.0, 30.0)}, BED) == ScaleChoice(
        1.0, "every piece fits the bed at full size")
    # no margin: the bed is named without one
    assert choose_scale({"w": (600.0, 100.0, 1.0)}, BED).reason.endswith(
        "not fit the 250 × 210 × 220 mm bed, at 1:2.5 it does")


def test_a_requested_scale_is_kept_or_refused_with_the_scale_that_works():
    pieces = {"hub": (100.0, 100.0, 30.0), "wheel": (300.0, 150.0, 20.0)}
    assert choose_scale(pieces, BED, requested=2.0) == ScaleChoice(2.0, "as requested")
    with pytest.raises(InputError) as e:
        choose_scale(pieces, BED, requested=1.0, margin=5.0)
    assert (e.value.parameter, e.value.value) == ("--scale", "1:1")
    assert e.value.limit == ("wheel (300.0 × 150.0 × 20.0 mm) does not fit the 250 × 210 × 220 mm bed with 5 mm "
                             "margins; every piece fits at 1:1.5")
    # a piece too large at every standard scale: the largest reduction is named
    with pytest.raises(InputError) as e:
        choose_scale({"hub": (10.0, 10.0, 1.0), "rail": (1e5, 1.0, 1.0)}, BED, requested=3.0)
    assert e.value.limit.endswith("every piece fits at 1:50")


def test_nothing_fits_even_at_the_largest_reduction():
    with pytest.raises(InputError) as e:
        choose_scale({"hub": (10.0, 10.0, 1.0), "rail": (1e5, 1.0, 1.0)}, BED)
    assert (e.value.parameter, e.value.value, e.value.limit) == (
        "--scale", "auto", "rail does not fit the bed even at 1:50; choose a larger printer")


def test_larger_names_the_next_larger_standard_scale():
    assert larger(2.5) == "print at 1:2 (a larger bed)"
    assert larger(1.5) == "print at 1:1 (a larger bed)"
    assert larger(1.0) == "it is too small even at full size"


def test_a_module_too_small_at_the_scale_is_refused_in_full():
    with pytest.raises(InputError) as e:
        check_printable(4.0, 3.0, 1.0)
    assert (e.value.parameter, e.value.value) == ("--scale", "1:4")
    assert e.value.limit == ("the scaled module 0.75 mm is below the printable 1 mm; print at 1:3 or larger "
                             "(a larger printer)")
    # at exactly the least module it prints (3 / 3 = 1 mm), and 1:3 is the scale named for a limit of exactly 3
    check_printable(3.0, 3.0, 1.0)
    # the automatic choice is named: the bed is what is too small
    auto = ScaleChoice(4.0, "wheel is 900.0 × 150.0 × 20.0 mm; at 1:3 it does not fit the bed, at 1:4 it does")
    with pytest.raises(InputError) as e:
        check_printable(4.0, 3.0, 1.0, choice=auto)
    assert e.value.limit.endswith("(a larger printer) — the bed is too small: " + auto.reason)
    with pytest.raises(InputError) as e:
        check_printable(4.0, 3.0, 1.0, choice=ScaleChoice(4.0, "as requested"))
    assert e.value.limit.endswith("(a larger printer)")
    # below the least module even at full size
    with pytest.raises(InputError) as e:
        check_printable(1.0, 0.5, 1.0)
    assert "print at full size or larger" in e.value.limit


def test_a_feature_too_thin_at_the_scale_is_refused_in_full():
    check_printable(2.0, None, 1.0, {"tip land": 1.6}, 0.8)  # exactly two line widths
    with pytest.raises(InputError) as e:
        check_printable(2.5, None, 1.0, {"web": 5.0, "tip land": 1.6}, 0.8)
    assert (e.value.parameter, e.value.value) == ("--scale", "1:2.5")
    assert e.value.limit == ("tip land is 0.64 mm at this scale, below two line widths (0.8 mm); it prints at 1:2 "
                             "or larger (a larger printer), or thicken it")


def test_the_standard_series():
    assert STANDARD_SCALES[0] == 1.0 and STANDARD_SCALES[-1] == 50.0
    assert list(STANDARD_SCALES) == sorted(STANDARD_SCALES)


def test_edges_of_the_search_name_the_right_piece_and_scale():
    # the piece that fits at no standard scale is named, not the first one too large at a smaller reduction
    with pytest.raises(InputError) as e:
        choose_scale({"beam": (11000.0, 1.0, 1.0), "rail": (1e5, 1.0, 1.0)}, BED)
    assert e.value.limit.startswith("rail does not fit")
    # y is the edge that decides, with margins; no margin unless one is given
    assert smallest_fitting((230.0, 201.0, 10.0), BED, 5.0) == 1.5
    assert smallest_fitting((250.0, 210.0, 10.0), BED) == 1.0
    # the largest scale named for a module is module / least module (3 / 0.8 = 3.75: 1:3)
    with pytest.raises(InputError) as e:
        check_printable(4.0, 3.0, 0.8)
    assert "print at 1:3 or larger" in e.value.limit


def test_a_bed_too_small_for_the_printable_module_is_refused_as_the_bed_with_the_least_bed_that_prints_it():
    """The scale the bed forces makes the module unprintable: the bed is refused (the user never gave a scale), with
    the least square bed that prints the kit at the smallest reduction the module allows — and that bed does."""
    from propulsor.printing.scale import least_bed

    pieces = {"wheel": (120.0, 110.0, 8.0), "pinion": (40.0, 40.0, 8.0)}
    bed = (50.0, 50.0, 50.0)
    choice = choose_scale(pieces, bed, margin=8.0)
    assert choice.S == 4.0  # 120 / 4 = 30 <= 50 - 16 = 34; at 1:3, 40 > 34
    with pytest.raises(InputError) as e:
        check_printable(choice.S, 2.5, 1.0, choice=choice)
    assert (e.value.parameter, e.value.value) == ("--bed", "50x50x50")
    assert e.value.limit == ("too small for this kit: " + choice.reason + "; at 1:4 the module would be 0.625 mm, "
                             "below the printable 1 mm")
    assert e.value.hint == "a bed of at least 72 x 72 x 4 mm prints it at 1:2.5 (module 1 mm): --bed 72x72x50, or a " \
                           "larger printer"
    # the pieces at 1:2.5 need 48 + 16 mm; the clearance coupon's 56 mm bar (printed at full size) 72
    assert least_bed(pieces, 2.5, 8.0) == (72.0, 72.0, 3.2)
    # that bed prints it: the scale chosen there is 1:2.5 and its module is printable
    there = choose_scale(pieces, (72.0, 72.0, 50.0), margin=8.0)
    assert there.S == 2.5
    check_printable(there.S, 2.5, 1.0, choice=there)
    # a requested scale is refused as the scale, as before
    with pytest.raises(InputError) as e:
        check_printable(4.0, 2.5, 1.0, choice=choose_scale(pieces, bed, requested=4.0, margin=8.0))
    assert e.value.parameter == "--scale"
