"""`propulsor check` on crafted files: never a traceback, never a hang, memory under the ceiling.

Each case runs the command line in a subprocess with a timeout and the address space limited to
policy.CHECK_MEMORY_CEILING (RLIMIT_AS), and asserts exit 1 (the file invalid, with its reason) and
no traceback.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import resource
import signal
import struct
import subprocess
import sys
import zipfile
from pathlib import Path

import ezdxf
import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from propulsor.export.manifest import write_manifest
from propulsor.export.mesh import write_stl
from propulsor.policy import CHECK_MEMORY_CEILING, THREEMF_UNZIPPED_MAX_BYTES

SRC = Path(__file__).resolve().parents[1] / "src"


def _limit():
    resource.setrlimit(resource.RLIMIT_AS, (CHECK_MEMORY_CEILING, CHECK_MEMORY_CEILING))


def check(path, timeout=60) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env.setdefault("PYTHONPATH", str(SRC))
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "check", str(path)], capture_output=True, text=True,
                       timeout=timeout, env=env, preexec_fn=_limit)
    assert "Traceback" not in r.stdout + r.stderr, r.stdout + r.stderr
    return r


def invalid(path, fragment: str):
    r = check(path)
    assert r.returncode == 1, (r.returncode, r.stdout, r.stderr)
    assert fragment in r.stdout, r.stdout
    return r


# -- special files and links ------------------------------------------------------------------------

def test_fifo_is_invalid_not_a_hang(tmp_path):
    os.mkfifo(tmp_path / "manifest.json")
    os.mkfifo(tmp_path / "part.stl")
    r = invalid(tmp_path, "is a FIFO")
    assert r.stdout.count("is a FIFO") == 2
    invalid(tmp_path / "manifest.json", "is a FIFO")


def test_manifest_symlink_to_dev_zero(tmp_path):
    (tmp_path / "manifest.json").symlink_to("/dev/zero")
    invalid(tmp_path, "symbolic link leading outside the folder")


def test_symlink_out_of_the_folder_is_invalid(tmp_path):
    outside = tmp_path / "elsewhere.stl"
    write_stl(trimesh.creation.box((10, 10, 10)), outside)
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "box.stl").symlink_to(outside)
    invalid(tmp_path / "out", "box.stl: regular file in the folder: is a symbolic link leading outside")


def test_sparse_manifest_is_not_read(tmp_path):
    m = tmp_path / "manifest.json"
    m.write_bytes(b"{")
    os.truncate(m, 5 << 30)
    invalid(tmp_path, "bytes: larger than the")


# -- formats ----------------------------------------------------------------------------------------

def test_stl_claiming_4e9_triangles(tmp_path):
    p = tmp_path / "huge.stl"
    p.write_bytes(b"\0" * 80 + struct.pack("<I", 4_000_000_000) + b"\0" * 50)
    invalid(tmp_path, "binary STL declares 4000000000 triangles")


def test_stl_of_stacked_triangles(tmp_path):
    """4600 copies of one triangle: every vertex pair and triangle pair is close (n^2 / 2)."""
    tri = struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 10, 0, 0, 0, 10, 0, 0)
    (tmp_path / "stack.stl").write_bytes(b"\0" * 80 + struct.pack("<I", 4600) + tri * 4600)
    invalid(tmp_path, "self-intersecting triangle pairs: not tested: more than")


def _zip_bomb(path: Path, members: int, each: int):
    block = b"\0" * (1 << 20)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED, compresslevel=9) as zf:
        for k in range(members):
            with zf.open(f"3D/m{k}.model", "w", force_zip64=True) as fh:
                for _ in range(each >> 20):
                    fh.write(block)


def test_3mf_zip_bomb(tmp_path):
    _zip_bomb(tmp_path / "bomb.3mf", 1, THREEMF_UNZIPPED_MAX_BYTES + (1 << 20))
    assert (tmp_path / "bomb.3mf").stat().st_size < 1 << 20
    invalid(tmp_path, "zip members declare")


def _glb(gltf: dict, binary: bytes = b"", length=None, json_len=None) -> bytes:
    j = json.dumps(gltf).encode()
    j += b" " * (-len(j) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<II", json_len if json_len is not None else len(j), 0x4E4F534A) + j
    if binary:
        body += struct.pack("<II", len(binary), 0x004E4942) + binary
    total = 12 + len(body)
    return struct.pack("<III", 0x46546C67, 2, length if length is not None else total) + body


def _box_glb(nodes) -> bytes:
    box = trimesh.creation.box((1, 1, 1))
    data = trimesh.Scene(box).export(file_type="glb")
    head, body = data[:20], data[20:]
    n = struct.unpack_from("<I", head, 12)[0]
    gltf = json.loads(body[:n])
    rest = body[n:]
    gltf["nodes"] = nodes
    gltf["scenes"] = [{"nodes": [0]}]
    binary = rest[8:8 + struct.unpack_from("<I", rest, 0)[0]]
    return _glb(gltf, binary)


def test_glb_huge_json_chunk_length(tmp_path):
    (tmp_path / "a.glb").write_bytes(_glb({"asset": {"version": "2.0"}}, json_len=0xFFFFFFF0))
    invalid(tmp_path, "declares 4294967280 bytes")


def test_glb_node_cycle(tmp_path):
    nodes = [{"children": [1]}, {"mesh": 0, "children": [2]}, {"children": [1]}]
    (tmp_path / "cycle.glb").write_bytes(_box_glb(nodes))
    invalid(tmp_path, "node 1 is a child twice")
    nodes = [{"mesh": 0}, {"children": [2]}, {"children": [1]}]
    (tmp_path / "cycle.glb").write_bytes(_box_glb(nodes))
    invalid(tmp_path, "lies on a cycle of children")


def _dxf(path: Path, add):
    doc = ezdxf.new("R2010", units=ezdxf.units.MM)
    doc.header["$INSUNITS"] = 4
    doc.layers.add("CUT")
    add(doc.modelspace())
    doc.saveas(path)


def test_dxf_huge_circle(tmp_path):
    _dxf(tmp_path / "c.dxf", lambda msp: msp.add_circle((0, 0), 1e12, dxfattribs={"layer": "CUT"}))
    invalid(tmp_path, "CIRCLE #1 radius = 1000000000000.0: beyond")


def test_dxf_huge_vertex(tmp_path):
    _dxf(tmp_path / "v.dxf", lambda msp: msp.add_lwpolyline([(0, 0, 1.0), (1e308, 0, 1.0)], format="xyb",
                                                          close=True, dxfattribs={"layer": "CUT"}))
    invalid(tmp_path, "LWPOLYLINE #1 x = 1e+308: beyond")


def test_dxf_huge_bulge_arc(tmp_path):
    """Vertices in range, but a bulge whose arc has a radius of 2.5e11 mm."""
    _dxf(tmp_path / "b.dxf", lambda msp: msp.add_lwpolyline([(0, 0, 1e12), (1, 0, 1.0)], format="xyb",
                                                          close=True, dxfattribs={"layer": "CUT"}))
    invalid(tmp_path, "arc radius")


# -- the manifest's file list -----------------------------------------------------------------------

@pytest.fixture()
def listed(tmp_path):
    out = tmp_path / "out"
    write_stl(trimesh.creation.box((10, 10, 10)), out / "box.stl")
    (out / "notes.txt").write_text("hello\n")
    write_manifest(out, "box", {}, {}, [], versions={})
    assert check(out).returncode == 0
    return out


def test_missing_or_changed_listed_file(listed):
    (listed / "notes.txt").write_text("hellO\n")
    invalid(listed, "sha256 mismatches: notes.txt")
    (listed / "notes.txt").unlink()
    invalid(listed, "listed files missing: missing: notes.txt")


def test_listed_file_replaced_by_a_link_out(listed, tmp_path):
    copy = tmp_path / "copy.txt"
    copy.write_bytes((listed / "notes.txt").read_bytes())
    (listed / "notes.txt").unlink()
    (listed / "notes.txt").symlink_to(copy)
    r = invalid(listed, "path 'notes.txt' leaves the folder")
    assert "notes.txt: regular file in the folder: is a symbolic link leading outside the folder" in r.stdout


def test_manifest_text_is_escaped(listed):
    data = json.loads((listed / "manifest.json").read_text())
    data["checks"] = [{"name": "evil\n\x1b[2Jok /tmp/x", "passed": False}]
    (listed / "manifest.json").write_text(json.dumps(data))
    r = invalid(listed, "evil\\x0a\\x1b[2Jok /tmp/x")
    assert "\x1b" not in r.stdout and not any(line.startswith("ok /tmp") for line in r.stdout.splitlines())


# -- random and mutated files -----------------------------------------------------------------------

def _seeds() -> dict[str, bytes]:
    box = trimesh.creation.box((10, 10, 10))
    out = {"box.stl": trimesh.exchange.stl.export_stl(box),
           "box.3mf": trimesh.exchange.threemf.export_3MF(box),
           "box.glb": trimesh.Scene(box).export(file_type="glb")}
    s = io.StringIO()
    doc = ezdxf.new("R2010", units=ezdxf.units.MM)
    doc.modelspace().add_lwpolyline([(0, 0, 0), (10, 0, 0.5), (10, 10, 0), (0, 10, 0)], format="xyb", close=True,
                                    dxfattribs={"layer": "CUT"})
    doc.modelspace().add_circle((5, 5), 2, dxfattribs={"layer": "CUT"})
    doc.write(s)
    out["box.dxf"] = s.getvalue().encode()
    out["manifest.json"] = json.dumps({"part": "x", "files": [{"path": "box.stl", "bytes": 1, "sha256": "0"}],
                                       "checks": [], "versions": {}}).encode()
    return out


SEEDS = _seeds()


@st.composite
def hostile(draw):
    name = draw(st.sampled_from(sorted(SEEDS)))
    data = bytearray(SEEDS[name])
    mode = draw(st.sampled_from(["mutate", "random", "dxf value"]))
    if mode == "random":
        data = bytearray(draw(st.binary(max_size=400)))
    elif mode == "dxf value":
        name, data = "box.dxf", bytearray(SEEDS["box.dxf"])
    for _ in range(draw(st.integers(1, 6)) if mode != "dxf value" else 0):
        k = draw(st.integers(0, max(len(data) - 1, 0)))
        op = draw(st.sampled_from(["flip", "big", "cut", "dup"]))
        if op == "flip" and data:
            data[k] ^= 1 << draw(st.integers(0, 7))
        elif op == "big" and len(data) >= k + 4:
            data[k:k + 4] = struct.pack("<I", draw(st.sampled_from([0xFFFFFFFF, 0x7FFFFFFF, 1 << 24, 0])))
        elif op == "cut":
            data = data[:k]
        elif op == "dup":
            data = data[:k] + data[k:k + 64] * 8 + data[k:]
    if mode == "dxf value":  # a coordinate, radius or bulge of an entity made huge or not finite
        lines = bytes(data).split(b"\n")
        start = next(i for i, line in enumerate(lines) if line.strip() == b"ENTITIES")
        nums = [i for i in range(start, len(lines)) if lines[i - 1].strip() in (b"10", b"20", b"40", b"42")]
        lines[draw(st.sampled_from(nums))] = draw(st.sampled_from([b"1e12", b"-1e13", b"1e308", b"nan", b"inf"]))
        data = bytearray(b"\n".join(lines))
    return name, bytes(data)


class Hang(BaseException):  # not swallowed by a handler of Exception
    pass


def _hang(signum, frame):
    raise Hang()


@settings(max_examples=200, deadline=None, suppress_health_check=list(HealthCheck), derandomize=True)
@given(cases=st.lists(hostile(), min_size=3, max_size=3))
def test_random_and_mutated_files_never_traceback(tmp_path_factory, cases):
    """In process (a subprocess each would take minutes): main() returns 0 or 1 with a summary line,
    within an alarm, and the peak resident size of the process stays under the ceiling."""
    from propulsor.cli import main

    folder = tmp_path_factory.mktemp("fuzz")
    for k, (name, data) in enumerate(cases):
        (folder / (name if name == "manifest.json" else f"{k}_{name}")).write_bytes(data)
    out, err = io.StringIO(), io.StringIO()
    old = signal.signal(signal.SIGALRM, _hang)
    signal.alarm(20)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(["check", "-q", str(folder)])
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    assert code in (0, 1), (code, out.getvalue(), err.getvalue())
    assert out.getvalue().rstrip().endswith("invalid") and not err.getvalue(), err.getvalue()
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 < CHECK_MEMORY_CEILING
