"""The final drive's fatigue step at the values the mutation run of 2026-11-28 found unpinned (TEST-GAPS.md F*):
the ring's load cycles, a standing vehicle, the static safeties, q_s, a required S_Hmin other than 1."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from propulsor.params import load_params, read_part_file
from propulsor.parts.final_drive import FinalDriveParams
from propulsor.parts.final_drive.design import design
from propulsor.parts.final_drive.fatigue import fatigue

PART = Path(__file__).resolve().parents[1] / "parts" / "final_drive.toml"


from test_part_final_drive import _Writer  # noqa: E402 - the output writer's parts the fatigue step uses


@pytest.fixture(scope="module")
def p():
    _, mp = read_part_file(PART)
    return load_params(FinalDriveParams, mp)


def _run(p):
    dd = design(p)
    w = _Writer()
    fatigue(dd, w, {})
    cols, rows = w.tables["strength_factors"]
    by = {(r[0], r[1], r[2], r[3]): r for r in rows}
    return dd, w.derived, by


@pytest.fixture
def default(p):   # each test runs the step: mutmut ties a test to the functions it calls itself
    return _run(p)


def test_ring_load_cycles_are_carrier_turns_times_planets(p, default):  # F3
    dd, d, _ = default
    # carrier: 7.852 km/h over a 15-tooth sprocket of 125 mm pitch = 7.852/3.6/1.875 = 1.1633 rev/s; 3 planets
    n_c = 7.852 / 3.6 / (15 * 0.125)
    assert d["load_cycles_per_hour_ring"] == pytest.approx(3600 * n_c * 3, rel=1e-12)
    # the sun turns i - 1 times faster than the carrier relative to it, passing the same 3 planets
    assert d["load_cycles_per_hour_ring"] == pytest.approx(d["load_cycles_per_hour_sun"] / (dd.ps.ratio - 1), rel=1e-12)


def test_standing_vehicle_has_infinite_lives(p):  # F4
    _, d, _ = _run(dataclasses.replace(p, design_speed_kmh=0.0))
    lives = [v for k, v in d.items() if k.endswith("_h") and "life" in k]
    assert len(lives) == 8 and all(v == math.inf for v in lives)


def test_static_safeties_are_the_seed_limits_over_the_stress(p, default):  # F5, F6
    _, d, by = default
    # seed 004 ch. 4.1: sigma_Hmax = 44 HRC = 44 * 59 = 2596 MPa; sigma_FlimM = 2.8 sigma_t = 2.8 * 785 = 2198 MPa
    for mesh, g in (("sun_planet", "sun"), ("sun_planet", "planet"), ("planet_ring", "ring")):
        sH = by[(mesh, "pitting", g, "sigma_H")][4]
        assert by[(mesh, "pitting", g, "S_H_static")][4] == pytest.approx(2596.0 / sH, rel=1e-12)
    for g in ("sun", "planet"):
        sF = by[("sun_planet", "bending", g, "sigma_F")][4]
        assert by[("sun_planet", "bending", g, "S_F_static")][4] == pytest.approx(2198.0 / sF, rel=1e-12)


def test_q_s_is_the_notch_parameter_of_the_stress_correction_factor(default):  # F9
    dd, _, by = default
    from propulsor.parts.final_drive.strength import mesh_stresses

    sp, _ = mesh_stresses(dd.p, dd.ps)
    for g, tf in (("sun", sp.root1_B), ("planet", sp.root2_B)):
        q_s = by[("sun_planet", "bending", g, "q_s")][4]
        # ISO 6336-3 eq. for Y_S (method B): Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L)), L = s_Fn/h_Fe
        L = tf.s_Fn / tf.h_Fe
        assert by[("sun_planet", "bending", g, "Y_S")][4] == pytest.approx(
            (1.2 + 0.13 * L) * q_s ** (1 / (1.21 + 2.3 / L)), rel=1e-9)
        assert q_s == pytest.approx(tf.s_Fn / (2 * tf.rho_F), rel=1e-12)


def test_pitting_life_meets_a_required_safety_other_than_one(p, default):  # F7 (now: cycles_at_limit's S_Hmin * sigma_H)
    p12 = dataclasses.replace(p, pitting_safety_S_Hmin=1.05)
    _, d, _ = _run(p12)
    life = d["strength_sun_planet_pitting_life_sun_h"]
    assert 0 < life < default[1]["strength_sun_planet_pitting_life_sun_h"]  # a higher minimum: reached sooner
    _, d, _ = _run(dataclasses.replace(p12, service_life_h=life))
    assert d["strength_sun_planet_S_H_pitting_sun"] == pytest.approx(1.05, rel=1e-9)
