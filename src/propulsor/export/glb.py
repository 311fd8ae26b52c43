"""GLB (binary glTF 2.0) of an assembly, and its script twin for pages opened from disk.

One node per component, named as the component of the assembly STEP (children of one root node named
as the assembly, which turns the project's z-up frame into glTF's y-up one), each with its own mesh and
material (a base colour from the fixed palette of :mod:`propulsor.export.render`): components that
are the same solid (planets, legs, sectors) share the solid's vertex and index accessors, so a
solid is stored once however often it is placed.  Each vertex carries a shading normal (NORMAL:
smooth across tangent edges, split at feature edges; :mod:`propulsor.export.normals`).  glTF's unit is the metre: vertex positions and
node translations are the millimetres × 0.001.  Written here (not through trimesh's exporter) so
that the bytes depend on the meshes only: JSON with sorted keys, chunks padded as the glTF 2.0
specification asks (JSON with spaces, BIN with zeros).

An assembly may move (:meth:`parts.writer.OutputWriter.add_motion`): each motion is a glTF animation
(named as the motion, its poses in ``extras``) with one key per proof pose (STEP interpolation: the
poses themselves, nothing between), at the GIF's frame times; a moving component's node then carries
its placement as translation and rotation (glTF animates those, not a matrix).

A page that shows the GLB carries its bytes as a data block (``export/viewer_page.py``): a page opened
from disk (file://) may not fetch() or XHR a file beside it, and no file beside a page is run as a script.
"""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np

from .normals import smooth_normals
from .render import palette_colour
from ..write_root import prepare

#: glTF's unit is the metre; the project's the millimetre
MM_TO_M = 1e-3
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_FLOAT, _UNSIGNED_INT = 5126, 5125
_SQRT_HALF = 0.7071067811865476


def _pad(data: bytes, fill: bytes) -> bytes:
    return data + fill * (-len(data) % 4)


def lift_planar(poses) -> np.ndarray:
    """(…, 4, 4) rigid placements of (…, 2, 3) planar poses: the rotation about z and the x-y shift."""
    poses = np.asarray(poses, float)
    out = np.zeros(poses.shape[:-2] + (4, 4))
    out[..., :2, :2] = poses[..., :, :2]
    out[..., :2, 3] = poses[..., :, 2]
    out[..., 2, 2] = out[..., 3, 3] = 1.0
    return out


