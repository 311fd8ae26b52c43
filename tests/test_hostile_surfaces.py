"""The newer surfaces under attack: what a rebuild may remove, studies sharing a folder, a scheduler that
never answers, big tables read back, law tables that cost minutes, model data the viewer reads.

Every refusal is one line, exit 2 (bad input, naming the key) or 3 (the environment, naming the path and the
errno), never a traceback; nothing is deleted that the command did not write."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from propulsor import output_folder as of
from propulsor.errors import EnvironmentFailure

ROOT = Path(__file__).resolve().parents[1]
SMALL_WHEEL = 'type = "road_wheel"\nlightening_holes = 0\n'


from test_hostile_env import _cli, _one_error_line, _popen  # noqa: E402 - the command-line helpers of the first round


@pytest.fixture
def wheel(tmp_path):
    f = tmp_path / "wheel.toml"
    f.write_text(SMALL_WHEEL)
    return f


def _folder(path: Path, files: dict[str, str]) -> Path:
    path.mkdir(parents=True, exist_ok=True)
    for rel, text in files.items():
        (path / rel).parent.mkdir(parents=True, exist_ok=True)
        (path / rel).write_text(text)
    return path


# -- 1. the swap removes only the previous build's own files ---------------------------------------

def test_a_file_saved_into_out_during_the_build_is_never_deleted_by_the_swap(tmp_path):
    """Saved after the build began: the swap is refused (exit 3 by EnvironmentFailure), the file and the old
    output stay where they were."""
    out = _folder(tmp_path / "out", {"manifest.json": "old", "tables/a.csv": "1"})
    before = of.snapshot(out)
    (out / "mine.txt").write_text("precious")
    (out / "notes").mkdir()
    new = _folder(tmp_path / ".out.tmp-aaaaaaaa", {"manifest.json": "new"})
    with pytest.raises(EnvironmentFailure, match="changed during the build"):
        of.replace(new, out, before)
    assert (out / "mine.txt").read_text() == "precious" and (out / "notes").is_dir()
    assert (out / "manifest.json").read_text() == "old"


def test_a_file_changed_in_out_during_the_build_is_not_the_old_builds_own(tmp_path):
    out = _folder(tmp_path / "out", {"manifest.json": "old", "report.md": "as built"})
    before = of.snapshot(out)
    time.sleep(0.01)
    (out / "report.md").write_text("my edits, longer")
    new = _folder(tmp_path / ".out.tmp-aaaaaaaa", {"manifest.json": "new"})
    with pytest.raises(EnvironmentFailure):
        of.replace(new, out, before)
    assert (out / "report.md").read_text() == "my edits, longer"


@pytest.mark.parametrize("fallback", [False, True])
def test_a_file_saved_in_the_instant_of_the_swap_is_kept(tmp_path, fallback):
    """Saved between the last look and the exchange itself: the exchange is undone, the file stays."""
    out = _folder(tmp_path / "out", {"manifest.json": "old"})
    before = of.snapshot(out)
    new = _folder(tmp_path / ".out.tmp-aaaaaaaa", {"manifest.json": "new"})
    calls = []

    def exchange(a, b):
        if not calls:
            (out / "late.txt").write_text("saved at the swap")
        calls.append(1)
        return False if fallback else of.rename_exchange(a, b)

    with pytest.raises(EnvironmentFailure):
        of.replace(new, out, before, exchange=exchange)
    assert (out / "late.txt").read_text() == "saved at the swap"
    assert (out / "manifest.json").read_text() == "old"


def test_the_swap_removes_the_old_output_and_keeps_only_the_new(tmp_path):
    out = _folder(tmp_path / "out", {"manifest.json": "old", "tables/a.csv": "1"})
    before = of.snapshot(out)
    new = _folder(tmp_path / ".out.tmp-aaaaaaaa", {"manifest.json": "new"})
    assert of.replace(new, out, before) is None
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert (out / "manifest.json").read_text() == "new" and not (out / "tables").exists()


def test_what_appears_in_the_old_output_while_it_is_removed_is_kept_beside_it(tmp_path):
    out = tmp_path / "out"
    old = _folder(tmp_path / ".out.old-aaaaaaaa", {"manifest.json": "old", "tables/a.csv": "1"})
    own = of.snapshot(old)
    (old / "tables" / "late.csv").write_text("mine")
    kept = of.discard(old, own, out)
    assert kept is not None and kept.name.startswith("out.kept-")
    assert (kept / "tables" / "late.csv").read_text() == "mine" and not (kept / "manifest.json").exists()


def test_a_build_does_not_delete_a_file_saved_into_out_while_it_runs(tmp_path, wheel):
    out = tmp_path / "out"
    out.mkdir()  # an empty folder: taken without --force
    p = _popen("build", str(wheel), "--out", str(out), "-q")
    t0 = time.monotonic()
    while p.poll() is None and time.monotonic() - t0 < 300:
        if any((t / "tables").exists() for t in tmp_path.glob(".out.tmp-*")):
            break
        time.sleep(0.02)
    (out / "thesis.docx").write_text("a week of work")
    _, err = p.communicate(timeout=300)
    assert p.returncode == 3, err
    assert "changed during the build" in _one_error_line(err)
    assert (out / "thesis.docx").read_text() == "a week of work"
    assert not list(tmp_path.glob(".out.*"))


# -- 2. a study owns its folder as a build does ----------------------------------------------------

WHEEL_PART = ROOT / "parts" / "road_wheel.toml"
ONE_VARIANT = f"""
[study]
part = "{WHEEL_PART}"
depth = "design"

