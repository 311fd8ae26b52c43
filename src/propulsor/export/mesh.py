"""STL / 3MF output of tessellated solids (tessellation: :mod:`propulsor.solids.tessellate`).

The chord error (linear deflection) is policy.CHORD_TOL_MM (0.005 mm, below the 0.01 mm the
outputs promise, docs/architecture.md, "The data flow of one build"), the angular deflection policy.ANGULAR_TOL_RAD.
Files are deterministic: binary STL has a fixed 80-byte header; the 3MF zip is rewritten with
fixed entry time stamps.
"""

from __future__ import annotations

import hashlib
import io
import re
import uuid
import zipfile
from pathlib import Path

import numpy as np
import trimesh

from ..policy import ANGULAR_TOL_RAD, CHORD_TOL_MM
from ..solids.tessellate import MERGE_TOL_MM, merge_close_vertices, triangulate  # noqa: F401  (public here too)
from ..write_root import prepare

#: fixed zip entry time (the earliest a zip can hold)
ZIP_DATE_TIME = (1980, 1, 1, 0, 0, 0)


def to_trimesh(solid, chord_tol: float = CHORD_TOL_MM, angular_tol: float = ANGULAR_TOL_RAD,
               parallel: bool = True) -> trimesh.Trimesh:
    """Tessellate a solid into a trimesh.Trimesh (merged vertices, no processing
    that could hide defects); metadata['chord_deflection_mm'] holds the
    deflection OCCT reports for the mesh.  parallel=False keeps BRepMesh on the
    calling thread (required in a forked worker: OCCT's thread pool does not
    survive a fork)."""
    v, f, d = triangulate(solid, chord_tol, angular_tol, parallel)
    m = trimesh.Trimesh(vertices=v, faces=f, process=False, validate=False)
    m.metadata["chord_deflection_mm"] = d
    return m


#: name used by the part writer
tessellate = to_trimesh


