"""The non-circular pair's screen below its design (parts/noncircular_pair/feasibility.py, cutting.py, bores.py): the
given and the chosen blend of the walking law with the part file's cutter, their refusals in full with their
remedies, the module that closes a given centre distance, the law search's refusals and what it is handed, the
sector method's pointed tips and the largest module that keeps a tip land, the candidates' pitch curves, the dry
run's bores; the part file's law, rack, shaper, thinning and mounting rule; the bores' DIN 6885-1 keyway depths, the
sized bore's rule and the refusal of a given one.

Expected values from closed forms, or from the library called directly with the same inputs (never copied from the
module's output); a library call replaced by a recorder where the point is what the module hands on.  Fast and in
this process, for mutation testing (mutation/targets.toml, target ``noncircular_screen``): nothing is built at
collection or in a module-scoped fixture.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from types import SimpleNamespace

import pytest

PARTS = Path(__file__).resolve().parent.parent / "parts"


def _part(name, **kw):
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams

    _, mapping = read_part_file(PARTS / f"{name}.toml")
    mapping.update(kw)
    return load_params(NoncircularPairParams, mapping)


def _seed002(**kw):
    """Seed 002 (a = 100, b = 50, c = 236.5, n = 4, m = 2.5, z_H = 80, x = +0.5) without the law search."""
    return _part("ncg_seed002", law_search=False, **kw)


def _law():
    from propulsor.laws.walking import WalkingLaw

    return WalkingLaw(a=100.0, b=50.0, c=236.5, n=4)


def _cutter(m=2.5, alpha_deg=20.0, z0=20, x0=None, x=0.5):
    from propulsor.gears.generability import CutterSpec

    return CutterSpec(m=m, alpha=math.radians(alpha_deg), x=x, x_H=-x, z0=z0, shaper_x0=x0)


def _remedy(law, cutter, z_H):
    """The smallest generable blend up to 45 deg, said as the refusals say it."""
    from propulsor.gears.generability import choose_smoothing

    d = choose_smoothing(law, cutter, z_H, delta_max=math.pi / 4)
    deg = math.degrees(d.delta)
    return (f"a blend of {deg:.3f} deg would work (smoothing_max_deg >= {deg:.3f}; hub speed ripple "
            f"{100 * d.ripple.ripple:.2f} %)")


def _record_check_generable(monkeypatch):
    from propulsor.gears.generability import check_generable
    from propulsor.parts.noncircular_pair import feasibility

    seen = []

    def rec(pc, cutter):
        seen.append((pc.law, pc.L, cutter))
        return check_generable(pc, cutter)

    monkeypatch.setattr(feasibility, "check_generable", rec)
    return seen


# =========================================================================== the given blend
def test_a_given_blend_is_the_smoothed_law_closed_on_the_module_with_the_part_files_cutter(monkeypatch):
    """smoothing_deg = 10 at m = 2.5, alpha 22.5 deg: the blend of half-width 10 deg (the window-integral blend, no
    hand-over value); L = pi m z_H / perimeter per mm (80 pitches on the driven curve); z = 80 // 4 = 20 driver
    teeth; the rack at alpha with x = +0.5 on the driver and -0.5 on the driven wheel, the part file's shaper z0 = 20
    with x0 = -x (None); its generability and hub-speed ripple."""
    from propulsor.gears.generability import SmoothingDesign, check_generable
    from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw, hub_speed_ripple, perimeter_per_mm
    from propulsor.parts.noncircular_pair.feasibility import _smoothing

    seen = _record_check_generable(monkeypatch)
    law = _law()
    sm = _smoothing(_seed002(smoothing_deg=10.0, pressure_angle_deg=22.5), law, 2.5)
    sl = SmoothedWalkingLaw(law, math.radians(10.0))
    L = math.pi * 2.5 * 80 / float(perimeter_per_mm(sl))
    cutter = _cutter(alpha_deg=22.5)
    g = check_generable(PitchCurves(sl, L), cutter)
    assert g.ok and sl.u_h is None
    assert isinstance(sm, SmoothingDesign)
    assert sm == SmoothingDesign(law=sl, delta=math.radians(10.0), L=pytest.approx(L, rel=1e-12), z_H=80, z=20,
                                 cutter=cutter, generability=g, ripple=hub_speed_ripple(sl))
    assert sm.L == pytest.approx(L, rel=1e-12) and type(sm.z) is int and type(sm.z_H) is int
    assert seen == [(sl, pytest.approx(L, rel=1e-12), cutter)]
    # the closure: the driven curve's perimeter holds 80 pitches of pi m
    assert float(perimeter_per_mm(sm.law)) * sm.L == pytest.approx(80 * math.pi * 2.5, rel=1e-12)


def test_a_given_blend_with_a_hand_over_value_scales_u(monkeypatch):
    """blend_hand_over = 1.05: the blend's hand-over value u_h = 1.05 u of the exact law (u = the law's mean ratio
    at hand-over)."""
    from propulsor.gears.noncircular import SmoothedWalkingLaw, perimeter_per_mm
    from propulsor.parts.noncircular_pair.feasibility import _smoothing

    seen = _record_check_generable(monkeypatch)
    law = _law()
    sm = _smoothing(_seed002(smoothing_deg=10.0, blend_hand_over=1.05), law, 2.5)
    sl = SmoothedWalkingLaw(law, math.radians(10.0), u_h=1.05 * law.u)
    assert sm.law == sl and sm.law.u_h == pytest.approx(1.05 * law.u, rel=1e-15)
    assert sm.L == pytest.approx(math.pi * 2.5 * 80 / float(perimeter_per_mm(sl)), rel=1e-12)
    assert sm.delta == math.radians(10.0) and sm.generability.ok
    assert seen[0][2] == _cutter() and seen[0][0] == sl
    # a hand-over value below 1 (0.98 u) is a value too, not "none": the blend checked for generability carries it
    # (refused at 10 deg, which does not matter here)
    from propulsor.errors import InputError

    with pytest.raises(InputError):
        _smoothing(_seed002(smoothing_deg=10.0, blend_hand_over=0.98), law, 2.5)
    assert seen[-1][0].u_h == pytest.approx(0.98 * law.u, rel=1e-15)


def test_the_cutter_takes_the_catalogue_shaper_or_the_part_files_own_shift(monkeypatch):
    """shaper_d0_mm = 50 at m = 2.5: the catalogue's z0 and x0 (not the file's shaper_teeth = 23); shaper_own_x0: the
    file's shaper_teeth with its own shaper_x0; neither: shaper_teeth with x0 = -x (None)."""
    from propulsor.gears.catalogue import catalogue_shaper
    from propulsor.parts.noncircular_pair.feasibility import _smoothing

    seen = _record_check_generable(monkeypatch)
    law = _law()
    cat = catalogue_shaper(50.0, 2.5, math.radians(20.0))
    sm = _smoothing(_seed002(smoothing_deg=10.0, shaper_d0_mm=50.0, shaper_teeth=23), law, 2.5)
    assert sm.cutter == _cutter(z0=cat.z0, x0=cat.x0) and seen[-1][2] == sm.cutter and cat.x0 is not None
    own = _smoothing(_seed002(smoothing_deg=10.0, shaper_own_x0=True, shaper_x0=0.3, shaper_teeth=23), law, 2.5)
    assert own.cutter == _cutter(z0=23, x0=0.3)
    plain = _smoothing(_seed002(smoothing_deg=10.0, shaper_teeth=23), law, 2.5)
    assert plain.cutter == _cutter(z0=23, x0=None)
    assert [s[2] for s in seen] == [_cutter(z0=cat.z0, x0=cat.x0), _cutter(z0=23, x0=0.3), _cutter(z0=23)]


