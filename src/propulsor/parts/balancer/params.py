"""Parameters of the suspension balancer (seed 004 ch. 2 and 8)."""

from __future__ import annotations

from dataclasses import dataclass

from ...errors import InputError
from ...params import PartParams, param

__all__ = ["BalancerParams"]

_WHY_ARM = "twice the depth of the largest balancer arm"
_WHY_AXLE = "past the axles of the heaviest road wheels"


@dataclass(frozen=True)
class BalancerParams(PartParams):
    """Parameters of the suspension balancer (seed 004 ch. 2 and 8)."""

    # -- torsion-bar suspension, seed 004 ch. 2 ------------------------------------------------
    P_st_N: float = param(31490.0, "N", "static wheel load P_st (eq. 3)", min=0.0, min_exclusive=True,
                          max=1e7, why="1000 t on one wheel")
    R_b_mm: float = param(360.0, "mm", "balancer arm R_б: upper-axle axis to wheel axis", min=50.0, max=2000.0,
                          why="twice the arm of the heaviest tracked vehicles")
    beta_st_deg: float = param(43.144, "deg", "static balancer angle from the downward vertical (eq. 5)",
                               min=0.0, max=180.0, min_exclusive=True, max_exclusive=True,
                               why="an angle from the downward vertical")
    d_T_mm: float = param(46.0, "mm", "torsion bar diameter d_T (eq. 6)", min=5.0, max=200.0,
                          why="the thickest torsion bars of tanks (60 ... 80 mm) with margin")
    L_T_mm: float = param(2000.0, "mm", "torsion bar working length L_T (not printed; hull width)", min=100.0,
                          max=6000.0, why="the hull width of the widest tracked carrier")
    tau_max_MPa: float = param(1600.0, "MPa", "allowed torsion bar shear [τ]max (seed: 1100 ... 1600)",
                               min=100.0, max=2500.0, why="above the ultimate shear strength of spring steels")
    G_MPa: float = param(83000.0, "MPa", "shear modulus of the bar G", min=1000.0,
                         max=200000.0, why="above the shear modulus of any steel (79 ... 83 GPa)")
    beta0_deg: float = param(0.0, "deg", "adopted mounting angle β0 (0: eq. 9, β_st − γ_st)", min=0.0, max=180.0,
                             why="an angle from the downward vertical")
    beta_m_deg: float = param(0.0, "deg", "adopted full-travel angle β_m (0: eq. 10, β0 + γ_m)", min=0.0, max=180.0,
                              why="an angle from the downward vertical")
    G_p_N: float = param(473000.0, "N", "sprung weight G_п (eq. 2)", min=0.0, min_exclusive=True,
                         max=1e8, why="10 000 t sprung weight")
    I_y_kgm2: float = param(421100.0, "kg m^2", "body pitch inertia I_y (eq. 2)", min=0.0, min_exclusive=True,
                            max=1e9, why="a thousand times the 50 t carrier's")
    n_wheels_side: int = param(8, "", "road wheels per side (assumed equally spaced over the base)", min=2,
                               max=20, integer=True, why="the longest tracked chassis")
    base_m: float = param(6.846, "m", "first-to-last wheel base (seed Table 11)", min=0.5, max=30.0,
                          why="the longest tracked chassis")
    damped_wheels: list = param([1, 2, 7, 8], "", "wheels with dampers, numbered from the front (n_a = 4)")
    T_phi_s: float = param(1.8, "s", "design pitch period T_φ (eq. 1; 0.5 ... 1.8)", min=0.1, max=10.0,
                           why="the seed's range is 0.5 ... 1.8 s")
    nu: float = param(13.5, "", "pitch amplitude ratio per period ν (10 ... 17)", min=1.0, min_exclusive=True,
                      max=100.0, why="the seed's range is 10 ... 17")
    reb_factor: float = param(0.85, "", "μ_reb = μ_mean / reb_factor (0.8 ... 0.9)", min=0.0, max=1.0,
                              min_exclusive=True, why="a ratio of a mean to its rebound value is below 1")
    h_n_m: float = param(0.05, "m", "bump height h_н (eq. 27)", min=0.0, min_exclusive=True,
                         max=2.0, why="a bump higher than the hull")
    zdd_over_g: float = param(0.5, "", "allowed shake acceleration / g (eq. 27)", min=0.0, min_exclusive=True,
                              max=10.0, why="10 g is far beyond crew tolerance")
    i_a: float = param(0.453, "", "damper–wheel ratio i (eq. 28)", min=0.01, max=10.0,
                       why="a lever ratio of the damper on the arm")
    damper_reading: str = param("lever", "", "reading of i: lever = L_a/R_b (ear at i·R_b); literal = R_b/L_a",
                                choices=["lever", "literal"])
    p_max_MPa: float = param(20.0, "MPa", "largest damper pressure", min=0.1,
                             max=200.0, why="past hydraulic damper pressures")
    d_rod_mm: float = param(40.0, "mm", "damper rod diameter", min=0.0,
                            max=500.0, why="past the rods of the largest dampers")
    # -- strength ----------------------------------------------------------------------------
    yield_MPa: float = param(930.0, "MPa", "yield of 40ХН2МА after quench 850 °C and temper (seed 004 §8.3)", min=100.0,
                             max=3000.0, why="past the strongest steels")
    safety: float = param(1.5, "", "required safety factor on yield (allowable = yield / safety)", min=1.0,
                          max=10.0, why="a safety factor past 10 is no design")
    k_stop: float = param(2.0, "", "stop load = k_stop · P(β_m) (ours; the seed gives none)", min=1.0, max=10.0,
                          why="a stop load of 10 × P(β_m) is a crash")
    n_stations: int = param(360, "", "beam stations along the arm", min=10, max=5000, integer=True,
                            why="0.1 mm stations on a 0.5 m arm")
    # -- arm plate -----------------------------------------------------------------------------
    arm_width_mm: float = param(60.0, "mm", "arm (plate) width b along the axles", min=10.0, max=300.0,
                                why="a plate thicker than the arm is no lever")
    h_ref_mm: float = param(120.0, "mm", "depth of the constant-section reference arm (FE comparison)", min=10.0,
                            max=2000.0, why=_WHY_ARM)
    h_min_mm: float = param(40.0, "mm", "least manufacturable arm depth", min=5.0, max=2000.0, why=_WHY_ARM)
    h_max_mm: float = param(400.0, "mm", "largest arm depth searched", min=10.0, max=2000.0, why=_WHY_ARM)
    depth_margin_mm: float = param(1.0, "mm", "added to the equal-strength half depth", min=0.0, max=50.0,
                                   why=_WHY_ARM)
    smoothing_mm: float = param(20.0, "mm", "half width of the outline's smoothing window", min=1.0, max=100.0,
                                why=_WHY_ARM)
    fillet_mm: float = param(15.0, "mm", "in-plane fillet between arm edges and bosses", min=1.0, max=100.0,
                             why=_WHY_ARM)
    upper_boss_r_mm: float = param(90.0, "mm", "radius of the plate boss at the upper axle", min=10.0,
                                   max=1000.0, why=_WHY_ARM)
    lower_boss_r_mm: float = param(80.0, "mm", "radius of the plate boss at the wheel spindle", min=10.0,
                                   max=1000.0, why=_WHY_ARM)
    s_stop_mm: float = param(230.0, "mm", "stop-pad station along the arm", min=0.0, min_exclusive=True,
                             max=2000.0, why="the longest arm")
    stop_pad_length_mm: float = param(50.0, "mm", "length of the flat stop pad", min=5.0,
                                      max=2000.0, why="the longest arm")
    stop_pad_height_mm: float = param(20.0, "mm", "height of the stop pad over the arm edge", min=2.0,
                                      max=500.0, why=_WHY_ARM)
    ear_pin_d_mm: float = param(40.0, "mm", "damper ear pin diameter", min=5.0, max=500.0, why=_WHY_ARM)
    ear_wall_mm: float = param(20.0, "mm", "wall around the ear pin hole", min=3.0, max=500.0, why=_WHY_ARM)
    ear_ligament_mm: float = param(5.0, "mm", "ligament between the pin hole and the arm's core", min=0.0,
                                   max=500.0, why=_WHY_ARM)
    # -- upper axle (hull bearings, torsion-bar socket) -------------------------------------------
    d_upper_mm: float = param(120.0, "mm", "upper axle journal (hull bearing seats)", min=20.0,
                              max=1000.0, why=_WHY_AXLE)
    D_upper_mm: float = param(160.0, "mm", "shoulder (collar) at the arm", min=25.0, max=1000.0, why=_WHY_AXLE)
    r_upper_mm: float = param(8.0, "mm", "shoulder fillet radius", min=0.5, max=200.0, why=_WHY_AXLE)
    upper_collar_mm: float = param(10.0, "mm", "collar length inboard of the arm face", min=2.0,
                                   max=500.0, why=_WHY_AXLE)
    a1_mm: float = param(70.0, "mm", "outer hull bearing centre, inboard of the arm mid-plane", min=0.0,
                         min_exclusive=True, max=2000.0, why=_WHY_AXLE)
    a2_mm: float = param(200.0, "mm", "inner hull bearing centre", min=0.0, min_exclusive=True,
                         max=2000.0, why=_WHY_AXLE)
    hull_bearing_B_mm: float = param(40.0, "mm", "hull bearing width (seat length)", min=5.0,
                                     max=500.0, why=_WHY_AXLE)
    upper_end_mm: float = param(20.0, "mm", "journal beyond the inner bearing", min=0.0, max=1000.0, why=_WHY_AXLE)
    spline_D_mm: float = param(65.0, "mm", "torsion-bar spline, nominal diameter D (GOST 6033-80)", min=10.0,
                               max=500.0, why="the largest involute splines of GOST 6033-80")
    spline_m_mm: float = param(2.0, "mm", "spline module m", min=0.5, max=10.0,
                               why="the largest spline module of GOST 6033-80")
    spline_z: int = param(31, "", "spline teeth z", min=6, max=200, integer=True,
                          why="GOST 6033-80 tabulates fewer teeth")
    spline_length_mm: float = param(120.0, "mm", "spline engagement length l", min=5.0,
                                    max=1000.0, why="engagement past 2 D carries no more")
    spline_n: float = param(1.4, "", "crushing safety n (GOST 21425; seed 004 §4.3: 1.4)", min=1.0,
                            max=10.0, why="a safety factor past 10 is no design")
    spline_K_sum: float = param(3.71, "", "load concentration K_Σ (seed 004 §4.3: 1 × 2.65 × 1.4)", min=1.0,
                                max=20.0, why="past any tabulated load concentration")
    bolt_bore_d_mm: float = param(22.0, "mm", "torsion-bar retaining-bolt bore through the upper axle", min=2.0,
                                  max=500.0, why=_WHY_AXLE)
    plug_r_mm: float = param(30.0, "mm", "radius of the bolt boss on the outboard face", min=2.0,
                             max=500.0, why=_WHY_AXLE)
    plug_length_mm: float = param(40.0, "mm", "bolt boss length outboard of the arm face", min=0.0,
                                  max=1000.0, why=_WHY_AXLE)
    # -- lower axle (road-wheel spindle) -------------------------------------------------------
    D_lower_mm: float = param(140.0, "mm", "spindle shoulder (collar) at the arm", min=20.0,
                              max=1000.0, why=_WHY_AXLE)
    r_lower_mm: float = param(8.0, "mm", "spindle shoulder fillet radius", min=0.5, max=200.0, why=_WHY_AXLE)
    lower_collar_mm: float = param(10.0, "mm", "collar length outboard of the arm face", min=2.0,
                                   max=500.0, why=_WHY_AXLE)
    nut_length_mm: float = param(30.0, "mm", "spindle end for the bearing nut", min=5.0, max=500.0, why=_WHY_AXLE)
    lube_bore_d_mm: float = param(16.0, "mm", "axial lubrication bore from the spindle end", min=2.0,
                                  max=500.0, why=_WHY_AXLE)
    lube_cross_d_mm: float = param(8.0, "mm", "radial lubrication hole between the bearings", min=1.0,
                                   max=500.0, why=_WHY_AXLE)
    # -- hull-side envelope (for the travel sweep) ----------------------------------------------
    hull_side_z_mm: float = param(-52.0, "mm", "hull side plane (z, negative = inboard of the arm mid-plane)",
                                  max=0.0,
                                  min=-5000.0, why="an inboard offset (the lower limit: the hull's half width)")
    hull_bottom_mm: float = param(100.0, "mm", "hull bottom below the torsion axis (eq. 5: H = 0.1 m)", min=0.0,
                                  max=5000.0, why="past the hull height")
    hull_bore_d_mm: float = param(170.0, "mm", "hull bearing-housing bore around the upper axle", min=10.0,
                                  max=2000.0, why=_WHY_AXLE)
    fender_height_mm: float = param(520.0, "mm", "lowest structure over the wheels (sponson with the upper "
                                    "track run) above the torsion axis", min=0.0,
                                    max=5000.0, why="past the hull height")
    # -- sweep -----------------------------------------------------------------------------------
    sweep_steps_per_deg: float = param(1.0, "1/deg", "travel sweep steps per degree of β", min=1.0, max=20.0,
                                       why="0.05° steps resolve every clearance of the travel")
    min_clearance_mm: float = param(10.0, "mm", "least clearance accepted to hull, neighbours and own wheel",
                                    min=0.0, max=500.0, why="past the gaps a running gear has")
    sweep_chord_mm: float = param(0.1, "mm", "tessellation chord of the sweep meshes (clearance error <= 2x)",
                                  min=0.001, max=1.0, why="a coarser chord hides clearances of millimetres")
    road_wheel_file: str = param("road_wheel.toml", "", "road wheel part file (relative to this file)")

    def validate(self) -> None:
        if not isinstance(self.damped_wheels, list) or not self.damped_wheels:
            raise InputError("damped_wheels", self.damped_wheels, "must be a non-empty list of wheel numbers")
        for k in self.damped_wheels:
            if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= self.n_wheels_side:
                raise InputError("damped_wheels", self.damped_wheels,
                                 f"wheel numbers must be whole numbers 1 ... n_wheels_side = {self.n_wheels_side}")
        if len(set(self.damped_wheels)) != len(self.damped_wheels):
            raise InputError("damped_wheels", self.damped_wheels, "one damper per wheel")
        if not self.h_min_mm < self.h_max_mm:
            raise InputError("h_min_mm", self.h_min_mm, f"must be < h_max_mm = {self.h_max_mm:g}")
        z_c0 = -0.5 * self.arm_width_mm - self.upper_collar_mm
        if not -self.a1_mm + 0.5 * self.hull_bearing_B_mm <= z_c0 - self.r_upper_mm:
            raise InputError("a1_mm", self.a1_mm, f"the outer hull bearing must sit inboard of the shoulder fillet: "
                             f"a1 >= {-(z_c0 - self.r_upper_mm) + 0.5 * self.hull_bearing_B_mm:g} mm")
        if not self.a2_mm - self.a1_mm >= self.hull_bearing_B_mm + 10.0:
            raise InputError("a2_mm", self.a2_mm, f"must exceed a1 + bearing width + 10 = "
                             f"{self.a1_mm + self.hull_bearing_B_mm + 10:g} mm")
        if not self.hull_side_z_mm <= z_c0 - self.min_clearance_mm:
            raise InputError("hull_side_z_mm", self.hull_side_z_mm, f"the hull side must lie min_clearance_mm "
                             f"inboard of the upper collar face (z = {z_c0:g} mm): <= {z_c0 - self.min_clearance_mm:g}")
        if not self.hull_bore_d_mm > self.d_upper_mm + 2 * self.min_clearance_mm:
            raise InputError("hull_bore_d_mm", self.hull_bore_d_mm, f"must exceed the journal d_upper_mm + "
                             f"2 min_clearance_mm = {self.d_upper_mm + 2 * self.min_clearance_mm:g} mm")
        if not self.D_upper_mm / 2 + 5.0 <= self.upper_boss_r_mm:
            raise InputError("upper_boss_r_mm", self.upper_boss_r_mm, f"must be >= D_upper_mm/2 + 5 = "
                             f"{self.D_upper_mm / 2 + 5:g} mm")
        if not self.D_lower_mm / 2 + 5.0 <= self.lower_boss_r_mm:
            raise InputError("lower_boss_r_mm", self.lower_boss_r_mm, f"must be >= D_lower_mm/2 + 5 = "
                             f"{self.D_lower_mm / 2 + 5:g} mm")
        if not self.upper_boss_r_mm + self.lower_boss_r_mm + 2 * self.fillet_mm < self.R_b_mm:
            raise InputError("R_b_mm", self.R_b_mm, f"the arm must be longer than both bosses and fillets: "
                             f"> {self.upper_boss_r_mm + self.lower_boss_r_mm + 2 * self.fillet_mm:g} mm")
        sp = self.spline()
        if not sp.D_f_hub + 2 * 10.0 <= self.d_upper_mm - 2:
            raise InputError("spline_D_mm", self.spline_D_mm, f"the socket (major diameter {sp.D_f_hub:.3f} mm) "
                             f"needs a 10 mm wall under the relieved journal d_upper_mm − 3 = {self.d_upper_mm - 3:g} mm")
        if not self.bolt_bore_d_mm < sp.D_a_hub - 4.0:
            raise InputError("bolt_bore_d_mm", self.bolt_bore_d_mm, f"must be < the spline minor diameter − 4 = "
                             f"{sp.D_a_hub - 4:.3f} mm")
        if not self.bolt_bore_d_mm / 2 + 5.0 <= self.plug_r_mm < self.d_upper_mm / 2:
            raise InputError("plug_r_mm", self.plug_r_mm, f"must lie in [bolt bore/2 + 5, d_upper/2) = "
                             f"[{self.bolt_bore_d_mm / 2 + 5:g}, {self.d_upper_mm / 2:g}) mm")
        socket_end = self.upper_z_in + self.spline_length_mm
        if not socket_end <= z_c0 - self.r_upper_mm - 20.0:
            raise InputError("spline_length_mm", self.spline_length_mm, f"the socket must end 20 mm inboard of the "
                             f"shoulder fillet (journal from {self.upper_z_in:g} to {z_c0:g} mm)")

    # -- helpers --------------------------------------------------------------------------------
    @property
    def upper_z_in(self) -> float:
        """Inboard end of the upper axle, mm (balancer frame)."""
        return -(self.a2_mm + 0.5 * self.hull_bearing_B_mm + self.upper_end_mm)

    def spline(self):
        from ...geometry.involute_spline import InvoluteSpline

        try:
            return InvoluteSpline(self.spline_D_mm, self.spline_m_mm, self.spline_z)
        except InputError as exc:
            raise InputError({"spline_D": "spline_D_mm", "spline_m": "spline_m_mm"}.get(exc.parameter, exc.parameter),
                             exc.value, exc.limit) from None
