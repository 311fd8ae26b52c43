"""The cam design search (laws/cam_design.py's search_design, seed 001 after eq. 29) on a grid of seven candidates
(issue 36: the mutation run of cam_design's search): each candidate's row is evaluate's, the ranking is by the
rule written out here, the leaders are verified on flat ground, the reason is given in full with the margins
computed here from the chosen row.  About 1.5 s a test."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.laws.cam_design import DesignLimits, SearchGrid, evaluate, search_design, verify
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw

MECH = CamMechanism()
# a looser pressure angle and footprint: three candidates pass, one of each law
LOOSE = dict(footprint_ratio_max=1.2, gamma_max_deg=40.0)
# linear 0.01, 0.105 (blows up), 0.2 (blows up); quadratic 0, 0.025, 0.05; exponential 0.012·exp(−0.5|φ|)
GRID = SearchGrid(linear_k0=(0.01, 0.2, 3), quadratic_k0=(0.0, 0.05, 3), exponential_k0=(0.012, 0.012, 1),
                  exponential_k1=(-0.5, -0.5, 1))
EXP, QUAD, LIN = "K = 0.012·exp(-0.5·|φ|)", "K = 0.025·φ²", "K = 0.01·|φ|"
# ranked: the feasible by hub-speed variation (1.49, 8.63, 11.44 %); then the infeasible by their number of
# violations - K = 0 (pressure angle only), K = 0.05·φ² (pressure angle; radius of curvature), each group by its
# variation; the two blow-ups (no figures: whose message holds a '; ' of its own) after every candidate with figures
RANKED = [EXP, QUAD, LIN, "K = 0·φ²", "K = 0.05·φ²", "K = 0.105·|φ|", "K = 0.2·|φ|"]


def _rows(limits):
    return {r["label"]: r for r in (evaluate(MECH, law, limits) for law in GRID.laws())}


def _margins_text(row, limits):
    """The two tightest limits of a row: 1 − value/limit, or value/limit − 1 for the lower limits."""
    m = {"pressure angle": 1 - row["gamma_max_deg"] / limits.gamma_max_deg,
         "cam radius of curvature": min(row["R_min_mm"], row["R_outer_min_mm"]) / (limits.R_factor * 20.0) - 1,
         "Hertz stress": 1 - max(row["sigma_max_MPa"], row["sigma_return_max_MPa"]) / limits.sigma_allow,
         "footprint ratio": 1 - row["footprint_ratio"] / limits.footprint_ratio_max,
         "cam core": (row["H_min_mm"] - 20.0) / limits.cam_core_min - 1}
    two = sorted(m, key=m.get)[:2]
    return ", ".join(f"{k} (margin {100 * m[k]:.1f}%)" for k in two)


def test_search_ranks_every_candidate_verifies_the_leader_and_says_why():
    limits = DesignLimits(**LOOSE)
    res = search_design(MECH, limits, GRID)
    rows = _rows(limits)
    assert (res.n_evaluated, res.n_feasible) == (7, 3)
    assert [r["label"] for r in res.rows] == RANKED and [r["rank"] for r in res.rows] == list(range(1, 8))
    v = [rows[k]["hub_speed_variation_pct"] for k in (EXP, QUAD, LIN)]
    assert v == sorted(v) and [r["feasible"] for r in res.rows] == [True] * 3 + [False] * 4
    for r in res.rows[1:]:                      # every row as evaluate gives it (only the leader was verified)
        want = dict(rows[r["label"]], rank=r["rank"])
        assert r.keys() == want.keys()
        assert all(r[k] == want[k] or (r[k] != r[k] and want[k] != want[k]) for k in want), r["label"]
    # the leader: its row with the flat-ground verification; the chosen: re-evaluated with the error estimate
    ver = verify(MECH, CurvatureLaw("exponential", 0.012, -0.5), limits)
    assert ver["verify_violations"] == ""
    lead = res.rows[0]
    assert {k: lead[k] for k in ver} == ver
    est = evaluate(MECH, CurvatureLaw("exponential", 0.012, -0.5), limits, estimate_error=True)
    assert 0 < est["H_error_mm"] < 1e-6 and res.chosen["H_error_mm"] == est["H_error_mm"]
    assert res.chosen == dict(est, **ver, rank=1)
    assert res.law == CurvatureLaw("exponential", 0.012, -0.5)
    q, lin = rows[QUAD]["hub_speed_variation_pct"], rows[LIN]["hub_speed_variation_pct"]
    assert res.reason == (f"{EXP}: smallest hub-speed variation of eq. 8, {est['hub_speed_variation_pct']:.3f} %, "
                          f"among 3 feasible of 7 candidates; tightest limits: {_margins_text(est, limits)}; "
                          f"best quadratic: {QUAD} {q:.3f} %; best linear: {LIN} {lin:.3f} %")
    assert _margins_text(est, limits).startswith("footprint ratio (margin 15.2%), Hertz stress")
    assert 0.0 < res.elapsed_s < 60.0


def test_a_leader_that_fails_on_flat_ground_gives_way_to_the_next():
    """The idle shoes of the leader clear the ground by 1.146 mm, those of K = 0.025·φ² by 1.768 mm: a limit of
    1.6 mm leaves the leader infeasible with the verification's message and chooses the quadratic law."""
    limits = DesignLimits(ground_clearance_min=1.6, **LOOSE)
    res = search_design(MECH, limits, GRID)
    rows = _rows(limits)
    c_exp = verify(MECH, CurvatureLaw("exponential", 0.012, -0.5), limits)["ground_clearance_min_mm"]
    ver = verify(MECH, CurvatureLaw("quadratic", 0.025), limits)
    assert c_exp < 1.6 <= ver["ground_clearance_min_mm"]
    assert res.n_feasible == 2 and res.law == CurvatureLaw("quadratic", 0.025)
    # the failed leader is the least violating of the infeasible (one violation, the smallest variation)
    assert [r["label"] for r in res.rows] == [QUAD, LIN, EXP] + RANKED[3:]
    failed = res.rows[2]
    assert failed["feasible"] is False
    assert failed["violations"] == f"idle shoe ground clearance {c_exp:.4g} mm < 1.6 mm"
    assert failed["verify_violations"] == failed["violations"] and failed["ground_clearance_min_mm"] == c_exp
    est = evaluate(MECH, CurvatureLaw("quadratic", 0.025), limits, estimate_error=True)
    assert res.chosen == dict(est, **ver, rank=1)
    lin = rows[LIN]["hub_speed_variation_pct"]
    assert res.reason == (f"{QUAD}: smallest hub-speed variation of eq. 8, {est['hub_speed_variation_pct']:.3f} %, "
                          f"among 2 feasible of 7 candidates; tightest limits: {_margins_text(est, limits)}; "
                          f"best linear: {LIN} {lin:.3f} %")


