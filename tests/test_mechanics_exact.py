"""Exact values and refusals of the mechanics laws (mutation target ``mechanics``): every refusal's message in
full, both sides of every limit, formula values computed independently here.  Every law or object is built inside
its test (a law built at collection cannot kill a mutant of its construction)."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


# ============================================================== carrier_strength.py (seed 004 eq. 48-53, §4.3)

def test_carrier_static_capacity_refuses_each_input_by_name_and_unit():
    from propulsor.laws.carrier_strength import static_capacity_radial_roller as c0

    good = dict(D_we=15.0, D_pw=80.0, i=1, Z=16, L_we=15.0, alpha_rad=0.0)
    for name, unit in (("D_we", " mm"), ("D_pw", " mm"), ("i", ""), ("Z", ""), ("L_we", " mm")):
        assert refused(c0, **{**good, name: 0}) == f"{name} = 0: must be > 0{unit}"
        assert refused(c0, **{**good, name: -1.0}) == f"{name} = -1.0: must be > 0{unit}"
    # eq. 48 with the planet bearing's rollers: 44 (1 - 15/80) 1 16 15 15 = 128 700 N (Table 8)
    assert c0(**good) == pytest.approx(44 * (1 - 15 / 80) * 16 * 15 * 15, rel=1e-15)
    assert c0(**good) == pytest.approx(128700.0, rel=1e-15)


def test_carrier_bearing_safety_refuses_a_load_of_zero():
    from propulsor.laws.carrier_strength import PLANET_BEARING_004

    assert refused(PLANET_BEARING_004.S0, 0.0) == "bearing_load = 0.0: must be > 0 N"
    assert PLANET_BEARING_004.S0(1e-9) == pytest.approx(128700.0 / 1e-9)


def test_spline_allowable_each_factor_divides():
    from propulsor.laws.carrier_strength import spline_allowable

    # eq. 52-53 with every factor != 1: sigma_T / (n K_pr K_z K_p)
    assert spline_allowable(785.0, 1.4, 2.65, 1.2, 1.4) == pytest.approx(785.0 / (1.4 * 2.65 * 1.2 * 1.4), rel=1e-15)
    assert spline_allowable(630.0, 1.5, 1.1, 2.0, 1.3) == pytest.approx(630.0 / (1.5 * 1.1 * 2.0 * 1.3), rel=1e-15)


def test_spline_crushing_stress_refusals():
    from propulsor.laws.carrier_strength import spline_crushing_stress

    assert refused(spline_crushing_stress, 100.0, 0.0, 140.0) == "S_u = 0.0: must be > 0"
    assert refused(spline_crushing_stress, 100.0, 5528.74, 0.0) == "spline_length = 0.0: must be > 0 mm"
    assert spline_crushing_stress(100.0, 50.0, 4.0) == pytest.approx(100.0 * 1e3 / (50.0 * 4.0), rel=1e-15)


def test_shaft_equivalent_stress_refusals():
    from propulsor.laws.carrier_strength import shaft_equivalent_stress

    assert refused(shaft_equivalent_stress, 1.0, 1.0, 0.0, 1.0, 1.0, 970.0) == "W_i = 0.0: must be > 0 mm³"
    assert refused(shaft_equivalent_stress, 1.0, 1.0, 1.0, 1.0, -2.0, 970.0) == "W_k = -2.0: must be > 0 mm³"
    sh = shaft_equivalent_stress(1000.0, 10.0, 100.0, 2.0, 40.0, 970.0)
    assert (sh.sigma_b, sh.tau) == (100.0, 50.0)
    assert sh.sigma_eq == pytest.approx(math.sqrt(100.0 ** 2 + 4 * 50.0 ** 2), rel=1e-15)
    assert sh.margin == pytest.approx(970.0 / math.sqrt(20000.0), rel=1e-15)


# ============================================================== tyre_heat.py (seed 004 ch. 7, eq. 76-80, Table 12)

def _tyre(**kw):
    from propulsor.laws.tyre_heat import SolidTyre

    args = dict(R=315.0, b=90.0, H=40.0, E=6.0, alpha=60.0)
    args.update(kw)
    return SolidTyre(**args)


def test_tyre_speed_refusals_and_speed_zero():
    from propulsor.laws.tyre_heat import air_cooling_coefficient, n_rpm, track_frequency

    assert refused(track_frequency, 4.0, 0.0) == "t_track = 0.0: must be > 0 m"
    assert refused(track_frequency, -1.0, 0.15) == "V = -1.0: speeds must be finite and >= 0 m/s"
    assert refused(track_frequency, [1.0, float("nan")], 0.15) == "V = [1.0, nan]: speeds must be finite and >= 0 m/s"
    assert refused(track_frequency, [float("inf")], 0.15).startswith("V = [inf]: ")
    assert float(track_frequency(0.0, 0.15)) == 0.0
    assert float(track_frequency(3.0, 0.5)) == pytest.approx(2 * math.pi * 3.0 / 0.5, rel=1e-15)
    assert refused(air_cooling_coefficient, 4.0, 0.0) == "A_heatexchange = 0.0: must be > 0 m^2"
    assert refused(air_cooling_coefficient, 4.0, 0.002, 0.0) == "rho_air = 0.0: must be > 0 kg/m^3"
    assert refused(air_cooling_coefficient, 4.0, 0.002, 1.2, 0.0) == "c_air = 0.0: must be > 0 J/(kg K)"
    assert refused(air_cooling_coefficient, -4.0, 0.002) == "V = -4.0: speeds must be finite and >= 0 m/s"
    assert refused(air_cooling_coefficient, [float("nan")], 0.002) == "V = [nan]: speeds must be finite and >= 0 m/s"
    assert float(air_cooling_coefficient(0.0, 0.002)) == 0.0
    # the defaults are air's: rho 1.2 kg/m^3, c 1005 J/(kg K)
    assert float(air_cooling_coefficient(2.0, 0.5)) == pytest.approx(2.0 * 0.5 * 1.2 * 1005.0, rel=1e-15)
    assert float(air_cooling_coefficient(2.0, 0.5, 1.0, 1000.0)) == pytest.approx(1000.0, rel=1e-15)
    assert refused(n_rpm, 10.0, 0.0) == "R = 0.0: must be > 0 mm"
    assert refused(n_rpm, -5.0, 315.0) == "V = -5.0: speeds must be finite and >= 0 km/h"
    assert refused(n_rpm, [float("inf")], 315.0) == "V = [inf]: speeds must be finite and >= 0 km/h"
    assert float(n_rpm(0.0, 315.0)) == 0.0
    # 36 km/h on R = 500 mm: 10 m/s / (2 pi 0.5 m) rev/s; the printed 60 V / (3.6 pi R) is twice that
    assert float(n_rpm(36.0, 500.0)) == pytest.approx(600.0 / math.pi, rel=1e-15)
    assert float(n_rpm(36.0, 500.0, True)) == pytest.approx(1200.0 / math.pi, rel=1e-15)
    assert float(n_rpm(36.0, 500.0, as_printed=False)) == pytest.approx(600.0 / math.pi, rel=1e-15)


def test_tyre_table12_coefficient_refusals():
    from propulsor.laws.tyre_heat import G_ACC, heating_coefficient, inertial_load

    assert refused(heating_coefficient, 0.0, 1420.0) == "m_rubber = 0.0: must be > 0 kg"
    assert refused(heating_coefficient, 0.336, 0.0) == "c_rubber = 0.0: must be > 0 J/(kg K)"
    assert heating_coefficient(2.0, 500.0) == 1.0 / 1000.0
    assert refused(inertial_load, 0.0, 30.0) == "mass = 0.0: must be > 0 kg"
    assert refused(inertial_load, 36.0, 0.0) == "accel_g = 0.0: must be > 0"
    assert G_ACC == 9.81
    assert inertial_load(2.0, 3.0) == pytest.approx(2.0 * 3.0 * 9.81, rel=1e-15)


def test_tyre_surface_refusals_and_both_sides_of_H_below_R():
    from propulsor.laws.tyre_heat import tyre_surface

    assert refused(tyre_surface, 0.0, 90.0, 40.0) == "R = 0.0: must be > 0 mm"
    assert refused(tyre_surface, 315.0, 0.0, 40.0) == "b = 0.0: must be > 0 mm"
    assert refused(tyre_surface, 315.0, 90.0, 0.0) == "H = 0.0: must be > 0 mm"
    assert refused(tyre_surface, 315.0, 90.0, 315.0) == "H = 315.0: rubber thickness must be < R = 315 mm"
    assert refused(tyre_surface, 315.5, 90.0, 400.0) == "H = 400.0: rubber thickness must be < R = 315.5 mm"
    # just below R: a full disc of rubber, 2 pi R^2 sides minus a hair
    assert tyre_surface(100.0, 10.0, 99.0) == pytest.approx(2 * math.pi * (100.0 ** 2 - 1.0) + 2 * math.pi * 1000.0,
                                                            rel=1e-15)
    assert tyre_surface(100.0, 10.0, 20.0) == pytest.approx(2 * math.pi * (10000.0 - 6400.0) + 2 * math.pi * 1000.0,
                                                            rel=1e-15)


def test_solid_tyre_refusals_in_full():
    assert refused(_tyre, R=0.0) == "R = 0.0: must be > 0 mm"
    assert refused(_tyre, b=-1.0) == "b = -1.0: must be > 0 mm"
    assert refused(_tyre, H=0.0) == "H = 0.0: must be > 0 mm"
    assert refused(_tyre, H=315.0) == "H = 315.0: rubber thickness must be < R = 315 mm"
    assert refused(_tyre, H=315.0, F=1e5) == "H = 315.0: rubber thickness must be < R = 315 mm"   # F given too
    assert _tyre(H=314.999, F=1e5).H == 314.999
    assert refused(_tyre, E=0.0) == "E = 0.0: must be > 0 MPa"
    assert refused(_tyre, alpha=0.0) == "alpha = 0.0: must be > 0 W/(m^2 K)"
    assert refused(_tyre, psi=float("nan")) == "psi = nan: must be a finite number"
    for psi in (0.0, 1.0, -0.1, 1.5):
        assert refused(_tyre, psi=psi) == f"psi = {psi!r}: internal friction must lie in (0, 1) (seed: 0.25 ... 0.5)"
    assert refused(_tyre, F=0.0) == "F = 0.0: must be > 0 mm^2"


def test_solid_tyre_keeps_floats_and_its_defaults():
    t = _tyre(R="315", b=90, H=40, E=6, alpha=60, psi="0.4", F="5e5")   # text and integers from a file: floats
    assert (t.R, t.b, t.H, t.E, t.alpha, t.psi, t.F) == (315.0, 90.0, 40.0, 6.0, 60.0, 0.4, 5e5)
    assert all(type(v) is float for v in (t.R, t.b, t.H, t.E, t.alpha, t.psi, t.F))
    # psi just inside (0, 1) is taken
    assert _tyre(psi=1e-9).psi == 1e-9
    assert _tyre(psi=0.999999).psi == 0.999999
    d = _tyre()
    assert d.psi == 0.35
    assert d.F == pytest.approx(2 * math.pi * (315.0 ** 2 - 275.0 ** 2) + 2 * math.pi * 315.0 * 90.0, rel=1e-15)
    assert _tyre(F=1234.5).F == 1234.5


def test_solid_tyre_load_refusals():
    t = _tyre()
    assert refused(t.contact_length, 0.0) == "P = 0.0: tyre load must be finite and > 0 N"
    assert refused(t.q_m, -3) == "P = -3.0: tyre load must be finite and > 0 N"
    assert refused(t.q_mean, [1.0, float("nan")]) == "P = [1.0, nan]: tyre load must be finite and > 0 N"
    assert refused(t.work_per_turn, [2.0, 0.0]) == "P = [2.0, 0.0]: tyre load must be finite and > 0 N"
    assert refused(t.work_per_turn, [2, -1]) == "P = [2.0, -1.0]: tyre load must be finite and > 0 N"   # as read
    assert refused(t.deflection, float("inf")) == "P = inf: tyre load must be finite and > 0 N"
    assert float(t.contact_length(1e-6)) > 0


def test_solid_tyre_deflection_limit_both_sides():
    # l = 2 cbrt(H/R) sqrt(R P / (E b)), lambda = l^2 / (8 R) = cbrt(H/R)^2 P / (2 E b): lambda = H at
    # P* = 2 E b H / cbrt(H/R)^2
    R, b, H, E = 100.0, 10.0, 8.0, 1.0
    t = _tyre(R=R, b=b, H=H, E=E)
    P_star = 2 * E * b * H / (H / R) ** (2 / 3)
    below = 0.999 * P_star
    assert float(t.deflection(below)) == pytest.approx(0.999 * H, rel=1e-12)
    msg = refused(t.deflection, 1.001 * P_star)
    lam = 1.001 * H
    assert msg == f"P = {float(1.001 * P_star)!r}: deflection {lam:.4g} mm reaches the rubber thickness H = 8 mm"
    # exactly at H (H/R = 1/8, E = b = 1: l = sqrt(R P), lambda = P / 8 = H at P = 64): refused, it "reaches" H
    exact = _tyre(R=64.0, b=1.0, H=8.0, E=1.0)
    assert refused(exact.deflection, 64.0) == "P = 64.0: deflection 8 mm reaches the rubber thickness H = 8 mm"
    assert float(exact.deflection(63.0)) == pytest.approx(63.0 / 8.0, rel=1e-15)
    msg = refused(t.deflection, [below, 1.002 * P_star, 0.5 * P_star])
    assert msg == (f"P = {float(1.002 * P_star)!r}: deflection {1.002 * H:.4g} mm reaches the rubber thickness "
                   f"H = 8 mm")


def test_solid_tyre_chain_exact():
    R, b, H, E, alpha, psi, F = 200.0, 50.0, 30.0, 4.0, 40.0, 0.3, 3e5
    t = _tyre(R=R, b=b, H=H, E=E, alpha=alpha, psi=psi, F=F)
    P, V = 5000.0, 30.0
    l = 2 * (H / R) ** (1 / 3) * math.sqrt(R * P / (E * b))
    lam = l * l / (8 * R)
    q = 4 * P / (math.pi * b * l)
    A = math.pi * q * lam * b * R * (1 - lam / (2 * R)) / 1000.0
    n = 60 * V / (3.6 * 2 * math.pi * R / 1000.0)
    Q = psi * A * n / 60
    assert float(t.contact_length(P)) == pytest.approx(l, rel=1e-14)
    assert float(t.deflection(P)) == pytest.approx(lam, rel=1e-14)
    assert float(t.q_m(P)) == pytest.approx(q, rel=1e-14)
    assert float(t.q_mean(P)) == pytest.approx(P / (b * l), rel=1e-14)
    assert float(t.work_per_turn(P)) == pytest.approx(A, rel=1e-14)
    assert float(t.heat_rate(P, V)) == pytest.approx(Q, rel=1e-14)
    assert float(t.heat_rate(P, V, True)) == pytest.approx(2 * Q, rel=1e-14)
    assert float(t.heat_rate(P, V, as_printed_n=True)) == pytest.approx(2 * Q, rel=1e-14)
    assert float(t.temperature(P, V)) == pytest.approx(20.0 + Q / (alpha * F * 1e-6), rel=1e-14)
    assert float(t.temperature(P, V, -5.0)) == pytest.approx(-5.0 + Q / (alpha * F * 1e-6), rel=1e-14)
    assert float(t.temperature(P, V, 0.0, True)) == pytest.approx(2 * Q / (alpha * F * 1e-6), rel=1e-14)
    assert float(t.temperature(P, V, t_air=0.0, as_printed_n=True)) == pytest.approx(2 * Q / (alpha * F * 1e-6),
                                                                                     rel=1e-14)
    assert refused(t.temperature, P, V, float("inf")) == "t_air = inf: must be a finite number"
    # arrays broadcast
    T = t.temperature(np.array([P, 2 * P]), np.array([V, V]))
    assert T.shape == (2,)


def test_solid_tyre_temperature_curve_exact():
    t = _tyre(R=200.0, b=50.0, H=30.0, E=4.0, alpha=40.0, psi=0.3, F=3e5)
    c = t.temperature_curve(5000.0, 60.0, 10.0, 3)
    assert set(c) == {"V_kmh", "n_rpm", "Q_W", "T_C"}
    assert c["V_kmh"].tolist() == [0.0, 30.0, 60.0]
    assert c["n_rpm"] == pytest.approx([0.0, 30 / 3.6 / (2 * math.pi * 0.2) * 60, 60 / 3.6 / (2 * math.pi * 0.2) * 60],
                                       rel=1e-14)
    Q = t.heat_rate(5000.0, 30.0)
    assert c["Q_W"] == pytest.approx([0.0, float(Q), 2 * float(Q)], rel=1e-14)
    assert c["T_C"] == pytest.approx([10.0, 10.0 + float(Q) / 12.0, 10.0 + 2 * float(Q) / 12.0], rel=1e-14)
    d = t.temperature_curve(5000.0, 60.0)        # defaults: t_air 20, 51 samples
    assert len(d["V_kmh"]) == 51 and d["T_C"][0] == 20.0
    assert len(t.temperature_curve(5000.0, 60.0, num=2)["V_kmh"]) == 2
    assert len(t.temperature_curve(5000.0, 60.0, num=2.7)["V_kmh"]) == 2
    assert refused(t.temperature_curve, 5000.0, 60.0, num=1) == "num = 1: need >= 2 samples"
    assert refused(t.temperature_curve, 5000.0, 0.0) == "V_max = 0.0: must be > 0 km/h"


# ============================================================== damper_heat.py (seed 004 ch. 6, eq. 73-75, Table 11)

def test_damper_station_refusals_and_table11_defaults():
    from propulsor.laws.damper_heat import Station

    for k in ("m1", "C1", "m2", "C2", "b2", "m_a", "c_steel", "S"):
        kw = dict(m1=400.0, C1=2.0e6, b1=2.0e3)
        kw[k] = 0.0
        assert refused(Station, **kw) == f"{k} = 0.0: must be > 0"
        kw[k] = -1.0
        assert refused(Station, **kw) == f"{k} = -1.0: must be > 0"
    st = Station(m1=400.0, C1=2.0e6, b1=0.0)          # no tyre damping is allowed
    assert (st.m2, st.C2, st.b2, st.m_a, st.c_steel, st.S, st.rho_air, st.c_air, st.T_env) == (
        3125.0, 164400.0, 3.426e4, 20.0, 487.0, 0.247, 1.2, 1005.0, 20.0)


def test_damper_cooling_coefficient_exact():
    from propulsor.laws.damper_heat import Station, cooling_coefficient

    st = Station(m1=1.0, C1=1.0, b1=0.0, S=0.5, rho_air=2.0, c_air=1000.0)
    assert cooling_coefficient(st, 3.0) == 3.0 * 0.5 * 2.0 * 1000.0


def _station_numbers():
    from propulsor.laws.damper_heat import Station

    return Station(m1=2.0, C1=30.0, b1=5.0, m2=7.0, C2=11.0, b2=3.0, m_a=4.0, c_steel=0.5, S=0.25, rho_air=2.0,
                   c_air=8.0, T_env=10.0)


def test_damper_system_matrix_written_out():
    from propulsor.laws.damper_heat import Road, _system

    st = _station_numbers()
    m1, C1, b1, m2, C2, b2 = 2.0, 30.0, 5.0, 7.0, 11.0, 3.0
    M, x0, w = _system(st, Road(0.4, 2.0), 3.0, False)
    assert w == pytest.approx(2 * math.pi * 3.0 / 2.0, rel=1e-15)
    E = np.zeros((6, 6))
    E[0, 1] = E[2, 3] = 1.0
    E[1] = [-(C1 + C2) / m1, -(b1 + b2) / m1, C2 / m1, b2 / m1, C1 / m1, b1 * w / m1]
    E[3] = [C2 / m2, b2 / m2, -C2 / m2, -b2 / m2, 0, 0]
    E[4, 5], E[5, 4] = w, -w
    assert M == pytest.approx(E, rel=1e-15, abs=0)
    assert x0.tolist() == [0.0, 0.0, 0.0, 0.0, 0.0, 0.2]
    P, x0p, wp = _system(st, Road(0.4, 2.0), 3.0, True)
    E[1] = [-(C1 + C2) / m1, -b1 / m1, C2 / m1, 0.0, C1 / m1, b1 * w / m1]
    E[3] = [C2 / m2, -b2 / m2, -C2 / m2, b2 / m2, 0, 0]        # printed: - b2 (z1' - z2')
    assert P == pytest.approx(E, rel=1e-15, abs=0)
    assert x0p.tolist() == [0.0, 0.0, 0.0, 0.0, 0.0, 0.2] and wp == w


def test_damper_right_hand_side_written_out():
    from propulsor.laws.damper_heat import Road, _rhs

    st = _station_numbers()
    road = Road(0.4, 2.0)
    V, t = 3.0, 0.3
    y = [0.01, -0.2, 0.03, 0.5, 35.0]
    w = 2 * math.pi * V / 2.0
    q, dq = 0.2 * math.sin(w * t), 0.2 * w * math.cos(w * t)
    k_air = V * 0.25 * 2.0 * 8.0
    P = 3.0 * (0.5 + 0.2) ** 2
    dT = (P - k_air * (35.0 - 10.0)) / (4.0 * 0.5)
    f, wf = _rhs(st, road, V, False)
    assert wf == pytest.approx(w, rel=1e-15)
    Fd = 3.0 * (0.5 + 0.2)
    a1 = (-30.0 * (0.01 - q) - 5.0 * (-0.2 - dq) - 11.0 * (0.01 - 0.03) + Fd) / 2.0
    a2 = (-11.0 * (0.03 - 0.01) - Fd) / 7.0
    assert f(t, y) == pytest.approx([-0.2, a1, 0.5, a2, dT], rel=1e-14)
    f, _ = _rhs(st, road, V, True)
    a1 = (-30.0 * (0.01 - q) - 11.0 * (0.01 - 0.03) - 5.0 * (-0.2 - dq)) / 2.0
    a2 = (-11.0 * (0.03 - 0.01) - 3.0 * (-0.2 - 0.5)) / 7.0
    assert f(t, y) == pytest.approx([-0.2, a1, 0.5, a2, dT], rel=1e-14)


def test_damper_powers_by_doubling():
    from propulsor.laws.damper_heat import _powers

    rng = np.random.default_rng(7)
    Phi = rng.normal(size=(4, 4)) / 2
    x = rng.normal(size=4)
    for n in range(1, 12):
        out = _powers(Phi, x, n)
        want = np.array([np.linalg.matrix_power(Phi, k) @ x for k in range(n)])
        assert out.shape == (n, 4)
        assert out == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_damper_simulate_refusal_and_grid():
    from propulsor.laws.damper_heat import Road, simulate

    st = _station_numbers()
    assert refused(simulate, st, Road(0.4, 2.0), 1.0, 0.0) == "t_end = 0.0: must be > 0 s"
    r = simulate(st, Road(0.4, 2.0), 1.0, 2.0, n_out=5)
    assert r.t.tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert r.V == 1.0 and r.T[0] == 10.0 and r.z2[0] == 0.0
    assert len(simulate(st, Road(0.4, 2.0), 1.0, 2.0).t) == 400
    one = simulate(st, Road(0.4, 2.0), 1.0, 2.0, n_out=1)
    assert one.t.tolist() == [0.0] and one.T.tolist() == [10.0]
    # at rest on the road (V = 0) nothing moves and nothing heats
    rest = simulate(st, Road(0.4, 2.0), 0.0, 2.0, n_out=3)
    assert rest.T.tolist() == [10.0, 10.0, 10.0] and rest.mean_power == 0.0 and rest.rise == 0.0


# ============================================================== traction.py (seed 004 ch. 4.1-4.2, ch. 5)

def test_traction_sprocket_torque_exact_and_refusals():
    from propulsor.laws import traction as tr

    assert tr.G_ACC == 9.81
    good = dict(f=0.5, M=2000.0, z=12, t=0.2, eta_gus=0.8)
    assert tr.sprocket_torque(**good) == pytest.approx(0.5 * 2000.0 * 9.81 * 12 * 0.2 / (2 * math.pi * 0.8),
                                                       rel=1e-15)
    assert tr.sprocket_torque(**good, g=10.0) == pytest.approx(0.5 * 2000.0 * 10.0 * 12 * 0.2 / (2 * math.pi * 0.8),
                                                               rel=1e-15)
    for name in ("f", "M", "z", "t", "eta_gus"):
        assert refused(tr.sprocket_torque, **{**good, name: 0}) == f"{name} = 0: must be > 0"


def test_traction_final_drive_torques_exact_and_refusals():
    from propulsor.laws import traction as tr

    assert tr.power_ratio(2.0, 0.9, 0.8) == pytest.approx(1.0 + 2.0 * 0.9 * 0.8, rel=1e-15)
    t = tr.final_drive_torques(1000.0, 5.0, 2.0, 0.9, 0.8, 1.5, 4)
    i_sil = 1.0 + 2.0 * 0.9 * 0.8
    eta = i_sil / 5.0
    assert (t.M_vk, t.i_br) == (1000.0, 5.0)
    assert t.i_sil == pytest.approx(i_sil, rel=1e-15)
    assert t.eta_br == pytest.approx(eta, rel=1e-15)
    assert t.M_sol == pytest.approx(1000.0 * 1.5 / (5.0 * eta), rel=1e-14)
    assert t.M_sat == pytest.approx(1000.0 * 1.5 / (5.0 * 4 * eta), rel=1e-14)
    assert t.M_ring == pytest.approx(1000.0 - 1000.0 / i_sil, rel=1e-14)
    assert refused(tr.final_drive_torques, 0.0, 5.0, 2.0, 0.9, 0.8, 1.5, 4) == "M_vk = 0.0: must be > 0"
    assert refused(tr.final_drive_torques, 1000.0, 5.0, 2.0, 0.9, 0.8, 1.5, 0) == "n_w = 0: must be > 0"
    assert tr.planet_bearing_load(1000.0, 1.5, 0.2, 3, 2) == pytest.approx(1000.0 * 1.5 / (0.2 * 3 * 2), rel=1e-15)
    assert refused(tr.planet_bearing_load, 1000.0, 1.5, 0.0, 3, 2) == "r_vod = 0.0: must be > 0"


def test_traction_track_forces_both_sides_of_the_slack_clamp():
    from propulsor.laws import traction as tr

    # P_t = 2 pi M / (z t); raw = P_0 - P_t / (1 + z_sv / z_rab)
    P_t = 2 * math.pi * 1000.0 / (10 * 0.5)
    raw = 5000.0 - P_t / (1.0 + 3 / 4)
    f = tr.track_forces(1000.0, 10, 0.5, 5000.0, 3, 4)
    assert f.P_t == pytest.approx(P_t, rel=1e-15)
    assert f.P_sv_raw == pytest.approx(raw, rel=1e-15) and raw > 0
    assert f.P_sv == pytest.approx(raw, rel=1e-15)
    assert f.P_r == pytest.approx(raw + P_t, rel=1e-15)
    c = math.cos(math.radians(30.0))
    assert f.Q == pytest.approx(math.sqrt(raw ** 2 + (raw + P_t) ** 2 + 2 * raw * (raw + P_t) * c), rel=1e-15)
    g = tr.track_forces(1000.0, 10, 0.5, 5000.0, 3, 4, wrap_deg=60.0)
    assert g.Q == pytest.approx(math.sqrt(raw ** 2 + (raw + P_t) ** 2 + raw * (raw + P_t)), rel=1e-14)
    low = tr.track_forces(1000.0, 10, 0.5, 100.0, 3, 4)       # a slack side that would push: clamped to 0
    assert low.P_sv_raw < 0 and low.P_sv == 0.0 and low.P_r == pytest.approx(P_t, rel=1e-15)
    assert low.Q == pytest.approx(P_t, rel=1e-15)
    assert refused(tr.track_forces, 1000.0, 10, 0.0, 5000.0, 3, 4) == "t = 0.0: must be > 0"


def test_traction_vehicle_defaults_are_seed_004_ch5():
    from propulsor.laws import traction as tr

    v = tr.Vehicle()
    assert (v.M, v.V_max, v.K_f, v.F, v.eta_gm_max, v.alpha_max_deg, v.i_slope, v.f_gr, v.f_gr_max, v.n_N, v.K_g,
            v.z, v.t, v.D_k, v.eta_r, v.f_r, v.B_0) == (50000.0, 50.0, 0.6, 10.293, 0.87, 30.0, 0.025, 0.015, 0.08,
                                                        2000.0, 1.25, 15, 0.125, 630.0, 0.94, 0.02, 0.034)


def test_traction_losses_and_power_exact():
    from propulsor.laws import traction as tr

    assert tr.transmission_efficiency([]) == 1.0
    assert tr.transmission_efficiency([(2, 1, 3), (1, 0, 2)]) == pytest.approx(
        0.985 ** 3 * 0.96 * 0.99 ** 5, rel=1e-15)
    assert tr.transmission_speed_loss(1500.0) == pytest.approx(4.57e-6 * 1500.0 ** 2 - 15.0 + 9.0, rel=1e-15)
    assert tr.rolling_loss_coefficient(0.05, 1000.0) == pytest.approx(0.05 - 0.0146, rel=1e-15)
    v = tr.Vehicle(M=1000.0, V_max=36.0, K_f=0.5, F=2.0, i_slope=0.01, f_gr=0.02, D_k=500.0, eta_r=0.9,
                   f_r=0.03, B_0=0.04)
    f_k = 0.04 - 1.46e-5 * 500.0
    assert tr.running_gear_speed_loss(v) == pytest.approx((0.03 + f_k) * 1000.0 * 9.81 * 36.0 / 3600.0, rel=1e-14)
    assert tr.running_gear_speed_loss(v, 18.0) == pytest.approx((0.03 + f_k) * 1000.0 * 9.81 * 18.0 / 3600.0,
                                                                rel=1e-14)
    road = 0.03 * 1000.0 * 9.81 * 36.0 / (3600.0 * 0.9)
    air = 0.5 * 2.0 * 36.0 ** 3 / (3.6 ** 3 * 1e3 * 0.9)
    N_sgm = (0.03 + f_k) * 1000.0 * 9.81 * 36.0 / 3600.0
    assert tr.engine_power_required(v, 0.8, 2.5) == pytest.approx((road + air + N_sgm) / 0.8 + 2.5, rel=1e-14)
    w = tr.Vehicle(M=1000.0, alpha_max_deg=20.0, f_gr_max=0.1)
    a = math.radians(20.0)
    assert tr.max_traction_force(w) == pytest.approx((0.1 * math.cos(a) + math.sin(a)) * 1000.0 * 9.81, rel=1e-15)
    assert tr.min_speed(100.0, 0.8, 2e5) == pytest.approx(3600.0 * 100.0 * 0.8 / 2e5, rel=1e-15)


def test_traction_gears_exact():
    from propulsor.laws import traction as tr

    assert tr.gear_count(60.0, 5.0, 1.5, 1.3) == pytest.approx(
        (math.log(60.0) - math.log(5.0) - math.log(1.5)) / math.log(1.3), rel=1e-14)
    assert tr.progression_ratio(60.0, 5.0, 1.5, 5) == pytest.approx((60.0 / 7.5) ** 0.25, rel=1e-15)
    assert tr.gear_top_speeds(5.0, 1.5, 2.0, 4) == pytest.approx([5.0, 15.0, 30.0, 60.0], rel=1e-15)
    assert tr.gear_top_speeds(5.0, 1.5, 2.0, 1) == [5.0]
    assert refused(tr.gear_top_speeds, 0.0, 1.5, 2.0, 4) == "V_min = 0.0: must be > 0"
    assert refused(tr.gear_top_speeds, 5.0, 1.5, 2.0, 0) == "m_n = 0: must be > 0"
    assert tr.transmission_ratio(1800.0, 12, 0.2, 30.0) == pytest.approx(0.06 * 1800.0 * 12 * 0.2 / 30.0, rel=1e-15)
    assert refused(tr.transmission_ratio, 1800.0, 12, 0.2, 0.0) == "V = 0.0: must be > 0"
    assert tr.transmission_speed_loss_geared(1500.0, True) == pytest.approx(4.7e-6 * 1500.0 ** 2 - 14.85 + 9.0,
                                                                            rel=1e-14)
    assert tr.transmission_speed_loss_geared(1500.0, False) == pytest.approx(4.1e-6 * 1500.0 ** 2 - 14.85 + 7.4,
                                                                             rel=1e-14)
    assert tr.vehicle_speed(1800.0, 12, 0.2, 8.0) == pytest.approx(0.06 * 12 * 0.2 * 1800.0 / 8.0, rel=1e-15)
    assert refused(tr.vehicle_speed, 1800.0, 12, 0.2, 0.0) == "U = 0.0: must be > 0"
    assert tr.traction_coefficient(300.0, 10.0, 0.9, 20.0, 0.95, 1000.0, 20.0) == pytest.approx(
        3600.0 * ((300.0 - 10.0) * 0.9 - 20.0) * 0.95 / (1000.0 * 9.81 * 20.0), rel=1e-14)
    assert tr.traction_coefficient(300.0, 10.0, 0.9, 20.0, 0.95, 1000.0, 20.0, g=10.0) == pytest.approx(
        3600.0 * ((300.0 - 10.0) * 0.9 - 20.0) * 0.95 / (1000.0 * 10.0 * 20.0), rel=1e-14)
    assert refused(tr.traction_coefficient, 300.0, 10.0, 0.9, 20.0, 0.95, 1000.0, 0.0) == "V = 0.0: must be > 0"
    assert tr.resistance_coefficient(0.1, 0.3) == pytest.approx(0.1 * math.cos(0.3) + math.sin(0.3), rel=1e-15)


def test_traction_engine_characteristic_exact():
    from propulsor.laws import traction as tr

    assert tr.ENGINE_004[0] == (0.429, 0.4) and tr.ENGINE_004[-1] == (1.04, 0.5) and len(tr.ENGINE_004) == 8
    e = tr.engine_characteristic(500.0, 2000.0, modes=((0.5, 0.6), (1.0, 1.0)), N_exhaust=7.0)
    n = [1000.0, 2000.0]
    N = [300.0, 500.0]
    ej = [0.06 * 500.0 * 0.25, 0.06 * 500.0]
    vo = [0.03 * 500.0 * 0.25, 0.03 * 500.0]
    vsp = 0.035 * 500.0
    tot = [ej[k] + vo[k] + 7.0 + vsp for k in range(2)]
    assert e["n_k"] == n and e["N_ek"] == N
    assert e["M_ek"] == pytest.approx([9550.0 * 300.0 / 1000.0, 9550.0 * 500.0 / 2000.0], rel=1e-15)
    assert e["N_ej"] == pytest.approx(ej, rel=1e-15) and e["N_vo"] == pytest.approx(vo, rel=1e-15)
    assert e["N_vsp"] == pytest.approx([vsp, vsp], rel=1e-15)
    assert e["N_total"] == pytest.approx(tot, rel=1e-15)
    assert e["N_eob"] == pytest.approx([N[k] - tot[k] for k in range(2)], rel=1e-14)
    assert e["M_eob"] == pytest.approx([9550.0 * (N[k] - tot[k]) / n[k] for k in range(2)], rel=1e-14)
    d = tr.engine_characteristic(500.0, 2000.0)                  # Table 8's modes, no exhaust loss
    assert d["n_k"] == pytest.approx([2000.0 * a for a, _ in tr.ENGINE_004], rel=1e-15)
    assert d["N_total"][6] == pytest.approx(0.06 * 500 + 0.03 * 500 + 0.035 * 500, rel=1e-15)
    assert refused(tr.engine_characteristic, 0.0, 2000.0) == "N_e = 0.0: must be > 0"
    assert refused(tr.engine_characteristic, 500.0, 0.0) == "n_N = 0.0: must be > 0"


def test_traction_characteristic_exact():
    from propulsor.laws import traction as tr

    v = tr.Vehicle(M=20000.0, V_max=40.0, K_g=1.5, n_N=1800.0, z=12, t=0.2, D_k=500.0, eta_r=0.9, f_r=0.03,
                   B_0=0.04)
    modes = ((0.5, 0.6), (1.0, 1.0))
    c = tr.traction_characteristic(v, 400.0, 5.0, 3, 0.85, modes=modes, high_from=2)
    q = (40.0 / (1.5 * 5.0)) ** 0.5
    V_top = [5.0, 7.5 * q, 7.5 * q * q]          # V_j = V_min K_g q^(j-1), j >= 2
    assert c.V_top == pytest.approx(V_top, rel=1e-14)
    U = [0.06 * 1800.0 * 12 * 0.2 / x for x in V_top]
    assert c.U == pytest.approx(U, rel=1e-14)
    e = tr.engine_characteristic(400.0, 1800.0, modes)
    assert c.n_k == tuple(e["n_k"]) and c.N_eob == tuple(e["N_eob"])
    f_loss = 0.03 + 0.04 - 1.46e-5 * 500.0
    for j in range(3):
        high = j >= 1
        for k, n in enumerate(e["n_k"]):
            Vx = 0.06 * 12 * 0.2 * n / U[j]
            s = (4.7e-6 * n * n - 0.0099 * n + 9.0) if high else (4.1e-6 * n * n - 0.0099 * n + 7.4)
            cr = f_loss * 20000.0 * 9.81 * Vx / 3600.0
            assert c.V[j][k] == pytest.approx(Vx, rel=1e-14)
            assert c.N_str[j][k] == pytest.approx(s, rel=1e-14)
            assert c.N_cr[j][k] == pytest.approx(cr, rel=1e-14)
            assert c.f_g[j][k] == pytest.approx(3600.0 * ((e["N_eob"][k] - s) * 0.85 - cr) * 0.9 / (20000.0 * 9.81 * Vx),
                                                rel=1e-13)
    # defaults: Table 8's eight modes, gears 3 and up high (eq. 71)
    d = tr.traction_characteristic(v, 400.0, 5.0, 4, 0.85)
    assert len(d.n_k) == 8 and len(d.V) == 4 and all(len(row) == 8 for row in d.f_g)
    n0 = d.n_k[0]
    assert d.N_str[1][0] == pytest.approx(4.1e-6 * n0 * n0 - 0.0099 * n0 + 7.4, rel=1e-14)
    assert d.N_str[2][0] == pytest.approx(4.7e-6 * n0 * n0 - 0.0099 * n0 + 9.0, rel=1e-14)


# ============================================================== shoe.py (seed 001 eq. 1-7, 11-13)

def _dsinc_series(x: float) -> float:
    """d/dx (sin x / x) = sum_k>=1 (-1)^k 2k x^(2k-1) / (2k+1)!, summed in 50-digit decimals."""
    from decimal import Decimal, getcontext

    getcontext().prec = 50
    X = Decimal(x)
    s, fact = Decimal(0), Decimal(1)
    for k in range(1, 30):
        fact *= (2 * k) * (2 * k + 1)                 # (2k+1)!
        s += (-1) ** k * 2 * k * X ** (2 * k - 1) / fact
    return float(s)


def test_shoe_sinc_and_its_derivative_on_both_sides_of_the_series_switch():
    from propulsor import policy
    from propulsor.laws.shoe import _dsinc, _sinc

    assert policy.SINC_SERIES_BELOW == 1e-2
    assert _sinc(0.0) == 1.0
    assert _sinc(np.array([0.3, -2.0])) == pytest.approx([math.sin(0.3) / 0.3, math.sin(2.0) / 2.0], rel=1e-15)
    # the series side (|x| < 0.01) is exact to rounding; the closed form loses digits to cancellation near 0.01
    for x, rel in ((0.0, 0), (1e-6, 1e-15), (1e-3, 1e-15), (-0.004, 1e-15), (0.0099, 1e-14), (-0.0099, 1e-14),
                   (0.0101, 1e-11), (-0.0101, 1e-11), (0.05, 1e-13), (-0.5, 1e-14), (2.0, 1e-14), (7.5, 1e-14)):
        assert float(_dsinc(x)) == pytest.approx(_dsinc_series(x), rel=rel, abs=1e-300), x
    xs = np.array([0.0, 0.0099, -0.02, 3.0])
    assert _dsinc(xs) == pytest.approx([_dsinc_series(v) for v in xs], rel=1e-12, abs=1e-300)


def test_shoe_polyline_self_intersection_cases():
    from propulsor.laws.shoe import _segments_intersect

    assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0]]))
    assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]))
    # a Z folded back over its first segment crosses it
    assert _segments_intersect(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, -1.0]]))
    # the same three segments, the last one stopping short of the first: no crossing
    assert not _segments_intersect(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 0.5]]))
    # a convex arc never crosses itself
    t = np.linspace(0.0, 3.0, 40)
    assert not _segments_intersect(np.column_stack([np.cos(t), np.sin(t)]))
    # a loop (more than a full turn) does
    t = np.linspace(0.0, 7.0, 60)
    assert _segments_intersect(np.column_stack([(1 + 0.05 * t) * np.cos(t), (1 + 0.05 * t) * np.sin(t) + 0.3 * t]))
    # touching only at a segment's end (t = 0 or 1) is not a crossing; parallel segments never cross
    assert not _segments_intersect(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 0.0]]))
    assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [-1.0, 1.0]]))
    # a crossing of segments 0 and 2 in the middle of both (t = u = 1/2)
    assert _segments_intersect(np.array([[0.0, 0.0], [2.0, 0.0], [1.5, 1.0], [1.0, -1.0]]))
    # crossing the last segment only
    assert _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.5, -1.0]]))



def test_shoe_polyline_crossings_at_vertices_are_counted_once():
    """Segments are half-open [start, end): a crossing exactly at a vertex is found (it was missed when both ends were
    open), a point beyond a segment's end is not on it, and an exact fold-back is left to the radius test."""
    from propulsor.laws.shoe import _segments_intersect

    # segment 4 crosses the polyline exactly at its vertex (1, 0), the end of segment 0 and the start of segment 1
    assert _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.5, 1.0], [0.5, -1.0]]))
    # the polyline comes down onto segment 0 at (1, 0) (a vertex on it) and goes on through to the other side
    assert _segments_intersect(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 0.0], [0.5, -1.0]]))
    # segment 2 meets segment 0's line at x = 1.25, a quarter of a segment beyond its end (1, 0): no crossing
    assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [1.5, -1.0]]))
    # up to (0, 0), right to (1, 0), back left through (0, 0) to (-1, 0): a fold-back (a cusp), not a crossing here
    assert not _segments_intersect(np.array([[0.0, -1.0], [0.0, 0.0], [1.0, 0.0], [-1.0, 0.0]]))
    # a crossing whose cross product of directions is exactly 1 ((1, 0) x (0, 1)) at t = u = 1/2
    assert _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [0.5, -0.5], [0.5, 0.5]]))


