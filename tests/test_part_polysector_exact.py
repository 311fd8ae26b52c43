"""The composite (polysector) gear's design and proofs, number by number (parts/polysector/design.py, contact_law.py,
mesh_proof.py, proofs.py): the synthesis of the part file (seed 003 eq. 1-4) against the part file's numbers and
the closed forms of the positions, every refusal in full and both sides of each limit of the layout (the hub, the
slot, the pin holes, the stem), the layout's dimensions worked out in the test, the outlines the design hands on;
the contact law's poles on hand-made lines, its result's weights, shares and snaps on given samples, its
refinement rule on both sides of each limit; the proof steps on a stand-in of the output writer.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``polysector_design``): each design
is made in its test (0.3 s), no CAD solid is built and no whole part; the figures are not tested (not mutated).
"""

from __future__ import annotations

import dataclasses
import importlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.polysector import EPS_S_MIN, PolysectorGeometry
from propulsor.params import load_params, read_part_file
from propulsor.parts.polysector import PolysectorParams

pd = importlib.import_module("propulsor.parts.polysector.design")
ROOT = Path(__file__).resolve().parents[1]
_, DATA = read_part_file(ROOT / "parts" / "polysector.toml")


def _p(**changes):
    """The part file's parameters (parts/polysector.toml) with ``changes``."""
    return load_params(PolysectorParams, {**DATA, **changes})


def _ns(p, **changes):
    """The fields of ``p`` as a plain namespace with ``changes`` (values the parameters' own checks refuse)."""
    return SimpleNamespace(**{**{f.name: getattr(p, f.name) for f in dataclasses.fields(p)}, **changes})


def _refusal(fn, *args):
    with pytest.raises(InputError) as e:
        fn(*args)
    return str(e.value)


def _poly(profile, tol=1e-3):
    return [np.asarray(loop.polyline(tol)) for loop in profile.loops]


def _same_profile(a, b):
    pa, pb = _poly(a), _poly(b)
    assert len(pa) == len(pb)
    for x, y in zip(pa, pb):
        assert x.shape == y.shape and np.allclose(x, y, atol=1e-12, rtol=0)


# --- design.py: synthesis (eq. 1-4) ----------------------------------------------------------------------------------

def test_synthesis_of_the_part_file_positions_by_their_closed_forms():
    """m = 3, z = 36, z2 = 40, z_усл = 36, 42, 48: e = m (z_усл − z)/2 = 0, 9, 18 mm, a = r + e + r2 = 54 + e + 60,
    i_n = r2/(r + e) = 60/(54 + e); ε_s of eq. 4 (per flow, both flows) and u_exit the geometry's own; the largest
    offset 28.26 mm (the part file's comment), where the driving corner stops reaching the gear (ε_s 1.0896)."""
    p = _p()
    geo, positions, e_max = pd.synthesis(p)
    assert (geo.m, geo.z, geo.z_c, geo.i_s, geo.z2, geo.flows, geo.thinning) == (3.0, 36, 10, 3, 40, 2, 0.1)
    assert geo.alpha == math.radians(20.0)
    assert e_max == pytest.approx(28.264027546, abs=1e-7)
    # past e_max the driving corner no longer reaches the gear's tip circle (ε_s is 1.0896 there, above 1.05)
    assert geo.epsilon_s(e_max - 1e-6)[1] == pytest.approx(1.08964, abs=1e-5)
    with pytest.raises(InputError, match="driving corner does not reach"):
        geo.epsilon_s(e_max + 1e-6)
    assert [q.k for q in positions] == [1, 2, 3]
    for q, zc, e in zip(positions, (36, 42, 48), (0.0, 9.0, 18.0)):
        assert q.z_cond == zc and type(q.z_cond) is int
        assert q.offset == e
        assert q.a == 54.0 + e + 60.0
        assert q.ratio_nominal == pytest.approx(60.0 / (54.0 + e), rel=1e-15)
        ef, eb = geo.epsilon_s(e)
        assert (q.eps_s_flow, q.eps_s) == (ef, eb) and eb == pytest.approx(2 * ef, rel=1e-15)
        assert q.u_exit == geo.exit_angle(e)
    assert [round(q.eps_s, 4) for q in positions] == [2.1387, 1.7678, 1.4565]
    # the rack's pressure angle reaches the geometry (25°: a larger base circle, another e_max)
    geo25, _, e_max25 = pd.synthesis(_p(pressure_angle_deg=25.0))
    assert geo25.alpha == math.radians(25.0) and e_max25 != pytest.approx(e_max, abs=0.1)
    # a position at 54 (e = 27 mm) is within e_max: accepted (the part file's note: it fails later, tip on tip)
    assert pd.synthesis(_p(conditional_teeth=[54]))[1][0].offset == 27.0


def test_synthesis_refusals_in_full_and_both_sides():
    p = _p()
    s = pd.synthesis
    assert _refusal(s, _p(conditional_teeth=[])) == "conditional_teeth = []: needs at least one position"
    assert _refusal(s, _ns(p, conditional_teeth=[36, 42.0])) == "conditional_teeth[2] = 42.0: must be a whole number"
    assert _refusal(s, _ns(p, conditional_teeth=[36, True])) == "conditional_teeth[2] = True: must be a whole number"
    assert _refusal(s, _p(conditional_teeth=[36, 30])) == (
        "conditional_teeth[2] = 30: must be >= the blank's z = 36 (offset >= 0)")
    assert _refusal(s, _p(conditional_teeth=[40])) == (
        "conditional_teeth[1] = 40: must be a multiple of flows·i_s = 6 (all sectors in tooth phase with the gear); "
        "nearest 36 or 42")
    assert _refusal(s, _p(conditional_teeth=[36, 42, 50])) == (
        "conditional_teeth[3] = 50: must be a multiple of flows·i_s = 6 (all sectors in tooth phase with the gear); "
        "nearest 48 or 54")
    # one flow: multiples of 3; the largest offset is 0.8597 mm (ε_s of one flow only)
    assert _refusal(s, _p(flows=1, conditional_teeth=[36, 39])) == (
        "conditional_teeth[2] = 39: offset e = 4.5 mm is past the largest offset of eq. 1/3 (ε_s >= 1.05): "
        "e_max = 0.8597 mm (z_усл <= 36.57)")
    # 0.26 mm past the largest offset (one flow of 11-tooth sectors: e_max = 4.2366 mm; z_усл = 39 is e = 4.5)
    assert _refusal(s, _p(flows=1, sector_teeth=11, conditional_teeth=[36, 39])) == (
        "conditional_teeth[2] = 39: offset e = 4.5 mm is past the largest offset of eq. 1/3 (ε_s >= 1.05): "
        "e_max = 4.2366 mm (z_усл <= 38.82)")
    assert _refusal(s, _p(conditional_teeth=[60])) == (
        "conditional_teeth[1] = 60: offset e = 36 mm is past the largest offset of eq. 1/3 (ε_s >= 1.05): "
        "e_max = 28.2640 mm (z_усл <= 54.84)")
    # the library's refusals under the part file's names
    assert _refusal(s, _p(sector_teeth=12)) == (
        "sector_teeth = 12: too large for the gaps: eq. 2 z_c = z/i_s − (1…3) ≤ 11")
    assert _refusal(s, _p(blank_teeth=35)) == (
        "blank_teeth = 35: must be a multiple of i_s·flows = 6 (sectors equally spaced in tooth phase)")
    assert _refusal(s, _p(sector_teeth=2)) == (
        "sector_teeth = 2: eq. 4: ε_s = 0.8054 < 1.05 already at e = 0; more teeth per sector or more sectors are "
        "needed")
    assert _refusal(s, _ns(p, flows=3)) == "flows = 3: must be 1 or 2"


def test_synthesis_refuses_an_epsilon_below_the_minimum_at_a_position(monkeypatch):
    """The last refusal (ε_s of a position below 1.05) cannot happen below e_max; with the geometry's ε_s given
    it is the position's, 1.05 itself accepted."""
    monkeypatch.setattr(PolysectorGeometry, "max_offset", lambda self, eps_min=EPS_S_MIN: 30.0)
    eps = {0.0: (1.0, 2.0), 9.0: (0.525, EPS_S_MIN), 18.0: (0.52, 1.04)}
    monkeypatch.setattr(PolysectorGeometry, "epsilon_s", lambda self, e: eps[e])
    assert _refusal(pd.synthesis, _p()) == "conditional_teeth[3] = 48: ε_s = 1.0400 < 1.05 (eq. 4)"
    geo, positions, e_max = pd.synthesis(_p(conditional_teeth=[36, 42]))
    assert e_max == 30.0 and [(q.eps_s_flow, q.eps_s) for q in positions] == [(1.0, 2.0), (0.525, EPS_S_MIN)]


# --- design.py: layout ----------------------------------------------------------------------------------------------

def _layout(p):
    geo, positions, _ = pd.synthesis(p)
    return pd.layout(p, geo, positions)


def test_layout_of_the_part_file_worked_out():
    """r_f = r − 1.25 m = 50.25, r_rim = r_f − 2.5 m = 42.75; R_hub = r + e_lo − 1.25 m; the stem end y_end =
    shaft/2 + 2 web − e_lo; the bolt at R_hub − web − d_bolt/2, its slot from there less e_hi to less e_lo; the pin
    beside the slot at d_bolt/2 + web + d_pin/2, above the stem end by web + d_pin/2."""
    lay = _layout(_p())
    assert (lay.r_rim, lay.w_stem, lay.y_end, lay.d_bolt, lay.y_slot0, lay.y_slot1, lay.d_pin, lay.x_pin,
            lay.y_pin, lay.R_hub, lay.d_bore, lay.rho_bolt) == (
        42.75, 22.0, 13.0, 5.5, 27.5, 45.5, 4.0, 6.75, 17.0, 50.25, 18.0, 45.5)
    # least offset 9, largest 18, other holes and webs, rim 3 modules, positions given out of order
    lay = _layout(_p(conditional_teeth=[48, 42], web_mm=2.5, bolt_d_mm=6.0, pin_d_mm=3.0, rim_modules=3.0,
                     shaft_d_mm=16.0, stem_width_mm=30.0))
    R_hub = 54.0 + 9.0 - 3.75
    rho = R_hub - 2.5 - 3.0
    assert lay.R_hub == R_hub and lay.rho_bolt == rho
    assert lay.r_rim == 50.25 - 9.0
    assert lay.y_end == 8.0 + 5.0 - 9.0
    assert (lay.y_slot0, lay.y_slot1) == (rho - 18.0, rho - 9.0)
    assert lay.x_pin == 3.0 + 2.5 + 1.5 and lay.y_pin == lay.y_end + 2.5 + 1.5
    assert (lay.w_stem, lay.d_bolt, lay.d_pin, lay.d_bore) == (30.0, 6.0, 3.0, 16.0)


def test_layout_refuses_a_slot_reaching_the_stem_end_on_its_limit():
    """The slot from rho_bolt − e_hi must clear the stem end + web: R_hub − shaft/2 >= e_hi − e_lo + d_bolt +
    4 web; the part file's R_hub = 50.25 needs 31.5 mm: a shaft of 37.5 mm is the limit (exactly, in binary)."""
    assert _layout(_p(shaft_d_mm=37.5)).d_bore == 37.5
    assert _refusal(_layout, _p(shaft_d_mm=37.6)) == (
        "conditional_teeth = [36, 42, 48]: offset range 18 mm too large for the hub: the slot would reach the stem "
        "end (needs R_hub − shaft/2 = 31.450 mm >= 31.500 mm)")
    # least offset 9: R_hub = 59.25 needs 9 + 5.5 + 8 = 22.5 mm: a shaft of 73.5 is the limit
    assert _layout(_p(conditional_teeth=[48, 42], shaft_d_mm=73.5)).y_slot0 == 54.5 - 18.0
    assert _refusal(_layout, _p(conditional_teeth=[48, 42], shaft_d_mm=73.6)) == (
        "conditional_teeth = [48, 42]: offset range 9 mm too large for the hub: the slot would reach the stem "
        "end (needs R_hub − shaft/2 = 22.450 mm >= 22.500 mm)")


def test_layout_refuses_a_stem_narrower_than_slot_pin_and_webs():
    """2 (d_bolt/2 + web + d_pin/2 + d_pin/2 + web) = 21.5 mm for the part file; 23.5 with a 7.5 mm bolt."""
    assert _layout(_p(stem_width_mm=21.5)).w_stem == 21.5
    assert _refusal(_layout, _p(stem_width_mm=21.4)) == (
        "stem_width_mm = 21.4: must be >= 21.500 mm (slot, pin and webs side by side)")
    assert _layout(_p(stem_width_mm=23.5, bolt_d_mm=7.5)).x_pin == 7.75
    assert _refusal(_layout, _p(stem_width_mm=23.4, bolt_d_mm=7.5)) == (
        "stem_width_mm = 23.4: must be >= 23.500 mm (slot, pin and webs side by side)")


def test_layout_refuses_pin_holes_closer_than_a_pin_and_a_web():
    """Offsets 0, 9, 18 (given out of order): neighbours 9 mm apart need d_pin + web <= 9."""
    kw = dict(conditional_teeth=[48, 36, 42], stem_width_mm=30.0)
    assert _layout(_p(pin_d_mm=7.0, **kw)).d_pin == 7.0
    assert _refusal(_layout, _p(pin_d_mm=7.1, **kw)) == (
        "conditional_teeth = [48, 36, 42]: offsets 0 and 9 mm: pin holes closer than d_pin + web = 9.1 mm")
    # 12 mm apart: 36 and 44 would be out of phase; 36 and 48 with a web of 2.5: d_pin <= 15.5 by spacing alone
    kw = dict(conditional_teeth=[42, 48], stem_width_mm=30.0, web_mm=2.5)
    assert _refusal(_layout, _p(pin_d_mm=6.6, **kw)) == (
        "conditional_teeth = [42, 48]: offsets 9 and 18 mm: pin holes closer than d_pin + web = 9.1 mm")
    assert _layout(_p(pin_d_mm=6.5, **kw)).d_pin == 6.5


def test_layout_refuses_a_pin_hole_off_the_hub_disc_on_its_limit():
    """Offsets 0 and 18 mm: the pin hole of 18 mm at (x_pin, y_pin + 18) plus d_pin/2 + web must stay inside
    R_hub = 50.25: hypot(4.75 + r_p, 33 + r_p) + r_p + 2 = 50.25 solved for r_p in the test."""
    from scipy.optimize import brentq

    rp = brentq(lambda r: math.hypot(4.75 + r, 33.0 + r) + r + 2.0 - 50.25, 1.0, 10.0, xtol=1e-12)
    assert rp == pytest.approx(6.8, abs=0.1)
    kw = dict(conditional_teeth=[48, 36], stem_width_mm=60.0)
    assert _layout(_p(pin_d_mm=2 * rp - 0.01, **kw)).d_pin == 2 * rp - 0.01
    d = round(2 * rp + 0.01, 3)
    assert _refusal(_layout, _p(pin_d_mm=d, **kw)) == (
        "conditional_teeth = [48, 36]: the pin hole of offset 18 mm falls off the hub disc (R_hub = 50.250 mm)")


