"""Tessellation of the exported meshes (solids/tessellate.py): OCCT's achieved deflection held to the
0.01 mm the files promise by meshing again only the faces that miss it, and the mesh as written (STL is
float32) still closed and free of self-intersections."""

import math

import cadquery as cq
import numpy as np
import pytest

from propulsor.checks.mesh import edge_counts, self_intersections
from propulsor.policy import MESH_CHORD_LIMIT_MM
from propulsor.solids import tessellate as T


def _disc(chamfer_mm: float, drill_point: bool):
    body = cq.Workplane("XY").circle(50.0).extrude(20.0).faces(">Z").edges().chamfer(chamfer_mm)
    if drill_point:  # a blind bore with a 118 deg drill point: a cone down to its apex
        r, depth = 8.0, 12.0
        tip = r / math.tan(math.radians(59.0))
        hole = (cq.Workplane("XZ").polyline([(0, 25), (r, 25), (r, 20 - depth), (0, 20 - depth - tip)]).close()
                .revolve(360, (0, 0, 0), (0, 1, 0)).translate((20, 0, 0)))
        body = body.cut(hole)
    return body.val()


def _mesh(solid, monkeypatch):
    passes, refined = [], []
    mesh_shape, refine_faces = T.mesh_shape, T.refine_faces
    monkeypatch.setattr(T, "mesh_shape", lambda *a, **k: passes.append(mesh_shape(*a, **k)) or passes[-1])
    monkeypatch.setattr(T, "refine_faces", lambda *a, **k: refined.append(refine_faces(*a, **k)) or refined[-1])
    v, f, d = T.triangulate(solid, parallel=False)
    return v, f, d, passes, refined


def _closed_and_clean_in_float32(v, f):
    v32 = v.astype(np.float32).astype(np.float64)  # what the STL holds
    counts = edge_counts(f)
    counts = counts[1] if isinstance(counts, tuple) else counts
    assert np.all(np.asarray(counts) == 2)
    assert self_intersections(v32, f)[0] == 0


def test_faces_that_miss_the_chord_are_meshed_again_alone(monkeypatch):
    """A 45 deg chamfer cone of a disc misses the request (0.0122 mm at 0.005): that face alone is meshed
    again with its surface deflection controlled, instead of the whole disc at half the request."""
    v, f, d, passes, refined = _mesh(_disc(8.0, drill_point=False), monkeypatch)
    assert len(passes) == 1 and passes[0] > MESH_CHORD_LIMIT_MM
    assert len(refined) == 1 and d == refined[0] <= MESH_CHORD_LIMIT_MM
    _closed_and_clean_in_float32(v, f)


def test_an_apex_is_left_to_the_global_halving(monkeypatch):
    """A drill point's cone reaches its apex: refined alone it folds once written in float32; it is left
    to the halving of the whole request, and the written mesh is closed and clean."""
    v, f, d, passes, refined = _mesh(_disc(8.0, drill_point=True), monkeypatch)
    assert len(refined) == 1 and refined[0] > MESH_CHORD_LIMIT_MM  # the apex cone still misses
    assert len(passes) >= 2 and d <= MESH_CHORD_LIMIT_MM
    _closed_and_clean_in_float32(v, f)
