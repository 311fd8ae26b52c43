"""The final drive's fatigue strength by ISO 6336 (pitting: part 2, bending: part 3, limits: part 5) for a service
life at the design torque, and the factor table of every strength calculation (sun–planet and planet–ring;
pitting and bending): each factor with its value, the method (A/B/C) it is determined by, the life point it is taken
at (the gear's N_L, or the static / reference point of a factor the life interpolates), the clause of ISO 6336 it
comes from (the 2006 editions' clause numbers unless a 2019 clause is named) and its basis.

Load cycles per hour of running at the design speed (every gear counted relative to the carrier):
sun n_s·k, planet n_s·z1/z2 (each flank once per turn in each mesh; its root is bent both ways, Y_M = 0.7),
ring n_c·k, with n_c the carrier's speed, n_s = n_c·(i − 1) the sun's relative speed and k planets.
"""

from __future__ import annotations

import math

from ...check import Check
from .design import FinalDriveDesign

__all__ = ["fatigue", "cycles_per_hour", "fatigue_rows"]

# clauses of the 2006 editions of ISO 6336-1/-2/-3 (and 6336-5:2003) each factor comes from
_SRC = {
    "F_t": "ISO 6336-1 cl. 3 (F_t = 2000·T_1/d_1)", "b": "ISO 6336-2 cl. 5 (common face width)",
    "u": "ISO 6336-2 cl. 5 (u = z2/z1, < 0 internal)", "K_A": "ISO 6336-1 cl. 5 / Annex A",
    "K_v": "ISO 6336-1 cl. 6.3 method B, Table 8", "f_sh": "ISO 6336-1 cl. 7 method C (torsion of the pinion under all its meshes' torque)",
    "f_ma": "ISO 6336-1 cl. 7 method C (f_ma = f_Hβ, ISO 1328-1)", "F_betax": "ISO 6336-1 cl. 7 method C",
    "y_beta": "ISO 6336-1 cl. 7 (running-in, hardened)", "F_betay": "ISO 6336-1 cl. 7 (F_βx − y_β)",
    "c_gamma_beta": "ISO 6336-1 cl. 9 (0.85·c_γα, c_γα = 20)", "K_Hbeta": "ISO 6336-1 cl. 7 method C",
    "N_F": "ISO 6336-1 cl. 7 (K_Fβ exponent)", "K_Fbeta": "ISO 6336-1 cl. 7 (K_Hβ^N_F)",
    "K_Halpha": "ISO 6336-1 cl. 8, Table 9", "K_Falpha": "ISO 6336-1 cl. 8, Table 9",
    "Z_H": "ISO 6336-2 cl. 6 (eq. 9)", "Z_E": "ISO 6336-2 cl. 8 (eq. 18)", "Z_eps": "ISO 6336-2 cl. 9 (eq. 25)",
    "Z_beta": "ISO 6336-2 cl. 10 (spur: 1)", "Z_B": "ISO 6336-2:2019 6.2 (M_1; an internal mate with z2 < 0)", "Z_D": "ISO 6336-2:2019 6.2 (M_2; internal wheel: 1)",
    "sigma_H0": "ISO 6336-2 cl. 5 (eq. 2)", "sigma_H": "ISO 6336-2 cl. 5 (eq. 1, 3)",
    "N_L": "ISO 6336-2 cl. 11 / ISO 6336-3 cl. 11 (load cycles)", "Z_NT": "ISO 6336-2 cl. 11, Table 2",
    "Z_L": "ISO 6336-2 cl. 12 method B", "Z_v": "ISO 6336-2 cl. 12 method B", "Z_R": "ISO 6336-2 cl. 12 method B",
    "Z_W": "ISO 6336-2 cl. 13 (both flanks case-hardened)", "Z_X": "ISO 6336-2 cl. 14",
    "Z_LvR": "ISO 6336-2:2019 5.4 method B (static to reference, log-log)",
    "Y_delta_relT_static": "ISO 6336-3:2019 cl. 12 method B (static, case-hardened)",
    "Y_dRX": "ISO 6336-3:2019 5.4 method B (static to reference, log-log)",
    "sigma_Hlim": "ISO 6336-5:2003 (case-hardened wrought steel)", "sigma_HG": "ISO 6336-2 cl. 5 (σ_Hlim·Z_NT·(Z_L·Z_v·Z_R at N_L)·Z_W·Z_X)",
    "S_H": "ISO 6336-2 cl. 5 (σ_HG/σ_H)", "S_H_static": "seed 004 ch. 4.1 (σ_Hmax = 44·HRC over σ_H)",
    "d_en": "ISO 6336-3 cl. 6 method B (outer point of single contact)", "Y_F": "ISO 6336-3 cl. 6 method B",
    "Y_S": "ISO 6336-3 cl. 7 method B", "q_s": "ISO 6336-3 cl. 7 (s_Fn/(2·ρ_F))",
    "b_F": "ISO 6336-3:2019 5.2 (wider face: narrower + at most 1 module each side)",
    "Y_beta": "ISO 6336-3 cl. 8 (spur: 1)", "Y_B": "ISO 6336-3 cl. 9 (rim thickness factor)",
    "Y_DT": "ISO 6336-3 cl. 9 (ε_α < 2.05: 1)", "sigma_F": "ISO 6336-3 cl. 5 method B",
    "Y_F_C": "ISO 6336-3:1996 method C (load at the tip)", "Y_S_C": "ISO 6336-3:1996 method C",
    "Y_eps": "ISO 6336-3:1996 (0.25 + 0.75/ε_α)", "sigma_F_C": "ISO 6336-3:1996 method C, for comparison",
    "Y_ST": "ISO 6336-3 cl. 5 (2.0)", "Y_NT": "ISO 6336-3 cl. 11, Table 3",
    "Y_delta_relT": "ISO 6336-3 cl. 12 method B", "Y_R_relT": "ISO 6336-3 cl. 13 method B",
    "Y_X": "ISO 6336-3 cl. 14", "Y_M": "ISO 6336-3 cl. 5 (idler: 0.7)",
    "sigma_Flim": "ISO 6336-5:2003 (case-hardened wrought steel)",
    "sigma_FG": "ISO 6336-3 cl. 5 (σ_Flim·Y_ST·Y_NT·(Y_δrelT·Y_RrelT·Y_X at N_L)·Y_M)", "S_F": "ISO 6336-3 cl. 5 (σ_FG/σ_F)",
    "S_F_static": "seed 004 ch. 4.1 (σ_FlimM = 2.8·σ_t over σ_F, method B)",
}


