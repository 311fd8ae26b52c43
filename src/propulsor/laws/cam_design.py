"""Choice of the curvature law of the fixed cam (seed 001, after eq. 29).

Seed 001 only says: integrate eq. 20 for several k0 (k1) and keep the variant with
admissible contact stress "at optimal values of the other parameters".  Ours: evaluate a
grid of candidates of every law, reject those violating any limit, and choose the one
with the smallest hub-speed variation (max − min)/mean of dX02/dφ = H'·sin φ + R0 + r + C
(eq. 8) over the support phase.

Limits (all parameters of :class:`DesignLimits`):
  * pressure angle |γ| <= gamma_max over the whole turn (eq. 17);
  * convex radius of curvature of the cam working profile (eq. 16) and of the outer
    channel wall >= R_factor·r over the whole turn (no undercut, margin);
  * Hertz stress (eq. 14) <= sigma_allow with P in support and P_return in return;
  * shoe without cusps or loops (radius of curvature σ = Y2 − Y1'·sin φ > 0, no
    self-intersection);
  * footprint ratio (shoe arc / hub travel per step) <= footprint_ratio_max (ours): the
    objective alone would pick K = 1/H0, a round wheel (zero variation) — it is the
    discreteness of the footprints that makes the mover walk (seed 001, introduction);
  * H - r >= cam_core_min over the whole turn (the cam keeps a core around its axle);
  * optional: return lift (max H − H(±π/n)) <= return_lift_max;
  * the leader is then verified by placing all shoes on flat ground (shoe.py): hub
    height variation <= hub_height_tol and idle shoes clear the ground.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from propulsor import policy
from propulsor.errors import InputError, require, require_finite, require_positive
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion
from propulsor.laws.shoe import hub_height_on_flat, return_ground_clearance, shoe_loop_check, shoe_table


@dataclass(frozen=True)
class DesignLimits:
    """Limits of the cam design search (see module docstring).  Defaults ours: 30°
    pressure angle, convex radii >= 1.5·r, 1500 MPa (hardened steel), footprint ratio
    <= 0.85, cam core >= 40 mm, hub height on flat constant within 0.01 mm."""

    gamma_max_deg: float = 30.0
    R_factor: float = 1.5
    sigma_allow: float = 1500.0
    shoe_radius_min: float = 0.0
    footprint_ratio_max: float = 0.85
    cam_core_min: float = 40.0
    hub_height_tol: float = 0.01
    ground_clearance_min: float = 0.0
    return_lift_max: float | None = None

    def __post_init__(self):
        g = require_finite("gamma_max_deg", self.gamma_max_deg)
        require(0.0 < g < 90.0, "gamma_max_deg", g, "must be in (0, 90) deg")
        require_positive("R_factor", self.R_factor)
        require_positive("sigma_allow", self.sigma_allow, "MPa")
        require(require_finite("shoe_radius_min", self.shoe_radius_min) >= 0.0,
                "shoe_radius_min", self.shoe_radius_min, "must be >= 0 mm")
        require_positive("footprint_ratio_max", self.footprint_ratio_max)
        require(require_finite("cam_core_min", self.cam_core_min) >= 0.0,
                "cam_core_min", self.cam_core_min, "must be >= 0 mm")
        require_positive("hub_height_tol", self.hub_height_tol, "mm")
        if self.return_lift_max is not None:
            require(require_finite("return_lift_max", self.return_lift_max) >= 0.0,
                    "return_lift_max", self.return_lift_max, "must be >= 0 mm (or None: no limit)")
        require(require_finite("ground_clearance_min", self.ground_clearance_min) >= 0.0,
                "ground_clearance_min", self.ground_clearance_min, "must be >= 0 mm")


@dataclass(frozen=True)
class SearchGrid:
    """Candidate coefficients (ours).  Linear/quadratic: k0 over [lo, hi] with n values;
    exponential: k0 × k1 grid.  Laws are used in the symmetric (even) form."""

    linear_k0: tuple = (-0.004, 0.03, 60)
    quadratic_k0: tuple = (-0.004, 0.05, 60)
    exponential_k0: tuple = (0.0, 0.012, 13)
    exponential_k1: tuple = (-2.0, 2.0, 11)
    symmetric: bool = True

    def __post_init__(self):
        for name in ("linear_k0", "quadratic_k0", "exponential_k0", "exponential_k1"):
            v = getattr(self, name)
            ok = (isinstance(v, (tuple, list)) and len(v) == 3 and all(math.isfinite(float(x)) for x in v)
                  and float(v[0]) <= float(v[1]) and int(v[2]) == v[2] and int(v[2]) >= 0)
            require(ok, f"SearchGrid.{name}", v, "must be (lo, hi, n) with lo <= hi and a whole n >= 0")

    def laws(self) -> list[CurvatureLaw]:
        lo, hi, n = self.linear_k0
        out = [CurvatureLaw("linear", float(k), symmetric=self.symmetric) for k in np.linspace(lo, hi, int(n))]
        lo, hi, n = self.quadratic_k0
        out += [CurvatureLaw("quadratic", float(k), symmetric=self.symmetric) for k in np.linspace(lo, hi, int(n))]
        lo, hi, n = self.exponential_k0
        lo1, hi1, n1 = self.exponential_k1
        for k0 in np.linspace(lo, hi, int(n)):
            for k1 in np.linspace(lo1, hi1, int(n1)):
                out.append(CurvatureLaw("exponential", float(k0), float(k1), symmetric=self.symmetric))
        return out


def _min_positive(a) -> float:
    a = np.asarray(a, dtype=float)
    a = a[np.isfinite(a) & (a > 0)]
    return float(a.min()) if a.size else math.inf


def evaluate(mech: CamMechanism, law: CurvatureLaw, limits: DesignLimits,
             return_phase: ReturnPhase = ReturnPhase(), estimate_error: bool = False) -> dict:
    """Figures of one candidate (a CSV row) and its limit violations."""
    row = dict(law=law.kind, k0=law.k0, k1=law.k1, label=law.label(), feasible=False, violations="",
               hub_speed_variation_pct=math.nan, gamma_max_deg=math.nan, gamma_max_support_deg=math.nan,
               R_min_mm=math.nan, R_outer_min_mm=math.nan, undercut=False, sigma_max_MPa=math.nan,
               sigma_return_max_MPa=math.nan, shoe_radius_min_mm=math.nan, shoe_self_intersecting=False,
               footprint_ratio=math.nan, H_min_mm=math.nan, H_max_mm=math.nan, H_support_end_mm=math.nan,
               return_lift_mm=math.nan, H_error_mm=math.nan, hub_height_variation_mm=math.nan,
               ground_clearance_min_mm=math.nan)
    try:
        cm = cam_motion(mech, law, return_phase, estimate_error=estimate_error)
    except InputError as e:
        row["violations"] = f"blow-up: {e}"
        return row
    s = mech.phi_s
    phi_t = np.linspace(0.0, 2 * math.pi, policy.CAM_TURN_SAMPLES)
    tab = cm.table(phi_t)
    phi_s = np.linspace(-s, s, policy.CAM_SUPPORT_SAMPLES)
    hs = cm.hub_speed(phi_s)
    st = shoe_table(cm.support, phi_s)
    lc = shoe_loop_check(st, limits.shoe_radius_min)
    arc = float(np.trapezoid(st.radius, phi_s))
    travel = float(np.trapezoid(hs, phi_s))
    undercut = bool(np.any((tab.K_path > 0) & (tab.R_profile <= 0)) or np.any(
        (tab.K_path < 0) & (tab.R_outer <= 0)))
    sig_sup = tab.sigma_H[tab.support]
    sig_ret = tab.sigma_H[~tab.support]
    H_end = float(cm.support.state(np.array([s]))[0][0])
    row.update(
        hub_speed_variation_pct=100.0 * float((hs.max() - hs.min()) / (travel / (2.0 * s))),
        gamma_max_deg=math.degrees(float(np.max(np.abs(tab.gamma)))),
        gamma_max_support_deg=math.degrees(float(np.max(np.abs(tab.gamma[tab.support])))),
        R_min_mm=_min_positive(tab.R_profile), R_outer_min_mm=_min_positive(tab.R_outer), undercut=undercut,
        sigma_max_MPa=float(np.max(sig_sup)) if np.all(np.isfinite(sig_sup)) else math.inf,
        sigma_return_max_MPa=float(np.max(sig_ret)) if np.all(np.isfinite(sig_ret)) else math.inf,
        shoe_radius_min_mm=lc.radius_min, shoe_self_intersecting=lc.self_intersecting,
        footprint_ratio=arc / travel, H_min_mm=float(tab.H.min()), H_max_mm=float(tab.H.max()),
        H_support_end_mm=H_end, return_lift_mm=float(tab.H.max()) - H_end,
        H_error_mm=cm.H_error_mm if cm.H_error_mm is not None else math.nan)
    viol = []
    Rlim = limits.R_factor * mech.r
    if row["gamma_max_deg"] > limits.gamma_max_deg:
        viol.append(f"pressure angle {row['gamma_max_deg']:.2f}° > {limits.gamma_max_deg:g}°")
    if undercut:
        viol.append("undercut (cam profile radius of curvature < 0)")
    if min(row["R_min_mm"], row["R_outer_min_mm"]) < Rlim:
        viol.append(f"cam radius of curvature {min(row['R_min_mm'], row['R_outer_min_mm']):.2f} mm < "
                    f"{limits.R_factor:g}·r = {Rlim:g} mm")
    smax = max(row["sigma_max_MPa"], row["sigma_return_max_MPa"])
    if not smax <= limits.sigma_allow:
        viol.append(f"Hertz stress {smax:.0f} MPa > {limits.sigma_allow:g} MPa")
    if not lc.ok:
        viol.append(f"shoe cusp/loop (min radius {lc.radius_min:.2f} mm, self-intersecting {lc.self_intersecting})")
    if row["footprint_ratio"] > limits.footprint_ratio_max:
        viol.append(f"footprint ratio {row['footprint_ratio']:.4f} > {limits.footprint_ratio_max:g}")
    core = row["H_min_mm"] - mech.r
    if core < limits.cam_core_min:
        viol.append(f"cam core H_min − r = {core:.2f} mm < {limits.cam_core_min:g} mm")
    if limits.return_lift_max is not None and row["return_lift_mm"] > limits.return_lift_max:
        viol.append(f"return lift {row['return_lift_mm']:.2f} mm > {limits.return_lift_max:g} mm")
    row["violations"] = "; ".join(viol)
    row["feasible"] = not viol
    return row


@dataclass
class DesignResult:
    """Outcome of :func:`search_design`."""

    chosen: dict | None  # CSV row of the chosen candidate (re-evaluated with the error estimate)
    law: CurvatureLaw | None
    reason: str
    rows: list = field(default_factory=list)  # all candidates, ranked (feasible first, by objective)
    n_evaluated: int = 0
    n_feasible: int = 0
    elapsed_s: float = 0.0


def _law_of(row: dict, symmetric: bool) -> CurvatureLaw:
    return CurvatureLaw(row["law"], row["k0"], row["k1"], symmetric=symmetric)


def search_design(mech: CamMechanism = CamMechanism(), limits: DesignLimits = DesignLimits(),
                  grid: SearchGrid = SearchGrid(), return_phase: ReturnPhase = ReturnPhase()) -> DesignResult:
    """Evaluate every candidate of the grid, rank, choose (see module docstring)."""
    t0 = time.perf_counter()
    rows = [evaluate(mech, law, limits, return_phase) for law in grid.laws()]
    feas = sorted((r for r in rows if r["feasible"]), key=lambda r: r["hub_speed_variation_pct"])
    res = DesignResult(chosen=None, law=None, reason="", n_evaluated=len(rows))
    chosen = None
    for best in feas:  # the placed-shoe verification (slower) only for the leaders
        law = _law_of(best, grid.symmetric)
        cand = evaluate(mech, law, limits, return_phase, estimate_error=True)
        ver = verify(mech, law, limits, return_phase)
        best.update(ver)
        cand.update(ver)
        if ver["verify_violations"] or not cand["feasible"]:
            best["feasible"] = False
            best["violations"] = "; ".join(v for v in (cand["violations"], ver["verify_violations"]) if v)
            continue
        chosen = cand
        break
    feas = [r for r in feas if r["feasible"]]
    # the infeasible by how far they are from feasible: fewest violated limits first, then the objective; a
    # candidate whose motion could not be computed (a blow-up: no figures at all) after every one that could
    # (its message may itself hold a '; ', so it is not counted as violations)
    infeas = sorted((r for r in rows if not r["feasible"]),
                    key=lambda r: (r["violations"].startswith("blow-up"), len(r["violations"].split("; ")),
                                   np.nan_to_num(r["hub_speed_variation_pct"], nan=1e9)))
    ranked = feas + infeas
    for i, r in enumerate(ranked, 1):
        r["rank"] = i
    res.rows = ranked
    res.n_feasible = len(feas)
    if chosen is None:
        res.reason = (f"no candidate of {len(rows)} satisfies the limits; closest: {ranked[0]['label']} "
                      f"({ranked[0]['violations']})")
    else:
        best = feas[0]
        chosen["rank"] = best["rank"]
        res.chosen, res.law = chosen, law
        margins = _margins(chosen, limits, mech)
        tight = ", ".join(f"{k} (margin {v:.1%})" for k, v in sorted(margins.items(), key=lambda kv: kv[1])[:2])
        by_law = {}
        for r in feas:
            by_law.setdefault(r["law"], r)
        others = "; ".join(f"best {k}: {v['label']} {v['hub_speed_variation_pct']:.3f} %"
                           for k, v in by_law.items() if v is not best)
        res.reason = (f"{chosen['label']}: smallest hub-speed variation of eq. 8, "
                      f"{chosen['hub_speed_variation_pct']:.3f} %, among {len(feas)} feasible of {len(rows)} "
                      f"candidates; tightest limits: {tight}" + (f"; {others}" if others else ""))
    res.elapsed_s = time.perf_counter() - t0
    return res


def verify(mech: CamMechanism, law: CurvatureLaw, limits: DesignLimits,
           return_phase: ReturnPhase = ReturnPhase(), n_phi: int = 19) -> dict:
    """Independent check of a design by placing the shoes of all legs on flat ground
    (shoe.hub_height_on_flat): hub height variation over a step and the ground clearance
    of the idle legs."""
    cm = cam_motion(mech, law, return_phase, estimate_error=False)
    s = mech.phi_s
    phi = np.linspace(-s, s, n_phi)
    hh = hub_height_on_flat(cm, phi, n_shoe=601)
    clr = return_ground_clearance(cm, phi[1:-1], n_shoe=601)
    var = float(hh.max() - hh.min())
    v = []
    if var > limits.hub_height_tol:
        v.append(f"hub height on flat varies {var:.4g} mm > {limits.hub_height_tol:g} mm")
    if float(clr.min()) < limits.ground_clearance_min:
        v.append(f"idle shoe ground clearance {float(clr.min()):.4g} mm < {limits.ground_clearance_min:g} mm")
    return dict(hub_height_variation_mm=var, hub_height_mean_mm=float(hh.mean()),
                ground_clearance_min_mm=float(clr.min()), verify_violations="; ".join(v))


def _margins(row: dict, limits: DesignLimits, mech: CamMechanism) -> dict:
    """Relative margins to each limit (0 = on the limit)."""
    Rlim = limits.R_factor * mech.r
    return {
        "pressure angle": 1.0 - row["gamma_max_deg"] / limits.gamma_max_deg,
        "cam radius of curvature": min(row["R_min_mm"], row["R_outer_min_mm"]) / Rlim - 1.0,
        "Hertz stress": 1.0 - max(row["sigma_max_MPa"], row["sigma_return_max_MPa"]) / limits.sigma_allow,
        "footprint ratio": 1.0 - row["footprint_ratio"] / limits.footprint_ratio_max,
        "cam core": (row["H_min_mm"] - mech.r) / limits.cam_core_min - 1.0 if limits.cam_core_min > 0 else math.inf,
    }


CSV_COLUMNS = ("rank", "law", "k0", "k1", "feasible", "hub_speed_variation_pct", "gamma_max_deg",
               "gamma_max_support_deg", "R_min_mm", "R_outer_min_mm", "sigma_max_MPa", "sigma_return_max_MPa",
               "shoe_radius_min_mm", "shoe_self_intersecting", "footprint_ratio", "H_min_mm", "H_max_mm",
               "H_support_end_mm", "return_lift_mm", "H_error_mm", "hub_height_variation_mm",
               "ground_clearance_min_mm", "violations")


__all__ = ["DesignLimits", "SearchGrid", "DesignResult", "evaluate", "verify", "search_design", "CSV_COLUMNS"]
