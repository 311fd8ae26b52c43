"""Composite (polysector) gear with stepwise adjustable ratio (seed 003, Skoibeda & Dankov).

Pure math (numpy/scipy).  Millimetres and radians.  The figures of the seed are lost; the
geometry below is derived from the text and the equations, and every derivation names the
equation it restates.

Frames and names
----------------
* The blank: spur gear z, m, α (x = 0), pitch radius r = m z / 2, base r_b = r cos α,
  tip r_a = r + m.  A *sector* carries z_c consecutive teeth of the blank; its pitch arc keeps the
  blank's centre O' ("centre of the sector's pitch arc", eq. 18–20).
* The composite wheel turns about O1.  Sector j of flow f sits with O' at the *offset* e
  (вылет) from O1 on its mid-line; the mid-line of flow 1's sector j is at 2πj/i_s, flow 2 is
  turned by half a sector pitch, π/i_s.  The sector's pitch arc touches the circle of radius
  r + e about O1 at the mid-line point M: that circle is the envelope of the pitch arcs, the
  *conditional* pitch circle, r_усл = r + e, z_усл = 2 r_усл / m (seed 003 before eq. 15).
* The solid gear z2 (pitch r2, tip r_a2 = r2 + m) turns about O2 = (a, 0), a = r_усл + r2:
  conditional pitch circle rolling on the gear's pitch circle, nominal ratio
  i_n = r2 / r_усл = r2 / (a − r2) (eq. 7/8 at α_wt = α).
* Tooth phase: a sector whose mid-line passes the line of centres meshes the gear like the
  conditional gear does (at M both pitch circles touch).  All 2 i_s sectors meet the gear in the
  same phase only when the arc between neighbouring sectors on the conditional circle,
  π r_усл / i_s, is a whole number of pitches: z_усл / (2 i_s) whole.  So the offsets are
  e = m (z_усл − z) / 2 with z_усл a multiple of 2 i_s (our rule; the seed's "arbitrary
  offsets" need sectors re-clocked per position).

Eq. 1 and 3 (largest offset), our derivation
--------------------------------------------
Sector COD: O is the sector's centre (our O'), D the point of its tip circle on the mid-line,
C a tip corner at angle δ from the mid-line.  Then (law of cosines in O1OC, O1 on the
mid-line behind O by e)
    O1C² = e² + r_a² + 2 e r_a cos δ                          (eq. 1 row 3 = eq. 3 row 5)
    CD = 2 r_a sin(δ/2)                                        (eq. 1 row 4 = eq. 3 row 2)
    O1C² = CD² + (e + r_a)² − 2 CD (e + r_a) sin(δ/2)          (eq. 1 row 5 = eq. 3 row 1)
(the printed "+" of the last row does not close the triangle O1DC: its angle at D is
90° − δ/2, so the cosine term is −; with "−" the row is the same condition as the first,
which is why the system is one condition short).  C on the mating gear's tip circle
(triangle O1 O2 C, β2 the angle at O2):
    O1C² = a² + r_a2² − 2 a r_a2 cos β2                        (eq. 1 row 2; eq. 3 row 4 prints
                                                                 "+": the internal-mesh sign)
δ of eq. 3, (2 z_c − 3) π/(2z) − inv α + inv α_a, is the tip corner of the *driving* flank of
the extreme tooth (the flank facing the rest of the sector); δ of eq. 1,
(2 z_c − 1) π/(2z) − inv α + inv α_a, is no tooth point; with its inv signs swapped,
(2 z_c − 1) π/(2z) + inv α − inv α_a, it is the *outer* tip corner of the extreme tooth.
Closing condition (ours, the lost figure's hand-over pose): a sector can *drive* while a driving
corner of its teeth lies inside the gear's tip circle.  The wheel turns CCW and every tooth drives
with its CCW flank, so the trailing extreme tooth's driving corner is eq. 3's C (δ_in, the corner
of the flank facing the rest of the sector) and the leading tooth's is its outer corner, the mirror
of δ_out (eq. 1's δ with the swapped signs).  One sector drives over
φ1 = u_exit(δ_in) + u_exit(δ_out) of wheel turn, u_exit(δ) the mid-line angle at which the trailing
tooth's corner δ leaves the gear's tip circle (entry of the leading corner mirrors the exit of the
trailing one).  Eq. 4 then reads
    ε_s = φ1 i_s / 2π          per flow (i_s sectors of one flow),
    ε_s = φ1 (2 i_s) / 2π      both flows together (2 i_s sectors, evenly interleaved; the seed
                               gives up overlap within one flow on purpose).
The largest offset is the largest e with ε_s (both flows) ≥ ε_s,min = 1.05 (eq. 4's lower bound)
at which both driving corners still reach into the gear's tip circle (for short sectors or small
gears the leading tooth's outer corner stops reaching it first, with ε_s still above 1.05).  Counting the whole tip land instead (its non-driving corners too) accepts offsets where the
driving corner never reaches the gear in time: for m 4, z 30, z_c 9, i_s 3, z2 24 (thinning 0.1 mm)
that reading gives 38.36 mm, the driving corners 33.70 mm.  ε_s ≥ 1.05 is necessary, not sufficient:
the hand-over itself (tip-on-tip contact, snaps) is proved on the outlines by the tracked contact law
(:mod:`propulsor.parts.polysector.contact_law`).  The flank-contact-only overlap of one flow at e = 0
is (z_c − 1 + ε_α) / (z_c + k) < 1 (k empty pitches between sectors, eq. 2).

Eq. 5–8 (instantaneous ratio)
-----------------------------
The sector's flanks are involutes of its base circle about O'; their normals touch that circle.
In flank contact the common normal is the internal common tangent of the base circles about O'
and O2 (the driving side); it cuts the line of centres in the pole P (Kennedy), and
i_t = ω1/ω2 = O2P / O1P.  With O2P = r2 cos α / cos α_wt (α_wt: pressure angle of the gear at
P) this is eq. 7, i_t = r2 (cos α/cos α_wt) / (a − r2 cos α/cos α_wt), and eq. 8 is
Δi = (i_n − i_t)/i_n.  Eq. 5/6 are the same for an internal gear (O1P = O2P − a,
a = r2 − r1): i_t = d2 c / (d1 − d2 (1 − c)), c = cos α/cos α_wt.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import InputError, require
from .involute import inv

__all__ = ["PolysectorGeometry", "sector_teeth_eq2", "delta_eq1_printed", "delta_eq3", "delta_outer_corner",
           "eq1_residuals", "ratio_eq5", "ratio_error_eq6", "ratio_eq7", "ratio_error_eq8", "pole_flank",
           "epsilon_alpha_pair", "tooth_position_error", "EPS_S_MIN", "EPS_S_MAX"]

#: eq. 4: the sector overlap ratio should lie within 1.05 … 1.3 (seed 003 after eq. 4)
EPS_S_MIN = 1.05
EPS_S_MAX = 1.3


def sector_teeth_eq2(z1: int, i_s: int, k: int) -> float:
    """Eq. 2: z_c = (z1 − k i_s)/i_s = z1/i_s − k, k = 1 … 3 empty pitches between the sectors of
    one flow (room for the other flow's sector body at the least offset)."""
    return z1 / i_s - k


def delta_eq1_printed(z_c: int, z: int, alpha: float, r_b: float, r_a: float) -> float:
    """δ of eq. 1 as printed: (2 z_c − 1) π/(2z) − inv α + inv(arccos(r_b/r_a))."""
    return (2 * z_c - 1) * math.pi / (2 * z) - inv(alpha) + inv(math.acos(r_b / r_a))


def delta_eq3(z_c: int, z: int, alpha: float, r_b: float, r_a: float, thinning: float = 0.0) -> float:
    """δ of eq. 3: (2 z_c − 3) π/(2z) − inv α + inv(arccos(r_b/r_a)): the tip corner of the extreme
    tooth's driving (inner) flank, angle from the sector mid-line about O'.  ``thinning``: arc
    tooth-thickness allowance on the pitch circle (our addition; 0 gives the seed's formula)."""
    r = r_b / math.cos(alpha)
    return (2 * z_c - 3) * math.pi / (2 * z) - inv(alpha) + inv(math.acos(r_b / r_a)) + thinning / (2 * r)


def delta_outer_corner(z_c: int, z: int, alpha: float, r_b: float, r_a: float, thinning: float = 0.0) -> float:
    """Eq. 1's δ with its inv signs swapped, (2 z_c − 1) π/(2z) + inv α − inv α_a: the outer tip
    corner of the extreme tooth (angle from the sector mid-line about O')."""
    r = r_b / math.cos(alpha)
    return (2 * z_c - 1) * math.pi / (2 * z) + inv(alpha) - inv(math.acos(r_b / r_a)) - thinning / (2 * r)


def eq1_residuals(e: float, r_a: float, delta: float, a: float, r_a2: float, beta2: float) -> np.ndarray:
    """The rows of eq. 1 / eq. 3 (external mesh, row 5 with the corrected sign) as residuals of O1C²:
    [row3 − row5, row3 − row2]; both 0 when C (at δ) lies on the gear's tip circle at angle β2."""
    o1c2 = e * e + r_a * r_a + 2 * e * r_a * math.cos(delta)
    cd = 2 * r_a * math.sin(delta / 2)
    row5 = cd * cd + (e + r_a) ** 2 - 2 * cd * (e + r_a) * math.sin(delta / 2)
    row2 = a * a + r_a2 * r_a2 - 2 * a * r_a2 * math.cos(beta2)
    return np.array([o1c2 - row5, o1c2 - row2])


def ratio_eq5(d1: float, d2: float, alpha: float, alpha_wt: float) -> float:
    """Eq. 5 (internal mesh): i_t = d2 c / (d1 − d2 (1 − c)), c = cos α / cos α_wt."""
    c = math.cos(alpha) / math.cos(alpha_wt)
    return d2 * c / (d1 - d2 * (1.0 - c))


def ratio_error_eq6(d1: float, d2: float, alpha: float, alpha_wt: float) -> float:
    """Eq. 6: Δi = 1 − d1 c / (d1 − d2 (1 − c))."""
    c = math.cos(alpha) / math.cos(alpha_wt)
    return 1.0 - d1 * c / (d1 - d2 * (1.0 - c))


def ratio_eq7(r2: float, a: float, alpha, alpha_wt):
    """Eq. 7 (external mesh): i_t = r2 (cos α/cos α_wt) / (a − r2 cos α/cos α_wt)."""
    rw2 = r2 * np.cos(alpha) / np.cos(alpha_wt)
    return rw2 / (a - rw2)


def ratio_error_eq8(r2: float, a: float, alpha, alpha_wt):
    """Eq. 8: Δi = {r2/(a − r2) − i_t} / (r2/(a − r2))."""
    i_n = r2 / (a - r2)
    return (i_n - ratio_eq7(r2, a, alpha, alpha_wt)) / i_n


def epsilon_alpha_pair(z1: float, z2: float, m: float, alpha: float) -> float:
    """Transverse contact ratio of a standard external pair (x = 0, h_a* = 1; ISO 21771)."""
    r1, r2 = m * z1 / 2, m * z2 / 2
    rb1, rb2 = r1 * math.cos(alpha), r2 * math.cos(alpha)
    ra1, ra2 = r1 + m, r2 + m
    g = math.sqrt(ra1 ** 2 - rb1 ** 2) + math.sqrt(ra2 ** 2 - rb2 ** 2) - (r1 + r2) * math.sin(alpha)
    return g / (math.pi * m * math.cos(alpha))


def pole_flank(e: float, u, r_b: float, r_b2: float, a: float) -> tuple[np.ndarray, np.ndarray]:
    """Pole of a flank contact, sector mid-line at wheel angle u (from the line of centres, CCW;
    wheel CCW drives the gear CW): (O2P, O1P) in mm.

    The line of action is the internal common tangent of the base circles (O', r_b) and
    (O2, r_b2) on the driving side: with n the unit vector O'→O2 and cos α' = (r_b + r_b2)/|O'O2|,
    it touches the sector's base circle at T1 = O' + r_b R(−α') n.  The pole is where it cuts
    the x axis (the line O1O2)."""
    u = np.asarray(u, float)
    ox, oy = e * np.cos(u), e * np.sin(u)
    dx, dy = a - ox, -oy
    d = np.hypot(dx, dy)
    nx, ny = dx / d, dy / d
    ap = np.arccos((r_b + r_b2) / d)
    c, s = np.cos(-ap), np.sin(-ap)
    tx, ty = c * nx - s * ny, s * nx + c * ny  # R(−α') n
    T1x, T1y = ox + r_b * tx, oy + r_b * ty
    # the line of action is perpendicular to (tx, ty) at T1: points T1 + λ (−ty, tx)
    lam = -T1y / tx
    Px = T1x - lam * ty
    return a - Px, Px


@dataclass(frozen=True)
class PolysectorGeometry:
    """One composite gear and its solid mate: blank (z, m, α), i_s sectors of z_c teeth per flow,
    ``flows`` (1 or 2) layers, gear z2; thinning: arc tooth-thickness allowance of every tooth on
    its pitch circle (mm)."""

    m: float
    z: int
    z_c: int
    i_s: int
    z2: int
    alpha: float = math.radians(20.0)
    flows: int = 2
    thinning: float = 0.0

    def __post_init__(self):
        require(self.flows in (1, 2), "flows", self.flows, "must be 1 or 2")
        require(self.z % (self.i_s * self.flows) == 0, "z", self.z,
                f"must be a multiple of i_s·flows = {self.i_s * self.flows} (sectors equally spaced in tooth phase)")
        k = self.z // self.i_s - self.z_c
        require(k >= 1, "z_c", self.z_c,
                f"too large for the gaps: eq. 2 z_c = z/i_s − (1…3) ≤ {self.z // self.i_s - 1}")
        require(self.z_c >= 2, "z_c", self.z_c, "must be >= 2")

    # --- the blank -------------------------------------------------------------------------
    @property
    def r(self) -> float:
        return self.m * self.z / 2.0

    @property
    def r_b(self) -> float:
        return self.r * math.cos(self.alpha)

    @property
    def r_a(self) -> float:
        return self.r + self.m

    @property
    def r2(self) -> float:
        return self.m * self.z2 / 2.0

    @property
    def r_b2(self) -> float:
        return self.r2 * math.cos(self.alpha)

    @property
    def r_a2(self) -> float:
        return self.r2 + self.m

    @property
    def k_gap(self) -> int:
        """Empty pitches between neighbouring sectors of one flow (eq. 2: z_c = z/i_s − k)."""
        return self.z // self.i_s - self.z_c

    @property
    def n_sectors(self) -> int:
        return self.i_s * self.flows

    # --- positions ------------------------------------------------------------------------
    def offset_for(self, z_cond: int) -> float:
        return self.m * (z_cond - self.z) / 2.0

    def z_cond(self, e: float) -> float:
        return 2.0 * (self.r + e) / self.m

    def center_distance(self, e: float) -> float:
        return self.r + e + self.r2

    def ratio_nominal(self, e: float) -> float:
        """i_n = r2 / r_усл (eq. 8's r2/(a − r2))."""
        return self.r2 / (self.r + e)

    # --- eq. 1/3/4 --------------------------------------------------------------------------
    def tip_land(self) -> tuple[float, float]:
        """(δ_in, δ_out): the extreme tooth's tip land spans these angles from the mid-line about O'
        (eq. 3's δ and eq. 1's δ with the inv signs swapped)."""
        return (delta_eq3(self.z_c, self.z, self.alpha, self.r_b, self.r_a, self.thinning),
                delta_outer_corner(self.z_c, self.z, self.alpha, self.r_b, self.r_a, self.thinning))

    def tip_land_distance(self, e: float, u: float) -> float:
        """Least distance from O2 to the tip land of the trailing extreme tooth of a sector whose
        mid-line is at wheel angle u (the land spans u − δ_out … u − δ_in about O')."""
        a = self.center_distance(e)
        d_in, d_out = self.tip_land()
        ox, oy = e * math.cos(u), e * math.sin(u)
        beta = math.atan2(-oy, a - ox)  # direction O' → O2
        lo, hi = u - d_out, u - d_in
        if lo <= beta <= hi:
            return math.hypot(a - ox, oy) - self.r_a
        best = math.inf
        for ang in (lo, hi):
            cx, cy = ox + self.r_a * math.cos(ang), oy + self.r_a * math.sin(ang)
            best = min(best, math.hypot(cx - a, cy))
        return best

    def exit_angle(self, e: float) -> float:
        """u_exit: mid-line angle at which the sector's tip land (its last tooth) leaves the gear's tip
        circle: the whole engagement, every pose where the sector's outline can touch the gear."""
        f = lambda u: self.tip_land_distance(e, u) - self.r_a2
        return self._leave(f, e, "the sector's teeth do not reach the gear's tip circle")

    def corner_exit(self, e: float, delta: float) -> float:
        """Mid-line angle at which the trailing extreme tooth's tip corner at ``delta`` (from the mid-line
        about O', on the trailing side) leaves the gear's tip circle."""
        a = self.center_distance(e)

        def f(u):
            cx = e * math.cos(u) + self.r_a * math.cos(u - delta)
            cy = e * math.sin(u) + self.r_a * math.sin(u - delta)
            return math.hypot(cx - a, cy) - self.r_a2

        return self._leave(f, e, "the sector's driving corner does not reach the gear's tip circle")

    @staticmethod
    def _leave(f, e: float, why: str) -> float:
        # the trailing tooth is deepest in the gear near the pose that puts it on the line of
        # centres; it leaves the tip circle past that pose
        grid = np.linspace(0.0, math.pi / 2, 721)
        vals = np.array([f(u) for u in grid])
        k = int(np.argmin(vals))
        require(vals[k] < 0.0, "offset", e, why)
        k1 = k + int(np.argmax(vals[k:] > 0.0))
        require(vals[k1] > 0.0, "offset", e, "the sector never leaves the gear's tip circle")
        return brentq(f, grid[k1 - 1], grid[k1], xtol=1e-13)

    def driving_span(self, e: float) -> tuple[float, float]:
        """(u_enter, u_exit): the mid-line angles between which a *driving* corner of the sector lies inside
        the gear's tip circle.  The wheel turns CCW, so a tooth drives with its CCW flank: the trailing
        tooth's driving corner is the inner one, eq. 3's δ, and it leaves last at corner_exit(δ_in); the
        leading tooth's driving corner is its outer one, which by the sector's mirror symmetry enters at
        −corner_exit(δ_out).  Past the offset where these no longer span a sector pitch the driving corner
        never reaches the gear in time: the outer (non-driving) corner of the leading tooth would."""
        d_in, d_out = self.tip_land()
        return -self.corner_exit(e, d_out), self.corner_exit(e, d_in)

    def phi1(self, e: float) -> float:
        """Wheel angle over which one sector has a driving corner in the gear's tip circle."""
        u0, u1 = self.driving_span(e)
        return u1 - u0

    def epsilon_s(self, e: float) -> tuple[float, float]:
        """Eq. 4: (ε_s per flow, ε_s all flows together) = φ1 i_s/2π, φ1 · flows · i_s / 2π."""
        p = self.phi1(e)
        return p * self.i_s / (2 * math.pi), p * self.i_s * self.flows / (2 * math.pi)

    def corner_pose(self, e: float) -> dict:
        """Eq. 1/3 at the exit pose: O1C, CD, β2 and the residuals of the rows, for eq. 3's corner C (the
        trailing tooth's driving corner) as it leaves the gear's tip circle (the report's and the tests'
        hand-worked check)."""
        d = self.tip_land()[0]
        u = self.corner_exit(e, d)
        a = self.center_distance(e)
        ox, oy = e * math.cos(u), e * math.sin(u)
        cx, cy = ox + self.r_a * math.cos(u - d), oy + self.r_a * math.sin(u - d)
        dist = abs(math.hypot(cx - a, cy) - self.r_a2)
        beta2 = math.atan2(cy, a - cx)  # angle at O2 between O2O1 and O2C
        o1c = math.hypot(cx, cy)
        return {"u_exit": u, "delta": d, "O1C": o1c, "CD": 2 * self.r_a * math.sin(d / 2), "beta2": beta2,
                "on_tip_circle": dist, "residuals": eq1_residuals(e, self.r_a, d, a, self.r_a2, beta2)}

    def max_offset(self, eps_min: float = EPS_S_MIN) -> float:
        """Largest offset e with ε_s (all flows, driving corners) ≥ eps_min (eq. 1/3 with the closing
        condition, eq. 4) at which both driving corners still reach the gear's tip circle (past it the
        leading tooth's outer corner passes outside that circle, ε_s is undefined)."""
        f = lambda e: self.epsilon_s(e)[1] - eps_min
        if f(0.0) < 0.0:
            raise InputError("z_c", self.z_c, f"eq. 4: ε_s = {self.epsilon_s(0.0)[1]:.4f} < {eps_min} already at "
                             f"e = 0; more teeth per sector or more sectors are needed")
        def g(e):
            try:
                return f(e)
            except InputError:  # the driving corners no longer reach the gear's tip circle
                return -1.0

        lo, step = 0.0, self.m
        while g(lo + step) > 0.0:
            lo += step
            require(lo < 100.0 * self.r, "offset", lo, "no largest offset found")
        return brentq(g, lo, lo + step, xtol=1e-10)

    def flank_overlap_one_flow(self) -> float:
        """(z_c − 1 + ε_α)/(z_c + k): one flow's flank-contact overlap at e = 0 (< 1 for any
        external spur mesh; why the second flow is needed)."""
        ea = epsilon_alpha_pair(self.z, self.z2, self.m, self.alpha)
        return (self.z_c - 1 + ea) / (self.z_c + self.k_gap)

    # --- eq. 5-8 ----------------------------------------------------------------------------
    def ratio_flank(self, e: float, u) -> np.ndarray:
        """i_t of a flank contact (eq. 7 with the pole of :func:`pole_flank`)."""
        a = self.center_distance(e)
        o2p, _ = pole_flank(e, u, self.r_b, self.r_b2, a)
        alpha_wt = np.arccos(np.clip(self.r_b2 / o2p, -1.0, 1.0))
        return ratio_eq7(self.r2, a, self.alpha, alpha_wt)

    def alpha_wt_flank(self, e: float, u) -> np.ndarray:
        a = self.center_distance(e)
        o2p, _ = pole_flank(e, u, self.r_b, self.r_b2, a)
        return np.arccos(np.clip(self.r_b2 / o2p, -1.0, 1.0))


# --- eq. 15-22: tooth position error ---------------------------------------------------------
def _flank_angle(rho: float, r_b: float, half_pitch_angle: float, alpha: float) -> float:
    """Angle from a tooth's centre line to its flank at radius rho about the gear's own centre:
    π/(2z) + inv α − inv α_ρ (eq. 15–17: ψ = π/(2z), φ = ψ + inv α at the base circle)."""
    return half_pitch_angle + inv(alpha) - inv(math.acos(min(1.0, r_b / rho)))


def tooth_position_error(m: float, z: int, z_c: int, e: float, alpha: float, r_y: float) -> list[dict]:
    """Eq. 15–22: for each tooth n of the sector (n = 0 … z_c − 1, centred on the mid-line) and its
    right (+1) and left (−1) flank, the points where the sector's flank and the conditional gear's
    flank cross the circle of radius r_y about the wheel axis O1, in the frame X, Y of eq. 18–19
    (origin O' = centre of the sector's pitch arc, Y along the mid-line towards M), their distance
    R (eq. 21) and the angle β of the line joining them to the X axis (eq. 22).

    Conditional gear (eq. 15–19): z_усл = 2(r + e)/m teeth about O1, flank at angle
    π/(2 z_усл) + inv α − inv α_y from its tooth's centre line, tooth n's centre line at
    (n − (z_c − 1)/2)·2π/z_усл from the mid-line; shifted to the X, Y frame by −e along Y (eq. 19,
    read as y = r_y cos(·) − (r_усл − r): the printed "sin" and "− r_усл − r" do not put the point
    on the circle).  Sector (eq. 20): the involute of the blank in the frame X'O'Y' whose Y' axis
    passes through the flank's base-circle point, x' = ∓r_b (sin t − t cos t),
    y' = r_b (cos t + t sin t), rotated by A = π/(2z) + inv α into X O' Y; the point at distance r_y
    from O1 found by root search on t.  Returns rows with NaN where a flank does not reach r_y.
    """
    r = m * z / 2.0
    r_b = r * math.cos(alpha)
    r_cond = r + e
    z_cond = 2.0 * r_cond / m
    r_b_cond = r_cond * math.cos(alpha)
    r_a = r + m
    A = math.pi / (2 * z) + inv(alpha)
    rows = []
    for n in range(z_c):
        off = n - (z_c - 1) / 2.0
        for side in (1, -1):
            # conditional gear (about O1), eq. 18-19
            if r_y >= r_b_cond:
                th = off * 2 * math.pi / z_cond + side * _flank_angle(r_y, r_b_cond, math.pi / (2 * z_cond), alpha)
                xc, yc = r_y * math.sin(th), r_y * math.cos(th) - e
            else:
                xc = yc = math.nan
            # sector (about O'), eq. 20: flank of tooth n, its base point at angle c_n + side·A

            def point(t):
                xp = -side * r_b * (math.sin(t) - t * math.cos(t))
                yp = r_b * (math.cos(t) + t * math.sin(t))
                ang = off * 2 * math.pi / z + side * A  # clockwise rotation of the frame by this angle
                ca, sa = math.cos(ang), math.sin(ang)
                return xp * ca + yp * sa, yp * ca - xp * sa

            t_max = math.sqrt((r_a / r_b) ** 2 - 1.0)
            f = lambda t: math.hypot(*(np.add(point(t), (0.0, e)))) - r_y
            if f(0.0) < 0.0 < f(t_max):
                t = brentq(f, 0.0, t_max, xtol=1e-14)
                xs, ys = point(t)
            else:
                xs = ys = math.nan
            R = math.hypot(xc - xs, yc - ys)
            beta = math.atan2(yc - ys, xc - xs) if math.isfinite(R) else math.nan
            rows.append({"tooth": n + 1, "flank": "right" if side > 0 else "left", "r_y": r_y, "x_cond": xc,
                         "y_cond": yc, "x_sector": xs, "y_sector": ys, "R": R, "beta": beta})
    return rows
