"""What every drive law must satisfy, law by law (laws/law.py): theta(0) = 0, one period adds 2 pi n / periods
to theta and repeats U, U = d theta / d phi and its derivatives agree with finite differences, the one-float path
(``theta1``, ``U_derivs1``) equals the array path on small and large arrays, ``phi_of_theta`` inverts ``theta``, the
mean ratio is n turns per driven turn; and each law against an independent form of itself (the ellipse's radii,
the Fourier series written out, a table or a pitch curve sampled from a known law).  The cases
`make mutation MODULE=laws` found no test for (mutation/README.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.laws.law import require_law
from propulsor.laws.pitch_curve_law import PitchCurveLaw
from propulsor.laws.ratio_laws import EllipticalLaw, FourierLaw
from propulsor.laws.table_law import TableLaw
from propulsor.laws.walking import WalkingLaw

SEED002_SIN = (-0.041163336, 0.007288343, -0.002416844, 0.001071365)


def _fourier_table(k=3, rows=721):
    law = FourierLaw(k, (0.02, -0.005), (0.03, 0.004))
    th = np.linspace(0.0, 2 * math.pi, rows)
    return law, TableLaw(tuple(np.degrees(th)), tuple(np.degrees(law.phi_of_theta(th))))


def _ellipse_curve(e=0.25, p=40.0, rows=3601):
    a = np.linspace(0.0, 360.0, rows, endpoint=False)
    # the driver turns by theta = -a: its radius at theta is p / (1 + e cos theta), cos symmetric
    return EllipticalLaw(e), PitchCurveLaw(tuple(a), tuple(p / (1 + e * np.cos(np.radians(a)))), 1)


LAWS = {
    "ellipse_1": lambda: EllipticalLaw(0.3),
    "ellipse_2lobe": lambda: EllipticalLaw(0.2, 2),
    "circle": lambda: EllipticalLaw(0.0),
    "fourier_seed002": lambda: FourierLaw(4, (0.0, 0.0, 0.0, 0.0), SEED002_SIN),
    "fourier_cos_sin": lambda: FourierLaw(3, (0.02, -0.005), (0.03, 0.004)),
    "fourier_none": lambda: FourierLaw(2),
    "table": lambda: _fourier_table()[1],
    "pitch_curve": lambda: _ellipse_curve()[1],
    "walking_seed002": lambda: WalkingLaw(100.0, 50.0, 236.5, 4),
}


@pytest.fixture(scope="module", params=sorted(LAWS))
def law(request):
    return LAWS[request.param]()


def _inside(law, n=37):
    """Driven angles inside the smooth pieces of two periods (off the corners by 1e-3 rad)."""
    lo = law.period_start
    pts = np.linspace(lo + 1e-3, lo + law.period - 1e-3, n)
    if law.corner_phis:
        pts = pts[np.min(np.abs(pts[:, None] - np.asarray(law.corner_phis)[None, :]), axis=1) > 2e-3]
    return np.concatenate([pts, pts + law.period])


def test_the_law_is_a_law_and_closes(law):
    require_law(law)
    assert law.periods * law.period == pytest.approx(2 * math.pi, abs=1e-12)
    assert law.breakpoints[0] == pytest.approx(law.period_start, abs=1e-12)
    assert law.breakpoints[-1] == pytest.approx(law.period_start + law.period, abs=1e-12)
    assert list(law.breakpoints) == sorted(law.breakpoints)


def test_theta_starts_at_zero_and_adds_its_share_of_turns_each_period(law):
    assert float(law.theta(np.array([0.0]))[0]) == pytest.approx(0.0, abs=1e-12)
    phi = _inside(law)
    step = 2 * math.pi * law.n / law.periods
    np.testing.assert_allclose(law.theta(phi + law.period) - law.theta(phi), step, atol=1e-10)
    np.testing.assert_allclose(law.theta(phi + 2 * math.pi) - law.theta(phi), 2 * math.pi * law.n, atol=1e-9)
    np.testing.assert_allclose(law.U(phi + law.period), law.U(phi), rtol=1e-10)
    np.testing.assert_allclose(law.dU_dphi(phi - law.period), law.dU_dphi(phi), rtol=1e-8, atol=1e-10)


def test_derivatives_are_those_of_theta(law):
    phi, h = _inside(law), 1e-5
    U, dU, d2U = law.U(phi), law.dU_dphi(phi), law.d2U_dphi2(phi)
    np.testing.assert_allclose((law.theta(phi + h) - law.theta(phi - h)) / (2 * h), U, rtol=1e-8)
    np.testing.assert_allclose((law.U(phi + h) - law.U(phi - h)) / (2 * h), dU, atol=1e-6 * np.max(np.abs(U)))
    np.testing.assert_allclose((law.dU_dphi(phi + h) - law.dU_dphi(phi - h)) / (2 * h), d2U,
                               atol=1e-5 * max(1.0, float(np.max(np.abs(d2U)))))
    assert np.all(U > 0)


def test_the_mean_ratio_is_n_turns_per_driven_turn(law):
    phi = np.linspace(law.period_start, law.period_start + law.period, 20001)
    U = law.U(phi)
    mean = float(np.sum((U[1:] + U[:-1]) / 2 * np.diff(phi))) / law.period
    assert mean == pytest.approx(law.n, rel=1e-7)


def test_the_one_float_path_equals_the_array_path(law):
    phi = _inside(law, 11)
    big = [law.U(phi), law.dU_dphi(phi), law.d2U_dphi2(phi)]
    th = law.theta(phi)
    for i, p in enumerate(phi.tolist()):
        one = law.U_derivs1(p)
        assert one == pytest.approx((big[0][i], big[1][i], big[2][i]), rel=1e-9, abs=1e-9)
        assert law.theta1(p) == pytest.approx(th[i], abs=1e-11)
    # a small array (the per-point path of some laws) gives the same as a large one
    small = phi[:3]
    np.testing.assert_allclose(law.U(small), big[0][:3], rtol=1e-12)
    np.testing.assert_allclose(law.dU_dphi(small), big[1][:3], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(law.d2U_dphi2(small), big[2][:3], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(law.theta(small), th[:3], atol=1e-12)
    # asked twice (a remembered last answer) the same
    np.testing.assert_array_equal(law.theta(phi), th)
    assert law.theta1(phi[4]) == law.theta1(phi[4])


def test_phi_of_theta_inverts_theta(law):
    phi = _inside(law)
    np.testing.assert_allclose(law.phi_of_theta(law.theta(phi)), phi, atol=1e-9)


# ---- each law against an independent form of itself ---------------------------------------------------------

@pytest.mark.parametrize("e, k", [(0.3, 1), (0.2, 2), (0.5, 3)])
def test_ellipse_ratio_is_its_radii(e, k):
    law = EllipticalLaw(e, k)
    q = (1 - e * e) / 2 if k == 1 else (-1 + math.sqrt(1 + (k * k - 1) * (1 - e * e))) / (k * k - 1)
    assert law.q == pytest.approx(q, rel=1e-14)
    phi = np.linspace(-3.0, 3.0, 41)
    th = law.theta(phi)
    r1 = law.driver_radius_rel(th)
    np.testing.assert_allclose(r1, q / (1 + e * np.cos(th)), rtol=1e-14)
    np.testing.assert_allclose(law.U(phi), (1 - r1) / r1, rtol=1e-12)  # U = r2 / r1, r1 + r2 = L
    assert law.U_min == pytest.approx((1 - q / (1 - e)) / (q / (1 - e)), rel=1e-6)
    assert law.U_max == pytest.approx((1 - q / (1 + e)) / (q / (1 + e)), rel=1e-6)


def test_circle_turns_evenly():
    law = EllipticalLaw(0.0)
    phi = np.linspace(-1.0, 1.0, 21)
    np.testing.assert_allclose(law.U(phi), 1.0, rtol=1e-15)
    np.testing.assert_allclose(law.theta(phi), phi, atol=1e-15)


def test_fourier_phi_is_its_series():
    cos, sin = (0.02, -0.005), (0.03, 0.004)
    law = FourierLaw(3, cos, sin)
    th = np.linspace(-7.0, 7.0, 57)
    series = th / 3 + sum(c * np.cos((j + 1) * th) for j, c in enumerate(cos)) \
        + sum(s * np.sin((j + 1) * th) for j, s in enumerate(sin)) - sum(cos)
    np.testing.assert_allclose(law.phi_of_theta(th), series, atol=1e-15)
    slope = 1 / 3 + sum(-(j + 1) * c * np.sin((j + 1) * th) for j, c in enumerate(cos)) \
        + sum((j + 1) * s * np.cos((j + 1) * th) for j, s in enumerate(sin))
    np.testing.assert_allclose(law.U(law.phi_of_theta(th)), 1 / slope, rtol=1e-12)


def test_fourier_start_guess_is_already_close():
    """theta's Hermite start (its table of one period) is within 1e-9 rad of the answer: Newton then needs one
    or two steps (the generator asks ~20 000 times)."""
    law = FourierLaw(4, (0.0, 0.0, 0.0, 0.0), SEED002_SIN)
    phi = np.linspace(-4.0, 9.0, 2001)
    assert np.max(np.abs(law._guess(phi) - law.theta(phi))) < 1e-9


def test_table_law_through_a_known_law():
    law, table = _fourier_table()
    assert (table.n, table.periods) == (law.n, law.periods)
    phi = np.linspace(0.0, 2 * math.pi, 97)
    np.testing.assert_allclose(table.theta(phi), law.theta(phi), atol=2e-9)
    np.testing.assert_allclose(table.U(phi), law.U(phi), rtol=2e-7)


def test_pitch_curve_law_of_an_ellipse_is_the_elliptical_law():
    law, curve = _ellipse_curve()
    assert (curve.n, curve.periods) == (1, 1)
    # the centre distance closes the ellipse about its focus: L0 = p / q
    assert curve.L0 == pytest.approx(40.0 / law.q, rel=1e-9)
    phi = np.linspace(-3.0, 3.0, 61)
    np.testing.assert_allclose(curve.U(phi), law.U(phi), rtol=1e-7)
    np.testing.assert_allclose(curve.theta(phi), law.theta(phi), atol=1e-8)
    th = np.linspace(0.0, 2 * math.pi, 13)
    np.testing.assert_allclose(curve.driver_radius_given(th), 40.0 / (1 + 0.25 * np.cos(th)), rtol=1e-9)
