"""A drive law given as a table of angles (``laws.law.Law``): ``driver_deg,driven_deg`` over one period.

The first row is the origin of both angles (theta = phi = 0); the last closes the period: the driven
span P must divide 360 deg (``periods`` = 360 / P lobes) and over those periods the driver makes a
whole number n of turns, n dividing the periods (the driver curve closes).  Between the rows a
periodic quintic spline of theta(phi) - n phi: U = d theta / d phi is C3, and repeats with period P.
Both columns must be strictly increasing (U > 0); the spline's U is checked > 0 too.
Refusals name the key (``law_file``), the first bad row (1 = the first data row) and the limit.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from .walking import invert_theta

__all__ = ["TableLaw", "read_law_table", "parse_law_table", "table_rows", "row_numbers"]

#: columns of a law table, in this order
COLUMNS = ("driver_deg", "driven_deg")
#: least data rows (a quintic spline needs 6 points)
MIN_ROWS = 7
#: most data rows read
MAX_ROWS = 100_000
#: largest file read (bytes)
MAX_BYTES = 8 << 20
#: least step between two rows, as a share of the table's span (rows 1e-300 apart are one row)
MIN_GAP = 1e-9
#: tolerance on whole periods and whole driver turns (deg)
CLOSE_TOL_DEG = 1e-6
#: pieces of one period for the quadratures (Gauss per piece: the spline's knots are only C4)
PIECES = 16
#: samples per period when checking the spline's ratio stays > 0
_CHECK_SAMPLES = 20000


def _bad(key: str, row: int, value, limit: str, column: str = "") -> InputError:
    """InputError naming the key, the data row (1 = the first after the header) and its column."""
    return InputError(f"{key} row {row}{(' ' + column) if column else ''}", value, limit)


#: longest field of a table's row (a number is at most numbers.MAX_CHARS; the rest is a refusal's)
FIELD_MAX_CHARS = 256
#: largest angle of a table row (deg): a period's rows lie within a few turns
ANGLE_MAX_DEG = 1e5


def table_rows(text: str, key: str, columns: tuple[str, str], max_rows: int) -> list[list[str]]:
    """The data rows (lists of fields) of a CSV table text whose first non-empty row is `columns`; blank
    rows left out.  InputError naming `key` for another header, a field over FIELD_MAX_CHARS (a row or the
    header of a file that is no table echoes nothing of it), more than `max_rows` rows, or CSV that does
    not parse."""
    old = csv.field_size_limit(FIELD_MAX_CHARS)
    try:
        rows = []
        for r in csv.reader(io.StringIO(text)):
            if r and any(c.strip() for c in r):
                rows.append(r)
                if len(rows) > max_rows + 1:
                    raise InputError(key, f"more than {max_rows} rows", f"at most {max_rows} rows")
    except csv.Error as exc:
        raise InputError(key, f"row {len(rows) + 1}", f"is not a CSV table {','.join(columns)} ({exc})") from None
    finally:
        csv.field_size_limit(old)
    if not rows:
        raise InputError(key, "(empty)", f"a table needs the header {','.join(columns)} and its rows")
    if tuple(c.strip() for c in rows[0]) != columns:
        raise InputError(key, "(its first line)", f"the header must be {','.join(columns)}: not a table of this kind")
    return rows[1:]


def row_numbers(key: str, i: int, r: list[str], columns: tuple[str, str]) -> tuple[float, float]:
    """The two numbers of data row `i` (numbers.parse: plain ASCII digits, finite, not subnormal) within
    ±ANGLE_MAX_DEG for an angle; InputError naming the row otherwise."""
    from ..numbers import parse

    if len(r) != 2:
        raise _bad(key, i, ",".join(r)[:80], f"two columns: {','.join(columns)}")
    out = []
    for col, cell in zip(columns, r):
        try:
            v = float(parse(cell, key))
        except InputError as exc:
            raise _bad(key, i, cell.strip()[:40], exc.limit, col) from None
        if col.endswith("_deg") and abs(v) > ANGLE_MAX_DEG:
            raise _bad(key, i, v, f"an angle within ±{ANGLE_MAX_DEG:g} deg", col)
        out.append(v)
    return out[0], out[1]


def parse_law_table(text: str, key: str = "law_file") -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(driver_deg, driven_deg) of a CSV text with the header ``driver_deg,driven_deg``."""
    th, ph = [], []
    for i, r in enumerate(table_rows(text, key, COLUMNS, MAX_ROWS), start=1):
        a, b = row_numbers(key, i, r, COLUMNS)
        th.append(a)
        ph.append(b)
    return tuple(th), tuple(ph)


def read_table_text(path: Path, key: str, what: str) -> str:
    """The UTF-8 text of a CSV table a part file names under `key`: a regular file (never a FIFO or a
    device, never waited on) of at most MAX_BYTES; InputError naming `key` otherwise."""
    from ..regular_file import read_regular

    path = Path(path)
    try:
        raw = read_regular(path, MAX_BYTES)
    except OSError as exc:
        raise InputError(key, str(path), f"cannot be read: {exc.strerror or exc}") from None
    except ValueError as exc:
        raise InputError(key, str(path), f"{exc}; {what} is a CSV file of at most {MAX_BYTES} bytes") from None
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(key, str(path), "must be UTF-8 text") from None


def _whole_periods(span_ph: float) -> float | None:
    """N, the periods per driven turn, when the driven span divides 360 deg (to CLOSE_TOL_DEG); None otherwise."""
    N = 360.0 / span_ph
    return float(round(N)) if abs(N - round(N)) * span_ph < CLOSE_TOL_DEG else None


