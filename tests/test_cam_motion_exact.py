"""Exact values of the cam's roller-centre path (seed 001; mutation target ``mechanics_cam``): the support phase of
eq. 20, the return closure and the per-angle table of ``propulsor.laws.cam_motion`` against values computed
independently here (closed forms, hand calculations, the seed's equations written out).  Every cam is built inside
its test (a cam built at collection or in a module fixture cannot kill a mutant of its construction)."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


def test_straight_roller_path_is_h0_over_cos_phi_with_gamma_equal_to_phi():
    """K = 0: the roller centre runs on the line at H0 below the axle, H = H0/cos φ, γ = atan(H'/H) = φ."""
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    mech = CamMechanism(R0=70.0, r=15.0, n_legs=5)
    p = solve_support(mech, CurvatureLaw("zero"), estimate_error=False)
    phi = np.linspace(-math.pi / 5, math.pi / 5, 9)
    H, g = p.state(phi)
    assert H == pytest.approx(85.0 / np.cos(phi), rel=1e-9)
    assert g == pytest.approx(phi, abs=1e-9)
