"""The composite gear's proofs and derived tables: synthesis (eq. 1–4), the proof of every position on
the finished outlines (:mod:`.mesh_proof`, eq. 4–8 measured), tooth position error (eq. 15–22),
friction loss (eq. 12–14) and torsional dynamics (eq. 9–11)."""

from __future__ import annotations

import math

import numpy as np

from ... import policy
from ...check import Check
from ...parallel import start as start_in_fork
from .design import PolysectorDesign

__all__ = ["synthesis_step", "start_proofs", "proof_results", "position_error_step", "efficiency_step",
           "dynamics_step", "prove_positions", "chord_for", "full_turn", "eq7_max_di", "law_checks"]


def eq7_max_di(dd: PolysectorDesign, pos) -> float:
    """Largest |Δi| of eq. 7/8 (flank contact) over the sector's engagement."""
    u = np.linspace(-pos.u_exit, pos.u_exit, 201)
    return float(np.max(np.abs((pos.ratio_nominal - dd.geo.ratio_flank(pos.offset, u)) / pos.ratio_nominal)))


def law_checks(name: str, law) -> list:
    """The hand-over checks of a tracked contact law (:class:`.contact_law.LawResult`): no tip-on-tip contact,
    no snap above ``policy.POLYSECTOR_SNAP_TOL_DEG``."""
    step = math.degrees(law.step_min)
    return [Check.at_most(f"{name}.no_tip_on_tip", math.degrees(law.tip_tip_angle()), 0.0, "deg",
                          f"wheel turn per sector period over which the gear rests on tips only (tip land or corner of "
                          f"both bodies), tracked contact law, {len(law.phi)} steps down to {step:.4f}° at every "
                          f"hand-over"),
            Check.at_most(f"{name}.no_snap", math.degrees(law.snap_max()), policy.POLYSECTOR_SNAP_TOL_DEG, "deg",
                          f"largest jump of the gear beyond its nominal advance within one finest step ({step:.4f}° "
                          f"of wheel turn)")]


def chord_for(dd: PolysectorDesign, pos) -> float:
    """Chord tolerance of a position's proof: the finer one where eq. 7 predicts a conjugate mesh."""
    if eq7_max_di(dd, pos) < policy.POLYSECTOR_CONJUGATE_DI:
        return policy.POLYSECTOR_PROOF_CHORD_TOL_CONJUGATE_MM
    return policy.POLYSECTOR_PROOF_CHORD_TOL_MM


def prove_positions(dd: PolysectorDesign, ks) -> list:
    from .mesh_proof import prove_position

    return [prove_position(dd, dd.positions[k], None, chord_for(dd, dd.positions[k])) for k in ks]


