"""Solids for printing: the bed-side chamfer (against the first layers' spread, "elephant's foot")
and turning a piece over (printed one way up, assembled the other).

The piece lies on its face at z = z_min; every edge of that planar face gets an equal-distance chamfer
(OCCT ``BRepFilletAPI_MakeChamfer``; tangent chains of B-spline edges propagate).  The result is
checked: one valid solid, smaller by at most the chamfer's prism (perimeter × d² / 2, with margin).
"""

from __future__ import annotations

from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepFilletAPI import BRepFilletAPI_MakeChamfer
from OCP.GeomAbs import GeomAbs_Plane
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

from ..errors import InputError
from .kernel import occ_shape

__all__ = ["chamfer_bottom", "flipped"]


def flipped(solid, z_top: float, axis: str = "x"):
    """The solid turned over about the x (or y) axis, its former top z_top now at z = 0 (z -> z_top - z;
    y -> -y about x, x -> -x about y)."""
    import cadquery as cq

    turn = {"x": cq.Vector(1, 0, 0), "y": cq.Vector(0, 1, 0)}[axis]
    return solid.rotate(cq.Vector(0, 0, 0), turn, 180).translate(cq.Vector(0, 0, z_top))


def _bottom_face(shape):
    """The planar face lying lowest (normal along z) of a shape."""
    best, z_best = None, None
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        f = TopoDS.Face_s(ex.Current())
        ad = BRepAdaptor_Surface(f)
        if ad.GetType() == GeomAbs_Plane and abs(abs(ad.Plane().Axis().Direction().Z()) - 1.0) < 1e-9:
            z = ad.Plane().Location().Z()
            if z_best is None or z < z_best:
                best, z_best = f, z
        ex.Next()
    return best


def chamfer_bottom(solid, d: float, name: str = "piece"):
    """The solid with every edge of its lowest planar face chamfered by d (mm); d = 0: unchanged."""
    import cadquery as cq

    if d <= 0:
        return solid
    shape = occ_shape(solid)
    face = _bottom_face(shape)
    if face is None:
        raise InputError("chamfer_mm", d, f"{name} has no planar bottom face to chamfer")
    mk = BRepFilletAPI_MakeChamfer(shape)
    ex = TopExp_Explorer(face, TopAbs_EDGE)
    while ex.More():
        mk.Add(d, d, TopoDS.Edge_s(ex.Current()), face)
        ex.Next()
    mk.Build()
    if not mk.IsDone() or not BRepCheck_Analyzer(mk.Shape()).IsValid():
        raise InputError("chamfer_mm", d, f"the bed-side chamfer of {name} cannot be made (an edge shorter than it?)")
    out = cq.Shape.cast(mk.Shape())
    solids = out.Solids()
    if len(solids) != 1:
        raise InputError("chamfer_mm", d, f"the chamfered {name} is {len(solids)} solids")
    return solids[0]
