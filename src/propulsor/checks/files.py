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

Nothing is trusted: every file is read through checks.safe_read (regular files only, no symbolic
link followed inside a folder, sizes bounded by policy.READ_LIMIT_BYTES) and vetted by
checks.formats before a library parses it; whatever fails inside a file's check makes that file
invalid with a one-line reason.  A FIFO, device, socket or symbolic link leading out of the folder
is invalid without being opened.
"""

from __future__ import annotations

import io
import json
import os
import unicodedata
from pathlib import Path

import numpy as np

from ..errors import EnvironmentFailure
from ..policy import CHECK_MEMORY_CEILING, MESH_BOX_PAIRS_MAX, MESH_VOLUME_REL_TOL, STEP_VOLUME_REL_TOL
from . import formats
from .pages import check_html_file
from .result import Check
from .safe_read import Refused, opened, read_bytes, sha256_and_size, walk

MANIFEST = "manifest.json"

#: manifests parsed during one check, by (path, device, inode, size, mtime): each is read once
_MANIFESTS: dict[tuple, object] = {}


def load_manifest(path: Path):
    """The parsed manifest at `path` (read through safe_read), or None when it is missing, not a
    regular file, too large or malformed (its own check reports why)."""
    try:
        st = os.lstat(path)
    except OSError:
        return None
    key = (str(path), st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns)
    if key not in _MANIFESTS:
        try:
            data = json.loads(read_bytes(path, "manifest").decode("utf-8"))
        except (Refused, ValueError, RecursionError):
            data = None
        if len(_MANIFESTS) > 64:
            _MANIFESTS.clear()
        _MANIFESTS[key] = data
    return _MANIFESTS[key]


def _manifest_entry(file: Path) -> dict:
    """The manifest entry recorded for `file` (nearest manifest.json above it); {} when there is none
    or the manifest is malformed (the manifest's own check reports that)."""
    for folder in [file.parent, *file.parent.parents]:
        m = folder / MANIFEST
        if os.path.lexists(m):
            data = load_manifest(m)
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
        with opened(path, "step") as f:
            try:
                solids = read_step_solids(f.lib_path)
            except Exception as exc:  # noqa: BLE001 - any reader failure is a failed check
                raise Refused(str(exc).replace(f.lib_path, name)) from None
    except Refused as exc:
        return [Check.flag(f"{name}: STEP parses", False, str(exc))]
    out = [Check.flag(f"{name}: STEP parses", True, "read and transferred by OCCT"),
           Check.at_least(f"{name}: solids", len(solids), 1, "", "one or more solids")]
    entry = _manifest_entry(path)
    for k, s in enumerate(solids):
        for c in brep_checks(s, f"{name}: solid {k + 1}"):
            if c.name.endswith(": solids"):
                continue  # each item is one solid by construction
            out.append(c)
        out += _step_mesh_checks(s, f"{name}: solid {k + 1} mesh", entry.get("genus") if len(solids) == 1 else None)
    if "volume_mm3" in entry and solids:
        total = sum(volume(s) for s in solids)
        out.append(Check.equal_within(f"{name}: volume vs manifest", total, float(entry["volume_mm3"]), rel_tol=STEP_VOLUME_REL_TOL, unit="mm^3"))
    return out


def _step_mesh_checks(solid, name: str, genus) -> list[Check]:
    """The mesh checks on a STEP solid's own tessellation (what a slicer or a CAM package meshes): closed,
    oriented, one body, the genus the manifest records, no self-intersection, volume against the B-rep."""
    from ..export.mesh import tessellate
    from .brep import volume
    from .mesh import mesh_checks

    try:
        mesh = tessellate(solid, parallel=False)
    except Exception as exc:  # noqa: BLE001 - a solid OCCT cannot mesh is a failed check
        return [Check.flag(f"{name}: tessellates", False, _why(exc))]
    return mesh_checks(mesh, name, expected_genus=genus, brep_volume=volume(solid), max_box_pairs=MESH_BOX_PAIRS_MAX)


def check_mesh_file(path: Path) -> list[Check]:
    from ..export.mesh import load_mesh
    from .mesh import mesh_checks

    name = path.name
    kind = "3mf" if path.suffix.lower() == ".3mf" else "stl"
    try:
        data = read_bytes(path, kind)
        if kind == "stl":
            formats.stl_kind(data)
        else:
            formats.check_3mf_zip(data)
    except Refused as exc:
        return [Check.flag(f"{name}: loads", False, str(exc))]
    try:
        mesh = load_mesh(io.BytesIO(data), file_type=kind, max_pairs=MESH_BOX_PAIRS_MAX)
        del data
        if len(mesh.faces) == 0:
            raise ValueError("no triangles")
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: loads", False, _why(exc))]
    entry = _manifest_entry(path)
    out = [Check.flag(f"{name}: loads", True, f"{len(mesh.faces)} triangles, {len(mesh.vertices)} vertices")]
    out += mesh_checks(
        mesh,
        name,
        expected_volume=entry.get("volume_mm3"),
        expected_genus=entry.get("genus"),
        expected_bodies=entry.get("bodies"),
        volume_rel_tol=MESH_VOLUME_REL_TOL,
        max_box_pairs=MESH_BOX_PAIRS_MAX,
    )
    return out


def check_dxf_file(path: Path) -> list[Check]:
    import ezdxf

    from ..export.dxf import CUT, dxf_summary, polygon_area

    name = path.name
    try:
        with opened(path, "dxf") as f:
            doc = ezdxf.readfile(f.lib_path)
    except Refused as exc:
        return [Check.flag(f"{name}: DXF parses", False, str(exc))]
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: DXF parses", False, _why(exc))]
    try:
        formats.check_dxf_doc(doc)
    except Refused as exc:
        return [Check.flag(f"{name}: DXF within bounds", False, str(exc))]
    try:
        info = dxf_summary(doc)
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: DXF parses", False, _why(exc))]
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
        data = read_bytes(path, "glb")
        formats.check_glb(data)
    except Refused as exc:
        return [Check.flag(f"{name}: loads", False, str(exc))]
    try:
        scene = trimesh.load(io.BytesIO(data), file_type="glb", force="scene")
        del data
        nodes = sorted(scene.graph.nodes_geometry)
        if not nodes:
            raise ValueError("no mesh node")
    except Exception as exc:  # noqa: BLE001
        return [Check.flag(f"{name}: loads", False, _why(exc))]
    out = [Check.flag(f"{name}: loads", True, f"{len(nodes)} mesh nodes")]
    model = {}
    data = load_manifest(path.parent / MANIFEST)
    try:
        media = data.get("media", {}) if isinstance(data, dict) else {}
        model = next((e for e in media.get("models", []) if isinstance(e, dict) and e.get("path") == name), {})
    except (AttributeError, TypeError):
        model = {}
    if model.get("components"):
        out.append(Check.equals(f"{name}: nodes are the assembly's components", nodes, sorted(model["components"]), "",
                                "one named node per component of the assembly STEP"))
    step_name = model.get("step")
    if isinstance(step_name, str) and step_name and (Path(step_name).name != step_name or step_name == ".."):
        return out + [Check.flag(f"{name}: assembly STEP in the folder", False,
                                 f"the manifest names {step_name!r}, not a file beside {name}")]
    step = path.parent / str(step_name or "")
    if step_name and os.path.lexists(step):
        from ..export.step import read_step, step_instance_names
        from ..solids.kernel import bounding_box

        try:
            with opened(step, "step") as f:
                names = sorted(step_instance_names(f.lib_path))
                shape = read_step(f.lib_path)
        except Refused as exc:
            return out + [Check.flag(f"{name}: assembly STEP readable", False, f"{step.name} {exc}")]
        out.append(Check.equals(f"{name}: nodes are the STEP's components", nodes, names,
                                "", f"the component occurrences of {step.name}"))

        lo, hi = bounding_box(shape)
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


def _listed_file(p: Path, entry: dict, hashes: dict) -> str | None:
    """What is wrong with one listed file ('missing', 'size', 'sha256' or a reason), None when it is as
    recorded.  Hashes are taken once per path."""
    size = entry.get("bytes")
    size = size if isinstance(size, int) and not isinstance(size, bool) else None
    if p not in hashes:
        try:
            hashes[p] = sha256_and_size(p, size)
        except Refused as exc:
            hashes[p] = ("missing" if str(exc) == "no such file" else str(exc), -1)
    digest, got = hashes[p]
    if got < 0:
        return digest
    if size is None or got != size:
        return "size"
    return None if digest == entry.get("sha256") else "sha256"


def check_manifest_file(path: Path) -> list[Check]:
    """The manifest parses, and the folder holds exactly the files it lists, each with the recorded
    size and sha256 (a missing, changed or unreadable listed file makes the folder invalid)."""
    name = path.name
    folder = path.parent
    try:
        data = json.loads(read_bytes(path, "manifest").decode("utf-8"))
    except (Refused, ValueError, RecursionError) as exc:
        return [Check.flag(f"{name}: parses", False, str(exc) if isinstance(exc, Refused)
                           else _why(exc))]
    files, problems = _manifest_structure(data, folder)
    if problems:
        return [Check.flag(f"{name}: parses", False, "; ".join(problems))]
    out = [Check.flag(f"{name}: parses", True, f"{len(files)} files listed")]
    missing, wrong_size, wrong_hash, unreadable = [], [], [], []
    hashes: dict = {}
    for e in files:
        what = _listed_file(folder / e["path"], e, hashes)
        if what == "missing":
            missing.append(e["path"])
        elif what == "size":  # another size is another hash: both are reported
            wrong_size.append(e["path"])
            wrong_hash.append(e["path"])
        elif what == "sha256":
            wrong_hash.append(e["path"])
        elif what is not None:
            unreadable.append(f"{e['path']} ({what})")
    out.append(Check.equals(f"{name}: listed files missing", len(missing), 0, "", "missing: " + ", ".join(missing) if missing else "all listed files exist"))
    out.append(Check.equals(f"{name}: listed files unreadable", len(unreadable), 0, "",
                            ", ".join(unreadable) or "all listed files are regular files within the limit"))
    out.append(Check.equals(f"{name}: size mismatches", len(wrong_size), 0, "", ", ".join(wrong_size) or "sizes as recorded"))
    out.append(Check.equals(f"{name}: sha256 mismatches", len(wrong_hash), 0, "", ", ".join(wrong_hash) or "hashes as recorded"))
    listed = {e["path"] for e in files}
    present, _ = walk(folder)
    unlisted = [rel for rel in (q.relative_to(folder).as_posix() for q in present)
                if rel != MANIFEST and rel not in listed]
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
    ".html": check_html_file,
}


