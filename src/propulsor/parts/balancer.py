"""Suspension balancer of the 50 t tracked carrier (seed 004, ch. 2 and 8; SPEC §5).

Wires the parameters to the library:

* the torsion-bar suspension calculation of seed 004 ch. 2, eq. 1-28
  (:mod:`propulsor.laws.suspension`): twist angles, balancer angles, travel f(β) (eq. 11),
  elastic characteristic P(β) (eq. 13), specific potential energy (eq. 15-16), c' (eq. 20/24),
  damper coefficients and forces (eq. 19-28), compared with every printed number;
* the balancer as a beam with its load cases (wheel force at β_m, damper force E, stop) and an
  equal-strength depth (:mod:`propulsor.laws.balancer_beam`), checked on the *built* outline at
  every station, the axle–arm shoulder fillets with Peterson's K_t, and the seed's FE figures
  (§8.3: ~300 MPa body, 724 MPa singular point);
* the solid: arm plate (side outline around the equal-strength depth with the damper ear and the
  stop pad, :mod:`propulsor.geometry.arm_outline`), upper axle (hull-bearing journal, involute
  spline socket for the torsion bar, GOST 6033-80 :mod:`propulsor.geometry.involute_spline`,
  retaining-bolt bore and its boss), lower axle (road-wheel spindle with the bearing seats of
  ``road_wheel.toml`` and a lubrication bore);
* a travel sweep β0 … β_m with the road wheel mounted, manifold3d booleans against a hull-side
  envelope and the neighbouring stations, with the minimum clearance and where it occurs.

Frame of the balancer (mm): origin on the upper-axle axis in the arm's mid-plane; x along the arm
to the wheel axis (|x| = R_b); y across the arm, positive the way the wheel force turns it; z along
the axles, outboard positive.  World frame of the sweep: x forward, y up, z outboard; the balancer
at angle β (from the downward vertical, seed 004 eq. 5) is the balancer frame turned about z by
β − 90°, so the wheel axis sits at (R_b sin β, −R_b cos β).

Readings taken where the seed is inconsistent (also in the report):
* damper lever ratio (eq. 28): i = L_a / R_b = 0.453 ("lever"): ear at 163 mm, rod force =
  wheel force / i; the only reading that gives the printed piston D_p = 0.11 m.  The literal
  reading puts the ear at 795 mm, beyond the 360 mm balancer, and is refused.
* [τ] = 1600 MPa and L_T = 2000 mm (not printed) reproduce γ_m = 96.043°; γ_st then comes out
  24.348° against the printed 24.358°, and only γ_st < 24.355° reproduces the printed
  c' = 2.138e5 N/m with the printed λ = 0.822 m: the seed's last digits disagree.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..parallel import start as start_in_fork
from ..check import Check
from ..errors import InputError
from ..params import load_params, param, read_part_file
from . import PartType

__all__ = ["BalancerParams", "BalancerModel", "resolve", "PART_TYPE", "build"]

RHO_STEEL_KG_MM3 = 7.85e-6
#: the arm edges are B-splines within this of the smoothed edge y(x) (its requirement has a 1 mm margin)
OUTLINE_FIT_TOL_MM = 1e-4

#: numbers printed in seed 004 ch. 2 (the acceptance data of issue 5)
THESIS = {
    "gamma_m_deg": 96.043, "gamma_st_deg": 24.358, "beta0_deg": 19.0, "beta_m_deg": 115.0,
    "f_st_m": 0.078, "f_full_m": 0.492, "f_dyn_m": 0.414, "d_T_m": 0.046, "lambda_m": 0.822,
    "lambda_ut_m": 0.822, "c_prime_N_per_m": 2.138e5, "c_N_per_m": 164400.0, "mu_mean": 3.426e4,
    "mu_reb_max": 5.229e4, "mu_reb": 4.031e4, "mu_comp": 28220.0, "T_phi_s": 1.8,
    "R_k_comp_max_N": 2.134e4, "D_piston_m": 0.11,
}

# library parameter name -> part-file parameter name (error messages name the part file's keys)
_RENAME = {
    "P_st": "P_st_N", "R_b": "R_b_mm", "d_T": "d_T_mm", "L_T": "L_T_mm", "tau_max": "tau_max_MPa",
    "G": "G_MPa", "G_p": "G_p_N", "T_phi": "T_phi_s", "p_max": "p_max_MPa", "d_rod": "d_rod_mm",
    "b": "arm_width_mm", "h": "h_ref_mm", "s_stop": "s_stop_mm", "a1": "a1_mm", "a2": "a2_mm",
    "d_upper": "d_upper_mm", "D_upper": "D_upper_mm", "r_upper": "r_upper_mm", "D_lower": "D_lower_mm",
    "r_lower": "r_lower_mm", "h_min": "h_min_mm", "h_max": "h_max_mm", "sigma_yield": "yield_MPa",
    "d_lower": "bearing_inner_d_mm (road wheel)", "e_w": "row_offset_mm (road wheel)",
    "n_side": "n_wheels_side", "base_m": "base_m", "wheel_x_m": "n_wheels_side", "damper_x_m": "damped_wheels",
}


def _renamed(exc: InputError) -> InputError:
    name = _RENAME.get(exc.parameter, exc.parameter)
    return InputError(name, exc.value, exc.limit)


@dataclass
class BalancerParams:
    """Parameters of the suspension balancer (seed 004 ch. 2 and 8)."""

    # -- torsion-bar suspension, seed 004 ch. 2 ------------------------------------------------
    P_st_N: float = param(31490.0, "N", "static wheel load P_st (eq. 3)", min=0.0, min_exclusive=True)
    R_b_mm: float = param(360.0, "mm", "balancer arm R_б: upper-axle axis to wheel axis", min=50.0, max=2000.0)
    beta_st_deg: float = param(43.144, "deg", "static balancer angle from the downward vertical (eq. 5)",
                               min=0.0, max=180.0, min_exclusive=True, max_exclusive=True)
    d_T_mm: float = param(46.0, "mm", "torsion bar diameter d_T (eq. 6)", min=5.0, max=200.0)
    L_T_mm: float = param(2000.0, "mm", "torsion bar working length L_T (not printed; hull width)", min=100.0)
    tau_max_MPa: float = param(1600.0, "MPa", "allowed torsion bar shear [τ]max (seed: 1100 ... 1600)",
                               min=100.0, max=2500.0)
    G_MPa: float = param(83000.0, "MPa", "shear modulus of the bar G", min=1000.0)
    beta0_deg: float = param(0.0, "deg", "adopted mounting angle β0 (0: eq. 9, β_st − γ_st)", min=0.0, max=180.0)
    beta_m_deg: float = param(0.0, "deg", "adopted full-travel angle β_m (0: eq. 10, β0 + γ_m)", min=0.0, max=180.0)
    G_p_N: float = param(473000.0, "N", "sprung weight G_п (eq. 2)", min=0.0, min_exclusive=True)
    I_y_kgm2: float = param(421100.0, "kg m^2", "body pitch inertia I_y (eq. 2)", min=0.0, min_exclusive=True)
    n_wheels_side: int = param(8, "", "road wheels per side (assumed equally spaced over the base)", min=2,
                               max=20, integer=True)
    base_m: float = param(6.846, "m", "first-to-last wheel base (seed Table 11)", min=0.5, max=30.0)
    damped_wheels: list = param([1, 2, 7, 8], "", "wheels with dampers, numbered from the front (n_a = 4)")
    T_phi_s: float = param(1.8, "s", "design pitch period T_φ (eq. 1; 0.5 ... 1.8)", min=0.1, max=10.0)
    nu: float = param(13.5, "", "pitch amplitude ratio per period ν (10 ... 17)", min=1.0, min_exclusive=True)
    reb_factor: float = param(0.85, "", "μ_reb = μ_mean / reb_factor (0.8 ... 0.9)", min=0.0, max=1.0,
                              min_exclusive=True)
    h_n_m: float = param(0.05, "m", "bump height h_н (eq. 27)", min=0.0, min_exclusive=True)
    zdd_over_g: float = param(0.5, "", "allowed shake acceleration / g (eq. 27)", min=0.0, min_exclusive=True)
    i_a: float = param(0.453, "", "damper–wheel ratio i (eq. 28)", min=0.01, max=10.0)
    damper_reading: str = param("lever", "", "reading of i: lever = L_a/R_b (ear at i·R_b); literal = R_b/L_a",
                                choices=["lever", "literal"])
    p_max_MPa: float = param(20.0, "MPa", "largest damper pressure", min=0.1)
    d_rod_mm: float = param(40.0, "mm", "damper rod diameter", min=0.0)
    # -- strength ----------------------------------------------------------------------------
    yield_MPa: float = param(930.0, "MPa", "yield of 40ХН2МА after quench 850 °C and temper (seed §8.3)", min=100.0)
    safety: float = param(1.5, "", "required safety factor on yield (allowable = yield / safety)", min=1.0)
    k_stop: float = param(2.0, "", "stop load = k_stop · P(β_m) (ours; the seed gives none)", min=1.0, max=10.0)
    n_stations: int = param(360, "", "beam stations along the arm", min=10, max=5000, integer=True)
    # -- arm plate -----------------------------------------------------------------------------
    arm_width_mm: float = param(60.0, "mm", "arm (plate) width b along the axles", min=10.0, max=300.0)
    h_ref_mm: float = param(120.0, "mm", "depth of the constant-section reference arm (FE comparison)", min=10.0)
    h_min_mm: float = param(40.0, "mm", "least manufacturable arm depth", min=5.0)
    h_max_mm: float = param(400.0, "mm", "largest arm depth searched", min=10.0)
    depth_margin_mm: float = param(1.0, "mm", "added to the equal-strength half depth", min=0.0, max=50.0)
    smoothing_mm: float = param(20.0, "mm", "half width of the outline's smoothing window", min=1.0, max=100.0)
    fillet_mm: float = param(15.0, "mm", "in-plane fillet between arm edges and bosses", min=1.0, max=100.0)
    upper_boss_r_mm: float = param(90.0, "mm", "radius of the plate boss at the upper axle", min=10.0)
    lower_boss_r_mm: float = param(80.0, "mm", "radius of the plate boss at the wheel spindle", min=10.0)
    s_stop_mm: float = param(230.0, "mm", "stop-pad station along the arm", min=0.0, min_exclusive=True)
    stop_pad_length_mm: float = param(50.0, "mm", "length of the flat stop pad", min=5.0)
    stop_pad_height_mm: float = param(20.0, "mm", "height of the stop pad over the arm edge", min=2.0)
    ear_pin_d_mm: float = param(40.0, "mm", "damper ear pin diameter", min=5.0)
    ear_wall_mm: float = param(20.0, "mm", "wall around the ear pin hole", min=3.0)
    ear_ligament_mm: float = param(5.0, "mm", "ligament between the pin hole and the arm's core", min=0.0)
    # -- upper axle (hull bearings, torsion-bar socket) -------------------------------------------
    d_upper_mm: float = param(120.0, "mm", "upper axle journal (hull bearing seats)", min=20.0)
    D_upper_mm: float = param(160.0, "mm", "shoulder (collar) at the arm", min=25.0)
    r_upper_mm: float = param(8.0, "mm", "shoulder fillet radius", min=0.5)
    upper_collar_mm: float = param(10.0, "mm", "collar length inboard of the arm face", min=2.0)
    a1_mm: float = param(70.0, "mm", "outer hull bearing centre, inboard of the arm mid-plane", min=0.0,
                         min_exclusive=True)
    a2_mm: float = param(200.0, "mm", "inner hull bearing centre", min=0.0, min_exclusive=True)
    hull_bearing_B_mm: float = param(40.0, "mm", "hull bearing width (seat length)", min=5.0)
    upper_end_mm: float = param(20.0, "mm", "journal beyond the inner bearing", min=0.0)
    spline_D_mm: float = param(65.0, "mm", "torsion-bar spline, nominal diameter D (GOST 6033-80)", min=10.0)
    spline_m_mm: float = param(2.0, "mm", "spline module m", min=0.5, max=10.0)
    spline_z: int = param(31, "", "spline teeth z", min=6, max=200, integer=True)
    spline_length_mm: float = param(120.0, "mm", "spline engagement length l", min=5.0)
    spline_n: float = param(1.4, "", "crushing safety n (GOST 21425; seed §4.3: 1.4)", min=1.0)
    spline_K_sum: float = param(3.71, "", "load concentration K_Σ (seed §4.3: 1 × 2.65 × 1.4)", min=1.0)
    bolt_bore_d_mm: float = param(22.0, "mm", "torsion-bar retaining-bolt bore through the upper axle", min=2.0)
    plug_r_mm: float = param(30.0, "mm", "radius of the bolt boss on the outboard face", min=2.0)
    plug_length_mm: float = param(40.0, "mm", "bolt boss length outboard of the arm face", min=0.0)
    # -- lower axle (road-wheel spindle) -------------------------------------------------------
    D_lower_mm: float = param(140.0, "mm", "spindle shoulder (collar) at the arm", min=20.0)
    r_lower_mm: float = param(8.0, "mm", "spindle shoulder fillet radius", min=0.5)
    lower_collar_mm: float = param(10.0, "mm", "collar length outboard of the arm face", min=2.0)
    nut_length_mm: float = param(30.0, "mm", "spindle end for the bearing nut", min=5.0)
    lube_bore_d_mm: float = param(16.0, "mm", "axial lubrication bore from the spindle end", min=2.0)
    lube_cross_d_mm: float = param(8.0, "mm", "radial lubrication hole between the bearings", min=1.0)
    # -- hull-side envelope (for the travel sweep) ----------------------------------------------
    hull_side_z_mm: float = param(-52.0, "mm", "hull side plane (z, negative = inboard of the arm mid-plane)",
                                  max=0.0)
    hull_bottom_mm: float = param(100.0, "mm", "hull bottom below the torsion axis (eq. 5: H = 0.1 m)", min=0.0)
    hull_bore_d_mm: float = param(170.0, "mm", "hull bearing-housing bore around the upper axle", min=10.0)
    fender_height_mm: float = param(520.0, "mm", "lowest structure over the wheels (sponson with the upper "
                                    "track run) above the torsion axis", min=0.0)
    # -- sweep -----------------------------------------------------------------------------------
    sweep_steps_per_deg: float = param(1.0, "1/deg", "travel sweep steps per degree of β", min=1.0, max=20.0)
    min_clearance_mm: float = param(10.0, "mm", "least clearance accepted to hull, neighbours and own wheel",
                                    min=0.0)
    sweep_chord_mm: float = param(0.1, "mm", "tessellation chord of the sweep meshes (clearance error <= 2x)",
                                  min=0.001, max=1.0)
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
        suspension_design(self)
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
        from ..geometry.involute_spline import InvoluteSpline

        try:
            return InvoluteSpline(self.spline_D_mm, self.spline_m_mm, self.spline_z)
        except InputError as exc:
            raise InputError({"spline_D": "spline_D_mm", "spline_m": "spline_m_mm"}.get(exc.parameter, exc.parameter),
                             exc.value, exc.limit) from None


def suspension_design(p: BalancerParams):
    """The seed's suspension (library objects) for these parameters; InputError names the part-file key."""
    from ..laws.suspension import SuspensionDesign, TorsionSuspension, uniform_wheel_positions

    try:
        tor = TorsionSuspension(P_st=p.P_st_N, R_b=p.R_b_mm, beta_st_deg=p.beta_st_deg, d_T=p.d_T_mm, L_T=p.L_T_mm,
                                tau_max=p.tau_max_MPa, G=p.G_MPa, beta0_deg=p.beta0_deg or None,
                                beta_m_deg=p.beta_m_deg or None)
        xs = uniform_wheel_positions(p.n_wheels_side, p.base_m)
        damped = tuple(xs[k - 1] for k in sorted(set(p.damped_wheels))
                       if isinstance(k, int) and 1 <= k <= p.n_wheels_side)
        return SuspensionDesign(torsion=tor, G_p=p.G_p_N, I_y_kgm2=p.I_y_kgm2, wheel_x_m=xs, damper_x_m=damped,
                                T_phi=p.T_phi_s, nu=p.nu, reb_factor=p.reb_factor, h_n_m=p.h_n_m,
                                zdd_over_g=p.zdd_over_g, i_a=p.i_a, damper_reading=p.damper_reading,
                                p_max=p.p_max_MPa, d_rod=p.d_rod_mm)
    except InputError as exc:
        raise _renamed(exc) from None


