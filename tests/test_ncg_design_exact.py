"""The non-circular pair's design of the walking law, step by step (parts/noncircular_pair/design.py): the papers'
sector method on seed 002 and seed 000, the generated teeth of a given blend and of the law search's ranked
candidates (the tooth generator replaced by a recorder, so each candidate's cutter, blend and frame are read as
the design hands them over), the feasibility of a sector pair's given bores.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``noncircular_design``): nothing is
built at collection or in a module-scoped fixture.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from stand_ins import record_generate_pair

PARTS = Path(__file__).resolve().parent.parent / "parts"


def _part(name, **kw):
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams

    _, mapping = read_part_file(PARTS / f"{name}.toml")
    mapping.update(kw)
    return load_params(NoncircularPairParams, mapping)


def _record_sector_gears(monkeypatch, error=None):
    """geometry.sector_outline's two gear builders replaced: each call recorded, answered "DRV" / "DVN" (or
    ``error`` raised by the driver's)."""
    from propulsor.geometry import sector_outline

    calls = []

    def drv(table, m, backlash):
        calls.append(("driver", table, m, backlash))
        if error is not None:
            raise error
        return "DRV"

    def dvn(table, m, backlash):
        calls.append(("driven", table, m, backlash))
        return "DVN"

    monkeypatch.setattr(sector_outline, "sector_driver_gear", drv)
    monkeypatch.setattr(sector_outline, "sector_driven_gear", dvn)
    return calls


def _record_generate_pair(monkeypatch, outcomes):
    """design.generate_pair replaced (stand_ins.record_generate_pair)."""
    import importlib

    return record_generate_pair(monkeypatch, importlib.import_module("propulsor.parts.noncircular_pair.design"),
                                outcomes)


# =========================================================================== sectors
def test_sector_design_of_seed_002_is_the_papers_table_at_the_module_with_its_closure(monkeypatch):
    """Seed 002 (n = 4, z_H = 80, m = 2.5): i = 80 / 4 = 20 sectors a leg, L = pi m / arc of the table at L = 1 (the
    sector arcs are linear in L); the outlines of the table at m with the part file's backlash 0.16 mm; the closure
    |4 sum dtheta - 2 pi n|; z = 80 / 4 = 20 driver teeth; the hub speed of the table."""
    from propulsor.gears.sectors import sector_hub_speed, sector_table
    from propulsor.laws.walking import WalkingLaw
    from propulsor.parts.noncircular_pair.design import design_sectors

    calls = _record_sector_gears(monkeypatch)
    p = _part("ncg_seed002", method="sectors")
    said = []
    d = design_sectors(p, said.append)
    law = WalkingLaw(a=100.0, b=50.0, c=236.5, n=4)
    L = math.pi * 2.5 / sector_table(law, 1.0, 20).arc
    assert said == ["sectors: outlines (20 sectors per leg)"]
    assert (d.method, d.m, d.z_H, d.z, type(d.z_H), type(d.z)) == ("sectors", 2.5, 80, 20, int, int)
    assert d.law == law and d.run_law is d.law and d.L == pytest.approx(L, rel=1e-12)
    assert d.table.i == 20 and d.table.arc == pytest.approx(math.pi * 2.5, rel=1e-12)
    assert d.pc.law is d.law and d.pc.L == d.L
    assert calls == [("driver", d.table, 2.5, 0.16), ("driven", d.table, 2.5, 0.16)]
    assert (d.driver, d.driven, d.smoothing, d.shaper, d.search_tries) == ("DRV", "DVN", None, None, ())
    assert d.closure_error == pytest.approx(abs(4 * float(np.sum(d.table.dtheta)) - 8 * math.pi), abs=1e-15)
    assert d.closure_error < 1e-9
    hub = sector_hub_speed(d.table)
    assert d.ripple == hub


def test_sector_design_of_seed_000_counts_the_driver_teeth_by_its_turns(monkeypatch):
    """Seed 000 (n = 2, z_H = 96, m = 2): 24 sectors a leg, z = 96 / 2 = 48; the given backlash reaches the
    outlines."""
    from propulsor.parts.noncircular_pair.design import design_sectors

    calls = _record_sector_gears(monkeypatch)
    p = _part("ncg_seed000", method="sectors", backlash_mm=0.3)
    d = design_sectors(p)
    assert (d.z_H, d.z, d.m, d.table.i, d.law.n) == (96, 48, 2.0, 24, 2)
    assert [c[2:] for c in calls] == [(2.0, 0.3), (2.0, 0.3)]
    assert d.closure_error == pytest.approx(abs(4 * float(np.sum(d.table.dtheta)) - 4 * math.pi), abs=1e-15)


