"""Generated tooth outlines (rack and shaper envelopes), checked against independent geometry:
the analytic involute, the ISO 21771 / GOST 16532 / GOST 19274 root, form and undercut formulas,
and a brute-force 'no point of the outline lies inside the tool at any instant' test."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.optimize import brentq

from propulsor.errors import InputError
from propulsor.gears.cutters import ShaperCutter
from propulsor.gears.generation import generate_external_side, generate_internal_side
from propulsor.geometry.bspline import fit_curve, fit_points, spline_deviation
from propulsor.geometry.gear_outline import exact_area, external_gear_profile, internal_gear_profile
from propulsor.policy import SPLINE_FIT_TOL_MM

ALPHA = math.radians(20.0)


def inv(a):
    return np.tan(a) - a


def inv_inverse(v):
    return brentq(lambda a: math.tan(a) - a - v, 1e-9, 1.5, xtol=1e-16, rtol=1e-15)


def half_angle_external(z, m, x, r_y):
    """Half tooth angle on radius r_y of an involute tooth (ISO 21771 eq. (66) rearranged)."""
    r = m * z / 2
    s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    a_y = np.arccos(r * math.cos(ALPHA) / r_y)
    return s / (2 * r) + inv(ALPHA) - inv(a_y)


def polar(P):
    return np.hypot(P[:, 0], P[:, 1]), np.arctan2(P[:, 0], P[:, 1])  # angle from +y towards +x


# --------------------------------------------------------------------------- external: involute
@pytest.mark.parametrize("z,x", [(8, 0.0), (12, 0.0), (16, 0.5), (20, 0.0), (50, 0.5), (30, -0.3)])
def test_flank_is_the_involute_of_the_base_circle(z, x):
    m = 2.0
    side = generate_external_side(z, m, x)
    r, psi = polar(side.flank.sample(600))
    assert r.min() >= side.r_b
    err = np.abs(psi - half_angle_external(z, m, x, r)) * r
    assert err.max() < 1e-6
    # and the fitted splines keep to the exact envelopes within the policy tolerance
    for cur in (side.flank, side.fillet):
        sp = fit_curve(cur, cur.u0, cur.u1)
        assert len(sp.poles) < 60
        assert spline_deviation(sp, cur, cur.u0, cur.u1) <= SPLINE_FIT_TOL_MM


@pytest.mark.parametrize("z,x", [(8, 0.0), (12, 0.0), (20, 0.0), (50, 0.5), (25, 1.0)])
def test_root_circle_is_m_times_z_minus_2p5_plus_2x(z, x):
    m = 2.0
    side = generate_external_side(z, m, x)
    d_f = m * (z - 2 * 1.25 + 2 * x)
    r, _ = polar(side.fillet.sample(400))
    assert 2 * side.r_f == pytest.approx(d_f, abs=1e-12)
    assert 2 * r.min() == pytest.approx(d_f, abs=1e-9)   # the fillet starts on the root circle
    assert np.all(2 * r >= d_f - 1e-9)                  # and never dips below it
    # the fillet is tangent to the root circle at its start (radial velocity 0)
    p = side.fillet(np.array([side.fillet.u0, side.fillet.u0 + 1e-6]))
    dr = np.diff(np.hypot(p[:, 0], p[:, 1]))[0]
    assert abs(dr) < 1e-9


def test_undercut_appears_exactly_below_x_min():
    # x_min = h_l* − z sin²α/2, h_l* = h_a* + c* − ρ_f*(1 − sin α) (GOST 16532 / ISO 53 tool)
    h_l = 1.25 - 0.38 * (1 - math.sin(ALPHA))
    assert generate_external_side(8, 2.0, 0.0).undercut
    assert not generate_external_side(20, 2.0, 0.0).undercut
    for z in (8, 12, 17):
        x_min = h_l - z * math.sin(ALPHA) ** 2 / 2
        assert generate_external_side(z, 2.0, x_min - 0.01).undercut
        assert not generate_external_side(z, 2.0, x_min + 0.01).undercut


@pytest.mark.parametrize("z,x", [(20, 0.0), (40, 0.3), (12, 0.4)])
def test_form_diameter_without_undercut(z, x):
    # involute begins where the tool flank ends: ρ_l = r sin α − (h_l* − x)m/sin α (GOST 16532)
    m = 3.0
    side = generate_external_side(z, m, x)
    assert not side.undercut
    h_l = 1.25 - 0.38 * (1 - math.sin(ALPHA))
    r = m * z / 2
    rho_l = r * math.sin(ALPHA) - (h_l - x) * m / math.sin(ALPHA)
    assert side.r_Ff == pytest.approx(math.hypot(r * math.cos(ALPHA), rho_l), abs=1e-9)


def _rack_penetration(side, z, m, x, P):
    """Largest depth (mm) by which points P (gear frame) enter the ISO 53 rack tool over all
    tool positions (brute force over the rolling; vertical depth in the tool frame)."""
    r = m * z / 2
    p = math.pi * m
    w = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    rho = 0.38 * m
    eta_t = -(1.25 - x) * m
    eta_f = eta_t + rho * (1 - math.sin(ALPHA))
    xi_f = w / 2 - eta_f * math.tan(ALPHA)
    xi_c = xi_f + rho * math.cos(ALPHA)
    s = np.linspace(-1.5 * p, 1.5 * p, 6001)
    th = s / r  # tool → gear rotation is −s/r; inverse rotates by +s/r
    G = np.column_stack([r * np.sin(s / r), r * np.cos(s / r)])
    worst = -np.inf  # max over points and tool positions of η − η_tool(ξ): > 0 = inside the tool
    for q in P:
        d = q[None, :] - G
        c, sn = np.cos(th), np.sin(th)
        xi = c * d[:, 0] - sn * d[:, 1] + s
        eta = sn * d[:, 0] + c * d[:, 1]
        # distance from the nearest tool tooth centre (teeth centred at p/2 + k p), folded to the left half
        dd = np.abs((xi - p / 2 + p / 2) % p - p / 2)
        xl = p / 2 - dd
        low = np.where(xl >= xi_c, eta_t,
                       np.where(xl >= xi_f, eta_t + rho - np.sqrt(np.clip(rho ** 2 - (xl - xi_c) ** 2, 0, None)),
                                (w / 2 - xl) / math.tan(ALPHA)))
        worst = max(worst, float(np.max(eta - low)))
    return worst


def test_undercut_boundary_is_the_real_edge_of_the_cut_region():
    z, m, x = 8, 2.0, 0.0
    side = generate_external_side(z, m, x)
    assert side.undercut
    P = np.vstack([side.fillet.sample(60), side.flank.sample(60)])
    # the trimmed outline is touched by the tool but never entered
    pen = [_rack_penetration(side, z, m, x, P[i:i + 1]) for i in range(len(P))]
    assert max(pen) < 1e-6
    # the trimmed-away loop (untrimmed flank below the crossing) is inside the tool: a test that can fail
    fl = side.flank.with_range(side.extra["eta_f"] / math.cos(ALPHA), side.flank.u0)
    inner = fl.sample(40)[5:-5]
    assert min(_rack_penetration(side, z, m, x, inner[i:i + 1]) for i in range(len(inner))) > 1e-3
    # form circle: above the base circle, where the fillet meets the involute with a corner
    assert side.r_Ff > side.r_b
    t_fil = np.diff(side.fillet(np.array([side.fillet.u1 - 1e-7, side.fillet.u1])), axis=0)[0]
    t_fla = np.diff(side.flank(np.array([side.flank.u0, side.flank.u0 + 1e-7])), axis=0)[0]
    cosang = t_fil @ t_fla / np.linalg.norm(t_fil) / np.linalg.norm(t_fla)
    assert cosang < 0.999


def test_thinning_reduces_the_reference_thickness_by_its_value():
    z, m, x, j = 24, 2.5, 0.2, 0.16
    a, b = generate_external_side(z, m, x), generate_external_side(z, m, x, thinning_n_mm=j)
    r = m * z / 2
    for side, expect in ((a, m * (math.pi / 2 + 2 * x * math.tan(ALPHA))), (b, None)):
        u = side.flank.param_at_radius(r)
        _, psi = polar(side.flank(np.array([u])))
        side.s_ref = 2 * r * psi[0]
        if expect is not None:
            assert side.s_ref == pytest.approx(expect, abs=1e-9)
    assert a.s_ref - b.s_ref == pytest.approx(j, abs=1e-9)
    # normal displacement of each flank = j cos α / 2 (span W_k shrinks by j cos α)
    ry = r * 1.03
    ua, ub = a.flank.param_at_radius(ry), b.flank.param_at_radius(ry)
    da = polar(a.flank(np.array([ua])))[1][0] - polar(b.flank(np.array([ub])))[1][0]
    assert da * a.r_b == pytest.approx(j * math.cos(ALPHA) / 2, abs=1e-9)


# --------------------------------------------------------------------------- internal (ring)
RINGS = [  # z, m, x, d_a (GOST 19274 tip with k2), z0, x0
    (56, 10.0, 1.417, 10 * (56 - 2 * (1 - 1.417 - (0.25 - 0.125 * 1.417))), 14, 0.04),
    (60, 2.0, 0.0, 2 * (60 - 2 * (1 - 0.25)), 20, 0.0),
]


@pytest.mark.parametrize("z,m,x,d_a,z0,x0", RINGS)
def test_ring_generated_by_shaper(z, m, x, d_a, z0, x0):
    shaper = ShaperCutter(z0, m, x0)
    side = generate_internal_side(z, m, x, d_a, shaper)
    r = m * z / 2
    # machining centre distance, independently (GOST 19274 tab. 1)
    a_w0_ang = inv_inverse(inv(ALPHA) + 2 * math.tan(ALPHA) * (x - x0) / (z - z0))
    a_w0 = m * (z - z0) / 2 * math.cos(ALPHA) / math.cos(a_w0_ang)
    d_a0 = m * (z0 + 2 * (1.25 + x0))
    assert 2 * side.r_f == pytest.approx(2 * a_w0 + d_a0, abs=1e-9)
    rr, _ = polar(side.fillet.sample(300))
    assert 2 * rr.max() == pytest.approx(2 * a_w0 + d_a0, abs=1e-9)
    for cur in (side.flank, side.fillet):
        sp = fit_curve(cur, cur.u0, cur.u1)
        assert spline_deviation(sp, cur, cur.u0, cur.u1) <= SPLINE_FIT_TOL_MM
    # involute of the ring's base circle; space half angle e_y/(2 r_y) = e/(2r) + inv α − inv α_y
    rf, psi = polar(side.flank.sample(600))
    e = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    a_y = np.arccos(r * math.cos(ALPHA) / rf)
    assert np.max(np.abs(psi - (e / (2 * r) + inv(ALPHA) - inv(a_y))) * rf) < 1e-6
    # space width on the reference circle, where it meets the flank (thesis ring: r < r_a, it does not)
    if side.r_a < r < side.r_Ff:
        u = side.flank.param_at_radius(r)
        assert 2 * r * polar(side.flank(np.array([u])))[1][0] == pytest.approx(e, abs=1e-9)
    # form circle: ρ_l = a_w0 sin α_w0 + ρ of the shaper where its tip round begins
    t_s = shaper.tip_round[0]
    rho_l = a_w0 * math.sin(a_w0_ang) + shaper.r_b0 * t_s
    assert side.r_Ff == pytest.approx(math.hypot(r * math.cos(ALPHA), rho_l), abs=1e-8)
    assert not side.undercut


def test_ring_tip_inside_shaper_limit_is_refused():
    with pytest.raises(InputError, match="d_a"):
        generate_internal_side(60, 2.0, 0.0, 116.0, ShaperCutter(20, 2.0, 0.0))


def test_bad_inputs_name_the_parameter():
    with pytest.raises(InputError, match="^m = "):
        generate_external_side(20, -2.0)
    with pytest.raises(InputError, match="d_a"):
        generate_external_side(20, 2.0, 0.0, d_a=80.0)  # pointed long before
    with pytest.raises(InputError, match="rho_a0_star"):
        ShaperCutter(14, 10.0, 0.04, rho_a0_star=2.0).tip_round


# --------------------------------------------------------------------------- outlines
@settings(max_examples=12, deadline=None)
@given(z=st.integers(9, 80), x=st.floats(-0.3, 0.8), j=st.floats(0.0, 0.2))
def test_outline_closed_and_thickness_exact(z, x, j):
    m = 2.0
    d_a = m * (z + 2 + 2 * x)
    s_a = 2 * (d_a / 2) * half_angle_external(z, m, x, d_a / 2) - j * (d_a / (m * z))
    if s_a < 0.2 * m:  # pointed: the generator refuses it (tested above)
        return
    g = external_gear_profile(z, m, x, d_a, thinning_n_mm=j)
    assert g.profile.outer.is_closed(1e-9)
    assert len(g.profile.outer.segments) == 6 * z
    # area of one pitch sector: independent count via the polyline vs exact Green area
    assert exact_area(g.profile) == pytest.approx(g.profile.area(1e-5), rel=1e-6)


def test_fit_points_meets_tolerance_on_dense_data():
    side = generate_external_side(18, 2.0, 0.1)
    P = side.flank.sample(3000)
    sp = fit_points(P)
    assert len(sp.poles) < 200
    assert spline_deviation(sp, side.flank, side.flank.u0, side.flank.u1, 500) <= 2 * SPLINE_FIT_TOL_MM


def test_ring_outline_closed():
    g = internal_gear_profile(56, 10.0, 1.417, RINGS[0][3], 14, 0.04)
    assert g.profile.holes[0].is_closed(1e-9)
    assert g.profile.outer.is_closed(1e-12)
    assert g.d_f == pytest.approx(2 * g.side.extra["a_w0"] + g.side.extra["d_a0"], abs=1e-9)


def _shaper_polygon(sh: ShaperCutter, n: int = 150) -> np.ndarray:
    """Dense outline of the shaper teeth near the top (exact involute, tip round, tip arc), the
    teeth joined by chords below the base circle (ignored by the penetration check)."""
    t_s, c, a_fl, a_tip = sh.tip_round
    rho = sh.rho_a0_star * sh.m
    a = np.linspace(a_fl, a_tip, n)
    psi_tip = math.atan2(c[0], c[1])
    ps = np.linspace(psi_tip, 0.0, n)
    R = np.vstack([sh.involute.point(np.linspace(0.0, t_s, n))[:-1],
                   np.column_stack([c[0] + rho * np.cos(a), c[1] + rho * np.sin(a)])[:-1],
                   sh.r_a0 * np.column_stack([np.sin(ps), np.cos(ps)])[:-1]])  # base → tip → centre line
    tooth = np.vstack([R * [-1, 1], R[::-1]])  # left half base → centre, right half centre → base
    out = []
    for k in range(-4, 5):  # teeth swept past the ring slot at ±2 ring pitches of rolling
        th = -2 * math.pi * k / sh.z0
        out.append(tooth @ np.array([[math.cos(th), math.sin(th)], [-math.sin(th), math.cos(th)]]))
    return np.vstack(out)


def _shaper_penetration(side, sh, P):
    """Largest depth (mm) by which points P (ring frame) enter the shaper over the rolling."""
    from matplotlib.path import Path

    V = _shaper_polygon(sh)
    poly = Path(V)
    A, B = V, np.roll(V, -1, axis=0)
    ab = B - A
    L2 = np.einsum("ij,ij->i", ab, ab)
    r_w0, r_w = side.extra["r_w0"], side.extra["r_w"]
    p = 2 * math.pi * r_w0 / sh.z0
    s = np.linspace(-2 * p, 2 * p, 4001)
    th = -s / r_w + s / r_w0
    G = r_w * np.column_stack([np.sin(s / r_w), np.cos(s / r_w)])
    C = r_w0 * np.column_stack([np.sin(s / r_w0), np.cos(s / r_w0)])
    c, sn = np.cos(-th), np.sin(-th)
    worst = 0.0
    for q in P:
        d = q[None, :] - G
        Q = C + np.column_stack([c * d[:, 0] - sn * d[:, 1], sn * d[:, 0] + c * d[:, 1]])
        # only the generating part of the shaper (involute, round, tip) counts: below its base
        # circle the polygon's chords are not the real shaper (its root clears the ring tips)
        Q = Q[np.hypot(Q[:, 0], Q[:, 1]) >= sh.r_b0]
        for y in Q[poly.contains_points(Q)]:  # depth = distance to the outline
            t = np.clip(np.einsum("ij,ij->i", y - A, ab) / L2, 0, 1)
            worst = max(worst, float(np.min(np.linalg.norm(A + t[:, None] * ab - y, axis=1))))
    return worst


def _rotate(P, ang):
    c, s = math.cos(ang), math.sin(ang)
    return P @ np.array([[c, -s], [s, c]]).T


@pytest.mark.parametrize("z,m,x,d_a,z0,x0", RINGS)
def test_ring_outline_is_never_entered_by_the_shaper(z, m, x, d_a, z0, x0):
    sh = ShaperCutter(z0, m, x0)
    side = generate_internal_side(z, m, x, d_a, sh)
    P = np.vstack([side.fillet.sample(12), side.flank.sample(12)])
    assert _shaper_penetration(side, sh, P) < 1e-6
    # the same points turned 2 µm into the space (towards +y) are cut away: the check can fail
    Q = _rotate(P[2:-2], 2e-3 / side.r)
    assert min(_shaper_penetration(side, sh, q[None, :]) for q in Q[::3]) > 1e-4


class PolarCentrode:
    """Gear centrode given as a pitch curve r(φ) in polar form (φ counter-clockwise from +x),
    run clockwise from φ0 by arc length s: dφ/ds = −1/√(r² + r'²) (tooth spacing is true arc
    length).  Integrated once (solve_ivp, rtol 1e-12, dense output), then evaluated vectorised.
    With r = R it is ``CircleCentrode(R)`` (φ0 = π/2).  A reference implementation of the
    centrode protocol of ``gears.envelope`` for the tests (the product's non-circular gears use
    ``PitchCurveCentrode`` on their shared arc-length frame).
    """

    def __init__(self, r, dr, s_span: tuple, phi0: float = math.pi / 2):
        from scipy.integrate import solve_ivp

        self.r, self.dr, self.phi0 = r, dr, float(phi0)
        f = lambda s, y: [-1.0 / math.hypot(float(r(y[0])), float(dr(y[0])))]
        lo, hi = float(s_span[0]), float(s_span[1])
        kw = dict(dense_output=True, rtol=1e-12, atol=1e-14, method="DOP853")
        self._fwd = solve_ivp(f, (0.0, hi), [self.phi0], **kw).sol if hi > 0 else None
        self._bwd = solve_ivp(f, (0.0, lo), [self.phi0], **kw).sol if lo < 0 else None

    def phi(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        out = np.empty_like(s)
        pos = s >= 0
        if np.any(pos):
            out[pos] = self._fwd(s[pos])[0]
        if np.any(~pos):
            out[~pos] = self._bwd(s[~pos])[0]
        return out

    def point(self, s):
        ph = self.phi(s)
        r = np.asarray(self.r(ph), float) * np.ones_like(ph)
        return np.column_stack([r * np.cos(ph), r * np.sin(ph)])

    def angle(self, s):
        ph = self.phi(s)
        r = np.asarray(self.r(ph), float) * np.ones_like(ph)
        dr = np.asarray(self.dr(ph), float) * np.ones_like(ph)
        # dG/dφ, reversed (φ decreases with s)
        tx = -(dr * np.cos(ph) - r * np.sin(ph))
        ty = -(dr * np.sin(ph) + r * np.cos(ph))
        return np.arctan2(ty, tx)


def test_generic_centrode_reproduces_the_circle():
    """The envelope machinery takes any pitch curve parametrised by arc length: a polar pitch
    curve r(φ) = R gives the circular gear's flank and fillet to rounding (hook for the
    non-circular gears)."""
    z, m, x = 14, 2.0, 0.2
    side = generate_external_side(z, m, x)
    R = m * z / 2
    pc = PolarCentrode(lambda ph: R + 0 * ph, lambda ph: 0 * ph, (-10.0, 10.0))
    for cur in (side.fillet, side.flank):
        u = np.linspace(cur.u0, cur.u1, 50)
        gen = type(cur)(cur.piece, cur.cutter, pc, cur.u0, cur.u1)
        assert np.abs(gen(u) - cur(u)).max() < 1e-9
    # an eccentric circle (a non-circular pitch curve about the origin) still puts the tool's
    # straight flank on an involute of the circle's own centre: distance of the flank's normals
    e = 1.5
    rr = lambda ph: e * np.sin(ph) + np.sqrt(R ** 2 - (e * np.cos(ph)) ** 2)
    drr = lambda ph: e * np.cos(ph) + (e ** 2 * np.cos(ph) * np.sin(ph)) / np.sqrt(R ** 2 - (e * np.cos(ph)) ** 2)
    pe = PolarCentrode(rr, drr, (-10.0, 10.0))
    cur = side.flank
    shifted = type(cur)(cur.piece, cur.cutter, pe, cur.u0, cur.u1)(np.linspace(cur.u0, cur.u1, 50))
    assert np.abs(shifted - (cur(np.linspace(cur.u0, cur.u1, 50)) + [0.0, e])).max() < 1e-8


def test_ring_thinning_widens_the_space_by_its_value():
    z, m, x, d_a, z0, x0 = RINGS[1]
    sh = ShaperCutter(z0, m, x0)
    a = generate_internal_side(z, m, x, d_a, sh)
    b = generate_internal_side(z, m, x, d_a, sh, thinning_n_mm=0.1)
    r = m * z / 2
    e = [2 * r * polar(s.flank(np.array([s.flank.param_at_radius(r)])))[1][0] for s in (a, b)]
    assert e[1] - e[0] == pytest.approx(0.1, abs=1e-9)


@pytest.mark.parametrize("internal", [False, True])
def test_dense_points_of_one_pitch_join_up(internal):
    if internal:
        z, m, x, d_a, z0, x0 = RINGS[1]
        side = generate_internal_side(z, m, x, d_a, ShaperCutter(z0, m, x0))
    else:
        z, side = 18, generate_external_side(18, 2.0, 0.3)
    d = side.dense(300)
    assert np.allclose(d["fillet"][-1], d["flank"][0], atol=1e-12)
    assert np.allclose(d["flank"][-1], d["tip"][0], atol=1e-9)
    assert np.allclose(d["fillet"][0], d["root"][0], atol=1e-9)
    assert np.allclose(np.hypot(*d["tip"].T), side.r_a) and np.allclose(np.hypot(*d["root"].T), side.r_f)
    # the arcs end on the mirrored side of this tooth / space, or of the next one (rotated a pitch)
    ends = {"tip": d["flank_mirror"][-1], "root": d["fillet_mirror"][0]}
    pz = 2 * math.pi / z
    for key, p in ends.items():
        q = d[key][-1]
        across = (key == "tip") != internal
        target = p if across else _rotate(p[None, :], -pz)[0]
        assert np.allclose(q, target, atol=1e-9), key
