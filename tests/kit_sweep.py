"""The sweep of print kits over every printer profile, made affordable without skipping a profile.

Every profile (each built-in one and a quick ``--bed 180x180x180``) still runs ``propulsor print`` to
exit 0 with its own kit folder, checks and plates; what is shared is only work whose result cannot
differ between them:

- **the kit's design** (:class:`KitMemo`): profiles whose settings are equal but for their name and
  title (e.g. the Bambu A1, P1 and X1: the same 256 mm bed, nozzle, margins and allowances) get the
  same kit, computed once — the same pieces, placed for their own printer;
- **the printed pieces** (tessellation, bed-side chamfer and mesh checks of each solid), computed once
  for the same solid; the clearance coupon made once for the same allowances, whatever the bed;
- **the pictures of the assembled model** (side, exploded, step views), drawn once for the same meshes
  placed alike under the same title;
- **the noncircular pair's design** at the same parameters (the full-size pair whose size sets the
  scale, and the printed pair at one scale with one printer's allowances), whichever bed asked, and the
  rating of that printed pair under the hand on its crank (the same pair, the same handle radius);
- **the slicing** (:class:`SharedSlicer`): a plate file with the same bytes (same pieces at the same
  places) and the same print settings is sliced once by PrusaSlicer, on a bed that every profile that
  laid it out holds (the beds are rectangles from the origin), and every object's extents and every
  extrusion of the G-code (skirt too) are checked against each profile's own bed.  The G-code's time and filament do not depend on the bed's size.
  The slicing runs beside the building of the next profile's kit.
"""

from __future__ import annotations

import dataclasses
import hashlib
from pathlib import Path

import numpy as np

from propulsor.printing.printers import Printer, load_printer, printer_names

#: the quick profile of the sweep (--bed)
QUICK_BED = "180x180x180"


def profiles() -> list[tuple[str, list[str], Printer]]:
    """(label, propulsor print arguments, Printer) of every built-in profile and of --bed 180x180x180."""
    out = [(n, ["--printer", n], load_printer(n)) for n in printer_names()]
    return out + [("bed180", ["--bed", QUICK_BED], load_printer("generic", bed=QUICK_BED))]


def kit_key(p: Printer) -> tuple:
    """What a kit depends on: every setting of the profile but its name and title."""
    return tuple(v for f, v in dataclasses.asdict(p).items() if f not in ("name", "title"))


def _print_settings(p: Printer) -> tuple:
    """The slicer settings but the bed's size."""
    return kit_key(dataclasses.replace(p, bed_x_mm=100.0, bed_y_mm=100.0, bed_z_mm=100.0))


class KitMemo:
    """Shares the kit design and printed pieces between profiles (install with pytest's monkeypatch;
    one memo per part file, dropped after it)."""

    def __init__(self, monkeypatch):
        import propulsor.parts as parts
        import propulsor.printing.kit as kit_mod

        self.kits: dict = {}
        self.pieces: dict = {}
        self.designs: dict = {}
        self.hits = {"kit": 0, "piece": 0, "design": 0, "hand_load": 0}
        real_get_kit = parts.get_kit

        def get_kit(name):
            make = real_get_kit(name)

            def kit(params, printer, scale=None, source=None):
                key = (name, repr(params), str(source), kit_key(printer), scale)
                if key in self.kits:
                    self.hits["kit"] += 1
                    k = self.kits[key]
                    return dataclasses.replace(k, printer=printer, pieces=list(k.pieces))
                k = make(params, printer, scale, source=source)
                self.kits[key] = dataclasses.replace(k, pieces=list(k.pieces))
                return k

            if name == "noncircular_pair":
                self._share_pair_design()
            return kit

        real_inline = kit_mod.inline

        def inline(fn, *args):
            key = (fn.__name__, id(args[0]), args[1:])
            if key not in self.pieces:
                self.pieces[key] = (args[0], real_inline(fn, *args))  # the solid kept: its id stays its own
            else:
                self.hits["piece"] += 1
            return self.pieces[key][1]

        self._mp = monkeypatch
        self._share_pictures()
        import propulsor.printing.coupon as coupon

        real_coupon = coupon.coupon_pieces
        coupons: dict = {}

        def coupon_pieces(printer):  # the same coupon for the same allowances, whatever the bed
            key = _print_settings(printer)
            if key not in coupons:
                coupons[key] = real_coupon(printer)
            return list(coupons[key])

        monkeypatch.setattr(coupon, "coupon_pieces", coupon_pieces)
        monkeypatch.setattr(parts, "get_kit", get_kit)
        # the pieces made in this process (no forked workers), so that the memo sees them
        monkeypatch.setattr(kit_mod, "fork_pool", lambda n: None)
        monkeypatch.setattr(kit_mod, "inline", inline)

    def _share_pictures(self) -> None:
        """The pictures of the assembled model (guide and report) drawn once for the same meshes, placed
        alike under the same title: a kit equal but for its printer's name draws the same picture."""
        import propulsor.printing.guide as guide
        import propulsor.printing.kit as kit_mod

        self.pictures: dict = {}
        self.hits["picture"] = 0

        def digest(mesh) -> str:
            return hashlib.sha1(np.ascontiguousarray(mesh.vertices).tobytes()
                                + np.ascontiguousarray(mesh.faces).tobytes()).hexdigest()

        def shared(w, name: str, key, draw) -> str:
            rel = f"plots/{name}.png"
            if key in self.pictures:
                self.hits["picture"] += 1
                w.path(rel).write_bytes(self.pictures[key])
                w.plots.append(rel)
            else:
                draw()
                self.pictures[key] = w.path(rel).read_bytes()
            return rel

        real_picture, real_assembled = guide.picture, kit_mod._assembly_picture

        def picture(w, name, items, title, *args, **kwargs):
            key = ("view", name, title, repr(args), repr(sorted(kwargs.items(), key=lambda kv: kv[0])),
                   tuple((label, str(colour), digest(m)) for label, m, colour in items))
            return shared(w, name, key, lambda: real_picture(w, name, items, title, *args, **kwargs))

        def assembly_picture(w, kit, meshes):
            key = ("assembled", kit.part, kit.scale.label,
                   tuple((pl.label, pl.piece, np.asarray(pl.matrix).tobytes(), str(pl.colour)) for pl in kit.assembly),
                   tuple((n, digest(m)) for n, m in sorted(meshes.items())))
            shared(w, "assembled", key, lambda: real_assembled(w, kit, meshes))

        self._mp.setattr(guide, "picture", picture)
        self._mp.setattr(kit_mod, "_assembly_picture", assembly_picture)

    def _share_pair_design(self) -> None:
        import propulsor.parts.noncircular_pair.kit as ncg

        if getattr(ncg.pair_design, "_memo", None) is self:
            return
        real = ncg.pair_design

        def pair_design(p, source=None):
            key = (repr(p), str(source))
            if key in self.designs:
                self.hits["design"] += 1
            else:
                self.designs[key] = real(p, source)
            return self.designs[key]

        pair_design._memo = self
        self._mp.setattr(ncg, "pair_design", pair_design)
        real_hand = ncg.hand_load
        hands: dict = {}

        def hand_load(q, kd, r_h, *args, **kw):  # the same printed pair (memoised above) and crank: the same rating
            key = (repr(q), id(kd), r_h, args, repr(sorted(kw.items())))
            if key in hands:
                self.hits["hand_load"] += 1
            else:
                hands[key] = (kd, real_hand(q, kd, r_h, *args, **kw))  # kd kept: its id stays its own
            return hands[key][1]

        self._mp.setattr(ncg, "hand_load", hand_load)


