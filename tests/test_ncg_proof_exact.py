"""The non-circular pair's full-cycle proof and its checks, number by number (parts/noncircular_pair/pair_proof.py,
proofs.py): the proof of a circular pair built by the non-circular path (its backlash and transmission error known
by hand), the same pair with its law moved (teeth off the law's position: the running position searched) and
mounted too close (jammed), results of given arrays, and the checks' messages in full on stubs.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``noncircular_proof``): nothing is
built at collection or in a module-scoped fixture (a pair built once is kept in a plain dict; every function under
test is called inside its test).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

_PAIR: dict = {}


def _circular():
    """A circular pair built by the non-circular path (a Fourier law with every term zero, k = 2: z 20/40, m 2.5,
    x +-0.5, L = 75 mm, U = 2, backlash 0.16 mm): about 1.7 s once."""
    if "dd" not in _PAIR:
        from propulsor.params import load_params
        from propulsor.parts.noncircular_pair import NoncircularPairParams, pair_design

        kw = dict(law="fourier", driver_turns=2, fourier_cos=[0.0], fourier_sin=[0.0], module_mm=2.5,
                  driven_teeth=40, driver_shift=0.5, face_width_mm=20.0, compare_methods=False)
        p = load_params(NoncircularPairParams, kw)
        _PAIR["p"], _PAIR["dd"] = p, pair_design(p)
    return _PAIR["p"], _PAIR["dd"]


def _m3d_overlap(drv_loops, dvn_loops, L, theta, phi):
    """Overlap area of the driver (axis (L, 0), turned +theta) and the driven wheel (axis 0, turned -phi), both
    placed in the world frame with their points rotated one by one (manifold3d only for the area)."""
    import manifold3d as m3d

    def placed(loops, ang, centre):
        c, s = math.cos(ang), math.sin(ang)
        return [np.column_stack([c * q[:, 0] - s * q[:, 1] + centre, s * q[:, 0] + c * q[:, 1]]) for q in loops]

    a = m3d.CrossSection([np.ascontiguousarray(q) for q in placed(drv_loops, theta, L)], m3d.FillRule.Positive)
    b = m3d.CrossSection([np.ascontiguousarray(q) for q in placed(dvn_loops, -phi, 0.0)], m3d.FillRule.Positive)
    return (a ^ b).area()


# =========================================================================== PairProof of given arrays
def _proof(**kw):
    from propulsor.parts.noncircular_pair.pair_proof import PairProof

    phi = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5])
    base = dict(phi=phi, theta_law=3.0 * phi + 0.25, overlap_law=np.array([0.0, 2e-6, 0.5e-6, 0.0, 3.0, 0.0]),
                offset=np.zeros(6), least_overlap=np.zeros(6),
                phi_drive=phi + np.array([-0.01, -0.02, np.nan, -0.04, -0.03, -0.015]),
                phi_coast=phi + np.array([0.02, 0.01, np.nan, 0.03, 0.05, 0.04]),
                pairs_drive=np.array([1, 2, 7, 2, 3, 1]), pairs_coast=np.array([2, 2, 0, 1, 1, 1]),
                r_ref=np.array([10.0, 20.0, 30.0, 40.0, 50.0, 60.0]), name="mesh")
    base.update(kw)
    return PairProof(**base)


def test_summary_of_a_proof_takes_the_finite_phases_and_counts_overlaps_above_1e_6_mm2():
    pr = _proof()
    te = [-0.01, -0.02, -0.04, -0.03, -0.015]
    bl = [0.03 * 10, 0.03 * 20, 0.07 * 40, 0.08 * 50, 0.055 * 60]
    s = pr.summary()
    assert s == pytest.approx({"steps": 6, "overlap_law_max_mm2": 3.0, "overlap_law_steps": 2,
                               "te_min_rad": -0.04, "te_max_rad": -0.01, "te_pp_rad": 0.03,
                               "backlash_min_mm": 0.3, "backlash_max_mm": 4.0, "contact_pairs_min": 1,
                               "contact_pairs_mean": (1 + 2 + 2 + 3 + 1) / 5, "jams": 1}, rel=1e-12, abs=1e-15)
    assert min(bl) == pytest.approx(0.3) and max(bl) == pytest.approx(4.0) and np.ptp(te) == pytest.approx(0.03)
    assert [type(s[k]) for k in ("steps", "overlap_law_steps", "contact_pairs_min", "jams")] == [int] * 4
    assert all(type(s[k]) is float for k in s if k not in ("steps", "overlap_law_steps", "contact_pairs_min", "jams"))


def test_summary_of_a_proof_without_a_free_phase_is_nan_and_no_pairs():
    nan = np.full(6, np.nan)
    s = _proof(phi_drive=nan, phi_coast=nan).summary()
    assert s["steps"] == 6 and s["jams"] == 6 and s["contact_pairs_min"] == 0 and type(s["contact_pairs_min"]) is int
    for k in ("te_min_rad", "te_max_rad", "te_pp_rad", "backlash_min_mm", "backlash_max_mm", "contact_pairs_mean"):
        assert math.isnan(s[k]), k


def test_theta_actual_interpolates_the_running_pairs_periodically_over_the_turn():
    """theta_law = 3 phi + 0.25 over [0, 2.5] (n = round(7.5 / 2.5) = 3 driver turns a turn); the running position
    phi_run = phi + te (te = -0.01 .. -0.04; the jammed phase at phi + offset): the teeth put the driven wheel at phi
    where the driver is at 3 (phi - te(phi)) + 0.25, te linear between the running positions and carried over
    the turn's end by theta(phi + 2 pi) = theta(phi) + 6 pi."""
    offset = np.array([0.0, 0.0, -0.025, 0.0, 0.0, 0.0])
    lag = np.array([0.01, -0.02, np.nan, -0.04, -0.03, -0.015])
    pr = _proof(offset=offset, phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]) + lag)
    x = pr.phi + np.array([0.01, -0.02, -0.025, -0.04, -0.03, -0.015])
    y = 3.0 * pr.phi + 0.25
    got = pr.theta_actual()
    # by hand: the piece of the chain (x_k, y_k) -> (x_k+1, y_k+1) holding phi; at phi = 0 (below its own running
    # position 0.01) the piece from the last pair carried back by one turn (x_5 - 2 pi, y_5 - 6 pi) to (x_0, y_0)
    xs = np.concatenate([[x[-1] - 2 * math.pi], x, [x[0] + 2 * math.pi]])
    ys = np.concatenate([[y[-1] - 6 * math.pi], y, [y[0] + 6 * math.pi]])
    for k, ph in enumerate(pr.phi):
        j = int(np.searchsorted(xs, ph)) - 1
        t = (ph - xs[j]) / (xs[j + 1] - xs[j])
        assert got[k] == pytest.approx(ys[j] + t * (ys[j + 1] - ys[j]), abs=1e-12)
    assert got[0] == pytest.approx(y[0] - 0.01 * (y[0] - (y[-1] - 6 * math.pi)) / (x[0] - (x[-1] - 2 * math.pi)),
                                   abs=1e-12)
    assert got[5] == pytest.approx(y[5] + 0.015 * (y[0] + 6 * math.pi - y[5]) / (x[0] + 2 * math.pi - x[5]), abs=1e-12)


