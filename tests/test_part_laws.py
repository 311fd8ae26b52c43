"""The part-file key ``law`` of the non-circular pair: laws a part file can name, keys of other laws
refused (exit 2 naming them), the design of a law without a hub."""

from __future__ import annotations

import math

import pytest

from propulsor.cli import main
from propulsor.errors import InputError
from propulsor.params import load_params
from propulsor.parts.noncircular_pair import NoncircularPairParams
from propulsor.parts.noncircular_pair.design import _law

ELLIPTICAL = dict(law="elliptical", eccentricity=0.3, driver_turns=1, module_mm=2.5, driven_teeth=30,
                  driver_shift=0.0, driver_bore_mm=16.0, driven_bore_mm=16.0, compare_methods=False)


def _params(**kw):
    return load_params(NoncircularPairParams, kw)


def test_walking_is_the_default_law():
    p = _params()
    assert p.law == "walking" and _law(p).kind == "walking"


@pytest.mark.parametrize("extra, key", [
    (dict(a_mm=80.0), "a_mm"),
    (dict(smoothing_deg=5.0), "smoothing_deg"),
    (dict(fourier_sin=[0.01]), "fourier_sin"),
    (dict(law_file="x.csv"), "law_file"),
])
def test_keys_of_another_law_are_refused_naming_them(extra, key):
    with pytest.raises(InputError, match=rf"^{key} = .*: is a key of law = \"\w+\", not of law = \"elliptical\""):
        _params(**ELLIPTICAL, **extra)


def test_a_walking_part_file_refuses_the_eccentricity():
    with pytest.raises(InputError, match=r'^eccentricity = 0.2: is a key of law = "elliptical", not of law = "walking"'):
        _params(eccentricity=0.2)


def test_cli_exits_2_with_one_line_naming_the_key(tmp_path, capsys):
    f = tmp_path / "p.toml"
    f.write_text('type = "noncircular_pair"\nlaw = "elliptical"\neccentricity = 0.3\ndriver_turns = 1\n'
                 'driven_teeth = 30\nb_mm = 40.0\ncompare_methods = false\n')
    rc = main(["build", str(f), "--out", str(tmp_path / "out"), "-q"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1
    assert err[0].startswith("propulsor: error: b_mm = 40") and 'law = "elliptical"' in err[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("kw, match", [
    (dict(eccentricity=1.0), r"^eccentricity = 1\.0: must be <= 0\.9"),
    (dict(method="sectors"), r"^method = 'sectors': the sector method is the walking law's"),
    (dict(driven_teeth=31, driver_turns=2), r"^driven_teeth = 31: must be a multiple of driver_turns = 2"),
])
def test_bad_elliptical_part_files_are_refused(kw, match):
    with pytest.raises(InputError, match=match):
        _params(**{**ELLIPTICAL, **kw})


def test_fourier_ratio_not_positive_is_refused_in_validation():
    with pytest.raises(InputError, match=r"^fourier_cos = \[1\.5\]: d phi / d theta = .* <= 0"):
        _params(law="fourier", driver_turns=1, fourier_cos=[1.5], compare_methods=False)


def test_table_law_file_is_read_relative_to_the_part_file(tmp_path):
    (tmp_path / "t.csv").write_text("driver_deg,driven_deg\n" + "".join(
        f"{2 * x + math.degrees(0.2 * math.sin(math.radians(2 * x)))!r},{float(x)!r}\n" for x in range(0, 181, 10)))
    p = _params(law="table", law_file="t.csv", module_mm=2.0, driven_teeth=60, compare_methods=False)
    law = _law(p, tmp_path / "part.toml")
    assert (law.kind, law.n, law.periods) == ("table", 2, 2)
    with pytest.raises(InputError, match=r"^law_file = .*t\.csv'?: cannot be read"):
        _law(p, tmp_path / "elsewhere" / "part.toml")


def test_an_elliptical_pair_not_generable_says_what_would_make_it_so():
    from propulsor.parts.noncircular_pair.design import design

    # 12 teeth of m = 2.5 on an ellipse of e = 0.6: the vertex radius of curvature is below the rack's limit
    p = _params(**{**ELLIPTICAL, "eccentricity": 0.6, "driven_teeth": 12, "driver_shift": 0.0,
                   "driver_bore_mm": 0.0, "driven_bore_mm": 0.0})
    with pytest.raises(InputError, match=r"^driver_shift = 0\.0: the elliptical law's pitch curves are not generable "
                                         r".*works with driver_shift >= .*or driven_teeth >= \d+"):
        design(p)


def test_inputs_listed_are_the_laws_own():
    """The report and manifest list the inputs that apply: a walking pair's as before the other laws
    existed (no ``law``, no other law's keys); an elliptical pair's without a_mm, b_mm, c_mm."""
    from propulsor.params import applying_inputs
    from propulsor.parts.noncircular_pair.params import LAW_KEYS, NoncircularPairParams

    walking = applying_inputs(NoncircularPairParams())
    assert "law" not in walking and "a_mm" in walking
    assert not {k for law, keys in LAW_KEYS.items() if law != "walking" for k in keys} & set(walking)
    ell = NoncircularPairParams(law="elliptical", eccentricity=0.3, driver_turns=1)
    listed = applying_inputs(ell)
    assert listed["law"] == "elliptical" and listed["eccentricity"] == 0.3
    assert not {"a_mm", "b_mm", "c_mm", "law_file", "fourier_cos"} & set(listed)
    assert ell.meaning("driver_turns").startswith("k: lobes")
    assert NoncircularPairParams().meaning("driver_turns") == "n: driver turns per driven (carrier) turn; 1, 2 or 4"


def test_a_law_without_a_hub_proves_on_one_core():
    """The proof of an elliptical pair in one process (a study's proof depth, ``make``'s busy queue): no
    as-built hub speed is asked of a law without a hub (it raised AttributeError when run inline)."""
    from pathlib import Path

    from propulsor.params import read_part_file
    from propulsor.study.evaluate import evaluate

    part = Path(__file__).resolve().parents[1] / "parts" / "ncg_elliptical.toml"
    ptype, base = read_part_file(part)
    row = evaluate(ptype, base, str(part), {}, "proof", ("center_distance_mm",))
    assert row["status"] == "ok", row["reason"]
    assert row["values"]["center_distance_mm"] > 0
