"""Issue 14, "See it move": the GLB of every assembly, the isometric pictures, the HTML twins of the
reports, output/index.html, and the page and reports opened from disk in a real browser.

The outputs are those of one real build of the road wheel (the fastest part file).  The browser
tests (marker ``browser``) drive Debian's headless ``chromium`` through the DevTools protocol; in
``make check`` the same test runs over the whole ``output/`` (markers ``browser`` and ``sweep``).
"""

from __future__ import annotations

import base64
import io
import json
import os
import re
from pathlib import Path
from urllib.parse import unquote, urlparse

import numpy as np
import pytest
import trimesh
from PIL import Image

from propulsor.cli import main
from propulsor.export.gallery import INDEX, key_values, render_gallery, status, write_gallery
from propulsor.export.gallery_values import number
from propulsor.export.glb import write_glb
from propulsor.export.render import render_iso
from propulsor.export.step import step_instance_names
from propulsor.geometry.rows import row_ids

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "road_wheel.toml"
PHONE_PX, DESKTOP_PX = 390, 1366


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    """The road wheel built as `make` builds it: into ./output/road_wheel, beside the gallery."""
    cwd = tmp_path_factory.mktemp("gallery")
    here = os.getcwd()
    os.chdir(cwd)
    try:
        assert main(["build", str(PART), "-q"]) == 0
    finally:
        os.chdir(here)
    return cwd / "output" / PART.stem


def _stl_bounds(folder: Path, names) -> np.ndarray:
    pts = np.vstack([trimesh.load(folder / f"{n}.stl", process=False).bounds for n in names])
    return np.array([pts.min(axis=0), pts.max(axis=0)])


def test_every_assembly_has_a_glb_with_named_nodes_in_metres(out, manifest):
    models = manifest["media"]["models"]
    assert [m["step"] for m in models] == ["road_wheel_assembly.step"]
    for m in models:
        scene = trimesh.load(out / m["path"])
        assert isinstance(scene, trimesh.Scene)
        nodes = sorted(scene.graph.nodes_geometry)
        assert nodes == sorted(m["components"]) == sorted(step_instance_names(out / m["step"]))
        # glTF is y-up and in metres: the wheel's axis (z, mm) is the scene's y, scaled by 1e-3
        lo, hi = _stl_bounds(out, m["components"])
        expect = np.array([[lo[0], lo[2], -hi[1]], [hi[0], hi[2], -lo[1]]]) * 1e-3
        assert np.allclose(scene.bounds, expect, atol=1e-6), (scene.bounds, expect)
        assert 0.5 < scene.extents.max() < 1.0  # the wheel is ~630 mm across
        colours = {tuple(g.visual.material.baseColorFactor) for g in scene.geometry.values()}
        assert len(colours) == len(m["components"])  # a distinct colour per component
        assert "script" not in m and not (out / (m["path"] + ".js")).exists()  # no script twin: the pages carry it
        block = re.search(r'<script type="application/octet-stream" id="glb-[0-9a-f]{16}" class="propulsor-glb">'
                          r'([^<]*)</script>', (out / "report.html").read_text()).group(1)
        assert base64.b64decode(block) == (out / m["path"]).read_bytes()  # the GLB's bytes for a page from disk


def test_propulsor_check_validates_the_glb_and_catches_millimetres(out, manifest, tmp_path, monkeypatch):
    import shutil

    import propulsor.export.glb as glb
    from propulsor.checks.files import check_file

    m = manifest["media"]["models"][0]
    assert all(c.passed for c in check_file(out / m["path"])) and len(check_file(out / m["path"])) == 4
    # the same assembly written without the mm -> m scale: the check names the extent
    bad = tmp_path / "bad"
    shutil.copytree(out, bad)
    meshes = {}
    for c in m["components"]:
        mesh = trimesh.load(out / f"{c}.stl", process=False)
        meshes[c] = (mesh.vertices, mesh.faces)
    monkeypatch.setattr(glb, "MM_TO_M", 1.0)
    glb.write_glb(bad / m["path"], "x", meshes, [(c, c, np.eye(4)) for c in m["components"]])
    failed = [c.name for c in check_file(bad / m["path"]) if not c.passed]
    assert failed == [f"{m['path']}: extent vs the STEP in metres"]


