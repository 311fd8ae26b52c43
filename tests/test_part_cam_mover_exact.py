"""The cam mover's design and proofs, number by number (parts/cam_mover/design.py, proofs.py): the plan of a fixed
law (law, motion, walls, core, ring, plate, leg, roller, shoe, carrier, axial layers) against closed forms where the
seed has them, every refusal of ``plan`` in full, the searched branch through a recorder of the search, and the proof
steps (hub height, support variation, the finite-difference check, the 2D sweeps on the outlines and the 3D spot
checks on meshes made in the test) with their checks on a stub of the output writer.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``cam_mover_design``): every plan is
made inside its test (0.15 s), nothing is built as a CAD solid or written but the two STL files the 3D step reads.
"""

from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor import policy
from propulsor.errors import InputError
from propulsor.laws.cam_motion import CurvatureLaw
from propulsor.parts.cam_mover import CamMoverParams, plan
from propulsor.parts.cam_mover import design as cd
from propulsor.parts.cam_mover import proofs as cp
from stand_ins import SaidWriter

S = math.pi / 4  # the support phase of four legs is |φ| <= π/4
LIN = dict(law="linear", k0=0.0093)  # parts/cam_linear.toml


def _refusal(**kw):
    with pytest.raises(InputError) as e:
        plan(CamMoverParams(**kw))
    return str(e.value)


def _loops(*profiles):
    return [loop.polyline() for prof in profiles for loop in prof.loops]


def _steps(p, n):
    """The part's parameters with fewer sweep steps than the file allows (a proof of 72 steps, not 720)."""
    q = dataclasses.replace(p)
    object.__setattr__(q, "sweep_steps", n)
    return q


# ---------------------------------------------------------------------------------------------- design.py: plan


def test_plan_of_the_linear_law_file_closed_forms():
    p = CamMoverParams(**LIN)
    pl = plan(p)
    assert pl.params is p and pl.search is None
    assert (pl.law.kind, pl.law.k0, pl.law.k1, pl.law.symmetric) == ("linear", 0.0093, 0.0, True)
    assert (pl.mech.R0, pl.mech.r, pl.mech.C, pl.mech.n_legs) == (90.0, 20.0, 210.0, 4)
    # H(0) = H0 = R0 + r and the law only lifts the path: the least H is H0, the walls r and r + c off the path
    assert pl.H_min == pytest.approx(110.0, abs=1e-9)
    assert pl.H_max == pytest.approx(169.25057094550377, rel=1e-9)
    assert pl.working_r == pytest.approx((110.0 - 20.0, pl.H_max - 20.0), abs=2e-5)
    assert pl.outer_r == pytest.approx((110.0 + 20.2, pl.H_max + 20.2), abs=2e-5)
    assert pl.rim_radius == pytest.approx(pl.outer_r[1] + 12.0, abs=1e-12)
    # the ODE was integrated with its error measured against the reference integration
    assert pl.motion.H_error_mm is not None and 0.0 < pl.motion.H_error_mm <= 1e-6
    H = pl.motion.H_derivs(np.array([0.0, 0.5 * S, S]))[0]
    assert H[0] == pytest.approx(110.0, abs=1e-9) and H[2] > H[1] > H[0]
    assert pl.R_convex_min == pytest.approx(87.14179804809561, rel=1e-9)
    assert pl.R_convex_where == "working wall at φ = 75.70°"
    ev = pl.evaluation
    assert ev["H_error_mm"] == pytest.approx(pl.motion.H_error_mm, rel=1e-6) and ev["feasible"] and ev["law"] == "linear"
    assert ev["gamma_max_deg"] == pytest.approx(23.299381568307954, rel=1e-9)
    assert ev["R_min_mm"] == pytest.approx(87.14188744136612, rel=1e-9)
    # the path loop lies on H (min H0 at φ = 0), the walls r and r + c from it
    for loop, lo in ((pl.path, 110.0), (pl.working, 90.0), (pl.outer, 130.2)):
        r = np.hypot(*loop.polyline(1e-4).T)
        assert r.min() == pytest.approx(lo, abs=1e-6) and r.max() == pytest.approx(lo + pl.H_max - 110.0, abs=1e-4)
    # axial layers: plate, channel (roller + 2 gaps), carrier above the carrier gap
    assert pl.z == dict(plate=(0.0, 12.0), channel=(12.0, 34.0), roller=(13.0, 33.0), carrier=(36.0, 56.0),
                        shoe=(36.0, 76.0), pin=(13.0, 36.0))


def test_plan_outlines_closed_forms():
    p = CamMoverParams(**LIN)
    pl = plan(p)
    rim = pl.rim_radius
    hole = math.pi * 5.5 ** 2
    # plate: a disc of the rim radius with the bore and six cam bolt holes
    assert pl.plate.area(1e-5) == pytest.approx(math.pi * (rim ** 2 - 20.0 ** 2) - 6 * hole, rel=1e-6)
    assert len(pl.plate.holes) == 7 and len(pl.core.holes) == 7 and len(pl.ring.holes) == 1
    centres = sorted((round(float(c[0]), 6), round(float(c[1]), 6))
                     for c in (h.polyline(1e-4).mean(axis=0) for h in pl.plate.holes) if abs(c[0]) + abs(c[1]) > 1)
    want = sorted((round(60.0 * math.cos(a) + 0.0, 6), round(60.0 * math.sin(a) + 0.0, 6))
                  for a in np.arange(6) * math.pi / 3)
    assert np.allclose(centres, want, atol=1e-6)
    for h in pl.plate.holes:
        q = h.polyline(1e-4)
        if np.hypot(*q.mean(axis=0)) > 1:
            assert np.ptp(q[:, 0]) == pytest.approx(11.0, abs=1e-9)
        else:
            assert np.ptp(q[:, 0]) == pytest.approx(40.0, abs=1e-9)
    # ring: the rim disc minus what the outer wall encloses; core: the working wall's inside minus bore and holes
    outer_area = abs(pl.outer.signed_area(1e-5))
    working_area = abs(pl.working.signed_area(1e-5))
    assert pl.ring.area(1e-5) == pytest.approx(math.pi * rim ** 2 - outer_area, rel=1e-6)
    assert pl.core.area(1e-5) == pytest.approx(working_area - math.pi * 400.0 - 6 * hole, rel=1e-6)
    assert pl.ring.area(1e-5) == pytest.approx(39256.01571284255, rel=1e-6)
    assert pl.core.area(1e-5) == pytest.approx(48547.02575731053, rel=1e-6)
    # leg: 30 wide, 25 behind the roller axle, to the socket's end 100 + 30
    q = pl.leg.outer.polyline(1e-4)
    assert q.min(axis=0) == pytest.approx([-15.0, -25.0]) and q.max(axis=0) == pytest.approx([15.0, 130.0])
    assert pl.leg.area(1e-5) == pytest.approx(30.0 * 155.0, rel=1e-9)
    # roller: radius r with the pin bore (pin + diametral clearance)
    assert pl.roller.area(1e-6) == pytest.approx(math.pi * (400.0 - (16.05 / 2) ** 2), rel=1e-6)
    # shoe: from the boss face (100 mm) to the ground curve at C = 210 mm; boss 30 + 2·10 wide
    q = pl.shoe.profile.outer.polyline(1e-4)
    assert q.min(axis=0)[1] == pytest.approx(100.0, abs=1e-9) and q.max(axis=0)[1] == pytest.approx(210.0, abs=1e-6)
    assert q.max(axis=0)[0] == pytest.approx(196.85060708, rel=1e-7)
    assert pl.shoe.inner_y_at_boss == pytest.approx(193.42934422370914, rel=1e-9)
    assert pl.shoe.profile.area(1e-5) == pytest.approx(11233.173571283245, rel=1e-6)
    boss = [x for x in q if abs(x[1] - 100.0) < 1e-9]
    assert max(abs(x[0]) for x in boss) == pytest.approx(25.0, abs=1e-9)


