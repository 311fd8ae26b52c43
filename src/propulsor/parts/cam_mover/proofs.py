"""The cam mover's proofs on the geometry, not on the formulas.

* the roller outline swept through a full carrier turn (``sweep_steps`` >= 720 positions H(φ))
  against the cam channel bodies with manifold3d booleans: overlap with the working wall and with
  the outer wall, gap to each (min/max); plus 3D spot checks of the roller and cam meshes read
  back from the exported STL files;
* the shoe outline read back from the exported DXF, placed for every leg at every step by the
  computed leg position, lowest point → hub height over flat ground; its variation over each
  support phase;
* neighbouring legs + shoes against each other, legs and shoes against the carrier over a turn
  (all of them share one axial layer, so plan-view overlap is 3D overlap; the cam and the
  rollers sit in the layer below, separated by ``carrier_axial_gap_mm``).
"""

from __future__ import annotations

import math

import numpy as np

from ... import policy
from ...check import Check
from ...checks.motion import rotation_matrices
from ...geometry import cam_outlines as co
from .design import Plan

__all__ = ["leg_poses", "hub_height_from_outline", "support_variation", "profile_fd_check", "motion_proofs",
           "spot_checks_3d", "engineering_checks", "motion_proof_checks", "spot_checks_and_tables"]

#: 3D spot checks of the roller and cam meshes (exported STL) per turn
SPOT_CHECKS_3D = 16


def leg_poses(pl: Plan, phi) -> np.ndarray:
    """(n, 2, 3) affine matrices of the leg frame → CAD frame for carrier angles φ."""
    rot, pos = co.leg_placement(pl.motion, phi)
    return rotation_matrices(rot, pos)


def hub_height_from_outline(pl: Plan, pts: np.ndarray, phi: np.ndarray) -> dict:
    """Place the shoe outline points (leg frame) of every leg at every carrier angle φ by the
    computed leg position; the lowest point of all is where the vehicle stands on flat ground:
    hub height = −(its y).  Returns per step the hub height, the supporting leg (its own
    carrier angle wrapped into the support phase) and the clearance of the lowest idle shoe."""
    n = pl.mech.n_legs
    ang = (phi[:, None] + 2.0 * math.pi * np.arange(n)[None, :] / n).ravel()
    M = leg_poses(pl, ang)
    x0, x1 = pts[None, :, 0], pts[None, :, 1]
    low = np.empty(len(M))
    for a in range(0, len(M), 128):  # a block of placements at a time, its heights in the cache (all 2 880 at once:
        m = M[a:a + 128, 1]          # 50 MB arrays, 0.3-0.8 s; so 0.05 s), each height computed as before
        low[a:a + 128] = (x0 * m[:, 0:1] + x1 * m[:, 1:2] + m[:, 2:3]).min(axis=1)
    low = low.reshape(len(phi), n)
    order = np.argsort(low, axis=1)
    lowest = np.take_along_axis(low, order[:, :1], axis=1)[:, 0]
    second = np.take_along_axis(low, order[:, 1:2], axis=1)[:, 0]
    leg = order[:, 0]
    w = pl.motion.wrap(phi + 2.0 * math.pi * leg / n)
    return dict(hub=-lowest, leg=leg, w=w, idle_clearance=second - lowest)


def support_variation(res: dict, n_legs: int) -> tuple[float, list]:
    """Largest max − min of the hub height within one leg's support phase, and per leg."""
    per = []
    for j in range(n_legs):
        m = res["leg"] == j
        per.append(float(np.ptp(res["hub"][m])) if np.any(m) else math.nan)
    return float(np.nanmax(per)), per


