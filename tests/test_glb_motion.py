"""The motion in the 3D view: a part's poses (planar, as its GIF has them) become a glTF animation of the
assembly's moving components, each placed at pose · reference⁻¹ · its assembly placement; one key per
pose (STEP), the poses' proof steps in the animation's extras; the Khronos validator (npm's
gltf-validator, when web/node_modules holds it) finds no error and no warning."""

from __future__ import annotations

import json
import math
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest

from propulsor.checks.motion import rotation_matrices
from propulsor.export.glb import MM_TO_M, lift_planar, write_glb
from propulsor.parts.writer import OutputWriter

ROOT = Path(__file__).resolve().parents[1]


def box(sx, sy, sz):
    v = np.array([[x, y, z] for x in (0, sx) for y in (0, sy) for z in (0, sz)], float)
    f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4], [2, 6, 3], [3, 6, 7],
                  [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return v, f


def gltf_of(path: Path) -> tuple[dict, bytes]:
    data = path.read_bytes()
    n = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + n])
    return doc, data[20 + n + 8:]


def accessor(doc: dict, blob: bytes, k: int) -> np.ndarray:
    a = doc["accessors"][k]
    v = doc["bufferViews"][a["bufferView"]]
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a["type"]]
    return np.frombuffer(blob, "<f4", a["count"] * width, v["byteOffset"]).reshape(a["count"], width)


def placed(P0, name="a"):
    return [("still", "s", np.eye(4)), (name, "m", P0)]


def motion_writer(tmp_path, P0, poses, ref):
    w = OutputWriter(tmp_path, "test", None)
    w.add_motion("asm", {"name": "turn", "title": "a turn", "frame_ms": 60, "steps": list(range(len(poses)))},
                 {"arm": (poses, ref)})
    return w._motion_placements("asm", placed(P0, "arm"))


def test_a_moving_component_is_placed_at_pose_times_reference_inverse_times_its_placement(tmp_path):
    L, h = 80.0, 5.0
    P0 = np.eye(4)
    P0[:3, 3] = [L, 0.0, h]  # the assembly shows the arm at (L, 0), h above the plane
    angles = np.linspace(0.0, 1.5, 6)
    poses = rotation_matrices(angles, np.tile([L, 0.0], (6, 1)))
    [(info, moves)] = motion_writer(tmp_path, P0, poses, rotation_matrices([0.0], [[L, 0.0]])[0])
    assert info["name"] == "turn" and list(moves) == [1]
    M = moves[1]
    for a, m in zip(angles, M):
        assert np.allclose(m[:2, :2], [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        assert np.allclose(m[:3, 3], [L, 0.0, h])  # it turns about its own axis, at its own height
    with pytest.raises(ValueError, match="no component"):
        w = OutputWriter(tmp_path, "test", None)
        w.add_motion("asm", {"name": "x", "frame_ms": 60}, {"nobody": (poses, poses[0])})
        w._motion_placements("asm", placed(P0, "arm"))


def test_the_glb_animates_the_moving_nodes_at_each_pose_and_passes_the_validator(tmp_path):
    meshes = {"s": box(40, 30, 5), "m": box(60, 10, 5)}
    P0 = lift_planar(rotation_matrices([0.3], [[50.0, 20.0]])[0])
    angles = np.linspace(0.0, 2.0, 7)
    M = lift_planar(rotation_matrices(angles, np.tile([50.0, 20.0], (7, 1))))
    info = {"name": "turn", "frame_ms": 60, "title": "a <b>turn</b>", "steps": [3, 5, 7, 9, 11, 13, 15], "poses": "p"}
    glb = write_glb(tmp_path / "asm.glb", "asm", meshes, placed(P0), [(info, {1: M})])
    doc, blob = gltf_of(glb)
    still, arm = doc["nodes"][0], doc["nodes"][1]
    assert "translation" not in still and "rotation" not in still
    assert "matrix" not in arm and np.allclose(arm["translation"], P0[:3, 3] * MM_TO_M)
    [anim] = doc["animations"]
    assert anim["name"] == "turn" and anim["extras"]["steps"] == info["steps"] and anim["extras"]["title"] == info["title"]
    assert {c["target"]["path"] for c in anim["channels"]} == {"translation", "rotation"}
    assert all(c["target"]["node"] == 1 for c in anim["channels"])
    assert all(s["interpolation"] == "STEP" for s in anim["samplers"])
    times = accessor(doc, blob, anim["samplers"][0]["input"])[:, 0]
    assert np.allclose(times, np.arange(7) * 0.06)
    by_path = {c["target"]["path"]: accessor(doc, blob, anim["samplers"][c["sampler"]]["output"]) for c in anim["channels"]}
    assert np.allclose(by_path["translation"], M[:, :3, 3] * MM_TO_M, atol=1e-7)
    q = by_path["rotation"]  # about z by each angle: (0, 0, sin(a/2), cos(a/2))
    assert np.allclose(q, np.column_stack([0 * angles, 0 * angles, np.sin(angles / 2), np.cos(angles / 2)]), atol=1e-6)

    node = shutil.which("node")
    if node is None or not (ROOT / "web" / "node_modules" / "gltf-validator").is_dir():
        pytest.skip("the glTF validator needs node and `make validate-glb`'s web/node_modules")
    r = subprocess.run([node, str(ROOT / "web" / "validate_glb.mjs"), str(glb)], capture_output=True, text=True)
    assert r.returncode == 0 and "0 errors, 0 warnings" in r.stdout, r.stdout + r.stderr


def test_an_assembly_without_motion_is_written_as_before(tmp_path):
    meshes = {"s": box(40, 30, 5), "m": box(60, 10, 5)}
    P0 = lift_planar(rotation_matrices([0.3], [[50.0, 20.0]])[0])
    doc, _ = gltf_of(write_glb(tmp_path / "asm.glb", "asm", meshes, placed(P0)))
    assert "animations" not in doc and "matrix" in doc["nodes"][1]
    assert all("target" in v for v in doc["bufferViews"])


def test_the_validator_script_fails_on_a_warning_alone(tmp_path):
    """`make check` runs web/validate_glb.mjs over every GLB: a warning fails it as an error does."""
    node = shutil.which("node")
    if node is None or not (ROOT / "web" / "node_modules" / "gltf-validator").is_dir():
        pytest.skip("the glTF validator needs node and `make validate-glb`'s web/node_modules")
    good = write_glb(tmp_path / "good.glb", "asm", {"s": box(1, 1, 1)}, [("a", "s", np.eye(4))])
    doc, blob = gltf_of(good)
    doc["nodes"][0]["wobble"] = 1  # an unexpected property: a warning, no error
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    bad = tmp_path / "bad.glb"
    bad.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(blob)) + struct.pack("<I4s", len(js), b"JSON")
                    + js + struct.pack("<I4s", len(blob), b"BIN\0") + blob)
    r = subprocess.run([node, str(ROOT / "web" / "validate_glb.mjs"), str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 1, r.stdout + r.stderr
    assert "bad.glb: 0 errors, 1 warnings" in r.stdout and "UNEXPECTED_PROPERTY" in r.stdout
    assert "good.glb: 0 errors, 0 warnings" in r.stdout and "2 GLB file(s), 1 with errors or warnings" in r.stdout
