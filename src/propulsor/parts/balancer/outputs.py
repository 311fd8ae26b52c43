"""The balancer's outputs: the suspension table against the seed's printed numbers, solids, mass
properties, assembly, DXF, notes; and its build."""

from __future__ import annotations

import math

import numpy as np

from ...check import Check
from ...parallel import start as start_in_fork
from .damper import damper_heat_results, start_damper_heat
from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import travel_animation
from .design import RHO_STEEL_KG_MM3, THESIS, BalancerModel, resolve
from .plots import characteristic_plot, side_view_plot
from .proofs import socket_ear_pad_checks, strength_proof, sweep_job, travel_sweep_checks
from .solids import balancer_solid, sweep_mesh

__all__ = ["build", "suspension_rows", "printed_digits"]


# ------------------------------------------------------------------------------------------------
# reporting helpers
# ------------------------------------------------------------------------------------------------
def suspension_rows(m: BalancerModel) -> list:
    """Quantity, symbol, equation, computed, unit, printed, note."""
    from ...laws.suspension import equivalent_stiffness, pitch_period

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
        ("elastic force at beta_m", "P(beta_m)", "13", t.P_m, "N", None, "≈ 94 kN: three times the static wheel load"),
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
PRINTED_AS = {"gamma_m_deg": "96.043", "gamma_st_deg": "24.358", "beta0_deg": "19", "beta_m_deg": "115",
               "f_st_m": "0.078", "f_full_m": "0.492", "f_dyn_m": "0.414", "d_T_m": "0.046", "lambda_m": "0.822",
               "lambda_ut_m": "0.822", "c_prime_N_per_m": "2.138e5", "c_N_per_m": "164400", "mu_mean": "3.426e4",
               "mu_reb_max": "5.229e4", "mu_reb": "4.031e4", "mu_comp": "28220", "T_phi_s": "1.8",
               "R_k_comp_max_N": "2.134e4", "D_piston_m": "0.11"}


def quantum(text: str) -> float:
    """Value of one unit in the last printed digit of a number as printed ("2.138e5" -> 100)."""
    t = text.lower()
    if "e" in t:
        mant, exp = t.split("e")
        dec = len(mant.split(".")[1]) if "." in mant else 0
        return 10.0 ** (int(exp) - dec)
    if "." in t:
        return 10.0 ** -len(t.split(".")[1])
    return 10.0 ** (len(t) - len(t.rstrip("0")))


def printed_digits(v, printed) -> bool | None:
    """Does the computed value show the printed number to its printed digits?"""
    if printed is None:
        return None
    key = next((k for k, x in THESIS.items() if x == printed), None)
    q = quantum(PRINTED_AS[key]) if key in PRINTED_AS else 10.0 ** (math.floor(math.log10(abs(printed))) - 3)
    return bool(round(v / q) == round(printed / q))



def suspension_outputs(m: BalancerModel, w, built: dict) -> None:
    """The seed's suspension calculation against every printed number; the elastic characteristic."""
    t, d = m.tor, m.design
    D = w.derived
    w.progress("inputs: suspension, road wheel, beam model, outline")
    rows = suspension_rows(m)
    w.add_table("suspension", ["quantity", "symbol", "equation", "computed", "unit", "printed", "printed_digits_match",
                               "note"],
                [[q, s, e, v, u, pr, printed_digits(v, pr), note] for (q, s, e, v, u, pr, note) in rows])
    c = t.characteristic(int(round(math.degrees(t.beta_m - t.beta0) * 4)) + 1)
    w.add_table("elastic_characteristic", {"beta_deg": np.degrees(c["beta"]), "f_mm": c["f"], "P_N": c["P"],
                                           "M_T_Nm": c["M_T"] / 1000.0, "tau_bar_MPa": t.tau(c["beta"])}, None)
    w.add_plot("elastic_characteristic", characteristic_plot(m))
    D.update({
        "gamma_m_deg": math.degrees(t.gamma_m), "gamma_st_deg": math.degrees(t.gamma_st),
        "beta0_deg": math.degrees(t.beta0), "beta_m_deg": math.degrees(t.beta_m), "f_st_mm": t.f_st,
        "f_full_mm": t.f_full, "f_dyn_mm": t.f_dyn, "P_at_beta_m_N": t.P_m, "M_T_max_Nm": t.M_T_max / 1000,
        "lambda_ut_mm": t.lambda_ut, "c_prime_printed_lambda_N/m": suspension_rows(m)[11][3],
        "c_static_N/m": d.c_static, "mu_mean_eq23_Ns/m": d.mu_mean, "R_k_comp_max_N": d.R_k_comp_max,
        "L_a_mm": d.L_a, "R_a_comp_max_N": d.R_a_comp_max, "R_a_reb_max_N": d.R_a_reb_max,
        "D_piston_mm": d.D_piston, "station_pitch_mm": m.pitch,
    })
    w.add_checks([Check.at_most("torsion bar shear at beta_m", float(t.tau(t.beta_m)), t.tau_max * (1 + 1e-12), "MPa",
                                "τ = G d_T (β_m − β0) / (2 L_T) <= [τ]max (eq. 7)")])



