"""Exact values of the spur gear geometry and the load per tooth's math (issue 36, mutation testing of the
`gears_spur` target): each expected value computed here independently from the standard (ISO 21771, ISO 6336,
DIN 3960) or from involute geometry, both sides of every limit, refusals in full.  Fast, in-process, no part builds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears import tooth_load as tlm
from propulsor.gears.tooth_load import DenseOutline, RootSection


# ============================================================================ tooth_load: the load case
def _refusal(call, text):
    with pytest.raises(InputError) as e:
        call()
    assert str(e.value) == text


def test_torques_refuse_in_full_at_both_sides_of_each_limit():
    U = np.array([2.0, 3.0])
    _refusal(lambda: tlm.torques(U, T1_Nm=1.0, eta=0.0), "load_efficiency = 0.0: must be within (0, 1]")
    _refusal(lambda: tlm.torques(U, T1_Nm=1.0, eta=1.5), "load_efficiency = 1.5: must be within (0, 1]")
    T1, T2, _ = tlm.torques(U, T1_Nm=1.0, eta=1.0)          # eta = 1 is allowed: T2 = T1 U
    assert T2.tolist() == [2.0, 3.0]
    _refusal(lambda: tlm.torques(U, vehicle_mass_kg=100.0, rolling_resistance=0.1),
             "load_vehicle_mass_kg = 100.0: a vehicle load needs the walking law (its hub speed dX01/dphi); "
             "give load_driver_torque_Nm")
    _refusal(lambda: tlm.torques(U, power_W=100.0, speed_rpm=0.0),
             "load_driver_speed_rpm = 0.0: a power load needs the driver speed (> 0 rpm)")
    _refusal(lambda: tlm.torques(U), "load_driver_torque_Nm = 0.0: no load given (a driver torque, a power or a vehicle)")
    # a power of 0 W with no torque is no load (not a power load missing its speed)
    _refusal(lambda: tlm.torques(U, power_W=0.0), "load_driver_torque_Nm = 0.0: no load given (a driver torque, a "
                                                   "power or a vehicle)")


def test_torques_of_small_loads_and_the_defaults():
    U = np.array([2.0, 4.0])
    # loads below one unit are loads: 0.5 N·m, 0.5 W at 0.5 rpm, 0.5 kg
    T1, T2, what = tlm.torques(U, T1_Nm=0.5, eta=0.9)
    assert T1.tolist() == [0.5, 0.5] and T2 == pytest.approx([0.9, 1.8], rel=1e-15)
    assert what == "driver torque T1 = 0.5 N·m, T2 = T1·U·eta (eta = 0.9)"
    T1, T2, what = tlm.torques(np.array([3.0]), power_W=0.5, speed_rpm=0.5)
    omega = 2 * math.pi * 0.5 / 60.0
    assert T1 == pytest.approx([0.5 / omega], rel=1e-15) and T2 == pytest.approx([1.5 / omega], rel=1e-15)
    assert what == (f"power 0.5 W at 0.5 rpm of the driver: T1 = P/omega1 = {0.5 / omega:.4f} N·m, "
                    "T2 = T1·U·eta (eta = 1)")
    # the vehicle: no rolling resistance given is none; one propulsor by default
    dX = np.array([100.0, 80.0])
    T1, T2, _ = tlm.torques(U, vehicle_mass_kg=0.5, dX01_dphi=dX)
    assert T1.tolist() == [0.0, 0.0] and T2.tolist() == [0.0, 0.0]
    T1, T2, what = tlm.torques(U, vehicle_mass_kg=0.5, rolling_resistance=0.1, dX01_dphi=dX)
    F_R = 0.1 * 0.5 * 9.80665
    assert T2 == pytest.approx(F_R * dX * 1e-3, rel=1e-15) and T1 == pytest.approx(F_R * dX * 1e-3 / U, rel=1e-15)
    assert what == (f"vehicle 0.5 kg, rolling resistance f = 0.1, 1 driven propulsor(s): F_R = f·M·g/N_p = "
                    f"{F_R:.2f} N per propulsor, T2 = F_R·dX01/dphi, T1 = T2/(U·eta)")


def test_torques_of_an_integer_ratio_keep_a_fractional_torque():
    """U given as integers (a ratio table of whole numbers): the driver torque 2.5 N·m stays 2.5."""
    T1, T2, _ = tlm.torques([2, 4], T1_Nm=2.5)
    assert T1.tolist() == [2.5, 2.5] and T2.tolist() == [5.0, 10.0]


# ============================================================================ tooth_load: stiffness, sharing, Hertz
def _c_prime_by_hand(zn1, zn2, x1, x2, alpha_deg, h_fP_star, E_ratio, C_M, C_R):
    """ISO 6336-1:2006 eq. 60-63, Table 12's constants typed here."""
    C = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)
    i1 = 1.0 / zn1 if zn1 > 0 else 0.0
    i2 = 1.0 / zn2 if zn2 > 0 else 0.0
    q = (C[0] + C[1] * i1 + C[2] * i2 + C[3] * x1 + C[4] * x1 * i1 + C[5] * x2 + C[6] * x2 * i2 + C[7] * x1 ** 2
         + C[8] * x2 ** 2)
    C_B = (1 + 0.5 * (1.2 - h_fP_star)) * (1 - 0.02 * (20.0 - alpha_deg))
    return E_ratio * C_M * C_R * C_B / q


def test_c_prime_by_hand_off_the_defaults():
    for zn1, zn2 in ((0.8, 80.0), (25.0, 0.6), (-40.0, 30.0), (math.inf, 30.0), (30.0, -40.0)):
        got = float(tlm.c_prime(zn1, zn2, 0.3, -0.2, math.radians(25.0), 1.4, 0.7, 0.75, 0.9))
        assert got == pytest.approx(_c_prime_by_hand(zn1, zn2, 0.3, -0.2, 25.0, 1.4, 0.7, 0.75, 0.9), rel=1e-13)
    # arrays of phases, a concave driver pitch curve (negative z_n1) taken as a rack side
    got = tlm.c_prime(np.array([20.0, -50.0]), np.array([40.0, 40.0]), 0.5, -0.5, math.radians(20.0))
    assert got.dtype == np.float64
    assert got.tolist() == pytest.approx([_c_prime_by_hand(20.0, 40.0, 0.5, -0.5, 20.0, 1.25, 1.0, 0.8, 1.0),
                                          _c_prime_by_hand(math.inf, 40.0, 0.5, -0.5, 20.0, 1.25, 1.0, 0.8, 1.0)],
                                         rel=1e-13)


def test_share_load_by_hand():
    k, l1, l2 = [2.0, 3.0, 4.0], [1.5, 1.0, 2.0], [3.0, 2.0, 1.0]
    a = [k[i] * l1[i] * l2[i] for i in range(3)]               # 9, 6, 8 N·mm per rad
    # one pair closed: Δ = δ0 + T1/a0 (below 1 N·mm too)
    F, D = tlm.share_load(0.5, l1[:1], l2[:1], [0.01], k[:1])
    assert D == pytest.approx(0.01 + 0.5 / 9.0, rel=1e-15) and F.tolist() == pytest.approx([0.5 / 1.5], rel=1e-14)
    # gaps 0, 0.1, 1: T1 = 3 closes the first two pairs (Δ = (3 + 0.6)/15 = 0.24 < 1), not the third
    F, D = tlm.share_load(3.0, l1, l2, [0.0, 0.1, 1.0], k)
    assert D == pytest.approx((3.0 + 6.0 * 0.1) / 15.0, rel=1e-15)
    assert F.tolist() == pytest.approx([2.0 * 3.0 * D, 3.0 * 2.0 * (D - 0.1), 0.0], rel=1e-14)
    assert float(np.dot(F, l1)) == pytest.approx(3.0, rel=1e-14)
    # all three closed: Δ = (T1 + Σ a δ)/Σ a, gaps unsorted
    F, D = tlm.share_load(100.0, l1, l2, [0.2, 0.1, 0.3], k)
    assert D == pytest.approx((100.0 + 9 * 0.2 + 6 * 0.1 + 8 * 0.3) / 23.0, rel=1e-15)
    assert float(np.dot(F, l1)) == pytest.approx(100.0, rel=1e-14)
    # no torque or a negative one: nothing carried, Δ = 0 whatever the gaps
    for T1 in (0.0, -5.0):
        F, D = tlm.share_load(T1, l1, l2, [0.2, 0.1, 0.3], k)
        assert D == 0.0 and F.shape == (3,) and F.dtype == np.float64 and not F.any()
    F, D = tlm.share_load(0.0, [1], [2], [0], [3])             # whole numbers given: the forces are floats
    assert F.dtype == np.float64 and D == 0.0
    F, D = tlm.share_load(5.0, [], [], [], [])
    assert D == 0.0 and F.shape == (0,)


def test_hertz_by_hand_and_silent():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # σ_H = Z_E √(F K / (b ρ_red)), ρ_red = 1/(1/ρ1 + 1/ρ2); F below 1 N, K = 1.5
        s = float(tlm.hertz(0.5, 20.0, 10.0, 30.0, 190.0, K=1.5))
        assert s == pytest.approx(190.0 * math.sqrt(0.5 * 1.5 * (1 / 10 + 1 / 30) / 20.0), rel=1e-14)
        # flat against flat (1/ρ_red = 0) and convex in a wider concave: no line contact, nan, no warning
        assert math.isnan(float(tlm.hertz(100.0, 20.0, 10.0, -10.0, 190.0)))
        assert math.isnan(float(tlm.hertz(100.0, 20.0, -5.0, 10.0, 190.0)))
        # an edge (ρ1 = 0): infinite, no warning
        assert float(tlm.hertz(100.0, 20.0, 0.0, 10.0, 190.0)) == math.inf
        assert float(tlm.hertz(-3.0, 20.0, 10.0, 10.0, 190.0)) == 0.0


# ============================================================================ tooth_load: outlines
def _circle(R, n, ccw=True, offset=0.0):
    t = 2 * math.pi * (np.arange(n) + offset) / n
    if not ccw:
        t = -t
    return np.column_stack([R * np.cos(t), R * np.sin(t)])


