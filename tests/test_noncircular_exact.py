"""The pitch-curve math of the non-circular pair (gears/noncircular.py) against values computed in the test.

Every expected value is worked out here, not by the module: a circular law (the walking law with b = 0: U = n
everywhere, two circles r_H = L n / (1 + n), r = L / (1 + n)); the elliptical pair of k = 1 (both wheels the
ellipse r = p / (1 + e cos theta) about a focus, L = 2a, tan(theta/2) = (1 + e)/(1 - e) tan(phi/2), perimeter
4 a E(e), radius of curvature (r (2a - r))^(3/2) / (a b)); seed 000's / 002's law written out (U = u (A + 3b cos 2w)
/ A); the pitch points' curvature as the signed curvature of the parametric curve (x'y'' - y'x'') / |P'|^3 on a dense
grid with the extremes refined by scipy, the concave stretches' ends by bisection; perimeters by scipy's quad.
Laws are built inside each test (mutmut ties a test to the functions it calls itself).
"""

import math
import types

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar
from scipy.special import ellipe

from propulsor.errors import InputError
from propulsor.gears import noncircular as nc
from propulsor.gears.noncircular import (
    MAX_CURVATURE_FLIPS,
    PitchCurves,
    SmoothedWalkingLaw,
    centre_distance,
    driven_teeth,
    hub_speed_ripple,
    module_for,
    perimeter_per_mm,
    whole_pitches,
    whole_teeth,
)
from propulsor.laws.ratio_laws import EllipticalLaw, FourierLaw
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw

PI = math.pi


# --------------------------------------------------------------------------- helpers (the test's own math)
def _walking_U(law_abcn, phi):
    """Seed 000 eq. 15 written out: (U, U', U'') of the exact walking law, w = phi wrapped into [-pi/4, pi/4)."""
    a, b, c, n = law_abcn
    A = a - b + c
    u = n * PI * A / (A * PI + 6 * b)
    w = (np.asarray(phi, float) + PI / 4) % (PI / 2) - PI / 4
    return (u * (A + 3 * b * np.cos(2 * w)) / A, -6 * b * u * np.sin(2 * w) / A, -12 * b * u * np.cos(2 * w) / A)


def _ellipse(e, L):
    """The k = 1 elliptical pair's closed forms: a, b, p and theta(phi)."""
    a = L / 2
    p = a * (1 - e * e)
    bb = a * math.sqrt(1 - e * e)

    def theta(phi):
        phi = np.asarray(phi, float)
        j = np.round(phi / (2 * PI))
        w = phi - 2 * PI * j
        return 2 * np.arctan((1 + e) / (1 - e) * np.tan(w / 2)) + 2 * PI * j

    return a, bb, p, theta


def _curve_geometry(U3, L, curve):
    """The pitch point P(phi) of a curve as (x', y', x'', y'') in phi, from U, U', U'' (arrays): driven radius
    R = L U/(1+U) at polar angle phi, driver R = L/(1+U) at polar angle theta (d theta/d phi = U)."""
    U, dU, d2U = U3

    def parts(phi):
        q = 1 + U
        if curve == "driven":
            R, R1, R2 = L * U / q, L * dU / q**2, L * d2U / q**2 - 2 * L * dU**2 / q**3
            a1, a2 = np.ones_like(U), np.zeros_like(U)
        else:
            R, R1, R2 = L / q, -L * dU / q**2, -L * d2U / q**2 + 2 * L * dU**2 / q**3
            a1, a2 = U, dU
        # P = R (cos a, sin a): derivatives in phi, in the frame turned by a (the same in every frame)
        # P' = (R', R a'),  P'' = (R'' - R a'^2, 2 R' a' + R a'')
        x1, y1 = R1, R * a1
        x2, y2 = R2 - R * a1**2, 2 * R1 * a1 + R * a2
        return R, x1, y1, x2, y2

    return parts(None)


def _rho_brute(law_U, L, curve, phi):
    """Signed radius of curvature |P'|^3 / (x'y'' - y'x'') of the curve at the driven angles phi, and the
    numerator (its sign: convex > 0)."""
    R, x1, y1, x2, y2 = _curve_geometry(law_U(phi), L, curve)
    num = x1 * y2 - y1 * x2
    with np.errstate(divide="ignore"):  # a grid point on an inflection: +-inf
        return np.hypot(x1, y1) ** 3 / num, num


def _refine_min(f, x, y):
    """The least of f sampled as y at x, refined by scipy's bounded search between the neighbouring samples."""
    k = int(np.argmin(y))
    lo, hi = x[max(k - 1, 0)], x[min(k + 1, len(x) - 1)]
    res = minimize_scalar(lambda p: float(f(np.array([p]))[0]), bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-13})
    return (float(res.x), float(res.fun)) if res.fun < y[k] else (float(x[k]), float(y[k]))


def _bisect(g, a, b, n=80):
    ga = g(a)
    for _ in range(n):
        m = 0.5 * (a + b)
        if (g(m) > 0) == (ga > 0):
            a, ga = m, g(m)
        else:
            b = m
    return 0.5 * (a + b)


def _brute_summary(law_U, L, curve, lo, hi, N=200001):
    """(rho_convex_min, its phi, concave intervals, |rho| concave min, its phi) of the smooth pieces on [lo, hi]."""
    phi = np.linspace(lo, hi, N)
    rho, num = _rho_brute(law_U, L, curve, phi)
    cx = num > 0
    out = {}
    out["convex"] = _refine_min(lambda p: _rho_brute(law_U, L, curve, p)[0], phi[cx], rho[cx]) if cx.any() else None
    cc = num < 0
    if cc.any():
        s = np.sign(num)
        flips = np.flatnonzero(s[:-1] != s[1:])
        g = lambda p: float(_rho_brute(law_U, L, curve, np.array([p]))[1][0])
        edges = [_bisect(g, phi[k], phi[k + 1]) for k in flips]
        pts = [lo] + edges + [hi]
        out["intervals"] = [(a, b) for a, b in zip(pts[:-1], pts[1:]) if g(0.5 * (a + b)) < 0]
        out["concave"] = _refine_min(lambda p: np.abs(_rho_brute(law_U, L, curve, p)[0]), phi[cc], np.abs(rho[cc]))
    else:
        out["intervals"], out["concave"] = [], None
    return out


# --------------------------------------------------------------------------- the module's small pieces
def test_finite_is_one_finite_real_number():
    assert nc._finite(1.5) and nc._finite(-2) and nc._finite(np.float64(0.25)) and nc._finite(0)
    assert not nc._finite(math.nan) and not nc._finite(math.inf) and not nc._finite(-math.inf)
    assert not nc._finite(np.array([1.0])) and not nc._finite(np.array(1.0)) and not nc._finite("1")


def test_rho_of_a_circle_a_spiral_and_a_concave_curve():
    assert nc._rho(7.0, 0.0, 0.0) == 7.0
    # r = e^(k psi): rho = r sqrt(1 + k^2) (the logarithmic spiral)
    k, r = 0.3, 2.0
    assert nc._rho(r, k * r, k * k * r) == pytest.approx(r * math.sqrt(1 + k * k), rel=1e-15)
    # r'' large: concave (negative); (r^2 + r'^2)^1.5 / (r^2 + 2 r'^2 - r r'') by hand
    assert nc._rho(2.0, 1.0, 10.0) == pytest.approx(5 ** 1.5 / (4 + 2 - 20), rel=1e-15)


def test_leg_samples_are_600_cosine_spaced_points_a_piece_the_joints_once():
    law = types.SimpleNamespace(breakpoints=(-1.0, 0.5, 2.0))
    x = nc._leg_samples(law)
    t = np.linspace(0.0, PI, 600)
    s = 0.5 * (1 - np.cos(t))
    first, second = -1.0 + 1.5 * s, 0.5 + 1.5 * s
    assert len(x) == 1199  # the joint 0.5 once
    assert x[0] == -1.0 and x[-1] == 2.0 and 0.5 in x
    assert np.allclose(x[:600], first, rtol=0, atol=1e-15)
    assert np.allclose(x[599:], second, rtol=0, atol=1e-15)
    assert np.all(np.diff(x) > 0)
    assert len(nc._leg_samples(law, per_piece=11)) == 21


def test_leg_integral_is_exact_per_smooth_piece():
    # |x - 0.5| has its kink at the breakpoint: exact (to rounding) only when the pieces are split there
    law = types.SimpleNamespace(breakpoints=(-1.0, 0.5, 2.0))
    assert nc._leg_integral(law, lambda x: np.abs(x - 0.5)) == pytest.approx(1.5 ** 2, rel=1e-14)
    # a polynomial of degree 9 over one piece: int_{-1}^{3} (x^9 + 2 x) dx = (3^10 - 1)/10 + 8
    law1 = types.SimpleNamespace(breakpoints=(-1.0, 3.0))
    assert nc._leg_integral(law1, lambda x: x**9 + 2 * x) == pytest.approx((3**10 - 1) / 10 + 8, rel=1e-13)
    # a function Gauss-Legendre of 96 nodes integrates to rounding: exp over [0, 2]
    law2 = types.SimpleNamespace(breakpoints=(0.0, 2.0))
    assert nc._leg_integral(law2, np.exp) == pytest.approx(math.e**2 - 1, rel=1e-14)


