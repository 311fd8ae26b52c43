"""The one-point paths of the drive law, the pitch curves and the envelope (the solvers' calls with one
float or a one-element array, evaluated in ``math``) give the array functions' results bit for bit:
the same operations in the same order, so every generated tooth and output file stays byte-identical
(issue 13).  The Fourier laws among them (their array functions the one-point path at each angle since 02bfeb1;
before, numpy's Newton over the whole array and a matrix product, these tests failed on them).  Light: a few
thousand evaluations."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.gears.cutters import ShaperCutter
from propulsor.gears.envelope import PitchCurveCentrode, envelope_points
from propulsor.gears.involute import BasicRack
from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw
from propulsor.gears.noncircular_teeth import ToothSpec
from propulsor.gears.pitch_frame import ArcFrame, BodyPitchCurve
from propulsor.laws.ratio_laws import FourierLaw
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw

#: the Fourier laws of parts/ncg_fourier_seed002.toml and parts/ncg_fourier_3lobe.toml, and one with cosines
FOURIER = (FourierLaw(4, (0.0, 0.0, 0.0, 0.0), (-0.041163336, 0.007288343, -0.002416844, 0.001071365)),
           FourierLaw(3, (0.0, 0.005), (0.04,)), FourierLaw(2, (0.03, -0.01), (0.02, 0.0, 0.005)))


def _laws():
    for seed in (SEED_000, SEED_002):
        law = WalkingLaw(**seed)
        yield law
        yield SmoothedWalkingLaw(law, 0.2)
        yield SmoothedWalkingLaw(law, 0.12, u_h=0.75 * law.u)


def _angles(law, n=120):
    """Random driven angles over several turns plus the window ends and hand-overs (and their
    neighbouring floats), where the branches switch."""
    rng = np.random.default_rng(13)
    d = getattr(law, "delta", 0.1)
    edges = []
    for k in range(-5, 6):
        h = math.pi / 4 + k * math.pi / 2
        for x in (h, h - d, h + d):
            edges += [x, float(np.nextafter(x, 10.0)), float(np.nextafter(x, -10.0))]
    return np.concatenate([rng.uniform(-9.0, 9.0, n), edges, [0.0, -0.0]])


def _same(a, b) -> bool:
    return np.asarray(a, float).tobytes() == np.asarray(b, float).tobytes()


@pytest.mark.parametrize("law", list(_laws()) + list(FOURIER), ids=lambda lw: type(lw).__name__)
def test_law_one_point_equals_array(law):
    phi = _angles(law)
    U, dU, d2U, th = law.U(phi), law.dU_dphi(phi), law.d2U_dphi2(phi), law.theta(phi)
    for i, p in enumerate(phi):
        assert _same(law.U_derivs1(float(p)), (U[i], dU[i], d2U[i])), p
        assert _same(law.theta1(float(p)), th[i]), p


@pytest.mark.parametrize("law", [lw for lw in _laws() if isinstance(lw, SmoothedWalkingLaw)] + list(FOURIER),
                         ids=["blend_000", "blend_u_h_000", "blend_002", "blend_u_h_002", "fourier_seed002",
                              "fourier_3lobe", "fourier_cos"])
def test_law_few_angles_equal_array(law):
    """Arrays of 1 to 8 angles take the one-point path (``laws.law.one_point_values``): each element is the large
    array's, bit for bit; an array with a non-finite angle, or of 9, takes the array path."""
    phi = _angles(law)
    full = (law.U(phi), law.dU_dphi(phi), law.d2U_dphi2(phi), law.theta(phi))
    k = 0
    for n in [1, 2, 3, 5, 8] * 40:
        if k + n > len(phi):
            break
        part = phi[k:k + n]
        for f, ref in zip((law.U, law.dU_dphi, law.d2U_dphi2, law.theta), full):
            assert _same(f(part), ref[k:k + n]), (f.__name__, part)
        k += n
    assert len(phi) - k < 8
    with_nan = np.array([0.3, math.nan])
    assert np.isnan(law.theta(with_nan)[1]) and _same(law.theta(with_nan)[:1], law.theta(phi[:0].tolist() + [0.3]))


@pytest.mark.parametrize("law", list(_laws())[1:3] + list(FOURIER[:2]),
                         ids=["blend", "blend_u_h", "fourier_seed002", "fourier_3lobe"])
def test_pitch_curve_one_point_equals_array(law):
    pc = PitchCurves(law, 160.0)
    phi = _angles(law, 60)
    for curve in ("driven", "driver"):
        fns = (pc.r_H, pc.dr_H, pc.d2r_H) if curve == "driven" else (pc.r, pc.r_theta, pc.r_thetatheta)
        for p in phi[::3]:
            # a scalar phi: what rho_H / rho and the curvature search compute (numpy scalar semantics)
            assert _same(pc.polar_derivatives1(curve, float(p)), tuple(float(f(float(p))) for f in fns)), p
        whole = pc._polar_derivatives(curve, phi)
        assert all(_same(w, f(phi)) for w, f in zip(whole, fns))
    for role in ("driven", "driver"):
        bc = BodyPitchCurve(pc, role)
        for p in phi:
            two = np.array([p, p])  # the array path
            one = np.array([p])     # the one-point path
            assert _same(bc.point(one), bc.point(two)[:1])
            assert _same(bc.dpoint(one), bc.dpoint(two)[:1])
            assert _same(bc.normal(one), bc.normal(two)[:1])
            assert _same(bc.offset(one, -2.75), bc.offset(two, -2.75)[:1])


