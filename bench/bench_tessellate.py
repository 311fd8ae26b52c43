"""Benchmark (issue 40): the meshing of the files' solids (:func:`propulsor.solids.tessellate.triangulate`).

    .venv/bin/python bench/bench_tessellate.py [STEP_FILE ...] [--repeat N]

Every solid of each STEP file (a build's ``<part>/<solid>.step``; none given: spur gears z = 20 and 80, m = 2.5,
20 mm wide, generated and extruded here) is read once, then meshed ``--repeat`` times as a build meshes it (one thread, as in a forked worker); printed per solid: the least CPU seconds of a meshing
(``time.process_time``), the triangles and the deflection the mesh reports.  Paired with an older tree: run it again
with that tree's ``src`` first on ``PYTHONPATH`` (``git worktree add /tmp/wt_old <rev>``).

2026-11-30 (2 cores, the other idle; the seed-002 pair's files of ``make``): before (1b00a34) the driven wheel 2.28
CPU s, 97 562 triangles, 0.00993 mm (BRepMesh's side faces: 0.0188 mm, meshed again with interior nodes), the
driver 0.55 s, 26 956, 0.00887 mm; the sides as strips on their own triangulation's edge nodes (0bb9148) 1.81 s,
29 436, 0.00249 mm and 0.47 s, 9 484, 0.00250 mm; the sides not meshed by BRepMesh at all (3dbf814) 1.00 s and
0.43 s, the same triangles.
2026-12-02 (2 cores; every solid of ``make``'s STEP files but the assemblies, 57, read once; 13ee34b's
``tessellate.py`` loaded beside the new one in one process, the two meshing each solid in turn, least of five each):
24.24 -> 18.86 CPU s in all (a second run 20.84 -> 15.82), every mesh identical (nodes, triangles, deflection).  Three
changes: a prism's second cap is its first cap's triangulation moved (BRepMesh gives a gear's two caps the same
triangles node for node; its Delaunay of a cap is most of what BRepMesh still does on a gear: 0.35-0.45 s of the
seed-002 driven wheel's 1.0 s); the faces beside an edge read by the list's ends (OCP iterates a
TopTools_ListOfShape at 0.16-0.24 ms an element: 0.3-0.45 s of that wheel); a side's checks without numpy's
``cross`` and ``norm`` on 3-vectors.  Per solid: the seed-002 driven wheel 1.18 -> 0.78 s, the final drive's ring
1.05 -> 0.73, the polysector gear 0.55 -> 0.37; the cams' and the road wheel's solids (no prism sides) and the
balancer (a torus face: BRepMesh meshes it whole) as before.  ``make``'s single build of all part files, the old tree
and the new in turn, three rounds (the third new first): 149.2 / 134.2 / 127.3 -> 128.2 / 116.0 / 114.3 s wall, 282.5 /
252.3 / 242.6 -> 242.1 / 219.3 / 216.3 user s (about 10 % of make's CPU paired; the machine drifted faster through
the rounds), the 635 files of the build identical to the reference list.

2026-12-02, a fourteenth session (2 cores; the 57 solids of ``make``'s STEP files, e6699b3's ``tessellate.py`` beside
the new one in one process, least of five each): 16.10 -> 15.19 CPU s in all.  The balancer 2.19 -> 1.59 s (its
prism sides meshed apart although a torus makes the shape not ruled: 139 814 -> 103 846 triangles, the deflection
0.00707 mm as before) and the final drives' carriers 0.49 -> 0.30 and 0.53 -> 0.28 (one side no strip fits: before,
it sent the whole carrier to BRepMesh; now it alone is BRepMesh's, its mesh identical); every other mesh identical
and as fast.  Not seen here, since a STEP file holds its faces where they are placed: in the build, the cam plate's
raised core and ring are placed by a location (``kernel.shifted_z``), which sent the cam to BRepMesh whole (1.34 CPU
s, 0.00498 mm): now strips, 0.31 s and 0.00250 mm, in each of the four cam parts.  A user's spline prism chamfered at
its top (B-spline chamfer faces, no strips): each halving's faces that miss the limit are meshed again too: 8.5 CPU
s, 222 854 triangles and 0.047 mm (the limit failed) -> 0.79 s, 28 056 triangles, 0.0053 mm.

2026-12-02, a fifteenth session (2 cores; the 57 solids of ``make``'s STEP files, 965c6b0's ``tessellate.py`` beside the
new one in one process, least of three each): 17.45 -> 11.97 CPU s in all.  Where the faces BRepMesh is left after the
cylinder bands are all planes (a prism's first cap; 38 of the 57 solids: every gear, the cams, the shoes, the
carriers' discs), they are triangulated by BRepMesh's Delabella algorithm instead of its default (Watson's): the same
nodes (the edges are discretised before either runs), as many triangles, the same ones off the caps, the reported
deflection the same; the mesh volumes move by 1e-16 relative (the sum's order).  Per solid: the seed-002 driven wheel
0.83 -> 0.41, the seed-000 driven 0.99 -> 0.51, the final drive's ring 0.83 -> 0.46, a cam 0.29 -> 0.12-0.13.  On
extrusions' faces (the balancer's, the carriers' holed side, which BRepMesh meshes where no strip fits) Delabella left
faces bare, so it is given planes only, and a face it leaves bare sends the pass to Watson's.  ``make``: its STL, 3MF
and GLB files of those solids (and the report pages that embed them, the manifests' mesh volumes in their last bits)
change, every other file identical, 19 "all checks passed"; the exported meshes measured against the STEP faces as
before (seed-002 driven 0.00248 mm, the cam 0.00250, the ring 0.00251 in float32, as before).
"""

from __future__ import annotations

import argparse
import time


def main(argv=None) -> int:
    from propulsor.export.step import read_step_solids
    from propulsor.solids.tessellate import triangulate

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args(argv)
    solids = [(f"{path}[{k}]", s) for path in a.files for k, s in enumerate(read_step_solids(path))]
    if not a.files:
        from propulsor.geometry.gear_outline import external_gear_profile
        from propulsor.solids.build import extrude_profile

        solids = [(f"spur gear z = {z}, m = 2.5, b = 20", extrude_profile(external_gear_profile(z, 2.5, 0.0).profile,
                                                                              20.0)) for z in (20, 80)]
    for name, solid in solids:
        best, got = float("inf"), None
        for _ in range(max(1, a.repeat)):
            t0 = time.process_time()
            got = triangulate(solid, parallel=False)
            best = min(best, time.process_time() - t0)
        v, f, d = got
        print(f"{name}: {best:.3f} CPU s, {len(f)} triangles, {len(v)} vertices, deflection {d:.5f} mm", flush=True)
    print("no target of its own: a part of make's (issue 40: make <= 60 s wall on two idle cores)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
