"""Composite (polysector) gear, pure math (seed 003): eq. 1–8, 12–14, 9–11, 15–22 against independent
computations — hand-worked cases, the limiting case e = 0 (the composite is the blank gear), and the
generated tooth outline itself."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.involute import inv
from propulsor.gears.polysector import (EPS_S_MIN, PolysectorGeometry, delta_eq1_printed, delta_eq3,
                                        delta_outer_corner, epsilon_alpha_pair, pole_flank, ratio_eq5, ratio_eq7,
                                        ratio_error_eq6, ratio_error_eq8, sector_teeth_eq2, tooth_position_error)
from propulsor.gears.polysector_dynamics import TorsionalModel, loss_eq12, loss_eq13, loss_instant

A20 = math.radians(20.0)


def geo(**kw):
    base = dict(m=3.0, z=36, z_c=10, i_s=3, z2=40)
    base.update(kw)
    return PolysectorGeometry(**base)


# --- eq. 2 ------------------------------------------------------------------------------------------
def test_eq2_sector_teeth_and_the_gaps():
    assert sector_teeth_eq2(36, 3, 2) == 10
    assert sector_teeth_eq2(30, 3, 1) == 9
    assert geo().k_gap == 2
    with pytest.raises(InputError, match="too large for the gaps"):
        geo(z_c=12)  # z/i_s = 12: no empty pitch left
    with pytest.raises(InputError, match="multiple"):
        geo(z=34)  # sectors of the two flows would be out of tooth phase


# --- eq. 1 / 3: δ against the generated tooth -------------------------------------------------------
@pytest.mark.parametrize("thinning", [0.0, 0.1])
def test_delta_of_eq3_and_eq1_swapped_are_the_tip_corners_of_the_generated_tooth(thinning):
    from propulsor.geometry.gear_outline import external_gear_profile

    g = geo(thinning=thinning)
    blank = external_gear_profile(36, 3.0, 0.0, thinning_n_mm=thinning)
    half_tip = blank.side.tip_angle  # half angular tooth thickness at the tip, measured on the outline
    centre = (g.z_c - 1) * math.pi / g.z  # the extreme tooth's centre line
    d_in, d_out = g.tip_land()
    assert d_in == pytest.approx(centre - half_tip, abs=1e-7)
    assert d_out == pytest.approx(centre + half_tip, abs=1e-7)
    # as printed, eq. 1's δ is no point of the tooth
    printed = delta_eq1_printed(g.z_c, g.z, A20, g.r_b, g.r_a)
    assert min(abs(printed - d_in), abs(printed - d_out)) > 1e-3
    assert delta_eq3(g.z_c, g.z, A20, g.r_b, g.r_a) == pytest.approx(
        (2 * g.z_c - 3) * math.pi / (2 * g.z) - inv(A20) + inv(math.acos(g.r_b / g.r_a)), abs=1e-15)
    assert delta_outer_corner(g.z_c, g.z, A20, g.r_b, g.r_a) == pytest.approx(
        (2 * g.z_c - 1) * math.pi / (2 * g.z) + inv(A20) - inv(math.acos(g.r_b / g.r_a)), abs=1e-15)


def test_exit_angle_at_e0_is_the_intersection_of_the_tip_circles():
    """Hand-worked e = 0: the sector is the blank; a tip corner at δ leaves the gear's tip circle where the two
    tip circles cross, at λ from the line of centres: cos λ = (r_a² + a² − r_a2²)/(2 a r_a), i.e. at u = λ + δ.
    The tip land leaves by its outer corner; a sector drives from the leading tooth's driving (outer) corner
    entering, −(λ + δ_out), to the trailing tooth's driving corner (eq. 3's δ_in) leaving, λ + δ_in."""
    g = geo()
    a = g.center_distance(0.0)
    lam = math.acos((g.r_a ** 2 + a * a - g.r_a2 ** 2) / (2 * a * g.r_a))
    d_in, d_out = g.tip_land()
    assert g.exit_angle(0.0) == pytest.approx(lam + d_out, abs=1e-10)
    assert g.driving_span(0.0) == pytest.approx((-(lam + d_out), lam + d_in), abs=1e-10)
    pf, pb = g.epsilon_s(0.0)
    assert pf == pytest.approx((2 * lam + d_in + d_out) * 3 / (2 * math.pi), abs=1e-10)
    assert pb == pytest.approx(2 * pf, abs=1e-12)


def test_largest_offset_from_the_driving_corner():
    """m 4, z 30, z_c 9, i_s 3, z2 24: counting the whole tip land (its non-driving corners too) accepts
    offsets up to 38.36 mm; with the driving corners ε_s (both flows) falls to 1.05 at 33.70 mm, and there the
    trailing tooth's driving corner (eq. 3's C) leaves the gear's tip circle."""
    g = PolysectorGeometry(m=4.0, z=30, z_c=9, i_s=3, z2=24, thinning=0.1)
    e_max = g.max_offset()
    assert e_max == pytest.approx(33.70, abs=0.01)
    u0, u1 = g.driving_span(e_max)
    assert (u1 - u0) * 6 / (2 * math.pi) > EPS_S_MIN  # ε_s is still 1.14 there, but just beyond it ...
    with pytest.raises(InputError, match="driving corner does not reach"):
        g.driving_span(e_max + 1e-6)  # ... the leading tooth's driving corner never reaches the gear
    # while the tip land (by its non-driving corner) still reaches far into the gear's tip circle
    assert 2 * g.exit_angle(e_max + 4.0) * 6 / (2 * math.pi) > EPS_S_MIN
    cp = g.corner_pose(e_max)
    assert cp["delta"] == g.tip_land()[0] and cp["on_tip_circle"] < 1e-9