def test_envelope_one_point_equals_array():
    law = SmoothedWalkingLaw(WalkingLaw(**SEED_000), 0.25)
    pc = PitchCurves(law, 160.0)
    frame = ArcFrame(pc)
    rng = np.random.default_rng(5)
    hits = refused = 0
    for spec in (ToothSpec(m=4.0, x=0.3, z0=20, thinning_mm=0.05),
                 ToothSpec(m=4.0, x=-0.3, shaper=ShaperCutter(20, 4.0, 0.1, BasicRack()), thinning_mm=0.05)):
        tools = spec.rack_tools() + spec.shaper_tools()
        for role in ("driven", "driver"):
            curve = BodyPitchCurve(pc, role)
            for tool in tools:
                cen = PitchCurveCentrode(curve, frame, float(rng.uniform(0.0, frame.perimeter)))
                for piece, (a, b) in ((tool.fillet, tool.fillet_range), (tool.flank, tool.flank_range)):
                    if piece is tool.fillet and getattr(tool.cutter, "e", 0.0) != 0.0:
                        # a re-phased shaper's tip round has no closed-form contact: round_envelope's, not this
                        for u in (np.array([a]), np.array([a, b])):
                            with pytest.raises(ValueError) as exc:
                                envelope_points(piece, u, tool.cutter, cen)
                            assert str(exc.value) == ("the tip round of a re-phased shaper (e != 0) has no "
                                                      "closed-form contact: its envelope is round_envelope's")
                        refused += 1
                        continue
                    for u in np.linspace(a, b, 9):
                        X1, s1 = envelope_points(piece, np.array([u]), tool.cutter, cen)
                        X2, s2 = envelope_points(piece, np.array([u, u]), tool.cutter, cen)
                        assert X1.shape == (1, 2) and s1.shape == (1,)
                        assert X2.shape == (2, 2) and s2.shape == (2,)
                        assert _same(X1, X2[:1]) and _same(s1, s2[:1]), (role, tool.kind, u)
                        hits += 1
    # the second spec's two shaper sides are re-phased (e = (x + x0) m = -0.8 mm): their tip rounds refused
    assert (hits, refused) == (2 * 2 * 4 * 2 * 9 - 2 * 2 * 9, 2 * 2)


@pytest.mark.parametrize("law", list(_laws()), ids=lambda law: type(law).__name__)
def test_arc_frame_phi_of_one_float_equals_the_array_path(law):
    """ArcFrame.phi1 (one float, the envelope's tooth placement) evaluates the splines in plain Python: the same
    float as ArcFrame.phi (scipy's compiled evaluation) at arc lengths over three legs either side of zero, on the
    tabulated nodes (an interval's end) and between them; nan for nan."""
    fr = ArcFrame(PitchCurves(law, 160.0))
    rng = np.random.default_rng(11)
    s = np.concatenate([rng.uniform(-3 * fr.leg, 3 * fr.leg, 3000), fr.S, fr.S + fr.leg, [0.0, fr.leg, -fr.leg]])
    ref = fr.phi(s)
    got = np.array([fr.phi1(float(x)) for x in s])
    assert np.array_equal(got, ref)
    assert fr.phi1(math.nan) is None
    # arrays of up to 8 arc lengths take phi1 at each (laws.law.SMALL_ARRAY): the large array's bytes
    k = 0
    for n in [1, 2, 3, 5, 8, 9] * 60:
        assert _same(fr.phi(s[k:k + n]), ref[k:k + n]), (n, s[k:k + n])
        k += n
    with_nan = np.array([0.3, math.nan])
    assert np.isnan(fr.phi(with_nan)[1]) and _same(fr.phi(with_nan)[:1], fr.phi(s[:0].tolist() + [0.3]))


def test_ppoly_of_one_float_is_scipys_evaluation_bit_for_bit():
    """The plain-Python evaluation of a PPoly (pitch_frame._PPoly1) against scipy's on a Hermite spline and its
    derivative: random points inside and outside (extrapolated by the end pieces), every break point and its two
    neighbouring floats, nan."""
    from scipy.interpolate import CubicHermiteSpline

    from propulsor.gears.pitch_frame import _PPoly1

    rng = np.random.default_rng(3)
    x = np.unique(rng.uniform(-2.0, 3.0, 60))
    sp = CubicHermiteSpline(x, rng.normal(size=len(x)), rng.normal(size=len(x)))
    pts = np.concatenate([rng.uniform(-3.0, 4.0, 4000), x, np.nextafter(x, -np.inf), np.nextafter(x, np.inf)])
    for pp in (sp, sp.derivative()):
        f = _PPoly1(pp)
        assert np.array_equal(np.array([f(float(v)) for v in pts]), pp(pts))
        assert math.isnan(f(math.nan))
    with pytest.raises(ValueError):
        _PPoly1(CubicHermiteSpline(x, np.zeros((len(x), 2)), np.zeros((len(x), 2))))
