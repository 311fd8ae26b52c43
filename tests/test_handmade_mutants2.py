"""Engineering truths the round-2 hand-made mutants of issue 36 found unpinned (mutation/handmade.toml, round = 2;
mutation/README.md, "Hand-made mutants, round 2").

Each test computes its expected value independently of the code under test (a closed form, the definition a
docstring states) and names the mutant it kills."""

from __future__ import annotations

import pytest

from propulsor.errors import InputError
from propulsor.params import load_params
from propulsor.parts.road_wheel.params import RoadWheelParams


# ---- parts/road_wheel/params.py: Kozlov's deflection limit in the parameter check (mutant road_wheel-params-64) ----
def _load_for_deflection(share: float, R=315.0, b=90.0, H=40.0, E=6.0, rows=2) -> float:
    """Wheel load (N) whose Kozlov deflection lambda_m is ``share`` of the rubber thickness H.

    Eq. 80 l = 2 (H/R)^(1/3) sqrt(R P / (E b)) and eq. 79 lambda_m = l^2 / (8 R) give, in closed form,
    lambda_m = (H/R)^(2/3) P / (2 E b)  (P the load of one row, N; E MPa; lengths mm)."""
    P_row = share * H * 2.0 * E * b / (H / R) ** (2.0 / 3.0)
    return rows * P_row


@pytest.mark.parametrize("share, refused", [(0.75, False), (0.95, False), (1.05, True), (1.5, True)])
def test_load_is_refused_where_kozlov_deflection_reaches_the_rubber(share, refused):
    """The part file's check refuses a load exactly where lambda_m = l^2/(8R) reaches H: three quarters of H
    passes (l^2/(4R), twice the deflection, would already refuse it), 5 % over H is refused."""
    mapping = {"load_N": _load_for_deflection(share)}
    if refused:
        with pytest.raises(InputError) as e:
            load_params(RoadWheelParams, mapping)
        assert "load_N" in str(e.value)
    else:
        p = load_params(RoadWheelParams, mapping)
        lam = float(p.tyre().deflection(p.load_N / p.rows))
        assert lam == pytest.approx(share * p.tyre_thickness_mm, rel=1e-9)
