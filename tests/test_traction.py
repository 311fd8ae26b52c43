"""Load path of seed 004: eq. 40-47 (ch. 4.1-4.2) and the traction calculation eq. 54-68 (ch. 5).

Every printed number is reproduced to its printed digits, or the test shows with numbers where the
printed value contradicts the printed inputs (see the docstring of propulsor.laws.traction)."""

import math

import pytest

from propulsor.errors import InputError
from propulsor.laws import traction as tr

# ch. 4.1 inputs
F, MASS, Z, ETA_GUS = 0.57, 50000.0, 15, 0.92


def test_eq40_sprocket_torque_uses_the_pitch_of_eq45_not_the_printed_0_14():
    M = tr.sprocket_torque(F, MASS, Z, 0.125, ETA_GUS)
    assert round(M, 3) == 90687.503          # the value §4.3 carries on ("90687.503")
    assert round(M, -1) == 90690             # printed result of eq. 40
    M_printed_t = tr.sprocket_torque(F, MASS, Z, 0.14, ETA_GUS)
    assert round(M_printed_t) == 101570      # with the t = 0.14 m eq. 40 prints
    assert abs(M_printed_t - 90690) / 90690 > 0.1


def test_eq41_power_ratio_and_efficiency():
    assert round(tr.power_ratio(3.5, 0.985, 0.99), 3) == 4.413       # printed as "1 − 3,5·…" (sign)
    assert round(1.0 - 3.5 * 0.985 * 0.99, 3) == -2.413              # what the printed sign would give
    t = tr.final_drive_torques(90687.503, 4.5, 3.5, 0.985, 0.99, 1.09, 3)
    assert round(t.eta_br, 3) == 0.981


def test_eq42_43_sun_and_planet_torque():
    M = tr.sprocket_torque(F, MASS, Z, 0.125, ETA_GUS)
    t = tr.final_drive_torques(M, 4.5, 3.5, 0.985, 0.99, 1.09, 3)
    assert math.floor(t.M_sol) == 22399                               # printed 22 399 (22 399.6 truncated)
    assert round(90690 * 1.09 / (4.5 * 0.981), 1) == 22392.6         # with the printed, rounded inputs
    # eq. 43 prints Ω in the formula but its 6 849 is M/(i_sil·n_w) without it
    assert math.floor(M / (t.i_sil * 3)) == 6849
    assert round(t.M_sat, 1) == 7466.5
    assert t.M_sat == pytest.approx(t.M_sol / 3, rel=1e-12)


def test_eq44_planet_bearing_load():
    M = tr.sprocket_torque(F, MASS, Z, 0.125, ETA_GUS)
    assert round(tr.planet_bearing_load(M, 1.09, 0.18, 3, 2)) == 91527
    assert round(tr.planet_bearing_load(90690, 1.09, 0.18, 3, 2)) == 91530   # with the rounded 90 690


def test_eq45_47_track_forces():
    f = tr.track_forces(90687.503, 15, 0.125, 31057.0, 10, 64)
    assert round(f.P_t, 3) == 303896.739
    assert round(f.P_sv_raw, 3) == -231772.612
    assert f.P_sv == 0.0
    assert round(f.P_r, 3) == 303896.739          # printed 303 895.739: one newton short of P_t + 0
    assert round(f.Q, 3) == round(f.P_r, 3)        # eq. 47 with P_sv = 0 (printed "√(303895,739)")
    # eq. 45 with the printed 3.14 instead of π: 303 742.7, not the printed value
    assert round(90687.503 * 2 * 3.14 / (15 * 0.125), 1) == 303742.7


def test_ch5_transmission_efficiency_and_losses():
    eta = tr.transmission_efficiency([(1, 0, 0), (0, 0, 1), (0, 0, 0), (1, 0, 1), (0, 0, 1), (0, 0, 1)])
    assert round(eta, 3) == 0.932
    # eq. 54: 7.28 kW for n_N = 2000; printed 7.08
    assert round(tr.transmission_speed_loss(2000.0), 2) == 7.28
    assert round(tr.rolling_loss_coefficient(0.034, 630.0), 4) == 0.0248            # eq. 55
    assert round(tr.running_gear_speed_loss(tr.VEHICLE_004), 3) == 305.214          # eq. 56


