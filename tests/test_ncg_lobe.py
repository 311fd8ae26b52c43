"""A wheel of equal lobes cut as one lobe and patterned (geometry.noncircular_outline.generate_gear,
gears.noncircular_teeth.generate_teeth ``lobe``; the driven wheel has the law's ``periods`` lobes, the driver
periods / n): its outline repeats exactly every lobe, it is the wheel cut tooth by tooth to within the fits'
tolerance, every tooth keeps its own record, and a wheel of one lobe (a one-period law, a driver of n = periods, a
tooth count that is no multiple of the lobes) is cut tooth by tooth as before."""

from __future__ import annotations

import dataclasses
import math
import sys
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


def _cut_calls(part: str, monkeypatch, **changed) -> dict:
    """The arguments each wheel of the part file's design (its keys ``changed``) is cut with (role -> (pc, spec,
    frame, tol))."""
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
    design(load_params(NoncircularPairParams, {**base, **changed}), source=str(ROOT / part))
    return calls


def _turn(P: np.ndarray, a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.column_stack([c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1]])


@pytest.fixture(scope="module")
def seed_000():
    """Seed 000's pair (4 periods, n = 2: a driven wheel of 96 teeth in 4 lobes, a driver of 48 in 2; a space of
    every driven lobe whose root land vanished, re-phased shapers' lifted roots): both wheels cut as the build cuts
    them and tooth by tooth."""
    mp = pytest.MonkeyPatch()
    try:
        calls = _cut_calls("parts/ncg_seed000.toml", mp)
    finally:
        mp.undo()
    pc, spec, frame, tol = calls["driven"]
    lobed = outline_module.generate_gear(pc, "driven", spec, frame, tol)
    each = outline_module.generate_gear(pc, "driven", spec, frame, tol, lobe=False)
    _pc, spec_d, frame_d, tol_d = calls["driver"]
    driver = (outline_module.generate_gear(pc, "driver", spec_d, frame_d, tol_d),
              outline_module.generate_gear(pc, "driver", spec_d, frame_d, tol_d, lobe=False))
    return pc, calls, lobed, each, driver


def _repeats(segs, n: int) -> None:
    N = len(segs)
    assert N % n == 0
    per = N // n
    for j in range(1, n):
        for i in range(per):
            a, b = segs[i], segs[i + j * per]
            assert np.array_equal(a.knots, b.knots)
            assert np.max(np.abs(_turn(a.poles, 2 * math.pi * j / n) - b.poles)) < 1e-12


def test_the_lobed_wheels_repeat_exactly_every_lobe(seed_000):
    pc, _calls, lobed, _each, (driver, _) = seed_000
    assert (pc.law.n, pc.law.periods) == (2, 4)
    _repeats(lobed.profile.outer.segments, 4)
    _repeats(driver.profile.outer.segments, 2)  # counter-clockwise on its body: each lobe the last turned on


def test_the_built_driven_wheel_of_four_periods_repeats_exactly(monkeypatch):
    """Seed 002's pair as the build designs it (n = 4): its driven wheel's lobes are each other's turns by 90 deg."""
    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    base = tomllib.loads((ROOT / "parts/ncg_seed002.toml").read_text(encoding="utf-8"))
    base.pop("type")
    base.pop("meta", None)
    d = design(load_params(NoncircularPairParams, base), source=str(ROOT / "parts/ncg_seed002.toml"))
    assert d.law.n == 4 and len(d.driven.teeth) == 80
    _repeats(d.driven.profile.outer.segments, 4)


def _same_cut(a, b, lobes: int, first: slice) -> float:
    """The greatest pole moved between two cuts of one wheel (mm); the cut lobe's pieces (``first`` of the lobes, in
    the chain) the same floats, but for the joints the snap moves."""
    assert len(a) == len(b)
    assert [s.poles.shape for s in a] == [s.poles.shape for s in b]
    per = len(a) // lobes
    lo = first.start * per
    same = sum(np.array_equal(x.poles, y.poles) and np.array_equal(x.knots, y.knots)
               for x, y in zip(a[lo:lo + per], b[lo:lo + per]))
    assert same >= per - 2
    return max(float(np.max(np.abs(x.poles - y.poles))) for x, y in zip(a, b))


