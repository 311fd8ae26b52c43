"""The maker's guide of a kit (``print_guide.md`` and ``.html``): what to print, with what settings, how
long and how much filament, which material survives a hand on the crank (where the kit rates it), the hardware,
then the assembly step by step with pictures — the side view, the exploded view and one picture a step — and what
to change when parts are tight or loose.

Text from the part file (its title) and the kit's own names is written as text (escaped Markdown).
"""

from __future__ import annotations

from ..export.report import md_text
from .coupon import advice
from .planning import hours
from .views import SIDE, exploded, picture


def _cell(text) -> str:
    return md_text(text).replace("|", "\\|")


def _table(head, rows) -> list[str]:
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    return out + ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows] + [""]


def plates_lines(p, plans, sliced: bool) -> list[str]:
    """The plates as a maker prints them (Markdown): a table of each plate's pieces, time and filament,
    then the totals (PrusaSlicer's for the printer's settings), or the estimate when not sliced."""
    total_t = sum(q.time_s or 0 for q in plans) if sliced else None
    rows = []
    for q in plans:
        rows.append([f"plate {q.plate}", str(q.pieces), hours(q.time_s) if sliced else "not sliced",
                     f"{q.filament_g:.0f} g" if sliced and q.filament_g is not None else f"about {q.estimate_g:.0f} g",
                     q.names])
    lines = _table(["plate", "pieces", "time", "filament", "what"], rows)
    if sliced:
        lines += [f"In all: {hours(total_t)} of printing, {sum(q.filament_g or 0 for q in plans):.0f} g of "
                  f"filament (PrusaSlicer's estimate for these settings).", ""]
    else:
        lines += [f"Not sliced (PrusaSlicer is not installed, or `--slice no`): the filament is estimated at "
                  f"{p.infill_percent:g} % infill and {p.perimeters} perimeters; no print time.", ""]
    return lines


def step_pictures(w, kit, items) -> list[str | None]:
    """One picture a step: the pieces placed by then, the step's own in colour (kit.step_parts: the
    labels each step adds)."""
    out: list[str | None] = []
    shown: set[str] = set()
    for k, labels in enumerate(kit.step_parts, 1):
        if not labels:
            out.append(None)
            continue
        now = shown | set(labels)
        sel = [it for it in items if it[0] in now]
        out.append(picture(w, f"step_{k}", sel, f"step {k}", dim=shown) if sel else None)
        shown = now
    return out


def write_guide(kit, w, plans, items, sliced: bool, title: str) -> None:
    """print_guide.md (+ .html) into the writer's folder; items: the assembled model [(label, mesh, colour)]."""
    from ..export.html import write_report_html

    p = kit.printer
    title = title[len("Print kit: "):] if title.startswith("Print kit: ") else title
    lines = [f"# Print guide: {md_text(title)}", ""]
    lines += [f"Printer: {md_text(p.label)}. Scale {kit.scale.label} ({md_text(kit.scale.reason)}).", ""]
    lines += ["## 1. What to print", ""]
    lines += [f"Settings: {md_text(p.settings_text)}. Every piece lies on the face it is laid on in the plate "
              f"files (`plate_<k>.3mf`, one object a piece, mm); pins, axles and handles lie on the flat along "
              f"their side so that their layers run along them.", "",
              f"Each plate file carries these settings as a PrusaSlicer project (open it as a project: the printer "
              f"gets what the times and grams below assume); its pieces sit centred on the bed, at least "
              f"{p.margin_mm:g} mm from its edges, so that the slicer's skirt stays on the bed. Keep them where they "
              f"are: PrusaSlicer's window keeps a project's positions, but its command line arranges the pieces "
              f"anew unless told not to (`prusa-slicer --export-gcode --dont-arrange plate_1.3mf`), and the skirt "
              f"around a full plate arranged to the bed's edges leaves the bed.", ""]
    lines += plates_lines(p, plans, sliced)
    lines += _table(["piece", "count", "what"], [[pc.name, str(pc.count), pc.what] for pc in kit.pieces])
    if kit.material_notes:
        lines += ["### Which material: a hand on the crank", ""] + [md_text(t) + "\n" for t in kit.material_notes]
        if kit.material_table is not None:
            lines += _table(*kit.material_table)
    if kit.hardware:
        lines += ["## 2. Hardware", "", "Steel pins fit the same holes as the printed ones:", ""]
        lines += [f"- {h.count} × {md_text(h.what)}" + (f" (instead of the printed `{md_text(h.instead_of)}`)"
                                                        if h.instead_of else "") for h in kit.hardware] + [""]
    lines += ["## 3. Test the fits first", ""] + [f"{k}. {t}" for k, t in enumerate(advice(p), 1)] + [""]
    lines += ["## 4. Assembly", ""]
    if items:
        side = picture(w, "assembled_side", items, f"{kit.part}: side view", view=SIDE)
        span = max(float(m.bounds[1][2] - m.bounds[0][2]) for _, m, _ in items)
        expl = picture(w, "exploded", exploded(items, 1.0 * span + 5.0), f"{kit.part}: exploded view")
        lines += [f"![side view]({side})", "", f"![exploded view]({expl})", ""]
    pics = step_pictures(w, kit, items) if items else []
    for k, step in enumerate(kit.steps, 1):
        lines += [f"{k}. {md_text(step)}", ""]
        if k <= len(pics) and pics[k - 1]:
            # indented by four: the picture stays inside its step's item, and the steps one list numbered 1, 2, 3 …
            lines += [f"    ![step {k}]({pics[k - 1]})", ""]
    lines += ["## 5. Tight or loose?", "",
              f"- A wheel that binds on its pin: `--set running_clearance_mm={p.running_clearance_mm + 0.1:g}`; "
              f"one that wobbles: `{max(0.1, p.running_clearance_mm - 0.1):g}`.",
              f"- A pin that will not press in: `--set press_fit_mm=0`; one that falls out: "
              f"`--set press_fit_mm={p.press_fit_mm + 0.05:g}` (or a drop of glue).",
              f"- Gears that grind: `--set backlash_mm={p.backlash_mm + 0.1:g}`; gears that knock: "
              f"`{max(0.1, p.backlash_mm - 0.1):g}`.",
              ""]
    if kit.guide_notes:
        lines += ["## 6. As printed", ""] + [md_text(t) + "\n" for t in kit.guide_notes]
    lines += ["The proofs of the printed geometry are in [print_report.html](print_report.html) (its text: "
              "[print_report.md](print_report.md)).", ""]
    path = w.path("print_guide.md")
    path.write_text("\n".join(lines), encoding="utf-8")
    w.path("print_guide.html")
    write_report_html(path)