def test_plan_carrier_closed_form():
    p = CamMoverParams(**LIN)
    car = plan(p).carrier
    # slide bottom = H_min − leg_back − leg_end_gap; slot half width = leg/2 + clearance
    assert car.slot_bottom == pytest.approx(110.0 - 25.0 - 3.0, abs=1e-9)
    assert car.slot_half_width == pytest.approx(15.1, abs=1e-12)
    R, h, b = 195.0, 15.1, car.slot_bottom
    L = math.sqrt(R * R - h * h)
    slot = 2 * h * (L - b) + R * R * math.asin(h / R) - h * L
    expected = math.pi * R * R - 4 * slot - math.pi * 34.0 ** 2 - 4 * math.pi * 4.5 ** 2
    assert car.profile.area(1e-5) == pytest.approx(expected, rel=1e-6)
    # the sprocket holes lie between the slides: at −45° + k·90° on the 65 mm radius
    centres = [h.polyline(1e-4).mean(axis=0) for h in car.profile.holes]
    holes = sorted((round(float(c[0]), 5), round(float(c[1]), 5)) for c in centres if np.hypot(*c) > 1)
    r = 65.0 / math.sqrt(2)
    assert np.allclose(holes, sorted([(-r, -r), (-r, r), (r, -r), (r, r)]), atol=1e-6)
    # three legs: the holes move to −90° + 60° + k·90°
    p3 = CamMoverParams(**LIN, n_legs=3, carrier_bolt_count=2, carrier_bolt_circle_mm=100.0)
    c3 = [h.polyline(1e-4).mean(axis=0) for h in plan(p3).carrier.profile.holes]
    got = sorted((round(float(c[0]), 5), round(float(c[1]), 5)) for c in c3 if np.hypot(*c) > 1)
    a = -0.5 * math.pi + math.pi / 3
    want = sorted([(round(50 * math.cos(a), 5), round(50 * math.sin(a), 5)),
                   (round(50 * math.cos(a + math.pi), 5), round(50 * math.sin(a + math.pi), 5))])
    assert np.allclose(got, want, atol=1e-6)


def test_plan_three_sprocket_holes_between_three_slides():
    """Three legs (slides at −90°, 30°, 150°) and three holes on the 95 mm radius, in the slides' reach: the holes
    sit midway between the slides, at −30°, 90°, 210° (half a turn on, they would sit in the slides)."""
    pl = plan(CamMoverParams(**LIN, n_legs=3, carrier_bolt_count=3, carrier_bolt_circle_mm=190.0))
    got = sorted((round(float(c[0]), 4), round(float(c[1]), 4))
                 for c in (h.polyline(1e-4).mean(axis=0) for h in pl.carrier.profile.holes) if np.hypot(*c) > 1)
    want = sorted((round(95.0 * math.cos(a), 4), round(95.0 * math.sin(a), 4)) for a in np.radians([-30.0, 90.0, 210.0]))
    assert np.allclose(got, want, atol=1e-3)


def test_plan_of_the_zero_law_is_the_straight_path():
    """K = 0: H = H0 / cos φ over the support phase, the shoe's ground curve the circle of C about the roller axle."""
    pl = plan(CamMoverParams(law="zero", carrier_radius_mm=300.0))
    phi = np.linspace(-S, S, 101)
    assert np.max(np.abs(pl.motion.H_derivs(phi)[0] - 110.0 / np.cos(phi))) <= 1e-7
    ground = np.vstack([seg.sample(1e-4) for seg in pl.shoe.curve])
    assert np.max(np.abs(np.hypot(ground[:, 0], ground[:, 1]) - 210.0)) <= 1e-5
    assert pl.evaluation["law"] == "zero" and pl.evaluation["shoe_radius_min_mm"] == pytest.approx(210.0)


def test_plan_with_a_lowered_return_top_and_no_cam_bolts():
    """return_mode 'top' with H(π) = 100 mm puts the least H below H0; no cam bolts: the core has the bore only."""
    pl = plan(CamMoverParams(**LIN, return_mode="top", return_top_mm=100.0, axle_diameter_mm=159.0, cam_bolt_count=0))
    assert pl.H_min == pytest.approx(100.0, abs=1e-9)
    assert pl.motion.H_derivs(np.array([math.pi]))[0][0] == pytest.approx(100.0, abs=1e-9)
    assert pl.R_convex_min == pytest.approx(73.49369588778038, rel=1e-9)
    assert pl.R_convex_where == "working wall at φ = 80.69°"
    assert len(pl.plate.holes) == 1 and len(pl.core.holes) == 1
    assert pl.carrier.slot_bottom == pytest.approx(72.0, abs=1e-9)
    # the law's evaluation uses the same return phase (H(π) = 100 mm, not the default closure's)
    assert pl.evaluation["H_min_mm"] == pytest.approx(100.0, abs=1e-9)
    assert pl.evaluation["H_max_mm"] == pytest.approx(pl.H_max, abs=1e-3)


def test_plan_layers_of_a_wider_groove_gap_and_a_short_guide():
    pl = plan(CamMoverParams(**LIN, groove_axial_gap_mm=2.0))
    assert pl.z == dict(plate=(0.0, 12.0), channel=(12.0, 36.0), roller=(14.0, 34.0), carrier=(38.0, 58.0),
                        shoe=(38.0, 78.0), pin=(14.0, 38.0))
    # the slide reaches 0.5 mm beyond the leg's inner end at H_max: a guide of 0.5 mm is still a guide
    R = math.hypot(pl.H_max - 25.0 + 0.5, 15.1)
    short = plan(CamMoverParams(**LIN, carrier_radius_mm=R))
    assert short.carrier.slot_rim - (short.H_max - 25.0) == pytest.approx(0.5, abs=1e-6)


def test_plan_of_a_searched_law_takes_the_searchs_law(monkeypatch):
    seen = []
    law = CurvatureLaw("linear", 0.0093, 0.0, symmetric=True)

    def search(mech, limits, grid, ret):
        seen.append((mech, limits, grid, ret))
        return SimpleNamespace(law=law, reason="")

    monkeypatch.setattr(cd, "search_design", search)
    p = CamMoverParams(symmetric_law=False)
    pl = plan(p)
    ((mech, limits, grid, ret),) = seen
    assert mech == p.mechanism() and limits == p.limits() and ret == p.return_phase()
    assert grid.symmetric is False and grid == type(grid)(symmetric=False)
    assert pl.law is law and pl.search.law is law
    assert pl.H_max == pytest.approx(169.25057094550377, rel=1e-9)

    monkeypatch.setattr(cd, "search_design", lambda *a: SimpleNamespace(law=None, reason="no law keeps γ <= 30°"))
    with pytest.raises(InputError) as e:
        plan(CamMoverParams())
    assert str(e.value) == ("law = 'searched': the design search found no admissible law: no law keeps γ <= 30°")


def test_plan_refuses_a_path_that_blows_up_under_the_laws_own_names():
    assert _refusal(law="quadratic", k0=1.0) == (
        "k0 = 1.0: roller path of eq. 20 must stay regular (cos γ > 0.001, 0 < ρ < ∞) over the support phase "
        "|φ| <= 45°; it blows up (cos γ → 0 (path tangent turns radial)) at φ = 18.98° (K = 1·φ²)")
    assert _refusal(law="exponential", k0=0.005, k1=8.0) == (
        "k0, k1 = (0.005, 8.0): roller path of eq. 20 must stay regular (cos γ > 0.001, 0 < ρ < ∞) over the support "
        "phase |φ| <= 45°; it blows up (cos γ → 0 (path tangent turns radial)) at φ = 21.92° (K = 0.005·exp(8·|φ|))")


def test_law_input_error_renames_the_laws_error():
    exc = InputError("law", 1, "it blows up", hint="x")
    e = cd._law_input_error(CurvatureLaw("exponential", 0.5, 2.0), exc)
    assert (e.parameter, e.value, e.limit, e.hint) == ("k0, k1", (0.5, 2.0), "it blows up", "K = 0.5·exp(2·|φ|)")
    e = cd._law_input_error(CurvatureLaw("quadratic", 0.25, 0.0, symmetric=True), exc)
    assert (e.parameter, e.value, e.limit, e.hint) == ("k0", 0.25, "it blows up", "K = 0.25·φ²")


