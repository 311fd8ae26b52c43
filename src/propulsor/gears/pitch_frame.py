"""The pair's shared arc-length frame and the pitch curves in each gear's body frame (seeds 000 and
002): the geometry every tooth of :mod:`.noncircular_teeth` is placed on.  Pure math (numpy).

Both pitch curves are parametrised by the driven angle phi and share ONE arc-length frame
s(phi) = integral sqrt(r_H^2 + r_H'^2) dphi (``ArcFrame``; rolling without slip: the driver's arc
over the same phi is equal).  ``BodyPitchCurve``: a pitch curve in its gear's body frame (the
driven wheel's point of polar angle phi; the driver's at body polar angle pi - theta).
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from ..errors import require
from ..laws.law import SMALL_ARRAY
from ..planar import norms
from ..policy import FD_STEP_PHI_RAD, FOOT_GAUSS_NEWTON_STEPS
from .noncircular import PitchCurves, leg_breakpoints

__all__ = ["ArcFrame", "BodyPitchCurve"]

#: Gauss-Legendre nodes and weights of the arc-length integrals
_GX, _GW = np.polynomial.legendre.leggauss(10)


class _PPoly1:
    """One float through a scipy ``PPoly`` of one value per x (a CubicHermiteSpline, its derivative) in plain Python:
    the interval and the sum that scipy's compiled ``evaluate`` takes (the same operations, so the same float: checked
    bit for bit in the tests), without its array call (about 6 us; tens of thousands of one-point calls a pair).
    Extrapolates by the end pieces, as the spline does."""

    __slots__ = ("x", "rows", "last")

    def __init__(self, pp):
        c = np.asarray(pp.c, float)
        if c.ndim != 2:
            raise ValueError("a PPoly of one value per x is needed")
        self.x = [float(v) for v in pp.x]
        self.rows = [list(map(float, row)) for row in c[::-1]]  # the constant term's first
        self.last = len(self.x) - 2

    def __call__(self, xv: float) -> float:
        x = self.x
        if xv != xv:
            return math.nan
        if xv >= x[-1]:
            i = self.last
        elif xv < x[0]:
            i = 0
        else:
            i = bisect.bisect_right(x, xv) - 1
        s = xv - x[i]
        # scipy's evaluate_poly1: res = res + c[k - 1 - kp] * z (* 1.0), then z *= s
        res, z = 0.0, 1.0
        for row in self.rows:
            res = res + row[i] * z
            z = z * s
        return res


class ArcFrame:
    """Shared arc length s(phi) of the pair's pitch curves, s(0) = 0 (true arc length
    ds = sqrt(r_H^2 + r_H'^2) dphi, seed 000 eq. 12 for r_H; docs/architecture.md, "closure").  Periodic per leg:
    s(phi + P) = s(phi) + leg (P: the law's period, pi/2 for the walking law).  Tabulated on one period (nodes at the law's breakpoints, the
    ends of the C2 blend windows) by 10-point Gauss-Legendre; s(phi) and its inverse phi(s)
    are evaluated by cubic Hermite interpolation with the exact slopes ds/dphi, dphi/ds
    (interpolation error ~1e-11 rad with the default node density, see the tests).  phi(s) is
    the inverse of this s(phi) to rounding: the inverse interpolant's value is polished by one
    Newton step on s(phi) (the two interpolants alone disagree by up to ~1e-9 rad where the
    ratio varies steeply, e.g. a = 0, b = 106, c = 127 mm, n = 1)."""

    def __init__(self, pc: PitchCurves, per_piece: int = 400):
        from scipy.interpolate import CubicHermiteSpline

        self.pc = pc
        #: the law's period in phi (one leg of the walking law) and -period_start (pi/4 there)
        self.period, self._p0 = pc.law.period, -pc.law.period_start
        bp = leg_breakpoints(pc.law)
        nodes = np.unique(np.concatenate([np.linspace(a, b, per_piece + 1) for a, b in zip(bp[:-1], bp[1:])]))
        self.nodes = nodes
        seg = self._gauss(nodes[:-1], nodes[1:])
        S = np.concatenate([[0.0], np.cumsum(seg)])
        j0 = int(np.searchsorted(nodes, 0.0, side="right") - 1)
        S0 = S[j0] + float(self._gauss(np.array([nodes[j0]]), np.array([0.0]))[0])
        self.S = S - S0
        self.leg = float(S[-1])
        self.perimeter = float(pc.law.periods) * self.leg
        g = pc.ds_dphi(nodes)
        self._s_of = CubicHermiteSpline(nodes, self.S, g)
        self._phi_of = CubicHermiteSpline(self.S, nodes, 1.0 / g)
        self._ds_of = self._s_of.derivative()
        self._phi1_of, self._s1_of, self._ds1_of = _PPoly1(self._phi_of), _PPoly1(self._s_of), _PPoly1(self._ds_of)

    def _gauss(self, a, b):
        a = np.asarray(a, float)
        b = np.asarray(b, float)
        x = 0.5 * (b - a)[:, None] * _GX[None, :] + 0.5 * (a + b)[:, None]
        f = self.pc.ds_dphi(x.ravel()).reshape(x.shape)
        return 0.5 * (b - a) * (f @ _GW)

    def s_exact(self, phi):
        """s(phi) by quadrature from the nearest node below (reference for the interpolant)."""
        phi = np.atleast_1d(np.asarray(phi, float))
        k = np.floor((phi + self._p0) / self.period)
        w = phi - k * self.period
        j = np.clip(np.searchsorted(self.nodes, w, side="right") - 1, 0, len(self.nodes) - 2)
        return self.S[j] + self._gauss(self.nodes[j], w) + k * self.leg

    def s(self, phi):
        phi = np.atleast_1d(np.asarray(phi, float))
        k = np.floor((phi + self._p0) / self.period)
        return self._s_of(phi - k * self.period) + k * self.leg

    def _inverse(self, w):
        """phi in the tabulated leg of arc length w: the inverse interpolant, then one Newton step on
        the s interpolant (its slope is the exact ds/dphi at the nodes, cubic between)."""
        ph = self._phi_of(w)
        return ph - (self._s_of(ph) - w) / self._ds_of(ph)

    def phi(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        if s.ndim == 1 and len(s) <= SMALL_ARRAY:
            # a few arc lengths (the envelope's and the tip searches' small arrays, a thousand calls a design): each by
            # ``phi1``, the same operations as the splines' compiled evaluation, without its cost per call
            got = [self.phi1(x) for x in s.tolist()]
            if None not in got:
                return np.array(got, dtype=float)
        k = np.floor((s - self.S[0]) / self.leg)
        return self._inverse(s - k * self.leg) + k * self.period

    def phi1(self, s: float):
        """``phi`` of one float s (the same operations), or None if s is not finite."""
        if not math.isfinite(s):
            return None
        k = float(math.floor((s - self.S[0]) / self.leg))
        w = s - k * self.leg
        ph = self._phi1_of(w)  # _inverse of one float
        return ph - (self._s1_of(ph) - w) / self._ds1_of(ph) + k * self.period


def _one(phi):
    """phi as one finite float when it is an array of one element (the solvers' one-point calls),
    else None (the array path)."""
    if type(phi) is np.ndarray and phi.shape == (1,):
        x = float(phi[0])
        if math.isfinite(x):
            return x
    return None


class BodyPitchCurve:
    """One gear's pitch curve in its body frame, as a function of the driven angle phi.

    role 'driven': P = r_H(phi) (cos phi, sin phi) (seed 000 eq. 12);
    role 'driver': P = r(phi) (cos beta, sin beta), beta = pi - theta(phi), r = L - r_H
    (seed 000 eq. 13).  ``sgn``: +1 if the generation arc (clockwise on the body, gear on the
    right of travel) runs with phi, -1 if against it.
    """

    def __init__(self, pc: PitchCurves, role: str):
        require(role in ("driver", "driven"), "role", role, "must be 'driver' or 'driven'")
        self.pc, self.role = pc, role
        self.sgn = -1.0 if role == "driven" else 1.0

    def polar(self, phi):
        """(radius, body polar angle) of the pitch point."""
        phi = np.asarray(phi, float)
        if self.role == "driven":
            return self.pc.r_H(phi), phi
        return self.pc.L - self.pc.r_H(phi), math.pi - self.pc.law.theta(phi)

    def point(self, phi):
        x = _one(phi)
        if x is not None:
            px, py, _, _ = self._at1(x)
            return np.array([[px, py]])
        r, a = self.polar(phi)
        return np.column_stack([r * np.cos(a), r * np.sin(a)])

    def dpoint(self, phi):
        """dP/dphi."""
        x = _one(phi)
        if x is not None:
            _, _, dx, dy = self._at1(x)
            return np.array([[dx, dy]])
        phi = np.atleast_1d(np.asarray(phi, float))
        r, a = self.polar(phi)
        c, s = np.cos(a), np.sin(a)
        if self.role == "driven":
            dr, da = self.pc.dr_H(phi), 1.0
        else:
            dr, da = -self.pc.dr_H(phi), -self.pc.law.U(phi)
        return np.column_stack([dr * c - r * da * s, dr * s + r * da * c])

    def normal(self, phi):
        """Unit outward normal (away from the gear body)."""
        x = _one(phi)
        if x is not None:
            _, _, dx, dy = self._at1(x)
            nx, ny = self._normal1(dx, dy)
            return np.array([[nx, ny]])
        d = self.sgn * self.dpoint(phi)
        d = d / norms(d)[:, None]
        return np.column_stack([-d[:, 1], d[:, 0]])

    def offset(self, phi, h):
        """Equidistant at height h (outwards > 0) - the tip (h > 0) and root (h < 0) curves."""
        x = _one(phi)
        if x is not None and isinstance(h, (float, int)):
            px, py, dx, dy = self._at1(x)
            nx, ny = self._normal1(dx, dy)
            return np.array([[px + h * nx, py + h * ny]])
        return self.point(phi) + h * self.normal(phi)

    def heights(self, P, h: float, grid, E=None):
        """Signed heights of the points P (k x 2, k > 1) above the equidistant at h, each along the outward normal at
        its foot point: the nearest of the sampled angles ``grid`` (their points E = offset(grid, h), when not given),
        then ``FOOT_GAUSS_NEWTON_STEPS`` Gauss-Newton steps on the foot's condition (P - F(phi)) . F'(phi) = 0 within
        the samples either side, F' by central differences.  The height is stationary at the foot, so the phi left
        after the steps (about 1e-10 rad) moves it far below rounding.  (``noncircular_teeth.make_side``'s fillet trim
        on the root, ``tip_search.flank_reach`` on the pitch curve itself.)"""
        at = self.point if h == 0.0 else (lambda ph: self.offset(ph, h))
        if E is None:
            E = at(grid)
        j = np.clip(np.argmin(norms(E[None, :, :] - P[:, None, :]), axis=1), 1, len(grid) - 2)
        lo, hi, ph = grid[j - 1], grid[j + 1], grid[j]
        for _ in range(FOOT_GAUSS_NEWTON_STEPS):
            F = at(ph)
            dF = (at(ph + FD_STEP_PHI_RAD) - at(ph - FD_STEP_PHI_RAD)) / (2.0 * FD_STEP_PHI_RAD)
            ph = np.clip(ph - np.einsum("ij,ij->i", F - P, dF) / np.einsum("ij,ij->i", dF, dF), lo, hi)
        return np.einsum("ij,ij->i", P - at(ph), self.normal(ph))

    def equidistant(self, h: float) -> "Equidistant":
        """The equidistant at height h as a curve of phi (``offset``), for the spline fits."""
        return Equidistant(self, float(h))

    # ---- one point: the operations of the array functions above on one float, in ``math`` ----
    def _at1(self, phi: float):
        """(x, y, dx/dphi, dy/dphi) of the pitch point of driven angle phi (one float)."""
        pc = self.pc
        U, r_H, dr_H = pc.pitch1(phi)
        if self.role == "driven":
            r, a, dr, da = r_H, phi, dr_H, 1.0
        else:
            r, a, dr, da = pc.L - r_H, math.pi - pc.law.theta1(phi), -dr_H, -U
        c, s = math.cos(a), math.sin(a)
        return r * c, r * s, dr * c - r * da * s, dr * s + r * da * c

    def _normal1(self, dx: float, dy: float):
        """Unit outward normal from dP/dphi (``normal``: sgn dP / |dP| turned by +90 degrees)."""
        sg = self.sgn
        dx, dy = sg * dx, sg * dy
        n = math.sqrt(dx * dx + dy * dy)
        return -(dy / n), dx / n

    def rho(self, phi):
        """Signed radius of curvature (> 0 convex) at the pitch point of driven angle phi."""
        return self.pc.rho_H(phi) if self.role == "driven" else self.pc.rho(phi)


class Equidistant:
    """The equidistant at height ``h`` of a body pitch curve as a curve of the driven angle phi:
    ``curve.offset(phi, h)`` (the tip land, h > 0, and the root, h < 0)."""

    __slots__ = ("curve", "h")

    def __init__(self, curve: BodyPitchCurve, h: float):
        self.curve, self.h = curve, h

    def __call__(self, phi):
        return self.curve.offset(phi, self.h)
