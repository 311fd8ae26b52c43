"""Exact numbers of the motion checks (checks/motion/) on small geometry made in each test (issue 36: mutation
tests of the as-built transmission, the contact events and the backlash search).  Each expected value is computed
here independently - by hand (the angle at which a turning straight edge meets a corner), by a brute-force search
(the first angle at which manifold3d's boolean finds common area) or from the involute's own geometry (the lines of
action, the base circles, epsilon_alpha) - never by the function under test."""

from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import pytest

from propulsor import policy
from propulsor.checks.motion import outline, transmission_sweep
from propulsor.checks.motion.transmission import TransmissionResult
from propulsor.errors import InputError
from propulsor.geometry.profile import Profile, circle_loop

from contact_reference import checked, contact, pruned_hit
from test_motion import ALPHA, epsilon_alpha, involute_gear

# ---------------------------------------------------------------------------------------------------------------
# the as-built transmission (transmission.py): a bar turning about its end between two blocks
# ---------------------------------------------------------------------------------------------------------------

BAR = np.array([[0.0, -0.5], [10.0, -0.5], [10.0, 0.5], [0.0, 0.5]])  # the driven body: turns about its end (0, 0)


def _square(cx, cy, h=1.0):
    return np.array([[cx - h, cy - h], [cx + h, cy - h], [cx + h, cy + h], [cx - h, cy + h]])


def _edge_meets_corner(q, half=0.5):
    """The turn (rad, CCW) at which the bar's upper edge y = +half first reaches the point q (relative to the axis,
    above the bar): the edge is the line at distance `half` from the axis."""
    return math.atan2(q[1], q[0]) - math.asin(half / math.hypot(*q))


# the driven axis off the origin; the driver's axis at the upper block's centre, the lower block 7 mm below it
C2 = np.array([5.0, -3.0])
C1 = C2 + (6.0, 3.0)
BLOCKS = [_square(0.0, 0.0), _square(0.0, -7.0)]  # the driver body, in its own frame (axis at its origin)
E_CCW = _edge_meets_corner((7.0, 2.0))            # the upper block's corner (7, 2) on the bar's upper edge: 0.2096
E_CW = _edge_meets_corner((7.0, 3.0))             # the lower block's corner (7, -3) on the bar's lower edge: 0.3392


def _tip_on_turned_edge(a, b, th, axis=(14.0, 0.0)):
    """Where the bar's tip circle (radius^2 = 10^2 + 0.5^2 = 100.25 about the driven axis) meets the edge a -> b of a
    block on the driver turned by th about `axis`: (R, the point P, the driven angle e that puts the tip there)."""
    R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    A, B = np.array(axis) + R @ a, np.array(axis) + R @ b
    d = B - A
    qa, qb, qc = d @ d, 2 * A @ d, A @ A - 100.25
    t = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
    P = A + t * d
    return R, P, math.atan2(P[1], P[0]) - math.atan2(0.5, 10.0)


def _sweep(phis, senses=(1, 1), law=lambda p: 0.0, **kw):
    kw.setdefault("max_angle", 0.5)
    return transmission_sweep(BLOCKS, C1, [BAR], C2, law, phis, senses=senses, **kw)


def test_free_rotations_both_ways_are_the_corners_met_by_the_bars_edges():
    res = _sweep([0.0, 0.05, -0.02], contact_tol=2e-3, name="bar")
    assert res.name == "bar" and res.contact_tol == 2e-3
    assert res.phi.tolist() == [0.0, 0.05, -0.02] and res.theta.tolist() == [0.0, 0.0, 0.0]
    assert res.overlap_area.tolist() == [0.0, 0.0, 0.0]
    # the driven turned on by phi (sense +1: CCW) has phi less to go forwards and phi more backwards
    assert res.free_fwd == pytest.approx([E_CCW, E_CCW - 0.05, E_CCW + 0.02], abs=1e-12)
    assert res.free_back == pytest.approx([E_CW, E_CW + 0.05, E_CW - 0.02], abs=1e-12)
    # one corner touches each way; the contact points are the blocks' corners, in the world frame
    assert res.pairs_coast.tolist() == [1, 1, 1] and res.pairs_drive.tolist() == [1, 1, 1]
    assert res.contact_point_coast == pytest.approx(np.tile(C2 + (7.0, 2.0), (3, 1)), abs=1e-9)
    assert res.contact_point_drive == pytest.approx(np.tile(C2 + (7.0, -3.0), (3, 1)), abs=1e-9)
    # r_ref by default: the mean distance of the contact points from the driven axis
    assert res.r_ref == pytest.approx(np.full(3, 0.5 * (math.sqrt(53.0) + math.sqrt(58.0))), abs=1e-9)


def test_the_driven_sense_swaps_the_flanks():
    res = _sweep([0.0, 0.05], senses=(1, -1))
    # sense -1: the driven turns CW as phi grows, its forward turn is CW
    assert res.free_fwd == pytest.approx([E_CW, E_CW - 0.05], abs=1e-12)
    assert res.free_back == pytest.approx([E_CCW, E_CCW + 0.05], abs=1e-12)
    assert res.contact_point_coast == pytest.approx(np.tile(C2 + (7.0, -3.0), (2, 1)), abs=1e-9)
    assert res.contact_point_drive == pytest.approx(np.tile(C2 + (7.0, 2.0), (2, 1)), abs=1e-9)


def _first_touch(fixed_loops, moving_loops, centre, sign, limit, step=2e-3):
    """The least turn in (0, limit] of the moving loops about centre (sign +1: CCW) at which they share area with the
    fixed ones (manifold3d's boolean), found on a grid of `step` then by bisection; inf when none."""
    A = m3d.CrossSection([np.ascontiguousarray(p) for p in fixed_loops], m3d.FillRule.EvenOdd)
    B = m3d.CrossSection([np.ascontiguousarray(p - centre) for p in moving_loops], m3d.FillRule.EvenOdd)

    def area(d):
        return (A ^ B.rotate(math.degrees(sign * d)).translate(tuple(centre))).area()

    prev = 0.0
    for d in np.arange(step, limit + step, step):
        d = min(d, limit)
        if area(d) > 0.0:
            lo, hi = prev, d
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if area(mid) > 0.0 else (mid, hi)
            return hi
        prev = d
    return math.inf


def _placed(loops, angle, centre):
    c, s = math.cos(angle), math.sin(angle)
    R = np.array([[c, -s], [s, c]])
    return [p @ R.T + centre for p in loops]


@pytest.mark.parametrize("s1, s2", [(1, 1), (-1, 1), (1, -1), (-1, -1)])
def test_driver_and_driven_are_placed_by_their_senses_about_their_own_axes(s1, s2):
    """The driver turned by s1 theta(phi) about its axis, the driven by s2 phi about its own: the free turns are those
    of the bodies placed so by hand, found by the boolean's first common area."""
    driver = [_square(1.5, 0.5, 0.8)]  # off the driver's axis: its turn moves it
    phis = [0.04, -0.03]
    law = lambda p: 0.25 + 2.0 * p  # noqa: E731
    res = _sweep(phis, senses=(s1, s2), law=law)
    assert res.theta == pytest.approx([0.33, 0.19], abs=1e-15)
    res = transmission_sweep(driver, C1, [BAR], C2, law, phis, senses=(s1, s2), max_angle=0.5)
    for k, phi in enumerate(phis):
        fixed = _placed(driver, s1 * law(phi), C1)
        moving = _placed([BAR], s2 * phi, C2)
        fwd = _first_touch(fixed, moving, C2, s2, 0.5)
        back = _first_touch(fixed, moving, C2, -s2, 0.5)
        assert math.isfinite(fwd) or math.isfinite(back)
        for got, want in ((res.free_fwd[k], fwd), (res.free_back[k], back)):
            if math.isinf(want):
                assert got == math.inf
            else:
                assert got == pytest.approx(want, abs=1e-7)  # the boolean works on a 1e-8 mm grid


def test_the_search_stops_at_max_angle_on_both_sides_of_it():
    assert _sweep([0.0], max_angle=E_CCW + 1e-6).free_fwd[0] == pytest.approx(E_CCW, abs=1e-12)
    short = _sweep([0.0], max_angle=E_CCW - 1e-6)
    assert short.free_fwd[0] == math.inf and short.pairs_coast[0] == 0
    assert np.isnan(short.contact_point_coast[0]).all()
    assert short.free_back[0] == math.inf  # E_CW is further still
    # the next step's search starts from this step's answer, never beyond max_angle: a step whose contact lies just
    # past max_angle after one well inside it finds none
    m = E_CCW - 0.02
    res = _sweep([0.03, 0.01], max_angle=m)
    assert res.free_fwd[0] == pytest.approx(E_CCW - 0.03, abs=1e-12) and res.free_fwd[1] == math.inf
    res = _sweep([0.01, 0.03], max_angle=m)
    assert res.free_fwd[0] == math.inf and res.free_fwd[1] == pytest.approx(E_CCW - 0.03, abs=1e-12)
    # a max_angle below the first window (1e-3 rad): a contact 7e-4 rad away is found within 9e-4, not within 5e-4
    near = [E_CCW - 7e-4]
    assert _sweep(near, max_angle=9e-4).free_fwd[0] == pytest.approx(7e-4, abs=1e-12)
    assert _sweep(near, max_angle=5e-4).free_fwd[0] == math.inf


def test_r_ref_as_a_number_an_array_a_callable_or_nan_without_contact():
    phis = [0.0, 0.05]
    assert _sweep(phis, r_ref=12.5).r_ref.tolist() == [12.5, 12.5]
    assert _sweep(phis, r_ref=[11.0, 13.0]).r_ref.tolist() == [11.0, 13.0]
    assert _sweep(phis, r_ref=lambda p: 10.0 + 2.0 * p).r_ref.tolist() == [10.0, 10.1]
    res = _sweep(phis, max_angle=0.1)  # no contact within 0.1 rad either way
    assert np.isnan(res.r_ref).all() and np.isnan(res.backlash_mm).all()
    # the contact points of one side only: their mean distance
    res = _sweep(phis, max_angle=0.3)
    assert np.isinf(res.free_back).all()
    assert res.r_ref == pytest.approx(np.full(2, math.sqrt(53.0)), abs=1e-9)


def test_overlapping_bodies_report_the_common_area_and_no_free_turn():
    # the upper block lowered into the bar: a 2 mm x 0.3 mm overlap at phi = 0; the bar turned 0.8 rad clears it
    # (the upper block spans y = 0.2 .. 2.2 from the driven axis, x = 5 .. 7; the bar turned 0.8 rad is above it)
    res = transmission_sweep(BLOCKS, C2 + (6.0, 1.2), [BAR], C2, lambda p: 0.0, [0.0, 0.8], senses=(1, 1),
                             max_angle=0.5)
    assert res.overlap_area[0] == pytest.approx(2.0 * 0.3, abs=1e-7)  # the boolean works on a 1e-8 mm grid
    assert np.isnan(res.free_fwd[0]) and np.isnan(res.free_back[0])
    assert np.isnan(res.contact_point_drive[0]).all() and np.isnan(res.contact_point_coast[0]).all()
    assert res.pairs_drive[0] == 0 and res.pairs_coast[0] == 0
    # the next step is measured: the bar's lower edge, turned back from 0.8 rad, meets the corner (5, 2.2)
    assert res.overlap_area[1] == 0.0 and res.free_fwd[1] == math.inf
    q = (5.0, 2.2)
    assert res.free_back[1] == pytest.approx(0.8 - math.atan2(q[1], q[0]) - math.asin(0.5 / math.hypot(*q)), abs=1e-12)
    assert res.pairs_drive.tolist() == [0, 1]
    chk = {c.name: c for c in res.checks()}
    assert not chk["mesh.overlap_area"].passed
    assert chk["mesh.overlap_area"].value == pytest.approx(0.6, abs=1e-7)
    assert chk["mesh.overlap_area"].message == "max overlap 0.6 mm^2 at phi = 0.000000 rad (step 0)"
    assert "1 steps interfere" in chk["mesh.backlash"].message


@pytest.mark.parametrize("depth, interferes", [(math.sqrt(2e-6), True), (math.sqrt(5e-7), False)])
def test_an_overlap_counts_from_overlap_area_tol(depth, interferes):
    """policy.OVERLAP_AREA_TOL_MM2 = 1e-6 mm^2: a diamond's corner pushed d into the bar's edge overlaps it by d^2:
    2e-6 mm^2 interferes (no free turn), 5e-7 mm^2 does not (its free turns are measured)."""
    assert policy.OVERLAP_AREA_TOL_MM2 == 1e-6
    diamond = [np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]])]
    centre = C2 + (6.0, 0.5 + 1.0 - depth)
    res = transmission_sweep(diamond, centre, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5)
    assert res.overlap_area[0] == pytest.approx(depth * depth, rel=1e-3)
    assert np.isnan(res.free_fwd[0]) == interferes
    assert {c.name: c for c in res.checks()}["mesh.overlap_area"].passed == (not interferes)


def test_bad_inputs_are_refused_with_their_messages():
    def refused(msg, **kw):
        args = dict(driver_profile=BLOCKS, driver_center=C1, driven_profile=[BAR], driven_center=C2,
                    law_theta_of_phi=lambda p: 0.0, phis=[0.0])
        args.update(kw)
        with pytest.raises(InputError) as e:
            transmission_sweep(**args)
        assert str(e.value) == msg

    refused("driven_center = (np.float64(11.0), np.float64(0.0)): must differ from driver_center", driven_center=C1)
    refused("phis = (0,): must be a 1-D array of finite angles", phis=[])
    refused("phis = (1, 2): must be a 1-D array of finite angles", phis=[[0.0, 0.1]])
    refused("phis = (2,): must be a 1-D array of finite angles", phis=[0.0, math.nan])
    refused("phis = (2,): must be a 1-D array of finite angles", phis=[math.inf, 0.0])
    refused("senses = (1, 2): each must be +1 or -1", senses=(1, 2))
    refused("senses = (2, 1): each must be +1 or -1", senses=(2, 1))
    refused("senses = (0, 1): each must be +1 or -1", senses=(0, 1))
    refused("contact_tol = 0.0: must be > 0 mm", contact_tol=0.0)
    refused("contact_merge = 0.0: must be > 0 mm", contact_merge=0.0)
    refused("max_angle = 0.0: must be > 0 rad", max_angle=0.0)
    refused("law_theta_of_phi = 'non-finite': must return finite angles", law_theta_of_phi=lambda p: math.nan)
    refused("law_theta_of_phi = 'non-finite': must return finite angles",
            law_theta_of_phi=lambda p: 0.0 if p < 0.05 else math.inf, phis=[0.0, 0.1])
    # accepted: a scalar phi, centres half a millimetre apart, both senses negative
    res = transmission_sweep(BLOCKS, C2 + (0.5, 0.0), [BAR], C2, lambda p: 0.0, 0.0)
    assert res.phi.tolist() == [0.0] and res.overlap_area[0] > 1.0
    res = _sweep([0.0], senses=(-1, -1))
    assert res.free_fwd[0] == pytest.approx(E_CW, abs=1e-12)


def test_chord_tol_and_max_segment_reach_the_outlines():
    """A disc (a Profile: sampled to chord_tol) met by the bar's upper edge: the edge first touches the inscribed
    polygon at the vertex it reaches first."""
    disc = Profile(circle_loop(1.0))
    q = np.array([6.0, 2.5])  # the disc's centre from the driven axis: the edge touches it mid-bar
    for tol in (0.05, 0.01):
        (poly,) = disc.polylines(tol)
        want = min(_edge_meets_corner(q + v) for v in poly)
        res = transmission_sweep(disc, C2 + q, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5,
                                 chord_tol=tol)
        assert res.free_fwd[0] == pytest.approx(want, abs=1e-12)
    # the bar's edges cut into 0.1 mm pieces by default and 1 mm ones when asked: the contact counts group the same
    res = transmission_sweep(BLOCKS, C1, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5,
                             max_segment=1.0)
    assert res.free_fwd[0] == pytest.approx(E_CCW, abs=1e-12) and res.pairs_coast[0] == 1


@pytest.mark.parametrize("gap, tol, merge, pairs", [(1.2e-3, 1e-3, 0.5, 1), (1.2e-3, 1.3e-3, 0.5, 2),
                                                    (0.7e-3, None, 0.5, 2), (1.2e-3, 1.3e-3, 3.0, 1)])
def test_a_second_corner_counts_as_a_pair_within_contact_tol_and_apart_by_contact_merge(gap, tol, merge, pairs):
    """A second, small block whose corner lies `gap` mm beyond the bar's upper edge at its first contact, 2.5 mm
    further along it: its remaining gap (the arc at its radius) is gap (s^2 + 1/4)^(1/2) / s, s its distance along the
    edge; it is a second pair when that is within contact_tol (default 1e-3 mm) and the two points are more than
    contact_merge apart along the bar."""
    e = E_CCW
    u, n = np.array([math.cos(e), math.sin(e)]), np.array([-math.sin(e), math.cos(e)])
    s1 = float(np.dot((7.0, 2.0), u))
    s2 = s1 + 2.5
    corner = s2 * u + (0.5 + gap) * n  # from the driven axis
    arc = gap * math.hypot(s2, 0.5) / s2
    assert (arc <= (tol or 1e-3)) == (pairs == 2 or merge == 3.0)
    small = _square(*(corner + (-0.3, 0.3)), h=0.3) - (C1 - C2)
    kw = dict(contact_merge=merge) if tol is None else dict(contact_tol=tol, contact_merge=merge)
    res = transmission_sweep(BLOCKS + [small], C1, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5, **kw)
    assert res.free_fwd[0] == pytest.approx(e, abs=1e-12)
    assert res.pairs_coast[0] == pairs and res.pairs_drive[0] == 1


# ---------------------------------------------------------------------------------------------------------------
# two identical involute spur gears: a constant ratio, no transmission error, the backlash of the thinning
# ---------------------------------------------------------------------------------------------------------------

Z, MOD, J_N = 16, 2.0, 0.1


def test_identical_involute_gears_run_at_a_constant_ratio_with_the_backlash_of_their_thinning():
    """Two z = 16, m = 2 gears, each tooth thinned by J_N / 2 along the normal, on the standard centre distance,
    driver at the world origin turning CCW (the driven CW): the free turn each way is (J_N / 2) / r_b of the driven
    at every step, the loaded flank's contact lies on the line of action x cos(alpha) - y sin(alpha) = r_b (the
    tangent through the pitch point of the driver's base circle on the side its rotation pushes), the other flank's
    on its mirror image, and one or two tooth pairs carry as epsilon_alpha says."""
    g, info = involute_gear(Z, MOD, J_N, n_flank=200)
    o = outline(g)
    a = MOD * Z
    r_b = info["r_b"]
    steps = 24
    phi0 = math.pi / Z  # a driven tooth space faces the driver's tooth 0
    phis = phi0 + np.arange(steps) * (2 * math.pi / Z) / steps
    # (contact_tol 3e-5 mm: the second pair's gap reads up to 1e-5 mm off on these polylines)
    res = transmission_sweep(o, (0.0, 0.0), o, (a, 0.0), lambda p: p - phi0, phis, r_ref=info["r"], contact_tol=3e-5)
    free = J_N / 2 / r_b
    # (the polylines inscribed in the convex flanks: up to 1e-6 rad more, 15 nm on r_b)
    assert res.free_fwd == pytest.approx(np.full(steps, free + 5e-7), abs=5e-7)
    assert res.free_back == pytest.approx(np.full(steps, free + 5e-7), abs=5e-7)
    assert np.abs(res.te_mid).max() < 3e-7 and res.te_drive_pp < 1e-6
    # the contact points: on the two lines of action, to half a flank edge (the first contact is a vertex of one
    # polyline on an edge of the other; along the flank is across the line)
    r = np.hypot(g[:, 0], g[:, 1])
    flank = (r[:-1] > r_b) & (r[1:] > r_b) & (r[:-1] < info["r_a"] - 1e-9) & (r[1:] < info["r_a"] - 1e-9)
    half_edge = 0.5 * np.linalg.norm(np.diff(g, axis=0), axis=1)[flank].max()  # 0.0066 mm
    ca, sa = math.cos(ALPHA), math.sin(ALPHA)
    drive, coast = res.contact_point_drive, res.contact_point_coast
    assert np.abs(drive[:, 0] * ca - drive[:, 1] * sa - r_b).max() < half_edge
    assert np.abs(coast[:, 0] * ca + coast[:, 1] * sa - r_b).max() < half_edge
    # within the path of contact: between the tangent points of the two base circles
    t_drive = drive[:, 0] * sa + drive[:, 1] * ca  # along the line, 0 at the driver's tangent point
    assert (t_drive > 0.0).all() and (t_drive < a * sa).all()
    eps = epsilon_alpha(Z, Z, MOD)  # 1.556
    for flank in ("drive", "coast"):
        assert res.fraction_pairs(2, flank) == pytest.approx(eps - 1, abs=1.5 / steps)
        assert res.fraction_pairs(1, flank) == pytest.approx(2 - eps, abs=1.5 / steps)
    assert res.contact_ratio_mean == pytest.approx(eps, abs=1.5 / steps)
    # r_ref by default: the contact points' mean distance from the driven axis
    auto = transmission_sweep(o, (0.0, 0.0), o, (a, 0.0), lambda p: p - phi0, phis[:4])
    pts = np.vstack([auto.contact_point_drive, auto.contact_point_coast])
    assert auto.r_ref == pytest.approx(np.full(4, np.mean(np.hypot(pts[:, 0] - a, pts[:, 1]))), abs=1e-12)


