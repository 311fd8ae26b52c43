"""The spline fits of a generated wheel made in lock step (geometry/bspline.py ``fit_curves``; the points of many
teeth's curves computed together, gears/curve_batch.py ``evaluate_curves``): the splines of the fits made one
after the other, bit for bit; the points of every curve those it gives alone, bit for bit; the curves of a law that
does not say it is elementwise each evaluated alone."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.gears import curve_batch
from propulsor.gears.noncircular import PitchCurves
from propulsor.gears.noncircular_teeth import ToothSpec, generate_teeth
from propulsor.gears.pitch_frame import ArcFrame, BodyPitchCurve
from propulsor.geometry import bspline
from propulsor.laws.ratio_laws import EllipticalLaw, FourierLaw
from propulsor.policy import SPLINE_FIT_TOL_MM


def _involute(r_b, fail_at=None):
    def f(u):
        u = np.asarray(u, float)
        if fail_at is not None and np.any(u > fail_at):
            raise ValueError(f"involute of r_b = {r_b} asked past u = {fail_at}")
        return np.column_stack([r_b * (np.cos(u) + u * np.sin(u)), r_b * (np.sin(u) - u * np.cos(u))])
    return f


def _same(a, b) -> bool:
    return (np.array_equal(a.knots, b.knots) and np.array_equal(a.poles, b.poles) and a.degree == b.degree)


def test_fits_in_lock_step_are_the_fits_one_after_the_other_each_parameter_asked_once():
    curves = [(_involute(r), 0.0, u1) for r, u1 in ((37.5, 0.9), (12.0, 1.4), (80.0, 0.3), (5.0, 2.5))]
    rounds = []

    def evaluate(requests):
        rounds.append([len(u) for _, u in requests])
        return [f(u) for f, u in requests]

    got = bspline.fit_curves(curves, evaluate, n0=8)
    for (f, u0, u1), s in zip(curves, got):
        assert _same(s, bspline.fit_curve(f, u0, u1, n0=8))
    assert len(rounds) >= 2 and rounds[0] == [8, 8, 8, 8]  # every fit's first points asked in one call
    assert len(rounds[-1]) < 4  # the fits that reached the tolerance dropped out


def test_the_first_failing_fit_s_error_is_raised_after_the_others_end():
    """The second and fourth curves fail (the fourth first in time: it is asked past its end at once); the second's
    error is raised, as when the fits run one after the other, and a batch that raises is evaluated curve by curve."""
    curves = [(_involute(37.5), 0.0, 0.9), (_involute(12.0, fail_at=1.0), 0.0, 1.4), (_involute(80.0), 0.0, 0.3),
              (_involute(5.0, fail_at=0.1), 0.0, 2.5)]

    def evaluate(requests):
        return [f(u) for f, u in requests]

    with pytest.raises(ValueError, match="r_b = 12.0"):
        bspline.fit_curves(curves, evaluate, n0=8)
    with pytest.raises(ValueError, match="r_b = 12.0"):
        for f, u0, u1 in curves:
            bspline.fit_curve(f, u0, u1, n0=8)
    with pytest.raises(RuntimeError, match="did not reach"):
        bspline.fit_curves(curves[:1] + curves[2:3], evaluate, n0=8, max_points=9)


class _NotElementwise:
    """A law as another gives it, without saying ``elementwise`` (a law of a user's that does not promise it)."""

    def __init__(self, law):
        self._law = law

    def __getattr__(self, name):
        if name == "elementwise":
            raise AttributeError(name)
        return getattr(self._law, name)


def _pitch(law, m):
    pc0 = PitchCurves(law, 100.0)
    z_H = round(pc0.perimeter_driven() / (math.pi * m) / law.n) * law.n
    return PitchCurves(law, 100.0 * z_H * math.pi * m / pc0.perimeter_driven())


@pytest.mark.parametrize("law, role, grouped", [
    (EllipticalLaw(e=0.4, k=2), "driven", True),
    (EllipticalLaw(e=0.4, k=2), "driver", True),
    (FourierLaw(2, (0.03, -0.01), (0.02, 0.0, 0.005)), "driven", True),
    (FourierLaw(2, (0.03, -0.01), (0.02, 0.0, 0.005)), "driver", True),
    (_NotElementwise(EllipticalLaw(e=0.4, k=2)), "driven", False),
])
def test_the_teeth_s_curves_evaluated_together_give_each_curve_s_own_points(monkeypatch, law, role, grouped):
    m = 2.0
    pc = _pitch(law, m)
    frame = ArcFrame(pc)
    g = generate_teeth(pc, role, ToothSpec(m=m), frame)
    curve = BodyPitchCurve(pc, role)
    rng = np.random.default_rng(7)
    requests = []
    for R, Lf in g.sides:
        for c in (R.flank, R.fillet, Lf.flank, Lf.fillet):
            requests.append((c, np.sort(rng.uniform(min(c.u0, c.u1), max(c.u0, c.u1), int(rng.integers(2, 12))))))
    for h in (-2.5, 1.9, 2.0):
        requests.append((curve.equidistant(h), np.sort(rng.uniform(0.0, 2.0 * math.pi, 9))))
    requests.append((requests[0][0], np.array([requests[0][0].u0])))  # one parameter: the curve's one-point path
    alone = [np.asarray(f(u), float) for f, u in requests]
    calls = []
    real = curve_batch.envelope_points
    monkeypatch.setattr(curve_batch, "envelope_points", lambda *a: calls.append(len(a[1])) or real(*a))
    together = curve_batch.evaluate_curves(requests)
    assert all(np.array_equal(a, b) for a, b in zip(alone, together))  # bit for bit
    if grouped:
        assert 0 < len(calls) <= 8 and sum(calls) == sum(len(u) for f, u in requests[:-4])
    else:
        assert calls == []  # a law that does not say it is elementwise: each curve evaluated alone


def _elementwise_laws():
    from pathlib import Path

    from propulsor.building import load_part
    from propulsor.gears.smoothed_law import SmoothedWalkingLaw
    from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw
    from propulsor.parts.noncircular_pair.cutting import law_of

    parts = Path(__file__).resolve().parents[1] / "parts"
    for seed in (SEED_000, SEED_002):
        law = WalkingLaw(**seed)
        yield law
        yield SmoothedWalkingLaw(law, 0.12, u_h=0.75 * law.u)
    yield EllipticalLaw(e=0.4, k=2)
    yield FourierLaw(2, (0.03, -0.01), (0.02, 0.0, 0.005))
    for name in ("ncg_table.toml", "ncg_pitch_curve.toml", "ncg_fourier_seed002.toml", "ncg_fourier_3lobe.toml"):
        _, p, _ = load_part(parts / name)
        yield law_of(p, parts / name)


@pytest.mark.parametrize("law", list(_elementwise_laws()), ids=lambda lw: f"{type(lw).__name__}")
def test_a_law_that_says_it_is_elementwise_gives_each_angle_its_own_value_in_any_array(law):
    """What ``elementwise = True`` promises (laws/law.py), on the functions the teeth's curves read: each angle's
    value, bit for bit, whatever array it comes in (2 to 17 angles at a time, or all 160 together), and so for the
    pitch points and normals of both wheels."""
    assert law.elementwise is True
    rng = np.random.default_rng(3)
    phi = rng.uniform(-7.0, 7.0, 160)
    pc = PitchCurves(law, 120.0)
    fns = [law.U, law.dU_dphi, law.d2U_dphi2, law.theta]
    fns += [getattr(BodyPitchCurve(pc, r), f) for r in ("driver", "driven") for f in ("point", "normal")]
    for fn in fns:
        whole = np.asarray(fn(phi), float)
        for size in (2, 3, 8, 9, 17):
            parts = [np.asarray(fn(phi[i:i + size]), float) for i in range(0, len(phi), size)]
            assert np.concatenate(parts).tobytes() == whole.tobytes(), (fn, size)