def test_theta_actual_of_a_two_turn_law_on_half_a_turn_of_samples():
    """n = round((theta_N - theta_0) / (phi_N - phi_0)): 2 for theta = 2 phi sampled over [0, pi); the periodic
    copies are 2 pi and 4 pi away (a linear law: theta_actual = 2 (phi - c) for a constant lag c)."""
    phi = np.linspace(0.0, 2 * math.pi, 9)[:-1]
    c = 0.05
    n = len(phi)
    pr = _proof(phi=phi, theta_law=2.0 * phi, overlap_law=np.zeros(n), offset=np.zeros(n), least_overlap=np.zeros(n),
                phi_drive=phi + c, phi_coast=phi + 2 * c, pairs_drive=np.ones(n, int), pairs_coast=np.ones(n, int),
                r_ref=np.ones(n))
    assert pr.theta_actual() == pytest.approx(2.0 * (phi - c), abs=1e-12)


def test_ratio_actual_is_the_slope_between_consecutive_running_positions_where_they_advance():
    phi = np.array([0.0, 0.1, 0.2, 0.3, 0.4])
    lag = np.array([0.0, 0.02, 0.15, 0.15, 0.1])  # running 0, 0.12, 0.35, 0.45, 0.5
    theta = np.array([0.0, 0.3, 0.5, 0.9, 1.0])
    pr = _proof(phi=phi, theta_law=theta, overlap_law=np.zeros(5), offset=np.zeros(5), least_overlap=np.zeros(5),
                phi_drive=phi + lag, phi_coast=phi + lag, pairs_drive=np.ones(5, int), pairs_coast=np.ones(5, int),
                r_ref=np.ones(5))
    x, r = pr.ratio_actual()
    assert x == pytest.approx([0.06, 0.235, 0.4, 0.475])
    assert r == pytest.approx([0.3 / 0.12, 0.2 / 0.23, 0.4 / 0.1, 0.1 / 0.05])
    # a running position that goes back (or stands) gives no ratio
    lag2 = np.array([0.0, -0.15, 0.0, 0.0, 0.0])  # running 0, -0.05, 0.2, 0.3, 0.4
    pr2 = _proof(phi=phi, theta_law=theta, overlap_law=np.zeros(5), offset=np.zeros(5), least_overlap=np.zeros(5),
                 phi_drive=phi + lag2, phi_coast=phi, pairs_drive=np.ones(5, int), pairs_coast=np.ones(5, int),
                 r_ref=np.ones(5))
    x2, r2 = pr2.ratio_actual()
    assert x2 == pytest.approx([0.075, 0.25, 0.35]) and r2 == pytest.approx([0.2 / 0.25, 0.4 / 0.1, 0.1 / 0.1])
    pr3 = _proof(phi=phi, theta_law=theta, overlap_law=np.zeros(5), offset=np.zeros(5), least_overlap=np.zeros(5),
                 phi_drive=np.array([0.0, 0.0, 0.2, 0.3, 0.4]), phi_coast=phi, pairs_drive=np.ones(5, int),
                 pairs_coast=np.ones(5, int), r_ref=np.ones(5))
    x3, _ = pr3.ratio_actual()
    assert x3 == pytest.approx([0.1, 0.25, 0.35])


