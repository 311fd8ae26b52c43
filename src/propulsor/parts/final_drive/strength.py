"""The final drive's load path and strength (seed 004 ch. 4.1–4.3): working stresses of both meshes
by ISO 6336 at the design torque, their static safeties against the thesis's allowables (σ_Hmax = 44·HRC,
σ_FlimM = 2.8·σ_t; the fatigue safeties are in :mod:`.fatigue`), the face width each mesh needs, the planet and carrier bearings'
static safety (ISO 76), the carrier spline and the carrier shaft — as derived values, checks, a
bearing table and a note with the thesis's values beside ours.
"""

from __future__ import annotations

import math

from ...check import Check
from .design import FinalDriveDesign

__all__ = ["strength", "mesh_stresses", "required_face_width", "SPLINE_004", "SHAFT_004"]

# seed 004 §4.2: planet bearing load eq. 44 with i = 2 bearings per planet; the carrier bearing's load
# as Table 8 prints it (its reactions R_A, R_B of Fig. 15 are not given in the text)
BEARINGS_PER_PLANET = 2
CARRIER_BEARING_LOAD_TABLE8_N = 858508.0
# seed 004 §4.3: spline Эв. 120 × 3.5 × 34, working length 140 mm, n = 1.4, K_Σ = K_pr·K_z·K_p = 2.65·1·1.4,
# hub steel 30ХГСЛ σ_T = 630 MPa (the thesis computes [σ] with 785 MPa)
SPLINE_004 = dict(D=120.0, m=3.5, z=34, L=140.0, n=1.4, K_pr=2.65, K_z=1.0, K_p=1.4, sigma_T_hub=630.0,
                  sigma_T_printed=785.0)
# seed 004 §4.3: carrier shaft, 30ХН3А σ_T = 970 MPa, lever 222 mm, moduli as printed
SHAFT_004 = dict(L=222.0, W_i=169646.003, W_k=272271.363, sigma_T=970.0)


def _loads(p, ps):
    """(sun torque per mesh N·m, relative pitch-line speed of the sun m/s)."""
    T_sun = p.sprocket_torque_Nm * p.load_share_Omega / p.power_ratio_i_sil  # seed 004 eq. 42
    n_carrier = p.design_speed_kmh / 3.6 / (p.sprocket_teeth * p.track_pitch_mm * 1e-3)  # rev/s
    v = math.pi * ps.sun.d * 1e-3 * n_carrier * (ps.ratio - 1.0)  # sun relative to the carrier
    return T_sun / p.n_planets, v


def ring_root(p, ps):
    """The ring's root as made for ISO 6336-3 (internal gear): arc tooth thickness on d3 less the space widening
    E_sn, the shaper's tip radius as its fillet, the rim under the root."""
    from ...gears.iso6336 import InternalRoot
    from .design import ring_outer_d

    return InternalRoot(ps.ring.s - p.tooth_thinning_mm, p.shaper_tip_radius_star * p.module_mm,
                        0.5 * (ring_outer_d(p, ps) - ps.ring.d_f))


def mesh_stresses(p, ps, b_sp: float | None = None, b_pr: float | None = None):
    """ISO 6336 stresses of (sun–planet, planet–ring) at the design torque.  b_sp, b_pr: common face widths to try
    (the face width search; every root then bent over that width), by default the design's (each root over the
    common face plus at most one module each side within its own face, ISO 6336-3:2019 5.2)."""
    from ...gears.iso6336 import MeshLoad, mesh_stress, root_face_width

    T1, v = _loads(p, ps)
    # the sun passes the whole input torque through its body: its torsional wind-up under all n_planets meshes'
    # torque enters K_Hβ (f_sh, ISO 6336-1 method C)
    load = MeshLoad(T1, v, p.application_factor_K_A, p.accuracy_grade, pinion_torsion=True,
                    pinion_meshes=p.n_planets)
    m = p.module_mm
    bF_sp = bF_pr = None
    if b_sp is None:   # the design's faces: each root over the common face plus at most a module each side
        b_sp = min(p.width_sun_mm, p.width_planet_mm)
        bF_sp = (root_face_width(p.width_sun_mm, b_sp, m), root_face_width(p.width_planet_mm, b_sp, m))
    if b_pr is None:
        b_pr = min(p.width_planet_mm, p.width_ring_mm)
        bF_pr = (root_face_width(p.width_planet_mm, b_pr, m), root_face_width(p.width_ring_mm, b_pr, m))
    # the root's form factors of the teeth as made: thinned by the allowance E_sn of the solids
    sp = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, b_sp, load, E_sn=p.tooth_thinning_mm, b_F=bF_sp)
    # the planet passes the sun's tangential force on to the ring (equal base-circle forces)
    load_pr = MeshLoad(T1 * p.z_planet / p.z_sun, v, p.application_factor_K_A, p.accuracy_grade)
    # one centre distance per mesh, the one the carrier makes: the planets sit on the sun–planet a_w, so the
    # planet–ring mesh runs there too (a set that is not coaxial runs it off the a_w of its shifts)
    pr = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, b_pr, load_pr, a_w=ps.a_w,
                     internal_root=ring_root(p, ps), E_sn=p.tooth_thinning_mm, b_F=bF_pr)
    return sp, pr


