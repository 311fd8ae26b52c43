"""The balancer's proofs: stresses on the built outline, the socket, ear and stop pad, and the travel
sweep β0 … β_m with the road wheel mounted (manifold3d booleans against a hull-side envelope and
the neighbouring stations, :func:`propulsor.checks.motion.sweep_solids_3d`), with the minimum
clearance and where it occurs.

World frame of the sweep: x forward, y up, z outboard; the balancer at angle β (from the downward
vertical, seed 004 eq. 5) is the balancer frame turned about z by β − 90°, so the wheel axis sits at
(R_b sin β, −R_b cos β).
"""

from __future__ import annotations

import math
import time

import numpy as np

from ...check import Check
from .design import BalancerModel

__all__ = ["hull_envelope", "travel_sweep", "sweep_job", "strength_proof", "socket_ear_pad_checks",
           "travel_sweep_checks", "fmt_point"]


# ------------------------------------------------------------------------------------------------
# travel sweep
# ------------------------------------------------------------------------------------------------
def _rz(theta: float, t=(0.0, 0.0, 0.0)) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:3, 3] = t
    return T


def hull_envelope(m: BalancerModel):
    """manifold3d solid of the hull-side envelope (world frame): the side plate (plane z = hull_side_z_mm,
    30 mm thick) with the bearing-housing bore, the bottom plate inboard of it (hull_bottom_mm below the
    torsion axis) and the fender / sponson slab over the wheels (fender_height_mm above the axis)."""
    from ...solids.kernel import manifold_cube, manifold_cylinder

    p = m.p
    X = m.pitch + p.R_b_mm + m.wheel.r_tyre + 300.0
    z_out = m.z_hub + m.wheel.z_outboard + 200.0
    zs, H, yf = p.hull_side_z_mm, p.hull_bottom_mm, p.fender_height_mm
    side = manifold_cube([2 * X, yf + H + 30.0, 30.0], [-X, -H - 30.0, zs - 30.0])
    bore = manifold_cylinder(100.0, 0.5 * p.hull_bore_d_mm, 256, [0.0, 0.0, zs - 50.0])
    bottom = manifold_cube([2 * X, 30.0, 600.0], [-X, -H - 30.0, zs - 600.0])
    fender = manifold_cube([2 * X, 30.0, z_out - zs + 10.0], [-X, yf, zs - 10.0])
    return (side - bore) + bottom + fender


def _neighbour_angles(m: BalancerModel, betas: np.ndarray, offset: float) -> tuple[np.ndarray, np.ndarray]:
    """For each β, the neighbour's travel angle that brings the two wheel axes closest, and that distance
    (analytic search over 4001 angles)."""
    tor = m.tor
    R = m.p.R_b_mm
    bb = np.linspace(tor.beta0, tor.beta_m, 4001)
    cx, cy = R * np.sin(bb) + offset, -R * np.cos(bb)
    ang, dist = [], []
    for b in betas:
        d = np.hypot(cx - R * math.sin(b), cy + R * math.cos(b))
        j = int(np.argmin(d))
        ang.append(bb[j])
        dist.append(d[j])
    return np.array(ang), np.array(dist)


#: largest search length of the exact gap (mm); farther bodies are reported as ">= this"
SWEEP_GAP_MAX_MM = 2000.0


def _gap(A, B, w0: float) -> float:
    """Exact least distance (manifold3d min_gap) with a search window doubled from w0 until it holds the gap."""
    w = float(w0)
    while True:
        g = float(A.min_gap(B, w))
        if g < w or w >= SWEEP_GAP_MAX_MM:
            return g
        w *= 2.0


