"""The pair as made: its as-built transmission within the shop's (or the printer's) tolerances.

A made pair differs from the drawing by
* the centre distance: L + dL, |dL| <= f_a;
* the radial run-out of each wheel: its outline turns about an axis e_i off its own centre (e_i <= F_r,i / 2, the
  offset in the direction psi_i of the wheel's body frame);
* the tooth thickness: each flank thinner (t_i > 0) or thicker (t_i < 0) along its normal, t_i in [t_lo, t_hi].

Each case is the as-built contact of :mod:`.as_built` on the outlines so changed (both directions over the whole
driven turn: run-out breaks the leg's period), sampled every ``policy.TOLERANCE_STEP_DRIVER_DEG`` of driver with
every change of contact bisected.  What it gives: the transmission error peak-to-peak of each direction, the least
backlash (a jam where it reaches zero: the driven angle named), the largest step of driven speed at a change of
contact (a tooth pair that loses contact before the next takes over: named with its angle).

Defaults for a machined pair (``iso1328``): accuracy grade A of ISO 1328 for the module and the mean pitch diameter
d = z m of each wheel: radial run-out F_r = 0.8 (0.3 m + 1.25 sqrt(d) + 7) 2^((A - 5) / 2) micrometres (ISO 1328-2:1997,
5.4.1); centre-distance allowance f_a = IT_A / 2 of the centre distance (ISO 286-1 standard tolerance of the same
grade number, i = 0.45 L^(1/3) + 0.001 L: DIN 3964's pairing of centre-distance and gear grades); tooth thickness
thinner by 0 .. F_r tan(alpha) per flank (the run-out's share of the thickness tolerance, DIN 3967).  For a print
kit (``printed``): the printer's xy accuracy on every edge (each flank +- acc), the pins' running clearance as
run-out, the centre distance +- acc.  Worst case: the corners (L - f_a with the thickest teeth, L + f_a with the
thinnest, each with the run-outs in phase and opposed); Monte Carlo: N cases drawn uniformly with a stated seed.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, replace

import numpy as np

from ... import policy
from ...checks.motion.contact_events import DRIVE, REVERSE, PairOutlines, resolve_contact
from ...checks.motion.outlines import Outline, offset_outline

__all__ = ["Tolerances", "Case", "CaseResult", "ToleranceStudy", "iso1328", "printed", "worst_cases",
           "monte_carlo_cases", "run_case", "tolerance_study"]


@dataclass(frozen=True)
class Tolerances:
    """What the made pair may differ by (mm)."""

    f_a: float                   #: centre distance allowance: L +- f_a
    e_driver: float              #: largest eccentricity (half the radial run-out) of the driver
    e_driven: float
    t_lo: float                  #: flank offset range (mm, + thinner) of every tooth of both wheels
    t_hi: float
    source: str                  #: where the numbers come from


@dataclass(frozen=True)
class Case:
    name: str
    dL: float = 0.0
    e_driver: float = 0.0
    psi_driver: float = 0.0
    e_driven: float = 0.0
    psi_driven: float = 0.0
    t_driver: float = 0.0
    t_driven: float = 0.0


@dataclass(frozen=True)
class CaseResult:
    case: Case
    te_pp_drive: float
    te_pp_reverse: float
    backlash_min_mm: float
    backlash_min_phi: float
    step_max: float
    step_theta: float            #: driver angle of the largest step (rad)
    lost: int                    #: samples without contact

    @property
    def jam(self) -> bool:
        return not self.backlash_min_mm > 0.0


@dataclass(frozen=True)
class ToleranceStudy:
    tolerances: Tolerances
    worst: tuple                  #: CaseResult of every worst-case corner
    samples: tuple                #: CaseResult of the Monte Carlo cases
    seed: int
    seconds: float

    def percentiles(self, name: str, q=(5, 50, 95)) -> tuple:
        v = np.array([getattr(r, name) for r in self.samples], float)
        return tuple(float(np.percentile(v, k)) for k in q) if len(v) else tuple(math.nan for _ in q)


def _it(L: float, grade: int) -> float:
    """ISO 286-1 standard tolerance IT<grade> (mm) for a size L (mm): i = 0.45 L^(1/3) + 0.001 L micrometres and
    the grade's multiple (IT5 7 i ... IT11 100 i; each grade 1.6 times the last)."""
    i = 0.45 * L ** (1.0 / 3.0) + 0.001 * L
    mult = {5: 7, 6: 10, 7: 16, 8: 25, 9: 40, 10: 64, 11: 100, 12: 160}[int(min(max(grade, 5), 12))]
    return mult * i * 1e-3


def _runout(m: float, d: float, grade: int) -> float:
    """ISO 1328-2:1997 radial run-out tolerance F_r (mm) of grade A for module m and reference diameter d."""
    return 0.8 * (0.3 * m + 1.25 * math.sqrt(d) + 7.0) * 2.0 ** ((grade - 5) / 2.0) * 1e-3


