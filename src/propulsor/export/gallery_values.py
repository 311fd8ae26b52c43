"""The gallery's words for a part at a glance: key numbers with a label, a unit and a rounding a person
reads; the checks a badge names; a polysector position as its offset and ratio.

A label and a unit come from the manifest's glossary ({name: {unit, meaning}}) when it has the name,
else from the name itself (its unit suffix taken off, ``_`` as spaces, the unit from the suffix).
Numbers: four significant digits, no exponent between 0.001 and 10 000 000, thousands grouped by a
thin space; a value below 1e-9 of its unit is 0 (the float's noise: 2.8e-14 mm is 0 mm); a value that
is not a number is "—" with why.
"""

from __future__ import annotations

import math

from .report import _fmt
from .units import name_stem, unit_from_name

#: what a value that is not a number means, by part type (else NO_VALUE)
NO_VALUE_WHY = {"noncircular_pair": "no free position: the pair jams", "polysector_gear": "no free position"}
NO_VALUE = "not defined for this design"
#: the same for a non-circular pair with the papers' sector teeth (``method = "sectors"``), which jam
SECTOR_WHY = "sector method: not defined, its teeth jam"
#: at most this many check names on a badge (then "and n more")
BADGE_NAMES = 4


def number(v: float) -> str:
    """`v` rounded for a reader: 4 significant digits, no exponent in [0.001, 1e7), 0 below 1e-9."""
    if v == 0 or abs(v) < 1e-9:
        return "0"
    a = abs(v)
    if a >= 1e7 or a < 1e-3:
        return f"{v:.3e}".replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")
    digits = max(0, 3 - math.floor(math.log10(a)))
    text = f"{round(v, digits):,.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text.replace(",", "\u2009")


def value_text(v, part: str = "", why: str | None = None) -> str:
    """A derived value as the gallery shows it (a list or table as the report shows it); `why`: what a value
    that is not a number means (else by part type)."""
    why = why or NO_VALUE_WHY.get(part, NO_VALUE)
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, (int, float)):
        if isinstance(v, float) and not math.isfinite(v):
            return f"— ({why})" if math.isnan(v) else ("∞" if v > 0 else "−∞")
        return number(float(v)) if isinstance(v, float) else str(v)
    if v is None:
        return f"— ({why})"
    return _fmt(v)


def label(name: str, glossary: dict) -> tuple[str, str]:
    """(label, unit) of derived value `name`: the glossary's meaning and unit, else from the name."""
    g = glossary.get(name) if isinstance(glossary, dict) else None
    g = g if isinstance(g, dict) else {}
    unit = g.get("unit") if isinstance(g.get("unit"), str) else unit_from_name(name)
    meaning = g.get("meaning") if isinstance(g.get("meaning"), str) and g.get("meaning").strip() else None
    if meaning is None:
        stem = name_stem(name)
        meaning = stem.replace("_", " ").strip() or name
    return meaning, unit


def failed_names(manifest: dict) -> tuple[list[str], list[str]]:
    """(names of the failed checks the part file does not list, names of the documented failures)."""
    documented = set(manifest.get("expected_failures", []))
    failed = [str(c.get("name")) for c in manifest.get("checks", []) if isinstance(c, dict) and not c.get("passed")]
    return [n for n in failed if n not in documented], [n for n in failed if n in documented]


def names_text(names: list[str]) -> str:
    shown = ", ".join(names[:BADGE_NAMES])
    return shown + (f" and {len(names) - BADGE_NAMES} more" if len(names) > BADGE_NAMES else "")


def position_title(manifest: dict, k: int) -> str | None:
    """"e = 18 mm, i = 0.833" for the k-th model of a polysector gear (its ``derived.positions``)."""
    pos = manifest.get("derived", {}).get("positions")
    if manifest.get("part") != "polysector_gear" or not isinstance(pos, list) or k >= len(pos):
        return None
    p = pos[k]
    e, i = (p.get("offset_mm"), p.get("ratio_nominal")) if isinstance(p, dict) else (None, None)
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in (e, i)):
        return None
    return f"e = {number(float(e))} mm, i = {float(i):.3g}"
