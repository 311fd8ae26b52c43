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


def _circular_outlines():
    """The circular pair's design, its outer outlines (driver, driven), their largest radii and the least-overlap
    search's half span (half a pitch at the driven pitch radius)."""
    from propulsor.checks.motion import outline

    _, dd = _circular()
    d = dd.d
    drv = outline([d.driver.profile.outer.polyline(1e-4)])
    dvn = outline([d.driven.profile.outer.polyline(1e-4)])
    reach = float(np.linalg.norm(drv.points, axis=1).max())
    r_dvn = float(np.linalg.norm(dvn.points, axis=1).max())
    return dd, drv, dvn, reach, r_dvn, 0.5 * math.pi * 2.5 / 50


def _n_vertices(cs) -> int:
    return sum(len(q) for q in cs.to_polygons())


# =========================================================================== PairProof of given arrays
def _proof(**kw):
    from propulsor.parts.noncircular_pair.pair_proof import PairProof

    phi = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5])
    base = dict(phi=phi, theta_law=3.0 * phi + 0.25, overlap_law=np.array([0.0, 2e-6, 1e-6, 0.0, 3.0, 0.0]),
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
    import warnings

    nan = np.full(6, np.nan)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no mean of an empty slice
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


def test_theta_actual_counts_the_driver_turns_from_the_laws_rise_over_the_sampled_span():
    """Samples from phi = 1 over 7/8 of a turn of a law theta = 2 phi + 1.5 (n = round(2 x 5.50 / 5.50) = 2, not
    the ratio of the sums): theta_actual = 2 (phi - c) + 1.5 for a constant lag c."""
    phi = 1.0 + np.arange(8) * (2 * math.pi / 8)
    c = 0.04
    n = len(phi)
    pr = _proof(phi=phi, theta_law=2.0 * phi + 1.5, overlap_law=np.zeros(n), offset=np.zeros(n),
                least_overlap=np.zeros(n), phi_drive=phi + c, phi_coast=phi + 2 * c, pairs_drive=np.ones(n, int),
                pairs_coast=np.ones(n, int), r_ref=np.ones(n))
    assert pr.theta_actual() == pytest.approx(2.0 * (phi - c) + 1.5, abs=1e-12)


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
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a standing position is left out, not divided by (numpy's warning an error)
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
                    pitch_mm=math.pi * 2.5, windows=3, tick=ticks.append, on_jam=lambda: ticks.append("jam"))
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


def test_proof_over_a_whole_turn_in_its_default_windows_the_same_in_any_windows():
    """Phases all round the driven turn (every 9 deg): each is proved, the default 16 windows (policy
    PAIR_PROOF_WINDOW_RAD, 0.4 rad: two or three phases each) tick at the last phase of each, and the proof is the
    same to the bit in 63 windows of a tenth of a radian (at most one phase each) or in one window."""
    from propulsor import policy
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    phis = np.radians(np.arange(0.0, 360.0, 9.0)) + 0.003
    ticks = []
    args = (dd.profiles[0], dd.profiles[1], 75.0, d.run_law.theta, phis, lambda ph: 50.0 + 0 * ph)
    pr = prove_pair(*args, tick=ticks.append)
    jt = 0.16 / math.cos(math.radians(20.0))
    assert policy.PAIR_PROOF_WINDOW_RAD == 0.4
    # 16 windows over the phases' span 351 deg: 21.94 deg each, the last phase of each at 18, 36, 63, 81, ...
    # (the last window holds its end)
    last = [int(np.nonzero(np.degrees(phis - phis[0]) < 351.0 / 16 * (k + 1) + (k == 15))[0].max()) + 1
            for k in range(16)]
    assert len(set(last)) == 16 and ticks == last and ticks[:4] == [3, 5, 8, 10] and ticks[-1] == 40
    assert pr.jams == 0 and pr.backlash_mm == pytest.approx(np.full(40, jt), abs=2e-4)
    ref = _by_sweep(d, 75.0, d.run_law.theta, phis, np.full(40, 50.0))
    assert pr.phi_drive == pytest.approx(phis - ref.free_back, abs=1e-9)
    assert pr.pairs_drive.tolist() == ref.pairs_drive.tolist()
    for windows in (63, 1):
        other = prove_pair(*args, windows=windows)
        for name, value in vars(pr).items():
            if isinstance(value, np.ndarray):
                assert np.array_equal(value, getattr(other, name), equal_nan=True), (windows, name)


def _turn_phases(n: int) -> np.ndarray:
    return np.arange(n) * (2 * math.pi / n)


def test_a_pair_that_repeats_is_proved_over_one_period_each_later_phase_its_like_turned():
    """The circular pair (k = 2: the law's periods 2; its driven wheel cut as two lobes, the second the first turned
    by pi, its driver one lobe turning a whole turn a period): 160 phases over the turn, the first 80 measured (the
    outlines repeat to rounding, 3.6e-14 mm), each later phase the first period's like: its overlaps, offsets and
    tooth pairs the same, its driven angles moved by the phases' own difference, so its transmission error and
    backlash those of its like to rounding.  Measured whole (``periods`` 1), every phase agrees to 1e-13 rad and the
    first period is the same to the bit."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    phis = _turn_phases(160)
    r_of = lambda ph: 50.0 + 0 * ph
    ticks = []
    args = (dd.profiles[0], dd.profiles[1], 75.0, d.run_law.theta, phis, r_of)
    pr = prove_pair(*args, pitch_mm=math.pi * 2.5, periods=2, tick=ticks.append)
    whole = prove_pair(*args, pitch_mm=math.pi * 2.5)
    assert (pr.measured, whole.measured, len(pr.phi)) == (80, 160, 160)
    assert pr.cyclic_mm < 1e-12 and whole.cyclic_mm == math.inf
    assert pr.measured_text() == ("the first period's 80 measured, each later one its like there turned: both "
                                  f"outlines repeat under a period's turns to {pr.cyclic_mm:.1e} mm")
    assert whole.measured_text() == "each measured"
    assert ticks[-1] == 160 and ticks[-2] == 80  # the first period's windows, then the turn told done
    for name in ("phi", "theta_law", "overlap_law", "offset", "least_overlap", "pairs_drive", "pairs_coast",
                 "r_ref"):
        assert np.array_equal(getattr(pr, name), getattr(whole, name)), name
    for name in ("phi_drive", "phi_coast"):
        a, b = getattr(pr, name), getattr(whole, name)
        assert np.array_equal(a[:80], b[:80]) and np.max(np.abs(a - b)) < 1e-13, name
        assert not np.array_equal(a[80:], b[80:])  # measured, not the same floats: rounding apart
    assert np.max(np.abs(pr.te_drive[80:] - pr.te_drive[:80])) < 1e-14
    assert pr.summary()["steps"] == 160 and pr.summary()["jams"] == 0
    # through prove(): generated teeth over the whole turn ask for the law's periods
    from propulsor.parts.noncircular_pair.proofs import prove

    assert prove(d, 4, 4).measured == 80 and prove(d, 4, 2).measured == 80  # half a turn: measured whole


def test_cyclic_mismatch_turns_each_outline_by_a_period_and_refuses_a_law_or_phases_that_do_not_repeat():
    """The circular pair's outlines repeat to rounding under a period's turns (the driven wheel by pi, the driver by
    the law's 2 pi); a driven vertex moved 2e-9 mm along its radius is that far off (above the policy's 1e-9 mm: the
    pair is then measured whole), a driver vertex where the driver turns half a turn a period (the law halved); a law that does not repeat (theta 1e-8 rad off at one
    later phase), uneven phases, periods that do not divide the phases or an outline of two loops: inf."""
    from propulsor import policy
    from propulsor.checks.motion import outline
    from propulsor.parts.noncircular_pair.pair_proof import _outer_only, cyclic_mismatch, prove_pair

    _, dd = _circular()
    d = dd.d
    drv_loop = _outer_only(d.driver.profile)[0]
    dvn_loop = _outer_only(d.driven.profile)[0]
    drv, dvn = outline([drv_loop]), outline([dvn_loop])
    phis = _turn_phases(160)
    theta = d.run_law.theta(phis)
    assert policy.CYCLIC_TOL_MM == 1e-9
    assert cyclic_mismatch(drv, dvn, phis, theta, 80) < 1e-12
    k = len(dvn_loop) // 3

    def moved(loop, k, by):
        q = loop.copy()
        q[k] *= 1.0 + by / float(np.hypot(*q[k]))
        return q

    off = cyclic_mismatch(drv, outline([moved(dvn_loop, k, 2e-9)]), phis, theta, 80)
    assert 1.9e-9 < off < 2.1e-9
    # the driver turns a whole turn a period: any driver repeats; turning half a turn (the law halved) its 20 involute
    # teeth repeat to rounding, a vertex moved does not
    assert cyclic_mismatch(outline([moved(drv_loop, 7, 2e-9)]), dvn, phis, theta, 80) < 1e-12
    assert cyclic_mismatch(drv, dvn, phis, 0.5 * theta, 80) < 1e-12
    off = cyclic_mismatch(outline([moved(drv_loop, 7, 2e-9)]), dvn, phis, 0.5 * theta, 80)
    assert 1.9e-9 < off < 2.1e-9
    bent = theta.copy()
    bent[123] += 1e-8
    assert cyclic_mismatch(drv, dvn, phis, bent, 80) == math.inf
    uneven = phis.copy()
    uneven[37] += 1e-8
    assert cyclic_mismatch(drv, dvn, uneven, theta, 80) == math.inf
    assert cyclic_mismatch(drv, dvn, phis[:150], theta[:150], 80) == math.inf
    assert cyclic_mismatch(drv, dvn, phis, theta, 0) == math.inf
    two = outline([dvn_loop, 0.2 * dvn_loop[::-1]])
    assert cyclic_mismatch(drv, two, phis, theta, 80) == math.inf
    # the pair with that driven vertex moved is measured whole
    pr = prove_pair([drv_loop], [moved(dvn_loop, k, 2e-9)], 75.0, d.run_law.theta, _turn_phases(40),
                    lambda ph: 50.0 + 0 * ph, pitch_mm=math.pi * 2.5, periods=2)
    assert pr.measured == 40 and pr.cyclic_mm == math.inf


def test_an_outline_of_five_lobes_turned_by_a_fifth_and_phases_that_do_not_start_at_zero():
    """A chiral outline of five equal lobes (500 vertices): turned by a fifth of a turn either way every vertex lands
    on the one 100 on (to rounding); turned 1e-7 rad more, each misses by its radius times that; turned by half a turn
    it does not repeat.  As both wheels of a pair whose phases start at 0.01 rad (the driver two turns a driven one,
    theta starting at 0.3): it repeats every 10 of 50 phases; with the driver of two loops, inf."""
    from propulsor.checks.motion import outline
    from propulsor.parts.noncircular_pair.pair_proof import _turned_onto, cyclic_mismatch

    t = np.linspace(0.0, 2 * math.pi, 500, endpoint=False)
    r = 10.0 + np.cos(5 * t) + 0.3 * np.sin(10 * t + 0.4)
    P = np.column_stack([r * np.cos(t), r * np.sin(t)])
    assert _turned_onto(P, 2 * math.pi / 5) < 1e-12 and _turned_onto(P, -2 * math.pi / 5) < 1e-12
    assert 0.8e-6 < _turned_onto(P, 2 * math.pi / 5 + 1e-7) < 1.2e-6
    assert _turned_onto(P, math.pi) > 0.1
    assert _turned_onto(np.zeros((0, 2)), 1.0) == math.inf
    body = outline([P])
    phis = 0.01 + np.arange(50) * (2 * math.pi / 50)
    theta = 2.0 * phis + 0.3
    assert cyclic_mismatch(body, body, phis, theta, 10) < 1e-12
    assert cyclic_mismatch(outline([P, 0.3 * P[::-1]]), body, phis, theta, 10) == math.inf


def test_a_repeating_pair_whose_phases_need_the_running_position_search_is_measured_whole():
    """The circular pair with its law moved ahead (the teeth overlap at the law's position at every phase: the running
    position searched, each search starting from the last phase's offset): it repeats, but its phases are not
    independent, so every phase of the turn is measured, the same as without ``periods``."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    half = 0.5 * math.pi * 2.5 / 50
    g = float(np.linspace(-half, half, 13)[7])
    moved = lambda ph: d.run_law.theta(ph) + 2 * g
    args = (dd.profiles[0], dd.profiles[1], 75.0, moved, _turn_phases(40), lambda ph: 50.0 + 0 * ph)
    ticks = []
    pr = prove_pair(*args, pitch_mm=math.pi * 2.5, periods=2, tick=ticks.append)
    assert np.all(pr.overlap_law > 1.0) and pr.jams == 0
    assert pr.measured == 40 and pr.cyclic_mm == math.inf
    # the first period's windows told, then the whole turn's past them: the progress never goes back
    assert ticks == sorted(set(ticks)) and ticks[-1] == 40 and 20 in ticks
    whole = prove_pair(*args, pitch_mm=math.pi * 2.5)
    for name, value in vars(pr).items():
        if isinstance(value, np.ndarray):
            assert np.array_equal(value, getattr(whole, name), equal_nan=True), name


def test_proof_of_teeth_off_the_laws_position_runs_from_the_free_position_nearest_the_law():
    """The driver 2 g ahead of the law (g = 7/12 of the scan's span from its start, 0.0131 rad): the teeth overlap at
    the law's position; the running position is the driven wheel g further on (U = 2), where the loaded flanks touch
    with the same backlash as at the law's position of the law moved with it.  The first phase is searched cold:
    the 13-point scan from the law's position meets g itself (area 0); each next one starts warm from the last
    offset with a Brent search, whose free point is not that start."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    pitch = 2 * math.pi / 40
    half = 0.5 * math.pi * 2.5 / 50
    g = float(np.linspace(-half, half, 13)[7])
    phis = np.arange(6) * (pitch / 3) + 0.02
    moved = lambda ph: d.run_law.theta(ph) + 2 * g
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, lambda ph: 50.0 + 0 * ph,
                    pitch_mm=math.pi * 2.5, windows=2)
    jt = 0.16 / math.cos(math.radians(20.0))
    for k, ph in enumerate(phis):
        assert pr.overlap_law[k] == pytest.approx(_m3d_overlap(d.driver.profile.outer.polyline(1e-4)[None],
                                                               d.driven.profile.outer.polyline(1e-4)[None],
                                                               75.0, float(moved(ph)), float(ph)), rel=1e-3)
    assert np.all(pr.overlap_law > 1.0) and pr.least_overlap.tolist() == [0.0] * 6 and pr.jams == 0
    # the offset lies in the free interval: loaded flanks at g - j_t / (2 r), the other at g + j_t / (2 r)
    assert np.all(pr.offset > g - jt / 100) and np.all(pr.offset < g + jt / 100)
    assert pr.offset[0] == g and np.all(np.abs(np.diff(pr.offset)) > 1e-9)
    assert pr.te_drive == pytest.approx(np.full(6, g - jt / 100), abs=5e-6)
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
    events = []
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 71.0, d.run_law.theta, phis, lambda ph: 50.0 + 0 * ph,
                    pitch_mm=math.pi * 2.5, windows=2, tick=events.append, on_jam=lambda: events.append("jam"))
    assert events == ["jam", 1, 2]  # told once, at the first jammed phase (before its window ends), not at each
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


def test_lens_and_meet_cuts_give_each_overlap_of_the_whole_bodies_to_the_last_bit_and_are_kept_while_they_hold():
    """``_LensCrops``: the driver cut to the disc about the driven axis, the driven wheel to the disc about the
    driver axis's positions over the offsets searched; ``_MeetCrops``: each cut to the sector about its own axis that
    holds where the two bodies' polar envelopes meet over those offsets.  Jammed (L = 71 mm) and with the driver ahead
    of the law (L = 75 mm, 2 degrees), over phases a fortieth of a pitch apart: the overlap of either's cuts equals that
    of the whole outlines exactly at every offset of the search span (its scan and random points), the discs' cuts
    hold fewer vertices than the bodies and the sectors' fewer than the discs', and a cut is kept over the next phases
    while it holds.  A disc 2 mm short of the driven tip radius loses overlap (the check can fail)."""
    from propulsor.parts.noncircular_pair.pair_proof import _LensCrops, _MeetCrops, _overlap_at

    dd, drv, dvn, reach, r_dvn, half = _circular_outlines()
    d = dd.d
    rng = np.random.default_rng(7)
    pitch = 2 * math.pi / 40
    for L, ahead in ((71.0, 0.0), (75.0, math.radians(2.0))):
        lens = _LensCrops(L, reach + 1.0, r_dvn + 1.0)
        meet = _MeetCrops(drv, dvn, L, reach + 1.0, r_dvn + 1.0)
        cuts, meet_cuts = [], []
        for ph in np.arange(8) * pitch / 40 + 0.3:
            th = float(d.run_law.theta(ph)) + ahead
            start = 0.002
            cd, cn = lens.at(drv, dvn, ph + start, th, half)
            md, mn = meet.at(drv, dvn, ph + start, th, half)
            cuts.append((cd, cn))  # the cuts themselves, held: an id of a cut freed may be reused by the next
            meet_cuts.append((md, mn))
            assert _n_vertices(cd.section) < 0.5 * len(drv.points) and _n_vertices(cn.section) < 0.5 * len(dvn.points)
            assert _n_vertices(md.section) + _n_vertices(mn.section) < _n_vertices(cd.section) + _n_vertices(cn.section)
            offs = np.r_[start + np.linspace(-half, half, 13), start + rng.uniform(-half, half, 6)]
            whole = [_overlap_at(drv, dvn, L, th, ph + o) for o in offs]
            assert max(whole) > 1.0
            assert [_overlap_at(cd, cn, L, th, ph + o) for o in offs] == whole
            assert [_overlap_at(md, mn, L, th, ph + o) for o in offs] == whole
        # each side's cut kept over some phases; a disc's, whose centre moves 0.3-0.6 mm a phase against its 1 mm
        # spare, made afresh at others
        for made, afresh in ((cuts, True), (meet_cuts, False)):
            for side in (0, 1):
                kept = [made[i][side] is made[i - 1][side] for i in range(1, len(made))]
                assert any(kept) and (not all(kept) or not afresh), (L, side, kept)
    short = _LensCrops(71.0, reach + 1.0, r_dvn - 2.0, spare=0.0)
    th = float(d.run_law.theta(0.3))
    cd, cn = short.at(drv, dvn, 0.3, th, half)
    assert _overlap_at(cd, cn, 71.0, th, 0.3) < _overlap_at(drv, dvn, 71.0, th, 0.3) - 1.0


def test_a_polar_envelope_holds_its_body_and_one_widened_holds_it_turned_and_a_sector_cut_its_sector():
    """``PolarEnvelope``: a square of four vertices (edges sweeping 90 degrees each) and a gear lie inside their
    envelopes, and the square turned by less than ``widen`` inside the widened one; ``cut_to_sector`` keeps the whole
    sector it names.  The meet cuts with the driven envelope left unwidened lose overlap at an offset of the span
    (the overlap check above can fail)."""
    import manifold3d as m3d

    from propulsor.checks.motion import PolarEnvelope, cut_to_sector, outline
    from propulsor.parts.noncircular_pair.pair_proof import _MeetCrops, _overlap_at

    square = np.array([[10.0, 0.0], [0.0, 10.0], [-10.0, 0.0], [0.0, -10.0]])
    for widen in (0.0, 0.2):
        env = PolarEnvelope(outline([square]), widen)
        for turn in ((0.0, 0.19, -0.19) if widen else (0.0,)):
            c, s = math.cos(turn), math.sin(turn)
            cs = m3d.CrossSection([np.ascontiguousarray(square @ np.array([[c, s], [-s, c]]))], m3d.FillRule.Positive)
            assert (cs - env.section).area() == 0.0 and cs.area() == pytest.approx(200.0)
    # cut_to_sector keeps the whole sector of the disc (its arc's chords outside the circle): at least its area
    plate = m3d.CrossSection([np.array([[-30.0, -30.0], [30.0, -30.0], [30.0, 30.0], [-30.0, 30.0]])],
                             m3d.FillRule.Positive)
    for a0, a1 in ((0.1, 0.6), (-0.3, 2.0), (2.9, 3.5)):
        cut = cut_to_sector(plate, a0, a1, 20.0)
        assert 0.5 * 400.0 * (a1 - a0) <= cut.area() < 0.5 * 400.0 * (a1 - a0) * 1.001
    dd, drv, dvn, reach, r_dvn, half = _circular_outlines()
    for o in (drv, dvn):
        assert (o.section - PolarEnvelope(o).section).area() == 0.0
    narrow = _MeetCrops(drv, dvn, 71.0, reach + 1.0, r_dvn + 1.0, spare=0.0, spare_rad=0.0)
    narrow.envelopes[half] = PolarEnvelope(dvn)
    th = float(dd.d.run_law.theta(0.3))
    cd, cn = narrow.at(drv, dvn, 0.3, th, half)
    assert any(_overlap_at(cd, cn, 71.0, th, 0.3 + o) < _overlap_at(drv, dvn, 71.0, th, 0.3 + o) - 1e-6
               for o in np.linspace(-half, half, 13))


def test_the_least_overlap_search_on_the_cuts_of_the_span_it_searches_gives_the_whole_outlines_result(monkeypatch):
    """``_least_overlap(..., crops)``: each search takes the cuts for the span it searches (the warm Brent search its
    quarter span, the scan the whole): the same offset and area as on the whole outlines, cold, warm and warm falling
    back to the scan; the quarter span's cut differs from the whole outlines beyond it (a scan taking it would err),
    and every offset a search evaluates is evaluated on the cuts of a span that holds it.  In ``prove_pair`` of a
    jammed mount every search's cuts hold the overlap of its whole span."""
    from propulsor.parts.noncircular_pair import pair_proof
    from propulsor.parts.noncircular_pair.pair_proof import _least_overlap, _MeetCrops, _overlap_at, prove_pair

    dd, drv, dvn, reach, r_dvn, half = _circular_outlines()
    d = dd.d
    th3 = float(d.run_law.theta(0.3))
    for L, ph, th, start, warm in ((71.0, 0.3, th3, 0.002, False), (71.0, 0.3, th3, 0.002, True),
                                   (75.0, 0.0, 0.02, 0.01 - 0.9 * half, True), (75.0, 0.0, 0.02, 0.0095, True)):
        m = _MeetCrops(drv, dvn, L, reach + 1.0, r_dvn + 1.0, spare=0.0, spare_rad=0.0)
        crops = lambda h: m.at(drv, dvn, ph + start, th, h)  # noqa: B023 (used within the loop)
        assert _least_overlap(drv, dvn, L, ph, th, start, half, warm, crops) == \
            _least_overlap(drv, dvn, L, ph, th, start, half, warm)
        if L == 71.0:  # a fresh cut (a held one that holds the quarter span is kept for it)
            cd, cn = _MeetCrops(drv, dvn, L, reach + 1.0, r_dvn + 1.0, spare=0.0, spare_rad=0.0).at(
                drv, dvn, ph + start, th, 0.25 * half)
            offs = start + np.linspace(-half, half, 21)
            assert any(_overlap_at(cd, cn, L, th, ph + o) != _overlap_at(drv, dvn, L, th, ph + o) for o in offs)
    # each offset evaluated on the cuts of a span that holds it
    m = _MeetCrops(drv, dvn, 71.0, reach + 1.0, r_dvn + 1.0, spare=0.0, spare_rad=0.0)
    spans, evaluated = {}, []

    def crops(h):
        cd, cn = m.at(drv, dvn, 0.3 + 0.002, th3, h)
        spans[id(cd)] = max(spans.get(id(cd), 0.0), h)
        return cd, cn

    real_at = pair_proof._overlap_at
    monkeypatch.setattr(pair_proof, "_overlap_at", lambda a, b, L, th, p: evaluated.append((id(a), p - 0.3 - 0.002))
                        or real_at(a, b, L, th, p))
    for warm in (False, True):
        pair_proof._least_overlap(drv, dvn, 71.0, 0.3, th3, 0.002, half, warm, crops)
    assert evaluated and all(abs(o) <= spans[k] + 1e-12 for k, o in evaluated)
    monkeypatch.setattr(pair_proof, "_overlap_at", real_at)
    seen = []
    real = pair_proof._least_overlap

    def checked(drv_, dvn_, L, phi, theta, start, half_, warm, crops=None):
        for h in (half_, 0.25 * half_):
            cd, cn = crops(h)
            for o in start + np.linspace(-h, h, 9):
                assert _overlap_at(cd, cn, L, theta, phi + o) == _overlap_at(drv_, dvn_, L, theta, phi + o)
        seen.append(warm)
        return real(drv_, dvn_, L, phi, theta, start, half_, warm, crops)

    monkeypatch.setattr(pair_proof, "_least_overlap", checked)
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 71.0, d.run_law.theta, np.array([0.0, 0.05]),
                    lambda ph: 50.0 + 0 * ph, pitch_mm=math.pi * 2.5, windows=2)
    assert seen == [False, True] and pr.jams == 2


# =========================================================================== proofs.py
def _record_prove_pair(monkeypatch):
    from propulsor.parts.noncircular_pair import pair_proof

    calls = []

    def fake(drv, dvn, L, theta_of_phi, phis, r_ref, **kw):
        calls.append(SimpleNamespace(drv=drv, dvn=dvn, L=L, theta=theta_of_phi, phis=phis, r_ref=r_ref, **kw))
        return "PROOF"

    monkeypatch.setattr(pair_proof, "prove_pair", fake)
    return calls


def _stub_design(kind="fourier", method="generated", z_H=40, L=75.0):
    """The circular pair's run law (theta = 2 phi, r_H = L U / (1 + U) = 50 mm at L = 75) under a stub design."""
    _, dd = _circular()
    return SimpleNamespace(law=SimpleNamespace(kind=kind, n=2), run_law=dd.d.run_law, L=L, m=2.5, z_H=z_H,
                           method=method, table=SimpleNamespace(arc=7.25),
                           driver=SimpleNamespace(profile="DRV"), driven=SimpleNamespace(profile="DVN"))


def test_prove_samples_phases_per_tooth_over_the_legs_at_the_mount_with_the_tooth_pitch(monkeypatch):
    """N = phases per tooth x z_H x legs / 4 phases, legs x pi/2 / N apart from 0; the driven pitch radius of the run
    law (a circular pair: L U / (1 + U)); the pitch pi m of generated teeth, the sector arc of the papers' teeth;
    the mount given, else the design L; the progress said and counted."""
    from propulsor.parts.noncircular_pair.proofs import prove
    from propulsor.progress import Reporter

    calls = _record_prove_pair(monkeypatch)
    said = []
    d = _stub_design()
    assert prove(d, 5, 4, said.append) == "PROOF"
    c = calls[0]
    assert (c.drv, c.dvn, c.L, c.name, c.pitch_mm) == ("DRV", "DVN", 75.0, "mesh", pytest.approx(math.pi * 2.5))
    assert len(c.phis) == 200 and c.phis == pytest.approx(np.arange(200) * (2 * math.pi / 200), abs=1e-15)
    assert c.periods == 2  # generated teeth over the whole turn: the law's periods (the proof measures one if it can)
    assert c.theta(np.array([0.3, 1.1])) == pytest.approx([0.6, 2.2], abs=1e-12)
    assert c.r_ref(np.array([0.3, 1.1])) == pytest.approx([75.0 * 2 / 3, 50.0], rel=1e-9)
    assert said == ["generated: proof over the whole driven turn, 200 phases"]
    c.tick(7)  # a text callback: the tick says nothing
    said.clear()
    prove(d, 5, progress=said.append)  # four legs unless told
    assert len(calls[-1].phis) == 200 and said == ["generated: proof over the whole driven turn, 200 phases"]
    calls.pop()
    said[:] = ["generated: proof over the whole driven turn, 200 phases"]
    assert said == ["generated: proof over the whole driven turn, 200 phases"]
    said.clear()
    rep = Reporter(said.append)
    prove(_stub_design(method="sectors", z_H=36), 4, 3, rep, 76.5)
    c = calls[1]
    assert c.L == 76.5 and c.pitch_mm == 7.25 and len(c.phis) == 108 and c.periods == 1
    prove(_stub_design(method="sectors", z_H=36), 4, 4)
    assert calls.pop().periods == 1  # the papers' sector teeth: measured whole
    prove(_stub_design(z_H=41), 4, 4)
    assert calls.pop().periods == 1  # a period's arc holding no whole teeth: no period (as_built.period_span)
    assert c.phis == pytest.approx(np.arange(108) * (3 * math.pi / 2 / 108), abs=1e-15)
    assert said == ["sectors: proof over 3/4 of the driven turn, 108 phases",
                    "sectors: proof over 3/4 of the driven turn: phase 0/108"]
    c.tick(108)
    assert said[-1] == "sectors: proof over 3/4 of the driven turn: phase 108/108"
    assert said[-1].done == 108 and said[-1].total == 108
    said.clear()
    prove(_stub_design(kind="walking", z_H=80), 4, 1, said.append)
    assert said == ["generated: proof over 1 leg(s), 80 phases"] and len(calls[2].phis) == 80
    assert calls[2].periods == 1
    assert calls[2].phis[-1] == pytest.approx(79 * (math.pi / 2) / 80)
    said.clear()
    prove(_stub_design(kind="walking", z_H=81), 4, 4, said.append, 0.0)
    assert said == ["generated: proof over 4 leg(s), 324 phases"] and calls[3].L == 75.0
    prove(_stub_design(z_H=30), 4, 3, said.append)  # 4 x 30 x 3 / 4 = 90
    assert len(calls[4].phis) == 90
    prove(_stub_design(z_H=31), 4, 1, said.append)  # 4 x 31 / 4 = 31
    assert len(calls[5].phis) == 31 and said[-1] == "generated: proof over 1/4 of the driven turn, 31 phases"


def test_compare_builds_the_other_method_at_the_same_module_and_proves_one_leg(monkeypatch):
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair import proofs

    p = _part("ncg_seed002", proof_phases_per_tooth=6, module_mm=0.0, center_distance_mm=125.0)
    got = []

    def other(q, prog):
        got.append(q)
        assert prog is say
        return "OTHER"

    proved = []
    monkeypatch.setattr(proofs, "design_sectors", other)
    monkeypatch.setattr(proofs, "design_generated", lambda q, prog: (_ for _ in ()).throw(AssertionError("no")))
    monkeypatch.setattr(proofs, "prove", lambda d, ppt, legs, prog: proved.append((d, ppt, legs, prog)) or "PR")
    walking = SimpleNamespace(kind="walking")
    say = lambda s: None
    d = SimpleNamespace(method="generated", law=walking, m=3.0)
    assert proofs.compare(p, d, say) == ("OTHER", "PR", "")
    q = got[0]
    assert (q.method, q.module_mm, q.center_distance_mm) == ("sectors", 3.0, 0.0)
    assert (q.a_mm, q.driven_teeth, q.driver_turns) == (p.a_mm, p.driven_teeth, p.driver_turns)
    assert proved == [("OTHER", 6, 1, say)]
    monkeypatch.setattr(proofs, "design_generated", other)
    monkeypatch.setattr(proofs, "design_sectors", lambda q, prog: (_ for _ in ()).throw(AssertionError("no")))
    assert proofs.compare(p, SimpleNamespace(method="sectors", law=walking, m=2.0), say) == ("OTHER", "PR", "")
    assert (got[1].method, got[1].module_mm, got[1].center_distance_mm) == ("generated", 2.0, 0.0)
    # refused: the other method's InputError as the note
    monkeypatch.setattr(proofs, "design_generated",
                        lambda q, prog: (_ for _ in ()).throw(InputError("driver_shift", 0.5, "too much", "less")))
    assert proofs.compare(p, SimpleNamespace(method="sectors", law=walking, m=2.0), say) == (
        None, None, "The generated method is not possible for these parameters: driver_shift = 0.5: too much (less)")
    # the module the other method gets is validated: below ISO 54's least
    assert proofs.compare(p, SimpleNamespace(method="sectors", law=walking, m=0.01), say) == (
        None, None, "The generated method is not possible for these parameters: module_mm = 0.01: must be 0 (from "
                    "center_distance_mm) or >= 0.05 mm, the smallest module of ISO 54 / GOST 9563")
    assert proofs.compare(p, SimpleNamespace(method="generated", law=SimpleNamespace(kind="fourier"), m=2.0), say) == (
        None, None, "The sector method exists for the walking law only (this pair's law: fourier).")


def _part(name, **kw):
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams
    from pathlib import Path

    _, mapping = read_part_file(Path(__file__).resolve().parent.parent / "parts" / f"{name}.toml")
    mapping.update(kw)
    return load_params(NoncircularPairParams, mapping)


def _gen_check(curve, concave=False):
    return SimpleNamespace(curve=curve, rho_convex_min=12.345678, rho_limit=10.69, concave=concave,
                           rho_concave_min=-31.25, r0=12.5)


def _gear(role, undercut=0, tip=0.7):
    return SimpleNamespace(role=role, undercut_teeth=undercut, teeth=[None] * (20 if role == "driver" else 80),
                           tip_thickness_min=tip, shortened_teeth=3, shaper_teeth=5)


def test_checks_of_a_generated_pair_with_their_messages_in_full():
    from propulsor.parts.noncircular_pair.proofs import checks_generated

    g = SimpleNamespace(driver=_gen_check("driver"), driven=_gen_check("driven", True))
    perim = 80 * math.pi * 2.5 + 2e-9
    d = SimpleNamespace(smoothing=SimpleNamespace(generability=g), closure_error=3e-10, law=SimpleNamespace(n=4),
                        pc=SimpleNamespace(perimeter_driven=lambda: perim), z_H=80, m=2.5, shaper=None,
                        driver=_gear("driver", 0, 0.625), driven=_gear("driven", 2, 0.6249999995))
    p = SimpleNamespace(tip_land_min_module=0.25, shaper_teeth=23)
    pr = _proof()
    out = checks_generated(d, pr, p)
    rows = [(c.name, c.passed, c.value, c.limit, c.unit, c.message) for c in out]
    assert rows[:4] == [
        ("law.closure_error", True, 3e-10, 1e-9, "rad",
         "|theta(2 pi) - 2 pi n| = 3e-10 rad: the driver makes exactly n = 4 turns"),
        ("teeth.closure_error", False, pytest.approx(2e-9, abs=1e-12), 1e-9, "mm",
         "driven pitch perimeter vs z_H pi m = 80 x 7.853982 mm"),
        ("generability.driver_rho_min", True, 12.345678, 10.69, "mm",
         "driver convex rho_min 12.3457 mm vs rack undercut limit (h_a* - x) m / sin^2 alpha = 10.6900 mm"),
        ("generability.driven_rho_min", True, 12.345678, 10.69, "mm",
         "driven convex rho_min 12.3457 mm vs limit 10.6900 mm")]
    assert rows[4] == ("generability.driven_concave_rho", False, -31.25, 12.5, "mm",
                       "driven concave |rho|_min -31.2500 mm vs shaper pitch radius r0 = 12.500 mm")
    assert rows[5:9] == [
        ("teeth.driver_undercut", True, 0.0, 0, "teeth", "0 of 20 driver teeth undercut"),
        ("teeth.driver_tip_land", True, 0.625, pytest.approx(0.625 - 1e-9, abs=1e-15), "mm",
         "least tip land 0.6250 mm; 3 teeth tip-shortened, 5 cut by the shaper z0 = 23"),
        ("teeth.driven_undercut", False, 2.0, 0, "teeth", "2 of 80 driven teeth undercut"),
        ("teeth.driven_tip_land", True, 0.6249999995, pytest.approx(0.625 - 1e-9, abs=1e-15), "mm",
         "least tip land 0.6250 mm; 3 teeth tip-shortened, 5 cut by the shaper z0 = 23")]
    assert rows[9] == ("mesh.overlap_area", False, 3.0, 1e-6, "mm^2",
                       "max overlap 3 mm^2 over 6 phases at the law's positions")
    assert [c.name for c in out[10:]] == ["mesh.runs_without_jam", "mesh.backlash_min", "mesh.contact_continuity"]
    assert len(out) == 13
    # a catalogue shaper: its z0 and the cutting offset named; the tip land just below the limit fails; no overlap
    d.shaper = SimpleNamespace(z0=10)
    g.driver.concave, g.driven.concave = True, False
    g.driver.rho_concave_min = 12.5
    d.driver.tip_thickness_min = 0.6249999989
    pr2 = _proof(overlap_law=np.array([0.0, 1e-6, 0.0, 0.0, 0.0, 0.0]))
    out = checks_generated(d, pr2, p)
    assert [(c.name, c.passed, c.message) for c in out if "concave" in c.name] == [
        ("generability.driver_concave_rho", False, "driver concave |rho|_min 12.5000 mm vs shaper pitch radius r0 = "
         "12.500 mm (r0 + cutting offset e of the catalogue shaper's own x0)")]
    tip = [c for c in out if c.name == "teeth.driver_tip_land"][0]
    assert not tip.passed and tip.message.endswith("cut by the shaper z0 = 10")
    ov = [c for c in out if c.name == "mesh.overlap_area"][0]
    assert ov.passed and ov.message == "max overlap 1e-06 mm^2 over 6 phases at the law's positions"


def test_checks_common_and_of_sectors_with_their_messages_in_full():
    from propulsor.parts.noncircular_pair.proofs import checks_common, checks_sectors

    pr = _proof(least_overlap=np.array([0.0, 0.0, 12.34567, 0.0, 0.5, 0.0]))
    rows = [(c.name, c.passed, c.value, c.limit, c.unit, c.message) for c in checks_common(pr)]
    assert rows == [
        ("mesh.runs_without_jam", False, 1.0, 0, "phases",
         "1 of 6 phases have no free position of the driven wheel (least overlap up to 12.35 mm^2)"),
        ("mesh.backlash_min", True, pytest.approx(0.3), 0.0, "mm",
         "backlash 0.30000 .. 4.00000 mm on the driven pitch curve at the proof's 6 phases (the least as built, "
         "between them too: the derived backlash_min_mm)"),
        ("mesh.contact_continuity", True, 1.0, 1, "pairs", "least tooth pairs in contact 1, mean 1.8000")]
    free = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]), phi_coast=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.6]),
                  pairs_drive=np.array([0, 1, 1, 1, 1, 1]))
    rows = [(c.name, c.passed, c.message) for c in checks_common(free, "sectors")]
    assert rows == [
        ("sectors.runs_without_jam", True,
         "0 of 6 phases have no free position of the driven wheel (least overlap up to 0 mm^2)"),
        ("sectors.backlash_min", False,
         "backlash 0.00000 .. 6.00000 mm on the driven pitch curve at the proof's 6 phases (the least as built, "
         "between them too: the derived backlash_min_mm)"),
        ("sectors.contact_continuity", False, "least tooth pairs in contact 0, mean 0.8333")]
    d = SimpleNamespace(closure_error=2.5e-9)
    out = checks_sectors(d, pr)
    assert (out[0].name, out[0].passed, out[0].value, out[0].limit, out[0].unit, out[0].message) == (
        "law.closure_error", False, 2.5e-9, 1e-9, "rad",
        "|4 sum dtheta - 2 pi n| = 2.5e-09 rad (sector table, seed 000 eqs. 48-51)")
    assert [c.name for c in out[1:]] == ["sectors.runs_without_jam", "sectors.backlash_min",
                                         "sectors.contact_continuity"]
    assert checks_sectors(SimpleNamespace(closure_error=1e-9), pr)[0].passed


