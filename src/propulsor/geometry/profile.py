"""Closed 2D profiles made of exact segments: lines, circular arcs, B-splines.

This is the hand-over format between the math layers (which produce outlines)
and the solid / DXF layers (which consume them).  numpy/scipy (a spline's exact area: the compiled
:mod:`.spline_foot`).

Conventions: millimetres, radians; an outer loop runs counter-clockwise, a
hole clockwise.  A segment knows its exact curve and can sample itself to a
chord tolerance for meshing, DXF polylines and 2D booleans.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import BSpline

from ..errors import require
from ..planar import norms
from ..policy import CHORD_TOL_MM, OUTLINE_JOINT_TOL_MM


def _rot(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]])


@dataclass(frozen=True)
class Line:
    p0: tuple[float, float]
    p1: tuple[float, float]

    @property
    def start(self) -> np.ndarray:
        return np.asarray(self.p0, float)

    @property
    def end(self) -> np.ndarray:
        return np.asarray(self.p1, float)

    def sample(self, chord_tol: float = CHORD_TOL_MM) -> np.ndarray:
        return np.array([self.p0, self.p1], float)

    def sweep(self) -> float:
        """``integral of (x dy - y dx)`` along the segment: twice the signed area its chords to the origin sweep."""
        (x0, y0), (x1, y1) = self.p0, self.p1
        return float(x0) * float(y1) - float(x1) * float(y0)

    def reversed(self) -> "Line":
        return Line(self.p1, self.p0)

    def transformed(self, angle: float = 0.0, offset=(0.0, 0.0)) -> "Line":
        R, o = _rot(angle), np.asarray(offset, float)
        return Line(tuple(R @ self.start + o), tuple(R @ self.end + o))

    def scaled(self, k: float) -> "Line":
        return Line(tuple(k * self.start), tuple(k * self.end))


@dataclass(frozen=True)
class Arc:
    """Circular arc from angle a0 to a1 (signed sweep a1 - a0; > 0 is CCW)."""

    center: tuple[float, float]
    radius: float
    a0: float
    a1: float

    def point(self, a: float) -> np.ndarray:
        cx, cy = self.center
        return np.array([cx + self.radius * math.cos(a), cy + self.radius * math.sin(a)])

    @property
    def start(self) -> np.ndarray:
        return self.point(self.a0)

    @property
    def end(self) -> np.ndarray:
        return self.point(self.a1)

    @property
    def mid(self) -> np.ndarray:
        return self.point(0.5 * (self.a0 + self.a1))

    def sample(self, chord_tol: float = CHORD_TOL_MM) -> np.ndarray:
        sweep = abs(self.a1 - self.a0)
        if self.radius <= chord_tol:
            n = 2
        else:
            da = 2.0 * math.acos(max(-1.0, 1.0 - chord_tol / self.radius))
            n = max(2, int(math.ceil(sweep / max(da, 1e-9))) + 1)
        a = np.linspace(self.a0, self.a1, n)
        cx, cy = self.center
        return np.column_stack([cx + self.radius * np.cos(a), cy + self.radius * np.sin(a)])

    def sweep(self) -> float:
        """``integral of (x dy - y dx)`` along the arc (x = cx + r cos a, y = cy + r sin a): r^2 (a1 - a0)
        + r cx (sin a1 - sin a0) - r cy (cos a1 - cos a0)."""
        cx, cy = self.center
        r = self.radius
        return (r * r * (self.a1 - self.a0) + r * cx * (math.sin(self.a1) - math.sin(self.a0))
                - r * cy * (math.cos(self.a1) - math.cos(self.a0)))

    def reversed(self) -> "Arc":
        return Arc(self.center, self.radius, self.a1, self.a0)

    def transformed(self, angle: float = 0.0, offset=(0.0, 0.0)) -> "Arc":
        c = _rot(angle) @ np.asarray(self.center, float) + np.asarray(offset, float)
        return Arc(tuple(c), self.radius, self.a0 + angle, self.a1 + angle)

    def scaled(self, k: float) -> "Arc":
        return Arc(tuple(k * np.asarray(self.center, float)), k * self.radius, self.a0, self.a1)


@dataclass(frozen=True, eq=False)
class Spline:
    """Non-rational B-spline curve in the plane (clamped knot vector)."""

    knots: np.ndarray
    poles: np.ndarray  # (n, 2)
    degree: int = 3

    def __post_init__(self):
        object.__setattr__(self, "knots", np.asarray(self.knots, float))
        object.__setattr__(self, "poles", np.asarray(self.poles, float))

    @property
    def _bs(self) -> BSpline:
        return BSpline(self.knots, self.poles, self.degree, extrapolate=False)

    @property
    def start(self) -> np.ndarray:
        return self.poles[0].copy()

    @property
    def end(self) -> np.ndarray:
        return self.poles[-1].copy()

    def evaluate(self, u: np.ndarray) -> np.ndarray:
        return self._bs(np.asarray(u, float))

    def sample(self, chord_tol: float = CHORD_TOL_MM) -> np.ndarray:
        """Sample so that the chord error stays below chord_tol (checked, refined).  Kept per tolerance on the spline
        (its knots and poles never change: a frozen value) and returned read-only: a loop is sampled at the same
        tolerance by its profile's orientation, the proofs and the exports.  Pickled with it: a forked worker is sent
        the samples (a copy of about 0.8 MB a wheel and tolerance) rather than sampling again (88 ms a seed-002 wheel at
        the proofs' tolerance)."""
        kept = self.__dict__.get("_samples")
        if kept is None:
            kept = self.__dict__["_samples"] = {}
        p = kept.get(chord_tol)
        if p is None:
            p = kept[chord_tol] = self._sample(chord_tol)
        p.flags.writeable = False  # (again after a pickle round trip, which does not keep the flag)
        return p

    def _sample(self, chord_tol: float) -> np.ndarray:
        """The samples of :meth:`sample`: scipy's B-spline evaluation itself (``_dierckx.evaluate_spline``, what
        ``BSpline.__call__`` hands its points to, without building the BSpline and its checks at every piece: the
        same floats; tests/test_profile_sample_fast.py holds it to ``BSpline``)."""
        from scipy.interpolate import _dierckx

        t0, t1 = self.knots[self.degree], self.knots[-self.degree - 1]
        t = np.ascontiguousarray(self.knots, dtype=np.float64)
        c = np.ascontiguousarray(self.poles, dtype=np.float64).reshape(len(self.poles), -1)
        k = int(self.degree)

        def bs(x):
            return _dierckx.evaluate_spline(t, c, k, np.ascontiguousarray(x, dtype=np.float64), 0, False)

        n = max(8, 4 * len(self.poles))
        while True:
            u = np.linspace(t0, t1, n)
            p = bs(u)
            mid = bs(0.5 * (u[:-1] + u[1:]))
            dev = mid - 0.5 * (p[:-1] + p[1:])  # the chords' midpoints off the curve
            err = np.max(norms(dev)) if n > 1 else 0.0
            if err <= chord_tol or n > 200000:
                return p
            n = int(n * max(1.5, math.sqrt(err / chord_tol) * 1.2))

    def sweep(self) -> float:
        """``integral of (x dy - y dx)`` along the spline, exact up to degree 3 (Gauss-Legendre on each knot span:
        :func:`.spline_foot.sweep_area`, compiled)."""
        from .spline_foot import sweep_area

        return sweep_area(self.knots, self.poles, self.degree)

    def reversed(self) -> "Spline":
        k = self.knots
        return Spline(k[0] + k[-1] - k[::-1], self.poles[::-1].copy(), self.degree)

    def transformed(self, angle: float = 0.0, offset=(0.0, 0.0)) -> "Spline":
        P = self.poles @ _rot(angle).T + np.asarray(offset, float)
        return Spline(self.knots.copy(), P, self.degree)

    def scaled(self, k: float) -> "Spline":
        """The curve scaled by k about the origin (a B-spline scales with its poles)."""
        return Spline(self.knots.copy(), k * self.poles, self.degree)


Segment = Line | Arc | Spline


@dataclass(eq=False)
class Loop:
    """A closed chain of segments; each segment's end is the next one's start."""

    segments: list = field(default_factory=list)

    def __post_init__(self):
        self.segments = list(self.segments)
        if not self.segments:
            raise ValueError("a loop needs at least one segment")

    def gaps(self) -> np.ndarray:
        """Distance between each segment's end and the next one's start."""
        s = self.segments
        return np.array([np.linalg.norm(s[i].end - s[(i + 1) % len(s)].start) for i in range(len(s))])

    def is_closed(self, tol: float = OUTLINE_JOINT_TOL_MM) -> bool:
        return bool(np.all(self.gaps() <= tol))

    def polyline(self, chord_tol: float = CHORD_TOL_MM) -> np.ndarray:
        """Closed polyline (first point not repeated at the end)."""
        pts = [seg.sample(chord_tol)[:-1] for seg in self.segments]
        return np.vstack(pts)

    def exact_signed_area(self) -> float:
        """The signed area (mm^2, > 0 counter-clockwise) of the exact loop: half the sum of its segments' ``sweep``
        (Green's theorem; no sampling)."""
        return 0.5 * math.fsum(seg.sweep() for seg in self.segments)

    def signed_area(self, chord_tol: float = CHORD_TOL_MM) -> float:
        """The signed area (mm^2) of the loop's polyline at ``chord_tol``."""
        p = self.polyline(chord_tol)
        x, y = p[:, 0], p[:, 1]
        return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))

    def reversed(self) -> "Loop":
        return Loop([s.reversed() for s in reversed(self.segments)])

    def transformed(self, angle: float = 0.0, offset=(0.0, 0.0)) -> "Loop":
        return Loop([s.transformed(angle, offset) for s in self.segments])

    def scaled(self, k: float) -> "Loop":
        return Loop([s.scaled(k) for s in self.segments])

    def oriented(self, ccw: bool = True) -> "Loop":
        """The loop running counter-clockwise (``ccw``) or clockwise: itself or reversed, by the sign of its exact
        area (a loop's sense needs no sampling: a seed-002 pair's 592 splines sampled at CHORD_TOL_MM only for it took
        27 ms, their exact sweeps 8 ms)."""
        return self if (self.exact_signed_area() > 0) == ccw else self.reversed()