def _allowables(p):
    sigma_Hmax = 44.0 * p.flank_hardness_HRC    # seed 004 ch. 4.1
    sigma_FlimM = 2.8 * p.core_yield_MPa         # seed 004 ch. 4.1
    return sigma_Hmax, sigma_FlimM


def _margin(p, s) -> float:
    """Smallest ratio (achieved static safety / required safety) of one mesh, root stresses by method B;
    >= 1 passes."""
    sHmax, sFlim = _allowables(p)
    out = [sHmax / s.sigma_H / p.contact_safety_S_Hmin, sFlim / s.sigma_F1_B / p.bending_safety_S_Fm]
    if s.sigma_F2_B is not None:
        out.append(sFlim / s.sigma_F2_B / p.bending_safety_S_Fm)
    return min(out)


def required_face_width(p, ps, mesh: str) -> float:
    """Least face width (mm) at which the mesh ('sun_planet' or 'planet_ring') meets the static S_Hmin and S_Fm."""
    from scipy.optimize import brentq

    def f(b):
        sp, pr = mesh_stresses(p, ps, b, b)
        return _margin(p, sp if mesh == "sun_planet" else pr) - 1.0

    lo, hi = 1e-3 * p.module_mm, 200.0 * p.module_mm
    if f(hi) < 0:
        return math.inf
    return brentq(f, lo, hi, xtol=1e-6)


