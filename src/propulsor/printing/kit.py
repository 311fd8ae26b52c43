"""A print kit: the pieces as they print, their proofs on the printed geometry, plates, report.

A part type's kit function returns a :class:`Kit`: pieces (solids at print size, FDM allowances
already in the geometry), the assembled model (pieces placed as on the desk), the checks made on
that printed geometry (motion sweeps, fits), derived values and assembly steps.  :func:`write_kit`
turns it into files with the shared pipeline's writer: an STL per piece with the mesh checks
(watertight, one body, genus, no self-intersection), plates (pieces laid on their largest face,
shelf-packed with gaps, one 3MF per plate with a named object per piece, mm), pictures of each plate
and of the assembled model, ``print_report.md`` (scale and why, allowances, filament per plate,
assembly steps) and the manifest.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..check import Check
from ..parallel import fork_pool, inline, threads_ok
from .layout import lay_flat, pack, placed
from .piece import Piece
from .printers import Printer
from .scale import ScaleChoice


@dataclass
class Placed:
    """A printed piece in the assembled model: its label, the piece's name, the 4 × 4 placement of the
    printed piece (as :func:`place` makes it) and a colour for the picture."""

    label: str
    piece: str
    matrix: np.ndarray
    colour: str = "0.6"


def place(dx: float = 0.0, dy: float = 0.0, dz: float = 0.0, rot_z: float = 0.0, flip: str | None = None,
          z_top: float = 0.0) -> np.ndarray:
    """4 × 4 placement: the piece optionally turned over about the x or y axis with its top z_top brought to
    z = 0 (:func:`propulsor.solids.printed.flipped`), then turned about z by rot_z (rad), then moved."""
    F = np.eye(4)
    if flip is not None:
        F = np.diag({"x": [1.0, -1.0, -1.0, 1.0], "y": [-1.0, 1.0, -1.0, 1.0]}[flip])
        F[2, 3] = z_top
    c, s = np.cos(rot_z), np.sin(rot_z)
    M = np.eye(4)
    M[:2, :2] = [[c, -s], [s, c]]
    M[:3, 3] = (dx, dy, dz)
    return M @ F


@dataclass
class Kit:
    part: str
    printer: Printer
    scale: ScaleChoice
    pieces: list[Piece]
    #: assembled model: the printed pieces placed as on the desk
    assembly: list[Placed] = field(default_factory=list)
    checks: list[Check] = field(default_factory=list)
    derived: dict = field(default_factory=dict)
    allowances: list[tuple[str, float, str]] = field(default_factory=list)  # (name, value mm, how applied)
    steps: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    #: the labels of `assembly` each step places (one list a step; the guide's step pictures)
    step_parts: list = field(default_factory=list)
    #: pins in their holes, measured on the pieces (:mod:`.fits`)
    fits: list = field(default_factory=list)
    #: bought parts: steel pins that may replace printed ones (instead_of: the piece), or that the kit needs
    hardware: list = field(default_factory=list)
    #: checks of the kit that fail as the part file documents (its [meta] expected_failures, e.g. the
    #: papers' sector teeth that jam): reported as documented, like the part's own
    expected_failures: list[str] = field(default_factory=list)
    #: paragraphs of the guide's section "As printed": the printed pair within the printer's accuracy
    guide_notes: list[str] = field(default_factory=list)
    #: paragraphs of the guide's "Which material" (what to print it in: the hand on the crank against each printed
    #: material) and its table (head, rows) or None
    material_notes: list[str] = field(default_factory=list)
    material_table: tuple | None = None
    #: tables of the kit report: (name, columns, rows), written as tables/<name>.csv
    tables: list = field(default_factory=list)


def plate_checks(kit: Kit, plates, flat: dict) -> list[Check]:
    """Pieces on a plate do not touch (least gap between footprints) and every plate fits the bed."""
    p = kit.printer
    out = []
    for k, plate in enumerate(plates, 1):
        boxes = []
        for pl in plate.placements:
            m = placed(flat[pl.name], pl)
            boxes.append(m.bounds)
        lo = np.min([b[0] for b in boxes], axis=0)
        hi = np.max([b[1] for b in boxes], axis=0)
        m = p.margin_mm
        inside = bool(lo[0] >= m - 1e-9 and lo[1] >= m - 1e-9 and hi[0] <= p.bed_x_mm - m + 1e-9
                      and hi[1] <= p.bed_y_mm - m + 1e-9 and hi[2] <= p.bed_z_mm + 1e-9 and abs(lo[2]) < 1e-9)
        out.append(Check.flag(f"plate_{k}.on_bed", inside,
                              f"pieces span x {lo[0]:.1f} … {hi[0]:.1f}, y {lo[1]:.1f} … {hi[1]:.1f}, z 0 … {hi[2]:.1f} mm "
                              f"on a {p.bed_x_mm:g} × {p.bed_y_mm:g} × {p.bed_z_mm:g} mm bed, at least {m:g} mm from "
                              f"its edges (the slicer's skirt)"))
        centre = 0.5 * (lo[:2] + hi[:2])
        off = float(np.max(np.abs(centre - [0.5 * p.bed_x_mm, 0.5 * p.bed_y_mm])))
        out.append(Check.at_most(f"plate_{k}.centred", off, 1e-6, "mm",
                                 f"the pieces' block centred on the bed (centre at x {centre[0]:.1f}, y {centre[1]:.1f} mm)"))
        gap = np.inf
        for i in range(len(boxes)):
            for j in range(i + 1, len(boxes)):
                a, b = boxes[i], boxes[j]
                g = max(b[0][0] - a[1][0], a[0][0] - b[1][0], b[0][1] - a[1][1], a[0][1] - b[1][1])
                gap = min(gap, g)
        if len(boxes) > 1:
            out.append(Check.at_least(f"plate_{k}.least_gap", float(gap), 0.5 * p.piece_gap_mm, "mm",
                                      f"least gap between the footprints of {len(boxes)} pieces"))
    return out


def _plate_picture(w, name: str, objects, printer: Printer) -> None:
    import matplotlib.pyplot as plt
    from matplotlib.patches import Polygon, Rectangle

    fig, ax = plt.subplots(figsize=(6, 6 * printer.bed_y_mm / printer.bed_x_mm))
    ax.add_patch(Rectangle((0, 0), printer.bed_x_mm, printer.bed_y_mm, fill=False, lw=1.5, ec="0.3"))
    m = printer.margin_mm  # the pieces stay inside it: the slicer's skirt lies between it and the bed's edge
    ax.add_patch(Rectangle((m, m), printer.bed_x_mm - 2 * m, printer.bed_y_mm - 2 * m, fill=False, lw=0.8, ec="0.6",
                           ls="--"))
    for k, (label, mesh) in enumerate(objects):
        outline = mesh.vertices[:, :2]
        try:
            from scipy.spatial import ConvexHull

            hull = outline[ConvexHull(outline).vertices]
        except Exception:  # noqa: BLE001 - a degenerate footprint is drawn as its box
            lo, hi = outline.min(axis=0), outline.max(axis=0)
            hull = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        ax.add_patch(Polygon(hull, closed=True, fc=f"C{k % 10}", alpha=0.45, ec="k", lw=0.6))
        c = hull.mean(axis=0)
        ax.annotate(label, c, ha="center", va="center", fontsize=7)
    ax.set_xlim(-5, printer.bed_x_mm + 5)
    ax.set_ylim(-5, printer.bed_y_mm + 5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(f"{name}: {len(objects)} piece(s) on the {printer.name} bed, "
                 f"{printer.bed_x_mm:g} × {printer.bed_y_mm:g} mm")
    w.add_plot(name, fig)
    plt.close(fig)


def assembled_meshes(kit: Kit, meshes: dict) -> list:
    """[(label, mesh, colour)] of the assembled model: the printed pieces' meshes {name: mesh} placed."""
    out = []
    for pl in kit.assembly:
        m = meshes[pl.piece].copy()
        m.apply_transform(pl.matrix)
        out.append((pl.label, m, pl.colour))
    return out


