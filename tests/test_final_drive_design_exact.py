"""The final drive's design and proofs steps (parts/final_drive/design.py, proofs.py), limit by limit (issue 36: the
mutation run of the final_drive_design target).  Each test makes its design in this process (0.1 s each, no part
build): the refusals in full on both sides of each limit, the outlines against the generators called here with the
part's numbers, the set's values from seed 004's formulas."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from propulsor.params import load_params, read_part_file
from propulsor.parts.final_drive import FinalDriveParams
from stand_ins import SaidWriter

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "final_drive.toml"


def _params(**changes):
    _, mp = read_part_file(PART)
    return dataclasses.replace(load_params(FinalDriveParams, mp), **changes)


def _refusal(param, **changes):
    from propulsor.errors import InputError
    from propulsor.parts.final_drive.design import design

    with pytest.raises(InputError) as e:
        design(_params(**changes))
    assert e.value.parameter == param
    return e.value


# ---- design(): the refusals ------------------------------------------------------------------------------------------
def test_a_neighbour_gap_of_a_tenth_of_a_millimetre_is_accepted():
    """z = 12/13/38, five planets ((12 + 38)/5 = 10): the planets' tips clear by 2·a_w·sin(π/5) − d_a,planet =
    0.117 mm (seed 004 eq. 30), a set that can be made; six planets of the part file overlap (refused)."""
    from propulsor.parts.final_drive.design import design

    dd = design(_params(z_sun=12, z_planet=13, z_ring=38, n_planets=5, planet_bore_mm=60.0))
    ps = dd.ps
    gap = 2 * ps.a_w * math.sin(math.pi / 5) - ps.d_a_planet
    assert 0.1 < gap < 0.12 and ps.neighbour_gap == pytest.approx(gap, abs=1e-9)
    assert dd.ps.n_planets == 5 and len(dd.outlines) == 3


@pytest.mark.parametrize("field, z, x, other", [
    ("sun_bore_mm", "z_sun", "x_sun", dict(z_planet=30, x_planet=0.5, z_ring=68)),
    ("planet_bore_mm", "z_planet", "x_planet", dict(z_sun=30, x_sun=1.0, z_ring=46)),
])
def test_a_bore_below_one_millimetre_is_refused_where_the_teeth_leave_less(field, z, x, other):
    """m = 0.5, z = 8, x = −0.8 (the other gear shifted so that the set can be made): d_f − 2m =
    m·(z − 2.5 + 2x) − 2m = 0.95 mm; a bore of 0.97 mm is refused, one of 0.9 mm is not."""
    from propulsor.parts.final_drive.design import design

    small = dict(module_mm=0.5, **{z: 8, x: -0.8}, **other, sun_bore_mm=0.0, planet_bore_mm=0.0, sun_keyway=False,
                 ring_bolts=0, n_planets=1)
    limit = 0.5 * (8 - 2.5 + 2 * -0.8) - 2 * 0.5
    assert limit == pytest.approx(0.95, abs=1e-12)
    e = _refusal(field, **{**small, field: 0.97})
    assert (e.value, e.limit) == (0.97, "must be < d_f − 2m = 0.950 mm")
    dd = design(_params(**{**small, field: 0.9}))
    hole = dd.outlines[0 if z == "z_sun" else 1].profile.holes
    assert len(hole) == 1 and {(sg.center, sg.radius) for sg in hole[0].segments} == {((0.0, 0.0), 0.45)}


def test_a_ring_outside_diameter_under_a_millimetre_is_refused_as_any_other():
    """0 means the root diameter plus 8 modules; any positive diameter up to d_f + 4m is refused, 0.5 mm too."""
    e = _refusal("ring_outer_d_mm", ring_outer_d_mm=0.5)
    from propulsor.parts.final_drive.design import planetary_set

    ps = planetary_set(_params())
    assert (e.value, e.limit) == (0.5, f"must be > d_f + 4m = {ps.ring.d_f + 40.0:.3f} mm (rim under the bolts)")
    assert e.limit == "must be > d_f + 4m = 650.409 mm (rim under the bolts)"


# ---- gear_outlines(): the ring cut by the part's shaper -------------------------------------------------------------
def test_the_ring_is_cut_by_a_shaper_of_the_parts_tip_radius():
    """The part's shaper tip radius 0.2 m (2 mm) rounds the ring's root: the ring's teeth are those
    internal_gear_profile cuts with ρ_a0* = 0.2 and not those of its default 0.1."""
    from propulsor.geometry.gear_outline import internal_gear_profile
    from propulsor.parts.final_drive.design import design

    p = _params(ring_bolts=0)
    dd = design(p)
    ps = dd.ps
    assert p.shaper_tip_radius_star == 0.2
    area = abs(dd.outlines[2].profile.holes[0].signed_area())
    for rho, same in ((0.2, True), (0.1, False)):
        ring = internal_gear_profile(56, 10.0, ps.x_ring, ps.d_a_ring, 14, 0.04, outer_d=ps.ring.d_f + 80.0,
                                     rho_a0_star=rho, thinning_n_mm=0.15)
        other = abs(ring.profile.holes[0].signed_area())
        assert (other == pytest.approx(area, rel=1e-12)) is same, rho


# ---- proofs.py: the carrier sweep -------------------------------------------------------------------------------------
def test_carrier_sweep_is_the_windowed_sweep_of_each_mesh_on_the_finished_outlines(monkeypatch):
    """0.025 steps a degree: ceil(360·0.025) = 9 steps a turn (10 at 361°).  Each mesh is sweep_pair_windowed of its
    members' outlines within 1 µm (policy), edges split at max(0.1, 0.05·m) = 0.5 mm, reach one module, clearance
    limit 0, at the poses of member_poses; the sweep counts its six meshes to the build's reporter."""
    from propulsor.checks.motion import outline, sweep_pair_windowed
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.proofs import member_poses, start_sweep, sweep_results
    from propulsor.progress import Reporter

    from test_final_drive_exact import _PlotWriter

    class Said(Reporter):
        def __init__(self):
            super().__init__(None)
            self.said, self.counts = [], []

        def __call__(self, message):
            self.said.append(message)

        def count(self, phase, done, total, unit=""):
            self.counts.append((phase, done, total, unit))

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    p = _params()
    object.__setattr__(p, "sweep_steps_per_deg", 0.025)            # below the parameter's least: a short test
    dd = design(p)
    w, built = _PlotWriter(), {}
    w.progress = Said()
    start_sweep(dd, w, built)
    sweep_results(dd, w, built)
    assert w.progress.said == ["interference sweep over one carrier turn (9 steps), in a second process while the "
                               "solids are built", "interference sweep done"]
    assert w.progress.counts == [("interference sweep", k, 6, "mesh") for k in range(7)]
    sweeps = built["sweeps"]
    psi = [2 * math.pi * j / 9 for j in range(9)]
    M_sun, M_ring, M_pl = member_poses(p, dd.ps, psi)
    sun_o, planet_o, ring_o = dd.outlines
    A = {name: outline(o.profile, 1e-3, 0.5) for name, o in (("sun", sun_o), ("planet", planet_o), ("ring", ring_o))}
    checks = []
    for i, s in enumerate(sweeps):
        k, tag = divmod(i, 2)
        name = f"mesh_sun_planet{k + 1}" if tag == 0 else f"mesh_planet{k + 1}_ring"
        want = sweep_pair_windowed(A["sun" if tag == 0 else "ring"], M_sun if tag == 0 else M_ring, A["planet"],
                                   M_pl[k], reach=10.0, chord_tol=1e-3, max_segment=0.5, name=name,
                                   clearance_limit=0.0)
        assert s.name == name and list(s.psi) == pytest.approx(psi, rel=1e-15, abs=1e-15)
        assert list(s.overlap_mm2) == list(want.overlap_area) and list(s.clearance_mm) == list(want.clearance)
        got = [(c.name, c.passed, c.value, c.limit, c.unit) for c in s.result.checks()]
        assert got == [(c.name, c.passed, c.value, c.limit, c.unit) for c in want.checks()]
        checks += got
    assert [(c.name, c.passed, c.value, c.limit, c.unit) for c in w.checks] == checks
    assert [c[1] for c in checks] == [True] * 12 and {c[3] for c in checks[1::2]} == {0.0}


