"""What the noncircular pair's derived values mean (export.glossary)."""

#: the derived values the report's summary shows
KEY_VALUES = ("law", "method", "center_distance_mm", "driver_teeth", "driven_teeth", "speed_ripple", "ratio_min",
              "ratio_max", "te_pp_rad",
              "jam_phases", "backlash_min_mm")

_PAIR = {
    "center_distance_mm": ("mm", "centre distance L of the pitch curves"),
    "speed_ripple": ("", "ripple of the hub's horizontal speed over a leg: (max − min) / mean of v/ω"),
    "smoothing_deg": ("deg", "width of the law's smoothing around each leg hand-over"),
    "overlap_law_max_mm2": ("mm²", "largest overlap of the tooth outlines turned by the law over the motion proof"),
    "jam_phases": ("", "phases of the motion proof where the driven gear cannot follow the law (teeth jam)"),
    "proof_phases": ("", "phases (driver positions) the motion proof checks over the driven gear's turn"),
    "te_pp_rad": ("rad", "peak-to-peak transmission error of the driven gear against the law, as built (the drive "
                         "flanks' contact resolved by contact events)"),
    "backlash_min_mm": ("mm", "least circumferential backlash as built: the gap between the two directions' contacts "
                              "on the driven pitch curve, over every contact position (the check mesh.backlash_min: "
                              "at the motion proof's phases)"),
    "backlash_max_mm": ("mm", "largest circumferential backlash as built on the driven pitch curve"),
    "least_overlap_max_mm2": ("mm²", "largest overlap left at the driven angle of least overlap over the proof"),
}

#: the pair as built (parts/noncircular_pair/as_built_outputs.py): both directions' contact on the finished outlines
AS_BUILT = {
    "te_min_rad": ("rad", "least transmission error of the loaded (drive) flanks as built: actual driven angle - law"),
    "te_max_rad": ("rad", "largest transmission error of the loaded (drive) flanks as built"),
    "te_pp_reverse_rad": ("rad", "peak-to-peak transmission error as built, reverse direction"),
    "backlash_min_phi_deg": ("deg", "driven angle of the least backlash"),
    "speed_as_built_min": ("", "least driven speed over the law's at the same driver angle, drive direction"),
    "speed_as_built_max": ("", "largest driven speed over the law's, drive direction"),
    "speed_as_built_reverse_min": ("", "least driven speed over the law's, reverse direction"),
    "speed_as_built_reverse_max": ("", "largest driven speed over the law's, reverse direction"),
    "speed_step_max": ("", "largest change of the driven speed (share of the law's) across a change of contact, drive"),
    "speed_step_reverse_max": ("", "largest change of the driven speed across a change of contact, reverse"),
    "corner_contact_share": ("", "share of the driver's turning with the load on a tooth corner, drive"),
    "corner_contact_reverse_share": ("", "share of the driver's turning with the load on a tooth corner, reverse"),
    "corner_run_max_deg": ("deg", "longest run of driver angle with the load on a tooth corner (either direction)"),
    "as_built_span_deg": ("deg", "driven angle resolved: one period after which the pair repeats"),
    "as_built_evaluations": ("", "contact positions measured for the as-built transmission (both directions)"),
    "as_built_stretches": ("", "stretches whose driven speed departs from the law's or whose contact is on a corner"),
    "speed_ripple_as_built": ("", "(max - min)/mean of the hub speed v/omega the finished outlines deliver, the larger of the two directions; speed_ripple is the law's"),
    "speed_ripple_as_built_drive": ("", "as-built hub speed ripple, drive direction"),
    "speed_ripple_as_built_reverse": ("", "as-built hub speed ripple, reverse direction"),
    "speed_as_built_min_rel": ("", "least as-built hub speed over its mean A/u (drive)"),
    "speed_as_built_max_rel": ("", "largest as-built hub speed over its mean A/u (drive)"),
    "speed_as_built_phi_min_deg": ("deg", "driven angle within a leg of the least as-built hub speed (drive)"),
    "speed_as_built_phi_max_deg": ("deg", "driven angle within a leg of the largest as-built hub speed (drive)"),
    "tolerance_grade": ("", "ISO 1328 accuracy grade the pair was measured as made within"),
    "tolerance_f_a_mm": ("mm", "centre-distance allowance +- f_a = IT/2 of the grade (as made)"),
    "tolerance_runout_driver_mm": ("mm", "radial run-out tolerance F_r of the driver (ISO 1328-2)"),
    "tolerance_runout_driven_mm": ("mm", "radial run-out tolerance F_r of the driven wheel (ISO 1328-2)"),
    "tolerance_thinning_max_mm": ("mm", "largest thinning of a flank along its normal (as made)"),
    "tolerance_backlash_min_mm": ("mm", "least backlash over the worst-case corners of the tolerances"),
    "tolerance_te_pp_max_rad": ("rad", "largest transmission error peak-to-peak over the worst-case corners"),
    "tolerance_step_max": ("", "largest speed step at a change of contact over the worst-case corners"),
    "tolerance_samples": ("", "Monte Carlo cases of the pair as made"),
    "tolerance_backlash_min_p5_mm": ("mm", "least backlash of the pair as made: 5th percentile of the Monte Carlo"),
    "tolerance_backlash_min_p50_mm": ("mm", "least backlash of the pair as made: median of the Monte Carlo"),
    "tolerance_te_pp_p50_rad": ("rad", "transmission error peak-to-peak as made: median of the Monte Carlo"),
    "tolerance_te_pp_p95_rad": ("rad", "transmission error peak-to-peak as made: 95th percentile of the Monte Carlo"),
}