def test_a_driver_ahead_of_the_law_moves_the_centre_of_the_backlash():
    """The driver turned c ahead of the law (theta = phi + c, a 1:1 pair): the driven follows, te_mid = c; a centre
    distance larger by da opens the backlash by 2 da sin(alpha) along the normal."""
    g, info = involute_gear(Z, MOD, J_N, n_flank=200)
    o = outline(g)
    phi0 = math.pi / Z
    phis = phi0 + np.array([0.0, 0.07, 0.19])
    c = 2e-3
    res = transmission_sweep(o, (0.0, 0.0), o, (MOD * Z, 0.0), lambda p: p - phi0 + c, phis)
    assert res.te_mid == pytest.approx(np.full(3, c), abs=3e-7)
    assert res.free_fwd == pytest.approx(np.full(3, J_N / 2 / info["r_b"] + c + 5e-7), abs=5e-7)
    assert res.free_back == pytest.approx(np.full(3, J_N / 2 / info["r_b"] - c + 5e-7), abs=5e-7)
    # the centre distance opened by da: the working pressure angle alpha_w, the tooth thickness on the working pitch
    # circle s_w = d_w (s / d + inv alpha - inv alpha_w) (ISO 21771), the free turn (p_w - 2 s_w) / r_w
    da = 0.05
    a_w = MOD * Z + da
    alpha_w = math.acos(MOD * Z * math.cos(ALPHA) / a_w)
    inv = lambda x: math.tan(x) - x  # noqa: E731
    s = math.pi * MOD / 2 - J_N / (2 * math.cos(ALPHA))
    free_total = 2 * math.pi / Z - 4 * (s / (MOD * Z) + inv(ALPHA) - inv(alpha_w))
    res = transmission_sweep(o, (0.0, 0.0), o, (a_w, 0.0), lambda p: p - phi0, phis)
    assert (res.free_fwd + res.free_back) == pytest.approx(np.full(3, free_total + 1e-6), abs=1e-6)
    assert free_total > J_N / info["r_b"] + 2 * da * math.sin(ALPHA) / info["r_b"] * 0.9



# ---------------------------------------------------------------------------------------------------------------
# the checks of a transmission result (TransmissionResult.checks): values, limits on both sides, messages in full
# ---------------------------------------------------------------------------------------------------------------


def _result(free_fwd, free_back, r_ref, overlap=None, pairs_drive=None, pairs_coast=None, name="mesh"):
    n = len(free_fwd)
    z = np.zeros(n)
    return TransmissionResult(np.arange(n) * 0.1, 2.0 * np.arange(n) * 0.1, z if overlap is None else np.array(overlap),
                              np.array(free_fwd, float), np.array(free_back, float), np.array(r_ref, float),
                              np.array(pairs_drive if pairs_drive is not None else [1] * n),
                              np.array(pairs_coast if pairs_coast is not None else [1] * n),
                              np.zeros((n, 2)), np.zeros((n, 2)), 1e-3, name)


def test_checks_report_interference_contact_loss_and_the_least_pairs_in_full():
    # step 1 interferes (nan), step 3 finds no contact backwards within the search angle (inf)
    res = _result([0.010, math.nan, 0.012, 0.011], [0.008, math.nan, 0.002, math.inf], [10.0, 10.0, 5.0, 10.0],
                  overlap=[0.0, 2e-6, 0.0, 0.0], pairs_drive=[1, 0, 2, 0], pairs_coast=[2, 0, 1, 1], name="m")
    chk = res.checks(te_limit_rad=0.006, backlash_range_mm=(0.05, 0.2))
    assert [c.name for c in chk] == ["m.overlap_area", "m.backlash", "m.contact_continuity", "m.transmission_error"]
    ov, bl, cc, te = chk
    assert (ov.passed, ov.value, ov.limit, ov.unit) == (False, 2e-6, 1e-6, "mm^2")
    assert ov.message == "max overlap 2e-06 mm^2 at phi = 0.100000 rad (step 1)"
    # backlash 0.18 and 0.07 mm where finite: the least at step 2
    assert (bl.passed, bl.limit, bl.unit) == (False, 0.05, "mm") and bl.value == pytest.approx(0.07, abs=1e-15)
    assert bl.message == ("backlash 0.07000 .. 0.18000 mm (min at phi = 0.200000 rad); 1 steps interfere, "
                          "1 steps without contact within the search angle; allowed 0.05 .. 0.2 mm")
    assert (cc.passed, cc.value, cc.limit, cc.unit) == (False, 0.0, 1.0, "pairs")
    assert cc.message == "least tooth pairs in contact 0; mean on drive flank 0.7500"
    # drive-flank te = -free_back where finite: -0.008, -0.002: 0.006 peak to peak, at its limit
    assert (te.passed, te.limit, te.unit) == (True, 0.006, "rad") and te.value == pytest.approx(0.006, abs=1e-15)
    assert te.message == "drive-flank transmission error peak-to-peak 6.000e-03 rad"
    assert not res.checks(te_limit_rad=0.006 - 1e-12)[3].passed
    assert len(res.checks()) == 3
    # the coast flank's least counts too
    res2 = _result([0.01, 0.01], [0.01, 0.01], [10.0, 10.0], pairs_drive=[2, 1], pairs_coast=[1, 0])
    assert res2.checks()[2].value == 0 and not res2.checks()[2].passed
    res3 = _result([0.01, 0.01], [0.01, 0.01], [10.0, 10.0], pairs_drive=[0, 1], pairs_coast=[1, 2])
    assert res3.checks()[2].value == 0
    res4 = _result([0.01, 0.01], [0.01, 0.01], [10.0, 10.0], pairs_drive=[1, 2], pairs_coast=[2, 1])
    c = res4.checks()[2]
    assert c.passed and c.value == 1 and c.message == "least tooth pairs in contact 1; mean on drive flank 1.5000"


def test_backlash_limits_are_strict_below_and_inclusive_above():
    res = _result([0.010, 0.007, 0.012], [0.004, 0.004, 0.006], [10.0, 10.0, 10.0])  # 0.14, 0.11, 0.18 mm
    lo, hi = res.backlash_min_mm, res.backlash_max_mm
    assert lo == pytest.approx(0.11, abs=1e-15) and hi == pytest.approx(0.18, abs=1e-15)

    def ok(rng=None):
        return {c.name: c for c in res.checks(backlash_range_mm=rng)}["mesh.backlash"].passed

    assert ok() and ok((lo - 1e-12, hi)) and not ok((lo, hi)) and not ok((lo - 1e-12, hi - 1e-12))
    assert ok((lo - 1e-12, None))
    c = {c.name: c for c in res.checks()}["mesh.backlash"]
    assert c.limit == 0.0 and c.message == ("backlash 0.11000 .. 0.18000 mm (min at phi = 0.100000 rad); "
                                            "0 steps interfere, 0 steps without contact within the search angle")
    assert c.value == pytest.approx(0.11, abs=1e-15)
    # no backlash at all fails the default limit (> 0)
    assert not {c.name: c for c in _result([0.0], [0.0], [10.0]).checks()}["mesh.backlash"].passed
    # nothing finite: nan, the first step named
    c = _result([math.inf, math.inf], [math.inf, 0.01], [10.0, 10.0]).checks()[1]
    assert not c.passed and c.message.startswith("backlash nan .. nan mm (min at phi = 0.000000 rad); 0 steps interfere, "
                                                 "2 steps without contact")
    c = _result([math.inf, 0.01], [0.01, 0.01], [10.0, 10.0]).checks()[1]
    assert c.message.startswith("backlash 0.20000 .. 0.20000 mm (min at phi = 0.100000 rad); 0 steps interfere, 1 steps")
    # the overlap check passes at its tolerance, and names the step of the largest overlap
    r = _result([0.01] * 3, [0.01] * 3, [10.0] * 3, overlap=[0.0, 1e-6, 0.5e-6])
    assert r.checks()[0].passed and r.checks()[0].message == "max overlap 1e-06 mm^2 at phi = 0.100000 rad (step 1)"
    assert "; 0 steps interfere, 0 steps without" in r.checks()[1].message  # at the tolerance: not interfering


def test_fraction_pairs_of_either_flank():
    res = _result([0.01] * 4, [0.01] * 4, [10.0] * 4, pairs_drive=[1, 2, 2, 1], pairs_coast=[1, 1, 1, 2])
    assert res.fraction_pairs(2) == 0.5 and res.fraction_pairs(2, "drive") == 0.5
    assert res.fraction_pairs(2, "coast") == 0.25 and res.fraction_pairs(1, "coast") == 0.75
    assert res.fraction_pairs(3) == 0.0


# ---------------------------------------------------------------------------------------------------------------
# the contact law (contact_events.py): the resolved contact of two identical involute gears, then its pieces
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import Outline  # noqa: E402
from propulsor.checks.motion import contact_events as ce  # noqa: E402
from propulsor.checks.motion.contact_events import (DRIVE, KINDS, REVERSE, ContactLaw, PairOutlines,  # noqa: E402
                                                    Stretch, contact_law, resolve_contact, runs)


def _gear_pair(j_n=J_N):
    """Two identical z = 16 gears as PairOutlines: the driven's tooth 0 on +x facing the driver at (L, 0), the
    driver's teeth at pi + pi/Z + 2 pi k / Z (a space on its -x axis): meshed at phi = theta = 0."""
    g, info = involute_gear(Z, MOD, j_n, n_flank=200)
    c, s = math.cos(math.pi + math.pi / Z), math.sin(math.pi + math.pi / Z)
    driver = outline(g @ np.array([[c, -s], [s, c]]).T)
    teeth2 = 2 * math.pi * np.arange(Z) / Z
    return PairOutlines(driver, outline(g), MOD * Z, math.pi + math.pi / Z + teeth2, teeth2), info


def _one_to_one(phi):
    return np.asarray(phi, float)


def test_identical_gears_contact_law_is_the_law_less_half_the_backlash_on_the_pairs_that_mesh():
    """1:1 identical gears: the loaded (drive) contact lags the law by (J_N / 2) / r_b at the law's speed, the reverse
    leads it by as much; the driver turns CCW, so its tooth above the line of centres (15) pushes the driven's tooth 0
    down, then tooth 14 the driven's tooth 1 (drive), and in reverse the driver's tooth 0 pushes tooth 0 up, then
    15 pushes 1: every sample named so; flank contact all through; the samples uniform in driver angle (1 deg: 23
    steps over a pitch) and every change of pair bisected to between h_min and 2 h_min of driven angle."""
    po, info = _gear_pair()
    free = J_N / 2 / info["r_b"]
    span = 2 * math.pi / Z
    h = 1.2e-5  # the intervals halve from 0.0171: 3.33e-5 is above 2 h: halved once more, to 1.67e-5
    law = {}
    for d in (DRIVE, REVERSE):
        c = resolve_contact(po, _one_to_one, 0.0, span, d, step_driver_rad=math.radians(1.0), h_min=h)
        law[d] = c
        assert c.direction == d and c.name == ("drive" if d == DRIVE else "reverse")
        assert np.all(np.diff(c.phi) > 0) and c.phi[0] == 0.0 and c.phi[-1] == span
        assert c.theta == pytest.approx(c.phi, abs=1e-15)
        want = -d * (free + 5e-7)  # (the polylines inscribed: up to 1e-6 rad more)
        assert c.te == pytest.approx(np.full(len(c.te), want), abs=5e-7)
        assert (c.kind == 0).all() and c.evaluations == len(c.phi)
        pairs = set(zip(c.driver_tooth.tolist(), c.driven_tooth.tolist()))
        assert pairs == ({(15, 0), (14, 1)} if d == DRIVE else {(0, 0), (15, 1)})
        grid = np.linspace(0.0, span, 24)
        assert all(np.min(np.abs(c.phi - g)) < 1e-12 for g in grid)
        assert not all(np.min(np.abs(c.phi - g)) < 1e-9 for g in np.linspace(0.0, span, 25))
        st = np.stack([c.kind, c.driver_tooth, c.driven_tooth], axis=1)
        change = np.nonzero(np.any(st[1:] != st[:-1], axis=1))[0]
        assert len(change) >= 1
        gaps = c.phi[change + 1] - c.phi[change]
        assert (gaps > h).all() and (gaps <= 2 * h).all()
        assert c.step_max < 2e-3
    both = contact_law(po, _one_to_one, 0.0, span, step_driver_rad=math.radians(1.0), h_min=h)
    assert [x.direction for x in both] == [DRIVE, REVERSE]
    assert both[0].te.tolist() == law[DRIVE].te.tolist() and both[1].phi.tolist() == law[REVERSE].phi.tolist()


def test_a_law_ahead_and_behind_is_followed_sample_by_sample():
    """theta = phi + 0.002 sin(8 phi): the 1:1 driven follows the driver, te = theta - phi -+ (J_N / 2) / r_b; the
    samples are uniform in theta (the law inverted: _phi_of_theta) from phi0 to phi1."""
    po, info = _gear_pair()
    free = J_N / 2 / info["r_b"] + 5e-7

    def law(p):
        p = np.asarray(p, float)
        return p + 0.002 * np.sin(8.0 * p)

    phi0, phi1 = 0.1, 0.1 + 2 * math.pi / Z
    step = math.radians(2.0)
    for d in (DRIVE, REVERSE):
        c = resolve_contact(po, law, phi0, phi1, d, step_driver_rad=step, h_min=1e-3)
        assert c.te == pytest.approx(0.002 * np.sin(8.0 * c.phi) - d * free, abs=5e-7)
        assert c.theta == pytest.approx(law(c.phi), abs=1e-15)
        th = np.linspace(law(phi0), law(phi1), int(math.ceil((law(phi1) - law(phi0)) / step)) + 1)
        assert all(np.min(np.abs(c.theta - t)) < 1e-12 for t in th)
        assert c.phi[0] == phi0 and c.phi[-1] == phi1


def test_resolve_contact_stops_at_max_evals_and_reports_progress():
    po, _ = _gear_pair()
    span = 2 * math.pi / Z
    ticks = []
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0), max_evals=30,
                        tick=lambda done, total: ticks.append((done, total)))
    assert c.evaluations == 30 and len(c.phi) == 30  # 24 samples, 6 bisections
    assert ticks[-1] == (30, 30) and [t[0] for t in ticks[:24]] == list(range(1, 25))
    assert all(total >= done for done, total in ticks)
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0), max_evals=24)
    assert c.evaluations == 24
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0), max_evals=29)
    assert c.evaluations == 29  # a round of bisections cut short at the budget
    # h_min wider than half the sampling step: nothing to bisect
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0), h_min=0.01)
    assert c.evaluations == 24 and len(c.phi) == 24
    # two samples at the least
    c = resolve_contact(po, _one_to_one, 0.0, 1e-4, DRIVE, step_driver_rad=math.radians(1.0))
    assert c.phi.tolist() == [0.0, 1e-4]


def test_a_pair_apart_has_no_contact_and_a_contact_is_found_anew_after_one_without():
    """The compiled search (``contact_track.track``): nothing within the largest free rotation of a pair 5 mm apart;
    a position searched from a neighbour's contact, 1e-4 rad away, finds the contact of the full search from the
    law's position, also from a neighbour 1-5 mrad off on either side; the reference search at one position
    (``tests/contact_reference.py``) finds the same, and its contact point lies on the line of action."""
    from propulsor.checks.motion.contact_track import track

    def one(pair, phi, d, seed=math.nan, seed_phi=math.nan):
        te, kind, a, b = track(pair, [phi], [phi], d, [seed], [seed_phi], False)
        return float(te[0]), int(kind[0]), int(a[0]), int(b[0])

    po, info = _gear_pair()
    apart = PairOutlines(po.drv, po.dvn, MOD * Z + 5.0, po.driver_teeth, po.driven_teeth)
    r = one(apart, 0.0, DRIVE)
    assert math.isnan(r[0]) and r[1:4] == (-1, -1, -1)
    r = contact(apart, 0.0, 0.0, DRIVE)
    assert math.isnan(r[0]) and r[1:4] == (-1, -1, -1) and np.isnan(r[4]).all() and r[4].shape == (2,)
    # tracking from a neighbour's contact gives the contact of a full search
    te = one(po, 0.01, DRIVE)[0]
    tracked = one(po, 0.0101, DRIVE, te, 0.01)
    full = one(po, 0.0101, DRIVE)
    assert math.isfinite(full[0]) and full[1] >= 0
    assert tracked[0] == pytest.approx(full[0], abs=1e-15) and tracked[1:4] == full[1:4]
    # from a neighbour whose contact lay 5e-3 rad on the loaded side (the start inside the driver: the first hit
    # found within a fifth of the margin is searched again from the law's position), or on the free side: the same
    for d in (DRIVE, REVERSE):
        want = one(po, 0.0101, d)
        for off in (-5e-3, -1e-3, 1e-3, 5e-3):
            assert one(po, 0.0101, d, want[0] + off, 0.01)[0] == pytest.approx(want[0], abs=1e-15)
    full = contact(po, 0.0101, 0.0101, DRIVE)
    assert full[:4] == one(po, 0.0101, DRIVE)
    # the contact point, in the driven frame: on the driven outline, on the drive line of action when turned
    p = np.asarray(full[4])
    ang = -(0.0101 + full[0])
    world = np.array([math.cos(ang) * p[0] - math.sin(ang) * p[1], math.sin(ang) * p[0] + math.cos(ang) * p[1]])
    # driven at the origin, driver at (L, 0) turning CCW: the drive line x cos a + y sin a = L - r_b ... from the
    # driver's side, the tangent to its base circle on which its CCW turn pushes: (L - x) cos a + y sin a = r_b
    assert abs((MOD * Z - world[0]) * math.cos(ALPHA) + world[1] * math.sin(ALPHA) - info["r_b"]) < 1e-2  # half a flank edge
    assert abs(math.hypot(*p) - info["r"]) < 1.0


def test_contact_events_speeds_stretches_and_corner_runs_by_hand():
    """A contact law written by hand (phi in 1e-5 rad steps, step_window 2.5e-5): te rising 0.01 rad/rad over the
    first state (samples 0-3), falling 0.02 over the second (4-7, the driver's tooth 3 instead of 2), then a single
    sample on a driven tip corner (8) and two on the first state again (9, 10)."""
    phi = np.arange(11) * 1e-5
    te = np.array([0.0, 1e-7, 2e-7, 3e-7, 2.8e-7, 0.8e-7, -1.2e-7, -3.2e-7, -3.0e-7, -3.0e-7, -2.9e-7])
    kind = np.array([0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0])
    drv = np.array([2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3])
    dvn = np.array([5, 5, 5, 5, 5, 5, 5, 5, 5, 6, 6])
    theta = 2.0 * phi
    law = ContactLaw(DRIVE, phi, theta, te, kind, drv, dvn, 11, step_window=2.5e-5)
    # the change 3|4: before, samples 0..3 (the window reached: 3e-5 >= 2.5e-5); after, 4..7
    before = 1.0 + (te[3] - te[0]) / (phi[3] - phi[0])
    after = 1.0 + (te[7] - te[4]) / (phi[7] - phi[4])
    ev = law.events()
    # 7|8 and 8|9: sample 8 alone in its state has no speed on its side: no event there
    assert len(ev) == 1
    assert ev[0][0] == pytest.approx(3.5e-5, abs=1e-18)
    assert ev[0][1] == pytest.approx(before, abs=1e-12) and ev[0][2] == pytest.approx(after, abs=1e-12)
    assert (before, after) == (pytest.approx(1.01), pytest.approx(0.98))
    assert ev[0][3:] == ((0, 2, 5), (0, 3, 5)) and all(type(x) is int for x in ev[0][3] + ev[0][4])
    # sample 8 in the first state: the change 8|9 (driven tooth 6) has 4..8 before (window: 4..7, one more: 8) and
    # 9..10 after
    law = ContactLaw(DRIVE, phi, theta, te, np.zeros(11, int), drv, dvn, 11, step_window=2.5e-5)
    ev = law.events()
    assert len(ev) == 2 and ev[1][3:] == ((0, 3, 5), (0, 3, 6))
    assert ev[1][1] == pytest.approx(1.0 + (te[8] - te[5]) / 3e-5, abs=1e-12)
    assert ev[1][2] == pytest.approx(1.0 + (te[10] - te[9]) / 1e-5, abs=1e-12)
    assert law.events() == ev and law.events() is not law.events()  # a copy, computed once
    assert law.step_max == pytest.approx(max(abs(e[2] - e[1]) for e in ev), abs=1e-15)
    k = int(np.argmax([abs(e[2] - e[1]) for e in ev]))
    at = law.step_at()
    assert at[0] == ev[k][0] and at[1] == pytest.approx(2.0 * ev[k][0], abs=1e-18)