def _not_generable(law, deg, cutter, z_H=80):
    from propulsor.gears.generability import check_generable
    from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw, perimeter_per_mm

    sl = SmoothedWalkingLaw(law, math.radians(deg))
    g = check_generable(PitchCurves(sl, math.pi * cutter.m * z_H / float(perimeter_per_mm(sl))), cutter)
    return [c.reason for c in (g.driver, g.driven) if not c.ok]


def test_a_given_blend_that_is_not_generable_is_refused_with_its_reasons_and_the_smallest_that_works():
    """smoothing_deg = 7.5: the driven wheel's concave notch within the shaper (the driver passes); 6 deg: both
    gears; 1 deg, the least positive blend a part file gives, is a given blend too.  The remedy: the smallest
    generable blend up to 45 deg with its ripple."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import _smoothing

    law = _law()
    cutter = _cutter()
    remedy = _remedy(law, cutter, 80)
    for deg, n_reasons in ((7.5, 1), (6.0, 2), (1.0, 2)):
        reasons = _not_generable(law, deg, cutter)
        assert len(reasons) == n_reasons and all(reasons)
        with pytest.raises(InputError) as e:
            _smoothing(_seed002(smoothing_deg=deg), law, 2.5)
        assert (e.value.parameter, e.value.value) == ("smoothing_deg", deg)
        assert str(e.value) == (f"smoothing_deg = {deg!r}: the pitch curves are not generable with this blend: "
                                f"{'; '.join(reasons)} ({remedy})")
    # the driver only: a shaper of 12 teeth (r0 15 mm) fits the driven notch at 7 deg, the rack undercuts the driver
    small = _cutter(z0=12)
    reasons = _not_generable(law, 7.0, small)
    assert len(reasons) == 1 and reasons[0].startswith("driver:")
    with pytest.raises(InputError) as e:
        _smoothing(_seed002(smoothing_deg=7.0, shaper_teeth=12), law, 2.5)
    assert str(e.value) == (f"smoothing_deg = 7.0: the pitch curves are not generable with this blend: {reasons[0]} "
                            f"({_remedy(law, small, 80)})")


def test_the_remedy_says_so_when_no_blend_up_to_45_deg_works(monkeypatch):
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair import feasibility

    asked = []

    def none_works(law, cutter, z_H, **kw):
        asked.append((law, cutter, z_H, kw))
        raise InputError("delta_max", kw["delta_max"], "nothing")

    monkeypatch.setattr(feasibility, "choose_smoothing", none_works)
    law = _law()
    assert feasibility._smallest_generable(law, _cutter(), 80) == "no blend up to 45 deg works either"
    assert asked == [(law, _cutter(), 80, {"delta_max": math.pi / 4})]
    with pytest.raises(InputError) as e:
        feasibility._smoothing(_seed002(smoothing_deg=7.5), law, 2.5)
    assert str(e.value).endswith(" (no blend up to 45 deg works either)")


def test_the_blends_hand_over_value_refused_below_is_named_blend_hand_over(monkeypatch):
    """An InputError the blend raises about u_h is the part file's blend_hand_over (same value, limit, hint); any
    other passes unchanged.  The blend is asked with delta = radians(smoothing_deg) and u_h = blend_hand_over u."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair import feasibility

    asked = []

    def refuse(name):
        def blend(law, delta, u_h=None):
            asked.append((law, delta, u_h))
            raise InputError(name, 7.25, "must be small", "a hint")
        return blend

    law = _law()
    monkeypatch.setattr(feasibility, "SmoothedWalkingLaw", refuse("u_h"))
    with pytest.raises(InputError) as e:
        feasibility._smoothing(_seed002(smoothing_deg=12.0, blend_hand_over=1.5), law, 2.5)
    assert str(e.value) == "blend_hand_over = 7.25: must be small (a hint)"
    assert asked == [(law, math.radians(12.0), pytest.approx(1.5 * law.u, rel=1e-15))]
    monkeypatch.setattr(feasibility, "SmoothedWalkingLaw", refuse("delta"))
    with pytest.raises(InputError) as e:
        feasibility._smoothing(_seed002(smoothing_deg=12.0), law, 2.5)
    assert str(e.value) == "delta = 7.25: must be small (a hint)"
    assert asked[-1] == (law, math.radians(12.0), None)


# =========================================================================== the chosen blend
def test_without_a_given_blend_the_smallest_generable_is_chosen_within_smoothing_max_deg(monkeypatch):
    """smoothing_deg = 0: choose_smoothing up to radians(smoothing_max_deg), the remedies within the part file's
    field limits, named by its keys (the blend's by smoothing_max_deg); the result is that of the library."""
    from propulsor.gears.generability import choose_smoothing
    from propulsor.parts.noncircular_pair import feasibility

    law = _law()
    got = feasibility._smoothing(_seed002(smoothing_max_deg=20.0), law, 2.5)
    want = choose_smoothing(law, _cutter(), 80, delta_max=math.radians(20.0))
    assert got == want and 0 < got.delta < math.radians(20.0)
    asked = []
    monkeypatch.setattr(feasibility, "choose_smoothing", lambda *a, **kw: asked.append((a, kw)) or "SM")
    assert feasibility._smoothing(_seed002(smoothing_max_deg=20.0, pressure_angle_deg=21.0), law, 3.0) == "SM"
    assert asked == [((law, _cutter(m=3.0, alpha_deg=21.0), 80),
                      dict(delta_max=math.radians(20.0),
                           limits={"x": (-1.0, 1.5), "x_H": (-1.5, 1.0), "z_H": (4, 480), "m": (0.0, 50.0),
                                   "z0": (6, 200)},
                           keys={"x": "driver_shift", "x_H": "-driver_shift", "z_H": "driven_teeth",
                                 "m": "module_mm", "z0": "shaper_teeth", "delta": "smoothing_max_deg"}))]


def test_no_blend_within_smoothing_max_deg_is_refused_naming_it_with_the_smallest_that_works():
    """smoothing_max_deg = 2: the library's refusal (limit and remedies) after the part's sentence, and the smallest
    generable blend up to 45 deg."""
    from propulsor.errors import InputError
    from propulsor.gears.generability import choose_smoothing
    from propulsor.parts.noncircular_pair.feasibility import _smoothing

    law = _law()
    cutter = _cutter()
    p = _seed002(smoothing_max_deg=2.0)
    from propulsor.parts.noncircular_pair.smooth_law import PART_KEYS, generability_limits

    with pytest.raises(InputError) as lib:
        choose_smoothing(law, cutter, 80, delta_max=math.radians(2.0), limits=generability_limits(p),
                         keys={**PART_KEYS, "delta": "smoothing_max_deg"})
    assert "smoothing_max_deg >= " in lib.value.hint
    with pytest.raises(InputError) as e:
        _smoothing(p, law, 2.5)
    assert (e.value.parameter, e.value.value) == ("smoothing_max_deg", 2.0)
    assert str(e.value) == ("smoothing_max_deg = 2.0: no C2 smoothing up to 2 deg keeps both pitch curves generable: "
                            f"{lib.value.limit} ({lib.value.hint}) ({_remedy(law, cutter, 80)})")


