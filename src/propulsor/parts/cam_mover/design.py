"""The cam mover's design (seed 001): law of motion → motion → outlines, every cross-parameter check.

1. Law of motion: the roller-centre path H(φ) over the support phase from a curvature law K(φ)
   by integrating seed 001 eq. 20 (laws.cam_motion, error measured), closed C2 over the return
   phase; the law is either searched against the limits (laws.cam_design: pressure angle eq. 17,
   cam radius of curvature eq. 16, Hertz stress eq. 14-15, shoe without loops, footprint ratio,
   cam core) or given (family + coefficients).
2. Outlines (geometry.cam_outlines): channel walls (eq. 9-10 at r and at r + clearance), carrier
   with radial slides, leg, roller, shoe - exact B-splines / arcs / lines.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy
from ...errors import InputError, input_names
from ...geometry import cam_outlines as co
from ...geometry.profile import Profile
from ...laws.cam_design import SearchGrid, evaluate, search_design
from ...laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
from ...laws.shoe import shoe_loop_check, shoe_table
from .params import MIN_WEB_MM, CamMoverParams

__all__ = ["feasible", "Plan", "plan"]


@dataclass(frozen=True)
class Plan:
    """Everything computed before any solid: law, motion, outlines, numbers (InputError if
    the design cannot be built)."""

    params: CamMoverParams
    mech: CamMechanism
    law: CurvatureLaw
    motion: object
    search: object  # DesignResult or None
    evaluation: dict  # laws.cam_design.evaluate row of the law used (with the error estimate)
    H_min: float
    H_max: float
    working_r: tuple
    outer_r: tuple
    rim_radius: float
    R_convex_min: float  # least convex radius of curvature of the two channel walls, mm
    R_convex_where: str
    working: object
    outer: object
    path: object
    core: Profile
    ring: Profile
    plate: Profile
    shoe: object  # ShoeGeometry
    leg: Profile
    roller: Profile
    carrier: object  # CarrierGeometry
    z: dict


def _convex_radius_min(t) -> tuple[float, str]:
    """Least radius of curvature of the channel walls where they are convex toward the roller:
    the working wall where the path bends toward the axis (K > 0), R = 1/K − r (eq. 16); the
    outer wall where it bends away (K < 0), |1/K| − (r + clearance).  Undercut shows as R <= 0."""
    wk = t.K_path > 0
    ok = t.K_path < 0
    cands = []

    def least(values) -> int:
        """The first sample whose value is the least within ``policy.EXTREME_TIE_REL`` (a symmetric law's two mirror
        points: the same one named on every machine)."""
        lo = float(np.min(values))
        return int(np.flatnonzero(values <= lo + policy.EXTREME_TIE_REL * abs(lo))[0])

    if np.any(wk):
        i = least(np.where(wk, t.R_profile, np.inf))
        cands.append((float(np.min(t.R_profile[wk])), f"working wall at φ = {math.degrees(t.phi[i]):.2f}°"))
    if np.any(ok):
        i = least(np.where(ok, t.R_outer, np.inf))
        cands.append((float(np.min(t.R_outer[ok])), f"outer wall at φ = {math.degrees(t.phi[i]):.2f}°"))
    if not cands:
        return math.inf, "straight"
    return min(cands)


def _law_input_error(law: CurvatureLaw, exc: InputError) -> InputError:
    """Re-issue a law error of laws.cam_motion under the part file's parameter name."""
    if law.kind == "exponential":
        return InputError("k0, k1", (law.k0, law.k1), exc.limit, hint=law.label())
    return InputError("k0", law.k0, exc.limit, hint=law.label())


