"""The non-circular pair's outputs: solids, assembly, DXF, the papers' tables, plots, checks, notes;
and its build.

Frames (the contract other tools read): the driven wheel's axis at the origin, the driver's at
(L, 0); ``driven.dxf`` / ``driver.dxf`` hold each gear about its own axis in its phase at
phi = theta = 0 of the assembly (the contact of law angle 0 on the line of centres).
"""

from __future__ import annotations

import math

import numpy as np

from ...gears.noncircular import PitchCurves
from ...gears.sectors import (
    PINION_POINT_COLUMNS, RADII_COLUMNS, SECTOR_COLUMNS, WHEEL_POINT_COLUMNS, pinion_tooth_points,
    sector_hub_speed, sector_radii, structured_rows, wheel_space_points,
)
from ...laws.law import is_walking
from .law_outputs import law_derived, law_figure, law_notes, speed_ratio_plot
from ...laws.walking import LEG_PERIOD
from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import pair_animation
from .as_built_outputs import as_built_values
from .bores import sized_derived, sized_note, with_bores
from .design import Design, PairDesign, bores, mounting, pair_design, sector_design_table
from .params import NoncircularPairParams
from .proofs import checks_generated, checks_sectors, other_method, proofs

__all__ = ["build", "start_solids", "write_outputs", "solids", "assembly_and_dxf", "tables", "plots",
           "checks_and_derived", "notes"]


def start_solids(p: NoncircularPairParams, w, profiles):
    """Extrude both gears (face width) and hand them to the writer (STEP/STL/3MF and the shared
    checks, in its workers).  Returns (driver, driven) solids for the assembly."""
    load_kernel = getattr(w, "load_kernel", None)
    if load_kernel is not None:  # said, beside the jobs started before this step (the as-built contact)
        load_kernel()
    from ...solids.build import extrude_profile

    w.progress("solids")
    prof_drv, prof_dvn = profiles
    # the driven wheel (the larger work) goes to the workers before the driver is extruded
    s_dvn = extrude_profile(prof_dvn, p.face_width_mm)
    w.add_solid("driven", s_dvn, expected_genus=1 if p.driven_bore_mm > 0 else 0)
    s_drv = extrude_profile(prof_drv, p.face_width_mm)
    w.add_solid("driver", s_drv, expected_genus=1 if p.driver_bore_mm > 0 else 0)
    return s_drv, s_dvn


def sector_tables(w, p: NoncircularPairParams, note_if_missing: bool = True):
    """Table 1 (both seeds) and Tables 2-4 (seed 002) of the papers' method for these parameters."""
    if p.driven_teeth % 4:
        w.add_note("Sector tables not written: the papers' method needs driven_teeth = 4 x sectors per leg.")
        return None
    table, L, m = sector_design_table(p)
    w.add_note(
        f"The papers' tables for these parameters (seed 000 Table 1 -> tables/sectors.csv, seed 002 Tables 2-4 -> "
        f"radii.csv, driver_teeth.csv, driven_spaces.csv): i = {table.i} sectors per leg, L = {L:.6f} mm "
        f"({'given' if p.center_distance_mm > 0 else 'from the module: sector arc = pi m'}; sector arc "
        f"{table.arc:.4f} mm), m = {m:g} mm, j_n = {p.backlash_mm:g} mm; angles in rad and deg as printed.")
    w.add_table("sectors", list(SECTOR_COLUMNS), [[r[c] for c in SECTOR_COLUMNS] for r in table.rows()])
    rad = sector_radii(table, m)
    w.add_table("radii", list(RADII_COLUMNS), [[r[c] for c in RADII_COLUMNS] for r in rad.rows()])
    for name, arr, cols in (("driver_teeth", pinion_tooth_points(table, m, p.backlash_mm), PINION_POINT_COLUMNS),
                            ("driven_spaces", wheel_space_points(table, m, p.backlash_mm), WHEEL_POINT_COLUMNS)):
        w.add_table(name, list(cols), [[r[c] for c in cols] for r in structured_rows(arr)])
    return table