def test_sector_outlines_refusing_name_the_part_files_keys(monkeypatch):
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.design import design_sectors

    for key, name in (("m", "module_mm"), ("z_H", "driven_teeth"), ("z0", "shaper_teeth")):
        _record_sector_gears(monkeypatch, InputError(key, 3, "too few"))
        with pytest.raises(InputError) as e:
            design_sectors(_part("ncg_seed002", method="sectors"))
        assert str(e.value) == f"{name} = 3: too few"


def test_design_of_the_sector_method_is_the_dry_runs_sector_design(monkeypatch):
    """design() of a sector pair: design_sectors through the parameters' store (the same object a second time),
    its progress passed on."""
    from propulsor.parts.noncircular_pair.design import design

    calls = _record_sector_gears(monkeypatch)
    p = _part("ncg_seed002", method="sectors")
    said = []
    d = design(p, said.append)
    assert d.method == "sectors" and d.driver == "DRV" and said == ["sectors: outlines (20 sectors per leg)"]
    assert design(p) is d and len(calls) == 2


def test_feasibility_of_a_sector_pair_checks_its_given_bores_on_the_cut_roots(monkeypatch):
    from propulsor.parts.noncircular_pair import bores, feasibility
    from propulsor.parts.noncircular_pair.design import feasible

    seen = []
    monkeypatch.setattr(feasibility, "feasible", lambda p, source=None: seen.append(("screen", p, source)))
    monkeypatch.setattr(bores, "check_given_on_design", lambda p, d: seen.append(("bores", p, d.method, d.driver)))
    _record_sector_gears(monkeypatch)
    p = _part("ncg_seed002", method="sectors")
    feasible(p, "SRC")
    assert seen == [("screen", p, "SRC"), ("bores", p, "sectors", "DRV")]
    seen.clear()
    q = _part("ncg_seed002", law_search=False)
    feasible(q)
    assert seen == [("screen", q, None)]


def test_feasibility_refuses_a_sector_pairs_bore_wider_than_its_root():
    """The real outlines (0.5 s): the driven wheel's 40 mm bore fits, a 400 mm one is refused by its key."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.design import feasible

    feasible(_part("ncg_seed002", method="sectors"))
    with pytest.raises(InputError) as e:
        feasible(_part("ncg_seed002", method="sectors", driven_bore_mm=400.0))
    assert e.value.parameter == "driven_bore_mm" and e.value.value == 400.0


# =========================================================================== generated, a given blend
def test_generated_teeth_of_the_walking_law_on_the_screened_blend(monkeypatch):
    """law_search = false: the screen's blend, module and centre distance; both wheels cut on one arc-length frame
    of its pitch curves, the driver at +x and the driven wheel at -x, thinned by j_n / (2 cos alpha) each, with the
    part file's shaper_teeth, tip land 0.25 m and tip height limit."""
    from propulsor.gears.noncircular_teeth import ArcFrame
    from propulsor.parts.noncircular_pair.cutting import rack_of
    from propulsor.parts.noncircular_pair.design import design_generated
    from propulsor.parts.noncircular_pair.feasibility import screened

    p = _part("ncg_seed002", law_search=False, tip_height_max_module=1.5, shaper_teeth=23, rack_profile="C")
    sm = screened(p).smoothing
    calls = _record_generate_pair(monkeypatch, [("G1", "G2")])
    said = []
    d = design_generated(p, said.append)
    assert said == ["generated: choosing the smoothing of the law",
                    "generated: the teeth of both wheels (20 and 80), rack/shaper envelopes"]
    c = calls[0]
    assert c.pc == sm.pair and isinstance(c.frame, ArcFrame) and c.frame.pc == sm.pair and c.progress == said.append
    th = 0.16 / (2 * math.cos(math.radians(20.0)))
    for spec, x in ((c.drv, 0.5), (c.dvn, -0.5)):
        assert (spec.m, spec.x, spec.z0, spec.shaper, spec.rack) == (2.5, x, 23, None, rack_of(p))
        assert spec.rack != rack_of(_part("ncg_seed002"))  # profile C, not the default A
        assert spec.thinning_mm == pytest.approx(th, rel=1e-12)
        assert spec.tip_min_mm == pytest.approx(0.625) and spec.tip_max_mm == pytest.approx(3.75)
        assert spec.tip_floor == 0.5
    assert (d.method, d.law.n, d.run_law, d.L, d.m, d.z_H, d.z) == ("generated", 4, sm.law, sm.L, 2.5, 80, 20)
    assert type(d.z) is int and type(d.z_H) is int
    assert d.pc == sm.pair and d.smoothing is sm and (d.driver, d.driven) == ("G1", "G2")
    assert d.ripple is sm.ripple and d.closure_error == sm.closure_error and d.shaper is None
    assert d.search is None and d.search_tries == ()


