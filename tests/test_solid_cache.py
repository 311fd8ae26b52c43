"""A batch's identical solids written and checked once (parts/solid_cache.py): the second build's files and checks
of a solid it shares with the first are the bytes and values the first made, which are the ones the solid gives
on its own; a solid that differs in anything the files or checks depend on (its B-rep to the bit, its name, its
expected genus, a mesh made in threads) is made afresh; an entry is whole or absent; a build alone keeps none."""

from __future__ import annotations

import os
from pathlib import Path

import cadquery as cq
import numpy as np
import pytest

from propulsor.parts import solid_cache, solid_files
from propulsor.solids.kernel import volume


def _hub(shift: float = 0.0):
    """A user's part: a turned hub (revolved section) with a flange bolted on (union) and its edges filleted; made
    anew at each call, as another build makes its own copy of the same solid."""
    prof = cq.Workplane("XZ").polyline([(5, 0), (18, 0), (18, 6), (10, 6), (10, 16), (5, 16)]).close()
    hub = prof.revolve(360, (0, 0, 0), (0, 1, 0))
    lug = cq.Workplane().box(8, 8, 4, centered=(True, True, False)).translate((18, 0, 0))
    return hub.union(lug).edges("|Z").fillet(0.5).translate((shift, 0, 0)).val()


def _files(folder: Path, name: str) -> dict:
    rels = (f"{name}.step", f"{name}.stl", f"{name}.3mf", f"views/{name}.png")
    return {rel: (folder / rel).read_bytes() for rel in rels}


def _as_values(checks) -> list:
    return [(c.name, c.passed, repr(c.value), c.message) for c in checks]


def _made(folder: Path, solid, name: str = "hub", genus=1, key=True, forked=True):
    (folder / "views").mkdir(parents=True, exist_ok=True)
    v = volume(solid)
    k = solid_cache.solid_key(solid, name, genus, v) if key else None
    return solid_files.solid_files_and_checks(str(folder), name, solid, genus, v, forked, k)


@pytest.fixture
def counted(monkeypatch):
    """Counts the halves computed (the STEP's, the mesh's)."""
    made = {"step": 0, "mesh": 0}
    step, mesh = solid_files._step_and_checks, solid_files._mesh_and_checks

    def step_counted(*a):
        made["step"] += 1
        return step(*a)

    def mesh_counted(*a):
        made["mesh"] += 1
        return mesh(*a)

    monkeypatch.setattr(solid_files, "_step_and_checks", step_counted)
    monkeypatch.setattr(solid_files, "_mesh_and_checks", mesh_counted)
    return made


def test_a_solid_two_builds_share_is_written_and_checked_once_the_same_bytes(tmp_path, counted):
    alone = _made(tmp_path / "alone", _hub(), key=False)  # no batch: computed, nothing kept
    assert solid_cache.solid_key(_hub(), "hub", 1, 1.0) is None and counted == {"step": 1, "mesh": 1}
    with solid_cache.batch_scope() as root:
        first = _made(tmp_path / "first", _hub())
        assert counted == {"step": 2, "mesh": 2} and len(os.listdir(root)) == 2  # its two halves kept
        hits = solid_cache.hits[0]
        second = _made(tmp_path / "second", _hub())  # another build's copy of the same solid
        assert counted == {"step": 2, "mesh": 2} and solid_cache.hits[0] == hits + 2  # both halves taken
    assert not Path(root).exists()  # the batch's entries go with it
    want = _files(tmp_path / "alone", "hub")
    assert _files(tmp_path / "first", "hub") == want and _files(tmp_path / "second", "hub") == want
    for got in (first, second):
        assert _as_values(got[0]) == _as_values(alone[0])
        assert all(np.array_equal(a, b) for a, b in zip(got[1], alone[1]))
    assert all(c.passed for c in second[0]) and any("STEP round trip" in c.name for c in second[0])


@pytest.mark.parametrize("other", ["moved 1e-6 mm", "another name", "another genus", "meshed in threads"])
def test_a_solid_that_differs_in_what_its_files_depend_on_is_made_afresh(tmp_path, counted, monkeypatch, other):
    with solid_cache.batch_scope():
        _made(tmp_path / "first", _hub())
        assert counted == {"step": 1, "mesh": 1}
        if other == "moved 1e-6 mm":
            _made(tmp_path / "second", _hub(1e-6))
            want = {"step": 2, "mesh": 2}
        elif other == "another name":
            _made(tmp_path / "second", _hub(), name="boss")
            assert (tmp_path / "second" / "boss.step").read_bytes() != (tmp_path / "first" / "hub.step").read_bytes()
            want = {"step": 2, "mesh": 2}
        elif other == "another genus":
            got = _made(tmp_path / "second", _hub(), genus=0)
            assert not all(c.passed for c in got[0])  # the genus check says it: not the first's answer
            want = {"step": 2, "mesh": 2}
        else:  # the same B-rep meshed in threads (a build in its own process): the mesh half apart, the STEP shared
            monkeypatch.setattr(solid_files, "threads_ok", lambda: True)
            _made(tmp_path / "second", _hub(), forked=False)
            want = {"step": 1, "mesh": 2}
        assert counted == want