def synthesis_step(dd: PolysectorDesign, w, built: dict) -> None:
    """Eq. 1–4: the largest offset, z_c, the positions; derived values, checks, the positions table."""
    from ...gears.polysector import EPS_S_MAX, EPS_S_MIN, delta_eq1_printed, epsilon_alpha_pair, sector_teeth_eq2

    p, geo = dd.p, dd.geo
    w.progress("synthesis (seed 003 eq. 1-4)")
    cp = geo.corner_pose(dd.e_max)
    d_in, d_out = geo.tip_land()
    d = w.derived
    d.update({
        "r_blank_mm": geo.r, "r_b_blank_mm": geo.r_b, "r_a_blank_mm": geo.r_a, "r_gear_mm": geo.r2,
        "r_a_gear_mm": geo.r_a2, "empty_pitches_k": geo.k_gap,
        "z_c_eq2": sector_teeth_eq2(p.blank_teeth, p.sectors_per_flow, geo.k_gap),
        "delta_eq3_rad": d_in, "delta_eq1_swapped_rad": d_out,
        "delta_eq1_printed_rad": delta_eq1_printed(p.sector_teeth, p.blank_teeth, geo.alpha, geo.r_b, geo.r_a),
        "offset_max_mm": dd.e_max, "z_cond_max": p.blank_teeth + 2 * dd.e_max / p.module_mm,
        "eq3_O1C_mm": cp["O1C"], "eq3_CD_mm": cp["CD"], "eq3_beta2_rad": cp["beta2"], "eq3_u_exit_rad": cp["u_exit"],
        "eq3_residual_max_mm2": float(np.max(np.abs(cp["residuals"]))),
        "flank_overlap_one_flow_e0": geo.flank_overlap_one_flow(),
        "epsilon_alpha_blank_gear": epsilon_alpha_pair(p.blank_teeth, p.gear_teeth, p.module_mm, geo.alpha),
        "hub_radius_mm": dd.layout.R_hub, "bolt_radius_mm": dd.layout.rho_bolt,
    })
    rows = []
    for q in dd.positions:
        rows.append([q.k, q.z_cond, q.offset, p.module_mm * q.z_cond, q.a, q.ratio_nominal, q.eps_s_flow, q.eps_s,
                     q.u_exit, eq7_max_di(dd, q)])
        w.add_checks([Check.at_least(f"position{q.k}.epsilon_s_eq4", q.eps_s, EPS_S_MIN, "",
                                     f"eq. 4 (both flows, φ1 between the driving corners): ε_s = {q.eps_s:.4f} "
                                     f"(per flow {q.eps_s_flow:.4f}); the seed asks 1.05 … 1.3 at the largest offset"),
                      Check.at_most(f"position{q.k}.offset_eq3", q.offset, dd.e_max, "mm",
                                    f"offset {q.offset:g} mm within the largest offset of eq. 1/3, {dd.e_max:.4f} mm")])
    w.add_table("positions", ["position", "z_cond", "offset_mm", "d_cond_mm", "center_distance_mm", "ratio_nominal",
                              "epsilon_s_per_flow", "epsilon_s", "u_exit_rad", "delta_i_eq8_max"], rows)
    top = dd.positions[-1]
    eps_at_max = geo.epsilon_s(dd.e_max)[1]
    why_max = (f"ε_s = {eps_at_max:.4f} there; past it the leading tooth's driving corner no longer reaches the gear's "
               f"tip circle" if eps_at_max > EPS_S_MIN + 1e-6 else f"ε_s falls to {EPS_S_MIN} there")
    w.add_note(
        f"Synthesis (seed 003 eq. 1–4): blank z = {p.blank_teeth}, m = {p.module_mm:g} mm; {p.flows} flow(s) of "
        f"i_s = {p.sectors_per_flow} sectors of z_c = {p.sector_teeth} teeth (eq. 2: z/i_s − k with k = {geo.k_gap} "
        f"empty pitches); gear z2 = {p.gear_teeth}. Largest offset of eq. 1/3 with our closing condition "
        f"(ε_s ≥ {EPS_S_MIN} for both flows, φ1 from the leading tooth's driving corner entering the gear's tip "
        f"circle to the trailing tooth's driving corner leaving it): e_max = {dd.e_max:.4f} mm "
        f"(z_усл ≤ {d['z_cond_max']:.2f}; {why_max}); at it eq. 3's corner C (δ = {cp['delta']:.5f} rad) lies on the gear's tip "
        f"circle with O1C = {cp['O1C']:.4f} mm, CD = {cp['CD']:.4f} mm, β2 = {cp['beta2']:.5f} rad (rows of eq. 1/3 "
        f"agree within {d['eq3_residual_max_mm2']:.2g} mm²). The positions are the conditional tooth counts "
        f"{list(p.conditional_teeth)} (multiples of flows·i_s = {p.flows * p.sectors_per_flow}: every sector meets "
        f"the gear in tooth phase); the last has ε_s = {top.eps_s:.4f}"
        + (" — within the seed's 1.05 … 1.3." if EPS_S_MIN <= top.eps_s <= EPS_S_MAX else ".")
        + f" One flow alone overlaps (z_c − 1 + ε_α)/(z_c + k) = {geo.flank_overlap_one_flow():.4f} < 1 with flank "
        f"contact only at e = 0: the second flow is what keeps the mesh continuous.")