[vary]
tyre_width_mm = [70.0]

[objectives]
minimize = ["T_at_V_max_C"]
"""


def test_a_study_takes_the_lock_of_its_folder(tmp_path, capsys):
    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    out = tmp_path / "out"
    lock = of.OutputLock(out)
    lock.acquire(wait=False)  # a build (or another study) of that folder
    try:
        assert main(["explore", str(study), "--out", str(out), "--no-wait", "-q"]) == 2
    finally:
        lock.release()
    line = _one_error_line(capsys.readouterr().err)
    assert f"is in use by process {os.getpid()}" in line, line
    assert not out.exists()


def test_a_study_waiting_for_a_build_vets_the_folder_the_build_left(tmp_path, capsys):
    """The build that held the folder wrote a part there: the study refuses it (exit 2) once it has the lock,
    before any cluster starts, and leaves the build's files alone."""
    import threading

    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    out = tmp_path / "out"
    lock = of.OutputLock(out)
    lock.acquire(wait=False)
    codes = []
    t = threading.Thread(target=lambda: codes.append(main(["explore", str(study), "--out", str(out), "-q"])))
    t.start()
    time.sleep(1.0)
    _folder(out, {"manifest.json": '{"part": "road_wheel", "files": [], "versions": {"propulsor": "0"}}'})
    lock.release()
    t.join(timeout=120)
    assert codes == [2]
    err = capsys.readouterr().err
    assert "is in use by process" in err and "not a study folder" in err and "Traceback" not in err
    assert sorted(p.name for p in out.iterdir()) == ["manifest.json"]


def test_build_best_never_deletes_files_it_did_not_write(tmp_path, capsys):
    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    out = tmp_path / "out"
    mine = _folder(out / "best" / "1", {"my_notes.txt": "keep me"})
    (out / "study.json").write_text("{}")  # a study folder of before
    code = main(["explore", str(study), "--out", str(out), "--workers", "1", "--build-best", "1", "-q"])
    line = _one_error_line(capsys.readouterr().err)
    assert code == 2 and "--build-best" in line and "best/1" in line, line
    assert (mine / "my_notes.txt").read_text() == "keep me"
    assert not (out / "results.csv").exists()  # refused before any work


# -- 4. a scheduler that never answers, or has no worker ------------------------------------------

BIN = Path(sys.executable).parent


def _listener(behaviour: str):
    """A TCP listener on 127.0.0.1 that accepts and then never answers ('silent') or sends garbage."""
    import socket
    import threading

    srv = socket.socket()
    srv.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    held = []

    def serve():
        while True:
            try:
                conn, _ = srv.accept()
            except OSError:
                return
            held.append(conn)
            if behaviour == "garbage":
                try:
                    conn.sendall(os.urandom(64) + b"\xff" * 64)
                except OSError:
                    pass

    threading.Thread(target=serve, daemon=True).start()
    return srv, f"tcp://127.0.0.1:{srv.getsockname()[1]}"


