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
import json
import math
import struct
import zipfile

from ..policy import (CHORD_TOL_MM, DXF_COORD_MAX_MM, DXF_POINTS_MAX, GLB_DRAWN_TRIANGLES_MAX, GLB_ITEMS_MAX,
                      GLB_JSON_MAX_BYTES, READ_LIMIT_BYTES, THREEMF_MEMBERS_MAX, THREEMF_UNZIPPED_MAX_BYTES)
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


# --- GLB -------------------------------------------------------------------------------------------
_GLB_MAGIC, _JSON, _BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
_ITEM_BYTES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
_ITEM_COUNT = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def _index(v, n: int, what: str) -> int:
    if not isinstance(v, int) or isinstance(v, bool) or not 0 <= v < n:
        raise Refused(f"{what} = {v!r}: not an index below {n}")
    return v


def _size(v, what: str, default=None) -> int:
    if v is None and default is not None:
        return default
    if not isinstance(v, int) or isinstance(v, bool) or v < 0:
        raise Refused(f"{what} = {v!r}: not a whole number >= 0")
    return v


def _list(gltf: dict, key: str) -> list:
    v = gltf.get(key, [])
    if not isinstance(v, list) or not all(isinstance(x, dict) for x in v):
        raise Refused(f"'{key}' is not a list of objects")
    if len(v) > GLB_ITEMS_MAX:
        raise Refused(f"{len(v)} {key}: more than {GLB_ITEMS_MAX}")
    return v


def check_glb(data: bytes) -> dict:
    """The GLB's JSON (a dict) once header, chunks, buffers and node graph are sound."""
    if len(data) < 20:
        raise Refused(f"{len(data)} bytes: shorter than a GLB header")
    magic, version, length = struct.unpack_from("<III", data, 0)
    if magic != _GLB_MAGIC or version != 2:
        raise Refused("not a glTF 2 binary (magic 'glTF', version 2)")
    if length != len(data):
        raise Refused(f"header length {length} bytes but the file has {len(data)}")
    chunks, at = [], 12
    while at < len(data):
        if at + 8 > len(data):
            raise Refused(f"chunk header at byte {at} runs past the end of the file")
        n, kind = struct.unpack_from("<II", data, at)
        if n > len(data) - at - 8:
            raise Refused(f"chunk at byte {at} declares {n} bytes; {len(data) - at - 8} remain in the file")
        chunks.append((kind, at + 8, n))
        at += 8 + n
    if not chunks or chunks[0][0] != _JSON:
        raise Refused("the first chunk is not JSON")
    _, start, n = chunks[0]
    if n > GLB_JSON_MAX_BYTES:
        raise Refused(f"JSON chunk of {n} bytes: more than {GLB_JSON_MAX_BYTES}")
    try:
        gltf = json.loads(data[start:start + n].decode("utf-8"))
    except (ValueError, RecursionError) as exc:
        raise Refused(f"JSON chunk does not parse: {type(exc).__name__}: {exc}") from None
    if not isinstance(gltf, dict):
        raise Refused("JSON chunk is not an object")
    bin_len = next((m for kind, _, m in chunks[1:] if kind == _BIN), 0)
    _check_buffers(gltf, bin_len, len(data))
    _check_nodes(gltf)
    drawn_triangles(gltf)
    return gltf


def drawn_triangles(gltf: dict) -> int:
    """Triangles the 3D view draws of a sound GLB's JSON (after :func:`check_glb`'s node checks): each node's
    mesh once per node (a mesh instanced by many nodes counts each time), a primitive's triangles from its
    index count (else its vertex count; strips and fans n - 2; lines and points one per item).  Refused
    past policy.GLB_DRAWN_TRIANGLES_MAX, and past policy.GLB_ITEMS_MAX primitives in all its meshes."""
    meshes, accessors = _list(gltf, "meshes"), _list(gltf, "accessors")
    per_mesh, primitives = [], 0
    for k, mesh in enumerate(meshes):
        prims = mesh.get("primitives", [])
        if not isinstance(prims, list) or not all(isinstance(p, dict) for p in prims):
            raise Refused(f"meshes[{k}].primitives is not a list of objects")
        primitives += len(prims)
        if primitives > GLB_ITEMS_MAX:
            raise Refused(f"more than {GLB_ITEMS_MAX} primitives in its meshes")
        n = 0
        for j, prim in enumerate(prims):
            attrs = prim.get("attributes", {})
            if not isinstance(attrs, dict):
                raise Refused(f"meshes[{k}].primitives[{j}].attributes is not an object")
            source = prim["indices"] if "indices" in prim else attrs.get("POSITION")
            if source is None:
                continue
            count = _size(accessors[_index(source, len(accessors), f"meshes[{k}].primitives[{j}] accessor")]
                          .get("count"), f"meshes[{k}].primitives[{j}] count")
            mode = prim.get("mode", 4)
            n += count // 3 if mode == 4 else max(count - 2, 0) if mode in (5, 6) else count
        per_mesh.append(n)
    total = sum(per_mesh[node["mesh"]] for node in _list(gltf, "nodes") if "mesh" in node)
    if total > GLB_DRAWN_TRIANGLES_MAX:
        raise Refused(f"its nodes draw {total} triangles, more than the {GLB_DRAWN_TRIANGLES_MAX} the 3D view draws")
    return total


