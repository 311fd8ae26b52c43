"""The load case of a non-circular pair's print kit: the torque a hand puts on the kit's crank, rated on the printed
pair for every printed material of the catalogue, and the verdict the maker's guide gives (for a print kit the
torque a hand can put on the crank is the load case, and the guide says which material survives it).

Load case: the hand's force F_hand (``policy.KIT_HAND_FORCE_N``, a stated assumption with its ergonomics source)
tangential at the radius r_h of the crank handle as the kit builds it (:func:`.kit.rig_sizes`), the driven wheel
held (the pair turns against nothing else that a hand would feel):

    T1 = F_hand·r_h          (N·m, r_h in mm / 1000)

in both directions of turning (the drive flanks and the reverse flanks: a hand turns either way).  The pair rated is
the kit's own design object, the one its gears are cut from: designed anew at the print module m/S with the face
width b/S and its teeth thinned for the printer's backlash.  The math is the load per tooth's
(:func:`.tooth_load_outputs.analyse`: the contacts on the finished outlines, sharing by ISO 6336-1's single stiffness
c′ scaled by E/E_steel, Hertz with the flanks' measured radii of curvature, ISO 6336-3's 30° section of each tooth's
real outline), run once per printed material (E and ν change the sharing and Z_E) and direction, with K_A = K_v =
K_Hβ = 1 (a static push) and the part file's efficiency η for T2 = T1·U·η.

Verdict: a material survives the hand when its least safeties over both wheels and both directions reach the part
file's required ones, S_H >= ``load_S_Hmin`` and S_F >= ``load_S_Fmin`` (ISO 6336-2 / -3 cl. 5:
S_H = σ_Hlim·Z_NT/σ_H, S_F = σ_FE·Y_NT/σ_F; static printed limits, Z_NT = Y_NT = 1).  The printed limits are static
strengths of flat-printed bars with ±30 … 40 % spread (``gears/data/gear_materials.toml``): the verdict is a
judgement at the stated hand force, not a rating.  The force a material takes is estimated from the safeties at
F_hand as

    F_allow = F_hand·min(S_F/S_Fmin, (S_H/S_Hmin)²)

(root stress in proportion to the load, contact stress to its square root, the sharing as at F_hand: exact where the
loaded pairs do not change; above F_hand more pairs close and the estimate is on the safe side, below it not).
Whether no material survives or all do, the kit builds: the verdict is the guide's and the report's, its derived
values are the manifest's; the kit's check ``hand_load.equilibrium`` is that of the analysis itself (a loaded pair
at every phase, Σ F·l1 = T1); a loaded tooth whose 30° section is not found on its outline (the seed-000 kit's
driven teeth 8-15, on and beside the concave stretch of its pitch curve at the legs' hand-over) is named
as not rated at the root in the verdict, the check's message and ``hand_load_root_unrated_teeth``.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ... import policy
from ...check import Check

__all__ = ["Rating", "HandLoad", "hand_torque_Nm", "printed_materials", "hand_load", "TABLE_COLUMNS"]

TABLE_COLUMNS = ["material", "S_F_min", "S_F_required", "root_worst", "sigma_F_max_MPa", "sigma_FE_MPa", "S_H_min",
                 "S_H_required", "flank_worst", "sigma_H_max_MPa", "sigma_Hlim_MPa", "force_allow_N",
                 "torque_allow_Nm", "survives", "uncertainty"]

_DIRECTIONS = {1: "drive", -1: "reverse"}


def hand_torque_Nm(force_N: float, r_h_mm: float) -> float:
    """T1 = F_hand·r_h (N·m) of a hand pushing the crank handle at r_h (mm) with F_hand (N), tangentially."""
    return float(force_N) * float(r_h_mm) * 1e-3


def printed_materials() -> list[str]:
    """The catalogue's printed materials (those rated by static limits: PLA, PETG, nylon), in catalogue order."""
    from ...gears.gear_materials import materials

    return [name for name, m in materials().items() if m.static]


def _tooth_key(t: str):
    """'driven 8' before 'driven 10'."""
    g, j = t.split()
    return g, int(j)


def _join(names) -> str:
    names = list(names)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


