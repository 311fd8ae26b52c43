"""Exact tests of the non-circular pair's teeth math (gears/envelope.py, generability.py, generation.py,
noncircular_teeth.py, smoothed_law.py) and the polysector: each expected value computed in the test."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.smoothed_law import SmoothedWalkingLaw
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw

LAW0 = WalkingLaw(**SEED_000)
LAW2 = WalkingLaw(**SEED_002)


def _refusal(fn) -> str:
    with pytest.raises(InputError) as e:
        fn()
    return str(e.value)


# ---- the smoothed law (gears/smoothed_law.py) ---------------------------------------------------------------------

def _free_blend(law: WalkingLaw, d: float, u_h: float):
    """The blend with a free hand-over value written in t (not in t/delta) with eps as a fifth unknown: p(0) = u_h,
    p, p', p'' = (1 - eps) U, U', U'' at t = delta, and one leg's driver angle n pi/2 kept:
    integral_{-d}^{d} p + (1 - eps) (n pi/2 - E) = n pi/2 with E the exact law's window integral (seed 000 eq. 9/11).
    Unknowns (c0, c2, c4, c6, eps) of p = c0 + c2 t^2 + c4 t^4 + c6 t^6."""
    K = 3 * law.b * law.u / law.A
    U, dU, d2U = law.u + K * math.sin(2 * d), 2 * K * math.cos(2 * d), -4 * K * math.sin(2 * d)
    E = 2 * (law.u * d + K * (1 - math.cos(2 * d)) / 2)
    I = law.n * math.pi / 2
    A = np.array([
        [1, 0, 0, 0, 0],
        [1, d ** 2, d ** 4, d ** 6, U],
        [0, 2 * d, 4 * d ** 3, 6 * d ** 5, dU],
        [0, 2, 12 * d ** 2, 30 * d ** 4, d2U],
        [2 * d, 2 * d ** 3 / 3, 2 * d ** 5 / 5, 2 * d ** 7 / 7, -(I - E)],
    ], float)
    rhs = np.array([u_h, U, dU, d2U, I - (I - E)])
    c0, c2, c4, c6, eps = np.linalg.solve(A, rhs)
    return (lambda t: c0 + c2 * t ** 2 + c4 * t ** 4 + c6 * t ** 6), eps


def test_a_blend_that_dips_below_zero_is_refused_with_its_least_value():
    # seed 000's law with a hand-over value of 10 over a 0.6 rad window: the window's excess integral is more than
    # the rest of the leg holds, eps > 1, and the law scaled by (1 - eps) is negative from the window's end on
    p, eps = _free_blend(LAW0, 0.6, 10.0)
    t = np.linspace(0.0, 0.6, 600_001)
    least = float(p(t).min())
    assert eps > 1 and least == pytest.approx(float(p(0.6)), rel=1e-12) and least < -2
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, 0.6, 10.0)) == (
        f"delta = 0.6: blend makes U <= 0 (min {least:.4g}); use a smaller delta")
    # a hand-over value of 5 keeps it above zero: accepted, its window's values those of the blend written in t
    ok = SmoothedWalkingLaw(LAW0, 0.6, 5.0)
    p5, eps5 = _free_blend(LAW0, 0.6, 5.0)
    assert float(p5(t).min()) > 0.3
    assert ok.eps == pytest.approx(eps5, rel=1e-9)
    assert ok._blend_min() == pytest.approx(float(p5(t).min()), rel=1e-9)
    phi = math.pi / 4 + 2 * math.pi / 2 + np.linspace(-0.59, 0.59, 41)
    np.testing.assert_allclose(ok.U(phi), p5(phi - math.pi / 4 - math.pi), rtol=1e-10)


@pytest.mark.parametrize("delta", [math.pi / 4, 0.7])
def test_blend_half_widths_up_to_a_quarter_turn_of_the_leg_are_accepted(delta):
    # pi/4 is allowed (the windows of neighbouring hand-overs meet), and so is anything above pi/5
    sl = SmoothedWalkingLaw(LAW2, delta)
    assert sl.delta == delta
    assert sl.leg_breakpoints == tuple(sorted({-math.pi / 4, -math.pi / 4 + delta, math.pi / 4 - delta, math.pi / 4}))
    # the closure holds whatever the width: n driver turns a driven turn
    assert float(sl.theta(2 * math.pi)) == pytest.approx(2 * math.pi * LAW2.n, abs=1e-12)


def test_the_smoothed_laws_refusals_in_full():
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, math.pi / 4 + 1e-9)) == (
        f"delta = {math.pi / 4 + 1e-9!r}: blend half-width must be <= pi/4 = 0.785398 rad")
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, 0.0)) == "delta = 0.0: must be > 0 rad"
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, -0.1)) == "delta = -0.1: must be > 0 rad"
    assert _refusal(lambda: SmoothedWalkingLaw("seed 000", 0.1)) == "law = 'seed 000': must be a WalkingLaw"
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, 0.1, 0.0)) == "u_h = 0.0: must be > 0"
    assert _refusal(lambda: SmoothedWalkingLaw(LAW0, 0.1, -1.0)) == "u_h = -1.0: must be > 0"
    sl = SmoothedWalkingLaw(LAW0, 0.1)
    assert _refusal(lambda: sl.blend(0.0, 3)) == "order = 3: must be -1, 0, 1 or 2"
    assert _refusal(lambda: sl.blend(0.0, -2)) == "order = -2: must be -1, 0, 1 or 2"


def test_a_half_width_given_as_a_numpy_float32_is_kept_as_a_python_float():
    # a study's sampler hands numpy scalars on; the law is the same as with the Python float of that value
    d32 = np.float32(0.2)
    a, b = SmoothedWalkingLaw(LAW2, d32), SmoothedWalkingLaw(LAW2, float(d32))
    assert type(a.delta) is float and a.delta == b.delta
    phi = np.linspace(0.0, 2 * math.pi, 1001)
    assert np.array_equal(a.U(phi), b.U(phi)) and np.array_equal(a.theta(phi), b.theta(phi))
    assert np.array_equal(a.blend(np.linspace(-0.2, 0.2, 9), 1), b.blend(np.linspace(-0.2, 0.2, 9), 1))


# ---- generability and the choice of the smoothing (gears/generability.py) ------------------------------------------

from propulsor.gears.generability import (CurveCheck, CutterSpec, Generability, _check_curve,  # noqa: E402
                                          check_generable, choose_smoothing, remedies)
from propulsor.gears.involute import BasicRack  # noqa: E402
from propulsor.gears.noncircular import CurvatureSummary, PitchCurves, hub_speed_ripple, perimeter_per_mm  # noqa: E402

S2_20 = math.sin(math.radians(20.0)) ** 2


def test_cutter_spec_refusals_in_full():
    assert _refusal(lambda: CutterSpec(m=0.0)) == "m = 0.0: must be > 0 mm"
    assert _refusal(lambda: CutterSpec(m=2.0, alpha=0.0)) == "alpha = 0.0: pressure angle must be in (0, pi/2) rad"
    assert _refusal(lambda: CutterSpec(m=2.0, alpha=math.pi / 2)) == (
        f"alpha = {math.pi / 2!r}: pressure angle must be in (0, pi/2) rad")
    assert _refusal(lambda: CutterSpec(m=2.0, alpha=math.nan)) == "alpha = nan: must be a finite number"
    assert _refusal(lambda: CutterSpec(m=2.0, h_a=0.0)) == "h_a = 0.0: must be > 0"
    assert _refusal(lambda: CutterSpec(m=2.0, x=math.inf)) == "x = inf: must be a finite number"
    assert _refusal(lambda: CutterSpec(m=2.0, x_H=math.nan)) == "x_H = nan: must be a finite number"
    assert _refusal(lambda: CutterSpec(m=2.0, z0=5)) == "z0 = 5: shaper cutter tooth count must be a whole number >= 6"
    assert _refusal(lambda: CutterSpec(m=2.0, z0=12.5)) == (
        "z0 = 12.5: shaper cutter tooth count must be a whole number >= 6")
    assert _refusal(lambda: CutterSpec(m=2.0, z0=math.inf)) == "z0 = inf: must be a finite number"
    six = CutterSpec(m=2.0, z0=6.0)
    assert six.z0 == 6 and type(six.z0) is int
    assert _refusal(lambda: CutterSpec(m=2.0).shift("ring")) == "role = 'ring': must be 'driver' or 'driven'"


def test_cutter_spec_quantities_by_hand():
    c = CutterSpec(m=3.0, alpha=math.radians(25.0), h_a=0.8, x=0.3, x_H=-0.2, z0=17, shaper_x0=0.1)
    s2 = math.sin(math.radians(25.0)) ** 2
    # rack undercut limit rho >= (h_a* - x) m / sin^2 alpha, for either shift
    assert c.rho_limit(0.3) == pytest.approx((0.8 - 0.3) * 3.0 / s2, rel=1e-15)
    assert c.rho_limit(-0.2) == pytest.approx((0.8 + 0.2) * 3.0 / s2, rel=1e-15)
    assert c.r0 == 3.0 * 17 / 2 and CutterSpec(m=3.0).r0 == math.inf
    # the shaper of its own x0 rolls (x + x0) m above the pitch curve; tied to -x: on it
    assert c.shaper_offset(0.3) == pytest.approx(0.4 * 3.0, rel=1e-15)
    assert c.shaper_offset(-0.2) == pytest.approx(-0.1 * 3.0, rel=1e-15)
    assert CutterSpec(m=3.0, z0=17).shaper_offset(0.3) == 0.0
    assert (c.shift("driver"), c.shift("driven")) == (0.3, -0.2)
    rack = BasicRack(alpha=math.radians(25.0), rho_f_star=0.3)
    t = c.tooth_spec("driven", rack, thinning_mm=0.05, tip_min_mm=0.4)
    assert (t.m, t.x, t.thinning_mm, t.rack, t.z0, t.tip_min_mm) == (3.0, -0.2, 0.05, rack, 17, 0.4)
    d = CutterSpec(m=3.0, x=0.3).tooth_spec("driver", rack)
    assert (d.x, d.thinning_mm, d.z0, d.tip_min_mm) == (0.3, 0.0, None, 0.0)


def _summary(curve="driver", convex=20.0, concave=False, rho_cc=math.inf):
    return CurvatureSummary(curve=curve, rho_convex_min=convex, phi_convex_min=0.1, concave=concave,
                            rho_concave_min=rho_cc, phi_concave_min=0.2 if concave else math.nan,
                            concave_intervals=((0.1, 0.3),) if concave else (), corner=None)


def test_one_curve_against_the_rack_limit_and_the_shaper_on_both_sides():
    c = CutterSpec(m=2.0, x=0.25, z0=20)                       # r0 = 20 mm; limit (1 - 0.25) 2 / sin^2 20 deg
    lim = 0.75 * 2.0 / S2_20
    ok = _check_curve(_summary(convex=lim * (1 + 1e-9), concave=True, rho_cc=20.0 + 1e-9), c, 0.25)
    assert ok == CurveCheck("driver", lim * (1 + 1e-9), pytest.approx(lim, rel=1e-15), True, 20.0 + 1e-9, 20.0,
                            True, "")
    bad = _check_curve(_summary(convex=lim * (1 - 1e-9), concave=True, rho_cc=20.0), c, 0.25)
    assert not bad.ok and bad.reason == (
        f"driver: convex rho_min {lim * (1 - 1e-9):.3f} mm < rack undercut limit {lim:.3f} mm; "
        "driver: concave |rho|_min 20.000 mm <= shaper pitch radius 20.000 mm")
    # no shaper: any concave stretch fails; a convex curve needs none
    none = _check_curve(_summary(curve="driven", convex=50.0, concave=True, rho_cc=300.0), CutterSpec(m=2.0), 0.0)
    assert none.reason == "driven: concave (|rho| >= 300.000 mm) and no shaper cutter z0 given"
    assert none.r0 == math.inf and not none.ok
    assert _check_curve(_summary(convex=50.0), CutterSpec(m=2.0), 0.0).ok
    # a shaper of its own x0 = 0.5 on a gear of x = 0.25: it rolls e = 1.5 mm out, so it needs |rho| > 21.5 mm
    own = CutterSpec(m=2.0, x=0.25, z0=20, shaper_x0=0.5)
    assert _check_curve(_summary(convex=50.0, concave=True, rho_cc=21.5 + 1e-9), own, 0.25).ok
    near = _check_curve(_summary(convex=50.0, concave=True, rho_cc=21.4), own, 0.25)
    assert near.r0 == pytest.approx(21.5, rel=1e-15)
    assert near.reason == ("driver: concave |rho|_min 21.400 mm <= shaper pitch radius 20.000 mm "
                           "+ cutting offset +1.500 mm")


def test_both_curves_are_checked_with_their_own_shift():
    sl = SmoothedWalkingLaw(LAW2, 0.15)
    L = math.pi * 2.5 * 80 / perimeter_per_mm(sl)
    pair = PitchCurves(sl, L)
    c = CutterSpec(m=2.5, x=0.5, x_H=-0.3, z0=20)
    g = check_generable(pair, c)
    for chk, curve, x in ((g.driver, "driver", 0.5), (g.driven, "driven", -0.3)):
        cs = pair.curvature(curve)
        assert chk.curve == curve
        assert chk.rho_limit == pytest.approx((1.0 - x) * 2.5 / S2_20, rel=1e-14)
        assert (chk.rho_convex_min, chk.concave, chk.rho_concave_min) == (cs.rho_convex_min, cs.concave,
                                                                         cs.rho_concave_min)
        assert chk.ok == (cs.rho_convex_min >= chk.rho_limit and (not cs.concave or 25.0 < cs.rho_concave_min))
    assert g.ok == (g.driver.ok and g.driven.ok)
    T = CurveCheck("d", 1.0, 0.5, False, math.inf, math.inf, True, "")
    F = CurveCheck("d", 0.1, 0.5, False, math.inf, math.inf, False, "x")
    assert [Generability(a, b).ok for a, b in ((T, T), (T, F), (F, T), (F, F))] == [True, False, False, False]


def test_the_smoothing_chosen_is_the_narrowest_generable_one_and_its_pair_closes():
    cutter = CutterSpec(m=2.5, x=0.5, z0=20)
    d = choose_smoothing(LAW2, cutter, 80, rtol=1e-7)
    L = math.pi * 2.5 * 80 / perimeter_per_mm(SmoothedWalkingLaw(LAW2, d.delta))
    assert d.L == pytest.approx(L, rel=1e-14) and d.z_H == 80 and d.z == 20 and d.cutter is cutter
    assert d.law.delta == d.delta and d.law.law is LAW2
    assert d.generability.ok and d.generability == check_generable(PitchCurves(d.law, L), cutter)
    assert d.ripple == hub_speed_ripple(d.law)
    assert d.pair.L == d.L and d.pair.law is d.law
    assert d.closure_error == pytest.approx(abs(float(d.law.theta(2 * math.pi)) - 8 * math.pi), abs=1e-15)
    assert d.closure_error < 1e-12
    # the bisection's last step is within rtol: a blend narrower by 2 rtol is not generable
    for delta, ok in ((d.delta * (1 - 2e-7), False), (d.delta, True)):
        sl = SmoothedWalkingLaw(LAW2, delta)
        assert check_generable(PitchCurves(sl, math.pi * 2.5 * 80 / perimeter_per_mm(sl)), cutter).ok is ok
    # a coarser tolerance stops further from the boundary, on the generable side
    coarse = choose_smoothing(LAW2, cutter, 80, rtol=1e-2)
    assert d.delta <= coarse.delta <= d.delta * 1.0101


def test_choose_smoothing_refusals_in_full():
    c = CutterSpec(m=2.5, x=0.5, z0=20)
    assert _refusal(lambda: choose_smoothing("seed 002", c, 80)) == "law = 'seed 002': must be a WalkingLaw"
    assert _refusal(lambda: choose_smoothing(LAW2, c, 80, delta_max=math.pi / 4 + 1e-9)) == (
        f"delta_max = {math.pi / 4 + 1e-9!r}: must be <= pi/4 = 0.785398 rad")
    assert _refusal(lambda: choose_smoothing(LAW2, c, 80, delta_max=0.0)) == "delta_max = 0.0: must be > 0 rad"
    assert _refusal(lambda: choose_smoothing(LAW2, c, 82)) == (
        "z_H = 82: must be a multiple of n = 4 so the driver has z_H/n whole teeth (nearest valid: 80, 84)")
    assert _refusal(lambda: choose_smoothing(WalkingLaw(a=100, b=50, c=236.5, n=3), c, 81)) == (
        "n = 3: the driver pitch curve repeats every n*pi/2 and closes only if n divides the 4 legs: n in {1, 2, 4}")
    # pi/4 itself is a valid upper end
    assert choose_smoothing(LAW2, c, 80, delta_max=math.pi / 4).generability.ok


def _generable(law, cutter, z_H, delta):
    sl = SmoothedWalkingLaw(law, delta)
    return check_generable(PitchCurves(sl, math.pi * cutter.m * z_H / perimeter_per_mm(sl)), cutter)


def test_no_smoothing_up_to_delta_max_names_the_remedies_and_the_blend_that_would_work():
    c = CutterSpec(m=2.5, x=0.5, z0=20)
    need = choose_smoothing(LAW2, c, 80).delta                        # about 0.148 rad
    dmax = need / 2
    text = _refusal(lambda: choose_smoothing(LAW2, c, 80, delta_max=dmax))
    # the first of 24 steps from delta_max to pi/4 that is generable
    first = next(d for d in np.linspace(dmax, math.pi / 4, 25)[1:] if _generable(LAW2, c, 80, float(d)).ok)
    g = _generable(LAW2, c, 80, dmax)
    L = math.pi * 2.5 * 80 / perimeter_per_mm(SmoothedWalkingLaw(LAW2, dmax))
    bits = remedies(g, c, 80, 4, L)
    assert bits
    assert text == (f"delta_max = {dmax!r}: no blend half-width up to delta_max makes both pitch curves generable ("
                    + " | ".join(bits) + f"; delta = {first:.4f} rad would work)")
    keyed = _refusal(lambda: choose_smoothing(LAW2, c, 80, delta_max=dmax, keys={"delta": "blend_deg"}))
    assert keyed.endswith(f"; blend_deg >= {math.degrees(first):.2f} would work)")
    # a driver cut with x = -0.5 (rack limit 1.5 m / sin^2 20 deg = 32 mm): no blend up to pi/4 works
    neg = CutterSpec(m=2.5, x=-0.5)
    assert not any(_generable(LAW2, neg, 80, float(d)).ok for d in np.linspace(0.3, math.pi / 4, 25))
    assert _refusal(lambda: choose_smoothing(LAW2, neg, 80, delta_max=0.3)).endswith(
        "; no delta up to pi/4 works)")
    # at pi/4 there is nothing beyond to try
    full = _refusal(lambda: choose_smoothing(LAW2, neg, 80, delta_max=math.pi / 4))
    sl4 = SmoothedWalkingLaw(LAW2, math.pi / 4)
    L4 = math.pi * 2.5 * 80 / perimeter_per_mm(sl4)
    bits4 = remedies(check_generable(PitchCurves(sl4, L4), neg), neg, 80, 4, L4)
    assert full == (f"delta_max = {math.pi / 4!r}: no blend half-width up to delta_max makes both pitch curves "
                    "generable (" + " | ".join(bits4) + ")")
    # delta_max just below the narrowest generable blend: the first step beyond it works
    just = need * 0.999
    first = just + (math.pi / 4 - just) / 24
    assert _refusal(lambda: choose_smoothing(LAW2, c, 80, delta_max=just)).endswith(
        f"; delta = {first:.4f} rad would work)")
    # between pi/5 and pi/4 (seed 000, x = -0.3: generable from about 0.67 rad)
    c0 = CutterSpec(m=2.0, x=-0.3, z0=20)
    assert not _generable(LAW0, c0, 96, 0.65).ok
    first = next(d for d in np.linspace(0.65, math.pi / 4, 25)[1:] if _generable(LAW0, c0, 96, float(d)).ok)
    assert _refusal(lambda: choose_smoothing(LAW0, c0, 96, delta_max=0.65)).endswith(
        f"; delta = {first:.4f} rad would work)")
    # the part's limits and names reach the remedies
    limits = {"x": (-1.0, 0.6), "z_H": (4, 480), "m": (0.5, 10.0), "z0": (6, 40)}
    keys = {"x": "driver_shift", "x_H": "-driver_shift", "z_H": "driven_teeth", "m": "module_mm",
            "z0": "shaper_teeth", "delta": "blend_deg"}
    text = _refusal(lambda: choose_smoothing(LAW2, neg, 80, delta_max=0.3, limits=limits, keys=keys))
    sl3 = SmoothedWalkingLaw(LAW2, 0.3)
    L3 = math.pi * 2.5 * 80 / perimeter_per_mm(sl3)
    bits3 = remedies(check_generable(PitchCurves(sl3, L3), neg), neg, 80, 4, L3, limits, keys)
    assert text == ("delta_max = 0.3: no blend half-width up to delta_max makes both pitch curves generable ("
                    + " | ".join(bits3) + "; no delta up to pi/4 works)")
    assert "driver_shift" in text and bits3 != remedies(check_generable(PitchCurves(sl3, L3), neg), neg, 80, 4, L3)


def _check(curve, rho_cv, lim, concave=False, rho_cc=math.inf, r0=math.inf, ok=False):
    return CurveCheck(curve, rho_cv, lim, concave, rho_cc, r0, ok, "")


def test_remedies_of_a_convex_stretch_below_the_rack_limit_by_hand():
    c = CutterSpec(m=2.0, x=0.2, x_H=-0.4, z0=20)
    rho, lim = 6.0, (1.0 - 0.2) * 2.0 / S2_20                 # 9.355 mm
    good = _check("driven", 50.0, 5.0, ok=True)
    bits = remedies(Generability(_check("driver", rho, lim), good), c, 60, 2, 120.0)
    x_need = 1.0 - rho * S2_20 / 2.0                          # (h_a - x) m / s2 = rho
    z_need = math.ceil(60 * lim / rho / 2) * 2                 # rho and L grow with z_H at a fixed module
    m_max = rho * S2_20 / (1.0 - 0.2)
    assert bits == [f"driver: convex rho_min 6.000 mm < undercut limit {lim:.3f} mm; works with "
                    f"x >= {x_need:.3f}, or z_H >= {z_need} at m = 2, or m <= {m_max:.4g} mm at L = 120.000 mm"]
    # the driven wheel's shift is -driver_shift in the part file: x_H >= v reads driver_shift <= -v
    keys = {"x": "driver_shift", "x_H": "-driver_shift", "z_H": "driven_teeth", "m": "module_mm", "z0": "shaper_teeth"}
    lim_H = (1.0 + 0.4) * 2.0 / S2_20
    bits = remedies(Generability(good, _check("driven", rho, lim_H)), c, 60, 2, 120.0, keys=keys)
    xH_need = 1.0 - rho * S2_20 / 2.0
    z_need = math.ceil(60 * lim_H / rho / 2) * 2
    m_max = rho * S2_20 / (1.0 + 0.4)
    assert bits == [f"driven: convex rho_min 6.000 mm < undercut limit {lim_H:.3f} mm; works with "
                    f"driver_shift <= {-xH_need:.3f}, or driven_teeth >= {z_need} at module_mm = 2, or "
                    f"module_mm <= {m_max:.4g} mm at L = 120.000 mm"]


def test_remedies_stay_within_the_limits_both_sides():
    c = CutterSpec(m=2.0, x=0.2, z0=20)
    rho, lim = 6.0, (1.0 - 0.2) * 2.0 / S2_20
    good = _check("driven", 50.0, 5.0, ok=True)
    x_need = 1.0 - rho * S2_20 / 2.0
    z_need = math.ceil(60 * lim / rho / 2) * 2
    m_max = rho * S2_20 / 0.8

    def text(limits):
        return remedies(Generability(_check("driver", rho, lim), good), c, 60, 2, 120.0, limits)[0]

    at = {"x": (x_need, x_need), "z_H": (z_need, z_need), "m": (m_max, m_max)}
    assert text(at).endswith(f"x >= {x_need:.3f}, or z_H >= {z_need} at m = 2, or m <= {m_max:.4g} mm at L = 120.000 mm")
    for name, lo, hi in (("x", x_need * (1 + 1e-9), 5.0), ("x", -5.0, x_need * (1 - 1e-9)),
                         ("z_H", z_need + 1, 999), ("z_H", 4, z_need - 1), ("m", m_max * (1 + 1e-9), 9.0),
                         ("m", 0.0, m_max * (1 - 1e-9))):
        t = text({**at, name: (lo, hi)})
        assert {"x": "x >=", "z_H": "z_H >=", "m": "m <="}[name] not in t, (name, lo, hi, t)
    none = {"x": (9.0, 9.0), "z_H": (1, 2), "m": (9.0, 9.0)}
    assert text(none) == (f"driver: convex rho_min 6.000 mm < undercut limit {lim:.3f} mm; no profile shift, "
                          "tooth count or module within their limits makes it generable (a smoother law)")
    # a corner (rho = 0): nothing at a finite shift, tooth count or module helps
    corner = remedies(Generability(_check("driver", 0.0, lim), good), c, 60, 2, 120.0)
    assert corner == [f"driver: convex rho_min 0.000 mm < undercut limit {lim:.3f} mm; no profile shift, tooth "
                      "count or module within their limits makes it generable (a smoother law)"]
    # h_a <= x: no module limit from the rack (the limit is <= 0), the other remedies stay
    high = CutterSpec(m=2.0, x=1.0, z0=20)
    t = remedies(Generability(_check("driver", rho, 0.5 + rho), good), high, 60, 2, 120.0)[0]
    assert " or m <=" not in t and "x >= " in t


def test_remedies_of_a_concave_stretch_name_the_largest_shaper_that_fits():
    c = CutterSpec(m=2.0, x=0.0, z0=30)                          # r0 = 30 mm
    good = _check("driver", 50.0, 5.0, ok=True)
    for rho_cc, z0_max in ((25.0, 24), (25.1, 25), (24.9, 24)):  # m z0 / 2 < |rho| strictly
        bits = remedies(Generability(good, _check("driven", 50.0, 5.0, True, rho_cc, 30.0)), c, 60, 2, 120.0,
                        keys={"z0": "shaper_teeth"})
        assert bits == [f"driven: concave |rho|_min {rho_cc:.3f} mm needs a shaper with shaper_teeth <= {z0_max} "
                        "(r0 < |rho|)"]
    lim = {"z0": (25, 200)}
    bits = remedies(Generability(good, _check("driven", 50.0, 5.0, True, 25.0, 30.0)), c, 60, 2, 120.0, lim)
    assert bits == ["driven: concave |rho|_min 25.000 mm: no shaper within the limits fits inside it (r0 < |rho|; "
                    "a smoother law)"]
    assert remedies(Generability(good, _check("driven", 50.0, 5.0, True, 0.9, 30.0)), c, 60, 2, 120.0) == [
        "driven: concave |rho|_min 0.900 mm: no shaper within the limits fits inside it (r0 < |rho|; a smoother law)"]
    # a shaper of its own x0 rolls e = (x + x0) m out: it must fit inside |rho| - e
    own = CutterSpec(m=2.0, x=0.0, x_H=0.5, z0=30, shaper_x0=0.25)   # driven: e = 0.75 * 2 = 1.5 mm
    bits = remedies(Generability(good, _check("driven", 50.0, 5.0, True, 25.0, 31.5)), own, 60, 2, 120.0)
    assert bits == ["driven: concave |rho|_min 25.000 mm needs a shaper with z0 <= 23 (r0 < |rho| - e, e = +1.500 mm)"]
    # a curve that passes its check is not named, and a concave stretch the shaper fits has no remedy
    assert remedies(Generability(good, _check("driven", 50.0, 5.0, True, 40.0, 30.0, ok=False)), c, 60, 2,
                    120.0) == []


# ---- the generated teeth of the pair (gears/noncircular_teeth.py) on a circular pair: the involute spur gear ------

from scipy.optimize import brentq  # noqa: E402

from propulsor.gears.involute import inv  # noqa: E402
from propulsor.gears.noncircular_teeth import SHAPER_MARGIN_PITCHES, ToothSpec, generate_teeth  # noqa: E402
from propulsor.gears.pitch_frame import ArcFrame  # noqa: E402
from propulsor.laws.ratio_laws import EllipticalLaw  # noqa: E402

ALPHA = math.radians(20.0)


def _circular_pair(m: float, z_H: int):
    """An elliptical law of eccentricity 0 and 2 lobes: circles of radii L/3 and 2L/3, ratio 2; L so that the driven
    circle carries z_H teeth (2 pi (2L/3) = pi m z_H)."""
    return PitchCurves(EllipticalLaw(e=0.0, k=2), 3 * m * z_H / 4)


def _land(z: int, m: float, x: float, r_y: float, thinning: float = 0.0) -> float:
    """Arc tooth thickness of an involute spur gear at radius r_y: s_y = d_y (s / d + inv alpha - inv alpha_y),
    s = m (pi/2 + 2 x tan alpha) - thinning on the pitch circle (ISO 21771)."""
    r = m * z / 2
    s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA)) - thinning
    a_y = math.acos(r * math.cos(ALPHA) / r_y)
    return 2 * r_y * (s / (2 * r) + float(inv(ALPHA)) - float(inv(a_y)))


@pytest.mark.parametrize("role, x, thinning", [("driven", 0.0, 0.0), ("driver", 0.3, 0.0), ("driven", -0.2, 0.1),
                                               ("driver", 0.5, 0.06)])
def test_rack_cut_teeth_of_a_circular_pair_have_the_involute_gears_tip_land(role, x, thinning):
    m, z_H = 2.0, 40
    pc = _circular_pair(m, z_H)
    ticks = []
    g = generate_teeth(pc, role, ToothSpec(m=m, x=x, thinning_mm=thinning), tick=lambda k, z: ticks.append((k, z)))
    z, U = (40, 1.0) if role == "driven" else (20, 2.0)
    r_H = m * z_H / 2                                    # the arc frame runs on the driven circle: phi = s / r_H
    assert (g.role, g.z, g.n, len(g.teeth), len(g.sides), len(g.tips)) == (role, z, 2, z, z, z)
    assert type(g.z) is int                              # a count of teeth (z_H // n for the driver)
    assert ticks == [(k + 1, z) for k in range(z)]
    r = m * z / 2
    r_a = r + (1 + x) * m
    s_a = _land(z, m, x, r_a, thinning)
    half = s_a / (2 * r_a) / U                           # half the tip's angle, in the driven angle
    for k, (tooth, tip) in enumerate(zip(g.teeth, g.tips)):
        s_c = (k + 0.5) * math.pi * m if role == "driven" else k * math.pi * m
        assert tooth.s_centre == pytest.approx(s_c, rel=1e-12, abs=1e-12)
        assert tooth.phi_centre == pytest.approx(s_c / r_H, rel=1e-9, abs=1e-12)
        assert (tooth.right, tooth.left, tooth.undercut, tooth.shortened) == ("rack", "rack", False, False)
        assert tooth.tip_height_mm == pytest.approx((1 + x) * m, rel=1e-15)
        assert tooth.tip_thickness_mm == pytest.approx(s_a, rel=1e-9)
        h, hr, hl = tip
        assert h == tooth.tip_height_mm
        sgn = -1.0 if role == "driven" else 1.0          # the right flank is the clockwise one of the body
        assert hr[1] == pytest.approx(tooth.phi_centre + sgn * half, abs=1e-10)
        assert hl[1] == pytest.approx(tooth.phi_centre - sgn * half, abs=1e-10)


def test_a_tip_land_below_the_minimum_is_shortened_to_the_tallest_height_that_keeps_it():
    m, z_H, x = 2.0, 40, 0.5
    pc = _circular_pair(m, z_H)
    r = m * 20 / 2
    full = _land(20, m, x, r + (1 + x) * m)                 # about 0.87 mm at the nominal tip
    t_min = 1.2
    assert full < t_min
    r_y = brentq(lambda ry: _land(20, m, x, ry) - t_min, r, r + (1 + x) * m, xtol=1e-13)
    g = generate_teeth(pc, "driver", ToothSpec(m=m, x=x, tip_min_mm=t_min))
    for tooth, tip in zip(g.teeth, g.tips):
        assert tooth.shortened
        assert tooth.tip_height_mm == pytest.approx(r_y - r, abs=2e-6)     # the bisection's 1e-6 mm
        assert tooth.tip_height_mm <= r_y - r + 1e-9                        # never above: the land is kept
        assert t_min <= tooth.tip_thickness_mm < t_min + 1e-5
        assert tip[0] == tooth.tip_height_mm
    # the land at the nominal tip is enough: nothing is shortened
    ok = generate_teeth(pc, "driver", ToothSpec(m=m, x=x, tip_min_mm=full * 0.999))
    assert not any(t.shortened for t in ok.teeth)
    # a land that no height down to (tip_floor + x) m gives: refused with the land there
    floor_land = _land(20, m, x, r + (0.5 + x) * m)
    text = _refusal(lambda: generate_teeth(pc, "driver", ToothSpec(m=m, x=x, tip_min_mm=3.0)))
    assert text == (f"m = 2.0: driver tooth at phi = {g.teeth[0].phi_centre:.4f} rad is pointed or cannot be cut: tip "
                    f"land {floor_land:.3f} mm < 3.000 mm even with the tip shortened to 1.00 m (use a smaller "
                    "profile shift, a larger shaper, more teeth or a wider smoothing)")
    # a lower floor reaches a height with the land
    low = generate_teeth(pc, "driver", ToothSpec(m=m, x=x, tip_min_mm=1.9, tip_floor=-0.2))
    r_y = brentq(lambda ry: _land(20, m, x, ry) - 1.9, r - 0.5, r + (1 + x) * m, xtol=1e-13)
    assert low.teeth[3].tip_height_mm == pytest.approx(r_y - r, abs=2e-6)


def test_a_tip_height_limit_cuts_every_tip_there():
    m, z_H, x = 2.0, 40, 0.4
    spec = ToothSpec(m=m, x=x, tip_max_mm=2.5)
    assert (spec.h_tip, spec.h_tip_cut, spec.h_root) == pytest.approx(((1 + x) * m, 2.5, (1.25 - x) * m), rel=1e-15)
    assert ToothSpec(m=m, x=x, tip_max_mm=3.0).h_tip_cut == pytest.approx(2.8, rel=1e-15)   # the nominal is lower
    assert ToothSpec(m=m, x=x).h_tip_cut == pytest.approx(2.8, rel=1e-15)                   # 0: no limit
    g = generate_teeth(_circular_pair(m, z_H), "driven", spec)
    land = _land(40, m, x, 40 + 2.5)
    assert all(t.tip_height_mm == 2.5 and not t.shortened for t in g.teeth)
    assert all(t.tip_thickness_mm == pytest.approx(land, rel=1e-9) for t in g.teeth)


@pytest.mark.parametrize("x, undercut", [(0.0, True), (0.2, True), (0.4, False)])
def test_a_small_driver_is_undercut_below_the_iso_limiting_shift(x, undercut):
    # z = 12: x_min = h_a* - z sin^2(alpha) / 2 = 0.298
    m = 2.0
    assert 1 - 12 * math.sin(ALPHA) ** 2 / 2 == pytest.approx(0.2981, abs=1e-4)
    g = generate_teeth(_circular_pair(m, 24), "driver", ToothSpec(m=m, x=x))
    assert g.z == 12 and all(t.undercut is undercut for t in g.teeth)
    for right, left in g.sides:
        for side in (right, left):
            assert side.undercut is undercut
            # the trimmed fillet ends where the trimmed flank begins (the crossing of the two envelopes)
            assert np.linalg.norm(side.fillet.at(side.fillet.u1) - side.flank.at(side.flank.u0)) < 1e-6


def test_the_driver_needs_a_whole_number_of_teeth_a_turn():
    m = 2.0
    pc = PitchCurves(EllipticalLaw(e=0.0, k=2), 3 * m * 41 / 4)       # 41 teeth on the driven circle
    assert generate_teeth(pc, "driven", ToothSpec(m=m)).z == 41
    # no lobe of whole teeth: the driven wheel asked to be cut as one is cut tooth by tooth
    g = generate_teeth(pc, "driven", ToothSpec(m=m), lobe=True)
    assert (g.z, g.lobes, len(g.sides)) == (41, 1, 41)
    assert _refusal(lambda: generate_teeth(pc, "driver", ToothSpec(m=m))) == "z_H = 41: must be a multiple of n = 2"


def test_sides_within_one_and_a_half_pitches_of_a_concave_stretch_are_cut_by_the_shaper():
    law = EllipticalLaw(e=0.5, k=3)                  # the driven curve is concave about its 3 waists
    m = 2.0
    pc0 = PitchCurves(law, 100.0)
    z_H = round(pc0.perimeter_driven() / (math.pi * m) / 3) * 3
    pc = PitchCurves(law, 100.0 * z_H * math.pi * m / pc0.perimeter_driven())
    frame = ArcFrame(pc)
    p = math.pi * m
    cs = pc.curvature("driven")
    assert cs.concave
    zones = [(float(frame.s(np.array([a + k * law.period]))[0]), float(frame.s(np.array([b + k * law.period]))[0]))
             for a, b in cs.concave_intervals for k in range(-1, law.periods + 2)]
    g = generate_teeth(pc, "driven", ToothSpec(m=m, z0=20), frame=frame)
    kinds = [t.right for t in g.teeth]
    expect = ["shaper" if any(a - SHAPER_MARGIN_PITCHES * p <= (k + 0.5) * p <= b + SHAPER_MARGIN_PITCHES * p
                              for a, b in zones) else "rack" for k in range(g.z)]
    assert kinds == expect and [t.left for t in g.teeth] == expect
    assert 0 < expect.count("shaper") < g.z
    assert _refusal(lambda: generate_teeth(pc, "driven", ToothSpec(m=m), frame=frame)) == (
        "z0 = None: a concave pitch curve needs a shaper cutter")
    # the convex driver is all rack
    assert {t.right for t in generate_teeth(pc, "driver", ToothSpec(m=m), frame=frame).teeth} == {"rack"}


def test_cutter_numbers_are_kept_as_python_floats_and_any_pressure_angle_below_a_right_angle_is_taken():
    c = CutterSpec(m=np.float32(2.5), h_a=np.float32(0.8), x=np.float32(0.25), x_H=np.float32(-0.25), z0=np.int64(20))
    assert [type(v) for v in (c.m, c.h_a, c.x, c.x_H, c.z0)] == [float, float, float, float, int]
    assert (c.m, c.h_a, c.x, c.x_H, c.z0) == (2.5, float(np.float32(0.8)), 0.25, -0.25, 20)
    steep = CutterSpec(m=2.0, alpha=1.2)                           # 68.8 deg: above pi/3, below pi/2
    assert steep.rho_limit(0.0) == pytest.approx(2.0 / math.sin(1.2) ** 2, rel=1e-15)


def test_a_convex_radius_equal_to_the_rack_limit_is_generable_and_a_shaper_equal_to_the_concave_radius_is_not():
    c = CutterSpec(m=2.0, x=0.25, z0=20)
    lim = (1.0 - 0.25) * 2.0 / math.sin(math.radians(20.0)) ** 2      # the limit's own floats
    assert _check_curve(_summary(convex=lim), c, 0.25).ok
    eq = _check_curve(_summary(convex=50.0, concave=True, rho_cc=20.0), c, 0.25)
    assert not eq.ok
    good = _check("driven", 50.0, 5.0, ok=True)
    # remedies: none for a convex radius at the limit; the shaper remedy for a concave radius equal to r0
    assert remedies(Generability(_check("driver", lim, lim, True, 50.0, 20.0), good), c, 60, 2, 120.0) == []
    assert remedies(Generability(good, _check("driven", 50.0, 5.0, True, 20.0, 20.0)), c, 60, 2, 120.0) == [
        "driven: concave |rho|_min 20.000 mm needs a shaper with z0 <= 19 (r0 < |rho|)"]


def test_remedies_of_a_thin_convex_radius_and_the_smallest_shaper_there_is():
    c = CutterSpec(m=2.0, x=0.2, z0=20)
    good = _check("driven", 50.0, 5.0, ok=True)
    lim = (1.0 - 0.2) * 2.0 / S2_20
    bits = remedies(Generability(_check("driver", 0.5, lim), good), c, 60, 2, 120.0)   # 0.5 mm: below 1, above 0
    x_need = 1.0 - 0.5 * S2_20 / 2.0
    z_need = math.ceil(60 * lim / 0.5 / 2) * 2
    assert bits == [f"driver: convex rho_min 0.500 mm < undercut limit {lim:.3f} mm; works with x >= {x_need:.3f}, "
                    f"or z_H >= {z_need} at m = 2, or m <= {0.5 * S2_20 / 0.8:.4g} mm at L = 120.000 mm"]
    # a shaper has at least 6 teeth: 6 fits inside |rho| = 6.5 mm (r0 = 6 mm), none fits inside 5.5 mm
    assert remedies(Generability(good, _check("driven", 50.0, 5.0, True, 6.5, 20.0)), c, 60, 2, 120.0) == [
        "driven: concave |rho|_min 6.500 mm needs a shaper with z0 <= 6 (r0 < |rho|)"]
    assert remedies(Generability(good, _check("driven", 50.0, 5.0, True, 5.5, 20.0)), c, 60, 2, 120.0) == [
        "driven: concave |rho|_min 5.500 mm: no shaper within the limits fits inside it (r0 < |rho|; a smoother law)"]


def test_the_least_value_of_a_cubic_on_the_unit_interval_against_a_dense_sampling():
    from propulsor.gears.smoothed_law import cubic_min_01

    rng = np.random.default_rng(7)
    w = np.linspace(0.0, 1.0, 200_001)
    kinds = {"end": 0, "inside": 0}
    for _ in range(300):
        a = rng.normal(size=4) * rng.choice([0.1, 1.0, 10.0], size=4)
        p = a[0] + w * (a[1] + w * (a[2] + w * a[3]))
        k = int(np.argmin(p))
        kinds["inside" if 0 < k < len(w) - 1 else "end"] += 1
        assert cubic_min_01(*a) == pytest.approx(float(p.min()), abs=1e-9 * (1 + np.abs(a).sum()))
        assert cubic_min_01(*a) <= float(p.min()) + 1e-12 * (1 + np.abs(a).sum())
    assert min(kinds.values()) > 30
    # complex critical points (p' = 1 + w^2 > 0 has none real) and real ones outside: only the ends count
    assert cubic_min_01(0.0, 1.0, 0.0, 1.0 / 3) == 0.0
    assert cubic_min_01(1.0, -3.0, 0.0, 1.0) == pytest.approx(1 - 3 + 1, rel=1e-15)   # p' = 0 at w = 1 exactly
    assert cubic_min_01(0.0, -3.0 * 1.5 ** 2, 0.0, 1.0) == pytest.approx(-6.75 + 1, rel=1e-15)  # root at 1.5: the end
    # the smoothed law's blend: its least value is the hand-over's for a shallow dip
    sl = SmoothedWalkingLaw(LAW0, 0.3, 0.05)
    assert sl._blend_min() == pytest.approx(0.05, rel=1e-12)
    t = np.linspace(-0.29, 0.29, 7)
    assert np.array_equal(sl.blend(t), sl.blend(t, 0))
    np.testing.assert_allclose(sl.blend(t), sl.U(math.pi / 4 + t), rtol=1e-13)


# ---- generated teeth of circular spur gears and rings (gears/generation.py) ----------------------------------------

from propulsor.gears.cutters import ShaperCutter  # noqa: E402
from propulsor.gears.generation import generate_external_side, generate_internal_side  # noqa: E402
from propulsor.gears.involute import inv_inverse  # noqa: E402

RACK = BasicRack()


@pytest.mark.parametrize("z, x, th", [(20, 0.0, 0.0), (30, 0.5, 0.0), (12, 0.0, 0.0), (25, -0.3, 0.1)])
def test_an_external_sides_radii_and_angles_by_hand(z, x, th):
    m = 2.0
    s = generate_external_side(z, m, x, thinning_n_mm=th)
    r = m * z / 2
    r_a = r + (1 + x) * m
    assert (s.r, s.r_b, s.r_a, s.r_f) == pytest.approx((r, r * math.cos(ALPHA), r_a, r - (1.25 - x) * m), rel=1e-15)
    assert (s.z, s.internal, s.undercut) == (z, False, z == 12)
    # the rack's tip land rolls out the root circle: its end at pi m/4 - h_fP tan a - rho_fP tan(pi/4 - a/2) from
    # the space's centre line is the fillet's start; thinning turns the side thinning / 2r towards the tooth centre
    half_land = math.pi * m / 4 - 1.25 * m * math.tan(ALPHA) - 0.38 * m * math.tan(math.pi / 4 - ALPHA / 2)
    assert s.root_angle == pytest.approx(math.pi / z - half_land / r - th / (2 * r), abs=1e-13)
    assert s.tip_angle == pytest.approx(_land(z, m, x, r_a, th) / (2 * r_a), abs=1e-13)
    # the rack's numbers: eta_f the depth of its tip line below the rolling line, its tip round, its space width
    assert s.extra["eta_f"] == pytest.approx(-(1.25 - x) * m + 0.38 * m * (1 - math.sin(ALPHA)), rel=1e-12)
    assert s.extra["rho"] == pytest.approx(0.38 * m, rel=1e-15)
    assert s.extra["w"] == pytest.approx(m * (math.pi / 2 + 2 * x * math.tan(ALPHA)), rel=1e-15)
    # the flank ends on the tip circle, the fillet starts on the root circle
    assert np.hypot(*s.flank.at(s.flank.u1)) == pytest.approx(r_a, abs=1e-9)
    assert np.hypot(*s.fillet.at(s.fillet.u0)) == pytest.approx(s.r_f, abs=1e-9)


def test_a_given_tip_diameter_is_kept():
    s = generate_external_side(20, 2.0, 0.0, d_a=43.0)
    assert s.r_a == 21.5 and np.hypot(*s.flank.at(s.flank.u1)) == pytest.approx(21.5, abs=1e-9)


def test_dense_points_of_one_pitch_by_hand():
    z, m = 20, 2.0
    s = generate_external_side(z, m, 0.0)
    d = s.dense(51)
    assert set(d) == {"fillet", "flank", "fillet_mirror", "flank_mirror", "tip", "root"}
    assert all(v.shape == (51, 2) for v in d.values())
    assert np.array_equal(d["fillet_mirror"], d["fillet"] * [-1, 1])
    assert np.array_equal(d["flank_mirror"], d["flank"] * [-1, 1])
    ta, ra = s.tip_angle, s.root_angle
    # the tip arc across the tooth from this side's end to the mirrored one; the root arc across the space on the right
    np.testing.assert_allclose(np.hypot(*d["tip"].T), s.r_a, rtol=1e-15)
    np.testing.assert_allclose(np.arctan2(d["tip"][:, 0], d["tip"][:, 1]), np.linspace(ta, -ta, 51), atol=1e-15)
    np.testing.assert_allclose(np.hypot(*d["root"].T), s.r_f, rtol=1e-15)
    np.testing.assert_allclose(np.arctan2(d["root"][:, 0], d["root"][:, 1]),
                               np.linspace(ra, 2 * math.pi / z - ra, 51), atol=1e-14)
    np.testing.assert_allclose(d["flank"][-1], d["tip"][0], atol=1e-9)
    np.testing.assert_allclose(d["fillet"][0], d["root"][0], atol=1e-9)
    assert len(s.dense()["flank"]) == 400


def test_an_external_sides_refusals_in_full():
    assert _refusal(lambda: generate_external_side(2, 2.0)) == "z = 2: must be >= 3"
    assert _refusal(lambda: generate_external_side(20, 0.0)) == "m = 0.0: must be > 0 mm"
    assert _refusal(lambda: generate_external_side(20, 2.0, math.nan)) == "x = nan: must be a finite number"
    assert _refusal(lambda: generate_external_side(20, 2.0, thinning_n_mm=math.inf)) == (
        "thinning_n_mm = inf: must be a finite number")
    assert _refusal(lambda: generate_external_side(20, 2.0, d_a=0.0)) == "d_a = 0.0: must be > 0 mm"
    # root radius r + eta_t = 20 - (1.25 - x) 2 > 0 needs x > -8.75
    assert _refusal(lambda: generate_external_side(20, 2.0, -8.75)) == (
        "x = -8.75: root radius must be > 0 (r_f = 0 mm)")
    # the tip must clear the root and base circles (base: 20 cos 20 deg = 18.794 mm)
    r_b = 20 * math.cos(ALPHA)
    assert _refusal(lambda: generate_external_side(20, 2.0, 0.0, d_a=2 * r_b)) == (
        f"d_a = {2 * r_b!r}: must exceed the root and base diameters ({2 * r_b:.6f} mm)")
    assert _refusal(lambda: generate_external_side(20, 2.0, 1.0, d_a=38.9)) == (   # root 20 - 0.25 x 2 = 19.5 mm
        "d_a = 38.9: must exceed the root and base diameters (39.000000 mm)")
    # the form circle: where the rack's straight flank ends, d = (h_fP* - x) m - rho_fP (1 - sin a) below the rolling
    # line, d / sin a from the pitch point along the line of action
    depth = (1.25 - 0.6) * 2.0 - 0.38 * 2.0 * (1 - math.sin(ALPHA))
    r_Ff = math.hypot(20 * math.cos(ALPHA), 20 * math.sin(ALPHA) - depth / math.sin(ALPHA))
    assert _refusal(lambda: generate_external_side(20, 2.0, 0.6, d_a=38.4)) == (
        f"d_a = 38.4: must exceed the form diameter d_Ff = {2 * r_Ff:.6f} mm")
    # a tip so large that the tooth is pointed below it
    assert _refusal(lambda: generate_external_side(20, 2.0, 0.0, d_a=47.0)) == (
        "d_a = 47.0: tooth is pointed below the tip circle")
    # thinning so large that the fillets of one space overlap
    assert _refusal(lambda: generate_external_side(20, 2.0, 0.0, thinning_n_mm=-4.0)) == (
        "thinning_n_mm = -4.0: fillets of one space overlap")


def test_a_ring_sides_machining_numbers_by_gost_19274():
    z, m, x, z0, x0 = 60, 2.0, 0.3, 20, 0.1
    shaper = ShaperCutter(z0, m, x0)
    d_a = 2 * (m * z / 2 - (1 - x) * m)
    s = generate_internal_side(z, m, x, d_a, shaper)
    a_w0_ang = float(inv_inverse(float(inv(ALPHA)) + 2 * math.tan(ALPHA) * (x - x0) / (z - z0)))
    a_w0 = m * (z - z0) / 2 * math.cos(ALPHA) / math.cos(a_w0_ang)
    r_a0 = m * (z0 + 2 * (1.25 + x0)) / 2
    assert s.extra == pytest.approx({"a_w0": a_w0, "alpha_w0": a_w0_ang, "r_w0": a_w0 * z0 / (z - z0),
                                     "r_w": a_w0 * z / (z - z0), "d_a0": 2 * r_a0}, rel=1e-12)
    assert (s.r, s.r_b, s.r_a, s.r_f) == pytest.approx((60.0, 60 * math.cos(ALPHA), d_a / 2, a_w0 + r_a0), rel=1e-12)
    assert (s.z, s.internal) == (60, True)
    # the ring's space on +y: its half angle at the tip circle e_a / (2 r_a), with e = m (pi/2 + 2 x tan a)
    e = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    a_a = math.acos(60 * math.cos(ALPHA) / s.r_a)
    assert s.tip_angle == pytest.approx(e / 120 + float(inv(ALPHA)) - float(inv(a_a)), abs=1e-11)
    assert s.undercut is False
    d = s.dense(31)
    np.testing.assert_allclose(np.arctan2(d["tip"][:, 0], d["tip"][:, 1]),
                               np.linspace(s.tip_angle, 2 * math.pi / z - s.tip_angle, 31), atol=1e-14)
    np.testing.assert_allclose(np.arctan2(d["root"][:, 0], d["root"][:, 1]),
                               np.linspace(s.root_angle, -s.root_angle, 31), atol=1e-14)
    # thinning widens the space: the side turns thinning / 2r away from the space's centre line
    t = generate_internal_side(z, m, x, d_a, shaper, thinning_n_mm=0.1)
    assert t.tip_angle == pytest.approx(s.tip_angle + 0.1 / 120, abs=1e-13)
    assert t.root_angle == pytest.approx(s.root_angle + 0.1 / 120, abs=1e-13)


def test_a_ring_sides_refusals_in_full():
    sh = ShaperCutter(20, 2.0, 0.0)
    assert _refusal(lambda: generate_internal_side(23, 2.0, 0.0, 40.0, sh)) == "z = 23: ring needs z >= z0 + 4 = 24"
    four_more = generate_internal_side(24, 2.0, 0.5, 46.0, sh)                 # z0 + 4 teeth: cut
    assert four_more.z == 24 and four_more.r_a == 23.0
    assert _refusal(lambda: generate_internal_side(60, 2.5, 0.0, 117.0, sh)) == "m = 2.5: must equal the shaper module 2.0"
    assert _refusal(lambda: generate_internal_side(60, 2.0, math.nan, 117.0, sh)) == "x = nan: must be a finite number"
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, 117.0, sh, math.inf)) == (
        "thinning_n_mm = inf: must be a finite number")
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, -1.0, sh)) == "d_a = -1.0: must be > 0 mm"
    # x - x0 so negative that inv alpha_w0 <= 0: inv 20 deg + 2 tan 20 deg (x / 40) <= 0 below x = -0.8345
    x_lo = -float(inv(ALPHA)) * 40 / (2 * math.tan(ALPHA))
    assert _refusal(lambda: generate_internal_side(60, 2.0, x_lo - 0.01, 117.0, sh)) == (
        f"x = {x_lo - 0.01!r}: machining pressure angle would be <= 0 (x − x0 too negative)")
    # the root: a_w0 = 40 mm (x = x0), r_a0 = m (z0 + 2 (h_a* + c* + x0)) / 2 = 22.5 mm
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, 125.2, sh)) == (
        "d_a = 125.2: must be < root diameter 125.000000 mm")
    r_b = 60 * math.cos(ALPHA)
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, 2 * r_b, sh)) == (
        f"d_a = {2 * r_b!r}: must be > base diameter {2 * r_b:.6f} mm")


def _to_polyline(P: np.ndarray, Q: np.ndarray) -> np.ndarray:
    """Distance of each point P to the polyline Q (point to segment, exact)."""
    A, B = Q[:-1], Q[1:]
    AB = B - A
    L2 = np.einsum("ij,ij->i", AB, AB)
    out = []
    for p in P:
        t = np.clip(np.einsum("ij,ij->i", p - A, AB) / L2, 0.0, 1.0)
        out.append(float(np.min(np.linalg.norm(A + t[:, None] * AB - p, axis=1))))
    return np.array(out)


def test_a_shaper_of_its_own_shift_cuts_the_racks_flank_and_its_root_gap_is_measured():
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import make_side

    law = EllipticalLaw(e=0.5, k=3)
    m, x = 2.0, 0.2
    pc0 = PitchCurves(law, 100.0)
    z_H = round(pc0.perimeter_driven() / (math.pi * m) / 3) * 3
    pc = PitchCurves(law, 100.0 * z_H * math.pi * m / pc0.perimeter_driven())
    frame = ArcFrame(pc)
    spec = ToothSpec(m=m, x=x, z0=20, shaper=ShaperCutter(20, m, 0.1))      # e = (x + x0) m = 0.6 mm
    g = generate_teeth(pc, "driven", spec, frame=frame)
    rack = spec.rack_tools()
    shaped = [k for k, t in enumerate(g.teeth) if t.right == "shaper"]
    assert len(shaped) == 24 and all(t.tip_height_mm == (1 + x) * m for t in g.teeth)
    gaps = []
    for k in shaped[:3] + shaped[-2:]:
        tooth = g.teeth[k]
        for which in (0, 1):
            side = g.sides[k][which]
            # the same imaginary rack: the shaper's flank is the rack's flank of this tooth (Aronhold-Kennedy)
            ref = make_side(rack[which], PitchCurveCentrode(g.curve, frame, tooth.s_centre))
            dense = ref.flank(np.linspace(ref.flank.u0, ref.flank.u1, 4001))
            u_tip = g.tips[k][1 + which][0]
            P = side.flank(np.linspace(side.flank.u0 + 0.3 * (u_tip - side.flank.u0), u_tip, 12))
            assert _to_polyline(P, dense).max() < 1e-6
            # the root gap: the distance from the fillet's start to the root equidistant, its foot at phi_root
            X0 = side.fillet.at(side.fillet.u0)
            ph = side.phi_root + np.linspace(-0.02, 0.02, 40001)
            E = g.curve.offset(ph, -spec.h_root)
            j = int(np.argmin(np.linalg.norm(E - X0, axis=1)))
            assert side.root_gap_mm == pytest.approx(float(_to_polyline(X0[None, :], E)[0]), abs=1e-9)
            assert side.phi_root == pytest.approx(float(ph[j]), abs=2e-6)
            gaps.append(side.root_gap_mm)
    assert max(gaps) > 1e-3                   # the re-phased shaper leaves a gap of microns there


def test_the_helpers_of_the_teeth_on_circles_by_hand():
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, _concave_zones
    from propulsor.gears.tip_search import land_length, near

    m, z_H = 2.0, 40
    pc = _circular_pair(m, z_H)                       # driven radius 40 mm, driver 20 mm turning twice as fast
    driven, driver = BodyPitchCurve(pc, "driven"), BodyPitchCurve(pc, "driver")
    # the tip equidistant's arc between two driven angles: (r + h) times the body's turn
    assert land_length(driven, 2.5, 0.1, 0.4) == pytest.approx(42.5 * 0.3, rel=1e-9)
    assert land_length(driven, -1.0, 0.4, 0.1) == pytest.approx(39.0 * 0.3, rel=1e-9)
    assert land_length(driver, 2.5, 0.1, 0.4) == pytest.approx(22.5 * 2 * 0.3, rel=1e-9)
    # a solver's angle moved by whole turns of the body next to the reference: 2 pi driven, 2 pi / n = pi driver
    assert near(0.3 + 2 * math.pi, 0.25, driven) == pytest.approx(0.3, abs=1e-15)
    assert near(0.3 - 3 * 2 * math.pi, 0.25, driven) == pytest.approx(0.3, abs=1e-14)
    assert near(0.3 + math.pi, 0.25, driver) == pytest.approx(0.3, abs=1e-15)
    assert near(0.3 + 0.9 * math.pi, 0.25, driven) == pytest.approx(0.3 + 0.9 * math.pi, abs=1e-15)  # < half a turn
    assert near(0.3 + 0.45 * math.pi, 0.25, driver) == pytest.approx(0.3 + 0.45 * math.pi, abs=1e-15)
    # concave stretches: none on circles; on the 3-lobed ellipse's driven curve every leg's, one more either side
    assert _concave_zones(driven) == []
    law = EllipticalLaw(e=0.5, k=3)
    lobed = BodyPitchCurve(PitchCurves(law, 100.0), "driven")
    iv = lobed.pc.curvature("driven").concave_intervals
    zones = _concave_zones(lobed)
    assert len(zones) == len(iv) * (law.periods + 3)
    assert zones == [(a + k * law.period, b + k * law.period) for a, b in iv for k in range(-1, law.periods + 2)]
    assert _concave_zones(BodyPitchCurve(PitchCurves(law, 100.0), "driver")) == []
    # the heights of points above an equidistant at their feet: on the driven circle (r = 40) the radius less 40 + h,
    # whatever the grid's nearest sample (1.5 degrees apart); on the driver circle (r = 20) likewise, and 0 on it
    ang = np.array([0.1013, 0.2, 0.3371, 0.41])
    grid = np.linspace(0.0, 0.5, 21)
    for h in (0.0, 2.5, -1.25):
        for d in (0.7, -0.3):
            P = (40.0 + h + d) * np.column_stack([np.cos(ang), np.sin(ang)])
            assert driven.heights(P, h, grid) == pytest.approx(np.full(4, d), abs=1e-12)
    on = driver.point(ang)
    assert driver.heights(on * 1.05, 0.0, grid) == pytest.approx(np.full(4, 1.0), abs=1e-12)
    assert driver.heights(on, 0.0, grid) == pytest.approx(np.zeros(4), abs=1e-12)


def test_an_external_side_of_three_teeth_a_stub_rack_a_steep_rack_and_a_small_module():
    assert generate_external_side(3, 2.0, 0.0).z == 3                     # 3 teeth: the least there is
    stub = BasicRack(h_a_star=0.8)
    assert generate_external_side(20, 2.0, 0.1, rack=stub).r_a == pytest.approx(2.0 * (20 + 1.6 + 0.2) / 2, rel=1e-15)
    # a 25 deg rack cuts the 25 deg involute: its tip land by ISO 21771 with alpha = 25 deg
    a25 = math.radians(25.0)
    steep = generate_external_side(20, 2.0, 0.0, rack=BasicRack(alpha=a25, rho_f_star=0.3))
    r, r_a = 20.0, 22.0
    a_a = math.acos(r * math.cos(a25) / r_a)
    assert steep.tip_angle == pytest.approx(math.pi / 40 + float(inv(a25)) - float(inv(a_a)), abs=1e-12)
    # a module of 0.1 mm: a root radius below 1 mm is still a root
    tiny = generate_external_side(20, 0.1, 0.0)
    assert tiny.r_f == pytest.approx(1.0 - 0.125, rel=1e-15)


def test_a_tip_on_the_form_circle_is_refused_and_just_above_it_is_cut():
    s = generate_external_side(20, 2.0, 0.6)
    assert _refusal(lambda: generate_external_side(20, 2.0, 0.6, d_a=2 * s.r_Ff)) == (
        f"d_a = {2 * s.r_Ff!r}: must exceed the form diameter d_Ff = {2 * s.r_Ff:.6f} mm")
    assert generate_external_side(20, 2.0, 0.6, d_a=2 * s.r_Ff + 0.01).r_a == s.r_Ff + 0.005


def test_a_ring_sides_limits_in_full_on_both_sides():
    m = 2.0
    a = ALPHA
    # the shaper's generating limit: its base circle generates the ring point a_w0 sin(alpha_w0) along the line of
    # action from the ring's base circle
    z, z0, x, x0 = 13, 8, 1.0, -0.2
    sh = ShaperCutter(z0, m, x0)
    aw = float(inv_inverse(float(inv(a)) + 2 * math.tan(a) * (x - x0) / (z - z0)))
    a_w0 = m * (z - z0) / 2 * math.cos(a) / math.cos(aw)
    d_end = 2 * math.hypot(m * z / 2 * math.cos(a), a_w0 * math.sin(aw))
    assert _refusal(lambda: generate_internal_side(z, m, x, d_end - 0.005, sh)) == (
        f"d_a = {d_end - 0.005!r}: ring tip inside the shaper's generating limit: must be >= {d_end:.6f} mm (the "
        "shaper base circle generates no involute below it)")
    assert generate_internal_side(z, m, x, d_end + 0.005, sh).r_a == pytest.approx(d_end / 2 + 0.0025, rel=1e-15)
    # the form circle: where the shaper's tip round begins, a_w0 sin(alpha_w0) + r_b0 t_s along the line of action
    z, z0, x, x0 = 60, 20, 0.3, 0.1
    sh = ShaperCutter(z0, m, x0)
    aw = float(inv_inverse(float(inv(a)) + 2 * math.tan(a) * (x - x0) / (z - z0)))
    a_w0 = m * (z - z0) / 2 * math.cos(a) / math.cos(aw)
    d_Ff = 2 * math.hypot(60 * math.cos(a), a_w0 * math.sin(aw) + sh.r_b0 * sh.tip_round[0])
    assert _refusal(lambda: generate_internal_side(z, m, x, d_Ff + 0.01, sh)) == (
        f"d_a = {d_Ff + 0.01!r}: must be < the form diameter d_Ff = {d_Ff:.6f} mm")
    ok = generate_internal_side(z, m, x, d_Ff - 0.01, sh)
    assert ok.r_Ff == pytest.approx(d_Ff / 2, rel=1e-12)
    # at the form circle itself, and at the root circle itself: refused
    assert _refusal(lambda: generate_internal_side(z, m, x, 2 * ok.r_Ff, sh)) == (
        f"d_a = {2 * ok.r_Ff!r}: must be < the form diameter d_Ff = {2 * ok.r_Ff:.6f} mm")
    assert _refusal(lambda: generate_internal_side(z, m, x, 2 * ok.r_f, sh)) == (
        f"d_a = {2 * ok.r_f!r}: must be < root diameter {2 * ok.r_f:.6f} mm")


def test_a_ring_space_thinned_until_its_tooth_is_pointed_or_narrowed_until_its_root_land_vanishes():
    sh = ShaperCutter(20, 2.0, 0.0)
    s = generate_internal_side(60, 2.0, 0.0, 117.0, sh)
    # thinning turns each side of the space thinning / 2r outwards: the tooth is pointed when the space's half angle
    # at the tip circle reaches half a pitch, pi / z; the root land vanishes when the root angle reaches 0
    th_pointed = (math.pi / 60 - s.tip_angle) * 120
    th_root = -s.root_angle * 120
    assert 2.0 < th_pointed < 2.3 and -0.6 < th_root < -0.4
    assert generate_internal_side(60, 2.0, 0.0, 117.0, sh, th_pointed - 0.01).tip_angle < math.pi / 60
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, 117.0, sh, th_pointed + 0.01)) == (
        f"d_a = 117.0: ring tooth is pointed at the tip circle")
    assert generate_internal_side(60, 2.0, 0.0, 117.0, sh, th_root + 0.01).root_angle > 0
    shown = repr(sh)
    shown = shown[:120] + "…" if len(shown) > 120 else shown
    assert _refusal(lambda: generate_internal_side(60, 2.0, 0.0, 117.0, sh, th_root - 0.01)) == (
        f"shaper = {shown}: root land of the ring space vanished")


def test_a_law_without_a_corner_takes_the_least_blend_the_search_tries():
    from propulsor.policy import SMOOTHING_DELTA_MIN_RAD

    c = CutterSpec(m=2.0, x=0.0, z0=20)
    flat = WalkingLaw(a=60.0, b=0.0, c=360.0, n=2)          # no crank: U is constant, no corner to smooth
    d = choose_smoothing(flat, c, 96)
    assert d.delta == SMOOTHING_DELTA_MIN_RAD and d.generability.ok
    assert d.z == 48 and d.z_H == 96 and type(d.z) is int
    # a mild corner (b = 1 mm): bisected between the last failing and the first passing half-width as usual
    mild = WalkingLaw(a=60.0, b=1.0, c=360.0, n=2)
    m = choose_smoothing(mild, c, 96)
    assert SMOOTHING_DELTA_MIN_RAD < m.delta < 0.01
    assert _generable(mild, c, 96, m.delta).ok and not _generable(mild, c, 96, m.delta * (1 - 2e-6)).ok


# ---- the polysector (gears/polysector.py) ---------------------------------------------------------------------------

def test_the_conditional_tooth_count_and_the_pressure_angle_of_a_flank_contact():
    from propulsor.gears.polysector import PolysectorGeometry, pole_flank, ratio_eq7

    g = PolysectorGeometry(m=4.0, z=30, z_c=9, i_s=3, z2=24)
    # the conditional pitch circle r + e: z_cond = 2 (r + e) / m
    assert g.z_cond(6.0) == pytest.approx(2 * (60.0 + 6.0) / 4.0, rel=1e-15)
    assert g.z_cond(0.0) == 30.0 and g.z_cond(g.offset_for(42)) == pytest.approx(42.0, rel=1e-15)
    # at e = 0 the sector is the blank: the pole is the pitch point, the working pressure angle the blank's
    u = np.linspace(-0.2, 0.2, 9)
    np.testing.assert_allclose(g.alpha_wt_flank(0.0, u), math.radians(20.0), atol=1e-12)
    # off centre: cos(alpha_wt) = r_b2 / O2P at the pole of the flank contact, and eq. 7 with it is the ratio
    e = 6.0
    a = 60.0 + e + 48.0
    o2p = pole_flank(e, u, 60.0 * math.cos(math.radians(20.0)), 48.0 * math.cos(math.radians(20.0)), a)[0]
    aw = g.alpha_wt_flank(e, u)
    np.testing.assert_allclose(np.cos(aw), 48.0 * math.cos(math.radians(20.0)) / o2p, rtol=1e-14)
    assert np.ptp(aw) > 1e-3                      # the pole moves as the sector turns
    np.testing.assert_allclose(g.ratio_flank(e, u), ratio_eq7(48.0, a, math.radians(20.0), aw), rtol=1e-14)


def test_the_polysector_geometrys_refusals_in_full_and_eq1_as_printed():
    from propulsor.gears.polysector import PolysectorGeometry, delta_eq1_printed

    base = dict(m=3.0, z=36, z_c=10, i_s=3, z2=40)
    assert _refusal(lambda: PolysectorGeometry(**{**base, "flows": 3})) == "flows = 3: must be 1 or 2"
    assert PolysectorGeometry(**{**base, "flows": 1}).n_sectors == 3
    assert _refusal(lambda: PolysectorGeometry(**{**base, "z": 33})) == (
        "z = 33: must be a multiple of i_s·flows = 6 (sectors equally spaced in tooth phase)")
    assert PolysectorGeometry(**{**base, "z": 33, "z_c": 9, "flows": 1}).k_gap == 2      # 33 = 3 x 11: one flow
    assert _refusal(lambda: PolysectorGeometry(**{**base, "z_c": 12})) == (
        "z_c = 12: too large for the gaps: eq. 2 z_c = z/i_s − (1…3) ≤ 11")
    assert PolysectorGeometry(**{**base, "z_c": 11}).k_gap == 1
    assert _refusal(lambda: PolysectorGeometry(**{**base, "z_c": 1})) == "z_c = 1: must be >= 2"
    assert PolysectorGeometry(**{**base, "z_c": 2}).k_gap == 10
    # eq. 1's delta as the seed prints it: (2 z_c - 1) pi / 2z - inv(alpha) + inv(alpha_a)
    r_b, r_a = 54.0 * math.cos(ALPHA), 57.0
    a_a = math.acos(r_b / r_a)
    assert delta_eq1_printed(10, 36, ALPHA, r_b, r_a) == pytest.approx(
        19 * math.pi / 72 - (math.tan(ALPHA) - ALPHA) + (math.tan(a_a) - a_a), rel=1e-14)


def test_the_tip_lands_distance_from_the_gears_axis_against_a_dense_sampling():
    from propulsor.gears.polysector import PolysectorGeometry

    g = PolysectorGeometry(m=3.0, z=36, z_c=10, i_s=3, z2=40)
    d_in, d_out = g.tip_land()
    for e in (0.0, 4.5, 9.0):
        a = g.center_distance(e)
        inside = 0
        for u in np.linspace(-0.3, 1.2, 31):
            ox, oy = e * math.cos(u), e * math.sin(u)
            ang = np.linspace(u - d_out, u - d_in, 20001)          # the land's arc about O', radius r_a
            C = np.column_stack([ox + g.r_a * np.cos(ang), oy + g.r_a * np.sin(ang)])
            brute = float(np.min(np.hypot(C[:, 0] - a, C[:, 1])))
            assert g.tip_land_distance(e, u) == pytest.approx(brute, abs=1e-6)
            beta = math.atan2(-oy, a - ox)
            inside += (u - d_out) <= beta <= (u - d_in)
        assert 0 < inside < 31                                     # both branches: the nearest point inside, an end


def test_the_largest_offset_next_to_the_least_overlap_and_its_refusal():
    from propulsor.gears.polysector import PolysectorGeometry

    g = PolysectorGeometry(m=3.0, z=36, z_c=10, i_s=3, z2=40)
    eps0 = g.epsilon_s(0.0)[1]
    # asking for just under the overlap at e = 0: the largest offset is a few microns
    e = g.max_offset(eps_min=eps0 - 1e-6)
    assert 0.0 < e < 0.05
    assert g.epsilon_s(e)[1] == pytest.approx(eps0 - 1e-6, abs=1e-9)
    assert _refusal(lambda: g.max_offset(eps_min=eps0 + 1e-6)) == (
        f"z_c = 10: eq. 4: ε_s = {eps0:.4f} < {eps0 + 1e-6} already at e = 0; more teeth per sector or more sectors "
        "are needed")


def test_eq8_off_the_nominal_angle_and_the_tooth_position_rows_by_their_geometry():
    from propulsor.gears.polysector import PolysectorGeometry, ratio_eq7, ratio_error_eq8, tooth_position_error

    # eq. 8: (i_n - i_t) / i_n with i_n = r2 / (a - r2), at a working pressure angle of 23 deg
    aw = math.radians(23.0)
    i_n = 48.0 / (114.0 - 48.0)
    assert ratio_error_eq8(48.0, 114.0, ALPHA, aw) == pytest.approx(
        (i_n - ratio_eq7(48.0, 114.0, ALPHA, aw)) / i_n, rel=1e-14)
    assert abs(ratio_error_eq8(48.0, 114.0, ALPHA, aw)) > 0.01
    # the exit pose's record
    g = PolysectorGeometry(m=3.0, z=36, z_c=10, i_s=3, z2=40)
    pose = g.corner_pose(4.5)
    d = g.tip_land()[0]
    assert pose["u_exit"] == g.corner_exit(4.5, d) and pose["delta"] == d
    u, a = pose["u_exit"], g.center_distance(4.5)
    cx, cy = 4.5 * math.cos(u) + 57.0 * math.cos(u - d), 4.5 * math.sin(u) + 57.0 * math.sin(u - d)
    assert pose["beta2"] == pytest.approx(math.atan2(cy, a - cx), abs=1e-15)
    assert pose["O1C"] == pytest.approx(math.hypot(cx, cy), rel=1e-15)
    # eq. 15-22: every point on the circle r_y about O1; the conditional gear's flank by its own involute; the left
    # flank of tooth n the mirror of the right flank of tooth z_c + 1 - n
    m, z, z_c, e, r_y = 3.0, 36, 3, 5.0, 56.0
    rows = tooth_position_error(m, z, z_c, e, ALPHA, r_y)
    assert [(r["tooth"], r["flank"]) for r in rows] == [(n, f) for n in (1, 2, 3) for f in ("right", "left")]
    assert set(rows[0]) == {"tooth", "flank", "r_y", "x_cond", "y_cond", "x_sector", "y_sector", "R", "beta"}
    z_cond = 2 * (54.0 + e) / m
    r_b_cond = (54.0 + e) * math.cos(ALPHA)
    a_y = math.acos(r_b_cond / r_y)
    for r in rows:
        off = r["tooth"] - 2
        side = 1 if r["flank"] == "right" else -1
        assert r["r_y"] == r_y
        assert math.hypot(r["x_sector"], r["y_sector"] + e) == pytest.approx(r_y, abs=1e-9)
        th = off * 2 * math.pi / z_cond + side * (math.pi / (2 * z_cond) + float(inv(ALPHA)) - (math.tan(a_y) - a_y))
        assert (r["x_cond"], r["y_cond"] + e) == pytest.approx((r_y * math.sin(th), r_y * math.cos(th)), abs=1e-12)
        assert r["R"] == pytest.approx(math.hypot(r["x_cond"] - r["x_sector"], r["y_cond"] - r["y_sector"]), rel=1e-15)
        assert r["beta"] == pytest.approx(math.atan2(r["y_cond"] - r["y_sector"], r["x_cond"] - r["x_sector"]),
                                          abs=1e-15)
    for n in range(3):
        right, left = rows[2 * n], rows[2 * (2 - n) + 1]
        assert (left["x_sector"], left["y_sector"]) == pytest.approx((-right["x_sector"], right["y_sector"]), abs=1e-9)
    # below the conditional base circle: no conditional point (nan), the sector's still found where it reaches
    low = tooth_position_error(m, z, z_c, e, ALPHA, r_b_cond - 0.5)
    assert all(math.isnan(r["x_cond"]) and math.isnan(r["R"]) and math.isnan(r["beta"]) for r in low)


def test_the_polysector_drives_losses_and_its_equations_of_motion_by_hand():
    from propulsor.gears.polysector_dynamics import TorsionalModel, loss_eq12, loss_eq13

    # eq. 12 / 13 (14 internal): the sum 1/z1 + 1/z2 of an external mesh, the difference of an internal one
    f, m, aw, z1, z2, l1, l2 = 0.08, 3.0, math.radians(21.0), 20, 56, 4.0, 6.0
    for internal, s in ((False, 1 / 20 + 1 / 56), (True, 1 / 20 - 1 / 56)):
        assert loss_eq12(f, m, aw, z1, z2, l1, l2, internal) == pytest.approx(
            f / (m * math.cos(aw)) * s * (16.0 + 36.0) / 10.0, rel=1e-14)
        assert loss_eq13(f, 1.6, z1, z2, 0.9, internal) == pytest.approx(f * 1.6 * math.pi / 2 * s * 0.9, rel=1e-14)
    # eq. 9-11: M q'' = -K q - B q' - (J3 + J45, J45) acc - (M4, M4), each link damped at zeta
    tm = TorsionalModel(J1=1.0, J2=0.5, J3=0.2, J4=0.3, J5=0.4, c1=2.0e4, c2=3.0e4, i54=1.5, zeta=0.07, M4=12.0)
    J45 = 0.3 + 0.4 * 1.5 ** 2
    b1, b2 = tm.damping()
    assert b2 / (2 * math.sqrt(3.0e4 * J45)) == pytest.approx(0.07, rel=1e-14)
    assert b1 / (2 * math.sqrt(2.0e4 * (0.2 * J45 / (0.2 + J45) + J45))) == pytest.approx(0.07, rel=1e-14)
    A, g, h = tm.state_matrices()
    M = np.array([[0.2 + J45, J45], [J45, J45]])
    rng = np.random.default_rng(5)
    for _ in range(3):
        y, acc = rng.normal(size=4), float(rng.normal())
        dy = A @ y + g * acc + h
        assert dy[:2] == pytest.approx(y[2:], abs=1e-15)
        rhs = (-np.array([2.0e4 * y[0], 3.0e4 * y[1]]) - np.array([b1 * y[2], b2 * y[3]])
               - np.array([0.2 + J45, J45]) * acc - np.array([12.0, 12.0]))
        np.testing.assert_allclose(M @ dy[2:], rhs, rtol=1e-12, atol=1e-9)


def test_the_polysector_drives_torque_from_its_own_motion():
    from propulsor.gears.polysector_dynamics import TorsionalModel

    tm = TorsionalModel(J1=1.0, J2=0.5, J3=0.2, J4=0.3, J5=0.4, c1=2.0e4, c2=3.0e4, i54=1.5, zeta=0.07, M4=12.0)
    J45 = 0.3 + 0.4 * 1.5 ** 2
    # at rest under the load: the static deflection stays, M1 = Pi' M4 throughout (both integrations)
    for breaks in (None, [0.0, 10.0]):
        r = tm.simulate(5.0, lambda q: np.full_like(q, 0.4), lambda q: np.zeros_like(q), 0.2, n_out=201, breaks=breaks)
        np.testing.assert_allclose(r.q2, -12.0 / 2.0e4, rtol=1e-9)
        np.testing.assert_allclose(r.q3, -12.0 / 3.0e4, rtol=1e-9)
        np.testing.assert_allclose(r.M1, 0.4 * 12.0, rtol=1e-9)
        assert r.M1_static == pytest.approx(0.4 * 12.0, rel=1e-15) and r.torque_factor == pytest.approx(1.0, rel=1e-9)
        np.testing.assert_allclose(r.q1, 5.0 * r.t, rtol=1e-15)
    # a rippled transmission: M1 = J2 Pi' acc + Pi' (J3 (acc + q2'') + J45 (acc + q2'' + q3'') + M4), acc = Pi'' w0^2,
    # with q2'', q3'' the second differences of the motion the simulation returns
    w0 = 5.0
    P1 = lambda q: 0.4 + 0.02 * np.sin(3 * q)
    P2 = lambda q: 0.06 * np.cos(3 * q)
    r = tm.simulate(w0, P1, P2, 0.4, n_out=8001)
    dt = r.t[1] - r.t[0]
    d2 = lambda y: (y[2:] - 2 * y[1:-1] + y[:-2]) / dt ** 2
    acc = P2(r.q1[1:-1]) * w0 ** 2
    p1 = P1(r.q1[1:-1])
    M1 = 0.5 * p1 * acc + p1 * (0.2 * (acc + d2(r.q2)) + J45 * (acc + d2(r.q2) + d2(r.q3)) + 12.0)
    np.testing.assert_allclose(r.M1[1:-1], M1, rtol=2e-4)
    assert np.ptp(r.M1) > 0.05


# ---- shaper-cut sides (noncircular_teeth.ToothSpec.shaper_tools, make_side) -----------------------------------------

def _shaped_tooth(spec, m: float = 2.0, z_H: int = 40, k: int = 3):
    """The two sides of driven tooth k of the circular pair cut by ``spec``'s shaper (make_side, as generate_teeth
    does near a concave stretch), with the pieces to measure them."""
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, make_side

    pc = _circular_pair(m, z_H)
    frame, curve = ArcFrame(pc), BodyPitchCurve(pc, "driven")
    s_k = (k + 0.5) * math.pi * m
    ph_k = float(frame.phi(np.array([s_k]))[0])
    right, left = spec.shaper_tools()
    R, L = (make_side(tool, PitchCurveCentrode(curve, frame, s_k), spec.h_root) for tool in (right, left))
    return curve, ph_k, R, L, 1.5 * math.pi * m / (m * z_H / 2)


@pytest.mark.parametrize("x, thinning, own_x0", [(0.0, 0.0, None), (0.3, 0.0, None), (-0.2, 0.12, None),
                                                 (0.2, 0.0, 0.1), (0.2, 0.1, 0.1), (0.0, 0.08, -0.2)])
def test_shaper_cut_teeth_of_a_circular_gear_have_the_involute_gears_land_at_every_height(x, thinning, own_x0):
    """A shaper that meshes with the gear's imaginary rack generates the rack's involute: x0 = -x rolling on the pitch
    circle, or a catalogue shaper of its own x0 re-phased by e = (x + x0) m.  The land at radius r_y is ISO 21771's
    s_y = d_y (s / d + inv alpha - inv alpha_y) with s = m (pi/2 + 2 x tan alpha) - thinning, and the tooth is
    centred on its centre line."""
    from propulsor.gears.tip_search import land_length, tip_hit

    m = 2.0
    shaper = None if own_x0 is None else ShaperCutter(20, m, own_x0)
    spec = ToothSpec(m=m, x=x, thinning_mm=thinning, z0=24, shaper=shaper)
    curve, ph_k, R, L, span = _shaped_tooth(spec)
    assert (R.kind, L.kind) == ("shaper", "shaper")
    for h in (0.0, 0.35 * (1 + x) * m, 0.9 * (1 + x) * m):
        hr, hl = tip_hit(R, curve, h, ph_k, span), tip_hit(L, curve, h, ph_k, span)
        # the right side is the clockwise one of the body: on the driven wheel (phi runs clockwise) the smaller phi
        assert hl[1] > ph_k > hr[1]
        assert 0.5 * (hr[1] + hl[1]) == pytest.approx(ph_k, abs=1e-9)
        assert land_length(curve, h, hl[1], hr[1]) == pytest.approx(_land(40, m, x, 40.0 + h, thinning), rel=1e-7)
        # the hit lies on the flank and on the equidistant
        assert np.linalg.norm(R.flank.at(hr[0]) - curve.offset(np.array([hr[1]]), h)[0]) < 1e-8


def test_shaper_tools_refusals_in_full():
    assert _refusal(lambda: ToothSpec(m=2.0, x=0.3).shaper_tools()) == (
        "z0 = None: a concave pitch curve needs a shaper cutter")
    assert _refusal(lambda: ToothSpec(m=2.0, x=-1.2, z0=8).shaper_tools()) == (
        "z0 = 8: the shaper z0 = 8 with x0 = +1.2 (-x of the gear it cuts) cannot be made: rho_a0_star = 0.1: tip "
        "rounds of the shaper tooth overlap (use a smaller profile shift (driver_shift) or another shaper)")
    # x0 = -1.5 puts the 8-tooth shaper's tip circle inside its base circle: x0 > 8 (cos 20 deg - 1) / 2 - 1.25
    x0_min = 8 * (math.cos(ALPHA) - 1) / 2 - 1.25
    assert x0_min == pytest.approx(-1.4912, abs=1e-4)
    assert _refusal(lambda: ToothSpec(m=2.0, x=1.5, z0=8).shaper_tools()) == (
        "z0 = 8: the shaper z0 = 8 with x0 = -1.5 (-x of the gear it cuts) cannot be made: x0 = -1.5: the shaper's tip "
        f"circle d_a0 = 15.000 mm lies inside its base circle d_b0 = {16 * math.cos(ALPHA):.3f} mm: it has no "
        f"involute (x0 > {x0_min:.3f} for z0 = 8) (use a smaller profile shift (driver_shift) or another shaper)")
    # a catalogue shaper: its module must be the gear's (to 1e-9 of it), and it must be makeable
    assert _refusal(lambda: ToothSpec(m=2.0, x=0.2, shaper=ShaperCutter(20, 2.5, 0.1)).shaper_tools()) == (
        "m = 2.0: must equal the shaper's module 2.5 mm")
    assert len(ToothSpec(m=2.0, x=0.2, shaper=ShaperCutter(20, 2.0 * (1 + 9e-10), 0.1)).shaper_tools()) == 2
    assert _refusal(lambda: ToothSpec(m=2.0, x=0.2, shaper=ShaperCutter(20, 2.0 * (1 + 2e-9), 0.1)).shaper_tools()) \
        .startswith("m = 2.0: must equal the shaper's module 2 mm")
    assert _refusal(lambda: ToothSpec(m=2.0, x=0.2, shaper=ShaperCutter(8, 2.0, 1.2)).shaper_tools()) == (
        "z0 = 8: the shaper z0 = 8, x0 = +1.2 cannot be made: rho_a0_star = 0.1: tip rounds of the shaper tooth overlap")


def test_where_a_re_phased_shapers_tip_round_lies_wholly_below_the_root_the_flank_is_cut_down_to_it():
    """The seed-002 pair as built (parts/ncg_seed002.toml: the law search's blend, the catalogue shaper d0 = 25 mm,
    z0 = 10, x0 = 0 on the driven wheel of x = -0.5: e = (x + x0) m = -1.25 mm): at the concave stretches the shaper's
    tip round lies wholly below the root equidistant, and the flank is cut where it crosses the equidistant, its
    first hundredth standing in for the fillet (make_side's ``fillet_is_flank``)."""
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, make_side

    m, x = 2.5, -0.5
    sl = SmoothedWalkingLaw(LAW2, 0.13962634015954636, u_h=3.0464623475326484)
    pc = PitchCurves(sl, 124.27158616017297)
    frame, curve = ArcFrame(pc), BodyPitchCurve(pc, "driven")
    rack = BasicRack(rho_f_star=0.38)
    spec = ToothSpec(m=m, x=x, thinning_mm=0.08513422179807296, rack=rack, z0=10, tip_min_mm=0.625,
                     shaper=ShaperCutter(10, m, 0.0, rack))
    assert spec.h_root == pytest.approx((1.25 + 0.5) * m, rel=1e-15)
    tools = spec.shaper_tools()
    assert [t.cutter.e for t in tools] == pytest.approx([-1.25, -1.25], rel=1e-15)

    def height(side_curve, u, ph):
        """signed height of the point at u above the root equidistant, measured from its foot at ph"""
        P = side_curve.at(u)
        F = curve.offset(np.array([ph]), -spec.h_root)[0]
        return float(np.dot(P - F, curve.normal(np.array([ph]))[0]))

    found = 0
    for k in (8, 11):                                    # the teeth next to the first concave stretch
        s_k = (k + 0.5) * math.pi * m
        for tool in tools:
            side = make_side(tool, PitchCurveCentrode(curve, frame, s_k), spec.h_root)
            if not side.fillet_is_flank:
                continue
            found += 1
            fil, fla = side.fillet, side.flank
            assert (side.kind, side.undercut) == ("shaper", False)
            # the fillet is the flank's own first hundredth: the same piece and cutter, ending where the flank begins
            assert fil.piece is fla.piece and fil.u1 == fla.u0
            assert fil.u1 - fil.u0 == pytest.approx(0.01 * (fla.u1 - fil.u0), rel=1e-9)
            # it starts on the root equidistant (the foot at phi_root, gap nil) and the flank rises from there
            assert side.root_gap_mm < 1e-9
            assert height(fil, fil.u0, side.phi_root) == pytest.approx(0.0, abs=1e-9)
            # the foot is a least distance (bounded search): along the curve it is good to sqrt(eps), about 1e-6 mm
            X0 = fil.at(fil.u0)
            assert np.linalg.norm(X0 - curve.offset(np.array([side.phi_root]), -spec.h_root)[0]) < 2e-6
            assert height(fla, fla.u0, side.phi_root) > 0.0
            # the uncut flank below that point lies below the root (it is the part the equidistant replaces)
            assert height(fla, fil.u0 - 0.01 * (fla.u1 - fil.u0), side.phi_root) < 0.0
    assert found == 2


def _three_lobed(m: float = 2.0):
    """The 3-lobed elliptical law (e = 0.5) scaled so that the driven curve carries a multiple of 3 teeth of m."""
    law = EllipticalLaw(e=0.5, k=3)
    pc0 = PitchCurves(law, 100.0)
    z_H = round(pc0.perimeter_driven() / (math.pi * m) / 3) * 3
    return PitchCurves(law, 100.0 * z_H * math.pi * m / pc0.perimeter_driven())


def test_a_tip_floor_above_the_flanks_reach_and_a_root_gap_over_a_tenth_of_the_module_are_refused():
    import re

    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, make_side
    from propulsor.gears.tip_search import tip_hit

    m = 2.0
    pc = _three_lobed(m)
    frame = ArcFrame(pc)
    phi0 = float(frame.phi(np.array([0.5 * math.pi * m]))[0])          # driven tooth 0's centre
    # a land of 5 mm is nowhere; shortening may go down to 4 m, above the rack flank's reach (its straight flank
    # ends (1.5 h_a* + 0.5) m / cos alpha = 4.26 mm along the flank from the reference line)
    assert _refusal(lambda: generate_teeth(pc, "driven", ToothSpec(m=m, tip_min_mm=5.0, tip_floor=4.0, z0=20))) == (
        f"m = 2.0: driven tooth at phi = {phi0:.4f} rad is pointed or cannot be cut: the rack flank envelope does not "
        "reach 4.00 m above the pitch curve (generating limit of the cutter) (use a smaller profile shift, a larger "
        "shaper, more teeth or a wider smoothing)")
    curve = BodyPitchCurve(pc, "driven")
    side = make_side(ToothSpec(m=m).rack_tools()[0], PitchCurveCentrode(curve, frame, 0.5 * math.pi * m))
    span = 1.5 * math.pi * m / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))
    assert tip_hit(side, curve, 4.0 * m, phi0, span) is None and tip_hit(side, curve, 1.0 * m, phi0, span) is not None
    # tooth 9 next to the concave stretch is shaper-cut: its right flank (an involute from the shaper's base circle)
    # does not reach the nominal tip (1 + x) m, and a floor there leaves nothing to shorten to
    phi9 = float(frame.phi(np.array([9.5 * math.pi * m]))[0])
    assert _refusal(lambda: generate_teeth(pc, "driven", ToothSpec(m=m, x=0.2, tip_min_mm=0.1, tip_floor=1.0,
                                                                    z0=20))) == (
        f"m = 2.0: driven tooth at phi = {phi9:.4f} rad is pointed or cannot be cut: the shaper flank envelope does "
        "not reach 1.20 m above the pitch curve (generating limit of the cutter) (use a smaller profile shift, a "
        "larger shaper, more teeth or a wider smoothing)")
    # within reach the land is what it is: zero where the teeth are pointed at 2.5 m
    assert _refusal(lambda: generate_teeth(pc, "driven", ToothSpec(m=m, tip_min_mm=5.0, tip_floor=2.5, z0=20))) == (
        f"m = 2.0: driven tooth at phi = {phi0:.4f} rad is pointed or cannot be cut: tip land 0.000 mm < 5.000 mm even "
        "with the tip shortened to 2.50 m (use a smaller profile shift, a larger shaper, more teeth or a wider "
        "smoothing)")
    # a catalogue shaper of x0 = 1.5 on a wheel of x = 0.8: e = 4.6 mm, its fillet lands off the root
    spec = ToothSpec(m=m, x=0.8, z0=20, shaper=ShaperCutter(80, m, 1.5))
    text = _refusal(lambda: generate_teeth(pc, "driven", spec))
    got = re.fullmatch(r"z0 = 80: driven tooth at phi = (\S+) rad: the re-phased shaper leaves its fillet (\S+) mm off "
                       r"the root \(more than 0\.1 m\) \(a larger shaper or a wider blend\)", text)
    assert got, text
    phi, gap = float(got.group(1)), float(got.group(2))
    centres = frame.phi((np.arange(60) + 0.5) * math.pi * m)
    k = int(np.argmin(abs(centres - phi)))
    assert abs(centres[k] - phi) < 5e-5                                 # a tooth centre, to the 4 decimals printed
    tools = spec.shaper_tools()
    gaps = [make_side(t, PitchCurveCentrode(curve, frame, (k + 0.5) * math.pi * m), spec.h_root).root_gap_mm
            for t in tools]
    assert gaps[0] <= 0.1 * m < gaps[1] and round(gaps[1], 3) == gap   # the right side passed, the left did not
    # every tooth before it was within 0.1 m on both sides
    for j in range(k):
        s_j = (j + 0.5) * math.pi * m
        for t in tools:
            if any(a - 1.5 * math.pi * m <= s_j <= b + 1.5 * math.pi * m
                   for a, b in (frame.s(np.array(z)) for z in _zones(curve))):
                assert make_side(t, PitchCurveCentrode(curve, frame, s_j), spec.h_root).root_gap_mm <= 0.1 * m