# ------------------------------------------------------------------------------------------------
# the model: every derived dimension, resolved before anything is written
# ------------------------------------------------------------------------------------------------
@dataclass
class BalancerModel:
    p: BalancerParams
    design: object  # SuspensionDesign
    wheel_p: object  # RoadWheelParams
    wheel: object  # WheelModel
    wheel_file: Path
    geom: object  # BalancerGeometry
    analysis: object  # BalancerAnalysis
    spline: object  # InvoluteSpline
    z_hub: float  # wheel hub inboard face (balancer frame)
    e_w: float  # wheel mid-plane
    L_a: float  # damper ear station
    pitch: float  # station pitch
    outline: object = None  # ArmOutline
    ear: tuple = ()  # (x, y, r_pin, r_ear)
    pad: tuple = ()  # (x0, x1, y)
    extras: dict = field(default_factory=dict)

    @property
    def tor(self):
        return self.design.torsion


def _wheel_inputs(p: BalancerParams, source: Path | None):
    from ..solids.road_wheel import wheel_model
    from . import get_part_type

    RoadWheelParams = get_part_type("road_wheel").params_cls

    base = Path(source).resolve().parent if source is not None else Path.cwd()
    f = Path(p.road_wheel_file)
    f = f if f.is_absolute() else base / f
    if not f.is_file():
        raise InputError("road_wheel_file", p.road_wheel_file, f"does not exist (looked for {f})")
    typ, mapping = read_part_file(f)
    if typ != "road_wheel":
        raise InputError("road_wheel_file", p.road_wheel_file, f"names part type {typ!r}, not 'road_wheel'")
    try:
        wp = load_params(RoadWheelParams, mapping)
    except InputError as exc:
        raise InputError(f"{exc.parameter} (in {f.name})", exc.value, exc.limit) from None
    return f, wp, wheel_model(wp)


