"""Generating cutters: the one cutter type of the tooth generator.

Pure math (numpy/scipy).  Millimetres and radians.

A cutter outline is made of pieces (``LinePiece``, ``ArcPiece``, ``InvolutePiece``, each with
``point(u)`` and ``tangent(u)``); one side of a tool is a ``CutterSide``: the piece that generates
the fillet, the piece that generates the flank, their parameter ranges and the cutter's centrode
(``gears.envelope``).  Both tools make ``CutterSide`` objects, for circular and non-circular gears:

* ``RackCutter``: the ISO 53 basic rack (α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38) shifted by
  x·m away from the gear axis, its space of width w = m(π/2 + 2x tan α) − thinning centred on
  ξ = 0 of its rolling line (ISO 21771 eq. (61));
* ``ShaperCutter``: a pinion-type cutter z0, x0 (GOST 9323), inside a ring (GOST 19274) or outside
  a concave stretch of a non-circular pitch curve.

Tooth-thickness allowance ("thinning"): the reduction of the arc tooth thickness on the pitch
curve, the tooth-thickness deviation E_sn of ISO 21771 with its sign dropped.  Two mating gears
thinned by t1 and t2 have the normal backlash j_bn = (t1 + t2)·cos α; a normal backlash j_n split
evenly is j_n / (2 cos α) per gear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import brentq

from ..errors import require, require_finite, require_positive
from ..policy import INVOLUTE_T_MIN, ROUNDING_TOL, TOOL_TIP_LAND_TOL_MM
from .envelope import EnvelopeCurve, RackCentrode
from .involute import BasicRack, inv

__all__ = ["LinePiece", "ArcPiece", "InvolutePiece", "PlacedPiece", "CutterSide", "RackCutter", "ShaperCutter",
           "shaper_rack"]


@dataclass(frozen=True)
class LinePiece:
    """Straight piece of a cutter outline: P(u) = p0 + u·d (d unit vector)."""

    p0: tuple
    d: tuple

    def point(self, u):
        u = np.atleast_1d(np.asarray(u, float))
        return np.asarray(self.p0)[None, :] + u[:, None] * np.asarray(self.d)[None, :]

    def tangent(self, u):
        u = np.atleast_1d(np.asarray(u, float))
        return np.repeat(np.asarray(self.d, float)[None, :], len(u), axis=0)

    def point1(self, u: float) -> tuple[float, float]:
        """``point`` at one float u, as (x, y) floats (the same operations)."""
        return float(self.p0[0]) + u * float(self.d[0]), float(self.p0[1]) + u * float(self.d[1])

    def tangent1(self, u: float) -> tuple[float, float]:
        return float(self.d[0]), float(self.d[1])


@dataclass(frozen=True)
class ArcPiece:
    """Circular piece: P(a) = c + ρ(cos a, sin a), parameter a = polar angle about c."""

    c: tuple
    rho: float

    def point(self, a):
        a = np.atleast_1d(np.asarray(a, float))
        return np.column_stack([self.c[0] + self.rho * np.cos(a), self.c[1] + self.rho * np.sin(a)])

    def tangent(self, a):
        a = np.atleast_1d(np.asarray(a, float))
        return np.column_stack([-np.sin(a), np.cos(a)])

    def point1(self, a: float) -> tuple[float, float]:
        """``point`` at one float a, as (x, y) floats (the same operations; math.cos = np.cos here)."""
        return self.c[0] + self.rho * math.cos(a), self.c[1] + self.rho * math.sin(a)

    def tangent1(self, a: float) -> tuple[float, float]:
        return -math.sin(a), math.cos(a)


@dataclass(frozen=True)
class InvolutePiece:
    """Right flank (x > 0) of an involute tooth centred on the +y axis, roll parameter t = tan α_y.

    Radius r_y = r_b √(1+t²); polar angle from +y towards +x: ψ(t) = β − (t − atan t),
    β = half tooth angle on the base circle (= s/(2r) + inv α).  Tangent direction
    (sin ψ − t cos ψ, cos ψ + t sin ψ) (regular also at t = 0).
    """

    r_b: float
    beta: float

    #: a shaper's involute meshes with the ISO 53 rack: with its own x0 the shaper-on-line contact
    #: is exact on it (``envelope.ShaperOnRackCentrode``)
    conjugate_to_rack = True

    def point(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        r = self.r_b * np.sqrt(1.0 + t * t)
        psi = self.beta - (t - np.arctan(t))
        return np.column_stack([r * np.sin(psi), r * np.cos(psi)])

    def tangent(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        psi = self.beta - (t - np.arctan(t))
        return np.column_stack([np.sin(psi) - t * np.cos(psi), np.cos(psi) + t * np.sin(psi)])

    def point1(self, t: float) -> tuple[float, float]:
        """``point`` at one float t, as (x, y) floats (the same operations; numpy's arctan, which
        differs from math.atan)."""
        r = self.r_b * math.sqrt(1.0 + t * t)
        psi = self.beta - (t - float(np.arctan(t)))
        return r * math.sin(psi), r * math.cos(psi)

    def tangent1(self, t: float) -> tuple[float, float]:
        psi = self.beta - (t - float(np.arctan(t)))
        c, s = math.cos(psi), math.sin(psi)
        return s - t * c, c + t * s


@dataclass(frozen=True)
class PlacedPiece:
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

    @property
    def conjugate_to_rack(self) -> bool:
        return getattr(self.piece, "conjugate_to_rack", False)

    def _rot1(self, x: float, y: float) -> tuple[float, float]:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return c * x - s * y, s * x + c * y

    def point1(self, u: float) -> tuple[float, float]:
        """``point`` at one float u, as (x, y) floats (the same operations)."""
        x, y = self._rot1(*self.piece.point1(u))
        x, y = x + float(self.offset[0]), y + float(self.offset[1])
        return (x * -1.0, y * 1.0) if self.mirror else (x, y)

    def tangent1(self, u: float) -> tuple[float, float]:
        x, y = self._rot1(*self.piece.tangent1(u))
        return (x * -1.0, y * 1.0) if self.mirror else (x, y)



@dataclass(frozen=True)
class CutterSide:
    """One side of a generating tool: ``fillet`` piece over ``fillet_range`` (generates the
    fillet), ``flank`` piece over ``flank_range`` (generates the flank), ``cutter`` its centrode,
    ``kind`` "rack" or "shaper"."""

    fillet: object
    fillet_range: tuple
    flank: object
    flank_range: tuple
    cutter: object
    kind: str  # "rack" | "shaper"

    def envelopes(self, gear) -> tuple[EnvelopeCurve, EnvelopeCurve]:
        """(fillet, flank) generated on the gear centrode ``gear``."""
        return (EnvelopeCurve(self.fillet, self.cutter, gear, *self.fillet_range, "fillet"),
                EnvelopeCurve(self.flank, self.cutter, gear, *self.flank_range, "flank"))

    def placed(self, angle: float, offset: tuple, mirror: bool) -> "CutterSide":
        """The same side with both pieces rotated by ``angle``, shifted by ``offset``, then mirrored."""
        return CutterSide(PlacedPiece(self.fillet, angle, offset, mirror), self.fillet_range,
                          PlacedPiece(self.flank, angle, offset, mirror), self.flank_range, self.cutter, self.kind)


@dataclass(frozen=True)
class RackCutter:
    """ISO 53 rack cutting one gear (module m, profile shift x, thinning in mm of arc tooth thickness).

    Tool in the rack frame (rolling line η = 0, η > 0 away from the gear axis, the tool's space
    centred on ξ = 0): tip line η_t = −(h_a* + c* − x)m; straight flank ξ = ±(w/2 − η tan α) with
    w = m(π/2 + 2x tan α) − thinning; tip round ρ_f = ρ_f*·m tangent to both, centred at
    (±ξ_c, η_t + ρ_f); the straight flank ends at η_f = η_t + ρ_f(1 − sin α)."""

    m: float
    x: float = 0.0
    rack: BasicRack = BasicRack()
    thinning_mm: float = 0.0

    @property
    def w(self) -> float:
        return self.m * (math.pi / 2 + 2.0 * self.x * math.tan(self.rack.alpha)) - self.thinning_mm

    @property
    def rho(self) -> float:
        return self.rack.rho_f_star * self.m

    @property
    def eta_t(self) -> float:
        return -(self.rack.h_fP_star - self.x) * self.m

    @property
    def eta_f(self) -> float:
        """End of the straight flank (form point of the tool)."""
        return self.eta_t + self.rho * (1.0 - math.sin(self.rack.alpha))

    @property
    def xi_c(self) -> float:
        """Abscissa of the tip round centre (= its tangent point on the tip land)."""
        a = self.rack.alpha
        return self.w / 2.0 - self.eta_f * math.tan(a) + self.rho * math.cos(a)

    def sides(self, u_top: float, parameter: str = "rho_f_star") -> tuple[CutterSide, CutterSide]:
        """Right (+ξ, clockwise side of the gear tooth) and left sides; the straight flank runs
        from η_f to the distance u_top along it.  InputError naming ``parameter`` (the tip-round
        coefficient) when the tip rounds overlap."""
        a = self.rack.alpha
        sa, ca = math.sin(a), math.cos(a)
        w, rho, eta_t, xi_c = self.w, self.rho, self.eta_t, self.xi_c
        require(xi_c <= math.pi * self.m / 2.0 + TOOL_TIP_LAND_TOL_MM, parameter, self.rack.rho_f_star,
                "tool tip rounds overlap (no tip land)")
        u_f = self.eta_f / ca
        cut = RackCentrode()
        right = CutterSide(ArcPiece((xi_c, eta_t + rho), rho), (-math.pi / 2, -(math.pi - a)),
                           LinePiece((w / 2.0, 0.0), (-sa, ca)), (u_f, u_top), cut, "rack")
        left = CutterSide(ArcPiece((-xi_c, eta_t + rho), rho), (-math.pi / 2, -a),
                          LinePiece((-w / 2.0, 0.0), (sa, ca)), (u_f, u_top), cut, "rack")
        return right, left


def shaper_rack(alpha: float, h_a_star: float = 1.0, c_star: float = 0.25) -> BasicRack:
    """The rack a shaper's tooth is drawn from: its pressure angle and its tooth depth h_a* + c*.  A shaper rounds its
    tip by its own rho_a0* (:class:`ShaperCutter`), never by the rack's fillet radius; that one is ISO 53's 0.38
    where the rack's tip land holds it and the largest that fits where it does not (from alpha = 24 deg at
    h_a* + c* = 1.25), so that no shaper is refused for a radius it does not have; a steeper one is refused for its
    own tooth (its tip rounds meeting, or no tip land: tan alpha >= pi / (4 (h_a* + c*)))."""
    bare = BasicRack(alpha=alpha, h_a_star=h_a_star, c_star=c_star, rho_f_star=0.0)
    return BasicRack(alpha=alpha, h_a_star=h_a_star, c_star=c_star,
                     rho_f_star=min(BasicRack().rho_f_star, bare.rho_f_star_max))


@dataclass(frozen=True)
class ShaperCutter:
    """Shaper (pinion-type) cutter, GOST 9323: z0 teeth, module m, profile shift x0, tip
    diameter d_a0 = m(z0 + 2(h_a* + c* + x0)), tip round radius rho_a0 = rho_a0_star·m, tooth
    thickness on d0 = m(π/2 + 2 x0 tan α) (a new tool; the same ISO 53 rack generates it).

    rho_a0_star default 0.1 is OUR default (a typical tip rounding of shaper cutters; the
    shaper's narrow tip land does not admit the rack's 0.38)."""

    z0: int
    m: float
    x0: float = 0.0
    rack: BasicRack = BasicRack()
    rho_a0_star: float = 0.1

    def __post_init__(self):
        require(int(self.z0) == self.z0 and self.z0 >= 6, "z0", self.z0, "must be a whole number >= 6")
        require_positive("m", self.m, "mm")
        require_finite("x0", self.x0)
        r = require_finite("rho_a0_star", self.rho_a0_star)
        require(r > 0, "rho_a0_star", r, "must be > 0")

    @property
    def r0(self):
        return self.m * self.z0 / 2.0

    @property
    def r_b0(self):
        return self.r0 * math.cos(self.rack.alpha)

    @property
    def r_a0(self):
        return self.r0 + (self.rack.h_fP_star + self.x0) * self.m

    @property
    def d_a0(self):
        return 2.0 * self.r_a0

    @cached_property
    def involute(self) -> InvolutePiece:
        a = self.rack.alpha
        s0 = self.m * (math.pi / 2 + 2.0 * self.x0 * math.tan(a))
        return InvolutePiece(self.r_b0, s0 / (2.0 * self.r0) + float(inv(a)))

    @cached_property
    def tip_round(self):
        """(t*, centre, a_flank, a_tip): roll parameter where the round touches the involute, its
        centre and the polar angles (about the centre) of the two tangent points."""
        rho = self.rho_a0_star * self.m
        inv_p = self.involute
        x0_min = self.z0 * (math.cos(self.rack.alpha) - 1.0) / 2.0 - self.rack.h_fP_star
        require(self.r_a0 > self.r_b0, "x0", self.x0,
                f"the shaper's tip circle d_a0 = {self.d_a0:.3f} mm lies inside its base circle d_b0 = "
                f"{2.0 * self.r_b0:.3f} mm: it has no involute (x0 > {x0_min:.3f} for z0 = {self.z0})")
        t_a = math.sqrt((self.r_a0 / self.r_b0) ** 2 - 1.0)

        def centre(t):
            P = inv_p.point(t)[0]
            T = inv_p.tangent(t)[0]
            T = T / np.linalg.norm(T)
            n_in = np.array([-T[1], T[0]])  # towards the tooth centre
            return P + rho * n_in, n_in

        f = lambda t: float(np.linalg.norm(centre(t)[0])) - (self.r_a0 - rho)
        require(f(t_a) > 0 and f(0.0) < 0, "rho_a0_star", self.rho_a0_star, "tip round does not fit the shaper tooth")
        t_s = brentq(f, 0.0, t_a, xtol=ROUNDING_TOL, rtol=ROUNDING_TOL, maxiter=200)
        c, n_in = centre(t_s)
        a_flank = math.atan2(-n_in[1], -n_in[0])
        a_tip = math.atan2(c[1], c[0])
        require(math.atan2(c[0], c[1]) > 0, "rho_a0_star", self.rho_a0_star, "tip rounds of the shaper tooth overlap")
        return t_s, (float(c[0]), float(c[1])), a_flank, a_tip

    def side(self, centrode) -> CutterSide:
        """The right side of the shaper tooth on +y: tip round (from the tip land to the involute)
        and involute (from the round down to the base circle), rolling on ``centrode``."""
        t_s, c, a_flank, a_tip = self.tip_round
        return CutterSide(ArcPiece(c, self.rho_a0_star * self.m), (a_tip, a_flank),
                          self.involute, (t_s, INVOLUTE_T_MIN), centrode, "shaper")
