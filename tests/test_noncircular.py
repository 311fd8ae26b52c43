"""Pitch curves, closure, curvature, corners and C2 smoothing of the walking law (SPEC §3)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, assume
from hypothesis import strategies as st
from scipy.integrate import quad

from propulsor.errors import InputError
from propulsor.gears.generability import CutterSpec, check_generable, choose_smoothing
from propulsor.gears.noncircular import (
    PitchCurves,
    SmoothedWalkingLaw,
    centre_distance,
    driven_teeth,
    hub_speed_ripple,
    module_for,
    perimeter_per_mm,
)
from propulsor.gears.sectors import sector_hub_speed, sector_table
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw, wrap_leg

LAW0 = WalkingLaw(**SEED_000)
LAW2 = WalkingLaw(**SEED_002)


# --------------------------------------------------------------------------- pitch curves
def test_pitch_radii_sum_to_L_and_ratio():
    pc = PitchCurves(LAW0, 143.5)
    phi = np.linspace(0, 2 * math.pi, 301)
    assert np.allclose(pc.r_H(phi) + pc.r(phi), 143.5)
    assert np.allclose(pc.r_H(phi) / pc.r(phi), LAW0.U(phi))
    # seed 000 eq. 12 at phi = 0: 143.5 * 2 pi (A + 3b) / ((A pi + 6 b) + 2 pi (A + 3b))
    A, b = 320.0, 100.0
    eq12 = 143.5 * 2 * math.pi * (A + 3 * b) / ((A * math.pi + 6 * b) + 2 * math.pi * (A + 3 * b))
    assert pc.r_H(0.0) == pytest.approx(eq12, rel=1e-14)


def test_derivatives_match_finite_differences():
    sl = SmoothedWalkingLaw(LAW0, 0.2)
    pc = PitchCurves(sl, 140.0)
    phi = np.linspace(-0.7, 0.7, 57) + 0.013
    h = 1e-5
    assert np.allclose((pc.r_H(phi + h) - pc.r_H(phi - h)) / (2 * h), pc.dr_H(phi), atol=1e-6)
    assert np.allclose((pc.dr_H(phi + h) - pc.dr_H(phi - h)) / (2 * h), pc.d2r_H(phi), atol=1e-5)
    # driver derivatives in theta, through the inverse theta -> phi
    th = sl.theta(phi)
    r_of_th = lambda t: pc.driver_radius(t)
    assert np.allclose((r_of_th(th + h) - r_of_th(th - h)) / (2 * h), pc.r_theta(phi), atol=1e-6)
    assert np.allclose((r_of_th(th + h) - 2 * r_of_th(th) + r_of_th(th - h)) / h**2,
                       pc.r_thetatheta(phi), atol=2e-3)


def _fd_curvature(xy_fun, s, h=1e-4):
    p0, pp, pm = xy_fun(s), xy_fun(s + h), xy_fun(s - h)
    d1 = (pp - pm) / (2 * h)
    d2 = (pp - 2 * p0 + pm) / h**2
    return (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.hypot(d1[:, 0], d1[:, 1]) ** 3


@pytest.mark.parametrize("law, L", [(LAW0, 139.0), (LAW2, 124.3)])
def test_radius_of_curvature_vs_finite_differences(law, L):
    """rho from the polar formula vs curvature of the xy points (independent path)."""
    sl = SmoothedWalkingLaw(law, 0.15)
    pc = PitchCurves(sl, L)
    phi = np.linspace(-math.pi / 4 + 0.003, math.pi / 4 - 0.003, 91)
    kappa = _fd_curvature(pc.driven_xy, phi)
    assert np.allclose(1 / pc.rho_H(phi), kappa, rtol=1e-4, atol=1e-6)
    th = sl.theta(phi)
    kappa_d = _fd_curvature(pc.driver_xy, th)
    assert np.allclose(1 / pc.rho(phi), kappa_d, rtol=1e-4, atol=1e-6)


def test_perimeters_closure_driver_is_driven_over_n():
    """Driver perimeter integrated in theta == driven perimeter / n (rolling, n | 4)."""
    for law, L in ((LAW0, 136.6), (LAW2, 124.2), (WalkingLaw(a=80, b=60, c=300, n=1), 150.0)):
        for lw in (law, SmoothedWalkingLaw(law, 0.1)):
            pc = PitchCurves(lw, L)
            assert pc.perimeter_driver() == pytest.approx(pc.perimeter_driven() / law.n, rel=1e-10)


def test_true_arc_length_not_r_dphi():
    """SPEC Trap 3: the perimeter uses sqrt(r^2 + r'^2); r dphi alone is shorter."""
    pc = PitchCurves(LAW0, 143.5)
    edges = [-math.pi / 4, math.pi / 4]
    true_leg = quad(lambda p: float(np.hypot(pc.r_H(p), pc.dr_H(p))), *edges, epsabs=1e-12)[0]
    naive_leg = quad(lambda p: float(pc.r_H(p)), *edges, epsabs=1e-12)[0]
    assert pc.perimeter_driven() == pytest.approx(4 * true_leg, rel=1e-12)
    assert 4 * naive_leg < pc.perimeter_driven() - 1.0


def test_centre_distance_from_module_seeds():
    """SPEC Trap 3: exact law, seed 000 L = 136.61 at m = 2, z_H = 96; seed 002 L = 124.20 at m = 2.5, z_H = 80."""
    L0 = centre_distance(LAW0, m=2.0, z_H=96)
    L2 = centre_distance(LAW2, m=2.5, z_H=80)
    assert round(L0, 2) == 136.61
    assert round(L2, 2) == 124.20
    assert PitchCurves(LAW0, L0).perimeter_driven() == pytest.approx(math.pi * 2 * 96, rel=1e-12)
    # the seeds' own L do not give their module
    assert module_for(LAW0, 143.5, 96) == pytest.approx(2.0 * 143.5 / L0, rel=1e-12)
    assert abs(module_for(LAW0, 143.5, 96) - 2.0) > 0.05
    assert module_for(LAW2, L2, 80) == pytest.approx(2.5, rel=1e-12)
    assert driven_teeth(LAW2, L2, 2.5) == 80


def test_teeth_not_whole_names_nearest():
    with pytest.raises(InputError) as e:
        driven_teeth(LAW0, 143.5, 2.0)
    msg = str(e.value)
    assert e.value.parameter == "L"
    assert "z_H = 100" in msg and "z_H = 102" in msg  # 143.5 gives 100.85 teeth, n = 2
    L100 = centre_distance(LAW0, 2.0, 100)
    assert f"{L100:.4f}" in msg
    with pytest.raises(InputError) as e:
        centre_distance(LAW2, 2.5, 82)  # not a multiple of n = 4
    assert e.value.parameter == "z_H" and "80" in str(e.value) and "84" in str(e.value)
    with pytest.raises(InputError):
        centre_distance(LAW2, 2.5, 80.5)
    with pytest.raises(InputError) as e:
        PitchCurves(WalkingLaw(a=60, b=100, c=360, n=3), 140.0)
    assert e.value.parameter == "n"


# --------------------------------------------------------------------------- Trap 2
def test_corners_of_exact_law():
    L0 = centre_distance(LAW0, 2.0, 96)
    corners = PitchCurves(LAW0, L0).corners()
    assert len(corners) == 6  # 4 notches on the driven wheel, 2 tips on the driver body (n = 2)
    driven = [c for c in corners if c.curve == "driven"]
    driver = [c for c in corners if c.curve == "driver"]
    assert all(c.kind == "concave" for c in driven) and all(c.kind == "convex" for c in driver)
    # tangent turns ~80 deg in seed 000 (SPEC): 2 atan(|r'|/r) at the hand-over
    assert math.degrees(driven[0].turn) == pytest.approx(79.55, abs=0.01)
    # driver tips at theta = pi/2 + k pi (two tips per driver turn, n = 2)
    assert {round(c.angle % (2 * math.pi), 9) for c in driver} == {
        round(math.pi / 2, 9), round(3 * math.pi / 2, 9)}
    cs = PitchCurves(LAW0, L0).curvature("driver")
    assert cs.rho_convex_min == 0.0
    # next to its tips the seed-000 driver is even concave (large radius): check the sign of rho
    assert cs.concave and len(cs.concave_intervals) == 2
    a, b = cs.concave_intervals[1]
    pc0 = PitchCurves(LAW0, L0)
    assert pc0.rho(0.5 * (a + b)) < 0 < pc0.rho(a - 0.01)
    assert cs.rho_concave_min == pytest.approx(np.min(np.abs(pc0.rho(np.linspace(a, b - 1e-9, 2001)))), rel=1e-6)
    assert len(PitchCurves(LAW2, 124.2).corners()) == 5  # n = 4: one driver tip
    assert PitchCurves(LAW0, L0).curvature("driven").concave
    L2 = centre_distance(LAW2, 2.5, 80)
    assert PitchCurves(LAW2, L2).curvature("driver").rho_convex_min == 0.0
    assert PitchCurves(SmoothedWalkingLaw(LAW0, 0.1), L0).corners() == []


def test_undercut_limits_of_spec():
    assert CutterSpec(m=2.0).rho_limit(0.0) == pytest.approx(17.10, abs=0.005)
    assert CutterSpec(m=2.5).rho_limit(0.0) == pytest.approx(21.37, abs=0.005)
    g = check_generable(PitchCurves(LAW0, centre_distance(LAW0, 2.0, 96)), CutterSpec(m=2.0, z0=20))
    assert not g.ok and not g.driver.ok and "undercut" in g.driver.reason


# --------------------------------------------------------------------------- smoothing
@pytest.mark.parametrize("law", [LAW0, LAW2])
@pytest.mark.parametrize("delta", [0.02, 0.15, math.pi / 8])
def test_smoothing_closure_and_periodicity(law, delta):
    sl = SmoothedWalkingLaw(law, delta)
    assert abs(float(sl.theta(2 * math.pi)) - 2 * math.pi * law.n) < 1e-9
    # independent: quadrature of U_s over the turn split at the window ends
    edges = sorted({0.0, 2 * math.pi} | {e for w in sl.windows for e in w if 0 <= e <= 2 * math.pi})
    total = sum(quad(lambda p: float(sl.U(p)), a, b, epsabs=1e-13, epsrel=1e-13)[0]
                for a, b in zip(edges[:-1], edges[1:]))
    last = sl.windows[-1]
    if last[1] > 2 * math.pi:  # window wrapping past 2 pi is covered by periodicity
        pass
    assert abs(total - 2 * math.pi * law.n) < 1e-9
    phi = np.linspace(-4, 4, 97)
    assert np.allclose(sl.U(phi + math.pi / 2), sl.U(phi), rtol=1e-12)
    # outside the windows the exact law is untouched
    out = np.abs(wrap_leg(phi - math.pi / 4)) > delta
    assert np.allclose(sl.U(phi[out]), law.U(phi[out]), rtol=1e-14)
    # theta_s is the integral of U_s: finite differences
    h = 1e-6
    assert np.allclose((sl.theta(phi + h) - sl.theta(phi - h)) / (2 * h), sl.U(phi), rtol=1e-7)


@pytest.mark.parametrize("law", [LAW0, LAW2])
def test_smoothing_is_C2(law):
    """U_s, U_s', U_s'' continuous at the window ends and at the hand-over; the exact law is not."""
    delta = 0.12
    sl = SmoothedWalkingLaw(law, delta)
    h = 1e-10
    for x in (math.pi / 4 - delta, math.pi / 4 + delta, math.pi / 4, 3 * math.pi / 4 + delta):
        for f in (sl.U, sl.dU_dphi, sl.d2U_dphi2):
            assert abs(float(f(x + h)) - float(f(x - h))) < 1e-6
        # derivatives consistent with finite differences across the joint
        hh = 1e-5  # a jump J of the 3rd derivative at a C2 joint shifts the 2nd difference by ~J hh / 6
        fd1 = (sl.U(x + hh) - sl.U(x - hh)) / (2 * hh)
        fd2 = (sl.U(x + hh) - 2 * sl.U(x) + sl.U(x - hh)) / hh**2
        assert fd1 == pytest.approx(float(sl.dU_dphi(x)), abs=1e-5)
        assert fd2 == pytest.approx(float(sl.d2U_dphi2(x)), abs=1e-2)
        fd3 = (sl.dU_dphi(x + hh) - 2 * sl.dU_dphi(x) + sl.dU_dphi(x - hh)) / hh**2
        assert abs(fd3) < 5e3  # ~ mean of the one-sided 3rd derivatives: bounded, no spike
    # the exact law at the hand-over: slope jump, second difference blows up
    x = math.pi / 4
    assert abs(law.dU_dphi(x + h) - law.dU_dphi(x - h)) > 1.0
    hh = 1e-5
    assert abs((law.U(x + hh) - 2 * law.U(x) + law.U(x - hh)) / hh**2) > 1e5


def test_rho_continuous_with_smoothing():
    sl = SmoothedWalkingLaw(LAW2, 0.15)
    pc = PitchCurves(sl, 124.3)
    for x in (math.pi / 4 - 0.15, math.pi / 4 + 0.15, math.pi / 4):
        assert pc.rho(x + 1e-8) == pytest.approx(pc.rho(x - 1e-8), rel=1e-5)
        assert pc.rho_H(x + 1e-8) == pytest.approx(pc.rho_H(x - 1e-8), rel=1e-5)


@settings(max_examples=40, deadline=None)
@given(a=st.floats(0, 200), b=st.floats(1, 200), c=st.floats(50, 500), n=st.sampled_from([1, 2, 4]),
       delta=st.floats(0.005, math.pi / 4))
def test_smoothing_properties(a, b, c, n, delta):
    assume(a - b + c > 10)
    law = WalkingLaw(a=a, b=b, c=c, n=n)
    try:
        sl = SmoothedWalkingLaw(law, delta)
    except InputError as e:  # only allowed reason: the blend would make U <= 0
        assert e.parameter == "delta"
        return
    assert abs(float(sl.theta(2 * math.pi)) - 2 * math.pi * n) < 1e-9
    # C2 matching at the window end t = delta, against the exact law there
    x = math.pi / 4 + delta
    for order, f in ((0, law.U), (1, law.dU_dphi), (2, law.d2U_dphi2)):
        exact = float(f(x + 1e-15))  # just outside the window: the exact law
        assert float(sl.blend(delta, order)) == pytest.approx(exact, rel=1e-9, abs=1e-9 * (1 + sl.K / delta**order))
    # window integral kept: odd antiderivative of the blend vs the exact law's
    exact_int = 2 * (law.u * delta + sl.K * (1 - math.cos(2 * delta)) / 2)
    assert 2 * float(sl.blend(delta, -1)) == pytest.approx(exact_int, rel=1e-12)
    phi = np.linspace(0, math.pi / 2, 50)
    assert np.all(sl.U(phi) > 0)
    r = hub_speed_ripple(sl)
    assert r.mean == pytest.approx(law.A / law.u)
    assert r.v_min <= r.mean <= r.v_max


# --------------------------------------------------------------------------- the price
def test_exact_law_has_no_ripple_and_sector_method_has():
    assert hub_speed_ripple(LAW0).ripple < 1e-12
    r0 = sector_hub_speed(sector_table(LAW0, 143.5, 24)).ripple
    r2 = sector_hub_speed(sector_table(LAW2, 125.0, 20)).ripple
    assert r0 == pytest.approx(0.132, abs=0.002)   # SPEC: about 13 %
    assert r2 == pytest.approx(0.083, abs=0.002)   # SPEC: about 8 %


def test_ripple_value_and_location():
    sl = SmoothedWalkingLaw(LAW2, 0.15)
    r = hub_speed_ripple(sl)
    phi = np.linspace(-math.pi / 4, math.pi / 4, 200001)
    v = sl.hub_speed(phi)
    assert r.ripple == pytest.approx(np.ptp(v) / (LAW2.A / LAW2.u), rel=1e-6)
    # the minimum at the hand-over, the maximum inside the window
    assert abs(abs(r.phi_min) - math.pi / 4) < 1e-6
    assert math.pi / 4 - 0.15 < abs(r.phi_max) < math.pi / 4
    # a narrower window costs less ripple
    assert hub_speed_ripple(SmoothedWalkingLaw(LAW2, 0.05)).ripple < r.ripple


def test_choose_smoothing_seed002():
    """Seed 002, m = 2.5, z_H = 80: driver shift +0.5, shaper z0 = 20 for the concave driven dent."""
    cutter = CutterSpec(m=2.5, x=0.5, z0=20)
    d = choose_smoothing(LAW2, cutter, 80)
    assert d.generability.ok
    assert d.closure_error < 1e-9
    assert d.z == 20
    assert d.pair.perimeter_driven() == pytest.approx(math.pi * 2.5 * 80, rel=1e-12)
    # the binding constraint sits at its limit: a slightly narrower blend fails
    narrower = SmoothedWalkingLaw(LAW2, d.delta * 0.99)
    L_n = math.pi * 2.5 * 80 / perimeter_per_mm(narrower)
    assert not check_generable(PitchCurves(narrower, L_n), cutter).ok
    # the price beats the sector method's ~8 %
    assert 0.0 < d.ripple.ripple < 0.05
    assert d.delta == pytest.approx(0.1479, abs=5e-4)
    assert d.ripple.ripple == pytest.approx(0.0294, abs=5e-4)


def test_choose_smoothing_fails_with_numbers():
    """Seed 000 with an unshifted rack: no delta up to pi/8 works; the error says what would."""
    with pytest.raises(InputError) as e:
        choose_smoothing(LAW0, CutterSpec(m=2.0, x=0.0, z0=20), 96)
    msg = str(e.value)
    assert e.value.parameter == "delta_max"
    assert "undercut limit 17.097" in msg and "x >=" in msg and "z_H >=" in msg
    assert "\n" not in msg
    with pytest.raises(InputError) as e:
        choose_smoothing(LAW2, CutterSpec(m=2.5, x=0.5), 80)  # no shaper: concave dent remains
    assert "shaper" in str(e.value)


def test_bad_smoothing_input():
    with pytest.raises(InputError) as e:
        SmoothedWalkingLaw(LAW0, 0.0)
    assert e.value.parameter == "delta"
    with pytest.raises(InputError):
        SmoothedWalkingLaw(LAW0, 1.0)
    with pytest.raises(InputError) as e:
        CutterSpec(m=2.0, z0=3)
    assert e.value.parameter == "z0"
    with pytest.raises(InputError) as e:
        CutterSpec(m=-2.0)
    assert e.value.parameter == "m"


def test_cutter_spec_gives_each_gear_its_shift():
    """One imaginary rack: the driver is cut with x, the driven wheel with x_H."""
    from propulsor.gears.involute import BasicRack

    c = CutterSpec(m=2.5, x=0.5, x_H=-0.5, z0=20)
    rack = BasicRack()
    drv, dvn = c.tooth_spec("driver", rack, 0.1, 0.6), c.tooth_spec("driven", rack, 0.1, 0.6)
    assert (drv.x, dvn.x) == (0.5, -0.5)
    assert drv.m == dvn.m == 2.5 and drv.z0 == dvn.z0 == 20 and drv.thinning_mm == 0.1 and drv.tip_min_mm == 0.6
    with pytest.raises(InputError):
        c.shift("idler")