def test_extreme_refines_between_the_neighbouring_samples():
    f = lambda p: (np.asarray(p) - 0.3) ** 2 + 1.0
    x = np.linspace(0.0, 1.0, 5)  # 0, 0.25, 0.5, ...: the least sample 0.25, the true minimum at 0.3
    p, v = nc._extreme(f, x, f(x), "min")
    assert p == pytest.approx(0.3, abs=1e-7) and v == pytest.approx(1.0, abs=1e-15)
    g = lambda p: 5.0 - (np.asarray(p) - 0.6) ** 2
    p, v = nc._extreme(g, x, g(x), "max")
    assert p == pytest.approx(0.6, abs=1e-7) and v == pytest.approx(5.0, abs=1e-15)
    # the least sample first or last: the search runs between it and its one neighbour
    h = lambda p: (np.asarray(p) - 0.1) ** 2
    p, v = nc._extreme(h, x, h(x), "min")
    assert p == pytest.approx(0.1, abs=1e-9) and v == pytest.approx(0.0, abs=1e-15)
    k = lambda p: (np.asarray(p) - 0.9) ** 2
    p, v = nc._extreme(k, x, k(x), "min")
    assert p == pytest.approx(0.9, abs=1e-9) and v == pytest.approx(0.0, abs=1e-15)
    km = lambda p: -((np.asarray(p) - 0.95) ** 2)
    p, v = nc._extreme(km, x, km(x), "max")
    assert p == pytest.approx(0.95, abs=1e-9) and v == pytest.approx(0.0, abs=1e-15)
    # one sample: itself, no search (floats)
    p, v = nc._extreme(f, np.array([0.7]), np.array([3.0]), "min")
    assert (p, v) == (0.7, 3.0) and type(p) is float and type(v) is float
    # a flat function: the search cannot beat the first sample, which stays (not a point it wandered to)
    flat = lambda p: np.full(np.shape(p), 2.0)
    assert nc._extreme(flat, x, flat(x), "min") == (0.0, 2.0)
    assert nc._extreme(flat, x, flat(x), "max") == (0.0, 2.0)
    # the sample is the extreme: the search cannot beat it and the sample stays, bit for bit
    lin = lambda p: np.asarray(p) * 1.0
    p, v = nc._extreme(lin, x, lin(x), "min")
    assert (p, v) == (0.0, 0.0)
    p, v = nc._extreme(lin, x, lin(x), "max")
    assert (p, v) == (1.0, 1.0)


def test_on_side_keeps_one_sign_of_the_radius():
    f = lambda p: np.asarray(p) * 1.0
    convex, concave = nc._on_side(f, 1.0), nc._on_side(f, -1.0)
    assert convex(2.5) == 2.5 and convex(-2.5) == math.inf and convex(np.array(3.0)) == 3.0
    assert concave(-2.5) == 2.5 and concave(2.5) == math.inf and concave(np.array(-4.0)) == 4.0
    assert convex(math.inf) == math.inf and concave(-math.inf) == math.inf  # a denominator 0: +-inf
    assert convex(0.0) == math.inf and concave(0.0) == math.inf
    assert type(convex(np.float64(1.5))) is float


# --------------------------------------------------------------------------- pitch curves: closed forms
def test_circular_law_gives_two_circles():
    """The walking law with b = 0: U = n, the pitch curves are circles r_H = L n/(1+n), r = L/(1+n)."""
    for n in (1, 2, 4):
        law = WalkingLaw(a=50.0, b=0.0, c=250.0, n=n)
        L = 120.0
        pc = PitchCurves(law, L)
        phi = np.linspace(-3.0, 7.0, 41)
        rH, r = L * n / (1 + n), L / (1 + n)
        assert np.allclose(pc.r_H(phi), rH, rtol=1e-15) and np.allclose(pc.r(phi), r, rtol=1e-15)
        assert np.all(pc.dr_H(phi) == 0) and np.all(pc.d2r_H(phi) == 0)
        assert np.all(pc.r_theta(phi) == 0) and np.all(pc.r_thetatheta(phi) == 0)
        assert np.allclose(pc.rho_H(phi), rH, rtol=1e-15) and np.allclose(pc.rho(phi), r, rtol=1e-15)
        assert np.allclose(pc.ds_dphi(phi), rH, rtol=1e-15)
        assert pc.perimeter_driven() == pytest.approx(2 * PI * rH, rel=1e-14)
        assert pc.perimeter_driver() == pytest.approx(2 * PI * r, rel=1e-14)
        assert perimeter_per_mm(law) == pytest.approx(2 * PI * n / (1 + n), rel=1e-14)
        assert pc.corners() == []
        for curve, R in (("driven", rH), ("driver", r)):
            cs = pc.curvature(curve)
            assert cs.curve == curve and cs.rho_convex_min == pytest.approx(R, rel=1e-14)
            assert -PI / 4 <= cs.phi_convex_min <= PI / 4
            assert cs.concave is False and cs.rho_concave_min == math.inf and math.isnan(cs.phi_concave_min)
            assert cs.concave_intervals == () and cs.corner is None
        # no ripple: v / omega = A / n everywhere, the mean A / u = A / n
        rip = hub_speed_ripple(law)
        assert rip.mean == pytest.approx(300.0 / n, rel=1e-15)
        assert rip.v_min == pytest.approx(300.0 / n, rel=1e-14) and rip.v_max == pytest.approx(300.0 / n, rel=1e-14)
        assert abs(rip.ripple) < 1e-14
        assert -PI / 4 <= rip.phi_min <= PI / 4 and -PI / 4 <= rip.phi_max <= PI / 4


def test_elliptical_pair_is_two_ellipses_about_their_foci():
    e, L = 0.3, 100.0
    law = EllipticalLaw(e)
    pc = PitchCurves(law, L)
    a, b, p, theta = _ellipse(e, L)
    phi = np.linspace(-PI + 1e-3, PI - 1e-3, 37)
    th = theta(phi)
    # the driver: r = p / (1 + e cos theta), its theta derivatives
    r = p / (1 + e * np.cos(th))
    r1 = p * e * np.sin(th) / (1 + e * np.cos(th)) ** 2
    r2 = p * e * (np.cos(th) * (1 + e * np.cos(th)) + 2 * e * np.sin(th) ** 2) / (1 + e * np.cos(th)) ** 3
    assert np.allclose(pc.r(phi), r, rtol=1e-13)
    assert np.allclose(pc.r_theta(phi), r1, rtol=1e-11, atol=1e-12)
    assert np.allclose(pc.r_thetatheta(phi), r2, rtol=1e-11, atol=1e-12)
    assert np.allclose(pc.driver_radius(th), r, rtol=1e-13)
    # the driven wheel: the same ellipse, r_H = p / (1 - e cos phi)
    rH = p / (1 - e * np.cos(phi))
    drH = -p * e * np.sin(phi) / (1 - e * np.cos(phi)) ** 2
    d2rH = p * e * (-np.cos(phi) * (1 - e * np.cos(phi)) + 2 * e * np.sin(phi) ** 2) / (1 - e * np.cos(phi)) ** 3
    assert np.allclose(pc.r_H(phi), rH, rtol=1e-13)
    assert np.allclose(pc.dr_H(phi), drH, rtol=1e-11, atol=1e-12)
    assert np.allclose(pc.d2r_H(phi), d2rH, rtol=1e-11, atol=1e-12)
    assert np.allclose(pc.ds_dphi(phi), np.hypot(rH, drH), rtol=1e-13)
    # radius of curvature of an ellipse at focal distance r: (r (2a - r))^(3/2) / (a b), both convex
    assert np.allclose(pc.rho(phi), (r * (2 * a - r)) ** 1.5 / (a * b), rtol=1e-11)
    assert np.allclose(pc.rho_H(phi), (rH * (2 * a - rH)) ** 1.5 / (a * b), rtol=1e-11)
    # points
    assert np.allclose(pc.driven_xy(phi), np.column_stack([rH * np.cos(phi), rH * np.sin(phi)]), rtol=1e-13,
                       atol=1e-12)
    assert np.allclose(pc.driver_xy(th), np.column_stack([r * np.cos(th), r * np.sin(th)]), rtol=1e-13, atol=1e-12)
    assert pc.driven_xy(0.0).shape == (2,) and pc.driven_xy([0.0, 1.0]).shape == (2, 2)
    assert pc.driver_xy([0, 1]).dtype == float
    assert pc.driver_xy(0.5).shape == (2,) and np.allclose(pc.driver_xy(0.5), pc.driver_radius(0.5) * np.array(
        [math.cos(0.5), math.sin(0.5)]), rtol=1e-15)
    assert np.allclose(pc.driver_xy(0.5), p / (1 + e * math.cos(0.5)) * np.array([math.cos(0.5), math.sin(0.5)]),
                       rtol=1e-13)
    # perimeters 4 a E(e), both
    P = 4 * a * ellipe(e * e)
    assert pc.perimeter_driven() == pytest.approx(P, rel=1e-13)
    assert pc.perimeter_driver() == pytest.approx(P, rel=1e-13)
    assert perimeter_per_mm(law) == pytest.approx(P / L, rel=1e-13)
    # the least radius of curvature: b^2/a = p at the ends of the major axis (phi = 0 or +-pi)
    for curve in ("driven", "driver"):
        cs = pc.curvature(curve)
        assert cs.rho_convex_min == pytest.approx(p, rel=1e-11)
        assert min(abs(cs.phi_convex_min), PI - abs(cs.phi_convex_min)) < 1e-5
        assert cs.concave is False and cs.concave_intervals == () and cs.corner is None
        assert cs.rho_concave_min == math.inf and math.isnan(cs.phi_concave_min)
        # lengths scale with L: the same pair at L = 0.01 mm (radii and their curvature 1e-4 of these)
        small = PitchCurves(law, L * 1e-4).curvature(curve)
        assert small.rho_convex_min == pytest.approx(p * 1e-4, rel=1e-11) and small.concave is False


def test_pitch1_is_the_law_written_out_at_one_angle():
    law = WalkingLaw(**SEED_000)
    L = 140.0
    pc = PitchCurves(law, L)
    for phi in (0.0, 0.3, -0.7, 1.9, PI / 4 - 1e-3):
        U, dU, _ = (float(v) for v in _walking_U((60.0, 100.0, 360.0, 2), phi))
        got = pc.pitch1(phi)
        assert got[0] == pytest.approx(U, rel=1e-14)
        assert got[1] == pytest.approx(L * U / (1 + U), rel=1e-14)
        assert got[2] == pytest.approx(L * dU / (1 + U) ** 2, rel=1e-13, abs=1e-13)
        assert all(type(v) is float for v in got)