def test_generated_teeth_with_a_catalogue_shaper_take_its_teeth_and_name_its_key(monkeypatch):
    from propulsor.errors import InputError
    from propulsor.gears.catalogue import shaper_entry
    from propulsor.parts.noncircular_pair.design import design_generated
    from propulsor.parts.noncircular_pair.feasibility import screened

    p = _part("ncg_seed002", law_search=False, shaper_d0_mm=50.0, shaper_teeth=23)
    sh = screened(p).shaper
    assert sh is not None
    calls = _record_generate_pair(monkeypatch, [("G1", "G2"), InputError("z0", 20, "cannot cut")])
    d = design_generated(p)
    assert calls[0].drv.z0 == sh.z0 == 20 and calls[0].drv.shaper is sh and calls[0].dvn.shaper is sh
    assert d.shaper == shaper_entry(50.0, 2.5)
    with pytest.raises(InputError) as e:
        design_generated(p)
    assert str(e.value) == "shaper_d0_mm = 20: cannot cut"
    p2 = _part("ncg_seed002", law_search=False)
    _record_generate_pair(monkeypatch, [InputError("z0", 20, "cannot cut")])
    with pytest.raises(InputError) as e:
        design_generated(p2)
    assert str(e.value) == "shaper_teeth = 20: cannot cut"


# =========================================================================== generated, the law search
def _selected(points, tries=5, per=2):
    """The law search's candidates in the order the design tries them, by its rules written out: each (shaper d0,
    ripple to 4 decimals) once, at most ``per`` a shaper, at most ``tries`` in all."""
    out, seen, count = [], set(), {}
    for pt in points:
        key = (pt.d0_mm, round(pt.ripple, 4))
        if key in seen or count.get(pt.d0_mm, 0) >= per:
            continue
        seen.add(key)
        if len(out) >= tries:
            break
        count[pt.d0_mm] = count.get(pt.d0_mm, 0) + 1
        out.append(pt)
    return out


def _check_candidate(call, pt, p, law, entries):
    from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw
    from propulsor.gears.noncircular_teeth import ArcFrame
    from propulsor.parts.noncircular_pair.cutting import rack_of

    sl = SmoothedWalkingLaw(law, pt.delta, u_h=pt.u_h_rel * law.u)
    assert call.pc == PitchCurves(sl, pt.L)
    assert isinstance(call.frame, ArcFrame) and call.frame.pc == call.pc
    entry = [e for e in entries if e.d0_mm == pt.d0_mm][0]
    sh = entry.cutter(math.radians(20.0))
    th = 0.16 / (2 * math.cos(math.radians(20.0)))
    for spec, x in ((call.drv, 0.5), (call.dvn, -0.5)):
        assert (spec.m, spec.x, spec.z0, spec.rack) == (2.5, x, sh.z0, rack_of(p))
        assert spec.shaper == sh and spec.thinning_mm == pytest.approx(th, rel=1e-12)
        assert spec.tip_min_mm == pytest.approx(0.25 * 2.5) and spec.tip_max_mm == pytest.approx(
            p.tip_height_max_module * 2.5)
    return sl, sh