def test_the_chosen_blends_refusal_keeps_the_library_limit_whole_and_stops_at_45_deg(monkeypatch):
    """The library's message after its first ': ' only (a limit with a colon of its own kept whole); below 45 deg
    the smallest blend up to 45 deg is looked for, at 45 deg not (none is larger)."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair import feasibility

    asked = []

    def refuse(law, cutter, z_H, **kw):
        asked.append(kw["delta_max"])
        raise InputError("delta_max", 0.5, "first: second", "hint")

    monkeypatch.setattr(feasibility, "choose_smoothing", refuse)
    law = _law()
    for deg, remedy, tries in ((44.9, "no blend up to 45 deg works either", [math.radians(44.9), math.pi / 4]),
                               (45.0, "no blend up to 45 deg works", [math.pi / 4])):
        asked.clear()
        with pytest.raises(InputError) as e:
            feasibility._smoothing(_seed002(smoothing_max_deg=deg), law, 2.5)
        assert str(e.value) == (f"smoothing_max_deg = {deg!r}: no C2 smoothing up to {deg:g} deg keeps both pitch "
                                f"curves generable: first: second (hint) ({remedy})")
        assert asked == pytest.approx(tries, rel=1e-15)
        assert e.value.__cause__ is None and e.value.__suppress_context__


# =========================================================================== screen
def test_screen_of_a_given_centre_distance_scales_the_module_to_close_it():
    """module_mm = 0, center_distance_mm = 130: L is linear in m (L = pi m z_H / perimeter per mm), so m = 130 x
    perimeter / (pi 80); the blend redone at that module (its cutter at m); no catalogue shaper."""
    from propulsor.gears.noncircular import SmoothedWalkingLaw, perimeter_per_mm
    from propulsor.parts.noncircular_pair.feasibility import Screen, screen

    p = _seed002(smoothing_deg=10.0, module_mm=0.0, center_distance_mm=130.0)
    s = screen(p)
    m = 130.0 * float(perimeter_per_mm(SmoothedWalkingLaw(_law(), math.radians(10.0)))) / (math.pi * 80)
    assert isinstance(s, Screen) and s.m == pytest.approx(m, rel=1e-12)
    assert s.smoothing.L == pytest.approx(130.0, rel=1e-12) and s.smoothing.cutter == _cutter(m=s.m)
    assert (s.shaper, s.search, s.entries, s.sector, s.smooth) == (None, None, (), (), None)
    # the module given: kept; the catalogue shaper named
    from propulsor.gears.catalogue import catalogue_shaper

    s2 = screen(_seed002(smoothing_deg=10.0, shaper_d0_mm=50.0))
    assert s2.m == 2.5 and s2.shaper == catalogue_shaper(50.0, 2.5) and s2.smoothing.cutter.z0 == s2.shaper.z0


def test_screen_refuses_a_mounting_distance_below_the_blends_centre_distance():
    from propulsor.errors import InputError
    from propulsor.gears.noncircular import SmoothedWalkingLaw, perimeter_per_mm
    from propulsor.parts.noncircular_pair.feasibility import screen

    L = math.pi * 2.5 * 80 / float(perimeter_per_mm(SmoothedWalkingLaw(_law(), math.radians(10.0))))
    with pytest.raises(InputError) as e:
        screen(_seed002(smoothing_deg=10.0, mounting_distance_mm=round(L - 0.01, 3)))
    assert str(e.value) == (f"mounting_distance_mm = {round(L - 0.01, 3)!r}: must be >= the design centre distance "
                            f"L = {L:.6f} mm (or 0)")
    assert screen(_seed002(smoothing_deg=10.0, mounting_distance_mm=round(L + 0.01, 3))).m == 2.5


def test_screen_asks_the_shaper_the_concave_wheel_needs_under_the_part_files_keys(monkeypatch):
    """At 10 deg the driven wheel is concave (the driver not): its tooth spec (x = -0.5, the tooth settings of the
    part file) is asked for its shaper tools; a refusal named z0 is shaper_teeth, or shaper_d0_mm with a catalogue
    shaper."""
    from propulsor.errors import InputError
    from propulsor.gears.noncircular_teeth import ToothSpec
    from propulsor.parts.noncircular_pair.cutting import rack_of
    from propulsor.parts.noncircular_pair.feasibility import screen

    asked = []

    def tools(self):
        asked.append(self)
        raise InputError("z0", self.z0, "cannot be made")

    monkeypatch.setattr(ToothSpec, "shaper_tools", tools)
    p = _seed002(smoothing_deg=10.0, tip_land_min_module=0.3, tip_height_max_module=1.1, backlash_mm=0.2,
                 rack_profile="D")
    with pytest.raises(InputError) as e:
        screen(p)
    assert str(e.value) == "shaper_teeth = 20: cannot be made"
    (t,) = asked
    assert (t.x, t.m, t.z0, t.shaper) == (-0.5, 2.5, 20, None)
    assert t.thinning_mm == pytest.approx(0.2 / (2 * math.cos(math.radians(20.0))), rel=1e-15)
    assert t.tip_min_mm == pytest.approx(0.75) and t.tip_max_mm == pytest.approx(2.75) and t.rack == rack_of(p)
    assert t.rack != ToothSpec(x=0.0, m=2.5).rack  # the file's rack D (its fillet 0.39 m), not the spec's default
    with pytest.raises(InputError) as e:
        screen(_seed002(smoothing_deg=10.0, shaper_d0_mm=50.0, shaper_teeth=23))
    assert str(e.value) == "shaper_d0_mm = 20: cannot be made" and asked[-1].shaper is not None


def test_screen_of_a_law_without_corners_is_the_smooth_laws_screen(monkeypatch):
    from propulsor.laws.ratio_laws import EllipticalLaw
    from propulsor.parts.noncircular_pair import smooth_law
    from propulsor.parts.noncircular_pair.feasibility import Screen, screen

    asked = []
    monkeypatch.setattr(smooth_law, "screen_smooth", lambda p, law: asked.append((p, law)) or SimpleNamespace(m=1.75))
    p = _part("ncg_elliptical")
    s = screen(p)
    assert asked == [(p, EllipticalLaw(0.3, 1))]
    assert s == Screen(1.75, smooth=s.smooth) and s.smooth.m == 1.75 and s.smoothing is None


# =========================================================================== the law search
def test_the_law_search_needs_a_module_with_a_catalogue_shaper():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import screen

    p = _part("ncg_seed002")
    with pytest.raises(InputError) as e:
        screen(dataclasses.replace(p, module_mm=0.0, center_distance_mm=130.0))
    assert str(e.value) == "module_mm = 0.0: the law search needs the module (catalogue cutters)"
    with pytest.raises(InputError) as e:
        screen(dataclasses.replace(p, module_mm=7.0))
    assert str(e.value) == "module_mm = 7.0: the cutter catalogue lists no shaper at this module"


def test_the_law_search_is_handed_every_catalogue_shaper_at_the_module_and_the_exact_laws_centre_distance(
        monkeypatch):
    """m = 2.5: the catalogue shapers listed at 2.5 mm (ascending d0, each cutter at the file's pressure angle), the
    exact law's closure L_ref, the band, x; a refusal about L_band is center_distance_band_mm; the mounting distance
    checked against the least L of the ranked points."""
    from propulsor.errors import InputError
    from propulsor.gears import law_search
    from propulsor.gears.catalogue import shaper_diameters, shaper_entry
    from propulsor.gears.noncircular import centre_distance
    from propulsor.parts.noncircular_pair.feasibility import Screen, screen

    asked = []
    res = SimpleNamespace(points=[SimpleNamespace(L=125.0), SimpleNamespace(L=124.5), SimpleNamespace(L=126.0)])

    def search(*a):
        asked.append(a)
        return res

    monkeypatch.setattr(law_search, "search_law", search)
    p = _part("ncg_seed002", pressure_angle_deg=21.0, center_distance_band_mm=4.0)
    law = _law()
    alpha = math.radians(21.0)
    entries = []
    for d0 in shaper_diameters():
        try:
            entries.append(shaper_entry(d0, 2.5))
        except InputError:
            pass
    assert len(entries) >= 2
    s = screen(p)
    assert s == Screen(2.5, search=res, entries=tuple(entries))
    ((lw, m, z_H, x, shapers, L_ref, band, a),) = asked
    assert (lw, m, z_H, x, band, a) == (law, 2.5, 80, 0.5, 4.0, alpha)
    assert L_ref == pytest.approx(centre_distance(law, 2.5, 80), rel=1e-15)
    assert shapers == [(e.d0_mm, e.cutter(alpha)) for e in entries]
    # the mounting distance: at least the least L of the points
    assert screen(dataclasses.replace(p, mounting_distance_mm=124.5)).search is res
    with pytest.raises(InputError) as e:
        screen(dataclasses.replace(p, mounting_distance_mm=124.49))
    assert str(e.value) == ("mounting_distance_mm = 124.49: must be >= the design centre distance L = 124.500000 mm "
                            "(or 0)")

    def band(*a):
        raise InputError("L_band", 4.0, "no blend within the band")

    monkeypatch.setattr(law_search, "search_law", band)
    with pytest.raises(InputError) as e:
        screen(p)
    assert str(e.value) == "center_distance_band_mm = 4.0: no blend within the band"


def test_the_candidates_pitch_curves_are_each_ranked_blend_at_its_centre_distance():
    from propulsor.gears.noncircular import SmoothedWalkingLaw
    from propulsor.parts.noncircular_pair.feasibility import _candidate_curves

    p = _part("ncg_seed002")
    law = _law()
    pts = [SimpleNamespace(delta=0.12, u_h_rel=1.02, L=124.0), SimpleNamespace(delta=0.2, u_h_rel=0.99, L=125.5)]
    got = _candidate_curves(p, SimpleNamespace(search=SimpleNamespace(points=pts)))
    assert [(c.law, c.L) for c in got] == [(SmoothedWalkingLaw(law, 0.12, u_h=1.02 * law.u), 124.0),
                                           (SmoothedWalkingLaw(law, 0.2, u_h=0.99 * law.u), 125.5)]
    assert got[0].law.u_h == pytest.approx(1.02 * law.u, rel=1e-15)


# =========================================================================== sectors
def test_the_sector_table_is_a_quarter_of_the_driven_teeth_a_leg_with_the_arc_a_pitch():
    """i = z_H // 4 sectors a leg; L from the module so that the sector arc is pi m (the arcs are linear in L), or
    the centre distance given."""
    from propulsor.gears.sectors import sector_table
    from propulsor.parts.noncircular_pair.feasibility import sector_design_table

    law = _law()
    table, L, m = sector_design_table(_part("ncg_seed002", method="sectors", driven_teeth=84, module_mm=2.0))
    assert m == 2.0 and table.i == 21
    assert L == pytest.approx(math.pi * 2.0 / sector_table(law, 1.0, 21).arc, rel=1e-12)
    assert table.arc == pytest.approx(math.pi * 2.0, rel=1e-12)
    table, L, m = sector_design_table(dataclasses.replace(_part("ncg_seed002", method="sectors"),
                                                          center_distance_mm=130.0))
    assert (L, m, table.i, table.L) == (130.0, 2.5, 20, 130.0)


def _root(f, lo, hi):
    """The sign change of f in [lo, hi] by scipy's Brent (an independent root finder)."""
    from scipy.optimize import brentq

    return brentq(f, lo, hi, xtol=1e-15, rtol=1e-15)


def test_the_largest_sector_module_is_where_the_thinner_tip_land_reaches_zero():
    """Seed 002's table at its L: the least tip land min(driver, driven) falls with m through 0 between 2.5 and
    3 mm; the largest module with a positive land is that root, to the last bits; a limit above the root bounds
    nothing, one below it is returned."""
    from propulsor.gears.sectors import sector_tip_thickness
    from propulsor.parts.noncircular_pair.feasibility import _largest_sector_module, sector_design_table

    table, L, m = sector_design_table(_part("ncg_seed002", method="sectors"))
    land = lambda mm: min(sector_tip_thickness(table, mm, 0.16))  # noqa: E731
    assert land(2.5) > 0 > land(3.0)
    root = _root(land, 2.5, 3.0)
    for hi in (3.0, 10.0):
        got = _largest_sector_module(table, 0.16, hi)
        assert got == pytest.approx(root, rel=1e-13, abs=0) and land(got) > 0
        assert land(got * (1 + 1e-13)) <= 0
    assert _largest_sector_module(table, 0.16, 2.0) == pytest.approx(2.0, rel=1e-15)
    # more backlash: thinner tips, a smaller module
    assert _largest_sector_module(table, 0.6, 10.0) == pytest.approx(
        _root(lambda mm: min(sector_tip_thickness(table, mm, 0.6)), 2.0, 3.0), rel=1e-13)


def test_sector_teeth_pointed_at_the_tip_are_refused_with_the_largest_module_that_keeps_a_land():
    """Seed 002 at its sector L (m 2.5) with module 3: the driver's tip land is negative; the refusal names the
    module, both lands, L and the largest module (the root of the thinner land)."""
    from propulsor.errors import InputError
    from propulsor.gears.sectors import sector_tip_thickness
    from propulsor.parts.noncircular_pair.feasibility import Screen, screen, sector_design_table

    table, L, _ = sector_design_table(_part("ncg_seed002", method="sectors"))
    p = dataclasses.replace(_part("ncg_seed002", method="sectors"), module_mm=3.0, center_distance_mm=L)
    t_drv, t_dvn = sector_tip_thickness(table, 3.0, 0.16)
    assert t_drv < 0 < t_dvn
    root = _root(lambda mm: min(sector_tip_thickness(table, mm, 0.16)), 2.5, 3.0)
    with pytest.raises(InputError) as e:
        screen(p)
    assert str(e.value) == (f"module_mm = 3.0: sector teeth are pointed at the tip: tip land {t_drv:.3f} mm <= 0 "
                            f"(driver {t_drv:.3f}, driven {t_dvn:.3f} mm) at L = {L:.4f} mm (the largest module with "
                            f"a tip land > 0 at this L is {root:.4f} mm)")
    # at the module of the table both lands are positive: the screen is the table, its L and m
    ok = screen(_part("ncg_seed002", method="sectors"))
    assert isinstance(ok, Screen) and ok.m == 2.5 and ok.sector[1:] == (L, 2.5) and ok.sector[0].i == 20
    assert (ok.smoothing, ok.search) == (None, None)
    with pytest.raises(InputError) as e:
        screen(_part("ncg_seed002", method="sectors", mounting_distance_mm=round(L - 0.01, 3)))
    assert str(e.value).startswith(f"mounting_distance_mm = {round(L - 0.01, 3)!r}: must be >= the design centre "
                                   f"distance L = {L:.6f} mm")


# =========================================================================== screened, feasible
def test_screened_is_the_screen_once_per_parameters_and_per_law_file(monkeypatch):
    from propulsor.parts import pipeline
    from propulsor.parts.noncircular_pair import feasibility

    asked = []
    monkeypatch.setattr(pipeline, "design_of", lambda p, fn, *a: asked.append((p, fn, a)) or "SCR")
    walking = _part("ncg_seed002")
    assert feasibility.screened(walking, "x/ncg_seed002.toml") == "SCR"
    assert asked == [(walking, feasibility.screen, ())]
    for name in ("ncg_table", "ncg_pitch_curve"):
        p = _part(name)
        asked.clear()
        feasibility.screened(p, PARTS / f"{name}.toml")
        assert asked == [(p, feasibility.screen, (str(PARTS / f"{name}.toml"),))]
        asked.clear()
        feasibility.screened(p)
        assert asked == [(p, feasibility.screen, (None,))]


def test_feasible_checks_the_given_bores_on_the_pitch_curves_the_screen_settled(monkeypatch):
    """A smooth law: its screen's pitch curves; a given or chosen blend: the blend at its L; the law search: every
    ranked candidate, and only when a bore is given; the sector method: none here."""
    from propulsor.parts.noncircular_pair import bores, feasibility
    from propulsor.parts.noncircular_pair.feasibility import Screen

    checked = []
    monkeypatch.setattr(bores, "check_given_on_pitch_curves", lambda p, pc, m: checked.append((p, pc, m)))
    scr = {}
    monkeypatch.setattr(feasibility, "screened", lambda p, source=None: scr["now"])
    monkeypatch.setattr(feasibility, "_candidate_curves", lambda p, s: ["PC1", "PC2"])
    p = _part("ncg_seed002")
    scr["now"] = Screen(1.5, smooth=SimpleNamespace(pc="PCS", m=1.25))
    feasibility.feasible(p)
    assert checked == [(p, "PCS", 1.25)]
    checked.clear()
    sl = _law()
    scr["now"] = Screen(2.0, smoothing=SimpleNamespace(law=sl, L=120.0))
    feasibility.feasible(p, "SRC")
    ((q0, pc, m),) = checked
    assert q0 is p and (pc.law, pc.L, m) == (sl, 120.0, 2.0)  # the file's bores, on the blend's pitch curves
    for (drv, dvn), want in (((16.0, 40.0), 1), ((0.0, 40.0), 1), ((16.0, None), 1), ((None, None), 0),
                             ((0.0, 0.0), 0)):
        kw = dict(driver_bore_mm=drv, driven_bore_mm=dvn)
        checked.clear()
        q = dataclasses.replace(p, **kw)
        scr["now"] = Screen(2.5, search="S")
        feasibility.feasible(q)
        assert checked == [(q, ["PC1", "PC2"], 2.5)] * want
    checked.clear()
    scr["now"] = Screen(2.5, sector=("T", 1.0, 2.5))
    feasibility.feasible(p)
    assert checked == []


# =========================================================================== cutting.py
def test_the_part_files_law_rack_shaper_and_thinning():
    """The walking law of a, b, c, n; the ISO 53 rack at the file's pressure angle; no shaper (shaper_teeth with
    x0 = -x), the file's own shaper of shaper_x0 on a rack of h_a* 1, c* 0.25, or the catalogue's at the module;
    thinning j_n / (2 cos alpha) on each gear."""
    from propulsor.gears.catalogue import catalogue_shaper, rack_profile
    from propulsor.gears.cutters import ShaperCutter, shaper_rack
    from propulsor.laws.walking import WalkingLaw
    from propulsor.parts.noncircular_pair.cutting import law_of, rack_of, shaper_of, thinning

    p = _part("ncg_seed000", pressure_angle_deg=22.0, backlash_mm=0.3)
    assert law_of(p) == WalkingLaw(a=60.0, b=100.0, c=360.0, n=2)
    assert rack_of(p) == rack_profile("A", math.radians(22.0))
    assert thinning(p) == pytest.approx(0.3 / (2 * math.cos(math.radians(22.0))), rel=1e-15)
    assert shaper_of(p, 2.0) is None
    own = shaper_of(_part("ncg_seed000", shaper_own_x0=True, shaper_x0=0.4, shaper_teeth=17, pressure_angle_deg=22.0),
                    2.0)
    assert own == ShaperCutter(17, 2.0, 0.4, shaper_rack(math.radians(22.0), 1.0, 0.25))
    assert shaper_of(_part("ncg_seed000", shaper_d0_mm=50.0, pressure_angle_deg=22.0), 2.0) == catalogue_shaper(
        50.0, 2.0, math.radians(22.0))


def test_a_shaper_the_catalogue_lacks_is_named_shaper_d0_mm():
    from propulsor.errors import InputError
    from propulsor.gears.catalogue import catalogue_shaper
    from propulsor.parts.noncircular_pair.cutting import shaper_of

    with pytest.raises(InputError) as lib:
        catalogue_shaper(50.0, 7.0, math.radians(20.0))
    with pytest.raises(InputError) as e:
        shaper_of(_part("ncg_seed000", shaper_d0_mm=50.0), 7.0)
    assert (e.value.parameter, e.value.value, e.value.limit, e.value.hint) == (
        "shaper_d0_mm", lib.value.value, lib.value.limit, lib.value.hint)


def test_mounting_fits_at_or_beyond_L_less_a_nanometre():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.cutting import mounting_fits

    p = _part("ncg_seed000")
    for v in (0.0, 100.0, 100.0 - 1e-9, 100.0 - 0.5e-9, 101.0):
        mounting_fits(dataclasses.replace(p, mounting_distance_mm=v), 100.0)
    for v in (100.0 - 2e-9, 50.0):
        with pytest.raises(InputError) as e:
            mounting_fits(dataclasses.replace(p, mounting_distance_mm=v), 100.0)
        assert str(e.value) == (f"mounting_distance_mm = {v!r}: must be >= the design centre distance "
                                "L = 100.000000 mm (or 0)")


# =========================================================================== bores.py
def test_keyway_depths_are_din_6885_1s_by_the_shafts_range():
    """t2 (hub) of DIN 6885-1: over 12 up to 17 mm 2.3, over 17 up to 22 mm 2.8, over 6 up to 8 mm 1.0; none
    without a keyway."""
    from propulsor.parts.noncircular_pair.bores import _t2, bore_limit

    assert [_t2(d, True) for d in (7.0, 8.0, 16.0, 17.0, 17.5, 22.0, 40.0)] == [1.0, 1.0, 2.3, 2.3, 2.8, 2.8, 3.3]
    assert _t2(16.0, False) == 0.0
    assert bore_limit(30.0, 2.0) == 28.0 and bore_limit(10.0, 0.5) == 9.5


def test_the_largest_standard_bore_under_a_limit_with_and_without_its_keyway():
    """lim 12: keyed 18 (9 + 2.8 = 11.8 < 12; 19: 12.3), plain 22 (11 < 12; 24: 12); lim 11.8: keyed 16 (18 reaches
    it); lim 5: keyed 7 (3.5 + 1.0; 6 mm is below DIN 6885-1's range), plain 9; lim 4: no keyed bore, plain 7; keyed
    up to 230 mm only (220 at any limit above 110 + 11.4)."""
    from propulsor.parts.noncircular_pair.bores import largest_bore

    assert largest_bore(12.0, True) == 18.0 and largest_bore(12.0, False) == 22.0
    assert largest_bore(11.8, True) == 16.0 and largest_bore(11.80001, True) == 18.0
    assert largest_bore(5.0, True) == 7.0 and largest_bore(5.0, False) == 9.0
    assert largest_bore(4.0, True) is None and largest_bore(4.0, False) == 7.0
    assert largest_bore(1.5, False) is None
    assert largest_bore(500.0, True) == 220.0


def test_a_given_bore_is_refused_when_it_or_its_keyway_reaches_a_module_below_the_root():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.bores import check_given

    check_given("driver_bore_mm", 0.0, True, 1.0, 2.0)  # none given
    check_given("driver_bore_mm", 18.0, True, 13.81, 2.0)  # 9 + 2.8 = 11.8 < 11.81
    with pytest.raises(InputError) as e:
        check_given("driver_bore_mm", 18.0, True, 13.8, 2.0)
    assert str(e.value) == ("driver_bore_mm = 18.0: bore + keyway must stay one module inside the root: bore/2 + t2 = "
                            "11.800 mm >= 11.800 mm (the largest standard bore that fits is 16 mm; leave "
                            "driver_bore_mm out to size it from the gear)")
    check_given("driven_bore_mm", 22.0, False, 13.01, 2.0)
    with pytest.raises(InputError) as e:
        check_given("driven_bore_mm", 22.0, False, 13.0, 2.0)
    assert str(e.value) == ("driven_bore_mm = 22.0: bore must stay one module inside the root: bore/2 + t2 = 11.000 mm "
                            ">= 11.000 mm (the largest standard bore that fits is 20 mm; leave driven_bore_mm out to "
                            "size it from the gear)")
    with pytest.raises(InputError) as e:
        check_given("driven_bore_mm", 10.0, True, 5.0, 1.0)
    assert str(e.value) == ("driven_bore_mm = 10.0: bore + keyway must stay one module inside the root: bore/2 + t2 = "
                            "6.400 mm >= 4.000 mm (no standard keyed bore fits; keyway = false allows a plain one; "
                            "leave driven_bore_mm out to size it from the gear)")
    with pytest.raises(InputError) as e:
        check_given("driven_bore_mm", 10.0, False, 2.5, 1.0)
    assert str(e.value).endswith("(no standard bore fits; leave driven_bore_mm out to size it from the gear)")


def test_a_sized_bore_is_the_largest_standard_shaft_within_the_hub_and_the_rim():
    """r_f 20, m 2: hub d <= 2 x 20 / 2 = 20, rim: d/2 + t2 < 18: keyed 20 (10 + 2.8), rim 20 - 10 - 2.8 = 7.20 mm;
    r_f 20, m 8: rim binds (lim 12): keyed 18; r_f 5, m 2: no keyed bore (7 mm: 3.5 + 1 >= 3), plain 5 (hub 5)."""
    from propulsor.parts.noncircular_pair.bores import Bore, size_bore

    assert size_bore(20.0, 2.0, True) == Bore(20.0, True, True, (
        "20 mm: the least root radius r_f = 20.00 mm carries a standard shaft of d <= 20.00 mm (a body 2 d across); "
        "the bore with its DIN 6885-1 keyway (6 mm wide, t2 = 2.8 mm) leaves a rim of 7.20 mm >= 1 m = 2.00 mm below "
        "the root"))
    assert size_bore(20.0, 8.0, True).d_mm == 18.0 and size_bore(20.0, 8.0, False).d_mm == 20.0
    assert size_bore(20.0, 2.0, False) == Bore(20.0, False, True, (
        "20 mm: the least root radius r_f = 20.00 mm carries a standard shaft of d <= 20.00 mm (a body 2 d across); "
        "the bore leaves a rim of 10.00 mm >= 1 m = 2.00 mm below the root"))
    assert size_bore(5.0, 2.0, True) == Bore(0.0, False, True, (
        "no bore: the least root radius r_f = 5.00 mm carries a standard shaft of d <= 5.00 mm (a body 2 d across), "
        "and the smallest keyed bore, 7 mm, does not fit; keyway = false gives a plain bore"))
    assert size_bore(5.0, 2.0, False).d_mm == 5.0
    assert size_bore(1.4, 0.5, False) == Bore(0.0, False, True, (
        "no bore: the least root radius r_f = 1.40 mm carries a standard shaft of d <= 1.40 mm (a body 2 d across), "
        "and the smallest bore, 3 mm, does not fit"))


def test_the_root_bound_is_the_largest_pitch_radius_within_a_pitch_of_the_least():
    """Stand-in pitch curves: the driver's r = 50 + 10 cos phi, least (40) at phi = pi, the driven wheel's
    r_H = 80 - 5 cos phi, least (75) at 0, the contact arc 40 mm per rad: a pitch pi m either way is w = pi m / 40 rad,
    the largest radius within it 40 + 10 (1 - cos w), 75 + 5 (1 - cos w).  The sampled bound lies at or above it, by
    at most
    the radius change over a sample (A dphi) and the window's widening by a sample (A sin(w + dphi) dphi)."""
    import numpy as np

    from propulsor.parts.noncircular_pair.bores import root_bound

    pc = SimpleNamespace(r=lambda phi: 50.0 + 10.0 * np.cos(phi), r_H=lambda phi: 80.0 - 5.0 * np.cos(phi),
                         ds_dphi=lambda phi: np.full_like(phi, 40.0))
    for which, A, least in (("driver", 10.0, 40.0), ("driven", 5.0, 75.0)):
        for m, samples in ((2.0, 4096), (3.0, 1000)):
            w = math.pi * m / 40.0
            dphi = 2 * math.pi / samples
            true = least + A * (1 - math.cos(w))
            got = root_bound(pc, which, m, samples)
            assert true <= got <= true + A * dphi * (1 + math.sin(w + dphi)) + 1e-12, (which, m, samples)
    # a pitch either way, not half a pitch nor two
    got = root_bound(pc, "driver", 2.0)
    assert got > 40.0 + 10.0 * (1 - math.cos(0.75 * math.pi * 2.0 / 40.0)) + 10.0 * 2 * math.pi / 4096
    assert got < 40.0 + 10.0 * (1 - math.cos(1.25 * math.pi * 2.0 / 40.0))


def test_the_root_bound_covers_a_crest_between_samples_and_a_window_across_phi_0():
    """r = 45 - 5 cos 4 phi (least 40 at phi = 0, crests of 50 at pi/4 + k pi/2), 5 mm of arc per rad, m = 2: a pitch
    either way is 2 pi / 5 = 1.26 rad > pi/4, so the window holds a crest; at 60 samples the crest lies midway between
    two (pi/4 = 7.5 samples), whose radii fall short of 50: the bound adds the largest change between samples
    (at most 20 dphi).  r = 40 + 10 (1 - cos phi) - 4 sin phi + 0.8 sin 2 phi: least at a phi0 > 0 (found on a fine
    grid), the window of w = 0.2 pi rad reaches across phi = 0 to the side where r rises faster: the largest radius
    within it (on the fine grid), r(phi0 - w), is the bound's floor."""
    import numpy as np

    from propulsor.parts.noncircular_pair.bores import root_bound

    dphi = 2 * math.pi / 60
    crest = SimpleNamespace(r=lambda phi: 45.0 - 5.0 * np.cos(4 * phi), r_H=None,
                            ds_dphi=lambda phi: np.full_like(phi, 5.0))
    assert max(45.0 - 5.0 * math.cos(4 * k * dphi) for k in range(-12, 13)) < 49.9
    assert 50.0 <= root_bound(crest, "driver", 2.0, 60) <= 50.0 + 20.0 * dphi
    f = lambda phi: 40.0 + 10.0 * (1 - np.cos(phi)) - 4.0 * np.sin(phi) + 0.8 * np.sin(2 * phi)  # noqa: E731
    skew = SimpleNamespace(r_H=f, r=None, ds_dphi=lambda phi: np.full_like(phi, 10.0))
    fine = np.linspace(-math.pi, math.pi, 200001)
    phi0, w = float(fine[np.argmin(f(fine))]), math.pi * 2.0 / 10.0
    window = fine[np.abs(fine - phi0) <= w]
    true = float(np.max(f(window)))
    assert 0 < phi0 < w and true == pytest.approx(float(f(phi0 - w)), abs=1e-3) and f(phi0 - w) > f(phi0 + w) + 0.3
    got = root_bound(skew, "driven", 2.0, 4096)
    assert true <= got <= true + 2 * 17.0 * 2 * math.pi / 4096


def test_the_root_bound_widens_its_window_by_a_sample_for_a_crest_at_its_edge():
    """A crest 5 mm high and half a sample wide (sigma) at 6.7 samples from the least radius (phi = 0), the window
    reaching 6.8 samples (64 samples, arc 64 / 6.8 mm per rad, m = 2): the crest lies within a pitch, between the
    6th sample (0.7 below: 0.70 mm up) and the 7th (beyond the pitch, 3.49 mm up); the sample changes reach at
    most 3.49 mm, so without the 7th sample the bound would stay below the crest."""
    import numpy as np

    from propulsor.parts.noncircular_pair.bores import root_bound

    dphi = 2 * math.pi / 64
    def r(phi):
        off = (phi + math.pi) % (2 * math.pi) - math.pi - 6.7 * dphi
        return 40.0 + 0.01 * (1 - np.cos(phi)) + 5.0 * np.exp(-(off / (0.5 * dphi)) ** 2)

    pc = SimpleNamespace(r=r, r_H=None, ds_dphi=lambda phi: np.full_like(phi, 64 / 6.8))
    w = math.pi * 2.0 / (64 / 6.8)
    assert w == pytest.approx(6.8 * dphi, rel=1e-12)
    fine = np.linspace(-w, w, 100001)
    crest = float(np.max(r(fine)))
    samples = r(np.arange(65) * dphi)
    assert crest > 44.9 and float(samples[6]) + float(np.max(np.abs(np.diff(samples)))) < crest
    assert crest <= root_bound(pc, "driver", 2.0, 64) <= crest + 2 * 3.5


def test_a_given_bore_is_refused_on_the_pitch_curves_with_the_bound_it_reaches():
    """Stand-in pitch curves of constant radius (circles: the root bound is the radius itself), m = 2, a rim of one
    module: the driver (r = 50) takes a plain bore below 96 mm and refuses 96 (48 >= 48, the limit itself); the driven
    wheel (r_H = 24.5) refuses a keyed 40 mm bore (DIN 6885-1, 38-44 mm: t2 = 3.3 mm; 23.3 >= 22.5) and takes a keyed
    30 mm one (over 30-38 mm: t2 = 3.3; 18.3 < 22.5); of two candidate curves (r = 50 and 55) a bore is refused only
    where it reaches the root on both (the larger bound, 55); a bore of 1 mm on a 0.9 mm curve (m = 0.5) is refused;
    none given or 0: nothing checked."""
    import numpy as np

    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.bores import check_given_on_pitch_curves

    def circle(r, r_H):
        return SimpleNamespace(r=lambda phi: np.full_like(phi, r), r_H=lambda phi: np.full_like(phi, r_H),
                               ds_dphi=lambda phi: np.full_like(phi, 30.0))

    def part(driver=None, driven=None, keyway=False):
        return SimpleNamespace(driver_bore_mm=driver, driven_bore_mm=driven, keyway=keyway)

    pc = circle(50.0, 24.5)
    check_given_on_pitch_curves(part(95.9), pc, 2.0)
    with pytest.raises(InputError) as e:
        check_given_on_pitch_curves(part(96.0), pc, 2.0)
    assert (e.value.parameter, e.value.value) == ("driver_bore_mm", 96.0)
    assert e.value.limit == ("bore must stay one module inside the root, which lies inside the pitch curve: bore/2 + "
                             "t2 = 48.000 mm >= 48.000 mm (the driver's largest pitch radius within a pitch of its "
                             "least, 50.000 mm, less 2.000 mm)")
    assert e.value.hint.endswith("; leave driver_bore_mm out to size it from the gear")
    check_given_on_pitch_curves(part(driven=30.0, keyway=True), pc, 2.0)
    with pytest.raises(InputError) as e:
        check_given_on_pitch_curves(part(driven=40.0, keyway=True), pc, 2.0)
    assert (e.value.parameter, e.value.value) == ("driven_bore_mm", 40.0)
    assert e.value.limit == ("bore + keyway must stay one module inside the root, which lies inside the pitch curve: "
                             "bore/2 + t2 = 23.300 mm >= 22.500 mm (the driven's largest pitch radius within a pitch "
                             "of its least, 24.500 mm, less 2.000 mm)")
    # candidates: refused only on the larger bound
    check_given_on_pitch_curves(part(105.9), [circle(50.0, 24.5), circle(55.0, 24.5)], 2.0)
    with pytest.raises(InputError) as e:
        check_given_on_pitch_curves(part(106.0), [circle(50.0, 24.5), circle(55.0, 24.5)], 2.0)
    assert "bore/2 + t2 = 53.000 mm >= 53.000 mm" in e.value.limit and "55.000 mm, less 2.000 mm" in e.value.limit
    with pytest.raises(InputError) as e:
        check_given_on_pitch_curves(part(1.0), circle(0.9, 0.9), 0.5)
    assert "bore/2 + t2 = 0.500 mm >= 0.400 mm" in e.value.limit and "0.900 mm, less 0.500 mm" in e.value.limit
    for none in (None, 0.0):
        check_given_on_pitch_curves(part(none, none, True), circle(0.9, 0.9), 0.5)
    check_given_on_pitch_curves(part(400.0), [], 2.0)  # no curves: nothing to check against


def test_the_bores_of_a_design_as_given_or_sized_with_their_keyways():
    """bores(p, d) on a stand-in design (least root radii 60 and 30 mm, m = 2): a bore given is kept as given (not
    sized), keyed only where the part file keys it and the bore is not 0; one left out is sized from its gear; a given
    bore 0.5 mm under the rim limit taken, at the limit refused (check_given: a plain bore, d/2 < r_f - m; a 0.9 mm one
    on a 0.9 mm root at m = 0.5 refused, 0 never checked)."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.bores import Bore, bores, check_given, size_bore

    d = SimpleNamespace(driver=SimpleNamespace(root_min_radius=60.0), driven=SimpleNamespace(root_min_radius=30.0),
                        m=2.0)

    def part(driver, driven, keyway):
        return SimpleNamespace(driver_bore_mm=driver, driven_bore_mm=driven, keyway=keyway)

    drv, dvn = bores(part(40.0, None, False), d)
    assert drv == Bore(40.0, False, False) and drv.sized is False and drv.keyway is False
    assert dvn == size_bore(30.0, 2.0, False) and dvn.sized is True
    drv, dvn = bores(part(40.0, 0.0, True), d)
    assert drv == Bore(40.0, True, False) and dvn == Bore(0.0, False, False)
    check_given("driven_bore_mm", 55.0, False, 30.0, 2.0)  # 27.5 < 28
    with pytest.raises(InputError) as e:
        check_given("driven_bore_mm", 56.0, False, 30.0, 2.0)
    assert e.value.limit == "bore must stay one module inside the root: bore/2 + t2 = 28.000 mm >= 28.000 mm"
    with pytest.raises(InputError):
        check_given("driven_bore_mm", 0.9, False, 0.9, 0.5)  # 0.45 >= 0.4
    check_given("driven_bore_mm", 0.0, True, 1.4, 0.5)


def test_the_note_on_the_bores_sized_names_each_sized_bore_and_its_rule():
    """The report's note: nothing where the part file gives both bores; each bore sized from its gear named with its
    key and its rule, joined with "and no" and "; "."""
    from propulsor.parts.noncircular_pair.bores import Bore, sized_derived, sized_note

    given, a, b = Bore(40.0, True, False), Bore(30.0, True, True, "30 mm: rule A"), Bore(0.0, False, True, "no bore: B")
    assert sized_note((given, given)) == "" and sized_derived((given, given)) == {}
    assert sized_note((a, b)) == ("Bores sized from the gear (the part file gives no driver_bore_mm and no "
                                  "driven_bore_mm; give one to choose it): driver 30 mm: rule A; driven no bore: B.")
    assert sized_note((given, b)) == ("Bores sized from the gear (the part file gives no driven_bore_mm; give one to "
                                      "choose it): driven no bore: B.")
    assert sized_note((a, given)).startswith("Bores sized from the gear (the part file gives no driver_bore_mm; give")
    assert sized_derived((a, b)) == {"driver_bore_mm": 30.0, "driven_bore_mm": 0.0}


def test_an_unknown_rack_profile_is_refused_under_the_part_files_key():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.cutting import rack_of

    with pytest.raises(InputError) as e:
        rack_of(SimpleNamespace(rack_profile="E", pressure_angle_deg=20.0))  # ISO 53 has A to D
    assert e.value.parameter == "rack_profile" and e.value.value == "E" and "ISO 53" in e.value.limit


def test_the_files_own_shaper_is_refused_under_the_files_keys_and_a_d0_below_a_millimetre_asks_the_catalogue():
    """shaper_d0_mm = 0 (none): the own shaper of shaper_teeth and shaper_x0, whose refusals name those keys (the
    cutter's z0 and x0); any d0 > 0, however small, is the catalogue's to accept or refuse."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.cutting import shaper_of

    own = dict(shaper_d0_mm=0.0, shaper_own_x0=True, pressure_angle_deg=20.0, shaper_teeth=17, shaper_x0=0.2)
    with pytest.raises(InputError) as e:
        shaper_of(SimpleNamespace(**{**own, "shaper_teeth": 5}), 2.0)
    assert (e.value.parameter, e.value.value) == ("shaper_teeth", 5)
    with pytest.raises(InputError) as e:
        shaper_of(SimpleNamespace(**{**own, "shaper_x0": math.nan}), 2.0)
    assert e.value.parameter == "shaper_x0" and math.isnan(e.value.value)
    with pytest.raises(InputError) as e:
        shaper_of(SimpleNamespace(shaper_d0_mm=0.5, shaper_own_x0=False, pressure_angle_deg=20.0), 2.0)
    assert (e.value.parameter, e.value.value) == ("shaper_d0_mm", 0.5)


def test_a_two_lobe_elliptical_pair_is_the_law_of_its_driver_turns():
    from propulsor.laws.ratio_laws import EllipticalLaw
    from propulsor.parts.noncircular_pair.cutting import law_of

    p = _part("ncg_elliptical_2lobe")
    assert p.law == "elliptical" and p.driver_turns == 2
    assert law_of(p) == EllipticalLaw(p.eccentricity, 2) and law_of(p).k == 2


def test_a_mounting_distance_below_a_millimetre_is_refused_like_any_other_below_L():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.cutting import mounting_fits

    with pytest.raises(InputError) as e:
        mounting_fits(SimpleNamespace(mounting_distance_mm=0.5), 100.0)
    assert e.value.parameter == "mounting_distance_mm" and e.value.value == 0.5


def test_the_pair_is_cut_driver_beside_driven_here_with_the_driven_wheels_teeth_counted(monkeypatch):
    """The driver's outline goes to ``parallel.start`` (a forked worker), which is handed on so that each wheel may
    fit half its teeth in one more; the driven wheel is cut here, its teeth counted through the build's reporter as
    the step "generated: the driven wheel's teeth cut and fitted" in steps."""
    import propulsor.geometry.noncircular_outline as outline_module
    import propulsor.parallel as parallel
    from propulsor.parts.noncircular_pair.cutting import generate_pair
    from propulsor.policy import SPLINE_FIT_TOL_MM
    from propulsor.progress import Reporter

    calls, started = [], []

    def gear(pc, role, spec, frame, tol, start=None, tick=None):
        calls.append((pc, role, spec, frame, tol, start, tick))
        if tick is not None:
            tick(3, 10)
        return f"outline of the {role}"

    def start(fn, *args):
        started.append(fn)
        return SimpleNamespace(result=lambda: fn(*args))

    monkeypatch.setattr(outline_module, "generate_gear", gear)
    monkeypatch.setattr(parallel, "start", start)
    said = []
    got = generate_pair("PC", "SPEC1", "SPEC2", "FRAME", Reporter(said.append))
    assert got == ("outline of the driver", "outline of the driven")
    assert started[0] is gear
    driver = next(c for c in calls if c[1] == "driver")
    driven = next(c for c in calls if c[1] == "driven")
    assert driver[:6] == ("PC", "driver", "SPEC1", "FRAME", SPLINE_FIT_TOL_MM, start) and driver[6] is None
    assert driven[:6] == ("PC", "driven", "SPEC2", "FRAME", SPLINE_FIT_TOL_MM, start)
    assert [str(e) for e in said] == ["generated: the driven wheel's teeth cut and fitted: step 3/10"]
    assert (said[0].phase, said[0].done, said[0].total) == ("generated: the driven wheel's teeth cut and fitted", 3, 10)
    # without a reporter nothing is counted (and nothing breaks)
    calls.clear()
    generate_pair("PC", "SPEC1", "SPEC2", "FRAME", None)
    assert next(c for c in calls if c[1] == "driven")[6] is None


def test_a_module_below_a_millimetre_is_the_files_and_a_centre_distance_below_one_scales_the_module_to_it():
    """module_mm = 0.8 (>= ISO 54's 0.05): kept, the blend's L that of 0.8 mm; center_distance_mm = 0.9 mm (module
    0): the module that closes L = 0.9 mm (the design is scale invariant: L = pi m z_H / perimeter per mm)."""
    from propulsor.gears.noncircular import SmoothedWalkingLaw, perimeter_per_mm
    from propulsor.parts.noncircular_pair.feasibility import screen

    per = float(perimeter_per_mm(SmoothedWalkingLaw(_law(), math.radians(10.0))))
    s = screen(_seed002(smoothing_deg=10.0, module_mm=0.8))
    assert s.m == 0.8 and s.smoothing.L == pytest.approx(math.pi * 0.8 * 80 / per, rel=1e-12)
    s = screen(_seed002(smoothing_deg=10.0, module_mm=0.0, center_distance_mm=0.9))
    assert s.m == pytest.approx(0.9 * per / (math.pi * 80), rel=1e-12)
    assert s.smoothing.L == pytest.approx(0.9, rel=1e-12) and s.smoothing.cutter == _cutter(m=s.m)


def test_the_sector_table_takes_a_given_centre_distance_below_a_millimetre():
    from propulsor.parts.noncircular_pair.feasibility import sector_design_table

    table, L, m = sector_design_table(_part("ncg_seed002", method="sectors", center_distance_mm=0.9))
    assert (L, m, table.L) == (0.9, 2.5, 0.9)


def test_the_largest_sector_module_below_a_millimetre():
    """Seed 002's sector table at a tenth of its L: its teeth a tenth as wide; the largest module with a land, the
    root of the thinner land, lies below 1 mm."""
    from propulsor.gears.sectors import sector_table, sector_tip_thickness
    from propulsor.parts.noncircular_pair.feasibility import _largest_sector_module, sector_design_table

    table, L, _ = sector_design_table(_part("ncg_seed002", method="sectors"))
    small = sector_table(_law(), 0.1 * L, table.i)
    land = lambda mm: min(sector_tip_thickness(small, mm, 0.016))  # noqa: E731
    assert land(0.2) > 0 > land(0.5)
    root = _root(land, 0.2, 0.5)
    got = _largest_sector_module(small, 0.016, 1.0)
    assert root < 1.0 and got == pytest.approx(root, rel=1e-13, abs=0)


def test_the_law_search_takes_the_shapers_the_catalogue_lists_at_the_module_past_those_it_lacks(monkeypatch):
    """At 3 mm the catalogue has no 25 mm shaper (its first) but the four larger ones: the search is handed those; at
    0.8 mm it has none: refused as such (the module is given)."""
    from propulsor.errors import InputError
    from propulsor.gears import law_search
    from propulsor.gears.catalogue import shaper_diameters, shaper_entry
    from propulsor.parts.noncircular_pair.feasibility import screen

    asked = []
    res = SimpleNamespace(points=[SimpleNamespace(L=150.0)])
    monkeypatch.setattr(law_search, "search_law", lambda *a: asked.append(a) or res)
    with pytest.raises(InputError):
        shaper_entry(shaper_diameters()[0], 3.0)
    s = screen(_part("ncg_seed002", module_mm=3.0))
    assert [e.d0_mm for e in s.entries] == [38.0, 50.0, 75.0, 100.0] == [d for d, _ in asked[0][4]]
    with pytest.raises(InputError) as e:
        screen(_part("ncg_seed002", module_mm=0.8))
    assert str(e.value) == "module_mm = 0.8: the cutter catalogue lists no shaper at this module"
