"""The checks' compiled kernels (checks/kernels.py): compiled before a build's work when they are not (a fresh
install: the trial's 12-19 s silences inside the build), said so, and ahead at `make install`."""

from __future__ import annotations

import re
from pathlib import Path

from propulsor.checks import kernels

SRC = Path(__file__).resolve().parents[1] / "src"


def test_every_module_with_cached_kernels_is_listed():
    cached = sorted("propulsor." + f.relative_to(SRC / "propulsor").with_suffix("").as_posix().replace("/", ".")
                    for f in (SRC / "propulsor").rglob("*.py") if re.search(r"njit\([^)]*cache\s*=\s*True", f.read_text()))
    assert cached == sorted(kernels.MODULES)


def test_warm_leaves_no_kernel_cold_and_a_missing_index_is_cold(monkeypatch):
    kernels.warm()
    assert not kernels.cold()
    ds = kernels._dispatchers()
    # each one compiled (or loaded) by warm, or compiled inside a kernel that calls it and cached on disk
    assert len(ds) >= 15 and all(d.signatures or d._cache._cache_file._load_index() for d in ds)
    # a kernel whose code on disk is missing or stale (numba's index empty) and not compiled in this process
    d = ds[-1]
    monkeypatch.setattr(type(d), "signatures", property(lambda self: [] if self is d else self.overloads.keys()))
    monkeypatch.setattr(d._cache._cache_file, "_load_index", lambda: {})
    assert kernels.cold()


def test_a_build_with_cold_kernels_compiles_them_first_and_says_so(monkeypatch):
    from propulsor.parts.pipeline import Pipeline

    said, order = [], []
    monkeypatch.setattr(kernels, "cold", lambda: True)
    monkeypatch.setattr(kernels, "warm", lambda: order.append("warm"))

    class W:
        progress = staticmethod(said.append)

    Pipeline(lambda p, w: order.append("design") or "d", (lambda d, w, built: order.append("step"),))(object(), W())
    assert order == ["warm", "design", "step"]
    assert said == ["compiling the numeric kernels for this machine (once after an install or an update: about 30 s)"]
    monkeypatch.setattr(kernels, "cold", lambda: False)
    order.clear()
    Pipeline(lambda p, w: order.append("design") or "d", ())(object(), W())
    assert order == ["design"]
