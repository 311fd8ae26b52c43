"""Parameters of the planetary final drive (seed 004 ch. 4)."""

from __future__ import annotations

from dataclasses import dataclass

from ... import policy
from ...params import PartParams, param

__all__ = ["FinalDriveParams"]

_WHY_MODULE = "the largest modules of GOST 9563 / ISO 54 series 1"
_WHY_TEETH = "a z = 300 gear at m = 50 is 15 m across"
_WHY_SHIFT = "past it the tooth turns pointed or the rack undercuts the root at any z"
_WHY_WIDTH = "b = 20 modules at the largest common module: wider faces carry no more (ISO 6336 K_Hβ)"
_WHY_DIAMETER = "the reference diameter of the largest gear (z = 300, m = 50)"


@dataclass(frozen=True)
class FinalDriveParams(PartParams):
    """Parameters of the planetary final drive (ring fixed, sun in, carrier out)."""

    module_mm: float = param(10.0, "mm", "module m", min=0.5, max=50.0, why=_WHY_MODULE)
    z_sun: int = param(16, "", "sun teeth z1", min=7, max=300, integer=True, why=_WHY_TEETH)
    z_planet: int = param(20, "", "planet teeth z2", min=7, max=300, integer=True, why=_WHY_TEETH)
    z_ring: int = param(56, "", "ring teeth z3", min=12, max=600, integer=True, why="z1 + 2·z2 with both at their limit")
    x_sun: float = param(0.5, "", "sun profile shift x1", min=-1.0, max=2.0, why=_WHY_SHIFT)
    x_planet: float = param(0.5, "", "planet profile shift x2", min=-1.0, max=2.0, why=_WHY_SHIFT)
    x_ring: float = param(1.417, "", "ring profile shift x3 (GOST 19274 sign)", min=-1.0, max=3.0,
                          why="internal teeth turn pointed or the shaper undercuts them past it")
    ring_shift_for_coaxiality: bool = param(
        False, "", "replace x_ring by the shift that makes both operating centre distances equal")
    n_planets: int = param(3, "", "number of planets k", min=1, max=12, integer=True,
                           why="neighbouring planets of z2 >= 7 collide past 12 on any ring of z3 <= 600 that is built")
    shaper_z0: int = param(14, "", "teeth of the shaper cutter that cuts the ring", min=6, max=200, integer=True,
                           why="largest disc shaper cutters (GOST 9323: d0 <= 200 mm at m >= 1)")
    shaper_x0: float = param(0.04, "", "profile shift of the shaper cutter", min=-1.5, max=1.5, why=_WHY_SHIFT)
    shaper_tip_radius_star: float = param(
        0.1, "", "tip radius ρ_a0* of the shaper cutter, in modules: it rounds the ring's root (the fillet radius of "
        "the ring's substitute rack in ISO 6336-3)", min=0.02, max=0.5,
        why="half a module is past any shaper tooth's tip land (a narrower tooth refuses less: its rounds must not meet)")
    width_sun_mm: float = param(80.0, "mm", "face width of the sun", min=0, min_exclusive=True, max=1000.0, why=_WHY_WIDTH)
    width_planet_mm: float = param(75.0, "mm", "face width of a planet", min=0, min_exclusive=True, max=1000.0, why=_WHY_WIDTH)
    width_ring_mm: float = param(80.0, "mm", "face width of the ring", min=0, min_exclusive=True, max=1000.0, why=_WHY_WIDTH)
    tooth_thinning_mm: float = param(
        0.15, "mm", "tooth thickness allowance E_sn of every gear (ring: space widening); "
        "normal backlash of a mesh ≈ 2·E_sn·cos α", min=0.0, max=2.0,
        why="ten times the largest allowance of GOST 1643 at m <= 50")
    sun_bore_mm: float = param(80.0, "mm", "sun bore diameter (0: no bore)", min=0.0, max=15000.0, why=_WHY_DIAMETER)
    sun_keyway: bool = param(True, "", "DIN 6885-1 keyway in the sun bore")
    planet_bore_mm: float = param(110.0, "mm", "planet bore (bearing seat) diameter (0: no bore)", min=0.0, max=15000.0,
                                 why=_WHY_DIAMETER)
    ring_outer_d_mm: float = param(0.0, "mm", "ring outside diameter (0: root diameter + 8 modules)", min=0.0, max=40000.0,
                                  why="a ring of z3 = 600, m = 50 and a rim of 100 modules")
    ring_bolts: int = param(12, "", "mounting holes in the ring rim (0: none)", min=0, max=72, integer=True,
                            why="a bolt every 5°, the densest flange pattern in use")
    ring_bolt_d_mm: float = param(18.0, "mm", "mounting hole diameter", min=0, min_exclusive=True, max=200.0,
                                 why="M180 bolts are the largest in ISO 262")
    # --- load and strength (seed 004 ch. 4.1-4.3, ISO 6336) -------------------------------------------
    sprocket_torque_Nm: float = param(90687.503, "N·m", "design torque of the carrier (sprocket) M_vk.max; seed 004 "
                                      "eq. 40 with t = 0.125 m (the printed 90 690)", min=0, min_exclusive=True,
                                      max=1e7, why="ten times the torque of the heaviest tracked vehicle drives")
    load_share_Omega: float = param(1.09, "", "load-sharing factor Ω between the planets (seed 004 eq. 42)",
                                    min=1.0, max=2.0, why="one planet of two carrying everything")
    power_ratio_i_sil: float = param(4.413, "", "power ratio i_sil = 1 + p·η_ext·η_int (seed 004 eq. 41); "
                                     "sun torque = M_vk.max·Ω/i_sil", min=1.0, max=50.0,
                                     why="the largest single-stage planetary ratios")
    design_speed_kmh: float = param(7.852, "km/h", "vehicle speed at the design torque (seed 004 eq. 65, V_min)",
                                    min=0.0, max=200.0, why="faster than any tracked vehicle")
    sprocket_teeth: int = param(15, "", "sprocket teeth z (seed 004 eq. 40)", min=6, max=60, integer=True,
                                why="track sprockets have 9 ... 30 teeth")
    track_pitch_mm: float = param(125.0, "mm", "track pitch t (seed 004 eq. 45)", min=20.0, max=500.0,
                                  why="the pitch of any track link")
    application_factor_K_A: float = param(1.0, "", "application factor K_A (1: the design torque is already the "
                                          "largest, adhesion-limited one)", min=1.0, max=3.0,
                                          why="ISO 6336-1 Table A.1 tops out at 2.25")
    accuracy_grade: int = param(6, "", "ISO 1328 accuracy grade of the gears", min=3, max=8, integer=True,
                                why="ISO 6336-1 Table 9 (K_Hα) is used for grades 3 ... 8")
    flank_hardness_HRC: float = param(59.0, "HRC", "flank hardness (seed 004 ch. 4.1: σ_Hmax = 44·HRC)",
                                      min=20.0, max=68.0, why="the range of hardened gear steels")
    core_yield_MPa: float = param(785.0, "MPa", "σ_t of the gear steel (seed 004 ch. 4.1: σ_FlimM = 2.8·σ_t)",
                                  min=100.0, max=2500.0, why="the range of gear steels")
    bending_safety_S_Fm: float = param(1.75, "", "required bending safety S_Fm (seed 004 ch. 4.1)",
                                       min=1.0, max=5.0, why="no code asks more")
    contact_safety_S_Hmin: float = param(1.0, "", "required static contact safety against σ_Hmax = 44·HRC",
                                         min=1.0, max=5.0, why="no code asks more")
    # --- fatigue (ISO 6336-2/-3/-5); seed 004 prints no duty, no oil and no roughness: stated defaults ------
    service_life_h: float = param(100.0, "h", "running time at the design torque and speed that the gears must "
                                  "endure (load cycles of each gear follow from its speed relative to the carrier; "
                                  "seed 004 prints no duty)", min=0, min_exclusive=True, max=200000.0,
                                  why="23 years of running day and night")
    sigma_Hlim_MPa: float = param(1500.0, "MPa", "pitting endurance limit σ_Hlim of the flank (seed 004: carburized "
                                  "18Х2Н4МА at 59 HRC; ISO 6336-5:2003, case-hardened wrought steel, quality MQ: "
                                  "1500; ML 1300, ME 1650)",
                                  min=200.0, max=2000.0, why="above ISO 6336-5's best case-hardened steel (ME 1650)")
    sigma_Flim_MPa: float = param(425.0, "MPa", "bending endurance limit σ_Flim of the root (carburized 18Х2Н4МА; "
                                  "ISO 6336-5:2003, case-hardened wrought steel, quality MQ, core hardness >= 25 HRC: "
                                  "425; ML 312, ME 525)",
                                  min=100.0, max=800.0, why="above ISO 6336-5's best case-hardened steel (ME 525)")
    flank_roughness_Rz_um: float = param(3.0, "µm", "mean peak-to-valley roughness R_z of the flanks (ground)",
                                         min=0.1, max=40.0, why="a rough hobbed flank")
    root_roughness_Rz_um: float = param(10.0, "µm", "mean peak-to-valley roughness R_z of the tooth root (hobbed, "
                                        "not ground)", min=0.1, max=40.0,
                                        why="the range of ISO 6336-3's surface factor Y_RrelT")
    oil_viscosity_40_mm2_s: float = param(220.0, "mm²/s", "kinematic viscosity ν_40 of the gear oil at 40 °C "
                                          "(ISO VG 220)", min=10.0, max=3200.0, why="ISO VG 3200, the thickest grade")
    pitting_safety_S_Hmin: float = param(1.0, "", "required pitting fatigue safety S_Hmin (ISO 6336-2)",
                                         min=1.0, max=5.0, why="no code asks more")
    bending_fatigue_safety_S_Fmin: float = param(1.4, "", "required bending fatigue safety S_Fmin (ISO 6336-3)",
                                                 min=1.0, max=5.0, why="no code asks more")
    sweep_steps_per_deg: float = param(float(policy.PLANETARY_SWEEP_STEPS_PER_DEG), "1/deg",
                                       "interference sweep steps per degree of carrier turn",
                                       min=float(policy.PLANETARY_SWEEP_STEPS_PER_DEG), max=20.0,
                                       why="0.05° steps resolve every clearance the outlines hold")

    def validate(self) -> None:
        """Nothing between fields to check here: whether the set can be made is the design's own question
        (:func:`.design.feasible`, run by the dry run and the Python API after this)."""
