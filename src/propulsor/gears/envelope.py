"""Envelope of a cutter rolling on a gear centrode: the one centrode protocol of the tooth generator.

Pure math (numpy/scipy).  Millimetres and radians.

Method (Litvin & Fuentes-Aznar, *Noncircular Gears*, 2009, ch. 4; docs/architecture.md, "tooth
generator"): the cutter centrode (rack: its rolling line; shaper: its rolling circle) rolls without
slip on the gear centrode (pitch curve).  Both are parametrised by the common arc length ``s`` of
the rolling, so the cutter pose in the gear frame is

    θ(s) = τ_gear(s) − τ_cutter(s)                    (tangent directions coincide)
    X(u, s) = G(s) + R(θ(s)) · (P(u) − C(s))          (the contact points coincide)

with P(u) a point of the cutter outline, C(s) / G(s) the cutter / gear centrode points.  Meshing
equation (Willis' theorem): at the instant of contact the normal of the cutter outline at P passes
through the instantaneous centre of rotation, i.e. the current centrode contact point C(s).  For
each cutter point it is solved for s in closed form (rack: the normal meets the rolling line;
circle: the normal meets the rolling circle), so the envelope is evaluated point by point, exact to
rounding and vectorised.

**Centrode protocol.**  Every centrode has ``point(s)`` = G(s) (n, 2) and ``angle(s)`` = τ(s) (n,);
a cutter centrode also has ``contact(P, N)`` = s solving the meshing equation for cutter points P
with unit normals N.  Cutter centrodes: ``RackCentrode`` (rack), ``ExternalCircleCentrode``
(shaper outside a gear), ``CircleCentrode`` (shaper inside a ring).  Gear centrodes:
``CircleCentrode`` (circular gear) and ``PitchCurveCentrode`` (a non-circular pitch curve on the
shared arc-length frame).

Undercut: the envelope of the tool's straight flank is the involute *and* its mirrored branch beyond
the cusp on the base circle; when the shift is too small the trochoid of the tool tip round crosses
it.  The boundary of the cut region is found by trimming that self-intersection (``trim_crossing``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import InputError
from .envelope_point import envelope_point1, nearer_circle_crossing1
from ..policy import (ENVELOPE_SAMPLES_PER_FLANK, ROUNDING_TOL, SHAPER_MESH_FD_STEP_MM, SHAPER_MESH_SAMPLES,
                      SHAPER_MESH_STOP_MM, SHAPER_MESH_WINDOW_R)

__all__ = [
    "nearer_circle_crossing", "RackCentrode", "CircleCentrode", "ExternalCircleCentrode", "ShaperOnRackCentrode",
    "InternalCircleCentrode", "PitchCurveCentrode", "RoundEnvelope", "round_envelope",
    "envelope_points", "EnvelopeCurve",
]


def nearer_circle_crossing(P, N, centre, R: float, parameter: str, whose: str) -> np.ndarray:
    """Meshing equation of a rolling circle: the normal lines P + λN (N unit) cross the circle of
    radius R about `centre`; of the two crossings the one nearer to P is the pitch point of the
    contact.  InputError naming `parameter` (given the radius R) when a normal misses the circle."""
    Q = np.asarray(P, float) - np.asarray(centre, float)
    b = np.einsum("ij,ij->i", Q, N)
    c = np.einsum("ij,ij->i", Q, Q) - R ** 2
    disc = b * b - c
    if np.any(disc < 0):
        raise InputError(parameter, R, f"a generating point's normal misses the {whose} rolling circle",
                         "every one must cross it")
    sq = np.sqrt(disc)
    l1, l2 = -b + sq, -b - sq
    lam = np.where(np.abs(l1) <= np.abs(l2), l1, l2)
    return P + lam[:, None] * N


def _rot(theta, v):
    """Rotate vectors v (n,2) by angles theta (n,) counter-clockwise."""
    c, s = np.cos(theta), np.sin(theta)
    return np.column_stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]])


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

    # one cutter point (floats; ``envelope_points``' one-point path, the same operations)
    def contact1(self, px, py, nx, ny, piece=None):
        if ny == 0.0:
            return None
        return px + (-py / ny) * nx

    def pose1(self, s: float):
        """(C_x, C_y, angle) at one rolling arc s."""
        return s, 0.0, 0.0


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
        C = nearer_circle_crossing(P, N, (0.0, 0.0), self.R, "r0", "cutter's")
        return self.R * np.arctan2(C[:, 0], C[:, 1])


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
        C = nearer_circle_crossing(P, N, (0.0, self.R), self.R, "r0", "shaper's")
        return self.R * np.arctan2(C[:, 0], self.R - C[:, 1])

    # one cutter point (floats; ``envelope_points``' one-point path, the same operations)
    def contact1(self, px, py, nx, ny, piece=None):
        R = self.R
        C = nearer_circle_crossing1(px, py, nx, ny, 0.0, R, R)
        return None if C is None else R * float(np.arctan2(C[0], R - C[1]))

    def pose1(self, s: float):
        R = self.R
        return R * math.sin(s / R), R - R * math.cos(s / R), s / R


@dataclass(frozen=True)
class ShaperOnRackCentrode:
    """A shaper cutter with its OWN profile shift x0 meshing with the imaginary rack that rolls on
    the gear centrode (the gear's shift x): the gear's shift comes from the cutting position, not
    from the shaper's x0 (Litvin & Fuentes-Aznar 2009, ch. 6: generation by a shaper as the mate of
    the imaginary rack).

    Rack frame (``RackCentrode``): rolling line eta = 0 touching the gear centrode at (s, 0).  A
    shaper of reference radius R and shift x0 meshes with the same rack when its reference circle
    rolls on the line eta = e = (x + x0) m (the rack's reference line lies x m above eta = 0 and
    x0 m below the shaper's reference circle).  Gear flank, rack flank and shaper involute touch at
    ONE point when the shaper's pitch point (s + c, e) lies on the rack flank's normal through the
    rack's pitch point (s, 0) (Aronhold-Kennedy: the three instantaneous centres are collinear on
    the common normal): c = +e cot(alpha) for the right flank (normal (cos a, sin a)), -e cot(alpha)
    for the left.  So one side of a tooth is cut per pass (the shaper is re-phased per flank, as
    for thinning).  With e = 0 this is ``ExternalCircleCentrode`` (x0 = -x).

    Shaper frame as ``ExternalCircleCentrode``: centre (0, R), rolling point at the origin for
    beta = (s + c)/R = 0.  ``point(s)`` / ``angle(s)`` are the shaper-frame point and tangent
    direction that coincide with the rack's (s, 0) and its line, so ``envelope_points``' pose
    X = G(s) + R(tau_g - tau_c)(P - C(s)) places the shaper exactly.

    Meshing equation: the cutter normal passes through the instantaneous centre of the shaper relative to the
    gear.  On the involute the shaper's and the rack's pitch points both lie on the normal, so the closed-form
    shaper-on-line contact solves it (``contact_on``); the tip round's envelope is the equidistant of its centre's
    path (``round_envelope``)."""

    R: float
    e: float
    c: float

    def _beta(self, s):
        return (np.atleast_1d(np.asarray(s, float)) + self.c) / self.R

    def point(self, s):
        b = self._beta(s)
        R = self.R
        cb, sb = np.cos(b), np.sin(b)
        # C_ext(beta) + R(beta) (-c, -e)
        return np.column_stack([R * sb - cb * self.c + sb * self.e, R - R * cb - sb * self.c - cb * self.e])

    def angle(self, s):
        return self._beta(s)

    def contact(self, P, N):
        """Shaper-on-line contact (exact on the involute): the normal meets the rolling circle."""
        return ExternalCircleCentrode(self.R).contact(P, N) - self.c

    # one cutter point (floats; ``envelope_points``' one-point path, the same operations)
    def contact1(self, px, py, nx, ny, piece=None):
        """``contact_on`` where it is closed-form (e = 0 or a piece conjugate to the rack), else None."""
        if not (self.e == 0.0 or getattr(piece, "conjugate_to_rack", False)):
            return None
        s0 = ExternalCircleCentrode(self.R).contact1(px, py, nx, ny)
        return None if s0 is None else s0 - self.c

    def pose1(self, s: float):
        R = self.R
        b = (s + self.c) / R
        cb, sb = math.cos(b), math.sin(b)
        return R * sb - cb * self.c + sb * self.e, R - R * cb - sb * self.c - cb * self.e, b

    def contact_on(self, P, N, gear=None, piece=None):
        """The meshing equation where it is closed-form: the shaper-on-line contact, exact for a piece conjugate to
        the rack (``piece.conjugate_to_rack``: the shaper's involute, both instantaneous centres on its normal) and
        for e = 0.  The tip round of a re-phased shaper (e != 0) is neither: its envelope is the equidistant of its
        centre's path (:func:`round_envelope`, which ``noncircular_teeth.make_side`` uses), so it is refused here
        (ValueError)."""
        if self.e == 0.0 or getattr(piece, "conjugate_to_rack", False):
            return self.contact(P, N)
        raise ValueError("the tip round of a re-phased shaper (e != 0) has no closed-form contact: its envelope is "
                         "round_envelope's")


@dataclass(frozen=True)
class InternalCircleCentrode:
    """Pitch circle of an internal gear (ring) as a gear centrode for a cutter rolling inside it:
    radius R about the origin, touched at the top (0, R) at s = 0 and run counter-clockwise, so
    that the ring's body lies on the right of travel (as on ``PitchCurveCentrode``) and the
    cutter's side (eta > 0 of a rack) points to the centre: G(s) = R(-sin(s/R), cos(s/R)),
    tangent angle pi + s/R.  A rack of shift x_r rolling on it leaves a ring TOOTH of arc
    thickness m(pi/2 + 2 x_r tan alpha) centred on +y, i.e. the ring shift of GOST 19274 /
    ISO 21771 (space width m(pi/2 + 2 x tan alpha)) is x = -x_r."""

    R: float

    def point(self, s):
        s = np.atleast_1d(np.asarray(s, float))
        return np.column_stack([-self.R * np.sin(s / self.R), self.R * np.cos(s / self.R)])

    def angle(self, s):
        return math.pi + np.atleast_1d(np.asarray(s, float)) / self.R


class PitchCurveCentrode:
    """Gear centrode of a non-circular gear: its pitch curve (``BodyPitchCurve``) run clockwise
    on the body from the tooth centre s_k of the shared arc-length frame (``ArcFrame``) by the
    generation arc sg (gear on the right of travel).  ``s_k`` is one tooth centre, or an array
    of centres matching the generation arcs passed in (many teeth at once)."""

    def __init__(self, curve, frame, s_k):
        self.curve, self.frame = curve, frame
        self.s_k = float(s_k) if np.ndim(s_k) == 0 else np.asarray(s_k, float)
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

    def pose1(self, sg: float):
        """(G_x, G_y, tangent angle) at one generation arc sg (floats, the operations of ``point``
        and ``angle``), or None for many tooth centres or a non-finite arc."""
        if not isinstance(self.s_k, float):
            return None
        sgn = self.curve.sgn
        ph = self.frame.phi1(self.s_k + sgn * sg)
        if ph is None:
            return None
        x, y, dx, dy = self.curve._at1(ph)
        return x, y, float(np.arctan2(sgn * dy, sgn * dx))


def envelope_points(piece, u, cutter, gear):
    """Envelope of one cutter-outline piece in the gear frame.

    For every cutter parameter u: solve the meshing equation for the rolling arc length s,
    then place the cutter point by the pose of that instant.  Returns (X (n,2), s (n,)).
    """
    if type(u) is np.ndarray and u.shape == (1,) and hasattr(piece, "point1") and hasattr(cutter, "contact1") \
            and hasattr(gear, "pose1"):
        out = envelope_point1(piece, float(u[0]), cutter, gear)
        if out is not None:
            return out
    P = piece.point(u)
    T = piece.tangent(u)
    T = T / np.linalg.norm(T, axis=1)[:, None]
    N = np.column_stack([-T[:, 1], T[:, 0]])
    s = cutter.contact_on(P, N, gear, piece) if hasattr(cutter, "contact_on") else cutter.contact(P, N)
    theta = gear.angle(s) - cutter.angle(s)
    X = gear.point(s) + _rot(theta, P - cutter.point(s))
    return X, s


@dataclass(frozen=True)
class EnvelopeCurve:
    """Exact generated curve: envelope of ``piece`` for u in [u0, u1], rotated by ``rotation`` about the gear
    axis."""

    piece: object
    cutter: object
    gear: object
    u0: float
    u1: float
    kind: str = ""  # "fillet" | "flank"
    rotation: float = 0.0

    def __call__(self, u):
        X, _ = envelope_points(self.piece, u, self.cutter, self.gear)
        if self.rotation:
            X = _rot(np.full(len(X), self.rotation), X)
        return X

    def at(self, u: float) -> np.ndarray:
        return self(np.array([u]))[0]

    def sample(self, n: int = ENVELOPE_SAMPLES_PER_FLANK) -> np.ndarray:
        return self(np.linspace(self.u0, self.u1, n))

    def with_range(self, u0, u1) -> "EnvelopeCurve":
        return EnvelopeCurve(self.piece, self.cutter, self.gear, float(u0), float(u1), self.kind, self.rotation)

    def rotated(self, angle: float) -> "EnvelopeCurve":
        return EnvelopeCurve(self.piece, self.cutter, self.gear, self.u0, self.u1, self.kind, self.rotation + angle)

    def param_at_radius(self, r: float) -> float:
        """Parameter where the curve crosses radius r (must be bracketed by [u0, u1])."""
        f = lambda u: float(np.hypot(*self.at(u))) - r
        fa, fb = f(self.u0), f(self.u1)
        if fa * fb > 0:
            raise ValueError("radius not bracketed")
        return brentq(f, self.u0, self.u1, xtol=ROUNDING_TOL, rtol=ROUNDING_TOL, maxiter=200)


@dataclass(frozen=True)
class RoundEnvelope:
    """Envelope of a tool's tip round (a circle of centre ``centre`` and radius ``rho`` in the cutter
    frame) parametrised by the rolling arc s: the equidistant at rho of the trajectory of its centre,
    X(s) = T(s) + side rho n(s) (n the unit normal of T').  No meshing-equation branch to choose:
    used for the re-phased shaper (``ShaperOnRackCentrode``), whose instantaneous centre is no
    circle.  u0 / u1 are the rolling arcs where the contact reaches the tip-land end of the round and
    the involute (``round_envelope``).  The interface of ``EnvelopeCurve`` the generator uses."""

    centre: tuple
    rho: float
    side: float
    cutter: object
    gear: object
    u0: float
    u1: float
    kind: str = "fillet"

    def _pose(self, s):
        """The round's centre in the gear frame at each rolling arc s, and the cutter's turn relative to the gear."""
        s = np.atleast_1d(np.asarray(s, float))
        C = np.repeat(np.asarray(self.centre, float)[None, :], len(s), axis=0)
        theta = self.gear.angle(s) - self.cutter.angle(s)
        return self.gear.point(s) + _rot(theta, C - self.cutter.point(s)), theta

    def _T(self, s):
        return self._pose(s)[0]

    def _dir(self, Tp, Tm):
        """The unit contact direction from the centre's positions a step ahead (Tp) and behind (Tm)."""
        d = Tp - Tm
        d = d / np.linalg.norm(d, axis=1)[:, None]
        return self.side * np.column_stack([-d[:, 1], d[:, 0]])

    def contact_dir(self, s):
        """Unit direction from the round's centre to the contact point, in the gear frame (the centre's positions a
        step either side of each s in one evaluation: each row is the one its own s gives, the functions on the way
        being elementwise)."""
        s = np.atleast_1d(np.asarray(s, float))
        h = SHAPER_MESH_FD_STEP_MM
        n = len(s)
        T = self._T(np.concatenate([s + h, s - h]))
        return self._dir(T[:n], T[n:])

    def _centre_turn_dir(self, s):
        """(the centre T(s), the cutter's turn at s, the contact direction at s) from one evaluation at s and a step
        either side (row by row as apart: the functions on the way are elementwise)."""
        s = np.atleast_1d(np.asarray(s, float))
        h = SHAPER_MESH_FD_STEP_MM
        n = len(s)
        T, th = self._pose(np.concatenate([s, s + h, s - h]))
        return T[:n], th[:n], self._dir(T[n:2 * n], T[2 * n:])

    def __call__(self, s):
        T, _, d = self._centre_turn_dir(s)
        return T + self.rho * d

    def at(self, s: float) -> np.ndarray:
        return self(np.array([s]))[0]

    def sample(self, n: int = ENVELOPE_SAMPLES_PER_FLANK) -> np.ndarray:
        return self(np.linspace(self.u0, self.u1, n))

    def with_range(self, u0, u1) -> "RoundEnvelope":
        return RoundEnvelope(self.centre, self.rho, self.side, self.cutter, self.gear, float(u0), float(u1), self.kind)


def round_envelope(fillet_piece, a_tip: float, a_flank: float, rho: float, cutter, gear) -> RoundEnvelope:
    """The tip round's envelope from its junction with the involute (rolling arc s_f: the closed-form
    contact of that point, exact there) to the instant its contact reaches the tip-land end a_tip,
    followed continuously in s (``policy.SHAPER_MESH_WINDOW_R`` r0 either way).  InputError naming the
    shaper's pitch diameter ``d0`` when the contact never reaches the tip land."""
    a = np.array([a_flank, a_tip])
    P = fillet_piece.point(a)
    T = fillet_piece.tangent(a)
    T = T / np.linalg.norm(T, axis=1)[:, None]
    N = np.column_stack([-T[:, 1], T[:, 0]])
    s_f = float(cutter.contact(P[:1], N[:1])[0])
    centre = tuple(float(v) for v in (P[0] - rho * _unit_radial(P, fillet_piece, a)[0]))
    # which side of the centre trajectory: the one that reproduces the junction point
    best = None
    for side in (1.0, -1.0):
        env = RoundEnvelope(centre, rho, side, cutter, gear, s_f, s_f)
        X = env.at(s_f)
        th = gear.angle(np.array([s_f])) - cutter.angle(np.array([s_f]))
        Xj = gear.point(np.array([s_f]))[0] + _rot(th, P[:1] - cutter.point(np.array([s_f])))[0]
        err = float(np.linalg.norm(X - Xj))
        if best is None or err < best[0]:
            best = (err, side)
    side = best[1]
    env = RoundEnvelope(centre, rho, side, cutter, gear, s_f, s_f)
    # contact angle on the round (cutter frame) along s, relative to the junction; target: the tip end
    W = 2.0 * SHAPER_MESH_WINDOW_R * cutter.R
    u_tip = (P[1] - np.asarray(centre)) / rho
    u_fl = (P[0] - np.asarray(centre)) / rho
    target = math.atan2(u_fl[0] * u_tip[1] - u_fl[1] * u_tip[0], float(u_fl @ u_tip))

    def ang(ss):
        _, th, d = env._centre_turn_dir(ss)
        v = _rot(-th, d)
        return np.arctan2(u_fl[0] * v[:, 1] - u_fl[1] * v[:, 0], v @ u_fl)

    for direction in (1.0, -1.0):
        ss = s_f + direction * np.linspace(0.0, W, SHAPER_MESH_SAMPLES * 4)
        A = np.unwrap(ang(ss))
        rel = (A - target) * math.copysign(1.0, target)
        hit = np.nonzero(rel >= 0.0)[0]
        if len(hit) and hit[0] > 0 and np.all(np.abs(A[: hit[0]]) <= abs(target)):
            k = int(hit[0])
            base = A[k - 1]
            f = lambda q: float(base + np.angle(np.exp(1j * (ang(q)[0] - base))) - target)
            s_t = brentq(f, ss[k - 1], ss[k], xtol=SHAPER_MESH_STOP_MM)
            return env.with_range(s_t, s_f)
    raise InputError("d0", 2.0 * cutter.R, "the contact of the shaper's tip round never reaches its tip land",
                     "the shaper is too large for the gear's curvature there")


def _unit_radial(P, piece, a):
    """Outward unit radial of a (placed) circular piece at parameters a (from its tangent)."""
    T = piece.tangent(a)
    T = T / np.linalg.norm(T, axis=1)[:, None]
    c1 = piece.point(a)
    # the centre lies along the normal; the radial is the normal pointing away from it
    N = np.column_stack([T[:, 1], -T[:, 0]])
    probe = piece.point(a + 1e-3)
    # chord midpoint bends towards the centre: pick the normal pointing away from it
    mid = 0.5 * (c1 + probe)
    sgn = np.sign(np.einsum("ij,ij->i", c1 - mid, N))
    return N * np.where(sgn == 0, 1.0, sgn)[:, None]
