"""The non-circular pair's as-built outputs and a print kit's hand load, number by number
(parts/noncircular_pair/as_built_outputs.py, kit_load.py): the as-built checks, values, table and note, the tooth
height check, the tolerance study's check, rows and values, and the hand on a kit's crank rated per printed material,
each input made in the test (contact laws of a few samples, AsBuilt, tolerance results, ratings and tooth loads of
given numbers), every expected value worked out here from the docstrings' formulas.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``noncircular_outputs``): no pair is
built, no CAD solid, no figure drawn (the plot is replaced by a recorder; it is not mutated).
"""

from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor.checks.motion.contact_events import DRIVE, REVERSE, KINDS, ContactLaw
from propulsor.parts.noncircular_pair.as_built import AsBuilt, HubSpeed
from stand_ins import SaidWriter

DEG = 180.0 / math.pi


def _cl(direction, te, kind=(0, 0, 0, 0, 0, 0), driver=(0, 0, 0, 0, 0, 0), driven=(0, 0, 0, 0, 0, 0), evaluations=7):
    """Six samples phi = 0, 0.25 .. 1.25 rad, the driver at theta = 2 phi."""
    phi = np.arange(6) * 0.25
    return ContactLaw(direction, phi, 2.0 * phi, np.asarray(te, float), np.asarray(kind), np.asarray(driver),
                      np.asarray(driven), evaluations)


def _drive():
    """Flank contact; te flat then rising 0.125 a step: speed 1, 1, 1.5, 1.5, 1.5; the tooth pair changes between
    samples 2 and 3 (driver 0 -> 1, driven 5 -> 4): one step of 0.5 at phi 0.625 (driver 1.25 rad)."""
    return _cl(DRIVE, [0, 0, 0, 0.125, 0.25, 0.375], driver=(0, 0, 0, 1, 1, 1), driven=(5, 5, 5, 4, 4, 4),
               evaluations=11)


def _reverse():
    """te = 0.5 + phi/256 (speed 1 + 1/256 everywhere); samples 2 and 3 on a driver tip and root corner: three
    changes of state, none with a chord on both sides (no step), corner share 0.4 (intervals half, whole, half of
    five equal ones), the corner run 0.5 + 0.5 half-intervals + 0.5 = 1 rad of driver from theta 1 rad."""
    phi = np.arange(6) * 0.25
    return _cl(REVERSE, 0.5 + phi / 256, kind=(0, 0, 1, 3, 0, 0), driver=(2,) * 6, driven=(7,) * 6, evaluations=13)


def _ab(hub=(), drive=None, reverse=None):
    return AsBuilt(drive or _drive(), reverse or _reverse(), math.pi / 2, hub, 0.03125, 0.25, 0.75)


def _hubs():
    return (HubSpeed(0.25, 0.875, 1.125, 0.5, 1.0), HubSpeed(0.375, 0.75, 1.125, 0.25, 1.25))


def _p(**kw):
    f = dict(as_built_ripple_margin=0.1875, speed_step_max=0.5, corner_run_max_deg=57.5, tooth_height_min_share=0.75,
             rack_profile="A", pressure_angle_deg=20.0, driver_shift=0.25, tolerance_grade=8, tolerance_seed=7)
    f.update(kw)
    return SimpleNamespace(**f)


# =========================================================================== as_built_checks
def test_as_built_checks_of_a_walking_pair_each_with_its_limit_and_message_in_full():
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_checks

    hub, step, corner, contact = checks = as_built_checks(_ab(_hubs()), _p(), 0.1875)
    assert [c.name for c in checks] == ["as_built.hub_speed_ripple", "as_built.speed_step", "as_built.corner_load",
                                        "as_built.contact"]
    # the larger ripple of the two directions against the law's + the margin: 0.375 <= 0.1875 + 0.1875
    assert (hub.passed, hub.value, hub.limit, hub.unit) == (True, 0.375, 0.375, "")
    assert hub.message == ("hub speed ripple as built 25.000 % (drive), 37.500 % (reverse) against the law's 18.750 % "
                           "+ 18.75 points")
    assert (step.passed, step.value, step.limit, step.unit) == (True, 0.5, 0.5, "")
    assert step.message == ("largest change of the driven speed across a change of contact: drive 50.000 % at driver "
                            f"{1.25 * DEG:.3f} deg; reverse 0.000 %")
    assert f"{1.25 * DEG:.3f}" == "71.620"
    assert (corner.passed, corner.value, corner.limit, corner.unit) == (True, pytest.approx(DEG), 57.5, "deg")
    assert corner.message == ("longest run of driver angle with the load on a tooth corner 57.296 deg (reverse at "
                              "driver 57.296 deg); share of the cycle on a corner 0.00 % (drive), 40.00 % (reverse)")
    assert (contact.passed, contact.value, contact.limit, contact.unit) == (True, 0, 0, "samples")
    assert contact.message == "0 samples without a contact within the largest free rotation"


def test_as_built_checks_fail_just_past_each_limit_and_count_every_lost_sample():
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_checks

    p = _p(as_built_ripple_margin=0.125, speed_step_max=0.4375, corner_run_max_deg=57.25)
    hub, step, corner, contact = as_built_checks(_ab(_hubs()), p, 0.1875)
    assert (hub.passed, hub.limit) == (False, 0.3125)
    assert hub.message.endswith("against the law's 18.750 % + 12.5 points")
    assert (step.passed, step.limit) == (False, 0.4375)
    assert (corner.passed, corner.limit) == (False, 57.25)
    # no hub (not the walking law): no ripple check; samples without contact in either direction are counted
    nan = math.nan
    drive = _cl(DRIVE, [0, nan, 0, 0, 0, 0])
    reverse = _cl(REVERSE, [0.5, 0.5, 0.5, 0.5, nan, nan])
    checks = as_built_checks(_ab((), drive, reverse), _p(), None)
    assert [c.name for c in checks] == ["as_built.speed_step", "as_built.corner_load", "as_built.contact"]
    step, corner, contact = checks
    assert (step.value, step.passed) == (0.0, True)
    assert step.message == ("largest change of the driven speed across a change of contact: drive 0.000 %; reverse "
                            "0.000 %")
    assert (corner.value, corner.passed) == (0.0, True)
    assert corner.message == ("longest run of driver angle with the load on a tooth corner 0.000 deg; share of the "
                              "cycle on a corner 0.00 % (drive), 0.00 % (reverse)")
    assert (contact.passed, contact.value, contact.limit) == (False, 3, 0)
    assert contact.message == "3 samples without a contact within the largest free rotation"
    one = as_built_checks(_ab((), _cl(DRIVE, [0, nan, 0, 0, 0, 0]), _cl(REVERSE, [0.5] * 6)), _p(), None)[-1]
    assert (one.passed, one.value) == (False, 1)


# =========================================================================== stretch_rows
def test_stretch_rows_list_each_directions_stretches_in_full():
    from propulsor.parts.noncircular_pair.as_built_outputs import _STRETCH_COLUMNS, stretch_rows

    assert _STRETCH_COLUMNS == ["direction", "driver_from_deg", "driver_to_deg", "driven_from_deg", "driven_to_deg",
                                "kinds", "driver_teeth", "driven_teeth", "speed_min_rel", "speed_max_rel"]
    rows = stretch_rows(_ab())
    # drive: intervals 2..4 at speed 1.5 (driver 1 .. 2.5 rad, driven 0.5 .. 1.25); reverse: intervals 1..3 touch a
    # corner (driver 0.5 .. 2 rad, driven 0.25 .. 1), its kinds sorted by name
    assert rows == [
        ["drive", pytest.approx(DEG), pytest.approx(2.5 * DEG), pytest.approx(0.5 * DEG), pytest.approx(1.25 * DEG),
         "flank", "0 1", "4 5", 1.5, 1.5],
        ["reverse", pytest.approx(0.5 * DEG), pytest.approx(2 * DEG), pytest.approx(0.25 * DEG), pytest.approx(DEG),
         f"{KINDS[3]}; {KINDS[1]}; {KINDS[0]}", "2", "7", 1 + 1 / 256, 1 + 1 / 256]]
    assert KINDS[3] == "driver root corner" and KINDS[1] == "driver tip corner"


