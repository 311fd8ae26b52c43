"""Parameters of the non-circular pair: the walking drive (seeds 000, 002) or another law (``law``)."""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

from ... import policy
from ...errors import InputError
from ...laws.walking import WalkingLaw
from ...params import PartParams, param

__all__ = ["METHODS", "LAWS", "LAW_KEYS", "LOAD_KEYS", "NoncircularPairParams"]

METHODS = ("generated", "sectors")
#: the drive laws a part file can name (``law = "..."``)
LAWS = ("walking", "elliptical", "fourier", "table", "pitch_curve")
#: the keys that belong to one law only: a part file of another law may not set them
LAW_KEYS = {
    "walking": ("a_mm", "b_mm", "c_mm", "blend_hand_over", "smoothing_deg"),
    "elliptical": ("eccentricity",),
    "fourier": ("fourier_cos", "fourier_sin"),
    "table": ("law_file",),
    "pitch_curve": ("pitch_curve_file",),
}


#: the load per tooth's keys (listed in a report and a manifest only when a load is given)
LOAD_KEYS = ("load_driver_torque_Nm", "load_power_W", "load_driver_speed_rpm", "load_vehicle_mass_kg",
             "load_rolling_resistance", "load_propulsors", "load_efficiency", "load_K_A", "load_K_v", "load_K_beta",
             "gear_material", "load_life_hours", "load_S_Hmin", "load_S_Fmin")


# =========================================================================== parameters
_WHY_MECHANISM = "a walking drive of 5 m hub height is larger than any built"
#: the upper limit of a pair's own lengths (centre distances, bores), law-neutral
_WHY_PAIR = "a gear pair 10 m across (bores of 5 m) is larger than any built"
#: what a bore the part file does not give is (parts/noncircular_pair/bores.py)
_SIZED_RULE = ("the largest standard shaft (ISO 775) of d <= the least root radius (a body 2 d across) whose bore "
               "and keyway stay one module inside the root")
_SIZED = f"sized from the gear: {_SIZED_RULE}; the report says which and why"