def test_no_candidate_names_the_closest_with_its_violations():
    """A clearance of 2 mm fails all three leaders: no choice; the closest is the leader by the objective, with its
    verification's message; a single feasible law names no other."""
    limits = DesignLimits(ground_clearance_min=2.0, **LOOSE)
    res = search_design(MECH, limits, GRID)
    c = verify(MECH, CurvatureLaw("exponential", 0.012, -0.5), limits)["ground_clearance_min_mm"]
    assert (res.chosen, res.law, res.n_feasible, res.n_evaluated) == (None, None, 0, 7)
    assert [r["label"] for r in res.rows] == RANKED
    assert all(r["feasible"] is False for r in res.rows)
    assert res.reason == f"no candidate of 7 satisfies the limits; closest: {EXP} (idle shoe ground clearance " \
                         f"{c:.4g} mm < 2 mm)"
    one = search_design(MECH, DesignLimits(**LOOSE), SearchGrid(linear_k0=(0.01, 0.01, 1), quadratic_k0=(0, 0, 0),
                                                                exponential_k0=(0, 0, 0), exponential_k1=(0, 0, 0)))
    row = evaluate(MECH, CurvatureLaw("linear", 0.01), DesignLimits(**LOOSE), estimate_error=True)
    assert one.reason == (f"{LIN}: smallest hub-speed variation of eq. 8, {row['hub_speed_variation_pct']:.3f} %, "
                          f"among 1 feasible of 1 candidates; tightest limits: "
                          f"{_margins_text(row, DesignLimits(**LOOSE))}")


