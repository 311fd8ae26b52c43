"""The driven wheel of a law of n > 1 periods cut as one lobe and patterned (geometry.noncircular_outline.generate_gear,
gears.noncircular_teeth.generate_teeth ``lobe``): its outline repeats exactly every 2 pi / n, it is the wheel cut
tooth by tooth to within the fits' tolerance, every tooth keeps its own record, and a wheel without the period (a
driver, one period, a tooth count that is no multiple of n) is cut tooth by tooth as before."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import propulsor.geometry.noncircular_outline as outline_module
from propulsor.gears.noncircular_teeth import generate_teeth
from propulsor.params import load_params
from propulsor.parts.noncircular_pair.design import design
from propulsor.parts.noncircular_pair.params import NoncircularPairParams
from propulsor.policy import SPLINE_FIT_TOL_MM

ROOT = Path(__file__).resolve().parents[1]


def _cut_calls(part: str, monkeypatch) -> dict:
    """The arguments each wheel of the part file's design is cut with (role -> (pc, spec, frame, tol))."""
    calls = {}
    real = outline_module.generate_gear

    def recording(pc, role, spec, frame=None, tol=SPLINE_FIT_TOL_MM, *rest, **kw):
        calls[role] = (pc, spec, frame, tol)
        return real(pc, role, spec, frame, tol, *rest, **kw)

    monkeypatch.setattr(outline_module, "generate_gear", recording)
    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    base = tomllib.loads((ROOT / part).read_text(encoding="utf-8"))
    base.pop("type")
    base.pop("meta", None)
    design(load_params(NoncircularPairParams, base), source=str(ROOT / part))
    return calls


def _turn(P: np.ndarray, a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.column_stack([c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1]])


@pytest.fixture(scope="module")
def seed_000():
    """Seed 000's pair (n = 2, 96 driven teeth, two spaces a lobe whose root land vanished, re-phased shapers'
    lifted roots): both wheels cut as the build cuts them and the driven one tooth by tooth."""
    mp = pytest.MonkeyPatch()
    try:
        calls = _cut_calls("parts/ncg_seed000.toml", mp)
    finally:
        mp.undo()
    pc, spec, frame, tol = calls["driven"]
    lobed = outline_module.generate_gear(pc, "driven", spec, frame, tol)
    each = outline_module.generate_gear(pc, "driven", spec, frame, tol, lobe=False)
    return pc, calls, lobed, each


def _repeats(segs, n: int) -> None:
    N = len(segs)
    assert N % n == 0
    per = N // n
    for j in range(1, n):
        for i in range(per):
            a, b = segs[i], segs[i + j * per]
            assert np.array_equal(a.knots, b.knots)
            assert np.max(np.abs(_turn(a.poles, 2 * math.pi * j / n) - b.poles)) < 1e-12


def test_the_lobed_driven_wheel_repeats_exactly_every_period(seed_000):
    pc, _calls, lobed, _each = seed_000
    assert pc.law.n == 2
    _repeats(lobed.profile.outer.segments, 2)


def test_the_built_driven_wheel_of_four_periods_repeats_exactly(monkeypatch):
    """Seed 002's pair as the build designs it (n = 4): its driven wheel's lobes are each other's turns by 90 deg."""
    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    base = tomllib.loads((ROOT / "parts/ncg_seed002.toml").read_text(encoding="utf-8"))
    base.pop("type")
    base.pop("meta", None)
    d = design(load_params(NoncircularPairParams, base), source=str(ROOT / "parts/ncg_seed002.toml"))
    assert d.law.n == 4 and len(d.driven.teeth) == 80
    _repeats(d.driven.profile.outer.segments, 4)


def test_the_lobed_driven_wheel_is_the_wheel_cut_tooth_by_tooth_within_the_fits_tolerance(seed_000):
    _pc, _calls, lobed, each = seed_000
    a, b = lobed.profile.outer.segments, each.profile.outer.segments
    assert len(a) == len(b)
    assert [s.poles.shape for s in a] == [s.poles.shape for s in b]
    moved = max(float(np.max(np.abs(x.poles - y.poles))) for x, y in zip(a, b))
    # the lobes cut tooth by tooth differ from one another by the fits' own choices (1e-6 mm here), within tol
    assert 1e-9 < moved < SPLINE_FIT_TOL_MM
    # the first lobe's teeth are the same cut: its pieces the same floats, but for the joints the snap moves
    per = len(a) // 2
    same = sum(np.array_equal(x.poles, y.poles) and np.array_equal(x.knots, y.knots) for x, y in zip(a[:per], b[:per]))
    assert same >= per - 2
    assert lobed.root_min_radius == pytest.approx(each.root_min_radius, abs=1e-9)
    assert len(lobed.root_gaps) == len(each.root_gaps) > 0
    assert np.allclose(lobed.root_gaps, each.root_gaps, rtol=0, atol=1e-9)


def test_every_tooth_of_the_lobed_wheel_keeps_its_own_record(seed_000):
    _pc, _calls, lobed, each = seed_000
    assert len(lobed.teeth) == len(each.teeth) == 96
    for t, u in zip(lobed.teeth, each.teeth):
        assert (t.s_centre, t.phi_centre, t.right, t.left, t.undercut, t.tip_height_mm, t.shortened) == (
            u.s_centre, u.phi_centre, u.right, u.left, u.undercut, u.tip_height_mm, u.shortened)
        assert t.tip_thickness_mm == pytest.approx(u.tip_thickness_mm, abs=1e-8)
    assert lobed.shaper_teeth == each.shaper_teeth > 0
    assert lobed.shortened_teeth == each.shortened_teeth


def test_only_one_lobe_is_generated(seed_000):
    pc, calls, _lobed, _each = seed_000
    _pc, spec, frame, _tol = calls["driven"]
    g = generate_teeth(pc, "driven", spec, frame, lobe=True)
    assert (g.z, g.lobes, len(g.sides), len(g.tips), len(g.teeth)) == (96, 2, 48, 48, 96)
    assert [t.phi_centre for t in g.teeth] == [float(x) for x in frame.phi((np.arange(96) + 0.5) * math.pi * spec.m)]
    whole = generate_teeth(pc, "driven", spec, frame)
    assert (whole.lobes, len(whole.sides)) == (1, 96)


def test_a_driver_and_a_one_period_driven_wheel_are_cut_tooth_by_tooth(seed_000, monkeypatch):
    pc, calls, _lobed, _each = seed_000
    _pc, spec, frame, _tol = calls["driver"]
    assert generate_teeth(pc, "driver", spec, frame, lobe=True).lobes == 1
    one = _cut_calls("parts/ncg_elliptical.toml", monkeypatch)["driven"]
    assert one[0].law.n == 1
    assert generate_teeth(one[0], "driven", one[1], one[2], lobe=True).lobes == 1
