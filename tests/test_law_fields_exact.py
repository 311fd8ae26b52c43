"""The walking law's and the Fourier law's refusals with the whole of their answer (parameter, value, limit), the fields
each law keeps (their values and types, which part files, the manifest and the study tables print), and the Fourier
inversion's Hermite start at the edges of its table.  The cases `make mutation MODULE=laws` found no test for
(mutation/README.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.laws.ratio_laws import LOBES_MAX, EllipticalLaw, FourierLaw
from propulsor.laws.walking import WalkingLaw, check_n_closes

SEED002_SIN = (-0.041163336, 0.007288343, -0.002416844, 0.001071365)
LENGTH = "a length must be >= 0 mm"


def _err(fn, *a, **kw):
    with pytest.raises(InputError) as e:
        fn(*a, **kw)
    return e.value.parameter, e.value.value, e.value.limit


@pytest.mark.parametrize("args, want", [
    ((-1, 100, 360, 2), ("a", -1, LENGTH)),
    ((60, -1, 360, 2), ("b", -1, LENGTH)),
    ((60, 100, -2, 2), ("c", -2, LENGTH)),
    ((60, 100, 360, 2.5), ("n", 2.5, "driver turns per driven turn must be a whole number")),
    ((60, 100, 360, 0), ("n", 0, "driver turns per driven turn must be >= 1")),
    ((60, 500, 360, 2), ("a - b + c", -80.0,
                         "hub height Y01 = a - b + c must be > 0 mm, else the law is not positive")),
    ((60, 100, 40, 2), ("a - b + c", 0.0, "hub height Y01 = a - b + c must be > 0 mm, else the law is not positive")),
    (("x", 100, 360, 2), ("a", "x", "must be a number")),
])
def test_each_refusal_of_a_walking_law(args, want):
    assert _err(WalkingLaw, *args) == want


def test_a_walking_law_keeps_its_lengths_as_floats_and_n_as_a_whole_number():
    law = WalkingLaw(60, 100, 360, 2.0)
    assert (law.a, law.b, law.c, law.n) == (60.0, 100.0, 360.0, 2)
    assert [type(v) for v in (law.a, law.b, law.c, law.n)] == [float, float, float, int]
    # a hub height just above 0 (A = 0.5 mm) is a law; its ratio is u everywhere the crank is 0
    low = WalkingLaw(0.25, 0.0, 0.25, 1)
    assert low.A == 0.5 and low.U_min == low.U_max == pytest.approx(1.0, rel=1e-15)


def test_which_n_close_the_four_legs():
    for n in (1, 2, 4):
        check_n_closes(n)
    for n in (3, 5, 8):
        assert _err(check_n_closes, n) == (
            "n", n, "the driver pitch curve repeats every n*pi/2 and closes only if n divides the 4 legs: "
                    "n in {1, 2, 4}")


def test_the_walking_law_inverts_theta_over_turns_of_the_driver():
    law = WalkingLaw(100.0, 50.0, 236.5, 4)
    phi = np.linspace(-3.0, 3 * 2 * math.pi, 301)
    np.testing.assert_allclose(law.phi_of_theta(law.theta(phi)), phi, atol=1e-10)


@pytest.mark.parametrize("args, want", [
    ((2.5,), ("driver_turns", 2.5, f"lobes of the driven wheel must be a whole number 1 .. {LOBES_MAX}")),
    ((0,), ("driver_turns", 0, f"lobes of the driven wheel must be a whole number 1 .. {LOBES_MAX}")),
    ((LOBES_MAX + 1,), ("driver_turns", LOBES_MAX + 1,
                        f"lobes of the driven wheel must be a whole number 1 .. {LOBES_MAX}")),
    (("x",), ("driver_turns", "x", "must be a number")),
    ((2, (0.1, "x")), ("fourier_cos[1]", "x", "must be a number")),
    ((2, (), (0.1, math.nan)), ("fourier_sin[1]", math.nan, "must be a finite number")),
    ((1, (1.2,), ()), ("fourier_cos", [1.2], "d phi / d theta = -0.2 <= 0 at theta = 90.00 deg: the driven wheel "
                                             "would stop or turn back (the ratio must stay > 0)")),
    ((1, (), (1.2,)), ("fourier_sin", [1.2], "d phi / d theta = -0.2 <= 0 at theta = 180.00 deg: the driven wheel "
                                             "would stop or turn back (the ratio must stay > 0)")),
    ((1, (0.2,), (1.2,)), ("fourier_sin", [1.2], "d phi / d theta = -0.2166 <= 0 at theta = 170.53 deg: the driven "
                                                 "wheel would stop or turn back (the ratio must stay > 0)")),
    ((1, (1.2,), (0.2,)), ("fourier_cos", [1.2], "d phi / d theta = -0.2166 <= 0 at theta = 99.47 deg: the driven "
                                                 "wheel would stop or turn back (the ratio must stay > 0)")),
    ((1, (0.0, 0.6), (0.0, 0.3)), ("fourier_cos", [0.0, 0.6], "d phi / d theta = -0.3416 <= 0 at theta = 238.28 "
                                                              "deg: the driven wheel would stop or turn back (the "
                                                              "ratio must stay > 0)")),
    # the one the ratio's slope comes from, where both series pull it down (the more negative sum of slopes)
    ((1, (-1.2,), (0.3,)), ("fourier_cos", [-1.2], "d phi / d theta = -0.2369 <= 0 at theta = 255.96 deg: the driven "
                                                   "wheel would stop or turn back (the ratio must stay > 0)")),
    ((1, (0.9,), (-0.9,)), ("fourier_sin", [-0.9], "d phi / d theta = -0.2728 <= 0 at theta = 45.00 deg: the driven "
                                                   "wheel would stop or turn back (the ratio must stay > 0)")),
    # a slope of exactly 0 (the driven wheel stops there) is refused too
    ((1, (), (1.0,)), ("fourier_sin", [1.0], "d phi / d theta = 0 <= 0 at theta = 180.00 deg: the driven wheel "
                                             "would stop or turn back (the ratio must stay > 0)")),
    ((3, (0.0, 0.0, 0.2)), ("fourier_cos", [0.0, 0.0, 0.2], "d phi / d theta = -0.2667 <= 0 at theta = 270.00 deg: "
                                                            "the driven wheel would stop or turn back (the ratio "
                                                            "must stay > 0)")),
])
def test_each_refusal_of_a_fourier_law(args, want):
    got = _err(FourierLaw, *args)
    if isinstance(want[1], float) and math.isnan(want[1]):
        assert got[0] == want[0] and math.isnan(got[1]) and got[2] == want[2]
    else:
        assert got == want


def test_a_fourier_law_keeps_its_terms_as_tuples_of_floats():
    law = FourierLaw(2.0, [1e-3, 0], [0])
    assert (law.k, law.cos, law.sin) == (2, (0.001, 0.0), (0.0,))
    assert type(law.k) is int and type(law.cos) is tuple and type(law.sin) is tuple
    assert {type(v) for v in law.cos + law.sin} == {float}
    ellipse = EllipticalLaw(0, 2.0)
    assert (ellipse.e, ellipse.k) == (0.0, 2) and type(ellipse.e) is float and type(ellipse.k) is int


@pytest.mark.parametrize("args", [(4, (0.0,) * 4, SEED002_SIN), (3, (0.02, -0.005), (0.03, 0.004)), (1, (0.3,), (0.2,))],
                         ids=["seed002", "k3", "k1"])
def test_the_hermite_start_is_within_1e_12_rad_everywhere_and_at_the_table_edges(args):
    """theta's start (cubic Hermite in a table of one period, theta and its slope) is within 1e-12 rad of theta,
    as an array and as one float; at phi just below a period's start (x rounds to the table's end) it takes the
    last interval instead of reading past the table.  (The law is made here, not at collection: a mutant of its
    construction must be the one tested.)"""
    law = FourierLaw(*args)
    P = law.period
    h = P / 4096
    phi = np.concatenate([np.linspace(-4.0, 9.0, 2001), [-1e-300, -P - 1e-300, 0.0, 1e-300, h * 0.3, h * 0.999,
                                                         P - h * 0.3, P * (1 - 1e-16), P, 2 * P + 1e-12]])
    th = np.array([law.theta1(p) for p in phi.tolist()])
    np.testing.assert_allclose(law.theta(phi), th, rtol=0, atol=1e-13)
    assert np.max(np.abs(law._guess(phi) - th)) < 1e-12
    assert max(abs(law._guess1(p) - t) for p, t in zip(phi.tolist(), th.tolist())) < 1e-12
    # one float and a few (the per-point path) and many (the array path) agree
    few = phi[-8:]
    np.testing.assert_allclose(law.theta(few), th[-8:], rtol=0, atol=1e-13)
    np.testing.assert_allclose(law.U(few), [law.U_derivs1(p)[0] for p in few.tolist()], rtol=1e-13)


# ---- a pitch curve: the given curve, its spline, its closure, the refusals of the conjugate wheel ----------------

def _egg(rows=72):
    a = np.linspace(0.0, 360.0, rows, endpoint=False)
    return a, 40 / (1 + 0.25 * np.cos(np.radians(a))) + 2 * np.sin(np.radians(2 * a) + 0.3)


@pytest.mark.parametrize("k", [1, 2, 3])
def test_a_pitch_curve_keeps_its_rows_and_closes_to_the_last_bit(k):
    from propulsor.laws.pitch_curve_law import PitchCurveLaw

    a, r = _egg()
    law = PitchCurveLaw(tuple(a), tuple(r), k)
    # the driver turns by theta = -a: at theta = -a_i the given curve's radius is the row's (an asymmetric curve)
    np.testing.assert_allclose(law.driver_radius_given(-np.radians(a)), r, rtol=1e-12)
    assert abs(float(law.driver_radius_given(np.radians([30.0]))[0]) - r[list(a).index(330.0)]) < 1e-9
    # the spline is the periodic quintic: its slope and curvature run on across the first row
    assert law._r.k == 5
    for order in (1, 2, 4):
        d = law._r.derivative(order)
        assert float(d(0.0)) == pytest.approx(float(d(2 * math.pi)), rel=1e-9, abs=1e-9)
    assert [float(v) for v in law.theta(np.array([2 * math.pi / k, 2 * math.pi]))] == [2 * math.pi, 2 * math.pi * k]
    assert float(law.phi_of_theta(np.array([2 * math.pi]))[0]) == 2 * math.pi / k


def test_a_pitch_curve_whose_closing_radius_is_off_by_more_than_1e_9_of_the_first():
    from propulsor.laws.pitch_curve_law import PitchCurveLaw

    a, r = _egg(8)
    a, r = list(a) + [360.0], list(r)
    r[1] = 2 * r[0]  # the tolerance is of the first row's radius, not the second's
    PitchCurveLaw(tuple(a), tuple(r + [r[0] * (1 + 0.9e-9)]), 1)
    assert _err(PitchCurveLaw, tuple(a), tuple(r + [r[0] * (1 + 1.5e-9)]), 1) == (
        "pitch_curve_file row 9 angle_deg", 360.0, "the rows span one turn: angles up to 360 deg (that row only to "
                                                    "close the curve, with the first row's radius)")


def _spike(rows, height):
    a = np.linspace(0.0, 360.0, rows, endpoint=False)
    r = np.full(rows, 40.0)
    r[rows // 3] = 40.0 * height
    return tuple(a), tuple(r)


def test_a_pitch_curve_too_sharp_for_the_law_is_refused_in_the_users_terms():
    from propulsor.laws.pitch_curve_law import PitchCurveLaw

    # a peak one row wide among 3600: the conjugate law's spline turns back between the curve's rows
    assert _err(PitchCurveLaw, *_spike(3600, 2.0), 1) == (
        "pitch_curve_file", "3600 rows", "the law of the conjugate wheel has a ratio U = -0.7083 <= 0 near it "
                                         "(between the curve's rows): a smoother curve, or rows where its radius "
                                         "turns fastest")
    # higher still: no centre distance closes the turn at the law's samples (was scipy's ValueError, a traceback)
    assert _err(PitchCurveLaw, *_spike(3600, 3.0), 1, key="my_curve") == (
        "my_curve", "3600 rows", "no centre distance closes a 1-lobe driven wheel at the law's 2048 samples a turn: "
                                 "the curve's largest radius is a peak too narrow to follow (a smoother curve, or "
                                 "more lobes)")


def test_a_pitch_curve_file_names_its_key_and_what_it_is(tmp_path):
    from propulsor.laws.pitch_curve_law import RADIUS_MAX_MM, parse_pitch_curve, read_pitch_curve
    from propulsor.laws.table_law import MAX_BYTES

    big = tmp_path / "big.csv"
    big.write_text("angle_deg,radius_mm\n" + "0,1\n" * (MAX_BYTES // 4 + 10), encoding="utf-8")
    p, v, limit = _err(read_pitch_curve, big, "curve_key")
    assert (p, v) == ("curve_key", str(big)) and limit.endswith(f"; a pitch curve table is a CSV file of at most "
                                                                f"{MAX_BYTES} bytes")
    bad = tmp_path / "bad.csv"
    bad.write_text("angle_deg,radius_mm\n0,40\n10,x\n", encoding="utf-8")
    assert _err(read_pitch_curve, bad, "curve_key") == ("curve_key row 2 radius_mm", "x", "must be a number in plain digits (0-9, '.', an exponent e±NNN)")
    # a radius at the limit is taken, above it refused
    rows = "".join(f"{a},{RADIUS_MAX_MM if a == 0 else 40}\n" for a in range(0, 360, 30))
    assert parse_pitch_curve("angle_deg,radius_mm\n" + rows)[1][0] == RADIUS_MAX_MM


def test_theta_remembers_its_last_array_by_its_values_and_shape():
    law = FourierLaw(3, (0.02, -0.005), (0.03, 0.004))
    phi = np.linspace(-1.0, 2.0, 16)
    th = law.theta(phi)
    again = law.theta(phi.reshape(4, 4))  # the same bytes in another shape: not the remembered answer
    assert again.shape == (4, 4)
    np.testing.assert_array_equal(again.ravel(), th)
    th[0] = 99.0  # the caller's copy, not the remembered one
    assert law.theta(phi)[0] != 99.0


def test_a_law_table_one_row_short_of_its_period_is_told_the_row_that_closes_it():
    from propulsor.laws.table_law import TableLaw

    short = ([30.0 * i for i in range(12)], [15.0 * i for i in range(12)])  # 0 ... 330, 0 ... 165: 360,180 missing
    assert _err(TableLaw, *short) == (
        "law_file row 12 driven_deg", 165.0, "the last row closes the period: the driven span 165 deg must divide "
                                             "360 deg (the rows seem to stop one step short: add the closing row "
                                             "360,180)")
    TableLaw(tuple(short[0] + [360.0]), tuple(short[1] + [180.0]))  # with it, a law
    # a 4-period table (driven 1 ... 91) one step short: the closing row is one period on, not one turn
    four = ([22.5 * i for i in range(8)], [11.25 * i + 1.0 for i in range(8)])
    assert _err(TableLaw, *four)[2].endswith("(the rows seem to stop one step short: add the closing row 180,91)")
    TableLaw(tuple(four[0] + [180.0]), tuple(four[1] + [91.0]))
    # rows that do not stop one even step short: no row to suggest
    assert _err(TableLaw, [0.0, 40, 80, 120, 160, 200, 240, 300], [0.0, 20, 40, 60, 80, 100, 120, 170])[2] == (
        "the last row closes the period: the driven span 170 deg must divide 360 deg")


def test_lobes_are_counted_on_the_driven_pitch_curve():
    from propulsor.laws.pitch_curve_law import PitchCurveLaw
    from propulsor.parts.noncircular_pair.law_outputs import lobes_text

    a = np.linspace(0.0, 360.0, 72, endpoint=False)
    oval = PitchCurveLaw(tuple(a), tuple(40 / (1 + 0.2 * np.cos(np.radians(2 * a)))), 1)  # 2-fold, k = 1
    assert [lobes_text(x) for x in (EllipticalLaw(0.3), EllipticalLaw(0.2, 2), FourierLaw(3, (0.02,), (0.03,)),
                                    oval, EllipticalLaw(0.0))] == [
        "1 lobe", "2 lobes", "3 lobes", "2 lobes", "a round wheel (no lobes)"]
