"""The pair as built in the report: derived values, checks, the table of stretches that depart from the law and
the plot of the driven speed in both directions (:mod:`.as_built`)."""

from __future__ import annotations

import math

import numpy as np

from ...check import Check
from ...checks.motion.contact_events import KINDS
from ...laws.law import is_walking
from .as_built import AsBuilt, as_built, combine

__all__ = ["as_built_values", "as_built_checks", "tooth_height_check", "stretch_rows", "tolerance_values",
           "tolerance_check"]

_STRETCH_COLUMNS = ["direction", "driver_from_deg", "driver_to_deg", "driven_from_deg", "driven_to_deg", "kinds",
                    "driver_teeth", "driven_teeth", "speed_min_rel", "speed_max_rel"]


def _result(dd, built: dict, progress=None) -> AsBuilt | None:
    jobs = built.get("as_built")
    if jobs is None:
        return as_built(dd.d, dd.mount, built["proof"])
    if jobs == ():
        return None
    drive, reverse = _collected(jobs, progress, "as built: both directions' contact", "direction")
    if isinstance(drive, tuple):  # the drive direction's job measured the load per tooth on its contact too
        drive, built["tooth_load"] = drive
    return combine(dd.d, drive, reverse)


def _collected(jobs, progress, phase: str, unit: str) -> list:
    """The results of the jobs in their order, counted as they come when some run in workers (those run in
    this process were counted when they ran)."""
    from ...parallel import Done, result
    from ...progress import counter

    if all(isinstance(j, Done) for j in jobs):
        return [j.result() for j in jobs]
    if any(hasattr(j, "propulsor_ticks") for j in jobs):  # they count themselves while they are waited for
        return [result(j) for j in jobs]
    tick = counter(progress, phase, len(jobs), unit)
    out = []
    for k, j in enumerate(jobs):
        out.append(j.result())
        tick(k + 1)
    return out


def tooth_height_check(d, p) -> Check | None:
    """Every tooth keeps ``p.tooth_height_min_share`` of its addendum (h_a* + x) m (the driver shifted by +x, the
    driven wheel by -x); the teeth below are named (generated teeth)."""
    from .design import _rack

    if d.method != "generated":
        return None
    share_min = p.tooth_height_min_share
    h_a_star = _rack(p).h_a_star
    low, least, shortened = [], (math.inf, ""), 0
    for gear, x in ((d.driver, p.driver_shift), (d.driven, -p.driver_shift)):
        h_a = (h_a_star + x) * d.m
        for k, t in enumerate(gear.teeth):
            share = t.tip_height_mm / h_a
            shortened += bool(t.shortened)
            if share < least[0]:
                least = (share, f"{gear.role} tooth {k}")
            if share < share_min:
                low.append(f"{gear.role} {k} ({share:.3f})")
    msg = (f"least share of the addendum {least[0]:.3f} ({least[1]}); {shortened} tips shortened where pointed"
           + (f"; below {share_min:g}: " + ", ".join(low) if low else ""))
    return Check.at_least("teeth.tooth_height", least[0], share_min, "", msg)


def as_built_checks(ab: AsBuilt, p, law_ripple: float | None) -> list[Check]:
    """The as-built checks, each with its part-file limit."""
    out = []
    if ab.hub:
        lim = law_ripple + p.as_built_ripple_margin
        dr, rv = ab.hub
        out.append(Check.at_most("as_built.hub_speed_ripple", ab.ripple, lim, "",
                                 f"hub speed ripple as built {100 * dr.ripple:.3f} % (drive), {100 * rv.ripple:.3f} % "
                                 f"(reverse) against the law's {100 * law_ripple:.3f} % + {100 * p.as_built_ripple_margin:g} "
                                 "points"))
    steps = []
    for c in ab.directions:
        at = c.step_at()
        steps.append(f"{c.name} {100 * c.step_max:.3f} %" + (f" at driver {math.degrees(at[1]):.3f} deg" if at else ""))
    out.append(Check.at_most("as_built.speed_step", ab.step_max, p.speed_step_max, "",
                             "largest change of the driven speed across a change of contact: " + "; ".join(steps)))
    run, where = ab.corner_run_max_deg()
    out.append(Check.at_most("as_built.corner_load", run, p.corner_run_max_deg, "deg",
                             f"longest run of driver angle with the load on a tooth corner {run:.3f} deg"
                             + (f" ({where})" if where else "") + f"; share of the cycle on a corner "
                             f"{100 * ab.drive.edge_share:.2f} % (drive), {100 * ab.reverse.edge_share:.2f} % (reverse)"))
    lost = sum(int(np.count_nonzero(~np.isfinite(c.te))) for c in ab.directions)
    out.append(Check.at_most("as_built.contact", lost, 0, "samples",
                             f"{lost} samples without a contact within the largest free rotation"))
    return out


