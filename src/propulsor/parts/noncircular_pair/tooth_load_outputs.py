"""The load per tooth of the pair over its cycle (seed 002: "one of the expected drawbacks of the design
will be the uneven distribution of the load between different teeth"): the load case over one period, its sharing
between the tooth pairs in contact on the finished outlines, the contact stress of every pair and the root stress of
every tooth at every phase, the peak of each tooth, its safeties against the material's limits, the load cycles of
each tooth per driven turn — tables, a plot, checks with the part file's required safeties, derived values.

The contacts are the as-built ones: the drive direction's resolved contact law (:mod:`.as_built`) places the driven
wheel at each phase, and :func:`checks.motion.mesh_load.phase_contacts` lists every tooth pair within reach with its
gap; the math is :mod:`propulsor.gears.tooth_load` (sharing by ISO 6336-1's single stiffness c′ of the local
equivalent gears, Hertz with the flanks' measured curvatures, ISO 6336-3's 30° section on each tooth's real outline).
The driven teeth of one period stand for their repeats in the other periods (the pair repeats, :func:`.as_built
.period_span`); each driver tooth meshes ``n`` times per driven turn at the same phase of the law.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ... import policy
from ...check import Check
from ...progress import count_to

__all__ = ["ToothLoad", "analyse", "summary", "equilibrium", "tooth_load_values", "contact_and_load", "FACTOR_SOURCES",
           "PHASE_COLUMNS", "PEAK_COLUMNS"]

#: every factor of the report's factor table with its source
FACTOR_SOURCES = {
    "K_A": "ISO 6336-1:2006 cl. 5 / Annex A (the part file's load_K_A)",
    "K_v": "ISO 6336-1:2006 cl. 6 (the part file's load_K_v; not computed: a slow drive)",
    "K_Hbeta": "ISO 6336-1:2006 cl. 7 (the part file's load_K_beta)",
    "K_Fbeta": "ISO 6336-1:2006 cl. 7 (taken = K_Hbeta)",
    "K_Halpha": "replaced by the explicit sharing between the tooth pairs on the as-built outlines (gears/tooth_load.py)",
    "c_prime": "ISO 6336-1:2006 9.3, eq. 60-63 and Table 12 (C_M = 0.8, C_R = 1, C_B of the rack) at the local "
               "equivalent gears z_n = 2 rho / m of the pitch curves, times E/E_steel",
    "Z_E": "ISO 6336-2:2006 eq. 18 (E, nu of the material catalogue)",
    "Z_H_Z_eps_Z_B": "not used: the Hertz stress with the flanks' radii of curvature measured at each contact point "
                     "on the outlines and the pair's own share of the load replaces them",
    "sigma_H": "Hertz line contact, Z_E sqrt(F_n K_A K_v K_Hbeta / (b rho_red))",
    "s_Fn": "ISO 6336-3:2006 cl. 6: chord between the 30 deg tangent points of the real fillets (tooth axis: the "
            "pitch curve's normal at the tooth centre)",
    "rho_F": "ISO 6336-3:2006 cl. 6: radius of curvature of the real fillet at its 30 deg point (tension side)",
    "h_Fe": "ISO 6336-3:2006 cl. 6: bending arm of the load at its point of application on the real flank",
    "alpha_Fen": "ISO 6336-3:2006 cl. 6: angle of the load's line to the section",
    "Y_F": "ISO 6336-3:2006 eq. 10 form: 6 (h_Fe/m) cos alpha_Fen / ((s_Fn/m)^2 cos alpha_n)",
    "Y_S": "ISO 6336-3:2006 eq. 39: (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L))",
    "Y_epsilon": "not used: the load is placed where it acts with its own share",
    "sigma_F": "ISO 6336-3:2006 cl. 5: 6 M / (b s_Fn^2) Y_S K_A K_v K_Fbeta = F_t/(b m) Y_F Y_S K_A K_v K_Fbeta",
    "sigma_Hlim": "the material catalogue (gears/data/gear_materials.toml)",
    "sigma_FE": "the material catalogue: sigma_Flim Y_ST (steels, Y_ST = 2) or the printed XY strength",
    "Z_NT": "ISO 6336-2:2006 Table 2 (steels; 1 at the endurance limit; printed: static, 1)",
    "Y_NT": "ISO 6336-3:2006 Table 3 (steels; 1 at the endurance limit; printed: static, 1)",
    "Z_L_Z_v_Z_R_Z_W_Z_X": "1 (not rated: no lubricant, roughness or size data for this pair)",
    "Y_deltarelT_Y_RrelT_Y_X": "1 (not rated)",
    "S_H": "ISO 6336-2:2006 cl. 5: sigma_Hlim Z_NT / sigma_H",
    "S_F": "ISO 6336-3:2006 cl. 5: sigma_FE Y_NT / sigma_F",
}

PHASE_COLUMNS = ["driver_deg", "driven_deg", "T1_Nm", "T2_Nm", "pairs_loaded", "driver_tooth", "driven_tooth",
                 "gap_um", "share", "F_n_N", "l1_mm", "l2_mm", "rho_driver_mm", "rho_driven_mm", "sigma_H_MPa",
                 "sigma_F_driver_MPa", "sigma_F_driven_MPa", "h_Fe_driver_mm", "h_Fe_driven_mm", "Y_F_driver",
                 "Y_S_driver", "Y_F_driven", "Y_S_driven", "corner", "r_driver_mm", "r_driven_mm"]
PEAK_COLUMNS = ["gear", "tooth", "measured_as", "cycles_per_driven_turn", "F_n_max_N", "sigma_H_max_MPa",
                "sigma_H_at_driver_deg", "sigma_F_max_MPa", "sigma_F_at_driver_deg", "s_Fn_mm", "rho_F_mm", "S_H",
                "S_F"]


@dataclass
class _Peak:
    F: float = 0.0
    sH: float = 0.0
    sH_at: float = math.nan
    sF: float = 0.0
    sF_at: float = math.nan


@dataclass
class ToothLoad:
    """The load per tooth over one period (see the module docstring)."""

    rows: list                  #: one row per loaded pair and phase (PHASE_COLUMNS)
    theta: np.ndarray           #: driver angle of every phase, rad (sorted)
    phi: np.ndarray
    T1: np.ndarray              #: N·m
    T2: np.ndarray
    loaded: np.ndarray          #: loaded pairs per phase
    imbalance: float            #: largest |sum F l1 - T1| / T1 over the phases
    lost: int                   #: phases without a contact
    peaks: dict                 #: gear -> {tooth: _Peak} (measured teeth)
    sections: dict              #: gear -> {tooth: RootSection}
    load_case: str
    material: object
    Z_E: float
    c_prime: tuple              #: (min, max) N/(mm·µm)
    K_H: float
    K_F: float
    window_rad: float
    evaluations: int
    teeth: dict = field(default_factory=dict)   #: gear -> number of teeth
    repeat: dict = field(default_factory=dict)  #: gear -> teeth per period (a tooth j stands for j mod it)
    cycles: dict = field(default_factory=dict)  #: gear -> load cycles per driven turn

    def tooth_peak(self, gear: str, j: int) -> tuple[_Peak, str]:
        """The peak of tooth j of ``gear`` and how it was measured ("measured", or "as tooth k": the tooth of the
        measured period it repeats)."""
        q = self.repeat[gear] or self.teeth[gear]
        k = j % q
        pk = self.peaks[gear].get(k)
        if pk is None:
            return _Peak(math.nan, math.nan, math.nan, math.nan, math.nan), "not loaded"
        return pk, "measured" if k == j else f"as tooth {k}"

    def section_of(self, gear: str, j: int):
        q = self.repeat[gear] or self.teeth[gear]
        return self.sections[gear].get(j % q) or next((s for i, s in self.sections[gear].items() if i % q == j % q),
                                                      None)


def _fold(peaks: dict, q: int) -> dict:
    """The peaks of the teeth measured over one period folded onto the teeth of one period (j mod q): a tooth whose
    mesh the period's ends split is measured in two pieces, under two numbers of the same class."""
    out = {}
    for j, pk in peaks.items():
        k = j % q
        o = out.setdefault(k, _Peak())
        o.F = max(o.F, pk.F)
        if pk.sH > o.sH:
            o.sH, o.sH_at = pk.sH, pk.sH_at
        if pk.sF > o.sF:
            o.sF, o.sF_at = pk.sF, pk.sF_at
    return out


