"""Printer profiles for print kits: bed, nozzle, layer and the FDM allowances, as data.

Built-in profiles live as TOML files in ``printers/`` beside this module (``propulsor print --printer
NAME``); a user's own printer is a TOML file of the same keys (``--printer my_printer.toml``: its
bed_x_mm, bed_y_mm and bed_z_mm are required), or a bed alone (``--bed 180x180x180``).  Every
allowance has a default from common desktop-FDM practice (0.4 mm nozzle, 0.2 mm layers) and may be
overridden by name.  The values are validated like part parameters.
"""

from __future__ import annotations

import dataclasses
import os
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from .. import policy
from ..errors import InputError, did_you_mean
from ..params import load_params, param

_WHY_BED = "the largest desktop printers (about 1 m)"
_WHY_FIT = "a fit looser than 2 mm is no fit"


@dataclass(frozen=True)
class Printer:
    """One printer and the allowances its prints need (mm unless named otherwise)."""

    name: str = param("generic", "", "profile name")
    title: str = param("", "", "what the profile is")
    bed_x_mm: float = param(220.0, "mm", "bed width (x)", min=50.0, max=1000.0, why=_WHY_BED)
    bed_y_mm: float = param(220.0, "mm", "bed depth (y)", min=50.0, max=1000.0, why=_WHY_BED)
    bed_z_mm: float = param(250.0, "mm", "largest print height (z)", min=50.0, max=1000.0, why=_WHY_BED)
    shape: str = param("rectangle", "", "bed outline (a rectangle bed_x_mm × bed_y_mm from the origin)",
                       choices=("rectangle",))
    margin_mm: float = param(policy.PLATE_MARGIN_MM, "mm", "least distance of the pieces to the bed's edges: room "
                             "for the slicer's skirt (PrusaSlicer's default, 6 mm out) and the bed's clips", min=0.0,
                             max=50.0, why="margins of 50 mm leave nothing of a 100 mm bed")
    nozzle_mm: float = param(0.4, "mm", "nozzle diameter", min=0.1, max=1.2, why="the largest common nozzles")
    layer_mm: float = param(0.2, "mm", "layer height", min=0.05, max=0.8, why="at most 2/3 of the largest nozzle")
    line_width_mm: float = param(0.0, "mm", "extrusion width (0: the nozzle diameter)", min=0.0, max=2.0,
                                 why="1.5 × the largest nozzle")
    backlash_mm: float = param(0.3, "mm", "normal backlash of printed gear meshes (FDM: 0.2 ... 0.4), made by "
                               "thinning the teeth", min=0.0, max=2.0, why=_WHY_FIT)
    running_clearance_mm: float = param(0.25, "mm", "radial clearance of a running fit (pin in bore; FDM: "
                                        "0.2 ... 0.3)", min=0.0, max=2.0, why=_WHY_FIT)
    press_fit_mm: float = param(0.05, "mm", "radial interference of a press fit (FDM: 0 ... 0.1)", min=0.0,
                                max=0.5, why="past it printed parts split")
    hole_undersize_mm: float = param(0.15, "mm", "how much smaller than drawn holes print (diameter; FDM: "
                                     "0.1 ... 0.2), added to every hole", min=0.0, max=1.0,
                                     why="holes 1 mm small want a calibrated printer, not an allowance")
    chamfer_mm: float = param(0.4, "mm", "chamfer of bed-side edges against the first layers' spread "
                              "(elephant's foot; 0.3 ... 0.5)", min=0.0, max=2.0, why="ten layers of 0.2 mm")
    min_module_mm: float = param(1.0, "mm", "least printable module (smaller teeth are mush)", min=0.2, max=10.0,
                                 why="any printer prints module 10")
    piece_gap_mm: float = param(5.0, "mm", "gap between pieces on a plate", min=1.0, max=50.0,
                                why="a gap of half a 100 mm bed")
    density_g_cm3: float = param(1.24, "g/cm^3", "filament density (PLA: 1.24)", min=0.5, max=3.0,
                                 why="past any filament")
    # --- print settings: the kit's time and filament are for these (sliced, or estimated without a slicer)
    material: str = param("PLA", "", "filament", choices=("PLA", "PETG", "ABS", "ASA"))
    filament_d_mm: float = param(1.75, "mm", "filament diameter", choices=(1.75, 2.85))
    perimeters: int = param(3, "", "perimeters (walls) round every layer: pins and bosses are mostly wall",
                            min=1, max=10, why="a 4 mm pin is all wall at 3")
    infill_percent: float = param(15.0, "%", "infill density", min=0.0, max=100.0, why="solid")
    top_layers: int = param(5, "", "solid top layers", min=0, max=30, why="6 mm of 0.2 mm layers")
    bottom_layers: int = param(4, "", "solid bottom layers", min=0, max=30, why="6 mm of 0.2 mm layers")
    nozzle_temp_c: float = param(210.0, "°C", "nozzle temperature (PLA 200 ... 220)", min=150.0, max=320.0,
                                 why="the hottest common hot ends")
    bed_temp_c: float = param(60.0, "°C", "bed temperature (PLA 55 ... 65)", min=0.0, max=130.0,
                              why="the hottest common beds")

    @property
    def line_width(self) -> float:
        return self.line_width_mm or self.nozzle_mm

    @property
    def min_feature_mm(self) -> float:
        """Least wall, tip land or web: two line widths."""
        return 2.0 * self.line_width

    @property
    def bed(self) -> tuple[float, float, float]:
        return (self.bed_x_mm, self.bed_y_mm, self.bed_z_mm)

    @property
    def label(self) -> str:
        """The printer as the report names it."""
        return f"{self.title or self.name} ({self.bed_x_mm:g} × {self.bed_y_mm:g} × {self.bed_z_mm:g} mm)"

    @property
    def settings_text(self) -> str:
        """The print settings as a maker sets them in the slicer."""
        return (f"{self.material} {self.filament_d_mm:g} mm, nozzle {self.nozzle_mm:g} mm at {self.nozzle_temp_c:g} °C, "
                f"bed {self.bed_temp_c:g} °C, layer {self.layer_mm:g} mm, {self.perimeters} perimeters, "
                f"{self.top_layers} top / {self.bottom_layers} bottom layers, {self.infill_percent:g} % infill, "
                f"no supports")

    def skirt(self) -> tuple[int, float]:
        """(loops, distance mm) of the skirt the plates' settings ask for: PrusaSlicer's default skirt
        (policy.SLICER_SKIRTS, SLICER_SKIRT_DISTANCE_MM) when the margin holds it with its line and the room
        beyond; else one brought in to fit, or none (0, 0) when not even 1 mm does."""
        room = self.margin_mm - policy.SLICER_BRIM_MM - policy.SLICER_SKIRTS * policy.SLICER_FIRST_LAYER_LINE_MM \
            - policy.SLICER_EDGE_ROOM_MM
        if room >= policy.SLICER_SKIRT_DISTANCE_MM:
            return policy.SLICER_SKIRTS, policy.SLICER_SKIRT_DISTANCE_MM
        return (policy.SLICER_SKIRTS, float(int(room))) if room >= 1.0 else (0, 0.0)

    def slicer_config(self) -> dict[str, str]:
        """The kit's print settings as PrusaSlicer's configuration keys and values (bed, nozzle, layers, walls,
        infill, filament, temperatures, skirt and brim): the plates carry them (``Metadata/Slic3r_PE.config``)
        and :meth:`slicer_args` gives them on the command line, so that a plate opened in the slicer prints what
        the kit's times and grams were sliced with."""
        loops, distance = self.skirt()
        return {"bed_shape": self.bed_shape(), "max_print_height": f"{self.bed_z_mm:g}",
                "nozzle_diameter": f"{self.nozzle_mm:g}", "layer_height": f"{self.layer_mm:g}",
                "perimeters": str(self.perimeters), "fill_density": f"{self.infill_percent:g}%",
                "top_solid_layers": str(self.top_layers), "bottom_solid_layers": str(self.bottom_layers),
                "filament_type": self.material, "filament_diameter": f"{self.filament_d_mm:g}",
                "filament_density": f"{self.density_g_cm3:g}", "temperature": f"{self.nozzle_temp_c:g}",
                "first_layer_temperature": f"{self.nozzle_temp_c + 5:g}", "bed_temperature": f"{self.bed_temp_c:g}",
                "first_layer_bed_temperature": f"{self.bed_temp_c:g}", "support_material": "0",
                "skirts": str(loops), "skirt_distance": f"{distance:g}", "brim_width": f"{policy.SLICER_BRIM_MM:g}"}

    def slicer_args(self) -> list[str]:
        """PrusaSlicer's command-line options for these settings (:meth:`slicer_config`)."""
        out = []
        for key, value in self.slicer_config().items():
            flag = key.replace("_", "-")
            if key in _SLICER_SWITCHES:  # an on/off option is a flag of its own: --support-material, --no-...
                out.append(f"--{flag}" if value == "1" else f"--no-{flag}")
            else:
                out += [f"--{flag}", value]
        return out

    def bed_shape(self) -> str:
        """The bed as PrusaSlicer's --bed-shape: corners x,y in mm."""
        x, y = self.bed_x_mm, self.bed_y_mm
        return f"0x0,{x:g}x0,{x:g}x{y:g},0x{y:g}"


