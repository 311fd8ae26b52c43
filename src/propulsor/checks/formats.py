"""What a file under check must be before a library parses it (`propulsor check`).

Each function takes what checks.safe_read read (bytes, or a parsed DXF document) and raises
checks.safe_read.Refused with a one-line reason when the file would make a reader allocate or loop
beyond the limits of policy.py:

* STL: a binary file is 84 + 50 n bytes for its n triangles; anything else must be ASCII
  ('solid ...') within its own, smaller limit;
* 3MF: member count and declared sizes before decompressing, then decompression itself bounded
  (declared sizes can lie);
* GLB: the header's length is the file's, each chunk lies within the file, the JSON chunk is bounded
  and parses, buffers, views and accessors lie within the binary chunk and are not too many, no
  external URIs, the nodes form a forest (children in range, each node reached once from the
  roots), and the triangles its nodes draw (a mesh counted for every node instancing it) are within
  policy.GLB_DRAWN_TRIANGLES_MAX, its primitives within policy.GLB_ITEMS_MAX: the 3D view's own budget;
* DXF: coordinates, radii and arc radii finite and within policy.DXF_COORD_MAX_MM, and the points
  the arcs flatten to within policy.DXF_POINTS_MAX, before anything is flattened.
"""

from __future__ import annotations

import io
import math
import struct
import zipfile

from ..policy import (CHORD_TOL_MM, DXF_COORD_MAX_MM, DXF_POINTS_MAX, READ_LIMIT_BYTES, THREEMF_MEMBERS_MAX,
                      THREEMF_UNZIPPED_MAX_BYTES)
from .safe_read import Refused


# --- STL -------------------------------------------------------------------------------------------
def stl_kind(data: bytes) -> str:
    """'binary' or 'ascii'."""
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            return "binary"
    if data.lstrip()[:5].lower() == b"solid":
        limit = READ_LIMIT_BYTES["stl_ascii"]
        if len(data) > limit:
            raise Refused(f"ASCII STL of {len(data)} bytes: larger than the {limit} bytes allowed")
        return "ascii"
    if len(data) < 84:
        raise Refused(f"{len(data)} bytes: shorter than a binary STL header (84 bytes) and not ASCII")
    n = struct.unpack_from("<I", data, 80)[0]
    raise Refused(f"binary STL declares {n} triangles, i.e. 84 + 50 n = {84 + 50 * n} bytes, "
                  f"but the file has {len(data)}")


# --- 3MF -------------------------------------------------------------------------------------------
def check_3mf_zip(data: bytes) -> None:
    """The zip's members: how many, their declared and their actual decompressed sizes."""
    try:
        zf = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, ValueError, OSError, EOFError) as exc:
        raise Refused(f"not a zip archive: {exc}") from None
    with zf:
        infos = zf.infolist()
        if len(infos) > THREEMF_MEMBERS_MAX:
            raise Refused(f"{len(infos)} zip members: more than {THREEMF_MEMBERS_MAX}")
        declared = sum(i.file_size for i in infos)
        if declared > THREEMF_UNZIPPED_MAX_BYTES:
            raise Refused(f"zip members declare {declared} bytes: more than {THREEMF_UNZIPPED_MAX_BYTES} unzipped")
        total = 0
        for info in infos:
            try:
                with zf.open(info) as member:
                    while block := member.read(1 << 20):
                        total += len(block)
                        if total > THREEMF_UNZIPPED_MAX_BYTES:
                            raise Refused(f"zip members inflate past {THREEMF_UNZIPPED_MAX_BYTES} bytes "
                                          f"(declared {declared})")
            except Refused:
                raise
            except Exception as exc:  # noqa: BLE001 - a corrupt, encrypted or truncated member
                raise Refused(f"zip member {info.filename!r} unreadable: {type(exc).__name__}: {exc}") from None


# --- GLB (export/glb_check.py: the pages that show a model ask the same) -----------------------------
def check_glb(data: bytes) -> dict:
    """The GLB's JSON (a dict) once header, chunks, buffers, node graph and drawn triangles are sound
    (export.glb_check.check_glb); Refused otherwise."""
    from ..export import glb_check

    try:
        return glb_check.check_glb(data)
    except glb_check.Refused as exc:
        raise Refused(str(exc)) from None


