"""Fits measured on the printed pieces: a pin against the very hole it goes into.

A :class:`Fit` names the pin's piece (and where the pin stands on it), the hole's piece and where the
hole is, in each piece's own frame (the solid as the kit built it).  :func:`measure` reads both off
the pieces' meshes: the hole's radius is the least distance from the hole's axis to the holed piece's
vertices (a round hole's vertices lie on its circle; any other edge is farther), the pin's the largest
distance of the pin's vertices from its axis.  The hole prints `hole_undersize_mm` small (diameter):
that is taken off the measured hole.  A running fit must keep at least the running clearance
(radial), a press fit at least the press interference and less than the hole's wall can take.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..check import Check

#: a press fit tighter than this (radial, mm) splits a printed part
PRESS_MAX_MM = 0.3
#: a fit drawn exactly to its allowance measures it to within the vertices' rounding (mm)
TOL_MM = 1e-5


@dataclass(frozen=True)
class Fit:
    name: str
    pin: str
    hole: str
    hole_at: tuple[float, float]
    kind: str  # "running" or "press"
    what: str = ""
    #: the pin's axis on its piece, and the height range (its piece's frame) where it stands; None: all
    pin_at: tuple[float, float] = (0.0, 0.0)
    pin_z: tuple[float, float] | None = None


def hole_radius(mesh, at) -> float:
    """Radius of the round hole whose axis (parallel to z) passes through `at` (x, y): the least
    distance from the axis to the piece's vertices."""
    v = np.asarray(mesh.vertices)
    return float(np.min(np.hypot(v[:, 0] - at[0], v[:, 1] - at[1])))


def pin_radius(mesh, at=(0.0, 0.0), z=None, reach: float | None = None) -> float:
    """Radius of the pin whose axis passes through `at`: the largest distance from the axis of the
    piece's vertices within the height range `z` and within `reach` of the axis (a pin standing on a
    larger piece)."""
    v = np.asarray(mesh.vertices)
    if z is not None:
        # above the face the pin stands on (its vertices there are the face's too)
        v = v[(v[:, 2] > z[0] + 1e-3) & (v[:, 2] <= z[1] + 1e-9)]
    r = np.hypot(v[:, 0] - at[0], v[:, 1] - at[1])
    if reach is not None:
        r = r[r <= reach]
    return float(np.max(r))


def measure(fit: Fit, meshes: dict, printer) -> Check:
    """The fit's check on the pieces' meshes {name: mesh in the piece's own frame}."""
    under = printer.hole_undersize_mm
    r_hole = hole_radius(meshes[fit.hole], fit.hole_at) - under / 2
    reach = None if fit.pin_z is None else r_hole + 1.0
    r_pin = pin_radius(meshes[fit.pin], fit.pin_at, fit.pin_z, reach)
    where = (f"⌀{2 * r_pin:.3f} mm {fit.pin} in the ⌀{2 * r_hole:.3f} mm hole of {fit.hole} as printed (drawn "
             f"{2 * r_hole + under:.3f} mm, {under:g} mm undersize)")
    if fit.kind == "running":
        return Check.at_least(f"fit.{fit.name}", r_hole - r_pin, printer.running_clearance_mm - TOL_MM, "mm",
                              f"radial running clearance, measured: {where}" + (f"; {fit.what}" if fit.what else ""))
    interference = r_pin - r_hole
    ok = printer.press_fit_mm - TOL_MM <= interference <= PRESS_MAX_MM
    return Check.flag(f"fit.{fit.name}", ok, f"radial press interference {interference:.4f} mm (at least "
                      f"{printer.press_fit_mm:g}, at most {PRESS_MAX_MM:g}), measured: {where}"
                      + (f"; {fit.what}" if fit.what else ""))