def test_dense_outline_of_a_regular_polygon():
    R, n = 10.0, 40
    p = _circle(R, n)
    o = DenseOutline(np.vstack([p, p[:1]]))              # given closed: the repeated point dropped
    assert len(o) == n and np.array_equal(o.points, p)
    assert np.allclose(o.seg_len, 2 * R * math.sin(math.pi / n), rtol=0, atol=1e-13)
    assert np.allclose(o.turn, 2 * math.pi / n, rtol=0, atol=1e-13)      # left turns, 9° each
    assert not o.corner.any()
    t = 2 * math.pi * np.arange(n) / n
    assert np.allclose(o.tangent, np.column_stack([-np.sin(t), np.cos(t)]), rtol=0, atol=1e-13)
    assert np.allclose(np.cos(o.polar), np.cos(t), rtol=0, atol=1e-13)
    assert np.allclose(np.sin(o.polar), np.sin(t), rtol=0, atol=1e-13)
    assert o.nearest([[R * 1.1, 0.0]]).tolist() == [0] and o.nearest([0.0, -R]).tolist() == [30]
    assert len(DenseOutline(p)) == n
    # 30 sides: 12° turns are corners (> 10°); a corner angle given: 40 sides' 9° turns are corners above 8°
    assert DenseOutline(_circle(R, 30)).corner.all()
    assert DenseOutline(p, corner_deg=8.0).corner.all() and not DenseOutline(p, corner_deg=9.5).corner.any()
    # clockwise: right turns
    oc = DenseOutline(_circle(R, n, ccw=False))
    assert np.allclose(oc.turn, -2 * math.pi / n, rtol=0, atol=1e-13)
    # the turning angle is wrapped to (-π, π]: a square's corners turn by +π/2
    sq = DenseOutline(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]))
    assert np.allclose(sq.turn, math.pi / 2) and sq.corner.all()
    assert np.allclose(sq.tangent[0], np.array([1.0, -1.0]) / math.sqrt(2))


def test_curvature_of_a_circle_convex_and_concave():
    R = 10.0
    o = DenseOutline(_circle(R, 20000))
    for i in (0, 5000, 12345):     # a cubic fitted over ±0.1 mm of arc: 1/R to the fit's 2e-5
        assert tlm.curvature_at(o, i, 0.1) == pytest.approx(1.0 / R, rel=5e-5)
    oc = DenseOutline(_circle(R, 20000, ccw=False))
    assert tlm.curvature_at(oc, 77, 0.1) == pytest.approx(-1.0 / R, rel=5e-5)
    # fewer than 5 vertices within the half length: no curvature
    h = float(o.seg_len[0])
    assert math.isnan(tlm.curvature_at(o, 0, 1.5 * h))
    assert tlm.curvature_at(o, 0, 2.01 * h) == pytest.approx(1.0 / R, rel=1e-4)


def _arc_and_chord(R=10.0, n_arc=6001, n_line=3001, span=math.pi / 2):
    """An outline: a CCW arc of radius R over ``span`` about +y, closed by its straight chord (two corners)."""
    t = math.pi / 2 - span / 2 + span * np.arange(n_arc) / (n_arc - 1)
    arc = np.column_stack([R * np.cos(t), R * np.sin(t)])
    s = np.linspace(0.0, 1.0, n_line)[1:-1, None]
    line = arc[-1] + s * (arc[0] - arc[-1])
    return np.vstack([arc, line]), n_arc


def test_curvature_stops_at_a_corner_and_takes_the_more_curved_side_there():
    R = 10.0
    pts, n_arc = _arc_and_chord(R)
    o = DenseOutline(pts)
    assert o.corner[0] and o.corner[n_arc - 1] and o.corner.sum() == 2
    h = 0.3                                        # more than the few vertices to the corner: the fit stops there
    for i in (0, 3, n_arc - 1, n_arc - 4):
        assert tlm.curvature_at(o, i, h) == pytest.approx(1.0 / R, rel=5e-4), i
    for i in (n_arc + 2, len(pts) - 3):            # on the chord, next to a corner: flat
        assert abs(tlm.curvature_at(o, i, h)) < 1e-9
    # a corner with a straight side only is flat
    sq = DenseOutline(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]))
    assert math.isnan(tlm.curvature_at(sq, 0, 0.3))


def test_crossing_interpolates_the_30_degree_point_and_takes_the_nearer_vertex():
    R = 10.0
    for off, near in ((0.3, 30.3), (0.8, 29.8)):
        # vertices at (i + off) degrees; the tangent's angle to +y at θ is θ (0 <= θ <= 90°)
        o = DenseOutline(_circle(R, 360, offset=off))
        run = np.arange(89, -1, -1)                 # from θ ≈ 90° down towards 0°
        p, i = tlm._crossing(o, run, np.array([0.0, 1.0]), math.radians(30.0))
        v_lo = int(math.floor(30.0 - off))          # the first vertex at or below 30°, and the one before it
        v_hi = v_lo + 1
        f = (v_hi + off) - 30.0                     # 30° lies f of the way from v_hi to v_lo
        assert i == (v_lo if f >= 0.5 else v_hi) and (i + off) == pytest.approx(near)
        assert p == pytest.approx(o.points[v_hi] + f * (o.points[v_lo] - o.points[v_hi]), abs=1e-12)
        # none within the angle, or the first vertex already within it: no point
        p, i = tlm._crossing(o, run[:30], np.array([0.0, 1.0]), math.radians(30.0))
        assert i == -1 and np.isnan(p).all() and p.shape == (2,)
        p, i = tlm._crossing(o, run[60:], np.array([0.0, 1.0]), math.radians(30.0))
        assert i == -1 and np.isnan(p).all()


# ============================================================================ tooth_load: the root of a real tooth
@pytest.fixture(scope="module")
def iso_gear():
    """z = 20, m = 2.5, x = 0 generated by the ISO 53 rack (ρ_fP* = 0.38), its outline at 1e-4 mm, tooth 0 on +y."""
    from propulsor.geometry.gear_outline import external_gear_profile

    g = external_gear_profile(20, 2.5, 0.0)
    o = DenseOutline(g.profile.outer.polyline(1e-4))
    centres = math.pi / 2 + 2 * math.pi * np.arange(20) / 20
    return o, centres


def test_root_section_of_a_generated_tooth_is_iso_6336_3(iso_gear):
    from propulsor.gears.iso6336 import tooth_form_factor

    o, centres = iso_gear
    iso = tooth_form_factor(20, 2.5, 0.0, d_en=50.0)
    for tooth in range(20):
        ax = np.array([math.cos(centres[tooth]), math.sin(centres[tooth])])
        sec = tlm.root_section(o, tooth, centres, ax, 2.5)
        assert sec.ok and sec.tooth == tooth and np.array_equal(sec.axis, ax)
        assert sec.s_Fn == pytest.approx(iso.s_Fn, rel=2e-5)
        assert sec.rho_lo == pytest.approx(iso.rho_F, rel=1.5e-3) and sec.rho_hi == pytest.approx(iso.rho_F, rel=1.5e-3)
        # the chord across the tooth at the 30° points: its middle on the axis, A_lo on the clockwise side
        cross = lambda u, v: float(u[0] * v[1] - u[1] * v[0])
        assert cross(ax, sec.C) == pytest.approx(0.0, abs=1e-9)
        assert cross(ax, sec.A_lo - sec.C) < 0 < cross(ax, sec.A_hi - sec.C)   # A_lo clockwise of the axis
    # ISO 6336-3 eq. 31's terms: the section lies ½m(z·cos(π/3 − θ) + G/cos θ − ρ_fP*) from the centre
    G = 0.38 - 1.25
    along = 0.5 * 2.5 * (20 * math.cos(math.pi / 3 - iso.theta) + G / math.cos(iso.theta) - 0.38)
    sec = tlm.root_section(o, 0, centres, np.array([0.0, 1.0]), 2.5)
    assert float(sec.C[1]) == pytest.approx(along, rel=1e-4)


def test_root_section_refuses_too_few_points_and_no_30_degree_point(iso_gear):
    o, centres = iso_gear
    ax = np.array([0.0, 1.0])
    # a circle's vertices at (i + 0.5)°, the axis +y: the tangent at polar angle θ is θ from it, so a cell about 30°
    # walked down from its upper edge finds the 30° point; a cell of 8 vertices is enough, of 7 too few
    circ = DenseOutline(_circle(10.0, 360, offset=0.5))
    for c, n_in in (([22.5, 30.0, 37.5], 8), ([22.5, 30.0, 36.5], 7)):
        sec = tlm.root_section(circ, 1, np.radians(c), ax, 1.0)
        assert np.isnan(sec.A_lo).all() and math.isnan(sec.rho_lo) and not sec.ok
        assert np.isfinite(sec.A_hi).all() == (n_in >= 8), n_in
    # no tangent within 0° of the axis: no section (nan, not ok); at 30° the same cell has one
    sec = tlm.root_section(o, 0, centres, ax, 2.5, angle_deg=0.0)
    assert not sec.ok and math.isnan(sec.rho_lo) and math.isnan(sec.rho_hi)
    # a tooth alone on its gear: its cell is the whole turn
    one = tlm.root_section(o, 0, centres[:1], ax, 2.5)
    assert np.isfinite(one.A_lo).all() and np.isfinite(one.A_hi).all()


def test_root_section_s_fn_at_another_angle(iso_gear):
    """At 45° (angle_deg) the section lies lower on the fillet (whose tangent turns from 90° to the axis at the root
    towards 0° on the flank): a wider chord than at 30°."""
    o, centres = iso_gear
    ax = np.array([0.0, 1.0])
    s30 = tlm.root_section(o, 0, centres, ax, 2.5).s_Fn
    s45 = tlm.root_section(o, 0, centres, ax, 2.5, angle_deg=45.0)
    assert s45.ok and s45.s_Fn > s30 + 0.3