def test_shoe_polyline_parallel_and_collinear_segments_raise_no_warning():
    """Parallel segments divide by a zero cross product (x/0 and 0/0): silently, and they never cross."""
    import warnings

    from propulsor.laws.shoe import _segments_intersect

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [-1.0, 1.0]]))
        assert not _segments_intersect(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]))   # 0/0

def _hand_table(radius, X=None, Y=None):
    from propulsor.laws.shoe import ShoeTable

    radius = np.asarray(radius, dtype=float)
    n = len(radius)
    phi = np.linspace(-0.5, 0.5, n)
    X = np.linspace(0.0, 1.0, n) if X is None else np.asarray(X, float)
    Y = np.zeros(n) if Y is None else np.asarray(Y, float)
    z = np.zeros(n)
    return ShoeTable(phi=phi, Y1=z, dY1=z, Y2=z, X_B=X, Y_B=Y, rho=z, alpha=z, radius=radius)


def test_shoe_loop_check_both_sides_of_the_radius_limit():
    from propulsor.laws.shoe import shoe_loop_check

    c = shoe_loop_check(_hand_table([3.0, 2.0, 0.5, 4.0, 5.0]))
    assert (c.radius_min, c.phi_at_min, c.self_intersecting, c.ok) == (0.5, 0.0, False, True)
    assert type(c.radius_min) is float and type(c.phi_at_min) is float
    assert shoe_loop_check(_hand_table([3.0, 2.0, 0.0, 4.0, 5.0])).ok is False          # 0 is not > 0
    assert shoe_loop_check(_hand_table([3.0, 2.0, 0.5, 4.0, 5.0]), 0.5).ok is False
    assert shoe_loop_check(_hand_table([3.0, 2.0, 0.5, 4.0, 5.0]), 0.49).ok is True
    c = shoe_loop_check(_hand_table([-1.0, 2.0, 0.5, 4.0, 5.0]))
    assert (c.radius_min, c.phi_at_min, c.ok) == (-1.0, -0.5, False)
    crossing = _hand_table([1.0, 1.0, 1.0, 1.0], X=[0.0, 2.0, 2.0, 1.0], Y=[0.0, 0.0, 1.0, -1.0])
    c = shoe_loop_check(crossing)
    assert c.self_intersecting is True and c.ok is False and c.radius_min == 1.0