def test_law_search_cuts_the_ranked_candidates_until_both_wheels_can_be_cut(monkeypatch):
    """Seed 002 (law_search = true): the candidates tried in rank order; a generator's refusal (InputError named by
    the catalogue shaper's key, RuntimeError, ValueError) is kept as the reason after its first ': ', and the next
    candidate is cut; the first pair cut is the design, on that candidate's blend, centre distance and shaper."""
    from propulsor.errors import InputError
    from propulsor.gears.generability import CutterSpec, check_generable
    from propulsor.gears.noncircular import hub_speed_ripple
    from propulsor.parts.noncircular_pair.design import design_generated
    from propulsor.parts.noncircular_pair.feasibility import law_of, screened

    p = _part("ncg_seed002", tip_height_max_module=1.5)
    law = law_of(p)
    scr = screened(p)
    calls = _record_generate_pair(monkeypatch, [InputError("z0", 10, "cannot cut: the tip", "a hint"),
                                                RuntimeError("lost: the envelope"), ("G1", "G2")])
    said = []
    d = design_generated(p, said.append)
    pts = _selected(scr.search.points)
    assert len(calls) == 3
    assert said == ["law search: catalogue shapers, blend half-width and hand-over value"] + [
        f"law search: generating the teeth of candidate {k + 1} (ripple {100 * pt.ripple:.2f} %, shaper d0 "
        f"{pt.d0_mm:g})" for k, pt in enumerate(pts[:3])]
    assert said[1] == "law search: generating the teeth of candidate 1 (ripple 2.46 %, shaper d0 25)"
    for call, pt in zip(calls, pts):
        sl, sh = _check_candidate(call, pt, p, law, scr.entries)
        assert call.progress == said.append
    pt = pts[2]
    sl, sh = _check_candidate(calls[2], pt, p, law, scr.entries)
    assert (d.method, d.law, d.run_law, d.L, d.m, d.z_H, d.z) == ("generated", law, sl, pt.L, 2.5, 80, 20)
    assert type(d.z) is int and (d.driver, d.driven) == ("G1", "G2") and d.pc == calls[2].pc
    sm = d.smoothing
    cutter = CutterSpec(m=2.5, alpha=math.radians(20.0), x=0.5, x_H=-0.5, z0=sh.z0, shaper_x0=sh.x0)
    assert sm.cutter == cutter and sm.law == sl and sm.delta == sl.delta and sm.L == pt.L
    assert (sm.z_H, sm.z) == (80, 20) and type(sm.z) is int and sm.generability == check_generable(calls[2].pc, cutter)
    assert sm.ripple == hub_speed_ripple(sl) and d.ripple is sm.ripple and d.closure_error == sm.closure_error
    assert d.search is scr.search and d.shaper.d0_mm == pt.d0_mm
    assert d.search_tries == ((pts[0], "cannot cut: the tip (a hint)"), (pts[1], "the envelope"), (pts[2], ""))


def _synthetic_search(monkeypatch, p, points):
    """The screen's law search replaced by the given points (the catalogue entries kept)."""
    import importlib

    design_mod = importlib.import_module("propulsor.parts.noncircular_pair.design")
    from propulsor.parts.noncircular_pair.feasibility import screened

    scr = screened(p)
    fake = SimpleNamespace(m=scr.m, search=SimpleNamespace(points=points), entries=scr.entries)
    monkeypatch.setattr(design_mod, "screened", lambda q, source=None: fake)
    return fake