# =========================================================================== tooth_height_check
def _tooth(h, shortened=False):
    return SimpleNamespace(tip_height_mm=h, shortened=shortened)


def _teeth_design(method="generated"):
    """m = 2, x = 0.25: the driver's addendum (1 + 0.25) 2 = 2.5 mm, the driven wheel's (1 - 0.25) 2 = 1.5 mm
    (ISO 53 profile A: h_a* = 1)."""
    drv = SimpleNamespace(role="driver", teeth=[_tooth(2.5), _tooth(2.0, True), _tooth(1.875)])
    dvn = SimpleNamespace(role="driven", teeth=[_tooth(1.5, True), _tooth(1.125, True), _tooth(1.25)])
    return SimpleNamespace(method=method, m=2.0, driver=drv, driven=dvn)


def test_tooth_height_is_the_least_share_of_each_wheels_shifted_addendum_with_the_low_teeth_named():
    from propulsor.gears.catalogue import rack_profile
    from propulsor.parts.noncircular_pair.as_built_outputs import tooth_height_check

    assert rack_profile("A", math.radians(20.0)).h_a_star == 1.0
    d = _teeth_design()
    # shares: driver 1, 0.8, 0.75; driven 1, 0.75, 0.8333: the least 0.75 first at driver tooth 2 (a tie after)
    ok = tooth_height_check(d, _p(tooth_height_min_share=0.75))
    assert (ok.name, ok.passed, ok.value, ok.limit, ok.unit) == ("teeth.tooth_height", True, 0.75, 0.75, "")
    assert ok.message == "least share of the addendum 0.750 (driver tooth 2); 3 tips shortened where pointed"
    low = tooth_height_check(d, _p(tooth_height_min_share=0.8))
    assert (low.passed, low.value, low.limit) == (False, 0.75, 0.8)
    assert low.message == ("least share of the addendum 0.750 (driver tooth 2); 3 tips shortened where pointed; "
                           "below 0.8: driver 2 (0.750), driven 1 (0.750)")
    # unshifted: both addenda 2 mm, shares 1.25, 1, 0.9375 / 0.75, 0.5625, 0.625
    flat = tooth_height_check(d, _p(tooth_height_min_share=0.6, driver_shift=0.0))
    assert flat.value == 0.5625
    assert flat.message.endswith("(driven tooth 1); 3 tips shortened where pointed; below 0.6: driven 1 (0.562)")
    assert tooth_height_check(_teeth_design("sectors"), _p()) is None


def test_tooth_height_of_the_elliptical_part_files_pair_is_the_whole_addendum_on_every_tooth():
    """The real teeth (the stand-ins above have their attributes): the elliptical file's unshifted pair (m = 2.5 mm,
    profile A) keeps h_a = m on all 30 + 30 teeth, none shortened; about 1 s."""
    from pathlib import Path

    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design
    from propulsor.parts.noncircular_pair.as_built_outputs import tooth_height_check

    _, mapping = read_part_file(Path(__file__).resolve().parent.parent / "parts" / "ncg_elliptical.toml")
    p = load_params(NoncircularPairParams, mapping)
    d = design(p)
    assert (d.method, d.m, p.driver_shift, p.rack_profile) == ("generated", 2.5, 0.0, "A")
    for gear in (d.driver, d.driven):
        assert len(gear.teeth) == 30
        assert [t.tip_height_mm for t in gear.teeth] == pytest.approx([2.5] * 30, abs=1e-9)
        assert not any(t.shortened for t in gear.teeth)
    c = tooth_height_check(d, p)
    assert (c.passed, c.value, c.limit) == (True, pytest.approx(1.0, abs=1e-9), p.tooth_height_min_share)
    assert c.message == "least share of the addendum 1.000 (driver tooth 0); 0 tips shortened where pointed"


# =========================================================================== _collected
def test_collected_results_come_in_the_jobs_order_counted_as_they_come(monkeypatch):
    import propulsor.parallel as parallel
    import propulsor.progress as progress
    from propulsor.parallel import Done
    from propulsor.parts.noncircular_pair.as_built_outputs import _collected

    assert _collected([Done(3), Done(4)], None, "x", "y") == [3, 4]
    monkeypatch.setattr(progress, "COUNT_EVERY_S", 0.0)
    events = []
    rep = progress.Reporter(events.append)
    jobs = [SimpleNamespace(result=lambda: "a"), Done("b"), SimpleNamespace(result=lambda: "c")]
    assert _collected(jobs, rep, "phase A", "case") == ["a", "b", "c"]
    assert [str(e) for e in events] == ["phase A: case 0/3", "phase A: case 1/3", "phase A: case 2/3",
                                           "phase A: case 3/3"]
    # jobs that count themselves are waited for by parallel.result, nothing counted here
    seen = []
    monkeypatch.setattr(parallel, "result", lambda j: seen.append(j) or j.v * 2)
    ticking = [SimpleNamespace(v=1, result=None), SimpleNamespace(v=5, propulsor_ticks=1, result=None)]
    events.clear()
    assert _collected(ticking, rep, "phase A", "case") == [2, 10]
    assert seen == ticking and events == []


# =========================================================================== as_built_values
def _dd(walking=True, method="sectors"):
    d = SimpleNamespace(method=method, law=SimpleNamespace(kind="walking" if walking else "elliptical"),
                        ripple=SimpleNamespace(ripple=0.1875))
    if method == "generated":
        d = SimpleNamespace(**{**vars(_teeth_design()), **vars(d)})
    return SimpleNamespace(d=d, p=_p(), mount=80.0)


def _proof():
    return SimpleNamespace(summary=lambda: {"steps": 40, "backlash_min_mm": 0.0625})


def _recorders(monkeypatch, ab):
    """combine, the plot, the load per tooth and the tolerance values replaced by recorders."""
    import propulsor.parts.noncircular_pair.as_built_outputs as abo
    import propulsor.parts.noncircular_pair.tooth_load_outputs as tlo

    calls = SimpleNamespace(combine=[], plot=[], tooth_load=[], tolerance=[], as_built=[])
    monkeypatch.setattr(abo, "combine", lambda d, *c: calls.combine.append((d, c)) or ab)
    monkeypatch.setattr(abo, "as_built", lambda d, mount, pr: calls.as_built.append((d, mount, pr)) or ab)
    monkeypatch.setattr(abo, "_plot", lambda w, d, a: calls.plot.append((w, d, a)))
    monkeypatch.setattr(tlo, "tooth_load_values", lambda w, dd, built, a: calls.tooth_load.append((w, dd, built, a)))
    return calls


