"""Non-circular gear pair of the driving wheel-walking propulsor (seeds 000 and 002, issue 3).

law (seed 000 eqs. 1-15, periodic per leg: SPEC §3 Trap 1) -> pitch curves r_H(phi), r(theta)
(seed 000 eqs. 12-13) closed by true arc length (Trap 3) -> teeth -> finished outlines ->
full-cycle proof on the outlines (``parts.noncircular_proof``) -> solids with face width, bore
and keyway -> STEP / STL / 3MF / DXF, the papers' tables, transmission table, plots, report.

Two tooth methods:

* ``generated`` (default, SPEC §3.2): a C2, closure-exact blend of the law around every leg
  hand-over (``gears.noncircular.SmoothedWalkingLaw``, Trap 2) whose half-width is the smallest
  keeping both pitch curves generable (rack undercut limit rho >= (h_a* - x) m / sin^2 alpha on
  convex parts with the driver shifted by +x and the driven wheel by -x; shaper z0 with
  r0 < |rho| on concave parts), or given by the user; conjugate teeth enveloped by the ISO 53
  rack / the shaper on one shared arc-length frame (``geometry.noncircular_outline``).
* ``sectors``: the papers' own method (seed 000 eqs. 16-52, seed 002 Tables 2-4,
  ``gears.sectors``) on the exact law; its teeth are not conjugate and the proof measures
  what that costs (interference at the law's positions, jams, transmission error).

Frames (the contract other tools read): the driven wheel's axis at the origin, the driver's at
(L, 0); ``driven.dxf`` / ``driver.dxf`` hold each gear about its own axis in its phase at
phi = theta = 0 of the assembly (the contact of law angle 0 on the line of centres).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import policy
from ..check import Check
from ..errors import InputError
from ..gears.noncircular import (
    CutterSpec, PitchCurves, SmoothedWalkingLaw, check_generable, choose_smoothing, hub_speed_ripple,
    perimeter_per_mm,
)
from ..gears.sectors import (
    PINION_POINT_COLUMNS, RADII_COLUMNS, SECTOR_COLUMNS, WHEEL_POINT_COLUMNS, pinion_tooth_points,
    sector_hub_speed, sector_radii, sector_table, structured_rows, wheel_space_points,
)
from ..gears.involute import BasicRack
from ..laws.walking import LEG_PERIOD, WalkingLaw
from ..params import param
from . import PartType

METHODS = ("generated", "sectors")


# =========================================================================== parameters
@dataclass
class NoncircularPairParams:
    """Parameters of the walking-drive pair.  Defaults: seed 002 (a = 100, b = 50, c = 236.5 mm,
    n = 4, m = 2.5, z 20/80)."""

    a_mm: float = param(100.0, "mm", "hub-to-crank axis distance a (seed 000 eq. 1)", min=0.0)
    b_mm: float = param(50.0, "mm", "crank length b", min=0.0)
    c_mm: float = param(236.5, "mm", "shoe stand length c", min=0.0)
    driver_turns: int = param(4, "", "n: driver turns per driven (carrier) turn; 1, 2 or 4", min=1, max=4, integer=True)
    method: str = param("generated", "", "tooth method: generated (conjugate, default) or sectors (the papers')",
                        choices=METHODS)
    module_mm: float = param(2.5, "mm", "module m (0: from center_distance_mm, generated teeth only)", min=0.0)
    driven_teeth: int = param(80, "", "z_H: driven-wheel teeth (sectors: 4 x sectors per leg)", min=4, integer=True)
    center_distance_mm: float = param(0.0, "mm", "L; 0: from module and teeth by closure (true arc length)", min=0.0)
    pressure_angle_deg: float = param(20.0, "deg", "pressure angle of the ISO 53 rack", min=10.0, max=35.0)
    backlash_mm: float = param(0.16, "mm", "normal backlash j_n (seed 002: 0.16 mm)", min=0.0, max=2.0)
    driver_shift: float = param(0.5, "", "profile shift x of the driver (the driven wheel gets -x)", min=-1.0, max=1.5)
    shaper_teeth: int = param(20, "", "z0 of the shaper cutter for concave pitch-curve stretches", min=6, max=200,
                              integer=True)
    smoothing_deg: float = param(0.0, "deg", "half-width of the C2 blend at hand-over; 0: smallest generable",
                                 min=0.0, max=45.0)
    smoothing_max_deg: float = param(22.5, "deg", "largest blend half-width searched", min=0.0, max=45.0,
                                     min_exclusive=True)
    tip_land_min_module: float = param(0.25, "", "least tip land (in modules); thinner tips are shortened",
                                       min=0.0, max=1.0)
    mounting_distance_mm: float = param(0.0, "mm", "installed centre distance (seed 000: L_ust = 144 for L = 143.5); "
                                        "0: the design L", min=0.0)
    face_width_mm: float = param(20.0, "mm", "face width of both gears", min=0.0, min_exclusive=True)
    driver_bore_mm: float = param(16.0, "mm", "driver bore diameter (0: none)", min=0.0)
    driven_bore_mm: float = param(40.0, "mm", "driven-wheel bore diameter (0: none)", min=0.0)
    keyway: bool = param(True, "", "hub keyway in each bore (DIN 6885-1 / GOST 23360-78)")
    proof_phases_per_tooth: int = param(4, "", "phases per driven tooth in the full-cycle proof", min=4, max=64,
                                        integer=True)
    compare_methods: bool = param(True, "", "prove the other tooth method too (2D, one leg) and report the comparison")

    def validate(self) -> None:
        A = self.a_mm - self.b_mm + self.c_mm
        if not A > 0:
            raise InputError("a_mm - b_mm + c_mm", A, "hub height Y01 = a - b + c must be > 0 mm, else the law is not positive")
        if self.driver_turns not in (1, 2, 4):
            raise InputError("driver_turns", self.driver_turns,
                             "the driver pitch curve closes only if n divides the 4 legs: n in {1, 2, 4}")
        n = self.driver_turns
        z = self.driven_teeth
        if z % n:
            raise InputError("driven_teeth", z, f"must be a multiple of driver_turns = {n} (whole driver teeth)",
                             f"nearest valid: {max(n, z // n * n)}, {(z // n + 1) * n}")
        if self.method == "sectors":
            if z % 4:
                raise InputError("driven_teeth", z, "the sector method needs 4 x (sectors per leg) teeth",
                                 f"nearest valid: {max(4, z // 4 * 4)}, {(z // 4 + 1) * 4}")
            if not self.module_mm > 0:
                raise InputError("module_mm", self.module_mm, "the sector method needs the module of its tooth heights (> 0 mm)")
        else:
            if (self.module_mm > 0) == (self.center_distance_mm > 0):
                raise InputError("center_distance_mm", self.center_distance_mm,
                                 "generated teeth: give either module_mm (closure fixes L) or center_distance_mm "
                                 "(closure fixes the module), not both", f"module_mm = {self.module_mm}")
            if self.smoothing_deg > self.smoothing_max_deg:
                raise InputError("smoothing_deg", self.smoothing_deg, f"must be <= smoothing_max_deg = {self.smoothing_max_deg}")
        for name in ("driver_bore_mm", "driven_bore_mm"):
            d = getattr(self, name)
            if self.keyway and d > 0 and not 6.0 < d <= 230.0:
                raise InputError(name, d, "a keyway needs a bore over 6 up to 230 mm (DIN 6885-1); set keyway = false")
        WalkingLaw(a=self.a_mm, b=self.b_mm, c=self.c_mm, n=n)  # the law's own checks


# =========================================================================== design
@dataclass
class Design:
    """Law, closure and teeth of one method (no files)."""

    method: str
    law: WalkingLaw
    run_law: object          # the law the teeth realise (smoothed for generated, exact for sectors)
    L: float
    m: float
    z_H: int
    z: int
    pc: PitchCurves
    smoothing: object = None  # SmoothingDesign (generated)
    table: object = None      # SectorTable (sectors)
    driver: object = None     # GeneratedGear | SectorGear
    driven: object = None
    ripple: object = None     # HubSpeedRipple
    closure_error: float = math.nan

    @property
    def smoothing_deg(self) -> float:
        return math.degrees(self.smoothing.delta) if self.smoothing is not None else 0.0


def _law(p: NoncircularPairParams) -> WalkingLaw:
    return WalkingLaw(a=p.a_mm, b=p.b_mm, c=p.c_mm, n=p.driver_turns)


def _rack(p) -> BasicRack:
    return BasicRack(alpha=math.radians(p.pressure_angle_deg))


def _thinning(p) -> float:
    """Arc tooth-thickness reduction per gear: j_n split evenly, j_n / (2 cos alpha)."""
    return p.backlash_mm / (2.0 * math.cos(math.radians(p.pressure_angle_deg)))


def _smoothing(p, law: WalkingLaw, m: float):
    """The blend: given (smoothing_deg > 0) or the smallest generable (choose_smoothing)."""
    cutter = CutterSpec(m=m, alpha=math.radians(p.pressure_angle_deg), x=p.driver_shift, x_H=-p.driver_shift,
                        z0=p.shaper_teeth)
    z_H = p.driven_teeth
    if p.smoothing_deg > 0:
        from ..gears.noncircular import SmoothingDesign

        sl = SmoothedWalkingLaw(law, math.radians(p.smoothing_deg))
        L = math.pi * m * z_H / perimeter_per_mm(sl)
        g = check_generable(PitchCurves(sl, L), cutter)
        if not g.ok:
            best = _smallest_generable(law, cutter, z_H)
            raise InputError("smoothing_deg", p.smoothing_deg, "the pitch curves are not generable with this blend: "
                             + "; ".join(c.reason for c in (g.driver, g.driven) if not c.ok), best)
        return SmoothingDesign(law=sl, delta=sl.delta, L=L, z_H=z_H, z=z_H // law.n, cutter=cutter,
                               generability=g, ripple=hub_speed_ripple(sl))
    try:
        return choose_smoothing(law, cutter, z_H, delta_max=math.radians(p.smoothing_max_deg))
    except InputError as exc:
        best = _smallest_generable(law, cutter, z_H) if p.smoothing_max_deg < 45.0 else "no blend up to 45 deg works"
        raise InputError(
            "smoothing_max_deg", p.smoothing_max_deg,
            f"no C2 smoothing up to {p.smoothing_max_deg:g} deg keeps both pitch curves generable: "
            f"{str(exc).split(': ', 1)[-1]} [x = driver_shift, z_H = driven_teeth, z0 = shaper_teeth, m = module_mm]",
            best) from None


def _smallest_generable(law, cutter, z_H) -> str:
    try:
        d = choose_smoothing(law, cutter, z_H, delta_max=math.pi / 4)
    except InputError as exc:
        return "no blend up to 45 deg works either"
    return (f"a blend of {math.degrees(d.delta):.3f} deg would work "
            f"(smoothing_max_deg >= {math.degrees(d.delta):.3f}; hub speed ripple {100 * d.ripple.ripple:.2f} %)")


def design_generated(p: NoncircularPairParams, progress=lambda s: None) -> Design:
    """Seed 000/002 law -> C2 blend -> closure -> generated teeth (SPEC §3.2)."""
    from ..geometry.noncircular_outline import ArcFrame, ToothSpec, generate_gear

    law = _law(p)
    z_H = p.driven_teeth
    m = p.module_mm if p.module_mm > 0 else 1.0
    progress("generated: choosing the smoothing of the law")
    sm = _smoothing(p, law, m)
    if p.center_distance_mm > 0:  # module from L: the design is scale invariant (rho and limits ~ m)
        scale = p.center_distance_mm / sm.L
        m *= scale
        sm = _smoothing(_replace(p, module_mm=m, center_distance_mm=0.0), law, m)
    L = sm.L
    pc = sm.pair
    frame = ArcFrame(pc)
    rack = _rack(p)
    th = _thinning(p)
    common = dict(m=m, thinning_mm=th, rack=rack, z0=p.shaper_teeth, tip_min_mm=p.tip_land_min_module * m)
    g = sm.generability
    for chk, x in ((g.driver, p.driver_shift), (g.driven, -p.driver_shift)):
        if chk.concave:  # fail fast: the shaper this gear needs must exist
            ToothSpec(x=x, **common).shaper_tools()
    progress(f"generated: driver teeth ({z_H // law.n}), rack/shaper envelopes")
    drv = generate_gear(pc, "driver", ToothSpec(x=p.driver_shift, **common), frame)
    progress(f"generated: driven teeth ({z_H})")
    dvn = generate_gear(pc, "driven", ToothSpec(x=-p.driver_shift, **common), frame)
    return Design("generated", law, sm.law, L, m, z_H, z_H // law.n, pc, smoothing=sm, driver=drv, driven=dvn,
                  ripple=sm.ripple, closure_error=sm.closure_error)


def _replace(p, **kw):
    import dataclasses

    return dataclasses.replace(p, **kw)


def sector_design_table(p: NoncircularPairParams):
    """(SectorTable, L, m) of the papers' method for these parameters: L given, or from the
    module so that the sector arc r_Hk dphi_k is pi m (the arcs are linear in L)."""
    law = _law(p)
    i = p.driven_teeth // 4
    m = p.module_mm
    if p.center_distance_mm > 0:
        L = p.center_distance_mm
    else:
        L = math.pi * m / sector_table(law, 1.0, i).arc
    return sector_table(law, L, i), L, m


def design_sectors(p: NoncircularPairParams, progress=lambda s: None) -> Design:
    """The papers' sector method on the exact law (seed 000 eqs. 16-52, seed 002 Tables 2-4)."""
    from ..geometry.noncircular_outline import sector_driven_gear, sector_driver_gear, sector_tip_thickness

    law = _law(p)
    table, L, m = sector_design_table(p)
    sector_radii(table, m)
    t_drv, t_dvn = sector_tip_thickness(table, m, p.backlash_mm)
    if not min(t_drv, t_dvn) > 0:
        m_ok = _largest_sector_module(table, p.backlash_mm, m)
        raise InputError("module_mm", m,
                         f"sector teeth are pointed at the tip: tip land {min(t_drv, t_dvn):.3f} mm <= 0 "
                         f"(driver {t_drv:.3f}, driven {t_dvn:.3f} mm) at L = {L:.4f} mm",
                         f"the largest module with a tip land > 0 at this L is {m_ok:.4f} mm")
    progress(f"sectors: outlines ({table.i} sectors per leg)")
    drv = sector_driver_gear(table, m, p.backlash_mm)
    dvn = sector_driven_gear(table, m, p.backlash_mm)
    closure = abs(4 * float(np.sum(table.dtheta)) - 2 * math.pi * law.n)
    return Design("sectors", law, law, L, m, 4 * table.i, 4 * table.i // law.n, PitchCurves(law, L), table=table,
                  driver=drv, driven=dvn, ripple=sector_hub_speed(table), closure_error=closure)


