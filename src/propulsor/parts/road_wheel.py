"""Road wheel with solid rubber tyres of the 50 t tracked carrier (seed 004, ch. 5 and 7; SPEC §8).

Seed 004 gives the wheel: diameter D_k = 630 mm, double row ("двухрядный"), on a track with a
rubber-faced running surface (ch. 5); the static wheel load P_st = 31 490 N (ch. 2, eq. 3); the
tyre heat estimate of Kozlov (ch. 7, eq. 76–80) and the "track" frequency ω = 2πV/t (§7.2) with
the parametric-resonance speeds 7.3, 10.8 and 21.7 m/s read from its Ince–Strutt diagram
(fig. 35).  It prints no tyre width, rubber thickness, rim or disc dimensions: those below are
ours (the same illustrative tyre as tests/test_tyre_heat.py: b = 90 mm, H = 40 mm, E = 6 MPa,
α = 60 W/(m² K), ψ = 0.35).

Geometry, wheel frame (mm): axis = z, origin on the axis at the hub's inboard face, +z outboard
(away from the balancer arm).  Solids, each a solid of revolution built from an exact half section
(``solids.revolve``):

* ``disc``: hub tube with the two bearing seats (outer rings; the seats are counterbores from
  each end, the relief between them leaves the shoulders) and one web per row, with
  ``lightening_holes`` holes through every web — genus 1 + rows × holes;
* ``rim_<k>``: steel ring per row on the web's edge — genus 1;
* ``tyre_<k>``: solid rubber ring vulcanised on the rim — genus 1.

Kozlov's temperature uses the kinematic wheel speed n = V/(2πR) (``laws.tyre_heat``: the seed's
printed n = 60V/(3.6πR) is twice that, read with R a diameter); the printed reading is plotted
beside it.  The track pitch for ω is ch. 7's Table 12 value L = 0.15 m (ch. 4 uses t = 0.14 m,
ch. 5 t_r = 0.125 m: the seed is inconsistent; the part file may change it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..check import Check
from ..errors import InputError
from ..params import param
from . import PartType

__all__ = ["RoadWheelParams", "WheelModel", "wheel_model", "wheel_solids", "PART_TYPE", "build"]

#: the seed's parametric-resonance speeds of the road wheels (ch. 7, fig. 35), m/s
RESONANCE_SPEEDS_MPS = (7.3, 10.8, 21.7)


@dataclass
class RoadWheelParams:
    """Parameters of the double road wheel with solid rubber tyres."""

    tyre_radius_mm: float = param(315.0, "mm", "outer (rolling) radius of the tyres R (seed 004 ch. 5: D_k = 630)",
                                  min=100.0, max=1000.0)
    rows: int = param(2, "", "tyre rows (seed 004 ch. 5: double)", choices=[1, 2])
    tyre_width_mm: float = param(90.0, "mm", "tyre width b per row", min=10.0, max=400.0)
    tyre_thickness_mm: float = param(40.0, "mm", "rubber thickness H", min=5.0, max=200.0)
    row_gap_mm: float = param(80.0, "mm", "gap between the rows (the track's guide horns run in it)", min=0.0, max=400.0)
    row_offset_mm: float = param(5.0, "mm", "inboard face of the inner row from the hub's inboard face",
                                 min=-200.0, max=200.0)
    rim_thickness_mm: float = param(12.0, "mm", "radial thickness of the steel rim", min=3.0, max=60.0)
    web_thickness_mm: float = param(16.0, "mm", "thickness of each disc web", min=4.0, max=60.0)
    hub_outer_d_mm: float = param(210.0, "mm", "outside diameter of the hub tube", min=20.0)
    hub_length_mm: float = param(230.0, "mm", "length of the hub tube", min=20.0)
    hub_relief_d_mm: float = param(124.0, "mm", "hub bore between the bearing seats (leaves the shoulders)", min=10.0)
    bearing_inner_d_mm: float = param(100.0, "mm", "inboard bearing bore d (= balancer spindle seat)", min=10.0)
    bearing_inner_D_mm: float = param(180.0, "mm", "inboard bearing outside diameter D (= hub seat)", min=15.0)
    bearing_inner_B_mm: float = param(46.0, "mm", "inboard bearing width B", min=5.0)
    bearing_outer_d_mm: float = param(80.0, "mm", "outboard bearing bore d (= balancer spindle seat)", min=10.0)
    bearing_outer_D_mm: float = param(140.0, "mm", "outboard bearing outside diameter D (= hub seat)", min=15.0)
    bearing_outer_B_mm: float = param(35.0, "mm", "outboard bearing width B", min=5.0)
    lightening_holes: int = param(6, "", "lightening holes per web (0: none)", min=0, max=24, integer=True)
    lightening_hole_d_mm: float = param(60.0, "mm", "lightening hole diameter", min=5.0)
    # Kozlov (seed 004 eq. 76-80)
    load_N: float = param(31490.0, "N", "wheel load P (seed 004 eq. 3: P_st), shared equally by the rows",
                          min=0.0, min_exclusive=True)
    E_rubber_MPa: float = param(6.0, "MPa", "rubber compression modulus E_p (eq. 80)", min=0.1, max=200.0)
    psi: float = param(0.35, "", "internal friction of the rubber ψ (eq. 77; seed: 0.25 ... 0.5)",
                       min=0.0, max=1.0, min_exclusive=True, max_exclusive=True)
    alpha_W_m2K: float = param(60.0, "W/(m^2 K)", "heat transfer rubber -> air α (eq. 76)", min=0.1)
    t_air_C: float = param(20.0, "°C", "air temperature t_в (eq. 76; seed Table 12: 20)", min=-60.0, max=60.0)
    V_max_kmh: float = param(50.0, "km/h", "largest vehicle speed (seed 004 ch. 5: 50)", min=1.0, max=200.0)
    track_pitch_m: float = param(0.15, "m", "track link pitch t for ω = 2πV/t (seed Table 12: 0.15)",
                                 min=0.01, max=1.0)
    t_allow_C: float = param(120.0, "°C", "admissible steady tyre temperature (ours; the seed prints none)",
                             min=30.0, max=300.0)
    q_allow_MPa: float = param(5.0, "MPa", "admissible mean contact pressure (ours; the seed's first criterion)",
                               min=0.1, max=50.0)
    rho_steel_kg_m3: float = param(7850.0, "kg/m^3", "density of the disc and rims", min=1000.0, max=20000.0)
    rho_rubber_kg_m3: float = param(1150.0, "kg/m^3", "density of the tyres", min=500.0, max=3000.0)

    def validate(self) -> None:
        wheel_model(self)  # raises InputError for geometry that cannot be made
        tyre = self.tyre()
        P_row = self.load_N / self.rows
        lam = float(tyre.contact_length(P_row)) ** 2 / (8.0 * self.tyre_radius_mm)
        if not lam < self.tyre_thickness_mm:
            raise InputError("load_N", self.load_N, f"Kozlov's deflection λ_m = {lam:.4g} mm reaches the rubber "
                             f"thickness H = {self.tyre_thickness_mm:g} mm (eq. 79)")

    def tyre(self):
        from ..laws.tyre_heat import SolidTyre

        return SolidTyre(R=self.tyre_radius_mm, b=self.tyre_width_mm, H=self.tyre_thickness_mm,
                         E=self.E_rubber_MPa, alpha=self.alpha_W_m2K, psi=self.psi)


@dataclass
class WheelModel:
    """Derived wheel geometry, wheel frame (mm)."""

    p: RoadWheelParams
    r_tyre: float
    r_rim_out: float
    r_rim_in: float
    r_hub: float
    rows_z: list = field(default_factory=list)  # (z0, z1) of each row
    web_z: list = field(default_factory=list)  # (z0, z1) of each web
    z_mid: float = 0.0  # wheel mid-plane (load line)
    hole_circle_r: float = 0.0

    @property
    def z_inboard(self) -> float:
        """Most inboard z of the wheel (hub face or inner row)."""
        return min(0.0, self.rows_z[0][0])

    @property
    def z_outboard(self) -> float:
        return max(self.p.hub_length_mm, self.rows_z[-1][1])

    def disc_section(self):
        """Half section (x = r, y = z) of hub + webs."""
        from ..geometry.profile import Profile, polygon_loop

        p = self.p
        L, B1, B2 = p.hub_length_mm, p.bearing_inner_B_mm, p.bearing_outer_B_mm
        R1, R2, Rr = p.bearing_inner_D_mm / 2, p.bearing_outer_D_mm / 2, p.hub_relief_d_mm / 2
        pts = [(R1, 0.0), (self.r_hub, 0.0)]
        for (w0, w1) in self.web_z:
            pts += [(self.r_hub, w0), (self.r_rim_in, w0), (self.r_rim_in, w1), (self.r_hub, w1)]
        pts += [(self.r_hub, L), (R2, L), (R2, L - B2), (Rr, L - B2), (Rr, B1), (R1, B1)]
        return Profile(polygon_loop(pts), name="disc")

    def ring_section(self, r0: float, r1: float, z0: float, z1: float, name: str):
        from ..geometry.profile import Profile, polygon_loop

        return Profile(polygon_loop([(r0, z0), (r1, z0), (r1, z1), (r0, z1)]), name=name)

    def sections(self) -> dict:
        """Name -> half section of every solid."""
        out = {"disc": self.disc_section()}
        for k, (z0, z1) in enumerate(self.rows_z, 1):
            out[f"rim_{k}"] = self.ring_section(self.r_rim_in, self.r_rim_out, z0, z1, f"rim_{k}")
            out[f"tyre_{k}"] = self.ring_section(self.r_rim_out, self.r_tyre, z0, z1, f"tyre_{k}")
        return out

    def genus(self, name: str) -> int:
        return 1 + (len(self.rows_z) * self.p.lightening_holes if name == "disc" else 0)


def wheel_model(p: RoadWheelParams) -> WheelModel:
    """Derived geometry; InputError naming the parameter for geometry that cannot be made."""
    R, H, b = p.tyre_radius_mm, p.tyre_thickness_mm, p.tyre_width_mm
    if not H < 0.5 * R:
        raise InputError("tyre_thickness_mm", H, f"must be < R/2 = {0.5 * R:g} mm")
    r_rim_out = R - H
    r_rim_in = r_rim_out - p.rim_thickness_mm
    r_hub = 0.5 * p.hub_outer_d_mm
    for nm, d, D, B in (("inner", p.bearing_inner_d_mm, p.bearing_inner_D_mm, p.bearing_inner_B_mm),
                        ("outer", p.bearing_outer_d_mm, p.bearing_outer_D_mm, p.bearing_outer_B_mm)):
        if not D > d + 10.0:
            raise InputError(f"bearing_{nm}_D_mm", D, f"must exceed the bore d = {d:g} mm by > 10 mm")
        if not D + 20.0 <= p.hub_outer_d_mm:
            raise InputError("hub_outer_d_mm", p.hub_outer_d_mm, f"must leave a 10 mm wall around the {nm} "
                             f"bearing seat: >= {D + 20.0:g} mm")
    if not p.hub_relief_d_mm < min(p.bearing_inner_D_mm, p.bearing_outer_D_mm) - 4.0:
        raise InputError("hub_relief_d_mm", p.hub_relief_d_mm, "must be < the smaller bearing D − 4 mm "
                         "(shoulders for the outer rings)")
    if not p.hub_relief_d_mm > max(p.bearing_inner_d_mm, p.bearing_outer_d_mm) + 10.0:
        raise InputError("hub_relief_d_mm", p.hub_relief_d_mm, "must exceed the larger bearing bore d + 10 mm "
                         "(the spindle passes through)")
    if not p.bearing_inner_B_mm + p.bearing_outer_B_mm + 10.0 <= p.hub_length_mm:
        raise InputError("hub_length_mm", p.hub_length_mm, "must hold both bearings and 10 mm between them")
    if not r_rim_in > r_hub + 20.0:
        raise InputError("hub_outer_d_mm", p.hub_outer_d_mm, f"hub must end 20 mm inside the rim (rim bore "
                         f"{2 * r_rim_in:g} mm)")
    z0 = p.row_offset_mm
    rows = [(z0, z0 + b)]
    if p.rows == 2:
        rows.append((z0 + b + p.row_gap_mm, z0 + 2 * b + p.row_gap_mm))
    if p.rows == 2 and not p.row_gap_mm > 0:
        raise InputError("row_gap_mm", p.row_gap_mm, "two rows need a gap > 0 mm")
    webs = []
    for (a, c) in rows:
        zc = 0.5 * (a + c)
        w0, w1 = zc - 0.5 * p.web_thickness_mm, zc + 0.5 * p.web_thickness_mm
        if not p.web_thickness_mm < b:
            raise InputError("web_thickness_mm", p.web_thickness_mm, f"must be < the tyre width {b:g} mm")
        if not (w0 > 0.5 and w1 < p.hub_length_mm - 0.5):
            raise InputError("hub_length_mm", p.hub_length_mm, f"every web must sit on the hub: web from "
                             f"{w0:g} to {w1:g} mm, hub from 0 to {p.hub_length_mm:g} mm (row_offset_mm, rows)")
        webs.append((w0, w1))
    if len(webs) == 2 and not webs[1][0] > webs[0][1] + 1.0:
        raise InputError("row_gap_mm", p.row_gap_mm, "the webs overlap")
    hc = 0.5 * (r_hub + r_rim_in)
    if p.lightening_holes:
        rh = 0.5 * p.lightening_hole_d_mm
        if not (hc - rh > r_hub + 5.0 and hc + rh < r_rim_in - 5.0):
            raise InputError("lightening_hole_d_mm", p.lightening_hole_d_mm,
                             f"must be < {2 * (0.5 * (r_rim_in - r_hub) - 5.0):g} mm (5 mm to hub and rim)")
        if p.lightening_holes > 1 and 2 * hc * math.sin(math.pi / p.lightening_holes) <= p.lightening_hole_d_mm + 5.0:
            raise InputError("lightening_holes", p.lightening_holes, "holes overlap: fewer or smaller holes")
    z_mid = 0.5 * (rows[0][0] + rows[-1][1])
    return WheelModel(p, R, r_rim_out, r_rim_in, r_hub, rows, webs, z_mid, hc)


def wheel_solids(m: WheelModel) -> dict:
    """Name -> cadquery Solid of every wheel part, in the wheel frame."""
    from ..solids.kernel import cut, cylinder
    from ..solids.revolve import revolve_section

    out = {}
    for name, sec in m.sections().items():
        sol = revolve_section(sec)
        if name == "disc" and m.p.lightening_holes:
            z0, z1 = m.web_z[0][0] - 1.0, m.web_z[-1][1] + 1.0
            tools = []
            for k in range(m.p.lightening_holes):
                a = 2.0 * math.pi * (k + 0.5) / m.p.lightening_holes
                tools.append(cylinder(0.5 * m.p.lightening_hole_d_mm, z0, z1,
                                      (m.hole_circle_r * math.cos(a), m.hole_circle_r * math.sin(a))))
            sol = cut(sol, *tools, name="disc lightening holes")
        out[name] = sol
    return out


def mass_properties(m: WheelModel, solids: dict) -> dict:
    """Mass (kg) and centre of mass (mm, wheel frame) of every solid and of the whole wheel."""
    from ..solids.kernel import mass_properties as _mass_props

    p = m.p
    out = {}
    tot, mom = 0.0, np.zeros(3)
    for name, sol in solids.items():
        rho = (p.rho_rubber_kg_m3 if name.startswith("tyre") else p.rho_steel_kg_m3) * 1e-9
        mk, ck = _mass_props(sol, rho)
        out[name] = (mk, ck)
        tot += mk
        mom += mk * ck
    out["wheel"] = (tot, mom / tot)
    return out


def kozlov_table(p: RoadWheelParams, num: int = 101) -> dict:
    """Temperature over speed (seed 004 eq. 76-80) with the track frequency (§7.2)."""
    from ..laws.tyre_heat import track_frequency

    tyre = p.tyre()
    P_row = p.load_N / p.rows
    V = np.linspace(0.0, p.V_max_kmh, num)
    Vm = V / 3.6
    w = track_frequency(Vm, p.track_pitch_m)
    return {
        "V_kmh": V, "V_mps": Vm, "n_rpm": tyre.temperature_curve(P_row, p.V_max_kmh, p.t_air_C, num)["n_rpm"],
        "track_frequency_Hz": w / (2 * math.pi), "omega_track_rad_s": w,
        "Q_W_per_row": tyre.heat_rate(P_row, V),
        "T_C": tyre.temperature(P_row, V, p.t_air_C),
        "T_printed_n_C": tyre.temperature(P_row, V, p.t_air_C, as_printed_n=True),
    }


def _kozlov_plot(p: RoadWheelParams, tab: dict):
    from ..export.plots import new_figure

    fig, ax = new_figure(7.5, 4.8)
    ax.plot(tab["V_kmh"], tab["T_C"], lw=1.6, label="Kozlov eq. 76-80, n = V/(2πR)")
    ax.plot(tab["V_kmh"], tab["T_printed_n_C"], lw=1.0, ls="--", label="same with the printed n = 60V/(3.6πR)")
    ax.axhline(p.t_allow_C, color="r", lw=0.8, ls=":", label=f"admissible {p.t_allow_C:g} °C (ours)")
    for v in RESONANCE_SPEEDS_MPS:
        vk = 3.6 * v
        if vk <= p.V_max_kmh:
            f = v / p.track_pitch_m
            ax.axvline(vk, color="k", lw=0.7, ls="-.")
            ax.text(vk, ax.get_ylim()[0] + 0.05 * (ax.get_ylim()[1] - ax.get_ylim()[0]),
                    f" {v:g} m/s\n track f = {f:.0f} Hz", fontsize=7)
    ax.set_xlabel("vehicle speed V, km/h")
    ax.set_ylabel("steady tyre temperature T, °C")
    ax.set_title(f"Solid tyre temperature (seed 004 ch. 7), P = {p.load_N / p.rows:.0f} N per row")
    top = ax.secondary_xaxis("top", functions=(lambda v: v / 3.6 / p.track_pitch_m,
                                               lambda f: f * p.track_pitch_m * 3.6))
    top.set_xlabel(f"track frequency f = V/t, Hz (t = {p.track_pitch_m:g} m; ω = 2πf)")
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    return fig


def _section_loops(m: WheelModel) -> list:
    """Full cross-section (both sides of the axis) of every solid, x = radius, y = z."""
    from ..geometry.profile import Line, Loop, Profile

    out = []
    for name, sec in m.sections().items():
        out.append(sec)
        segs = [Line((-s.p0[0], s.p0[1]), (-s.p1[0], s.p1[1])) for s in sec.outer.segments]
        out.append(Profile(Loop(segs), name=name + "_mirror"))
    return out


def _web_blank(m: WheelModel):
    from ..geometry.profile import Profile, circle_loop

    holes = [circle_loop(m.r_hub, ccw=False)]
    for k in range(m.p.lightening_holes):
        a = 2.0 * math.pi * (k + 0.5) / m.p.lightening_holes
        holes.append(circle_loop(0.5 * m.p.lightening_hole_d_mm,
                                 (m.hole_circle_r * math.cos(a), m.hole_circle_r * math.sin(a)), ccw=False))
    return Profile(circle_loop(m.r_rim_in), holes, name="web")


def build(p: RoadWheelParams, w) -> None:
    m = wheel_model(p)
    d = w.derived
    tyre = p.tyre()
    P_row = p.load_N / p.rows
    w.progress("Kozlov tyre heat (seed 004 eq. 76-80)")
    l = float(tyre.contact_length(P_row))
    lam = float(tyre.deflection(P_row))
    T_vmax = float(tyre.temperature(P_row, p.V_max_kmh, p.t_air_C))
    T_vmax_printed = float(tyre.temperature(P_row, p.V_max_kmh, p.t_air_C, as_printed_n=True))
    q_mean, q_m = float(tyre.q_mean(P_row)), float(tyre.q_m(P_row))
    d.update({
        "load_per_row_N": P_row, "contact_length_l_mm": l, "deflection_lambda_m_mm": lam,
        "peak_pressure_q_m_MPa": q_m, "mean_pressure_MPa": q_mean,
        "work_per_turn_A_J": float(tyre.work_per_turn(P_row)),
        "cooling_surface_F_mm2": tyre.F,
        "n_at_V_max_rpm": float(tyre.temperature_curve(P_row, p.V_max_kmh, p.t_air_C, 2)["n_rpm"][-1]),
        "heat_at_V_max_Q_W": float(tyre.heat_rate(P_row, p.V_max_kmh)),
        "T_at_V_max_C": T_vmax, "T_at_V_max_printed_n_C": T_vmax_printed,
        "track_frequency_at_V_max_Hz": p.V_max_kmh / 3.6 / p.track_pitch_m,
        "tyre_radius_mm": m.r_tyre, "rim_outer_radius_mm": m.r_rim_out, "rim_inner_radius_mm": m.r_rim_in,
        "wheel_mid_plane_z_mm": m.z_mid,
        "hub_bore_inner_seat_mm": p.bearing_inner_D_mm, "hub_bore_outer_seat_mm": p.bearing_outer_D_mm,
        "spindle_seats_required_mm": [p.bearing_inner_d_mm, p.bearing_outer_d_mm],
    })
    w.add_checks([
        Check.at_most("tyre temperature at V_max (Kozlov, eq. 76)", T_vmax, p.t_allow_C, "°C",
                      f"steady tyre temperature at {p.V_max_kmh:g} km/h, kinematic n; with the seed's printed n "
                      f"(twice the wheel speed) it would be {T_vmax_printed:.1f} °C"),
        Check.at_most("mean contact pressure P/(b l)", q_mean, p.q_allow_MPa, "MPa",
                      "seed 004 §7.1 first tyre criterion; admissible value ours"),
        Check.at_most("deflection / rubber thickness", lam / p.tyre_thickness_mm, 1.0, "",
                      "Kozlov's λ_m (eq. 79) must stay inside the rubber"),
    ])
    tab = kozlov_table(p)
    w.add_table("tyre_temperature", tab, None)
    w.add_plot("tyre_temperature", _kozlov_plot(p, tab))

    w.progress("solids: disc, rims, tyres (revolved exact sections)")
    solids = wheel_solids(m)
    for name, sol in solids.items():
        w.add_solid(name, sol, expected_genus=m.genus(name))
    mp = mass_properties(m, solids)
    for name, (mk, ck) in mp.items():
        d[f"mass_{name}_kg"] = mk
    d["centre_of_mass_wheel_mm"] = [float(x) for x in mp["wheel"][1]]
    w.add_table("mass_properties", ["solid", "mass_kg", "com_x_mm", "com_y_mm", "com_z_mm"],
                [[k, v[0], *map(float, v[1])] for k, v in mp.items()])
    w.add_assembly("road_wheel_assembly", [(name, sol, (0.0, 0.0, 0.0), 0.0) for name, sol in solids.items()])

    w.progress("DXF: section and web blank")
    refs = [("line", {"p0": (0.0, m.z_inboard - 20.0), "p1": (0.0, m.z_outboard + 20.0)}),
            ("line", {"p0": (-m.r_tyre - 20.0, m.z_mid), "p1": (m.r_tyre + 20.0, m.z_mid)})]
    w.add_dxf("road_wheel_section", _section_loops(m), refs)
    w.add_dxf("road_wheel_web", [_web_blank(m)],
              [("circle", {"radius": m.hole_circle_r})] if p.lightening_holes else [])

    w.add_note(
        f"Road wheel D = {2 * m.r_tyre:g} mm, {p.rows} row(s) of b = {p.tyre_width_mm:g} mm solid rubber, "
        f"H = {p.tyre_thickness_mm:g} mm, on steel rims; hub seats {p.bearing_inner_D_mm:g} / "
        f"{p.bearing_outer_D_mm:g} mm for bearings of bore {p.bearing_inner_d_mm:g} / {p.bearing_outer_d_mm:g} mm "
        f"(the balancer spindle's seats are taken from these). Seed 004 gives D_k = 630 mm and the double row "
        f"(ch. 5); tyre width, rubber thickness, rubber constants, rim, disc and bearings are ours.")
    w.add_note(
        f"Kozlov (seed 004 eq. 76-80) per row at P = {P_row:.0f} N: contact chord l = {l:.2f} mm, deflection "
        f"λ_m = {lam:.2f} mm, q_m = {q_m:.3f} MPa, mean {q_mean:.3f} MPa; at {p.V_max_kmh:g} km/h T = {T_vmax:.1f} °C "
        f"(admissible {p.t_allow_C:g} °C, ours). Reading taken: n = V/(2πR); the printed n = 60V/(3.6πR) is the wheel "
        f"speed only for R a diameter and would give {T_vmax_printed:.1f} °C. Track pitch t = {p.track_pitch_m:g} m "
        f"(ch. 7 Table 12; ch. 4 prints 0.14 m, ch. 5 0.125 m). The plot marks the seed's parametric-resonance speeds "
        f"{', '.join(f'{v:g}' for v in RESONANCE_SPEEDS_MPS)} m/s (fig. 35) with their track frequencies; Kozlov's "
        f"estimate ignores that dynamic load, which the seed argues can reach the static load (36 kg × 30 g).")


PART_TYPE = PartType(
    name="road_wheel",
    summary="double road wheel with solid rubber tyres, Kozlov heat estimate (seed 004 ch. 7)",
    params_cls=RoadWheelParams,
    build=build,
)
