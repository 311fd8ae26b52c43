"""Catalogue of generating cutters a workshop can buy: ISO 53 racks A-D and GOST 9323 / DIN 1825
shaper cutters (data: ``gears/data/cutters.toml``, which cites its tables).

Pure math layer (stdlib + the cutter types).  A design names a cutter by its catalogue key: the
rack profile ``"A"`` .. ``"D"``, the shaper by its nominal pitch diameter d0 (25, 38, 50, 75,
100 mm) at the gear's module; the shaper keeps its own profile shift x0 (the gear's shift comes
from the cutting position, ``gears.noncircular_teeth.ToothSpec.shaper``).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from ..errors import InputError
from .cutters import ShaperCutter, shaper_rack
from .involute import BasicRack

__all__ = ["ShaperEntry", "rack_profile", "rack_profiles", "shaper_diameters", "shaper_entry", "catalogue_shaper"]


@lru_cache(maxsize=1)
def _data() -> dict:
    text = resources.files(__package__).joinpath("data").joinpath("cutters.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


def rack_profiles() -> tuple[str, ...]:
    """Keys of the ISO 53 rack profiles ("A", "B", "C", "D")."""
    return tuple(sorted(_data()["rack"]))


def rack_profile(name: str, alpha: float | None = None) -> BasicRack:
    """The ISO 53 basic rack of profile ``name`` (ISO 53:1998 Table 1); ``alpha`` (rad) overrides the
    catalogue's 20 deg for special racks."""
    racks = _data()["rack"]
    if name not in racks:
        raise InputError("rack_profile", name, f"must be one of {', '.join(sorted(racks))} (ISO 53:1998)")
    r = racks[name]
    return BasicRack(alpha=math.radians(r["alpha_deg"]) if alpha is None else alpha, h_a_star=r["h_a_star"],
                     c_star=r["c_star"], rho_f_star=r["rho_f_star"])


def shaper_diameters() -> tuple[float, ...]:
    """Nominal pitch diameters d0 (mm) of the catalogue's shapers, ascending."""
    return tuple(sorted(v["d0_mm"] for v in _data()["shaper"].values()))


@dataclass(frozen=True)
class ShaperEntry:
    """One catalogue shaper: nominal d0 (mm), module m (mm), z0, x0, h_a0*, rho_a0*, the standard."""

    d0_mm: float
    m: float
    z0: int
    x0: float
    h_a0_star: float
    rho_a0_star: float
    standard: str
    source: str

    @property
    def name(self) -> str:
        return f"d0 {self.d0_mm:g} m {self.m:g} z0 {self.z0} x0 {self.x0:+g} ({self.standard})"

    def cutter(self, alpha: float = math.radians(20.0)) -> ShaperCutter:
        """The shaper as a generating tool (tip d_a0 = m(z0 + 2(h_a0* + x0)), tip round rho_a0* m)."""
        return ShaperCutter(self.z0, self.m, self.x0, shaper_rack(alpha, 1.0, self.h_a0_star - 1.0), self.rho_a0_star)


def _module_key(m: float) -> str:
    return f"{m:g}"


def shaper_entry(d0_mm: float, m: float) -> ShaperEntry:
    """The catalogue shaper of nominal pitch diameter d0 at module m; InputError naming ``d0`` (the
    nominal diameters, or the modules listed for d0) when there is none."""
    shapers = _data()["shaper"]
    for v in shapers.values():
        if abs(v["d0_mm"] - d0_mm) < 1e-9:
            z = v["z0"].get(_module_key(m))
            if z is None:
                raise InputError("d0", d0_mm, f"the catalogue lists no shaper d0 = {d0_mm:g} mm at m = {m:g} mm",
                                 f"modules listed: {', '.join(sorted(v['z0'], key=float))}")
            return ShaperEntry(float(v["d0_mm"]), float(m), int(z), float(v["x0"]), float(v["h_a0_star"]),
                               float(v["rho_a0_star"]), v["standard"], v.get("source", "catalogue"))
    raise InputError("d0", d0_mm, "is not a nominal shaper diameter of the catalogue",
                     f"nominal d0: {', '.join(f'{d:g}' for d in shaper_diameters())} mm")


def catalogue_shaper(d0_mm: float, m: float, alpha: float = math.radians(20.0)) -> ShaperCutter:
    """``shaper_entry(d0_mm, m).cutter(alpha)``."""
    return shaper_entry(d0_mm, m).cutter(alpha)