def test_counted_ticks_a_job_done_in_this_process():
    from propulsor.parallel import Done
    from propulsor.parts.noncircular_pair.proofs import _counted

    ticks = []
    job = Done(5)
    assert _counted(job, ticks.append, 3) is job and ticks == [3]
    other = SimpleNamespace()
    assert _counted(other, ticks.append, 4) is other and ticks == [3]


class _Design(str):
    """The design a proofs() world hands around: "D", with the two wheels' profiles it samples."""

    driver = SimpleNamespace(profile="driver profile")
    driven = SimpleNamespace(profile="driven profile")
    method = "sectors"  # the papers' teeth: the other method is "generated"


def _proofs_world(monkeypatch, proof, tolerance_grade=0, compare_methods=False, load_given=False, free=True):
    """proofs() with its steps recorded: the outer loops sampled, prove, start (run at once as a Done; a job started
    only where a worker is free (``forked_only``): one while ``free``, else None), abandon, count_shared, counter,
    the tolerance steps, compare."""
    import propulsor.parallel as parallel
    import propulsor.progress as progress
    from propulsor.parallel import Done
    from propulsor.parts.noncircular_pair import as_built, pair_proof, proofs, tolerance

    log = []
    def prove(d, ppt, legs, prog, mount, on_jam=None):
        if np.any(~np.isfinite(proof.phi_drive)):  # the proof meets its first jammed phase on its way
            log.append(("jam",))
            on_jam()
        log.append(("prove", d, ppt, legs, mount, prog))
        return proof

    monkeypatch.setattr(proofs, "prove", prove)
    monkeypatch.setattr(pair_proof, "_outer_only", lambda profile: log.append(("sample", profile)))

    def start(fn, *a, counter=None, forked_only=False):
        log.append(("start", fn, a, counter) + (("forked only",) if forked_only else ()))
        if forked_only and not free:
            return None
        return Done(("ran", fn, a)) if fn is tolerance.run_case else ("job", fn, a)

    monkeypatch.setattr(parallel, "start", start)
    monkeypatch.setattr(parallel, "abandon", lambda job: log.append(("abandon", job)))
    monkeypatch.setattr(progress, "count_shared", lambda prog, phase, parts, unit="": log.append(
        ("count_shared", phase, parts, unit, prog)) or ["C1", "C2"])
    ticks = []
    monkeypatch.setattr(progress, "counter", lambda prog, phase, total, unit="": log.append(
        ("counter", phase, total, unit, prog)) or ticks.append)
    monkeypatch.setattr(tolerance, "iso1328", lambda d, mount, grade, alpha: log.append(("iso1328", d, mount, grade, alpha))
                        or SimpleNamespace(source="ISO 1328 grade 8"))
    monkeypatch.setattr(tolerance, "worst_cases", lambda tol: log.append(("worst", tol.source)) or ["W1", "W2", "W3", "W4"])
    monkeypatch.setattr(tolerance, "monte_carlo_cases", lambda tol, n, seed: log.append(("mc", tol.source, n, seed))
                        or [f"M{k}" for k in range(n)])
    monkeypatch.setattr(proofs, "compare", lambda p, d, prog: log.append(("compare", p, d, prog)) or ("OD", "OP", "note"))
    p = SimpleNamespace(proof_phases_per_tooth=6, tolerance_grade=tolerance_grade, pressure_angle_deg=25.0,
                        tolerance_samples=2, tolerance_seed=9, compare_methods=compare_methods, load_given=load_given)
    said = []
    dd = SimpleNamespace(p=p, d=_Design("D"), mount=76.0)
    return dd, SimpleNamespace(progress=said.append), said, log, ticks, as_built, tolerance