def _exact_gaps(m: BalancerModel, off, cdist, pose_a, pose_b, W: float) -> tuple[dict, set]:
    """Exact gaps at selected steps of a pair whose gap is capped (>= W) at every step: evenly spread
    steps, and for a neighbour the steps around the one where the two wheel axes come closest.  For a
    neighbour the wheel-to-wheel gap (axis distance − 2 R_tyre) bounds the gap from above, so one
    min_gap call with that window is exact; the hull's window grows.  Returns {step: gap} and the
    searched steps whose window did not reach (their gap stays a lower bound)."""
    n = len(cdist)
    cand = np.linspace(0, n - 1, min(n, 13)).round().astype(int).tolist()
    exact = {}
    if off is None:
        for k in cand:
            exact[k] = _gap(pose_a(k), pose_b(k), W)
        return exact, set()
    ka = int(np.argmin(cdist))
    near = list(range(max(0, ka - 2), min(n, ka + 3)))
    for k in near:  # closest wheel axes first: the least gap found bounds every later window
        exact[k] = float(pose_a(k).min_gap(pose_b(k), cdist[k] - 2.0 * m.wheel.r_tyre + 1.0))
    g_min = min(exact.values())
    for k in cand:
        if k not in exact:
            exact[k] = float(pose_a(k).min_gap(pose_b(k), min(cdist[k] - 2.0 * m.wheel.r_tyre, g_min) + 1.0))
    lower = {kk for kk, g in exact.items()
             if kk not in near and g >= min(cdist[kk] - 2.0 * m.wheel.r_tyre, g_min) + 1.0 - 1e-9}
    return exact, lower


def travel_sweep(m: BalancerModel, bal_mesh, wheel_meshes) -> dict:
    """Balancer with its wheel from β0 to β_m against the hull envelope and both neighbours.

    Every step: intersection volume and min_gap with the search window W = max(2 min_clearance, 20 mm)
    (a gap >= W is recorded as W, capped).  A pair capped at every step is searched further at
    selected steps with a growing window, so that its least gap is still exact."""
    from ...checks.motion import sweep_solids_3d
    from ...checks.proximity import nearest_points
    from ...parallel import tick
    from ...solids.kernel import manifold

    p, tor = m.p, m.tor
    n = int(math.ceil(math.degrees(tor.beta_m - tor.beta0) * p.sweep_steps_per_deg)) + 1
    betas = np.linspace(tor.beta0, tor.beta_m, n)
    wheel_T = _rz(0.0, (p.R_b_mm, 0.0, m.z_hub))
    mb = manifold(bal_mesh, "balancer mesh")
    mw = [manifold(wm, "wheel mesh").transform(np.ascontiguousarray(wheel_T[:3])) for wm in wheel_meshes]
    wheel_all = mw[0]
    for x in mw[1:]:
        wheel_all = wheel_all + x
    unit = mb + wheel_all
    hull = hull_envelope(m)
    W = max(2.0 * p.min_clearance_mm, 20.0)
    clock = time.perf_counter
    t0 = clock()
    res = {"beta": betas, "pairs": {}, "window_mm": W, "timing_s": {}}
    own_vol = float((mb ^ wheel_all).volume())
    own_gap = _gap(mb, wheel_all, W)
    res["own"] = (own_vol, own_gap)

    def pose_a(k):
        return unit.transform(np.ascontiguousarray(_rz(betas[k] - math.pi / 2)[:3]))

    targets = {"hull": None, "front": m.pitch, "rear": -m.pitch}
    res["timing_s"]["setup"] = clock() - t0
    Ta = np.array([_rz(b - math.pi / 2) for b in betas])
    tick(0, len(targets))  # the bodies swept against, to the build that started this (parallel.start's counter)
    for name, off in targets.items():
        t0 = clock()
        nb, cdist = np.full(n, np.nan), np.full(n, np.nan)
        if off is not None:
            nb, cdist = _neighbour_angles(m, betas, off)

        def pose_b(k):
            if off is None:
                return hull
            return unit.transform(np.ascontiguousarray(_rz(nb[k] - math.pi / 2, (off, 0.0, 0.0))[:3]))

        # the shared 3D sweep; bodies whose (conservative) boxes stay W apart skip the booleans
        Tb = None if off is None else np.array([_rz(nb[k] - math.pi / 2, (off, 0.0, 0.0)) for k in range(n)])
        sw = sweep_solids_3d(unit, Ta, hull if off is None else unit, Tb, search_length=W, skip_apart=True,
                             name=f"travel_{name}")
        vol, gap = sw.overlap_volume, sw.gap
        res["timing_s"][f"{name}_steps"] = clock() - t0
        t0 = clock()
        capped = gap >= W - 1e-9
        exact, still_lower = {}, set()
        if capped.all():
            exact, still_lower = _exact_gaps(m, off, cdist, pose_a, pose_b, W)
            for k, g in exact.items():
                gap[k] = g
            k = min(exact, key=exact.get)
        else:
            k = int(np.argmin(gap))
        # steps searched with a window that did not reach (>= window) stay lower bounds
        lower = capped.copy()
        for kk in exact:
            lower[kk] = kk in still_lower
        dd = {"overlap_mm3": vol, "gap_mm": gap, "capped": lower,
              "neighbour_beta": nb, "axis_distance_mm": cdist, "worst_step": k, "searched_steps": sorted(exact)}
        res["timing_s"][f"{name}_search"] = clock() - t0
        t0 = clock()
        dist, pa, pb = nearest_points(pose_a(k), pose_b(k), float(gap[k]) + 2.0)
        dd["where"] = (pa, pb, dist)
        dd["what"] = _which(m, pa, betas[k], bal_mesh, wheel_meshes)
        res["pairs"][name] = dd
        res["timing_s"][f"{name}_where"] = clock() - t0
        tick(len(res["pairs"]), len(targets))
    dist, pa, pb = nearest_points(mb, wheel_all, own_gap + 2.0)
    res["own_where"] = (pa, pb, dist)
    return res


