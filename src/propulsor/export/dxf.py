"""DXF for laser / waterjet cutting: closed outlines on layer CUT, reference
geometry on layer REF, millimetres ($INSUNITS = 4).

Each loop of a `Profile` becomes one closed LWPOLYLINE: lines are straight
segments, circular arcs exact bulges (bulge = tan(sweep / 4)), B-splines
polylines whose chord error is below policy.CHORD_TOL_MM (what every CAM reads;
SPLINE entities are not accepted everywhere).  Files are deterministic: ezdxf's
creation / update dates and GUIDs are written as fixed values.
"""

from __future__ import annotations

import math
from itertools import islice
from pathlib import Path

import ezdxf
import numpy as np
from ezdxf import path as dxfpath

from ..geometry.profile import Arc, Line, Loop, Profile, Spline
from ..policy import CHORD_TOL_MM, DXF_POINTS_MAX, POINT_TOL_MM
from ..write_root import prepare

CUT = "CUT"
REF = "REF"
DXF_VERSION = "R2010"


def loop_vertices(loop: Loop, chord_tol: float = CHORD_TOL_MM) -> list[tuple[float, float, float]]:
    """(x, y, bulge) of a closed LWPOLYLINE for one loop."""
    if not loop.is_closed(1e-6):
        raise ValueError(f"loop is not closed: largest gap {float(loop.gaps().max()):.3g} mm")
    out: list[tuple[float, float, float]] = []
    for seg in loop.segments:
        if isinstance(seg, Line):
            out.append((float(seg.p0[0]), float(seg.p0[1]), 0.0))
        elif isinstance(seg, Arc):
            out.append((*map(float, seg.start), math.tan((seg.a1 - seg.a0) / 4.0)))
        elif isinstance(seg, Spline):
            for p in seg.sample(chord_tol)[:-1]:
                out.append((float(p[0]), float(p[1]), 0.0))
        else:
            raise TypeError(f"unknown segment type {type(seg).__name__}")
    # drop zero-length steps (a segment ending where the next begins is implicit)
    clean: list[tuple[float, float, float]] = []
    for v in out:
        if clean and math.hypot(v[0] - clean[-1][0], v[1] - clean[-1][1]) <= POINT_TOL_MM:
            clean[-1] = (clean[-1][0], clean[-1][1], clean[-1][2] or v[2])
            continue
        clean.append(v)
    if len(clean) > 1 and math.hypot(clean[0][0] - clean[-1][0], clean[0][1] - clean[-1][1]) <= POINT_TOL_MM:
        clean.pop()
    return clean


def _new_doc():
    doc = ezdxf.new(DXF_VERSION, setup=False, units=ezdxf.units.MM)
    doc.header["$INSUNITS"] = 4
    doc.header["$MEASUREMENT"] = 1
    doc.header["$LUNITS"] = 2
    doc.layers.add(CUT, color=7)
    doc.layers.add(REF, color=1)
    # ezdxf adds the CLASS entries of the entity types in use in the order of a set of strings,
    # which follows PYTHONHASHSEED: sort them so that the same drawing gives the same bytes
    classes = doc.classes
    add_required = classes.add_required_classes

    def add_required_sorted(dxfversion):
        add_required(dxfversion)
        classes.classes = type(classes.classes)(sorted(classes.classes.items()))

    classes.add_required_classes = add_required_sorted
    return doc


def _add_lwpolyline(msp, xyb, closed: bool, dxfattribs: dict):
    """An LWPOLYLINE of (x, y, bulge) vertices, stored in one step: ezdxf's ``add_lwpolyline`` appends
    point by point, each append copying the whole array (a 50 000-vertex loop took 11.6 s)."""
    e = msp.add_lwpolyline([], format="xyb", close=closed, dxfattribs=dxfattribs)
    v = np.zeros((len(xyb), 5))  # x, y, start width, end width, bulge (ezdxf's vertex layout)
    if len(xyb):
        a = np.asarray(xyb, float)
        v[:, 0], v[:, 1], v[:, 4] = a[:, 0], a[:, 1], a[:, 2]
    e.lwpoints.set(v)
    return e


def _add_ref(msp, kind: str, data, chord_tol: float):
    at = {"layer": REF}
    if kind == "circle":
        msp.add_circle(tuple(map(float, data.get("center", (0.0, 0.0)))), float(data["radius"]), dxfattribs=at)
    elif kind == "arc":
        a0, a1 = math.degrees(float(data["a0"])), math.degrees(float(data["a1"]))
        if a1 < a0:
            a0, a1 = a1, a0
        msp.add_arc(tuple(map(float, data.get("center", (0.0, 0.0)))), float(data["radius"]), a0, a1, dxfattribs=at)
    elif kind == "line":
        msp.add_line(tuple(map(float, data["p0"])), tuple(map(float, data["p1"])), dxfattribs=at)
    elif kind == "polyline":
        pts = np.asarray(data["points"], float)
        _add_lwpolyline(msp, [(float(x), float(y), 0.0) for x, y in pts], bool(data.get("closed", False)), at)
    elif kind == "loop":
        _add_lwpolyline(msp, loop_vertices(data, chord_tol), True, at)
    elif kind == "point":
        msp.add_point(tuple(map(float, data["p"])), dxfattribs=at)
    else:
        raise ValueError(f"unknown reference curve kind {kind!r} (circle, arc, line, polyline, loop, point)")


