"""A spline's samples are kept per chord tolerance (geometry/profile.py ``Spline.sample``): the points sampled
anew, bit for bit, read-only (a caller cannot change what the next one reads), carried through a pickle (a forked
worker gets them rather than sampling again)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from propulsor.geometry.profile import Loop, Spline


def _spline():
    return Spline(np.array([0, 0, 0, 0, 0.5, 1, 1, 1, 1.0]), np.array([[0, 0], [1, 2], [2, -1], [3, 0.5], [4, 0.0]]))


def test_the_samples_are_sampled_once_per_tolerance_and_are_those_sampled_anew():
    s = _spline()
    fine, coarse = s.sample(1e-4), s.sample(5e-3)
    assert s.sample(1e-4) is fine and s.sample(5e-3) is coarse
    assert len(fine) > len(coarse)
    assert fine.tobytes() == _spline().sample(1e-4).tobytes() == s._sample(1e-4).tobytes()
    with pytest.raises(ValueError):
        fine[0, 0] = 1.0  # read-only
    loop = Loop([s, Spline(s.knots, s.poles[::-1].copy())])
    assert loop.polyline(1e-4)[: len(fine) - 1].tobytes() == fine[:-1].tobytes()


def test_the_samples_go_with_a_pickle_and_stay_read_only():
    s = _spline()
    kept = s.sample(1e-4)
    t = pickle.loads(pickle.dumps(s))
    assert "_samples" in t.__dict__
    got = t.sample(1e-4)
    assert got.tobytes() == kept.tobytes() and not got.flags.writeable