def test_proofs_run_the_whole_cycle_then_both_directions_as_built_and_the_tolerance_cases(monkeypatch):
    from propulsor.checks.motion.contact_events import DRIVE, REVERSE
    from propulsor.parts.noncircular_pair.proofs import other_method, proofs

    pr = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]))
    dd, w, said, log, ticks, as_built, tolerance = _proofs_world(monkeypatch, pr, tolerance_grade=8,
                                                                  compare_methods=True)
    built = {}
    proofs(dd, w, built)
    assert "other" not in built  # the other method's comparison is a step of its own (after the solids)
    other_method(dd, w, built)
    f = as_built.contact_direction
    assert built["proof"] is pr
    assert built["as_built"] == (("job", f, ("D", 76.0, DRIVE)), ("job", f, ("D", 76.0, REVERSE)))
    tol, cases = built["tolerance"]
    assert tol.source == "ISO 1328 grade 8"
    assert [c.result() for c in cases] == [("ran", tolerance.run_case, ("D", 76.0, c))
                                           for c in ["W1", "W2", "W3", "W4", "M0", "M1"]]
    assert ticks == [1, 2, 3, 4, 5, 6]
    assert built["other"] == ("OD", "OP", "note")
    say = w.progress
    # both directions started before the proof (a worker free), the outer loops sampled before them (sent with the
    # design: the proof and the jobs read the same samples)
    assert log[:7] == [("count_shared", "as built: contact in both directions", 2, "position", say),
                       ("sample", "driver profile"), ("sample", "driven profile"),
                       ("start", f, ("D", 76.0, DRIVE), "C1", "forked only"),
                       ("start", f, ("D", 76.0, REVERSE), "C2", "forked only"),
                       ("prove", "D", 6, 4, 76.0, say),
                       ("iso1328", "D", 76.0, 8, pytest.approx(math.radians(25.0)))]
    assert log[7:10] == [("worst", "ISO 1328 grade 8"), ("mc", "ISO 1328 grade 8", 2, 9),
                         ("counter", "as made: tolerance cases", 6, "case", say)]
    assert log[-1] == ("compare", dd.p, "D", say)
    assert said == ["as built: both directions' contact on the finished outlines, resolved by contact events",
                    "as made: 6 cases within ISO 1328 grade 8"]


