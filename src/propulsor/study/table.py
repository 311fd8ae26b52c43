"""The study's table: a row per variant as it finishes, in two files with the same rows and values —
results.csv (appended a row at a time and flushed) and results.parquet (typed columns, rewritten
through a temporary file and one rename after each finished variant, so a reader sees the old table
or the new one).  An interrupted study keeps what finished; --resume reads results.csv back.

Column types (the same in both): variant int; key, status, reason, failed_checks, worker text;
all_checks_passed bool; seconds float; every other column (the varied parameters and the values asked
for) from its values — bool, int, float where ints and floats mix, else text.  An empty cell is null.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

from ..atomic_file import replace_atomically
from ..errors import InputError
from .results import cell, columns
from .spec import Study

RESULTS = "results.csv"
PARQUET = "results.parquet"
#: columns whose type does not depend on the values
FIXED = {"variant": "int", "key": "text", "status": "text", "reason": "text", "failed_checks": "text",
         "worker": "text", "all_checks_passed": "bool", "seconds": "float"}


def parse_cell(text: str):
    """A CSV cell back as a value (the column's type is applied after: :func:`typed`)."""
    if text == "":
        return None
    if text in ("true", "false"):
        return text == "true"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def kinds(cols: list[str], rows: list[dict]) -> dict[str, str]:
    """Each column's type: int, float, bool or text."""
    out = {}
    for c in cols:
        if c in FIXED:
            out[c] = FIXED[c]
            continue
        vs = [r.get(c) for r in rows if r.get(c) is not None]
        if all(isinstance(v, bool) for v in vs) and vs:
            out[c] = "bool"
        elif all(isinstance(v, int) and not isinstance(v, bool) for v in vs) and vs:
            out[c] = "int"
        elif all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vs):
            out[c] = "float"  # an empty column too
        else:
            out[c] = "text"
    return out


def typed(v, kind: str):
    """`v` as a value of its column's type (None, and empty text, as null)."""
    if v is None or (kind == "text" and v == ""):
        return None
    if kind == "float":
        return float(v)
    if kind == "text":
        return cell(v)
    return v


def _coerced(cols, rows):
    k = kinds(cols, rows)
    return [{c: typed(r.get(c), k[c]) for c in cols} for r in rows], k


def write_parquet(path: Path, cols: list[str], rows: list[dict]) -> Path:
    """results.parquet of `rows`, through a temporary file in the same folder and one rename."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    data, k = _coerced(cols, rows)
    types = {"int": pa.int64(), "float": pa.float64(), "bool": pa.bool_(), "text": pa.string()}
    schema = pa.schema([pa.field(c, types[k[c]]) for c in cols])
    table = pa.table({c: pa.array([r[c] for r in data], type=types[k[c]]) for c in cols}, schema=schema)
    return replace_atomically(path, lambda tmp: pq.write_table(table, tmp))


def read_parquet(path: Path) -> list[dict]:
    import pyarrow.parquet as pq

    return pq.read_table(path).to_pylist()


def read_csv(path: Path, cols: list[str]) -> list[dict]:
    """The rows of results.csv, typed (:func:`kinds`); a row cut short by an interruption is left out.
    InputError when its columns are not `cols`."""
    with open(path, newline="", encoding="utf-8") as f:
        text = f.read()
    if not text.endswith("\n"):  # the last line was cut short
        text = text[:text.rfind("\n") + 1]
    reader = csv.reader(io.StringIO(text, newline=""))
    header = next(reader, None)
    if header != cols:
        raise InputError("--resume", str(path), "the table there has other columns (another study or other "
                         "objectives): choose another --out or run without --resume")
    rows = [{c: (v if FIXED.get(c) == "text" else parse_cell(v)) for c, v in zip(cols, rec)}
            for rec in reader if len(rec) == len(cols)]
    return _coerced(cols, rows)[0]


class Table:
    """results.csv and results.parquet of a study in `folder`.  With `resume`, the rows of results.csv
    whose key is in `keys` (this study's variants at this project version) are kept and both files
    written anew with them (a stale row, or a line cut short, is gone); else the table starts empty."""

    def __init__(self, folder: Path, study: Study, resume: bool, keys=None):
        self.path = folder / RESULTS
        self.parquet = folder / PARQUET
        self.cols = columns(study)
        self.rows: list[dict] = []
        if resume and self.path.is_file():
            wanted = None if keys is None else set(keys)
            self.rows = [r for r in read_csv(self.path, self.cols) if wanted is None or r["key"] in wanted]
        def header_and_rows(tmp: str) -> None:
            with open(tmp, "w", newline="", encoding="utf-8") as f:
                w = csv.writer(f)
                w.writerow(self.cols)
                for r in self.rows:
                    w.writerow([cell(r.get(c)) for c in self.cols])

        replace_atomically(self.path, header_and_rows)
        self._f = open(self.path, "a", newline="", encoding="utf-8")
        self._w = csv.writer(self._f)
        write_parquet(self.parquet, self.cols, self.rows)

    def done_keys(self) -> set[str]:
        return {str(r["key"]) for r in self.rows}

    def add(self, row: dict) -> None:
        self.rows.append(row)
        self._w.writerow([cell(row.get(c)) for c in self.cols])
        self._f.flush()
        write_parquet(self.parquet, self.cols, self.rows)

    def close(self) -> None:
        self._f.close()