def test_root_stress_by_hand_on_a_given_section():
    sec = RootSection(3, np.array([-2.0, 0.0]), np.array([2.0, 0.0]), 1.5, 0.7, np.array([0.0, 1.0]))
    assert sec.s_Fn == 4.0 and sec.C.tolist() == [0.0, 0.0] and sec.ok
    b, m, K, a = 20.0, 2.0, 1.3, math.radians(20.0)
    for P, rho in (([1.5, 3.0], 0.7), ([-1.5, 3.0], 1.5)):      # the tension fillet: on the loaded side
        F = np.array([-300.0, -100.0])
        out = tlm.root_stress(sec, P, F, b, m, a, K)
        M = abs(P[0] * F[1] - P[1] * F[0])
        h = M / 300.0
        a_Fen = math.acos(300.0 / math.hypot(300.0, 100.0))
        L, q_s = 4.0 / h, 4.0 / (2 * rho)
        Y_S = (1.2 + 0.13 * L) * q_s ** (1 / (1.21 + 2.3 / L))
        assert out["M"] == pytest.approx(M, rel=1e-15) and out["h_Fe"] == pytest.approx(h, rel=1e-15)
        assert out["s_Fn"] == 4.0 and out["rho_F"] == rho and out["alpha_Fen"] == pytest.approx(a_Fen, rel=1e-15)
        assert out["Y_S"] == pytest.approx(Y_S, rel=1e-14)
        assert out["Y_F"] == pytest.approx(6 * (h / m) * math.cos(a_Fen) / ((4.0 / m) ** 2 * math.cos(a)), rel=1e-14)
        assert out["sigma_F"] == pytest.approx(6 * M / (b * 16.0) * Y_S * K, rel=1e-14)
        assert tlm.root_stress(sec, P, F, b, m, a)["sigma_F"] == pytest.approx(6 * M / (b * 16.0) * Y_S, rel=1e-14)
    # a force along the section (F ⟂ axis): α_Fen = 0; a force along the axis: no arm
    out = tlm.root_stress(sec, [1.0, 2.0], [-50.0, 0.0], b, m, a)
    assert out["alpha_Fen"] == 0.0 and out["h_Fe"] == pytest.approx(2.0, rel=1e-15)
    out = tlm.root_stress(sec, [1.0, 2.0], [0.0, -50.0], b, m, a)
    assert math.isnan(out["h_Fe"]) and out["M"] == 50.0
    out = tlm.root_stress(sec, [1.0, 2.0], [0.0, 0.0], b, m, a)
    assert math.isnan(out["h_Fe"]) and math.isnan(out["alpha_Fen"])


def test_root_stress_of_a_generated_tooth_is_iso_6336_3(iso_gear):
    """The whole normal force at the tip (d_en = d_a, ISO 6336-3 method C) on the counter-clockwise flank."""
    from propulsor.gears.iso6336 import tooth_form_factor

    o, centres = iso_gear
    ax = np.array([0.0, 1.0])
    sec = tlm.root_section(o, 0, centres, ax, 2.5)
    d_en = 52.0                                  # between d = 50 and d_a = 55
    iso = tooth_form_factor(20, 2.5, 0.0, d_en=d_en)
    r = np.hypot(o.points[:, 0], o.points[:, 1])
    on = np.nonzero((o.points[:, 0] > 0) & (np.abs(o.points[:, 1]) > 0) & (np.abs(o.polar - math.pi / 2) < math.pi / 20))[0]
    i = on[np.argmin(np.abs(r[on] - d_en / 2))]
    P = o.points[i]
    d_b = 50.0 * math.cos(math.radians(20.0))
    a_y = math.acos(d_b / (2 * np.hypot(*P)))
    # the line of action at P: tangent to the base circle, pushing the flank into the tooth
    t = o.tangent[i]
    F = 1000.0 * np.array([-t[1], t[0]])
    out = tlm.root_stress(sec, P, F, 20.0, 2.5, math.radians(20.0))
    assert out["h_Fe"] == pytest.approx(iso.h_Fe, rel=5e-3)
    assert out["alpha_Fen"] == pytest.approx(iso.alpha_Fen, rel=5e-3)
    assert out["Y_F"] == pytest.approx(iso.Y_F, rel=5e-3) and out["Y_S"] == pytest.approx(iso.Y_S, rel=5e-3)
    assert a_y > 0


def test_y_s_is_iso_6336_3_eq_39():
    got = tlm.y_s(np.array([4.0, 5.0]), np.array([2.0, 2.5]), np.array([1.0, 0.8]))
    want = [(1.2 + 0.13 * L) * q ** (1 / (1.21 + 2.3 / L)) for L, q in ((2.0, 2.0), (2.0, 5.0 / 1.6))]
    assert got.tolist() == pytest.approx(want, rel=1e-15)
    assert float(tlm.y_s(3, 2, 1)) == pytest.approx((1.2 + 0.13 * 1.5) * 1.5 ** (1 / (1.21 + 2.3 / 1.5)), rel=1e-15)


# ============================================================================ involute.py: ISO 21771 / DIN 3960
from propulsor.gears import involute as inv_mod                    # noqa: E402
from propulsor.gears.involute import BasicRack, SpurGear           # noqa: E402

A20 = math.radians(20.0)


def _inv(a):
    return math.tan(a) - a


def test_inv_and_its_inverse_by_hand():
    assert float(inv_mod.inv(A20)) == pytest.approx(0.014904383867336446, rel=1e-15)   # published inv 20°
    for deg in (0.5, 5.0, 20.0, 45.0, 70.0, 85.0, 89.5):
        a = math.radians(deg)
        assert inv_mod.inv_inverse(_inv(a)) == pytest.approx(a, rel=1e-14), deg
    assert inv_mod.inv_inverse(0.0) == 0.0
    assert inv_mod.inv_inverse(1e-12) == pytest.approx((3e-12) ** (1 / 3), rel=1e-6)
    assert inv_mod.inv_inverse(1e6) == pytest.approx(math.pi / 2 - 1e-6, rel=1e-12)   # tan α ≈ 1e6
    _refusal(lambda: inv_mod.inv_inverse(-1e-9),
             "inv value = -1e-09: must be >= 0 (involute function of an angle in [0, π/2))")
    _refusal(lambda: inv_mod.inv_inverse(math.nan), "inv value = nan: must be a finite number")


def test_basic_rack_limits_in_full():
    for a in (10.0, 35.0):
        BasicRack(alpha=math.radians(a), c_star=0.0, rho_f_star=0.0)
    _refusal(lambda: BasicRack(alpha=math.radians(9.99)), f"alpha = {math.radians(9.99)!r}: must be within 10°..35° "
                                                          "(0.1745..0.6109 rad)")
    _refusal(lambda: BasicRack(alpha=math.radians(35.01)), f"alpha = {math.radians(35.01)!r}: must be within "
                                                           "10°..35° (0.1745..0.6109 rad)")
    _refusal(lambda: BasicRack(h_a_star=0.0), "h_a_star = 0.0: must be > 0")
    BasicRack(h_a_star=2.0, c_star=0.0, rho_f_star=0.0, alpha=math.radians(10.0))
    _refusal(lambda: BasicRack(h_a_star=2.01), "h_a_star = 2.01: must be <= 2")
    _refusal(lambda: BasicRack(c_star=-0.01), "c_star = -0.01: must be within 0..1")
    _refusal(lambda: BasicRack(c_star=1.01), "c_star = 1.01: must be within 0..1")
    _refusal(lambda: BasicRack(rho_f_star=-0.01), "rho_f_star = -0.01: must be >= 0")
    # the tool's tip land: ρ_f* <= (π/4 − (h_a* + c*) tan α) cos α / (1 − sin α)
    r_max = (math.pi / 4 - 1.25 * math.tan(A20)) * math.cos(A20) / (1 - math.sin(A20))
    assert BasicRack().rho_f_star_max == pytest.approx(r_max, rel=1e-15)
    BasicRack(rho_f_star=r_max)
    _refusal(lambda: BasicRack(rho_f_star=r_max + 1e-4), f"rho_f_star = {r_max + 1e-4!r}: must be <= {r_max:.4f} "
                                                          "(tool tip land)")
    # no land at all: π/4 = (h_a* + c*) tan α
    c0 = math.pi / 4 / math.tan(math.radians(35.0)) - 1.0
    _refusal(lambda: BasicRack(alpha=math.radians(35.0), c_star=c0 + 1e-3, rho_f_star=0.0),
             f"c_star = {c0 + 1e-3!r}: tool tooth has no tip land left (π/4 − (h_a*+c*)·tan α ≤ 0)")
    assert BasicRack().h_l_star == pytest.approx(1.25 - 0.38 * (1 - math.sin(A20)), rel=1e-15)


def test_z_min_feasible_by_hand():
    def by_hand(alpha, h_a, c, rho):
        h_l = h_a + c - rho * (1 - math.sin(alpha))
        for z in range(2, 200):
            x = h_l - z * math.sin(alpha) ** 2 / 2
            d_a = z + 2 * (h_a + x)
            s_a = d_a * ((math.pi / 2 + 2 * x * math.tan(alpha)) / z + _inv(alpha)
                         - _inv(math.acos(z * math.cos(alpha) / d_a)))
            if s_a > 0:
                return z

    assert inv_mod.z_min_feasible(BasicRack()) == 8 == by_hand(A20, 1.0, 0.25, 0.38)
    for r in (BasicRack(alpha=math.radians(14.5), rho_f_star=0.2), BasicRack(alpha=math.radians(25.0), h_a_star=1.2,
                                                                            rho_f_star=0.1),
              BasicRack(h_a_star=0.8, c_star=0.3, rho_f_star=0.3)):
        assert inv_mod.z_min_feasible(r) == by_hand(r.alpha, r.h_a_star, r.c_star, r.rho_f_star)


def _gear_by_hand(z, m, x, internal=False, alpha=A20, h_a=1.0, c=0.25):
    d = m * z
    d_b = d * math.cos(alpha)
    s = m * (math.pi / 2 + (-1 if internal else 1) * 2 * x * math.tan(alpha))
    d_a = d - 2 * (h_a - x) * m if internal else d + 2 * (h_a + x) * m
    return d, d_b, s, d_a