def _loads(p, d, phi):
    """(T1, T2, text) at the law phases phi (N·m)."""
    from ...gears.tooth_load import torques
    from ...laws.law import is_walking

    U = np.asarray(d.run_law.U(phi), float)
    dX = np.asarray(d.law.dX01_dphi(phi), float) if is_walking(d.law) and p.load_vehicle_mass_kg > 0 else None
    return torques(U, T1_Nm=p.load_driver_torque_Nm, power_W=p.load_power_W, speed_rpm=p.load_driver_speed_rpm,
                   eta=p.load_efficiency, vehicle_mass_kg=p.load_vehicle_mass_kg,
                   rolling_resistance=p.load_rolling_resistance, propulsors=p.load_propulsors, dX01_dphi=dX)


def analyse(d, mount: float, p, c_phi, c_te, phi0: float, span: float, step_deg: float | None = None,
            direction: int = 1, tick=None) -> ToothLoad:
    """The load per tooth over the law phases phi0 .. phi0 + span of design ``d`` mounted at ``mount`` under the part
    file's load case; ``c_phi``, ``c_te``: the resolved contact of ``direction`` (as-built driven offset te at the
    law phases c_phi; ``checks.motion.contact_events.DRIVE`` = 1, the driver turning counter-clockwise, or REVERSE =
    -1: the other flanks loaded) the driven wheel is placed by.  ``tick(done, total)``: told the sampled
    positions evaluated (progress only)."""
    from ...checks.motion.contact_events import _phi_of_theta
    from ...checks.motion.mesh_load import phase_contacts
    from ...gears.gear_materials import material
    from ...gears.iso6336 import z_e
    from ...gears.pitch_frame import BodyPitchCurve
    from ...gears.tooth_load import (DenseOutline, c_prime, curvature_at, curvatures_at, hertz, root_section,
                                     root_stress, share_load)
    from .as_built import pair_outlines
    from .design import _rack

    mat = material(p.gear_material)
    pair = pair_outlines(d, mount)
    dense = {"driver": DenseOutline(d.driver.profile.outer.polyline(policy.TOOTH_LOAD_DENSE_CHORD_MM)),
             "driven": DenseOutline(d.driven.profile.outer.polyline(policy.TOOTH_LOAD_DENSE_CHORD_MM))}
    centres = {"driver": pair.driver_teeth, "driven": pair.driven_teeth}
    gears = {"driver": d.driver, "driven": d.driven}
    axes = {g: BodyPitchCurve(d.pc, g).normal(np.array([t.phi_centre for t in gears[g].teeth])) for g in gears}
    m, b, alpha = d.m, p.face_width_mm, math.radians(p.pressure_angle_deg)
    Z_E = z_e(mat.iso, mat.iso)
    K_H = p.load_K_A * p.load_K_v * p.load_K_beta
    K_F = K_H
    rack = _rack(p)
    th = d.run_law.theta
    step = math.radians(step_deg if step_deg is not None else policy.TOOTH_LOAD_STEP_DRIVER_DEG)
    th0, th1 = float(th(np.array([phi0]))[0]), float(th(np.array([phi0 + span]))[0])
    n = max(2, int(math.ceil(abs(th1 - th0) / step)) + 1)
    grid = _phi_of_theta(th, phi0, phi0 + span, np.linspace(th0, th1, n))
    grid[0], grid[-1] = phi0, phi0 + span
    ok = np.isfinite(c_te)
    cp, c_te_ok = np.asarray(c_phi, float)[ok], np.asarray(c_te, float)[ok]

    def stiffness(phi):
        zn1 = 2.0 * np.asarray(d.pc.rho(phi), float) / m
        zn2 = 2.0 * np.asarray(d.pc.rho_H(phi), float) / m
        return c_prime(zn1, zn2, p.driver_shift, -p.driver_shift, alpha, rack.h_fP_star, mat.E_MPa / 206000.0)

    # the load and the stiffness on a fine table of the period (both smooth in phi), interpolated at every phase
    tab = np.linspace(phi0, phi0 + span, 2049)
    T1t, T2t, _ = _loads(p, d, tab)
    ct = stiffness(tab)
    # the window: a few single-pair deflections under the whole load, as rotation of the driven wheel
    r1 = float(np.min(np.asarray(d.pc.r(tab), float)))
    rH = float(np.min(np.asarray(d.pc.r_H(tab), float)))
    defl = float(np.max(T1t)) * 1e3 / (r1 * math.cos(alpha)) / (float(np.min(ct)) * b * 1e3)   # mm
    window = max(2e-5, policy.TOOTH_LOAD_GAP_WINDOW_DEFLECTIONS * defl / rH)
    evals = 0

    def evaluate(phi: float, theta: float | None = None):
        nonlocal evals
        evals += 1
        if theta is None:
            theta = float(th(np.array([phi]))[0])
        te0 = float(np.interp(phi, cp, c_te_ok))
        te, cs = phase_contacts(pair, phi, theta, te0, window, direction)
        T1, T2 = float(np.interp(phi, tab, T1t)), float(np.interp(phi, tab, T2t))
        if not cs:
            return dict(phi=phi, theta=theta, te=math.nan, cs=[], F=np.zeros(0), T1=T1, T2=T2)
        k = float(np.interp(phi, tab, ct)) * b * 1e3
        F, _ = share_load(T1 * 1e3, [c.l1 for c in cs], [c.l2 for c in cs], [c.gap for c in cs],
                          np.full(len(cs), k))
        return dict(phi=phi, theta=theta, te=te, cs=cs, F=F, T1=T1, T2=T2)

    def key(r):
        return frozenset((c.driver_tooth, c.driven_tooth) for c, f in zip(r["cs"], r["F"]) if f > 0)

    recs = []
    for x, t in zip(grid, np.linspace(th0, th1, n)):
        recs.append(evaluate(float(x), float(t)))
        if tick is not None:
            tick(len(recs), n)
    # every change of the set of loaded pairs, bisected
    extra = []
    for a, bb in zip(recs[:-1], recs[1:]):
        if key(a) == key(bb):
            continue
        lo, hi = a, bb
        for _ in range(policy.TOOTH_LOAD_REFINE_STEPS):
            mid = evaluate(0.5 * (lo["phi"] + hi["phi"]))
            extra.append(mid)
            if key(mid) == key(lo):
                lo = mid
            else:
                hi = mid
    recs = sorted(recs + extra, key=lambda r: r["phi"])

    sections = {"driver": {}, "driven": {}}

    def section(g, j):
        if j not in sections[g]:
            sections[g][j] = root_section(dense[g], j, centres[g], axes[g][j], m)
        return sections[g][j]

    fit = policy.TOOTH_LOAD_FLANK_FIT_MODULE * m
    # the vertex of each loaded contact on either flank (the k-d trees asked for all of them at once: each point's
    # answer is its own query's), and their curvatures fitted together (curvatures_at: the values of one at a time)
    loaded = [c for r in recs for c, F in zip(r["cs"], r["F"]) if F > 0]
    near = {g: (dense[g].nearest(np.array([c.p_driver if g == "driver" else c.p_driven for c in loaded]))
                if loaded else np.zeros(0, np.int64)) for g in dense}
    at = {id(c): (int(near["driver"][k]), int(near["driven"][k])) for k, c in enumerate(loaded)}
    curvatures_at(dense["driver"], near["driver"], fit)
    curvatures_at(dense["driven"], near["driven"], fit)
    peaks = {"driver": {}, "driven": {}}
    rows = []
    imbalance, lost = 0.0, 0
    for r in recs:
        if not r["cs"]:
            lost += 1
            continue
        tot = float(sum(f * c.l1 for c, f in zip(r["cs"], r["F"]))) * 1e-3
        imbalance = max(imbalance, abs(tot - r["T1"]) / r["T1"])
        nl = int(np.count_nonzero(r["F"] > 0))
        phi_c, theta = r["phi"] + r["te"], r["theta"]
        Rd = np.array([[math.cos(phi_c), -math.sin(phi_c)], [math.sin(phi_c), math.cos(phi_c)]])    # world -> driven
        Rt = np.array([[math.cos(theta), math.sin(theta)], [-math.sin(theta), math.cos(theta)]])   # world -> driver
        Ftot = float(np.sum(r["F"]))
        for c, F in zip(r["cs"], r["F"]):
            if not F > 0:
                continue
            i1, i2 = at[id(c)]
            rho1 = 1.0 / curvature_at(dense["driver"], i1, fit)
            rho2 = 1.0 / curvature_at(dense["driven"], i2, fit)
            sH = float(hertz(F, b, rho1, rho2, Z_E, K_H))
            corner = [g for g, i in (("driver", i1), ("driven", i2))
                      if np.any(dense[g].corner[[(i - 1) % len(dense[g]), i, (i + 1) % len(dense[g])]])]
            out = {}
            for g, P, Fv, j in (("driver", c.p_driver, Rt @ (-F * c.n), c.driver_tooth),
                                ("driven", c.p_driven, Rd @ (F * c.n), c.driven_tooth)):
                sec = section(g, j)
                out[g] = root_stress(sec, P, Fv, b, m, alpha, K_F) if sec.ok else None
                pk = peaks[g].setdefault(j, _Peak())
                pk.F = max(pk.F, F)
                if math.isfinite(sH) and sH > pk.sH:
                    pk.sH, pk.sH_at = sH, math.degrees(theta)
                if out[g] is not None and out[g]["sigma_F"] > pk.sF:
                    pk.sF, pk.sF_at = out[g]["sigma_F"], math.degrees(theta)
            od, on = out["driver"] or {}, out["driven"] or {}
            rows.append([math.degrees(theta), math.degrees(r["phi"]), r["T1"], r["T2"], nl, c.driver_tooth,
                         c.driven_tooth, 1e3 * c.gap * c.l2, F / Ftot, F, c.l1, c.l2, rho1, rho2, sH,
                         od.get("sigma_F", math.nan), on.get("sigma_F", math.nan), od.get("h_Fe", math.nan),
                         on.get("h_Fe", math.nan), od.get("Y_F", math.nan), od.get("Y_S", math.nan),
                         on.get("Y_F", math.nan), on.get("Y_S", math.nan), " ".join(corner),
                         float(np.hypot(*c.p_driver)), float(np.hypot(*c.p_driven))])
    theta_all = np.array([r["theta"] for r in recs])
    z = {"driver": len(d.driver.teeth), "driven": len(d.driven.teeth)}
    n_turns = d.law.n
    # teeth per period of the pair: a tooth j stands for j mod q in the other periods
    from .as_built import period_span

    per = period_span(d)
    repeat = {"driver": max(1, min(z["driver"], int(round(z["driver"] * n_turns * per / (2 * math.pi))))),
              "driven": max(1, min(z["driven"], int(round(z["driven"] * per / (2 * math.pi)))))}
    peaks = {g: _fold(peaks[g], repeat[g]) for g in peaks}
    return ToothLoad(
        rows=rows, theta=theta_all, phi=np.array([r["phi"] for r in recs]), T1=np.array([r["T1"] for r in recs]),
        T2=np.array([r["T2"] for r in recs]), loaded=np.array([int(np.count_nonzero(r["F"] > 0)) for r in recs]),
        imbalance=imbalance, lost=lost, peaks=peaks, sections=sections, load_case=_loads(p, d, tab[:1])[2],
        material=mat, Z_E=Z_E, c_prime=(float(np.min(ct)), float(np.max(ct))), K_H=K_H, K_F=K_F, window_rad=window,
        evaluations=evals, teeth=z, repeat=repeat, cycles={"driver": float(n_turns), "driven": 1.0})


