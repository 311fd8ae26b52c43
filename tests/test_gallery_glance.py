"""The gallery read at a glance: key numbers labelled (the manifest's glossary, else the name), with a
unit and a reader's rounding; no "nan"; badges naming the failed and documented-failure checks; a
polysector's positions as offset and ratio; animations at full size, linked."""

from __future__ import annotations

import json
import math

from propulsor.export.gallery import key_values, render_gallery, status
from propulsor.export.gallery_values import number


def test_numbers_rounded_for_a_reader():
    assert number(2.842170943040401e-14) == "0"  # the float's noise
    assert number(114.55929238248478) == "114.6"
    assert number(0.08198692886384809) == "0.08199"
    assert number(3.0) == "3" and number(-12.25) == "-12.25"
    assert number(9759992.180092718) == "9\u2009759\u2009992"
    assert number(2.1e-5) == "2.100e-5"


def _part(folder, name, part="road_wheel", **fields):
    (folder / name).mkdir()
    m = {"part": part, "files": [], "checks": [], "expected_failures": [], "derived": {}}
    m.update(fields)
    (folder / name / "manifest.json").write_text(json.dumps(m))
    return m


def test_key_numbers_labelled_from_the_glossary_or_the_name(tmp_path):
    m = _part(tmp_path, "fd", part="planetary_final_drive",
              derived={"coaxiality_mismatch_mm": 2.842170943040401e-14, "ratio_i_1H": 4.999999999,
                       "design_torque_carrier_Nm": 1234.5678},
              glossary={"ratio_i_1H": {"unit": "", "meaning": "ratio sun → carrier <b>"}})
    page = render_gallery(tmp_path)
    assert "<dt>ratio sun → carrier &lt;b&gt;</dt><dd>5</dd>" in page  # the glossary's meaning, escaped
    assert "<dt>coaxiality mismatch</dt><dd>0&nbsp;mm</dd>" in page
    assert "<dt>design torque carrier</dt><dd>1\u2009235&nbsp;N·m</dd>" in page
    head = page.split("<script>")[0]  # the page before the viewer's script
    assert "e-14" not in head and "coaxiality_mismatch_mm" not in head
    assert key_values(m | {"glossary": {}})[0] == ("ratio i 1H", "5", "")


def test_no_nan_but_why(tmp_path):
    _part(tmp_path, "ncg", part="noncircular_pair",
          derived={"backlash_min_mm": math.nan, "te_pp_rad": math.nan, "contact_ratio_mean": math.nan})
    page = render_gallery(tmp_path)
    head = page.split("<script>")[0]
    assert "nan" not in head and "NaN" not in head
    assert "<dt>backlash min</dt><dd>— (no free position: the pair jams)</dd>" in head


def test_badges_name_the_failed_checks():
    checks = [{"name": "a", "passed": True}, {"name": "jam <x>", "passed": False}, {"name": "b", "passed": False}]
    assert status({"checks": checks, "expected_failures": ["b"]}) == (
        "bad", "failed: 1 of 3 checks: jam <x> (documented: b)")
    assert status({"checks": checks, "expected_failures": ["b", "jam <x>"]}) == (
        "doc", "documented failures: 2 of 3 checks: jam <x>, b (the part file lists them)")


def test_polysector_positions_and_full_size_animations(tmp_path):
    from PIL import Image

    (tmp_path / "ps").mkdir()
    (tmp_path / "ps" / "anim").mkdir()
    Image.new("RGB", (640, 480)).save(tmp_path / "ps" / "anim" / "a.gif")
    models = []
    from test_viewer_page import tiny_glb

    for k in range(1, 3):
        (tmp_path / "ps" / f"assembly_{k}.glb").write_bytes(tiny_glb())
        models.append({"path": f"assembly_{k}.glb", "title": f"assembly_{k}"})
    m = {"part": "polysector_gear", "files": [], "checks": [], "expected_failures": [],
         "derived": {"positions": [{"offset_mm": 0.0, "ratio_nominal": 1.1111111}, {"offset_mm": 18.0, "ratio_nominal": 0.8333333}]},
         "media": {"models": models, "animations": [{"path": "anim/a.gif", "title": "t", "width_px": 640, "height_px": 480}]}}
    (tmp_path / "ps" / "manifest.json").write_text(json.dumps(m))
    page = render_gallery(tmp_path)
    assert "<option>e = 0 mm, i = 1.11</option><option>e = 18 mm, i = 0.833</option>" in page
    assert '<a href="ps/anim/a.gif"><img src="ps/anim/a.gif"' in page and 'width="640"' in page
    assert ">full size</a>" in page