# the method (ISO 6336 A/B/C) each factor is determined by; "" for a quantity of the load or the geometry
_METHOD = {
    "K_v": "B", "f_sh": "C", "f_ma": "C", "F_betax": "C", "y_beta": "C", "F_betay": "C", "c_gamma_beta": "C",
    "K_Hbeta": "C", "N_F": "C", "K_Fbeta": "C", "K_Halpha": "C", "K_Falpha": "C",
    "Z_H": "B", "Z_E": "B", "Z_eps": "B", "Z_beta": "B", "Z_B": "B", "Z_D": "B", "sigma_H0": "B", "sigma_H": "B",
    "Z_NT": "B", "Z_L": "B", "Z_v": "B", "Z_R": "B", "Z_W": "B", "Z_X": "B", "Z_LvR": "B", "sigma_HG": "B",
    "S_H": "B", "d_en": "B", "Y_F": "B", "Y_S": "B", "q_s": "B", "Y_beta": "B", "Y_B": "B", "Y_DT": "B",
    "b_F": "B", "sigma_F": "B", "Y_F_C": "C", "Y_S_C": "C", "Y_eps": "C", "sigma_F_C": "C", "Y_ST": "B",
    "Y_NT": "B", "Y_delta_relT": "B", "Y_R_relT": "B", "Y_X": "B", "Y_M": "B", "Y_delta_relT_static": "B",
    "Y_dRX": "B", "sigma_FG": "B", "S_F": "B",
}
# the life point a life-dependent factor is taken at: the gear's N_L, or the reference / static point
_AT_N_L = {"N_L", "Z_NT", "Z_LvR", "sigma_HG", "S_H", "Y_NT", "Y_dRX", "sigma_FG", "S_F"}
_AT_POINT = {"Z_L": "5e7 (reference)", "Z_v": "5e7 (reference)", "Z_R": "5e7 (reference)",
             "Y_delta_relT": "3e6 (reference)", "Y_R_relT": "3e6 (reference)", "Y_X": "3e6 (reference)",
             "Y_delta_relT_static": "1e3 (static)"}


