"""What every derived value of a build means: a glossary per part type, merged with what the build
itself described (``OutputWriter.describe``, which wins), gives each derived value a unit and a
meaning for the report's table and the manifest's ``glossary``.

A part type's glossary is a dict ``{name: (unit, meaning)}``.  A name may hold placeholders
``<word>``: ``<solid>_volume_mm3`` matches ``carrier_volume_mm3`` and its meaning may say
``{solid}``.  Nested values are named by path: ``outer.key`` for a key of a dict, ``outer[].key``
for a key of the dicts in a list.  A dict of plain values (one per case: ``sigma_MPa.stop``) needs no
entries of its own: each value is the outer name's quantity for that key.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .units import unit_of_path

#: what every part type shares (the writer derives these names itself)
COMMON = {
    "<solid>_volume_mm3": ("mm³", "volume of the solid {solid} (exact, from its B-rep)"),
    # a print kit's own (printing.kit)
    "scale_S": ("", "scale of the printed model: printed length over the part's length"),
    "plates": ("", "build plates the printed pieces are packed on"),
    "pieces": ("", "printed pieces, every copy counted"),
    "filament_volume_cm3": ("cm³", "filament volume of all plates"),
    "filament_mass_g": ("g", "filament mass of all plates at the printer's filament density"),
    "printer": ("", "the printer profile the kit was made for"),
    "bed_mm": ("mm", "build volume of the printer: x, y, z"),
    "pieces_volume_cm3": ("cm³", "solid volume of every printed piece (100 % infill)"),
    "filament_estimate_g": ("g", "filament estimated at the profile's infill, perimeters and top/bottom layers "
                                 "(used where the plates were not sliced)"),
    "infill_percent": ("%", "sparse infill of the print settings"),
    "print_time_s": ("s", "printing time of all plates, from PrusaSlicer's G-code (normal mode)"),
    "filament_sliced_g": ("g", "filament of all plates, from PrusaSlicer's G-code"),
}

_PLACEHOLDER = re.compile(r"<([A-Za-z_][A-Za-z0-9_]*)>")


@dataclass(frozen=True)
class Entry:
    path: str
    unit: str
    meaning: str
    name_unit: str  # the unit the path's names carry (units.unit_of_path)


def _compile(glossary: dict):
    exact, patterns = {}, []
    for key, value in glossary.items():
        if "<" in key:
            rx = re.escape(key)
            for name in _PLACEHOLDER.findall(key):
                rx = rx.replace(re.escape(f"<{name}>"), f"(?P<{name}>.+?)")
            patterns.append((re.compile(rx + r"\Z"), value))
        else:
            exact[key] = value
    # the pattern with the most literal text is the most specific
    patterns.sort(key=lambda p: -len(_PLACEHOLDER.sub("", p[0].pattern)))
    return exact, patterns


class Glossary:
    """Looks up (unit, meaning) of a derived value's path."""

    def __init__(self, *glossaries: dict, described: dict | None = None):
        merged: dict = {}
        for g in (COMMON, *glossaries):
            merged.update(g)
        self.exact, self.patterns = _compile(merged)
        self.described = dict(described or {})

    def lookup(self, path: str):
        if path in self.described:
            return tuple(self.described[path])
        if path in self.exact:
            return tuple(self.exact[path])
        for rx, (unit, meaning) in self.patterns:
            m = rx.match(path)
            if m:
                return unit, meaning.format(**m.groupdict())
        return None


def _plain(v) -> bool:
    return not isinstance(v, (dict, list, tuple)) or all(not isinstance(x, (dict, list, tuple)) for x in v)


def explain(derived: dict, glossary: Glossary) -> tuple[list[Entry], list[str]]:
    """Every derived value's path with its unit and meaning (in the order of `derived`, outer before
    inner), and the paths that have no meaning."""
    entries: list[Entry] = []
    missing: list[str] = []

    def visit(path: str, keys: list, value, parent):
        found = glossary.lookup(path)
        if found is None and parent is not None and _plain(value):
            # a case of a dict of plain values: the outer quantity for this key
            found = (parent.unit, f"{parent.meaning}: {keys[-1]}")
        if found is None or not str(found[1]).strip():
            missing.append(path)
            entry = None
        else:
            entry = Entry(path, str(found[0]), str(found[1]), unit_of_path(keys))
            entries.append(entry)
        if isinstance(value, dict) and entry is not None:
            for k, x in value.items():
                visit(f"{path}.{k}", keys + [str(k)], x, entry)
        elif isinstance(value, (list, tuple)) and value and all(isinstance(x, dict) for x in value):
            seen: dict = {}
            for item in value:
                for k, x in item.items():
                    seen.setdefault(str(k), x)
            for k, x in seen.items():
                visit(f"{path}[].{k}", keys + [k], x, None)

    for name, value in derived.items():
        visit(str(name), [str(name)], value, None)
    return entries, missing


def manifest_glossary(entries) -> dict:
    """The manifest's ``glossary``: {path: {"unit": ..., "meaning": ...}}."""
    return {e.path: {"unit": e.unit, "meaning": e.meaning} for e in entries}
