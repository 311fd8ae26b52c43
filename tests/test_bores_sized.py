"""The pair's bores where the part file gives none: sized from the gear (parts/noncircular_pair/bores.py); a bore the
part file gives is kept, or refused naming key, value and limit."""

from __future__ import annotations

import numpy as np
import pytest

import propulsor
from propulsor import policy
from propulsor.cli import main
from propulsor.errors import InputError
from propulsor.geometry.gear_outline import keyway_for_shaft

#: a user's small pair: module 1, 20 / 40 teeth, a 2-lobe Fourier law; no bore written
SMALL = """type = "noncircular_pair"
law = "fourier"
driver_turns = 2
fourier_sin = [0.04]
module_mm = 1.0
driven_teeth = 40
face_width_mm = 6.0
compare_methods = false
"""


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    f = tmp_path_factory.mktemp("small") / "small.toml"
    f.write_text(SMALL)
    return f


def _hole_radii(profile):
    """(least, largest) distance from the gear's axis of its one hole (the bore and its keyway)."""
    assert len(profile.holes) == 1
    r = np.hypot(*profile.holes[0].polyline(0.01).T)
    return float(r.min()), float(r.max())


def test_a_small_gear_without_bores_builds_with_bores_sized_from_it(small, capsys):
    assert main(["build", str(small), "--dry-run", "-q"]) == 0  # the 40 mm bore of old never written: no refusal
    capsys.readouterr()
    gear = propulsor.part(small)
    assert gear.params.driver_bore_mm is None and gear.params.driven_bore_mm is None  # the inputs: not given
    dd = gear.design
    m = dd.d.m
    for which, gear_d, bore, prof in zip(("driver", "driven"), (dd.d.driver, dd.d.driven), dd.bores, dd.profiles):
        r_f = gear_d.root_min_radius
        d = bore.d_mm
        assert bore.sized and bore.keyway and d == getattr(dd.p, f"{which}_bore_mm")
        # a standard shaft the body carries (d <= r_f: the gear at least 2 d across about it), the largest one
        assert d in policy.BORE_STANDARD_D_MM and d <= r_f
        bigger = [s for s in policy.BORE_STANDARD_D_MM if s > d]
        assert bigger[0] > r_f or bigger[0] / 2 + keyway_for_shaft(bigger[0])[1] >= r_f - m
        # the solid's hole as built: the bore's radius, the keyway's bottom t2 beyond it, a rim of >= one module
        r_lo, r_hi = _hole_radii(prof)
        t2 = keyway_for_shaft(d)[1]
        assert r_lo == pytest.approx(d / 2, abs=1e-6)
        assert np.hypot(keyway_for_shaft(d)[0] / 2, d / 2 + t2) == pytest.approx(r_hi, abs=1e-6)
        assert r_f - (d / 2 + t2) >= policy.BORE_RIM_MIN_MODULES * m
        assert f"{d:g} mm" in bore.why and f"r_f = {r_f:.2f} mm" in bore.why
    # module 1, z 20 / 40: an 8 mm driver bore (r_f 8.7 mm), a 16 mm driven one (r_f 17.7 mm)
    assert (dd.p.driver_bore_mm, dd.p.driven_bore_mm) == (8.0, 16.0)
    from propulsor.parts.noncircular_pair.bores import sized_derived, sized_note

    assert sized_derived(dd.bores) == {"driver_bore_mm": 8.0, "driven_bore_mm": 16.0}
    note = sized_note(dd.bores)
    assert note.startswith("Bores sized from the gear") and "DIN 6885-1" in note


def test_a_bore_written_is_kept_and_one_too_large_is_refused_naming_key_value_limit(small):
    dd = propulsor.part(small, driven_bore_mm=12.0).design
    assert dd.p.driven_bore_mm == 12.0 and not dd.bores[1].sized and dd.bores[0].sized
    assert _hole_radii(dd.profiles[1])[0] == pytest.approx(6.0, abs=1e-6)
    r_f, m = dd.d.driven.root_min_radius, dd.d.m
    # a bore over the pitch curve's bound: refused before any tooth is cut (the dry run refuses what the build does)
    from propulsor.parts.noncircular_pair.bores import root_bound
    from propulsor.parts.noncircular_pair.feasibility import screened

    scr = screened(dd.p, small)
    bound = root_bound(scr.smooth.pc, "driven", m)
    assert r_f < bound < r_f + 2.0 * m  # an upper bound of the cut root, and a close one
    with pytest.raises(InputError) as exc:
        propulsor.part(small, driven_bore_mm=40.0)
    e = exc.value
    assert (e.parameter, e.value) == ("driven_bore_mm", 40.0)
    assert "one module inside the root, which lies inside the pitch curve" in e.limit
    assert f"{bound - m:.3f} mm" in e.limit and "leave driven_bore_mm out" in e.hint
    big = small.parent / "big_bore.toml"
    big.write_text(SMALL + "driven_bore_mm = 40.0\n")
    assert main(["build", str(big), "--dry-run", "-q"]) == 2
    assert main(["build", str(small), "--dry-run", "-q"]) == 0
    # a bore between the bound and the cut root: passes the dry run, refused by the design on the cut root
    t2 = keyway_for_shaft(28.0)[1]
    assert r_f - m <= 14.0 + t2 < bound - m
    gear = propulsor.part(small, driven_bore_mm=28.0)
    with pytest.raises(InputError) as exc:
        gear.design
    e = exc.value
    assert (e.parameter, e.value) == ("driven_bore_mm", 28.0)
    assert "one module inside the root" in e.limit and f"{r_f - m:.3f} mm" in e.limit
    assert "leave driven_bore_mm out" in e.hint


