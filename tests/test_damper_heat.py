"""Damper heat of one road-wheel station (seed 004 ch. 6, eq. 73-75, Table 11).

The seed prints no result numbers for ch. 6 (its figure 25 is lost); what is checked: Table 11 as
given, the printed model's defects shown with numbers, and the physics of the integrated model
(energy balance of the heat equation, steady temperature = mean power / air-flow coefficient, the
linear model's frequency response)."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.laws.damper_heat import TABLE_11, Road, Station, cooling_coefficient, simulate

ST = Station(m1=400.0, C1=2.0e6, b1=2.0e3)
ROAD = Road(0.2, 6.846)


def test_table11_and_the_units_it_mixes():
    assert TABLE_11["m"] == pytest.approx(50000 / 16)           # 3125 kg: the 50 t vehicle on 16 wheels
    assert TABLE_11["V"] == pytest.approx(50 / 3.6, abs=5e-4)   # 13.889 m/s = 50 km/h
    assert TABLE_11["C"] == 164400.0                            # ch. 2's c = 164 400 N/m ("кН/град" printed)
    # eq. 75 as printed, A / ht_steel: 1 kJ gives 2.05 "K" — with the damper's 20 kg it is 0.103 K
    assert 1000.0 / TABLE_11["c_steel"] == pytest.approx(2.053, abs=1e-3)
    assert 1000.0 / (TABLE_11["m_a"] * TABLE_11["c_steel"]) == pytest.approx(0.1027, abs=1e-4)
    assert cooling_coefficient(ST, 13.889) == pytest.approx(13.889 * 0.247 * 1.2 * 1005, rel=1e-12)


def test_the_printed_damper_sign_feeds_energy_in():
    printed = simulate(ST, ROAD, 3.0, 20.0, as_printed=True)
    ours = simulate(ST, ROAD, 3.0, 20.0)
    assert np.abs(ours.z2).max() < 0.2                       # bounded, about the road height
    assert np.abs(printed.z2).max() > 1e6                    # metres: the printed equations blow up


def test_heat_equation_balance_and_steady_state():
    r = simulate(ST, ROAD, TABLE_11["V"], 30.0)
    k = cooling_coefficient(ST, r.V)
    tau = ST.m_a * ST.c_steel / k
    assert tau < 3.0                                         # air flow at 50 km/h: a 2.4 s time constant
    # after > 10 τ the temperature sits at the mean damper power over the cooling coefficient
    assert r.rise == pytest.approx(r.mean_power / k, rel=0.03)
    assert r.T[0] == ST.T_env and r.T[-len(r.T) // 4:].min() > ST.T_env + 0.5 * r.rise


def test_body_response_matches_the_linear_frequency_response():
    """Steady amplitude of z2 against the complex frequency response of the same two-mass system."""
    V = 8.0
    r = simulate(ST, ROAD, V, 40.0, n_out=4001)
    w = 2 * math.pi * V / ROAD.wavelength
    s = 1j * w
    K = np.array([[ST.m1 * s * s + (ST.b1 + ST.b2) * s + ST.C1 + ST.C2, -(ST.b2 * s + ST.C2)],
                  [-(ST.b2 * s + ST.C2), ST.m2 * s * s + ST.b2 * s + ST.C2]])
    Z = np.linalg.solve(K, np.array([(ST.C1 + ST.b1 * s) * ROAD.a, 0.0]))
    tail = r.z2[len(r.z2) // 2:]
    assert 0.5 * (tail.max() - tail.min()) == pytest.approx(abs(Z[1]), rel=2e-3)
    # mean damper power = ½ b2 ω² |Z2 − Z1|²
    P = 0.5 * ST.b2 * w * w * abs(Z[1] - Z[0]) ** 2
    assert r.mean_power == pytest.approx(P, rel=2e-3)


def test_short_bumps_heat_more_than_long_waves_at_speed():
    """§6.4: the damper heats most on high-frequency periodic roads."""
    long_ = simulate(ST, Road(0.2, 17.115), 8.0, 30.0)
    short = simulate(ST, Road(0.05, 1.0), 8.0, 30.0)
    assert short.rise > 10 * long_.rise


def test_bad_inputs():
    with pytest.raises(InputError, match="m1"):
        Station(m1=0.0, C1=1.0, b1=0.0)
    with pytest.raises(InputError, match="t_end"):
        simulate(ST, ROAD, 1.0, 0.0)


@pytest.mark.parametrize("road,V,as_printed", [(ROAD, 5.0, False), (Road(0.05, 1.0), 13.889, False),
                                               (ROAD, 3.0, True)])
def test_exact_solution_agrees_with_a_numerical_integration(road, V, as_printed):
    """simulate() solves the linear station exactly (matrix exponential of the quadratic-form states); scipy's
    DOP853 on the equations as written (rtol 1e-10) gives the same temperature, body motion and power."""
    t_end = 20.0 if as_printed else 30.0
    exact = simulate(ST, road, V, t_end, as_printed=as_printed)
    num = simulate(ST, road, V, t_end, as_printed=as_printed, rtol=1e-10)
    scale = np.abs(num.z2).max()
    assert np.abs(exact.z2 - num.z2).max() <= 1e-7 * scale
    if not as_printed:
        assert np.abs(exact.T - num.T).max() < 1e-7
        assert exact.mean_power == pytest.approx(num.mean_power, rel=1e-8)
