"""Text from part files and manifests reaching a page is shown as text, never run: report.html,
print_report.html and index.html with script, event-handler, frame, javascript: link and
attribute-breaking payloads in every field that reaches them; manifest paths that leave the part's
folder are not linked; a malformed manifest is a note on the gallery page, not a failed command.

Fast: the reports are written by the real OutputWriter from a small part file (road wheel
parameters, no solid built); the gallery from synthetic manifests.  The browser test (marker
``browser``) opens both in headless Chromium and checks that no payload ran.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import lxml.html
import pytest

from propulsor.cli import main
from propulsor.export.gallery import INDEX, render_gallery

ROOT = Path(__file__).resolve().parents[1]
#: what a payload does when it runs: marks the page (the browser test looks for the mark)
MARK = "document.documentElement.dataset.pwned='1'"
PAYLOADS = [
    f"<script>{MARK}</script>",
    f"<img src=x onerror=\"{MARK}\">",
    "<iframe src=\"javascript:parent.document.documentElement.dataset.pwned='1'\"></iframe>",
    "[x](javascript:alert(1))",
    f"\"><svg onload=\"{MARK}\">",
    f"'><img src=x onerror={MARK}>",
    "![p](data:image/svg+xml,<svg onload=alert(1)>) [r](JaVaScRiPt:alert(1)) [e](&#106;avascript:alert(1))",
]
ALL = " ".join(PAYLOADS)
URL_ATTRS = ("href", "src", "action", "formaction", "data", "srcdoc", "xlink:href", "poster", "background")
BANNED_TAGS = {"iframe", "object", "embed", "svg", "math", "frame", "frameset", "base", "form", "link", "applet"}


def assert_inert(page: str, scripts: int = 0) -> lxml.html.HtmlElement:
    """No executable form in `page`: at most `scripts` inline scripts (ours) and no script file, no
    on* attribute, no javascript:/data: address, no frame, object, embed or svg; the CSP meta there."""
    doc = lxml.html.document_fromstring(page)
    data = doc.xpath('//script[@type="application/octet-stream"]')  # the 3D view's model data: never run
    assert all(re.fullmatch(r"[A-Za-z0-9+/=]*", s.text or "") and s.get("class") == "propulsor-glb" for s in data)
    found = [s for s in doc.xpath("//script") if s not in data]
    assert len(found) <= scripts and all(s.get("src") is None for s in doc.xpath("//script")), \
        [lxml.html.tostring(s)[:80] for s in found]
    for el in doc.iter():
        if not isinstance(el.tag, str):
            continue
        assert el.tag.lower() not in BANNED_TAGS, lxml.html.tostring(el)[:120]
        for name, value in el.attrib.items():
            assert not name.lower().startswith("on"), (el.tag, name, value)
            if name.lower() in URL_ATTRS:
                v = re.sub(r"[\x00-\x20]", "", value).lower()
                assert not v.startswith(("javascript:", "data:", "vbscript:", "/", "\\")) and ":" not in v, (name, value)
    csp = doc.xpath('//meta[@http-equiv="Content-Security-Policy"]/@content')
    assert len(csp) == 1 and "default-src 'none'" in csp[0] and "unsafe-inline" not in csp[0].split("script-src")[1]
    assert doc.xpath("//meta")[1].get("http-equiv") == "Content-Security-Policy"  # before any style or script
    return doc


def poisoned_part_file(folder: Path) -> Path:
    """The road wheel's parameters with a title and notes made of every payload."""
    body = (ROOT / "parts" / "road_wheel.toml").read_text(encoding="utf-8").split("[meta]")[0]
    folder.mkdir(parents=True, exist_ok=True)
    part = folder / "poisoned.toml"
    part.write_text(body + "[meta]\n" + f"title = {json.dumps('Wheel ' + ALL)}\n"
                    + f"notes = {json.dumps(PAYLOADS)}\n", encoding="utf-8")
    return part


