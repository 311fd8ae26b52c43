"""Solids for printing: turning a piece over (printed one way up, assembled the other).  The bed-side
chamfer is made on the printed mesh (:mod:`propulsor.printing.chamfer`)."""

from __future__ import annotations

from .cq_import import import_cadquery

__all__ = ["flipped"]


def flipped(solid, z_top: float, axis: str = "x"):
    """The solid turned over about the x (or y) axis, its former top z_top now at z = 0 (z -> z_top - z;
    y -> -y about x, x -> -x about y)."""
    cq = import_cadquery()

    turn = {"x": cq.Vector(1, 0, 0), "y": cq.Vector(0, 1, 0)}[axis]
    return solid.rotate(cq.Vector(0, 0, 0), turn, 180).translate(cq.Vector(0, 0, z_top))
