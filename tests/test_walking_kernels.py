"""The walking law's array functions compiled (laws/walking_kernels.py): ``WalkingLaw.U`` / ``dU_dphi`` and
``SmoothedWalkingLaw.U`` / ``dU_dphi`` equal numpy's element-wise formulas (the array path they replace) bit for bit,
on random laws (both blends: closure-exact and with a free hand-over value), random angles over many legs, angles at
and beside the windows' edges and the hand-overs, and non-finite angles; any array shape."""

from __future__ import annotations

import math

import numpy as np

from propulsor.gears.smoothed_law import SmoothedWalkingLaw
from propulsor.laws.walking import LEG_PERIOD, WalkingLaw, wrap_leg


def _numpy_exact(law: WalkingLaw, phi, what: int):
    """The array path as numpy computes it (laws/walking.py before the kernel)."""
    with np.errstate(invalid="ignore"):  # inf and nan give nan, as they do compiled
        if what == 0:
            return law._u * (law._A + law._3b * np.cos(2 * wrap_leg(phi))) / law._A
        return law._m6bu * np.sin(2 * wrap_leg(phi)) / law._A


def _numpy_smoothed(s: SmoothedWalkingLaw, phi, what: int):
    phi = np.asarray(phi, dtype=float)
    with np.errstate(invalid="ignore"):
        t = wrap_leg(phi - math.pi / 4)
    inw = np.abs(t) < s.delta
    blend = s._p(t) if what == 0 else s._dp(t)
    exact = _numpy_exact(s.law, phi, what)
    return np.where(inw, blend, s._1me * exact if s.u_h is not None else exact)


def _angles(rng, delta: float) -> np.ndarray:
    h = math.pi / 4 + LEG_PERIOD * np.arange(-9, 10)  # hand-overs
    edges = np.concatenate([h - delta, h + delta, h])
    near = np.concatenate([np.nextafter(edges, np.inf), np.nextafter(edges, -np.inf)])
    return np.concatenate([rng.uniform(-30.0, 30.0, 3000), edges, near, [np.nan, np.inf, -np.inf, 0.0, -0.0]])


def _same(a, b) -> bool:
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)


def test_the_compiled_walking_laws_are_numpys_formulas_bit_for_bit():
    rng = np.random.default_rng(11)
    laws = 0
    for a, b, c, n in ((60.0, 100.0, 360.0, 2), (100.0, 50.0, 236.5, 4), (66.0, 97.0, 350.0, 2),
                       (95.0, 55.0, 240.0, 4), (80.0, 70.0, 300.0, 3), (110.0, 45.0, 230.0, 4)):  # seeds 000, 002, more
        law = WalkingLaw(a, b, c, n)
        delta = float(rng.uniform(0.02, 0.25))
        phi = _angles(rng, delta)
        for what, f in ((0, law.U), (1, law.dU_dphi)):
            assert _same(f(phi), _numpy_exact(law, phi, what))
            one, ref = f(0.3), _numpy_exact(law, 0.3, what)  # one angle: a numpy scalar, as numpy gives it
            assert type(one) is type(ref) and one == ref
        for s in (SmoothedWalkingLaw(law, delta), SmoothedWalkingLaw(law, delta, u_h=float(law.u) * 0.9)):
            for what, f in ((0, s.U), (1, s.dU_dphi)):
                assert _same(f(phi), _numpy_smoothed(s, phi, what))
                grid = phi[:3000].reshape(60, 50)  # any shape
                assert _same(f(grid), _numpy_smoothed(s, grid, what))
            laws += 1
    assert laws == 12


def test_an_angle_exactly_at_a_windows_edge_takes_the_exact_law():
    """|t| = delta exactly (numpy's ``np.abs(t) < delta`` false): the exact law's value, as numpy gives it, not the
    blend's (equal there in exact arithmetic, not in the last bits)."""
    law = WalkingLaw(100.0, 50.0, 236.5, 4)
    differ = 0
    for d in (0.05, 0.1, 0.17, 0.2):
        delta = (math.pi / 4 + d) - math.pi / 4  # t of the angle pi/4 + d, exactly
        s = SmoothedWalkingLaw(law, delta)
        phi = np.concatenate([np.full(9, math.pi / 4 + d), math.pi / 4 + d + LEG_PERIOD * np.arange(1, 4)])
        t = wrap_leg(phi - math.pi / 4)
        at_edge = np.abs(t) == delta
        assert at_edge[:9].all()
        for what, f in ((0, s.U), (1, s.dU_dphi)):
            got = f(phi)
            assert _same(got, _numpy_smoothed(s, phi, what))
            assert _same(got[at_edge], _numpy_exact(law, phi[at_edge], what))
            blend = (s._p if what == 0 else s._dp)(t[at_edge])
            differ += int(np.any(blend != got[at_edge]))
    assert differ > 0  # the edge's two values differ somewhere: the test can tell the branches apart

