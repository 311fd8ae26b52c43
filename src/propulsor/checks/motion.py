"""Motion checks: interference and clearance of mating bodies over a motion cycle.

SPEC §3.2 ("verify from the finished outlines, not from the formulas"), §6 and §9
("interference and clearance of mating parts over the sampled cycle with manifold
booleans").  manifold3d, numpy and scipy only; no part or gear module is imported,
so any outline (generated teeth, the seeds' sector teeth, planetary gears, cams)
is checked the same way.

Three tools:

* :func:`sweep_pair` - two planar bodies, one rigid pose each per step: overlap
  area (manifold3d ``CrossSection`` intersection) and the minimum distance
  between the boundaries (exact for the sampled polylines).
* :func:`transmission_sweep` - a gear pair on its finished outlines: at each
  driven angle phi the driver is placed at the law angle theta(phi); the free
  rotation of the driven body in each direction until first contact is computed
  analytically (every boundary vertex runs on a circle about the driven centre;
  its first crossing of the other boundary is a circle-segment intersection).
  That gives backlash, transmission error against the law and the number of
  tooth pairs in contact (contact ratio along the cycle).
* :func:`sweep_solids_3d` - intersection volume (and optional gap) of two
  triangle meshes under 4x4 poses, for parts that are not prismatic.

Frames and signs: millimetres, radians, angles counter-clockwise positive.
Outlines are polylines whose material lies on the left of every edge (outer
loop CCW, holes CW, as :class:`propulsor.geometry.profile.Profile` guarantees;
raw polylines are re-oriented by nesting depth, i.e. even-odd).

Accuracy: clearance, backlash and contact are exact for the polylines; the
polylines lie within ``chord_tol`` of the true curves (on the concave side of a
convex flank), so each boundary can read up to ``chord_tol`` too thin.  The
default :data:`propulsor.policy.MOTION_CHORD_TOL_MM` (0.1 um) keeps that far below
the 1 um resolution asked of backlash.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass
from typing import Callable, Sequence

import manifold3d as m3d
import numpy as np
from scipy.spatial import cKDTree

from .. import policy
from ..check import Check
from ..errors import InputError, require, require_positive
from ..geometry.profile import Profile

__all__ = [
    "Outline",
    "outline",
    "Pose",
    "poses_from_angles",
    "SweepResult",
    "sweep_pair",
    "sweep_pair_windowed",
    "TransmissionResult",
    "transmission_sweep",
    "Sweep3DResult",
    "sweep_solids_3d",
]

_ANG_EPS = 1e-10  # rad: a hit this close to 0 is a touching contact, not a full turn


# ----------------------------------------------------------------------------
# outlines
# ----------------------------------------------------------------------------


def _signed_area(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _points_in_polygon(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Even-odd ray casting of many points against one closed polygon."""
    x, y = pts[:, 0][:, None], pts[:, 1][:, None]
    a, b = poly, np.roll(poly, -1, axis=0)
    ax, ay, bx, by = a[:, 0][None], a[:, 1][None], b[:, 0][None], b[:, 1][None]
    cond = (ay > y) != (by > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xi = ax + (y - ay) * (bx - ax) / (by - ay)
    return (np.count_nonzero(cond & (x < xi), axis=1) % 2) == 1


def _clean_loop(p, name: str) -> np.ndarray:
    p = np.asarray(p, float)
    require(p.ndim == 2 and p.shape[1] == 2, name, p.shape, "must be an (n, 2) array of points")
    require(bool(np.all(np.isfinite(p))), name, "non-finite", "points must be finite")
    if len(p) > 1 and np.linalg.norm(p[0] - p[-1]) <= policy.POINT_TOL_MM:
        p = p[:-1]
    step = np.linalg.norm(np.diff(p, axis=0, append=p[:1]), axis=1)
    p = p[step > policy.POINT_TOL_MM]  # drop repeated vertices
    require(len(p) >= 3, name, len(p), "a closed loop needs at least 3 distinct points")
    return p


def _orient_by_nesting(loops: list[np.ndarray]) -> list[np.ndarray]:
    """Outer loops (even nesting depth) CCW, holes (odd depth) CW: material on the left."""
    out = []
    for i, p in enumerate(loops):
        depth = sum(bool(_points_in_polygon(p[:1], q)[0]) for j, q in enumerate(loops) if j != i)
        ccw = depth % 2 == 0
        out.append(p if (_signed_area(p) > 0) == ccw else p[::-1].copy())
    return out


def _densify(p: np.ndarray, max_seg: float) -> np.ndarray:
    """Insert points on the straight edges so that no edge exceeds max_seg (same polyline)."""
    q = np.roll(p, -1, axis=0)
    n = np.maximum(1, np.ceil(np.linalg.norm(q - p, axis=1) / max_seg).astype(int))
    if np.all(n == 1):
        return p
    idx = np.repeat(np.arange(len(p)), n)
    k = np.arange(len(idx)) - np.repeat(np.cumsum(n) - n, n)
    t = (k / np.repeat(n, n))[:, None]
    return p[idx] + t * (q[idx] - p[idx])


class Outline:
    """A planar body prepared for motion checks (in its own body frame).

    ``loops``: closed polylines (first point not repeated), material on the left;
    ``section``: the manifold3d CrossSection of those loops (fill rule Positive);
    ``points``: all vertices after subdividing long edges, with edge arrays
    ``seg_a``/``seg_b`` (edge k runs from point k to point ``nxt[k]``), ``prev``,
    ``loop_id``, ``arclen`` (arc length of each vertex along its loop) and a
    cKDTree of the points; ``center``, ``r_min``, ``radius``: an annulus holding
    every boundary point (used to discard far points before any tree query).
    """

    def __init__(self, loops: Sequence[np.ndarray], max_segment: float = policy.MOTION_MAX_SEGMENT_MM):
        require_positive("max_segment", max_segment, "mm")
        require(len(loops) >= 1, "loops", len(loops), "need at least one closed loop")
        cleaned = [_clean_loop(p, f"loops[{i}]") for i, p in enumerate(loops)]
        self.loops = _orient_by_nesting(cleaned)
        self.section = m3d.CrossSection([np.ascontiguousarray(p) for p in self.loops], m3d.FillRule.Positive)
        dense = [_densify(p, max_segment) for p in self.loops]
        sizes = np.array([len(d) for d in dense])
        starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
        self.points = np.vstack(dense)
        self.loop_id = np.repeat(np.arange(len(dense)), sizes)
        local = np.arange(len(self.points)) - starts[self.loop_id]
        self.nxt = starts[self.loop_id] + (local + 1) % sizes[self.loop_id]
        self.prev = starts[self.loop_id] + (local - 1) % sizes[self.loop_id]
        self.seg_a = self.points
        self.seg_b = self.points[self.nxt]
        self.seg_len = np.linalg.norm(self.seg_b - self.seg_a, axis=1)
        self.half_len = 0.5 * float(self.seg_len.max())
        cum = np.cumsum(self.seg_len)
        loop_start_cum = (cum - self.seg_len)[starts]
        self.arclen = cum - self.seg_len - loop_start_cum[self.loop_id]
        self.perimeter = np.array([self.seg_len[self.loop_id == i].sum() for i in range(len(dense))])
        self.tree = cKDTree(self.points)
        lo, hi = self.points.min(axis=0), self.points.max(axis=0)
        self.center = 0.5 * (lo + hi)
        dc = np.linalg.norm(self.points - self.center, axis=1)
        self.radius = float(dc.max())
        self.r_min = float(dc.min())  # the whole boundary lies in the annulus r_min .. radius about center

    def boundary_lower_bound(self, P: np.ndarray) -> np.ndarray:
        """A lower bound of the distance from each point (body frame) to the boundary (annulus test)."""
        d = _norm(P - self.center)
        return np.maximum(d - self.radius, self.r_min - d)

    @property
    def area(self) -> float:
        return float(self.section.area())

    def __len__(self) -> int:
        return len(self.points)


_OUTLINE_CACHE: "weakref.WeakKeyDictionary[Profile, dict]" = weakref.WeakKeyDictionary()


def outline(body, chord_tol: float = policy.MOTION_CHORD_TOL_MM, max_segment: float = policy.MOTION_MAX_SEGMENT_MM) -> Outline:
    """Outline of a Profile (sampled to chord_tol, cached per profile) or of a list of closed polylines.

    An :class:`Outline` passes through unchanged.
    """
    if isinstance(body, Outline):
        return body
    if isinstance(body, Profile):
        require_positive("chord_tol", chord_tol, "mm")
        per = _OUTLINE_CACHE.setdefault(body, {})
        key = (float(chord_tol), float(max_segment))
        if key not in per:
            per[key] = Outline(body.polylines(chord_tol), max_segment)
        return per[key]
    if isinstance(body, np.ndarray) and body.ndim == 2:
        body = [body]
    try:
        loops = list(body)
    except TypeError:
        raise InputError("body", type(body).__name__, "must be a Profile, an Outline or a list of closed (n, 2) polylines") from None
    return Outline(loops, max_segment)


# ----------------------------------------------------------------------------
# poses
# ----------------------------------------------------------------------------


@dataclass(frozen=True)
class Pose:
    """Rigid planar pose: rotate by ``angle`` about ``pivot`` (body coordinates), then translate by ``offset``.

    A body point x goes to R(angle)·(x − pivot) + pivot + offset.
    """

    angle: float = 0.0
    pivot: tuple[float, float] = (0.0, 0.0)
    offset: tuple[float, float] = (0.0, 0.0)

    def matrix(self) -> np.ndarray:
        """2x3 affine matrix [R | t] (the form manifold3d's CrossSection.transform takes)."""
        c, s = math.cos(self.angle), math.sin(self.angle)
        R = np.array([[c, -s], [s, c]])
        p, o = np.asarray(self.pivot, float), np.asarray(self.offset, float)
        return np.column_stack([R, p + o - R @ p])


def poses_from_angles(angles, pivot=(0.0, 0.0), offset=(0.0, 0.0)) -> list[Pose]:
    """One Pose per angle, all about the same pivot and with the same translation."""
    return [Pose(float(a), tuple(map(float, pivot)), tuple(map(float, offset))) for a in np.ravel(angles)]


def _pose_stack(poses, n: int | None, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(n, 2, 3) matrices and (n,) angles from a Pose, a sequence of Poses or an (n, 2, 3) array."""
    if isinstance(poses, Pose):
        poses = [poses] * (n or 1)
    if isinstance(poses, np.ndarray):
        M = np.asarray(poses, float)
        require(M.ndim == 3 and M.shape[1:] == (2, 3), name, M.shape, "must be Poses or an (n, 2, 3) array")
        ang = np.arctan2(M[:, 1, 0], M[:, 0, 0])
    else:
        poses = list(poses)
        require(all(isinstance(p, Pose) for p in poses), name, "mixed", "must be Pose objects")
        M = np.array([p.matrix() for p in poses]).reshape(-1, 2, 3)
        ang = np.array([p.angle for p in poses], float)
    require(len(M) >= 1, name, len(M), "need at least one pose")
    require(bool(np.all(np.isfinite(M))), name, "non-finite", "poses must be finite")
    if n is not None and len(M) == 1 and n > 1:
        M, ang = np.repeat(M, n, axis=0), np.repeat(ang, n)
    return M, ang


def _apply(M: np.ndarray, P: np.ndarray) -> np.ndarray:
    return P @ M[:, :2].T + M[:, 2]


def _inverse(M: np.ndarray) -> np.ndarray:
    R = M[:, :2]
    return np.column_stack([R.T, -R.T @ M[:, 2]])


def _compose(M1: np.ndarray, M2: np.ndarray) -> np.ndarray:
    """M1 ∘ M2 (apply M2 first)."""
    return np.column_stack([M1[:, :2] @ M2[:, :2], M1[:, :2] @ M2[:, 2] + M1[:, 2]])


# ----------------------------------------------------------------------------
# distances
# ----------------------------------------------------------------------------


def _norm(V: np.ndarray) -> np.ndarray:
    return np.sqrt(np.einsum("ij,ij->i", V, V))


def _point_seg(P: np.ndarray, A: np.ndarray, B: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    d = B - A
    dd = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", P - A, d) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
    Q = A + t[:, None] * d
    return np.linalg.norm(P - Q, axis=1), Q


def _ball_pairs(tgt: Outline, P: np.ndarray, r) -> tuple[np.ndarray, np.ndarray]:
    """(point index, edge index) pairs: edges of tgt with an end within r of each point."""
    lists = tgt.tree.query_ball_point(P, r)
    counts = np.fromiter((len(l) for l in lists), int, len(lists))
    if counts.sum() == 0:
        return np.empty(0, int), np.empty(0, int)
    verts = np.concatenate([np.asarray(l, int) for l in lists if len(l)])
    pi = np.repeat(np.arange(len(P)), counts)
    return np.concatenate([pi, pi]), np.concatenate([verts, tgt.prev[verts]])


def _min_dist_points_to(P: np.ndarray, tgt: Outline):
    """Least distance from points P (tgt body frame) to tgt's edges: (d, index in P, foot point)."""
    lb = tgt.boundary_lower_bound(P)  # lower bound of each point's distance
    i0 = int(np.argmin(lb))
    ub = float(tgt.tree.query(P[i0])[0])
    keep = np.nonzero(lb <= ub + 1e-9 * (1.0 + ub))[0]  # never empty: holds for i0 up to rounding
    # a tighter upper bound from a subsample, then one bounded query: points farther than
    # ub + half_len from every vertex can never be candidates, and the tree skips them cheaply
    sub = keep[:: max(1, len(keep) // 64)]
    ub = min(ub, float(tgt.tree.query(P[sub])[0].min()))
    dv, _ = tgt.tree.query(P[keep], distance_upper_bound=ub + tgt.half_len + 1e-9 * (1.0 + ub))
    ub = float(dv.min())
    cand = keep[dv <= ub + tgt.half_len]
    pi, si = _ball_pairs(tgt, P[cand], ub + tgt.half_len + 1e-12)
    if len(pi) == 0:  # cannot happen (the nearest vertex is always in the ball); be safe
        j = int(np.argmin(dv))
        return float(dv[j]), int(keep[j]), tgt.points[int(tgt.tree.query(P[keep[j]])[1])]
    d, Q = _point_seg(P[cand][pi], tgt.seg_a[si], tgt.seg_b[si])
    j = int(np.argmin(d))
    return float(d[j]), int(cand[pi[j]]), Q[j]


def _dist_each_point(P: np.ndarray, tgt: Outline) -> np.ndarray:
    """Distance from every point of P (tgt body frame) to tgt's boundary."""
    if len(P) == 0:
        return np.empty(0)
    dv, _ = tgt.tree.query(P)
    pi, si = _ball_pairs(tgt, P, dv + tgt.half_len + 1e-12)
    d, _ = _point_seg(P[pi], tgt.seg_a[si], tgt.seg_b[si])
    out = np.full(len(P), np.inf)
    np.minimum.at(out, pi, d)
    return out


def crop_to_sector(section: m3d.CrossSection, a0: float, a1: float, r_in: float, r_out: float) -> list[np.ndarray]:
    """Loops of ``section`` inside the annular sector a0..a1, r_in..r_out (about the origin)."""
    n = max(8, int(math.ceil((a1 - a0) / 0.02)))
    a = np.linspace(a0, a1, n)
    outer = np.column_stack([r_out * np.cos(a), r_out * np.sin(a)])
    inner = np.column_stack([r_in * np.cos(a[::-1]), r_in * np.sin(a[::-1])]) if r_in > 0 else np.zeros((1, 2))
    wedge = m3d.CrossSection([np.ascontiguousarray(np.vstack([outer, inner]))], m3d.FillRule.Positive)
    return [np.asarray(p, float) for p in (section ^ wedge).to_polygons()]


# ----------------------------------------------------------------------------
# check records
# ----------------------------------------------------------------------------


def _record(name: str, passed: bool, value, limit, unit: str, message: str) -> Check:
    return Check(name, bool(passed), None if value is None else float(value),
                 None if limit is None else float(limit), unit, message)


# ----------------------------------------------------------------------------
# pair sweep: overlap area + clearance
# ----------------------------------------------------------------------------


@dataclass
class SweepResult:
    """Per-step overlap area and clearance of two planar bodies (world frame).

    ``clearance[k]`` > 0: least distance between the boundaries (the closest points
    are ``point_a[k]`` on A and ``point_b[k]`` on B).  When the bodies overlap by
    more than OVERLAP_AREA_TOL_MM2, ``clearance[k]`` = −(boundary penetration):
    the largest distance of a vertex of the overlap region from the boundary of
    the body it lies inside (how deep one outline reaches into the other; both
    points are that vertex).  It is an estimate, not the minimum translation
    distance: it is 0 when the bodies coincide or share edges, so the overlap
    area stays the authority for interference.
    """

    angle_a: np.ndarray
    angle_b: np.ndarray
    overlap_area: np.ndarray
    clearance: np.ndarray
    point_a: np.ndarray
    point_b: np.ndarray
    clearance_limit: float | None = None
    name: str = "motion"

    @property
    def n_steps(self) -> int:
        return len(self.overlap_area)

    @property
    def max_overlap(self) -> float:
        return float(self.overlap_area.max())

    @property
    def step_max_overlap(self) -> int:
        return int(np.argmax(self.overlap_area))

    @property
    def min_clearance(self) -> float:
        return float(self.clearance.min())

    @property
    def step_min_clearance(self) -> int:
        return int(np.argmin(self.clearance))

    @property
    def interfering_steps(self) -> np.ndarray:
        return np.nonzero(self.overlap_area > policy.OVERLAP_AREA_TOL_MM2)[0]

    def where_min_clearance(self) -> dict:
        k = self.step_min_clearance
        return {"step": k, "angle_a": float(self.angle_a[k]), "angle_b": float(self.angle_b[k]),
                "point": 0.5 * (self.point_a[k] + self.point_b[k]), "clearance": float(self.clearance[k])}

    def checks(self) -> list[dict]:
        k = self.step_max_overlap
        tol = policy.OVERLAP_AREA_TOL_MM2
        n_bad = len(self.interfering_steps)
        out = [_record(
            f"{self.name}.overlap_area", self.max_overlap <= tol, self.max_overlap, tol, "mm^2",
            f"max overlap {self.max_overlap:.3g} mm^2 at step {k} (angles {self.angle_a[k]:.6f}, "
            f"{self.angle_b[k]:.6f} rad); {n_bad} of {self.n_steps} steps interfere")]
        if self.clearance_limit is not None:
            w = self.where_min_clearance()
            ok = self.min_clearance >= self.clearance_limit
            out.append(_record(
                f"{self.name}.min_clearance", ok, self.min_clearance, self.clearance_limit, "mm",
                f"min clearance {self.min_clearance:.6g} mm at step {w['step']} near "
                f"({w['point'][0]:.4f}, {w['point'][1]:.4f})"))
        return out


def _clearance_step(A: Outline, B: Outline, Ma: np.ndarray, Mb: np.ndarray, inter) -> tuple[float, np.ndarray, np.ndarray]:
    """Signed clearance of one step (see SweepResult) and the two world points."""
    rel_ba = _compose(_inverse(Ma), Mb)  # B body -> A body
    rel_ab = _inverse(rel_ba)
    if inter is not None:
        polys = [np.asarray(p, float) for p in inter.to_polygons()]
        V = np.vstack(polys)
        da = _dist_each_point(V, A)  # overlap vertices live in A's body frame (A kept in its frame)
        db = _dist_each_point(_apply(rel_ab, V), B)
        depth = np.maximum(da, db)
        j = int(np.argmax(depth))
        pw = _apply(Ma, V[j:j + 1])[0]
        return -float(depth[j]), pw, pw
    PB = _apply(rel_ba, B.points)
    d1, i1, q1 = _min_dist_points_to(PB, A)  # B vertices -> A edges (A frame)
    PA = _apply(rel_ab, A.points)
    d2, i2, q2 = _min_dist_points_to(PA, B)  # A vertices -> B edges (B frame)
    if d1 <= d2:
        return d1, _apply(Ma, q1[None])[0], _apply(Ma, PB[i1:i1 + 1])[0]
    return d2, _apply(Mb, PA[i2:i2 + 1])[0], _apply(Mb, q2[None])[0]


def _pose_pair(poses_a, poses_b):
    """Matrices and angles of two pose sequences of equal length (a single Pose is held fixed)."""
    n = None
    for p in (poses_a, poses_b):
        if not isinstance(p, Pose):
            n = len(p) if n is None else n
    Ma, ang_a = _pose_stack(poses_a, n, "poses_a")
    Mb, ang_b = _pose_stack(poses_b, n, "poses_b")
    require(len(Ma) == len(Mb), "poses_b", len(Mb), f"must have as many steps as poses_a ({len(Ma)})")
    return Ma, ang_a, Mb, ang_b


def sweep_pair(profile_a, poses_a, profile_b, poses_b, chord_tol: float = policy.MOTION_CHORD_TOL_MM, *,
               clearance_limit: float | None = None, name: str = "motion",
               max_segment: float = policy.MOTION_MAX_SEGMENT_MM) -> SweepResult:
    """Overlap area and clearance of two planar bodies at every step of a motion.

    profile_a/b: Profile, Outline or list of closed polylines (body coordinates);
    poses_a/b: a Pose (held fixed), a sequence of Poses or an (n, 2, 3) array of
    affine matrices, one per step.  Overlap area from a manifold3d CrossSection
    intersection; clearance from the boundaries (cKDTree candidates, exact
    point-to-edge refinement in both directions: the exact distance between the
    two polylines when they do not cross).  clearance_limit (mm), when given,
    adds a minimum-clearance record to ``checks()``.
    """
    A, B = outline(profile_a, chord_tol, max_segment), outline(profile_b, chord_tol, max_segment)
    Ma, ang_a, Mb, ang_b = _pose_pair(poses_a, poses_b)
    N = len(Ma)
    area = np.zeros(N)
    clear = np.zeros(N)
    pa = np.zeros((N, 2))
    pb = np.zeros((N, 2))
    for k in range(N):
        rel = _compose(_inverse(Ma[k]), Mb[k])  # B body -> A body
        inter = A.section ^ B.section.transform(rel)
        area[k] = inter.area()
        clear[k], a_pt, b_pt = _clearance_step(A, B, Ma[k], Mb[k], inter if area[k] > policy.OVERLAP_AREA_TOL_MM2 else None)
        pa[k], pb[k] = a_pt, b_pt
    return SweepResult(ang_a, ang_b, area, clear, pa, pb, clearance_limit, name)


def sweep_pair_windowed(profile_a, poses_a, profile_b, poses_b, reach: float,
                        chord_tol: float = policy.MOTION_CHORD_TOL_MM, *, clearance_limit: float | None = None,
                        name: str = "motion", max_segment: float = policy.MOTION_MAX_SEGMENT_MM,
                        window_sides: int = 48) -> SweepResult:
    """:func:`sweep_pair` for a large body A and a small body B (a ring and a planet, a sun and a planet).

    The motion is taken in A's body frame and cut into runs of steps over which B's centre moves by
    at most half B's radius; for each run A is cropped (one manifold3d boolean) to the convex hull of
    the discs of radius ``radius_B + reach`` about B's centres, and the run is swept against that
    window.  B lies inside the window, so the overlap area is exact; the cut edges of the window lie
    at least ``reach`` from B, so every clearance below ``reach`` is exact too and a larger one is
    reported as ``reach`` (a lower bound).  Steps are as in :func:`sweep_pair`; points are world points.
    """
    reach = require_positive("reach", reach, "mm")
    A, B = outline(profile_a, chord_tol, max_segment), outline(profile_b, chord_tol, max_segment)
    Ma, ang_a, Mb, ang_b = _pose_pair(poses_a, poses_b)
    N = len(Ma)
    rel = np.array([_compose(_inverse(Ma[k]), Mb[k]) for k in range(N)])  # B body -> A body
    cB = np.einsum("kij,j->ki", rel[:, :, :2], B.center) + rel[:, :, 2]
    R = (B.radius + reach) / math.cos(math.pi / window_sides)  # the polygon holds the disc
    ring = np.column_stack([np.cos(np.arange(window_sides) * 2 * math.pi / window_sides),
                            np.sin(np.arange(window_sides) * 2 * math.pi / window_sides)]) * R
    area, clear = np.zeros(N), np.zeros(N)
    pa, pb = np.zeros((N, 2)), np.zeros((N, 2))
    ident = Pose()
    k0 = 0
    while k0 < N:
        k1 = k0 + 1
        while k1 < N and np.linalg.norm(cB[k1] - cB[k0]) <= 0.5 * B.radius:
            k1 += 1
        pts = (cB[k0:k1, None, :] + ring[None]).reshape(-1, 2)
        window = m3d.CrossSection.hull_points(np.ascontiguousarray(pts))
        polys = [np.asarray(q, float) for q in (A.section ^ window).to_polygons()]
        polys = [q for q in polys if len(q) >= 3]
        if not polys:  # nothing of A within reach of B over this run
            area[k0:k1], clear[k0:k1] = 0.0, reach
            pa[k0:k1] = pb[k0:k1] = _apply(Ma[k0], cB[k0:k0 + 1])[0]
        else:
            r = sweep_pair(Outline(polys, max_segment), ident, B, rel[k0:k1], chord_tol, max_segment=max_segment)
            area[k0:k1] = r.overlap_area
            clear[k0:k1] = np.minimum(r.clearance, reach)
            for j, k in enumerate(range(k0, k1)):
                pa[k] = _apply(Ma[k], r.point_a[j:j + 1])[0]
                pb[k] = _apply(Ma[k], r.point_b[j:j + 1])[0]
        k0 = k1
    return SweepResult(ang_a, ang_b, area, clear, pa, pb, clearance_limit, name)


# ----------------------------------------------------------------------------
# gear pair: free rotation, backlash, transmission error, contact count
# ----------------------------------------------------------------------------


def _rot_hits(P: np.ndarray, C: np.ndarray, tgt: Outline, sign: float, w: float, rho: np.ndarray, lb: np.ndarray):
    """First entering hit of points P rotating by sign·δ about C (all in tgt's body frame) on tgt's boundary.

    rho: distance of each point from C; lb: lower bound of its distance from tgt's
    boundary (Outline.boundary_lower_bound).  Returns (delta, edge, t) per point: delta
    in [0, w] or inf when no entering hit happens within the window w; edge index
    and parameter of the hit.  An entering hit is one where the point's velocity
    points into tgt's material (material lies left of each edge), so exits and
    grazing touches do not count.
    """
    m = len(P)
    delta = np.full(m, np.inf)
    edge = np.full(m, -1)
    tpar = np.zeros(m)
    chord_factor = 2.0 * math.sin(0.5 * min(w, math.pi))
    keep = np.nonzero(lb <= chord_factor * rho)[0]
    if len(keep) == 0:
        return delta, edge, tpar
    dv, _ = tgt.tree.query(P[keep])
    reach = chord_factor * rho[keep] + tgt.half_len + 1e-12
    cand = keep[dv <= reach]
    if len(cand) == 0:
        return delta, edge, tpar
    reach = reach[dv <= reach]
    # candidates in chunks: a wide window (disengaged teeth) must not build a huge pair list at once
    n_near = tgt.tree.query_ball_point(P[cand[:16]], reach[:16], return_length=True)
    chunk = max(1, int(400000 // (float(np.mean(n_near)) + 1.0)))
    for c0 in range(0, len(cand), chunk):
        _rot_hits_chunk(P, C, tgt, sign, w, rho, cand[c0:c0 + chunk], reach[c0:c0 + chunk], delta, edge, tpar)
    return delta, edge, tpar


def _rot_hits_chunk(P, C, tgt: Outline, sign: float, w: float, rho, cand, reach, delta, edge, tpar) -> None:
    """Circle-edge intersections of _rot_hits for one chunk of candidate points (fills delta, edge, tpar)."""
    pi, si = _ball_pairs(tgt, P[cand], reach)
    if len(pi) == 0:
        return
    p = P[cand][pi] - C
    r2 = rho[cand][pi] ** 2
    a = tgt.seg_a[si] - C
    d = tgt.seg_b[si] - tgt.seg_a[si]
    qa = np.einsum("ij,ij->i", d, d)
    qb = 2.0 * np.einsum("ij,ij->i", a, d)
    qc = np.einsum("ij,ij->i", a, a) - r2
    disc = qb * qb - 4.0 * qa * qc
    ok = disc >= 0.0
    sq = np.sqrt(np.where(ok, disc, 0.0))
    best = np.full(len(pi), np.inf)
    best_t = np.zeros(len(pi))
    for root in ((-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)):
        t = root
        valid = ok & (t >= -1e-12) & (t <= 1.0 + 1e-12)
        t = np.clip(t, 0.0, 1.0)
        q = a + t[:, None] * d
        ang = sign * np.arctan2(p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0], np.einsum("ij,ij->i", p, q))
        ang = np.where(ang < -_ANG_EPS, ang + 2.0 * math.pi, np.maximum(ang, 0.0))
        # velocity of the moving point at q: sign * perp(q); material normal of the edge: perp(d)
        entering = sign * (q[:, 0] * d[:, 0] + q[:, 1] * d[:, 1]) > 0.0  # perp(q)·perp(d) = q·d
        valid &= entering & (ang <= w)
        better = valid & (ang < best)
        best = np.where(better, ang, best)
        best_t = np.where(better, t, best_t)
    # reduce per point
    order = np.lexsort((best, pi))
    first = np.ones(len(order), bool)
    first[1:] = pi[order][1:] != pi[order][:-1]
    sel = order[first]
    idx = cand[pi[sel]]
    delta[idx] = best[sel]
    edge[idx] = si[sel]
    tpar[idx] = best_t[sel]


@dataclass
class _FreeRotation:
    delta: float  # free rotation (rad, >= 0), inf if none within the search limit
    n_pairs: int  # distinct contact zones within the contact tolerance at the touching position
    point: np.ndarray  # world point of the first contact (nan if none)


def _cluster_count(pos: np.ndarray, loop: np.ndarray, perimeter: np.ndarray, merge: float) -> int:
    """Number of groups of boundary positions (arc length along driven loops), gaps > merge split groups."""
    n = 0
    for lid in np.unique(loop):
        s = np.sort(pos[loop == lid])
        gaps = np.diff(np.concatenate([s, [s[0] + perimeter[lid]]]))
        k = int(np.count_nonzero(gaps > merge))
        n += max(k, 1)
    return n


def _free_rotation(drv: Outline, dvn: Outline, P1: np.ndarray, C1: np.ndarray, P2: np.ndarray,
                   rho1: np.ndarray, lb1: np.ndarray, rho2: np.ndarray, lb2: np.ndarray,
                   M2: np.ndarray, body_sign: float, w0: float, w_max: float, tol: float, merge: float) -> _FreeRotation:
    """Free rotation of the driven body (body sense body_sign) until first contact with the driver.

    P1: driven vertices in the driver frame, C1: driven centre in the driver frame;
    P2: driver vertices in the driven frame (driven centre at its origin);
    rho*/lb*: their distances from the rotation centre / lower bounds of their
    distances from the other body.
    Side 1: driven vertices hit driver edges, rotating by +body_sign about C1.
    Side 2: driver vertices hit driven edges, rotating by −body_sign about 0.
    """
    w = w0
    while True:
        d1, e1, t1 = _rot_hits(P1, C1, drv, body_sign, w, rho1, lb1)
        d2, e2, t2 = _rot_hits(P2, np.zeros(2), dvn, -body_sign, w, rho2, lb2)
        dmin = min(d1.min(), d2.min())
        if not np.isfinite(dmin):
            if w >= w_max:
                return _FreeRotation(math.inf, 0, np.full(2, np.nan))
            w = min(4.0 * w, w_max)
            continue
        rmin = max(min(rho1[np.isfinite(d1)].min(initial=np.inf), rho2[np.isfinite(d2)].min(initial=np.inf)), 1e-9)
        need = dmin + 2.0 * tol / rmin
        if need > w and w < w_max:
            w = min(need, w_max)
            continue
        break
    # contact zones at the touching position: gap (arc at the point's radius) within tol
    f1, f2 = np.isfinite(d1), np.isfinite(d2)
    c1 = np.nonzero(f1)[0][(d1[f1] - dmin) * rho1[f1] <= tol]
    c2 = np.nonzero(f2)[0][(d2[f2] - dmin) * rho2[f2] <= tol]
    pos = np.concatenate([dvn.arclen[c1], dvn.arclen[e2[c2]] + t2[c2] * dvn.seg_len[e2[c2]]])
    loop = np.concatenate([dvn.loop_id[c1], dvn.loop_id[e2[c2]]])
    n_pairs = _cluster_count(pos, loop, dvn.perimeter, merge)
    # world point of the first contact (driven rotated into contact)
    if d1.min() <= d2.min():
        i = int(np.argmin(d1))
        pt_driven_frame = dvn.points[i]
        ang = body_sign * dmin
    else:
        i = int(np.argmin(d2))
        k = e2[i]
        pt_driven_frame = dvn.seg_a[k] + t2[i] * (dvn.seg_b[k] - dvn.seg_a[k])
        ang = body_sign * dmin
    c, s = math.cos(ang), math.sin(ang)
    pw = _apply(M2, np.array([[c * pt_driven_frame[0] - s * pt_driven_frame[1], s * pt_driven_frame[0] + c * pt_driven_frame[1]]]))[0]
    return _FreeRotation(float(dmin), n_pairs, pw)


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

    def checks(self, te_limit_rad: float | None = None, backlash_range_mm: tuple[float, float] | None = None) -> list[dict]:
        tol = policy.OVERLAP_AREA_TOL_MM2
        k = int(np.argmax(self.overlap_area))
        out = [_record(f"{self.name}.overlap_area", self.max_overlap <= tol, self.max_overlap, tol, "mm^2",
                       f"max overlap {self.max_overlap:.3g} mm^2 at phi = {self.phi[k]:.6f} rad (step {k})")]
        bl = self.backlash_mm
        finite = np.isfinite(bl)
        n_int = int(np.count_nonzero(self.overlap_area > tol))
        n_free = int(np.count_nonzero(~finite)) - n_int
        kmin = int(np.argmin(np.where(finite, bl, np.inf))) if np.any(finite) else 0
        lo, hi = backlash_range_mm if backlash_range_mm is not None else (0.0, None)
        ok = bool(np.all(finite)) and self.backlash_min_mm > lo and (hi is None or self.backlash_max_mm <= hi)
        out.append(_record(f"{self.name}.backlash", ok, self.backlash_min_mm, lo, "mm",
                           f"backlash {self.backlash_min_mm:.5f} .. {self.backlash_max_mm:.5f} mm "
                           f"(min at phi = {self.phi[kmin]:.6f} rad); "
                           f"{n_int} steps interfere, {n_free} steps without contact within the search angle"
                           + (f"; allowed {lo} .. {hi} mm" if backlash_range_mm is not None else "")))
        mn = int(min(self.pairs_drive.min(), self.pairs_coast.min()))
        out.append(_record(f"{self.name}.contact_continuity", mn >= 1, mn, 1, "pairs",
                           f"least tooth pairs in contact {mn}; mean on drive flank {self.contact_ratio_mean:.4f}"))
        if te_limit_rad is not None:
            pp = self.te_drive_pp
            out.append(_record(f"{self.name}.transmission_error", pp <= te_limit_rad, pp, te_limit_rad, "rad",
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
    w_fwd = w_back = min(1e-3, max_angle)
    for k in range(N):
        M1 = Pose(s1 * theta[k], (0.0, 0.0), tuple(c1)).matrix()
        M2 = Pose(s2 * phis[k], (0.0, 0.0), tuple(c2)).matrix()
        rel21 = _compose(_inverse(M1), M2)  # driven body -> driver body
        rel12 = _inverse(rel21)
        area[k] = (drv.section ^ dvn.section.transform(rel21)).area()
        if area[k] > policy.OVERLAP_AREA_TOL_MM2:  # interfering: free rotations have no meaning
            fwd[k] = back[k] = np.nan
            ptc[k] = ptd[k] = np.nan
            continue
        P1 = _apply(rel21, dvn.points)
        C1 = rel21[:, 2]
        P2 = _apply(rel12, drv.points)
        rho1 = _norm(P1 - C1)
        lb1 = drv.boundary_lower_bound(P1)
        rho2 = _norm(P2)
        lb2 = dvn.boundary_lower_bound(P2)
        geo = (P1, C1, P2, rho1, lb1, rho2, lb2, M2)
        f = _free_rotation(drv, dvn, *geo, s2, w_fwd, max_angle, contact_tol, contact_merge)
        b = _free_rotation(drv, dvn, *geo, -s2, w_back, max_angle, contact_tol, contact_merge)
        fwd[k], pc[k], ptc[k] = f.delta, f.n_pairs, f.point
        back[k], pd[k], ptd[k] = b.delta, b.n_pairs, b.point
        # start the next step's search just above this step's answer
        if math.isfinite(f.delta):
            w_fwd = min(max(1.25 * f.delta, 1e-6), max_angle)
        if math.isfinite(b.delta):
            w_back = min(max(1.25 * b.delta, 1e-6), max_angle)
    if r_ref is None:
        pts = np.vstack([ptd, ptc])
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        rr = np.full(N, float(np.mean(np.linalg.norm(pts - c2, axis=1))) if len(pts) else np.nan)
    elif callable(r_ref):
        rr = np.array([float(r_ref(p)) for p in phis])
    else:
        rr = np.broadcast_to(np.asarray(r_ref, float), (N,)).copy()
    return TransmissionResult(phis, theta, area, fwd, back, rr, pd, pc, ptd, ptc, float(contact_tol), name)


# ----------------------------------------------------------------------------
# 3D: intersection volume of two meshes over a motion
# ----------------------------------------------------------------------------


def _manifold(mesh, name: str) -> m3d.Manifold:
    if isinstance(mesh, m3d.Manifold):
        return mesh
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        V, F = mesh.vertices, mesh.faces
    else:
        try:
            V, F = mesh
        except (TypeError, ValueError):
            raise InputError(name, type(mesh).__name__, "must be (vertices, faces), an object with .vertices/.faces or a manifold3d.Manifold") from None
    V = np.ascontiguousarray(np.asarray(V, np.float64))
    F = np.ascontiguousarray(np.asarray(F, np.uint64))
    require(V.ndim == 2 and V.shape[1] == 3, name, V.shape, "vertices must be (n, 3)")
    require(F.ndim == 2 and F.shape[1] == 3, name, F.shape, "faces must be (m, 3) triangles")
    man = m3d.Manifold(m3d.Mesh64(V, F))
    require(str(man.status()).endswith("NoError") and not man.is_empty(), name, str(man.status()),
            "must be a closed, oriented 2-manifold mesh")
    return man


@dataclass
class Sweep3DResult:
    """Per-step intersection volume (mm³) and, when searched, gap (mm) of two solids."""

    overlap_volume: np.ndarray
    gap: np.ndarray | None
    name: str = "motion3d"

    @property
    def max_overlap(self) -> float:
        return float(self.overlap_volume.max())

    @property
    def step_max_overlap(self) -> int:
        return int(np.argmax(self.overlap_volume))

    def checks(self) -> list[dict]:
        tol = policy.OVERLAP_VOLUME_TOL_MM3
        k = self.step_max_overlap
        return [_record(f"{self.name}.overlap_volume", self.max_overlap <= tol, self.max_overlap, tol, "mm^3",
                        f"max overlap volume {self.max_overlap:.3g} mm^3 at step {k}; "
                        f"{int(np.count_nonzero(self.overlap_volume > tol))} of {len(self.overlap_volume)} steps interfere")]


def sweep_solids_3d(mesh_a, poses_a, mesh_b, poses_b, *, search_length: float | None = None,
                    name: str = "motion3d") -> Sweep3DResult:
    """Intersection volume of two triangle meshes at every step (manifold3d booleans).

    mesh_a/b: (vertices (n,3), faces (m,3)), an object with .vertices/.faces
    (e.g. trimesh) or a manifold3d.Manifold; poses_a/b: (n, 4, 4) homogeneous
    matrices or one (4, 4) matrix held fixed.  search_length (mm), when given,
    also reports the gap between the solids (manifold3d min_gap, capped at
    search_length; 0 when they touch or overlap).
    """
    A, B = _manifold(mesh_a, "mesh_a"), _manifold(mesh_b, "mesh_b")

    def stack(T, nm):
        T = np.asarray(T, float)
        if T.ndim == 2:
            T = T[None]
        require(T.ndim == 3 and T.shape[1:] == (4, 4), nm, T.shape, "must be (4, 4) or (n, 4, 4) matrices")
        require(bool(np.all(np.isfinite(T))), nm, "non-finite", "poses must be finite")
        return T

    Ta, Tb = stack(poses_a, "poses_a"), stack(poses_b, "poses_b")
    N = max(len(Ta), len(Tb))
    require(len(Ta) in (1, N) and len(Tb) in (1, N), "poses_b", len(Tb), f"must have 1 or {N} poses like poses_a")
    Ta, Tb = np.broadcast_to(Ta, (N, 4, 4)), np.broadcast_to(Tb, (N, 4, 4))
    vol = np.zeros(N)
    gap = np.zeros(N) if search_length is not None else None
    if search_length is not None:
        require_positive("search_length", search_length, "mm")
    for k in range(N):
        Ak = A.transform(np.ascontiguousarray(Ta[k][:3, :4]))
        Bk = B.transform(np.ascontiguousarray(Tb[k][:3, :4]))
        vol[k] = (Ak ^ Bk).volume()
        if gap is not None:
            gap[k] = Ak.min_gap(Bk, float(search_length))
    return Sweep3DResult(vol, gap, name)
