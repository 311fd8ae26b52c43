"""The composite gear's tracked contact law (parts/polysector/contact_law.py) on hand-built cases with known
hand-overs: the default design moved to z_усл = 54 (e = 27 mm) meets the gear tip on tip at every hand-over;
a 2.5-module variant at e = 40 mm snaps the gear forward; in flank and edge contact the ratio from the pole
of the contact normal is the contact law's own dφ/dθ."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from propulsor import policy
from propulsor.params import load_params, read_part_file

ROOT = Path(__file__).resolve().parents[1]


def _design(**changes):
    from propulsor.parts.polysector import PolysectorParams, design

    _, data = read_part_file(ROOT / "parts" / "polysector.toml")
    return design(load_params(PolysectorParams, {**data, **changes}))


def _window(dd, deg0, deg1, n, te0, **kw):
    """The law over wheel angles deg0 … deg1 (n + 1 grid angles), from a start near the gear angle φ/i_n + te0."""
    from propulsor.parts.polysector.contact_law import ContactLaw, position_bodies, track
    from propulsor.parts.polysector.proofs import chord_for

    pos = dd.positions[0]
    bodies = position_bodies(dd, pos, chord_for(dd, pos))
    grid = np.radians(np.linspace(deg0, deg1, n + 1))
    th0 = ContactLaw(bodies).pose(grid[0], grid[0] / pos.ratio_nominal + te0 - 1e-3, 0.0).theta
    return track(bodies, grid, th0, **kw), pos


@pytest.fixture(scope="module")
def tip_on_tip():
    """Default design at z_усл = 54: the wheel turn 24.5° … 25.9° of the period holds one hand-over."""
    return _window(_design(conditional_teeth=[54]), 24.5, 25.9, 6, -0.0314)


def test_tip_on_tip_hand_over_is_resolved_and_fails_its_check(tip_on_tip):
    from propulsor.parts.polysector.contact_law import TYPES
    from propulsor.parts.polysector.proofs import law_checks

    law, pos = tip_on_tip
    kinds = [TYPES[k] for k in law.kind]
    # flank contact of the outgoing sector, then the incoming sector's leading tooth on the gear's tooth tip
    assert kinds[0] == "flank" and "tip_tip" in kinds
    first = kinds.index("tip_tip")
    assert law.driver[first] != law.driver[0]
    # 0.71° of wheel turn on tips, resolved to the finest step (a coarse step would quantise it by 0.23°)
    assert math.degrees(law.tip_tip_angle()) == pytest.approx(0.714, abs=0.01)
    assert law.phi[first] - law.phi[first - 1] <= policy.POLYSECTOR_LAW_STEP_MIN_RAD * (1 + 1e-9)
    # the gear is pushed ahead by the tips: Δi of the steps up to 0.63 (the gear runs 2.7 times too fast)
    assert np.nanmax(law.delta_i) == pytest.approx(0.627, abs=0.01)
    failed = {c.name for c in law_checks("position4", law) if not c.passed}
    assert failed == {"position4.no_tip_on_tip"}


def test_snap_of_the_gear_is_resolved_and_fails_its_check():
    """m 2.5, z 40, z_c 8, i_s 4, z2 36 at z_усл = 72 (e = 40 mm, ε_s = 1.08 by eq. 4): while the outgoing
    sector still drives on its flank, the incoming sector's flank meets the gear's tip corner and throws
    the gear forward by 1.73° within one finest step of wheel turn."""
    from propulsor.parts.polysector.proofs import law_checks

    dd = _design(module_mm=2.5, blank_teeth=40, sector_teeth=8, sectors_per_flow=4, gear_teeth=36,
                 face_width_mm=10.0, conditional_teeth=[72])
    law, pos = _window(dd, 20.27, 20.67, 2, math.radians(-2.8627))
    assert math.degrees(law.snap_max()) == pytest.approx(1.733, abs=0.02)
    k = int(np.argmax(law.jumps()))
    assert law.phi[k + 1] - law.phi[k] <= policy.POLYSECTOR_LAW_STEP_MIN_RAD * (1 + 1e-9)  # localised to the finest step
    assert law.driver[k + 1] != law.driver[k]
    assert law.tip_tip_angle() == 0.0
    failed = {c.name for c in law_checks("position4", law) if not c.passed}
    assert failed == {"position4.no_snap"}


@pytest.mark.parametrize("deg0, deg1", [(2.0, 4.0), (22.0, 24.0)])
def test_ratio_from_the_pole_is_the_laws_own_derivative(deg0, deg1):
    """Default design at z_усл = 48 (e = 18 mm): flank contact (2° … 4°) and the edge contacts before the
    hand-over (22° … 24°): the Δi of the pole of the contact normal, averaged over each step, is the
    step's own Δφ/Δθ of the tracked law, within the outlines' accuracy."""
    dd = _design(conditional_teeth=[48])
    te0 = {2.0: -0.0017, 22.0: -0.0073}[deg0]
    law, pos = _window(dd, deg0, deg1, 40, te0, step_min=1.0)
    di_step = (pos.ratio_nominal - np.diff(law.phi) / np.diff(law.theta)) / pos.ratio_nominal
    same = law.kind[1:] == law.kind[:-1]
    di_mid = 0.5 * (law.delta_i[1:] + law.delta_i[:-1])
    assert same.sum() >= 30
    if deg0 == 22.0:  # a sector's tip corner on the gear's flank, then the gear's tip corner on a sector's flank
        assert {1, 2} <= set(law.kind.tolist())
    assert np.max(np.abs(di_step[same] - di_mid[same])) < 2e-3
    assert np.max(np.abs(law.delta_i)) > 3e-3  # far from conjugate here


def test_e0_is_conjugate_with_flank_contact_only():
    """Limiting case e = 0: the sectors are the blank; every pose is flank on flank, Δi = 0, no jump."""
    dd = _design(conditional_teeth=[36])
    law, pos = _window(dd, 0.0, 20.0, 18, -0.0017)
    assert set(law.kind.tolist()) == {0}
    assert np.max(np.abs(law.delta_i)) < 1e-9
    assert np.ptp(law.te) < 1e-5 and law.snap_max() < 1e-5