def test_axis_annulus_and_outer_loop_of_a_profile():
    from propulsor.checks.motion import outline
    from propulsor.geometry.profile import Profile
    from propulsor.parts.noncircular_pair.pair_proof import _axis_annulus, _outer_only
    from propulsor import policy

    sq = np.array([[1.0, 2.0], [4.0, 2.0], [4.0, 3.0], [1.0, 3.0]])
    o = outline([sq])
    _axis_annulus(o)
    assert o.center.tolist() == [0.0, 0.0] and type(o.r_min) is float and type(o.radius) is float
    assert o.r_min == pytest.approx(math.sqrt(1 + 4)) and o.radius == pytest.approx(5.0)
    loops = [sq]
    assert _outer_only(loops) is loops
    _, dd = _circular()
    prof = dd.d.driver.profile
    bored = dd.profiles[0]
    assert isinstance(bored, Profile) and len(bored.holes) == 1
    out = _outer_only(bored)
    assert len(out) == 1 and np.array_equal(out[0], bored.outer.polyline(policy.MOTION_CHORD_TOL_MM))
    assert not np.array_equal(out[0], bored.outer.polyline(10 * policy.MOTION_CHORD_TOL_MM))
    assert _outer_only(prof)[0].shape == out[0].shape


# =========================================================================== prove_pair
def _by_sweep(d, L, theta_of_phi, phis, r_ref):
    """The transmission sweep of the whole (uncropped) outer loops of both wheels."""
    from propulsor import policy
    from propulsor.checks.motion import outline, transmission_sweep

    drv = outline([d.driver.profile.outer.polyline(policy.MOTION_CHORD_TOL_MM)])
    dvn = outline([d.driven.profile.outer.polyline(policy.MOTION_CHORD_TOL_MM)])
    return transmission_sweep(drv, (L, 0.0), dvn, (0.0, 0.0), theta_of_phi, phis, r_ref=r_ref)


