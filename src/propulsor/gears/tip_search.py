"""The tips of the generated non-circular teeth (seeds 000 and 002; :mod:`.noncircular_teeth`): where a flank meets
the tip equidistant at a height, the tip land's length between a tooth's two flanks, and the tallest tip whose land is
at least the minimum (tip shortening).  Pure math (numpy/scipy).  Millimetres, radians.

A tooth's tip at height h above its pitch curve runs along the equidistant ``curve.offset(phi, h)`` from where the
left flank meets it to where the right one does (``tip_hit``: (flank parameter u, driven angle phi), or None where
the flank stops short of h).  ``ToothLand`` is one tooth's land as a function of h; ``tallest_tip`` searches it.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import fsolve

from ..planar import norms
from ..policy import (FD_STEP_ARC_RAD, FD_STEP_PHI_RAD, FD_STEP_REL, NEWTON_STOP_MM, ROOT_XTOL_FINE, SOLVE_RESIDUAL_MM,
                      TIP_HEIGHT_TOL_MM, TIP_NEWTON_ITER_MAX, TIP_REACH_PROBE_MM, TIP_SECANT_STEPS_MAX)
from .envelope import PitchCurveCentrode, envelope_points
from .pitch_frame import ArcFrame, BodyPitchCurve

__all__ = ["tip_hit", "tip_hits_batch", "near", "land_length", "ToothLand", "flank_reach", "tallest_tip"]

#: Gauss-Legendre nodes and weights of the tip land's length
_GX, _GW = np.polynomial.legendre.leggauss(10)


def tip_hit(side, curve: BodyPitchCurve, h: float, phi_guess: float, span: float, memo=None):
    """(u, phi) where the flank meets the tip equidistant at height h (None if it does not within
    the flank's range): nearest pair of samples, then fsolve.  ``memo`` (a dict, one per tooth), when given, keeps
    what does not depend on h between the calls of one tooth's tip search: the flank's 41 samples and the pitch
    curve's points and normals at the 121 sampled angles (the equidistant at h is ``point + h normal``, the
    operations of ``curve.offset``: the same samples to the last bit)."""
    fla = side.flank
    u = np.linspace(fla.u0, fla.u1, 41)
    ph = phi_guess + np.linspace(-0.6, 0.6, 121) * span
    if memo is None:
        X = fla(u)
        T = curve.offset(ph, h)
    else:
        kept = memo.get(id(fla))
        if kept is None or kept[0] is not fla or kept[1] != (phi_guess, span):
            kept = memo[id(fla)] = (fla, (phi_guess, span), fla(u), curve.point(ph), curve.normal(ph))
        X, P, N = kept[2], kept[3], kept[4]
        T = P + h * N
    D = norms(X[:, None, :] - T[None, :, :])
    i, j = np.unravel_index(int(np.argmin(D)), D.shape)
    g = lambda y: fla.at(y[0]) - curve.offset(np.array([y[1]]), h)[0]
    tol = SOLVE_RESIDUAL_MM
    ok = lambda y: np.linalg.norm(g(y)) <= tol and min(fla.u0, fla.u1) - tol <= y[0] <= max(fla.u0, fla.u1) + tol
    try:
        sol = _newton(fla, curve, h, float(u[i]), float(ph[j]))
    except (ArithmeticError, ValueError):  # a step off the flank's domain: the hybrid method decides
        sol = None
    if sol is not None and ok(sol):
        return float(sol[0]), near(float(sol[1]), phi_guess, curve)
    sol = fsolve(g, [u[i], ph[j]], xtol=ROOT_XTOL_FINE, full_output=True)[0]
    if not ok(sol) and i in (0, len(u) - 1):
        # the flank's end can be a cusp of its envelope (a shaper's involute starts on its base circle, where its
        # derivative vanishes): fsolve stalls there, so start again from the sample next to it
        sol = fsolve(g, [u[1] if i == 0 else u[-2], ph[j]], xtol=ROOT_XTOL_FINE, full_output=True)[0]
    if not ok(sol):
        return None
    return float(sol[0]), near(float(sol[1]), phi_guess, curve)


def _newton(fla, curve: BodyPitchCurve, h: float, u: float, ph: float):
    """(u, phi) where the flank ``fla`` meets the equidistant at h, by Newton's method from (u, ph): the Jacobian by
    forward differences (the steps of :func:`tip_hits_batch`), the flank and the equidistant each evaluated twice an
    iteration, where fsolve's hybrid method takes about 29 evaluations of both a root.  Stops once the residual is
    below ``NEWTON_STOP_MM``, after one more step of the last Jacobian (no evaluation: it takes the root from about
    1e-12 mm to rounding).  None, for the caller's hybrid method to decide, where an iterate leaves the flank's
    range (there the plain iteration may run to a root off the flank while one lies on it, or to none) or
    ``TIP_NEWTON_ITER_MAX`` iterations do not get there (from the nearest of the samples it takes 2 or 3 on the
    seed pairs' tips)."""
    eu, ep = FD_STEP_REL * max(1.0, abs(fla.u1 - fla.u0)), FD_STEP_PHI_RAD
    lo, hi = min(fla.u0, fla.u1) - SOLVE_RESIDUAL_MM, max(fla.u0, fla.u1) + SOLVE_RESIDUAL_MM
    ax = ay = bx = by = 0.0
    for k in range(TIP_NEWTON_ITER_MAX + 1):
        Xu = fla.at(u)
        T = curve.offset(np.array([ph]), h)[0]
        gx, gy = float(Xu[0] - T[0]), float(Xu[1] - T[1])
        if k > 0 and math.hypot(gx, gy) < NEWTON_STOP_MM:
            det = ax * (-by) - ay * (-bx)
            return u - (gx * (-by) - gy * (-bx)) / det, ph - (ax * gy - ay * gx) / det
        if k == TIP_NEWTON_ITER_MAX:
            return None
        dX = (fla.at(u + eu) - Xu) / eu
        dT = (curve.offset(np.array([ph + ep]), h)[0] - T) / ep
        ax, ay, bx, by = float(dX[0]), float(dX[1]), float(dT[0]), float(dT[1])
        det = ax * (-by) - ay * (-bx)
        if not (math.isfinite(det) and det != 0.0):
            return None
        u, ph = u - (gx * (-by) - gy * (-bx)) / det, ph - (ax * gy - ay * gx) / det
        if not (lo <= u <= hi and math.isfinite(ph)):
            return None
    return None


def near(phi: float, ref: float, curve: BodyPitchCurve) -> float:
    """phi moved by whole periods of the body pitch curve (2 pi driven, 2 pi / n driver) next to ref: a
    solver may land on the same point one turn away."""
    period = 2.0 * math.pi if curve.role == "driven" else 2.0 * math.pi / curve.pc.law.n
    return float(phi - period * round((phi - ref) / period))


def tip_hits_batch(sides: list, s_k: np.ndarray, ph_k: np.ndarray, curve: BodyPitchCurve, frame: ArcFrame,
                   h: float, span: float) -> list:
    """``tip_hit`` for many sides at once (grouped by their cutter piece): vectorised sampling for
    the start and a vectorised Newton iteration on (u, phi); sides that do not converge fall back
    to ``tip_hit``."""
    out = [None] * len(sides)
    groups: dict = {}
    for i, sd in enumerate(sides):
        groups.setdefault((id(sd.flank.piece), sd.flank.u0, sd.flank.u1), []).append(i)
    nu, nph = 41, 121
    for (_, u0, u1), idx in groups.items():
        idx = np.asarray(idx)
        n = len(idx)
        fla = sides[idx[0]].flank
        sk = np.asarray(s_k, float)[idx]
        pk = np.asarray(ph_k, float)[idx]

        def X(u, skk):
            cen = PitchCurveCentrode(curve, frame, skk)
            return envelope_points(fla.piece, u, fla.cutter, cen)[0]

        ug = np.linspace(u0, u1, nu)
        Xs = X(np.tile(ug, n), np.repeat(sk, nu)).reshape(n, nu, 2)
        pg = pk[:, None] + np.linspace(-0.6, 0.6, nph)[None, :] * span
        Ts = curve.offset(pg.ravel(), h).reshape(n, nph, 2)
        D = norms(Xs[:, :, None, :] - Ts[:, None, :, :]).reshape(n, -1)
        k = np.argmin(D, axis=1)
        u = ug[k // nph]
        ph = pg[np.arange(n), k % nph]
        eu, ep = FD_STEP_REL * max(1.0, abs(u1 - u0)), FD_STEP_PHI_RAD
        for _ in range(12):
            Xu = X(u, sk)
            T = curve.offset(ph, h)
            G = Xu - T
            if np.max(norms(G)) < NEWTON_STOP_MM:
                break
            dX = (X(u + eu, sk) - Xu) / eu
            dT = (curve.offset(ph + ep, h) - T) / ep
            det = dX[:, 0] * (-dT[:, 1]) - dX[:, 1] * (-dT[:, 0])
            det = np.where(np.abs(det) > 1e-300, det, 1e-300)
            du = -(G[:, 0] * (-dT[:, 1]) - G[:, 1] * (-dT[:, 0])) / det
            dp = -(dX[:, 0] * G[:, 1] - dX[:, 1] * G[:, 0]) / det
            u, ph = u + du, ph + dp
        res = norms(X(u, sk) - curve.offset(ph, h))
        for j, i in enumerate(idx):
            tol = SOLVE_RESIDUAL_MM
            if res[j] <= tol and min(u0, u1) - tol <= u[j] <= max(u0, u1) + tol:
                out[i] = (float(u[j]), near(float(ph[j]), float(pk[j]), curve))
            else:
                out[i] = tip_hit(sides[i], curve, h, float(pk[j]), span)
    return out


def land_length(curve: BodyPitchCurve, h: float, a: float, b: float) -> float:
    """Length (mm) of the equidistant at height h between the driven angles a and b (either order): 10-point
    Gauss-Legendre in phi of its speed |d/dphi (P + h n)|."""
    ph = 0.5 * (b - a) * _GX + 0.5 * (a + b)
    # |d/dphi (P + h n)| by central differences of the exact equidistant (h small vs rho)
    eps = FD_STEP_ARC_RAD
    d = (curve.offset(ph + eps, h) - curve.offset(ph - eps, h)) / (2 * eps)
    return abs(0.5 * (b - a) * float(np.dot(_GW, norms(d))))


class ToothLand:
    """One tooth's tip land as a function of the tip height h: ``land(h) = (t, right hit, left hit)``, t the land's
    length along the equidistant (negative where the flanks cross below h, -1.0 where a side has no tip there), the
    hits ``tip_hit``'s (u, phi) or None.  The nominal height's hits come from the batched search (``at_nominal``);
    every other height's from ``tip_hit``, with one memo for the tooth (its samples that do not depend on h)."""

    def __init__(self, right, left, curve: BodyPitchCurve, frame: ArcFrame, s_k: float, ph_k: float, span: float,
                 h_nominal: float, at_nominal: tuple):
        self.sides, self.curve, self.frame = (right, left), curve, frame
        self.s_k, self.ph_k, self.span = s_k, ph_k, span
        self.h_nominal, self.at_nominal = h_nominal, at_nominal
        self.first = 0  # the side searched first (0 right, 1 left): the one that last had no tip
        self.memo = {}

    def hits(self, h: float) -> tuple:
        if h == self.h_nominal:
            return self.at_nominal
        # a side without a tip at h leaves no land there, whatever the other side reaches (every reader of a landless
        # result asks only whether a hit is None): where the side searched first has none, the other side's search is
        # not made
        a = self.first
        got = [None, None]
        got[a] = tip_hit(self.sides[a], self.curve, h, self.ph_k, self.span, self.memo)
        if got[a] is not None:
            got[1 - a] = tip_hit(self.sides[1 - a], self.curve, h, self.ph_k, self.span, self.memo)
            if got[1 - a] is None:
                self.first = 1 - a
        return got[0], got[1]

    def __call__(self, h: float) -> tuple:
        hr, hl = self.hits(h)
        if hr is None or hl is None:
            return -1.0, hr, hl
        curve, frame, s_k = self.curve, self.frame, self.s_k
        # right side is clockwise: generation arc sg > 0; left sg < 0
        sg_r = curve.sgn * (frame.s(np.array([hr[1]]))[0] - s_k)
        sg_l = curve.sgn * (frame.s(np.array([hl[1]]))[0] - s_k)
        t = land_length(curve, h, hl[1], hr[1])
        return (t if sg_r > sg_l else -t), hr, hl



def flank_reach(sides, curve: BodyPitchCurve, phi_guess: float, span: float) -> float:
    """Where a tooth's tip leaves its flanks: the height above the pitch curve (along its outward normal at the foot
    point, ``BodyPitchCurve.heights``, within the tip search's 121 sampled angles) of the higher end of each side's
    flank, the lower of the two sides.  Only a guess for ``tallest_tip``'s bracket: what it decides rests on the
    heights it evaluates."""
    E = np.array([sd.flank.at(u) for sd in sides for u in (sd.flank.u0, sd.flank.u1)])
    hgt = curve.heights(E, 0.0, phi_guess + np.linspace(-0.6, 0.6, 121) * span)
    return float(min(max(hgt[0], hgt[1]), max(hgt[2], hgt[3])))


def tallest_tip(thickness, h_lo: float, at_lo: tuple, h_hi: float, at_hi: tuple, t_min: float, reach=None):
    """(h, thickness(h)) of the bisection of [h_lo, h_hi] down to ``TIP_HEIGHT_TOL_MM`` for the largest tip height
    whose land is at least ``t_min`` (``thickness(h) = (land, right hit, left hit)``; at_lo, at_hi: its values at
    h_lo and h_hi, at_lo[0] >= t_min > at_hi[0]), in fewer evaluations, the
    same h to the last bit: the land's root is first bracketed to 1e-3 of the tolerance by the Illinois method (the
    land is smooth and falls with the height), then the bisection's halvings are taken over, each decided by that
    bracket and evaluated only within 1e-8 mm of it.  Where the flank stops short of a height (no tip: a hit None) the
    halvings are evaluated from there on, as before.  Both rest on what the bisection already assumed: a land of at
    least ``t_min`` at a height, and a tip, hold at every lower height too.

    ``reach()``, when given, guesses the height where the tip leaves a flank (``flank_reach``).  Where h_hi has no
    tip, the heights ``TIP_REACH_PROBE_MM`` either side of that guess are evaluated first: they bracket the height
    the bisection would otherwise close in on evaluation by evaluation (the flank's end), or, below the flank's end
    with too thin a land, give the Illinois method a tipped upper end.  Whatever the guess, the bracket is made of
    heights evaluated.  Where the height found so has no tip or too thin a land (the tip's existence is not monotone
    next to a flank's cusp), the search is made again without the probes."""
    def f(res):
        return res[0] - t_min

    # Illinois (regula falsi with halving) on f(h) = land - t_min, while the heights tried have a tip: where the
    # flank does not reach (a hit None) the land jumps, and the bisection below finds that height as it always did
    a, b, fa, fb, kept = h_lo, h_hi, f(at_lo), f(at_hi), 0
    tipped = at_hi[1] is not None and at_hi[2] is not None
    probed = False
    if not tipped and reach is not None:
        try:
            r = float(reach())
        except (ArithmeticError, ValueError):  # no guess (a flank's end its solver cannot take): the bisection decides
            r = math.nan
        for hp in (r - TIP_REACH_PROBE_MM, r + TIP_REACH_PROBE_MM):
            if a < hp < b:
                probed = True
                res = thickness(hp)
                if f(res) >= 0.0:
                    a, fa = hp, f(res)
                else:
                    b, fb = hp, f(res)
                    tipped = res[1] is not None and res[2] is not None
    steps = 0
    # at most TIP_SECANT_STEPS_MAX secant steps (Illinois converges in 6 to 12 on a tooth's land): the bracket is
    # valid after any of them and the bisection below decides the height, so a crawl is cut short, never wrong
    while b - a > 1e-3 * TIP_HEIGHT_TOL_MM and tipped and steps < TIP_SECANT_STEPS_MAX:
        steps += 1
        # fa >= 0 > fb throughout, so the secant's root lies in [a, b): at an end (a root found exactly, fa = 0) the
        # clamp steps just off it and the next evaluation closes the bracket (a midpoint there would only halve it)
        m = b - fb * (b - a) / (fb - fa)
        m = min(max(m, a + 2.5e-4 * TIP_HEIGHT_TOL_MM), b - 2.5e-4 * TIP_HEIGHT_TOL_MM)  # a step off a root at an end
        res = thickness(m)
        fm = f(res)
        if fm >= 0.0:
            a, fa = m, fm
            if kept == -1:
                fb *= 0.5
            kept = -1
        else:
            b, fb = m, fm
            tipped = res[1] is not None and res[2] is not None  # no tip at m: bisect from here on
            if kept == 1:
                fa *= 0.5
            kept = 1
    # the bisection's own steps (the same floats), the land evaluated only where the bracket cannot tell
    lo, hi, best, best_h = h_lo, h_hi, at_lo, h_lo
    while hi - lo > TIP_HEIGHT_TOL_MM:
        mid = 0.5 * (lo + hi)
        if mid < a - 1e-8:
            lo = mid
        elif mid > b + 1e-8:
            hi = mid
        else:
            res = thickness(mid)
            if res[0] >= t_min:
                lo, best, best_h = mid, res, mid
            else:
                hi = mid
    if best_h != lo:
        best = thickness(lo)
    if probed and not (best[0] >= t_min and best[1] is not None and best[2] is not None):
        # the probes' bracket misled the halvings: next to a flank's cusp a tip can vanish below a height that has one
        # (the seed-002 pair without backlash: none 0.5 um below the flank's end, one again 1 um below), so the
        # bisection is made again from the start, without them
        return tallest_tip(thickness, h_lo, at_lo, h_hi, at_hi, t_min)
    return lo, best
