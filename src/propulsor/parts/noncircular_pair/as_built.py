"""The as-built hub speed of a pair: the loaded contact law of the finished outlines, resolved around every
change of contact, and the hub speed ripple from its derivative.

The full-cycle proof samples the loaded flank's transmission error te(phi) (driver at theta_law(phi), the driven
wheel turned back until the outlines touch: ``pair_proof``) at ``proof_phases_per_tooth`` phases per tooth.  That
is enough for overlap and backlash, not for a derivative: where the contact leaves the conjugate flanks (a tip
corner of the leaving pair touching the mate's flank, or one corner sliding over a flank) te bends within a
fraction of a step, and a spline through the column smears or misses it.  Here te is resolved by bisection:
an interval is split while its midpoint departs from the chord by more than ``slope_tol`` x width / 4 (a change
of slope of more than ``slope_tol`` inside it), down to ``h_min``.  The driven wheel runs at
phi_a = phi + te(phi) while the driver turns by theta_law(phi), so the hub speed per driver radian is

    v/omega = dX01/dphi (phi_a) * (1 + te'(phi)) / U(phi)           (seed 000 eq. 2-3)

with te' the chord slopes of the resolved samples and U the law the teeth realise; the ripple is
(max - min) / mean with the mean A/u of every closed law (``laws.walking.HubSpeedRipple``).  A pair whose
tooth count per leg is whole repeats per leg, and one leg is resolved.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy
from ...laws.walking import LEG_PERIOD

__all__ = ["AsBuilt", "resolve_contact_law", "as_built_speed", "as_built"]


@dataclass(frozen=True)
class AsBuilt:
    """The as-built hub speed over the resolved stretch (one leg or the whole turn)."""

    phi: np.ndarray      #: resolved driven law angles (rad)
    te: np.ndarray       #: loaded-flank transmission error there (rad)
    ripple: float        #: (max - min) / mean of v/omega
    v_min_rel: float     #: least v/omega over its mean
    v_max_rel: float
    phi_min: float       #: driven angle of the least speed within the leg (rad)
    phi_max: float
    finest_step: float   #: the narrowest resolved interval (rad)
    evaluations: int     #: contact positions measured beyond the proof's

    @property
    def te_slope_extremes(self) -> tuple[float, float]:
        s = np.diff(self.te) / np.diff(self.phi)
        return float(s.min()), float(s.max())


def resolve_contact_law(evaluate, phi, te, slope_tol: float, h_min: float, max_evals: int):
    """(phi, te, evaluations): the samples (phi, te) refined by bisection where the chord is not the law:
    ``evaluate(array of phi) -> array of te`` measures new points, level by level; an interval is split
    while |te(mid) - chord(mid)| > slope_tol (b - a) / 4 and (b - a) / 2 >= h_min, at most ``max_evals``
    measurements in all.  Intervals with a non-finite end are left as they are."""
    pts = {float(x): float(y) for x, y in zip(phi, te)}
    xs = sorted(pts)
    todo = [(a, b) for a, b in zip(xs[:-1], xs[1:]) if math.isfinite(pts[a]) and math.isfinite(pts[b])]
    n = 0
    while todo and n < max_evals:
        todo = todo[:max_evals - n]
        mids = np.array([0.5 * (a + b) for a, b in todo])
        vals = np.asarray(evaluate(mids), float)
        n += len(mids)
        nxt = []
        for (a, b), m, v in zip(todo, mids, vals):
            pts[float(m)] = float(v)
            if not math.isfinite(v):
                continue
            if abs(v - 0.5 * (pts[a] + pts[b])) > slope_tol * (b - a) / 4 and (b - a) / 2 >= h_min:
                nxt += [(a, float(m)), (float(m), b)]
        todo = nxt
    xs = np.array(sorted(pts))
    return xs, np.array([pts[x] for x in xs]), n


def as_built_speed(law, run_law, phi, te, samples: int = 20001):
    """(phi grid, v/omega) of the loaded outlines: te piecewise linear through the resolved samples, its
    chord slopes for te', the law ``run_law`` the teeth realise for U, the mechanism's ``law`` for dX01/dphi."""
    grid = np.union1d(np.linspace(phi[0], phi[-1], samples), 0.5 * (phi[1:] + phi[:-1]))
    k = np.clip(np.searchsorted(phi, grid, side="right") - 1, 0, len(phi) - 2)
    slope = np.diff(te) / np.diff(phi)
    t = te[k] + slope[k] * (grid - phi[k])
    return grid, law.dX01_dphi(grid + t) * (1.0 + slope[k]) / run_law.U(grid)


def as_built(d, mount: float, pr) -> AsBuilt | None:
    """The as-built speed of design ``d`` (generated or sector teeth) at the installed centre distance from
    its full-cycle proof ``pr``; None where the proof found a jam (no running position: no speed)."""
    from ...gears.noncircular import PitchCurves
    from .pair_proof import prove_pair

    if pr.jams or not np.all(np.isfinite(pr.phi_drive)):
        return None
    one_leg = d.z_H % 4 == 0
    span = LEG_PERIOD if one_leg else 2 * math.pi
    sel = pr.phi < span - 1e-12
    phi = np.append(pr.phi[sel], span)
    te = np.append(pr.te_drive[sel], pr.te_drive[0])  # periodic: the pair repeats per leg / per turn
    pc = PitchCurves(d.run_law, d.L)
    pitch = math.pi * d.m if d.method == "generated" else d.table.arc

    def evaluate(ph):
        ph = np.asarray(ph, float)
        order = np.argsort(ph)
        r = prove_pair(d.driver.profile, d.driven.profile, mount, d.run_law.theta, ph[order], pc.r_H,
                       name="as_built", pitch_mm=pitch)
        out = np.empty(len(ph))
        out[order] = r.phi_drive - ph[order]
        return out

    xs, ys, n = resolve_contact_law(evaluate, phi, te, policy.AS_BUILT_SLOPE_TOL, policy.AS_BUILT_STEP_MIN_RAD,
                                    policy.AS_BUILT_EVALUATIONS_MAX)
    ok = np.isfinite(ys)
    xs, ys = xs[ok], ys[ok]
    grid, v = as_built_speed(d.law, d.run_law, xs, ys)
    mean = d.law.hub_speed_ratio
    i, j = int(np.argmin(v)), int(np.argmax(v))
    return AsBuilt(xs, ys, float((v[j] - v[i]) / mean), float(v[i] / mean), float(v[j] / mean), float(grid[i]),
                   float(grid[j]), float(np.min(np.diff(xs))), n)