# =========================================================================== outputs
def _life(tl: ToothLoad, p, gear: str):
    """(N_L or None, Z_NT, Y_NT) of a tooth of ``gear``: the endurance limit without a life, else its cycles."""
    from ...gears.gear_materials import y_nt_of, z_nt_of

    if not p.load_life_hours > 0:
        return None, 1.0, 1.0
    driven_turns = p.load_driver_speed_rpm / tl.cycles["driver"] * 60.0 * p.load_life_hours
    N = tl.cycles[gear] * driven_turns
    return N, z_nt_of(tl.material, N), y_nt_of(tl.material, N)


def peak_rows(tl: ToothLoad, p) -> list[list]:
    rows = []
    mat = tl.material
    for g in ("driver", "driven"):
        _, Z_NT, Y_NT = _life(tl, p, g)
        for j in range(tl.teeth[g]):
            pk, how = tl.tooth_peak(g, j)
            sec = tl.section_of(g, j)
            rows.append([g, j, how, tl.cycles[g], pk.F, pk.sH, pk.sH_at, pk.sF, pk.sF_at,
                         sec.s_Fn if sec is not None and sec.ok else math.nan,
                         min(sec.rho_lo, sec.rho_hi) if sec is not None and sec.ok else math.nan,
                         mat.sigma_Hlim_MPa * Z_NT / pk.sH if pk.sH > 0 else math.nan,
                         mat.sigma_FE_MPa * Y_NT / pk.sF if pk.sF > 0 else math.nan])
    return rows