def test_seed_000_derivatives_and_curvature_written_out():
    law = WalkingLaw(**SEED_000)
    L = 139.0
    pc = PitchCurves(law, L)
    phi = np.linspace(-PI / 4 + 1e-3, PI / 4 - 1e-3, 29) + PI / 2  # the second leg
    U, dU, d2U = _walking_U((60.0, 100.0, 360.0, 2), phi)
    q = 1 + U
    assert np.allclose(pc.r_H(phi), L * U / q, rtol=1e-14)
    assert np.allclose(pc.dr_H(phi), L * dU / q**2, rtol=1e-13, atol=1e-13)
    assert np.allclose(pc.d2r_H(phi), L * d2U / q**2 - 2 * L * dU**2 / q**3, rtol=1e-13, atol=1e-13)
    assert np.allclose(pc.r(phi), L / q, rtol=1e-14)
    # dr/dtheta = (dr/dphi) / U, d2r/dtheta2 = d/dphi(dr/dtheta) / U
    r_p = -L * dU / q**2
    r_pp = -L * d2U / q**2 + 2 * L * dU**2 / q**3
    assert np.allclose(pc.r_theta(phi), r_p / U, rtol=1e-13, atol=1e-13)
    assert np.allclose(pc.r_thetatheta(phi), (r_pp / U - r_p * dU / U**2) / U, rtol=1e-12, atol=1e-12)
    # the radius of curvature against the parametric curvature of the points (x'y'' - y'x'')
    law_U = lambda p: _walking_U((60.0, 100.0, 360.0, 2), p)
    assert np.allclose(pc.rho_H(phi), _rho_brute(law_U, L, "driven", phi)[0], rtol=1e-11)
    assert np.allclose(pc.rho(phi), _rho_brute(law_U, L, "driver", phi)[0], rtol=1e-11)


def test_polar_derivatives_of_the_smoothed_law_at_one_point_and_on_arrays():
    law = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.15)
    L = 124.3
    pc = PitchCurves(law, L)
    phis = np.array([0.0, 0.5, PI / 4 - 0.05, PI / 4 + 0.01, -0.77, 2.4])
    U, dU, d2U = law.U(phis), law.dU_dphi(phis), law.d2U_dphi2(phis)
    q = 1 + U
    expect = {"driven": (L * U / q, L * dU / q**2, L * d2U / q**2 - 2 * L * dU**2 / q**3)}
    r_p, r_pp = -L * dU / q**2, -L * d2U / q**2 + 2 * L * dU**2 / q**3
    expect["driver"] = (L / q, r_p / U, (r_pp / U - r_p * dU / U**2) / U)
    for curve in ("driven", "driver"):
        arr = pc._polar_derivatives(curve, phis)
        for got, want in zip(arr, expect[curve]):
            assert np.allclose(got, want, rtol=1e-12, atol=1e-12)
        for i, p in enumerate(phis):
            one = pc.polar_derivatives1(curve, float(p))
            for got, want in zip(one, expect[curve]):
                assert got == pytest.approx(want[i], rel=1e-12, abs=1e-12)
        # an integer angle is taken as the float
        assert pc.polar_derivatives1(curve, 0) == pc.polar_derivatives1(curve, 0.0)


def test_pitch_curves_refuse_a_bad_L_and_a_bad_law():
    law = WalkingLaw(**SEED_000)
    for bad in (0.0, -1.0):
        with pytest.raises(InputError) as e:
            PitchCurves(law, bad)
        assert str(e.value) == f"L = {bad!r}: must be > 0 mm"
    assert PitchCurves(law, 1e-9).L == 1e-9
    assert type(PitchCurves(law, 5).L) is float
    with pytest.raises(InputError) as e:
        PitchCurves("walking", 100.0)
    assert str(e.value) == "law = 'str': must be a drive law (laws.law.Law: U, theta, period, n)"


# --------------------------------------------------------------------------- corners
def test_corners_of_the_exact_walking_law_by_hand():
    """At the hand-over phi = pi/4 + k pi/2, U' jumps from -6bu/A to +6bu/A: the driven tangent turns by
    2 atan(|r_H'|/r_H) inwards (a notch), the driver's (dr/dtheta = -r_H'/U) by 2 atan(|r'|/r) outwards."""
    for abcn, L in (((60.0, 100.0, 360.0, 2), 136.6), ((100.0, 50.0, 236.5, 4), 124.2)):
        a, b, c, n = abcn
        law = WalkingLaw(a=a, b=b, c=c, n=n)
        pc = PitchCurves(law, L)
        A = a - b + c
        u = n * PI * A / (A * PI + 6 * b)
        U = u * A / A  # cos(pi/2) = 0 at the hand-over
        rH, r = L * U / (1 + U), L / (1 + U)
        d = L * (6 * b * u / A) / (1 + U) ** 2
        turn_driven = 2 * math.atan(d / rH)
        turn_driver = 2 * math.atan((d / U) / r)
        got = pc.corners()
        # each hand-over: the driven notch, then the driver tip if that body angle is new (n | 4: 4/n tips)
        want = []
        seen = set()
        for k in range(4):
            ph = PI / 4 + k * PI / 2
            want.append(("driven", ph, ph, turn_driven, "concave"))
            th = n * ph  # theta(pi/4 + k pi/2) = n (pi/4 + k pi/2): each leg turns the driver by n pi/2
            if round(th % (2 * PI), 6) not in seen:
                seen.add(round(th % (2 * PI), 6))
                want.append(("driver", ph, th, turn_driver, "convex"))
        assert len(got) == len(want) == 4 + 4 // n
        for cn, (curve, ph, ang, turn, kind) in zip(got, want):
            assert (cn.curve, cn.kind) == (curve, kind)
            assert cn.phi == pytest.approx(ph, abs=1e-15) and cn.angle == pytest.approx(ang, abs=1e-12)
            assert cn.turn == pytest.approx(turn, rel=1e-9)
            assert type(cn.angle) is float
    assert math.degrees(turn_driven) == pytest.approx(29.34, abs=0.01)  # seed 002


def test_corner_summary_of_the_exact_walking_law():
    """A corner wins over the smooth pieces: radius 0 at a convex tip (driver), 0 at a notch (driven)."""
    # seed 002: the driven curve is convex but for its notches; the driver convex but for its tip
    law = WalkingLaw(**SEED_002)
    L = 124.2
    pc = PitchCurves(law, L)
    law_U = lambda p: _walking_U((100.0, 50.0, 236.5, 4), p)
    dn = pc.curvature("driven")
    brute = _brute_summary(law_U, L, "driven", -PI / 4, PI / 4 - 1e-12)
    assert brute["intervals"] == [] and dn.concave is True
    assert dn.rho_concave_min == 0.0 and dn.phi_concave_min == PI / 4
    assert dn.concave_intervals == ((PI / 4, PI / 4),)
    assert dn.corner.curve == "driven" and dn.corner.kind == "concave" and dn.corner.phi == PI / 4
    assert dn.rho_convex_min == pytest.approx(brute["convex"][1], rel=1e-9)
    assert dn.phi_convex_min == pytest.approx(brute["convex"][0], abs=1e-6)
    dr = pc.curvature("driver")
    brute = _brute_summary(law_U, L, "driver", -PI / 4, PI / 4 - 1e-12)
    assert brute["intervals"] == [] and dr.concave is False
    assert dr.rho_convex_min == 0.0 and dr.phi_convex_min == PI / 4
    assert dr.corner.curve == "driver" and dr.corner.kind == "convex" and dr.concave_intervals == ()
    assert dr.rho_concave_min == math.inf and math.isnan(dr.phi_concave_min)
    # seed 000: the driver is concave next to its tips as well (two stretches of the leg)
    law = WalkingLaw(**SEED_000)
    L = 136.6
    pc = PitchCurves(law, L)
    law_U = lambda p: _walking_U((60.0, 100.0, 360.0, 2), p)
    dr = pc.curvature("driver")
    brute = _brute_summary(law_U, L, "driver", -PI / 4, PI / 4 - 1e-12)
    assert len(brute["intervals"]) == 2 == len(dr.concave_intervals) and dr.concave is True
    (a0, b0), (a1, b1) = dr.concave_intervals
    assert a0 == -PI / 4 and b1 == PI / 4
    assert b0 == pytest.approx(brute["intervals"][0][1], abs=2e-14)
    assert a1 == pytest.approx(brute["intervals"][1][0], abs=2e-14)
    assert b0 == pytest.approx(-a1, abs=1e-12)
    assert dr.rho_concave_min == pytest.approx(brute["concave"][1], rel=1e-9)
    assert abs(dr.phi_concave_min) == pytest.approx(abs(brute["concave"][0]), abs=1e-6)
    assert dr.rho_convex_min == 0.0 and dr.phi_convex_min == PI / 4 and dr.corner.kind == "convex"


# --------------------------------------------------------------------------- curvature of smooth laws
def test_curvature_of_the_smoothed_seed_000_law_against_the_parametric_curve():
    """The blended seed-000 law (scalar path: the solvers' one-point calls): convex least radius, the concave
    stretches' ends and least |radius| of both curves against the points' curvature on a 200 001-point grid."""
    base = WalkingLaw(**SEED_000)
    law = SmoothedWalkingLaw(base, 0.2)
    L = 138.0
    pc = PitchCurves(law, L)
    law_U = lambda p: (law.U(p), law.dU_dphi(p), law.d2U_dphi2(p))
    for curve in ("driven", "driver"):
        cs = pc.curvature(curve)
        brute = _brute_summary(law_U, L, curve, -PI / 4, PI / 4)
        assert cs.curve == curve and cs.corner is None
        assert cs.rho_convex_min == pytest.approx(brute["convex"][1], rel=1e-9)
        assert cs.phi_convex_min == pytest.approx(brute["convex"][0], abs=2e-6)
        assert len(cs.concave_intervals) == len(brute["intervals"]) >= 1
        assert cs.concave is True
        for got, want in zip(cs.concave_intervals, brute["intervals"]):
            assert got == pytest.approx(want, abs=2e-14)  # brentq to ROOT_XTOL_FINE = 1e-14
        assert cs.rho_concave_min == pytest.approx(brute["concave"][1], rel=1e-9)
        assert abs(cs.phi_concave_min) == pytest.approx(abs(brute["concave"][0]), abs=2e-6)  # +-: symmetric
        assert pc.curvature(curve) is cs  # computed once
    with pytest.raises(InputError) as e:
        pc.curvature("idler")
    assert str(e.value) == "curve = 'idler': must be 'driven' or 'driver'"