def test_as_built_values_of_a_walking_pair_every_value_the_table_and_the_note(monkeypatch):
    from propulsor import policy
    from propulsor.parallel import Done
    from propulsor.parts.noncircular_pair.as_built_outputs import _STRETCH_COLUMNS, as_built_values, stretch_rows

    ab = _ab(_hubs())
    calls = _recorders(monkeypatch, ab)
    dd, w = _dd(), SaidWriter()
    drive, reverse = Done("the drive contact"), Done("the reverse contact")
    built = {"as_built": (drive, reverse), "proof": _proof()}
    assert as_built_values(w, dd, built) is None
    assert calls.combine == [(dd.d, ("the drive contact", "the reverse contact"))] and calls.as_built == []
    assert w.said == ["as built: speeds, transmission error, backlash and stretches from the contact positions",
                      "as built: the plot of the driven speed and the transmission error"]
    assert [c.name for c in w.checks] == ["as_built.hub_speed_ripple", "as_built.speed_step", "as_built.corner_load",
                                          "as_built.contact"]
    assert w.checks[0].limit == 0.375  # the law's ripple of the design + the margin
    assert w.derived == {
        "te_min_rad": 0.0, "te_max_rad": 0.375, "te_pp_rad": 0.375, "te_pp_reverse_rad": 1.25 / 256,
        "backlash_min_mm": 0.03125, "backlash_max_mm": 0.25, "backlash_min_phi_deg": pytest.approx(0.75 * DEG),
        "speed_as_built_min": 1.0, "speed_as_built_max": 1.5,
        "speed_as_built_reverse_min": 1 + 1 / 256, "speed_as_built_reverse_max": 1 + 1 / 256,
        "speed_step_max": 0.5, "speed_step_reverse_max": 0.0,
        "corner_contact_share": 0.0, "corner_contact_reverse_share": pytest.approx(0.4),
        "corner_run_max_deg": pytest.approx(DEG), "as_built_span_deg": pytest.approx(90.0),
        "as_built_evaluations": 24, "as_built_stretches": 2,
        "speed_ripple_as_built": 0.375, "speed_ripple_as_built_drive": 0.25, "speed_ripple_as_built_reverse": 0.375,
        "speed_as_built_min_rel": 0.875, "speed_as_built_max_rel": 1.125,
        "speed_as_built_phi_min_deg": pytest.approx(0.5 * DEG), "speed_as_built_phi_max_deg": pytest.approx(DEG)}
    assert type(w.derived["te_min_rad"]) is type(w.derived["te_max_rad"]) is float  # plain numbers, not numpy's
    assert w.tables == {"as_built_stretches": (_STRETCH_COLUMNS, stretch_rows(ab))}
    assert len(w.tables["as_built_stretches"][1]) == 2
    assert calls.plot == [(w, dd.d, ab)]
    assert calls.tooth_load == [(w, dd, built, ab)]
    assert w.notes == [
        f"As built: both directions' loaded contact on the finished outlines at the installed centre distance, "
        f"sampled every {policy.CONTACT_STEP_DRIVER_DEG:g} deg of driver over one period (90.0 deg of the driven "
        f"wheel) and every change of the tooth pair or contact kind (flank, driver tip corner, driven tip corner, "
        f"driver root corner, driven root corner) located to {policy.CONTACT_EVENT_STEP_RAD:g} rad (24 contact "
        f"positions): hub speed ripple as built 25.00 % (drive) and 37.50 % (reverse) against the law's 18.75 %; "
        f"driven speed over the law's 1.0000 .. 1.5000 (drive), 1.0039 .. 1.0039 (reverse); largest step at a change "
        f"of contact 50.00 %; transmission error peak-to-peak 3.750e-01 rad (drive), 4.883e-03 rad (reverse); least "
        f"backlash 0.03125 mm (backlash_min_mm, over every contact position; the motion proof's 40 phases alone give "
        f"0.06250 mm); load on a corner 0.00 % / 40.00 % of the cycle.  tables/as_built_stretches.csv lists every "
        f"stretch whose speed is off the law's by more than {100 * policy.CONTACT_STRETCH_SPEED_TOL:g} % or whose "
        f"contact is on a corner."]
    assert (policy.CONTACT_STEP_DRIVER_DEG, policy.CONTACT_EVENT_STEP_RAD, policy.CONTACT_STRETCH_SPEED_TOL) == (
        0.05, 1e-5, 0.01)


def test_as_built_values_without_a_hub_and_with_the_directions_resolved_here(monkeypatch):
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_values

    ab = _ab(drive=_cl(DRIVE, [0.0] * 6, kind=(0, 1, 0, 0, 0, 0)))  # on a corner 0.5 of 2.5 rad of driver: 20 %
    calls = _recorders(monkeypatch, ab)
    dd, w = _dd(walking=False, method="generated"), SaidWriter()
    proof = _proof()
    as_built_values(w, dd, {"proof": proof})
    assert calls.as_built == [(dd.d, 80.0, proof)] and calls.combine == []
    assert [c.name for c in w.checks] == ["teeth.tooth_height", "as_built.speed_step", "as_built.corner_load",
                                          "as_built.contact"]
    assert not any(k.startswith("speed_ripple") or k.startswith("speed_as_built_phi") for k in w.derived)
    assert len(w.derived) == 19
    assert "hub speed" not in w.notes[0]
    assert ("positions): driven speed over the law's 1.0000 .. 1.0000 (drive)" in w.notes[0])
    assert "load on a corner 20.00 % / 40.00 % of the cycle." in w.notes[0]
    assert w.checks[2].message.endswith("share of the cycle on a corner 20.00 % (drive), 40.00 % (reverse)")


def test_as_built_values_after_a_jam_say_so_and_go_on_to_the_load_and_tolerances(monkeypatch):
    import propulsor.parts.noncircular_pair.as_built_outputs as abo

    calls, tolerance = _recorders(monkeypatch, None), []
    monkeypatch.setattr(abo, "tolerance_values", lambda w, dd, built: tolerance.append((w, dd, built)) or "t")
    dd, w = _dd(walking=False, method="generated"), SaidWriter()
    built = {"as_built": (), "proof": _proof()}
    assert abo.as_built_values(w, dd, built) == "t"
    assert calls.combine == calls.as_built == calls.plot == []
    assert w.notes == ["As built: not measured - the proof found phases without a running position (jam)."]
    assert [c.name for c in w.checks] == ["teeth.tooth_height"] and w.derived == {} and w.tables == {}
    assert calls.tooth_load == [(w, dd, built, None)] and tolerance == [(w, dd, built)]
    assert w.said == ["as built: speeds, transmission error, backlash and stretches from the contact positions"]
    # and after the as-built values too
    calls = _recorders(monkeypatch, _ab())
    w = SaidWriter()
    built = {"proof": _proof()}
    assert abo.as_built_values(w, dd, built) is None
    assert len(calls.tooth_load) == 1 and calls.tooth_load[0][:3] == (w, dd, built)
    assert isinstance(calls.tooth_load[0][3], AsBuilt)
    assert len(tolerance) == 2 and tolerance[1] == (w, dd, built)


# =========================================================================== tolerance
def _case(name, dL=0.0, e1=0.0, psi1=0.0, e2=0.0, psi2=0.0, t1=0.0, t2=0.0):
    return SimpleNamespace(name=name, dL=dL, e_driver=e1, psi_driver=psi1, e_driven=e2, psi_driven=psi2, t_driver=t1,
                           t_driven=t2)


def _tr(name, backlash, *, jam=False, lost=0, step=0.0, te=(1e-3, 2e-3), phi=0.5, theta=0.25, **case):
    return SimpleNamespace(case=_case(name, **case), jam=jam, lost=lost, step_max=step, step_theta=theta,
                           backlash_min_mm=backlash, backlash_min_phi=phi, te_pp_drive=te[0], te_pp_reverse=te[1])


def _tol():
    return SimpleNamespace(source="ISO 1328-1 grade 8 (test)", f_a=0.0315, e_driver=0.0125, e_driven=0.02, t_hi=0.0625)