def test_with_a_load_case_the_drive_directions_job_goes_on_to_the_load_per_tooth(monkeypatch):
    """A pair with a load case: the drive direction's job is the contact and the load per tooth on it
    (``tooth_load_outputs.contact_and_load``, beside the build), the reverse one the contact alone."""
    from propulsor.checks.motion.contact_events import DRIVE, REVERSE
    from propulsor.parts.noncircular_pair.proofs import proofs
    from propulsor.parts.noncircular_pair.tooth_load_outputs import contact_and_load

    pr = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]))
    dd, w, said, log, ticks, as_built, _ = _proofs_world(monkeypatch, pr, load_given=True)
    built = {}
    proofs(dd, w, built)
    assert built["as_built"] == (("job", contact_and_load, ("D", 76.0, DRIVE, dd.p)),
                                 ("job", as_built.contact_direction, ("D", 76.0, REVERSE)))


def test_where_no_worker_is_free_both_directions_run_after_the_proof_as_before(monkeypatch):
    """No worker free when the proof starts (a budget of one process, or every slot of make's builds taken): nothing
    is started ahead; after the proof each direction starts as always (in a worker if one is free by then, else
    run here), so a study's variant runs the proof, then the contact, in its one process."""
    from propulsor.checks.motion.contact_events import DRIVE, REVERSE
    from propulsor.parts.noncircular_pair.proofs import proofs

    pr = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]))
    dd, w, said, log, ticks, as_built, _ = _proofs_world(monkeypatch, pr, free=False)
    built = {}
    proofs(dd, w, built)
    f = as_built.contact_direction
    assert [e for e in log if e[0] in ("start", "prove", "abandon")] == [
        ("start", f, ("D", 76.0, DRIVE), "C1", "forked only"), ("start", f, ("D", 76.0, REVERSE), "C2", "forked only"),
        ("prove", "D", 6, 4, 76.0, w.progress),
        ("start", f, ("D", 76.0, DRIVE), "C1"), ("start", f, ("D", 76.0, REVERSE), "C2")]
    assert built["as_built"] == (("job", f, ("D", 76.0, DRIVE)), ("job", f, ("D", 76.0, REVERSE)))


