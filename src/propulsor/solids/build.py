"""Profile → B-rep solid by direct OCCT construction (no booleans).

Every segment of a ``geometry.profile.Profile`` becomes one OCCT edge on its exact curve
(Geom_BSplineCurve from poles/knots, trimmed Geom_Circle, Geom_Line segment); consecutive edges
share their TopoDS_Vertex, so each loop is one closed wire built without search or healing.
The outer wire and the hole wires bound one planar face, which is extruded along +Z.
"""

from __future__ import annotations

import math

import numpy as np

from OCP.BRep import BRep_Builder
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace
from OCP.BRepPrimAPI import BRepPrimAPI_MakePrism
from OCP.Geom import Geom_BSplineCurve, Geom_Circle, Geom_Line
from OCP.gp import gp_Ax2, gp_Dir, gp_Pln, gp_Pnt, gp_Vec
from OCP.TColgp import TColgp_Array1OfPnt
from OCP.TColStd import TColStd_Array1OfInteger, TColStd_Array1OfReal
from OCP.TopoDS import TopoDS, TopoDS_Vertex, TopoDS_Wire

from ..errors import require, require_positive
from ..geometry.profile import Arc, Line, Loop, Profile, Spline
from ..policy import POINT_TOL_MM
from .cq_import import import_cadquery

__all__ = ["extrude_profile", "profile_face", "loop_wire"]

_Z = gp_Dir(0.0, 0.0, 1.0)
_MZ = gp_Dir(0.0, 0.0, -1.0)
_X = gp_Dir(1.0, 0.0, 0.0)


def _bspline_curve(sp: Spline) -> Geom_BSplineCurve:
    poles = sp.poles
    n = len(poles)
    arr = TColgp_Array1OfPnt(1, n)
    for i, (x, y) in enumerate(poles, 1):
        arr.SetValue(i, gp_Pnt(float(x), float(y), 0.0))
    kv, mult = np.unique(sp.knots, return_counts=True)
    kn = TColStd_Array1OfReal(1, len(kv))
    mu = TColStd_Array1OfInteger(1, len(kv))
    for i, (k, m) in enumerate(zip(kv, mult), 1):
        kn.SetValue(i, float(k))
        mu.SetValue(i, int(m))
    return Geom_BSplineCurve(arr, kn, mu, int(sp.degree))


def _edge(seg, v0, v1):
    """OCCT edge of one segment between the given (shared) vertices."""
    if isinstance(seg, Spline):
        c = _bspline_curve(seg)
        return BRepBuilderAPI_MakeEdge(c, v0, v1, c.FirstParameter(), c.LastParameter()).Edge()
    if isinstance(seg, Arc):
        cx, cy = seg.center
        if seg.a1 >= seg.a0:  # CCW: parameter = polar angle
            circ = Geom_Circle(gp_Ax2(gp_Pnt(cx, cy, 0.0), _Z, _X), seg.radius)
            p0, p1 = seg.a0, seg.a1
        else:  # CW: axis −Z, parameter = −polar angle
            circ = Geom_Circle(gp_Ax2(gp_Pnt(cx, cy, 0.0), _MZ, _X), seg.radius)
            p0, p1 = -seg.a0, -seg.a1
        shift = 2.0 * math.pi * math.floor(p0 / (2.0 * math.pi))
        return BRepBuilderAPI_MakeEdge(circ, v0, v1, p0 - shift, p1 - shift).Edge()
    if isinstance(seg, Line):
        a, b = seg.start, seg.end
        L = float(np.linalg.norm(b - a))
        require(L > POINT_TOL_MM, "line segment", L, "must be longer than the point tolerance")
        d = (b - a) / L
        ln = Geom_Line(gp_Pnt(float(a[0]), float(a[1]), 0.0), gp_Dir(float(d[0]), float(d[1]), 0.0))
        return BRepBuilderAPI_MakeEdge(ln, v0, v1, 0.0, L).Edge()
    raise TypeError(f"unknown segment type {type(seg).__name__}")


def loop_wire(loop: Loop, tol: float = 1e-7) -> TopoDS_Wire:
    """One closed wire, edges in loop order sharing their vertices."""
    gaps = loop.gaps()
    require(float(gaps.max()) <= tol, "loop gap", float(gaps.max()), f"must be <= {tol} mm (closed loop)")
    bb = BRep_Builder()
    segs = loop.segments
    verts = []
    for s in segs:
        p = s.start
        v = TopoDS_Vertex()
        bb.MakeVertex(v, gp_Pnt(float(p[0]), float(p[1]), 0.0), tol)
        verts.append(v)
    w = TopoDS_Wire()
    bb.MakeWire(w)
    n = len(segs)
    for i, s in enumerate(segs):
        bb.Add(w, _edge(s, verts[i], verts[(i + 1) % n]))
    w.Closed(True)
    return w


def profile_face(profile: Profile):
    """Planar face (z = 0, normal +Z) bounded by the outer loop with the holes cut out."""
    mk = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), _Z), loop_wire(profile.outer), True)
    for h in profile.holes:
        mk.Add(loop_wire(h))
    return mk.Face()


def extrude_profile(profile: Profile, width_mm: float):
    """Prism of the profile from z = 0 to z = width_mm, as a ``cadquery.Solid``."""
    cq = import_cadquery()

    w = require_positive("width_mm", width_mm, "mm")
    face = profile_face(profile)
    prism = BRepPrimAPI_MakePrism(face, gp_Vec(0.0, 0.0, w), True)
    return cq.Solid(TopoDS.Solid_s(prism.Shape()))
