"""Printer profiles for print kits: bed, nozzle, layer and the FDM allowances, as data.

Profiles live as TOML files in ``printers/`` beside this module (``generic``, ``prusa_mk4``,
``bambu_x1``); every allowance has a default from common desktop-FDM practice (0.4 mm nozzle,
0.2 mm layers) and may be overridden by name.  The values are validated like part parameters.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from importlib import resources

from ..errors import InputError
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
                                     "0.1 ... 0.2), added to every hole", min=0.0, max=1.0, why=_WHY_FIT)
    chamfer_mm: float = param(0.4, "mm", "chamfer of bed-side edges against the first layers' spread "
                              "(elephant's foot; 0.3 ... 0.5)", min=0.0, max=2.0, why="five layers")
    min_module_mm: float = param(1.0, "mm", "least printable module (smaller teeth are mush)", min=0.2, max=10.0,
                                 why="any printer prints module 10")
    piece_gap_mm: float = param(5.0, "mm", "gap between pieces on a plate", min=1.0, max=50.0,
                                why="a tenth of the smallest bed")
    density_g_cm3: float = param(1.24, "g/cm^3", "filament density (PLA: 1.24)", min=0.5, max=3.0,
                                 why="past any filament")

    @property
    def line_width(self) -> float:
        return self.line_width_mm or self.nozzle_mm

    @property
    def min_feature_mm(self) -> float:
        """Least wall, tip land or web: two line widths."""
        return 2.0 * self.line_width

    def bed_shape(self) -> str:
        """The bed as PrusaSlicer's --bed-shape: corners x,y in mm."""
        x, y = self.bed_x_mm, self.bed_y_mm
        return f"0x0,{x:g}x0,{x:g}x{y:g},0x{y:g}"


def printer_names() -> list[str]:
    folder = resources.files(__package__).joinpath("printers")
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def load_printer(name: str, overrides: dict | None = None) -> Printer:
    """The profile called `name` with `overrides` (validated; InputError naming the key)."""
    import tomllib

    if name not in printer_names():
        raise InputError("--printer", name, f"unknown printer (known: {', '.join(printer_names())})")
    text = resources.files(__package__).joinpath("printers").joinpath(f"{name}.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    for key, value in (overrides or {}).items():
        if key in ("name", "title"):
            raise InputError(f"print.{key}", value, "is the profile's own; choose another --printer")
        data[key] = value
    known = {f.name for f in dataclasses.fields(Printer)}
    unknown = sorted(set(data) - known)
    if unknown:
        raise InputError(f"print.{unknown[0]}", data[unknown[0]], f"unknown printer setting (known: "
                         f"{', '.join(sorted(known - {'name', 'title'}))})")
    return load_params(Printer, data)
