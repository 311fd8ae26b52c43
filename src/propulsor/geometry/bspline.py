"""Clamped cubic B-spline fitting of exact curves to a guaranteed tolerance.

numpy/scipy only.  Method: cubic interpolation at chord-length parameters (not-a-knot end
conditions; scipy's knot vector is clamped, so the first/last poles are the end points
exactly), with adaptive refinement: between every two interpolation points the exact curve
is checked at 1/4, 1/2, 3/4 of the interval by its true normal distance to the spline (foot
point by Newton projection), and the interval is split where the distance exceeds half the
tolerance.  The result deviates from the exact curve by ≤ ``policy.SPLINE_FIT_TOL_MM``.
"""

from __future__ import annotations

import functools

import numpy as np
from scipy.interpolate import BSpline, make_interp_spline

from ..errors import require
from ..planar import norms
from ..policy import SPLINE_FIT_TOL_MM
from .profile import Spline
from .spline_foot import foot_distances

__all__ = ["fit_curve", "fit_curves", "fit_points", "spline_deviation"]


def _chord_params(P: np.ndarray) -> np.ndarray:
    d = norms(np.diff(P, axis=0))
    return np.concatenate([[0.0], np.cumsum(d)])


def _interp(P: np.ndarray):
    t = _chord_params(P)
    if np.any(np.diff(t) <= 0):
        raise ValueError("coincident consecutive points")
    k = 3 if len(P) >= 4 else len(P) - 1
    if k < 2 or P.ndim != 2 or P.shape[1] != 2 or not (np.isfinite(t).all() and np.isfinite(P).all()):
        return make_interp_spline(t, P, k=k), t  # its special cases and its errors
    return _not_a_knot_spline(t, P, k), t


def _not_a_knot_spline(x: np.ndarray, y: np.ndarray, k: int):
    """``make_interp_spline(x, y, k)`` (not-a-knot ends) for finite, strictly increasing x, y of shape (n, 2) and
    k >= 2: the steps scipy 1.17's function takes for it, without its checks and case analysis (about 75 of its
    100 us a call, 1 400 calls a seed-002 design): scipy's knots (``_not_a_knot``), its collocation matrix in
    LAPACK's band storage (``_dierckx._coloc``) and LAPACK's ``gbsv`` on it, the same arguments in the same order,
    so the same spline to the last bit (tests/test_spline_fit_fast.py holds it to ``make_interp_spline``)."""
    from scipy.interpolate import _dierckx
    from scipy.interpolate._bsplines import _not_a_knot

    t = _not_a_knot(x, k)
    nt = t.size - k - 1
    ab = np.zeros((3 * k + 1, nt), dtype=np.float64, order="F")
    _dierckx._coloc(x, t, k, ab.T, 0)
    rhs = np.empty((nt, 2), dtype=np.float64)
    rhs[:] = y
    _, _, c, info = _gbsv()(k, k, ab, rhs, overwrite_ab=True, overwrite_b=True)
    if info != 0:
        return make_interp_spline(x, y, k=k)  # its error
    return BSpline.construct_fast(t, np.ascontiguousarray(c.reshape(nt, 2)), k)


@functools.cache
def _gbsv():
    """LAPACK's banded solver for float64 (scipy's, as ``make_interp_spline`` gets it)."""
    from scipy.linalg import get_lapack_funcs

    return get_lapack_funcs(("gbsv",), (np.zeros((1, 1)), np.zeros((1, 1))))[0]


def _project(bs, Q: np.ndarray, t0: np.ndarray, lo: float, hi: float, iters: int = 6) -> np.ndarray:
    """Distance of points Q to the spline curve, Newton foot-point search from t0 (compiled:
    :func:`.spline_foot.foot_distances`, one pass of the basis functions for the point and both derivatives)."""
    return foot_distances(bs.t, bs.c, bs.k, Q, np.asarray(t0, float), lo, hi, iters)


def _to_spline(bs) -> Spline:
    """profile.Spline of a scipy BSpline (degree 3; fewer than 4 points give a lower degree)."""
    return Spline(bs.t, bs.c, int(bs.k))


def fit_curve(func, u0: float, u1: float, tol: float = SPLINE_FIT_TOL_MM, n0: int = 12,
              max_points: int = 4000) -> Spline:
    """Clamped cubic B-spline through the exact curve ``func(u) -> (n,2)`` on [u0, u1],
    within ``tol`` (mm) of it everywhere checked (1/4, 1/2, 3/4 of every interval).  ``func`` is evaluated once
    at each parameter over the refinement's rounds (a point of the curve depends on its parameter alone)."""
    fit = _fit_steps(u0, u1, tol, n0, max_points)
    try:
        uu = next(fit)
        while True:
            uu = fit.send(np.asarray(func(uu), float))
    except StopIteration as done:
        return done.value


