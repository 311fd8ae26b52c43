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


@pytest.mark.parametrize("law", [FourierLaw(4, (0.0,) * 4, SEED002_SIN), FourierLaw(3, (0.02, -0.005), (0.03, 0.004)),
                                 FourierLaw(1, (0.3,), (0.2,))], ids=["seed002", "k3", "k1"])
def test_the_hermite_start_is_within_1e_12_rad_everywhere_and_at_the_table_edges(law):
    """theta's start (cubic Hermite in a table of one period, theta and its slope) is within 1e-12 rad of theta,
    as an array and as one float; at phi just below a period's start (x rounds to the table's end) it takes the
    last interval instead of reading past the table."""
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