def test_proofs_of_a_jammed_pair_build_nothing_as_built_and_without_a_grade_no_tolerance(monkeypatch):
    """A jammed pair: the directions started ahead of the proof are abandoned (their workers killed), none is
    started after it; where no worker was free none was started at all."""
    from propulsor.checks.motion.contact_events import DRIVE, REVERSE
    from propulsor.parts.noncircular_pair import as_built
    from propulsor.parts.noncircular_pair.proofs import other_method, proofs

    f = as_built.contact_direction
    for pr in (_proof(), _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, np.inf]))):
        for free in (True, False):
            dd, w, said, log, ticks, _, _ = _proofs_world(monkeypatch, pr, tolerance_grade=8, free=free)
            built = {}
            proofs(dd, w, built)
            other_method(dd, w, built)
            assert built == {"proof": pr, "as_built": (), "other": (None, None, "")} and said == []
            starts = [e for e in log if e[0] == "start"]
            assert starts == [("start", f, ("D", 76.0, DRIVE), "C1", "forked only"),
                              ("start", f, ("D", 76.0, REVERSE), "C2", "forked only")]
            # abandoned as the proof meets its first jam (their workers stop then, not after the whole proof), and
            # again after it (no transmission as built: a job already stopped is left as it is)
            jobs = ([("abandon", ("job", f, ("D", 76.0, DRIVE))), ("abandon", ("job", f, ("D", 76.0, REVERSE)))]
                    if free else [("abandon", None), ("abandon", None)])
            events = [e for e in log if e[0] in ("jam", "abandon", "prove")]
            assert [e[0] for e in events] == ["jam", "abandon", "abandon", "prove", "abandon", "abandon"]
            assert events[1:3] == jobs and events[4:] == jobs
    # a jam counted though every phi_drive is finite
    pr = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]))
    pr_jam = SimpleNamespace(jams=1, phi_drive=pr.phi_drive)
    dd, w, said, log, ticks, _, _ = _proofs_world(monkeypatch, pr_jam)
    built = {}
    proofs(dd, w, built)
    assert built["as_built"] == ()
    dd, w, said, log, ticks, _, _ = _proofs_world(monkeypatch, pr, tolerance_grade=0)
    built = {}
    proofs(dd, w, built)
    other_method(dd, w, built)
    assert len(built["as_built"]) == 2 and "tolerance" not in built and built["other"] == (None, None, "")
    assert said == ["as built: both directions' contact on the finished outlines, resolved by contact events"]