def cycles_per_hour(p, ps) -> dict[str, float]:
    """Load cycles per hour of running at the design speed: sun, planet, ring (see module docstring)."""
    n_c = p.design_speed_kmh / 3.6 / (p.sprocket_teeth * p.track_pitch_mm * 1e-3)  # rev/s of the carrier
    n_s = n_c * (ps.ratio - 1.0)
    return {"sun": 3600.0 * n_s * p.n_planets, "planet": 3600.0 * n_s * p.z_sun / p.z_planet,
            "ring": 3600.0 * n_c * p.n_planets}


def _hours(cycles: float, per_hour: float) -> float:
    return math.inf if cycles == math.inf or per_hour <= 0 else cycles / per_hour


def fatigue_rows(p, ps, sp, pr, v: float):
    """(rows of the factor table, {(mesh, gear): (Pitting, hours)}, {(mesh, gear): (RootFatigue, hours)})."""
    from ...gears.iso6336_life import (N_STATIC_F, N_STATIC_H, cycles_at_limit, pitting_safety, rho_red,
                                       root_fatigue_safety)

    cph = cycles_per_hour(p, ps)
    sHmax, sFlim = 44.0 * p.flank_hardness_HRC, 2.8 * p.core_yield_MPa
    rows, pit, root = [], {}, {}
    da = {"sun": ps.d_a_sun, "planet": ps.d_a_planet, "ring": ps.d_a_ring}

    for tag, s, mesh, (g1, g2) in (("sun_planet", sp, ps.mesh_sun_planet, ("sun", "planet")),
                                   ("planet_ring", pr, ps.mesh_planet_ring, ("planet", "ring"))):
        G1, G2 = mesh.gear1, mesh.gear2
        f = s.face
        rr = rho_red(G1.d_b, G2.d_b, s.alpha_w, mesh.internal)   # at the centre distance the carrier makes
        common = [
            ("F_t", s.F_t, "N", f"2000·T_1/d_1, T_1 = {s.F_t * s.d1 / 2000.0:.1f} N·m per mesh on d_1 = {s.d1:g} mm "
                                f"(the {g1}'s reference diameter)"),
            ("b", s.b, "mm", "the narrower face of the mesh"),
            ("u", s.u, "", f"z2/z1 = {G2.z}/{G1.z}" + (" (internal)" if mesh.internal else "")),
            ("K_A", s.K_A, "", "part parameter application_factor_K_A"),
            ("K_v", s.K_v, "", f"v = {v:.3f} m/s (relative to the carrier), z1 = {G1.z}, grade {p.accuracy_grade}, "
                               f"K_A·F_t/b = {s.K_A * s.F_t / s.b:.1f} N/mm (>= 100)"),
            ("f_sh", f.f_sh, "µm", f"0.023·(F_m/b)·(b/d_1)², F_m/b = {f.F_m_b:.1f} N/mm" if f.f_sh
             else f"0: the {g1} passes no torque through its body"),
            ("f_ma", f.f_ma, "µm", f"f_Hβ of ISO 1328-1 at d = {s.d1:g} mm, b = {s.b:g} mm, grade {p.accuracy_grade}"),
            ("F_betax", f.F_betax, "µm", "1.33·f_sh + f_ma"),
            ("y_beta", f.y_beta, "µm", "0.15·F_βx, at most 6 µm"),
            ("F_betay", f.F_betay, "µm", "F_βx − y_β"),
            ("c_gamma_beta", f.c_gamma_beta, "N/(mm·µm)", "0.85·c_γα, c_γα = 20 N/(mm·µm)"),
        ]
        khb = [("K_Hbeta", s.K_Hbeta, "", f"1 + c_γβ·F_βy/(2·F_m/b), F_m = F_t·K_A·K_v = {f.F_m_b * s.b:.0f} N")]
        kfb = [("N_F", f.N_F, "", f"(b/h)²/(1 + b/h + (b/h)²), h = (d_a1 − d_f1)/2 = {f.h:.3f} mm"),
               ("K_Fbeta", s.K_Fbeta, "", "K_Hβ^N_F")]
        # -- pitting
        sig = {g1: s.sigma_H, g2: s.sigma_H_wheel}
        prow = [(*t, "") for t in common + khb + [
            ("K_Halpha", s.K_Halpha, "", f"Table 9, surface-hardened spur, grade {p.accuracy_grade}"),
            ("Z_H", s.Z_H, "", f"α = 20°, α_w = {math.degrees(s.alpha_w):.4f}° at a_w = {s.a_w:.3f} mm (the carrier's)"),
            ("Z_E", s.Z_E, "√MPa", "steel on steel: E = 206 000 MPa, ν = 0.3 both"),
            ("Z_eps", s.Z_eps, "", f"√((4 − ε_α)/3), ε_α = {s.eps_alpha:.4f}"),
            ("Z_beta", 1.0, "", "β = 0"),
            ("Z_B", s.Z_B, "", f"{g1}: max(1, M_1)" + (" with the ring's internal geometry (z2, d_a2, d_b2 < 0)"
                                                         if mesh.internal else "")),
            ("Z_D", s.Z_D, "", f"{g2}: max(1, M_2)" + (" (internal wheel: 1)" if mesh.internal else "")),
            ("sigma_H0", s.sigma_H0, "MPa", "Z_H·Z_E·Z_ε·Z_β·√(F_t/(d_1·b)·(u + 1)/u)"),
        ]]
        for g, zf in ((g1, "Z_B"), (g2, "Z_D")):
            P = pitting_safety(sig[g], p.sigma_Hlim_MPa, cph[g] * p.service_life_h, p.oil_viscosity_40_mm2_s, v,
                               p.flank_roughness_Rz_um, p.flank_roughness_Rz_um, rr, p.pitting_safety_S_Hmin)
            hours = _hours(cycles_at_limit(P.limit_at, p.pitting_safety_S_Hmin * sig[g], N_STATIC_H), cph[g] * 1.0)
            pit[(tag, g)] = (P, hours)
            prow += [(*t, g) for t in [
                ("sigma_H", sig[g], "MPa", f"{zf}·σ_H0·√(K_A·K_v·K_Hβ·K_Hα)"),
                ("N_L", P.N_L, "", f"{cph[g]:.0f} cycles/h × {p.service_life_h:g} h"),
                ("Z_NT", P.Z_NT, "", f"case-hardened steel at N_L"),
                ("Z_L", P.Z_L, "", f"ν_40 = {p.oil_viscosity_40_mm2_s:g} mm²/s, σ_Hlim = {p.sigma_Hlim_MPa:g} MPa"),
                ("Z_v", P.Z_v, "", f"v = {v:.3f} m/s"),
                ("Z_R", P.Z_R, "", f"R_z = {p.flank_roughness_Rz_um:g} µm, ρ_red = {rr:.3f} mm, R_z10 = {P.R_z10:.3f} µm"),
                ("Z_W", P.Z_W, "", "both flanks case-hardened"),
                ("Z_X", P.Z_X, "", "size factor of pitting"),
                ("Z_LvR", P.Z_LvR, "", f"Z_L·Z_v·Z_R at N_L: reference {P.Z_L * P.Z_v * P.Z_R:.4f} (N >= 5e7), "
                                       f"static 1 (N <= 1e5), log-log between, w = {P.w:.4f}"),
                ("sigma_Hlim", p.sigma_Hlim_MPa, "MPa", "part parameter sigma_Hlim_MPa"),
                ("sigma_HG", P.sigma_HG, "MPa", f"pitting limit at N_L"),
                ("S_H", P.S_H, "", f"required {p.pitting_safety_S_Hmin:g}"),
                ("S_H_static", sHmax / sig[g], "", f"44·HRC = {sHmax:.0f} MPa over σ_H"),
            ]]
        rows += [[tag, "pitting", *r] for r in prow]
        # -- bending (method B checks, method C beside)
        brow = [(*t, "") for t in common + khb + kfb + [("K_Falpha", s.K_Falpha, "", f"Table 9, grade {p.accuracy_grade}")]]
        gears = [(g1, G1, da[g1], s.root1_B, s.d_en1, s.sigma_F1_B, s.Y_F1, s.Y_S1, s.sigma_F1, s.b_F1)]
        if s.sigma_F2_B is not None:
            gears.append((g2, G2, da[g2], s.root2_B, s.d_en2, s.sigma_F2_B, s.Y_F2, s.Y_S2, s.sigma_F2, s.b_F2))
        for g, G, d_a, tf, d_en, sF, YFc, YSc, sFc, bF in gears:
            idler = g == "planet"
            q_s = tf.s_Fn / (2.0 * tf.rho_F)
            R = root_fatigue_safety(sF, q_s, mesh.m, p.sigma_Flim_MPa, p.root_roughness_Rz_um,
                                    cph[g] * p.service_life_h, p.bending_fatigue_safety_S_Fmin, idler, Y_S=tf.Y_S)
            hours = _hours(cycles_at_limit(R.limit_at, p.bending_fatigue_safety_S_Fmin * sF, N_STATIC_F), cph[g] * 1.0)
            root[(tag, g)] = (R, hours)
            brow += [(*t, g) for t in [
                ("d_en", d_en, "mm", f"outer point of single contact (d_a = {d_a:.3f} mm, ε_α = {s.eps_alpha:.4f})"),
                ("Y_F", tf.Y_F, "", f"method B, s_Fn = {tf.s_Fn:.3f} mm, h_Fe = {tf.h_Fe:.3f} mm, the tooth as made "
                                    f"(thinned by E_sn = {p.tooth_thinning_mm:g} mm)"
                                    + (", internal gear: substitute rack, ρ_fP = the shaper's tip radius"
                                       if G.internal else "")),
                ("Y_S", tf.Y_S, "", f"method B, ρ_F = {tf.rho_F:.3f} mm"
                                    + ("" if 1.0 <= q_s < 8.0 else f"; q_s = {q_s:.2f} outside the formula's 1 <= q_s < 8")),
                ("q_s", q_s, "", f"s_Fn/(2·ρ_F)"),
                ("Y_beta", 1.0, "", "β = 0"),
                ("Y_B", s.Y_B2 if G.internal else 1.0, "",
                 "internal gear: the rim under the root (1 from s_R >= 3.5·m)" if G.internal else "solid rim"),
                ("Y_DT", 1.0, "", "ε_α < 2.05"),
                ("b_F", bF, "mm", f"face the root is bent over: the common {s.b:g} mm plus at most one module each "
                                  f"side, within the {g}'s own face"),
                ("sigma_F", sF, "MPa", f"F_t/(b_F·m)·Y_F·Y_S·Y_B·K_A·K_v·K_Fβ·K_Fα, m = {mesh.m:g} mm "
                                       f"(method B: the checks use it)"),
                ("Y_F_C", YFc, "", f"load at the tip d_a = {d_a:.3f} mm"),
                ("Y_S_C", YSc, "", f"load at the tip"),
                ("Y_eps", s.Y_eps, "", f"ε_α = {s.eps_alpha:.4f}"),
                ("sigma_F_C", sFc, "MPa", f"F_t/(b·m)·Y_F·Y_S·Y_ε·K (method C, for comparison)"),
                ("N_L", R.N_L, "", f"{cph[g]:.0f} cycles/h × {p.service_life_h:g} h"),
                ("Y_ST", R.Y_ST, "", "stress correction factor of the test gear"),
                ("Y_NT", R.Y_NT, "", f"case-hardened steel at N_L"),
                ("Y_delta_relT", R.Y_delta_relT, "", f"q_s = {q_s:.3f}, ρ' = 0.003 mm (case-hardened)"),
                ("Y_R_relT", R.Y_R_relT, "", f"root R_z = {p.root_roughness_Rz_um:g} µm"),
                ("Y_X", R.Y_X, "", f"m = {mesh.m:g} mm, surface-hardened"),
                ("Y_M", R.Y_M, "", "idler, bent both ways" if idler else "bent one way"),
                ("Y_delta_relT_static", R.Y_delta_relT_static, "", f"0.44·Y_S + 0.12, Y_S = {tf.Y_S:.4f}"),
                ("Y_dRX", R.Y_dRX, "", f"Y_δrelT·Y_RrelT·Y_X at N_L: reference "
                                       f"{R.Y_delta_relT * R.Y_R_relT * R.Y_X:.4f} (N >= 3e6), static "
                                       f"{R.Y_delta_relT_static:.4f} (N <= 1e3), log-log between, w = {R.w:.4f}"),
                ("sigma_Flim", p.sigma_Flim_MPa, "MPa", "part parameter sigma_Flim_MPa"),
                ("sigma_FG", R.sigma_FG, "MPa", f"root stress limit at N_L"),
                ("S_F", R.S_F, "", f"required {p.bending_fatigue_safety_S_Fmin:g}"),
                ("S_F_static", sFlim / sF, "", f"2.8·σ_t = {sFlim:.0f} MPa over σ_F"),
            ]]
        rows += [[tag, "bending", *r] for r in brow]
    def life_point(tag, calc, gear, sym):
        if sym in _AT_POINT:
            return _AT_POINT[sym]
        if sym in _AT_N_L and gear:
            return f"{(pit if calc == 'pitting' else root)[(tag, gear)][0].N_L:.4g}"
        return ""

    rows = [[t, c, gear, sym, val, unit, _METHOD.get(sym, ""), life_point(t, c, gear, sym), _SRC[sym], basis]
            for t, c, sym, val, unit, basis, gear in rows]
    return rows, pit, root


