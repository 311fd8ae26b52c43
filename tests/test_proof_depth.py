"""The `proof` depth of a part (and of a design study): the design and the part type's declared proof steps
only — no solid, no file — with the build's own derived values and checks, to the last digit."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SEED002 = ROOT / "parts" / "ncg_seed002.toml"
FINAL_DRIVE = ROOT / "parts" / "final_drive.toml"


def as_json(v):
    """A value as the manifest holds it (jsonable, then through JSON text)."""
    from propulsor.export.manifest import jsonable

    return json.loads(json.dumps(jsonable(v)))


def no_solid(monkeypatch):
    """Any solid made from here on fails the test (the extrusion every part type's solids start from)."""
    import propulsor.solids.build as sb

    def refuse(*a, **k):
        raise AssertionError("the proof depth made a solid")

    monkeypatch.setattr(sb, "extrude_profile", refuse)


def no_figure(monkeypatch):
    """Any figure drawn from here on fails the test: a proof keeps values only, and its writer drops figures
    (``ProofWriter.draws_plots``), so the steps draw none (every plot of a step starts from ``new_figure``)."""
    import propulsor.export.plots as plots

    def refuse(*a, **k):
        raise AssertionError("the proof depth drew a figure")

    monkeypatch.setattr(plots, "new_figure", refuse)


def same_as_build(manifest: dict, derived: dict, checks, solids_only: set[str]) -> None:
    """Every derived value equals the manifest's (to the last digit); only the solids' own values are
    missing; every check is one of the build's with the same result (name, passed, value, limit, message)."""
    built = manifest["derived"]
    assert set(built) - set(derived) == solids_only, sorted(set(built) - set(derived))
    assert not set(derived) - set(built), sorted(set(derived) - set(built))
    for name, value in derived.items():
        assert as_json(value) == built[name], (name, value, built[name])
    by_name = {c["name"]: c for c in manifest["checks"]}
    assert len(checks) > 0
    for c in checks:
        assert as_json(c) == by_name[c.name], c.name


# ---- the pipeline's declaration and the writer that writes nothing ---------------------------------

def test_a_pipeline_runs_its_proof_steps_only_in_the_build_order():
    from propulsor.parts.pipeline import Pipeline

    ran = []

    def step(name):
        def f(d, w, built):
            ran.append((name, d))
        f.__name__ = name
        return f

    a, b, c = step("a"), step("b"), step("c")
    pl = Pipeline(lambda p, w: "D", (a, b, c), proof_steps=(c, a))
    pl.prove(None, None)
    assert ran == [("a", "D"), ("c", "D")] and pl.proves_alone
    ran.clear()
    pl(None, None)
    assert [n for n, _ in ran] == ["a", "b", "c"]
    with pytest.raises(ValueError, match="'x' is not a step of the build"):
        Pipeline(lambda p, w: "D", (a, b), proof_steps=(step("x"),))
    assert not Pipeline(lambda p, w: "D", (a,)).proves_alone


def test_the_proof_writer_keeps_values_and_refuses_files():
    import matplotlib.pyplot as plt

    from propulsor.export.plots import new_figure
    from propulsor.parts.proof_writer import ProofWriter
    from propulsor.params import load_params
    from propulsor.parts import get_part_type

    params = load_params(get_part_type("road_wheel").params_cls, {})
    w = ProofWriter("road_wheel", params)
    w.derived["x_mm"] = 1.5
    w.add_table("t", ["a"], [[1]])
    w.add_table("d", {"a": [1, 2]}, None)  # write_csv's other form: a dict of columns
    fig, _ = new_figure()
    w.add_plot("p", fig)
    assert not plt.fignum_exists(fig.number)  # dropped, not kept open
    assert w.table_rows["t"] == (["a"], [[1]]) and w.folder is None
    for call in (lambda: w.path("plots/x.png"), lambda: w.add_solid("s", None), lambda: w.add_assembly("a", [])):
        with pytest.raises(RuntimeError, match="proof steps make values and checks only"):
            call()
    assert w.finish() == []


def test_a_part_type_without_proof_steps_proves_by_its_whole_build(monkeypatch):
    import propulsor

    wheel = propulsor.part(ROOT / "parts" / "road_wheel.toml")
    seen = []
    monkeypatch.setattr(propulsor.Part, "build", property(lambda self: seen.append(1) or propulsor.Build(
        ("x: y",), ("c",), {"v": 1}, {}, {}, {})))
    run = wheel.proof_run
    assert (run.whole_build, run.failures, run.checks, run.derived, seen) == (True, ("x: y",), ("c",), {"v": 1}, [1])
    with pytest.raises(propulsor.InputError, match="depth = 'everything': must be build or proof"):
        wheel.prove(depth="everything")


# ---- the seed-002 pair with one changed value: the proof depth against its full build --------------

@pytest.fixture(scope="module")
def seed002_built(tmp_path_factory):
    """The seed-002 pair with backlash 0.15 mm, built fully (`propulsor build`'s files): its manifest."""
    from propulsor.cli import main

    tmp = tmp_path_factory.mktemp("ncg")
    part = tmp / "ncg.toml"
    part.write_text(SEED002.read_text().replace("backlash_mm = 0.16 ", "backlash_mm = 0.15 "), encoding="utf-8")
    assert "backlash_mm = 0.15 " in part.read_text()
    assert main(["build", str(part), "--out", str(tmp / "built"), "--keep-failed", "-q"]) in (0, 1)
    return part, json.loads((tmp / "built" / "manifest.json").read_text())


def test_the_pairs_proof_depth_gives_the_builds_values_and_checks_without_a_solid(seed002_built, monkeypatch):
    from propulsor.params import read_part_file
    from propulsor.study.evaluate import evaluate

    part, manifest = seed002_built
    no_solid(monkeypatch)
    no_figure(monkeypatch)
    type_name, base = read_part_file(SEED002)
    wanted = tuple(manifest["derived"])
    row = evaluate(type_name, base, str(SEED002), {"backlash_mm": 0.15}, "proof", wanted)
    # the study's row: every value but the solids' volumes, each the manifest's to the last digit
    assert row["status"] == "error" and row["reason"] == ("driven_volume_mm3: not computed at depth proof for "
                                                          "this variant (a deeper depth may compute it)"), row
    assert set(wanted) - set(row["values"]) == {"driven_volume_mm3", "driver_volume_mm3"}
    for name, value in row["values"].items():
        assert as_json(value) == manifest["derived"][name], name
    assert row["all_checks_passed"] is True and manifest["passed"]
    # the same from the Python interface, with the checks: a subset of the build's, the same results
    import propulsor

    gear = propulsor.part(part)
    run = gear.proof_run
    assert not run.whole_build and run.failures == ()
    same_as_build(manifest, run.derived, run.checks, {"driven_volume_mm3", "driver_volume_mm3"})
    names = {c.name for c in run.checks}
    assert {"mesh.runs_without_jam", "mesh.backlash_min", "mesh.overlap_area", "law.closure_error"} <= names
    assert not any(n.startswith(("brep", "step", "mesh_")) or "volume" in n for n in names), names
    assert [c.name for c in gear.prove(depth="proof")] == [c.name for c in run.checks]


# ---- the final drive: strength, sweeps and sizes at proof depth; its volumes at build depth ----------

def test_the_final_drives_proof_depth_gives_the_builds_values_and_checks_without_a_solid(tmp_path, monkeypatch):
    import propulsor
    from propulsor.cli import main

    part = tmp_path / "fd.toml"
    part.write_text(FINAL_DRIVE.read_text(), encoding="utf-8")
    assert main(["build", str(part), "--out", str(tmp_path / "built"), "--keep-failed", "-q"]) in (0, 1)
    manifest = json.loads((tmp_path / "built" / "manifest.json").read_text())
    no_solid(monkeypatch)
    no_figure(monkeypatch)
    run = propulsor.part(part).proof_run
    volumes = {n for n in manifest["derived"] if n.endswith("_volume_mm3")}
    assert volumes == {f"{s}_volume_mm3" for s in ("sun", "planet", "ring", "carrier")}
    same_as_build(manifest, run.derived, run.checks, volumes)
    assert {"strength_sun_planet_S_H_pitting_sun", "carrier_cheek_radius_mm", "ring_outer_d_mm"} <= set(run.derived)


def test_a_loaded_pairs_proof_depth_draws_no_figure(monkeypatch):
    """The Fourier seed-002 pair with its load case: the as-built contact and the load per tooth at proof depth, their
    values made (the speed as built, the teeth's stresses) and not one of their figures drawn."""
    import tomllib

    from propulsor.study.evaluate import evaluate

    f = ROOT / "parts" / "ncg_fourier_seed002.toml"
    base = tomllib.loads(f.read_text())
    ptype = base.pop("type")
    base.pop("meta", None)
    no_figure(monkeypatch)
    row = evaluate(ptype, base, str(f), {}, "proof",
                   ("speed_as_built_min", "tooth_load_driver_sigma_F_max_MPa", "tooth_load_S_F_min"))
    assert row["status"] == "ok", row
    v = row["values"]
    assert 0.0 < v["speed_as_built_min"] < 1.0 and v["tooth_load_driver_sigma_F_max_MPa"] > 0.0
    assert v["tooth_load_S_F_min"] > 0.0