def test_a_jammed_pairs_comparison_starts_in_the_worker_its_contact_leaves_and_is_collected_once(monkeypatch):
    """compare_methods: where the proof meets a jam, the other method's comparison starts in a worker (forked only)
    as soon as the contact started ahead is dropped, beside the rest of the proof, and the comparison step collects
    that job (never computing it again); where no worker is free it is computed in the comparison step as before, and
    a pair that runs never starts it early."""
    import propulsor.parallel as parallel
    from propulsor.parts.noncircular_pair import proofs as proofs_mod
    from propulsor.parts.noncircular_pair.proofs import other_method, proofs

    for free in (True, False):
        dd, w, said, log, ticks, _, _ = _proofs_world(monkeypatch, _proof(), compare_methods=True, free=free)
        monkeypatch.setattr(parallel, "result", lambda job: log.append(("result", job)) or ("OD2", "OP2", "n2"))
        fake_compare = proofs_mod.compare
        built = {}
        proofs(dd, w, built)
        events = [e[0] if e[0] != "start" else ("start", e[1]) for e in log
                  if e[0] in ("jam", "abandon", "prove", "start", "compare")]
        assert events[:6] == [("start", events[0][1]), ("start", events[0][1]), "jam", "abandon", "abandon",
                              ("start", fake_compare)]
        assert events[6:] == ["prove", "abandon", "abandon"]
        assert [e for e in log if e[0] == "start" and e[1] is fake_compare] == [
            ("start", fake_compare, (dd.p, dd.d), None, "forked only")]
        assert ("other_job" in built) == free
        assert said == (["generated: the other tooth method over one leg, for comparison, in a second process "
                         "beside the proof"] if free else [])
        other_method(dd, w, built)
        assert "other_job" not in built
        if free:
            assert built["other"] == ("OD2", "OP2", "n2")
            assert [e for e in log if e[0] in ("result", "compare")] == [
                ("result", ("job", fake_compare, (dd.p, dd.d)))]
        else:
            assert built["other"] == ("OD", "OP", "note")
            assert [e[0] for e in log if e[0] in ("result", "compare")] == ["compare"]
    # a pair that runs: the comparison waits for its own step, computed there
    pr = _proof(phi_drive=np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5]))
    dd, w, said, log, ticks, _, _ = _proofs_world(monkeypatch, pr, compare_methods=True)
    built = {}
    proofs(dd, w, built)
    assert "other_job" not in built and not any(e[0] == "start" and e[1] is proofs_mod.compare for e in log)