def test_a_gear_too_small_for_a_keyed_bore_gets_none_or_a_plain_one_with_keyway_off(small):
    keyed = propulsor.part(small, module_mm=0.5).design  # driver r_f 4.35 mm: no 7 mm keyed bore fits
    assert keyed.bores[0].d_mm == 0.0 and not keyed.profiles[0].holes and "keyway = false" in keyed.bores[0].why
    assert keyed.bores[1].d_mm == 8.0 and keyed.bores[1].keyway
    plain = propulsor.part(small, module_mm=0.5, keyway=False).design
    r_f = plain.d.driver.root_min_radius
    d = plain.bores[0].d_mm
    assert d == max(s for s in policy.BORE_STANDARD_D_MM if s <= r_f) == 4.0 and not plain.bores[0].keyway
    assert _hole_radii(plain.profiles[0]) == pytest.approx((2.0, 2.0), abs=1e-6)  # a plain circle


def test_params_lists_the_bores_as_not_given(capsys):
    assert main(["params", "noncircular_pair"]) == 0
    rows = [ln for ln in capsys.readouterr().out.splitlines() if ln.startswith(("driver_bore_mm", "driven_bore_mm"))]
    assert len(rows) == 2 and all("(not given)" in r and "sized from the gear" in r for r in rows)


@pytest.mark.parametrize("keyway", [True, False])
def test_the_sized_bore_is_the_largest_standard_shaft_with_its_hub_and_rim(keyway):
    """Over roots of 3 ... 120 mm and modules of 0.5 ... 6 mm: the sized bore keeps the body 2 d across about it and,
    with its keyway, a rim of one module below the root; the next standard shaft would break one of them (root 10 mm,
    m = 4: a 9 mm keyed bore, as a 10 mm one's keyway bottom, 5 + 1.4 = 6.4 mm, passes r_f - m = 6 mm)."""
    from propulsor.parts.noncircular_pair.bores import size_bore

    def fits(d, r_f, m):
        keyed = keyway and 6.0 < d <= 230.0
        if keyway and not keyed:
            return False
        t2 = keyway_for_shaft(d)[1] if keyed else 0.0
        return d <= 2 * r_f / policy.BORE_HUB_RATIO and d / 2 + t2 < r_f - policy.BORE_RIM_MIN_MODULES * m

    for r_f in np.linspace(3.0, 120.0, 60):
        for m in (0.5, 1.0, 2.0, 4.0, 6.0):
            b = size_bore(float(r_f), m, keyway)
            ok = [s for s in policy.BORE_STANDARD_D_MM if fits(s, r_f, m)]
            assert b.d_mm == (ok[-1] if ok else 0.0), (r_f, m)
            assert b.keyway == (keyway and b.d_mm > 0)
    assert size_bore(10.0, 4.0, True).d_mm == 9.0  # the keyway binds: a 10 mm bore's reaches 6.4 mm > 10 - 4


def test_the_report_says_the_bores_sized_and_names_its_two_least_backlashes(small, tmp_path):
    """One build of the small pair: the bores as built are derived values with the rule in a note; the least backlash
    of the motion proof's phases (the check) and the one over every contact position (backlash_min_mm) are named as
    the two things they are, each number where its name is."""
    import json
    import re

    out = tmp_path / "out"
    assert main(["build", str(small), "--out", str(out), "-q"]) == 0
    m = json.loads((out / "manifest.json").read_text())
    d = m["derived"]
    assert (d["driver_bore_mm"], d["driven_bore_mm"]) == (8.0, 16.0)
    assert m["inputs"]["driver_bore_mm"] is None  # the input: not given
    notes = (out / "report.md").read_text()
    assert "Bores sized from the gear (the part file gives no driver_bore_mm and no driven_bore_mm" in notes
    assert "| driver_bore_mm |  | mm | not given: sized from the gear, the largest standard shaft" in notes
    check = next(c for c in m["checks"] if c["name"] == "mesh.backlash_min")
    steps = 40 * 4  # driven_teeth × proof_phases_per_tooth
    assert f"at the proof's {steps} phases" in check["message"] and "backlash_min_mm" in check["message"]
    said = re.search(r"least backlash ([0-9.]+) mm \(backlash_min_mm, over every contact position; the motion "
                     r"proof's (\d+) phases alone give ([0-9.]+) mm\)", notes)
    assert said is not None
    assert float(said.group(1)) == pytest.approx(d["backlash_min_mm"], abs=5e-6)
    assert float(said.group(3)) == pytest.approx(check["value"], abs=5e-6) and int(said.group(2)) == steps


