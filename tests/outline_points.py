"""Test helper: points along closed outlines, for comparing two outlines point by point."""

from __future__ import annotations

import numpy as np


def dense(loops, h):
    """Points along closed polylines, at most h apart."""
    out = []
    for q in loops:
        q = np.vstack([q, q[:1]])
        for p0, p1 in zip(q[:-1], q[1:]):
            n = max(1, int(np.hypot(*(p1 - p0)) / h) + 1)
            out.append(p0 + np.outer(np.arange(n) / n, p1 - p0))
    return np.vstack(out)