#: PrusaSlicer's on/off options among :meth:`Printer.slicer_config`'s keys
_SLICER_SWITCHES = frozenset({"support_material"})

#: keys a user's profile file must give (a bed of unknown size is no printer)
REQUIRED_IN_FILE = ("bed_x_mm", "bed_y_mm", "bed_z_mm")


def printer_names() -> list[str]:
    folder = resources.files(__package__).joinpath("printers")
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def is_profile_path(name: str) -> bool:
    """`--printer` names a file (a path or a .toml name), not a built-in profile."""
    return name.endswith(".toml") or os.sep in name or "/" in name


def _read_profile_file(path: str) -> dict:
    """The TOML table of a user's profile file (InputError on --printer naming why not)."""
    from ..params import read_part_toml

    if not os.path.lexists(path):
        raise InputError("--printer", path, "no such profile file (a built-in name, or the path of your profile)")
    try:
        data = read_part_toml(path)
    except InputError as exc:
        raise InputError("--printer", path, exc.limit.replace("a part file is", "a printer profile is")) from None
    missing = [k for k in REQUIRED_IN_FILE if k not in data]
    if missing:
        raise InputError(f"printer.{missing[0]}", "missing", f"a printer profile gives its bed size in mm "
                         f"({', '.join(REQUIRED_IN_FILE)}) in {path}")
    data.setdefault("name", Path(path).stem)
    data.setdefault("title", f"{data['name']} (profile {Path(path).name})")
    return data