def test_plan_refuses_a_shoe_with_a_cusp_or_a_loop():
    assert _refusal(law="linear", k0=0.005, symmetric_law=False) == (
        "k0 = 0.005: the shoe profile has a cusp (tangent reversal): least radius of curvature σ = Y2 − Y1'·sin φ = "
        "-956.7 mm at φ = -45.00°; must be > 0 mm (seed 001 eq. 3, 7) (K = 0.005·φ)")
    assert _refusal(law="exponential", k0=-0.002, k1=1.0) == (
        "k0, k1 = (-0.002, 1.0): the shoe profile crosses itself: least radius of curvature σ = Y2 − Y1'·sin φ = "
        "-7041 mm at φ = -45.00°; must be > 0 mm (seed 001 eq. 3, 7) (K = -0.002·exp(1·|φ|))")
    # the part file's least shoe radius is the limit (the linear law's shoe is the circle of C at φ = 0)
    assert _refusal(**LIN, shoe_radius_min_mm=250.0) == (
        "k0 = 0.0093: the shoe profile has a cusp (tangent reversal): least radius of curvature σ = Y2 − Y1'·sin φ = "
        "210 mm at φ = 0.00°; must be > 250 mm (seed 001 eq. 3, 7) (K = 0.0093·|φ|)")
    assert plan(CamMoverParams(**LIN, shoe_radius_min_mm=209.0)).H_min == pytest.approx(110.0, abs=1e-9)


def test_plan_refuses_a_roller_the_cam_cannot_take():
    assert _refusal(law="quadratic", k0=0.05) == (
        "roller_radius_mm = 20.0: must be < the least convex radius of curvature of the cam channel R = 12.47 mm "
        "(working wall at φ = 44.97°, eq. 16) (K = 0.05·φ²)")
    assert _refusal(law="quadratic", k0=0.05, roller_radius_mm=40.0) == (
        "roller_radius_mm = 40.0: the cam is undercut (radius of curvature of the roller-centre path < r) "
        "(K = 0.05·φ²)")
    assert _refusal(**LIN, roller_radius_mm=87.5) == (
        "roller_radius_mm = 87.5: must be < the least convex radius of curvature of the cam channel R = 49.46 mm "
        "(working wall at φ = 45.03°, eq. 16) (K = 0.0093·|φ|)")
    # a convex radius left but under 1 mm is still "must be < R", not "undercut"
    assert _refusal(law="quadratic", k0=0.05, roller_radius_mm=25.5) == (
        "roller_radius_mm = 25.5: must be < the least convex radius of curvature of the cam channel R = 0.5557 mm "
        "(outer wall at φ = 101.93°, eq. 16) (K = 0.05·φ²)")
    # H_min − r against the axle bore: 80 mm against 81, and 79.5 passes
    assert _refusal(**LIN, return_mode="top", return_top_mm=100.0, axle_diameter_mm=162.0) == (
        "roller_radius_mm = 20.0: the working wall reaches the axle bore: H_min − r = 80 mm must be > "
        "axle_diameter/2 = 81 mm")


def test_convex_radius_min_of_a_table():
    t = SimpleNamespace(phi=np.radians([0.0, 10.0, 20.0, 30.0]), K_path=np.array([0.01, -0.02, 0.005, -0.001]),
                        R_profile=np.array([80.0, -70.0, 50.0, 900.0]), R_outer=np.array([5.0, 40.0, 3.0, 20.0]))
    assert cd._convex_radius_min(t) == (20.0, "outer wall at φ = 30.00°")
    t.R_outer = np.array([5.0, 60.0, 3.0, 70.0])
    assert cd._convex_radius_min(t) == (50.0, "working wall at φ = 20.00°")
    t.K_path = np.array([0.01, 0.02, 0.005, 0.001])
    assert cd._convex_radius_min(t) == (-70.0, "working wall at φ = 10.00°")
    t.K_path = -t.K_path
    assert cd._convex_radius_min(t) == (3.0, "outer wall at φ = 20.00°")
    t.K_path = np.zeros(4)
    assert cd._convex_radius_min(t) == (math.inf, "straight")
    # one sample each way: the working wall's own radius, not the smaller outer one elsewhere
    t.K_path = np.array([0.0, 0.01, 0.0, -0.01])
    assert cd._convex_radius_min(t) == (-70.0, "working wall at φ = 10.00°")
    # a symmetric law's two mirror points, their last bits either way (one CPU's maths or another's): the first named
    t.K_path = np.array([0.01, 0.01, 0.01, 0.01])
    for a, b in ((50.0, np.nextafter(50.0, 0.0)), (np.nextafter(50.0, 0.0), 50.0)):
        t.R_profile = np.array([80.0, a, 90.0, b])
        assert cd._convex_radius_min(t) == (min(a, b), "working wall at φ = 10.00°")


def test_plan_refuses_holes_and_fits_on_both_sides():
    assert _refusal(**LIN, cam_bolt_count=30) == "cam_bolt_count = 30: holes overlap on the pitch circle (pitch 12.57 mm)"
    assert plan(CamMoverParams(**LIN, cam_bolt_count=26)).H_min == pytest.approx(110.0, abs=1e-9)  # pitch 14.5 mm
    # the cam bolt holes (r 5.5 mm) keep 3 mm to the bore (20 mm) and to the working wall (90 mm) exactly at 57 and 163
    for circle in (57.0, 163.0):
        assert len(plan(CamMoverParams(**LIN, cam_bolt_circle_mm=circle)).plate.holes) == 7
    for circle in (56.5, 163.5):
        assert _refusal(**LIN, cam_bolt_circle_mm=circle) == (
            f"cam_bolt_circle_mm = {circle}: holes must keep 3 mm of material between the radii 20 and 90 mm")
    assert _refusal(**LIN, cam_bolt_circle_mm=170.0) == (
        "cam_bolt_circle_mm = 170.0: holes must keep 3 mm of material between the radii 20 and 90 mm")
    assert _refusal(**LIN, return_mode="top", return_top_mm=100.0, axle_diameter_mm=159.0) == (
        "cam_bolt_circle_mm = 120.0: holes must keep 3 mm of material between the radii 79.5 and 80 mm")
    # the shoe's own refusals under the part file's names
    assert _refusal(**LIN, shoe_rim_mm=185.0) == (
        "shoe_rim_mm = 185.0: must be < Y2_min − boss half width = 185 mm (seed 001 eq. 7)")
    assert _refusal(**LIN, shoe_rim_mm=150.0) == (
        "leg_mount_mm = 100.0: must be < 55.62 mm (the inner rim of the shoe at the boss)")
    assert _refusal(**LIN, socket_depth_mm=91.0) == (
        "socket_depth_mm = 91.0: must be <= 90.43 mm (the shoe rim is 193.4 mm from the roller axle at the boss)")
    assert plan(CamMoverParams(**LIN, socket_depth_mm=90.0)).H_min == pytest.approx(110.0, abs=1e-9)
    assert _refusal(**LIN, carrier_bore_mm=160.0) == (
        "carrier_bore_mm = 160.0: must be <= 2·(slide bottom 82 − 3) = 158 mm (slide bottom = H_min − leg_back − "
        "leg_end_gap)")
    assert _refusal(**LIN, carrier_bore_mm=158.5, carrier_bolt_count=0) == (
        "carrier_bore_mm = 158.5: must be <= 2·(slide bottom 82 − 3) = 158 mm (slide bottom = H_min − leg_back − "
        "leg_end_gap)")
    assert plan(CamMoverParams(**LIN, carrier_bore_mm=158.0, carrier_bolt_count=0)).carrier.slot_bottom == 82.0
    assert _refusal(**LIN, carrier_bolt_circle_mm=380.0) == (
        "carrier_bolt_circle_mm = 380.0: holes must keep 3 mm of material between the radii 34 and 195 mm")
    assert _refusal(**LIN, carrier_bolt_count=30, carrier_bolt_hole_mm=4.0, carrier_bolt_circle_mm=300.0) == (
        "carrier_bolt_circle_mm = 300.0: sprocket hole 4 comes within -2 mm of a slide; needs 3 mm")
    assert _refusal(**LIN, carrier_bolt_count=40) == "carrier_bolt_count = 40: holes overlap (pitch 10.21 mm)"
    # the sprocket holes (r 4.5 mm) keep 3 mm to the bore (34 mm) and the rim (195 mm): circles 83 ... 375 mm
    for circle in (83.0, 375.0):
        assert len(plan(CamMoverParams(**LIN, carrier_bolt_circle_mm=circle)).carrier.profile.holes) == 5
    for circle in (82.0, 376.0):
        assert _refusal(**LIN, carrier_bolt_circle_mm=circle) == (
            f"carrier_bolt_circle_mm = {circle}: holes must keep 3 mm of material between the radii 34 and 195 mm")
    # the carrier outline's own refusals under the part file's names, with the part file's values: a slide of the
    # leg's width plus twice the clearance (0.1 mm) as wide as the carrier is refused at the leg's 199.8 mm
    assert _refusal(**LIN, carrier_radius_mm=80.0, carrier_bolt_count=0) == (
        "carrier_radius_mm = 80.0: must reach beyond the slot bottom 82 mm")
    assert _refusal(**LIN, carrier_radius_mm=100.0, leg_width_mm=200.0, carrier_bolt_count=0) == (
        "leg_width_mm = 200.0: its slide (leg_width + 2·slide_clearance = 200.2 mm) must be narrower than the carrier "
        "diameter 200 mm")
    assert _refusal(**LIN, carrier_radius_mm=100.0, leg_width_mm=199.8, carrier_bolt_count=0) == (
        "leg_width_mm = 199.8: its slide (leg_width + 2·slide_clearance = 200 mm) must be narrower than the carrier "
        "diameter 200 mm")
    assert len(plan(CamMoverParams(**LIN, carrier_bolt_count=34)).carrier.profile.holes) == 35  # pitch 12.01 mm
    assert _refusal(**LIN, carrier_radius_mm=120.0) == (
        "carrier_radius_mm = 120.0: the leg leaves its slide at H_max = 169.3 mm: the slide must reach beyond "
        "H_max − leg_back = 144.3 mm")
    assert _refusal(**LIN, n_legs=8, leg_width_mm=60.0) == "leg_width_mm = 60.0: neighbouring slides meet at the slide bottom"


