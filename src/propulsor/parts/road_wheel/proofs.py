"""The road wheel's proof: Kozlov's steady tyre temperature (seed 004 eq. 76-80) over speed."""

from __future__ import annotations

import math

import numpy as np

from ...check import Check
from .design import RoadWheelDesign
from .params import RoadWheelParams

__all__ = ["RESONANCE_SPEEDS_MPS", "kozlov_table", "kozlov_proof", "kozlov_plot"]

#: the seed's parametric-resonance speeds of the road wheels (ch. 7, fig. 35), m/s
RESONANCE_SPEEDS_MPS = (7.3, 10.8, 21.7)


def kozlov_table(p: RoadWheelParams, num: int = 101) -> dict:
    """Temperature over speed (seed 004 eq. 76-80) with the track frequency (§7.2)."""
    from ...laws.tyre_heat import track_frequency

    tyre = p.tyre()
    P_row = p.load_N / p.rows
    V = np.linspace(0.0, p.V_max_kmh, num)
    Vm = V / 3.6
    w = track_frequency(Vm, p.track_pitch_m)
    return {
        "V_kmh": V, "V_mps": Vm, "n_rpm": tyre.temperature_curve(P_row, p.V_max_kmh, p.t_air_C, num)["n_rpm"],
        "track_frequency_Hz": w / (2 * math.pi), "omega_track_rad_s": w,
        "Q_W_per_row": tyre.heat_rate(P_row, V),
        "T_C": tyre.temperature(P_row, V, p.t_air_C),
        "T_printed_n_C": tyre.temperature(P_row, V, p.t_air_C, as_printed_n=True),
    }


def kozlov_plot(p: RoadWheelParams, tab: dict):  # pragma: no mutate block (the figure only)
    from ...export.plots import new_figure

    fig, ax = new_figure(7.5, 4.8)
    ax.plot(tab["V_kmh"], tab["T_C"], lw=1.6, label="Kozlov eq. 76-80, n = V/(2πR)")
    ax.plot(tab["V_kmh"], tab["T_printed_n_C"], lw=1.0, ls="--", label="same with the printed n = 60V/(3.6πR)")
    ax.axhline(p.t_allow_C, color="r", lw=0.8, ls=":", label=f"admissible {p.t_allow_C:g} °C (ours)")
    for v in RESONANCE_SPEEDS_MPS:
        vk = 3.6 * v
        if vk <= p.V_max_kmh:
            f = v / p.track_pitch_m
            ax.axvline(vk, color="k", lw=0.7, ls="-.")
            ax.text(vk, ax.get_ylim()[0] + 0.05 * (ax.get_ylim()[1] - ax.get_ylim()[0]),
                    f" {v:g} m/s\n track f = {f:.0f} Hz", fontsize=7)
    ax.set_xlabel("vehicle speed V, km/h")
    ax.set_ylabel("steady tyre temperature T, °C")
    ax.set_title(f"Solid tyre temperature (seed 004 ch. 7), P = {p.load_N / p.rows:.0f} N per row")
    top = ax.secondary_xaxis("top", functions=(lambda v: v / 3.6 / p.track_pitch_m,
                                               lambda f: f * p.track_pitch_m * 3.6))
    top.set_xlabel(f"track frequency f = V/t, Hz (t = {p.track_pitch_m:g} m; ω = 2πf)")
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    return fig


def kozlov_proof(dd: RoadWheelDesign, w, built: dict) -> None:
    """Kozlov's tyre heat (seed 004 eq. 76-80): derived values, checks, table and plot."""
    p, m, tyre, P_row = dd.p, dd.model, dd.tyre, dd.P_row
    d = w.derived
    w.progress("Kozlov tyre heat (seed 004 eq. 76-80)")
    l = float(tyre.contact_length(P_row))
    lam = float(tyre.deflection(P_row))
    T_vmax = float(tyre.temperature(P_row, p.V_max_kmh, p.t_air_C))
    T_vmax_printed = float(tyre.temperature(P_row, p.V_max_kmh, p.t_air_C, as_printed_n=True))
    q_mean, q_m = float(tyre.q_mean(P_row)), float(tyre.q_m(P_row))
    d.update({
        "load_per_row_N": P_row, "contact_length_l_mm": l, "deflection_lambda_m_mm": lam,
        "peak_pressure_q_m_MPa": q_m, "mean_pressure_MPa": q_mean,
        "work_per_turn_A_J": float(tyre.work_per_turn(P_row)),
        "cooling_surface_F_mm2": tyre.F,
        "n_at_V_max_rpm": float(tyre.temperature_curve(P_row, p.V_max_kmh, p.t_air_C, 2)["n_rpm"][-1]),
        "heat_at_V_max_Q_W": float(tyre.heat_rate(P_row, p.V_max_kmh)),
        "T_at_V_max_C": T_vmax, "T_at_V_max_printed_n_C": T_vmax_printed,
        "track_frequency_at_V_max_Hz": p.V_max_kmh / 3.6 / p.track_pitch_m,
        "tyre_radius_mm": m.r_tyre, "rim_outer_radius_mm": m.r_rim_out, "rim_inner_radius_mm": m.r_rim_in,
        "wheel_mid_plane_z_mm": m.z_mid,
        "hub_bore_inner_seat_mm": p.bearing_inner_D_mm, "hub_bore_outer_seat_mm": p.bearing_outer_D_mm,
        "spindle_seats_required_mm": [p.bearing_inner_d_mm, p.bearing_outer_d_mm],
    })
    w.add_checks([
        Check.at_most("tyre temperature at V_max (Kozlov, eq. 76)", T_vmax, p.t_allow_C, "°C",
                      f"steady tyre temperature at {p.V_max_kmh:g} km/h, kinematic n; with the seed's printed n "
                      f"(twice the wheel speed) it would be {T_vmax_printed:.1f} °C"),
        Check.at_most("mean contact pressure P/(b l)", q_mean, p.q_allow_MPa, "MPa",
                      "seed 004 §7.1 first tyre criterion; admissible value ours"),
        Check.at_most("deflection / rubber thickness", lam / p.tyre_thickness_mm, 1.0, "",
                      "Kozlov's λ_m (eq. 79) must stay inside the rubber"),
    ])
    tab = kozlov_table(p)
    w.add_table("tyre_temperature", tab, None)
    w.add_plot("tyre_temperature", kozlov_plot(p, tab))
    built.update(l=l, lam=lam, T_vmax=T_vmax, T_vmax_printed=T_vmax_printed, q_mean=q_mean, q_m=q_m)