def test_layout_guards_that_hold_by_construction(monkeypatch):
    """The slot's end, the pin hole of the least offset and the stems cannot meet the roots and the shaft (their
    refusals went as dead code): y_slot1 + d_bolt/2 = r_f − web, hypot(x_pin, y_pin + e_lo) − d_pin/2 − web
    >= shaft/2 + 2 web, y_end + e_lo = shaft/2 + 2 web, for any parameters (here three sets)."""
    for kw in ({}, dict(conditional_teeth=[48, 42], web_mm=2.5, shaft_d_mm=16.0, stem_width_mm=30.0),
               dict(module_mm=2.0, blank_teeth=48, sector_teeth=14, gear_teeth=30, conditional_teeth=[54, 60])):
        p = _p(**kw)
        geo, positions, _ = pd.synthesis(p)
        lay = pd.layout(p, geo, positions)
        e_lo = min(q.offset for q in positions)
        r_f = geo.r - 1.25 * p.module_mm
        assert lay.y_slot1 + p.bolt_d_mm / 2 == pytest.approx(r_f - p.web_mm, abs=1e-12)
        assert lay.y_end + e_lo == pytest.approx(p.shaft_d_mm / 2 + 2 * p.web_mm, abs=1e-12)
        assert math.hypot(lay.x_pin, lay.y_pin + e_lo) - p.pin_d_mm / 2 - p.web_mm >= p.shaft_d_mm / 2 + 2 * p.web_mm


def test_a_slot_ending_a_web_below_the_roots_is_not_refused_for_rounding():
    """A web of 3.1 mm at z_усл = 48 (e = 18 mm): the slot's outer end y_slot1 + d_bolt/2 is r_f − web = 47.15 mm
    but 7e-15 mm above it in floating point; it was refused ('the slot reaches the tooth roots')."""
    for bolt in (5.5, 6.6, 4.5):
        p = _p(web_mm=3.1, bolt_d_mm=bolt, conditional_teeth=[48], stem_width_mm=40.0)
        lay = _layout(p)
        assert lay.y_slot1 + bolt / 2 == pytest.approx(50.25 - 3.1, abs=1e-12)
        assert pd.design(p).layout == lay


# --- design.py: the design's outlines ---------------------------------------------------------------------------------

def test_design_hands_on_the_outlines_of_the_library():
    from propulsor.geometry.polysector_outline import blank_outline, hub_profile, mating_gear, place, sector_profile

    p = _p()
    dd = pd.design(p)
    geo, positions, e_max = pd.synthesis(p)
    assert dd.p is p and dd.positions == positions and dd.e_max == e_max
    assert dd.geo == geo
    lay = pd.layout(p, geo, positions)
    assert dd.layout == lay
    blank = blank_outline(36, 3.0, 0.1)
    _same_profile(dd.blank.profile, blank.profile)
    _same_profile(dd.sector, sector_profile(blank, 10, lay))
    assert len(dd.hubs) == 2
    third = 2 * math.pi / 3
    for f, base in ((0, 0.0), (1, math.pi / 3)):
        _same_profile(dd.hubs[f], hub_profile(lay, [base, base + third, base + 2 * third], [0.0, 9.0, 18.0], True))
    # z_c = 10, even: phase π/2 (a space of the sector on the mid-line, a gear tooth facing −x)
    assert dd.gear_phase == math.pi / 2
    gear, gear_prof = mating_gear(40, 3.0, 0.1, 20.0, math.pi / 2, True)
    _same_profile(dd.gear.profile, gear.profile)
    _same_profile(dd.gear_profile, gear_prof)
    assert dd.sector_angles(1) == [0.0, third, 2 * third]
    assert dd.sector_angles(2) == pytest.approx([math.pi / 3, math.pi, 5 * math.pi / 3], abs=1e-15)
    for flow in (1, 2):
        placed = dd.placed_sectors(positions[2], flow)
        assert len(placed) == 3
        for s, ang in zip(placed, dd.sector_angles(flow)):
            _same_profile(s, place(dd.sector, ang, 18.0))


def test_design_of_an_odd_sector_one_flow_no_keyways():
    from propulsor.geometry.polysector_outline import hub_profile, mating_gear

    p = _p(sector_teeth=11, flows=1, conditional_teeth=[36], keyways=False, gear_bore_mm=25.0)
    dd = pd.design(p)
    # z_c = 11, odd: a space of the gear faces −x: phase π/2 + π/z2
    assert dd.gear_phase == math.pi / 2 + math.pi / 40
    assert len(dd.hubs) == 1
    _same_profile(dd.hubs[0], hub_profile(dd.layout, [0.0, 2 * math.pi / 3, 4 * math.pi / 3], [0.0], False))
    _same_profile(dd.gear_profile, mating_gear(40, 3.0, 0.1, 25.0, math.pi / 2 + math.pi / 40, False)[1])
    assert len(dd.gear_profile.loops) == len(mating_gear(40, 3.0, 0.1, 25.0, 0.0, False)[1].loops)


def test_design_names_the_gear_bore_and_feasible_refuses_what_design_refuses():
    assert _refusal(pd.design, _p(gear_bore_mm=200.0)) == (
        "gear_bore_mm = 200.0: must leave a rim of one module under the root: < 106.500 mm")
    assert pd.feasible(_p()) is None
    assert _refusal(pd.feasible, _p(stem_width_mm=21.4)) == (
        "stem_width_mm = 21.4: must be >= 21.500 mm (slot, pin and webs side by side)")


def test_one_flow_collisions_measure_each_neighbour_at_every_position(monkeypatch):
    """The gap of sector i to sector i + 1 (mod i_s) of flow 1, on the outer outlines at 0.01 mm, at every
    position; refused below web/2 ('nearly touch'), at or below 0 ('collide'), web/2 itself accepted."""
    dd = pd.design(_p())
    dd3 = pd.design(_p(web_mm=3.0, stem_width_mm=30.0))
    calls = []
    gaps = iter([])

    def gap(A, B):
        calls.append((A, B))
        return next(gaps)

    monkeypatch.setattr(pd, "_poly_gap", gap)
    gaps = iter([5.0] * 9)
    pd._one_flow_collisions(dd)
    assert len(calls) == 9
    for n, pos in enumerate(dd.positions):
        secs = [s.outer.polyline(0.01) for s in dd.placed_sectors(pos, 1)]
        for i in range(3):
            A, B = calls[3 * n + i]
            assert np.array_equal(A, secs[i]) and np.array_equal(B, secs[(i + 1) % 3])
    gaps = iter([5.0, 5.0, 5.0, 1.0, 1.0, 1.0, 0.99])
    msg = _refusal(pd._one_flow_collisions, dd)
    assert msg == ("sector_teeth = 10: sectors of one flow nearly touch at offset 18 mm (gap 0.990 mm < 1 mm)")
    gaps = iter([0.0])
    assert _refusal(pd._one_flow_collisions, dd) == (
        "sector_teeth = 10: sectors of one flow collide at offset 0 mm (gap 0.000 mm < 1 mm)")
    gaps = iter([-0.5])
    assert "collide" in _refusal(pd._one_flow_collisions, dd)
    gaps = iter([1.5] * 8 + [1.49])
    assert _refusal(pd._one_flow_collisions, dd3) == (
        "sector_teeth = 10: sectors of one flow nearly touch at offset 18 mm (gap 1.490 mm < 1.5 mm)")


def _stem_gap(hw, y):
    """Chord between neighbouring stems' end corners (±hw, y) of one flow of three: 2 hypot(hw, y) sin(π/3 −
    atan(hw/y))."""
    return 2.0 * math.hypot(hw, y) * math.sin(math.pi / 3 - math.atan(hw / y))


def test_one_flow_collisions_of_the_part_file_and_the_vertex_gap():
    """The part file's sectors of one flow are 11.517 mm apart at e = 0: their stems' end corners (±11, 13) turned
    by 120°; ``_poly_gap`` is the least distance between the vertices."""
    dd = pd.design(_p())
    for pos in dd.positions:
        secs = [s.outer.polyline(0.01) for s in dd.placed_sectors(pos, 1)]
        A, B = np.asarray(secs[0]), np.asarray(secs[1])
        if pos.offset == 0.0:
            brute = float(np.min(np.linalg.norm(A[:, None, :] - B[None, :, :], axis=2)))
            assert pd._poly_gap(A, B) == pytest.approx(brute, abs=1e-12)
        assert pd._poly_gap(A, B) == pytest.approx(_stem_gap(11.0, 13.0 + pos.offset), abs=1e-9)
    assert _stem_gap(11.0, 13.0) == pytest.approx(11.5167, abs=1e-4)
    sq = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    assert pd._poly_gap(sq, sq + [4.0, 0.5]) == pytest.approx(math.hypot(3.0, 0.5), abs=1e-15)
    assert type(pd._poly_gap(sq, sq + 3.0)) is float
    assert pd._one_flow_collisions(dd) is None


def test_stems_of_one_flow_nearly_touching_are_refused_on_the_web_limit():
    """Wide stems: the corners (±w/2, 13) of neighbouring stems come within web/2 = 1 mm at a width solved in the
    test; 0.02 mm narrower is accepted, 0.02 mm wider refused with the gap measured."""
    from scipy.optimize import brentq

    hw = brentq(lambda h: _stem_gap(h, 13.0) - 1.0, 15.0, 22.4, xtol=1e-12)
    assert pd.design(_p(stem_width_mm=round(2 * hw - 0.02, 3))).layout.w_stem == round(2 * hw - 0.02, 3)
    w = round(2 * hw + 0.02, 3)
    assert _refusal(pd.design, _p(stem_width_mm=w)) == (
        f"sector_teeth = 10: sectors of one flow nearly touch at offset 0 mm (gap {_stem_gap(w / 2, 13.0):.3f} mm "
        f"< 1 mm)")


# --- contact_law.py ----------------------------------------------------------------------------------------------------

cl = importlib.import_module("propulsor.parts.polysector.contact_law")


def _bodies(k, chord=1e-3, margin=0.05, **changes):
    dd = pd.design(_p(**changes))
    return dd, dd.positions[k], cl.position_bodies(dd, dd.positions[k], chord, margin)


def test_wrap_to_minus_pi_up_to_pi():
    assert cl._wrap(math.pi) == -math.pi and cl._wrap(-math.pi) == -math.pi
    assert np.allclose(cl._wrap([1.5 * math.pi, -1.5 * math.pi, 0.25, 2 * math.pi]),
                       [-0.5 * math.pi, 0.5 * math.pi, 0.25, 0.0], atol=1e-15)


def test_position_bodies_of_the_part_file():
    """One sector period 2π/6; the sectors whose mid-line (wrapped: 0, 2π/3, −2π/3 of flow 1, π/3, −π, −π/3 of
    flow 2) sweeps within u_exit + margin of the line of centres over the period; the gear cropped about O2."""
    from propulsor import policy
    from propulsor.checks.motion import crop_to_sector, outline
    from propulsor.geometry.polysector_outline import place

    dd, pos, b = _bodies(2)
    assert (b.a, b.offset, b.i_n) == (132.0, 18.0, 60.0 / 72.0) and b.period == 2 * math.pi / 6
    assert (b.r_a, b.r_a2, b.chord_tol) == (57.0, 63.0, 1e-3)
    assert b.r_b == 54.0 * math.cos(math.radians(20.0)) and b.r_b2 == 60.0 * math.cos(math.radians(20.0))
    assert b.w_max == 2 * math.pi / 40
    third = 2 * math.pi / 3
    assert b.angles == [(0.0, 1), (third, 1), (2 * third, 1), (math.pi / 3, 2), (math.pi / 3 + third, 2),
                        (math.pi / 3 + 2 * third, 2)]
    assert sorted(b.sectors) == [0, 5]   # u_exit = 0.770: within −1.870 … 0.820
    for j in b.sectors:
        ref = outline(place(dd.sector, b.angles[j][0], 18.0), 1e-3, policy.MOTION_MAX_SEGMENT_MM)
        assert np.array_equal(b.sectors[j].points, ref.points)
    Z = 2.0 * math.asin((57.0 + 18.0) / 132.0) + 0.2
    t_hi = b.period / b.i_n + 4 * math.pi / 40
    full = outline(dd.gear_profile, 1e-3, policy.MOTION_MAX_SEGMENT_MM)
    ref = outline(crop_to_sector(full.section, math.pi - Z - 0.1, math.pi + Z + t_hi, 60.0 - 4.5, 63.0 + 3.0),
                  1e-3, policy.MOTION_MAX_SEGMENT_MM)
    assert np.array_equal(b.gear.points, ref.points)
    r = np.hypot(b.gear.points[:, 0], b.gear.points[:, 1])
    assert r.min() >= 55.5 - 5e-3 and r.max() <= 63.0 + 1e-6 and len(b.gear.points) < len(full.points)
    # the margin on both sides of 0.2770: mid-lines −π/3 + π/3 = 0 ... the sectors at ±π/3 and −2π/3 come in
    assert sorted(cl.position_bodies(dd, pos, 1e-3, 0.27).sectors) == [0, 5]
    assert sorted(cl.position_bodies(dd, pos, 1e-3).sectors) == [0, 5]  # the default margin, 0.05
    assert sorted(cl.position_bodies(dd, pos, 1e-3, 0.28).sectors) == [0, 2, 3, 5]
    # e = 0: u_exit = 1.139 takes four sectors with the default margin
    dd, pos, b = _bodies(0)
    assert sorted(b.sectors) == [0, 2, 3, 5] and b.offset == 0.0 and b.a == 114.0
    assert b.i_n == 40 / 36 and Z != 2.0 * math.asin(min(1.0, 57.0 / 114.0)) + 0.2


def test_pole_of_a_line_cutting_the_line_of_centres():
    """P = T − T_y d/d_y on the x axis; i_t = (a − P_x)/P_x; of two lines the one most parallel to the normal;
    a line parallel to the axis (|d_y| < 1e-12) has no pole."""
    # line 0 crosses the axis at x = 55 − 40·0.6/0.8 = 25
    lines = [(np.array([55.0, 40.0]), np.array([0.6, 0.8])), (np.array([10.0, 10.0]), np.array([1.0, 0.0]))]
    assert cl._pole(lines, (0.6, 0.8), 100.0) == pytest.approx(75.0 / 25.0, rel=1e-15)
    assert cl._pole(lines, (-0.6, -0.8), 100.0) == pytest.approx(3.0, rel=1e-15)  # the sense does not matter
    assert math.isnan(cl._pole(lines, (1.0, 0.0), 100.0))  # the horizontal line is picked: no pole
    tilt = [(np.array([10.0, 1.0]), np.array([1.0, 2e-12]))]
    assert cl._pole(tilt, (1.0, 0.0), 100.0) == pytest.approx((100.0 - (10.0 - 5e11)) / (10.0 - 5e11), rel=1e-9)
    assert math.isnan(cl._pole([(np.array([10.0, 1.0]), np.array([1.0, 0.9e-12]))], (1.0, 0.0), 100.0))


