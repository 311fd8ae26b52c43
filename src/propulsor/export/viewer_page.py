"""The 3D view on a page: its figure, its style and its script, shared by the gallery and each report.html.

The figure (``<figure class="viewer" data-models='[...]'>`` with a canvas and a status line) names, for each
assembly, a data block of the same page: ``<script type="application/octet-stream" id="glb-…"
class="propulsor-glb">`` holding the GLB's bytes in base64.  A script element of that type is data the
browser never runs; the viewer decodes it, checks it (header, chunks, lists, no external URI, the nodes a
forest, the triangles drawn within the budget) and hands it to three.js's loader.  The GLB is read here
bounded and checked as ``propulsor check`` checks a GLB (export/glb_check.py) before a byte of it is
put on the page; a page carries at most policy.PAGE_MODEL_BYTES_MAX of them.  The page's one executable
script is the vendored three.js (``web/three.min.js``, ``make viewer-lib``) followed by ours
(``web/viewer.js``), inline, allowed by its sha256 alone: no file beside the page is ever loaded as a script,
so the page works opened from disk and runs nothing a part folder holds.  Every text from a manifest is
escaped; every address percent-encoded.
"""

from __future__ import annotations

import json
from html import escape
from importlib import resources
from urllib.parse import quote

#: the style of the view and its tools (part list, section, exploded view, motion)
VIEWER_STYLE = """
figure.viewer { margin: 8px 0; max-width: 760px; }
figure.viewer canvas { display: block; width: 100%; aspect-ratio: 4 / 3; max-height: 70vh; border: 1px solid var(--line);
                       border-radius: 4px; touch-action: none; background: #f5f7fa; }
.tools { display: flex; flex-wrap: wrap; gap: 4px 18px; align-items: flex-start; margin: 4px 0; font-size: 0.9em; }
.tools ul { list-style: none; padding: 0; margin: 4px 0; columns: 2 180px; }
.tools li.picked { background: var(--panel); font-weight: 600; }
.tools .swatch { display: inline-block; width: 0.9em; height: 0.9em; margin: 0 5px 0 3px; border: 1px solid var(--line);
                 vertical-align: -0.1em; }
.tools input[type=range] { width: 140px; vertical-align: middle; }
.tools .motion button { min-width: 4.5em; margin-right: 6px; }
.tools .pose { margin-left: 6px; color: var(--muted); white-space: nowrap; }
"""


def url(path: str) -> str:
    """A relative path as an address: every character but letters, digits, ``/ - . _ ~`` percent-encoded
    (a ``:`` never makes it a scheme, a ``#`` or ``?`` stays part of the name)."""
    return quote(path, safe="/")


def view_of(model: dict) -> dict:
    """{"view": the 3D view's first camera direction in glTF's frame (y up)} of a model whose manifest entry
    names one (``view_dir``, the part's frame, z up: the balancer's arm is seen from below); else {}."""
    d = model.get("view_dir")
    return {"view": [d[0], d[2], -d[1]]} if d else {}


#: the type of a model's data block: a <script> element of this type is never run by a browser
DATA_TYPE = "application/octet-stream"
#: the class of the data blocks (``propulsor check`` reads each one as a GLB)
DATA_CLASS = "propulsor-glb"


def model_data(path) -> tuple[str | None, int, str]:
    """(the GLB's bytes in base64, their number, "") when the file at `path` is a GLB the viewer may draw —
    a regular file within policy's GLB limit that export.glb_check.check_glb accepts (sound, bounded, within
    the drawn-triangle budget) —, else (None, 0, why not)."""
    import base64

    from ..policy import READ_LIMIT_BYTES
    from ..regular_file import read_regular
    from .glb_check import check_glb

    try:
        data = read_regular(path, READ_LIMIT_BYTES["glb"])
        check_glb(data)
    except (OSError, ValueError) as exc:  # glb_check.Refused and regular_file.NotRegular are ValueErrors
        return None, 0, str(getattr(exc, "strerror", None) or exc)
    return base64.b64encode(data).decode("ascii"), len(data), ""


