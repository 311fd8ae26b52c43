"""report.md: the human-readable account of one built part.

A summary first (PASSED / FAILED, the key derived values with their units, the failed checks), then
what was built, the inputs, every derived value with its unit and meaning, every check with value,
limit and PASS/FAIL, the tables, figures and views, the notes, and the References: every source the
report names, numbered in the order it first names them (:mod:`.references`).
The exporter only formats: values arrive computed.  The title (and the part file's notes, through
:func:`md_text`) are text, never Markdown or HTML: a ``<script>`` or ``[x](javascript:...)`` in them
reads as written.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ..write_root import prepare


from .units import unit_from_name  # noqa: F401  (the report's units come from the names)


_MD_ESCAPES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}


def md_text(text) -> str:
    """`text` as Markdown that shows it as written, on one line: ``<``, ``>``, ``&`` as entities (no
    HTML can start), ``\\ ` * [ ]`` escaped by a backslash (no code span, emphasis, link or image)."""
    one_line = re.sub(r"\s*[\r\n]+\s*", " ", str(text))
    return re.sub(r"[&<>\\`*\[\]]", lambda m: _MD_ESCAPES.get(m.group(), "\\" + m.group()), one_line)


def md_plain(text: str) -> str:
    """The text that :func:`md_text` wrote (its escapes undone)."""
    import html

    return html.unescape(re.sub(r"\\([\\`*\[\]])", r"\1", text))


#: a value that is not a number (NaN) as reports show it
NOT_DEFINED = "— (not defined)"


def _fmt(v) -> str:
    try:
        import numpy as np

        if isinstance(v, np.generic):
            v = v.item()
        if isinstance(v, np.ndarray):
            v = v.tolist()
    except ImportError:  # pragma: no cover
        pass
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        if not math.isfinite(v):  # never "nan" on a page: what it means
            return NOT_DEFINED if math.isnan(v) else ("∞" if v > 0 else "−∞")
        return f"{v:.6g}"
    if isinstance(v, dict):
        return ", ".join(f"{k}: {_fmt(x)}" for k, x in v.items())
    if isinstance(v, (list, tuple)):
        if len(v) > 8:
            return "[" + ", ".join(_fmt(x) for x in v[:8]) + f", ... ({len(v)} values)]"
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    return "" if v is None else str(v)


def _cell(s: str) -> str:
    return str(s).replace("|", "\\|").replace("\n", " ")


def _value_rows(values) -> list[tuple[str, str, str, str]]:
    """Rows (name, value, unit, meaning) from a dict name -> value or
    name -> (value, unit[, meaning])."""
    rows = []
    items = values.items() if isinstance(values, dict) else values
    for name, v in items:
        unit = meaning = ""
        if isinstance(v, tuple) and 2 <= len(v) <= 3 and isinstance(v[1], str):
            unit = v[1]
            meaning = v[2] if len(v) > 2 else ""
            v = v[0]
        rows.append((str(name), _fmt(v), unit, meaning))
    return rows


def _table(header, rows) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(_cell(c) for c in r) + " |" for r in rows]
    return out


def _refs(items) -> list[tuple[str, str]]:
    out = []
    for it in items:
        if isinstance(it, (str, Path)):
            out.append((Path(it).as_posix(), Path(it).stem.replace("_", " ")))
        else:
            out.append((Path(it[0]).as_posix(), str(it[1])))
    return out


