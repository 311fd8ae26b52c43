"""Intersection volume (and optional gap) of two triangle meshes under 4x4 poses, for parts that are
not prismatic (manifold3d booleans)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy
from ...check import Check
from ...errors import require, require_positive
from .distance import check_record

__all__ = ['box_corners', 'box_of', 'box_gap', 'Sweep3DResult', 'sweep_solids_3d']


def box_corners(man) -> np.ndarray:
    """The 8 corners (homogeneous, (8, 4)) of a manifold's axis-aligned bounding box, the least first
    and the greatest last."""
    bb = man.bounding_box()
    return np.array([[x, y, z, 1.0] for x in (bb[0], bb[3]) for y in (bb[1], bb[4]) for z in (bb[2], bb[5])])


def box_of(corners: np.ndarray, T: np.ndarray):
    """(least, greatest) corner of the axis-aligned box around box corners moved by the 4x4 matrix T."""
    q = corners @ T.T
    return q[:, :3].min(axis=0), q[:, :3].max(axis=0)


def box_gap(a, b) -> float:
    """Distance between two axis-aligned boxes (0 when they overlap)."""
    d = np.maximum(0.0, np.maximum(a[0] - b[1], b[0] - a[1]))
    return float(np.linalg.norm(d))


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

    def checks(self) -> list[Check]:
        tol = policy.OVERLAP_VOLUME_TOL_MM3
        k = self.step_max_overlap
        return [check_record(f"{self.name}.overlap_volume", self.max_overlap <= tol, self.max_overlap, tol, "mm^3",
                        f"max overlap volume {self.max_overlap:.3g} mm^3 at step {k}; "
                        f"{int(np.count_nonzero(self.overlap_volume > tol))} of {len(self.overlap_volume)} steps interfere")]


def sweep_solids_3d(mesh_a, poses_a, mesh_b, poses_b, *, search_length: float | None = None,
                    name: str = "motion3d", skip_apart: bool = False) -> Sweep3DResult:
    """Intersection volume of two triangle meshes at every step (manifold3d booleans).

    mesh_a/b: (vertices (n,3), faces (m,3)), an object with .vertices/.faces
    (e.g. trimesh) or a manifold3d.Manifold; poses_a/b: (n, 4, 4) homogeneous
    matrices or one (4, 4) matrix held fixed; poses_b None: B stays where it is (not
    transformed).  search_length (mm), when given, also reports the gap between the
    solids (manifold3d min_gap, capped at search_length; 0 when they touch or overlap; a step with a
    gap > 0 has volume 0 without a boolean).
    skip_apart (with search_length): a step whose bodies' boxes (the transformed corners of
    their bounding boxes, a conservative bound) lie search_length or more apart neither
    overlaps nor comes within search_length: it is recorded as volume 0 and gap
    search_length without a boolean.

    The gap is sought where it is cheap first (:class:`_Gaps`); the value is min_gap's with search_length, bit for
    bit.
    """
    from ...solids.kernel import manifold  # here: the kernel module loads OCP, which the 2D proofs never need

    A, B = manifold(mesh_a, "mesh_a"), manifold(mesh_b, "mesh_b")
    b_fixed = poses_b is None
    if b_fixed:
        poses_b = np.eye(4)

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
    if skip_apart:
        require(search_length is not None, "skip_apart", skip_apart, "needs search_length")
        corners_a, corners_b = box_corners(A), box_corners(B)
    gaps = _Gaps(A, B, float(search_length)) if gap is not None else None
    for k in range(N):
        if skip_apart:
            box_b = box_of(corners_b, Tb[k]) if not b_fixed else (corners_b[0, :3], corners_b[-1, :3])
            if box_gap(box_of(corners_a, Ta[k]), box_b) >= search_length:
                gap[k] = gaps.apart()
                continue
        Ak = A.transform(np.ascontiguousarray(Ta[k][:3, :4]))
        Bk = B if b_fixed else B.transform(np.ascontiguousarray(Tb[k][:3, :4]))
        if gaps is not None:
            gap[k] = gaps.at(Ak, Bk, Ta[k], None if b_fixed else Tb[k])
            if gap[k] > 0.0:  # apart: the intersection is empty, its volume 0 without a boolean
                continue
        vol[k] = (Ak ^ Bk).volume()
    return Sweep3DResult(vol, gap, name)


class _Gaps:
    """The gaps of a sweep's steps, each equal to ``Ak.min_gap(Bk, W)`` bit for bit, found with fewer triangle pairs.

    manifold3d's min_gap is 0 where the bodies intersect, else the square root of the least of W² and the squared
    distances of the triangle pairs whose boxes, widened by the search length, meet: so a smaller search length gives
    the same value wherever the least distance lies within it (only pairs farther apart are left out).  Hence:

    * after a step with a gap below W, the next is sought within that gap plus ``policy.SWEEP3D_GAP_GUESS_MM`` (or
      twice its last change, if more) and kept where found within; sought again within W where not (the balancer's
      hull envelope, 13 mm from the unit at every step, W = 20 mm: a step's min_gap 68 -> 22 ms, most of what is left
      the intersection min_gap tests first);
    * after a step with no gap below W (or at the first), the bodies' convex hulls are measured first: hulls that do
      not intersect and lie W or more apart hold bodies W or more apart (each body lies in its hull), whose min_gap
      is sqrt(W²) = W; measured in full where the hulls come closer."""

    def __init__(self, A, B, W: float):
        self.A, self.B, self.W = A, B, W
        self.last, self.change = None, 0.0  # the last step's gap when below W, and its change from the step before
        self._hulls = None

    def hulls(self):
        if self._hulls is None:
            self._hulls = (self.A.hull(), self.B.hull())
        return self._hulls

    def apart(self) -> float:
        """A step whose bodies' boxes lie W or more apart (the caller's bound): its gap, W, and no guess for the next
        step (a gap of W is no gap found)."""
        self.last, self.change = None, 0.0
        return self.W

    def at(self, Ak, Bk, Ta, Tb) -> float:
        W, last = self.W, self.last
        g = None
        if last is not None:
            s1 = last + max(policy.SWEEP3D_GAP_GUESS_MM, 2.0 * abs(self.change))
            if s1 < W:
                r = Ak.min_gap(Bk, s1)
                if r < s1:
                    g = r
        else:
            ha, hb = self.hulls()
            hak = ha.transform(np.ascontiguousarray(Ta[:3, :4]))
            hbk = hb if Tb is None else hb.transform(np.ascontiguousarray(Tb[:3, :4]))
            W1 = W * (1.0 + 1e-9) + 1e-9  # beyond W by more than the distances' rounding
            if hak.min_gap(hbk, W1) >= W1:
                g = math.sqrt(W * W)  # what min_gap returns when nothing lies within W
        if g is None:
            g = Ak.min_gap(Bk, W)
        if g < W:
            self.change = 0.0 if last is None else g - last
            self.last = g
        else:
            self.apart()  # nothing within W: no guess for the next step
        return g
