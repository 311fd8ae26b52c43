"""output/index.html: one page for every part built in an output folder.

Reads the manifests and the files beside them only (every ``*/manifest.json``; a print kit
``<name>_kit/`` is shown with its part ``<name>/``): each part with its title, its status (checks
passed / documented failures / failed, with counts), a few key derived values with units, the
animations (``media.animations``), an interactive 3D view of the assembly (``media.models``: the
GLB read, checked and carried on the page as a data block, drawn by ``web/viewer.js`` with the vendored
three.js, both inlined; viewer_page.py), the pictures (``media.pictures``), links to
the HTML report, the files by format and the print kit.  The page is self-contained (inline style
and script, relative links), so it works opened from disk, with no network.

Every text from a manifest (titles, names, values) is escaped; every path it names is linked only
when it is relative, inside that part's folder and an existing regular file (gallery_manifest.py),
and written percent-encoded.  A manifest that cannot be read, or has a field of the wrong type, is a
note on the page ("output/<name>: manifest not readable: <reason>"); the other parts are shown.

Deterministic: the same manifests give the same bytes (folders sorted, no time stamp).  Written
through a temporary file and one rename; never over an ``index.html`` that propulsor did not write.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Iterator
from html import escape
from pathlib import Path
from urllib.parse import quote

from .gallery_manifest import ManifestError, inside, load_manifest
from .html import page_pieces, write_atomically
from .manifest import MANIFEST
from .gallery_values import SECTOR_WHY, failed_names, label, names_text, position_title, value_text
from .viewer_page import VIEWER_STYLE, viewer_figure, viewer_script  # noqa: F401  (viewer_script: public here too)

INDEX = "index.html"
#: the mark of a page propulsor wrote (an index.html without it is never replaced)
GENERATOR = '<meta name="generator" content="propulsor">'

#: key derived values per part type: name patterns (regular expressions), the first match of each shown
KEY_VALUES = {
    "noncircular_pair": [r"law", r"method", r"center_distance_mm", r"module_mm", r"driver_teeth", r"driven_teeth",
                         r"speed_ripple", r"ratio_min", r"ratio_max", r"backlash_min_mm", r"te_pp_rad",
                         r"contact_ratio_mean"],
    "planetary_final_drive": [r"ratio_i_1H", r"a_w_sun_planet_mm", r"epsilon_alpha_sun_planet",
                              r"epsilon_alpha_planet_ring", r"strength_sun_planet_S_H", r"strength_planet_ring_S_H",
                              r"coaxiality_mismatch_mm", r"design_torque_carrier_Nm"],
    "cam_mover": [r"law", r"hub_height_mean_mm", r"hub_height_variation_exact_mm", r"hub_speed_variation_pct",
                  r"sigma_max_support_MPa", r"neighbour_clearance_min_mm", r"roller_overlap_max_mm2"],
    "balancer": [r"beta0_deg", r"beta_m_deg", r"f_dyn_mm", r"mass_balancer_kg", r"min_clearance_overall_mm",
                 r"sigma_vM_body_elastic_built_MPa", r"damper_heat_max_steady_rise_K"],
    "road_wheel": [r"tyre_radius_mm", r"mass_wheel_kg", r"load_per_row_N", r"peak_pressure_q_m_MPa",
                   r"T_at_V_max_C"],
    "polysector_gear": [r"offset_max_mm", r"z_cond_max", r"z_c_eq2", r"r_blank_mm", r"r_gear_mm",
                        r"epsilon_alpha_blank_gear"],
}
#: how many derived values a part type without a list shows (its first scalar ones)
DEFAULT_KEY_VALUES = 6
#: the file formats linked, in this order
FILE_FORMATS = ("STEP", "STL", "3MF", "DXF", "CSV", "GLB")

STYLE = """
header { border-bottom: 1px solid var(--line); margin-bottom: 8px; }
nav ul { list-style: none; padding: 0; margin: 6px 0; display: flex; flex-wrap: wrap; gap: 4px 14px; }
section.part { border: 1px solid var(--line); border-radius: 8px; padding: 4px 14px 14px; margin: 18px 0; }
.sub { color: var(--muted); margin: 0 0 6px; }
.badge { display: inline-block; border-radius: 10px; padding: 1px 9px; color: #fff; font-size: 0.85em;
         font-weight: 600; }