def test_spur_gear_dimensions_external_and_ring():
    for z, m, x, internal in ((23, 2.5, 0.3, False), (17, 4.0, -0.2, False), (71, 3.0, 0.4, True),
                              (60, 2.0, -0.3, True)):
        g = SpurGear(z, m, x, internal=internal)
        d, d_b, s, d_a = _gear_by_hand(z, m, x, internal)
        assert (g.d, g.p) == pytest.approx((d, math.pi * m), rel=1e-15)
        assert g.d_b == pytest.approx(d_b, rel=1e-15) and g.p_b == pytest.approx(math.pi * m * math.cos(A20), rel=1e-15)
        assert g.s == pytest.approx(s, rel=1e-15) and g.e == pytest.approx(math.pi * m - s, rel=1e-14)
        assert g.s_n == g.s and g.d_a == pytest.approx(d_a, rel=1e-15)
        # arc thickness on d_y: d_y (s/d ± (inv α − inv α_y)), + external; the ring's tooth widens outwards
        for d_y in (d_b * 1.0001, 0.5 * (d + d_a), d_a):
            a_y = math.acos(d_b / d_y)
            sgn = -1 if internal else 1
            want = d_y * (s / d + sgn * (_inv(A20) - _inv(a_y)))
            assert g.s_at(d_y) == pytest.approx(want, rel=1e-13) and g.tip_thickness(d_y) == g.s_at(d_y)
            assert float(g.psi_at(d_y)) == pytest.approx(want / d_y, rel=1e-13)
            assert g.rho_at(d_y) == pytest.approx(0.5 * math.sqrt(d_y ** 2 - d_b ** 2), rel=1e-12)
        assert g.s_na == pytest.approx(g.s_at(d_a), rel=1e-15)
        assert g.rho_a == pytest.approx(0.5 * math.sqrt(max(0.0, d_a ** 2 - d_b ** 2)), rel=1e-13)
        assert g.psi_at(np.array([d, d_a])).tolist() == pytest.approx([g.s_at(d) / d, g.s_at(d_a) / d_a], rel=1e-13)
        # constant chord: s_c = s cos²α, its height from the tip ½(±(d_a − d) − s_c tan α), ρ_c = ½ d sin α ± ½ s cos α
        s_c = s * math.cos(A20) ** 2
        assert g.s_c == pytest.approx(s_c, rel=1e-15)
        h = 0.5 * ((d - d_a) if internal else (d_a - d)) - 0.5 * s_c * math.tan(A20)
        assert g.h_c() == pytest.approx(h, rel=1e-13)
        assert g.h_c(d_a + (-1 if internal else 1) * 0.4) == pytest.approx(h + 0.2, rel=1e-13)
        assert g.rho_c == pytest.approx(0.5 * d * math.sin(A20) + (-0.5 if internal else 0.5) * s * math.cos(A20),
                                        rel=1e-14)
    # the base circle is the lowest diameter with a flank: just below it (beyond the rounding), refused
    g = SpurGear(23, 2.5, 0.3)
    _refusal(lambda: g.s_at(g.d_b * (1 - 1e-9)), f"d_y = {g.d_b * (1 - 1e-9)!r}: must be >= base diameter "
                                                  f"d_b = {g.d_b:.6f} mm")
    assert g.s_at(g.d_b * (1 - 1e-16)) == pytest.approx(g.d_b * (g.s / g.d + _inv(A20)), rel=1e-12)


def test_roots_undercut_and_shaper_by_hand():
    g = SpurGear(23, 2.5, 0.3)
    assert g.d_f == pytest.approx(57.5 - 2 * (1.25 - 0.3) * 2.5, rel=1e-15)
    h_l = 1.25 - 0.38 * (1 - math.sin(A20))
    assert g.x_min == pytest.approx(h_l - 23 * math.sin(A20) ** 2 / 2, rel=1e-14)
    assert g.z_min == pytest.approx(2 * h_l / math.sin(A20) ** 2, rel=1e-15)
    assert g.rho_l == pytest.approx(0.5 * 57.5 * math.sin(A20) - (h_l - 0.3) * 2.5 / math.sin(A20), rel=1e-14)
    r = SpurGear(71, 3.0, 0.4, internal=True)
    assert r.d_f == pytest.approx(213.0 + 2 * (1.25 + 0.4) * 3.0, rel=1e-15)
    assert r.rho_l == pytest.approx(0.5 * 213.0 * math.sin(A20) + (h_l + 0.4) * 3.0 / math.sin(A20), rel=1e-14)
    _refusal(lambda: r.d_0, "z0 = None: this quantity needs the shaper cutter of the ring (z0, x0)")
    # a ring cut by a shaper z0 = 25, x0 = 0.1: inv α_w0 = inv α + 2 tan α (x − x0)/(z − z0), a_w0, d_f = d_a0 + 2 a_w0
    s = SpurGear(71, 3.0, 0.4, internal=True, z0=25, x0=0.1)
    a_w0 = inv_mod.inv_inverse(_inv(A20) + 2 * math.tan(A20) * 0.3 / 46)
    assert s.alpha_w0 == pytest.approx(a_w0, rel=1e-14) and s.d_0 == 75.0
    d_a0 = 75.0 + 2 * (1.25 + 0.1) * 3.0
    aw = 3.0 * 46 / 2 * math.cos(A20) / math.cos(a_w0)
    assert s.d_a0 == pytest.approx(d_a0, rel=1e-15) and s.a_w0 == pytest.approx(aw, rel=1e-14)
    assert s.d_b0 == pytest.approx(75.0 * math.cos(A20), rel=1e-15)
    assert s.d_f == pytest.approx(d_a0 + 2 * aw, rel=1e-14)
    rho_a0 = 0.5 * math.sqrt(d_a0 ** 2 - (75.0 * math.cos(A20)) ** 2)
    assert s.rho_a0 == pytest.approx(rho_a0, rel=1e-14)
    assert s.rho_l == pytest.approx(aw * math.sin(a_w0) + rho_a0, rel=1e-14)
    assert s.shaper_tip_cut_margin == pytest.approx(s.rho_a - aw * math.sin(a_w0), rel=1e-13)


def test_spur_gear_refusals_in_full():
    _refusal(lambda: SpurGear(20, 0.0), "m = 0.0: must be > 0 mm")
    _refusal(lambda: SpurGear(20, 2.0, math.inf), "x = inf: must be a finite number")
    _refusal(lambda: SpurGear(20, 2.0, rack="ISO"), "rack = 'ISO': must be a BasicRack")
    _refusal(lambda: SpurGear(20.5, 2.0), "z = 20.5: must be a whole number of teeth")
    assert SpurGear(20.0, 2.0).z == 20 and type(SpurGear(20.0, 2.0).z) is int
    SpurGear(8, 2.0, 0.3)
    _refusal(lambda: SpurGear(7, 2.0, 0.6),
             "z = 7: must be >= 8: for fewer teeth no profile shift avoids both undercut and a pointed tip")
    _refusal(lambda: SpurGear(8, 2.0, 0.0, internal=True),
             "z = 8: a ring needs z >= 9 (it must exceed the smallest feasible pinion, z = 8)")
    _refusal(lambda: SpurGear(20, 2.0, z0=10), "z0 = 10: a shaper cutter is given for internal gears only")
    _refusal(lambda: SpurGear(60, 2.0, 3.01), "x = 3.01: must be within -3..3")
    _refusal(lambda: SpurGear(60, 2.0, -3.01), "x = -3.01: must be within -3..3")
    # no tooth at the reference circle: s = m(π/2 + 2x tan α) <= 0
    x0 = -math.pi / 4 / math.tan(A20)
    _refusal(lambda: SpurGear(60, 2.0, x0 - 0.01),
             f"x = {x0 - 0.01!r}: gives no tooth thickness at the reference circle (s = "
             f"{2.0 * (math.pi / 2 + 2 * (x0 - 0.01) * math.tan(A20)):.4f} mm)")
    # shaper: z0 whole, >= 6, < z; |x0| <= 1.5
    SpurGear(71, 3.0, 0.4, internal=True, z0=6)
    for z0, msg in ((5, "z0 = 5: must be a whole number >= 6"), (6.5, "z0 = 6.5: must be a whole number >= 6"),
                    (71, "z0 = 71: must be < z = 71 (shaper inside the ring)")):
        _refusal(lambda: SpurGear(71, 3.0, 0.4, internal=True, z0=z0), msg)
    assert SpurGear(71, 3.0, 0.4, internal=True, z0=70.0).z0 == 70
    SpurGear(71, 3.0, 0.4, internal=True, z0=25, x0=-1.5)
    _refusal(lambda: SpurGear(71, 3.0, 0.4, internal=True, z0=25, x0=-1.51), "x0 = -1.51: must be within -1.5..1.5")
    _refusal(lambda: SpurGear(71, 3.0, 0.4, internal=True, z0=25, x0=1.51), "x0 = 1.51: must be within -1.5..1.5")
    _refusal(lambda: SpurGear(71, 3.0, 0.4, internal=True, z0=25, x0=math.nan), "x0 = nan: must be a finite number")


def test_validate_refusals_in_full():
    # a pointed external tip: z = 10, x = 1.0 -> s_na < 0
    g = SpurGear.__new__(SpurGear)
    for name, val in (("z", 10), ("m", 2.0), ("x", 1.0), ("rack", BasicRack()), ("internal", False), ("z0", None),
                      ("x0", 0.0)):
        object.__setattr__(g, name, val)
    _refusal(g.validate, f"x = 1.0: tooth is pointed: s_na = {g.s_na:.4f} mm at d_a = {g.d_a:.4f} mm (must be > 0)")
    # external tip inside the base circle: x = -3 on many teeth
    e = SpurGear.__new__(SpurGear)
    for name, val in (("z", 20), ("m", 1.0), ("x", -4.0), ("rack", BasicRack()), ("internal", False), ("z0", None),
                      ("x0", 0.0)):
        object.__setattr__(e, name, val)
    _refusal(e.validate, f"x = -4.0: tip diameter d_a = {e.d_a:.4f} mm is inside the base circle "
                         f"d_b = {e.d_b:.4f} mm")


