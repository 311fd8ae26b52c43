"""Outputs that link, numbers for reading (issue 39): the gallery links each kit's print guide and shows a kit
built under another name (``propulsor print --out``) with its report, guide, plates and pictures; the kit report
links the guide's HTML page; the guide numbers its assembly steps 1, 2, 3 … in one list; the study page rounds
its values with their units (a ripple in per cent) and does not scroll sideways on a phone; no page shows "nan".

The outputs are real: one road-wheel build, its print kit (built into a folder not named ``<part>_kit``, and the
same kit as ``road_wheel_kit``) and a two-variant study of it, in one gallery folder.
"""

from __future__ import annotations

import json
import math
import re
import shutil
from pathlib import Path

import pytest

from propulsor.cli import main
from propulsor.study.page import NOT_A_NUMBER, shown

ROOT = Path(__file__).resolve().parents[1]
WHEEL = ROOT / "parts" / "road_wheel.toml"
PHONE_PX = 390
STUDY = f"""
[study]
part = "{WHEEL}"
depth = "design"
title = "road wheel: tyre width x load"

[vary]
tyre_width_mm = [70.0, 90.0]
load_N = [30000.0]

[objectives]
minimize = ["T_at_V_max_C", "peak_pressure_q_m_MPa"]
require = ["all_checks_passed"]
record = ["contact_length_l_mm"]
"""


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("outputs") / "output"
    study = out.parent / "wheel_study.toml"
    study.write_text(STUDY, encoding="utf-8")
    assert main(["build", str(WHEEL), "--out", str(out / "road_wheel"), "-q"]) == 0
    assert main(["print", str(WHEEL), "--out", str(out / "my_wheel_print"), "-q", "--slice", "no"]) == 0
    shutil.copytree(out / "my_wheel_print", out / "road_wheel_kit")
    assert main(["explore", str(study), "--out", str(out / "wheel_study"), "--workers", "1", "-q"]) == 0
    # a sector-method pair as its manifest records it: the teeth jam, so backlash and transmission error are
    # not numbers (NaN in the manifest's JSON)
    (out / "sector_pair").mkdir()
    (out / "sector_pair" / "manifest.json").write_text(json.dumps(
        {"part": "noncircular_pair", "title": "sector pair", "files": [], "checks": [], "expected_failures": [],
         "derived": {"method": "sectors", "speed_ripple": 0.07869341195173282, "backlash_min_mm": math.nan,
                     "te_pp_rad": math.nan, "center_distance_mm": 79.54009282751963}}))
    assert main(["gallery", str(out), "-q"]) == 0
    return out


def test_the_gallery_links_each_kit_s_guide_and_shows_a_kit_under_another_name(folder):
    index = (folder / "index.html").read_text(encoding="utf-8")
    for kit in ("road_wheel_kit", "my_wheel_print"):
        assert f'<a href="{kit}/print_guide.html">print guide</a>' in index
        assert f'<a href="{kit}/print_report.html">report</a>' in index
        assert f'<a href="{kit}/plate_1.3mf">plate_1.3mf</a>' in index
        assert f'<img src="{kit}/plots/plate_1.png"' in index
    # the kit under its own name is a card of its own, with no report.html it does not have
    card = index[index.index('<section class="part" id="my_wheel_print">'):]
    card = card[:card.index("</section>")]
    assert "my_wheel_print/report.html" not in card and "my_wheel_print/print_guide.html" in card


def test_the_gallery_says_why_a_value_is_not_a_number_and_a_ripple_in_per_cent(folder):
    index = (folder / "index.html").read_text(encoding="utf-8")
    card = index[index.index('<section class="part" id="sector_pair">'):]
    card = card[:card.index("</section>")]
    assert "<dd>7.869&nbsp;%</dd>" in card and "<dd>79.54&nbsp;mm</dd>" in card
    assert card.count("<dd>— (sector method: not defined, its teeth jam)</dd>") == 2 and "nan" not in card.lower()


def test_the_kit_report_links_the_guide_s_html_and_the_guide_the_report_s(folder):
    report = (folder / "road_wheel_kit" / "print_report.html").read_text(encoding="utf-8")
    guide = (folder / "road_wheel_kit" / "print_guide.html").read_text(encoding="utf-8")
    assert '<a href="print_guide.html">print_guide.html</a>' in report
    assert '<a href="print_report.html">print_report.html</a>' in guide
    # the Markdown only as the guide's text beside its page
    assert report.count('href="print_guide.md"') == report.count('(its text: <a href="print_guide.md">') == 1


