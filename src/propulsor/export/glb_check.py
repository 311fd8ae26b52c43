"""What a GLB must be before anything parses its data: the 3D view's pages (viewer_page.py: a model goes on a
page only when it passes) and `propulsor check` (checks/formats.py re-exports these) ask the same.

The header's length is the file's, each chunk lies within the file, the JSON chunk is bounded and parses,
buffers, views and accessors lie within the binary chunk and are not too many (policy.GLB_ITEMS_MAX each, and
primitives in all), no external URIs, the nodes form a forest (children in range, each node reached once from
the roots), and the triangles its nodes draw (a mesh counted for every node instancing it) are within
policy.GLB_DRAWN_TRIANGLES_MAX.  A GLB that is not is :class:`Refused` with a one-line reason.
"""

from __future__ import annotations

import json
import struct

from ..policy import GLB_DRAWN_TRIANGLES_MAX, GLB_ITEMS_MAX, GLB_JSON_MAX_BYTES


class Refused(ValueError):
    """A GLB that is not sound or not bounded: the one-line reason."""


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
