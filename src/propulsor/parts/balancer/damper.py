"""Heat of the station's telescopic damper (seed 004 ch. 6, eq. 73–75, Table 11) beside the road
wheel's tyre heat (ch. 7): the two-mass model of :mod:`propulsor.laws.damper_heat` integrated over the
seed's roads and speeds, in a forked worker while the balancer's solids are checked.

Inputs that are not in the seed (ours): the tyre-on-track stiffness and damping of the unsprung mass,
C1 = 2 MN/m and b1 = 2 kN·s/m (a rubber-tyred road wheel on a steel track); the unsprung mass is the
built balancer plus its road wheel.  The sprung mass per wheel (3125 kg), the damper's mass, surface and
steel, the air and the design speed are Table 11's; the damper coefficient at the wheel is ch. 2's μ_mean.
"""

from __future__ import annotations

import numpy as np

from ... import policy
from ...parallel import start as start_in_fork

__all__ = ["start_damper_heat", "damper_heat_results", "ROADS", "C1_N_PER_M", "B1_NS_PER_M"]

C1_N_PER_M, B1_NS_PER_M = 2.0e6, 2.0e3
#: seed 004 §6.2: sinusoidal roads, height 0.2 m at 1, 1.5, 2, 2.5 vehicle bases (D = 6.846 m), and the
#: short 0.05 m bumps at the mean road-wheel spacing (1 m, Δt4 of §6.3)
ROADS = (("Δt5: L = 6.846 m (1 base), 0.2 m", 0.2, 6.846), ("Δt1: L = 10.269 m (1.5 bases), 0.2 m", 0.2, 10.269),
         ("Δt2: L = 13.692 m (2 bases), 0.2 m", 0.2, 13.692), ("Δt3: L = 17.115 m (2.5 bases), 0.2 m", 0.2, 17.115),
         ("Δt4: L = 1 m (wheel spacing), 0.05 m", 0.05, 1.0))


def _job(m1: float, b2: float):
    from ...laws.damper_heat import TABLE_11, Road, Station, cooling_coefficient, simulate

    st = Station(m1=m1, C1=C1_N_PER_M, b1=B1_NS_PER_M, b2=b2)
    speeds = np.asarray(policy.DAMPER_HEAT_SPEEDS_KMH, float) / 3.6
    out = []
    for name, h, L in ROADS:
        road = Road(h, L)
        runs = [simulate(st, road, float(V), policy.DAMPER_HEAT_T_END_S) for V in speeds]
        design = simulate(st, road, TABLE_11["V"], policy.DAMPER_HEAT_T_END_S)
        steady = [r.mean_power / cooling_coefficient(st, r.V) for r in runs]
        out.append((name, h, L, runs, steady, design))
    return st, speeds, out


def start_damper_heat(m, w, built: dict) -> None:
    """Start the damper-heat integration in a forked worker (needs the built unsprung mass)."""
    m1 = float(built["mass"] + built["wm_tot"])
    w.progress("damper heat (seed 004 ch. 6): two-mass model over 5 roads × "
               f"{len(policy.DAMPER_HEAT_SPEEDS_KMH)} speeds, in a second process")
    built["pending_damper"] = start_in_fork(_job, m1, float(m.design.mu_mean))


def damper_heat_results(m, w, built: dict) -> None:
    """Table, derived values, plot (damper beside the tyre) and note of the damper heat."""
    from ...export.plots import new_figure
    from ...laws.damper_heat import TABLE_11

    st, speeds, res = built.pop("pending_damper").result()
    D = w.derived
    rows = []
    for name, h, L, runs, steady, design in res:
        for r, s in zip(runs, steady):
            rows.append([name, h, L, r.V * 3.6, r.mean_power, r.rise, s])
    w.add_table("damper_heat", ["road", "height_m", "wavelength_m", "V_kmh", "mean_damper_power_W",
                                f"rise_after_{policy.DAMPER_HEAT_T_END_S:g}s_K", "steady_rise_K"], rows)
    worst = max(((name, max(steady), runs[int(np.argmax(steady))].V) for name, h, L, runs, steady, _ in res),
                key=lambda x: x[1])
    D.update({"damper_heat_m1_unsprung_kg": st.m1, "damper_heat_b2_Ns_per_m": st.b2,
              "damper_heat_max_steady_rise_K": worst[1], "damper_heat_max_steady_rise_road": worst[0],
              "damper_heat_max_steady_rise_speed_kmh": worst[2] * 3.6})
    for name, h, L, runs, steady, design in res:
        D[f"damper_heat_rise_at_{TABLE_11['V']:g}mps_L{L:g}_K"] = design.rise

    # pragma: no mutate start (the figure only; the table, values and note above and below are the numbers)
    fig, _ = new_figure(13.0, 4.4)
    fig.clf()
    ax1, ax2, ax3 = (fig.add_subplot(1, 3, k) for k in (1, 2, 3))
    for ax in (ax1, ax2, ax3):
        ax.grid(True, lw=0.4, alpha=0.6)
    for name, h, L, runs, steady, design in res:
        ax1.plot(design.t, design.T, lw=0.9, label=name)
        ax2.plot(speeds * 3.6, steady, marker="o", ms=3, lw=0.9, label=name)
    ax1.set_xlabel("time, s")
    ax1.set_ylabel("damper temperature, °C")
    ax1.set_title(f"Damper at V = {TABLE_11['V']:g} m/s (Table 11)", fontsize=9)
    ax2.set_xlabel("vehicle speed V, km/h")
    ax2.set_ylabel("steady damper temperature rise, K")
    ax2.set_title("Damper heat over speed (seed 004 ch. 6)", fontsize=9)
    ax2.legend(fontsize=6)
    tyre = m.wheel_p.tyre()
    V = np.linspace(0.0, float(max(policy.DAMPER_HEAT_SPEEDS_KMH)), 101)
    P_row = m.wheel_p.load_N / m.wheel_p.rows
    ax3.plot(V, tyre.temperature(P_row, V, m.wheel_p.t_air_C) - m.wheel_p.t_air_C, lw=1.2)
    ax3.set_xlabel("vehicle speed V, km/h")
    ax3.set_ylabel("steady tyre temperature rise, K")
    ax3.set_title("Road wheel tyre, Kozlov (seed 004 ch. 7)", fontsize=9)
    fig.tight_layout()
    # pragma: no mutate end
    w.add_plot("damper_and_tyre_heat", fig)
    w.add_note(
        f"Damper heat (seed 004 ch. 6): two-mass station, sprung {st.m2:g} kg, unsprung {st.m1:.1f} kg (built balancer "
        f"+ road wheel), C2 = {st.C2:g} N/m, damper b2 = μ_mean = {st.b2:.0f} N·s/m at the wheel, tyre on track "
        f"C1 = {st.C1:g} N/m, b1 = {st.b1:g} N·s/m (ours), solved exactly (matrix exponential of the linear system) over "
        f"{policy.DAMPER_HEAT_T_END_S:g} s from rest at {st.T_env:g} °C; damper {st.m_a:g} kg of steel "
        f"({st.c_steel:g} J/(kg·K)), cooled by the air flow V·S·ρ·c_air over S = {st.S:g} m². Largest steady rise "
        f"{worst[1]:.2f} K on {worst[0]} at {worst[2] * 3.6:.0f} km/h. The printed sprung-mass equation has the "
        f"damper with the wrong sign (it feeds energy in) and no damper reaction on the wheel; eq. 75 lacks the "
        f"damper's mass — readings in propulsor/laws/damper_heat.py. Plot: plots/damper_and_tyre_heat.png, beside "
        f"the road wheel's tyre heat.")
