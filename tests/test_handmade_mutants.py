"""Engineering truths the hand-made mutants of issue 36 found unpinned (mutation/handmade.toml, mutation/README.md).

Each test computes its expected value independently of the code under test (geometry, a balance of forces, the
definition a docstring states) and names the mutant it kills."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from propulsor.gears.involute import SpurGear
from propulsor.params import load_params, read_part_file
from propulsor.parts.final_drive import FinalDriveParams

FINAL_DRIVE = Path(__file__).resolve().parents[1] / "parts" / "final_drive.toml"


@pytest.fixture(scope="module")
def fd():
    """(params, planetary set) of the project's final drive part file."""
    from propulsor.parts.final_drive.design import planetary_set

    _, mp = read_part_file(FINAL_DRIVE)
    p = load_params(FinalDriveParams, mp)
    return p, planetary_set(p)


# ---- gears/involute.py: dimension over rollers of an odd tooth count (mutant gears-involute-479) -------------------
_ODD = [SpurGear(17, 10.0, 0.5), SpurGear(21, 4.0, -0.2), SpurGear(57, 10.0, 1.417, internal=True, z0=14, x0=0.04)]


@pytest.mark.parametrize("g", _ODD, ids=["z17", "z21", "ring57"])
def test_odd_tooth_count_M_is_the_chord_between_the_two_most_distant_rollers(g):
    """For odd z the two rollers sit in spaces (z - 1)/2 pitches apart, not opposite: M is the straight distance
    between their centres (a chord of the circle of roller centres d_D, placed here by coordinates) plus D
    (external) or minus D (a ring, between the rollers)."""
    from test_involute import _over_rollers_numeric  # the roller centre radius found on sampled flanks

    D = 1.7362 * g.m if not g.internal else 1.5 * g.m
    sgn = -1.0 if g.internal else 1.0
    R = 0.5 * (_over_rollers_numeric(g, D) - sgn * D)   # roller centre radius (the even-z reading 2R ± D)
    assert 2 * R == pytest.approx(g.d_D(D), abs=1e-6)
    pitch = 2 * math.pi / g.z
    a1, a2 = 0.0, (g.z - 1) / 2 * pitch
    chord = math.hypot(R * math.cos(a1) - R * math.cos(a2), R * math.sin(a1) - R * math.sin(a2))
    assert g.M(D) == pytest.approx(chord + sgn * D, abs=1e-6)
    # and it is shorter than the even-z reading d_D ± D by d_D (1 - cos(pi / 2z)), about d_D pi^2 / 8 z^2
    assert g.d_D(D) + sgn * D - g.M(D) > 0.5 * g.d_D(D) * (math.pi / (2 * g.z)) ** 2 * 0.9


# ---- parts/final_drive/strength.py: the planet is an idler (mutant final_drive-strength-69) -------------------------
def test_planet_passes_the_suns_tangential_force_on_to_the_ring(fd):
    """Moments about the planet's pin: the planet (an idler on a bearing) carries the same tangential force at its
    reference circle in both meshes, so F_t of the planet-ring mesh equals F_t of the sun-planet mesh."""
    from propulsor.parts.final_drive.strength import mesh_stresses

    p, ps = fd
    sp, pr = mesh_stresses(p, ps)
    assert pr.F_t == pytest.approx(sp.F_t, rel=1e-12)
    # and F_t = 2000 T / d with the sun's torque per planet of seed 004 eq. 42 (M_vk Omega / i_sil / n_w)
    T_sun = p.sprocket_torque_Nm * p.load_share_Omega / p.power_ratio_i_sil / p.n_planets
    assert sp.F_t == pytest.approx(2000.0 * T_sun / ps.sun.d, rel=1e-12)


# ---- parts/final_drive/strength.py: the least face width meets the required safeties (final_drive-strength-87) -----
@pytest.mark.parametrize("mesh, changes", [("sun_planet", {}), ("planet_ring", {}),
                                           ("sun_planet", {"x_sun": 0.2, "core_yield_MPa": 300.0})],
                         ids=["sun_planet", "planet_ring", "sun_root_governs"])
