"""Independent as-built transmission of a non-circular gear pair, from the DXF files only.

This script deliberately imports NOTHING from the ``propulsor`` package: it reads the
exported ``driver.dxf`` / ``driven.dxf`` outlines, the law table
``tables/pitch_curves.csv`` and a few scalars of ``manifest.json`` (mounting distance,
driver turns, hub height A, u, b) and measures the transmission with its own geometry
(ezdxf + numpy + scipy + manifold3d's Clipper2 booleans), so its numbers can cross-check
the ones the build reports in ``manifest.json["derived"]``.

How it works
  * Outer contour = the CUT-layer polyline of largest area in each DXF (bores ignored),
    flattened by ezdxf with chord error <= 1e-4 mm.  Each body sits at its own origin
    (a driver DXF found placed at (L, 0) is shifted back).  Convention, checked against
    the REF pitch curves: driven axis at the origin turned by -phi, driver axis at (L, 0)
    turned by +theta(phi), pitch point at (r_H(phi), 0).
  * Law: periodic cubic spline of theta - n*phi over the table's span P (one leg),
    extended by theta(phi + P) = theta(phi) + n*P;  U = d theta / d phi.
  * For driver angles theta over one period (step --step-deg of DRIVER angle) the driver
    is placed at theta, both outlines are cropped to a box around the pitch point, and
    the driven wheel is turned away from the law position phi until the outlines first
    touch (overlap area > 1e-9 mm^2), bisected to --tol rad:
      drive   = turned back (te < 0).  Why: at the pitch point (r_H, 0) the driver turning
                +theta (about (L, 0)) moves in -y, and so does the driven wheel going
                forward (turned -phi); the driver's loaded flank pushes the driven flank
                lying on its -y side, and turning the driven back (+y) closes that gap;
      reverse = turned forward (te > 0), the other flanks.
    te = actual driven angle - phi.  The search is warm-started from the previous sample.
  * Speeds are secants between consecutive samples: 1 + d te / d phi.  Hub speed
    v/omega = (A + 3 b cos 2w) (1 + te') / U(phi), w = phi + te wrapped into [-P/2, P/2);
    ripple = (max - min) / (A/u).  Around each extreme of the speed and of the hub speed
    the grid is refined x10 (tolerance /10) and re-measured.
  * Backlash = (te_reverse - te_drive) * r_H(phi).

Usage:  python bench/as_built_independent.py BUILD_FOLDER [--step-deg 0.05] [--span-deg X]
"""
import argparse
import json
import math
import sys
import time
from pathlib import Path

import ezdxf
import manifold3d as mf
import numpy as np
from ezdxf import path as ezpath
from scipy.interpolate import CubicSpline

AREA_EPS = 1e-9  # mm^2: overlap threshold


def outer_contour(dxf_file, layer="CUT"):
    """Largest-area closed polyline of the layer, flattened, counter-clockwise."""
    best, best_area = None, 0.0
    for e in ezdxf.readfile(dxf_file).modelspace().query("LWPOLYLINE POLYLINE"):
        if e.dxf.layer.upper() != layer:
            continue
        pts = np.array([(v.x, v.y) for v in ezpath.make_path(e).flattening(1e-4)])
        if np.allclose(pts[0], pts[-1]):
            pts = pts[:-1]
        x, y = pts.T
        area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
        if abs(area) > abs(best_area):
            best, best_area = pts, area
    if best is None:
        sys.exit(f"no {layer} polyline in {dxf_file}")
    return (best if best_area > 0 else best[::-1]), abs(best_area)


def rot(xy, a):
    c, s = math.cos(a), math.sin(a)
    return xy @ np.array([[c, s], [-s, c]])


def polar_radius(xy, ang):
    """Radius of a star-shaped closed curve (about the origin) at polar angles ang."""
    a = np.arctan2(xy[:, 1], xy[:, 0])
    o = np.argsort(a)
    r = np.hypot(xy[:, 0], xy[:, 1])
    return np.interp(np.mod(ang + np.pi, 2 * np.pi) - np.pi, a[o], r[o], period=2 * np.pi)