def _zones(curve):
    from propulsor.gears.noncircular_teeth import _concave_zones
    return _concave_zones(curve)


def test_the_batched_tip_search_finds_each_sides_own_hit_and_none_where_the_flank_stops_short():
    """tip_hits_batch (one vectorised Newton iteration for many sides, grouped by their cutter piece) against
    tip_hit side by side (a start from the nearest samples, then fsolve): the same (u, phi) to 1e-10, on the rack-cut
    sides of a circular driver and the shaper-cut sides of the 3-lobed wheel, at the nominal tip and above the
    flank's reach (None from both)."""
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, make_side
    from propulsor.gears.tip_search import tip_hit, tip_hits_batch

    m = 2.0
    for pc, role, spec, ks in ((_circular_pair(m, 40), "driver", ToothSpec(m=m, x=0.3), range(0, 20, 3)),
                               (_three_lobed(m), "driven", ToothSpec(m=m, x=0.2, z0=20), range(6, 14))):
        frame, curve = ArcFrame(pc), BodyPitchCurve(pc, role)
        tools = spec.shaper_tools() if spec.z0 else spec.rack_tools()
        offset = 0.5 if role == "driven" else 0.0
        s_k = np.array([(k + offset) * math.pi * m for k in ks])
        ph_k = frame.phi(s_k)
        sides = [make_side(t, PitchCurveCentrode(curve, frame, s), spec.h_root) for s in s_k for t in tools]
        span = 1.5 * math.pi * m / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))
        for h in (spec.h_tip, 0.4 * m, 10.0 * m):
            got = tip_hits_batch(sides, np.repeat(s_k, 2), np.repeat(ph_k, 2), curve, frame, h, span)
            want = [tip_hit(sd, curve, h, float(p), span) for sd, p in zip(sides, np.repeat(ph_k, 2))]
            assert len(got) == len(sides)
            found = [g is not None for g in got]
            assert found == [w is not None for w in want]
            # 0.4 m: every side; the nominal tip: the shaper's involute starts on its base circle below it next to the
            # concave stretch (teeth 9 to 13 but tooth 9's left: shortened there); 10 m: none
            assert sum(found) == {0.4 * m: len(sides), 10.0 * m: 0}.get(h, len(sides) if role == "driver" else 7)
            if role == "driven" and h == spec.h_tip:
                # tooth 8's right and tooth 9's left reach the tip 3 and 4 thousandths into the involute's roll from
                # the base circle, where it has a cusp: fsolve started there stalled and tip_hit said no tip
                assert found[:8] == [True] * 6 + [False, True]
                assert 0.0 < got[4][0] < 0.005 and 0.0 < got[7][0] < 0.005
            for g, w, p in zip(got, want, np.repeat(ph_k, 2)):
                if g is None:
                    continue
                assert g[0] == pytest.approx(w[0], abs=1e-10) and g[1] == pytest.approx(w[1], abs=1e-10)
                assert abs(g[1] - p) < 0.6 * span                    # next to its own tooth, not a turn away