def test_required_face_width_puts_the_smallest_safety_on_its_requirement(fd, mesh, changes):
    """At the face width required_face_width returns, the smallest of S_H / S_Hmin and S_F / S_Fm (static, seed 004
    ch. 4.1: sigma_Hmax = 44 HRC, sigma_FlimM = 2.8 sigma_t, root by method B) is 1; a tenth narrower it is below.
    The project's drive is sized by the sun's flank and the ring's root; a sun of shift 0.2 in a softer core steel
    (sigma_t = 300 MPa) by the sun's root (the pinion of the mesh)."""
    import dataclasses

    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses, required_face_width

    p, ps = fd
    if changes:
        p = dataclasses.replace(p, **changes)
        ps = planetary_set(p)
    sHmax, sFlim = 44.0 * p.flank_hardness_HRC, 2.8 * p.core_yield_MPa

    def safeties(b):
        s = mesh_stresses(p, ps, b, b)[0 if mesh == "sun_planet" else 1]
        roots = [x for x in (s.sigma_F1_B, s.sigma_F2_B) if x is not None]
        return [sHmax / s.sigma_H / p.contact_safety_S_Hmin] + [sFlim / x / p.bending_safety_S_Fm for x in roots]

    b = required_face_width(p, ps, mesh)
    at = safeties(b)
    assert min(at) == pytest.approx(1.0, abs=1e-5)
    assert min(safeties(0.9 * b)) < 1.0 < min(safeties(1.1 * b))
    if changes:
        assert at.index(min(at)) == 1  # the pinion's (sun's) root is the one on its limit


# ---- checks/motion/sweep2d.py: penetration depth of an overlap (mutant checks-sweep2d-116) -------------------------
def test_penetration_of_two_overlapping_squares_is_the_depth_of_the_corner_inside():
    """Squares A = [0, 10]^2 and B = A moved by (7, 3): the overlap is [7, 10] x [3, 10]; B's corner (7, 3) lies
    3 mm inside A (to A's edge y = 0) and A's corner (10, 10) 3 mm inside B (to B's edge x = 7): the boundary
    penetration is 3 mm, the clearance -3 mm at one of those corners."""
    import numpy as np

    from propulsor.checks.motion import Pose, sweep2d

    sq = [np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0], [0.0, 0.0]])]
    r = sweep2d.sweep_pair(sq, Pose(), sq, [Pose(0.0, (0.0, 0.0), (7.0, 3.0))], max_segment=0.25)
    assert r.overlap_area[0] == pytest.approx(21.0, abs=1e-6)
    assert r.clearance[0] == pytest.approx(-3.0, abs=1e-6)
    corner = tuple(np.round(r.point_a[0], 6))
    assert corner in ((7.0, 3.0), (10.0, 10.0))


# ---- parts/cam_mover/design.py: the two refusal limits of the cam's and the carrier's webs -------------------------
_CAM_FAST = dict(law="quadratic", k0=0.017)  # a fixed law: no design search (a second per plan)


def test_cam_core_refusal_sits_at_half_the_axle_diameter():
    """The working wall must clear the axle bore: H_min - r > axle_diameter / 2 (a radius against a radius).  With
    the return phase brought down to H(pi) = 90 mm, H_min - r = 70 mm: an axle of 139 mm (radius 69.5) is accepted,
    141 mm (radius 70.5) refused naming the wall and the bore (mutant cam_mover-design-124)."""
    from propulsor.errors import InputError
    from propulsor.parts.cam_mover.design import plan
    from propulsor.parts.cam_mover.params import CamMoverParams

    low = dict(_CAM_FAST, return_mode="top", return_top_mm=90.0, cam_bolt_count=0)
    pl = plan(CamMoverParams(**low, axle_diameter_mm=139.0))
    assert pl.H_min - 20.0 == pytest.approx(70.0, abs=1e-6)
    with pytest.raises(InputError, match="axle bore"):
        plan(CamMoverParams(**low, axle_diameter_mm=141.0))


def test_neighbouring_slides_limit_is_the_half_angle_between_legs():
    """Radial slides of half width w/2 + clearance, n of them: the edges of two neighbours meet on their bisector
    (pi/n from each centreline) at the radius rho with rho sin(pi/n) = w/2 + clearance; with the least web the slide
    bottom rho_b = H_min - leg_back - leg_end_gap must keep rho_b sin(pi/n) >= w/2 + clearance + web.  For 8 legs a
    leg 2 mm narrower than the limit width is accepted, 2 mm wider refused (mutant cam_mover-design-188)."""
    from propulsor.errors import InputError
    from propulsor.parts.cam_mover.design import plan
    from propulsor.parts.cam_mover.params import MIN_WEB_MM, CamMoverParams

    p0 = CamMoverParams(**_CAM_FAST, n_legs=8, carrier_bolt_count=0)
    rho_b = plan(p0).H_min - p0.leg_back_mm - p0.leg_end_gap_mm
    w_lim = 2.0 * (rho_b * math.sin(math.pi / 8) - MIN_WEB_MM - p0.slide_clearance_mm)
    plan(CamMoverParams(**_CAM_FAST, n_legs=8, carrier_bolt_count=0, leg_width_mm=w_lim - 2.0))
    with pytest.raises(InputError, match="neighbouring slides meet"):
        plan(CamMoverParams(**_CAM_FAST, n_legs=8, carrier_bolt_count=0, leg_width_mm=w_lim + 2.0))
