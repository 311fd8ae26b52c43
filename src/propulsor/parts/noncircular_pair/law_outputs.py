"""Outputs of a non-circular pair whose law has no hub (elliptical, Fourier, table): the law given beside
the ratio the teeth deliver, the output speed ratio, the notes and the derived values of the report."""

from __future__ import annotations

import math

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from .design import Design, PairDesign

__all__ = ["law_figure", "speed_ratio_plot", "law_notes", "law_derived"]


def law_figure(w, d: Design, pr, fig, ax):
    """The law the part file gives (table rows where it is a table) beside the ratio the teeth deliver,
    over one period of the law."""
    law = d.law
    P = law.period
    ph = np.linspace(0.0, P, 2001)
    ax.plot(np.degrees(ph), law.U(ph), "k-", lw=0.9, label=f"{law.kind} law U(phi) (the part file's)")
    if law.kind == "table":
        x = np.radians(np.asarray(law.driven_deg) - law.driven_deg[0])
        th = np.radians(np.asarray(law.driver_deg) - law.driver_deg[0])
        mid = 0.5 * (x[1:] + x[:-1])
        ax.plot(np.degrees(mid), np.diff(th) / np.diff(x), "g+", ms=4, label="the table's rows: secant slopes")
    x, u = pr.ratio_actual()
    ax.plot(np.degrees(np.mod(x, P)), u, ".", ms=2.5, label="generated teeth: d theta / d phi from the outlines")
    ax.set_xlabel(f"driven angle phi within one period ({math.degrees(P):g} deg), deg")
    ax.set_ylabel("gear ratio U = d theta / d phi")
    ax.set_title(f"The {law.kind} law vs the ratio the teeth deliver")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("figure2_ratio", fig)