def resolve(p: BalancerParams, source: Path | None = None) -> BalancerModel:
    """Everything the build needs, or InputError (nothing is written before this returns)."""
    from ..laws.balancer_beam import BalancerAnalysis, BalancerGeometry

    design = suspension_design(p)
    f, wp, wm = _wheel_inputs(p, source)
    b = p.arm_width_mm
    z_hub = 0.5 * b + p.lower_collar_mm
    e_w = z_hub + wm.z_mid
    z_wheel_in = z_hub + wm.z_inboard
    if not wp.bearing_inner_d_mm + 2 * 5.0 <= p.D_lower_mm:
        raise InputError("D_lower_mm", p.D_lower_mm, f"the spindle collar must exceed the inner bearing bore "
                         f"{wp.bearing_inner_d_mm:g} mm (road wheel) by 10 mm")
    if not p.D_lower_mm / 2 + p.min_clearance_mm <= wp.bearing_inner_D_mm / 2:
        raise InputError("D_lower_mm", p.D_lower_mm, f"the collar must stay min_clearance_mm inside the wheel hub's "
                         f"seat (D = {wp.bearing_inner_D_mm:g} mm): <= {wp.bearing_inner_D_mm - 2 * p.min_clearance_mm:g}")
    if not wp.bearing_outer_d_mm < wp.bearing_inner_d_mm:
        raise InputError("bearing_outer_d_mm (road wheel)", wp.bearing_outer_d_mm,
                         f"the outboard bearing must be smaller than the inboard one ({wp.bearing_inner_d_mm:g} mm): "
                         "the bearings slide on from the spindle end")
    # the wheel must clear the arm plate axially, and the bolt boss on the upper axis radially
    if not z_wheel_in >= 0.5 * b + p.min_clearance_mm:
        raise InputError("lower_collar_mm", p.lower_collar_mm, f"the wheel's inboard face (z = {z_wheel_in:g} mm) "
                         f"must lie min_clearance_mm outboard of the arm face z = {0.5 * b:g} mm")
    plug_end = 0.5 * b + p.plug_length_mm
    if plug_end > z_wheel_in - p.min_clearance_mm:
        gap = p.R_b_mm - wm.r_tyre - p.plug_r_mm
        if gap < p.min_clearance_mm:
            raise InputError("R_b_mm", p.R_b_mm, f"arm shorter than the wheel radius allows: the tyre (R = "
                             f"{wm.r_tyre:g} mm) passes the bolt boss on the upper axis (r = {p.plug_r_mm:g} mm, "
                             f"reaching z = {plug_end:g} mm into the wheel) at R_b − R − r = {gap:g} mm; need "
                             f">= {wm.r_tyre + p.plug_r_mm + p.min_clearance_mm:g} mm (or a shorter boss)")
    try:
        geom = BalancerGeometry(b=b, h=p.h_ref_mm, e_w=e_w, e_a=0.0, s_stop=p.s_stop_mm, a1=p.a1_mm, a2=p.a2_mm,
                                d_upper=p.d_upper_mm, D_upper=p.D_upper_mm, r_upper=p.r_upper_mm,
                                d_lower=wp.bearing_inner_d_mm, D_lower=p.D_lower_mm, r_lower=p.r_lower_mm,
                                h_min=p.h_min_mm, h_max=p.h_max_mm, d_upper_bore=p.bolt_bore_d_mm)
        an = BalancerAnalysis(design, geom, k_stop=p.k_stop, sigma_yield=p.yield_MPa, safety=p.safety,
                              n_stations=p.n_stations)
        an.cases  # noqa: B018  (raises for a damper ear beyond the balancer, a stop off the arm)
        for row in an.transitions():  # Peterson ranges
            pass
    except InputError as exc:
        raise _renamed(exc) from None
    L_a = design.L_a
    if not p.upper_boss_r_mm < L_a < p.R_b_mm - p.lower_boss_r_mm:
        raise InputError("i_a", p.i_a, f"the damper ear (L_a = {L_a:.4g} mm, reading '{p.damper_reading}') must sit "
                         f"on the arm between the bosses ({p.upper_boss_r_mm:g} ... {p.R_b_mm - p.lower_boss_r_mm:g} mm)")
    x0, x1 = p.s_stop_mm - 0.5 * p.stop_pad_length_mm, p.s_stop_mm + 0.5 * p.stop_pad_length_mm
    if not (x0 - p.smoothing_mm > p.upper_boss_r_mm and x1 + p.smoothing_mm < p.R_b_mm - p.lower_boss_r_mm):
        raise InputError("s_stop_mm", p.s_stop_mm, f"the stop pad with its blends (±{p.smoothing_mm:g} mm) must lie "
                         f"between the bosses ({p.upper_boss_r_mm:g} ... {p.R_b_mm - p.lower_boss_r_mm:g} mm)")
    if not p.stop_pad_length_mm > 2 * p.smoothing_mm:
        raise InputError("stop_pad_length_mm", p.stop_pad_length_mm, f"must exceed 2 × smoothing_mm = "
                         f"{2 * p.smoothing_mm:g} mm (flat face)")
    n = p.n_wheels_side
    m = BalancerModel(p, design, wp, wm, f, geom, an, p.spline(), z_hub, e_w, L_a, 1000.0 * p.base_m / (n - 1))
    m.outline = _outline(m)
    return m


def _outline(m: BalancerModel):
    """Arm side outline around the equal-strength depth, with the damper ear and the stop pad."""
    from ..geometry.arm_outline import arm_outline, smooth_majorant

    p, an = m.p, m.analysis
    h_eq = an.envelope_depth()
    m.extras["h_eq"] = h_eq
    ds = 1.0
    grid = np.arange(-p.upper_boss_r_mm - 20.0, p.R_b_mm + p.lower_boss_r_mm + 20.0 + ds, ds)
    s = np.append(an.s, p.R_b_mm)
    hh = np.append(h_eq, h_eq[-1])
    req = 0.5 * np.interp(grid, s, hh) + p.depth_margin_mm
    core = smooth_majorant(req, ds, p.smoothing_mm)
    r_pin = 0.5 * p.ear_pin_d_mm
    r_ear = r_pin + p.ear_wall_mm
    y_e = float(np.interp(m.L_a, grid, core)) + p.ear_ligament_mm + r_pin
    x0, x1 = p.s_stop_mm - 0.5 * p.stop_pad_length_mm, p.s_stop_mm + 0.5 * p.stop_pad_length_mm
    win = (grid >= x0 - 2 * p.smoothing_mm) & (grid <= x1 + 2 * p.smoothing_mm)
    y_pad = float(core[win].max()) + p.stop_pad_height_mm
    m.ear = (m.L_a, y_e, r_pin, r_ear)
    m.pad = (x0, x1, y_pad)
    try:
        return arm_outline(p.R_b_mm, p.upper_boss_r_mm, p.lower_boss_r_mm, grid, req, req, p.fillet_mm,
                           p.smoothing_mm, circles=[(m.L_a, y_e, r_ear)], plateaus=[(x0, x1, y_pad)],
                           holes=[(m.L_a, y_e, r_pin)], tol=OUTLINE_FIT_TOL_MM)
    except InputError as exc:
        raise InputError("arm_width_mm", p.arm_width_mm, f"the arm outline cannot be drawn ({exc}); the "
                         "equal-strength depth may exceed a boss: widen the arm or enlarge the bosses") from None