def test_proof_of_a_circular_pair_is_its_backlash_and_half_of_it_as_transmission_error():
    """Conjugate involute teeth thinned by j_n / (2 cos alpha) each: at every phase the loaded flanks touch with the
    driven wheel j_t / (2 r) behind the law (j_t = j_n / cos alpha = 0.17027 mm on r = 50 mm), the other flanks
    j_t / r later; one or two pairs in contact; the same as the sweep of the whole outlines; ticks at each
    window's last phase."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    p, dd = _circular()
    d = dd.d
    pitch = 2 * math.pi / 40
    phis = np.arange(8) * (pitch / 4) + 0.01
    r_of = lambda ph: np.full(np.shape(ph), 50.0)
    ticks = []
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, d.run_law.theta, phis, r_of, name="gears",
                    pitch_mm=math.pi * 2.5, windows=3, tick=ticks.append)
    jt = 0.16 / math.cos(math.radians(20.0))
    assert pr.name == "gears" and np.array_equal(pr.phi, phis) and pr.r_ref.tolist() == [50.0] * 8
    assert pr.theta_law == pytest.approx(2 * phis, abs=1e-12)
    assert pr.overlap_law.tolist() == [0.0] * 8 and pr.offset.tolist() == [0.0] * 8
    assert pr.least_overlap.tolist() == [0.0] * 8
    assert pr.backlash_mm == pytest.approx(np.full(8, jt), abs=2e-4)
    assert pr.te_drive == pytest.approx(np.full(8, -jt / 100.0), abs=3e-6)
    ref = _by_sweep(d, 75.0, d.run_law.theta, phis, r_of(phis))
    assert pr.phi_drive == pytest.approx(phis - ref.free_back, abs=1e-9)
    assert pr.phi_coast == pytest.approx(phis + ref.free_fwd, abs=1e-9)
    assert pr.pairs_drive.tolist() == ref.pairs_drive.tolist() and pr.pairs_coast.tolist() == ref.pairs_coast.tolist()
    assert set(pr.pairs_drive.tolist()) == {1, 2} and pr.jams == 0
    # three windows of 7/3 quarter pitches over 0.01 .. 0.01 + 7 pitch / 4: phases 0-2, 3-4, 5-7
    assert ticks == [3, 5, 8]
    pr1 = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, d.run_law.theta, phis[:2], r_of)
    assert pr1.name == "mesh" and pr1.pairs_drive.tolist() == ref.pairs_drive[:2].tolist()


def test_proof_over_a_whole_turn_in_its_default_windows_of_a_tenth_of_a_radian():
    """Phases all round the driven turn (every 9 deg): each is proved (a window of 0.1 rad holds at most one) and
    the default 63 windows tick at the last phase of each one that holds a phase."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    phis = np.radians(np.arange(0.0, 360.0, 9.0)) + 0.003
    ticks = []
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, d.run_law.theta, phis, lambda ph: 50.0 + 0 * ph,
                    tick=ticks.append)
    jt = 0.16 / math.cos(math.radians(20.0))
    assert ticks == list(range(1, 41))
    assert pr.jams == 0 and pr.backlash_mm == pytest.approx(np.full(40, jt), abs=2e-4)
    ref = _by_sweep(d, 75.0, d.run_law.theta, phis, np.full(40, 50.0))
    assert pr.phi_drive == pytest.approx(phis - ref.free_back, abs=1e-9)
    assert pr.pairs_drive.tolist() == ref.pairs_drive.tolist()


def test_proof_of_teeth_off_the_laws_position_runs_from_the_free_position_nearest_the_law():
    """The driver 0.02 rad ahead of the law: the teeth overlap at the law's position; the running position is the
    driven wheel 0.02 / U = 0.01 rad further on (U = 2), where the loaded flanks touch with the same backlash as at
    the law's position of the law moved with it."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    pitch = 2 * math.pi / 40
    phis = np.arange(6) * (pitch / 3) + 0.02
    moved = lambda ph: d.run_law.theta(ph) + 0.02
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, lambda ph: 50.0 + 0 * ph,
                    pitch_mm=math.pi * 2.5, windows=2)
    jt = 0.16 / math.cos(math.radians(20.0))
    for k, ph in enumerate(phis):
        assert pr.overlap_law[k] == pytest.approx(_m3d_overlap(d.driver.profile.outer.polyline(1e-4)[None],
                                                               d.driven.profile.outer.polyline(1e-4)[None],
                                                               75.0, float(moved(ph)), float(ph)), rel=1e-3)
    assert np.all(pr.overlap_law > 1.0) and pr.least_overlap.tolist() == [0.0] * 6 and pr.jams == 0
    # the offset lies in the free interval: loaded flanks at 0.01 - j_t / (2 r), the other at 0.01 + j_t / (2 r)
    assert np.all(pr.offset > 0.01 - jt / 100) and np.all(pr.offset < 0.01 + jt / 100)
    assert pr.te_drive == pytest.approx(np.full(6, 0.01 - jt / 100), abs=5e-6)
    assert pr.backlash_mm == pytest.approx(np.full(6, jt), abs=3e-4)
    # from the running position the free rotations of the whole outlines (the driver at the moved law)
    run = phis + pr.offset
    at = {float(q): float(moved(ph)) for q, ph in zip(run, phis)}
    ref = _by_sweep(d, 75.0, lambda q: at[float(q)], run, np.full(6, 50.0))
    assert pr.phi_drive == pytest.approx(run - ref.free_back, abs=1e-9)
    assert pr.phi_coast == pytest.approx(run + ref.free_fwd, abs=1e-9)
    assert pr.pairs_drive.tolist() == ref.pairs_drive.tolist() and pr.pairs_coast.tolist() == ref.pairs_coast.tolist()
    assert pr.phi_run == pytest.approx(pr.phi_drive)


def test_proof_of_a_pair_mounted_too_close_is_jammed_at_every_phase_with_its_least_overlap():
    """At L - 4 mm no position of the driven wheel within half a pitch is free: every phase is a jam, its least
    overlap the least over a scan of the driven wheel's position (0.5 pi m / r_min either side of the law's)."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    phis = np.array([0.0, 0.05])
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 71.0, d.run_law.theta, phis, lambda ph: 50.0 + 0 * ph,
                    pitch_mm=math.pi * 2.5, windows=1)
    assert pr.jams == 2 and np.all(np.isnan(pr.phi_drive)) and np.all(np.isnan(pr.phi_coast))
    assert pr.pairs_drive.tolist() == [0, 0]
    drv = d.driver.profile.outer.polyline(1e-4)[None]
    dvn = d.driven.profile.outer.polyline(1e-4)[None]
    half = 0.5 * math.pi * 2.5 / 50.0
    for k, ph in enumerate(phis):
        th = float(d.run_law.theta(ph))
        scan = [_m3d_overlap(drv, dvn, 71.0, th, ph + o) for o in np.linspace(-half, half, 61)]
        assert pr.least_overlap[k] <= min(scan) + 0.05 and pr.least_overlap[k] > 10.0
        assert pr.least_overlap[k] == pytest.approx(_m3d_overlap(drv, dvn, 71.0, th, ph + pr.offset[k]), rel=1e-3)
        assert abs(pr.offset[k]) <= half
        assert pr.overlap_law[k] == pytest.approx(_m3d_overlap(drv, dvn, 71.0, th, ph), rel=1e-3)
    assert pr.phi_run == pytest.approx(phis + pr.offset)