def profile_fd_check(motion, n: int = 14400) -> dict:
    """Independent finite-difference check of eq. 9–10 and eq. 16 (acceptance 2): H sampled
    on a uniform grid (values only, not the ODE's H'), H' by 5-point central differences →
    ψ (eq. 10) → profile points (eq. 9) vs the table's; curvature of the table's profile
    points by 5-point differences vs 1/R of eq. 16.  Points within 4 steps of a place where
    a higher derivative of H jumps (±φs, 0, π) are left out."""
    h = 2.0 * math.pi / n
    s = motion.mech.phi_s
    phi = -s + h * np.arange(n)
    offs = np.arange(-2, 3)
    grid = phi[:, None] + h * offs[None, :]
    H = motion.H_derivs(grid.ravel())[0].reshape(grid.shape)
    w1 = np.array([1.0, -8.0, 0.0, 8.0, -1.0]) / (12.0 * h)
    w2 = np.array([-1.0, 16.0, -30.0, 16.0, -1.0]) / (12.0 * h * h)
    H0 = H[:, 2]
    H1 = H @ w1
    r = motion.mech.r
    psi = phi - np.arctan(H1 / H0)
    X = H0 * np.sin(phi) - r * np.sin(psi)
    Y = H0 * np.cos(phi) - r * np.cos(psi)
    t = motion.table(phi)
    keep = np.ones(n, bool)
    for a in (-s, 0.0, s, math.pi, 2 * math.pi - s):
        keep &= np.abs(phi - a) > 4.5 * h
    dpt = float(np.max(np.hypot(X - t.X, Y - t.Y)[keep]))
    # curvature of the table's profile points (eq. 9 with the ODE's H')
    P = motion.table(grid.ravel())
    Xg, Yg = P.X.reshape(grid.shape), P.Y.reshape(grid.shape)
    x1, y1, x2, y2 = Xg @ w1, Yg @ w1, Xg @ w2, Yg @ w2
    kfd = -(x1 * y2 - y1 * x2) / (x1 ** 2 + y1 ** 2) ** 1.5  # Y-down frame: sign flips
    with np.errstate(divide="ignore"):
        k16 = 1.0 / t.R_profile
    dk = float(np.max(np.abs(kfd - k16)[keep]))
    kmax = float(np.max(np.abs(k16[keep])))
    # radius where the wall is really curved (|R| <= 10·H0): relative deviation of R
    curved = keep & (np.abs(k16) >= 0.1 / motion.mech.H0)
    rel = np.abs(kfd - k16) / np.maximum(np.abs(kfd), 1e-300)  # = |R_FD − R| / |R|
    return dict(points_max_mm=dpt, curvature_abs_max=dk, curvature_rel_max=dk / kmax if kmax > 0 else dk,
                R_rel_max=float(np.max(rel[curved])) if np.any(curved) else 0.0, samples=int(np.count_nonzero(keep)))


def _section_polys(cs) -> list:
    return [np.asarray(q, float) for q in cs.to_polygons()]


