"""Load path of the 50 t tracked carrier: design torque, final-drive torques, track forces and the
traction calculation (seed 004 ch. 4.1, 4.2 and ch. 5).

    M_vk.max = f·M·g·z·t / (2π·η_gus)                              eq. 40  (sprocket torque, N·m)
    i_sil = 1 + p·η_vnsh·η_vnt,   η_br = i_sil / i_br                eq. 41  (printed "1 − p·…": sign misprint)
    M_sol = M_vk.max·Ω / (i_br·η_br) = M_vk.max·Ω / i_sil            eq. 42
    M_sat = M_vk.max·Ω / (i_br·n_w·η_br)                             eq. 43
    P_sat = M_vk.max·Ω / (r_vod·n_w·i)                               eq. 44  (load on one planet bearing)
    P_t = 2π·M_vk.max / (z_vk·t)                                     eq. 45  (track pull)
    P_sv = max(0, P_0 − P_t / (1 + z_sv/z_rab)),  P_r = P_sv + P_t    eq. 46
    Q = √(P_sv² + P_r² + 2·P_sv·P_r·cos 30°)                         eq. 47  (load on the sprocket axle)

    N_str.m = 4.57e-6·n_N² − 0.010·n_N + 9                          eq. 54  (transmission speed losses, kW)
    f_k = B_0 − 1.46e-5·D_k                                          eq. 55
    N_sgm = (f_r + f_k)·M·g·V_max / 3600                             eq. 56  (running gear speed losses, kW)
    N_e.ob = (f_c·M·g·V/(3600 η_r) + K_f·F·V³/(3.6³·10³·η_r) + N_sgm)/η_tr + N_str.m    eq. 57
    N'_e = 1.2·N_e.ob                                                eq. 58
    P_max = (f_max·cos α_max + sin α_max)·M·g                        eq. 64
    V_min = 3600·max N_e.ob·η_gm / P_max                             eq. 65
    n_k = n_N·n'_k,  N_ek = N'_e·N_k,  M_ek = 9550·N_ek/n_k              after eq. 58 (Table 8 of ch. 5)
    N_ej = 0.06·N'_e·(n_k/n_N)²,  N_vo = 0.03·N'_e·(n_k/n_N)²,  N_vsp = 0.035·N'_e   eq. 59–61
    N_e.ob = N_ek − N_ej − N_vo − N_vyp − N_vsp,  M_e.ob = 9550·N_e.ob/n_k           eq. 62–63 (Table 10)
    q = 0.9·n_N / n_M,   m_n = (lg V_max − lg V_min − lg K_g)/lg q    eq. 66
    q_ut = (V_max / (K_g·V_min))^(1/(m_n − 1))                       eq. 68
    V_1max = V_min,  V_jmax = V_min·K_g·q_ut^(j−1)  (j >= 2)           after eq. 68 (ch. 5.1.2)
    U_tr,j = 0.06·n_N·z·t / V_jmax                                   eq. 69  (total ratio, t in m)
    N_str,n = 4.1e-6·n² − 0.0099·n + 7.4  (gears 1, 2)               eq. 70  (transmission speed losses, kW)
    N_str,n = 4.7e-6·n² − 0.0099·n + 9    (gears 3, 4)               eq. 71
    N_cr,Vj = (f_r + f_k)·M·g·V_kj / 3600                            eq. 72  (running-gear speed losses, kW)
    V_kj = 0.06·z·t·n_k / U_tr,j                                     ch. 5.1.3 (printed "3.6·z_Г·n_k/(60·U)")
    f_g = 3600·((N_e.ob − N_str)·η_tr − N_cr)·η_r / (M·g·V_kj)        ch. 5.1.3 (specific pull per gear and point)
    f_c = f·cos α + sin α,  f = 0.03 ... 0.15,  α = 0 ... 30° by 5°    ch. 5.1.3 (resistance lines, Fig. 18)

What the printed digits say (each one reproduced in ``tests/test_traction.py``):

* eq. 40 prints t = 0.14 m but its result 90 690 N·m is the track pitch of eq. 45 and ch. 5,
  t = 0.125 m (90 687.503 N·m, the value ch. 4.3 carries on); with 0.14 m it is 101 570 N·m.
* eq. 42: 22 399 N·m is M_vk.max·Ω / i_sil truncated (22 399.6); with the rounded η_br = 0.981 it
  would be 22 392.6.
* eq. 43: 6 849 N·m is M_vk.max / (i_sil·n_w) truncated (6 849.95) — without the Ω the equation
  prints; with Ω it is 7 466.5 N·m.
* eq. 44: 91 527 N is the formula with M_vk.max = 90 687.503 N·m.
* eq. 46: P_r is printed 303 895.739 N, one newton below P_t + 0 = 303 896.739 N.
* eq. 54 gives 7.28 kW for n_N = 2000, printed 7.08 kW; eq. 57 reproduces its printed 664.498 kW
  only with 7.08 kW and η_tr = 0.932.
* Table 10 prints the ejector cooling N_ej (eq. 59) as 0 in every mode, yet its "total" and N_e.ob rows
  include it: 41 kW in mode 1 = 4.417 + 28 + 8.834 (eq. 59 with n_vn = n_k), 100 kW in mode 7 = 24 + 28 + 48.
* eq. 64 gives 279 232.837 N; printed 279 322.837 N (digits transposed). eq. 65's printed
  V_min = 7.852 km/h follows from the correct 279 232.837 N.
* eq. 66 with the printed q = 1.261 gives m_n = 7.03, printed 4.41 (and 4.794 for the "+1" form);
  eq. 68 with the chosen m_n = 4 gives the printed q_ut = 1.721.
* ch. 5.1.2 prints the top speeds per gear 7.852, 16.888, 29.058, 50 km/h: V_min·K_g·q_ut^(j−1) with the
  unrounded q_ut = 1.72062 (with the printed 1.721: 16.892, 29.070, 50.030); the second gear starts a step
  K_g·q_ut = 2.15 above the first.  Of eq. 69's four ratios the text prints 28.655, 7.743 and 4.5; the second,
  13.323, is lost in the print.  The Mathcad line before eq. 68 prints q_ut = 1.524 with a "K_k" that no
  input defines (1.524 needs K_k = 1.80 at m_n = 4): not reproducible.
* eq. 70/71 and f_g have no printed values (their results are Figs. 16–18, not in the text).  n_vn, the
  gearbox input speed, is taken as the engine speed n_k (the input reducer's ratio is not given).  At n_N
  eq. 71 gives 8.0 kW for the high gears where eq. 54 gave 7.28 kW (printed 7.08) for the same box.

Units: forces N, torques N·m, power kW, speeds km/h, masses kg (as the seed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from propulsor.errors import require_positive

__all__ = ["G_ACC", "sprocket_torque", "power_ratio", "final_drive_torques", "planet_bearing_load",
           "track_forces", "TrackForces", "FinalDriveTorques", "Vehicle", "VEHICLE_004", "transmission_speed_loss",
           "rolling_loss_coefficient", "running_gear_speed_loss", "engine_power_required", "max_traction_force",
           "min_speed", "gear_count", "progression_ratio", "transmission_efficiency", "ENGINE_004",
           "engine_characteristic", "gear_top_speeds", "transmission_ratio", "transmission_speed_loss_geared",
           "vehicle_speed", "traction_coefficient", "resistance_coefficient", "TractionCharacteristic",
           "traction_characteristic", "RESISTANCE_F", "RESISTANCE_ALPHA_DEG"]

G_ACC = 9.81  # m/s², seed 004 eq. 40


def sprocket_torque(f: float, M: float, z: int, t: float, eta_gus: float, g: float = G_ACC) -> float:
    """Largest sprocket torque M_vk.max, N·m (seed 004 eq. 40); f specific pull, M mass kg, t pitch m."""
    for name, v in (("f", f), ("M", M), ("z", z), ("t", t), ("eta_gus", eta_gus)):
        require_positive(name, v)
    return f * M * g * z * t / (2.0 * math.pi * eta_gus)


def power_ratio(p: float, eta_external: float, eta_internal: float) -> float:
    """Power ratio i_sil = 1 + p·η_vnsh·η_vnt of a ring-fixed planetary set (seed 004 eq. 41)."""
    return 1.0 + p * eta_external * eta_internal


@dataclass(frozen=True)
class FinalDriveTorques:
    M_vk: float     # sprocket (carrier) torque, N·m
    i_br: float     # kinematic ratio
    i_sil: float    # power ratio (eq. 41)
    eta_br: float   # efficiency i_sil / i_br
    M_sol: float    # sun torque, N·m (eq. 42)
    M_sat: float    # torque one planet passes, as eq. 43 prints (with Ω), N·m
    M_ring: float   # ring reaction M_vk − M_sol, N·m


def final_drive_torques(M_vk: float, i_br: float, p: float, eta_external: float, eta_internal: float,
                        Omega: float, n_w: int) -> FinalDriveTorques:
    """Sun and planet torques of the final drive at the sprocket torque (seed 004 eq. 41–43)."""
    require_positive("M_vk", M_vk)
    require_positive("n_w", n_w)
    i_sil = power_ratio(p, eta_external, eta_internal)
    eta = i_sil / i_br
    M_sol = M_vk * Omega / (i_br * eta)
    M_sat = M_vk * Omega / (i_br * n_w * eta)
    return FinalDriveTorques(M_vk, i_br, i_sil, eta, M_sol, M_sat, M_vk - M_vk / i_sil)


def planet_bearing_load(M_vk: float, Omega: float, r_vod: float, n_w: int, i: int) -> float:
    """Load on one planet bearing P_sat, N (seed 004 eq. 44); r_vod carrier radius m, i bearings per planet."""
    require_positive("r_vod", r_vod)
    return M_vk * Omega / (r_vod * n_w * i)


@dataclass(frozen=True)
class TrackForces:
    P_t: float      # track pull, N (eq. 45)
    P_sv_raw: float  # slack-side tension before the clamp, N (eq. 46)
    P_sv: float     # slack-side tension, N (>= 0)
    P_r: float      # working-side tension, N
    Q: float        # load on the sprocket axle, N (eq. 47)


def track_forces(M_vk: float, z_vk: int, t: float, P_0: float, z_sv: int, z_rab: int,
                 wrap_deg: float = 30.0) -> TrackForces:
    """Track branch tensions and the sprocket axle load (seed 004 eq. 45–47); t in m."""
    require_positive("t", t)
    P_t = 2.0 * math.pi * M_vk / (z_vk * t)
    raw = P_0 - P_t / (1.0 + z_sv / z_rab)
    P_sv = max(0.0, raw)
    P_r = P_sv + P_t
    c = math.cos(math.radians(wrap_deg))
    return TrackForces(P_t, raw, P_sv, P_r, math.sqrt(P_sv ** 2 + P_r ** 2 + 2.0 * P_sv * P_r * c))


# --- chapter 5: traction -----------------------------------------------------------------------------
@dataclass(frozen=True)
class Vehicle:
    """Inputs of seed 004 ch. 5 ("Параметры машины / дороги / двигателя / движителя")."""

    M: float = 50000.0          # kg
    V_max: float = 50.0         # km/h
    K_f: float = 0.6            # N·s²/m⁴, drag coefficient
    F: float = 10.293           # m², frontal area
    eta_gm_max: float = 0.87    # efficiency at the lowest speed
    alpha_max_deg: float = 30.0
    i_slope: float = 0.025
    f_gr: float = 0.015
    f_gr_max: float = 0.08
    n_N: float = 2000.0         # rpm at maximum power
    K_g: float = 1.25           # ratio step of first to second gear
    z: int = 15
    t: float = 0.125            # m
    D_k: float = 630.0          # mm, road wheel
    eta_r: float = 0.94         # track–sprocket efficiency (ch. 5; eq. 40 uses 0.92)
    f_r: float = 0.02           # specific track rewinding losses
    B_0: float = 0.034          # rubber-tyred double road wheel


VEHICLE_004 = Vehicle()


def transmission_efficiency(counts) -> float:
    """η_tr = Π 0.985^n_cyl·0.96^n_bev·0.99^n_pl over the reducers (seed 004 ch. 5.1, Table 9)."""
    eta = 1.0
    for n_cyl, n_bev, n_pl in counts:
        eta *= 0.985 ** n_cyl * 0.96 ** n_bev * 0.99 ** n_pl
    return eta


def transmission_speed_loss(n_N: float) -> float:
    """Speed losses of a central planetary gearbox at maximum power, kW (seed 004 eq. 54)."""
    return 4.57e-6 * n_N ** 2 - 0.010 * n_N + 9.0


def rolling_loss_coefficient(B_0: float, D_k: float) -> float:
    """f_k = B_0 − 1.46e-5·D_k, D_k in mm (seed 004 eq. 55)."""
    return B_0 - 1.46e-5 * D_k


def running_gear_speed_loss(v: Vehicle, V: float | None = None) -> float:
    """Speed losses in the running gear N_sgm, kW (seed 004 eq. 56 / eq. 72 at speed V km/h)."""
    V = v.V_max if V is None else V
    return (v.f_r + rolling_loss_coefficient(v.B_0, v.D_k)) * v.M * G_ACC * V / 3600.0


def engine_power_required(v: Vehicle, eta_tr: float, N_str: float) -> float:
    """Engine power N_e.ob needed at V_max on the design road, kW (seed 004 eq. 57)."""
    f_c = v.f_gr + v.i_slope
    V = v.V_max
    road = f_c * v.M * G_ACC * V / (3600.0 * v.eta_r)
    air = v.K_f * v.F * V ** 3 / (3.6 ** 3 * 1e3 * v.eta_r)
    return (road + air + running_gear_speed_loss(v)) / eta_tr + N_str


def max_traction_force(v: Vehicle) -> float:
    """Largest pull on the steepest slope P_max, N (seed 004 eq. 64)."""
    a = math.radians(v.alpha_max_deg)
    return (v.f_gr_max * math.cos(a) + math.sin(a)) * v.M * G_ACC


def min_speed(N_eob_max: float, eta_gm: float, P_max: float) -> float:
    """Lowest speed V_min, km/h (seed 004 eq. 65)."""
    return 3600.0 * N_eob_max * eta_gm / P_max


def gear_count(V_max: float, V_min: float, K_g: float, q: float) -> float:
    """Required number of gears m_n (seed 004 eq. 66)."""
    return (math.log(V_max) - math.log(V_min) - math.log(K_g)) / math.log(q)


def progression_ratio(V_max: float, V_min: float, K_g: float, m_n: int) -> float:
    """Refined geometric ratio step q_ut (seed 004 eq. 68)."""
    return (V_max / (K_g * V_min)) ** (1.0 / (m_n - 1))


#: seed 004 ch. 5, "Таблица 8. Характеристики двигателя": relative speed n'_k and relative power N_k per mode
ENGINE_004 = ((0.429, 0.4), (0.524, 0.556), (0.619, 0.678), (0.714, 0.783), (0.810, 0.889), (0.905, 0.978),
              (1.0, 1.0), (1.04, 0.5))


def engine_characteristic(N_e: float, n_N: float, modes=ENGINE_004, N_exhaust: float = 0.0) -> dict:
    """External speed characteristic in the vehicle (seed 004 eq. 59–63, Table 10): per mode the speed,
    power, torque, the losses of the engine's systems and what is left, kW, rpm, N·m."""
    require_positive("N_e", N_e)
    require_positive("n_N", n_N)
    out = {k: [] for k in ("n_k", "N_ek", "M_ek", "N_ej", "N_vo", "N_vsp", "N_total", "N_eob", "M_eob")}
    for rel_n, rel_N in modes:
        n = n_N * rel_n
        N = N_e * rel_N
        ej = 0.06 * N_e * (n / n_N) ** 2
        vo = 0.03 * N_e * (n / n_N) ** 2
        vsp = 0.035 * N_e
        tot = ej + vo + N_exhaust + vsp
        for k, v in (("n_k", n), ("N_ek", N), ("M_ek", 9550.0 * N / n), ("N_ej", ej), ("N_vo", vo), ("N_vsp", vsp),
                     ("N_total", tot), ("N_eob", N - tot), ("M_eob", 9550.0 * (N - tot) / n)):
            out[k].append(v)
    return out