def fit_curves(curves, evaluate, tol: float = SPLINE_FIT_TOL_MM, n0: int = 12, max_points: int = 4000) -> list:
    """:func:`fit_curve` of every ``(func, u0, u1)`` of ``curves``, in lock step: each round of refinement asks
    ``evaluate(requests)`` for the new points of all the fits still refining at once (``requests``: a list of
    ``(func, parameters)``; it returns their points, ``func(parameters)`` each, in order), so that one call can
    compute the points of many curves of one kind together.  The splines are those of :func:`fit_curve`, each fit
    asking for the same parameters in the same order, when ``evaluate`` gives the points ``func`` gives.  An error
    of a fit is raised once every fit has ended, the first fit's of those that failed (as one after the other)."""
    require(tol > 0, "tol", tol, "must be > 0")
    out: list = [None] * len(curves)
    errors: dict[int, BaseException] = {}
    live: dict[int, tuple] = {}  # fit index -> (generator, parameters it asks for)
    for i, (_, u0, u1) in enumerate(curves):
        fit = _fit_steps(u0, u1, tol, n0, max_points)
        try:
            live[i] = (fit, next(fit))
        except StopIteration as done:
            out[i] = done.value
        except Exception as exc:  # noqa: BLE001 - raised below in the fits' order
            errors[i] = exc
    while live:
        idx = list(live)
        try:
            pts = evaluate([(curves[i][0], live[i][1]) for i in idx])
        except Exception:  # noqa: BLE001 - each curve on its own: the error goes to the fit whose curve raised it
            pts = []
            for i in idx:
                try:
                    pts.append(np.asarray(curves[i][0](live[i][1]), float))
                except Exception as exc:  # noqa: BLE001
                    errors[i] = exc
                    pts.append(None)
        for i, P in zip(idx, pts):
            fit = live.pop(i)[0]
            if P is None:
                continue
            try:
                live[i] = (fit, fit.send(np.asarray(P, float)))
            except StopIteration as done:
                out[i] = done.value
            except Exception as exc:  # noqa: BLE001
                errors[i] = exc
    if errors:
        raise errors[min(errors)]
    return out


def _fit_steps(u0: float, u1: float, tol: float, n0: int, max_points: int):
    """The refinement of :func:`fit_curve` as a generator: it yields the parameters whose curve points it needs (each
    parameter once over the rounds, in the order first asked) and is sent those points; it returns the spline."""
    require(tol > 0, "tol", tol, "must be > 0")
    v = np.linspace(0.0, 1.0, n0)  # normalised parameter (u1 < u0 allowed)
    known: dict[float, np.ndarray] = {}  # the curve's points by parameter: each evaluated once over the rounds

    def missing(uu: np.ndarray) -> np.ndarray:
        return np.array([x for x in dict.fromkeys(uu.tolist()) if x not in known], float)

    def at(uu: np.ndarray) -> np.ndarray:
        return np.array([known[x] for x in uu.tolist()]).reshape(len(uu), 2)

    while True:
        u = u0 + (u1 - u0) * v
        new = missing(u)
        if len(new):
            for x, q in zip(new.tolist(), (yield new)):
                known[x] = q
        P = at(u)
        bs, t = _interp(P)
        fr = np.array([0.25, 0.5, 0.75])
        uq = (u[:-1, None] + fr[None, :] * np.diff(u)[:, None]).ravel()
        tq = (t[:-1, None] + fr[None, :] * np.diff(t)[:, None]).ravel()
        new = missing(uq)
        if len(new):
            for x, q in zip(new.tolist(), (yield new)):
                known[x] = q
        err = _project(bs, at(uq), tq, t[0], t[-1]).reshape(-1, 3).max(axis=1)
        bad = err > 0.5 * tol
        if not np.any(bad):
            return _to_spline(bs)
        if len(u) + bad.sum() > max_points:
            raise RuntimeError(f"spline fit did not reach {tol} mm with {max_points} points")
        v = np.sort(np.concatenate([v, 0.5 * (v[:-1] + v[1:])[bad]]))


def fit_points(points, tol: float = SPLINE_FIT_TOL_MM, n0: int = 12) -> Spline:
    """Clamped cubic B-spline through a subset of an ordered dense point array such that every
    point of the array lies within ``tol`` of the spline (normal distance).  The exact curve
    between the points is not known here: give points dense enough, or use :func:`fit_curve`."""
    P = np.asarray(points, float)
    require(P.ndim == 2 and P.shape[1] == 2 and len(P) >= 2, "points", P.shape, "must be (n >= 2, 2)")
    n = len(P)
    idx = np.unique(np.linspace(0, n - 1, min(n, n0)).round().astype(int))
    while True:
        bs, t = _interp(P[idx])
        # parameter guesses for every point: chord length within its interval
        tt = np.empty(n)
        for a, b, ta, tb in zip(idx[:-1], idx[1:], t[:-1], t[1:]):
            seg = _chord_params(P[a:b + 1])
            tt[a:b + 1] = ta + (tb - ta) * seg / seg[-1]
        err = _project(bs, P, tt, t[0], t[-1])
        if np.all(err <= tol):
            return _to_spline(bs)
        bad_iv = np.unique(np.searchsorted(idx, np.nonzero(err > tol)[0]) - 1)
        bad_iv = bad_iv[(bad_iv >= 0) & (bad_iv < len(idx) - 1)]
        mids = (idx[bad_iv] + idx[bad_iv + 1]) // 2
        new = np.unique(np.concatenate([idx, mids]))
        if len(new) == len(idx):
            return _to_spline(make_interp_spline(_chord_params(P), P, k=3))
        idx = new


def spline_deviation(spline: Spline, func, u0: float, u1: float, n: int = 2000) -> float:
    """Largest normal distance of n exact points func(u) to the spline (for tests/reports)."""
    from scipy.interpolate import BSpline

    bs = BSpline(spline.knots, spline.poles, spline.degree)
    Q = func(np.linspace(u0, u1, n))
    tl = np.linspace(spline.knots[0], spline.knots[-1], 4 * n)
    S = bs(tl)
    # nearest sampled spline point as the start of the projection
    j = np.array([np.argmin(np.linalg.norm(S - q, axis=1)) for q in Q])
    return float(_project(bs, Q, tl[j], spline.knots[0], spline.knots[-1]).max())
