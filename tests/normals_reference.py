"""The reference of export/normals.py's smooth_normals: the numpy formulation its compiled crease sums replaced,
every pair of corners of a vertex held as arrays.  The tests compare the two on meshes with wide fans, bit for bit."""

from __future__ import annotations

import numpy as np

#: triangles turning less than this from each other are shaded as one surface
CREASE_DEG = 30.0
#: vertices closer than this (mm) are one vertex
MERGE_MM = 1e-6


def _row_ids(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(index of the first of each distinct row, in the rows' sorted order; the distinct row of each row)
    of an integer array (n, c): np.unique(axis=0) by a lexical sort of the columns (much faster)."""
    order = np.lexsort(rows.T[::-1])
    s = rows[order]
    new = np.r_[True, np.any(s[1:] != s[:-1], axis=1)]
    ids = np.cumsum(new) - 1
    inverse = np.empty(len(rows), np.int64)
    inverse[order] = ids
    return order[new], inverse


def _sum_rows(index: np.ndarray, values: np.ndarray, n: int) -> np.ndarray:
    """Sum of the rows of `values` (k, 3) by `index` into n rows."""
    return np.column_stack([np.bincount(index, values[:, j], minlength=n) for j in range(3)])


def smooth_normals(vertices, faces, crease_deg: float = CREASE_DEG):
    """(vertices (k, 3), normals (k, 3) unit, faces (m, 3)) of the mesh (vertices (n, 3), faces (m, 3)):
    the same triangles in the same order, each corner's vertex carrying its shading normal."""
    v = np.asarray(vertices, np.float64).reshape(-1, 3)
    f = np.asarray(faces, np.int64).reshape(-1, 3)
    if len(f) == 0:
        return v[:0], v[:0], f
    key = np.round(v / MERGE_MM).astype(np.int64)
    first, same = _row_ids(key)
    fm = same[f]  # the faces on merged vertices
    pos = v[first]
    a, b, c = pos[fm[:, 0]], pos[fm[:, 1]], pos[fm[:, 2]]
    area_n = np.cross(b - a, c - a)  # twice the area, along the normal
    length = np.linalg.norm(area_n, axis=1)
    unit = np.divide(area_n, length[:, None], out=np.zeros_like(area_n), where=length[:, None] > 0)

    corner_v = fm.reshape(-1)
    corner_f = np.repeat(np.arange(len(fm)), 3)
    order = np.argsort(corner_v, kind="stable")
    sv = corner_v[order]
    starts = np.flatnonzero(np.r_[True, sv[1:] != sv[:-1]])
    sizes = np.diff(np.r_[starts, len(sv)])
    group = np.repeat(np.arange(len(starts)), sizes)  # of each sorted corner
    k = sizes[group]
    # every pair (corner, corner of the same vertex), corners in sorted order
    cc = np.repeat(np.arange(len(sv)), k)
    dd = np.repeat(starts[group], k) + (np.arange(len(cc)) - np.repeat(np.cumsum(k) - k, k))
    fc, fd = corner_f[order][cc], corner_f[order][dd]
    near = np.einsum("ij,ij->i", unit[fc], unit[fd]) >= np.cos(np.radians(crease_deg))
    near |= fc == fd
    acc = _sum_rows(cc[near], area_n[fd[near]], len(sv))
    # a corner of a triangle with no area: the mean of every triangle at its vertex (or +z)
    whole = _sum_rows(group, area_n[corner_f[order]], len(starts))
    weak = np.linalg.norm(acc, axis=1) <= 1e-30
    acc[weak] = whole[group[weak]]
    weak = np.linalg.norm(acc, axis=1) <= 1e-30
    acc[weak] = (0.0, 0.0, 1.0)
    n_sorted = acc / np.linalg.norm(acc, axis=1)[:, None]
    normals = np.empty_like(n_sorted)
    normals[order] = n_sorted

    # one vertex per (merged vertex, normal)
    nkey = np.round(normals * 1e6).astype(np.int64)
    rows = np.column_stack([corner_v, nkey])
    out_first, out_of_corner = _row_ids(rows)
    out_v = pos[corner_v[out_first]]
    out_n = normals[out_first]
    return out_v, out_n, out_of_corner.reshape(-1, 3)