def test_the_lobed_wheels_are_the_wheels_cut_tooth_by_tooth_within_the_fits_tolerance(seed_000):
    _pc, _calls, lobed, each, (driver, driver_each) = seed_000
    moved = _same_cut(lobed.profile.outer.segments, each.profile.outer.segments, 4, slice(0, 1))
    # the lobes cut tooth by tooth differ from one another by the fits' own choices (1e-6 mm here), within tol
    assert 1e-9 < moved < SPLINE_FIT_TOL_MM
    # the driver's chain runs from its last tooth: the cut lobe (teeth 0 .. 23) is the chain's second
    assert _same_cut(driver.profile.outer.segments, driver_each.profile.outer.segments, 2, slice(1, 2)) < 1e-9
    assert [t.__dict__ for t in driver.teeth[:24]] == [t.__dict__ for t in driver_each.teeth[:24]]
    assert driver.root_min_radius == pytest.approx(driver_each.root_min_radius, abs=1e-9)
    assert lobed.root_min_radius == pytest.approx(each.root_min_radius, abs=1e-9)
    assert len(lobed.root_gaps) == len(each.root_gaps) > 0
    assert np.allclose(lobed.root_gaps, each.root_gaps, rtol=0, atol=1e-9)


def test_every_tooth_of_the_lobed_wheel_keeps_its_own_record(seed_000):
    _pc, _calls, lobed, each, _driver = seed_000
    assert len(lobed.teeth) == len(each.teeth) == 96
    for t, u in zip(lobed.teeth, each.teeth):
        assert (t.s_centre, t.phi_centre, t.right, t.left, t.undercut, t.tip_height_mm, t.shortened) == (
            u.s_centre, u.phi_centre, u.right, u.left, u.undercut, u.tip_height_mm, u.shortened)
        assert t.tip_thickness_mm == pytest.approx(u.tip_thickness_mm, abs=1e-8)
    assert lobed.shaper_teeth == each.shaper_teeth > 0
    assert lobed.shortened_teeth == each.shortened_teeth


def test_only_one_lobe_is_generated(seed_000):
    pc, calls, _lobed, _each, _driver = seed_000
    _pc, spec, frame, _tol = calls["driven"]
    g = generate_teeth(pc, "driven", spec, frame, lobe=True)
    assert (g.z, g.lobes, len(g.sides), len(g.tips), len(g.teeth)) == (96, 4, 24, 24, 96)
    assert [t.phi_centre for t in g.teeth] == [float(x) for x in frame.phi((np.arange(96) + 0.5) * math.pi * spec.m)]
    whole = generate_teeth(pc, "driven", spec, frame)
    assert (whole.lobes, len(whole.sides)) == (1, 96)
    _pc, spec, frame, _tol = calls["driver"]
    g = generate_teeth(pc, "driver", spec, frame, lobe=True)
    assert (g.z, g.lobes, len(g.sides), len(g.teeth)) == (48, 2, 24, 48)
    assert [t.phi_centre for t in g.teeth] == [float(x) for x in frame.phi(np.arange(48) * math.pi * spec.m)]


def test_wheels_of_one_lobe_are_cut_tooth_by_tooth(monkeypatch):
    one = _cut_calls("parts/ncg_elliptical.toml", monkeypatch)  # one period: a 1:1 pair of ellipses
    assert (one["driven"][0].law.n, one["driven"][0].law.periods) == (1, 1)
    for role in ("driver", "driven"):
        pc, spec, frame, _tol = one[role]
        assert generate_teeth(pc, role, spec, frame, lobe=True).lobes == 1
    four = _cut_calls("parts/ncg_seed002.toml", monkeypatch)["driver"]  # n = periods = 4: one lobe a driver turn
    assert generate_teeth(four[0], "driver", four[1], four[2], lobe=True).lobes == 1