def test_tolerance_check_passes_at_the_step_limit_and_names_every_jam_and_loss_in_full():
    from propulsor.parts.noncircular_pair.as_built_outputs import tolerance_check

    fine = [_tr("tight", 0.0125, step=0.25), _tr("tight opposed", 0.015), _tr("loose", 0.25), _tr("loose opp", 0.3)]
    ok = tolerance_check(_tol(), fine, 0.25)
    assert (ok.name, ok.passed, ok.value, ok.limit, ok.unit) == ("tolerance.worst_case", True, 0.0125, 0.0, "mm")
    assert ok.message == ("least backlash 0.0125 mm over the worst-case corners of ISO 1328-1 grade 8 (test); largest "
                          "speed step 25.00 %")
    bad = [_tr("tight", -0.0125, jam=True, step=0.5, phi=math.radians(30.0)),
           _tr("tight opposed", 0.015, step=0.3125, theta=math.radians(12.5)),
           _tr("loose", 0.25, lost=3, theta=math.radians(40.0)),
           _tr("loose opp", 0.3, step=0.25)]
    chk = tolerance_check(_tol(), bad, 0.25)
    assert (chk.passed, chk.value, chk.limit) == (False, -0.0125, 0.0)
    assert chk.message == ("least backlash -0.0125 mm over the worst-case corners of ISO 1328-1 grade 8 (test); "
                           "largest speed step 50.00 %; tight: jam (backlash -0.0125 mm at driven 30.00 deg); tight "
                           "opposed: contact lost (0 samples without contact; speed step 31.25 % at driver 12.50 "
                           "deg); loose: contact lost (3 samples without contact; speed step 0.00 % at driver 40.00 "
                           "deg)")
    one = tolerance_check(_tol(), [_tr("a", 0.5, step=0.0)] * 3 + [_tr("b", 0.0, lost=1)], 0.25)
    assert not one.passed and one.value == 0.0 and one.message.endswith("; b: contact lost (1 samples without "
                                                                         "contact; speed step 0.00 % at driver "
                                                                         "14.32 deg)")


def test_tolerance_rows_in_micrometres_and_degrees_in_full():
    from propulsor.parts.noncircular_pair.as_built_outputs import _TOL_COLUMNS, tolerance_rows

    assert _TOL_COLUMNS == ["case", "dL_um", "e_driver_um", "psi_driver_deg", "e_driven_um", "psi_driven_deg",
                            "t_driver_um", "t_driven_um", "te_pp_drive_rad", "te_pp_reverse_rad", "backlash_min_mm",
                            "backlash_min_phi_deg", "step_max", "step_driver_deg", "lost_samples"]
    r = _tr("mc 3", 0.0375, lost=2, step=0.125, te=(3e-4, 5e-4), phi=math.pi / 4, theta=math.pi / 6, dL=-0.0315,
            e1=0.0125, psi1=math.pi / 2, e2=0.02, psi2=math.pi, t1=0.0625, t2=0.03125)
    assert tolerance_rows([r]) == [["mc 3", pytest.approx(-31.5), pytest.approx(12.5), pytest.approx(90.0),
                                    pytest.approx(20.0), pytest.approx(180.0), pytest.approx(62.5),
                                    pytest.approx(31.25), 3e-4, 5e-4, 0.0375, pytest.approx(45.0), 0.125,
                                    pytest.approx(30.0), 2]]


def _tol_results():
    """Four corners (least backlash 0.0125 mm, largest TE 0.004 rad at 'tight opp' reverse, step 0.25) and five
    draws (backlash 0.1, 0.05, 0.2, 0.15, 0.3; TE as their larger direction 0.001, 0.005, 0.002, 0.003, 0.0025; the
    first's speed step 0.3125, larger than the corners': the worst-case values are the corners' alone)."""
    worst = [_tr("tight", 0.0125, te=(3e-3, 1e-3), step=0.125), _tr("tight opp", 0.025, te=(1e-3, 4e-3), step=0.25),
             _tr("loose", 0.5, te=(2e-3, 2e-3)), _tr("loose opp", 0.625, te=(1e-3, 1e-3), step=0.0625)]
    mc = [_tr("mc 0", 0.1, te=(1e-3, 5e-4), step=0.3125), _tr("mc 1", 0.05, te=(5e-3, 1e-3)),
          _tr("mc 2", 0.2, te=(1e-3, 2e-3)),
          _tr("mc 3", 0.15, te=(3e-3, 1e-3)), _tr("mc 4", 0.3, te=(2.5e-3, 2e-3))]
    return worst, mc


def test_tolerance_values_the_cases_table_values_percentiles_and_note(monkeypatch):
    import propulsor.parallel as parallel
    from propulsor.parallel import Done
    from propulsor.parts.noncircular_pair.as_built_outputs import _TOL_COLUMNS, tolerance_rows, tolerance_values

    worst, mc = _tol_results()
    dd, w = _dd(), SaidWriter()
    tol = _tol()
    tolerance_values(w, dd, {"tolerance": (tol, [Done(r) for r in worst + mc])})
    assert [c.name for c in w.checks] == ["tolerance.worst_case"]
    assert w.checks[0].passed and w.checks[0].value == 0.0125
    assert w.checks[0].message.endswith("largest speed step 25.00 %")  # the corners' (limit: speed_step_max 0.5)
    assert w.tables == {"tolerance_cases": (_TOL_COLUMNS, tolerance_rows(worst + mc))}
    # percentiles with linear interpolation between the sorted draws (numpy's default): of 5, the p-th at 4 p/100
    bl = sorted([0.1, 0.05, 0.2, 0.15, 0.3])
    te = sorted([1e-3, 5e-3, 2e-3, 3e-3, 2.5e-3])
    assert w.derived == {
        "tolerance_grade": 8, "tolerance_f_a_mm": 0.0315, "tolerance_runout_driver_mm": 0.025,
        "tolerance_runout_driven_mm": 0.04, "tolerance_thinning_max_mm": 0.0625, "tolerance_backlash_min_mm": 0.0125,
        "tolerance_te_pp_max_rad": 4e-3, "tolerance_step_max": 0.25, "tolerance_samples": 5,
        "tolerance_backlash_min_p5_mm": pytest.approx(bl[0] + 0.2 * (bl[1] - bl[0])),
        "tolerance_backlash_min_p50_mm": pytest.approx(bl[2]),
        "tolerance_te_pp_p50_rad": pytest.approx(te[2]),
        "tolerance_te_pp_p95_rad": pytest.approx(te[3] + 0.8 * (te[4] - te[3]))}
    assert {type(v) for v in w.derived.values()} == {float, int}
    assert w.notes == [
        "As made (ISO 1328-1 grade 8 (test)): the as-built transmission of the pair within these tolerances, both "
        "directions over the whole driven turn, at the 4 worst-case corners (tight: L - f_a with the thickest teeth; "
        "loose: L + f_a with the thinnest; each with the wheels' run-outs in phase and opposed) and 5 Monte Carlo "
        "cases (seed 7): least backlash 0.0125 mm at the worst case, transmission error peak-to-peak up to 4.000e-03 "
        "rad, largest speed step 25.00 %; Monte Carlo least backlash 5 % / 50 %: 0.0600 / 0.1500 mm, TE "
        "peak-to-peak 50 % / 95 %: 2.500e-03 / 4.600e-03 rad.  tables/tolerance_cases.csv lists every case."]
    assert w.said == []
    # the corners alone: no percentiles; jobs that count themselves waited for by parallel.result
    monkeypatch.setattr(parallel, "result", lambda j: j.r)
    w = SaidWriter()
    tolerance_values(w, dd, {"tolerance": (tol, [SimpleNamespace(r=r, propulsor_ticks=1) for r in worst])})
    assert w.derived["tolerance_samples"] == 0 and not any("_p5" in k or "_p50" in k for k in w.derived)
    assert len(w.derived) == 9
    assert w.notes[0].endswith("and 0 Monte Carlo cases (seed 7): least backlash 0.0125 mm at the worst case, "
                               "transmission error peak-to-peak up to 4.000e-03 rad, largest speed step 25.00 %.  "
                               "tables/tolerance_cases.csv lists every case.")
    # the step limit is the part file's speed_step_max
    dd.p.speed_step_max = 0.1875
    w = SaidWriter()
    tolerance_values(w, dd, {"tolerance": (tol, [Done(r) for r in worst])})
    assert not w.checks[0].passed
    # no study: nothing
    for built in ({}, {"tolerance": None}, {"tolerance": ()}):
        w = SaidWriter()
        assert tolerance_values(w, dd, built) is None
        assert (w.checks, w.tables, w.derived, w.notes) == ([], {}, {}, [])