@pytest.mark.parametrize("cos, sin, L", [((0.3,), (0.1, 0.08), 100.0), ((0.0, 0.0, 0.0, 0.0, 0.03), (0.05,), 100.0),
                                         ((0.0, 0.0, 0.0, 0.0, 0.03), (0.05,), 0.01)])
def test_curvature_of_a_fourier_law_with_a_concave_stretch(cos, sin, L):
    """Fourier laws (the array path): concave stretches inside the period (the driver's with the first law, five on
    each wheel with the second; the second at L = 0.01 mm too, where D = r^2 + 2r'^2 - r r'' is below 1 mm^2)."""
    law = FourierLaw(k=1, cos=cos, sin=sin)
    pc = PitchCurves(law, L)
    law_U = lambda p: (law.U(p), law.dU_dphi(p), law.d2U_dphi2(p))
    concave_somewhere = []
    for curve in ("driven", "driver"):
        cs = pc.curvature(curve)
        brute = _brute_summary(law_U, L, curve, -PI, PI)
        concave_somewhere.append(bool(brute["intervals"]))
        assert cs.rho_convex_min == pytest.approx(brute["convex"][1], rel=1e-9)
        assert cs.phi_convex_min == pytest.approx(brute["convex"][0], abs=2e-6)
        assert len(cs.concave_intervals) == len(brute["intervals"])
        for got, want in zip(cs.concave_intervals, brute["intervals"]):
            assert got == pytest.approx(want, abs=2e-14)  # brentq to ROOT_XTOL_FINE = 1e-14
        assert cs.concave is bool(brute["intervals"])
        if brute["concave"]:
            assert cs.rho_concave_min == pytest.approx(brute["concave"][1], rel=1e-9)
            assert cs.phi_concave_min == pytest.approx(brute["concave"][0], abs=2e-6)
        else:
            assert cs.rho_concave_min == math.inf
    assert concave_somewhere == ([False, True] if cos == (0.3,) else [True, True])


def _flips(law, L, curve):
    """Sign changes of the curvature over one period, on a grid 20 times as dense as the module's."""
    law_U = lambda p: (law.U(p), law.dU_dphi(p), law.d2U_dphi2(p))
    phi = np.linspace(law.breakpoints[0], law.breakpoints[-1], 24001)
    s = np.sign(_rho_brute(law_U, L, curve, phi)[1])
    return int(np.sum(s[:-1] != s[1:]))


def test_a_law_whose_curve_flips_more_than_64_times_is_refused():
    L = 100.0
    for j, want in ((32, 64), (33, 66)):
        law = FourierLaw(k=1, sin=(0.0,) * (j - 1) + (0.02,))
        assert _flips(law, L, "driven") == want
        pc = PitchCurves(law, L)
        if want <= MAX_CURVATURE_FLIPS:
            # a concave stretch across the period's ends counts twice (its two ends): want/2 + 1 pieces
            assert len(pc.curvature("driven").concave_intervals) == want // 2 + 1
            continue
        with pytest.raises(InputError) as e:
            pc.curvature("driven")
        assert str(e.value) == (
            f"law = '{want} changes of curvature': the driven pitch curve turns from convex to concave and back "
            f"{want} times over one period, more than 64: no cutter generates such a curve; a smoother law "
            "(fewer or smoother rows of a table)")
    keyed = FourierLaw(k=1, sin=(0.0,) * 32 + (0.02,))
    object.__setattr__(keyed, "key", "law_file")
    with pytest.raises(InputError) as e:
        PitchCurves(keyed, L).curvature("driven")
    assert e.value.parameter == "law_file"
    assert e.value.limit.startswith("the driven pitch curve turns")


def test_extremes_of_convex_stretches_narrower_than_a_sample_stay_convex():
    """16 waves of 0.05 rad: the driven wheel's convex stretches are narrower than the samples' spacing (one sample
    each).  The least convex radius is that of a convex stretch (0.0195 mm, a quarter wave's peak), not the concave
    radius of the stretch next to it: the old code bracketed the search between convex samples 0.8 rad apart,
    across concave stretches, and gave rho_convex_min = -1.6e8 mm."""
    law = FourierLaw(k=1, sin=(0.0,) * 15 + (0.05,))
    L = 100.0
    cs = PitchCurves(law, L).curvature("driven")
    law_U = lambda p: (law.U(p), law.dU_dphi(p), law.d2U_dphi2(p))
    brute = _brute_summary(law_U, L, "driven", -PI, PI, N=100001)
    assert cs.rho_convex_min > 0
    assert cs.rho_convex_min == pytest.approx(brute["convex"][1], rel=1e-6)
    assert cs.rho_concave_min == pytest.approx(brute["concave"][1], rel=1e-6)
    # 16 waves: each stretch's extremes repeat every 2 pi / 16 of theta; the found ones lie on their own side
    rho_at = _rho_brute(law_U, L, "driven", np.array([cs.phi_convex_min, cs.phi_concave_min]))[0]
    assert rho_at[0] == pytest.approx(cs.rho_convex_min, rel=1e-9) and rho_at[1] < 0


# --------------------------------------------------------------------------- hub speed ripple
def test_hub_speed_ripple_of_the_blend_against_a_dense_grid():
    law = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.15)
    rip = hub_speed_ripple(law)
    phi = np.linspace(-PI / 4, PI / 4, 400001)
    v = law.hub_speed(phi)
    pmin, vmin = _refine_min(law.hub_speed, phi, v)
    pmax, negmax = _refine_min(lambda p: -law.hub_speed(p), phi, -v)
    vmax = -negmax
    mean = 286.5 / (4 * PI * 286.5 / (286.5 * PI + 300))
    assert rip.mean == pytest.approx(mean, rel=1e-14)
    assert rip.v_min == pytest.approx(vmin, rel=1e-12) and rip.v_max == pytest.approx(vmax, rel=1e-12)
    assert rip.ripple == pytest.approx((vmax - vmin) / mean, rel=1e-9)
    assert abs(rip.phi_min) == pytest.approx(abs(pmin), abs=1e-6)
    assert rip.phi_max == pytest.approx(pmax, abs=1e-5) or rip.phi_max == pytest.approx(-pmax, abs=1e-5)
    assert rip.v_min < mean < rip.v_max


# --------------------------------------------------------------------------- closure and teeth
def test_whole_teeth_refusals_in_full():
    assert whole_teeth("z_H", 96, 2) == 96 and type(whole_teeth("z_H", 96.0, 2)) is int
    assert whole_teeth("z_H", 1, 1) == 1
    assert whole_teeth("z_H", 4, 4) == 4
    for bad in (0, 0.0, -4, 95.5, 0.5):
        with pytest.raises(InputError) as e:
            whole_teeth("z_H", bad, 2)
        assert str(e.value) == f"z_H = {bad!r}: tooth count must be a whole number >= 1"
    with pytest.raises(InputError) as e:
        whole_teeth("driven_teeth", 97, 2)
    assert str(e.value) == ("driven_teeth = 97: must be a multiple of n = 2 so the driver has z_H/n whole teeth "
                            "(nearest valid: 96, 98)")
    with pytest.raises(InputError) as e:
        whole_teeth("z_H", 82.0, 4)
    assert str(e.value) == ("z_H = 82: must be a multiple of n = 4 so the driver has z_H/n whole teeth "
                            "(nearest valid: 80, 84)")
    with pytest.raises(InputError) as e:
        whole_teeth("z_H", 3, 4)  # below the first multiple: 4 twice
    assert str(e.value) == ("z_H = 3: must be a multiple of n = 4 so the driver has z_H/n whole teeth "
                            "(nearest valid: 4, 4)")
    with pytest.raises(InputError) as e:
        whole_teeth("z_H", math.nan, 2)
    assert str(e.value) == "z_H = nan: must be a finite number"


def test_centre_distance_and_module_of_the_circular_law():
    """The circular law (U = n): the driven circle of radius L n/(1+n) holds z_H teeth of module m when
    2 pi L n/(1+n) = pi m z_H: L = m z_H (1+n)/(2n)."""
    law = WalkingLaw(a=50.0, b=0.0, c=250.0, n=2)
    assert centre_distance(law, 2.0, 96) == pytest.approx(2.0 * 96 * 3 / 4, rel=1e-14)
    assert centre_distance(law, 2.5, 4.0) == pytest.approx(2.5 * 4 * 3 / 4, rel=1e-14)
    assert module_for(law, 144.0, 96) == pytest.approx(144.0 * 4 / (3 * 96), rel=1e-14)
    assert module_for(law, 3.0, 2) == pytest.approx(3.0 * 4 / (3 * 2), rel=1e-14)
    for f, name in ((centre_distance, "m"), (module_for, "L")):
        for bad in (0.0, -2.0):
            with pytest.raises(InputError) as e:
                f(law, bad, 96)
            assert str(e.value) == f"{name} = {bad!r}: must be > 0 mm"
        with pytest.raises(InputError) as e:
            f(law, 2.0, 97)
        assert str(e.value) == ("z_H = 97: must be a multiple of n = 2 so the driver has z_H/n whole teeth "
                                "(nearest valid: 96, 98)")
        with pytest.raises(InputError) as e:
            f(law, 2.0, 0)
        assert str(e.value) == "z_H = 0: tooth count must be a whole number >= 1"