def test_the_seed002_pairs_mirror_teeth_get_the_same_shortened_tip():
    """The seed-002 law is even within a leg, so the driven wheel's teeth either side of a concave stretch are mirror
    images, and the shortening of their tips (the tallest height with a land of 0.25 m) must be the same.  It was not:
    tip_hit said "no tip" where its start sat on the shaper involute's cusp at the base circle, the bisection took
    the height for one the flank does not reach, and tooth 11 was cut to 0.154 mm where its mirror tooth 8 kept
    0.215 mm."""
    from propulsor.gears.noncircular_teeth import BodyPitchCurve
    from propulsor.gears.tip_search import tip_hit

    m, x = 2.5, -0.5
    sl = SmoothedWalkingLaw(LAW2, 0.13962634015954636, u_h=3.0464623475326484)
    pc = PitchCurves(sl, 124.27158616017297)
    rack = BasicRack(rho_f_star=0.38)
    spec = ToothSpec(m=m, x=x, thinning_mm=0.08513422179807296, rack=rack, z0=10, tip_min_mm=0.625,
                     shaper=ShaperCutter(10, m, 0.0, rack))
    g = generate_teeth(pc, "driven", spec)
    assert g.z == 80
    t8, t11 = g.teeth[8], g.teeth[11]
    assert (t8.shortened, t11.shortened) == (True, True)
    assert t8.tip_height_mm == pytest.approx(0.21576, abs=1e-5)
    assert t11.tip_height_mm == pytest.approx(t8.tip_height_mm, abs=2e-6)        # the bisection's 1e-6 mm each
    assert t11.tip_thickness_mm == pytest.approx(t8.tip_thickness_mm, abs=1e-5)
    # every shortened tip is the tallest with the land: its flanks reach it, and 2 um higher the land is too thin
    curve = BodyPitchCurve(pc, "driven")
    span = 1.5 * math.pi * m / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))
    for k in (8, 9, 10, 11):
        tooth, (R, L) = g.teeth[k], g.sides[k]
        assert tooth.tip_thickness_mm >= 0.625
        for h in np.linspace(0.0, tooth.tip_height_mm, 7):
            assert tip_hit(R, curve, h, tooth.phi_centre, span) is not None
            assert tip_hit(L, curve, h, tooth.phi_centre, span) is not None