# ---- proofs.py: the sheet and the outline checks ----------------------------------------------------------------------
def test_the_sheet_and_outline_steps_say_what_they_do_and_use_the_tips_the_gears_are_made_with():
    """Unshifted gears (x = 0): the planet's tip is m·(z + 2) = 220 mm in both sheets, the sun's m·(z + 2) = 180 mm,
    and the ring's as the set has it."""
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.proofs import outline_checks, sheet_and_conditions

    dd = design(_params(x_sun=0.0, x_planet=0.0))
    w = SaidWriter()
    sheet_and_conditions(dd, w, {})
    outline_checks(dd, w, {})
    assert w.said == ["planetary set: sheet and conditions", "generated outlines (rack: sun, planets; shaper: ring)"]
    (tip,) = [r for r in w.tables["sheet_sun_planet"][1] if r[1] == "d_a"]
    assert tip[:3] == ["tip diameter", "d_a", "mm"] and tip[3:] == pytest.approx([180.0, 220.0], abs=1e-9)
    (ring_tip,) = [r for r in w.tables["sheet_planet_ring"][1] if r[1] == "d_a"]
    assert ring_tip[3] == pytest.approx(220.0, abs=1e-9) and ring_tip[4] == dd.ps.d_a_ring


def test_the_planetary_set_takes_every_number_of_the_parameters():
    """Not the set's defaults (the part's own numbers are seed 004's, which are the defaults): a shaper of 25 teeth
    shifted 0.1, faces 60/70/90 mm and the ring's x = 1.2 as given (no coaxiality correction)."""
    from propulsor.parts.final_drive.design import planetary_set

    ps = planetary_set(_params(shaper_z0=25, shaper_x0=0.1, width_sun_mm=60.0, width_planet_mm=70.0,
                               width_ring_mm=90.0, x_ring=1.2, ring_shift_for_coaxiality=False))
    assert (ps.z0, ps.x0, ps.b_sun, ps.b_planet, ps.b_ring, ps.x_ring) == (25, 0.1, 60.0, 70.0, 90.0, 1.2)
    assert (ps.z_sun, ps.z_planet, ps.z_ring, ps.m, ps.x_sun, ps.x_planet, ps.n_planets) == (16, 20, 56, 10.0, 0.5,
                                                                                             0.5, 3)