def test_slide_and_hole_limits_at_their_edges():
    """The sprocket holes' distance to a slide and the slides' own gap, each just inside and just outside."""
    # eight legs: 0.5·w + 0.1 + 3 against 82·sin(22.5°) = 31.38 mm: w = 56.5 passes, 56.6 does not
    assert plan(CamMoverParams(**LIN, n_legs=8, leg_width_mm=56.5, carrier_bolt_count=0)).carrier.slot_half_width == \
        pytest.approx(28.35)
    assert _refusal(**LIN, n_legs=8, leg_width_mm=56.7, carrier_bolt_count=0) == (
        "leg_width_mm = 56.7: neighbouring slides meet at the slide bottom")


def test_feasible_checks_a_fixed_law_and_leaves_a_searched_one(monkeypatch):
    searched = []
    monkeypatch.setattr(cd, "search_design", lambda *a: searched.append(a))
    assert cd.feasible(CamMoverParams()) is None  # searched: the build checks it after the search
    assert searched == []
    assert cd.feasible(CamMoverParams(**LIN)) is None
    with pytest.raises(InputError) as e:
        cd.feasible(CamMoverParams(**LIN, carrier_radius_mm=120.0))
    assert str(e.value).startswith("carrier_radius_mm = 120.0: the leg leaves its slide")


# -------------------------------------------------------------------------------------------- proofs.py


def test_leg_poses_turn_the_leg_by_pi_plus_phi_about_the_roller_axle():
    pl = plan(CamMoverParams(**LIN))
    phi = np.array([0.0, 0.3, 2.0])
    M = cp.leg_poses(pl, phi)
    H = pl.motion.H_derivs(phi)[0]
    assert M.shape == (3, 2, 3)
    a = math.pi + phi
    assert np.allclose(M[:, 0, 0], np.cos(a), atol=1e-12) and np.allclose(M[:, 0, 1], -np.sin(a), atol=1e-12)
    assert np.allclose(M[:, 1, 0], np.sin(a), atol=1e-12) and np.allclose(M[:, 1, 1], np.cos(a), atol=1e-12)
    assert np.allclose(M[:, 0, 2], H * np.sin(phi), atol=1e-9) and np.allclose(M[:, 1, 2], -H * np.cos(phi), atol=1e-9)


def test_hub_height_of_a_point_shoe_on_the_straight_path():
    """K = 0: H·cos φ = H0, so a shoe of one point C out along the leg stands at H0 + C·cos w (w the supporting
    leg's angle), the supporting leg the one nearest the downward vertical."""
    pl = plan(CamMoverParams(law="zero", carrier_radius_mm=300.0))
    phi = np.radians([0.0, 10.0, 40.0, 50.0, 100.0, 359.0])
    res = cp.hub_height_from_outline(pl, np.array([[0.0, 210.0]]), phi)
    w = np.radians([0.0, 10.0, 40.0, -40.0, 10.0, -1.0])
    assert list(res["leg"]) == [0, 0, 0, 3, 3, 0]
    assert res["w"] == pytest.approx(w, abs=1e-12)
    assert res["hub"] == pytest.approx(110.0 + 210.0 * np.cos(w), abs=1e-7)
    # the next lowest leg: the neighbour in the return phase, above the ground by its own lower height
    assert np.all(res["idle_clearance"] > 0.0)
    assert res["idle_clearance"][0] == pytest.approx(float(-pl.motion.H_derivs(np.array([0.5 * math.pi]))[0][0]
                                                           * math.cos(0.5 * math.pi) - 210 * math.cos(0.5 * math.pi)
                                                           + 320.0), abs=1e-7)
    # a shoe of two points: the lowest of them
    two = cp.hub_height_from_outline(pl, np.array([[0.0, 100.0], [0.0, 210.0]]), phi)
    assert two["hub"] == pytest.approx(res["hub"], abs=1e-9)


def test_hub_height_from_the_exact_shoe_is_r0_r_c():
    pl = plan(CamMoverParams(**LIN))
    phi = 2.0 * math.pi * np.arange(720) / 720
    res = cp.hub_height_from_outline(pl, pl.shoe.profile.outer.polyline(policy.MOTION_CHORD_TOL_MM), phi)
    assert res["hub"] == pytest.approx(320.0, abs=1e-4)
    assert float(res["hub"].mean()) == pytest.approx(319.9999825697587, abs=1e-9)
    assert np.all(np.abs(res["w"]) <= S + 1e-12)
    # leg j stands at φ + j·90°: leg 3 takes over past φ = 45°, leg 2 past 135°, ... (a tie at the change itself)
    changes = [(i, int(res["leg"][i])) for i in range(1, 720) if res["leg"][i] != res["leg"][i - 1]]
    assert res["leg"][0] == 0 and [c[1] for c in changes] == [3, 2, 1, 0]
    assert [c[0] for c in changes] == pytest.approx([90, 270, 450, 630], abs=1)
    var, per = cp.support_variation(res, 4)
    assert var == pytest.approx(5.9374601391937176e-05, rel=1e-6) and var == max(per) and len(per) == 4


def test_support_variation_per_leg():
    res = dict(leg=np.array([0, 0, 1, 1, 1, 2]), hub=np.array([1.0, 1.5, 2.0, 2.25, 1.75, 9.0]))
    var, per = cp.support_variation(res, 4)
    assert var == 0.5 and per[:3] == [0.5, 0.5, 0.0] and math.isnan(per[3])
    var, per = cp.support_variation(res, 2)
    assert var == 0.5 and per == [0.5, 0.5]