@dataclass(frozen=True)
class NoncircularPairParams(PartParams):
    """Parameters of the walking-drive pair.  Defaults: seed 002 as ``parts/ncg_seed002.toml`` builds it
    (a = 100, b = 50, c = 236.5 mm, n = 4, m = 2.5, z 20/80, the law searched for the least ripple); the bores, which
    the seed's file gives (16 / 40 mm), sized from the gear when not given."""

    #: `propulsor params` and the reference list the law and its own keys first, the walking law's a, b, c after
    #: the others' (a class attribute, not a field)
    params_order: ClassVar[tuple] = ("law", "driver_turns", "eccentricity", "fourier_cos", "fourier_sin", "law_file",
                                     "pitch_curve_file", "a_mm", "b_mm", "c_mm")

    a_mm: float = param(100.0, "mm", "walking law: hub-to-crank axis distance a (seed 000 eq. 1)", min=0.0, max=5000.0,
                        why=_WHY_MECHANISM)
    b_mm: float = param(50.0, "mm", "walking law: crank length b", min=0.0, max=5000.0, why=_WHY_MECHANISM)
    c_mm: float = param(236.5, "mm", "walking law: shoe stand length c", min=0.0, max=5000.0, why=_WHY_MECHANISM)
    law: str = param("walking", "", "drive law: walking (a_mm, b_mm, c_mm, driver_turns), elliptical "
                     "(eccentricity, driver_turns lobes of the driven wheel), fourier (fourier_cos, fourier_sin, "
                     "driver_turns), table (law_file), pitch_curve (pitch_curve_file, driver_turns driver turns per driven turn)",
                     choices=LAWS)
    driver_turns: int = param(4, "", "n: driver turns per driven (carrier) turn; walking: 1, 2 or 4; elliptical and "
                              "fourier: the driven wheel's lobes k (driver turns per driven turn); table: from the "
                              "table", min=1, max=12, integer=True,
                              why="a 12-lobe driven wheel: every lobe narrower than 30 deg")
    eccentricity: float = param(0.0, "", "elliptical law: eccentricity e of the driver ellipse, turning about a "
                                "focus", min=0.0, max=0.9, why="the driven wheel's radius L - r1 nearly vanishes")
    fourier_cos: list = param([], "rad", "fourier law: c_j of phi(theta) = theta / k + sum_j (c_j cos j theta + s_j "
                              "sin j theta), j = 1, 2, ...")
    fourier_sin: list = param([], "rad", "fourier law: s_j of the same series")
    law_file: str = param("", "", "table law: CSV with columns driver_deg,driven_deg over one period (relative to "
                          "the part file; the first row is the origin, the last closes the period)")
    pitch_curve_file: str = param("", "", "pitch_curve law: CSV with columns angle_deg,radius_mm, the driver's pitch "
                                  "curve over one turn (relative to the part file; scaled so its perimeter holds the "
                                  "teeth)")
    method: str = param("generated", "", "tooth method: generated (conjugate, default) or sectors (the papers')",
                        choices=METHODS)
    module_mm: float = param(2.5, "mm", "module m (0: from center_distance_mm, generated teeth only)", min=0.0, max=50.0,
                       why="the largest modules of GOST 9563 / ISO 54 series 1")
    driven_teeth: int = param(80, "", "z_H: driven-wheel teeth (sectors: 4 x sectors per leg)", min=4, max=480,
                              integer=True, why="a 1.5 m pitch curve at m = 1 mm (the papers use 80 and 96)")
    center_distance_mm: float = param(0.0, "mm", "L; 0: from module and teeth by closure (true arc length)", min=0.0,
                                      max=10000.0, why=_WHY_PAIR)
    pressure_angle_deg: float = param(20.0, "deg", "pressure angle of the ISO 53 rack", min=10.0, max=35.0,
                                      why="the largest pressure angle of special racks; past it the tips turn pointed")
    backlash_mm: float = param(0.16, "mm", "normal backlash j_n (seed 002: 0.16 mm)", min=0.0, max=2.0,
                               why="ten times the paper's 0.16 mm: more is a loose coupling, not a gear")
    driver_shift: float = param(0.5, "", "profile shift x of the driver (the driven wheel gets -x)", min=-1.0, max=1.5,
                                 why="past it the driver teeth turn pointed")
    shaper_teeth: int = param(20, "", "z0 of the shaper cutter for concave pitch-curve stretches", min=6, max=200,
                              integer=True, why="largest disc shaper cutters (GOST 9323: d0 <= 200 mm at m >= 1)")
    rack_profile: str = param("A", "", "ISO 53 basic rack profile of the cutting rack (A, B, C, D; ISO 53:1998 "
                              "Table 1)", choices=("A", "B", "C", "D"))
    shaper_d0_mm: float = param(0.0, "mm", "nominal pitch diameter of the catalogue shaper for concave stretches "
                                "(GOST 9323 / DIN 1825: 25, 38, 50, 75, 100; its own z0 and x0); 0: a shaper of "
                                "shaper_teeth with x0 = -x of the gear it cuts", min=0.0, max=100.0,
                                why="the largest nominal diameter of the catalogue (gears/data/cutters.toml)")
    law_search: bool = param(True, "", "search the cutters: where a pitch curve is concave, the catalogue shapers at "
                             "the module, largest first, until both gears can be cut (shaper_d0_mm and shaper_teeth "
                             "are then not used); walking law: with the blend shape (half-width and hand-over value) "
                             "for the least ripple of the driven (hub) speed under generability (gears/law_search.py; "
                             "smoothing_deg and smoothing_max_deg then not used either)")
    center_distance_band_mm: float = param(5.0, "mm", "walking law's search: largest |L - L_exact| (L_exact: "
                                           "closure of the exact law at module_mm, driven_teeth)", min=0.0, min_exclusive=True,
                                           max=100.0, why="a band of 100 mm is no longer the seed's drive")
    blend_hand_over: float = param(0.0, "", "U_s at hand-over over u: the blend's second shape parameter (closure "
                                   "by scaling U outside the windows); 0: the window-integral blend", min=0.0, max=2.0,
                                   why="twice the mean ratio at hand-over is no longer a blend of this law")
    shaper_own_x0: bool = param(False, "", "with shaper_d0_mm = 0: the shaper of shaper_teeth keeps its own shift "
                                "shaper_x0 (re-phased per flank) instead of x0 = -x of the gear")
    shaper_x0: float = param(0.0, "", "own profile shift x0 of the shaper (shaper_own_x0 = true)", min=-1.0, max=1.5,
                             why="past it the shaper's teeth turn pointed")
    smoothing_deg: float = param(0.0, "deg", "half-width of the C2 blend at hand-over; 0: smallest generable",
                                 min=0.0, max=45.0, why="one leg's support phase is 90° wide")
    smoothing_max_deg: float = param(22.5, "deg", "largest blend half-width searched", min=0.0, max=45.0,
                                     min_exclusive=True, why="one leg's support phase is 90° wide")
    tip_land_min_module: float = param(0.25, "", "least tip land (in modules); thinner tips are shortened",
                                       min=0.0, max=1.0, why="a standard tooth's tip land is about 0.6 m")
    tip_height_max_module: float = param(0.0, "", "largest tip height above the pitch curve (in modules) of the "
                                         "teeth of both wheels; 0: (1 + x) m. Where a pitch curve is concave the "
                                         "mate's long tips touch its teeth outside the line of action (tip "
                                         "interference of an internal mesh): shorten them", min=0.0, max=3.0,
                                         why="a tooth of the ISO 53 rack with the largest shift reaches 2.5 m")
    mounting_distance_mm: float = param(0.0, "mm", "installed centre distance (seed 000: L_ust = 144 for L = 143.5); "
                                        "0: the design L", min=0.0, max=10000.0, why=_WHY_PAIR)
    face_width_mm: float = param(20.0, "mm", "face width of both gears", min=0.0, min_exclusive=True, max=1000.0,
                                  why="20 modules at m = 50: wider faces carry no more (ISO 6336 K_Hβ)")
    driver_bore_mm: float = param(None, "mm", "driver bore diameter (0: none); not given: " + _SIZED, min=0.0,
                                  max=5000.0, why=_WHY_PAIR)
    driven_bore_mm: float = param(None, "mm", "driven-wheel bore diameter (0: none); not given: " + _SIZED, min=0.0,
                                  max=5000.0, why=_WHY_PAIR)
    keyway: bool = param(True, "", "keyway in each bore (DIN 6885-1 / GOST 23360-78); a sized bore takes one, or none "
                         "when no keyed bore fits")
    proof_phases_per_tooth: int = param(4, "", "phases per driven tooth in the full-cycle proof", min=4, max=64,
                                        integer=True, why="64 phases a tooth resolve contact to 1/64 of a pitch")
    as_built_ripple_margin: float = param(policy.AS_BUILT_RIPPLE_MARGIN, "", "as built: the hub speed ripple the finished outlines deliver "
                                          "(both directions) may exceed the law's by this share (0.005: half a "
                                          "point; walking law)", min=0.0, max=1.0,
                                          why="a ripple twice the mean is no longer a walking drive")
    speed_step_max: float = param(policy.AS_BUILT_SPEED_STEP_MAX, "", "as built: the largest change of the driven speed, as a share of the "
                                  "law's, across a change of the tooth pair or contact kind (an impact)",
                                  min=0.0, min_exclusive=True, max=1.0, why="a step of the whole speed is a stop")
    corner_run_max_deg: float = param(policy.AS_BUILT_CORNER_RUN_MAX_DEG, "deg", "as built: the longest run of driver angle with the load on a "
                                      "tooth's corner (tip or root) instead of its flank", min=0.0, max=360.0,
                                      why="one driver turn")
    tooth_height_min_share: float = param(policy.TOOTH_HEIGHT_MIN_SHARE, "", "least share of its addendum a tooth keeps when its tip is "
                                          "shortened (a lower one is named and fails)", min=0.0, max=1.0,
                                          why="a share of the whole addendum")
    tolerance_grade: int = param(0, "", "as made: the accuracy grade of ISO 1328 (5 ... 12) whose run-out, centre-"
                                 "distance and thickness tolerances the as-built transmission is measured within "
                                 "(worst-case corners and tolerance_samples Monte Carlo cases; a print kit uses its "
                                 "printer's accuracy instead); 0: not measured", min=0, max=12, integer=True,
                                 why="ISO 1328's coarsest grade")
    tolerance_samples: int = param(8, "", "as made: Monte Carlo cases beside the worst-case corners", min=0,
                                   max=200, integer=True, why="2-4 CPU s a case for the seed-002 pair of 80 teeth, ISO 1328 grade 8-12")
    tolerance_seed: int = param(1, "", "as made: the seed of the Monte Carlo cases (the same seed, the same cases)",
                                min=0, max=2**31 - 1, integer=True, why="a 31-bit seed")
    compare_methods: bool = param(True, "", "walking law: prove the other tooth method too (2D, one leg) and report "
                                  "the comparison (the sector method is the walking law's)")
    # --- the load per tooth (parts/noncircular_pair/tooth_load_outputs.py): off unless a load is given ---------
    load_driver_torque_Nm: float = param(0.0, "N·m", "load per tooth: the driver's torque T1 (constant; the driven "
                                         "torque follows T2 = T1·U·eta); 0: no torque load", min=0.0, max=1e6,
                                         why="the torque of a 1 MW engine at 10 rpm")
    load_power_W: float = param(0.0, "W", "load per tooth: the driver's power P at load_driver_speed_rpm (T1 = P/omega1); "
                                "0: no power load", min=0.0, max=1e8, why="a 100 MW drive")
    load_driver_speed_rpm: float = param(0.0, "rpm", "load per tooth: the driver's speed (a power load, the load "
                                         "cycles of load_life_hours)", min=0.0, max=1e5, why="a 100 000 rpm spindle")
    load_vehicle_mass_kg: float = param(0.0, "kg", "load per tooth (walking law): the vehicle's mass M; the carrier "
                                        "torque T2 = f·M·g/N_p·dX01/dphi (rolling resistance per driven propulsor, "
                                        "seed 004 eq. 40), T1 = T2/(U·eta); 0: no vehicle load", min=0.0, max=1e6,
                                        why="a 1000 t vehicle")
    load_rolling_resistance: float = param(0.08, "", "load per tooth: rolling resistance coefficient f of the ground "
                                           "(seed 004 ch. 5: 0.015 on a road, f_max = 0.08)", min=0.0, max=1.0,
                                           why="a resistance equal to the weight")
    load_propulsors: int = param(4, "", "load per tooth: driven propulsors sharing the vehicle's resistance", min=1,
                                 max=64, integer=True, why="32 wheels a side")
    load_efficiency: float = param(0.97, "", "load per tooth: efficiency eta of the mesh (T2 = T1·U·eta)", min=0.0,
                                   min_exclusive=True, max=1.0, why="no loss")
    load_K_A: float = param(1.0, "", "load per tooth: application factor K_A (ISO 6336-1 Annex A)", min=1.0, max=3.0,
                            why="ISO 6336-1 Table A.1 tops out at 2.25")
    load_K_v: float = param(1.0, "", "load per tooth: dynamic factor K_v (ISO 6336-1 cl. 6; 1 for a slow walking "
                            "drive)", min=1.0, max=3.0, why="a resonant mesh")
    load_K_beta: float = param(1.0, "", "load per tooth: face load factor K_Hbeta = K_Fbeta (ISO 6336-1 cl. 7)",
                               min=1.0, max=3.0, why="the contact on a third of the face")
    gear_material: str = param("steel_through_MQ", "", "load per tooth: the material of both gears "
                               "(gears/data/gear_materials.toml: steels of ISO 6336-5, printed PLA, PETG, nylon)",
                               choices=("steel_case_MQ", "steel_through_MQ", "PLA", "PETG", "nylon"))
    load_life_hours: float = param(0.0, "h", "load per tooth: running time at the load (load cycles of each tooth "
                                   "from load_driver_speed_rpm); 0: rated at the endurance limit", min=0.0,
                                   max=200000.0, why="23 years of running day and night")
    load_S_Hmin: float = param(1.0, "", "load per tooth: required contact safety S_H (ISO 6336-2)", min=0.5, max=5.0,
                               why="no code asks more")
    load_S_Fmin: float = param(1.4, "", "load per tooth: required root safety S_F (ISO 6336-3)", min=0.5, max=5.0,
                               why="no code asks more")

    def _validate_law_keys(self) -> None:
        """Keys of another law are refused (set to anything but their default)."""
        import dataclasses

        defaults = {f.name: (f.default if f.default is not dataclasses.MISSING else f.default_factory())
                    for f in dataclasses.fields(self)}
        for other, keys in LAW_KEYS.items():
            if other == self.law:
                continue
            for k in keys:
                if getattr(self, k) != defaults[k]:
                    raise InputError(k, getattr(self, k), f"is a key of law = \"{other}\", not of law = "
                                     f"\"{self.law}\" (its keys: {', '.join(LAW_KEYS[self.law]) or 'none'})")
        if self.law != "walking":
            if self.method != "generated":
                raise InputError("method", self.method, "the sector method is the walking law's (the papers'); "
                                 f"law = \"{self.law}\" has generated teeth")
        for key in ("fourier_cos", "fourier_sin"):
            for i, v in enumerate(getattr(self, key)):
                if isinstance(v, bool) or not isinstance(v, (int, float)):
                    raise InputError(f"{key}[{i}]", v, "must be a number (rad)")
        if self.law == "table" and not self.law_file:
            raise InputError("law_file", "", "law = \"table\" needs the CSV file of its angles")
        if self.law == "pitch_curve" and not self.pitch_curve_file:
            raise InputError("pitch_curve_file", "", "law = \"pitch_curve\" needs the CSV file of the driver's curve")
        if self.law == "elliptical":
            from ...laws.ratio_laws import EllipticalLaw

            EllipticalLaw(self.eccentricity, self.driver_turns)
        if self.law == "fourier":
            from ...laws.ratio_laws import FourierLaw

            FourierLaw(self.driver_turns, tuple(float(v) for v in self.fourier_cos),
                       tuple(float(v) for v in self.fourier_sin))

    #: what ``driver_turns`` means under each law (the report states the one that applies)
    _DRIVER_TURNS_MEANING = {
        "walking": "n: driver turns per driven (carrier) turn; 1, 2 or 4",
        "elliptical": "k: lobes of the driven wheel (driver turns per driven turn)",
        "fourier": "k: driver turns per driven turn (the law's theta / k)",
        "table": "driver turns per driven turn: from the table",
        "pitch_curve": "k: driver turns per driven turn (the driven wheel's lobes: k times the driver curve's own)",
    }

    @property
    def load_given(self) -> bool:
        """A load case for the load per tooth is given (a driver torque, a power or a vehicle)."""
        return self.load_driver_torque_Nm > 0 or self.load_power_W > 0 or self.load_vehicle_mass_kg > 0

    def applies(self, name: str) -> bool:
        """The law's own keys and every shared one; another law's keys (refused when set) are not
        listed, nor ``law`` itself for the default walking law, nor the load per tooth's keys without a load."""
        if name == "law":
            return self.law != "walking"
        if name in LOAD_KEYS and not self.load_given:
            return False
        return not any(name in keys for other, keys in LAW_KEYS.items() if other != self.law)

    def meaning(self, name: str) -> str:
        if name == "driver_turns":
            return self._DRIVER_TURNS_MEANING[self.law]
        if name in ("driver_bore_mm", "driven_bore_mm") and getattr(self, name) is None:
            return (f"not given: sized from the gear, {_SIZED_RULE}; the derived {name} is the bore as built, a note "
                    "says why")
        return super().meaning(name)

    def _validate_load(self) -> None:
        """The load per tooth: one load case at most, each with what it needs."""
        given = [k for k in ("load_driver_torque_Nm", "load_power_W", "load_vehicle_mass_kg") if getattr(self, k) > 0]
        if len(given) > 1:
            raise InputError(given[1], getattr(self, given[1]), f"give one load case only: {given[0]} is set too")
        if not given:
            return
        if self.method != "generated":
            raise InputError(given[0], getattr(self, given[0]), "the load per tooth needs generated teeth (method = "
                             "\"generated\"; the sector teeth have no tooth record)")
        if self.load_vehicle_mass_kg > 0 and self.law != "walking":
            raise InputError("load_vehicle_mass_kg", self.load_vehicle_mass_kg, f"a vehicle load needs the walking law "
                             f"(its hub speed dX01/dphi); law = \"{self.law}\": give load_driver_torque_Nm")
        if self.load_power_W > 0 and not self.load_driver_speed_rpm > 0:
            raise InputError("load_driver_speed_rpm", self.load_driver_speed_rpm,
                             "a power load needs the driver's speed (> 0 rpm)")
        if self.load_life_hours > 0 and not self.load_driver_speed_rpm > 0:
            raise InputError("load_driver_speed_rpm", self.load_driver_speed_rpm,
                             "load_life_hours needs the driver's speed (> 0 rpm) to count the load cycles")

    def validate(self) -> None:
        if 0 < self.module_mm < policy.MODULE_MIN_MM:
            raise InputError("module_mm", self.module_mm, f"must be 0 (from center_distance_mm) or >= "
                             f"{policy.MODULE_MIN_MM:g} mm, the smallest module of ISO 54 / GOST 9563")
        self._validate_law_keys()
        self._validate_load()
        if self.law != "walking":
            self._validate_common(self.driver_turns if self.law != "table" else 1)
            return
        if not self.a_mm < self.c_mm:
            raise InputError("a_mm", self.a_mm, f"must be < c_mm = {self.c_mm:g}: the crank axes lie inside the "
                             "circle of the shoe stands (seed 000: 60 < 360, seed 002: 100 < 236.5)")
        A = self.a_mm - self.b_mm + self.c_mm
        if not A > 0:
            raise InputError("a_mm - b_mm + c_mm", A, "hub height Y01 = a - b + c must be > 0 mm, else the law is not positive")
        if self.driver_turns not in (1, 2, 4):
            raise InputError("driver_turns", self.driver_turns,
                             "the driver pitch curve closes only if n divides the 4 legs: n in {1, 2, 4}")
        n = self.driver_turns
        z = self.driven_teeth
        self._validate_common(n)
        WalkingLaw(a=self.a_mm, b=self.b_mm, c=self.c_mm, n=n)  # the law's own checks

    def _validate_common(self, n: int) -> None:
        """The rules of every law: whole driver teeth, the tooth method's inputs, bores."""
        z = self.driven_teeth
        if 0 < self.tolerance_grade < 5:
            raise InputError("tolerance_grade", self.tolerance_grade, "must be 0 (not measured) or 5 ... 12 (ISO 1328; "
                             "the run-out formula holds from grade 5)")
        if z % n:
            raise InputError("driven_teeth", z, f"must be a multiple of driver_turns = {n} (whole driver teeth)",
                             f"nearest valid: {max(n, z // n * n)}, {(z // n + 1) * n}")
        if self.method == "sectors":
            if z % 4:
                raise InputError("driven_teeth", z, "the sector method needs 4 x (sectors per leg) teeth",
                                 f"nearest valid: {max(4, z // 4 * 4)}, {(z // 4 + 1) * 4}")
            if not self.module_mm > 0:
                raise InputError("module_mm", self.module_mm, "the sector method needs the module of its tooth heights (> 0 mm)")
        else:
            if (self.module_mm > 0) == (self.center_distance_mm > 0):
                raise InputError("center_distance_mm", self.center_distance_mm,
                                 "generated teeth: give either module_mm (closure fixes L) or center_distance_mm "
                                 "(closure fixes the module), not both", f"module_mm = {self.module_mm}")
            if self.blend_hand_over > 0 and not self.smoothing_deg > 0 and not self.law_search:
                raise InputError("blend_hand_over", self.blend_hand_over,
                                 "a hand-over value needs the blend half-width smoothing_deg > 0")
            if self.smoothing_deg > self.smoothing_max_deg:
                raise InputError("smoothing_deg", self.smoothing_deg, f"must be <= smoothing_max_deg = {self.smoothing_max_deg}")
        for name in ("driver_bore_mm", "driven_bore_mm"):
            d = getattr(self, name)
            if self.keyway and d is not None and d > 0 and not 6.0 < d <= 230.0:
                raise InputError(name, d, "a keyway needs a bore over 6 up to 230 mm (DIN 6885-1); set keyway = false")
