"""The carrier (водило) of the final drive as a part (seed 004 §4.2–4.3): one cheek with the three
planet pins, the journal with the seats of the carrier bearings of Table 8 and the involute spline
Эв. 120 × 3.5 × 34 (GOST 6033) to the sprocket hub; and the sweep of one carrier turn that proves the
pins never touch the planets' bores.

Layout (ours; the thesis gives the bearings and the spline, not the drawing), z along the axis, the
gears' faces at 0 … b_ring:

* cheek: disc of radius a_w + d_pin, CHEEK_T_MM thick, GAP_MM below the gears;
* pins: Ø d_pin = bore of the planet bearing (Table 8, 10231…: d = 55 mm), from the cheek through the
  planets to the top of the ring's face;
* journal: Ø 120 mm = bore of the carrier bearings 3524 (120 × 215 × 58) and 224 (120 × 215 × 40),
  long enough for both plus a spacer;
* spline: Эв. 120 × 3.5 × 34, working length 140 mm (seed 004 §4.3), the shaft's end.
"""

from __future__ import annotations

import math

import numpy as np

from ... import policy
from ...parallel import start as start_in_fork
from .design import FinalDriveDesign, body_offsets

__all__ = ["carrier_solid", "carrier_layout", "pin_sweep", "start_pin_sweep", "carrier", "carrier_values", "pin_sweep_results"]

CHEEK_T_MM, GAP_MM, SPACER_MM = 40.0, 5.0, 10.0
PIN_D_MM = 55.0                      # planet bearing bore (seed 004 Table 8, bearing 10231…)
JOURNAL_D_MM = 120.0                 # carrier bearings 3524 / 224 bore (Table 8)
BEARING_WIDTHS_MM = (58.0, 40.0)     # 3524: 120 × 215 × 58 (GOST 5721); 224: 120 × 215 × 40 (GOST 8338)
SPLINE_LENGTH_MM = 140.0             # seed 004 §4.3, L = 140


def carrier_layout(dd: FinalDriveDesign) -> dict:
    """Radii and z levels of the carrier (mm)."""
    p, ps = dd.p, dd.ps
    z_cheek_top = -GAP_MM
    z_cheek_bot = z_cheek_top - CHEEK_T_MM
    z_journal_bot = z_cheek_bot - sum(BEARING_WIDTHS_MM) - SPACER_MM
    return dict(R_cheek=ps.a_w + PIN_D_MM, r_pin=0.5 * PIN_D_MM, z_pin_top=p.width_ring_mm, z_cheek_top=z_cheek_top,
                z_cheek_bot=z_cheek_bot, z_journal_bot=z_journal_bot, z_spline_bot=z_journal_bot - SPLINE_LENGTH_MM)


def _pin_centres(dd: FinalDriveDesign):
    from ...gears.planetary_kinematics import PlanetaryKinematics

    p, ps = dd.p, dd.ps
    kin = PlanetaryKinematics(p.z_sun, p.z_planet, p.z_ring, p.n_planets, ps.a_w)
    return kin, [tuple(float(v) for v in kin.planet_centre(0.0, k)) for k in range(p.n_planets)]


def carrier_solid(dd: FinalDriveDesign):
    """The carrier: cheek, pins, journal and spline, fused into one solid (genus 0)."""
    from ...geometry.involute_spline import InvoluteSpline
    from ...geometry.profile import Profile
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder, fuse, shifted_z
    from .strength import SPLINE_004

    if not dd.p.planet_bore_mm > PIN_D_MM:
        from ...errors import InputError
        raise InputError("planet_bore_mm", dd.p.planet_bore_mm, f"must exceed the planet pin Ø {PIN_D_MM} mm")
    L = carrier_layout(dd)
    _, centres = _pin_centres(dd)
    cheek = cylinder(L["R_cheek"], L["z_cheek_bot"], L["z_cheek_top"])
    pins = [cylinder(L["r_pin"], L["z_cheek_top"] - 1.0, L["z_pin_top"], center=c) for c in centres]
    journal = cylinder(0.5 * JOURNAL_D_MM, L["z_journal_bot"], L["z_cheek_bot"] + 1.0)
    spline = InvoluteSpline(SPLINE_004["D"], SPLINE_004["m"], SPLINE_004["z"])
    shaft = shifted_z(extrude_profile(Profile(spline.shaft_loop(), [], name="carrier spline"),
                                      L["z_journal_bot"] - L["z_spline_bot"] + 1.0), L["z_spline_bot"])
    return fuse(cheek, *pins, journal, shaft, name="carrier")