def _which(m: BalancerModel, point_world, beta, bal_mesh, wheel_meshes) -> str:
    """Name the body (balancer or a wheel solid) nearest a world point at balancer angle beta."""
    from scipy.spatial import cKDTree

    if point_world is None:
        return "?"
    T = _rz(beta - math.pi / 2)
    q = np.linalg.solve(T, np.append(point_world, 1.0))[:3]  # balancer frame
    best, name = cKDTree(bal_mesh[0]).query(q)[0], "balancer"
    qw = q - np.array([m.p.R_b_mm, 0.0, m.z_hub])
    for nm, (V, F) in zip(m.extras["wheel_names"], wheel_meshes):  # resolve names every wheel solid
        d = cKDTree(V).query(qw)[0]
        if d < best:
            best, name = d, f"wheel {nm}"
    return name


def sweep_job(m: BalancerModel, bal_mesh, wheel_meshes):
    return travel_sweep(m, bal_mesh, wheel_meshes)



def fmt_point(pnt) -> str:
    return "?" if pnt is None else f"({pnt[0]:.1f}, {pnt[1]:.1f}, {pnt[2]:.1f})"



def strength_proof(m: BalancerModel, w, built: dict) -> None:
    """Stresses on the built outline at every station (seed 004 ch. 8), the axle-arm transitions."""
    from ...geometry.arm_outline import section_depth
    from .plots import stress_plot

    p, an = m.p, m.analysis
    D = w.derived
    w.progress("beam model on the built outline")
    s = an.s
    h_eq = m.extras["h_eq"]
    h_built = section_depth(m.outline.profile, s)
    sig = an.stresses(h_built)
    allow = an.sigma_allow
    res = an.run()
    cols = {"s_mm": s, "h_built_mm": h_built, "h_equal_strength_mm": h_eq}
    for name, v in sig.items():
        f = an.forces([c_ for c_ in an.cases if c_.name == name][0])
        key = name.replace(" ", "_").replace("+", "plus")
        cols.update({f"{key}_N_N": f["N"], f"{key}_V_y_N": f["V_y"], f"{key}_T_Nmm": f["T"],
                     f"{key}_M_y_Nmm": f["M_y"], f"{key}_M_z_Nmm": f["M_z"], f"{key}_sigma_vM_MPa": v,
                     f"{key}_safety": p.yield_MPa / np.maximum(v, 1e-12)})
    w.add_table("arm_stresses", cols, None)
    w.add_plot("arm_stresses", stress_plot(m, s, sig, h_built, h_eq))
    for name, v in sig.items():
        k = int(np.argmax(v))
        w.add_checks([Check.at_most(f"arm sigma_vM, {name}", float(v.max()), allow * (1 + 1e-9), "MPa",
                                    f"beam model on the built section depth at every one of {len(s)} stations; "
                                    f"largest at s = {s[k]:.1f} mm (least safety {p.yield_MPa / v.max():.3f})")])
    short = h_built - h_eq
    k = int(np.argmin(short))
    w.add_checks([
        Check.at_least("built depth - equal-strength depth", float(short.min()), 0.0, "mm",
                       f"built outline encloses the equal-strength depth everywhere (least margin at s = {s[k]:.1f} mm)"),
        Check.at_least("least arm depth vs h_min", float(h_built.min()), p.h_min_mm, "mm", "least manufacturable depth"),
    ])
    for c_ in res["checks"]:
        if "constant arm" in c_.name or "equal-strength arm" in c_.name or c_.name == "torsion bar shear at beta_m":
            continue  # the reference arm is a comparison; the arm is checked on its built depth above
        w.add_checks([c_])
    trs = res["transitions"]
    w.add_table("transitions", ["case", "where", "K_t_bending", "K_t_torsion", "sigma_nom_MPa", "tau_nom_MPa",
                                "sigma_vM_nom_MPa", "sigma_vM_peak_MPa", "safety"],
                [[r["case"], r["where"], r["K_t_bending"], r["K_t_torsion"], r["sigma_nom"], r["tau_nom"],
                  r["sigma_vM_nom"], r["sigma_vM_peak"], p.yield_MPa / r["sigma_vM_peak"]] for r in trs])
    sc = res["sigma_vM_constant"]
    body_el = float(np.max(sig["beta_m elastic"][h_built < 0.95 * 2 * p.lower_boss_r_mm]))
    D.update({
        "sigma_allow_MPa": allow,
        "sigma_vM_max_built_MPa": {k_: float(v.max()) for k_, v in sig.items()},
        "sigma_vM_body_elastic_built_MPa": body_el,
        "sigma_vM_constant_ref_MPa": {k_: float(np.max(v)) for k_, v in sc.items()},
        "transition_peak_max_MPa": max(r["sigma_vM_peak"] for r in trs),
        "K_t_upper_bending": trs[0]["K_t_bending"], "K_t_upper_torsion": trs[0]["K_t_torsion"],
        "K_t_spindle_bending": trs[1]["K_t_bending"],
        "e_w_wheel_mid_plane_mm": m.e_w, "h_equal_strength_range_mm": [float(h_eq.min()), float(h_eq.max())],
    })
    built.update(s=s, h_eq=h_eq, h_built=h_built, sig=sig, allow=allow, sc=sc, body_el=body_el, trs=trs)