def motion_proofs(pl: Plan, shoe_loops: list, channel_loops: list, tick=None) -> dict:
    """The 2D sweeps and the hub-height proof on the exported outlines; ``tick(done)``: told how many of the
    sweeps (7; 8 with four legs or more) are done after each (progress only)."""
    from ...checks.motion import Pose, outline, sweep_pair

    p = pl.params
    n = int(p.n_legs)
    N = int(p.sweep_steps)
    phi = 2.0 * math.pi * np.arange(N) / N
    legM = leg_poses(pl, phi)
    out = {"phi": phi}
    # --- roller in the channel: the channel loops read back from the DXF, split by nesting
    depth = []
    for i, q in enumerate(channel_loops):
        d = 0
        for j, o in enumerate(channel_loops):
            if i != j and _inside(q[0], o):
                d += 1
        depth.append(d)
    ring_loops = [q for q, d in zip(channel_loops, depth) if d <= 1]
    core_loops = [q for q, d in zip(channel_loops, depth) if d >= 2]
    roller = outline(pl.roller)

    def done() -> None:
        if tick is not None:
            tick(sum(k != "phi" for k in out))

    out["roller_working"] = sweep_pair(core_loops, Pose(), roller, legM,
                                       name="roller_vs_working_wall", max_segment=0.5)
    done()
    out["roller_outer"] = sweep_pair(ring_loops, Pose(), roller, legM,
                                     name="roller_vs_outer_wall", max_segment=0.5)
    done()
    # --- hub height on flat ground from the exported shoe outline
    pts = np.vstack(shoe_loops)
    out["hub"] = hub_height_from_outline(pl, pts, phi)
    done()
    # the same with the exact shoe curve (the splines of the STEP solid), for comparison
    exact = pl.shoe.profile.outer.polyline(policy.MOTION_CHORD_TOL_MM)
    out["hub_exact"] = hub_height_from_outline(pl, exact, phi)
    done()
    # --- legs and shoes against the carrier and each other (one axial layer)
    cm = 1e-3
    body_cs = outline(pl.shoe.profile, cm, 1.0).section + outline(pl.leg, cm, 1.0).section
    body = outline(_section_polys(body_cs), cm, 1.0)
    car = outline(pl.carrier.profile, cm, 1.0)
    carM = rotation_matrices(phi)
    out["leg_carrier"] = sweep_pair(car, carM, outline(pl.leg, cm, 1.0), legM, name="leg_vs_carrier_slide",
                                    max_segment=1.0)
    done()
    out["shoe_carrier"] = sweep_pair(car, carM, outline(pl.shoe.profile, cm, 1.0), legM, name="shoe_vs_carrier",
                                     max_segment=1.0)
    done()
    nb = leg_poses(pl, phi + 2.0 * math.pi / n)
    out["neighbours"] = sweep_pair(body, legM, body, nb, name="neighbouring_legs", max_segment=1.0)
    done()
    if n >= 4:
        op = leg_poses(pl, phi + 2.0 * math.pi * (n // 2) / n)
        out["opposite"] = sweep_pair(body, legM, body, op, name="opposite_legs", max_segment=1.0)
        done()
    return out


def _inside(pt, poly) -> bool:
    x, y = float(pt[0]), float(pt[1])
    a = poly
    b = np.roll(poly, -1, axis=0)
    cond = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xi = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(cond & (x < xi)) % 2)


def spot_checks_3d(pl: Plan, cam_mesh, roller_mesh, k: int = SPOT_CHECKS_3D):
    """Roller and cam meshes (read back from the exported STL) at k carrier angles: overlap
    volume and gap with manifold3d (the axial fit in the channel included)."""
    from ...checks.motion import sweep_solids_3d

    phi = 2.0 * math.pi * np.arange(k) / k + 0.5 * math.pi / k
    M = leg_poses(pl, phi)
    T = np.zeros((k, 4, 4))
    T[:, :2, :2] = M[:, :, :2]
    T[:, :2, 3] = M[:, :, 2]
    T[:, 2, 2] = 1.0
    T[:, 2, 3] = pl.z["roller"][0]
    T[:, 3, 3] = 1.0
    return phi, sweep_solids_3d(cam_mesh, np.eye(4), roller_mesh, T, search_length=5.0, name="roller_vs_cam_3d")



def engineering_checks(dd: Plan, w, built: dict) -> None:
    """The law's limits (eq. 14-17, 3), the finite-difference check of eq. 9-10 and 16, the carrier's
    guide length, the axial layers."""
    p, pl = dd.params, dd
    mech, motion = pl.mech, pl.motion
    d = w.derived
    ev = pl.evaluation
    lim = p.limits()
    checks = [
        Check.at_most("law: ODE error of H (eq. 20)", motion.H_error_mm, policy.CAM_H_ERROR_MAX_MM, "mm",
                      f"max |H − H_ref| against a DOP853 integration at {policy.CAM_ODE_REF_TOL:g}"),
        Check.at_most("law: pressure angle (eq. 17)", ev["gamma_max_deg"], lim.gamma_max_deg, "deg",
                      f"largest |γ| over the turn ({ev['gamma_max_support_deg']:.3f}° in support)"),
        Check.at_least("law: convex cam radius of curvature (eq. 16)", pl.R_convex_min, lim.R_factor * mech.r, "mm",
                       f"least convex radius of the channel walls ({pl.R_convex_where}) >= {lim.R_factor:g}·r"),
        Check.at_most("law: Hertz stress (eq. 14-15)", max(ev["sigma_max_MPa"], ev["sigma_return_max_MPa"]),
                      lim.sigma_allow, "MPa", f"support {ev['sigma_max_MPa']:.1f} MPa at P = {mech.P:g} N, return "
                                              f"{ev['sigma_return_max_MPa']:.1f} MPa at {mech.P_return:g} N"),
        Check.greater_than("shoe: least radius of curvature (eq. 3)", ev["shoe_radius_min_mm"], lim.shoe_radius_min,
                           "mm", "σ = Y2 − Y1'·sin φ, no cusp; self-intersecting: "
                                 f"{bool(ev['shoe_self_intersecting'])}"),
        Check.at_most("shoe: footprint ratio", ev["footprint_ratio"], lim.footprint_ratio_max, "",
                      "shoe arc / hub travel per step (discrete footprints; ours)"),
        Check.at_least("cam: core H_min − r", pl.H_min - mech.r, lim.cam_core_min, "mm", "material around the axle"),
    ]
    fd = profile_fd_check(motion)
    d.update(fd_profile_points_max_mm=fd["points_max_mm"], fd_profile_curvature_abs_max_per_mm=fd["curvature_abs_max"],
             fd_profile_R_rel_max=fd["R_rel_max"])
    checks += [
        Check.at_most("law: eq. 9-10 profile points vs finite differences", fd["points_max_mm"], 1e-6, "mm",
                      f"H' by 5-point differences of H on {fd['samples']} points of a turn"),
        Check.at_most("law: eq. 16 radius vs finite-difference curvature", fd["curvature_rel_max"], 1e-5, "",
                      f"max |1/R(eq. 16) − κ_FD| = {fd['curvature_abs_max']:.3g} 1/mm over the largest curvature; "
                      f"relative deviation of R where |R| <= 10·H0: {fd['R_rel_max']:.3g}"),
    ]
    guide = pl.carrier.slot_rim - (pl.H_max - p.leg_back_mm)
    checks.append(Check.at_least("carrier: leg length inside its slide at H_max", guide, p.leg_guide_min_mm, "mm",
                                 "guide length of the radial slide"))
    zc = pl.z["carrier"][0]
    checks.append(Check.greater_than("assembly: axial gap cam → carrier/legs/shoes", zc - pl.z["channel"][1], 0.0,
                                     "mm", "the channel layer and the carrier layer are separate"))
    w.add_checks(checks)


def motion_proof_checks(dd: Plan, w, built: dict) -> None:
    """Roller in the channel, hub height from the exported shoe DXF, legs and shoes against the carrier
    and each other over a turn (2D sweeps on the exported outlines)."""
    p, pl = dd.params, dd
    mech = pl.mech
    d = w.derived
    s = mech.phi_s
    lim = p.limits()
    n = mech.n_legs
    w.progress(f"cam_mover: motion proofs ({p.sweep_steps} steps per turn)")
    from ...progress import counter

    tick = counter(w.progress, "cam_mover: motion proofs", 7 + (int(p.n_legs) >= 4), "sweep")
    pr = built["proofs"] = motion_proofs(pl, built["shoe_loops"], built["channel_loops"], tick)
    tol = policy.OVERLAP_AREA_TOL_MM2
    rw, ro = pr["roller_working"], pr["roller_outer"]
    c = p.channel_clearance_mm
    checks = []
    for res, what in ((rw, "working wall"), (ro, "outer wall")):
        checks.append(Check.at_most(f"roller in channel: overlap with the {what}", res.max_overlap, tol, "mm^2",
                                    f"manifold3d intersection area, max over {res.n_steps} steps of a turn "
                                    f"(step {res.step_max_overlap})"))
    # the roller rolls on the working wall (gap 0 up to the DXF chord tolerance) and keeps
    # the designed clearance to the outer wall: it neither lifts off nor binds
    checks.append(Check("roller in channel: gap to the working wall", bool(rw.clearance.min() >= 0.0 and
                                                                         rw.clearance.max() <= policy.CHORD_TOL_MM),
                        float(rw.clearance.max()), [0.0, policy.CHORD_TOL_MM], "mm",
                        f"rolling contact: gap {rw.clearance.min():.3g} .. {rw.clearance.max():.3g} mm over the turn "
                        f"(0 by design; the DXF polyline lies within {policy.CHORD_TOL_MM:g} mm of the curve)"))
    checks.append(Check("roller in channel: clearance to the outer wall", bool(ro.clearance.min() > 0.5 * c and
                                                                              ro.clearance.max() < 1.5 * c),
                        float(ro.clearance.min()), [0.5 * c, 1.5 * c], "mm",
                        f"clearance {ro.clearance.min():.5f} .. {ro.clearance.max():.5f} mm "
                        f"(designed {c:g} mm) — no binding"))
    hub = pr["hub"]
    var, per = support_variation(hub, n)
    var_x, _ = support_variation(pr["hub_exact"], n)
    interior = np.abs(hub["w"]) < 0.9 * s
    idle = float(hub["idle_clearance"][interior].min())
    checks += [
        Check.at_most("hub height: variation over a support phase (exported shoe DXF)", var, lim.hub_height_tol, "mm",
                      f"largest max − min per support phase over {len(pr['phi'])} steps of a turn: "
                      + ", ".join(f"leg {j + 1}: {v:.2e}" for j, v in enumerate(per))
                      + f"; exact curve: {var_x:.2e} mm"),
        Check.at_most("hub height: mean vs R0 + r + C", abs(float(hub["hub"].mean()) - mech.hub_height),
                      lim.hub_height_tol, "mm", f"mean {float(hub['hub'].mean()):.6f} mm, design {mech.hub_height:g} mm"),
        Check.greater_than("hub height: idle shoes clear the ground", idle, 0.0, "mm",
                           "least ground clearance of the legs not in support (inner 90 % of each support phase)"),
    ]
    for key, what in (("leg_carrier", "legs in their slides"), ("shoe_carrier", "shoes vs carrier"),
                      ("neighbours", "neighbouring legs + shoes"), ("opposite", "opposite legs + shoes")):
        if key not in pr:
            continue
        res = pr[key]
        checks.append(Check.at_most(f"collision: {what}: overlap", res.max_overlap, tol, "mm^2",
                                    f"max over {res.n_steps} steps; clearance {res.clearance.min():.4f} .. "
                                    f"{res.clearance.max():.4f} mm"))
        checks.append(Check.greater_than(f"collision: {what}: clearance", res.min_clearance, 0.0, "mm",
                                         f"least clearance at step {res.step_min_clearance}"))
    w.add_checks(checks)
    d.update(roller_gap_working_mm=[float(rw.clearance.min()), float(rw.clearance.max())],
             roller_clearance_outer_mm=[float(ro.clearance.min()), float(ro.clearance.max())],
             roller_overlap_max_mm2=max(rw.max_overlap, ro.max_overlap),
             hub_height_variation_dxf_mm=var, hub_height_variation_exact_mm=var_x,
             hub_height_mean_mm=float(hub["hub"].mean()), idle_shoe_ground_clearance_min_mm=idle,
             leg_slide_clearance_mm=[pr["leg_carrier"].min_clearance, float(pr["leg_carrier"].clearance.max())],
             shoe_carrier_clearance_min_mm=pr["shoe_carrier"].min_clearance,
             neighbour_clearance_min_mm=pr["neighbours"].min_clearance, sweep_steps=int(p.sweep_steps))


def spot_checks_and_tables(dd: Plan, w, built: dict) -> None:
    """3D spot checks of roller and cam on the exported meshes; the sweep and hub-height tables."""
    from ...export.mesh import load_mesh

    pl = dd
    motion = pl.motion
    d = w.derived
    pr = built["proofs"]
    rw, ro, hub = pr["roller_working"], pr["roller_outer"], pr["hub"]
    # 3D spot checks on the exported meshes
    w.progress("cam_mover: 3D spot checks (exported STL)")
    w.wait_for_files("cam", "roller")
    phi3, s3 = spot_checks_3d(pl, load_mesh(w.folder / "cam.stl"), load_mesh(w.folder / "roller.stl"))
    w.add_checks([Check.at_most("roller in channel (3D, exported meshes): overlap volume", s3.max_overlap,
                                policy.OVERLAP_VOLUME_TOL_MM3, "mm^3",
                                f"{len(phi3)} carrier angles; gap {float(s3.gap.min()):.4g} .. "
                                f"{float(s3.gap.max()):.4g} mm (manifold3d min_gap)")])
    d["roller_cam_3d_gap_mm"] = [float(s3.gap.min()), float(s3.gap.max())]
    w.add_table("roller_sweep", {
        "phi_deg": np.degrees(pr["phi"]), "H_mm": motion.H_derivs(pr["phi"])[0],
        "gap_working_wall_mm": rw.clearance, "clearance_outer_wall_mm": ro.clearance,
        "overlap_working_mm2": rw.overlap_area, "overlap_outer_mm2": ro.overlap_area}, None)
    w.add_table("hub_height", {
        "phi_deg": np.degrees(pr["phi"]), "supporting_leg": hub["leg"] + 1,
        "leg_phi_deg": np.degrees(hub["w"]), "hub_height_dxf_mm": hub["hub"],
        "hub_height_exact_mm": pr["hub_exact"]["hub"], "idle_shoe_clearance_mm": hub["idle_clearance"]}, None)