@dataclass(frozen=True)
class Rating:
    """One printed material under the hand: its least safeties over both wheels and both directions."""

    name: str
    material: object        #: gears.gear_materials.GearMaterial
    S_F: float
    S_H: float
    sigma_F_max_MPa: float
    sigma_H_max_MPa: float
    root_worst: str         #: "driven tooth 27, drive": where S_F is least
    flank_worst: str        #: where S_H is least
    S_Fmin: float
    S_Hmin: float
    force_N: float
    analyses: tuple         #: (direction, ToothLoad) of each direction
    unrated: tuple = ()     #: "driven 8", ...: loaded teeth whose 30 deg section is not found (root not rated)

    @property
    def survives(self) -> bool:
        return bool(self.S_F >= self.S_Fmin and self.S_H >= self.S_Hmin)

    @property
    def force_allow_N(self) -> float:
        """The hand force this material takes (module docstring: an estimate from the safeties at F_hand)."""
        return self.force_N * min(self.S_F / self.S_Fmin, (self.S_H / self.S_Hmin) ** 2)

    @property
    def margin(self) -> float:
        """The lesser of S_F/S_Fmin and S_H/S_Hmin: above 1 the material survives."""
        return min(self.S_F / self.S_Fmin, self.S_H / self.S_Hmin)

    def safeties(self) -> str:
        return f"{self.name} S_F {self.S_F:.2f}, S_H {self.S_H:.2f}"