# =========================================================================== kit_load
def _mat(name):
    from propulsor.gears.gear_materials import materials

    return materials()[name]


def _tl(lost=0, imbalance=0.0, sections=None, phases=4):
    return SimpleNamespace(lost=lost, imbalance=imbalance, theta=np.zeros(phases),
                           sections=sections or {"driver": {}, "driven": {}})


def _rating(name, S_F, S_H, *, unrated=(), analyses=None, sF=20.0, sH=50.0, S_Fmin=2.0, S_Hmin=1.25, force=50.0):
    from propulsor.parts.noncircular_pair.kit_load import Rating

    return Rating(name, _mat(name), S_F, S_H, sF, sH, f"driven tooth 3, drive ({name})",
                  f"driver tooth 1, reverse ({name})", S_Fmin, S_Hmin, force,
                  analyses if analyses is not None else ((1, _tl()), (-1, _tl())), unrated)


def _hl(*ratings, contacts=()):
    from propulsor.parts.noncircular_pair.kit_load import HandLoad

    return HandLoad(50.0, 40.0, 2.0, 1.25, 8.0, 2.0, 1.25, tuple(ratings), "driver torque T1 = 2 N·m (test)",
                    contacts)


def _three():
    """PLA passes (S_F 2.5 >= 2, S_H 1.5 >= 1.25), PETG fails at the root, nylon at the flank."""
    return (_rating("PLA", 2.5, 1.5, unrated=("driven 10", "driven 8"), sF=20.0, sH=55.5),
            _rating("PETG", 1.5, 1.5, sF=28.0, sH=46.5), _rating("nylon", 2.5, 1.0, unrated=("driven 9",), sF=14.0,
                                                                 sH=58.0))


def test_hand_torque_is_force_times_handle_radius_in_metres():
    from propulsor.parts.noncircular_pair.kit_load import hand_torque_Nm

    assert hand_torque_Nm(50, 40) == 2.0
    assert hand_torque_Nm(48.0, 62.5) == 3.0
    assert isinstance(hand_torque_Nm(3, 500), float) and hand_torque_Nm(3, 500) == 1.5


def test_the_printed_materials_are_the_catalogues_static_ones_in_its_order():
    from propulsor.parts.noncircular_pair.kit_load import printed_materials

    assert printed_materials() == ["PLA", "PETG", "nylon"]


def test_tooth_names_sort_by_number_and_names_join_with_and():
    from propulsor.parts.noncircular_pair.kit_load import _join, _tooth_key

    assert _tooth_key("driven 10") == ("driven", 10)
    assert sorted(["driven 10", "driver 2", "driven 8", "driven 9"], key=_tooth_key) == [
        "driven 8", "driven 9", "driven 10", "driver 2"]
    assert _join(["PLA"]) == "PLA"
    assert _join(iter(["PLA", "PETG"])) == "PLA and PETG"
    assert _join(["PLA", "PETG", "nylon"]) == "PLA, PETG and nylon"


def test_a_rating_survives_on_both_required_safeties_and_its_force_scales_root_and_square_of_flank():
    pla, petg, nylon = _three()
    # F_allow = F min(S_F/S_Fmin, (S_H/S_Hmin)^2); margin = min(S_F/S_Fmin, S_H/S_Hmin)
    assert (pla.survives, pla.force_allow_N, pla.margin) == (True, 62.5, 1.2)
    assert (petg.survives, petg.force_allow_N, petg.margin) == (False, 37.5, 0.75)
    assert (nylon.survives, nylon.force_allow_N, nylon.margin) == (False, pytest.approx(32.0), 0.8)
    assert _rating("PLA", 2.0, 1.25).survives is True  # both exactly at their limits
    assert _rating("PLA", 2.0, 1.2499).survives is False
    assert _rating("PLA", 1.9999, 1.25).survives is False
    assert _rating("PLA", 4.0, 1.25, force=40.0).force_allow_N == 40.0  # the flank's square decides
    assert _rating("PLA", 4.0, 2.5).margin == 2.0
    assert pla.safeties() == "PLA S_F 2.50, S_H 1.50"


def test_the_verdict_names_who_survives_and_who_not_with_the_safeties_and_the_unrated_roots():
    pla, petg, nylon = _three()
    hl = _hl(pla, petg, nylon)
    assert hl.survivors == ["PLA"] and hl.best is pla
    unrated = (" The roots of 3 teeth (driven 8, driven 9, driven 10) are not rated: ISO 6336-3's 30° section is not "
               "found on their outline.")
    assert hl.sentence() == ("PLA survives it (PLA S_F 2.50, S_H 1.50); PETG and nylon do not (PETG S_F 1.50, S_H "
                             "1.50; nylon S_F 2.50, S_H 1.00) against the required S_F 2, S_H 1.25." + unrated)
    pla2 = _rating("PETG", 2.25, 1.25)
    assert _hl(pla, pla2, nylon).sentence() == (
        "PLA and PETG survive it (PLA S_F 2.50, S_H 1.50; PETG S_F 2.25, S_H 1.25); nylon does not (nylon S_F 2.50, "
        "S_H 1.00) against the required S_F 2, S_H 1.25." + unrated)
    assert _hl(pla, pla2).sentence() == ("PLA and PETG all survive it (PLA S_F 2.50, S_H 1.50; PETG S_F 2.25, S_H "
                                         "1.25 against the required S_F 2, S_H 1.25). The roots of 2 teeth (driven "
                                         "8, driven 10) are not rated: ISO 6336-3's 30° section is not found on "
                                         "their outline.")
    assert _hl(pla2).sentence() == "PETG survives it (PETG S_F 2.25, S_H 1.25 against the required S_F 2, S_H 1.25)."
    # none: the best (largest margin: nylon 0.8 over PETG 0.75) and the force it takes, 50 (1/1.25)^2 = 32 N
    assert _hl(petg, nylon).best is nylon
    assert _hl(petg, nylon).sentence() == (
        "No printed material survives it (PETG S_F 1.50, S_H 1.50; nylon S_F 2.50, S_H 1.00 against the required S_F "
        "2, S_H 1.25): print it in nylon or turn gently: in nylon the teeth take about 32 N on the handle (1.280 "
        "N·m). The roots of 1 teeth (driven 9) are not rated: ISO 6336-3's 30° section is not found on their "
        "outline.")
    assert _hl(nylon).sentence().startswith("No printed material survives it (nylon S_F 2.50, S_H 1.00 against")
    assert _hl(petg).sentence().endswith("in PETG the teeth take about 38 N on the handle (1.500 N·m).")
    assert _hl(petg)._unrated() == ""