def test_driven_teeth_both_sides_of_whole_and_the_nearest_valid_in_full():
    """z = L P1/(pi m) with P1 = 2 pi n/(1+n) (the circular law, n = 2): z = 4 L / (3 m)."""
    law = WalkingLaw(a=50.0, b=0.0, c=250.0, n=2)
    assert driven_teeth(law, 75.0, 1.0) == 100 and type(driven_teeth(law, 75.0, 1.0)) is int
    assert driven_teeth(law, 1.5, 1.0) == 2
    # one lobe, one tooth (n = 1: z = L / m): the least whole count
    assert driven_teeth(WalkingLaw(a=50.0, b=0.0, c=250.0, n=1), 1.0, 1.0) == 1
    # within TOOTH_COUNT_TOL = 1e-6 of a whole even count: accepted; 2e-6 off: refused
    assert driven_teeth(law, 75.0 * (1 + 0.5e-6 / 100), 1.0) == 100
    assert driven_teeth(law, 75.0 * (1 - 0.5e-6 / 100), 1.0) == 100

    def msg(L, m, z, options):
        parts = [f"z_H = {zz}: L = {m * zz * 3 / 4:.4f} mm at m = {m:g}, or m = {L * 4 / (3 * zz):.5f} mm at L = {L:g}"
                 for zz in options]
        return (f"L = {L!r}: gives z_H = {z:.4f} teeth of m = {m:g}, not a whole multiple of n = 2 "
                f"(nearest valid: {'; '.join(parts)})")

    for L, m, options in ((75.0 * (1 + 2e-6 / 100), 1.0, (100, 102)), (75.0 * (1 - 2e-6 / 100), 1.0, (98, 100)),
                          (75.6375, 1.0, (100, 102)), (75.75, 1.0, (100, 102)), (75.0, 1.01, (98, 100)),
                          (0.975, 1.0, (2,)), (1.5e-7, 1.0, (2,)), (0.0015, 0.0012, (2,)), (2.25, 1.0, (2, 4))):
        z = 4 * L / (3 * m)
        with pytest.raises(InputError) as e:
            driven_teeth(law, L, m)
        assert str(e.value) == msg(L, m, z, options), (L, m)
        assert e.value.parameter == "L"
    for name, args in (("L", (0.0, 1.0)), ("m", (75.0, -1.0))):
        with pytest.raises(InputError) as e:
            driven_teeth(law, *args)
        assert str(e.value) == f"{name} = {args[0] if name == 'L' else args[1]!r}: must be > 0 mm"


def test_whole_pitches_both_sides_of_the_tolerance():
    # exactly TOOTH_COUNT_TOL = 1e-6 pitches from a whole number (0): refused (the tolerance is strict)
    assert 1e-6 * PI / (PI * 1.0) == 1e-6
    with pytest.raises(InputError) as e:
        whole_pitches(1e-6 * PI, 1.0)
    assert str(e.value) == ("m = 1.0: the driven pitch curve (0.000003 mm) holds 0.000001 pitches, not a whole "
                            "number")
    m = 2.0
    P = PI * m * 40
    assert whole_pitches(P, m) == 40 and type(whole_pitches(P, m)) is int
    assert whole_pitches(P * (1 + 0.9e-6 / 40), m) == 40
    assert whole_pitches(P * (1 - 0.9e-6 / 40), m) == 40
    for P2 in (P * (1 + 1.1e-6 / 40), P * (1 - 1.1e-6 / 40), P + 1.0, PI * m * 40.5):
        z = P2 / (PI * m)
        with pytest.raises(InputError) as e:
            whole_pitches(P2, m)
        assert str(e.value) == (f"m = 2.0: the driven pitch curve ({P2:.6f} mm) holds {z:.6f} pitches, "
                                "not a whole number")


def test_perimeter_of_seed_002_by_quadrature_and_its_centre_distance():
    """Seed 002 (SPEC Trap 3): L = 124.20 at m = 2.5, z_H = 80; the perimeter per mm by quad of the law written
    out, the driver's by quad in theta over its body turn (pi/2 of phi: n = 4)."""
    law = WalkingLaw(**SEED_002)
    abcn = (100.0, 50.0, 236.5, 4)

    def ds(p):
        U, dU, _ = _walking_U(abcn, p)
        return float(math.hypot(U / (1 + U), dU / (1 + U) ** 2))

    P1 = 4 * quad(ds, -PI / 4, PI / 4, epsabs=1e-14, epsrel=1e-14)[0]
    assert perimeter_per_mm(law) == pytest.approx(P1, rel=1e-13)
    L = PI * 2.5 * 80 / P1
    assert round(L, 2) == 124.20
    assert centre_distance(law, 2.5, 80) == pytest.approx(L, rel=1e-13)
    pc = PitchCurves(law, L)
    assert pc.perimeter_driven() == pytest.approx(P1 * L, rel=1e-13)
    assert pc.perimeter_driver() == pytest.approx(P1 * L / 4, rel=1e-12)
    assert module_for(law, 124.0, 80) == pytest.approx(124.0 * P1 / (PI * 80), rel=1e-13)


# =========================================================================== gears/pitch_frame.py
def _ellipse_driven(e, L):
    """The k = 1 elliptical pair's driven wheel r_H = p / (1 - e cos phi) and its slope; its arc length by quad."""
    a, b, p, theta = _ellipse(e, L)
    rH = lambda f: p / (1 - e * np.cos(f))
    drH = lambda f: -p * e * np.sin(f) / (1 - e * np.cos(f)) ** 2
    arc = lambda f0, f1: quad(lambda f: math.hypot(rH(f), drH(f)), f0, f1, epsabs=1e-13, epsrel=1e-13, limit=200)[0]
    return rH, drH, arc


def test_arc_frame_of_the_circular_law_is_r_phi():
    from propulsor.gears.pitch_frame import ArcFrame

    law = WalkingLaw(a=50.0, b=0.0, c=250.0, n=2)
    L = 120.0
    rH = L * 2 / 3
    fr = ArcFrame(PitchCurves(law, L))
    assert fr.period == PI / 2 and fr._p0 == PI / 4
    assert len(fr.nodes) == 401 and fr.nodes[0] == -PI / 4 and fr.nodes[-1] == PI / 4
    assert np.allclose(fr.nodes, np.linspace(-PI / 4, PI / 4, 401), rtol=0, atol=1e-15)
    assert np.allclose(fr.S, rH * fr.nodes, rtol=0, atol=1e-11)
    assert fr.leg == pytest.approx(rH * PI / 2, rel=1e-14) and fr.perimeter == pytest.approx(2 * PI * rH, rel=1e-14)
    phi = np.array([-7.0, -PI / 4, -0.3, 0.0, 0.2, PI / 4, 1.0, 3.0, 12.5])
    assert np.allclose(fr.s(phi), rH * phi, rtol=0, atol=1e-10)
    assert np.allclose(fr.s_exact(phi), rH * phi, rtol=0, atol=1e-10)
    s = rH * phi
    assert np.allclose(fr.phi(s), phi, rtol=0, atol=1e-13)
    for x, ph in zip(s, phi):
        assert fr.phi1(float(x)) == pytest.approx(ph, abs=1e-13) and type(fr.phi1(float(x))) is float
    assert fr.phi1(math.nan) is None and fr.phi1(math.inf) is None and fr.phi1(-math.inf) is None
    assert fr.s(0.5).shape == (1,) and fr.phi(10.0).shape == (1,)
    assert len(ArcFrame(PitchCurves(law, L), per_piece=10).nodes) == 11


def test_arc_frame_of_the_elliptical_pair_against_quadrature():
    from propulsor.gears.pitch_frame import ArcFrame

    e, L = 0.4, 90.0
    law = EllipticalLaw(e)
    a, b, p, _ = _ellipse(e, L)
    rH, drH, arc = _ellipse_driven(e, L)
    fr = ArcFrame(PitchCurves(law, L))
    assert fr.period == 2 * PI and fr._p0 == PI and len(fr.nodes) == 401
    P = 4 * a * ellipe(e * e)
    assert fr.leg == pytest.approx(P, rel=1e-13) and fr.perimeter == pytest.approx(P, rel=1e-13)
    assert fr.S[0] == pytest.approx(-P / 2, rel=1e-13) and fr.S[-1] == pytest.approx(P / 2, rel=1e-13)
    for ph in (-2.9, -1.0, -0.01, 0.0, 0.37, 1.3, 3.0, 4.0, 7.5, -8.0):
        k = math.floor((ph + PI) / (2 * PI))
        w = ph - 2 * PI * k
        want = arc(0.0, w) + k * P
        assert float(fr.s(ph)[0]) == pytest.approx(want, abs=1e-8)  # the cubic Hermite interpolant
        assert float(fr.s_exact(ph)[0]) == pytest.approx(want, abs=1e-11)
        assert float(fr.phi(want)[0]) == pytest.approx(ph, abs=1e-9)
        assert fr.phi1(want) == pytest.approx(ph, abs=1e-9)
    # the node values are the arc lengths from phi = 0
    j = [0, 73, 200, 327, 400]
    assert np.allclose(fr.S[j], [arc(0.0, x) for x in fr.nodes[j]], rtol=0, atol=1e-10)


