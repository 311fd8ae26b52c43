"""What the polysector gear's derived values mean (export.glossary).  Equation numbers are those of
seed 003."""

#: the derived values the report's summary shows
KEY_VALUES = ("offset_max_mm", "z_cond_max", "epsilon_alpha_blank_gear", "dynamics_natural_frequencies_Hz")

GLOSSARY = {
    "r_blank_mm": ("mm", "pitch radius r of the blank gear the sectors are cut from"),
    "r_b_blank_mm": ("mm", "base radius r_b of the blank gear"),
    "r_a_blank_mm": ("mm", "tip radius r_a of the blank gear"),
    "r_gear_mm": ("mm", "pitch radius r2 of the solid mating gear"),
    "r_a_gear_mm": ("mm", "tip radius r_a2 of the solid mating gear"),
    "empty_pitches_k": ("", "empty pitches k between neighbouring sectors of a flow"),
    "z_c_eq2": ("", "teeth of one sector by seed 003 eq. 2"),
    "delta_eq3_rad": ("rad", "half angle δ of a sector's tip corner from its mid-line (our reading of eq. 3)"),
    "delta_eq1_swapped_rad": ("rad", "δ by eq. 1 with its two terms swapped (the reading that agrees with eq. 3)"),
    "delta_eq1_printed_rad": ("rad", "δ by eq. 1 as printed in seed 003"),
    "offset_max_mm": ("mm", "largest offset e of the sectors from the wheel's axis (eq. 1 and 3)"),
    "z_cond_max": ("", "conditional tooth count z_cond = z + 2 e / m at the largest offset"),
    "eq3_O1C_mm": ("mm", "distance O1C from the wheel's axis to a sector's tip corner at the largest offset (eq. 3)"),
    "eq3_CD_mm": ("mm", "chord CD from the tip corner to the mid-line point of the tip circle (eq. 3)"),
    "eq3_beta2_rad": ("rad", "angle β2 of eq. 3 at the largest offset"),
    "eq3_u_exit_rad": ("rad", "roll angle u at which a sector's tooth leaves the mesh (eq. 3)"),
    "eq3_residual_max_mm2": ("mm²", "largest residual of eq. 3's system at its solution"),
    "flank_overlap_one_flow_e0": ("", "transverse overlap of one flow's sectors at zero offset"),
    "epsilon_alpha_blank_gear": ("", "transverse contact ratio ε_α of the blank gear with the mating gear"),
    "hub_radius_mm": ("mm", "radius of the hub disc that carries the sectors"),
    "bolt_radius_mm": ("mm", "radius of the circle of the sectors' fixing bolts"),
    "position<k>_flank_deviation_max_um": ("µm", "largest deviation of a sector's flank from the conditional "
                                                 "gear's flank at position {k}"),
    "position<k>_loss_mean": ("", "mean mesh loss factor ψ at position {k} over a mesh cycle (measured on the outlines)"),
    "position<k>_loss_eq13_plain": ("", "mesh loss factor ψ at position {k} by eq. 13 for a plain gear of z_cond teeth"),
    "position<k>_C_ext": ("", "correction C_ext = measured / plain loss factor at position {k}"),
    "position<k>_dynamic_torque_factor": ("", "peak over nominal mesh torque at position {k} (torsional dynamics)"),
    "dynamics_natural_frequencies_Hz": ("Hz", "natural frequencies of the torsional model of the drive"),
    "positions": ("", "one entry per adjustment position of the sectors (the fields below)"),
    "positions[].offset_mm": ("mm", "offset e of the sectors at this position"),
    "positions[].center_distance_mm": ("mm", "centre distance a of the wheel and the mating gear at this position"),
    "positions[].ratio_nominal": ("", "nominal ratio i_n = r2 / (r + e) at this position"),
    "positions[].epsilon_s": ("", "sector overlap ε_s of both flows measured on the outlines (seed 003 eq. 4)"),
    "positions[].epsilon_s_per_flow": ("", "sector overlap ε_s of one flow measured on the outlines"),
    "positions[].epsilon_s_eq4": ("", "sector overlap ε_s by seed 003 eq. 4"),
    "positions[].epsilon_s_steps": ("", "mean number of sectors engaged over the motion proof's steps"),
    "positions[].ratio_error_max": ("", "largest relative deviation of the instantaneous ratio from the nominal"),
    "positions[].contact_pairs_min": ("", "least number of tooth pairs in contact over the motion proof"),
    "positions[].z_cond": ("", "conditional tooth count z_cond = z + 2 e / m at this position"),
    "positions[].share_two_sectors_engaged": ("", "share of the motion proof's steps with two sectors engaged"),
    "positions[].share_two_pairs_in_contact": ("", "share of the motion proof's steps with two tooth pairs in contact"),
    "positions[].transmission_error_pp_rad": ("rad", "peak-to-peak transmission error over the motion proof"),
    "positions[].proof_chord_tol_mm": ("mm", "chord tolerance of the outlines in the motion proof"),
    "positions[].proof_steps_per_period": ("", "steps of the motion proof per tooth period"),
    "positions[].contact_shares": ("", "share of one sector period (wheel turn) spent in each contact type of the "
                                   "tracked contact law: flank on flank, sector tip on gear flank, gear tip on "
                                   "sector flank, tip on tip"),
    "positions[].tip_on_tip_deg": ("deg", "wheel turn per sector period during which the contact is tip on tip "
                                   "(tip land or corner of both bodies); must be 0"),
    "positions[].snap_max_deg": ("deg", "largest jump of the gear beyond its nominal advance within the contact "
                                 "law's finest step (the gear snapping forward at a hand-over)"),
    "positions[].contact_law_steps_per_period": ("", "poses of the tracked contact law over one sector period "
                                                 "(refined around every hand-over)"),
    "positions[].contact_law_step_min_deg": ("deg", "finest wheel step of the tracked contact law"),
    # print kit
    "print_module_mm": ("mm", "module of the printed gears"),
    "print_center_distance_mm": ("mm", "centre distance of the printed pair"),
    "print_position": ("", "adjustment position the printed sectors are set at"),
    "print_offset_mm": ("mm", "offset of the printed sectors"),
    "print_face_width_mm": ("mm", "face width of the printed gears"),
    "print_backlash_n_design_mm": ("mm", "normal backlash the printed teeth are thinned for"),
    "print_backlash_n_min_mm": ("mm", "least normal backlash of the printed pair"),
    "axle_wheel_d_mm": ("mm", "diameter of the printed wheel's axle pin"),
    "axle_gear_d_mm": ("mm", "diameter of the printed gear's axle pin"),
}