def test_shoe_arc_length_is_the_trapezoid_of_the_radius():
    from propulsor.laws.shoe import shoe_arc_length

    tab = _hand_table([1.0, 3.0, 2.0, 5.0, 4.0])       # phi step 0.25
    assert shoe_arc_length(tab) == pytest.approx(0.25 * (0.5 + 3 + 2 + 5 + 2), rel=1e-15)
    assert type(shoe_arc_length(tab)) is float


class _FakeMotion:
    """A motion with a known hub speed and cam path (duck-typed for hub_travel_per_step and _depth)."""

    def __init__(self, s):
        from types import SimpleNamespace

        self.mech = SimpleNamespace(phi_s=s)

    def hub_speed(self, phi):
        return 3.0 + np.asarray(phi) ** 2 + np.asarray(phi) ** 3

    def H_derivs(self, phi):
        phi = np.asarray(phi, dtype=float)
        return 100.0 + 10.0 * phi ** 2, None, None, None


def test_shoe_hub_travel_per_step_and_depth_by_hand():
    from propulsor.laws.shoe import _depth, hub_travel_per_step

    m = _FakeMotion(0.6)
    for n in (5, 2001):
        phi = np.linspace(-0.6, 0.6, n)
        want = float(np.trapezoid(3.0 + phi ** 2 + phi ** 3, phi))
        assert hub_travel_per_step(m, n) == pytest.approx(want, rel=1e-14)
    phi = np.linspace(-0.6, 0.6, 2001)
    assert hub_travel_per_step(m) == pytest.approx(float(np.trapezoid(3.0 + phi ** 2, phi)), rel=1e-14)
    assert hub_travel_per_step(m, 3) == pytest.approx(0.6 * (3.36 + 2 * 3.0 + 3.36) / 2 * 2 / 2, rel=1e-14)
    p = np.array([0.2, -0.4])
    XB, YB = np.array([5.0, -3.0]), np.array([30.0, 40.0])
    want = (100.0 + 10.0 * p ** 2 + YB) * np.cos(p) + XB * np.sin(p)
    assert _depth(m, p, XB, YB) == pytest.approx(want, rel=1e-15)


def _cam(kind="quadratic", k0=0.017, **mech):
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion

    return cam_motion(CamMechanism(**mech), CurvatureLaw(kind, k0))


def test_shoe_table_against_eq7_eq11_eq13_written_out():
    from propulsor.laws.shoe import shoe_table

    cm = _cam()
    sup = cm.support
    phi = np.array([-0.7, -0.3, 0.2, 0.5, 0.78])
    tab = shoe_table(sup, phi)
    d = sup.derivs(phi)
    H, H1, H2 = d["H"], d["H1"], d["H2"]
    Y1 = H1 / np.tan(phi) - H                                                 # eq. 7 with eq. 1
    dY1 = H2 / np.tan(phi) - H1 / np.sin(phi) ** 2 - H1
    Y2 = 320.0 - (H + Y1) * np.cos(phi)                                       # R0 + r + C = 320 mm
    XB, YB = Y2 * np.sin(phi), Y1 + Y2 * np.cos(phi)                          # eq. 11
    assert tab.phi.tolist() == phi.tolist()
    assert tab.Y1 == pytest.approx(Y1, rel=1e-8)
    assert tab.dY1 == pytest.approx(dY1, rel=1e-8)
    assert tab.Y2 == pytest.approx(Y2, rel=1e-9)
    assert tab.X_B == pytest.approx(XB, rel=1e-9)
    assert tab.Y_B == pytest.approx(YB, rel=1e-8)
    assert tab.rho == pytest.approx(np.sqrt(XB ** 2 + YB ** 2), rel=1e-9)             # eq. 13
    assert tab.alpha == pytest.approx(np.arctan2(XB, YB), rel=1e-8)                   # eq. 12
    assert tab.radius == pytest.approx(Y2 - dY1 * np.sin(phi), rel=1e-8)
    # a scalar angle gives one row; at phi = 0 the limit Y1 = H''(0) - H(0) and Y1' = 0 (even law)
    z = shoe_table(sup, 0.0)
    d0 = sup.derivs(0.0)
    assert z.Y1.shape == (1,)
    assert z.Y1[0] == pytest.approx(d0["H2"][0] - d0["H"][0], abs=1e-9)
    assert z.dY1[0] == pytest.approx(0.0, abs=1e-9)
    assert z.X_B[0] == 0.0 and z.alpha[0] == 0.0
    assert z.Y2[0] == pytest.approx(320.0 - d0["H"][0] - z.Y1[0], rel=1e-15)
    # near 0 (the series side of sin x / x) the table is eq. 7 still
    p = np.array([-3e-3, 1e-3, 4e-3])
    e = shoe_table(sup, p)
    d = sup.derivs(p)
    assert e.Y1 == pytest.approx(d["H1"] / np.tan(p) - d["H"], abs=1e-7)
    assert e.dY1 == pytest.approx(d["H2"] / np.tan(p) - d["H1"] / np.sin(p) ** 2 - d["H1"], abs=1e-4)
    h = 1e-4
    fd = (shoe_table(sup, 0.3 + h).Y1 - shoe_table(sup, 0.3 - h).Y1) / (2 * h)
    assert shoe_table(sup, 0.3).dY1 == pytest.approx(fd, rel=1e-6)


def test_shoe_table_of_an_odd_law_uses_both_sides():
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import shoe_table

    cm = cam_motion(CamMechanism(), CurvatureLaw("linear", 0.005, symmetric=False))
    phi = np.array([-0.6, -0.25, 0.25, 0.6])
    tab = shoe_table(cm.support, phi)
    d = cm.support.derivs(phi)
    Y1 = d["H1"] / np.tan(phi) - d["H"]
    assert tab.Y1 == pytest.approx(Y1, rel=1e-7)
    assert tab.dY1 == pytest.approx(d["H2"] / np.tan(phi) - d["H1"] / np.sin(phi) ** 2 - d["H1"], rel=1e-7)


def test_shoe_footprint_ratio_and_travel_by_hand_on_a_real_cam():
    from propulsor.laws.shoe import footprint_ratio, hub_travel_per_step, shoe_table

    cm = _cam()
    s = math.pi / 4
    for n in (2001, 301):
        phi = np.linspace(-s, s, n)
        travel = float(np.trapezoid(cm.hub_speed(phi), phi))
        arc = float(np.trapezoid(shoe_table(cm.support, phi).radius, phi))
        assert hub_travel_per_step(cm, n) == pytest.approx(travel, rel=1e-14)
        assert footprint_ratio(cm, n) == pytest.approx(arc / travel, rel=1e-13)
        if n == 2001:
            assert hub_travel_per_step(cm) == pytest.approx(travel, rel=1e-14)
            assert footprint_ratio(cm) == pytest.approx(arc / travel, rel=1e-13)


def _brute_depth(cm, legs, n=400001):
    from propulsor.laws.shoe import _depth, shoe_table

    s = cm.mech.phi_s
    grid = np.linspace(-s, s, n)
    tab = shoe_table(cm.support, grid)
    return [float(np.max(_depth(cm, np.full_like(grid, pl), tab.X_B, tab.Y_B))) for pl in legs]


def test_shoe_hub_height_on_flat_finds_the_lowest_point_of_every_leg():
    """A cam whose idle shoe digs into the ground (an odd law): the hub height on flat is not constant, and the
    refined search equals a brute force over 100 001 shoe points to 1e-6 mm, where 41 samples are mm off."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import hub_height_on_flat

    cm = cam_motion(CamMechanism(), CurvatureLaw("linear", 0.005, symmetric=False), estimate_error=False)
    phi = np.array([0.0, 0.7])
    hh = hub_height_on_flat(cm, phi, n_shoe=41)
    want = [max(_brute_depth(cm, cm.leg_angles(p), 100001)) for p in phi]
    assert hh == pytest.approx(want, abs=1e-6)
    assert hub_height_on_flat(cm, 0.7).tolist() == pytest.approx([want[1]], abs=1e-6)
    assert want[1] - 320.0 > 1.0                 # a cam that does not keep the hub level
    coarse = max(_brute_depth(cm, cm.leg_angles(0.7), 41))
    assert want[1] - coarse > 1e-4
    # a single grid point (n_shoe = 1) is taken as it is
    one = hub_height_on_flat(cm, phi, n_shoe=1)
    from propulsor.laws.shoe import _depth, shoe_table

    t = shoe_table(cm.support, np.array([-cm.mech.phi_s]))
    want1 = [max(float(_depth(cm, np.array([pl]), t.X_B, t.Y_B)[0]) for pl in cm.leg_angles(p)) for p in phi]
    assert one == pytest.approx(want1, rel=1e-14)




def test_shoe_hub_height_on_flat_is_eq7s_constant_height_from_three_samples():
    """The cam of eq. 20 with eq. 7's shoes keeps the hub at R0 + r + C = 320 mm on flat ground (seed 001, eq. 5-7):
    the refinement between the neighbours of the best sample finds it even from 3 or 4 samples a shoe, where the
    samples alone are up to 10 mm low (at 0.3 and 0.7 rad the best sample is the last but one)."""
    from propulsor.laws.shoe import hub_height_on_flat

    cm = _cam()
    p = np.array([-0.6, -0.3436, 0.0, 0.3, 0.7])
    for n in (3, 4):
        assert hub_height_on_flat(cm, p, n_shoe=n) == pytest.approx(np.full(5, 320.0), abs=1e-9)

def test_shoe_hub_height_on_flat_refines_without_a_warning():
    """The bounded refinement gets its options as scipy names them (an unknown option is an OptimizeWarning)."""
    import warnings

    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import hub_height_on_flat

    cm = cam_motion(CamMechanism(), CurvatureLaw("linear", 0.005, symmetric=False), estimate_error=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        hh = hub_height_on_flat(cm, 0.7, n_shoe=41)
    assert hh[0] == pytest.approx(max(_brute_depth(cm, cm.leg_angles(0.7), 100001)), abs=1e-6)

def test_shoe_return_ground_clearance_of_the_idle_legs():
    from propulsor.laws.shoe import return_ground_clearance

    cm = _cam()
    for p in (-0.6, 0.0, 0.3):
        idle = [p + 2 * math.pi * j / 4 for j in (1, 2, 3)]
        for n in (801, 101):
            want = 320.0 - max(_brute_depth(cm, idle, n))
            got = return_ground_clearance(cm, p, n) if n != 801 else return_ground_clearance(cm, p)
            assert got.shape == (1,) and got[0] == pytest.approx(want, rel=1e-13)
    both = return_ground_clearance(cm, np.array([0.1, -0.2]), 201)
    assert both == pytest.approx([320.0 - max(_brute_depth(cm, [0.1 + 2 * math.pi * j / 4 for j in (1, 2, 3)], 201)),
                                  320.0 - max(_brute_depth(cm, [-0.2 + 2 * math.pi * j / 4 for j in (1, 2, 3)], 201))],
                                 rel=1e-13)



def test_shoe_return_ground_clearance_samples_801_points_of_the_shoe():
    """An odd law: an idle shoe's lowest point is inside its profile, not at its tip, so the clearance is that of the
    801 (or n) samples - 1e-4 mm from 802's, 0.07 mm from 50's (the tests above have the lowest point at a tip)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import return_ground_clearance

    cm = cam_motion(CamMechanism(), CurvatureLaw("linear", 0.005, symmetric=False), estimate_error=False)
    idle = [0.3 + 2 * math.pi * j / 4 for j in (1, 2, 3)]
    want = {n: 320.0 - max(_brute_depth(cm, idle, n)) for n in (801, 802, 50)}
    assert abs(want[801] - want[802]) > 1e-5 and abs(want[801] - want[50]) > 1e-2
    assert return_ground_clearance(cm, 0.3)[0] == pytest.approx(want[801], rel=1e-13)
    assert return_ground_clearance(cm, 0.3, 50)[0] == pytest.approx(want[50], rel=1e-13)

# ============================================================== suspension.py (seed 004 ch. 2, eq. 1-28)