def test_profile_fd_check_agrees_with_eq_9_10_and_16():
    pl = plan(CamMoverParams(**LIN))
    fd = cp.profile_fd_check(pl.motion)
    # 14400 samples less 4 a side of 0, ±φs and π (and the wrap at 2π − φs): 5 + 9 + 9 + 9 + 4
    assert fd["samples"] == 14400 - 36
    assert 0.0 < fd["points_max_mm"] <= 1e-7
    assert 0.0 < fd["curvature_abs_max"] <= 1e-8
    assert 0.0 < fd["curvature_rel_max"] <= 1e-6
    assert fd["curvature_rel_max"] == pytest.approx(fd["curvature_abs_max"] / (1.0 / 87.14179804809561 + 0.0),
                                                    rel=0.2) or fd["curvature_rel_max"] < 1e-6
    assert 0.0 < fd["R_rel_max"] <= 1e-5
    small = cp.profile_fd_check(pl.motion, n=3600)
    assert small["samples"] == 3600 - 36 and small["points_max_mm"] <= 1e-5
    # the zero law: a straight path has no curvature where it is curved enough to count
    z = cp.profile_fd_check(plan(CamMoverParams(law="zero", carrier_radius_mm=300.0)).motion, n=3600)
    assert z["samples"] == 3600 - 36 and z["points_max_mm"] <= 1e-5


def test_profile_fd_check_largest_curvature_and_relative_deviation():
    """kmax is the largest |1/R| of eq. 16 over the kept samples: the relative deviation is the absolute one over it."""
    pl = plan(CamMoverParams(**LIN))
    fd = cp.profile_fd_check(pl.motion, n=7200)
    t = pl.motion.table(-S + 2 * math.pi / 7200 * np.arange(7200))
    kmax = float(np.max(np.abs(1.0 / t.R_profile)))
    assert fd["curvature_rel_max"] == pytest.approx(fd["curvature_abs_max"] / kmax, rel=1e-3)


def test_profile_fd_check_relative_deviation_of_r_where_curved():
    """R_rel_max by the docstring's recipe in the test: 5-point curvature of the table's profile points against
    1/R of eq. 16, |κ_FD − κ| / |κ_FD| over the kept samples whose |κ| >= 0.1/H0."""
    pl = plan(CamMoverParams(**LIN))
    motion = pl.motion
    n = 7200
    h = 2 * math.pi / n
    phi = -S + h * np.arange(n)
    keep = np.ones(n, bool)
    for a in (-S, 0.0, S, math.pi, 2 * math.pi - S):
        keep &= np.abs(phi - a) > 4.5 * h
    k = np.array([-2, -1, 0, 1, 2])
    P = motion.table((phi[:, None] + h * k[None, :]).ravel())
    X, Y = P.X.reshape(n, 5), P.Y.reshape(n, 5)
    d1 = np.array([1.0, -8.0, 0.0, 8.0, -1.0]) / (12 * h)
    d2 = np.array([-1.0, 16.0, -30.0, 16.0, -1.0]) / (12 * h * h)
    x1, y1, x2, y2 = X @ d1, Y @ d1, X @ d2, Y @ d2
    kfd = -(x1 * y2 - y1 * x2) / (x1 ** 2 + y1 ** 2) ** 1.5
    k16 = 1.0 / motion.table(phi).R_profile
    curved = keep & (np.abs(k16) >= 0.1 / 110.0)
    want = float(np.max((np.abs(kfd - k16) / np.abs(kfd))[curved]))
    fd = cp.profile_fd_check(motion, n=n)
    assert fd["R_rel_max"] == pytest.approx(want, rel=1e-6)
    assert fd["curvature_abs_max"] == pytest.approx(float(np.max(np.abs(kfd - k16)[keep])), rel=1e-6)
    # the relative deviation where the wall is curved is not the one where it is nearly straight
    flat = keep & ~curved
    assert np.any(flat) and np.count_nonzero(curved) > 100


def test_inside_of_a_diamond_by_crossings():
    """|x| + |y| < 1: every point of a grid off the edges, the crossings' convention on a vertex's height (y = 0) and
    on the right edge (outside), and no floating-point warning from the horizontal edges of a square."""
    import warnings

    diamond = np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]])
    for x in np.linspace(-1.3, 1.3, 27):
        for y in np.linspace(-1.25, 1.25, 11):
            if abs(abs(x) + abs(y) - 1.0) > 1e-6:
                assert cp._inside((x, y), diamond) == (abs(x) + abs(y) < 1.0), (x, y)
    assert cp._inside((0.5, 0.0), diamond) and cp._inside((-0.5, 0.0), diamond)
    assert not cp._inside((-2.0, 0.0), diamond) and not cp._inside((2.0, 0.0), diamond)
    assert cp._inside((0.2, 0.5), diamond) and cp._inside((0.45, 0.5), diamond)
    assert not cp._inside((0.5, 0.5), diamond)  # on the right edge: the crossing at x itself is not counted
    # edges whose rise is not 1: |x|/2 + |y|/3 < 1
    wide = np.array([[0.0, -3.0], [2.0, 0.0], [0.0, 3.0], [-2.0, 0.0]])
    for x in np.linspace(-2.5, 2.5, 21):
        for y in np.linspace(-3.5, 3.5, 15):
            if abs(abs(x) / 2 + abs(y) / 3 - 1.0) > 1e-6:
                assert cp._inside((x, y), wide) == (abs(x) / 2 + abs(y) / 3 < 1.0), (x, y)
    sq = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert cp._inside((1.0, 1.0), sq)  # y = 1 crosses the horizontal edges at infinity: divide
        cp._inside((1.0, 0.0), sq)  # y = 0 on the bottom edge: 0/0, invalid (no warning either)
        assert not cp._inside((3.0, 2.0), sq)


def test_inside_of_a_square():
    sq = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    assert cp._inside((1.0, 1.0), sq) is True
    assert cp._inside((3.0, 1.0), sq) is False
    assert cp._inside((-1.0, 1.0), sq) is False
    assert cp._inside((1.0, 3.0), sq) is False
    assert cp._inside((1.999, 0.001), sq) is True


def _proved(n=72, **kw):
    p = _steps(CamMoverParams(**{**LIN, **kw}), n)
    pl = dataclasses.replace(plan(p), params=p)
    return pl, {"shoe_loops": _loops(pl.shoe.profile), "channel_loops": _loops(pl.ring, pl.core)}


def test_motion_proofs_on_the_outlines():
    pl, built = _proved()
    ticks = []
    out = cp.motion_proofs(pl, built["shoe_loops"], built["channel_loops"], ticks.append)
    assert ticks == [1, 2, 3, 4, 5, 6, 7, 8]
    assert set(out) == {"phi", "roller_working", "roller_outer", "hub", "hub_exact", "leg_carrier", "shoe_carrier",
                        "neighbours", "opposite"}
    assert out["phi"] == pytest.approx(2 * math.pi * np.arange(72) / 72)
    rw, ro = out["roller_working"], out["roller_outer"]
    assert rw.name == "roller_vs_working_wall" and ro.name == "roller_vs_outer_wall" and rw.n_steps == 72
    # the roller rolls on the working wall (gap within the chord tolerance) and keeps c = 0.2 mm to the outer wall
    assert rw.max_overlap == 0.0 and 0.0 <= rw.clearance.min() and rw.clearance.max() <= 0.002
    assert ro.clearance.min() == pytest.approx(0.2, abs=2e-3) and ro.clearance.max() == pytest.approx(0.2, abs=2e-3)
    # the leg in its slide: the slide clearance per side
    assert out["leg_carrier"].min_clearance == pytest.approx(0.1, abs=1e-9)
    assert out["leg_carrier"].name == "leg_vs_carrier_slide"
    assert out["shoe_carrier"].min_clearance == pytest.approx(15.585520086594386, rel=1e-6)
    assert out["neighbours"].min_clearance == pytest.approx(83.2224033977553, rel=1e-6)
    assert out["opposite"].min_clearance == pytest.approx(196.4194138064164, rel=1e-6)
    assert (out["shoe_carrier"].name, out["neighbours"].name, out["opposite"].name) == (
        "shoe_vs_carrier", "neighbouring_legs", "opposite_legs")
    assert out["hub"]["hub"] == pytest.approx(320.0, abs=2e-3)
    assert out["hub_exact"]["hub"] == pytest.approx(320.0, abs=1e-4)
    assert np.ptp(out["hub_exact"]["hub"]) < np.ptp(out["hub"]["hub"])


