"""The pair as made (parts/noncircular_pair/tolerance.py): ISO 1328 / ISO 286 numbers by hand, the as-built
transmission of the made pair against the drawn one's, and the worst-case check failing when the tolerances
outgrow the backlash."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from propulsor.parts.noncircular_pair.tolerance import (Case, iso1328, monte_carlo_cases, printed, run_case, scaled,
                                                        worst_cases)

PARTS = Path(__file__).resolve().parent.parent / "parts"


def test_iso1328_grade_8_of_the_seed002_pair_by_hand():
    """m = 2.5, z 20 / 80 (d = 50 / 200 mm), L = 124.27 mm, grade 8.
    F_r = 0.8 (0.3 m + 1.25 sqrt(d) + 7) 2^((8 - 5)/2) um (ISO 1328-2:1997):
      driver 0.8 (0.75 + 8.839 + 7) 2.8284 = 37.54 um; driven 0.8 (0.75 + 17.678 + 7) 2.8284 = 57.54 um.
    f_a = IT8 / 2, IT8 = 25 i, i = 0.45 L^(1/3) + 0.001 L = 0.45 x 4.9902 + 0.1243 = 2.3699 um: 29.62 um.
    thinning up to F_r,max tan 20 deg = 57.54 x 0.36397 = 20.94 um."""

    class D:
        m, z, z_H = 2.5, 20, 80

    t = iso1328(D, 124.2714, 8)
    assert 2 * t.e_driver == pytest.approx(37.54e-3, abs=0.01e-3)
    assert 2 * t.e_driven == pytest.approx(57.54e-3, abs=0.01e-3)
    assert t.f_a == pytest.approx(29.62e-3, abs=0.01e-3)
    assert (t.t_lo, t.t_hi) == (0.0, pytest.approx(20.94e-3, abs=0.01e-3))
    assert iso1328(D, 124.2714, 9).e_driven == pytest.approx(t.e_driven * math.sqrt(2))  # one grade: x sqrt 2
    p = printed(0.15, 0.25)
    assert (p.f_a, p.e_driver, p.t_lo, p.t_hi) == (0.15, 0.25, -0.15, 0.15)
    names = [c.name for c in worst_cases(t)]
    assert names == ["tight, run-outs in phase", "tight, run-outs opposed", "loose, run-outs in phase",
                     "loose, run-outs opposed"]
    a, b = monte_carlo_cases(t, 5, 7), monte_carlo_cases(t, 5, 7)
    assert a == b and len({c.dL for c in a}) == 5 and all(abs(c.dL) <= t.f_a for c in a)


@pytest.fixture(scope="module")
def elliptical():
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design

    _, mapping = read_part_file(PARTS / "ncg_elliptical.toml")
    p = load_params(NoncircularPairParams, mapping)
    return p, design(p)


def test_the_made_pair_loses_backlash_as_the_tolerances_say(elliptical):
    """The drawn pair (no deviation) has the as-built backlash; the tight corner of grade 8 less by about
    2 tan(alpha) f_a (the centre distance) plus the run-outs' approach; the loose corner more."""
    p, d = elliptical
    tol = iso1328(d, d.L, 8)
    step = math.radians(1.0)  # the cases at 1 deg of driver (the build's 0.5): the same corners, half the time
    nominal = run_case(d, d.L, Case("nominal"), step)
    cases = worst_cases(tol)
    tight, loose = run_case(d, d.L, cases[0], step), run_case(d, d.L, cases[2], step)
    assert nominal.lost == 0 and not nominal.jam
    assert 0.16 < nominal.backlash_min_mm < 0.18
    drop = nominal.backlash_min_mm - tight.backlash_min_mm
    assert 2 * math.tan(math.radians(20)) * tol.f_a < drop < 2 * math.tan(math.radians(20)) * (
        tol.f_a + tol.e_driver + tol.e_driven) + 1e-3
    assert loose.backlash_min_mm > nominal.backlash_min_mm
    assert tight.te_pp_drive > nominal.te_pp_drive  # the run-outs add once-a-turn error


def test_the_worst_case_check_fails_when_the_tolerances_outgrow_the_backlash(elliptical):
    """Mutation: grade 8's tolerances six times as wide: the tight corner jams; the check names it."""
    from propulsor.parts.noncircular_pair.as_built_outputs import tolerance_check

    p, d = elliptical
    tol = iso1328(d, d.L, 8)
    step = math.radians(1.0)
    fine = [run_case(d, d.L, c, step) for c in worst_cases(tol)[:1]]
    assert tolerance_check(tol, fine, p.speed_step_max).passed
    wide = scaled(tol, 6.0)
    bad = [run_case(d, d.L, c, step) for c in worst_cases(wide)[:1]]
    chk = tolerance_check(wide, bad, p.speed_step_max)
    assert not chk.passed and "tight, run-outs in phase: jam" in chk.message


def test_a_study_may_minimise_and_require_the_as_built_and_as_made_values(tmp_path):
    """The derived values of the pair as built and as made are a study's objectives and requirements like any
    other (their meanings in the part type's glossary); a name no manifest gives is still refused."""
    from propulsor.errors import InputError
    from propulsor.study.spec import load_study

    text = f"""
[study]
part = "{PARTS / 'ncg_seed002.toml'}"
depth = "proof"
title = "as built"

[vary]
module_mm = [2.5]

[objectives]
minimize = ["speed_ripple_as_built", "tolerance_te_pp_p95_rad"]
require = ["speed_step_max <= 0.02", "corner_run_max_deg <= 0.5", "tolerance_backlash_min_mm >= 0.05"]
record = ["te_pp_reverse_rad", "as_built_stretches"]
"""
    f = tmp_path / "s.toml"
    f.write_text(text, encoding="utf-8")
    s = load_study(f)
    assert s.minimize == ("speed_ripple_as_built", "tolerance_te_pp_p95_rad")
    f.write_text(text.replace("speed_step_max <= 0.02", "speed_stepmax <= 0.02"), encoding="utf-8")
    with pytest.raises(InputError, match="speed_stepmax"):
        load_study(f)