def test_the_guides_words_table_and_caveat_in_full():
    pla, petg, nylon = _three()
    hl = _hl(pla, petg, nylon)
    lead = ("A firm hand on the crank, 50 N on the handle at 40.0 mm from the driver's axis, puts T1 = 2.000 N·m on "
            "the driver; with the driven wheel held, the printed teeth (module 1.25 mm, face width 8 mm) carry it in "
            "either direction.")
    assert hl.lead() == lead
    caveat = ("The printed strengths are static limits of flat-printed bars (layers in the gear's plane, as the plates "
              "lay the gears: the tooth root bends along the layers), not fatigue ratings, and uncertain (PLA (+-30 %; "
              "the lower end of the published XY range is used), PETG (+-30 %), nylon (+-40 %: moisture halves the "
              "stiffness of PA6)); a data sheet of your own filament beats them. The safeties hold for the teeth only "
              "(not the handle, pins or bores).")
    assert hl.caveat() == caveat
    assert hl.guide_lines() == [lead + " " + hl.sentence(), caveat]
    head, rows = hl.guide_table()
    assert head == ["material", "S_F (root)", "S_H (flank)", "least at", "takes about", "survives?"]
    assert rows == [
        ["PLA", "2.50 (≥ 2)", "1.50 (≥ 1.25)",
         "root: driven tooth 3, drive (PLA); flank: driver tooth 1, reverse (PLA)",
         "62 N on the handle", "yes"],
        ["PETG", "1.50 (≥ 2)", "1.50 (≥ 1.25)",
         "root: driven tooth 3, drive (PETG); flank: driver tooth 1, reverse (PETG)", "38 N on the handle", "no"],
        ["nylon", "2.50 (≥ 2)", "1.00 (≥ 1.25)",
         "root: driven tooth 3, drive (nylon); flank: driver tooth 1, reverse (nylon)", "32 N on the handle", "no"]]
    from propulsor.parts.noncircular_pair.kit_load import TABLE_COLUMNS

    assert TABLE_COLUMNS == ["material", "S_F_min", "S_F_required", "root_worst", "sigma_F_max_MPa", "sigma_FE_MPa",
                             "S_H_min", "S_H_required", "flank_worst", "sigma_H_max_MPa", "sigma_Hlim_MPa",
                             "force_allow_N", "torque_allow_Nm", "survives", "uncertainty"]
    assert hl.table_rows() == [
        ["PLA", 2.5, 2.0, "driven tooth 3, drive (PLA)", 20.0, 50.0, 1.5, 1.25, "driver tooth 1, reverse (PLA)", 55.5,
         83.0, 62.5, 2.5, "yes", "+-30 %; the lower end of the published XY range is used"],
        ["PETG", 1.5, 2.0, "driven tooth 3, drive (PETG)", 28.0, 42.0, 1.5, 1.25, "driver tooth 1, reverse (PETG)",
         46.5, 70.0, 37.5, 1.5, "no", "+-30 %"],
        ["nylon", 2.5, 2.0, "driven tooth 3, drive (nylon)", 14.0, 35.0, 1.0, 1.25, "driver tooth 1, reverse (nylon)",
         58.0, 58.0, pytest.approx(32.0), pytest.approx(1.28), "no", "+-40 %: moisture halves the stiffness of PA6"]]


def test_the_derived_values_every_material_and_the_unrated_teeth_sorted():
    pla, petg, nylon = _three()
    v = _hl(pla, petg, nylon).derived()
    want = {"hand_load_force_N": 50.0, "hand_load_crank_radius_mm": 40.0, "hand_load_T1_Nm": 2.0,
            "hand_load_S_Fmin": 2.0, "hand_load_S_Hmin": 1.25, "hand_load_survivors": ["PLA"],
            "hand_load_root_unrated_teeth": ["driven 8", "driven 9", "driven 10"]}
    for r, sf, sh, sF, sH, force, ok in ((pla, 2.5, 1.5, 20.0, 55.5, 62.5, True),
                                         (petg, 1.5, 1.5, 28.0, 46.5, 37.5, False),
                                         (nylon, 2.5, 1.0, 14.0, 58.0, pytest.approx(32.0), False)):
        n = r.name
        want.update({f"hand_load_{n}_S_F_min": sf, f"hand_load_{n}_S_H_min": sh,
                     f"hand_load_{n}_sigma_F_max_MPa": sF, f"hand_load_{n}_sigma_H_max_MPa": sH,
                     f"hand_load_{n}_root_worst": f"driven tooth 3, drive ({n})",
                     f"hand_load_{n}_flank_worst": f"driver tooth 1, reverse ({n})",
                     f"hand_load_{n}_force_allow_N": force, f"hand_load_{n}_survives": ok})
    assert v == want


def test_the_kits_check_is_the_analyses_equilibrium_and_the_unrated_roots_do_not_fail_it():
    from propulsor.gears.tooth_load import RootSection

    pla, petg, nylon = _three()
    ok = _hl(pla, petg, nylon).checks()
    assert len(ok) == 1
    (c,) = ok
    assert (c.name, c.passed, c.value, c.limit, c.unit) == ("hand_load.equilibrium", True, 0.0, 1e-9, "")
    # the worst of six: all equal, the first (PLA, drive) speaks
    assert c.message == ("the hand on the crank (2.0000 N·m), 6 analyses (printed materials × both directions): PLA, "
                         "drive: 0 of 4 phases without a loaded pair; 0 teeth without a 30 deg section; largest |sum F "
                         "l1 - T1| / T1 0.00e+00 The roots of 3 teeth (driven 8, driven 9, driven 10) are not rated: "
                         "ISO 6336-3's 30° section is not found on their outline.")
    # a failed section is named by the analysis's own message, and does not fail the kit
    cut = {"driver": {}, "driven": {8: RootSection(8, np.zeros(2), np.zeros(2), 0.5, math.nan, np.zeros(2))}}
    at_limit = _rating("PETG", 1.5, 1.5, analyses=((1, _tl(imbalance=1e-9)), (-1, _tl(sections=cut))))
    c = _hl(at_limit).checks()[0]
    assert (c.passed, c.value) == (True, 1e-9)
    assert c.message.startswith("the hand on the crank (2.0000 N·m), 2 analyses (printed materials × both "
                                "directions): PETG, drive: 0 of 4 phases")
    # past the limit, and a phase without a loaded pair: each failed analysis named, the value the worst's
    bad = _rating("PLA", 2.5, 1.5, analyses=((1, _tl(imbalance=2e-9)), (-1, _tl(lost=1, imbalance=0.5, phases=6))))
    c = _hl(at_limit, bad).checks()[0]
    assert (c.passed, c.value) == (False, 1.0)
    assert c.message == ("the hand on the crank (2.0000 N·m), 4 analyses (printed materials × both directions): PLA, "
                         "drive: 0 of 4 phases without a loaded pair; 0 teeth without a 30 deg section; largest |sum F "
                         "l1 - T1| / T1 2.00e-09; PLA, reverse: 1 of 6 phases without a loaded pair; 0 teeth without a "
                         "30 deg section; largest |sum F l1 - T1| / T1 5.00e-01")
    big = _rating("PLA", 2.5, 1.5, analyses=((1, _tl(imbalance=3.0)), (-1, _tl(lost=2))))
    assert _hl(big).checks()[0].value == 3.0
    lost = _rating("PLA", 2.5, 1.5, analyses=((1, _tl(imbalance=0.0)), (-1, _tl(lost=2))))
    c = _hl(lost).checks()[0]
    assert (c.passed, c.value) == (False, 2.0) and "PLA, reverse: 2 of 4" in c.message and "drive:" not in c.message