# =========================================================================== the search's details
def test_least_overlap_refines_the_scan_to_a_micro_radian_without_a_warning():
    """Jammed at L = 71 with the driver turned 0.013 rad: the least overlap's position, found to 1e-11 rad by a
    bounded search on the placement written out, is met within 5e-7 rad from a cold start (the 13-point scan and
    its Brent refinement at xatol 1e-6); a warm start whose quarter span holds it keeps that Brent search's point
    (the same search run here), one whose quarter span ends short of it gives the cold start's answer exactly."""
    import warnings

    from scipy.optimize import minimize_scalar

    from propulsor.checks.motion import outline
    from propulsor.parts.noncircular_pair.pair_proof import _least_overlap

    _, dd = _circular()
    d = dd.d
    drv = outline([d.driver.profile.outer.polyline(1e-4)])
    dvn = outline([d.driven.profile.outer.polyline(1e-4)])
    half = 0.5 * math.pi * 2.5 / 50
    th = 0.013
    f = lambda o: _m3d_overlap(drv.loops, dvn.loops, 71.0, th, o)
    ref = minimize_scalar(f, bounds=(0.0, 0.02), method="bounded", options={"xatol": 1e-10})
    assert 0.009 < ref.x < 0.01  # inside the bracket, a hundredth of a pitch from the nearest scan point
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cold = _least_overlap(drv, dvn, 71.0, 0.0, th, 0.0, half, False)
        assert cold[0] == pytest.approx(ref.x, abs=5e-7) and cold[1] == pytest.approx(ref.fun, rel=1e-9)
        q = 0.25 * half
        start = ref.x + 0.5 * q
        off, area = _least_overlap(drv, dvn, 71.0, 0.0, th, start, half, True)
        assert off == pytest.approx(ref.x, abs=1e-6) and area == pytest.approx(ref.fun, rel=1e-9)
        assert (off, area) != _least_overlap(drv, dvn, 71.0, 0.0, th, start, half, False)  # the warm search's own
        far = ref.x + 1.1 * q
        assert _least_overlap(drv, dvn, 71.0, 0.0, th, far, half, True) == \
            _least_overlap(drv, dvn, 71.0, 0.0, th, far, half, False)