def _tangent_pole(P, Q, r, pick, a):
    """The x-axis crossing of the tangent from P to the circle (Q, r) whose direction is nearer ``pick``: tangent
    points by the right angle at T, (T − Q)·(P − T) = 0, solved as Q + r (cos, sin)(γ) with γ = β ± acos(r/d)."""
    v = np.subtract(P, Q)
    d = float(np.hypot(*v))
    best = None
    for g in (math.atan2(v[1], v[0]) + math.acos(r / d), math.atan2(v[1], v[0]) - math.acos(r / d)):
        T = np.asarray(Q) + r * np.array([math.cos(g), math.sin(g)])
        assert abs(np.dot(T - Q, P - T)) < 1e-9
        u = (P - T) / np.hypot(*(P - T))
        s = abs(u @ np.asarray(pick))
        if best is None or s > best[0]:
            best = (s, T, u)
    _, T, u = best
    px = T[0] - T[1] * u[0] / u[1]
    return (a - px) / px


def test_pole_ratio_of_a_corner_on_an_involute_of_a_base_circle():
    a, rb2 = 132.0, 56.38
    O2 = np.array([a, 0.0])
    C = np.array([70.0, 8.0])
    for normal in ((1.0, 0.3), (1.0, -0.3)):
        assert cl.pole_ratio(C, O2, rb2, normal, a) == pytest.approx(_tangent_pole(C, O2, rb2, normal, a), rel=1e-12)
    assert cl.pole_ratio(C, O2, rb2, (1.0, 0.3), a) != pytest.approx(cl.pole_ratio(C, O2, rb2, (1.0, -0.3), a))
    # every normal direction, those near the bisector of the two tangents included
    for t in np.linspace(0.0, math.pi, 181)[:-1]:
        n = (math.cos(t), math.sin(t))
        for P, Q, r in ((C, O2, rb2), (np.array([30.0, 70.0]), np.array([5.0, -3.0]), 40.0)):
            assert cl.pole_ratio(P, Q, r, n, a) == pytest.approx(_tangent_pole(P, Q, r, n, a), rel=1e-9)
    # a corner exactly on the base circle: no tangent (nan) either way
    assert math.isnan(cl.pole_ratio((40.0, 0.0), (0.0, 0.0), 40.0, (0.0, 1.0), a))
    assert math.isnan(cl.pole_ratio([40, 0], [0, 0], 40.0, (0.0, 1.0), a))
    assert cl.pole_ratio([70, 8], [132, 0], rb2, (1.0, 0.3), a) == pytest.approx(
        cl.pole_ratio(C, O2, rb2, (1.0, 0.3), a), rel=1e-15)
    # on the base circle or inside it: no tangent
    assert math.isnan(cl.pole_ratio(O2 + [-rb2, 0.0], O2, rb2, (1.0, 0.0), a))
    assert math.isfinite(cl.pole_ratio(O2 + [-rb2 - 1e-6, 5.0], O2, rb2, (0.0, 1.0), a))
    assert math.isnan(cl.pole_ratio(O2 + [-10.0, 0.0], O2, rb2, (1.0, 0.0), a))
    # a corner about another centre (a sector's O' off the axis)
    Os = np.array([17.0, 4.0])
    assert cl.pole_ratio(C, Os, 50.0, (0.2, 1.0), a) == pytest.approx(_tangent_pole(C, Os, 50.0, (0.2, 1.0), a),
                                                                      rel=1e-12)


def test_flank_ratio_is_the_internal_common_tangents_pole():
    """Centres on the axis: both internal tangents cut it at O1P = a r_b/(r_b + r_b2): i_t = r_b2/r_b (eq. 7 at
    e = 0).  Off the axis: through the internal centre of similitude H = (r_b2 O' + r_b O2)/(r_b + r_b2), the
    tangent from H to the base circle about O' nearer the normal."""
    rb, rb2, a = 50.74, 56.38, 114.0
    O2 = np.array([a, 0.0])
    assert cl.flank_ratio((0.0, 0.0), rb, O2, rb2, (1.0, 0.4), a) == pytest.approx(rb2 / rb, rel=1e-14)
    assert cl.flank_ratio((0.0, 0.0), rb, O2, rb2, (1.0, -0.4), a) == pytest.approx(rb2 / rb, rel=1e-14)
    Os = np.array([17.0, 5.0])
    a = 140.0
    O2 = np.array([a, 0.0])
    H = (rb2 * Os + rb * O2) / (rb + rb2)
    for t in np.linspace(0.0, math.pi, 181)[:-1]:
        normal = (math.cos(t), math.sin(t))
        assert cl.flank_ratio(Os, rb, O2, rb2, normal, a) == pytest.approx(_tangent_pole(H, Os, rb, normal, a),
                                                                           rel=1e-9)
    # base circles that touch or cross have no internal tangent
    assert math.isnan(cl.flank_ratio((0.0, 0.0), 50.0, (100.0, 0.0), 50.0, (0.0, 1.0), 100.0))
    assert math.isfinite(cl.flank_ratio((0.0, 0.0), 50.0, (100.0 + 1e-6, 0.0), 50.0, (1.0, 1.0), 100.0))
    assert math.isnan(cl.flank_ratio((0.0, 0.0), 50.0, (90.0, 0.0), 50.0, (0.0, 1.0), 90.0))


def _res(phi, theta, kind, driver=None, i_n=0.8, step_min=0.01, snap=0.001, i_t=None):
    n = len(phi)
    i_t = np.full(n, i_n) if i_t is None else np.asarray(i_t, float)
    return cl.LawResult(np.asarray(phi, float), np.asarray(theta, float),
                        np.zeros(n, int) if driver is None else np.asarray(driver), np.asarray(kind), i_t,
                        (i_n - i_t) / i_n, i_n, step_min, snap, 7)


def test_law_result_weights_shares_tips_snaps_on_given_samples():
    phi = [0.0, 0.1, 0.11, 0.12, 0.4]
    th = [0.0, 0.125, 0.1375, 0.16, 0.51]
    law = _res(phi, th, [0, 1, 3, 3, 2], i_t=[0.8, 0.8, np.nan, 0.5, 1.0])
    assert np.allclose(law.te, np.array(th) - np.array(phi) / 0.8, atol=1e-15)
    assert np.allclose(law.weights(), [0.05, 0.055, 0.01, 0.145, 0.14], atol=1e-15)
    sh = law.shares()
    assert list(sh) == ["flank", "sector_tip", "gear_tip", "tip_tip"]
    assert sh == pytest.approx({"flank": 0.125, "sector_tip": 0.1375, "gear_tip": 0.35, "tip_tip": 0.3875}, abs=1e-12)
    assert law.tip_tip_angle() == pytest.approx(0.155, abs=1e-15)
    assert np.allclose(law.jumps(), [0.0, 0.0, 0.0225 - 0.0125, 0.35 - 0.35], atol=1e-15)
    # fine steps (<= 0.01 (1 + 1e-9)): the second and third; the third jumps 0.01 beyond its advance
    assert law.snap_max() == pytest.approx(0.01, abs=1e-15)
    assert law.ratio_error_max() == pytest.approx(0.375, abs=1e-15)  # |0.8 − 0.5|/0.8, NaN left out
    assert law.at(np.array([0.0, 0.104, 0.106, 0.39, 5.0])).tolist() == [0, 1, 2, 4, 4]
    assert law.at(np.array([0.0])).dtype.kind == "i"
    # a step just over the finest is not counted; no fine step at all: no snap
    assert _res([0.0, 0.0100001, 0.02], [0.0, 0.5, 0.6], [0, 0, 0]).snap_max() == pytest.approx(0.1 - 0.0099999 / 0.8,
                                                                                          abs=1e-12)
    assert _res([0.0, 0.010000000009], [0.0, 0.5], [0, 0]).snap_max() == pytest.approx(0.5 - 0.0125, abs=1e-9)
    assert _res([0.0, 0.1], [0.0, 0.5], [0, 0]).snap_max() == 0.0
    assert math.isnan(_res([0.0, 0.005], [0.0, np.nan], [0, 3]).snap_max())
    assert type(_res([0.0, 0.005, 0.01], [0.0, 0.1, 0.2], [0, 0, 0]).snap_max()) is float


def _s(phi, theta, driver=0, kind=0, i_t=0.8, sectors=None):
    return cl._Sample(phi, theta, driver, kind, i_t, (driver,) if sectors is None else sectors)


def test_refine_on_both_sides_of_each_limit():
    from propulsor import policy

    r, i_n, snap = cl._refine, 0.8, 1e-3
    a = _s(0.0, 0.0)
    assert not r(a, _s(0.08, 0.1), i_n, snap)
    assert r(a, _s(0.08, math.nan), i_n, snap) and r(_s(0.0, math.nan), _s(0.08, 0.1), i_n, snap)
    # a hand-over: neither driver among the other's sectors; two sectors sharing the load are no hand-over
    assert r(a, _s(0.08, 0.1, driver=1), i_n, snap)
    assert not r(a, _s(0.08, 0.1, driver=1, sectors=(0, 1)), i_n, snap)
    assert not r(_s(0.0, 0.0, sectors=(0, 1)), _s(0.08, 0.1, driver=1), i_n, snap)
    assert r(a, _s(0.08, 0.1, kind=1), i_n, snap) and r(_s(0.0, 0.0, kind=3), _s(0.08, 0.1, kind=3), i_n, snap)
    assert not r(_s(0.0, 0.0, kind=2), _s(0.08, 0.1, kind=2), i_n, snap)
    # the gear's advance beyond φ/i_n: the snap tolerance on both sides
    assert not r(_s(0.0, 0.0, i_t=0.08 / 0.10099), _s(0.08, 0.10099, i_t=0.08 / 0.10099), i_n, snap)
    assert r(a, _s(0.08, 0.1 + 1.01e-3), i_n, snap)
    assert r(a, _s(0.08, 0.1 - 1.01e-3), i_n, snap)
    # the gear standing or turning back; an end without a ratio
    assert r(_s(0.0, 0.0), _s(1e-4, 0.0), i_n, 1.0) and r(_s(0.0, 0.0), _s(1e-4, -1e-5), i_n, 1.0)
    assert r(a, _s(0.08, 0.1, i_t=math.nan), i_n, snap) and r(_s(0.0, 0.0, i_t=math.nan), _s(0.08, 0.1), i_n, snap)
    # the step's own ratio against the mean of its ends: split above 1 % of i_n
    lim = policy.POLYSECTOR_LAW_RATIO_SPLIT * i_n
    assert lim == 0.008
    sec = 0.08 / 0.1
    assert not r(_s(0.0, 0.0, i_t=sec + 0.0079), _s(0.08, 0.1, i_t=sec + 0.0079), i_n, 1.0)
    assert r(_s(0.0, 0.0, i_t=sec + 0.0081), _s(0.08, 0.1, i_t=sec + 0.0081), i_n, 1.0)
    assert r(_s(0.0, 0.0, i_t=sec - 0.0081), _s(0.08, 0.1, i_t=sec - 0.0081), i_n, 1.0)
    assert not r(_s(0.0, 0.0, i_t=sec - 0.0079), _s(0.08, 0.1, i_t=sec - 0.0079), i_n, 1.0)
    assert not r(_s(0.0, 0.0, i_t=sec - 0.0158), _s(0.08, 0.1, i_t=sec + 0.0158), i_n, 1.0)  # the mean is sec
    # exactly on each limit (binary-exact numbers): not refined
    assert abs(0.625 - 0.25 / 0.5) == 0.125
    assert not r(_s(0.0, 0.0, i_t=0.4), _s(0.25, 0.625, i_t=0.4), 0.5, 0.125)
    assert r(_s(0.0, 0.0, i_t=0.4), _s(0.25, 0.625, i_t=0.4), 0.5, 0.1249999)


class _FakeLaw:
    """ContactLaw.pose replaced by a given law: theta(φ), driver(φ), kind(φ)."""

    def __init__(self, monkeypatch, theta, driver=lambda x: 0, kind=lambda x: 0, i_t=lambda x: 0.8):
        self.calls = []

        def pose(law, phi, th_prev, h):
            law.evaluations += 1
            self.calls.append((phi, th_prev, h))
            if len(self.calls) > 50000:  # a tracking that never ends fails here, not at the mutation run's timeout
                raise RuntimeError("track does not end")
            d = driver(phi)
            return cl._Sample(phi, theta(phi), d, kind(phi), i_t(phi), (d,))

        monkeypatch.setattr(cl.ContactLaw, "pose", pose)


def _fake_bodies(i_n=0.8):
    return SimpleNamespace(i_n=i_n, a=100.0, chord_tol=1e-3)


def test_track_halves_its_step_to_the_finest_at_a_hand_over_and_doubles_it_after(monkeypatch):
    """grid 0, 0.25 … 1, a hand-over of driver at φ = 0.3, finest step 0.01: worked out step by step from the
    rules (halve while refined and above the finest, accept, double up to the grid's step, land on every grid
    angle)."""
    fake = _FakeLaw(monkeypatch, theta=lambda x: x / 0.8, driver=lambda x: 0 if x < 0.3 else 1)
    law = cl.track(_fake_bodies(), np.linspace(0.0, 1.0, 5), 0.2, step_min=0.01, snap_tol=1e-3)
    expect = [0.0, 0.25, 0.28125, 0.296875, 0.306875, 0.326875, 0.366875, 0.446875, 0.5, 0.60625, 0.75, 1.0]
    assert law.phi == pytest.approx(expect, abs=1e-12)
    assert law.driver.tolist() == [0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1]
    assert np.allclose(law.theta, np.array(expect) / 0.8, atol=1e-12)
    assert law.kind.tolist() == [0] * 12 and np.allclose(law.delta_i, 0.0)
    assert (law.ratio_nominal, law.step_min, law.snap_tol) == (0.8, 0.01, 1e-3)
    assert law.evaluations == len(fake.calls) == 1 + 11 + 7  # the first, the accepted, the refined (0.5, 0.375, 0.3125; 0.34375, 0.3125; 0.328125, 0.3125)
    assert [c[0] for c in fake.calls[2:6]] == [0.5, 0.375, 0.3125, 0.28125]
    # the first pose from theta0 − 1e-5 with no step; each later one from the last pose, the step it made
    assert fake.calls[0] == (0.0, 0.2 - 1e-5, 0.0)
    assert fake.calls[1] == (0.25, 0.0, 0.25)
    assert fake.calls[-1] == (1.0, pytest.approx(0.75 / 0.8), 0.25)