def test_arc_frame_of_the_blend_has_nodes_at_the_window_ends_and_repeats_per_leg():
    from propulsor.gears.pitch_frame import ArcFrame

    base = WalkingLaw(**SEED_002)
    law = SmoothedWalkingLaw(base, 0.15)
    L = 124.3
    pc = PitchCurves(law, L)
    fr = ArcFrame(pc, per_piece=50)
    bp = law.breakpoints
    assert len(bp) >= 3 and all(x in fr.nodes for x in bp)
    assert len(fr.nodes) == 50 * (len(bp) - 1) + 1
    ds = lambda f: float(np.hypot(pc.r_H(f), pc.dr_H(f)))
    leg = sum(quad(ds, x0, x1, epsabs=1e-13, epsrel=1e-13)[0] for x0, x1 in zip(bp[:-1], bp[1:]))
    assert fr.leg == pytest.approx(leg, rel=1e-12)
    assert fr.perimeter == pytest.approx(4 * leg, rel=1e-12)
    for ph in (0.1, PI / 4 - 0.1, PI / 4 + 0.05, -0.7):
        pts = [x for x in bp if min(0.0, ph) < x < max(0.0, ph)]
        want = math.copysign(quad(ds, min(0.0, ph), max(0.0, ph), points=pts or None, epsabs=1e-13)[0], ph)
        for k in (-2, 0, 3):
            assert float(fr.s_exact(ph + k * PI / 2)[0]) == pytest.approx(want + k * leg, abs=1e-9)
            assert float(fr.s(ph + k * PI / 2)[0]) == pytest.approx(want + k * leg, abs=1e-7)
            assert float(fr.phi(want + k * leg)[0]) == pytest.approx(ph + k * PI / 2, abs=1e-9)


def _ellipse_body(e, L):
    """Points and dP/dphi of the k = 1 elliptical pair in the body frames, by hand: the driven wheel at polar angle
    phi, the driver at pi - theta (tan(theta/2) = c tan(phi/2), c = (1+e)/(1-e))."""
    a, b, p, theta = _ellipse(e, L)
    c = (1 + e) / (1 - e)

    def driven(f):
        r = p / (1 - e * np.cos(f))
        dr = -p * e * np.sin(f) / (1 - e * np.cos(f)) ** 2
        P = np.column_stack([r * np.cos(f), r * np.sin(f)])
        dP = np.column_stack([dr * np.cos(f) - r * np.sin(f), dr * np.sin(f) + r * np.cos(f)])
        return P, dP

    def driver(f):
        th = theta(f)
        dth = c / np.cos(f / 2) ** 2 / (1 + (c * np.tan(f / 2)) ** 2)
        r = p / (1 + e * np.cos(th))
        dr = p * e * np.sin(th) / (1 + e * np.cos(th)) ** 2 * dth
        be, dbe = PI - th, -dth
        P = np.column_stack([r * np.cos(be), r * np.sin(be)])
        dP = np.column_stack([dr * np.cos(be) - r * dbe * np.sin(be), dr * np.sin(be) + r * dbe * np.cos(be)])
        return P, dP

    return driven, driver


def test_body_pitch_curves_of_the_elliptical_pair_by_hand():
    from propulsor.gears.pitch_frame import BodyPitchCurve

    e, L = 0.35, 80.0
    pc = PitchCurves(EllipticalLaw(e), L)
    a, b, p, _ = _ellipse(e, L)
    driven, driver = _ellipse_body(e, L)
    phis = np.array([-2.5, -1.0, -0.2, 0.0, 0.4, 1.7, 2.9])
    with pytest.raises(InputError) as err:
        BodyPitchCurve(pc, "idler")
    assert str(err.value) == "role = 'idler': must be 'driver' or 'driven'"
    for role, hand, sgn in (("driven", driven, -1.0), ("driver", driver, 1.0)):
        bc = BodyPitchCurve(pc, role)
        assert bc.sgn == sgn and bc.role == role and bc.pc is pc
        P, dP = hand(phis)
        t = sgn * dP / np.linalg.norm(dP, axis=1)[:, None]
        N = np.column_stack([-t[:, 1], t[:, 0]])
        # outward: away from the focus (the wheel's centre) on these convex ellipses
        assert np.all(np.einsum("ij,ij->i", N, P) > 0)
        r, ang = bc.polar(phis)
        assert np.allclose(r, np.hypot(P[:, 0], P[:, 1]), rtol=1e-13)
        assert np.allclose(np.cos(ang), P[:, 0] / r, atol=1e-12) and np.allclose(np.sin(ang), P[:, 1] / r, atol=1e-12)
        assert np.allclose(bc.point(phis), P, rtol=0, atol=1e-11)
        assert np.allclose(bc.dpoint(phis), dP, rtol=0, atol=1e-10)
        assert np.allclose(bc.normal(phis), N, rtol=0, atol=1e-12)
        for h in (1.5, -2.0):
            assert np.allclose(bc.offset(phis, h), P + h * N, rtol=0, atol=1e-11)
        rho = (np.hypot(P[:, 0], P[:, 1]) * (2 * a - np.hypot(P[:, 0], P[:, 1]))) ** 1.5 / (a * b)
        assert np.allclose(bc.rho(phis), rho, rtol=1e-11)
        # one point (the solvers' calls: a one-element array) the same, as a (1, 2) array
        for i, f in enumerate(phis):
            one = np.array([f])
            for got, want in ((bc.point(one), P[i]), (bc.dpoint(one), dP[i]), (bc.normal(one), N[i]),
                              (bc.offset(one, 0.75), P[i] + 0.75 * N[i]), (bc.offset(one, 2), P[i] + 2 * N[i]),
                              (bc.offset(one, np.float64(-1.25)), P[i] - 1.25 * N[i])):
                assert got.shape == (1, 2)
                assert np.allclose(got[0], want, rtol=0, atol=1e-10)
        # a float (not an array) and a longer array take the array path: the same points
        assert np.allclose(bc.point(0.4), P[4], atol=1e-11) and bc.point(0.4).shape == (1, 2)
        assert np.allclose(bc.dpoint(0.4), dP[4], atol=1e-10) and bc.dpoint(0.4).shape == (1, 2)
        assert np.allclose(bc.normal(0.4), N[4], atol=1e-12)
        assert np.allclose(bc.offset(np.array([0.4]), np.array([1.5])), P[4] + 1.5 * N[4], atol=1e-11)
        # a non-finite one-point call: the array path's nan
        assert np.all(np.isnan(bc.point(np.array([math.nan]))))


def test_one_is_a_finite_one_element_array():
    from propulsor.gears import pitch_frame as pf

    assert pf._one(np.array([0.5])) == 0.5 and type(pf._one(np.array([0.5]))) is float
    assert pf._one(np.array([3])) == 3.0
    for x in (0.5, np.array(0.5), np.array([0.5, 0.6]), np.array([[0.5]]), np.array([math.nan]),
              np.array([math.inf]), [0.5], np.float64(0.5)):
        assert pf._one(x) is None


# =========================================================================== gears/envelope_point.py
def test_nearer_circle_crossing_by_hand():
    from propulsor.gears.envelope_point import nearer_circle_crossing1

    # from (0, 0) along +x to the circle of radius 2 about (5, 0): crossings at x = 3 and 7, the nearer 3
    assert nearer_circle_crossing1(0.0, 0.0, 1.0, 0.0, 5.0, 0.0, 2.0) == pytest.approx((3.0, 0.0), abs=1e-15)
    # along -x: lambda = -3 or -7 (both behind): the nearer -3
    assert nearer_circle_crossing1(0.0, 0.0, -1.0, 0.0, 5.0, 0.0, 2.0) == pytest.approx((3.0, 0.0), abs=1e-15)
    # from inside, (5.5, 0) along +y about (5, 0), R = 2: lambda = +-sqrt(4 - 0.25)
    # both equally near (b = 0): the + root, as the array function (envelope.nearer_circle_crossing) takes it
    from propulsor.gears.envelope import nearer_circle_crossing

    got = nearer_circle_crossing1(5.5, 0.0, 0.0, 1.0, 5.0, 0.0, 2.0)
    assert got == pytest.approx((5.5, math.sqrt(3.75)), abs=1e-15)
    arr = nearer_circle_crossing(np.array([[5.5, 0.0]]), np.array([[0.0, 1.0]]), (5.0, 0.0), 2.0, "x", "y")
    assert tuple(arr[0]) == got
    # off-centre and slanted: the nearer of the two roots of |q + lam n|^2 = R^2, computed here
    px, py, nx, ny, cx, cy, R = 1.0, -2.0, 0.6, 0.8, 4.0, 3.0, 2.5
    qx, qy = px - cx, py - cy
    B, C = qx * nx + qy * ny, qx * qx + qy * qy - R * R
    l1, l2 = -B + math.sqrt(B * B - C), -B - math.sqrt(B * B - C)
    lam = min((l1, l2), key=abs)
    assert nearer_circle_crossing1(px, py, nx, ny, cx, cy, R) == pytest.approx((px + lam * nx, py + lam * ny),
                                                                            abs=1e-14)
    assert lam == l2 and abs(l1) > abs(l2)
    # the other way along the same line: the nearer is now l1's point
    got = nearer_circle_crossing1(px, py, -nx, -ny, cx, cy, R)
    assert got == pytest.approx((px + lam * nx, py + lam * ny), abs=1e-14)
    # a root nearer on the + side: from (9, 0) along -x, circle about (5, 0) R 2: lambda 2 (x = 7) or 6
    assert nearer_circle_crossing1(9.0, 0.0, -1.0, 0.0, 5.0, 0.0, 2.0) == pytest.approx((7.0, 0.0), abs=1e-15)
    # tangent (disc = 0): the touching point; missing: None
    assert nearer_circle_crossing1(0.0, 2.0, 1.0, 0.0, 5.0, 0.0, 2.0) == pytest.approx((5.0, 2.0), abs=1e-15)
    assert nearer_circle_crossing1(0.0, 2.5, 1.0, 0.0, 5.0, 0.0, 2.0) is None
    assert nearer_circle_crossing1(0.0, math.nan, 1.0, 0.0, 5.0, 0.0, 2.0) is None


class _Line:
    """A straight cutter piece P(u) = (u, 0.5 u), tangent (2, 1) (not unit)."""

    def point1(self, u):
        return u, 0.5 * u

    def tangent1(self, u):
        return 2.0, 1.0


