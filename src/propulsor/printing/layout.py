"""Pieces on plates: each piece laid on its largest planar face, plates packed shelf by shelf.

A piece is a triangle mesh (trimesh).  :func:`lay_flat` turns it so that its largest planar face
(the largest coplanar facet, by area) lies on the bed, z = 0, and moves its footprint's corner to
the origin.  :func:`pack` places footprints on as few plates as a shelf packer manages: pieces by
decreasing depth, left to right along a shelf, a new shelf above the deepest piece of the last,
a new plate when the bed is full; a piece is turned by 90° when only that fits.  Each plate's pieces are
then centred on the bed as one block: the room left over is shared between the opposite edges, none of
them nearer to an edge than the margin (which holds the slicer's skirt, policy.PLATE_MARGIN_MM).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import trimesh

from ..errors import InputError


def _rotation_to_minus_z(n: np.ndarray) -> np.ndarray:
    """4 × 4 rotation taking the unit vector n to (0, 0, −1)."""
    return trimesh.geometry.align_vectors(np.asarray(n, float), np.array([0.0, 0.0, -1.0]))


def lay_flat(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The mesh on its largest planar face, its footprint's smallest enclosing rectangle along x and y
    with the corner at the origin; and the 4 × 4 transform."""
    areas = np.asarray(mesh.facets_area)
    if len(areas):
        k = int(np.argmax(areas))
        normal = np.asarray(mesh.facets_normal[k])
        face_area = float(areas[k])
    else:
        normal, face_area = np.array([0.0, 0.0, -1.0]), 0.0
    # a single triangle larger than every facet is a planar face too
    if len(mesh.faces) and float(mesh.area_faces.max()) > face_area:
        normal = np.asarray(mesh.face_normals[int(np.argmax(mesh.area_faces))])
    T = _rotation_to_minus_z(normal)
    out = mesh.copy()
    out.apply_transform(T)
    # turn about z so that the footprint's smallest enclosing rectangle is axis-aligned
    T2, _ = trimesh.bounds.oriented_bounds_2D(np.asarray(out.vertices)[:, :2])
    Rz = np.eye(4)
    Rz[:2, :2] = T2[:2, :2]
    out.apply_transform(Rz)
    T = Rz @ T
    lo = out.bounds[0]
    shift = trimesh.transformations.translation_matrix(-lo)
    out.apply_transform(shift)
    return out, shift @ T


@dataclass
class Placement:
    name: str
    x: float
    y: float
    turned: bool  # turned by 90° about z


@dataclass
class Plate:
    placements: list[Placement] = field(default_factory=list)


def pack(footprints: dict[str, tuple[float, float]], bed_x: float, bed_y: float, gap: float,
         margin: float | None = None) -> list[Plate]:
    """Shelf packing of rectangular footprints {name: (x, y)} on beds of bed_x × bed_y with `gap`
    between pieces and at least `margin` (None: the gap) to the bed's edge, each plate's block of pieces
    centred on the bed.  Deterministic (ties broken by name)."""
    margin = gap if margin is None else margin
    usable_x, usable_y = bed_x - 2 * margin, bed_y - 2 * margin
    items = []
    for name, (w, d) in footprints.items():
        if w <= usable_x and d <= usable_y:
            # prefer the orientation whose depth is smaller (lower shelves), when it fits
            turned = d > w and d <= usable_x and w <= usable_y
        elif d <= usable_x and w <= usable_y:
            turned = True
        else:
            raise InputError("piece", name, f"{w:.1f} × {d:.1f} mm does not fit the {bed_x:g} × {bed_y:g} mm bed "
                             f"with {margin:g} mm margins", f"a bed of at least {math.ceil(max(w, d) + 2 * margin):g} "
                             f"× {math.ceil(min(w, d) + 2 * margin):g} mm")
        items.append((name, (d, w) if turned else (w, d), turned))
    items.sort(key=lambda it: (-it[1][1], -it[1][0], it[0]))
    plates: list[Plate] = []
    sizes = {name: size for name, size, _ in items}
    plate, x, y, shelf_d = None, 0.0, 0.0, 0.0
    for name, (w, d), turned in items:
        if plate is not None and x + w > usable_x + 1e-9:  # next shelf
            x, y, shelf_d = 0.0, y + shelf_d + gap, 0.0
        if plate is None or y + d > usable_y + 1e-9:  # next plate
            plate = Plate()
            plates.append(plate)
            x, y, shelf_d = 0.0, 0.0, 0.0
        plate.placements.append(Placement(name, margin + x, margin + y, turned))
        x += w + gap
        shelf_d = max(shelf_d, d)
    for plate in plates:
        _centre(plate, sizes, bed_x, bed_y)
    return plates


def _centre(plate: Plate, sizes: dict[str, tuple[float, float]], bed_x: float, bed_y: float) -> None:
    """Move a plate's pieces as one block so that their joint footprint is centred on the bed."""
    lo_x = min(p.x for p in plate.placements)
    lo_y = min(p.y for p in plate.placements)
    hi_x = max(p.x + sizes[p.name][0] for p in plate.placements)
    hi_y = max(p.y + sizes[p.name][1] for p in plate.placements)
    dx = 0.5 * (bed_x - (hi_x - lo_x)) - lo_x
    dy = 0.5 * (bed_y - (hi_y - lo_y)) - lo_y
    for p in plate.placements:
        p.x += dx
        p.y += dy


def placed(mesh: trimesh.Trimesh, p: Placement) -> trimesh.Trimesh:
    """A laid-flat mesh (footprint corner at the origin) moved to its place on the plate."""
    out = mesh.copy()
    if p.turned:
        out.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [0, 0, 1]))
        out.apply_translation(-out.bounds[0])
    out.apply_translation([p.x, p.y, 0.0])
    return out