def parse_bed(text: str) -> dict:
    """'180x180x180' (or 180×180×180, 180x180 with the height = the width): the bed keys of a quick
    profile; InputError naming --bed otherwise."""
    from ..numbers import parse

    parts = re.split(r"\s*[x×X*]\s*", text.strip()) if isinstance(text, str) else []
    if len(parts) not in (2, 3):
        raise InputError("--bed", text, "must be WIDTHxDEPTHxHEIGHT in mm, e.g. 180x180x180")
    try:
        vals = [float(parse(v, "--bed")) for v in parts]
    except InputError:
        raise InputError("--bed", text, "must be WIDTHxDEPTHxHEIGHT in mm in plain digits, e.g. 180x180x180") from None
    if len(vals) == 2:
        vals.append(min(vals))
    x, y, z = vals
    return {"name": f"bed_{x:g}x{y:g}x{z:g}", "title": f"your printer (--bed {x:g}x{y:g}x{z:g}), 0.4 mm nozzle",
            "bed_x_mm": x, "bed_y_mm": y, "bed_z_mm": z}


def load_printer(name: str, overrides: dict | None = None, bed: str | None = None) -> Printer:
    """The profile `name` (a built-in name or a profile file's path) with `overrides` (validated;
    InputError naming the key); `bed`: a quick profile from --bed WxDxH instead."""
    import tomllib

    if bed is not None:
        data = parse_bed(bed)
    elif is_profile_path(name):
        data = _read_profile_file(name)
    elif name not in printer_names():
        raise InputError("--printer", name, f"unknown printer (built in: {', '.join(printer_names())}; or the path "
                         f"of your own profile, e.g. my_printer.toml with bed_x_mm, bed_y_mm, bed_z_mm; or --bed "
                         f"180x180x180)")
    else:
        text = resources.files(__package__).joinpath("printers").joinpath(f"{name}.toml").read_text(encoding="utf-8")
        data = tomllib.loads(text)
    for key, value in (overrides or {}).items():
        if key in ("name", "title"):
            raise InputError(f"print.{key}", value, "is the profile's own; choose another --printer")
        data[key] = value
    known = {f.name for f in dataclasses.fields(Printer)}
    unknown = sorted(set(data) - known)
    if unknown:
        settable = sorted(known - {"name", "title"})
        table = "print" if unknown[0] in (overrides or {}) else "printer"
        raise InputError(f"{table}.{unknown[0]}", data[unknown[0]], f"unknown printer setting (known: "
                         f"{', '.join(settable)})",
                         did_you_mean(unknown[0], settable) or "propulsor params printer lists them")
    # a key is named where the user wrote it: the part file's [print] table, or the printer's profile
    where = {k: ("print" if k in (overrides or {}) else "printer") for k in data}
    for key in ("bed_x_mm", "bed_y_mm", "bed_z_mm", "margin_mm"):
        if key in data:
            _named(key, data[key], where[key])
    try:
        return load_params(Printer, data)
    except InputError as exc:
        if exc.parameter in known:
            raise InputError(f"{where.get(exc.parameter, 'printer')}.{exc.parameter}", exc.value, exc.limit,
                             exc.hint) from None
        raise


def _named(key: str, value, table: str = "printer") -> None:
    """A bed size that is not a positive number: InputError naming the key (in `table`: "print" for the part file's
    [print] table, "printer" for the profile) before the limits do."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{table}.{key}", value, "must be a number of mm")
    if not value > 0 and key.startswith("bed_"):
        raise InputError(f"{table}.{key}", value, "must be a positive size in mm")
