"""Tooth root of an internal spur gear (a ring) by ISO 6336-3:2019 (6.2, internal gears: the substitute rack),
method B.  mm, radians.

The internal gear's tooth is taken as the tooth of a rack with its reference line on the reference circle d2, its
tooth thickness s2 there (as made: the thickness allowance E_sn of the solid removed), flanks at α, its root
on the root circle d_f2 and a root fillet of radius ρ_fP2, the tip radius ρ_a0 of the pinion-type cutter that
generates it.  Depth y is measured from d2 towards the root (y = (d − d2)/2):

    h_fP2 = (d_f2 − d2)/2,   x_c = s2/2 + (h_fP2 − ρ_fP2)·tan α + ρ_fP2/cos α      (centre of the fillet)
    s_Fn2 = 2·(x_c − ρ_fP2·cos 30°)                          root chord at the 30° tangents
    y_F   = h_fP2 − ρ_fP2·(1 − sin 30°)                      their depth
    ρ_F2  = ρ_fP2
    load at d_en2, the single-contact point nearest the ring's tip (method B; the internal wheel's tip point moved
    (ε_α − 1) base pitches into the path of contact):
    d_en2 = 2·√((√(r_a2² − r_b2²) + (ε_α − 1)·p_b)² + r_b2²)
    y_e = (d_en2 − d2)/2,  its half thickness x_e = s2/2 + y_e·tan α, its line of action (at α on the rack) meets
    the tooth centre line at y_e + x_e·tan α:
    h_Fe2 = y_F − y_e − x_e·tan α,   α_Fen2 = α
    Y_F = 6·(h_Fe/m)·cos α_Fen/((s_Fn/m)²·cos α),   Y_S = (1.2 + 0.13·L)·q_s^(1/(1.21 + 2.3/L)),
    L = s_Fn/h_Fe,  q_s = s_Fn/(2·ρ_F)  (the Y_S formula is fitted for 1 <= q_s < 8)
    Y_B (internal gear, rim s_R below the root): 1 for s_R >= 3.5·m, 1.15·ln(8.324·m/s_R) for 1.75 < s_R/m < 3.5

Method C of the 1996 edition puts the load at the ring's tip, d_en2 = d_a2, and applies Y_ε.
"""

from __future__ import annotations

import math

from ..errors import InputError, require_positive
from .tooth_form import ToothForm

__all__ = ["d_en_internal", "internal_tooth_form", "y_b_internal"]


def d_en_internal(d_a2: float, d_b2: float, m: float, alpha: float, eps_alpha: float) -> float:
    """Diameter of the single-contact point nearest the internal wheel's tip (ISO 6336-3:2019 method B)."""
    r_b = 0.5 * d_b2
    if not d_a2 > d_b2:
        raise InputError("d_a2", d_a2, f"the internal wheel's tip must lie outside its base circle {d_b2:.4f} mm")
    g = math.sqrt((0.5 * d_a2) ** 2 - r_b ** 2) + math.pi * m * math.cos(alpha) * (eps_alpha - 1.0)
    return 2.0 * math.sqrt(g * g + r_b * r_b)


def internal_tooth_form(d: float, d_f: float, s: float, m: float, rho_fP: float, d_en: float,
                        alpha: float = math.radians(20.0)) -> ToothForm:
    """Y_F and Y_S of an internal spur gear's tooth, load at diameter d_en (ISO 6336-3:2019, 6.2, substitute
    rack; see the module docstring): d the reference, d_f the root diameter, s the arc tooth thickness on d as
    made, ρ_fP the root fillet radius (the cutter's tip radius), mm."""
    for name, val in (("d", d), ("s", s), ("m", m), ("rho_fP", rho_fP), ("d_en", d_en)):
        require_positive(name, val, "mm")
    if not d_f > d:
        raise InputError("d_f", d_f, f"an internal gear's root diameter must exceed its reference diameter {d:g} mm")
    t = math.tan(alpha)
    h_fP = 0.5 * (d_f - d)
    x_c = 0.5 * s + (h_fP - rho_fP) * t + rho_fP / math.cos(alpha)
    s_Fn = 2.0 * (x_c - rho_fP * math.cos(math.pi / 6.0))
    y_F = h_fP - rho_fP * (1.0 - math.sin(math.pi / 6.0))
    y_e = 0.5 * (d_en - d)
    x_e = 0.5 * s + y_e * t
    h_Fe = y_F - y_e - x_e * t
    if not (s_Fn > 0 and h_Fe > 0):
        raise InputError("d_en", d_en, f"no bending arm below the load point (h_Fe = {h_Fe:.4f} mm, s_Fn = {s_Fn:.4f} mm)")
    Y_F = 6.0 * (h_Fe / m) * math.cos(alpha) / ((s_Fn / m) ** 2 * math.cos(alpha))
    L = s_Fn / h_Fe
    q_s = s_Fn / (2.0 * rho_fP)
    Y_S = (1.2 + 0.13 * L) * q_s ** (1.0 / (1.21 + 2.3 / L))
    return ToothForm(math.pi / 6.0, s_Fn, rho_fP, h_Fe, alpha, Y_F, Y_S)


def y_b_internal(s_R: float, m: float) -> float:
    """Rim thickness factor Y_B of an internal gear (ISO 6336-3:2019, Y_B of internal gears; see the module docstring)."""
    require_positive("s_R", s_R, "mm")
    r = s_R / m
    if r >= 3.5:
        return 1.0
    if r <= 1.75:
        raise InputError("s_R", s_R, f"rim under the root must exceed 1.75·m = {1.75 * m:g} mm (ISO 6336-3 Y_B)")
    return 1.15 * math.log(8.324 / r)
