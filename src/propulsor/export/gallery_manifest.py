"""A part's manifest as the gallery reads it: every field it shows checked for its type, every path
it links checked against the part's folder.

A manifest is data from disk (written by propulsor, or edited, or damaged): :func:`load_manifest`
returns a clean copy of the fields the gallery reads, or raises :class:`ManifestError` naming the
first field of the wrong type (the gallery then shows a note instead of the part).  A path (a
picture, an animation, a model, a file) is kept only when it is relative, stays
inside the part's folder (after links are followed) and names an existing regular file
(:func:`inside`); any other entry is left out.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from .manifest import MANIFEST

#: the media kinds the gallery shows, and the fields of an entry it reads: field -> (type check, what)
_TEXT = (lambda v: isinstance(v, str), "a string")
_COUNT = (lambda v: isinstance(v, int) and not isinstance(v, bool) and v >= 0, "a whole number >= 0")
_NUMBER = (lambda v: isinstance(v, (int, float)) and not isinstance(v, bool), "a number")
_DIRECTION = (lambda v: isinstance(v, list) and len(v) == 3 and all(
    isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in v)
    and any(x != 0 for x in v), "three finite numbers, not all 0")
MEDIA_FIELDS = {
    "animations": {"path": _TEXT, "title": _TEXT, "frames": _COUNT, "width_px": _COUNT, "height_px": _COUNT,
                   "bytes": _COUNT, "least_clearance_mm": _NUMBER},
    "models": {"path": _TEXT, "title": _TEXT, "view_dir": _DIRECTION},
    "pictures": {"path": _TEXT, "title": _TEXT},
}
#: the suffix of a model (a GLB, carried on the page as data: no file of a part's folder is loaded as a script)
MODEL_SUFFIX = ".glb"


class ManifestError(ValueError):
    """A manifest the gallery cannot show: not JSON, or a field of the wrong type."""


def _kind(v) -> str:
    return {dict: "an object", list: "a list", str: "a string", bool: "true/false", type(None): "null"}.get(
        type(v), "a number" if isinstance(v, (int, float)) else type(v).__name__)


def _need(cond: bool, where: str, value, what: str) -> None:
    if not cond:
        raise ManifestError(f"{where} is {_kind(value)}, not {what}")


def _list(data: dict, key: str, where: str) -> list:
    v = data.get(key)
    if v is None:
        return []
    _need(isinstance(v, list), where, v, "a list")
    return v


def _entries(items: list, where: str, fields: dict) -> list[dict]:
    out = []
    for k, e in enumerate(items):
        _need(isinstance(e, dict), f"{where}[{k}]", e, "an object")
        clean = {}
        for key, (ok, what) in fields.items():
            v = e.get(key)
            if v is None:
                continue
            _need(ok(v), f"{where}[{k}].{key}", v, what)
            clean[key] = v
        out.append(clean)
    return out


def inside(part_dir: Path, rel) -> str | None:
    """`rel` when it is a relative path naming an existing regular file inside `part_dir` (links
    followed); else None."""
    if not isinstance(rel, str) or not rel or rel.startswith(("/", "\\")) or any(ord(c) < 0x20 for c in rel):
        return None
    if ".." in rel.replace("\\", "/").split("/"):
        return None
    try:
        base = part_dir.resolve()
        target = (part_dir / rel).resolve()
        ok = target.is_relative_to(base) and target != base and target.is_file()
    except (OSError, ValueError, RuntimeError):
        return None
    return rel if ok else None


def clean_manifest(data, part_dir: Path) -> dict:
    """The fields of `data` (a loaded manifest) that the gallery reads, checked; paths not inside
    `part_dir` left out.  Raises ManifestError."""
    _need(isinstance(data, dict), "the manifest", data, "an object")
    part = data.get("part")
    _need(isinstance(part, str), "part", part, "a string")
    title = data.get("title")
    _need(title is None or isinstance(title, str), "title", title, "a string")
    checks = _entries(_list(data, "checks", "checks"), "checks",
                      {"name": _TEXT, "passed": (lambda v: isinstance(v, bool), "true/false")})
    expected = _list(data, "expected_failures", "expected_failures")
    for k, n in enumerate(expected):
        _need(isinstance(n, str), f"expected_failures[{k}]", n, "a string")
    derived = data.get("derived")
    derived = {} if derived is None else derived
    _need(isinstance(derived, dict), "derived", derived, "an object")
    files = [f for f in _entries(_list(data, "files", "files"), "files", {"path": _TEXT, "format": _TEXT})
             if inside(part_dir, f.get("path")) and "format" in f]
    media = data.get("media")
    media = {} if media is None else media
    _need(isinstance(media, dict), "media", media, "an object")
    shown = {}
    for kind, fields in MEDIA_FIELDS.items():
        entries = _entries(_list(media, kind, f"media.{kind}"), f"media.{kind}", fields)
        kept = []
        for e in entries:
            if not inside(part_dir, e.get("path")):
                continue
            if kind == "models" and not e["path"].endswith(MODEL_SUFFIX):
                continue
            e.pop("script", None)  # the GLB's script twin of older builds: never loaded
            lc = e.get("least_clearance_mm")
            if lc is not None and not math.isfinite(lc):
                del e["least_clearance_mm"]
            kept.append(e)
        shown[kind] = kept
    glossary = data.get("glossary")
    glossary = {k: {f: g[f] for f in ("unit", "meaning") if isinstance(g.get(f), str)}
                for k, g in (glossary.items() if isinstance(glossary, dict) else ()) if isinstance(g, dict)}
    return {"part": part, "title": title, "checks": checks, "expected_failures": list(expected),
            "derived": derived, "files": files, "media": shown, "glossary": glossary}


def load_manifest(part_dir: Path) -> dict:
    """The clean manifest of the part in `part_dir` (:func:`clean_manifest`); ManifestError when it
    cannot be read, is not JSON or has a field of the wrong type."""
    from ..policy import MANIFEST_MAX_BYTES
    from ..regular_file import read_regular

    try:
        raw = read_regular(part_dir / MANIFEST, MANIFEST_MAX_BYTES)
    except OSError as exc:
        raise ManifestError(exc.strerror or type(exc).__name__) from None
    except ValueError as exc:  # a FIFO, a device, a link, too large
        raise ManifestError(f"manifest.json {exc}") from None
    try:
        data = json.loads(raw.decode("utf-8"))
    except (ValueError, RecursionError) as exc:  # not UTF-8, not JSON, nested too deep
        raise ManifestError(f"not JSON: {str(exc).splitlines()[0] if str(exc) else type(exc).__name__}") from None
    return clean_manifest(data, part_dir)
