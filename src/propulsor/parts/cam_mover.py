"""Driven wheel-walking propulsor with a fixed cam (seed 001): cam, carrier, legs, rollers, shoes.

Mechanism (seed 001, fig. 3; SPEC §4): a cam fixed on the axle O2; a carrier turning around
it with ``n_legs`` radial slides; in each slide a leg with a roller that rides the cam in a
guide channel (a closed-track cam); a support shoe on every leg.

Pipeline:

1. Law of motion — the roller-centre path H(φ) over the support phase from a curvature law
   K(φ) by integrating seed 001 eq. 20 (laws.cam_motion, error measured), closed C2 over the
   return phase; the law is either searched against the limits (laws.cam_design: pressure
   angle eq. 17, cam radius of curvature eq. 16, Hertz stress eq. 14–15, shoe without loops,
   footprint ratio, cam core) or given (family + coefficients).
2. Per φ: pressure angle, radius of curvature of both channel walls (eq. 16), Hertz stress
   (eq. 14), hub speed analogue (eq. 8); the shoe (eq. 1, 7, 11–13) — tables as CSV.
3. Outlines (geometry.cam_outlines): channel walls (eq. 9–10 at r and at r + clearance),
   carrier with radial slides, leg, roller, shoe — exact B-splines / arcs / lines.
4. Solids (STEP/STL/3MF each, all shared checks), an assembly STEP at a chosen carrier
   angle, DXF of the cam channel, of the shoe and of the carrier.
5. Proofs on the geometry, not on the formulas:
   * the roller outline swept through a full carrier turn (``sweep_steps`` ≥ 720 positions
     H(φ)) against the cam channel bodies with manifold3d booleans: overlap with the working
     wall and with the outer wall, gap to each (min/max); plus 3D spot checks of the roller
     and cam meshes read back from the exported STL files;
   * the shoe outline read back from the exported DXF, placed for every leg at every step
     by the computed leg position, lowest point → hub height over flat ground; its variation
     over each support phase;
   * neighbouring legs + shoes against each other, legs and shoes against the carrier over
     a turn (all of them share one axial layer, so plan-view overlap is 3D overlap; the cam
     and the rollers sit in the layer below, separated by ``carrier_axial_gap_mm``).

Axial stack (z along the axle, cam back face at z = 0): cam plate [0, tp]; channel
[tp, tp + dg] with dg = roller width + 2·groove_axial_gap; roller [tp + gap, tp + gap + b];
carrier, legs [zc, zc + carrier_thickness] with zc = tp + dg + carrier_axial_gap; shoes
[zc, zc + shoe_width]; the roller pin from the leg down through the roller.

Defaults are ours (SPEC §4: R0 + r + C = 320 mm like the driving propulsor, R0 = 90, r = 20,
C = 210 mm, four legs); every other dimension is ours too and is a parameter.
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass

import numpy as np

from .. import policy
from ..check import Check
from ..errors import InputError
from ..geometry import cam_outlines as co
from ..geometry.profile import Profile
from ..laws.cam_design import CSV_COLUMNS, DesignLimits, SearchGrid, evaluate, search_design
from ..laws.cam_motion import RETURN_MODES, CamMechanism, CurvatureLaw, ReturnPhase, cam_motion
from ..laws.shoe import shoe_loop_check, shoe_table
from ..params import param
from . import PartType

LAWS = ("searched", "zero", "linear", "quadratic", "exponential")

#: least material (mm) kept around holes and between features (ours)
MIN_WEB_MM = 3.0
#: 3D spot checks of the roller and cam meshes (exported STL) per turn
SPOT_CHECKS_3D = 16


@dataclass(frozen=True)
class CamMoverParams:
    """Parameters of the fixed-cam propulsor.  Seed 001 gives no numbers; all defaults ours."""

    # --- law of motion (seed 001 eq. 20) ---------------------------------------------------
    law: str = param("searched", "", "curvature law K(φ): 'searched' (design search against the limits) "
                     "or a fixed family zero | linear (k0·φ) | quadratic (k0·φ²) | exponential (k0·e^(k1·φ))",
                     choices=list(LAWS))
    k0: float = param(0.0, "1/mm", "coefficient k0 of a fixed law (per rad^n)", min=-1.0, max=1.0)
    k1: float = param(0.0, "1/rad", "exponent k1 of the exponential law", min=-50.0, max=50.0)
    symmetric_law: bool = param(True, "", "use K(|φ|) (even law, symmetric cam and shoes; ours) instead of the literal K(φ)")
    return_mode: str = param("min_gamma", "", "return-phase closure (C2): min_gamma | min_jerk | top",
                             choices=list(RETURN_MODES))
    return_top_mm: float = param(0.0, "mm", "H(π) for return_mode = 'top' (0 otherwise)", min=0.0, max=10000.0)
    # --- mechanism (seed 001 eq. 6, 14-15) ------------------------------------------------
    R0_mm: float = param(90.0, "mm", "radius of the cam's initial circle R0", min=5.0, max=5000.0)
    roller_radius_mm: float = param(20.0, "mm", "roller radius r", min=1.0, max=1000.0)
    stand_C_mm: float = param(210.0, "mm", "shoe stand length C (hub height R0 + r + C)", min=1.0, max=10000.0)
    n_legs: int = param(4, "", "number of legs (seed 001: 4)", min=3, max=8, integer=True)
    roller_width_mm: float = param(20.0, "mm", "roller width = contact line length b (eq. 14)", min=1.0, max=1000.0)
    load_support_N: float = param(5000.0, "N", "force along the leg in support P (eq. 14)", min=0.0, max=1e8,
                                  min_exclusive=True)
    load_return_N: float = param(500.0, "N", "spring force along the leg in the return phase", min=0.0, max=1e8)
    E_cam_MPa: float = param(2.1e5, "MPa", "Young's modulus of the cam E1 (eq. 15)", min=1.0, max=1e7)
    E_roller_MPa: float = param(2.1e5, "MPa", "Young's modulus of the roller E2 (eq. 15)", min=1.0, max=1e7)
    channel_clearance_mm: float = param(0.2, "mm", "clearance of the roller in the guide channel "
                                        "(channel width = 2r + clearance)", min=0.0, max=100.0, min_exclusive=True)
    # --- limits of the design search and of the checks -------------------------------------
    gamma_max_deg: float = param(30.0, "deg", "largest pressure angle (eq. 17)", min=0.0, max=90.0,
                                 min_exclusive=True, max_exclusive=True)
    R_factor: float = param(1.5, "", "convex cam radius of curvature (eq. 16) >= R_factor·r", min=0.0,
                            max=100.0, min_exclusive=True)
    sigma_allow_MPa: float = param(1500.0, "MPa", "allowable Hertz stress (eq. 14)", min=0.0, max=1e5,
                                   min_exclusive=True)
    footprint_ratio_max: float = param(0.85, "", "shoe arc / hub travel per step (< 1 keeps the footprints "
                                       "discrete; ours)", min=0.0, max=10.0, min_exclusive=True)
    cam_core_min_mm: float = param(40.0, "mm", "least H − r (cam material around the axle)", min=0.0, max=10000.0)
    hub_height_tol_mm: float = param(0.01, "mm", "allowed hub height variation over a support phase",
                                     min=0.0, max=100.0, min_exclusive=True)
    shoe_radius_min_mm: float = param(0.0, "mm", "least radius of curvature of the shoe (no cusp)", min=0.0,
                                      max=10000.0)
    # --- cam body ----------------------------------------------------------------------------
    cam_plate_mm: float = param(12.0, "mm", "thickness of the cam back plate (channel floor)", min=1.0, max=1000.0)
    cam_rim_mm: float = param(12.0, "mm", "least radial wall outside the outer guide wall", min=1.0, max=1000.0)
    groove_axial_gap_mm: float = param(1.0, "mm", "axial gap of the roller to the channel floor and to the "
                                       "channel top", min=0.0, max=100.0, min_exclusive=True)
    axle_diameter_mm: float = param(40.0, "mm", "axle O2 diameter = cam bore", min=1.0, max=5000.0)
    cam_bolt_count: int = param(6, "", "mounting holes of the cam", min=0, max=64, integer=True)
    cam_bolt_circle_mm: float = param(120.0, "mm", "pitch circle diameter of the cam mounting holes", min=1.0,
                                      max=10000.0)
    cam_bolt_hole_mm: float = param(11.0, "mm", "cam mounting hole diameter (M10 clearance)", min=0.5, max=500.0)
    # --- carrier -------------------------------------------------------------------------------
    carrier_radius_mm: float = param(195.0, "mm", "outer radius of the carrier disc", min=1.0, max=10000.0)
    carrier_thickness_mm: float = param(20.0, "mm", "carrier (and leg) thickness", min=1.0, max=1000.0)
    carrier_bore_mm: float = param(68.0, "mm", "carrier bore (bearing seat on the axle)", min=1.0, max=5000.0)
    carrier_axial_gap_mm: float = param(2.0, "mm", "axial gap cam top face → carrier", min=0.0, max=100.0,
                                        min_exclusive=True)
    carrier_bolt_count: int = param(4, "", "holes for the chain sprocket, between the slides", min=0, max=64,
                                    integer=True)
    carrier_bolt_circle_mm: float = param(130.0, "mm", "pitch circle diameter of the sprocket holes", min=1.0,
                                          max=10000.0)
    carrier_bolt_hole_mm: float = param(9.0, "mm", "sprocket hole diameter (M8 clearance)", min=0.5, max=500.0)
    slide_clearance_mm: float = param(0.1, "mm", "clearance of the leg in its slide, per side", min=0.0,
                                      max=100.0, min_exclusive=True)
    # --- leg, roller ---------------------------------------------------------------------------
    leg_width_mm: float = param(30.0, "mm", "leg width across the slide", min=1.0, max=1000.0)
    leg_back_mm: float = param(25.0, "mm", "leg length behind the roller axle", min=0.0, max=1000.0)
    leg_end_gap_mm: float = param(3.0, "mm", "gap of the leg's inner end to the slide bottom at the smallest H",
                                  min=0.0, max=1000.0, min_exclusive=True)
    leg_guide_min_mm: float = param(30.0, "mm", "least length of the leg inside its slide (at the largest H)",
                                    min=0.0, max=1000.0)
    leg_mount_mm: float = param(100.0, "mm", "roller axle → shoe boss face (where the leg enters the shoe)",
                                min=1.0, max=10000.0)
    socket_depth_mm: float = param(30.0, "mm", "depth of the shoe socket taking the leg end", min=1.0, max=1000.0)
    socket_clearance_mm: float = param(0.05, "mm", "clearance of the leg end in the shoe socket, per side",
                                       min=0.0, max=10.0)
    roller_pin_mm: float = param(16.0, "mm", "roller axle (pin) diameter", min=1.0, max=1000.0)
    roller_bore_clearance_mm: float = param(0.05, "mm", "diametral clearance of the roller on its pin", min=0.0,
                                            max=10.0)
    shoe_bolt_hole_mm: float = param(9.0, "mm", "shoe bolt clearance hole (M8)", min=0.5, max=100.0)
    leg_tap_drill_mm: float = param(6.8, "mm", "tap drill of the shoe bolts in the leg (M8)", min=0.5, max=100.0)
    leg_tap_depth_mm: float = param(15.0, "mm", "depth of the tapped holes in the leg", min=0.5, max=1000.0)
    # --- shoe ------------------------------------------------------------------------------------
    shoe_width_mm: float = param(40.0, "mm", "shoe width along the axle (>= leg thickness + cover)", min=1.0,
                                 max=1000.0)
    shoe_rim_mm: float = param(15.0, "mm", "thickness of the shoe rim under the ground curve", min=1.0, max=1000.0)
    shoe_boss_wall_mm: float = param(10.0, "mm", "wall of the shoe boss around the leg socket", min=1.0, max=1000.0)
    # --- outputs ---------------------------------------------------------------------------------
    assembly_angle_deg: float = param(20.0, "deg", "carrier angle of the assembly STEP (leg 0 from the "
                                      "downward vertical)", min=-360.0, max=360.0)
    sweep_steps: int = param(720, "", "carrier positions per turn of the motion proofs", min=720, max=100000,
                             integer=True)

    # ------------------------------------------------------------------ derived objects
    def mechanism(self) -> CamMechanism:
        return CamMechanism(R0=self.R0_mm, r=self.roller_radius_mm, C=self.stand_C_mm, n_legs=int(self.n_legs),
                            b=self.roller_width_mm, P=self.load_support_N, P_return=self.load_return_N,
                            E1=self.E_cam_MPa, E2=self.E_roller_MPa, channel_clearance=self.channel_clearance_mm)

    def limits(self) -> DesignLimits:
        return DesignLimits(gamma_max_deg=self.gamma_max_deg, R_factor=self.R_factor,
                            sigma_allow=self.sigma_allow_MPa, shoe_radius_min=self.shoe_radius_min_mm,
                            footprint_ratio_max=self.footprint_ratio_max, cam_core_min=self.cam_core_min_mm,
                            hub_height_tol=self.hub_height_tol_mm)

    def return_phase(self) -> ReturnPhase:
        if self.return_mode == "top":
            return ReturnPhase("top", self.return_top_mm)
        return ReturnPhase(self.return_mode)

    def fixed_law(self) -> CurvatureLaw:
        return CurvatureLaw(self.law, self.k0, self.k1, symmetric=self.symmetric_law)

    # ------------------------------------------------------------------ validation
    def validate(self) -> None:
        """Cross-parameter checks (InputError: parameter, value, limit).  For a fixed law the
        whole design is computed here (law, shoe, curvature, fits); a searched law is
        checked the same way by build() after the search."""
        self._static_checks()
        if self.law != "searched":
            plan(self)

    def _static_checks(self) -> None:
        if self.law == "searched":
            for name in ("k0", "k1"):
                if getattr(self, name) != 0.0:
                    raise InputError(name, getattr(self, name), "must be 0 with law = 'searched' "
                                                                "(the search chooses the coefficients)")
        else:
            if self.law == "zero" and self.k0 != 0.0:
                raise InputError("k0", self.k0, "must be 0 for law = 'zero'")
            if self.law != "exponential" and self.k1 != 0.0:
                raise InputError("k1", self.k1, "only law = 'exponential' uses k1; must be 0")
        if self.return_mode == "top" and not self.return_top_mm > 0.0:
            raise InputError("return_top_mm", self.return_top_mm, "must be > 0 mm with return_mode = 'top'")
        if self.return_mode != "top" and self.return_top_mm != 0.0:
            raise InputError("return_top_mm", self.return_top_mm, "must be 0 unless return_mode = 'top'")
        if self.axle_diameter_mm >= 2.0 * self.R0_mm:
            raise InputError("axle_diameter_mm", self.axle_diameter_mm,
                             f"must be < 2·R0 = {2 * self.R0_mm:g} mm (the cam's initial circle)")
        if self.roller_pin_mm + self.roller_bore_clearance_mm + 2.0 * MIN_WEB_MM > 2.0 * self.roller_radius_mm:
            raise InputError("roller_pin_mm", self.roller_pin_mm,
                             f"must be <= 2·r − clearance − {2 * MIN_WEB_MM:g} = "
                             f"{2 * self.roller_radius_mm - self.roller_bore_clearance_mm - 2 * MIN_WEB_MM:g} mm")
        if self.roller_pin_mm + 2.0 * MIN_WEB_MM > self.leg_width_mm:
            raise InputError("roller_pin_mm", self.roller_pin_mm,
                             f"must be <= leg_width − {2 * MIN_WEB_MM:g} = {self.leg_width_mm - 2 * MIN_WEB_MM:g} mm")
        if self.shoe_width_mm < self.carrier_thickness_mm + MIN_WEB_MM:
            raise InputError("shoe_width_mm", self.shoe_width_mm,
                             f"must be >= carrier_thickness + {MIN_WEB_MM:g} = "
                             f"{self.carrier_thickness_mm + MIN_WEB_MM:g} mm (cover over the leg socket)")
        if self.leg_tap_depth_mm > self.carrier_thickness_mm - MIN_WEB_MM:
            raise InputError("leg_tap_depth_mm", self.leg_tap_depth_mm,
                             f"must be <= carrier_thickness − {MIN_WEB_MM:g} = "
                             f"{self.carrier_thickness_mm - MIN_WEB_MM:g} mm")
        q = 0.25 * self.leg_width_mm  # the two shoe bolts sit at X = ±w/4, mid socket
        if 0.5 * self.shoe_bolt_hole_mm + MIN_WEB_MM / 2 > q or self.shoe_bolt_hole_mm + MIN_WEB_MM > self.socket_depth_mm:
            raise InputError("shoe_bolt_hole_mm", self.shoe_bolt_hole_mm,
                             f"must be <= {min(2 * q - MIN_WEB_MM, self.socket_depth_mm - MIN_WEB_MM):g} mm "
                             f"(two holes at ±leg_width/4 in the socket)")
        if self.leg_tap_drill_mm > self.shoe_bolt_hole_mm:
            raise InputError("leg_tap_drill_mm", self.leg_tap_drill_mm,
                             f"must be <= shoe_bolt_hole_mm = {self.shoe_bolt_hole_mm:g} mm")
        if self.carrier_bore_mm + 2.0 * MIN_WEB_MM >= 2.0 * self.carrier_radius_mm:
            raise InputError("carrier_bore_mm", self.carrier_bore_mm,
                             f"must be < 2·carrier_radius − {2 * MIN_WEB_MM:g} mm")


# ----------------------------------------------------------------------------- the design


@dataclass
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
    if np.any(wk):
        i = int(np.argmin(np.where(wk, t.R_profile, np.inf)))
        cands.append((float(t.R_profile[i]), f"working wall at φ = {math.degrees(t.phi[i]):.2f}°"))
    if np.any(ok):
        i = int(np.argmin(np.where(ok, t.R_outer, np.inf)))
        cands.append((float(t.R_outer[i]), f"outer wall at φ = {math.degrees(t.phi[i]):.2f}°"))
    if not cands:
        return math.inf, "straight"
    return min(cands)


def _law_input_error(law: CurvatureLaw, exc: InputError) -> InputError:
    """Re-issue a law error of laws.cam_motion under the part file's parameter name."""
    if law.kind == "exponential":
        return InputError("k0, k1", (law.k0, law.k1), exc.limit, hint=law.label())
    return InputError("k0", law.k0, exc.limit, hint=law.label())


