"""Exact values of the balancer arm as a beam (seed 004 ch. 8; mutation target ``mechanics_beam``): the statics,
sections and checks of ``propulsor.laws.balancer_beam`` against values computed independently here (hand
calculations, the textbook formulas written out, physical identities).  Everything is built inside its test."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


def test_in_plane_moment_falls_by_the_shear_between_stations():
    """dM_z/ds = -V_y between loads: M_z at s is the sum of (s_k - s) F_y over the loads outboard."""
    from propulsor.laws.balancer_beam import PointLoad, internal_forces

    loads = [PointLoad("a", 250.0, 40.0, 0.0, 3000.0), PointLoad("b", 100.0, 0.0, 0.0, -1000.0)]
    f = internal_forces(loads, [110.0, 130.0])
    assert f["V_y"].tolist() == [3000.0, 3000.0]
    assert f["M_z"][0] - f["M_z"][1] == pytest.approx(20.0 * 3000.0, rel=1e-15)
    assert f["M_z"].tolist() == [140.0 * 3000.0, 120.0 * 3000.0]


def test_internal_forces_take_integer_stations():
    """Stations given as integers (mm) are stations like any other: the sums are floats."""
    from propulsor.laws.balancer_beam import PointLoad, internal_forces

    loads = [PointLoad("w", 360.0, 150.0, -1500.0, 2500.0)]
    f = internal_forces(loads, [0, 100])
    assert f["N"].tolist() == [-1500.0, -1500.0] and f["V_y"].tolist() == [2500.0, 2500.0]
    assert f["T"].tolist() == [-150.0 * 2500.0] * 2 and f["M_y"].tolist() == [150.0 * -1500.0] * 2
    assert f["M_z"].tolist() == [360.0 * 2500.0, 260.0 * 2500.0]
    assert internal_forces(loads, 7)["M_z"].tolist() == [353.0 * 2500.0]


def test_no_loads_need_no_reactions():
    from propulsor.laws.balancer_beam import reactions

    r = reactions([], 60.0, 200.0)
    assert r.bearing1.tolist() == [0.0, 0.0, 0.0] and r.bearing2.tolist() == [0.0, 0.0, 0.0]
    assert r.bar_torque == 0.0 and (r.z1, r.z2) == (-60.0, -200.0)
    F, M = r.residual([])
    assert F.tolist() == [0.0, 0.0, 0.0] and M.tolist() == [0.0, 0.0, 0.0]


def test_slender_rectangle_torsion_is_silent_where_cosh_overflows():
    """h/b = 40: the series' cosh(n pi h / 2b) overflows to inf beyond n = 11 (1/cosh -> 0, no warning), and the
    thin-strip limits hold: J -> h b^3 / 3 (1 - 0.630 b/h), tau_max -> T / (J / b)."""
    import warnings

    from propulsor.laws.balancer_beam import _rect_torsion

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        J, k = _rect_torsion(400.0, 10.0)
    assert J == pytest.approx(400.0 * 10.0 ** 3 / 3 * (1 - 0.630 * 10.0 / 400.0), rel=1e-4)
    assert k == pytest.approx(10.0 / J, rel=1e-12)


def test_wall_thickness_of_the_arm_is_kept_as_a_float():
    from propulsor.laws.balancer_beam import BalancerGeometry

    g = BalancerGeometry(t_wall="8")
    assert g.t_wall == 8.0 and type(g.t_wall) is float


def test_hollow_section_wall_limit_on_the_smaller_side_both_ways():
    """The wall must be below half of min(b, h), whichever side is the smaller."""
    from propulsor.laws.balancer_beam import RectSection

    assert RectSection(20.0, 10.0, 4.999).t == 4.999          # h the smaller: 2t = 9.998 < 10
    assert RectSection(10.0, 20.0, 4.999).t == 4.999
    assert refused(RectSection, 20.0, 10.0, 5.0) == "t = 5.0: wall must be < half of min(b, h) = 5 mm"


def _solid_torsion_factor(h, b, terms=2000):
    """tau_max / T of a solid rectangle h x b (h >= b), Timoshenko & Goodier §109, summed here."""
    J = h * b ** 3 / 3 * (1 - 192 * b / (math.pi ** 5 * h) * sum(math.tanh(n * math.pi * h / (2 * b)) / n ** 5
                                                                   for n in range(1, 2 * terms, 2)))
    s = sum(1 / (n ** 2 * math.cosh(min(n * math.pi * h / (2 * b), 700.0))) for n in range(1, 2 * terms, 2))
    return b / J * (1 - 8 / math.pi ** 2 * s)


def test_von_mises_at_the_y_faces_adds_axial_and_in_plane_bending():
    """No out-of-plane bending, no shear force: the y-faces (sigma = |N|/A + |M_z|/W_z with tau_T) govern."""
    from propulsor.laws.balancer_beam import RectSection

    b, h = 60.0, 100.0
    N, T, Mz = -30000.0, 4e6, -2e6
    sig = 30000.0 / (b * h) + 2e6 / (b * h ** 2 / 6)
    tau = 4e6 * _solid_torsion_factor(h, b)
    want = math.sqrt(sig ** 2 + 3 * tau ** 2)
    assert float(RectSection(b, h).von_mises(N, 0.0, T, 0.0, Mz)) == pytest.approx(want, rel=1e-8)
    # the corner (no shear on a solid section's corner) and the z-faces are both lower here
    assert want > sig and want > math.sqrt((30000.0 / (b * h)) ** 2 + 3 * tau ** 2)


def test_von_mises_at_the_z_faces_adds_both_shears():
    """No in-plane bending: the z-faces (sigma = |N|/A + |M_y|/W_y, tau = tau_T + tau_V) govern; tau_V = 1.5 V/A
    at the neutral axis of a solid rectangle."""
    from propulsor.laws.balancer_beam import RectSection

    b, h = 60.0, 100.0
    N, V, T, My = 20000.0, -90000.0, -3e6, 1.5e6
    sig = 20000.0 / (b * h) + 1.5e6 / (h * b ** 2 / 6)
    tau = 3e6 * _solid_torsion_factor(h, b) + 1.5 * 90000.0 / (b * h)
    want = math.sqrt(sig ** 2 + 3 * tau ** 2)
    assert float(RectSection(b, h).von_mises(N, V, T, My, 0.0)) == pytest.approx(want, rel=1e-8)
    assert want > sig


def test_equal_strength_depth_just_above_the_allowable_at_h_min_is_deeper():
    """At h_min the stress is 0.5 % over the allowable: the depth rises above h_min to sigma = sigma_allow
    (M_z / (b h^2 / 6) = sigma: h = sqrt(6 M / (sigma b)))."""
    from propulsor.laws.balancer_beam import BalancerGeometry, equal_strength_depth

    M = 60.0 * 40.0 ** 2 / 6 * 100.5                       # 100.5 MPa at h_min = 40 mm
    f = {"N": np.array([0.0]), "V_y": np.array([0.0]), "T": np.array([0.0]), "M_y": np.array([0.0]),
         "M_z": np.array([M])}
    h = equal_strength_depth(f, BalancerGeometry(), 100.0)
    assert h[0] == pytest.approx(math.sqrt(6 * M / (100.0 * 60.0)), abs=1e-8) and h[0] > 40.0 + 0.09


def test_equal_strength_depth_of_a_hollow_arm():
    """A hollow arm (wall t): W_z = (b h^3 - (b - 2t)(h - 2t)^3) / (6 h); the depth solves W_z sigma = M_z (found
    here by bisection), deeper than the solid arm's sqrt(6 M / (sigma b))."""
    from propulsor.laws.balancer_beam import BalancerGeometry, equal_strength_depth

    b, t, sa, M = 60.0, 8.0, 200.0, 8e7
    f = {"N": np.array([0.0]), "V_y": np.array([0.0]), "T": np.array([0.0]), "M_y": np.array([0.0]),
         "M_z": np.array([M])}

    def W(h):
        return (b * h ** 3 - (b - 2 * t) * (h - 2 * t) ** 3) / (6 * h)

    lo, hi = 40.0, 400.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if W(mid) * sa < M else (lo, mid)
    h = equal_strength_depth(f, BalancerGeometry(t_wall=t), sa)
    assert h[0] == pytest.approx(lo, abs=1e-7)
    assert h[0] > math.sqrt(6 * M / (sa * b)) + 10.0


