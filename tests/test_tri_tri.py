"""The compiled narrow phase of the self-intersection check (checks/tri_tri.py) against the vectorised numpy
one it replaced (tests/tri_tri_reference.py), pair by pair: on every candidate pair of real meshes (a
tessellated solid, the same rounded to float32 and with vertices pushed through the surface) and on
constructed pairs of every kind (apart, crossing, coplanar overlapping or touching, sharing a vertex or
an edge, folded, duplicated)."""

from __future__ import annotations

import numpy as np
import pytest

from propulsor.checks.mesh import overlapping_pairs, self_intersections
from propulsor.checks.tri_tri import pairs_intersect

from tri_tri_reference import _pairs_intersect


def _normals(V, F):
    T = V[F]
    N = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    N /= np.maximum(np.linalg.norm(N, axis=1), 1e-300)[:, None]
    return N, np.einsum("ij,ij->i", N, T[:, 0])


def _both(V, F, I, J, eps):
    N, D = _normals(V, F)
    return pairs_intersect(V, F, I, J, N, D, eps), _pairs_intersect(V, F, I, J, eps, N, D)


def _mesh():
    import cadquery as cq

    from propulsor.solids.tessellate import triangulate

    solid = (cq.Workplane("XY").polygon(7, 40.0).extrude(8.0).faces(">Z").workplane().hole(9.0)
             .edges("|Z").fillet(1.5).val())
    V, F, _ = triangulate(solid, parallel=False)
    return V, F


@pytest.mark.parametrize("variant", ["as meshed", "float32", "dented"])
def test_every_candidate_pair_of_a_mesh_decided_as_the_reference(variant):
    V, F = _mesh()
    if variant == "float32":
        V = V.astype(np.float32).astype(np.float64)
    elif variant == "dented":  # some vertices pushed through the surface: real intersections
        rng = np.random.default_rng(7)
        k = rng.choice(len(V), 40, replace=False)
        V = V.copy()
        V[k] += rng.normal(0.0, 2.0, (40, 3))
    T = V[F]
    eps = 1e-10 * float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    P = overlapping_pairs(T.min(axis=1) - eps, T.max(axis=1) + eps)
    got, ref = _both(V, F, P[:, 0], P[:, 1], eps)
    assert len(P) > 10_000
    assert np.array_equal(got, ref)
    if variant == "dented":
        assert got.sum() > 10
        assert self_intersections(V, F)[0] == int(ref.sum())
    else:
        assert not got.any()


def _pair_mesh(a, b, shared: int):
    """Two triangles (3, 3) as one mesh; the first `shared` vertices of b are those of a."""
    V = np.vstack([a, b[shared:]])
    fb = list(range(shared)) + list(range(3, 3 + 3 - shared))
    return V, np.array([[0, 1, 2], fb])


def test_constructed_pairs_of_every_kind_decided_as_the_reference():
    rng = np.random.default_rng(11)
    eps = 1e-9
    base = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    cases = []
    for _ in range(3000):
        kind = rng.integers(0, 6)
        a = base + rng.normal(0, 0.05, (3, 3)) * (kind != 2)
        if kind == 0:  # anywhere near
            b = rng.uniform(-0.5, 1.5, (3, 3))
        elif kind == 1:  # coplanar (z = 0), overlapping, touching or apart
            a[:, 2] = 0.0
            b = np.column_stack([rng.uniform(-0.5, 1.5, (3, 2)), np.zeros(3)])
            if rng.random() < 0.3:  # a vertex exactly on an edge of a
                b[0, :2] = a[0, :2] + rng.random() * (a[1, :2] - a[0, :2])
        elif kind == 2:  # coplanar on a tilted plane through exact grid points
            a = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 2.0], [0.0, 2.0, 0.0]])
            uv = rng.integers(-1, 3, (3, 2)).astype(float)
            b = np.column_stack([uv[:, 0], uv[:, 1], uv[:, 0]])
        else:  # sharing 1 or 2 vertices (3: the same triangle)
            b = rng.uniform(-0.5, 1.5, (3, 3))
            if rng.random() < 0.4:
                b[:, 2] = 0.0
                a[:, 2] = 0.0
        shared = {3: 1, 4: 2, 5: int(rng.integers(1, 4))}.get(int(kind), 0)
        if shared:
            b[:shared] = a[:shared]
        cases.append((a, b, shared))
    hits = {}
    for a, b, shared in cases:
        V, F = _pair_mesh(a, b, shared)
        N, _ = _normals(V, F)
        if np.any(np.linalg.norm(np.cross(V[F][:, 1] - V[F][:, 0], V[F][:, 2] - V[F][:, 0]), axis=1) <= eps):
            continue  # degenerate triangles never reach the narrow phase
        got, ref = _both(V, F, np.array([0]), np.array([1]), eps)
        assert got[0] == ref[0], (a, b, shared)
        hits.setdefault((shared, bool(ref[0])), 0)
        hits[(shared, bool(ref[0]))] += 1
    # every kind met, both outcomes (a duplicated triangle always intersects itself)
    assert {(s, h) for s in (0, 1, 2) for h in (False, True)} <= set(hits)
    assert hits.get((3, True), 0) > 0 and (3, False) not in hits
