"""The study's table (results.csv, a row per variant as it finishes; read back for --resume), the
ranking (Pareto layers) and the Pareto front's picture."""

from __future__ import annotations

import csv
import math
from pathlib import Path

from ..errors import InputError
from .spec import ALL_CHECKS, Study

RESULTS = "results.csv"
FRONT = "front.csv"
FRONT_PNG = "pareto_front.png"
TAIL = ("all_checks_passed", "status", "reason", "failed_checks", "seconds", "worker")


def columns(study: Study) -> list[str]:
    return ["variant", "key", *study.varied, *study.values, *TAIL]


def cell(v) -> str:
    """A value as the table writes it: floats to the last digit (repr), booleans as true / false."""
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    return str(v)


def parse_cell(text: str):
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


class Table:
    """results.csv, appended a row at a time (flushed: an interrupted study keeps what finished)."""

    def __init__(self, folder: Path, study: Study, resume: bool):
        self.path = folder / RESULTS
        self.cols = columns(study)
        self.rows: list[dict] = []
        if resume and self.path.is_file():
            with open(self.path, newline="", encoding="utf-8") as f:
                reader = csv.reader(f)
                header = next(reader, None)
                if header != self.cols:
                    raise InputError("--resume", str(self.path), "the table there has other columns (another study "
                                     "or other objectives): choose another --out or run without --resume")
                for rec in reader:
                    if len(rec) == len(self.cols):
                        self.rows.append({c: parse_cell(v) for c, v in zip(self.cols, rec)})
            self._f = open(self.path, "a", newline="", encoding="utf-8")
            self._w = csv.writer(self._f)
        else:
            self._f = open(self.path, "w", newline="", encoding="utf-8")
            self._w = csv.writer(self._f)
            self._w.writerow(self.cols)
            self._f.flush()

    def done_keys(self) -> set[str]:
        return {str(r["key"]) for r in self.rows}

    def add(self, row: dict) -> None:
        self.rows.append(row)
        self._w.writerow([cell(row.get(c)) for c in self.cols])
        self._f.flush()

    def close(self) -> None:
        self._f.close()


def ranked(study: Study, rows: list[dict]) -> list[tuple[int, dict]]:
    """The rows that meet every requirement, best first, each with its Pareto layer (1: the front —
    no other variant is at least as good in every objective and better in one; 2: the front once
    the first is removed …); within a layer by the first objective."""
    def vec(r):
        return tuple((r[n] if n in study.minimize else -r[n]) for n in study.objectives)

    ok = [r for r in rows if r.get("status") == "ok"
          and all(isinstance(r.get(n), (int, float)) and not isinstance(r.get(n), bool)
                  and math.isfinite(r[n]) for n in study.objectives)]
    out, layer, rest = [], 1, ok
    while rest:
        vs = [vec(r) for r in rest]
        front = [r for r, v in zip(rest, vs)
                 if not any(all(a <= b for a, b in zip(u, v)) and u != v for u in vs)]
        front.sort(key=lambda r: (vec(r), int(r["variant"])))
        out += [(layer, r) for r in front]
        ids = {id(r) for r in front}
        rest = [r for r in rest if id(r) not in ids]
        layer += 1
    return out


def write_front(folder: Path, study: Study, rank: list[tuple[int, dict]]) -> None:
    cols = ["rank", "pareto_layer", *columns(study)]
    with open(folder / FRONT, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for k, (layer, r) in enumerate(rank, 1):
            w.writerow([k, layer] + [cell(r.get(c)) for c in cols[2:]])


def plot_front(folder: Path, study: Study, rows: list[dict], rank: list[tuple[int, dict]]) -> Path | None:
    """pareto_front.png: every variant that met the requirements (grey), the front (red, joined), the
    variants refused by a requirement (x); the first two objectives on the axes (one: against the
    variant number)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    objs = study.objectives
    front = [r for layer, r in rank if layer == 1]
    others = [r for layer, r in rank if layer > 1]
    refused = [r for r in rows if r.get("status") == "rejected"
               and all(isinstance(r.get(n), (int, float)) for n in objs[:2])]

    def xy(rs):
        if len(objs) >= 2:
            return [r[objs[0]] for r in rs], [r[objs[1]] for r in rs]
        return [int(r["variant"]) for r in rs], [r[objs[0]] for r in rs]

    fig, ax = plt.subplots(figsize=(7, 5), dpi=100)
    if refused:
        ax.scatter(*xy(refused), marker="x", color="0.6", label="refused by a requirement")
    if others:
        ax.scatter(*xy(others), color="0.45", s=18, label="meets the requirements")
    if front:
        fx, fy = xy(sorted(front, key=lambda r: (xy([r])[0][0], xy([r])[1][0])))
        ax.plot(fx, fy, "-o", color="tab:red", ms=5, label="Pareto front")
        for layer_rank, (layer, r) in enumerate(rank, 1):
            if layer == 1:
                x, y = xy([r])
                ax.annotate(str(r["variant"]), (x[0], y[0]), fontsize=7, xytext=(3, 3), textcoords="offset points")
    if len(objs) >= 2:
        ax.set_xlabel(f"{objs[0]} ({'min' if objs[0] in study.minimize else 'max'})")
        ax.set_ylabel(f"{objs[1]} ({'min' if objs[1] in study.minimize else 'max'})")
    else:
        ax.set_xlabel("variant")
        ax.set_ylabel(f"{objs[0]} ({'min' if objs[0] in study.minimize else 'max'})")
    extra = f"; front over {', '.join(objs)}" if len(objs) > 2 else ""
    ax.set_title(f"{study.title}: {len(rank)} of {len(rows)} variants meet the requirements{extra}", fontsize=9)
    ax.grid(True, alpha=0.3)
    if front or others or refused:
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = folder / FRONT_PNG
    fig.savefig(path)
    plt.close(fig)
    return path


def requirement_failure(study: Study, row: dict) -> str:
    """The first requirement the row does not meet ('' when it meets all)."""
    for req in study.require:
        value = row.get("all_checks_passed") if req.name == ALL_CHECKS else row.get(req.name)
        if not req.holds(value):
            if req.name == ALL_CHECKS and value is None:
                return f"{ALL_CHECKS}: no check runs at depth {study.depth} for this part (depth proof runs them all)"
            if req.name == ALL_CHECKS:
                return f"{ALL_CHECKS}: failed {row.get('failed_checks') or '?'}"
            return f"{req} does not hold ({req.name} = {cell(value) or 'none'})"
    return ""
