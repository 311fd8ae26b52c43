"""The balancer's plots: elastic characteristic, stresses along the arm, side view, travel clearance."""

from __future__ import annotations

import math

import numpy as np

from .design import BalancerModel

__all__ = ["characteristic_plot", "stress_plot", "side_view_plot", "sweep_plot"]


def characteristic_plot(m: BalancerModel):
    from ...export.plots import new_figure

    t = m.tor
    c = t.characteristic(361)
    fig, ax = new_figure(7.0, 4.6)
    ax.plot(c["f"], c["P"] / 1000, lw=1.5, label="P(f), eq. 11 and 13")
    for b, lab, off in ((t.beta_st, "β_ст", (12, -28)), (t.beta_m, "β_m", (-160, -6))):
        ax.plot([float(t.f(b))], [float(t.P(b)) / 1000], "o", ms=5)
        ax.annotate(f"{lab} = {math.degrees(b):.3f}°\nf = {float(t.f(b)):.1f} mm, P = {float(t.P(b)) / 1000:.2f} kN",
                    (float(t.f(b)), float(t.P(b)) / 1000), textcoords="offset points", xytext=off, fontsize=7)
    k = t.stiffness_at_static
    fs = np.linspace(t.f_st - 60, t.f_st + 60, 3)
    ax.plot(fs, (t.P_st + k * (fs - t.f_st)) / 1000, "--", lw=0.8, label=f"tangent at f_ст: c = {1000 * k:.0f} N/m")
    ax.set_xlabel("wheel travel f, mm")
    ax.set_ylabel("force at the wheel axis P, kN")
    ax.set_title("Elastic characteristic of the torsion-bar suspension (seed 004 ch. 2)")
    top = ax.secondary_xaxis("top", functions=(lambda f: np.degrees(np.arccos(np.clip(math.cos(t.beta0) - f / t.R_b, -1, 1))),
                                               lambda bd: t.R_b * (math.cos(t.beta0) - np.cos(np.radians(bd)))))
    top.set_xlabel("balancer angle β, deg")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    return fig


def stress_plot(m: BalancerModel, s, sig, h_built, h_eq):
    from ...export import plots as _agg  # noqa: F401  (selects the Agg backend before pyplot)
    import matplotlib.pyplot as plt

    p = m.p
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7.5, 7.0), dpi=100, sharex=True)
    for name, v in sig.items():
        ax1.plot(s, v, lw=1.2, label=f"σ_vM, {name}")
    allow = p.yield_MPa / p.safety
    ax1.axhline(allow, color="r", ls=":", lw=0.9, label=f"allowable {allow:.0f} MPa = {p.yield_MPa:g}/{p.safety:g}")
    ax1.axhline(300.0, color="k", ls="--", lw=0.7, label="seed FE: ~300 MPa in the body")
    ax1.set_ylabel("von Mises stress, MPa")
    ax1.grid(True, lw=0.4, alpha=0.6)
    sf = np.min([p.yield_MPa / np.maximum(v, 1e-9) for v in sig.values()], axis=0)
    axr = ax1.twinx()
    axr.plot(s, sf, color="0.4", lw=0.8, ls="-.", label="least safety factor")
    axr.set_ylabel("safety factor on yield")
    axr.set_ylim(0, max(6.0, float(np.nanmax(np.minimum(sf, 20))) * 1.05))
    ax1.legend(fontsize=7, loc="upper right")
    ax1.set_title("Balancer arm on its built outline: stresses (beam model) and safety")
    ax2.plot(s, h_built, lw=1.4, label="built section depth (band about the axis)")
    ax2.plot(s, h_eq, lw=1.0, ls="--", label="equal-strength depth (largest load case)")
    ax2.axhline(p.h_ref_mm, color="0.5", lw=0.7, ls=":", label=f"reference constant arm {p.h_ref_mm:g} mm")
    ax2.set_xlabel("station along the arm s, mm (0: upper axle, R_б: wheel axle)")
    ax2.set_ylabel("depth h, mm")
    ax2.set_ylim(0, max(250.0, float(np.max(h_built[np.isfinite(h_built)])) * 1.05))
    ax2.grid(True, lw=0.4, alpha=0.6)
    ax2.legend(fontsize=7)
    fig.tight_layout()
    return fig


def side_view_plot(m: BalancerModel):
    """2D side view (world) of the arm outline and the wheel at β0, β_ст, β_m with the envelope lines."""
    from ...export.plots import new_figure

    p, t = m.p, m.tor
    fig, ax = new_figure(7.5, 6.5)
    poly = m.outline.profile.polylines(0.2)
    for b, col in ((t.beta0, "tab:blue"), (t.beta_st, "tab:green"), (t.beta_m, "tab:red")):
        th = b - math.pi / 2
        R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
        for k, pl in enumerate(poly):
            q = np.vstack([pl, pl[:1]]) @ R.T
            ax.plot(q[:, 0], q[:, 1], color=col, lw=0.9, label=f"β = {math.degrees(b):.2f}°" if k == 0 else None)
        c = R @ np.array([p.R_b_mm, 0.0])
        a = np.linspace(0, 2 * math.pi, 200)
        ax.plot(c[0] + m.wheel.r_tyre * np.cos(a), c[1] + m.wheel.r_tyre * np.sin(a), color=col, lw=0.6, ls="--")
    X = m.pitch
    ax.axhline(p.fender_height_mm, color="k", lw=0.8, ls=":", label="fender / sponson")
    ax.axhline(-p.hull_bottom_mm, color="k", lw=0.8, ls="-.", label="hull bottom (inboard of the side)")
    ax.plot([X, -X], [0.0, 0.0], "k+", ms=6, label=f"neighbouring upper axles (pitch {X:.0f} mm)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (forward), mm")
    ax.set_ylabel("y (up), mm")
    ax.set_title("Balancer and road wheel (dashed: tyre) over the travel")
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    return fig


def sweep_plot(m: BalancerModel, sw: dict):
    from ...export.plots import new_figure

    fig, ax = new_figure()
    bd = np.degrees(sw["beta"])
    for name, d in sw["pairs"].items():
        lab = {"hull": "hull envelope", "front": "front neighbour", "rear": "rear neighbour"}[name]
        ok = ~d["capped"]
        line, = ax.plot(bd[ok], d["gap_mm"][ok], lw=1.0, marker="o", ms=2.5, label=f"{lab} (exact)")
        if name != "hull":
            ax.plot(bd, d["axis_distance_mm"] - 2.0 * m.wheel.r_tyre, lw=0.8, ls="--", color=line.get_color(),
                    label=f"{lab}: wheel-to-wheel gap, axis distance − 2R (upper bound)")
    ax.axhline(sw["window_mm"], color="0.6", lw=0.6, ls="-.",
               label=f"search window {sw['window_mm']:g} mm (steps not drawn lie above it)")
    ax.axhline(m.p.min_clearance_mm, color="r", ls=":", lw=0.9, label=f"least accepted {m.p.min_clearance_mm:g} mm")
    ax.axhline(sw["own"][1], color="0.3", ls="--", lw=0.8, label=f"own wheel to balancer {sw['own'][1]:.2f} mm")
    ax.set_xlabel("balancer angle β, deg")
    ax.set_ylabel("least gap (manifold3d min_gap), mm")
    ax.set_yscale("log")
    ax.set_title("Travel sweep β0 … β_m: clearance of balancer + road wheel")
    ax.legend(fontsize=6.5)
    fig.tight_layout()
    return fig