@dataclass(frozen=True)
class HandLoad:
    """The hand on the kit's crank and each printed material's rating under it."""

    force_N: float
    r_h_mm: float
    T1_Nm: float
    m_mm: float
    b_mm: float
    S_Fmin: float
    S_Hmin: float
    ratings: tuple          #: Rating per printed material
    load_case: str
    contacts: tuple = ()    #: the resolved contact laws the pair was placed by, [(direction, ContactLaw)]

    @property
    def survivors(self) -> list[str]:
        return [r.name for r in self.ratings if r.survives]

    @property
    def best(self) -> Rating:
        """The material that takes the most (the largest margin over the required safeties)."""
        return max(self.ratings, key=lambda r: r.margin)

    # ----------------------------------------------------------------------------------------- words
    def lead(self) -> str:
        return (f"A firm hand on the crank, {self.force_N:g} N on the handle at {self.r_h_mm:.1f} mm from the "
                f"driver's axis, puts T1 = {self.T1_Nm:.3f} N·m on the driver; with the driven wheel held, the printed "
                f"teeth (module {self.m_mm:.4g} mm, face width {self.b_mm:.4g} mm) carry it in either direction.")

    def sentence(self) -> str:
        """The verdict in plain words with the numbers: which printed material survives the hand and which not."""
        required = f"against the required S_F {self.S_Fmin:g}, S_H {self.S_Hmin:g}"
        ok = [r for r in self.ratings if r.survives]
        bad = [r for r in self.ratings if not r.survives]
        if not bad:
            return (f"{_join(r.name for r in ok)} {'all survive' if len(ok) > 1 else 'survives'} it "
                    f"({'; '.join(r.safeties() for r in ok)} {required})." + self._unrated())
        if ok:
            return (f"{_join(r.name for r in ok)} {'survive' if len(ok) > 1 else 'survives'} it "
                    f"({'; '.join(r.safeties() for r in ok)}); {_join(r.name for r in bad)} "
                    f"{'do' if len(bad) > 1 else 'does'} not ({'; '.join(r.safeties() for r in bad)}) {required}."
                    + self._unrated())
        b = self.best
        return self._none(b, required, bad) + self._unrated()

    def _unrated(self) -> str:
        teeth = sorted({t for r in self.ratings for t in r.unrated}, key=_tooth_key)
        if not teeth:
            return ""
        return (f" The roots of {len(teeth)} teeth ({', '.join(teeth)}) are not rated: ISO 6336-3's 30° section is "
                f"not found on their outline.")

    def _none(self, b, required, bad) -> str:
        return (f"No printed material survives it ({'; '.join(r.safeties() for r in bad)} {required}): print it in "
                f"{b.name} or turn gently: in {b.name} the teeth take about {b.force_allow_N:.0f} N on the handle "
                f"({hand_torque_Nm(b.force_allow_N, self.r_h_mm):.3f} N·m).")

    def caveat(self) -> str:
        unc = ", ".join(f"{r.name} ({r.material.uncertainty})" for r in self.ratings)
        return ("The printed strengths are static limits of flat-printed bars (layers in the gear's plane, as the "
                "plates lay the gears: the tooth root bends along the layers), not fatigue ratings, and uncertain "
                f"({unc}); a data sheet of your own filament beats them. The safeties hold for the teeth only (not "
                "the handle, pins or bores).")

    def guide_lines(self) -> list[str]:
        """The guide's paragraphs (plain text: the guide escapes them)."""
        return [self.lead() + " " + self.sentence(), self.caveat()]

    def table_rows(self) -> list[list]:
        return [[r.name, r.S_F, r.S_Fmin, r.root_worst, r.sigma_F_max_MPa, r.material.sigma_FE_MPa, r.S_H, r.S_Hmin,
                 r.flank_worst, r.sigma_H_max_MPa, r.material.sigma_Hlim_MPa, r.force_allow_N,
                 hand_torque_Nm(r.force_allow_N, self.r_h_mm), "yes" if r.survives else "no", r.material.uncertainty]
                for r in self.ratings]

    def guide_table(self) -> tuple[list[str], list[list[str]]]:
        head = ["material", "S_F (root)", "S_H (flank)", "least at", "takes about", "survives?"]
        rows = [[r.name, f"{r.S_F:.2f} (≥ {r.S_Fmin:g})", f"{r.S_H:.2f} (≥ {r.S_Hmin:g})",
                 f"root: {r.root_worst}; flank: {r.flank_worst}", f"{r.force_allow_N:.0f} N on the handle",
                 "yes" if r.survives else "no"] for r in self.ratings]
        return head, rows

    def derived(self) -> dict:
        out = {"hand_load_force_N": self.force_N, "hand_load_crank_radius_mm": self.r_h_mm,
               "hand_load_T1_Nm": self.T1_Nm, "hand_load_S_Fmin": self.S_Fmin, "hand_load_S_Hmin": self.S_Hmin,
               "hand_load_survivors": self.survivors,
               "hand_load_root_unrated_teeth": sorted({t for r in self.ratings for t in r.unrated}, key=_tooth_key)}
        for r in self.ratings:
            out.update({f"hand_load_{r.name}_S_F_min": r.S_F, f"hand_load_{r.name}_S_H_min": r.S_H,
                        f"hand_load_{r.name}_sigma_F_max_MPa": r.sigma_F_max_MPa,
                        f"hand_load_{r.name}_sigma_H_max_MPa": r.sigma_H_max_MPa,
                        f"hand_load_{r.name}_root_worst": r.root_worst,
                        f"hand_load_{r.name}_flank_worst": r.flank_worst,
                        f"hand_load_{r.name}_force_allow_N": r.force_allow_N,
                        f"hand_load_{r.name}_survives": r.survives})
        return out

    def checks(self) -> list[Check]:
        """The analysis carries the hand for every material and direction (``hand_load.equilibrium``): a loaded pair
        at every phase and Σ F·l1 = T1.  A loaded tooth whose 30 deg section is not found (the load per tooth's
        ``tooth_load.equilibrium`` fails on it) is named here and in the verdict as not rated at the root, and does
        not fail the kit: the hand's verdict is the guide's."""
        from .tooth_load_outputs import equilibrium

        runs = [(r, d, tl) for r in self.ratings for d, tl in r.analyses]
        parts = [equilibrium(tl, "hand_load.equilibrium", f"{r.name}, {_DIRECTIONS[d]}: ") for r, d, tl in runs]
        bad = [c for c, (_, _, tl) in zip(parts, runs) if not (tl.lost == 0 and tl.imbalance <= 1e-9)]
        worst = max(range(len(runs)), key=lambda k: max(runs[k][2].imbalance, float(runs[k][2].lost)))
        tl = runs[worst][2]
        return [Check("hand_load.equilibrium", not bad, max(tl.imbalance, float(tl.lost)), 1e-9, "",
                      f"the hand on the crank ({self.T1_Nm:.4f} N·m), {len(parts)} analyses (printed materials × both "
                      f"directions): " + ("; ".join(c.message for c in bad) if bad else parts[worst].message)
                      + self._unrated())]

    def note(self) -> str:
        """The report's note: the load case, the model and every material's numbers."""
        tl = self.ratings[0].analyses[0][1]
        return (f"The hand on the crank (parts/noncircular_pair/kit_load.py: for a print kit the torque a hand can "
                f"put on the crank is the load case): F_hand = {self.force_N:g} N (a stated assumption: a firm "
                f"one-hand push on a small handle, of the order of MIL-STD-1472D's thumb-finger grip of 48 N, "
                f"policy.KIT_HAND_FORCE_N) tangential at the handle's radius r_h = {self.r_h_mm:.3f} mm, the driven "
                f"wheel held: T1 = F_hand·r_h = {self.T1_Nm:.4f} N·m; {self.load_case}.  Rated on the printed pair "
                f"(module {self.m_mm:.4g} mm, face width {self.b_mm:.4g} mm, the teeth thinned for the printer's "
                f"backlash) by the load per tooth's analysis over one period in both directions ({len(tl.theta)} "
                f"phases of the drive direction), K_A = K_v = K_Hbeta = 1, for each printed material of the catalogue: "
                + "; ".join(f"{r.name} (E {r.material.E_MPa:g} MPa) S_F {r.S_F:.3f} (sigma_F {r.sigma_F_max_MPa:.2f} "
                            f"MPa, {r.root_worst}; sigma_FE {r.material.sigma_FE_MPa:g} MPa), S_H {r.S_H:.3f} "
                            f"(sigma_H {r.sigma_H_max_MPa:.2f} MPa, {r.flank_worst}; sigma_Hlim "
                            f"{r.material.sigma_Hlim_MPa:g} MPa), takes about {r.force_allow_N:.0f} N"
                            for r in self.ratings)
                + f" against the part file's S_Fmin {self.S_Fmin:g}, S_Hmin {self.S_Hmin:g}.  " + self.sentence()
                + "  " + self.caveat() + "  tables/hand_load.csv.")