class Law:
    def __init__(self, csv_file, n):
        t = np.genfromtxt(csv_file, delimiter=",", names=True)
        self.phi0, self.P, self.n = t["phi_rad"][0], t["phi_rad"][-1] - t["phi_rad"][0], n
        self.span_err = (t["theta_rad"][-1] - t["theta_rad"][0]) - n * self.P
        g = t["theta_rad"] - n * t["phi_rad"]
        g[-1] = g[0]
        rh = t["r_H_mm"].copy()
        rh[-1] = rh[0]
        self.g = CubicSpline(t["phi_rad"], g, bc_type="periodic")
        self.rH = CubicSpline(t["phi_rad"], rh, bc_type="periodic")
        self.table = t

    def theta(self, phi):
        return self.n * phi + self.g(phi)

    def U(self, phi):
        return self.n + self.g(phi, 1)

    def phi_of(self, th):
        phi = np.asarray(th, float) / self.n
        for _ in range(30):
            phi = phi - (self.theta(phi) - th) / self.U(phi)
        return phi


class Mesh:
    """Outlines placed at a driver angle and cropped around the pitch point."""

    def __init__(self, drv, dvn, L, law, half):
        self.drv, self.dvn, self.L, self.law, self.half = drv, dvn, L, law, half
        self.jams = 0  # placements whose outlines overlap at the law's own position

    def place(self, th):
        phi = float(self.law.phi_of(th))
        rh, h = float(self.law.rH(phi)), self.half
        box = lambda m: mf.CrossSection([np.array([[rh - h - m, -h - m], [rh + h + m, -h - m],
                                                   [rh + h + m, h + m], [rh - h - m, h + m]])])
        # crop in the body frame, far less work than rotating the whole outline
        self.a = mf.CrossSection([self.drv]) ^ box(0).translate((-self.L, 0)).rotate(-math.degrees(th))
        self.a = self.a.rotate(math.degrees(th)).translate((self.L, 0))
        self.b = mf.CrossSection([self.dvn]) ^ box(1.0).rotate(math.degrees(phi))
        self.b = self.b.rotate(-math.degrees(phi))
        return phi

    def overlap(self, te):  # driven turned to phi + te, i.e. by a further -te
        return (self.a ^ self.b.rotate(-math.degrees(te))).area() > AREA_EPS

    def contact(self, s, guess, tol, dt=3e-4, tmax=0.05):
        """First touch turning the driven by s*t, t >= 0, from the law position; te or nan."""
        if self.overlap(0.0):
            self.jams += 1
            return np.nan
        t0 = max(s * guess, 0.0) if np.isfinite(guess) else 0.0
        lo = max(t0 - dt, 0.0)
        if lo > 0 and self.overlap(s * lo):
            lo = 0.0
        hi, step = t0 + dt, dt
        while not self.overlap(s * hi):
            lo, hi, step = hi, hi + 2 * step, 2 * step
            if hi > tmax:
                return np.nan
        while hi - lo > tol:
            mid = 0.5 * (lo + hi)
            if self.overlap(s * mid):
                hi = mid
            else:
                lo = mid
        return s * 0.5 * (lo + hi)


def sweep(mesh, thetas, tol, guess=(np.nan, np.nan)):
    out = np.empty((len(thetas), 3))
    gd, gr = guess
    for i, th in enumerate(thetas):
        phi = mesh.place(th)
        gd = mesh.contact(-1, gd, tol)
        gr = mesh.contact(+1, gr, tol)
        out[i] = phi, gd, gr
    return out