def test_suspension_free_functions_exact():
    from propulsor.laws import suspension as s

    assert s.G_ACC == 9.81
    P, R, b, t = 30000.0, 350.0, 0.7, 1500.0
    assert s.torsion_bar_diameter(P, R, b, t) == pytest.approx((64 * P * R * math.sin(b) / (math.pi * t)) ** (1 / 3),
                                                                rel=1e-15)
    assert s.equivalent_stiffness(0.8, 30000.0, 0.5) == pytest.approx(2 * 0.8 * 30000.0 / 0.25, rel=1e-15)
    assert s.pitch_stiffness(4e5, 1.5, 8.0) == pytest.approx(2 * math.pi ** 2 * 4e5 / (2.25 * 8.0), rel=1e-15)
    assert s.pitch_period(4e5, 2e5, 8.0) == pytest.approx(math.sqrt(2 * math.pi ** 2 * 4e5 / (2e5 * 8.0)), rel=1e-15)
    ln = math.log(12.0)
    assert s.mean_damping_coefficient(2e5, 4e5, 8.0, 5.0, 12.0) == pytest.approx(
        math.sqrt(2) * ln / 5.0 * math.sqrt(2e5 * 4e5 * 8.0 / (4 * math.pi ** 2 + ln * ln)), rel=1e-14)
    assert s.rebound_damping_max(2e5, 1.5, 500.0, 80.0) == pytest.approx(2e5 * 1.5 / (4 * math.log(500.0 / 80.0)),
                                                                         rel=1e-15)
    R = (4e5 * 0.6 * 9.81 - 1.5e5 * 8 * 0.05 * 9.81) / 9.81 / (2 * 3)
    assert s.compression_force_max(4e5, 1.5e5, 8, 0.05, 3, 0.6) == pytest.approx(R, rel=1e-14)
    R5 = (4e5 * 0.5 * 9.81 - 1.5e5 * 8 * 0.05 * 9.81) / 9.81 / (2 * 3)
    assert s.compression_force_max(4e5, 1.5e5, 8, 0.05, 3) == pytest.approx(R5, rel=1e-14)
    assert s.rod_force_ratio(0.4) == 2.5 and s.rod_force_ratio(0.4, "lever") == 2.5
    assert s.rod_force_ratio(0.4, "literal") == 0.4
    assert s.damper_ear_arm(360.0, 0.4) == 144.0 and s.damper_ear_arm(360.0, 0.4, "lever") == 144.0
    assert s.damper_ear_arm(360.0, 0.4, "literal") == 900.0
    assert s.piston_diameter(1000.0, 2.0) == pytest.approx(math.sqrt(4000.0 / (2 * math.pi)), rel=1e-15)
    assert s.piston_diameter(1000.0, 2.0, 30.0) == pytest.approx(math.sqrt(4000.0 / (2 * math.pi) + 900.0), rel=1e-15)
    assert s.piston_diameter(1000.0, 2.0, 0.0) == s.piston_diameter(1000.0, 2.0)


def test_suspension_free_function_refusals_in_full():
    from propulsor.laws import suspension as s

    assert refused(s.torsion_bar_diameter, 0.0, 360.0, 0.7, 1600.0) == "P_st = 0.0: must be > 0 N"
    assert refused(s.torsion_bar_diameter, 1.0, 0.0, 0.7, 1600.0) == "R_b = 0.0: must be > 0 mm"
    assert refused(s.torsion_bar_diameter, 1.0, 360.0, 0.7, 0.0) == "tau_max = 0.0: must be > 0 MPa"
    assert refused(s.torsion_bar_diameter, 1.0, 360.0, float("nan"), 1.0) == "beta_st = nan: must be a finite number"
    for b in (0.0, math.pi, -0.1, 4.0):
        assert refused(s.torsion_bar_diameter, 1.0, 360.0, b, 1.0) == f"beta_st = {b!r}: must lie in (0, pi) rad"
    assert s.torsion_bar_diameter(1.0, 1.0, 1e-9, 1.0) > 0 and s.torsion_bar_diameter(1.0, 1.0, 3.14159, 1.0) > 0
    assert refused(s.equivalent_stiffness, 0.0, 1.0, 1.0) == "lambda_ut = 0.0: must be > 0"
    assert refused(s.equivalent_stiffness, 1.0, 0.0, 1.0) == "P_st = 0.0: must be > 0 N"
    assert refused(s.equivalent_stiffness, 1.0, 1.0, 0.0) == "f_full = 0.0: must be > 0"
    for fn in (s.pitch_stiffness, s.pitch_period):
        assert refused(fn, 0.0, 1.0, 1.0) == "I_y = 0.0: must be > 0 kg m^2"
        assert refused(fn, 1.0, 1.0, 0.0) == "sum_l2 = 0.0: must be > 0 m^2"
    assert refused(s.pitch_stiffness, 1.0, 0.0, 1.0) == "T_phi = 0.0: must be > 0 s"
    assert refused(s.pitch_period, 1.0, 0.0, 1.0) == "c = 0.0: must be > 0 N/m"
    m = s.mean_damping_coefficient
    assert refused(m, 0.0, 1.0, 1.0, 1.0, 2.0) == "c = 0.0: must be > 0 N/m"
    assert refused(m, 1.0, 0.0, 1.0, 1.0, 2.0) == "I_y = 0.0: must be > 0 kg m^2"
    assert refused(m, 1.0, 1.0, 0.0, 1.0, 2.0) == "sum_l2 = 0.0: must be > 0 m^2"
    assert refused(m, 1.0, 1.0, 1.0, 0.0, 2.0) == "sum_la2 = 0.0: must be > 0 m^2"
    assert refused(m, 1.0, 1.0, 1.0, 1.0, float("inf")) == "nu = inf: must be a finite number"
    assert refused(m, 1.0, 1.0, 1.0, 1.0, 1.0) == "nu = 1.0: amplitude ratio over one period must be > 1"
    assert m(1.0, 1.0, 1.0, 1.0, 1.0 + 1e-9) > 0
    r = s.rebound_damping_max
    assert refused(r, 0.0, 1.0, 2.0, 1.0) == "c = 0.0: must be > 0 N/m"
    assert refused(r, 1.0, 0.0, 2.0, 1.0) == "T_phi = 0.0: must be > 0 s"
    assert refused(r, 1.0, 1.0, 0.0, 1.0) == "f_full = 0.0: must be > 0"
    assert refused(r, 1.0, 1.0, 2.0, 0.0) == "f_st = 0.0: must be > 0"
    assert refused(r, 1.0, 1.0, 2.0, 2.0) == "f_full = 2.0: must exceed f_st = 2"
    assert refused(r, 1.0, 1.0, 2.0, 2.5) == "f_full = 2.0: must exceed f_st = 2.5"
    assert r(1.0, 1.0, 2.0 + 1e-9, 2.0) > 0
    c = s.compression_force_max
    assert refused(c, 0.0, 1.0, 8, 0.05, 3) == "G_p = 0.0: must be > 0 N"
    assert refused(c, 1.0, 0.0, 8, 0.05, 3) == "c = 0.0: must be > 0 N/m"
    assert refused(c, 1.0, 1.0, 0, 0.05, 3) == "n_side = 0: must be > 0"
    assert refused(c, 1.0, 1.0, 8, 0.0, 3) == "h_n = 0.0: must be > 0 m"
    assert refused(c, 1.0, 1.0, 8, 0.05, 0) == "n_a_side = 0: must be > 0"
    assert refused(c, 1.0, 1.0, 8, 0.05, 3, 0.0) == "zdd_over_g = 0.0: must be > 0"
    # R = 0 exactly: G_p zdd = c n h  (1000 * 0.5 = 100 * 10 * 0.5)
    assert refused(c, 1000.0, 100.0, 10, 0.5, 2) == "h_n = 0.5: bump too high: compression force limit 0 N <= 0"
    assert refused(c, 1000.0, 100.0, 10, 0.6, 2) == "h_n = 0.6: bump too high: compression force limit -25 N <= 0"
    assert c(1000.0, 100.0, 10, 0.4, 2) == pytest.approx(25.0, rel=1e-13)
    assert c(1000.0, 100.0, 10, 0.499, 2) == pytest.approx(0.25, rel=1e-9)          # a small positive limit
    assert refused(s.rod_force_ratio, 0.0) == "i_a = 0.0: must be > 0"
    assert refused(s.rod_force_ratio, 0.4, "lever arm") == \
        "damper_reading = 'lever arm': must be one of ('lever', 'literal')"
    assert refused(s.damper_ear_arm, 0.0, 0.4) == "R_b = 0.0: must be > 0"
    assert refused(s.damper_ear_arm, 360.0, 0.4, "x") == "damper_reading = 'x': must be one of ('lever', 'literal')"
    assert refused(s.piston_diameter, 0.0, 20.0) == "F_rod = 0.0: must be > 0 N"
    assert refused(s.piston_diameter, 1.0, 0.0) == "p_max = 0.0: must be > 0 MPa"
    assert refused(s.piston_diameter, 1.0, 1.0, float("nan")) == "d_rod = nan: must be a finite number"
    assert refused(s.piston_diameter, 1.0, 1.0, -1e-9) == "d_rod = -1e-09: must be >= 0 mm"


def test_suspension_deg_limits_both_sides():
    from propulsor.laws.suspension import _deg

    assert _deg("a", "10", 0.0, 180.0) == 10.0
    assert _deg("a", 1e-9, 0.0, 180.0) == 1e-9 and _deg("a", 179.999, 0.0, 180.0) == 179.999
    assert refused(_deg, "a", 0.0, 0.0, 180.0) == "a = 0.0: must lie in (0, 180) deg"
    assert refused(_deg, "a", 180.0, 0.0, 180.0) == "a = 180.0: must lie in (0, 180) deg"
    assert refused(_deg, "b", -180.5, -180.0, 180.0) == "b = -180.5: must lie in (-180, 180) deg"
    assert refused(_deg, "b", None, -180.0, 180.0) == "b = None: must be a number"


def _torsion(**kw):
    from propulsor.laws.suspension import TorsionSuspension

    return TorsionSuspension(**kw)


def test_torsion_suspension_refusals_in_full():
    assert refused(_torsion, P_st=0.0) == "P_st = 0.0: must be > 0 N"
    assert refused(_torsion, R_b=0.0) == "R_b = 0.0: must be > 0 mm"
    assert refused(_torsion, d_T=0.0) == "d_T = 0.0: must be > 0 mm"
    assert refused(_torsion, L_T=0.0) == "L_T = 0.0: must be > 0 mm"
    assert refused(_torsion, tau_max=0.0) == "tau_max = 0.0: must be > 0 MPa"
    assert refused(_torsion, G=0.0) == "G = 0.0: must be > 0 MPa"
    assert refused(_torsion, beta_st_deg=180.0) == "beta_st_deg = 180.0: must lie in (0, 180) deg"
    assert refused(_torsion, beta0_deg=-181.0) == "beta0_deg = -181.0: must lie in (-180, 180) deg"
    assert refused(_torsion, beta0_deg=43.144) == \
        "beta0_deg = 43.144: must be < beta_st_deg = 43.144 (travel angles out of order)"
    assert refused(_torsion, beta_m_deg=180.0) == "beta_m_deg = 180.0: must lie in (-180, 180) deg"
    assert refused(_torsion, beta_m_deg=43.144) == \
        "beta_m_deg = 43.144: must be > beta_st_deg = 43.144 (travel angles out of order)"
    # a bar so thin the static twist passes half a turn
    assert refused(_torsion, d_T=10.0) == "d_T = 10.0: static twist gamma_st >= 180 deg: bar far too thin"
    msg = refused(_torsion, d_T=29.0)
    t = dict(P_st=31490.0, R_b=360.0, b=math.radians(43.144), d=29.0, L=2000.0, tau=1600.0, G=83000.0)
    g_st = 32 * t["P_st"] * t["R_b"] * math.sin(t["b"]) * t["L"] / (math.pi * t["d"] ** 4 * t["G"])
    g_m = 2 * t["tau"] * t["L"] / (t["G"] * t["d"])
    assert g_st < math.pi and g_st >= g_m
    assert msg == (f"d_T = 29.0: torsion bar yields under the static load: gamma_st = {math.degrees(g_st):.6g} "
                   f">= gamma_m = {math.degrees(g_m):.6g} deg (tau > [tau] = 1600 MPa)")
    # beta0 adopted below zero: the balancer would swing through the vertical
    assert refused(_torsion, beta0_deg=-1.0, beta_m_deg=60.0) == (
        "beta0_deg = -1.0: must be > 0 deg: the balancer may not swing through the downward vertical "
        "(f(beta) would not be monotonic, P(beta) < 0)")
    assert _torsion(beta0_deg=1e-6, beta_m_deg=60.0).beta0_deg == 1e-6
    assert refused(_torsion, beta0_deg=0.0, beta_m_deg=60.0) == (
        "beta0_deg = 0.0: must be > 0 deg: the balancer may not swing through the downward vertical "
        "(f(beta) would not be monotonic, P(beta) < 0)")
    # an adopted beta0 so low that eq. 10's beta_m = beta0 + gamma_m stays below beta_st
    t = dict(tau=1600.0, L=500.0, G=83000.0, d=46.0)
    g_m = 2 * t["tau"] * t["L"] / (t["G"] * t["d"])
    b_m = math.radians(10.0) + g_m
    assert b_m < math.radians(170.0)
    assert refused(_torsion, beta_st_deg=170.0, beta0_deg=10.0, L_T=500.0) == (
        f"beta0_deg = {math.degrees(math.radians(10.0))!r}: travel angles out of order: need beta0 < beta_st = 170 "
        f"< beta_m = {math.degrees(b_m):.6g} deg")


def test_torsion_suspension_stored_values_and_travel_exact():
    t = _torsion(P_st="30000", R_b=350, beta_st_deg=40, d_T=48, L_T=2100, tau_max=1500, G=80000)
    assert (t.P_st, t.R_b, t.beta_st_deg, t.d_T, t.L_T, t.tau_max, t.G) == (30000.0, 350.0, 40.0, 48.0, 2100.0,
                                                                              1500.0, 80000.0)
    assert all(type(v) is float for v in (t.P_st, t.R_b, t.beta_st_deg, t.d_T, t.L_T, t.tau_max, t.G))
    b_st = math.radians(40.0)
    g_st = 32 * 30000.0 * 350.0 * math.sin(b_st) * 2100.0 / (math.pi * 48.0 ** 4 * 80000.0)
    b0 = b_st - g_st
    k = 80000.0 * math.pi * 48.0 ** 4 / 32 / 2100.0
    beta = np.array([b0, 0.9, 1.3])
    assert t.f(beta) == pytest.approx(350.0 * (math.cos(b0) - np.cos(beta)), rel=1e-14, abs=1e-12)
    assert t.M_T(beta) == pytest.approx(k * (beta - b0), rel=1e-14, abs=1e-9)
    assert t.P(beta[1:]) == pytest.approx(k * (beta[1:] - b0) / (350.0 * np.sin(beta[1:])), rel=1e-14)
    assert t.tau(beta) == pytest.approx(80000.0 * 48.0 * (beta - b0) / 4200.0, rel=1e-14, abs=1e-12)
    assert float(t.f(0.9)) == pytest.approx(350.0 * (math.cos(b0) - math.cos(0.9)), rel=1e-14)
    c = t.characteristic(5)
    b_m = b0 + 2 * 1500.0 * 2100.0 / (80000.0 * 48.0)
    assert c["beta"] == pytest.approx(np.linspace(b0, b_m, 5), rel=1e-15)
    assert c["f"] == pytest.approx(t.f(c["beta"]), rel=1e-15) and c["P"] == pytest.approx(t.P(c["beta"]), rel=1e-15)
    assert c["M_T"] == pytest.approx(t.M_T(c["beta"]), rel=1e-15)
    assert len(t.characteristic()["beta"]) == 201
    assert len(t.characteristic(2)["beta"]) == 2 and len(t.characteristic(2.9)["beta"]) == 2
    assert refused(t.characteristic, 1) == "num = 1: need >= 2 samples"
    # adopted angles are kept (as floats) and used
    a = _torsion(beta0_deg="19", beta_m_deg=115)
    assert (a.beta0_deg, a.beta_m_deg) == (19.0, 115.0) and type(a.beta_m_deg) is float
    assert a.beta0 == pytest.approx(math.radians(19.0), rel=1e-15)
    assert a.beta_m == pytest.approx(math.radians(115.0), rel=1e-15)


def test_torsion_suspension_yield_at_beta_m_both_sides():
    # the adopted beta_m at exactly beta0 + gamma_m is accepted (tau = [tau]), a hair beyond is refused
    t = _torsion()
    bm = math.degrees(t.beta0 + t.gamma_m)
    assert _torsion(beta_m_deg=bm).beta_m_deg == bm
    over = bm + 0.01
    msg = refused(_torsion, beta_m_deg=over)
    tau_m = t.G * t.d_T * (math.radians(over) - t.beta0) / (2 * t.L_T)
    assert msg == (f"beta_m_deg = {over!r}: torsion bar yields at beta_m: tau = {tau_m:.6g} MPa > [tau] = 1600 MPa "
                   f"(twist {math.degrees(math.radians(over) - t.beta0):.6g} > gamma_m = "
                   f"{math.degrees(t.gamma_m):.6g} deg)")
    # the beta_m computed from eq. 10 past 180 deg: refused with its value
    msg = refused(_torsion, beta_st_deg=150.0, L_T=4000.0)
    t = _torsion(beta_st_deg=150.0, L_T=4000.0, beta_m_deg=179.0)       # the same bar with beta_m adopted
    assert msg == f"beta_m_deg = {math.degrees(t.beta0 + t.gamma_m)!r}" + (
        ": must be < 180 deg (P(beta) = M / (R_b sin beta) is singular there)")


def _design(**kw):
    from propulsor.laws.suspension import SuspensionDesign

    args = dict(wheel_x_m=(-2.0, -0.5, 1.0, 2.5), damper_x_m=(-2.0, 2.5))
    args.update(kw)
    return SuspensionDesign(**args)