def pitch_polyline(d: Design, role: str, n: int = 1441) -> np.ndarray:
    from ...gears.noncircular_teeth import BodyPitchCurve

    span = 2 * math.pi if role == "driven" else 2 * math.pi / d.law.n
    return BodyPitchCurve(d.pc, role).point(np.linspace(0.0, span, n, endpoint=False))


def figure2(w, d: Design, pr, other, pr_other):
    from ...export.plots import new_figure

    fig, ax = new_figure(8.0, 5.0)
    if not is_walking(d.law):
        return law_figure(w, d, pr, fig, ax)
    ph = np.linspace(0.0, LEG_PERIOD, 2001)
    ax.plot(np.degrees(ph), d.law.U(ph), "k--", lw=0.9, label="law U(phi), seed 000 eq. 15 (exact)")
    if d.method == "generated":
        ax.plot(np.degrees(ph), d.run_law.U(ph), "k-", lw=1.0,
                label=f"law with C2 blend, {d.smoothing_deg:.2f} deg")
    for dd, pp in ((d, pr), (other, pr_other)):
        if dd is None or pp is None:
            continue
        x, u = pp.ratio_actual()
        x = np.mod(x, LEG_PERIOD)
        ax.plot(np.degrees(x), u, ".", ms=2.5, label=f"{dd.method} teeth: d theta / d phi from the outlines")
    ax.set_xlabel("driven angle phi within one leg, deg")
    ax.set_ylabel("gear ratio U = d theta / d phi")
    ax.set_title("The papers' Figure 2 (seed 000), from geometry: the law vs the ratio the teeth deliver")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("figure2_ratio", fig)