def test_law_search_refused_by_every_candidate_names_each_once_and_tries_at_most_five(monkeypatch):
    """Points made from seed 002's best: a repeat of one shaper's ripple to 4 decimals (0.02456 and 0.024604) is tried
    once, a shaper at
    most twice, five candidates in all; every refusal listed with its shaper and ripple."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.design import design_generated
    from propulsor.parts.noncircular_pair.feasibility import screened

    p = _part("ncg_seed002")
    best = screened(p).search.points[0]
    mk = lambda d0, r: dataclasses.replace(best, d0_mm=d0, ripple=r)
    points = [mk(25.0, 0.02456), mk(25.0, 0.024604), mk(38.0, 0.02456), mk(25.0, 0.0250), mk(25.0, 0.0251),
              mk(50.0, 0.0252), mk(38.0, 0.0253), mk(38.0, 0.0254), mk(75.0, 0.0255), mk(100.0, 0.0256)]
    _synthetic_search(monkeypatch, p, points)
    calls = _record_generate_pair(monkeypatch, [RuntimeError(f"no: {k}") for k in range(9)])
    with pytest.raises(InputError) as e:
        design_generated(p)
    tried = [points[0], points[2], points[3], points[5], points[6]]
    assert _selected(points) == tried and len(calls) == 5
    assert str(e.value) == (
        "driver_shift = 0.5: none of the 5 least-ripple generable blends can be cut: "
        "d0 25 ripple 2.46 %: 0; d0 38 ripple 2.46 %: 1; d0 25 ripple 2.50 %: 2; d0 50 ripple 2.52 %: 3; "
        "d0 38 ripple 2.53 %: 4 (another driver_shift, more teeth or a wider center_distance_band_mm)")
    # fewer points than five: all of them, the count said
    _synthetic_search(monkeypatch, p, points[:3])
    calls = _record_generate_pair(monkeypatch, [ValueError("bad: v"), InputError("m", 2.5, "too small")])
    with pytest.raises(InputError) as e:
        design_generated(p)
    assert str(e.value) == (
        "driver_shift = 0.5: none of the 2 least-ripple generable blends can be cut: "
        "d0 25 ripple 2.46 %: v; d0 38 ripple 2.46 %: too small (another driver_shift, more teeth or a wider "
        "center_distance_band_mm)")
    # the sixth point of a new shaper after five tries is not tried: the fifth refusal ends the search
    _synthetic_search(monkeypatch, p, points[:1] + [mk(38.0, 0.03), mk(50.0, 0.031), mk(75.0, 0.032),
                                                      mk(100.0, 0.033), mk(50.0, 0.034), mk(75.0, 0.035)])
    calls = _record_generate_pair(monkeypatch, [RuntimeError("x")] * 5 + [("G1", "G2")])
    with pytest.raises(InputError):
        design_generated(p)
    assert len(calls) == 5


def test_law_search_cuts_at_the_part_files_pressure_angle_and_rack(monkeypatch):
    """At 22 deg with profile B: the candidate's cutter and both tooth specs carry the file's angle and rack (not the
    defaults 20 deg and profile A)."""
    from propulsor.parts.noncircular_pair.cutting import rack_of
    from propulsor.parts.noncircular_pair.design import design_generated
    from propulsor.parts.noncircular_pair.feasibility import screened

    p = _part("ncg_seed002", pressure_angle_deg=22.0, rack_profile="B")
    scr = screened(p)
    _synthetic_search(monkeypatch, p, scr.search.points[:1])
    calls = _record_generate_pair(monkeypatch, [("G1", "G2")])
    d = design_generated(p)
    assert d.smoothing.cutter.alpha == pytest.approx(math.radians(22.0), rel=1e-15)
    entry = [e for e in scr.entries if e.d0_mm == scr.search.points[0].d0_mm][0]
    sh = entry.cutter(math.radians(22.0))
    for spec in (calls[0].drv, calls[0].dvn):
        assert spec.rack == rack_of(p) and spec.rack != rack_of(_part("ncg_seed002"))
        assert spec.shaper == sh and spec.thinning_mm == pytest.approx(0.16 / (2 * math.cos(math.radians(22.0))))


def _gears_and_no_bores(monkeypatch):
    """The tooth generator answering stub gears, and no bores: the pair's steps without its outlines."""
    import importlib

    from propulsor.parts.noncircular_pair import cutting
    from propulsor.parts.noncircular_pair.bores import Bore

    design_mod = importlib.import_module("propulsor.parts.noncircular_pair.design")
    monkeypatch.setattr(cutting, "generate_pair", lambda pc, a, b, frame, progress=None: (
        SimpleNamespace(profile="P1"), SimpleNamespace(profile="P2")))
    monkeypatch.setattr(design_mod, "bores", lambda p, d: (Bore(0.0, False, False), Bore(0.0, False, False)))


def test_a_table_laws_file_is_read_relative_to_the_part_file(monkeypatch):
    """ncg_table.toml's law_file (ncg_table_law.csv) beside the part file: the design, the feasibility and the
    part's design read it there; without the part file's path it is looked for in the working directory."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.design import design, design_generated, feasible, pair_design

    _gears_and_no_bores(monkeypatch)
    src = PARTS / "ncg_table.toml"
    p = _part("ncg_table")
    dd = pair_design(p, src)
    assert dd.d.method == "generated" and dd.profiles == ("P1", "P2") and dd.mount == dd.d.L
    assert design(p, source=src).z_H == 60 and design_generated(p, source=src).z == 30
    feasible(p, src)
    for call in (lambda q: pair_design(q), lambda q: design(q), lambda q: design_generated(q), lambda q: feasible(q)):
        with pytest.raises(InputError) as e:
            call(_part("ncg_table"))
        assert e.value.parameter == "law_file" and str(e.value).endswith(
            "ncg_table_law.csv': cannot be read: No such file or directory")