def test_side_speed_window_reaches_one_sample_past_it_within_the_state():
    phi = np.array([0.0, 1e-5, 2e-5, 3e-5, 4e-5, 5e-5, 6e-5])
    te = np.array([0.0, 0.0, 0.0, 0.0, 1e-7, 3e-7, 6e-7])
    kind = np.zeros(7, int)
    drv = np.array([1, 1, 1, 1, 2, 2, 2])
    dvn = np.zeros(7, int)
    law = ContactLaw(DRIVE, phi, 2 * phi, te, kind, drv, dvn, 7, step_window=1.5e-5)
    # after the change 3|4: from 4 on, 5 is 1e-5 < 1.5e-5 away, 6 is 2e-5: the chord 4..6
    (ev,) = law.events()
    assert ev[1] == pytest.approx(1.0, abs=1e-12)  # 1..3 flat: the chord 1..3 (window), not 0..3 ... all flat
    assert ev[2] == pytest.approx(1.0 + (6e-7 - 1e-7) / 2e-5, abs=1e-12)
    law = ContactLaw(DRIVE, phi, 2 * phi, te, kind, drv, dvn, 7, step_window=0.5e-5)
    (ev,) = law.events()  # the window shorter than a step: the next sample
    assert ev[2] == pytest.approx(1.0 + (3e-7 - 1e-7) / 1e-5, abs=1e-12)
    law = ContactLaw(DRIVE, phi, 2 * phi, te, kind, drv, dvn, 7)  # default 2e-5: 4..6 (2e-5 is not < 2e-5)
    assert law.step_window == policy.CONTACT_STEP_WINDOW_RAD == 2e-5
    (ev,) = law.events()
    assert ev[2] == pytest.approx(1.0 + (6e-7 - 1e-7) / 2e-5, abs=1e-12)
    # a sample without contact (nan) at the chord's end: no speed, no event
    te2 = te.copy()
    te2[6] = math.nan
    law = ContactLaw(DRIVE, phi, 2 * phi, te2, kind, drv, dvn, 7, step_window=1.5e-5)
    assert law.events() == [] and law.step_max == 0.0 and law.step_at() is None
    te3 = te.copy()
    te3[1] = math.nan  # before: from 3 back to 2 (1e-5 < 1.5e-5), one more: 1 (nan); sample 0 is not reached
    law = ContactLaw(DRIVE, phi, 2 * phi, te3, kind, drv, dvn, 7, step_window=1.5e-5)
    assert law.events() == []
    te3 = te.copy()
    te3[0] = math.nan
    law = ContactLaw(DRIVE, phi, 2 * phi, te3, kind, drv, dvn, 7, step_window=1.5e-5)
    assert len(law.events()) == 1


def test_stretches_and_the_longest_corner_run():
    phi = np.arange(8) * 0.01
    theta = np.radians(np.arange(8) * 0.5)  # 0.5 deg of driver a sample
    # speeds of the 7 intervals: 1, 1.005, 1.02, 1, 1, 0.97, 1
    slope = np.array([0.0, 0.005, 0.02, 0.0, 0.0, -0.03, 0.0])
    te = np.concatenate([[0.0], np.cumsum(slope * 0.01)])
    kind = np.array([0, 0, 0, 0, 1, 0, 0, 0])  # a driver tip corner at sample 4
    drv = np.array([1, 1, 1, 2, 2, 2, 2, 2])
    dvn = np.array([7, 7, 7, 8, 8, 8, 9, 9])
    law = ContactLaw(REVERSE, phi, theta, te, kind, drv, dvn, 8)
    (s,) = law.stretches()
    # bad intervals (speed off by more than 0.01, or a corner at either end): 2 (1.02); 3, 4 (sample 4's corner);
    # 5 (0.97): one stretch, samples 2..6
    assert s == Stretch(1.0, pytest.approx(3.0), 0.02, 0.06, ("driver tip corner", "flank"), (1, 2), (7, 8, 9),
                        pytest.approx(0.97), pytest.approx(1.02))
    assert type(s.speed_min) is float and type(s.driver_teeth[0]) is int
    # a looser tolerance keeps the corner's intervals and the 0.97 one, a looser still the corner's; a tighter adds 1.005
    assert [(x.phi_from_rad, x.phi_to_rad) for x in law.stretches(0.025)] == [(0.03, 0.06)]
    assert [(x.phi_from_rad, x.phi_to_rad) for x in law.stretches(0.035)] == [(0.03, 0.05)]
    assert [(x.phi_from_rad, x.phi_to_rad) for x in law.stretches(0.004)] == [(0.01, 0.06)]
    # without the corner: two stretches, each of one interval
    flat = ContactLaw(REVERSE, phi, theta, te, np.zeros(8, int), drv, dvn, 8)
    s1, s2 = flat.stretches()
    assert (s1.phi_from_rad, s1.phi_to_rad, s2.phi_from_rad, s2.phi_to_rad) == (0.02, 0.03, 0.05, 0.06)
    assert (s1.theta_from_deg, s1.theta_to_deg) == (pytest.approx(1.0), pytest.approx(1.5))
    assert (s2.speed_min, s2.speed_max) == (pytest.approx(0.97), pytest.approx(0.97))
    assert (s2.driver_teeth, s2.driven_teeth, s2.kinds) == ((2,), (8, 9), ("flank",))
    # an interval without contact at an end (nan speed) is not a stretch
    te_nan = te.copy()
    te_nan[3] = math.nan
    assert [(x.phi_from_rad, x.phi_to_rad) for x in ContactLaw(REVERSE, phi, theta, te_nan, np.zeros(8, int), drv, dvn,
                                                               8).stretches()] == [(0.05, 0.06)]
    # the corner run: sample 4 alone reaches half-way to 3 and 5: 0.5 deg, from 2 deg
    assert law.corner_run_max() == (pytest.approx(0.5), pytest.approx(2.0))
    # runs at both ends: half-way only inwards
    k2 = np.array([1, 1, 0, 0, 0, 3, 3, 3])
    law2 = ContactLaw(REVERSE, phi, theta, te, k2, drv, dvn, 8)
    assert law2.corner_run_max() == (pytest.approx(1.25), pytest.approx(2.5))
    k3 = np.array([1, 1, 1, 0, 0, 0, 3, 3])
    assert ContactLaw(REVERSE, phi, theta, te, k3, drv, dvn, 8).corner_run_max() == (pytest.approx(1.25),
                                                                                       pytest.approx(0.0))
    # a corner sample without contact does not count
    te4 = te.copy()
    te4[4] = math.nan
    best, at = ContactLaw(REVERSE, phi, theta, te4, kind, drv, dvn, 8).corner_run_max()
    assert best == 0.0 and math.isnan(at)
    # unnamed kinds (-1: no contact) are left out of a stretch's kinds
    k5 = np.array([0, 0, 0, 0, -1, 0, 0, 0])
    s5 = ContactLaw(REVERSE, phi, theta, te, k5, drv, dvn, 8).stretches()
    assert all(x.kinds == ("flank",) for x in s5)


def test_runs_of_true():
    assert runs([True, True, False, True, False, False, True]) == [(0, 1), (3, 3), (6, 6)]
    assert runs([False, False]) == [] and runs([]) == [] and runs([1]) == [(0, 0)]
    assert runs(np.array([0, 1, 1, 1])) == [(1, 3)]


# an L-shaped driver (a concave corner at (2, 2)) and a driven square with a straight-through vertex on its lower edge
L_SHAPE = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [2.0, 2.0], [2.0, 4.0], [0.0, 4.0]])
SQUARE_MID = np.array([[-1.0, -1.0], [0.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])


def _po(driver=L_SHAPE, driven=SQUARE_MID, L=20.0, **kw):
    return PairOutlines(Outline([driver], 100.0), Outline([driven], 100.0), L, [0.0, math.pi], [0.0], **kw)


def test_turning_angles_and_corners():
    po = _po()
    assert ce._turning(po.drv) == pytest.approx([math.pi / 2] * 3 + [-math.pi / 2] + [math.pi / 2] * 2, abs=1e-15)
    assert ce._turning(po.dvn) == pytest.approx([math.pi / 2, 0.0, math.pi / 2, math.pi / 2, math.pi / 2], abs=1e-15)
    assert po.corner_drv.tolist() == [True] * 6 and po.corner_dvn.tolist() == [True, False, True, True, True]
    # a CW loop (a hole) turns the other way
    hole = Outline([_square(0.0, 0.0), _square(0.0, 0.0, 0.5)], 100.0)
    assert ce._turning(hole)[4:] == pytest.approx([-math.pi / 2] * 4, abs=1e-15)
    # the corner limit: 20 deg by default, both sides of it; and as given
    bend = lambda deg: np.array([[0.0, 0.0], [5.0, 0.0], [5.0 + 5.0 * math.cos(math.radians(deg)),  # noqa: E731
                                                          5.0 * math.sin(math.radians(deg))], [0.0, 8.0]])
    assert _po(driven=bend(19.0)).corner_dvn[1] == False  # noqa: E712
    assert _po(driven=bend(21.0)).corner_dvn[1] == True  # noqa: E712
    assert _po(driven=bend(21.0), corner_deg=22.0).corner_dvn[1] == False  # noqa: E712
    assert _po(driver=bend(21.0), corner_deg=20.5).corner_drv[1] == True  # noqa: E712


def _kind(po, side, v, e, t):
    """The contact kind the compiled search gives (``contact_track._kind_nb``), checked equal to the reference's
    (``tests/contact_reference.py``)."""
    from propulsor.checks.motion.contact_track import _kind_nb

    from contact_reference import kind

    got = int(_kind_nb(side, v, e, t, policy.CONTACT_CORNER_NEAR_MM, po.corner_dvn, po.turn_dvn, po.corner_drv,
                       po.turn_drv, po.drv.seg_len, po.drv.nxt, po.dvn.seg_len, po.dvn.nxt))
    assert got == kind(po, side, v, e, t)
    return got


def test_contact_kind_of_a_vertex_on_an_edge():
    po = _po()
    near = policy.CONTACT_CORNER_NEAR_MM
    assert near == 2e-3
    # side 1: a driven vertex on a driver edge; the driven vertex's own corner first (convex: driven tip corner)
    assert KINDS[_kind(po, 1, 0, 1, 0.5)] == "driven tip corner"
    # a straight-through driven vertex: the driver's corners at the edge's ends within 2e-3 mm
    # (edge 1 runs (4, 0) -> (4, 2), 2 mm long: t = 9.9e-4 is 1.98e-3 mm from its start)
    assert _kind(po, 1, 1, 1, 0.5) == 0
    assert KINDS[_kind(po, 1, 1, 1, 0.99e-3)] == "driver tip corner"
    assert _kind(po, 1, 1, 1, 1.01e-3) == 0
    # edge 2 runs (4, 2) -> (2, 2): its end is the concave corner
    assert KINDS[_kind(po, 1, 1, 2, 1.0 - 0.99e-3)] == "driver root corner"
    assert _kind(po, 1, 1, 2, 1.0 - 1.01e-3) == 0
    # side 2: a driver vertex on a driven edge
    assert KINDS[_kind(po, 2, 0, 0, 0.5)] == "driver tip corner"
    assert KINDS[_kind(po, 2, 3, 0, 0.5)] == "driver root corner"
    # a driven square whose lower-left corner is concave: its own root corner
    notch = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [0.0, 2.0]])
    po2 = _po(driver=SQUARE_MID, driven=notch)
    assert KINDS[_kind(po2, 1, 2, 0, 0.5)] == "driven root corner"
    assert KINDS[_kind(po2, 1, 3, 0, 0.5)] == "driven tip corner"
    # side 2 with a straight-through driver vertex (1 of SQUARE_MID): the driven's corners at the edge's ends
    # (driven edge 1 runs (1, 0) -> (1, 1), 1 mm, from a convex corner to the concave one)
    assert _kind(po2, 2, 1, 1, 0.5) == 0
    assert KINDS[_kind(po2, 2, 1, 1, 1.98e-3)] == "driven tip corner"
    assert KINDS[_kind(po2, 2, 1, 1, 2e-3)] == "driven tip corner"  # 2e-3 x 1 mm: at the limit exactly, within it
    assert _kind(po2, 2, 1, 1, 2.02e-3) == 0
    assert KINDS[_kind(po2, 2, 1, 1, 1.0 - 1.98e-3)] == "driven root corner"
    assert _kind(po2, 2, 1, 1, 1.0 - 2.02e-3) == 0


def test_pair_outlines_keeps_the_vertices_within_reach_sorted_by_angle():
    # a driver of radius R1 = 5 at L = 12: driven vertices farther than L - R1 - 1 = 6 from the driven axis
    drv = np.array([[5.0, 0.0], [0.0, 5.0], [-5.0, 0.0], [0.0, -5.0]])
    dvn = np.array([[7.0, 0.0], [0.0, 6.5], [-5.0, 0.0], [0.0, -8.0], [4.0, -6.0]])  # radii 7, 6.5, 5, 8, 7.21
    po = PairOutlines(Outline([drv], 100.0), Outline([dvn], 100.0), 12.0, [0.0], [0.0])
    assert (po.R1, po.R2, po.L) == (5.0, 8.0, 12.0)
    assert po.o1.tolist() == [3, 4, 0, 1]  # by polar angle: -pi/2, -0.98, 0, pi/2; the radius-5 vertex left out
    assert po.a1 == pytest.approx([-math.pi / 2, math.atan2(-6.0, 4.0), 0.0, math.pi / 2], abs=1e-15)
    # driver vertices farther than L - R2 - 1 = 3: all four, from -pi/2 up (atan2 of (-5, 0) is pi)
    assert po.o2.tolist() == [3, 0, 1, 2]
    # the half widths: the largest angle from the line of centres of a point at a radius between the body's least
    # and greatest within R_mate + 1 of the mate's axis, + 0.02 (by brute force over radii and angles)
    def widest(r_lo, r_hi, r_mate):
        best = 0.0
        for r in np.linspace(r_lo, r_hi, 64):
            a = np.linspace(0.0, math.pi, 31417)  # 1e-4 rad apart
            ok = np.hypot(12.0 - r * np.cos(a), r * np.sin(a)) <= r_mate + 1.0
            if ok.any():
                best = max(best, a[ok].max())
        return best + 0.02
    assert po.hw_dvn == pytest.approx(widest(5.0, 8.0, 5.0), abs=1e-4)
    assert po.hw_drv == pytest.approx(widest(5.0, 5.0, 8.0), abs=1e-4)
    # the search's windows of polar angle: vertices within centre +- hw, wrapped
    order, angs = po.o1, po.a1
    assert sorted(ce._window_nb(order, angs, 0.0, 0.1).tolist()) == [0]
    assert sorted(ce._window_nb(order, angs, math.pi / 2 + 2 * math.pi, 0.1).tolist()) == [1]
    assert sorted(ce._window_nb(order, angs, math.pi, math.pi / 2 + 0.01).tolist()) == [1, 3]
    assert sorted(ce._window_nb(order, angs, math.pi, math.pi / 2 - 0.01).tolist()) == []
    assert ce._window_nb(order, angs, 1.0, math.pi).tolist() == order.tolist()
    assert sorted(ce._window_nb(order, angs, -1.2, 0.4).tolist()) == [3, 4]


def test_nearest_tooth_wraps_and_takes_the_first_on_a_tie():
    c = np.array([0.0, 2.0, 4.0])
    assert ce._nearest_tooth_nb(c, 0.9) == 0 and ce._nearest_tooth_nb(c, 1.1) == 1
    assert ce._nearest_tooth_nb(c, 1.0) == 0  # a tie: the first
    assert ce._nearest_tooth_nb(c, 2 * math.pi - 0.1) == 0 and ce._nearest_tooth_nb(c, -2.0) == 2
    assert ce._nearest_tooth_nb(c, 5.5) == 0  # 5.5 - 2 pi = -0.78: nearer 0 than 4 (1.5 away)


def test_chunks_are_the_bounding_circles_of_runs():
    pts = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [10.0, 10.0], [13.0, 14.0]])
    cc, cr = ce._chunks(pts, np.array([0, 1, 2, 3, 4]), 2)
    assert cc.tolist() == [[1.0, 0.0], [6.0, 6.0], [13.0, 14.0]]
    assert cr == pytest.approx([1.0 + 1e-9, math.hypot(4.0, 4.0) + 1e-9, 1e-9], abs=1e-15)
    cc, cr = ce._chunks(pts, np.array([4, 3, 2]), 3)
    assert cc.tolist() == [[7.5, 8.0]] and cr[0] == pytest.approx(math.hypot(5.5, 6.0) + 1e-9, abs=1e-15)
    cc, cr = ce._chunks(pts, np.array([], int), 4)
    assert cc.shape == (0, 2) and cr.shape == (0,)


def test_distance_field_bounds_the_distance_to_the_boundary_from_below():
    """The field's grid (two cells beyond the box each side, `cells` along the longer side) and its values: the
    distance between the centres of the nearest cell holding a vertex (brute force over the cells), less a cell's
    diagonal, half the longest edge and 1e-9, at least 0; every point of a cell at least that far from the outline."""
    sq = Outline([np.array([[0.0, 0.0], [8.0, 0.0], [8.0, 4.0], [0.0, 4.0]])], 1.0)  # edges of 1 mm
    x0, y0, h, nx, ny, vals = ce.distance_field(sq, 16)
    assert h == 0.5 and (x0, y0) == (-1.0, -1.0) and (nx, ny) == (20, 12)
    assert ce.distance_field(sq, 16) is ce.distance_field(sq, 3)  # cached on the outline
    cells = np.array([(i, j) for i in range(nx) for j in range(ny)])
    centres = np.column_stack([x0 + (cells[:, 0] + 0.5) * h, y0 + (cells[:, 1] + 0.5) * h])
    ix = np.clip(np.floor((sq.points[:, 0] - x0) / h).astype(int), 0, nx - 1)
    iy = np.clip(np.floor((sq.points[:, 1] - y0) / h).astype(int), 0, ny - 1)
    held = centres[ix * ny + iy]
    d = np.min(np.linalg.norm(centres[:, None, :] - held[None, :, :], axis=2), axis=1)
    want = np.maximum(d - h * math.sqrt(2.0) - 0.5 - 1e-9, 0.0)
    assert vals == pytest.approx(want, abs=1e-12)
    assert vals.max() > 0.0
    rng = np.random.default_rng(5)
    p = np.column_stack([rng.uniform(x0, x0 + nx * h, 4000), rng.uniform(y0, y0 + ny * h, 4000)])
    k = np.floor((p[:, 0] - x0) / h).astype(int) * ny + np.floor((p[:, 1] - y0) / h).astype(int)
    true = np.minimum.reduce([np.abs(p[:, 0]), np.abs(p[:, 0] - 8.0), np.abs(p[:, 1]), np.abs(p[:, 1] - 4.0)])
    inside = (p[:, 0] > 0) & (p[:, 0] < 8) & (p[:, 1] > 0) & (p[:, 1] < 4)
    outside_d = np.hypot(np.maximum(np.maximum(-p[:, 0], p[:, 0] - 8.0), 0.0),
                         np.maximum(np.maximum(-p[:, 1], p[:, 1] - 4.0), 0.0))
    dist = np.where(inside, true, outside_d)
    assert (vals[k] <= dist + 1e-12).all()
    # a box away from the origin: the grid starts two cells below and left of it
    off = Outline([np.array([[3.0, 1.0], [11.0, 1.0], [11.0, 5.0], [3.0, 5.0]])], 1.0)
    x0, y0, h, nx, ny, vals2 = ce.distance_field(off, 16)
    assert (x0, y0, h, nx, ny) == (2.0, 0.0, 0.5, 20, 12)
    assert vals2 == pytest.approx(want, abs=1e-12)  # the same shape: the same values cell by cell
    # a taller box: cells along the longer side (y)
    tall = Outline([np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 10.0], [0.0, 10.0]])], 1.0)
    x0, y0, h, nx, ny, vals = ce.distance_field(tall, 20)
    assert h == 0.5 and (x0, y0) == (-1.0, -1.0) and (nx, ny) == (8, 24)



def test_a_flat_contact_is_one_pair_where_the_vertices_lie_closer_than_contact_merge():
    """A block turned 0.15 rad about the driven axis, its lower edge on the line the bar's upper edge reaches at
    0.15 rad: the whole 2 mm edge touches at once.  Cut into 0.1 mm pieces (max_segment, the default) the touching
    vertices lie 0.1 mm apart: one pair; uncut, only the block's two corners touch, 2 mm apart: two pairs (one with a
    contact_merge of 3 mm)."""
    beta = 0.15
    c, s = math.cos(beta), math.sin(beta)
    R = np.array([[c, -s], [s, c]])
    centre = C2 + R @ (6.0, 1.5)
    block = [_square(0.0, 0.0) @ R.T]  # in the driver's frame: turned with it
    def sweep(**kw):
        return transmission_sweep(block, centre, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5, **kw)
    res = sweep()
    assert res.free_fwd[0] == pytest.approx(beta, abs=1e-12) and res.pairs_coast[0] == 1
    assert sweep(max_segment=10.0).pairs_coast[0] == 2
    assert sweep(max_segment=10.0, contact_merge=3.0).pairs_coast[0] == 1