def test_an_entry_is_whole_or_absent(tmp_path, monkeypatch):
    with solid_cache.batch_scope() as root:
        key = solid_cache.solid_key(_hub(), "hub", 0, 1.0)
        (tmp_path / "a.step").write_bytes(b"x")
        solid_cache.store(key, "step", tmp_path, ("a.step", "missing.stl"), ["checks"])  # a file it cannot copy
        assert os.listdir(root) == [] and solid_cache.fetch(key, "step", tmp_path / "b", ("a.step",)) is None
        secret = tmp_path / "secret"
        secret.write_bytes(b"not a build's file")
        (tmp_path / "link.step").symlink_to(secret)
        solid_cache.store(key, "step", tmp_path, ("link.step",), ["checks"])  # a link is not kept
        assert os.listdir(root) == []
        solid_cache.store(key, "step", tmp_path, ("a.step",), ["checks"])
        solid_cache.store(key, "step", tmp_path, ("a.step",), ["other"])  # a second build's: the first kept
        assert len(os.listdir(root)) == 1
        assert solid_cache.fetch(key, "step", tmp_path / "b", ("a.step",)) == ["checks"]
        assert (tmp_path / "b" / "a.step").read_bytes() == b"x"
        with solid_cache.batch_scope() as inner:  # nested: the same folder
            assert inner == root
        assert Path(root).exists()
    assert solid_cache._ROOT is None and not Path(root).exists()


def _report_scope(args, part_file, depfile, gallery=True) -> int:
    with open(os.environ["SCOPE_LOG"], "a") as f:
        f.write(f"{part_file.stem} {solid_cache._ROOT} {Path(solid_cache._ROOT).is_dir()}\n")
    return 0


def test_the_builds_of_a_batch_share_one_folder_removed_after(tmp_path, monkeypatch):
    import propulsor.cli as cli
    from propulsor.cli import main

    log = tmp_path / "log"
    monkeypatch.setenv("SCOPE_LOG", str(log))
    monkeypatch.setattr(cli, "build_one", _report_scope)
    monkeypatch.chdir(tmp_path)
    root = Path(__file__).resolve().parents[1] / "parts"
    assert main(["build", str(root / "cam_linear.toml"), str(root / "cam_quadratic.toml")]) == 0
    rows = [line.split() for line in log.read_text().splitlines()]
    assert len(rows) == 2 and rows[0][1] == rows[1][1] and all(r[2] == "True" for r in rows)
    assert not Path(rows[0][1]).exists() and solid_cache._ROOT is None


def test_no_temporary_folder_or_no_room_means_each_build_makes_its_own(tmp_path, monkeypatch, counted):
    import tempfile

    def refused(*a, **k):
        raise PermissionError(13, "Permission denied")

    with monkeypatch.context() as m:
        m.setattr(tempfile, "mkdtemp", refused)
        with solid_cache.batch_scope() as root:
            assert root is None and solid_cache.solid_key(_hub(), "hub", 1, 1.0) is None
            _made(tmp_path / "a", _hub())
    with solid_cache.batch_scope():
        _made(tmp_path / "b", _hub())
        import shutil

        def full(*a, **k):
            raise OSError(28, "No space left on device")

        m2 = monkeypatch.context()
        with m2 as m:
            m.setattr(shutil, "copyfile", full)
            got = _made(tmp_path / "c", _hub())  # the entries there but not copied: made afresh
    assert counted == {"step": 3, "mesh": 3} and all(c.passed for c in got[0])
    assert _files(tmp_path / "c", "hub") == _files(tmp_path / "a", "hub")


def test_a_half_is_kept_by_a_link_or_across_file_systems_by_a_copy(tmp_path, monkeypatch):
    (tmp_path / "a.step").write_bytes(b"solid")
    for linked in (True, False):
        with solid_cache.batch_scope() as root:
            key = solid_cache.solid_key(_hub(), "hub", 1, 1.0)
            if not linked:
                def other_device(*a, **k):
                    raise OSError(18, "Invalid cross-device link")

                monkeypatch.setattr(os, "link", other_device)
            solid_cache.store(key, "step", tmp_path, ("a.step",), ["checks"])
            kept = Path(root) / f"{key[1]}-step" / "a.step"
            assert kept.read_bytes() == b"solid" and os.path.samefile(kept, tmp_path / "a.step") == linked
            assert solid_cache.fetch(key, "step", tmp_path / "b", ("a.step",)) == ["checks"]
            assert not os.path.samefile(tmp_path / "b" / "a.step", tmp_path / "a.step")  # a taker gets a copy
