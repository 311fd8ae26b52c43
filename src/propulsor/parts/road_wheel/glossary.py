"""What the road wheel's derived values mean (export.glossary)."""

#: the derived values the report's summary shows
KEY_VALUES = ("mass_wheel_kg", "T_at_V_max_C", "mean_pressure_MPa", "deflection_lambda_m_mm", "load_per_row_N")

GLOSSARY = {
    "mass_<solid>_kg": ("kg", "mass of {solid} (its volume times its material's density)"),
    "mass_wheel_kg": ("kg", "mass of the whole road wheel: disc, rims and tyres"),
    "centre_of_mass_wheel_mm": ("mm", "centre of mass of the whole wheel (x, y, z; z along the axle)"),
    "load_per_row_N": ("N", "radial load on one tyre row: the static wheel load shared by the rows"),
    "contact_length_l_mm": ("mm", "length l of the tyre's contact chord under the row load (Kozlov)"),
    "deflection_lambda_m_mm": ("mm", "radial deflection λ_m of the rubber under the row load (Kozlov, seed 004 eq. 79)"),
    "peak_pressure_q_m_MPa": ("MPa", "peak contact pressure q_m in the middle of the contact (Kozlov)"),
    "mean_pressure_MPa": ("MPa", "mean contact pressure P / (b l) of one row"),
    "work_per_turn_A_J": ("J", "hysteresis work A lost in the rubber per wheel turn (Kozlov)"),
    "cooling_surface_F_mm2": ("mm²", "cooling surface F of one tyre (its free faces)"),
    "n_at_V_max_rpm": ("rpm", "wheel speed at the vehicle's top speed, n = V / (2π R)"),
    "heat_at_V_max_Q_W": ("W", "heat generated in one tyre at the top speed (Kozlov)"),
    "T_at_V_max_C": ("°C", "steady tyre temperature at the top speed (Kozlov, seed 004 eq. 76-80, kinematic n)"),
    "T_at_V_max_printed_n_C": ("°C", "steady tyre temperature at the top speed with the wheel speed as printed "
                                     "in seed 004 (twice the kinematic one), for comparison"),
    "track_frequency_at_V_max_Hz": ("Hz", "track-link excitation frequency V / t at the top speed"),
    "tyre_radius_mm": ("mm", "outer radius of the tyres"),
    "rim_outer_radius_mm": ("mm", "outer radius of the rims (the tyres' seat)"),
    "rim_inner_radius_mm": ("mm", "inner radius of the rims (the disc's seat)"),
    "wheel_mid_plane_z_mm": ("mm", "axial position of the wheel's mid-plane from the inboard face"),
    "hub_bore_inner_seat_mm": ("mm", "diameter of the hub's inboard bearing seat"),
    "hub_bore_outer_seat_mm": ("mm", "diameter of the hub's outboard bearing seat"),
    "spindle_seats_required_mm": ("mm", "bearing bores the spindle must carry (inboard, outboard)"),
    # print kit
    "print_tyre_radius_mm": ("mm", "tyre radius of the printed model"),
    "print_wheel_length_mm": ("mm", "axial length of the printed wheel"),
    "axle_d_mm": ("mm", "diameter of the printed axle"),
    "wheel_bore_d_mm": ("mm", "bore of the printed wheel on its axle"),
    "wheel_slabs": ("", "slabs the printed wheel is cut into (glued in order)"),
}