def test_ch5_engine_power_eq57_58():
    v = tr.VEHICLE_004
    N = tr.engine_power_required(v, 0.932, 7.08)          # with the printed 7.08 kW and η_tr = 0.932
    assert N == pytest.approx(664.498, abs=0.006)           # printed 664.498 (ours 664.494)
    assert round(1.2 * 664.498, 3) == pytest.approx(797.398, abs=1e-9)   # printed 797.397
    assert abs(1.2 * 664.498 - 797.397) < 2e-3
    N_728 = tr.engine_power_required(v, 0.932, tr.transmission_speed_loss(2000.0))
    assert round(N_728, 3) == 664.694                       # with eq. 54 as computed
    assert min((800.0, 1000.0, 630.0), key=lambda s: abs(s - 1.2 * N)) == 800.0     # N'_e = 800 kW


def test_ch5_max_pull_min_speed_gears():
    v = tr.VEHICLE_004
    P = tr.max_traction_force(v)
    assert round(P, 3) == 279232.837                         # printed 279 322.837 (digits transposed)
    assert round(tr.min_speed(700.0, v.eta_gm_max, P), 3) == 7.852          # printed V_min: from the right P
    assert round(tr.min_speed(700.0, v.eta_gm_max, 279322.837), 3) == 7.849  # from the printed P
    q = 0.9 * v.n_N / 1428.0
    assert round(q, 3) == 1.261
    m_n = tr.gear_count(v.V_max, 7.852, v.K_g, q)
    assert round(m_n, 2) == 7.03                             # printed 4.41 (and 4.794 for the "+1" form)
    assert round(tr.progression_ratio(v.V_max, 7.852, v.K_g, 4), 3) == 1.721   # eq. 68 as printed


def test_table10_engine_characteristic_eq59_63():
    e = tr.engine_characteristic(800.0, 2000.0)
    # rows as printed (Table 10; its cells split over lines in the seed's text)
    assert [round(x) for x in e["n_k"]] == [858, 1048, 1238, 1428, 1620, 1810, 2000, 2080]
    assert [math.floor(x) for x in e["N_ek"]] == [320, 444, 542, 626, 711, 782, 800, 400]
    assert [math.floor(x) for x in e["M_ek"]] == [3561, 4053, 4184, 4189, 4192, 4128, 3820, 1836]
    assert round(e["N_vo"][0], 3) == 4.417 and [round(x) for x in e["N_vo"][-2:]] == [24, 26]
    assert e["N_vsp"][0] == pytest.approx(28.0)
    assert [math.floor(x) for x in e["N_total"]] == [41, 47, 55, 64, 75, 86, 100, 105]   # printed truncated
    assert round(e["N_total"][5], 2) == 86.97
    assert [math.floor(10 * x) / 10 for x in e["N_eob"][2:6]] == [486.8, 561.6, 635.9, 695.4]
    assert [round(x) for x in (e["N_eob"][0], e["N_eob"][1], e["N_eob"][6], e["N_eob"][7])] == [279, 397, 700, 294]
    assert [math.floor(x) for x in e["M_eob"]] == [3102, 3617, 3755, 3756, 3749, 3669, 3342, 1350]
    # the printed cooling row is 0 in every mode, but the totals hold eq. 59's ejector losses
    no_ej = [t - j for t, j in zip(e["N_total"], e["N_ej"])]
    assert round(no_ej[0], 1) == 32.4 and round(e["N_ej"][0], 3) == 8.834
    assert round(e["N_ej"][6]) == 48 and round(no_ej[6]) == 52


def test_bad_inputs_name_the_quantity():
    with pytest.raises(InputError, match="t"):
        tr.sprocket_torque(F, MASS, Z, 0.0, ETA_GUS)
    with pytest.raises(InputError, match="r_vod"):
        tr.planet_bearing_load(1.0, 1.0, -1.0, 3, 2)