def test_least_overlap_search_finds_the_free_interval_and_otherwise_the_least_overlap():
    """``_least_overlap`` directly: from a start inside the free interval the start itself (area 0); from a start
    0.6 half-span away a free offset found by the 13-point scan; warm from a start near the free interval the
    Brent search's point; on a jammed mount the least area of the scan refined."""
    from propulsor.checks.motion import outline
    from propulsor.parts.noncircular_pair.pair_proof import _least_overlap, _overlap_at

    _, dd = _circular()
    d = dd.d
    drv = outline([d.driver.profile.outer.polyline(1e-4)])
    dvn = outline([d.driven.profile.outer.polyline(1e-4)])
    th = 0.02
    loops_d, loops_n = drv.loops, dvn.loops
    # _overlap_at against the placement written out
    for o in (0.0, 0.004, 0.01):
        assert _overlap_at(drv, dvn, 75.0, th, o) == pytest.approx(_m3d_overlap(loops_d, loops_n, 75.0, th, o),
                                                                    rel=1e-6, abs=1e-9)
    jt = 0.16 / math.cos(math.radians(20.0))
    lo, hi = 0.01 - jt / 100, 0.01 + jt / 100  # the free interval of the driven wheel
    half = 0.5 * math.pi * 2.5 / 50
    off, area = _least_overlap(drv, dvn, 75.0, 0.0, th, 0.01, half, False)
    assert area == 0.0 and lo < off < hi
    assert off == pytest.approx(0.01, abs=1e-12)  # the scan's middle point
    off, area = _least_overlap(drv, dvn, 75.0, 0.0, th, 0.01 + 0.6 * half, half, False)
    assert area == 0.0 and lo < off < hi
    # the grid point 0.01 + 0.6 half - 7 half / 6 = 0.01 - 0.5667 half lies outside: the free point found is
    # one of the scan's points or a Brent point
    grid = 0.01 + 0.6 * half + np.linspace(-half, half, 13)
    off, area = _least_overlap(drv, dvn, 75.0, 0.0, th, 0.0095, half, True)
    assert area <= 1e-6 and lo < off < hi
    # warm start far from the free interval: the Brent search ends on its bracket, so the scan runs
    off, area = _least_overlap(drv, dvn, 75.0, 0.0, th, 0.01 - 0.9 * half, half, True)
    assert area <= 1e-6 and lo < off < hi
    # jammed (L = 71): the least area over the scan and its refinement, not more than the scan's least
    scan = np.array([_overlap_at(drv, dvn, 71.0, th, o) for o in np.linspace(-half, half, 13)])
    off, area = _least_overlap(drv, dvn, 71.0, 0.0, th, 0.0, half, False)
    assert area > 10.0 and area <= scan.min() and area == pytest.approx(_overlap_at(drv, dvn, 71.0, th, off))
    i = int(np.argmin(scan))
    g = np.linspace(-half, half, 13)
    assert g[max(i - 1, 0)] <= off <= g[min(i + 1, 12)]
    fine = min(_overlap_at(drv, dvn, 71.0, th, o) for o in np.linspace(g[max(i - 1, 0)], g[min(i + 1, 12)], 41))
    assert area <= fine + 1e-3