@pytest.mark.parametrize("behaviour", ["silent", "garbage"])
def test_a_listener_that_never_answers_like_a_scheduler_is_exit_2_within_seconds(tmp_path, behaviour):
    srv, address = _listener(behaviour)
    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    t0 = time.monotonic()
    try:
        r = _cli("explore", str(study), "--out", str(tmp_path / "out"), "--scheduler", address, "-q", timeout=60)
    finally:
        srv.close()
    assert time.monotonic() - t0 < 40
    assert r.returncode == 2, r.stderr
    line = _one_error_line(r.stderr)
    assert "--scheduler" in line and "no Dask scheduler answers" in line, line
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("address", ["tls://127.0.0.1:8786", "ws://127.0.0.1:8786", "ucx://127.0.0.1:8786", "--",
                                     "", "tcp://127.0.0.1:99999", "tcp://a b:1"])
def test_a_scheduler_address_other_than_tcp_is_one_line(tmp_path, address, capsys):
    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    t0 = time.monotonic()
    assert main(["explore", str(study), "--out", str(tmp_path / "out"), f"--scheduler={address}", "-q"]) == 2
    assert time.monotonic() - t0 < 5
    line = _one_error_line(capsys.readouterr().err)
    assert "--scheduler" in line, line


def test_a_scheduler_without_workers_is_exit_3_after_the_stated_wait(tmp_path):
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    log = open(tmp_path / "dask.log", "w")
    sched = subprocess.Popen([str(BIN / "dask"), "scheduler", "--host", "127.0.0.1", "--port", str(port),
                              "--no-dashboard"], stdout=log, stderr=subprocess.STDOUT, cwd=tmp_path)
    try:
        from propulsor.study.cluster import probe

        deadline = time.monotonic() + 60
        while True:
            try:
                probe(f"tcp://127.0.0.1:{port}", 2)
                break
            except Exception:
                assert time.monotonic() < deadline
                time.sleep(0.5)
        study = tmp_path / "s.toml"
        study.write_text(ONE_VARIANT)
        t0 = time.monotonic()
        r = _cli("explore", str(study), "--out", str(tmp_path / "out"), "--scheduler", f"tcp://127.0.0.1:{port}",
                 "--worker-wait", "2", "-q", timeout=90)
        assert time.monotonic() - t0 < 60
        assert r.returncode == 3, r.stderr
        line = _one_error_line(r.stderr)
        assert f"tcp://127.0.0.1:{port}" in line and "[ETIMEDOUT]" in line and "--worker-wait" in line, line
        assert not of.lock_path(tmp_path / "out").exists()
    finally:
        sched.terminate()
        sched.wait(timeout=10)
        log.close()


# -- 5. results.csv read back as a stream, bounded ---------------------------------------------------

def _study(tmp_path):
    from propulsor.study import load_study

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    return load_study(study)


def _header(study) -> str:
    from propulsor.study.results import columns

    return ",".join(columns(study)) + "\n"