def test_span_measurement_w_k_by_iso_21771():
    for z, m, x in ((23, 2.5, 0.3), (17, 4.0, -0.2), (60, 2.0, 0.5), (9, 3.0, 0.5)):
        g = SpurGear(z, m, x)
        for k in (1, 2, 3, 7):
            want = m * math.cos(A20) * (math.pi * (k - 0.5) + z * _inv(A20) + 2 * x * math.tan(A20))
            assert g.W(k) == pytest.approx(want, rel=1e-15)
        a_x = math.acos(g.d_b / (g.d + 2 * x * m))
        k = round(z / math.pi * (math.tan(a_x) - _inv(A20) - 2 * x * math.tan(A20) / z) + 0.5)
        assert g.k_W == max(1, k) and g.W_k == g.W(g.k_W) and g.rho_W == 0.5 * g.W_k
    assert SpurGear(23, 2.5, 0.0).k_W == 3 and SpurGear(60, 2.0, 0.0).k_W == 7
    _refusal(lambda: SpurGear(23, 2.5).W(0), "k = 0: must be a whole number >= 1")
    _refusal(lambda: SpurGear(23, 2.5).W(1.5), "k = 1.5: must be a whole number >= 1")
    # a ring spans spaces: the same formula with its own x
    r = SpurGear(71, 3.0, 0.4, internal=True)
    assert r.W(9) == pytest.approx(3.0 * math.cos(A20) * (math.pi * 8.5 + 71 * _inv(A20) + 0.8 * math.tan(A20)),
                                   rel=1e-15)


def test_dimension_over_rollers_by_hand():
    for z, m, x, internal in ((24, 2.5, 0.3, False), (23, 2.5, 0.3, False), (70, 3.0, 0.4, True),
                              (71, 3.0, 0.4, True)):
        g = SpurGear(z, m, x, internal=internal)
        d_b = m * z * math.cos(A20)
        D = 1.7 * m
        if internal:
            v = _inv(A20) + 2 * x * math.tan(A20) / z + math.pi / (2 * z) - D / d_b
        else:
            v = _inv(A20) + 2 * x * math.tan(A20) / z - math.pi / (2 * z) + D / d_b
        a_D = inv_mod.inv_inverse(v)
        assert g.alpha_D(D) == pytest.approx(a_D, rel=1e-14)
        d_D = d_b / math.cos(a_D)
        assert g.d_D(D) == pytest.approx(d_D, rel=1e-14)
        dd = d_D * (math.cos(math.pi / (2 * z)) if z % 2 else 1.0)
        assert g.M(D) == pytest.approx(dd - D if internal else dd + D, rel=1e-14)
        r = 0.5 * d_b * math.tan(a_D)
        assert g.rho_M(D) == pytest.approx(r + 0.5 * D if internal else r - 0.5 * D, rel=1e-13)
        # the recommended roller touches the flanks on d + 2xm: its centre's pressure angle from that contact
        Dr = g.D_recommended
        a_y = math.acos(d_b / (m * z + 2 * x * m))
        assert math.tan(g.alpha_D(Dr)) == pytest.approx(math.tan(a_y) + (-Dr if internal else Dr) / d_b, rel=1e-12)
        assert inv_mod.roller_diameter_for_contact_at(g, m * z + 2 * x * m) == Dr
    g = SpurGear(24, 2.5, 0.3)
    _refusal(lambda: g.alpha_D(0.0), "D = 0.0: must be > 0 mm")
    D0 = g.d_b * (math.pi / 48 - 0.6 * math.tan(A20) / 24 - _inv(A20))     # inv α_D = 0
    _refusal(lambda: g.alpha_D(0.999 * D0), f"D = {0.999 * D0!r}: roller too small/large for this tooth (inv α_D <= 0)")
    assert g.alpha_D(1.001 * D0) > 0
    _refusal(lambda: inv_mod.roller_diameter_for_contact_at(g, 1.5 * g.d_a),
             f"d_y = {1.5 * g.d_a!r}: no roller diameter makes contact on this diameter")
    _refusal(lambda: inv_mod.roller_diameter_for_contact_at(g, 0.9 * g.d_b),
             f"d_y = {0.9 * g.d_b!r}: must be >= base diameter d_b = {g.d_b:.6f} mm")


def test_x_sum_for_centre_distance_by_hand():
    for z1, z2, internal, a_w in ((20, 40, False, 76.0), (20, 40, False, 74.0), (20, 70, True, 63.0)):
        zs = z2 - z1 if internal else z2 + z1
        a_wt = math.acos(2.5 * zs / 2 * math.cos(A20) / a_w)
        want = zs * (_inv(a_wt) - _inv(A20)) / (2 * math.tan(A20))
        assert inv_mod.x_sum_for_centre_distance(z1, z2, 2.5, a_w, internal=internal) == pytest.approx(want, rel=1e-13)
    _refusal(lambda: inv_mod.x_sum_for_centre_distance(20, 40, 0.0, 75.0), "m = 0.0: must be > 0 mm")
    _refusal(lambda: inv_mod.x_sum_for_centre_distance(20, 40, 2.5, 0.0), "a_w = 0.0: must be > 0 mm")
    _refusal(lambda: inv_mod.x_sum_for_centre_distance(40, 40, 2.5, 75.0, internal=True),
             "z2 = 40: must exceed z1 for an internal pair")
    lim = 75.0 * math.cos(A20)
    _refusal(lambda: inv_mod.x_sum_for_centre_distance(20, 40, 2.5, lim),
             f"a_w = {lim!r}: must exceed a·cos α = {lim:.4f} mm")


def test_flank_values_at_and_below_the_base_circle():
    for internal, (z, x) in ((False, (23, 0.3)), (True, (71, 0.4))):
        g = SpurGear(z, 2.5, x, internal=internal)
        sgn = -1 if internal else 1
        # at the base circle: α_y = 0, ρ = 0; the rounding allowance 1e-15 accepted exactly
        assert g.rho_at(g.d_b) == 0.0
        assert g.s_at(g.d_b) == pytest.approx(g.d_b * (g.s / g.d + sgn * _inv(A20)), rel=1e-13)
        assert g.s_at(g.d_b * (1 - 1e-15)) == pytest.approx(g.d_b * (g.s / g.d + sgn * _inv(A20)), rel=1e-13)
        # the half tooth angle below the base circle is the base circle's (vectorised, clipped)
        assert g.psi_at(np.array([0.9 * g.d_b, g.d_b])).tolist() == pytest.approx(
            [g.s / g.d + sgn * _inv(A20)] * 2, rel=1e-13)
        _refusal(lambda: g.rho_at(0.9 * g.d_b), f"d_y = {0.9 * g.d_b!r}: must be >= base diameter d_b = {g.d_b:.6f} mm")
    a1 = inv_mod.inv_inverse(1.0)                 # tan α − α = 1: α = 1.132267725272885 rad (scipy's brentq)
    assert _inv(a1) == pytest.approx(1.0, rel=1e-14) and a1 == pytest.approx(1.132267725272885, rel=1e-14)


def test_outline_tangents_of_unequal_segments_and_fits_in_a_tilted_frame():
    # a 2 x 1 rectangle: the tangent at a corner bisects the two unit directions, whatever the sides' lengths
    rect = DenseOutline(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]))
    assert np.allclose(rect.tangent[1], np.array([1.0, 1.0]) / math.sqrt(2), rtol=0, atol=1e-15)
    # the curvature formula κ = 2c2/(1 + c1²)^1.5 of a cubic fitted in a frame tilted by 30° from the tangent
    R = 10.0
    o = DenseOutline(_circle(R, 20000))
    idx = np.arange(-40, 41) % 20000
    t = np.array([math.cos(math.pi / 2 + math.radians(30)), math.sin(math.pi / 2 + math.radians(30))])
    assert tlm._fit(o, 0, idx, t) == pytest.approx(1.0 / R, rel=1e-4)
    assert math.isnan(tlm._fit(o, 0, idx[:4], t))


def test_curvature_next_to_a_corner_and_at_a_concave_corner():
    R = 10.0
    pts, n_arc = _arc_and_chord(R)
    o = DenseOutline(pts)
    for i in (1, 2, n_arc - 2, n_arc - 3):           # the corner one or two vertices away: the arc alone
        assert tlm.curvature_at(o, i, 0.3) == pytest.approx(1.0 / R, rel=5e-4), i
    # traversed clockwise the arc is concave: at the corner the more curved side is the arc's, κ = −1/R
    rev = DenseOutline(pts[::-1])
    j = len(pts) - n_arc                              # the reversed arc's first vertex (a corner)
    assert rev.corner[j]
    assert tlm.curvature_at(rev, j, 0.3) == pytest.approx(-1.0 / R, rel=5e-4)


def test_root_section_wherever_the_outline_starts(iso_gear):
    """The cell of tooth 0 straddling the outline's first vertex (the loop rolled): the same section; the 30° point's
    own vertex as the first vertex: its fillet radius still measured."""
    o, centres = iso_gear
    ax = np.array([0.0, 1.0])
    ref = tlm.root_section(o, 0, centres, ax, 2.5)
    i_tip = int(np.argmax(o.points[:, 1]))             # tooth 0's tip, inside its cell
    for k in (i_tip, int(o.nearest(ref.A_lo)[0]), int(o.nearest(ref.A_hi)[0])):
        rolled = DenseOutline(np.roll(o.points, -k, axis=0))
        sec = tlm.root_section(rolled, 0, centres, ax, 2.5)
        assert sec.A_lo == pytest.approx(ref.A_lo, abs=1e-12) and sec.A_hi == pytest.approx(ref.A_hi, abs=1e-12)
        assert sec.rho_lo == pytest.approx(ref.rho_lo, rel=1e-9) and sec.rho_hi == pytest.approx(ref.rho_hi, rel=1e-9)


def test_root_section_without_points_keeps_its_tooth_and_axis():
    circ = DenseOutline(_circle(10.0, 360, offset=0.5))
    ax = np.array([0.0, 1.0])
    sec = tlm.root_section(circ, 1, np.radians([22.5, 30.0, 36.5]), ax, 1.0)      # 7 vertices: too few
    assert sec.tooth == 1 and np.array_equal(sec.axis, ax) and sec.A_lo.shape == (2,) and sec.A_hi.shape == (2,)
    assert math.isnan(sec.rho_hi) and np.isnan(sec.A_hi).all()


