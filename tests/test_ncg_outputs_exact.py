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
    assert corner.message == ("longest run of driver angle with the load on a tooth corner 57.296 deg (reverse at driver "
                              "57.296 deg); share of the cycle on a corner 0.00 % (drive), 40.00 % (reverse)")
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
    assert step.message == "largest change of the driven speed across a change of contact: drive 0.000 %; reverse 0.000 %"
    assert (corner.value, corner.passed) == (0.0, True)
    assert corner.message == ("longest run of driver angle with the load on a tooth corner 0.000 deg; share of the cycle on "
                              "a corner 0.00 % (drive), 0.00 % (reverse)")
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

    ab = _ab()
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
    assert ("positions): driven speed over the law's 1.0000 .. 1.5000 (drive)" in w.notes[0])


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
    assert chk.message == ("least backlash -0.0125 mm over the worst-case corners of ISO 1328-1 grade 8 (test); largest "
                           "speed step 50.00 %; tight: jam (backlash -0.0125 mm at driven 30.00 deg); tight opposed: "
                           "contact lost (0 samples without contact; speed step 31.25 % at driver 12.50 deg); loose: "
                           "contact lost (3 samples without contact; speed step 0.00 % at driver 40.00 deg)")
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
    draws (backlash 0.1, 0.05, 0.2, 0.15, 0.3; TE as their larger direction 0.001, 0.005, 0.002, 0.003, 0.0025)."""
    worst = [_tr("tight", 0.0125, te=(3e-3, 1e-3), step=0.125), _tr("tight opp", 0.025, te=(1e-3, 4e-3), step=0.25),
             _tr("loose", 0.5, te=(2e-3, 2e-3)), _tr("loose opp", 0.625, te=(1e-3, 1e-3), step=0.0625)]
    mc = [_tr("mc 0", 0.1, te=(1e-3, 5e-4)), _tr("mc 1", 0.05, te=(5e-3, 1e-3)), _tr("mc 2", 0.2, te=(1e-3, 2e-3)),
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
