"""Drive laws of a non-circular pair given by the user (``laws.law.Law``): elliptical, Fourier series.

Angles in rad: phi the driven angle, theta the driver angle, theta(0) = 0, U = d theta / d phi.
Both laws have k lobes on the driven wheel and k driver turns per driven turn: period 2 pi / k in phi.

* ``EllipticalLaw(e, k)``: the driver is an ellipse of eccentricity e turning about a focus,
  r1 = p / (1 + e cos theta); the driven wheel, r2 = L - r1, has k lobes (k = 1: two equal
  ellipses, 1:1; Litvin & Fuentes-Aznar, Noncircular Gears, 2009, ch. 3-4).  Closure
  integral_0^2pi r1 / (L - r1) dtheta = 2 pi / k with q = p / L:
  2 pi q / sqrt((1 - q)^2 - e^2) = 2 pi / k, i.e. (k^2 - 1) q^2 + 2 q - (1 - e^2) = 0.
  Then phi(theta) = (2/k) atan(c tan(theta/2)), c = sqrt((1 - q - e) / (1 - q + e)), and
  U = (1 - q + e cos theta) / q, from (1 - e)/(1 + e) to (1 + e)/(1 - e) at k = 1.
* ``FourierLaw(k, cos, sin)``: phi(theta) = theta / k + sum_j (c_j cos j theta + s_j sin j theta)
  (the form ncgears takes), shifted by the constant - sum c_j so that phi(0) = 0 (a rotation of the
  driven wheel); d phi / d theta must stay > 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, require_finite
from .law import one_point_values
from .fourier_kernels import derivs_many, phi_many, slopes_one, theta_many, theta_one

__all__ = ["EllipticalLaw", "FourierLaw"]

#: largest eccentricity of an elliptical law (the driven wheel's radius L - r1 -> 0 as e -> 1)
E_MAX = 0.9
#: largest lobe count of a driven wheel
LOBES_MAX = 12
#: samples of d phi / d theta over one driver turn when checking it stays > 0
_FOURIER_CHECK_SAMPLES = 20000
#: points of the table of theta over one period that starts the Fourier law's Newton iteration
_GUESS_POINTS = 4096


def _lobes(value) -> int:
    k = require_finite("driver_turns", value)
    if k != round(k) or not 1 <= k <= LOBES_MAX:
        raise InputError("driver_turns", value, f"lobes of the driven wheel must be a whole number 1 .. {LOBES_MAX}")
    return int(round(k))


class _PeriodicLaw:
    """What the k-lobe laws share: period 2 pi / k, k driver turns per driven turn, one smooth piece."""

    scalar_path = False
    corner_phis = ()

    @property
    def n(self) -> int:
        return self.k

    @property
    def periods(self) -> int:
        return self.k

    @property
    def period(self) -> float:
        return 2 * math.pi / self.k

    @property
    def period_start(self) -> float:
        return -math.pi / self.k

    @property
    def breakpoints(self) -> tuple:
        return (-math.pi / self.k, math.pi / self.k)

    @property
    def U_min(self) -> float:
        return float(np.min(self.U(np.linspace(-math.pi / self.k, math.pi / self.k, 4001))))

    @property
    def U_max(self) -> float:
        return float(np.max(self.U(np.linspace(-math.pi / self.k, math.pi / self.k, 4001))))


@dataclass(frozen=True)
class EllipticalLaw(_PeriodicLaw):
    """Elliptical driver about a focus, e its eccentricity, k lobes of the driven wheel."""

    e: float
    k: int = 1

    kind = "elliptical"
    #: the array functions give each angle the value it gets alone (law.py: ``elementwise``)
    elementwise = True

    def __post_init__(self):
        e = require_finite("eccentricity", self.e)
        if not 0.0 <= e < 1.0:
            raise InputError("eccentricity", self.e, "an ellipse has 0 <= e < 1")
        if e > E_MAX:
            raise InputError("eccentricity", self.e, f"must be <= {E_MAX}: the driven wheel's radius L - r1 "
                             "nearly vanishes at the driver's far vertex")
        k = _lobes(self.k)
        object.__setattr__(self, "e", e)
        object.__setattr__(self, "k", k)
        # closure: (k^2 - 1) q^2 + 2 q - (1 - e^2) = 0, q = p / L
        if k == 1:
            q = (1 - e * e) / 2
        else:
            q = (-1 + math.sqrt(1 + (k * k - 1) * (1 - e * e))) / (k * k - 1)
        # the driven wheel's radius at the driver's far vertex, L (1 - q - e), stays > 0 for every k: q = (1 - e^2) /
        # (1 + sqrt(1 + (k^2 - 1)(1 - e^2))) <= (1 - e^2) / 2, so 1 - q - e >= (1 - e)^2 / 2 > 0
        object.__setattr__(self, "q", q)
        object.__setattr__(self, "_alpha", 1 - q)
        object.__setattr__(self, "_c", math.sqrt((1 - q - e) / (1 - q + e)))

    def driver_radius_rel(self, theta):
        """Driver radius over L at driver angle theta: q / (1 + e cos theta)."""
        return self.q / (1 + self.e * np.cos(np.asarray(theta, dtype=float)))

    def theta(self, phi):
        x = self.k * np.asarray(phi, dtype=float) / 2
        j = np.floor(x / math.pi + 0.5)
        w = x - j * math.pi
        return 2 * (np.arctan(np.tan(w) / self._c) + j * math.pi)

    def phi_of_theta(self, theta, tol: float = 0.0):
        th = np.asarray(theta, dtype=float) / 2
        j = np.floor(th / math.pi + 0.5)
        w = th - j * math.pi
        return (2.0 / self.k) * (np.arctan(self._c * np.tan(w)) + j * math.pi)

    def U(self, phi):
        return (self._alpha + self.e * np.cos(self.theta(phi))) / self.q

    def dU_dphi(self, phi):
        th = self.theta(phi)
        return -self.e * np.sin(th) / self.q * (self._alpha + self.e * np.cos(th)) / self.q

    def d2U_dphi2(self, phi):
        th = self.theta(phi)
        U = (self._alpha + self.e * np.cos(th)) / self.q
        dU = -self.e * np.sin(th) / self.q * U
        return -self.e / self.q * (np.cos(th) * U * U + np.sin(th) * dU)

    def theta1(self, phi: float) -> float:
        """``theta`` at one float phi, in ``math``."""
        x = self.k * float(phi) / 2
        j = math.floor(x / math.pi + 0.5)
        return 2 * (math.atan(math.tan(x - j * math.pi) / self._c) + j * math.pi)

    def U_derivs1(self, phi: float) -> tuple:
        """(U, dU/dphi, d2U/dphi2) at one float phi, from one theta(phi)."""
        th = self.theta1(phi)
        c, s = math.cos(th), math.sin(th)
        U = (self._alpha + self.e * c) / self.q
        dU = -self.e * s / self.q * U
        return U, dU, -self.e / self.q * (c * U * U + s * dU)


@dataclass(frozen=True)
class FourierLaw(_PeriodicLaw):
    """phi(theta) = theta / k + sum_j (c_j cos j theta + s_j sin j theta) - sum_j c_j (rad)."""

    k: int
    cos: tuple = ()
    sin: tuple = ()

    kind = "fourier"
    #: the array functions give each angle the value it gets alone (law.py: ``elementwise``): each is the one-point
    #: path at every angle (``fourier_kernels.theta_many``, ``derivs_many``, ``phi_many``)
    elementwise = True

    def __post_init__(self):
        k = _lobes(self.k)
        c = tuple(require_finite(f"fourier_cos[{i}]", v) for i, v in enumerate(self.cos))
        s = tuple(require_finite(f"fourier_sin[{i}]", v) for i, v in enumerate(self.sin))
        object.__setattr__(self, "k", k)
        object.__setattr__(self, "cos", c)
        object.__setattr__(self, "sin", s)
        J = max(len(c), len(s))
        object.__setattr__(self, "_j", np.arange(1, J + 1, dtype=float))
        object.__setattr__(self, "_c", np.array(c + (0.0,) * (J - len(c))))
        object.__setattr__(self, "_s", np.array(s + (0.0,) * (J - len(s))))
        object.__setattr__(self, "_c0", float(np.sum(self._c)))
        object.__setattr__(self, "_terms", tuple((float(j), float(cj), float(sj))
                                                 for j, cj, sj in zip(self._j, self._c, self._s) if cj or sj))
        object.__setattr__(self, "_last", (math.nan, math.nan))
        object.__setattr__(self, "_last_arr", (None, None, None))  # (phi's bytes and shape, theta, U's derivatives)
        th = np.linspace(0.0, 2 * math.pi, _FOURIER_CHECK_SAMPLES, endpoint=False)
        g = self._g(th, 1)
        i = int(np.argmin(g))
        if not g[i] > 0:
            # the series that pulls d phi / d theta down there (the sum of its terms' slopes, the more negative)
            t = th[i]
            by_cos = float(np.sum(-self._j * self._c * np.sin(self._j * t)))
            by_sin = float(np.sum(self._j * self._s * np.cos(self._j * t)))
            key = "fourier_cos" if by_cos <= by_sin else "fourier_sin"
            raise InputError(key, list(c if key == "fourier_cos" else s),
                             f"d phi / d theta = {g[i]:.4g} <= 0 at theta = {math.degrees(th[i]):.2f} deg: the "
                             "driven wheel would stop or turn back (the ratio must stay > 0)")
        ph = np.linspace(0.0, self.period, _GUESS_POINTS + 1)
        T = self._newton(ph, self.k * ph)
        T[0], T[-1] = 0.0, 2 * math.pi
        D = (self.period / _GUESS_POINTS) / self._g(T, 1)  # d theta per grid step: h U
        object.__setattr__(self, "_T", T)
        object.__setattr__(self, "_D", D)
        object.__setattr__(self, "_T_list", T.tolist())
        object.__setattr__(self, "_D_list", D.tolist())
        # the compiled one-point path's data (laws/fourier_kernels.py): the non-zero terms, the start's table
        object.__setattr__(self, "_series", np.array(self._terms, dtype=float).reshape(-1, 3))
        object.__setattr__(self, "_table", np.ascontiguousarray(np.vstack([T, D])))

    def _g(self, theta, order: int):
        """phi(theta) (order 0) or its 1st / 2nd / 3rd derivative in theta, summed by numpy over the whole array
        (the start's table and the check of d phi / d theta > 0 at construction; not elementwise: a matrix product
        sums a row in an order that depends on the array's length)."""
        th = np.asarray(theta, dtype=float)
        if not len(self._j):
            return {0: th / self.k, 1: np.full_like(th, 1.0 / self.k)}.get(order, np.zeros_like(th))
        a = np.multiply.outer(th, self._j)
        j = self._j
        cs, sn = np.cos(a), np.sin(a)
        if order == 0:
            return th / self.k + cs @ self._c + sn @ self._s - self._c0
        if order == 1:
            return 1.0 / self.k + sn @ (-j * self._c) + cs @ (j * self._s)
        if order == 2:
            return cs @ (-j * j * self._c) + sn @ (-j * j * self._s)
        return sn @ (j ** 3 * self._c) + cs @ (-j ** 3 * self._s)

    def phi_of_theta(self, theta, tol: float = 0.0):
        th = np.asarray(theta, dtype=float)
        return phi_many(np.ascontiguousarray(th.ravel()), float(self.k), self._series, self._c0).reshape(th.shape)

    def _many(self, phi, what: int):
        """Function ``what`` (-1 theta, 0 U, 1 dU/dphi, 2 d2U/dphi2) at the angles ``phi``: the one-point path at each
        (:func:`.fourier_kernels.theta_many`, :func:`.fourier_kernels.derivs_many`; a few angles by the one-point
        functions themselves).  The last array's theta and derivatives are kept: a pitch curve asks for U, U' and U''
        of one array in turn."""
        small = one_point_values(self, phi, what)
        if small is not None:
            return small
        phi = np.asarray(phi, dtype=float)
        key = (phi.tobytes(), phi.shape)
        kept, th, der = self._last_arr
        if kept != key:
            th = theta_many(np.ascontiguousarray(phi.ravel()), float(self.k), self._series, self._c0, self.period,
                            self._table, _GUESS_POINTS)
            der = None
        if what < 0:
            out = th
        else:
            if der is None:
                der = derivs_many(th, float(self.k), self._series)
            out = der[what]
        object.__setattr__(self, "_last_arr", (key, th, der))
        return out.reshape(phi.shape).copy()

    def theta(self, phi):
        """Inverse of phi(theta): Newton from a Hermite start on the monotone phi(theta), steps bounded, at each
        angle (``theta1``)."""
        return self._many(phi, -1)

    def _newton(self, phi, th):
        for _ in range(100):
            step = (self._g(th, 0) - phi) / self._g(th, 1)
            step = np.clip(step, -0.5, 0.5)
            th = th - step
            if np.all(np.abs(step) < 1e-12):
                break
        return th - (self._g(th, 0) - phi) / self._g(th, 1)  # one more step: at rounding level

    def _guess(self, phi):
        """theta(phi) by cubic Hermite interpolation in the table of one period (theta and its slope U; a
        start for Newton within about 1e-12 rad): theta(phi + P) = theta(phi) + 2 pi."""
        P, T, D = self.period, self._T, self._D
        m = np.floor(phi / P)
        x = (phi - m * P) * (_GUESS_POINTS / P)
        i = np.clip(np.floor(x), 0, _GUESS_POINTS - 1)
        t = x - i
        i = np.nan_to_num(i).astype(int)
        t2, t3 = t * t, t * t * t
        return (2 * math.pi * m + (2 * t3 - 3 * t2 + 1) * T[i] + (t3 - 2 * t2 + t) * D[i]
                + (3 * t2 - 2 * t3) * T[i + 1] + (t3 - t2) * D[i + 1])

    def U(self, phi):
        return self._many(phi, 0)

    def dU_dphi(self, phi):
        return self._many(phi, 1)

    def d2U_dphi2(self, phi):
        return self._many(phi, 2)

    # ---- one point (a float), in ``math``: the tooth generator's calls, one at a time ----------------
    def _g01(self, th: float) -> tuple:
        """(phi(theta), d phi / d theta) at one float theta."""
        g0, g1 = th / self.k, 1.0 / self.k
        for j, c, s in self._terms:
            ca, sa = math.cos(j * th), math.sin(j * th)
            g0 += c * ca + s * sa
            g1 += j * (s * ca - c * sa)
        return g0 - self._c0, g1

    def _guess1(self, phi: float) -> float:
        """``_guess`` at one float phi, in ``math``."""
        P = self.period
        m = math.floor(phi / P)
        x = (phi - m * P) * (_GUESS_POINTS / P)
        i = min(max(int(x), 0), _GUESS_POINTS - 1)
        t = x - i
        T, D = self._T_list, self._D_list
        t2, t3 = t * t, t * t * t
        return (2 * math.pi * m + (2 * t3 - 3 * t2 + 1) * T[i] + (t3 - 2 * t2 + t) * D[i]
                + (3 * t2 - 2 * t3) * T[i + 1] + (t3 - t2) * D[i + 1])

    def theta1(self, phi: float) -> float:
        """``theta`` at one float phi: the same Newton iteration in ``math`` (equal to rounding), the last
        point remembered (the generator asks for U and theta of one phi in turn); compiled
        (:func:`.fourier_kernels.theta_one`, the same operations: :meth:`_theta1_py` to the last bit) where phi is
        finite."""
        phi = float(phi)
        last = self._last
        if last[0] == phi:
            return last[1]
        if not math.isfinite(phi):
            return self._theta1_py(phi)
        th = theta_one(phi, float(self.k), self._series, self._c0, self.period, self._table, _GUESS_POINTS)
        object.__setattr__(self, "_last", (phi, th))
        return th

    def _theta1_py(self, phi: float) -> float:
        """:meth:`theta1` in Python (the reference of the compiled path, and its path for a phi not finite)."""
        th = self._guess1(phi)
        for _ in range(100):
            g0, g1 = self._g01(th)
            step = min(max((g0 - phi) / g1, -0.5), 0.5)
            th -= step
            if abs(step) < 1e-12:
                break
        g0, g1 = self._g01(th)
        th -= (g0 - phi) / g1
        object.__setattr__(self, "_last", (phi, th))
        return th

    def U_derivs1(self, phi: float) -> tuple:
        """(U, dU/dphi, d2U/dphi2) at one float phi, from one inversion theta(phi); the series' sums compiled
        (:func:`.fourier_kernels.slopes_one`, the same operations as :meth:`_U_derivs1_py`), the powers here."""
        th = self.theta1(phi)
        g1, g2, g3 = slopes_one(th, float(self.k), self._series)
        return 1.0 / g1, -g2 / g1 ** 3, (3 * g2 * g2 - g3 * g1) / g1 ** 5

    def _U_derivs1_py(self, phi: float) -> tuple:
        """:meth:`U_derivs1` in Python (the reference of the compiled sums)."""
        th = self._theta1_py(float(phi))
        g1, g2, g3 = 1.0 / self.k, 0.0, 0.0
        for j, c, s in self._terms:
            ca, sa = math.cos(j * th), math.sin(j * th)
            g1 += j * (s * ca - c * sa)
            g2 -= j * j * (c * ca + s * sa)
            g3 += j ** 3 * (c * sa - s * ca)
        return 1.0 / g1, -g2 / g1 ** 3, (3 * g2 * g2 - g3 * g1) / g1 ** 5
