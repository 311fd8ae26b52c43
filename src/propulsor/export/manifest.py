"""manifest.json: what a part folder holds and how it was made (docs/architecture.md, "The data flow of one build").

Keys: part, inputs, derived, glossary (the unit and meaning of every derived value, by path:
``name``, ``name.key`` in a dict, ``name[].key`` in the dicts of a list), checks (list of {name, passed, value, limit, unit,
message}), files (every file in the folder but the manifest itself: {path,
format, bytes, sha256}, sorted by path), versions.  No time stamps; keys sorted;
numpy values converted; non-finite floats written as strings ('nan', 'inf').
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import platform
from pathlib import Path

import numpy as np

from ..write_root import prepare

MANIFEST = "manifest.json"

FORMATS = {
    ".step": "STEP",
    ".stp": "STEP",
    ".stl": "STL",
    ".3mf": "3MF",
    ".dxf": "DXF",
    ".csv": "CSV",
    ".png": "PNG",
    ".gif": "GIF",
    ".svg": "SVG",
    ".pdf": "PDF",
    ".md": "Markdown",
    ".json": "JSON",
    ".toml": "TOML",
    ".txt": "text",
    ".glb": "GLB",
    ".js": "JavaScript",
    ".html": "HTML",
}

_PACKAGES = ("numpy", "scipy", "cadquery", "manifold3d", "trimesh", "ezdxf", "matplotlib", "pillow", "markdown")


def jsonable(v):
    """Convert numpy / dataclass / Path / Check values into JSON-safe Python values."""
    if hasattr(v, "to_dict") and callable(v.to_dict):
        return jsonable(v.to_dict())
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {f.name: jsonable(getattr(v, f.name)) for f in dataclasses.fields(v)}
    if isinstance(v, dict):
        return {str(k): jsonable(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [jsonable(x) for x in v]
    if isinstance(v, np.ndarray):
        return jsonable(v.tolist())
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        f = float(v)
        return f if math.isfinite(f) else repr(f)
    if v is None or isinstance(v, str):
        return v
    if isinstance(v, Path):
        return v.as_posix()
    return str(v)


def sha256_of(path: str | Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def file_entries(folder: str | Path, exclude=(MANIFEST,)) -> list[dict]:
    """{path (relative, posix), format, bytes, sha256} for every file under folder."""
    folder = Path(folder)
    out = []
    for p in sorted(folder.rglob("*"), key=lambda q: q.relative_to(folder).as_posix()):
        rel = p.relative_to(folder).as_posix()
        if not p.is_file() or rel in exclude:
            continue
        out.append(
            {
                "path": rel,
                "format": FORMATS.get(p.suffix.lower(), p.suffix.lower().lstrip(".") or "unknown"),
                "bytes": p.stat().st_size,
                "sha256": sha256_of(p),
            }
        )
    return out


def library_versions() -> dict:
    """Versions of Python and the libraries that shape the outputs."""
    from importlib import metadata

    from ..version import __version__

    v = {"python": platform.python_version(), "propulsor": __version__}
    for name in _PACKAGES:
        try:
            v[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            v[name] = None
    try:
        import OCP

        v["OCP"] = getattr(OCP, "__version__", None) or metadata.version("cadquery-ocp")
    except Exception:  # noqa: BLE001 - a missing OCP is recorded, not fatal
        v["OCP"] = None
    return v


def write_manifest(folder: str | Path, part: str, inputs, derived, checks, versions: dict | None = None,
                   file_info: dict | None = None, expected_failures=(), media: dict | None = None,
                   title: str | None = None, glossary: dict | None = None) -> Path:
    """Write folder/manifest.json; file_info adds keys to file entries by
    relative path (e.g. {'gear.step': {'volume_mm3': ...}}); versions default
    to library_versions().  expected_failures: names of checks the part file
    documents as failing (they are recorded, and do not make `passed` false).  media: what the
    gallery shows ({kind: [entry, ...]}, e.g. 'animations', 'models', 'pictures'; each entry a dict
    with at least 'path'), written under the key ``media`` when not empty.  title: the part file's
    ``[meta] title`` (the gallery's heading), written when given.  glossary: {path: {"unit", "meaning"}}
    of every derived value (export.glossary), written when given."""
    folder = Path(folder)
    prepare(folder / MANIFEST)
    files = file_entries(folder)
    for entry in files:
        extra = (file_info or {}).get(entry["path"])
        if extra:
            entry.update(jsonable(extra))
    data = {
        "part": part,
        "inputs": jsonable(inputs),
        "derived": jsonable(derived),
        "checks": [jsonable(c) for c in checks],
        "expected_failures": sorted(expected_failures),
        "passed": all(bool(jsonable(c).get("passed")) or jsonable(c).get("name") in set(expected_failures)
                      for c in checks),
        "files": files,
        "versions": jsonable(versions if versions is not None else library_versions()),
    }
    if title is not None:
        data["title"] = str(title)
    if glossary is not None:
        data["glossary"] = jsonable(glossary)
    if media:
        data["media"] = jsonable({k: v for k, v in media.items() if v})
    path = folder / MANIFEST
    path.write_text(json.dumps(data, indent=2, sort_keys=True, allow_nan=False) + "\n", encoding="utf-8")
    return path


def read_manifest(path: str | Path) -> dict:
    p = Path(path)
    if p.is_dir():
        p = p / MANIFEST
    return json.loads(p.read_text(encoding="utf-8"))