def summary(tl: ToothLoad, p) -> dict:
    """The derived values of the load per tooth (their meanings: the glossary's TOOTH_LOAD)."""
    out = {}
    mat = tl.material
    sH_all, sF_all = [], []
    for g in ("driver", "driven"):
        pk = tl.peaks[g]
        _, Z_NT, Y_NT = _life(tl, p, g)
        F = {j: v.F for j, v in pk.items() if v.F > 0} or {-1: math.nan}
        sF = {j: v.sF for j, v in pk.items() if v.sF > 0} or {-1: math.nan}
        sH = {j: v.sH for j, v in pk.items() if v.sH > 0} or {-1: math.nan}
        jF, jH = max(sF, key=sF.get), max(sH, key=sH.get)
        nan = _Peak(math.nan, math.nan, math.nan, math.nan, math.nan)
        out.update({
            f"tooth_load_{g}_sigma_F_max_MPa": sF[jF], f"tooth_load_{g}_sigma_F_worst_tooth": jF,
            f"tooth_load_{g}_sigma_F_worst_driver_deg": pk.get(jF, nan).sF_at,
            f"tooth_load_{g}_sigma_H_max_MPa": sH[jH], f"tooth_load_{g}_sigma_H_worst_tooth": jH,
            f"tooth_load_{g}_sigma_H_worst_driver_deg": pk.get(jH, nan).sH_at,
            f"tooth_load_{g}_F_n_max_N": max(F.values()),
            f"tooth_load_{g}_uneven_F": max(F.values()) / min(F.values()),
            f"tooth_load_{g}_uneven_sigma_F": max(sF.values()) / min(sF.values()),
            f"tooth_load_{g}_S_H_min": mat.sigma_Hlim_MPa * Z_NT / sH[jH],
            f"tooth_load_{g}_S_F_min": mat.sigma_FE_MPa * Y_NT / sF[jF],
            f"tooth_load_{g}_cycles_per_driven_turn": tl.cycles[g],
        })
        sH_all.append(out[f"tooth_load_{g}_S_H_min"])
        sF_all.append(out[f"tooth_load_{g}_S_F_min"])
    out.update({
        "tooth_load_S_H_min": float(np.min(sH_all)), "tooth_load_S_F_min": float(np.min(sF_all)),
        "tooth_load_T1_max_Nm": float(np.max(tl.T1)), "tooth_load_T1_min_Nm": float(np.min(tl.T1)),
        "tooth_load_T2_max_Nm": float(np.max(tl.T2)), "tooth_load_T2_min_Nm": float(np.min(tl.T2)),
        "tooth_load_pairs_min": int(np.min(tl.loaded)), "tooth_load_pairs_max": int(np.max(tl.loaded)),
        "tooth_load_pairs_mean": float(np.mean(tl.loaded)),
        "tooth_load_c_prime_min": tl.c_prime[0], "tooth_load_c_prime_max": tl.c_prime[1],
        "tooth_load_Z_E": tl.Z_E, "tooth_load_phases": int(len(tl.theta)), "tooth_load_material": p.gear_material,
        "tooth_load_sigma_Hlim_MPa": mat.sigma_Hlim_MPa, "tooth_load_sigma_FE_MPa": mat.sigma_FE_MPa,
    })
    return out