def test_the_search_evaluates_and_verifies_with_the_return_phase_it_was_given():
    """A minimum-jerk return moves the cam over the return phase (its H, its pressure angle there) and the idle
    shoes: every row, the leader's verification and the chosen row are those of that return phase."""
    from propulsor.laws.cam_motion import ReturnPhase

    rp = ReturnPhase("min_jerk")
    limits = DesignLimits(**LOOSE)
    grid = SearchGrid(linear_k0=(0.01, 0.01, 1), quadratic_k0=(0.025, 0.025, 1), exponential_k0=(0, 0, 0),
                      exponential_k1=(0, 0, 0))
    res = search_design(MECH, limits, grid, rp)
    lin, quad = CurvatureLaw("linear", 0.01), CurvatureLaw("quadratic", 0.025)
    rows = {r["label"]: r for r in res.rows}
    plain = evaluate(MECH, lin, limits)
    want = evaluate(MECH, lin, limits, rp)
    assert want["H_max_mm"] != pytest.approx(plain["H_max_mm"], rel=1e-6)       # the return phase matters
    for k, v in want.items():
        got = rows[LIN][k]
        assert got == v or (got != got and v != v), k
    ver = verify(MECH, res.law, limits, rp)
    assert res.chosen == dict(evaluate(MECH, res.law, limits, rp, estimate_error=True), **ver, rank=1)
    other = verify(MECH, res.law, limits)
    assert ver["ground_clearance_min_mm"] != pytest.approx(other["ground_clearance_min_mm"], rel=1e-6)
    assert res.law in (lin, quad)


def test_a_blow_up_row_holds_every_column_with_nothing_measured():
    """The path of K = 0.2·|φ| turns radial at 20.2°: its row has every column of a row, the figures not a number,
    the flags false, the violation the refusal's message."""
    from propulsor.errors import InputError
    from propulsor.laws.cam_motion import cam_motion

    law = CurvatureLaw("linear", 0.2)
    with pytest.raises(InputError) as e:
        cam_motion(MECH, law)
    row = evaluate(MECH, law, DesignLimits())
    figures = ["hub_speed_variation_pct", "gamma_max_deg", "gamma_max_support_deg", "R_min_mm", "R_outer_min_mm",
               "undercut", "sigma_max_MPa", "sigma_return_max_MPa", "shoe_radius_min_mm", "shoe_self_intersecting",
               "footprint_ratio", "H_min_mm", "H_max_mm", "H_support_end_mm", "return_lift_mm", "H_error_mm",
               "hub_height_variation_mm", "ground_clearance_min_mm"]
    assert list(row) == ["law", "k0", "k1", "label", "feasible", "violations"] + figures
    assert [row[k] for k in ("law", "k0", "k1", "label", "feasible")] == ["linear", 0.2, 0.0, "K = 0.2·|φ|", False]
    assert row["violations"] == f"blow-up: {e.value}" and "at φ = 20.2°" in row["violations"]
    for k in figures:
        if k in ("undercut", "shoe_self_intersecting"):
            assert row[k] is False, k
        else:
            assert type(row[k]) is float and math.isnan(row[k]), k


@pytest.mark.parametrize("law, inner, outer", [
    (CurvatureLaw("quadratic", 0.08), True, False),       # K up to 0.065/mm: a convex path radius of 15.4 mm < r
    (CurvatureLaw("exponential", 0.012, 1.0), False, True),   # K down to −27/mm: a concave radius of 0.04 mm
    (CurvatureLaw("quadratic", 0.05), False, False),      # K within −0.025 ... 0.031/mm: radii of 32 mm and more
])
def test_undercut_is_a_path_curved_tighter_than_the_roller_on_either_wall(law, inner, outer):
    """The cam's working profile (convex path, K > 0) is undercut where the path's radius 1/K is under the roller's
    r = 20 mm; the outer channel wall (concave path, K < 0) where 1/|K| is under r plus the channel clearance."""
    from propulsor import policy
    from propulsor.laws.cam_motion import cam_motion

    tab = cam_motion(MECH, law).table(np.linspace(0.0, 2 * math.pi, policy.CAM_TURN_SAMPLES))
    K = tab.K_path
    assert bool(np.any(K > 1 / MECH.r)) is inner
    assert bool(np.any(-K > 1 / (MECH.r + MECH.channel_clearance))) is outer
    row = evaluate(MECH, law, DesignLimits())
    assert row["undercut"] is (inner or outer)
    assert ("undercut (cam profile radius of curvature < 0)" in row["violations"].split("; ")) is (inner or outer)


