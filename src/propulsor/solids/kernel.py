"""The kernel adapter: every call into OCCT (OCP / cadquery) and manifold3d that parts and checks need.

Parts and checks never import OCP, cadquery or manifold3d themselves (docs/architecture.md,
"Layers"); they call these functions:

* shape conversion: :func:`occ_shape`, :func:`as_solid`, :func:`solids_of`, :func:`one_solid`;
* placement: :func:`moved` (OCCT transform), :func:`shifted_z` (cadquery location),
  :func:`z_rotation` (an assembly placement);
* primitives: :func:`cylinder` (OCCT), :func:`cq_cylinder`, :func:`box`;
* booleans: :func:`fuse` / :func:`cut` (OCCT, unified and validity-checked),
  :func:`cq_fuse` / :func:`cq_cut` (cadquery's booleans, cleaned, one solid expected);
* properties: :func:`volume`, :func:`mass_properties`;
* meshes as manifold3d solids: :func:`manifold`, :func:`manifold_cube`, :func:`manifold_cylinder`.

Tessellation is :mod:`propulsor.solids.tessellate`.
"""

from __future__ import annotations

import numpy as np
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder
from OCP.GProp import GProp_GProps
from OCP.gp import gp_Ax1, gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain
from OCP.TopAbs import TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS, TopoDS_Shape
from OCP.TopTools import TopTools_ListOfShape

from ..errors import InputError, require, require_positive
from ..policy import TOUCHING_VOLUME_REL_TOL
from .cq_import import import_cadquery

__all__ = ["occ_shape", "as_solid", "solids_of", "one_solid", "moved", "shifted_z", "z_rotation", "cylinder",
           "cq_cylinder", "box", "fuse", "cut", "cq_fuse", "cq_cut", "volume", "brep_bytes", "mass_properties",
           "manifold", "manifold_cube", "manifold_cylinder"]


# -- shape conversion -----------------------------------------------------------------------------
def occ_shape(obj) -> TopoDS_Shape:
    """The TopoDS_Shape of an OCP shape, a cadquery Shape or a cadquery Workplane."""
    if isinstance(obj, TopoDS_Shape):
        return obj
    if hasattr(obj, "wrapped"):
        return obj.wrapped
    if hasattr(obj, "val"):  # Workplane
        return obj.val().wrapped
    raise TypeError(f"not a shape: {type(obj).__name__}")


def solids_of(shape) -> list:
    """All TopoDS_Solid in a shape, in exploration order."""
    out = []
    ex = TopExp_Explorer(occ_shape(shape), TopAbs_SOLID)
    while ex.More():
        out.append(TopoDS.Solid_s(ex.Current()))
        ex.Next()
    return out


def as_solid(shape):
    """The single solid of a shape as a ``cadquery.Solid`` (raises if there is not exactly one)."""
    cq = import_cadquery()

    out = solids_of(shape)
    require(len(out) == 1, "solid count", len(out), "a boolean result must be exactly one solid")
    return cq.Solid(out[0])


def one_solid(shape, name: str):
    """The single solid of a cadquery boolean result (cleaned)."""
    cq = import_cadquery()

    shape = shape.clean()
    solids = shape.Solids() if hasattr(shape, "Solids") else [shape]
    if len(solids) != 1:
        raise RuntimeError(f"{name}: boolean result has {len(solids)} solids")
    return cq.Solid(solids[0].wrapped)


# -- placement ------------------------------------------------------------------------------------
def moved(shape, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0, rot_z: float = 0.0):
    """Rotate about the world z axis by rot_z (rad), then translate (an OCCT copy, one solid)."""
    t = gp_Trsf()
    if rot_z:
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), float(rot_z))
    t2 = gp_Trsf()
    t2.SetTranslation(gp_Vec(float(dx), float(dy), float(dz)))
    t = t2.Multiplied(t)
    res = BRepBuilderAPI_Transform(occ_shape(shape), t, True).Shape()
    return as_solid(res)