def test_resume_reads_results_csv_as_a_stream(tmp_path):
    """20 MB of rows of other variants: read a line at a time, the memory is the rows kept, not the file."""
    import tracemalloc

    from propulsor.study.table import read_csv

    study = _study(tmp_path)
    cols = _header(study).strip().split(",")
    line = ",".join(["7", "stale"] + ["1.5"] * (len(cols) - 2)) + "\n"
    path = tmp_path / "results.csv"
    with open(path, "w") as f:
        f.write(_header(study))
        f.write(line * (20_000_000 // len(line)))
        f.write(line.replace("stale", "mine").replace("7,", "9,", 1))
    tracemalloc.start()
    try:
        rows = read_csv(path, cols, keys=["mine"])
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert [(r["variant"], r["key"]) for r in rows] == [(1, "mine")]  # numbered by the key's place
    assert peak < 4_000_000, peak


def test_resume_keeps_the_first_row_of_a_key_and_leaves_other_keys(tmp_path):
    """A key written twice (a row repeated by an interrupted resume): the first row is kept, the later one left; a row
    of a key the study does not have is left; the rows kept are numbered by the keys' places."""
    from propulsor.study.table import read_csv

    study = _study(tmp_path)
    cols = _header(study).strip().split(",")
    row = lambda v, key, x: ",".join([v, key] + [x] * (len(cols) - 2)) + "\n"  # noqa: E731
    path = tmp_path / "results.csv"
    path.write_text(_header(study) + row("3", "b", "2.5") + row("1", "stale", "9.5") + row("4", "a", "1.5")
                    + row("5", "b", "7.5"))
    rows = read_csv(path, cols, keys=["a", "b"])
    assert [(r["variant"], r["key"]) for r in rows] == [(2, "b"), (1, "a")]
    firsts = {r["key"]: float(r[cols[-1]]) for r in rows}
    assert firsts == {"b": 2.5, "a": 1.5}


def test_resume_refuses_a_results_csv_larger_than_the_limit_by_its_size(tmp_path, monkeypatch):
    from propulsor.study import table
    from propulsor.study.table import read_csv

    study = _study(tmp_path)
    path = tmp_path / "results.csv"
    path.write_text(_header(study))
    os.truncate(path, 3 << 30)  # 3 GB, sparse: never read
    with pytest.raises(of.InputError, match="more than the"):
        read_csv(path, _header(study).strip().split(","), keys=["k"])
    monkeypatch.setattr(table, "RESULTS_MAX_BYTES", 10)
    os.truncate(path, 100)
    with pytest.raises(of.InputError, match="--resume"):
        read_csv(path, _header(study).strip().split(","), keys=["k"])


@pytest.mark.parametrize("tamper", ["not utf-8", "huge field", "nul byte"])
def test_a_tampered_results_csv_is_one_line_exit_2(tmp_path, tamper, capsys):
    from propulsor.cli import main

    study_file = tmp_path / "s.toml"
    study_file.write_text(ONE_VARIANT)
    study = _study(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / "study.json").write_text("{}")
    body = {"not utf-8": b"1,k\xff\xfe,1\n", "huge field": b'1,"' + b"x" * 200_000 + b'",1\n',
            "nul byte": b"1,k\x00,\x00\n"}[tamper]
    (out / "results.csv").write_bytes(_header(study).encode() + body)
    code = main(["explore", str(study_file), "--out", str(out), "--resume", "--workers", "1", "-q"])
    err = capsys.readouterr().err
    if tamper == "nul byte":  # a row of no key of this study: left out, the study runs
        assert code == 0 and "Traceback" not in err, err
        return
    line = _one_error_line(err)
    assert code == 2 and "--resume" in line, line


def test_a_repeated_row_does_not_survive_resume(tmp_path):
    from propulsor.study.table import read_csv

    study = _study(tmp_path)
    cols = _header(study).strip().split(",")
    line = ",".join(["1", "k1"] + ["2.5"] * (len(cols) - 2)) + "\n"
    path = tmp_path / "results.csv"
    path.write_text(_header(study) + line + line + line.replace("2.5", "3.5"))
    rows = read_csv(path, cols, keys=["k1", "k2"])
    assert len(rows) == 1


def test_results_parquet_is_not_rewritten_for_every_row(tmp_path, monkeypatch):
    from propulsor.study import table

    study = _study(tmp_path)
    calls = []
    real = table.write_parquet
    monkeypatch.setattr(table, "write_parquet", lambda *a: calls.append(1) or real(*a))
    t = table.Table(tmp_path, study, False)
    for k in range(1, 501):
        t.add({"variant": k, "key": f"k{k}", "tyre_width_mm": 70.0, "T_at_V_max_C": 1.0 * k, "status": "ok"})
    assert len(calls) <= 2
    t.close()
    import pyarrow.parquet as pq

    assert pq.read_table(tmp_path / "results.parquet").num_rows == 500


# -- 6. a law table's work bounded, its hints within the limits --------------------------------------

TABLE_PART = (ROOT / "parts" / "ncg_table.toml").read_text()


def _law_table(path: Path, rows: int, noise: float) -> Path:
    """theta = 2 phi + 0.2 sin 2 phi over 180 deg of the driven wheel, `rows` rows, the inner rows moved by
    `noise` of a row's driver step (a table from a noisy measurement)."""
    import numpy as np

    ph = np.linspace(0.0, 180.0, rows)
    x = np.radians(ph)
    th = np.degrees(2 * x + 0.2 * np.sin(2 * x))
    th[1:-1] += np.random.default_rng(1).uniform(-noise, noise, rows - 2) * (360.0 / rows)
    th[-1] = 360.0
    path.write_text("driver_deg,driven_deg\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(th, ph)))
    return path


@pytest.mark.parametrize("rows, noise", [(100_000, 0.3), (20_000, 0.3)])
def test_a_noisy_law_table_within_the_row_limit_is_refused_in_seconds(tmp_path, rows, noise):
    _law_table(tmp_path / "law.csv", rows, noise)
    part = tmp_path / "p.toml"
    part.write_text(TABLE_PART.replace("ncg_table_law.csv", "law.csv"))
    t0 = time.monotonic()
    r = _cli("build", str(part), "--dry-run", timeout=90)
    assert time.monotonic() - t0 < 45
    assert r.returncode == 2, r.stderr
    line = _one_error_line(r.stderr)
    assert line.startswith("propulsor: error: law_file") and "None" not in line, line


def test_a_smooth_law_table_of_the_most_rows_is_screened_in_seconds(tmp_path):
    _law_table(tmp_path / "law.csv", 100_000, 0.0)
    part = tmp_path / "p.toml"
    part.write_text(TABLE_PART.replace("ncg_table_law.csv", "law.csv"))
    t0 = time.monotonic()
    r = _cli("build", str(part), "--dry-run", timeout=90)
    assert r.returncode == 0, r.stderr
    assert time.monotonic() - t0 < 45


def test_generability_hints_stay_within_the_parameters_limits():
    import math
    import re

    from propulsor.gears.generability import CurveCheck, CutterSpec, Generability, remedies

    cutter = CutterSpec(m=2.0, alpha=math.radians(20.0), x=0.5, x_H=-0.5, z0=20)
    limits = {"x": (-1.0, 1.5), "x_H": (-1.5, 1.0), "z_H": (4, 480), "m": (0.0, 50.0), "z0": (6, 200)}
    for rho in (-12.5, 0.0, 1e-6, 0.5):
        bad = CurveCheck(curve="driver", rho_convex_min=rho, rho_limit=8.5, concave=True, rho_concave_min=rho * 0.01,
                         r0=20.0, ok=False, reason="")
        ok = CurveCheck(curve="driven", rho_convex_min=50.0, rho_limit=8.5, concave=False, rho_concave_min=math.inf,
                        r0=20.0, ok=True, reason="")
        text = "; ".join(remedies(Generability(bad, ok), cutter, 60, 2, 120.0, limits))
        assert "None" not in text, text
        for name, value in re.findall(r"\b(x|x_H|z_H|z0) (?:>=|<=) (-?[0-9.]+)", text):
            lo, hi = limits[name]
            assert lo <= float(value) <= hi, text
        for value in re.findall(r"\bm <= (-?[0-9.e+-]+) mm", text):
            assert 0 < float(value) <= 50, text


# -- 3. the viewer never runs model data; check validates what it reads ------------------------------

def _bomb_glb(nodes: int = 9_999, vertices: int = 30_000) -> bytes:
    """A GLB within every size limit whose nodes all instance one mesh: nodes × vertices / 3 triangles drawn."""
    import json
    import struct

    blob = bytes(12 * vertices)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"children": list(range(1, nodes))}] + [{"mesh": 0} for _ in range(1, nodes)],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": vertices, "type": "VEC3",
                          "min": [0, 0, 0], "max": [0, 0, 0]}],
           "bufferViews": [{"buffer": 0, "byteLength": len(blob)}], "buffers": [{"byteLength": len(blob)}]}
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    total = 12 + 8 + len(js) + 8 + len(blob)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(js), b"JSON") + js
            + struct.pack("<I4s", len(blob), b"BIN\0") + blob)