def test_the_outer_walls_least_radius_and_a_stress_not_a_number_taken_as_infinite():
    """K = 0.05·φ² is concave near φ = ±π (K down to −0.0254/mm): the outer wall's least radius of curvature is
    1/|K| − (r + channel clearance) = 19.13 mm.  K = 0.08·φ² undercuts the return: its Hertz stress there is not a
    number (663 samples), taken as infinite."""
    from propulsor import policy
    from propulsor.laws.cam_motion import cam_motion

    phi = np.linspace(0.0, 2 * math.pi, policy.CAM_TURN_SAMPLES)
    law = CurvatureLaw("quadratic", 0.05)
    K = cam_motion(MECH, law).table(phi).K_path
    row = evaluate(MECH, law, DesignLimits())
    assert row["R_outer_min_mm"] == pytest.approx(1 / abs(K.min()) - (MECH.r + MECH.channel_clearance), rel=1e-9)
    assert round(row["R_outer_min_mm"], 2) == 19.13
    tab = cam_motion(MECH, CurvatureLaw("quadratic", 0.08)).table(phi)
    assert np.isnan(tab.sigma_H[~tab.support]).any()
    row = evaluate(MECH, CurvatureLaw("quadratic", 0.08), DesignLimits())
    assert row["sigma_return_max_MPa"] == math.inf and math.isfinite(row["sigma_max_MPa"])
    assert "Hertz stress inf MPa > 1500 MPa" in row["violations"]


def test_a_looping_shoe_and_a_support_stress_not_a_number_are_reported():
    """K = −0.008·|φ| makes a shoe that crosses itself (its polyline checked here); K = 0.0825·φ² turns the path
    back within the support (γ near 180°): its support stress is not a number there, taken as infinite."""
    from propulsor import policy
    from propulsor.laws.cam_motion import cam_motion
    from propulsor.laws.shoe import shoe_loop_check, shoe_table

    law = CurvatureLaw("linear", -0.008)
    s = math.pi / 4
    lc = shoe_loop_check(shoe_table(cam_motion(MECH, law).support, np.linspace(-s, s, policy.CAM_SUPPORT_SAMPLES)))
    assert lc.self_intersecting is True
    row = evaluate(MECH, law, DesignLimits())
    assert row["shoe_self_intersecting"] is True
    assert f"shoe cusp/loop (min radius {lc.radius_min:.2f} mm, self-intersecting True)" in row["violations"]
    law = CurvatureLaw("quadratic", 0.0825)
    tab = cam_motion(MECH, law).table(np.linspace(0.0, 2 * math.pi, policy.CAM_TURN_SAMPLES))
    assert np.isnan(tab.sigma_H[tab.support]).any()
    assert evaluate(MECH, law, DesignLimits())["sigma_max_MPa"] == math.inf


def test_a_blow_up_ranks_after_every_candidate_with_figures_however_many_limits_they_violate():
    """With a Hertz limit of 100 MPa every candidate violates it: K = 0·φ² two limits, K = 0.05·φ² three.  A blow-up's
    message holds a '; ' of its own; counted as violations it ranked a blow-up ahead of the three-limit candidate,
    whose figures are known.  Blow-ups come last, among themselves by the grid's order."""
    res = search_design(MECH, DesignLimits(footprint_ratio_max=1.2, gamma_max_deg=40.0, sigma_allow=100.0), GRID)
    assert res.n_feasible == 0
    assert [r["label"] for r in res.rows] == [EXP, QUAD, LIN, "K = 0·φ²", "K = 0.05·φ²", "K = 0.105·|φ|",
                                              "K = 0.2·|φ|"]
    assert [r["violations"].count("; ") for r in res.rows[3:5]] == [1, 2]
    assert all(r["violations"].startswith("blow-up: ") and "; " in r["violations"] for r in res.rows[5:])
    assert res.reason == (f"no candidate of 7 satisfies the limits; closest: {EXP} ({res.rows[0]['violations']})")
