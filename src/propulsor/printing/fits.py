"""Fits measured on the printed pieces: a pin against the very hole it goes into.

A :class:`Fit` names the pin's piece (and where the pin stands on it), the hole's piece and where the
hole is, in each piece's own frame (the solid as the kit built it).  :func:`measure` reads both off
the pieces' meshes: the hole's radius is the least distance from the hole's axis to the holed piece's
vertices (a round hole's vertices lie on its circle; any other edge is farther), the pin's the largest
distance of the pin's vertices from its axis.  The hole prints `hole_undersize_mm` small (diameter):
that is taken off the measured hole.  A running fit must keep at least the running clearance
(radial), a press fit at least the press interference and less than the hole's wall can take.

A slot (a pin that presses into a slot's width, anywhere along it) has vertices only at the ends of
its straight sides: a :class:`Fit` with ``slot=True`` reads the hole off the piece's edges instead
(the least distance from the axis to an edge seen from above).

A :class:`Rim` is the wall between pins standing on a disc and the disc's rim (a carrier with its
pins, one piece): each pin's axis and radius are read off its vertices above the disc, the rim is the
outline (convex hull) of the disc's vertices, and the wall is the least distance from a pin's axis to
that outline less the pin's radius: at least the least feature (two line widths).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

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
    #: the hole is a slot (or any hole whose sides are long straight edges): measured off the edges
    slot: bool = False

    @property
    def pieces(self) -> tuple[str, ...]:
        return (self.pin, self.hole)


@dataclass(frozen=True)
class Rim:
    """Pins standing on a disc, one piece: the printed wall between each pin and the disc's rim.  `pins_at`
    are the pins' axes as drawn (each vertex above the disc belongs to the nearest one; the pin's own
    axis is then fitted to its vertices); `disc_z` is the disc's height range and `pin_z` the pins'
    (the piece's frame); `at` is the disc's axis."""

    name: str
    piece: str
    pins_at: tuple[tuple[float, float], ...]
    disc_z: tuple[float, float]
    pin_z: tuple[float, float]
    at: tuple[float, float] = (0.0, 0.0)
    what: str = ""
    kind: ClassVar[str] = "rim"

    @property
    def pieces(self) -> tuple[str, ...]:
        return (self.piece,)


def hole_radius(mesh, at) -> float:
    """Radius of the round hole whose axis (parallel to z) passes through `at` (x, y): the least
    distance from the axis to the piece's vertices."""
    v = np.asarray(mesh.vertices)
    return float(np.min(np.hypot(v[:, 0] - at[0], v[:, 1] - at[1])))


def slot_radius(mesh, at) -> float:
    """Half the width of a slot (or any hole) whose axis passes through `at`: the least distance from
    the axis to the piece's edges projected on the xy plane (a face's edges lie on its material, so the
    nearest ones bound the hole)."""
    v = np.asarray(mesh.vertices)[:, :2] - np.asarray(at, float)
    e = np.asarray(mesh.edges_unique)
    a, b = v[e[:, 0]], v[e[:, 1]]
    d = b - a
    L2 = np.einsum("ij,ij->i", d, d)
    t = np.clip(-np.einsum("ij,ij->i", a, d) / np.where(L2 > 0, L2, 1.0), 0.0, 1.0)
    return float(np.min(np.hypot(*(a + t[:, None] * d).T)))


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


def measure(fit: Fit | Rim, meshes: dict, printer) -> Check:
    """The fit's (or rim's) check on the pieces' meshes {name: mesh in the piece's own frame}."""
    if isinstance(fit, Rim):
        return _measure_rim(fit, meshes[fit.piece], printer)
    under = printer.hole_undersize_mm
    r_hole = (slot_radius if fit.slot else hole_radius)(meshes[fit.hole], fit.hole_at) - under / 2
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


def circle_fit(xy) -> tuple[np.ndarray, float]:
    """Centre and radius of the circle through points (n × 2) in the least-squares sense (Kåsa): exact
    for points on a circle."""
    xy = np.asarray(xy, float)
    m = xy.mean(axis=0)
    u = xy - m
    A = np.column_stack([2 * u, np.ones(len(u))])
    sol = np.linalg.lstsq(A, np.einsum("ij,ij->i", u, u), rcond=None)[0]
    c = m + sol[:2]
    return c, float(np.max(np.hypot(*(xy - c).T)))


def rim_pins(mesh, rim: Rim) -> list[tuple[np.ndarray, float] | None]:
    """[(axis, radius) or None when the pin has no vertices] of each pin of `rim`, read off the piece's
    vertices above the disc (each to the nearest drawn axis)."""
    v = np.asarray(mesh.vertices)
    v = v[(v[:, 2] > rim.pin_z[0] + 1e-3) & (v[:, 2] <= rim.pin_z[1] + 1e-9)][:, :2]
    drawn = np.asarray(rim.pins_at, float)
    nearest = np.argmin(np.hypot(v[:, None, 0] - drawn[None, :, 0], v[:, None, 1] - drawn[None, :, 1]), axis=1)
    return [circle_fit(v[nearest == k]) if np.count_nonzero(nearest == k) >= 3 else None for k in range(len(drawn))]


def rim_outline(mesh, rim: Rim):
    """The disc's outline seen from above: the convex hull (scipy) of its vertices in `disc_z`."""
    from scipy.spatial import ConvexHull

    v = np.asarray(mesh.vertices)
    v = v[(v[:, 2] >= rim.disc_z[0] - 1e-9) & (v[:, 2] <= rim.disc_z[1] + 1e-9)]
    return ConvexHull(v[:, :2])


def rim_walls(mesh, rim: Rim) -> list[tuple[float, np.ndarray, float, float] | None]:
    """[(wall, pin axis, pin radius, the axis' distance inside the rim) or None when the pin has no
    vertices] of each pin of `rim` on the piece's mesh."""
    hull = rim_outline(mesh, rim)
    out = []
    for pin in rim_pins(mesh, rim):
        if pin is None:
            out.append(None)
            continue
        c, r = pin
        # a point's distance inside a convex outline: the least over its edges' lines (negative outside)
        inside = float(np.min(-(hull.equations[:, :2] @ c + hull.equations[:, 2])))
        out.append((inside - r, c, r, inside))
    return out


def _measure_rim(rim: Rim, mesh, printer) -> Check:
    least = printer.min_feature_mm
    walls = rim_walls(mesh, rim)
    missing = [k for k, w in enumerate(walls, 1) if w is None]
    if missing:
        return Check.flag(f"fit.{rim.name}", False, f"pin(s) {missing} of {rim.piece} not found above its disc")
    k = min(range(len(walls)), key=lambda i: walls[i][0])
    wall, c, r, inside = walls[k]
    return Check.at_least(
        f"fit.{rim.name}", wall, least - TOL_MM, "mm",
        f"printed wall between each pin and the rim of {rim.piece}, least at pin {k + 1}: measured ⌀{2 * r:.3f} mm, "
        f"its axis {float(np.hypot(*(c - np.asarray(rim.at)))):.3f} mm from the disc's axis and {inside:.3f} mm "
        f"inside the rim (at least {least:g} mm, two line widths)" + (f"; {rim.what}" if rim.what else ""))