@dataclass(eq=False)
class Profile:
    """A planar region: one outer loop (CCW) and any number of holes (CW)."""

    outer: Loop
    holes: list = field(default_factory=list)
    name: str = ""

    def __post_init__(self):
        self.outer = self.outer.oriented(True)
        self.holes = [h.oriented(False) for h in self.holes]

    @property
    def loops(self) -> list:
        return [self.outer, *self.holes]

    def area(self, chord_tol: float = CHORD_TOL_MM) -> float:
        return sum(l.signed_area(chord_tol) for l in self.loops)

    def transformed(self, angle: float = 0.0, offset=(0.0, 0.0)) -> "Profile":
        """The region turned by `angle` (rad) about the origin, then moved by `offset` (mm): a rigid motion keeps each
        loop's sense, so the loops are not sampled again to orient them (:meth:`_of_oriented`)."""
        return Profile._of_oriented(self.outer.transformed(angle, offset),
                                    [h.transformed(angle, offset) for h in self.holes], self.name)

    def scaled(self, k: float) -> "Profile":
        """The region scaled by k > 0 about the origin (a print kit's 1:S is k = 1/S); the loops keep their sense."""
        require(k > 0, "k", k, "must be > 0")
        return Profile._of_oriented(self.outer.scaled(k), [h.scaled(k) for h in self.holes], self.name)

    @classmethod
    def _of_oriented(cls, outer: Loop, holes: list, name: str) -> "Profile":
        """A profile of loops already oriented (the outer CCW, the holes CW): those of an oriented profile moved
        rigidly or scaled by k > 0, which keep the sign of every loop's area (``__post_init__`` would find it again
        from each loop's exact area)."""
        p = cls.__new__(cls)
        p.outer, p.holes, p.name = outer, list(holes), name
        return p

    def polylines(self, chord_tol: float = CHORD_TOL_MM) -> list:
        return [l.polyline(chord_tol) for l in self.loops]


