"""The cam mover's outputs: tables, DXF, solids, assembly, plots, notes; and its build.

Axial stack (z along the axle, cam back face at z = 0): cam plate [0, tp]; channel [tp, tp + dg]
with dg = roller width + 2·groove_axial_gap; roller [tp + gap, tp + gap + b]; carrier, legs
[zc, zc + carrier_thickness] with zc = tp + dg + carrier_axial_gap; shoes [zc, zc + shoe_width];
the roller pin from the leg down through the roller.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ...check import Check
from ...geometry import cam_outlines as co
from ...laws.cam_design import CSV_COLUMNS
from ...laws.shoe import shoe_table
from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import walking_animation
from .design import Plan, plan
from .params import CamMoverParams
from .proofs import engineering_checks, motion_proof_checks, spot_checks_and_tables

__all__ = ["build", "build_solids", "expected_genus", "plots"]


def build_solids(pl: Plan) -> dict:
    """Solids of every part, each in its own frame (z from its own bottom face)."""
    from ...solids.build import extrude_profile
    from ...solids.kernel import box, cq_cut, cq_cylinder, cq_fuse, shifted_z

    p = pl.params
    z = pl.z
    tp = z["plate"][1]
    dg = z["channel"][1] - z["channel"][0]
    plate = extrude_profile(pl.plate, tp)
    core = shifted_z(extrude_profile(pl.core, dg), tp)
    ring = shifted_z(extrude_profile(pl.ring, dg), tp)
    cam = cq_fuse(plate, core, ring, name="cam", touching=True)  # the core and ring stand on the plate
    carrier = extrude_profile(pl.carrier.profile, p.carrier_thickness_mm)
    # leg: bar + roller pin (down to the roller's lower face) − tapped holes for the shoe bolts
    t = p.carrier_thickness_mm
    bar = extrude_profile(pl.leg, t)
    pin_len = z["pin"][1] - z["pin"][0]
    pin = cq_cylinder(0.5 * p.roller_pin_mm, -pin_len, 0.0)
    ys = p.leg_mount_mm + 0.5 * p.socket_depth_mm
    xs = 0.25 * p.leg_width_mm
    leg = cq_fuse(bar, pin, clean=False, touching=True)  # the pin stands under the bar
    taps = [cq_cylinder(0.5 * p.leg_tap_drill_mm, t - p.leg_tap_depth_mm, t + 1.0, x, ys) for x in (-xs, xs)]
    leg = cq_cut(leg, *taps, name="leg")
    roller = extrude_profile(pl.roller, p.roller_width_mm)
    # shoe: prism of the outline − socket for the leg end − bolt holes through the cover
    ws = p.shoe_width_mm
    shoe = extrude_profile(pl.shoe.profile, ws)
    hw = 0.5 * p.leg_width_mm + p.socket_clearance_mm
    y0, y1 = p.leg_mount_mm - 1.0, p.leg_mount_mm + p.socket_depth_mm
    socket = box(2 * hw, y1 - y0, t + 1.0, (-hw, y0, -1.0))
    bolts = [cq_cylinder(0.5 * p.shoe_bolt_hole_mm, t - 0.5, ws + 1.0, x, ys) for x in (-xs, xs)]
    shoe = cq_cut(shoe, socket, *bolts, name="shoe")
    return dict(cam=cam, carrier=carrier, leg=leg, roller=roller, shoe=shoe)


#: mesh genus of each part: cam bore + mounting holes; carrier bore + sprocket holes; leg
#: (blind holes only) 0; roller 1; shoe: two bolt holes from the socket to the top face
def expected_genus(p: CamMoverParams) -> dict:
    return dict(cam=1 + p.cam_bolt_count, carrier=1 + p.carrier_bolt_count, leg=0, roller=1, shoe=2)


def plots(w, pl: Plan, t, pr: dict) -> None:
    """The law, the channel outline, the proofs, the design search."""
    from ...export.plots import new_figure

    p = pl.params
    mech = pl.mech
    deg = np.degrees(t.phi)
    # law
    fig, axes = _axes(4, 9.5)
    with np.errstate(divide="ignore"):
        Rw = np.where(t.K_path > 0, t.R_profile, np.nan)
        Ro = np.where(t.K_path < 0, t.R_outer, np.nan)
    series = ((axes[0], [(t.H, "H (roller-centre path)")], "H, mm"),
              (axes[1], [(np.degrees(t.gamma), "γ (eq. 17)")], "pressure angle, deg"),
              (axes[2], [(Rw, "working wall, convex (eq. 16)"), (Ro, "outer wall, convex")], "R, mm"),
              (axes[3], [(t.sigma_H, "σ_H (eq. 14)")], "Hertz stress, MPa"))
    for ax, curves, ylab in series:
        for y, lab in curves:
            ax.plot(deg, y, lw=1.0, label=lab)
        ax.axvspan(-math.degrees(mech.phi_s), math.degrees(mech.phi_s), color="0.92")
        ax.set_ylabel(ylab)
        ax.legend(fontsize=7, loc="upper right")
    axes[1].axhline(p.gamma_max_deg, c="C3", lw=0.8, ls="--")
    axes[1].axhline(-p.gamma_max_deg, c="C3", lw=0.8, ls="--")
    axes[2].axhline(p.R_factor * mech.r, c="C3", lw=0.8, ls="--")
    axes[2].set_yscale("log")
    axes[3].axhline(p.sigma_allow_MPa, c="C3", lw=0.8, ls="--")
    axes[0].set_title(f"{pl.law.label()} (seed 001 eq. 14-20); grey: support phase, dashed: limits")
    axes[-1].set_xlabel("carrier angle φ, deg")
    fig.tight_layout()
    w.add_plot("cam_law", fig)
    # channel outline
    fig, ax = new_figure(6.5, 6.5)
    for loop, lab in ((pl.working, "working wall"), (pl.outer, "outer wall"), (pl.path, "roller-centre path")):
        q = loop.polyline(0.05)
        q = np.vstack([q, q[:1]])
        ax.plot(q[:, 0], q[:, 1], lw=0.8, label=lab)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.set_title("Cam channel (CAD frame, y up; φ from the downward vertical)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    w.add_plot("cam_channel", fig)
    # proofs
    fig, (a1, a2) = _axes(2, 6.5)
    ph = np.degrees(pr["phi"])
    a1.plot(ph, (pr["hub"]["hub"] - mech.hub_height) * 1e3, lw=0.8, label="exported DXF outline")
    a1.plot(ph, (pr["hub_exact"]["hub"] - mech.hub_height) * 1e3, lw=0.8, label="exact shoe curve")
    a1.set_ylabel("hub height − (R0 + r + C), µm")
    a1.legend(fontsize=8)
    a1.set_title("Hub height over flat ground (lowest point of the placed shoes)")
    a2.plot(ph, pr["roller_working"].clearance * 1e3, lw=0.8, label="gap to working wall, µm")
    a2.plot(ph, (pr["roller_outer"].clearance - p.channel_clearance_mm) * 1e3, lw=0.8,
            label=f"clearance to outer wall − {p.channel_clearance_mm:g} mm, µm")
    a2.set_xlabel("carrier angle φ of leg 1, deg")
    a2.legend(fontsize=8)
    fig.tight_layout()
    w.add_plot("proofs", fig)
    if pl.search is not None:
        fig, ax = new_figure(8.0, 5.0)
        rows = pl.search.rows
        for kind, mk in (("linear", "o"), ("quadratic", "s"), ("exponential", "^")):
            for feas, col in ((True, "C2"), (False, "0.7")):
                rr = [r for r in rows if r["law"] == kind and r["feasible"] == feas
                      and np.isfinite(r["hub_speed_variation_pct"])]
                if rr:
                    ax.scatter([r["k0"] for r in rr], [r["hub_speed_variation_pct"] for r in rr], marker=mk, s=14,
                               c=col, label=f"{kind} ({'feasible' if feas else 'rejected'})")
        ch = pl.search.chosen
        ax.scatter([ch["k0"]], [ch["hub_speed_variation_pct"]], marker="*", s=160, c="C3", label="chosen")
        ax.set_xlabel("k0, 1/mm")
        ax.set_ylabel("hub speed variation (eq. 8), %")
        ax.set_title(f"Design search: {pl.search.n_feasible} feasible of {pl.search.n_evaluated}")
        ax.legend(fontsize=7)
        fig.tight_layout()
        w.add_plot("design_search", fig)


def _axes(n: int, height: float):
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(n, 1, figsize=(8.0, height), dpi=100, sharex=True)
    for a in axes:
        a.grid(True, lw=0.4, alpha=0.6)
    return fig, axes



def law_and_derived(dd: Plan, w, built: dict) -> None:
    """The law of motion's numbers (derived values) and the design search's choice."""
    built["t_start"] = time.perf_counter()
    p, pl = dd.params, dd
    mech, motion = pl.mech, pl.motion
    d = w.derived
    law, ev = pl.law, pl.evaluation
    w.progress("cam_mover: law of motion" + (" (design search)" if p.law == "searched" else ""))
    d = w.derived
    d.update(law=law.label(), law_kind=law.kind, k0=law.k0, k1=law.k1, symmetric_law=law.symmetric,
             H0_mm=mech.H0, hub_height_design_mm=mech.hub_height, E_reduced_MPa=mech.E,
             H_min_mm=pl.H_min, H_max_mm=pl.H_max, H_error_mm=motion.H_error_mm,
             return_top_mm=float(motion.H_derivs(np.array([math.pi]))[0][0]),
             gamma_max_deg=ev["gamma_max_deg"], gamma_max_support_deg=ev["gamma_max_support_deg"],
             R_convex_min_mm=pl.R_convex_min, R_convex_min_where=pl.R_convex_where,
             sigma_max_support_MPa=ev["sigma_max_MPa"], sigma_max_return_MPa=ev["sigma_return_max_MPa"],
             hub_speed_variation_pct=ev["hub_speed_variation_pct"], footprint_ratio=ev["footprint_ratio"],
             shoe_radius_min_mm=ev["shoe_radius_min_mm"], cam_rim_radius_mm=pl.rim_radius,
             working_wall_radius_mm=list(pl.working_r), outer_wall_radius_mm=list(pl.outer_r),
             slide_bottom_radius_mm=pl.carrier.slot_bottom, z_layers_mm={k: list(v) for k, v in pl.z.items()})
    if pl.search is not None:
        sr = pl.search
        d.update(search_candidates=sr.n_evaluated, search_feasible=sr.n_feasible, search_choice=sr.reason)
        w.progress(f"cam_mover: design search {sr.n_evaluated} candidates in {sr.elapsed_s:.2f} s")
        w.add_note("Design search (ours; seed 001 only says to keep a variant with admissible contact stress): "
                   + sr.reason + ".")


def tables(dd: Plan, w, built: dict) -> None:
    """The law over a turn, the shoe, the design search (or the evaluation of the given law)."""
    pl = dd
    mech, motion = pl.mech, pl.motion
    ev = pl.evaluation
    w.progress("cam_mover: tables")
    phi_t = np.radians(np.arange(-45.0 * 4 / mech.n_legs, 360.0 - 180.0 / mech.n_legs + 1e-9, 0.5))
    t = built["law_table"] = motion.table(phi_t)
    w.add_table("cam_law", {
        "phi_deg": np.degrees(phi_t), "phase": np.where(t.support, "support", "return"), "H_mm": t.H,
        "dH_mm_per_rad": t.H1, "d2H_mm_per_rad2": t.H2, "gamma_deg": np.degrees(t.gamma),
        "K_path_per_mm": t.K_path, "R_profile_mm": t.R_profile, "R_outer_wall_mm": t.R_outer,
        "sigma_H_MPa": t.sigma_H, "X_mm": t.X, "Y_mm": t.Y, "X_outer_mm": t.X_outer, "Y_outer_mm": t.Y_outer,
        "hub_speed_dX02_mm_per_rad": t.hub_speed}, None)
    phi_s = np.radians(np.arange(-180.0 / mech.n_legs, 180.0 / mech.n_legs + 1e-9, 0.5))
    st = built["shoe_table"] = shoe_table(motion.support, phi_s)
    sd = motion.support.derivs(phi_s)
    w.add_table("shoe", {
        "phi_deg": np.degrees(phi_s), "H_mm": sd["H"], "Y1_mm": st.Y1, "dY1_mm_per_rad": st.dY1, "Y2_mm": st.Y2,
        "X_B_mm": st.X_B, "Y_B_mm": st.Y_B, "rho_mm": st.rho, "alpha_deg": np.degrees(st.alpha),
        "shoe_radius_mm": st.radius}, None)
    if pl.search is not None:
        rows = [[r.get(c, "") for c in CSV_COLUMNS] for r in pl.search.rows]
        w.add_table("design_search", list(CSV_COLUMNS), rows)
    else:
        w.add_table("design_evaluation", list(CSV_COLUMNS), [[ev.get(c, 1 if c == "rank" else "") for c in CSV_COLUMNS]])


def drawings(dd: Plan, w, built: dict) -> None:
    """DXF of the cam channel, the shoe and the carrier; the channel and shoe loops read back from them."""
    from ...export.dxf import read_dxf, read_dxf_loops

    p, pl = dd.params, dd
    st = built["shoe_table"]
    w.progress("cam_mover: DXF")
    path_ref = [("loop", pl.path), ("circle", {"center": (0.0, 0.0), "radius": p.R0_mm})]
    dxf_channel = w.add_dxf("cam_channel", [pl.ring, pl.core], path_ref)
    leg_ref = [("loop", pl.leg.outer), ("point", {"p": (0.0, 0.0)}),
               ("line", {"p0": (0.0, -p.leg_back_mm), "p1": (0.0, float(np.max(st.Y_B)))})]
    dxf_shoe = w.add_dxf("shoe", [pl.shoe.profile], leg_ref)
    w.add_dxf("carrier", [pl.carrier.profile])
    shoe_loops = built["shoe_loops"] = read_dxf_loops(dxf_shoe)
    channel_loops = built["channel_loops"] = read_dxf_loops(dxf_channel)
    n_loops_expected = {"cam_channel": 4 + p.cam_bolt_count, "shoe": 1}
    for name, path, loops in (("cam_channel", dxf_channel, channel_loops), ("shoe", dxf_shoe, shoe_loops)):
        info = read_dxf(path)
        n_open = len(info["layers"].get("CUT", {}).get("open", []))
        w.add_checks([Check.equals(f"{name}.dxf: closed CUT loops", len(loops), n_loops_expected[name], "loops",
                                   f"{len(loops)} closed loops, {n_open} open entities on CUT; $INSUNITS = "
                                   f"{info['insunits']} (mm)"),
                      Check.equals(f"{name}.dxf: open CUT entities", n_open, 0, "")])


def solids_and_assembly(dd: Plan, w, built: dict) -> None:
    """Every solid (files and checks by the writer) and the assembly at ``assembly_angle_deg``."""
    p, pl = dd.params, dd
    mech, motion = pl.mech, pl.motion
    d = w.derived
    zc = pl.z["carrier"][0]
    w.progress("cam_mover: solids")
    solids = build_solids(pl)
    genus = expected_genus(p)
    for name in ("cam", "carrier", "leg", "roller", "shoe"):
        w.add_solid(name, solids[name], expected_genus=genus[name])
    a0 = math.radians(p.assembly_angle_deg)
    comps = [("cam", solids["cam"], (0.0, 0.0, 0.0), 0.0),
             ("carrier", solids["carrier"], (0.0, 0.0, zc), a0)]
    n = mech.n_legs
    for j in range(n):
        aj = a0 + 2.0 * math.pi * j / n
        rot, pos = co.leg_placement(motion, np.array([aj]))
        x, y = float(pos[0, 0]), float(pos[0, 1])
        comps += [(f"leg_{j + 1}", solids["leg"], (x, y, zc), float(rot[0])),
                  (f"roller_{j + 1}", solids["roller"], (x, y, pl.z["roller"][0]), float(rot[0])),
                  (f"shoe_{j + 1}", solids["shoe"], (x, y, zc), float(rot[0]))]
    w.add_assembly("assembly", comps)
    d["assembly_carrier_angle_deg"] = p.assembly_angle_deg


def plots_and_notes(dd: Plan, w, built: dict) -> None:
    p, pl = dd.params, dd
    c = p.channel_clearance_mm
    w.progress("cam_mover: plots")
    plots(w, pl, built["law_table"], built["proofs"])
    w.add_note(
        "Seed 001 gives the method, not the numbers: the dimensions, loads, materials and limits are ours "
        "(the hub height R0 + r + C = 320 mm is that of the driving propulsor). The working wall of the channel is the "
        "roller envelope at exactly r from the designed roller-centre path (the springs and the ground load "
        "press the roller onto it, so the hub height is exact there); the outer guide wall is at "
        f"r + {c:g} mm. The law is used as K(|φ|) (even) unless symmetric_law = false. The return phase is "
        f"closed C2 by two minimum-jerk quintics ({p.return_mode}). Springs, bearings and axial retainers are "
        "not modelled.")
    w.progress(f"cam_mover: built in {time.perf_counter() - built['t_start']:.1f} s")  # timings stay out of the files


start_animation, collect_animation = pipeline_steps(walking_animation)

build = Pipeline(lambda p, w: design_of(p, plan),
                 (law_and_derived, engineering_checks, tables, drawings, solids_and_assembly, motion_proof_checks,
                  start_animation, spot_checks_and_tables, plots_and_notes, collect_animation))
