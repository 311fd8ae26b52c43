"""mkdocs hooks: the reference pages generated from the code (docs/gen_reference.py) at every build, handed to
mkdocs as generated files (nothing is written into docs/), and listed in the navigation."""

from __future__ import annotations

import importlib.util
from pathlib import Path

_spec = importlib.util.spec_from_file_location("gen_reference", Path(__file__).with_name("gen_reference.py"))
gen_reference = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(gen_reference)

_PAGES: dict[str, str] = {}


def on_config(config):
    _PAGES.clear()
    _PAGES.update(gen_reference.pages())
    # the part types' pages under "Reference" in the navigation, as the registry names them
    parts = [{Path(p).stem: p} for p in sorted(_PAGES) if p.startswith("reference/parts/")]
    for item in config["nav"]:
        if isinstance(item, dict) and "Reference" in item:
            entries = item["Reference"]
            k = entries.index("PART_TYPES")
            entries[k:k + 1] = [{"Part types": parts}]
    return config


def on_files(files, config):
    from mkdocs.structure.files import File

    for rel, text in _PAGES.items():
        files.append(File.generated(config, rel, content=text))
    return files