def drawn_triangles(gltf: dict) -> int:
    """Triangles the 3D view draws of a sound GLB's JSON (export.glb_check.drawn_triangles); Refused past the budget."""
    from ..export import glb_check

    try:
        return glb_check.drawn_triangles(gltf)
    except glb_check.Refused as exc:
        raise Refused(str(exc)) from None


# --- DXF -------------------------------------------------------------------------------------------
def _arc_points(radius: float, sweep: float) -> int:
    """Points policy.CHORD_TOL_MM flattening gives an arc (as geometry.profile.Arc.sample)."""
    if radius <= CHORD_TOL_MM:
        return 2
    da = 2.0 * math.acos(max(-1.0, 1.0 - CHORD_TOL_MM / radius))
    return int(math.ceil(abs(sweep) / max(da, 1e-9))) + 1


def _coord(v, what: str) -> float:
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise Refused(f"{what} = {v!r}: not a number") from None
    if not math.isfinite(x) or abs(x) > DXF_COORD_MAX_MM:
        raise Refused(f"{what} = {x!r}: beyond the ±{DXF_COORD_MAX_MM:g} mm a drawing may span")
    return x


def _bulged(points, what: str, closed: bool) -> int:
    """Points of a polyline of (x, y, bulge) vertices once flattened."""
    pts = [(_coord(x, f"{what} x"), _coord(y, f"{what} y"), b) for x, y, b in points]
    total = len(pts)
    for i, (x0, y0, b) in enumerate(pts if closed else pts[:-1]):
        try:
            b = float(b)
        except (TypeError, ValueError):
            raise Refused(f"{what} bulge = {b!r}: not a number") from None
        if not math.isfinite(b):
            raise Refused(f"{what} bulge = {b!r}: not finite")
        if abs(b) < 1e-15:
            continue
        x1, y1, _ = pts[(i + 1) % len(pts)]
        r = math.hypot(x1 - x0, y1 - y0) * (1.0 + b * b) / (4.0 * abs(b))
        _coord(r, f"{what} arc radius (bulge {b!r})")
        total += _arc_points(r, 4.0 * math.atan(b))
    return total


def check_dxf_doc(doc) -> None:
    """Coordinates and radii of every entity in the model space within bounds, and the points their
    curves flatten to within policy.DXF_POINTS_MAX."""
    total = 0
    for k, e in enumerate(doc.modelspace()):
        t = e.dxftype()
        what = f"{t} #{k + 1}"
        if t == "LWPOLYLINE":
            total += _bulged(e.get_points("xyb"), what, bool(e.closed))
        elif t == "POLYLINE":
            vs = [(v.dxf.location[0], v.dxf.location[1], v.dxf.get("bulge", 0.0)) for v in e.vertices]
            total += _bulged(vs, what, bool(e.is_closed))
            for v in e.vertices:
                _coord(v.dxf.location[2], f"{what} z")
        elif t in ("CIRCLE", "ARC"):
            for a, c in zip("xyz", e.dxf.center):
                _coord(c, f"{what} centre {a}")
            r = _coord(e.dxf.radius, f"{what} radius")
            total += _arc_points(abs(r), 2 * math.pi)
        elif t == "ELLIPSE":
            for a, c in zip("xyz", e.dxf.center):
                _coord(c, f"{what} centre {a}")
            major = math.hypot(*(_coord(c, f"{what} major axis") for c in e.dxf.major_axis))
            _coord(major, f"{what} major axis")
            ratio = float(e.dxf.ratio)
            if not (math.isfinite(ratio) and 0.0 < ratio <= 1.0):
                raise Refused(f"{what} ratio = {ratio!r}: not within (0, 1]")
            total += _arc_points(major, 2 * math.pi)
        elif t == "SPLINE":
            pts = list(e.control_points) + list(e.fit_points)
            for p in pts:
                for c in p:
                    _coord(c, f"{what} point")
            for kn in e.knots:
                if not math.isfinite(float(kn)):
                    raise Refused(f"{what} knot = {kn!r}: not finite")
            if not 1 <= int(e.dxf.degree) <= 11:
                raise Refused(f"{what} degree = {e.dxf.degree}: not within 1 ... 11")
            total += 64 * max(len(pts), 1)
        elif t in ("LINE", "POINT"):
            for name in ("start", "end", "location"):
                if e.dxf.hasattr(name):
                    for c in e.dxf.get(name):
                        _coord(c, f"{what} {name}")
        if total > DXF_POINTS_MAX:
            raise Refused(f"its curves flatten to more than {DXF_POINTS_MAX} points (at {what})")