def _largest_sector_module(table, j_n, m_hi) -> float:
    from ..geometry.noncircular_outline import sector_tip_thickness

    lo, hi = 0.0, m_hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if min(sector_tip_thickness(table, mid, j_n)) > 0:
            lo = mid
        else:
            hi = mid
    return lo


def design(p: NoncircularPairParams, progress=lambda s: None) -> Design:
    return design_generated(p, progress) if p.method == "generated" else design_sectors(p, progress)


# =========================================================================== proof
def mounting(p: NoncircularPairParams, d: Design) -> float:
    """Installed centre distance: the design L unless mounting_distance_mm > 0 (>= L)."""
    if p.mounting_distance_mm <= 0:
        return d.L
    if p.mounting_distance_mm < d.L - 1e-9:
        raise InputError("mounting_distance_mm", p.mounting_distance_mm,
                         f"must be >= the design centre distance L = {d.L:.6f} mm (or 0)")
    return p.mounting_distance_mm


def prove(d: Design, phases_per_tooth: int, legs: int = 4, progress=lambda s: None, mount: float | None = None):
    """Proof of the pair over ``legs`` legs (4 = the whole driven turn) with
    ``phases_per_tooth`` phases per driven tooth (``parts.noncircular_proof``), the gears at the
    installed centre distance ``mount`` (default the design L)."""
    from .noncircular_proof import prove_pair

    N = phases_per_tooth * d.z_H * legs // 4
    phis = np.arange(N) * (legs * LEG_PERIOD / N)
    pc = PitchCurves(d.run_law, d.L)
    pitch = math.pi * d.m if d.method == "generated" else d.table.arc
    progress(f"{d.method}: proof over {legs} leg(s), {N} phases")
    return prove_pair(d.driver.profile, d.driven.profile, mount or d.L, d.run_law.theta, phis, pc.r_H,
                      name="mesh", pitch_mm=pitch)