def test_damper_ear_on_the_arm_face_at_the_wheel_station_does_not_bend_the_spindle():
    """The ear at the wheel station (i_a = 1: L_a = R_b) on the arm's outboard face (e_a = b/2 = 30 mm) is on the
    arm, not on the spindle: the spindle root carries the wheel force alone, M = (e_w - b/2) P_w."""
    from propulsor.laws.balancer_beam import BalancerAnalysis, BalancerGeometry
    from propulsor.laws.suspension import SuspensionDesign, thesis_design

    d0 = thesis_design()
    d = SuspensionDesign(wheel_x_m=d0.wheel_x_m, damper_x_m=d0.damper_x_m, i_a=1.0)
    tor = d.torsion
    for e_a in (30.0, 25.0):
        a = BalancerAnalysis(d, BalancerGeometry(e_a=e_a), n_stations=3)
        ear = a.cases[1].loads[1]
        assert (ear.s, ear.z) == (360.0, e_a)
        Pw = (tor.M_T_max + d.R_a_comp_max * d.L_a) / (360.0 * math.sin(tor.beta_m))
        row = a.transitions()[3]
        assert (row["case"], row["where"]) == ("beta_m + damper", "wheel spindle fillet")
        assert row["sigma_nom"] == pytest.approx((150.0 - 30.0) * Pw / (math.pi * 90.0 ** 3 / 32), rel=1e-12)


def test_run_reports_the_statics_residual_as_force_plus_moment_over_the_arm():
    """The residual check's value is |F| + |M| / R_b of the loads with their reactions (N); a geometry whose
    rounding leaves a moment residual (3.7e-9 N mm, no force residual) in the elastic case shows the moment's
    share.  The equal-strength check is in MPa."""
    from propulsor.laws.balancer_beam import BalancerAnalysis, BalancerGeometry, reactions
    from propulsor.laws.suspension import thesis_design

    d = thesis_design()
    g = BalancerGeometry(e_w=151.1, a1=70.9, a2=191.3, e_a=17.3)
    a = BalancerAnalysis(d, g, n_stations=3)
    checks = {c.name: c for c in a.run()["checks"]}
    c = a.cases[0]
    F, M = reactions(c.loads, 70.9, 191.3).residual(c.loads)
    assert np.linalg.norm(M) > 1e-9 and np.linalg.norm(F) == 0.0       # the case this test is about
    k = checks["beta_m elastic: statics residual"]
    assert k.value >= 0.0
    assert k.value == pytest.approx(np.linalg.norm(F) + np.linalg.norm(M) / 360.0, rel=1e-12)
    for name in ("beta_m elastic", "beta_m + damper", "stop"):
        k = checks[f"{name}: equal-strength arm sigma_vM"]
        assert (k.unit, k.limit) == ("MPa", pytest.approx(620.0 * (1 + 1e-9), rel=1e-15))
