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


def test_a_kernel_compiled_into_another_is_compiled_again_when_its_own_file_changes(tmp_path):
    """Two modules in a fresh package: b's cached kernel calls a's.  After a's file changes (its kernel now returns 2),
    a new process must see 2 through b.  numba alone keys b's disk cache on b's file and loads b's old code, which
    still returns 1 (the package without :func:`nbcache.bind`: shown here, so the test sees the hazard it guards);
    with both modules bound to both files, b is compiled again."""
    import os
    import subprocess
    import sys

    def write(pkg, bound):
        d = tmp_path / pkg
        d.mkdir()
        (d / "__init__.py").write_text("")
        tail = "\nfrom propulsor.nbcache import bind\nbind(globals(), FILES)\n" if bound else ""
        files = f"FILES = [{str(d / 'a.py')!r}, {str(d / 'b.py')!r}]\n"
        (d / "a.py").write_text("from numba import njit\n" + files + "@njit(cache=True)\ndef f(x):\n    return x + 1\n"
                                + tail)
        (d / "b.py").write_text(f"from numba import njit\nfrom {pkg}.a import f\n" + files
                                + "@njit(cache=True)\ndef g(x):\n    return f(x) * 1\n" + tail)
        return d

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(SRC)]))

    def run(pkg):
        out = subprocess.run([sys.executable, "-c", f"from {pkg}.b import g; print(g(0))"], env=env,
                             capture_output=True, text=True, check=True)
        return int(out.stdout.split()[-1])

    for pkg, bound in (("plain", False), ("bound", True)):
        d = write(pkg, bound)
        assert run(pkg) == 1 and run(pkg) == 1  # compiled, then loaded from the disk cache
        a = d / "a.py"
        a.write_text(a.read_text().replace("return x + 1", "return x + 2 "))  # another size: another stamp
        st = a.stat()
        os.utime(a, (st.st_atime, st.st_mtime + 10))
        assert run(pkg) == (2 if bound else 1), pkg


def test_the_kernel_sources_are_the_listed_modules_files():
    from propulsor import nbcache

    want = sorted([str(SRC / (m.replace(".", "/") + ".py")) for m in kernels.MODULES] + list(nbcache.INTRINSICS))
    assert sorted(nbcache.SOURCES) == want
    assert all(Path(f).is_file() for f in nbcache.SOURCES)