def write_poisoned_report(folder: Path, report_name: str = "report.md") -> Path:
    """report.md / print_report.md and the HTML twin written by the OutputWriter: the payloads in the
    title, the notes, a check's name and message, a derived value's name and text."""
    from propulsor.building import load_part
    from propulsor.check import Check
    from propulsor.parts.writer import OutputWriter

    part = poisoned_part_file(folder)
    part_type, params, _ = load_part(part)
    w = OutputWriter(folder / "out", part_type.name, params, source=part)
    w.report_name = report_name
    w.add_checks([Check(f"check {p}", False, 1.0, 2.0, "mm", f"message {p}") for p in PAYLOADS])
    w.derived.update({f"text_{k}": f"value {p}" for k, p in enumerate(PAYLOADS)})
    w.finish()
    return folder / "out" / Path(report_name).with_suffix(".html")


@pytest.mark.parametrize("report_name", ["report.md", "print_report.md"])
def test_report_pages_show_the_payloads_as_text(tmp_path, report_name):
    page = write_poisoned_report(tmp_path, report_name)
    doc = assert_inert(page.read_text(encoding="utf-8"))
    text = doc.text_content()
    for p in PAYLOADS[:3]:  # the markup reads as written, in the heading, the notes and the tables
        assert text.count(p) >= 4, (p, text.count(p))
    assert doc.xpath("//h1")[0].text_content() == "Wheel " + ALL
    assert doc.xpath("//title")[0].text == "Wheel " + ALL
    md = page.with_suffix(".md").read_text(encoding="utf-8")
    title, notes = md.splitlines()[0], md.split("## Notes")[1]
    assert "<" not in title and "<" not in notes  # report.md: text too, no link either
    assert not re.search(r"(?<!\\)\]\((?:javascript|data|JaVaScRiPt):", title + notes)
    assert r"\[x\](javascript:alert(1))" in title


def test_markdown_links_and_images_only_to_files_in_the_folder():
    from propulsor.export.html import markdown_to_html

    md = ("[a](views/a.png) ![b](plots/b.png) [c](../secret.txt) [d](/etc/passwd) [e](//host/x) "
          "[f](%2e%2e/x) [g](file:///etc/passwd) [h](data:text/html,x) [i](views\\..\\..\\x) [j][r] <http://x.y>\n\n"
          "[r]: javascript:alert(1)\n\n<script>alert(1)</script>\n\n<div onclick=\"alert(1)\">k</div>\n")
    doc = lxml.html.fragment_fromstring(markdown_to_html(md), create_parent="div")
    assert not doc.xpath("//script|//div/div|//*[@onclick]")  # a block of raw HTML is text too
    assert [(e.tag, e.get("href") or e.get("src")) for e in doc.xpath("//a|//img")] == [
        ("a", "views/a.png"), ("img", "plots/b.png")]
    assert doc.text_content().split()[:10] == ["a", "c", "d", "e", "f", "g", "h", "i", "j", "http://x.y"]
    assert "<script>alert(1)</script>" in doc.text_content()


# ---- the gallery -----------------------------------------------------------------------------------