# =========================================================================== solids / files
def _with_bore(profile, bore_d: float, keyway: bool, root_min: float, m: float, which: str):
    from ..geometry.gear_outline import _bore_loop, keyway_for_shaft
    from ..geometry.profile import Profile

    if bore_d <= 0:
        return profile
    name = f"{which}_bore_mm"
    t2 = keyway_for_shaft(bore_d)[1] if keyway else 0.0
    lim = root_min - m
    if not bore_d / 2 + t2 < lim:
        raise InputError(name, bore_d, f"bore{' + keyway' if keyway else ''} must stay one module inside the root: "
                         f"bore/2 + t2 = {bore_d / 2 + t2:.3f} mm >= {lim:.3f} mm",
                         f"largest bore about {2 * (lim - t2):.1f} mm")
    return Profile(profile.outer, [_bore_loop(bore_d, True if keyway else None)], profile.name)


def _checks_generated(d: Design, pr, p) -> list[Check]:
    sm = d.smoothing
    g = sm.generability
    out = [
        Check.at_most("law.closure_error", d.closure_error, 1e-9, "rad",
                      f"|theta(2 pi) - 2 pi n| = {d.closure_error:.3g} rad: the driver makes exactly n = {d.law.n} turns"),
        Check.at_most("teeth.closure_error", abs(d.pc.perimeter_driven() - d.z_H * math.pi * d.m), 1e-9, "mm",
                      f"driven pitch perimeter vs z_H pi m = {d.z_H} x {math.pi * d.m:.6f} mm"),
        Check.at_least("generability.driver_rho_min", g.driver.rho_convex_min, g.driver.rho_limit, "mm",
                       f"driver convex rho_min {g.driver.rho_convex_min:.4f} mm vs rack undercut limit "
                       f"(h_a* - x) m / sin^2 alpha = {g.driver.rho_limit:.4f} mm"),
        Check.at_least("generability.driven_rho_min", g.driven.rho_convex_min, g.driven.rho_limit, "mm",
                       f"driven convex rho_min {g.driven.rho_convex_min:.4f} mm vs limit {g.driven.rho_limit:.4f} mm"),
    ]
    for chk in (g.driver, g.driven):
        if chk.concave:
            out.append(Check.greater_than(f"generability.{chk.curve}_concave_rho", chk.rho_concave_min, chk.r0, "mm",
                                          f"{chk.curve} concave |rho|_min {chk.rho_concave_min:.4f} mm vs shaper pitch "
                                          f"radius r0 = {chk.r0:.3f} mm"))
    for gear in (d.driver, d.driven):
        out.append(Check.at_most(f"teeth.{gear.role}_undercut", gear.undercut_teeth, 0, "teeth",
                                 f"{gear.undercut_teeth} of {len(gear.teeth)} {gear.role} teeth undercut"))
        out.append(Check.at_least(f"teeth.{gear.role}_tip_land", gear.tip_thickness_min, p.tip_land_min_module * d.m - 1e-9,
                                  "mm", f"least tip land {gear.tip_thickness_min:.4f} mm; {gear.shortened_teeth} teeth "
                                        f"tip-shortened, {gear.shaper_teeth} cut by the shaper z0 = {p.shaper_teeth}"))
    s = pr.summary()
    tol = policy.OVERLAP_AREA_TOL_MM2
    out.append(Check.at_most("mesh.overlap_area", s["overlap_law_max_mm2"], tol, "mm^2",
                             f"max overlap {s['overlap_law_max_mm2']:.3g} mm^2 over {s['steps']} phases at the law's positions"))
    return out + _checks_common(pr)