def ratio_and_layout_plots(w, d: Design, pr, profiles, mount: float, table=None):
    from ...export.plots import new_figure

    fig, ax = new_figure()
    ok = np.isfinite(pr.te_drive)
    ax.plot(np.degrees(pr.phi), 1e3 * (pr.phi_run - pr.phi), ".-", ms=2, lw=0.6,
            label="running position (loaded flank; least overlap where jammed)")
    ax.set_xlabel("driven angle phi, deg")
    ax.set_ylabel("transmission error (actual - law), mrad of the driven wheel")
    ax2 = ax.twinx()
    ax2.plot(np.degrees(pr.phi[ok]), pr.backlash_mm[ok], "r.", ms=2, label="backlash")
    ax2.set_ylabel("backlash on the driven pitch curve, mm", color="r")
    ax.set_title(f"{d.method} teeth: transmission error and backlash over the whole cycle")
    fig.tight_layout()
    w.add_plot("transmission_error", fig)

    if not is_walking(d.law):
        speed_ratio_plot(w, d, pr)
        _pair_plot(w, d, profiles, mount)
        return
    fig, ax = new_figure()
    ph = np.linspace(-math.pi / 4, math.pi / 4, 4001)
    mean = d.law.hub_speed_ratio
    ax.plot(np.degrees(ph), d.law.hub_speed(ph) / mean, "k--", lw=0.9, label="exact law (constant)")
    if d.method == "generated":
        ax.plot(np.degrees(ph), d.run_law.hub_speed(ph) / mean, "b-", lw=1.0,
                label=f"C2 blend {d.smoothing_deg:.2f} deg: ripple {100 * d.ripple.ripple:.2f} %")
    if table is not None or d.method == "sectors":
        from ...gears.sectors import sector_ratio

        tab = table
        if tab is not None:
            ax.plot(np.degrees(ph), d.law.dX01_dphi(ph) / sector_ratio(tab, ph) / mean, "g-", lw=0.8,
                    label=f"sector method (ideal teeth): ripple {100 * sector_hub_speed(tab).ripple:.2f} %")
    ax.set_xlabel("driven angle phi within one leg, deg")
    ax.set_ylabel("hub speed v/omega relative to its mean")
    ax.set_title("Price of the tooth method: hub speed over one leg (seed 000 eq. 2-3)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("hub_speed", fig)
    _pair_plot(w, d, profiles, mount)


def _pair_plot(w, d: Design, profiles, mount: float):
    from ...export.plots import new_figure

    fig, ax = new_figure(6.5, 6.5)
    for prof, off in ((profiles[1], (0.0, 0.0)), (profiles[0], (mount, 0.0))):
        for q in prof.polylines(0.01):
            q = np.vstack([q, q[:1]]) + np.asarray(off)
            ax.plot(q[:, 0], q[:, 1], lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.set_title(f"pair at phi = theta = 0 ({d.method} teeth), centre distance {mount:.4f} mm")
    fig.tight_layout()
    w.add_plot("pair", fig)


def _pct(x):
    return f"{100 * x:.2f} %"


def write_notes(w, d, pr, other, pr_other, other_note, p, mount):
    s = pr.summary()
    law = d.law
    if not is_walking(law):
        return law_notes(w, d, pr, p, mount, s)
    w.add_note(
        f"Law (seed 000 eqs. 1-15, wrapped to be periodic per leg): A = a - b + c = {law.A:g} mm, "
        f"u = n pi A / (A pi + 6 b) = {law.u:.6f}, n = {law.n}; constant hub speed v/omega = A/u = "
        f"{law.hub_speed_ratio:.4f} mm/rad with the exact law.  Closure by true arc length (the pitch curves' lengths, not chords): "
        f"L = {d.L:.6f} mm, m = {d.m:.6f} mm, z {d.z}/{d.z_H}; the driver makes exactly n turns per driven turn "
        f"(closure error {d.closure_error:.2g} rad).")
    if d.method == "generated" and d.search is not None:
        _search_notes(w, d, p)
    if d.method == "generated":
        sm = d.smoothing
        g = sm.generability
        r = d.ripple
    if d.method == "generated" and d.search is None:
        w.add_note(
            f"Price of smoothing: the exact law has corners at leg hand-over (phi = 45 deg + k 90 deg); "
            f"it is replaced there by an even degree-6 polynomial in the blend window of half-width "
            f"{d.smoothing_deg:.4f} deg ({sm.delta:.6f} rad), matching U, U', U'' at the window ends (C2) and the "
            f"window integral (closure exact).  It was chosen as the "
            f"{'smallest blend' if p.smoothing_deg == 0 else 'given blend'} keeping both pitch curves generable: "
            f"driver convex rho_min {g.driver.rho_convex_min:.3f} mm >= rack undercut limit {g.driver.rho_limit:.3f} mm "
            f"(shift x = {p.driver_shift:+g}), driven rho_min {g.driven.rho_convex_min:.3f} mm >= {g.driven.rho_limit:.3f} mm "
            f"(x = {-p.driver_shift:+g})"
            + (f", driven concave |rho|_min {g.driven.rho_concave_min:.3f} mm > shaper pitch radius {g.driven.r0:.3f} mm"
               if g.driven.concave else "")
            + (f", driver concave |rho|_min {g.driver.rho_concave_min:.3f} mm > {g.driver.r0:.3f} mm" if g.driver.concave else "")
            + f".  The hub speed v/omega = (dX01/dphi)/U is constant outside the windows; inside them it ripples by "
              f"(max - min)/mean = {_pct(r.ripple)}, the minimum at phi = {math.degrees(r.phi_min):.3f} deg (hand-over) "
              f"and the maximum at phi = {math.degrees(r.phi_max):.3f} deg (inside the window).")
    if d.method == "generated":
        if d.shaper is None:
            shaper = f"a shaper z0 = {p.shaper_teeth} (x0 = -x of the gear)"
            rack = f"ISO 53 rack (alpha = {p.pressure_angle_deg:g} deg, h_a* = 1, c* = 0.25, rho_f* = 0.38)"
        else:
            e = d.shaper
            shaper = (f"the catalogue shaper d0 = {e.d0_mm:g} mm ({e.standard}: m = {e.m:g}, z0 = {e.z0}, own x0 = "
                      f"{e.x0:+g}, h_a0* = {e.h_a0_star:g}, rho_a0* = {e.rho_a0_star:g}"
                      f"{'; x0 and rho_a0* are ours, see gears/data/cutters.toml' if e.source == 'ours' else ''}), "
                      f"re-phased per flank so that it cuts the rack's flank (gears/envelope.py, ShaperOnRackCentrode); "
                      f"root lifted where its fillet stops short of the root equidistant: at most "
                      f"{_root_bridge_max(d):.3f} mm")
            from ...gears.catalogue import rack_profile

            rk = rack_profile(p.rack_profile)
            rack = (f"ISO 53:1998 rack profile {p.rack_profile} (alpha = {p.pressure_angle_deg:g} deg, h_a* = "
                    f"{rk.h_a_star:g}, c* = {rk.c_star:g}, rho_f* = {rk.rho_f_star:g})")
        w.add_note(
            f"Generated teeth: {rack} "
            f"rolling on each pitch curve on one shared arc-length frame; driver shift {p.driver_shift:+g}, driven "
            f"{-p.driver_shift:+g} (one imaginary rack: the pair stays conjugate at the pitch-curve centre distance); "
            f"{d.driven.shaper_teeth + d.driver.shaper_teeth} teeth next to concave stretches cut by "
            f"{shaper}; {d.driver.shortened_teeth + d.driven.shortened_teeth} tips "
            f"shortened to a land of {p.tip_land_min_module:g} m; undercut teeth: "
            f"{d.driver.undercut_teeth + d.driven.undercut_teeth}; backlash j_n = {p.backlash_mm:g} mm as tooth "
            f"thinning j_n/(2 cos alpha) per gear.")
    else:
        w.add_note(
            f"Sector teeth (the papers' method): {d.table.i} sectors per leg of equal arc "
            f"{d.table.arc:.4f} mm (pi m = {math.pi * d.m:.4f} mm), base radius r - m, tip r + m, root r - 1.25 m, "
            f"backlash as the angular correction j_n/(4 r_b), j_n = {p.backlash_mm:g} mm (seed 002 Tables 2-4).  "
            "Transitions the papers leave open (ours): below the base circle the flank is radial down to the root; "
            "a driven tooth between spaces i and i+1 has the tip radius of sector i+1 (the 6th point of Table 4; a "
            "radial flank where that tip lies below the base circle of sector i); a driver space straddling two "
            "sectors has a root whose radius passes between the two root radii by the quintic smoothstep in angle.  "
            f"Even with ideal teeth the staircase ratio leaves a hub speed ripple of {_pct(d.ripple.ripple)}.")
    w.add_note(
        f"Proof on the finished outlines ({d.method}, {s['steps']} phases over the whole driven turn, "
        f"{pr.measured_text()}, "
        f"{p.proof_phases_per_tooth} per driven tooth, manifold3d booleans, gears at the installed centre "
        f"distance {mount:.4f} mm): overlap at the law's positions max "
        f"{s['overlap_law_max_mm2']:.4g} mm^2 ({s['overlap_law_steps']} phases); phases without a free position "
        f"(jam) {s['jams']}; transmission error of the loaded flank {s['te_min_rad']:.4e} .. {s['te_max_rad']:.4e} rad "
        f"(peak-to-peak {s['te_pp_rad']:.3e} rad); backlash {s['backlash_min_mm']:.4f} .. {s['backlash_max_mm']:.4f} mm "
        f"on the driven pitch curve; tooth pairs in contact min {s['contact_pairs_min']}, mean "
        f"{s['contact_pairs_mean']:.3f}.")
    if pr_other is not None:
        so = pr_other.summary()
        w.add_note(
            f"Comparison with the {other.method} method for the same law, module and teeth (one leg, "
            f"{so['steps']} phases; L = {other.L:.4f} mm): hub speed ripple {_pct(other.ripple.ripple)} vs "
            f"{_pct(d.ripple.ripple)}; overlap at the law's positions max {so['overlap_law_max_mm2']:.4g} mm^2 "
            f"({so['overlap_law_steps']} phases); jams {so['jams']} (least overlap up to "
            f"{float(np.max(pr_other.least_overlap)):.4g} mm^2); transmission error peak-to-peak "
            f"{so['te_pp_rad']:.3e} rad; backlash {so['backlash_min_mm']:.4f} .. {so['backlash_max_mm']:.4f} mm.  "
            "plots/figure2_ratio.png shows both against the law.")
    elif other_note:
        w.add_note(other_note)



def _root_bridge_max(d) -> float:
    """Largest lift (mm) of the root where a re-phased shaper's fillet stops short of the root equidistant."""
    return float(max([0.0] + [g for gear in (d.driver, d.driven) for g in getattr(gear, "root_gaps", ())]))


def _search_notes(w, d, p) -> None:
    """The law search: what was searched, what binds, the candidates tried, the papers' method beside it."""
    res = d.search
    best = res.points[0]
    chosen = d.search_tries[-1][0]
    sl = d.run_law
    r = d.ripple
    refused = [f"{100 * t.ripple:.2f} % (d0 {t.d0_mm:g} mm, delta {math.degrees(t.delta):.2f} deg): {why}"
               for t, why in d.search_tries if why]
    table = sector_design_table(p)[0] if p.driven_teeth % 4 == 0 else None
    papers = f"; the papers' sector method (ideal teeth) {_pct(sector_hub_speed(table).ripple)}" if table is not None else ""
    w.add_note(
        f"Law search (gears/law_search.py): the blend at hand-over is an even degree-6 polynomial in the "
        f"window of half-width delta with a free hand-over value U_s(phi_h) = u_h (the depth of the hub-speed dip), "
        f"C2 at the window ends; closure is kept exact by scaling U by (1 - eps) outside the windows instead of a "
        f"bump beside the dip.  Searched: delta on {len(set(q.delta for q in res.points))} generable half-widths of "
        f"the scan, at each the smallest generable u_h (scan and bisection), for every catalogue shaper at m = "
        f"{d.m:g} mm, with the centre distance within {res.L_band:g} mm of L_exact = {res.L_ref:.3f} mm (closure of the "
        f"exact law); {res.evaluations} laws evaluated, {len(res.points)} generable points (tables/law_search.csv, "
        f"plots/law_search_front.png: the Pareto fronts ripple vs centre distance and ripple vs curvature margin).  "
        f"Least screened ripple {_pct(best.ripple)} (shaper d0 {best.d0_mm:g} mm); "
        + (f"refused by the tooth generator: {'; '.join(refused)}; " if refused else "")
        + f"built: {_pct(r.ripple)} with delta = {math.degrees(chosen.delta):.3f} deg, u_h = {chosen.u_h_rel:.6f} u, "
          f"eps = {sl.eps:.3e}, L = {d.L:.4f} mm, shaper d0 {chosen.d0_mm:g} mm (z0 {chosen.z0}); binding: "
          f"{chosen.binding} (margin {chosen.margin_mm:.4f} mm); hub speed minimum at phi = "
          f"{math.degrees(r.phi_min):.3f} deg, maximum at {math.degrees(r.phi_max):.3f} deg{papers}.")


def law_search_outputs(w, d) -> None:
    """tables/law_search.csv and plots/law_search_front.png (law_search = true)."""
    res = d.search
    tried = {(t.d0_mm, t.delta, t.u_h_rel): ("built" if not why else "refused") for t, why in d.search_tries}
    cols = ["rank", "shaper_d0_mm", "z0", "delta_deg", "u_h_over_u", "center_distance_mm", "speed_ripple",
            "curvature_margin_mm", "binding", "front_ripple_vs_L", "front_ripple_vs_margin", "teeth"]
    w.add_table("law_search", cols, [[k + 1, q.d0_mm, q.z0, math.degrees(q.delta), q.u_h_rel, q.L, q.ripple,
                                      q.margin_mm, q.binding, q.front_L, q.front_margin,
                                      tried.get((q.d0_mm, q.delta, q.u_h_rel), "")]
                                     for k, q in enumerate(res.points)])
    from ...export.plots import new_figure

    fig, ax0 = new_figure(9.0, 4.2)
    fig.delaxes(ax0)
    a1, a2 = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for ax in (a1, a2):
        ax.grid(True, lw=0.4, alpha=0.6)
    for ax, key, front, label in ((a1, "L", "front_L", "centre distance L, mm"),
                                  (a2, "margin_mm", "front_margin", "least curvature margin, mm")):
        for d0 in sorted({q.d0_mm for q in res.points}):
            qs = [q for q in res.points if q.d0_mm == d0]
            ax.plot([getattr(q, key) for q in qs], [100 * q.ripple for q in qs], "o", ms=3, label=f"shaper d0 {d0:g}")
        fr = sorted((q for q in res.points if getattr(q, front)), key=lambda q: getattr(q, key))
        ax.plot([getattr(q, key) for q in fr], [100 * q.ripple for q in fr], "k-", lw=0.8, label="Pareto front")
        for q, why in d.search_tries:
            ax.plot(getattr(q, key), 100 * q.ripple, "rx" if why else "g*", ms=9 if not why else 7)
        ax.set_xlabel(label)
        ax.set_ylabel("hub speed ripple, %")
    a1.legend(fontsize=7)
    a1.set_title("law search: built (star), refused by the generator (x)", fontsize=9)
    fig.tight_layout()
    w.add_plot("law_search_front", fig)


def solids(dd: PairDesign, w, built: dict) -> None:
    """Both gears to the writer: their files and checks run in workers beside the rest of the build."""
    built["solids"] = start_solids(dd.p, w, dd.profiles)


def assembly_and_dxf(dd: PairDesign, w, built: dict) -> None:
    """The pair's assembly STEP and a DXF of each gear (axis at the origin, phase phi = theta = 0)."""
    d = dd.d
    s_drv, s_dvn = built["solids"]
    prof_drv, prof_dvn = dd.profiles
    w.add_assembly("pair", [("driven", s_dvn, (0.0, 0.0, 0.0), 0.0),
                            ("driver", s_drv, (dd.mount, 0.0, 0.0), 0.0)])

    # ---- DXF (gear axis at the origin, phase phi = theta = 0 of the assembly)
    for role, prof in (("driver", prof_drv), ("driven", prof_dvn)):
        ref = [("polyline", {"points": pitch_polyline(d, role), "closed": True}),
               ("point", {"p": (0.0, 0.0)})]
        w.add_dxf(role, [prof], ref, beside=True)  # not read back by the build


def tables(dd: PairDesign, w, built: dict) -> None:
    """The papers' tables for these parameters, the transmission table, pitch curves, teeth."""
    p, d = dd.p, dd.d
    pr = built["proof"]
    table = sector_tables(w, p) if p.law == "walking" else None  # the papers' tables: the walking law's
    built["table"] = d.table if d.table is not None else table  # the sector method's table, for the plots
    th_act = pr.theta_actual()
    jam = ~np.isfinite(pr.phi_drive)
    # theta_actual: the driver angle at which the outlines put the driven wheel at phi (loaded flanks
    # touching; at a jammed phase the position of least overlap); te_run: driven running angle - law
    w.add_table("transmission", ["phi_rad", "theta_law_rad", "theta_actual_rad", "te_run_rad", "te_drive_rad",
                                 "backlash_mm", "pairs_drive", "overlap_law_mm2", "least_overlap_mm2", "jam"],
                [[float(a), float(b), float(c), float(r) - float(a), float(e) if math.isfinite(e) else None,
                  float(f) if math.isfinite(f) else None, int(g), float(h), float(i), bool(j)]
                 for a, b, c, r, e, f, g, h, i, j in zip(pr.phi, pr.theta_law, th_act, pr.phi_run, pr.te_drive,
                                                          pr.backlash_mm, pr.pairs_drive, pr.overlap_law,
                                                          pr.least_overlap, jam)])
    pcr = PitchCurves(d.run_law, d.L)
    if not is_walking(d.law):
        ph = np.linspace(0.0, 2 * math.pi, 1441)
        w.add_table("pitch_curves", ["phi_rad", "r_H_mm", "theta_rad", "r_mm", "ratio_U"],
                    [[float(a), float(b), float(c), float(e), float(f)] for a, b, c, e, f in
                     zip(ph, pcr.r_H(ph), d.run_law.theta(ph), pcr.r(ph), d.run_law.U(ph))])
    ph = np.linspace(-math.pi / 4, math.pi / 4, 721)
    if is_walking(d.law):
        w.add_table("pitch_curves", ["phi_rad", "r_H_mm", "theta_rad", "r_mm", "ratio_U", "hub_speed_mm_per_rad"],
                    [[float(a), float(b), float(c), float(e), float(f), float(g)] for a, b, c, e, f, g in
                     zip(ph, pcr.r_H(ph), d.run_law.theta(ph), pcr.r(ph), d.run_law.U(ph), d.run_law.hub_speed(ph))])
    if d.method == "generated" and d.search is not None:
        law_search_outputs(w, d)
    if d.method == "generated":
        rows = []
        for gear in (d.driver, d.driven):
            for k, t in enumerate(gear.teeth):
                rows.append([gear.role, k, t.phi_centre, t.right, t.left, t.undercut, t.tip_height_mm,
                             t.tip_thickness_mm, t.shortened])
        w.add_table("teeth", ["gear", "tooth", "phi_centre_rad", "cutter_right", "cutter_left", "undercut",
                              "tip_height_mm", "tip_land_mm", "tip_shortened"], rows)


def plots(dd: PairDesign, w, built: dict) -> None:
    """The papers' Figure 2 from geometry, transmission error, hub speed, the pair."""
    d = dd.d
    pr = built["proof"]
    other, pr_other, _ = built["other"]
    figure2(w, d, pr, other, pr_other)
    ratio_and_layout_plots(w, d, pr, dd.profiles, dd.mount, built["table"])


def checks_and_derived(dd: PairDesign, w, built: dict) -> None:
    """Closure, generability, teeth and proof checks; every derived value of the report (the bores sized from
    the gear last, where the part file gives none)."""
    _checks_and_derived(dd, w, built)
    w.derived.update(sized_derived(dd.bores))


def _checks_and_derived(dd: PairDesign, w, built: dict) -> None:
    p, d = dd.p, dd.d
    pr = built["proof"]
    other, pr_other, _ = built["other"]
    w.add_checks(checks_generated(d, pr, p) if d.method == "generated" else checks_sectors(d, pr))
    s = pr.summary()
    if not is_walking(d.law):
        law_derived(dd, w, pr, s)
        return as_built_values(w, dd, built)
    w.derived.update({
        "center_distance_mm": d.L, "mounting_distance_mm": dd.mount, "module_mm": d.m, "driver_teeth": d.z, "driven_teeth": d.z_H,
        "driver_turns": d.law.n, "method": d.method, "smoothing_deg": d.smoothing_deg,
        "speed_ripple": d.ripple.ripple,
        "speed_ripple_phi_min_deg": math.degrees(d.ripple.phi_min),
        "speed_ripple_phi_max_deg": math.degrees(d.ripple.phi_max),
        "hub_height_mm": d.law.A, "u": d.law.u, "hub_speed_mean_mm_per_rad": d.law.hub_speed_ratio,
        "closure_error_rad": d.closure_error,
        "proof_phases": s["steps"], "overlap_law_max_mm2": s["overlap_law_max_mm2"],
        "overlap_law_phases": s["overlap_law_steps"], "jam_phases": s["jams"],
        "te_min_rad": s["te_min_rad"], "te_max_rad": s["te_max_rad"], "te_pp_rad": s["te_pp_rad"],
        "backlash_min_mm": s["backlash_min_mm"], "backlash_max_mm": s["backlash_max_mm"],
        "contact_pairs_min": s["contact_pairs_min"], "contact_ratio_mean": s["contact_pairs_mean"],
    })
    if d.method == "generated":
        g = d.smoothing.generability
        w.derived.update({
            "smoothing_rad": d.smoothing.delta,
            "driver_rho_min_mm": g.driver.rho_convex_min, "driver_rho_limit_mm": g.driver.rho_limit,
            "driven_rho_min_mm": g.driven.rho_convex_min, "driven_rho_limit_mm": g.driven.rho_limit,
            "driven_concave_rho_min_mm": g.driven.rho_concave_min, "shaper_r0_mm": g.driven.r0,
            "driver_shift": p.driver_shift, "driven_shift": -p.driver_shift,
            "tip_shortened_teeth": d.driver.shortened_teeth + d.driven.shortened_teeth,
            "shaper_cut_teeth": d.driver.shaper_teeth + d.driven.shaper_teeth,
            "undercut_teeth": d.driver.undercut_teeth + d.driven.undercut_teeth,
        })
        if d.shaper is not None:
            w.derived.update({"rack_profile": p.rack_profile, "shaper_d0_mm": d.shaper.d0_mm, "shaper_z0": d.shaper.z0,
                              "shaper_x0": d.shaper.x0, "shaper_standard": d.shaper.standard,
                              "root_bridge_max_mm": _root_bridge_max(d)})
        if d.search is not None:
            w.derived.update({"law_search_points": len(d.search.points), "law_search_evaluations": d.search.evaluations,
                              "law_search_tries": len(d.search_tries), "blend_u_h_over_u": d.search_tries[-1][0].u_h_rel,
                              "blend_eps": d.run_law.eps, "law_search_binding": d.search_tries[-1][0].binding,
                              "law_search_best_screened_ripple": d.search.points[0].ripple})
    else:
        w.derived.update({"sector_arc_mm": d.table.arc, "sectors_per_leg": d.table.i})
    as_built_values(w, dd, built)
    if pr_other is not None:
        so = pr_other.summary()
        w.derived.update({f"compare_{other.method}_{k}": v for k, v in {
            "center_distance_mm": other.L, "speed_ripple": other.ripple.ripple, "smoothing_deg": other.smoothing_deg,
            "overlap_law_max_mm2": so["overlap_law_max_mm2"], "jam_phases": so["jams"], "proof_phases": so["steps"],
            "te_pp_rad": so["te_pp_rad"], "backlash_min_mm": so["backlash_min_mm"],
            "backlash_max_mm": so["backlash_max_mm"], "least_overlap_max_mm2": float(np.max(pr_other.least_overlap)),
        }.items()})


def notes(dd: PairDesign, w, built: dict) -> None:
    other, pr_other, other_note = built["other"]
    write_notes(w, dd.d, built["proof"], other, pr_other, other_note, dd.p, dd.mount)
    if sized_note(dd.bores):
        w.add_note(sized_note(dd.bores))


#: the output steps after the proofs, in the order the report and the manifest list what they add
start_animation, collect_animation = pipeline_steps(pair_animation)
#: the output steps after the proofs (the animation drawn beside them)
OUTPUT_STEPS = (start_animation, assembly_and_dxf, tables, plots, checks_and_derived, notes, collect_animation)


def write_outputs(p: NoncircularPairParams, w, d: Design, profiles, pr, other=None, pr_other=None,
                  other_note: str = "", solids=None) -> None:
    """Solids (STEP/STL/3MF with the shared checks), assembly, DXF, tables, plots, checks, report values
    of a pair already designed and proved."""
    chosen = bores(p, d)
    p = with_bores(p, chosen)
    dd = PairDesign(p, d, tuple(profiles), mounting(p, d), chosen)
    built = {"solids": solids if solids is not None else start_solids(p, w, profiles), "proof": pr,
             "other": (other, pr_other, other_note)}
    for step in OUTPUT_STEPS:
        step(dd, w, built)


#: the full-cycle proof (and the other method's, the as-built speed) and every check and derived value of the
#: report: from the 2D outlines at the installed centre distance, no solid (Pipeline.prove)
PROOF_STEPS = (proofs, other_method, checks_and_derived)

build = Pipeline(lambda p, w: design_of(p, pair_design, getattr(w, "source", None), progress=w.progress), (proofs, solids, other_method) + OUTPUT_STEPS,
                 proof_steps=PROOF_STEPS, design_apart=True, solid_steps=(solids, assembly_and_dxf))