def checks(tl: ToothLoad, vals: dict, p) -> list[Check]:
    mat = tl.material
    static = " (static limits of a printed material, not a fatigue rating)" if mat.static else ""
    out = [
        Check.at_least("tooth_load.S_H", vals["tooth_load_S_H_min"], p.load_S_Hmin, "",
                       f"least contact safety sigma_Hlim Z_NT / sigma_H over every tooth: driver "
                       f"{vals['tooth_load_driver_S_H_min']:.3f} (tooth {vals['tooth_load_driver_sigma_H_worst_tooth']}, "
                       f"sigma_H {vals['tooth_load_driver_sigma_H_max_MPa']:.1f} MPa at driver "
                       f"{vals['tooth_load_driver_sigma_H_worst_driver_deg']:.2f} deg), driven "
                       f"{vals['tooth_load_driven_S_H_min']:.3f} (tooth {vals['tooth_load_driven_sigma_H_worst_tooth']}); "
                       f"{p.gear_material} sigma_Hlim = {mat.sigma_Hlim_MPa:g} MPa{static}"),
        Check.at_least("tooth_load.S_F", vals["tooth_load_S_F_min"], p.load_S_Fmin, "",
                       f"least root safety sigma_FE Y_NT / sigma_F over every tooth: driver "
                       f"{vals['tooth_load_driver_S_F_min']:.3f} (tooth {vals['tooth_load_driver_sigma_F_worst_tooth']}, "
                       f"sigma_F {vals['tooth_load_driver_sigma_F_max_MPa']:.1f} MPa at driver "
                       f"{vals['tooth_load_driver_sigma_F_worst_driver_deg']:.2f} deg), driven "
                       f"{vals['tooth_load_driven_S_F_min']:.3f} (tooth {vals['tooth_load_driven_sigma_F_worst_tooth']}, "
                       f"sigma_F {vals['tooth_load_driven_sigma_F_max_MPa']:.1f} MPa); {p.gear_material} sigma_FE = "
                       f"{mat.sigma_FE_MPa:g} MPa{static}"),
        equilibrium(tl),
    ]
    return out


