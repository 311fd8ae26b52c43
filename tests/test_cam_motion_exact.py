"""Exact values of the cam's roller-centre path (seed 001; mutation target ``mechanics_cam``): the support phase of
eq. 20, the return closure and the per-angle table of ``propulsor.laws.cam_motion`` against values computed
independently here (closed forms, hand calculations, the seed's equations written out).  Every cam is built inside
its test (a cam built at collection or in a module fixture cannot kill a mutant of its construction)."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


def test_straight_roller_path_is_h0_over_cos_phi_with_gamma_equal_to_phi():
    """K = 0: the roller centre runs on the line at H0 below the axle, H = H0/cos φ, γ = atan(H'/H) = φ."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    mech = CamMechanism(R0=70.0, r=15.0, n_legs=5)
    p = solve_support(mech, CurvatureLaw("zero"), estimate_error=False)
    phi = np.linspace(-math.pi / 5, math.pi / 5, 9)
    H, g = p.state(phi)
    assert H == pytest.approx(85.0 / np.cos(phi), rel=1e-9)
    assert g == pytest.approx(phi, abs=1e-9)


def _first_event(H0, K, end):
    """Seed 001 eq. 20 integrated here (RK45, not the module's DOP853) to its first irregular point: (index of the
    event - 0 cos γ = 0.001, 1 ρ = 100 H0, 2 ρ = 1e-6 H0 - and its φ in degrees)."""
    from scipy.integrate import solve_ivp

    def f(p, y):
        return [y[0] * math.tan(y[1]), 1.0 - y[0] * K(p) / math.cos(y[1])]

    events = [lambda p, y: math.cos(y[1]) - 1e-3, lambda p, y: 100.0 * H0 - y[0], lambda p, y: y[0] - 1e-6 * H0]
    for e in events:
        e.terminal = True
    sol = solve_ivp(f, (0.0, end), [H0, 0.0], method="RK45", rtol=1e-12, atol=1e-12, events=events)
    assert sol.status == 1
    which = [i for i, t in enumerate(sol.t_events) if len(t)][0]
    return which, math.degrees(sol.t_events[which][0])


def test_blow_up_where_the_path_runs_away_names_rho_to_infinity():
    """A strongly negative curvature near φ = 0 only (K = -0.3·e^(-50|φ|)) throws the path outward on a nearly
    straight line: ρ reaches 100 H0 (at 47.18°) before cos γ falls to 0.001 (three legs: support ±60°)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    which, deg = _first_event(110.0, lambda p: -0.3 * math.exp(-50.0 * abs(p)), math.pi / 3)
    assert which == 1 and round(deg, 2) == 47.18
    assert refused(solve_support, CamMechanism(n_legs=3), CurvatureLaw("exponential", -0.3, -50.0)) == (
        "CurvatureLaw(k0, k1) = (-0.3, -50.0): roller path of eq. 20 must stay regular (cos γ > 0.001, 0 < ρ < ∞) "
        f"over the support phase |φ| <= 60°; it blows up (ρ → ∞) at φ = {deg:.4g}° (K = -0.3·exp(-50·|φ|))")


def test_blow_up_of_an_odd_law_on_the_leading_side_is_at_a_negative_angle():
    """K = 0.05·φ (literal): regular for φ > 0, but K < 0 on the leading half turns the tangent radial at
    φ = -25.81° (the even law K = 0.05·|φ| is regular on both sides)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    which, deg = _first_event(110.0, lambda p: 0.05 * p, -math.pi / 4)
    assert which == 0 and round(deg, 2) == -25.81
    assert refused(solve_support, CamMechanism(), CurvatureLaw("linear", 0.05, symmetric=False),
                   estimate_error=False) == (
        "CurvatureLaw.k0 = 0.05: roller path of eq. 20 must stay regular (cos γ > 0.001, 0 < ρ < ∞) over the "
        f"support phase |φ| <= 45°; it blows up (cos γ → 0 (path tangent turns radial)) at φ = {deg:.4g}° "
        "(K = 0.05·φ)")
    solve_support(CamMechanism(), CurvatureLaw("linear", 0.05), estimate_error=False)


def test_blow_up_angle_of_a_steep_linear_law():
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    which, deg = _first_event(110.0, lambda p: 0.2 * abs(p), math.pi / 4)
    assert which == 0 and round(deg, 1) == 20.2
    assert refused(solve_support, CamMechanism(), CurvatureLaw("linear", 0.2)).endswith(
        f"it blows up (cos γ → 0 (path tangent turns radial)) at φ = {deg:.4g}° (K = 0.2·|φ|)")


def test_slope_of_the_shoe_angle_ratio_is_eq20s_identity():
    """q = (γ − φ)/φ; with γ' = 1 − g (eq. 20) its derivative is dq/dφ = −(g + q)/φ, g = H·K/cos γ, all read off
    the path's state at φ (no quadrature)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    for law, K in ((CurvatureLaw("quadratic", 0.017), lambda p: 0.017 * p * p),
                   (CurvatureLaw("exponential", 0.004, 0.6, symmetric=False), lambda p: 0.004 * np.exp(0.6 * p))):
        sp = solve_support(CamMechanism(), law, estimate_error=False)
        phi = np.array([-0.7, -0.3, 0.2, 0.75])
        H, gam = sp.state(phi)
        q_want = (gam - phi) / phi
        g = H * K(phi) / np.cos(gam)
        q, dq = sp.delta_over_phi(phi)
        assert q == pytest.approx(q_want, rel=1e-9)
        assert dq == pytest.approx(-(g + q_want) / phi, rel=1e-8)


def test_hertz_stress_flat_undercut_and_unloaded_points():
    """Eq. 14 with E = 2 E1 E2 / (E1 + E2): on the flat profile at φ = 0 (K(0) = 0, R = ∞) only the roller's
    1/r counts; where the path bends tighter than the roller (K > 0, R = 1/K − r <= 0) the profile is undercut
    (nan); with no spring force in the return phase (P_return = 0) the stress is 0 where the profile exists."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion

    m = CamMechanism(R0=50.0, r=60.0, P_return=0.0, E1=2.0e5, E2=1.0e5)
    cm = cam_motion(m, CurvatureLaw("quadratic", 0.06), ReturnPhase("top", 140.0), estimate_error=False)
    t = cm.table(np.array([0.0, 0.7, 2.0, 3.0, 4.0]))
    E = 2 * 2.0e5 * 1.0e5 / 3.0e5
    assert t.R_profile[0] == math.inf
    assert t.sigma_H[0] == pytest.approx(0.418 * math.sqrt(5000.0 * E / (20.0 * 60.0)), rel=1e-12)
    assert t.support.tolist() == [True, True, False, False, False]
    assert t.K_path[1] > 1 / 60.0 and t.K_path[3] > 1 / 60.0                  # tighter than the roller
    assert np.isnan(t.sigma_H[1]) and np.isnan(t.sigma_H[3])
    assert 0 < t.K_path[2] < 1 / 60.0 and 0 < t.K_path[4] < 1 / 60.0
    assert t.sigma_H[2] == 0.0 and t.sigma_H[4] == 0.0


def test_hertz_stress_where_the_closure_passes_behind_the_axle_is_nan():
    """A free (minimum-jerk) closure of a steep law dips below the axle (H < 0 near φ = π: the pressure angle
    beyond 90°, cos γ < 0): no contact stress is defined there."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion

    cm = cam_motion(CamMechanism(), CurvatureLaw("quadratic", 0.06), ReturnPhase("min_jerk"), estimate_error=False)
    phi = np.linspace(1.0, 5.2, 85)
    t = cm.table(phi)
    behind = t.H < 0
    assert behind.any() and (np.abs(t.gamma[behind]) > math.pi / 2).all()
    assert np.isnan(t.sigma_H[behind]).all()
    ok = (t.H > 0) & (t.R_profile > 0)
    assert ok.any() and np.isfinite(t.sigma_H[ok]).all()


def test_default_closure_has_the_smallest_pressure_angle_norm():
    """ReturnPhase() ('min_gamma'): H(π) minimises the 8-norm (mean of γ^8)^(1/8) of the return phase's pressure
    angle γ = atan2(H', H) over 721 angles; found here by golden section on closures built with ReturnCurve.build
    (136.0 mm for the quadratic law, between the support end 141.0 mm and the free quintic's top 174.4 mm)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnCurve, cam_motion

    cm = cam_motion(CamMechanism(), CurvatureLaw("quadratic", 0.0171), estimate_error=False)
    s = math.pi / 4
    a, b = s, 2 * math.pi - s
    da, db = cm.support.derivs(np.array([s])), cm.support.derivs(np.array([-s]))
    ea = tuple(float(da[k][0]) for k in ("H", "H1", "H2"))
    eb = tuple(float(db[k][0]) for k in ("H", "H1", "H2"))
    phi = np.linspace(a, b, 721)

    def norm8(h):
        H, H1 = ReturnCurve.build(ea, eb, a, b, h).derivs(phi, 1)
        return float(np.mean(np.arctan2(H1, H) ** 8) ** 0.125)

    lo, hi = 100.0, 170.0
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        lo, hi = (lo, x2) if norm8(x1) < norm8(x2) else (x1, hi)
    top = float(cm.ret.derivs(np.array([math.pi]), 0)[0][0])
    assert top == pytest.approx(0.5 * (lo + hi), abs=1e-5)
    assert round(top, 1) == 136.0
    assert cm.ret.coef == pytest.approx(ReturnCurve.build(ea, eb, a, b, top).coef, rel=1e-12, abs=1e-9)
    assert norm8(top) < norm8(top - 0.01) and norm8(top) < norm8(top + 0.01)


def test_integration_error_is_measured_against_a_tighter_integration_on_2001_angles():
    """H_error_mm = max |H − H_ref| over 2001 angles of the support phase, H_ref from eq. 20 integrated here
    (DOP853 at rtol = atol = 1e-13, both sides for the literal law): a few 1e-9 mm, below the 1e-6 mm limit."""
    from scipy.integrate import solve_ivp

    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    s = math.pi / 4
    for law, K in ((CurvatureLaw("quadratic", 0.0171), lambda p: 0.0171 * p * p),
                   (CurvatureLaw("linear", 0.004, symmetric=False), lambda p: 0.004 * p)):
        def f(p, y):
            c = math.cos(y[1])
            return [y[0] * math.tan(y[1]), 1.0 - y[0] * K(p) / c]

        pos = solve_ivp(f, (0.0, s), [110.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-13, dense_output=True)
        neg = solve_ivp(f, (0.0, -s), [110.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-13, dense_output=True)
        grid = np.linspace(-s, s, 2001)
        if law.is_even:
            H_ref = pos.sol(np.abs(grid))[0]
        else:
            H_ref = np.where(grid >= 0, pos.sol(np.clip(grid, 0, s))[0], neg.sol(np.clip(grid, -s, 0))[0])
        path = solve_support(CamMechanism(), law)
        plain = solve_support(CamMechanism(), law, estimate_error=False)
        want = float(np.max(np.abs(plain.state(grid)[0] - H_ref)))
        assert path.H_error_mm == pytest.approx(want, rel=1e-12) and 1e-10 < path.H_error_mm < 1e-6
        assert plain.state(grid)[0].tolist() == path.state(grid)[0].tolist()
