"""Heating of the telescopic damper of one road-wheel station on a sinusoidal road (seed 004 ch. 6,
eq. 73–75, Table 11): a two-mass model, linear, solved exactly (matrix exponential; scipy's DOP853
on the same equations is the cross-check).

    m1·z1'' = −C1·(z1 − q) − b1·(z1' − q') − C2·(z1 − z2) − b2·(z1' − z2')     unsprung mass (wheel, balancer)
    m2·z2'' = −C2·(z2 − z1) − b2·(z2' − z1')                                    sprung mass per wheel
    q = a·sin ωt,  ω = 2π·V / L                                                 road, height 2a, wavelength L
    m_a·c_steel·dT/dt = b2·(z2' − z1')² − V·S·ρ_air·c_air·(T − T_env)            eq. 74–75 (damper power in,
                                                                                 air flow out)

Readings of the printed model (each shown with numbers in ``tests/test_damper_heat.py``):

* the printed ODE before eq. 74 writes the sprung mass's damper term as −b2·(z1' − z2'): a negative
  damper that feeds energy into the body (the free motion grows instead of decaying); and the unsprung
  mass's equation carries no damper reaction.  This module uses the damper between the masses with
  the sign that dissipates, acting on both (``as_printed=True`` integrates the printed equations).
* eq. 75 prints t = T_env + A / ht_steel: J divided by J/(kg·K) is not a temperature; the damper's mass
  m_a = 20 kg of Table 11 completes it (t = T_env + A/(m_a·c_steel), as the seed's ch. 7 does with its
  "temperature coefficient" 1/(m·c)).
* eq. 74's cooling term ∫∫ X'·R·V·S·c_air is not a power; the cooling used is the air flow through the
  damper's surface heated to the damper's temperature, V·S·ρ_air·c_air·(T − T_env) (ρ_air is in
  Table 11; ch. 7 Table 12 writes the same flow coefficient V·A·ρ·c_air).
* Table 11 gives the suspension stiffness "164 400 кН/град"; it is ch. 2's c = 164 400 N/m.

m1, C1 and b1 (unsprung mass, tyre-on-track stiffness and damping) are not in the seed; the caller
gives them (the balancer part: its built balancer plus road wheel, and its stated assumptions).

Units SI: kg, N/m, N·s/m, m, s, W, °C.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from propulsor.errors import require_positive

__all__ = ["Station", "Road", "TABLE_11", "simulate", "DamperRun", "speed_sweep", "cooling_coefficient"]

#: seed 004 Table 11
TABLE_11 = dict(m=3125.0, m_a=20.0, c_steel=487.0, T_env=20.0, S=0.247, rho_air=1.2, V=13.889, D=6.846,
                c_air=1005.0, C=164400.0)


@dataclass(frozen=True)
class Station:
    """One road-wheel station: masses, stiffnesses, damping, the damper's thermal data."""

    m1: float                 # unsprung mass, kg
    C1: float                 # tyre/track radial stiffness, N/m
    b1: float                 # tyre damping, N·s/m
    m2: float = TABLE_11["m"]    # sprung mass per wheel, kg
    C2: float = TABLE_11["C"]    # suspension stiffness at the wheel, N/m
    b2: float = 3.426e4          # damper coefficient at the wheel, N·s/m (ch. 2 eq. 23, μ_mean)
    m_a: float = TABLE_11["m_a"]
    c_steel: float = TABLE_11["c_steel"]
    S: float = TABLE_11["S"]
    rho_air: float = TABLE_11["rho_air"]
    c_air: float = TABLE_11["c_air"]
    T_env: float = TABLE_11["T_env"]

    def __post_init__(self):
        for k in ("m1", "C1", "m2", "C2", "b2", "m_a", "c_steel", "S"):
            require_positive(k, getattr(self, k))


@dataclass(frozen=True)
class Road:
    height: float      # crest to trough, m (seed: 0.2 m; 0.05 m for the short bumps)
    wavelength: float  # m

    @property
    def a(self) -> float:
        return 0.5 * self.height