def block_id(address: str) -> str:
    """The id of the data block of the model at `address` (the same model, the same id)."""
    import hashlib

    return "glb-" + hashlib.sha256(address.encode("utf-8")).hexdigest()[:16]


def page_budget() -> dict:
    """What a page may still carry as model data: bytes left (policy.PAGE_MODEL_BYTES_MAX at first) and the
    ids of the blocks already on it (a model named twice is carried once)."""
    from ..policy import PAGE_MODEL_BYTES_MAX

    return {"left": PAGE_MODEL_BYTES_MAX, "ids": set()}


def viewer_figure(models: list[dict], prefix: str = "", titles=(), what: str = "assembly",
                  heading: str = "<h3>3D</h3>", folder=None, budget: dict | None = None, links: bool = True) -> str:
    """The 3D view of a part's assemblies: `models` the manifest's ``media.models`` entries, their paths
    relative to the part's folder — `folder` where this process reads them, `prefix` that folder as the page
    reaches it ("" beside the page, else ending in "/"); `titles` the names the selector shows (else each
    model's title); `what` names the selector; `budget` what the page may still carry (:func:`page_budget`;
    a fresh one when None), lowered by what this figure carries.  Each model whose GLB is sound
    (:func:`model_data`) and fits the budget gets a data block after the figure (once a page); the others are
    named in the caption with why.  "" when there is no model.  `links`: the GLBs' names linked to their files (a
    page beside them); False where the page has no files beside it (a notebook's view): their names only."""
    from pathlib import Path

    budget = page_budget() if budget is None else budget
    titles = list(titles)
    data, blocks, missing = [], [], []
    for k, m in enumerate(models):
        path = m.get("path")
        if not isinstance(path, str) or not path.endswith(".glb"):
            continue
        ident = block_id(prefix + path)
        if ident not in budget["ids"]:
            b64, n, why = model_data(Path(folder or ".") / path)
            if b64 is not None and n > budget["left"]:
                b64, why = None, "more model data than this page carries (the part's report shows it)"
            if b64 is None:
                missing.append(f"{path} ({why})")
                continue
            budget["left"] -= n
            budget["ids"].add(ident)
            blocks.append(f'<script type="{DATA_TYPE}" id="{ident}" class="{DATA_CLASS}">{b64}</script>')
        data.append({"block": ident,
                     "title": (titles[k] if k < len(titles) and titles[k] else str(m.get("title", path))),
                     **view_of(m)})
    glbs = " · ".join((f'<a href="{escape(url(prefix + m["path"]))}">{escape(m["path"])}</a>' if links else
                       escape(m["path"])) for m in models if isinstance(m.get("path"), str))
    not_shown = f" — not drawn: {escape('; '.join(missing))}" if missing else ""
    if not data:
        return f'{heading}<p class="note">3D view: GLB: {glbs}{not_shown}</p>' if missing else ""
    select = ""
    if len(data) > 1:
        opts = "".join(f"<option>{escape(d['title'])}</option>" for d in data)
        select = f'<label>{escape(what)} <select aria-label="assembly">{opts}</select></label>'
    return (f"{heading}<figure class=\"viewer\" data-models='{escape(json.dumps(data), quote=True)}' "
            f'data-state="waiting">{select}<canvas></canvas>'
            f'<figcaption><span class="status">the 3D view loads when it comes into view</span> — GLB: {glbs}'
            f"{not_shown}</figcaption></figure>" + "".join(blocks))


def viewer_script() -> str:
    """The 3D views' script: three.js as vendored (``web/three.min.js``, ``make viewer-lib``), then ours
    (``web/viewer.js``), one inline script."""
    web = resources.files(__package__).joinpath("web")
    return "\n".join(web.joinpath(f).read_text(encoding="utf-8") for f in ("three.min.js", "viewer.js"))