def socket_ear_pad_checks(m: BalancerModel, w, built: dict) -> None:
    """Spline socket crushing and wall torsion, ear pin and ear, stop pad."""
    p, t, d, an = m.p, m.tor, m.design, m.analysis
    sp = m.spline
    sig_cr = sp.crushing_stress(t.M_T_max, p.spline_length_mm)
    cr_allow = p.yield_MPa / (p.spline_n * p.spline_K_sum)
    d_o, d_i = p.d_upper_mm - 3.0, sp.D_f_hub
    tau_sock = 16.0 * t.M_T_max * d_o / (math.pi * (d_o**4 - d_i**4))
    F_rod = max(d.R_a_comp_max, d.R_a_reb_max)
    r_pin = 0.5 * p.ear_pin_d_mm
    pin_tau = F_rod / (2.0 * math.pi * r_pin**2)
    ear_bear = F_rod / (p.ear_pin_d_mm * p.arm_width_mm)
    ear_net = F_rod / (2.0 * p.ear_wall_mm * p.arm_width_mm)
    F_stop = ([c_ for c_ in an.cases if c_.name == "stop"][0].loads[1].F_y) * -1.0
    pad_p = F_stop / (p.stop_pad_length_mm * p.arm_width_mm)
    w.add_checks([
        Check.at_most("spline socket crushing (GOST 21425, seed 004 §4.3)", sig_cr, cr_allow, "MPa",
                      f"{sp.designation()}, l = {p.spline_length_mm:g} mm, T = M_T(β_m) = {t.M_T_max / 1e6:.3f} kN m; "
                      f"[σ] = {p.yield_MPa:g}/({p.spline_n:g} × {p.spline_K_sum:g})"),
        Check.at_least("socket wall torsion safety", p.yield_MPa / (math.sqrt(3) * tau_sock), p.safety, "",
                       f"hollow journal {d_o:g}/{d_i:.2f} mm at the socket: τ = {tau_sock:.1f} MPa"),
        Check.at_most("ear pin double shear", pin_tau, p.yield_MPa / (math.sqrt(3) * p.safety), "MPa",
                      f"rod force max(R_a,comp, R_a,reb) = {F_rod / 1000:.1f} kN, pin Ø{p.ear_pin_d_mm:g}"),
        Check.at_most("ear bearing pressure", ear_bear, p.yield_MPa / p.safety, "MPa", "F / (d_pin b)"),
        Check.at_most("ear net-section tension", ear_net, p.yield_MPa / p.safety, "MPa", "F / (2 wall b)"),
        Check.at_most("stop pad contact pressure", pad_p, p.yield_MPa / p.safety, "MPa",
                      f"stop force {F_stop / 1000:.1f} kN (k_stop = {p.k_stop:g}) on the flat pad"),
    ])
    w.add_table("spline_socket", ["quantity", "value", "unit"], [
        ["designation", sp.designation(), ""], ["module m", sp.m, "mm"], ["teeth z", sp.z, ""],
        ["pressure angle", 30.0, "deg"], ["profile shift x", sp.x, ""], ["pitch diameter d", sp.d, "mm"],
        ["base diameter d_b", 2 * sp.r_b, "mm"], ["hub minor diameter D_a", sp.D_a_hub, "mm"],
        ["hub major diameter D_f (flat root)", sp.D_f_hub, "mm"], ["shaft major diameter d_a", sp.d_a_shaft, "mm"],
        ["basic space width e", sp.e, "mm"], ["engagement length l", p.spline_length_mm, "mm"],
        ["S_F = 0.5 d_m h z", sp.S_F, "mm^3/mm"], ["crushing stress", sig_cr, "MPa"], ["admissible", cr_allow, "MPa"]])



