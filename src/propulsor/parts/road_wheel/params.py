"""Parameters of the road wheel (seed 004 ch. 5 and 7)."""

from __future__ import annotations

from dataclasses import dataclass

from ...errors import InputError
from ...params import PartParams, param

__all__ = ["RoadWheelParams"]

_WHY_HUB = "the hub of a 2 m wheel"
_WHY_BEARING = "the largest rolling bearings a road wheel takes (ISO 15: d <= 1000 mm)"


@dataclass(frozen=True)
class RoadWheelParams(PartParams):
    """Parameters of the double road wheel with solid rubber tyres."""

    tyre_radius_mm: float = param(315.0, "mm", "outer (rolling) radius of the tyres R (seed 004 ch. 5: D_k = 630)",
                                  min=100.0, max=1000.0, why="a 2 m road wheel is larger than any tracked vehicle's")
    rows: int = param(2, "", "tyre rows (seed 004 ch. 5: double)", choices=[1, 2])
    tyre_width_mm: float = param(90.0, "mm", "tyre width b per row", min=10.0, max=400.0, why="the widest solid tyres of heavy road wheels")
    tyre_thickness_mm: float = param(40.0, "mm", "rubber thickness H", min=5.0, max=200.0, why="solid rubber over 200 mm overheats at any speed (seed 004 eq. 76)")
    row_gap_mm: float = param(80.0, "mm", "gap between the rows (the track's guide horns run in it)", min=0.0, max=400.0, why="the guide horns of the widest tracks")
    row_offset_mm: float = param(5.0, "mm", "inboard face of the inner row from the hub's inboard face",
                                 min=-200.0, max=200.0, why="as far as the widest tyre")
    rim_thickness_mm: float = param(12.0, "mm", "radial thickness of the steel rim", min=3.0, max=60.0, why="a fifth of the largest tyre radius")
    web_thickness_mm: float = param(16.0, "mm", "thickness of each disc web", min=4.0, max=60.0, why="a fifth of the largest tyre radius")
    hub_outer_d_mm: float = param(210.0, "mm", "outside diameter of the hub tube", min=20.0, max=1000.0, why=_WHY_HUB)
    hub_length_mm: float = param(230.0, "mm", "length of the hub tube", min=20.0, max=1000.0, why=_WHY_HUB)
    hub_relief_d_mm: float = param(124.0, "mm", "hub bore between the bearing seats (leaves the shoulders)", min=10.0, max=1000.0, why=_WHY_HUB)
    bearing_inner_d_mm: float = param(100.0, "mm", "inboard bearing bore d (= balancer spindle seat)", min=10.0, max=1000.0, why=_WHY_BEARING)
    bearing_inner_D_mm: float = param(180.0, "mm", "inboard bearing outside diameter D (= hub seat)", min=15.0, max=1000.0, why=_WHY_BEARING)
    bearing_inner_B_mm: float = param(46.0, "mm", "inboard bearing width B", min=5.0, max=500.0, why=_WHY_BEARING)
    bearing_outer_d_mm: float = param(80.0, "mm", "outboard bearing bore d (= balancer spindle seat)", min=10.0, max=1000.0, why=_WHY_BEARING)
    bearing_outer_D_mm: float = param(140.0, "mm", "outboard bearing outside diameter D (= hub seat)", min=15.0, max=1000.0, why=_WHY_BEARING)
    bearing_outer_B_mm: float = param(35.0, "mm", "outboard bearing width B", min=5.0, max=500.0, why=_WHY_BEARING)
    lightening_holes: int = param(6, "", "lightening holes per web (0: none)", min=0, max=24, integer=True, why="one hole every 15°")
    lightening_hole_d_mm: float = param(60.0, "mm", "lightening hole diameter", min=5.0, max=1000.0, why="half the largest wheel")
    # Kozlov (seed 004 eq. 76-80)
    load_N: float = param(31490.0, "N", "wheel load P (seed 004 eq. 3: P_st), shared equally by the rows",
                          min=0.0, min_exclusive=True, max=1e7, why="1000 t on one wheel")
    E_rubber_MPa: float = param(6.0, "MPa", "rubber compression modulus E_p (eq. 80)", min=0.1, max=200.0, why="hard polyurethane; rubber is 2 ... 20 MPa")
    psi: float = param(0.35, "", "internal friction of the rubber ψ (eq. 77; seed: 0.25 ... 0.5)",
                       min=0.0, max=1.0, min_exclusive=True, max_exclusive=True, why="a loss factor is below 1")
    alpha_W_m2K: float = param(60.0, "W/(m^2 K)", "heat transfer rubber -> air α (eq. 76)", min=0.1, max=1000.0, why="forced-air heat transfer stays below it")
    t_air_C: float = param(20.0, "°C", "air temperature t_в (eq. 76; seed Table 12: 20)", min=-60.0, max=60.0, why="the climatic range of vehicle standards")
    V_max_kmh: float = param(50.0, "km/h", "largest vehicle speed (seed 004 ch. 5: 50)", min=1.0, max=200.0, why="faster than any tracked vehicle")
    track_pitch_m: float = param(0.15, "m", "track link pitch t for ω = 2πV/t (seed Table 12: 0.15)",
                                 min=0.01, max=1.0, why="the longest track links")
    t_allow_C: float = param(120.0, "°C", "admissible steady tyre temperature (ours; the seed prints none)",
                             min=30.0, max=300.0, why="rubber decomposes past it")
    q_allow_MPa: float = param(5.0, "MPa", "admissible mean contact pressure (ours; the seed's first criterion)",
                               min=0.1, max=50.0, why="ten times the allowable pressure of solid rubber")
    rho_steel_kg_m3: float = param(7850.0, "kg/m^3", "density of the disc and rims", min=1000.0, max=20000.0, why="denser than tungsten")
    rho_rubber_kg_m3: float = param(1150.0, "kg/m^3", "density of the tyres", min=500.0, max=3000.0, why="the densest filled rubbers")

    def validate(self) -> None:
        """Kozlov's deflection against the rubber (eq. 79); whether the geometry can be made is the design's
        own question (:func:`.design.feasible`)."""
        tyre = self.tyre()
        P_row = self.load_N / self.rows
        lam = float(tyre.contact_length(P_row)) ** 2 / (8.0 * self.tyre_radius_mm)
        if not lam < self.tyre_thickness_mm:
            raise InputError("load_N", self.load_N, f"Kozlov's deflection λ_m = {lam:.4g} mm reaches the rubber "
                             f"thickness H = {self.tyre_thickness_mm:g} mm (eq. 79)")

    def tyre(self):
        from ...laws.tyre_heat import SolidTyre

        return SolidTyre(R=self.tyre_radius_mm, b=self.tyre_width_mm, H=self.tyre_thickness_mm,
                         E=self.E_rubber_MPa, alpha=self.alpha_W_m2K, psi=self.psi)
