"""Every output file's sha256, one line each: the regression list to keep before a refactor.

    python bench/output_hashes.py [output/] > before.txt      # before the change
    python bench/output_hashes.py [output/] | diff before.txt -   # after it

Lists every regular file under each part folder of the output directory (the manifest too),
sorted by path; dot-files (locks, temporary folders) are skipped.
"""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path


def output_hashes(root: Path) -> list[tuple[str, str]]:
    rows = []
    for f in sorted(root.rglob("*")):
        rel = f.relative_to(root)
        if not f.is_file() or any(part.startswith(".") for part in rel.parts):
            continue
        rows.append((rel.as_posix(), hashlib.sha256(f.read_bytes()).hexdigest()))
    return rows


def main(argv: list[str]) -> int:
    root = Path(argv[1] if len(argv) > 1 else "output")
    for rel, digest in output_hashes(root):
        print(f"{digest}  {rel}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