def write_stl(mesh: trimesh.Trimesh, path: str | Path, name: str = "") -> Path:
    """Binary STL with a fixed header (deterministic)."""
    path = Path(path)
    prepare(path)
    tri = np.asarray(mesh.triangles, np.float64)
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    ln = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, ln, out=np.zeros_like(normals), where=ln > 0)
    rec = np.zeros(len(tri), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    rec["n"] = normals
    rec["v"] = tri
    header = f"propulsor binary STL {name} mm".encode("ascii", "replace")[:80].ljust(80, b" ")
    with open(path, "wb") as fh:
        fh.write(header)
        fh.write(np.uint32(len(tri)).tobytes())
        fh.write(rec.tobytes())
    return path


_UUID = re.compile(rb'UUID="[0-9a-fA-F-]{36}"')


def _fixed_uuids(xml: bytes) -> bytes:
    """Replace random UUIDs (trimesh writes uuid4) by ones derived from the content."""
    seed = hashlib.sha256(_UUID.sub(b'UUID=""', xml)).hexdigest()
    counter = iter(range(1 << 30))
    return _UUID.sub(lambda m: f'UUID="{uuid.uuid5(uuid.NAMESPACE_OID, f"{seed}:{next(counter)}")}"'.encode(), xml)


def _deterministic_zip(data: bytes, extra: dict[str, bytes] | None = None) -> bytes:
    """Rewrite a zip with fixed entry times and attributes (same order), UUIDs fixed, each entry deflated
    here (trimesh's zip is written stored: its bodies are compressed once, not twice); `extra` entries
    {name: body} appended after them, alike."""
    out = io.BytesIO()

    def put(zout, name: str, body: bytes) -> None:
        zi = zipfile.ZipInfo(name, date_time=ZIP_DATE_TIME)
        zi.compress_type = zipfile.ZIP_DEFLATED
        zi.external_attr = 0o644 << 16
        zi.create_system = 3
        zout.writestr(zi, body, compress_type=zipfile.ZIP_DEFLATED, compresslevel=6)

    with zipfile.ZipFile(io.BytesIO(data)) as zin, zipfile.ZipFile(out, "w") as zout:
        for info in zin.infolist():
            body = zin.read(info.filename)
            if info.filename.endswith((".model", ".rels", ".xml")):
                body = _fixed_uuids(body)
            put(zout, info.filename, body)
        for name, body in (extra or {}).items():
            put(zout, name, body)
    return out.getvalue()


#: where PrusaSlicer (and its forks) keep a project's print settings inside a 3MF
SLICER_CONFIG_ENTRY = "Metadata/Slic3r_PE.config"


def slicer_config_text(config: dict[str, str]) -> str:
    """PrusaSlicer's configuration text ("; key = value" lines, keys sorted) of `config`."""
    lines = ["; the print kit's settings, written by propulsor: PrusaSlicer reads them with the plate"]
    for key in sorted(config):
        value = str(config[key])
        if "\n" in value or "\r" in value:
            raise ValueError(f"a slicer setting is one line: {key}")
        lines.append(f"; {key} = {value}")
    return "\n".join(lines) + "\n"


def write_3mf(mesh: trimesh.Trimesh, path: str | Path, name: str = "") -> Path:
    """3MF via trimesh (units mm, object called `name`), zip time stamps and
    UUIDs fixed (deterministic)."""
    path = Path(path)
    prepare(path)
    m = trimesh.Trimesh(vertices=np.asarray(mesh.vertices), faces=np.asarray(mesh.faces), process=False, validate=False)
    m.units = "millimeters"
    if name:
        scene = trimesh.Scene()
        scene.add_geometry(m, geom_name=name, node_name=name)
        scene.units = "millimeters"
        data = trimesh.exchange.threemf.export_3MF(scene, compression=zipfile.ZIP_STORED)
    else:
        data = trimesh.exchange.threemf.export_3MF(m, compression=zipfile.ZIP_STORED)
    path.write_bytes(_deterministic_zip(data))
    return path


def write_3mf_objects(objects, path: str | Path, slicer_config: dict[str, str] | None = None) -> Path:
    """One 3MF holding several named objects [(name, mesh)] in millimetres, each placed where its
    vertices are (a print plate); zip time stamps and UUIDs fixed (deterministic).  `slicer_config`:
    the print settings {PrusaSlicer key: value} the plate carries (``Metadata/Slic3r_PE.config``)."""
    path = Path(path)
    prepare(path)
    scene = trimesh.Scene()
    for name, mesh in objects:
        m = trimesh.Trimesh(vertices=np.asarray(mesh.vertices), faces=np.asarray(mesh.faces), process=False,
                            validate=False)
        m.units = "millimeters"
        scene.add_geometry(m, geom_name=name, node_name=name)
    scene.units = "millimeters"
    extra = {SLICER_CONFIG_ENTRY: slicer_config_text(slicer_config).encode()} if slicer_config else None
    path.write_bytes(_deterministic_zip(trimesh.exchange.threemf.export_3MF(scene, compression=zipfile.ZIP_STORED),
                                        extra))
    return path


def load_mesh(path: str | Path, file_type: str | None = None, max_pairs: int | None = None) -> trimesh.Trimesh:
    """Load STL / 3MF into one Trimesh with merged vertices (no repair); `path` may be a binary file
    object when `file_type` ('stl', '3mf') is given; max_pairs: see merge_close_vertices."""
    if file_type is None:
        loaded = trimesh.load(str(Path(path)), force="mesh", process=False)
    else:
        loaded = trimesh.load(path, file_type=file_type, force="mesh", process=False)
    v, f = merge_close_vertices(np.asarray(loaded.vertices), np.asarray(loaded.faces), MERGE_TOL_MM, max_pairs)
    return trimesh.Trimesh(vertices=v, faces=f, process=False, validate=False)