def speed_ratio_plot(w, d: Design, pr=None):
    """A law without a hub: the output speed ratio omega_driven / omega_driver = 1/U over one driven turn, the law's
    beside the one the teeth deliver (the proof's running positions, ``pr``)."""
    from ...export.plots import new_figure

    fig, ax = new_figure()
    ph = np.linspace(0.0, 2 * math.pi, 4001)
    ax.plot(np.degrees(ph), 1.0 / d.run_law.U(ph), "b-", lw=1.0, label=f"{d.law.kind} law (the part file's)")
    if pr is not None:
        x, u = pr.ratio_actual()
        ok = np.isfinite(u) & (u > 0)
        ax.plot(np.degrees(np.mod(x[ok], 2 * math.pi)), 1.0 / u[ok], "C1.", ms=3,
                label="generated teeth: d phi / d theta from the outlines")
    ax.set_xlabel("driven angle phi, deg")
    ax.set_ylabel("output speed ratio omega_driven / omega_driver = 1/U")
    ax.set_title("Output speed over one driven turn (driven over driver speed)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("speed_ratio", fig)


_LAW_TEXT = {
    "elliptical": "the driver an ellipse about a focus, r1 = p / (1 + e cos theta), e = {e:g}, the driven wheel "
                  "r2 = L - r1 with {lobes}; closure integral r1 / (L - r1) dtheta = 2 pi / k gives p / L = {q:.6f} "
                  "(Litvin & Fuentes-Aznar, Noncircular Gears, 2009, ch. 3-4)",
    "fourier": "phi(theta) = theta / k + sum_j (c_j cos j theta + s_j sin j theta), k = {k}, {J} harmonic(s)",
    "table": "the part file's table of {rows} rows over one period of {P:g} deg, a periodic quintic spline of "
             "theta(phi) - n phi through them",
    "pitch_curve": "the driver's pitch curve of the part file ({rows} rows, a periodic quintic spline r(a)) with "
                   "its conjugate driven wheel of {lobes}: closure integral r / (L0 - r) dtheta = 2 pi / k at "
                   "L0 = {L0:.6f} mm as given, the pair scaled by L / L0 = {S:.6f} so that its perimeter holds the "
                   "teeth",
}


def lobes_text(law, samples: int = 4096) -> str:
    """The driven wheel's lobes counted on its pitch curve: the maxima of its radius r2 = L U / (1 + U), i.e. of U,
    over one driven turn (a 2-fold oval driver with k = 1 makes a 2-lobe driven wheel); "a round wheel" for none."""
    U = np.asarray(law.U(np.linspace(0.0, 2 * math.pi, samples, endpoint=False)), float)
    if float(np.ptp(U)) <= 1e-9 * float(np.mean(U)):
        return "a round wheel (no lobes)"
    lobes = int(np.count_nonzero((U > np.roll(U, 1)) & (U >= np.roll(U, -1))))
    return f"{lobes} lobe" + ("" if lobes == 1 else "s")


def law_notes(w, d, pr, p, mount, s) -> None:
    """Notes of a law without a hub (elliptical, Fourier, table)."""
    law = d.law
    g = d.smoothing.generability
    text = _LAW_TEXT[law.kind].format(
        e=getattr(law, "e", 0.0), k=law.n, lobes=lobes_text(law), q=getattr(law, "q", 0.0), J=len(getattr(law, "_j", ())),
        rows=getattr(law, "rows", len(getattr(law, "driven_deg", ()))), P=math.degrees(law.period),
        L0=getattr(law, "L0", 0.0), S=d.L / getattr(law, "L0", d.L))
    w.add_note(
        f"Law ({law.kind}): {text}.  U = d theta / d phi from {float(np.min(law.U(np.linspace(0, law.period, 4001)))):.6f} "
        f"to {float(np.max(law.U(np.linspace(0, law.period, 4001)))):.6f}; {law.periods} period(s) per driven turn, "
        f"n = {law.n} driver turn(s).  Closure by true arc length: L = {d.L:.6f} mm, m = {d.m:.6f} mm, z {d.z}/{d.z_H} "
        f"(closure error {d.closure_error:.2g} rad).  No corners: no blend.  Generability: driver convex rho_min "
        f"{g.driver.rho_convex_min:.3f} mm >= rack undercut limit {g.driver.rho_limit:.3f} mm (x = {p.driver_shift:+g}), "
        f"driven {g.driven.rho_convex_min:.3f} mm >= {g.driven.rho_limit:.3f} mm (x = {-p.driver_shift:+g})"
        + (f", driven concave |rho|_min {g.driven.rho_concave_min:.3f} mm > shaper {g.driven.r0:.3f} mm"
           if g.driven.concave else "")
        + (f", driver concave |rho|_min {g.driver.rho_concave_min:.3f} mm > {g.driver.r0:.3f} mm" if g.driver.concave else "")
        + ".")
    shaper = ("no shaper: both pitch curves are convex" if not (g.driver.concave or g.driven.concave) else
              f"the shaper z0 = {p.shaper_teeth if d.shaper is None else d.shaper.z0}"
              + ("" if d.shaper is None else f" (catalogue d0 = {d.shaper.d0_mm:g} mm, {d.shaper.standard})"))
    w.add_note(
        f"Generated teeth: ISO 53 rack profile {p.rack_profile} (alpha = {p.pressure_angle_deg:g} deg) rolling on each "
        f"pitch curve on one shared arc-length frame, driver shift {p.driver_shift:+g}, driven {-p.driver_shift:+g}; "
        f"{shaper}; {d.driver.shortened_teeth + d.driven.shortened_teeth} tips shortened to a land of "
        f"{p.tip_land_min_module:g} m; undercut teeth: {d.driver.undercut_teeth + d.driven.undercut_teeth}; backlash "
        f"j_n = {p.backlash_mm:g} mm as tooth thinning j_n/(2 cos alpha) per gear.")
    w.add_note(
        f"Proof on the finished outlines ({s['steps']} phases over the whole driven turn, {pr.measured_text()}, "
        f"gears at {mount:.4f} mm): "
        f"overlap at the law's positions max {s['overlap_law_max_mm2']:.4g} mm^2; jams {s['jams']}; transmission "
        f"error {s['te_min_rad']:.4e} .. {s['te_max_rad']:.4e} rad (peak-to-peak {s['te_pp_rad']:.3e} rad); backlash "
        f"{s['backlash_min_mm']:.4f} .. {s['backlash_max_mm']:.4f} mm; tooth pairs in contact min "
        f"{s['contact_pairs_min']}, mean {s['contact_pairs_mean']:.3f}.  plots/figure2_ratio.png: the law given beside "
        "the ratio the teeth deliver; plots/speed_ratio.png: the output speed over the turn, the law's beside the teeth's.")


def law_design_values(dd: PairDesign) -> dict:
    """The derived values of a law without a hub (elliptical, Fourier, table, pitch curve) that come from its
    design alone: the build's, and a design-depth study's."""
    p, d = dd.p, dd.d
    law = d.law
    g = d.smoothing.generability
    U = law.U(np.linspace(0.0, law.period, 4001))
    out = {
        "center_distance_mm": d.L, "mounting_distance_mm": dd.mount, "module_mm": d.m, "driver_teeth": d.z,
        "driven_teeth": d.z_H, "driver_turns": law.n, "method": d.method, "law": law.kind, "law_periods": law.periods,
        "ratio_min": float(np.min(U)), "ratio_max": float(np.max(U)), "closure_error_rad": d.closure_error,
        "driver_rho_min_mm": g.driver.rho_convex_min, "driver_rho_limit_mm": g.driver.rho_limit,
        "driven_rho_min_mm": g.driven.rho_convex_min, "driven_rho_limit_mm": g.driven.rho_limit,
        "driven_concave_rho_min_mm": g.driven.rho_concave_min, "shaper_r0_mm": g.driven.r0,
        "driver_shift": p.driver_shift, "driven_shift": 0.0 - p.driver_shift,
        "tip_shortened_teeth": d.driver.shortened_teeth + d.driven.shortened_teeth,
        "shaper_cut_teeth": d.driver.shaper_teeth + d.driven.shaper_teeth,
        "undercut_teeth": d.driver.undercut_teeth + d.driven.undercut_teeth,
    }
    if law.kind == "elliptical":
        out.update({"eccentricity": law.e, "focal_parameter_mm": law.q * d.L})
    if law.kind == "pitch_curve":
        out.update({"pitch_curve_center_distance_mm": law.L0, "pitch_curve_scale": d.L / law.L0})
    if d.shaper is not None:
        out.update({"rack_profile": p.rack_profile, "shaper_d0_mm": d.shaper.d0_mm, "shaper_z0": d.shaper.z0,
                    "shaper_x0": d.shaper.x0, "shaper_standard": d.shaper.standard})
    return out


def law_derived(dd: PairDesign, w, pr, s) -> None:
    """Derived values of a law without a hub (elliptical, Fourier, table): the design's and the proof's."""
    w.derived.update(law_design_values(dd))
    w.derived.update({
        "proof_phases": s["steps"], "overlap_law_max_mm2": s["overlap_law_max_mm2"],
        "overlap_law_phases": s["overlap_law_steps"], "jam_phases": s["jams"],
        "te_min_rad": s["te_min_rad"], "te_max_rad": s["te_max_rad"], "te_pp_rad": s["te_pp_rad"],
        "backlash_min_mm": s["backlash_min_mm"], "backlash_max_mm": s["backlash_max_mm"],
        "contact_pairs_min": s["contact_pairs_min"], "contact_ratio_mean": s["contact_pairs_mean"],
    })
