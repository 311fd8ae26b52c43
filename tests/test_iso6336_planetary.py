

def test_the_ring_is_rated_in_bending_on_its_substitute_rack():
    """ISO 6336-3:2019, 6.2 (internal gears, method B): the ring's tooth as a rack tooth on its reference circle
    d3 = 560 mm, thickness s3 as made, flanks at 20°, root on d_f3, fillet ρ_fP = the shaper's tip radius.
    The corrected ring: x3 = 1.5, s3 = 10·(π/2 − 2·1.5·tan 20°) − E_sn = 4.7889 − 0.15 = 4.6389 mm,
    d_f3 = d_a0 + 2·a_w0 = 165.8 + 2·222.3044 = 610.4089 mm (shaper z0 = 14, x0 = 0.04), ρ_fP = 0.1·m = 1 mm:

        h_fP = (d_f3 − d3)/2 = 25.2044;  x_c = s3/2 + (h_fP − ρ)·tan α + ρ/cos α = 2.3194 + 8.8096 + 1.0642 = 12.1932
        s_Fn = 2·(x_c − ρ·cos 30°) = 22.6546 mm;  y_F = h_fP − ρ·(1 − sin 30°) = 24.7044 mm
        d_en = 2·√((√(r_a² − r_b²) + (ε_α − 1)·p_b)² + r_b²) = 576.654 mm (ε_α = 1.3491)
        y_e = (d_en − d3)/2 = 8.3268;  x_e = s3/2 + y_e·tan α = 5.3501;  h_Fe = y_F − y_e − x_e·tan α = 14.4306 mm
        Y_F = 6·(h_Fe/m)/(s_Fn/m)² = 1.6871;  L = s_Fn/h_Fe = 1.5699, q_s = s_Fn/(2ρ) = 11.327
        Y_S = (1.2 + 0.13·L)·q_s^(1/(1.21 + 2.3/L)) = 3.479 (q_s past the formula's fitted 8: a sharp root)
        σ_F = F_t/(b·m)·Y_F·Y_S·Y_B·K_A·K_v·K_Fβ·K_Fα,  Y_B = 1 (rim s_R = 4·m >= 3.5·m)"""
    from propulsor.gears.iso6336 import InternalRoot

    ps = _set()
    a = ALPHA
    s3 = 10.0 * (math.pi / 2 - 2 * 1.5 * math.tan(a)) - 0.15
    d_f3 = 10.0 * (14 + 2 * (1.25 + 0.04)) + 2 * ps.ring.a_w0
    assert round(d_f3, 4) == 610.4089
    rho = 1.0
    h_fP = (d_f3 - 560.0) / 2
    x_c = s3 / 2 + (h_fP - rho) * math.tan(a) + rho / math.cos(a)
    s_Fn = 2 * (x_c - rho * math.cos(math.pi / 6))
    y_F = h_fP - rho * (1 - math.sin(math.pi / 6))
    s = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 80.0, MeshLoad(T_MESH * 20 / 16, V_REL),
                    a_w=ps.a_w, internal_root=InternalRoot(s3, rho, 40.0))
    r_b, r_a = 280.0 * math.cos(a), ps.d_a_ring / 2
    d_en = 2 * math.sqrt((math.sqrt(r_a ** 2 - r_b ** 2) + (s.eps_alpha - 1) * math.pi * 10 * math.cos(a)) ** 2 + r_b ** 2)
    y_e = (d_en - 560.0) / 2
    x_e = s3 / 2 + y_e * math.tan(a)
    h_Fe = y_F - y_e - x_e * math.tan(a)
    Y_F = 6 * (h_Fe / 10) / (s_Fn / 10) ** 2
    L, q_s = s_Fn / h_Fe, s_Fn / (2 * rho)
    Y_S = (1.2 + 0.13 * L) * q_s ** (1 / (1.21 + 2.3 / L))
    assert (round(s_Fn, 4), round(h_Fe, 4), round(Y_F, 4), round(Y_S, 3)) == (22.6546, 14.4306, 1.6871, 3.479)
    assert s.d_en2 == pytest.approx(d_en, rel=1e-12)
    assert (s.root2_B.s_Fn, s.root2_B.h_Fe, s.root2_B.Y_F, s.root2_B.Y_S) == pytest.approx((s_Fn, h_Fe, Y_F, Y_S), rel=1e-12)
    K = s.K_A * s.K_v * s.K_Fbeta * s.K_Falpha
    assert s.sigma_F2_B == pytest.approx(s.F_t / (80.0 * 10.0) * Y_F * Y_S * K, rel=1e-12)