def test_a_contact_at_the_driven_outlines_first_vertex():
    """The bar's tip corner (10, 0.5), its outline's first vertex, meets a block's lower edge y = 3 (a driven vertex on
    a driver edge)."""
    bar = np.roll(BAR, -2, axis=0)
    assert bar[0].tolist() == [10.0, 0.5]
    res = transmission_sweep([_square(0.0, 0.0)], C2 + (10.0, 4.0), [bar], C2, lambda p: 0.0, [0.0], senses=(1, 1),
                             max_angle=0.5)
    assert res.free_fwd[0] == pytest.approx(math.atan2(3, math.sqrt(100.25 - 9)) - math.atan2(0.5, 10), abs=1e-12)
    assert res.contact_point_coast[0] == pytest.approx(C2 + (math.sqrt(100.25 - 9), 3.0), abs=1e-9)
    assert res.pairs_coast[0] == 1  # the driven vertex's own contact counts


def test_inputs_of_other_types_and_shapes_give_float_results():
    import warnings

    # centres as (1, 2) arrays, integer phis and r_ref: the same free turns, float arrays; pairs counted in integers
    res = transmission_sweep(BLOCKS, np.array([[11, 0]]), [BAR], np.array([[5, -3]]), lambda p: 0.0, [0, 1],
                             senses=(1, 1), max_angle=0.5, r_ref=12)
    assert res.free_fwd[0] == pytest.approx(E_CCW, abs=1e-12)
    assert res.phi.dtype == np.float64 and res.r_ref.dtype == np.float64 and res.r_ref.tolist() == [12.0, 12.0]
    assert res.pairs_drive.dtype.kind == "i" and res.pairs_coast.dtype.kind == "i"
    with pytest.raises(InputError) as e:
        transmission_sweep(BLOCKS, (11, 0), [BAR], (11, 0), lambda p: 0.0, [0.0])
    assert str(e.value) == "driven_center = (np.float64(11.0), np.float64(0.0)): must differ from driver_center"
    # no contact anywhere: r_ref nan, silently (no mean of an empty set)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = _sweep([0.0], max_angle=0.1)
    assert math.isnan(res.r_ref[0])


def test_a_contact_in_the_middle_of_a_long_edge_is_found():
    """Bug found by the mutation runs: the annulus bounding an outline's boundary (Outline.r_min .. radius) was taken
    from its vertices alone, but an edge comes nearer its centre between its ends; the free-rotation search used it
    as a lower bound of a point's distance from the boundary and left out the points it put out of reach.  A bar cut
    into 10 mm edges (max_segment = 10): its centre (5, 0) is 5.02 mm from every vertex, 0.5 mm from its long edges;
    a block's corner 1 mm above the middle of its upper edge was never met (free turn inf instead of 0.1955 rad)."""
    o = Outline([BAR], 10.0)
    assert len(o) == 4 and o.center.tolist() == [5.0, 0.0]
    assert o.r_min == pytest.approx(0.5, abs=1e-15) and o.radius == pytest.approx(math.hypot(5.0, 0.5), abs=1e-15)
    rng = np.random.default_rng(2)
    p = np.column_stack([rng.uniform(-2, 12, 2000), rng.uniform(-3, 3, 2000)])
    d_edges = np.minimum.reduce([np.hypot(np.clip(p[:, 0], 0, 10) - p[:, 0], y - p[:, 1]) for y in (-0.5, 0.5)]
                                + [np.hypot(x - p[:, 0], np.clip(p[:, 1], -0.5, 0.5) - p[:, 1]) for x in (0.0, 10.0)])
    assert (o.boundary_lower_bound(p) <= d_edges + 1e-12).all()
    q = np.array([5.0, 1.5])  # the block's lower-right corner from the driven axis
    for ms in (0.1, 10.0):
        block = _square(q[0] - 0.3, q[1] + 0.3, 0.3) - (C1 - C2)  # in the driver's frame
        res = transmission_sweep([block], C1, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5,
                                 max_segment=ms)
        assert res.free_fwd[0] == pytest.approx(_edge_meets_corner(q), abs=1e-12)


def test_every_hit_of_a_window_puts_a_vertex_on_an_edge():
    """PairOutlines._all_hits (the per-tooth load's search): each finite hit, the driven wheel turned from its actual
    angle phi_a back (sign +1) or on (-1) by the hit's delta, puts the vertex on the other outline's edge at the
    hit's parameter (world frame: driven at the origin turned by -phi_a + sign delta, driver at (L, 0) turned by
    theta); the least of them is the first hit of the pruned search."""
    po, _ = _gear_pair()
    L = MOD * Z

    def rot(a):
        return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])

    for sign in (1.0, -1.0):
        phi_a, theta, w = 0.01, 0.01, 0.01
        (i1, d1, e1, t1), (i2, d2, e2, t2) = po._all_hits(phi_a, theta, sign, w)
        assert np.isfinite(d1).any() and np.isfinite(d2).any()
        assert (d1[np.isfinite(d1)] <= w).all() and (d1[np.isfinite(d1)] >= 0).all()
        Rt = rot(theta)
        for k in np.nonzero(np.isfinite(d1))[0]:
            v = rot(-phi_a + sign * d1[k]) @ po.dvn.points[i1[k]]
            a, b = po.drv.seg_a[e1[k]], po.drv.seg_b[e1[k]]
            assert np.linalg.norm(v - ((L, 0.0) + Rt @ (a + t1[k] * (b - a)))) < 1e-9
        for k in np.nonzero(np.isfinite(d2))[0]:
            v = (L, 0.0) + Rt @ po.drv.points[i2[k]]
            a, b = po.dvn.seg_a[e2[k]], po.dvn.seg_b[e2[k]]
            assert np.linalg.norm(v - rot(-phi_a + sign * d2[k]) @ (a + t2[k] * (b - a))) < 1e-9
        first = pruned_hit(po, phi_a, theta, sign, w)
        assert first[0] == min(d1.min(), d2.min())
        side = 1 if d1.min() <= d2.min() else 2
        assert first[1] == side
        if side == 1:
            k = int(np.argmin(d1))
            assert first[2:] == (i1[k], e1[k], t1[k])
        else:
            k = int(np.argmin(d2))
            assert first[2:] == (i2[k], e2[k], t2[k])


def test_the_pruned_hits_of_a_window_are_every_finite_hit_in_order():
    """PairOutlines.hits (the per-tooth load's search) leaves out the window's vertices that cannot reach the mate:
    its finite hits are those of PairOutlines._all_hits (no vertex left out), bit for bit and in the same order, at
    poses near contact, apart and in a wide window, both ways; and it does leave vertices out."""
    po, _ = _gear_pair()
    left_out = 0
    for sign in (1.0, -1.0):
        for phi_a, theta, w in ((0.01, 0.01, 0.01), (0.0, 0.0, 0.002), (0.013, 0.0, 0.05), (0.2, 0.21, 0.3),
                                (0.05, 0.04, 1e-4), (1.0, 1.0, 0.02)):
            whole, pruned = po._all_hits(phi_a, theta, sign, w), po.hits(phi_a, theta, sign, w)
            for (iw, dw, ew, tw), (ip, dp, ep, tp) in zip(whole, pruned):
                fw, fp = np.isfinite(dw), np.isfinite(dp)
                assert fw.sum() == fp.sum()
                for a, b in ((iw, ip), (dw, dp), (ew, ep), (tw, tp)):
                    assert np.array_equal(a[fw], b[fp])
                left_out += len(dw) - len(dp)
    assert left_out > 0


def test_nearest_teeth_compiled_as_numpy_gives_them():
    """mesh_load._nearest (compiled) against numpy's argmin over |(angle - centre + pi) mod 2 pi - pi|: the same
    index for every angle, ties (an angle halfway between two centres) to the first, angles beyond +-pi wrapped."""
    from propulsor.checks.motion.mesh_load import _nearest

    centres = 2 * math.pi * np.arange(17) / 17 - 0.3
    ang = np.concatenate([np.linspace(-9.0, 9.0, 4001), 0.5 * (centres[:-1] + centres[1:]), centres])
    d = np.abs((ang[:, None] - centres[None, :] + math.pi) % (2 * math.pi) - math.pi)
    assert np.array_equal(_nearest(centres, ang), np.argmin(d, axis=1))


def test_side_speed_at_the_window_exactly_and_at_the_first_sample():
    """phi in quarter radians (exact in binary), step_window 0.5: a sample exactly step_window away ends the walk
    (< step_window), the next one in the state is taken once more; walking back to the first sample takes it."""
    phi = np.arange(9) * 0.25
    te = np.array([0.0, 0.01, 0.03, 0.03, 0.0, 0.02, 0.05, 0.09, 0.14])
    drv = np.array([1, 1, 1, 2, 2, 2, 2, 2, 2])
    z = np.zeros(9, int)
    (ev,) = ContactLaw(DRIVE, phi, phi, te, z, drv, z, 9, step_window=0.5).events()
    # before 2|3: from 2 back to 1 (0.25 < 0.5), 0 is 0.5 away: ends the walk, taken once more: the chord 0..2
    assert ev[1] == pytest.approx(1.0 + (te[2] - te[0]) / 0.5, abs=1e-15)
    # after: from 3 on to 4 (0.25), 5 is 0.5 away: ends the walk, taken once more: the chord 3..5
    assert ev[2] == pytest.approx(1.0 + (te[5] - te[3]) / 0.5, abs=1e-15)
    assert ev[0] == 0.625 and ev[3:] == ((0, 1, 0), (0, 2, 0))


def test_resolve_contact_by_default_samples_every_0_05_deg_of_driver():
    po, _ = _gear_pair()
    assert policy.CONTACT_STEP_DRIVER_DEG == 0.05
    c = resolve_contact(po, _one_to_one, 0.0, 0.01, REVERSE)
    n = int(math.ceil(math.degrees(0.01) / 0.05)) + 1  # 13
    assert all(np.min(np.abs(c.phi - g)) < 1e-12 for g in np.linspace(0.0, 0.01, n))
    assert not all(np.min(np.abs(c.phi - g)) < 1e-9 for g in np.linspace(0.0, 0.01, n + 1))


def test_a_pair_with_a_contact_ratio_below_one_hands_over_on_a_tip_corner():
    """The identical gears 1.5 mm apart: epsilon_alpha = 0.85 (ISO 21771 at the working pressure angle), so for
    about 15 % of each pitch the leaving pair's driver tip corner pushes the driven flank (drive) before the next pair
    meets; the contact kind changes are bisected like the tooth changes, and the driven runs off the law's speed
    only there (a stretch on each corner run, none on the flanks)."""
    po0, info = _gear_pair()
    a_w = MOD * Z + 1.5
    po = PairOutlines(po0.drv, po0.dvn, a_w, po0.driver_teeth, po0.driven_teeth)
    alpha_w = math.acos(2 * info["r_b"] / a_w)
    g = 2 * math.sqrt(info["r_a"] ** 2 - info["r_b"] ** 2) - a_w * math.sin(alpha_w)
    eps = g / (math.pi * MOD * math.cos(ALPHA))
    assert 0.8 < eps < 0.9
    span = 2 * 2 * math.pi / Z
    h = 1e-5
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(0.5), h_min=h)
    assert np.isfinite(c.te).all()
    kinds = set(c.kind.tolist())
    assert 0 in kinds and kinds - {0} and kinds <= {0, 1, 2}
    st = np.stack([c.kind, c.driver_tooth, c.driven_tooth], axis=1)
    change = np.nonzero(np.any(st[1:] != st[:-1], axis=1))[0]
    kind_change = change[c.kind[change] != c.kind[change + 1]]
    assert len(kind_change) >= 3
    gaps = c.phi[change + 1] - c.phi[change]
    assert (gaps > h).all() and (gaps <= 2 * h).all()
    # the share of the driven's turning on a corner: 1 - epsilon_alpha
    on_corner = np.diff(c.phi)[(c.kind[:-1] != 0) & (c.kind[1:] != 0)].sum() / span
    assert on_corner == pytest.approx(1 - eps, abs=0.03)
    s = c.stretches()
    assert s and all(set(x.kinds) - {"flank"} for x in s)
    assert c.step_max > 0.01
    run, at = c.corner_run_max()
    assert run == pytest.approx(math.degrees((1 - eps) * 2 * math.pi / Z), abs=1.0)


def test_resolve_contact_progress_totals():
    """tick(done, total): while sampling, the samples plus the changes of state seen so far projected over the rest
    (each bisected ceil(log2(spacing / 2 h_min)) times); then the samples plus those of the changes found, or one more
    than done; at the end done = total = the measurements."""
    po, _ = _gear_pair()
    span = 2 * math.pi / Z
    ticks = []
    step, h = math.radians(1.0), 1e-5
    c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=step, h_min=h,
                        tick=lambda done, total: ticks.append((done, total)))
    n = int(math.ceil(span / step)) + 1
    rounds = math.ceil(math.log2((span / (n - 1)) / (2 * h)))
    assert n == 24 and rounds == 10
    grid = np.linspace(0.0, span, n)
    idx = [int(np.argmin(np.abs(c.phi - g))) for g in grid]
    states = [(c.kind[i], c.driver_tooth[i], c.driven_tooth[i]) for i in idx]
    want, changes = [], 0
    for k in range(1, n + 1):
        if k > 1 and states[k - 1] != states[k - 2]:
            changes += 1
        want.append((k, n + round(changes * (n - 1) / max(k - 1, 1) * rounds)))
    assert ticks[:n] == want
    est = n + changes * rounds
    assert ticks[n:-1] == [(e, max(est, e + 1)) for e in range(n + 1, c.evaluations + 1)]
    assert ticks[-1] == (c.evaluations, c.evaluations)


def test_window_wraps_across_plus_and_minus_pi():
    order, angs = np.arange(5), np.array([-3.12, -1.0, 0.0, 1.0, 3.1])
    assert sorted(ce._window_nb(order, angs, 3.1, 0.1).tolist()) == [0, 4]     # -3.12 is 3.163 - 2 pi
    assert sorted(ce._window_nb(order, angs, -3.1, 0.1).tolist()) == [0, 4]    # 3.1 is -3.183 + 2 pi
    assert sorted(ce._window_nb(order, angs, 3.1 + 2 * math.pi, 0.1).tolist()) == [0, 4]
    assert sorted(ce._window_nb(order, angs, 0.5, 0.6).tolist()) == [2, 3]


def test_runs_take_any_true_value_and_events_skip_a_change_without_a_speed():
    assert runs(np.array([0, 2, 3, 0, -1])) == [(1, 2), (4, 4)]
    # a change whose one side is a single sample is skipped, and the next change is still found
    phi = np.arange(9) * 1e-5
    te = np.array([0.0, 0.0, 1e-7, 2e-7, 3e-7, 3e-7, 3e-7, 3e-7, 3e-7])
    drv = np.array([9, 1, 1, 1, 1, 2, 2, 2, 2])
    z = np.zeros(9, int)
    (ev,) = ContactLaw(DRIVE, phi, phi, te, z, drv, z, 9, step_window=2.5e-5).events()
    assert ev[3:] == ((0, 1, 0), (0, 2, 0)) and ev[0] == pytest.approx(4.5e-5, abs=1e-18)


def test_step_at_is_the_largest_change_of_speed_and_corner_runs_at_the_ends():
    # two changes: speeds 1.0 -> 1.05 (a step of 0.05, sum 2.05) then 1.05 -> 0.95 (0.1)
    phi = np.arange(9) * 0.25
    slope = np.array([0.0, 0.0, 0.0, 0.05, 0.05, 0.05, -0.05, -0.05])
    te = np.concatenate([[0.0], np.cumsum(slope * 0.25)])
    drv = np.array([1, 1, 1, 2, 2, 2, 3, 3, 3])
    z = np.zeros(9, int)
    law = ContactLaw(DRIVE, phi, 2 * phi, te, z, drv, z, 9, step_window=0.4)
    ev = law.events()
    assert [(round(a, 12), round(b, 12)) for _, a, b, _, _ in ev] == [(1.0, 1.05), (1.05, 0.95)]
    assert law.step_at() == (pytest.approx(1.375), pytest.approx(2.75)) and law.step_max == pytest.approx(0.1)
    # corner runs starting at sample 1 and ending at the last but one: both reach half-way to their neighbours;
    # of two equal runs, the first
    k = np.array([0, 1, 1, 0, 0, 0, 0, 2, 0])
    theta = np.radians(np.arange(9) * 1.0)
    law = ContactLaw(DRIVE, phi, theta, te, k, drv, z, 9)
    assert law.corner_run_max() == (pytest.approx(2.0), pytest.approx(1.0))
    k = np.array([0, 0, 0, 0, 0, 0, 0, 1, 1])
    assert ContactLaw(DRIVE, phi, theta, te, k, drv, z, 9).corner_run_max() == (pytest.approx(1.5), pytest.approx(7.0))
    k = np.array([0, 0, 0, 0, 0, 0, 0, 1, 0])  # ending at the last but one: half-way to the last
    assert ContactLaw(DRIVE, phi, theta, te, k, drv, z, 9).corner_run_max() == (pytest.approx(1.0), pytest.approx(7.0))
    k = np.array([0, 1, 0, 0, 0, 0, 2, 0, 0])  # driver angles in quarter radians: the two runs are equal exactly
    best, at = ContactLaw(DRIVE, phi, phi, te, k, drv, z, 9).corner_run_max()
    assert (best, at) == (math.degrees(0.25), math.degrees(0.25))


def test_stretch_speed_limit_is_strict_and_each_stretch_reads_its_own_samples():
    phi = np.arange(6) * 0.25
    te = np.array([0.0, 0.0, 0.0625, 0.0625, 0.0625, 0.0625])  # speeds 1, 1.25, 1, 1, 1
    z = np.zeros(6, int)
    law = ContactLaw(DRIVE, phi, phi, te, z, np.array([1, 1, 2, 3, 4, 5]), np.array([7, 7, 8, 9, 9, 9]), 6)
    assert law.stretches(0.25) == []
    (s,) = law.stretches(0.2)
    assert (s.phi_from_rad, s.phi_to_rad, s.driver_teeth, s.driven_teeth) == (0.25, 0.5, (1, 2), (7, 8))
    assert (s.speed_min, s.speed_max) == (1.25, 1.25)


def test_a_contact_is_tracked_from_its_neighbour_in_one_small_window():
    """The module's promise (one measurement under a millisecond): from a neighbouring sample's contact the driven
    wheel is placed a margin m = 3e-4 + |dphi| / 4 rad (at most 1e-3) on the free side of it and turned through 2 m:
    one search; a contact found within m / 5 of that start, or none, is searched again from the law's position with
    windows growing x4 from 3e-3 rad.  The hits searched are recorded around the real search, in the reference
    search at one position (``tests/contact_reference.py``), which the compiled search matches at each of these
    positions to the last bit (``checked``)."""
    po, _ = _gear_pair()
    calls = []

    def recorded(pair, phi_a, theta, sign, w):
        calls.append((phi_a, sign, w))
        return pruned_hit(pair, phi_a, theta, sign, w)

    assert (policy.CONTACT_TRACK_MARGIN_RAD, policy.CONTACT_TRACK_MARGIN_MAX_RAD, policy.CONTACT_SEARCH_START_RAD) == (
        3e-4, 1e-3, 3e-3)
    for d in (DRIVE, REVERSE):
        sign = 1.0 if d == DRIVE else -1.0
        calls.clear()
        te0 = checked(po, 0.01, 0.01, d, hit=recorded)[0]
        # the full search: nothing within 3e-3 rad (te 3.3e-3 rad), found within 1.2e-2
        assert calls == [(0.01, sign, 3e-3), (0.01, sign, pytest.approx(1.2e-2))]
        for dphi, m in ((1e-4, 3e-4 + 0.25e-4), (-2e-3, 3e-4 + 5e-4), (1e-2, 1e-3)):
            calls.clear()
            te = checked(po, 0.01 + dphi, 0.01 + dphi, d, te0, 0.01, hit=recorded)[0]
            assert calls == [(pytest.approx(0.01 + dphi + te0 + sign * m, abs=1e-15), sign, pytest.approx(2 * m))]
            assert te == pytest.approx(te0, abs=1e-6)
        # the neighbour's contact 0.9 m on the loaded side: found 0.1 m from the start, searched again
        m = 3e-4
        calls.clear()
        te = checked(po, 0.01, 0.01, d, te0 - sign * 0.9 * m, 0.01, hit=recorded)[0]
        assert len(calls) == 3 and calls[1] == (0.01, sign, 3e-3) and te == te0
        # dphi not given: 0, the least margin
        calls.clear()
        checked(po, 0.01, 0.01, d, te0, hit=recorded)
        assert calls == [(pytest.approx(0.01 + te0 + sign * m, abs=1e-15), sign, pytest.approx(2 * m))]
        # 0.7 m: found 0.3 m from the start: kept
        calls.clear()
        te = checked(po, 0.01, 0.01, d, te0 - sign * 0.7 * m, 0.01, hit=recorded)[0]
        assert len(calls) == 1 and te == pytest.approx(te0, abs=1e-15)
    # a full search that widens its window: the pair set 0.5 mm apart (te 0.015 rad): 3e-3, then 1.2e-2, then 4.8e-2
    far = PairOutlines(po.drv, po.dvn, MOD * Z + 0.5, po.driver_teeth, po.driven_teeth)
    calls.clear()
    hit = lambda pair, phi_a, theta, sign, w: (calls.append(w), pruned_hit(pair, phi_a, theta, sign, w))[1]  # noqa: E731
    assert -4.8e-2 < checked(far, 0.0, 0.0, DRIVE, hit=hit)[0] < -1.2e-2
    assert calls == [3e-3, pytest.approx(1.2e-2), pytest.approx(4.8e-2)]


