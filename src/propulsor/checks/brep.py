"""Validity of B-rep solids and of their STEP round trip (docs/architecture.md, "The data flow of one build").

`brep_checks`: OCCT's BRepCheck_Analyzer finds the shape valid, it is exactly
one solid, its shells are closed (BRepCheck_Shell: no free edges), its volume is
positive, and OCCT's exact volume agrees with the volume of a triangulation within what the
triangulation's own error allows (deflection × area).  `step_roundtrip_check`: the STEP file read back holds exactly one
solid whose volume equals the built one within policy.STEP_VOLUME_REL_TOL.
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from OCP.BRepCheck import BRepCheck_Analyzer, BRepCheck_NoError, BRepCheck_Shell
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_SHELL, TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

from ..policy import ANGULAR_TOL_RAD, CHORD_TOL_MM, MESH_VOLUME_REL_TOL, STEP_VOLUME_REL_TOL
from ..check import Check
from ..solids.kernel import occ_shape, volume  # noqa: F401  (volume: public here too)


def _sub(shape, kind) -> list:
    out = []
    ex = TopExp_Explorer(shape, kind)
    while ex.More():
        out.append(ex.Current())
        ex.Next()
    return out


class TriangulatedVolume(NamedTuple):
    """The volume of a shape's triangulation and what bounds its difference from the exact volume."""

    volume_mm3: float
    deflection_mm: float  # the chord error of the triangulation (mesh_shape: OCCT's estimate, measured at an apex)
    area_mm2: float  # the B-rep's surface area

    @property
    def bound_mm3(self) -> float:
        """|triangulated − exact volume| ≤ deflection × area: every triangle lies within the deflection of
        its face, so the region between the two surfaces is at most that thick over the whole area."""
        return self.deflection_mm * self.area_mm2


def triangulated_volume(shape, chord_tol: float = CHORD_TOL_MM) -> TriangulatedVolume:
    """Volume of the shape's BRepMesh triangulation (mm^3), an independent estimate of the exact volume:
    OCCT's exact Gauss integration is wrong on some faces (an extrusion of a 400-point periodic
    interpolating B-spline: +8 %), the triangulated volume is not; with the bound of its own error."""
    from ..solids.tessellate import mesh_shape

    sh = occ_shape(shape)
    deflection = mesh_shape(sh, chord_tol, ANGULAR_TOL_RAD, True)
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(sh, props, False, False, True)
    area = GProp_GProps()
    BRepGProp.SurfaceProperties_s(sh, area)
    return TriangulatedVolume(float(props.Mass()), max(float(deflection), chord_tol), float(area.Mass()))


def volume_from_triangulation(shape, chord_tol: float = CHORD_TOL_MM) -> float:
    """The volume of the shape's triangulation (:func:`triangulated_volume`), mm^3."""
    return triangulated_volume(shape, chord_tol).volume_mm3


def shell_closed(shell) -> bool:
    """BRepCheck_Shell.Closed(): every edge of the shell bounds two faces."""
    return BRepCheck_Shell(TopoDS.Shell_s(shell)).Closed(False) == BRepCheck_NoError


def brep_checks(solid, name: str = "solid", cross_check_volume: bool = True, chord_tol: float = CHORD_TOL_MM,
                volume_mm3: float | None = None) -> list[Check]:
    """Valid B-rep, exactly one solid, closed shell(s), positive volume; and
    (cross_check_volume) OCCT's exact volume agrees with the volume of a fine
    triangulation within the triangulation's deflection × area (or policy.MESH_VOLUME_REL_TOL of the
    volume, the larger: :class:`TriangulatedVolume`).  volume_mm3: the solid's volume when the caller
    has it (:func:`propulsor.solids.kernel.volume` of this very shape)."""
    shape = occ_shape(solid)
    out: list[Check] = []
    if shape is None or shape.IsNull():
        return [Check.flag(f"{name}: shape exists", False, "null shape")]
    valid = BRepCheck_Analyzer(shape).IsValid()
    out.append(Check.flag(f"{name}: BRepCheck_Analyzer valid", valid, "OCCT topology and geometry check"))
    solids = _sub(shape, TopAbs_SOLID)
    out.append(Check.equals(f"{name}: solids", len(solids), 1, "", "exactly one solid"))
    shells = _sub(shape, TopAbs_SHELL)
    n_open = sum(not shell_closed(s) for s in shells)
    out.append(Check.equals(f"{name}: open shells", n_open, 0, "", f"{len(shells)} shell(s), all closed"))
    v = volume(shape) if volume_mm3 is None else volume_mm3
    out.append(Check.greater_than(f"{name}: B-rep volume", v, 0.0, "mm^3", "positive volume (outward faces)"))
    if cross_check_volume and solids:
        t = triangulated_volume(shape, chord_tol)
        out.append(
            Check.equal_within(
                f"{name}: exact volume vs triangulated", v, t.volume_mm3, rel_tol=MESH_VOLUME_REL_TOL,
                abs_tol=t.bound_mm3, unit="mm^3",
                message=f"OCCT volume {v:.9g} vs triangulation {t.volume_mm3:.9g} mm^3: they may differ by the "
                        f"triangulation's deflection {t.deflection_mm:.3g} mm times the area {t.area_mm2:.6g} mm^2 "
                        f"= {t.bound_mm3:.3g} mm^3 (or {MESH_VOLUME_REL_TOL:g} of the volume); more means OCCT's "
                        "volume integration failed",
            )
        )
    return out


def step_roundtrip_check(solid, step_path: str | Path, name: str | None = None, rel_tol: float = STEP_VOLUME_REL_TOL,
                         built_volume: float | None = None) -> Check:
    """Re-import the STEP file: passes when it holds exactly one solid whose
    volume equals the built solid's within rel_tol (value: re-imported volume).  built_volume: the
    built solid's volume when the caller has it (:func:`propulsor.solids.kernel.volume` of `solid`)."""
    from ..export.step import read_step_solids

    step_path = Path(step_path)
    name = name or step_path.name
    cname = f"{name}: STEP round trip"
    try:
        solids = read_step_solids(step_path, as_written=True)  # the healing that would hide a defect left out
    except (ValueError, FileNotFoundError) as exc:
        return Check(cname, False, None, {"solids": 1, "rel_tol": rel_tol}, "mm^3", f"STEP re-import failed: {exc}")
    v0 = volume(solid) if built_volume is None else built_volume
    v1 = sum(volume(s) for s in solids)
    dev = abs(v1 - v0) / abs(v0) if v0 else float("inf")
    ok = len(solids) == 1 and dev <= rel_tol
    msg = f"{len(solids)} solid(s) re-imported from {step_path.name}; volume {v1:.10g} vs built {v0:.10g} mm^3 (relative {dev:.2g})"
    return Check(cname, ok, v1, {"expected": v0, "rel_tol": rel_tol, "solids": 1}, "mm^3", msg)