def test_proof_search_spans_half_a_pitch_and_starts_from_the_law_after_a_free_phase():
    """The driver 2 g ahead of the law (g = 0.0131 rad, a point of the scan) at every other phase only: after a free
    phase the search starts cold at the law's position again (the scan meets the running position g on, not a pitch
    or more away); a pitch of 0.2 mm (search +-0.002 rad) cannot reach it - those phases are jams -, none given is
    taken as 8 mm.  Pairs are counted in integers."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    pitch = 2 * math.pi / 40
    phis = np.arange(6) * (pitch / 3) + 0.02
    half = 0.5 * math.pi * 2.5 / 50
    g = float(np.linspace(-half, half, 13)[7])
    moved = lambda ph: d.run_law.theta(ph) + 2 * g * (np.round((ph - 0.02) / (pitch / 3)) % 2)
    jt = 0.16 / math.cos(math.radians(20.0))
    r50 = lambda ph: 50.0 + 0 * ph
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, r50, pitch_mm=math.pi * 2.5, windows=2)
    assert pr.pairs_drive.dtype.kind == "i" and pr.pairs_coast.dtype.kind == "i"
    assert pr.jams == 0 and pr.offset[0::2].tolist() == [0.0] * 3
    assert pr.offset[1::2].tolist() == [g] * 3  # each searched cold from the law's position: the scan meets g
    assert pr.te_drive[1::2] == pytest.approx(np.full(3, g - jt / 100), abs=5e-6)
    assert pr.te_drive[0::2] == pytest.approx(np.full(3, -jt / 100), abs=5e-6)
    small = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, r50, pitch_mm=0.2, windows=2)
    assert small.jams == 3 and np.all(np.isnan(small.phi_drive[1::2])) and np.all(small.least_overlap[1::2] > 0.1)
    assert np.all(np.abs(small.offset[1::2]) <= 0.002 + 1e-12)
    none = prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, r50, windows=2)
    assert none.jams == 0 and none.te_drive == pytest.approx(pr.te_drive, abs=5e-6)


def test_proof_ticks_each_default_window_by_its_last_phase():
    """80 phases every 4.5 deg: the turn's 16 windows (0.4 rad: edges from the first phase to the last + 1e-12) hold
    five phases each; each window ticks the count of phases done at its end."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    phis = np.radians(np.arange(0.0, 360.0, 4.5)) + 0.003
    ticks = []
    prove_pair(dd.profiles[0], dd.profiles[1], 75.0, dd.d.run_law.theta, phis, lambda ph: 50.0 + 0 * ph,
               tick=ticks.append)
    edges = np.linspace(phis[0], phis[-1] + 1e-12, 17)
    expected = []
    for w in range(16):
        inside = [k for k, ph in enumerate(phis) if edges[w] <= ph < edges[w + 1]]
        if inside:
            expected.append(inside[-1] + 1)
    assert ticks == expected == list(range(5, 81, 5))


def test_proof_of_a_pair_mounted_a_millimetre_apart_is_the_sweep_of_the_whole_outlines():
    """At L + 1 mm the driver's root circle lies 1.625 mm outside the driven tip circle (more than the crop's 1 mm:
    no driver radius reaches within r_dvn + 1 of the driven axis on the line of centres, the half width's cosine
    clipped at -1): the proof is the transmission sweep of the whole outer loops."""
    from propulsor.parts.noncircular_pair.pair_proof import prove_pair

    _, dd = _circular()
    d = dd.d
    phis = np.arange(5) * (2 * math.pi / 40 / 5) + 0.007
    r50 = lambda ph: 50.0 + 0 * ph
    pr = prove_pair(dd.profiles[0], dd.profiles[1], 76.0, d.run_law.theta, phis, r50, pitch_mm=math.pi * 2.5,
                    windows=2)
    ref = _by_sweep(d, 76.0, d.run_law.theta, phis, r50(phis))
    assert pr.jams == 0 and np.all(pr.backlash_mm > 0.17 + 0.5)
    assert pr.phi_drive == pytest.approx(phis - ref.free_back, abs=1e-9)
    assert pr.phi_coast == pytest.approx(phis + ref.free_fwd, abs=1e-9)
    assert pr.pairs_drive.tolist() == ref.pairs_drive.tolist()


def test_a_searched_free_position_that_the_sweep_finds_overlapping_is_a_jam_of_that_overlap(monkeypatch):
    """The sweep at the searched position is the judge: where it measures overlap (here 5 mm^2, made up for the first
    such phase) the phase is a jam with that least overlap; the window's next phases are proved as before."""
    import dataclasses

    from propulsor.parts.noncircular_pair import pair_proof

    real = pair_proof.transmission_sweep
    single = []

    def sweep(*a, **kw):
        tr = real(*a, **kw)
        if len(a[5]) == 1:
            single.append(float(a[5][0]))
            if len(single) == 1:
                return dataclasses.replace(tr, overlap_area=np.array([5.0]))
        return tr

    monkeypatch.setattr(pair_proof, "transmission_sweep", sweep)
    _, dd = _circular()
    d = dd.d
    half = 0.5 * math.pi * 2.5 / 50
    g = float(np.linspace(-half, half, 13)[7])
    phis = np.arange(4) * (2 * math.pi / 40 / 4) + 0.02
    moved = lambda ph: d.run_law.theta(ph) + 2 * g
    pr = pair_proof.prove_pair(dd.profiles[0], dd.profiles[1], 75.0, moved, phis, lambda ph: 50.0 + 0 * ph,
                               pitch_mm=math.pi * 2.5, windows=1)
    assert len(single) == 4 and pr.jams == 1 and pr.least_overlap.tolist() == [5.0, 0.0, 0.0, 0.0]
    assert math.isnan(pr.phi_drive[0]) and math.isnan(pr.phi_coast[0]) and pr.pairs_drive[0] == 0
    assert np.all(np.isfinite(pr.phi_drive[1:])) and pr.offset[0] == g


def test_a_contact_direction_counts_its_positions_only_where_a_counter_listens(monkeypatch):
    """``as_built.contact_direction`` hands the job's tick to the contact search only in a job started with a counter
    (``parallel.listening``): a study's variant, whose jobs have none, skips the counting of its ten thousand
    positions; a build's job, started with one, is told each."""
    from propulsor import job_ticks, parallel
    from propulsor.parts.noncircular_pair import as_built

    seen = []
    monkeypatch.setattr(as_built, "pair_outlines", lambda d, mount: "PAIR")
    monkeypatch.setattr(as_built, "period_span", lambda d: 1.5)

    def resolve(pair, theta, phi0, phi1, direction, step_driver_rad=None, tick=None):
        seen.append(tick)
        if tick is not None:
            tick(7, 9)
        return (pair, phi0, phi1, direction)

    monkeypatch.setattr(as_built, "resolve_contact", resolve)
    d = SimpleNamespace(run_law=SimpleNamespace(theta=None))
    assert job_ticks._TICK is None and not parallel.listening()
    assert as_built.contact_direction(d, 75.0, 1) == ("PAIR", 0.0, 1.5, 1) and seen == [None]
    told = []
    monkeypatch.setattr(job_ticks, "_TICK", lambda done, total: told.append((done, total)))
    assert parallel.listening()
    as_built.contact_direction(d, 75.0, -1)
    assert seen[-1] is parallel.tick and told == [(7, 9)]
