"""Gear solids built from generated outlines, measured ON THE SOLID with OCCT:
tooth thickness on the reference circle (the solid cut by a circle at mid face width),
tip / root diameters (the solid cut by radial rays), volume, B-rep validity."""

import math

import numpy as np
import pytest
from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRep import BRep_Tool
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_VERTEX
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt

from propulsor.geometry.gear_outline import exact_area, external_gear_profile, internal_gear_profile
from propulsor.policy import SPLINE_FIT_TOL_MM
from propulsor.solids.build import extrude_profile

ALPHA = math.radians(20.0)
W = 20.0
TOL = 2 * SPLINE_FIT_TOL_MM  # 0.02 µm: stricter than the 0.5 µm asked; two flanks each within the fit tolerance


def _vertices(shape):
    out = []
    ex = TopExp_Explorer(shape, TopAbs_VERTEX)
    while ex.More():
        p = BRep_Tool.Pnt_s(TopoDS.Vertex_s(ex.Current()))
        out.append((p.X(), p.Y(), p.Z()))
        ex.Next()
    return np.unique(np.round(np.array(out), 12), axis=0)


def _cut(solid, edge):
    sec = BRepAlgoAPI_Section(solid.wrapped, edge)
    sec.SetFuzzyValue(0.0)
    sec.Build()
    assert sec.IsDone()
    return _vertices(sec.Shape())


def circle_crossings(solid, r, z=W / 2):
    """Polar angles (from +y towards +x) where the circle of radius r at height z crosses
    the solid's boundary."""
    e = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), r)).Edge()
    v = _cut(solid, e)
    assert np.allclose(np.hypot(v[:, 0], v[:, 1]), r, atol=1e-9)
    return np.sort(np.arctan2(v[:, 0], v[:, 1]))


def ray_crossings(solid, phi, r_max, z=W / 2):
    """Radii where the ray from the axis at polar angle phi (from +y towards +x) crosses the boundary."""
    d = (math.sin(phi), math.cos(phi))
    e = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, z), gp_Pnt(r_max * d[0], r_max * d[1], z)).Edge()
    v = _cut(solid, e)
    return np.sort(np.hypot(v[:, 0], v[:, 1]))


def arc_around_top(angles, r):
    """Arc length on radius r between the two crossings that enclose the +y direction."""
    left = angles[angles < 0].max()
    right = angles[angles > 0].min()
    return r * (right - left)


def volume(solid):
    p = GProp_GProps()
    BRepGProp.VolumePropertiesGK_s(solid.wrapped, p, 1e-10, True, True)
    return p.Mass()


@pytest.mark.parametrize("z", [12, 16, 20, 50])
@pytest.mark.parametrize("x", [0.0, 0.5])
def test_tooth_thickness_and_tip_on_the_solid(z, x):
    m = 2.0
    g = external_gear_profile(z, m, x)
    solid = extrude_profile(g.profile, W)
    assert BRepCheck_Analyzer(solid.wrapped).IsValid()
    r = m * z / 2
    ang = circle_crossings(solid, r)
    assert len(ang) == 2 * z  # each tooth crosses the reference circle twice
    s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    assert arc_around_top(ang, r) == pytest.approx(s, abs=TOL)
    # every tooth alike (patterned by exact rotation): all tooth arcs
    a = np.sort(np.mod(ang + math.pi / z, 2 * math.pi))
    arcs = r * (a[1::2] - a[0::2])
    assert np.allclose(arcs, s, atol=TOL)
    # tip and root diameters on the solid: rays through a tooth centre and a space centre
    d_a = m * (z + 2 + 2 * x)
    rr = ray_crossings(solid, 0.0, d_a)
    assert 2 * rr.max() == pytest.approx(d_a, abs=TOL)
    rr = ray_crossings(solid, math.pi / z, d_a)
    assert 2 * rr.max() == pytest.approx(m * (z - 2.5 + 2 * x), abs=TOL)
    # tip diameter = largest radius of the solid anywhere at mid face width: a circle just
    # outside d_a meets nothing, one just inside meets every tooth twice
    assert len(circle_crossings_or_none(solid, d_a / 2 + TOL)) == 0
    assert len(circle_crossings(solid, d_a / 2 - TOL)) == 2 * z
    # volume = exact profile area × face width
    assert volume(solid) == pytest.approx(exact_area(g.profile) * W, rel=1e-6)