def test_the_tip_lands_arc_on_a_non_circular_equidistant_against_its_chords():
    """land_length (10-point Gauss-Legendre in the driven angle, the equidistant's speed by central differences) on the
    driven wheel of the Fourier law of parts/ncg_fourier_3lobe.toml (0.04 sin theta + 0.005 cos 2 theta: not even in
    phi, so a mirrored node set would not do), where the speed varies along the arc: the sum of 200 001 chords of the
    equidistant, to 1e-9."""
    from propulsor.gears.noncircular_teeth import BodyPitchCurve
    from propulsor.gears.tip_search import land_length
    from propulsor.laws.ratio_laws import FourierLaw

    curve = BodyPitchCurve(PitchCurves(FourierLaw(k=3, cos=(0.0, 0.005), sin=(0.04,)), 100.0), "driven")
    for h, a, b in ((2.4, 0.5, 0.62), (-2.5, 1.1, 0.95), (0.0, 2.0, 2.3)):
        P = curve.offset(np.linspace(min(a, b), max(a, b), 200001), h)
        chords = float(np.sum(np.linalg.norm(np.diff(P, axis=0), axis=1)))
        assert land_length(curve, h, a, b) == pytest.approx(chords, rel=1e-9)


def test_the_batched_tip_search_converges_itself_and_falls_back_only_where_the_flank_stops_short(monkeypatch):
    """The batch's own Newton iteration (finite-difference Jacobian, both unknowns of every side at once) must
    converge: tip_hit (fsolve, one side at a time) is its fallback, called only for the sides that have no hit.
    A broken iteration would still give the right answers through the fallback, only 16 times slower."""
    import propulsor.gears.noncircular_teeth as nt
    import propulsor.gears.tip_search as ts
    from propulsor.gears.envelope import PitchCurveCentrode

    calls = []
    single = ts.tip_hit

    def counted(*a, **k):
        calls.append(a[2])
        return single(*a, **k)

    m = 2.0
    for pc, role, spec, ks, misses in ((_circular_pair(m, 40), "driver", ToothSpec(m=m, x=0.3), range(0, 20, 3), 0),
                                       (_three_lobed(m), "driven", ToothSpec(m=m, x=0.2, z0=20), range(6, 14), 9)):
        frame, curve = ArcFrame(pc), nt.BodyPitchCurve(pc, role)
        tools = spec.shaper_tools() if spec.z0 else spec.rack_tools()
        s_k = np.array([(k + (0.5 if role == "driven" else 0.0)) * math.pi * m for k in ks])
        sides = [nt.make_side(t, PitchCurveCentrode(curve, frame, s), spec.h_root) for s in s_k for t in tools]
        span = 1.5 * math.pi * m / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))
        monkeypatch.setattr(ts, "tip_hit", counted)
        for h in (spec.h_tip, 0.4 * m):
            calls.clear()
            got = ts.tip_hits_batch(sides, np.repeat(s_k, 2), np.repeat(frame.phi(s_k), 2), curve, frame, h, span)
            assert len(calls) == sum(g is None for g in got) == (misses if h == spec.h_tip else 0)
        monkeypatch.setattr(ts, "tip_hit", single)


