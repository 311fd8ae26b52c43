"""The 3D view's tools in a real browser (headless Chromium), on a report.html written beside a small
moving assembly (a plate that stands still, an arm that turns through the poses of its motion, a block):
the report draws its 3D view after its summary; the wheel zooms toward the cursor (the point under it
stays under it); a two-finger pinch zooms; the exploded view moves the parts apart; the motion slider
moves the arm; the first view looks from the direction the model names; no console error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.checks.motion import rotation_matrices
from propulsor.export.glb import lift_planar, write_glb
from propulsor.export.html import write_report_html
from propulsor.geometry.rows import row_ids
from test_glb_motion import box
from test_viewer_browser import _model_pixels, _settle, _shot

pytestmark = pytest.mark.browser  # needs headless Chromium (skipped where none is installed)

FRAMES = 7
REPORT = """# A moving test assembly

## Summary

**PASSED: all 1 checks passed.**

## Inputs

| name | value |
|---|---|
| a | 1 |
"""


@pytest.fixture(scope="module")
def report_page(tmp_path_factory):
    """The report.html of a moving assembly, opened from disk in headless Chromium: the page."""
    from cdp_browser import headless_page

    folder = tmp_path_factory.mktemp("report")
    meshes = {"plate": box(120, 80, 4), "arm": box(70, 12, 8), "block": box(20, 20, 20)}
    lift = lambda x, y: lift_planar(rotation_matrices([0.0], [[x, y]])[0])  # noqa: E731
    comps = [("plate", "plate", np.eye(4)), ("arm", "arm", lift(30.0, 40.0) @ np.diag([1, 1, 1, 1.0])),
             ("block", "block", lift(95.0, 55.0))]
    comps[1][2][2, 3] = 4.0  # on the plate
    angles = np.linspace(0.0, 0.5 * math.pi, FRAMES)
    poses = rotation_matrices(angles, np.tile([30.0, 40.0], (FRAMES, 1)))
    moves = {1: lift_planar(poses) @ np.linalg.inv(lift(30.0, 40.0)) @ comps[1][2]}
    info = {"name": "turn", "frame_ms": 60, "title": "the arm turning", "steps": list(range(0, 2 * FRAMES, 2))}
    write_glb(folder / "asm.glb", "asm", meshes, comps, [(info, moves)])
    md = folder / "report.md"
    md.write_text(REPORT, encoding="utf-8")
    # seen from below first, as the balancer's assembly is (its arm would hide under its wheel from above)
    write_report_html(md, [{"path": "asm.glb", "title": "asm", "view_dir": [1.0, -1.0, -1.0]}])
    with headless_page() as page:
        page.open((folder / "report.html").as_uri(), 1000)
        assert _settle(page, 0) == "drawn"
        yield page


def _js(page, body: str):
    return page.evaluate(f"(() => {{ const f = document.querySelector('figure.viewer'), v = f.propulsorView; {body} }})()")


def _fit(page) -> None:
    _js(page, "v.fit(); return 1;")
    _settle(page, 0)


def test_the_report_draws_its_3d_view_after_its_summary(report_page):
    order = report_page.evaluate("""Array.from(document.querySelectorAll('h2, figure.viewer'))
        .map(e => e.tagName === 'FIGURE' ? 'view' : e.textContent)""")
    assert order[:3] == ["Summary", "3D view", "view"] and order.index("Inputs") > order.index("view"), order
    img = _shot(report_page, 0)
    assert len(row_ids(img.reshape(-1, 3))[0]) > 20  # drawn, not one colour
    assert report_page.errors == []


def test_the_motion_slider_moves_the_arm_through_its_poses(report_page):
    _fit(report_page)
    slider = "f.querySelector('.tools input[aria-label=\"motion pose\"]')"
    assert _js(report_page, f"return {slider}.max;") == str(FRAMES - 1)
    shots, arm = [], []
    for j in (0, FRAMES - 1, 0):
        _js(report_page, f"const s = {slider}; s.value = '{j}'; s.dispatchEvent(new Event('input')); return 1;")
        _settle(report_page, 0)
        shots.append(_shot(report_page, 0))
        arm.append(_js(report_page, "return v.parts[1].quaternion.toArray();"))
    changed = (np.abs(shots[1] - shots[0]).sum(axis=2) > 24).mean()
    assert changed > 0.005, changed  # the arm stands elsewhere
    assert np.abs(shots[2] - shots[0]).sum(axis=2).max() <= 24 * 3  # and back where it was
    turned = 2 * math.degrees(math.acos(min(1.0, abs(float(np.dot(arm[0], arm[1]))))))
    assert abs(turned - 90.0) < 0.5, turned  # the last pose: a quarter turn
    label = _js(report_page, "return f.querySelector('.tools .pose').textContent;")
    assert label == f"pose 1 of {FRAMES} (proof step 1)", label
    assert report_page.errors == []


def test_the_wheel_zooms_toward_the_point_under_the_cursor(report_page):
    _fit(report_page)
    # a model point off the centre, under the cursor
    hit = _js(report_page, """const c = v.canvas, b = c.getBoundingClientRect(), T = window.PROPULSOR_THREE;
        for (const [u, w] of [[0.72, 0.4], [0.3, 0.62], [0.65, 0.65], [0.35, 0.35]]) {
          const r = new T.Raycaster(); r.setFromCamera(new T.Vector2(u * 2 - 1, 1 - w * 2), v.camera);
          const h = r.intersectObject(v.root, true);
          if (h.length) return {x: b.left + u * b.width, y: b.top + w * b.height, p: h[0].point.toArray(),
                                d: v.camera.position.distanceTo(v.controls.target)};
        } return null;""")
    assert hit is not None
    report_page.send("Input.dispatchMouseEvent", type="mouseMoved", x=hit["x"], y=hit["y"])
    for _ in range(5):
        report_page.send("Input.dispatchMouseEvent", type="mouseWheel", x=hit["x"], y=hit["y"], deltaX=0, deltaY=-120)
    _settle(report_page, 0)
    after = _js(report_page, f"""const c = v.canvas, b = c.getBoundingClientRect(), T = window.PROPULSOR_THREE;
        const p = new T.Vector3().fromArray({hit['p']}).project(v.camera);
        return {{x: b.left + (p.x + 1) / 2 * b.width, y: b.top + (1 - p.y) / 2 * b.height,
                 d: v.camera.position.distanceTo(v.controls.target)}};""")
    assert after["d"] < 0.85 * hit["d"], (hit, after)  # zoomed in
    assert math.hypot(after["x"] - hit["x"], after["y"] - hit["y"]) < 3.0, (hit, after)  # the point stayed
    assert report_page.errors == []


def test_a_two_finger_pinch_zooms(report_page):
    _fit(report_page)
    before = _js(report_page, "return v.camera.position.distanceTo(v.controls.target);")
    small = len(_model_pixels(_shot(report_page, 0)))
    x, y = _js(report_page, "const b = v.canvas.getBoundingClientRect(); return [b.left + b.width / 2, b.top + b.height / 2];")
    report_page.send("Emulation.setTouchEmulationEnabled", enabled=True, maxTouchPoints=2)

    def touches(s):
        return [{"x": x - s, "y": y, "id": 0}, {"x": x + s, "y": y, "id": 1}]

    report_page.send("Input.dispatchTouchEvent", type="touchStart", touchPoints=touches(30))
    for s in range(40, 160, 10):
        report_page.send("Input.dispatchTouchEvent", type="touchMove", touchPoints=touches(s))
    report_page.send("Input.dispatchTouchEvent", type="touchEnd", touchPoints=[])
    report_page.send("Emulation.setTouchEmulationEnabled", enabled=False)
    _settle(report_page, 0)
    after = _js(report_page, "return v.camera.position.distanceTo(v.controls.target);")
    assert after < 0.7 * before, (before, after)  # fingers apart: closer
    assert len(_model_pixels(_shot(report_page, 0))) > 1.3 * small
    assert report_page.errors == []


def test_the_exploded_view_moves_the_parts_apart(report_page):
    _fit(report_page)
    spread = """const T = window.PROPULSOR_THREE, c = v.box.getCenter(new T.Vector3());
        return v.parts.map(p => new T.Box3().setFromObject(p).getCenter(new T.Vector3()).distanceTo(c));"""
    whole, near = _shot(report_page, 0), _js(report_page, spread)
    ex = "f.querySelector('.tools input[aria-label=\"exploded view\"]')"
    _js(report_page, f"const s = {ex}; s.value = '1000'; s.dispatchEvent(new Event('input')); return 1;")
    _settle(report_page, 0)
    apart, far = _shot(report_page, 0), _js(report_page, spread)
    assert (np.abs(apart - whole).sum(axis=2) > 24).mean() > 0.01
    assert sum(far) > 1.8 * sum(near), (near, far)  # each part 2.5 times as far from the centre
    _js(report_page, f"const s = {ex}; s.value = '0'; s.dispatchEvent(new Event('input')); return 1;")
    _settle(report_page, 0)
    assert np.allclose(_js(report_page, spread), near, atol=1e-6)  # and back together
    assert report_page.errors == []


def test_the_first_view_looks_from_the_direction_the_model_names(report_page):
    _fit(report_page)
    d = np.array(_js(report_page, "return v.camera.position.clone().sub(v.controls.target).normalize().toArray();"))
    # the part's (1, -1, -1) (z up) is glTF's (1, -1, 1) (y up): from below
    assert np.allclose(d, np.array([1.0, -1.0, 1.0]) / math.sqrt(3.0), atol=1e-6), d
    assert report_page.errors == []