def _check_buffers(gltf: dict, bin_len: int, file_len: int) -> None:
    buffers = _list(gltf, "buffers")
    for k, b in enumerate(buffers):
        if "uri" in b:
            raise Refused(f"buffers[{k}] has a URI: a GLB keeps its data in its binary chunk")
        if _size(b.get("byteLength"), f"buffers[{k}].byteLength") > bin_len:
            raise Refused(f"buffers[{k}].byteLength {b['byteLength']} exceeds the binary chunk ({bin_len} bytes)")
    for k, im in enumerate(_list(gltf, "images")):
        if "uri" in im:
            raise Refused(f"images[{k}] has a URI: a GLB keeps its data in its binary chunk")
    views = _list(gltf, "bufferViews")
    view_len = []
    for k, v in enumerate(views):
        b = buffers[_index(v.get("buffer"), len(buffers), f"bufferViews[{k}].buffer")]
        off = _size(v.get("byteOffset"), f"bufferViews[{k}].byteOffset", 0)
        n = _size(v.get("byteLength"), f"bufferViews[{k}].byteLength")
        if off + n > b["byteLength"]:
            raise Refused(f"bufferViews[{k}] ends at byte {off + n} of a {b['byteLength']}-byte buffer")
        if "byteStride" in v and not 4 <= _size(v["byteStride"], f"bufferViews[{k}].byteStride") <= 252:
            raise Refused(f"bufferViews[{k}].byteStride = {v['byteStride']}: not within 4 ... 252")
        view_len.append(n)
    for k, a in enumerate(_list(gltf, "accessors")):
        if a.get("componentType") not in _ITEM_BYTES or a.get("type") not in _ITEM_COUNT:
            raise Refused(f"accessors[{k}]: unknown componentType or type")
        if "sparse" in a:
            raise Refused(f"accessors[{k}] is sparse (not read)")
        count = _size(a.get("count"), f"accessors[{k}].count")
        row = _ITEM_BYTES[a["componentType"]] * _ITEM_COUNT[a["type"]]
        if "bufferView" in a:
            v = _index(a["bufferView"], len(views), f"accessors[{k}].bufferView")
            stride = views[v].get("byteStride", row)
            need = _size(a.get("byteOffset"), f"accessors[{k}].byteOffset", 0) + (
                (count - 1) * stride + row if count else 0)
            if need > view_len[v]:
                raise Refused(f"accessors[{k}] needs {need} bytes of a {view_len[v]}-byte buffer view")
        elif count * row > file_len:
            raise Refused(f"accessors[{k}] of {count} items has no data and is larger than the file")


def _check_nodes(gltf: dict) -> None:
    nodes = _list(gltf, "nodes")
    n = len(nodes)
    n_meshes = len(_list(gltf, "meshes"))
    parent = [-1] * n
    for k, node in enumerate(nodes):
        if "mesh" in node:
            _index(node["mesh"], n_meshes, f"nodes[{k}].mesh")
        children = node.get("children", [])
        if not isinstance(children, list):
            raise Refused(f"nodes[{k}].children is not a list")
        for c in children:
            c = _index(c, n, f"nodes[{k}].children")
            if parent[c] != -1 or c == k:
                raise Refused(f"node {c} is a child twice (of nodes {parent[c] if c != k else k} and {k}): "
                              "the nodes are not a tree")
            parent[c] = k
    for s, scene in enumerate(_list(gltf, "scenes")):
        roots = scene.get("nodes", [])
        if not isinstance(roots, list):
            raise Refused(f"scenes[{s}].nodes is not a list")
        for r in roots:
            if parent[_index(r, n, f"scenes[{s}].nodes")] != -1:
                raise Refused(f"scenes[{s}] has node {r} as a root, but it is a child of node {parent[r]}")
    # every node has at most one parent: the nodes not reached from the parentless ones lie on cycles
    seen = [False] * n
    stack = [k for k in range(n) if parent[k] == -1]
    while stack:
        k = stack.pop()
        seen[k] = True
        stack.extend(nodes[k].get("children", []))
    if not all(seen):
        raise Refused(f"node {seen.index(False)} lies on a cycle of children")


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
