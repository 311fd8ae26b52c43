"""The load per tooth's compiled steps give the floats of the numpy steps they replace.

* ``gears/tooth_load_kernels.py``: every vertex's fit windows and its points in the frames of its fits are those of
  ``tooth_load._problems`` (the same vertices, the same x and y to the last bit: numpy's ``q @ t`` is one fused
  multiply-add for two columns), on outlines with and without corners, at several half lengths.
* ``checks/motion/mesh_load.py``: ``phase_contacts`` (its window's hits gathered, their points, each tooth pair's
  first hit, compiled) lists the contacts of the numpy path it replaced (``_all_hits``, ``_nearest``,
  ``_first_of_each_pair``), field by field, bit for bit, on a toothed pair at hundreds of phases, with start values
  off by up to 20 margins (the searches again from 4 and 16 margins).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor import policy
from propulsor.checks.kernels import _toothed
from propulsor.checks.motion import Outline
from propulsor.checks.motion.contact_events import DRIVE, REVERSE, PairOutlines, _rot, resolve_contact
from propulsor.checks.motion import mesh_load
from propulsor.gears import tooth_load as tlm
from propulsor.gears.tooth_load_kernels import fit_windows, frame_coordinates


def _outlines():
    t = np.linspace(0.0, 2.0 * math.pi, 2400, endpoint=False)
    rr = 20.0 + 1.2 * np.sign(np.cos(12 * t)) * np.abs(np.cos(12 * t)) ** 0.3  # flat tips and roots with corners
    toothed = np.column_stack([rr * np.cos(t), rr * np.sin(t)])
    u = np.linspace(0.0, 2.0 * math.pi, 1500, endpoint=False)
    ellipse = np.column_stack([30.0 * np.cos(u), 12.0 * np.sin(u)])  # smooth, the point spacing varying
    return toothed, ellipse


@pytest.mark.parametrize("half", [0.6, 0.25, 0.11])
def test_the_fit_windows_and_frame_coordinates_are_those_of_problems(half):
    rng = np.random.default_rng(11)
    checked = 0
    for P in _outlines():
        o = tlm.DenseOutline(P)
        todo = np.unique(np.concatenate([rng.integers(0, len(o), 250), np.nonzero(o.corner)[0][:40]]))
        is_corner, Ks, first, last = fit_windows(o.seg_len, o.corner, todo, half)
        rows, frames, want = [], [], []
        for r, i in enumerate(todo.tolist()):
            corner, probs = tlm._problems(o, i, half)
            assert bool(is_corner[r]) == corner
            n = len(o)
            d_a = o.points[(i + 1) % n] - o.points[i]
            d_b = o.points[i] - o.points[(i - 1) % n]
            fr = ([d_a / np.linalg.norm(d_a), d_b / np.linalg.norm(d_b)] if corner else [o.tangent[i]] * 3)
            for f, pr in enumerate(probs):
                rows.append((r, f))
                frames.append(fr[f])
                want.append(pr)
        X, Y, off = frame_coordinates(o.points, todo, Ks, first, last, np.array(frames), np.array(rows, np.int64))
        short = 0
        for p, pr in enumerate(want):
            x, y = X[off[p]:off[p + 1]], Y[off[p]:off[p + 1]]
            if pr is None:  # fewer than five vertices: no fit
                assert len(x) < 5
                short += 1
                continue
            A, yw = pr
            assert np.array_equal(x.view(np.int64), A[:, 1].view(np.int64))
            assert np.array_equal(y.view(np.int64), yw.view(np.int64))
        checked += len(want) - short
        assert np.any(is_corner) == np.any(o.corner)
    assert checked > 50  # fits of five vertices or more, checked


def _reference(pair, phi, theta, te, window, direction, margin=policy.CONTACT_TRACK_MARGIN_RAD):
    """phase_contacts as it was written in numpy (before its gathering was compiled)."""
    sign = 1.0 if direction == DRIVE else -1.0
    for mg in (margin, 4.0 * margin, 16.0 * margin):
        start = phi + te + sign * mg
        d, side, v, e, t = mesh_load._all_hits(pair, start, theta, sign, mg + window)
        if len(d) and float(np.min(d)) > 0.2 * mg:
            break
    else:
        if not len(d):
            return math.nan, []
    dmin = float(np.min(d))
    drv, dvn = pair.drv, pair.dvn
    s2 = np.where(side == 2, e, 0)
    p_dvn = np.where((side == 1)[:, None], dvn.points[np.where(side == 1, v, 0)],
                     dvn.seg_a[s2] + t[:, None] * (dvn.seg_b[s2] - dvn.seg_a[s2]))
    e_drv = np.where(side == 1, e, 0)
    p_drv_edge = drv.seg_a[e_drv] + t[:, None] * (drv.seg_b[e_drv] - drv.seg_a[e_drv])
    p_drv = np.where((side == 2)[:, None], drv.points[np.where(side == 2, v, 0)], p_drv_edge)
    t_dvn = mesh_load._nearest(pair.driven_teeth, np.arctan2(p_dvn[:, 1], p_dvn[:, 0]))
    t_drv = mesh_load._nearest(pair.driver_teeth, np.arctan2(p_drv[:, 1], p_drv[:, 0]))
    res = []
    for k in mesh_load._first_of_each_pair(d, t_drv, t_dvn).tolist():
        phi_c = start - sign * float(d[k])
        R_dvn = _rot(-phi_c)
        x = R_dvn @ p_dvn[k]
        if side[k] == 1:
            s = drv.seg_b[e[k]] - drv.seg_a[e[k]]
            n = _rot(theta) @ (-np.array([-s[1], s[0]]) / math.hypot(s[0], s[1]))
        else:
            s = dvn.seg_b[e[k]] - dvn.seg_a[e[k]]
            n = R_dvn @ (np.array([-s[1], s[0]]) / math.hypot(s[0], s[1]))
        tau2 = float(x[0] * n[1] - x[1] * n[0])
        r1 = x - (pair.L, 0.0)
        tau1 = float(r1[0] * n[1] - r1[1] * n[0])
        l2, l1 = -sign * tau2, sign * tau1
        if l2 <= 0 or l1 <= 0:
            continue
        res.append((int(t_drv[k]), int(t_dvn[k]), float(d[k]) - dmin, p_drv[k], p_dvn[k], x, n, l1, l2,
                    "driver" if side[k] == 1 else "driven", int(v[k])))
    res.sort(key=lambda c: c[2])
    return (start - sign * dmin) - phi, res


def _same(a, b) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(np.asarray(a, float).view(np.int64), np.asarray(b, float).view(np.int64))
    if isinstance(a, float):
        return np.float64(a).view(np.int64) == np.float64(b).view(np.int64)
    return a == b


@pytest.mark.parametrize("direction", [DRIVE, REVERSE])
def test_phase_contacts_lists_the_contacts_of_the_numpy_steps(direction):
    z1, z2, m = 12, 18, 1.0
    drv, dvn = Outline([_toothed(z1, 0.5 * m * z1, 1.6 * m)]), Outline([_toothed(z2, 0.5 * m * z2, 1.6 * m)])
    pair = PairOutlines(drv, dvn, 0.5 * m * (z1 + z2), 2 * math.pi * np.arange(z1) / z1,
                        2 * math.pi * np.arange(z2) / z2)
    law = lambda phi: np.asarray(phi, float) * z2 / z1  # noqa: E731
    c = resolve_contact(pair, law, 0.0, 2 * math.pi / z2 * 3, direction, step_driver_rad=0.004)
    ok = np.isfinite(c.te)
    assert ok.sum() > 100
    rng = np.random.default_rng(7)
    mg = policy.CONTACT_TRACK_MARGIN_RAD
    listed = fallbacks = 0
    for phi, te in zip(c.phi[ok], c.te[ok]):
        off = float(rng.choice([0.0, 0.0, -0.9, -3.5, -12.0, 1.5])) * mg * (1.0 if direction == DRIVE else -1.0)
        for window in (0.02, 0.004):
            args = (pair, float(phi), float(law(np.array([phi]))[0]), float(te) + off, window, direction)
            te_ref, ref = _reference(*args)
            te_got, got = mesh_load.phase_contacts(*args)
            assert _same(te_ref, te_got) or (math.isnan(te_ref) and math.isnan(te_got))
            assert len(got) == len(ref)
            for g, r in zip(got, ref):
                fields = (g.driver_tooth, g.driven_tooth, g.gap, g.p_driver, g.p_driven, g.x, g.n, g.l1, g.l2,
                          g.edge_of, g.vertex)
                assert all(_same(a, b) for a, b in zip(fields, r)), (phi, fields, r)
            listed += len(got)
            fallbacks += off < -0.8 * mg or off > 0
    assert listed > 200 and fallbacks > 50