@functools.lru_cache(maxsize=4)
def plan(p: CamMoverParams) -> Plan:
    """Law → motion → outlines, with every cross-parameter check that needs the law."""
    p._static_checks()
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


# ------------------------------------------------------------------------------ solids


def build_solids(pl: Plan) -> dict:
    """Solids of every part, each in its own frame (z from its own bottom face)."""
    from ..solids.build import extrude_profile
    from ..solids.kernel import box, cq_cut, cq_cylinder, cq_fuse, shifted_z

    p = pl.params
    z = pl.z
    tp = z["plate"][1]
    dg = z["channel"][1] - z["channel"][0]
    plate = extrude_profile(pl.plate, tp)
    core = shifted_z(extrude_profile(pl.core, dg), tp)
    ring = shifted_z(extrude_profile(pl.ring, dg), tp)
    cam = cq_fuse(plate, core, ring, name="cam")
    carrier = extrude_profile(pl.carrier.profile, p.carrier_thickness_mm)
    # leg: bar + roller pin (down to the roller's lower face) − tapped holes for the shoe bolts
    t = p.carrier_thickness_mm
    bar = extrude_profile(pl.leg, t)
    pin_len = z["pin"][1] - z["pin"][0]
    pin = cq_cylinder(0.5 * p.roller_pin_mm, -pin_len, 0.0)
    ys = p.leg_mount_mm + 0.5 * p.socket_depth_mm
    xs = 0.25 * p.leg_width_mm
    leg = cq_fuse(bar, pin, clean=False)
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


