"""The carrier's bearings, spline and shaft: static capacity (ISO 76), crushing of the spline,
equivalent stress of the carrier shaft (seed 004 ch. 4.2, 4.3).

    C_0r = 44·(1 − D_we·cos α / D_pw)·i·Z·L_we·D_we·cos α        eq. 48 / 49 (ISO 76:2006 eq. 7, radial
                                                                   roller bearings, N, lengths mm)
    K_0 = S_0 = C_0 / R                                           eq. 50 (static safety factor)
    K_Σ = K_pr·K_z·K_p                                            eq. 52
    [σ]_sm = σ_T / (n·K_Σ),   σ = T / (S_u·L)                     eq. 53 (GOST 21425-75; the spline's
                                                                   S_u, eq. 51, is geometry/involute_spline.py)
    σ_v = Q·L / W_i,  τ = T / W_k,  σ_pr = √(σ_v² + 4τ²),  k = σ_T / σ_pr      shaft, after eq. 53

What the printed digits say (each one in ``tests/test_carrier_strength.py``):

* eq. 48 (planet bearing 10231…, D_w = L_w = 15, D_pw = 80, z = 16, α = 0): C_0 = 128 700 N as in
  Table 8; K_0 = 128 700 / 92 000 = 1.399, printed 1.39 (truncated).
* eq. 49 (carrier bearing, D_w = 25, α = 12°, D_pw = 167.519, i = 2, z = 36, L_w = 21.4) gives
  1 415 838 N; Table 8 lists 1 398 120 N for bearing 3524 (1.3 % less), and its safety 1.629 is
  1 398 120 / 858 508 — the text says R = 522 000 N for the same bearing (K_0 = 2.68 with it).
* Table 8's second carrier bearing "224" (GOST 8338: a ball bearing 120 × 215 × 40) with C_0 = 706 336 N and
  no inputs: no radial ball bearing in that envelope reaches it (ISO 76 with f_0 = 20, balls as large as the
  section and as many as fit: C_0 <= 499 906 N); a roller bearing (e.g. 2224, GOST 8328) would.
* eq. 53: [σ]_sm = 785/(1.4·3.71) = 151.136 MPa as printed, but the text says the hub (the weaker
  part the check is made for) is 30ХГСЛ with σ_T = 630 MPa: [σ]_sm = 121.294 MPa, margin 1.035
  instead of 1.29. The printed σ = 117.164 MPa is T/(S_u·L) with T in N·mm; the "·2π" printed in
  eq. 53 would give 0.736 MPa.
* shaft: "√(σ_v² · 4τ²)" is printed for √(σ_v² + 4τ²); 775.831 MPa is the latter (the former
  would be 264 918, not a stress). W_i = 169 646.003 mm³ is π·120³/32 (solid 120 mm section); the printed
  W_k = 272 271.363 mm³ is not the polar modulus of that section (2·W_i = 339 292.006 mm³) — it
  is π·d³/16 of d = 111.513 mm.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from propulsor.errors import require_positive

__all__ = ["RollerBearing", "static_capacity_radial_roller", "spline_allowable", "spline_crushing_stress",
           "shaft_equivalent_stress", "ShaftStress", "PLANET_BEARING_004", "CARRIER_BEARING_004"]


def static_capacity_radial_roller(D_we: float, D_pw: float, i: int, Z: int, L_we: float, alpha_rad: float) -> float:
    """Basic static radial load rating C_0r of a radial roller bearing, N (ISO 76:2006; seed 004 eq. 48–49)."""
    for name, v in (("D_we", D_we), ("D_pw", D_pw), ("i", i), ("Z", Z), ("L_we", L_we)):
        require_positive(name, v, "mm" if name in ("D_we", "D_pw", "L_we") else "")
    c = math.cos(alpha_rad)
    return 44.0 * (1.0 - D_we * c / D_pw) * i * Z * L_we * D_we * c


@dataclass(frozen=True)
class RollerBearing:
    """A radial roller bearing by its rolling elements (ISO 76) and its catalogue size."""

    designation: str
    d: float        # bore, mm
    D: float        # outside diameter, mm
    B: float        # width, mm
    D_we: float     # roller diameter, mm
    D_pw: float     # pitch diameter of the roller set, mm
    i: int          # rows
    Z: int          # rollers per row
    L_we: float     # roller length, mm
    alpha_deg: float = 0.0
    C0_catalogue: float | None = None   # N, as the thesis's Table 8 lists it

    @property
    def C0(self) -> float:
        """ISO 76 static rating from the rolling elements, N."""
        return static_capacity_radial_roller(self.D_we, self.D_pw, self.i, self.Z, self.L_we,
                                             math.radians(self.alpha_deg))

    def S0(self, load_N: float) -> float:
        """Static safety factor S_0 = C_0 / P_0 (seed 004 eq. 50)."""
        return self.C0 / require_positive("bearing_load", load_N, "N")


# Table 8 of seed 004 with the rolling elements of eq. 48 / 49.  Planet bearing "10231…" (thesis): the
# thesis gives only its rollers; d × D × B here are ours, from the rollers (raceways D_pw ∓ D_w = 65 / 95 mm,
# rings 5 / 7.5 mm, ribs 3 mm each side of the 15 mm roller) — D = 110 mm is the planet bore of
# final_drive.toml.  Carrier bearing 3524 (GOST 5721, double-row spherical roller = ISO 22224): 120 × 215 × 58.
PLANET_BEARING_004 = RollerBearing("10231 (thesis; d x D x B ours)", 55.0, 110.0, 21.0, 15.0, 80.0, 1, 16,
                                   15.0, 0.0, 128700.0)
CARRIER_BEARING_004 = RollerBearing("3524 (GOST 5721)", 120.0, 215.0, 58.0, 25.0, 167.519, 2, 36, 21.4, 12.0,
                                    1398120.0)


def spline_allowable(sigma_T: float, n: float, K_pr: float, K_z: float, K_p: float) -> float:
    """Allowed crushing pressure [σ]_sm = σ_T / (n·K_pr·K_z·K_p), MPa (seed 004 eq. 52–53)."""
    return sigma_T / (n * K_pr * K_z * K_p)


def spline_crushing_stress(T_Nm: float, S_u: float, L: float) -> float:
    """Mean crushing pressure σ = T / (S_u·L), MPa; T in N·m, S_u mm³/mm, L mm (seed 004 eq. 53, without
    the printed stray 2π)."""
    return T_Nm * 1e3 / (require_positive("S_u", S_u) * require_positive("spline_length", L, "mm"))


@dataclass(frozen=True)
class ShaftStress:
    sigma_b: float    # bending, MPa
    tau: float        # torsion, MPa
    sigma_eq: float   # √(σ² + 4τ²), MPa
    margin: float     # σ_T / σ_eq


def shaft_equivalent_stress(Q: float, L: float, W_i: float, T_Nm: float, W_k: float, sigma_T: float) -> ShaftStress:
    """Bending Q·L/W_i, torsion T/W_k, equivalent √(σ² + 4τ²) and margin σ_T/σ_eq (seed 004 §4.3);
    Q in N, L in mm, W in mm³, T in N·m."""
    s = Q * L / require_positive("W_i", W_i, "mm³")
    t = T_Nm * 1e3 / require_positive("W_k", W_k, "mm³")
    e = math.sqrt(s * s + 4.0 * t * t)
    return ShaftStress(s, t, e, sigma_T / e)
