"""Closed tooth outlines of the non-circular walking-drive pair (seeds 000 and 002).

numpy/scipy only.  Millimetres, radians.  Two tooth methods:

**Generated (conjugate) teeth** (SPEC §3.2, Litvin & Fuentes-Aznar, *Noncircular Gears*, 2009,
ch. 4 and 6).  Both pitch curves are parametrised by the driven angle phi and share ONE
arc-length frame s(phi) = integral sqrt(r_H^2 + r_H'^2) dphi (SPEC Trap 3; rolling without
slip: the driver's arc over the same phi is equal).  An ISO 53 rack cutter rolls on each
pitch curve (``gears.generation.envelope_points``: meshing equation solved in closed form per
cutter point), the driver's tool shifted by +x m, the driven wheel's by -x m (one imaginary
rack between the two centrodes: its reference line is x m off both pitch curves, so the
generated pair keeps the centre distance and is conjugate: at each instant the two tool
flanks touch the gears at the same point of the line of action through the pitch point).
Tooth k of the driver is centred at s = k p, tooth k of the driven wheel at s = (k + 1/2) p,
p = pi m: the pair is phased by construction.  Where a pitch curve is concave (or within
``SHAPER_MARGIN_PITCHES`` pitches of a concave stretch) the side is cut by a shaper (pinion)
cutter z0 rolling on the outside of the pitch curve with its pitch circle, profile shift
x0 = -x_gear (it meshes with the same imaginary rack, so its involute generates the same
flank; only the fillet differs).  Tip and root are the equidistants of the pitch curve at
(h_a* + x) m and (h_a* + c* - x) m (the envelope of the tool's tip land, resp. the shaper's
tip circle); tips are shortened tooth by tooth where the tip land would be thinner than a
given minimum.  Undercut is detected per tooth side (cusp of the flank envelope) and trimmed.
Every piece is fitted by a clamped cubic B-spline within ``policy.SPLINE_FIT_TOL_MM``.

**Sector teeth** (the papers' method, seed 000 eqs. 16-52 and seed 002 Tables 2-4, see
``gears.sectors``): each sector is a piece of a circular gear of radius r_k with one driver
tooth / one driven space, involute flanks with the papers' base radius r_b = r - m from r_b
to the tip r + m, a radial flank foot down to the root r - 1.25 m, backlash as the angular
correction j_n / (4 r_b) per flank.  Transitions the papers leave open are closed as follows
(ours): a driven-wheel tooth between spaces i and i+1 has the tip radius of sector i+1 (the
papers' 6th point of Table 4 extends the flank of space i to it); a driver space straddling
two sectors has a root whose radius passes from r_f(i) to r_f(i+1) by the quintic smoothstep
6t^5 - 15t^4 + 10t^3 of the angle across the space (C2 in the angle).

Body frames (the pair's assembly frame at phi = theta = 0): the driven wheel's axis at the
origin, its pitch point of polar angle phi is the contact point when the driven wheel has
turned by -phi (clockwise); the driver's axis at its own origin (at (L, 0) in the assembly),
the pitch point of law angle theta sits at body polar angle pi - theta (contact on the line
of centres when the driver has turned by +theta, counter-clockwise).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import fsolve

from ..errors import InputError, require
from ..gears.generation import (ArcPiece, EnvelopeCurve, LinePiece, RackCentrode, ShaperCutter, envelope_points,
                                nearer_circle_crossing, trim_crossing)
from ..gears.involute import BasicRack
from ..gears.noncircular import PitchCurves, _leg_breakpoints
from ..gears.sectors import SectorTable, involute
from ..laws.walking import LEG_PERIOD
from ..policy import SPLINE_FIT_TOL_MM
from .bspline import fit_curve
from .profile import Arc, Line, Loop, Profile, Spline

__all__ = [
    "ArcFrame", "PitchCurve", "ToothSpec", "GeneratedGear", "generate_gear",
    "SectorGear", "sector_driver_gear", "sector_driven_gear", "sector_tip_thickness",
    "SHAPER_MARGIN_PITCHES",
]

_GX, _GW = np.polynomial.legendre.leggauss(10)
#: initial interpolation points of every spline fit (refined adaptively to the tolerance):
#: few knots keep the tessellation of the solids (OCCT meshes every knot span) and the DXF light
_FIT_N0 = 8


def _fit(func, u0, u1, tol):
    return fit_curve(func, u0, u1, tol, n0=_FIT_N0)
#: a tooth side is cut by the shaper when a concave stretch of its pitch curve lies within this
#: many pitches of the tooth centre (the rack's neighbouring teeth would gouge there)
SHAPER_MARGIN_PITCHES = 1.5


# =========================================================================== arc-length frame
class ArcFrame:
    """Shared arc length s(phi) of the pair's pitch curves, s(0) = 0 (SPEC Trap 3: true arc
    length ds = sqrt(r_H^2 + r_H'^2) dphi, seed 000 eq. 12 for r_H).  Periodic per leg:
    s(phi + pi/2) = s(phi) + leg.  Tabulated on one leg (nodes at the law's breakpoints, the
    ends of the C2 blend windows) by 10-point Gauss-Legendre; s(phi) and its inverse phi(s)
    are evaluated by cubic Hermite interpolation with the exact slopes ds/dphi, dphi/ds
    (interpolation error ~1e-11 rad with the default node density, see the tests)."""

    def __init__(self, pc: PitchCurves, per_piece: int = 400):
        from scipy.interpolate import CubicHermiteSpline

        self.pc = pc
        bp = _leg_breakpoints(pc.law)
        nodes = np.unique(np.concatenate([np.linspace(a, b, per_piece + 1) for a, b in zip(bp[:-1], bp[1:])]))
        self.nodes = nodes
        seg = self._gauss(nodes[:-1], nodes[1:])
        S = np.concatenate([[0.0], np.cumsum(seg)])
        j0 = int(np.searchsorted(nodes, 0.0, side="right") - 1)
        S0 = S[j0] + float(self._gauss(np.array([nodes[j0]]), np.array([0.0]))[0])
        self.S = S - S0
        self.leg = float(S[-1])
        self.perimeter = 4.0 * self.leg
        g = pc.ds_dphi(nodes)
        self._s_of = CubicHermiteSpline(nodes, self.S, g)
        self._phi_of = CubicHermiteSpline(self.S, nodes, 1.0 / g)

    def _gauss(self, a, b):
        a = np.asarray(a, float)
        b = np.asarray(b, float)
        x = 0.5 * (b - a)[:, None] * _GX[None, :] + 0.5 * (a + b)[:, None]
        f = self.pc.ds_dphi(x.ravel()).reshape(x.shape)
        return 0.5 * (b - a) * (f @ _GW)

    def s_exact(self, phi):
        """s(phi) by quadrature from the nearest node below (reference for the interpolant)."""
        phi = np.atleast_1d(np.asarray(phi, float))
        k = np.floor((phi + math.pi / 4) / LEG_PERIOD)
        w = phi - k * LEG_PERIOD
        j = np.clip(np.searchsorted(self.nodes, w, side="right") - 1, 0, len(self.nodes) - 2)
        return self.S[j] + self._gauss(self.nodes[j], w) + k * self.leg

    def s(self, phi):
        phi = np.atleast_1d(np.asarray(phi, float))
        k = np.floor((phi + math.pi / 4) / LEG_PERIOD)
        return self._s_of(phi - k * LEG_PERIOD) + k * self.leg

    def phi(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        k = np.floor((s - self.S[0]) / self.leg)
        return self._phi_of(s - k * self.leg) + k * LEG_PERIOD


# =========================================================================== pitch curves in body frames
class PitchCurve:
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
        r, a = self.polar(phi)
        return np.column_stack([r * np.cos(a), r * np.sin(a)])

    def dpoint(self, phi):
        """dP/dphi."""
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
        d = self.sgn * self.dpoint(phi)
        d = d / np.linalg.norm(d, axis=1)[:, None]
        return np.column_stack([-d[:, 1], d[:, 0]])

    def offset(self, phi, h):
        """Equidistant at height h (outwards > 0) - the tip (h > 0) and root (h < 0) curves."""
        return self.point(phi) + h * self.normal(phi)

    def rho(self, phi):
        """Signed radius of curvature (> 0 convex) at the pitch point of driven angle phi."""
        return self.pc.rho_H(phi) if self.role == "driven" else self.pc.rho(phi)


class _Centrode:
    """Gear centrode for ``envelope_points``: the pitch curve run clockwise on the body from
    the tooth centre s_k by the generation arc sg (gear on the right of travel)."""

    def __init__(self, curve: PitchCurve, frame: ArcFrame, s_k: float):
        self.curve, self.frame, self.s_k = curve, frame, float(s_k)
        self._key = None

    def phi(self, sg):
        sg = np.atleast_1d(np.asarray(sg, float))
        if self._key is not None and self._key[0] is sg:
            return self._key[1]
        ph = self.frame.phi(self.s_k + self.curve.sgn * sg)
        self._key = (sg, ph)
        return ph

    def point(self, sg):
        return self.curve.point(self.phi(sg))

    def angle(self, sg):
        d = self.curve.sgn * self.curve.dpoint(self.phi(sg))
        return np.arctan2(d[:, 1], d[:, 0])


# =========================================================================== cutters
@dataclass(frozen=True)
class ExternalCircleCentrode:
    """Rolling circle of a shaper cutter outside the gear: centre (0, R) in the cutter frame,
    touching the rolling line y = 0 at the origin at s = 0, C(s) = (R sin(s/R), R - R cos(s/R)),
    tangent angle s/R (the cutter frame of ``RackCentrode`` with the line bent into a circle)."""

    R: float

    def point(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        return np.column_stack([self.R * np.sin(s / self.R), self.R - self.R * np.cos(s / self.R)])

    def angle(self, s):
        return np.atleast_1d(np.asarray(s, float)) / self.R

    def contact(self, P, N):
        """Meshing equation: the normal P + lam N meets the rolling circle; the crossing nearer
        to P is the pitch point (involute: contact and pitch point on one ray of the line of action)."""
        C = nearer_circle_crossing(P, N, (0.0, self.R), self.R, "shaper_teeth", "shaper's")
        return self.R * np.arctan2(C[:, 0], self.R - C[:, 1])


@dataclass(frozen=True)
class _Placed:
    """A cutter-outline piece rotated by ``angle`` about the origin, shifted by ``offset``,
    then mirrored x -> -x if ``mirror``."""

    piece: object
    angle: float = 0.0
    offset: tuple = (0.0, 0.0)
    mirror: bool = False

    def _rot(self, v):
        c, s = math.cos(self.angle), math.sin(self.angle)
        out = np.column_stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]])
        return out

    def point(self, u):
        p = self._rot(self.piece.point(u)) + np.asarray(self.offset, float)[None, :]
        return p * np.array([-1.0, 1.0]) if self.mirror else p

    def tangent(self, u):
        t = self._rot(self.piece.tangent(u))
        return t * np.array([-1.0, 1.0]) if self.mirror else t


@dataclass(frozen=True)
class _SideTool:
    """The pieces generating one tooth side: (fillet piece, range), (flank piece, range), centrode."""

    fillet: object
    fillet_range: tuple
    flank: object
    flank_range: tuple
    cutter: object
    kind: str  # "rack" | "shaper"


@dataclass(frozen=True)
class ToothSpec:
    """Teeth of one gear of the pair.

    m: module (mm); x: profile shift coefficient; thinning_mm: arc tooth-thickness reduction on
    the pitch curve (a normal backlash j_n split evenly is j_n / (2 cos alpha) per gear);
    rack: ISO 53 basic rack; z0: shaper teeth for concave stretches (None: none allowed);
    tip_min_mm: least tip-land thickness before the tip is shortened; tip_floor: the tip may be
    shortened down to (tip_floor + x) m above the pitch curve, else the teeth are pointed
    (InputError)."""

    m: float
    x: float = 0.0
    thinning_mm: float = 0.0
    rack: BasicRack = BasicRack()
    z0: int | None = None
    tip_min_mm: float = 0.0
    tip_floor: float = 0.5

    @property
    def h_tip(self) -> float:
        return (self.rack.h_a_star + self.x) * self.m

    @property
    def h_root(self) -> float:
        return (self.rack.h_fP_star - self.x) * self.m

    def rack_tools(self) -> tuple[_SideTool, _SideTool]:
        """Right (+xi, clockwise side of the tooth) and left tools of the ISO 53 rack (as in
        ``generation.generate_external_side``, tool space of width w - thinning centred at xi = 0)."""
        rk, m, x = self.rack, self.m, self.x
        a = rk.alpha
        sa, ca, ta = math.sin(a), math.cos(a), math.tan(a)
        w = m * (math.pi / 2 + 2.0 * x * ta) - self.thinning_mm
        rho = rk.rho_f_star * m
        eta_t = -(rk.h_fP_star - x) * m
        eta_f = eta_t + rho * (1.0 - sa)
        xi_c = w / 2.0 - eta_f * ta + rho * ca
        require(xi_c <= math.pi * m / 2.0 + 1e-12, "rho_f_star", rk.rho_f_star, "tool tip rounds overlap (no tip land)")
        u_f = eta_f / ca
        u_top = (1.5 * (rk.h_a_star + abs(x)) + 0.5) * m / ca
        cut = RackCentrode()
        right = _SideTool(ArcPiece((xi_c, eta_t + rho), rho), (-math.pi / 2, -(math.pi - a)),
                          LinePiece((w / 2.0, 0.0), (-sa, ca)), (u_f, u_top), cut, "rack")
        left = _SideTool(ArcPiece((-xi_c, eta_t + rho), rho), (-math.pi / 2, -a),
                         LinePiece((-w / 2.0, 0.0), (sa, ca)), (u_f, u_top), cut, "rack")
        return right, left

    def shaper_tools(self) -> tuple[_SideTool, _SideTool]:
        """Right and left tools of the shaper z0 (x0 = -x: it meshes with the same imaginary
        rack), its space centred on the bottom of its rolling circle; thinning widens the
        shaper teeth by thinning/(2 r0) of rotation per flank."""
        require(self.z0 is not None, "shaper_teeth", self.z0, "a concave pitch curve needs a shaper cutter")
        try:
            sh = ShaperCutter(int(self.z0), self.m, -self.x, self.rack)
            R0 = sh.r0
            t_s, c, a_flank, a_tip = sh.tip_round
        except InputError as exc:
            raise InputError("shaper_teeth", self.z0,
                             f"the shaper z0 = {self.z0} with x0 = {-self.x:+g} (-x of the gear it cuts) cannot be made: "
                             f"{exc}", "use a smaller profile shift (driver_shift) or another shaper") from None
        ang = -math.pi + math.pi / sh.z0 - self.thinning_mm / (2.0 * R0)
        cut = ExternalCircleCentrode(R0)
        rnd = ArcPiece(c, sh.rho_a0_star * self.m)
        out = []
        for mir in (False, True):
            out.append(_SideTool(_Placed(rnd, ang, (0.0, R0), mir), (a_tip, a_flank),
                                 _Placed(sh.involute, ang, (0.0, R0), mir), (t_s, 1e-9), cut, "shaper"))
        return tuple(out)


# =========================================================================== one generated side
@dataclass
class _Side:
    fillet: EnvelopeCurve
    flank: EnvelopeCurve
    kind: str
    undercut: bool
    phi_root: float  # driven angle of the pitch point generating the fillet start (on the root curve)


def _flank_has_cusp(flank: EnvelopeCurve, u1: float, n: int = 48) -> bool:
    P = flank(np.linspace(flank.u0, u1, n))
    d = np.diff(P, axis=0)
    return bool(np.any(np.einsum("ij,ij->i", d[:-1], d[1:]) < 0))


def _make_side(tool: _SideTool, cen: _Centrode) -> _Side:
    fil = EnvelopeCurve(tool.fillet, tool.cutter, cen, *tool.fillet_range, "fillet")
    fla = EnvelopeCurve(tool.flank, tool.cutter, cen, *tool.flank_range, "flank")
    _, s0 = envelope_points(tool.fillet, np.array([fil.u0]), tool.cutter, cen)
    return _Side(fil, fla, tool.kind, False, float(cen.phi(s0)[0]))


def _trim_undercut(side: _Side, u_tip: float) -> None:
    """Undercut (SPEC §3.2, 'undercut per tooth'): the flank envelope below the tip turns back
    (cusp) and the fillet trochoid crosses it; keep the outer boundary (``trim_crossing``)."""
    if not _flank_has_cusp(side.flank, u_tip):
        return
    cross = trim_crossing(side.fillet, side.flank.with_range(side.flank.u0, u_tip))
    if cross is not None:
        side.fillet = side.fillet.with_range(side.fillet.u0, cross[0])
        side.flank = side.flank.with_range(cross[1], side.flank.u1)
        side.undercut = True


def _tip_hit(side: _Side, curve: PitchCurve, h: float, phi_guess: float, span: float):
    """(u, phi) where the flank meets the tip equidistant at height h (None if it does not within
    the flank's range): nearest pair of samples, then fsolve."""
    fla = side.flank
    u = np.linspace(fla.u0, fla.u1, 41)
    X = fla(u)
    ph = phi_guess + np.linspace(-0.6, 0.6, 121) * span
    T = curve.offset(ph, h)
    D = np.linalg.norm(X[:, None, :] - T[None, :, :], axis=2)
    i, j = np.unravel_index(int(np.argmin(D)), D.shape)
    g = lambda y: fla.at(y[0]) - curve.offset(np.array([y[1]]), h)[0]
    sol = fsolve(g, [u[i], ph[j]], xtol=1e-14, full_output=True)[0]
    if np.linalg.norm(g(sol)) > 1e-9 or not (min(fla.u0, fla.u1) - 1e-9 <= sol[0] <= max(fla.u0, fla.u1) + 1e-9):
        return None
    return float(sol[0]), float(sol[1])


class _BatchCentrode(_Centrode):
    """_Centrode of many teeth at once: s_k is an array matching the generation arcs passed in."""


def _tip_hits_batch(sides: list, s_k: np.ndarray, ph_k: np.ndarray, curve: PitchCurve, frame: ArcFrame,
                    h: float, span: float) -> list:
    """``_tip_hit`` for many sides at once (grouped by their cutter piece): vectorised sampling for
    the start and a vectorised Newton iteration on (u, phi); sides that do not converge fall back
    to ``_tip_hit``."""
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
            cen = _BatchCentrode(curve, frame, 0.0)
            cen.s_k = skk
            return envelope_points(fla.piece, u, fla.cutter, cen)[0]

        ug = np.linspace(u0, u1, nu)
        Xs = X(np.tile(ug, n), np.repeat(sk, nu)).reshape(n, nu, 2)
        pg = pk[:, None] + np.linspace(-0.6, 0.6, nph)[None, :] * span
        Ts = curve.offset(pg.ravel(), h).reshape(n, nph, 2)
        D = np.linalg.norm(Xs[:, :, None, :] - Ts[:, None, :, :], axis=3).reshape(n, -1)
        k = np.argmin(D, axis=1)
        u = ug[k // nph]
        ph = pg[np.arange(n), k % nph]
        eu, ep = 1e-7 * max(1.0, abs(u1 - u0)), 1e-8
        for _ in range(12):
            Xu = X(u, sk)
            T = curve.offset(ph, h)
            G = Xu - T
            if np.max(np.linalg.norm(G, axis=1)) < 1e-12:
                break
            dX = (X(u + eu, sk) - Xu) / eu
            dT = (curve.offset(ph + ep, h) - T) / ep
            det = dX[:, 0] * (-dT[:, 1]) - dX[:, 1] * (-dT[:, 0])
            det = np.where(np.abs(det) > 1e-300, det, 1e-300)
            du = -(G[:, 0] * (-dT[:, 1]) - G[:, 1] * (-dT[:, 0])) / det
            dp = -(dX[:, 0] * G[:, 1] - dX[:, 1] * G[:, 0]) / det
            u, ph = u + du, ph + dp
        res = np.linalg.norm(X(u, sk) - curve.offset(ph, h), axis=1)
        for j, i in enumerate(idx):
            if res[j] <= 1e-9 and min(u0, u1) - 1e-9 <= u[j] <= max(u0, u1) + 1e-9:
                out[i] = (float(u[j]), float(ph[j]))
            else:
                out[i] = _tip_hit(sides[i], curve, h, float(pk[j]), span)
    return out




def _arc_len(curve: PitchCurve, h: float, a: float, b: float) -> float:
    x = 0.5 * (b - a) * _GX + 0.5 * (a + b)
    ph = x
    # |d/dphi (P + h n)| by central differences of the exact equidistant (h small vs rho)
    eps = 1e-6
    d = (curve.offset(ph + eps, h) - curve.offset(ph - eps, h)) / (2 * eps)
    return abs(0.5 * (b - a) * float(np.dot(_GW, np.linalg.norm(d, axis=1))))


# =========================================================================== generated gear
@dataclass
class GeneratedTooth:
    s_centre: float
    phi_centre: float
    right: str
    left: str
    undercut: bool
    tip_height_mm: float
    tip_thickness_mm: float
    shortened: bool


@dataclass
class GeneratedGear:
    """A generated non-circular gear: its profile and the per-tooth record."""

    role: str
    profile: Profile
    teeth: list
    root_min_radius: float
    pitch_points: np.ndarray  # (n, 2) pitch curve in the body frame (reference)

    @property
    def undercut_teeth(self) -> int:
        return sum(t.undercut for t in self.teeth)

    @property
    def shortened_teeth(self) -> int:
        return sum(t.shortened for t in self.teeth)

    @property
    def shaper_teeth(self) -> int:
        return sum(t.right == "shaper" or t.left == "shaper" for t in self.teeth)

    @property
    def tip_thickness_min(self) -> float:
        return min(t.tip_thickness_mm for t in self.teeth)


def _concave_zones(curve: PitchCurve) -> list[tuple[float, float]]:
    """Concave stretches of the pitch curve as intervals of the driven angle (all legs, one turn)."""
    side = "driven" if curve.role == "driven" else "driver"
    cs = curve.pc.curvature(side)
    out = []
    for a, b in cs.concave_intervals:
        for k in range(-1, 6):
            out.append((a + k * LEG_PERIOD, b + k * LEG_PERIOD))
    return out


def generate_gear(pc: PitchCurves, role: str, spec: ToothSpec, frame: ArcFrame | None = None,
                  tol: float = SPLINE_FIT_TOL_MM) -> GeneratedGear:
    """Generated teeth on the pitch curve of one gear of the pair (see the module docstring).

    Teeth: driven z_H = perimeter / (pi m), centres at s = (k + 1/2) p; driver z = z_H / n,
    centres at s = k p (k = 0 .. z-1 covers the driver's first turn, phi in [0, 2 pi / n)).
    """
    frame = frame or ArcFrame(pc)
    curve = PitchCurve(pc, role)
    m = spec.m
    p = math.pi * m
    n = pc.law.n
    z_H = frame.perimeter / p
    require(abs(z_H - round(z_H)) < 1e-6, "module_mm", m,
            f"the driven pitch curve ({frame.perimeter:.6f} mm) holds {z_H:.6f} pitches, not a whole number")
    z_H = int(round(z_H))
    if role == "driven":
        z, centres = z_H, (np.arange(z_H) + 0.5) * p
    else:
        require(z_H % n == 0, "driven_teeth", z_H, f"must be a multiple of n = {n}")
        z, centres = z_H // n, np.arange(z_H // n) * p
    phic = frame.phi(centres)
    span = 1.5 * p / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))  # phi of 1.5 pitches
    zones = _concave_zones(curve)
    rack_r, rack_l = spec.rack_tools()
    shaper = None
    teeth_sides = []
    for s_k, ph_k in zip(centres, phic):
        sides = []
        for which, rack_tool in ((0, rack_r), (1, rack_l)):
            tool = rack_tool
            if zones:
                margin = SHAPER_MARGIN_PITCHES * p
                for a, b in zones:
                    sa_, sb_ = frame.s(np.array([a, b]))
                    if sa_ - margin <= s_k <= sb_ + margin:
                        if shaper is None:
                            shaper = spec.shaper_tools()
                        tool = shaper[which]
                        break
            sides.append(_make_side(tool, _Centrode(curve, frame, s_k)))
        teeth_sides.append(sides)

    # tips: nominal height, shortened where the tip land is too thin
    teeth, tips = [], []
    flat = [sd for pair in teeth_sides for sd in pair]
    nominal = _tip_hits_batch(flat, np.repeat(centres, 2), np.repeat(phic, 2), curve, frame, spec.h_tip, span)
    for k, ((s_k, ph_k), (R, Lf)) in enumerate(zip(zip(centres, phic), teeth_sides)):
        def hits(h, k=k):
            if h == spec.h_tip:
                return nominal[2 * k], nominal[2 * k + 1]
            return _tip_hit(R, curve, h, ph_k, span), _tip_hit(Lf, curve, h, ph_k, span)

        def thickness(h):
            hr, hl = hits(h)
            if hr is None or hl is None:
                return -1.0, hr, hl
            # right side is clockwise: generation arc sg > 0; left sg < 0
            sg_r = curve.sgn * (frame.s(np.array([hr[1]]))[0] - s_k)
            sg_l = curve.sgn * (frame.s(np.array([hl[1]]))[0] - s_k)
            t = _arc_len(curve, h, hl[1], hr[1])
            return (t if sg_r > sg_l else -t), hr, hl

        h = spec.h_tip
        t, hr, hl = thickness(h)
        shortened = False
        if t < spec.tip_min_mm:
            # tip shortening: the largest height (bisection to 1 nm) with a tip land >= the minimum
            h_lo = (spec.tip_floor + spec.x) * m
            t_lo, hr_lo, hl_lo = thickness(h_lo)
            if not t_lo >= spec.tip_min_mm:
                why = (f"the {'shaper' if 'shaper' in (R.kind, Lf.kind) else 'rack'} flank envelope does not reach "
                       f"{spec.tip_floor + spec.x:.2f} m above the pitch curve (generating limit of the cutter)"
                       if hr_lo is None or hl_lo is None else
                       f"tip land {max(t_lo, 0.0):.3f} mm < {spec.tip_min_mm:.3f} mm even with the tip shortened to "
                       f"{spec.tip_floor + spec.x:.2f} m")
                raise InputError(
                    "module_mm", m, f"{role} tooth at phi = {ph_k:.4f} rad is pointed or cannot be cut: {why}",
                    "use a smaller profile shift, a larger shaper, more teeth or a wider smoothing")
            lo, hi = h_lo, h
            best = (t_lo, hr_lo, hl_lo)
            while hi - lo > 1e-6:
                mid = 0.5 * (lo + hi)
                res = thickness(mid)
                if res[0] >= spec.tip_min_mm:
                    lo, best = mid, res
                else:
                    hi = mid
            h = lo
            t, hr, hl = best
            shortened = True
        _trim_undercut(R, hr[0])
        _trim_undercut(Lf, hl[0])
        tips.append((h, hr, hl))
        teeth.append(GeneratedTooth(float(s_k), float(ph_k), R.kind, Lf.kind, R.undercut or Lf.undercut,
                                    float(h), float(t), shortened))

    # fit and chain (counter-clockwise on the body: increasing polar angle)
    order = list(range(z)) if role == "driven" else list(range(z - 1, -1, -1))
    units = []
    for k in order:
        R, Lf = teeth_sides[k]
        h, hr, hl = tips[k]
        fil_r = _fit(R.fillet, R.fillet.u0, R.fillet.u1, tol)
        fla_r = _fit(R.flank, R.flank.u0, hr[0], tol)
        tip = _fit(lambda ph: curve.offset(ph, h), hr[1], hl[1], tol)
        fla_l = _fit(Lf.flank, hl[0], Lf.flank.u0, tol)
        fil_l = _fit(Lf.fillet, Lf.fillet.u1, Lf.fillet.u0, tol)
        units.append(([fil_r, fla_r, tip, fla_l, fil_l], R.phi_root, Lf.phi_root))
    segs = []
    root_r = []
    hf = -spec.h_root
    for i, (unit, _phr, phl) in enumerate(units):
        segs.extend(unit)
        nxt = units[(i + 1) % len(units)]
        ph_a, ph_b = phl, nxt[1]
        # unwrap: the next tooth's right root point follows counter-clockwise
        if role == "driven":
            while ph_b < ph_a:
                ph_b += 2 * math.pi
        else:  # driver: counter-clockwise = decreasing phi; one driver turn = 2 pi / n of phi
            while ph_b > ph_a:
                ph_b -= 2 * math.pi / n
        root = _fit(lambda ph: curve.offset(ph, hf), ph_a, ph_b, tol)
        root_r.append(float(np.min(np.linalg.norm(root.poles, axis=1))))
        segs.append(root)
    segs = _snap(segs)
    prof = Profile(Loop(segs), name=f"{role} generated z={z} m={m:g}")
    ph = np.linspace(0.0, 2 * math.pi / (1 if role == "driven" else n), 1441)
    return GeneratedGear(role, prof, teeth, min(root_r), curve.point(ph))


def _snap(segs: list, tol: float = 1e-6) -> list:
    """Make consecutive splines share their end points exactly (they agree to ~1e-9 mm)."""
    out = []
    for i, s in enumerate(segs):
        prev = segs[i - 1]
        gap = float(np.linalg.norm(prev.end - s.start))
        if gap > tol:
            raise RuntimeError(f"outline pieces {i - 1} and {i} do not meet: gap {gap:.3g} mm")
        P = s.poles.copy()
        P[0] = prev.end
        out.append(Spline(s.knots, P, s.degree))
    return out


# =========================================================================== sector teeth
@dataclass
class SectorGear:
    role: str
    profile: Profile
    tip_thickness_min: float
    root_min_radius: float


def _legs(table: SectorTable, role: str) -> list[int]:
    n = table.law.n
    return list(range(4)) if role == "driven" else list(range(4 // n))


def _flank_fun(r_b: float, base: float, sign: float):
    """Involute flank of base r_b as a function of the roll parameter t: polar angle base + sign*(t - atan t)."""
    def f(t):
        t = np.atleast_1d(np.asarray(t, float))
        r = r_b * np.sqrt(1.0 + t * t)
        a = base + sign * (t - np.arctan(t))
        return np.column_stack([r * np.cos(a), r * np.sin(a)])
    return f


def _t_of_r(r_b: float, r: float) -> float:
    return math.sqrt(max((r / r_b) ** 2 - 1.0, 0.0))


def _polar_pt(r, a):
    return (float(r * math.cos(a)), float(r * math.sin(a)))


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


def sector_driver_gear(table: SectorTable, m: float, j_n: float, tol: float = SPLINE_FIT_TOL_MM) -> SectorGear:
    """Driver outline of the sector method (seed 002 Table 3 flanks), body frame of the module docstring."""
    n = table.law.n
    segs = []
    r_all = table.r
    feet = []  # per tooth: (first-flank foot angle, second-flank foot angle, r_f), in theta
    units = []
    for k in _legs(table, "driver"):
        shift = k * n * LEG_PERIOD
        for i in range(table.i):
            r = float(r_all[i])
            rb, rf, ra = r - m, r - 1.25 * m, r + m
            th, dth = float(table.theta[i]) + shift, float(table.dtheta[i])
            nu3 = float(involute(math.acos(rb / r)))
            d = j_n / (4 * rb)
            b1 = th + 0.25 * dth + d - nu3  # first flank: theta = b1 + nu(r)
            b2 = th + 0.75 * dth - d + nu3  # second flank: theta = b2 - nu(r)
            ta = _t_of_r(rb, ra)
            f1, f2 = _flank_fun(rb, b1, 1.0), _flank_fun(rb, b2, -1.0)
            a1 = b1 + ta - math.atan(ta)
            a2 = b2 - (ta - math.atan(ta))
            unit = [Line(_polar_pt(rf, b1), _polar_pt(rb, b1)), _fit(f1, 0.0, ta, tol),
                    Arc((0.0, 0.0), ra, a1, a2), _fit(f2, ta, 0.0, tol), Line(_polar_pt(rb, b2), _polar_pt(rf, b2))]
            units.append(unit)
            feet.append((b1, b2, rf, ra * (a2 - a1)))
    for j, unit in enumerate(units):
        segs.extend(unit)
        b1n = feet[(j + 1) % len(feet)][0] + (2 * math.pi if j + 1 == len(feet) else 0.0)
        a0, rf0 = feet[j][1], feet[j][2]
        rf1 = feet[(j + 1) % len(feet)][2]
        if abs(rf1 - rf0) < 1e-9:
            segs.append(Arc((0.0, 0.0), rf0, a0, b1n))
        else:
            def root(a, a0=a0, a1=b1n, r0=rf0, r1=rf1):
                a = np.atleast_1d(np.asarray(a, float))
                t = (a - a0) / (a1 - a0)
                rr = r0 + (r1 - r0) * t ** 3 * (10 - 15 * t + 6 * t * t)
                return np.column_stack([rr * np.cos(a), rr * np.sin(a)])
            segs.append(_fit(root, a0, b1n, tol))
    loop = Loop(segs)
    # theta frame -> driver body frame: beta = pi - theta, i.e. mirror x -> -x
    mir = Loop([_mirror_seg(s) for s in loop.segments])
    prof = Profile(mir, name=f"driver sectors i={table.i}")
    return SectorGear("driver", prof, float(min(f[3] for f in feet)), float(min(f[2] for f in feet)))


def _mirror_seg(s):
    if isinstance(s, Line):
        return Line((-s.p0[0], s.p0[1]), (-s.p1[0], s.p1[1]))
    if isinstance(s, Arc):
        return Arc((-s.center[0], s.center[1]), s.radius, math.pi - s.a0, math.pi - s.a1)
    return Spline(s.knots.copy(), s.poles * np.array([-1.0, 1.0]), s.degree)


def sector_driven_gear(table: SectorTable, m: float, j_n: float, tol: float = SPLINE_FIT_TOL_MM) -> SectorGear:
    """Driven-wheel outline of the sector method (seed 002 Table 4 spaces; the tooth between
    spaces i and i+1 reaches the tip radius r_H(i+1) + m, the papers' 6th point)."""
    rH = table.r_H
    spaces = []
    for k in range(4):
        shift = k * LEG_PERIOD
        for i in range(table.i):
            r = float(rH[i])
            rb, rf = r - m, r - 1.25 * m
            ph, dph = float(table.phi[i]) + shift, float(table.dphi[i])
            nu3 = float(involute(math.acos(rb / r)))
            d = j_n / (4 * rb)
            b1 = ph + 0.25 * dph - d + nu3  # first flank phi = b1 - nu(r)
            b2 = ph + 0.75 * dph + d - nu3  # second flank phi = b2 + nu(r)
            spaces.append((rb, rf, r + m, b1, b2))
    segs = []
    N = len(spaces)
    tmin, rfmin = math.inf, math.inf
    for j in range(N):
        rb, rf, ra, b1, b2 = spaces[j]
        rbn, rfn, ran, b1n, b2n = spaces[(j + 1) % N]
        if j + 1 == N:
            b1n += 2 * math.pi
        r_top = ran  # tip of the next sector (seed 002 Table 4, point 6)
        t_top = _t_of_r(rb, r_top)
        t_top_n = _t_of_r(rbn, ran)
        a_end = b2 + (t_top - math.atan(t_top))
        a_next = b1n - (t_top_n - math.atan(t_top_n))
        tmin = min(tmin, r_top * (a_next - a_end))
        rfmin = min(rfmin, rf)
        if j == 0:
            segs.append(_fit(_flank_fun(rb, b1, -1.0), _t_of_r(rb, ra), 0.0, tol))
            segs.append(Line(_polar_pt(rb, b1), _polar_pt(rf, b1)))
        segs.append(Arc((0.0, 0.0), rf, b1, b2))
        if r_top <= rf:
            raise InputError("driven_teeth", 4 * len(table.phi),
                             f"sector method: the tip radius of sector {(j + 1) % table.i + 1} ({r_top:.3f} mm) lies below "
                             f"the root of sector {j % table.i + 1} ({rf:.3f} mm): the driven notch is deeper than a tooth",
                             "use fewer sectors (a larger module) or the generated method")
        if r_top <= rb + 1e-9:  # the 6th point of Table 4 lies below the base circle: radial flank only
            segs.append(Line(_polar_pt(rf, b2), _polar_pt(r_top, b2)))
        else:
            segs.append(Line(_polar_pt(rf, b2), _polar_pt(rb, b2)))
            segs.append(_fit(_flank_fun(rb, b2, 1.0), 0.0, t_top, tol))
        segs.append(Arc((0.0, 0.0), r_top, a_end, a_next))
        if j + 1 < N:
            segs.append(_fit(_flank_fun(rbn, b1n, -1.0), t_top_n, 0.0, tol))
            segs.append(Line(_polar_pt(rbn, b1n), _polar_pt(rfn, b1n)))
    # the last tip arc ends where the first flank begins (a_first + 2 pi)
    prof = Profile(Loop(segs), name=f"driven sectors i={table.i}")
    return SectorGear("driven", prof, float(tmin), float(rfmin))
