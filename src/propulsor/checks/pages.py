"""What `propulsor check` demands of a page (``report.html``, ``print_report.html``, ``index.html``,
``study.html``): that it runs nothing but propulsor's own scripts and that the model data its 3D view reads
are GLBs the view may draw.

A page propulsor writes (export/html.py ``page``) begins with its Content-Security-Policy, before any
other element, and that policy allows scripts by sha256 alone: so a page passes only when

* it begins exactly as ``page`` begins it, the policy's meta the first element after the charset;
* the policy has exactly the directives ``page`` writes: ``default-src 'none'``, ``img-src 'self'``,
  ``style-src`` and ``script-src`` by sha256 only, ``base-uri 'none'``, ``form-action 'none'`` — and
  every script hash in it is one of propulsor's own scripts (the 3D view, the study page's table);
* every ``<script`` in it is either an inline script whose text has one of those hashes, or one of the 3D
  view's data blocks (``<script type="application/octet-stream" id="glb-…" class="propulsor-glb">``),
  each of which decodes to a GLB that checks.formats.check_glb accepts (sound, bounded, within the
  triangles the view draws).

Whatever else a page holds (an ``onerror`` attribute, a script of another type, a file beside it named
as a script) the browser does not run under that policy, and the view reads nothing but those blocks.
"""

from __future__ import annotations

import base64
import binascii
import re
from functools import lru_cache
from pathlib import Path

from . import formats
from .result import Check
from .safe_read import Refused, read_bytes

_HEAD = re.compile(r'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
                   r'<meta http-equiv="Content-Security-Policy" content="([^"<>]*)">\n')
_HASH = re.compile(r"'sha256-[A-Za-z0-9+/]{43}='")
_SCRIPT_TAG = re.compile(r"<script\b[^>]*>", re.IGNORECASE)
_DATA_TAG = re.compile(r'<script type="application/octet-stream" id="glb-[0-9a-f]{16}" class="propulsor-glb">')
_SCRIPT_END = re.compile(r"</script", re.IGNORECASE)


@lru_cache(maxsize=1)
def known_scripts() -> frozenset:
    """The CSP sources (sha256) of every script propulsor puts on a page."""
    from ..export.html import TABLE_SORT_SCRIPT, script_hash
    from ..export.viewer_page import viewer_script

    return frozenset({script_hash(viewer_script()), script_hash(TABLE_SORT_SCRIPT)})


def _policy_problem(csp: str) -> str:
    want = {"default-src": "'none'", "img-src": "'self'", "base-uri": "'none'", "form-action": "'none'"}
    seen = set()
    for part in csp.split(";"):
        words = part.split()
        if not words:
            continue
        name, sources = words[0].lower(), words[1:]
        if name in seen:
            return f"its policy names {name} twice"
        seen.add(name)
        if name in want:
            if sources != [want[name]]:
                return f"its policy's {name} is {' '.join(sources)!r}, not {want[name]}"
        elif name == "style-src":
            if not sources or not all(_HASH.fullmatch(s) for s in sources):
                return "its policy's style-src allows more than its own style sheet"
        elif name == "script-src":
            if sources == ["'none'"]:
                continue
            unknown = [s for s in sources if s not in known_scripts()]
            if not sources or unknown:
                return f"its policy's script-src allows {unknown[0] if unknown else 'nothing named'}, not one of " \
                       "propulsor's scripts"
        else:
            return f"its policy has {name}, which propulsor does not write"
    missing = ({"script-src", "style-src"} | set(want)) - seen
    return f"its policy lacks {sorted(missing)[0]}" if missing else ""


def page_problems(text: str) -> tuple[str, int]:
    """(why the page may run what propulsor did not write or its 3D view may read a bad model — "" when
    neither —, the number of model data blocks checked)."""
    from ..export.html import _sha256

    head = _HEAD.match(text)
    if head is None:
        return "it does not begin with propulsor's Content-Security-Policy", 0
    why = _policy_problem(head.group(1))
    if why:
        return why, 0
    at, blocks = head.end(), 0
    while True:
        tag = _SCRIPT_TAG.search(text, at)
        if tag is None:
            return "", blocks
        end = _SCRIPT_END.search(text, tag.end())
        if end is None:
            return f"a script at character {tag.start()} is not closed", blocks
        body = text[tag.end():end.start()]
        if tag.group(0) == "<script>":
            if _sha256(body) not in known_scripts():
                return f"an inline script at character {tag.start()} is not one of propulsor's", blocks
        elif _DATA_TAG.fullmatch(tag.group(0)):
            try:
                data = base64.b64decode(body, validate=True)
            except (binascii.Error, ValueError):
                return f"the model data at character {tag.start()} is not base64", blocks
            try:
                formats.check_glb(data)
            except Refused as exc:
                return f"the model data at character {tag.start()} is a GLB the 3D view may not draw: {exc}", blocks
            blocks += 1
        else:
            return f"a script element propulsor does not write at character {tag.start()}: {tag.group(0)[:60]}", blocks
        at = end.end()


def check_html_file(path: Path) -> list[Check]:
    """A page: runs nothing but propulsor's scripts; its 3D view's model data sound (:func:`page_problems`)."""
    name = path.name
    try:
        text = read_bytes(path, "html").decode("utf-8")
    except UnicodeDecodeError as exc:
        return [Check.flag(f"{name}: runs only propulsor's scripts", False, f"not UTF-8 ({exc.reason})")]
    why, blocks = page_problems(text)
    return [Check.flag(f"{name}: runs only propulsor's scripts", not why,
                       why or f"its policy and scripts are propulsor's; {blocks} model(s) sound")]