def write_dxf(
    path: str | Path,
    cut_profiles: list[Profile],
    ref_curves=(),
    placements=None,
    chord_tol: float = CHORD_TOL_MM,
) -> Path:
    """Write profiles (layer CUT) and reference curves (layer REF) to a DXF.

    ref_curves: (kind, data) with kind 'circle' {center, radius}, 'arc'
    {center, radius, a0, a1 (rad)}, 'line' {p0, p1}, 'polyline' {points,
    closed}, 'loop' (a Loop), 'point' {p}.  placements: one (dx, dy) or
    (dx, dy, angle_rad) per profile (profiles are rotated, then shifted);
    reference curves are written where they are.
    """
    path = Path(path)
    prepare(path)
    if placements is not None and len(placements) != len(cut_profiles):
        raise ValueError(f"placements: {len(placements)} given for {len(cut_profiles)} profiles")
    old = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True  # fixed dates / GUIDs / ezdxf stamps
    try:
        doc = _new_doc()
        _fill(doc.modelspace(), cut_profiles, ref_curves, placements, chord_tol)
        doc.saveas(path)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = old
    return path


def _fill(msp, cut_profiles, ref_curves, placements, chord_tol):
    for k, prof in enumerate(cut_profiles):
        if placements is not None:
            pl = tuple(placements[k])
            angle = float(pl[2]) if len(pl) > 2 else 0.0
            prof = prof.transformed(angle, (float(pl[0]), float(pl[1])))
        for loop in prof.loops:
            _add_lwpolyline(msp, loop_vertices(loop, chord_tol), True, {"layer": CUT})
    for kind, data in ref_curves:
        _add_ref(msp, kind, data, chord_tol)


_CLOSED_KINDS = ("LWPOLYLINE", "POLYLINE", "CIRCLE", "SPLINE", "ELLIPSE")


def _lwpolyline_points(e, chord_tol: float) -> np.ndarray:
    """Exact expansion of an LWPOLYLINE: bulge arcs sampled on the true circle."""
    v = [(float(x), float(y), float(b)) for x, y, b in e.get_points("xyb")]
    n = len(v)
    out = []
    last = n if e.closed else n - 1
    for i in range(last):
        x0, y0, b = v[i]
        x1, y1, _ = v[(i + 1) % n]
        if abs(b) < 1e-15:
            out.append((x0, y0))
            continue
        cx, cy = x1 - x0, y1 - y0
        L = math.hypot(cx, cy)
        if L == 0.0:
            continue
        d = 0.5 * L * (1.0 - b * b) / (2.0 * b)  # signed offset of the centre, left of the chord
        mx, my = 0.5 * (x0 + x1) - cy / L * d, 0.5 * (y0 + y1) + cx / L * d
        r = math.hypot(x0 - mx, y0 - my)
        a0 = math.atan2(y0 - my, x0 - mx)
        arc = Arc((mx, my), r, a0, a0 + 4.0 * math.atan(b))
        out.extend(map(tuple, arc.sample(chord_tol)[:-1]))
    if not e.closed and n:
        out.append(v[-1][:2])
    return np.array(out, float).reshape(-1, 2)


def _entity_points(e, chord_tol: float) -> np.ndarray:
    if e.dxftype() == "LWPOLYLINE":
        return _lwpolyline_points(e, chord_tol)
    p = dxfpath.make_path(e)
    pts = np.array([(v.x, v.y) for v in islice(p.flattening(chord_tol, segments=4), DXF_POINTS_MAX + 1)], float)
    if len(pts) > DXF_POINTS_MAX:
        raise ValueError(f"{e.dxftype()} flattens to more than {DXF_POINTS_MAX} points")
    return pts


def _is_closed(e) -> bool:
    t = e.dxftype()
    if t == "CIRCLE":
        return True
    if t == "LWPOLYLINE":
        return bool(e.closed)
    if t == "POLYLINE":
        return bool(e.is_closed)
    if t == "SPLINE":
        return bool(e.closed)
    if t == "ELLIPSE":
        return abs((e.dxf.end_param - e.dxf.start_param) - 2 * math.pi) < 1e-12
    return False


def read_dxf(path: str | Path, chord_tol: float = CHORD_TOL_MM) -> dict:
    """Summary of a DXF: units, and per layer the closed loops (point arrays,
    last point not repeated) and the entities that are not closed loops."""
    return dxf_summary(ezdxf.readfile(str(path)), chord_tol)


def dxf_summary(doc, chord_tol: float = CHORD_TOL_MM) -> dict:
    """:func:`read_dxf` of a document already read (ezdxf)."""
    layers: dict[str, dict] = {}
    for e in doc.modelspace():
        lay = layers.setdefault(e.dxf.layer, {"loops": [], "open": []})
        t = e.dxftype()
        if t in _CLOSED_KINDS:
            pts = _entity_points(e, chord_tol)
            closed_flag = _is_closed(e)
            if len(pts) > 1 and np.linalg.norm(pts[0] - pts[-1]) <= POINT_TOL_MM:
                pts = pts[:-1]
                closed_flag = True
            (lay["loops"] if closed_flag else lay["open"]).append(pts if closed_flag else (t, pts))
        else:
            lay["open"].append((t, None))
    return {"insunits": int(doc.header.get("$INSUNITS", 0)), "layers": layers, "version": doc.dxfversion}


def read_dxf_loops(path: str | Path, layer: str = CUT, chord_tol: float = CHORD_TOL_MM) -> list[np.ndarray]:
    """The closed loops on `layer` as (n, 2) point arrays (arcs flattened to chord_tol)."""
    return read_dxf(path, chord_tol)["layers"].get(layer, {"loops": []})["loops"]


def polygon_area(pts: np.ndarray) -> float:
    """Signed shoelace area of a closed polyline (CCW > 0)."""
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