def write_report(
    path: str | Path,
    title: str,
    intro: str = "",
    inputs=None,
    derived=None,
    checks=(),
    tables=(),
    figures=(),
    notes=(),
    part: str = "",
    plots=(),
    views=(),
    key_values=(),
    lead=(),
    inputs_heading: str = "Inputs",
    inputs_last: bool = False,
) -> Path:
    """Write a Markdown report.

    inputs / derived: dict name -> value, or name -> (value, unit[, meaning]).
    checks: list of Check (or dicts with the same keys).  tables / figures
    (alias plots): relative paths or (relative path, caption) pairs.  notes:
    strings.  part: the part type, printed under the title.  views: the isometric pictures
    of the solids and assemblies (relative paths or (path, caption) pairs).  key_values: names of
    derived values the summary shows (those present, in this order).  lead: Markdown lines placed first,
    before the summary (a print kit's: what to print, with what, how long, then the assembly).
    inputs_heading / inputs_last: the inputs' section's heading, and whether it closes the report (an
    appendix, before the references) instead of following the summary.
    """
    from .references import Citer

    cite = Citer()
    inputs = inputs or {}
    derived = derived or {}
    tables = _refs(tables)
    figures = _refs(list(figures) + list(plots))
    views = _refs(views)
    path = Path(path)
    prepare(path)
    cks = [c.to_dict() if hasattr(c, "to_dict") else dict(c) for c in checks]
    n_fail = sum(not c["passed"] for c in cks)
    lines = [f"# {cite(md_text(title))}", ""]
    if part:
        lines += [f"Part type: `{part}`", ""]
    lines += [cite(line) for line in lead]
    lines += ["## Summary", ""]
    if n_fail:
        lines += [f"**FAILED: {n_fail} of {len(cks)} checks failed.**", ""]
    else:
        lines += [f"**PASSED: all {len(cks)} checks passed.**", ""]
    derived_rows = [tuple(cite(c) for c in r) for r in _value_rows(derived)]
    by_name = {r[0]: r for r in derived_rows}
    key_rows = [by_name[k] for k in key_values if k in by_name]
    if key_rows:
        lines += ["Key values:", ""] + _table(["name", "value", "unit", "meaning"], key_rows) + [""]
    failed = [c for c in cks if not c["passed"]]
    if failed:
        lines += ["Failed checks:", ""]
        lines += [f"- {cite(_cell(c['name']))}: {_fmt(c['value'])} against the limit {_fmt(c['limit'])} "
                  f"{c.get('unit', '')}".rstrip() + (f" ({cite(c['message'])})" if c.get("message") else "")
                  for c in failed] + [""]
    if intro.strip():
        lines += [cite(intro.strip()), ""]
    input_rows = [tuple(cite(c) for c in r) for r in _value_rows(inputs)]
    inputs_section = [f"## {inputs_heading}", ""] + _table(["name", "value", "unit", "meaning"], input_rows) + [""]
    if not inputs_last:
        lines += inputs_section
    lines += ["## Derived values", ""] + _table(["name", "value", "unit", "meaning"], derived_rows) + [""]
    lines += ["## Checks", ""]
    rows = [
        (cite(c["name"]), _fmt(c["value"]), _fmt(c["limit"]), c.get("unit", ""), "PASS" if c["passed"] else "**FAIL**",
         cite(c.get("message", "")))
        for c in cks
    ]
    lines += _table(["check", "value", "limit", "unit", "result", "note"], rows) + [""]
    if tables:
        lines += ["## Tables", ""] + [f"- [{p}]({p}): {cite(cap)}" for p, cap in tables] + [""]
    if figures:
        lines += ["## Figures", ""]
        for p, cap in figures:
            cap = cite(cap)
            lines += [f"![{cap}]({p})", "", f"*{cap}*", ""]
    if views:
        lines += ["## Views", "", "Isometric pictures of every solid and assembly (3D models: the `.glb` files).", ""]
        for p, cap in views:
            cap = cite(cap)
            lines += [f"![{cap}]({p})", "", f"*{cap}*", ""]
    if notes:
        lines += ["## Notes", ""] + [f"- {cite(n)}" for n in notes] + [""]
    if inputs_last:
        lines += inputs_section
    refs = cite.references()
    if refs:
        lines += ["## References", ""]
        for r in refs:
            lines += [r, ""]
    path.write_text("\n".join(lines), encoding="utf-8")
    return path