def solids_and_sweep_start(m: BalancerModel, w, built: dict) -> None:
    """The balancer and road-wheel solids, their sweep meshes, the travel sweep started in a forked worker,
    mass properties, the assembly at β_st, the arm outline's DXF, the side view."""
    from ...solids.kernel import mass_properties, z_rotation
    from ...solids.road_wheel import wheel_solids

    p, t, an = m.p, m.tor, m.analysis
    D = w.derived
    h_built = built["h_built"]
    w.progress("solids: balancer (plate ∪ upper axle ∪ spindle − socket, bores) and the road wheel")
    bal = balancer_solid(m)
    wsol = wheel_solids(m.wheel)
    w.progress("sweep meshes")
    bal_mesh = sweep_mesh(bal, p.sweep_chord_mm)
    wheel_meshes = [sweep_mesh(s_, p.sweep_chord_mm) for s_ in wsol.values()]
    for s_, (V, F) in zip(wsol.values(), wheel_meshes):  # the assembly's GLB and picture reuse them
        w.add_known_mesh(s_, V, F)
    w.progress(f"travel sweep β0 … β_m ({int(math.ceil(math.degrees(t.beta_m - t.beta0) * p.sweep_steps_per_deg)) + 1} "
               "steps × hull + 2 neighbours), in a second process while the solids are checked")
    from ...progress import count_to

    built["pending_sweep"] = start_in_fork(sweep_job, m, bal_mesh, wheel_meshes,
                                           counter=count_to(w.progress, "travel sweep", "body"))
    w.add_solid("balancer", bal, expected_genus=3)
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
    th = math.degrees(t.beta_st - math.pi / 2)
    comps = [("balancer", bal, z_rotation(th))]
    for nm, s_ in wsol.items():
        comps.append((f"road_wheel_{nm}", s_, z_rotation(th, (p.R_b_mm, 0.0, m.z_hub))))
    w.add_assembly("assembly_beta_st", comps, picture_from_below=True)  # seen from above the wheel hides the arm
    built["assembly_components"] = [c[0] for c in comps]  # they all turn with the arm (the 3D view's motion)

    # DXF of the arm's side outline (plate blank)
    refs = [("line", {"p0": (-p.upper_boss_r_mm - 10, 0.0), "p1": (p.R_b_mm + p.lower_boss_r_mm + 10, 0.0)}),
            ("circle", {"center": (0.0, 0.0), "radius": 0.5 * p.d_upper_mm}),
            ("circle", {"center": (0.0, 0.0), "radius": 0.5 * p.bolt_bore_d_mm}),
            ("circle", {"center": (p.R_b_mm, 0.0), "radius": 0.5 * m.wheel_p.bearing_inner_d_mm}),
            ("line", {"p0": (m.pad[0], m.pad[2]), "p1": (m.pad[1], m.pad[2])})]
    w.add_dxf("balancer_arm_outline", [m.outline.profile], refs)
    w.add_plot("side_view", side_view_plot(m))
    built.update(mass=mass, com=com, wm_tot=wm_tot)


def notes(m: BalancerModel, w, built: dict) -> None:
    p, t, d = m.p, m.tor, m.design
    D = w.derived
    allow, h_eq, s, sig, body_el, sc, trs = (built[k] for k in ("allow", "h_eq", "s", "sig", "body_el", "sc", "trs"))
    mass, com, wm_tot, betas, own_gap, pc, nrm = (built[k] for k in ("mass", "com", "wm_tot", "betas", "own_gap",
                                                                     "pc", "nrm"))
    sp = m.spline
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


start_animation, collect_animation = pipeline_steps(travel_animation)

build = Pipeline(lambda p, w: design_of(p, resolve, getattr(w, "source", None)),
                 (suspension_outputs, strength_proof, socket_ear_pad_checks, solids_and_sweep_start,
                  start_damper_heat, travel_sweep_checks, start_animation, damper_heat_results, notes, collect_animation))
