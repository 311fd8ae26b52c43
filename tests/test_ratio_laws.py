"""Any law, any pair: the law interface (laws/law.py) and the user's laws (laws/ratio_laws.py)
against closed forms: elliptical gears (Litvin & Fuentes-Aznar 2009, ch. 3-4), Fourier series."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipe

from propulsor.errors import InputError
from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw, centre_distance
from propulsor.laws.law import Law, is_walking, require_law
from propulsor.laws.ratio_laws import EllipticalLaw, FourierLaw
from propulsor.laws.walking import SEED_002, WalkingLaw
from outline_points import dense


def test_walking_laws_are_laws_with_their_leg_as_period():
    law = WalkingLaw(**SEED_002)
    for lw in (law, SmoothedWalkingLaw(law, 0.1)):
        assert isinstance(lw, Law) and is_walking(lw)
        assert lw.period == math.pi / 2 and lw.periods == 4 and lw.period_start == -math.pi / 4
    assert law.corner_phis == (math.pi / 4,)
    assert SmoothedWalkingLaw(law, 0.1).corner_phis == ()


def test_pitch_curves_take_any_law_and_refuse_a_non_law():
    pc = PitchCurves(EllipticalLaw(0.3), 100.0)
    assert pc.perimeter_driven() > 0
    with pytest.raises(InputError, match="law"):
        PitchCurves(object(), 100.0)


def test_require_law_refuses_a_driver_that_does_not_close():
    class ThreeOnTwo(EllipticalLaw):
        @property
        def n(self):
            return 3

    with pytest.raises(InputError, match=r"n = 3: .*divides its 2 periods"):
        require_law(ThreeOnTwo(0.2, 2))


@pytest.mark.parametrize("e", [0.1, 0.3, 0.6])
def test_elliptical_1to1_centre_distance_is_2a_of_the_ellipse_holding_the_teeth(e):
    m, z = 2.5, 36
    law = EllipticalLaw(e, 1)
    L = centre_distance(law, m, z)
    a = z * math.pi * m / (4 * ellipe(e * e))  # perimeter 4 a E(e) = z pi m
    assert L == pytest.approx(2 * a, rel=1e-9)
    pc = PitchCurves(law, L)
    # the driver is the ellipse about its focus: r1 = a (1 - e^2) / (1 + e cos theta)
    th = np.linspace(0.0, 2 * math.pi, 37)
    assert np.allclose(pc.driver_radius(th), a * (1 - e * e) / (1 + e * np.cos(th)), rtol=1e-12, atol=0)
    # both wheels are the same ellipse: equal perimeters
    assert pc.perimeter_driver() == pytest.approx(pc.perimeter_driven(), rel=1e-10)


@pytest.mark.parametrize("e", [0.1, 0.3, 0.6])
def test_elliptical_1to1_ratio_range(e):
    law = EllipticalLaw(e, 1)
    assert law.U_max == pytest.approx((1 + e) / (1 - e), rel=1e-12)
    assert law.U_min == pytest.approx((1 - e) / (1 + e), rel=1e-9)
    assert float(law.U(0.0)) == pytest.approx((1 + e) / (1 - e), rel=1e-12)


@pytest.mark.parametrize("k", [2, 3])
def test_elliptical_k_lobes_closes_by_the_independent_closure_integral(k):
    e, m, z_H = 0.3, 2.0, 24 * k
    law = EllipticalLaw(e, k)
    L = centre_distance(law, m, z_H)
    p = L * law.q
    r1 = lambda t: p / (1 + e * math.cos(t))  # noqa: E731
    total = quad(lambda t: r1(t) / (L - r1(t)), 0.0, 2 * math.pi, epsabs=1e-13, epsrel=1e-13)[0]
    assert total == pytest.approx(2 * math.pi / k, rel=1e-10)
    pc = PitchCurves(law, L)
    # the driver's pitch perimeter holds z_H / k teeth of the module
    assert pc.perimeter_driver() == pytest.approx(math.pi * m * z_H / k, rel=1e-10)
    assert float(law.theta(2 * math.pi)) == pytest.approx(2 * math.pi * k, rel=1e-14)
    phi = np.linspace(-4.0, 4.0, 81)
    assert np.allclose(law.phi_of_theta(law.theta(phi)), phi, atol=1e-13)


@pytest.mark.parametrize("law", [EllipticalLaw(0.4, 2), FourierLaw(3, (0.02, -0.01), (0.015, 0.0, 0.004))])
def test_derivatives_are_those_of_theta(law):
    x = np.linspace(-1.3, 1.3, 27)
    h = 1e-5
    assert np.allclose((law.theta(x + h) - law.theta(x - h)) / (2 * h), law.U(x), rtol=0, atol=1e-8)
    assert np.allclose((law.U(x + h) - law.U(x - h)) / (2 * h), law.dU_dphi(x), rtol=0, atol=1e-7)
    assert np.allclose((law.dU_dphi(x + h) - law.dU_dphi(x - h)) / (2 * h), law.d2U_dphi2(x), rtol=0, atol=1e-5)
    assert float(law.theta(2 * math.pi)) == pytest.approx(2 * math.pi * law.n, rel=1e-13)


@pytest.mark.parametrize("e", [1.0, 1.5, -0.1, math.nan])
def test_eccentricity_of_no_ellipse_is_refused(e):
    with pytest.raises(InputError, match="eccentricity"):
        EllipticalLaw(e, 1)


def test_fourier_law_is_the_series_it_is_given():
    k, c, s = 2, (0.03, 0.01), (0.02,)
    law = FourierLaw(k, c, s)
    th = np.linspace(0.0, 2 * math.pi, 50)
    phi = th / k + c[0] * np.cos(th) + c[1] * np.cos(2 * th) + s[0] * np.sin(th) - sum(c)
    assert np.allclose(law.theta(phi), th, rtol=0, atol=1e-13)


@pytest.mark.parametrize("k", [1, 2, 4])
def test_fourier_zero_coefficients_are_circular_gears_of_the_spur_pitch_radii(k):
    m, z_H = 2.0, 40 * k
    law = FourierLaw(k, (0.0, 0.0), (0.0,))
    L = centre_distance(law, m, z_H)
    assert L == pytest.approx(m * z_H / 2 + m * (z_H // k) / 2, rel=1e-13)
    pc = PitchCurves(law, L)
    phi = np.linspace(0.0, 2 * math.pi, 31)
    assert np.allclose(pc.r_H(phi), m * z_H / 2, rtol=1e-13, atol=0)
    assert np.allclose(pc.r(phi), m * (z_H // k) / 2, rtol=1e-13, atol=0)
    assert pc.curvature("driven").rho_convex_min == pytest.approx(m * z_H / 2, rel=1e-9)


def test_fourier_ratio_not_positive_is_refused_naming_the_key():
    with pytest.raises(InputError, match=r"fourier_cos = \[1\.2\]: d phi / d theta = .* <= 0"):
        FourierLaw(1, (1.2,), ())


def test_fourier_zero_law_generates_the_spur_gear_of_the_same_teeth():
    """Same circle -> same teeth: the driven wheel of the all-zero Fourier law (1:1) generated by the
    rack on the pair's arc-length frame is the spur gear of z teeth, half a pitch turned (its teeth
    centred at s = (k + 1/2) p, the spur gear's tooth 0 on +y), within 1 um."""
    from scipy.spatial import cKDTree

    from propulsor.gears.noncircular_teeth import ToothSpec
    from propulsor.geometry.gear_outline import external_gear_profile
    from propulsor.geometry.noncircular_outline import generate_gear

    m, z = 2.0, 20
    law = FourierLaw(1, (0.0,), (0.0,))
    pc = PitchCurves(law, centre_distance(law, m, z))
    gen = np.vstack(generate_gear(pc, "driven", ToothSpec(m=m)).profile.polylines(0.0001))
    spur = dense(external_gear_profile(z, m).profile.polylines(0.0001), 0.0005)
    c, s = math.cos(math.pi / z), math.sin(math.pi / z)
    spur = spur @ np.array([[c, s], [-s, c]])
    assert float(np.max(cKDTree(spur).query(gen)[0])) < 1e-3
