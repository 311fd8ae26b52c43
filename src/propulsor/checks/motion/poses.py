"""Rigid planar poses: 2x3 affine matrices, their stacks, products and inverses."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ...errors import require
from ...fused import fma as _fma  # noqa: F401  (sweep_steps takes it from here)
from ...nbcache import bind

__all__ = ['Pose', 'poses_from_angles', 'rotation_matrices', 'pose_stack', 'apply_pose', 'inverse_pose', 'compose_poses']


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


def rotation_matrices(angles, centres=None) -> np.ndarray:
    """(n, 2, 3) affine matrices: rotation by each angle about the origin, then translation to each
    centre ((n, 2); none: no translation)."""
    angles = np.asarray(angles, float)
    c, s = np.cos(angles), np.sin(angles)
    M = np.zeros((len(angles), 2, 3))
    M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = c, -s, s, c
    if centres is not None:
        M[:, :, 2] = centres
    return M


def pose_stack(poses, n: int | None, name: str) -> tuple[np.ndarray, np.ndarray]:
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


@njit(cache=True)
def _apply_pose_nb(M, P):
    """``P @ M[:, :2].T + M[:, 2]`` as numpy computes it with OpenBLAS here (a test keeps them equal bit for bit): for
    two points or more each row's two products summed by one fused multiply-add, x r0 first (the matrix product's
    kernel), for one point y r1 first (the matrix-vector kernel); the translation added after."""
    n = len(P)
    out = np.empty((n, 2))
    a, b, c = M[0, 0], M[0, 1], M[0, 2]
    d, e, f = M[1, 0], M[1, 1], M[1, 2]
    if n == 1:
        x, y = P[0, 0], P[0, 1]
        out[0, 0] = _fma(x, a, y * b) + c
        out[0, 1] = _fma(x, d, y * e) + f
        return out
    for i in range(n):
        x, y = P[i, 0], P[i, 1]
        out[i, 0] = _fma(y, b, x * a) + c
        out[i, 1] = _fma(y, e, x * d) + f
    return out


def apply_pose(M: np.ndarray, P: np.ndarray) -> np.ndarray:
    """Points P (n, 2) moved by the affine 2x3 matrix M: ``P @ M[:, :2].T + M[:, 2]``, the same floats, compiled for
    the float64 arrays in C order the motion checks pass (7-8 times numpy's speed on 300 to 10 000 points); numpy
    for anything else."""
    if (type(P) is np.ndarray and type(M) is np.ndarray and P.dtype == np.float64 and M.dtype == np.float64
            and P.ndim == 2 and P.shape[1] == 2 and M.shape == (2, 3) and P.flags.c_contiguous
            and M.flags.c_contiguous):
        return _apply_pose_nb(M, P)
    return P @ M[:, :2].T + M[:, 2]


def inverse_pose(M: np.ndarray) -> np.ndarray:
    R = M[:, :2]
    return np.column_stack([R.T, -R.T @ M[:, 2]])


def compose_poses(M1: np.ndarray, M2: np.ndarray) -> np.ndarray:
    """M1 ∘ M2 (apply M2 first)."""
    return np.column_stack([M1[:, :2] @ M2[:, :2], M1[:, :2] @ M2[:, 2] + M1[:, 2]])


# the disk cache of this module's kernel keyed on every kernel source (nbcache)
bind(globals())
