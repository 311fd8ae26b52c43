"""Seed 001: choice of the curvature law K(φ) of the fixed cam against limits."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.laws.cam_design import CSV_COLUMNS, DesignLimits, SearchGrid, evaluate, search_design
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, ReturnPhase, cam_motion
from propulsor.laws.shoe import footprint_ratio, hub_height_on_flat, shoe_loop_check, shoe_table

MECH = CamMechanism()
LIMITS = DesignLimits()
S = math.pi / 4


@pytest.fixture(scope="module")
def result():
    return search_design(MECH, LIMITS)


def test_search_evaluates_at_least_200_candidates(result):
    """The time budget (<= 10 s) is measured by bench/bench_cam_search.py, not here."""
    assert result.n_evaluated >= 200 and len(result.rows) == result.n_evaluated
    assert result.chosen is not None and result.law is not None
    assert {"linear", "quadratic", "exponential"} <= {r["law"] for r in result.rows}
    assert any(r["violations"].startswith("blow-up") for r in result.rows)  # recorded, not fatal
    for r in result.rows:
        assert set(CSV_COLUMNS) <= set(r)


def test_chosen_satisfies_every_limit_checked_independently(result):
    """Recompute the chosen design on denser grids, not from the search's rows."""
    law = result.law
    cm = cam_motion(MECH, law, ReturnPhase())
    assert cm.H_error_mm <= 1e-6
    phi = np.linspace(0, 2 * math.pi, 7201)
    t = cm.table(phi)
    assert np.degrees(np.max(np.abs(t.gamma))) <= LIMITS.gamma_max_deg
    lim = LIMITS.R_factor * MECH.r
    convex_inner = t.R_profile[t.K_path > 0]
    assert np.all(convex_inner >= lim)
    convex_outer = t.R_outer[t.K_path < 0]
    assert np.all(convex_outer >= lim)
    assert np.all(np.isfinite(t.sigma_H)) and np.max(t.sigma_H) <= LIMITS.sigma_allow
    assert np.min(t.H) - MECH.r >= LIMITS.cam_core_min
    sh = shoe_table(cm.support, np.linspace(-S, S, 1001))
    assert shoe_loop_check(sh).ok
    assert footprint_ratio(cm) <= LIMITS.footprint_ratio_max
    hh = hub_height_on_flat(cm, np.linspace(-S, S, 9), n_shoe=801)
    assert np.max(hh) - np.min(hh) <= 0.01
    assert result.chosen["hub_height_variation_mm"] <= 0.01
    assert result.chosen["ground_clearance_min_mm"] > 0.0


def test_chosen_is_best_feasible_and_rows_ranked(result):
    feas = [r for r in result.rows if r["feasible"]]
    assert len(feas) == result.n_feasible >= 2
    assert result.rows[:len(feas)] == feas  # feasible first
    v = [r["hub_speed_variation_pct"] for r in feas]
    assert v == sorted(v)
    assert result.chosen["hub_speed_variation_pct"] == pytest.approx(v[0], rel=1e-9)
    assert all(r["violations"] for r in result.rows[len(feas):])
    assert [r["rank"] for r in result.rows] == list(range(1, len(result.rows) + 1))
    assert "hub-speed variation" in result.reason and result.chosen["label"] in result.reason
    # the objective matters: some infeasible candidate has a smaller variation (it is the limits that bind)
    assert min(r["hub_speed_variation_pct"] for r in result.rows if not r["feasible"]
               and not r["violations"].startswith("blow-up")) < v[0]


def test_objective_closed_form_for_straight_path():
    """K = 0: dX02/dφ = 320 + H0·tan²φ (eq. 8); variation = H0 / mean, mean over ±π/4 of
    tan² = 4/π − 1."""
    row = evaluate(MECH, CurvatureLaw("zero"), LIMITS)
    mean = 320 + MECH.H0 * (4 / math.pi - 1)
    assert row["hub_speed_variation_pct"] == pytest.approx(100 * MECH.H0 / mean, rel=1e-4)
    assert row["hub_speed_variation_pct"] == pytest.approx(31.42, abs=0.01)
    assert not row["feasible"] and "pressure angle" in row["violations"]  # γ = φ reaches 45°


def test_footprint_limit_keeps_it_walking():
    """Without the footprint limit the objective drifts to a round wheel (K ≈ 1/H0)."""
    grid = SearchGrid(linear_k0=(0.0, 0.03, 4), quadratic_k0=(0.0, 0.05, 4), exponential_k0=(0.0, 0.012, 13),
                      exponential_k1=(-0.5, 0.5, 3))
    loose = search_design(MECH, DesignLimits(footprint_ratio_max=2.0), grid)
    assert loose.chosen["footprint_ratio"] > 0.95
    assert loose.chosen["hub_speed_variation_pct"] < 3.0
    tight = search_design(MECH, LIMITS, grid)
    assert tight.chosen["footprint_ratio"] <= LIMITS.footprint_ratio_max


def test_limits_change_or_block_the_choice():
    grid = SearchGrid(linear_k0=(0.0, 0.03, 16), quadratic_k0=(0.0, 0.05, 16), exponential_k0=(0.0, 0.0, 0),
                      exponential_k1=(0.0, 0.0, 0))
    base = search_design(MECH, LIMITS, grid)
    # pressure angle and footprint ratio pull in opposite directions (more curvature:
    # smaller γ, longer footprint); a looser footprint limit buys a steadier hub
    looser = search_design(MECH, DesignLimits(footprint_ratio_max=0.9), grid)
    assert looser.chosen["hub_speed_variation_pct"] < base.chosen["hub_speed_variation_pct"]
    assert LIMITS.footprint_ratio_max < looser.chosen["footprint_ratio"] <= 0.9
    assert search_design(MECH, DesignLimits(gamma_max_deg=15.0), grid).chosen is None
    none = search_design(MECH, DesignLimits(sigma_allow=300.0), grid)
    assert none.chosen is None and none.n_feasible == 0 and "no candidate" in none.reason
    lift = search_design(MECH, DesignLimits(return_lift_max=0.0), grid)
    assert lift.chosen is None


def test_hertz_limit_is_applied():
    # a softer roller, a heavier load: σ = 0.418·√(P·E/(b·cos γ)·(1/r + 1/R)) grows like √P
    row = evaluate(CamMechanism(P=30000.0), CurvatureLaw("quadratic", 0.017), LIMITS)
    assert row["sigma_max_MPa"] > 1500 and "Hertz" in row["violations"]
    row1 = evaluate(MECH, CurvatureLaw("quadratic", 0.017), LIMITS)
    assert row["sigma_max_MPa"] / row1["sigma_max_MPa"] == pytest.approx(math.sqrt(6.0), rel=1e-9)


@pytest.mark.parametrize("kw", [dict(gamma_max_deg=90), dict(gamma_max_deg=float("nan")), dict(R_factor=0),
                                dict(sigma_allow=-1), dict(footprint_ratio_max=0), dict(cam_core_min=-1),
                                dict(hub_height_tol=0), dict(return_lift_max=-1.0)])
def test_bad_limits_raise(kw):
    with pytest.raises(InputError):
        DesignLimits(**kw)


def test_bad_grid_raises():
    with pytest.raises(InputError):
        SearchGrid(linear_k0=(0.03, 0.0, 5))
    with pytest.raises(InputError):
        SearchGrid(quadratic_k0=(0.0, 0.05, 2.5))
