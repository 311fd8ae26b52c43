"""The reference of export/normals.py's crease sums (``_crease_sums``, compiled): the numpy formulation it replaced,
every pair of corners of a vertex held as arrays.  The tests put it in the compiled one's place and compare
``smooth_normals`` both ways, bit for bit."""

from __future__ import annotations

import numpy as np

from propulsor.export.normals import _sum_rows


def crease_sums(starts, sizes, corner_face, unit, area_n, cos_crease):
    """``_crease_sums``' value: for each corner (sorted by vertex), the sum of ``area_n`` of the triangles of its
    vertex's corners within the crease of its own triangle, its own always, in the order of the corners."""
    group = np.repeat(np.arange(len(starts)), sizes)  # of each sorted corner
    k = sizes[group]
    # every pair (corner, corner of the same vertex), corners in sorted order
    cc = np.repeat(np.arange(len(corner_face)), k)
    dd = np.repeat(starts[group], k) + (np.arange(len(cc)) - np.repeat(np.cumsum(k) - k, k))
    fc, fd = corner_face[cc], corner_face[dd]
    near = np.einsum("ij,ij->i", unit[fc], unit[fd]) >= cos_crease
    near |= fc == fd
    return _sum_rows(cc[near], area_n[fd[near]], len(corner_face))