def cooling_coefficient(st: Station, V: float) -> float:
    """Air-flow cooling V·S·ρ_air·c_air, W/K (seed 004 eq. 74, Table 11)."""
    return V * st.S * st.rho_air * st.c_air


def _rhs(st: Station, road: Road, V: float, as_printed: bool):
    """The station's equations as a right-hand side f(t, y), y = (z1, z1', z2, z2', T) (for a numerical
    integrator: the cross-check of :func:`simulate`'s exact solution)."""
    w = 2.0 * math.pi * V / road.wavelength
    a = road.a
    k_air = cooling_coefficient(st, V)
    heat = 1.0 / (st.m_a * st.c_steel)

    def f(t, y):
        z1, v1, z2, v2, T = y
        q, dq = a * math.sin(w * t), a * w * math.cos(w * t)
        if as_printed:
            a1 = (-st.C1 * (z1 - q) - st.C2 * (z1 - z2) - st.b1 * (v1 - dq)) / st.m1
            a2 = (-st.C2 * (z2 - z1) - st.b2 * (v1 - v2)) / st.m2
        else:
            Fd = st.b2 * (v2 - v1)
            a1 = (-st.C1 * (z1 - q) - st.b1 * (v1 - dq) - st.C2 * (z1 - z2) + Fd) / st.m1
            a2 = (-st.C2 * (z2 - z1) - Fd) / st.m2
        P = st.b2 * (v2 - v1) ** 2
        return [v1, a1, v2, a2, heat * (P - k_air * (T - st.T_env))]

    return f, w


def _system(st: Station, road: Road, V: float, as_printed: bool) -> tuple[np.ndarray, np.ndarray, float]:
    """The station as an autonomous linear system x' = M·x, x = (z1, z1', z2, z2', s, c), with the road
    q = s = a·sin ωt, q' = ω·c (c = a·cos ωt) carried as a harmonic oscillator; returns M, x(0), ω."""
    w = 2.0 * math.pi * V / road.wavelength
    m1, m2, C1, C2, b1, b2 = st.m1, st.m2, st.C1, st.C2, st.b1, st.b2
    M = np.zeros((6, 6))
    M[0, 1] = M[2, 3] = 1.0
    # unsprung mass: −C1·(z1 − q) − b1·(z1' − q') − C2·(z1 − z2) [+ b2·(z2' − z1') when the damper acts on it]
    M[1] = [-(C1 + C2) / m1, -b1 / m1, C2 / m1, 0.0, C1 / m1, b1 * w / m1]
    # sprung mass: −C2·(z2 − z1) − b2·(z2' − z1')   (printed: − b2·(z1' − z2'))
    M[3] = [C2 / m2, b2 / m2, -C2 / m2, -b2 / m2, 0.0, 0.0]
    if as_printed:
        M[3, 1], M[3, 3] = -b2 / m2, b2 / m2
    else:
        M[1, 1] -= b2 / m1
        M[1, 3] += b2 / m1
    M[4, 5], M[5, 4] = w, -w
    x0 = np.array([0.0, 0.0, 0.0, 0.0, 0.0, road.a])
    return M, x0, w


def _powers(Phi: np.ndarray, x: np.ndarray, n: int) -> np.ndarray:
    """x, Phi·x, Phi²·x, ... (n states, as rows), by doubling: rows [k, 2k) = Phi^k applied to rows [0, k)."""
    out = np.empty((n, len(x)))
    out[0] = x
    k, P = 1, Phi
    while k < n:
        m = min(k, n - k)
        out[k:k + m] = out[:m] @ P.T
        k, P = k + m, P @ P if m == k else P
    return out


@dataclass(frozen=True)
class DamperRun:
    V: float
    t: np.ndarray
    T: np.ndarray           # damper temperature, °C
    z2: np.ndarray          # body motion, m
    mean_power: float       # over the last excitation periods, W

    @property
    def rise(self) -> float:
        return float(self.T[-1] - self.T[0])


