"""Print kit of the balancer with its road wheel: the arm swinging on a journal boss of a bracket (the
hull side, lying on the desk), the road wheel turning on the arm's spindle, two stop posts on the
bracket ending the swing at the travel's ends β0 (full rebound) and β_m (full bump, on the arm's stop
pad).

Everything is the full-size design at 1:S (the arm's side outline scaled exactly, the balancer
frame's z stations ÷ S), laid with the axles vertical: bracket face at the hull side's z, the arm's
mid-plane at 0, the wheel outboard above it.  Printed changes: the upper axle is the bracket's boss
(the arm has a bore over it with the running clearance; the torsion bar's spline socket, m = 2 mm,
is not printed: below the printable module at any kit scale here), the spindle is a plain pin of
the outboard bearing's bore ÷ S with the collar the wheel's hub rests on, and the wheel prints in
slabs (:mod:`propulsor.solids.printed_wheel`).

The proof on the printed outline: the arm swept from β0 to β_m (4 steps per degree) against the
stop posts — overlap 0, the least clearance the running clearance, reached at the two ends where
the posts stop it — and the axial layers: posts below the wheel, the wheel above the arm, the arm
above the bracket.
"""

from __future__ import annotations

import math

import numpy as np

from ...check import Check
from ...errors import InputError
from ...geometry.profile import Profile, circle_loop, hull_of_circles
from ...printing.fits import Fit
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.scale import check_printable, choose_scale
from .design import resolve
from .params import BalancerParams

__all__ = ["kit"]

#: bracket plate thickness, stop post radius, material round boss and posts, sweep steps per degree
PLATE_T_MM, POST_R_MM, RIM_MM, STEPS_PER_DEG = 5.0, 4.0, 8.0, 4
#: added to the posts' drawn clearance (mm): the sweep measures on polylines of the exact outline
DRAW_MARGIN_MM = 0.01


def _arm_frame_edge(poly: np.ndarray, x: float, side: float) -> float:
    """The arm outline's edge at station x on the side sign(side): largest side·y where the vertical
    line at x crosses the outline polyline."""
    a, b = poly, np.roll(poly, -1, axis=0)
    ys = []
    for p0, p1 in zip(a, b):
        if (p0[0] - x) * (p1[0] - x) <= 0 and p0[0] != p1[0]:
            t = (x - p0[0]) / (p1[0] - p0[0])
            ys.append(p0[1] + t * (p1[1] - p0[1]))
    return max(side * y for y in ys) * side


def _dist_point_poly(pt, poly: np.ndarray) -> float:
    a, b = poly, np.roll(poly, -1, axis=0)
    d = b - a
    t = np.clip(((pt - a) * d).sum(axis=1) / np.maximum((d * d).sum(axis=1), 1e-300), 0.0, 1.0)
    return float(np.min(np.linalg.norm(a + t[:, None] * d - pt, axis=1)))


def _rot(a: float) -> np.ndarray:
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


