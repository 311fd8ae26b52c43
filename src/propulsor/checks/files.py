"""Checks of output files already on disk (`propulsor check PATH`).

For a folder (recursively) or one file:
* STEP: parses, holds one or more solids, each valid with closed shells and
  positive volume; total volume equals the manifest's `volume_mm3` for the file
  (policy.STEP_VOLUME_REL_TOL) when the manifest records one (in the file's
  entry, or as derived value '<file stem>_volume_mm3');
* STL / 3MF: loads; watertight, consistently wound, positive volume, no
  self-intersection (checks.mesh); bodies / genus / volume against the manifest
  entry's `bodies`, `genus`, `volume_mm3` when recorded;
* DXF: parses, $INSUNITS = 4 (mm), layer CUT holds closed loops only, each with
  at least three points and non-zero area;
* manifest.json: every listed file exists with the recorded size and sha256,
  every file of the folder is listed, the recorded checks all passed.
Returns {file path: [Check, ...]}, files in sorted order.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..policy import MESH_VOLUME_REL_TOL, STEP_VOLUME_REL_TOL
from .result import Check

MANIFEST = "manifest.json"


def _manifest_entry(file: Path) -> dict:
    """The manifest entry recorded for `file` (nearest manifest.json above it); {} when there is none
    or the manifest is malformed (the manifest's own check reports that)."""
    for folder in [file.parent, *file.parent.parents]:
        m = folder / MANIFEST
        if m.is_file():
            try:
                data = json.loads(m.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                return {}
            if not isinstance(data, dict) or not isinstance(data.get("files"), list):
                return {}
            rel = file.relative_to(folder).as_posix()
            entry = next((dict(e) for e in data["files"] if isinstance(e, dict) and e.get("path") == rel), {})
            entry = {k: v for k, v in entry.items() if k not in _NUMERIC_KEYS or _is_number(v)}
            # the part writer records solid volumes as derived '<stem>_volume_mm3'
            derived = data.get("derived", {})
            key = f"{file.stem}_volume_mm3"
            if "volume_mm3" not in entry and isinstance(derived, dict) and _is_number(derived.get(key)):
                entry["volume_mm3"] = derived[key]
            return entry
    return {}


#: manifest entry keys that must be numbers to be used
_NUMERIC_KEYS = ("volume_mm3", "genus", "bodies", "bytes")


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_step_file(path: Path) -> list[Check]:
    from ..export.step import read_step_solids
    from .brep import brep_checks, volume

    name = path.name
    try:
        solids = read_step_solids(path)
    except Exception as exc:  # noqa: BLE001 - any reader failure is a failed check
        return [Check.flag(f"{name}: STEP parses", False, str(exc))]
    out = [Check.flag(f"{name}: STEP parses", True, "read and transferred by OCCT"),
           Check.at_least(f"{name}: solids", len(solids), 1, "", "one or more solids")]
    for k, s in enumerate(solids):
        for c in brep_checks(s, f"{name}: solid {k + 1}"):
            if c.name.endswith(": solids"):
                continue  # each item is one solid by construction
            out.append(c)
    entry = _manifest_entry(path)
    if "volume_mm3" in entry and solids:
        total = sum(volume(s) for s in solids)
        out.append(Check.equal_within(f"{name}: volume vs manifest", total, float(entry["volume_mm3"]), rel_tol=STEP_VOLUME_REL_TOL, unit="mm^3"))
    return out


def check_mesh_file(path: Path) -> list[Check]:
    from ..export.mesh import load_mesh
    from .mesh import mesh_checks

    name = path.name
    try:
        mesh = load_mesh(path)
        if len(mesh.faces) == 0:
            raise ValueError("no triangles")
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: loads", False, f"{type(exc).__name__}: {exc}")]
    entry = _manifest_entry(path)
    out = [Check.flag(f"{name}: loads", True, f"{len(mesh.faces)} triangles, {len(mesh.vertices)} vertices")]
    out += mesh_checks(
        mesh,
        name,
        expected_volume=entry.get("volume_mm3"),
        expected_genus=entry.get("genus"),
        expected_bodies=entry.get("bodies"),
        volume_rel_tol=MESH_VOLUME_REL_TOL,
    )
    return out


def check_dxf_file(path: Path) -> list[Check]:
    from ..export.dxf import CUT, polygon_area, read_dxf

    name = path.name
    try:
        info = read_dxf(path)
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: DXF parses", False, f"{type(exc).__name__}: {exc}")]
    out = [Check.flag(f"{name}: DXF parses", True, f"DXF {info['version']}")]
    out.append(Check.equals(f"{name}: $INSUNITS", info["insunits"], 4, "", "drawing units millimetres (4)"))
    cut = info["layers"].get(CUT, {"loops": [], "open": []})
    out.append(Check.at_least(f"{name}: closed loops on {CUT}", len(cut["loops"]), 1, "", "the outline to cut"))
    out.append(Check.equals(f"{name}: open entities on {CUT}", len(cut["open"]), 0, "", "every cut contour closed"))
    bad = [k for k, p in enumerate(cut["loops"]) if len(p) < 3 or abs(polygon_area(np.asarray(p))) <= 0.0]
    out.append(Check.equals(f"{name}: degenerate {CUT} loops", len(bad), 0, "", "each loop >= 3 points, non-zero area"))
    return out


def check_glb_file(path: Path) -> list[Check]:
    """An assembly's GLB: loads with trimesh as a scene; its mesh nodes are the components of the
    assembly STEP beside it (the manifest's ``media.models`` entry) and the scene is in metres (the
    STEP's extent in millimetres × 0.001, whatever the axes' order)."""
    import numpy as np
    import trimesh

    name = path.name
    try:
        scene = trimesh.load(path, force="scene")
        nodes = sorted(scene.graph.nodes_geometry)
        if not nodes:
            raise ValueError("no mesh node")
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: loads", False, f"{type(exc).__name__}: {exc}")]
    out = [Check.flag(f"{name}: loads", True, f"{len(nodes)} mesh nodes")]
    model = {}
    m = path.parent / MANIFEST
    try:
        media = json.loads(m.read_text(encoding="utf-8")).get("media", {}) if m.is_file() else {}
        model = next((e for e in media.get("models", []) if isinstance(e, dict) and e.get("path") == name), {})
    except (OSError, ValueError, AttributeError):
        model = {}
    if model.get("components"):
        out.append(Check.equals(f"{name}: nodes are the assembly's components", nodes, sorted(model["components"]), "",
                                "one named node per component of the assembly STEP"))
    step = path.parent / str(model.get("step", ""))
    if model.get("step") and step.is_file():
        from ..export.step import read_step, step_instance_names
        from ..solids.kernel import bounding_box

        out.append(Check.equals(f"{name}: nodes are the STEP's components", nodes, sorted(step_instance_names(step)),
                                "", f"the component occurrences of {step.name}"))

        lo, hi = bounding_box(read_step(step))
        want = np.sort(np.asarray(hi, float) - np.asarray(lo, float)) * 1e-3
        got = np.sort(np.asarray(scene.extents, float))
        out.append(Check.at_most(f"{name}: extent vs the STEP in metres", float(np.max(np.abs(got - want))), 1e-4, "m",
                                 "glTF is in metres: the STEP's mm × 0.001"))
    return out


def _manifest_structure(data, folder: Path) -> tuple[list[dict], list[str]]:
    """The well-formed file entries of a manifest and what is wrong with the rest."""
    problems = []
    if not isinstance(data, dict):
        return [], [f"is a JSON {type(data).__name__}, not an object"]
    for key, typ in (("part", str), ("files", list), ("checks", list), ("expected_failures", list)):
        if key not in data and key in ("expected_failures",):
            continue
        if not isinstance(data.get(key), typ):
            problems.append(f"'{key}' is missing or not a {typ.__name__}")
    entries = []
    root = folder.resolve()
    for k, e in enumerate(data.get("files") if isinstance(data.get("files"), list) else []):
        path = e.get("path") if isinstance(e, dict) else None
        if not isinstance(path, str) or not path:
            problems.append(f"files[{k}] has no 'path'")
        elif Path(path).is_absolute() or root not in (root / path).resolve().parents:
            problems.append(f"files[{k}] path {path!r} leaves the folder")
        else:
            entries.append(e)
    return entries, problems


def check_manifest_file(path: Path) -> list[Check]:
    from ..export.manifest import file_entries, sha256_of

    name = path.name
    folder = path.parent
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        return [Check.flag(f"{name}: parses", False, f"{type(exc).__name__}: {exc}")]
    files, problems = _manifest_structure(data, folder)
    if problems:
        return [Check.flag(f"{name}: parses", False, "; ".join(problems))]
    out = [Check.flag(f"{name}: parses", True, f"{len(files)} files listed")]
    missing, wrong_size, wrong_hash = [], [], []
    for e in files:
        p = folder / e["path"]
        if not p.is_file():
            missing.append(e["path"])
            continue
        if p.stat().st_size != e.get("bytes"):
            wrong_size.append(e["path"])
        if sha256_of(p) != e.get("sha256"):
            wrong_hash.append(e["path"])
    out.append(Check.equals(f"{name}: listed files missing", len(missing), 0, "", "missing: " + ", ".join(missing) if missing else "all listed files exist"))
    out.append(Check.equals(f"{name}: size mismatches", len(wrong_size), 0, "", ", ".join(wrong_size) or "sizes as recorded"))
    out.append(Check.equals(f"{name}: sha256 mismatches", len(wrong_hash), 0, "", ", ".join(wrong_hash) or "hashes as recorded"))
    listed = {e["path"] for e in files}
    unlisted = [e["path"] for e in file_entries(folder) if e["path"] not in listed]
    out.append(Check.equals(f"{name}: unlisted files", len(unlisted), 0, "", ", ".join(unlisted) or "every file listed"))
    documented = {f for f in data.get("expected_failures", []) if isinstance(f, str)}
    failed = [c.get("name") if isinstance(c, dict) else repr(c) for c in data["checks"]
              if not (isinstance(c, dict) and c.get("passed") is True)]
    unexpected = [f for f in failed if f not in documented]
    known = [f for f in failed if f in documented]
    msg = "; ".join(map(str, unexpected)) or "all recorded checks passed"
    if known:
        msg += f" ({len(known)} documented as expected failures in the part file: {'; '.join(map(str, known))})"
    out.append(Check.equals(f"{name}: recorded failed checks", len(unexpected), 0, "", msg))
    return out


CHECKERS = {
    ".step": check_step_file,
    ".stp": check_step_file,
    ".stl": check_mesh_file,
    ".3mf": check_mesh_file,
    ".dxf": check_dxf_file,
    ".glb": check_glb_file,
}


def check_file(path: str | Path) -> list[Check]:
    """Checks of one file (empty list for formats without checks).  Never raises: a checker that
    fails on a malformed file makes that file invalid, with the reason."""
    p = Path(path)
    fn = check_manifest_file if p.name == MANIFEST else CHECKERS.get(p.suffix.lower())
    if fn is None:
        return []
    try:
        return fn(p)
    except Exception as exc:  # noqa: BLE001 - whatever breaks on a malformed file is a failed check
        return [Check.flag(f"{p.name}: readable", False, f"{type(exc).__name__}: {exc}")]


def check_path(path: str | Path) -> dict[str, list[Check]]:
    """Check a file or every checkable file under a folder: {path: checks}; {} when there is
    nothing to check (no STEP, STL, 3MF, DXF or manifest)."""
    p = Path(path)
    if not p.exists():
        return {str(p): [Check.flag(f"{p}: exists", False, "no such file or folder")]}
    files = [p] if p.is_file() else sorted(q for q in p.rglob("*") if q.is_file())
    out: dict[str, list[Check]] = {}
    for f in files:
        cks = check_file(f)
        if cks:
            out[str(f)] = cks
    return out


def summary(results: dict[str, list[Check]]) -> tuple[int, int]:
    """(number of checks, number failed) over all files."""
    n = sum(len(v) for v in results.values())
    failed = sum(not c.passed for v in results.values() for c in v)
    return n, failed


def format_results(results: dict[str, list[Check]], verbose: bool = False) -> str:
    """Text for the command line: per file a PASS/FAIL line, failed checks (all
    checks when verbose) indented below, then one summary line."""
    lines = []
    for path, cks in results.items():
        bad = [c for c in cks if not c.passed]
        lines.append(f"{'FAIL' if bad else 'PASS'} {path} ({len(cks)} checks)")
        for c in cks if verbose else bad:
            lines.append(f"    {c}")
    n, failed = summary(results)
    lines.append(f"{len(results)} files, {n} checks, {failed} failed")
    return "\n".join(lines)