def test_motion_proofs_of_three_legs_have_no_opposite_leg():
    pl, built = _proved(n=36, n_legs=3, carrier_bolt_count=0)
    ticks = []
    out = cp.motion_proofs(pl, built["shoe_loops"], built["channel_loops"], ticks.append)
    assert ticks == [1, 2, 3, 4, 5, 6, 7] and "opposite" not in out and out["neighbours"].n_steps == 36
    out = cp.motion_proofs(pl, built["shoe_loops"], built["channel_loops"])
    assert "opposite" not in out


def test_motion_proofs_of_five_legs_take_the_leg_two_places_on_as_opposite():
    from propulsor.checks.motion import outline, sweep_pair

    pl, built = _proved(n=36, n_legs=5, leg_width_mm=30.0, carrier_bolt_count=0)
    out = cp.motion_proofs(pl, built["shoe_loops"], built["channel_loops"])
    phi = 2 * math.pi * np.arange(36) / 36
    body_cs = outline(pl.shoe.profile, 1e-3, 1.0).section + outline(pl.leg, 1e-3, 1.0).section
    body = outline([np.asarray(q, float) for q in body_cs.to_polygons()], 1e-3, 1.0)
    legM = cp.leg_poses(pl, phi)
    want = sweep_pair(body, legM, body, cp.leg_poses(pl, phi + 2 * math.pi * 2 / 5), name="x", max_segment=1.0)
    assert out["opposite"].clearance == pytest.approx(want.clearance, rel=1e-12)
    near = sweep_pair(body, legM, body, cp.leg_poses(pl, phi + 2 * math.pi / 5), name="x", max_segment=1.0)
    assert out["neighbours"].clearance == pytest.approx(near.clearance, rel=1e-12)
    other = sweep_pair(body, legM, body, cp.leg_poses(pl, phi - 2 * math.pi * 2 / 5), name="x", max_segment=1.0)
    assert np.max(np.abs(other.clearance - want.clearance)) > 1e-3


def test_engineering_checks_of_the_linear_law():
    pl, built = _proved()
    w = SaidWriter()
    cp.engineering_checks(pl, w, built)
    got = [(c.name, c.passed, c.limit, c.unit) for c in w.checks]
    assert got == [
        ("law: ODE error of H (eq. 20)", True, 1e-06, "mm"),
        ("law: pressure angle (eq. 17)", True, 30.0, "deg"),
        ("law: convex cam radius of curvature (eq. 16)", True, 30.0, "mm"),
        ("law: Hertz stress (eq. 14-15)", True, 1500.0, "MPa"),
        ("shoe: least radius of curvature (eq. 3)", True, 0.0, "mm"),
        ("shoe: footprint ratio", True, 0.85, ""),
        ("cam: core H_min − r", True, 40.0, "mm"),
        ("law: eq. 9-10 profile points vs finite differences", True, 1e-06, "mm"),
        ("law: eq. 16 radius vs finite-difference curvature", True, 1e-05, ""),
        ("carrier: leg length inside its slide at H_max", True, 30.0, "mm"),
        ("assembly: axial gap cam → carrier/legs/shoes", True, 0.0, "mm")]
    v = [c.value for c in w.checks]
    assert v[0] == pytest.approx(pl.motion.H_error_mm) and v[1] == pytest.approx(23.299381568307954, rel=1e-9)
    assert v[2] == pytest.approx(87.14179804809561, rel=1e-9) and v[3] == pytest.approx(764.3354553873432, rel=1e-9)
    assert v[4] == pytest.approx(210.0, rel=1e-9) and v[5] == pytest.approx(0.8426741665315893, rel=1e-9)
    assert v[6] == pytest.approx(90.0, abs=1e-9) and 0 < v[7] <= 1e-7 and 0 < v[8] <= 1e-6
    # guide: the slide's rim less (H_max − leg_back); the axial gap: carrier bottom − channel top
    assert v[9] == pytest.approx(pl.carrier.slot_rim - (pl.H_max - 25.0), abs=1e-12)
    assert v[9] == pytest.approx(50.16390896790185, rel=1e-9) and v[10] == 2.0
    m = [c.message for c in w.checks]
    assert m[0] == "max |H − H_ref| against a DOP853 integration at 1e-13"
    assert m[1] == "largest |γ| over the turn (23.299° in support)"
    assert m[2] == "least convex radius of the channel walls (working wall at φ = 75.70°) >= 1.5·r"
    assert m[3] == "support 764.3 MPa at P = 5000 N, return 243.4 MPa at 500 N"
    assert m[4] == "σ = Y2 − Y1'·sin φ, no cusp; self-intersecting: False"
    assert m[5] == "shoe arc / hub travel per step (discrete footprints; ours)"
    assert m[6] == "material around the axle"
    assert m[7] == "H' by 5-point differences of H on 14364 points of a turn"
    assert m[8].startswith("max |1/R(eq. 16) − κ_FD| = ") and " 1/mm over the largest curvature; relative deviation " \
        "of R where |R| <= 10·H0: " in m[8]
    assert m[9] == "guide length of the radial slide" and m[10] == "the channel layer and the carrier layer are separate"
    d = w.derived
    assert set(d) == {"fd_profile_points_max_mm", "fd_profile_curvature_abs_max_per_mm", "fd_profile_R_rel_max"}
    assert d["fd_profile_points_max_mm"] == v[7] and 0 < d["fd_profile_curvature_abs_max_per_mm"] <= 1e-8
    assert 0 < d["fd_profile_R_rel_max"] <= 1e-5


def test_engineering_checks_take_the_larger_hertz_stress_and_fail_where_the_part_fails():
    pl, built = _proved(sigma_allow_MPa=700.0, load_return_N=5000.0, leg_guide_min_mm=60.0, R_factor=5.0,
                        gamma_max_deg=20.0, footprint_ratio_max=0.5, cam_core_min_mm=95.0, shoe_radius_min_mm=0.0)
    w = SaidWriter()
    cp.engineering_checks(pl, w, built)
    by = {c.name: c for c in w.checks}
    hz = by["law: Hertz stress (eq. 14-15)"]
    # equal loads: the return's curvature is the larger (the support's convex wall is flatter)
    assert hz.value == pytest.approx(max(pl.evaluation["sigma_max_MPa"], pl.evaluation["sigma_return_max_MPa"]))
    assert hz.value == pytest.approx(pl.evaluation["sigma_return_max_MPa"]) and not hz.passed
    assert hz.message == (f"support {pl.evaluation['sigma_max_MPa']:.1f} MPa at P = 5000 N, return "
                          f"{pl.evaluation['sigma_return_max_MPa']:.1f} MPa at 5000 N")
    assert [c.passed for c in w.checks] == [True, False, False, False, True, False, False, True, True, False, True]
    assert by["law: convex cam radius of curvature (eq. 16)"].limit == 100.0
    assert by["shoe: least radius of curvature (eq. 3)"].limit == 0.0


def test_engineering_checks_of_the_returns_larger_stress():
    pl, built = _proved()
    pl = dataclasses.replace(pl, evaluation={**pl.evaluation, "sigma_return_max_MPa": 900.0,
                                             "shoe_self_intersecting": True})
    w = SaidWriter()
    cp.engineering_checks(pl, w, built)
    assert w.checks[3].value == 900.0
    assert w.checks[4].message == "σ = Y2 − Y1'·sin φ, no cusp; self-intersecting: True"


