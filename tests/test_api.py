"""The Python API (propulsor.api): the same parts, validation and bytes as the command line; the examples
run; the public API type-checks; the commands that need no CAD kernel do not import it."""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import propulsor
from propulsor.errors import InputError
from propulsor.params import load_params, read_part_file
from propulsor.parts import params_class, part_type_names

ROOT = Path(__file__).resolve().parents[1]
PARTS = ROOT / "parts"
KERNEL = ("cadquery", "OCP", "manifold3d")


def _shas(folder: Path) -> dict[str, str]:
    return {q.relative_to(folder).as_posix(): hashlib.sha256(q.read_bytes()).hexdigest()
            for q in sorted(folder.rglob("*")) if q.is_file()}


def _cli(*args, cwd=ROOT, timeout=900):
    return subprocess.run([sys.executable, "-m", "propulsor.cli", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=timeout)


def _same_as_build(tmp_path, part_file: Path):
    """The acceptance's own command: `python -c "import propulsor; propulsor.part(F).write(OUT)"` against
    `propulsor build F --out OUT` (each a fresh interpreter, as a script or the command line is)."""
    api_out, cli_out = tmp_path / "api", tmp_path / "cli"
    r = subprocess.run([sys.executable, "-c", f"import propulsor; print(propulsor.part({str(part_file)!r})"
                        f".write({str(api_out)!r}))"], capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert r.returncode == 0 and r.stdout.strip() == str(api_out), r.stderr
    r = _cli("build", str(part_file), "--out", str(cli_out), "-q")
    assert r.returncode == 0, r.stderr
    a, b = _shas(api_out), _shas(cli_out)
    assert a.keys() == b.keys() and len(a) > 10
    assert [k for k in a if a[k] != b[k]] == []


@pytest.mark.parametrize("name", ["road_wheel", "cam_linear"])
def test_part_write_gives_the_bytes_of_propulsor_build(tmp_path, name):
    _same_as_build(tmp_path, PARTS / f"{name}.toml")


@pytest.mark.sweep
@pytest.mark.parametrize("name", ["balancer", "ncg_seed002", "final_drive", "polysector"])
def test_part_write_gives_the_bytes_of_propulsor_build_every_part_type(tmp_path, name):
    _same_as_build(tmp_path, PARTS / f"{name}.toml")


def test_a_part_in_memory_solids_profiles_checks_assembly():
    wheel = propulsor.part("road_wheel", lightening_holes=0)
    assert wheel.type == "road_wheel" and wheel.source is None and wheel.params.lightening_holes == 0
    assert set(wheel.solids) >= {"disc", "rim_1", "tyre_1"}
    v = wheel.solids["disc"].Volume()
    assert v > 1e5
    outlines = wheel.profiles
    assert outlines and all(pl.shape[1] == 2 and len(pl) > 3 for pls in outlines.values() for pl in pls)
    checks = wheel.prove(raise_on_failure=True)
    assert checks and all(c.passed for c in checks)
    asm = wheel.assembly()
    assert [c.name for c in asm.children][:3] == ["disc", "rim_1", "tyre_1"]
    with pytest.raises(InputError, match="assembly = 'nope'"):
        wheel.assembly("nope")


def test_a_written_part_is_not_built_again(tmp_path, monkeypatch):
    """After .write, .build / .solids / .prove() are the build that was written (a study at depth build
    writes each variant and reads its values: one build, not two); the values are the manifest's."""
    import propulsor.building as building

    calls = []
    real = building.produce_build
    monkeypatch.setattr(building, "produce_build", lambda *a, **k: calls.append(1) or real(*a, **k))
    import matplotlib.pyplot as plt

    open_before = set(plt.get_fignums())
    wheel = propulsor.part("road_wheel", lightening_holes=0)
    wheel.write(tmp_path / "w")
    assert calls == [1]
    # the build drew its plots in this process and closed each (a study's worker builds thousands)
    assert set(plt.get_fignums()) == open_before and (tmp_path / "w" / "plots").is_dir()
    checks = wheel.prove(raise_on_failure=True)
    assert set(wheel.solids) >= {"disc", "rim_1", "tyre_1"} and calls == [1]
    manifest = json.loads((tmp_path / "w" / "manifest.json").read_text())
    assert len(checks) == len(manifest["checks"]) > 0
    assert wheel.build.derived["mass_wheel_kg"] == manifest["derived"]["mass_wheel_kg"]


@pytest.mark.parametrize("make", [
    lambda: propulsor.part("noncircular_pair", module_mm=-3),
    lambda: propulsor.parameters("noncircular_pair", module_mm=-3),
    lambda: propulsor.part(PARTS / "ncg_seed002.toml", module_mm=-3),
    lambda: params_class("noncircular_pair")(module_mm=-3),
    lambda: dataclasses.replace(params_class("noncircular_pair")(), module_mm=-3),
    lambda: load_params(params_class("noncircular_pair"), {"module_mm": -3}),
], ids=["part(type)", "parameters()", "part(file, override)", "dataclass", "replace", "load_params"])
def test_bad_values_are_refused_however_the_parameters_are_made(make):
    with pytest.raises(InputError) as exc:
        make()
    assert exc.value.parameter == "module_mm" and ">= 0.0 mm" in str(exc.value)


def test_parameters_are_frozen_and_unknown_keys_refused():
    p = propulsor.parameters("road_wheel")
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.tyre_radius_mm = 1.0  # type: ignore[misc]
    with pytest.raises(InputError, match="unknown parameter"):
        propulsor.part("road_wheel", tyre_radius=300)
    with pytest.raises(InputError, match="must be a part type"):
        propulsor.part("no_such_type")


@pytest.mark.parametrize("part_file", sorted(PARTS.glob("*.toml")), ids=lambda p: p.stem)
def test_keys_equal_to_the_defaults_can_be_deleted(part_file):
    """One source of defaults: a part file without its keys that equal the defaults gives the same
    parameters (so the same build)."""
    t, mapping = read_part_file(part_file)
    cls = params_class(t)
    defaults = {f.name: (f.default if f.default is not dataclasses.MISSING else f.default_factory())
                for f in dataclasses.fields(cls)}
    lean = {k: v for k, v in mapping.items() if defaults.get(k) != v}
    assert load_params(cls, lean, validate=False) == load_params(cls, mapping, validate=False)


def test_noncircular_defaults_are_the_seed_002_part_file():
    """The defaults are seed 002's part file but for its bores: the file writes 16 / 40 mm, the defaults leave them
    out (sized from the gear, parts/noncircular_pair/bores.py)."""
    _, mapping = read_part_file(PARTS / "ncg_seed002.toml")
    cls = params_class("noncircular_pair")
    assert (mapping["driver_bore_mm"], mapping["driven_bore_mm"]) == (16.0, 40.0)
    assert cls().driver_bore_mm is None and cls().driven_bore_mm is None
    assert cls(driver_bore_mm=16.0, driven_bore_mm=40.0) == load_params(cls, mapping, validate=False)


def test_the_examples_run(tmp_path):
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "sweep_module.py")], capture_output=True, text=True,
                       timeout=300, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "188.643" in r.stdout  # a_w of the thesis drive at m = 10 mm
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "show_in_viewer.py")], capture_output=True,
                       text=True, timeout=300, cwd=tmp_path)
    assert r.returncode == 0 and ("ocp_vscode" in r.stdout or not r.stdout), r.stderr
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "custom_flange.py"), str(tmp_path / "fl")],
                       capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "all valid" in r.stdout
    r = _cli("check", str(tmp_path / "fl" / "driver_with_flange.step"))
    assert r.returncode == 0 and "1 file(s) checked, 0 invalid" in r.stdout