def equilibrium(tl: ToothLoad, name: str = "tooth_load.equilibrium", what: str = "") -> Check:
    """The analysis is whole: a loaded pair at every phase, every loaded tooth's 30 deg section found, and the pairs'
    forces balance the driver torque (Σ F·l1 = T1); ``what`` opens the message (the load case it is of)."""
    missing = [f"{g} {j}" for g in ("driver", "driven") for j, s in tl.sections[g].items() if not s.ok]
    return Check(name, tl.lost == 0 and not missing and tl.imbalance <= 1e-9,
                 max(tl.imbalance, float(tl.lost + len(missing))), 1e-9, "",
                 what + f"{tl.lost} of {len(tl.theta)} phases without a loaded pair; {len(missing)} teeth without a "
                 f"30 deg section" + (f" ({', '.join(missing)})" if missing else "") + f"; largest |sum F l1 - T1| / "
                 f"T1 {tl.imbalance:.2e}")


def _plot(w, tl: ToothLoad, p) -> None:
    from ...export.plots import new_figure

    fig, ax0 = new_figure(9.0, 7.0)
    fig.delaxes(ax0)
    a1, a2, a3 = fig.add_subplot(3, 1, 1), fig.add_subplot(3, 1, 2), fig.add_subplot(3, 1, 3)
    for ax, g in ((a1, "driver"), (a2, "driven")):
        z = tl.teeth[g]
        sF = np.array([tl.tooth_peak(g, j)[0].sF for j in range(z)])
        sH = np.array([tl.tooth_peak(g, j)[0].sH for j in range(z)])
        x = np.arange(z)
        ax.bar(x - 0.2, sF, 0.4, label="peak root stress sigma_F")
        ax.bar(x + 0.2, sH, 0.4, label="peak contact stress sigma_H")
        ax.axhline(tl.material.sigma_FE_MPa / p.load_S_Fmin, color="C0", ls="--", lw=0.8,
                   label=f"sigma_FE / S_Fmin = {tl.material.sigma_FE_MPa / p.load_S_Fmin:.0f} MPa")
        ax.axhline(tl.material.sigma_Hlim_MPa / p.load_S_Hmin, color="C1", ls="--", lw=0.8,
                   label=f"sigma_Hlim / S_Hmin = {tl.material.sigma_Hlim_MPa / p.load_S_Hmin:.0f} MPa")
        ok = sF[np.isfinite(sF) & (sF > 0)]
        ax.set_title(f"{g}: peak stress of every tooth over the cycle (most / least loaded root "
                     f"{ok.max() / ok.min():.3f})", fontsize=9)
        ax.set_xlabel(f"{g} tooth")
        ax.set_ylabel("MPa")
        ax.legend(fontsize=6, ncol=2)
    rows = np.array([[r[0], r[14], r[15], r[16]] for r in tl.rows], float)
    if len(rows):
        o = np.argsort(rows[:, 0], kind="stable")
        a3.plot(rows[o, 0], rows[o, 2], ".", ms=1.5, label="sigma_F driver tooth")
        a3.plot(rows[o, 0], rows[o, 3], ".", ms=1.5, label="sigma_F driven tooth")
        a3.plot(rows[o, 0], rows[o, 1], ".", ms=1.5, label="sigma_H")
    a3.set_xlabel("driver angle theta, deg (one period)")
    a3.set_ylabel("MPa")
    a3.set_title(f"stress of every loaded pair over the period ({tl.load_case.split(',')[0]})", fontsize=9)
    a3.legend(fontsize=6, markerscale=4)
    fig.tight_layout()
    w.add_plot("tooth_load", fig)