def _worst(per_direction, key: str):
    """(least safety, largest stress, 'gear tooth j, direction') over both wheels and directions."""
    best = None
    for d, v in per_direction:
        for g in ("driver", "driven"):
            S = v[f"tooth_load_{g}_{key}_min"]
            stress = v[f"tooth_load_{g}_sigma_{key[-1]}_max_MPa"]
            tooth = v[f"tooth_load_{g}_sigma_{key[-1]}_worst_tooth"]
            if best is None or S < best[0]:
                best = (S, stress, f"{g} tooth {tooth}, {_DIRECTIONS[d]}")
    return best


def hand_load(q, kd, r_h_mm: float, force_N: float | None = None, names=None, contacts=None,
              count=None) -> HandLoad | None:
    """The hand on the crank of the kit whose printed pair is ``kd`` (the kit's own design: ``kd.d`` mounted at
    ``kd.mount``) made from the kit's parameters ``q``, its handle at ``r_h_mm``, pushed with ``force_N``
    (``policy.KIT_HAND_FORCE_N`` by default); each material of ``names`` (the printed ones of the catalogue by
    default) rated in both directions; ``contacts``: the pair's resolved contact laws [(direction, ContactLaw)] of
    both directions where known (``HandLoad.contacts`` of an earlier rating of the same pair).  None for teeth
    without a tooth record (the papers' sector teeth: the load per tooth needs generated teeth).  ``count(done,
    total)``: told the ratings done (a material in one direction each; progress only)."""
    from ...checks.motion.contact_events import DRIVE, REVERSE
    from .as_built import contact_direction, period_span
    from .tooth_load_outputs import analyse, summary

    d = kd.d
    if d.method != "generated":
        return None
    names = printed_materials() if names is None else list(names)
    force_N = policy.KIT_HAND_FORCE_N if force_N is None else force_N
    T1 = hand_torque_Nm(force_N, r_h_mm)
    step = math.radians(policy.KIT_HAND_LOAD_CONTACT_STEP_DEG)
    span = period_span(d)
    if contacts is None:
        contacts = tuple((dr, contact_direction(d, kd.mount, dr, step)) for dr in (DRIVE, REVERSE))
    ratings, load_case = [], ""
    total = len(contacts) * len(names)
    if count is not None:
        count(0, total)
    for name in names:
        ql = dataclasses.replace(q, load_driver_torque_Nm=T1, load_power_W=0.0, load_vehicle_mass_kg=0.0,
                                 load_life_hours=0.0, load_K_A=1.0, load_K_v=1.0, load_K_beta=1.0, gear_material=name)
        runs, vals = [], []
        for dr, c in contacts:
            ok = np.isfinite(c.te)
            if not np.any(ok):
                raise ValueError(f"the printed pair has no contact in the {_DIRECTIONS[dr]} direction")
            tl = analyse(d, kd.mount, ql, c.phi, c.te, float(c.phi[0]), span, direction=dr)
            runs.append((dr, tl))
            vals.append((dr, summary(tl, ql)))
            load_case = tl.load_case
            if count is not None:
                count(len(contacts) * len(ratings) + len(runs), total)
        S_F, sF, root = _worst(vals, "S_F")
        S_H, sH, flank = _worst(vals, "S_H")
        unrated = tuple(sorted({f"{g} {j}" for _, tl in runs for g in ("driver", "driven")
                                for j, sec in tl.sections[g].items() if not sec.ok}))
        ratings.append(Rating(name, runs[0][1].material, S_F, S_H, sF, sH, root, flank, q.load_S_Fmin,
                              q.load_S_Hmin, float(force_N), tuple(runs), unrated))
    return HandLoad(float(force_N), float(r_h_mm), T1, d.m, q.face_width_mm, q.load_S_Fmin, q.load_S_Hmin,
                    tuple(ratings), load_case, tuple(contacts))