# --- chapter 5.1.2-5.1.3: ratios and the traction characteristic ------------------------------------------
#: seed 004 ch. 5.1.3: the family of resistance lines f_c, soil f = 0.03 ... 0.15 (step ours), slope 0 ... 30° by 5°
RESISTANCE_F = (0.03, 0.06, 0.09, 0.12, 0.15)
RESISTANCE_ALPHA_DEG = (0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0)


def gear_top_speeds(V_min: float, K_g: float, q_ut: float, m_n: int) -> list[float]:
    """Top speed of each gear, km/h (seed 004 ch. 5.1.2): V_1 = V_min, V_j = V_min·K_g·q_ut^(j−1) for j >= 2."""
    require_positive("V_min", V_min)
    require_positive("m_n", m_n)
    return [V_min] + [V_min * K_g * q_ut ** (j - 1) for j in range(2, m_n + 1)]


def transmission_ratio(n_N: float, z: int, t: float, V: float) -> float:
    """Total transmission ratio U_tr at the top speed V (km/h) of a gear (seed 004 eq. 69); t in m, n_N rpm."""
    require_positive("V", V)
    return 0.06 * n_N * z * t / V


def transmission_speed_loss_geared(n: float, high: bool) -> float:
    """Speed losses of the gearbox at input speed n (rpm), kW: eq. 70 (gears 1, 2) or eq. 71 (gears 3, 4)."""
    if high:
        return 4.7e-6 * n * n - 0.0099 * n + 9.0
    return 4.1e-6 * n * n - 0.0099 * n + 7.4


