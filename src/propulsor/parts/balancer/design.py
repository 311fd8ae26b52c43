"""The balancer's design: the seed's suspension, the road wheel it carries, the beam model, the arm outline.

* the torsion-bar suspension calculation of seed 004 ch. 2, eq. 1-28 (:mod:`propulsor.laws.suspension`):
  twist angles, balancer angles, travel f(β) (eq. 11), elastic characteristic P(β) (eq. 13), specific
  potential energy (eq. 15-16), c' (eq. 20/24), damper coefficients and forces (eq. 19-28);
* the balancer as a beam with its load cases (wheel force at β_m, damper force E, stop) and an
  equal-strength depth (:mod:`propulsor.laws.balancer_beam`);
* the arm plate's side outline around the equal-strength depth with the damper ear and the stop pad
  (:mod:`propulsor.geometry.arm_outline`).

Readings taken where the seed is inconsistent (also in the report):
* damper lever ratio (eq. 28): i = L_a / R_b = 0.453 ("lever"): ear at 163 mm, rod force =
  wheel force / i; the only reading that gives the printed piston D_p = 0.11 m.  The literal
  reading puts the ear at 795 mm, beyond the 360 mm balancer, and is refused.
* [τ] = 1600 MPa and L_T = 2000 mm (not printed) reproduce γ_m = 96.043°; γ_st then comes out
  24.348° against the printed 24.358°, and only γ_st < 24.355° reproduces the printed
  c' = 2.138e5 N/m with the printed λ = 0.822 m: the seed's last digits disagree.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...errors import InputError
from ...params import load_params, read_part_file
from ..pipeline import design_of
from .params import BalancerParams

__all__ = ["feasible", "BalancerModel", "THESIS", "RHO_STEEL_KG_MM3", "suspension_design", "resolve", "spindle_dims"]

RHO_STEEL_KG_MM3 = 7.85e-6


#: the arm edges are B-splines within this of the smoothed edge y(x) (its requirement has a 1 mm margin)
OUTLINE_FIT_TOL_MM = 1e-4


#: numbers printed in seed 004 ch. 2 (the acceptance data of the suspension calculation)
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


def suspension_design(p: BalancerParams):
    """The seed's suspension (library objects) for these parameters; InputError names the part-file key."""
    from ...laws.suspension import SuspensionDesign, TorsionSuspension, uniform_wheel_positions

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
@dataclass(frozen=True)
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
    #: h_eq (equal-strength depth), spindle dimensions, mu_reb_max_printed_c, wheel_names
    extras: dict = field(default_factory=dict)

    @property
    def tor(self):
        return self.design.torsion


def _wheel_inputs(p: BalancerParams, source: Path | None):
    from .. import get_part_type, vet

    road_wheel = get_part_type("road_wheel")  # a part type is looked up, never imported

    base = Path(source).resolve().parent if source is not None else Path.cwd()
    f = Path(p.road_wheel_file)
    f = f if f.is_absolute() else base / f
    if not f.is_file():
        raise InputError("road_wheel_file", p.road_wheel_file, f"does not exist (looked for {f})")
    typ, mapping = read_part_file(f)
    if typ != "road_wheel":
        raise InputError("road_wheel_file", p.road_wheel_file, f"names part type {typ!r}, not 'road_wheel'")
    try:
        wp = load_params(road_wheel.params_cls, mapping, validate=False)
        vet(road_wheel, wp, f)
    except InputError as exc:
        raise InputError(f"{exc.parameter} (in {f.name})", exc.value, exc.limit) from None
    return f, wp, design_of(wp, road_wheel.design).model


def resolve(p: BalancerParams, source: Path | None = None) -> BalancerModel:
    """Everything the build needs, or InputError (nothing is written before this returns)."""
    from ...laws.balancer_beam import BalancerAnalysis, BalancerGeometry
    from ...laws.suspension import rebound_damping_max

    design = design_of(p, suspension_design)
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
    t = design.torsion
    extras = spindle_dims(p, wp, z_hub)
    extras["mu_reb_max_printed_c"] = rebound_damping_max(THESIS["c_prime_N_per_m"], design.T_phi, t.f_full, t.f_st)
    extras["wheel_names"] = list(wm.sections())  # the road wheel's solids, in the order they are built
    m = BalancerModel(p, design, wp, wm, f, geom, an, p.spline(), z_hub, e_w, L_a, 1000.0 * p.base_m / (n - 1),
                      extras=extras)
    try:
        outline, ear, pad, h_eq = _outline(m)
    except InputError as exc:  # the equal-strength depth's refusal names the library's h_max
        raise _renamed(exc) from None
    extras["h_eq"] = h_eq
    return dataclasses.replace(m, outline=outline, ear=ear, pad=pad)


def _outline(m: BalancerModel):
    """Arm side outline around the equal-strength depth, with the damper ear and the stop pad:
    (outline, ear (x, y, r_pin, r_ear), pad (x0, x1, y), equal-strength depth h_eq)."""
    from ...geometry.arm_outline import arm_outline, smooth_majorant

    p, an = m.p, m.analysis
    h_eq = an.envelope_depth()
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
    ear = (m.L_a, y_e, r_pin, r_ear)
    pad = (x0, x1, y_pad)
    try:
        outline = arm_outline(p.R_b_mm, p.upper_boss_r_mm, p.lower_boss_r_mm, grid, req, req, p.fillet_mm,
                           p.smoothing_mm, circles=[(m.L_a, y_e, r_ear)], plateaus=[(x0, x1, y_pad)],
                           holes=[(m.L_a, y_e, r_pin)], tol=OUTLINE_FIT_TOL_MM)
    except InputError as exc:
        raise InputError("arm_width_mm", p.arm_width_mm, f"the arm outline cannot be drawn ({exc}); the "
                         "equal-strength depth may exceed a boss: widen the arm or enlarge the bosses") from None
    return outline, ear, pad, h_eq


def spindle_dims(p: BalancerParams, wp, z_hub: float) -> dict:
    """Seats of the road wheel's bearings on the spindle, its end, the relief radius between the seats
    and the station of the lubrication cross hole (balancer frame, mm)."""
    r2 = 0.5 * wp.bearing_outer_d_mm
    zb1 = z_hub
    L = wp.hub_length_mm
    s1 = (zb1, zb1 + wp.bearing_inner_B_mm)
    s2 = (zb1 + L - wp.bearing_outer_B_mm, zb1 + L)
    rr = r2 + 2.0  # relief between the seats
    z_end = s2[1] + p.nut_length_mm
    z_cross = 0.5 * (s1[1] + s2[0])
    return {"spindle_seat_1": s1, "spindle_seat_2": s2, "spindle_end": z_end, "z_cross": z_cross,
            "spindle_relief_r": rr}


def feasible(p, source=None) -> None:
    """InputError (parameter, value, limit) when the balancer cannot be made as its parameters say: the seed's
    suspension, the road wheel file it names, the arm and its equal-strength depth (:func:`resolve`, computed once:
    the build reuses it, :func:`~propulsor.parts.pipeline.design_of`).  What the parameters cannot tell from their
    fields; run by the dry run, the Python API and each build's load after ``validate()`` (``parts.vet``); the size
    estimate needs only the suspension (``estimate.py``: several builds are ordered without this)."""
    design_of(p, resolve, source)
