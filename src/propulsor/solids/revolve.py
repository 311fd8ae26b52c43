"""Solids of revolution by direct OCCT construction.

A half section is given as a ``geometry.profile.Profile`` in the (r, z) plane: x = radius
(>= 0), y = axial coordinate.  Its face is built by ``solids.build.profile_face`` (exact lines,
arcs and B-splines), turned into the world XZ plane (x -> radius along world x, y -> world z)
and revolved a full turn about the world z axis, then moved so that the axis passes through
``center`` (x, y).  Primitives, placement and booleans: :mod:`propulsor.solids.kernel`.
"""

from __future__ import annotations

import math

from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
from OCP.BRepPrimAPI import BRepPrimAPI_MakeRevol
from OCP.gp import gp_Ax1, gp_Dir, gp_Pnt, gp_Trsf

from ..errors import require
from ..geometry.profile import Profile
from .build import profile_face
from .kernel import as_solid, moved

__all__ = ["revolve_section"]


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