def test_suspension_design_refusals_in_full():
    assert refused(_design, torsion=3) == "torsion = 3: must be a TorsionSuspension"
    assert refused(_design, G_p=0.0) == "G_p = 0.0: must be > 0 N"
    assert refused(_design, I_y_kgm2=0.0) == "I_y_kgm2 = 0.0: must be > 0 kg m^2"
    assert refused(_design, wheel_x_m=(1.0, float("nan"))) == "wheel_x_m = nan: must be a finite number"
    assert refused(_design, wheel_x_m=(1.0,), damper_x_m=(1.0,)) == \
        "wheel_x_m = (1.0,): need >= 2 wheel positions per side"
    assert refused(_design, wheel_x_m=(1.0, 1.0, 2.0)) == "wheel_x_m = (1.0, 1.0, 2.0): wheel positions must be distinct"
    assert refused(_design, damper_x_m=(float("inf"),)) == "damper_x_m = inf: must be a finite number"
    assert refused(_design, damper_x_m=()) == "damper_x_m = (): need >= 1 damped wheel per side"
    assert refused(_design, damper_x_m=(-2.0, 2.4)) == "damper_x_m = 2.4: a damper must sit on a wheel of wheel_x_m"
    assert refused(_design, damper_x_m=(-2.0 + 2e-9,)) == \
        f"damper_x_m = {-2.0 + 2e-9!r}: a damper must sit on a wheel of wheel_x_m"
    assert _design(damper_x_m=(-2.0 + 5e-10,)).damper_x_m == (-2.0 + 5e-10,)
    # exactly the tolerance (1e-9 m) off a wheel still sits on it
    assert _design(wheel_x_m=(0.0, 2.0), damper_x_m=(1e-9,)).damper_x_m == (1e-9,)
    assert refused(_design, wheel_x_m=(0.0, 2.0), damper_x_m=(1.0000001e-9,)) == \
        "damper_x_m = 1.0000001e-09: a damper must sit on a wheel of wheel_x_m"
    assert refused(_design, damper_x_m=(-2.0, -2.0)) == "damper_x_m = (-2.0, -2.0): one damper per wheel"
    assert refused(_design, T_phi=0.0) == "T_phi = 0.0: must be > 0 s"
    assert refused(_design, nu=float("nan")) == "nu = nan: must be a finite number"
    assert refused(_design, nu=1.0) == "nu = 1.0: must be > 1"
    assert refused(_design, reb_factor=float("inf")) == "reb_factor = inf: must be a finite number"
    for rf in (0.0, 1.0000001):
        assert refused(_design, reb_factor=rf) == f"reb_factor = {rf!r}: must lie in (0, 1] (seed: 0.8 ... 0.9)"
    assert _design(reb_factor=1.0).reb_factor == 1.0 and _design(nu=1.0001).nu == 1.0001
    assert refused(_design, h_n_m=0.0) == "h_n_m = 0.0: must be > 0 m"
    assert refused(_design, zdd_over_g=0.0) == "zdd_over_g = 0.0: must be > 0"
    assert refused(_design, i_a=0.0) == "i_a = 0.0: must be > 0"
    assert refused(_design, damper_reading="x") == "damper_reading = 'x': must be one of ('lever', 'literal')"
    assert refused(_design, p_max=0.0) == "p_max = 0.0: must be > 0 MPa"
    assert refused(_design, d_rod=float("nan")) == "d_rod = nan: must be a finite number"
    assert refused(_design, d_rod=-0.5) == "d_rod = -0.5: must be >= 0 mm"
    assert _design(d_rod=0.0).d_rod == 0.0


def test_suspension_design_stores_floats_and_defaults():
    d = _design(G_p="4e5", I_y_kgm2=4, wheel_x_m=[-2, "1"], damper_x_m=["-2"], T_phi="1.5", h_n_m="0.04",
                zdd_over_g="0.6", i_a="0.5", p_max="25")
    assert (d.G_p, d.I_y_kgm2, d.wheel_x_m, d.damper_x_m, d.T_phi, d.h_n_m, d.zdd_over_g, d.i_a, d.p_max) == (
        4e5, 4.0, (-2.0, 1.0), (-2.0,), 1.5, 0.04, 0.6, 0.5, 25.0)
    assert all(type(v) is float for v in (d.G_p, d.I_y_kgm2, d.T_phi, d.h_n_m, d.zdd_over_g, d.i_a, d.p_max)
               + d.wheel_x_m + d.damper_x_m)
    e = _design()
    assert (e.G_p, e.I_y_kgm2, e.T_phi, e.nu, e.reb_factor, e.h_n_m, e.zdd_over_g, e.i_a, e.damper_reading,
            e.p_max, e.d_rod) == (473000.0, 421100.0, 1.8, 13.5, 0.85, 0.05, 0.5, 0.453, "lever", 20.0, 40.0)


def test_suspension_uniform_wheel_positions_and_thesis_design():
    from propulsor.laws.suspension import thesis_design, uniform_wheel_positions

    assert uniform_wheel_positions(3, 4.0) == (-2.0, 0.0, 2.0)
    assert uniform_wheel_positions(3, 4.0, 1.0) == (-1.0, 1.0, 3.0)
    assert uniform_wheel_positions(2.0, 4.0, 0.0) == (0.0, 4.0)
    assert all(type(x) is float for x in uniform_wheel_positions(3, 4.0))
    assert refused(uniform_wheel_positions, 0, 4.0) == "n_side = 0: must be > 0"
    assert refused(uniform_wheel_positions, 1, 4.0) == "n_side = 1: need >= 2 wheels"
    assert refused(uniform_wheel_positions, 3, 0.0) == "base_m = 0.0: must be > 0 m"
    assert refused(uniform_wheel_positions, 3, 4.0, float("nan")) == "x_cg_m = nan: must be a finite number"
    d = thesis_design()
    xs = tuple(float(x) for x in np.linspace(0.0, 6.846, 8) - 3.423)
    assert d.wheel_x_m == pytest.approx(xs, rel=1e-15)
    assert d.damper_x_m == pytest.approx((xs[0], xs[1], xs[6], xs[7]), rel=1e-15)
    assert d.torsion.P_st == 31490.0 and d.torsion.beta0_deg is None and d.T_phi == 1.8


# ============================================================== balancer_beam.py (seed 004 ch. 8)

def test_balancer_limit_check_both_sides():
    from propulsor.laws.balancer_beam import _limit_check

    c = _limit_check("x", 2.0, 2.0, "MPa")
    assert (c.name, c.passed, c.value, c.limit, c.unit) == ("x", True, 2.0, 2.0, "MPa")
    assert _limit_check("x", 2.0000001, 2.0, "MPa").passed is False
    assert _limit_check("x", 2.0, 2.0, "-", kind="min").passed is True
    assert _limit_check("x", 1.9999999, 2.0, "-", kind="min").passed is False
    assert _limit_check("x", 3.0, 2.0, "-", "min").passed is True
    assert _limit_check("name", 1.0, 2.0, "-").message == "name"
    assert _limit_check("name", 1.0, 2.0, "-", note="why").message == "why"


def test_balancer_point_load_refusals_and_floats():
    from propulsor.laws.balancer_beam import PointLoad

    p = PointLoad("w", "1", 2, 3, 4)
    assert (p.s, p.z, p.F_x, p.F_y) == (1.0, 2.0, 3.0, 4.0) and all(type(v) is float for v in (p.s, p.z, p.F_x, p.F_y))
    for k in ("s", "z", "F_x", "F_y"):
        kw = dict(s=1.0, z=2.0, F_x=3.0, F_y=4.0)
        kw[k] = float("nan")
        assert refused(PointLoad, "w", **kw) == f"w.{k} = nan: must be a finite number"


def test_balancer_geometry_refusals_in_full():
    from propulsor.laws.balancer_beam import BalancerGeometry as G

    for k in ("b", "h", "s_stop", "a1", "a2", "d_upper", "D_upper", "r_upper", "d_lower", "D_lower", "r_lower",
              "h_min", "h_max"):
        assert refused(G, **{k: 0.0}) == f"{k} = 0.0: must be > 0 mm"
    assert refused(G, e_w=float("nan")) == "e_w = nan: must be a finite number"
    assert refused(G, e_a=float("inf")) == "e_a = inf: must be a finite number"
    assert refused(G, t_wall=0.0) == "t_wall = 0.0: must be > 0 mm"
    assert refused(G, t_wall=30.0) == "t_wall = 30.0: must be < b/2 = 30 mm"
    assert refused(G, t_wall=20.0) == "t_wall = 20.0: must be < h_min/2 = 20 mm"
    assert G(t_wall=19.99).t_wall == 19.99 and G(t_wall=29.0, h_min=60.0).t_wall == 29.0
    assert refused(G, a1=200.0) == "a2 = 200.0: second bearing must lie beyond a1 = 200 mm"
    assert refused(G, h_min=400.0) == "h_min = 400.0: must be < h_max = 400 mm"
    assert refused(G, D_upper=110.0) == "D_upper = 110.0: shoulder must exceed the journal d_upper = 110 mm"
    assert refused(G, D_lower=90.0) == "D_lower = 90.0: shoulder must exceed the spindle d_lower = 90 mm"
    assert refused(G, d_upper_bore=float("nan")) == "d_upper_bore = nan: must be a finite number"
    assert refused(G, d_upper_bore=110.0) == "d_upper_bore = 110.0: must lie in [0, d_upper = 110) mm"
    assert refused(G, d_upper_bore=-1.0) == "d_upper_bore = -1.0: must lie in [0, d_upper = 110) mm"
    assert refused(G, d_lower_bore=90.0) == "d_lower_bore = 90.0: must lie in [0, d_lower = 90) mm"
    assert G(d_upper_bore=109.9, d_lower_bore="89.9").d_lower_bore == 89.9
    assert refused(G, e_w=30.0) == "e_w = 30.0: wheel mid-plane must lie outboard of the arm face b/2 = 30 mm"
    g = G(e_w=30.001, b="60", e_a=5)
    assert g.e_w == 30.001 and g.b == 60.0 and type(g.e_a) is float and type(g.d_upper_bore) is float
    d = G()
    assert (d.b, d.h, d.t_wall, d.e_w, d.e_a, d.s_stop, d.a1, d.a2, d.d_upper, d.D_upper, d.r_upper, d.d_lower,
            d.D_lower, d.r_lower, d.h_min, d.h_max, d.d_upper_bore, d.d_lower_bore) == (
        60.0, 120.0, None, 150.0, 0.0, 300.0, 60.0, 200.0, 110.0, 150.0, 6.0, 90.0, 130.0, 6.0, 40.0, 400.0, 0.0, 0.0)


def _rect_torsion_reference(a, b, terms=40):
    """Timoshenko & Goodier §109 for a >= b, summed here with many terms."""
    J = a * b ** 3 / 3 * (1 - 192 * b / (math.pi ** 5 * a) * sum(math.tanh(n * math.pi * a / (2 * b)) / n ** 5
                                                                   for n in range(1, 2 * terms, 2)))
    s = sum(1 / (n ** 2 * math.cosh(min(n * math.pi * a / (2 * b), 700.0))) for n in range(1, 2 * terms, 2))
    return J, b / J * (1 - 8 / math.pi ** 2 * s)


def test_balancer_rect_torsion_and_sections_exact():
    from propulsor.laws.balancer_beam import RectSection, _rect_torsion

    for a, b in ((120.0, 60.0), (60.0, 120.0), (50.0, 50.0), (400.0, 10.0)):
        J, k = _rect_torsion(a, b)
        Jr, kr = _rect_torsion_reference(max(a, b), min(a, b))            # the module's 40 terms
        assert J == pytest.approx(Jr, rel=1e-13) and k == pytest.approx(kr, rel=1e-13)
        Jc, kc = _rect_torsion_reference(max(a, b), min(a, b), 4000)     # converged: 40 terms are within 1e-8
        assert J == pytest.approx(Jc, rel=1e-8) and k == pytest.approx(kc, rel=1e-8)
    # two terms only: a coarser value (the default is 40)
    assert _rect_torsion(50.0, 50.0, 1)[0] != pytest.approx(_rect_torsion(50.0, 50.0)[0], rel=1e-6)
    assert _rect_torsion(50.0, 50.0, 40) == _rect_torsion(50.0, 50.0)
    s = RectSection(60, "100")
    assert (s.b, s.h, s.t) == (60.0, 100.0, None) and type(s.b) is float
    assert s.A == 6000.0 and s.I_z == 60 * 100 ** 3 / 12 and s.I_y == 100 * 60 ** 3 / 12
    assert s.W_z == pytest.approx(60 * 100 ** 2 / 6, rel=1e-15) and s.W_y == pytest.approx(100 * 60 ** 2 / 6, rel=1e-15)
    J, k = _rect_torsion(100.0, 60.0)
    assert s.J_t == J and float(s.tau_torsion(-2e6)) == pytest.approx(2e6 * k, rel=1e-15)
    assert float(s.tau_shear_y(-6000.0)) == pytest.approx(1.5, rel=1e-15)
    hs = RectSection(60.0, 100.0, 5)
    assert hs.t == 5.0 and type(hs.t) is float
    assert hs.A == 6000.0 - 50 * 90 and hs.I_y == pytest.approx((100 * 60 ** 3 - 90 * 50 ** 3) / 12, rel=1e-15)
    Q = (60 * 100 ** 2 - 50 * 90 ** 2) / 8
    assert float(hs.tau_shear_y(1000.0)) == pytest.approx(1000.0 * Q / (hs.I_z * 10.0), rel=1e-15)
    assert refused(RectSection, 0.0, 1.0) == "b = 0.0: must be > 0 mm"
    assert refused(RectSection, 1.0, 0.0) == "h = 0.0: must be > 0 mm"
    assert refused(RectSection, 10.0, 20.0, 0.0) == "t = 0.0: must be > 0 mm"
    assert refused(RectSection, 10.0, 20.0, 5.0) == "t = 5.0: wall must be < half of min(b, h) = 5 mm"
    assert refused(RectSection, 20.0, 10.0, 5.0) == "t = 5.0: wall must be < half of min(b, h) = 5 mm"
    assert RectSection(10.0, 20.0, 4.999).t == 4.999


def test_balancer_von_mises_three_points_exact():
    from propulsor.laws.balancer_beam import RectSection

    for t in (None, 6.0):
        s = RectSection(60.0, 100.0, t)
        N, V, T, My, Mz = -3000.0, 2000.0, -1.5e6, 2e6, -4e6
        sN, sz, sy = 3000.0 / s.A, 4e6 / s.W_z, 2e6 / s.W_y
        tT, tV = float(s.tau_torsion(T)), float(s.tau_shear_y(V))
        tc = 0.0 if t is None else tT
        p = [math.sqrt((sN + sz) ** 2 + 3 * tT ** 2), math.sqrt((sN + sy) ** 2 + 3 * (tT + tV) ** 2),
             math.sqrt((sN + sz + sy) ** 2 + 3 * tc ** 2)]
        assert float(s.von_mises(N, V, T, My, Mz)) == pytest.approx(max(p), rel=1e-14)
        # each point can be the largest: the y-faces (bending M_z), the z-faces (shear), the corner
        assert float(s.von_mises(0.0, 0.0, 3e6, 0.0, 1e3)) == pytest.approx(
            max(math.sqrt((1e3 / s.W_z) ** 2 + 3 * float(s.tau_torsion(3e6)) ** 2),
                math.sqrt(3) * float(s.tau_torsion(3e6)),
                math.sqrt((1e3 / s.W_z) ** 2 + 3 * (0 if t is None else float(s.tau_torsion(3e6))) ** 2)), rel=1e-14)
        assert float(s.von_mises(0.0, 5e4, 0.0, 1e3, 0.0)) == pytest.approx(
            math.sqrt((1e3 / s.W_y) ** 2 + 3 * float(s.tau_shear_y(5e4)) ** 2), rel=1e-14)
    solid = RectSection(60.0, 100.0)
    # corner of a solid section: no torsional shear there
    assert float(solid.von_mises(0.0, 0.0, 1e3, 5e6, 5e6)) == pytest.approx(5e6 / solid.W_z + 5e6 / solid.W_y,
                                                                           rel=1e-12)
    assert float(RectSection(60.0, 100.0, 6.0).von_mises(0.0, 0.0, 1e6, 5e6, 5e6)) == pytest.approx(
        math.sqrt((5e6 / RectSection(60.0, 100.0, 6.0).W_z + 5e6 / RectSection(60.0, 100.0, 6.0).W_y) ** 2
                  + 3 * float(RectSection(60.0, 100.0, 6.0).tau_torsion(1e6)) ** 2), rel=1e-12)


def _kt_reference(D, d, r, load):
    h = (D - d) / 2
    x = h / r
    u = math.sqrt(x)
    if load == "bending" and x <= 2:
        C = (0.947 + 1.206 * u - 0.131 * x, 0.022 - 3.405 * u + 0.915 * x, 0.869 + 1.777 * u - 0.555 * x,
             -0.810 + 0.422 * u - 0.260 * x)
    elif load == "bending":
        C = (1.232 + 0.832 * u - 0.008 * x, -3.813 + 0.968 * u - 0.260 * x, 7.423 - 4.868 * u + 0.869 * x,
             -3.839 + 3.070 * u - 0.600 * x)
    else:
        C = (0.905 + 0.783 * u - 0.075 * x, -0.437 - 1.969 * u + 0.553 * x, 1.557 + 1.073 * u - 0.578 * x,
             -1.061 + 0.171 * u + 0.086 * x)
    q = 2 * h / D
    return C[0] + C[1] * q + C[2] * q ** 2 + C[3] * q ** 3


def test_balancer_peterson_fits_exact_and_their_ranges():
    """Pilkey & Pilkey Charts 3.10 / 3.12 (Roark Table 17.1 case 17) at points of every branch and range end."""
    from propulsor.laws.balancer_beam import kt_shoulder_fillet as kt

    D, d = 150.0, 110.0                                    # h = 20
    for r in (200.0, 20.0, 10.0001, 10.0, 9.9999, 4.0, 1.0):  # h/r = 0.1, 1, 2-, 2, 2+, 5, 20
        assert kt(D, d, r) == pytest.approx(_kt_reference(D, d, r, "bending"), rel=1e-14), r
        assert kt(D, d, r, "bending") == kt(D, d, r)
    for r in (80.0, 20.0, 5.0):                             # h/r = 0.25, 1, 4
        assert kt(D, d, r, "torsion") == pytest.approx(_kt_reference(D, d, r, "torsion"), rel=1e-14), r
    # the default upper axle: K_t = 2.05 bending, 1.61 torsion (module docstring)
    assert round(kt(150.0, 110.0, 6.0), 2) == 2.05 and round(kt(150.0, 110.0, 6.0, "torsion"), 2) == 1.61
    assert refused(kt, 150.0, 110.0, 201.0) == "r = 201.0: h/r = 0.0995 outside Peterson's bending fit 0.1 ... 20"
    assert refused(kt, 150.0, 110.0, 0.999) == "r = 0.999: h/r = 20.02 outside Peterson's bending fit 0.1 ... 20"
    assert refused(kt, 150.0, 110.0, 81.0, "torsion") == "r = 81.0: h/r = 0.2469 outside Peterson's torsion fit 0.25 ... 4"
    assert refused(kt, 150.0, 110.0, 4.99, "torsion") == "r = 4.99: h/r = 4.008 outside Peterson's torsion fit 0.25 ... 4"
    assert refused(kt, 150.0, 110.0, 6.0, "shear") == "load = 'shear': must be 'bending' or 'torsion'"
    assert refused(kt, 0.0, 110.0, 6.0) == "D = 0.0: must be > 0 mm"
    assert refused(kt, 150.0, 0.0, 6.0) == "d = 0.0: must be > 0 mm"
    assert refused(kt, 150.0, 110.0, 0.0) == "r = 0.0: must be > 0 mm"
    assert refused(kt, 110.0, 110.0, 6.0) == "D = 110.0: shoulder must exceed the shaft d = 110 mm"