def test_resolve_contact_seeds_each_measurement_with_its_neighbour():
    """Each sample of the grid is measured from the previous sample's contact (dphi: their distance), each bisection
    from the contact at the interval's left end; the compiled runs (contact_track.track) give, bit for bit, what
    the reference search (``tests/contact_reference.py``) gives one position at a time seeded so."""
    from propulsor.checks.motion import contact_events

    po, _ = _gear_pair()
    calls = []
    real = contact_events.track

    def recorded(pair, phis, thetas, direction, seeds, seed_phis, chained, *reuse):
        r = real(pair, phis, thetas, direction, seeds, seed_phis, chained, *reuse)
        calls.append((list(map(float, phis)), list(map(float, thetas)), list(map(float, seeds)),
                      list(map(float, seed_phis)), chained, r[0].tolist(), list(zip(*(a.tolist() for a in r[1:])))))
        return r

    contact_events.track = recorded
    try:
        span = 2 * math.pi / Z
        c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0))
    finally:
        contact_events.track = real
    n = 24
    grid = calls[0]
    assert grid[4] is True and len(grid[0]) == n and math.isnan(grid[2][0]) and math.isnan(grid[3][0])
    assert all(not call[4] for call in calls[1:]) and sum(len(call[0]) for call in calls) == c.evaluations
    # the grid, one position after the other from the one before, as the reference search does it
    prev = prev_phi = None
    for phi, theta, te, state in zip(grid[0], grid[1], grid[5], grid[6]):
        r = contact(po, phi, theta, DRIVE, prev, 0.0 if prev_phi is None else phi - prev_phi)
        assert (r[0] == te or (math.isnan(r[0]) and math.isnan(te))) and r[1:4] == state  # kind, driver, driven tooth
        prev, prev_phi = (te, phi) if math.isfinite(te) else (None, None)
    te_at = dict(zip(c.phi.tolist(), c.te.tolist()))
    measured = set(grid[0])
    for phis, thetas, seeds, seed_phis, _, tes, states in calls[1:]:
        for phi, theta, seed, a, te, state in zip(phis, thetas, seeds, seed_phis, tes, states):
            assert a == max(x for x in measured if x < phi)  # the interval's left end, measured in an earlier round
            assert seed == te_at[a] or (math.isnan(seed) and math.isnan(te_at[a]))
            r = contact(po, phi, theta, DRIVE, seed, phi - a)
            assert r[0] == te == te_at[phi] and r[1:4] == state
        measured |= set(phis)
    assert len(calls) > 2  # bisections in more than one round
    assert len({st for call in calls for st in call[6]}) >= 2  # two tooth pairs


def test_contact_of_a_bar_and_a_block_off_the_line_of_centres():
    """PairOutlines on bodies that are not round (grids whose origins differ in x and y): the driven bar along +x
    from the assembly origin, the driver's block (its axis 8 mm away) with its lower-right corner at (7, 1.8): turned
    back (drive: the driven turns CCW) the bar's upper edge meets the corner at atan2(1.8, 7) - asin(0.5 / |q|); a
    driver tip corner on the driven flank, at that corner turned into the driven's frame."""
    q = np.array([7.0, 1.8])
    block = _square(q[0] - 1.0 - 8.0, q[1] + 1.0)  # in the driver's frame (axis at (8, 0))
    # teeth named by the nearest centre's polar angle: the corner lies at 2.078 rad in the driver's frame (tooth 0 at
    # 2.0, not 1 at 2.2), at 0.069 rad in the driven's when touching (tooth 0 at 0.05, not 1 at 0.2)
    po = PairOutlines(Outline([block], 100.0), Outline([BAR], 100.0), 8.0, [2.0, 2.2], [0.05, 0.2])
    e = _edge_meets_corner(q)
    assert 0.15 < e < policy.MOTION_MAX_FREE_ANGLE_RAD
    te, kind, t1, t2, p = checked(po, 0.0, 0.0, DRIVE)
    assert te == pytest.approx(-e, abs=1e-12)
    assert KINDS[kind] == "driver tip corner" and (t1, t2) == (0, 0)
    c, s = math.cos(-e), math.sin(-e)
    assert p == pytest.approx((c * q[0] - s * q[1], s * q[0] + c * q[1]), abs=1e-9)
    # turned on (reverse: CW) nothing is met within the largest free rotation
    assert math.isnan(checked(po, 0.0, 0.0, REVERSE)[0])
    # the driver turned by theta about its axis: the corner moves on a circle about (8, 0)
    th = 0.05
    qw = np.array([8.0, 0.0]) + np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]]) @ (q - (8.0, 0.0))
    assert checked(po, 0.0, th, DRIVE)[0] == pytest.approx(-_edge_meets_corner(qw), abs=1e-12)
    assert checked(po, 0.02, th, DRIVE)[0] == pytest.approx(-_edge_meets_corner(qw) - 0.02, abs=1e-12)



def test_a_driven_corner_on_a_driver_edge_names_the_teeth_from_the_contact_point():
    """The bar's tip corner (10, 0.5), a driven vertex, meets the block's lower edge y = 2.2 (the driver's axis 14 mm
    away): te = -(atan2(2.2, (100.25 - 2.2^2)^(1/2)) - atan2(0.5, 10)), a driven tip corner; the contact point is the
    corner itself in the driven frame, at 2.662 rad in the driver's (tooth 0 at 2.6, not 1 at 2.8)."""
    block = _square(10.0 - 14.0, 3.2)
    po = PairOutlines(Outline([block], 100.0), Outline([BAR], 100.0), 14.0, [2.6, 2.8], [0.0, 0.3])
    x = math.sqrt(100.25 - 2.2 ** 2)
    e = math.atan2(2.2, x) - math.atan2(0.5, 10.0)
    te, kind, t1, t2, p = checked(po, 0.0, 0.0, DRIVE)
    assert te == pytest.approx(-e, abs=1e-12)
    assert KINDS[kind] == "driven tip corner" and (t1, t2) == (0, 0)
    assert p.tolist() == [10.0, 0.5] and p.dtype == np.float64
    assert math.atan2(2.2, x - 14.0) == pytest.approx(2.6622, abs=1e-4)


def test_phi_of_theta_inverts_a_strongly_curved_law():
    """theta = phi + 0.4 sin(phi) over 0 .. 6 rad (monotone, its slope 0.6 .. 1.4): the driven angles of 200 driver
    angles found to 1e-12 rad of the law."""
    law = lambda p: np.asarray(p, float) + 0.4 * np.sin(np.asarray(p, float))  # noqa: E731
    th = np.linspace(law(0.0), law(6.0), 200)
    phi = ce._phi_of_theta(law, 0.0, 6.0, th)
    assert np.abs(law(phi) - th).max() < 1e-12


def test_a_driven_corner_on_a_turned_driver_edge():
    """The same bar and block, the driver turned by 0.05 rad about its axis (14, 0): the tip's circle |x| =
    (100.25)^(1/2) meets the turned lower edge at t = 0.458 of it; the contact point, taken back into the driver's
    frame, lies at 2.6474 rad there (teeth at 2.6006 and 2.7006: the first is nearer by 0.0064 rad)."""
    th = 0.05
    R, P, e = _tip_on_turned_edge((-5.0, 2.2), (-3.0, 2.2), th)
    local = R.T @ (P - (14.0, 0.0))
    assert math.atan2(local[1], local[0]) == pytest.approx(2.6474, abs=1e-4)
    po = PairOutlines(Outline([_square(10.0 - 14.0, 3.2)], 100.0), Outline([BAR], 100.0), 14.0, [2.6006, 2.7006],
                      [0.0, 0.3])
    te, kind, t1, t2, p = checked(po, 0.0, th, DRIVE)
    assert te == pytest.approx(-e, abs=1e-12) and (KINDS[kind], t1, t2) == ("driven tip corner", 0, 0)


def test_the_window_is_widened_to_take_in_contacts_within_contact_tol_of_the_first():
    """The first contact 3e-5 rad inside the search's fourth window (1e-3 x 4^3 = 0.064 rad), a second corner 0.7e-3 mm
    beyond the edge 2.5 mm further along it (its hit 7e-5 rad later, outside that window): the window is widened to
    the first hit + 2 contact_tol / r_min, and the second corner counts as a pair."""
    e = 0.064 - 3e-5
    rho = 7.0
    a = e + math.asin(0.5 / rho)
    q1 = rho * np.array([math.cos(a), math.sin(a)])
    u, n = np.array([math.cos(e), math.sin(e)]), np.array([-math.sin(e), math.cos(e)])
    s2 = float(np.dot(q1, u)) + 2.5
    q2 = s2 * u + (0.5 + 0.7e-3) * n
    assert _edge_meets_corner(q2) > 0.064
    blocks = [_square(*(q1 + (-1.0, 1.0))) - (C1 - C2), _square(*(q2 + (-0.3, 0.3)), h=0.3) - (C1 - C2)]
    res = transmission_sweep(blocks, C1, [BAR], C2, lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5)
    assert res.free_fwd[0] == pytest.approx(e, abs=1e-12) and res.pairs_coast[0] == 2


# ---------------------------------------------------------------------------------------------------------------
# poses.py: the rigid planar poses (2x3 affine matrices [R | t]) written out by hand
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import poses as pz  # noqa: E402


def test_a_pose_turns_about_its_pivot_then_moves_by_its_offset():
    # a quarter turn about (1, 2), then (3, 4) on: x -> R (x - p) + p + o with R (u, v) = (-v, u)
    M = pz.Pose(math.pi / 2, (1.0, 2.0), (3.0, 4.0)).matrix()
    assert M.shape == (2, 3)
    assert M == pytest.approx(np.array([[0.0, -1.0, 1.0 + 2.0 + 3.0], [1.0, 0.0, 2.0 - 1.0 + 4.0]]), abs=1e-15)
    for x in ((0.0, 0.0), (1.0, 2.0), (5.0, -1.0)):
        u, v = x[0] - 1.0, x[1] - 2.0
        assert M[:, :2] @ x + M[:, 2] == pytest.approx((-v + 1.0 + 3.0, u + 2.0 + 4.0), abs=1e-14)
    assert pz.Pose().matrix().tolist() == [[1.0, -0.0, 0.0], [0.0, 1.0, 0.0]]


def test_poses_from_angles_one_pose_per_angle_in_floats():
    ps = pz.poses_from_angles(np.array([[0, 1], [2, 3]]), pivot=(1, 2), offset=(3, 4))
    assert ps == [pz.Pose(float(a), (1.0, 2.0), (3.0, 4.0)) for a in (0, 1, 2, 3)]
    for p in ps:
        assert type(p.angle) is float and all(type(c) is float for c in p.pivot + p.offset)
        assert type(p.pivot) is tuple and type(p.offset) is tuple
    assert pz.poses_from_angles([0.5]) == [pz.Pose(0.5, (0.0, 0.0), (0.0, 0.0))]


def test_rotation_matrices_are_the_turns_then_the_translations():
    a = [0.3, -2.0]
    M = pz.rotation_matrices(a)
    assert M.shape == (2, 2, 3)
    for k, t in enumerate(a):
        assert M[k].tolist() == [[math.cos(t), -math.sin(t), 0.0], [math.sin(t), math.cos(t), 0.0]]
    M = pz.rotation_matrices(np.array([1, 2]), [[5.0, 6.0], [7.0, 8.0]])
    assert M.dtype == np.float64
    assert M[0].tolist() == [[math.cos(1), -math.sin(1), 5.0], [math.sin(1), math.cos(1), 6.0]]
    assert M[1].tolist() == [[math.cos(2), -math.sin(2), 7.0], [math.sin(2), math.cos(2), 8.0]]


def test_pose_stack_of_one_pose_held_fixed():
    p = pz.Pose(0.25, (1.0, 0.0), (0.0, 2.0))
    M, ang = pz.pose_stack(p, None, "poses_a")
    assert M.shape == (1, 2, 3) and ang.tolist() == [0.25]
    assert M[0].tolist() == p.matrix().tolist()
    M, ang = pz.pose_stack(p, 3, "poses_a")
    assert M.shape == (3, 2, 3) and ang.tolist() == [0.25] * 3
    assert all(M[k].tolist() == p.matrix().tolist() for k in range(3))
    # a list of one pose (or one matrix) stretched to n = 2 steps; n = 1 and None leave it one
    for one in ([p], p.matrix()[None]):
        M, ang = pz.pose_stack(one, 2, "poses_a")
        assert M.shape == (2, 2, 3) and ang == pytest.approx([0.25, 0.25], abs=1e-15)
        assert M[0].tolist() == M[1].tolist() and M[1] == pytest.approx(p.matrix(), abs=1e-15)
        for n in (1, None):
            M, ang = pz.pose_stack(one, n, "poses_a")
            assert M.shape == (1, 2, 3) and len(ang) == 1


def test_pose_stack_of_matrices_reads_the_angle_from_the_first_column():
    t = np.array([0.7, -2.5, 3.0])
    M = np.zeros((3, 2, 3), int).astype(float)
    M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = np.cos(t), -np.sin(t), np.sin(t), np.cos(t)
    M[:, :, 2] = [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
    out, ang = pz.pose_stack(M, 3, "poses_b")
    assert out.tolist() == M.tolist() and ang == pytest.approx(t, abs=1e-15)
    # integer matrices (quarter turns) come out as floats; so do integer Pose angles
    q = np.array([[[0, -1, 3], [1, 0, 4]]])
    out, ang = pz.pose_stack(q, None, "poses_b")
    assert out.dtype == np.float64 and ang.dtype == np.float64 and ang.tolist() == [math.pi / 2]
    out, ang = pz.pose_stack([pz.Pose(1), pz.Pose(2)], 2, "poses_b")
    assert ang.dtype == np.float64 and ang.tolist() == [1.0, 2.0]
    assert out == pytest.approx(np.array([pz.Pose(1.0).matrix(), pz.Pose(2.0).matrix()]), abs=0)


def test_pose_stack_refusals_in_full():
    def msg(poses, name="poses_a"):
        with pytest.raises(InputError) as e:
            pz.pose_stack(poses, None, name)
        return str(e.value)

    assert msg(np.zeros((2, 3))) == "poses_a = (2, 3): must be Poses or an (n, 2, 3) array"
    assert msg(np.zeros((4, 2, 2)), "poses_b") == "poses_b = (4, 2, 2): must be Poses or an (n, 2, 3) array"
    assert msg(np.zeros((1, 3, 3))) == "poses_a = (1, 3, 3): must be Poses or an (n, 2, 3) array"
    assert msg([pz.Pose(), "x"], "poses_b") == "poses_b = 'mixed': must be Pose objects"
    assert msg([]) == "poses_a = 0: need at least one pose"
    assert msg(np.zeros((0, 2, 3)), "poses_b") == "poses_b = 0: need at least one pose"
    bad = np.zeros((2, 2, 3))
    bad[1, 0, 2] = np.inf
    assert msg(bad) == "poses_a = 'non-finite': poses must be finite"
    assert msg([pz.Pose(math.nan)], "poses_b") == "poses_b = 'non-finite': poses must be finite"
    # the limits' other sides: one pose, finite
    assert pz.pose_stack(np.zeros((1, 2, 3)), None, "poses_a")[0].shape == (1, 2, 3)


def test_apply_inverse_and_compose_poses_by_hand():
    A = pz.Pose(math.pi / 2, (0.0, 0.0), (1.0, 0.0)).matrix()   # (x, y) -> (1 - y, x)
    B = pz.Pose(math.pi, (0.0, 0.0), (0.0, 2.0)).matrix()       # (x, y) -> (-x, 2 - y)
    P = np.array([[1.0, 0.0], [2.0, 3.0]])
    assert pz.apply_pose(A, P) == pytest.approx(np.array([[1.0, 1.0], [-2.0, 2.0]]), abs=1e-15)
    # A o B: (x, y) -> A(-x, 2 - y) = (1 - 2 + y, -x)
    AB = pz.compose_poses(A, B)
    assert pz.apply_pose(AB, P) == pytest.approx(np.array([[-1.0, -1.0], [2.0, -2.0]]), abs=1e-15)
    assert AB == pytest.approx(np.array([[0.0, 1.0, -1.0], [-1.0, 0.0, 0.0]]), abs=1e-15)
    # A's inverse: (u, v) -> (v, 1 - u)
    Ai = pz.inverse_pose(A)
    assert Ai == pytest.approx(np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]]), abs=1e-15)
    assert pz.apply_pose(Ai, np.array([[1.0, 1.0], [-2.0, 2.0]])) == pytest.approx(P, abs=1e-15)


# ---------------------------------------------------------------------------------------------------------------
# distance.py: the KD-tree least distance, its pruning discs and balls, against brute force over every edge
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import distance as dz  # noqa: E402

SQUARE10 = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]])  # CCW: kept in this order, edges 10 mm


def _seg_dist(p, a, b):
    """Distance from p to the segment ab and its foot, written out."""
    d = (b[0] - a[0], b[1] - a[1])
    t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1])
    t = min(max(t, 0.0), 1.0)
    q = (a[0] + t * d[0], a[1] + t * d[1])
    return math.hypot(p[0] - q[0], p[1] - q[1]), q


def _brute_nearest(P, loop):
    """(least distance, its point's index, foot) over every point and every edge of one closed loop."""
    best = (math.inf, -1, None)
    for i, p in enumerate(P):
        for k in range(len(loop)):
            d, q = _seg_dist(p, loop[k], loop[(k + 1) % len(loop)])
            if d < best[0]:
                best = (d, i, q)
    return best


def _polygon(n, r=1.0, c=(0.0, 0.0)):
    a = 2.0 * math.pi * np.arange(n) / n
    return np.column_stack([c[0] + r * np.cos(a), c[1] + r * np.sin(a)])


def test_chunk_discs_hold_each_run_of_32_vertices_and_are_cached():
    src = Outline([_polygon(70)], 100.0)
    assert len(src.points) == 70
    reps, rho, rho_max = dz._chunk_discs(src)
    assert reps.tolist() == [0, 32, 64]
    want = [max(math.dist(src.points[r], src.points[i]) for i in range(r, min(r + 32, 70))) for r in (0, 32, 64)]
    assert rho == pytest.approx(want, abs=1e-15) and rho_max == pytest.approx(max(want), abs=1e-15)
    # a run of 32 vertices of the 70-gon spans 31 steps: its farthest vertex is 2 sin(31 pi / 70) away; 6 vertices: 5
    assert want == pytest.approx([2 * math.sin(31 * math.pi / 70)] * 2 + [2 * math.sin(5 * math.pi / 70)], abs=1e-12)
    assert dz._chunk_discs(src) is dz._chunk_discs(src)


