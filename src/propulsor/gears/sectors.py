"""The papers' own tooth method for the non-circular pair ("sector method").

Seed 000, eqs. 16-52: one leg's quarter of the driven wheel (phi in
[-pi/4, pi/4]) is split into i sectors of equal pitch arc r_Hk * dphi_k, each a
piece of a circular gear carrying one tooth (driver) / one space (driven).
Seed 002 (Tables 2-4) then gives every sector its circles and five involute
points per flank.  This module reproduces that method exactly; its teeth are
*not* conjugate (the ratio is a staircase), see :func:`sector_hub_speed`.

Rules recovered from the printed tables of seed 002 (formula blocks lost):

* Table 2: r_b = r - m, r_f = r - 1.25 m, r_a = r + m (same for r_H).
* Table 3 (driver teeth): points j = 1..5 at r_j = r_b, r - m/2, r, r + m/2,
  r + m; cos alpha_j = r_b / r_j, nu_j = inv alpha_j = tan alpha_j - alpha_j;
  backlash correction delta = j_n / (4 r_b) (seed 002, eq. 11, in rad);
  first flank  theta_j   = theta_i + dtheta_i/4 + delta - nu_3 + nu_j,
  second flank theta_s_j = theta_i + 3 dtheta_i/4 - delta + nu_3 - nu_j
  (the tooth is half the sector arc at the pitch circle, thinned by the backlash).
* Table 4 (driven spaces): the same at r_H with delta_H = j_n / (4 r_bH)
  (seed 002, eq. 13), the space widened by the backlash:
  first flank  phi_j   = phi_i + dphi_i/4 - delta_H + nu_3 - nu_j,
  second flank phi_s_j = phi_i + 3 dphi_i/4 + delta_H - nu_3 + nu_j,
  and a 6th point on the second flank only at r_6 = r_H(i+1) + m, the tip circle
  of the next sector, cos alpha_6 = (r_H(i) - m) / (r_H(i+1) + m) (seed 002, eq. 15-16).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from propulsor.errors import InputError, require_finite, require_positive
from propulsor.policy import SECTOR_ITER_TOL_RAD
from propulsor.laws.walking import LEG_PERIOD, HubSpeedRipple, WalkingLaw, check_n_closes, wrap_leg

#: convergence of the papers' iterations; the papers state 1e-6 rad (seed 000,
#: eqs. 28-31, 49-51) but their printed tables are the converged, symmetric
#: solution: with the step criterion 1e-6 and the damping 0.5/i the closure
#: residual stays ~4e-5 rad and the last printed digit of a few rows flips.
SECTOR_TOL_RAD = SECTOR_ITER_TOL_RAD

SECTOR_COLUMNS = (
    "i", "phi_rad", "phi_deg", "dphi_rad", "dphi_deg", "r_H_mm",
    "theta_rad", "theta_deg", "dtheta_rad", "dtheta_deg", "r_mm",
)
RADII_COLUMNS = (
    "i", "theta_deg", "r_mm", "r_b_mm", "r_f_mm", "r_a_mm",
    "phi_deg", "r_H_mm", "r_bH_mm", "r_fH_mm", "r_aH_mm",
)
PINION_POINT_COLUMNS = (
    "i", "j", "alpha_rad", "alpha_deg", "inv_rad", "inv_deg",
    "theta_rad", "theta_deg", "theta_s_rad", "theta_s_deg", "r_mm",
)
WHEEL_POINT_COLUMNS = (
    "i", "j", "alpha_rad", "alpha_deg", "inv_rad", "inv_deg",
    "phi_rad", "phi_deg", "phi_s_rad", "phi_s_deg", "r_H_mm",
)


def _rows(columns, arrays) -> list[dict]:
    out = []
    for k in range(len(arrays[0])):
        row = {}
        for name, arr in zip(columns, arrays):
            v = arr[k]
            if name in ("i", "j"):
                row[name] = int(v)
            else:
                v = float(v)
                row[name] = None if math.isnan(v) else v
        out.append(row)
    return out


def _structured(columns, arrays) -> np.ndarray:
    dtype = [(c, "i8" if c in ("i", "j") else "f8") for c in columns]
    out = np.zeros(len(arrays[0]), dtype=dtype)
    for c, a in zip(columns, arrays):
        out[c] = a
    return out


@dataclass(frozen=True)
class SectorTable:
    """Table 1 of seeds 000/002: one leg's sectors (arrays indexed by sector - 1).

    r_H and r are the radii recomputed by eqs. 41-44 from the converged
    intervals (not r_H of the law at the sector middle; they differ by ~0.01 mm
    and the papers print the recomputed ones).
    """

    law: WalkingLaw
    L: float
    phi: np.ndarray
    dphi: np.ndarray
    r_H: np.ndarray
    theta: np.ndarray
    dtheta: np.ndarray
    r: np.ndarray

    @property
    def i(self) -> int:
        """Number of sectors per leg."""
        return len(self.phi)

    @property
    def arc(self) -> float:
        """Common sector pitch arc l = r_Hk dphi_k = r_k dtheta_k (mm), seed 000 eq. 52."""
        return float(np.mean(self.r_H * self.dphi))

    @property
    def ratio(self) -> np.ndarray:
        """Staircase ratio of each sector U_k = dtheta_k / dphi_k = r_Hk / r_k."""
        return self.dtheta / self.dphi

    def _arrays(self):
        k = np.arange(1, self.i + 1)
        return (
            k, self.phi, np.degrees(self.phi), self.dphi, np.degrees(self.dphi), self.r_H,
            self.theta, np.degrees(self.theta), self.dtheta, np.degrees(self.dtheta), self.r,
        )

    def rows(self) -> list[dict]:
        """Table 1 as a list of dict rows with the columns SECTOR_COLUMNS."""
        return _rows(SECTOR_COLUMNS, self._arrays())

    def to_structured(self) -> np.ndarray:
        """Table 1 as a numpy structured array with the columns SECTOR_COLUMNS."""
        return _structured(SECTOR_COLUMNS, self._arrays())


def _r_H_law(law: WalkingLaw, L: float, phi):
    """Driven pitch radius r_H = L U / (1 + U), seed 000 eq. 12 / 18-20."""
    U = law.U(phi)
    return L * U / (1 + U)


def _driven_intervals(law: WalkingLaw, L: float, i: int, tol: float, max_iter: int):
    """Seed 000 eqs. 21-31: equal-arc intervals dphi_k of the driven quarter."""
    quarter = math.pi / 2
    dphi1 = quarter / i  # eq. 27
    for _ in range(max_iter):
        phi = np.empty(i)
        dphi = np.empty(i)
        phi[0], dphi[0] = -math.pi / 4, dphi1  # eq. 21
        for k in range(1, i):
            phi[k] = phi[k - 1] + dphi[k - 1]  # eq. 22-23
            arc_prev = _r_H_law(law, L, phi[k - 1] + 0.5 * dphi[k - 1]) * dphi[k - 1]
            d = dphi[k - 1]
            for _ in range(max_iter):  # eq. 25-26 by successive approximation
                d_new = arc_prev / _r_H_law(law, L, phi[k] + 0.5 * d)
                if abs(d_new - d) <= tol:
                    d = d_new
                    break
                d = d_new
            dphi[k] = d
        dphi1_new = dphi1 + 0.5 * (quarter - dphi.sum()) / i  # eq. 29-30
        if abs(dphi1_new - dphi1) <= tol:  # eq. 31
            return phi, dphi
        dphi1 = dphi1_new
    raise InputError("i", i, f"sector iteration (seed 000 eqs. 25-31) did not converge in {max_iter} cycles")


def _driver_intervals(dphi: np.ndarray, total: float, tol: float, max_iter: int, L: float):
    """Seed 000 eqs. 39-40, 48-51: driver intervals dtheta_k summing to total."""
    i = len(dphi)
    dth1 = total / i  # eq. 48 (pi / i for n = 2)
    for _ in range(max_iter):
        dth = np.empty(i)
        dth[0] = dth1
        for k in range(1, i):  # eq. 39-40
            dth[k] = dth[k - 1] * dphi[k - 1] * dphi[k] / (
                dth[k - 1] * (dphi[k] - dphi[k - 1]) + dphi[k - 1] * dphi[k]
            )
        if not np.all(dth > 0):
            raise InputError("L", L, "driver sector recursion (seed 000 eq. 39-40) gave a non-positive interval")
        dth1_new = dth1 + 0.5 * (total - dth.sum()) / i  # eq. 50
        if abs(dth1_new - dth1) <= tol:  # eq. 51
            return dth
        dth1 = dth1_new
    raise InputError("i", i, f"driver sector iteration (seed 000 eqs. 48-51) did not converge in {max_iter} cycles")


def sector_table(law: WalkingLaw, L: float, i: int, tol: float = SECTOR_TOL_RAD,
                 max_iter: int = 10000) -> SectorTable:
    """Table 1 of seeds 000/002: the sector split of one leg (seed 000 eqs. 16-52).

    law: the drive law (its n fixes sum dtheta = n pi/2, theta_1 = -n pi/4);
    L: centre distance (mm); i: sectors (teeth of the driven wheel) per leg.
    """
    if not isinstance(law, WalkingLaw):
        raise InputError("law", law, "must be a WalkingLaw")
    check_n_closes(law.n)
    L = require_positive("L", L, "mm")
    fi = require_finite("i", i)
    if fi != round(fi) or fi < 2:
        raise InputError("i", i, "sectors per leg must be a whole number >= 2")
    i = int(round(fi))
    tol = require_positive("tol", tol, "rad")
    phi, dphi = _driven_intervals(law, L, i, tol, max_iter)
    total = law.n * math.pi / 2
    dth = _driver_intervals(dphi, total, tol, max_iter, L)
    r_H = dth * L / (dphi + dth)  # eq. 41-42
    r = L - r_H  # eq. 43-44
    theta = -total / 2 + np.concatenate([[0.0], np.cumsum(dth)[:-1]])  # eq. 45-47
    return SectorTable(law=law, L=L, phi=phi, dphi=dphi, r_H=r_H, theta=theta, dtheta=dth, r=r)


# --------------------------------------------------------------------------- Table 2
@dataclass(frozen=True)
class SectorRadii:
    """Table 2 of seed 002: circles of every sector (mm)."""

    table: SectorTable
    m: float

    @property
    def r_b(self):
        """Driver 'base' radius r_b = r - m (seed 002 rule; not r cos alpha)."""
        return self.table.r - self.m

    @property
    def r_f(self):
        """Driver root radius r_f = r - 1.25 m."""
        return self.table.r - 1.25 * self.m

    @property
    def r_a(self):
        """Driver tip radius r_a = r + m."""
        return self.table.r + self.m

    @property
    def r_bH(self):
        return self.table.r_H - self.m

    @property
    def r_fH(self):
        return self.table.r_H - 1.25 * self.m

    @property
    def r_aH(self):
        return self.table.r_H + self.m

    def _arrays(self):
        t = self.table
        return (
            np.arange(1, t.i + 1), np.degrees(t.theta), t.r, self.r_b, self.r_f, self.r_a,
            np.degrees(t.phi), t.r_H, self.r_bH, self.r_fH, self.r_aH,
        )

    def rows(self) -> list[dict]:
        return _rows(RADII_COLUMNS, self._arrays())

    def to_structured(self) -> np.ndarray:
        return _structured(RADII_COLUMNS, self._arrays())


def sector_radii(table: SectorTable, m: float) -> SectorRadii:
    """Table 2 of seed 002 for module m (mm)."""
    m = require_positive("m", m, "mm")
    if not np.all(table.r - 1.25 * m > 0):
        raise InputError("m", m, f"root radius r - 1.25 m must be > 0: m < {float(np.min(table.r)) / 1.25:.4f} mm")
    return SectorRadii(table=table, m=m)


def involute(alpha):
    """Involute function inv alpha = tan alpha - alpha (seed 002, eq. 12/14)."""
    alpha = np.asarray(alpha, dtype=float)
    return np.tan(alpha) - alpha


def _point_radii(r, m):
    """The five radii of seed 002: r - m, r - m/2, r, r + m/2, r + m (columns j = 1..5)."""
    return r[:, None] + m * np.array([-1.0, -0.5, 0.0, 0.5, 1.0])[None, :]


def _check_backlash(j_n):
    j_n = require_finite("j_n", j_n)
    if j_n < 0:
        raise InputError("j_n", j_n, "backlash must be >= 0 mm")
    return j_n


def pinion_tooth_points(table: SectorTable, m: float, j_n: float) -> np.ndarray:
    """Table 3 of seed 002: five involute points per flank of every driver tooth.

    Returns a structured array (columns PINION_POINT_COLUMNS), rows ordered by
    sector i then point j; polar angles in the driver frame theta.
    """
    sector_radii(table, m)
    j_n = _check_backlash(j_n)
    r = table.r
    r_b = r - m
    rj = _point_radii(r, m)
    alpha = np.arccos(np.clip(r_b[:, None] / rj, -1.0, 1.0))
    nu = involute(alpha)
    delta = j_n / (4 * r_b)  # seed 002, eq. 11 (in rad)
    base1 = table.theta + 0.25 * table.dtheta + delta - nu[:, 2]
    base2 = table.theta + 0.75 * table.dtheta - delta + nu[:, 2]
    th1 = base1[:, None] + nu
    th2 = base2[:, None] - nu
    I, J = np.meshgrid(np.arange(1, table.i + 1), np.arange(1, 6), indexing="ij")
    arrays = [a.ravel() for a in (I, J, alpha, np.degrees(alpha), nu, np.degrees(nu),
                                    th1, np.degrees(th1), th2, np.degrees(th2), rj)]
    return _structured(PINION_POINT_COLUMNS, arrays)


def wheel_space_points(table: SectorTable, m: float, j_n: float) -> np.ndarray:
    """Table 4 of seed 002: involute points of every driven-wheel space.

    Five points per flank as for the driver, plus a 6th point on the second
    flank at the tip circle of the next sector r_H(i+1) + m (for the last
    sector the next one is sector 1 of the next leg).  Its first-flank columns
    are NaN ('-' in the paper).  Polar angles in the driven frame phi.
    """
    sector_radii(table, m)
    j_n = _check_backlash(j_n)
    rH = table.r_H
    r_b = rH - m
    r_next_tip = np.roll(rH, -1) + m
    rj = np.concatenate([_point_radii(rH, m), r_next_tip[:, None]], axis=1)
    alpha = np.arccos(np.clip(r_b[:, None] / rj, -1.0, 1.0))  # eq. 14-15
    nu = involute(alpha)
    delta = j_n / (4 * r_b)  # seed 002, eq. 13 (in rad)
    base1 = table.phi + 0.25 * table.dphi - delta + nu[:, 2]
    base2 = table.phi + 0.75 * table.dphi + delta - nu[:, 2]
    ph1 = base1[:, None] - nu
    ph1[:, 5] = np.nan
    ph2 = base2[:, None] + nu
    I, J = np.meshgrid(np.arange(1, table.i + 1), np.arange(1, 7), indexing="ij")
    arrays = [a.ravel() for a in (I, J, alpha, np.degrees(alpha), nu, np.degrees(nu),
                                    ph1, np.degrees(ph1), ph2, np.degrees(ph2), rj)]
    return _structured(WHEEL_POINT_COLUMNS, arrays)


def sector_tip_thickness(table: SectorTable, m: float, j_n: float) -> tuple[float, float]:
    """Least tip-land thickness (mm) of the driver teeth and of the driven-wheel teeth of the
    sector method (seed 002 Tables 3-4 rules; the driven tooth between spaces i and i+1 has the
    tip radius r_H(i+1) + m)."""
    r, rH = table.r, table.r_H
    rb, rbH = r - m, rH - m
    nu3 = involute(np.arccos(rb / r))
    nu5 = involute(np.arccos(rb / (r + m)))
    d = j_n / (4 * rb)
    th1 = table.theta + 0.25 * table.dtheta + d - nu3 + nu5
    th2 = table.theta + 0.75 * table.dtheta - d + nu3 - nu5
    t_drv = float(np.min((r + m) * (th2 - th1)))
    nu3H = involute(np.arccos(rbH / rH))
    dH = j_n / (4 * rbH)
    r6 = np.roll(rH, -1) + m
    nu6 = involute(np.arccos(np.clip(rbH / r6, -1, 1)))
    ph_s6 = table.phi + 0.75 * table.dphi + dH - nu3H + nu6
    rHn, rbHn, phn, dphn = np.roll(rH, -1), np.roll(rbH, -1), np.roll(table.phi, -1), np.roll(table.dphi, -1)
    phn = phn.copy()
    phn[-1] += LEG_PERIOD
    nu3n = involute(np.arccos(rbHn / rHn))
    nu5n = involute(np.arccos(rbHn / (rHn + m)))
    ph_1n = phn + 0.25 * dphn - j_n / (4 * rbHn) + nu3n - nu5n
    t_dvn = float(np.min(r6 * (ph_1n - ph_s6)))
    return t_drv, t_dvn


def structured_rows(arr: np.ndarray) -> list[dict]:
    """A structured array as dict rows (NaN -> None, the paper's '-')."""
    return _rows(arr.dtype.names, [arr[c] for c in arr.dtype.names])


# --------------------------------------------------------------------------- price
def sector_ratio(table: SectorTable, phi):
    """Staircase ratio of the sector method: U = dtheta_k / dphi_k on sector k (periodic per leg)."""
    w = wrap_leg(phi)
    edges = np.append(table.phi, table.phi[-1] + table.dphi[-1])
    k = np.clip(np.searchsorted(edges, w, side="right") - 1, 0, table.i - 1)
    return table.ratio[k]


def sector_hub_speed(table: SectorTable, samples_per_sector: int = 400) -> HubSpeedRipple:
    """Hub speed ripple the sector method leaves even with ideal teeth.

    v/omega = (dX01/dphi) / U_k on sector k (seed 000 eq. 2, 3); the mean is
    the time (driver-angle) mean, sum dX01 / sum dtheta over the leg, which
    equals A/u for a closed sector table.
    """
    law = table.law
    phis, vs = [], []
    for k in range(table.i):
        p = np.linspace(table.phi[k], table.phi[k] + table.dphi[k], samples_per_sector)
        phis.append(p)
        vs.append(law.dX01_dphi(p) / table.ratio[k])
    phi = np.concatenate(phis)
    v = np.concatenate(vs)
    A, b = law.A, law.b
    x_leg = A * np.sum(table.dphi) + 1.5 * b * (
        math.sin(2 * (table.phi[-1] + table.dphi[-1])) - math.sin(2 * table.phi[0])
    )
    mean = x_leg / np.sum(table.dtheta)
    imin, imax = int(np.argmin(v)), int(np.argmax(v))
    return HubSpeedRipple(
        ripple=float((v[imax] - v[imin]) / mean), mean=float(mean), v_min=float(v[imin]),
        v_max=float(v[imax]), phi_min=float(phi[imin]), phi_max=float(phi[imax]),
    )