def speeds(law, th, phi, te, A, b):
    """Secant driven speed over the law's and hub speed, at interval midpoints."""
    pm, tm = 0.5 * (phi[1:] + phi[:-1]), 0.5 * (te[1:] + te[:-1])
    sp = 1.0 + np.diff(te) / np.diff(phi)
    w = np.mod(pm + tm + law.P / 2, law.P) - law.P / 2
    hub = (A + 3 * b * np.cos(2 * w)) * sp / law.U(pm)
    return pm, sp, hub


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build", type=Path)
    ap.add_argument("--step-deg", type=float, default=0.05, help="driver-angle step")
    ap.add_argument("--span-deg", type=float, default=None, help="driver span (default: one period)")
    ap.add_argument("--start-deg", type=float, default=0.0, help="driven angle phi to start at")
    ap.add_argument("--tol", type=float, default=1e-8, help="bisection tolerance, rad")
    ap.add_argument("--crop-mm", type=float, default=None, help="half size of the mesh box (default 4 m)")
    ap.add_argument("--refine", type=int, default=10)
    ap.add_argument("--csv", type=Path, default=None, help="write the samples (theta, phi, te drive, te reverse)")
    args = ap.parse_args()
    t_start = time.time()
    man = json.loads((args.build / "manifest.json").read_text())
    d, inp = man["derived"], man["inputs"]
    L, n = d["mounting_distance_mm"], int(d["driver_turns"])
    A, u, b = d["hub_height_mm"], d["u"], inp["b_mm"]
    law = Law(args.build / "tables" / "pitch_curves.csv", n)
    drv, drv_area = outer_contour(args.build / "driver.dxf")
    dvn, dvn_area = outer_contour(args.build / "driven.dxf")
    shifted = abs(drv.mean(0)[0] - L) < abs(drv.mean(0)[0])
    if shifted:
        drv = drv - [L, 0.0]
    print(f"driver outline {len(drv)} pts, area {drv_area:.2f} mm^2 (placed at "
          f"{'(L,0): shifted back' if shifted else 'its own origin'}); driven {len(dvn)} pts")
    print(f"law table: P = {math.degrees(law.P):.6f} deg, n = {n}, theta span - n P = {law.span_err:.2e} rad")
    # --- convention check against the REF pitch curves and the table's own U
    tab = law.table
    ref_d, _ = outer_contour(args.build / "driven.dxf", "REF")
    ref_r, _ = outer_contour(args.build / "driver.dxf", "REF")
    if shifted:
        ref_r = ref_r - [L, 0.0]
    e_h = np.max(np.abs(polar_radius(ref_d, tab["phi_rad"]) - tab["r_H_mm"]))
    e_r = np.max(np.abs(polar_radius(ref_r, np.pi - tab["theta_rad"]) - tab["r_mm"]))
    e_m = np.max(np.abs(polar_radius(ref_r, np.pi + tab["theta_rad"]) - tab["r_mm"]))
    e_U = np.max(np.abs(law.U(tab["phi_rad"]) - tab["ratio_U"]))
    hub_law = (A + 3 * b * np.cos(2 * tab["phi_rad"])) / tab["ratio_U"]
    e_hub = np.max(np.abs(hub_law - tab["hub_speed_mm_per_rad"]))
    e_L = np.max(np.abs(tab["r_H_mm"] + tab["r_mm"] - L))
    print(f"check: REF driven r(phi) vs r_H {e_h:.1e} mm; REF driver r(pi-theta) vs r {e_r:.1e} mm "
          f"(mirrored {e_m:.1e});\n       r_H + r - L {e_L:.1e} mm; spline U vs table {e_U:.1e}; (A + 3b cos 2phi)/U vs table "
          f"hub speed {e_hub:.1e} mm/rad; law ripple from table {np.ptp(hub_law) / (A / u):.6f}")

    m = d.get("module_mm", 2.0)
    mesh = Mesh(drv, dvn, L, law, args.crop_mm or 4 * m)
    th0 = float(law.theta(args.start_deg * math.pi / 180))
    span = math.radians(args.span_deg) if args.span_deg else n * law.P
    nstep = int(round(span / math.radians(args.step_deg)))
    dth = span / nstep
    R = args.refine
    t1 = time.time()
    res = sweep(mesh, th0 + dth * np.arange(nstep + 1), args.tol)
    t_coarse = time.time() - t1
    data = {R * k: row for k, row in enumerate(res)}  # key: index on the fine grid
    # --- refine x R around the extremes of speed and hub speed, both directions
    keys = np.array(sorted(data))
    centres = set()
    for col in (1, 2):
        th = th0 + dth / R * keys
        arr = np.array([data[k] for k in keys])
        ok = np.isfinite(arr[:, col])
        _, sp, hub = speeds(law, th[ok], arr[ok, 0], arr[ok, col], A, b)
        for v in (sp, hub):
            for i in (int(np.argmin(v)), int(np.argmax(v))):
                centres.add(int(keys[ok][i]) // R)
    t1 = time.time()
    nref = 0
    for c in sorted(centres):
        k = np.arange(max(c - 3, 0) * R, min(c + 4, nstep) * R + 1)
        prev = data.get(k[0])
        out = sweep(mesh, th0 + dth / R * k, args.tol / 10, (prev[1], prev[2]))
        data.update(zip(k.tolist(), out))
        nref += len(k)
    t_ref = time.time() - t1
    keys = np.array(sorted(data))
    arr = np.array([data[k] for k in keys])
    th = th0 + dth / R * keys
    phi, ted, ter = arr.T
    if args.csv:
        np.savetxt(args.csv, np.column_stack([th, arr]), delimiter=",", fmt="%.12g",
                   header="theta_rad,phi_rad,te_drive_rad,te_reverse_rad", comments="")

    res_dir = {}
    for name, te, pre in (("drive", ted, ""), ("reverse", ter, "reverse_")):
        ok = np.isfinite(te)
        pm, sp, hub = speeds(law, th[ok], phi[ok], te[ok], A, b)
        res_dir[name] = dict(bad=int((~ok).sum()), te_min=te[ok].min(), te_max=te[ok].max(),
                             pp=np.ptp(te[ok]), sp_min=sp.min(), sp_max=sp.max(),
                             hub_min=hub.min() / (A / u), hub_max=hub.max() / (A / u),
                             ripple=np.ptp(hub) / (A / u),
                             phi_hmin=math.degrees(pm[np.argmin(hub)]), phi_hmax=math.degrees(pm[np.argmax(hub)]))
    bl = (ter - ted) * law.rH(phi)
    okb = np.isfinite(bl)
    i_bl = np.argmin(np.where(okb, bl, np.inf))
    r, q = res_dir["drive"], res_dir["reverse"]
    g = lambda k: d.get(k, float("nan"))
    table = [
        ("speed_ripple_as_built_drive", r["ripple"], g("speed_ripple_as_built_drive"), "pts", 0.003),
        ("speed_ripple_as_built_reverse", q["ripple"], g("speed_ripple_as_built_reverse"), "pts", 0.003),
        ("speed_ripple_as_built", max(r["ripple"], q["ripple"]), g("speed_ripple_as_built"), "pts", 0.003),
        ("speed_ripple (law)", None, g("speed_ripple"), "", None),
        ("te_pp_rad", r["pp"], g("te_pp_rad"), "rel", 0.05),
        ("te_pp_reverse_rad", q["pp"], g("te_pp_reverse_rad"), "rel", 0.05),
        ("te_min_rad", r["te_min"], g("te_min_rad"), "", None),
        ("te_max_rad", r["te_max"], g("te_max_rad"), "", None),
        ("backlash_min_mm", bl[i_bl], g("backlash_min_mm"), "abs", 0.005),
        ("backlash_min_phi_deg", math.degrees(phi[i_bl]), g("backlash_min_phi_deg"), "", None),
        ("backlash_max_mm", np.max(bl[okb]), g("backlash_max_mm"), "", None),
        ("speed_as_built_min", r["sp_min"], g("speed_as_built_min"), "", None),
        ("speed_as_built_max", r["sp_max"], g("speed_as_built_max"), "", None),
        ("speed_as_built_reverse_min", q["sp_min"], g("speed_as_built_reverse_min"), "", None),
        ("speed_as_built_reverse_max", q["sp_max"], g("speed_as_built_reverse_max"), "", None),
        ("speed_as_built_min_rel", r["hub_min"], g("speed_as_built_min_rel"), "", None),
        ("speed_as_built_max_rel", r["hub_max"], g("speed_as_built_max_rel"), "", None),
        ("speed_as_built_phi_min_deg", r["phi_hmin"], g("speed_as_built_phi_min_deg"), "", None),
        ("speed_as_built_phi_max_deg", r["phi_hmax"], g("speed_as_built_phi_max_deg"), "", None),
    ]
    span_deg = math.degrees(span)
    partial = span < n * law.P - 1e-9
    print(f"\ndriver span {span_deg:.3f} deg from phi = {args.start_deg} deg, step {math.degrees(dth):.4f} deg, "
          f"{len(res)} coarse + {nref} refined samples ({len(centres)} windows), tol {args.tol:g} rad, "
          f"no contact: drive {r['bad']}, reverse {q['bad']} (of which overlapping at the law: {mesh.jams})"
          + ("  [PARTIAL span: manifest values cover the full period]" if partial else ""))
    print(f"{'quantity':32s} {'independent':>14s} {'manifest':>14s}  {'diff':>11s}  accept")
    for name, mine, theirs, kind, lim in table:
        if mine is None:
            print(f"{name:32s} {'':>14s} {theirs:14.7g}")
            continue
        diff = mine - theirs
        verdict = ""
        if kind == "pts":
            verdict = f"{'ok' if abs(diff) <= lim else 'FAIL'} ({100 * diff:+.3f} pts, limit 0.3)"
        elif kind == "rel":
            verdict = f"{'ok' if abs(diff) <= lim * abs(theirs) else 'FAIL'} ({100 * diff / theirs:+.2f} %, limit 5 %)"
        elif kind == "abs":
            verdict = f"{'ok' if abs(diff) <= lim else 'FAIL'} ({diff:+.5f} mm, limit 0.005)"
        print(f"{name:32s} {mine:14.7g} {theirs:14.7g}  {diff:+11.3e}  {verdict}")
    tot = time.time() - t_start
    print(f"\nruntime {tot:.1f} s total: coarse sweep {t_coarse:.1f} s ({t_coarse / span_deg:.2f} s per driver "
          f"degree at {math.degrees(dth):.3f} deg), refinement {t_ref:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