def strength(dd: FinalDriveDesign, w, built: dict) -> None:
    """Load path, ISO 6336 stresses of both meshes, bearings, spline, shaft: derived values, checks, tables."""
    from ...geometry.involute_spline import InvoluteSpline
    from ...laws.carrier_strength import (CARRIER_BEARING_004, PLANET_BEARING_004, shaft_equivalent_stress,
                                          spline_allowable, spline_crushing_stress)
    from ...laws.traction import planet_bearing_load, track_forces

    p, ps = dd.p, dd.ps
    w.progress("strength: ISO 6336 stresses, bearings, spline, shaft")
    d = w.derived
    sHmax, sFlim = _allowables(p)
    T1, v = _loads(p, ps)
    sp, pr = mesh_stresses(p, ps)
    d.update({"design_torque_carrier_Nm": p.sprocket_torque_Nm, "sun_torque_Nm": T1 * p.n_planets,
              "sun_torque_per_mesh_Nm": T1, "pitch_line_speed_rel_m_s": v,
              "sigma_Hmax_allowable_MPa": sHmax, "sigma_FlimM_MPa": sFlim,
              "sigma_Fmax_allowable_MPa": sFlim / p.bending_safety_S_Fm})
    rows = []
    for tag, s, gears in (("sun_planet", sp, ("sun", "planet")), ("planet_ring", pr, ("planet", "ring"))):
        b_req = required_face_width(p, ps, tag)
        b = s.b
        roots = [(gears[0], s.sigma_F1, s.sigma_F1_B, s.Y_F1, s.Y_S1)]
        if s.sigma_F2 is not None:
            roots.append((gears[1], s.sigma_F2, s.sigma_F2_B, s.Y_F2, s.Y_S2))
        vals = {"F_t_N": s.F_t, "b_mm": b, "K_A": s.K_A, "K_v": s.K_v, "K_Hbeta": s.K_Hbeta, "K_Halpha": s.K_Halpha,
                "K_Fbeta": s.K_Fbeta, "K_Falpha": s.K_Falpha, "Z_H": s.Z_H, "Z_E": s.Z_E, "Z_eps": s.Z_eps,
                "Z_B": s.Z_B, "Y_eps": s.Y_eps, "sigma_H0_MPa": s.sigma_H0, "sigma_H_MPa": s.sigma_H,
                "S_H_static": sHmax / s.sigma_H}
        for g, sC, sB, YF, YS in roots:
            vals.update({f"Y_F_method_C_{g}": YF, f"Y_S_method_C_{g}": YS, f"sigma_F_{g}_method_C_MPa": sC,
                         f"sigma_F_{g}_method_B_MPa": sB, f"S_F_{g}_static": sFlim / sB})
        vals["face_width_required_mm"] = b_req
        for k, x in vals.items():
            d[f"strength_{tag}_{k}"] = x
            rows.append([tag, k, x])
        w.describe(f"strength_{tag}_S_H_static", "", "static contact safety σ_Hmax/σ_H, σ_Hmax = 44·HRC (seed 004 ch. 4.1)")
        w.describe(f"strength_{tag}_face_width_required_mm", "mm",
                   "least face width meeting the static S_H and S_F (root stress by ISO 6336-3 method B)")
        checks = [
            Check.at_least(f"strength_{tag}.S_H_static", sHmax / s.sigma_H, p.contact_safety_S_Hmin, "",
                           f"S_H static (σ_Hmax = 44·HRC = {sHmax:.0f} MPa, seed 004 ch. 4.1) over ISO 6336-2 "
                           f"σ_H = {s.sigma_H:.1f} MPa at the design torque"),
            Check.at_most(f"strength_{tag}.face_width", b_req, b, "mm",
                          f"face width the mesh needs for the static checks ({b_req:.2f} mm) within the one it "
                          f"has ({b:g} mm)"),
        ]
        for g, sC, sB, YF, YS in roots:
            w.describe(f"strength_{tag}_sigma_F_{g}_method_B_MPa", "MPa",
                       "root stress by ISO 6336-3:2006 method B (load at the outer point of single contact); the checks use it")
            w.describe(f"strength_{tag}_sigma_F_{g}_method_C_MPa", "MPa",
                       "root stress by ISO 6336-3:1996 method C (load at the tip, Y_ε), for comparison")
            w.describe(f"strength_{tag}_Y_F_method_C_{g}", "", "form factor Y_F, load at the tip (method C)")
            w.describe(f"strength_{tag}_Y_S_method_C_{g}", "", "stress correction factor Y_S, load at the tip (method C)")
            w.describe(f"strength_{tag}_S_F_{g}_static", "",
                       "static bending safety σ_FlimM/σ_F (method B), σ_FlimM = 2.8·σ_t (seed 004 ch. 4.1)")
            checks.append(Check.at_least(
                f"strength_{tag}.S_F_{g}_static", sFlim / sB, p.bending_safety_S_Fm, "",
                f"S_F static (σ_FlimM = 2.8·σ_t = {sFlim:.0f} MPa, seed 004 ch. 4.1) over ISO 6336-3 method B "
                f"σ_F = {sB:.1f} MPa (method C: {sC:.1f} MPa)"))
        w.add_checks(checks)
    w.add_table("strength_meshes", ["mesh", "quantity", "value"], rows)

    # --- bearings (seed 004 §4.2, ISO 76) ---------------------------------------------------------------
    r_vod = ps.a_w * 1e-3
    P_sat = planet_bearing_load(p.sprocket_torque_Nm, p.load_share_Omega, r_vod, p.n_planets, BEARINGS_PER_PLANET)
    tf = track_forces(p.sprocket_torque_Nm, p.sprocket_teeth, p.track_pitch_mm * 1e-3, 31057.0, 10, 64)
    brows = []
    for role, br, load, printed in (("planet", PLANET_BEARING_004, P_sat, (128700.0, 92000.0, 1.39)),
                                    ("carrier", CARRIER_BEARING_004, CARRIER_BEARING_LOAD_TABLE8_N,
                                     (1398120.0, 858508.0, 1.629))):
        S0 = br.S0(load)
        brows.append([role, br.designation, f"{br.d:g} x {br.D:g} x {br.B:g}", br.C0, br.C0_catalogue, load, S0,
                      printed[0], printed[1], printed[2]])
        d[f"bearing_{role}_C0_N"] = br.C0
        d[f"bearing_{role}_load_N"] = load
        d[f"bearing_{role}_S0"] = S0
        w.add_checks([Check.at_least(f"bearing_{role}.S0", S0, 1.0, "",
                                     f"ISO 76 C0 = {br.C0:.0f} N over the load {load:.0f} N ({br.designation})")])
    w.add_table("bearings", ["role", "designation", "d_x_D_x_B_mm", "C0_ISO76_N", "C0_thesis_Table8_N", "load_N",
                             "S0", "thesis_C0_N", "thesis_load_N", "thesis_S0"], brows)
    d.update({"track_pull_P_t_N": tf.P_t, "sprocket_axle_load_Q_N": tf.Q})

    # --- spline and shaft (seed 004 §4.3) ---------------------------------------------------------------
    sp_ = SPLINE_004
    spline = InvoluteSpline(sp_["D"], sp_["m"], sp_["z"])
    sigma_sm = spline_crushing_stress(p.sprocket_torque_Nm, spline.S_F, sp_["L"])
    allow = spline_allowable(sp_["sigma_T_hub"], sp_["n"], sp_["K_pr"], sp_["K_z"], sp_["K_p"])
    allow_printed = spline_allowable(sp_["sigma_T_printed"], sp_["n"], sp_["K_pr"], sp_["K_z"], sp_["K_p"])
    sh = shaft_equivalent_stress(tf.Q, SHAFT_004["L"], SHAFT_004["W_i"], p.sprocket_torque_Nm, SHAFT_004["W_k"],
                                 SHAFT_004["sigma_T"])
    d.update({"spline_S_u_mm3_per_mm": spline.S_F, "spline_sigma_MPa": sigma_sm, "spline_allowable_MPa": allow,
              "spline_margin": allow / sigma_sm, "spline_margin_thesis_785MPa": allow_printed / sigma_sm,
              "shaft_sigma_bending_MPa": sh.sigma_b, "shaft_tau_MPa": sh.tau, "shaft_sigma_eq_MPa": sh.sigma_eq,
              "shaft_margin": sh.margin})
    w.add_checks([
        Check.at_least("spline.margin", allow / sigma_sm, 1.0, "",
                       f"{spline.designation()}: σ = {sigma_sm:.3f} MPa, [σ]_sm = σ_T/(n·K_Σ) = {allow:.3f} MPa with "
                       f"the hub steel's σ_T = {sp_['sigma_T_hub']:g} MPa (thesis: 785 MPa → {allow_printed:.3f} MPa)"),
        Check.at_least("shaft.margin", sh.margin, 1.0, "",
                       f"σ_eq = √(σ² + 4τ²) = {sh.sigma_eq:.3f} MPa against σ_T = {SHAFT_004['sigma_T']:g} MPa"),
    ])
    w.add_note(
        f"Strength at the design torque M_vk.max = {p.sprocket_torque_Nm:.1f} N·m (seed 004 eq. 40 with t = 0.125 m; "
        f"printed 90 690 N·m), sun torque M_vk·Ω/i_sil = {T1 * p.n_planets:.1f} N·m (thesis 22 399 N·m), "
        f"{T1:.1f} N·m per mesh; relative pitch-line speed {v:.3f} m/s at {p.design_speed_kmh:g} km/h. "
        f"ISO 6336 (spur; K_Hβ by method C with the sun's torsional deformation f_sh under all {p.n_planets} meshes' "
        f"torque): sun–planet σ_H = {sp.sigma_H:.1f} MPa (S_H static = 44·HRC/σ_H = {sHmax / sp.sigma_H:.3f}), σ_F by method B sun "
        f"{sp.sigma_F1_B:.1f} MPa (S_F static = {sFlim / sp.sigma_F1_B:.3f}), planet {sp.sigma_F2_B:.1f} MPa "
        f"(method C: {sp.sigma_F1:.1f}, {sp.sigma_F2:.1f} MPa); planet–ring σ_H = {pr.sigma_H:.1f} MPa "
        f"(the planet's flank, Z_B = {pr.Z_B:.4f}; the ring's {pr.sigma_H_wheel:.1f} MPa; S_H static = "
        f"{sHmax / pr.sigma_H:.3f}), σ_F planet {pr.sigma_F1_B:.1f} MPa by method B "
        f"(S_F static = {sFlim / pr.sigma_F1_B:.3f}; method C {pr.sigma_F1:.1f} MPa). These static safeties set the "
        f"working stresses at the peak torque against the thesis's allowables: σ_Hmax = 44·HRC = {sHmax:.0f} MPa, "
        f"σ_FlimM = 2.8·σ_t = {sFlim:.0f} MPa, σ_Fmax = σ_FlimM/S_Fm = {sFlim / p.bending_safety_S_Fm:.0f} MPa; the thesis "
        f"computes no working stress. The contact formulas used here (Z_H, Z_E, Z_ε, Z_B, σ_H0: the helical "
        f"ones of gears/iso6336_helical.py at β = 0) reproduce the published ISO/TR 6336-30:2017 example 1 within 1 % "
        f"(σ_H0, σ_H; tests/test_iso6336_helical.py); no published root-stress example was at hand. "
        f"Face width needed: sun–planet {d['strength_sun_planet_face_width_required_mm']:.1f} mm, "
        f"planet–ring {d['strength_planet_ring_face_width_required_mm']:.1f} mm. The ring's root by ISO 6336-3 for "
        f"internal gears (substitute rack with the shaper's tip radius {p.shaper_tip_radius_star * p.module_mm:g} mm "
        f"as its fillet): σ_F {pr.sigma_F2_B:.1f} MPa by method B (S_F static = {sFlim / pr.sigma_F2_B:.3f}).")
    if abs(ps.coaxiality_mismatch) > 1e-9:
        from ...gears.iso6336 import MeshLoad, mesh_stress

        own = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, pr.b,
                          MeshLoad(T1 * p.z_planet / p.z_sun, v, p.application_factor_K_A, p.accuracy_grade))
        w.add_note(
            f"The planet–ring mesh is rated at the centre distance the carrier makes, a_w = {pr.a_w:.3f} mm "
            f"(α_w = {math.degrees(pr.alpha_w):.4f}°, ε_α = {pr.eps_alpha:.4f}, Z_H = {pr.Z_H:.4f}, Z_B = {pr.Z_B:.4f}, "
            f"σ_H = {pr.sigma_H:.1f} MPa), not at the {ps.mesh_planet_ring.a_w:.3f} mm of its shifts, which the thesis "
            f"uses (there: α_w = {math.degrees(own.alpha_w):.4f}°, ε_α = {own.eps_alpha:.4f}, Z_H = {own.Z_H:.4f}, "
            f"Z_B = {own.Z_B:.4f} — the thesis prints 1.205 —, σ_H = {own.sigma_H:.1f} MPa). The set is not coaxial: "
            f"the planets sit on the sun–planet centre distance, so the planet–ring teeth run "
            f"{pr.a_w - own.a_w:.3f} mm deeper than their shifts provide for (the overlap the sweep reports).")
    w.add_note(
        f"Bearings (ISO 76): planet bearing load eq. 44 = {P_sat:.0f} N with r_vod = a_w = {r_vod * 1e3:.3f} mm "
        f"(thesis: r_vod = 180 mm → 91 527 N, Table 8: 92 000 N), C0 = {PLANET_BEARING_004.C0:.0f} N, "
        f"S0 = {d['bearing_planet_S0']:.3f} (thesis 1.39); carrier bearing 3524: eq. 49 gives C0 = "
        f"{CARRIER_BEARING_004.C0:.0f} N, Table 8 lists 1 398 120 N; at Table 8's load 858 508 N S0 = "
        f"{d['bearing_carrier_S0']:.3f} (thesis 1.629; the text says R = 522 000 N for it). "
        f"Spline {spline.designation()}: S_u = {spline.S_F:.2f} mm³/mm, σ = {sigma_sm:.3f} MPa (thesis 117.164), "
        f"[σ]_sm = {allow:.3f} MPa with the hub's 630 MPa — margin {allow / sigma_sm:.3f}; the thesis uses 785 MPa: "
        f"{allow_printed:.3f} MPa, margin {allow_printed / sigma_sm:.3f} (printed 1.29). Carrier shaft: σ = "
        f"{sh.sigma_b:.3f} MPa, τ = {sh.tau:.3f} MPa, σ_eq = √(σ² + 4τ²) = {sh.sigma_eq:.3f} MPa (thesis 775.831, "
        f"printed as √(σ²·4τ²)), margin {sh.margin:.3f} (thesis 1.25).")