def shifted_z(solid, dz: float):
    """A cadquery solid moved along z by a location (the same solid when dz is 0)."""
    cq = import_cadquery()

    return solid.moved(cq.Location(cq.Vector(0.0, 0.0, float(dz)))) if dz else solid


def z_rotation(angle_deg: float, then_translation=None):
    """Assembly placement: a rotation about the world z axis (degrees), applied after an optional
    translation (x, y, z) of the component in the rotated frame."""
    cq = import_cadquery()

    rot = cq.Location(cq.Vector(0, 0, 0), cq.Vector(0, 0, 1), angle_deg)
    return rot if then_translation is None else rot * cq.Location(cq.Vector(*then_translation))


# -- primitives -----------------------------------------------------------------------------------
def cylinder(radius: float, z0: float, z1: float, center=(0.0, 0.0), axis: str = "z"):
    """A cylinder of the given radius.  axis 'z': from z0 to z1 about (cx, cy); axis 'x' or 'y':
    along that world axis from z0 to z1 (coordinates along the axis), passing through center =
    the other two coordinates ((y, z) for 'x', (x, z) for 'y')."""
    cq = import_cadquery()

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


def cq_cylinder(radius: float, z0: float, z1: float, x: float = 0.0, y: float = 0.0):
    """cadquery's cylinder along +z from z0 to z1 about (x, y)."""
    cq = import_cadquery()

    return cq.Solid.makeCylinder(float(radius), float(z1 - z0), cq.Vector(float(x), float(y), float(z0)),
                                 cq.Vector(0.0, 0.0, 1.0))


def box(dx: float, dy: float, dz: float, corner=(0.0, 0.0, 0.0)):
    """An axis-parallel box with its least corner at ``corner``."""
    cq = import_cadquery()

    return cq.Solid.makeBox(dx, dy, dz, cq.Vector(*corner))


# -- booleans -------------------------------------------------------------------------------------
def _boolean(op, a, tools, name: str):
    args = TopTools_ListOfShape()
    args.Append(occ_shape(a))
    tl = TopTools_ListOfShape()
    for t in tools:
        tl.Append(occ_shape(t))
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
    """Union of solids (OCCT, same-domain faces unified; one solid expected)."""
    return _boolean(BRepAlgoAPI_Fuse(), a, tools, name)


def cut(a, *tools, name: str = "cut"):
    """a minus the tools (OCCT, same-domain faces unified; one solid expected)."""
    return _boolean(BRepAlgoAPI_Cut(), a, tools, name)


def cq_fuse(a, *tools, name: str = "fuse", clean: bool = True, touching: bool = False):
    """Union by cadquery's boolean, cleaned, one solid expected (clean=False: the raw result).

    ``touching``: the solids only touch (faces in common, no volume; the cam plate and the core and ring standing on
    it): OCCT's glue option (``BOPAlgo_GlueShift``), which skips the search for intersections (the cam: 0.95 -> 0.36
    CPU s, the same solid, its BREP text identical).  Glued solids that do overlap give a wrong union (two boxes
    overlapping by a corner: the two boxes, their volumes summed; two tools overlapping each other: no solid), so
    it is kept only when it is one solid whose volume is the sum of theirs
    (:data:`~propulsor.policy.TOUCHING_VOLUME_REL_TOL`): solids with no volume in common; else they are fused as
    overlapping ones."""
    if touching:
        glued = a.fuse(*tools, glue=True)
        if len(glued.Solids()) == 1:
            total = sum(volume(s) for s in (a, *tools))
            if abs(volume(glued) - total) <= TOUCHING_VOLUME_REL_TOL * abs(total):
                return one_solid(glued, name) if clean else glued
    return one_solid(a.fuse(*tools), name) if clean else a.fuse(*tools)


