"""One point of an envelope (``envelope.envelope_points`` for one cutter parameter): the solvers'
one-point calls evaluated on floats with the operations of the array functions, in the same order
(``math`` for cos, sin, sqrt; numpy for arctan / arctan2 and the arc-length spline), so bit-identical
to them (docs/architecture.md, «tooth generator», one-point paths).  Pure math.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["envelope_point1", "nearer_circle_crossing1"]


def nearer_circle_crossing1(px, py, nx, ny, cx, cy, R):
    """``nearer_circle_crossing`` for one point (floats, the same operations), or None where the
    normal misses the circle (the array function raises)."""
    qx, qy = px - cx, py - cy
    b = qx * nx + qy * ny
    c = (qx * qx + qy * qy) - R ** 2
    disc = b * b - c
    if not disc >= 0:
        return None
    sq = math.sqrt(disc)
    l1, l2 = -b + sq, -b - sq
    lam = l1 if abs(l1) <= abs(l2) else l2
    return px + lam * nx, py + lam * ny


def envelope_point1(piece, u: float, cutter, gear):
    """``envelope_points`` for one cutter parameter u (the solvers' one-point calls): the same
    operations on floats (``math``; numpy only for arctan / arctan2 / the arc-length spline), so
    bit-identical; None where the array path is needed (not closed-form, not finite, or an error
    to raise)."""
    if not math.isfinite(u):
        return None
    px, py = piece.point1(u)
    tx, ty = piece.tangent1(u)
    n = math.sqrt(tx * tx + ty * ty)
    tx, ty = tx / n, ty / n
    s = cutter.contact1(px, py, -ty, tx, piece)
    if s is None or not math.isfinite(s):
        return None
    G = gear.pose1(s)
    if G is None:
        return None
    gx, gy, tau = G
    cx, cy, ca = cutter.pose1(s)
    theta = tau - ca
    c, sn = math.cos(theta), math.sin(theta)
    vx, vy = px - cx, py - cy
    return np.array([[gx + (c * vx - sn * vy), gy + (sn * vx + c * vy)]]), np.array([s])
