"""STEP files: one named solid, an assembly of named placed parts, and reading back.

Units are millimetres, schema AP214 (AUTOMOTIVE_DESIGN), written through OCCT's
XCAF so that product names survive.  Output is deterministic: OCCT stamps the
current time into the header's FILE_NAME entity; it is rewritten to the fixed
`STEP_TIMESTAMP` so the same input gives byte-identical files.
"""

from __future__ import annotations

import re
from pathlib import Path

from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPCAFControl import STEPCAFControl_Writer
from OCP.STEPControl import STEPControl_AsIs, STEPControl_Reader
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.TopoDS import TopoDS_Shape
from OCP.XCAFDoc import XCAFDoc_DocumentTool

from ..solids.cq_import import import_cadquery
from ..solids.kernel import occ_shape, solids_of  # noqa: F401  (solids_of: public here too)
from ..write_root import prepare

STEP_TIMESTAMP = "2000-01-01T00:00:00"
STEP_SCHEMA = "AP214IS"

_TS = re.compile(r"'\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}'")
_NAUO = re.compile(r"(NEXT_ASSEMBLY_USAGE_OCCURRENCE\(\s*)'[^']*'")


def _set_units() -> None:
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    Interface_Static.SetCVal_s("write.step.schema", STEP_SCHEMA)
    Interface_Static.SetIVal_s("write.step.assembly", 1)
    Interface_Static.SetCVal_s("write.step.product.name", "propulsor")


def fix_header(path: str | Path) -> None:
    """Make a written STEP file reproducible (in place): fixed time stamp, occurrence ids 1..n."""
    p = Path(path)
    data = p.read_bytes()
    head_end = data.find(b"ENDSEC;")
    if head_end < 0:
        raise ValueError(f"{p}: no STEP header section")
    head = data[:head_end].decode("latin-1")
    head = _TS.sub(f"'{STEP_TIMESTAMP}'", head, count=1)
    body = data[head_end:]
    # OCCT numbers assembly occurrences with a process-wide counter: renumber 1, 2, ...  (a body without one is
    # written as it is: a gear's 4 MB are not decoded, searched and encoded again for nothing)
    if b"NEXT_ASSEMBLY_USAGE_OCCURRENCE" in body:
        counter = iter(range(1, 1 << 30))
        body = _NAUO.sub(lambda m: f"{m.group(1)}'{next(counter)}'", body.decode("latin-1")).encode("latin-1")
    p.write_bytes(head.encode("latin-1") + body)


def _write_failed(path: Path, what: str) -> Exception:
    """Why OCCT's writer failed (it gives no errno): a folder that takes no new file of 64 KiB is the
    machine's refusal (EnvironmentFailure, exit 3: disk or inodes full, read-only, no permission); else
    the writer's own failure."""
    import os
    import tempfile

    from ..errors import EnvironmentFailure

    try:
        fd, probe = tempfile.mkstemp(prefix=".probe.", dir=path.parent)
        try:
            os.write(fd, bytes(65536))
            os.fsync(fd)
        finally:
            os.close(fd)
            os.unlink(probe)
    except OSError as exc:
        return EnvironmentFailure(path, exc.errno, "cannot write", exc.strerror or "")
    return RuntimeError(f"{what} failed: {path}")


def write_step(solid, path: str | Path, name: str) -> Path:
    """Write one solid to STEP (mm, AP214) as a product called `name`."""
    shape = occ_shape(solid)
    path = Path(path)
    prepare(path)
    _set_units()
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    label = tool.AddShape(shape, False)
    TDataStd_Name.Set_s(label, TCollection_ExtendedString(name))
    writer = STEPCAFControl_Writer()
    writer.SetNameMode(True)
    if not writer.Transfer(doc, STEPControl_AsIs):
        raise RuntimeError(f"STEP transfer failed for {name}")
    if writer.Write(str(path)) != IFSelect_RetDone:
        raise _write_failed(path, "STEP write")
    fix_header(path)
    return path


def _location(loc, rot_z=None):
    import math

    cq = import_cadquery()

    if isinstance(loc, cq.Location):
        return loc
    if rot_z is not None:  # (x, y, z) mm and a rotation about z in radians
        return cq.Location(cq.Vector(*map(float, loc)), cq.Vector(0, 0, 1), math.degrees(float(rot_z)))
    if loc is None:
        return cq.Location()
    if isinstance(loc[0], (tuple, list)):  # ((x, y, z), (ax, ay, az), angle_deg)
        t, axis, ang = loc
        return cq.Location(cq.Vector(*map(float, t)), cq.Vector(*map(float, axis)), float(ang))
    return cq.Location(cq.Vector(*map(float, loc)))