def vehicle_speed(n_k: float, z: int, t: float, U: float) -> float:
    """Vehicle speed V_kj = 0.06·z·t·n_k/U, km/h (seed 004 ch. 5.1.3); n_k rpm, t m."""
    require_positive("U", U)
    return 0.06 * z * t * n_k / U


def traction_coefficient(N_eob: float, N_str: float, eta_tr: float, N_cr: float, eta_r: float, M: float,
                         V: float, g: float = G_ACC) -> float:
    """Specific pull f_g = 3600·((N_e.ob − N_str)·η_tr − N_cr)·η_r/(M·g·V) (seed 004 ch. 5.1.3); kW, kg, km/h."""
    require_positive("V", V)
    return 3600.0 * ((N_eob - N_str) * eta_tr - N_cr) * eta_r / (M * g * V)


def resistance_coefficient(f: float, alpha: float) -> float:
    """Resistance to straight motion f_c = f·cos α + sin α on a slope α (rad) (seed 004 ch. 5.1.3)."""
    return f * math.cos(alpha) + math.sin(alpha)


@dataclass(frozen=True)
class TractionCharacteristic:
    """Seed 004 Fig. 18 as numbers: per gear j (0-based) the ratio and per engine mode k the point."""

    U: tuple            # U_tr per gear (eq. 69)
    V_top: tuple        # top speed per gear, km/h
    n_k: tuple          # engine speed per mode, rpm (Table 10)
    N_eob: tuple        # engine power in the vehicle per mode, kW (Table 10)
    V: tuple            # V[j][k], km/h
    N_str: tuple        # N_str[j][k], kW (eq. 70 / 71)
    N_cr: tuple         # N_cr[j][k], kW (eq. 72)
    f_g: tuple          # f_g[j][k]


