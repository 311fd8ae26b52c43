"""The points of many curves of one kind at once, for the spline fits made in lock step
(:func:`..geometry.bspline.fit_curves`): one evaluation of a generated flank (``EnvelopeCurve``) for the teeth of
a wheel together, where each tooth differs only by its tooth centre on the pitch curve, and one of the tip lands
(``Equidistant``) of every height.

Every point is the one its own curve gives, bit for bit: the cutter's pieces, its closed-form contact, the arc-length
frame and the pitch curve compute each point from its own parameter and tooth alone, and so does a law that says it is
``elementwise`` (laws/law.py: every law of the package does; a law that does not say so has its curves evaluated
one by one).  A request of one parameter is left to its curve: its one-point path (``envelope_point1``,
``BodyPitchCurve._at1``) takes other operations than the arrays'.
"""

from __future__ import annotations

import numpy as np

from .envelope import EnvelopeCurve, PitchCurveCentrode, _rot, envelope_points
from .pitch_frame import Equidistant

__all__ = ["evaluate_curves"]


def _key(func, n: int):
    """What curves evaluated together share (None: evaluated on its own): the kind, the cutter's piece, the pitch
    curve and its frame; only where the law is ``elementwise`` (laws/law.py)."""
    if n < 2:
        return None
    if type(func) is EnvelopeCurve and type(func.gear) is PitchCurveCentrode and isinstance(func.gear.s_k, float):
        g = func.gear
        if getattr(g.curve.pc.law, "elementwise", False) is True:
            return ("envelope", id(func.piece), id(func.cutter), id(g.curve), id(g.frame), func.rotation)
    elif type(func) is Equidistant and getattr(func.curve.pc.law, "elementwise", False) is True:
        return ("equidistant", id(func.curve))
    return None


def evaluate_curves(requests) -> list:
    """``[func(u) for func, u in requests]``, the curves of one kind evaluated together (``_key``)."""
    out: list = [None] * len(requests)
    groups: dict = {}
    for i, (func, u) in enumerate(requests):
        k = _key(func, len(u))
        if k is None:
            out[i] = np.asarray(func(u), float)
        else:
            groups.setdefault(k, []).append(i)
    for k, idx in groups.items():
        if len(idx) == 1:
            func, u = requests[idx[0]]
            out[idx[0]] = np.asarray(func(u), float)
            continue
        us = [np.asarray(requests[i][1], float) for i in idx]
        lens = np.array([len(u) for u in us])
        U = np.concatenate(us)
        first = requests[idx[0]][0]
        if k[0] == "envelope":
            g = first.gear
            sk = np.repeat(np.array([requests[i][0].gear.s_k for i in idx], float), lens)
            X, _ = envelope_points(first.piece, U, first.cutter, PitchCurveCentrode(g.curve, g.frame, sk))
            if first.rotation:
                X = _rot(np.full(len(X), first.rotation), X)
        else:
            h = np.repeat(np.array([requests[i][0].h for i in idx], float), lens)
            X = first.curve.point(U) + h[:, None] * first.curve.normal(U)
        for i, part in zip(idx, np.split(X, np.cumsum(lens)[:-1])):
            out[i] = part
    return out
