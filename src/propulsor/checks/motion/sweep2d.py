"""Two planar bodies, one rigid pose each per step: overlap area (manifold3d ``CrossSection``
intersection) and the least distance between the boundaries (exact for the sampled polylines)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import manifold3d as m3d
import numpy as np

from ... import policy
from ...check import Check
from ...errors import require, require_positive
from .outlines import FacingCut, Outline, outline
from .poses import Pose, apply_pose, compose_poses, inverse_pose, pose_stack
from .distance import check_record
from .crossing import certainly_apart
from .nearest import dist_each, nearest_edge
from .sweep_steps import apart_steps, move_each

__all__ = ['SweepResult', 'sweep_pair', 'sweep_pair_windowed']


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

    def checks(self) -> list[Check]:
        k = self.step_max_overlap
        tol = policy.OVERLAP_AREA_TOL_MM2
        n_bad = len(self.interfering_steps)
        out = [check_record(
            f"{self.name}.overlap_area", self.max_overlap <= tol, self.max_overlap, tol, "mm^2",
            f"max overlap {self.max_overlap:.3g} mm^2 at step {k} (angles {self.angle_a[k]:.6f}, "
            f"{self.angle_b[k]:.6f} rad); {n_bad} of {self.n_steps} steps interfere")]
        if self.clearance_limit is not None:
            w = self.where_min_clearance()
            ok = self.min_clearance >= self.clearance_limit
            out.append(check_record(
                f"{self.name}.min_clearance", ok, self.min_clearance, self.clearance_limit, "mm",
                f"min clearance {self.min_clearance:.6g} mm at step {w['step']} near "
                f"({w['point'][0]:.4f}, {w['point'][1]:.4f})"))
        return out


def _boundary_distance(A: Outline, B: Outline, Ma: np.ndarray, Mb: np.ndarray, rel_ba: np.ndarray,
                       rel_ab: np.ndarray):
    """Least distance between the boundaries of A and B at one step (world poses Ma, Mb; rel_ba: B's body to A's,
    rel_ab its inverse), exact when they do not cross: (d, world point on A, world point on B, B's vertices in A's
    frame, A's in B's)."""
    PB = apply_pose(rel_ba, B.points)
    PA = apply_pose(rel_ab, A.points)
    # B vertices -> A edges (A frame) and A vertices -> B edges (B frame); the one with more vertices searched for an
    # answer within the other's only (nearest_edge's cap: inf where there is none, which the choice below skips; the
    # same distance, the tie among equally near pairs taken as nearest_edge says)
    if len(B.points) <= len(A.points):
        d1, i1, q1 = nearest_edge(PB, A, B)
        d2, i2, q2 = nearest_edge(PA, B, A, d1)
    else:
        d2, i2, q2 = nearest_edge(PA, B, A)
        d1, i1, q1 = nearest_edge(PB, A, B, d2)
    if d1 <= d2:
        return d1, apply_pose(Ma, q1[None])[0], apply_pose(Ma, PB[i1:i1 + 1])[0], PB, PA
    return d2, apply_pose(Mb, PA[i2:i2 + 1])[0], apply_pose(Mb, q2[None])[0], PB, PA


def _penetration(A: Outline, B: Outline, Ma: np.ndarray, rel_ab: np.ndarray, inter) -> tuple[float, np.ndarray,
                                                                                              np.ndarray]:
    """Signed clearance of an overlapping step (see SweepResult: minus the boundary penetration) and its point
    (Ma: A's world pose, rel_ab: A's body to B's)."""
    polys = [np.asarray(p, float) for p in inter.to_polygons()]
    V = np.vstack(polys)
    da = dist_each(V, A)  # overlap vertices live in A's body frame (A kept in its frame)
    db = dist_each(apply_pose(rel_ab, V), B)
    depth = np.maximum(da, db)
    j = int(np.argmax(depth))
    pw = apply_pose(Ma, V[j:j + 1])[0]
    return -float(depth[j]), pw, pw


def _pose_pair(poses_a, poses_b):
    """Matrices and angles of two pose sequences of equal length (a single Pose is held fixed)."""
    n = None
    for p in (poses_a, poses_b):
        if not isinstance(p, Pose):
            n = len(p) if n is None else n
    Ma, ang_a = pose_stack(poses_a, n, "poses_a")
    Mb, ang_b = pose_stack(poses_b, n, "poses_b")
    require(len(Ma) == len(Mb), "poses_b", len(Mb), f"must have as many steps as poses_a ({len(Ma)})")
    return Ma, ang_a, Mb, ang_b


def sweep_pair(profile_a, poses_a, profile_b, poses_b, chord_tol: float = policy.MOTION_CHORD_TOL_MM, *,
               clearance_limit: float | None = None, name: str = "motion",
               max_segment: float = policy.MOTION_MAX_SEGMENT_MM, section_b=None) -> SweepResult:
    """Overlap area and clearance of two planar bodies at every step of a motion.

    profile_a/b: Profile, Outline or list of closed polylines (body coordinates);
    poses_a/b: a Pose (held fixed), a sequence of Poses or an (n, 2, 3) array of
    affine matrices, one per step.  Overlap area from a manifold3d CrossSection
    intersection (0 without it at a step where the boundaries are certainly apart:
    :func:`~propulsor.checks.motion.crossing.certainly_apart`); clearance from the boundaries (the compiled grid search
    of :mod:`.nearest`, exact point-to-edge distances in both directions, the body of more vertices searched only for
    an answer within the other way's: the exact distance between the two polylines when they do not cross).
    clearance_limit (mm), when given, adds a minimum-clearance record to ``checks()``.  ``section_b()``: a part of
    B's section that holds every point B has in common with A at every step, asked for at the first step that takes
    the boolean (the intersections take it; the distances take B's whole outline).
    """
    A, B = outline(profile_a, chord_tol, max_segment), outline(profile_b, chord_tol, max_segment)
    sec_b = None
    Ma, ang_a, Mb, ang_b = _pose_pair(poses_a, poses_b)
    N = len(Ma)
    area = np.zeros(N)
    clear = np.zeros(N)
    pa = np.zeros((N, 2))
    pb = np.zeros((N, 2))
    overlapped = False
    # the steps where the bodies are certainly apart in one compiled loop (sweep_steps: the same values), the others
    # (and the one where that loop stops) step by step here
    rel_ba = np.array([compose_poses(inverse_pose(Ma[k]), Mb[k]) for k in range(N)]).reshape(N, 2, 3)
    rel_ab = np.array([inverse_pose(r) for r in rel_ba]).reshape(N, 2, 3)
    k = 0
    while k < N:
        if not overlapped:
            k = apart_steps(A, B, rel_ba, rel_ab, Ma, Mb, k, clear, pa, pb)
            if k >= N:
                break
        # the boundaries' least distance first: where it shows the bodies apart, their common area is 0
        # without the boolean (crossing.certainly_apart); after an overlapping step, the boolean first
        d = None
        if not overlapped:
            d, a_pt, b_pt, PB, PA = _boundary_distance(A, B, Ma[k], Mb[k], rel_ba[k], rel_ab[k])
        if d is None or not certainly_apart(A, B, PB, PA, d):
            if sec_b is None:
                sec_b = B.section if section_b is None else section_b()
            inter = A.section ^ sec_b.transform(rel_ba[k])
            area[k] = inter.area()
            if area[k] > policy.OVERLAP_AREA_TOL_MM2:
                d, a_pt, b_pt = _penetration(A, B, Ma[k], rel_ab[k], inter)
            elif d is None:
                d, a_pt, b_pt, _, _ = _boundary_distance(A, B, Ma[k], Mb[k], rel_ba[k], rel_ab[k])
        overlapped = area[k] > policy.OVERLAP_AREA_TOL_MM2
        clear[k], pa[k], pb[k] = d, a_pt, b_pt
        k += 1
    return SweepResult(ang_a, ang_b, area, clear, pa, pb, clearance_limit, name)


#: how much wider (rad) than a run needs the windowed sweep cuts the small body (:class:`.outlines.FacingCut`, kept
#: for the runs after while it holds them)
FACING_SPARE_RAD = 0.3


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
    reported as ``reach`` (a lower bound).  Steps are as in :func:`sweep_pair`; points are world points.  The
    intersections take B cut to the sector about its axis that faces the run's window (:class:`.outlines.FacingCut`:
    the same areas and polygons, among fewer vertices).
    """
    reach = require_positive("reach", reach, "mm")
    A, B = outline(profile_a, chord_tol, max_segment), outline(profile_b, chord_tol, max_segment)
    Ma, ang_a, Mb, ang_b = _pose_pair(poses_a, poses_b)
    N = len(Ma)
    rel = np.array([compose_poses(inverse_pose(Ma[k]), Mb[k]) for k in range(N)])  # B body -> A body
    cB = np.einsum("kij,j->ki", rel[:, :, :2], B.center) + rel[:, :, 2]
    R = (B.radius + reach) / math.cos(math.pi / window_sides)  # the polygon holds the disc
    ring = np.column_stack([np.cos(np.arange(window_sides) * 2 * math.pi / window_sides),
                            np.sin(np.arange(window_sides) * 2 * math.pi / window_sides)]) * R
    area, clear = np.zeros(N), np.zeros(N)
    pa, pb = np.zeros((N, 2)), np.zeros((N, 2))
    ident = Pose()
    facing = FacingCut(B, FACING_SPARE_RAD)
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
            pa[k0:k1] = pb[k0:k1] = apply_pose(Ma[k0], cB[k0:k0 + 1])[0]
        else:
            crop = Outline(polys, max_segment)
            r = sweep_pair(crop, ident, B, rel[k0:k1], chord_tol, max_segment=max_segment,
                           section_b=lambda crop=crop, run=rel[k0:k1]: facing.section(
                               np.vstack([apply_pose(inverse_pose(r), crop.points) for r in run])))
            area[k0:k1] = r.overlap_area
            clear[k0:k1] = np.minimum(r.clearance, reach)
            pa[k0:k1] = move_each(Ma[k0:k1], r.point_a)  # each apply_pose(Ma[k], point[None])[0]
            pb[k0:k1] = move_each(Ma[k0:k1], r.point_b)
        k0 = k1
    return SweepResult(ang_a, ang_b, area, clear, pa, pb, clearance_limit, name)
