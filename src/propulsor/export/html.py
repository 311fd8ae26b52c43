"""HTML twins of the Markdown reports, and the page frame the gallery shares with them.

``report.md`` → ``report.html`` (``print_report.md`` → ``print_report.html``) beside it, converted by
Python-Markdown (with its ``tables`` extension), so the twin has the same content — tables, images,
links — as the Markdown.  The page is self-contained: its style sheet is inline, nothing is loaded
from the network (it works opened from disk).

Text in a report comes from part files (title, notes) and is data, never markup: the conversion
keeps no raw HTML (a ``<script>`` in the Markdown is shown as text), and a link or image is kept
only when its address is a relative path inside the report's folder (:func:`local_url`); any other
(``javascript:``, ``data:``, a scheme, a leading ``/``, a ``..``) is shown as its text.  Every page
carries a Content-Security-Policy that lets it run only its own inline script (by its sha256) and
load only files beside it (:func:`content_security_policy`).  Wide tables scroll inside their own box, so the
page itself is as wide as the screen (a phone's too).  Deterministic: the same Markdown gives the
same bytes.
"""

from __future__ import annotations

import base64
import hashlib
import html
from collections.abc import Iterable, Iterator
from pathlib import Path
from urllib.parse import unquote

#: the style of every page the project writes (inline: nothing fetched)
STYLE = """
:root { --fg: #1d232b; --muted: #5c6773; --line: #d5dae0; --bg: #ffffff; --panel: #f4f6f8;
        --ok: #1f7a3a; --doc: #8a5a00; --bad: #b3261e; --link: #1f5fa8; }
* { box-sizing: border-box; }
html { -webkit-text-size-adjust: 100%; }
body { margin: 0 auto; max-width: 1200px; padding: 12px 16px 40px; color: var(--fg); background: var(--bg);
       font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       overflow-wrap: anywhere; }
h1 { font-size: 1.5em; margin: 0.4em 0; } h2 { font-size: 1.2em; margin: 1.2em 0 0.4em; }
h3 { font-size: 1.05em; margin: 1em 0 0.3em; }
a { color: var(--link); }
code { font: 0.92em/1.3 ui-monospace, "DejaVu Sans Mono", monospace; background: var(--panel); padding: 0 3px;
       border-radius: 3px; }
img { max-width: 100%; height: auto; }
.scroll { overflow-x: auto; max-width: 100%; margin: 0.5em 0; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid var(--line); padding: 3px 6px; text-align: left; vertical-align: top;
         overflow-wrap: normal; }
th { background: var(--panel); }
"""


#: the study page's one script (its table sorted by a click on a column; study/page.py); `propulsor
#: check` knows it by its hash (checks/pages.py)
TABLE_SORT_SCRIPT = """
document.querySelectorAll('th').forEach(function (th, col) {
  th.addEventListener('click', function () {
    var body = th.closest('table').tBodies[0], rows = Array.prototype.slice.call(body.rows);
    var dir = th.dataset.dir === 'asc' ? -1 : 1; th.dataset.dir = dir === 1 ? 'asc' : 'desc';
    rows.sort(function (a, b) {
      var x = a.cells[col].dataset.v, y = b.cells[col].dataset.v, nx = parseFloat(x), ny = parseFloat(y);
      if (!isNaN(nx) && !isNaN(ny)) return dir * (nx - ny);
      return dir * x.localeCompare(y);
    });
    rows.forEach(function (r) { body.appendChild(r); });
  });
});
"""


def _sha256(text: str) -> str:
    return "'sha256-" + base64.b64encode(hashlib.sha256(text.encode("utf-8")).digest()).decode("ascii") + "'"


def content_security_policy(style: str, script: str = "") -> str:
    """The policy of a page whose one inline style sheet is `style` and one inline script `script`
    (the exact text between the tags): nothing runs but that script, by its sha256 — no script file (not
    even one beside the page: a part folder's files are data), no other inline code, no plug-in, no frame,
    no form, no network; images from the page's own folder."""
    scripts = _sha256(script) if script else "'none'"
    return ("default-src 'none'; img-src 'self'; " f"style-src {_sha256(style)}; script-src {scripts}; "
            "base-uri 'none'; form-action 'none'")


def page(title: str, body: str, style: str = "", script: str = "") -> str:
    """A whole HTML document: inline style (STYLE + `style`), `body` as given, an inline `script`; a
    Content-Security-Policy that lets only these two run."""
    return "".join(page_pieces(title, [body], style, script))


def page_pieces(title: str, body: Iterable[str], style: str = "", script: str = "") -> Iterator[str]:
    """:func:`page` in pieces, its body's pieces (joined by newlines) taken one at a time as they come: a page of
    tens of megabytes (the gallery, every part's 3D model in it) written without the whole of it in memory."""
    css = STYLE + style
    code = f"\n{script}\n" if script else ""
    csp = content_security_policy(css, code)  # no " < & in it: written as it is
    yield "\n".join(["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
                     f'<meta http-equiv="Content-Security-Policy" content="{csp}">',
                     '<meta name="viewport" content="width=device-width, initial-scale=1">',
                     '<meta name="generator" content="propulsor">',
                     f"<title>{html.escape(title)}</title>", f"<style>{css}</style>", "</head>", "<body>", ""])
    for k, piece in enumerate(body):
        yield piece if k == 0 else "\n" + piece
    yield "\n" + "\n".join(([f"<script>{code}</script>"] if script else []) + ["</body>", "</html>", ""])