def test_track_defaults_tip_ratios_and_lost_contact(monkeypatch):
    from propulsor import policy

    # tips from 0.1 to 0.2: the step's own ratio h/Δθ where the gear advanced; no refinement of equal kinds
    # beyond the finest: the default finest step and snap tolerance
    th = lambda x: x / 0.8 + (0.05 if x > 0.15 else 0.0)
    _FakeLaw(monkeypatch, theta=th, kind=lambda x: 3 if 0.1 < x < 0.2 else 0, i_t=lambda x: math.nan)
    law = cl.track(_fake_bodies(), np.array([0.0, 0.1, 0.2]), 0.0)
    assert law.step_min == policy.POLYSECTOR_LAW_STEP_MIN_RAD
    assert law.snap_tol == math.radians(policy.POLYSECTOR_SNAP_TOL_DEG)
    tips = law.kind == 3
    assert tips.sum() >= 2 and law.phi[tips].min() > 0.1 and law.phi[tips].max() < 0.2
    i = np.nonzero(tips)[0]
    for k in i:
        dphi, dth = law.phi[k] - law.phi[k - 1], law.theta[k] - law.theta[k - 1]
        assert law.i_t[k] == pytest.approx(dphi / dth, rel=1e-12)
        assert law.delta_i[k] == pytest.approx((0.8 - dphi / dth) / 0.8, rel=1e-12)
    assert np.nanmax(law.delta_i) > 0.5  # the jump: the gear far ahead of φ/i_n
    assert np.isnan(law.i_t[~tips]).all()
    # the jump at 0.15 resolved to the finest step
    assert law.snap_max() == pytest.approx(0.05, abs=1e-3)
    # a tip sample where the gear stood still keeps NaN; a lost contact (NaN) is kept and tracking goes on from the
    # last pose found
    fake = _FakeLaw(monkeypatch, theta=lambda x: math.nan if 0.3 < x < 0.4 else (0.5 if x < 0.5 else x),
                    kind=lambda x: 3, i_t=lambda x: math.nan)
    law = cl.track(_fake_bodies(), np.array([0.0, 0.25, 0.5]), 0.5, step_min=0.125)
    assert law.phi.tolist() == [0.0, 0.125, 0.25, 0.375, 0.5]
    assert np.isnan(law.theta[3]) and np.isnan(law.i_t).all()  # the gear stood: no step ratio
    assert [c[1] for c in fake.calls][-2:] == [0.5, 0.5]
    # a single grid angle: one sample
    _FakeLaw(monkeypatch, theta=lambda x: 0.25)
    law = cl.track(_fake_bodies(), np.array([0.3]), 0.25)
    assert law.phi.tolist() == [0.3] and law.theta.tolist() == [0.25]


def _cross(u, v):
    return float(u[0] * v[1] - u[1] * v[0])


def _scan(cz, deg0, deg1, te0, step=0.1):
    """Poses of the contact law at wheel angles deg0, deg0 + step … deg1 (each from the one before), from a start
    a hair behind φ/i_n + te0; the law, its position and the samples."""
    dd = pd.design(_p(conditional_teeth=cz))
    pos = dd.positions[0]
    law = cl.ContactLaw(cl.position_bodies(dd, pos, 1e-3))
    grid = np.radians(np.arange(deg0, deg1 + 1e-9, step))
    s = law.pose(grid[0], grid[0] / pos.ratio_nominal + te0 - 1e-3, 0.0)
    out = [s]
    for g in grid[1:]:
        s = law.pose(g, s.theta, g - s.phi)
        out.append(s)
    return law, pos, out


def test_contact_law_at_e0_is_conjugate_flank_contact_on_the_line_of_action():
    """e = 0: the sectors are the blank; the gear follows φ/i_n exactly (to the outlines' accuracy), the contact
    is flank on flank with i_t = r_b2/r_b = 40/36, 0.02 mm from the line of action through the pitch point (a r/(r + r2), 0)
    at α = 20° to the y axis; the outline normals at the contact point lie along it."""
    law, pos, out = _scan([36], 0.0, 0.2, -0.0017, step=0.1)
    assert law.evaluations == 3
    i_n = 40 / 36
    for s in out:
        assert (s.driver, s.kind, s.sectors) == (0, 0, (0,))
        assert s.i_t == pytest.approx(i_n, rel=1e-12)
    th = np.array([s.theta for s in out])
    assert np.allclose(np.diff(th), np.radians(0.1) / i_n, atol=2e-6, rtol=0)
    alpha = math.radians(20.0)
    loa = np.array([math.sin(alpha), math.cos(alpha)])  # the line of action's direction (either sense)
    P = np.array([114.0 * 54.0 / 114.0, 0.0])
    for s in out[1:]:
        room, C = law.back_room(0, s.phi, s.theta + 1e-5, 2e-5)
        assert room == pytest.approx(1e-5, abs=2e-7)
        off = min(abs(_cross(loa, C - P)), abs(_cross(loa * [-1, 1], C - P)))
        assert off < 0.03  # the mean of the boundary points within the 1 µm contact tolerance (a 0.3 mm stretch)
        side = loa if abs(_cross(loa, C - P)) < 0.03 else loa * [-1, 1]
        for n in (law._normal_gear(C, s.theta), law._normal_sector(0, C, s.phi)):
            assert abs(abs(float(n @ side)) - 1.0) < 1e-3 and np.hypot(*n) == pytest.approx(1.0, abs=1e-12)
    # the free start: turned back by 0.2 mrad the gear overlaps the driving sector, forward it does not
    s = out[1]
    assert law.overlaps(0, s.phi, s.theta - 2e-4) and not law.overlaps(0, s.phi, s.theta + 2e-4)


def test_contact_law_frames_and_engagement():
    """The gear's body frame: world = R(−θ) X + (a, 0); the wheel's: world = R(φ) X; a sector is engaged when a
    vertex of it, turned by φ, lies inside the gear's tip circle."""
    dd, pos, b = _bodies(0)
    law = cl.ContactLaw(b)
    phi, th = 0.3, -0.2
    rel21, M2 = law._rel21(phi, th)
    X = np.array([3.0, 4.0])
    world = np.array([[math.cos(-th), -math.sin(-th)], [math.sin(-th), math.cos(-th)]]) @ X + [114.0, 0.0]
    assert np.allclose(M2[:, :2] @ X + M2[:, 2], world, atol=1e-12)
    wheel = np.array([[math.cos(phi), math.sin(phi)], [-math.sin(phi), math.cos(phi)]]) @ world
    assert np.allclose(rel21[:, :2] @ X + rel21[:, 2], wheel, atol=1e-12)
    seen = {}
    for ph in (0.3, -0.3, 0.9, -0.9):
        R = np.array([[math.cos(ph), -math.sin(ph)], [math.sin(ph), math.cos(ph)]])
        for j, o in b.sectors.items():
            exp = bool(np.min(np.hypot(*(o.points @ R.T - [114.0, 0.0]).T)) < 63.0)
            assert law.engaged(j, ph) == exp
            seen.setdefault(j, set()).add(exp)
    assert any(len(v) == 2 for v in seen.values())
    # nothing engaged (e = 18 mm: sectors 1 and 6 only, at π and 2π/3): no pose
    s = cl.ContactLaw(_bodies(2)[2]).pose(math.pi, 0.0, 0.0)
    assert math.isnan(s.theta) and (s.phi, s.driver, s.kind, s.sectors) == (math.pi, -1, 3, ()) and math.isnan(s.i_t)
    # a step the gear cannot make free within two pitches ahead: no pose; half of it is made
    s0 = law.pose(0.0, -0.0027, 0.0)
    assert s0.theta == pytest.approx(-0.0016672, abs=2e-6)
    lost = law.pose(0.01, s0.theta, 0.01)
    assert math.isnan(lost.theta) and math.isnan(lost.i_t)
    assert (lost.phi, lost.driver, lost.kind, lost.sectors) == (0.01, -1, 3, ())
    assert law.pose(0.005, s0.theta, 0.005).theta == pytest.approx(s0.theta + 0.005 / (40 / 36), abs=2e-6)


def test_contact_law_edge_contacts_before_a_hand_over_and_the_flank_ratio():
    """z_усл = 48 (e = 18 mm): 2.0° … 2.5° flank on flank, i_t = eq. 7's pole of the base circles' internal
    tangent (gears.polysector.ratio_flank at the driving sector's mid-line u = φ); 22.0° … 23.7° the incoming
    sector's tip corner on the gear's flank, 23.8° on the gear's tip corner on the sector's flank; the contact
    point on the tip circle of the body whose corner it is; the ratio of the pole within 2e-3 of the step's own
    Δφ/Δθ."""
    law, pos, out = _scan([48], 2.0, 2.5, -0.0017)
    geo = law.b
    dd = pd.design(_p(conditional_teeth=[48]))
    for s in out:
        assert (s.driver, s.kind) == (0, 0)
        assert s.i_t == pytest.approx(float(dd.geo.ratio_flank(18.0, np.array([s.phi]))[0]), rel=1e-9)
    law, pos, out = _scan([48], 22.0, 24.0, -0.0073)
    assert [s.kind for s in out] == [1] * 18 + [2] * 3
    assert all(s.driver == 5 and s.sectors == (5,) for s in out)
    b = law.b
    for s in (out[0], out[17], out[18], out[20]):
        _, C = law.back_room(5, s.phi, s.theta + 1e-4, 2e-4)
        ang = b.angles[5][0] + s.phi
        Os = 18.0 * np.array([math.cos(ang), math.sin(ang)])
        on_sector_tip = math.hypot(*(C - Os)) >= 57.0 - 2e-3 - 1e-9
        on_gear_tip = math.hypot(*(C - [132.0, 0.0])) >= 63.0 - 2e-3 - 1e-9
        assert (on_sector_tip, on_gear_tip) == ((True, False) if s.kind == 1 else (False, True))
    for a, c in zip(out[:-1], out[1:]):
        if a.kind == c.kind:
            assert (c.phi - a.phi) / (c.theta - a.theta) == pytest.approx(0.5 * (a.i_t + c.i_t), abs=2e-3)
    assert geo.i_n == 60.0 / 72.0


def test_contact_law_tip_on_tip_at_z54():
    """z_усл = 54 (e = 27 mm): flank contact of sector 1 to 24.9°, then from 25.0° to 25.6° the incoming sector 6
    rests tip on tip (no normal: i_t NaN, the contact point on both tip circles), then its tip corner drives."""
    law, pos, out = _scan([54], 24.5, 25.9, -0.0314)
    assert [s.kind for s in out] == [0] * 5 + [3] * 7 + [1] * 3
    assert [s.driver for s in out] == [0] * 5 + [5] * 10
    assert all(math.isnan(s.i_t) for s in out[5:12]) and all(math.isfinite(s.i_t) for s in out[:5] + out[12:])
    s = out[8]
    _, C = law.back_room(5, s.phi, s.theta + 1e-4, 2e-4)
    ang = law.b.angles[5][0] + s.phi
    assert math.hypot(*(C - 27.0 * np.array([math.cos(ang), math.sin(ang)]))) >= 57.0 - 2e-3
    assert math.hypot(*(C - [141.0, 0.0])) >= 63.0 - 2e-3


# --- proofs.py -----------------------------------------------------------------------------------------------------------

pp = importlib.import_module("propulsor.parts.polysector.proofs")


def _said():
    from stand_ins import SaidWriter

    return SaidWriter()


def test_eq7_largest_ratio_error_and_the_proofs_chord():
    """|Δi| of eq. 7/8 over the engagement −u_exit … u_exit (201 angles): 0 at e = 0, 0.1387 at 9 mm, 0.2323 at
    18 mm (a finer grid of 2001 angles finds no more than 1e-4 above); the conjugate position proved at 3e-5 mm."""
    from propulsor import policy

    dd = pd.design(_p())
    got = [pp.eq7_max_di(dd, q) for q in dd.positions]
    assert got[0] == 0.0 and type(got[0]) is float
    assert got[1:] == pytest.approx([0.13870976, 0.23231872], abs=1e-7)
    for q, g in zip(dd.positions, got):
        u = np.linspace(-q.u_exit, q.u_exit, 201)
        i_t = dd.geo.ratio_flank(q.offset, u)
        assert g == pytest.approx(float(np.max(np.abs(1.0 - i_t / q.ratio_nominal))), abs=1e-15)
        fine = np.linspace(-q.u_exit, q.u_exit, 2001)
        assert 0.0 <= float(np.max(np.abs(1.0 - dd.geo.ratio_flank(q.offset, fine) / q.ratio_nominal))) - g < 1e-4
    assert [pp.chord_for(dd, q) for q in dd.positions] == [3e-5, 1e-4, 1e-4]
    assert (policy.POLYSECTOR_PROOF_CHORD_TOL_CONJUGATE_MM, policy.POLYSECTOR_PROOF_CHORD_TOL_MM) == (3e-5, 1e-4)


def test_chord_on_both_sides_of_the_conjugate_limit(monkeypatch):
    dd = pd.design(_p())
    monkeypatch.setattr(pp, "eq7_max_di", lambda dd, pos: 0.99e-4)
    assert pp.chord_for(dd, dd.positions[2]) == 3e-5
    monkeypatch.setattr(pp, "eq7_max_di", lambda dd, pos: 1e-4)
    assert pp.chord_for(dd, dd.positions[0]) == 1e-4


def test_law_checks_in_full_on_both_sides_of_their_limits():
    def law(tip_rad, snap_rad, n=17, step=5e-5):
        return SimpleNamespace(step_min=step, phi=np.zeros(n), tip_tip_angle=lambda: tip_rad, snap_max=lambda: snap_rad)

    tip, snap = pp.law_checks("position2", law(0.0, math.radians(0.05)))
    assert (tip.name, tip.passed, tip.value, tip.limit, tip.unit) == ("position2.no_tip_on_tip", True, 0.0, 0.0, "deg")
    assert tip.message == ("wheel turn per sector period over which the gear rests on tips only (tip land or corner of "
                           "both bodies), tracked contact law, 17 steps down to 0.0029° at every hand-over")
    assert (snap.name, snap.passed, snap.limit, snap.unit) == ("position2.no_snap", True, 0.05, "deg")
    assert snap.value == pytest.approx(0.05, abs=1e-15)
    assert snap.message == ("largest jump of the gear beyond its nominal advance within one finest step (0.0029° of "
                            "wheel turn)")
    tip, snap = pp.law_checks("p", law(math.radians(0.714), math.radians(0.0501), n=3, step=math.radians(0.01)))
    assert (tip.passed, snap.passed) == (False, False)
    assert tip.value == pytest.approx(0.714) and snap.value == pytest.approx(0.0501)
    assert "3 steps down to 0.0100°" in tip.message and "(0.0100° of wheel turn)" in snap.message
    assert pp.law_checks("p", law(1e-12, math.nan))[0].passed is False
    assert pp.law_checks("p", law(1e-12, math.nan))[1].passed is False


