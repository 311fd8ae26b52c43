"""Show a propulsor assembly in the OCP CAD viewer (VS Code extension `ocp_vscode`), or say how to get it.

    python examples/show_in_viewer.py [part file]     (default: parts/road_wheel.toml)
"""

from __future__ import annotations

import sys
from pathlib import Path

import propulsor


def main(part_file: Path) -> int:
    try:
        from ocp_vscode import show
    except ImportError:
        print("ocp_vscode is not installed: `pip install ocp_vscode` and the VS Code extension "
              "'OCP CAD Viewer' (bernhard-42.ocp-cad-viewer), open its viewer, then run this again.")
        return 0
    part = propulsor.part(part_file)
    show(part.assembly())
    return 0


if __name__ == "__main__":
    default = Path(__file__).resolve().parents[1] / "parts" / "road_wheel.toml"
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else default))
