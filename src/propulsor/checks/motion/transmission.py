"""A gear pair on its finished outlines: at each driven angle phi the driver is placed at the law angle
theta(phi); the free rotation of the driven body both ways until first contact gives backlash,
transmission error against the law and the tooth pairs in contact."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ... import policy
from ...check import Check
from ...errors import require, require_positive
from ...planar import norms
from .outlines import outline
from .distance import check_record
from .transmission_kernel import sweep_steps

__all__ = ['TransmissionResult', 'transmission_sweep']


@dataclass
class TransmissionResult:
    """Gear-pair behaviour over a cycle, measured on the finished outlines.

    Per step (driven law angle ``phi``, driver at ``theta`` = law(phi)):
    ``free_fwd``/``free_back``: free rotation of the driven (rad, in the phi sense)
    forwards / backwards from its nominal position until it touches the driver;
    ``backlash_angle`` = their sum (circumferential backlash as a driven angle);
    ``backlash_mm`` = backlash_angle · r_ref;
    ``te_drive`` = −free_back: transmission error of the loaded flank (driver
    pushing the driven forwards), actual driven angle minus the law;
    ``te_coast`` = +free_fwd (the other flank); ``te_mid`` = mean of the two
    (error of the centre of the backlash: 0 for conjugate teeth with symmetric
    thinning); ``pairs_drive``/``pairs_coast``: tooth pairs in contact (gap
    within ``contact_tol`` mm) at the drive / coast contact position;
    ``overlap_area``: driver ∩ driven at the nominal position (mm²).  At steps
    where that exceeds OVERLAP_AREA_TOL_MM2 the free rotations are NaN and the
    pair counts 0 (the outlines interfere; the overlap check reports it).
    """

    phi: np.ndarray
    theta: np.ndarray
    overlap_area: np.ndarray
    free_fwd: np.ndarray
    free_back: np.ndarray
    r_ref: np.ndarray
    pairs_drive: np.ndarray
    pairs_coast: np.ndarray
    contact_point_drive: np.ndarray
    contact_point_coast: np.ndarray
    contact_tol: float
    name: str = "mesh"

    @property
    def backlash_angle(self) -> np.ndarray:
        return self.free_fwd + self.free_back

    @property
    def backlash_mm(self) -> np.ndarray:
        return self.backlash_angle * self.r_ref

    @property
    def te_drive(self) -> np.ndarray:
        return -self.free_back

    @property
    def te_coast(self) -> np.ndarray:
        return self.free_fwd.copy()

    @property
    def te_mid(self) -> np.ndarray:
        return 0.5 * (self.free_fwd - self.free_back)

    @property
    def phi_drive(self) -> np.ndarray:
        """Actual driven angle when the driver drives (loaded flank in contact)."""
        return self.phi - self.free_back

    @property
    def te_drive_pp(self) -> float:
        """Peak-to-peak transmission error of the loaded flank (rad)."""
        te = self.te_drive[np.isfinite(self.te_drive)]
        return float(np.ptp(te)) if len(te) else math.nan

    @property
    def backlash_min_mm(self) -> float:
        b = self.backlash_mm[np.isfinite(self.backlash_mm)]
        return float(b.min()) if len(b) else math.nan

    @property
    def backlash_max_mm(self) -> float:
        b = self.backlash_mm[np.isfinite(self.backlash_mm)]
        return float(b.max()) if len(b) else math.nan

    @property
    def max_overlap(self) -> float:
        return float(self.overlap_area.max())

    @property
    def contact_ratio_mean(self) -> float:
        """Mean number of tooth pairs in contact on the drive flank (≈ epsilon_alpha for involute pairs)."""
        return float(np.mean(self.pairs_drive))

    def fraction_pairs(self, k: int, flank: str = "drive") -> float:
        """Fraction of the steps with exactly k pairs in contact."""
        p = self.pairs_drive if flank == "drive" else self.pairs_coast
        return float(np.mean(p == k))

    def checks(self, te_limit_rad: float | None = None, backlash_range_mm: tuple[float, float] | None = None) -> list[Check]:
        tol = policy.OVERLAP_AREA_TOL_MM2
        k = int(np.argmax(self.overlap_area))
        out = [check_record(f"{self.name}.overlap_area", self.max_overlap <= tol, self.max_overlap, tol, "mm^2",
                       f"max overlap {self.max_overlap:.3g} mm^2 at phi = {self.phi[k]:.6f} rad (step {k})")]
        bl = self.backlash_mm
        finite = np.isfinite(bl)
        n_int = int(np.count_nonzero(self.overlap_area > tol))
        n_free = int(np.count_nonzero(~finite)) - n_int
        kmin = int(np.argmin(np.where(finite, bl, np.inf))) if np.any(finite) else 0
        lo, hi = backlash_range_mm if backlash_range_mm is not None else (0.0, None)
        ok = bool(np.all(finite)) and self.backlash_min_mm > lo and (hi is None or self.backlash_max_mm <= hi)
        out.append(check_record(f"{self.name}.backlash", ok, self.backlash_min_mm, lo, "mm",
                           f"backlash {self.backlash_min_mm:.5f} .. {self.backlash_max_mm:.5f} mm "
                           f"(min at phi = {self.phi[kmin]:.6f} rad); "
                           f"{n_int} steps interfere, {n_free} steps without contact within the search angle"
                           + (f"; allowed {lo} .. {hi} mm" if backlash_range_mm is not None else "")))
        mn = int(min(self.pairs_drive.min(), self.pairs_coast.min()))
        out.append(check_record(f"{self.name}.contact_continuity", mn >= 1, mn, 1, "pairs",
                           f"least tooth pairs in contact {mn}; mean on drive flank {self.contact_ratio_mean:.4f}"))
        if te_limit_rad is not None:
            pp = self.te_drive_pp
            out.append(check_record(f"{self.name}.transmission_error", pp <= te_limit_rad, pp, te_limit_rad, "rad",
                               f"drive-flank transmission error peak-to-peak {pp:.3e} rad"))
        return out


def transmission_sweep(driver_profile, driver_center, driven_profile, driven_center,
                       law_theta_of_phi: Callable, phis, *, senses: tuple[int, int] = (1, -1),
                       r_ref=None, chord_tol: float = policy.MOTION_CHORD_TOL_MM,
                       contact_tol: float = policy.MOTION_CONTACT_TOL_MM,
                       contact_merge: float = policy.MOTION_CONTACT_MERGE_MM,
                       max_angle: float = policy.MOTION_MAX_FREE_ANGLE_RAD,
                       max_segment: float = policy.MOTION_MAX_SEGMENT_MM, name: str = "mesh") -> TransmissionResult:
    """Backlash, transmission error and contact count of a gear pair from its finished outlines.

    Each profile is given in its own body frame with its axis at the origin; at
    angle 0 it is placed with its axis at driver_center / driven_center.  At
    step k the driven body turns by senses[1]·phis[k] and the driver by
    senses[0]·law_theta_of_phi(phis[k]) (default (1, -1): an external pair, the
    driver turning CCW while the driven turns CW; use (1, 1) for an internal
    pair).  The free rotation of the driven about its axis in each direction is
    found analytically: every boundary vertex of the driven runs on a circle
    about the driven axis (and every driver vertex, relatively, the other way);
    the first circle-edge crossing that enters the other body is the contact
    (searched up to max_angle rad).  Tooth pairs in contact are counted at the
    touching position as groups of points whose remaining gap (arc at the
    point's own radius) is within contact_tol mm, grouped along the driven
    boundary (groups further apart than contact_merge mm are different pairs).
    r_ref: radius for backlash in mm - a number, an array per step or a
    callable r(phi); default the mean distance of the first contact points
    from the driven axis.
    """
    drv = outline(driver_profile, chord_tol, max_segment)
    dvn = outline(driven_profile, chord_tol, max_segment)
    c1 = np.asarray(driver_center, float).reshape(2)
    c2 = np.asarray(driven_center, float).reshape(2)
    require(np.linalg.norm(c2 - c1) > 0, "driven_center", tuple(c2), "must differ from driver_center")
    phis = np.atleast_1d(np.asarray(phis, float))
    require(phis.ndim == 1 and len(phis) >= 1 and bool(np.all(np.isfinite(phis))), "phis", phis.shape, "must be a 1-D array of finite angles")
    s1, s2 = (float(s) for s in senses)
    require(abs(s1) == 1 and abs(s2) == 1, "senses", senses, "each must be +1 or -1")
    require_positive("contact_tol", contact_tol, "mm")
    require_positive("contact_merge", contact_merge, "mm")
    require_positive("max_angle", max_angle, "rad")
    theta = np.array([float(law_theta_of_phi(p)) for p in phis])
    require(bool(np.all(np.isfinite(theta))), "law_theta_of_phi", "non-finite", "must return finite angles")

    N = len(phis)
    area = np.zeros(N)
    fwd = np.zeros(N)
    back = np.zeros(N)
    pd = np.zeros(N, int)
    pc = np.zeros(N, int)
    ptd = np.zeros((N, 2))
    ptc = np.zeros((N, 2))
    # the steps in one compiled loop (transmission_kernel): at each step the poses, whether the bodies are certainly
    # apart (crossing.certainly_apart: their common area 0.0 without the boolean, as the 2D sweeps do) and the free
    # rotations both ways (backlash.free_rotations), each step's first windows just above the step before's answers;
    # where the bodies may overlap, the area from the boolean, and no rotations above the tolerance (interfering)
    sweep_steps(drv, dvn, phis, theta, (s1, s2), c1, c2, max_angle, contact_tol, contact_merge,
                (area, fwd, back, pd, pc, ptd, ptc), lambda rel21: (drv.section ^ dvn.section.transform(rel21)).area())
    if r_ref is None:
        pts = np.vstack([ptd, ptc])
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        rr = np.full(N, float(np.mean(norms(pts - c2))) if len(pts) else np.nan)
    elif callable(r_ref):
        rr = np.array([float(r_ref(p)) for p in phis])
    else:
        rr = np.broadcast_to(np.asarray(r_ref, float), (N,)).copy()
    return TransmissionResult(phis, theta, area, fwd, back, rr, pd, pc, ptd, ptc, float(contact_tol), name)
