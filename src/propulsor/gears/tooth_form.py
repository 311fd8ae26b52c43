"""The tooth form of ISO 6336-3 (its own module: the external form factor of :mod:`.iso6336` and the internal
one of :mod:`.iso6336_internal` both return it)."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["ToothForm"]


@dataclass(frozen=True)
class ToothForm:
    theta: float      # rad, angle of the 30° tangent construction
    s_Fn: float       # mm, root chord at the 30° tangents
    rho_F: float      # mm, root fillet radius there
    h_Fe: float       # mm, bending moment arm (load at d_en)
    alpha_Fen: float  # rad, load direction angle
    Y_F: float
    Y_S: float
