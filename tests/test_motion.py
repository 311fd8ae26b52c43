"""Motion checks (checks/motion.py): overlap, clearance, backlash, transmission error, contact count.

All geometry is made here from first principles (circles, squares, exact involute
spur gears), so the expected numbers are analytic and independent of the gear
modules of the package.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor import policy
from propulsor.checks.motion import (
    Outline,
    Pose,
    outline,
    poses_from_angles,
    sweep_pair,
    sweep_solids_3d,
    transmission_sweep,
)
from propulsor.errors import InputError
from propulsor.geometry.profile import Profile, circle_loop, polygon_loop

ALPHA = math.radians(20.0)


# ---------------------------------------------------------------------------
# independent geometry
# ---------------------------------------------------------------------------


def inv(a: float) -> float:
    return math.tan(a) - a


def involute_teeth(z: int, m: float, half_pitch_angle: float, r_in: float, r_out: float,
                   n_flank: int = 300, sag: float = 1e-6) -> np.ndarray:
    """Closed polyline of z involute "teeth" (ISO 21771 involute, alpha = 20 deg, base radius m z cos(alpha) / 2).

    Each tooth has the half angle half_pitch_angle on the pitch circle r = m z / 2
    and runs from r_in (root circle, radial line below the base circle) to r_out
    (tip circle); tooth 0 is centred on the +x axis.  Flank vertices lie exactly
    on the involute, equally spaced in arc length.  Used for an external gear
    (teeth) and for the hole of an internal gear (its tooth spaces).
    """
    r = m * z / 2
    r_b = r * math.cos(ALPHA)
    t0 = math.sqrt(max(0.0, (r_in / r_b) ** 2 - 1))
    t1 = math.sqrt((r_out / r_b) ** 2 - 1)  # roll angles at both ends
    t = np.sqrt(np.linspace(t0**2, t1**2, n_flank))  # equal involute arc length (s = r_b t^2 / 2)
    rho = r_b * np.sqrt(1 + t**2)
    half = half_pitch_angle + inv(ALPHA) - (t - np.arctan(t))  # half tooth angle at radius rho
    if r_in < r_b:
        rho, half = np.concatenate([[r_in], rho]), np.concatenate([[half[0]], half])

    def arc(radius, a0, a1):
        da = 2 * math.acos(1 - sag / radius)
        return np.linspace(a0, a1, max(2, int(math.ceil(abs(a1 - a0) / da)) + 1))[1:-1]

    pts = []
    for k in range(z):
        g = 2 * math.pi * k / z
        pts.append(np.c_[rho * np.cos(g - half), rho * np.sin(g - half)])
        a = arc(r_out, g - half[-1], g + half[-1])
        pts.append(np.c_[r_out * np.cos(a), r_out * np.sin(a)])
        pts.append(np.c_[rho[::-1] * np.cos(g + half[::-1]), rho[::-1] * np.sin(g + half[::-1])])
        a = arc(r_in, g + half[0], g + 2 * math.pi / z - half[0])
        pts.append(np.c_[r_in * np.cos(a), r_in * np.sin(a)])
    return np.vstack(pts)


def involute_gear(z: int, m: float, j_n: float = 0.0, n_flank: int = 300, sag: float = 1e-6):
    """Exact external involute spur gear (x = 0, h_a* = 1, c* = 0.25, no fillet).

    Every tooth is thinned by j_n/2 measured along the normal (= along the line of
    action), i.e. by j_n / (2 cos alpha) on the pitch circle.
    """
    r = m * z / 2
    s = math.pi * m / 2 - j_n / (2 * math.cos(ALPHA))  # tooth thickness on the pitch circle
    pts = involute_teeth(z, m, s / (2 * r), r - 1.25 * m, r + m, n_flank, sag)
    return pts, dict(r=r, r_b=r * math.cos(ALPHA), r_a=r + m, r_f=r - 1.25 * m)


def ring_gear(z: int, m: float, j_n: float = 0.0, rim: float = 10.0, n_flank: int = 400, sag: float = 1e-6):
    """Internal spur gear: rim circle + a hole whose "teeth" are the ring's tooth spaces.

    Ring roots at r + 1.25 m; ring tips at r - m + 7.6 m / z (the tip circle of
    an internal gear is raised by 15.2 m / z on the diameter, the usual correction
    that keeps the ring tip off the pinion's base circle region).  Each ring tooth
    thinned by j_n/2 normal, i.e. each space widened by j_n / (2 cos alpha) on the
    pitch circle.  Tooth space 0 is centred on the +x axis.
    """
    r = m * z / 2
    r_a = r - m + 7.6 * m / z
    e = math.pi * m / 2 + j_n / (2 * math.cos(ALPHA))  # space width on the pitch circle
    hole = involute_teeth(z, m, e / (2 * r), r_a, r + 1.25 * m, n_flank, sag)
    t = np.linspace(0, 2 * np.pi, 4000, endpoint=False)
    rim_loop = np.c_[(r + 1.25 * m + rim) * np.cos(t), (r + 1.25 * m + rim) * np.sin(t)]
    return [rim_loop, hole[::-1]], dict(r=r, r_b=r * math.cos(ALPHA), r_a=r_a, r_f=r + 1.25 * m)


def epsilon_alpha(z1, z2, m):
    """Transverse contact ratio of a standard external pair (ISO 21771 eq. for x = 0, a = a_w)."""
    r1, r2 = m * z1 / 2, m * z2 / 2
    a = r1 + r2
    g = (math.sqrt((r1 + m) ** 2 - (r1 * math.cos(ALPHA)) ** 2)
         + math.sqrt((r2 + m) ** 2 - (r2 * math.cos(ALPHA)) ** 2) - a * math.sin(ALPHA))
    return g / (math.pi * m * math.cos(ALPHA))


def epsilon_alpha_internal(z2, z3, m, r_a3):
    """Transverse contact ratio of an internal pair (pinion z2 with x = 0, ring z3, ring tip radius r_a3)."""
    r2, r3 = m * z2 / 2, m * z3 / 2
    a = r3 - r2
    g = (math.sqrt((r2 + m) ** 2 - (r2 * math.cos(ALPHA)) ** 2)
         - math.sqrt(r_a3**2 - (r3 * math.cos(ALPHA)) ** 2) + a * math.sin(ALPHA))
    return g / (math.pi * m * math.cos(ALPHA))


def lens_area(r1, r2, d):
    a1 = r1**2 * math.acos((d**2 + r1**2 - r2**2) / (2 * d * r1))
    a2 = r2**2 * math.acos((d**2 + r2**2 - r1**2) / (2 * d * r2))
    return a1 + a2 - 0.5 * math.sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2))


SQUARE = Profile(polygon_loop([(0, 0), (10, 0), (10, 10), (0, 10)]))


# ---------------------------------------------------------------------------
# pair sweeps: analytic cases
# ---------------------------------------------------------------------------


def test_two_circles_clearance_is_the_gap_for_every_rotation():
    tol = 1e-6
    a, b = Profile(circle_loop(10.0)), Profile(circle_loop(20.0))
    # B spins about its own centre at (31, 0): the gap stays 1.0
    res = sweep_pair(a, Pose(), b, poses_from_angles(np.linspace(0, 2 * np.pi, 13), offset=(31.0, 0.0)), tol)
    assert np.all(res.overlap_area == 0.0)
    # polylines are inscribed: the measured gap is never below the true one, and above it by < 2 chord_tol
    assert np.all(res.clearance >= 1.0 - 1e-12)
    assert np.all(res.clearance <= 1.0 + 2 * tol)
    assert np.allclose(res.point_a, [10.0, 0.0], atol=1e-2)
    assert np.allclose(res.point_b, [11.0, 0.0], atol=1e-2)
    assert res.checks()[0]["passed"]
    assert res.checks()[0]["name"].endswith("overlap_area")


def test_overlapping_circles_lens_area_and_penetration_depth():
    tol = 1e-6
    a, b = Profile(circle_loop(10.0)), Profile(circle_loop(20.0))
    res = sweep_pair(a, Pose(), b, [Pose(0.0, (0, 0), (25.0, 0.0))], tol)
    assert res.overlap_area[0] == pytest.approx(lens_area(10, 20, 25), rel=1e-5)
    # deepest overlap vertex: (10, 0) on A is 5 inside B (= r1 + r2 - d)
    assert res.clearance[0] == pytest.approx(-5.0, abs=1e-4)
    rec = res.checks()[0]
    assert not rec["passed"] and rec["value"] > policy.OVERLAP_AREA_TOL_MM2
    assert set(rec) == {"name", "passed", "value", "limit", "unit", "message"}


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(-25, 25), st.floats(-25, 25)), min_size=1, max_size=20))
def test_translated_squares_match_the_analytic_overlap_and_gap(shifts):
    s = np.array(shifts)
    res = sweep_pair(SQUARE, Pose(), SQUARE, [Pose(0.0, (0, 0), tuple(v)) for v in s])
    ox = np.maximum(0.0, 10 - np.abs(s[:, 0]))
    oy = np.maximum(0.0, 10 - np.abs(s[:, 1]))
    assert np.allclose(res.overlap_area, ox * oy, atol=1e-6)
    gx = np.maximum(0.0, np.abs(s[:, 0]) - 10)
    gy = np.maximum(0.0, np.abs(s[:, 1]) - 10)
    disjoint = ox * oy <= policy.OVERLAP_AREA_TOL_MM2
    assert np.allclose(res.clearance[disjoint], np.hypot(gx, gy)[disjoint], atol=1e-9)
    # overlapping: minus the boundary penetration = how deep a corner of one square sits in the other
    over = ~disjoint & (np.abs(s[:, 0]) > 1e-6) & (np.abs(s[:, 1]) > 1e-6)  # no shared edge lines
    depth = np.minimum(np.minimum(ox, oy), np.minimum(np.abs(s[:, 0]), np.abs(s[:, 1])))
    assert np.allclose(res.clearance[over], -depth[over], atol=1e-7)  # overlap vertices come from Clipper's grid


def test_rotated_square_corner_to_edge_gap():
    g = 0.37
    half_diag = 5 * math.sqrt(2)
    # B: the square turned 45 deg about its centre (5, 5), moved so its left corner is g right of A's edge
    pose = Pose(math.pi / 4, (5.0, 5.0), (10 + g + half_diag - 5, 0.0))
    res = sweep_pair(SQUARE, Pose(), SQUARE, [pose])
    assert res.clearance[0] == pytest.approx(g, abs=1e-12)
    assert res.point_a[0] == pytest.approx([10.0, 5.0], abs=1e-9)
    assert res.point_b[0] == pytest.approx([10 + g, 5.0], abs=1e-9)
    where = res.where_min_clearance()
    assert where["step"] == 0 and where["angle_b"] == pytest.approx(math.pi / 4)


def test_hole_is_empty_space_for_profiles_and_for_raw_polylines():
    ring = Profile(circle_loop(30.0), [circle_loop(20.0)])
    disc = Profile(circle_loop(5.0))
    # disc inside the hole, orbiting at radius 10 about the ring centre: 5 mm from the hole wall
    orbit = [Pose(a, (0.0, 0.0), (0.0, 0.0)) for a in np.linspace(0, 2 * np.pi, 9)]
    disc_at = Profile(circle_loop(5.0, center=(10.0, 0.0)))
    res = sweep_pair(ring, Pose(), disc_at, orbit, 1e-5)
    assert np.all(res.overlap_area == 0.0)
    assert np.allclose(res.clearance, 5.0, atol=3e-5)
    # same with raw polylines, both loops given counter-clockwise: nesting decides the hole
    t = np.linspace(0, 2 * np.pi, 2000, endpoint=False)
    raw = [np.c_[30 * np.cos(t), 30 * np.sin(t)], np.c_[20 * np.cos(t), 20 * np.sin(t)]]
    o = outline(raw)
    assert o.area == pytest.approx(math.pi * (30**2 - 20**2), rel=1e-5)
    res2 = sweep_pair(o, Pose(), disc, [Pose(0.0, (0, 0), (17.0, 0.0))])
    assert res2.overlap_area[0] > 1.0  # the disc crosses the hole wall
    res3 = sweep_pair(o, Pose(), disc, [Pose(0.0, (0, 0), (0.0, 0.0))])
    assert res3.overlap_area[0] == 0.0
    assert res3.clearance[0] == pytest.approx(15.0, abs=1e-3)


def _random_convex(rng, n, scale):
    from scipy.spatial import ConvexHull

    pts = rng.normal(size=(n, 2)) * scale
    return pts[ConvexHull(pts).vertices]


def _brute_distance(P, Q):
    """Least distance between two closed polylines: every vertex against every edge (no pruning)."""
    def one_way(V, W):
        A, B = W, np.roll(W, -1, axis=0)
        d = B - A
        t = np.clip(np.einsum("vij,ij->vi", V[:, None, :] - A[None], d) / np.einsum("ij,ij->i", d, d), 0, 1)
        foot = A[None] + t[..., None] * d[None]
        return np.min(np.linalg.norm(V[:, None, :] - foot, axis=2))
    return min(one_way(P, Q), one_way(Q, P))


def test_clearance_matches_brute_force_for_random_convex_bodies():
    rng = np.random.default_rng(7)
    for _ in range(6):
        a = _random_convex(rng, 12, 4.0)  # few vertices: long edges exercise the edge-length bound
        b = _random_convex(rng, 30, 3.0)
        ang = rng.uniform(0, 2 * np.pi, 40)
        off = np.c_[rng.uniform(6, 14, 40), rng.uniform(-4, 4, 40)]
        res = sweep_pair([a], Pose(), [b], [Pose(t, (0.0, 0.0), tuple(o)) for t, o in zip(ang, off)])
        for k in range(40):
            c, s_ = math.cos(ang[k]), math.sin(ang[k])
            bk = b @ np.array([[c, s_], [-s_, c]]) + off[k]
            if res.overlap_area[k] == 0.0:
                assert res.clearance[k] == pytest.approx(_brute_distance(a, bk), abs=1e-12)
                assert np.linalg.norm(res.point_a[k] - res.point_b[k]) == pytest.approx(res.clearance[k], abs=1e-12)
            else:
                assert res.clearance[k] <= 0.0


def test_free_rotation_matches_bisection_on_the_overlap_area():
    """The analytic angular clearance equals the first angle where a manifold3d boolean finds overlap."""
    import manifold3d as m3d

    rng = np.random.default_rng(11)
    for _ in range(4):
        drv = _random_convex(rng, 20, 3.0)
        dvn = _random_convex(rng, 20, 3.0) + (4.0, 0.0)  # turns about (0, 0), off its own centre
        centre = (12.0, 0.0)
        while sweep_pair([drv], Pose(0.0, (0, 0), centre), [dvn], Pose()).min_clearance < 0.05:
            centre = (centre[0] + 1.0, 0.0)
        res = transmission_sweep([drv], centre, [dvn], (0.0, 0.0), lambda p: 0.0, [0.0], senses=(1, 1),
                                 max_angle=math.pi)
        A = m3d.CrossSection([drv + centre])
        B = m3d.CrossSection([dvn])
        for sign, free in ((1, res.free_fwd[0]), (-1, res.free_back[0])):
            area = lambda d: (A ^ B.rotate(math.degrees(sign * d))).area()  # noqa: E731
            grid = np.arange(0.0, math.pi, 1e-3)
            hit = next((d for d in grid if area(d) > 0.0), None)
            if hit is None:
                assert free == math.inf
                continue
            lo, hi = hit - 1e-3, hit
            for _ in range(50):
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if area(mid) > 0.0 else (mid, hi)
            assert free == pytest.approx(hi, abs=1e-7)


def test_outline_of_a_profile_is_cached():
    p = Profile(circle_loop(7.0))
    assert outline(p, 1e-4) is outline(p, 1e-4)
    assert outline(p, 1e-4) is not outline(p, 1e-3)
    assert isinstance(outline(p), Outline)


def test_clearance_limit_record():
    a, b = Profile(circle_loop(10.0)), Profile(circle_loop(20.0))
    res = sweep_pair(a, Pose(), b, [Pose(0, (0, 0), (31.0, 0.0))], clearance_limit=1.5)
    recs = {r["name"]: r for r in res.checks()}
    assert not recs["motion.min_clearance"]["passed"]
    assert recs["motion.min_clearance"]["limit"] == 1.5


def test_bad_input_is_refused_with_the_parameter_named():
    with pytest.raises(InputError, match="poses_b"):
        sweep_pair(SQUARE, [Pose(), Pose()], SQUARE, [Pose(), Pose(), Pose()])
    with pytest.raises(InputError, match="loops"):
        outline([np.array([[0.0, 0.0], [1.0, 0.0]])])
    with pytest.raises(InputError, match="senses"):
        transmission_sweep(SQUARE, (0, 0), SQUARE, (30, 0), lambda p: p, [0.0], senses=(1, 2))


# ---------------------------------------------------------------------------
# involute gear pair z 20 / 30, m = 2: backlash, TE, contact ratio
# ---------------------------------------------------------------------------

Z1, Z2, M, J_N = 20, 30, 2.0, 0.1


@pytest.fixture(scope="module")
def gear_pair():
    g1, i1 = involute_gear(Z1, M, J_N)
    g2, i2 = involute_gear(Z2, M, J_N)
    return outline(g1), i1, outline(g2), i2


def _mesh(gear_pair, steps=200, law_offset=0.0, **kw):
    o1, i1, o2, i2 = gear_pair
    a = M * (Z1 + Z2) / 2
    u = Z2 / Z1
    phi0 = math.pi / Z2  # driven turned half a pitch: a tooth space faces the driver's tooth 0
    phis = phi0 + np.arange(steps) * (2 * math.pi / Z2) / steps  # one driven pitch, steps equal parts
    off = law_offset if callable(law_offset) else (lambda p: law_offset)
    kw.setdefault("r_ref", lambda p: i2["r"])  # a callable r(phi), as for non-circular gears
    res = transmission_sweep(o1, (0, 0), o2, (a, 0), lambda p: u * (p - phi0) + off(p), phis, **kw)
    return res


@pytest.fixture(scope="module")
def mesh_fine(gear_pair):
    return _mesh(gear_pair, contact_tol=1e-5)


def test_involute_pair_backlash_is_jn_over_cos_alpha(mesh_fine, gear_pair):
    res = mesh_fine
    j_t = J_N / math.cos(ALPHA)
    assert res.max_overlap == 0.0
    assert np.max(np.abs(res.backlash_mm - j_t)) < 1e-3  # within 1 um, as asked
    assert np.max(np.abs(res.backlash_mm - j_t)) < 2e-5  # measured: 8 nm (chord sag of the outlines)
    # each side: half the normal backlash over the driven base radius
    r_b2 = gear_pair[3]["r_b"]
    assert np.allclose(res.free_fwd, J_N / 2 / r_b2, atol=5e-7)  # 5e-7 rad = 14 nm on r_b2
    assert np.allclose(res.free_back, J_N / 2 / r_b2, atol=5e-7)
    assert all(r["passed"] for r in res.checks(te_limit_rad=1e-6, backlash_range_mm=(0.1, 0.11)))


def test_involute_pair_has_no_transmission_error(mesh_fine):
    assert np.max(np.abs(mesh_fine.te_mid)) < 1e-6
    assert mesh_fine.te_drive_pp < 1e-6
    # the loaded flank lags the law by half the backlash
    assert np.allclose(mesh_fine.te_drive, -0.5 * mesh_fine.backlash_angle, atol=1e-7)


def test_involute_pair_contact_ratio_along_the_cycle(mesh_fine):
    eps = epsilon_alpha(Z1, Z2, M)  # 1.6052
    n = len(mesh_fine.phi)
    for flank in ("drive", "coast"):
        assert mesh_fine.fraction_pairs(2, flank) == pytest.approx(eps - 1, abs=1.5 / n)
        assert mesh_fine.fraction_pairs(1, flank) == pytest.approx(2 - eps, abs=1.5 / n)
    assert mesh_fine.contact_ratio_mean == pytest.approx(eps, abs=1.5 / n)


def test_contact_tolerance_widens_the_two_pair_zone(gear_pair):
    # the gap of a pair that is about to engage grows ~quadratically: a 1 um tolerance
    # counts it a little early; the count never falls below the exact one
    eps = epsilon_alpha(Z1, Z2, M)
    res = _mesh(gear_pair, steps=100)  # default contact_tol = 1 um
    assert res.contact_tol == policy.MOTION_CONTACT_TOL_MM
    f2 = res.fraction_pairs(2)
    assert eps - 1 - 0.01 <= f2 <= eps - 1 + 0.06


def test_driver_ahead_of_the_law_shows_as_transmission_error(gear_pair):
    c = 2e-3  # driver 2 mrad ahead of the law
    res = _mesh(gear_pair, steps=24, law_offset=c, r_ref=None)
    # r_ref defaults to the mean radius of the contact points (on the driven's flanks, near the pitch circle)
    assert 28.19 < res.r_ref[0] < 32.0
    res = _mesh(gear_pair, steps=24, law_offset=c)
    # the driven follows the driver through the ratio: centre of the backlash moves by c / u
    assert np.allclose(res.te_mid, c * Z1 / Z2, atol=1e-6)
    assert np.allclose(res.backlash_mm, J_N / math.cos(ALPHA), atol=2e-5)
    # a varying law error is followed step by step (the flanks stay involutes: exact)
    err = lambda p: 1e-3 * math.sin(7 * p)  # noqa: E731
    res = _mesh(gear_pair, steps=24, law_offset=err)
    assert np.allclose(res.te_mid, [err(p) * Z1 / Z2 for p in res.phi], atol=1e-6)
    assert res.te_drive_pp == pytest.approx(np.ptp([err(p) * Z1 / Z2 for p in res.phi]), abs=2e-6)


def test_nominal_flank_clearance_is_half_the_normal_backlash(gear_pair):
    o1, i1, o2, i2 = gear_pair
    a = M * (Z1 + Z2) / 2
    phi0 = math.pi / Z2
    phis = phi0 + np.linspace(0, 2 * math.pi / Z2, 25)
    res = sweep_pair(o1, poses_from_angles(Z2 / Z1 * (phis - phi0)), o2, poses_from_angles(-phis, offset=(a, 0.0)))
    assert res.max_overlap == 0.0
    # involutes of one base circle are parallel: the normal gap on each side is j_n / 2 everywhere
    # (the polylines are inscribed in the convex flanks: never below, above by the chord sag, < 5 nm here)
    assert np.all(res.clearance >= J_N / 2 - 1e-9)
    assert np.all(res.clearance <= J_N / 2 + 5e-6)


BAR = [np.array([[0.0, -0.5], [10.0, -0.5], [10.0, 0.5], [0.0, 0.5]])]  # turns about its end (0, 0)
BLOCK = [np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])]  # 2 x 2 square about its centre


@pytest.mark.parametrize("block_at, expected", [
    # a block corner (7, 2) is met by the bar's upper edge (driver vertex on driven edge)
    ((6.0, 3.0), math.atan2(2, 7) - math.asin(0.5 / math.hypot(7, 2))),
    # the bar's tip corner (10, 0.5) meets the block's lower edge y = 3 (driven vertex on driver edge)
    ((10.0, 4.0), math.atan2(3, math.sqrt(100.25 - 9)) - math.atan2(0.5, 10)),
])
def test_free_rotation_of_a_bar_against_a_block_is_analytic(block_at, expected):
    res = transmission_sweep(BLOCK, block_at, BAR, (0.0, 0.0), lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.5)
    assert res.free_fwd[0] == pytest.approx(expected, abs=1e-12)
    assert res.free_back[0] == math.inf  # turning the other way it never meets the block
    rec = {r["name"]: r for r in res.checks()}
    assert not rec["mesh.backlash"]["passed"] and not rec["mesh.contact_continuity"]["passed"]
    # the search stops at max_angle
    short = transmission_sweep(BLOCK, block_at, BAR, (0.0, 0.0), lambda p: 0.0, [0.0], senses=(1, 1), max_angle=0.2)
    assert short.free_fwd[0] == math.inf


def test_disengaged_gears_have_no_contact(gear_pair):
    o1, i1, o2, i2 = gear_pair
    res = transmission_sweep(o1, (0, 0), o2, (70.0, 0), lambda p: 1.5 * p, [0.0, 0.1])
    assert np.all(np.isinf(res.free_fwd)) and np.all(res.pairs_drive == 0)
    assert not {r["name"]: r for r in res.checks()}["mesh.backlash"]["passed"]


def test_tight_centre_distance_is_interference(gear_pair):
    o1, i1, o2, i2 = gear_pair
    a = M * (Z1 + Z2) / 2 - 0.2  # 0.2 mm closer: j_n = 0.1 is used up (2 sin(alpha) 0.2 = 0.137 > 0.1)
    phi0 = math.pi / Z2
    res = transmission_sweep(o1, (0, 0), o2, (a, 0), lambda p: Z2 / Z1 * (p - phi0), phi0 + np.linspace(0, 0.2, 5))
    rec = {r["name"]: r for r in res.checks()}
    assert res.max_overlap > 0.0 and not rec["mesh.overlap_area"]["passed"]
    bad = res.overlap_area > policy.OVERLAP_AREA_TOL_MM2
    assert np.all(np.isnan(res.backlash_angle[bad])) and not rec["mesh.backlash"]["passed"]


def test_internal_pair_pinion_in_ring():
    z2, z3 = 20, 56
    pinion, _ = involute_gear(z2, M, J_N)
    ring_loops, ring = ring_gear(z3, M, J_N)
    a = M * (z3 - z2) / 2
    # the ring tip meets the line of action outside the pinion's base circle (no involute interference)
    assert math.sqrt(ring["r_a"] ** 2 - ring["r_b"] ** 2) > a * math.sin(ALPHA)
    steps = 60
    phis = np.arange(steps) * (2 * math.pi / z3) / steps  # one ring pitch
    # both turn the same way (senses (1, 1)); ring space 0 faces pinion tooth 0 at phi = 0
    res = transmission_sweep(pinion, (a, 0.0), ring_loops, (0.0, 0.0), lambda p: z3 / z2 * p, phis,
                             senses=(1, 1), r_ref=ring["r"], contact_tol=3e-5)
    assert res.max_overlap == 0.0
    assert np.allclose(res.backlash_mm, J_N / math.cos(ALPHA), atol=2e-5)
    assert np.max(np.abs(res.te_mid)) < 1e-6
    eps = epsilon_alpha_internal(z2, z3, M, ring["r_a"])  # 1.774
    assert res.fraction_pairs(2) == pytest.approx(eps - 1, abs=1.5 / steps)
    assert res.contact_ratio_mean == pytest.approx(eps, abs=1.5 / steps)


# ---------------------------------------------------------------------------
# 3D
# ---------------------------------------------------------------------------


def _box(lx, ly, lz):
    V = np.array([[x, y, z] for x in (0, lx) for y in (0, ly) for z in (0, lz)], float)
    F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return V, F


def _translation(x, y=0.0, z=0.0):
    T = np.eye(4)
    T[:3, 3] = (x, y, z)
    return T


def test_3d_intersection_volume_and_gap_of_boxes():
    box = _box(10, 10, 10)
    poses_b = np.array([_translation(8.0), _translation(5.0, 5.0, 5.0), _translation(12.0)])
    res = sweep_solids_3d(box, np.eye(4), box, poses_b, search_length=5.0)
    assert res.overlap_volume == pytest.approx([200.0, 125.0, 0.0], abs=1e-9)
    assert res.gap[2] == pytest.approx(2.0, abs=1e-9)
    rec = res.checks()[0]
    assert not rec["passed"] and rec["value"] == pytest.approx(200.0)
    # a box turned 90 deg about the z axis through its centre occupies the same space
    Rz = np.eye(4)
    Rz[:2, :2] = [[0, -1], [1, 0]]
    turn = _translation(5, 5) @ Rz @ _translation(-5, -5)
    assert sweep_solids_3d(box, np.eye(4), box, turn).overlap_volume[0] == pytest.approx(1000.0, rel=1e-12)


def test_3d_refuses_an_open_mesh():
    V, F = _box(10, 10, 10)
    with pytest.raises(InputError, match="mesh_b"):
        sweep_solids_3d((V, F), np.eye(4), (V, F[:-2]), np.eye(4))


def test_windowed_sweep_equals_the_plain_sweep():
    """sweep_pair_windowed crops the large body near the small one: same overlap and clearance."""
    from propulsor.checks.motion import sweep_pair_windowed
    from propulsor.geometry.gear_outline import external_gear_profile, internal_gear_profile
    from propulsor.gears.gear_pair import GearPair
    from propulsor.gears.involute import SpurGear

    m, z1, z2 = 2.0, 18, 50
    pair = GearPair(SpurGear(z1, m, 0.0), SpurGear(z2, m, 0.3, internal=True, z0=16, x0=0.0))
    planet = external_gear_profile(z1, m, 0.0, d_a=pair.d_a1, thinning_n_mm=0.05).profile
    ring = internal_gear_profile(z2, m, 0.3, pair.d_a2, 16, 0.0, thinning_n_mm=0.05).profile
    n = 40
    psi = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)  # the planet walks once round the ring
    c = pair.a_w * np.column_stack([np.cos(psi), np.sin(psi)])
    # the planet rolls on the fixed ring (planet tooth and ring space both on +y at psi = 0: in mesh
    # at the top; elsewhere the phase is arbitrary, so some steps overlap: both cases are compared)
    beta = psi * (1 - z2 / z1)
    Mp = np.zeros((n, 2, 3))
    Mp[:, 0, 0], Mp[:, 0, 1], Mp[:, 1, 0], Mp[:, 1, 1] = np.cos(beta), -np.sin(beta), np.sin(beta), np.cos(beta)
    Mp[:, :, 2] = c
    ring_pose = Pose(0.0)
    a = sweep_pair(ring, ring_pose, planet, Mp, chord_tol=1e-3, max_segment=0.1)
    b = sweep_pair_windowed(ring, ring_pose, planet, Mp, reach=m, chord_tol=1e-3, max_segment=0.1)
    assert np.allclose(a.overlap_area, b.overlap_area, atol=1e-9)
    assert np.allclose(np.minimum(a.clearance, m), b.clearance, atol=1e-9)
    # the closest points may differ where the minimum is attained twice; they are world points at it
    ok = b.clearance > 0
    assert np.allclose(np.linalg.norm(b.point_a - b.point_b, axis=1)[ok], b.clearance[ok], atol=1e-9)
    # a small reach caps the clearance there and stays exact below it
    c2 = sweep_pair_windowed(ring, ring_pose, planet, Mp, reach=0.01, chord_tol=1e-3, max_segment=0.1)
    assert np.allclose(np.minimum(a.clearance, 0.01), c2.clearance, atol=1e-12)
    assert (a.overlap_area == 0).all() and (a.clearance > 0).all()  # a true rolling mesh
    # the planet pushed 0.5 mm into the ring teeth: overlapping steps agree too
    Mp[:, :, 2] *= (pair.a_w + 0.5) / pair.a_w
    a = sweep_pair(ring, ring_pose, planet, Mp, chord_tol=1e-3, max_segment=0.1)
    b = sweep_pair_windowed(ring, ring_pose, planet, Mp, reach=m, chord_tol=1e-3, max_segment=0.1)
    assert (a.overlap_area > 0.1).all()
    assert np.allclose(a.overlap_area, b.overlap_area, rtol=1e-9)
    assert np.allclose(a.clearance, b.clearance, atol=1e-9)


@pytest.mark.parametrize("spare", [0.0, 0.3])
def test_the_windowed_sweep_cuts_the_small_body_to_where_it_faces_the_window_and_gives_the_same_bits(monkeypatch,
                                                                                                     spare):
    """sweep_pair_windowed intersects each window with the small body cut to the sector about its axis that holds the
    window over the run (outlines.FacingCut, a cut kept while it holds): every overlap area, clearance and point the same
    floats as with the small body's whole section, on a planet pushed 0.5 mm into a ring (every step overlaps) and in
    mesh; the cuts hold fewer vertices than the planet.  A disc spinning under a plate's edge (the window's extent
    within 1e-3 rad and 0.01 mm of the overlap's) gives the same bits too, and a disc in a plate's hole (a window all
    round it) is not cut."""
    from propulsor.checks.motion import rotation_matrices, sweep2d, sweep_pair_windowed
    from propulsor.checks.motion.outlines import FacingCut
    from propulsor.geometry.gear_outline import external_gear_profile, internal_gear_profile
    from propulsor.gears.gear_pair import GearPair
    from propulsor.gears.involute import SpurGear

    m, z1, z2 = 2.0, 18, 50
    pair = GearPair(SpurGear(z1, m, 0.0), SpurGear(z2, m, 0.3, internal=True, z0=16, x0=0.0))
    planet = outline(external_gear_profile(z1, m, 0.0, d_a=pair.d_a1, thinning_n_mm=0.05).profile, 1e-3, 0.1)
    ring = internal_gear_profile(z2, m, 0.3, pair.d_a2, 16, 0.0, thinning_n_mm=0.05).profile
    n = 60
    psi = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    beta = psi * (1 - z2 / z1)
    monkeypatch.setattr(sweep2d, "FACING_SPARE_RAD", spare)
    cuts = []
    real = FacingCut.section

    def n_vertices(cs):
        return sum(len(q) for q in cs.to_polygons())

    def seen(self, P):
        cs = real(self, P)
        cuts.append(n_vertices(cs))
        return cs

    for push in (0.5, 0.0):
        Mp = np.zeros((n, 2, 3))
        Mp[:, 0, 0], Mp[:, 0, 1], Mp[:, 1, 0], Mp[:, 1, 1] = np.cos(beta), -np.sin(beta), np.sin(beta), np.cos(beta)
        Mp[:, :, 2] = (pair.a_w + push) * np.column_stack([np.cos(psi), np.sin(psi)])
        monkeypatch.setattr(FacingCut, "section", lambda self, P: self.B.section)
        a = sweep_pair_windowed(ring, Pose(0.0), planet, Mp, reach=m, chord_tol=1e-3, max_segment=0.1)
        monkeypatch.setattr(FacingCut, "section", seen)
        b = sweep_pair_windowed(ring, Pose(0.0), planet, Mp, reach=m, chord_tol=1e-3, max_segment=0.1)
        for f in ("overlap_area", "clearance", "point_a", "point_b"):
            assert getattr(a, f).tobytes() == getattr(b, f).tobytes(), (push, f)
        if push:
            assert (a.overlap_area > 0.1).all()
    assert cuts and max(cuts) < 0.8 * n_vertices(planet.section)
    # tight: a disc spinning 0.3 rad under a plate's edge, the window 0.01 mm beyond it and no spare: the cap the
    # plate cuts off reaches to within 1e-3 rad and 0.01 mm of the window's own extent, so a cut short of any step's
    # window (in angle, in radius, or taken from the first step alone) changes the areas
    monkeypatch.setattr(sweep2d, "FACING_SPARE_RAD", 0.0)
    disc = outline([circle_loop(10.0, (0.0, 0.0)).polyline(1e-3)], 1e-3, 0.1)
    plate = [np.array([[-30.0, 5.0], [30.0, 5.0], [30.0, 40.0], [-30.0, 40.0]])]
    turns = rotation_matrices(np.linspace(0.0, 0.3, 10), np.zeros((10, 2)))
    monkeypatch.setattr(FacingCut, "section", lambda self, P: self.B.section)
    a = sweep_pair_windowed(plate, Pose(0.0), disc, turns, reach=0.01, chord_tol=1e-3, max_segment=0.1)
    monkeypatch.setattr(FacingCut, "section", seen)
    b = sweep_pair_windowed(plate, Pose(0.0), disc, turns, reach=0.01, chord_tol=1e-3, max_segment=0.1)
    assert (a.overlap_area > 5.0).all() and a.overlap_area.tobytes() == b.overlap_area.tobytes()
    assert cuts[-1] < 0.6 * n_vertices(disc.section)
    # a window all round the disc (a plate with a square hole the disc overlaps on every side): no cut
    holed = [np.array([[-30.0, -30.0], [30.0, -30.0], [30.0, 30.0], [-30.0, 30.0]]),
             np.array([[-9.5, -9.5], [-9.5, 9.5], [9.5, 9.5], [9.5, -9.5]])]
    monkeypatch.setattr(FacingCut, "section", lambda self, P: self.B.section)
    a = sweep_pair_windowed(holed, Pose(0.0), disc, turns, reach=0.01, chord_tol=1e-3, max_segment=0.1)
    monkeypatch.setattr(FacingCut, "section", seen)
    b = sweep_pair_windowed(holed, Pose(0.0), disc, turns, reach=0.01, chord_tol=1e-3, max_segment=0.1)
    assert (a.overlap_area > 1.0).all() and a.overlap_area.tobytes() == b.overlap_area.tobytes()
    assert cuts[-1] == n_vertices(disc.section)


@pytest.mark.parametrize("squeeze", [0.0, 0.2])
def test_the_common_area_without_the_boolean_where_apart_is_the_boolean_s_at_every_phase(gear_pair, monkeypatch,
                                                                                         squeeze):
    """transmission_sweep takes the common area as 0 without the boolean at a phase where the bodies are certainly
    apart (crossing.certainly_apart, in its compiled loop): every phase's area is the boolean's, bit for bit, on a pair
    in mesh and on one squeezed 0.2 mm into interference; the boolean runs exactly where they are not apart."""
    import propulsor.checks.motion.transmission as tm
    from propulsor.checks.motion.crossing import certainly_apart
    from propulsor.checks.motion.poses import apply_pose, compose_poses, inverse_pose

    o1, i1, o2, i2 = gear_pair
    a = M * (Z1 + Z2) / 2 - squeeze
    phi0 = math.pi / Z2
    phis = phi0 + np.linspace(0, 2 * math.pi / Z2, 9)
    theta = lambda p: Z2 / Z1 * (p - phi0)
    asked = []
    real = tm.sweep_steps

    def counting(*args):
        *rest, boolean = args
        return real(*rest, lambda rel: asked.append(rel.copy()) or boolean(rel))

    monkeypatch.setattr(tm, "sweep_steps", counting)
    res = transmission_sweep(o1, (0, 0), o2, (a, 0), theta, phis)
    drv, dvn = outline(o1), outline(o2)
    decided = []
    for k, p in enumerate(phis):
        M1 = Pose(theta(p), (0.0, 0.0), (0.0, 0.0)).matrix()
        M2 = Pose(-p, (0.0, 0.0), (a, 0.0)).matrix()
        rel = compose_poses(inverse_pose(M1), M2)
        assert res.overlap_area[k] == (drv.section ^ dvn.section.transform(rel)).area()
        decided.append(certainly_apart(drv, dvn, apply_pose(rel, dvn.points), apply_pose(inverse_pose(rel), drv.points),
                                       None))
        if not decided[-1]:  # the boolean asked of this phase, with numpy's pose to the last bit
            assert asked.pop(0).tobytes() == rel.tobytes()
    assert not asked
    if squeeze:
        assert res.max_overlap > 0.0 and not all(decided)
    else:
        assert all(decided) and res.max_overlap == 0.0