def test_motion_proof_checks_of_the_linear_law():
    pl, built = _proved()
    w = SaidWriter()
    cp.motion_proof_checks(pl, w, built)
    assert w.said == ["cam_mover: motion proofs (72 steps per turn)"]
    assert set(built["proofs"]) >= {"roller_working", "hub", "opposite"}
    got = [(c.name, c.passed, c.limit, c.unit) for c in w.checks]
    tol = policy.OVERLAP_AREA_TOL_MM2
    assert got == [
        ("roller in channel: overlap with the working wall", True, tol, "mm^2"),
        ("roller in channel: overlap with the outer wall", True, tol, "mm^2"),
        ("roller in channel: gap to the working wall", True, [0.0, policy.CHORD_TOL_MM], "mm"),
        ("roller in channel: clearance to the outer wall", True, pytest.approx([0.1, 0.3]), "mm"),
        ("hub height: variation over a support phase (exported shoe DXF)", True, 0.01, "mm"),
        ("hub height: mean vs R0 + r + C", True, 0.01, "mm"),
        ("hub height: idle shoes clear the ground", True, 0.0, "mm"),
        ("collision: legs in their slides: overlap", True, tol, "mm^2"),
        ("collision: legs in their slides: clearance", True, 0.0, "mm"),
        ("collision: shoes vs carrier: overlap", True, tol, "mm^2"),
        ("collision: shoes vs carrier: clearance", True, 0.0, "mm"),
        ("collision: neighbouring legs + shoes: overlap", True, tol, "mm^2"),
        ("collision: neighbouring legs + shoes: clearance", True, 0.0, "mm"),
        ("collision: opposite legs + shoes: overlap", True, tol, "mm^2"),
        ("collision: opposite legs + shoes: clearance", True, 0.0, "mm")]
    c = w.checks
    assert c[0].message == "manifold3d intersection area, max over 72 steps of a turn (step 0)"
    assert c[2].value == pytest.approx(0.0015380610874801272, rel=1e-6)
    assert c[2].message == ("rolling contact: gap 7.89e-05 .. 0.00154 mm over the turn (0 by design; the DXF polyline "
                            "lies within 0.005 mm of the curve)")
    assert c[3].value == pytest.approx(0.19858922132812634, rel=1e-6)
    assert c[3].message == "clearance 0.19859 .. 0.20010 mm (designed 0.2 mm) — no binding"
    assert c[4].value == pytest.approx(0.001326666870625104, rel=1e-6)
    assert c[4].message == ("largest max − min per support phase over 72 steps of a turn: leg 1: 1.33e-03, leg 2: "
                            "1.33e-03, leg 3: 1.33e-03, leg 4: 1.33e-03; exact curve: 5.25e-05 mm")
    assert c[5].value == pytest.approx(0.0005691608825486583, rel=1e-6)
    assert c[5].message == "mean 319.999431 mm, design 320 mm"
    assert c[6].value == pytest.approx(1.5412535569888632, rel=1e-6)
    assert c[6].message == "least ground clearance of the legs not in support (inner 90 % of each support phase)"
    assert c[7].message == "max over 72 steps; clearance 0.1000 .. 0.1000 mm"
    assert c[8].value == pytest.approx(0.1, abs=1e-9) and c[8].message == "least clearance at step 67"
    assert c[9].message == "max over 72 steps; clearance 15.5855 .. 74.8351 mm"
    assert c[10].value == pytest.approx(15.585520086594386, rel=1e-6) and c[10].message == "least clearance at step 0"
    assert c[11].message == "max over 72 steps; clearance 83.2224 .. 106.3589 mm"
    assert c[12].message == "least clearance at step 63"
    assert c[13].message == "max over 72 steps; clearance 196.4194 .. 287.7543 mm"
    d = w.derived
    assert d["roller_gap_working_mm"] == pytest.approx([7.892891856483673e-05, 0.0015380610874801272], rel=1e-6)
    assert d["roller_clearance_outer_mm"] == pytest.approx([0.19858922132812634, 0.2000990438462319], rel=1e-6)
    assert d["roller_overlap_max_mm2"] == 0.0
    assert d["hub_height_variation_dxf_mm"] == pytest.approx(0.001326666870625104, rel=1e-6)
    assert d["hub_height_variation_exact_mm"] == pytest.approx(5.2528322271427896e-05, rel=1e-6)
    assert d["hub_height_mean_mm"] == pytest.approx(319.99943083911745, rel=1e-12)
    assert d["idle_shoe_ground_clearance_min_mm"] == pytest.approx(1.5412535569888632, rel=1e-6)
    assert d["leg_slide_clearance_mm"] == pytest.approx([0.1, 0.1], abs=1e-9)
    assert d["shoe_carrier_clearance_min_mm"] == pytest.approx(15.585520086594386, rel=1e-6)
    assert d["neighbour_clearance_min_mm"] == pytest.approx(83.2224033977553, rel=1e-6)
    assert d["sweep_steps"] == 72 and type(d["sweep_steps"]) is int


def test_motion_proof_checks_fail_a_roller_off_its_wall_and_a_wide_variation():
    """Channel loops that are the outer wall twice: the roller is 0.2 mm off its working wall, the checks fail."""
    pl, built = _proved(hub_height_tol_mm=1e-4)
    built["channel_loops"] = [q for q in built["channel_loops"]]
    w = SaidWriter()
    from propulsor.progress import Reporter

    events = []
    w.progress = Reporter(events.append)
    cp.motion_proof_checks(pl, w, built)
    by = {c.name: c for c in w.checks}
    assert not by["hub height: variation over a support phase (exported shoe DXF)"].passed
    assert not by["hub height: mean vs R0 + r + C"].passed
    counts = [e for e in events if getattr(e, "done", None) is not None]
    assert counts[0].done == 0 and counts[-1].done == 8 and {e.total for e in counts} == {8}
    assert str(counts[0]) == "cam_mover: motion proofs: sweep 0/8" and str(counts[-1]) == "cam_mover: motion proofs: sweep 8/8"
    assert {e.phase for e in counts} == {"cam_mover: motion proofs"}


def test_motion_proof_checks_bounds_of_the_roller_gaps():
    pl, built = _proved()
    w = SaidWriter()
    cp.motion_proof_checks(pl, w, built)
    gw = w.checks[2]
    lo, hi = w.derived["roller_gap_working_mm"]
    assert gw.passed == (lo >= 0.0 and hi <= policy.CHORD_TOL_MM)
    # a channel clearance of 0.3 mm: the designed 0.2 mm gap is below half of 0.5 mm... the checks of a part file
    # whose clearance is 0.4 mm on walls cut for 0.2 mm fail both ways
    p = _steps(CamMoverParams(**LIN, channel_clearance_mm=0.45), 72)
    w2 = SaidWriter()
    cp.motion_proof_checks(dataclasses.replace(pl, params=p), w2, built)
    c = w2.checks[3]
    assert c.limit == pytest.approx([0.225, 0.675]) and not c.passed
    p = _steps(CamMoverParams(**LIN, channel_clearance_mm=0.13), 72)
    w3 = SaidWriter()
    cp.motion_proof_checks(dataclasses.replace(pl, params=p), w3, built)
    c = w3.checks[3]
    assert c.limit == pytest.approx([0.065, 0.195]) and not c.passed


def _sweep(clearance, overlap=0.0):
    c = np.asarray(clearance, float)
    return SimpleNamespace(max_overlap=overlap, clearance=c, n_steps=len(c), step_max_overlap=0,
                           min_clearance=float(c.min()), step_min_clearance=int(np.argmin(c)),
                           overlap_area=np.zeros(len(c)))


def _checks_of(monkeypatch, working, outer, w_leg=(0.0, 0.1), idle=(5.0, 1.0), n=4):
    """motion_proof_checks on given sweep results (the sweeps replaced by a recorder of them)."""
    pl, built = _proved()
    s = S
    hub = dict(hub=np.array([320.0, 320.0]), leg=np.array([0, 1]), w=np.array(w_leg), idle_clearance=np.array(idle))
    out = {"phi": np.array([0.0, 1.0]), "roller_working": _sweep(working), "roller_outer": _sweep(outer),
           "hub": hub, "hub_exact": hub, "leg_carrier": _sweep([0.1, 0.1]), "shoe_carrier": _sweep([15.0, 70.0]),
           "neighbours": _sweep([80.0, 90.0])}
    if n >= 4:
        out["opposite"] = _sweep([190.0, 200.0])
    monkeypatch.setattr(cp, "motion_proofs", lambda *a, **k: out)
    w = SaidWriter()
    cp.motion_proof_checks(pl, w, built)
    return {c.name: c for c in w.checks}, w


