"""The gallery's 3D views in a real browser (headless Chromium): a page of 30 views draws all 30 after
scrolling through; right drag pans (the model moves the way the pointer went); unticking a part in the
part list removes its colour from the image; the section plane changes the image; no console error.

The page is a gallery of 30 copies of one road wheel build (the fastest part file).
"""

from __future__ import annotations

import colorsys
import io
import shutil
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from propulsor.cli import main
from propulsor.export.gallery import INDEX, write_gallery
from propulsor.geometry.rows import row_ids

pytestmark = pytest.mark.browser  # needs headless Chromium (skipped where none is installed)

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "road_wheel.toml"
VIEWS = 30
BACKGROUND = np.array([245, 247, 250])


#: counts the WebGL contexts the page makes (run before the page's own script)
COUNT_CONTEXTS = """(() => { const get = HTMLCanvasElement.prototype.getContext; window.webglContexts = 0;
  HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
    if (/webgl/.test(kind) && !this.__counted) { this.__counted = true; window.webglContexts++; }
    return get.call(this, kind, ...rest); }; })();"""
#: a browser keeps this many WebGL contexts of a page at most (Chromium: 16, 8 on a phone); beyond, the
#: oldest is lost and its view goes blank
MAX_CONTEXTS = 8


@pytest.fixture(scope="module")
def page30(tmp_path_factory):
    """A gallery of 30 road wheels, opened from disk in headless Chromium: (page, folder)."""
    from cdp_browser import headless_page

    with headless_page() as page:
        folder = tmp_path_factory.mktemp("views")
        one = folder / "rw00"
        assert main(["build", str(PART), "--out", str(one), "-q"]) == 0
        for k in range(1, VIEWS):
            shutil.copytree(one, folder / f"rw{k:02d}")
        assert write_gallery(folder) is not None
        page.send("Page.addScriptToEvaluateOnNewDocument", source=COUNT_CONTEXTS)
        page.open((folder / INDEX).as_uri(), 1366)
        yield page


def _shot(page, k: int) -> np.ndarray:
    r = page.evaluate(f"""(async () => {{ const c = document.querySelectorAll('figure.viewer canvas')[{k}];
        c.scrollIntoView({{block: 'center'}}); await new Promise(r => setTimeout(r, 300));
        const b = c.getBoundingClientRect();
        return {{x: b.x + window.scrollX, y: b.y + window.scrollY, width: b.width, height: b.height}}; }})()""")
    assert r["width"] > 100 and r["height"] > 75, r
    return np.asarray(Image.open(io.BytesIO(page.screenshot(clip=r))).convert("RGB")).astype(int)


def _settle(page, k: int) -> str:
    return page.evaluate(f"""(async () => {{ const f = document.querySelectorAll('figure.viewer')[{k}];
        f.scrollIntoView({{block: 'center'}});
        for (let i = 0; i < 600 && !['drawn', 'error'].includes(f.dataset.state); i++) await new Promise(r => setTimeout(r, 50));
        await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
        return f.dataset.state; }})()""")


def _model_pixels(img: np.ndarray) -> np.ndarray:
    """(row, column) of the pixels that are not the background."""
    return np.argwhere(np.abs(img - BACKGROUND).sum(axis=2) > 24)


def test_thirty_views_on_one_page_all_draw(page30):
    assert page30.evaluate("document.querySelectorAll('figure.viewer').length") == VIEWS
    states = [_settle(page30, k) for k in range(VIEWS)]
    assert states == ["drawn"] * VIEWS, states
    for k in range(VIEWS):  # after scrolling through all of them, each still shows its model
        px = _shot(page30, k).reshape(-1, 3)
        colours = len(row_ids(px)[0])  # numpy's distinct rows, by one sort of the columns
        assert colours > 20, f"3D view {k}: the canvas shows {colours} colour(s): nothing drawn"
    assert page30.evaluate("window.webglContexts") <= MAX_CONTEXTS  # so none is ever lost to the limit
    assert page30.errors == []


