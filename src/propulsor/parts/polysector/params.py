"""Parameters of the composite (polysector) gear and its solid mate (seed 003)."""

from __future__ import annotations

from dataclasses import dataclass

from ...params import PartParams, param

__all__ = ["PolysectorParams"]

_WHY_TEETH = "a blank of z = 300 at m = 20 is 6 m across; sectors of larger wheels are not cut from one blank"
_WHY_MM = "the largest wheel this tool builds (z = 300, m = 20)"


@dataclass(frozen=True)
class PolysectorParams(PartParams):
    """Composite gear: i_s sectors of z_c teeth per flow cut from a blank (z, m), two flows (the second
    turned by half a sector pitch), set at the offsets of the positions; a solid gear z2 meshes with
    both flows."""

    module_mm: float = param(3.0, "mm", "module m of the blank, the sectors and the gear", min=0.5, max=20.0,
                             why="the largest modules of cut spur gears in adjustable drives")
    blank_teeth: int = param(36, "", "teeth z of the blank gear the sectors are cut from", min=12, max=300,
                             integer=True, why=_WHY_TEETH)
    sector_teeth: int = param(10, "", "teeth z_c of one sector (eq. 2: z/i_s − 1…3)", min=2, max=150, integer=True,
                              why="half the largest blank")
    sectors_per_flow: int = param(3, "", "sectors i_s of one flow", min=2, max=12, integer=True,
                                  why="more than 12 sectors per flow leave no room for the stems at the hub")
    flows: int = param(2, "", "flows (axial layers of sectors), the second turned by π/i_s", min=1, max=2,
                       integer=True, why="the seed's practical layout is two-flow")
    gear_teeth: int = param(40, "", "teeth z2 of the solid mating gear", min=12, max=300, integer=True, why=_WHY_TEETH)
    pressure_angle_deg: float = param(20.0, "deg", "pressure angle α of the basic rack (ISO 53)", min=14.5, max=25.0,
                                      why="the range of standard basic racks")
    conditional_teeth: list = param([36, 42, 48, 54], "", "z_усл of each position: conditional pitch circle "
                                    "r_усл = m z_усл/2, offset e = m (z_усл − z)/2; each a multiple of flows·i_s")
    tooth_thinning_mm: float = param(0.1, "mm", "tooth thickness allowance E_sn of every tooth (sectors and gear); "
                                     "normal backlash ≈ 2·E_sn·cos α", min=0.0, max=2.0,
                                     why="ten times the largest allowance of GOST 1643 at m <= 20")
    face_width_mm: float = param(12.0, "mm", "face width b of one flow's sectors (the gear spans all flows)",
                                 min=0.5, max=400.0, why="20 modules at the largest module")
    hub_thickness_mm: float = param(8.0, "mm", "thickness of one flow disc of the hub", min=0.5, max=400.0,
                                    why="20 modules at the largest module")
    rim_modules: float = param(2.5, "", "sector rim depth below the root circle, in modules", min=1.0, max=10.0,
                               why="a rim of 10 modules is a full web")
    stem_width_mm: float = param(22.0, "mm", "width of a sector's stem", min=1.0, max=2000.0, why=_WHY_MM)
    shaft_d_mm: float = param(18.0, "mm", "wheel shaft (hub bore) diameter", min=3.0, max=2000.0, why=_WHY_MM)
    keyways: bool = param(True, "", "DIN 6885-1 keyways in the hub bore and the gear bore")
    gear_bore_mm: float = param(20.0, "mm", "bore of the solid gear", min=3.0, max=2000.0, why=_WHY_MM)
    bolt_d_mm: float = param(5.5, "mm", "clamping bolt hole / slot width (M5: 5.5)", min=1.0, max=100.0,
                             why="M100 is past any sector clamp")
    pin_d_mm: float = param(4.0, "mm", "locating pin hole diameter", min=1.0, max=100.0, why="as the bolts")
    web_mm: float = param(2.0, "mm", "least material around every hole and between hole and edge", min=0.5,
                          max=100.0, why="as the bolts")
    proof_steps_per_pitch: int = param(6, "", "proof steps per conditional pitch over one sector period",
                                       min=4, max=200, integer=True, why="200 steps resolve 0.1 µm of flank")
    friction_coefficient: float = param(0.06, "", "friction coefficient f_з in the mesh (eq. 12–14)", min=0.0,
                                        max=0.5, why="dry steel on steel")
    # dynamics (eq. 9-11)
    speed_rpm: float = param(300.0, "rpm", "speed of the driving shaft (composite wheel), q1 = ω0 t", min=1.0,
                             max=10000.0, why="past the speeds of such adjustable drives")
    J1_kgm2: float = param(0.01, "kg·m²", "inertia J1 of the driving shaft with the composite wheel", min=1e-6, max=1e3,
                           why="a 2 t flywheel")
    J2_kgm2: float = param(0.002, "kg·m²", "inertia J2 of the solid gear", min=1e-6, max=1e3, why="as J1")
    J3_kgm2: float = param(0.002, "kg·m²", "inertia J3 of the intermediate wheel 3", min=1e-6, max=1e3, why="as J1")
    J4_kgm2: float = param(0.005, "kg·m²", "inertia J4 of wheel 4", min=1e-6, max=1e3, why="as J1")
    J5_kgm2: float = param(0.02, "kg·m²", "inertia J5 of the driven machine", min=1e-6, max=1e3, why="as J1")
    i54: float = param(1.0, "", "ratio i54 of the last stage (φ5 = φ4 i54)", min=0.01, max=100.0, why="one stage")
    c1_Nm_per_rad: float = param(2.0e4, "N·m/rad", "torsional stiffness c1 between wheels 2 and 3", min=1.0,
                                 max=1e9, why="a solid steel shaft of 200 mm")
    c2_Nm_per_rad: float = param(2.0e4, "N·m/rad", "torsional stiffness c2 between wheels 3 and 4", min=1.0,
                                 max=1e9, why="as c1")
    damping_ratio: float = param(0.05, "", "modal damping ratio of the elastic links (R1, R2)", min=0.0, max=1.0,
                                 why="critical damping")
    load_torque_Nm: float = param(20.0, "N·m", "resisting torque M4 on wheel 4", min=0.0, max=1e6, why="a 1 MN·m drive")

    def validate(self) -> None:
        """Nothing between fields to check here: the synthesis (eq. 1-4) refuses positions that cannot be made
        (:func:`.design.feasible`, run by the dry run and the Python API after this)."""