# ------------------------------------------------------------------------------ proofs


def _leg_poses(pl: Plan, phi) -> np.ndarray:
    """(n, 2, 3) affine matrices of the leg frame → CAD frame for carrier angles φ."""
    rot, pos = co.leg_placement(pl.motion, phi)
    c, s = np.cos(rot), np.sin(rot)
    M = np.empty((len(rot), 2, 3))
    M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = c, -s, s, c
    M[:, :, 2] = pos
    return M


def _rot_poses(phi) -> np.ndarray:
    phi = np.asarray(phi, float)
    c, s = np.cos(phi), np.sin(phi)
    M = np.zeros((len(phi), 2, 3))
    M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = c, -s, s, c
    return M


def hub_height_from_outline(pl: Plan, pts: np.ndarray, phi: np.ndarray) -> dict:
    """Place the shoe outline points (leg frame) of every leg at every carrier angle φ by the
    computed leg position; the lowest point of all is where the vehicle stands on flat ground:
    hub height = −(its y).  Returns per step the hub height, the supporting leg (its own
    carrier angle wrapped into the support phase) and the clearance of the lowest idle shoe."""
    n = pl.mech.n_legs
    ang = (phi[:, None] + 2.0 * math.pi * np.arange(n)[None, :] / n).ravel()
    M = _leg_poses(pl, ang)
    y = pts[None, :, 0] * M[:, 1, 0][:, None] + pts[None, :, 1] * M[:, 1, 1][:, None] + M[:, 1, 2][:, None]
    low = y.min(axis=1).reshape(len(phi), n)
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


