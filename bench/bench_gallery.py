"""Time the gallery's share of a build (issue 14): the isometric picture of every solid, and the GLB,
its script twin and the picture of every assembly, from the meshes of a built output folder, in
this one process (CPU seconds: the build spreads them over its two workers).  And the page itself.

Run: .venv/bin/python bench/bench_gallery.py [output folder]   (default output/; built parts needed)
Budget (issue 14): at most ~1 s wall added to a part build by its pictures and GLBs.
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import trimesh

ROOT = Path(__file__).resolve().parents[1]


def main(folder: str = str(ROOT / "output")) -> int:
    from propulsor.export.gallery import built_parts, render_gallery
    from propulsor.export.glb import write_glb
    from propulsor.export.render import palette_colour, render_iso

    folder = Path(folder)
    parts = built_parts(folder) if folder.is_dir() else []
    if not parts:
        print(f"bench_gallery: no built part in {folder}: run `make` first")
        return 0
    tmp = Path(tempfile.mkdtemp(prefix="bench-gallery-"))
    print(f"{'part':24s} {'solids':>7s} {'pictures s':>10s} {'assemblies':>10s} {'GLB+picture s':>13s}")
    for e in parts:
        m, out = e["manifest"], folder / e["name"]
        stls = [f["path"] for f in m["files"] if f["path"].endswith(".stl") and "/" not in f["path"]]
        meshes = {}
        t0 = time.process_time()
        for s in stls:
            mesh = trimesh.load(out / s, process=False)
            meshes[s[:-4]] = (np.asarray(mesh.vertices, float), np.asarray(mesh.faces))
        t_load = time.process_time() - t0
        t0 = time.process_time()
        for name, (v, f) in meshes.items():
            render_iso([(v, f, None, palette_colour(0))], tmp / f"{name}.png")
        t_pic = time.process_time() - t0
        t_asm = 0.0
        models = (m.get("media", {}) or {}).get("models", [])
        for k, model in enumerate(models):
            glb = trimesh.load(out / model["path"], force="scene")  # the placed meshes, as the build wrote them
            items, parts_meshes, comps = [], {}, []
            for j, node in enumerate(glb.graph.nodes_geometry):
                T, g = glb.graph[node]
                geom = glb.geometry[g]
                parts_meshes[node] = (np.asarray(geom.vertices) * 1e3, np.asarray(geom.faces))
                M = np.asarray(T, float).copy()
                M[:3, 3] *= 1e3
                comps.append((node, node, M))
                items.append((*parts_meshes[node], M, palette_colour(j)))
            t1 = time.process_time()  # only the writing counts (reading the GLB back is the bench's own)
            write_glb(tmp / f"a{k}.glb", model["title"], parts_meshes, comps)
            render_iso(items, tmp / f"a{k}.png")
            t_asm += time.process_time() - t1
        print(f"{e['name']:24s} {len(meshes):7d} {t_pic:10.2f} {len(models):10d} {t_asm:13.2f}"
              f"   (STL read {t_load:.2f} s, not part of a build)")
    t0 = time.perf_counter()
    page = render_gallery(folder)
    print(f"index.html of {len(parts)} parts: {len(page) / 1e3:.0f} kB in {time.perf_counter() - t0:.2f} s")
    print(json.dumps({"budget": "<= ~1 s wall per part build for its pictures and GLBs"}))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