@pytest.mark.parametrize("e", [0.0, 9.0, 18.0, 27.0])
def test_eq1_rows_hold_at_the_exit_pose(e):
    g = geo()
    cp = g.corner_pose(e)
    assert cp["on_tip_circle"] < 1e-9
    # O1C from the coordinates of C agrees with rows 3 and 5 (corrected sign) and row 2 of eq. 1
    assert np.max(np.abs(cp["residuals"])) < 1e-8
    assert cp["CD"] == pytest.approx(2 * g.r_a * math.sin(cp["delta"] / 2), abs=1e-12)
    o1c2 = e * e + g.r_a ** 2 + 2 * e * g.r_a * math.cos(cp["delta"])
    assert cp["O1C"] ** 2 == pytest.approx(o1c2, rel=1e-12)
    # the printed '+' of row 5 does not close the triangle O1DC (except at δ = 0)
    wrong = cp["CD"] ** 2 + (e + g.r_a) ** 2 + 2 * cp["CD"] * (e + g.r_a) * math.sin(cp["delta"] / 2)
    assert abs(wrong - o1c2) > 1.0


def test_largest_offset_is_where_eps_s_falls_to_1_05_or_the_driving_corner_stops_reaching_the_gear():
    g = geo()
    e_max = g.max_offset()
    assert e_max == pytest.approx(28.171, abs=1e-3)  # 28.264 with the part's 0.1 mm thinning
    # default design: ε_s never falls to 1.05; the leading tooth's driving corner stops reaching the gear first
    assert g.epsilon_s(e_max)[1] > EPS_S_MIN
    with pytest.raises(InputError, match="driving corner does not reach"):
        g.epsilon_s(e_max + 1e-6)
    g2 = geo(z2=100, z_c=8)  # a larger gear: here ε_s falls to 1.05 while the corners still reach it
    e2 = g2.max_offset()
    assert g2.epsilon_s(e2)[1] == pytest.approx(EPS_S_MIN, abs=1e-8)
    eps = [g.epsilon_s(e)[1] for e in (0.0, 9.0, 18.0, 27.0)]
    assert all(x > y for x, y in zip(eps, eps[1:]))  # the overlap shrinks as the sectors move out
    with pytest.raises(InputError, match="eq. 4"):
        geo(z_c=2).max_offset()  # sectors too short: below 1.05 already at e = 0


@pytest.mark.parametrize("z,z_c,i_s,z2", [(36, 10, 3, 40), (30, 8, 3, 30), (48, 10, 4, 100), (24, 10, 2, 17)])
def test_one_flow_overlap_with_flank_contact_only_is_below_one(z, z_c, i_s, z2):
    g = PolysectorGeometry(m=2.0, z=z, z_c=z_c, i_s=i_s, z2=z2)
    ea = epsilon_alpha_pair(z, z2, 2.0, A20)
    assert g.flank_overlap_one_flow() == pytest.approx((z_c - 1 + ea) / (z_c + g.k_gap), abs=1e-15)
    assert g.flank_overlap_one_flow() < 1.0


