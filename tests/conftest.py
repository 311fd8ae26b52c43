"""Fixtures shared by the test modules.

A part test module names its part file in ``PART``; ``out`` builds it once per module through the
command line (exit code 0 expected) and ``manifest`` reads the build's manifest.json.
"""

from __future__ import annotations

import json
import os

import pytest

from propulsor.cli import main

# mutation testing (mutation/run.py) forks a worker per mutant from a process that has already run the tests, and
# OCCT's thread pool does not survive a fork (export/mesh.py): a forked worker that meshes or runs a boolean in
# parallel waits forever.  There, OCCT's default pool gets one thread (the calling one: the same results).
if os.environ.get("PROPULSOR_OCCT_SERIAL") == "1":
    from OCP.OSD import OSD_ThreadPool

    OSD_ThreadPool.DefaultPool_s(1)


@pytest.fixture(scope="module")
def out(request, tmp_path_factory):
    """The module's ``PART`` built into a fresh folder named after it (one build per test module)."""
    part = request.module.PART
    folder = tmp_path_factory.mktemp(part.stem) / part.stem
    assert main(["build", str(part), "--out", str(folder), "-q"]) == 0
    return folder


@pytest.fixture(scope="module")
def manifest(out):
    """The manifest.json of the module's build."""
    return json.loads((out / "manifest.json").read_text())


@pytest.fixture
def slices_cleanly(tmp_path):
    """assert_slices(kit_folder, fullest_only): every plate (or the fullest) of a kit slices in PrusaSlicer
    with the generic printer's settings on the kit's own bed (its manifest's bed_mm), every object manifold and
    on the bed, every extrusion of the G-code on the bed."""
    def assert_slices(folder, fullest_only: bool = False) -> None:
        from propulsor.printing.printers import load_printer
        from propulsor.printing.slicer import slice_kit

        bed = json.loads((folder / "manifest.json").read_text())["derived"]["bed_mm"]
        printer = load_printer("generic", dict(zip(("bed_x_mm", "bed_y_mm", "bed_z_mm"), bed)))
        results = slice_kit(folder, printer, tmp_path, fullest_only)
        assert results
        for plate, r, off in results:
            assert r.ok, (plate, r.message)
            assert r.all_manifold and off == [], (plate, r.objects)

    return assert_slices


@pytest.fixture(scope="session")
def assert_animations():
    """assert_animations(folder, manifest, proof_tables): every GIF the manifest lists under
    ``media.animations`` exists with the listed bytes (<= 2 MB), decodes with Pillow with the listed
    frame count, size and frame duration; no frame is blank (more than one colour) and consecutive
    frames differ (it moves); its frame table ``tables/anim_<name>.csv`` has a row per frame, and the
    pose of each frame is the proof's pose at the listed proof step: ``proof_tables`` maps a GIF's
    name to (proof table name, {frame-table column: proof-table column}).  Returns the entries."""
    import csv

    import numpy as np
    from PIL import Image

    def table(folder, name):
        with open(folder / "tables" / f"{name}.csv", newline="") as fh:
            rows = list(csv.DictReader(fh))
        return rows

    def check(folder, manifest, proof_tables=None):
        entries = manifest.get("media", {}).get("animations", [])
        assert entries, "the build lists no animation"
        listed = {f["path"]: f for f in manifest["files"]}
        for e in entries:
            path = folder / e["path"]
            name = path.stem
            assert e["path"] == f"anim/{name}.gif" and path.is_file(), e["path"]
            assert path.stat().st_size == e["bytes"] == listed[e["path"]]["bytes"] and e["bytes"] <= 2_000_000
            assert e["title"] and e["poses"] and (e["least_clearance_mm"] is None or e["least_clearance_mm"] > 0)
            with Image.open(path) as im:
                assert im.format == "GIF" and im.size == (e["width_px"], e["height_px"])
                assert 480 <= e["width_px"] <= 640
                assert im.n_frames == e["frames"] >= 2
                prev = None
                for k in range(im.n_frames):
                    im.seek(k)
                    assert im.info.get("duration") == e["frame_ms"]
                    rgb = im.convert("RGB")
                    colours = rgb.getcolors(maxcolors=1 << 16)
                    assert colours is None or len(colours) > 1, f"{name}: frame {k} is blank"
                    data = rgb.tobytes()
                    assert data != prev, f"{name}: frame {k} repeats frame {k - 1}"
                    prev = data
            frames = table(folder, f"anim_{name}")
            assert [int(r["frame"]) for r in frames] == list(range(e["frames"]))
            if proof_tables and name in proof_tables:
                pname, cols = proof_tables[name]
                proof = table(folder, pname)
                for r in frames:
                    row = proof[int(r["proof_step"])]
                    for mine, theirs in cols.items():
                        assert np.isclose(float(r[mine]), float(row[theirs]), rtol=1e-12, atol=1e-12), \
                            (name, r["frame"], mine, r[mine], row[theirs])
        return entries

    return check


def _derived_paths(derived: dict):
    """(path, keys) of every derived value: ``name``, ``name.key`` in a dict, ``name[].key`` in the dicts
    of a list (keys: the names on the way, outermost first)."""
    def walk(path, keys, v):
        yield path, keys
        if isinstance(v, dict):
            for k, x in v.items():
                yield from walk(f"{path}.{k}", keys + [k], x)
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for k in dict.fromkeys(k for x in v for k in x):
                yield from walk(f"{path}[].{k}", keys + [k], next(x[k] for x in v if k in x))

    for name, value in derived.items():
        yield from walk(name, [name], value)


@pytest.fixture(scope="session")
def assert_explained():
    """assert_explained(folder): every derived value of the build's manifest has a glossary entry with a
    meaning and a unit that agrees with its name's suffix (a name without one: no unit a suffix could
    name); the report's derived table shows each top-level value's unit and meaning."""
    from propulsor.export.units import SUFFIX_UNITS, unit_of_path

    def check(folder) -> None:
        m = json.loads((folder / "manifest.json").read_text())
        glossary = m["glossary"]
        report = (folder / "report.md").read_text()
        for path, keys in _derived_paths(m["derived"]):
            assert path in glossary, path
            unit, meaning = glossary[path]["unit"], glossary[path]["meaning"]
            assert meaning.strip(), path
            named = unit_of_path(keys)
            assert unit == named if named else unit not in SUFFIX_UNITS.values(), (path, unit, named)
            if len(keys) == 1:
                from propulsor.export.report import md_text

                row = [r for r in report.splitlines() if r.startswith(f"| {path} | ")]
                assert row and f"| {unit} |" in row[-1] and md_text(meaning.split(" seed ")[0])[:20] in row[-1], path
        assert any(c["name"] == "report: every derived value explained" and c["passed"] for c in m["checks"])

    return check


@pytest.fixture(autouse=True)
def _figures_closed():
    """The figures a test left open closed after it: the tests' stand-in writers keep the figures handed to them
    (the build's writer saves and closes each, tests/test_api.py), and a worker running many such tests would pile
    them up (pyplot warns past 20).  pyplot is not imported for a test that never did."""
    import sys

    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")


@pytest.fixture(autouse=True)
def _fresh_law_searches():
    """Each test makes its own law searches: gears/law_search.py keeps a process's last searches by their inputs, and
    a test that patches what a search reads must not be handed another test's result."""
    from propulsor.gears import law_search

    law_search._SEARCHES.clear()
    yield