def test_the_public_api_and_the_examples_type_check():
    r = subprocess.run([sys.executable, "-m", "mypy", "src/propulsor/api.py", "src/propulsor/__init__.py",
                        "examples/"], capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("args", [["--help"], ["list"], ["params", "noncircular_pair"], ["params", "balancer"]])
def test_commands_that_need_no_kernel_do_not_import_it(args):
    # said at exit (the program's own end, cli.leave, runs the exit functions and leaves)
    code = ("import atexit, sys, runpy; sys.argv = ['propulsor'] + %r\n"
            "atexit.register(lambda: print('KERNEL', sorted(m for m in sys.modules if m.split('.')[0] in %r)))\n"
            "runpy.run_module('propulsor.cli', run_name='__main__')" % (args, KERNEL))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert "KERNEL []" in r.stdout, r.stdout[-400:] + r.stderr[-400:]


def test_import_propulsor_loads_no_kernel_and_the_api_has_docstrings():
    r = subprocess.run([sys.executable, "-c", "import sys, propulsor; print(sorted(m for m in sys.modules if "
                        "m.split('.')[0] in ('cadquery', 'OCP', 'manifold3d', 'scipy', 'trimesh')))"],
                       capture_output=True, text=True, timeout=60)
    assert r.stdout.strip() == "[]", r.stdout + r.stderr
    from propulsor import api

    for name in api.__all__:
        obj = getattr(api, name)
        assert (obj.__doc__ or "").strip(), name
    for name, member in vars(api.Part).items():
        if not name.startswith("_"):
            doc = getattr(member, "__doc__", None) or getattr(getattr(member, "fget", None), "__doc__", None)
            assert (doc or "").strip(), name
    assert json.loads(json.dumps(part_type_names()))


def test_the_api_reference_builds_without_a_warning(tmp_path):
    """What `make docs` runs (pdoc, warnings as errors)."""
    r = subprocess.run([sys.executable, "-W", "error", "-m", "pdoc", "propulsor.api", "propulsor.errors",
                        "propulsor.check", "-o", str(tmp_path)], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    page = (tmp_path / "propulsor" / "api.html").read_text()
    assert "def part" in page or "part(" in page


def test_values_are_a_read_only_mapping_with_units_and_meanings():
    """Part.values / Build.values: a mapping and attributes, the glossary's unit and meaning, a table."""
    from propulsor.api import Values

    derived = {"center_distance_mm": 101.25, "law": "elliptical", "sigma_MPa": {"stop": 12.5}}
    glossary = {"center_distance_mm": ("mm", "installed centre distance <L>"), "law": ("", "the law"),
                "sigma_MPa": ("MPa", "stress"), "sigma_MPa.stop": ("MPa", "stress: stop")}
    v = Values(derived, glossary, "proof")
    assert v.center_distance_mm == v["center_distance_mm"] == 101.25 and v.depth == "proof"
    assert dict(v) == derived and len(v) == 3 and "law" in v and "center_distance_mm" in dir(v)
    assert v.unit("center_distance_mm") == "mm" and v.meaning("sigma_MPa.stop") == "stress: stop"
    assert v.unit("law") == ""
    with pytest.raises(AttributeError, match="no derived value 'nope' at depth proof"):
        v.nope
    with pytest.raises(KeyError):
        v.unit("nope")
    with pytest.raises(AttributeError):
        v.center_distance_mm = 1.0
    with pytest.raises(TypeError):
        v["law"] = "x"  # type: ignore[index]
    derived["center_distance_mm"] = 0.0  # the mapping is its own copy
    assert v.center_distance_mm == 101.25
    lines = repr(v).splitlines()
    assert lines[0] == "<propulsor.Values: 3 derived values, depth proof>"
    assert lines[1].split() == ["center_distance_mm", "101.25", "mm"]
    page = v._repr_html_()
    assert "installed centre distance &lt;L&gt;" in page and "<L>" not in page


def test_kept_files_stand_for_a_build_only_while_what_it_read_is_unchanged(tmp_path):
    """A write after a build copies its files only when the part file (and every file it names) is as
    the build read it, and the kept folder is removed with its owner."""
    import gc

    from propulsor.building import KeptFiles, _digests

    part_file = tmp_path / "p.toml"
    part_file.write_text('type = "road_wheel"\n')
    folder = tmp_path / "kept"
    (folder / "tables").mkdir(parents=True)
    (folder / "manifest.json").write_text("{}")
    (folder / "tables" / "t.csv").write_text("a\n1\n")
    kept = KeptFiles(folder, _digests([part_file]))
    assert kept.current()
    into = tmp_path / "into"
    into.mkdir()
    kept.copy_into(into)
    assert _shas(into) == _shas(folder)
    part_file.write_text('type = "road_wheel"\n# a comment\n')  # the same parameters, other bytes
    assert not kept.current()
    part_file.write_text('type = "road_wheel"\n')
    assert kept.current()
    pid = os.fork()
    if pid == 0:  # a forked process (a worker, a Dask task) that lets go of its copy leaves the folder
        try:
            kept.drop()
        finally:
            os._exit(0)
    assert os.waitpid(pid, 0)[1] == 0 and kept.current()
    part_file.unlink()
    assert not kept.current()
    del kept
    gc.collect()
    assert not folder.exists()


def test_a_part_built_then_written_is_built_once_the_bytes_of_propulsor_build_and_shown_in_a_notebook(tmp_path):
    """.solids then .write(): one build (its files copied), the bytes of `propulsor build`; the values of
    the build are the manifest's with its units; _repr_html_ draws the build's GLB in the viewer, every text
    escaped.  In a fresh interpreter, as a script or a notebook's kernel is."""
    import base64
    from html.parser import HTMLParser

    part_file = tmp_path / 'wheel <&"> 1.toml'
    part_file.write_text((PARTS / "road_wheel.toml").read_text())
    api_out, cli_out = tmp_path / "api", tmp_path / "cli"
    script = f"""
import json, propulsor, propulsor.building as b
calls = []
real = b.produce_build
b.produce_build = lambda *a, **k: calls.append(1) or real(*a, **k)
wheel = propulsor.part({str(part_file)!r})
assert set(wheel.solids) >= {{"disc", "rim_1"}} and calls == [1]
html = wheel._repr_html_()
wheel.write({str(api_out)!r})
assert calls == [1], calls
values = wheel.build.values
print(json.dumps({{"calls": len(calls), "html": html, "values": dict(values),
                  "units": {{k: values.unit(k) for k in values}}, "depth": wheel.values.depth,
                  "proof": dict(wheel.values)}}))
"""
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert r.returncode == 0, r.stderr[-3000:]
    got = json.loads(r.stdout.splitlines()[-1])
    r = _cli("build", str(part_file), "--out", str(cli_out), "-q")
    assert r.returncode == 0, r.stderr
    a, b = _shas(api_out), _shas(cli_out)
    assert a.keys() == b.keys() and len(a) > 10
    assert [k for k in a if a[k] != b[k]] == []
    manifest = json.loads((cli_out / "manifest.json").read_text())
    assert got["values"] == manifest["derived"]
    assert got["units"] == {k: manifest["glossary"][k]["unit"] for k in manifest["derived"]}
    assert all(got["proof"][k] == manifest["derived"][k] for k in got["proof"])

    class Page(HTMLParser):
        def __init__(self):
            super().__init__()
            self.srcdoc, self.blocks, self.text, self._block = [], [], [], False

        def handle_starttag(self, tag, attrs):
            a = dict(attrs)
            if tag == "iframe":
                self.srcdoc.append(a["srcdoc"])
            self._block = tag == "script" and a.get("class") == "propulsor-glb"

        def handle_data(self, data):
            (self.blocks if self._block else self.text).append(data)

        def handle_endtag(self, tag):
            self._block = False

    outer = Page()
    outer.feed(got["html"])
    outer.close()
    assert 'wheel <&"> 1.toml' in "".join(outer.text) and 'wheel <&"> 1.toml' not in got["html"]
    assert 'wheel &lt;&amp;&quot;&gt; 1.toml' in got["html"]
    assert len(outer.srcdoc) == 1
    inner = Page()
    inner.feed(outer.srcdoc[0])
    inner.close()
    glbs = [base64.b64decode("".join(inner.blocks))]
    assert glbs[0][:4] == b"glTF"
    assert "mass_wheel_kg" in got["html"]
    # no link to a file beside the view: a notebook has none (the trial's dead link to the GLB)
    assert ".glb" in outer.srcdoc[0] and 'href="' not in outer.srcdoc[0].split("<figcaption>", 1)[1]


def test_a_pairs_solids_come_from_its_solid_steps_without_a_build_or_a_file(tmp_path, monkeypatch):
    """A non-circular pair declares its solid steps: .solids, .assembly(), .profiles run the design and those
    steps only (seconds; no build, nothing in the temporary folder), and the solids are the design's
    outlines extruded by the face width."""
    import tempfile

    import numpy as np

    import propulsor.building as building

    calls = []
    real = building.produce_build
    monkeypatch.setattr(building, "produce_build", lambda *a, **k: calls.append(1) or real(*a, **k))
    (tmp_path / "tmp").mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path / "tmp"))
    gear = propulsor.part(PARTS / "ncg_elliptical.toml")
    solids = gear.solids
    assert sorted(solids) == ["driven", "driver"] and [c.name for c in gear.assembly().children] == ["driven", "driver"]
    assert sorted(gear.profiles) == ["driven", "driver"]
    assert calls == [] and "build" not in gear.__dict__ and list((tmp_path / "tmp").iterdir()) == []

    def area(pl):
        return 0.5 * abs(np.dot(pl[:, 0], np.roll(pl[:, 1], -1)) - np.dot(pl[:, 1], np.roll(pl[:, 0], -1)))

    for role, profile in zip(("driver", "driven"), gear.design.profiles):
        outer, *holes = profile.polylines()
        expected = (area(outer) - sum(area(h) for h in holes)) * gear.params.face_width_mm
        assert solids[role].Volume() == pytest.approx(expected, rel=1e-4)
        assert gear.shapes.derived[f"{role}_volume_mm3"] == solids[role].Volume()