@pytest.mark.parametrize("z1,z2", [(20, 40), (36, 40), (54, 40)])
def test_epsilon_alpha_of_a_standard_pair_against_the_iso_sheet(z1, z2):
    from propulsor.gears.gear_pair import GearPair
    from propulsor.gears.involute import SpurGear

    pair = GearPair(SpurGear(z=z1, m=3.0), SpurGear(z=z2, m=3.0))
    assert epsilon_alpha_pair(z1, z2, 3.0, A20) == pytest.approx(pair.epsilon_alpha(), rel=1e-12)


# --- eq. 5-8 -----------------------------------------------------------------------------------------
def test_eq7_eq8_at_the_nominal_pressure_angle():
    assert ratio_eq7(60.0, 114.0, A20, A20) == pytest.approx(60.0 / 54.0, rel=1e-15)
    assert ratio_error_eq8(60.0, 114.0, A20, A20) == pytest.approx(0.0, abs=1e-15)


def test_eq5_eq6_internal_mesh_against_the_pole():
    """Internal mesh, hand-worked: d1 = 60, d2 = 120 (a = 30); the pole at O2P = r2 cos α / cos α_wt lies
    outside both centres, O1P = O2P − a; i_t = O2P/O1P."""
    d1, d2 = 60.0, 120.0
    for awt in (A20, math.radians(22.0), math.radians(18.5)):
        o2p = 60.0 * math.cos(A20) / math.cos(awt)
        i_t = o2p / (o2p - 30.0)
        assert ratio_eq5(d1, d2, A20, awt) == pytest.approx(i_t, rel=1e-13)
        assert ratio_error_eq6(d1, d2, A20, awt) == pytest.approx(1.0 - i_t / 2.0, abs=1e-13)


def test_pole_at_e0_is_the_pitch_point_and_off_centre_a_true_common_tangent():
    g = geo()
    u = np.linspace(-1.0, 1.0, 41)
    o2p, o1p = pole_flank(0.0, u, g.r_b, g.r_b2, g.center_distance(0.0))
    assert np.allclose(o2p, g.r2, atol=1e-12) and np.allclose(o1p, g.r, atol=1e-12)
    assert np.allclose(g.ratio_flank(0.0, u), g.ratio_nominal(0.0), rtol=1e-13)
    # e > 0: the line through the pole at α_wt is tangent to both base circles (independent construction)
    e = 18.0
    a = g.center_distance(e)
    for uu in (-0.4, 0.0, 0.3):
        o2p, o1p = pole_flank(e, uu, g.r_b, g.r_b2, a)
        P = np.array([float(o1p), 0.0])
        O2 = np.array([a, 0.0])
        Op = e * np.array([math.cos(uu), math.sin(uu)])
        # the tangent from P to the gear's base circle on the driving side, then its distance from O'
        ang = math.acos(g.r_b2 / float(o2p))  # α_wt
        d = np.array([math.sin(ang), math.cos(ang)])  # direction of the line of action (up-right)
        n = np.array([d[1], -d[0]])
        assert abs(float(np.dot(O2 - P, n))) == pytest.approx(g.r_b2, abs=1e-9)
        assert abs(float(np.dot(Op - P, n))) == pytest.approx(g.r_b, abs=1e-9)
        assert float(o2p) + float(o1p) == pytest.approx(a, abs=1e-12)
    assert g.ratio_flank(e, 0.0) == pytest.approx(g.ratio_nominal(e), rel=1e-12)  # mid-line on the line of centres


# --- eq. 15-22 ----------------------------------------------------------------------------------------
def test_position_error_vanishes_at_e0():
    for r_y in (52.0, 54.0, 55.5):
        rows = tooth_position_error(3.0, 36, 10, 0.0, A20, r_y)
        assert len(rows) == 20
        assert max(r["R"] for r in rows) < 1e-9