def factor_rows(tl: ToothLoad, p, vals: dict) -> list[list]:
    mat = tl.material
    N_drv, Z_drv, Y_drv = _life(tl, p, "driver")
    N_dvn, Z_dvn, Y_dvn = _life(tl, p, "driven")
    v = {"K_A": p.load_K_A, "K_v": p.load_K_v, "K_Hbeta": p.load_K_beta, "K_Fbeta": p.load_K_beta,
         "K_Halpha": "", "c_prime": f"{tl.c_prime[0]:.4f} .. {tl.c_prime[1]:.4f} N/(mm um)", "Z_E": tl.Z_E,
         "Z_H_Z_eps_Z_B": "", "sigma_H": f"driver {vals['tooth_load_driver_sigma_H_max_MPa']:.2f}, driven "
                                         f"{vals['tooth_load_driven_sigma_H_max_MPa']:.2f} MPa (peaks)",
         "s_Fn": "per tooth: tables/tooth_peaks.csv", "rho_F": "per tooth: tables/tooth_peaks.csv",
         "h_Fe": "per phase: tables/tooth_load.csv", "alpha_Fen": "per phase", "Y_F": "per phase", "Y_S": "per phase",
         "Y_epsilon": "", "sigma_F": f"driver {vals['tooth_load_driver_sigma_F_max_MPa']:.2f}, driven "
                                    f"{vals['tooth_load_driven_sigma_F_max_MPa']:.2f} MPa (peaks)",
         "sigma_Hlim": mat.sigma_Hlim_MPa, "sigma_FE": mat.sigma_FE_MPa,
         "Z_NT": f"driver {Z_drv:.4f}, driven {Z_dvn:.4f}" + ("" if N_drv is None else
                                                             f" (N_L {N_drv:.3g} / {N_dvn:.3g})"),
         "Y_NT": f"driver {Y_drv:.4f}, driven {Y_dvn:.4f}", "Z_L_Z_v_Z_R_Z_W_Z_X": 1.0,
         "Y_deltarelT_Y_RrelT_Y_X": 1.0, "S_H": vals["tooth_load_S_H_min"], "S_F": vals["tooth_load_S_F_min"]}
    return [[k, v[k], FACTOR_SOURCES[k]] for k in FACTOR_SOURCES]


def contact_and_load(d, mount: float, direction: int, p, step_driver_rad: float | None = None):
    """:func:`.as_built.contact_direction` and the load per tooth on that contact (:func:`analyse`, as the build reads
    it: the drive direction's, over the contact's span) in one worker job: (ContactLaw, ToothLoad).  The analysis
    needs this one direction only, so it runs there, beside the rest of the build, not after it in the build's own
    process (a single build's wall: its main process alone at the end for the 1-1.5 s it took)."""
    from .as_built import contact_direction

    c = contact_direction(d, mount, direction, step_driver_rad)
    return c, analyse(d, mount, p, c.phi, c.te, float(c.phi[0]), c.span)