def test_root_stress_small_forces_and_the_loaded_side_on_the_axis():
    sec = RootSection(0, np.array([-2.0, 0.0]), np.array([2.0, 0.0]), 1.5, 0.7, np.array([0.0, 1.0]))
    big = tlm.root_stress(sec, [1.5, 3.0], [-300.0, -100.0], 20.0, 2.0, A20)
    small = tlm.root_stress(sec, [1.5, 3.0], [-0.3, -0.1], 20.0, 2.0, A20)      # below 1 N: the same arm and angle
    assert small["h_Fe"] == pytest.approx(big["h_Fe"], rel=1e-14)
    assert small["alpha_Fen"] == pytest.approx(big["alpha_Fen"], rel=1e-14)
    assert small["sigma_F"] == pytest.approx(big["sigma_F"] / 1000.0, rel=1e-14)
    # the load on the axis (r·e = 0) reads the clockwise fillet; 0.5 mm to the counter-clockwise side, the other
    assert tlm.root_stress(sec, [0.0, 3.0], [-300.0, -100.0], 20.0, 2.0, A20)["rho_F"] == 1.5
    assert tlm.root_stress(sec, [0.5, 3.0], [-300.0, -100.0], 20.0, 2.0, A20)["rho_F"] == 0.7


def test_limits_of_racks_gears_and_centre_distances_on_their_accepted_side():
    _refusal(lambda: BasicRack(alpha=math.nan), "alpha = nan: must be a finite number")
    _refusal(lambda: BasicRack(c_star=math.nan), "c_star = nan: must be a finite number")
    assert BasicRack(c_star=1.0, rho_f_star=0.05).h_fP_star == 2.0          # c* = 1 is within 0..1
    assert SpurGear(9, 2.0, 0.0, internal=True).z == 9                        # a ring of z_min + 1 = 9 teeth
    assert SpurGear(20, 0.5).s == pytest.approx(0.25 * math.pi, rel=1e-15)   # a tooth thinner than 1 mm is a tooth
    assert SpurGear(100, 1.0, -3.0, internal=True).x == -3.0                 # |x| = 3 is within -3..3
    g = SpurGear(71, 3.0, 0.4, internal=True, z0=25.0)
    assert g.z0 == 25 and type(g.z0) is int
    _refusal(lambda: SpurGear(71, 3.0, 0.4, internal=True, z0=math.nan), "z0 = nan: must be a finite number")
    # an internal pair of z2 = z1 + 1 has z2 − z1 = 1 > 0: a shift sum exists
    a_wt = math.acos(2.5 / 2 * math.cos(A20) / 1.5)
    assert inv_mod.x_sum_for_centre_distance(20, 21, 2.5, 1.5, internal=True) == pytest.approx(
        (_inv(a_wt) - _inv(A20)) / (2 * math.tan(A20)), rel=1e-13)


# ============================================================================ catalogue.py: ISO 53 racks, GOST 9323 shapers
from propulsor.gears import catalogue as cat                        # noqa: E402


def test_iso_53_rack_profiles_table_1():
    assert cat.rack_profiles() == ("A", "B", "C", "D")
    for name, c, rho in (("A", 0.25, 0.38), ("B", 0.25, 0.30), ("C", 0.25, 0.25), ("D", 0.40, 0.39)):
        assert cat.rack_profile(name) == BasicRack(alpha=A20, h_a_star=1.0, c_star=c, rho_f_star=rho)
    assert cat.rack_profile("B", math.radians(22.5)) == BasicRack(math.radians(22.5), 1.0, 0.25, 0.30)
    _refusal(lambda: cat.rack_profile("E"), "rack_profile = 'E': must be one of A, B, C, D (ISO 53:1998)")


def test_shaper_catalogue_entries_and_refusals_in_full():
    assert cat.shaper_diameters() == (25.0, 38.0, 50.0, 75.0, 100.0)
    e = cat.shaper_entry(75.0, 2.5)
    assert e == cat.ShaperEntry(75.0, 2.5, 30, 0.0, 1.25, 0.1, "GOST 9323-79 type 1 (disc) / DIN 1825", "ours")
    assert type(e.z0) is int and type(e.d0_mm) is float and type(e.m) is float
    assert e.name == "d0 75 m 2.5 z0 30 x0 +0 (GOST 9323-79 type 1 (disc) / DIN 1825)"
    assert cat.shaper_entry(100, 6).z0 == 17 and cat.shaper_entry(25.0, 1.0).z0 == 25
    assert cat.shaper_entry(38.0 + 5e-10, 4.0).z0 == 10                  # d0 matched to 1e-9 mm
    _refusal(lambda: cat.shaper_entry(38.0 + 2e-9, 4.0), "d0 = 38.000000002: is not a nominal shaper diameter of the "
                                                         "catalogue (nominal d0: 25, 38, 50, 75, 100 mm)")
    _refusal(lambda: cat.shaper_entry(25.0, 3.0), "d0 = 25.0: the catalogue lists no shaper d0 = 25 mm at m = 3 mm "
                                                  "(modules listed: 1, 1.25, 1.5, 1.75, 2, 2.25, 2.5, 2.75)")
    # the tool: a rack of h_a* = 1 and c* = h_a0* − 1 = 0.25 (its addendum 1.25 m), tip round 0.1 m
    for tool in (e.cutter(), cat.catalogue_shaper(75.0, 2.5)):
        assert (tool.z0, tool.m, tool.x0, tool.rho_a0_star) == (30, 2.5, 0.0, 0.1)
        assert tool.rack == BasicRack(A20, 1.0, 0.25, 0.38)
    tool = cat.catalogue_shaper(50.0, 2.0, math.radians(22.0))
    assert tool.z0 == 25 and tool.rack.alpha == math.radians(22.0) and tool.rack.c_star == 0.25
    assert e.cutter(math.radians(22.0)).rack.alpha == math.radians(22.0)


# ============================================================================ gear_pair.py: ISO 21771 pair geometry
from propulsor.gears.gear_pair import GearPair                      # noqa: E402


def _pair_by_hand(z1, z2, x1, x2, m, internal):
    sg = -1 if internal else 1
    zs, xs = z2 + sg * z1, x2 + sg * x1
    a = m * zs / 2
    a_w_ang = inv_mod.inv_inverse(_inv(A20) + 2 * math.tan(A20) * xs / zs)
    a_w = a * math.cos(A20) / math.cos(a_w_ang)
    y = (a_w - a) / m
    dy = xs - y
    d1, d2 = m * z1, m * z2
    if internal:
        k2 = 0.25 - 0.125 * x2 if x2 < 2 else 0.0
        d_a1 = d1 + 2 * (1 + x1) * m
        d_a2 = d2 - 2 * (1 - x2 + dy - k2) * m
    else:
        d_a1 = d1 + 2 * (1 + x1 - dy) * m
        d_a2 = d2 + 2 * (1 + x2 - dy) * m
    return dict(a=a, alpha_w=a_w_ang, a_w=a_w, y=y, dy=dy, d_a1=d_a1, d_a2=d_a2, d_b1=d1 * math.cos(A20),
                d_b2=d2 * math.cos(A20), g_w=a_w * math.sin(a_w_ang), zs=zs, xs=xs)


def _margins_by_hand(z1, z2, x1, x2, m, internal, p1, p2):
    """The boundary points' radii of curvature (ISO 53 rack: h_l* = 1.25 - 0.38 (1 - sin a); a ring cut without a
    shaper: + instead of -) and the interference margins (GOST 16532 / 19274: rho_l <= rho_p; an undercut rho_l < 0
    counts as 0) for lowest active points p1, p2."""
    h_l = 1.25 - 0.38 * (1 - math.sin(A20))
    rho_l1 = 0.5 * m * z1 * math.sin(A20) - (h_l - x1) * m / math.sin(A20)
    if internal:
        rho_l2 = 0.5 * m * z2 * math.sin(A20) + (h_l + x2) * m / math.sin(A20)
        return rho_l1, rho_l2, (p1 - max(rho_l1, 0.0), rho_l2 - p2)
    rho_l2 = 0.5 * m * z2 * math.sin(A20) - (h_l - x2) * m / math.sin(A20)
    return rho_l1, rho_l2, (p1 - max(rho_l1, 0.0), p2 - max(rho_l2, 0.0))


def test_pair_contact_sliding_and_interference_by_hand():
    for z1, z2, x1, x2, internal in ((20, 47, 0.3, 0.1, False), (20, 70, 0.2, 0.5, True)):
        m = 2.5
        p = GearPair(SpurGear(z1, m, x1), SpurGear(z2, m, x2, internal=internal))
        h = _pair_by_hand(z1, z2, x1, x2, m, internal)
        assert p.d_a1 == pytest.approx(h["d_a1"], rel=1e-13) and p.d_a2 == pytest.approx(h["d_a2"], rel=1e-13)
        r1 = 0.5 * math.sqrt(h["d_a1"] ** 2 - h["d_b1"] ** 2)
        r2 = 0.5 * math.sqrt(h["d_a2"] ** 2 - h["d_b2"] ** 2)
        assert p.rho_a1() == pytest.approx(r1, rel=1e-12) and p.rho_a2() == pytest.approx(r2, rel=1e-12)
        g = h["g_w"]
        p1, p2 = (r2 - g, g + r1) if internal else (g - r2, g - r1)
        assert p.rho_p1() == pytest.approx(p1, rel=1e-12) and p.rho_p2() == pytest.approx(p2, rel=1e-12)
        eps = ((r1 - r2 + g) if internal else (r1 + r2 - g)) / (math.pi * m * math.cos(A20))
        assert p.epsilon_alpha() == pytest.approx(eps, rel=1e-12)
        s1, s2 = p.specific_sliding()
        assert s1 == pytest.approx(1 - r2 / p1 * z1 / z2, rel=1e-12) and s2 == pytest.approx(1 - r1 / p2 * z2 / z1,
                                                                                              rel=1e-12)
        rho_l1, rho_l2, want = _margins_by_hand(z1, z2, x1, x2, m, internal, p1, p2)
        assert p.involute_interference_margins() == pytest.approx(want, rel=1e-12)
        # given tips: the values on them
        da1, da2 = h["d_a1"] - 0.3, h["d_a2"] + (0.3 if internal else -0.3)
        r1g = 0.5 * math.sqrt(da1 ** 2 - h["d_b1"] ** 2)
        r2g = 0.5 * math.sqrt(da2 ** 2 - h["d_b2"] ** 2)
        assert p.rho_a1(da1) == pytest.approx(r1g, rel=1e-12) and p.rho_a2(da2) == pytest.approx(r2g, rel=1e-12)
        assert p.epsilon_alpha(da1, da2) == pytest.approx(
            ((r1g - r2g + g) if internal else (r1g + r2g - g)) / (math.pi * m * math.cos(A20)), rel=1e-12)
        assert p.s_na1 == pytest.approx(p.gear1.s_at(h["d_a1"]), rel=1e-13)
        assert p.s_na2 == pytest.approx(p.gear2.s_at(h["d_a2"]), rel=1e-13)
    assert GearPair.x_sum_for(20, 40, 2.5, 76.0) == inv_mod.x_sum_for_centre_distance(20, 40, 2.5, 76.0)
    assert GearPair.x_sum_for(20, 70, 2.5, 63.0, internal=True) == inv_mod.x_sum_for_centre_distance(
        20, 70, 2.5, 63.0, internal=True)