def _checks_common(pr, prefix: str = "mesh") -> list[Check]:
    """Proof checks; ``prefix`` 'mesh' for generated teeth, 'sectors' for the papers' teeth (separate
    names, so that a part file can document the papers' jams as expected failures without masking
    a failure of generated teeth)."""
    s = pr.summary()
    return [
        Check.at_most(f"{prefix}.runs_without_jam", s["jams"], 0, "phases",
                      f"{s['jams']} of {s['steps']} phases have no free position of the driven wheel "
                      f"(least overlap up to {float(np.max(pr.least_overlap)):.4g} mm^2)"),
        Check.greater_than(f"{prefix}.backlash_min", s["backlash_min_mm"], 0.0, "mm",
                           f"backlash {s['backlash_min_mm']:.5f} .. {s['backlash_max_mm']:.5f} mm on the driven pitch curve"),
        Check.at_least(f"{prefix}.contact_continuity", s["contact_pairs_min"], 1, "pairs",
                       f"least tooth pairs in contact {s['contact_pairs_min']}, mean {s['contact_pairs_mean']:.4f}"),
    ]


def _checks_sectors(d: Design, pr) -> list[Check]:
    return [Check.at_most("law.closure_error", d.closure_error, 1e-9, "rad",
                          f"|4 sum dtheta - 2 pi n| = {d.closure_error:.3g} rad (sector table, seed 000 eqs. 48-51)")] \
        + _checks_common(pr, "sectors")