def local_url(url: str) -> bool:
    """Whether `url` (as written in an attribute, entities and all) is a relative path that stays in
    the page's folder: no scheme (no ``:`` at all), no leading ``/``, no ``\\``, no ``..`` (also
    percent-encoded), no white space or control character.  A bare ``#fragment`` is local."""
    u = html.unescape(url)
    if not u or any(ord(c) <= 0x20 or ord(c) == 0x7F or c in "\\:" for c in u) or u.startswith("/"):
        return False
    path = unquote(u.split("#", 1)[0].split("?", 1)[0])
    return not any(ord(c) <= 0x20 or c in "\\:" for c in path) and ".." not in path.split("/")


def _markdown_extension():
    from markdown.extensions import Extension
    from markdown.treeprocessors import Treeprocessor

    class LocalLinksOnly(Treeprocessor):
        """A link whose address is not local becomes its text; an image, its alt text."""

        def run(self, root):
            for el in root.iter():
                if el.tag == "a" and not local_url(el.get("href", "")):
                    el.tag = "span"
                    el.attrib.clear()
                elif el.tag == "img" and not local_url(el.get("src", "")):
                    alt = el.get("alt", "")
                    el.tag = "span"
                    el.attrib.clear()
                    el.text = alt

    class NoRawHtml(Extension):
        """Raw HTML in the Markdown is text (Python-Markdown's own switch: its HTML block and inline
        HTML processors are taken out); addresses are checked (:class:`LocalLinksOnly`)."""

        def extendMarkdown(self, md):
            md.preprocessors.deregister("html_block")
            md.inlinePatterns.deregister("html")
            md.treeprocessors.register(LocalLinksOnly(md), "local_links_only", 1)

    return NoRawHtml()


def markdown_to_html(text: str) -> str:
    """The body HTML of a Markdown text (Python-Markdown, tables extension, raw HTML off, links and
    images only to local files); every table in a box that scrolls sideways on a narrow screen."""
    import markdown

    body = markdown.markdown(text, extensions=["tables", _markdown_extension()], output_format="html")
    return body.replace("<table>", '<div class="scroll"><table>').replace("</table>", "</table></div>")


#: where a report's 3D view goes: after its summary, before the first long table
_VIEW_BEFORE = "<h2>Inputs</h2>"


def write_report_html(md_path: str | Path, models=()) -> Path:
    """``<report>.html`` beside ``<report>.md``: the same content as a self-contained page; with
    `models` (the build's ``media.models`` entries) the 3D view of its assemblies after the summary
    (the gallery's viewer, inlined: it works opened from disk)."""
    md_path = Path(md_path)
    text = md_path.read_text(encoding="utf-8")
    from .report import md_plain
    from .viewer_page import VIEWER_STYLE, viewer_figure, viewer_script

    title = next((md_plain(ln[2:].strip()) for ln in text.splitlines() if ln.startswith("# ")), md_path.stem)
    body = markdown_to_html(text)
    figure = viewer_figure(list(models), "", heading="<h2>3D view</h2>", folder=md_path.parent)
    if figure:
        at = body.find(_VIEW_BEFORE)
        body = body + figure if at < 0 else body[:at] + figure + "\n" + body[at:]
        html_text = page(title, body, style=VIEWER_STYLE, script=viewer_script())
    else:
        html_text = page(title, body)
    out = md_path.with_suffix(".html")
    out.write_text(html_text, encoding="utf-8")
    return out


def script_hash(script: str) -> str:
    """The CSP source (``'sha256-…'``) of `script` as :func:`page` writes it between its tags."""
    return _sha256(f"\n{script}\n")


def write_atomically(path: str | Path, text: str | Iterable[str]) -> Path:
    """Write `text` (or its pieces, one at a time: :func:`page_pieces`) to `path` (UTF-8) through a temporary file
    in the same folder and one rename, so that a reader (or a second writer) sees the old file or the new one,
    never a part."""
    from ..atomic_file import replace_atomically

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as f:  # as Path.write_text
            for piece in ([text] if isinstance(text, str) else text):
                f.write(piece)

    return replace_atomically(path, write)


def view_page(folder: str | Path, lead: str = "") -> str | None:
    """A whole page (:func:`page`) with the 3D view of the assemblies a build wrote into `folder` (its
    manifest's ``media.models``: the GLBs, checked and inlined as the report's, and the vendored three.js: it
    needs no network) after `lead` (HTML, escaped by the caller); None when the build wrote no model.  What a
    notebook shows of a part (``propulsor.Part._repr_html_``)."""
    import json

    from ..policy import MANIFEST_MAX_BYTES
    from ..regular_file import read_regular
    from .viewer_page import VIEWER_STYLE, viewer_figure, viewer_script

    folder = Path(folder)
    manifest = json.loads(read_regular(folder / "manifest.json", MANIFEST_MAX_BYTES).decode("utf-8"))
    models = [m for m in manifest.get("media", {}).get("models", []) if isinstance(m, dict)]
    figure = viewer_figure(models, "", heading="", folder=folder, links=False)  # no file beside a notebook's view
    if not figure:
        return None
    return page(str(manifest.get("title") or manifest.get("part") or "part"), lead + figure, style=VIEWER_STYLE,
                script=viewer_script())
