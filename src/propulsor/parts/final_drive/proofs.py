"""The planetary final drive's proofs: the set's sheet and conditions, undercut of the generated
outlines, and overlap / clearance of every mesh over one carrier turn on the finished outlines
(:func:`propulsor.checks.motion.sweep_pair_windowed`, manifold3d booleans)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy
from ...check import Check
from ...errors import InputError
from ...parallel import start as start_in_fork
from .design import FinalDriveDesign, body_offsets, ring_outer_d
from .params import FinalDriveParams

__all__ = ["MeshSweep", "member_poses", "carrier_sweep", "sheet_and_conditions", "outline_checks", "start_sweep", "sweep_results",
           "dms"]


# --- the part -------------------------------------------------------------------------------------
def dms(angle_rad: float) -> str:
    s = math.degrees(angle_rad) * 3600.0
    d, rem = divmod(s, 3600.0)
    mnt, sec = divmod(rem, 60.0)
    return f"{int(d)}°{int(mnt):02d}'{sec:05.2f}\""



@dataclass
class MeshSweep:
    name: str
    psi: np.ndarray
    overlap_mm2: np.ndarray
    clearance_mm: np.ndarray
    result: object


def member_poses(p: FinalDriveParams, ps, psi) -> tuple:
    """(sun, ring, [planet k]) world poses ((n, 2, 3) matrices of the outlines' body frames) at carrier
    angles psi: sun at i_1H·ψ, planet k at its orbit position and absolute rotation, ring fixed
    (seed 004 eq. 32; phasing in :mod:`propulsor.gears.planetary_kinematics`)."""
    from ...checks.motion import rotation_matrices
    from ...gears.planetary_kinematics import PlanetaryKinematics

    psi = np.asarray(psi, float)
    n = len(psi)
    kin = PlanetaryKinematics(p.z_sun, p.z_planet, p.z_ring, p.n_planets, ps.a_w)
    off_ext, off_ring = body_offsets(p.z_ring)
    M_sun = rotation_matrices(kin.sun_angle(psi) + off_ext, np.zeros((n, 2)))
    M_ring = rotation_matrices(np.full(n, kin.ring_rotation + off_ring), np.zeros((n, 2)))
    M_pl = [rotation_matrices(kin.planet_angle(psi, k) + off_ext, kin.planet_centre(psi, k))
            for k in range(p.n_planets)]
    return M_sun, M_ring, M_pl


def carrier_sweep(p: FinalDriveParams, ps, outlines, steps_per_deg: float | None = None) -> list[MeshSweep]:
    """Overlap area and least clearance of every mesh (sun–planet k, planet k–ring) over one carrier turn.

    Each planet is swept on its own positions: sun at i_1H·ψ, planet k at its orbit position and
    absolute rotation, ring fixed (seed 004 eq. 32; phasing in
    :mod:`propulsor.gears.planetary_kinematics`).  manifold3d boolean per step.
    """
    from ...checks.motion import outline, sweep_pair_windowed
    from ...parallel import tick

    spd = steps_per_deg or p.sweep_steps_per_deg
    n = int(math.ceil(360.0 * spd))
    psi = np.arange(n) * (2.0 * math.pi / n)
    sun_o, planet_o, ring_o = outlines
    # outlines within 1 µm of the true curves; long edges split for the tree search (module-scaled)
    tol, seg = policy.PLANETARY_SWEEP_CHORD_TOL_MM, max(0.1, 0.05 * p.module_mm)
    A_sun = outline(sun_o.profile, tol, seg)
    A_pl = outline(planet_o.profile, tol, seg)
    A_ring = outline(ring_o.profile, tol, seg)

    M_sun, M_ring, M_planets = member_poses(p, ps, psi)
    out = []
    tick(0, 2 * p.n_planets)  # the meshes swept, to the build that started this (parallel.start's counter)
    for k in range(p.n_planets):
        M_pl = M_planets[k]
        for tag, A, MA in (("sun", A_sun, M_sun), ("ring", A_ring, M_ring)):
            name = f"mesh_{tag}_planet{k + 1}" if tag == "sun" else f"mesh_planet{k + 1}_ring"
            r = sweep_pair_windowed(A, MA, A_pl, M_pl, reach=p.module_mm, chord_tol=tol, max_segment=seg,
                                    name=name, clearance_limit=0.0)
            out.append(MeshSweep(name, psi, r.overlap_area, r.clearance, r))
            tick(len(out), 2 * p.n_planets)
    return out



def sheet_and_conditions(dd: FinalDriveDesign, w, built: dict) -> None:
    """The sheet of both meshes and the set's conditions: derived values, checks, tables."""
    p, ps = dd.p, dd.ps
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    w.progress("planetary set: sheet and conditions")
    d = w.derived
    d.update({
        "ratio_i_1H": ps.ratio,
        "n_planets": p.n_planets,
        "x_ring_used": ps.x_ring,
        "x_ring_for_coaxiality": ps.ring_shift_for_coaxiality(),
        "a_w_sun_planet_mm": sp.a_w,
        "a_w_planet_ring_mm": pr.a_w,
        "alpha_w_sun_planet_deg": math.degrees(sp.alpha_w),
        "alpha_w_sun_planet_dms": dms(sp.alpha_w),
        "alpha_w_planet_ring_deg": math.degrees(pr.alpha_w),
        "alpha_w_planet_ring_dms": dms(pr.alpha_w),
        "coaxiality_mismatch_mm": ps.coaxiality_mismatch,
        "neighbour_gap_mm": ps.neighbour_gap,
        "assembly_quotient": ps.assembly_quotient,
    })
    for tag, g, da in (("sun", ps.sun, ps.d_a_sun), ("planet", ps.planet, ps.d_a_planet), ("ring", ps.ring, ps.d_a_ring)):
        d.update({f"d_{tag}_mm": g.d, f"d_b_{tag}_mm": g.d_b, f"d_a_{tag}_mm": da, f"d_f_{tag}_mm": g.d_f,
                  f"s_n_{tag}_mm": g.s_n, f"k_W_{tag}": g.k_W, f"W_k_{tag}_mm": g.W_k,
                  f"D_roller_{tag}_mm": g.D_recommended, f"M_{tag}_mm": g.M(g.D_recommended)})
        if da >= g.d_b:
            d[f"s_na_{tag}_mm"] = g.tip_thickness(da)
    d.update({"d_w_sun_mm": sp.d_w1, "d_w_planet_sun_mesh_mm": sp.d_w2, "d_w_planet_ring_mesh_mm": pr.d_w1,
              "d_w_ring_mm": pr.d_w2})
    for c in ps.conditions():
        w.add_checks([Check(c.name, c.passed, c.value, c.limit, c.unit, c.message)])
    try:
        d["epsilon_alpha_sun_planet"] = ps.epsilon_alpha_sun_planet
        d["epsilon_alpha_planet_ring"] = ps.epsilon_alpha_planet_ring
    except InputError:
        pass
    cols = ["quantity", "symbol", "unit", "gear_1", "gear_2"]
    # each sheet on the tips the solids are made with: one planet serves both meshes with the smaller of its two
    # tips (shortened in the sun mesh), which the planet–ring pair alone would leave unshortened
    t = p.tooth_thinning_mm
    made = [("tooth thickness allowance of the solids (ring: space widening)", "E_sn", "mm", t, t)]
    w.add_table("sheet_sun_planet", cols, [list(r) for r in sp.sheet(d_a1=ps.d_a_sun, d_a2=ps.d_a_planet) + made])
    w.add_table("sheet_planet_ring", cols, [list(r) for r in pr.sheet(d_a1=ps.d_a_planet, d_a2=ps.d_a_ring) + made])
    w.add_table("conditions", ["name", "passed", "value", "limit", "unit", "message"],
                [[c.name, c.passed, c.value, c.limit, c.unit, c.message] for c in ps.conditions()])


def outline_checks(dd: FinalDriveDesign, w, built: dict) -> None:
    """Generated outlines: root and form diameters, undercut."""
    p, ps = dd.p, dd.ps
    d = w.derived
    w.progress("generated outlines (rack: sun, planets; shaper: ring)")
    outlines = dd.outlines
    sun_o, planet_o, ring_o = outlines
    d.update({"d_f_sun_generated_mm": sun_o.d_f, "d_f_planet_generated_mm": planet_o.d_f,
              "d_f_ring_generated_mm": ring_o.d_f, "d_Ff_sun_mm": sun_o.d_Ff, "d_Ff_planet_mm": planet_o.d_Ff,
              "ring_outer_d_mm": ring_outer_d(p, ps)})
    for tag, o in (("sun", sun_o), ("planet", planet_o)):
        w.add_checks([Check.flag(f"undercut_{tag}_generated", not any(o.undercut),
                                 f"rack envelope {'undercuts' if any(o.undercut) else 'does not undercut'} "
                                 f"the {tag} (form diameter d_Ff = {o.d_Ff:.4f} mm)")])


def start_sweep(dd: FinalDriveDesign, w, built: dict) -> None:
    """Start the carrier sweep in a forked worker (the solids are built meanwhile)."""
    p = dd.p
    w.progress(f"interference sweep over one carrier turn ({int(math.ceil(360 * p.sweep_steps_per_deg))} steps), "
               f"in a second process while the solids are built")
    from ...progress import count_to

    built["pending_sweep"] = start_in_fork(carrier_sweep, p, dd.ps, dd.outlines,
                                           counter=count_to(w.progress, "interference sweep", "mesh"))


def sweep_results(dd: FinalDriveDesign, w, built: dict) -> None:
    """The carrier sweep's table, checks and clearance plot."""
    d = w.derived
    sweeps = built["sweeps"] = built.pop("pending_sweep").result()
    w.progress("interference sweep done")
    rows = []
    psi = sweeps[0].psi
    for j in range(len(psi)):
        rows.append([math.degrees(psi[j])] + [v for s in sweeps for v in (s.overlap_mm2[j], s.clearance_mm[j])])
    w.add_table("carrier_sweep", ["psi_deg"] + [f"{s.name}_{q}" for s in sweeps for q in ("overlap_mm2", "clearance_mm")],
                rows)
    for s in sweeps:
        w.add_checks(s.result.checks())
        d[f"{s.name}_min_clearance_mm"] = float(s.clearance_mm.min())
        d[f"{s.name}_max_overlap_mm2"] = float(s.overlap_mm2.max())
    if not w.draws_plots:  # a proof's values only: no figure drawn to be dropped
        return
    from ...export.plots import new_figure

    fig, ax = new_figure()
    for s in sweeps:
        ax.plot(np.degrees(s.psi), s.clearance_mm, lw=0.8, label=s.name)
    ax.set_xlabel("carrier angle ψ, deg")
    ax.set_ylabel("least clearance, mm (negative: penetration)")
    ax.set_title("Planetary final drive: clearance of every mesh over one carrier turn")
    ax.legend(fontsize=7)
    w.add_plot("mesh_clearance", fig)
