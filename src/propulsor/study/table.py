"""The study's table: a row per variant as it finishes, in two files with the same rows and values —
results.csv (appended a row at a time and flushed) and results.parquet (typed columns, rewritten
through a temporary file and one rename at the start, at the end, on an interruption and now and then
in between, so a reader sees the old table or the new one).  An interrupted study keeps what finished;
--resume reads results.csv back as a stream.

Column types (the same in both): variant int; key, status, reason, failed_checks, worker text;
all_checks_passed bool; seconds float; every other column (the varied parameters and the values asked
for) from its values — bool, int, float where ints and floats mix, else text.  An empty cell is null.
"""

from __future__ import annotations

import csv
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
    if text in ("nan", "inf", "-inf"):  # a float the table wrote (results.cell: repr)
        return float(text)
    from ..numbers import parse

    try:
        return parse(text, "cell")  # plain ASCII digits only: "١٨٠" or "1_8_0" stay text
    except InputError:
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


#: largest results.csv read back by --resume (100 000 variants of a few kB each fit well below it)
RESULTS_MAX_BYTES = 1 << 30
#: largest field of results.csv read back (a reason or a list of failed checks is far shorter)
FIELD_MAX_CHARS = 1 << 16


def _resume_error(path: Path, why: str) -> InputError:
    return InputError("--resume", str(path), f"{why}: not a table this study wrote; choose another --out or run "
                      "without --resume")


def read_csv(path: Path, cols: list[str], keys=None) -> list[dict]:
    """The rows of results.csv, typed (:func:`kinds`), read as a stream (a line at a time: memory grows with
    the rows kept, never with the file); a row cut short by an interruption is left out.  With `keys` (this
    study's variant keys, in the order of its variants) only their rows are kept, the first of each key,
    numbered by the key's place.  InputError when the file is not a regular file of at most
    :data:`RESULTS_MAX_BYTES`, not UTF-8, has a field longer than :data:`FIELD_MAX_CHARS` or columns other
    than `cols`."""
    import os

    from ..regular_file import NotRegular, open_regular

    try:
        fd, st = open_regular(path)
    except NotRegular as exc:
        raise _resume_error(path, str(exc)) from None
    if st.st_size > RESULTS_MAX_BYTES:
        os.close(fd)
        raise _resume_error(path, f"is {st.st_size} bytes, more than the {RESULTS_MAX_BYTES} read back")
    place = None if keys is None else {str(k): i for i, k in enumerate(keys, 1)}
    rows: dict[str, dict] = {}
    with open(fd, newline="", encoding="utf-8", errors="strict") as f:
        cut = False
        if st.st_size:
            f.buffer.seek(st.st_size - 1)
            cut = f.buffer.read(1) != b"\n"  # the last line was cut short: its record is left out
            f.buffer.seek(0)
        old_limit = csv.field_size_limit(FIELD_MAX_CHARS)
        try:
            reader = csv.reader(f)
            header = next(reader, None)
            if header != cols:
                raise InputError("--resume", str(path), "the table there has other columns (another study or other "
                                 "objectives): choose another --out or run without --resume")
            pending = None
            ki = cols.index("key")
            for rec in reader:
                if pending is not None:
                    _keep(pending, cols, ki, place, rows)
                pending = rec
            if pending is not None and not cut:
                _keep(pending, cols, ki, place, rows)
        except UnicodeDecodeError as exc:
            raise _resume_error(path, f"is not UTF-8 ({exc.reason} at byte {exc.start} of a block)") from None
        except csv.Error as exc:
            raise _resume_error(path, f"line {reader.line_num}: {exc}") from None
        finally:
            csv.field_size_limit(old_limit)
    return _coerced(cols, list(rows.values()))[0]


def _keep(rec: list[str], cols: list[str], ki: int, place, rows: dict) -> None:
    """Add one record of results.csv to `rows` (by key, column ``ki``): only whole rows, only this study's keys, the
    first of each key."""
    if len(rec) != len(cols):
        return
    key = rec[ki]  # a text column: the row's key as written, before any cell is parsed
    if key in rows or (place is not None and key not in place):
        return  # another study's row, or a repeated one: left unparsed
    row = {c: (v if FIXED.get(c) == "text" else parse_cell(v)) for c, v in zip(cols, rec)}
    if place is not None:
        row["variant"] = place[key]
    elif not (isinstance(row["variant"], int) and not isinstance(row["variant"], bool) and row["variant"] >= 1):
        return
    rows[key] = row


class Table:
    """results.csv and results.parquet of a study in `folder`.  With `resume`, the rows of results.csv
    whose key is in `keys` (this study's variants at this project version) are kept and both files
    written anew with them (a stale row, a repeated one, or a line cut short, is gone); else the table
    starts empty.  results.csv gets each row as it comes; results.parquet is written at the start, at the
    end and on an interruption (:meth:`close`), and in between at most as often as keeps its writing under
    a twentieth of the time (:data:`PARQUET_SHARE`): never once per row of a long table."""

    #: the share of the study's time the rewrites of results.parquet may take between its start and its end
    PARQUET_SHARE = 0.05
    #: seconds between two rewrites of results.parquet at least
    PARQUET_EVERY_S = 10.0

    def __init__(self, folder: Path, study: Study, resume: bool, keys=None):
        import time

        self.path = folder / RESULTS
        self.parquet = folder / PARQUET
        self.cols = columns(study)
        self.rows: list[dict] = []
        if resume and self.path.is_file():
            self.rows = read_csv(self.path, self.cols, keys)
        self._rewrite_csv()
        self._f = open(self.path, "a", newline="", encoding="utf-8")
        self._w = csv.writer(self._f)
        self._clock = time.monotonic
        self._write_parquet()
        self._written = len(self.rows)

    def _write_parquet(self) -> None:
        t0 = self._clock()
        write_parquet(self.parquet, self.cols, self.rows)
        self._last = self._clock()
        self._cost = self._last - t0
        self._written = len(self.rows)

    def done_keys(self) -> set[str]:
        return {str(r["key"]) for r in self.rows}

    def add(self, row: dict) -> None:
        self.rows.append(row)
        self._w.writerow([cell(row.get(c)) for c in self.cols])
        self._f.flush()
        if self._clock() - self._last >= max(self.PARQUET_EVERY_S, self._cost / self.PARQUET_SHARE):
            self._write_parquet()

    def close(self) -> None:
        """Close results.csv and bring results.parquet up to date (also on an interruption)."""
        self._f.close()
        if self._written != len(self.rows):
            self._write_parquet()

    def in_order(self) -> None:
        """The whole study done: both files rewritten with the rows in the order of their variants (they came in
        the order the variants finished: 2, 4, 1, 3; the trial sorted them to compare two runs).  Once, at the end."""
        self.rows.sort(key=lambda r: int(r["variant"]))
        self._rewrite_csv()
        self._write_parquet()

    def _rewrite_csv(self) -> None:
        """results.csv anew with the header and the rows held (through a temporary file and one rename)."""

        def header_and_rows(tmp: str) -> None:
            with open(tmp, "w", newline="", encoding="utf-8") as f:
                w = csv.writer(f)
                w.writerow(self.cols)
                for r in self.rows:
                    w.writerow([cell(r.get(c)) for c in self.cols])

        replace_atomically(self.path, header_and_rows)