def tooth_load_values(w, dd, built: dict, ab) -> None:
    """The load per tooth of a pair with a load case: tables, plot, checks, derived values, note (nothing without a
    load; a failed check where the pair has no as-built contact)."""
    p, d = dd.p, dd.d
    if not p.load_given:
        return
    if ab is None:
        w.add_checks([Check("tooth_load.equilibrium", False, 1.0, 0.0, "",
                            "no as-built contact (the proof found a jam): no load per tooth")])
        return
    w.progress("load per tooth: sharing, contact and root stress of every tooth over the period")
    dr = ab.drive
    tl = built.pop("tooth_load", None)  # analysed on the drive contact by its own job (contact_and_load)
    if tl is None:
        tl = analyse(d, dd.mount, p, dr.phi, dr.te, float(dr.phi[0]), ab.span,
                     tick=count_to(w.progress, "load per tooth: sampled positions", "position"))
    vals = summary(tl, p)
    w.derived.update(vals)
    w.add_checks(checks(tl, vals, p))
    w.add_table("tooth_load", PHASE_COLUMNS, tl.rows)
    w.add_table("tooth_peaks", PEAK_COLUMNS, peak_rows(tl, p))
    w.add_table("tooth_load_factors", ["factor", "value", "source"], factor_rows(tl, p, vals))
    if w.draws_plots:  # a proof's values only: no figure drawn to be dropped
        _plot(w, tl, p)
    mat = tl.material
    w.add_note(
        f"Load per tooth (gears/tooth_load.py; seed 002: \"the uneven distribution of the load between different "
        f"teeth\"): {tl.load_case}; T1 {vals['tooth_load_T1_min_Nm']:.3f} .. {vals['tooth_load_T1_max_Nm']:.3f} N·m, "
        f"T2 {vals['tooth_load_T2_min_Nm']:.3f} .. {vals['tooth_load_T2_max_Nm']:.3f} N·m over one period "
        f"({len(tl.theta)} phases, every {policy.TOOTH_LOAD_STEP_DRIVER_DEG:g} deg of driver and every change of the "
        f"loaded pairs bisected {policy.TOOTH_LOAD_REFINE_STEPS} times; the drive direction's as-built contact).  "
        f"Sharing: each tooth pair within {tl.window_rad:.2e} rad of the first contact is a spring of ISO 6336-1's "
        f"single stiffness c' = {tl.c_prime[0]:.3f} .. {tl.c_prime[1]:.3f} N/(mm um) (local equivalent gears, "
        f"E/E_steel = {mat.E_MPa / 206000:.4f}) closed after its gap; {vals['tooth_load_pairs_min']} .. "
        f"{vals['tooth_load_pairs_max']} pairs loaded (mean {vals['tooth_load_pairs_mean']:.3f}); limits: one constant "
        f"stiffness per pair, no friction, no dynamics (K_A {p.load_K_A:g}, K_v {p.load_K_v:g}, K_beta "
        f"{p.load_K_beta:g} as given).  Contact stress by Hertz with the flanks' radii measured on the outlines, root "
        f"stress by ISO 6336-3's 30 deg section of each tooth's real outline with the load at its point of application.  "
        f"Worst teeth: driver {vals['tooth_load_driver_sigma_F_worst_tooth']} (sigma_F "
        f"{vals['tooth_load_driver_sigma_F_max_MPa']:.1f} MPa at driver {vals['tooth_load_driver_sigma_F_worst_driver_deg']:.2f} "
        f"deg), driven {vals['tooth_load_driven_sigma_F_worst_tooth']} (sigma_F {vals['tooth_load_driven_sigma_F_max_MPa']:.1f} "
        f"MPa at driver {vals['tooth_load_driven_sigma_F_worst_driver_deg']:.2f} deg); the most over the least loaded "
        f"tooth: root stress {vals['tooth_load_driver_uneven_sigma_F']:.3f} (driver), "
        f"{vals['tooth_load_driven_uneven_sigma_F']:.3f} (driven), normal force {vals['tooth_load_driver_uneven_F']:.3f} / "
        f"{vals['tooth_load_driven_uneven_F']:.3f}.  Material {p.gear_material}: {mat.title}; sigma_Hlim "
        f"{mat.sigma_Hlim_MPa:g} MPa, sigma_FE {mat.sigma_FE_MPa:g} MPa ({mat.basis}; {mat.source}; uncertainty "
        f"{mat.uncertainty}" + (f"; printed {mat.orientation}" if mat.orientation else "") + f").  Safeties: S_H "
        f"{vals['tooth_load_S_H_min']:.3f} (required {p.load_S_Hmin:g}), S_F {vals['tooth_load_S_F_min']:.3f} "
        f"(required {p.load_S_Fmin:g}); each driver tooth is loaded {tl.cycles['driver']:g} times per driven turn, each "
        f"driven tooth once.  tables/tooth_load.csv (every loaded pair at every phase), tables/tooth_peaks.csv (every "
        f"tooth), tables/tooth_load_factors.csv (every factor and its source), plots/tooth_load.png.")