@pytest.fixture(scope="module")
def built_wheel(tmp_path_factory):
    """A road wheel built once (as `propulsor build` writes it), in a gallery folder of its own."""
    folder = tmp_path_factory.mktemp("gallery")
    part = folder / "wheel.toml"
    part.write_text(SMALL_WHEEL)
    r = _cli("build", str(part), "--out", str(folder / "wheel"), "-q")
    assert r.returncode == 0, r.stderr
    return folder / "wheel"


def _rehash(folder: Path, rel: str) -> None:
    """The manifest made to list `rel` as it is now (an attacker who can write the folder can do this)."""
    import hashlib
    import json

    m = json.loads((folder / "manifest.json").read_text())
    data = (folder / rel).read_bytes()
    entry = {"path": rel, "format": "JS" if rel.endswith(".js") else "HTML", "bytes": len(data),
             "sha256": hashlib.sha256(data).hexdigest()}
    m["files"] = [f for f in m["files"] if f.get("path") != rel] + [entry]
    (folder / "manifest.json").write_text(json.dumps(m))


def test_no_page_loads_a_script_from_the_part_folder(built_wheel, tmp_path):
    import re
    import shutil

    from propulsor.export.gallery import render_gallery

    folder = tmp_path / "g"
    shutil.copytree(built_wheel, folder / "wheel")
    evil = "document.documentElement.dataset.pwned = '1';\n"
    (folder / "wheel" / "road_wheel_assembly.glb.js").write_text(evil)
    _rehash(folder / "wheel", "road_wheel_assembly.glb.js")
    for page in ((folder / "wheel" / "report.html").read_text(), render_gallery(folder)):
        csp = re.search(r'http-equiv="Content-Security-Policy" content="([^"]*)"', page).group(1)
        script_src = csp.split("script-src")[1].split(";")[0].split()
        assert script_src and all(s.startswith("'sha256-") for s in script_src), csp  # no 'self': no script file
        assert not re.search(r"<script[^>]*\bsrc=", page) and ".glb.js" not in page.split("<script>")[0]
        assert 'class="propulsor-glb"' in page  # the model is on the page, as data


