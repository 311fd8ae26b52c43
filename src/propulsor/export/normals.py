"""Vertex normals of a triangle mesh for shading: smooth across tangent edges, sharp at feature edges.

The tessellation of a solid gives each B-rep face its own triangles; vertices at the same place are
first taken as one (so that a fillet runs smoothly into the face it is tangent to).  Then every corner
of every triangle gets the area-weighted mean of the normals of the triangles around its vertex that
turn less than `crease_deg` from its own triangle: triangles meeting at a smaller angle are shaded as
one surface, at a larger one (a feature edge: a chamfer, a step, a hole's rim) each side keeps its
own.  Corners of one vertex with the same normal share a vertex of the result; the others are split.
Deterministic (sorts only, no hashing of floats).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..geometry.rows import row_ids as _row_ids
from ..nbcache import bind

#: triangles turning less than this from each other are shaded as one surface
CREASE_DEG = 30.0
#: vertices closer than this (mm) are one vertex
MERGE_MM = 1e-6


def _sum_rows(index: np.ndarray, values: np.ndarray, n: int) -> np.ndarray:
    """Sum of the rows of `values` (k, 3) by `index` into n rows."""
    return np.column_stack([np.bincount(index, values[:, j], minlength=n) for j in range(3)])


@njit(cache=True)
def _crease_sums(starts, sizes, corner_face, unit, area_n, cos_crease):
    """For each corner (the corners sorted by vertex: those of a vertex from ``starts[g]``, ``sizes[g]`` of them,
    ``corner_face`` the triangle of each): the sum of ``area_n`` of the triangles of its vertex's corners whose unit
    normal turns from its own triangle's by less than the crease (cosine at least ``cos_crease``), its own always,
    added in the order of the corners, from 0."""
    acc = np.zeros((len(corner_face), 3))
    for g in range(len(starts)):
        s0, k = starts[g], sizes[g]
        for a in range(s0, s0 + k):
            fa = corner_face[a]
            x = 0.0
            y = 0.0
            z = 0.0
            for b in range(s0, s0 + k):
                fb = corner_face[b]
                dot = unit[fa, 0] * unit[fb, 0] + unit[fa, 1] * unit[fb, 1] + unit[fa, 2] * unit[fb, 2]
                if fb == fa or dot >= cos_crease:
                    x += area_n[fb, 0]
                    y += area_n[fb, 1]
                    z += area_n[fb, 2]
            acc[a, 0] = x
            acc[a, 1] = y
            acc[a, 2] = z
    return acc


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
    # each corner (in sorted order): the sum of the area normals of the triangles at its vertex within the crease
    # angle of its own, in the order of the vertex's corners (compiled: the pairs of corners of a vertex are never
    # held at once; a fan of a thousand triangles at one vertex made a million of them)
    acc = _crease_sums(starts, sizes, np.ascontiguousarray(corner_f[order]), unit, area_n,
                       float(np.cos(np.radians(crease_deg))))
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


# the disk cache of the kernel keyed on every kernel source (one may be compiled into another's code)
bind(globals())