def _assembly_picture(w, kit: Kit, meshes: dict) -> None:
    """The assembled model seen from above (each printed piece's mesh placed and projected, the higher
    pieces on top)."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    fig, ax = plt.subplots(figsize=(7, 6))
    items = assembled_meshes(kit, meshes)
    items.sort(key=lambda it: it[1].bounds[1][2])
    for name, mesh, colour in items:
        up = mesh.face_normals[:, 2] > 0.5
        tris = mesh.triangles[up][:, :, :2]
        ax.add_collection(PolyCollection(tris, facecolors=colour, edgecolors="face", linewidths=0.2))
    lo = np.min([m.bounds[0] for _, m, _ in items], axis=0)
    hi = np.max([m.bounds[1] for _, m, _ in items], axis=0)
    ax.set_xlim(lo[0] - 5, hi[0] + 5)
    ax.set_ylim(lo[1] - 5, hi[1] + 5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(f"{kit.part}: the printed model assembled (top view, {kit.scale.label})")
    w.add_plot("assembled", fig)
    plt.close(fig)


def _printed_piece(solid, name: str, genus, chamfer: float, layer: float, forked: bool):
    """(mesh as built, mesh as printed: laid on its largest face with the bed-side chamfer, its mesh
    checks) of one piece; run in a forked worker (OCCT's mesher on one thread there)."""
    from ..checks.mesh import mesh_checks
    from ..export.mesh import to_trimesh
    from .chamfer import chamfer_first_layers

    mesh = to_trimesh(solid, parallel=not forked and threads_ok())
    printed = chamfer_first_layers(lay_flat(mesh)[0], chamfer, layer, name)
    return mesh, printed, mesh_checks(printed, name, expected_genus=genus)


def write_kit(kit: Kit, w, sliced: bool = False) -> None:
    """Pieces → STL + mesh checks; plates → 3MF + pictures; assembled picture; derived, checks and
    the report's text into the writer `w` (an OutputWriter whose report is print_report.md)."""
    from ..export.mesh import write_3mf_objects, write_stl
    from .planning import TABLE_COLUMNS, PlatePlan, estimate_g, slice_plates, table_rows

    from .coupon import coupon_pieces

    p = kit.printer
    flat = {}  # one per printed copy: name, or name_k when more than one is printed
    piece_meshes = {}
    coupon = coupon_pieces(p)
    kit.pieces = [pc for pc in kit.pieces if not pc.name.startswith("coupon")] + coupon
    # every piece tessellated, laid flat, chamfered and checked in forked workers beside each other
    from ..progress import counter

    pool = fork_pool(2)
    tick = counter(w.progress, "kit: pieces tessellated, laid flat and checked", len(kit.pieces), "piece")
    jobs = []
    for k, pc in enumerate(kit.pieces, 1):
        chamfer = p.chamfer_mm if pc.chamfer_mm is None else pc.chamfer_mm
        args = (pc.solid, pc.name, pc.genus, chamfer, p.layer_mm, pool is not None)
        jobs.append(pool.submit(_printed_piece, *args) if pool is not None else inline(_printed_piece, *args))
        if pool is None:
            tick(k)
    try:
        for k, (pc, job) in enumerate(zip(kit.pieces, jobs), 1):
            mesh, printed, checks = job.result()
            if pool is not None:
                tick(k)
            piece_meshes[pc.name] = mesh
            write_stl(printed, w.path(f"pieces/{pc.name}.stl"), pc.name)
            w.add_checks(checks)
            for k in range(pc.count):
                flat[pc.name if pc.count == 1 else f"{pc.name}_{k + 1}"] = printed
    finally:
        if pool is not None:
            pool.shutdown(wait=True, cancel_futures=True)
    from .fits import measure

    w.add_checks([measure(f, piece_meshes, p) for f in kit.fits])
    def feet(names):
        return {n: tuple((flat[n].bounds[1] - flat[n].bounds[0])[:2]) for n in names}

    first = [pc.name for pc in coupon]  # the coupon prints first, on a plate of its own
    plates = pack(feet(first), p.bed_x_mm, p.bed_y_mm, p.piece_gap_mm, p.margin_mm)
    plates += pack(feet([n for n in flat if n not in first]), p.bed_x_mm, p.bed_y_mm, p.piece_gap_mm, p.margin_mm)
    w.add_checks(plate_checks(kit, plates, flat))
    plans, paths = [], []
    tick = counter(w.progress, "kit: plates and their pictures", len(plates), "plate")
    for k, plate in enumerate(plates, 1):
        objects = [(pl.name, placed(flat[pl.name], pl)) for pl in plate.placements]
        write_3mf_objects(objects, w.path(f"plate_{k}.3mf"), p.slicer_config())
        paths.append(w.path(f"plate_{k}.3mf"))
        _plate_picture(w, f"plate_{k}", objects, p)
        vol = sum(float(m.volume) for _, m in objects)
        plans.append(PlatePlan(k, len(objects), vol / 1000.0, estimate_g([m for _, m in objects], p),
                               ", ".join(n for n, _ in objects)))
        tick(k)
    if sliced:
        w.add_checks(slice_plates(plans, paths, p, w.progress))
    w.add_table("plates", TABLE_COLUMNS, table_rows(plans))
    if kit.assembly:
        w.progress("kit: the picture of the kit assembled")
        _assembly_picture(w, kit, piece_meshes)
    from .guide import write_guide

    w.progress("kit: the print guide and the pictures of its assembly steps")
    write_guide(kit, w, plans, assembled_meshes(kit, piece_meshes) if kit.assembly else [], sliced, w.title)
    w.derived.update({"printer": p.name, "bed_mm": list(p.bed), "scale_S": kit.scale.S, "plates": len(plates),
                      "pieces": len(flat), "pieces_volume_cm3": sum(q.volume_cm3 for q in plans),
                      "filament_estimate_g": sum(q.estimate_g for q in plans), "infill_percent": p.infill_percent})
    if sliced and all(q.time_s is not None for q in plans):
        w.derived.update({"print_time_s": sum(q.time_s for q in plans),
                          "filament_sliced_g": sum(q.filament_g for q in plans)})
    w.derived.update(kit.derived)
    for name, columns, rows in kit.tables:
        w.add_table(name, columns, rows)
    w.expected_failures |= set(kit.expected_failures)
    w.add_checks(kit.checks)
    _report_lead(kit, w, plans, sliced)
    w.add_note("The maker's guide — what to print, with what, how long, the hardware, the clearance coupon and the "
               "assembly with pictures — is [print_guide.html](print_guide.html) (its text: "
               "[print_guide.md](print_guide.md)).")
    w.add_note("FDM allowances applied to the printed geometry: " + "; ".join(
        f"{name} {value:g} mm ({how})" for name, value, how in kit.allowances) + ".")
    for n in kit.notes:
        w.add_note(n)


def _skirt_text(p: Printer) -> str:
    """The skirt the plates' settings ask for, as the report says it."""
    loops, distance = p.skirt()
    if not loops:
        return "no room for a skirt: the plates ask for none"
    return f"room for the slicer's skirt, {loops} loop {distance:g} mm out of the pieces"


def _report_lead(kit: Kit, w, plans, sliced: bool) -> None:
    """The kit report opens as a maker reads it: what to print, on which printer with which settings, how
    long and how much filament, then the hardware and the assembly; the proofs follow, and the inputs
    (those of the full-size design, from the part file) close it as an appendix."""
    from ..export.report import md_text
    from .guide import plates_lines
    from .slicer import slicer_path

    p = kit.printer
    lead = ["## What to print", "",
            f"Printer: {md_text(p.label)}; each plate's pieces centred on the bed, at least {p.margin_mm:g} mm from "
            f"its edges ({_skirt_text(p)}), and each plate file carries these print settings for the slicer. "
            f"Scale {kit.scale.label}: {md_text(kit.scale.reason)}.", "",
            f"Print settings: {md_text(p.settings_text)}.", ""]
    lead += plates_lines(p, plans, sliced)
    if not sliced and slicer_path() is None:
        lead += ["PrusaSlicer is not installed here: with it (`apt-get install prusa-slicer`) `propulsor print` "
                 "slices every plate for its print time and filament.", ""]
    lead += ["## Assembly", ""]
    if kit.hardware:
        lead += ["Hardware a maker may use instead of printed pins (the holes fit either):", ""]
        lead += [f"- {h.count} × {md_text(h.what)}" + (f" (instead of the printed `{md_text(h.instead_of)}`)"
                                                       if h.instead_of else "") for h in kit.hardware] + [""]
    lead += [f"{k}. {md_text(step)}" for k, step in enumerate(kit.steps, 1)] + [""]
    lead += ["The pictures of every step, the side and exploded views and the clearance coupon are in the "
             "maker's guide, [print_guide.html](print_guide.html).", ""]
    w.report_lead = lead
    w.inputs_heading = f"Appendix: the full-size design's inputs (the part file; the model prints at {kit.scale.label})"
    w.inputs_last = True
