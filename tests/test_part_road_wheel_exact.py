"""The road wheel's design and its Kozlov proof, number by number (parts/road_wheel/design.py, proofs.py): the load
per row, the wheel model of the part file, and Kozlov's tyre heat (seed 004 eq. 76-80) computed in the test from the
seed's formulas - l = 2·∛(H/R)·√(R·P/(E·b)), λ_m = l²/8R, q_m = 4P/(π·b·l), A = π·q_m·λ_m·b·R·(1 − λ_m/2R),
Q = ψ·A·n/60 with n = V/(2πR), T = t_air + Q/(α·F) - with the checks, derived values and table on a stub of the
output writer.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``road_wheel_design``): no solid is
built and nothing written.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import importlib

from propulsor.errors import InputError
from propulsor.parts.road_wheel.params import RoadWheelParams
from stand_ins import SaidWriter

rd = importlib.import_module("propulsor.parts.road_wheel.design")  # the package's `design` is the function
rp = importlib.import_module("propulsor.parts.road_wheel.proofs")


def _kozlov(P, V_kmh, R=315.0, b=90.0, H=40.0, E=6.0, psi=0.35, alpha=60.0, t_air=20.0, printed=False):
    """Seed 004 eq. 76-80 by hand: (l, λ_m, q_m, q_mean, A [J], n [rpm], Q [W], T [°C], F [mm²])."""
    l = 2.0 * (H / R) ** (1.0 / 3.0) * math.sqrt(R * P / (E * b))
    lam = l * l / (8.0 * R)
    q_m = 4.0 * P / (math.pi * b * l)
    A = math.pi * q_m * lam * b * R * (1.0 - lam / (2.0 * R)) / 1000.0
    V = np.asarray(V_kmh, float)
    n = V / 3.6 * 60.0 / (2.0 * math.pi * R / 1000.0) * (2.0 if printed else 1.0)
    Q = psi * A * n / 60.0
    F = 2.0 * math.pi * (R ** 2 - (R - H) ** 2) + 2.0 * math.pi * R * b
    T = t_air + Q / (alpha * F * 1e-6)
    return dict(l=l, lam=lam, q_m=q_m, q_mean=P / (b * l), A=A, n=n, Q=Q, T=T, F=F)


def test_design_of_the_part_file():
    p = RoadWheelParams()
    dd = rd.design(p)
    assert dd.p is p and dd.P_row == 31490.0 / 2
    m = dd.model
    assert (m.r_tyre, m.r_rim_out, m.r_rim_in, m.r_hub) == (315.0, 275.0, 263.0, 105.0)
    assert m.rows_z == [(5.0, 95.0), (175.0, 265.0)] and m.z_mid == 135.0
    t = dd.tyre
    assert (t.R, t.b, t.H, t.E, t.alpha, t.psi) == (315.0, 90.0, 40.0, 6.0, 60.0, 0.35)
    one = rd.design(RoadWheelParams(rows=1, load_N=10000.0))
    assert one.P_row == 10000.0 and one.model.rows_z == [(5.0, 95.0)] and one.model.z_mid == 50.0


def test_feasible_refuses_geometry_that_cannot_be_made():
    assert rd.feasible(RoadWheelParams()) is None
    with pytest.raises(InputError) as e:
        rd.feasible(RoadWheelParams(tyre_radius_mm=150.0, tyre_thickness_mm=80.0, load_N=1000.0))
    assert str(e.value) == "tyre_thickness_mm = 80.0: must be < R/2 = 75 mm"
    with pytest.raises(InputError) as e:
        rd.design(RoadWheelParams(tyre_radius_mm=150.0, tyre_thickness_mm=80.0, load_N=1000.0))
    assert str(e.value) == "tyre_thickness_mm = 80.0: must be < R/2 = 75 mm"


def test_kozlov_table_of_the_part_file_is_eq_76_to_80():
    p = RoadWheelParams()
    tab = rp.kozlov_table(p)
    assert list(tab) == ["V_kmh", "V_mps", "n_rpm", "track_frequency_Hz", "omega_track_rad_s", "Q_W_per_row", "T_C",
                         "T_printed_n_C"]
    V = np.linspace(0.0, 50.0, 101)
    k = _kozlov(15745.0, V)
    kp = _kozlov(15745.0, V, printed=True)
    assert tab["V_kmh"] == pytest.approx(V, abs=1e-12) and len(tab["V_kmh"]) == 101
    assert tab["V_mps"] == pytest.approx(V / 3.6, rel=1e-12)
    assert tab["n_rpm"] == pytest.approx(k["n"], rel=1e-12)
    # the track links at pitch t: f = V/t, ω = 2πV/t
    assert tab["track_frequency_Hz"] == pytest.approx(V / 3.6 / 0.15, rel=1e-12)
    assert tab["omega_track_rad_s"] == pytest.approx(2 * math.pi * V / 3.6 / 0.15, rel=1e-12)
    assert tab["Q_W_per_row"] == pytest.approx(k["Q"], rel=1e-12)
    assert tab["T_C"] == pytest.approx(k["T"], rel=1e-12)
    assert tab["T_printed_n_C"] == pytest.approx(kp["T"], rel=1e-12)
    assert tab["T_C"][0] == 20.0 and tab["T_printed_n_C"][-1] - 20.0 == pytest.approx(2 * (tab["T_C"][-1] - 20.0))
    short = rp.kozlov_table(p, num=3)
    assert short["V_kmh"] == pytest.approx([0.0, 25.0, 50.0]) and short["n_rpm"] == pytest.approx(
        _kozlov(15745.0, [0.0, 25.0, 50.0])["n"])


def test_kozlov_table_of_other_fields():
    p = RoadWheelParams(rows=1, load_N=12000.0, tyre_radius_mm=300.0, tyre_width_mm=70.0, tyre_thickness_mm=30.0,
                        E_rubber_MPa=8.0, psi=0.4, alpha_W_m2K=50.0, t_air_C=-10.0, V_max_kmh=70.0,
                        track_pitch_m=0.2)
    tab = rp.kozlov_table(p, num=5)
    V = np.linspace(0.0, 70.0, 5)
    k = _kozlov(12000.0, V, R=300.0, b=70.0, H=30.0, E=8.0, psi=0.4, alpha=50.0, t_air=-10.0)
    assert tab["V_kmh"] == pytest.approx(V)
    assert tab["n_rpm"] == pytest.approx(k["n"], rel=1e-12)
    assert tab["track_frequency_Hz"] == pytest.approx(V / 3.6 / 0.2, rel=1e-12)
    assert tab["Q_W_per_row"] == pytest.approx(k["Q"], rel=1e-12)
    assert tab["T_C"] == pytest.approx(k["T"], rel=1e-12)
    # the printed n (twice the wheel speed) on the same air: a rise twice as large above −10 °C
    kp = _kozlov(12000.0, V, R=300.0, b=70.0, H=30.0, E=8.0, psi=0.4, alpha=50.0, t_air=-10.0, printed=True)
    assert tab["T_printed_n_C"] == pytest.approx(kp["T"], rel=1e-12)
    assert tab["T_printed_n_C"][0] == -10.0


def test_kozlov_proof_of_the_part_file():
    p = RoadWheelParams()
    dd = rd.design(p)
    w, built = SaidWriter(), {}
    rp.kozlov_proof(dd, w, built)
    k = _kozlov(15745.0, 50.0)
    kp = _kozlov(15745.0, 50.0, printed=True)
    assert w.said == ["Kozlov tyre heat (seed 004 eq. 76-80)"]
    d = w.derived
    assert list(d) == ["load_per_row_N", "contact_length_l_mm", "deflection_lambda_m_mm", "peak_pressure_q_m_MPa",
                       "mean_pressure_MPa", "work_per_turn_A_J", "cooling_surface_F_mm2", "n_at_V_max_rpm",
                       "heat_at_V_max_Q_W", "T_at_V_max_C", "T_at_V_max_printed_n_C", "track_frequency_at_V_max_Hz",
                       "tyre_radius_mm", "rim_outer_radius_mm", "rim_inner_radius_mm", "wheel_mid_plane_z_mm",
                       "hub_bore_inner_seat_mm", "hub_bore_outer_seat_mm", "spindle_seats_required_mm"]
    assert d["load_per_row_N"] == 15745.0
    assert d["contact_length_l_mm"] == pytest.approx(k["l"], rel=1e-12)
    assert d["deflection_lambda_m_mm"] == pytest.approx(k["lam"], rel=1e-12)
    assert d["peak_pressure_q_m_MPa"] == pytest.approx(k["q_m"], rel=1e-12)
    assert d["mean_pressure_MPa"] == pytest.approx(k["q_mean"], rel=1e-12)
    assert d["work_per_turn_A_J"] == pytest.approx(k["A"], rel=1e-12)
    assert d["cooling_surface_F_mm2"] == pytest.approx(k["F"], rel=1e-12)
    assert d["n_at_V_max_rpm"] == pytest.approx(float(k["n"]), rel=1e-12)
    assert d["n_at_V_max_rpm"] == pytest.approx(50.0 / 3.6 * 60 / (2 * math.pi * 0.315), rel=1e-12)
    assert d["heat_at_V_max_Q_W"] == pytest.approx(float(k["Q"]), rel=1e-12)
    assert d["T_at_V_max_C"] == pytest.approx(float(k["T"]), rel=1e-12)
    assert d["T_at_V_max_printed_n_C"] == pytest.approx(float(kp["T"]), rel=1e-12)
    assert d["track_frequency_at_V_max_Hz"] == pytest.approx(50.0 / 3.6 / 0.15, rel=1e-12)
    assert (d["tyre_radius_mm"], d["rim_outer_radius_mm"], d["rim_inner_radius_mm"], d["wheel_mid_plane_z_mm"]) == (
        315.0, 275.0, 263.0, 135.0)
    assert (d["hub_bore_inner_seat_mm"], d["hub_bore_outer_seat_mm"]) == (180.0, 140.0)
    assert d["spindle_seats_required_mm"] == [100.0, 80.0]
    for key in ("contact_length_l_mm", "deflection_lambda_m_mm", "T_at_V_max_C", "n_at_V_max_rpm"):
        assert type(d[key]) is float
    got = [(c.name, c.passed, c.limit, c.unit) for c in w.checks]
    assert got == [("tyre temperature at V_max (Kozlov, eq. 76)", True, 120.0, "°C"),
                   ("mean contact pressure P/(b l)", True, 5.0, "MPa"),
                   ("deflection / rubber thickness", True, 1.0, "")]
    T, q, ratio = (c.value for c in w.checks)
    assert T == pytest.approx(float(k["T"]), rel=1e-12) and q == pytest.approx(k["q_mean"], rel=1e-12)
    assert ratio == pytest.approx(k["lam"] / 40.0, rel=1e-12)
    assert w.checks[0].message == (f"steady tyre temperature at 50 km/h, kinematic n; with the seed's printed n "
                                   f"(twice the wheel speed) it would be {float(kp['T']):.1f} °C")
    assert w.checks[1].message == "seed 004 §7.1 first tyre criterion; admissible value ours"
    assert w.checks[2].message == "Kozlov's λ_m (eq. 79) must stay inside the rubber"
    cols, rows = w.tables["tyre_temperature"]
    assert rows is None and len(cols["V_kmh"]) == 101
    assert cols["T_C"] == pytest.approx(rp.kozlov_table(p)["T_C"], rel=1e-12)
    assert set(w.plots) == {"tyre_temperature"}
    assert w.plots["tyre_temperature"].axes[0].get_title() == "Solid tyre temperature (seed 004 ch. 7), P = 15745 N per row"
    assert built == pytest.approx(dict(l=k["l"], lam=k["lam"], T_vmax=float(k["T"]), T_vmax_printed=float(kp["T"]),
                                       q_mean=k["q_mean"], q_m=k["q_m"]), rel=1e-12)


def test_kozlov_proof_fails_a_hot_tyre_and_a_high_pressure():
    """One row under the whole load at 80 km/h on warm air: every check fails (the deflection too, at 0.6 of H...)."""
    p = RoadWheelParams(rows=1, load_N=30000.0, V_max_kmh=80.0, t_air_C=40.0, t_allow_C=60.0, q_allow_MPa=1.0,
                        tyre_thickness_mm=20.0)
    dd = rd.design(p)
    w, built = SaidWriter(), {}
    rp.kozlov_proof(dd, w, built)
    k = _kozlov(30000.0, 80.0, H=20.0, t_air=40.0)
    assert [c.passed for c in w.checks] == [False, False, k["lam"] / 20.0 <= 1.0]
    assert w.checks[0].value == pytest.approx(float(k["T"]), rel=1e-12)
    kp = _kozlov(30000.0, 80.0, H=20.0, t_air=40.0, printed=True)
    assert w.derived["T_at_V_max_printed_n_C"] == pytest.approx(float(kp["T"]), rel=1e-12)
    assert built["T_vmax_printed"] == pytest.approx(float(kp["T"]), rel=1e-12)
    assert w.derived["n_at_V_max_rpm"] == pytest.approx(80.0 / 3.6 * 60 / (2 * math.pi * 0.315), rel=1e-12)
    assert w.derived["load_per_row_N"] == 30000.0 and w.derived["track_frequency_at_V_max_Hz"] == pytest.approx(
        80.0 / 3.6 / 0.15)
    assert w.checks[0].message.startswith("steady tyre temperature at 80 km/h, kinematic n;")
    assert w.checks[2].value == pytest.approx(k["lam"] / 20.0, rel=1e-12)