def test_check_refuses_a_page_that_runs_a_script_propulsor_did_not_write(built_wheel, tmp_path):
    import shutil

    from propulsor.checks.files import check_file

    folder = tmp_path / "wheel"
    shutil.copytree(built_wheel, folder)
    assert all(c.passed for c in check_file(folder / "report.html"))
    page = (folder / "report.html").read_text()
    attacks = {
        "a script file": page.replace("</body>", '<script src="road_wheel_assembly.glb.js"></script></body>'),
        "a policy allowing script files": page.replace("script-src 'sha256-", "script-src 'self' 'sha256-", 1),
        "another inline script": page.replace("<script>\n", "<script>\nalert(1);\n", 1),
        "a script before the policy": page.replace('<meta charset="utf-8">', '<meta charset="utf-8"><script>x</script>'),
    }
    for what, text in attacks.items():
        (folder / "report.html").write_text(text)
        _rehash(folder, "report.html")
        checks = check_file(folder / "report.html")
        assert not all(c.passed for c in checks), what


def test_a_glb_drawing_too_many_triangles_is_invalid_alone_in_a_folder_and_on_a_page(built_wheel, tmp_path):
    import base64
    import re
    import shutil

    from propulsor.checks.files import check_path
    from propulsor.export.viewer_page import model_data

    bomb = _bomb_glb()
    (tmp_path / "bomb.glb").write_bytes(bomb)
    alone = check_path(tmp_path / "bomb.glb")[str(tmp_path / "bomb.glb")]
    assert not alone[0].passed and "triangles" in alone[0].message, alone
    assert model_data(tmp_path / "bomb.glb")[0] is None  # never put on a page
    folder = tmp_path / "wheel"
    shutil.copytree(built_wheel, folder)
    (folder / "road_wheel_assembly.glb").write_bytes(bomb)
    page = (folder / "report.html").read_text()
    page = re.sub(r'(class="propulsor-glb">)[^<]*', lambda m: m.group(1) + base64.b64encode(bomb).decode(), page)
    (folder / "report.html").write_text(page)
    for rel in ("road_wheel_assembly.glb", "report.html"):
        _rehash(folder, rel)
    results = check_path(folder)
    for rel in ("road_wheel_assembly.glb", "report.html"):
        assert not all(c.passed for c in results[str(folder / rel)]), rel


