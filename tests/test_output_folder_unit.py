"""output_folder's rules one by one, where a one-line change went unnoticed: a parent of the home
folder, a manifest without `part`, an empty folder, a part file deep in --out, the debris of an
interrupted replacement, the mode of a built folder."""

from __future__ import annotations

import json
import os
import stat

import pytest

from propulsor import output_folder as of
from propulsor.errors import InputError

MANIFEST = {"part": "road_wheel", "files": [{"path": "a.csv"}], "versions": {"propulsor": "0.1.0"}}


def test_a_parent_of_the_home_folder_is_never_replaced(tmp_path, monkeypatch):
    home = tmp_path / "home" / "me"
    home.mkdir(parents=True)
    monkeypatch.setenv("HOME", str(home))
    with pytest.raises(InputError, match="is a parent of the home folder"):
        of.vet_target(tmp_path / "home", force=True)
    with pytest.raises(InputError, match="is the home folder"):
        of.vet_target(home, force=True)


def test_a_manifest_without_part_is_not_a_propulsor_manifest(tmp_path):
    (tmp_path / "manifest.json").write_text(json.dumps(MANIFEST))
    assert of.read_manifest(tmp_path) == MANIFEST
    for key in ("part", "files", "versions"):
        (tmp_path / "manifest.json").write_text(json.dumps({k: v for k, v in MANIFEST.items() if k != key}))
        assert of.read_manifest(tmp_path) is None, key


def test_an_existing_empty_folder_is_taken_without_force(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    assert of.vet_target(out) == out
    (out / "x.txt").write_text("x")
    with pytest.raises(InputError, match="not written by propulsor"):
        of.vet_target(out)


def test_a_part_file_anywhere_below_out_is_refused(tmp_path):
    out = tmp_path / "out"
    (out / "sub").mkdir(parents=True)
    part = out / "sub" / "p.toml"
    part.write_text("")
    with pytest.raises(InputError, match="holds p.toml, which this build reads"):
        of.vet_target(out, force=True, keep=(part,))


def test_debris_of_an_interrupted_replacement_is_put_back_or_removed(tmp_path):
    out = tmp_path / "out"
    old = tmp_path / ".out.old-abcd1234"
    old.mkdir()
    (old / "manifest.json").write_text("old")
    assert of.clean_stale(out) == [] and (out / "manifest.json").read_text() == "old"  # back in place
    old.mkdir()
    tmp = tmp_path / ".out.tmp-abcd1234"
    tmp.mkdir()
    keep = tmp_path / ".out.tmp-not_ours!"  # not a name a build makes
    keep.mkdir()
    assert sorted(of.clean_stale(out)) == sorted([old, tmp])
    assert not old.exists() and not tmp.exists() and keep.exists() and out.exists()


def test_a_built_folder_gets_the_mode_a_new_folder_gets(tmp_path):
    saved = os.umask(0o027)
    try:
        tmp = of.make_temp(tmp_path / "out")
    finally:
        os.umask(saved)
    assert stat.S_IMODE(tmp.stat().st_mode) == 0o750
    assert tmp.name.startswith(".out.tmp-")