def test_balancer_statics_by_hand():
    from propulsor.laws.balancer_beam import PointLoad, internal_forces, moment_about, reactions

    loads = (PointLoad("a", 300.0, 100.0, -2000.0, 5000.0), PointLoad("b", 120.0, -20.0, 400.0, -1000.0))
    # (r - p) x F with r = (s, 0, z), F = (F_x, F_y, 0): (-z F_y, z F_x, s F_y) about the origin
    M0 = np.array([-100 * 5000.0 + -(-20) * -1000.0, 100 * -2000.0 + -20 * 400.0, 300 * 5000.0 + 120 * -1000.0])
    assert moment_about(loads, (0, 0, 0)) == pytest.approx(M0, rel=1e-15)
    p = (10.0, 0.0, -30.0)
    Mp = np.array([-(130) * 5000.0 - (10) * -1000.0, 130 * -2000.0 + 10 * 400.0, 290 * 5000.0 + 110 * -1000.0])
    assert moment_about(loads, p) == pytest.approx(Mp, rel=1e-15)
    r = reactions(loads, 60, 200)
    assert (r.z1, r.z2) == (-60.0, -200.0)
    F, M = r.residual(loads)
    assert np.abs(F).max() < 1e-9 and np.abs(M).max() < 1e-6
    assert r.bar_torque == pytest.approx(-M0[2], rel=1e-15)
    # x: B1 + B2 = -F_x; moment about y: -60 B1x - 200 B2x = -M_y
    Fx = -2000.0 + 400.0
    A = np.array([[1.0, 1.0], [-60.0, -200.0]])
    assert [r.bearing1[0], r.bearing2[0]] == pytest.approx(np.linalg.solve(A, [-Fx, -M0[1]]), rel=1e-12)
    assert [r.bearing1[1], r.bearing2[1]] == pytest.approx(np.linalg.solve(A, [-4000.0, M0[0]]), rel=1e-12)
    assert r.bearing1[2] == 0.0 and r.bearing2[2] == 0.0
    f = internal_forces(loads, [0.0, 120.0, 200.0, 300.0])
    # at 0: both loads outboard; at 120 only "a" (strictly outboard); at 300 none
    assert f["N"].tolist() == [-1600.0, -2000.0, -2000.0, 0.0]
    assert f["V_y"].tolist() == [4000.0, 5000.0, 5000.0, 0.0]
    assert f["T"].tolist() == [-100 * 5000.0 + 20 * -1000.0, -500000.0, -500000.0, 0.0]
    assert f["M_y"].tolist() == [100 * -2000.0 - 20 * 400.0, -200000.0, -200000.0, 0.0]
    assert f["M_z"].tolist() == [300 * 5000.0 + 120 * -1000.0, 180 * 5000.0, 100 * 5000.0, 0.0]
    assert internal_forces(loads, 0.0)["N"].shape == (1,)


def test_balancer_load_cases_exact_and_refusals():
    from propulsor.laws.balancer_beam import BalancerGeometry, load_cases
    from propulsor.laws.suspension import thesis_design

    d = thesis_design()
    tor = d.torsion
    b, R, MT, Pm = tor.beta_m, tor.R_b, tor.M_T_max, tor.P_m
    g = BalancerGeometry(e_w=140.0, e_a=12.0, s_stop=250.0)
    cs = load_cases(d, g, 2.5)
    assert [c.name for c in cs] == ["beta_m elastic", "beta_m + damper", "stop"]
    assert all(c.beta == b and c.bar_torque_expected == MT for c in cs)
    (w,) = cs[0].loads
    assert (w.name, w.s, w.z) == ("wheel", R, 140.0)
    assert (w.F_x, w.F_y) == pytest.approx((-Pm * math.cos(b), Pm * math.sin(b)), rel=1e-15)
    w, ear = cs[1].loads
    L_a, Fa = d.L_a, d.R_a_comp_max
    Pw = (MT + Fa * L_a) / (R * math.sin(b))
    assert (ear.name, ear.s, ear.z, ear.F_x, ear.F_y) == ("damper ear", L_a, 12.0, 0.0, -Fa)
    assert (w.F_x, w.F_y) == pytest.approx((-Pw * math.cos(b), Pw * math.sin(b)), rel=1e-15)
    w, stop = cs[2].loads
    Ps = 2.5 * Pm
    assert (w.F_x, w.F_y) == pytest.approx((-Ps * math.cos(b), Ps * math.sin(b)), rel=1e-15)
    assert (stop.name, stop.s, stop.z, stop.F_x) == ("stop pad", 250.0, 0.0, 0.0)
    assert stop.F_y == pytest.approx(-(Ps * R * math.sin(b) - MT) / 250.0, rel=1e-14)
    assert load_cases(d, g)[2].loads[0].F_y == pytest.approx(2.0 * Pm * math.sin(b), rel=1e-15)   # default k_stop 2
    assert load_cases(d, g, 1.0)[2].loads[1].F_y == pytest.approx(0.0, abs=1e-6)                # k = 1: pad idle
    assert refused(load_cases, d, g, float("nan")) == "k_stop = nan: must be a finite number"
    assert refused(load_cases, d, g, 0.999) == \
        "k_stop = 0.999: stop load factor must be >= 1 (the stop carries the excess over P(beta_m))"
    assert refused(load_cases, d, BalancerGeometry(s_stop=360.001)) == \
        "s_stop = 360.001: stop pad must lie on the arm, <= R_b = 360 mm"
    assert load_cases(d, BalancerGeometry(s_stop=360.0))[2].loads[1].s == 360.0
    from propulsor.laws.suspension import SuspensionDesign

    lit = SuspensionDesign(wheel_x_m=d.wheel_x_m, damper_x_m=d.damper_x_m, damper_reading="literal")
    assert refused(load_cases, lit, g) == (f"i_a = 0.453: damper ear arm L_a = {360 / 0.453:.4g} mm lies beyond the "
                                           f"balancer R_b = 360 mm (reading 'literal')")
    edge = SuspensionDesign(wheel_x_m=d.wheel_x_m, damper_x_m=d.damper_x_m, i_a=1.0)   # the ear at the wheel
    assert load_cases(edge, g)[1].loads[1].s == 360.0


def test_balancer_equal_strength_depth_branches():
    from propulsor.laws.balancer_beam import BalancerGeometry, RectSection, equal_strength_depth

    g = BalancerGeometry()
    f = {"N": np.array([0.0, 0.0, 0.0]), "V_y": np.array([0.0, 0.0, 0.0]), "T": np.array([0.0, 0.0, 0.0]),
         "M_y": np.array([0.0, 0.0, 0.0]), "M_z": np.array([1e3, 6e7, 60 * 40.0 ** 2 / 6 * 100.0])}
    h = equal_strength_depth(f, g, 100.0)
    # M_z / (b h^2 / 6) = 100 MPa: h = sqrt(6 M / (100 b)); the third station sits exactly on h_min
    assert h[0] == 40.0 and h[2] == 40.0
    assert h[1] == pytest.approx(math.sqrt(6 * 6e7 / (100.0 * 60.0)), abs=1e-8)
    assert float(RectSection(60.0, h[1]).von_mises(0, 0, 0, 0, 6e7)) == pytest.approx(100.0, rel=1e-10)
    assert refused(equal_strength_depth, f, g, 0.0) == "sigma_allow = 0.0: must be > 0 MPa"
    big = {k: v[1:2] for k, v in f.items()}
    big["M_z"] = np.array([60 * 400.0 ** 2 / 6 * 100.0 * 1.001])
    assert refused(equal_strength_depth, big, g, 100.0) == (
        "h_max = 400.0: even h_max leaves sigma_vM > 100 MPa at a station; widen the arm (b) or raise h_max")
    big["M_z"] = np.array([60 * 400.0 ** 2 / 6 * 100.0])                 # exactly at h_max: allowed
    assert equal_strength_depth(big, g, 100.0)[0] == pytest.approx(400.0, abs=1e-8)


def test_balancer_analysis_refusals_defaults_and_stations():
    from propulsor.laws.balancer_beam import YIELD_40KhN2MA, BalancerAnalysis, BalancerGeometry
    from propulsor.laws.suspension import thesis_design

    d = thesis_design()
    assert YIELD_40KhN2MA == 930.0
    a = BalancerAnalysis(d)
    assert (a.k_stop, a.sigma_yield, a.safety, a.n_stations) == (2.0, 930.0, 1.5, 73)
    assert a.geom == BalancerGeometry() and a.sigma_allow == 620.0
    assert a.s == pytest.approx(np.arange(73) * 360.0 / 73, rel=1e-14) and len(a.s) == 73
    b = BalancerAnalysis(d, sigma_yield="900", safety=1.0, n_stations=3.7)
    assert (b.sigma_yield, b.n_stations) == (900.0, 3) and type(b.sigma_yield) is float and type(b.n_stations) is int
    assert b.s.tolist() == [0.0, 120.0, 240.0] and b.sigma_allow == 900.0
    assert refused(BalancerAnalysis, d, sigma_yield=0.0) == "sigma_yield = 0.0: must be > 0 MPa"
    assert refused(BalancerAnalysis, d, safety=float("nan")) == "safety = nan: must be a finite number"
    assert refused(BalancerAnalysis, d, safety=0.999) == "safety = 0.999: safety factor must be >= 1"
    assert refused(BalancerAnalysis, d, n_stations=2) == "n_stations = 2: need >= 3 stations"
    assert [c.name for c in a.cases] == ["beta_m elastic", "beta_m + damper", "stop"]
    assert BalancerAnalysis(d, k_stop=3.0).cases[2].loads[0].F_y == pytest.approx(
        3.0 * d.torsion.P_m * math.sin(d.torsion.beta_m), rel=1e-15)


def test_balancer_stresses_mass_and_transitions_by_hand():
    from propulsor.laws.balancer_beam import (RHO_STEEL, BalancerAnalysis, BalancerGeometry, RectSection,
                                              internal_forces, kt_shoulder_fillet, moment_about)
    from propulsor.laws.suspension import thesis_design

    d = thesis_design()
    g = BalancerGeometry(d_upper_bore=30.0, d_lower_bore=20.0)
    a = BalancerAnalysis(d, g, n_stations=4)
    s = np.array([0.0, 90.0, 180.0, 270.0])
    h = np.array([150.0, 120.0, 90.0, 60.0])
    st = a.stresses(h)
    for c in a.cases:
        f = internal_forces(c.loads, s)
        want = [float(RectSection(60.0, h[i]).von_mises(f["N"][i], f["V_y"][i], f["T"][i], f["M_y"][i], f["M_z"][i]))
                for i in range(4)]
        assert st[c.name] == pytest.approx(want, rel=1e-15)
        assert a.forces(c)["M_z"] == pytest.approx(f["M_z"], rel=1e-15)
    assert a.stresses(100.0)["stop"].shape == (4,)
    # mass: the prism's areas with the last station's area carried to R_b, trapezoid rule
    A = 60.0 * np.array([150.0, 120.0, 90.0, 60.0, 60.0])
    ss = np.array([0.0, 90.0, 180.0, 270.0, 360.0])
    m, sc = a.arm_mass(h)
    assert RHO_STEEL == 7.85e-6
    assert m == pytest.approx(RHO_STEEL * float(np.trapezoid(A, ss)), rel=1e-14)
    assert sc == pytest.approx(float(np.trapezoid(A * ss, ss) / np.trapezoid(A, ss)), rel=1e-14)
    m0, _ = a.arm_mass()
    h_eq = a.envelope_depth()
    assert m0 == pytest.approx(a.arm_mass(h_eq)[0], rel=1e-15)
    from propulsor.laws.balancer_beam import equal_strength_depth

    assert h_eq.tolist() == np.max([equal_strength_depth(a.forces(c), g, 620.0) for c in a.cases], axis=0).tolist()
    # transitions: upper fillet at the inboard face, spindle fillet with the wheel load alone
    rows = a.transitions()
    assert [(r["case"], r["where"]) for r in rows] == [
        (c.name, w) for c in a.cases for w in ("upper axle fillet", "wheel spindle fillet")]
    kb_u, kt_u = kt_shoulder_fillet(150.0, 110.0, 6.0), kt_shoulder_fillet(150.0, 110.0, 6.0, "torsion")
    kb_l = kt_shoulder_fillet(130.0, 90.0, 6.0)
    W_u = math.pi * (110.0 ** 4 - 30.0 ** 4) / (32 * 110.0)
    W_l = math.pi * (90.0 ** 4 - 20.0 ** 4) / (32 * 90.0)
    for k, c in enumerate(a.cases):
        up, sp = rows[2 * k], rows[2 * k + 1]
        M = moment_about(c.loads, (0.0, 0.0, -30.0))
        sb, tt = math.hypot(M[0], M[1]) / W_u, abs(M[2]) / (2 * W_u)
        assert (up["K_t_bending"], up["K_t_torsion"]) == (kb_u, kt_u)
        assert up["sigma_nom"] == pytest.approx(sb, rel=1e-14) and up["tau_nom"] == pytest.approx(tt, rel=1e-14)
        assert up["sigma_vM_nom"] == pytest.approx(math.sqrt(sb ** 2 + 3 * tt ** 2), rel=1e-14)
        assert up["sigma_vM_peak"] == pytest.approx(math.sqrt((kb_u * sb) ** 2 + 3 * (kt_u * tt) ** 2), rel=1e-14)
        w = c.loads[0]
        Ms = moment_about([w], (360.0, 0.0, 30.0))
        sbl = math.hypot(Ms[0], Ms[1]) / W_l
        assert (sp["K_t_bending"], sp["K_t_torsion"], sp["tau_nom"]) == (kb_l, 1.0, 0.0)
        assert sp["sigma_nom"] == pytest.approx(sbl, rel=1e-14) and sp["sigma_vM_nom"] == sp["sigma_nom"]
        assert sp["sigma_vM_peak"] == pytest.approx(kb_l * sbl, rel=1e-14)
    # the stop pad at the wheel station but in the arm (z = 0 <= b/2) does not bend the spindle
    pad = BalancerAnalysis(d, BalancerGeometry(s_stop=360.0))
    stop = pad.cases[2]
    assert stop.loads[1].s == 360.0
    Ms = moment_about(stop.loads[:1], (360.0, 0.0, 30.0))
    assert pad.transitions()[5]["sigma_nom"] == pytest.approx(math.hypot(Ms[0], Ms[1]) / (math.pi * 90.0 ** 3 / 32),
                                                              rel=1e-14)


def test_balancer_run_checks_exact():
    from propulsor.laws.balancer_beam import BalancerAnalysis, reactions
    from propulsor.laws.suspension import thesis_design

    d = thesis_design()
    a = BalancerAnalysis(d, n_stations=12)
    r = a.run()
    checks = {c.name: c for c in r["checks"]}
    tor = d.torsion
    for c in a.cases:
        re = reactions(c.loads, 60.0, 200.0)
        F, M = re.residual(c.loads)
        scale = max(abs(L.F_y) for L in c.loads) * 360.0
        k = checks[f"{c.name}: statics residual"]
        assert k.value == pytest.approx(float(np.linalg.norm(F) + np.linalg.norm(M) / 360.0), rel=1e-9, abs=1e-12)
        assert k.limit == pytest.approx(1e-9 * scale / 360.0, rel=1e-15) and k.unit == "N" and k.passed
        k = checks[f"{c.name}: bar torque vs M_T(beta_m)"]
        assert k.value == pytest.approx(abs(re.bar_torque + c.bar_torque_expected) / c.bar_torque_expected, abs=1e-15)
        assert (k.limit, k.unit, k.message) == (1e-9, "-", "bar reacts the characteristic's torque")
        k = checks[f"{c.name}: constant arm sigma_vM"]
        assert k.value == float(np.max(r["sigma_vM_constant"][c.name])) and k.limit == 620.0 and k.unit == "MPa"
        k = checks[f"{c.name}: equal-strength arm sigma_vM"]
        assert k.value == float(np.max(r["sigma_vM_equal_strength"][c.name]))
        assert k.limit == pytest.approx(620.0 * (1 + 1e-9), rel=1e-15)
    for row in r["transitions"]:
        k = checks[f"{row['case']}: {row['where']} safety factor"]
        assert k.value == pytest.approx(930.0 / row["sigma_vM_peak"], rel=1e-15) and k.limit == 1.5
        assert k.message == f"K_t = {row['K_t_bending']:.3f} (Peterson)" and k.unit == "-"
    k = checks["torsion bar shear at beta_m"]
    assert (k.value, k.limit, k.unit) == (pytest.approx(float(tor.tau(tor.beta_m)), rel=1e-15), 1600.0, "MPa")
    assert len(r["checks"]) == 3 * 4 + 6 + 1
    assert r["s"].tolist() == a.s.tolist()
    assert r["h_equal_strength"] == pytest.approx(a.envelope_depth(), rel=1e-15)
    m_eq, sc_eq = a.arm_mass(r["h_equal_strength"])
    m_c, sc_c = a.arm_mass(120.0)
    assert (r["mass_equal_strength_kg"], r["com_equal_strength_mm"]) == pytest.approx((m_eq, sc_eq), rel=1e-15)
    assert (r["mass_constant_kg"], r["com_constant_mm"]) == pytest.approx((m_c, sc_c), rel=1e-15)
    assert r["sigma_vM_constant"]["stop"] == pytest.approx(a.stresses(120.0)["stop"], rel=1e-15)
    assert r["forces"]["stop"]["M_z"] == pytest.approx(a.forces(a.cases[2])["M_z"], rel=1e-15)
    assert len(r["transitions"]) == 6


# ============================================================== cam_design.py (seed 001, after eq. 29)

def test_cam_design_limits_refusals_both_sides_and_defaults():
    from propulsor.laws.cam_design import DesignLimits as L

    d = L()
    assert (d.gamma_max_deg, d.R_factor, d.sigma_allow, d.shoe_radius_min, d.footprint_ratio_max, d.cam_core_min,
            d.hub_height_tol, d.ground_clearance_min, d.return_lift_max) == (30.0, 1.5, 1500.0, 0.0, 0.85, 40.0, 0.01,
                                                                           0.0, None)
    assert refused(L, gamma_max_deg=float("nan")) == "gamma_max_deg = nan: must be a finite number"
    for g in (0.0, 90.0):
        assert refused(L, gamma_max_deg=g) == f"gamma_max_deg = {g!r}: must be in (0, 90) deg"
    assert L(gamma_max_deg=1e-9).gamma_max_deg == 1e-9 and L(gamma_max_deg=89.999).gamma_max_deg == 89.999
    assert refused(L, R_factor=0.0) == "R_factor = 0.0: must be > 0"
    assert refused(L, sigma_allow=0.0) == "sigma_allow = 0.0: must be > 0 MPa"
    assert refused(L, shoe_radius_min=float("inf")) == "shoe_radius_min = inf: must be a finite number"
    assert refused(L, shoe_radius_min=-1e-9) == "shoe_radius_min = -1e-09: must be >= 0 mm"
    assert refused(L, footprint_ratio_max=0.0) == "footprint_ratio_max = 0.0: must be > 0"
    assert refused(L, cam_core_min=float("nan")) == "cam_core_min = nan: must be a finite number"
    assert refused(L, cam_core_min=-1e-9) == "cam_core_min = -1e-09: must be >= 0 mm"
    assert refused(L, hub_height_tol=0.0) == "hub_height_tol = 0.0: must be > 0 mm"
    assert refused(L, return_lift_max=float("nan")) == "return_lift_max = nan: must be a finite number"
    assert refused(L, return_lift_max=-1e-9) == "return_lift_max = -1e-09: must be >= 0 mm (or None: no limit)"
    assert refused(L, ground_clearance_min=float("nan")) == "ground_clearance_min = nan: must be a finite number"
    assert refused(L, ground_clearance_min=-1e-9) == "ground_clearance_min = -1e-09: must be >= 0 mm"
    z = L(shoe_radius_min=0.0, cam_core_min=0.0, return_lift_max=0.0, ground_clearance_min=0.0)
    assert (z.shoe_radius_min, z.cam_core_min, z.return_lift_max, z.ground_clearance_min) == (0.0, 0.0, 0.0, 0.0)


