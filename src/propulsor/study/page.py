"""study.html: the study's page — the Pareto front (each point linked), the table of every variant
(sortable by any column), each variant linked to its files where the study made them (depth build:
variants/<key>/; --build-best: best/<rank>/).  Every text from the study file and the table is escaped.

Numbers are shown as a person reads them: four significant digits with the unit their name carries (79.54 mm),
a ripple (a fraction, no unit) in per cent, a value that is not a number as "—" with why; the table's cells keep
every digit for sorting (``data-v``) and results.csv keeps them all.  The picture and the table scroll inside their
own boxes: the page itself never scrolls sideways, even on a phone."""

from __future__ import annotations

import html
import math
from pathlib import Path

from ..export.gallery_values import number
from ..export.html import TABLE_SORT_SCRIPT as SCRIPT, page, write_atomically
from ..export.units import unit_from_name
from .results import FRONT_PNG, cell, columns
from .spec import Study

PAGE = "study.html"


_STYLE = ("body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse;font-size:12px}"
          "th,td{border:1px solid #ccc;padding:2px 6px;text-align:right}th{cursor:pointer;background:#eee}"
          "tr.front td{background:#fde8e8}td.t{text-align:left}td{white-space:nowrap}"
          ".scroll{overflow-x:auto;max-width:100%}.scroll img{max-width:none}")
#: what a value that is not a number means in the table
NOT_A_NUMBER = "— (not defined)"


def shown(name: str, v) -> str:
    """A value of column `name` as the page shows it: rounded, with its unit; a ripple in per cent."""
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return cell(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            return NOT_A_NUMBER if math.isnan(v) else ("∞" if v > 0 else "−∞")
        unit = "s" if name == "seconds" else unit_from_name(name)
        if not unit and "ripple" in name:
            return f"{number(100.0 * v)} %"
        return number(v) + (f" {unit}" if unit else "")
    return cell(v)


def _link(folder: Path, row: dict, best: dict) -> str:
    for rel in ([f"best/{best[row['variant']]}/report.html"] if row["variant"] in best else []) + \
               [f"variants/{row['key']}/report.html"]:
        if (folder / rel).is_file():
            return rel
    return ""


def _front_map(folder: Path, points, rows: list[dict], study: Study, best: dict) -> str:
    """The picture of the front with each point linked to its variant (its files where the study built
    them, else its row of the table)."""
    if not (folder / FRONT_PNG).is_file():
        return ""
    e = html.escape
    by_variant = {r["variant"]: r for r in rows}
    areas = []
    for variant, x, y in points or ():
        r = by_variant.get(variant)
        if r is None:
            continue
        href = _link(folder, r, best) or f"#v{variant}"
        title = f"variant {variant}: " + ", ".join(f"{n} = {shown(n, r.get(n))}" for n in study.objectives)
        areas.append(f'<area shape="circle" coords="{x},{y},6" href="{e(href, quote=True)}" '
                     f'alt="{e(title, quote=True)}" title="{e(title, quote=True)}">')
    # at its own size (the map's circles are in its pixels), in a box that scrolls on a narrow screen
    return (f'<div class="scroll"><img src="{FRONT_PNG}" alt="Pareto front" usemap="#front"></div>'
            f'<map name="front">{"".join(areas)}</map>')


def write_page(folder: Path, study: Study, rows: list[dict], rank: list[tuple[int, dict]], built_best: int = 0,
               points=None) -> Path:
    """Write study.html into `folder`; returns its path.  `points`: where plot_front drew each variant."""
    e = html.escape
    layer_of = {r["variant"]: layer for layer, r in rank}
    rank_of = {r["variant"]: k for k, (_, r) in enumerate(rank, 1)}
    best = {v: k for v, k in rank_of.items() if k <= built_best}
    cols = ["rank", "pareto_layer", *columns(study)]
    head = "".join(f"<th>{e(c)}</th>" for c in cols)
    body = []
    for r in sorted(rows, key=lambda r: (rank_of.get(r["variant"], 10**9), int(r["variant"]))):
        vals = {"rank": rank_of.get(r["variant"]), "pareto_layer": layer_of.get(r["variant"]), **r}
        link = _link(folder, r, best)
        cells = []
        for c in cols:
            text = cell(vals.get(c))
            html_text = e(shown(c, vals.get(c)))
            if c == "variant" and link:
                html_text = f'<a href="{e(link, quote=True)}">{html_text}</a>'
            cls = ' class="t"' if c in ("reason", "failed_checks", "status", "worker", "key") else ""
            cells.append(f'<td{cls} data-v="{e(text, quote=True)}">{html_text}</td>')
        tr = ' class="front"' if layer_of.get(r["variant"]) == 1 else ""
        body.append(f'<tr id="v{int(r["variant"])}"{tr}>{"".join(cells)}</tr>')
    objectives = ", ".join(f"{'minimize' if n in study.minimize else 'maximize'} {n}" for n in study.objectives)
    req = "; ".join(str(q) for q in study.require) or "none"
    img = _front_map(folder, points, rows, study, best)
    body_html = (f"<h1>{e(study.title)}</h1>"
                 f"<p>{len(rows)} variants of {e(study.part_file.name)} ({e(study.part_type)}) at depth "
                 f"{e(study.depth)}; {e(objectives)}; requirements: {e(req)}; {len(rank)} meet them (the front is "
                 f"shaded). Click a column to sort; a variant's number, and its point on the picture, link to its "
                 f"files where the study built them (else a point links to its row).</p>"
                 f'{img}<div class="scroll"><table><thead><tr>{head}</tr></thead><tbody>{"".join(body)}</tbody></table>'
                 f"</div>")
    return write_atomically(folder / PAGE, page(study.title, body_html, style=_STYLE, script=SCRIPT))