@pytest.mark.parametrize("x", [0.5, -0.4, 0.0])
def test_the_rack_tools_flank_runs_one_and_a_half_addenda_and_half_a_module_past_the_reference_line(x):
    """rack_tools: the straight flank is followed to u_top = (1.5 (h_a* + |x|) + 0.5) m / cos alpha along itself,
    well past any tip the gear is cut to ((h_a* + x) m above the pitch curve, plus its curvature's reach)."""
    right, left = ToothSpec(m=2.0, x=x).rack_tools()
    u_top = (1.5 * (1.0 + abs(x)) + 0.5) * 2.0 / math.cos(ALPHA)
    assert right.flank_range[1] == left.flank_range[1] == pytest.approx(u_top, rel=1e-15)


@pytest.mark.parametrize("role, x", [("driven", 0.0), ("driven", 0.3), ("driver", -0.2)])
def test_a_rack_cut_sides_root_angle_is_where_its_fillet_meets_the_root(role, x):
    """phi_root of a rack-cut side (make_side): the driven angle whose point on the root equidistant (h_root below
    the pitch curve) is the fillet's first point; on a circle that point's radius is r - h_root."""
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import BodyPitchCurve, make_side

    m = 2.0
    pc = _circular_pair(m, 40)
    frame, curve = ArcFrame(pc), BodyPitchCurve(pc, role)
    spec = ToothSpec(m=m, x=x)
    r = 40.0 if role == "driven" else 20.0
    for k in (0, 5):
        s_k = (k + (0.5 if role == "driven" else 0.0)) * math.pi * m
        for tool in spec.rack_tools():
            side = make_side(tool, PitchCurveCentrode(curve, frame, s_k))
            X0 = side.fillet.at(side.fillet.u0)
            assert float(np.linalg.norm(X0)) == pytest.approx(r - spec.h_root, abs=1e-9)
            assert np.linalg.norm(curve.offset(np.array([side.phi_root]), -spec.h_root)[0] - X0) < 1e-9
            assert side.root_gap_mm == 0.0 and not side.fillet_is_flank