def test_cam_design_search_grid_refusals_and_laws():
    from propulsor.laws.cam_design import SearchGrid

    d = SearchGrid()
    assert (d.linear_k0, d.quadratic_k0, d.exponential_k0, d.exponential_k1, d.symmetric) == (
        (-0.004, 0.03, 60), (-0.004, 0.05, 60), (0.0, 0.012, 13), (-2.0, 2.0, 11), True)
    assert len(d.laws()) == 60 + 60 + 13 * 11
    for name in ("linear_k0", "quadratic_k0", "exponential_k0", "exponential_k1"):
        for bad in ((0.03, 0.0, 5), (0.0, 0.05, 2.5), (0.0, 0.05, -1), (0.0, float("nan"), 3), (0.0, 1.0), [0, 1, 2, 3],
                    "0.0"):
            assert refused(SearchGrid, **{name: bad}) == \
                f"SearchGrid.{name} = {bad!r}: must be (lo, hi, n) with lo <= hi and a whole n >= 0"
        assert getattr(SearchGrid(**{name: [0.01, 0.01, 0]}), name) == [0.01, 0.01, 0]     # lo = hi, n = 0, a list
    g = SearchGrid(linear_k0=(0.0, 0.02, 3), quadratic_k0=(0.01, 0.01, 1), exponential_k0=(0.001, 0.002, 2),
                   exponential_k1=(-1.0, 1.0, 2), symmetric=False)
    laws = g.laws()
    assert [(L.kind, L.k0, L.k1, L.symmetric) for L in laws] == [
        ("linear", 0.0, 0.0, False), ("linear", 0.01, 0.0, False), ("linear", 0.02, 0.0, False),
        ("quadratic", 0.01, 0.0, False),
        ("exponential", 0.001, -1.0, False), ("exponential", 0.001, 1.0, False),
        ("exponential", 0.002, -1.0, False), ("exponential", 0.002, 1.0, False)]
    assert all(type(L.k0) is float and type(L.k1) is float for L in laws)
    assert all(L.symmetric for L in SearchGrid(linear_k0=(0.0, 0.02, 2), quadratic_k0=(0, 0, 0),
                                               exponential_k0=(0, 0, 0), exponential_k1=(0, 0, 0)).laws())


def test_cam_design_min_positive():
    from propulsor.laws.cam_design import _min_positive

    assert _min_positive([3.0, -1.0, 0.0, 2.0, float("inf"), float("nan")]) == 2.0
    assert _min_positive([-1.0, 0.0]) == math.inf and _min_positive([]) == math.inf
    assert type(_min_positive(np.array([5, 7]))) is float and _min_positive([1e-300]) == 1e-300


def test_cam_design_evaluate_row_written_out():
    from propulsor import policy
    from propulsor.laws.cam_design import DesignLimits, evaluate
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import shoe_loop_check, shoe_table

    mech, law = CamMechanism(), CurvatureLaw("quadratic", 0.017)
    row = evaluate(mech, law, DesignLimits())
    cm = cam_motion(mech, law)
    s = math.pi / 4
    tab = cm.table(np.linspace(0.0, 2 * math.pi, policy.CAM_TURN_SAMPLES))
    phi = np.linspace(-s, s, policy.CAM_SUPPORT_SAMPLES)
    hs = cm.hub_speed(phi)
    st = shoe_table(cm.support, phi)
    travel = float(np.trapezoid(hs, phi))
    H_end = float(cm.support.state(np.array([s]))[0][0])
    assert (row["law"], row["k0"], row["k1"], row["label"], row["feasible"], row["violations"]) == (
        "quadratic", 0.017, 0.0, "K = 0.017·φ²", True, "")
    assert row["hub_speed_variation_pct"] == pytest.approx(100 * (hs.max() - hs.min()) / (travel / (2 * s)), rel=1e-12)
    assert row["gamma_max_deg"] == pytest.approx(math.degrees(np.max(np.abs(tab.gamma))), rel=1e-12)
    assert row["gamma_max_support_deg"] == pytest.approx(math.degrees(np.max(np.abs(tab.gamma[tab.support]))),
                                                         rel=1e-12)
    Rp = tab.R_profile[np.isfinite(tab.R_profile) & (tab.R_profile > 0)]
    assert row["R_min_mm"] == pytest.approx(float(Rp.min()), rel=1e-12) and row["R_outer_min_mm"] == math.inf
    assert row["undercut"] is False and row["shoe_self_intersecting"] is False
    assert row["sigma_max_MPa"] == pytest.approx(float(np.max(tab.sigma_H[tab.support])), rel=1e-12)
    assert row["sigma_return_max_MPa"] == pytest.approx(float(np.max(tab.sigma_H[~tab.support])), rel=1e-12)
    assert row["shoe_radius_min_mm"] == pytest.approx(shoe_loop_check(st).radius_min, rel=1e-12)
    assert row["footprint_ratio"] == pytest.approx(float(np.trapezoid(st.radius, phi)) / travel, rel=1e-12)
    assert (row["H_min_mm"], row["H_max_mm"]) == pytest.approx((float(tab.H.min()), float(tab.H.max())), rel=1e-12)
    assert row["H_support_end_mm"] == pytest.approx(H_end, rel=1e-12)
    assert row["return_lift_mm"] == pytest.approx(float(tab.H.max()) - H_end, rel=1e-12)
    assert math.isnan(row["H_error_mm"]) and math.isnan(row["hub_height_variation_mm"])
    assert math.isnan(row["ground_clearance_min_mm"])
    est = evaluate(mech, law, DesignLimits(), estimate_error=True)
    assert 0 < est["H_error_mm"] <= 1e-6


def test_cam_design_evaluate_each_limit_both_sides():
    from propulsor.laws.cam_design import DesignLimits, evaluate
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw

    mech, law = CamMechanism(), CurvatureLaw("quadratic", 0.017)
    row = evaluate(mech, law, DesignLimits())
    g, Rm, sg = row["gamma_max_deg"], row["R_min_mm"], max(row["sigma_max_MPa"], row["sigma_return_max_MPa"])
    fr, core, lift, rs = row["footprint_ratio"], row["H_min_mm"] - 20.0, row["return_lift_mm"], row["shoe_radius_min_mm"]
    ok = dict(gamma_max_deg=g, R_factor=Rm / 20.0, sigma_allow=sg, footprint_ratio_max=fr, cam_core_min=core,
              return_lift_max=lift, shoe_radius_min=rs * 0.999)
    assert evaluate(mech, law, DesignLimits(**ok))["violations"] == ""       # every value on its limit passes
    v = evaluate(mech, law, DesignLimits(gamma_max_deg=g * 0.999))["violations"]
    assert v == f"pressure angle {g:.2f}° > {g * 0.999:g}°"
    v = evaluate(mech, law, DesignLimits(R_factor=Rm / 20.0 * 1.001))["violations"]
    assert v == f"cam radius of curvature {Rm:.2f} mm < {Rm / 20.0 * 1.001:g}·r = {Rm * 1.001:g} mm"
    v = evaluate(mech, law, DesignLimits(sigma_allow=sg * 0.999))["violations"]
    assert v == f"Hertz stress {sg:.0f} MPa > {sg * 0.999:g} MPa"
    v = evaluate(mech, law, DesignLimits(shoe_radius_min=rs))["violations"]
    assert v == f"shoe cusp/loop (min radius {rs:.2f} mm, self-intersecting False)"
    v = evaluate(mech, law, DesignLimits(footprint_ratio_max=fr * 0.999))["violations"]
    assert v == f"footprint ratio {fr:.4f} > {fr * 0.999:g}"
    v = evaluate(mech, law, DesignLimits(cam_core_min=core * 1.001))["violations"]
    assert v == f"cam core H_min − r = {core:.2f} mm < {core * 1.001:g} mm"
    r = evaluate(mech, law, DesignLimits(return_lift_max=lift * 0.999))
    assert r["violations"] == f"return lift {lift:.2f} mm > {lift * 0.999:g} mm" and r["feasible"] is False
    both = evaluate(mech, law, DesignLimits(gamma_max_deg=g * 0.999, cam_core_min=core * 1.001))["violations"]
    assert both == f"pressure angle {g:.2f}° > {g * 0.999:g}°; cam core H_min − r = {core:.2f} mm < {core * 1.001:g} mm"


def test_cam_design_evaluate_blow_up_and_undercut_rows():
    from propulsor.laws.cam_design import DesignLimits, evaluate
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion

    mech = CamMechanism()
    law = CurvatureLaw("linear", 0.2)
    with pytest.raises(InputError) as e:
        cam_motion(mech, law)
    row = evaluate(mech, law, DesignLimits())
    assert row["violations"] == f"blow-up: {e.value}" and row["feasible"] is False
    assert math.isnan(row["gamma_max_deg"]) and row["undercut"] is False and row["label"] == law.label()
    # a straight path (K = 0): gamma = phi reaches 45 deg at the support's ends (more in the return)
    z = evaluate(mech, CurvatureLaw("zero"), DesignLimits())
    assert z["gamma_max_support_deg"] == pytest.approx(45.0, abs=1e-6) and z["gamma_max_deg"] > 45.0
    assert z["violations"].startswith(f"pressure angle {z['gamma_max_deg']:.2f}° > 30°")


def test_cam_design_verify_messages_and_margins():
    from propulsor.laws.cam_design import DesignLimits, _margins, verify
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
    from propulsor.laws.shoe import hub_height_on_flat, return_ground_clearance

    mech = CamMechanism()
    law = CurvatureLaw("linear", 0.005, symmetric=False)          # an idle shoe digs in: the hub rises
    cm = cam_motion(mech, law, estimate_error=False)
    phi = np.linspace(-math.pi / 4, math.pi / 4, 5)
    hh = hub_height_on_flat(cm, phi, n_shoe=601)
    clr = return_ground_clearance(cm, phi[1:-1], n_shoe=601)
    v = verify(mech, law, DesignLimits(), n_phi=5)
    var = float(hh.max() - hh.min())
    assert v["hub_height_variation_mm"] == pytest.approx(var, rel=1e-12)
    assert v["hub_height_mean_mm"] == pytest.approx(float(hh.mean()), rel=1e-12)
    assert v["ground_clearance_min_mm"] == pytest.approx(float(clr.min()), rel=1e-12)
    assert var > 0.01 and float(clr.min()) < 0
    assert v["verify_violations"] == (f"hub height on flat varies {var:.4g} mm > 0.01 mm; idle shoe ground clearance "
                                      f"{float(clr.min()):.4g} mm < 0 mm")
    ok = verify(mech, law, DesignLimits(hub_height_tol=var, ground_clearance_min=0.0), n_phi=5)
    assert ok["verify_violations"] == f"idle shoe ground clearance {float(clr.min()):.4g} mm < 0 mm"
    good = CurvatureLaw("quadratic", 0.017)
    g = verify(mech, good, DesignLimits())                         # default: 19 angles
    cmg = cam_motion(mech, good, estimate_error=False)
    p19 = np.linspace(-math.pi / 4, math.pi / 4, 19)
    c19 = return_ground_clearance(cmg, p19[1:-1], n_shoe=601)
    assert g["ground_clearance_min_mm"] == pytest.approx(float(c19.min()), rel=1e-12) and g["verify_violations"] == ""
    tight = verify(mech, good, DesignLimits(ground_clearance_min=float(c19.min())))
    assert tight["verify_violations"] == ""                          # on the limit passes
    row = dict(gamma_max_deg=24.0, R_min_mm=45.0, R_outer_min_mm=60.0, sigma_max_MPa=900.0, sigma_return_max_MPa=1200.0,
               footprint_ratio=0.68, H_min_mm=80.0)
    m = _margins(row, DesignLimits(), mech)
    assert m == pytest.approx({"pressure angle": 0.2, "cam radius of curvature": 0.5, "Hertz stress": 0.2,
                               "footprint ratio": 0.2, "cam core": 0.5}, rel=1e-12)
    assert _margins(row, DesignLimits(cam_core_min=0.0), mech)["cam core"] == math.inf



def test_cam_design_cam_core_margin_for_a_core_limit_of_a_millimetre_or_less():
    """Only a cam core limit of 0 has no relative margin (inf); 1 mm or 0.5 mm are limits like any other."""
    from propulsor.laws.cam_design import DesignLimits, _margins
    from propulsor.laws.cam_motion import CamMechanism

    row = dict(gamma_max_deg=24.0, R_min_mm=45.0, R_outer_min_mm=60.0, sigma_max_MPa=900.0, sigma_return_max_MPa=1200.0,
               footprint_ratio=0.68, H_min_mm=80.0)
    mech = CamMechanism()
    core = 80.0 - mech.r                                        # H_min - r = 60 mm (r = 20 mm)
    assert core == 60.0
    for lim in (1.0, 0.5, 1e-9):
        assert _margins(row, DesignLimits(cam_core_min=lim), mech)["cam core"] == pytest.approx(core / lim - 1.0,
                                                                                                rel=1e-15)


def test_cam_design_verify_places_the_shoes_of_the_cam_it_was_given():
    """verify builds the cam with the given return phase and samples the idle shoes at the inner angles of its n_phi
    (n_phi = 3: the middle one only)."""
    from propulsor.laws.cam_design import DesignLimits, verify
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion
    from propulsor.laws.shoe import hub_height_on_flat, return_ground_clearance

    mech, good = CamMechanism(), CurvatureLaw("quadratic", 0.017)
    s = math.pi / 4
    rp = ReturnPhase("min_jerk")
    cm = cam_motion(mech, good, rp, estimate_error=False)
    p19 = np.linspace(-s, s, 19)
    want = float(return_ground_clearance(cm, p19[1:-1], n_shoe=601).min())
    other = float(return_ground_clearance(cam_motion(mech, good, estimate_error=False), p19[1:-1], n_shoe=601).min())
    assert abs(want - other) > 1e-3                                # the return phase moves the idle shoes
    assert verify(mech, good, DesignLimits(), rp)["ground_clearance_min_mm"] == pytest.approx(want, rel=1e-12)
    v3 = verify(mech, good, DesignLimits(), n_phi=3)
    cm0 = cam_motion(mech, good, estimate_error=False)
    assert v3["ground_clearance_min_mm"] == pytest.approx(float(return_ground_clearance(cm0, [0.0], 601)[0]), rel=1e-12)
    hh = hub_height_on_flat(cm0, np.array([-s, 0.0, s]), n_shoe=601)
    assert v3["hub_height_mean_mm"] == pytest.approx(float(hh.mean()), rel=1e-12) and hh == pytest.approx(320.0)


def test_cam_design_search_chooses_the_law_of_its_row_k1_and_symmetry_kept():
    """The chosen law is rebuilt from its row: an odd exponential law keeps its k1 and its odd form."""
    from propulsor.laws.cam_design import DesignLimits, SearchGrid, search_design
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw

    loose = DesignLimits(gamma_max_deg=89.0, R_factor=1e-6, sigma_allow=1e9, footprint_ratio_max=10.0,
                         cam_core_min=0.0, hub_height_tol=1e3)
    g = SearchGrid(linear_k0=(0, 0, 0), quadratic_k0=(0, 0, 0), exponential_k0=(0.002, 0.002, 1),
                   exponential_k1=(0.5, 0.5, 1), symmetric=False)
    r = search_design(CamMechanism(), loose, g)
    assert r.law == CurvatureLaw("exponential", 0.002, 0.5, symmetric=False)
    assert (r.chosen["k0"], r.chosen["k1"], r.chosen["label"]) == (0.002, 0.5, "K = 0.002·exp(0.5·φ)")

def test_damper_mean_power_window_on_a_lightly_damped_start():
    """A light damper (b2 = 3 kN s/m) still ringing from rest: the mean power depends on its window (the last
    max(1, int(t_end / 4T)) whole periods, 200 samples a period), and the exact solution and DOP853 on the
    equations as written agree on it to 1e-8 - each with its own window."""
    from propulsor.laws.damper_heat import Road, Station, simulate

    st = Station(m1=400.0, C1=2.0e6, b1=2.0e3, b2=3e3)
    road = Road(0.1, 4.0)
    got = {}
    for V, t_end in ((8.0, 1.2), (8.0, 2.0), (8.0, 5.1), (2.0, 7.0)):
        e = simulate(st, road, V, t_end, n_out=50)
        n = simulate(st, road, V, t_end, n_out=50, rtol=1e-11)
        assert e.mean_power == pytest.approx(n.mean_power, rel=1e-8), (V, t_end)
        assert e.T == pytest.approx(n.T, abs=1e-8) and e.z2 == pytest.approx(n.z2, abs=1e-9)
        assert e.t.tolist() == n.t.tolist() and e.V == n.V == V
        got[(V, t_end)] = e.mean_power
    assert abs(got[(8.0, 1.2)] / got[(8.0, 2.0)] - 1) > 0.1            # the window matters here
    # n_out = 2: the start and the end, the end as a finer grid has it
    two = simulate(st, road, 8.0, 2.0, n_out=2)
    assert two.T[-1] == pytest.approx(simulate(st, road, 8.0, 2.0, n_out=9).T[-1], rel=1e-12)
    assert two.z2[-1] == pytest.approx(simulate(st, road, 8.0, 2.0, n_out=9).z2[-1], rel=1e-9)


# ============================================================== cam_motion.py (seed 001, eq. 6-20)

def test_cam_mechanism_refusals_both_sides():
    from propulsor.laws.cam_motion import CamMechanism as M

    for k in ("R0", "r", "C", "b", "P", "E1", "E2"):
        assert refused(M, **{k: 0.0}) == f"{k} = 0.0: must be > 0"
    assert refused(M, P_return=float("nan")) == "P_return = nan: must be a finite number"
    assert refused(M, P_return=-1e-9) == "P_return = -1e-09: must be >= 0 N"
    assert refused(M, channel_clearance=float("inf")) == "channel_clearance = inf: must be a finite number"
    assert refused(M, channel_clearance=-1e-9) == "channel_clearance = -1e-09: must be >= 0 mm"
    assert M(P_return=0.0, channel_clearance=0.0).P_return == 0.0
    for n in (2, 13, 4.0, "4"):
        assert refused(M, n_legs=n) == f"n_legs = {n!r}: must be an integer in [3, 12] (seed 001: 4)"
    assert M(n_legs=3).phi_s == pytest.approx(math.pi / 3) and M(n_legs=np.int64(12)).phi_s == pytest.approx(
        math.pi / 12)