.badge.ok { background: var(--ok); } .badge.doc { background: var(--doc); } .badge.bad { background: var(--bad); }
dl.values { display: grid; grid-template-columns: fit-content(62%) 1fr; gap: 2px 12px; margin: 8px 0; }
dl.values dt { color: var(--muted); } dl.values dd { margin: 0; }
.media { display: grid; grid-template-columns: repeat(auto-fill, minmax(140px, 1fr)); gap: 10px; }
.media.anim { display: flex; flex-wrap: wrap; gap: 10px; } .media.anim figure { max-width: 100%; }
.media figure { margin: 0; }
figure img { display: block; border: 1px solid var(--line); border-radius: 4px; background: #fff; }
figcaption { font-size: 0.85em; color: var(--muted); }
.links a { margin-right: 10px; white-space: nowrap; }
details { margin: 4px 0; } summary { cursor: pointer; }
.files a { display: inline-block; margin-right: 10px; }
.kit { border-top: 1px dashed var(--line); margin-top: 12px; }
.unreadable { color: var(--bad); }
"""


def built_parts(folder: str | Path) -> list[dict]:
    """Every built part under `folder` (every sub-folder with a manifest.json): {name, manifest (the
    clean manifest, gallery_manifest.py), kit (name, manifest) or None, error (why the manifest is not
    shown) or None}, sorted by name; a kit whose part is not built is an entry of its own."""
    folder = Path(folder)
    found: dict[str, tuple[dict | None, str | None]] = {}
    for d in sorted(folder.iterdir()):
        if d.name.startswith(".") or not d.is_dir() or not (d / MANIFEST).exists():
            continue
        try:
            found[d.name] = (load_manifest(d), None)
        except ManifestError as exc:
            found[d.name] = (None, str(exc))
    out = []
    for name, (m, error) in found.items():
        if name.endswith("_kit") and name[:-4] in found and found[name[:-4]][0] is not None and m is not None:
            continue
        kit_name = f"{name}_kit"
        kit = None
        if m is not None and not name.endswith("_kit") and kit_name in found and found[kit_name][0] is not None:
            kit = (kit_name, found[kit_name][0])
        out.append({"name": name, "manifest": m, "kit": kit, "error": error})
    return out


def status(manifest: dict) -> tuple[str, str]:
    """(css class, text): every check passed / documented failures / failed, with counts and the names
    of the checks that failed."""
    checks = [c for c in manifest.get("checks", []) if isinstance(c, dict)]
    bad, documented = failed_names(manifest)
    n = len(checks)
    if bad:
        return "bad", (f"failed: {len(bad)} of {n} checks: {names_text(bad)}"
                       + (f" (documented: {names_text(documented)})" if documented else ""))
    if documented:
        return "doc", f"documented failures: {len(documented)} of {n} checks: {names_text(documented)} (the part file lists them)"
    return "ok", f"all {n} checks passed"


def key_values(manifest: dict) -> list[tuple[str, str, str]]:
    """(label, value, unit) of the part type's key derived values that the manifest holds: labelled from
    the manifest's glossary (else the name), rounded for a reader (gallery_values.py); a ripple (a fraction)
    in per cent."""
    derived = manifest.get("derived")
    derived = derived if isinstance(derived, dict) else {}
    patterns = KEY_VALUES.get(manifest.get("part", ""))
    names: list[str] = []
    if patterns:
        for pat in patterns:
            hit = next((k for k in derived if re.fullmatch(pat, k) and k not in names), None)
            if hit is not None:
                names.append(hit)
    else:
        names = [k for k, v in derived.items() if isinstance(v, (int, float, str))][:DEFAULT_KEY_VALUES]
    glossary = manifest.get("glossary") or {}
    sectors = manifest.get("part") == "noncircular_pair" and derived.get("method") == "sectors"
    why = SECTOR_WHY if sectors else None
    out = []
    for k in names:
        text, unit = label(k, glossary)
        v = derived[k]
        if not unit and "ripple" in k and isinstance(v, float) and math.isfinite(v):  # a fraction: in per cent
            out.append((text, value_text(100.0 * v), "%"))
            continue
        out.append((text, value_text(v, manifest.get("part", ""), why), unit))
    return out


def _url(path: str) -> str:
    """A relative path as an address: every character but letters, digits, ``/ - . _ ~`` percent-encoded
    (a ``:`` never makes it a scheme, a ``#`` or ``?`` stays part of the name)."""
    return quote(path, safe="/")


def _a(href: str, text: str) -> str:
    return f'<a href="{escape(_url(href))}">{escape(text)}</a>'


def _size(n) -> str:
    n = float(n)
    return f"{n / 1e6:.1f} MB" if n >= 1e6 else f"{n / 1e3:.0f} kB"


def _figure(src: str, caption: str, width=None, height=None) -> str:
    wh = f' width="{int(width)}" height="{int(height)}"' if width and height else ""
    return (f'<figure><img src="{escape(_url(src))}" alt="{escape(caption)}"{wh}>'
            f"<figcaption>{escape(caption)}</figcaption></figure>")


def _animation(name: str, e: dict) -> str:
    """An animation at its own size (narrower only on a narrower screen), linked to its file."""
    bits = [str(e.get("title") or Path(e["path"]).stem)]
    if e.get("frames"):
        bits.append(f"{e['frames']} frames")
    if e.get("width_px") and e.get("height_px"):
        bits.append(f"{e['width_px']} × {e['height_px']} px")
    if e.get("bytes"):
        bits.append(_size(e["bytes"]))
    lc = e.get("least_clearance_mm")
    if isinstance(lc, (int, float)) and math.isfinite(lc):
        bits.append(f"least clearance {lc:.3g} mm")
    src, caption = f"{name}/{e['path']}", ", ".join(bits)
    w, h = e.get("width_px"), e.get("height_px")
    wh = f' width="{int(w)}" height="{int(h)}"' if w and h else ""
    return (f'<figure><a href="{escape(_url(src))}"><img src="{escape(_url(src))}" alt="{escape(caption)}"{wh}></a>'
            f"<figcaption>{escape(caption)} · {_a(src, 'full size')}</figcaption></figure>")


def _viewer(folder: Path, name: str, models: list[dict], manifest: dict, budget: dict) -> str:
    """The 3D view of the part's assemblies (a polysector gear's positions named by offset and ratio), its
    GLBs carried as data blocks within the page's `budget`."""
    titles = [position_title(manifest, k) for k in range(len(models))]
    what = "position" if manifest.get("part") == "polysector_gear" else "assembly"
    return viewer_figure(models, f"{name}/", titles, what, folder=folder / name, budget=budget)


def _files(name: str, manifest: dict) -> str:
    by_format: dict[str, list[str]] = {}
    for f in manifest.get("files", []):
        if isinstance(f, dict) and f.get("format") in FILE_FORMATS:
            by_format.setdefault(f["format"], []).append(f["path"])
    rows = []
    for fmt in FILE_FORMATS:
        paths = by_format.get(fmt)
        if paths:
            links = "".join(_a(f"{name}/{p}", p) for p in paths)
            rows.append(f'<details><summary>{fmt} ({len(paths)})</summary><div class="files">{links}</div></details>')
    return "".join(rows)


def _is_kit(folder: Path, name: str) -> bool:
    """A print kit's folder: ``<part>_kit``, or one a kit was built into under another name (``propulsor print
    --out``), known by its report ``print_report.md``."""
    return name.endswith("_kit") or inside(folder / name, "print_report.md") is not None


def _report_links(name: str, folder: Path, stem: str) -> str:
    """The report (HTML, then its Markdown), a kit's print guide, and the manifest."""
    links = []
    if inside(folder / name, f"{stem}.html"):
        links.append(_a(f"{name}/{stem}.html", "report"))
    if stem == "print_report" and inside(folder / name, "print_guide.html"):
        links.append(_a(f"{name}/print_guide.html", "print guide"))
    if inside(folder / name, f"{stem}.md"):
        links.append(_a(f"{name}/{stem}.md", f"{stem}.md"))
    links.append(_a(f"{name}/{MANIFEST}", MANIFEST))
    return '<p class="links">' + "".join(links) + "</p>"


def _kit_media(kit_name: str, m: dict) -> list[str]:
    """A kit's plates (3MF) and pictures (``plots/*.png``), as its manifest lists them."""
    files = [f for f in m.get("files", []) if isinstance(f, dict) and isinstance(f.get("path"), str)]
    pics = [f["path"] for f in files if f.get("format") == "PNG" and f["path"].startswith("plots/")]
    plates = [f["path"] for f in files if f.get("format") == "3MF" and "/" not in f["path"]]
    out = []
    if plates:
        out.append('<p class="links">plates: ' + "".join(_a(f"{kit_name}/{p}", p) for p in plates) + "</p>")
    if pics:
        out.append('<div class="media">' + "".join(_figure(f"{kit_name}/{p}", Path(p).stem.replace("_", " "))
                                                     for p in pics) + "</div>")
    return out


def _kit(folder: Path, kit_name: str, m: dict) -> str:
    cls, text = status(m)
    out = [f'<div class="kit"><h3>Print kit: {_a(kit_name + "/", kit_name)}</h3>',
           f'<p><span class="badge {cls}">{escape(text)}</span></p>', _report_links(kit_name, folder, "print_report")]
    out += _kit_media(kit_name, m)
    out.append("</div>")
    return "".join(out)


def _section(folder: Path, entry: dict, budget: dict) -> str:
    name, m = entry["name"], entry["manifest"]
    media = m["media"]
    cls, text = status(m)
    title = m.get("title") or name
    out = [f'<section class="part" id="{escape(name)}">', f"<h2>{escape(title)}</h2>",
           f'<p class="sub">{_a(name + "/", name + "/")} · part type <code>{escape(m["part"])}</code> · '
           f'<span class="badge {cls}">{escape(text)}</span></p>']
    values = key_values(m)
    if values:
        out.append('<dl class="values">' + "".join(
            f"<dt>{escape(k)}</dt><dd>{escape(v)}{('&nbsp;' + escape(u)) if u and not v.startswith('—') else ''}</dd>"
            for k, v, u in values) + "</dl>")
    kit = _is_kit(folder, name)
    out.append(_report_links(name, folder, "print_report" if kit else "report"))
    if kit:  # a kit without its part: its plates and pictures here
        out += _kit_media(name, m)
    anims = media["animations"]
    if anims:
        out.append("<h3>Motion</h3><div class=\"media anim\">" + "".join(_animation(name, e) for e in anims) + "</div>")
    models = media["models"]
    out.append(_viewer(folder, name, models, m, budget))
    pics = media["pictures"]
    if pics:
        out.append("<h3>Pictures</h3><div class=\"media\">" + "".join(
            _figure(f"{name}/{e['path']}", str(e.get("title", e["path"]))) for e in pics) + "</div>")
    files = _files(name, m)
    if files:
        out.append("<h3>Files</h3>" + files)
    if entry["kit"]:
        out.append(_kit(folder, *entry["kit"]))
    out.append("</section>")
    return "\n".join(x for x in out if x)


def _unreadable(folder: Path, entry: dict) -> str:
    """The note of a part whose manifest is not shown: where, and why."""
    where = f"{folder.name}/{entry['name']}"
    return f'<p class="unreadable">{escape(where)}: manifest not readable: {escape(entry["error"])}</p>'


def render_gallery(folder: str | Path) -> str:
    """The page (HTML text) of every built part in `folder` (and of its design studies: gallery_studies.py)."""
    return "".join(gallery_pieces(folder))


def gallery_pieces(folder: str | Path) -> Iterator[str]:
    """:func:`render_gallery` in pieces (html.page_pieces), each part's section made when its turn comes: the page
    (some 40 MB for make's parts, their 3D models in it) is written without the whole of it in memory."""
    from .gallery_studies import STYLE as STUDY_STYLE, found_studies, studies_section

    folder = Path(folder)
    found = built_parts(folder)
    studies = found_studies(folder)
    parts = [e for e in found if e["manifest"] is not None]
    counts = {"ok": 0, "doc": 0, "bad": 0}
    for e in parts:
        counts[status(e["manifest"])[0]] += 1
    head = ["<header><h1>propulsor: built parts</h1>",
            f'<p class="sub">{len(parts)} part(s) in this folder: {counts["ok"]} with every check passed, '
            f'{counts["doc"]} with documented failures, {counts["bad"]} failed.  Each part\'s report, files and '
            "print kit are linked below; the 3D views turn with the mouse.</p>"]
    head += [_unreadable(folder, e) for e in found if e["manifest"] is None]
    nav = [f'<li><a href="#{escape(_url(e["name"]))}">{escape(e["name"])}</a></li>' for e in parts]
    if studies:
        nav.append('<li><a href="#design-studies">design studies</a></li>')
    if nav:
        head.append("<nav><ul>" + "".join(nav) + "</ul></nav>")
    head.append("</header>")
    from .viewer_page import page_budget

    budget = page_budget()  # the GLB bytes this page carries, shared by its parts in order
    body = itertools.chain(head, (_section(folder, e, budget) for e in parts),
                           [studies_section(studies)] if studies else [])
    return page_pieces("propulsor: built parts", body, style=STYLE + VIEWER_STYLE + (STUDY_STYLE if studies else ""),
                       script=viewer_script())


def write_gallery(folder: str | Path) -> Path | None:
    """Write ``folder/index.html`` (atomically); None, writing nothing, when an ``index.html`` there is
    not one propulsor wrote."""
    folder = Path(folder)
    target = folder / INDEX
    if target.is_symlink() or (target.exists() and not _ours(target)):
        return None
    return write_atomically(target, gallery_pieces(folder))


def is_ours(path: Path) -> bool:
    """A regular file (not a link) propulsor wrote as a gallery page."""
    return path.is_file() and not path.is_symlink() and _ours(path)


def _ours(path: Path) -> bool:
    """Whether `path` is a page propulsor wrote (a regular file: a FIFO or a device is never waited on)."""
    from ..regular_file import read_head

    try:
        return GENERATOR in read_head(path, 4096).decode("utf-8", "replace")
    except (OSError, ValueError):
        return False
