"""HTML twins of the Markdown reports, and the page frame the gallery shares with them.

``report.md`` → ``report.html`` (``print_report.md`` → ``print_report.html``) beside it, converted by
Python-Markdown (with its ``tables`` extension), so the twin has the same content — tables, images,
links — as the Markdown.  The page is self-contained: its style sheet is inline, nothing is loaded
from the network (it works opened from disk).  Wide tables scroll inside their own box, so the
page itself is as wide as the screen (a phone's too).  Deterministic: the same Markdown gives the
same bytes.
"""

from __future__ import annotations

import html
import os
import tempfile
from pathlib import Path

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


def page(title: str, body: str, style: str = "", script: str = "") -> str:
    """A whole HTML document: inline style (STYLE + `style`), `body` as given, an inline `script`."""
    out = ["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
           '<meta name="viewport" content="width=device-width, initial-scale=1">',
           '<meta name="generator" content="propulsor">',
           f"<title>{html.escape(title)}</title>", f"<style>{STYLE}{style}</style>", "</head>", "<body>", body]
    if script:
        out.append(f"<script>\n{script}\n</script>")
    out += ["</body>", "</html>", ""]
    return "\n".join(out)


def markdown_to_html(text: str) -> str:
    """The body HTML of a Markdown text (Python-Markdown, tables extension); every table in a box that
    scrolls sideways on a narrow screen."""
    import markdown

    body = markdown.markdown(text, extensions=["tables"], output_format="html")
    return body.replace("<table>", '<div class="scroll"><table>').replace("</table>", "</table></div>")


def write_report_html(md_path: str | Path) -> Path:
    """``<report>.html`` beside ``<report>.md``: the same content as a self-contained page."""
    md_path = Path(md_path)
    text = md_path.read_text(encoding="utf-8")
    title = next((ln[2:].strip() for ln in text.splitlines() if ln.startswith("# ")), md_path.stem)
    out = md_path.with_suffix(".html")
    out.write_text(page(title, markdown_to_html(text)), encoding="utf-8")
    return out


def write_atomically(path: str | Path, text: str) -> Path:
    """Write `text` to `path` through a temporary file in the same folder and one rename, so that a
    reader (or a second writer) sees the old file or the new one, never a part."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