def test_every_solid_and_assembly_has_a_picture_in_the_report(out, manifest):
    pictures = manifest["media"]["pictures"]
    solids = [f["path"][:-5] for f in manifest["files"] if f["path"].endswith(".step") and "assembly" not in f["path"]]
    assert sorted(p["of"] for p in pictures) == sorted(solids + ["road_wheel_assembly"])
    report = (out / "report.md").read_text()
    twin = (out / "report.html").read_text()
    for p in pictures:
        img = Image.open(out / p["path"])
        assert img.size[0] == 600 and 300 <= img.size[1] <= 600
        px = np.asarray(img.convert("RGB")).reshape(-1, 3)
        assert len(row_ids(px)[0]) > 50  # shaded, not a silhouette (distinct colours)
        assert (px != 255).any(axis=1).mean() > 0.1  # the part fills the picture
        assert f"]({p['path']})" in report and f'src="{p["path"]}"' in twin


def test_report_html_twin_has_the_reports_tables_and_links(out):
    md, html = (out / "report.md").read_text(), (out / "report.html").read_text()
    assert html.count("<table>") == md.count("\n|---") and html.count("<table>") >= 3
    page = re.sub(r"<script>.*?</script>", "", html, flags=re.S)  # the 3D view's library (namespaces in it)
    assert "http://" not in page and "https://" not in page  # nothing fetched
    md_links = set(re.findall(r"\]\(([^)\s]+)\)", md))
    assert {"tables/tyre_temperature.csv", "views/disc.png"} <= md_links
    # every link and image, and no other but the 3D view's model
    assert set(re.findall(r'(?:href|src)="([^"#]+)"', page)) == md_links | {"road_wheel_assembly.glb"}
    assert 'class="propulsor-glb"' in page.split("<h2>Inputs</h2>")[0]  # the 3D view before the tables


def test_pictures_and_glb_are_deterministic(out, manifest, tmp_path):
    mesh = trimesh.load(out / "disc.stl", process=False)
    items = [(mesh.vertices, mesh.faces, None, (0.3, 0.4, 0.7))]
    a, b = render_iso(items, tmp_path / "a.png"), render_iso(items, tmp_path / "b.png")
    assert a.read_bytes() == b.read_bytes()
    meshes = {"disc": (mesh.vertices, mesh.faces)}
    comps = [("one", "disc", np.eye(4)), ("two", "disc", np.diag([1.0, 1.0, 1.0, 1.0]) + np.eye(4, k=3) * 0)]
    g1 = write_glb(tmp_path / "a.glb", "x", meshes, comps).read_bytes()
    g2 = write_glb(tmp_path / "b.glb", "x", meshes, comps).read_bytes()
    assert g1 == g2
    assert render_gallery(out.parent) == render_gallery(out.parent)


def test_build_writes_the_gallery_beside_its_output(out, manifest):
    page = (out.parent / INDEX).read_text()
    assert page == render_gallery(out.parent)  # the build wrote it after its output was in place
    assert manifest["title"] in page and f'href="{out.name}/report.html"' in page
    cls, text = status(manifest)
    assert cls == "ok" and f"all {len(manifest['checks'])} checks passed" == text
    values = key_values(manifest)
    # labelled by the manifest's glossary (its meaning), with the unit and rounding of the gallery
    meaning = manifest["glossary"]["tyre_radius_mm"]["meaning"]
    assert (meaning, number(manifest["derived"]["tyre_radius_mm"]), "mm") in values
    from propulsor.export.viewer_page import block_id

    assert f'id="{block_id(out.name + "/road_wheel_assembly.glb")}"' in page


def test_gallery_status_counts_and_a_foreign_index_is_left_alone(tmp_path):
    def part(name, checks, expected=()):
        (tmp_path / name).mkdir()
        (tmp_path / name / "manifest.json").write_text(json.dumps(
            {"part": "road_wheel", "files": [], "checks": checks, "expected_failures": list(expected), "derived": {}}))
    ok, bad = {"name": "a", "passed": True}, {"name": "b", "passed": False}
    part("p1", [ok, ok])
    part("p2", [ok, bad], expected=["b"])
    part("p3", [ok, bad, bad])
    part("p3_kit", [ok])
    page = render_gallery(tmp_path)
    assert "all 2 checks passed" in page and "documented failures: 1 of 2 checks" in page
    assert "failed: 2 of 3 checks" in page and 'href="p3_kit/print_report.html"' not in page
    assert page.count('<section class="part"') == 3 and "Print kit" in page  # the kit with its part
    # an animation as the animation writer lists it (media.animations): shown with its frames and size
    frames = [Image.new("RGB", (64, 48), (40 * k, 90, 160)) for k in range(5)]
    (tmp_path / "p1" / "anim").mkdir()
    frames[0].save(tmp_path / "p1" / "anim" / "turn.gif", save_all=True, append_images=frames[1:], duration=80)
    m = json.loads((tmp_path / "p1" / "manifest.json").read_text())
    m["media"] = {"animations": [{"path": "anim/turn.gif", "title": "one turn", "frames": 5, "width_px": 64,
                                  "height_px": 48, "bytes": (tmp_path / "p1" / "anim" / "turn.gif").stat().st_size,
                                  "frame_ms": 80, "poses": 5, "least_clearance_mm": 0.125}]}
    (tmp_path / "p1" / "manifest.json").write_text(json.dumps(m))
    page = render_gallery(tmp_path)
    assert '<img src="p1/anim/turn.gif" alt="one turn, 5 frames, 64 × 48 px' in page
    assert "least clearance 0.125 mm" in page and 'width="64" height="48"' in page
    (tmp_path / INDEX).write_text("<html>someone else's page</html>")
    assert write_gallery(tmp_path) is None and "someone" in (tmp_path / INDEX).read_text()
    assert main(["gallery", str(tmp_path), "-q"]) == 2
    (tmp_path / INDEX).unlink()
    assert main(["gallery", str(tmp_path), "-q"]) == 0 and (tmp_path / INDEX).read_text() == page
    assert main(["gallery", str(tmp_path / "p1"), "-q"]) == 2  # no built part in it