def motion_proofs(pl: Plan, shoe_loops: list, channel_loops: list) -> dict:
    """The 2D sweeps and the hub-height proof on the exported outlines."""
    from ..checks.motion import Pose, outline, sweep_pair

    p = pl.params
    n = int(p.n_legs)
    N = int(p.sweep_steps)
    phi = 2.0 * math.pi * np.arange(N) / N
    legM = _leg_poses(pl, phi)
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
    out["roller_working"] = sweep_pair(core_loops, Pose(), roller, legM,
                                       name="roller_vs_working_wall", max_segment=0.5)
    out["roller_outer"] = sweep_pair(ring_loops, Pose(), roller, legM,
                                     name="roller_vs_outer_wall", max_segment=0.5)
    # --- hub height on flat ground from the exported shoe outline
    pts = np.vstack(shoe_loops)
    out["hub"] = hub_height_from_outline(pl, pts, phi)
    # the same with the exact shoe curve (the splines of the STEP solid), for comparison
    exact = pl.shoe.profile.outer.polyline(policy.MOTION_CHORD_TOL_MM)
    out["hub_exact"] = hub_height_from_outline(pl, exact, phi)
    # --- legs and shoes against the carrier and each other (one axial layer)
    cm = 1e-3
    body_cs = outline(pl.shoe.profile, cm, 1.0).section + outline(pl.leg, cm, 1.0).section
    body = outline(_section_polys(body_cs), cm, 1.0)
    car = outline(pl.carrier.profile, cm, 1.0)
    carM = _rot_poses(phi)
    out["leg_carrier"] = sweep_pair(car, carM, outline(pl.leg, cm, 1.0), legM, name="leg_vs_carrier_slide",
                                    max_segment=1.0)
    out["shoe_carrier"] = sweep_pair(car, carM, outline(pl.shoe.profile, cm, 1.0), legM, name="shoe_vs_carrier",
                                     max_segment=1.0)
    nb = _leg_poses(pl, phi + 2.0 * math.pi / n)
    out["neighbours"] = sweep_pair(body, legM, body, nb, name="neighbouring_legs", max_segment=1.0)
    if n >= 4:
        op = _leg_poses(pl, phi + 2.0 * math.pi * (n // 2) / n)
        out["opposite"] = sweep_pair(body, legM, body, op, name="opposite_legs", max_segment=1.0)
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
    from ..checks.motion import sweep_solids_3d

    phi = 2.0 * math.pi * np.arange(k) / k + 0.5 * math.pi / k
    M = _leg_poses(pl, phi)
    T = np.zeros((k, 4, 4))
    T[:, :2, :2] = M[:, :, :2]
    T[:, :2, 3] = M[:, :, 2]
    T[:, 2, 2] = 1.0
    T[:, 2, 3] = pl.z["roller"][0]
    T[:, 3, 3] = 1.0
    return phi, sweep_solids_3d(cam_mesh, np.eye(4), roller_mesh, T, search_length=5.0, name="roller_vs_cam_3d")


# ------------------------------------------------------------------------------- build


def _rows(cols: dict) -> tuple[list, list]:
    names = list(cols)
    return names, list(zip(*[np.asarray(v).tolist() if isinstance(v, np.ndarray) else list(v)
                             for v in cols.values()]))


def build(p: CamMoverParams, w) -> None:
    """Build every file of the part into the writer's folder (see module docstring)."""
    from ..export.dxf import read_dxf, read_dxf_loops
    from ..export.mesh import load_mesh

    t_start = time.perf_counter()
    w.progress("cam_mover: law of motion" + (" (design search)" if p.law == "searched" else ""))
    pl = plan(p)
    mech, motion, law = pl.mech, pl.motion, pl.law
    s = mech.phi_s
    ev = pl.evaluation
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
    # ---------------------------------------------------------------- engineering checks
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
    # ---------------------------------------------------------------- tables
    w.progress("cam_mover: tables")
    phi_t = np.radians(np.arange(-45.0 * 4 / mech.n_legs, 360.0 - 180.0 / mech.n_legs + 1e-9, 0.5))
    t = motion.table(phi_t)
    w.add_table("cam_law", *_rows({
        "phi_deg": np.degrees(phi_t), "phase": np.where(t.support, "support", "return"), "H_mm": t.H,
        "dH_mm_per_rad": t.H1, "d2H_mm_per_rad2": t.H2, "gamma_deg": np.degrees(t.gamma),
        "K_path_per_mm": t.K_path, "R_profile_mm": t.R_profile, "R_outer_wall_mm": t.R_outer,
        "sigma_H_MPa": t.sigma_H, "X_mm": t.X, "Y_mm": t.Y, "X_outer_mm": t.X_outer, "Y_outer_mm": t.Y_outer,
        "hub_speed_dX02_mm_per_rad": t.hub_speed}))
    phi_s = np.radians(np.arange(-180.0 / mech.n_legs, 180.0 / mech.n_legs + 1e-9, 0.5))
    st = shoe_table(motion.support, phi_s)
    sd = motion.support.derivs(phi_s)
    w.add_table("shoe", *_rows({
        "phi_deg": np.degrees(phi_s), "H_mm": sd["H"], "Y1_mm": st.Y1, "dY1_mm_per_rad": st.dY1, "Y2_mm": st.Y2,
        "X_B_mm": st.X_B, "Y_B_mm": st.Y_B, "rho_mm": st.rho, "alpha_deg": np.degrees(st.alpha),
        "shoe_radius_mm": st.radius}))
    if pl.search is not None:
        rows = [[r.get(c, "") for c in CSV_COLUMNS] for r in pl.search.rows]
        w.add_table("design_search", list(CSV_COLUMNS), rows)
    else:
        w.add_table("design_evaluation", list(CSV_COLUMNS), [[ev.get(c, 1 if c == "rank" else "") for c in CSV_COLUMNS]])
    # ---------------------------------------------------------------- 2D files
    w.progress("cam_mover: DXF")
    path_ref = [("loop", pl.path), ("circle", {"center": (0.0, 0.0), "radius": p.R0_mm})]
    dxf_channel = w.add_dxf("cam_channel", [pl.ring, pl.core], path_ref)
    leg_ref = [("loop", pl.leg.outer), ("point", {"p": (0.0, 0.0)}),
               ("line", {"p0": (0.0, -p.leg_back_mm), "p1": (0.0, float(np.max(st.Y_B)))})]
    dxf_shoe = w.add_dxf("shoe", [pl.shoe.profile], leg_ref)
    w.add_dxf("carrier", [pl.carrier.profile])
    shoe_loops = read_dxf_loops(dxf_shoe)
    channel_loops = read_dxf_loops(dxf_channel)
    n_loops_expected = {"cam_channel": 4 + p.cam_bolt_count, "shoe": 1}
    for name, path, loops in (("cam_channel", dxf_channel, channel_loops), ("shoe", dxf_shoe, shoe_loops)):
        info = read_dxf(path)
        n_open = len(info["layers"].get("CUT", {}).get("open", []))
        w.add_checks([Check.equals(f"{name}.dxf: closed CUT loops", len(loops), n_loops_expected[name], "loops",
                                   f"{len(loops)} closed loops, {n_open} open entities on CUT; $INSUNITS = "
                                   f"{info['insunits']} (mm)"),
                      Check.equals(f"{name}.dxf: open CUT entities", n_open, 0, "")])
    # ---------------------------------------------------------------- solids
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
    # ---------------------------------------------------------------- proofs on the geometry
    w.progress(f"cam_mover: motion proofs ({p.sweep_steps} steps per turn)")
    pr = motion_proofs(pl, shoe_loops, channel_loops)
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
    # 3D spot checks on the exported meshes
    w.progress("cam_mover: 3D spot checks (exported STL)")
    phi3, s3 = spot_checks_3d(pl, load_mesh(w.folder / "cam.stl"), load_mesh(w.folder / "roller.stl"))
    w.add_checks([Check.at_most("roller in channel (3D, exported meshes): overlap volume", s3.max_overlap,
                                policy.OVERLAP_VOLUME_TOL_MM3, "mm^3",
                                f"{len(phi3)} carrier angles; gap {float(s3.gap.min()):.4g} .. "
                                f"{float(s3.gap.max()):.4g} mm (manifold3d min_gap)")])
    d["roller_cam_3d_gap_mm"] = [float(s3.gap.min()), float(s3.gap.max())]
    w.add_table("roller_sweep", *_rows({
        "phi_deg": np.degrees(pr["phi"]), "H_mm": motion.H_derivs(pr["phi"])[0],
        "gap_working_wall_mm": rw.clearance, "clearance_outer_wall_mm": ro.clearance,
        "overlap_working_mm2": rw.overlap_area, "overlap_outer_mm2": ro.overlap_area}))
    w.add_table("hub_height", *_rows({
        "phi_deg": np.degrees(pr["phi"]), "supporting_leg": hub["leg"] + 1,
        "leg_phi_deg": np.degrees(hub["w"]), "hub_height_dxf_mm": hub["hub"],
        "hub_height_exact_mm": pr["hub_exact"]["hub"], "idle_shoe_clearance_mm": hub["idle_clearance"]}))
    # ---------------------------------------------------------------- plots
    w.progress("cam_mover: plots")
    _plots(w, pl, t, pr)
    w.add_note(
        "Seed 001 gives the method, not the numbers: the dimensions, loads, materials and limits are ours "
        "(SPEC §4: R0 + r + C = 320 mm like the driving propulsor). The working wall of the channel is the "
        "roller envelope at exactly r from the designed roller-centre path (the springs and the ground load "
        "press the roller onto it, so the hub height is exact there); the outer guide wall is at "
        f"r + {c:g} mm. The law is used as K(|φ|) (even) unless symmetric_law = false. The return phase is "
        f"closed C2 by two minimum-jerk quintics ({p.return_mode}). Springs, bearings and axial retainers are "
        "not modelled.")
    w.progress(f"cam_mover: built in {time.perf_counter() - t_start:.1f} s")  # timings stay out of the files


def _plots(w, pl: Plan, t, pr: dict) -> None:
    from ..export.plots import new_figure

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


PART_TYPE = PartType(
    name="cam_mover",
    summary="fixed cam (closed track), carrier, legs, rollers and shoes of the driven wheel-walking propulsor (seed 001)",
    params_cls=CamMoverParams,
    build=build,
)

__all__ = ["CamMoverParams", "PART_TYPE", "plan", "build_solids", "hub_height_from_outline", "profile_fd_check"]