def fatigue(dd: FinalDriveDesign, w, built: dict) -> None:
    """Pitting and bending fatigue safeties of every flank and root for the service life; the factor table."""
    from .strength import _loads, mesh_stresses

    p, ps = dd.p, dd.ps
    w.progress("strength: ISO 6336 fatigue safeties and factor table")
    d = w.derived
    _, v = _loads(p, ps)
    sp, pr = mesh_stresses(p, ps)
    rows, pit, root = fatigue_rows(p, ps, sp, pr, v)
    checks, said = [], []
    for (tag, g), (P, hours) in pit.items():
        d[f"strength_{tag}_S_H_pitting_{g}"] = P.S_H
        d[f"strength_{tag}_pitting_life_{g}_h"] = hours
        w.describe(f"strength_{tag}_S_H_pitting_{g}", "", f"pitting fatigue safety σ_HG/σ_H of the {g}'s flank (ISO 6336-2)")
        w.describe(f"strength_{tag}_pitting_life_{g}_h", "h",
                   f"running time at the design torque after which the {g}'s pitting safety falls to S_Hmin")
        checks.append(Check.at_least(
            f"strength_{tag}.S_H_pitting_{g}", P.S_H, p.pitting_safety_S_Hmin, "",
            f"ISO 6336-2 pitting fatigue: σ_HG = {P.sigma_HG:.1f} MPa (σ_Hlim = {p.sigma_Hlim_MPa:g} MPa, "
            f"Z_NT = {P.Z_NT:.4f} at N_L = {P.N_L:.3g}) over σ_H = {P.sigma_HG / P.S_H:.1f} MPa"))
        said.append(f"{tag.replace('_', '–')} mesh, {g} flank S_H = {P.S_H:.3f} ({_life(hours, 'S_Hmin')})")
    for (tag, g), (R, hours) in root.items():
        d[f"strength_{tag}_S_F_fatigue_{g}"] = R.S_F
        d[f"strength_{tag}_bending_life_{g}_h"] = hours
        w.describe(f"strength_{tag}_S_F_fatigue_{g}", "", f"bending fatigue safety σ_FG/σ_F of the {g}'s root (ISO 6336-3 method B)")
        w.describe(f"strength_{tag}_bending_life_{g}_h", "h",
                   f"running time at the design torque after which the {g}'s bending safety falls to S_Fmin")
        checks.append(Check.at_least(
            f"strength_{tag}.S_F_fatigue_{g}", R.S_F, p.bending_fatigue_safety_S_Fmin, "",
            f"ISO 6336-3 bending fatigue (method B): σ_FG = {R.sigma_FG:.1f} MPa (σ_Flim = {p.sigma_Flim_MPa:g} MPa, "
            f"Y_NT = {R.Y_NT:.4f} at N_L = {R.N_L:.3g}, Y_M = {R.Y_M:g}) over σ_F = {R.sigma_FG / R.S_F:.1f} MPa"))
        said.append(f"{tag.replace('_', '–')} mesh, {g} root S_F = {R.S_F:.3f} ({_life(hours, 'S_Fmin')})")
    w.add_checks(checks)
    cph = cycles_per_hour(p, ps)
    d.update({f"load_cycles_per_hour_{g}": x for g, x in cph.items()})
    for g in cph:
        w.describe(f"load_cycles_per_hour_{g}", "1/h", f"load cycles of a {g} tooth per hour at the design speed")
    w.add_table("strength_factors", ["mesh", "calculation", "gear", "factor", "value", "unit", "method", "N_L",
                                     "source", "basis"], rows)
    w.add_note(
        f"Fatigue (ISO 6336-2 pitting, ISO 6336-3 method B bending, limits of ISO 6336-5) for {p.service_life_h:g} h "
        f"at the design torque and {p.design_speed_kmh:g} km/h (seed 004 prints no duty: this running time is the "
        f"part file's service_life_h), σ_Hlim = {p.sigma_Hlim_MPa:g} MPa, σ_Flim = {p.sigma_Flim_MPa:g} MPa, "
        f"ν_40 = {p.oil_viscosity_40_mm2_s:g} mm²/s, flank R_z {p.flank_roughness_Rz_um:g} µm, root R_z "
        f"{p.root_roughness_Rz_um:g} µm; load cycles per hour: sun {cph['sun']:.0f}, planet {cph['planet']:.0f}, "
        f"ring {cph['ring']:.0f}. " + "; ".join(said) + ". K_Hβ of the sun–planet mesh includes the sun's torsional "
        f"deformation f_sh = {sp.face.f_sh:.2f} µm (F_βx = 1.33·f_sh + f_ma = {sp.face.F_betax:.2f} µm): "
        f"K_Hβ = {sp.K_Hbeta:.4f}. Every factor with its clause and basis: tables/strength_factors.csv.")
    for tag, calc, title in (("sun_planet", "pitting", "Sun–planet pitting"), ("sun_planet", "bending", "Sun–planet bending"),
                             ("planet_ring", "pitting", "Planet–ring pitting"),
                             ("planet_ring", "bending", "Planet–ring bending")):
        items = [f"{r[3]}{(' of the ' + r[2]) if r[2] else ''} = {_fmt(r[4])}{(' ' + r[5]) if r[5] else ''} "
                 f"({r[8]}{'; method ' + r[6] if r[6] else ''}{'; at N = ' + r[7] if r[7] else ''}; {r[9]})"
                 for r in rows if r[0] == tag and r[1] == calc]
        w.add_note(f"ISO 6336 factor table, {title}: " + "; ".join(items) + ".")


def _life(hours: float, what: str) -> str:
    if hours == math.inf:
        return f"never falls to {what}: the life factor's floor 0.85 at 1e10 cycles keeps it above"
    return f"falls to {what} after {hours:.4g} h"


def _fmt(x: float) -> str:
    if x == math.inf:
        return "inf"
    a = abs(x)
    return f"{x:.4g}" if a < 1e-3 or a >= 1e5 else (f"{x:.4f}" if a < 10 else f"{x:.2f}")