def start_proofs(dd: PolysectorDesign, w, built: dict) -> None:
    """The proofs of the positions in two forked workers (the solids are built meanwhile)."""
    n = len(dd.positions)
    w.progress(f"proof of {n} position(s) on the finished outlines, in two processes while the solids are built")
    order = sorted(range(n), key=lambda k: chord_for(dd, dd.positions[k]))  # the conjugate (slow) ones first
    halves = [order[0::2], order[1::2]]
    built["pending_proofs"] = [(ks, start_in_fork(prove_positions, dd, ks)) for ks in halves if ks]


def full_turn(dd: PolysectorDesign, pr) -> tuple[np.ndarray, ...]:
    """The period's measurements repeated over one full turn of the wheel: the sectors are the same
    outline turned by exactly one period and the gear advances period/i_n (a whole number of its
    pitches) per period, so θ(φ + period) = θ(φ) + period/i_n."""
    n_per = dd.p.flows * dd.p.sectors_per_flow
    phi = np.concatenate([pr.phi + k * pr.period for k in range(n_per)])
    theta = np.concatenate([pr.theta + k * pr.period / pr.ratio_nominal for k in range(n_per)])
    return phi, theta


def proof_results(dd: PolysectorDesign, w, built: dict) -> None:
    """Checks, tables, plots and the manifest's positions from the proofs."""
    from ...export.plots import new_figure
    from .contact_law import TYPES

    p, geo = dd.p, dd.geo
    proofs = {}
    for ks, fut in built.pop("pending_proofs"):
        for k, pr in zip(ks, fut.result()):
            proofs[k] = pr
    built["proofs"] = proofs
    w.progress("proofs done")
    tol = policy.OVERLAP_AREA_TOL_MM2
    positions = []
    # pragma: no mutate start (the figure only)
    fig, axes = new_figure(8.0, 7.0)
    fig.clf()
    ax1, ax2 = fig.add_subplot(2, 1, 1), fig.add_subplot(2, 1, 2)
    # pragma: no mutate end
    for k, q in enumerate(dd.positions):
        pr = proofs[k]
        it, di = pr.ratio_measured()
        law = pr.law
        kinds = law.kind[law.at(pr.phi)]
        ef, eb = pr.eps_s_measured()
        n_eng = pr.sectors_engaged
        two = float(np.mean(n_eng >= 2))
        ov = pr.overlap_flow.max(axis=0)
        di_max = law.ratio_error_max()
        shares = law.shares()
        tip_deg, snap_deg = math.degrees(law.tip_tip_angle()), math.degrees(law.snap_max())
        di_eq8 = (q.ratio_nominal - geo.ratio_flank(q.offset, pr.driver_u)) / q.ratio_nominal
        name = f"position{q.k}"
        for f in range(p.flows):
            w.add_checks([Check.at_most(f"{name}.flow{f + 1}.overlap_area", float(ov[f]), tol, "mm^2",
                                        f"gear against flow {f + 1}'s sectors at the measured pose, "
                                        f"{len(pr.phi)} steps of one sector period (the turn repeats it)")])
        w.add_checks([
            Check.at_least(f"{name}.contact_continuity", int(pr.pairs.min()), 1, "pairs",
                           f"tooth pairs in contact, both flows together: least {int(pr.pairs.min())}, "
                           f"mean {float(np.mean(pr.pairs)):.3f}"),
            Check.at_least(f"{name}.no_jam", float(np.nanmin(pr.coast_room)), 0.0, "rad",
                           "least room of the engaged sectors' other flanks at the pose the driving sector sets"),
            Check.equal_within(f"{name}.epsilon_s_measured", eb, q.eps_s, 0.0, policy.POLYSECTOR_EPS_S_MATCH, "",
                               f"ε_s measured on the outline's driving corners (engagement {pr.u_enter:.6f} … "
                               f"{pr.u_exit:.6f} rad) {eb:.5f} against eq. 4 {q.eps_s:.5f}"),
        ] + law_checks(name, law))
        positions.append({"offset_mm": q.offset, "center_distance_mm": q.a, "ratio_nominal": q.ratio_nominal,
                          "epsilon_s": eb, "epsilon_s_per_flow": ef, "ratio_error_max": di_max,
                          "contact_pairs_min": int(pr.pairs.min()),
                          "epsilon_s_eq4": q.eps_s, "z_cond": q.z_cond, "share_two_sectors_engaged": two,
                          "epsilon_s_steps": float(np.mean(n_eng)),
                          "share_two_pairs_in_contact": float(np.mean(pr.pairs >= 2)),
                          "transmission_error_pp_rad": float(np.ptp(law.te)),
                          "proof_chord_tol_mm": pr.chord_tol, "proof_steps_per_period": len(pr.phi),
                          "contact_shares": shares, "tip_on_tip_deg": tip_deg, "snap_max_deg": snap_deg,
                          "contact_law_steps_per_period": len(law.phi),
                          "contact_law_step_min_deg": math.degrees(law.step_min)})
        w.add_table(f"contact_law_{q.k}", ["phi_rad", "theta_rad", "te_rad", "driving_sector", "contact_type", "i_t",
                                           "delta_i"],
                    [[law.phi[i], law.theta[i], law.te[i], int(law.driver[i]) + 1, TYPES[law.kind[i]], law.i_t[i],
                      law.delta_i[i]] for i in range(len(law.phi))])
        phi_t, th_t = full_turn(dd, pr)
        w.add_table(f"transmission_{q.k}",
                    ["phi_rad", "theta_rad", "gear_rotation_ccw_rad", "theta_nominal_rad", "te_rad", "i_t",
                     "delta_i", "delta_i_eq8_flank", "driving_sector", "pairs_in_contact", "sectors_engaged",
                     "contact_type"],
                    [[phi_t[i], th_t[i], -th_t[i], phi_t[i] / q.ratio_nominal, th_t[i] - phi_t[i] / q.ratio_nominal,
                      it[i % len(pr.phi)], di[i % len(pr.phi)], di_eq8[i % len(pr.phi)],
                      int((pr.driver[i % len(pr.phi)] + (i // len(pr.phi))) % (p.flows * p.sectors_per_flow)) + 1,
                      int(pr.pairs[i % len(pr.phi)]), int(n_eng[i % len(pr.phi)]), TYPES[kinds[i % len(pr.phi)]]]
                     for i in range(len(phi_t))])
        # pragma: no mutate start (the figure only)
        ax1.plot(np.degrees(law.phi), law.te * 1e3, lw=0.9, label=f"e = {q.offset:g} mm")
        ax2.plot(np.degrees(law.phi), law.delta_i, lw=0.9, label=f"measured, e = {q.offset:g} mm")
        ax2.plot(np.degrees(pr.phi), di_eq8, lw=0.7, ls="--", label=f"eq. 7/8 (flank), e = {q.offset:g} mm")
        # pragma: no mutate end
        w.add_note(
            f"Position {q.k} (z_усл = {q.z_cond}, e = {q.offset:g} mm, a = {q.a:g} mm, i_n = {q.ratio_nominal:.5f}): "
            f"{len(pr.phi)} steps over one sector period, outlines within {pr.chord_tol:g} mm. ε_s measured "
            f"{eb:.4f} (per flow {ef:.4f}) against eq. 4 {q.eps_s:.4f}; two sectors engaged over {100 * two:.1f} % of "
            f"the turn; tooth pairs in contact {int(pr.pairs.min())} … {int(pr.pairs.max())}; transmission error "
            f"{1e3 * float(np.ptp(law.te)):.4f} mrad peak to peak; contact law tracked in {len(law.phi)} steps "
            f"(down to {math.degrees(law.step_min):.4f}° at the hand-overs): "
            + ", ".join(f"{t} {100 * v:.2f} %" for t, v in shares.items())
            + f" of the turn, tip on tip {tip_deg:.4f}° per period, largest snap {snap_deg:.4f}° (limit "
            f"{policy.POLYSECTOR_SNAP_TOL_DEG:g}°); |Δi| up to {di_max:.3g} (pole of the contact normal), "
            f"{float(np.max(np.abs(di_eq8))):.3g} by eq. 7/8 for a flank contact of the driving sector at the same "
            f"steps ({eq7_max_di(dd, q):.3g} over its whole engagement); overlap {float(ov.max()):.2g} mm².")
    # pragma: no mutate start (the figure only)
    ax1.set_ylabel("θ − φ/i_n, mrad")
    ax1.set_title("Composite gear: transmission error and ratio error over one sector period")
    ax1.legend(fontsize=7)
    ax2.set_xlabel("wheel angle φ, deg")
    ax2.set_ylabel("Δi = (i_n − i_t)/i_n")
    ax2.legend(fontsize=6, ncol=2)
    # pragma: no mutate end
    w.add_plot("ratio_error", fig)
    w.derived["positions"] = positions


def position_error_step(dd: PolysectorDesign, w, built: dict) -> None:
    """Eq. 15–22: R and β per tooth and flank at several r_y for every position; the largest deviation."""
    from ...export.plots import new_figure
    from ...gears.polysector import tooth_position_error

    p, geo = dd.p, dd.geo
    rows = []
    worst = {}
    # pragma: no mutate start (the figure only)
    fig, ax = new_figure()
    # pragma: no mutate end
    for q in dd.positions:
        r_c = geo.r + q.offset
        ys = [r_c - p.module_mm, r_c - 0.5 * p.module_mm, r_c, r_c + 0.5 * p.module_mm]
        best = 0.0
        for r_y in ys:
            res = tooth_position_error(p.module_mm, p.blank_teeth, p.sector_teeth, q.offset, geo.alpha, r_y)
            for rr in res:
                rows.append([q.k, rr["r_y"], rr["tooth"], rr["flank"], rr["x_cond"], rr["y_cond"], rr["x_sector"],
                             rr["y_sector"], rr["R"] * 1e3, rr["beta"]])
                if math.isfinite(rr["R"]):
                    best = max(best, rr["R"])
            # pragma: no mutate start (the figure only)
            if r_y == r_c:
                ax.plot([rr["tooth"] + (0.15 if rr["flank"] == "right" else -0.15) for rr in res],
                        [rr["R"] * 1e3 for rr in res], "o", ms=3, label=f"e = {q.offset:g} mm")
            # pragma: no mutate end
        worst[q.k] = best
        w.derived[f"position{q.k}_flank_deviation_max_um"] = best * 1e3
    w.add_table("tooth_position_error", ["position", "r_y_mm", "tooth", "flank", "x_cond_mm", "y_cond_mm",
                                         "x_sector_mm", "y_sector_mm", "R_um", "beta_rad"], rows)
    # pragma: no mutate start (the figure only)
    ax.set_xlabel("tooth of the sector")
    ax.set_ylabel("R at r_y = r_усл, µm")
    ax.set_yscale("symlog", linthresh=1.0)
    ax.set_title("Tooth position error of a sector against the conditional gear (eq. 15–22)")
    ax.legend(fontsize=7)
    # pragma: no mutate end
    w.add_plot("tooth_position_error", fig)
    w.add_note("Tooth position error (eq. 15–22): largest distance R between the sector's flank and the conditional "
               "gear's involute on circles r_y = r_усл − m … r_усл + m/2 about the wheel axis: "
               + ", ".join(f"position {k}: {1e3 * v:.1f} µm" for k, v in worst.items())
               + " (0 at e = 0, where the sector is the blank itself).")


def efficiency_step(dd: PolysectorDesign, w, built: dict) -> None:
    """Eq. 12–14 from the measured contact path of every position: mean loss, C1…C3, against eq. 13."""
    from ...gears.polysector import epsilon_alpha_pair
    from ...gears.polysector_dynamics import loss_eq12, loss_eq13, loss_instant

    p, geo = dd.p, dd.geo
    f = p.friction_coefficient
    rows = []
    for k, q in enumerate(dd.positions):
        pr = built["proofs"][k]
        it, _ = pr.ratio_measured()
        a = q.a
        O2 = np.array([a, 0.0])
        # every tooth pair in contact at every step counts once: the contact runs uniformly along each
        # pair's path, so this is the path average of eq. 12
        pts, its = [], []
        for kk, here in enumerate(pr.contacts):
            if not math.isfinite(it[kk]):
                continue
            for _j, pt in here:
                pts.append(pt)
                its.append(it[kk])
        Cw, itc = np.array(pts).reshape(-1, 2), np.array(its)
        o1p = a / (1.0 + itc)
        P = np.column_stack([o1p, np.zeros_like(o1p)])
        # contact normal: the tangent from C to the gear's base circle that passes nearer the pole
        v = Cw - O2
        dist = np.linalg.norm(v, axis=1)
        base = np.arctan2(v[:, 1], v[:, 0])
        half = np.arccos(np.clip(geo.r_b2 / dist, -1.0, 1.0))
        best_h, best_l = np.zeros(len(Cw)), np.zeros(len(Cw))
        cos_wt = geo.r_b2 / (a - o1p)
        for i in range(len(Cw)):
            cand = []
            for sgn in (1.0, -1.0):
                T = O2 + geo.r_b2 * np.array([math.cos(base[i] + sgn * half[i]), math.sin(base[i] + sgn * half[i])])
                dvec = Cw[i] - T
                nrm = dvec / max(np.linalg.norm(dvec), 1e-300)
                rel = P[i] - T
                cand.append((abs(rel[0] * nrm[1] - rel[1] * nrm[0]), T, nrm))
            _, T, nrm = min(cand, key=lambda c: c[0])
            best_h[i] = abs(-T[0] * nrm[1] + T[1] * nrm[0])  # distance of O1 from the line
            best_l[i] = np.linalg.norm(Cw[i] - P[i])
        psi = loss_instant(f, best_l, itc, best_h)
        ea = epsilon_alpha_pair(q.z_cond, p.gear_teeth, p.module_mm, geo.alpha)
        plain = loss_eq13(f, ea, q.z_cond, p.gear_teeth)
        r1, r2 = geo.r + q.offset, geo.r2
        rb1, rb2 = r1 * math.cos(geo.alpha), geo.r_b2
        l1 = math.sqrt((r2 + p.module_mm) ** 2 - rb2 ** 2) - r2 * math.sin(geo.alpha)
        l2 = math.sqrt((r1 + p.module_mm) ** 2 - rb1 ** 2) - r1 * math.sin(geo.alpha)
        eq12 = loss_eq12(f, p.module_mm, geo.alpha, q.z_cond, p.gear_teeth, l1, l2)
        mean_psi = float(np.mean(psi))
        C_ext = mean_psi / plain
        C1 = 1.0 / (math.cos(geo.alpha) * float(np.mean(1.0 / np.clip(cos_wt, 1e-9, None))))
        C2 = float(np.mean(best_l)) / ((l1 * l1 + l2 * l2) / (2 * (l1 + l2)))
        C3 = C_ext * C1 / C2
        rows.append([q.k, q.offset, f, ea, eq12, plain, mean_psi, C1, C2, C3, C_ext, 1.0 - mean_psi])
        w.derived[f"position{q.k}_loss_mean"] = mean_psi
        w.derived[f"position{q.k}_loss_eq13_plain"] = plain
        w.derived[f"position{q.k}_C_ext"] = C_ext
    w.add_table("efficiency", ["position", "offset_mm", "f", "epsilon_alpha_conditional", "psi_eq12_solid",
                               "psi_eq13_plain", "psi_measured", "C1", "C2", "C3", "C_ext", "efficiency"], rows)
    w.add_note("Friction loss (eq. 12–14) from the measured contact path (contact point, pole from the measured "
               "i_t, sliding speed (ω1 + ω2)·l, power arm of the wheel): "
               + "; ".join(f"position {r[0]}: ψ = {r[6]:.5f} against eq. 13 plain {r[5]:.5f}, C1 = {r[7]:.3f}, "
                           f"C2 = {r[8]:.3f}, C3 = {r[9]:.3f}, C_внеш = C2·C3/C1 = {r[10]:.3f}" for r in rows) + ".")


def dynamics_step(dd: PolysectorDesign, w, built: dict) -> None:
    """Eq. 9–11 integrated with the measured transmission as Π(q1): q2, q3, driving torque, peak factor."""
    from scipy.interpolate import CubicSpline

    from ...export.plots import new_figure
    from ...gears.polysector_dynamics import TorsionalModel

    p = dd.p
    model = TorsionalModel(p.J1_kgm2, p.J2_kgm2, p.J3_kgm2, p.J4_kgm2, p.J5_kgm2, p.c1_Nm_per_rad, p.c2_Nm_per_rad,
                           p.i54, p.damping_ratio, p.load_torque_Nm)
    omega0 = p.speed_rpm * 2 * math.pi / 60.0
    # pragma: no mutate start (the figure only)
    fig, axes = new_figure(8.0, 8.0)
    fig.clf()
    ax = [fig.add_subplot(3, 1, i) for i in (1, 2, 3)]
    # pragma: no mutate end
    rows = []
    for k, q in enumerate(dd.positions):
        pr = built["proofs"][k]
        te = pr.te
        x = np.append(pr.phi, pr.period)
        cs = CubicSpline(x, np.append(te, te[0]), bc_type="periodic")
        d1, d2 = cs.derivative(1), cs.derivative(2)
        per = pr.period
        Pi1 = lambda q1, d1=d1, q=q: 1.0 / q.ratio_nominal + d1(np.mod(q1, per))
        Pi2 = lambda q1, d2=d2: d2(np.mod(q1, per))
        t_end = 2 * math.pi / omega0
        # Π'' is linear between the spline's knots, repeated every period: solved exactly
        breaks = (x[None, :] + per * np.arange(int(math.ceil(omega0 * t_end / per)) + 1)[:, None]).ravel()
        res = model.simulate(omega0, Pi1, Pi2, t_end, n_out=3000, breaks=breaks)
        rows.append([q.k, q.offset, res.M1_static, float(res.M1.max()), float(res.M1.min()), res.torque_factor,
                     float(np.ptp(res.q2)), float(np.ptp(res.q3))])
        w.derived[f"position{q.k}_dynamic_torque_factor"] = res.torque_factor
        # pragma: no mutate start (the figure only)
        lab = f"e = {q.offset:g} mm"
        ax[0].plot(res.t * 1e3, res.q2 * 1e3, lw=0.7, label=lab)
        ax[1].plot(res.t * 1e3, res.q3 * 1e3, lw=0.7, label=lab)
        ax[2].plot(res.t * 1e3, res.M1, lw=0.7, label=lab)
        # pragma: no mutate end
    wn = model.natural_frequencies()
    w.derived["dynamics_natural_frequencies_Hz"] = [float(x / (2 * math.pi)) for x in wn]
    # pragma: no mutate start (the figure only)
    ax[0].set_ylabel("q2, mrad")
    ax[1].set_ylabel("q3, mrad")
    ax[2].set_ylabel("M1, N·m")
    ax[2].set_xlabel("time over one wheel turn, ms")
    ax[0].set_title(f"Torsional model (eq. 9–11), {p.speed_rpm:g} rpm, M4 = {p.load_torque_Nm:g} N·m")
    ax[0].legend(fontsize=7)
    # pragma: no mutate end
    w.add_plot("dynamics", fig)
    w.add_table("dynamics", ["position", "offset_mm", "M1_static_Nm", "M1_max_Nm", "M1_min_Nm", "torque_factor",
                             "q2_pp_rad", "q3_pp_rad"], rows)
    w.add_note("Dynamics (eq. 9–11, Lagrange form, Π = the measured gear angle, hand-over corners of the measured "
               "transmission spread over one proof step): natural frequencies "
               + ", ".join(f"{x / (2 * math.pi):.1f} Hz" for x in wn) + "; peak dynamic torque factor max|M1|/M1_static "
               + ", ".join(f"position {r[0]}: {r[5]:.3f}" for r in rows) + ".")