def _checker(name: str):
    return check_manifest_file if name == MANIFEST else CHECKERS.get(Path(name).suffix.lower())


def _why(exc: BaseException) -> str:
    """The reason a library's failure on a file gives: "out of memory" for a MemoryError (the check's
    address-space ceiling met), else the exception's name and text."""
    if isinstance(exc, MemoryError):
        return f"out of memory: checking it needs more than the ceiling of {CHECK_MEMORY_CEILING >> 20} MiB"
    return f"{type(exc).__name__}: {exc}"


def check_file(path: str | Path) -> list[Check]:
    """Checks of one file (empty list for formats without checks).  Never raises but
    EnvironmentFailure: a checker that fails on a malformed file makes that file invalid, with the
    reason."""
    p = Path(path)
    fn = _checker(p.name)
    if fn is None:
        return []
    try:
        return fn(p)
    except EnvironmentFailure:
        raise
    except Refused as exc:
        return [Check.flag(f"{p.name}: readable", False, str(exc))]
    except MemoryError as exc:
        return [Check.flag(f"{p.name}: readable", False, _why(exc))]
    except Exception as exc:  # noqa: BLE001 - whatever breaks on a malformed file is a failed check
        return [Check.flag(f"{p.name}: readable", False, _why(exc))]


def check_path(path: str | Path, progress=None) -> dict[str, list[Check]]:
    """Check a file or every checkable file under a folder: {path: checks}; {} when there is
    nothing to check (no STEP, STL, 3MF, DXF or manifest).  Symbolic links inside a folder are not
    followed (one leading out of it is invalid), FIFOs, devices and sockets are invalid unopened;
    the path given itself is followed when it is a symbolic link.  Raises EnvironmentFailure when
    the machine refuses to list or read.  `progress`: a progress.Reporter for the files' count."""
    p = Path(path)
    _MANIFESTS.clear()
    if not os.path.lexists(p):
        return {str(p): [Check.flag(f"{p}: exists", False, "no such file or folder")]}
    out: dict[str, list[Check]] = {}
    if not p.is_dir():
        if _checker(p.name) is not None:
            out[str(p)] = check_file(Path(os.path.realpath(p)))
        return out
    # `progress`: a progress.Reporter (called with a step, .count(phase, done, total, unit)) or None; duck-typed,
    # the checks sit below the progress layer
    count = getattr(progress, "count", None)
    if progress is not None:
        progress(f"check: reading {p}")
    files, bad = walk(p)
    files = [f for f in files if _checker(f.name) is not None]  # the formats with checks (check_file: [] else)
    phase = f"check: {len(files)} file(s) to check under {p}"
    if count is not None:
        count(phase, 0, len(files), "file")
    for k, f in enumerate(files, start=1):
        cks = check_file(f)
        if count is not None:
            count(phase, k, len(files), "file")
        if cks:
            out[str(f)] = cks
    for f, why in bad.items():
        out[str(f)] = [Check.flag(f"{f.name}: regular file in the folder", False, why)]
    return dict(sorted(out.items()))


def _escaped(ch: str) -> bool:
    cat = unicodedata.category(ch)
    return cat[0] == "C" or cat in ("Zl", "Zp")


def one_line(text) -> str:
    """`text` with control, format and line-separator characters escaped (file names and manifest
    text are data: they never start a line of their own nor move the cursor)."""
    s = str(text)
    if not any(_escaped(ch) for ch in s):
        return s
    return "".join((f"\\x{ord(ch):02x}" if ord(ch) < 0x100 else f"\\u{ord(ch):04x}" if ord(ch) < 0x10000
                    else f"\\U{ord(ch):08x}") if _escaped(ch) else ch for ch in s)


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
        lines.append(f"{'FAIL' if bad else 'PASS'} {one_line(path)} ({len(cks)} checks)")
        for c in cks if verbose else bad:
            lines.append(f"    {one_line(c)}")
    n, failed = summary(results)
    lines.append(f"{len(results)} files, {n} checks, {failed} failed")
    return "\n".join(lines)
