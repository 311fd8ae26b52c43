"""Torsion-bar suspension, seed 004 ch. 2 (eq. 1-28): the thesis's printed numbers and
independent checks (energy by quadrature, tangent stiffness by finite differences,
pitch period and log decrement of the damped pitch oscillator from its characteristic roots)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from propulsor.errors import InputError
from propulsor.laws.suspension import (
    SuspensionDesign,
    TorsionSuspension,
    compression_force_max,
    damper_ear_arm,
    equivalent_stiffness,
    mean_damping_coefficient,
    piston_diameter,
    pitch_period,
    pitch_stiffness,
    rebound_damping_max,
    rod_force_ratio,
    thesis_design,
    torsion_bar_diameter,
    uniform_wheel_positions,
)

T = TorsionSuspension()  # seed 004 values: P_st 31490 N, R_b 360, beta_st 43.144, d_T 46, L_T 2000, 1600 MPa, 83 GPa


# ----------------------------------------------------------------- eq. 6-12
def test_gamma_m_printed_96_043():
    assert round(math.degrees(T.gamma_m), 3) == 96.043  # seed: gamma_m = 96.043
    assert round(math.degrees(T.gamma_m), 2) == 96.04   # issue acceptance


def test_gamma_st_against_printed_24_358():
    g = math.degrees(T.gamma_st)
    # eq. 8 with the printed inputs gives 24.348 deg; the seed prints 24.358.  The seed's
    # own later numbers (c' = 2.138e5 with lambda = 0.822) need gamma_st in 24.32...24.35
    # (test below), so the printed last digit is inconsistent; we agree within 0.011 deg.
    assert round(g, 3) == 24.348
    assert abs(g - 24.358) < 0.011


def test_printed_c_prime_pins_gamma_st():
    # c' = 2 lambda P / f_full^2 = 2.138e5 (printed) with lambda = 0.822 m (printed):
    # scan gamma_st and keep the values that reproduce the printed c' to its 4 digits.
    ok = []
    for g in np.arange(24.30, 24.40, 0.001):
        b0 = T.beta_st - math.radians(g)
        f_full = 0.36 * (math.cos(b0) - math.cos(b0 + T.gamma_m))
        if round(equivalent_stiffness(0.822, 31490, f_full) / 1e5, 3) == 2.138:
            ok.append(g)
    assert ok and min(ok) > 24.31 and max(ok) < 24.355
    assert min(ok) <= math.degrees(T.gamma_st) <= max(ok)


def test_angles_round_to_printed_19_and_115():
    assert round(math.degrees(T.beta0)) == 19
    assert round(math.degrees(T.beta_m)) == 115
    assert math.degrees(T.beta0) == pytest.approx(18.7957, abs=1e-4)
    assert math.degrees(T.beta_m) == pytest.approx(114.8389, abs=1e-4)


def test_travel_printed():
    assert round(T.f_st / 1000, 3) == 0.078     # f_st = 0.078 m
    assert round(T.f_full / 1000, 3) == 0.492   # f_full = 0.492 m
    assert round(T.f_dyn / 1000, 3) == 0.414    # f_dyn = 0.414 m (eq. 12)
    # the seed computed from the unrounded angles: the printed 19 / 115 deg give 0.493
    Tr = TorsionSuspension(beta0_deg=19, beta_m_deg=115)
    assert round(Tr.f_full / 1000, 3) == 0.493


def test_bar_diameter_eq6_rounds_to_46():
    d = torsion_bar_diameter(31490, 360, math.radians(43.144), 1600)
    assert d == pytest.approx(46.2145, abs=1e-3)
    assert round(d / 1000, 3) == 0.046          # printed d_T = 0.046
    assert T.d_T_dyn == pytest.approx(d)


# ----------------------------------------------------------------- eq. 13-16
def test_characteristic_consistent_with_static_load():
    # eq. 8 and eq. 13 are the same moment balance: P(beta_st) = P_st
    assert float(T.P(T.beta_st)) == pytest.approx(31490, rel=1e-12)


def test_P_at_beta_m_about_94_kN():
    assert round(T.P_m / 1000) == 94
    assert T.P_m == pytest.approx(93600.4, abs=0.1)
    # the bar is exactly at [tau] there
    assert float(T.tau(T.beta_m)) == pytest.approx(1600.0, rel=1e-12)


def test_characteristic_arrays():
    c = T.characteristic(101)
    assert c["beta"][0] == pytest.approx(T.beta0) and c["beta"][-1] == pytest.approx(T.beta_m)
    assert c["P"][0] == 0.0 and c["f"][0] == pytest.approx(0.0, abs=1e-12)
    assert np.all(np.diff(c["f"]) > 0)
    assert c["P"][-1] == pytest.approx(T.P_m)


def test_lambda_ut_within_1pct_of_printed():
    assert abs(T.lambda_ut / 822.0 - 1) < 0.01   # eq. 16 with d_T = 46 mm: 813.9 mm
    assert T.lambda_ut == pytest.approx(813.888, abs=1e-3)
    # the printed 0.822 m is close to eq. 16 with the unrounded eq. 6 diameter 46.21 mm
    # (821.50 mm, 0.06 % low) - the likeliest source of the seed's value
    Td = TorsionSuspension(d_T=T.d_T_dyn)
    assert Td.lambda_ut == pytest.approx(821.498, abs=1e-3)
    assert abs(Td.lambda_ut / 822.0 - 1) < 1e-3


def test_lambda_ut_is_the_stored_energy_by_quadrature():
    # independent: integrate P df over the travel (df = R_b sin beta dbeta)
    U, _ = quad(lambda b: float(T.P(b)) * T.R_b * math.sin(b), T.beta0, T.beta_m, epsabs=1e-6)
    assert U / T.P_st == pytest.approx(T.lambda_ut, rel=1e-9)
    assert T.energy_full == pytest.approx(U, rel=1e-9)


def test_c_prime_printed_2_138e5():
    # eq. 24 with the printed lambda = 0.822 m and the computed f_full (m)
    c = equivalent_stiffness(0.822, 31490, T.f_full / 1000)
    assert round(c / 1e5, 3) == 2.138
    # the object's own value uses its eq. 16 lambda (1 % low): 2.117e5
    assert T.c_equiv_N_per_m == pytest.approx(2.1173e5, rel=1e-4)
    assert T.c_equiv_N_per_m / c == pytest.approx(T.lambda_ut / 822.0, rel=1e-12)


def test_tangent_stiffness_is_the_printed_164400():
    h = 1e-6
    fd = (float(T.P(T.beta_st + h)) - float(T.P(T.beta_st - h))) / (
        float(T.f(T.beta_st + h)) - float(T.f(T.beta_st - h)))
    assert T.stiffness_at_static == pytest.approx(fd, rel=1e-7)
    # seed: "c = 164400 N/m" (after eq. 1, Table 11); the characteristic's slope at f_st
    assert abs(1000 * T.stiffness_at_static / 164400 - 1) < 1e-3


# ----------------------------------------------------------------- eq. 1, 23-28
def test_eq27_compression_force_printed_2_134e4():
    # G_p = 473 000 N, n = 8 wheels/side, h = 0.05 m, n_a = 4, zdd = g/2
    assert round(compression_force_max(473000, 164400, 8, 0.05, 4) / 1e4, 3) == 2.134
    assert round(thesis_design().R_k_comp_max / 1e4, 3) == 2.134


def test_eq25_rebound_limit_printed_5_229e4():
    mu = rebound_damping_max(2.138e5, 1.8, T.f_full, T.f_st)
    assert mu == pytest.approx(5.229e4, rel=2e-4)   # 5.2285e4: printed digits +-1 in the last


def test_rebound_and_compression_coefficients_printed():
    mu_mean = 3.426e4                       # printed eq. 23 result
    mu_reb = mu_mean / 0.85                 # 0.8 ... 0.9 -> middle
    assert round(mu_reb / 1e4, 3) == 4.031  # printed 4.031e4
    assert mu_reb < 5.229e4                 # smaller of the two is adopted (seed)
    assert round((2 * mu_mean - mu_reb) / 1e4, 2) == 2.82  # eq. 21, printed 28 220


def test_pitch_period_round_trip_and_printed_1_8():
    S = 15.0
    c = pitch_stiffness(421100, 1.8, S)
    assert pitch_period(421100, c, S) == pytest.approx(1.8, rel=1e-12)
    # independent: J theta'' + 2 c S theta = 0 -> period from the eigenvalue
    lam = np.roots([421100, 0.0, 2 * c * S])
    assert 2 * math.pi / abs(lam[0].imag) == pytest.approx(1.8, rel=1e-12)


@pytest.mark.parametrize("nu", [10.0, 13.5, 17.0])
def test_eq23_gives_amplitude_ratio_nu_per_period(nu):
    I_y, c, S, Sa = 421100.0, 2.138e5, 40.17, 35.39
    mu = mean_damping_coefficient(c, I_y, S, Sa, nu)
    r = np.roots([I_y, 2 * mu * Sa, 2 * c * S])  # damped pitch of the body, both sides
    sigma, wd = -r[0].real, abs(r[0].imag)
    assert math.exp(sigma * 2 * math.pi / wd) == pytest.approx(nu, rel=1e-10)


def test_eq23_thesis_numbers_are_inconsistent():
    # with the printed T_phi = 1.8 s and c' = 2.138e5, eq. 26 fixes sum l_i^2; eq. 23
    # then needs the dampers' sum l_j^2 > sum l_i^2 to give the printed 3.426e4
    S = 2 * math.pi**2 * 421100 / (2.138e5 * 1.8**2)
    Sa = mean_damping_coefficient(2.138e5, 421100, S, 1.0, 13.5) / 3.426e4
    assert S == pytest.approx(12.0, abs=0.01) and Sa == pytest.approx(16.42, abs=0.01)
    assert Sa > S


def test_damper_reading_reproduces_piston_0_11():
    d = thesis_design()
    assert d.damper_reading == "lever"
    assert d.L_a == pytest.approx(0.453 * 360)
    assert d.R_a_reb_max == pytest.approx(T.P_m / 0.453)
    assert round(d.D_piston / 1000, 2) == 0.11             # printed D_p = 0.11 m
    # the literal reading (rod force = wheel force * 0.453) gives a 52 mm piston
    F_lit = T.P_m * rod_force_ratio(0.453, "literal")
    assert round(piston_diameter(F_lit, 20.0) / 1000, 2) == 0.05
    assert damper_ear_arm(360, 0.453, "literal") == pytest.approx(360 / 0.453)  # 795 mm > R_b
    # power balance: F_rod V_rod = F_wheel V_k in both readings
    for rd in ("lever", "literal"):
        v_ratio = damper_ear_arm(360, 0.453, rd) / 360  # V_rod / V_k
        assert rod_force_ratio(0.453, rd) * v_ratio == pytest.approx(1.0)


def test_thesis_design_layout_and_derived():
    d = thesis_design()
    assert d.n_side == 8 and d.n_a_side == 4
    assert d.sum_l2 == pytest.approx(40.172, abs=1e-3)
    assert d.mu_comp == pytest.approx(2 * d.mu_mean - d.mu_reb)
    assert d.mu_reb <= d.mu_reb_max
    assert d.c_static == pytest.approx(1000 * T.stiffness_at_static)


def test_uniform_wheel_positions():
    xs = uniform_wheel_positions(8, 6.846)
    assert xs[0] == pytest.approx(-3.423) and xs[-1] == pytest.approx(3.423)
    assert np.diff(xs) == pytest.approx(np.full(7, 6.846 / 7))


# ----------------------------------------------------------------- bad input
@pytest.mark.parametrize("kw, name", [
    (dict(beta0_deg=50.0), "beta0_deg"),                    # beta0 above beta_st
    (dict(beta_m_deg=40.0), "beta_m_deg"),                  # beta_m below beta_st
    (dict(beta0_deg=19.0, beta_m_deg=116.0), "beta_m_deg"),  # twist 97 deg > gamma_m: bar yields
    (dict(R_b=0.0), "R_b"),
    (dict(R_b=-360.0), "R_b"),
    (dict(P_st=float("nan")), "P_st"),
    (dict(d_T=float("inf")), "d_T"),
    (dict(beta_st_deg=180.0), "beta_st_deg"),
    (dict(tau_max=2000.0, beta0_deg=19.0, beta_m_deg=185.0), "beta_m_deg"),
])
def test_input_errors_name_parameter(kw, name):
    with pytest.raises(InputError) as e:
        TorsionSuspension(**kw)
    assert e.value.parameter == name
    assert name in str(e.value)


def test_yield_message_names_value_and_limit():
    with pytest.raises(InputError) as e:
        TorsionSuspension(beta0_deg=19.0, beta_m_deg=116.0)
    msg = str(e.value)
    assert "116" in msg and "1600" in msg and "yields" in msg
    assert msg.startswith("beta_m_deg = 116.0:")  # the value as given, not a degrees(radians) round trip


def test_design_input_errors():
    xs = uniform_wheel_positions(8, 6.846)
    with pytest.raises(InputError, match="damper_x_m"):
        SuspensionDesign(wheel_x_m=xs, damper_x_m=(0.123,))
    with pytest.raises(InputError, match="nu"):
        SuspensionDesign(wheel_x_m=xs, damper_x_m=xs[:1], nu=1.0)
    with pytest.raises(InputError, match="damper_reading"):
        SuspensionDesign(wheel_x_m=xs, damper_x_m=xs[:1], damper_reading="sideways")
    with pytest.raises(InputError, match="h_n"):
        compression_force_max(473000, 164400, 8, 0.5, 4)  # bump so high the limit is negative


# ----------------------------------------------------------------- properties
@settings(max_examples=60, deadline=None)
@given(P=st.floats(5e3, 8e4), R=st.floats(200, 600), bst=st.floats(20, 70),
       d=st.floats(30, 70), L=st.floats(1000, 3000))
def test_identities_hold_for_any_valid_design(P, R, bst, d, L):
    try:
        t = TorsionSuspension(P_st=P, R_b=R, beta_st_deg=bst, d_T=d, L_T=L)
    except InputError:
        return  # e.g. beta_m beyond 180 deg: rejected, fine
    assert float(t.P(t.beta_st)) == pytest.approx(P, rel=1e-10)
    assert float(t.tau(t.beta_m)) == pytest.approx(t.tau_max, rel=1e-10)
    assert t.f_full > t.f_st > 0
    assert t.energy_full == pytest.approx(t.lambda_ut * P, rel=1e-10)


def test_bar_yielding_under_static_load():
    with pytest.raises(InputError) as e:
        TorsionSuspension(d_T=28.0)
    assert e.value.parameter == "d_T" and "yields under the static load" in str(e.value)
