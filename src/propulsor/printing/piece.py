"""One printed piece of a kit (its own module: the kit, the coupon and the part types' kits all make them)."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Piece"]


@dataclass
class Piece:
    """One printed piece: a solid at print size (mm), how many to print, its expected genus.  The piece is
    printed on its largest planar face with the bed-side chamfer made in its first layers
    (:mod:`.chamfer`)."""

    name: str
    solid: object
    count: int = 1
    genus: int | None = None
    what: str = ""
    #: bed-side chamfer (mm) of this piece; None: the printer's chamfer_mm (0 for pins lying on their flat,
    #: :func:`.hardware.side_pin`: their walls are round at the bed)
    chamfer_mm: float | None = None
