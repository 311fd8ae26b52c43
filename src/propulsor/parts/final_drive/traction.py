"""The vehicle's traction characteristic (seed 004 ch. 5.1.2–5.1.3, Fig. 18) in the final drive's build: the
gears the design torque and design speed come from, as a table, a plot, derived values, two checks and a note
with the thesis's values beside ours.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ...check import Check
from .design import FinalDriveDesign

__all__ = ["traction", "GEARS_004", "ENGINE_POWER_004_KW"]

GEARS_004 = 4                  # seed 004 ch. 5.1.2: "Принимаем m_n = 4"
ENGINE_POWER_004_KW = 800.0    # seed 004 eq. 58: N'_e from the recommended series
# seed 004 ch. 5.1.2 as printed: top speed per gear (km/h) and eq. 69's ratios (the second is lost in the print)
PRINTED_V_TOP = (7.852, 16.888, 29.058, 50.0)
PRINTED_U = (28.655, None, 7.743, 4.5)


def traction(dd: FinalDriveDesign, w, built: dict) -> None:
    """Table ``traction_characteristic``, plot ``traction_characteristic``, derived values, checks and a note."""
    from ...laws import traction as tr

    p, ps = dd.p, dd.ps
    if p.design_speed_kmh <= 0.0:
        w.add_note("Traction characteristic (seed 004 ch. 5.1.3) not drawn: design_speed_kmh = 0 gives no lowest gear.")
        return
    w.progress("traction characteristic (seed 004 ch. 5.1.2-5.1.3)")
    v = replace(tr.VEHICLE_004, z=p.sprocket_teeth, t=p.track_pitch_mm * 1e-3)
    eta_tr = tr.transmission_efficiency([(1, 0, 0), (0, 0, 1), (0, 0, 0), (1, 0, 1), (0, 0, 1), (0, 0, 1)])
    c = tr.traction_characteristic(v, ENGINE_POWER_004_KW, p.design_speed_kmh, GEARS_004, eta_tr)
    q_ut = tr.progression_ratio(v.V_max, p.design_speed_kmh, v.K_g, GEARS_004)
    rows = []
    for j in range(GEARS_004):
        for k, n in enumerate(c.n_k):
            rows.append([j + 1, k + 1, n, c.N_eob[k], c.U[j], c.V[j][k], c.N_str[j][k], c.N_cr[j][k], c.f_g[j][k]])
    w.add_table("traction_characteristic", ["gear", "engine_mode", "n_k_rpm", "N_eob_kW", "U_tr", "V_kmh",
                                            "N_str_kW", "N_cr_kW", "f_g"], rows)
    d = w.derived
    d["traction_q_ut"] = q_ut
    d["traction_eta_tr"] = eta_tr
    for j in range(GEARS_004):
        d[f"traction_gear{j + 1}_U_tr"] = c.U[j]
        d[f"traction_gear{j + 1}_V_top_kmh"] = c.V_top[j]
        d[f"traction_gear{j + 1}_f_g_max"] = max(c.f_g[j])
    f_c_max = tr.resistance_coefficient(v.f_gr_max, math.radians(v.alpha_max_deg))
    air = v.K_f * v.F * (v.V_max / 3.6) ** 2 / (v.M * tr.G_ACC)
    f_road = v.f_gr + v.i_slope + air
    k_rated = min(range(len(c.n_k)), key=lambda k: abs(c.n_k[k] - v.n_N))   # Table 10 mode 7, n = n_N
    g1, top = max(c.f_g[0]), c.f_g[-1][k_rated]
    w.add_checks([
        Check.at_least("traction.first_gear_slope", g1, f_c_max, "",
                       f"largest f_g of gear 1 ({g1:.3f}) against f_c = f·cos α + sin α = {f_c_max:.3f} of the "
                       f"steepest slope (seed 004 eq. 64: f = {v.f_gr_max:g}, α = {v.alpha_max_deg:g}°)"),
        Check.at_least("traction.top_gear_road", top, f_road, "",
                       f"f_g of the top gear at n_N ({top:.4f}) against the design road f_gr + i = "
                       f"{v.f_gr + v.i_slope:g} plus air drag {air:.4f} at V_max = {v.V_max:g} km/h (seed 004 eq. 57)"),
    ])
    if w.draws_plots:  # a proof's values only: no figure drawn to be dropped
        _plot(w, tr, c, v)
    i_fd = ps.ratio
    ahead = ", ".join(f"{u / i_fd:.3f}" for u in c.U)
    thesis_V = ", ".join(f"{x:g}" for x in PRINTED_V_TOP)
    ours_V = ", ".join(f"{x:.3f}" for x in c.V_top)
    ours_U = ", ".join(f"{x:.3f}" for x in c.U)
    w.add_note(
        f"Traction characteristic (seed 004 ch. 5.1.2–5.1.3, Fig. 18; table traction_characteristic, plot "
        f"traction_characteristic): {GEARS_004} gears from V_min = {p.design_speed_kmh:g} km/h, K_g = {v.K_g:g}, "
        f"q_ut = {q_ut:.4f} (thesis 1.721). Top speeds {ours_V} km/h (thesis {thesis_V}; its 29.058 follows from "
        f"eq. 65's unrounded V_min = 7.85151, ours 29.059 from the printed 7.852); ratios eq. 69 U_tr = {ours_U} "
        f"(thesis 28.655, —, 7.743, 4.5: the second is lost in the print). Ahead of this final drive (i = {i_fd:g}) "
        f"the gearbox ratios are {ahead}. Every Table 10 engine point in every gear: transmission losses eq. 70 "
        f"(gears 1–2) / eq. 71 (3–4) with the gearbox input at engine speed, running gear eq. 72, η_tr = {eta_tr:.3f}, "
        f"η_r = {v.eta_r:g}; the thesis prints no f_g values (only Fig. 18). Verdict: gear 1 pulls f_g = {g1:.3f} at "
        f"most (near the torque peak; {c.f_g[0][k_rated]:.3f} at rated "
        f"power, on which eq. 65 sized V_min), above the {f_c_max:.3f} of a {v.alpha_max_deg:g}° slope on f = "
        f"{v.f_gr_max:g} and above the adhesion f = 0.57 of eq. 40 — the tracks slip before the engine stalls, so "
        f"the design torque is the adhesion-limited one; the top gear pulls {top:.4f} at V_max against "
        f"{f_road:.4f} needed. Resistance lines f_c = f·cos α + sin α for f = "
        f"{', '.join(f'{x:g}' for x in tr.RESISTANCE_F)} (the thesis gives only 0.03 … 0.15) and α = 0 … 30° by 5°.")


def _plot(w, tr, c, v) -> None:
    import numpy as np

    from ...export.plots import new_figure

    fig, _ = new_figure(9.0, 6.5)
    fig.clf()
    # fixed margins, no tight_layout: the layout pass would draw the figure once more
    gs = fig.add_gridspec(2, 2, width_ratios=(3.0, 1.2), height_ratios=(2.2, 1.0), left=0.08, right=0.98,
                          bottom=0.08, top=0.95, wspace=0.12, hspace=0.22)
    ax = fig.add_subplot(gs[0, 0])
    axr = fig.add_subplot(gs[0, 1], sharey=ax)
    axn = fig.add_subplot(gs[1, 0], sharex=ax)
    for a in (ax, axr, axn):
        a.grid(True, lw=0.4, alpha=0.6)
    for j in range(len(c.U)):
        ax.plot(c.V[j], c.f_g[j], marker="o", ms=3, lw=1.2, label=f"gear {j + 1}, U_tr = {c.U[j]:.3f}")
        axn.plot(c.V[j], c.n_k, marker="o", ms=3, lw=1.0, label=f"gear {j + 1}")
    ax.set_ylabel("specific pull f_g")
    ax.set_title("Traction characteristic, 50 t carrier (seed 004 Fig. 18)", fontsize=9)
    ax.legend(fontsize=7)
    ax.set_ylim(bottom=0.0)
    alphas = np.radians(np.array(tr.RESISTANCE_ALPHA_DEG))
    for f in tr.RESISTANCE_F:
        axr.plot(np.degrees(alphas), [tr.resistance_coefficient(f, a) for a in alphas], marker=".", ms=3, lw=0.9,
                 label=f"f = {f:g}")
    axr.set_xlabel("slope α, °")
    axr.set_title("f_c = f·cos α + sin α", fontsize=9)
    axr.set_xticks(tr.RESISTANCE_ALPHA_DEG[::2])
    axr.legend(fontsize=6)
    axn.set_xlabel("vehicle speed V, km/h")
    axn.set_ylabel("engine speed n, rpm")
    w.add_plot("traction_characteristic", fig)