def test_the_reports_note_in_full():
    pla, petg, nylon = _three()
    pla = dataclasses.replace(pla, analyses=((1, _tl(phases=9)), (-1, _tl(phases=5))))
    hl = _hl(pla, petg, nylon)
    assert hl.note() == (
        "The hand on the crank (parts/noncircular_pair/kit_load.py: for a print kit the torque a hand can put on the "
        "crank is the load case): F_hand = 50 N (a stated assumption: a firm one-hand push on a small handle, of the "
        "order of MIL-STD-1472D's thumb-finger grip of 48 N, policy.KIT_HAND_FORCE_N) tangential at the handle's "
        "radius r_h = 40.000 mm, the driven wheel held: T1 = F_hand·r_h = 2.0000 N·m; driver torque T1 = 2 N·m "
        "(test).  Rated on the printed pair (module 1.25 mm, face width 8 mm, the teeth thinned for the printer's "
        "backlash) by the load per tooth's analysis over one period in both directions (9 phases of the drive "
        "direction), K_A = K_v = K_Hbeta = 1, for each printed material of the catalogue: "
        "PLA (E 3000 MPa) S_F 2.500 (sigma_F 20.00 MPa, driven tooth 3, drive (PLA); sigma_FE 50 MPa), S_H 1.500 "
        "(sigma_H 55.50 MPa, driver tooth 1, reverse (PLA); sigma_Hlim 83 MPa), takes about 62 N; "
        "PETG (E 2000 MPa) S_F 1.500 (sigma_F 28.00 MPa, driven tooth 3, drive (PETG); sigma_FE 42 MPa), S_H 1.500 "
        "(sigma_H 46.50 MPa, driver tooth 1, reverse (PETG); sigma_Hlim 70 MPa), takes about 38 N; "
        "nylon (E 1200 MPa) S_F 2.500 (sigma_F 14.00 MPa, driven tooth 3, drive (nylon); sigma_FE 35 MPa), S_H 1.000 "
        "(sigma_H 58.00 MPa, driver tooth 1, reverse (nylon); sigma_Hlim 58 MPa), takes about 32 N "
        "against the part file's S_Fmin 2, S_Hmin 1.25.  " + hl.sentence() + "  " + hl.caveat()
        + "  tables/hand_load.csv.")


def test_worst_is_the_least_safety_over_both_wheels_and_directions_the_first_on_a_tie():
    from propulsor.parts.noncircular_pair.kit_load import _worst

    def v(drv, dvn):
        return {"tooth_load_driver_S_F_min": drv[0], "tooth_load_driver_sigma_F_max_MPa": drv[1],
                "tooth_load_driver_sigma_F_worst_tooth": drv[2], "tooth_load_driven_S_F_min": dvn[0],
                "tooth_load_driven_sigma_F_max_MPa": dvn[1], "tooth_load_driven_sigma_F_worst_tooth": dvn[2],
                "tooth_load_driver_S_H_min": drv[0] + 1, "tooth_load_driver_sigma_H_max_MPa": drv[1] + 100,
                "tooth_load_driver_sigma_H_worst_tooth": drv[2] + 20, "tooth_load_driven_S_H_min": dvn[0] + 1,
                "tooth_load_driven_sigma_H_max_MPa": dvn[1] + 100, "tooth_load_driven_sigma_H_worst_tooth": dvn[2] + 20}

    per = [(1, v((3.0, 10.0, 4), (2.0, 12.0, 7))), (-1, v((2.0, 13.0, 1), (2.5, 11.0, 9)))]
    assert _worst(per, "S_F") == (2.0, 12.0, "driven tooth 7, drive")
    assert _worst(per, "S_H") == (3.0, 112.0, "driven tooth 27, drive")
    per = [(1, v((3.0, 10.0, 4), (2.5, 12.0, 7))), (-1, v((1.5, 13.0, 1), (2.5, 11.0, 9)))]
    assert _worst(per, "S_F") == (1.5, 13.0, "driver tooth 1, reverse")
    assert _worst(per[:1], "S_F") == (2.5, 12.0, "driven tooth 7, drive")


@dataclasses.dataclass(frozen=True)
class _Q:
    """The kit parameters hand_load reads (a part file's load case, which it replaces by the hand's)."""

    load_driver_torque_Nm: float = 99.0
    load_power_W: float = 500.0
    load_vehicle_mass_kg: float = 80.0
    load_life_hours: float = 1000.0
    load_K_A: float = 1.5
    load_K_v: float = 1.2
    load_K_beta: float = 1.3
    gear_material: str = "steel_case_MQ"
    load_S_Fmin: float = 2.0
    load_S_Hmin: float = 1.25
    face_width_mm: float = 8.0


def _kit_stubs(monkeypatch, safeties):
    """analyse, summary and contact_direction replaced: each analysis recorded, its summary the given
    {(material, direction): (S_F driver, S_F driven, S_H driver, S_H driven)}, the stresses 100 / S, the worst tooth
    10 + direction."""
    import propulsor.parts.noncircular_pair.as_built as ab_mod
    import propulsor.parts.noncircular_pair.tooth_load_outputs as tlo

    calls = SimpleNamespace(analyse=[], contact=[])

    def analyse(d, mount, p, c_phi, c_te, phi0, span, step_deg=None, direction=1, tick=None):
        calls.analyse.append(SimpleNamespace(d=d, mount=mount, p=p, c_phi=c_phi, c_te=c_te, phi0=phi0, span=span,
                                             step_deg=step_deg, direction=direction, tick=tick))
        sections = {"driver": {}, "driven": {}}
        if p.gear_material == "PETG" and direction == -1:
            sections["driven"] = {9: SimpleNamespace(ok=False), 3: SimpleNamespace(ok=True)}
        if p.gear_material == "PETG" and direction == 1:
            sections["driver"] = {12: SimpleNamespace(ok=False)}
            sections["driven"] = {9: SimpleNamespace(ok=False)}
        return SimpleNamespace(material=_mat(p.gear_material), load_case=f"case of {p.gear_material} {direction}",
                               sections=sections, direction=direction, lost=0, imbalance=0.0, theta=c_phi)

    def summary(tl, p):
        sfd, sfn, shd, shn = safeties[(p.gear_material, tl.direction)]
        out = {}
        for g, sf, sh in (("driver", sfd, shd), ("driven", sfn, shn)):
            out.update({f"tooth_load_{g}_S_F_min": sf, f"tooth_load_{g}_sigma_F_max_MPa": 100 / sf,
                        f"tooth_load_{g}_sigma_F_worst_tooth": 10 + tl.direction,
                        f"tooth_load_{g}_S_H_min": sh, f"tooth_load_{g}_sigma_H_max_MPa": 100 / sh,
                        f"tooth_load_{g}_sigma_H_worst_tooth": 20 + tl.direction})
        return out

    def contact(d, mount, direction, step):
        calls.contact.append((d, mount, direction, step))
        return SimpleNamespace(phi=np.array([0.25, 0.5, 0.75]), te=np.array([math.nan, 0.0, 1e-3]),
                               direction=direction)

    monkeypatch.setattr(tlo, "analyse", analyse)
    monkeypatch.setattr(tlo, "summary", summary)
    monkeypatch.setattr(ab_mod, "contact_direction", contact)
    return calls


def _kd(method="generated", periods=2, z_H=30):
    return SimpleNamespace(d=SimpleNamespace(method=method, m=1.25, run_law=SimpleNamespace(periods=periods), z_H=z_H),
                           mount=37.5)