def write_assembly_step(path, components, name: str) -> Path:
    """Write an assembly STEP of named, placed components.

    components: (name, solid, location) with location a cadquery Location, an
    (x, y, z) translation, ((x, y, z), (ax, ay, az), angle_deg) or None; or
    (name, solid, (x, y, z), rot_z_rad) - placed by a rotation about z, then the
    translation.  For convenience the first two arguments may come in either
    order (components, path).  Each component keeps its name and placement.
    """
    cq = import_cadquery()
    from cadquery.occ_impl.exporters.assembly import exportAssembly

    if isinstance(components, (str, Path)):
        path, components = components, path
    path = Path(path)
    prepare(path)
    assy = cq.Assembly(name=name)
    seen = set()
    for comp in components:
        cname, solid = comp[0], comp[1]
        if cname in seen:
            raise ValueError(f"duplicate component name {cname!r}")
        seen.add(cname)
        loc = _location(comp[2] if len(comp) > 2 else None, comp[3] if len(comp) > 3 else None)
        assy.add(cq.Shape.cast(occ_shape(solid)), name=cname, loc=loc)
    _set_units()
    if not exportAssembly(assy, str(path)):
        raise _write_failed(path, "STEP assembly write")
    fix_header(path)
    return path


#: the shape-healing fixes the round trip's read of a file this program wrote leaves out (OCCT's
#: ``DE_ShapeFixParameters`` modes, 0 = NotFix): the searches for edges and wires that cross (five modes), the faces'
#: orientation within a shell and the edges' same-parameter repair.  On every STEP file ``make`` writes (78) they change
#: nothing: the shape read is the same, its BREP text byte for byte, in about half the transfer's time
#: (bench/bench_step_read.py).  On a file that needs them the shape is read as written (a face turned inside out
#: stays so), so that the round trip's check sees the defect a healing reader would hide.  The rest of the healing
#: runs as in any CAD reader: the fixes of solids, shells, faces, wires and edge curves change shapes (tolerances), and
#: the wires' orientation fix is what makes a CadQuery union's STEP mesh at all (examples/custom_flange.py).  A file
#: of anyone else (``propulsor check``) is read with the whole healing.
UNHEALED = ("FixSelfIntersectionMode", "FixSelfIntersectingEdgeMode", "FixIntersectingEdgesMode",
            "FixNonAdjacentIntersectingEdgesMode", "FixIntersectingWiresMode", "FixShellOrientationMode",
            "FixSameParameterMode")


def _fix_parameters():
    """The reader's shape-fix parameter map with the :data:`UNHEALED` modes off (the others at OCCT's defaults)."""
    from OCP.Resource import Resource_DataMapOfAsciiStringAsciiString
    from OCP.TCollection import TCollection_AsciiString

    m = Resource_DataMapOfAsciiStringAsciiString()
    for mode in UNHEALED:
        m.Bind(TCollection_AsciiString(f"FixShape.{mode}"), TCollection_AsciiString("0"))
    return m


def read_step(path: str | Path, as_written: bool = False) -> TopoDS_Shape:
    """Read a STEP file, healed as a CAD reader does (``as_written``: less the fixes of :data:`UNHEALED`, the round
    trip's read of a file this program wrote); raise ValueError if it does not parse or holds no shape."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(path)
    reader = STEPControl_Reader()
    status = reader.ReadFile(str(path))
    if status != IFSelect_RetDone:
        raise ValueError(f"{path}: STEP does not parse (status {int(status)})")
    if as_written:  # after ReadFile: reading makes the transfer's actor, which takes the parameters set from then on
        reader.SetShapeFixParameters(_fix_parameters())
    n = reader.TransferRoots()
    if n < 1:
        raise ValueError(f"{path}: STEP holds no transferable root")
    shape = reader.OneShape()
    if shape is None or shape.IsNull():
        raise ValueError(f"{path}: STEP gives an empty shape")
    return shape


def read_step_solids(path: str | Path, as_written: bool = False) -> list:
    """Read a STEP file (:func:`read_step`) and return its solids (list of TopoDS_Solid)."""
    return solids_of(read_step(path, as_written))


def step_product_names(path: str | Path) -> list[str]:
    """Names of PRODUCT entities in a STEP file (for checks and tests)."""
    text = Path(path).read_text(encoding="latin-1")
    return re.findall(r"PRODUCT\(\s*'((?:[^']|'')*)'", text)


def step_instance_names(path: str | Path) -> list[str]:
    """Names of the component occurrences (NEXT_ASSEMBLY_USAGE_OCCURRENCE) of an assembly STEP;
    one product used several times (identical planets) has one occurrence name per placement."""
    text = Path(path).read_text(encoding="latin-1")
    return re.findall(r"NEXT_ASSEMBLY_USAGE_OCCURRENCE\(\s*'(?:[^']|'')*'\s*,\s*'((?:[^']|'')*)'", text)