def plan(p: CamMoverParams) -> Plan:
    """Law → motion → outlines, with every cross-parameter check that needs the law."""
    p.static_checks()
    mech = p.mechanism()
    limits = p.limits()
    ret = p.return_phase()
    search = None
    if p.law == "searched":
        search = search_design(mech, limits, SearchGrid(symmetric=p.symmetric_law), ret)
        if search.law is None:
            raise InputError("law", p.law, f"the design search found no admissible law: {search.reason}")
        law = search.law
    else:
        law = p.fixed_law()
    try:
        motion = cam_motion(mech, law, ret, estimate_error=True)
    except InputError as exc:
        raise _law_input_error(law, exc) from None
    s = mech.phi_s
    # shoe without cusps or loops (seed 001 eq. 3: σ = Y2 − Y1'·sin φ > 0)
    st = shoe_table(motion.support, np.linspace(-s, s, policy.CAM_SUPPORT_SAMPLES * 4 + 1))
    lc = shoe_loop_check(st, p.shoe_radius_min_mm)
    if not lc.ok:
        what = "crosses itself" if lc.self_intersecting else "has a cusp (tangent reversal)"
        name, value = ("k0, k1", (law.k0, law.k1)) if law.kind == "exponential" else ("k0", law.k0)
        raise InputError(name, value, f"the shoe profile {what}: least radius of curvature "
                                      f"σ = Y2 − Y1'·sin φ = {lc.radius_min:.4g} mm at φ = "
                                      f"{math.degrees(lc.phi_at_min):.2f}°; must be > {p.shoe_radius_min_mm:g} mm "
                                      f"(seed 001 eq. 3, 7)", hint=law.label())
    # roller radius against the cam radius of curvature (eq. 16)
    phi_t = np.linspace(0.0, 2.0 * math.pi, 4 * policy.CAM_TURN_SAMPLES + 1)
    tab = motion.table(phi_t)
    Rmin, where = _convex_radius_min(tab)
    if not p.roller_radius_mm < Rmin:
        lim = ("the cam is undercut (radius of curvature of the roller-centre path < r)" if Rmin <= 0 else
               f"must be < the least convex radius of curvature of the cam channel R = {Rmin:.4g} mm ({where}, eq. 16)")
        raise InputError("roller_radius_mm", p.roller_radius_mm, lim, hint=law.label())
    if float(tab.H.min()) - p.roller_radius_mm <= 0.5 * p.axle_diameter_mm:
        raise InputError("roller_radius_mm", p.roller_radius_mm,
                         f"the working wall reaches the axle bore: H_min − r = {float(tab.H.min()) - p.roller_radius_mm:.4g} mm "
                         f"must be > axle_diameter/2 = {0.5 * p.axle_diameter_mm:g} mm")
    H_min, H_max = float(tab.H.min()), float(tab.H.max())
    # outlines
    working = co.cam_wall_loop(motion, "working")
    outer = co.cam_wall_loop(motion, "outer")
    path = co.cam_wall_loop(motion, "path")
    wr = co.radial_extent(motion, "working")
    orr = co.radial_extent(motion, "outer")
    rim_radius = orr[1] + p.cam_rim_mm
    # cam mounting holes inside the core, outside the bore
    holes = co.bolt_circle_loops(p.cam_bolt_count, p.cam_bolt_circle_mm, p.cam_bolt_hole_mm)
    if p.cam_bolt_count:
        co.check_hole_fits("cam_bolt_circle_mm", p.cam_bolt_circle_mm,
                           [(0.5 * p.cam_bolt_circle_mm, 0.0)], 0.5 * p.cam_bolt_hole_mm,
                           0.5 * p.axle_diameter_mm, wr[0], MIN_WEB_MM)
        pitch = math.pi * p.cam_bolt_circle_mm / p.cam_bolt_count
        if pitch < p.cam_bolt_hole_mm + MIN_WEB_MM:
            raise InputError("cam_bolt_count", p.cam_bolt_count, f"holes overlap on the pitch circle "
                                                                 f"(pitch {pitch:.4g} mm)")
    core, ring = co.channel_profiles(working, outer, rim_radius, p.axle_diameter_mm, holes)
    plate_prof = co.cam_plate_profile(rim_radius, p.axle_diameter_mm, holes)
    # leg and shoe
    socket_end = p.leg_mount_mm + p.socket_depth_mm
    with input_names({"rim": "shoe_rim_mm", "mount_y": "leg_mount_mm"}):
        shoe = co.shoe_profile(motion, p.shoe_rim_mm, p.leg_width_mm + 2.0 * p.shoe_boss_wall_mm, p.leg_mount_mm)
    if socket_end + MIN_WEB_MM > shoe.inner_y_at_boss:
        raise InputError("socket_depth_mm", p.socket_depth_mm,
                         f"must be <= {shoe.inner_y_at_boss - p.leg_mount_mm - MIN_WEB_MM:.4g} mm (the shoe rim "
                         f"is {shoe.inner_y_at_boss:.4g} mm from the roller axle at the boss)")
    leg = co.leg_profile(p.leg_width_mm, p.leg_back_mm, socket_end)
    roller = co.roller_profile(p.roller_radius_mm, p.roller_pin_mm + p.roller_bore_clearance_mm)
    # carrier: the slide must reach below the leg's inner end at the smallest H
    slot_bottom = H_min - p.leg_back_mm - p.leg_end_gap_mm
    if slot_bottom - 0.5 * p.carrier_bore_mm < MIN_WEB_MM:
        raise InputError("carrier_bore_mm", p.carrier_bore_mm,
                         f"must be <= 2·(slide bottom {slot_bottom:.4g} − {MIN_WEB_MM:g}) = "
                         f"{2 * (slot_bottom - MIN_WEB_MM):.4g} mm (slide bottom = H_min − leg_back − leg_end_gap)")
    slot_w = p.leg_width_mm + 2.0 * p.slide_clearance_mm
    carr_holes = co.bolt_circle_loops(p.carrier_bolt_count, p.carrier_bolt_circle_mm, p.carrier_bolt_hole_mm,
                                      phase=-0.5 * math.pi + math.pi / p.n_legs)
    if p.carrier_bolt_count:
        rc = 0.5 * p.carrier_bolt_circle_mm
        co.check_hole_fits("carrier_bolt_circle_mm", p.carrier_bolt_circle_mm, [(rc, 0.0)],
                           0.5 * p.carrier_bolt_hole_mm, 0.5 * p.carrier_bore_mm, p.carrier_radius_mm, MIN_WEB_MM)
        for k in range(p.carrier_bolt_count):
            a = -0.5 * math.pi + math.pi / p.n_legs + 2 * math.pi * k / p.carrier_bolt_count
            d = co.point_slot_distance((rc * math.cos(a), rc * math.sin(a)), p.n_legs, 0.5 * slot_w, slot_bottom)
            if d < 0.5 * p.carrier_bolt_hole_mm + MIN_WEB_MM:
                raise InputError("carrier_bolt_circle_mm", p.carrier_bolt_circle_mm,
                                 f"sprocket hole {k} comes within {d - 0.5 * p.carrier_bolt_hole_mm:.3g} mm of a "
                                 f"slide; needs {MIN_WEB_MM:g} mm")
        pitch = math.pi * p.carrier_bolt_circle_mm / p.carrier_bolt_count
        if pitch < p.carrier_bolt_hole_mm + MIN_WEB_MM:
            raise InputError("carrier_bolt_count", p.carrier_bolt_count, f"holes overlap (pitch {pitch:.4g} mm)")
    if slot_w >= 2.0 * p.carrier_radius_mm:
        raise InputError("leg_width_mm", p.leg_width_mm,
                         f"its slide (leg_width + 2·slide_clearance = {slot_w:g} mm) must be narrower than the carrier "
                         f"diameter {2.0 * p.carrier_radius_mm:g} mm")
    with input_names({"radius": "carrier_radius_mm"}):
        carrier = co.carrier_profile(p.n_legs, p.carrier_radius_mm, slot_w, slot_bottom, p.carrier_bore_mm, carr_holes)
    if carrier.slot_rim - (H_max - p.leg_back_mm) <= 0.0:
        raise InputError("carrier_radius_mm", p.carrier_radius_mm,
                         f"the leg leaves its slide at H_max = {H_max:.4g} mm: the slide must reach beyond "
                         f"H_max − leg_back = {H_max - p.leg_back_mm:.4g} mm")
    neighbour_gap = 2.0 * math.pi / p.n_legs
    if 0.5 * slot_w + MIN_WEB_MM > slot_bottom * math.sin(0.5 * neighbour_gap):
        raise InputError("leg_width_mm", p.leg_width_mm, "neighbouring slides meet at the slide bottom")
    tp = p.cam_plate_mm
    dg = p.roller_width_mm + 2.0 * p.groove_axial_gap_mm
    zc = tp + dg + p.carrier_axial_gap_mm
    z = dict(plate=(0.0, tp), channel=(tp, tp + dg), roller=(tp + p.groove_axial_gap_mm,
                                                              tp + p.groove_axial_gap_mm + p.roller_width_mm),
             carrier=(zc, zc + p.carrier_thickness_mm), shoe=(zc, zc + p.shoe_width_mm),
             pin=(tp + p.groove_axial_gap_mm, zc))
    evaluation = evaluate(mech, law, limits, ret, estimate_error=True)
    return Plan(p, mech, law, motion, search, evaluation, H_min, H_max, wr, orr, rim_radius, Rmin, where,
                working, outer, path, core, ring, plate_prof, shoe, leg, roller, carrier, z)


def feasible(p, source=None) -> None:
    """InputError (parameter, value, limit) when a fixed law's mechanism cannot be made (law, shoe, curvature,
    fits): the plan computed once (the build reuses it, :func:`~propulsor.parts.pipeline.design_of`).  A
    searched law is checked the same way by the build after the search, which the size estimate bounds first.
    Run by the dry run and the Python API after ``validate()`` (``parts.vet``)."""
    if p.law != "searched":
        from ..pipeline import design_of

        design_of(p, plan)
