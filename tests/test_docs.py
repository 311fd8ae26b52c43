"""The documentation: the README a front page (at most 150 lines, the two commands CI runs), every relative
link of the README and the guide resolving to a file, the reference generated from the code covering every
part type's parameters and derived values, the API tutorial's Python blocks run as written, and the site
built by `make docs`'s own commands with `mkdocs build --strict` (no warning)."""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
README = ROOT / "README.md"
API_TUTORIAL = DOCS / "tutorials" / "python-api.md"

_LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
_FENCE = re.compile(r"^(```|~~~).*?^\1", re.S | re.M)


def _gen_reference():
    spec = importlib.util.spec_from_file_location("gen_reference", DOCS / "gen_reference.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _links(md: Path) -> list[str]:
    text = _FENCE.sub("", md.read_text(encoding="utf-8"))
    text = re.sub(r"`[^`\n]*`", "", text)  # code spans hold no links
    return _LINK.findall(text)


def _relative(target: str) -> str | None:
    if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) or target.startswith(("#", "/")):
        return None
    return target.split("#", 1)[0] or None


def _pdoc_pages() -> set[str]:
    """The pages `make docs`'s pdoc writes under docs/api/ (its modules, read from the Makefile)."""
    line = next(ln for ln in (ROOT / "Makefile").read_text().splitlines() if "-m pdoc" in ln)
    mods = [w for w in line.split() if w.startswith("propulsor")]
    assert mods, line
    return {"api/index.html"} | {"api/" + m.replace(".", "/") + ".html" for m in mods}


def test_readme_is_a_front_page_of_at_most_150_lines_with_the_two_commands():
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 150
    commands = re.findall(r"^    (make(?: \w+)?)\s+#", text, re.M)
    assert commands[:2] == ["make", "make test"], commands
    ci = (ROOT / ".ci" / "run").read_text()
    assert ci.rstrip().splitlines()[-1] == "make test"  # CI runs the README's test command
    makefile = (ROOT / "Makefile").read_text()
    for target in ("all", "test", "docs"):
        assert re.search(rf"^{target}:", makefile, re.M), target
    # the picture is a committed, small PNG
    pics = [t for t in _links(README) if t.endswith(".png")]
    assert pics and all((ROOT / p).is_file() and (ROOT / p).stat().st_size < 100_000 for p in pics)


def test_every_relative_link_of_the_readme_and_the_guide_resolves_to_a_file():
    generated = set(_gen_reference().pages()) | _pdoc_pages()
    bad, seen = [], 0
    for md in [README, *sorted(DOCS.rglob("*.md"))]:
        if "api" in md.relative_to(ROOT).parts[:2]:
            continue
        for target in _links(md):
            rel = _relative(target)
            if rel is None:
                continue
            seen += 1
            path = (md.parent / rel).resolve()
            if path.is_file():
                continue
            if md != README and path.is_relative_to(DOCS) and path.relative_to(DOCS).as_posix() in generated:
                continue
            bad.append(f"{md.relative_to(ROOT)}: {target}")
    assert seen > 30
    assert not bad, bad


def test_the_reference_covers_every_parameter_and_derived_value_of_every_part_type():
    from propulsor.params import describe_params
    from propulsor.parts import glossary_of, params_class, part_type_names

    pages = _gen_reference().pages()
    for t in part_type_names():
        page = pages[f"reference/parts/{t}.md"]
        for row in describe_params(params_class(t)):
            assert f"| `{row['name']}` |" in page, (t, row["name"])
        for name in glossary_of(t):
            assert f"| `{name}` |" in page, (t, name)
    assert "| `2` | `EXIT_BAD_INPUT` |" in pages["reference/exit-codes.md"]
    assert "READ_LIMIT_BYTES['step']" in pages["reference/check-limits.md"]
    for cmd in ("build", "print", "check", "list", "params", "explore", "gallery"):
        assert f"## `propulsor {cmd}`" in pages["reference/cli.md"]


def _blocks(slow: bool) -> list[str]:
    text = API_TUTORIAL.read_text(encoding="utf-8")
    blocks = re.findall(r"(<!-- slow -->\n)?```python\n(.*?)```", text, re.S)
    assert blocks
    return [code for mark, code in blocks if slow or not mark]


def _run_blocks(blocks: list[str], monkeypatch) -> None:
    monkeypatch.chdir(ROOT)  # the tutorial runs from the project's folder
    ns: dict = {"__name__": "__tutorial__"}
    for k, code in enumerate(blocks):
        exec(compile(code, f"{API_TUTORIAL.name} block {k + 1}", "exec"), ns)


def test_the_api_tutorial_runs_as_written(monkeypatch, capsys):
    """Its fast blocks (parameters, errors, the design), in order, in one namespace."""
    _run_blocks(_blocks(slow=False), monkeypatch)
    out = capsys.readouterr().out
    assert "<propulsor.Part noncircular_pair from parts/ncg_elliptical.toml>" in out
    assert "eccentricity = 0.95: must be <= 0.9" in out
    assert "centre distance 76.7573 mm" in out


@pytest.mark.sweep
def test_the_api_tutorial_runs_as_written_slow_blocks_too(monkeypatch):
    _run_blocks(_blocks(slow=True), monkeypatch)


def test_make_docs_builds_the_site_strict_without_a_warning(tmp_path):
    """`make docs`'s commands (pdoc into docs/api, then mkdocs build --strict) on a copy of docs/."""
    if importlib.util.find_spec("mkdocs") is None or importlib.util.find_spec("material") is None:
        pytest.skip("mkdocs-material is not installed (the docs extra: pip install -c constraints.txt -e '.[docs]'; "
                    "`make install` installs it)")
    work = tmp_path / "repo"
    work.mkdir()
    shutil.copytree(DOCS, work / "docs", ignore=shutil.ignore_patterns("api"))
    shutil.copy(ROOT / "mkdocs.yml", work / "mkdocs.yml")
    for name in ("parts", "output", "src"):  # what the reference is generated from
        if (ROOT / name).exists():
            (work / name).symlink_to(ROOT / name)
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    line = next(ln for ln in (ROOT / "Makefile").read_text().splitlines() if "-m pdoc" in ln)
    mods = [w for w in line.split() if w.startswith("propulsor")]
    subprocess.run([sys.executable, "-W", "error", "-m", "pdoc", *mods, "-o", "docs/api"], cwd=work, env=env,
                   check=True, capture_output=True, text=True, timeout=300)
    r = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-d", str(tmp_path / "site")],
                       cwd=work, env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "WARNING" not in r.stderr, r.stderr
    site = tmp_path / "site"
    for page in ("index.html", "reference/parts/noncircular_pair.html", "reference/cli.html",
                 "tutorials/python-api.html", "api/index.html"):
        assert (site / page).is_file(), page
    # opened from disk (file://, as the README says): every local link of every page names a file that is there (a
    # folder address would show the folder's listing, not the page)
    bad = []
    for html in site.rglob("*.html"):
        if "api" in html.relative_to(site).parts:
            continue
        for target in re.findall(r'href="([^"]+)"', html.read_text(encoding="utf-8")):
            target = target.split("#")[0]
            if not target or re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) or target.startswith("/"):
                continue
            if not (html.parent / target).resolve().is_file():
                bad.append(f"{html.relative_to(site)} -> {target}")
    assert not bad, bad[:10]