# --- ch. 5.1.2-5.1.3: gears, ratios, traction characteristic (Fig. 18) -------------------------------------
def test_ch512_gear_top_speeds_and_ratios_eq68_69():
    v = tr.VEHICLE_004
    q = tr.progression_ratio(v.V_max, 7.852, v.K_g, 4)
    V = tr.gear_top_speeds(7.852, v.K_g, q, 4)
    assert round(V[0], 3) == 7.852 and round(V[1], 3) == 16.888 and round(V[3], 3) == 50.0   # as printed
    assert round(V[2], 3) == 29.059                           # printed 29.058: one in the last digit ...
    V_min_eq65 = tr.min_speed(700.0, v.eta_gm_max, tr.max_traction_force(v))     # 7.85151 unrounded
    q65 = tr.progression_ratio(v.V_max, V_min_eq65, v.K_g, 4)
    assert round(tr.gear_top_speeds(V_min_eq65, v.K_g, q65, 4)[2], 3) == 29.058  # ... from eq. 65's unrounded V_min
    # with the printed, rounded q_ut = 1.721 the speeds would not be the printed ones
    assert [round(x, 3) for x in tr.gear_top_speeds(7.852, v.K_g, 1.721, 4)[1:]] == [16.892, 29.07, 50.03]
    U = [tr.transmission_ratio(v.n_N, v.z, v.t, x) for x in V]
    assert round(U[0], 3) == 28.655 and round(U[2], 3) == 7.743 and round(U[3], 3) == 4.5   # printed
    assert round(U[1], 3) == 13.323                           # lost in the print
    assert round(0.06 * v.n_N * v.z * v.t, 3) == 225.0       # the numerator of eq. 69
    # top gear at the engine's rated speed runs at V_max: eq. 69 and the speed formula of 5.1.3 agree
    assert tr.vehicle_speed(v.n_N, v.z, v.t, U[3]) == pytest.approx(v.V_max, rel=1e-12)


def test_ch513_losses_eq70_72():
    assert tr.transmission_speed_loss_geared(2000.0, high=False) == pytest.approx(4.0)    # eq. 70
    assert tr.transmission_speed_loss_geared(2000.0, high=True) == pytest.approx(8.0)     # eq. 71
    # eq. 71 and eq. 54 describe the same box at n_N: 8.0 against 7.28 (printed 7.08) kW
    assert tr.transmission_speed_loss_geared(2000.0, True) > tr.transmission_speed_loss(2000.0) > 7.08
    v = tr.VEHICLE_004
    assert tr.running_gear_speed_loss(v, 50.0) == pytest.approx(305.214, abs=5e-4)      # eq. 72 at V_max = eq. 56


def test_ch513_traction_characteristic():
    v = tr.VEHICLE_004
    c = tr.traction_characteristic(v, 800.0, 7.852, 4, 0.932)
    assert len(c.f_g) == 4 and all(len(row) == 8 for row in c.f_g)
    # the rated point (mode 7, n_N) of each gear lies at that gear's top speed
    for j in range(4):
        assert c.V[j][6] == pytest.approx(c.V_top[j], rel=1e-12)
    # first gear: f_g by hand at the rated point, 3600·((700 − 4.0)·0.932 − 47.931)·0.94/(490 500·7.852)
    N_cr = (0.02 + 0.034 - 1.46e-5 * 630) * 50000 * 9.81 * 7.852 / 3600
    assert c.f_g[0][6] == pytest.approx(3600 * ((700.0 - 4.0) * 0.932 - N_cr) * 0.94 / (490500 * 7.852), rel=1e-9)
    assert round(c.f_g[0][6], 3) == 0.528
    # the steepest design slope (eq. 64: f = 0.08, α = 30°) needs f_c = 0.569: first gear reaches it only near the
    # engine's torque peak (modes 3-5: 0.600), not at rated power (0.528) on which eq. 65 sized V_min
    f_c_max = tr.resistance_coefficient(v.f_gr_max, math.radians(v.alpha_max_deg))
    assert round(f_c_max, 3) == 0.569
    assert max(c.f_g[0]) > f_c_max > c.f_g[0][6]
    assert round(max(c.f_g[0]), 3) == 0.600
    # top gear at V_max pulls the design road (f_c = f_gr + i = 0.04) with the air drag of eq. 57
    air = v.K_f * v.F * (v.V_max / 3.6) ** 2 / (v.M * tr.G_ACC)
    assert c.f_g[3][6] > v.f_gr + v.i_slope + air
    # every gear pulls less than the one below at the same engine point
    for j in range(3):
        assert all(a > b for a, b in zip(c.f_g[j], c.f_g[j + 1]))


def test_ch513_resistance_lines():
    assert tr.resistance_coefficient(0.03, 0.0) == pytest.approx(0.03)
    assert tr.resistance_coefficient(0.15, math.radians(30.0)) == pytest.approx(0.15 * math.sqrt(3) / 2 + 0.5)
    assert tr.RESISTANCE_ALPHA_DEG == (0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0)
    assert min(tr.RESISTANCE_F) == 0.03 and max(tr.RESISTANCE_F) == 0.15
    with pytest.raises(InputError, match="V"):
        tr.traction_coefficient(700.0, 4.0, 0.932, 0.0, 0.94, 50000.0, 0.0)