def _drag(page, k: int, dx: int, button: str = "right") -> None:
    c = page.evaluate(f"""(() => {{ const c = document.querySelectorAll('figure.viewer canvas')[{k}];
        const b = c.getBoundingClientRect(); return [b.x + b.width / 2, b.y + b.height / 2]; }})()""")
    x, y = c
    mask = {"left": 1, "right": 2}[button]
    page.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
    page.send("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button=button, buttons=mask, clickCount=1)
    for s in range(1, 11):
        page.send("Input.dispatchMouseEvent", type="mouseMoved", x=x + dx * s / 10, y=y, button=button, buttons=mask)
    page.send("Input.dispatchMouseEvent", type="mouseReleased", x=x + dx, y=y, button=button, buttons=0, clickCount=1)


def test_right_drag_pans_the_model_the_way_the_pointer_went(page30):
    k = 1
    assert _settle(page30, k) == "drawn"
    before = _model_pixels(_shot(page30, k))[:, 1].mean()
    _drag(page30, k, 120)
    after = _model_pixels(_shot(page30, k))[:, 1].mean()
    assert after - before > 60, (before, after)  # an orbit about the centre leaves the centroid where it was
    page30.evaluate("document.querySelectorAll('figure.viewer canvas')[1].dispatchEvent(new MouseEvent('dblclick')) || 1")
    assert page30.errors == []


def _hue_count(img: np.ndarray, hue: float) -> int:
    rgb = img.reshape(-1, 3)
    first, inverse = row_ids(rgb)  # numpy's unique rows and their inverse (axis=0), by one sort of the columns
    hsv = np.array([colorsys.rgb_to_hsv(*p) for p in rgb[first] / 255.0])
    near = (hsv[:, 1] > 0.15) & (np.abs(((hsv[:, 0] - hue) + 0.5) % 1.0 - 0.5) < 0.025)
    return int(near[inverse.reshape(-1)].sum())


def test_hiding_a_part_removes_its_colour(page30):
    k = 2
    assert _settle(page30, k) == "drawn"
    swatches = page30.evaluate(f"""Array.from(document.querySelectorAll('figure.viewer')[{k}]
        .querySelectorAll('.tools .parts li')).map(li => [li.textContent, getComputedStyle(li.querySelector('.swatch')).backgroundColor])""")
    assert len(swatches) == 5, swatches
    hues = [colorsys.rgb_to_hsv(*[int(v) / 255 for v in c[4:-1].split(",")])[0] for _, c in swatches]
    img = _shot(page30, k)
    # the part whose hue no other part shares, and that shows most
    alone = [i for i, h in enumerate(hues) if all(abs((h - o + 0.5) % 1 - 0.5) > 0.06 for j, o in enumerate(hues) if j != i)]
    i = max(alone, key=lambda i: _hue_count(img, hues[i]))
    shown = _hue_count(img, hues[i])
    assert shown > 500, (swatches[i], shown)
    page30.evaluate(f"document.querySelectorAll('figure.viewer')[{k}].querySelectorAll('.tools .parts input')[{i}].click() || 1")
    hidden = _hue_count(_shot(page30, k), hues[i])
    assert hidden < 0.02 * shown, (swatches[i], shown, hidden)
    page30.evaluate(f"document.querySelectorAll('figure.viewer')[{k}].querySelectorAll('.tools .parts input')[{i}].click() || 1")
    assert _hue_count(_shot(page30, k), hues[i]) > 0.9 * shown  # shown again
    assert page30.errors == []


def test_the_section_plane_changes_the_image(page30):
    k = 3
    assert _settle(page30, k) == "drawn"
    whole = _shot(page30, k)
    page30.evaluate(f"""(() => {{ const f = document.querySelectorAll('figure.viewer')[{k}];
        f.querySelector('.tools input[aria-label="section plane"]').click();
        const s = f.querySelector('.tools select[aria-label="section normal"]');
        s.selectedIndex = 0; s.dispatchEvent(new Event('change')); return 1; }})()""")
    cut = _shot(page30, k)
    changed = (np.abs(cut - whole).sum(axis=2) > 24).mean()
    assert changed > 0.05, changed
    assert len(_model_pixels(cut)) < 0.9 * len(_model_pixels(whole))  # half the model is cut away
    assert page30.errors == []