def test_a_kit_of_the_small_pair_takes_its_pins_from_the_sized_bores_on_an_80_mm_bed(small, tmp_path):
    """The print kit of the pair without bores: its full-size design sizes them (8 / 16 mm), the pins follow (the
    driven wheel's the largest printed pin, 12 mm, below its 16 mm bore); every plate, the coupon's first, on the
    80 x 80 mm bed inside its margins."""
    import json

    out = tmp_path / "kit"
    assert main(["print", str(small), "--bed", "80x80x80", "--slice", "no", "--out", str(out), "-q"]) == 0
    m = json.loads((out / "manifest.json").read_text())
    d = m["derived"]
    assert d["scale_S"] == 1.0 and d["pin_driven_d_mm"] == 12.0 and d["pin_driver_d_mm"] <= 8.0
    assert [c["name"] for c in m["checks"] if not c["passed"]] == []
    plates = {c["name"] for c in m["checks"] if c["name"].endswith(".on_bed")}
    assert "plate_1.on_bed" in plates and len(plates) >= 2
    assert "coupon, coupon_pin, coupon_key" in (out / "print_guide.md").read_text()


def _with_driven_bore(name: str, bore: float, tmp_path):
    from pathlib import Path

    src = Path(__file__).resolve().parents[1] / "parts" / f"{name}.toml"
    text = "\n".join(f"driven_bore_mm = {bore}" if ln.startswith("driven_bore_mm") else ln
                     for ln in src.read_text().splitlines())
    f = tmp_path / f"{name}_bore_{bore:g}.toml"
    f.write_text(text + "\n")
    return f


def test_the_dry_run_refuses_a_bore_the_law_search_cannot_carry(tmp_path):
    """The seed-002 pair by the law search (generated teeth): a driven bore over the root of every blend it ranked is
    refused by the dry run (before: valid, then refused after the teeth were cut); one under all of them passes."""
    from propulsor.parts.noncircular_pair.bores import root_bound
    from propulsor.parts.noncircular_pair.feasibility import _candidate_curves, screened

    f = _with_driven_bore("ncg_seed002", 170.0, tmp_path)
    with pytest.raises(InputError) as exc:
        propulsor.part(f)
    e = exc.value
    assert (e.parameter, e.value) == ("driven_bore_mm", 170.0) and "lies inside the pitch curve" in e.limit
    ok = propulsor.part(_with_driven_bore("ncg_seed002", 40.0, tmp_path))
    scr = screened(ok.params, None)
    curves = _candidate_curves(ok.params, scr)
    bounds = [root_bound(c, "driven", scr.m) for c in curves]
    assert len(curves) > 1 and f"{max(bounds) - scr.m:.3f} mm" in e.limit  # the most any candidate allows
    assert "may fit is 160 mm (the cut root decides)" in e.hint
    assert main(["build", str(f), "--dry-run", "-q"]) == 2


def test_the_dry_run_checks_a_sector_pairs_bore_on_its_cut_root(tmp_path):
    """The sector method's outlines are quick: the dry run checks a given bore on them as the build does, and
    names the largest standard bore that fits (before: valid, then refused by the build)."""
    f = _with_driven_bore("ncg_seed002_table", 170.0, tmp_path)
    assert main(["build", str(f), "--dry-run", "-q"]) == 2
    with pytest.raises(InputError) as exc:
        propulsor.part(f)
    e = exc.value
    assert (e.parameter, e.value) == ("driven_bore_mm", 170.0)
    gear = propulsor.part(_with_driven_bore("ncg_seed002_table", 40.0, tmp_path))
    r_f, m = gear.design.d.driven.root_min_radius, gear.design.d.m
    assert f">= {r_f - m:.3f} mm" in e.limit and "the largest standard bore that fits is 150 mm" in e.hint
    t2 = keyway_for_shaft(150.0)[1]
    assert 75.0 + t2 < r_f - m  # 150 fits: keyed, a module of rim under the root
    nxt = min(d for d in policy.BORE_STANDARD_D_MM if d > 150.0)
    assert nxt / 2 + keyway_for_shaft(nxt)[1] >= r_f - m  # the next standard size does not