def test_position_error_sector_points_against_the_polar_involute():
    """e > 0: the sector's flank point on the circle r_y about O1 from the polar involute (ρ', angle) about
    O' found by an independent root search, against eq. 20's rotated frame."""
    from scipy.optimize import brentq

    m, z, z_c, e, r_y = 3.0, 36, 10, 18.0, 72.0
    r = m * z / 2
    rb = r * math.cos(A20)
    rows = tooth_position_error(m, z, z_c, e, A20, r_y)
    for row in rows:
        n, side = row["tooth"] - 1, (1 if row["flank"] == "right" else -1)
        off = n - (z_c - 1) / 2

        def pt(rho):
            ang = off * 2 * math.pi / z + side * (math.pi / (2 * z) + inv(A20) - inv(math.acos(rb / rho)))
            return rho * math.sin(ang), rho * math.cos(ang)  # clockwise from the mid-line (+Y)

        f = lambda rho: math.hypot(pt(rho)[0], pt(rho)[1] + e) - r_y
        if f(rb) < 0 < f(r + m):
            rho = brentq(f, rb, r + m, xtol=1e-14)
            x, y = pt(rho)
            assert row["x_sector"] == pytest.approx(x, abs=1e-9)
            assert row["y_sector"] == pytest.approx(y, abs=1e-9)
            assert math.hypot(row["x_cond"], row["y_cond"] + e) == pytest.approx(r_y, abs=1e-9)
            assert row["R"] == pytest.approx(math.hypot(row["x_cond"] - x, row["y_cond"] - y), abs=1e-9)
        else:
            assert math.isnan(row["R"])
    # the middle teeth deviate least (the pitch arcs touch at M)
    R = {(r_["tooth"], r_["flank"]): r_["R"] for r_ in rows}
    assert R[(5, "right")] < R[(3, "right")]


# --- eq. 12-14 --------------------------------------------------------------------------------------
def test_eq12_equals_eq13_for_a_symmetric_active_line():
    m, z1, z2, f = 3.0, 36, 40, 0.06
    ea = epsilon_alpha_pair(z1, z2, m, A20)
    g = ea * math.pi * m * math.cos(A20)
    assert loss_eq12(f, m, A20, z1, z2, g / 2, g / 2) == pytest.approx(loss_eq13(f, ea, z1, z2), rel=1e-13)
    assert loss_eq12(f, m, A20, z1, z2, 0.3 * g, 0.7 * g) > loss_eq13(f, ea, z1, z2)
    assert loss_eq13(f, ea, z1, 80, internal=True) < loss_eq13(f, ea, z1, 80)


def test_instant_loss_of_a_solid_pair():
    """ψ = f·l·(1/r_b1 + 1/r_b2) for a solid pair (i_t = r_b2/r_b1, power arm r_b1)."""
    rb1, rb2, f, l = 50.0, 70.0, 0.07, 2.5
    assert loss_instant(f, l, rb2 / rb1, rb1) == pytest.approx(f * l * (1 / rb1 + 1 / rb2), rel=1e-14)


# --- eq. 9-11 -----------------------------------------------------------------------------------------
def test_torsional_model_static_deflection_and_frequencies():
    mdl = TorsionalModel(J1=0.01, J2=0.002, J3=0.002, J4=0.005, J5=0.02, c1=2e4, c2=1e4, i54=0.5, zeta=0.1, M4=20.0)
    # natural frequencies of (q2, q3): det(K − ω² M) = 0 by hand
    J3, J45 = 0.002, 0.005 + 0.02 * 0.25
    a_ = J3 * J45
    b_ = -(2e4 * J45 + 1e4 * (J3 + J45))
    c_ = 2e4 * 1e4
    w2 = sorted([(-b_ - s * math.sqrt(b_ * b_ - 4 * a_ * c_)) / (2 * a_) for s in (1, -1)])
    assert mdl.natural_frequencies() == pytest.approx(np.sqrt(w2), rel=1e-10)
    # constant ratio: the static state stays, M1 = Π' M4
    i21 = 0.9
    res = mdl.simulate(30.0, lambda q: np.full_like(np.asarray(q, float), i21), lambda q: np.zeros_like(np.asarray(q, float)),
                       0.05, n_out=200)
    assert np.allclose(res.q2, -20.0 / 2e4, atol=1e-12) and np.allclose(res.q3, -20.0 / 1e4, atol=1e-12)
    assert np.allclose(res.M1, i21 * 20.0, rtol=1e-9)
    assert res.torque_factor == pytest.approx(1.0, abs=1e-9)


