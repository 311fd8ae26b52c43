"""CSV tables: a header row (units in the column names, e.g. r_H_mm), then rows.

Floats are written with Python's shortest round-trip repr (exact and
deterministic) unless a printf format such as "%.9g" is given; integers as
integers, strings as they are.  Line ends are '\\n' on every platform.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from ..write_root import prepare


def format_value(v, float_format: str | None = None) -> str:
    """One cell: bools as true/false, ints as ints, floats repr-exact or by format."""
    if v is None:
        return ""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if not math.isfinite(f):
            return repr(f)
        if f == 0.0:
            f = 0.0  # no '-0.0'
        return (float_format % f) if float_format else repr(f)
    return str(v)


def write_csv(path: str | Path, columns, rows=None, float_format: str | None = None) -> Path:
    """Write a table.

    Either `columns` is a dict {name: sequence} (all the same length) and rows is
    None, or `columns` is a list of names and `rows` an iterable of sequences.
    """
    path = Path(path)
    prepare(path)
    if isinstance(columns, dict):
        if rows is not None:
            raise ValueError("give rows only with a list of column names")
        names = list(columns)
        cols = [list(np.asarray(c).tolist()) if isinstance(c, np.ndarray) else list(c) for c in columns.values()]
        lengths = {len(c) for c in cols}
        if len(lengths) > 1:
            raise ValueError(f"columns of different lengths: { {n: len(c) for n, c in zip(names, cols)} }")
        rows = list(zip(*cols))
    else:
        names = list(columns)
        rows = [list(r) for r in rows]
        for r in rows:
            if len(r) != len(names):
                raise ValueError(f"row {r!r} has {len(r)} cells, header has {len(names)}")
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(names)
        for r in rows:
            w.writerow([format_value(v, float_format) for v in r])
    return path


def read_csv(path: str | Path) -> tuple[list[str], list[list[str]]]:
    """(header, rows as strings) of a CSV written by write_csv."""
    with open(path, newline="", encoding="utf-8") as fh:
        data = list(csv.reader(fh))
    return data[0], data[1:]