#: the load per tooth (parts/noncircular_pair/tooth_load_outputs.py), with a load case in the part file
TOOTH_LOAD = {
    **{f"tooth_load_{g}_{k}": (unit, f"{text} ({g})") for g in ("driver", "driven") for k, (unit, text) in {
        "sigma_F_max_MPa": ("MPa", "largest root stress of any tooth over the cycle (ISO 6336-3 30° section of the real tooth, load at its point of application)"),
        "sigma_F_worst_tooth": ("", "the tooth with the largest root stress"),
        "sigma_F_worst_driver_deg": ("deg", "driver angle within the period of the largest root stress"),
        "sigma_H_max_MPa": ("MPa", "largest contact stress on any tooth's flank over the cycle (Hertz with the measured flank radii)"),
        "sigma_H_worst_tooth": ("", "the tooth with the largest contact stress"),
        "sigma_H_worst_driver_deg": ("deg", "driver angle within the period of the largest contact stress"),
        "F_n_max_N": ("N", "largest normal force on any tooth"),
        "uneven_F": ("", "the most over the least loaded tooth: ratio of the teeth's peak normal forces"),
        "uneven_sigma_F": ("", "the most over the least loaded tooth: ratio of the teeth's peak root stresses"),
        "S_H_min": ("", "least contact safety σ_Hlim·Z_NT/σ_H of the teeth"),
        "S_F_min": ("", "least root safety σ_FE·Y_NT/σ_F of the teeth"),
        "cycles_per_driven_turn": ("", "load cycles of each tooth per driven turn"),
    }.items()},
    "tooth_load_S_H_min": ("", "least contact safety of all teeth of both wheels (load per tooth)"),
    "tooth_load_S_F_min": ("", "least root safety of all teeth of both wheels (load per tooth)"),
    "tooth_load_T1_max_Nm": ("N·m", "largest driver torque over the cycle (load case)"),
    "tooth_load_T1_min_Nm": ("N·m", "least driver torque over the cycle"),
    "tooth_load_T2_max_Nm": ("N·m", "largest driven (carrier) torque over the cycle, T1·U·η"),
    "tooth_load_T2_min_Nm": ("N·m", "least driven (carrier) torque over the cycle"),
    "tooth_load_pairs_min": ("", "least number of tooth pairs carrying load at a phase"),
    "tooth_load_pairs_max": ("", "largest number of tooth pairs carrying load at a phase"),
    "tooth_load_pairs_mean": ("", "mean number of tooth pairs carrying load over the phases measured"),
    "tooth_load_c_prime_min": ("N/(mm·µm)", "least single stiffness c′ of a tooth pair (ISO 6336-1, local equivalent gears)"),
    "tooth_load_c_prime_max": ("N/(mm·µm)", "largest single stiffness c′ of a tooth pair"),
    "tooth_load_Z_E": ("√MPa", "elasticity factor Z_E of the gear material (ISO 6336-2)"),
    "tooth_load_phases": ("", "phases the load per tooth was measured at over one period"),
    "tooth_load_material": ("", "gear material of the load per tooth (catalogue name)"),
    "tooth_load_sigma_Hlim_MPa": ("MPa", "contact stress limit σ_Hlim of the material"),
    "tooth_load_sigma_FE_MPa": ("MPa", "root stress limit σ_FE = σ_Flim·Y_ST of the material"),
}