def test_motion_proof_checks_limits_of_the_roller_gaps(monkeypatch):
    c = 0.2
    tol = policy.CHORD_TOL_MM
    gap, clr = "roller in channel: gap to the working wall", "roller in channel: clearance to the outer wall"
    by, _ = _checks_of(monkeypatch, [0.0, tol], [0.5 * c + 1e-9, 1.5 * c - 1e-9])
    assert by[gap].passed and by[clr].passed
    by, _ = _checks_of(monkeypatch, [0.0, tol + 1e-6], [0.5 * c, 1.5 * c - 1e-9])
    assert not by[gap].passed and not by[clr].passed  # lifted off its wall; on the outer wall's half clearance
    by, _ = _checks_of(monkeypatch, [-1e-6, tol], [0.5 * c + 1e-9, 1.5 * c])
    assert not by[gap].passed and not by[clr].passed  # into its wall; binding at 1.5 c
    assert by[gap].value == tol and by[clr].value == pytest.approx(0.5 * c + 1e-9)


def test_motion_proof_checks_idle_shoes_inside_90_percent_of_the_support(monkeypatch):
    idle = "hub height: idle shoes clear the ground"
    by, w = _checks_of(monkeypatch, [0.0, 0.001], [0.2, 0.2], w_leg=(0.0, 0.9 * S), idle=(5.0, 1.0))
    assert by[idle].value == 5.0 and w.derived["idle_shoe_ground_clearance_min_mm"] == 5.0
    by, _ = _checks_of(monkeypatch, [0.0, 0.001], [0.2, 0.2], w_leg=(0.0, 0.9 * S - 1e-9), idle=(5.0, 1.0))
    assert by[idle].value == 1.0
    by, _ = _checks_of(monkeypatch, [0.0, 0.001], [0.2, 0.2], w_leg=(-0.9 * S + 1e-9, 0.0), idle=(0.5, 1.0))
    assert by[idle].value == 0.5


def _meshes(pl):
    """The cam (plate, then the channel's core and ring above it) and the roller as manifold3d solids."""
    from propulsor.checks.motion import outline

    z = pl.z
    plate = outline(pl.plate, 0.02, 1.0).section.extrude(z["plate"][1] - z["plate"][0])
    walls = (outline(pl.core, 0.02, 1.0).section + outline(pl.ring, 0.02, 1.0).section).extrude(z["channel"][1] - z["channel"][0])
    cam = plate + walls.translate([0.0, 0.0, z["channel"][0]])
    roller = outline(pl.roller, 0.02, 1.0).section.extrude(z["roller"][1] - z["roller"][0])
    return cam, roller


def test_spot_checks_3d_of_the_roller_in_the_channel():
    pl, _ = _proved()
    cam, roller = _meshes(pl)
    phi, res = cp.spot_checks_3d(pl, cam, roller, k=4)
    assert phi == pytest.approx(2 * math.pi * np.arange(4) / 4 + 0.5 * math.pi / 4)
    assert res.name == "roller_vs_cam_3d"
    assert res.max_overlap <= policy.OVERLAP_VOLUME_TOL_MM3
    assert np.all(res.gap >= 0.0) and np.all(res.gap <= 0.05)  # rolling on the working wall (0.02 mm chords)
    assert len(res.gap) == 4
    phi, res = cp.spot_checks_3d(pl, cam, roller)
    assert len(phi) == cp.SPOT_CHECKS_3D == 16 and phi[0] == pytest.approx(0.5 * math.pi / 16)
    # the roller one gap lower sits in the plate: z of the roller's bottom face is the layer's
    low = dataclasses.replace(pl, z={**pl.z, "roller": (11.0, 31.0)})
    _, res = cp.spot_checks_3d(low, cam, roller, k=2)
    assert res.max_overlap > 100.0


def test_spot_checks_3d_place_the_roller_by_the_leg_pose():
    """A roller one radius off the path (the leg turned by a quarter) cuts the channel walls."""
    pl, _ = _proved()
    cam, roller = _meshes(pl)
    far = roller.translate([25.0, 0.0, 0.0])
    _, res = cp.spot_checks_3d(pl, cam, far, k=2)
    assert res.max_overlap > 1000.0
    # a roller of 8 mm radius clears the walls by 12 mm: the gap is the roller's 1 mm above the channel floor
    small = dataclasses.replace(pl)
    from propulsor.checks.motion import outline
    from propulsor.geometry.profile import circle_loop, Profile

    tiny = outline(Profile(circle_loop(8.0)), 0.02, 1.0).section.extrude(20.0)
    _, res = cp.spot_checks_3d(small, cam, tiny, k=2)
    assert res.gap == pytest.approx([1.0, 1.0], abs=1e-9)
    # the roller's own z kept (not scaled): a roller 1 mm up in its own frame is 2 mm off the floor
    _, res = cp.spot_checks_3d(small, cam, tiny.translate([0.0, 0.0, 1.0]), k=2)
    assert res.gap == pytest.approx([2.0, 2.0], abs=1e-9)
    # the gap is searched within 5 mm: 11 mm off the floor (12 off the walls) reads 5
    _, res = cp.spot_checks_3d(small, cam, tiny.translate([0.0, 0.0, 10.0]), k=2)
    assert res.gap == pytest.approx([5.0, 5.0], abs=1e-9)


def test_spot_checks_and_tables(tmp_path):
    import trimesh

    pl, built = _proved()
    cam, roller = _meshes(pl)
    for name, m in (("cam", cam), ("roller", roller)):
        mesh = m.to_mesh()
        trimesh.Trimesh(mesh.vert_properties[:, :3], mesh.tri_verts, process=False).export(tmp_path / f"{name}.stl")
    w = SaidWriter(tmp_path)
    cp.motion_proof_checks(pl, w, built)
    n = len(w.checks)
    cp.spot_checks_and_tables(pl, w, built)
    assert w.said[-1] == "cam_mover: 3D spot checks (exported STL)" and w.waited == [("cam", "roller")]
    (c,) = w.checks[n:]
    assert (c.name, c.passed, c.limit, c.unit) == ("roller in channel (3D, exported meshes): overlap volume", True,
                                                   policy.OVERLAP_VOLUME_TOL_MM3, "mm^3")
    assert c.message.startswith("16 carrier angles; gap ") and c.message.endswith(" mm (manifold3d min_gap)")
    lo, hi = w.derived["roller_cam_3d_gap_mm"]
    assert 0.0 <= lo <= hi <= 0.05
    assert c.message == f"16 carrier angles; gap {lo:.4g} .. {hi:.4g} mm (manifold3d min_gap)"
    cols, rows = w.tables["roller_sweep"]
    pr = built["proofs"]
    assert rows is None and list(cols) == ["phi_deg", "H_mm", "gap_working_wall_mm", "clearance_outer_wall_mm",
                                           "overlap_working_mm2", "overlap_outer_mm2"]
    assert cols["phi_deg"] == pytest.approx(5.0 * np.arange(72))
    assert cols["H_mm"] == pytest.approx(pl.motion.H_derivs(pr["phi"])[0])
    assert cols["gap_working_wall_mm"] is pr["roller_working"].clearance
    assert cols["clearance_outer_wall_mm"] is pr["roller_outer"].clearance
    assert cols["overlap_working_mm2"] is pr["roller_working"].overlap_area
    assert cols["overlap_outer_mm2"] is pr["roller_outer"].overlap_area
    cols, rows = w.tables["hub_height"]
    hub = pr["hub"]
    assert rows is None and list(cols) == ["phi_deg", "supporting_leg", "leg_phi_deg", "hub_height_dxf_mm",
                                           "hub_height_exact_mm", "idle_shoe_clearance_mm"]
    assert cols["phi_deg"] == pytest.approx(5.0 * np.arange(72))
    assert list(cols["supporting_leg"]) == list(hub["leg"] + 1)
    assert cols["leg_phi_deg"] == pytest.approx(np.degrees(hub["w"]))
    assert cols["hub_height_dxf_mm"] is hub["hub"] and cols["hub_height_exact_mm"] is pr["hub_exact"]["hub"]
    assert cols["idle_shoe_clearance_mm"] is hub["idle_clearance"]