def traction_characteristic(v: Vehicle, N_e: float, V_min: float, m_n: int, eta_tr: float,
                            modes=ENGINE_004, high_from: int = 3) -> TractionCharacteristic:
    """The traction characteristic of seed 004 ch. 5.1.2–5.1.3: gears by eq. 68–69, every Table 10 engine point
    in every gear (eq. 70–72, f_g).  Gears >= ``high_from`` (1-based) are the "high" gears of eq. 71."""
    q_ut = progression_ratio(v.V_max, V_min, v.K_g, m_n)
    V_top = gear_top_speeds(V_min, v.K_g, q_ut, m_n)
    U = [transmission_ratio(v.n_N, v.z, v.t, Vj) for Vj in V_top]
    e = engine_characteristic(N_e, v.n_N, modes)
    f_loss = v.f_r + rolling_loss_coefficient(v.B_0, v.D_k)
    V, Nst, Ncr, fg = [], [], [], []
    for j, Uj in enumerate(U):
        high = j + 1 >= high_from
        Vj = [vehicle_speed(n, v.z, v.t, Uj) for n in e["n_k"]]
        sj = [transmission_speed_loss_geared(n, high) for n in e["n_k"]]
        cj = [f_loss * v.M * G_ACC * x / 3600.0 for x in Vj]
        gj = [traction_coefficient(N, s, eta_tr, c, v.eta_r, v.M, x) for N, s, c, x in zip(e["N_eob"], sj, cj, Vj)]
        V.append(tuple(Vj))
        Nst.append(tuple(sj))
        Ncr.append(tuple(cj))
        fg.append(tuple(gj))
    return TractionCharacteristic(tuple(U), tuple(V_top), tuple(e["n_k"]), tuple(e["N_eob"]), tuple(V), tuple(Nst),
                                  tuple(Ncr), tuple(fg))