def test_cam_curvature_law_refusals_values_and_labels():
    from propulsor.laws.cam_motion import LAW_KINDS, CurvatureLaw as C

    assert LAW_KINDS == ("zero", "linear", "quadratic", "exponential")
    assert refused(C, "cubic") == \
        "CurvatureLaw.kind = 'cubic': must be one of ('zero', 'linear', 'quadratic', 'exponential')"
    assert refused(C, "linear", float("nan")) == "CurvatureLaw.k0 = nan: must be a finite number"
    assert refused(C, "exponential", 0.1, float("inf")) == "CurvatureLaw.k1 = inf: must be a finite number"
    assert refused(C, "zero", 0.1) == "CurvatureLaw.k0 = 0.1: must be 0 for kind 'zero'"
    assert refused(C, "linear", 0.1, 0.2) == "CurvatureLaw.k1 = 0.2: only the 'exponential' law uses k1"
    assert refused(C, "exponential", 0.1, 50.001) == "CurvatureLaw.k1 = 50.001: must satisfy |k1| <= 50 1/rad"
    assert refused(C, "exponential", 0.1, -50.001) == "CurvatureLaw.k1 = -50.001: must satisfy |k1| <= 50 1/rad"
    assert C("exponential", 0.1, -50.0).k1 == -50.0
    d = C()
    assert (d.kind, d.k0, d.k1, d.symmetric) == ("quadratic", 0.0, 0.0, True)
    p = np.array([-0.5, 0.0, 0.25])
    for sym in (True, False):
        x = np.abs(p) if sym else p
        sg = np.where(p < 0, -1.0, 1.0) if sym else 1.0
        assert C("zero", symmetric=sym).K(p).tolist() == [0.0, 0.0, 0.0]
        assert C("zero", symmetric=sym).dK(p).tolist() == [0.0, 0.0, 0.0]
        assert C("linear", 0.3, symmetric=sym).K(p) == pytest.approx(0.3 * x, rel=1e-15)
        assert C("linear", 0.3, symmetric=sym).dK(p) == pytest.approx(sg * 0.3 * np.ones(3), rel=1e-15)
        assert C("quadratic", 0.3, symmetric=sym).K(p) == pytest.approx(0.3 * x * x, rel=1e-15)
        assert C("quadratic", 0.3, symmetric=sym).dK(p) == pytest.approx(sg * 0.6 * x, rel=1e-15)
        assert C("exponential", 0.3, 1.5, symmetric=sym).K(p) == pytest.approx(0.3 * np.exp(1.5 * x), rel=1e-15)
        assert C("exponential", 0.3, 1.5, symmetric=sym).dK(p) == pytest.approx(sg * 0.45 * np.exp(1.5 * x), rel=1e-15)
    assert C("linear", 0.3, symmetric=False).dK(-0.5) == 0.3          # odd law: K' > 0 on both sides
    assert C("linear", 0.3).dK(-0.5) == -0.3 and C("linear", 0.3).dK(0.0) == 0.3
    assert C("linear", symmetric=False).is_even is False and C("quadratic", symmetric=False).is_even is True
    assert C("zero", symmetric=False).is_even is True and C("exponential", 0.1, 1.0).is_even is True
    assert C("zero").label() == "K = 0"
    assert C("linear", 0.0123456789).label() == "K = 0.0123457·|φ|"
    assert C("linear", 0.5, symmetric=False).label() == "K = 0.5·φ"
    assert C("quadratic", 0.017).label() == "K = 0.017·φ²"
    assert C("exponential", 0.004, 0.6).label() == "K = 0.004·exp(0.6·|φ|)"
    assert C("exponential", 0.004, -0.6, symmetric=False).label() == "K = 0.004·exp(-0.6·φ)"


def test_cam_return_phase_refusals():
    from propulsor.laws.cam_motion import RETURN_MODES, ReturnPhase as R

    assert RETURN_MODES == ("min_gamma", "min_jerk", "top") and R().mode == "min_gamma" and R().H_top is None
    assert refused(R, "jerk") == "ReturnPhase.mode = 'jerk': must be one of ('min_gamma', 'min_jerk', 'top')"
    assert refused(R, "top") == "ReturnPhase.H_top = None: required by mode 'top'"
    assert refused(R, "top", 0.0) == "ReturnPhase.H_top = 0.0: must be > 0 mm"
    assert refused(R, "min_jerk", 150.0) == "ReturnPhase.H_top = 150.0: only mode 'top' takes H_top"
    assert R("top", 150.0).H_top == 150.0


def test_cam_rhs_and_support_derivatives_written_out():
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, _rhs_factory, solve_support

    for law, K in ((CurvatureLaw("zero"), lambda p: 0.0), (CurvatureLaw("linear", 0.01), lambda p: 0.01 * abs(p)),
                   (CurvatureLaw("linear", 0.01, symmetric=False), lambda p: 0.01 * p),
                   (CurvatureLaw("quadratic", 0.02), lambda p: 0.02 * p * p),
                   (CurvatureLaw("exponential", 0.004, 0.6), lambda p: 0.004 * math.exp(0.6 * abs(p))),
                   (CurvatureLaw("exponential", 0.004, 0.6, symmetric=False), lambda p: 0.004 * math.exp(0.6 * p))):
        f = _rhs_factory(law)
        for p in (-0.4, 0.3):
            rho, g = 120.0, 0.2
            assert f(p, [rho, g]) == pytest.approx([rho * math.tan(g), 1 - rho * K(p) / math.cos(g)], rel=1e-15)
    law = CurvatureLaw("quadratic", 0.017)
    sp = solve_support(CamMechanism(), law, estimate_error=False)
    assert sp.H_error_mm is None and (sp.rtol, sp.atol) == (1e-11, 1e-11)
    phi = np.array([-0.6, 0.0, 0.7])
    d = sp.derivs(phi)
    H, g = sp.state(phi)
    K = 0.017 * phi ** 2
    t, c = np.tan(g), np.cos(g)
    assert d["H"].tolist() == H.tolist() and d["gamma"].tolist() == g.tolist() and d["phi"].tolist() == phi.tolist()
    assert d["H1"] == pytest.approx(H * t, rel=1e-15, abs=1e-300)
    assert d["K"] == pytest.approx(K, rel=1e-15) and d["g"] == pytest.approx(H * K / c, rel=1e-15)
    assert d["dgamma"] == pytest.approx(1 - H * K / c, rel=1e-15)
    assert d["H2"] == pytest.approx(H * t * t + H * (1 - H * K / c) / c ** 2, rel=1e-14)
    assert d["dg"] == pytest.approx((H * t * K + H * 0.034 * np.abs(phi) * np.sign(phi)) / c
                                    + H * K / c * t * (1 - H * K / c), rel=1e-13, abs=1e-15)
    # the ODE's own check: H' by central differences of the dense solution
    h = 1e-5
    fd = (sp.state(phi[[0, 2]] + h)[0] - sp.state(phi[[0, 2]] - h)[0]) / (2 * h)
    assert d["H1"][[0, 2]] == pytest.approx(fd, rel=1e-7)
    assert H[1] == 110.0 and g[1] == 0.0                     # H(0) = H0 = R0 + r, gamma(0) = 0
    s = math.pi / 4
    assert sp.state(s * (1 + 1e-13))[0].shape == (1,)        # the support end, rounded, is taken
    assert refused(sp.state, [0.0, s * 1.001]) == f"phi = {s * 1.001!r}: support phase is |φ| <= 0.785398 rad"
    assert refused(sp.state, -s * 1.001) == f"phi = {s * 1.001!r}: support phase is |φ| <= 0.785398 rad"
    # an odd law integrates both sides; its negative side differs from the mirror
    odd = solve_support(CamMechanism(), CurvatureLaw("linear", 0.005, symmetric=False), estimate_error=True)
    Hn, gn = odd.state(np.array([-0.5]))
    Hp, gp = odd.state(np.array([0.5]))
    assert abs(Hn[0] - Hp[0]) > 1.0 and 0 < odd.H_error_mm <= 1e-6
    even = solve_support(CamMechanism(), law)
    He, ge = even.state(np.array([-0.5, 0.5]))
    assert He[0] == He[1] and ge[0] == -ge[1]
    q, dq = sp.delta_over_phi(np.array([0.5]))
    # q = (gamma - phi) / phi
    assert q[0] == pytest.approx((sp.state(0.5)[1][0] - 0.5) / 0.5, rel=1e-10)


def test_cam_straight_path_closed_form_and_blow_up_message():
    """K = 0: the roller path is the straight line H = H0 / cos(phi), gamma = phi (seed 001, eq. 20)."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    sp = solve_support(CamMechanism(), CurvatureLaw("zero"))
    phi = np.linspace(-0.78, 0.78, 7)
    H, g = sp.state(phi)
    assert H == pytest.approx(110.0 / np.cos(phi), rel=1e-10) and g == pytest.approx(phi, abs=1e-10)
    with pytest.raises(InputError) as e:
        solve_support(CamMechanism(), CurvatureLaw("linear", 0.2))
    m = str(e.value)
    assert m.startswith("CurvatureLaw.k0 = 0.2: roller path of eq. 20 must stay regular (cos γ > 0.001, 0 < ρ < ∞) "
                        "over the support phase |φ| <= 45°; it blows up (")
    assert m.endswith("° (K = 0.2·|φ|)")
    with pytest.raises(InputError) as e:
        solve_support(CamMechanism(), CurvatureLaw("exponential", 0.2, 1.0))
    assert str(e.value).startswith("CurvatureLaw(k0, k1) = (0.2, 1.0): roller path of eq. 20 must stay regular")


def test_cam_quintic_pieces_exact():
    from propulsor.laws.cam_return import ReturnCurve, _mono_row, _quintic_gram

    G = _quintic_gram()
    # int_0^1 (t^k)''' (t^m)''' dt = k(k-1)(k-2) m(m-1)(m-2) / (k + m - 5)
    want = np.zeros((6, 6))
    for k in (3, 4, 5):
        for m in (3, 4, 5):
            want[k, m] = (k * (k - 1) * (k - 2)) * (m * (m - 1) * (m - 2)) / (k + m - 5)
    assert G.tolist() == want.tolist() and G[3, 3] == 36.0 and G[5, 5] == 3600.0 / 5 and G[2, 5] == 0.0
    assert _mono_row(0.5, 0).tolist() == [1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125]
    assert _mono_row(2.0, 2).tolist() == [0.0, 0.0, 2.0, 12.0, 48.0, 160.0]
    assert _mono_row(1.0, 3).tolist() == [0.0, 0.0, 0.0, 6.0, 24.0, 60.0]
    end_a, end_b = (140.0, 30.0, -20.0), (138.0, -28.0, -25.0)
    a, b = math.pi / 4, 7 * math.pi / 4
    for top in (None, 170.0):
        rc = ReturnCurve.build(end_a, end_b, a, b, top)
        assert rc.a == a and rc.L == pytest.approx(0.75 * math.pi, rel=1e-15) and rc.coef.shape == (2, 6)
        for phi, end in ((a, end_a), (b, end_b)):
            vals = [float(v[0]) for v in rc.derivs(np.array([phi]), 2)]
            assert vals == pytest.approx(list(end), rel=1e-10)
        left = rc.derivs(np.array([math.pi - 1e-9]))
        right = rc.derivs(np.array([math.pi + 1e-9]))
        for m in range(3):
            assert float(left[m][0]) == pytest.approx(float(right[m][0]), rel=1e-6, abs=1e-5)
        if top is not None:
            assert float(rc.derivs(np.array([math.pi]), 0)[0][0]) == pytest.approx(170.0, rel=1e-12)
        # the derivatives are those of the values: central differences
        p, h = np.array([2.0, 4.5]), 1e-5
        d = rc.derivs(p)
        for m in range(3):
            fd = (rc.derivs(p + h, m + 1)[m] - rc.derivs(p - h, m + 1)[m]) / (2 * h)
            assert d[m + 1] == pytest.approx(fd, rel=1e-6, abs=1e-6)
        assert len(rc.derivs(p)) == 4 and len(rc.derivs(p, 1)) == 2
    # minimum jerk: any other C2 closure with the same ends has a larger integral of H'''^2
    free = ReturnCurve.build(end_a, end_b, a, b, None)
    pinned = ReturnCurve.build(end_a, end_b, a, b, 170.0)
    phi = np.linspace(a, b, 20001)
    jerk = lambda rc: float(np.trapezoid(rc.derivs(phi)[3] ** 2, phi))  # noqa: E731
    assert jerk(free) < jerk(pinned)


def test_cam_motion_turn_written_out():
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion

    m = CamMechanism(channel_clearance=0.3, P_return=400.0)
    cm = cam_motion(m, CurvatureLaw("quadratic", 0.017), ReturnPhase("top", 160.0), estimate_error=False)
    s = math.pi / 4
    assert cm.wrap(np.array([-s, s, 2 * math.pi - s, 7.0])) == pytest.approx([-s, s, -s, 7.0 - 2 * math.pi],
                                                                                rel=1e-15)
    assert cm.leg_angles(0.1) == pytest.approx([0.1, 0.1 + math.pi / 2, 0.1 + math.pi, 0.1 + 1.5 * math.pi],
                                               rel=1e-15)
    assert cm.leg_angles(np.array([0.0, 0.2])).shape == (2, 4)
    assert float(cm.ret.derivs(np.array([math.pi]), 0)[0][0]) == pytest.approx(160.0, rel=1e-10)
    phi = np.array([0.3, s, 2.0, 5.0, 2 * math.pi + 0.3])
    H, H1, H2, sup = cm.H_derivs(phi)
    assert sup.tolist() == [True, True, False, False, True]
    d = cm.support.derivs(np.array([0.3, s]))
    assert H[:2] == pytest.approx(d["H"], rel=1e-14) and H1[:2] == pytest.approx(d["H1"], rel=1e-13)
    r = cm.ret.derivs(np.array([2.0, 5.0]), 2)
    assert H[2:4] == pytest.approx(r[0], rel=1e-14) and H2[2:4] == pytest.approx(r[2], rel=1e-13)
    assert H[4] == pytest.approx(H[0], rel=1e-14)
    hs = cm.hub_speed(np.array([0.3, 0.3 + math.pi / 2, -0.2]))
    d3 = cm.support.derivs(np.array([0.3, -0.2]))
    assert hs == pytest.approx([d3["H1"][0] * math.sin(0.3) + 320.0, d3["H1"][0] * math.sin(0.3) + 320.0,
                                d3["H1"][1] * math.sin(-0.2) + 320.0], rel=1e-13)
    t = cm.table(phi)
    gam = np.arctan2(H1, H)
    K = (H * H + 2 * H1 * H1 - H * H2) / (H * H + H1 * H1) ** 1.5
    psi = phi - gam
    assert t.gamma == pytest.approx(gam, rel=1e-15) and t.K_path == pytest.approx(K, rel=1e-13)
    assert t.dgamma == pytest.approx(1 - H * K / np.cos(gam), rel=1e-13)
    assert t.psi == pytest.approx(psi, rel=1e-15)
    assert t.X == pytest.approx(H * np.sin(phi) - 20 * np.sin(psi), rel=1e-14)
    assert t.Y == pytest.approx(H * np.cos(phi) - 20 * np.cos(psi), rel=1e-14)
    assert t.X_outer == pytest.approx(H * np.sin(phi) + 20.3 * np.sin(psi), rel=1e-14)
    assert t.Y_outer == pytest.approx(H * np.cos(phi) + 20.3 * np.cos(psi), rel=1e-14)
    R = 1 / K - 20
    assert t.R_profile == pytest.approx(R, rel=1e-13) and t.R_outer == pytest.approx(-(1 / K + 20.3), rel=1e-13)
    assert t.R_path == pytest.approx(1 / K, rel=1e-13)
    E = 2 * 2.1e5 * 2.1e5 / (4.2e5)
    P = np.where(sup, 5000.0, 400.0)
    arg = P * E / (20.0 * np.cos(gam)) * (1 / 20 + 1 / R)
    ok = (arg > 0) & ~((K > 0) & (R <= 0))
    assert t.sigma_H[ok] == pytest.approx(0.418 * np.sqrt(arg[ok]), rel=1e-13)
    assert t.hub_speed == pytest.approx(cm.hub_speed(phi), rel=1e-15)
    assert t.support.tolist() == sup.tolist() and t.H.tolist() == H.tolist()
    # the straight support path (K = 0) has an infinite radius and the roller's own curvature in Hertz
    z = cam_motion(CamMechanism(), CurvatureLaw("zero"), ReturnPhase("min_jerk"), estimate_error=False).table(
        np.array([0.2]))
    assert abs(z.K_path[0]) < 1e-9


def test_damper_speed_sweep_is_one_run_a_speed():
    from propulsor.laws.damper_heat import Road, speed_sweep, simulate

    st = _station_numbers()
    road = Road(0.4, 2.0)
    runs = speed_sweep(st, road, [1, 2.5], 1.5)
    assert [r.V for r in runs] == [1.0, 2.5] and type(runs[0].V) is float
    for r, V in zip(runs, (1.0, 2.5)):
        one = simulate(st, road, V, 1.5)
        assert r.T.tolist() == one.T.tolist() and r.z2.tolist() == one.z2.tolist()
        assert r.mean_power == one.mean_power and len(r.t) == 400 and r.t[-1] == 1.5
    assert speed_sweep(st, road, [], 1.5) == []


def test_damper_numerical_path_at_rest_and_on_a_slow_road():
    """V = 0 (omega = 0: the window is the whole run) and omega = 0.63 rad/s < 1 (one period of 10 s, the last
    of a 30 s run): the exact solution and DOP853 agree on the window's mean power."""
    from propulsor.laws.damper_heat import Road, Station, simulate

    st = _station_numbers()
    rest = simulate(st, Road(0.4, 2.0), 0.0, 2.0, n_out=3, rtol=1e-10)
    assert rest.T.tolist() == [10.0, 10.0, 10.0] and rest.mean_power == 0.0 and rest.z2.tolist() == [0.0, 0.0, 0.0]
    light = Station(m1=400.0, C1=2.0e6, b1=2.0e3, b2=3e3)
    road = Road(0.1, 2.0)
    V = 0.2                                                   # omega = 2 pi 0.2 / 2 = 0.628 rad/s, T = 10 s
    e = simulate(light, road, V, 30.0, n_out=31)
    n = simulate(light, road, V, 30.0, n_out=31, rtol=1e-11)
    assert e.mean_power == pytest.approx(n.mean_power, rel=1e-6)
    whole = simulate(light, road, V, 10.0, n_out=11)          # the same window alone, from rest: a different mean
    assert abs(whole.mean_power / e.mean_power - 1) > 1e-6
    assert e.t[1] == 1.0 and e.T[-1] == pytest.approx(n.T[-1], abs=1e-9)


def test_damper_run_shorter_than_one_road_period_averages_the_whole_run():
    """Bug fixed: a run shorter than one road period (t_end = 5 s, T = 6.67 s) averaged the power over a window
    starting before t = 0, the motion extrapolated backwards (exact: 6e7 W, DOP853's dense output: 4e19 W); now
    the window is the whole run, as at V = 0."""
    from scipy.integrate import solve_ivp

    from propulsor.laws.damper_heat import Road, Station, _rhs, simulate

    light = Station(m1=400.0, C1=2.0e6, b1=2.0e3, b2=3e3)
    road = Road(0.1, 1.0)
    V, t_end = 0.15, 5.0                                      # omega = 0.94 rad/s, T = 6.67 s > t_end
    f, w = _rhs(light, road, V, False)
    assert 2 * math.pi / w > t_end
    sol = solve_ivp(f, (0.0, t_end), [0, 0, 0, 0, 20.0], method="DOP853", rtol=1e-12, atol=1e-13, dense_output=True)
    ts = np.linspace(0.0, t_end, 201)                          # the module's 200 samples of one window
    y = sol.sol(ts)
    want = float(np.trapezoid(3e3 * (y[3] - y[1]) ** 2, ts) / t_end)
    assert simulate(light, road, V, t_end).mean_power == pytest.approx(want, rel=1e-6)
    assert simulate(light, road, V, t_end, rtol=1e-11).mean_power == pytest.approx(want, rel=1e-6)
