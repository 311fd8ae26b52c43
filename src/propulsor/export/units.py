"""The unit a quantity's name ends in: derived values carry their units in their names (``a_w_mm``,
``pitch_line_speed_rel_m_s``, ``spline_S_u_mm3_per_mm``).

Suffixes are matched longest first, so a compound suffix (``_m_s``, ``_mm3_per_mm``, ``_N_mm``) is
read whole and never as its last token.  A bare symbol with a subscript (``epsilon_s``, ``beta_m``:
a Greek letter and one letter) names no unit.  In a nested value the outermost name that carries a
unit gives it (``sigma_MPa.stop`` is in MPa); otherwise the innermost name does.
"""

from __future__ import annotations

#: name suffix -> unit, for every suffix the derived values use (the longest match wins)
SUFFIX_UNITS: dict[str, str] = {
    "_mm3_per_mm": "mm³/mm",
    "_mm_per_rad": "mm/rad",
    "_Ns_per_m": "N·s/m",
    "_N_per_mm": "N/mm",
    "_N_per_m": "N/m",
    "_per_mm": "1/mm",
    "_Ns/m": "N·s/m",
    "_N/m": "N/m",
    "_N_mm": "N·mm",
    "_Nmm": "N·mm",
    "_Nm": "N·m",
    "_N_m": "N·m",
    "_m_s": "m/s",
    "_mps": "m/s",
    "_km_h": "km/h",
    "_kmh": "km/h",
    "_rpm": "rpm",
    "_Hz": "Hz",
    "_cm3": "cm³",
    "_mm3": "mm³",
    "_mm2": "mm²",
    "_mm": "mm",
    "_um": "µm",
    "_m": "m",
    "_deg": "deg",
    "_dms": "° ′ ″",
    "_rad": "rad",
    "_MPa": "MPa",
    "_mpa": "MPa",
    "_kN": "kN",
    "_N": "N",
    "_kg": "kg",
    "_g": "g",
    "_J": "J",
    "_W": "W",
    "_s": "s",
    "_K": "K",
    "_C": "°C",
    "_pct": "%",
}

_BY_LENGTH = sorted(SUFFIX_UNITS.items(), key=lambda kv: -len(kv[0]))

#: Greek letters spelt out: ``<letter>_<one letter>`` is a symbol with a subscript, not a unit
GREEK = frozenset("alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi omicron pi rho "
                  "sigma tau upsilon phi chi psi omega".split())


def unit_from_name(name: str) -> str:
    """The unit a quantity's name ends in ('' when it names none)."""
    name = str(name)
    head, _, tail = name.rpartition("_")
    if head.lower() in GREEK and len(tail) == 1:
        return ""
    for suffix, unit in _BY_LENGTH:
        if name.endswith(suffix) and len(name) > len(suffix):
            return unit
    return ""


def name_stem(name: str) -> str:
    """`name` without the unit suffix it ends in (``pitch_line_speed_rel_m_s`` → ``pitch_line_speed_rel``)."""
    name = str(name)
    if unit_from_name(name):
        for suffix, _ in _BY_LENGTH:
            if name.endswith(suffix) and len(name) > len(suffix):
                return name[: -len(suffix)]
    return name


def unit_of_path(keys) -> str:
    """The unit of a nested value reached through `keys` (outermost first; list items have no key):
    the outermost key that names a unit, else ''."""
    for key in keys:
        unit = unit_from_name(key)
        if unit:
            return unit
    return ""