def travel_sweep_checks(m: BalancerModel, w, built: dict) -> None:
    """The travel sweep's table, plot, overlap and clearance checks; analytic cross-checks of the envelope."""
    from .plots import sweep_plot

    p, t = m.p, m.tor
    D = w.derived
    sw = built["sweep"] = built.pop("pending_sweep").result()
    w.progress("travel sweep done")
    betas = sw["beta"]
    cols = {"beta_deg": np.degrees(betas), "f_mm": t.f(betas), "P_N": t.P(betas),
            "wheel_x_mm": p.R_b_mm * np.sin(betas), "wheel_y_mm": -p.R_b_mm * np.cos(betas)}
    for name, dd in sw["pairs"].items():
        if name != "hull":
            cols[f"{name}_neighbour_beta_deg"] = np.degrees(dd["neighbour_beta"])
            cols[f"{name}_wheel_gap_upper_bound_mm"] = dd["axis_distance_mm"] - 2.0 * m.wheel.r_tyre
        cols[f"{name}_overlap_mm3"] = dd["overlap_mm3"]
        cols[f"{name}_gap_mm"] = dd["gap_mm"]
        cols[f"{name}_gap_is_lower_bound"] = dd["capped"]
    w.add_table("travel_sweep", cols, None)
    w.add_plot("travel_clearance", sweep_plot(m, sw))
    from ...policy import OVERLAP_VOLUME_TOL_MM3 as tol

    labels = {"hull": "hull envelope", "front": "front neighbour station", "rear": "rear neighbour station"}
    overall = (math.inf, None)  # the least gap of the pairs and where
    for name, dd in sw["pairs"].items():
        k = dd["worst_step"]
        pa, pb, dist = dd["where"]
        gap = float(dd["gap_mm"][k])
        exact_steps = ~dd["capped"]
        steady = exact_steps.sum() > 1 and float(np.ptp(dd["gap_mm"][exact_steps])) < 0.01
        where = (f"at β = {math.degrees(betas[k]):.2f}°{' (the same at every step)' if steady else ''} between the "
                 f"{dd['what']} near {fmt_point(pa)} and the {labels[name]} near {fmt_point(pb)} (world mm)")
        w.add_checks([
            Check.at_most(f"travel sweep overlap, {labels[name]}", float(dd["overlap_mm3"].max()), tol, "mm^3",
                          f"manifold3d intersection volume at {len(betas)} steps β0 … β_m "
                          f"({p.sweep_steps_per_deg:g}/deg); {int(np.sum(dd['overlap_mm3'] > tol))} steps overlap"),
            Check.at_least(f"travel sweep clearance, {labels[name]}", gap, p.min_clearance_mm, "mm", f"least gap {where}"),
        ])
        D[f"min_clearance_{name}_mm"] = gap
        D[f"min_clearance_{name}_where"] = where
        if gap < overall[0]:
            overall = (gap, where)
    own_vol, own_gap = sw["own"]
    pa, pb, _ = sw["own_where"]
    w.add_checks([
        Check.at_most("own wheel vs balancer overlap", own_vol, tol, "mm^3", "road wheel mounted on the spindle"),
        Check.at_least("own wheel vs balancer clearance", own_gap, p.min_clearance_mm, "mm",
                       f"least gap near {fmt_point(pa)} / {fmt_point(pb)} (balancer frame); rigid over the travel"),
        Check.at_least("tyre to bolt boss (R_b - R - r_boss)", p.R_b_mm - m.wheel.r_tyre - p.plug_r_mm,
                       p.min_clearance_mm, "mm", "constant over the travel: both on fixed radii"),
    ])
    D["min_clearance_own_wheel_mm"] = own_gap
    D["min_clearance_overall_mm"] = min(overall[0], own_gap)
    D["min_clearance_overall_where"] = (overall[1] if overall[0] <= own_gap else
                                        f"own road wheel to balancer near {fmt_point(pa)} / {fmt_point(pb)} (balancer frame)")
    D["sweep_steps"] = len(betas)
    # analytic cross-checks of the envelope: fender over the wheel top at beta_m, wheel bottom at beta0
    top = -p.R_b_mm * math.cos(t.beta_m) + m.wheel.r_tyre
    D["fender_over_wheel_top_at_beta_m_mm"] = p.fender_height_mm - top
    D["wheel_bottom_below_axis_at_beta0_mm"] = p.R_b_mm * math.cos(t.beta0) + m.wheel.r_tyre
    # eq. 5, cos β_st = (H_кл + H − h_гус − R_ок) / R_б, read backwards: what β_st implies for this wheel
    D["eq5_ground_clearance_minus_track_mm"] = p.R_b_mm * math.cos(t.beta_st) - p.hull_bottom_mm + m.wheel.r_tyre
    # the stop pad face in the world at beta_m (for the hull's bump stop)
    th = t.beta_m - math.pi / 2
    Rm = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    pc = Rm @ np.array([p.s_stop_mm, m.pad[2]])
    nrm = Rm @ np.array([0.0, 1.0])
    D["stop_pad_face_at_beta_m_mm"] = [float(pc[0]), float(pc[1])]
    D["stop_pad_normal_at_beta_max"] = [float(nrm[0]), float(nrm[1])]

    built.update(betas=betas, own_gap=own_gap, pc=pc, nrm=nrm)