# ------------------------------------------------------------------------------------------------
# solids
# ------------------------------------------------------------------------------------------------
def _upper_section(m: BalancerModel):
    """Half section (x = r, y = z) of the upper axle, solid to the axis (bores are cut later)."""
    from ..geometry.profile import Arc, Line, Loop, Profile

    p = m.p
    b = p.arm_width_mm
    rj, Rc, rf = 0.5 * p.d_upper_mm, 0.5 * p.D_upper_mm, p.r_upper_mm
    z_in, z_c0 = p.upper_z_in, -0.5 * b - p.upper_collar_mm
    z_emb, z_p0, z_p1 = -0.5 * b + 5.0, 0.5 * b - 5.0, 0.5 * b + p.plug_length_mm
    B = p.hull_bearing_B_mm
    s1 = (-p.a1_mm - 0.5 * B, -p.a1_mm + 0.5 * B)
    s2 = (-p.a2_mm - 0.5 * B, -p.a2_mm + 0.5 * B)
    rr = rj - 1.5  # relief between the seats
    pts = [(0.0, z_in), (rj, z_in), (rj, s2[1]), (rr, s2[1] + 1.5), (rr, s1[0] - 1.5), (rj, s1[0]),
           (rj, z_c0 - rf)]
    segs = [Line(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    segs.append(Arc((rj + rf, z_c0 - rf), rf, math.pi, math.pi / 2))  # fillet, concave corner
    pts2 = [(rj + rf, z_c0), (Rc, z_c0), (Rc, z_emb), (rj, z_emb), (rj, z_p0), (p.plug_r_mm, z_p0),
            (p.plug_r_mm, z_p1), (0.0, z_p1), (0.0, z_in)]
    if p.plug_length_mm <= 0:
        pts2 = [(rj + rf, z_c0), (Rc, z_c0), (Rc, z_emb), (rj, z_emb), (rj, z_p0), (0.0, z_p0), (0.0, z_in)]
    segs += [Line(pts2[i], pts2[i + 1]) for i in range(len(pts2) - 1)]
    return Profile(Loop(segs), name="upper_axle")


def _spindle_section(m: BalancerModel):
    """Half section of the wheel spindle with the seats of the road wheel's bearings and the lube bore."""
    from ..geometry.profile import Arc, Line, Loop, Profile

    p, wp = m.p, m.wheel_p
    b = p.arm_width_mm
    Rc, rf = 0.5 * p.D_lower_mm, p.r_lower_mm
    r1, r2 = 0.5 * wp.bearing_inner_d_mm, 0.5 * wp.bearing_outer_d_mm
    z0, zb1 = 0.5 * b - 5.0, m.z_hub
    L = wp.hub_length_mm
    s1 = (zb1, zb1 + wp.bearing_inner_B_mm)
    s2 = (zb1 + L - wp.bearing_outer_B_mm, zb1 + L)
    rr = r2 + 2.0  # relief between the seats
    rn = r2 - 4.0  # nut zone
    z_end = s2[1] + p.nut_length_mm
    rl = 0.5 * p.lube_bore_d_mm
    z_cross = 0.5 * (s1[1] + s2[0])
    z_lb = z_cross - 0.5 * p.lube_cross_d_mm - 2.0
    tip = rl * math.tan(math.radians(31.0))  # 118° drill point
    segs = [Line((0.0, z0), (Rc, z0)), Line((Rc, z0), (Rc, zb1)), Line((Rc, zb1), (r1 + rf, zb1)),
            Arc((r1 + rf, zb1 + rf), rf, -math.pi / 2, -math.pi)]
    pts = [(r1, zb1 + rf), (r1, s1[1]), (rr, s1[1] + (r1 - rr)), (rr, s2[0] - (rr - r2)), (r2, s2[0]),
           (r2, s2[1]), (rn, s2[1] + (r2 - rn)), (rn, z_end), (rl, z_end), (rl, z_lb), (0.0, z_lb - tip),
           (0.0, z0)]
    segs += [Line(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    m.extras.update({"spindle_seat_1": s1, "spindle_seat_2": s2, "spindle_end": z_end, "z_cross": z_cross,
                     "spindle_relief_r": rr})
    return Profile(Loop(segs), name="spindle")


def balancer_solid(m: BalancerModel):
    """The balancer as one solid (plate ∪ upper axle ∪ spindle, minus socket, bolt bore, cross hole)."""
    from ..geometry.profile import Profile
    from ..solids.build import extrude_profile
    from ..solids.kernel import cut, cylinder, fuse, moved
    from ..solids.revolve import revolve_section

    p = m.p
    b = p.arm_width_mm
    plate = moved(extrude_profile(m.outline.profile, b), dz=-0.5 * b)
    upper = revolve_section(_upper_section(m))
    spindle = revolve_section(_spindle_section(m), center=(p.R_b_mm, 0.0))
    body = fuse(plate, upper, spindle, name="balancer body")
    z_in = p.upper_z_in
    socket = moved(extrude_profile(Profile(m.spline.hub_hole_loop()), p.spline_length_mm + 1.0), dz=z_in - 1.0)
    z_top = 0.5 * b + max(p.plug_length_mm, 0.0)
    bolt = cylinder(0.5 * p.bolt_bore_d_mm, z_in + p.spline_length_mm - 1.0, z_top + 1.0)
    cross = cylinder(0.5 * p.lube_cross_d_mm, 0.0, m.extras["spindle_relief_r"] + 2.0,
                     center=(p.R_b_mm, m.extras["z_cross"]), axis="y")
    return cut(body, socket, bolt, cross, name="balancer bores")


# ------------------------------------------------------------------------------------------------
# travel sweep
# ------------------------------------------------------------------------------------------------
def _rz(theta: float, t=(0.0, 0.0, 0.0)) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:3, 3] = t
    return T


def sweep_mesh(solid, chord):
    """(vertices, faces) of a solid at the sweep's chord (single-threaded BRepMesh)."""
    from ..solids.tessellate import triangulate

    V, F, _ = triangulate(solid, chord, 0.2, parallel=False)
    return V, F


def hull_envelope(m: BalancerModel):
    """manifold3d solid of the hull-side envelope (world frame): the side plate (plane z = hull_side_z_mm,
    30 mm thick) with the bearing-housing bore, the bottom plate inboard of it (hull_bottom_mm below the
    torsion axis) and the fender / sponson slab over the wheels (fender_height_mm above the axis)."""
    from ..solids.kernel import manifold_cube, manifold_cylinder

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


def _box_of(corners: np.ndarray, T: np.ndarray):
    q = corners @ T.T
    return q[:, :3].min(axis=0), q[:, :3].max(axis=0)


def _box_gap(a, b) -> float:
    """Distance between two axis-aligned boxes (0 when they overlap)."""
    d = np.maximum(0.0, np.maximum(a[0] - b[1], b[0] - a[1]))
    return float(np.linalg.norm(d))


def _gap(A, B, w0: float) -> float:
    """Exact least distance (manifold3d min_gap) with a search window doubled from w0 until it holds the gap."""
    w = float(w0)
    while True:
        g = float(A.min_gap(B, w))
        if g < w or w >= SWEEP_GAP_MAX_MM:
            return g
        w *= 2.0


def travel_sweep(m: BalancerModel, bal_mesh, wheel_meshes) -> dict:
    """Balancer with its wheel from β0 to β_m against the hull envelope and both neighbours.

    Every step: intersection volume and min_gap with the search window W = max(2 min_clearance, 20 mm)
    (a gap >= W is recorded as W, capped).  A pair capped at every step is searched further at
    selected steps with a growing window, so that its least gap is still exact."""
    from ..checks.proximity import nearest_points
    from ..solids.kernel import manifold

    p, tor = m.p, m.tor
    n = int(math.ceil(math.degrees(tor.beta_m - tor.beta0) * p.sweep_steps_per_deg)) + 1
    betas = np.linspace(tor.beta0, tor.beta_m, n)
    wheel_T = _rz(0.0, (p.R_b_mm, 0.0, m.z_hub))
    mb = manifold(*bal_mesh)
    mw = [manifold(*wm).transform(np.ascontiguousarray(wheel_T[:3])) for wm in wheel_meshes]
    wheel_all = mw[0]
    for x in mw[1:]:
        wheel_all = wheel_all + x
    unit = mb + wheel_all
    hull = hull_envelope(m)
    W = max(2.0 * p.min_clearance_mm, 20.0)
    bb = unit.bounding_box()
    corners = np.array([[x, y, z, 1.0] for x in (bb[0], bb[3]) for y in (bb[1], bb[4]) for z in (bb[2], bb[5])])
    hb = hull.bounding_box()
    hull_box = (np.array(hb[:3]), np.array(hb[3:]))
    import time as _time

    clock = _time.perf_counter
    t0 = clock()
    res = {"beta": betas, "pairs": {}, "window_mm": W, "timing_s": {}}
    own_vol = float((mb ^ wheel_all).volume())
    own_gap = _gap(mb, wheel_all, W)
    res["own"] = (own_vol, own_gap)

    def pose_a(k):
        return unit.transform(np.ascontiguousarray(_rz(betas[k] - math.pi / 2)[:3]))

    targets = {"hull": None, "front": m.pitch, "rear": -m.pitch}
    res["timing_s"]["setup"] = clock() - t0
    for name, off in targets.items():
        t0 = clock()
        vol, gap = np.zeros(n), np.zeros(n)
        nb, cdist = np.full(n, np.nan), np.full(n, np.nan)
        if off is not None:
            nb, cdist = _neighbour_angles(m, betas, off)

        def pose_b(k):
            if off is None:
                return hull
            return unit.transform(np.ascontiguousarray(_rz(nb[k] - math.pi / 2, (off, 0.0, 0.0))[:3]))

        for k in range(n):
            # bodies whose (conservative) boxes stay W apart neither overlap nor come within W: skip the booleans
            Ta = _rz(betas[k] - math.pi / 2)
            bx_a = _box_of(corners, Ta)
            bx_b = hull_box if off is None else _box_of(corners, _rz(nb[k] - math.pi / 2, (off, 0.0, 0.0)))
            if _box_gap(bx_a, bx_b) >= W:
                vol[k], gap[k] = 0.0, W
                continue
            A, B = pose_a(k), pose_b(k)
            vol[k] = (A ^ B).volume()
            gap[k] = A.min_gap(B, W)
        res["timing_s"][f"{name}_steps"] = clock() - t0
        t0 = clock()
        capped = gap >= W - 1e-9
        exact = {}
        if capped.all():
            # search on at selected steps: evenly spread, and for a neighbour around the step where the two
            # wheel axes come closest.  For a neighbour the wheel-to-wheel gap (axis distance − 2 R_tyre)
            # bounds the gap from above, so one min_gap call with that window is exact; the hull's window grows.
            cand = np.linspace(0, n - 1, min(n, 13)).round().astype(int).tolist()
            if off is not None:
                ka = int(np.argmin(cdist))
                near = list(range(max(0, ka - 2), min(n, ka + 3)))
                for k in near:  # closest wheel axes first: the least gap found bounds every later window
                    exact[k] = float(pose_a(k).min_gap(pose_b(k), cdist[k] - 2.0 * m.wheel.r_tyre + 1.0))
                g_min = min(exact.values())
                for k in cand:
                    if k not in exact:
                        exact[k] = float(pose_a(k).min_gap(
                            pose_b(k), min(cdist[k] - 2.0 * m.wheel.r_tyre, g_min) + 1.0))
            else:
                for k in cand:
                    exact[k] = _gap(pose_a(k), pose_b(k), W)
            for k, g in exact.items():
                gap[k] = g
            k = min(exact, key=exact.get)
        else:
            k = int(np.argmin(gap))
        # steps searched with a window that did not reach (>= window) stay lower bounds
        lower = capped.copy()
        for kk, g in exact.items():
            lower[kk] = off is not None and kk not in near and g >= min(cdist[kk] - 2.0 * m.wheel.r_tyre, g_min) + 1.0 - 1e-9
        dd = {"overlap_mm3": vol, "gap_mm": gap, "capped": lower,
              "neighbour_beta": nb, "axis_distance_mm": cdist, "worst_step": k, "searched_steps": sorted(exact)}
        res["timing_s"][f"{name}_search"] = clock() - t0
        t0 = clock()
        dist, pa, pb = nearest_points(pose_a(k), pose_b(k), float(gap[k]) + 2.0)
        dd["where"] = (pa, pb, dist)
        dd["what"] = _which(m, pa, betas[k], bal_mesh, wheel_meshes)
        res["pairs"][name] = dd
        res["timing_s"][f"{name}_where"] = clock() - t0
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
    best, name = math.inf, "?"
    d = cKDTree(bal_mesh[0]).query(q)[0]
    if d < best:
        best, name = d, "balancer"
    qw = q - np.array([m.p.R_b_mm, 0.0, m.z_hub])
    for nm, (V, F) in zip(m.extras.get("wheel_names", []), wheel_meshes):
        d = cKDTree(V).query(qw)[0]
        if d < best:
            best, name = d, f"wheel {nm}"
    return name


def _sweep_job(m: BalancerModel, bal_mesh, wheel_meshes):
    return travel_sweep(m, bal_mesh, wheel_meshes)


# ------------------------------------------------------------------------------------------------
# reporting helpers
# ------------------------------------------------------------------------------------------------
def _suspension_rows(m: BalancerModel) -> list:
    """Quantity, symbol, equation, computed, unit, printed, note."""
    from ..laws.suspension import equivalent_stiffness, pitch_period

    d, t = m.design, m.tor
    T = THESIS
    c_pr = equivalent_stiffness(T["lambda_ut_m"], t.P_st, t.f_full / 1000.0)
    rows = [
        ("torsion bar diameter for the dynamic travel", "d_T_dyn", "6", t.d_T_dyn / 1000, "m", T["d_T_m"],
         f"adopted d_T = {t.d_T / 1000:g} m"),
        ("largest twist", "gamma_m", "7", math.degrees(t.gamma_m), "deg", T["gamma_m_deg"], "[τ] = 1600 MPa, L_T = 2 m"),
        ("static twist", "gamma_st", "8", math.degrees(t.gamma_st), "deg", T["gamma_st_deg"],
         "printed 24.358 disagrees with the seed's own c' (needs < 24.355)"),
        ("mounting angle", "beta_0", "9", math.degrees(t.beta0), "deg", T["beta0_deg"], "printed rounded"),
        ("full-travel angle", "beta_m", "10", math.degrees(t.beta_m), "deg", T["beta_m_deg"], "printed rounded"),
        ("static travel", "f_st", "11", t.f_st / 1000, "m", T["f_st_m"], ""),
        ("full travel", "f_full", "11", t.f_full / 1000, "m", T["f_full_m"], ""),
        ("dynamic travel", "f_dyn", "12", t.f_dyn / 1000, "m", T["f_dyn_m"], ""),
        ("elastic force at beta_m", "P(beta_m)", "13", t.P_m, "N", None, "SPEC §5: ≈ 94 kN"),
        ("torsion bar torque at beta_m", "M_T(beta_m)", "13", t.M_T_max / 1000, "N m", None, ""),
        ("specific potential energy (refined)", "lambda_ut", "16", t.lambda_ut / 1000, "m", T["lambda_ut_m"],
         "eq. 16 with d_T = 46 mm; with the unrounded d_T_dyn 0.8215 m"),
        ("equal-energy stiffness, printed lambda", "c'_printed_lambda", "20/24", c_pr, "N/m", T["c_prime_N_per_m"],
         "λ = 0.822 m printed, f_full computed"),
        ("equal-energy stiffness, eq. 16 lambda", "c'_eq16_lambda", "20/24", t.c_equiv_N_per_m, "N/m", None, ""),
        ("stiffness near the static travel (tangent)", "c", "1, 27", d.c_static, "N/m", T["c_N_per_m"], ""),
        ("mean damper coefficient at the wheel", "mu_k,mean", "23", d.mu_mean, "N s/m", T["mu_mean"],
         "wheel positions not printed: equal spacing assumed; the printed value needs Σl_j² > Σl_i²"),
        ("rebound coefficient limit (no hang-up)", "mu_reb_max", "25",
         m.extras["mu_reb_max_printed_c"], "N s/m", T["mu_reb_max"],
         "c' = 2.138e5 N/m, T_φ = 1.8 s; the printed γ_st = 24.358 would give 5.2294e4"),
        ("rebound coefficient from the printed mu_mean", "mu_reb", "21", T["mu_mean"] / m.p.reb_factor, "N s/m",
         T["mu_reb"], f"μ_mean / {m.p.reb_factor:g}"),
        ("compression coefficient from the printed mu_mean", "mu_comp", "21",
         2 * T["mu_mean"] - T["mu_mean"] / m.p.reb_factor, "N s/m", T["mu_comp"], "2 μ_mean − μ_reb"),
        ("design pitch period", "T_phi", "1, 25", m.p.T_phi_s, "s", T["T_phi_s"], "design input"),
        ("pitch period with c' and the assumed wheel positions", "T_phi", "26",
         pitch_period(d.I_y_kgm2, c_pr, d.sum_l2), "s", None, "1.8 s needs Σl_i² = 12.0 m² (< 2 × 3.423² m²)"),
        ("compression force limit at the wheel", "R_k,comp_max", "27", d.R_k_comp_max, "N", T["R_k_comp_max_N"], ""),
        ("damper ear arm", "L_a", "28", d.L_a, "mm", None, f"reading '{d.damper_reading}'"),
        ("rod force, compression", "R_a,comp_max", "28", d.R_a_comp_max, "N", None, ""),
        ("rod force, rebound", "R_a,reb_max", "28", d.R_a_reb_max, "N", None, ""),
        ("piston diameter at p_max (full area)", "D_p", "28", d.D_piston / 1000, "m", T["D_piston_m"], ""),
    ]
    return rows


#: how the seed prints each number (its last printed digit fixes the comparison)
_PRINTED_AS = {"gamma_m_deg": "96.043", "gamma_st_deg": "24.358", "beta0_deg": "19", "beta_m_deg": "115",
               "f_st_m": "0.078", "f_full_m": "0.492", "f_dyn_m": "0.414", "d_T_m": "0.046", "lambda_m": "0.822",
               "lambda_ut_m": "0.822", "c_prime_N_per_m": "2.138e5", "c_N_per_m": "164400", "mu_mean": "3.426e4",
               "mu_reb_max": "5.229e4", "mu_reb": "4.031e4", "mu_comp": "28220", "T_phi_s": "1.8",
               "R_k_comp_max_N": "2.134e4", "D_piston_m": "0.11"}


def _quantum(text: str) -> float:
    """Value of one unit in the last printed digit of a number as printed ("2.138e5" -> 100)."""
    t = text.lower()
    if "e" in t:
        mant, exp = t.split("e")
        dec = len(mant.split(".")[1]) if "." in mant else 0
        return 10.0 ** (int(exp) - dec)
    if "." in t:
        return 10.0 ** -len(t.split(".")[1])
    return 10.0 ** (len(t) - len(t.rstrip("0")))


def _printed_digits(v, printed) -> bool | None:
    """Does the computed value show the printed number to its printed digits?"""
    if printed is None:
        return None
    key = next((k for k, x in THESIS.items() if x == printed), None)
    q = _quantum(_PRINTED_AS[key]) if key in _PRINTED_AS else 10.0 ** (math.floor(math.log10(abs(printed))) - 3)
    return bool(round(v / q) == round(printed / q))


def _characteristic_plot(m: BalancerModel):
    from ..export.plots import new_figure

    t = m.tor
    c = t.characteristic(361)
    fig, ax = new_figure(7.0, 4.6)
    ax.plot(c["f"], c["P"] / 1000, lw=1.5, label="P(f), eq. 11 and 13")
    for b, lab, off in ((t.beta_st, "β_ст", (12, -28)), (t.beta_m, "β_m", (-160, -6))):
        ax.plot([float(t.f(b))], [float(t.P(b)) / 1000], "o", ms=5)
        ax.annotate(f"{lab} = {math.degrees(b):.3f}°\nf = {float(t.f(b)):.1f} mm, P = {float(t.P(b)) / 1000:.2f} kN",
                    (float(t.f(b)), float(t.P(b)) / 1000), textcoords="offset points", xytext=off, fontsize=7)
    k = t.stiffness_at_static
    fs = np.linspace(t.f_st - 60, t.f_st + 60, 3)
    ax.plot(fs, (t.P_st + k * (fs - t.f_st)) / 1000, "--", lw=0.8, label=f"tangent at f_ст: c = {1000 * k:.0f} N/m")
    ax.set_xlabel("wheel travel f, mm")
    ax.set_ylabel("force at the wheel axis P, kN")
    ax.set_title("Elastic characteristic of the torsion-bar suspension (seed 004 ch. 2)")
    top = ax.secondary_xaxis("top", functions=(lambda f: np.degrees(np.arccos(np.clip(math.cos(t.beta0) - f / t.R_b, -1, 1))),
                                               lambda bd: t.R_b * (math.cos(t.beta0) - np.cos(np.radians(bd)))))
    top.set_xlabel("balancer angle β, deg")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    return fig


def _stress_plot(m: BalancerModel, s, sig, h_built, h_eq):
    from ..export import plots as _agg  # noqa: F401  (selects the Agg backend before pyplot)
    import matplotlib.pyplot as plt

    p = m.p
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7.5, 7.0), dpi=100, sharex=True)
    for name, v in sig.items():
        ax1.plot(s, v, lw=1.2, label=f"σ_vM, {name}")
    allow = p.yield_MPa / p.safety
    ax1.axhline(allow, color="r", ls=":", lw=0.9, label=f"allowable {allow:.0f} MPa = {p.yield_MPa:g}/{p.safety:g}")
    ax1.axhline(300.0, color="k", ls="--", lw=0.7, label="seed FE: ~300 MPa in the body")
    ax1.set_ylabel("von Mises stress, MPa")
    ax1.grid(True, lw=0.4, alpha=0.6)
    sf = np.min([p.yield_MPa / np.maximum(v, 1e-9) for v in sig.values()], axis=0)
    axr = ax1.twinx()
    axr.plot(s, sf, color="0.4", lw=0.8, ls="-.", label="least safety factor")
    axr.set_ylabel("safety factor on yield")
    axr.set_ylim(0, max(6.0, float(np.nanmax(np.minimum(sf, 20))) * 1.05))
    ax1.legend(fontsize=7, loc="upper right")
    ax1.set_title("Balancer arm on its built outline: stresses (beam model) and safety")
    ax2.plot(s, h_built, lw=1.4, label="built section depth (band about the axis)")
    ax2.plot(s, h_eq, lw=1.0, ls="--", label="equal-strength depth (largest load case)")
    ax2.axhline(p.h_ref_mm, color="0.5", lw=0.7, ls=":", label=f"reference constant arm {p.h_ref_mm:g} mm")
    ax2.set_xlabel("station along the arm s, mm (0: upper axle, R_б: wheel axle)")
    ax2.set_ylabel("depth h, mm")
    ax2.set_ylim(0, max(250.0, float(np.max(h_built[np.isfinite(h_built)])) * 1.05))
    ax2.grid(True, lw=0.4, alpha=0.6)
    ax2.legend(fontsize=7)
    fig.tight_layout()
    return fig


def _side_view_plot(m: BalancerModel):
    """2D side view (world) of the arm outline and the wheel at β0, β_ст, β_m with the envelope lines."""
    from ..export.plots import new_figure

    p, t = m.p, m.tor
    fig, ax = new_figure(7.5, 6.5)
    poly = m.outline.profile.polylines(0.2)
    for b, col in ((t.beta0, "tab:blue"), (t.beta_st, "tab:green"), (t.beta_m, "tab:red")):
        th = b - math.pi / 2
        R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
        for k, pl in enumerate(poly):
            q = np.vstack([pl, pl[:1]]) @ R.T
            ax.plot(q[:, 0], q[:, 1], color=col, lw=0.9, label=f"β = {math.degrees(b):.2f}°" if k == 0 else None)
        c = R @ np.array([p.R_b_mm, 0.0])
        a = np.linspace(0, 2 * math.pi, 200)
        ax.plot(c[0] + m.wheel.r_tyre * np.cos(a), c[1] + m.wheel.r_tyre * np.sin(a), color=col, lw=0.6, ls="--")
    X = m.pitch
    ax.axhline(p.fender_height_mm, color="k", lw=0.8, ls=":", label="fender / sponson")
    ax.axhline(-p.hull_bottom_mm, color="k", lw=0.8, ls="-.", label="hull bottom (inboard of the side)")
    ax.plot([X, -X], [0.0, 0.0], "k+", ms=6, label=f"neighbouring upper axles (pitch {X:.0f} mm)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (forward), mm")
    ax.set_ylabel("y (up), mm")
    ax.set_title("Balancer and road wheel (dashed: tyre) over the travel")
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    return fig


def _sweep_plot(m: BalancerModel, sw: dict):
    from ..export.plots import new_figure

    fig, ax = new_figure()
    bd = np.degrees(sw["beta"])
    for name, d in sw["pairs"].items():
        lab = {"hull": "hull envelope", "front": "front neighbour", "rear": "rear neighbour"}[name]
        ok = ~d["capped"]
        line, = ax.plot(bd[ok], d["gap_mm"][ok], lw=1.0, marker="o", ms=2.5, label=f"{lab} (exact)")
        if name != "hull":
            ax.plot(bd, d["axis_distance_mm"] - 2.0 * m.wheel.r_tyre, lw=0.8, ls="--", color=line.get_color(),
                    label=f"{lab}: wheel-to-wheel gap, axis distance − 2R (upper bound)")
    ax.axhline(sw["window_mm"], color="0.6", lw=0.6, ls="-.",
               label=f"search window {sw['window_mm']:g} mm (steps not drawn lie above it)")
    ax.axhline(m.p.min_clearance_mm, color="r", ls=":", lw=0.9, label=f"least accepted {m.p.min_clearance_mm:g} mm")
    ax.axhline(sw["own"][1], color="0.3", ls="--", lw=0.8, label=f"own wheel to balancer {sw['own'][1]:.2f} mm")
    ax.set_xlabel("balancer angle β, deg")
    ax.set_ylabel("least gap (manifold3d min_gap), mm")
    ax.set_yscale("log")
    ax.set_title("Travel sweep β0 … β_m: clearance of balancer + road wheel")
    ax.legend(fontsize=6.5)
    fig.tight_layout()
    return fig


def _fmt_pt(pnt) -> str:
    return "?" if pnt is None else f"({pnt[0]:.1f}, {pnt[1]:.1f}, {pnt[2]:.1f})"


# ------------------------------------------------------------------------------------------------
# build
# ------------------------------------------------------------------------------------------------
def build(p: BalancerParams, w) -> None:
    from ..geometry.arm_outline import section_depth
    from ..laws.suspension import rebound_damping_max
    from ..solids.road_wheel import wheel_solids

    w.progress("inputs: suspension, road wheel, beam model, outline")
    m = resolve(p, getattr(w, "source", None))
    t, d, an = m.tor, m.design, m.analysis
    m.extras["mu_reb_max_printed_c"] = rebound_damping_max(THESIS["c_prime_N_per_m"], d.T_phi, t.f_full, t.f_st)
    D = w.derived

    # -- suspension (seed 004 ch. 2) -------------------------------------------------------------
    rows = _suspension_rows(m)
    w.add_table("suspension", ["quantity", "symbol", "equation", "computed", "unit", "printed", "printed_digits_match",
                               "note"],
                [[q, s, e, v, u, pr, _printed_digits(v, pr), note] for (q, s, e, v, u, pr, note) in rows])
    c = t.characteristic(int(round(math.degrees(t.beta_m - t.beta0) * 4)) + 1)
    w.add_table("elastic_characteristic", {"beta_deg": np.degrees(c["beta"]), "f_mm": c["f"], "P_N": c["P"],
                                           "M_T_Nm": c["M_T"] / 1000.0, "tau_bar_MPa": t.tau(c["beta"])}, None)
    w.add_plot("elastic_characteristic", _characteristic_plot(m))
    D.update({
        "gamma_m_deg": math.degrees(t.gamma_m), "gamma_st_deg": math.degrees(t.gamma_st),
        "beta0_deg": math.degrees(t.beta0), "beta_m_deg": math.degrees(t.beta_m), "f_st_mm": t.f_st,
        "f_full_mm": t.f_full, "f_dyn_mm": t.f_dyn, "P_at_beta_m_N": t.P_m, "M_T_max_Nm": t.M_T_max / 1000,
        "lambda_ut_mm": t.lambda_ut, "c_prime_printed_lambda_N/m": _suspension_rows(m)[11][3],
        "c_static_N/m": d.c_static, "mu_mean_eq23_Ns/m": d.mu_mean, "R_k_comp_max_N": d.R_k_comp_max,
        "L_a_mm": d.L_a, "R_a_comp_max_N": d.R_a_comp_max, "R_a_reb_max_N": d.R_a_reb_max,
        "D_piston_mm": d.D_piston, "station_pitch_mm": m.pitch,
    })
    w.add_checks([Check.at_most("torsion bar shear at beta_m", float(t.tau(t.beta_m)), t.tau_max * (1 + 1e-12), "MPa",
                                "τ = G d_T (β_m − β0) / (2 L_T) <= [τ]max (eq. 7)")])

    # -- strength on the built outline (seed 004 ch. 8) --------------------------------------------
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
    w.add_plot("arm_stresses", _stress_plot(m, s, sig, h_built, h_eq))
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
    # spline socket, ear, stop pad
    sp = m.spline
    sig_cr = sp.crushing_stress(t.M_T_max, p.spline_length_mm)
    cr_allow = p.yield_MPa / (p.spline_n * p.spline_K_sum)
    d_o, d_i = p.d_upper_mm - 3.0, sp.D_f_hub
    tau_sock = 16.0 * t.M_T_max * d_o / (math.pi * (d_o**4 - d_i**4))
    F_rod = max(d.R_a_comp_max, d.R_a_reb_max)
    r_pin = 0.5 * p.ear_pin_d_mm
    r_ear = r_pin + p.ear_wall_mm
    pin_tau = F_rod / (2.0 * math.pi * r_pin**2)
    ear_bear = F_rod / (p.ear_pin_d_mm * p.arm_width_mm)
    ear_net = F_rod / (2.0 * p.ear_wall_mm * p.arm_width_mm)
    F_stop = ([c_ for c_ in an.cases if c_.name == "stop"][0].loads[1].F_y) * -1.0
    pad_p = F_stop / (p.stop_pad_length_mm * p.arm_width_mm)
    w.add_checks([
        Check.at_most("spline socket crushing (GOST 21425, seed §4.3)", sig_cr, cr_allow, "MPa",
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

    # -- solids ---------------------------------------------------------------------------------------
    w.progress("solids: balancer (plate ∪ upper axle ∪ spindle − socket, bores) and the road wheel")
    bal = balancer_solid(m)
    wsol = wheel_solids(m.wheel)
    m.extras["wheel_names"] = list(wsol)
    w.progress("sweep meshes")
    bal_mesh = sweep_mesh(bal, p.sweep_chord_mm)
    wheel_meshes = [sweep_mesh(s_, p.sweep_chord_mm) for s_ in wsol.values()]
    w.progress(f"travel sweep β0 … β_m ({int(math.ceil(math.degrees(t.beta_m - t.beta0) * p.sweep_steps_per_deg)) + 1} "
               "steps × hull + 2 neighbours), in a second process while the solids are checked")
    pending = start_in_fork(_sweep_job, m, bal_mesh, wheel_meshes)
    w.add_solid("balancer", bal, expected_genus=3)
    from ..solids.kernel import mass_properties

    mass, com = mass_properties(bal, RHO_STEEL_KG_MM3)
    wm_tot, wm_com = 0.0, np.zeros(3)
    for nm, s_ in wsol.items():
        rho = (m.wheel_p.rho_rubber_kg_m3 if nm.startswith("tyre") else m.wheel_p.rho_steel_kg_m3) * 1e-9
        mk, ck = mass_properties(s_, rho)
        wm_tot += mk
        wm_com += mk * (ck + np.array([p.R_b_mm, 0.0, m.z_hub]))
    wm_com /= wm_tot
    arm_m, arm_sc = an.arm_mass(h_built)
    D.update({"mass_balancer_kg": mass, "centre_of_mass_balancer_mm": [float(x) for x in com],
              "mass_wheel_kg": wm_tot, "centre_of_mass_wheel_mm": [float(x) for x in wm_com],
              "mass_arm_prism_beam_model_kg": arm_m, "com_arm_prism_station_mm": arm_sc,
              "unsprung_balancer_plus_wheel_kg": mass + wm_tot})
    w.add_table("mass_properties", ["body", "mass_kg", "com_x_mm", "com_y_mm", "com_z_mm", "frame"], [
        ["balancer (solid)", mass, *map(float, com), "balancer"],
        ["road wheel (disc, rims, tyres)", wm_tot, *map(float, wm_com), "balancer"],
        ["arm prism of the beam model", arm_m, arm_sc, 0.0, 0.0, "balancer (station)"]])

    # assembly at beta_st
    from ..solids.kernel import z_rotation

    th = math.degrees(t.beta_st - math.pi / 2)
    comps = [("balancer", bal, z_rotation(th))]
    for nm, s_ in wsol.items():
        comps.append((f"road_wheel_{nm}", s_, z_rotation(th, (p.R_b_mm, 0.0, m.z_hub))))
    w.add_assembly("assembly_beta_st", comps)

    # DXF of the arm's side outline (plate blank)
    sh = m.extras
    refs = [("line", {"p0": (-p.upper_boss_r_mm - 10, 0.0), "p1": (p.R_b_mm + p.lower_boss_r_mm + 10, 0.0)}),
            ("circle", {"center": (0.0, 0.0), "radius": 0.5 * p.d_upper_mm}),
            ("circle", {"center": (0.0, 0.0), "radius": 0.5 * p.bolt_bore_d_mm}),
            ("circle", {"center": (p.R_b_mm, 0.0), "radius": 0.5 * m.wheel_p.bearing_inner_d_mm}),
            ("line", {"p0": (m.pad[0], m.pad[2]), "p1": (m.pad[1], m.pad[2])})]
    w.add_dxf("balancer_arm_outline", [m.outline.profile], refs)
    w.add_plot("side_view", _side_view_plot(m))

    # -- travel sweep results -------------------------------------------------------------------------
    sw = pending.result()
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
    w.add_plot("travel_clearance", _sweep_plot(m, sw))
    from ..policy import OVERLAP_VOLUME_TOL_MM3 as tol

    labels = {"hull": "hull envelope", "front": "front neighbour station", "rear": "rear neighbour station"}
    overall = (math.inf, "", None)
    for name, dd in sw["pairs"].items():
        k = dd["worst_step"]
        pa, pb, dist = dd["where"]
        gap = float(dd["gap_mm"][k])
        exact_steps = ~dd["capped"]
        steady = exact_steps.sum() > 1 and float(np.ptp(dd["gap_mm"][exact_steps])) < 0.01
        where = (f"at β = {math.degrees(betas[k]):.2f}°{' (the same at every step)' if steady else ''} between the "
                 f"{dd['what']} near {_fmt_pt(pa)} and the {labels[name]} near {_fmt_pt(pb)} (world mm)")
        w.add_checks([
            Check.at_most(f"travel sweep overlap, {labels[name]}", float(dd["overlap_mm3"].max()), tol, "mm^3",
                          f"manifold3d intersection volume at {len(betas)} steps β0 … β_m "
                          f"({p.sweep_steps_per_deg:g}/deg); {int(np.sum(dd['overlap_mm3'] > tol))} steps overlap"),
            Check.at_least(f"travel sweep clearance, {labels[name]}", gap, p.min_clearance_mm, "mm", f"least gap {where}"),
        ])
        D[f"min_clearance_{name}_mm"] = gap
        D[f"min_clearance_{name}_where"] = where
        if gap < overall[0]:
            overall = (gap, name, where)
    own_vol, own_gap = sw["own"]
    pa, pb, _ = sw["own_where"]
    w.add_checks([
        Check.at_most("own wheel vs balancer overlap", own_vol, tol, "mm^3", "road wheel mounted on the spindle"),
        Check.at_least("own wheel vs balancer clearance", own_gap, p.min_clearance_mm, "mm",
                       f"least gap near {_fmt_pt(pa)} / {_fmt_pt(pb)} (balancer frame); rigid over the travel"),
        Check.at_least("tyre to bolt boss (R_b - R - r_boss)", p.R_b_mm - m.wheel.r_tyre - p.plug_r_mm,
                       p.min_clearance_mm, "mm", "constant over the travel: both on fixed radii"),
    ])
    D["min_clearance_own_wheel_mm"] = own_gap
    D["min_clearance_overall_mm"] = min(overall[0], own_gap)
    D["min_clearance_overall_where"] = (overall[2] if overall[0] <= own_gap else
                                        f"own road wheel to balancer near {_fmt_pt(pa)} / {_fmt_pt(pb)} (balancer frame)")
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

    # -- notes ------------------------------------------------------------------------------------
    el = sig["beta_m elastic"]
    w.add_note(
        f"Suspension (seed 004 ch. 2): γ_m = {math.degrees(t.gamma_m):.3f}° (printed 96.043), γ_ст = "
        f"{math.degrees(t.gamma_st):.3f}° (printed 24.358), β0 = {math.degrees(t.beta0):.3f}°, β_m = "
        f"{math.degrees(t.beta_m):.3f}° (printed rounded 19 / 115), f_ст = {t.f_st:.1f} mm, f_полн = {t.f_full:.1f} mm, "
        f"P(β_m) = {t.P_m / 1000:.2f} kN, λ_ут = {t.lambda_ut:.1f} mm (printed 822, −1.0 %: eq. 16 with the rounded "
        f"d_T = 46 mm; 821.5 mm with the unrounded eq. 6 diameter), c' = {D['c_prime_printed_lambda_N/m']:.4g} N/m "
        f"with the printed λ. Readings: [τ] = {p.tau_max_MPa:g} MPa and L_T = {p.L_T_mm:g} mm (not printed) reproduce "
        f"γ_m; the printed γ_ст = 24.358° is 0.010° above eq. 8 and would give c' = 2.139e5, not the printed 2.138e5 — "
        f"the seed's last digits disagree. μ_к.ср = 3.426e4 and T_φ = 1.8 s cannot be re-run (wheel positions not "
        f"printed; 1.8 s would need Σl² = 12.0 m², below the 23.4 m² of the two end wheels alone); the chain after "
        f"them (μ_об = 4.031e4, μ_пр = 28 220, μ_об^max = 5.229e4, R_к.пр^max = 2.134e4 N) is reproduced "
        f"(table suspension.csv).")
    w.add_note(
        f"Damper (eq. 28): i = {p.i_a:g} read as '{p.damper_reading}' — i = L_a/R_б, ear at L_a = {d.L_a:.1f} mm, rod "
        f"force = wheel force / i: R_a,comp = {d.R_a_comp_max / 1000:.1f} kN, R_a,reb = {d.R_a_reb_max / 1000:.1f} kN, "
        f"piston {d.D_piston:.1f} mm at {p.p_max_MPa:g} MPa (printed D_п = 0.11 m). The literal reading "
        f"(R_a = R_k × i) would put the ear at {p.R_b_mm / p.i_a:.0f} mm, beyond the {p.R_b_mm:g} mm balancer.")
    w.add_note(
        f"Strength (seed 004 ch. 8): load cases at β_m — wheel force P(β_m) = {t.P_m / 1000:.1f} kN at the wheel "
        f"mid-plane e_w = {m.e_w:.1f} mm outboard (force D of the FE); the same with the compression rod force "
        f"{d.R_a_comp_max / 1000:.1f} kN at the ear (force E); the stop case k_stop = {p.k_stop:g} × P(β_m) with the "
        f"pad reacting (ours). The arm (b = {p.arm_width_mm:g} mm) is drawn around the equal-strength depth for "
        f"[σ] = {p.yield_MPa:g}/{p.safety:g} = {allow:.0f} MPa ({h_eq.min():.1f} ... {h_eq.max():.1f} mm: the torsion "
        f"from the wheel offset is constant along the arm and sets most of it) and checked on its built section at "
        f"{len(s)} stations: largest σ_vM {max(float(v.max()) for v in sig.values()):.0f} MPa. Body stress for the "
        f"elastic case alone (the FE's force D): {body_el:.0f} MPa on the built arm; the library's constant "
        f"{p.h_ref_mm:g} mm reference arm gives {float(np.max(sc['beta_m elastic'])):.0f} MPa (elastic) and "
        f"{float(np.max(sc['beta_m + damper'])):.0f} MPa (with E) — the seed's FE reports ~300 MPa in the body, "
        f"724 MPa at a singular point.")
    w.add_note(
        "Axle–arm transitions (stepped shaft, Peterson / Pilkey charts 3.10 and 3.12): "
        + "; ".join(f"{r['case']}, {r['where']}: K_t = {r['K_t_bending']:.3f} bending"
                    + (f" / {r['K_t_torsion']:.3f} torsion" if r["K_t_torsion"] != 1.0 else "")
                    + f", σ_vM nominal {r['sigma_vM_nom']:.0f} MPa, peak {r['sigma_vM_peak']:.0f} MPa, safety "
                    f"{p.yield_MPa / r['sigma_vM_peak']:.2f}" for r in trs)
        + f". Peaks stay below the FE's 724 MPa singular value, which the seed attributes to a singularity, not a "
          f"resolved fillet.")
    w.add_note(
        f"Solid: arm plate {p.arm_width_mm:g} mm (DXF balancer_arm_outline.dxf), upper axle Ø{p.d_upper_mm:g} with hull "
        f"bearing seats at {p.a1_mm:g} and {p.a2_mm:g} mm inboard, shoulder Ø{p.D_upper_mm:g} / r {p.r_upper_mm:g}, "
        f"torsion-bar socket {sp.designation()} l = {p.spline_length_mm:g} mm at its inboard end, retaining-bolt bore "
        f"Ø{p.bolt_bore_d_mm:g} through to a boss r {p.plug_r_mm:g} on the outboard face; spindle with the road wheel's "
        f"bearing seats Ø{m.wheel_p.bearing_inner_d_mm:g} / Ø{m.wheel_p.bearing_outer_d_mm:g}, shoulder "
        f"Ø{p.D_lower_mm:g} / r {p.r_lower_mm:g}, lubrication bore Ø{p.lube_bore_d_mm:g} with a Ø{p.lube_cross_d_mm:g} "
        f"cross hole between the bearings; damper ear pin Ø{p.ear_pin_d_mm:g} at {m.L_a:.1f} mm, stop pad at "
        f"{p.s_stop_mm:g} mm. Mass {mass:.1f} kg, centre of mass ({com[0]:.1f}, {com[1]:.1f}, {com[2]:.1f}) mm "
        f"(balancer frame); road wheel {wm_tot:.1f} kg. Genus 3 (bolt bore through, ear pin hole, lube bore + cross "
        f"hole).")
    w.add_note(
        f"Travel sweep: {len(betas)} steps from β0 = {math.degrees(t.beta0):.3f}° to β_m = {math.degrees(t.beta_m):.3f}° "
        f"({p.sweep_steps_per_deg:g} per degree), balancer with its road wheel (meshes at {p.sweep_chord_mm:g} mm chord) "
        f"against the hull envelope (side plane z = {p.hull_side_z_mm:g} mm, bottom {p.hull_bottom_mm:g} mm below the "
        f"torsion axis, bearing-housing bore Ø{p.hull_bore_d_mm:g}, fender {p.fender_height_mm:g} mm above the axis) "
        f"and the neighbouring stations at ±{m.pitch:.1f} mm, each neighbour at every step in the travel angle that "
        f"brings its wheel closest. No overlap; least clearance {D['min_clearance_overall_mm']:.2f} mm "
        f"({D['min_clearance_overall_where']}). Own wheel to balancer {own_gap:.2f} mm. The hull's bump stop must meet "
        f"the pad face at β_m: face centre ({pc[0]:.1f}, {pc[1]:.1f}) mm, normal ({nrm[0]:.3f}, {nrm[1]:.3f}) (world).")


PART_TYPE = PartType(
    name="balancer",
    summary="suspension balancer with road wheel: torsion suspension calc, equal-strength arm, travel sweep "
            "(seed 004 ch. 2, 8)",
    params_cls=BalancerParams,
    build=build,
)
