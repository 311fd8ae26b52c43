"""The gear materials of the load per tooth: a small catalogue as data (``gears/data/gear_materials.toml``, which
names the source, the basis and the uncertainty of every value) and the life factors of their limits.

Life factors (the limit at N_L load cycles over the endurance limit):

* ``iso6336_case`` — case-hardened steel: Z_NT of ISO 6336-2:2006 Table 2 (1.6 up to 1e5, 1.0 at 5e7, 0.85 at 1e10),
  Y_NT of ISO 6336-3:2006 Table 3 (2.5 up to 1e3, 1.0 at 3e6, 0.85 at 1e10): :mod:`.iso6336_life`'s ``z_nt``, ``y_nt``.
* ``iso6336_through`` — through-hardened steel (V): the same Z_NT (no pitting permitted), Y_NT of ISO 6336-3:2006
  Table 3 for V, GGG, GTS: 2.5 up to 1e4, (3e6/N_L)^0.159 to 3e6, (3e6/N_L)^0.02 to 1e10, 0.85 beyond.
* ``static`` — printed polymers: the limits are static strengths (no fatigue line is known): factor 1 at any N_L
  (the check is then a static check, and the report says so).
mm, MPa.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

from ..errors import InputError

__all__ = ["GearMaterial", "materials", "material", "z_nt_of", "y_nt_of"]

LIVES = ("iso6336_case", "iso6336_through", "static")


@dataclass(frozen=True)
class GearMaterial:
    name: str
    title: str
    E_MPa: float
    nu: float
    sigma_Hlim_MPa: float   #: flank limit σ_Hlim (steels: ISO 6336-5; printed: 1.67 σ_y)
    sigma_FE_MPa: float     #: root limit σ_FE = σ_Flim·Y_ST (allowable nominal root stress at the endurance point)
    life: str
    basis: str
    orientation: str
    source: str
    uncertainty: str

    @property
    def iso(self):
        """The material as :class:`propulsor.gears.iso6336.Material` (E, ν) for Z_E."""
        from .iso6336 import Material

        return Material(self.E_MPa, self.nu)

    @property
    def static(self) -> bool:
        return self.life == "static"


@lru_cache(maxsize=1)
def materials() -> dict[str, GearMaterial]:
    """The catalogue, by name (read once)."""
    import tomllib
    from importlib import resources

    text = resources.files(__package__).joinpath("data").joinpath("gear_materials.toml").read_text(encoding="utf-8")
    out = {}
    for name, row in tomllib.loads(text).items():
        m = GearMaterial(name=name, **row)
        if m.life not in LIVES:  # pragma: no cover - the shipped catalogue is tested
            raise ValueError(f"gear_materials.toml: {name}: life {m.life!r} is not one of {LIVES}")
        out[name] = m
    return out


def material(name: str, key: str = "gear_material") -> GearMaterial:
    """The catalogue entry ``name``; an InputError naming ``key`` and the known names otherwise."""
    cat = materials()
    if name not in cat:
        raise InputError(key, name, f"is not in the gear material catalogue ({', '.join(cat)})")
    return cat[name]


def z_nt_of(m: GearMaterial, N_L: float | None) -> float:
    """Pitting life factor Z_NT of the material at N_L cycles (None: the endurance point, 1)."""
    if N_L is None or m.static:
        return 1.0
    from .iso6336_life import z_nt

    return z_nt(N_L)


def y_nt_of(m: GearMaterial, N_L: float | None) -> float:
    """Root life factor Y_NT of the material at N_L cycles (None: the endurance point, 1)."""
    if N_L is None or m.static:
        return 1.0
    if m.life == "iso6336_case":
        from .iso6336_life import y_nt

        return y_nt(N_L)
    N = float(N_L)
    if N <= 1e4:
        return 2.5
    if N <= 3e6:
        return (3e6 / N) ** (math.log(2.5) / math.log(3e6 / 1e4))   # 0.159: 2.5 at 1e4, 1.0 at 3e6
    if N <= 1e10:
        return (3e6 / N) ** 0.02
    return (3e6 / 1e10) ** 0.02
