"""The undercut trim of a generated tooth side (docs/architecture.md, «Tooth generator»): where the
fillet envelope and the flank envelope of one cutter cross away from their joint, the loop between
is inside the cut region; the real boundary runs along the first up to the crossing and along the
second from it (Litvin & Fuentes-Aznar 2009, ch. 6: undercut of generated teeth)."""

from __future__ import annotations

import numpy as np
from scipy.optimize import fsolve

from ..policy import CUSP_XATOL_REL, FD_STEP_REL, ROUNDING_TOL, SOLVE_RESIDUAL_MM
from .envelope import EnvelopeCurve

__all__ = ["trim_crossing"]


def _segment_crossings(A, B):
    """All crossings of polyline A with polyline B: arrays (i, j, ta, tb)."""
    a0, a1 = A[:-1, None, :], A[1:, None, :]
    b0, b1 = B[None, :-1, :], B[None, 1:, :]
    da, db = a1 - a0, b1 - b0
    w = b0 - a0
    den = da[..., 0] * db[..., 1] - da[..., 1] * db[..., 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        ta = (w[..., 0] * db[..., 1] - w[..., 1] * db[..., 0]) / den
        tb = (w[..., 0] * da[..., 1] - w[..., 1] * da[..., 0]) / den
    ok = (np.abs(den) > 0) & (ta >= 0) & (ta <= 1) & (tb >= 0) & (tb <= 1)
    i, j = np.nonzero(ok)
    return i, j, ta[i, j], tb[i, j]


def _cusp(curve: EnvelopeCurve, n: int = 2000):
    """Parameter of a cusp (envelope velocity → 0 with reversal) of ``curve``, or None."""
    v = np.linspace(0.0, 1.0, n)
    u = curve.u0 + (curve.u1 - curve.u0) * v
    d = np.diff(curve(u), axis=0)
    rev = np.nonzero(np.einsum("ij,ij->i", d[:-1], d[1:]) < 0)[0]
    if len(rev) == 0:
        return None
    k = int(rev[0])
    lo, hi = u[k], u[k + 2]
    step = FD_STEP_REL * abs(curve.u1 - curve.u0)
    speed = lambda t: float(np.linalg.norm(curve.at(t + step) - curve.at(t - step)))
    from scipy.optimize import minimize_scalar
    res = minimize_scalar(speed, bounds=(min(lo, hi), max(lo, hi)), method="bounded",
                          options={"xatol": CUSP_XATOL_REL * max(1.0, abs(hi))})
    return float(res.x)


def trim_crossing(first: EnvelopeCurve, second: EnvelopeCurve, n: int = 800):
    """Where ``first`` (ending where ``second`` starts) crosses ``second`` away from the
    joint, return the exact crossing parameters (u_first, u_second); None if no crossing.

    If ``second`` has a cusp (the envelope of a straight tool flank beyond the interference
    point runs back along the mirrored involute branch), only its part after the cusp can
    bound the cut region, so the crossing is searched there.  The loop between the crossing
    and the joint lies inside the cut region (undercut): the real boundary is ``first`` up to
    u_first, then ``second`` from u_second.  Of several crossings the outermost loop is removed
    (earliest on ``first``, latest on ``second``).  Samples are clustered towards the joint
    (resp. the cusp) so that the small loops of a slight undercut are found.
    """
    v = np.linspace(0.0, 1.0, n)
    ua = first.u0 + (first.u1 - first.u0) * (1.0 - (1.0 - v) ** 3)
    uc = _cusp(second)
    b0 = second.u0 if uc is None else uc
    ub = b0 + (second.u1 - b0) * v ** 3
    A, B = first(ua), second(ub)
    i, j, ta, tb = _segment_crossings(A, B)
    if uc is None:
        keep = ~((i >= n - 3) & (j <= 2))  # the joint itself
        i, j, ta, tb = i[keep], j[keep], ta[keep], tb[keep]
    if len(i) == 0:
        return None
    k = np.lexsort((-j, i))[0]
    x0 = np.array([ua[i[k]] + ta[k] * (ua[i[k] + 1] - ua[i[k]]), ub[j[k]] + tb[k] * (ub[j[k] + 1] - ub[j[k]])])
    g = lambda y: first.at(y[0]) - second.at(y[1])
    sol = fsolve(g, x0, xtol=ROUNDING_TOL, full_output=True)[0]
    if np.linalg.norm(g(sol)) > SOLVE_RESIDUAL_MM:
        raise RuntimeError("undercut crossing did not converge")
    return float(sol[0]), float(sol[1])