def test_prove_positions_proves_each_asked_position_at_its_chord(monkeypatch):
    mp = importlib.import_module("propulsor.parts.polysector.mesh_proof")
    calls = []
    monkeypatch.setattr(mp, "prove_position",
                        lambda d, pos, spp, chord: calls.append((d is dd, pos.k, spp, chord)) or pos.k)
    dd = pd.design(_p())
    assert pp.prove_positions(dd, [2, 0]) == [3, 1]
    assert calls == [(True, 3, None, 1e-4), (True, 1, None, 3e-5)]


def test_start_proofs_in_two_workers_the_conjugate_first(monkeypatch):
    started = []
    designs = []
    monkeypatch.setattr(pp, "start_in_fork",
                        lambda fn, d, ks: started.append((fn, ks)) or designs.append(d) or f"job{ks}")
    dd = pd.design(_p(conditional_teeth=[42, 36, 48]))
    w, built = _said(), {}
    pp.start_proofs(dd, w, built)
    assert w.said == ["proof of 3 position(s) on the finished outlines, in two processes while the solids are built"]
    # chords 1e-4, 3e-5, 1e-4: the conjugate one (index 1) first, the others in their order; alternately
    assert started == [(pp.prove_positions, [1, 2]), (pp.prove_positions, [0])]
    assert built == {"pending_proofs": [([1, 2], "job[1, 2]"), ([0], "job[0]")]}
    assert len(designs) == 2 and all(d is dd for d in designs)
    # four positions, chords 1e-4, 3e-5, 1e-4, 1e-4: (1, 2) and (0, 3) - every other one of the order to each
    started.clear()
    pp.start_proofs(pd.design(_p(conditional_teeth=[42, 36, 48, 54])), w, built)
    assert started == [(pp.prove_positions, [1, 2]), (pp.prove_positions, [0, 3])]
    started.clear()
    pp.start_proofs(pd.design(_p(conditional_teeth=[48])), w, built)
    assert started == [(pp.prove_positions, [0])] and built["pending_proofs"] == [([0], "job[0]")]
    assert w.said[-1] == "proof of 1 position(s) on the finished outlines, in two processes while the solids are built"


def test_full_turn_repeats_the_period_with_the_gears_advance():
    dd = pd.design(_p())
    per = math.pi / 3
    pr = SimpleNamespace(phi=np.array([0.0, per / 2]), theta=np.array([0.1, 0.5]), period=per, ratio_nominal=0.8)
    phi, th = pp.full_turn(dd, pr)
    k = np.repeat(np.arange(6), 2)
    assert np.allclose(phi, np.tile([0.0, per / 2], 6) + k * per, atol=1e-15)
    assert np.allclose(th, np.tile([0.1, 0.5], 6) + k * per / 0.8, atol=1e-15)
    pr1 = SimpleNamespace(phi=np.array([0.0]), theta=np.array([0.0]), period=2 * math.pi / 3, ratio_nominal=1.0)
    assert len(pp.full_turn(pd.design(_p(flows=1, conditional_teeth=[36])), pr1)[0]) == 3


def test_synthesis_step_of_the_part_file_in_full():
    from propulsor.gears.polysector import delta_eq1_printed, epsilon_alpha_pair

    dd = pd.design(_p())
    geo = dd.geo
    w = _said()
    pp.synthesis_step(dd, w, {})
    assert w.said == ["synthesis (seed 003 eq. 1-4)"]
    cp = geo.corner_pose(dd.e_max)
    d_in, d_out = geo.tip_land()
    alpha = math.radians(20.0)
    d = w.derived
    assert d == {
        "r_blank_mm": 54.0, "r_b_blank_mm": 54.0 * math.cos(alpha), "r_a_blank_mm": 57.0, "r_gear_mm": 60.0,
        "r_a_gear_mm": 63.0, "empty_pitches_k": 2, "z_c_eq2": 10.0, "delta_eq3_rad": d_in,
        "delta_eq1_swapped_rad": d_out,
        "delta_eq1_printed_rad": delta_eq1_printed(10, 36, alpha, 54.0 * math.cos(alpha), 57.0),
        "offset_max_mm": dd.e_max, "z_cond_max": pytest.approx(36 + 2 * 28.264027546 / 3, abs=1e-7),
        "eq3_O1C_mm": cp["O1C"], "eq3_CD_mm": cp["CD"], "eq3_beta2_rad": cp["beta2"], "eq3_u_exit_rad": cp["u_exit"],
        "eq3_residual_max_mm2": float(np.max(np.abs(cp["residuals"]))),
        "flank_overlap_one_flow_e0": pytest.approx((10 - 1 + epsilon_alpha_pair(36, 40, 3.0, alpha)) / 12, abs=1e-15),
        "epsilon_alpha_blank_gear": epsilon_alpha_pair(36, 40, 3.0, alpha),
        "hub_radius_mm": 50.25, "bolt_radius_mm": 45.5}
    assert d["r_gear_mm"] == 60.0 and d["eq3_residual_max_mm2"] < 1e-10
    assert d["eq3_O1C_mm"] == pytest.approx(79.8050, abs=1e-4) and cp["CD"] == pytest.approx(42.6296, abs=1e-4)
    cols, rows = w.tables["positions"]
    assert cols == ["position", "z_cond", "offset_mm", "d_cond_mm", "center_distance_mm", "ratio_nominal",
                    "epsilon_s_per_flow", "epsilon_s", "u_exit_rad", "delta_i_eq8_max"]
    for row, q in zip(rows, dd.positions):
        assert row == [q.k, q.z_cond, q.offset, 3.0 * q.z_cond, q.a, q.ratio_nominal, q.eps_s_flow, q.eps_s,
                       q.u_exit, pp.eq7_max_di(dd, q)]
    assert len(rows) == 3 and w.checks[0].name == "position1.epsilon_s_eq4"
    for n, q in enumerate(dd.positions):
        eps, off = w.checks[2 * n], w.checks[2 * n + 1]
        assert (eps.name, eps.passed, eps.value, eps.limit, eps.unit) == (
            f"position{q.k}.epsilon_s_eq4", True, q.eps_s, 1.05, "")
        assert eps.message == (f"eq. 4 (both flows, φ1 between the driving corners): ε_s = {q.eps_s:.4f} (per flow "
                               f"{q.eps_s_flow:.4f}); the seed asks 1.05 … 1.3 at the largest offset")
        assert (off.name, off.passed, off.value, off.limit, off.unit) == (
            f"position{q.k}.offset_eq3", True, q.offset, dd.e_max, "mm")
        assert off.message == f"offset {q.offset:g} mm within the largest offset of eq. 1/3, 28.2640 mm"
    assert w.checks[3].message == "offset 9 mm within the largest offset of eq. 1/3, 28.2640 mm"
    ea = epsilon_alpha_pair(36, 40, 3.0, alpha)
    assert w.notes == [
        "Synthesis (seed 003 eq. 1–4): blank z = 36, m = 3 mm; 2 flow(s) of i_s = 3 sectors of z_c = 10 teeth (eq. 2: "
        "z/i_s − k with k = 2 empty pitches); gear z2 = 40. Largest offset of eq. 1/3 with our closing condition "
        "(ε_s ≥ 1.05 for both flows, φ1 from the leading tooth's driving corner entering the gear's tip circle to the "
        "trailing tooth's driving corner leaving it): e_max = 28.2640 mm (z_усл ≤ 54.84; ε_s = 1.0896 there; past it "
        "the leading tooth's driving corner no longer reaches the gear's tip circle); at it eq. 3's corner C "
        f"(δ = {cp['delta']:.5f} rad) lies on the gear's tip circle with O1C = 79.8050 mm, CD = 42.6296 mm, "
        f"β2 = 0.09802 rad (rows of eq. 1/3 agree within {d['eq3_residual_max_mm2']:.2g} mm²). The positions are the "
        "conditional tooth counts [36, 42, 48] (multiples of flows·i_s = 6: every sector meets the gear in tooth "
        "phase); the last has ε_s = 1.4565. One flow alone overlaps (z_c − 1 + ε_α)/(z_c + k) = "
        f"{(9 + ea) / 12:.4f} < 1 with flank contact only at e = 0: the second flow is what keeps the mesh "
        "continuous."]
    assert f"{(9 + ea) / 12:.4f}" == "0.8919"


def test_synthesis_step_notes_of_one_flow_and_of_a_last_position_within_the_seeds_range():
    """One flow at z_усл = 36: ε_s falls to 1.05 at e_max = 0.8597 mm (1.0694 at e = 0: within 1.05 … 1.3);
    two flows at 36 and 54: the last ε_s 1.1600, within; a failing ε_s check below 1.05."""
    dd = pd.design(_p(flows=1, conditional_teeth=[36]))
    w = _said()
    pp.synthesis_step(dd, w, {})
    note = w.notes[0]
    assert "e_max = 0.8597 mm (z_усл ≤ 36.57; ε_s falls to 1.05 there)" in note
    assert "The positions are the conditional tooth counts [36] (multiples of flows·i_s = 3: every sector meets" in note
    assert "the last has ε_s = 1.0694 — within the seed's 1.05 … 1.3. One flow alone" in note
    assert "1 flow(s) of i_s = 3 sectors" in note
    dd = pd.design(_p(conditional_teeth=[36, 54]))
    w = _said()
    pp.synthesis_step(dd, w, {})
    assert "the last has ε_s = 1.1600 — within the seed's 1.05 … 1.3. One" in w.notes[0]
    assert [c.passed for c in w.checks] == [True] * 4
    low = dataclasses.replace(dd, positions=(dataclasses.replace(dd.positions[1], eps_s=1.0499, offset=28.3),))
    w = _said()
    pp.synthesis_step(low, w, {})
    assert [(c.name, c.passed) for c in w.checks] == [("position2.epsilon_s_eq4", False), ("position2.offset_eq3",
                                                                                          False)]
    assert "the last has ε_s = 1.0499. One flow" in w.notes[0]
    hi = dataclasses.replace(dd, positions=(dataclasses.replace(dd.positions[1], eps_s=1.3),))
    w = _said()
    pp.synthesis_step(hi, w, {})
    assert "the last has ε_s = 1.3000 — within the seed's 1.05 … 1.3." in w.notes[0]
    lo = dataclasses.replace(dd, positions=(dataclasses.replace(dd.positions[1], eps_s=EPS_S_MIN),))
    w = _said()
    pp.synthesis_step(lo, w, {})
    assert "the last has ε_s = 1.0500 — within the seed's 1.05 … 1.3." in w.notes[0]  # both ends inclusive
    hi = dataclasses.replace(dd, positions=(dataclasses.replace(dd.positions[1], eps_s=1.3001),))
    w = _said()
    pp.synthesis_step(hi, w, {})
    assert "the last has ε_s = 1.3001. One flow" in w.notes[0]


def test_position_error_step_against_eq_15_22_at_four_radii():
    """R and β of every tooth and flank of the sector at r_y = r_усл − m, − m/2, r_усл, + m/2 (gears.polysector's
    eq. 15-22 called in the test); the largest finite R per position in µm: 0 at e = 0."""
    from propulsor.gears.polysector import tooth_position_error

    dd = pd.design(_p(conditional_teeth=[36, 42]))
    w = _said()
    pp.position_error_step(dd, w, {})
    cols, rows = w.tables["tooth_position_error"]
    assert cols == ["position", "r_y_mm", "tooth", "flank", "x_cond_mm", "y_cond_mm", "x_sector_mm", "y_sector_mm",
                    "R_um", "beta_rad"]
    expect, worst = [], {}
    for q in dd.positions:
        rc = 54.0 + q.offset
        best = 0.0
        for r_y in (rc - 3.0, rc - 1.5, rc, rc + 1.5):
            for rr in tooth_position_error(3.0, 36, 10, q.offset, math.radians(20.0), r_y):
                expect.append([q.k, rr["r_y"], rr["tooth"], rr["flank"], rr["x_cond"], rr["y_cond"], rr["x_sector"],
                               rr["y_sector"], rr["R"] * 1e3, rr["beta"]])
                if math.isfinite(rr["R"]):
                    best = max(best, rr["R"])
        worst[q.k] = best
    assert len(rows) == len(expect) == 160
    for a, b in zip(rows, expect):
        assert a[:4] == b[:4] and np.allclose(np.array(a[4:], float), np.array(b[4:], float), equal_nan=True,
                                              rtol=0, atol=0)
    assert worst[1] == pytest.approx(0.0, abs=1e-12) and worst[2] == pytest.approx(1.5171, abs=1e-4)
    assert w.derived == {"position1_flank_deviation_max_um": pytest.approx(0.0, abs=1e-9),
                         "position2_flank_deviation_max_um": pytest.approx(1517.1, abs=0.1)}
    assert w.derived["position2_flank_deviation_max_um"] == worst[2] * 1e3
    assert w.notes == [
        "Tooth position error (eq. 15–22): largest distance R between the sector's flank and the conditional gear's "
        "involute on circles r_y = r_усл − m … r_усл + m/2 about the wheel axis: position 1: 0.0 µm, position 2: "
        "1517.1 µm (0 at e = 0, where the sector is the blank itself)."]
    assert list(w.plots) == ["tooth_position_error"] and w.plots["tooth_position_error"].axes  # the figure handed on


def _fake_proof(dd, q, eps_off=0.01, room=(0.003, 0.001, math.nan, 0.002)):
    """A PositionProof of 4 steps over the period with a tracked law of 9 samples (given numbers), the engagement
    chosen to give ε_s = eq. 4's + ``eps_off``."""
    from propulsor.parts.polysector.contact_law import LawResult
    from propulsor.parts.polysector.mesh_proof import PositionProof

    per, i_n = math.pi / 3, q.ratio_nominal
    phi = np.arange(4) * per / 4
    lphi = np.linspace(0.0, per, 9)
    kind = np.array([0, 0, 1, 1, 3, 2, 0, 0, 0])
    i_t = np.array([i_n, i_n * 1.01, 0.99 * i_n, i_n, math.nan, 1.02 * i_n, i_n, 0.98 * i_n, i_n])
    ltheta = lphi / i_n + np.array([0.0, 1e-4, 2e-4, 3e-4, 1e-3, 1.1e-3, 1.2e-3, 1.2e-3, 1.2e-3])
    law = LawResult(lphi, ltheta, np.array([0, 0, 0, 0, 5, 5, 5, 5, 5]), kind, i_t, (i_n - i_t) / i_n, i_n, 5e-5,
                    math.radians(0.05), 9)
    phi1 = (q.eps_s + eps_off) * 2 * math.pi / 6
    driver = np.array([0, 0, 5, 5])
    return PositionProof(
        k=q.k, phi=phi, period=per, theta=phi / i_n + np.array([0.0, 1e-4, 2e-4, 0.0]), theta_nominal=phi / i_n,
        driver=driver, driver_u=np.array([0.0, per / 4, per / 2 - per, 3 * per / 4 - per]),
        pairs=np.array([1, 2, 2, 1]), sectors_engaged=np.array([1, 2, 2, 1]),
        overlap_flow=np.array([[0.0, 1e-7], [5e-7, 0.0], [0.0, 0.0], [2e-7, 3e-7]]), coast_room=np.array(room),
        phi1_measured=phi1, u_enter=-phi1 / 2, u_exit=phi1 / 2, contact_points=np.zeros((4, 2)), contacts=[[]] * 4,
        drive_theta={}, ratio_nominal=i_n, chord_tol=1e-4, r_ref=dd.geo.r_b2, flows=2, i_s=3, law=law)


