"""Involute gear sheet (gears/involute.py): seed 004 Tables 6 and 7 row by row, two published
worked examples (KHK external, SDP-SI/KHK internal), independent geometric computations of W_k and
M from sampled involute flanks, identities, and the input errors.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

from propulsor.errors import InputError
from propulsor.gears.gear_pair import GearPair
from propulsor.gears.involute import (
    BasicRack,
    SpurGear,
    inv,
    inv_inverse,
    roller_diameter_for_contact_at,
    x_sum_for_centre_distance,
    z_min_feasible,
)


def dms(d, m, s):
    return math.radians(d + m / 60 + s / 3600)


ARCSEC = math.radians(1 / 3600)

# ----------------------------------------------------------------------------- the thesis set
SUN = SpurGear(16, 10.0, 0.5)
PLANET = SpurGear(20, 10.0, 0.5)
RING = SpurGear(56, 10.0, 1.417, internal=True, z0=14, x0=0.04)
SP = GearPair(SUN, PLANET)
PR = GearPair(PLANET, RING)
# the thesis ran the internal mesh at a_w = 188 (rounded); x3 for that is 1.41736 (printed 1.417)
X3_188 = 0.5 + x_sum_for_centre_distance(20, 56, 10.0, 188.0, internal=True)
PR188 = GearPair(PLANET, SpurGear(56, 10.0, X3_188, internal=True, z0=14, x0=0.04))
# tip diameters the thesis actually used downstream (d + 2m for the externals) and printed for the ring
DA_SUN_T, DA_PLANET_T, DA_RING_T = 180.0, 220.0, 567.45
D_ROLLER = 17.362

# (label, computed, printed, tolerance) — tolerance is one unit of the printed last digit unless
# noted; angles in radians with ±2".
TABLE6 = [
    ("a_w", SP.a_w, 188.643, 5e-4),
    ("alpha_w", SP.alpha_w, dms(26, 16, 50), 2 * ARCSEC),
    ("u", SP.u, 1.25, 1e-12),
    ("d1", SUN.d, 160.0, 1e-9),
    ("d2", PLANET.d, 200.0, 1e-9),
    ("d_f1", SUN.d_f, 145.0, 1e-9),
    ("d_f2", PLANET.d_f, 185.0, 1e-9),
    ("d_w1", SP.d_w1, 167.683, 5e-4),
    ("d_w2", SP.d_w2, 209.603, 5e-4),
    ("d_b1", SUN.d_b, 150.351, 5e-4),
    ("d_b2", PLANET.d_b, 187.938, 1e-3),  # 187.9385: Table 6 rounds down, Table 7 prints 187.939
    ("S_c1", SUN.s_c, 17.084, 5e-4),
    ("S_c2", PLANET.s_c, 17.084, 5e-4),
    ("h_c1 (d_a=180)", SUN.h_c(DA_SUN_T), 6.891, 5e-4),
    ("h_c2 (d_a=220)", PLANET.h_c(DA_PLANET_T), 6.891, 5e-4),
    ("rho_c1", SUN.rho_c, 36.452, 5e-4),
    ("rho_c2", PLANET.rho_c, 43.293, 1e-3),  # 43.2924; Table 7 prints 43.292
    ("rho_p1 (tips 180/220)", SP.rho_p1(DA_PLANET_T), 26.342, 5e-4),
    ("rho_p2 (tips 180/220)", SP.rho_p2(DA_SUN_T), 34.04, 5e-3),
    ("k1", SUN.k_W, 3, 0),
    ("k2", PLANET.k_W, 3, 0),
    ("W1", SUN.W_k, 79.464, 5e-4),
    ("W2", PLANET.W_k, 80.025, 5e-4),
    ("rho_W1", SUN.rho_W, 39.732, 5e-4),
    ("rho_W2", PLANET.rho_W, 40.012, 5e-4),
    ("rho_a2 (d_a=220)", PLANET.rho_at(DA_PLANET_T), 57.182, 5e-4),
    ("alpha_D1", SUN.alpha_D(D_ROLLER), dms(30, 12, 19), 2 * ARCSEC),
    ("d_D1", SUN.d_D(D_ROLLER), 173.971, 5e-4),
    ("d_D2", PLANET.d_D(D_ROLLER), 214.406, 5e-4),
    ("rho_M1", SUN.rho_M(D_ROLLER), 35.081, 5e-4),
    ("rho_M2", PLANET.rho_M(D_ROLLER), 42.916, 5e-4),
    ("M1", SUN.M(D_ROLLER), 191.333, 5e-4),
    ("M2", PLANET.M(D_ROLLER), 231.768, 5e-4),
    ("s_n", SUN.s_n, 19.348, 5e-4),
    ("x_min1", SUN.x_min, 0.064, 5e-4),
    ("x_min2", PLANET.x_min, -0.17, 5e-3),
    # the thesis took h_l* = 1; GOST's h_l* = h_a*+c*−ρ_f*(1−sin α) = 0.99997 moves the 3rd decimal
    ("rho_l1", SUN.rho_l, 12.743, 1e-3),
    ("rho_l2", PLANET.rho_l, 19.584, 1e-3),
    ("s_na1 (d_a=180)", SUN.tip_thickness(DA_SUN_T), 10.752, 1e-3),
    ("s_na2 (d_a=220)", PLANET.tip_thickness(DA_PLANET_T), 10.952, 1e-3),
    ("theta_p1", SP.specific_sliding(DA_SUN_T, DA_PLANET_T)[0], -0.73659, 5e-5),
    ("theta_p2", SP.specific_sliding(DA_SUN_T, DA_PLANET_T)[1], -0.81711, 5e-5),
    ("epsilon_alpha (tips 180/220)", SP.epsilon_alpha(DA_SUN_T, DA_PLANET_T), 0.784, 5e-4),
]

TABLE7 = [
    ("u", PR.u, 2.8, 1e-12),
    ("x3 for a_w = 188", X3_188, 1.417, 5e-4),
    ("alpha_w (a_w=188)", PR188.alpha_w, dms(25, 52, 50), 2 * ARCSEC),
    ("d_w1 (a_w=188)", PR188.d_w1, 208.889, 5e-4),
    ("d_w2 (a_w=188)", PR188.d_w2, 584.889, 5e-4),
    ("d2", RING.d, 560.0, 1e-9),
    ("d_a2", PR.d_a2, 567.45, 5e-3),
    ("d_f1", PLANET.d_f, 185.0, 1e-9),
    ("d_f2 (shaper)", RING.d_f, 609.17, 5e-3),
    ("d_b1", PLANET.d_b, 187.939, 5e-4),
    ("d_b2", RING.d_b, 526.228, 5e-4),
    ("S_c1", PLANET.s_c, 17.084, 5e-4),
    ("h_c1 (d_a=220)", PLANET.h_c(DA_PLANET_T), 6.891, 5e-4),
    ("h_c2", RING.h_c(DA_RING_T), -4.592, 5e-4),
    ("rho_c1", PLANET.rho_c, 43.292, 5e-4),
    ("rho_c2", RING.rho_c, 93.232, 5e-4),
    ("rho_p1 (a_w=188, tips 220/567.45)", PR188.rho_p1(DA_RING_T), 24.103, 5e-4),
    ("rho_p2 (a_w=188, tips 220/567.45)", PR188.rho_p2(DA_PLANET_T), 139.243, 5e-4),
    ("k1", PLANET.k_W, 3, 0),
    ("k2", RING.k_W, 9, 0),
    ("W1", PLANET.W_k, 80.025, 5e-4),
    ("W2", RING.W_k, 268.467, 5e-4),
    ("rho_W1", PLANET.rho_W, 40.012, 5e-4),
    ("rho_W2", RING.rho_W, 134.234, 5e-4),
    ("rho_a1 (d_a=220)", PLANET.rho_at(DA_PLANET_T), 57.182, 5e-4),
    ("rho_a2 (d_a=567.45)", RING.rho_at(DA_RING_T), 106.165, 5e-4),
    ("alpha_D1", PLANET.alpha_D(D_ROLLER), dms(28, 46, 14), 2 * ARCSEC),
    ("alpha_D2", RING.alpha_D(D_ROLLER), dms(24, 34, 17), 2 * ARCSEC),
    ("d_D1", PLANET.d_D(D_ROLLER), 214.406, 5e-4),
    ("d_D2", RING.d_D(D_ROLLER), 578.626, 5e-4),
    ("rho_M1", PLANET.rho_M(D_ROLLER), 42.916, 5e-4),
    ("rho_M2", RING.rho_M(D_ROLLER), 128.986, 5e-4),
    ("M1", PLANET.M(D_ROLLER), 231.768, 5e-4),
    ("M2", RING.M(D_ROLLER), 561.264, 5e-4),
    ("s_n1", PLANET.s_n, 19.348, 5e-4),
    ("s_n2", RING.s_n, 5.393, 5e-4),
    ("x_min1", PLANET.x_min, -0.17, 5e-3),
    ("rho_l1", PLANET.rho_l, 19.583, 1e-3),
    ("rho_l2 (shaper)", RING.rho_l, 151.463, 5e-4),
    ("s_na1 (d_a=220)", PLANET.tip_thickness(DA_PLANET_T), 10.952, 1e-3),
    ("s_na2 (d_a=567.45)", RING.tip_thickness(DA_RING_T), 8.344, 5e-4),
    ("epsilon_alpha (a_w=188, tips 220/567.45)", PR188.epsilon_alpha(DA_PLANET_T, DA_RING_T), 1.121, 1e-3),
]


@pytest.mark.parametrize("label, value, printed, tol", TABLE6, ids=[r[0] for r in TABLE6])
def test_thesis_table6_row(label, value, printed, tol):
    assert abs(value - printed) <= tol + 1e-12, f"{label}: computed {value!r}, printed {printed!r}"


@pytest.mark.parametrize("label, value, printed, tol", TABLE7, ids=[r[0] for r in TABLE7])
def test_thesis_table7_row(label, value, printed, tol):
    assert abs(value - printed) <= tol + 1e-12, f"{label}: computed {value!r}, printed {printed!r}"


def test_thesis_W_values_to_the_printed_digit():
    """SPEC §6: W over k teeth is right in the thesis: 79.464, 80.025, 268.467 mm."""
    assert (SUN.k_W, PLANET.k_W, RING.k_W) == (3, 3, 9)
    assert round(SUN.W_k, 3) == 79.464
    assert round(PLANET.W_k, 3) == 80.025
    assert round(RING.W_k, 3) == 268.467


def test_thesis_entries_that_do_not_follow_from_the_inputs():
    """Printed values of Tables 6/7 that the inputs do not give (documented, with the right value)."""
    # Table 6 d_a = 180 / 200: with x = 0.5 and tip shortening Δy = 0.1357 the tips are 187.286 / 227.286
    assert SP.delta_y == pytest.approx(0.135706, abs=1e-6)
    assert SP.d_a1 == pytest.approx(187.286, abs=5e-4) and SP.d_a1 - 180.0 > 7.0
    assert SP.d_a2 == pytest.approx(227.286, abs=5e-4) and SP.d_a2 - 200.0 > 27.0
    # ... and the thesis used d + 2m (180 / 220) downstream: h_c, s_na, ρ_p and ε_α reproduce only with
    # those (rows above); with the true tips ε_α is 1.227 (≥ 1.2 recommended), not 0.784
    assert SP.epsilon_alpha() == pytest.approx(1.2270, abs=1e-4)
    assert SP.epsilon_alpha() > 1.2 > SP.epsilon_alpha(DA_SUN_T, DA_PLANET_T)
    # Table 6 ρ_a1 = 49.894 matches neither d_a = 180 (49.485, used for ρ_p2 = 34.04) nor 187.286
    assert abs(SUN.rho_at(180.0) - 49.894) > 0.4 and abs(SUN.rho_at(SP.d_a1) - 49.894) > 5.0
    assert SUN.rho_at(180.0) == pytest.approx(49.484, abs=5e-4)
    # Table 6 α_D2 = 28°26'14" is a typo of 28°46'14" (Table 7)
    assert abs(PLANET.alpha_D(D_ROLLER) - dms(28, 26, 14)) > 19 * 60 * ARCSEC
    # Table 7 a_w = 188 is not what x3 = 1.417 gives (187.997), and neither equals the sun–planet 188.643
    assert PR.a_w == pytest.approx(187.9972, abs=1e-4)
    assert SP.a_w - 188.0 == pytest.approx(0.643, abs=5e-4)
    # Table 7 planet d_a = 220: the internal-mesh planet tip is d + 2(h_a* + x)m = 230
    assert PR.d_a1 == pytest.approx(230.0, abs=1e-9)
    # Table 7 ring S_c = 17.084 is the external value; the ring's chord is m(π/2 cos²α − x sin 2α)
    assert RING.s_c == pytest.approx(4.762, abs=5e-4)
    # ... its h_c = −4.592 (printed, and reproduced with s_c = 4.762) is negative: the chord lies beyond
    # the tip, so the constant chord of the ring cannot be measured ("выполнено" in the thesis is wrong)
    assert RING.h_c(DA_RING_T) < 0
    # Table 7 condition "ρ_p < ρ_W < ρ_a" for the ring: the printed numbers 139.243 < 134.234 < 106.165 are
    # false; for a ring the involute runs from the tip (small ρ) to the root, so ρ_a2 < ρ_W < ρ_p2 holds
    assert RING.rho_at(DA_RING_T) < RING.rho_W < PR188.rho_p2(DA_PLANET_T)


def test_sheet_rows_carry_the_same_numbers():
    rows = {r[1]: r for r in PR.sheet(D_ROLLER)}
    assert rows["W_k"][3:] == (PLANET.W_k, RING.W_k)
    assert rows["M"][3:] == (PLANET.M(D_ROLLER), RING.M(D_ROLLER))
    assert rows["d_a"][3:] == (PR.d_a1, PR.d_a2)
    assert rows["epsilon_alpha"][3] == PR.epsilon_alpha()
    assert rows["alpha_w"][3] == pytest.approx(math.degrees(PR.alpha_w))
    assert {r[1] for r in SP.sheet()} >= {"a_w", "d_f", "d_b", "d_w", "s_c", "h_c", "k", "s_na", "x_min"}


def test_tip_shortening_restores_the_radial_clearance():
    """External: shortened tips leave exactly c*m at both roots (GOST 16532); internal: (c* + k2)m at the
    planet root and (c* + Δy)m at the ring root for rack-cut rings."""
    assert SP.c_root1 == pytest.approx(2.5, abs=1e-12) and SP.c_root2 == pytest.approx(2.5, abs=1e-12)
    ring_rack = GearPair(PLANET, SpurGear(56, 10.0, 1.417, internal=True))
    assert ring_rack.c_root1 == pytest.approx((0.25 + ring_rack.k2) * 10, abs=1e-9)
    assert ring_rack.c_root2 == pytest.approx((0.25 + ring_rack.delta_y) * 10, abs=1e-9)


# ----------------------------------------------------------------------------- published examples
def test_khk_external_profile_shifted_example():
    """KHK Gear Technical Reference, 'Calculation of profile shifted spur gears' worked example
    (m = 3, α = 20°, z = 12/24, x = 0.6/0.36, a = 56.5 mm), as tabulated by
    http://bolsover.com/utilitiesforalibre/profile-shifted-external-spur-gears.html :
    Σx 0.960, inv α_w 0.034317, α_w 26.0888°, y 0.83333, d_w 37.667/75.333, h_a 4.420/3.700,
    d_a 44.840/79.400, d_f 32.100/66.660, ε 1.202 (their α_w, y from the rounded a = 56.5)."""
    assert x_sum_for_centre_distance(12, 24, 3.0, 56.5) == pytest.approx(0.960, abs=5e-4)
    p = GearPair(SpurGear(12, 3.0, 0.6), SpurGear(24, 3.0, 0.36))
    assert p.a_w == pytest.approx(56.500, abs=5e-4)
    # the page derives α_w from the rounded a = 56.5; from x the difference is in the 7th decimal
    assert float(inv(p.alpha_w)) == pytest.approx(0.034317, abs=1.5e-6)
    assert math.degrees(p.alpha_w) == pytest.approx(26.0888, abs=5e-4)
    assert p.y == pytest.approx(0.83333, abs=1e-4)
    assert (p.d_w1, p.d_w2) == pytest.approx((37.667, 75.333), abs=5e-4)
    assert ((p.d_a1 - p.gear1.d) / 2, (p.d_a2 - p.gear2.d) / 2) == pytest.approx((4.420, 3.700), abs=5e-4)
    assert (p.d_a1, p.d_a2) == pytest.approx((44.840, 79.400), abs=5e-4)
    assert (p.gear1.d_f, p.gear2.d_f) == pytest.approx((32.100, 66.660), abs=5e-4)
    assert (p.gear1.d_b, p.gear2.d_b) == pytest.approx((33.8289, 67.6579), abs=5e-5)
    assert p.epsilon_alpha() == pytest.approx(1.202, abs=5e-4)


def test_sdp_si_khk_internal_gear_example():
    """SDP/SI 'Elements of Metric Gear Technology' §5.1 Table 5-1 / KHK Technical Reference
    (http://www.sdp-si.com/D785/HTML1/D785T034_9.html): profile-shifted internal pair m = 3, α = 20°,
    z1 = 16, z2 = 24, x1 = 0, x2 = +0.5 → a_x = 13.1683 mm, α_w = 31.0937°, d_w 52.673 / 79.010,
    d_a 54.000 / 69.000, d_f 40.500 / 82.500 (their tips/roots are the nominal ones: h_a2 = (1 − x2)m,
    rack-generated root; no GOST k2/Δy correction).  The numbers were taken from that table as
    remembered and cross-checked: a_x and α_w agree with each other through a cos α / cos α_w."""
    p = GearPair(SpurGear(16, 3.0, 0.0), SpurGear(24, 3.0, 0.5, internal=True))
    assert p.a_w == pytest.approx(13.1683, abs=5e-5)
    assert math.degrees(p.alpha_w) == pytest.approx(31.0937, abs=1e-4)
    assert (p.d_w1, p.d_w2) == pytest.approx((52.673, 79.010), abs=5e-4)
    assert (p.gear1.d_a, p.gear2.d_a) == pytest.approx((54.0, 69.0), abs=1e-9)
    assert (p.gear1.d_f, p.gear2.d_f) == pytest.approx((40.5, 82.5), abs=1e-9)
    assert x_sum_for_centre_distance(16, 24, 3.0, 13.1683, internal=True) == pytest.approx(0.5, abs=1e-4)


def test_sdp_si_chordal_tooth_thickness_example():
    """SDP/SI Table 10-1 example: m = 10, α = 20°, z = 12, x = +0.3 → s = 17.8918 mm."""
    assert SpurGear(12, 10.0, 0.3).s == pytest.approx(17.8918, abs=5e-5)


# ----------------------------------------------------------------------------- independent geometry
def _flank_point(g: SpurGear, r, centre_angle, side):
    """Point of the involute flank at radius r of the tooth (ring: space) centred at centre_angle;
    side = ±1.  For a ring the 'tooth' is the space, half angle e/d + inv α − inv α_r."""
    a_r = math.acos(g.d_b / (2 * r))
    if g.internal:
        half = g.e / g.d + float(inv(g.alpha)) - float(inv(a_r))
    else:
        half = g.s / g.d + float(inv(g.alpha)) - float(inv(a_r))
    th = centre_angle + side * half
    return np.array([r * math.cos(th), r * math.sin(th)])


def _span_numeric(g: SpurGear, k: int) -> float:
    """Width of k adjacent teeth (ring: spaces) between two parallel planes perpendicular to the
    group's symmetry line: the support function of the sampled involute flanks."""
    pitch = 2 * math.pi / g.z
    beta = (k - 1) * pitch / 2
    t = np.array([-math.sin(beta), math.cos(beta)])
    rb = g.d_b / 2
    r_hi = (g.d_f / 2) if g.internal else (g.d_a / 2)
    lo, hi = rb * (1 + 1e-12), r_hi
    first = minimize_scalar(lambda r: _flank_point(g, r, 0.0, -1) @ t, bounds=(lo, hi), method="bounded",
                            options={"xatol": 1e-12})
    last = minimize_scalar(lambda r: -(_flank_point(g, r, (k - 1) * pitch, +1) @ t), bounds=(lo, hi),
                           method="bounded", options={"xatol": 1e-12})
    return -last.fun - first.fun


def _over_rollers_numeric(g: SpurGear, D: float) -> float:
    """Roller of diameter D in a space, centre on the space's symmetry line at radius R with the
    flank at distance D/2; M = 2R ± D (even z)."""
    pitch = 2 * math.pi / g.z
    # external: the space between teeth at 0 and pitch is centred at pitch/2, bounded by side +1 of
    # tooth 0; ring: the space itself is the 'tooth' centred at 0, bounded by its side +1 flank
    space_c = 0.0 if g.internal else pitch / 2
    rb = g.d_b / 2
    r_hi = max(g.d_f, g.d_a) / 2 + D

    def gap(R):
        c = np.array([R * math.cos(space_c), R * math.sin(space_c)])
        res = minimize_scalar(lambda r: np.linalg.norm(_flank_point(g, r, 0.0, +1) - c),
                              bounds=(rb * (1 + 1e-12), r_hi), method="bounded", options={"xatol": 1e-13})
        return res.fun - D / 2

    if g.internal:
        R = brentq(gap, g.d_D(D) / 2 - 2 * D, g.d_D(D) / 2 + 0.3 * D, xtol=1e-12)
        return 2 * R - D
    R = brentq(gap, g.d_D(D) / 2 - 0.3 * D, g.d_D(D) / 2 + 2 * D, xtol=1e-12)
    return 2 * R + D


@pytest.mark.parametrize("g", [SUN, PLANET, RING, SpurGear(30, 4.0, -0.2), SpurGear(40, 2.5, 0.3, internal=True)],
                         ids=["sun", "planet", "ring", "z30", "ring40"])
def test_W_k_equals_the_support_width_of_sampled_flanks(g):
    assert _span_numeric(g, g.k_W) == pytest.approx(g.W_k, abs=1e-6)


@pytest.mark.parametrize("g", [SUN, PLANET, RING, SpurGear(30, 4.0, -0.2), SpurGear(40, 2.5, 0.3, internal=True)],
                         ids=["sun", "planet", "ring", "z30", "ring40"])
def test_M_equals_a_roller_touching_sampled_flanks(g):
    D = 1.7362 * g.m if not g.internal else 1.5 * g.m
    assert _over_rollers_numeric(g, D) == pytest.approx(g.M(D), abs=1e-6)


def test_k_W_puts_the_caliper_contact_near_d_plus_2xm():
    for g in (SUN, PLANET, RING, SpurGear(60, 2.0, 0.0), SpurGear(25, 5.0, 0.8)):
        d_contact = 2 * math.hypot(g.d_b / 2, g.rho_W)
        d_target = g.d + 2 * g.x * g.m
        # one more or one fewer tooth moves the contact further from the target
        for k in (g.k_W - 1, g.k_W + 1):
            if k < 1:
                continue
            d_k = 2 * math.hypot(g.d_b / 2, g.W(k) / 2)
            assert abs(d_k - d_target) >= abs(d_contact - d_target)


def test_roller_for_contact_at_a_diameter_touches_there():
    for g in (SUN, RING):
        d_y = g.d + 2 * g.x * g.m
        D = roller_diameter_for_contact_at(g, d_y)
        contact_rho = g.rho_M(D)
        assert 2 * math.hypot(g.d_b / 2, contact_rho) == pytest.approx(d_y, abs=1e-8)
    assert (SUN.D_recommended, PLANET.D_recommended, RING.D_recommended) == pytest.approx(
        (20.941, 19.980, 16.259), abs=1e-3)
    # the thesis roller 17.362 follows no contact rule: contact at d or at d + 2xm gives other sizes
    assert abs(roller_diameter_for_contact_at(SUN, SUN.d) - D_ROLLER) > 4
    assert abs(roller_diameter_for_contact_at(SUN, SUN.d + 10) - D_ROLLER) > 3


# ----------------------------------------------------------------------------- identities
def test_inv_known_value_and_inverse_precision():
    assert float(inv(math.radians(20))) == pytest.approx(0.014904383867336446, abs=1e-17)
    eps = np.finfo(float).eps
    for a in np.linspace(1e-4, 1.5, 301):
        v = float(inv(a))
        b = inv_inverse(v)
        # residual at the level of the rounding noise of tan α − α itself
        assert abs(float(inv(b)) - v) <= 4 * eps * math.tan(b)
        # the angle to its condition number: an error eps·tan α in inv α moves α by that / tan²α
        assert abs(b - a) <= 8 * eps * (1 / math.tan(a) + a)


@given(st.floats(min_value=0.1, max_value=1.55))
@settings(max_examples=200, deadline=None)
def test_inv_inverse_roundtrip(a):
    eps = np.finfo(float).eps
    assert abs(inv_inverse(float(inv(a))) - a) <= 8 * eps * (1 / math.tan(a) + a)


@given(z1=st.integers(10, 60), dz=st.integers(0, 80), x1=st.floats(-0.3, 0.8), x2=st.floats(-0.3, 0.8),
       m=st.sampled_from([1.0, 2.5, 10.0]))
@settings(max_examples=80, deadline=None)
def test_external_pair_is_backlash_free_and_inverse_consistent(z1, dz, x1, x2, m):
    try:
        p = GearPair(SpurGear(z1, m, x1), SpurGear(z1 + dz, m, x2))
    except InputError:
        return
    # no backlash on the operating circles: s_w1 + s_w2 = p_w
    assert p.gear1.s_at(p.d_w1) + p.gear2.s_at(p.d_w2) == pytest.approx(math.pi * p.d_w1 / z1, abs=1e-9 * m)
    assert x_sum_for_centre_distance(z1, z1 + dz, m, p.a_w) == pytest.approx(x1 + x2, abs=1e-9)
    assert p.d_w1 + p.d_w2 == pytest.approx(2 * p.a_w, abs=1e-9)


@given(z1=st.integers(12, 40), dz=st.integers(8, 60), x1=st.floats(-0.2, 0.6), x2=st.floats(-0.2, 1.5))
@settings(max_examples=80, deadline=None)
def test_internal_pair_is_backlash_free_and_inverse_consistent(z1, dz, x1, x2):
    m = 4.0
    try:
        p = GearPair(SpurGear(z1, m, x1), SpurGear(z1 + dz, m, x2, internal=True))
    except InputError:
        return
    # the pinion tooth fills the ring space on the operating circles: s_w1 + s_w2 = p_w
    assert p.gear1.s_at(p.d_w1) + p.gear2.s_at(p.d_w2) == pytest.approx(math.pi * p.d_w1 / z1, abs=1e-9)
    assert x_sum_for_centre_distance(z1, z1 + dz, m, p.a_w, internal=True) == pytest.approx(x2 - x1, abs=1e-9)
    assert p.d_w2 - p.d_w1 == pytest.approx(2 * p.a_w, abs=1e-9)


def test_contact_ratio_equals_path_of_contact_from_coordinates():
    """ε_α as the length of the line of action covered by both tooth regions, from coordinates:
    pinion centre O1 = (0, 0), pitch point C = (0, r_w1), wheel centre (0, ±a_w), line of action
    through C at α_w; each gear contributes the part inside its tip circle (ring: outside it) and on
    the involute side of its base-circle tangency point N."""
    for p in (SP, PR, PR188, GearPair(SpurGear(12, 3.0, 0.6), SpurGear(24, 3.0, 0.36)),
              GearPair(SpurGear(16, 3.0), SpurGear(24, 3.0, 0.5, internal=True))):
        al = p.alpha_w
        C = np.array([0.0, p.d_w1 / 2])
        u = np.array([math.cos(al), -math.sin(al)])
        o1 = np.zeros(2)
        o2 = np.array([0.0, -p.a_w]) if p.internal else np.array([0.0, p.a_w])

        def circle(o, r):  # t-interval of the line inside the circle
            tn = (o - C) @ u
            h = math.sqrt(r * r - ((C - o) @ (C - o) - tn * tn))
            return tn, tn - h, tn + h

        tn1, a1, b1 = circle(o1, p.d_a1 / 2)
        tn2, a2, b2 = circle(o2, p.d_a2 / 2)
        lo1, hi1 = (max(a1, tn1), b1) if tn1 < 0 else (a1, min(b1, tn1))
        if p.internal:  # ring: outside its tip circle, on C's side of N2
            lo2, hi2 = (b2, math.inf) if tn2 < 0 else (-math.inf, a2)
        else:
            lo2, hi2 = (max(a2, tn2), b2) if tn2 < 0 else (a2, min(b2, tn2))
        seg = min(hi1, hi2) - max(lo1, lo2)
        assert seg / p.gear1.p_b == pytest.approx(p.epsilon_alpha(), abs=1e-9)


def test_z_min_feasible_and_x_min():
    assert z_min_feasible() == 8
    x_min8 = BasicRack().h_l_star - 8 * math.sin(math.radians(20)) ** 2 / 2
    assert SpurGear(8, 1.0, x_min8).s_na > 0
    with pytest.raises(InputError):  # z = 7: even x = x_min gives a pointed tip
        SpurGear(7, 1.0, BasicRack().h_l_star - 7 * math.sin(math.radians(20)) ** 2 / 2)
    # 'z_min = 17' of the handbooks is 2 h_l*/sin²α = 17.097 rounded: strictly, z = 17 at x = 0 is
    # undercut by 0.0056 m and z = 18 is the first free one
    assert SUN.z_min == pytest.approx(17.097, abs=5e-4)
    assert SpurGear(18, 2.0).x_min <= 0.0 < SpurGear(17, 2.0).x_min < 0.006


def test_basic_rack_boundary_height():
    r = BasicRack()
    assert r.h_l_star == pytest.approx(1.25 - 0.38 * (1 - math.sin(math.radians(20))), abs=1e-15)
    assert r.h_l_star == pytest.approx(0.99997, abs=1e-5)
    assert r.rho_f_star_max == pytest.approx(0.4719, abs=1e-4)


# ----------------------------------------------------------------------------- interference
def _khk_trochoid_margin(p: GearPair) -> float:
    """KHK Technical Reference, internal gears: trochoid interference avoided when
    θ1 z1/z2 + inv α_w − inv α_a2 − θ2 ≥ 0, θ1 = acos((r_a2² − r_a1² − a²)/(2 a r_a1)) + inv α_a1 − inv α_w,
    θ2 = acos((a² + r_a2² − r_a1²)/(2 a r_a2))."""
    ra1, ra2, a = p.d_a1 / 2, p.d_a2 / 2, p.a_w
    aa1 = math.acos(p.gear1.d_b / p.d_a1)
    aa2 = math.acos(p.gear2.d_b / p.d_a2)
    th1 = math.acos((ra2 ** 2 - ra1 ** 2 - a ** 2) / (2 * a * ra1)) + inv(aa1) - inv(p.alpha_w)
    th2 = math.acos((a * a + ra2 ** 2 - ra1 ** 2) / (2 * a * ra2))
    return float(th1 * p.gear1.z / p.gear2.z + inv(p.alpha_w) - inv(aa2) - th2)


def test_tip_interference_sweep_agrees_with_khk_trochoid_formula():
    """Where the involute-interference condition holds, the kinematic sweep finds interference exactly
    when KHK's closed-form trochoid condition fails (an independent formula)."""
    seen = {True: 0, False: 0}
    for z1 in (12, 20, 30):
        for dz in (4, 5, 6, 7, 8, 10, 12, 16, 24):
            for x1, x2 in ((0.0, 0.0), (0.3, 0.3), (0.5, 1.0), (0.0, 0.5)):
                try:
                    p = GearPair(SpurGear(z1, 3.0, x1), SpurGear(z1 + dz, 3.0, x2, internal=True))
                except InputError:
                    continue
                if p.d_a2 < p.gear2.d_b or min(p.involute_interference_margins()) < 0:
                    continue
                ok_khk = _khk_trochoid_margin(p) >= 0
                ok_sweep = p.tip_interference_depth(samples=1501) <= 1e-6
                assert ok_khk == ok_sweep, (z1, z1 + dz, x1, x2)
                seen[ok_khk] += 1
    assert seen[True] >= 5 and seen[False] >= 5  # both outcomes exercised


def test_thesis_planet_ring_mesh_is_free_of_interference():
    assert PR.tip_interference_depth() <= 1e-9
    m1, m2 = PR.involute_interference_margins()
    assert m1 > 0 and m2 > 0
    assert RING.shaper_tip_cut_margin > 0
    # a ring only 6 teeth larger than the pinion does interfere
    bad = GearPair(SpurGear(20, 3.0), SpurGear(26, 3.0, internal=True))
    assert bad.tip_interference_depth() > 0.1


def test_involute_interference_equals_khk_condition():
    """KHK: involute interference avoided when z1/z2 ≥ 1 − tan α_a2 / tan α_w (pinion not undercut)."""
    for z1, z2, x2 in ((20, 56, 0.0), (20, 40, 0.0), (20, 30, 0.0), (16, 40, 0.5), (30, 60, 0.0)):
        p = GearPair(SpurGear(z1, 2.0, 0.0), SpurGear(z2, 2.0, x2, internal=True))
        if p.d_a2 < p.gear2.d_b:
            assert p.involute_interference_margins()[0] < 0
            continue
        aa2 = math.acos(p.gear2.d_b / p.d_a2)
        khk_ok = z1 / z2 >= 1 - math.tan(aa2) / math.tan(p.alpha_w)
        assert khk_ok == (p.rho_p1() >= 0)


# ----------------------------------------------------------------------------- errors
@pytest.mark.parametrize("kwargs, param", [
    (dict(z=7, m=1.0), "z"),
    (dict(z=16.5, m=1.0), "z"),
    (dict(z=float("nan"), m=1.0), "z"),
    (dict(z=20, m=0.0), "m"),
    (dict(z=20, m=float("nan")), "m"),
    (dict(z=20, m=1.0, x=float("nan")), "x"),
    (dict(z=10, m=1.0, x=1.2), "x"),  # pointed tip
    (dict(z=8, m=1.0, internal=True), "z"),
    (dict(z=20, m=1.0, z0=10), "z0"),  # shaper on an external gear
    (dict(z=56, m=1.0, internal=True, z0=60), "z0"),
    (dict(z=56, m=1.0, internal=True, z0=14.5), "z0"),
])
def test_invalid_gear_raises_input_error(kwargs, param):
    with pytest.raises(InputError) as e:
        SpurGear(**kwargs)
    assert e.value.parameter == param


def test_pointed_tip_message_names_the_limit():
    with pytest.raises(InputError, match="pointed"):
        SpurGear(10, 1.0, 1.2)


@pytest.mark.parametrize("kwargs, param", [
    (dict(alpha=math.radians(5)), "alpha"),
    (dict(h_a_star=0.0), "h_a_star"),
    (dict(c_star=-0.1), "c_star"),
    (dict(rho_f_star=0.6), "rho_f_star"),
    (dict(rho_f_star=float("nan")), "rho_f_star"),
])
def test_invalid_rack_raises(kwargs, param):
    with pytest.raises(InputError) as e:
        BasicRack(**kwargs)
    assert e.value.parameter == param


def test_invalid_pairs_and_arguments_raise():
    with pytest.raises(InputError):
        GearPair(SpurGear(20, 2.0), SpurGear(30, 2.5))
    with pytest.raises(InputError):
        GearPair(SpurGear(30, 2.0), SpurGear(20, 2.0, internal=True))
    with pytest.raises(InputError):
        GearPair(SpurGear(30, 2.0, internal=True), SpurGear(60, 2.0, internal=True))
    with pytest.raises(InputError):
        inv_inverse(-1e-3)
    with pytest.raises(InputError):
        inv_inverse(float("nan"))
    with pytest.raises(InputError):
        SUN.W(0)
    with pytest.raises(InputError):
        SUN.s_at(SUN.d_b * 0.9)
    with pytest.raises(InputError):
        SUN.M(-1.0)
    with pytest.raises(InputError):
        x_sum_for_centre_distance(16, 20, 10.0, 100.0)  # a_w below a·cos α
    with pytest.raises(InputError):
        SpurGear(56, 10.0, 1.417, internal=True).d_a0  # no shaper given


def test_pinion_tip_corner_entering_the_ring_is_found():
    """The pinion-tip-corner branch of the internal-mesh sweep: a 20-tooth pinion (m = 3) in a 60-tooth
    ring is conjugate at its own tip (depth 0); with its tip circle enlarged to 71 mm its tip corners
    dig into the ring's teeth (its tip then reaches a_w + r_a1 = 95.5 mm from the ring's axis, past
    the ring's root radius 93.75 mm: interference is certain).  Only the pinion's corners enter: the
    ring's corners alone find nothing, so this pins the pinion branch (it failed with that branch
    switched off)."""
    p = GearPair(SpurGear(20, 3.0), SpurGear(60, 3.0, internal=True))
    assert p.tip_interference_depth(samples=3001) <= 1e-9
    assert p.a_w + 71.0 / 2 > p.gear2.d_f / 2
    assert p.tip_interference_depth(d_a1=71.0, samples=3001) > 0.5


def test_pinion_tip_past_the_ring_root_is_measured_as_deep_as_it_goes():
    """A pinion tip that reaches past the ring's root circle strikes the rim (no tip clearance): the
    sweep measures it as the radial depth past that circle.  z = 20 / 60, m = 3: a_w = 60 mm, ring root
    radius 93.75 mm; with d_a1 = 69 mm the pinion tip reaches 94.5 mm, 0.75 mm into the rim (the tooth
    branch alone saw about 0 here: its corners pass the ring's tooth spaces)."""
    p = GearPair(SpurGear(20, 3.0), SpurGear(60, 3.0, internal=True))
    reach = p.a_w + 69.0 / 2 - p.gear2.d_f / 2
    assert reach == pytest.approx(0.75)
    assert p.tip_interference_depth(d_a1=69.0, samples=3001) == pytest.approx(reach, abs=1e-6)
    # with the standard tip (66 mm) the tip stays 0.75 mm inside the root circle: no interference
    assert p.tip_interference_depth(d_a1=66.0, samples=3001) <= 1e-9
