"""The study's ranking (Pareto layers), front.csv and the Pareto front's picture; the table's columns
(the table itself, results.csv and results.parquet: table.py)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

from .spec import ALL_CHECKS, Study

FRONT = "front.csv"
FRONT_PNG = "pareto_front.png"
TAIL = ("all_checks_passed", "status", "reason", "failed_checks", "seconds", "worker")


def columns(study: Study) -> list[str]:
    return ["variant", "key", *study.varied, *study.values, *TAIL]


def cell(v) -> str:
    """A value as the tables write it: floats to the last digit (repr), booleans as true / false."""
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    return str(v)


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


def plot_front(folder: Path, study: Study, rows: list[dict], rank: list[tuple[int, dict]]) -> list[tuple]:
    """pareto_front.png: every variant that met the requirements (grey), the front (red, joined), the
    variants refused by a requirement (x); the first two objectives on the axes (one: against the
    variant number).  Returns where each variant is drawn: (variant, x, y) in the picture's pixels from
    its top left corner (the study page links the points)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    objs = study.objectives
    tex = _plain  # every text of the picture as written: a "$" never starts matplotlib's mathtext
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
        ax.set_xlabel(tex(f"{objs[0]} ({'min' if objs[0] in study.minimize else 'max'})"))
        ax.set_ylabel(tex(f"{objs[1]} ({'min' if objs[1] in study.minimize else 'max'})"))
    else:
        ax.set_xlabel("variant")
        ax.set_ylabel(tex(f"{objs[0]} ({'min' if objs[0] in study.minimize else 'max'})"))
    extra = f"; front over {', '.join(objs)}" if len(objs) > 2 else ""
    ax.set_title(tex(f"{study.title}: {len(rank)} of {len(rows)} variants meet the requirements{extra}"), fontsize=9)
    ax.grid(True, alpha=0.3)
    from matplotlib.ticker import ScalarFormatter

    for axis in (ax.xaxis, ax.yaxis):  # the values themselves on the ticks, never "1e-6 + 1.7026e-1"
        if isinstance(axis.get_major_formatter(), ScalarFormatter):
            axis.get_major_formatter().set_useOffset(False)
    if front or others or refused:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(folder / FRONT_PNG)
    height = fig.get_size_inches()[1] * fig.dpi
    points = []
    for r in [*refused, *others, *front]:
        (x,), (y,) = xy([r])
        px, py = ax.transData.transform((x, y))
        if math.isfinite(px) and math.isfinite(py):
            points.append((r["variant"], int(round(px)), int(round(height - py))))
    plt.close(fig)
    return points


def _plain(text: str) -> str:
    """`text` for matplotlib as it is written: "$" escaped (no mathtext), control characters as spaces."""
    return "".join(" " if ord(c) < 32 else c for c in str(text)).replace("$", r"\$")


def requirement_failure(study: Study, row: dict) -> str:
    """The first requirement the row does not meet ('' when it meets all)."""
    for req in study.require:
        value = row.get("all_checks_passed") if req.name == ALL_CHECKS else row.get(req.name)
        if not req.holds(value):
            if req.name == ALL_CHECKS and value is None:
                return f"{ALL_CHECKS}: no check runs at depth {study.depth} for this part (depth proof runs the proofs' checks, build all)"
            if req.name == ALL_CHECKS:
                return f"{ALL_CHECKS}: failed {row.get('failed_checks') or '?'}"
            return f"{req} does not hold ({req.name} = {cell(value) or 'none'})"
    return ""
