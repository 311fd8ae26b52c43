"""Generated (conjugate) tooth outlines: envelopes of a rack cutter and of a shaper cutter.

Pure math (numpy/scipy).  Millimetres and radians.

Method (Litvin & Fuentes-Aznar, *Noncircular Gears*, 2009, ch. 4 — brief §3.2): the cutter
centrode (rack: its rolling line; shaper: its rolling circle) rolls without slip on the gear
centrode (pitch curve).  Both centrodes are parametrised by the common arc length ``s`` of
the rolling, so the cutter pose in the gear frame is

    θ(s) = τ_gear(s) − τ_cutter(s)                    (tangent directions coincide)
    X(u, s) = G(s) + R(θ(s)) · (P(u) − C(s))          (the contact points coincide)

with P(u) a point of the cutter outline, C(s) / G(s) the cutter / gear centrode points.
Meshing equation (Willis' theorem; Litvin & Fuentes, ch. on generation by a rack): at the instant of contact the normal of the
cutter outline at P passes through the instantaneous centre of rotation, i.e. the current
centrode contact point C(s).  For each cutter point the meshing equation is solved for s in
closed form (rack: the normal meets the rolling line; circle: the normal meets the rolling
circle), so the envelope is evaluated point by point, exact to rounding and fully vectorised.
Nothing here assumes a circular *gear* centrode: the gear centrode object only needs
``point(s)`` = G(s) and ``angle(s)`` = τ(s), so a non-circular pitch curve parametrised by arc
length plugs in (``PolarCentrode`` for r(φ); ``CircleCentrode`` for circles).  A shaper cutting
a concave part uses ``CircleCentrode`` as the cutter centrode in the same way.

External gears: ISO 53 basic rack (α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38) as the tool —
tool addendum h_a0 = (h_a* + c*)m, tip round ρ_f = ρ_f*·m — shifted by x·m away from the gear
axis.  Internal gears (ring, seed 004 ch. 4: z3 = 56, x3 = 1.417, shaper z0 = 14, x0 = 0.04):
shaper cutter z0, x0 (itself an involute gear with tip
d_a0 = d0 + 2(h_a* + c* + x0)m and a tip round ρ_a0), cutting centre distance a_w0 from
inv α_w0 = inv α + 2 tan α (x2 − x0)/(z2 − z0) (GOST 19274, tab. 1).

Tooth-thickness allowance ("thinning"): ``thinning_n_mm`` is the reduction of the arc tooth
thickness on the reference circle, i.e. the tooth-thickness deviation E_sn of ISO 21771 with
its sign dropped (spur gear: normal = transverse).  Two mating gears thinned by t1 and t2 have
the normal backlash j_bn = (t1 + t2)·cos α; a normal backlash j_n split evenly is
thinning_n_mm = j_n / (2 cos α) per gear.  It is
produced by rotating each flank about the gear axis by thinning/(2r) towards the tooth centre
(ring: away from the space centre), which is exactly the envelope of a tool shifted tangentially
by thinning/2 per flank (rack) or re-phased per flank pass (shaper).  Per flank, the flank moves
by thinning·cos α / 2 along its normal; the span W_k shrinks by thinning·cos α.

Undercut: the envelope of the tool's straight flank is the involute *and* its mirrored branch
beyond the cusp on the base circle; when x < x_min the trochoid of the tool tip round crosses
the involute.  The boundary of the cut region is found by trimming that self-intersection
(``trim_crossing``): fillet up to the crossing, involute from it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from scipy.optimize import brentq, fsolve

from ..errors import InputError, require, require_finite, require_positive
from .involute import BasicRack, inv, inv_inverse

__all__ = [
    "LinePiece", "ArcPiece", "InvolutePiece",
    "RackCentrode", "CircleCentrode", "PolarCentrode",
    "EnvelopeCurve", "envelope_points", "trim_crossing",
    "GeneratedSide", "generate_external_side", "generate_internal_side",
    "ShaperCutter",
]


def nearer_circle_crossing(P, N, centre, R: float, parameter: str, whose: str) -> np.ndarray:
    """Meshing equation of a rolling circle: the normal lines P + λN (N unit) cross the circle of
    radius R about `centre`; of the two crossings the one nearer to P is the pitch point of the
    contact.  InputError naming `parameter` when a normal misses the circle."""
    Q = np.asarray(P, float) - np.asarray(centre, float)
    b = np.einsum("ij,ij->i", Q, N)
    c = np.einsum("ij,ij->i", Q, Q) - R ** 2
    disc = b * b - c
    if np.any(disc < 0):
        raise InputError(parameter, "normal misses the rolling circle",
                         f"every generating point's normal must cross the {whose} rolling circle")
    sq = np.sqrt(disc)
    l1, l2 = -b + sq, -b - sq
    lam = np.where(np.abs(l1) <= np.abs(l2), l1, l2)
    return P + lam[:, None] * N


def _rot(theta, v):
    """Rotate vectors v (n,2) by angles theta (n,) counter-clockwise."""
    c, s = np.cos(theta), np.sin(theta)
    return np.column_stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]])


# =========================================================================== cutter outline
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


@dataclass(frozen=True)
class InvolutePiece:
    """Right flank (x > 0) of an involute tooth centred on the +y axis, roll parameter t = tan α_y.

    Radius r_y = r_b √(1+t²); polar angle from +y towards +x: ψ(t) = β − (t − atan t),
    β = half tooth angle on the base circle (= s/(2r) + inv α).  Tangent direction
    (sin ψ − t cos ψ, cos ψ + t sin ψ) (regular also at t = 0).
    """

    r_b: float
    beta: float

    def point(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        r = self.r_b * np.sqrt(1.0 + t * t)
        psi = self.beta - (t - np.arctan(t))
        return np.column_stack([r * np.sin(psi), r * np.cos(psi)])

    def tangent(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        psi = self.beta - (t - np.arctan(t))
        return np.column_stack([np.sin(psi) - t * np.cos(psi), np.cos(psi) + t * np.sin(psi)])


# =========================================================================== centrodes
@dataclass(frozen=True)
class RackCentrode:
    """Rolling line of a rack cutter: C(s) = (s, 0), tangent angle 0 (cutter frame)."""

    def point(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        return np.column_stack([s, np.zeros_like(s)])

    def angle(self, s):
        return np.zeros_like(np.atleast_1d(np.asarray(s, float)))

    def contact(self, P, N):
        """Meshing equation: s where the normal line P + λN meets the rolling line y = 0."""
        lam = -P[:, 1] / N[:, 1]
        return P[:, 0] + lam * N[:, 0]


@dataclass(frozen=True)
class CircleCentrode:
    """Circle of radius R about the origin, touched at the top (0, R) at s = 0, run clockwise:
    G(s) = R(sin(s/R), cos(s/R)), tangent angle −s/R.  Used for a circular gear's pitch
    circle and for a shaper's rolling circle (shaper inside a ring)."""

    R: float

    def point(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        return np.column_stack([self.R * np.sin(s / self.R), self.R * np.cos(s / self.R)])

    def angle(self, s):
        return -np.atleast_1d(np.asarray(s, float)) / self.R

    def contact(self, P, N):
        """Meshing equation: the normal line P + λN meets the circle; of the two crossings the
        one on the same side of the foot of the perpendicular as P (smaller |λ|) is the pitch
        point of the contact (involute: contact point and pitch point on the same ray of the
        line of action)."""
        C = nearer_circle_crossing(P, N, (0.0, 0.0), self.R, "cutter outline", "cutter's")
        return self.R * np.arctan2(C[:, 0], C[:, 1])


class PolarCentrode:
    """Gear centrode given as a pitch curve r(φ) in polar form (φ counter-clockwise from +x),
    run clockwise from φ0 by arc length s: dφ/ds = −1/√(r² + r'²) (brief §3 Trap 3: tooth
    spacing is true arc length).  Integrated once (solve_ivp, rtol 1e-12, dense output), then
    evaluated vectorised.  With r = R it is ``CircleCentrode(R)`` (φ0 = π/2): the hook for
    non-circular gears, whose teeth are the same envelopes on this centrode.
    """

    def __init__(self, r, dr, s_span: tuple, phi0: float = math.pi / 2):
        from scipy.integrate import solve_ivp

        self.r, self.dr, self.phi0 = r, dr, float(phi0)
        f = lambda s, y: [-1.0 / math.hypot(float(r(y[0])), float(dr(y[0])))]
        lo, hi = float(s_span[0]), float(s_span[1])
        kw = dict(dense_output=True, rtol=1e-12, atol=1e-14, method="DOP853")
        self._fwd = solve_ivp(f, (0.0, hi), [self.phi0], **kw).sol if hi > 0 else None
        self._bwd = solve_ivp(f, (0.0, lo), [self.phi0], **kw).sol if lo < 0 else None

    def phi(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        out = np.empty_like(s)
        pos = s >= 0
        if np.any(pos):
            out[pos] = self._fwd(s[pos])[0]
        if np.any(~pos):
            out[~pos] = self._bwd(s[~pos])[0]
        return out

    def point(self, s):
        ph = self.phi(s)
        r = np.asarray(self.r(ph), float) * np.ones_like(ph)
        return np.column_stack([r * np.cos(ph), r * np.sin(ph)])

    def angle(self, s):
        ph = self.phi(s)
        r = np.asarray(self.r(ph), float) * np.ones_like(ph)
        dr = np.asarray(self.dr(ph), float) * np.ones_like(ph)
        # dG/dφ, reversed (φ decreases with s)
        tx = -(dr * np.cos(ph) - r * np.sin(ph))
        ty = -(dr * np.sin(ph) + r * np.cos(ph))
        return np.arctan2(ty, tx)


def envelope_points(piece, u, cutter, gear):
    """Envelope of one cutter-outline piece in the gear frame.

    For every cutter parameter u: solve the meshing equation for the rolling arc length s,
    then place the cutter point by the pose of that instant.  Returns (X (n,2), s (n,)).
    """
    P = piece.point(u)
    T = piece.tangent(u)
    T = T / np.linalg.norm(T, axis=1)[:, None]
    N = np.column_stack([-T[:, 1], T[:, 0]])
    s = cutter.contact(P, N)
    theta = gear.angle(s) - cutter.angle(s)
    X = gear.point(s) + _rot(theta, P - cutter.point(s))
    return X, s


@dataclass(frozen=True)
class EnvelopeCurve:
    """Exact generated curve: envelope of ``piece`` for u in [u0, u1], then mirrored about the
    y axis (if ``mirror``) and rotated by ``rotation`` about the gear axis."""

    piece: object
    cutter: object
    gear: object
    u0: float
    u1: float
    kind: str = ""  # "fillet" | "flank"
    rotation: float = 0.0
    mirror: bool = False

    def __call__(self, u):
        X, _ = envelope_points(self.piece, u, self.cutter, self.gear)
        if self.mirror:
            X = X * np.array([-1.0, 1.0])
        if self.rotation:
            X = _rot(np.full(len(X), self.rotation), X)
        return X

    def at(self, u: float) -> np.ndarray:
        return self(np.array([u]))[0]

    def sample(self, n: int = 200) -> np.ndarray:
        return self(np.linspace(self.u0, self.u1, n))

    def with_range(self, u0, u1) -> "EnvelopeCurve":
        return EnvelopeCurve(self.piece, self.cutter, self.gear, float(u0), float(u1), self.kind,
                             self.rotation, self.mirror)

    def rotated(self, angle: float) -> "EnvelopeCurve":
        return EnvelopeCurve(self.piece, self.cutter, self.gear, self.u0, self.u1, self.kind,
                             self.rotation + angle, self.mirror)

    def mirrored(self) -> "EnvelopeCurve":
        return EnvelopeCurve(self.piece, self.cutter, self.gear, self.u0, self.u1, self.kind,
                             -self.rotation, not self.mirror)

    def param_at_radius(self, r: float) -> float:
        """Parameter where the curve crosses radius r (must be bracketed by [u0, u1])."""
        f = lambda u: float(np.hypot(*self.at(u))) - r
        fa, fb = f(self.u0), f(self.u1)
        if fa * fb > 0:
            raise ValueError("radius not bracketed")
        return brentq(f, self.u0, self.u1, xtol=1e-15, rtol=1e-15, maxiter=200)


# =========================================================================== trimming
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
    step = 1e-7 * abs(curve.u1 - curve.u0)
    speed = lambda t: float(np.linalg.norm(curve.at(t + step) - curve.at(t - step)))
    from scipy.optimize import minimize_scalar
    res = minimize_scalar(speed, bounds=(min(lo, hi), max(lo, hi)), method="bounded",
                          options={"xatol": 1e-13 * max(1.0, abs(hi))})
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
    sol = fsolve(g, x0, xtol=1e-15, full_output=True)[0]
    if np.linalg.norm(g(sol)) > 1e-9:
        raise RuntimeError("undercut crossing did not converge")
    return float(sol[0]), float(sol[1])


# =========================================================================== generated side
@dataclass
class GeneratedSide:
    """One generated side of a tooth (external gear: the tooth on +y; ring: the space on +y),
    the side at x > 0, from the root to the tip: ``fillet`` then ``flank``.

    r_f: root radius (circle generated by the tool tip land); r_a: tip radius;
    r_Ff: form radius (where the involute begins); undercut: the tool tip trochoid cut the
    involute; root_angle / tip_angle: polar angles (from +y, towards +x positive) of the
    fillet start on the root circle and the flank end on the tip circle.
    """

    fillet: EnvelopeCurve
    flank: EnvelopeCurve
    r_f: float
    r_a: float
    r_Ff: float
    undercut: bool
    r_b: float
    r: float
    internal: bool = False
    z: int = 0
    extra: dict = field(default_factory=dict)

    @property
    def root_angle(self) -> float:
        p = self.fillet.at(self.fillet.u0)
        return float(math.atan2(p[0], p[1]))

    @property
    def tip_angle(self) -> float:
        p = self.flank.at(self.flank.u1)
        return float(math.atan2(p[0], p[1]))

    def dense(self, n: int = 400) -> dict:
        """Dense exact points of one pitch: fillet and flank of this side (root → tip), the
        mirrored side, the tip arc and the root arc adjoining them (external: tip across the
        tooth, root across the space to its right; ring: root across the space, tip across the
        tooth to its right).  Angles from +y, positive towards +x."""
        fil, fla = self.fillet.sample(n), self.flank.sample(n)
        ta, ra, pz = self.tip_angle, self.root_angle, 2.0 * math.pi / self.z
        if self.internal:
            tip, root = np.linspace(ta, pz - ta, n), np.linspace(ra, -ra, n)
        else:
            tip, root = np.linspace(ta, -ta, n), np.linspace(ra, pz - ra, n)
        return {
            "fillet": fil, "flank": fla,
            "fillet_mirror": fil * [-1, 1], "flank_mirror": fla * [-1, 1],
            "tip": self.r_a * np.column_stack([np.sin(tip), np.cos(tip)]),
            "root": self.r_f * np.column_stack([np.sin(root), np.cos(root)]),
        }


def generate_external_side(z: int, m: float, x: float = 0.0, d_a: float | None = None,
                           rack: BasicRack = BasicRack(), thinning_n_mm: float = 0.0) -> GeneratedSide:
    """Right side of the tooth on +y of an external spur gear generated by the ISO 53 rack.

    Tool in the rack frame (rolling line η = 0, η > 0 away from the gear axis, tooth of the
    tool centred at ξ = p/2): tip line η_t = −(h_a* + c* − x)m; straight flank
    ξ = w/2 − η tan α with w = m(π/2 + 2x tan α) the space width of the tool on its rolling
    line (= tooth thickness s of the gear, ISO 21771 eq. (61)); tip round ρ_f = ρ_f*·m tangent
    to both.  Root radius r_f = r + η_t (ISO 21771: d_f = d − 2(h_fP − x m)).
    """
    z = int(z)
    require(z >= 3, "z", z, "must be >= 3")
    m = require_positive("m", m, "mm")
    x = require_finite("x", x)
    th = require_finite("thinning_n_mm", thinning_n_mm)
    a = rack.alpha
    r = m * z / 2.0
    r_b = r * math.cos(a)
    if d_a is None:
        d_a = m * (z + 2.0 * rack.h_a_star + 2.0 * x)
    d_a = require_positive("d_a", d_a, "mm")
    r_a = d_a / 2.0
    rho = rack.rho_f_star * m
    eta_t = -(rack.h_fP_star - x) * m
    r_f = r + eta_t
    require(r_f > 0, "x", x, f"root radius must be > 0 (r_f = {r_f:.4g} mm)")
    require(r_a > max(r_f, r_b), "d_a", d_a,
            f"must exceed the root and base diameters ({2 * max(r_f, r_b):.6f} mm)")
    w = m * (math.pi / 2 + 2.0 * x * math.tan(a))
    sa, ca, ta = math.sin(a), math.cos(a), math.tan(a)
    eta_f = eta_t + rho * (1.0 - sa)            # end of the straight flank (form point of the tool)
    xi_c = w / 2.0 - eta_f * ta + rho * ca       # round centre / tip-land tangent point abscissa
    p = math.pi * m
    require(xi_c <= p / 2.0 + 1e-12, "rack.rho_f_star", rack.rho_f_star,
            "tool tip rounds overlap (no tip land)")
    cutter, gear = RackCentrode(), CircleCentrode(r)

    # straight flank, parameter u = distance along (−sin α, cos α) from its rolling-line point
    flank_piece = LinePiece((w / 2.0, 0.0), (-sa, ca))
    u_f = eta_f / ca
    # outer end: the flank point that generates r_a (+10 % margin), from
    # r_y² = r² + 2rη + (η/sin α)² on the regular branch
    ry = 1.1 * r_a
    eta_top = sa * sa * (-r + math.sqrt(r * r + (ry * ry - r * r) / (sa * sa)))
    u_top = eta_top / ca
    flank = EnvelopeCurve(flank_piece, cutter, gear, u_f, u_top, "flank")
    round_piece = ArcPiece((xi_c, eta_t + rho), rho)
    fillet = EnvelopeCurve(round_piece, cutter, gear, -math.pi / 2, -(math.pi - a), "fillet")

    undercut = eta_f < -r * sa * sa * (1.0 + 1e-12)
    cross = trim_crossing(fillet, flank) if undercut else None
    if cross is not None:
        fillet = fillet.with_range(fillet.u0, cross[0])
        flank = flank.with_range(cross[1], flank.u1)
    r_Ff = float(np.hypot(*flank.at(flank.u0)))
    require(r_a > r_Ff, "d_a", d_a, f"must exceed the form diameter d_Ff = {2 * r_Ff:.6f} mm")
    u_a = flank.param_at_radius(r_a)
    flank = flank.with_range(flank.u0, u_a)
    side = GeneratedSide(fillet, flank, r_f, r_a, r_Ff, cross is not None, r_b, r, False, z,
                         {"eta_f": eta_f, "rho": rho, "w": w})
    if th:
        dphi = th / (2.0 * r)
        side.fillet, side.flank = side.fillet.rotated(dphi), side.flank.rotated(dphi)
    require(side.tip_angle > 0.0, "d_a", d_a, "tooth is pointed below the tip circle")
    require(side.root_angle < math.pi / z, "thinning_n_mm", th, "fillets of one space overlap")
    return side


# =========================================================================== shaper cutter
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
        t_a = math.sqrt((self.r_a0 / self.r_b0) ** 2 - 1.0)

        def centre(t):
            P = inv_p.point(t)[0]
            T = inv_p.tangent(t)[0]
            T = T / np.linalg.norm(T)
            n_in = np.array([-T[1], T[0]])  # towards the tooth centre
            return P + rho * n_in, n_in

        f = lambda t: float(np.linalg.norm(centre(t)[0])) - (self.r_a0 - rho)
        require(f(t_a) > 0 and f(0.0) < 0, "rho_a0_star", self.rho_a0_star, "tip round does not fit the shaper tooth")
        t_s = brentq(f, 0.0, t_a, xtol=1e-15, rtol=1e-15, maxiter=200)
        c, n_in = centre(t_s)
        a_flank = math.atan2(-n_in[1], -n_in[0])
        a_tip = math.atan2(c[1], c[0])
        require(math.atan2(c[0], c[1]) > 0, "rho_a0_star", self.rho_a0_star, "tip rounds of the shaper tooth overlap")
        return t_s, (float(c[0]), float(c[1])), a_flank, a_tip


def generate_internal_side(z: int, m: float, x: float, d_a: float, shaper: ShaperCutter,
                           thinning_n_mm: float = 0.0) -> GeneratedSide:
    """Right side (x > 0) of the space on +y of a ring (internal gear) cut by a shaper.

    The shaper's rolling circle r_w0 = a_w0 z0/(z − z0) rolls inside the ring's r_w = a_w0 z/(z − z0)
    (GOST 19274: inv α_w0 = inv α + 2 tan α (x − x0)/(z − z0), a_w0 = m(z − z0) cos α/(2 cos α_w0)).
    The shaper tip generates the root circle r_f = a_w0 + r_a0, its tip round the fillet and its
    involute the ring's involute (base r_b = r cos α).  ``d_a`` is the ring's tip (inner) diameter.
    """
    z = int(z)
    require(z >= shaper.z0 + 4, "z", z, f"ring needs z >= z0 + 4 = {shaper.z0 + 4}")
    require(abs(shaper.m - m) < 1e-12, "m", m, f"must equal the shaper module {shaper.m}")
    x = require_finite("x", x)
    th = require_finite("thinning_n_mm", thinning_n_mm)
    d_a = require_positive("d_a", d_a, "mm")
    a = shaper.rack.alpha
    z0 = shaper.z0
    inv_w0 = float(inv(a)) + 2.0 * math.tan(a) * (x - shaper.x0) / (z - z0)
    require(inv_w0 > 0, "x", x, "machining pressure angle would be <= 0 (x − x0 too negative)")
    a_w0_ang = inv_inverse(inv_w0)
    a_w0 = m * (z - z0) / 2.0 * math.cos(a) / math.cos(a_w0_ang)
    r_w0 = a_w0 * z0 / (z - z0)
    r_w = a_w0 * z / (z - z0)
    r = m * z / 2.0
    r_b = r * math.cos(a)
    r_a = d_a / 2.0
    r_f = a_w0 + shaper.r_a0
    require(r_a < r_f, "d_a", d_a, f"must be < root diameter {2 * r_f:.6f} mm")
    require(r_a > r_b, "d_a", d_a, f"must be > base diameter {2 * r_b:.6f} mm")
    cutter, gear = CircleCentrode(r_w0), CircleCentrode(r_w)
    t_s, c, a_flank, a_tip = shaper.tip_round
    fillet = EnvelopeCurve(ArcPiece(c, shaper.rho_a0_star * m), cutter, gear, a_tip, a_flank, "fillet")
    # involute of the shaper from the round down towards its base circle
    flank = EnvelopeCurve(shaper.involute, cutter, gear, t_s, 1e-9, "flank")
    cross = trim_crossing(fillet, flank)
    if cross is not None:
        fillet = fillet.with_range(fillet.u0, cross[0])
        flank = flank.with_range(cross[1], flank.u1)
    r_Ff = float(np.hypot(*flank.at(flank.u0)))
    r_end = float(np.hypot(*flank.at(flank.u1)))
    require(r_end < r_a, "d_a", d_a,
            f"ring tip inside the shaper's generating limit: must be >= {2 * r_end:.6f} mm "
            "(the shaper base circle generates no involute below it)")
    require(r_a < r_Ff, "d_a", d_a, f"must be < the form diameter d_Ff = {2 * r_Ff:.6f} mm")
    u_a = flank.param_at_radius(r_a)
    flank = flank.with_range(flank.u0, u_a)
    side = GeneratedSide(fillet, flank, r_f, r_a, r_Ff, cross is not None, r_b, r, True, z,
                         {"a_w0": a_w0, "alpha_w0": a_w0_ang, "r_w0": r_w0, "r_w": r_w,
                          "d_a0": shaper.d_a0})
    if th:
        dphi = -th / (2.0 * r)
        side.fillet, side.flank = side.fillet.rotated(dphi), side.flank.rotated(dphi)
    require(side.root_angle > 0.0, "shaper", shaper, "root land of the ring space vanished")
    require(side.tip_angle < math.pi / z, "d_a", d_a, "ring tooth is pointed at the tip circle")
    return side