def _trs(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(translation (…, 3) m, unit quaternion (…, 4) x y z w) of rigid placements (…, 4, 4) in mm."""
    from scipy.spatial.transform import Rotation

    m = np.asarray(m, float)
    q = Rotation.from_matrix(m[..., :3, :3].reshape(-1, 3, 3)).as_quat().reshape(m.shape[:-2] + (4,))
    q = q * np.where(q[..., 3:] < 0.0, -1.0, 1.0)  # one sign (w >= 0)
    return m[..., :3, 3] * MM_TO_M, q


def write_glb(path: str | Path, name: str, meshes: dict, components, motions=()) -> Path:
    """Write an assembly GLB.

    meshes: solid key -> (vertices (n, 3) mm, faces (m, 3)); components: (component name, solid key,
    4×4 placement in mm), in the assembly's order (the k-th gets palette colour k); motions: (info,
    {component index: (frames, 4, 4) placements mm}), info with name, frame_ms and what ``extras``
    keeps (title, steps, poses)."""
    path = Path(path)
    blob = bytearray()
    views, accessors, geometry = [], [], {}

    def view(data: bytes, target: int | None) -> int:
        blob.extend(b"\0" * (-len(blob) % 4))
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        if target is not None:
            views[-1]["target"] = target
        blob.extend(data)
        return len(views) - 1

    for key in dict.fromkeys(k for _, k, _ in components):  # first use order
        v, n, f = smooth_normals(*meshes[key])
        pos = (v * MM_TO_M).astype("<f4")
        nrm = n.astype("<f4")
        idx = np.asarray(f, np.int64).astype("<u4").reshape(-1)
        accessors.append({"bufferView": view(pos.tobytes(), _ARRAY_BUFFER), "componentType": _FLOAT,
                          "count": len(pos), "type": "VEC3",
                          "min": [float(x) for x in pos.min(axis=0)], "max": [float(x) for x in pos.max(axis=0)]})
        accessors.append({"bufferView": view(nrm.tobytes(), _ARRAY_BUFFER), "componentType": _FLOAT,
                          "count": len(nrm), "type": "VEC3"})
        accessors.append({"bufferView": view(idx.tobytes(), _ELEMENT_ARRAY_BUFFER), "componentType": _UNSIGNED_INT,
                          "count": len(idx), "type": "SCALAR"})
        geometry[key] = (len(accessors) - 3, len(accessors) - 2, len(accessors) - 1)

    moving = {k for _, moves in motions for k in moves}
    nodes, gl_meshes, materials = [], [], []
    for k, (cname, key, matrix) in enumerate(components):
        m = np.asarray(matrix, np.float64).copy()
        m[:3, 3] *= MM_TO_M
        r, g, b = palette_colour(k)
        materials.append({"name": cname, "pbrMetallicRoughness": {
            "baseColorFactor": [r, g, b, 1.0], "metallicFactor": 0.2, "roughnessFactor": 0.6}})
        pos, nrm, idx = geometry[key]
        gl_meshes.append({"name": cname, "primitives": [
            {"attributes": {"NORMAL": nrm, "POSITION": pos}, "indices": idx, "material": k, "mode": 4}]})
        node = {"name": cname, "mesh": k}
        if k in moving:
            t, q = _trs(matrix)
            node["translation"], node["rotation"] = [float(x) for x in t], [float(x) for x in q]
        elif not np.allclose(m, np.eye(4), rtol=0.0, atol=1e-15):
            node["matrix"] = [float(x) for x in m.T.reshape(-1)]  # column-major
        nodes.append(node)
    # the root: the project's z-up frame turned into glTF's y-up one (-90° about x: z -> y, y -> -z)
    nodes.append({"name": name, "children": list(range(len(nodes))), "rotation": [-_SQRT_HALF, 0.0, 0.0, _SQRT_HALF]})
    animations = []
    for info, moves in motions:
        n = len(next(iter(moves.values())))
        times = (np.arange(n) * (float(info["frame_ms"]) / 1000.0)).astype("<f4")
        accessors.append({"bufferView": view(times.tobytes(), None), "componentType": _FLOAT, "count": n,
                          "type": "SCALAR", "min": [float(times[0])], "max": [float(times[-1])]})
        t_in = len(accessors) - 1
        channels, samplers = [], []
        for k in sorted(moves):
            t, q = _trs(moves[k])
            for path_, values, kind in (("translation", t, "VEC3"), ("rotation", q, "VEC4")):
                accessors.append({"bufferView": view(values.astype("<f4").tobytes(), None),
                                  "componentType": _FLOAT, "count": n, "type": kind})
                samplers.append({"input": t_in, "output": len(accessors) - 1, "interpolation": "STEP"})
                channels.append({"sampler": len(samplers) - 1, "target": {"node": k, "path": path_}})
        extras = {key: info[key] for key in ("title", "steps", "poses", "frame_ms") if key in info}
        animations.append({"name": str(info["name"]), "channels": channels, "samplers": samplers, "extras": extras})
    doc = {
        "asset": {"version": "2.0", "generator": "propulsor"},
        "scene": 0,
        "scenes": [{"name": name, "nodes": [len(nodes) - 1]}],
        "nodes": nodes, "meshes": gl_meshes, "materials": materials,
        "accessors": accessors, "bufferViews": views, "buffers": [{"byteLength": len(blob)}],
    }
    if animations:
        doc["animations"] = animations
    js = _pad(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode("utf-8"), b" ")
    bn = _pad(bytes(blob), b"\0")
    total = 12 + 8 + len(js) + 8 + len(bn)
    data = (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(js), b"JSON") + js
            + struct.pack("<I4s", len(bn), b"BIN\0") + bn)
    prepare(path)
    path.write_bytes(data)
    return path


def placement_matrix(component) -> np.ndarray:
    """The 4×4 placement (mm) of an assembly component as :func:`export.step.write_assembly_step`
    reads it: (name, solid, (x, y, z), rot_z_rad), (name, solid, cq.Location), ..."""
    from .step import _location

    loc = _location(component[2] if len(component) > 2 else None, component[3] if len(component) > 3 else None)
    t = loc.wrapped.Transformation()
    m = np.eye(4)
    for i in range(3):
        for j in range(4):
            m[i, j] = t.Value(i + 1, j + 1)
    return m