def _results(dd, prs, split=((1,), (0,))):
    built = {"pending_proofs": [(list(ks), SimpleNamespace(result=lambda ks=ks: [prs[k] for k in ks]))
                                for ks in split]}
    w = _said()
    pp.proof_results(dd, w, built)
    return w, built


def test_proof_results_checks_tables_and_note_of_given_proofs():
    from propulsor import policy
    from propulsor.parts.polysector.contact_law import TYPES

    dd = pd.design(_p(conditional_teeth=[36, 42]))
    prs = [_fake_proof(dd, q) for q in dd.positions]
    w, built = _results(dd, prs)
    assert built == {"proofs": {0: prs[0], 1: prs[1]}}
    assert w.said == ["proofs done"] and list(w.plots) == ["ratio_error"] and w.plots["ratio_error"].axes
    assert len(w.checks) == 2 * 7
    for n, (q, pr) in enumerate(zip(dd.positions, prs)):
        c = w.checks[7 * n: 7 * n + 7]
        name = f"position{q.k}"
        assert [x.name for x in c] == [f"{name}.flow1.overlap_area", f"{name}.flow2.overlap_area",
                                       f"{name}.contact_continuity", f"{name}.no_jam", f"{name}.epsilon_s_measured",
                                       f"{name}.no_tip_on_tip", f"{name}.no_snap"]
        assert [x.passed for x in c] == [True, True, True, True, True, False, True]  # tips 7.5°, no fine step
        assert [x.value for x in c[:4]] == [5e-7, 3e-7, 1.0, 0.001]
        assert [x.limit for x in c[:4]] == [policy.OVERLAP_AREA_TOL_MM2, 1e-6, 1, 0.0]
        assert [x.unit for x in c] == ["mm^2", "mm^2", "pairs", "rad", "", "deg", "deg"]
        assert c[0].message == ("gear against flow 1's sectors at the measured pose, 4 steps of one sector period "
                                "(the turn repeats it)")
        assert c[1].message.startswith("gear against flow 2's sectors")
        assert c[2].message == "tooth pairs in contact, both flows together: least 1, mean 1.500"
        assert c[3].message == "least room of the engaged sectors' other flanks at the pose the driving sector sets"
        ef, eb = pr.eps_s_measured()
        assert eb == pytest.approx(q.eps_s + 0.01, abs=1e-12) and ef == pytest.approx(eb / 2, abs=1e-15)
        assert c[4].value == eb and c[4].limit == {"expected": q.eps_s, "rel_tol": 0.0, "abs_tol": 0.02}
        assert c[4].message == (f"ε_s measured on the outline's driving corners (engagement {pr.u_enter:.6f} … "
                                f"{pr.u_exit:.6f} rad) {eb:.5f} against eq. 4 {q.eps_s:.5f}")
        assert [x.name for x in pp.law_checks(name, pr.law)] == [x.name for x in c[5:]]
        assert c[5].value == pytest.approx(math.degrees(pr.law.tip_tip_angle()))
    pos = w.derived["positions"]
    assert len(pos) == 2
    for q, pr, d in zip(dd.positions, prs, pos):
        law = pr.law
        ef, eb = pr.eps_s_measured()
        assert d == {
            "offset_mm": q.offset, "center_distance_mm": q.a, "ratio_nominal": q.ratio_nominal, "epsilon_s": eb,
            "epsilon_s_per_flow": ef, "ratio_error_max": pytest.approx(0.02, abs=1e-12), "contact_pairs_min": 1,
            "epsilon_s_eq4": q.eps_s, "z_cond": q.z_cond, "share_two_sectors_engaged": 0.5, "epsilon_s_steps": 1.5,
            "share_two_pairs_in_contact": 0.5, "transmission_error_pp_rad": pytest.approx(1.2e-3, abs=1e-15),
            "proof_chord_tol_mm": 1e-4, "proof_steps_per_period": 4,
            "contact_shares": {"flank": pytest.approx(0.5), "sector_tip": pytest.approx(0.25),
                               "gear_tip": pytest.approx(0.125), "tip_tip": pytest.approx(0.125)},
            "tip_on_tip_deg": pytest.approx(math.degrees(math.pi / 24)),
            "snap_max_deg": math.degrees(law.snap_max()), "contact_law_steps_per_period": 9,
            "contact_law_step_min_deg": math.degrees(5e-5)}
        assert type(d["contact_pairs_min"]) is int
        cols, rows = w.tables[f"contact_law_{q.k}"]
        assert cols == ["phi_rad", "theta_rad", "te_rad", "driving_sector", "contact_type", "i_t", "delta_i"]
        assert len(rows) == 9
        for i, r in enumerate(rows):
            assert r[:5] == [law.phi[i], law.theta[i], law.te[i], int(law.driver[i]) + 1, TYPES[law.kind[i]]]
            assert np.allclose(r[5:], [law.i_t[i], law.delta_i[i]], equal_nan=True, rtol=0, atol=0)
        cols, rows = w.tables[f"transmission_{q.k}"]
        assert cols == ["phi_rad", "theta_rad", "gear_rotation_ccw_rad", "theta_nominal_rad", "te_rad", "i_t",
                        "delta_i", "delta_i_eq8_flank", "driving_sector", "pairs_in_contact", "sectors_engaged",
                        "contact_type"]
        assert len(rows) == 24
        per = math.pi / 3
        for i, r in enumerate(rows):
            k, s = divmod(i, 4)
            phi = pr.phi[s] + k * per
            th = pr.theta[s] + k * per / q.ratio_nominal
            li = 2 * s  # the law's sample at the step
            eq8 = (q.ratio_nominal - float(dd.geo.ratio_flank(q.offset, np.array([pr.driver_u[s]]))[0])) \
                / q.ratio_nominal
            assert r[:5] == pytest.approx([phi, th, -th, phi / q.ratio_nominal, th - phi / q.ratio_nominal],
                                          abs=1e-12)
            assert np.allclose(r[5:8], [law.i_t[li], law.delta_i[li], eq8], equal_nan=True, rtol=0, atol=1e-12)
            assert r[8:] == [(int(pr.driver[s]) + k) % 6 + 1, int(pr.pairs[s]), int(pr.sectors_engaged[s]),
                             TYPES[law.kind[li]]]
            assert type(r[8]) is int and type(r[9]) is int and type(r[10]) is int
    q, pr = dd.positions[1], prs[1]
    ef, eb = pr.eps_s_measured()
    u = np.linspace(-q.u_exit, q.u_exit, 201)
    di_eq8 = (q.ratio_nominal - dd.geo.ratio_flank(q.offset, pr.driver_u)) / q.ratio_nominal
    assert w.notes[1] == (
        f"Position 2 (z_усл = 42, e = 9 mm, a = 123 mm, i_n = {q.ratio_nominal:.5f}): 4 steps over one sector period, "
        f"outlines within 0.0001 mm. ε_s measured {eb:.4f} (per flow {ef:.4f}) against eq. 4 {q.eps_s:.4f}; two "
        f"sectors engaged over 50.0 % of the turn; tooth pairs in contact 1 … 2; transmission error 1.2000 mrad peak "
        f"to peak; contact law tracked in 9 steps (down to {math.degrees(5e-5):.4f}° at the hand-overs): flank "
        f"50.00 %, sector_tip 25.00 %, gear_tip 12.50 %, tip_tip 12.50 % of the turn, tip on tip "
        f"{math.degrees(math.pi / 24):.4f}° per period, largest snap {math.degrees(pr.law.snap_max()):.4f}° (limit "
        f"0.05°); |Δi| up to 0.02 (pole of the contact normal), {float(np.max(np.abs(di_eq8))):.3g} by eq. 7/8 for a "
        f"flank contact of the driving sector at the same steps ({pp.eq7_max_di(dd, q):.3g} over its whole "
        f"engagement); overlap 5e-07 mm².")
    assert float(np.max(np.abs(1 - dd.geo.ratio_flank(q.offset, u) / q.ratio_nominal))) == pytest.approx(
        pp.eq7_max_di(dd, q), abs=1e-15)


def test_proof_results_checks_on_both_sides_of_their_limits():
    dd = pd.design(_p(conditional_teeth=[42]))
    q = dd.positions[0]
    w, _ = _results(dd, [_fake_proof(dd, q, eps_off=0.0199, room=(0.0, 0.1, 0.2, 0.3))], split=((0,),))
    assert [c.passed for c in w.checks[:5]] == [True] * 5
    pr = _fake_proof(dd, q, eps_off=-0.0201, room=(-1e-9, 0.1, 0.2, 0.3))
    pr.overlap_flow[2, 1] = 1.1e-6
    pr.pairs[3] = 0
    w, _ = _results(dd, [pr], split=((0,),))
    assert [c.passed for c in w.checks[:5]] == [True, False, False, False, False]
    assert w.checks[2].value == 0 and w.checks[3].value == -1e-9 and w.checks[1].value == 1.1e-6


def test_efficiency_step_on_contacts_along_the_line_of_action():
    """Contacts at distances l along the line of action through the pole P = (a/(1 + i_n), 0) at i_t = i_n (a solid
    pair's path): ψ = f l (1 + 1/i_t)/h with h = O1's distance from the line, P_x cos α (eq. 12's instantaneous
    loss); C1 = 1 (α_wt = α everywhere); C2 = mean l over eq. 12's path average (l1² + l2²)/(2 (l1 + l2)); a step
    without a ratio left out."""
    from propulsor.gears.polysector import epsilon_alpha_pair
    from propulsor.gears.polysector_dynamics import loss_eq12, loss_eq13

    dd = pd.design(_p(conditional_teeth=[36, 42], friction_coefficient=0.1))
    alpha = math.radians(20.0)
    u = np.array([math.sin(alpha), math.cos(alpha)])
    prs, ls = [], [[2.0, 1.5, 0.5], [3.0, 0.25]]
    for q, l in zip(dd.positions, ls):
        P = np.array([q.a / (1 + q.ratio_nominal), 0.0])
        it = np.array([q.ratio_nominal, q.ratio_nominal, math.nan, q.ratio_nominal])
        contacts = [[(0, P + l[0] * u), (3, P - l[1] * u)], [(0, P + l[2] * u)] if len(l) > 2 else [],
                    [(0, P + 9.0 * u)], [] if len(l) > 2 else [(5, P - l[1] * u)]]
        if len(l) == 2:
            contacts = [[(0, P + l[0] * u)], [], [(0, P + 9.0 * u)], [(5, P - l[1] * u)]]
        prs.append(SimpleNamespace(ratio_measured=lambda it=it: (it, 1 - it), contacts=contacts))
    w = _said()
    pp.efficiency_step(dd, w, {"proofs": {0: prs[0], 1: prs[1]}})
    cols, rows = w.tables["efficiency"]
    assert cols == ["position", "offset_mm", "f", "epsilon_alpha_conditional", "psi_eq12_solid", "psi_eq13_plain",
                    "psi_measured", "C1", "C2", "C3", "C_ext", "efficiency"]
    notes = []
    for q, l, row in zip(dd.positions, ls, rows):
        i_n = q.ratio_nominal
        h = q.a / (1 + i_n) * math.cos(alpha)
        assert h == pytest.approx((54.0 + q.offset) * math.cos(alpha), rel=1e-14)
        psi = float(np.mean([0.1 * x * (1 + 1 / i_n) / h for x in l]))
        ea = epsilon_alpha_pair(q.z_cond, 40, 3.0, alpha)
        plain = loss_eq13(0.1, ea, q.z_cond, 40)
        r1 = 54.0 + q.offset
        l1 = math.sqrt(63.0 ** 2 - (60 * math.cos(alpha)) ** 2) - 60 * math.sin(alpha)
        l2 = math.sqrt((r1 + 3.0) ** 2 - (r1 * math.cos(alpha)) ** 2) - r1 * math.sin(alpha)
        C2 = float(np.mean(l)) / ((l1 * l1 + l2 * l2) / (2 * (l1 + l2)))
        C_ext = psi / plain
        expect = [q.k, q.offset, 0.1, ea, loss_eq12(0.1, 3.0, alpha, q.z_cond, 40, l1, l2), plain, psi, 1.0, C2,
                  C_ext / C2, C_ext, 1 - psi]
        assert row[:4] == expect[:4] and row[4:] == pytest.approx(expect[4:], rel=1e-9)
        assert w.derived[f"position{q.k}_loss_mean"] == pytest.approx(psi, rel=1e-12)
        assert w.derived[f"position{q.k}_loss_eq13_plain"] == plain
        assert w.derived[f"position{q.k}_C_ext"] == pytest.approx(C_ext, rel=1e-12)
        notes.append(f"position {q.k}: ψ = {psi:.5f} against eq. 13 plain {plain:.5f}, C1 = 1.000, C2 = {C2:.3f}, "
                     f"C3 = {C_ext / C2:.3f}, C_внеш = C2·C3/C1 = {C_ext:.3f}")
    assert len(w.derived) == 6
    assert w.notes == ["Friction loss (eq. 12–14) from the measured contact path (contact point, pole from the "
                       "measured i_t, sliding speed (ω1 + ω2)·l, power arm of the wheel): " + "; ".join(notes) + "."]