def test_torsional_model_responds_to_a_ratio_ripple():
    mdl = TorsionalModel(J1=0.01, J2=0.002, J3=0.002, J4=0.005, J5=0.02, c1=2e4, c2=2e4, zeta=0.05, M4=20.0)
    amp, k = 1e-3, 6.0
    res = mdl.simulate(30.0, lambda q: 0.9 + amp * k * np.cos(k * np.asarray(q)),
                       lambda q: -amp * k * k * np.sin(k * np.asarray(q)), 0.2, n_out=400)
    assert res.torque_factor > 1.0 + 1e-3


def test_torsional_model_exact_solution_under_a_spline_transmission_matches_a_tight_integration():
    """simulate(..., breaks=knots) solves eq. 10 exactly (matrix exponentials of the ramp-forced system between the
    knots of Π''); DOP853 at rtol 1e-12, restarted at every knot (where the forcing has a corner), agrees to 1e-10 of
    the swing, and the default (Radau, rtol 1e-8, one run over the corners) to 1e-5."""
    from scipy.integrate import solve_ivp
    from scipy.interpolate import CubicSpline

    mdl = TorsionalModel(J1=0.01, J2=0.002, J3=0.002, J4=0.005, J5=0.02, c1=2e4, c2=1e4, i54=0.5, zeta=0.05, M4=20.0)
    rng = np.random.default_rng(1)
    per, n = 2 * math.pi / 9, 60
    x = np.linspace(0.0, per, n + 1)
    te = 1e-3 * rng.standard_normal(n)
    cs = CubicSpline(x, np.append(te, te[0]), bc_type="periodic")
    d1, d2 = cs.derivative(1), cs.derivative(2)
    Pi1 = lambda q: 0.9 + d1(np.mod(q, per))  # noqa: E731
    Pi2 = lambda q: d2(np.mod(q, per))  # noqa: E731
    om = 30.0
    t_end = 2 * math.pi / om
    breaks = (x[None, :] + per * np.arange(10)[:, None]).ravel()
    ex = mdl.simulate(om, Pi1, Pi2, t_end, 1500, breaks=breaks)
    A, g, h = mdl.state_matrices()
    y = np.array([-20.0 / 2e4, -20.0 / 1e4, 0.0, 0.0])
    ref = np.empty((len(ex.t), 4))
    tb = np.unique(np.concatenate([[0.0, t_end], breaks[(breaks > 0) & (breaks < om * t_end)] / om]))
    for a, b in zip(tb[:-1], tb[1:]):
        r = solve_ivp(lambda t, y: A @ y + g * float(Pi2(om * t)) * om * om + h, (a, b), y, method="DOP853",
                      rtol=1e-12, atol=1e-18, dense_output=True)
        sel = (ex.t >= a) & (ex.t <= b)
        ref[sel] = r.sol(ex.t[sel]).T
        y = r.y[:, -1]
    for k, got in ((0, ex.q2), (1, ex.q3)):
        swing = float(np.ptp(ref[:, k]))
        assert swing > 1e-4  # the ripple drives the system
        assert np.abs(got - ref[:, k]).max() <= 1e-10 * swing
    radau = mdl.simulate(om, Pi1, Pi2, t_end, 1500)
    assert np.abs(radau.M1 - ex.M1).max() <= 1e-5 * float(np.ptp(ex.M1))
    assert radau.torque_factor == pytest.approx(ex.torque_factor, rel=1e-6)


def test_a_sector_of_one_tooth_is_refused():
    """z_c = 1 leaves room for the empty pitch (eq. 2) but a sector needs two teeth to hand over."""
    from propulsor.errors import InputError
    from propulsor.gears.polysector import PolysectorGeometry

    PolysectorGeometry(m=4.0, z=30, z_c=2, i_s=3, z2=24)
    with pytest.raises(InputError, match=r"z_c = 1: must be >= 2"):
        PolysectorGeometry(m=4.0, z=30, z_c=1, i_s=3, z2=24)