class _Cutter:
    def __init__(self, s=None):
        self.s, self.calls = s, []

    def contact1(self, px, py, nx, ny, piece):
        self.calls.append((px, py, nx, ny, piece))
        return self.s if self.s is not None else px + 2 * py  # some parameter of the point

    def pose1(self, s):
        return 1.0 + s, -2.0, 0.3 * s  # the cutter's origin and angle at s


class _Gear:
    def __init__(self, none=False):
        self.none = none

    def pose1(self, s):
        return None if self.none else (10.0 - s, 4.0 + 0.5 * s, 1.1 - 0.2 * s)


def test_envelope_point_is_the_cutter_point_carried_into_the_gear():
    from propulsor.gears.envelope_point import envelope_point1

    piece, cutter, gear = _Line(), _Cutter(), _Gear()
    u = 0.8
    got = envelope_point1(piece, u, cutter, gear)
    assert got is not None
    pts, s = got
    px, py = u, 0.5 * u
    n = math.sqrt(5.0)
    # the contact is asked at the point with the unit normal (-t_y, t_x) of the unit tangent
    assert cutter.calls == [(px, py, -1.0 / n, 2.0 / n, piece)]
    s0 = px + 2 * py
    assert s.shape == (1,) and s[0] == s0
    cx, cy, ca = 1.0 + s0, -2.0, 0.3 * s0
    gx, gy, tau = 10.0 - s0, 4.0 + 0.5 * s0, 1.1 - 0.2 * s0
    th = tau - ca
    vx, vy = px - cx, py - cy
    want = (gx + math.cos(th) * vx - math.sin(th) * vy, gy + math.sin(th) * vx + math.cos(th) * vy)
    assert pts.shape == (1, 2) and tuple(pts[0]) == pytest.approx(want, abs=1e-14)
    for bad in (math.nan, math.inf):
        assert envelope_point1(piece, bad, _Cutter(), gear) is None
    assert envelope_point1(piece, u, _Cutter(s=math.nan), gear) is None
    assert envelope_point1(piece, u, _Cutter(s=math.inf), gear) is None
    assert envelope_point1(piece, u, cutter, _Gear(none=True)) is None

    class _NoContact(_Cutter):
        def contact1(self, *a):
            return None

    assert envelope_point1(piece, u, _NoContact(), gear) is None


# =========================================================================== gears/law_search.py
def test_margins_are_the_least_of_the_limits_named():
    from propulsor.gears.generability import CurveCheck, Generability
    from propulsor.gears.law_search import _margins

    def cc(curve, rcx, lim, concave, rcc, r0):
        return CurveCheck(curve=curve, rho_convex_min=rcx, rho_limit=lim, concave=concave, rho_concave_min=rcc,
                          r0=r0, ok=True, reason="")

    g = Generability(driver=cc("driver", 20.0, 17.0, False, 1.0, 30.0), driven=cc("driven", 50.0, 17.0, True, 25.0, 20.5))
    # driver convex 3, driver concave not counted (not concave: 1 - 30 would be least), driven convex 33,
    # driven concave 4.5
    assert _margins(g) == (3.0, "driver convex vs rack undercut limit")
    g = Generability(driver=cc("driver", 20.0, 17.0, True, 19.0, 17.5), driven=cc("driven", 18.0, 17.0, True, 25.0, 20.5))
    assert _margins(g) == (1.0, "driven convex vs rack undercut limit")
    g = Generability(driver=cc("driver", 20.0, 17.0, True, 19.0, 18.5), driven=cc("driven", 18.0, 17.0, False, 2.0, 20.5))
    assert _margins(g) == (0.5, "driver concave vs shaper r0 + e")
    g = Generability(driver=cc("driver", 30.0, 17.0, False, 0.0, 0.0), driven=cc("driven", 18.0, 17.0, True, 20.0, 20.25))
    assert _margins(g) == (-0.25, "driven concave vs shaper r0 + e")


def test_pareto_against_its_definition():
    from propulsor.gears.law_search import pareto

    rng = np.random.default_rng(7)
    for larger in (True, False):
        for _ in range(20):
            n = int(rng.integers(1, 12))
            rip = rng.integers(0, 4, n).astype(float) / 100  # ties in both columns
            val = rng.integers(0, 4, n).astype(float)
            got = pareto(val, rip, larger_is_better=larger)
            v = val if larger else -val
            want = [not any(rip[j] <= rip[i] and v[j] >= v[i] and (rip[j] < rip[i] or v[j] > v[i]) for j in range(n))
                    for i in range(n)]
            assert got.dtype == bool and got.tolist() == want
    # equal points keep each other; a point better in one and equal in the other beats
    assert pareto(np.array([1.0, 1.0]), np.array([0.1, 0.1]), True).tolist() == [True, True]
    assert pareto(np.array([1.0, 2.0]), np.array([0.1, 0.1]), True).tolist() == [False, True]
    assert pareto(np.array([1.0, 2.0]), np.array([0.1, 0.1]), False).tolist() == [True, False]
    assert pareto(np.array([1.0, 1.0]), np.array([0.2, 0.1]), True).tolist() == [False, True]


def _generable_at(law, delta, q, m, z_H, cutter, L_ref, band):
    """(law, L, generability) of the blend of half-width delta and hand-over value q u if both curves are generable
    and L lies within the band, else None (the search's own test of a point, written out)."""
    from propulsor.gears.generability import check_generable

    try:
        sl = SmoothedWalkingLaw(law, delta, u_h=q * law.u)
    except InputError:
        return None
    L = PI * m * z_H / perimeter_per_mm(sl)
    g = check_generable(PitchCurves(sl, L), cutter)
    return (sl, L, g) if g.ok and abs(L - L_ref) <= band else None


def test_search_law_on_a_short_scan_by_hand(monkeypatch):
    """Seed 002, m = 2.5, z_H = 80, x = +-0.5, the d0 = 25 mm shaper; blends of 3, 8 and 14 deg, hand-over values
    1.00 ... 1.03 u, 4 bisections.  3 deg: nothing generable (skipped); 8 deg: the first generable value 1.02 u, the
    least between 1.01 and 1.02 found to 0.01/16; 14 deg: generable at 1.00 u already (no bisection)."""
    import propulsor.gears.law_search as ls
    from propulsor.gears.catalogue import catalogue_shaper
    from propulsor.gears.generability import CutterSpec
    from propulsor.gears.law_search import LawPoint, search_law

    monkeypatch.setattr(ls, "LAW_SEARCH_DELTA_DEG", (3.0, 8.0, 14.0))
    monkeypatch.setattr(ls, "LAW_SEARCH_UH_SCAN", (1.0, 1.01, 1.02, 1.03))
    monkeypatch.setattr(ls, "LAW_SEARCH_UH_BISECTIONS", 4)
    law = WalkingLaw(**SEED_002)
    m, z_H, band = 2.5, 80, 5.0
    sh = catalogue_shaper(25.0, m)
    L_ref = centre_distance(law, m, z_H)
    res = search_law(law, m, z_H, 0.5, [(25, sh)], L_ref, band)
    cutter = CutterSpec(m=m, x=0.5, x_H=-0.5, z0=sh.z0, shaper_x0=sh.x0)
    ok = lambda d, q: _generable_at(law, d, q, m, z_H, cutter, L_ref, band)
    assert all(ok(math.radians(3.0), q) is None for q in (1.0, 1.01, 1.02, 1.03))
    d8, d14 = math.radians(8.0), math.radians(14.0)
    assert ok(d8, 1.01) is None and ok(d8, 1.02) is not None and ok(d14, 1.0) is not None
    assert res.evaluations == 4 + (3 + 4) + 1
    assert res.L_ref == L_ref and res.L_band == 5.0 and type(res.L_band) is float
    assert len(res.points) == 2
    by_delta = {round(p.delta, 12): p for p in res.points}
    p8, p14 = by_delta[round(d8, 12)], by_delta[round(d14, 12)]
    assert p14.u_h_rel == 1.0
    assert 1.01 < p8.u_h_rel <= 1.02 and ok(d8, p8.u_h_rel) is not None and ok(d8, p8.u_h_rel - 0.01 / 16) is None
    assert (p8.u_h_rel - 1.01) * 1600 == pytest.approx(round((p8.u_h_rel - 1.01) * 1600), abs=1e-9)
    for p in (p8, p14):
        sl, L, g = ok(p.delta, p.u_h_rel)
        assert p.d0_mm == 25.0 and type(p.d0_mm) is float and p.z0 == sh.z0 and type(p.z0) is int
        assert p.L == pytest.approx(L, rel=1e-14)
        assert p.ripple == pytest.approx(hub_speed_ripple(sl).ripple, rel=1e-12)
        limits = {"driver convex vs rack undercut limit": g.driver.rho_convex_min - g.driver.rho_limit,
                  "driven convex vs rack undercut limit": g.driven.rho_convex_min - g.driven.rho_limit}
        for c in (g.driver, g.driven):
            if c.concave:
                limits[f"{c.curve} concave vs shaper r0 + e"] = c.rho_concave_min - c.r0
        assert p.binding == min(limits, key=limits.get) and p.margin_mm == pytest.approx(min(limits.values()), abs=1e-12)
        assert all(type(getattr(p, f)) is float for f in ("delta", "u_h_rel", "L", "ripple", "margin_mm"))
    # ranked by ripple; the fronts by their definition over the two points
    assert [p.ripple for p in res.points] == sorted(p.ripple for p in res.points)
    assert res.best is res.points[0]
    a, b = res.points
    for p, q in ((a, b), (b, a)):
        beaten_L = q.ripple <= p.ripple and q.L <= p.L and (q.ripple < p.ripple or q.L < p.L)
        beaten_M = q.ripple <= p.ripple and q.margin_mm >= p.margin_mm and (q.ripple < p.ripple or q.margin_mm > p.margin_mm)
        assert p.front_L is (not beaten_L) and p.front_margin is (not beaten_M)
    assert isinstance(a, LawPoint)
    # a band of 0.1 mm drops 8 deg's point (L_exact + 0.11 mm at 1.02 u: the bisection finds none within it)
    narrow = search_law(law, m, z_H, 0.5, [(25, sh)], L_ref, 0.1)
    assert [round(p.delta, 12) for p in narrow.points] == [round(d14, 12)]