def test_pair_refusals_in_full():
    g = SpurGear(20, 2.5, 0.0)
    _refusal(lambda: GearPair(SpurGear(70, 2.5, 0.5, internal=True), g),
             "gear1.internal = True: the first gear of a pair must be external")
    _refusal(lambda: GearPair(g, SpurGear(40, 3.0)), "gear2.m = 3.0: must equal gear1.m = 2.5")
    other = BasicRack(c_star=0.3, rho_f_star=0.3)
    _refusal(lambda: GearPair(g, SpurGear(40, 2.5, rack=other)),
             f"gear2.rack = {other!r}: both gears must use the same basic rack")
    _refusal(lambda: GearPair(SpurGear(30, 2.5), SpurGear(30, 2.5, internal=True)),
             "gear2.z = 30: must exceed the pinion's z = 30")
    assert GearPair(SpurGear(30, 2.5), SpurGear(31, 2.5, 0.5, internal=True)).u == 31 / 30
    _refusal(lambda: GearPair(SpurGear(30, 2.5, -0.65), SpurGear(30, 2.5, -0.65)),
             "x = -1.3: shift sum too negative: inv α_w <= 0")
    _refusal(lambda: GearPair(g, "wheel"), str(InputError("gear", (g, "wheel"), "must be SpurGear")))  # value cut
    _refusal(lambda: GearPair(g, SpurGear(40, 2.5)).tip_interference_depth(),
             "gear2.internal = False: tip interference sweep is for internal pairs")


def _sheet_by_hand(p, h, D1, D2, da1, da2, internal):
    """The calculation sheet's rows as the ISO 21771 / GOST 16532 sheet lists them, each value from the
    pair worked out by hand (``h``) or the gear's own measured quantity (tested above)."""
    g1, g2 = p.gear1, p.gear2
    deg = math.degrees
    rows = [
        ("number of teeth", "z", "-", g1.z, g2.z),
        ("module", "m", "mm", g1.m, None),
        ("pressure angle", "alpha", "deg", 20.0, None),
        ("profile shift coefficient", "x", "-", g1.x, g2.x),
        ("gear ratio", "u", "-", g2.z / g1.z, None),
        ("operating pressure angle", "alpha_w", "deg", deg(h["alpha_w"]), None),
        ("operating centre distance", "a_w", "mm", h["a_w"], None),
        ("centre distance modification coefficient", "y", "-", h["y"], None),
        ("tip shortening coefficient", "delta_y", "-", h["dy"], None),
        ("reference diameter", "d", "mm", g1.m * g1.z, g2.m * g2.z),
        ("tip diameter", "d_a", "mm", da1, da2),
        ("root diameter", "d_f", "mm", g1.d_f, g2.d_f),
        ("operating pitch diameter", "d_w", "mm", 2 * h["a_w"] * g1.z / h["zs"], 2 * h["a_w"] * g2.z / h["zs"]),
        ("base diameter", "d_b", "mm", h["d_b1"], h["d_b2"]),
        ("reference tooth thickness", "s_n", "mm", g1.s_n, g2.s_n),
        ("constant chord", "s_c", "mm", g1.s_c, g2.s_c),
        ("height to constant chord", "h_c", "mm", g1.h_c(da1), g2.h_c(da2)),
        ("teeth (ring: spaces) spanned", "k", "-", g1.k_W, g2.k_W),
        ("base tangent length", "W_k", "mm", g1.W_k, g2.W_k),
        ("measuring roller diameter", "D", "mm", D1, D2),
        ("pressure angle at roller centre", "alpha_D", "deg", deg(g1.alpha_D(D1)), deg(g2.alpha_D(D2))),
        ("roller centre circle diameter", "d_D", "mm", g1.d_D(D1), g2.d_D(D2)),
        ("dimension over (ring: between) rollers", "M", "mm", g1.M(D1), g2.M(D2)),
        ("least profile shift (no undercut)", "x_min", "-", g1.x_min, None if internal else g2.x_min),
        ("radius of curvature at boundary point", "rho_l", "mm", g1.rho_l, g2.rho_l),
    ]
    r1 = 0.5 * math.sqrt(da1 ** 2 - h["d_b1"] ** 2)
    r2 = 0.5 * math.sqrt(da2 ** 2 - h["d_b2"] ** 2)
    g = h["g_w"]
    p1, p2 = (r2 - g, g + r1) if internal else (g - r2, g - r1)
    eps = ((r1 - r2 + g) if internal else (r1 + r2 - g)) / (math.pi * g1.m * math.cos(A20))
    rows += [("tooth thickness on tip circle", "s_na", "mm", g1.s_at(da1), g2.s_at(da2)),
             ("radius of curvature at lowest active point", "rho_p", "mm", p1, p2),
             ("transverse contact ratio", "epsilon_alpha", "-", eps, None)]
    return rows


def _same_rows(got, want):
    assert [r[:3] for r in got] == [r[:3] for r in want]
    for g, w in zip(got, want):
        for a, b in zip(g[3:], w[3:]):
            if b is None:
                assert a is None, g
            else:
                assert a == pytest.approx(b, rel=1e-11, abs=1e-12), (g, w)


@pytest.mark.parametrize("z1, z2, x1, x2, internal", [(20, 47, 0.3, 0.1, False), (20, 70, 0.2, 0.5, True)])
def test_pair_sheet_row_by_row(z1, z2, x1, x2, internal):
    """Every row of the calculation sheet: its quantity, symbol, unit and both gears' values - on the pair's own
    tips with each gear's recommended roller, then on given tips (a planet's one tip in two meshes) with one roller
    for both gears."""
    m = 2.5
    p = GearPair(SpurGear(z1, m, x1), SpurGear(z2, m, x2, internal=internal))
    h = _pair_by_hand(z1, z2, x1, x2, m, internal)
    g1, g2 = p.gear1, p.gear2
    assert g1.D_recommended != g2.D_recommended
    _same_rows(p.sheet(), _sheet_by_hand(p, h, g1.D_recommended, g2.D_recommended, h["d_a1"], h["d_a2"], internal))
    da1, da2 = h["d_a1"] - 0.3, h["d_a2"] + (0.3 if internal else -0.3)
    _same_rows(p.sheet(4.5, da1, da2), _sheet_by_hand(p, h, 4.5, 4.5, da1, da2, internal))
    # the rollers' rows read the roller: 4.5 mm and 5 mm give different alpha_D, d_D and M for both gears
    r45 = {r[1]: r for r in p.sheet(4.5)}
    r50 = {r[1]: r for r in p.sheet(5.0)}
    for sym in ("alpha_D", "d_D", "M"):
        assert r45[sym][3] != r50[sym][3] and r45[sym][4] != r50[sym][4]


def test_pair_sheet_of_a_ring_tip_inside_its_base_circle_stops_before_the_tip_rows():
    """A ring whose tip is given inside its base circle: s_na, rho_p and epsilon_alpha are undefined there, so the
    sheet ends with the boundary point's row (no error); the rows before are the same as on a valid tip."""
    p = GearPair(SpurGear(20, 2.5, 0.2), SpurGear(70, 2.5, 0.5, internal=True))
    da2 = p.gear2.d_b - 0.5
    rows = p.sheet(None, None, da2)
    assert [r[1] for r in rows][-1] == "rho_l" and len(rows) == 25
    assert {r[1]: r for r in rows}["d_a"][4] == da2