def kit(p: BalancerParams, printer: Printer, scale: float | None = None, source=None) -> Kit:
    from ...checks.motion import Pose, rotation_matrices, sweep_pair
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder, fuse
    from ...solids.printed_wheel import wheel_slabs

    m = resolve(p, source)
    wm, wp, tor = m.wheel, m.wheel_p, m.tor
    b = p.arm_width_mm
    outline_full = m.outline.profile
    pts = outline_full.outer.polyline(0.05)
    ext = pts.max(axis=0) - pts.min(axis=0)
    spindle_top = m.extras["spindle_end"]
    wheel_len = max(wm.z_outboard, wm.rows_z[-1][1]) - wm.z_inboard
    # the bracket's footprint at full size: hull of the journal and the two posts at the stop station
    # (the posts' radius and the rim are print sizes; taken at 1:3 here, the plate is checked on the bed)
    foot = []
    for beta, side in ((tor.beta_m, 1.0), (tor.beta0, -1.0)):
        y = _arm_frame_edge(pts, p.s_stop_mm, side) + side * 3 * (POST_R_MM + RIM_MM)
        foot.append(_rot(beta - math.pi / 2) @ np.array([p.s_stop_mm, y]))
    foot = np.array(foot + [[0.0, 0.0]])
    reach = np.ptp(foot, axis=0) + 2 * max(0.5 * p.d_upper_mm + 3 * RIM_MM, 3 * (POST_R_MM + RIM_MM))
    extents = {"arm": (float(ext[0]), float(ext[1]), spindle_top + 0.5 * b),
               "wheel": (2 * wm.r_tyre, 2 * wm.r_tyre, wheel_len),
               "bracket": (float(reach[0]), float(reach[1]), b)}
    choice = choose_scale(extents, printer.bed, scale, margin=printer.margin_mm)
    S = choice.S
    k = 1.0 / S
    check_printable(S, None, printer.min_module_mm, choice=choice, min_feature_mm=printer.min_feature_mm,
                    thinnest={"the arm's least depth": 2 * p.h_min_mm, "the web": wp.web_thickness_mm / 2})
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    ch = printer.chamfer_mm
    # --- z stations at print scale (balancer frame: arm mid-plane 0, outboard +)
    zb = p.hull_side_z_mm * k  # bracket face
    za0, za1 = -0.5 * b * k, 0.5 * b * k  # arm faces
    z_hub = m.z_hub * k
    z_wheel_in = z_hub + wm.z_inboard * k
    z_end = spindle_top * k
    if za0 - zb < clear:
        raise InputError("hull_side_z_mm", p.hull_side_z_mm, f"the bracket face must lie at least the running "
                         f"clearance ({clear:g} mm at 1:{S:g}) inboard of the arm")
    # --- arm: outline ÷ S with the bore over the bracket's boss, collar and spindle pin standing on it
    r_journal = 0.5 * p.d_upper_mm * k
    arm_bore = 2 * r_journal + 2 * clear + under
    arm_prof = outline_full.scaled(k)
    arm_prof = Profile(arm_prof.outer, list(arm_prof.holes) + [circle_loop(arm_bore / 2, ccw=False)], "arm")
    R = p.R_b_mm * k
    spindle_d = wp.bearing_outer_d_mm * k
    collar_r = 0.5 * p.D_lower_mm * k
    arm = fuse(extrude_profile(arm_prof, za1 - za0),
               cylinder(collar_r, za1 - za0 - 0.01, z_hub - za0, center=(R, 0.0)),
               cylinder(spindle_d / 2, z_hub - za0 - 0.01, z_end - za0, center=(R, 0.0)), name="arm")
    arm = arm  # printed on its inboard face: z_print = z - za0
    # --- wheel slabs on the spindle
    wheel_bore = spindle_d + 2 * clear + under
    if wm.r_hub * k - wheel_bore / 2 < printer.min_feature_mm:
        raise InputError("--scale", choice.label, "the printed wheel hub keeps less than two line widths round its bore")
    slabs = wheel_slabs(wm, S, wheel_bore)
    # --- bracket: plate at the hull side with the journal boss and the two stop posts
    arm_poly = arm_prof.outer.polyline(0.01)
    posts = []
    for beta, side in ((tor.beta_m, 1.0), (tor.beta0, -1.0)):
        x = p.s_stop_mm * k
        y = _arm_frame_edge(arm_poly, x, side)
        gap = clear + DRAW_MARGIN_MM
        c = np.array([x, y + side * (POST_R_MM + gap)])
        for _ in range(20):  # the post clears the outline by exactly `gap` at the travel's end
            d = _dist_point_poly(c, arm_poly) - POST_R_MM
            if abs(d - gap) < 1e-9:
                break
            c = c + side * np.array([0.0, gap - d])
        posts.append(_rot(beta - math.pi / 2) @ c)
    boss_top = za0 + (za1 - za0)  # flush with the arm's outboard face
    plate_loop = hull_of_circles([((0.0, 0.0), r_journal + RIM_MM)] + [(tuple(c), POST_R_MM + RIM_MM) for c in posts])
    plate = extrude_profile(Profile(plate_loop, [], "bracket"), PLATE_T_MM)
    # bracket in its own frame: plate 0 … PLATE_T (its top face is the hull side zb), boss and posts above
    collar_top = za0 - zb  # the upper collar the arm rests on: from the bracket face to the arm
    boss = fuse(cylinder(0.5 * p.D_upper_mm * k, PLATE_T_MM - 0.01, PLATE_T_MM + collar_top),
                cylinder(r_journal, PLATE_T_MM + collar_top - 0.01, PLATE_T_MM + boss_top - zb), name="boss")
    post_top = 0.0 - zb  # posts reach the arm's mid-plane
    post_solids = [cylinder(POST_R_MM, PLATE_T_MM - 0.01, PLATE_T_MM + post_top, center=tuple(c)) for c in posts]
    bracket = fuse(plate, boss, *post_solids, name="bracket")
    # --- the 2D proof: the arm's printed outline over the travel against the posts
    betas = np.linspace(tor.beta0, tor.beta_m, int(math.ceil(math.degrees(tor.beta_m - tor.beta0) * STEPS_PER_DEG)) + 1)
    post_loops = [circle_loop(POST_R_MM, tuple(c)) for c in posts]
    sweep = sweep_pair([lp.polyline(0.001) for lp in post_loops], Pose(), arm_prof, rotation_matrices(betas - math.pi / 2),
                       name="arm_vs_stop_posts", max_segment=0.5)
    # the journal boss in the arm's bore: a running fit, its clearance fixed by the radii
    checks = [
        Check.at_most("motion.arm_vs_posts.overlap_area", sweep.max_overlap, 1e-6, "mm^2",
                      f"printed arm outline against the two stop posts over {sweep.n_steps} steps from β0 = "
                      f"{math.degrees(tor.beta0):.3f}° to β_m = {math.degrees(tor.beta_m):.3f}°"),
        Check.at_least("motion.arm_vs_posts.least_clearance", sweep.min_clearance, clear, "mm",
                       f"least gap over the travel, at step {sweep.step_min_clearance} of {sweep.n_steps} (the posts "
                       f"stop the arm {clear + DRAW_MARGIN_MM:g} mm short of contact at both ends)"),
        Check.at_least("motion.posts_below_wheel", z_wheel_in - 0.0, clear, "mm",
                       f"the posts end at the arm's mid-plane, the wheel's inboard face is at z = {z_wheel_in:.3f} mm"),
        Check.at_least("motion.arm_above_bracket", za0 - zb, clear, "mm",
                       "axial gap of the arm's inboard face over the bracket plate (the arm rests on the boss's collar)"),
        Check.at_least("motion.wheel_above_arm", z_wheel_in - za1, clear, "mm",
                       "axial gap of the wheel's inboard face over the arm's outboard face"),
        Check.greater_than("fit.collar_inside_hub", wm.r_hub * k - collar_r, 0.0, "mm",
                           f"the spindle collar (r = {collar_r:.2f}) carries the wheel on its hub face only"),
    ]
    # --- pieces and the model assembled at the static angle
    pieces = [Piece("arm", arm, genus=len(arm_prof.holes), what=f"balancer arm R_b = {R:.2f} mm with collar and spindle "
                                                                  f"⌀{spindle_d:.2f}"),
              Piece("bracket", bracket, genus=0, what="bracket (hull side) with the journal boss and two stop posts")]
    pieces += [Piece(s.name, s.printed, genus=s.genus,
                     what=f"road wheel slab z {s.z0:.2f} … {s.z1:.2f} mm (printed on its half web)") for s in slabs]
    beta_st = tor.beta_st
    rot = beta_st - math.pi / 2
    wc = _rot(rot) @ np.array([R, 0.0])
    assembly = [Placed("bracket", "bracket", place(dz=zb - PLATE_T_MM), "0.75"),
                Placed("arm", "arm", place(dz=za0, rot_z=rot), "tab:blue")]
    assembly += [Placed(s.name, s.name, s.placement(dx=float(wc[0]), dy=float(wc[1]), dz=z_hub), ["0.3", "0.5"][j % 2])
                 for j, s in enumerate(slabs)]
    fits = [Fit("arm_on_boss", "bracket", "arm", (0.0, 0.0), "running", "the arm swings on the bracket's boss",
                pin_z=(PLATE_T_MM + collar_top, PLATE_T_MM + boss_top - zb))]
    fits += [Fit(f"{s.name}_on_spindle", "arm", s.name, (0.0, 0.0), "running", "the wheel turns on the arm's spindle",
                 pin_at=(R, 0.0), pin_z=(z_hub - za0, z_end - za0)) for s in slabs]
    return Kit(
        fits=fits,
        step_parts=[[s.name for s in slabs], ["bracket"], ["arm"], [], []],
        part="balancer", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        derived={"print_R_b_mm": R, "print_travel_deg": [math.degrees(tor.beta0), math.degrees(tor.beta_m)],
                 "print_arm_bore_d_mm": arm_bore, "print_spindle_d_mm": spindle_d, "print_wheel_bore_d_mm": wheel_bore,
                 "print_post_centres_mm": [[float(v) for v in c] for c in posts],
                 "print_arm_post_clearance_min_mm": sweep.min_clearance,
                 "print_arm_post_clearance_ends_mm": [float(sweep.clearance[0]), float(sweep.clearance[-1])],
                 "print_arm_post_clearance_inside_min_mm": float(sweep.clearance[1:-1].min()), "wheel_slabs": len(slabs)},
        allowances=[("running clearance", clear, f"arm bore ⌀{arm_bore:.2f} on the journal boss, wheel bore "
                                                 f"⌀{wheel_bore:.2f} on the spindle, the stop posts {clear:g} mm "
                                                 f"short of the arm at β0 and β_m"),
                    ("hole undersize", under, "added to every hole's diameter"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=[f"Glue the {len(slabs)} wheel slabs together in their order (wheel_1 inboard), half web to half web.",
               "Lay the bracket on the desk, boss up, and clamp or screw it down (the wheel swings out beyond it).",
               "Put the arm, spindle up, over the boss: it rests on the boss's collar.",
               "Put the wheel on the spindle, inboard side down: its hub rests on the spindle's collar.",
               f"Swing the arm by the wheel from post to post: that is the wheel's travel β0 = "
               f"{math.degrees(tor.beta0):.1f}° … β_m = {math.degrees(tor.beta_m):.1f}° (full rebound to full bump, "
               f"the bump post on the arm's stop pad); the wheel turns on the spindle."],
        notes=[f"The torsion bar's spline socket (m = {p.spline_m_mm:g} mm, {p.spline_m_mm / S:.3g} mm at 1:{S:g}) "
               f"is below the printable module ({printer.min_module_mm:g} mm) and is not printed; the arm swings "
               "freely on the boss — the full-size socket is in the part's STEP."])