def test_search_law_refusal_in_full(monkeypatch):
    import propulsor.gears.law_search as ls
    from propulsor.gears.catalogue import catalogue_shaper
    from propulsor.gears.law_search import search_law

    monkeypatch.setattr(ls, "LAW_SEARCH_DELTA_DEG", (3.0,))
    monkeypatch.setattr(ls, "LAW_SEARCH_UH_SCAN", (1.0, 1.2))
    law = WalkingLaw(**SEED_002)
    L_ref = centre_distance(law, 2.5, 80)
    with pytest.raises(InputError) as e:
        search_law(law, 2.5, 80, 0.5, [(25.0, catalogue_shaper(25.0, 2.5)), (38, catalogue_shaper(38.0, 2.5))],
                   L_ref, 5)
    assert str(e.value) == (f"L_band = 5: no blend keeps both pitch curves generable with |L - L_exact| <= 5 mm "
                            f"(L_exact = {L_ref:.3f} mm) for the shapers d0 = 25, 38 mm at m = 2.5 mm (a larger "
                            "driver_shift, more teeth or a larger band)")
    assert f"{L_ref:.3f}" == "124.198"


def test_arc_frame_of_a_fourier_law_against_quadrature_and_its_own_inverse():
    """A Fourier law with sine terms (ds/dphi not even in phi): s(phi) from 0 by quad; phi(s) is the inverse of
    s(phi) to rounding (one Newton step on the interpolant), at the start of a leg (its first node spacing) too."""
    from propulsor.gears.pitch_frame import ArcFrame

    law = FourierLaw(k=2, cos=(0.0, 0.05), sin=(0.08,))
    L = 90.0
    pc = PitchCurves(law, L)
    fr = ArcFrame(pc)
    ds = lambda f: float(np.hypot(pc.r_H(f), pc.dr_H(f)))
    leg = quad(ds, -PI / 2, PI / 2, epsabs=1e-13, epsrel=1e-13, limit=200)[0]
    assert fr.leg == pytest.approx(leg, rel=1e-13) and fr.perimeter == pytest.approx(2 * leg, rel=1e-13)
    first = fr.nodes[1] - fr.nodes[0]
    for ph in (-PI / 2 + 0.3 * first, PI / 2 + 0.3 * first, -1.2, -0.05, 0.7, 1.5, 2.9, -4.0):
        k = math.floor((ph + PI / 2) / PI)
        w = ph - k * PI
        want = math.copysign(quad(ds, min(0.0, w), max(0.0, w), epsabs=1e-13, epsrel=1e-13, limit=200)[0], w) + k * leg
        assert float(fr.s_exact(ph)[0]) == pytest.approx(want, abs=1e-10)
        assert float(fr.s(ph)[0]) == pytest.approx(want, abs=5e-8)  # the cubic Hermite interpolant
        assert float(fr.phi(want)[0]) == pytest.approx(ph, abs=1e-9)
        assert fr.phi1(want) == pytest.approx(ph, abs=1e-9)
    # node values: the arc from 0 to each node
    j = [0, 50, 133, 200, 301, 400]
    want = [math.copysign(quad(ds, min(0.0, x), max(0.0, x), epsabs=1e-13, epsrel=1e-13)[0], x) for x in fr.nodes[j]]
    assert np.allclose(fr.S[j], want, rtol=0, atol=1e-10)


def test_arc_frame_inverse_is_polished_to_rounding_on_a_steep_law():
    """a = 0, b = 106, c = 127 mm, n = 1 (the class docstring's case): the two interpolants alone disagree by up to
    1e-9 rad; after the Newton step s(phi(s)) = s to rounding, at every point of a leg."""
    from propulsor.gears.pitch_frame import ArcFrame

    law = SmoothedWalkingLaw(WalkingLaw(a=0.0, b=106.0, c=127.0, n=1), 0.3)
    fr = ArcFrame(PitchCurves(law, 100.0))
    s = np.linspace(fr.S[0], fr.S[-1], 4001)[:-1]
    s = np.concatenate([s, fr.S[0] + (fr.S[1] - fr.S[0]) * np.array([0.25, 0.5, 0.75])])  # the first node spacing
    back = fr.s(fr.phi(s))
    assert np.max(np.abs(back - s)) < 2e-12
    raw = fr._s_of(fr._phi_of(s))  # the inverse interpolant alone: the error the step removes
    assert np.max(np.abs(raw - s)) > 1e-9
    for x in np.concatenate([s[::400], s[-3:]]):
        assert float(fr.s(fr.phi1(float(x)))[0]) == pytest.approx(x, abs=2e-12)


def test_body_pitch_curves_radius_of_curvature_is_each_wheels_own():
    """A Fourier law whose wheels differ: the driven wheel's rho_H, the driver's rho, against the points' parametric
    curvature (x'y'' - y'x'') / |P'|^3."""
    from propulsor.gears.pitch_frame import BodyPitchCurve

    law = FourierLaw(k=1, cos=(0.3,), sin=(0.1, 0.08))
    L = 100.0
    pc = PitchCurves(law, L)
    law_U = lambda p: (law.U(p), law.dU_dphi(p), law.d2U_dphi2(p))
    phi = np.linspace(-3.0, 3.0, 25)
    for role in ("driven", "driver"):
        want = _rho_brute(law_U, L, role, phi)[0]
        assert np.allclose(BodyPitchCurve(pc, role).rho(phi), want, rtol=1e-10)
    assert not np.allclose(_rho_brute(law_U, L, "driven", phi)[0], _rho_brute(law_U, L, "driver", phi)[0], rtol=1e-3)


def test_arc_frame_sums_its_quadratures_within_one_smooth_piece():
    """The blend is only C2 at its window ends: a 10-point Gauss rule across one loses 2e-7 mm there.  With coarse
    nodes (1 and 2 a piece) s(0) = 0 and s just beside each window end still agree with quad to rounding: every
    quadrature starts at a node of its own piece."""
    from propulsor.gears.pitch_frame import ArcFrame

    law = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.15)
    pc = PitchCurves(law, 124.3)
    bp = law.breakpoints
    ds = lambda f: float(np.hypot(pc.r_H(f), pc.dr_H(f)))

    def arc(w):
        pts = [b for b in bp if min(0.0, w) < b < max(0.0, w)]
        return math.copysign(quad(ds, min(0.0, w), max(0.0, w), points=pts or None, epsabs=1e-13)[0], w)

    for per_piece in (1, 2):
        fr = ArcFrame(pc, per_piece=per_piece)
        assert len(fr.nodes) == 3 * per_piece + 1
        assert float(fr.s_exact(0.0)[0]) == pytest.approx(0.0, abs=1e-12)
        assert float(fr.s(0.0)[0]) == pytest.approx(0.0, abs=1e-9)  # the interpolant through S: 0 at its nodes
        assert np.allclose(fr.S, [arc(x) for x in fr.nodes], rtol=0, atol=1e-11)
        for b in bp[1:-1]:
            for w in (b - 1e-3, b + 1e-3, b - 0.06, b + 0.06):  # beside the window end and inside the pieces
                assert float(fr.s_exact(w)[0]) == pytest.approx(arc(w), abs=1e-11)


def test_search_law_cuts_with_the_pressure_angle_and_addendum_given(monkeypatch):
    """alpha = 22 deg, h_a* = 0.9: every point's margin and binding limit are those of that rack (undercut limit
    (h_a* - x) m / sin^2 alpha) and shaper, not of the 20 deg, h_a* = 1 defaults."""
    import propulsor.gears.law_search as ls
    from propulsor.gears.catalogue import catalogue_shaper
    from propulsor.gears.generability import CutterSpec, check_generable
    from propulsor.gears.law_search import search_law

    monkeypatch.setattr(ls, "LAW_SEARCH_DELTA_DEG", (14.0, 24.0))
    monkeypatch.setattr(ls, "LAW_SEARCH_UH_SCAN", (1.0, 1.05))
    monkeypatch.setattr(ls, "LAW_SEARCH_UH_BISECTIONS", 2)
    law = WalkingLaw(**SEED_002)
    m, z_H = 2.5, 80
    alpha, h_a = math.radians(22.0), 0.9
    sh = catalogue_shaper(25.0, m)
    res = search_law(law, m, z_H, 0.5, [(25.0, sh)], centre_distance(law, m, z_H), 5.0, alpha=alpha, h_a=h_a)
    assert res.points
    mine = CutterSpec(m=m, alpha=alpha, h_a=h_a, x=0.5, x_H=-0.5, z0=sh.z0, shaper_x0=sh.x0)
    assert mine.rho_limit(0.5) == pytest.approx((0.9 - 0.5) * 2.5 / math.sin(alpha) ** 2, rel=1e-12)
    for p in res.points:
        sl = SmoothedWalkingLaw(law, p.delta, u_h=p.u_h_rel * law.u)
        g = check_generable(PitchCurves(sl, p.L), mine)
        assert g.ok
        limits = {"driver convex vs rack undercut limit": g.driver.rho_convex_min - g.driver.rho_limit,
                  "driven convex vs rack undercut limit": g.driven.rho_convex_min - g.driven.rho_limit}
        for c in (g.driver, g.driven):
            if c.concave:
                limits[f"{c.curve} concave vs shaper r0 + e"] = c.rho_concave_min - c.r0
        assert p.binding == min(limits, key=limits.get)
        assert p.margin_mm == pytest.approx(min(limits.values()), abs=1e-12)