class SharedSlicer:
    """Slices the plates of kit folders as they are made (two PrusaSlicer runs at a time, beside the
    building of the next kit): a plate file with the same bytes and print settings as one already
    submitted is not sliced again when this profile's bed contains the bed it was sliced on (profiles
    come smallest bed first); else it is sliced again, on the overlap of the beds.  Every object's extents are then checked against each profile's
    own bed."""

    def __init__(self, work: Path, workers: int = 2):
        from concurrent.futures import ThreadPoolExecutor

        self.work = Path(work)
        self.pool = ThreadPoolExecutor(workers)
        self.runs: list = []  # (plate settings key, bed (x, y, z), future)
        self.members: list = []  # (label, plate path, printer, future)

    def _slice(self, plate: Path, printer: Printer):
        from propulsor.printing.slicer import slice_plate

        gcode = self.work / f"slice_{len(self.runs)}.gcode"
        return self.pool.submit(slice_plate, plate, printer.bed_shape(), gcode, args=printer.slicer_args())

    def add(self, label: str, folder: Path, printer: Printer) -> int:
        """Submit the plates of one kit folder; the number of its plates."""
        plates = sorted(Path(folder).glob("plate_*.3mf"))
        for plate in plates:
            key = (hashlib.sha256(plate.read_bytes()).hexdigest(), _print_settings(printer))
            fut = next((f for k, bed, f in self.runs if k == key and all(b <= own + 1e-9 for b, own in
                                                                          zip(bed, printer.bed))), None)
            if fut is None:
                earlier = [bed for k, bed, _ in self.runs if k == key]
                bed = tuple(min([own] + [b[i] for b in earlier]) for i, own in enumerate(printer.bed))
                on = dataclasses.replace(printer, bed_x_mm=bed[0], bed_y_mm=bed[1], bed_z_mm=bed[2])
                fut = self._slice(plate, on)
                self.runs.append((key, bed, fut))
            self.members.append((label, plate, printer, fut))
        return len(plates)

    def failures(self) -> list[str]:
        """Wait for every run; what failed, naming the profile and the plate."""
        out = []
        for label, plate, printer, fut in self.members:
            r = fut.result()
            off = r.off_bed(printer.bed_x_mm, printer.bed_y_mm)
            if r.ok:  # every line the G-code lays (the skirt too) on this profile's bed
                off += r.extrusions_off_bed(printer.bed_x_mm, printer.bed_y_mm)
            off += [f"object {j} above {printer.bed_z_mm:g} mm" for j, o in enumerate(r.objects, 1)
                    if float(o.get("max_z", o.get("size_z", 0.0))) > printer.bed_z_mm + 1e-3]
            if not (r.ok and r.all_manifold and not off and r.stats.get("time_s", 0) > 0):
                out.append(f"{label}: {plate.name}: {r.message}; manifold: {r.all_manifold}; off the bed: {off}; "
                           f"objects: {r.objects}")
        self.pool.shutdown()
        return out