# ---- the browser ---------------------------------------------------------------------------------

INSPECT = """(async () => {
  const sleep = ms => new Promise(r => setTimeout(r, ms));
  const viewers = Array.from(document.querySelectorAll('figure.viewer'));
  const settle = async f => { for (let k = 0; k < 600 && !['drawn', 'error'].includes(f.dataset.state); k++) await sleep(50); };
  const loaded = [];
  for (const f of viewers) {
    f.scrollIntoView();
    await settle(f);
    const sel = f.querySelector('select');
    for (let i = 1; sel && i < sel.options.length; i++) {  // every GLB of the part, through the viewer
      sel.selectedIndex = i;
      sel.dispatchEvent(new Event('change'));
      await settle(f);
      loaded.push(f.dataset.state + ': ' + f.querySelector('.status').textContent);
    }
    if (sel && sel.options.length > 1) { sel.selectedIndex = 0; sel.dispatchEvent(new Event('change')); await settle(f); }
  }
  window.scrollTo(0, 0);
  const imgs = Array.from(document.images);
  await Promise.all(imgs.map(i => i.decode().catch(() => null)));
  return {
    images: imgs.map(i => ({src: i.src, complete: i.complete, w: i.naturalWidth, h: i.naturalHeight})),
    urls: Array.from(document.querySelectorAll('[href], [src]')).map(e => e.href || e.src),
    viewers: viewers.map(f => f.dataset.state + ': ' + f.querySelector('.status').textContent).concat(loaded),
    scrollWidth: document.documentElement.scrollWidth,
  };
})()"""


def _local_file(url: str) -> Path | None:
    u = urlparse(url)
    return Path(unquote(u.path)) if u.scheme == "file" else None


def _inspect(page, url: str, width: int) -> dict:
    page.errors.clear()
    page.open(url, width)
    info = page.evaluate(INSPECT)
    bad = []
    for im in info["images"]:
        if not (im["complete"] and im["w"] > 0 and im["h"] > 0):
            bad.append(f"image not decoded: {im['src']}")
    for u in info["urls"]:
        f = _local_file(u)
        if f is None:
            bad.append(f"not a local file: {u}")
        elif not f.exists():
            bad.append(f"broken link: {u}")
    bad += [f"viewer: {v}" for v in info["viewers"] if not v.startswith("drawn")]
    if info["scrollWidth"] > width:
        bad.append(f"{url} is {info['scrollWidth']} px wide on a {width} px screen")
    bad += page.errors
    assert bad == [], "\n".join(bad)
    return info


def _canvas_drew(page, n: int) -> None:
    """A screenshot of each 3D canvas (scrolled into view) holds more than one colour."""
    for k in range(n):
        r = page.evaluate(f"""(() => {{ const c = document.querySelectorAll('figure.viewer canvas')[{k}];
            c.scrollIntoView({{block: 'center'}}); const b = c.getBoundingClientRect();
            return {{x: b.x + window.scrollX, y: b.y + window.scrollY, width: b.width, height: b.height}}; }})()""")
        assert r["width"] > 100 and r["height"] > 75, r
        px = np.asarray(Image.open(io.BytesIO(page.screenshot(clip=r))).convert("RGB")).reshape(-1, 3)
        colours = len(row_ids(px)[0])
        assert colours > 20, f"3D view {k}: the canvas shows {colours} colour(s): nothing drawn"