def cq_cut(a, *tools, name: str = "cut"):
    """a minus the tools by cadquery's boolean, cleaned; one solid expected."""
    return one_solid(a.cut(*tools), name)


# -- properties -----------------------------------------------------------------------------------
def volume(shape) -> float:
    """Volume of a shape (mm^3), OCCT Gauss integration over the faces."""
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(occ_shape(shape), props)
    return float(props.Mass())


def brep_bytes(shape) -> bytes:
    """The shape in OCCT's binary B-rep format (``BinTools``, with any triangulation it carries): every surface, curve,
    tolerance and location to the bit, in the shape's own order, so two shapes of the same bytes are the same B-rep
    (what a batch's identical solids are known by: ``parts.solid_cache``).  About 1-8 ms a solid of make's."""
    import io

    from OCP.BinTools import BinTools

    buf = io.BytesIO()
    BinTools.Write_s(occ_shape(shape), buf)
    return buf.getvalue()


def largest_radius(shape) -> float:
    """Largest distance from the z axis of a shape whose section is round about it: half the larger
    width of its exact (optimal) bounding box, mm."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(occ_shape(shape), box, False, False)
    x0, y0, _, x1, y1, _ = box.Get()
    return max(0.5 * (x1 - x0), 0.5 * (y1 - y0))


def bounding_box(shape) -> tuple[np.ndarray, np.ndarray]:
    """The exact (optimal) axis-aligned bounding box of a shape: (lower corner, upper corner), mm."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(occ_shape(shape), box, False, False)
    x0, y0, z0, x1, y1, z1 = box.Get()
    return np.array([x0, y0, z0]), np.array([x1, y1, z1])


def mass_properties(solid, rho: float) -> tuple[float, np.ndarray]:
    """Mass (volume × rho) and centre of mass (mm) of a solid."""
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(occ_shape(solid), g)
    c = g.CentreOfMass()
    return float(g.Mass()) * rho, np.array([c.X(), c.Y(), c.Z()])


# -- manifold3d -----------------------------------------------------------------------------------
def manifold(mesh, name: str = "mesh"):
    """A manifold3d solid of a closed triangle mesh: (vertices (n, 3), faces (m, 3)), an object with
    .vertices / .faces (a trimesh) or a manifold3d.Manifold (returned as it is).  InputError naming
    ``name`` when it is not a closed, oriented 2-manifold."""
    import manifold3d as m3d

    if isinstance(mesh, m3d.Manifold):
        return mesh
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        V, F = mesh.vertices, mesh.faces
    else:
        try:
            V, F = mesh
        except (TypeError, ValueError):
            raise InputError(name, type(mesh).__name__, "must be (vertices, faces), an object with .vertices/.faces "
                             "or a manifold3d.Manifold") from None
    V = np.ascontiguousarray(np.asarray(V, np.float64))
    F = np.ascontiguousarray(np.asarray(F, np.uint64))
    require(V.ndim == 2 and V.shape[1] == 3, name, V.shape, "vertices must be (n, 3)")
    require(F.ndim == 2 and F.shape[1] == 3, name, F.shape, "faces must be (m, 3) triangles")
    man = m3d.Manifold(m3d.Mesh64(V, F))
    require(str(man.status()).endswith("NoError") and not man.is_empty(), name, str(man.status()),
            "must be a closed, oriented 2-manifold mesh")
    return man


def manifold_cube(size, at=(0.0, 0.0, 0.0)):
    """manifold3d box of the given size with its least corner at ``at``."""
    import manifold3d as m3d

    return m3d.Manifold.cube(list(size)).translate(list(at))


def manifold_cylinder(height: float, radius: float, segments: int, at=(0.0, 0.0, 0.0)):
    """manifold3d cylinder along +z (``segments`` sides) with its base centre at ``at``."""
    import manifold3d as m3d

    return m3d.Manifold.cylinder(height, radius, radius, segments).translate(list(at))