def _wrap_angle(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def _tip_sweep_by_hand(p, d_a1=None, d_a2=None, n=20001):
    """The internal mesh's tip-corner sweep written out independently (complex numbers; the nearest tooth found by
    the least angle to every tooth centre, not by rounding): the pinion turns phi, the ring phi z1/z2 the same way
    about the origin, the pinion's centre at (0, a_w); each tip corner (half the tip's tooth angle off its tooth's
    centre line) is taken into the mate's frame; inside the mate's teeth (between its base/root and tip circles)
    the depth is the arc (psi_mate(r) - angle to the nearest tooth centre) r, past the ring's root circle (inside the
    pinion's) the radial distance past it.  The largest depth over a turn of the pinion by a grid of n and three
    rounds of finer grids about its best point; (pinion corners, ring corners)."""
    g1, g2 = p.gear1, p.gear2
    da1 = p.d_a1 if d_a1 is None else d_a1
    da2 = p.d_a2 if d_a2 is None else d_a2
    ra1, ra2 = da1 / 2, da2 / 2
    rf1, rf2 = g1.d_f / 2, g2.d_f / 2
    z1, z2 = g1.z, g2.z
    O1 = 1j * p.a_w
    psi1 = float(g1.psi_at(da1))
    psi2 = float(g2.psi_at(max(da2, g2.d_b)))
    c1 = math.pi / 2 + 2 * math.pi * np.arange(z1) / z1
    c2 = math.pi / 2 + math.pi / z2 + 2 * math.pi * np.arange(z2) / z2

    def depth(r, th, centres, g, lo, hi, past):
        delta = np.min(np.abs(_wrap_angle(th[:, None] - centres[None, :])), axis=1)
        ins = (r > lo) & (r < hi)
        return np.where(ins, (g.psi_at(np.where(ins, 2 * r, g.d)) - delta) * r, past)

    def pinion(phi):
        out = np.full(phi.shape, -np.inf)
        for s in (-1, 1):
            q = (O1 + ra1 * np.exp(1j * (math.pi / 2 + phi + s * psi1))) * np.exp(-1j * phi * z1 / z2)
            r = np.abs(q)
            out = np.maximum(out, depth(r, np.angle(q), c2, g2, max(ra2, g2.d_b / 2), rf2,
                                        np.where(r >= rf2, r - rf2, -np.inf)))
        return out

    def ring(phi):
        out = np.full(phi.shape, -np.inf)
        for s in (-1, 1):
            q = (ra2 * np.exp(1j * (math.pi / 2 + math.pi / z2 + s * psi2 + phi * z1 / z2)) - O1) * np.exp(-1j * phi)
            r = np.abs(q)
            out = np.maximum(out, depth(r, np.angle(q), c1, g1, max(g1.d_b / 2, rf1), ra1,
                                        np.where(r <= rf1, rf1 - r, -np.inf)))
        return out

    found = []
    for fn in (pinion, ring):
        phi = np.linspace(-math.pi, math.pi, n)
        d = fn(phi)
        i = int(np.argmax(d))
        best = float(d[i])
        lo, hi = phi[i] - (phi[1] - phi[0]), phi[i] + (phi[1] - phi[0])
        for _ in range(3):
            f = np.linspace(lo, hi, 2001)
            dd = fn(f)
            j = int(np.argmax(dd))
            best = max(best, float(dd[j]))
            lo, hi = f[j] - (f[1] - f[0]), f[j] + (f[1] - f[0])
        found.append(best)
    return tuple(found)


@pytest.mark.parametrize("z1, z2, x2, dd1, dd2, branch", [
    (20, 26, 0.0, 0.0, 0.0, "ring"),           # 6 teeth apart: the ring's corners dig 0.208 mm into the pinion
    (20, 24, 0.0, -1.0, 0.0, "ring"),          # 4 apart, a pinion tip 1 mm smaller: 0.695 mm
    (12, 20, 0.5, 0.0, 0.0, "ring"),           # a shifted ring 8 apart: 0.85 um, found all the same
    (20, 32, 0.0, 0.0, -2.0, "ring"),          # the ring's tip 2 mm lower: 0.033 mm
    (21, 27, 0.0, 0.0, 0.0, "ring"),           # an odd pinion (its tooth and space centres are not opposite)
    (20, 26, 0.0, 2.0, 3.0, "rim"),            # the pinion's tip 0.25 mm past the ring's root circle
    (20, 60, 0.0, 0.0, -3.6, "pinion root"),   # the ring's tip 0.3 mm inside the pinion's root circle
    (20, 60, 0.0, 0.0, 0.0, "none"),           # conjugate: 0 to rounding
    (20, 30, 0.0, 0.0, 0.0, "none"),
])
def test_tip_interference_depth_against_the_sweep_written_out(z1, z2, x2, dd1, dd2, branch):
    p = GearPair(SpurGear(z1, 3.0), SpurGear(z2, 3.0, x2, internal=True))
    kw = {"d_a1": p.d_a1 + dd1, "d_a2": p.d_a2 + dd2} if (dd1 or dd2) else {}
    pin, rin = _tip_sweep_by_hand(p, **kw)
    got = p.tip_interference_depth(**kw)
    assert got == pytest.approx(max(pin, rin), abs=1e-6)
    assert p.tip_interference_depths(**kw) == pytest.approx((pin, rin), abs=1e-6)   # each gear's corners alone
    if branch == "ring":
        assert rin > pin + 1e-5 and rin > 1e-6
    elif branch == "rim":
        assert got == pytest.approx(p.a_w + kw["d_a1"] / 2 - p.gear2.d_f / 2, abs=1e-12)
    elif branch == "pinion root":   # the ring's tip reaches r_a2 - a_w from the pinion's centre
        assert p.tip_interference_depths(**kw)[1] == pytest.approx(p.gear1.d_f / 2 - (kw["d_a2"] / 2 - p.a_w),
                                                                   abs=1e-12)
        assert got == pytest.approx(0.3, abs=1e-12)
    else:
        assert abs(got) <= 1e-9 and max(pin, rin) <= 1e-9


def test_tip_interference_of_a_ring_tip_inside_its_base_circle():
    """A ring tip given below its base circle (d_a2 = d_b2 - 1 mm): its corners sit on the base circle's tooth angle,
    the pinion's corners count from the base circle outwards (not from the given tip): 0.042 mm in a 20/32 pair."""
    p = GearPair(SpurGear(20, 3.0), SpurGear(32, 3.0, internal=True))
    da2 = p.gear2.d_b - 1.0
    pin, rin = _tip_sweep_by_hand(p, d_a2=da2)
    got = p.tip_interference_depth(d_a2=da2)
    assert got == pytest.approx(max(pin, rin), abs=1e-6) and got > 0.04
    assert p.tip_interference_depths(d_a2=da2) == pytest.approx((pin, rin), abs=1e-6)


def test_tip_interference_refines_between_the_samples():
    """Few samples (61 over a turn) still find the depth of the sweep's peak to 1e-6 mm: the search refines about the
    best sample (the 61 samples alone give 0.089 mm of the peak's 0.208 here, 6001 samples alone 0.2066)."""
    p = GearPair(SpurGear(20, 3.0), SpurGear(26, 3.0, internal=True))
    pin, rin = _tip_sweep_by_hand(p)
    got = p.tip_interference_depth(samples=61)
    assert got == pytest.approx(rin, abs=1e-6)
    # the ring's corners' peak is refined from the 61 samples; the pinion's corners' peak (0.178 mm) is narrower than
    # their spacing (0.10 rad) and is missed at 61 (found at the default 6001: above)
    assert p.tip_interference_depths(samples=61)[1] == pytest.approx(rin, abs=1e-6)


def test_interference_margins_and_sliding_on_given_tips_and_undercut_gears():
    """The margins and the specific sliding on tips given apart from the pair's own (each tip moves the mate's
    lowest active point: rho_p1 follows d_a2, rho_p2 follows d_a1), and on undercut gears (rho_l < 0 counts as 0:
    the involute runs down to the base circle) - every value by hand."""
    m = 2.5
    h_l = 1.25 - 0.38 * (1 - math.sin(A20))
    for z1, z2, x1, x2, internal in ((12, 14, 0.0, 0.0, False), (20, 47, 0.3, 0.1, False), (12, 70, 0.0, 0.5, True)):
        p = GearPair(SpurGear(z1, m, x1), SpurGear(z2, m, x2, internal=internal))
        h = _pair_by_hand(z1, z2, x1, x2, m, internal)
        da1, da2 = h["d_a1"] - 0.4, h["d_a2"] + (0.7 if internal else -0.7)
        r1 = 0.5 * math.sqrt(da1 ** 2 - h["d_b1"] ** 2)
        r2 = 0.5 * math.sqrt(da2 ** 2 - h["d_b2"] ** 2)
        g = h["g_w"]
        p1, p2 = (r2 - g, g + r1) if internal else (g - r2, g - r1)
        assert p.rho_p1(da2) == pytest.approx(p1, rel=1e-12) and p.rho_p2(da1) == pytest.approx(p2, rel=1e-12)
        rho_l1, rho_l2, want = _margins_by_hand(z1, z2, x1, x2, m, internal, p1, p2)
        if z1 == 12:
            assert rho_l1 < 0          # undercut pinion
        if z2 == 14:
            assert rho_l2 < 0
        assert p.involute_interference_margins(da1, da2) == pytest.approx(want, rel=1e-12, abs=1e-12)
        s1, s2 = p.specific_sliding(da1, da2)
        assert s1 == pytest.approx(1 - r2 / p1 * z1 / z2, rel=1e-12)
        assert s2 == pytest.approx(1 - r1 / p2 * z2 / z1, rel=1e-12)
    # a ring tip inside its base circle: the pinion's margin is the radial shortfall, less the pinion's rho_l
    p = GearPair(SpurGear(20, m, 0.3), SpurGear(70, m, 0.5, internal=True))
    rho_l1 = 0.5 * m * 20 * math.sin(A20) - (h_l - 0.3) * m / math.sin(A20)
    assert rho_l1 > 1.0
    d_b2 = 70 * m * math.cos(A20)
    m1, _ = p.involute_interference_margins(None, d_b2 - 0.6)
    assert m1 == pytest.approx(-0.3 - rho_l1, rel=1e-12)
    # on the base circle itself the involute has no length: rho_a2 = 0, the pinion's lowest point at -a_w sin(alpha_w)
    m1, _ = p.involute_interference_margins(None, d_b2)
    assert m1 == pytest.approx(-p.g_w - rho_l1, rel=1e-12)


def test_tip_interference_depth_samples_as_asked():
    """The sample count reaches the sweep: 30/33 teeth, the pinion's corners go 1.386 mm deep, the ring's 1.283 mm;
    7 samples over a turn miss the pinion's peak (the ring's is still refined to its value)."""
    p = GearPair(SpurGear(30, 3.0), SpurGear(33, 3.0, internal=True))
    pin, rin = _tip_sweep_by_hand(p)
    assert p.tip_interference_depth() == pytest.approx(pin, abs=1e-6) and pin > rin + 0.1
    assert p.tip_interference_depth(samples=7) == pytest.approx(rin, abs=1e-6)


def test_pinion_margin_of_an_undercut_pinion_in_a_ring_whose_tip_is_inside_its_base_circle():
    """rho_l of an undercut pinion counts as 0 in the ring-tip-inside-base-circle branch: the margin is the radial
    shortfall alone."""
    p = GearPair(SpurGear(12, 2.5), SpurGear(70, 2.5, 0.5, internal=True))
    assert p.gear1.rho_l < 0
    d_b2 = 70 * 2.5 * math.cos(A20)
    assert p.involute_interference_margins(None, d_b2 - 0.6)[0] == pytest.approx(-0.3, rel=1e-12)
