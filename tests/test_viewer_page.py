"""The 3D view's figure on a page: a model's first camera direction (the manifest's ``view_dir``, the
part's frame, z up; the balancer's is from below) reaches the viewer in glTF's frame (y up), through the
gallery; a direction that is not three finite numbers is a manifest the gallery does not show."""

from __future__ import annotations

import html
import json
import re

from propulsor.export.gallery import render_gallery
from propulsor.export.viewer_page import viewer_figure


def _models(page: str) -> list:
    return json.loads(html.unescape(re.search(r"data-models='([^']*)' data-state", page).group(1)))


def tiny_glb() -> bytes:
    """The least GLB the viewer takes: one scene of one empty node."""
    import struct

    js = json.dumps({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "a"}]})
    js = js.encode() + b" " * (-len(js) % 4)
    return struct.pack("<4sII", b"glTF", 2, 20 + len(js)) + struct.pack("<I4s", len(js), b"JSON") + js


def _part(folder, view_dir):
    (folder / "p").mkdir(exist_ok=True)
    (folder / "p" / "a.glb").write_bytes(tiny_glb())
    model = {"path": "a.glb", "title": "a", "view_dir": view_dir}
    (folder / "p" / "manifest.json").write_text(json.dumps(
        {"part": "balancer", "files": [], "checks": [], "derived": {}, "media": {"models": [model]}}))


def test_a_models_view_direction_reaches_the_viewer_in_gltf_axes(tmp_path):
    _part(tmp_path, [1.0, -1.0, -1.0])
    from propulsor.export.viewer_page import block_id

    assert _models(render_gallery(tmp_path)) == [{"block": block_id("p/a.glb"), "title": "a", "view": [1.0, -1.0, 1.0]}]
    # beside the page (a report.html), and a model without one keeps the viewer's own
    figure = viewer_figure([{"path": "a.glb", "title": "a"}], "", folder=tmp_path / "p")
    assert _models(figure) == [{"block": block_id("a.glb"), "title": "a"}]


def test_a_view_direction_that_is_not_three_numbers_is_refused(tmp_path):
    for bad in ("up", [1, 2], [0, 0, 0], [1, True, 0]):
        _part(tmp_path, bad)
        page = render_gallery(tmp_path)
        assert "manifest not readable" in page and "view_dir" in page, bad