def poisoned_gallery(folder: Path) -> Path:
    """An output folder of two parts whose manifests hold every payload in every text the gallery
    shows, and paths outside their folders; an evil script beside them that a leaked path would load."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "evil.js").write_text(MARK + ";\n")
    (folder / "secret.png").write_bytes(b"\x89PNG\r\n\x1a\n")
    good = folder / "good"
    for sub in ("", "views", "anim"):
        (good / sub).mkdir(parents=True, exist_ok=True)
    (good / "views" / "wheel.png").write_bytes(b"\x89PNG\r\n\x1a\n")
    (good / "anim" / "turn.gif").write_bytes(b"GIF89a")
    from test_viewer_page import tiny_glb

    (good / "wheel.glb").write_bytes(tiny_glb())
    (good / "wheel.glb.js").write_text(MARK + ";\n")  # a script twin of an older build: never loaded
    (good / "report.html").write_text("<p>report</p>")
    (good / "link.png").symlink_to(folder / "secret.png")  # a link out of the folder
    bad_paths = ["../../../../etc/evil.js", "../evil.js", "/etc/passwd", "javascript:alert(1)", "data:text/html,x",
                 "link.png", "views", "missing.png", "views/../../evil.js", "", "anim/turn.gif\u0000.png"]
    text = "T " + ALL
    media = {
        "animations": [{"path": "anim/turn.gif", "title": text, "frames": 3, "width_px": 64, "height_px": 48}]
                      + [{"path": p, "title": text} for p in bad_paths],
        "models": [{"path": "wheel.glb", "script": "wheel.glb.js", "title": text}]
                  + [{"path": "wheel.glb", "script": p, "title": text} for p in bad_paths]
                  + [{"path": p, "script": "wheel.glb.js", "title": text} for p in bad_paths]
                  + [{"path": "wheel.glb", "script": "report.html", "title": text}],
        "pictures": [{"path": "views/wheel.png", "title": text}] + [{"path": p, "title": text} for p in bad_paths],
    }
    manifest = {"part": "x " + ALL, "title": "Title " + ALL, "media": media,
                "files": [{"path": "wheel.glb", "format": "GLB"}] + [{"path": p, "format": "STEP"} for p in bad_paths],
                "checks": [{"name": p, "passed": False} for p in PAYLOADS], "expected_failures": [PAYLOADS[0]],
                "derived": {p: p for p in PAYLOADS}}
    (good / "manifest.json").write_text(json.dumps(manifest))
    evil = folder / "h_evil"  # a part whose only model's script is outside its folder
    evil.mkdir()
    (evil / "m.glb").write_bytes(b"glTF")
    (evil / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": [], "media": {
        "models": [{"path": "m.glb", "script": "../evil.js"}], "pictures": [{"path": "../secret.png"}]}}))
    odd = folder / "javascript:alert(1);x"  # a folder name that would be a javascript: address
    odd.mkdir()
    (odd / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": []}))
    return folder


def test_gallery_shows_manifest_text_as_text_and_links_only_files_in_the_part(tmp_path):
    folder = poisoned_gallery(tmp_path)
    page = render_gallery(folder)
    doc = assert_inert(page, scripts=1)
    assert doc.xpath("//h2")[0].text_content() == "Title " + ALL
    assert doc.xpath("//script[not(@type)]")[0].text.strip().startswith("/*")  # ours: the viewer
    for el in doc.xpath("//*[@href or @src]"):
        url = el.get("href") or el.get("src")
        if url.startswith("#"):
            continue
        target = (folder / re.sub(r"%([0-9A-F]{2})", lambda m: chr(int(m.group(1), 16)), url)).resolve()
        assert target.is_relative_to(folder.resolve()) and target.exists(), url
        assert target != folder.resolve() / "secret.png"
    models = [m for f in doc.xpath("//figure[@class='viewer']/@data-models") for m in json.loads(f)]
    from propulsor.export.viewer_page import block_id

    assert models and {m["block"] for m in models} == {block_id("good/wheel.glb")}  # nothing from outside
    assert page.count('class="propulsor-glb"') == 1 and not re.search(r"src=[^>]*\.js", page)
    srcs = sorted(doc.xpath("//img/@src"))
    assert srcs == ["good/anim/turn.gif", "good/views/wheel.png"]
    assert 'href="javascript%3Aalert%281%29%3Bx/"' in page  # the odd folder's name is a path, not a scheme


def test_gallery_renders_each_field_type_a_manifest_can_get_wrong(tmp_path, capsys):
    good = tmp_path / "a_good"
    good.mkdir()
    (good / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": [], "title": "fine",
                                                    "checks": [{"name": "c", "passed": True}]}))
    broken = {
        "b_title": {"part": "road_wheel", "files": [], "title": 5},
        "c_width": {"part": "road_wheel", "files": [], "media": {"animations": [{"path": "a.gif", "width_px": "abc"}]}},
        "d_media": {"part": "road_wheel", "files": [], "media": [1, 2]},
        "e_checks": {"part": "road_wheel", "files": [], "checks": {"name": "x"}},
        "f_check": {"part": "road_wheel", "files": [], "checks": ["x"]},
        "g_files": {"part": "road_wheel", "files": [{"path": 3, "format": "STEP"}]},
        "h_derived": {"part": "road_wheel", "files": [], "derived": [1]},
        "i_models": {"part": "road_wheel", "files": [], "media": {"models": [{"path": "m.glb", "title": ["x"]}]}},
        "j_part": {"part": 1, "files": []},
        "k_expected": {"part": "road_wheel", "files": [], "expected_failures": [None, 1]},
        "l_list": [1, 2, 3],
        "m_title_html": {"part": "road_wheel", "files": [], "title": {"<script>": 1}},
        "n_frames": {"part": "road_wheel", "files": [], "media": {"animations": [{"path": "a.gif", "frames": True}]}},
        "o_pictures": {"part": "road_wheel", "files": [], "media": {"pictures": "views/x.png"}},
    }
    for name, m in broken.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "manifest.json").write_text(json.dumps(m))
        for f in ("a.gif", "m.glb"):
            (tmp_path / name / f).write_bytes(b"x")
    (tmp_path / "p_json").mkdir()
    (tmp_path / "p_json" / "manifest.json").write_text('{"part": "road_wheel", "files": [')
    (tmp_path / "q_<i>x").mkdir()
    (tmp_path / "q_<i>x" / "manifest.json").write_bytes(b"\xff\xfe")
    assert main(["gallery", str(tmp_path), "-q"]) == 0
    assert "not written by propulsor" not in capsys.readouterr().err
    page = (tmp_path / INDEX).read_text(encoding="utf-8")
    doc = assert_inert(page, scripts=1)
    notes = [p.text_content() for p in doc.xpath("//p[@class='unreadable']")]
    names = sorted(broken) + ["p_json", "q_<i>x"]
    assert [n.split(":")[0] for n in notes] == [f"{tmp_path.name}/{n}" for n in names]
    assert all(": manifest not readable: " in n for n in notes)
    assert "b_title: manifest not readable: title is a number, not a string" in notes[0]
    assert "media.animations[0].width_px is a string" in notes[1]
    assert "not JSON" in notes[-2] and "not JSON" in notes[-1] and "q_&lt;i&gt;x" in page and "<i>" not in page
    assert [s.get("id") for s in doc.xpath("//section")] == ["a_good"] and "fine" in page


def test_gallery_that_cannot_be_written_is_an_environment_failure_not_a_foreign_page(tmp_path, monkeypatch, capsys):
    import errno

    import propulsor.export.gallery as gallery

    (tmp_path / "p").mkdir()
    (tmp_path / "p" / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": []}))

    def full(path, text):
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(gallery, "write_atomically", full)
    assert main(["gallery", str(tmp_path), "-q"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(tmp_path / INDEX) in err[0] and "ENOSPC" in err[0], err
    assert not (tmp_path / INDEX).exists()


@pytest.mark.browser
def test_injected_payloads_do_not_run_in_a_browser(tmp_path):
    """The poisoned report, print report and gallery opened from disk in headless Chromium: no payload
    marks the page, and the gallery's own viewer still runs (its script, the GLB carried as data)."""
    from cdp_browser import headless_page

    reports = [write_poisoned_report(tmp_path / k, name) for k, name in (("a", "report.md"), ("b", "print_report.md"))]
    gallery = poisoned_gallery(tmp_path / "g")
    (gallery / "index.html").write_text(render_gallery(gallery), encoding="utf-8")
    with headless_page() as page:
        for url in [r.as_uri() for r in reports] + [(gallery / "index.html").as_uri()]:
            page.open(url, 1000)
            state = page.evaluate("""(async () => {
                const sleep = ms => new Promise(r => setTimeout(r, ms));
                for (const f of document.querySelectorAll('figure.viewer')) {
                  f.scrollIntoView();
                  for (let k = 0; k < 100 && !['drawn', 'error'].includes(f.dataset.state); k++) await sleep(50);
                }
                for (const e of document.querySelectorAll('img')) await e.decode().catch(() => null);
                await sleep(300);
                return {pwned: document.documentElement.dataset.pwned || null, title: document.title,
                        viewers: Array.from(document.querySelectorAll('figure.viewer')).map(f => f.dataset.state)};
            })()""")
            assert state["pwned"] is None, (url, state)
            if url.endswith(INDEX):
                assert state["viewers"] and all(v != "waiting" for v in state["viewers"]), state  # our script ran
    assert not os.path.exists(tmp_path / "pwned")
