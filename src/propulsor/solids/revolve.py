"""Solids of revolution and simple placed primitives by direct OCCT construction.

A half section is given as a ``geometry.profile.Profile`` in the (r, z) plane: x = radius
(>= 0), y = axial coordinate.  Its face is built by ``solids.build.profile_face`` (exact lines,
arcs and B-splines), turned into the world XZ plane (x -> radius along world x, y -> world z)
and revolved a full turn about the world z axis, then moved so that the axis passes through
``center`` (x, y).  Boolean helpers wrap BRepAlgoAPI with a validity check of the result.
"""

from __future__ import annotations

import math

from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeRevol
from OCP.gp import gp_Ax1, gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain
from OCP.TopAbs import TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.TopTools import TopTools_ListOfShape

from ..errors import require, require_positive
from ..geometry.profile import Profile
from .build import profile_face

__all__ = ["revolve_section", "cylinder", "moved", "fuse", "cut", "as_solid"]


def _shape(s):
    return s.wrapped if hasattr(s, "wrapped") else s


def as_solid(shape):
    """The single solid of a shape as a ``cadquery.Solid`` (raises if there is not exactly one)."""
    import cadquery as cq

    sh = _shape(shape)
    ex = TopExp_Explorer(sh, TopAbs_SOLID)
    out = []
    while ex.More():
        out.append(TopoDS.Solid_s(ex.Current()))
        ex.Next()
    require(len(out) == 1, "solid count", len(out), "a boolean result must be exactly one solid")
    return cq.Solid(out[0])


def moved(shape, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0, rot_z: float = 0.0):
    """Rotate about the world z axis by rot_z (rad), then translate; returns the same kind of object."""
    t = gp_Trsf()
    if rot_z:
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), float(rot_z))
    t2 = gp_Trsf()
    t2.SetTranslation(gp_Vec(float(dx), float(dy), float(dz)))
    t = t2.Multiplied(t)
    res = BRepBuilderAPI_Transform(_shape(shape), t, True).Shape()
    return as_solid(res)


def revolve_section(section: Profile, center=(0.0, 0.0)):
    """Full revolution of a half section (x = radius, y = axial z) about the axis through center."""
    for loop in section.loops:
        for p in loop.polyline(0.01):
            require(p[0] >= -1e-9, "section radius", float(p[0]), "a half section must lie at r >= 0")
    face = profile_face(section)
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), math.pi / 2)  # (x, y, 0) -> (x, 0, y)
    face = BRepBuilderAPI_Transform(face, t, True).Shape()
    rev = BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0 * math.pi, True)
    rev.Build()
    require(rev.IsDone(), "revolve", "failed", "BRepPrimAPI_MakeRevol did not complete")
    sol = as_solid(rev.Shape())
    if center[0] or center[1]:
        sol = moved(sol, center[0], center[1], 0.0)
    return sol


def cylinder(radius: float, z0: float, z1: float, center=(0.0, 0.0), axis: str = "z"):
    """A cylinder of the given radius.  axis 'z': from z0 to z1 about (cx, cy); axis 'x' or 'y':
    along that world axis from z0 to z1 (coordinates along the axis), passing through center =
    the other two coordinates ((y, z) for 'x', (x, z) for 'y')."""
    import cadquery as cq

    r = require_positive("radius", radius, "mm")
    require(z1 > z0, "cylinder length", z1 - z0, "must be > 0")
    c0, c1 = float(center[0]), float(center[1])
    if axis == "z":
        ax = gp_Ax2(gp_Pnt(c0, c1, float(z0)), gp_Dir(0, 0, 1))
    elif axis == "x":
        ax = gp_Ax2(gp_Pnt(float(z0), c0, c1), gp_Dir(1, 0, 0))
    elif axis == "y":
        ax = gp_Ax2(gp_Pnt(c0, float(z0), c1), gp_Dir(0, 1, 0))
    else:
        raise ValueError(f"axis must be 'x', 'y' or 'z', not {axis!r}")
    return cq.Solid(BRepPrimAPI_MakeCylinder(ax, r, float(z1 - z0)).Solid())


def _boolean(op, a, tools, name: str):
    args = TopTools_ListOfShape()
    args.Append(_shape(a))
    tl = TopTools_ListOfShape()
    for t in tools:
        tl.Append(_shape(t))
    op.SetArguments(args)
    op.SetTools(tl)
    op.SetRunParallel(False)  # deterministic
    op.Build()
    require(op.IsDone(), name, "failed", "OCCT boolean did not complete")
    sh = op.Shape()
    unify = ShapeUpgrade_UnifySameDomain(sh, True, True, True)
    unify.Build()
    sh = unify.Shape()
    require(BRepCheck_Analyzer(sh).IsValid(), name, "invalid", "OCCT boolean gave an invalid shape")
    return as_solid(sh)


def fuse(a, *tools, name: str = "fuse"):
    """Union of solids (one solid expected)."""
    return _boolean(BRepAlgoAPI_Fuse(), a, tools, name)


def cut(a, *tools, name: str = "cut"):
    """a minus the tools (one solid expected)."""
    return _boolean(BRepAlgoAPI_Cut(), a, tools, name)