def _sector_tables(w, p: NoncircularPairParams, note_if_missing: bool = True):
    """Table 1 (both seeds) and Tables 2-4 (seed 002) of the papers' method for these parameters."""
    if p.driven_teeth % 4:
        w.add_note("Sector tables not written: the papers' method needs driven_teeth = 4 x sectors per leg.")
        return None
    table, L, m = sector_design_table(p)
    w.add_note(
        f"The papers' tables for these parameters (seed 000 Table 1 -> tables/sectors.csv, seed 002 Tables 2-4 -> "
        f"radii.csv, driver_teeth.csv, driven_spaces.csv): i = {table.i} sectors per leg, L = {L:.6f} mm "
        f"({'given' if p.center_distance_mm > 0 else 'from the module: sector arc = pi m'}; sector arc "
        f"{table.arc:.4f} mm), m = {m:g} mm, j_n = {p.backlash_mm:g} mm; angles in rad and deg as printed.")
    w.add_table("sectors", list(SECTOR_COLUMNS), [[r[c] for c in SECTOR_COLUMNS] for r in table.rows()])
    rad = sector_radii(table, m)
    w.add_table("radii", list(RADII_COLUMNS), [[r[c] for c in RADII_COLUMNS] for r in rad.rows()])
    for name, arr, cols in (("driver_teeth", pinion_tooth_points(table, m, p.backlash_mm), PINION_POINT_COLUMNS),
                            ("driven_spaces", wheel_space_points(table, m, p.backlash_mm), WHEEL_POINT_COLUMNS)):
        w.add_table(name, list(cols), [[r[c] for c in cols] for r in structured_rows(arr)])
    return table


def _pitch_polyline(d: Design, role: str, n: int = 1441) -> np.ndarray:
    from ..geometry.noncircular_outline import PitchCurve

    span = 2 * math.pi if role == "driven" else 2 * math.pi / d.law.n
    return PitchCurve(d.pc, role).point(np.linspace(0.0, span, n, endpoint=False))


def _figure2(w, d: Design, pr, other, pr_other):
    from ..export.plots import new_figure

    fig, ax = new_figure(8.0, 5.0)
    ph = np.linspace(0.0, LEG_PERIOD, 2001)
    ax.plot(np.degrees(ph), d.law.U(ph), "k--", lw=0.9, label="law U(phi), seed 000 eq. 15 (exact)")
    if d.method == "generated":
        ax.plot(np.degrees(ph), d.run_law.U(ph), "k-", lw=1.0,
                label=f"law with C2 blend, {d.smoothing_deg:.2f} deg")
    for dd, pp in ((d, pr), (other, pr_other)):
        if dd is None or pp is None:
            continue
        x, u = pp.ratio_actual()
        x = np.mod(x, LEG_PERIOD)
        ax.plot(np.degrees(x), u, ".", ms=2.5, label=f"{dd.method} teeth: d theta / d phi from the outlines")
    ax.set_xlabel("driven angle phi within one leg, deg")
    ax.set_ylabel("gear ratio U = d theta / d phi")
    ax.set_title("The papers' Figure 2 (seed 000), from geometry: the law vs the ratio the teeth deliver")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("figure2_ratio", fig)


