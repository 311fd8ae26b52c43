"""The bed-side chamfer made layer by layer (propulsor.printing.chamfer): the first layers are the bed
face eroded by the chamfer's depth at their mid-heights, the rest of the piece is untouched, the mesh
stays one closed body without self-intersection, and pieces that cannot take it are refused."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.checks.mesh import mesh_checks
from propulsor.errors import InputError
from propulsor.export.mesh import to_trimesh
from propulsor.geometry.profile import Profile, circle_loop, polygon_loop
from propulsor.printing.chamfer import chamfer_first_layers
from propulsor.solids.build import extrude_profile
from propulsor.solids.kernel import manifold

R, r, H = 20.0, 5.0, 10.0


@pytest.fixture(scope="module")
def washer():
    return to_trimesh(extrude_profile(Profile(circle_loop(R), [circle_loop(r, ccw=False)]), H))


@pytest.mark.parametrize("d, layer", [(0.4, 0.2), (0.4, 0.15), (0.3, 0.3)])
def test_layers_are_the_eroded_bed_face_at_their_mid_heights(washer, d, layer):
    out = chamfer_first_layers(washer, d, layer, "washer")
    n = math.ceil(d / layer - 1e-9)
    h = d / n
    M = manifold(out, "chamfered washer")
    for k in range(n):
        inset = d - (k + 0.5) * h
        # the slicer's section of layer k: a true 45° chamfer's section at that height
        area = M.slice((k + 0.5) * h).area()
        exact = math.pi * ((R - inset) ** 2 - (r + inset) ** 2)
        assert area == pytest.approx(exact, rel=2e-4)
    # above the chamfer the piece is untouched
    assert M.slice(d + 0.05).area() == pytest.approx(math.pi * (R ** 2 - r ** 2), rel=2e-4)
    # the volume taken off: the layers' insets, the same as a true chamfer's perimeter × d² / 2 (to first order)
    lost = sum(math.pi * (R ** 2 - r ** 2 - (R - i) ** 2 + (r + i) ** 2) * h
               for i in (d - (k + 0.5) * h for k in range(n)))
    assert washer.volume - out.volume == pytest.approx(lost, rel=2e-3)
    checks = {c.name.split(": ", 1)[1]: c for c in mesh_checks(out, "washer", expected_genus=1)}
    assert all(c.passed for c in checks.values()), [n for n, c in checks.items() if not c.passed]


def test_no_chamfer_leaves_the_mesh(washer):
    assert chamfer_first_layers(washer, 0.0, 0.2) is washer


def test_a_piece_with_leaning_walls_is_refused():
    import trimesh

    cone = trimesh.creation.cone(radius=10.0, height=10.0, sections=64)
    with pytest.raises(InputError, match="not vertical"):
        chamfer_first_layers(cone, 0.4, 0.2, "cone")


def test_a_web_narrower_than_twice_the_chamfer_is_refused():
    # two squares joined by a 0.5 mm web: eroding by 0.3 mm cuts the web
    pts = [(0, 0), (10, 0), (10, 4.75), (12, 4.75), (12, 0), (22, 0), (22, 10), (12, 10), (12, 5.25), (10, 5.25),
           (10, 10), (0, 10)]
    body = to_trimesh(extrude_profile(Profile(polygon_loop(pts)), 5.0))
    with pytest.raises(InputError, match="splits or removes"):
        chamfer_first_layers(body, 0.4, 0.2, "dumbbell")
    # a chamfer the web survives is made
    out = chamfer_first_layers(body, 0.2, 0.2, "dumbbell")
    assert manifold(out).slice(0.1).decompose().__len__() == 1
    assert np.isclose(out.bounds[1][2], 5.0)