def test_a_driver_of_four_lobes_is_its_first_lobe_turned_back(monkeypatch):
    """Seed 002's law at one driver turn a driven turn (n = 1, 4 periods): the driver's 80 teeth in 4 lobes, tooth
    k + 20 j its tooth k turned clockwise j quarter turns (its body angle is pi - theta); cut so, it is the driver cut
    tooth by tooth to within the fits' tolerance and repeats exactly."""
    calls = _cut_calls("parts/ncg_seed002.toml", monkeypatch, driver_turns=1)
    pc, spec, frame, tol = calls["driver"]
    assert (pc.law.n, pc.law.periods) == (1, 4)
    lobed = outline_module.generate_gear(pc, "driver", spec, frame, tol)
    each = outline_module.generate_gear(pc, "driver", spec, frame, tol, lobe=False)
    assert len(lobed.teeth) == 80
    _repeats(lobed.profile.outer.segments, 4)
    # the chain runs counter-clockwise from the last tooth: the cut lobe (teeth 0 .. 19) is its fourth
    assert _same_cut(lobed.profile.outer.segments, each.profile.outer.segments, 4, slice(3, 4)) < SPLINE_FIT_TOL_MM
    assert [(t.s_centre, t.phi_centre, t.tip_height_mm) for t in lobed.teeth] == [
        (t.s_centre, t.phi_centre, t.tip_height_mm) for t in each.teeth]


def test_a_space_whose_root_land_vanished_at_the_lobes_boundary(seed_000, monkeypatch):
    """Seed 000's driven lobe holds one space whose feet crossed (between its teeth 11 and 12: the two fillets trimmed
    at their crossing).  The lobe cut from tooth 12 on (its teeth 12 .. 35, each from its own sides) puts that space
    last, between tooth 35 and the next lobe's first tooth, 12 turned by a lobe: the head of the lobe's first tooth is
    trimmed there, turned back, and the pattern still repeats exactly; it is the wheel cut tooth by tooth, chained from
    tooth 12, to within the fits' tolerance, its first lobe's pieces (that joint's among them) those pieces."""
    pc, calls, _lobed, each, _driver = seed_000
    _pc, spec, frame, tol = calls["driven"]
    whole = generate_teeth(pc, "driven", spec, frame, lobe=False)
    k0, per = 12, 24

    def from_tooth_12(*_args, **_kw):
        return dataclasses.replace(whole, sides=whole.sides[k0:k0 + per], tips=whole.tips[k0:k0 + per],
                                   teeth=whole.teeth[k0:] + whole.teeth[:k0], lobes=4)

    trims = []
    real_trim = outline_module._trim_pairs

    def trim(*args):
        trims.append(sys._getframe(1).f_locals["j"])  # the space's next tooth: 0 = the next lobe's first
        return real_trim(*args)

    monkeypatch.setattr(outline_module, "generate_teeth", from_tooth_12)
    monkeypatch.setattr(outline_module, "_trim_pairs", trim)
    shifted = outline_module.generate_gear(pc, "driven", spec, frame, tol).profile.outer.segments
    assert trims == [0]
    _repeats(shifted, 4)
    # the wheel cut tooth by tooth, chained from tooth 0: its pieces from tooth 12's on are the shifted chain's
    ref = each.profile.outer.segments
    assert len(ref) == len(shifted)
    N, lobe_len = len(ref), len(ref) // 4
    mid = lobe_len // 2  # a piece of the first cut lobe far from its ends
    o = min((i for i in range(N) if ref[i].poles.shape == shifted[mid].poles.shape),
            key=lambda i: float(np.max(np.abs(ref[i].poles - shifted[mid].poles)))) - mid
    moved = [float(np.max(np.abs(shifted[s].poles - ref[(s + o) % N].poles))) for s in range(N)]
    assert max(moved) < tol
    # the cut lobe's pieces (teeth 12 .. 35, each from its own sides, the trimmed head of its first tooth and the
    # tail of its last among them) are the tooth-by-tooth wheel's: tooth 36 cut on its own is tooth 12 turned, here
    assert max(moved[:lobe_len]) < 1e-9
    assert max(moved) > 1e-9  # the other lobes: tooth 12 + 24 j cut on its own differs by the fits' own choices
