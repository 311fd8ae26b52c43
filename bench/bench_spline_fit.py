"""The spline fit of a non-circular pair's teeth with its foot-point distances compiled (geometry/spline_foot.py)
and with the same Newton iteration on scipy's BSpline and its derivative splines (the fit's method before).

    python bench/bench_spline_fit.py [part file ...]     # default: parts/ncg_seed002.toml parts/ncg_fourier_seed002.toml

For each part file: the design once (the teeth generated, every piece fitted), with every ``fit_curve`` call
recorded (its exact curve, parameter range, tolerance and first points).  Then every recorded fit is made again
twice, in turn, with the curve's points already known (the exact curve's evaluations are the same either way and
not what is compared): with the compiled distances, and with the scipy iteration.  Prints the CPU seconds of
each, the refinement rounds, and whether every spline (knots, poles) is the same bit for bit.
"""

from __future__ import annotations

import hashlib
import sys
import time
import tomllib
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ["parts/ncg_seed002.toml", "parts/ncg_fourier_seed002.toml"]


def record(part_file: str) -> list:
    """(exact points by parameter, u0, u1, tol, n0) of every fit_curve call of the part's design."""
    from propulsor.geometry import bspline
    from propulsor.study.evaluate import evaluate

    fits = []
    real = bspline.fit_curve

    def recording(func, u0, u1, tol=bspline.SPLINE_FIT_TOL_MM, n0=12, max_points=4000):
        known = {}

        def remembered(u):
            q = np.asarray(func(u), float)
            for x, p in zip(np.asarray(u, float).tolist(), q):
                known[x] = p
            return q

        out = real(remembered, u0, u1, tol, n0, max_points)
        fits.append((known, u0, u1, tol, n0, max_points))
        return out

    base = tomllib.loads((ROOT / part_file).read_text())
    ptype = base.pop("type")
    base.pop("meta", None)
    bspline.fit_curve = recording
    try:
        import propulsor.geometry.noncircular_outline as no

        no.fit_curve = recording
        evaluate(ptype, base, str(ROOT / part_file), {}, "design", ("center_distance_mm",))
    finally:
        bspline.fit_curve = real
        no.fit_curve = real
    return fits


def replay(fits, project) -> tuple[float, int, str]:
    """CPU seconds of making every recorded fit again with ``project`` as the foot-point distances, the rounds,
    and a hash of every spline."""
    from propulsor.geometry import bspline

    saved = bspline._project
    bspline._project = project
    rounds = [0]
    real_interp = bspline._interp

    def counting(P):
        rounds[0] += 1
        return real_interp(P)

    bspline._interp = counting
    h = hashlib.sha256()
    try:
        t0 = time.process_time()
        for known, u0, u1, tol, n0, max_points in fits:
            func = lambda u, k=known: np.array([k[x] for x in np.asarray(u, float).tolist()])
            sp = bspline.fit_curve(func, u0, u1, tol, n0, max_points)
            h.update(np.asarray(sp.knots).tobytes())
            h.update(np.asarray(sp.poles).tobytes())
        dt = time.process_time() - t0
    finally:
        bspline._project = saved
        bspline._interp = real_interp
    return dt, rounds[0], h.hexdigest()[:16]


def main(argv) -> int:
    from propulsor.geometry import bspline
    from propulsor.geometry.spline_foot import foot_distances_scipy

    same = True
    for part_file in argv or DEFAULT:
        fits = record(part_file)
        replay(fits, bspline._project)  # warm: the compiled kernel loaded
        comp = min(replay(fits, bspline._project) for _ in range(3))
        ref = min(replay(fits, foot_distances_scipy) for _ in range(3))
        same &= comp[2] == ref[2]
        print(f"{part_file}: {len(fits)} fits, {comp[1]} rounds; CPU s (least of 3): compiled {comp[0]:.3f}, scipy "
              f"{ref[0]:.3f}; splines {'identical' if comp[2] == ref[2] else 'DIFFERENT'} ({comp[2]} / {ref[2]})")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