def iso1328(d, mount: float, grade: int = 8, alpha: float = math.radians(20.0)) -> Tolerances:
    """Tolerances of a machined pair of accuracy grade ``grade`` (module d.m, mean pitch diameters z m)."""
    F1, F2 = _runout(d.m, d.z * d.m, grade), _runout(d.m, d.z_H * d.m, grade)
    f_a = 0.5 * _it(mount, grade)
    t = max(F1, F2) * math.tan(alpha)
    return Tolerances(f_a, 0.5 * F1, 0.5 * F2, 0.0, t,
                      f"ISO 1328 grade {grade}: F_r {1e3 * F1:.1f} / {1e3 * F2:.1f} um (driver / driven), "
                      f"f_a = IT{grade}/2 = {1e3 * f_a:.1f} um, flanks thinner by 0 .. {1e3 * t:.1f} um")


def printed(accuracy_mm: float, running_clearance_mm: float) -> Tolerances:
    """Tolerances of a printed pair: every edge +- the printer's xy accuracy, the pins' running clearance as the
    wheels' eccentricity, the centre distance +- the accuracy."""
    return Tolerances(accuracy_mm, running_clearance_mm, running_clearance_mm, -accuracy_mm, accuracy_mm,
                      f"printed: edges +- {accuracy_mm:g} mm (xy accuracy), run-out {running_clearance_mm:g} mm "
                      f"(the pins' running clearance), centre distance +- {accuracy_mm:g} mm")


def worst_cases(tol: Tolerances) -> list[Case]:
    """The corners: tight (L - f_a, the thickest teeth) and loose (L + f_a, the thinnest), each with the two
    wheels' run-outs in phase and opposed."""
    out = []
    for name, dL, t in (("tight", -tol.f_a, tol.t_lo), ("loose", tol.f_a, tol.t_hi)):
        for ph, psi2 in (("in phase", 0.0), ("opposed", math.pi)):
            out.append(Case(f"{name}, run-outs {ph}", dL, tol.e_driver, 0.0, tol.e_driven, psi2, t, t))
    return out


def monte_carlo_cases(tol: Tolerances, n: int, seed: int) -> list[Case]:
    rng = random.Random(seed)
    return [Case(f"sample {k + 1}", rng.uniform(-tol.f_a, tol.f_a), rng.uniform(0.0, tol.e_driver),
                 rng.uniform(0.0, 2 * math.pi), rng.uniform(0.0, tol.e_driven), rng.uniform(0.0, 2 * math.pi),
                 rng.uniform(tol.t_lo, tol.t_hi), rng.uniform(tol.t_lo, tol.t_hi)) for k in range(n)]


def _changed(o: Outline, e: float, psi: float, t: float) -> Outline:
    """The outline made: flanks offset inward by t (outward for t < 0), its centre e off the rotation axis."""
    return offset_outline(o, t, (e * math.cos(psi), e * math.sin(psi)))


def run_case(d, mount: float, case: Case, step_driver_rad: float | None = None) -> CaseResult:
    """Both directions of the pair made as ``case`` says, over the whole driven turn."""
    from ...gears.noncircular import PitchCurves
    from .as_built import pair_outlines

    base = pair_outlines(d, mount)
    drv = _changed(base.drv, case.e_driver, case.psi_driver, case.t_driver)
    dvn = _changed(base.dvn, case.e_driven, case.psi_driven, case.t_driven)
    po = PairOutlines(drv, dvn, mount + case.dL, base.driver_teeth, base.driven_teeth)
    step = step_driver_rad if step_driver_rad is not None else math.radians(policy.TOLERANCE_STEP_DRIVER_DEG)
    # a jammed case has no running position: its contact changes everywhere; bounded to a few times the samples
    cap = int(4 * 360.0 * d.law.n / math.degrees(step)) + 1000
    dr, rv = (resolve_contact(po, d.run_law.theta, 0.0, 2 * math.pi, k, step_driver_rad=step, max_evals=cap)
              for k in (DRIVE, REVERSE))
    x = np.union1d(dr.phi, rv.phi)
    okd, okr = np.isfinite(dr.te), np.isfinite(rv.te)
    gap = (np.interp(x, rv.phi[okr], rv.te[okr]) - np.interp(x, dr.phi[okd], dr.te[okd]))
    bl = gap * np.asarray(PitchCurves(d.run_law, d.L).r_H(x), float)
    k = int(np.argmin(bl))
    worst = max((dr, rv), key=lambda c: c.step_max)
    at = worst.step_at()
    lost = int(np.count_nonzero(~okd) + np.count_nonzero(~okr))
    return CaseResult(case, dr.te_pp, rv.te_pp, float(bl[k]), float(x[k]), worst.step_max,
                      at[1] if at else math.nan, lost)


def tolerance_study(d, mount: float, tol: Tolerances, samples: int = 8, seed: int = 1,
                    step_driver_rad: float | None = None) -> ToleranceStudy:
    """The worst-case corners and ``samples`` Monte Carlo cases (seeded) of the pair made within ``tol``."""
    import time

    t0 = time.perf_counter()
    worst = tuple(run_case(d, mount, c, step_driver_rad) for c in worst_cases(tol))
    mc = tuple(run_case(d, mount, c, step_driver_rad) for c in monte_carlo_cases(tol, samples, seed))
    return ToleranceStudy(tol, worst, mc, seed, time.perf_counter() - t0)


def scaled(tol: Tolerances, k: float) -> Tolerances:
    """The same tolerances k times as wide (a mutation for the tests; a sensitivity for a user)."""
    return replace(tol, f_a=tol.f_a * k, e_driver=tol.e_driver * k, e_driven=tol.e_driven * k, t_lo=tol.t_lo * k,
                   t_hi=tol.t_hi * k)