def test_the_guide_numbers_its_assembly_steps_in_one_list(folder):
    guide = (folder / "road_wheel_kit" / "print_guide.html").read_text(encoding="utf-8")
    md = (folder / "road_wheel_kit" / "print_guide.md").read_text(encoding="utf-8")
    section = md[md.index("## 4. Assembly"):md.index("## 5.")]
    steps = re.findall(r"^(\d+)\. ", section, re.M)
    assert steps == [str(k) for k in range(1, len(steps) + 1)] and len(steps) >= 3
    html = guide[guide.index("4. Assembly</h2>"):guide.index("5. Tight or loose?")]
    assert html.count("<ol>") == 1 and html.count("<li>") == len(steps)  # one list: the browser counts 1, 2, 3 …
    assert html.count('<img alt="step ') >= 2 and html.index("</ol>") > html.rindex('<img alt="step ')


def test_the_study_page_rounds_its_values_with_units():
    assert shown("center_distance_mm", 79.54009282751963) == "79.54 mm"
    assert shown("speed_ripple", 0.07869341195173282) == "7.869 %"
    assert shown("te_pp_rad", 0.0007040347456639395) == "7.040e-4 rad"
    assert shown("backlash_min_mm", math.nan) == NOT_A_NUMBER and "nan" not in NOT_A_NUMBER
    assert shown("driven_teeth", 64) == "64" and shown("all_checks_passed", True) == "true"


def test_the_study_page_of_a_real_study(folder):
    page = (folder / "wheel_study" / "study.html").read_text(encoding="utf-8")
    cells = re.findall(r'<td data-v="([0-9.e+-]+)">([^<]*)</td>', page)
    temps = [(v, t) for v, t in cells if t.endswith("°C")]
    assert temps and all(len(v) > len(t) - 3 for v, t in temps)  # every digit kept for sorting, fewer shown
    assert all(re.fullmatch(r"[0-9.\u2009]+ °C", t) for _, t in temps)
    assert '<div class="scroll"><img src="pareto_front.png"' in page and '<div class="scroll"><table>' in page


# --- in a real browser ---------------------------------------------------------------------------------------------

PAGE_TEXT = """(() => ({text: document.body.innerText, scrollWidth: document.documentElement.scrollWidth,
  links: Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'))}))()"""


@pytest.mark.browser
def test_the_pages_in_a_real_browser_no_nan_no_sideways_scroll_and_the_guide_linked(folder):
    from cdp_browser import find_chromium, headless_page

    if find_chromium() is None:
        pytest.skip("chromium is not installed")
    pages = [folder / "index.html", folder / "wheel_study" / "study.html"]
    pages += sorted(folder.glob("*/report.html")) + sorted(folder.glob("*/print_report.html"))
    pages += sorted(folder.glob("*/print_guide.html"))
    bad = []
    with headless_page() as page:
        for p in pages:
            page.open(p.as_uri(), PHONE_PX)
            got = page.evaluate(PAGE_TEXT)
            for m in re.finditer(r"\bnan\b", got["text"], re.I):
                bad.append(f"{p.relative_to(folder)}: shows {got['text'][max(0, m.start() - 40):m.end() + 20]!r}")
            if p.name == "study.html" and got["scrollWidth"] > PHONE_PX:
                bad.append(f"study.html is {got['scrollWidth']} px wide on a {PHONE_PX} px screen")
            if p.name == "index.html":
                for kit in ("road_wheel_kit", "my_wheel_print"):
                    if f"{kit}/print_guide.html" not in got["links"]:
                        bad.append(f"index.html links no guide of {kit}")
            if p.name == "print_report.html" and "print_guide.html" not in got["links"]:
                bad.append(f"{p.relative_to(folder)} links no print_guide.html")
    assert bad == []


def test_a_report_never_shows_nan():
    from propulsor.export.report import NOT_DEFINED, _fmt

    assert _fmt(math.nan) == NOT_DEFINED and _fmt([1.5, math.nan]) == f"[1.5, {NOT_DEFINED}]"
    assert _fmt(math.inf) == "∞" and _fmt(-math.inf) == "−∞" and _fmt(0.125) == "0.125"
