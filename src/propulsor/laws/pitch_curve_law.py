"""A drive law from the driver's pitch curve (a shape-driven design): ``angle_deg,radius_mm`` rows.

The driver's pitch curve r(a) in polar form about its axis (a counter-clockwise on the driver body, the
row of angle 0 in contact at the start: it points at the driven wheel) through the rows by a periodic
quintic spline; the driven wheel is its conjugate with k lobes (k driver turns per driven turn).  With
the driver angle theta = -a (the wheels turn in opposite senses, ``gears.pitch_frame``): closure
integral_0^2pi r / (L0 - r) dtheta = 2 pi / k fixes the centre distance L0 of the curve as given, and

    phi(theta) = integral_0^theta r / (L0 - r) dtheta,   U = d theta / d phi = (L0 - r) / r.

The law (``laws.law.Law``) is the spline of theta(phi) through dense samples of that integral
(``table_law.TableLaw``); the pair is then scaled so that its pitch perimeter holds the teeth
(``scale`` = L / L0 is reported).  Rows must have strictly increasing angles within one turn and
radii > 0 (a curve through the axis is refused, naming the row).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import InputError
from .table_law import TableLaw, read_table_text, row_numbers, table_rows

__all__ = ["PitchCurveLaw", "parse_pitch_curve", "read_pitch_curve"]

COLUMNS = ("angle_deg", "radius_mm")
MIN_ROWS = 8
MAX_ROWS = 100_000
#: largest radius of a pitch curve row (mm): a 10 m wheel
RADIUS_MAX_MM = 1e4
#: samples of phi(theta) per driver turn the law's spline goes through
SAMPLES = 2048
_GX, _GW = np.polynomial.legendre.leggauss(12)


def _bad(key, row, value, limit, column=""):
    return InputError(f"{key} row {row}{(' ' + column) if column else ''}", value, limit)


def parse_pitch_curve(text: str, key: str = "pitch_curve_file"):
    """(angle_deg, radius_mm) of a CSV text with the header ``angle_deg,radius_mm``."""
    a, r = [], []
    for i, row in enumerate(table_rows(text, key, COLUMNS, MAX_ROWS), start=1):
        x, y = row_numbers(key, i, row, COLUMNS)
        if not y <= RADIUS_MAX_MM:
            raise _bad(key, i, y, f"a radius of at most {RADIUS_MAX_MM:g} mm", "radius_mm")
        a.append(x)
        r.append(y)
    return tuple(a), tuple(r)


def read_pitch_curve(path: Path, key: str = "pitch_curve_file"):
    """``parse_pitch_curve`` of a file (InputError naming ``key`` if it cannot be read)."""
    return parse_pitch_curve(read_table_text(path, key, "a pitch curve table"), key)


def _curve(angle_deg, radius_mm, key):
    """Periodic quintic spline r(a) (a in rad, period 2 pi) through the rows, checked; with the rows' start angle
    (rad) and their count as given (a closing row added here is not counted)."""
    from scipy.interpolate import make_interp_spline

    a, r = np.asarray(angle_deg, float), np.asarray(radius_mm, float)
    if len(a) < MIN_ROWS:
        raise InputError(key, f"{len(a)} rows", f"a pitch curve needs at least {MIN_ROWS} rows over one turn")
    for i in range(len(a)):
        if not r[i] > 0:
            raise _bad(key, i + 1, float(r[i]), "the pitch curve must not reach or cross the axis: radius > 0 mm",
                       "radius_mm")
        if i and not a[i] - a[i - 1] > 1e-9 * 360.0:
            raise _bad(key, i + 1, float(a[i]), f"must be strictly increasing (row {i}: {a[i - 1]:g}) by more than "
                       "3.6e-07 deg", "angle_deg")
    closed = abs(a[-1] - a[0] - 360.0) < 1e-9
    if a[-1] - a[0] > 360.0 or (closed and abs(r[-1] - r[0]) > 1e-9 * r[0]):
        raise _bad(key, len(a), float(a[-1]), f"the rows span one turn: angles up to {a[0] + 360:g} deg "
                   "(that row only to close the curve, with the first row's radius)", "angle_deg")
    if not closed:
        a, r = np.append(a, a[0] + 360.0), np.append(r, r[0])
    x = np.radians(a - a[0])
    x[-1] = 2 * math.pi
    return make_interp_spline(x, r, k=5, bc_type="periodic"), math.radians(a[0]), len(angle_deg)


class PitchCurveLaw(TableLaw):
    """The law of a driver pitch curve with a conjugate k-lobe driven wheel (module docstring)."""

    kind = "pitch_curve"

    def __init__(self, angle_deg, radius_mm, k: int, key: str = "pitch_curve_file"):
        from scipy.optimize import brentq

        spl, a0, rows = _curve(angle_deg, radius_mm, key)
        kf = float(k)
        if kf != round(kf) or not 1 <= kf <= 12:
            raise InputError("driver_turns", k, "driver turns per driven turn must be a whole number 1 .. 12")
        k = int(round(kf))
        # Gauss-Legendre on SAMPLES segments of the driver turn: theta = -a (a from the first row)
        edges = np.linspace(0.0, 2 * math.pi, SAMPLES + 1)
        h = np.diff(edges)[:, None]
        t = edges[:-1, None] + 0.5 * h * (_GX[None, :] + 1)
        r_t = spl(np.mod(-t, 2 * math.pi))
        r_max = max(float(np.max(spl(np.linspace(0.0, 2 * math.pi, 20 * SAMPLES)))), float(np.max(r_t)))

        def closure(L):
            return float(np.sum(0.5 * h * (r_t / (L - r_t)) @ _GW[:, None])) - 2 * math.pi / k

        lo = r_max * (1 + 1e-9)
        if not closure(lo) > 0:
            # analytically the closure grows without bound as L comes down to the largest radius; sampled, a peak
            # narrower than the law's samples leaves it below 2 pi / k: no centre distance the law can resolve
            raise InputError(key, f"{rows} rows", f"no centre distance closes a {k}-lobe driven wheel at the law's "
                             f"{SAMPLES} samples a turn: the curve's largest radius is a peak too narrow to follow "
                             "(a smoother curve, or more lobes)")
        L0 = brentq(closure, lo, r_max * 1e6, xtol=1e-13 * r_max, rtol=4e-15)
        seg = (0.5 * h * (r_t / (L0 - r_t)) @ _GW[:, None])[:, 0]
        phi = np.concatenate([[0.0], np.cumsum(seg)])
        phi *= (2 * math.pi / k) / phi[-1]  # closure to the last bit
        object.__setattr__(self, "L0", float(L0))
        object.__setattr__(self, "rows", rows)
        object.__setattr__(self, "first_angle", a0)
        object.__setattr__(self, "_r", spl)
        try:
            TableLaw.__init__(self, tuple(np.degrees(edges)), tuple(np.degrees(phi)), key)
        except InputError as exc:  # about the law's own samples, not a row of the file: no row named
            if not exc.parameter.startswith(f"{key} row"):
                raise
            why = ("the conjugate wheel's angles would not increase" if "strictly increasing" in exc.limit
                   else exc.limit.split(":")[0].replace("the spline through the rows", "the law of the conjugate wheel"))
            raise InputError(key, f"{rows} rows", f"{why} (between the curve's rows): a smoother curve, or rows "
                             "where its radius turns fastest") from None

    def driver_radius_given(self, theta):
        """The given curve's radius (mm, unscaled) at driver angle theta."""
        return self._r(np.mod(-np.asarray(theta, float), 2 * math.pi))