# =========================================================================== the re-phased shaper's tip round
def _rephased_side(z0=19, m=2.0, x0=0.45, x=0.3, mirror=False):
    """One side of a shaper of its own shift x0 cutting a gear of shift x: re-phased by c = e cot(alpha),
    e = (x + x0) m (``envelope.ShaperOnRackCentrode``), as ``ToothSpec._own_shift_shaper_tools`` places it."""
    from propulsor.gears.cutters import CutterSide, ShaperCutter
    from propulsor.gears.envelope import ExternalCircleCentrode, ShaperOnRackCentrode

    sh = ShaperCutter(z0, m, x0)
    e = (x + x0) * m
    c = e / math.tan(math.radians(20.0))
    b = sh.side(ExternalCircleCentrode(sh.r0)).placed(-math.pi + math.pi / z0, (0.0, sh.r0), mirror)
    cut = ShaperOnRackCentrode(sh.r0, e, -c if mirror else c)
    return CutterSide(b.fillet, b.fillet_range, b.flank, b.flank_range, cut, "shaper"), sh


def _circumcentre(A, B, C):
    """Centre of the circle through three points (2D)."""
    ax, ay = A
    bx, by = B
    cx, cy = C
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return np.array([ux, uy])


@pytest.mark.parametrize("mirror", [False, True], ids=["right", "left"])
@pytest.mark.parametrize("gear_kind", ["circle", "pitch curve"])
def test_round_envelope_of_a_rephased_shaper_is_the_envelope_of_its_tip_circle(mirror, gear_kind):
    """The tip round of a shaper of its own shift (e = 1.5 mm) is a circle of radius rho about a centre fixed in the
    cutter; its envelope is the curve that touches every placed circle.  Found in the test, from the pose alone
    (X = G(s) + R(tau_g - tau_c)(P - C(s)), the module's protocol): every point of round_envelope's curve lies on the
    circle of its rolling arc s (|X - C(s)| = rho to 1e-9 mm) and is tangent to it (the curve's direction normal to
    X - C(s), to 1e-6 rad); at its flank end the junction of round and involute placed at its closed-form contact
    s_f (the involute's pitch point) to 1e-9 mm; at its other end the tip-land end of the round placed at that arc,
    to 1e-7 mm (the search stops at 1e-8 mm of arc)."""
    from propulsor.gears.envelope import CircleCentrode, PitchCurveCentrode, round_envelope
    from propulsor.gears.pitch_frame import BodyPitchCurve

    side, sh = _rephased_side(mirror=mirror)
    cut = side.cutter
    if gear_kind == "circle":
        gear = CircleCentrode(60.0)
    else:
        law = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.25)
        pc = PitchCurves(law, 200.0)
        gear = PitchCurveCentrode(BodyPitchCurve(pc, "driven"), ArcFrame(pc), 40.0)
    a_tip, a_fl = side.fillet_range
    rho = side.fillet.piece.rho
    fil = side.fillet
    P_j, P_mid, P_t = fil.point(np.array([a_fl, 0.5 * (a_tip + a_fl), a_tip]))
    centre = _circumcentre(P_j, P_mid, P_t)
    assert abs(np.linalg.norm(P_j - centre) - rho) < 1e-9 and abs(np.linalg.norm(P_t - centre) - rho) < 1e-9

    def place(Q, s):
        s = np.atleast_1d(np.asarray(s, float))
        th = gear.angle(s) - cut.angle(s)
        v = np.asarray(Q, float) - cut.point(s)
        c, sn = np.cos(th), np.sin(th)
        return gear.point(s) + np.column_stack([c * v[:, 0] - sn * v[:, 1], sn * v[:, 0] + c * v[:, 1]])

    env = round_envelope(fil, a_tip, a_fl, rho, cut, gear)
    T = fil.tangent(np.array([a_fl]))
    T = T / np.linalg.norm(T)
    s_f = float(cut.contact(P_j[None, :], np.column_stack([-T[:, 1], T[:, 0]]))[0])
    assert env.u1 == s_f and env.u0 != s_f and env.kind == "fillet"
    assert np.array_equal(env.sample(7), env(np.linspace(env.u0, env.u1, 7)))
    s = np.linspace(env.u0, env.u1, 9)
    X = env(s)
    C = place(centre, s)
    assert np.max(np.abs(np.linalg.norm(X - C, axis=1) - rho)) < 1e-9
    h = 1e-6 * abs(env.u1 - env.u0)
    d = env(s + h) - env(s - h)
    cosang = np.einsum("ij,ij->i", d, X - C) / (np.linalg.norm(d, axis=1) * rho)
    assert np.max(np.abs(cosang)) < 1e-6
    assert np.linalg.norm(env.at(env.u1) - place(P_j, s_f)[0]) < 1e-9
    assert np.linalg.norm(env.at(env.u0) - place(P_t, env.u0)[0]) < 1e-7
    # between its ends the contact runs over the round from the junction to the tip-land end, never past them
    th = gear.angle(s) - cut.angle(s)
    back = np.column_stack([np.cos(-th) * (X - gear.point(s))[:, 0] - np.sin(-th) * (X - gear.point(s))[:, 1],
                            np.sin(-th) * (X - gear.point(s))[:, 0] + np.cos(-th) * (X - gear.point(s))[:, 1]])
    Q = back + cut.point(s) - centre  # the contact in the cutter frame, from the round's centre
    a_of = lambda v: math.atan2(v[1], v[0])
    span = (a_of(P_t - centre) - a_of(P_j - centre) + math.pi) % (2 * math.pi) - math.pi
    rel = np.array([(a_of(q) - a_of(P_j - centre) + math.pi) % (2 * math.pi) - math.pi for q in Q]) / span
    assert rel[0] == pytest.approx(1.0, abs=1e-7) and rel[-1] == pytest.approx(0.0, abs=1e-9)
    assert np.all((rel >= -1e-9) & (rel <= 1.0 + 1e-7)) and np.all(np.diff(rel) < 0)