def test_live_points_keeps_a_run_exactly_at_its_bound_and_drops_it_beyond():
    tgt = Outline([SQUARE10], 100.0)
    src = Outline([_polygon(70)], 100.0)
    P = src.points + (12.0, 3.0)
    m = policy.MOTION_PRUNE_MARGIN_MM
    rho = [max(math.dist(src.points[r], src.points[i]) for i in range(r, min(r + 32, 70))) for r in (0, 32, 64)]
    dr = [min(math.dist(P[r], v) for v in SQUARE10) for r in (0, 32, 64)]
    assert dr[0] == pytest.approx(math.hypot(3.0, 3.0), abs=1e-12)  # (13, 3) to the corner (10, 0)
    keep = np.array([40, 3, 65, 10, 33, 0])  # runs 1, 0, 2, 0, 1, 0
    limit = dr[0] - rho[0]
    bound = limit - m
    assert bound + m == limit  # run 0 exactly at its bound (<=: kept)
    live = [dr[c] - rho[c] <= limit for c in range(3)]
    assert live[0] and not live[2]  # run 2 (near (12 + cos, 3 + sin) of angles 5.7..6.2) is farther off
    got = dz._live_points(P, keep, tgt, src, bound)
    assert got.tolist() == [k for k in keep.tolist() if live[k // 32]]
    assert 0 in got.tolist() and 3 in got.tolist()
    # a tenth of the margin beyond: run 0 is dropped
    got = dz._live_points(P, keep, tgt, src, bound - 0.1 * m)
    assert 0 not in got.tolist() and 3 not in got.tolist() and 10 not in got.tolist()


def test_ball_pairs_are_the_edges_on_each_side_of_every_vertex_within_r():
    tgt = Outline([SQUARE10], 100.0)
    assert tgt.prev.tolist() == [3, 0, 1, 2]
    # one vertex within r: the edge starting there (0 -> 1) and the one ending there (3 -> 0)
    pi, si = dz.ball_pairs(tgt, np.array([[-1.0, 0.0]]), 1.5)
    assert pi.tolist() == [0, 0] and si.tolist() == [0, 3]
    # none
    pi, si = dz.ball_pairs(tgt, np.array([[-1.0, 0.0], [5.0, 5.0]]), 0.5)
    assert pi.shape == si.shape == (0,) and pi.dtype.kind == si.dtype.kind == "i"
    # (5, -1) reaches (0, 0) and (10, 0) (sqrt 26 = 5.099); (-1, 0) reaches (0, 0) only
    pi, si = dz.ball_pairs(tgt, np.array([[5.0, -1.0], [-1.0, 0.0]]), 5.2)
    assert sorted(zip(pi.tolist(), si.tolist())) == [(0, 0), (0, 0), (0, 1), (0, 3), (1, 0), (1, 3)]


def test_dist_each_point_is_the_distance_to_the_nearest_edge():
    tgt = Outline([SQUARE10], 100.0)
    P = np.array([[5.0, -2.0], [12.0, 12.0], [5.0, 5.5], [-1.0, 0.0], [3.0, 9.0]])
    got = dz.dist_each_point(P, tgt)
    assert got == pytest.approx([2.0, math.sqrt(8.0), 4.5, 1.0, 1.0], abs=1e-12)
    assert got == pytest.approx([_brute_nearest(P[i:i + 1], SQUARE10)[0] for i in range(5)], abs=1e-12)
    assert dz.dist_each_point(P[2:3], tgt).tolist() == [4.5]
    e = dz.dist_each_point(np.empty((0, 2)), tgt)
    assert e.shape == (0,)


def test_within_are_the_points_whose_distance_to_an_edge_is_at_most_tol():
    """The middle of a long edge lies half an edge from its ends: a point 0.5 mm off it is within 1 mm though its
    nearest vertex is 5.02 mm away; the same indices as the distances of every point filtered."""
    tgt = Outline([SQUARE10], 100.0)
    P = np.array([[5.0, -0.5], [5.0, -1.5], [12.0, 12.0], [5.0, 5.5], [10.0, 10.9], [0.2, 0.2]])
    assert dz.within(P, tgt, 1.0).tolist() == [0, 4, 5]
    rng = np.random.default_rng(2)
    Q = rng.uniform(-3.0, 13.0, (400, 2))
    for tol in (0.05, 0.5, 2.0):
        assert dz.within(Q, tgt, tol).tolist() == np.nonzero(dz.dist_each_point(Q, tgt) <= tol)[0].tolist()
    assert dz.within(np.empty((0, 2)), tgt, 1.0).shape == (0,)


def test_min_dist_of_tied_points_is_the_first_and_the_middle_of_a_long_edge_counts():
    """(5, 0), the middle of the 10 mm edge, lies exactly half an edge from its ends; (10, 10) is a vertex: both at 0
    and the first point is the answer (nearest.py's "first pair at the least distance")."""
    tgt = Outline([SQUARE10], 100.0)
    assert tgt.half_len == 5.0
    d, i, q = dz.min_dist_points_to(np.array([[5.0, 0.0], [10.0, 10.0]]), tgt)
    assert (d, i, q.tolist()) == (0.0, 0, [5.0, 0.0])
    d, i, q = dz.min_dist_points_to(np.array([[5.0, 0.5], [10.5, 10.0]]), tgt)
    assert (d, i, q.tolist()) == (0.5, 0, [5.0, 0.0])


def test_min_dist_finds_a_mid_edge_point_that_the_subsample_bound_hides():
    """130 points (the subsample: every other): the nearest (0.01 below the top edge's middle, its corners 5 mm off)
    and one 0.04 inside a corner at odd places, the rest near the centre (7.07 mm from every corner); the least lower
    bound at a point 1.04 above the top edge (5.1 mm from the corners)."""
    tgt = Outline([SQUARE10], 100.0)
    P = np.array([(5.0 + 0.01 * math.cos(k), 5.0 + 0.01 * math.sin(k)) for k in range(130)])
    P[1] = (9.96, 9.96)
    P[3] = (5.0, 9.99)
    P[4] = (5.0, 11.04)
    want = _brute_nearest(P, SQUARE10)
    assert want[0] == pytest.approx(0.01, abs=1e-12) and want[1] == 3
    d, i, q = dz.min_dist_points_to(P, tgt)
    assert (d, i) == (pytest.approx(want[0], abs=1e-12), 3) and q == pytest.approx(np.array(want[2]), abs=1e-12)


def test_check_record_keeps_none_and_makes_numbers_floats():
    c = dz.check_record("motion.x", 1, None, None, "mm", "why")
    assert (c.name, c.passed, c.value, c.limit, c.unit, c.message) == ("motion.x", True, None, None, "mm", "why")
    c = dz.check_record("motion.y", 0, np.float32(0.5), 2, "mm^2", "")
    assert (c.passed, c.value, c.limit) == (False, 0.5, 2.0) and type(c.value) is float and type(c.limit) is float


# ---------------------------------------------------------------------------------------------------------------
# crossing.py: bodies certainly apart (no boolean): the limits of d and the crossing search's grid
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import crossing as cz  # noqa: E402


def _rect(x0, y0, x1, y1):
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])  # CCW, first corner (x0, y0)


def test_loop_firsts_are_the_first_vertex_of_each_loop_and_are_cached():
    o = Outline([_rect(0, 0, 10, 10), _polygon(3, 1.0, (5.0, 5.0))[::-1], _polygon(5, 0.5, (2.0, 2.0))[::-1]], 100.0)
    assert o.loop_id.tolist() == [0] * 4 + [1] * 3 + [2] * 5
    f = cz._loop_firsts(o)
    assert f.tolist() == [0, 4, 7] and f.dtype == np.int64
    assert cz._loop_firsts(o) is f
    assert cz._loop_firsts(Outline([_rect(0, 0, 1, 1)], 100.0)).tolist() == [0]


def test_certainly_apart_doubts_at_apart_min_and_trusts_just_above():
    # 10 mm apart, no edges on one line (collinear edges count as touching: zero orientations)
    A, B = Outline([SQUARE10], 100.0), Outline([_rect(20, 1, 30, 9)], 100.0)
    assert not cz.certainly_apart(A, B, B.points, A.points, cz.APART_MIN_MM)
    assert cz.certainly_apart(A, B, B.points, A.points, float(np.nextafter(cz.APART_MIN_MM, 1.0)))
    assert cz.certainly_apart(A, B, B.points, A.points, 10.0)
    # a body inside the other's hole is apart; inside the other (either way round) is not
    ring = Outline([_rect(-10, -10, 20, 20), SQUARE10[::-1] + 0.0], 100.0)
    inner = Outline([_rect(2, 2, 8, 8)], 100.0)
    assert cz.certainly_apart(ring, inner, inner.points, ring.points, 2.0)
    big = Outline([_rect(-10, -10, 20, 20)], 100.0)
    assert not cz.certainly_apart(big, inner, inner.points, big.points, 2.0)
    assert not cz.certainly_apart(inner, big, big.points, inner.points, 2.0)


def test_the_crossing_search_runs_up_to_half_the_longest_edge_inclusive():
    """A bar 20 x 2 mm through the 10 mm square (half edges 10 and 5): neither holds the other's first corner, the
    boundaries cross at x = 0 and 10.  With d at most 10 the edges are searched (crossing: not apart); above 10 the
    search is skipped, d having promised that no edges cross."""
    A, B = Outline([SQUARE10], 100.0), Outline([_rect(-5, 4, 15, 6)], 100.0)
    assert (A.half_len, B.half_len) == (5.0, 10.0)
    assert not cz.certainly_apart(A, B, B.points, A.points, 10.0)
    assert not cz.certainly_apart(A, B, B.points, A.points, 0.5)
    assert cz.certainly_apart(A, B, B.points, A.points, float(np.nextafter(10.0, 11.0)))


def test_the_crossing_search_finds_a_crossing_far_from_the_origin():
    """The square at x = 100..110 cut into 0.5 mm edges (a grid of 4 mm cells from (100, 0)), a bar 95..103 through
    its left edge: the crossings lie in the first column of cells."""
    A = Outline([_rect(100, 0, 110, 10)], 0.5)
    B = Outline([_rect(95, 4, 103, 6)], 0.5)
    from propulsor.checks.motion.nearest import grid_of
    g = grid_of(A)
    assert g.origin.tolist() == [100.0, 0.0] and g.nx == 3
    assert not cz.certainly_apart(A, B, B.points, A.points, 0.1)
    far = Outline([_rect(85, 4, 93, 6)], 0.5)
    assert cz.certainly_apart(A, far, far.points, A.points, 0.1)


# ---------------------------------------------------------------------------------------------------------------
# outlines.py: cleaning, orientation by nesting, subdivision, the annulus, crops and offsets, by hand
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import outlines as oz  # noqa: E402


def _msg(fn, *a, **kw):
    with pytest.raises(InputError) as e:
        fn(*a, **kw)
    return str(e.value)


def test_outline_refusals_in_full_and_both_sides_of_three_points():
    assert _msg(Outline, [np.zeros((3, 3))]) == "loops[0] = (3, 3): must be an (n, 2) array of points"
    assert _msg(Outline, [SQUARE10, np.zeros(4)]) == "loops[1] = (4,): must be an (n, 2) array of points"
    bad = SQUARE10.copy()
    bad[2, 1] = np.nan
    assert _msg(Outline, [SQUARE10, bad]) == "loops[1] = 'non-finite': points must be finite"
    assert _msg(Outline, [SQUARE10[:2]]) == "loops[0] = 2: a closed loop needs at least 3 distinct points"
    assert len(Outline([SQUARE10[:3]], 100.0)) == 3
    assert _msg(Outline, []) == "loops = 0: need at least one closed loop"
    assert _msg(Outline, [SQUARE10], 0.0) == "max_segment = 0.0: must be > 0 mm"
    assert _msg(oz.outline, SQUARE10, 1e-4, -1.0) == "max_segment = -1.0: must be > 0 mm"
    assert _msg(oz.outline, Profile(circle_loop(7.0)), 0.0) == "chord_tol = 0.0: must be > 0 mm"
    assert _msg(oz.outline, 5) == ("body = 'int': must be a Profile, an Outline or a list of closed (n, 2) "
                                   "polylines")


def test_clean_loop_drops_the_closing_point_and_repeated_vertices_only():
    # integer points come out as floats
    o = Outline([[[0, 0], [10, 0], [0, 10]]], 100.0)
    assert o.points.dtype == np.float64 and o.loops[0].dtype == np.float64
    # the first point repeated at the end (within POINT_TOL_MM): dropped
    o = Outline([np.vstack([SQUARE10, [[0.0, 5e-8]]])], 100.0)
    assert o.points.tolist() == SQUARE10.tolist()
    # a vertex exactly POINT_TOL_MM before the next: dropped (a step must exceed it)
    tol = policy.POINT_TOL_MM
    o = Outline([np.array([[0.0, 0.0], [tol, 0.0], [10.0, 0.0], [0.0, 10.0]])], 100.0)
    assert o.points.tolist() == [[tol, 0.0], [10.0, 0.0], [0.0, 10.0]]
    # the first two points within POINT_TOL_MM: the first goes, the last stays
    o = Outline([np.array([[0.0, 0.0], [5e-8, 0.0], [10.0, 0.0], [0.0, 10.0]])], 100.0)
    assert o.points.tolist() == [[5e-8, 0.0], [10.0, 0.0], [0.0, 10.0]]
    # a loop that returns to its start or to its second point on the way keeps every point
    o = Outline([np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 0.0], [0.0, -10.0], [-10.0, 0.0]])], 100.0)
    assert len(o) == 5
    o = Outline([np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [10.0, 0.0]])], 100.0)
    assert len(o) == 4


def test_signed_area_and_points_in_polygon_by_hand():
    tri = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 3.0]])
    assert oz._signed_area(tri) == 6.0 and oz._signed_area(tri[::-1]) == -6.0
    assert oz._signed_area(SQUARE10 + (3.0, 7.0)) == 100.0
    # a triangle off the origin, its slanted edge x + y = 65
    t = np.array([[20.0, 30.0], [30.0, 30.0], [20.0, 40.0]])
    pts = np.array([[24.9, 35.0], [25.1, 35.0], [21.0, 31.0], [19.9, 35.0], [22.0, 29.9], [20.0, 35.0], [25.0, 35.0]])
    # on the left edge: inside; on the slanted one: outside (the ray to +x counts crossings at x < the edge's x)
    assert oz._points_in_polygon(pts, t).tolist() == [True, False, True, False, False, True, False]
    assert oz._points_in_polygon(pts, t[::-1]).tolist() == [True, False, True, False, False, True, False]
    # a U: the ray from the left prong crosses three edges
    u = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [7.0, 10.0], [7.0, 3.0], [3.0, 3.0], [3.0, 10.0], [0.0, 10.0]])
    assert oz._points_in_polygon(np.array([[1.0, 5.0], [5.0, 5.0], [8.0, 5.0], [5.0, 1.0]]), u).tolist() == [
        True, False, True, True]


def test_orientation_by_nesting_outer_ccw_hole_cw_island_ccw():
    outer, hole, island = _rect(0, 0, 30, 30), _rect(5, 5, 25, 25), _rect(10, 10, 20, 20)
    o = Outline([outer[::-1], hole, island[::-1]], 100.0)
    assert [oz._signed_area(p) > 0 for p in o.loops] == [True, False, True]
    assert o.loops[0].tolist() == outer.tolist() and o.loops[1].tolist() == hole[::-1].tolist()
    assert o.loops[2].tolist() == island.tolist()
    assert o.area == pytest.approx(900.0 - 400.0 + 100.0, abs=1e-9)
    # a fourth level (depth 3): a hole again
    o = Outline([outer, hole, island, _rect(12, 12, 18, 18)], 100.0)
    assert [oz._signed_area(p) > 0 for p in o.loops] == [True, False, True, False]


def test_subdivision_arclength_and_perimeters_of_two_loops():
    # a 10 mm square cut at 6 mm: every edge in two of 5 mm; a CW hole of 2 mm sides left whole
    o = Outline([SQUARE10, _rect(4, 4, 6, 6)], 6.0)
    assert o.points.tolist() == [[0, 0], [5, 0], [10, 0], [10, 5], [10, 10], [5, 10], [0, 10], [0, 5],
                                 [4, 6], [6, 6], [6, 4], [4, 4]]
    assert o.loop_id.tolist() == [0] * 8 + [1] * 4
    assert o.arclen.tolist() == [0, 5, 10, 15, 20, 25, 30, 35, 0, 2, 4, 6]
    assert o.perimeter.tolist() == [40.0, 8.0]
    assert o.nxt.tolist() == [1, 2, 3, 4, 5, 6, 7, 0, 9, 10, 11, 8]
    assert o.prev.tolist() == [7, 0, 1, 2, 3, 4, 5, 6, 11, 8, 9, 10]
    assert o.half_len == 2.5 and o.area == pytest.approx(96.0, abs=1e-9)
    # a 12 mm edge cut at 5 mm: three edges of 4 mm
    o = Outline([np.array([[0.0, 0.0], [12.0, 0.0], [0.0, 1.0]])], 5.0)
    assert o.points[:4] == pytest.approx(np.array([[0, 0], [4, 0], [8, 0], [12, 0]]), abs=1e-15)


def test_the_annulus_of_a_plus_sign_reaches_its_inner_corners():
    """A plus sign, arms 2 w = 4 mm wide reaching L = 10 from its centre: the boundary's nearest points to the centre
    are the four inner corners (w, w) (w sqrt 2; the lines of their edges pass at w), its farthest the arms' corners
    (sqrt(L^2 + w^2))."""
    w, L = 2.0, 10.0
    plus = np.array([[w, -w], [L, -w], [L, w], [w, w], [w, L], [-w, L], [-w, w], [-L, w], [-L, -w], [-w, -w],
                     [-w, -L], [w, -L]])
    o = Outline([plus], 100.0)
    assert o.center.tolist() == [0.0, 0.0]
    assert o.r_min == pytest.approx(w * math.sqrt(2.0), abs=1e-12)
    assert o.radius == pytest.approx(math.hypot(L, w), abs=1e-12)
    P = np.array([[0.0, 0.0], [20.0, 0.0], [1.0, 1.0]])
    assert o.boundary_lower_bound(P) == pytest.approx(
        [w * math.sqrt(2), 20.0 - math.hypot(L, w), w * math.sqrt(2) - math.sqrt(2)], abs=1e-12)
    # off the origin: the same annulus about the box's centre
    o = Outline([plus + (100.0, -50.0)], 100.0)
    assert o.center.tolist() == [100.0, -50.0] and o.r_min == pytest.approx(w * math.sqrt(2.0), abs=1e-12)


def test_outline_of_a_profile_takes_max_segment_and_passes_an_outline_through():
    p = Profile(circle_loop(7.0))
    n = len([q for q in p.polylines(1e-2)[0]])
    o = oz.outline(p, 1e-2, 100.0)
    assert abs(len(o) - n) <= 1  # the polyline's vertices (its closing point dropped), none added
    assert len(oz.outline(p, 1e-2)) > 5 * len(o)  # the default 0.1 mm edges
    assert oz.outline(o) is o
    assert len(oz.outline(SQUARE10, max_segment=100.0)) == 4
    assert len(oz.outline((q for q in [SQUARE10]), max_segment=5.0)) == 8


def _wedge_area(a0, a1, r_in, r_out, n):
    """A polygon of n points on each arc: (n - 1) triangles of the outer arc less those of the inner one."""
    d = (a1 - a0) / (n - 1)
    return 0.5 * (n - 1) * math.sin(d) * (r_out ** 2 - r_in ** 2)


def test_crop_to_sector_is_the_polygonal_annular_sector():
    # (manifold3d keeps its points to about 4e-9 mm)
    big = m3d.CrossSection([np.ascontiguousarray(_rect(-20, -20, 20, 20))], m3d.FillRule.Positive)
    # a quarter: ceil((pi / 2) / 0.02) = 79 points on each arc
    loops = oz.crop_to_sector(big, 0.0, math.pi / 2, 2.0, 5.0)
    assert len(loops) == 1 and loops[0].dtype == np.float64 and len(loops[0]) == 2 * 79
    assert abs(oz._signed_area(loops[0])) == pytest.approx(_wedge_area(0.0, math.pi / 2, 2.0, 5.0, 79), abs=1e-7)
    r = np.hypot(loops[0][:, 0], loops[0][:, 1])
    assert r.min() == pytest.approx(2.0, abs=1e-8) and r.max() == pytest.approx(5.0, abs=1e-8)
    # a narrow sector (0.1 rad: ceil 5) takes the least, 8 points an arc; with r_in 0 a pie (the centre one point)
    loops = oz.crop_to_sector(big, 1.0, 1.1, 0.0, 5.0)
    assert len(loops[0]) == 9
    assert abs(oz._signed_area(loops[0])) == pytest.approx(_wedge_area(1.0, 1.1, 0.0, 5.0, 8), abs=1e-7)
    a = np.arctan2(loops[0][:, 1], loops[0][:, 0])
    assert a[np.hypot(loops[0][:, 0], loops[0][:, 1]) > 1.0].min() == pytest.approx(1.0, abs=1e-8)
    assert a.max() == pytest.approx(1.1, abs=1e-8)
    # a body inside the sector comes out whole
    sq = m3d.CrossSection([np.ascontiguousarray(_rect(1, 1, 2, 2))], m3d.FillRule.Positive)
    loops = oz.crop_to_sector(sq, 0.0, math.pi / 2, 0.5, 5.0)
    assert sorted(map(tuple, loops[0].tolist())) == [(1.0, 1.0), (1.0, 2.0), (2.0, 1.0), (2.0, 2.0)]


def test_offset_outline_thins_thickens_and_shifts():
    o = Outline([SQUARE10], 100.0)
    # the new outline's edges are the default 0.1 mm
    assert oz.offset_outline(o, 0.0).half_len == pytest.approx(0.05, abs=1e-12)
    same = oz.offset_outline(o, 0.0, (1.0, 2.0))
    assert same.loops[0].tolist() == (SQUARE10 + (1.0, 2.0)).tolist()
    thin = oz.offset_outline(o, 1.0)
    assert sorted(map(tuple, thin.loops[0].tolist())) == [(1.0, 1.0), (1.0, 9.0), (9.0, 1.0), (9.0, 9.0)]
    # thicker by 1: the sides moved out, the corners quarter circles of a 64-gon
    thick = oz.offset_outline(o, -1.0, (0.0, -3.0))
    assert thick.area == pytest.approx(100.0 + 40.0 + 0.5 * 64 * math.sin(2 * math.pi / 64), abs=1e-6)
    assert thick.points[:, 1].min() == pytest.approx(-4.0, abs=1e-9) and thick.points[:, 0].max() == pytest.approx(
        11.0, abs=1e-9)
    # two bodies thinned: the larger one is kept
    two = Outline([SQUARE10, _rect(12, 3, 16, 7)], 100.0)
    kept = oz.offset_outline(two, 1.0)
    assert sorted(map(tuple, kept.loops[0].tolist())) == [(1.0, 1.0), (1.0, 9.0), (9.0, 1.0), (9.0, 9.0)]
    two = Outline([_rect(12, 3, 16, 7), SQUARE10], 100.0)
    kept = oz.offset_outline(two, 1.0)
    assert sorted(map(tuple, kept.loops[0].tolist())) == [(1.0, 1.0), (1.0, 9.0), (9.0, 1.0), (9.0, 9.0)]