def test_a_part_tells_its_progress_to_a_callback_it_is_given(monkeypatch):
    """The trial's `_repr_html_` ran a build 32 s without a word: ``part.progress = print`` (any callable) is told the
    steps of the work the part starts — its proofs, build, solids and design."""
    import propulsor.building as building

    gear = propulsor.part("parts/ncg_elliptical.toml")
    assert gear.progress is None
    seen = []
    gear.progress = seen.append
    for name in ("prove", "build_in_memory", "solids"):
        monkeypatch.setattr(building, name, lambda loaded, progress=None, keep_files=False, name=name:
                            seen.append((name, progress)) or (_ for _ in ()).throw(RuntimeError("stop")))
    for attr in ("proof_run", "build", "shapes"):
        with pytest.raises(RuntimeError):
            getattr(gear, attr)
    assert [(n, p) for n, p in (x for x in seen if isinstance(x, tuple))] == [
        ("prove", seen.append), ("build_in_memory", seen.append), ("solids", seen.append)]
    said = []
    propulsor.part("parts/ncg_elliptical.toml", face_width_mm=11.0)  # a design not yet computed
    other = propulsor.part("parts/ncg_elliptical.toml", face_width_mm=11.0)
    other.progress = said.append
    other.design
    assert any("teeth" in str(e) for e in said), said
