"""Parameters of the driven wheel-walking propulsor with a fixed cam (seed 001)."""

from __future__ import annotations

from dataclasses import dataclass

from ...errors import InputError
from ...laws.cam_design import DesignLimits
from ...laws.cam_motion import RETURN_MODES, CamMechanism, CurvatureLaw, ReturnPhase
from ...params import PartParams, param

__all__ = ["LAWS", "MIN_WEB_MM", "CamMoverParams"]

LAWS = ("searched", "zero", "linear", "quadratic", "exponential")


#: least material (mm) kept around holes and between features (ours)
MIN_WEB_MM = 3.0

_WHY_SIZE = "a propulsor of 20 m hub height is larger than any built"
_WHY_CLEAR = "past the fits of any running mechanism"
_WHY_LOAD = "100 MN along one leg"


@dataclass(frozen=True)
class CamMoverParams(PartParams):
    """Parameters of the fixed-cam propulsor.  Seed 001 gives no numbers; all defaults ours."""

    # --- law of motion (seed 001 eq. 20) ---------------------------------------------------
    law: str = param("searched", "", "curvature law K(φ): 'searched' (design search against the limits) "
                     "or a fixed family zero | linear (k0·φ) | quadratic (k0·φ²) | exponential (k0·e^(k1·φ))",
                     choices=list(LAWS))
    k0: float = param(0.0, "1/mm", "coefficient k0 of a fixed law (per rad^n)", min=-1.0, max=1.0,
                      why="curvatures past 1/mm turn the roller path into loops")
    k1: float = param(0.0, "1/rad", "exponent k1 of the exponential law", min=-50.0, max=50.0,
                      why="e^(50·π/4) overflows any curvature law")
    symmetric_law: bool = param(True, "", "use K(|φ|) (even law, symmetric cam and shoes; ours) instead of the literal K(φ)")
    return_mode: str = param("min_gamma", "", "return-phase closure (C2): min_gamma | min_jerk | top",
                             choices=list(RETURN_MODES))
    return_top_mm: float = param(0.0, "mm", "H(π) for return_mode = 'top' (0 otherwise)", min=0.0, max=10000.0,
                                 why=_WHY_SIZE)
    # --- mechanism (seed 001 eq. 6, 14-15) ------------------------------------------------
    R0_mm: float = param(90.0, "mm", "radius of the cam's initial circle R0", min=5.0, max=5000.0, why=_WHY_SIZE)
    roller_radius_mm: float = param(20.0, "mm", "roller radius r", min=1.0, max=1000.0, why=_WHY_SIZE)
    stand_C_mm: float = param(210.0, "mm", "shoe stand length C (hub height R0 + r + C)", min=1.0, max=10000.0,
                              why=_WHY_SIZE)
    n_legs: int = param(4, "", "number of legs (seed 001: 4)", min=3, max=8, integer=True,
                        why="legs past 8 collide in the carrier slides")
    roller_width_mm: float = param(20.0, "mm", "roller width = contact line length b (eq. 14)", min=1.0, max=1000.0,
                                   why=_WHY_SIZE)
    load_support_N: float = param(5000.0, "N", "force along the leg in support P (eq. 14)", min=0.0, max=1e8,
                                  min_exclusive=True, why=_WHY_LOAD)
    load_return_N: float = param(500.0, "N", "spring force along the leg in the return phase", min=0.0, max=1e8,
                                 why=_WHY_LOAD)
    E_cam_MPa: float = param(2.1e5, "MPa", "Young's modulus of the cam E1 (eq. 15)", min=1.0, max=1e7,
                             why="past diamond (1.2e6 MPa)")
    E_roller_MPa: float = param(2.1e5, "MPa", "Young's modulus of the roller E2 (eq. 15)", min=1.0, max=1e7,
                                why="past diamond (1.2e6 MPa)")
    channel_clearance_mm: float = param(0.2, "mm", "clearance of the roller in the guide channel "
                                        "(channel width = 2r + clearance)", min=0.0, max=100.0, min_exclusive=True,
                                        why=_WHY_CLEAR)
    # --- limits of the design search and of the checks -------------------------------------
    gamma_max_deg: float = param(30.0, "deg", "largest pressure angle (eq. 17)", min=0.0, max=90.0,
                                 min_exclusive=True, max_exclusive=True,
                                 why="a pressure angle of 90° locks the follower")
    R_factor: float = param(1.5, "", "convex cam radius of curvature (eq. 16) >= R_factor·r", min=0.0,
                            max=100.0, min_exclusive=True, why="a limit past 100 roller radii rejects every cam")
    sigma_allow_MPa: float = param(1500.0, "MPa", "allowable Hertz stress (eq. 14)", min=0.0, max=1e5,
                                   min_exclusive=True, why="past the strength of any cam material")
    footprint_ratio_max: float = param(0.85, "", "shoe arc / hub travel per step (< 1 keeps the footprints "
                                       "discrete; ours)", min=0.0, max=10.0, min_exclusive=True,
                                       why="past 10 the shoes overlap whole steps")
    cam_core_min_mm: float = param(40.0, "mm", "least H − r (cam material around the axle)", min=0.0, max=10000.0,
                                   why=_WHY_SIZE)
    hub_height_tol_mm: float = param(0.01, "mm", "allowed hub height variation over a support phase",
                                     min=0.0, max=100.0, min_exclusive=True, why=_WHY_CLEAR)
    shoe_radius_min_mm: float = param(0.0, "mm", "least radius of curvature of the shoe (no cusp)", min=0.0,
                                      max=10000.0, why=_WHY_SIZE)
    # --- cam body ----------------------------------------------------------------------------
    cam_plate_mm: float = param(12.0, "mm", "thickness of the cam back plate (channel floor)", min=1.0, max=1000.0,
                                why=_WHY_SIZE)
    cam_rim_mm: float = param(12.0, "mm", "least radial wall outside the outer guide wall", min=1.0, max=1000.0,
                              why=_WHY_SIZE)
    groove_axial_gap_mm: float = param(1.0, "mm", "axial gap of the roller to the channel floor and to the "
                                       "channel top", min=0.0, max=100.0, min_exclusive=True, why=_WHY_CLEAR)
    axle_diameter_mm: float = param(40.0, "mm", "axle O2 diameter = cam bore", min=1.0, max=5000.0, why=_WHY_SIZE)
    cam_bolt_count: int = param(6, "", "mounting holes of the cam", min=0, max=64, integer=True,
                                why="a bolt every 5.6°")
    cam_bolt_circle_mm: float = param(120.0, "mm", "pitch circle diameter of the cam mounting holes", min=1.0,
                                      max=10000.0, why=_WHY_SIZE)
    cam_bolt_hole_mm: float = param(11.0, "mm", "cam mounting hole diameter (M10 clearance)", min=0.5, max=500.0,
                                    why=_WHY_SIZE)
    # --- carrier -------------------------------------------------------------------------------
    carrier_radius_mm: float = param(195.0, "mm", "outer radius of the carrier disc", min=1.0, max=10000.0,
                                     why=_WHY_SIZE)
    carrier_thickness_mm: float = param(20.0, "mm", "carrier (and leg) thickness", min=1.0, max=1000.0, why=_WHY_SIZE)
    carrier_bore_mm: float = param(68.0, "mm", "carrier bore (bearing seat on the axle)", min=1.0, max=5000.0,
                                   why=_WHY_SIZE)
    carrier_axial_gap_mm: float = param(2.0, "mm", "axial gap cam top face → carrier", min=0.0, max=100.0,
                                        min_exclusive=True, why=_WHY_CLEAR)
    carrier_bolt_count: int = param(4, "", "holes for the chain sprocket, between the slides", min=0, max=64,
                                    integer=True, why="a bolt every 5.6°")
    carrier_bolt_circle_mm: float = param(130.0, "mm", "pitch circle diameter of the sprocket holes", min=1.0,
                                          max=10000.0, why=_WHY_SIZE)
    carrier_bolt_hole_mm: float = param(9.0, "mm", "sprocket hole diameter (M8 clearance)", min=0.5, max=500.0,
                                        why=_WHY_SIZE)
    slide_clearance_mm: float = param(0.1, "mm", "clearance of the leg in its slide, per side", min=0.0,
                                      max=100.0, min_exclusive=True, why=_WHY_CLEAR)
    # --- leg, roller ---------------------------------------------------------------------------
    leg_width_mm: float = param(30.0, "mm", "leg width across the slide", min=1.0, max=1000.0, why=_WHY_SIZE)
    leg_back_mm: float = param(25.0, "mm", "leg length behind the roller axle", min=0.0, max=1000.0, why=_WHY_SIZE)
    leg_end_gap_mm: float = param(3.0, "mm", "gap of the leg's inner end to the slide bottom at the smallest H",
                                  min=0.0, max=1000.0, min_exclusive=True, why=_WHY_SIZE)
    leg_guide_min_mm: float = param(30.0, "mm", "least length of the leg inside its slide (at the largest H)",
                                    min=0.0, max=1000.0, why=_WHY_SIZE)
    leg_mount_mm: float = param(100.0, "mm", "roller axle → shoe boss face (where the leg enters the shoe)",
                                min=1.0, max=10000.0, why=_WHY_SIZE)
    socket_depth_mm: float = param(30.0, "mm", "depth of the shoe socket taking the leg end", min=1.0, max=1000.0,
                                   why=_WHY_SIZE)
    socket_clearance_mm: float = param(0.05, "mm", "clearance of the leg end in the shoe socket, per side",
                                       min=0.0, max=10.0, why=_WHY_CLEAR)
    roller_pin_mm: float = param(16.0, "mm", "roller axle (pin) diameter", min=1.0, max=1000.0, why=_WHY_SIZE)
    roller_bore_clearance_mm: float = param(0.05, "mm", "diametral clearance of the roller on its pin", min=0.0,
                                            max=10.0, why=_WHY_CLEAR)
    shoe_bolt_hole_mm: float = param(9.0, "mm", "shoe bolt clearance hole (M8)", min=0.5, max=100.0, why=_WHY_SIZE)
    leg_tap_drill_mm: float = param(6.8, "mm", "tap drill of the shoe bolts in the leg (M8)", min=0.5, max=100.0,
                                    why=_WHY_SIZE)
    leg_tap_depth_mm: float = param(15.0, "mm", "depth of the tapped holes in the leg", min=0.5, max=1000.0,
                                    why=_WHY_SIZE)
    # --- shoe ------------------------------------------------------------------------------------
    shoe_width_mm: float = param(40.0, "mm", "shoe width along the axle (>= leg thickness + cover)", min=1.0,
                                 max=1000.0, why=_WHY_SIZE)
    shoe_rim_mm: float = param(15.0, "mm", "thickness of the shoe rim under the ground curve", min=1.0, max=1000.0,
                               why=_WHY_SIZE)
    shoe_boss_wall_mm: float = param(10.0, "mm", "wall of the shoe boss around the leg socket", min=1.0, max=1000.0,
                                     why=_WHY_SIZE)
    # --- outputs ---------------------------------------------------------------------------------
    assembly_angle_deg: float = param(20.0, "deg", "carrier angle of the assembly STEP (leg 0 from the "
                                      "downward vertical)", min=-360.0, max=360.0, why="one turn either way")
    sweep_steps: int = param(720, "", "carrier positions per turn of the motion proofs", min=720, max=100000,
                             integer=True,
                             why="0.0036° steps; the size estimate bounds the product with the part's size")

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
        """Cross-parameter checks (InputError: parameter, value, limit).  Whether a fixed law's mechanism can
        be made (law, shoe, curvature, fits) is the design's own question (:func:`.design.feasible`)."""
        self.static_checks()

    def static_checks(self) -> None:
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