def test_crop_to_sector_keeps_an_inner_arc_below_one_mm_and_offset_keeps_a_triangle():
    big = m3d.CrossSection([np.ascontiguousarray(_rect(-20, -20, 20, 20))], m3d.FillRule.Positive)
    loops = oz.crop_to_sector(big, 0.0, math.pi / 2, 0.5, 5.0)
    assert len(loops[0]) == 2 * 79
    assert abs(oz._signed_area(loops[0])) == pytest.approx(_wedge_area(0.0, math.pi / 2, 0.5, 5.0, 79), abs=1e-7)
    # a right triangle (legs 12) thinned by 1: its legs move in by 1, its hypotenuse x + y = 12 by 1 to 12 - sqrt 2
    tri = Outline([np.array([[0.0, 0.0], [12.0, 0.0], [0.0, 12.0]])], 100.0)
    thin = oz.offset_outline(tri, 1.0)
    k = 11.0 - math.sqrt(2.0)
    assert len(thin.loops[0]) == 3
    assert np.array(sorted(map(tuple, thin.loops[0].tolist()))) == pytest.approx(
        np.array([(1.0, 1.0), (1.0, k), (k, 1.0)]), abs=1e-8)


# ---------------------------------------------------------------------------------------------------------------
# nearest.py: the vertex grid by hand, its levels and the compiled search's pruning against brute force
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import nearest as nz  # noqa: E402


def test_vertex_grid_of_a_unit_square_by_hand():
    """Edges of mean 0.0125 mm: cells of 8 x 0.0125 = 0.1 mm; 1.0 // 0.1 = 9 (0.1 is a little over a tenth): 10 x 10
    cells, the far corners (1.0 / 0.1 = 10) clamped into the last column and row."""
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    g = nz.VertexGrid(pts, np.roll(pts, -1, axis=0), np.full(4, 0.0125))
    assert (g.h, g.nx, g.ny) == (0.1, 10, 10) and g.origin.tolist() == [0.0, 0.0]
    assert g.items.tolist() == [0, 3, 1, 2] and g.items.dtype == np.int64  # cells 0, 9, 90, 99
    assert g.start.dtype == np.int64 and len(g.start) == 101
    assert np.flatnonzero(np.diff(g.start)).tolist() == [0, 9, 90, 99] and g.start[-1] == 4
    assert g.seg_b.tolist() == np.roll(pts, -1, axis=0).tolist() and g.seg_b.flags.c_contiguous
    # near: the cells within one of an occupied one (2 x 2 about each corner)
    want = sorted(ix * 10 + iy for cx in (0, 9) for cy in (0, 9) for ix in range(10) for iy in range(10)
                  if abs(ix - cx) <= 1 and abs(iy - cy) <= 1)
    assert g.near.dtype == np.bool_ and np.flatnonzero(g.near).tolist() == want and len(want) == 16