def check_in_browser(folder: Path, shots: Path) -> list[str]:
    """Open folder/index.html and every report page from disk at phone and desktop width; assert as the
    issue asks; write the two screenshots of the page into `shots`.  Returns the pages opened."""
    from cdp_browser import headless_page

    index = folder / INDEX
    reports = sorted(list(folder.glob("*/report.html")) + list(folder.glob("*/print_report.html")))
    assert index.is_file() and reports
    with headless_page() as page:
        shots.mkdir(parents=True, exist_ok=True)
        for width, name in ((PHONE_PX, "index_phone_390.png"), (DESKTOP_PX, "index_desktop_1366.png")):
            info = _inspect(page, index.as_uri(), width)
            assert info["viewers"], "the page has no 3D view"
            _canvas_drew(page, page.evaluate("document.querySelectorAll('figure.viewer').length"))
            page.evaluate("window.scrollTo(0, 0) || true")
            page.screenshot(shots / name, full=True)
        for rep in reports:
            _inspect(page, rep.as_uri(), PHONE_PX)
    return [str(index)] + [str(r) for r in reports]


@pytest.mark.browser
def test_gallery_and_reports_in_a_real_browser(out, tmp_path_factory, capsys):
    shots = Path(os.environ.get("PROPULSOR_SCREENSHOTS", tmp_path_factory.mktemp("screenshots")))
    opened = check_in_browser(out.parent, shots)
    assert len(opened) == 2
    with capsys.disabled():  # where a person finds them (or set PROPULSOR_SCREENSHOTS)
        print(f"\nbrowser test: screenshots in {shots}", flush=True)


@pytest.mark.browser
@pytest.mark.sweep
def test_full_output_in_a_real_browser(capsys):
    folder = ROOT / "output"
    if not (folder / INDEX).is_file():
        pytest.skip("no output/index.html: run `make` first")
    opened = check_in_browser(folder, folder / "screenshots")
    with capsys.disabled():
        print(f"\nbrowser test: {len(opened)} pages; screenshots in {folder / 'screenshots'}", flush=True)


def test_the_compiled_rasteriser_paints_the_numpy_rasterisers_picture_pixel_for_pixel(tmp_path):
    """render_iso's compiled painter (``render._paint``: each fragment painted as it is made) against the numpy span
    rasteriser it replaced (``tests/render_reference.py``, runs of 7 triangles and all at once): the same pixels, on
    a scene of overlapping boxes where two coincident faces of different colours tie in depth (the later one shows),
    on a sphere and on random triangles half off the picture, some of them edge-on.  And the PNG shows the tie."""
    import numpy as np
    import trimesh

    from propulsor.export import render
    from render_reference import paint

    def both(x, y, z, rgb, W, H):
        zbuf = np.full(H * W, -np.inf, np.float32)
        image = np.empty((H * W, 3), np.uint8)
        image[:] = 255
        render._paint(np.ascontiguousarray(x), np.ascontiguousarray(y), np.ascontiguousarray(z), rgb, W, H, zbuf,
                      image)
        for run in (7, 10 ** 9):
            assert np.array_equal(image, paint(x, y, z, rgb, W, H, run))
        return image

    box = trimesh.creation.box((10.0, 10.0, 10.0))
    V, F = np.asarray(box.vertices, float), np.asarray(box.faces, np.int64)
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=7.0)
    rng = np.random.default_rng(5)
    scenes = [np.concatenate([V[F], (V + (4.0, 3.0, 2.0))[F], V[F]]), np.asarray(sphere.vertices)[sphere.faces]]
    soup = rng.uniform(-5.0, 45.0, size=(400, 3, 3))
    soup[:40, 1] = soup[:40, 0]  # edge-on: a zero-area triangle on the screen
    scenes.append(soup)
    painted = 0
    for tri in scenes:
        scale = 3.7
        x, y, z = tri[:, :, 0] * scale + 60.5, 60.5 - tri[:, :, 1] * scale, tri[:, :, 2]
        rgb = rng.integers(0, 256, size=(len(tri), 3)).astype(np.uint8)
        image = both(x, y, z, rgb, 121, 97)
        painted += int(np.count_nonzero(np.any(image != 255, axis=1)))
    assert painted > 5000
    # the tie in a picture: the third box (blue) drawn over the first (red) where they coincide
    shifted = np.eye(4)
    shifted[:3, 3] = (4.0, 3.0, 2.0)
    items = [(V, F, None, (0.8, 0.2, 0.2)), (V, F, shifted, (0.2, 0.8, 0.2)), (V, F, None, (0.2, 0.2, 0.8))]
    render.render_iso(items, tmp_path / "boxes.png", width=120)
    from PIL import Image

    px = np.asarray(Image.open(tmp_path / "boxes.png").convert("RGB")).reshape(-1, 3)
    reds = np.sum((px[:, 0] > 150) & (px[:, 1] < 100) & (px[:, 2] < 100))
    blues = np.sum((px[:, 2] > 120) & (px[:, 0] < 100))
    assert blues > 100 and reds == 0