def test_the_viewer_refuses_what_check_refuses(tmp_path):
    """web/viewer.js's own model check (run in node): the bomb is refused by its triangles, a GLB with an
    external URI and a cycle of nodes too; a sound GLB passes."""
    import json
    import shutil
    import struct

    if not shutil.which("node"):
        pytest.skip("needs node to run web/viewer.js's model check")
    harness = tmp_path / "h.js"
    harness.write_text(
        "global.window = {}; global.document = {readyState: 'complete', querySelectorAll: () => []};\n"
        "global.IntersectionObserver = function () { this.observe = function () {}; };\n"
        f"require({json.dumps(str(ROOT / 'src/propulsor/export/web/viewer.js'))});\n"
        "const b = require('fs').readFileSync(process.argv[2]);\n"
        "console.log(window.PROPULSOR_VIEWER.glbProblem(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength)));\n")

    def glb(doc, blob=b""):
        js = json.dumps(doc).encode()
        js += b" " * (-len(js) % 4)
        return (struct.pack("<4sII", b"glTF", 2, 20 + len(js) + (8 + len(blob) if blob else 0))
                + struct.pack("<I4s", len(js), b"JSON") + js + (struct.pack("<I4s", len(blob), b"BIN\0") + blob
                                                                if blob else b""))

    cases = {"bomb": (_bomb_glb(), "triangles"),
             "uri": (glb({"asset": {"version": "2.0"}, "buffers": [{"uri": "x.bin", "byteLength": 4}]}), "external"),
             "cycle": (glb({"asset": {"version": "2.0"}, "nodes": [{"children": [1]}, {"children": [0]}]}), "cycle"),
             "sound": (glb({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{}]}), "")}
    for name, (data, want) in cases.items():
        (tmp_path / f"{name}.glb").write_bytes(data)
        out = subprocess.run(["node", str(harness), str(tmp_path / f"{name}.glb")], capture_output=True, text=True,
                             timeout=60)
        assert out.returncode == 0, out.stderr
        assert (want in out.stdout) if want else out.stdout.strip() == "", (name, out.stdout)


@pytest.mark.browser
def test_the_viewer_in_a_browser_refuses_a_model_that_draws_too_much_and_runs_no_file_beside_it(tmp_path):
    """A page whose model data block was swapped for the 9 999-node bomb, and a script beside it named as the
    old twin: the view says why it draws nothing (no freeze), and nothing beside the page runs."""
    import base64
    import re

    from cdp_browser import headless_page
    from test_viewer_page import tiny_glb

    from propulsor.export.html import write_report_html

    (tmp_path / "asm.glb").write_bytes(tiny_glb())
    (tmp_path / "report.md").write_text("# r\n\n## Inputs\n\nx\n", encoding="utf-8")
    page = write_report_html(tmp_path / "report.md", [{"path": "asm.glb", "title": "asm"}])
    text = re.sub(r'(class="propulsor-glb">)[^<]*', lambda m: m.group(1) + base64.b64encode(_bomb_glb()).decode(),
                  page.read_text())
    page.write_text(text.replace("</body>", '<script src="asm.glb.js"></script></body>'))
    (tmp_path / "asm.glb.js").write_text("document.documentElement.dataset.pwned = '1';\n")
    with headless_page() as b:
        b.open(page.as_uri(), 1000)
        state = b.evaluate("""(async () => { const f = document.querySelector('figure.viewer');
            f.scrollIntoView({block: 'center'});
            for (let i = 0; i < 400 && !['drawn', 'error'].includes(f.dataset.state); i++) await new Promise(r => setTimeout(r, 50));
            return {state: f.dataset.state, text: f.querySelector('.status').textContent,
                    pwned: document.documentElement.dataset.pwned || null}; })()""")
    assert state["state"] == "error" and "triangles" in state["text"] and state["pwned"] is None, state