def test_vertex_grid_cell_side_its_limits_and_vertex_order_in_a_cell():
    # a 10 x 4 box, edges of mean 0.5: 4 mm cells, 3 x 2 of them
    pts = np.array([[5.0, 3.0], [15.0, 3.0], [15.0, 7.0], [5.0, 7.0]])
    g = nz.VertexGrid(pts, pts, np.full(4, 0.5), 3.0)
    assert (g.h, g.nx, g.ny) == (12.0, 1, 1) and g.origin.tolist() == [5.0, 3.0]
    g = nz.VertexGrid(pts, pts, np.full(4, 0.5))
    assert (g.h, g.nx, g.ny) == (4.0, 3, 2)
    # at most 2^21 cells: a 2000 x 1000 box of 0.01 mm edges has cells of sqrt(2e6 / 2^21) = 0.9765625 mm (2000 of
    # them exactly: 2049 columns)
    pts = np.array([[0.0, 0.0], [2000.0, 0.0], [2000.0, 1000.0], [0.0, 1000.0]])
    g = nz.VertexGrid(pts, pts, np.full(4, 0.01))
    h = math.sqrt(2000.0 * 1000.0 / 2 ** 21)
    assert g.h == h and (g.nx, g.ny) == (int(2000.0 // h) + 1, int(1000.0 // h) + 1) == (2049, 1025)
    # a point: the least cell side 1e-6
    g = nz.VertexGrid(np.zeros((3, 2)), np.zeros((3, 2)), np.zeros(3))
    assert (g.h, g.nx, g.ny) == (1e-6, 1, 1) and g.items.tolist() == [0, 1, 2]
    # 90 vertices in three cells, interleaved: each cell lists its vertices in ascending order
    x = np.tile([0.5, 4.5, 8.5], 30)
    pts = np.column_stack([x, np.linspace(0.0, 1.0, 90)])
    g = nz.VertexGrid(pts, pts, np.full(90, 0.5))
    assert (g.nx, g.ny) == (3, 1)
    assert g.items.tolist() == list(range(0, 90, 3)) + list(range(1, 90, 3)) + list(range(2, 90, 3))


def test_vertex_grid_buckets_are_those_of_a_stable_sort_by_cell():
    """The compiled counting pass (``_bucket_nb``) against numpy's formulation: the vertices of each cell by a stable
    argsort of the cell index, the starts by searchsorted, and near[c] the OR of the occupied cells' 3 x 3 blocks;
    on clouds, rings, points on a lattice (many in one cell) and a stack of one point, at the three grid levels."""
    rng = np.random.default_rng(7)
    for trial in range(60):
        n = int(rng.integers(1, 3000))
        kind = trial % 4
        if kind == 0:
            P = rng.normal(size=(n, 2)) * rng.uniform(0.1, 100.0)
        elif kind == 1:
            a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
            P = np.column_stack([np.cos(a), np.sin(a)]) * rng.uniform(1.0, 200.0)
        elif kind == 2:
            P = np.round(rng.uniform(0.0, 10.0, size=(n, 2)), 1)
        else:
            P = np.zeros((n, 2)) + rng.normal(size=2)
        g = nz.VertexGrid(P, P, np.abs(rng.normal(size=n)) * rng.uniform(1e-3, 2.0), (1.0, 3.0, 9.0)[trial % 3])
        ix = np.minimum(((P[:, 0] - g.origin[0]) / g.h).astype(np.int64), g.nx - 1)
        iy = np.minimum(((P[:, 1] - g.origin[1]) / g.h).astype(np.int64), g.ny - 1)
        cell = ix * g.ny + iy
        order = np.argsort(cell, kind="stable")
        start = np.searchsorted(cell[order], np.arange(g.nx * g.ny + 1))
        occ = np.pad((np.diff(start) > 0).reshape(g.nx, g.ny), 1)
        near = np.zeros((g.nx, g.ny), bool)
        for dx in range(3):
            for dy in range(3):
                near |= occ[dx:dx + g.nx, dy:dy + g.ny]
        assert g.items.dtype == np.int64 and g.start.dtype == np.int64 and g.near.dtype == np.bool_
        assert np.array_equal(g.items, order) and np.array_equal(g.start, start)
        assert np.array_equal(g.near, near.ravel())


def test_grid_levels_are_cached_and_three_times_coarser():
    o = Outline([SQUARE10], 0.5)
    g0, g1 = nz.grid_of(o), nz.grid_of(o, 1)
    assert nz.grid_of(o, 0) is g0 and nz.grid_of(o, 1) is g1 and g1 is not g0
    assert g0.h == 4.0 and g1.h == 12.0 and sorted(o._vertex_grids) == [0, 1]
    # the level: the coarsest whose side is at most a quarter of the distance (4 h0 = 16 mm), never above MAX_LEVEL;
    # one coarser where its FAR_CELLS (6) cells are less than 1.25 times the distance (19 mm: 24 < 23.75 no; 20 mm:
    # 24 < 25, level 1; 48 - 1e-9: level 0's 24 < 60, level 1; 48 mm: level 1's 72 < 60 no; 60 mm: 72 < 75, level 2)
    ds = (1.0, 16.0, 19.0, 20.0, 16.0 * 3 - 1e-9, 48.0, 60.0, 16.0 * 9.5, 16.0 * 27 * 1.01, 16.0 * 3 ** 6)
    assert [nz._level_for(o, d) for d in ds] == [0, 0, 0, 1, 1, 1, 2, 2, 3, 4]
    assert nz.FAR_CELLS == 6.0 and nz.MAX_LEVEL == 4
    # a fine grid (h0 = 0.04 mm): 1 mm is 6.25 times 4 h0, level 1, whose 6 cells (0.72 mm) fall short of 1.25: 2
    fine = Outline([_rect(0, 0, 1, 1)], 0.005)
    assert nz.grid_of(fine).h == pytest.approx(0.04, abs=1e-15) and nz._level_for(fine, 1.0) == 2


def test_bodies_a_few_cells_apart_are_searched_in_a_grid_after_the_first_step(monkeypatch):
    """30 mm apart (h0 = 4 mm: more than the 6 cells of level 0, the level a quarter of the distance asks for): the
    first search is the KD-tree's, the next four run in level 1's grid (before, each was the tree's again), each
    distance the tree's to the bit."""
    calls = []
    tree = dz.min_dist_points_to

    def counted(P, tgt, src):
        calls.append(1)
        return tree(P, tgt, src)

    monkeypatch.setattr(dz, "min_dist_points_to", counted)
    tgt = Outline([SQUARE10], 0.5)
    src = Outline([_rect(0, 0, 1, 1)], 0.5)
    for k in range(5):
        P = src.points + (40.0 + 0.1 * k, 4.0 + 0.2 * k)
        d, i, q = nz.nearest_edge(P, tgt, src)
        assert (d, i) == tree(P, tgt, src)[:2] and d == pytest.approx(30.0 + 0.1 * k, abs=1e-12)
    assert len(calls) == 1 and sorted(tgt._vertex_grids) == [0, 1]


def test_the_compiled_search_prunes_about_the_box_centre():
    """A long bar (x -1 .. 21, y -1 .. 1; box centre (10, 0)) and three points: 0.5 right of its end, 0.9 above its
    middle near x = 0, 4 above it: the nearest is the first (brute force)."""
    bar = _rect(-1, -1, 21, 1)
    tgt = Outline([bar], 1.0)
    src = Outline([np.array([[21.5, 0.0], [0.0, 1.9], [0.0, 5.0]])], 100.0)
    want = _brute_nearest(src.points, bar)
    assert want[0] == pytest.approx(0.5, abs=1e-12)
    d, i, q = nz.nearest_edge(src.points, tgt, src)
    assert d == pytest.approx(0.5, abs=1e-12) and src.points[i].tolist() == [21.5, 0.0]
    assert q == pytest.approx(np.array([21.0, 0.0]), abs=1e-12)


def test_nearest_edge_remembers_the_distance_for_the_next_grid():
    """Far apart (the tree's answer), then the same two outlines again: the second search runs in the grid of the
    level the first distance asks for."""
    tgt = Outline([SQUARE10], 0.5)
    src = Outline([_rect(0, 0, 1, 1)], 0.5)
    P = src.points + (40.0, 4.0)
    d, i, q = nz.nearest_edge(P, tgt, src)
    assert d == pytest.approx(30.0, abs=1e-12) and tgt._nearest_hints == {id(src): d}
    assert sorted(tgt._vertex_grids) == [0]
    d2, _, _ = nz.nearest_edge(P, tgt, src)
    assert d2 == d and sorted(tgt._vertex_grids) == [0, nz._level_for(tgt, 30.0)] == [0, 1]
    # near (2.5 mm: the grid's own answer), the hint follows
    d3, _, _ = nz.nearest_edge(src.points + (12.5, 4.0), tgt, src)
    assert d3 == pytest.approx(2.5, abs=1e-12) and tgt._nearest_hints == {id(src): d3}


# ---------------------------------------------------------------------------------------------------------------
# sweep2d.py: the records, the pose pairs, a tie of the two directions and the windowed sweep, by hand
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import sweep2d as s2  # noqa: E402
from propulsor.checks.motion.poses import Pose  # noqa: E402


def test_sweep_result_records_in_full_both_sides_of_their_limits():
    tol = policy.OVERLAP_AREA_TOL_MM2
    r = s2.SweepResult(np.array([0.1, 0.2, 0.3]), np.array([-0.1, -0.2, -0.3]), np.array([0.0, tol, 0.5 * tol]),
                       np.array([0.5, 0.25, 0.75]), np.array([[1.0, 2.0], [3.0, 4.0], [0.0, 0.0]]),
                       np.array([[1.0, 2.0], [5.0, 8.0], [0.0, 0.0]]), 0.25, "gear")
    assert (r.n_steps, r.max_overlap, r.step_max_overlap, r.min_clearance, r.step_min_clearance) == (3, tol, 1, 0.25, 1)
    assert r.interfering_steps.tolist() == []
    w = r.where_min_clearance()
    assert set(w) == {"step", "angle_a", "angle_b", "point", "clearance"}
    assert (w["step"], w["angle_a"], w["angle_b"], w["clearance"]) == (1, 0.2, -0.2, 0.25)
    assert w["point"].tolist() == [4.0, 6.0]
    c = r.checks()
    assert [(x.name, x.passed, x.value, x.limit, x.unit) for x in c] == [
        ("gear.overlap_area", True, tol, tol, "mm^2"), ("gear.min_clearance", True, 0.25, 0.25, "mm")]
    assert c[0].message == "max overlap 1e-06 mm^2 at step 1 (angles 0.200000, -0.200000 rad); 0 of 3 steps interfere"
    assert c[1].message == "min clearance 0.25 mm at step 1 near (4.0000, 6.0000)"
    # just beyond both limits
    r.overlap_area[2] = 1.5 * tol
    r.clearance_limit = float(np.nextafter(0.25, 1.0))
    c = r.checks()
    assert (c[0].passed, c[1].passed) == (False, False) and r.interfering_steps.tolist() == [2]
    assert c[0].message == ("max overlap 1.5e-06 mm^2 at step 2 (angles 0.300000, -0.300000 rad); "
                            "1 of 3 steps interfere")
    r.clearance_limit = None
    assert [x.name for x in r.checks()] == ["gear.overlap_area"]


def test_sweep_pair_pose_refusals_in_full_and_a_single_pose_stretched():
    sq = [SQUARE10]
    assert _msg(s2.sweep_pair, sq, np.zeros((2, 3)), sq, Pose()) == (
        "poses_a = (2, 3): must be Poses or an (n, 2, 3) array")
    assert _msg(s2.sweep_pair, sq, Pose(), sq, np.zeros((2, 3))) == (
        "poses_b = (2, 3): must be Poses or an (n, 2, 3) array")
    three = [Pose(0.0, (0.0, 0.0), (20.0 + k, 0.0)) for k in range(3)]
    assert _msg(s2.sweep_pair, sq, three, sq, three[:2]) == "poses_b = 2: must have as many steps as poses_a (3)"
    # a list of one pose after a list of three: held for all three steps; a bare Pose either way round
    r = s2.sweep_pair(sq, three, sq, [Pose()], max_segment=100.0, name="pair")
    assert r.name == "pair" and r.clearance.tolist() == [10.0, 11.0, 12.0]
    r = s2.sweep_pair(sq, Pose(), sq, three, max_segment=100.0)
    assert r.name == "motion" and r.clearance.tolist() == [10.0, 11.0, 12.0] and r.angle_a.tolist() == [0.0] * 3


def test_a_tie_of_the_two_directions_reports_b_vertex_on_a_edge():
    """B (the square moved by (12, 3)) has its corner (12, 3) 2 mm from A's right edge, and A's corner (10, 10) lies
    2 mm from B's left edge: the first direction (B's vertices to A's edges) is reported."""
    r = s2.sweep_pair([SQUARE10], Pose(), [SQUARE10], [Pose(0.0, (0.0, 0.0), (12.0, 3.0))], max_segment=100.0)
    assert r.clearance[0] == 2.0
    assert r.point_a[0].tolist() == [10.0, 3.0] and r.point_b[0].tolist() == [12.0, 3.0]


def test_windowed_sweep_of_a_diamond_over_a_long_block_by_hand():
    """A: the block 0..100 x 0..10, held at a pose (turned 0.3 rad, moved (5, -2)); B: a diamond of half diagonal
    sqrt 2 (its lowest corner sqrt 2 below its centre) moving 0.5 mm a step along the block at heights giving the
    gaps g (reach 1): the common area is the triangle h^2 below the block's top (h = -g), the clearance g or -h
    (the corner, h deep in A), at most reach; runs whose window (sqrt 2 + reach) / cos(pi / 48) about the centres
    misses A report reach at the run's first centre."""
    th, off = 0.3, np.array([5.0, -2.0])
    R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    world = lambda p: R @ np.asarray(p, float) + off  # noqa: E731
    s = math.sqrt(2.0)
    diamond = np.array([[0.0, -s], [s, 0.0], [0.0, s], [-s, 0.0]])
    g = [3.0, 3.0, 0.5, 0.3, -0.2, -0.3, 0.05, 1.003, 1.2, 3.0, 3.0, 0.998]
    x = [10.0 + 0.5 * k for k in range(len(g))]
    x[10] = x[9] + 1.0  # 1 mm on: beyond half B's radius, a new run
    x[11] = x[10] + 5.0
    yc = [10.0 + s + gk for gk in g]
    poses_b = [Pose(th, (0.0, 0.0), tuple(world((xk, yk)))) for xk, yk in zip(x, yc)]
    r = s2.sweep_pair_windowed([_rect(0, 0, 100, 10)], Pose(th, (0.0, 0.0), tuple(off)), [diamond], poses_b, 1.0,
                               clearance_limit=0.0, name="win")
    assert r.name == "win" and r.clearance_limit == 0.0 and r.angle_a.tolist() == [th] * 12
    assert r.angle_b == pytest.approx([th] * 12, abs=1e-15)
    area = [max(0.0, -gk) ** 2 for gk in g]
    clear = [-(-gk) if gk < 0 else min(gk, 1.0) for gk in g]
    assert r.overlap_area == pytest.approx(area, abs=1e-8)
    assert r.clearance == pytest.approx(clear, abs=1e-8)
    # gaps within reach (0.998: its window reaches 0.005 below A's top): B's corner and the point of A's top below it
    for k in (2, 3, 6, 11):
        assert r.point_a[k] == pytest.approx(world((x[k], 10.0)), abs=1e-8)
        assert r.point_b[k] == pytest.approx(world((x[k], yc[k] - s)), abs=1e-8)
    for k in (4, 5):  # overlapping: both points the corner inside A
        assert r.point_a[k] == pytest.approx(world((x[k], yc[k] - s)), abs=1e-8)
        assert r.point_b[k] == pytest.approx(world((x[k], yc[k] - s)), abs=1e-8)
    # runs apart from A: steps 0 and 1 (one run: 0.5 mm apart), steps 9 and 10 alone: the run's first centre
    for k, k0 in ((0, 0), (1, 0), (9, 9), (10, 10)):
        assert r.point_a[k] == pytest.approx(world((x[k0], yc[k0])), abs=1e-12)
        assert r.point_b[k] == pytest.approx(world((x[k0], yc[k0])), abs=1e-12)
    assert r.step_min_clearance == 5 and [c.passed for c in r.checks()] == [False, False]
    # reach must be positive
    assert _msg(s2.sweep_pair_windowed, [SQUARE10], Pose(), [diamond], [Pose()], 0.0) == "reach = 0.0: must be > 0 mm"


def test_windowed_sweep_keeps_a_triangle_and_samples_profiles_to_chord_tol():
    """A triangle (legs 3) inside the window (reach 5) comes out whole; a diamond's edge parallel to its hypotenuse,
    (5 - sqrt 2 + 1.5 - 3) / sqrt 2 from it.  Two circles (r 50 and 2, their centres 52.5 apart): 0.5 plus at
    most the chord sags of the sampled circles (below chord_tol 1e-4 each)."""
    s = math.sqrt(2.0)
    diamond = np.array([[0.0, -s], [s, 0.0], [0.0, s], [-s, 0.0]])
    tri = np.array([[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]])
    r = s2.sweep_pair_windowed([tri], Pose(), [diamond], [Pose(0.0, (0.0, 0.0), (5.0, 1.5))], 5.0)
    assert r.name == "motion" and r.clearance_limit is None
    assert r.clearance[0] == pytest.approx((5.0 - s + 1.5 - 3.0) / s, abs=1e-8) and r.overlap_area[0] == 0.0
    big, small = Profile(circle_loop(50.0)), Profile(circle_loop(2.0))
    a = 0.123  # off the circles' first vertices: the sampled polygons lie inside the circles, by at most the sags
    r = s2.sweep_pair_windowed(big, Pose(), small, [Pose(0.0, (0.0, 0.0), (52.5 * math.cos(a), 52.5 * math.sin(a)))],
                               1.0, 1e-4)
    assert 0.5 <= r.clearance[0] <= 0.5 + 2e-4


# ---------------------------------------------------------------------------------------------------------------
# sweep3d.py: boxes of 10 mm moved by hand (volumes and gaps by hand), the refusals in full, the boxes' skip
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion import sweep3d as s3  # noqa: E402
from test_motion import _box, _translation  # noqa: E402


def test_sweep3d_refusals_in_full():
    box = _box(10, 10, 10)
    V, F = box
    e4 = np.eye(4)
    assert _msg(s3.sweep_solids_3d, (V, F[:-2]), e4, box, e4) == (
        "mesh_a = 'Error.NotManifold': must be a closed, oriented 2-manifold mesh")
    assert _msg(s3.sweep_solids_3d, box, e4, (V, F[:-2]), e4) == (
        "mesh_b = 'Error.NotManifold': must be a closed, oriented 2-manifold mesh")
    assert _msg(s3.sweep_solids_3d, box, np.zeros((4, 3)), box, e4) == (
        "poses_a = (1, 4, 3): must be (4, 4) or (n, 4, 4) matrices")  # one matrix: shown as a stack of one
    assert _msg(s3.sweep_solids_3d, box, e4, box, np.zeros((2, 4, 3))) == (
        "poses_b = (2, 4, 3): must be (4, 4) or (n, 4, 4) matrices")
    bad = np.array([e4, e4])
    bad[1, 0, 3] = np.nan
    assert _msg(s3.sweep_solids_3d, box, e4, box, bad) == "poses_b = 'non-finite': poses must be finite"
    assert _msg(s3.sweep_solids_3d, box, bad, box, e4) == "poses_a = 'non-finite': poses must be finite"
    three, two = np.array([e4] * 3), np.array([e4] * 2)
    assert _msg(s3.sweep_solids_3d, box, three, box, two) == "poses_b = 2: must have 1 or 3 poses like poses_a"
    assert _msg(s3.sweep_solids_3d, box, two, box, three) == "poses_b = 3: must have 1 or 3 poses like poses_a"
    assert _msg(s3.sweep_solids_3d, box, e4, box, e4, search_length=0.0) == "search_length = 0.0: must be > 0 mm"
    assert _msg(s3.sweep_solids_3d, box, e4, box, e4, skip_apart=True) == "skip_apart = True: needs search_length"


def test_sweep3d_one_pose_held_and_b_left_where_it_is():
    box = _box(10, 10, 10)
    # A moved along x by 5, 8, 12 against B held at one (integer) pose: 500, 200 and 0 mm^3, B never moved
    Ta = np.array([_translation(5.0), _translation(8.0), _translation(12.0)])
    r = s3.sweep_solids_3d(box, Ta, box, np.eye(4, dtype=int))
    assert r.name == "motion3d" and r.gap is None
    assert r.overlap_volume == pytest.approx([500.0, 200.0, 0.0], abs=1e-9)
    r = s3.sweep_solids_3d(box, Ta, box, None, search_length=3.0, name="cam")
    assert r.name == "cam" and r.overlap_volume == pytest.approx([500.0, 200.0, 0.0], abs=1e-9)
    assert r.gap == pytest.approx([0.0, 0.0, 2.0], abs=1e-9)
    # one pose of A against three of B
    r = s3.sweep_solids_3d(box, np.eye(4, dtype=int), box, Ta)
    assert r.overlap_volume == pytest.approx([500.0, 200.0, 0.0], abs=1e-9)


def test_sweep3d_skips_steps_whose_boxes_lie_search_length_apart():
    """search_length 2: a box gap of 2 or more is recorded as gap 2 without a boolean; 1.5 is measured; each face of
    B's box tried (B held where it is, then moved)."""
    box = _box(10, 10, 10)
    moves = [(12.0, 0.0, 0.0), (11.5, 0.0, 0.0), (0.0, 0.0, 11.5), (0.0, 0.0, -11.5), (0.0, 11.5, 0.0),
             (-11.5, 0.0, 0.0), (5.0, 0.0, 0.0), (13.0, 0.0, 0.0), (0.0, 0.0, 5.0)]
    Ta = np.array([_translation(*m) for m in moves])
    r = s3.sweep_solids_3d(box, Ta, box, None, search_length=2.0, skip_apart=True)
    assert r.gap == pytest.approx([2.0, 1.5, 1.5, 1.5, 1.5, 1.5, 0.0, 2.0, 0.0], abs=1e-9)
    assert r.overlap_volume == pytest.approx([0, 0, 0, 0, 0, 0, 500.0, 0, 500.0], abs=1e-9)
    # B moved too: A at x = 50, B at 55 (common 500 mm^3), then B back at the origin (40 apart)
    Ta = np.array([_translation(50.0)] * 3)
    Tb = np.array([_translation(55.0), np.eye(4), _translation(61.5)])
    r = s3.sweep_solids_3d(box, Ta, box, Tb, search_length=2.0, skip_apart=True)
    assert r.overlap_volume == pytest.approx([500.0, 0.0, 0.0], abs=1e-9)
    assert r.gap == pytest.approx([0.0, 2.0, 1.5], abs=1e-9)


def test_sweep3d_record_in_full_both_sides_of_the_limit():
    tol = policy.OVERLAP_VOLUME_TOL_MM3
    r = s3.Sweep3DResult(np.array([0.0, tol]), None, "cam")
    (c,) = r.checks()
    assert (c.name, c.passed, c.value, c.limit, c.unit) == ("cam.overlap_volume", True, tol, tol, "mm^3")
    assert c.message == "max overlap volume 0.001 mm^3 at step 1; 0 of 2 steps interfere"
    r = s3.Sweep3DResult(np.array([0.0, tol, 1.5 * tol]), None)
    (c,) = r.checks()
    assert (c.name, c.passed) == ("motion3d.overlap_volume", False)
    assert c.message == "max overlap volume 0.0015 mm^3 at step 2; 1 of 3 steps interfere"


def test_box_corners_and_moved_boxes_by_hand():
    from propulsor.solids.kernel import manifold
    V, F = _box(1.0, 2.0, 3.0)
    m = manifold((V + (4.0, 5.0, 6.0), F), "mesh")
    c = s3.box_corners(m)
    assert c.tolist() == [[x, y, z, 1.0] for x in (4.0, 5.0) for y in (5.0, 7.0) for z in (6.0, 9.0)]
    # a quarter turn about z: (x, y, z) -> (-y, x, z), then 1 mm up
    T = np.array([[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0]])
    lo, hi = s3.box_of(c, T)
    assert lo.tolist() == [-7.0, 4.0, 7.0] and hi.tolist() == [-5.0, 5.0, 10.0]
    assert s3.box_gap((lo, hi), (np.array([-4.0, 0.0, 0.0]), np.array([0.0, 4.0, 7.0]))) == 1.0
    assert s3.box_gap((lo, hi), (np.array([-1.0, 6.0, 12.0]), np.array([0.0, 8.0, 13.0]))) == pytest.approx(
        math.sqrt(16.0 + 1.0 + 4.0), abs=1e-15)


# ---------------------------------------------------------------------------------------------------------------
# mesh_load.py: every tooth pair within reach at one phase, on the bar and blocks (contact points, normals and
# lever arms by hand)
# ---------------------------------------------------------------------------------------------------------------

from propulsor.checks.motion.mesh_load import phase_contacts  # noqa: E402


def _blocks_over_the_bar(mirror=False):
    """Three blocks (driver axis 8 mm off) with their lower-right corners at q1 = (7, 1.8), q2 = (4, 1.4), q3 = (9.5,
    2.4) (mirrored: below the bar): the bar's upper edge, turned back, meets q1 first (e1 = 0.1825), then q3 (e3 =
    0.1964) and q2 (e2 = 0.2184); q1's block's lower-left corner (5, 1.8) at 0.2297."""
    qs = [np.array([7.0, 1.8]), np.array([4.0, 1.4]), np.array([9.5, 2.4])]
    blocks = [_square(q[0] - 1.0 - 8.0, q[1] + 1.0) for q in qs]
    teeth = [2.0, 2.2, 1.1]
    if mirror:
        blocks = [b[::-1] * (1.0, -1.0) for b in blocks]
        teeth = [-t for t in teeth]
    return PairOutlines(Outline(blocks, 100.0), Outline([BAR], 100.0), 8.0, teeth, [0.0]), qs


def test_phase_contacts_lists_the_pairs_within_the_window_by_their_gaps():
    po, (q1, q2, q3) = _blocks_over_the_bar()
    e1, e2, e3 = (_edge_meets_corner(q) for q in (q1, q2, q3))
    assert e1 < e3 < e2 < e1 + 0.05
    te, cs = phase_contacts(po, 0.0, 0.0, -e1, 0.05, DRIVE)
    assert te == pytest.approx(-e1, abs=1e-12)
    # q3's force would not pass torque (its line of action passes beyond the driver's axis: l1 < 0): left out
    assert [(c.driver_tooth, c.driven_tooth, c.edge_of, c.vertex) for c in cs] == [(0, 0, "driven", 1),
                                                                                    (1, 0, "driven", 5)]
    for c, q, e, gap in zip(cs, (q1, q2), (e1, e2), (0.0, e2 - e1)):
        u, n = np.array([math.cos(e), math.sin(e)]), np.array([math.sin(e), -math.cos(e)])  # the edge, its normal in
        assert c.gap == pytest.approx(gap, abs=1e-12)
        assert c.x == pytest.approx(q, abs=1e-9) and c.p_driver == pytest.approx(q - (8.0, 0.0), abs=1e-9)
        assert c.p_driven == pytest.approx((float(q @ u), 0.5), abs=1e-9)
        assert c.n == pytest.approx(n, abs=1e-12)
        assert c.l2 == pytest.approx(math.sqrt(q @ q - 0.25), abs=1e-9)
        assert c.l1 == pytest.approx((8.0 - q[0]) * math.cos(e) - q[1] * math.sin(e), abs=1e-9)
    assert (8.0 - q3[0]) * math.cos(e3) - q3[1] * math.sin(e3) < 0
    # a window of 0.03: q2 (0.036 on) is not listed
    te, cs = phase_contacts(po, 0.0, 0.0, -e1, 0.03, DRIVE)
    assert [(c.driver_tooth, c.gap) for c in cs] == [(0, 0.0)]
    # started 0.15 of the margin short of the contact (the first hit within 0.2 margin): searched again from 4 margins
    m = policy.CONTACT_TRACK_MARGIN_RAD
    te, cs = phase_contacts(po, 0.0, 0.0, -e1 - 0.85 * m, 0.05, DRIVE)
    assert te == pytest.approx(-e1, abs=1e-12) and len(cs) == 2
    # the phase moves the start: at phi = 0.01 (the driven turned 0.01 further) the same contact, te = -e1 - 0.01
    te, cs = phase_contacts(po, 0.01, 0.0, -e1 - 0.01, 0.05, DRIVE)
    assert te == pytest.approx(-e1 - 0.01, abs=1e-12) and cs[0].x == pytest.approx(q1, abs=1e-9)
    # the driven teeth named across +-pi: the contacts (at 0.069 and 0.118 rad) lie 0.08 and 0.13 from 2 pi - 0.01,
    # 2.9 from 3.0
    po2 = PairOutlines(po.drv, po.dvn, 8.0, po.driver_teeth, [2 * math.pi - 0.01, 3.0])
    assert [c.driven_tooth for c in phase_contacts(po2, 0.0, 0.0, -e1, 0.05, DRIVE)[1]] == [0, 0]
    # turned on (reverse), nothing within reach
    te, cs = phase_contacts(po, 0.0, 0.0, -e1, 0.05, REVERSE)
    assert math.isnan(te) and cs == []


def test_phase_contacts_in_reverse_is_the_mirror_image():
    po, (q1, q2, q3) = _blocks_over_the_bar(mirror=True)
    e1, e2 = _edge_meets_corner(q1), _edge_meets_corner(q2)
    te, cs = phase_contacts(po, 0.0, 0.0, e1, 0.05, REVERSE)
    assert te == pytest.approx(e1, abs=1e-12)
    assert [(c.driver_tooth, c.driven_tooth, c.edge_of) for c in cs] == [(0, 0, "driven"), (1, 0, "driven")]
    for c, q, e, gap in zip(cs, (q1, q2), (e1, e2), (0.0, e2 - e1)):
        qm = q * (1.0, -1.0)
        assert c.gap == pytest.approx(gap, abs=1e-12) and c.x == pytest.approx(qm, abs=1e-9)
        assert c.n == pytest.approx((math.sin(e), math.cos(e)), abs=1e-12)
        assert c.l2 == pytest.approx(math.sqrt(q @ q - 0.25), abs=1e-9)
        assert c.l1 == pytest.approx((8.0 - q[0]) * math.cos(e) - q[1] * math.sin(e), abs=1e-9)


def test_each_tooth_pair_keeps_its_first_hit_in_the_order_of_those_hits():
    """The pairs a phase lists: each (driver tooth, driven tooth) once, by its hit of least gap (the first of equal
    ones), in the order of those hits, as a dict filled over the hits sorted by gap keeps them; on random hits whose
    tooth indices share sums and differences (meshing pairs (i, j), (i + 1, j - 1)) and whose gaps tie; numpy's and
    the compiled one (_firsts_nb)."""
    from propulsor.checks.motion.mesh_load import _first_of_each_pair, _firsts_nb

    rng = np.random.default_rng(4)
    for trial in range(400):
        n = int(rng.integers(1, 60))
        d = rng.choice(np.linspace(0.0, 0.01, int(rng.integers(1, 12))), n)
        t_drv = rng.integers(0, 5, n)
        t_dvn = rng.integers(0, 5, n)
        want = {}
        for k in np.argsort(d, kind="stable"):
            want.setdefault((int(t_drv[k]), int(t_dvn[k])), int(k))
        got = _first_of_each_pair(d, t_drv, t_dvn)
        assert got.tolist() == list(want.values()), (d, t_drv, t_dvn)
        # and compiled (phase_contacts' own): the same choice, ties of gap and of pair included
        assert _firsts_nb(d, t_drv.astype(np.int64), t_dvn.astype(np.int64)).tolist() == got.tolist()


def test_phase_contacts_of_a_driven_corner_on_a_turned_driver_edge():
    """The bar's tip corner (10, 0.5) on the slanted lower edge (-5, 2.2) -> (-3, 2.0) of a block (driver axis 14 mm
    off, turned 0.05 rad; the edge is the block's third): the contact point P where the tip's circle meets the turned
    edge, the force on the driven along minus the edge's left normal, turned by theta; the lever arms its moments
    about both axes."""
    th = 0.05
    R, P, e = _tip_on_turned_edge((-5.0, 2.2), (-3.0, 2.0), th)
    block = np.array([[-3.0, 4.2], [-5.0, 4.2], [-5.0, 2.2], [-3.0, 2.0]])
    po = PairOutlines(Outline([block], 100.0), Outline([BAR], 100.0), 14.0, [2.6006, 2.7506],
                      [0.0, 0.3])
    te, cs = phase_contacts(po, 0.0, th, -e, 0.025, DRIVE)
    assert te == pytest.approx(-e, abs=1e-12) and len(cs) == 2
    c, c2 = cs
    assert (c.driver_tooth, c.driven_tooth, c.edge_of, c.vertex, c.gap) == (0, 0, "driver", 2, 0.0)
    assert c.x == pytest.approx(P, abs=1e-9) and c.p_driven.tolist() == [10.0, 0.5]
    assert c.p_driver == pytest.approx(R.T @ (P - (14.0, 0.0)), abs=1e-9)
    n = R @ (-np.array([0.2, 2.0]) / math.hypot(2.0, 0.2))
    assert c.n == pytest.approx(n, abs=1e-12)
    assert c.l2 == pytest.approx(-(P[0] * n[1] - P[1] * n[0]), abs=1e-9)
    assert c.l1 == pytest.approx((P[0] - 14.0) * n[1] - P[1] * n[0], abs=1e-9)
    # then the block's lower-left corner Q (driver frame (-5, 2.2): tooth 1 at 2.7506) on the bar's upper edge
    Q = np.array([14.0, 0.0]) + R @ (-5.0, 2.2)
    eq = _edge_meets_corner(Q)
    assert (c2.driver_tooth, c2.driven_tooth, c2.edge_of, c2.vertex) == (1, 0, "driven", 2)
    assert c2.gap == pytest.approx(eq - e, abs=1e-12) and c2.x == pytest.approx(Q, abs=1e-9)
    assert c2.n == pytest.approx((math.sin(eq), -math.cos(eq)), abs=1e-12)
    assert c2.l2 == pytest.approx(math.sqrt(Q @ Q - 0.25), abs=1e-9)
    assert c2.l1 == pytest.approx((14.0 - Q[0]) * math.cos(eq) - Q[1] * math.sin(eq), abs=1e-9)
    # a window just short of its gap (0.0195): the first pair alone
    assert [c.driver_tooth for c in phase_contacts(po, 0.0, th, -e, 0.019, DRIVE)[1]] == [0]


@pytest.mark.parametrize("run", [5, 7])
def test_resolve_contact_in_short_compiled_runs_is_the_one_long_run_bit_for_bit(monkeypatch, run):
    """The grid measured in runs of `run` positions (each run's first position searched from the last contact of the
    run before): the same te, states, evaluations and progress ticks as in one run, and each run seeded so."""
    from propulsor.checks.motion import contact_events

    po, _ = _gear_pair()
    span = 2 * math.pi / Z

    def law(**kw):
        ticks = []
        c = resolve_contact(po, _one_to_one, 0.0, span, DRIVE, step_driver_rad=math.radians(1.0),
                            tick=lambda done, total: ticks.append((done, total)), **kw)
        return c, ticks

    one, ticks_one = law()
    calls = []
    real = contact_events.track

    def recorded(pair, phis, thetas, direction, seeds, seed_phis, chained, *reuse):
        r = real(pair, phis, thetas, direction, seeds, seed_phis, chained, *reuse)
        calls.append((list(map(float, phis)), list(map(float, seeds)), list(map(float, seed_phis)), chained,
                      r[0].tolist()))
        return r

    monkeypatch.setattr(contact_events, "_TRACK_RUN", run)
    monkeypatch.setattr(contact_events, "track", recorded)
    many, ticks_many = law()
    for name in ("phi", "theta", "te", "kind", "driver_tooth", "driven_tooth"):
        assert getattr(many, name).tobytes() == getattr(one, name).tobytes(), name
    assert many.evaluations == one.evaluations == len(one.phi) and ticks_many == ticks_one
    grid = [c for c in calls if c[3]]
    assert [len(c[0]) for c in grid] == [run] * (24 // run) + ([24 % run] if 24 % run else [])
    assert math.isnan(grid[0][1][0]) and math.isnan(grid[0][2][0])
    for before, now in zip(grid[:-1], grid[1:]):
        assert now[1] == [before[4][-1]] and now[2] == [before[0][-1]]  # the last contact of the run before


def test_sweep3d_gaps_equal_min_gap_over_the_whole_search_on_a_filleted_union_whatever_branch_finds_them(monkeypatch):
    """Each step's gap equals manifold3d's min_gap within the whole search length, bit for bit, while most steps are
    found cheaper (:class:`sweep3d._Gaps`): a filleted CadQuery union (a U: a plate with two posts) swept past a
    filleted cylinder that comes from afar (the hulls W apart: no search of the bodies), closes in steadily (each gap
    sought within the last plus the guess), jumps away and back by more than the guess (sought again within W), sits
    in the U's mouth (inside the U's hull, apart from the U: the hulls' test must not answer) and runs into a post."""
    import cadquery as cq
    import manifold3d as m3d

    from propulsor.export.mesh import to_trimesh
    from propulsor.solids.kernel import manifold

    u = (cq.Workplane("XY").box(60.0, 20.0, 10.0).faces(">Z").workplane()
         .pushPoints([(-25.0, 0.0), (25.0, 0.0)]).rect(10.0, 20.0).extrude(30.0).edges("|Y").fillet(2.0).val())
    pin = cq.Workplane("XY").circle(6.0).extrude(20.0).edges().fillet(1.5).val()
    U, P = to_trimesh(u, chord_tol=0.05), to_trimesh(pin, chord_tol=0.05)
    W = 10.0
    # the pin (radius 6, z 8 .. 28) beside the U (x -30 .. 30; the plate's top at z 5, the posts' inner faces at x
    # +-20): far off, closing in on a post's outer face, out of reach and back (the hulls 7 mm apart: searched in
    # full), far off again, in the U's mouth (3 mm above the plate, inside the U's hull), into a post
    xs = [200.0, 120.0, 60.0, 45.0, 44.0, 43.2, 42.9, 60.0, 43.0, 42.0, 200.0, 0.0, 4.0, -14.5]
    T = np.array([_translation(x, 0.0, 8.0) for x in xs])
    calls = []
    real = m3d.Manifold.min_gap

    def counted(a, b, s):
        calls.append((a.num_tri(), float(s)))
        return real(a, b, s)

    monkeypatch.setattr(m3d.Manifold, "min_gap", counted)
    r = s3.sweep_solids_3d(U, np.eye(4), P, T, search_length=W)
    monkeypatch.undo()
    A, B = manifold(U, "u"), manifold(P, "pin")
    full = [A.min_gap(B.transform(np.ascontiguousarray(t[:3, :4])), W) for t in T]
    assert r.gap.tolist() == full  # bit for bit
    assert full[0] == W and full[-1] == 0.0 and full[11] == pytest.approx(3.0, abs=0.01)
    assert 0.0 < full[6] < full[5] < full[4] < full[3] < W and full[7] == W and full[8] == pytest.approx(7.0, abs=0.01)
    body, hull = A.num_tri(), A.hull().num_tri()
    whole = [s for n, s in calls if n == body and s == W]
    guessed = [s for n, s in calls if n == body and s < W]
    hulls = [s for n, s in calls if n == hull]
    assert len(hulls) >= 2 and len(guessed) >= 4  # the far steps by the hulls alone, the close ones by a guess
    # the body searched within W only at 45 (the hulls 9 apart), 43.2 (the guess reaching W), 60 and 200 (the guess
    # failing), 43 (the hulls 7 apart) and 0 (inside the U's hull)
    assert len(whole) == 6
    assert r.overlap_volume[-1] > 10.0 and r.overlap_volume[:-1].tolist() == [0.0] * (len(xs) - 1)
