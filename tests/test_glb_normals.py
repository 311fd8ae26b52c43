"""The GLB's shading normals: smooth across tangent edges (also where the tessellation gives each face
its own vertices), sharp at feature edges; unit length, one per vertex; the Khronos validator (npm's
gltf-validator, when web/node_modules holds it) finds no error and no warning."""

from __future__ import annotations

import json
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest
import trimesh

from propulsor.export.glb import write_glb
from propulsor.export.normals import smooth_normals

ROOT = Path(__file__).resolve().parents[1]


def _radial(v):
    r = v[:, :2] / np.linalg.norm(v[:, :2], axis=1)[:, None]
    return np.column_stack([r, np.zeros(len(v))])


def test_box_corners_keep_their_faces_normals():
    box = trimesh.creation.box((2.0, 3.0, 4.0))
    v, n, f = smooth_normals(box.vertices, box.faces)
    assert len(v) == 24  # each of the 8 corners split three ways
    assert np.allclose(v[f], box.vertices[box.faces])  # the same triangles, in the same order
    assert np.allclose(np.abs(n).max(axis=1), 1.0)  # every normal along an axis: a face's own


def test_cylinder_smooth_on_its_side_sharp_at_its_rims_even_with_a_seam():
    cyl = trimesh.creation.cylinder(radius=10.0, height=5.0, sections=48)
    # the side in two halves with vertices of their own, as a B-rep tessellation gives them
    v0, f0 = np.asarray(cyl.vertices), np.asarray(cyl.faces)
    side = np.abs(cyl.face_normals[:, 2]) < 0.5
    half = side & (cyl.triangles_center[:, 1] > 0)
    v1 = np.vstack([v0, v0])
    f1 = np.where(half[:, None], f0 + len(v0), f0)
    v, n, f = smooth_normals(v1, f1)
    whole_v, whole_n, whole_f = smooth_normals(v0, f0)
    assert len(v) == len(whole_v)  # the seam splits no vertex
    assert np.allclose(n[f], whole_n[whole_f], atol=1e-12)  # nor changes a normal
    corners_n = n[f]  # (m, 3, 3)
    for face in np.flatnonzero(side):  # round the side: within half a facet's turn of the radius
        assert np.all(np.einsum("ij,ij->i", corners_n[face], _radial(v[f[face]])) > np.cos(np.pi / 48))
    for face in np.flatnonzero(~side):
        assert np.allclose(np.abs(corners_n[face][:, 2]), 1.0)  # the caps flat up to their rims


def _glb_json(path: Path) -> dict:
    data = path.read_bytes()
    n = struct.unpack_from("<I", data, 12)[0]
    return json.loads(data[20:20 + n])


def test_glb_carries_unit_normals_and_passes_the_validator(tmp_path):
    cyl = trimesh.creation.cylinder(radius=10.0, height=5.0, sections=32)
    box = trimesh.creation.box((4.0, 4.0, 4.0))
    meshes = {"c": (cyl.vertices, cyl.faces), "b": (box.vertices, box.faces)}
    glb = write_glb(tmp_path / "a.glb", "a", meshes, [("c1", "c", np.eye(4)), ("b1", "b", np.eye(4)),
                                                         ("c2", "c", np.eye(4))])
    doc = _glb_json(glb)
    scene = trimesh.load(glb, force="scene")
    for mesh in doc["meshes"]:
        attrs = mesh["primitives"][0]["attributes"]
        assert doc["accessors"][attrs["NORMAL"]]["count"] == doc["accessors"][attrs["POSITION"]]["count"]
    for g in scene.geometry.values():
        assert np.allclose(np.linalg.norm(g.vertex_normals, axis=1), 1.0, atol=1e-6)
    node = shutil.which("node")
    if node is None or not (ROOT / "web" / "node_modules" / "gltf-validator").is_dir():
        pytest.skip("the glTF validator needs node and `make validate-glb`'s web/node_modules")
    r = subprocess.run([node, str(ROOT / "web" / "validate_glb.mjs"), str(glb)], capture_output=True, text=True)
    assert r.returncode == 0 and "0 errors, 0 warnings" in r.stdout, r.stdout + r.stderr


@pytest.mark.parametrize("sections", [8, 64, 400])
def test_the_compiled_crease_sums_are_the_numpy_formulations_bit_for_bit(sections, monkeypatch):
    """smooth_normals against itself with its crease sums in the numpy formulation they replaced
    (``tests/normals_reference.py``): the same vertices, normals and faces to the last bit on a cylinder whose caps are fans of ``sections`` triangles about one vertex
    (a cap's centre: every pair of its corners weighed), a torus (smooth everywhere) and a box cut by a cylinder
    (creases of every angle), duplicated vertices and a zero-area triangle included."""
    from normals_reference import crease_sums

    from propulsor.export import normals

    def reference(V, F):
        with monkeypatch.context() as m:
            m.setattr(normals, "_crease_sums", crease_sums)
            return normals.smooth_normals(V, F)

    meshes = [trimesh.creation.cylinder(radius=10.0, height=4.0, sections=sections),
              trimesh.creation.torus(20.0, 5.0, major_sections=sections // 2 + 4, minor_sections=12),
              trimesh.creation.box((30.0, 20.0, 10.0)).difference(trimesh.creation.cylinder(6.0, 40.0,
                                                                                          sections=sections))]
    for m in meshes:
        V = np.asarray(m.vertices, float)
        F = np.asarray(m.faces, np.int64)
        V = np.vstack([V, V[:5]])  # duplicated vertices (merged by the function)
        F = np.vstack([F, [[0, 0, 1]], F[:3] + 0])  # a zero-area triangle and three triangles twice
        got, want = smooth_normals(V, F), reference(V, F)
        assert all(g.dtype == w.dtype and np.array_equal(g, w) for g, w in zip(got, want))