def circle_loop(radius: float, center=(0.0, 0.0), ccw: bool = True) -> Loop:
    """A full circle as two half arcs (so that every edge has distinct ends)."""
    if ccw:
        return Loop([Arc(tuple(center), radius, 0.0, math.pi), Arc(tuple(center), radius, math.pi, 2 * math.pi)])
    return Loop([Arc(tuple(center), radius, 2 * math.pi, math.pi), Arc(tuple(center), radius, math.pi, 0.0)])


def polygon_loop(points) -> Loop:
    """A closed loop of straight lines through the given points."""
    p = np.asarray(points, float)
    return Loop([Line(tuple(p[i]), tuple(p[(i + 1) % len(p)])) for i in range(len(p))])


def hull_of_circles(circles) -> Loop:
    """The convex hull of circles [((x, y), r)] as arcs and lines (the arcs' ends on the circles,
    tangent to within the 0.5° sampling that finds them)."""
    from scipy.spatial import ConvexHull

    a = np.radians(np.arange(0.0, 360.0, 0.5))
    pts, owner, ang = [], [], []
    for i, ((x, y), r) in enumerate(circles):
        pts.append(np.column_stack([x + r * np.cos(a), y + r * np.sin(a)]))
        owner += [i] * len(a)
        ang.append(a)
    pts, owner, ang = np.vstack(pts), np.array(owner), np.concatenate(ang)
    v = ConvexHull(pts).vertices  # counter-clockwise
    start = next(j for j in range(len(v)) if owner[v[j]] != owner[v[j - 1]])
    v = np.roll(v, -start)
    runs = []
    for idx in v:
        if runs and runs[-1][0] == owner[idx]:
            runs[-1][1].append(ang[idx])
        else:
            runs.append((owner[idx], [ang[idx]]))
    segs = []
    for j, (i, angles) in enumerate(runs):
        (cx, cy), r = circles[i]
        a0 = angles[0]
        a1 = a0 + float(np.sum(np.mod(np.diff(angles), 2 * math.pi)))
        arc = Arc((cx, cy), r, a0, a1)
        if segs:
            segs.append(Line(tuple(segs[-1].end), tuple(arc.start)))
        segs.append(arc)
    segs.append(Line(tuple(segs[-1].end), tuple(segs[0].start)))
    return Loop(segs)