def test_efficiency_step_at_a_measured_ratio_off_the_nominal_one():
    """i_t = 1.05 i_n at every step: the pole P' = (a/(1 + i_t), 0), the working pressure angle cos α_wt =
    r_b2/(a - P'_x).  Contacts on both tangents from P' to the gear's base circle (the drive and the coast line of
    action), one 0.5 mm short of the tangent point, and one inside the base circle (no tangent: the radial line
    through O2).  Each contact's ψ = f |l| (1 + 1/i_t)/h, l = its distance from P', h = O1's distance from its line
    (P'_x cos α_wt on a line of action, a |sin β| on the radial line at polar angle β about O2); C1 = cos α_wt/cos α;
    C2 = mean |l| over eq. 12's path average; C3 = C_ext C1/C2."""
    from propulsor.gears.polysector_dynamics import loss_eq13

    dd = pd.design(_p(conditional_teeth=[36], friction_coefficient=0.1))
    (q,) = dd.positions
    alpha, r_b2, a = math.radians(20.0), dd.geo.r_b2, q.a
    i_t = 1.05 * q.ratio_nominal
    P = np.array([a / (1 + i_t), 0.0])
    cos_wt = r_b2 / (a - P[0])
    a_wt = math.acos(cos_wt)
    u_drive, u_coast = np.array([math.sin(a_wt), cos_wt]), np.array([math.sin(a_wt), -cos_wt])
    s_T = (a - P[0]) * math.sin(a_wt)  # P' to the drive line's tangent point
    beta = math.pi - 0.3
    inside = np.array([a, 0.0]) + 0.9 * r_b2 * np.array([math.cos(beta), math.sin(beta)])
    on_lines = [(u_drive, 2.0), (u_drive, -1.5), (u_coast, 0.75), (u_coast, -2.5), (u_drive, s_T - 0.5)]
    contacts = [[(0, P + l * u) for u, l in on_lines[:2]], [(1, P + l * u) for u, l in on_lines[2:]], [(2, inside)]]
    it = np.full(3, i_t)
    pr = SimpleNamespace(ratio_measured=lambda: (it, 1 - it), contacts=contacts)
    w = _said()
    pp.efficiency_step(dd, w, {"proofs": {0: pr}})
    (row,) = w.tables["efficiency"][1]
    h_line = P[0] * cos_wt
    ls = [abs(l) for _, l in on_lines] + [float(np.linalg.norm(inside - P))]
    hs = [h_line] * len(on_lines) + [a * abs(math.sin(beta))]
    psi = float(np.mean([0.1 * l * (1 + 1 / i_t) / h for l, h in zip(ls, hs)]))
    r1 = 54.0 + q.offset
    l1 = math.sqrt(63.0 ** 2 - (60 * math.cos(alpha)) ** 2) - 60 * math.sin(alpha)
    l2 = math.sqrt((r1 + 3.0) ** 2 - (r1 * math.cos(alpha)) ** 2) - r1 * math.sin(alpha)
    C1 = cos_wt / math.cos(alpha)
    C2 = float(np.mean(ls)) / ((l1 * l1 + l2 * l2) / (2 * (l1 + l2)))
    C_ext = psi / loss_eq13(0.1, row[3], q.z_cond, 40)
    assert C1 < 0.99  # the working angle is off the nominal one
    assert row[6:] == pytest.approx([psi, C1, C2, C_ext * C1 / C2, C_ext, 1 - psi], rel=1e-9)


def test_dynamics_step_hands_the_measured_transmission_to_eq_9_11(monkeypatch):
    """The model of the part's inertias, stiffnesses, damping, i54 and load; q1 = ω0 t over one wheel turn (3000
    samples); Π' = 1/i_n + te'(q1 mod period) and Π'' = te'' of the periodic cubic spline through the period's
    steps (Π' = 1/i_n, Π'' = 0 without a transmission error); the spline's knots repeated over the turn as the
    breaks; the rows, derived values and note from the results (the integration itself is the library's, run here
    on a recorder); the natural frequencies are K v = ω² M v's with M = [[J3 + J45, J45], [J45, J45]],
    K = diag(c1, c2)."""
    from scipy.interpolate import CubicSpline
    from scipy.linalg import eigh

    from propulsor.gears.polysector_dynamics import DynamicsResult, TorsionalModel

    calls = []

    def simulate(model, omega0, Pi1, Pi2, t_end, n_out=2000, q0=None, breaks=None):
        calls.append(SimpleNamespace(model=model, omega0=omega0, Pi1=Pi1, Pi2=Pi2, t_end=t_end, n_out=n_out, q0=q0,
                                     breaks=breaks))
        k = len(calls)
        t = np.linspace(0.0, t_end, 4)
        return DynamicsResult(t, omega0 * t, np.array([0.0, 1e-4, 3e-4, 0.0]) * k, np.array([0.0, -2e-4, 0.0, 0.0]),
                              np.array([20.0, 26.0 + k, 14.0, 25.0]), 25.0)

    monkeypatch.setattr(TorsionalModel, "simulate", simulate)
    dd = pd.design(_p(conditional_teeth=[36, 42], speed_rpm=600.0, load_torque_Nm=30.0, J4_kgm2=0.004, i54=2.0,
                      J1_kgm2=0.03, J2_kgm2=0.003, J3_kgm2=0.0025, J5_kgm2=0.015, c1_Nm_per_rad=3e4,
                      c2_Nm_per_rad=1e4, damping_ratio=0.07))
    per = math.pi / 3
    phi = np.arange(12) * per / 12
    te1 = 1e-4 * np.sin(2 * math.pi * phi / per)
    prs = {0: SimpleNamespace(te=np.zeros(12), phi=phi, period=per),
           1: SimpleNamespace(te=te1, phi=phi, period=per)}
    w = _said()
    pp.dynamics_step(dd, w, {"proofs": prs})
    assert len(calls) == 2
    model = calls[0].model
    assert model == TorsionalModel(0.03, 0.003, 0.0025, 0.004, 0.015, 3e4, 1e4, 2.0, 0.07, 30.0)
    om = 600.0 * 2 * math.pi / 60
    x = np.append(phi, per)
    breaks = (x[None, :] + per * np.arange(7)[:, None]).ravel()
    q1 = np.linspace(-0.3, 2 * math.pi + 0.3, 997)
    cs = CubicSpline(x, np.append(te1, te1[0]), bc_type="periodic")
    for c, q, spline in zip(calls, dd.positions, (None, cs)):
        assert (c.omega0, c.t_end, c.n_out, c.q0) == (om, 2 * math.pi / om, 3000, None)
        assert np.array_equal(c.breaks, breaks) and breaks[-1] == per * 7
        if spline is None:
            assert np.allclose(c.Pi1(q1), 1 / q.ratio_nominal, rtol=0, atol=1e-15)
            assert np.allclose(c.Pi2(q1), 0.0, rtol=0, atol=1e-15)
        else:
            m = np.mod(q1, per)
            assert np.allclose(c.Pi1(q1), 1 / q.ratio_nominal + spline.derivative(1)(m), rtol=0, atol=1e-15)
            assert np.allclose(c.Pi2(q1), spline.derivative(2)(m), rtol=0, atol=1e-15)
            assert np.max(np.abs(c.Pi1(q1) - 1 / q.ratio_nominal)) == pytest.approx(1e-4 * 6, rel=0.02)
    cols, rows = w.tables["dynamics"]
    assert cols == ["position", "offset_mm", "M1_static_Nm", "M1_max_Nm", "M1_min_Nm", "torque_factor", "q2_pp_rad",
                    "q3_pp_rad"]
    assert rows == [[1, 0.0, 25.0, 27.0, 14.0, 27.0 / 25.0, 3e-4, 2e-4],
                    [2, 9.0, 25.0, 28.0, 14.0, 28.0 / 25.0, 6e-4, 2e-4]]
    assert w.derived["position1_dynamic_torque_factor"] == 27.0 / 25.0
    assert w.derived["position2_dynamic_torque_factor"] == 28.0 / 25.0
    J45 = 0.004 + 0.015 * 4.0
    wn2 = eigh(np.diag([3e4, 1e4]), np.array([[0.0025 + J45, J45], [J45, J45]]), eigvals_only=True)
    hz = [math.sqrt(v) / (2 * math.pi) for v in sorted(wn2)]
    assert w.derived["dynamics_natural_frequencies_Hz"] == pytest.approx(hz, rel=1e-10)
    assert w.notes == [
        "Dynamics (eq. 9–11, Lagrange form, Π = the measured gear angle, hand-over corners of the measured "
        f"transmission spread over one proof step): natural frequencies {hz[0]:.1f} Hz, {hz[1]:.1f} Hz; peak dynamic "
        "torque factor max|M1|/M1_static position 1: 1.080, position 2: 1.120."]
    assert list(w.plots) == ["dynamics"] and len(w.plots["dynamics"].axes) == 3  # the figure drawn, handed on


# --- mesh_proof.py -------------------------------------------------------------------------------------------------------

mp = importlib.import_module("propulsor.parts.polysector.mesh_proof")


@pytest.mark.parametrize("changes", [{}, dict(sector_teeth=11, flows=1, conditional_teeth=[36])])
def test_driving_corner_span_puts_the_driving_corners_on_the_gears_tip_circle(changes):
    """u_exit: the trailing tooth's driving (inner) corner at −δ_in from the mid-line about O' leaves the gear's tip
    circle; u_enter: the leading tooth's driving (outer) corner at +δ_out enters it; both found on the outline's tip
    vertices, and each the corner exactly on the tip circle (|C − O2| = r_a2 to 1e-9 mm), inside on the engaged
    side, outside beyond; the library's eq. 4 span alike.  (u_enter was bisected on the mirrored side, so it stayed
    on the 721-point grid: 1.2e-4 … 1.1e-3 rad off, ε_s measured up to 0.002 off.)"""
    dd = pd.design(_p(**changes))
    geo = dd.geo
    d_in, d_out = geo.tip_land()
    for q in dd.positions:
        O2 = np.array([q.a, 0.0])
        u_enter, u_exit = mp._driving_corner_span(dd, q, 1e-4, geo.r_a2, O2)
        assert (u_enter, u_exit) == pytest.approx(geo.driving_span(q.offset), abs=1e-12)

        def corner(u, beta):
            return q.offset * np.array([math.cos(u), math.sin(u)]) + geo.r_a * np.array([math.cos(u + beta),
                                                                                         math.sin(u + beta)])
        for u, beta, inward in ((u_exit, -d_in, -1.0), (u_enter, d_out, 1.0)):
            assert math.hypot(*(corner(u, beta) - O2)) == pytest.approx(geo.r_a2, abs=1e-9)
            assert math.hypot(*(corner(u + inward * 1e-6, beta) - O2)) < geo.r_a2
            assert math.hypot(*(corner(u - inward * 1e-6, beta) - O2)) > geo.r_a2


def test_prove_position_at_e0_is_the_solid_pair_with_its_backlash():
    """e = 0 (the sectors are the blank): 4 steps a pitch over the period π/3 (24 steps); the gear follows φ/i_n
    within 2 µrad; the coast side's room is the backlash of two teeth thinned by 0.1 mm on the pitch circle,
    0.2 mm/r2 = 3.333 mrad; no overlap; every step in contact, the contact points on the lines of action through
    the pitch point (54, 0); the driving sector's pose is the actual pose; ε_s measured is eq. 4's; the proof's
    poses are the tracked law's at the same angles."""
    from propulsor.parts.polysector.contact_law import LawResult

    dd = pd.design(_p(conditional_teeth=[36]))
    q = dd.positions[0]
    pr = mp.prove_position(dd, q, 4, 3e-4)
    per = math.pi / 3
    assert (pr.k, pr.period, pr.ratio_nominal, pr.chord_tol, pr.flows, pr.i_s) == (1, per, 40 / 36, 3e-4, 2, 3)
    assert pr.r_ref == 60.0 * math.cos(math.radians(20.0))
    assert np.allclose(pr.phi, np.arange(24) * per / 24, rtol=0, atol=1e-15) and len(pr.phi) == 24
    assert np.array_equal(pr.theta_nominal, pr.phi / (40 / 36))
    assert np.ptp(pr.te) < 2e-6
    assert np.allclose(pr.coast_room, 0.2 / 60.0, rtol=0, atol=5e-6)
    assert pr.overlap_flow.shape == (24, 2) and pr.overlap_flow.max() < 1e-9
    assert pr.pairs.min() >= 1 and pr.pairs.max() <= 4
    assert [len(c) for c in pr.contacts] == pr.pairs.tolist()
    alpha = math.radians(20.0)
    for here in pr.contacts:
        for j, C in here:
            off = min(abs(_cross((math.sin(alpha), s * math.cos(alpha)), C - [54.0, 0.0])) for s in (1.0, -1.0))
            assert off < 0.03
    assert np.all(np.hypot(*(pr.contact_points - [54.0, 0.0]).T) < 12.0)
    assert sorted(pr.drive_theta) == [0, 2, 3, 5]
    angles = [0.0, 2 * per, 4 * per, per, 3 * per, 5 * per]
    for k in range(24):
        j = int(pr.driver[k])
        assert pr.drive_theta[j][k] == pr.theta[k]
        assert all(not (v[k] > pr.theta[k]) for v in pr.drive_theta.values())
        assert pr.driver_u[k] == pytest.approx(float(cl._wrap(angles[j] + pr.phi[k])), abs=1e-15)
    assert set(pr.sectors_engaged.tolist()) <= {2, 3} and pr.sectors_engaged.mean() == pytest.approx(2.0 + 5 / 24)
    ef, eb = pr.eps_s_measured()
    assert (pr.u_enter, pr.u_exit) == pytest.approx(dd.geo.driving_span(0.0), abs=1e-12)
    assert pr.phi1_measured == pr.u_exit - pr.u_enter
    assert eb == pytest.approx(q.eps_s, abs=1e-9) and ef == pytest.approx(q.eps_s_flow, abs=1e-9)
    assert isinstance(pr.law, LawResult) and pr.law.phi[0] == 0.0 and pr.law.phi[-1] == pytest.approx(per)
    assert np.allclose(pr.law.theta[pr.law.at(pr.phi)], pr.theta, rtol=0, atol=1e-12)
    it, di = pr.ratio_measured()
    assert np.allclose(it, 40 / 36, rtol=1e-9) and np.allclose(di, 0.0, atol=1e-9)


@pytest.mark.parametrize("changes", [{}, dict(gear_teeth=300), dict(gear_teeth=20),
                                     dict(blank_teeth=300, sector_teeth=98, conditional_teeth=[300])])
def test_the_proofs_gear_window_holds_every_gear_point_a_sector_can_reach(monkeypatch, changes):
    """The proof cuts the gear's outline to an annular sector (body frame) before it turns the pair; it must hold
    every gear point a sector can touch over the period.  A sector point lies within R1 = r_a + e of O1; a gear point
    at radius rho (root to tip circle) turned by th (s2 = -1) sits at world angle beta - th about O2 = (a, 0) and is
    within R1 of O1 when |beta - th - pi| <= arccos((a^2 + rho^2 - R1^2)/(2 a rho)); th runs over the period's
    phi/i_n (+- the backlash, 0.01 rad here).  Gears of 20 and 300 teeth (the reach 0.50 to 0.053 rad), a blank of
    300."""
    import propulsor.checks.motion as cm
    from propulsor import policy

    class Cut(Exception):
        pass

    seen, sampled = [], []

    def record(section, a0, a1, r_in, r_out):
        assert section is sampled[-1][0].section  # the gear's own outline is cut
        seen.append((a0, a1, r_in, r_out))
        raise Cut

    real_outline = cm.outline

    def outline(body, *args):
        o = real_outline(body, *args)
        sampled.append((o, body, args))
        return o

    monkeypatch.setattr(cm, "crop_to_sector", record)
    monkeypatch.setattr(cm, "outline", outline)
    dd = pd.design(_p(**changes))
    g, m = dd.geo, dd.p.module_mm
    per = 2 * math.pi / (dd.p.flows * dd.p.sectors_per_flow)
    for q in dd.positions:
        with pytest.raises(Cut):
            mp.prove_position(dd, q, 2, 3e-4)
        a0, a1, r_in, r_out = seen[-1]
        # the gear sampled at the proof's chord tolerance and the motion checks' longest segment
        assert sampled[-1][1] is dd.gear_profile and sampled[-1][2] == (3e-4, policy.MOTION_MAX_SEGMENT_MM)
        rho = np.linspace(g.r2 - 1.25 * m, g.r_a2, 401)
        R1 = g.r_a + q.offset
        reach = float(np.max(np.arccos(np.clip((q.a ** 2 + rho ** 2 - R1 ** 2) / (2 * q.a * rho), -1.0, 1.0))))
        assert 0.0 < reach < 0.6
        assert r_in <= g.r2 - 1.25 * m and r_out >= g.r_a2
        assert a0 <= math.pi - reach - 0.01 and a1 >= math.pi + reach + per / q.ratio_nominal + 0.01
        if reach + per / q.ratio_nominal < 2.0:  # the gear cut to a window, not kept whole (z2 = 40 and 300)
            assert a1 - a0 < 2 * math.pi