GLOSSARY = {
    **_PAIR,
    **AS_BUILT,
    **TOOTH_LOAD,
    "mounting_distance_mm": ("mm", "centre distance the pair is mounted at (the DXF and the assembly)"),
    "module_mm": ("mm", "module m of the teeth"),
    "driver_teeth": ("", "teeth z of the driver (the wheel the input turns)"),
    "driven_teeth": ("", "teeth z_H of the driven wheel (the output; the hub in a walking propulsor)"),
    "driver_turns": ("", "driver turns n per driven turn (the driven wheel's lobes; the legs for the walking law)"),
    "method": ("", "how the teeth were made: generated (conjugate, by a shaper or rack) or sectors (the papers' "
                   "involute sectors, seed 000 and seed 002)"),
    "speed_ripple_phi_min_deg": ("deg", "hub angle φ of the least hub speed"),
    "speed_ripple_phi_max_deg": ("deg", "hub angle φ of the largest hub speed"),
    "hub_height_mm": ("mm", "hub height A = a − b + c of the propulsor (seed 000 eq. 1-15)"),
    "u": ("", "reduced ratio coefficient u = n π A / (A π + 6 b) (seed 000 eq. 10)"),
    "hub_speed_mean_mm_per_rad": ("mm/rad", "hub speed analogue v/ω = A / u: horizontal hub travel per driver radian"),
    "closure_error_rad": ("rad", "closure of the pitch curves: the driven angle left over after one driven turn"),
    "overlap_law_phases": ("", "phases of the motion proof where the outlines turned by the law overlap"),
    "contact_pairs_min": ("", "least number of tooth pairs in contact over the motion proof"),
    "contact_ratio_mean": ("", "mean number of tooth pairs in contact over the motion proof"),
    "smoothing_rad": ("rad", "width δ of the law's smoothing around each leg hand-over"),
    "driver_rho_min_mm": ("mm", "least convex radius of curvature of the driver's pitch curve"),
    "driver_rho_limit_mm": ("mm", "least convex radius of curvature the driver's generating cutter can cut "
                                  "without undercut"),
    "driven_rho_min_mm": ("mm", "least convex radius of curvature of the driven pitch curve"),
    "driven_rho_limit_mm": ("mm", "least convex radius of curvature the driven gear's cutter can cut without undercut"),
    "driven_concave_rho_min_mm": ("mm", "least concave radius of curvature of the driven pitch curve (must exceed "
                                        "the shaper's radius)"),
    "shaper_r0_mm": ("mm", "pitch radius r0 of the shaper cutter"),
    "driver_shift": ("", "profile shift coefficient of the driver"),
    "driven_shift": ("", "profile shift coefficient of the driven gear (the driver's, opposite)"),
    "tip_shortened_teeth": ("", "teeth of both gears whose tips were shortened (a pointed tip cut back)"),
    "shaper_cut_teeth": ("", "teeth of both gears cut by the shaper (the others by the rack)"),
    "undercut_teeth": ("", "teeth of both gears undercut by their cutter"),
    "rack_profile": ("", "basic rack profile of the cutter (ISO 53 A, B, C or D)"),
    "shaper_d0_mm": ("mm", "pitch diameter d0 of the catalogue shaper cutter"),
    "shaper_z0": ("", "teeth z0 of the catalogue shaper cutter"),
    "shaper_x0": ("", "profile shift x0 of the catalogue shaper cutter"),
    "shaper_standard": ("", "standard of the catalogue shaper cutter"),
    "root_bridge_max_mm": ("mm", "largest bridge of the root fillet between the shaper-cut and rack-cut teeth"),
    "law_search_points": ("", "laws screened by the law search"),
    "law_search_evaluations": ("", "law evaluations the law search made"),
    "law_search_tries": ("", "searches run (each with a wider smoothing when the last could not be cut)"),
    "blend_u_h_over_u": ("", "ratio U at hand-over over u: the chosen blend's second shape parameter"),
    "blend_eps": ("", "the chosen blend's first shape parameter ε"),
    "law_search_binding": ("", "the limit that binds the chosen law (what stops a smaller ripple)"),
    "law_search_best_screened_ripple": ("", "hub speed ripple of the best law found by the screening"),
    "driver_bore_mm": ("mm", "the driver's bore as built, sized from the gear (the part file gives none; 0: no bore "
                             "fits; the notes say the rule)"),
    "driven_bore_mm": ("mm", "the driven wheel's bore as built, sized from the gear (the part file gives none; 0: no "
                             "bore fits; the notes say the rule)"),
    "sector_arc_mm": ("mm", "pitch-curve arc of one involute sector (seed 000 Table 1)"),
    "sectors_per_leg": ("", "involute sectors i per leg of the driven gear"),
    **{f"compare_<other>_{k}": (unit, f"{meaning}, with the teeth made by the other method ({{other}}), for comparison")
       for k, (unit, meaning) in _PAIR.items()},
    # laws without a hub (elliptical, fourier, table)
    "law": ("", "the drive law the part file names (walking, elliptical, fourier, table, pitch_curve)"),
    "law_periods": ("", "periods of the law per driven turn as the law declares them (the driven wheel's lobes, counted on its curve in the law line, may be more: a driver pitch curve's own symmetry multiplies them)"),
    "ratio_min": ("", "least gear ratio U = dθ/dφ of the law"),
    "ratio_max": ("", "largest gear ratio U = dθ/dφ of the law"),
    "eccentricity": ("", "eccentricity e of the elliptical driver"),
    "focal_parameter_mm": ("mm", "focal parameter p of the elliptical driver: r1 = p / (1 + e cos θ)"),
    "pitch_curve_center_distance_mm": ("mm", "centre distance L0 of the driver's pitch curve as the part file gives it"),
    "pitch_curve_scale": ("", "scale L / L0 of the pair against the pitch curve given (so that it holds the teeth)"),
    # print kit
    "print_module_mm": ("mm", "module of the printed gears"),
    "print_center_distance_mm": ("mm", "centre distance of the printed pair"),
    "print_face_width_mm": ("mm", "face width of the printed gears"),
    "print_backlash_n_design_mm": ("mm", "normal backlash the printed teeth are thinned for"),
    "print_backlash_n_min_mm": ("mm", "least normal backlash of the printed pair"),
    "print_backlash_t_max_mm": ("mm", "largest circumferential backlash of the printed pair"),
    "pin_driver_d_mm": ("mm", "diameter of the printed driver's pin"),
    "pin_driven_d_mm": ("mm", "diameter of the printed driven gear's pin"),
    # the hand on the print kit's crank (kit_load.py)
    "hand_load_force_N": ("N", "force of a firm hand on the kit's crank handle, tangential (a stated assumption: "
                               "policy.KIT_HAND_FORCE_N)"),
    "hand_load_crank_radius_mm": ("mm", "radius r_h of the kit's crank handle from the driver's axis, as built"),
    "hand_load_T1_Nm": ("N·m", "driver torque T1 = F_hand·r_h of the hand on the crank (the kit's load case, the driven "
                               "wheel held)"),
    "hand_load_S_Fmin": ("", "root safety S_F a printed material must reach under the hand (the part file's load_S_Fmin)"),
    "hand_load_S_Hmin": ("", "contact safety S_H a printed material must reach under the hand (the part file's "
                             "load_S_Hmin)"),
    "hand_load_survivors": ("", "the printed materials whose teeth survive the hand on the crank"),
    "hand_load_root_unrated_teeth": ("", "loaded teeth whose root is not rated under the hand: ISO 6336-3's 30° "
                                         "section is not found on their outline"),
    "hand_load_<material>_S_F_min": ("", "least root safety σ_FE/σ_F of the printed teeth in {material} under the "
                                         "hand, both wheels and directions"),
    "hand_load_<material>_S_H_min": ("", "least contact safety σ_Hlim/σ_H of the printed teeth in {material} under "
                                         "the hand"),
    "hand_load_<material>_sigma_F_max_MPa": ("MPa", "largest root stress of the printed teeth in {material} under the "
                                                    "hand"),
    "hand_load_<material>_sigma_H_max_MPa": ("MPa", "largest contact stress of the printed teeth in {material} under "
                                                    "the hand"),
    "hand_load_<material>_root_worst": ("", "the tooth and direction of the least root safety in {material}"),
    "hand_load_<material>_flank_worst": ("", "the tooth and direction of the least contact safety in {material}"),
    "hand_load_<material>_force_allow_N": ("N", "hand force the printed teeth in {material} take at the required "
                                                "safeties (estimate: root stress in proportion to the load, contact "
                                                "stress to its square root)"),
    "hand_load_<material>_survives": ("", "the printed teeth in {material} survive the hand on the crank"),
}
