"""Kozlov's solid-tyre heat estimate (seed 004 ch. 7, eq. 76-80) and the Table 12 rows.

The seed prints no Kozlov example with numbers; the printed numbers it does give (Table 12
formula rows, the 36 kg x 30 g estimate, 36 km/h = 10 m/s) are reproduced, and the
Kozlov chain is checked against an independent SI re-computation and its own physics
(load balance of the pressure, sagitta of the chord, scaling laws)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor.errors import InputError
from propulsor.laws.tyre_heat import (
    SolidTyre,
    air_cooling_coefficient,
    heating_coefficient,
    inertial_load,
    n_rpm,
    track_frequency,
    tyre_surface,
)

# illustrative tyre of the seed's road wheel: D_k = 630 mm (seed ch. 5), one row of a
# double wheel carrying half of P_st = 31 490 N; b, H, E, alpha are assumptions.
TYRE = SolidTyre(R=315.0, b=90.0, H=40.0, E=6.0, alpha=60.0, psi=0.35)
P_ROW = 31490.0 / 2


# ------------------------------------------------------------- Table 12 rows
def test_track_frequency_table12():
    w = track_frequency([4.0, 7.0, 20.0], 0.15)   # V = 4; 7; 20 m/s, L = 0.15 m
    assert w == pytest.approx([167.552, 293.215, 837.758], abs=1e-3)
    # "high-frequency (up to 140 Hz)" load: at the highest studied speed, 20 m/s
    assert w[-1] / (2 * math.pi) == pytest.approx(133.33, abs=0.01)
    assert w[-1] / (2 * math.pi) < 140.0


def test_table12_heating_and_cooling_coefficients():
    assert heating_coefficient(0.336, 1420) == pytest.approx(2.0959e-3, rel=1e-4)
    fc = air_cooling_coefficient([4.0, 7.0, 20.0], 0.002)   # V A rho c_air
    assert fc == pytest.approx([9.648, 16.884, 48.24], abs=1e-9)


def test_track_frequency_load_estimate_36kg_30g():
    F = inertial_load(36, 30)               # seed: 36 kg x 30 g ~ 1000 kgf
    assert F / 9.81 == pytest.approx(1080.0)
    assert abs(F / 9.81 / 1000 - 1) < 0.1
    assert F == pytest.approx(31490 / 3, rel=0.01)   # a third of P_st


def test_wheel_speed_eq77_and_printed_factor_two():
    # 36 km/h = 10 m/s on a 630 mm wheel: 10 / (2 pi 0.315) rev/s
    n = n_rpm(36.0, 315.0)
    assert n == pytest.approx(10 / (2 * math.pi * 0.315) * 60, rel=1e-12)
    assert n == pytest.approx(303.16, abs=0.01)
    assert n_rpm(36.0, 315.0, as_printed=True) == pytest.approx(2 * n, rel=1e-12)


# ------------------------------------------------------------- Kozlov chain
def test_kozlov_against_independent_si_computation():
    # all in SI, written out here independently of the module's mm units
    R, b, H, E, P, psi, alpha = 0.315, 0.090, 0.040, 6e6, P_ROW, 0.35, 60.0
    l = 2 * (H / R) ** (1 / 3) * math.sqrt(R * P / (E * b))          # eq. 80
    lam = l**2 / (8 * R)                                             # eq. 79
    q = 4 * P / (math.pi * b * l)
    A = math.pi * q * lam * b * R * (1 - lam / (2 * R))              # eq. 78, J
    V = 50.0                                                         # km/h
    n = V / 3.6 / (2 * math.pi * R) * 60                             # rpm
    Q = psi * A * n / 60                                             # eq. 77, W
    F = 2 * math.pi * (R**2 - (R - H) ** 2) + 2 * math.pi * R * b
    T = 20 + Q / (alpha * F)                                         # eq. 76
    assert float(TYRE.contact_length(P)) == pytest.approx(l * 1000, rel=1e-12)
    assert float(TYRE.deflection(P)) == pytest.approx(lam * 1000, rel=1e-12)
    assert float(TYRE.q_m(P)) == pytest.approx(q / 1e6, rel=1e-12)
    assert float(TYRE.work_per_turn(P)) == pytest.approx(A, rel=1e-12)
    assert float(TYRE.heat_rate(P, V)) == pytest.approx(Q, rel=1e-12)
    assert float(TYRE.temperature(P, V)) == pytest.approx(T, rel=1e-12)
    # the illustrative numbers themselves (regression)
    assert l * 1000 == pytest.approx(96.34, abs=0.01)
    assert T == pytest.approx(114.56, abs=0.01)


def test_pressure_integrates_to_load_and_deflection_is_sagitta():
    P = np.array([2e3, P_ROW, 3e4])
    l = TYRE.contact_length(P)
    # semi-elliptic pressure of peak q_m over the chord: pi/4 q_m b l = P
    assert math.pi / 4 * TYRE.q_m(P) * TYRE.b * l == pytest.approx(P, rel=1e-12)
    assert TYRE.q_mean(P) == pytest.approx(math.pi / 4 * TYRE.q_m(P), rel=1e-12)
    sag = TYRE.R - np.sqrt(TYRE.R**2 - (l / 2) ** 2)
    lam = TYRE.deflection(P)
    assert np.all(np.abs(lam / sag - 1) < (l / TYRE.R) ** 2 / 8)


def test_scaling_laws():
    P = P_ROW
    assert float(TYRE.contact_length(4 * P)) == pytest.approx(2 * float(TYRE.contact_length(P)), rel=1e-12)
    assert float(TYRE.deflection(4 * P)) == pytest.approx(4 * float(TYRE.deflection(P)), rel=1e-12)
    # temperature rise is linear in speed and in psi
    r1 = float(TYRE.temperature(P, 20.0)) - 20
    r2 = float(TYRE.temperature(P, 40.0)) - 20
    assert r2 == pytest.approx(2 * r1, rel=1e-12)
    T2 = SolidTyre(R=315.0, b=90.0, H=40.0, E=6.0, alpha=60.0, psi=0.5)
    assert float(T2.temperature(P, 20.0)) - 20 == pytest.approx(r1 * 0.5 / 0.35, rel=1e-12)
    # a thicker tyre deflects more (l ~ H^(1/3)) and heats more
    T3 = SolidTyre(R=315.0, b=90.0, H=60.0, E=6.0, alpha=60.0, psi=0.35, F=TYRE.F)
    assert float(T3.temperature(P, 50.0)) > float(TYRE.temperature(P, 50.0))


def test_temperature_curve():
    c = TYRE.temperature_curve(P_ROW, 50.0, num=11)
    assert c["V_kmh"][0] == 0 and c["V_kmh"][-1] == 50
    assert c["T_C"][0] == pytest.approx(20.0)
    assert np.all(np.diff(c["T_C"]) > 0)


def test_default_surface():
    assert TYRE.F == pytest.approx(tyre_surface(315, 90, 40))
    assert TYRE.F == pytest.approx(2 * math.pi * (315**2 - 275**2) + 2 * math.pi * 315 * 90)


@settings(max_examples=50, deadline=None)
@given(P=st.floats(1e3, 4e4), V=st.floats(1, 80))
def test_temperature_above_air_and_monotone_in_load(P, V):
    t1 = float(TYRE.temperature(P, V))
    t2 = float(TYRE.temperature(1.1 * P, V))
    assert 20 < t1 < t2


# ------------------------------------------------------------- bad input
@pytest.mark.parametrize("kw, name", [
    (dict(H=315.0), "H"),
    (dict(psi=1.5), "psi"),
    (dict(E=0.0), "E"),
    (dict(R=float("nan")), "R"),
    (dict(alpha=-1.0), "alpha"),
    (dict(F=0.0), "F"),
])
def test_tyre_input_errors(kw, name):
    args = dict(R=315.0, b=90.0, H=40.0, E=6.0, alpha=60.0)
    args.update(kw)
    with pytest.raises(InputError) as e:
        SolidTyre(**args)
    assert e.value.parameter == name


def test_load_and_speed_errors():
    with pytest.raises(InputError, match="P"):
        TYRE.temperature(-1.0, 20.0)
    with pytest.raises(InputError, match="V"):
        n_rpm(-5.0, 315.0)
    with pytest.raises(InputError, match="t_track"):
        track_frequency(4.0, 0.0)
    soft = SolidTyre(R=315.0, b=90.0, H=10.0, E=0.05, alpha=60.0)
    with pytest.raises(InputError, match="deflection"):
        soft.deflection(3e4)