def _whole_turns(span_th: float, N: float) -> tuple[float, float]:
    """n, the driver turns per driven turn over N periods of the driver span, and how far from whole it is (deg)."""
    n = span_th * N / 360.0
    return n, abs(n - round(n)) * 360.0 / N


def _closing_row_hint(th, ph) -> str:
    """Where the table stops one even step short of a period, the row that would close it (the first row one
    period on): a table lists its closing row, the first row's driver and driven angles plus one period's."""
    span_ph, span_th = ph[-1] - ph[0] + (ph[-1] - ph[-2]), th[-1] - th[0] + (th[-1] - th[-2])
    N = _whole_periods(span_ph)
    if N is not None and _whole_turns(span_th, N)[1] < CLOSE_TOL_DEG:
        return f" (the rows seem to stop one step short: add the closing row {th[0] + span_th:g},{ph[0] + span_ph:g})"
    return ""


def read_law_table(path: Path, key: str = "law_file") -> tuple[tuple[float, ...], tuple[float, ...]]:
    """``parse_law_table`` of a file (InputError naming ``key`` if it cannot be read)."""
    return parse_law_table(read_table_text(path, key, "a law table"), key)


@dataclass(frozen=True)
class TableLaw:
    """theta(phi) through the rows (driver_deg, driven_deg) of one period (see the module docstring)."""

    driver_deg: tuple
    driven_deg: tuple
    key: str = "law_file"

    kind = "table"
    #: the array functions give each angle the value it gets alone (law.py: ``elementwise``)
    elementwise = True
    scalar_path = False
    corner_phis = ()
    period_start = 0.0

    def __post_init__(self):
        from scipy.interpolate import make_interp_spline

        th, ph, key = np.asarray(self.driver_deg, float), np.asarray(self.driven_deg, float), self.key
        if len(th) != len(ph) or len(th) < MIN_ROWS:
            raise InputError(key, f"{len(th)} rows", f"a law table needs at least {MIN_ROWS} rows over one period")
        for col, v in (("driver_deg", th), ("driven_deg", ph)):
            gap = MIN_GAP * max(float(v[-1] - v[0]), 0.0)  # rows closer than that: a ratio of rounding errors
            bad = np.flatnonzero(~(np.diff(v) > gap))
            if len(bad):
                i = int(bad[0]) + 1
                raise _bad(key, i + 1, float(v[i]), f"must be strictly increasing (row {i}: {v[i - 1]:g})"
                           + (f" by more than {gap:.3g} deg" if v[i] > v[i - 1] else "") + ": the ratio must stay > 0",
                           col)
        span_ph, span_th = ph[-1] - ph[0], th[-1] - th[0]
        N = _whole_periods(span_ph)
        if N is None:
            raise _bad(key, len(th), float(ph[-1]),
                       f"the last row closes the period: the driven span {span_ph:g} deg must divide 360 deg"
                       + _closing_row_hint(th, ph), "driven_deg")
        N = int(N)
        n, off = _whole_turns(span_th, N)
        if not (off < CLOSE_TOL_DEG and round(n) >= 1):
            raise _bad(key, len(th), float(th[-1]),
                       f"over {N} periods of {span_ph:g} deg the driver must make whole turns, not {n:.6g}",
                       "driver_deg")
        n = int(round(n))
        if N % n:
            raise _bad(key, len(th), float(th[-1]),
                       f"{n} driver turns per driven turn must divide the {N} periods (the driver curve closes)",
                       "driver_deg")
        x = np.radians(ph - ph[0])
        P = 2 * math.pi / N
        x[-1] = P
        slope = n / 1.0  # mean d theta / d phi = n turns per driven turn
        y = np.radians(th - th[0]) - slope * x
        y[-1] = y[0]
        spl = make_interp_spline(x, y, k=5, bc_type="periodic")
        object.__setattr__(self, "n", n)
        object.__setattr__(self, "periods", N)
        object.__setattr__(self, "period", P)
        # the smooth pieces the quadratures and samplings split at: rows, at most PIECES of them
        idx = np.unique(np.round(np.linspace(0, len(x) - 1, min(PIECES, len(x) - 1) + 1)).astype(int))
        object.__setattr__(self, "breakpoints", tuple(float(v) for v in x[idx]))
        object.__setattr__(self, "_slope", float(slope))
        object.__setattr__(self, "_s", (spl, spl.derivative(1), spl.derivative(2), spl.derivative(3)))
        xs = np.linspace(0.0, P, _CHECK_SAMPLES)
        U = self.U(xs)
        j = int(np.argmin(U))
        if not U[j] > 0:
            row = int(np.searchsorted(x, xs[j], side="right"))
            raise _bad(key, row, float(ph[row - 1]),
                       f"the spline through the rows has a ratio U = {U[j]:.4g} <= 0 near it: more rows or a "
                       "smoother table", "driven_deg")

    def _w(self, phi):
        phi = np.asarray(phi, dtype=float)
        return phi - self.period * np.floor(phi / self.period)

    def theta(self, phi):
        phi = np.asarray(phi, dtype=float)
        return self._slope * phi + self._s[0](self._w(phi))

    def U(self, phi):
        return self._slope + self._s[1](self._w(phi))

    def dU_dphi(self, phi):
        return self._s[2](self._w(phi))

    def d2U_dphi2(self, phi):
        return self._s[3](self._w(phi))

    def phi_of_theta(self, theta, tol: float = 1e-14):
        theta = np.asarray(theta, dtype=float)
        return invert_theta(self, theta, theta / self._slope, tol, 80)

    def U_derivs1(self, phi: float) -> tuple:
        p = np.array([float(phi)])
        return float(self.U(p)[0]), float(self.dU_dphi(p)[0]), float(self.d2U_dphi2(p)[0])

    def theta1(self, phi: float) -> float:
        return float(self.theta(np.array([float(phi)]))[0])