def test_the_thesis_rings_overlap_is_swept_on_its_outline_within_a_micrometre():
    """The thesis set (x_ring = 1.417 as printed) overlaps planet and ring: the overlap area, 2.6538 mm² at its
    largest over 9 steps, is that of the ring's outline within 1 µm (0.5 mm of chord gives 2.6541 mm²)."""
    from propulsor.checks.motion import outline, sweep_pair_windowed
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.proofs import carrier_sweep, member_poses

    _, mp = read_part_file(ROOT / "parts" / "final_drive_thesis.toml")
    p = load_params(FinalDriveParams, mp)
    dd = design(p)
    sweeps = carrier_sweep(p, dd.ps, dd.outlines, steps_per_deg=0.025)
    assert len(sweeps) == 6 and len(sweeps[1].psi) == 9
    psi = [2 * math.pi * j / 9 for j in range(9)]
    _, M_ring, M_pl = member_poses(p, dd.ps, psi)
    B = outline(dd.outlines[1].profile, 1e-3, 0.5)
    want = sweep_pair_windowed(outline(dd.outlines[2].profile, 1e-3, 0.5), M_ring, B, M_pl[0], reach=10.0,
                               chord_tol=1e-3, max_segment=0.5, name="mesh_planet1_ring", clearance_limit=0.0)
    s = sweeps[1]
    assert s.name == "mesh_planet1_ring" and list(s.overlap_mm2) == list(want.overlap_area)
    assert round(float(s.overlap_mm2.max()), 4) == 2.6538 and list(s.clearance_mm) == list(want.clearance)