def stretch_rows(ab: AsBuilt) -> list[list]:
    rows = []
    for c in ab.directions:
        for s in c.stretches():
            rows.append([c.name, s.theta_from_deg, s.theta_to_deg, math.degrees(s.phi_from_rad),
                         math.degrees(s.phi_to_rad), "; ".join(s.kinds), " ".join(map(str, s.driver_teeth)),
                         " ".join(map(str, s.driven_teeth)), s.speed_min, s.speed_max])
    return rows


def _plot(w, d, ab: AsBuilt) -> None:  # pragma: no mutate block (the figure only)
    from ...export.plots import new_figure

    fig, ax = new_figure()
    for c, style in zip(ab.directions, ("C0-", "C3-")):
        x = np.repeat(np.degrees(c.phi), 2)[1:-1]
        y = np.repeat(c.speed, 2)
        ax.plot(x, y, style, lw=0.7, label=f"{c.name}: {c.speed_min:.4f} .. {c.speed_max:.4f}")
    ax.axhline(1.0, color="k", ls="--", lw=0.8, label="the law")
    ax.set_xlabel("driven angle phi over one period, deg")
    ax.set_ylabel("driven speed over the law's at the same driver angle")
    ax.set_title("As built: the driven speed the finished outlines deliver, both directions")
    ax.legend(fontsize=7)
    fig.tight_layout()
    w.add_plot("as_built_speed", fig)
    if ab.hub:
        from .as_built import as_built_speed

        fig, ax = new_figure()
        mean = d.law.hub_speed_ratio
        ph = np.linspace(ab.drive.phi[0], ab.drive.phi[-1], 4001)
        ax.plot(np.degrees(ph), d.run_law.hub_speed(ph) / mean, "k--", lw=0.9,
                label=f"the law (blend): ripple {100 * d.ripple.ripple:.2f} %")
        for c, h, style in zip(ab.directions, ab.hub, ("C0-", "C3-")):
            ok = np.isfinite(c.te)
            g, v = as_built_speed(d.law, d.run_law, c.phi[ok], c.te[ok])
            ax.plot(np.degrees(g), v / mean, style, lw=0.6, label=f"as built, {c.name}: ripple {100 * h.ripple:.2f} %")
        ax.set_xlabel("driven angle phi, deg")
        ax.set_ylabel("hub speed v/omega over its mean")
        ax.set_title("As built: hub speed over one leg (seed 000 eq. 2-3)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        w.add_plot("as_built_hub_speed", fig)


def as_built_values(w, dd, built: dict) -> None:
    """Derived values, checks, the stretches' table, plots and a note of the pair as built."""
    d, p = dd.d, dd.p
    ab = _result(dd, built, w.progress)
    w.progress("as built: speeds, transmission error, backlash and stretches from the contact positions")
    hc = tooth_height_check(d, p)
    if hc is not None:
        w.add_checks([hc])
    if ab is None:
        w.add_note("As built: not measured - the proof found phases without a running position (jam).")
        _tooth_load(w, dd, built, None)
        return tolerance_values(w, dd, built)
    walking = is_walking(d.law)
    w.add_checks(as_built_checks(ab, p, d.ripple.ripple if walking else None))
    dr, rv = ab.drive, ab.reverse
    vals = {
        "te_min_rad": float(np.nanmin(dr.te)), "te_max_rad": float(np.nanmax(dr.te)), "te_pp_rad": dr.te_pp,
        "te_pp_reverse_rad": rv.te_pp,
        "backlash_min_mm": ab.backlash_min_mm, "backlash_max_mm": ab.backlash_max_mm,
        "backlash_min_phi_deg": math.degrees(ab.backlash_min_phi),
        "speed_as_built_min": dr.speed_min, "speed_as_built_max": dr.speed_max,
        "speed_as_built_reverse_min": rv.speed_min, "speed_as_built_reverse_max": rv.speed_max,
        "speed_step_max": dr.step_max, "speed_step_reverse_max": rv.step_max,
        "corner_contact_share": dr.edge_share, "corner_contact_reverse_share": rv.edge_share,
        "corner_run_max_deg": ab.corner_run_max_deg()[0],
        "as_built_span_deg": math.degrees(ab.span), "as_built_evaluations": ab.evaluations,
        "as_built_stretches": len(stretch_rows(ab)),
    }
    if walking:
        h0, h1 = ab.hub
        vals.update({"speed_ripple_as_built": ab.ripple, "speed_ripple_as_built_drive": h0.ripple,
                     "speed_ripple_as_built_reverse": h1.ripple, "speed_as_built_min_rel": h0.v_min_rel,
                     "speed_as_built_max_rel": h0.v_max_rel, "speed_as_built_phi_min_deg": math.degrees(h0.phi_min),
                     "speed_as_built_phi_max_deg": math.degrees(h0.phi_max)})
    w.derived.update(vals)  # their meanings: the part type's glossary (AS_BUILT)
    w.add_table("as_built_stretches", _STRETCH_COLUMNS, stretch_rows(ab))
    if w.draws_plots:  # a proof's values only: no figure drawn to be dropped
        w.progress("as built: the plot of the driven speed and the transmission error")
        _plot(w, d, ab)
    from ... import policy

    proof = built["proof"].summary()  # the motion proof's phase samples, beside the contact positions resolved here
    hub = (f"hub speed ripple as built {100 * ab.hub[0].ripple:.2f} % (drive) and {100 * ab.hub[1].ripple:.2f} % "
           f"(reverse) against the law's {100 * d.ripple.ripple:.2f} %; " if walking else "")
    w.add_note(
        f"As built: both directions' loaded contact on the finished outlines at the installed centre distance, "
        f"sampled every {policy.CONTACT_STEP_DRIVER_DEG:g} deg of driver over one period ({math.degrees(ab.span):.1f} "
        f"deg of the driven wheel) and every change of the tooth pair or contact kind ({', '.join(KINDS)}) located "
        f"to {policy.CONTACT_EVENT_STEP_RAD:g} rad ({ab.evaluations} contact positions): {hub}driven speed over the "
        f"law's {dr.speed_min:.4f} .. {dr.speed_max:.4f} (drive), {rv.speed_min:.4f} .. {rv.speed_max:.4f} "
        f"(reverse); largest step at a change of contact {100 * ab.step_max:.2f} %; transmission error "
        f"peak-to-peak {dr.te_pp:.3e} rad (drive), {rv.te_pp:.3e} rad (reverse); least backlash "
        f"{ab.backlash_min_mm:.5f} mm (backlash_min_mm, over every contact position; the motion proof's "
        f"{proof['steps']} phases alone give {proof['backlash_min_mm']:.5f} mm); load on a corner {100 * dr.edge_share:.2f} % / {100 * rv.edge_share:.2f} % "
        f"of the cycle.  tables/as_built_stretches.csv lists every stretch whose speed is off the law's by more than "
        f"{100 * policy.CONTACT_STRETCH_SPEED_TOL:g} % or whose contact is on a corner.")
    _tooth_load(w, dd, built, ab)
    tolerance_values(w, dd, built)


def _tooth_load(w, dd, built: dict, ab) -> None:
    """The load per tooth on the as-built contact (:mod:`.tooth_load_outputs`; nothing without a load case)."""
    from .tooth_load_outputs import tooth_load_values

    tooth_load_values(w, dd, built, ab)


_TOL_COLUMNS = ["case", "dL_um", "e_driver_um", "psi_driver_deg", "e_driven_um", "psi_driven_deg", "t_driver_um",
                "t_driven_um", "te_pp_drive_rad", "te_pp_reverse_rad", "backlash_min_mm", "backlash_min_phi_deg",
                "step_max", "step_driver_deg", "lost_samples"]


def tolerance_check(tol, worst, step_limit: float) -> Check:
    """No jam and no loss of contact at the worst case of the tolerances: every corner keeps backlash and a contact
    at every sample, and no change of contact steps the driven speed by more than ``step_limit``."""
    bad = []
    for r in worst:
        if r.jam:
            bad.append(f"{r.case.name}: jam (backlash {r.backlash_min_mm:.4f} mm at driven "
                       f"{math.degrees(r.backlash_min_phi):.2f} deg)")
        elif r.lost or r.step_max > step_limit:  # (a jammed case has no running position: no speed to speak of)
            bad.append(f"{r.case.name}: contact lost ({r.lost} samples without contact; speed step "
                       f"{100 * r.step_max:.2f} % at driver {math.degrees(r.step_theta):.2f} deg)")
    least = min(r.backlash_min_mm for r in worst)
    msg = (f"least backlash {least:.4f} mm over the worst-case corners of {tol.source}; largest speed step "
           f"{100 * max(r.step_max for r in worst):.2f} %" + ("; " + "; ".join(bad) if bad else ""))
    return Check("tolerance.worst_case", not bad, least, 0.0, "mm", msg)


def tolerance_rows(results) -> list[list]:
    return [[r.case.name, 1e3 * r.case.dL, 1e3 * r.case.e_driver, math.degrees(r.case.psi_driver),
             1e3 * r.case.e_driven, math.degrees(r.case.psi_driven), 1e3 * r.case.t_driver, 1e3 * r.case.t_driven,
             r.te_pp_drive, r.te_pp_reverse, r.backlash_min_mm, math.degrees(r.backlash_min_phi), r.step_max,
             math.degrees(r.step_theta), r.lost] for r in results]


def tolerance_values(w, dd, built: dict) -> None:
    """The pair made within the part file's accuracy grade: the cases' table, derived values, the worst-case check."""
    job = built.get("tolerance")
    if not job:
        return
    tol, jobs = job
    rs = _collected(jobs, w.progress, "as made: tolerance cases", "case")
    worst, mc = rs[:4], rs[4:]
    p = dd.p
    w.add_checks([tolerance_check(tol, worst, p.speed_step_max)])
    w.add_table("tolerance_cases", _TOL_COLUMNS, tolerance_rows(rs))
    vals = {"tolerance_grade": p.tolerance_grade, "tolerance_f_a_mm": tol.f_a,
            "tolerance_runout_driver_mm": 2 * tol.e_driver, "tolerance_runout_driven_mm": 2 * tol.e_driven,
            "tolerance_thinning_max_mm": tol.t_hi,
            "tolerance_backlash_min_mm": min(r.backlash_min_mm for r in worst),
            "tolerance_te_pp_max_rad": max(max(r.te_pp_drive, r.te_pp_reverse) for r in worst),
            "tolerance_step_max": max(r.step_max for r in worst), "tolerance_samples": len(mc)}
    if mc:
        bl = np.array([r.backlash_min_mm for r in mc])
        te = np.array([max(r.te_pp_drive, r.te_pp_reverse) for r in mc])
        vals.update({"tolerance_backlash_min_p5_mm": float(np.percentile(bl, 5)),
                     "tolerance_backlash_min_p50_mm": float(np.percentile(bl, 50)),
                     "tolerance_te_pp_p50_rad": float(np.percentile(te, 50)),
                     "tolerance_te_pp_p95_rad": float(np.percentile(te, 95))})
    w.derived.update(vals)
    w.add_note(
        f"As made ({tol.source}): the as-built transmission of the pair within these tolerances, both directions over "
        f"the whole driven turn, at the 4 worst-case corners (tight: L - f_a with the thickest teeth; loose: L + f_a "
        f"with the thinnest; each with the wheels' run-outs in phase and opposed) and {len(mc)} Monte Carlo cases "
        f"(seed {p.tolerance_seed}): least backlash {vals['tolerance_backlash_min_mm']:.4f} mm at the worst case, "
        f"transmission error peak-to-peak up to {vals['tolerance_te_pp_max_rad']:.3e} rad, largest speed step "
        f"{100 * vals['tolerance_step_max']:.2f} %"
        + (f"; Monte Carlo least backlash 5 % / 50 %: {vals['tolerance_backlash_min_p5_mm']:.4f} / "
           f"{vals['tolerance_backlash_min_p50_mm']:.4f} mm, TE peak-to-peak 50 % / 95 %: "
           f"{vals['tolerance_te_pp_p50_rad']:.3e} / {vals['tolerance_te_pp_p95_rad']:.3e} rad" if mc else "")
        + ".  tables/tolerance_cases.csv lists every case.")
