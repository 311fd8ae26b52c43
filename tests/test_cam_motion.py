"""Seed 001: fixed cam of the driven wheel-walking propulsor — roller path, cam profile, shoes."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor import policy
from propulsor.errors import InputError
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion, solve_support
from propulsor.laws.shoe import (footprint_ratio, hub_height_on_flat, return_ground_clearance, shoe_arc_length,
                                 shoe_loop_check, shoe_table)

MECH = CamMechanism()  # ours: R0 = 90, r = 20, C = 210 mm, 4 legs
S = math.pi / 4
LAWS = [
    CurvatureLaw("linear", 0.0093),
    CurvatureLaw("quadratic", 0.0171),
    CurvatureLaw("exponential", 0.004, 0.6),
    CurvatureLaw("linear", 0.004, symmetric=False),
    CurvatureLaw("exponential", 0.006, -1.0, symmetric=False),
]


@pytest.fixture(scope="module")
def motions():
    return {law: cam_motion(MECH, law) for law in LAWS}


def test_defaults_are_ours():
    assert MECH.H0 == 110.0 and MECH.hub_height == 320.0 and MECH.n_legs == 4
    assert MECH.E == pytest.approx(2.1e5)
    assert CamMechanism(E1=2.1e5, E2=1.0e5).E == pytest.approx(2 * 2.1e5 * 1e5 / 3.1e5)  # eq. 15


# ----------------------------------------------------------------------- K = 0


def test_zero_curvature_is_straight_path_closed_form():
    sup = solve_support(MECH, CurvatureLaw("zero"))
    phi = np.linspace(-S, S, 1001)
    d = sup.derivs(phi)
    exact = MECH.H0 / np.cos(phi)
    assert np.max(np.abs(d["H"] / exact - 1.0)) <= 1e-9
    assert np.max(np.abs(d["gamma"] - phi)) <= 1e-9  # γ' = 1 → γ = φ
    assert np.max(np.abs(d["H1"] - MECH.H0 * np.sin(phi) / np.cos(phi) ** 2)) <= 1e-7
    # the roller centre runs on the straight line Y = H0 (cam frame, eq. 9 with r = 0)
    assert np.max(np.abs(d["H"] * np.cos(phi) - MECH.H0)) <= 1e-9 * MECH.H0


def test_zero_curvature_shoe_is_circle_of_radius_C_about_roller_centre():
    # K = 0: H'/tan φ = H → Y1 = 0, Y2 = R0 + r + C − H cos φ = C: the shoe point B is at
    # distance C from the roller centre (origin of the leg frame, eq. 11): circle radius C.
    sup = solve_support(MECH, CurvatureLaw("zero"))
    phi = np.linspace(-S, S, 401)
    t = shoe_table(sup, phi)
    assert np.max(np.abs(t.Y1)) <= 1e-8
    assert np.max(np.abs(t.Y2 - MECH.C)) <= 1e-8
    assert np.max(np.abs(np.hypot(t.X_B, t.Y_B) - MECH.C)) <= 1e-8
    assert np.max(np.abs(t.rho - MECH.C)) <= 1e-8  # eq. 13
    assert np.max(np.abs(t.alpha - phi)) <= 1e-10  # eq. 12: α = φ on a circle about C
    assert np.max(np.abs(t.radius - MECH.C)) <= 1e-7  # radius of curvature of the shoe


# ------------------------------------------------------------------ integration


@pytest.mark.parametrize("law", LAWS, ids=lambda l: l.label())
def test_integration_error_below_1e6_mm(motions, law):
    err = motions[law].H_error_mm
    assert err is not None and err <= policy.CAM_H_ERROR_MAX_MM
    # the error estimate is a real comparison: a sloppy integration shows a large one
    sloppy = solve_support(MECH, law, rtol=1e-4, atol=1e-4)
    assert sloppy.H_error_mm > 10 * err


@pytest.mark.parametrize("law", LAWS, ids=lambda l: l.label())
def test_eq20_satisfies_eq18_curvature(motions, law):
    """The integrated path has the prescribed curvature: eq. 18 from H, H', H'' (the
    H'' by finite differences of the dense H) equals K(φ)."""
    sup = motions[law].support
    phi = np.linspace(-S + 0.01, S - 0.01, 61)
    phi = phi[np.abs(phi) > 0.01]  # the even extension has a kink of K' at 0
    h = 1e-4
    Hm, H0, Hp = (sup.state(phi + k * h)[0] for k in (-1, 0, 1))
    H1 = (Hp - Hm) / (2 * h)
    H2 = (Hp - 2 * H0 + Hm) / h ** 2
    K18 = (H0 ** 2 + 2 * H1 ** 2 - H0 * H2) / (H0 ** 2 + H1 ** 2) ** 1.5
    assert np.max(np.abs(K18 - law.K(phi))) <= 1e-6
    d = sup.derivs(phi)
    assert np.max(np.abs(d["H2"] - H2)) <= 1e-3


def test_symmetric_law_gives_even_path_and_literal_does_not(motions):
    phi = np.linspace(0, S, 50)
    sym = motions[LAWS[0]].support
    assert np.max(np.abs(sym.state(phi)[0] - sym.state(-phi)[0])) == 0.0
    lit = motions[LAWS[3]].support
    assert np.max(np.abs(lit.state(phi)[0] - lit.state(-phi)[0])) > 1.0
    # literal K = k0·φ: the path bends away from the cam for φ < 0 → H grows faster there
    assert lit.state(np.array([-S]))[0][0] > lit.state(np.array([S]))[0][0]


# ------------------------------------------------------------- blow-up, bad input


def test_blow_up_inside_support_raises_naming_coefficient():
    with pytest.raises(InputError) as e:
        solve_support(MECH, CurvatureLaw("linear", 0.01, symmetric=False))
    assert e.value.parameter == "CurvatureLaw.k0" and e.value.value == 0.01
    assert "blows up" in str(e.value) and "45°" in str(e.value)
    with pytest.raises(InputError) as e:
        solve_support(MECH, CurvatureLaw("quadratic", 1.0))  # path curls back: cos γ → 0
    assert e.value.parameter == "CurvatureLaw.k0"
    with pytest.raises(InputError) as e:
        solve_support(MECH, CurvatureLaw("exponential", 0.005, 8.0))
    assert e.value.parameter == "CurvatureLaw(k0, k1)" and e.value.value == (0.005, 8.0)


@pytest.mark.parametrize("kw", [dict(R0=0), dict(r=-1), dict(C=float("nan")), dict(n_legs=2),
                                dict(n_legs=4.5), dict(b=0), dict(P=-5), dict(E1=0), dict(P_return=-1),
                                dict(channel_clearance=-0.1)])
def test_bad_mechanism_raises(kw):
    with pytest.raises(InputError):
        CamMechanism(**kw)


@pytest.mark.parametrize("kw", [dict(kind="cubic"), dict(kind="zero", k0=0.1), dict(kind="linear", k1=1.0),
                                dict(kind="linear", k0=float("inf")), dict(kind="exponential", k0=0.01, k1=100)])
def test_bad_law_raises(kw):
    with pytest.raises(InputError):
        CurvatureLaw(**kw)


def test_bad_return_phase_and_phi_raise(motions):
    for kw in (dict(mode="top", H_top=-3), dict(mode="top"), dict(mode="min_jerk", H_top=150.0), dict(mode="x")):
        with pytest.raises(InputError):
            ReturnPhase(**kw)
    with pytest.raises(InputError):
        motions[LAWS[0]].support.state(np.array([1.0]))


# ------------------------------------------------------------------ full turn


@pytest.mark.parametrize("law", LAWS, ids=lambda l: l.label())
@pytest.mark.parametrize("ret", [ReturnPhase(), ReturnPhase("min_jerk"), ReturnPhase("top", 150.0)],
                         ids=["min_gamma", "min_jerk", "top"])
def test_full_turn_is_c2_and_periodic(law, ret):
    cm = cam_motion(MECH, law, ret, estimate_error=False)
    for a in (S, -S, 7 * S):
        e = 1e-12
        L = cm.H_derivs(np.array([a - e]))
        R = cm.H_derivs(np.array([a + e]))
        for k, tol in ((0, 1e-8), (1, 1e-7), (2, 1e-6)):
            assert abs(L[k][0] - R[k][0]) <= tol * max(1.0, abs(L[k][0]))
    # second differences across the joint match H'' (no hidden kink), and periodicity
    # (C2, not C3: the error of the central difference falls like h; a jump of H'' would not fall)
    for a in (S, -S):
        H2 = cm.H_derivs(np.array([a]))[2][0]
        errs = []
        for h in (2e-3, 1e-3, 5e-4):
            Hm, H0, Hp = (cm.H_derivs(np.array([a + k * h]))[0][0] for k in (-1, 0, 1))
            errs.append(abs((Hp - 2 * H0 + Hm) / h ** 2 - H2))
        assert errs[2] <= 0.6 * errs[1] + 1e-6 and errs[1] <= 0.6 * errs[0] + 1e-6
        assert abs(2 * errs[2] - errs[1]) <= 0.05 * errs[1] + 1e-4  # Richardson: error → 0 with h
    phi = np.linspace(0, 2 * math.pi, 37)
    assert np.allclose(cm.H_derivs(phi)[0], cm.H_derivs(phi + 2 * math.pi)[0], rtol=0, atol=1e-9)
    if ret.mode == "top":
        assert cm.H_derivs(np.array([math.pi]))[0][0] == pytest.approx(150.0, abs=1e-9)


def test_return_is_minimum_jerk_quintic_when_free():
    """Free return phase: the two quintics form ONE quintic (jerk minimiser), so the
    fifth derivative (constant per piece) is equal on both pieces."""
    cm = cam_motion(MECH, LAWS[1], ReturnPhase("min_jerk"), estimate_error=False)
    c = cm.ret.coef
    assert c[0, 5] == pytest.approx(c[1, 5], rel=1e-8)
    # any other C2 closure (here the one with H(π) prescribed) has more jerk
    def jerk(cmx):
        phi = np.linspace(S, 7 * S, 4001)
        return np.trapezoid(cmx.ret.derivs(phi, 3)[3] ** 2, phi)
    other = cam_motion(MECH, LAWS[1], ReturnPhase("top", cm.H_derivs(np.array([math.pi]))[0][0] + 5),
                       estimate_error=False)
    assert jerk(other) > jerk(cm)


def test_all_legs_ride_one_closed_path(motions):
    cm = motions[LAWS[1]]
    legs = cm.leg_angles(0.3)
    assert np.allclose(np.diff(legs), math.pi / 2)
    H = cm.H_derivs(legs)[0]
    assert H[0] == pytest.approx(cm.support.state(np.array([0.3]))[0][0], abs=1e-12)
    assert cm.H_derivs(np.array([legs[2]]))[0][0] == pytest.approx(cm.H_derivs(np.array([0.3 + math.pi]))[0][0])


# ------------------------------------------------------------- profile (eq. 9-17)


def _fd_curvature(X, Y, h):
    x1, y1 = np.gradient(X, h, edge_order=2), np.gradient(Y, h, edge_order=2)
    x2, y2 = np.gradient(x1, h, edge_order=2), np.gradient(y1, h, edge_order=2)
    return (x1 * y2 - y1 * x2) / (x1 ** 2 + y1 ** 2) ** 1.5


@pytest.mark.parametrize("law", LAWS[:3], ids=lambda l: l.label())
def test_profile_radius_eq16_matches_finite_difference_curvature(motions, law):
    cm = motions[law]
    n = 20001
    phi = np.linspace(-math.pi / 4, 7 * math.pi / 4, n)
    h = phi[1] - phi[0]
    t = cm.table(phi)
    # cam frame (X, Y) with Y down is a left-handed frame: curvature sign flips
    kfd = -_fd_curvature(t.X, t.Y, h)
    # away from the points where dK/dφ jumps (the C2 joints ±π/4 and φ = 0 of the even law)
    inner = np.ones(n, bool)
    inner[:5] = inner[-5:] = False
    for a in (-S, 0.0, S):
        inner[np.abs(phi - a) < 5 * h] = False
    with np.errstate(divide="ignore"):
        k16 = 1.0 / t.R_profile
        ko = -1.0 / t.R_outer
    assert np.max(np.abs(kfd[inner] - k16[inner])) <= 1e-8
    kfo = -_fd_curvature(t.X_outer, t.Y_outer, h)
    assert np.max(np.abs(kfo[inner] - ko[inner])) <= 1e-8
    # eq. 16 with γ' of eq. 20 in the support phase
    d = cm.support.derivs(cm.wrap(phi[t.support]))
    with np.errstate(divide="ignore"):  # K = 0 at φ = 0: straight, R = ∞
        R16 = d["H"] / ((1 - d["dgamma"]) * np.cos(d["gamma"])) - MECH.r
    finite = np.isfinite(R16) & (np.abs(R16) < 1e6)
    assert np.max(np.abs(R16[finite] - t.R_profile[t.support][finite]) / np.abs(R16[finite])) <= 1e-9


def test_profile_points_are_roller_envelope(motions):
    """Eq. 9-10: the working profile lies at exactly r from the roller centre, and no other
    profile point comes closer (no undercut); the outer wall at r + clearance."""
    cm = motions[LAWS[1]]
    phi = np.linspace(0, 2 * math.pi, 8001)
    t = cm.table(phi)
    cx, cy = t.H * np.sin(phi), t.H * np.cos(phi)
    assert np.allclose(np.hypot(t.X - cx, t.Y - cy), MECH.r, atol=1e-9)
    ro = MECH.r + MECH.channel_clearance
    assert np.allclose(np.hypot(t.X_outer - cx, t.Y_outer - cy), ro, atol=1e-9)
    for k in range(0, 8001, 400):
        dmin = np.min(np.hypot(t.X - cx[k], t.Y - cy[k]))
        assert dmin >= MECH.r - 1e-6
        assert np.min(np.hypot(t.X_outer - cx[k], t.Y_outer - cy[k])) >= ro - 1e-6
    # the profile normal is along ψ: the roller centre, the profile point and the normal agree
    tx, ty = np.gradient(t.X), np.gradient(t.Y)
    cosang = (tx * np.sin(t.psi) + ty * np.cos(t.psi)) / np.hypot(tx, ty)
    assert np.max(np.abs(cosang[1:-1])) <= 1e-6


def test_pressure_angle_and_hertz_formula(motions):
    cm = motions[LAWS[0]]
    phi = np.array([0.0, 0.3, -0.5, 2.0])
    t = cm.table(phi)
    d = cm.H_derivs(phi)
    assert np.allclose(t.gamma, np.arctan(d[1] / d[0]))  # eq. 17
    for i in range(4):
        P = MECH.P if t.support[i] else MECH.P_return
        inv = 1 / MECH.r + (0.0 if not np.isfinite(t.R_profile[i]) else 1 / t.R_profile[i])
        sig = 0.418 * math.sqrt(P * MECH.E / (MECH.b * math.cos(t.gamma[i])) * inv)  # eq. 14
        assert t.sigma_H[i] == pytest.approx(sig, rel=1e-12)
    # at φ = 0 with K(0) = 0 the profile is flat: σ = 0.418·√(P·E/(b·r))
    assert t.sigma_H[0] == pytest.approx(0.418 * math.sqrt(5000 * 2.1e5 / (20 * 20)), rel=1e-9)
    assert t.sigma_H[0] == pytest.approx(677.23, abs=0.01)


def test_hub_speed_eq8_equals_eq4_and_derivative_of_eq3(motions):
    """dX02/dφ (eq. 8) = eq. 4 with Y1, Y2 of the shoe = d/dφ of X02 (eq. 3) integrated."""
    for law in (LAWS[1], LAWS[3]):
        cm = motions[law]
        phi = np.linspace(-S, S, 4001)
        sh = shoe_table(cm.support, phi)
        d = cm.support.derivs(phi)
        v8 = d["H1"] * np.sin(phi) + MECH.hub_height
        assert np.allclose(cm.hub_speed(phi[:-1]), v8[:-1], rtol=0, atol=1e-12)  # periodic: π/4 is the next leg
        v4 = d["H1"] * np.sin(phi) + (d["H"] + sh.Y1) * np.cos(phi) + sh.Y2
        assert np.max(np.abs(v8 - v4)) <= 1e-8
        integrand = sh.Y2 - sh.dY1 * np.sin(phi)
        cum = np.concatenate([[0], np.cumsum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(phi))])
        X02 = (d["H"] + sh.Y1) * np.sin(phi) + cum
        v3 = np.gradient(X02, phi)
        assert np.max(np.abs(v3[2:-2] - v8[2:-2]) / v8[2:-2]) <= 1e-5


# ------------------------------------------------------------------------- shoe


@pytest.mark.parametrize("law", LAWS, ids=lambda l: l.label())
def test_shoe_Y1_matches_direct_formula_and_limit(motions, law):
    sup = motions[law].support
    phi = np.linspace(-S, S, 201)
    t = shoe_table(sup, phi)
    d = sup.derivs(phi)
    far = np.abs(phi) > 0.2
    direct = d["H1"][far] / np.tan(phi[far]) - d["H"][far]
    assert np.max(np.abs(t.Y1[far] - direct)) <= 1e-8
    t0 = shoe_table(sup, np.array([0.0]))
    assert t0.Y1[0] == pytest.approx(sup.derivs(np.array([0.0]))["H2"][0] - MECH.H0, abs=1e-9)
    assert t0.Y1[0] == pytest.approx(-MECH.H0 ** 2 * float(law.K(0.0)), abs=1e-9)
    # continuity through the removable singularity
    eps = np.array([-1e-6, -1e-9, 1e-9, 1e-6])
    tiny = shoe_table(sup, eps)
    assert np.allclose(tiny.Y1, t0.Y1[0] + tiny.dY1 * eps, rtol=0, atol=1e-9)
    # Y1' against central differences, away from the kink of the even law at 0
    p = np.array([-0.7, -0.4, -0.1, 0.05, 0.3, 0.6])
    h = 1e-5
    fd = (shoe_table(sup, p + h).Y1 - shoe_table(sup, p - h).Y1) / (2 * h)
    assert np.max(np.abs(fd - shoe_table(sup, p).dY1)) <= 1e-5
    # eq. 1 normality: dY2/dφ = −dY1/dφ·cos φ
    fd2 = (shoe_table(sup, p + h).Y2 - shoe_table(sup, p - h).Y2) / (2 * h)
    assert np.max(np.abs(fd2 + shoe_table(sup, p).dY1 * np.cos(p))) <= 1e-5


@pytest.mark.parametrize("law", LAWS[:3], ids=lambda l: l.label())
def test_shoe_radius_matches_polyline_curvature_and_arc(motions, law):
    sup = motions[law].support
    n = 8001
    phi = np.linspace(-S, S, n)
    t = shoe_table(sup, phi)
    h = phi[1] - phi[0]
    k = _fd_curvature(t.X_B, t.Y_B, h)
    inner = (np.arange(n) >= 5) & (np.arange(n) < n - 5) & (np.abs(phi) > 5 * h)  # kink of K' at 0
    assert np.max(np.abs(np.abs(k[inner]) - 1 / t.radius[inner])) <= 1e-8
    poly = float(np.sum(np.hypot(np.diff(t.X_B), np.diff(t.Y_B))))
    assert shoe_arc_length(t) == pytest.approx(poly, rel=1e-6)


def test_shoe_loop_detection():
    ok = shoe_loop_check(shoe_table(solve_support(MECH, LAWS[1]), np.linspace(-S, S, 181)))
    assert ok.ok and not ok.self_intersecting and ok.radius_min == pytest.approx(MECH.C)  # K(0) = 0 → σ(0) = C
    # literal K = k0·φ, k0 = 0.005: the leading half bends outward, the shoe's tangent reverses
    bad = shoe_loop_check(shoe_table(solve_support(MECH, CurvatureLaw("linear", 0.005, symmetric=False)),
                                     np.linspace(-S, S, 181)))
    assert not bad.ok and bad.radius_min < 0 and bad.phi_at_min < 0
    # a concave path with a short stand: Y2 − Y1'·sin φ < 0 at the shoe ends, a looped shoe
    lp = shoe_loop_check(shoe_table(solve_support(CamMechanism(C=60.0), CurvatureLaw("quadratic", -0.01)),
                                    np.linspace(-S, S, 401)))
    assert not lp.ok and lp.radius_min < 0 and lp.self_intersecting


def test_hub_height_on_flat_is_constant_for_default_design():
    """Independent of eq. 7: place all four shoes, find the lowest point; variation ≤ 0.01 mm."""
    cm = cam_motion(MECH, CurvatureLaw("exponential", 0.004, 0.0), estimate_error=False)
    phi = np.linspace(-S, S, 13)
    hh = hub_height_on_flat(cm, phi, n_shoe=601)
    assert np.max(hh) - np.min(hh) <= 0.01
    assert np.max(np.abs(hh - MECH.hub_height)) <= 1e-6
    # the other legs clear the ground (zero only at hand-over)
    clr = return_ground_clearance(cm, np.array([-0.6, 0.0, 0.6]))
    assert np.all(clr > 0.5)


def test_hub_height_check_can_fail():
    """A design whose idle shoe digs into the ground: the lowest point is no longer the
    supporting shoe, and the placed-shoe computation shows it."""
    cm = cam_motion(MECH, CurvatureLaw("linear", 0.005, symmetric=False), estimate_error=False)
    hh = hub_height_on_flat(cm, np.array([0.0, 0.7]), n_shoe=301)
    assert hh[1] - MECH.hub_height > 1.0


def test_footprint_ratio_extremes():
    wheel = cam_motion(MECH, CurvatureLaw("exponential", 1 / MECH.H0, 0.0), estimate_error=False)
    assert footprint_ratio(wheel) == pytest.approx(1.0, abs=1e-6)  # K = 1/H0: a round wheel
    straight = cam_motion(MECH, CurvatureLaw("zero"), estimate_error=False)
    # circle shoe radius C: arc C·π/2, hub travel ∫(H0·tan²φ + 320) dφ
    travel = MECH.H0 * (2 - math.pi / 2) + 320 * math.pi / 2
    assert footprint_ratio(straight) == pytest.approx(MECH.C * math.pi / 2 / travel, rel=1e-6)


@settings(max_examples=15, deadline=None)
@given(k0=st.floats(0.0, 0.02), kind=st.sampled_from(["linear", "quadratic"]))
def test_property_error_and_c2(k0, kind):
    cm = cam_motion(MECH, CurvatureLaw(kind, k0))
    assert cm.H_error_mm <= policy.CAM_H_ERROR_MAX_MM
    L, R = cm.H_derivs(np.array([S - 1e-12])), cm.H_derivs(np.array([S + 1e-12]))
    assert abs(L[2][0] - R[2][0]) <= 1e-5 * max(1.0, abs(L[2][0]))


def test_other_leg_counts_close_the_turn():
    """n legs: support phase ±π/n, the path still closes C2, the hub stays level."""
    for n in (3, 6):
        m = CamMechanism(n_legs=n)
        cm = cam_motion(m, CurvatureLaw("quadratic", 0.01), estimate_error=False)
        s = math.pi / n
        L, R = cm.H_derivs(np.array([s - 1e-12])), cm.H_derivs(np.array([s + 1e-12]))
        assert all(abs(L[k][0] - R[k][0]) <= 1e-6 * max(1.0, abs(L[k][0])) for k in range(3))
        hh = hub_height_on_flat(cm, np.linspace(-s, s, 5), n_shoe=401)
        assert np.max(np.abs(hh - m.hub_height)) <= 1e-6
    t = cm.table(np.array([0.0, 0.2]))
    assert t.R_path[1] == pytest.approx(1 / t.K_path[1]) and np.isinf(t.R_path[0])  # K(0) = 0