def test_hand_load_rates_each_material_in_both_directions_under_the_hands_torque_alone(monkeypatch):
    from propulsor import policy
    from propulsor.parts.noncircular_pair.kit_load import hand_load

    safeties = {("PLA", 1): (3.0, 2.5, 1.5, 1.75), ("PLA", -1): (2.75, 4.0, 1.625, 1.4),
                ("PETG", 1): (2.0, 2.2, 1.3, 1.25), ("PETG", -1): (1.9, 2.1, 1.3, 1.35)}
    calls = _kit_stubs(monkeypatch, safeties)
    counted = []
    kd, q = _kd(), _Q()
    hl = hand_load(q, kd, 40, 50, names=("PLA", "PETG"), count=lambda done, total: counted.append((done, total)))
    # given as whole numbers, kept as floats (the manifest's values)
    assert [type(x) for x in (hl.force_N, hl.r_h_mm, hl.T1_Nm, hl.ratings[0].force_N)] == [float] * 4
    # the contacts of both directions resolved at the kit's step, over one period: 2 pi / 2 (30 teeth, 2 periods)
    step = math.radians(policy.KIT_HAND_LOAD_CONTACT_STEP_DEG)
    assert policy.KIT_HAND_LOAD_CONTACT_STEP_DEG == 0.5
    assert calls.contact == [(kd.d, 37.5, DRIVE, step), (kd.d, 37.5, REVERSE, step)]
    assert [(c.p.gear_material, c.direction) for c in calls.analyse] == [("PLA", 1), ("PLA", -1), ("PETG", 1),
                                                                        ("PETG", -1)]
    for c in calls.analyse:
        assert c.d is kd.d and c.mount == 37.5 and c.phi0 == 0.25 and type(c.phi0) is float and c.span == math.pi
        assert c.step_deg is None and c.tick is None
        assert c.c_te[1:].tolist() == [0.0, 1e-3] and c.c_phi.tolist() == [0.25, 0.5, 0.75]
        # the hand's torque alone, static: T1 = 50 N x 40 mm, no power, vehicle or life, every factor 1
        assert c.p == _Q(load_driver_torque_Nm=2.0, load_power_W=0.0, load_vehicle_mass_kg=0.0, load_life_hours=0.0,
                         load_K_A=1.0, load_K_v=1.0, load_K_beta=1.0, gear_material=c.p.gear_material)
    assert counted == [(0, 4), (1, 4), (2, 4), (3, 4), (4, 4)]
    assert (hl.force_N, hl.r_h_mm, hl.T1_Nm, hl.m_mm, hl.b_mm, hl.S_Fmin, hl.S_Hmin) == (50.0, 40.0, 2.0, 1.25, 8.0,
                                                                                         2.0, 1.25)
    assert hl.load_case == "case of PETG -1"  # the last analysis's words
    assert [dr for dr, _ in hl.contacts] == [DRIVE, REVERSE]
    pla, petg = hl.ratings
    assert (pla.name, pla.material, pla.S_F, pla.S_H) == ("PLA", _mat("PLA"), 2.5, 1.4)
    assert (pla.sigma_F_max_MPa, pla.sigma_H_max_MPa) == (40.0, 100 / 1.4)
    assert (pla.root_worst, pla.flank_worst) == ("driven tooth 11, drive", "driven tooth 19, reverse")
    assert (pla.S_Fmin, pla.S_Hmin, pla.force_N, pla.unrated) == (2.0, 1.25, 50.0, ())
    assert [(d, tl.direction, tl.material.name) for d, tl in pla.analyses] == [(1, 1, "PLA"), (-1, -1, "PLA")]
    assert (petg.S_F, petg.root_worst, petg.S_H, petg.flank_worst) == (1.9, "driver tooth 9, reverse", 1.25,
                                                                      "driven tooth 21, drive")
    assert petg.unrated == ("driven 9", "driver 12")
    assert hl.survivors == ["PLA"]


def test_hand_load_defaults_reuse_and_refusals(monkeypatch):
    from propulsor import policy
    from propulsor.parts.noncircular_pair.kit_load import hand_load

    safeties = {(n, dr): (3.0, 2.5, 1.5, 1.75) for n in ("PLA", "PETG", "nylon") for dr in (1, -1)}
    calls = _kit_stubs(monkeypatch, safeties)
    kd = _kd(periods=3, z_H=31)  # the periods do not hold whole teeth: the whole turn
    hl = hand_load(_Q(), kd, 30.0)
    assert [r.name for r in hl.ratings] == ["PLA", "PETG", "nylon"]
    assert hl.force_N == policy.KIT_HAND_FORCE_N == 50.0 and hl.T1_Nm == 1.5
    assert all(c.span == 2 * math.pi for c in calls.analyse) and len(calls.analyse) == 6
    assert all(r.force_N == 50.0 for r in hl.ratings)
    # the contacts given: not resolved again
    given = ((DRIVE, SimpleNamespace(phi=np.array([0.0, 1.0]), te=np.array([0.0, 0.0]))),
             (REVERSE, SimpleNamespace(phi=np.array([0.0, 1.0]), te=np.array([1e-3, 1e-3]))))
    calls.contact.clear()
    hl = hand_load(_Q(), kd, 30.0, 40.0, names=["nylon"], contacts=given)
    assert calls.contact == [] and hl.contacts == given and hl.T1_Nm == pytest.approx(1.2)
    assert [r.name for r in hl.ratings] == ["nylon"] and hl.ratings[0].force_N == 40.0
    # no contact in a direction: refused, named
    lost = ((DRIVE, given[0][1]), (REVERSE, SimpleNamespace(phi=np.array([0.0, 1.0]), te=np.array([math.nan] * 2))))
    with pytest.raises(ValueError) as e:
        hand_load(_Q(), kd, 30.0, names=["PLA"], contacts=lost)
    assert str(e.value) == "the printed pair has no contact in the reverse direction"
    with pytest.raises(ValueError) as e:
        hand_load(_Q(), kd, 30.0, names=["PLA"], contacts=((REVERSE, lost[1][1]), (DRIVE, given[0][1])))
    assert str(e.value) == "the printed pair has no contact in the reverse direction"
    with pytest.raises(ValueError) as e:
        hand_load(_Q(), kd, 30.0, names=["PLA"], contacts=((DRIVE, lost[1][1]),))
    assert str(e.value) == "the printed pair has no contact in the drive direction"
    # sector teeth (no tooth record): nothing to rate
    calls.analyse.clear()
    assert hand_load(_Q(), _kd("sectors"), 30.0) is None and calls.analyse == []


def test_the_jobs_of_both_directions_and_of_the_tolerance_cases_are_counted_by_their_names(monkeypatch):
    import propulsor.progress as progress
    from propulsor.parts.noncircular_pair.as_built_outputs import _result, tolerance_values

    monkeypatch.setattr(progress, "COUNT_EVERY_S", 0.0)
    import propulsor.parts.noncircular_pair.as_built_outputs as abo

    calls = _recorders(monkeypatch, "the as-built")
    events = []
    rep = progress.Reporter(events.append)
    dd = _dd()
    jobs = (SimpleNamespace(result=lambda: "drive"), SimpleNamespace(result=lambda: "reverse"))
    assert _result(dd, {"as_built": jobs, "proof": None}, rep) == "the as-built"
    assert calls.combine == [(dd.d, ("drive", "reverse"))]
    assert events == ["as built: both directions' contact: direction 0/2",
                      "as built: both directions' contact: direction 1/2",
                      "as built: both directions' contact: direction 2/2"]
    events.clear()
    worst, _ = _tol_results()
    w = SaidWriter()
    w.progress = rep
    tolerance_values(w, dd, {"tolerance": (_tol(), [SimpleNamespace(result=lambda r=r: r) for r in worst])})
    assert events == [f"as made: tolerance cases: case {k}/4" for k in range(5)]
    assert w.derived["tolerance_backlash_min_mm"] == 0.0125
    # as_built_values counts through the writer's progress
    events.clear()
    w = SaidWriter()
    w.progress = rep
    monkeypatch.setattr(abo, "tolerance_values", lambda *a: None)
    monkeypatch.setattr(abo, "combine", lambda d, *c: _ab())
    abo.as_built_values(w, _dd(walking=False), {"as_built": jobs, "proof": _proof()})
    assert events[:3] == ["as built: both directions' contact: direction 0/2",
                          "as built: both directions' contact: direction 1/2",
                          "as built: both directions' contact: direction 2/2"]