def pin_sweep(dd: FinalDriveDesign, steps_per_deg: float | None = None):
    """Overlap and clearance of the carrier's pin section (all pins) against each planet over one carrier
    turn (manifold3d booleans per step): the pins turn with the carrier, each planet about its pin."""
    from ...checks.motion import rotation_matrices, sweep_pair
    from ...geometry.profile import circle_loop

    p = dd.p
    spd = steps_per_deg or policy.CARRIER_PIN_SWEEP_STEPS_PER_DEG
    n = int(math.ceil(360.0 * spd))
    psi = np.arange(n) * (2.0 * math.pi / n)
    kin, centres = _pin_centres(dd)
    tol = policy.PLANETARY_SWEEP_CHORD_TOL_MM
    seg = max(0.1, 0.05 * p.module_mm)
    pins = [circle_loop(0.5 * PIN_D_MM, c, ccw=True).polyline(tol) for c in centres]
    off_ext, _ = body_offsets(p.z_ring)
    M_car = rotation_matrices(psi, np.zeros((n, 2)))
    planet = dd.outlines[1].profile
    out = []
    for k in range(p.n_planets):
        M_pl = rotation_matrices(kin.planet_angle(psi, k) + off_ext, kin.planet_centre(psi, k))
        r = sweep_pair(planet, M_pl, pins, M_car, tol, clearance_limit=0.0, name=f"carrier_pins_planet{k + 1}",
                       max_segment=seg)
        out.append(r)
    return psi, out


def start_pin_sweep(dd: FinalDriveDesign, w, built: dict) -> None:
    built["pending_pin_sweep"] = start_in_fork(pin_sweep, dd)


def carrier(dd: FinalDriveDesign, w, built: dict) -> None:
    """The carrier solid, written and checked by the writer like every solid."""
    w.progress("carrier: cheek, planet pins, bearing journal, spline Эв. 120 × 3.5 × 34")
    solid = carrier_solid(dd)
    w.add_solid("carrier", solid, expected_genus=0)
    built.setdefault("solids", {})["carrier"] = solid


def carrier_values(dd: FinalDriveDesign, w, built: dict) -> None:
    """The carrier's sizes (from its layout: no solid)."""
    L = carrier_layout(dd)
    w.derived.update({"carrier_cheek_radius_mm": L["R_cheek"], "carrier_pin_d_mm": PIN_D_MM,
                      "carrier_journal_d_mm": JOURNAL_D_MM, "carrier_spline_length_mm": SPLINE_LENGTH_MM,
                      "carrier_length_mm": L["z_pin_top"] - L["z_spline_bot"]})


def pin_sweep_results(dd: FinalDriveDesign, w, built: dict) -> None:
    """Checks and table of the pin sweep."""
    psi, res = built["pin_sweeps"] = built.pop("pending_pin_sweep").result()
    for r in res:
        w.add_checks(r.checks())
        w.derived[f"{r.name}_min_clearance_mm"] = float(r.clearance.min())
        w.derived[f"{r.name}_max_overlap_mm2"] = float(r.overlap_area.max())
    w.add_note(f"Carrier: cheek Ø {2 * carrier_layout(dd)['R_cheek']:.1f} mm with {dd.p.n_planets} pins Ø {PIN_D_MM:g} mm "
               f"(planet bearing bore, Table 8), journal Ø {JOURNAL_D_MM:g} mm for bearings 3524 and 224, spline "
               f"Эв. 120 × 3.5 × 34 over {SPLINE_LENGTH_MM:g} mm. Swept over one carrier turn ({len(psi)} steps) "
               f"against every planet: max overlap {max(r.overlap_area.max() for r in res):.3g} mm², least clearance "
               f"{min(r.clearance.min() for r in res):.4f} mm (pin to planet bore: the bearing's radial space).")
