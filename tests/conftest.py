"""Fixtures shared by the test modules.

A part test module names its part file in ``PART``; ``out`` builds it once per module through the
command line (exit code 0 expected) and ``manifest`` reads the build's manifest.json.
"""

from __future__ import annotations

import json

import pytest

from propulsor.cli import main


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
    with the generic printer's bed, every object manifold and on the bed."""
    def assert_slices(folder, fullest_only: bool = False) -> None:
        from propulsor.printing.printers import load_printer
        from propulsor.printing.slicer import slice_kit

        results = slice_kit(folder, load_printer("generic"), tmp_path, fullest_only)
        assert results
        for plate, r, off in results:
            assert r.ok, (plate, r.message)
            assert r.all_manifold and off == [], (plate, r.objects)

    return assert_slices
