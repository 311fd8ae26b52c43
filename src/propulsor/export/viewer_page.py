"""The 3D view on a page: its figure, its style and its script, shared by the gallery and each report.html.

The figure (``<figure class="viewer" data-models='[...]'>`` with a canvas and a status line) names the
assemblies' GLB script twins (``<name>.glb.js``); the script is the vendored three.js
(``web/three.min.js``, ``make viewer-lib``) followed by ours (``web/viewer.js``), one inline script, so
the page works opened from disk.  Every text from a manifest is escaped; every address percent-encoded.
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


def viewer_figure(models: list[dict], prefix: str = "", titles=(), what: str = "assembly",
                  heading: str = "<h3>3D</h3>") -> str:
    """The 3D view of a part's assemblies: `models` the manifest's ``media.models`` entries, their paths
    relative to the part's folder, `prefix` that folder as the page reaches it ("" beside the page, else
    ending in "/"); `titles` the names the selector shows (else each model's title); `what` names the
    selector.  "" when no model has a script twin."""
    titles = list(titles)
    data = [{"script": url(prefix + m["script"]),
             "title": (titles[k] if k < len(titles) and titles[k] else str(m.get("title", m["path"]))), **view_of(m)}
            for k, m in enumerate(models) if m.get("script")]
    if not data:
        return ""
    select = ""
    if len(data) > 1:
        opts = "".join(f"<option>{escape(d['title'])}</option>" for d in data)
        select = f'<label>{escape(what)} <select aria-label="assembly">{opts}</select></label>'
    glbs = " · ".join(f'<a href="{escape(url(prefix + m["path"]))}">{escape(m["path"])}</a>' for m in models)
    return (f"{heading}<figure class=\"viewer\" data-models='{escape(json.dumps(data), quote=True)}' "
            f'data-state="waiting">{select}<canvas></canvas>'
            f'<figcaption><span class="status">the 3D view loads when it comes into view</span> — GLB: {glbs}'
            f"</figcaption></figure>")


def viewer_script() -> str:
    """The 3D views' script: three.js as vendored (``web/three.min.js``, ``make viewer-lib``), then ours
    (``web/viewer.js``), one inline script."""
    web = resources.files(__package__).joinpath("web")
    return "\n".join(web.joinpath(f).read_text(encoding="utf-8") for f in ("three.min.js", "viewer.js"))
