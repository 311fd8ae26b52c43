"""Units from names, the glossaries of every part type, the report's layout and its References, and
no internal document references in the sources (fast: no part is built)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from propulsor.check import Check
from propulsor.export.glossary import Glossary, explain
from propulsor.export.report import write_report
from propulsor.export.units import SUFFIX_UNITS, unit_from_name, unit_of_path
from propulsor.parts import glossary_of, key_values_of, part_type_names

SRC = Path(__file__).resolve().parents[1] / "src"


@pytest.mark.parametrize("name, unit", [
    ("pitch_line_speed_rel_m_s", "m/s"), ("spline_S_u_mm3_per_mm", "mm³/mm"), ("v_max_km_h", "km/h"),
    ("traction_gear1_V_top_kmh", "km/h"), ("bending_moment_N_mm", "N·mm"), ("M_T_max_Nm", "N·m"),
    ("n_at_V_max_rpm", "rpm"), ("hub_speed_variation_pct", "%"), ("hub_speed_mean_mm_per_rad", "mm/rad"),
    ("fd_profile_curvature_abs_max_per_mm", "1/mm"), ("c_static_N/m", "N/m"), ("damper_b2_Ns_per_m", "N·s/m"),
    ("a_w_mm", "mm"), ("overlap_mm2", "mm²"), ("volume_mm3", "mm³"), ("T_at_V_max_C", "°C"),
    ("rise_K", "K"), ("P_N", "N"), ("f_Hz", "Hz"), ("deviation_um", "µm"), ("alpha_w_dms", "° ′ ″"),
    ("filament_volume_cm3", "cm³"), ("filament_mass_g", "g"), ("T_phi_s", "s"),
    ("epsilon_s", ""), ("beta_m", ""), ("strength_K_A", ""), ("k_W_sun", ""), ("law", ""),
])
def test_unit_from_the_name_suffix(name, unit):
    assert unit_from_name(name) == unit


def test_nested_values_take_the_outer_unit():
    assert unit_of_path(["sigma_vM_max_built_MPa", "beta_m"]) == "MPa"
    assert unit_of_path(["positions", "center_distance_mm"]) == "mm"
    assert unit_of_path(["positions", "epsilon_s"]) == ""


@pytest.mark.parametrize("part", part_type_names())
def test_every_glossary_entry_has_a_meaning_and_the_unit_its_name_says(part):
    glossary = glossary_of(part)
    assert glossary, part
    for key, (unit, meaning) in glossary.items():
        assert meaning.strip(), key
        keys = [k for k in re.split(r"\.|\[\]\.", key)]
        named = unit_of_path([re.sub(r"<\w+>", "x", k) for k in keys])
        assert unit == named if named else unit not in SUFFIX_UNITS.values(), (part, key, unit, named)
    assert all(isinstance(k, str) for k in key_values_of(part))


def test_patterns_nested_values_and_what_is_missing():
    g = Glossary({"mesh_<a>_<b>_gap_mm": ("mm", "gap of {a} and {b}"), "cases_MPa": ("MPa", "stress per case"),
                  "positions": ("", "per position"), "positions[].offset_mm": ("mm", "offset")},
                 described={"gear_volume_mm3": ("mm³", "ours")})
    entries, missing = explain({"mesh_sun_planet1_gap_mm": 0.1, "cases_MPa": {"stop": 3.0}, "gear_volume_mm3": 1.0,
                                "positions": [{"offset_mm": 0.0, "z_cond": 3}], "stray_mm": 2.0}, g)
    by = {e.path: (e.unit, e.meaning) for e in entries}
    assert by["mesh_sun_planet1_gap_mm"] == ("mm", "gap of sun and planet1")
    assert by["cases_MPa.stop"] == ("MPa", "stress per case: stop")
    assert by["gear_volume_mm3"] == ("mm³", "ours")  # described wins over the common pattern
    assert missing == ["positions[].z_cond", "stray_mm"]


def test_a_derived_value_without_a_meaning_fails_the_build(tmp_path):
    from propulsor.parts.writer import OutputWriter

    w = OutputWriter(tmp_path, "road_wheel", None)
    w.derived.update({"mass_wheel_kg": 1.0, "new_thing_mm": 2.0})
    c = w.explained_check()
    assert not c.passed and c.value == 1 and "new_thing_mm" in c.message
    w.describe("new_thing_mm", "mm", "a new length")
    assert w.explained_check().passed


def test_summary_first_then_sections_and_references(tmp_path):
    derived = {"a_w_mm": (120.0, "mm", "centre distance (seed 004 eq. 13)"),
               "S_F": (1.2, "", "root safety (ISO 6336-3)")}
    checks = [Check.at_most("root stress (ISO 6336-3)", 2.0, 1.0, "MPa", "seed 000 Table 1"),
              Check.at_most("fits", 1.0, 2.0, "mm")]
    p = write_report(tmp_path / "report.md", "Pair (seed 004)", inputs={"b_mm": (10.0, "mm", "width")},
                     derived=derived, checks=checks, notes=["see seed 004 ch. 4"], key_values=["S_F"])
    text = p.read_text()
    heads = [ln for ln in text.splitlines() if ln.startswith("## ")]
    assert heads == ["## Summary", "## Inputs", "## Derived values", "## Checks", "## Notes", "## References"]
    summary = text.split("## Inputs")[0]
    assert "**FAILED: 1 of 2 checks failed.**" in summary and "| S_F | 1.2 |  | root safety" in summary
    assert "root stress (ISO 6336-3 [2])" in summary and "fits" not in summary
    assert "# Pair ([1])" in text and "centre distance ([1] eq. 13)" in text and "[3] Table 1" in text
    refs = text.split("## References")[1]
    assert re.findall(r"\\\[(\d)\\\]", refs) == ["1", "2", "3"]
    assert "Taratorkin A. I." in refs and "ISO 6336-3:2019" in refs and "Skoybeda A. T., Zhukovets V. N." in refs
    assert "seed 00" not in text


def test_no_internal_document_references_in_the_sources():
    pattern = re.compile(r"\b[Ii]ssue \d|\bSPEC\b|\bTrap \d|\b[Tt]he brief\b")
    hits = [f"{p.relative_to(SRC)}:{k}" for p in sorted(SRC.rglob("*")) if p.suffix in (".py", ".toml", ".md")
            for k, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if pattern.search(line)]
    assert hits == []
