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
