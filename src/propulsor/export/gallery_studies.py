"""The gallery's design studies: every sub-folder of the gallery folder that holds a study propulsor
wrote (``study.json`` and ``study.html``, ``propulsor explore``), each with its title, part, depth and
counts, its Pareto front's picture and a link to its page (the front, the sortable table, each variant
linked).  study.json is data: read bounded, checked field by field, every text escaped; a study whose
study.json cannot be read is a note naming why."""

from __future__ import annotations

import json
from html import escape
from pathlib import Path
from urllib.parse import quote

from .gallery_manifest import inside

MARKER = "study.json"
PAGE = "study.html"
FRONT_PNG = "pareto_front.png"
#: the study's tables, linked where they exist
TABLES = ("results.csv", "results.parquet", "front.csv")
#: study.json is small; a larger one is not a study's
MAX_BYTES = 1 << 20

STYLE = """
section.studies { border: 1px solid var(--line); border-radius: 8px; padding: 4px 14px 14px; margin: 18px 0; }
.study { display: flex; flex-wrap: wrap; gap: 6px 18px; align-items: flex-start; margin: 10px 0; }
.study img { width: 280px; height: auto; }
"""


def _text(v) -> str | None:
    return v if isinstance(v, str) else None


def _count(v) -> int | None:
    return v if isinstance(v, int) and not isinstance(v, bool) and v >= 0 else None


def found_studies(folder: str | Path) -> list[dict]:
    """Every study under `folder`: {name, info (title, part, depth, variants, meeting, front) or None,
    error or None}, sorted by name."""
    from ..regular_file import read_regular

    folder = Path(folder)
    out: list[dict] = []
    import os

    from ..regular_file import NotRegular, open_regular

    for d in sorted(folder.iterdir()):
        if d.name.startswith(".") or not d.is_dir() or d.is_symlink() or not os.path.lexists(d / MARKER):
            continue
        if not inside(d, MARKER):  # a study.json that is a FIFO, a device, a link out of the folder …: said so
            try:
                fd, _ = open_regular(d / MARKER)
                os.close(fd)
                why = "is not a regular file inside the folder"
            except (NotRegular, OSError) as exc:
                why = str(getattr(exc, "strerror", None) or exc)
            out.append({"name": d.name, "info": None, "error": f"{MARKER} not readable: {why}"})
            continue
        if not inside(d, PAGE):
            out.append({"name": d.name, "info": None, "error": f"no {PAGE} yet (a study not finished, or "
                        f"interrupted: propulsor explore --resume finishes it)"})
            continue
        try:
            data = json.loads(read_regular(d / MARKER, MAX_BYTES).decode("utf-8"))
            if not isinstance(data, dict):
                raise ValueError("not an object")
        except (OSError, ValueError, RecursionError) as exc:
            out.append({"name": d.name, "info": None, "error": f"{MARKER} not readable: {exc}"})
            continue
        front = data.get("front")
        info = {"title": _text(data.get("title")) or d.name, "part": _text(data.get("part")),
                "depth": _text(data.get("depth")), "variants": _count(data.get("variants")),
                "meeting": _count(data.get("meeting_requirements")),
                "front": len(front) if isinstance(front, list) else None,
                "picture": inside(d, FRONT_PNG), "files": [f for f in TABLES if inside(d, f)]}
        out.append({"name": d.name, "info": info, "error": None})
    return out


def _href(path: str) -> str:
    return escape(quote(path, safe="/"))


def studies_section(entries: list[dict]) -> str:
    """The gallery's section of the studies ('' when there is none)."""
    if not entries:
        return ""
    out = ['<section class="studies" id="design-studies"><h2>Design studies</h2>',
           f'<p class="sub">{len(entries)} stud{"y" if len(entries) == 1 else "ies"} in this folder '
           "(propulsor explore): each page shows the Pareto front, the table of every variant (click a column "
           "to sort) and links each variant to its files.</p>"]
    for e in entries:
        name, info = e["name"], e["info"]
        if info is None:
            out.append(f'<p class="unreadable">{escape(name)}: {escape(e["error"])}</p>')
            continue
        facts = []
        if info["part"]:
            facts.append(f"part {escape(Path(info['part']).name)}")
        if info["depth"]:
            facts.append(f"depth {escape(info['depth'])}")
        if info["variants"] is not None:
            facts.append(f"{info['variants']} variants")
        if info["meeting"] is not None:
            facts.append(f"{info['meeting']} meet the requirements")
        if info["front"] is not None:
            facts.append(f"{info['front']} on the Pareto front")
        page = _href(f"{name}/{PAGE}")
        pic = (f'<a href="{page}"><img src="{_href(f"{name}/{FRONT_PNG}")}" '
               f'alt="{escape(info["title"], quote=True)}: Pareto front"></a>' if info["picture"] else "")
        out.append(f'<div class="study">{pic}<div><h3><a href="{page}">{escape(info["title"])}</a></h3>'
                   f'<p class="sub">{" · ".join(facts)}</p>'
                   f'<p class="links"><a href="{page}">study page</a>'
                   + "".join(f'<a href="{_href(f"{name}/{f}")}">{f}</a>' for f in info["files"])
                   + "</p></div></div>")
    out.append("</section>")
    return "\n".join(out)
