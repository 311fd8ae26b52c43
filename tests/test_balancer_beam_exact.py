"""Exact values of the balancer arm as a beam (seed 004 ch. 8; mutation target ``mechanics_beam``): the statics,
sections and checks of ``propulsor.laws.balancer_beam`` against values computed independently here (hand
calculations, the textbook formulas written out, physical identities).  Everything is built inside its test."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


def test_in_plane_moment_falls_by_the_shear_between_stations():
    """dM_z/ds = -V_y between loads: M_z at s is the sum of (s_k - s) F_y over the loads outboard."""
    from propulsor.laws.balancer_beam import PointLoad, internal_forces

    loads = [PointLoad("a", 250.0, 40.0, 0.0, 3000.0), PointLoad("b", 100.0, 0.0, 0.0, -1000.0)]
    f = internal_forces(loads, [110.0, 130.0])
    assert f["V_y"].tolist() == [3000.0, 3000.0]
    assert f["M_z"][0] - f["M_z"][1] == pytest.approx(20.0 * 3000.0, rel=1e-15)
    assert f["M_z"].tolist() == [140.0 * 3000.0, 120.0 * 3000.0]