def test_round_envelope_refuses_a_round_whose_contact_never_reaches_its_tip_land():
    """A gear that slides past the cutter without turning against it (its pose: the cutter's own point shifted by
    the rolling arc, the cutter's own angle): the round's centre runs on a straight line, so its contact stays at one
    point of the round and never reaches the tip land; the tip round is refused with the shaper's pitch diameter."""
    from propulsor.gears.envelope import round_envelope

    side, sh = _rephased_side()
    cut = side.cutter

    class Sliding:
        def point(self, s):
            s = np.atleast_1d(np.asarray(s, float))
            return cut.point(s) + np.column_stack([s, np.zeros_like(s)])

        def angle(self, s):
            return cut.angle(s)

    a_tip, a_fl = side.fillet_range
    with pytest.raises(InputError) as exc:
        round_envelope(side.fillet, a_tip, a_fl, side.fillet.piece.rho, cut, Sliding())
    assert str(exc.value) == (f"d0 = {2.0 * sh.r0!r}: the contact of the shaper's tip round never reaches its tip land "
                              "(the shaper is too large for the gear's curvature there)")


def test_a_cutter_normal_that_misses_its_rolling_circle_is_refused_with_the_circles_radius():
    """The rolling circle's meshing equation has no crossing for a normal line that passes the circle by: refused,
    naming the cutter's pitch radius r0 (a shaper outside the gear, one inside a ring)."""
    from propulsor.gears.envelope import CircleCentrode, ExternalCircleCentrode, nearer_circle_crossing

    # (0, 5) along +x passes the circle of radius 2 about the origin 3 above it; (0, 1.5) along +x crosses it
    P, N = np.array([[0.0, 1.5], [0.0, 5.0]]), np.array([[1.0, 0.0], [1.0, 0.0]])
    with pytest.raises(InputError) as exc:
        nearer_circle_crossing(P, N, (0.0, 0.0), 2.0, "r0", "shaper's")
    assert str(exc.value) == ("r0 = 2.0: a generating point's normal misses the shaper's rolling circle (every one "
                              "must cross it)")
    ok = nearer_circle_crossing(P[:1], N[:1], (0.0, 0.0), 2.0, "r0", "shaper's")
    assert ok[0] == pytest.approx((math.sqrt(4.0 - 2.25), 1.5), abs=1e-15)
    # a tangent line (disc = 0) touches: its one crossing
    assert nearer_circle_crossing(np.array([[0.0, 2.0]]), N[:1], (0.0, 0.0), 2.0, "r0", "x")[0] == pytest.approx(
        (0.0, 2.0), abs=1e-15)
    # the centrodes name r0 and whose circle it is; the shaper's circle is centred at (0, R)
    with pytest.raises(InputError) as exc:
        ExternalCircleCentrode(2.0).contact(np.array([[0.0, 7.0]]), N[:1])
    assert str(exc.value) == ("r0 = 2.0: a generating point's normal misses the shaper's rolling circle (every one "
                              "must cross it)")
    with pytest.raises(InputError) as exc:
        CircleCentrode(2.0).contact(np.array([[0.0, 5.0]]), N[:1])
    assert str(exc.value) == ("r0 = 2.0: a generating point's normal misses the cutter's rolling circle (every one "
                              "must cross it)")