def simulate(st: Station, road: Road, V: float, t_end: float, n_out: int = 400, as_printed: bool = False,
             rtol: float | None = None) -> DamperRun:
    """The station at speed V (m/s) from rest at T_env for t_end seconds, solved exactly.

    The mechanical system is linear with harmonic forcing, so x(t) = exp(M·t)·x(0) (:func:`_system`);
    the damper power b2·(z2' − z1')² is a quadratic form of x, whose products X = x ⊗ x obey the linear
    X' = (M ⊗ I + I ⊗ M)·X, and the heat equation (eq. 74–75) is linear in T − T_env driven by that power.
    The 37 states (X, T − T_env) are advanced over the output grid by one matrix exponential (scipy.linalg.expm):
    exact to rounding, where an integrator is exact to its tolerance.  rtol given: integrate the same
    equations with scipy's DOP853 instead (the cross-check in tests)."""
    from scipy.linalg import expm

    require_positive("t_end", t_end, "s")
    if rtol is not None:
        return _simulate_numerically(st, road, V, t_end, n_out, as_printed, rtol)
    M, x0, w = _system(st, road, V, as_printed)
    t_eval = np.linspace(0.0, t_end, n_out)
    dt = t_end / (n_out - 1) if n_out > 1 else 0.0   # np.linspace's step, exactly
    n = len(x0)
    d = np.zeros(n)
    d[3], d[1] = 1.0, -1.0                                   # z2' − z1'
    heat, k_air = 1.0 / (st.m_a * st.c_steel), cooling_coefficient(st, V)
    G = np.zeros((n * n + 1, n * n + 1))
    G[:n * n, :n * n] = np.kron(M, np.eye(n)) + np.kron(np.eye(n), M)
    G[n * n, :n * n] = heat * st.b2 * np.kron(d, d)
    G[n * n, n * n] = -heat * k_air
    Y = _powers(expm(G * dt), np.append(np.kron(x0, x0), 0.0), n_out)
    xs = _powers(expm(M * dt), x0, n_out)
    # mean damper power over the last whole periods (about a quarter of the run); the whole run at V = 0 or when
    # the run is shorter than one period (a window starting before t = 0 would extrapolate the motion backwards)
    T_per = 2.0 * math.pi / w if w > 0 else t_end
    n_per = max(1, int(0.25 * t_end / T_per))
    ts = np.linspace(t_end - min(n_per * T_per, t_end), t_end, 200 * n_per + 1)
    xt = _powers(expm(M * (ts[1] - ts[0])), expm(M * ts[0]) @ x0, len(ts))
    P = st.b2 * (xt @ d) ** 2
    mean_P = float(np.trapezoid(P, ts) / (ts[-1] - ts[0]))  # never an empty window: t_end > 0, T_per > 0
    return DamperRun(V, t_eval, st.T_env + Y[:, -1], xs[:, 2], mean_P)


def _simulate_numerically(st: Station, road: Road, V: float, t_end: float, n_out: int, as_printed: bool,
                          rtol: float) -> DamperRun:
    """:func:`simulate` by scipy's DOP853 on the equations as written (:func:`_rhs`)."""
    f, w = _rhs(st, road, V, as_printed)
    t_eval = np.linspace(0.0, t_end, n_out)
    sol = solve_ivp(f, (0.0, t_end), [0.0, 0.0, 0.0, 0.0, st.T_env], method="DOP853", t_eval=t_eval,
                    rtol=rtol, atol=1e-9, dense_output=True)
    if not sol.success:  # pragma: no cover - a linear system with bounded forcing
        raise RuntimeError(sol.message)
    T_per = 2.0 * math.pi / w if w > 0 else t_end
    n_per = max(1, int(0.25 * t_end / T_per))
    ts = np.linspace(t_end - min(n_per * T_per, t_end), t_end, 200 * n_per + 1)
    y = sol.sol(ts)
    P = st.b2 * (y[3] - y[1]) ** 2
    mean_P = float(np.trapezoid(P, ts) / (ts[-1] - ts[0]))  # never an empty window: t_end > 0, T_per > 0
    return DamperRun(V, sol.t, sol.y[4], sol.y[2], mean_P)


def speed_sweep(st: Station, road: Road, speeds, t_end: float) -> list[DamperRun]:
    """One :func:`simulate` per speed (m/s)."""
    return [simulate(st, road, float(V), t_end) for V in speeds]
