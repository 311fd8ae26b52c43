"""Benchmark (issue 40): the CPU seconds of drawing the animations' frames (export/animation.py ``render_frames``)
and of encoding them (``encode_gif``), over the animations of some part files.

    .venv/bin/python bench/bench_animation.py [part file ...]   (default: seven part files of make, one per kind)

Each part file is built once in this process (``PROPULSOR_JOBS=1``, into a temporary folder) to collect the
animations it draws; then each animation's frames are drawn three times, the remembered text masks
(``_text_mask``) forgotten before each (as a forked build's worker starts without them), and encoded once; the least
of the three draws is kept.  Prints each animation's frames, draw and encode seconds and a digest of its frames'
pixels (the same digest old and new: the same pictures).

2026-12-05 (2 cores, one running CI; the nine animations of ncg_elliptical_2lobe, final_drive, cam_mover, polysector,
ncg_seed002, balancer and road_wheel, 752 frames): a line of text set from the mask of its first drawing, moved
(``_text_mask``: 4 153 lines drawn, 1 039 distinct): the draws 1.505 -> 1.382 CPU s, every frame's pixels identical.
Tried and not kept: a moving shape's loops stacked and placed in one pass (1.382 -> 1.377: a frame's shapes are
mostly one loop each, and the arrays' arithmetic, not the calls, is the cost).  The encoding (Pillow's GIF writer,
``optimize``) takes about as long as the draws: a third of it the LZW code, the rest Pillow's frame-by-frame palette
and difference passes over whole frames (about 1.1 ms a frame), which a numpy rewrite would not beat by much.
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ("ncg_elliptical_2lobe", "final_drive", "cam_mover", "polysector", "ncg_seed002", "balancer", "road_wheel")


def collect(part_files) -> list:
    """The animations the builds of ``part_files`` draw (each built once, in this process)."""
    import propulsor.export.animation as A
    from propulsor.cli import main

    saved, draw = [], A.render_frames

    def keeping(anim):
        saved.append(anim)
        return draw(anim)

    A.render_frames = keeping
    try:
        with tempfile.TemporaryDirectory() as out:
            for p in part_files:
                main(["build", str(p), "--out-dir", out, "-q"])
    finally:
        A.render_frames = draw
    return saved


def main() -> None:
    os.environ["PROPULSOR_JOBS"] = "1"
    files = [Path(a) for a in sys.argv[1:]] or [ROOT / "parts" / f"{n}.toml" for n in DEFAULT]
    import propulsor.export.animation as A

    anims = collect(files)
    total_draw = total_enc = 0.0
    for a in anims:
        best = float("inf")
        for _ in range(3):
            A._text_mask.cache_clear()
            t = time.process_time()
            frames = A.render_frames(a)
            best = min(best, time.process_time() - t)
        t = time.process_time()
        A.encode_gif(frames, a.frame_ms)
        enc = time.process_time() - t
        digest = hashlib.sha256(b"".join(f.tobytes() for f in frames)).hexdigest()[:12]
        total_draw, total_enc = total_draw + best, total_enc + enc
        print(f"{a.n_frames:4d} frames: draw {best:.3f} s, encode {enc:.3f} s, pixels {digest}")
    print(f"{len(anims)} animations: draw {total_draw:.3f} CPU s, encode {total_enc:.3f} CPU s")


if __name__ == "__main__":
    main()