@pytest.mark.parametrize("changes", [{}, dict(gear_teeth=300), dict(flows=1, conditional_teeth=[36])])
def test_the_proof_outlines_every_sector_that_reaches_the_gear_in_the_period(monkeypatch, changes):
    """The proof turns only the sectors whose mid-line comes near the line of centres in the period; every sector
    whose outline (placed at the position's offset, turned by phi over the period, 241 angles) comes inside the
    gear's tip circle about O2 = (a, 0) must be among them, each sampled at the proof's chord tolerance and the motion
    checks' longest segment.  Stopped at its first free rotation."""
    import propulsor.checks.motion as cm
    import propulsor.checks.motion.backlash as bl
    import propulsor.geometry.polysector_outline as po
    from propulsor import policy

    class Turned(Exception):
        pass

    placed, sampled = [], []
    real_place, real_outline = po.place, cm.outline

    def place(profile, angle, offset):
        placed.append((angle, offset))
        return real_place(profile, angle, offset)

    def outline(body, *args):
        sampled.append((body, args))
        return real_outline(body, *args)

    def turned(*args, **kw):
        raise Turned

    monkeypatch.setattr(po, "place", place)
    monkeypatch.setattr(cm, "outline", outline)
    monkeypatch.setattr(bl, "free_rotation", turned)
    monkeypatch.setattr(bl, "free_rotations", turned)  # both senses at once (compiled: not through free_rotation)
    dd = pd.design(_p(**changes))
    per = 2 * math.pi / (dd.p.flows * dd.p.sectors_per_flow)
    seg = policy.MOTION_MAX_SEGMENT_MM
    for q in dd.positions:
        placed.clear()
        sampled.clear()
        with pytest.raises(Turned):
            mp.prove_position(dd, q, 2, 3e-4)
        assert all(o == q.offset for _, o in placed)
        outlined = {round(a, 12) for a, _ in placed}
        assert len(outlined) == len(placed)
        # the sector outlines (after the gear's two): at the proof's chord and segment
        assert [args for _, args in sampled[2:]] == [(3e-4, seg)] * len(placed)
        needed = set()
        for f in range(1, dd.p.flows + 1):
            for ang in dd.sector_angles(f):
                pts = real_outline(real_place(dd.sector, ang, q.offset), 3e-4, seg).points
                for ph in np.linspace(0.0, per, 241):
                    c, s_ = math.cos(ph), math.sin(ph)
                    P = pts @ np.array([[c, s_], [-s_, c]])
                    if np.min(np.hypot(P[:, 0] - q.a, P[:, 1])) < dd.geo.r_a2:
                        needed.add(round(ang, 12))
                        break
        assert needed and needed <= outlined
        assert len(outlined) < dd.p.flows * dd.p.sectors_per_flow  # not every sector


def test_prove_position_at_two_steps_a_pitch_is_the_four_step_proof_at_the_shared_angles():
    """The proof's poses do not depend on its step: at e = 0, 2 steps a pitch give the gear poses, the coast room and
    the tooth pairs of 4 steps a pitch at every other angle (every sector is then in the mesh phase of the blank).  (The
    search once started sector 6 at step 2 from the middle of a free range open on its coast side, extrapolated: a
    tooth away, inside the gear; from there its contact was 0.18 mm off and two of the four tooth pairs were lost.)"""
    dd = pd.design(_p(conditional_teeth=[36]))
    q = dd.positions[0]
    two, four = mp.prove_position(dd, q, 2, 3e-4), mp.prove_position(dd, q, 4, 3e-4)
    assert np.array_equal(two.phi, four.phi[::2])
    assert np.allclose(two.theta, four.theta[::2], rtol=0, atol=1e-12)
    assert np.allclose(two.coast_room, four.coast_room[::2], rtol=0, atol=1e-12)
    assert two.pairs.tolist() == four.pairs[::2].tolist() == [2, 3, 3, 4, 4, 4, 4, 4, 4, 3, 3, 2]
    assert [len(c) for c in two.contacts] == two.pairs.tolist()


def test_track_samples_every_grid_angle_of_an_uneven_grid_and_starts_from_theta0(monkeypatch):
    """Grid 0, 0.1, 0.5: 0.1 is a sample, the step doubles to 0.2 (below the largest grid step 0.4); two grid
    angles: one step;
    a lost first pose leaves theta0 as the pose to go on from."""
    fake = _FakeLaw(monkeypatch, theta=lambda x: x / 0.8)
    law = cl.track(_fake_bodies(), np.array([0.0, 0.1, 0.5]), 0.0, step_min=0.01)
    assert law.phi == pytest.approx([0.0, 0.1, 0.3, 0.5], abs=1e-15)
    assert [c[2] for c in fake.calls] == pytest.approx([0.0, 0.1, 0.2, 0.2], abs=1e-15)
    fake = _FakeLaw(monkeypatch, theta=lambda x: x / 0.8)
    law = cl.track(_fake_bodies(), np.array([0.0, 0.2]), 0.0, step_min=0.01)
    assert law.phi.tolist() == [0.0, 0.2] and fake.calls[1] == (0.2, 0.0, 0.2)
    fake = _FakeLaw(monkeypatch, theta=lambda x: math.nan if x == 0.0 else x / 0.8)
    law = cl.track(_fake_bodies(), np.array([0.0, 0.01]), 0.3, step_min=0.01)
    assert fake.calls[1] == (0.01, 0.3, 0.01) and law.phi.tolist() == [0.0, 0.01]


def test_snap_counts_a_step_of_exactly_the_finest_times_one_plus_1e_9():
    step = 0.01 * (1 + 1e-9)
    assert _res([0.0, step], [0.0, 0.5], [0, 0]).snap_max() == pytest.approx(0.5 - step / 0.8, abs=1e-15)


def test_outline_normals_at_the_line_of_action_twenty_degrees_on():
    """e = 0 at φ = 20°, θ ≈ 0.31 rad: the gear's and the sector's outline normals at the contact point still lie
    along a line of action (the frames turned both ways)."""
    law, pos, out = _scan([36], 20.0, 20.1, -0.0017)
    alpha = math.radians(20.0)
    P = np.array([54.0, 0.0])
    for s in out:
        assert s.theta == pytest.approx(s.phi * 36 / 40 - 0.0016672, abs=2e-6) and s.kind == 0
        j = s.driver
        _, C = law.back_room(j, s.phi, s.theta + 1e-5, 2e-5)
        lines = [np.array([math.sin(alpha), sg * math.cos(alpha)]) for sg in (1.0, -1.0)]
        side = min(lines, key=lambda d: abs(_cross(d, C - P)))
        assert abs(_cross(side, C - P)) < 0.03
        for n in (law._normal_gear(C, s.theta), law._normal_sector(j, C, s.phi)):
            assert abs(abs(float(n @ side)) - 1.0) < 1e-3


def test_a_jam_between_the_flows_is_the_overlap_of_the_jammed_flow_at_the_actual_pose(monkeypatch):
    """Flow 2's sectors turned 0.01 rad on the wheel out of phase with flow 1's (their teeth 9 mrad of gear angle off,
    three times the 3.3 mrad backlash): where both flows engage, the sector that drives the gear pushes it into the
    other flow's teeth.  The proof then measures, at each step, each flow's overlap with the gear at the actual pose
    as the sum over its engaged sectors of the area common to sector and gear, here computed anew from the full gear
    outline turned about (a, 0) and the sectors turned about the wheel's axis; the jammed steps have no coast room
    (< 0) and an overlap on the flow that does not drive; the driving flow's own overlap stays nil."""
    from propulsor import policy
    from propulsor.checks.motion import outline
    from propulsor.geometry.polysector_outline import place

    dd = pd.design(_p(conditional_teeth=[36]))
    cls = type(dd)
    real = cls.sector_angles
    monkeypatch.setattr(cls, "sector_angles", lambda self, f: [a + (0.01 if f == 2 else 0.0) for a in real(self, f)])
    # the tracked contact law of the position (its last step) is not asked here: through jammed bodies it halves its
    # step to the finest and takes minutes
    monkeypatch.setattr(importlib.import_module("propulsor.parts.polysector.contact_law"), "track",
                        lambda *a, **k: None)
    q = dd.positions[0]
    pr = mp.prove_position(dd, q, 4, 3e-4)
    angles = [a for f in (1, 2) for a in dd.sector_angles(f)]
    flows = [f for f in (1, 2) for _ in dd.sector_angles(f)]
    gear = outline(dd.gear_profile, 3e-4, policy.MOTION_MAX_SEGMENT_MM).section
    want = np.zeros((len(pr.phi), 2))
    for j in pr.drive_theta:  # every sector that can reach the gear in the period (one that does not has no overlap)
        sec = outline(place(dd.sector, angles[j], q.offset), 3e-4, policy.MOTION_MAX_SEGMENT_MM).section
        for k, (ph, th) in enumerate(zip(pr.phi, pr.theta)):
            g = gear.rotate(math.degrees(-th)).translate((q.a, 0.0))
            want[k, flows[j] - 1] += (sec.rotate(math.degrees(ph)) ^ g).area()
    jam = pr.coast_room < 0
    assert jam.sum() >= 4
    drv_flow = np.array([flows[j] for j in pr.driver])
    other = np.where(drv_flow == 1, 1, 0)  # the column of the flow that does not drive
    assert np.all(pr.overlap_flow >= 0.0)
    assert np.all(pr.overlap_flow[jam, other[jam]] > 1e-3)
    assert np.all(pr.overlap_flow[np.arange(len(pr.phi)), drv_flow - 1] < 1e-6)
    assert np.allclose(pr.overlap_flow, want, rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("changes", [{}, dict(conditional_teeth=[36]), dict(flows=1, conditional_teeth=[36])])
def test_a_start_s_overlap_without_the_boolean_where_apart_decides_as_the_boolean(monkeypatch, changes):
    """prove_position tests each free start of a sector for overlap by the boolean only where the outlines are not
    certainly apart (crossing.certainly_apart: there the boolean's area is 0, so the start is free): every array of the
    proof is the one the boolean at every start gives, bit for bit (2 steps a pitch, the first position: some starts
    land inside the gear and the boolean turns them down), and the boolean is taken at fewer starts."""
    import manifold3d as m3d

    import propulsor.checks.motion.crossing as cr

    dd = pd.design(_p(**changes))
    q = dd.positions[0]
    booleans = []
    real_xor = m3d.CrossSection.__xor__

    def counted(a, b):
        import sys

        r = real_xor(a, b)
        caller = sys._getframe(1)
        while caller.f_code.co_name == "common_area":  # the shared test of a common area: whose is it
            caller = caller.f_back
        booleans.append((r.area(), caller.f_code.co_name))
        return r

    def same(a, b) -> bool:
        if isinstance(a, np.ndarray):
            return a.dtype == b.dtype and a.tobytes() == b.tobytes()
        if isinstance(a, dict):
            return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
        if isinstance(a, (list, tuple)):
            return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
        if dataclasses.is_dataclass(a):
            return all(same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a))
        return bool(a == b) or (a != a and b != b)

    monkeypatch.setattr(m3d.CrossSection, "__xor__", counted)
    fast = mp.prove_position(dd, q, 2, 3e-4)
    n_fast, inside = len(booleans), [a > 1e-6 for a, _ in booleans].count(True)
    turned_down = [a > 1e-6 for a, f in booleans if f == "sector_free"].count(True)
    monkeypatch.setattr(cr, "certainly_apart", lambda *args: False)
    booleans.clear()
    slow = mp.prove_position(dd, q, 2, 3e-4)
    for f in dataclasses.fields(fast):
        assert same(getattr(fast, f.name), getattr(slow, f.name)), f.name
    assert n_fast < len(booleans) and inside == [a > 1e-6 for a, _ in booleans].count(True)
    assert turned_down == [a > 1e-6 for a, f in booleans if f == "sector_free"].count(True) >= 2


@pytest.mark.parametrize("changes", [{}, dict(flows=1, conditional_teeth=[36])])
def test_a_start_inside_the_gear_gets_no_free_rotation(monkeypatch, changes):
    """A sector's free start (prove_position's ``sector_free``) is turned down when it shares more than
    OVERLAP_AREA_TOL_MM2 with the gear, before any free rotation is searched from it: a rotation from inside the gear
    finds a false first contact.  At 3 steps a pitch starts land inside by 0.02-0.93 mm^2 (the test asserts some do, so
    that a tolerance loosened anywhere up to 1 mm^2 is caught); for each start the free rotations run if and only if
    its common area is within the tolerance."""
    import sys

    from propulsor import policy
    import propulsor.checks.motion.backlash as bl
    import propulsor.checks.motion.crossing as cr

    events = []  # ("area", common area of a start) / ("rotations", the turn found) from sector_free, in order
    real_area, real_rot = cr.common_area, bl.free_rotations

    def area(*args):
        got = real_area(*args)
        if sys._getframe(1).f_code.co_name == "sector_free":
            events.append(("area", got))
        return got

    def rotations(*args):
        got = real_rot(*args)
        if sys._getframe(1).f_code.co_name == "sector_free":
            events.append(("rotations", got[0].delta))
        return got

    monkeypatch.setattr(cr, "common_area", area)
    monkeypatch.setattr(bl, "free_rotations", rotations)
    dd = pd.design(_p(**changes))
    mp.prove_position(dd, dd.positions[0], 3, 3e-4)
    tol = policy.OVERLAP_AREA_TOL_MM2
    starts = [k for k, (what, _) in enumerate(events) if what == "area"]
    assert len(starts) >= 20
    inside = [events[k][1] for k in starts if events[k][1] > tol]
    assert len(inside) >= 2 and min(inside) <= 1.0
    for k in starts:
        rotated = k + 1 < len(events) and events[k + 1][0] == "rotations"
        assert rotated == (events[k][1] <= tol), (k, events[k])