def test_param_at_radius_finds_the_flank_point_at_a_radius_and_refuses_one_outside_it():
    """A rack-cut involute of a z = 30, m = 2 spur gear: the flank point at radius r found to rounding (its radius
    is r); a radius beyond both ends of the flank refused; the curves keep their kind and rotation when cut down
    or turned."""
    from propulsor.gears.envelope import CircleCentrode

    side = ToothSpec(m=2.0).rack_tools()[0]
    fil, fla = side.envelopes(CircleCentrode(30.0))
    assert (fil.kind, fla.kind) == ("fillet", "flank")
    r_ends = np.hypot(*fla(np.array([fla.u0, fla.u1])).T)
    r = float(np.mean(r_ends))
    u = fla.param_at_radius(r)
    assert min(fla.u0, fla.u1) < u < max(fla.u0, fla.u1)
    assert abs(float(np.hypot(*fla.at(u))) - r) < 1e-12
    # 0.1 mm beyond either end (the product of the two ends' differences under 1 mm^2)
    for far in (float(np.max(r_ends)) + 0.1, float(np.min(r_ends)) - 0.1):
        with pytest.raises(ValueError, match="^radius not bracketed$"):
            fla.param_at_radius(far)
    cut = fla.with_range(u, fla.u1).rotated(0.25)
    assert (cut.kind, cut.rotation, cut.u0, cut.u1) == ("flank", 0.25, u, fla.u1)
    assert fla.rotated(0.25).with_range(u, fla.u1).rotation == 0.25
    turned = fla.rotated(0.25).rotated(-0.5)
    assert turned.rotation == -0.25 and turned.kind == "flank"
    c, s = math.cos(-0.25), math.sin(-0.25)
    X = fla.at(u)
    assert np.allclose(turned.at(u), (c * X[0] - s * X[1], s * X[0] + c * X[1]), atol=1e-12)
    assert fla.with_range(u, fla.u1).rotated(0.25).at(u) == pytest.approx(fla.rotated(0.25).at(u), abs=0)
