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