def circle_crossings_or_none(solid, r):
    e = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, W / 2), gp_Dir(0, 0, 1)), r)).Edge()
    return _cut(solid, e)


def test_thinning_measured_on_the_solid():
    z, m, x, j = 20, 2.0, 0.5, 0.12
    solid = extrude_profile(external_gear_profile(z, m, x, thinning_n_mm=j).profile, W)
    r = m * z / 2
    s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA)) - j
    assert arc_around_top(circle_crossings(solid, r), r) == pytest.approx(s, abs=TOL)


def test_bore_with_keyway_solid():
    g = external_gear_profile(30, 2.0, 0.0, bore_d=25.0, keyway=True)  # DIN 6885: 8 x 7, t2 = 3.3
    solid = extrude_profile(g.profile, W)
    assert BRepCheck_Analyzer(solid.wrapped).IsValid()
    assert volume(solid) == pytest.approx(exact_area(g.profile) * W, rel=1e-6)
    # keyway bottom on +y at bore/2 + t2, bore elsewhere
    assert ray_crossings(solid, 0.0, 40.0).min() == pytest.approx(12.5 + 3.3, abs=1e-7)
    assert ray_crossings(solid, math.pi, 40.0).min() == pytest.approx(12.5, abs=1e-7)
    # the keyway is b = 8 wide: a circle of radius 14 crosses its sides at x = ±4
    ang = circle_crossings(solid, 14.0)
    inner = ang[np.abs(ang) < 0.5]
    assert 14.0 * np.sin(inner) == pytest.approx([-4.0, 4.0], abs=1e-7)


@pytest.mark.parametrize("z,m,x,d_a,z0,x0", [
    (56, 10.0, 1.417, 10 * (56 - 2 * (1 - 1.417 - (0.25 - 0.125 * 1.417))), 14, 0.04),
    (60, 2.0, 0.0, 2 * (60 - 2 * (1 - 0.25)), 20, 0.0),
])
def test_ring_solid(z, m, x, d_a, z0, x0):
    g = internal_gear_profile(z, m, x, d_a, z0, x0)
    w = W
    solid = extrude_profile(g.profile, w)
    assert BRepCheck_Analyzer(solid.wrapped).IsValid()
    assert volume(solid) == pytest.approx(exact_area(g.profile) * w, rel=1e-6)
    # root diameter = 2 a_w0 + d_a0 (GOST 19274), measured on the ray through a space centre
    a_w0, d_a0 = g.side.extra["a_w0"], m * (z0 + 2 * (1.25 + x0))
    rr = ray_crossings(solid, 0.0, g.d_f)
    assert 2 * rr.min() == pytest.approx(2 * a_w0 + d_a0, abs=TOL)
    # tip (inner) diameter on the ray through a tooth centre
    assert 2 * ray_crossings(solid, math.pi / z, g.d_f).min() == pytest.approx(d_a, abs=TOL)
    # space width e = m(π/2 + 2x tan α) on the reference circle, or via the involute on a
    # circle inside the flank when the reference circle lies in the bore (thesis ring)
    r = m * z / 2
    r_y = r if g.side.r_a < r < g.side.r_Ff else 0.5 * (g.side.r_a + g.side.r_Ff)
    e = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    a_y = math.acos(r * math.cos(ALPHA) / r_y)
    inv = lambda a: math.tan(a) - a
    e_y = 2 * r_y * (e / (2 * r) + inv(ALPHA) - inv(a_y))
    ang = circle_crossings(solid, r_y)
    assert len(ang) == 2 * z
    # crossings enclosing +y bound the space (material outside it)
    assert arc_around_top(ang, r_y) == pytest.approx(e_y, abs=TOL)
