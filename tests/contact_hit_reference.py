"""The reference of the contact search's first hit (checks/motion/contact_events.py, ``_first_hit_pruned``): the first
least of every hit of the whole window (:func:`_pair_hits`, no vertex left out), side 1 before side 2 on a tie."""

from __future__ import annotations

import math

from propulsor.checks.motion import contact_events as ce


def first_hit(phi_a, theta, sign, w, *kernel_args):
    i1, d1, e1, t1, i2, d2, e2, t2 = ce._pair_hits(float(phi_a), float(theta), float(sign), float(w), *kernel_args)
    k1, m1 = ce._least(d1)
    k2, m2 = ce._least(d2)
    if not (m1 < math.inf or m2 < math.inf):
        return math.inf, 0, -1, -1, 0.0
    if m1 <= m2:
        return m1, 1, i1[k1], e1[k1], t1[k1]
    return m2, 2, i2[k2], e2[k2], t2[k2]