def _plots(w, d: Design, pr, profiles, mount: float):
    from ..export.plots import new_figure

    fig, ax = new_figure()
    ok = np.isfinite(pr.te_drive)
    ax.plot(np.degrees(pr.phi), 1e3 * (pr.phi_run - pr.phi), ".-", ms=2, lw=0.6,
            label="running position (loaded flank; least overlap where jammed)")
    ax.set_xlabel("driven angle phi, deg")
    ax.set_ylabel("transmission error (actual - law), mrad of the driven wheel")
    ax2 = ax.twinx()
    ax2.plot(np.degrees(pr.phi[ok]), pr.backlash_mm[ok], "r.", ms=2, label="backlash")
    ax2.set_ylabel("backlash on the driven pitch curve, mm", color="r")
    ax.set_title(f"{d.method} teeth: transmission error and backlash over the whole cycle")
    fig.tight_layout()
    w.add_plot("transmission_error", fig)

    fig, ax = new_figure()
    ph = np.linspace(-math.pi / 4, math.pi / 4, 4001)
    mean = d.law.hub_speed_ratio
    ax.plot(np.degrees(ph), d.law.hub_speed(ph) / mean, "k--", lw=0.9, label="exact law (constant)")
    if d.method == "generated":
        ax.plot(np.degrees(ph), d.run_law.hub_speed(ph) / mean, "b-", lw=1.0,
                label=f"C2 blend {d.smoothing_deg:.2f} deg: ripple {100 * d.ripple.ripple:.2f} %")
    if d.table is not None or d.method == "sectors":
        from ..gears.sectors import sector_ratio

        tab = d.table
        if tab is not None:
            ax.plot(np.degrees(ph), d.law.dX01_dphi(ph) / sector_ratio(tab, ph) / mean, "g-", lw=0.8,
                    label=f"sector method (ideal teeth): ripple {100 * sector_hub_speed(tab).ripple:.2f} %")
    ax.set_xlabel("driven angle phi within one leg, deg")
    ax.set_ylabel("hub speed v/omega relative to its mean")
    ax.set_title("Price of the tooth method: hub speed over one leg (seed 000 eq. 2-3)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("hub_speed", fig)

    fig, ax = new_figure(6.5, 6.5)
    for prof, off in ((profiles[1], (0.0, 0.0)), (profiles[0], (mount, 0.0))):
        for q in prof.polylines(0.01):
            q = np.vstack([q, q[:1]]) + np.asarray(off)
            ax.plot(q[:, 0], q[:, 1], lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.set_title(f"pair at phi = theta = 0 ({d.method} teeth), centre distance {mount:.4f} mm")
    fig.tight_layout()
    w.add_plot("pair", fig)


def gear_profiles(p: NoncircularPairParams, d: Design):
    """(driver, driven) profiles with bore and keyway (InputError if they do not fit)."""
    return (_with_bore(d.driver.profile, p.driver_bore_mm, p.keyway, d.driver.root_min_radius, d.m, "driver"),
            _with_bore(d.driven.profile, p.driven_bore_mm, p.keyway, d.driven.root_min_radius, d.m, "driven"))


def compare(p: NoncircularPairParams, d: Design, prog=lambda s: None):
    """The other tooth method for the same law, module and teeth, proved over one leg (the pair
    repeats per leg) at its own design centre distance.  Returns (design, proof, note); (None,
    None, why) if it cannot be made."""
    alt = "sectors" if d.method == "generated" else "generated"
    try:
        q = _replace(p, method=alt, module_mm=d.m, center_distance_mm=0.0)
        q.validate()
        other = design_sectors(q, prog) if alt == "sectors" else design_generated(q, prog)
        return other, prove(other, p.proof_phases_per_tooth, 1, prog), ""
    except InputError as exc:
        return None, None, f"The {alt} method is not possible for these parameters: {exc}"


def build(p: NoncircularPairParams, w) -> None:
    prog = w.progress
    d = design(p, prog)
    profiles = gear_profiles(p, d)
    solids = start_solids(p, w, profiles)  # files and checks of the solids run beside the proof
    pr = prove(d, p.proof_phases_per_tooth, 4, prog, mounting(p, d))  # the built pair over the whole cycle
    other, pr_other, other_note = compare(p, d, prog) if p.compare_methods else (None, None, "")
    write_outputs(p, w, d, profiles, pr, other, pr_other, other_note, solids)


def start_solids(p: NoncircularPairParams, w, profiles):
    """Extrude both gears (face width) and hand them to the writer (STEP/STL/3MF and the shared
    checks, in its workers).  Returns (driver, driven) solids for the assembly."""
    from ..solids.build import extrude_profile

    w.progress("solids")
    prof_drv, prof_dvn = profiles
    s_drv = extrude_profile(prof_drv, p.face_width_mm)
    s_dvn = extrude_profile(prof_dvn, p.face_width_mm)
    w.add_solid("driven", s_dvn, expected_genus=1 if p.driven_bore_mm > 0 else 0)
    w.add_solid("driver", s_drv, expected_genus=1 if p.driver_bore_mm > 0 else 0)
    return s_drv, s_dvn


def write_outputs(p: NoncircularPairParams, w, d: Design, profiles, pr, other=None, pr_other=None,
                  other_note: str = "", solids=None) -> None:
    """Solids (STEP/STL/3MF with the shared checks), assembly, DXF, tables, plots, checks, report values."""
    prog = w.progress
    s_drv, s_dvn = solids if solids is not None else start_solids(p, w, profiles)
    prof_drv, prof_dvn = profiles
    w.add_assembly("pair", [("driven", s_dvn, (0.0, 0.0, 0.0), 0.0),
                            ("driver", s_drv, (mounting(p, d), 0.0, 0.0), 0.0)])

    # ---- DXF (gear axis at the origin, phase phi = theta = 0 of the assembly)
    for role, prof in (("driver", prof_drv), ("driven", prof_dvn)):
        ref = [("polyline", {"points": _pitch_polyline(d, role), "closed": True}),
               ("point", {"p": (0.0, 0.0)})]
        w.add_dxf(role, [prof], ref)

    # ---- tables
    table = _sector_tables(w, p)
    if d.method == "sectors":
        d.table = d.table or table
    elif table is not None:
        d.table = table
    th_act = pr.theta_actual()
    jam = ~np.isfinite(pr.phi_drive)
    # theta_actual: the driver angle at which the outlines put the driven wheel at phi (loaded flanks
    # touching; at a jammed phase the position of least overlap); te_run: driven running angle - law
    w.add_table("transmission", ["phi_rad", "theta_law_rad", "theta_actual_rad", "te_run_rad", "te_drive_rad",
                                 "backlash_mm", "pairs_drive", "overlap_law_mm2", "least_overlap_mm2", "jam"],
                [[float(a), float(b), float(c), float(r) - float(a), float(e) if math.isfinite(e) else None,
                  float(f) if math.isfinite(f) else None, int(g), float(h), float(i), bool(j)]
                 for a, b, c, r, e, f, g, h, i, j in zip(pr.phi, pr.theta_law, th_act, pr.phi_run, pr.te_drive,
                                                          pr.backlash_mm, pr.pairs_drive, pr.overlap_law,
                                                          pr.least_overlap, jam)])
    ph = np.linspace(-math.pi / 4, math.pi / 4, 721)
    pcr = PitchCurves(d.run_law, d.L)
    w.add_table("pitch_curves", ["phi_rad", "r_H_mm", "theta_rad", "r_mm", "ratio_U", "hub_speed_mm_per_rad"],
                [[float(a), float(b), float(c), float(e), float(f), float(g)] for a, b, c, e, f, g in
                 zip(ph, pcr.r_H(ph), d.run_law.theta(ph), pcr.r(ph), d.run_law.U(ph), d.run_law.hub_speed(ph))])
    if d.method == "generated":
        rows = []
        for gear in (d.driver, d.driven):
            for k, t in enumerate(gear.teeth):
                rows.append([gear.role, k, t.phi_centre, t.right, t.left, t.undercut, t.tip_height_mm,
                             t.tip_thickness_mm, t.shortened])
        w.add_table("teeth", ["gear", "tooth", "phi_centre_rad", "cutter_right", "cutter_left", "undercut",
                              "tip_height_mm", "tip_land_mm", "tip_shortened"], rows)

    # ---- plots
    _figure2(w, d, pr, other, pr_other)
    _plots(w, d, pr, profiles, mounting(p, d))

    # ---- checks, derived values, notes
    w.add_checks(_checks_generated(d, pr, p) if d.method == "generated" else _checks_sectors(d, pr))
    s = pr.summary()
    w.derived.update({
        "center_distance_mm": d.L, "mounting_distance_mm": mounting(p, d), "module_mm": d.m, "driver_teeth": d.z, "driven_teeth": d.z_H,
        "driver_turns": d.law.n, "method": d.method, "smoothing_deg": d.smoothing_deg,
        "speed_ripple": d.ripple.ripple,
        "speed_ripple_phi_min_deg": math.degrees(d.ripple.phi_min),
        "speed_ripple_phi_max_deg": math.degrees(d.ripple.phi_max),
        "hub_height_mm": d.law.A, "u": d.law.u, "hub_speed_mean_mm_per_rad": d.law.hub_speed_ratio,
        "closure_error_rad": d.closure_error,
        "proof_phases": s["steps"], "overlap_law_max_mm2": s["overlap_law_max_mm2"],
        "overlap_law_phases": s["overlap_law_steps"], "jam_phases": s["jams"],
        "te_min_rad": s["te_min_rad"], "te_max_rad": s["te_max_rad"], "te_pp_rad": s["te_pp_rad"],
        "backlash_min_mm": s["backlash_min_mm"], "backlash_max_mm": s["backlash_max_mm"],
        "contact_pairs_min": s["contact_pairs_min"], "contact_ratio_mean": s["contact_pairs_mean"],
    })
    if d.method == "generated":
        g = d.smoothing.generability
        w.derived.update({
            "smoothing_rad": d.smoothing.delta,
            "driver_rho_min_mm": g.driver.rho_convex_min, "driver_rho_limit_mm": g.driver.rho_limit,
            "driven_rho_min_mm": g.driven.rho_convex_min, "driven_rho_limit_mm": g.driven.rho_limit,
            "driven_concave_rho_min_mm": g.driven.rho_concave_min, "shaper_r0_mm": g.driven.r0,
            "driver_shift": p.driver_shift, "driven_shift": -p.driver_shift,
            "tip_shortened_teeth": d.driver.shortened_teeth + d.driven.shortened_teeth,
            "shaper_cut_teeth": d.driver.shaper_teeth + d.driven.shaper_teeth,
            "undercut_teeth": d.driver.undercut_teeth + d.driven.undercut_teeth,
        })
    else:
        w.derived.update({"sector_arc_mm": d.table.arc, "sectors_per_leg": d.table.i})
    if pr_other is not None:
        so = pr_other.summary()
        w.derived.update({f"compare_{other.method}_{k}": v for k, v in {
            "center_distance_mm": other.L, "speed_ripple": other.ripple.ripple, "smoothing_deg": other.smoothing_deg,
            "overlap_law_max_mm2": so["overlap_law_max_mm2"], "jam_phases": so["jams"], "proof_phases": so["steps"],
            "te_pp_rad": so["te_pp_rad"], "backlash_min_mm": so["backlash_min_mm"],
            "backlash_max_mm": so["backlash_max_mm"], "least_overlap_max_mm2": float(np.max(pr_other.least_overlap)),
        }.items()})
    _notes(w, d, pr, other, pr_other, other_note, p)


def _pct(x):
    return f"{100 * x:.2f} %"


def _notes(w, d, pr, other, pr_other, other_note, p):
    s = pr.summary()
    law = d.law
    w.add_note(
        f"Law (seed 000 eqs. 1-15, periodic per leg, SPEC Trap 1): A = a - b + c = {law.A:g} mm, "
        f"u = n pi A / (A pi + 6 b) = {law.u:.6f}, n = {law.n}; constant hub speed v/omega = A/u = "
        f"{law.hub_speed_ratio:.4f} mm/rad with the exact law.  Closure by true arc length (Trap 3): "
        f"L = {d.L:.6f} mm, m = {d.m:.6f} mm, z {d.z}/{d.z_H}; the driver makes exactly n turns per driven turn "
        f"(closure error {d.closure_error:.2g} rad).")
    if d.method == "generated":
        sm = d.smoothing
        g = sm.generability
        r = d.ripple
        w.add_note(
            f"Price of smoothing (SPEC Trap 2): the exact law has corners at leg hand-over (phi = 45 deg + k 90 deg); "
            f"it is replaced there by an even degree-6 polynomial in the blend window of half-width "
            f"{d.smoothing_deg:.4f} deg ({sm.delta:.6f} rad), matching U, U', U'' at the window ends (C2) and the "
            f"window integral (closure exact).  It was chosen as the "
            f"{'smallest blend' if p.smoothing_deg == 0 else 'given blend'} keeping both pitch curves generable: "
            f"driver convex rho_min {g.driver.rho_convex_min:.3f} mm >= rack undercut limit {g.driver.rho_limit:.3f} mm "
            f"(shift x = {p.driver_shift:+g}), driven rho_min {g.driven.rho_convex_min:.3f} mm >= {g.driven.rho_limit:.3f} mm "
            f"(x = {-p.driver_shift:+g})"
            + (f", driven concave |rho|_min {g.driven.rho_concave_min:.3f} mm > shaper pitch radius {g.driven.r0:.3f} mm"
               if g.driven.concave else "")
            + (f", driver concave |rho|_min {g.driver.rho_concave_min:.3f} mm > {g.driver.r0:.3f} mm" if g.driver.concave else "")
            + f".  The hub speed v/omega = (dX01/dphi)/U is constant outside the windows; inside them it ripples by "
              f"(max - min)/mean = {_pct(r.ripple)}, the minimum at phi = {math.degrees(r.phi_min):.3f} deg (hand-over) "
              f"and the maximum at phi = {math.degrees(r.phi_max):.3f} deg (inside the window).")
        w.add_note(
            f"Generated teeth: ISO 53 rack (alpha = {p.pressure_angle_deg:g} deg, h_a* = 1, c* = 0.25, rho_f* = 0.38) "
            f"rolling on each pitch curve on one shared arc-length frame; driver shift {p.driver_shift:+g}, driven "
            f"{-p.driver_shift:+g} (one imaginary rack: the pair stays conjugate at the pitch-curve centre distance); "
            f"{d.driven.shaper_teeth + d.driver.shaper_teeth} teeth next to concave stretches cut by a shaper z0 = "
            f"{p.shaper_teeth} (x0 = -x of the gear); {d.driver.shortened_teeth + d.driven.shortened_teeth} tips "
            f"shortened to a land of {p.tip_land_min_module:g} m; undercut teeth: "
            f"{d.driver.undercut_teeth + d.driven.undercut_teeth}; backlash j_n = {p.backlash_mm:g} mm as tooth "
            f"thinning j_n/(2 cos alpha) per gear.")
    else:
        w.add_note(
            f"Sector teeth (the papers' method): {d.table.i} sectors per leg of equal arc "
            f"{d.table.arc:.4f} mm (pi m = {math.pi * d.m:.4f} mm), base radius r - m, tip r + m, root r - 1.25 m, "
            f"backlash as the angular correction j_n/(4 r_b), j_n = {p.backlash_mm:g} mm (seed 002 Tables 2-4).  "
            "Transitions the papers leave open (ours): below the base circle the flank is radial down to the root; "
            "a driven tooth between spaces i and i+1 has the tip radius of sector i+1 (the 6th point of Table 4; a "
            "radial flank where that tip lies below the base circle of sector i); a driver space straddling two "
            "sectors has a root whose radius passes between the two root radii by the quintic smoothstep in angle.  "
            f"Even with ideal teeth the staircase ratio leaves a hub speed ripple of {_pct(d.ripple.ripple)}.")
    w.add_note(
        f"Proof on the finished outlines ({d.method}, {s['steps']} phases over the whole driven turn, "
        f"{p.proof_phases_per_tooth} per driven tooth, manifold3d booleans, gears at the installed centre "
        f"distance {mounting(p, d):.4f} mm): overlap at the law's positions max "
        f"{s['overlap_law_max_mm2']:.4g} mm^2 ({s['overlap_law_steps']} phases); phases without a free position "
        f"(jam) {s['jams']}; transmission error of the loaded flank {s['te_min_rad']:.4e} .. {s['te_max_rad']:.4e} rad "
        f"(peak-to-peak {s['te_pp_rad']:.3e} rad); backlash {s['backlash_min_mm']:.4f} .. {s['backlash_max_mm']:.4f} mm "
        f"on the driven pitch curve; tooth pairs in contact min {s['contact_pairs_min']}, mean "
        f"{s['contact_pairs_mean']:.3f}.")
    if pr_other is not None:
        so = pr_other.summary()
        w.add_note(
            f"Comparison with the {other.method} method for the same law, module and teeth (one leg, "
            f"{so['steps']} phases; L = {other.L:.4f} mm): hub speed ripple {_pct(other.ripple.ripple)} vs "
            f"{_pct(d.ripple.ripple)}; overlap at the law's positions max {so['overlap_law_max_mm2']:.4g} mm^2 "
            f"({so['overlap_law_steps']} phases); jams {so['jams']} (least overlap up to "
            f"{float(np.max(pr_other.least_overlap)):.4g} mm^2); transmission error peak-to-peak "
            f"{so['te_pp_rad']:.3e} rad; backlash {so['backlash_min_mm']:.4f} .. {so['backlash_max_mm']:.4f} mm.  "
            "plots/figure2_ratio.png shows both against the law.")
    elif other_note:
        w.add_note(other_note)


PART_TYPE = PartType(
    name="noncircular_pair",
    summary="non-circular gear pair of the wheel-walking propulsor drive (seeds 000, 002): generated or sector teeth",
    params_cls=NoncircularPairParams,
    build=build,
)
