"""The stable platform and the paper's position-independent navigation algorithm (Sec. 3).

Two coupled systems are integrated together, for several drift cases at once (the
cases are an array axis):

**The physical platform.** Its frame s turns, relative to inertial space, at the commanded
rates plus the gyro drift: ``omega_is^s = [p, q, r] + [b_g1, b_g2, b_g3]`` with ``r = 0``
in navigation (eq. 25). Its attitude ``C_s^i`` (columns = platform axes in inertial
coordinates) is integrated as a direction-cosine matrix, ``dC/dt = C [omega x]``. The
accelerometers measure the true specific force resolved in s: ``f = C^T (a_i - g_i)``.

**The algorithm** (Fig. 2), which only sees ``f`` and the known altitude:

* commands, eq. 12: ``p_dot = -f2/z``, ``q_dot = +f1/z``; ``r = 0`` (eq. 25);
  (eqs. 12, 15, 16 and the measured specific force, eq. 17, are the generated functions of
  ``pipeline.generated.platform_drift``; this module only wires them together);
* platform oscillation, eq. 15 (eqs. 9, 11 rewritten with the definitions of eqs. 13, 14:
  ``omega_y = u/z``, ``omega_x = -v/z``, ``phi_y = -x/R_G``, ``phi_x = y/R_G``);
* known altitude (vertical channel): ``|r_EB| = rho`` (true radius), so
  ``z = sqrt(rho^2 - x^2 - y^2)`` and ``z_dot = -(x x_dot + y y_dot)/z`` (constant altitude);
  ``R_G = rho``, so D of eq. 15 is exactly 1;
* position, eq. 16 explicit form with ``p_m = omega_x``, ``q_m = omega_y``, ``r_m = 0``::

      (lon_dot + omega_e) cos(lat) = cos(psi) p_m - sin(psi) q_m
      lat_dot = sin(psi) p_m + cos(psi) q_m
      psi_dot = -(lon_dot + omega_e) sin(lat) + r_m

A diagnostic copy of eq. 16 with ``r_m`` equal to the platform's true azimuth rate
(``b_g3``) is carried along: it isolates the tilt-induced rate errors that the paper's
analysis (eqs. 33-36) models from the azimuth error that it leaves out.

State per case (21): C_s^i (9, row-major), p, q, omega_x, omega_y, phi_x, phi_y,
lat, lon, psi, and the diagnostic lat, lon, psi.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pipeline.generated import frames
from pipeline.generated import platform_drift as gen
from pipeline.platform_drift.dop853 import solve_ivp
from pipeline.platform_drift.trajectory import Trajectory, c3, eq2_angles

__all__ = ["InitialState", "initial_state", "simulate", "N_STATE"]

N_STATE = 21


@dataclass(frozen=True)
class InitialState:
    """End-of-alignment state shared by the truth platform and the algorithm."""

    c_si: np.ndarray  # 3x3 platform attitude C_s^i
    p: float
    q: float
    r_0m: float  # r(0-) of the alignment; navigation commands r = 0 (eq. 25)
    omega_x: float
    omega_y: float
    phi_x: float
    phi_y: float
    lat: float
    lon: float
    psi: float


def initial_state(traj: Trajectory, level: str) -> InitialState:
    """Ideal end of alignment at t = 0 (the vehicle at rest).

    ``level = 'mass'``: the platform's axis 3 is along the radius (the mass vertical of the
    paper's spherical gravity), i.e. phi_x = phi_y = 0; ``'plumb'``: axis 3 along the
    apparent vertical (the specific force at t = 0), the state the paper's alignment ends in
    (eqs. 20, 21: phi ~ alpha). Axis 1 is at azimuth psi0 (north toward west).
    p0, q0 are p(0-), q(0-) of the generated ``alignment_rates`` (the exact rates that hold
    the platform still, eq. 19 exact with phi_dot = psi_dot = 0; eq. 24 is its r(0-) to
    first order), which do not jump at 0+ (Table 1); r(0-) is kept as ``r_0m`` and navigation
    commands r = 0 (eq. 25). omega_x0, omega_y0 follow from eq. 13 with the true inertial
    velocity, the eq. 14 tilts from the true position.
    """
    tr = traj.at(0.0)
    if tr.lat_dot != 0.0 or tr.lon_dot != 0.0:
        raise ValueError("the alignment (eqs. 20-24) ends with the vehicle at rest at t = 0")
    nwu = tr.nwu_i
    if level == "mass":
        c_si = nwu @ c3(traj.psi0)
    elif level == "plumb":
        # the apparent vertical: the generated specific force (eq. 17) in NWU axes
        f_i = nwu @ traj.specific_force_in(tr, nwu)
        up = f_i / np.linalg.norm(f_i)
        a1 = nwu @ c3(traj.psi0)[:, 0]
        a1 = a1 - up * (a1 @ up)
        a1 /= np.linalg.norm(a1)
        c_si = np.column_stack((a1, np.cross(up, a1), up))
    else:
        raise ValueError(f"unknown initial level {level!r}")
    # the angles of eq. 2 of C_s^{mN}
    psi, tilt_y, tilt_x = eq2_angles(nwu.T @ c_si)
    # eq. 24 (exact form): p(0-), q(0-), r(0-) that hold the platform still
    p0, q0, r0m = gen.alignment_rates(traj.earth.omega_e, tr.lat, psi, tilt_x, tilt_y)
    x, y, z = c_si.T @ tr.r_i
    u, v, _ = c_si.T @ tr.v_i
    omega_x, omega_y = gen.radius_rates_from_velocity(u, v, z)  # eq. 13
    phi_x, phi_y = gen.tilts_from_position(x, y, traj.rho)  # eq. 14
    return InitialState(
        c_si=c_si,
        p=float(p0),
        q=float(q0),
        r_0m=float(r0m),
        omega_x=float(omega_x),
        omega_y=float(omega_y),
        phi_x=float(phi_x),
        phi_y=float(phi_y),
        lat=tr.lat,
        lon=tr.lon,
        psi=float(psi),
    )


def _y0(init: InitialState, n_cases: int) -> np.ndarray:
    row = np.concatenate(
        [
            init.c_si.ravel(),
            [init.p, init.q, init.omega_x, init.omega_y, init.phi_x, init.phi_y],
            [init.lat, init.lon, init.psi, init.lat, init.lon, init.psi],
        ]
    )
    return np.tile(row, n_cases)


def _atol(n_cases: int) -> np.ndarray:
    # DCM 1e-14; rates (~1e-4 rad/s) 1e-19 rad/s; tilts 1e-15 rad; angles 1e-14 rad
    row = np.concatenate(
        [np.full(9, 1e-14), np.full(4, 1e-19), np.full(2, 1e-15), np.full(6, 1e-14)]
    )
    return np.tile(row, n_cases)


def make_rhs(traj: Trajectory, drift: np.ndarray):
    """RHS of the coupled platform + algorithm system for drifts ``drift`` (n_cases x 3)."""
    drift = np.asarray(drift, dtype=float)
    n = drift.shape[0]
    rg = traj.rho
    gm, omega_e = traj.earth.gm, traj.earth.omega_e
    r_cmd = 0.0  # eq. 25: the third gyro is commanded zero in navigation
    # eq. 16's r_m: 0 for the algorithm; the diagnostic is told the platform's true azimuth rate
    r_m_both = np.concatenate((np.zeros(n), drift[:, 2]))

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        tr = traj.at(t)
        rho = traj.rho  # known altitude
        Y = y.reshape(n, N_STATE)
        C = Y[:, :9].reshape(n, 3, 3)
        p, q, wx, wy, fx, fy = Y[:, 9:15].T
        lat, psi = Y[:, 15], Y[:, 17]
        lat2, psi2 = Y[:, 18], Y[:, 20]
        # accelerometers: true specific force in the physical platform frame
        f = traj.specific_force_in(tr, C)
        # algorithm: known altitude gives z = sqrt(rho^2 - x^2 - y^2) (eq. 14 for x, y)
        x, yy = gen.position_from_tilts(fx, fy, rg)
        z = gen.known_altitude_z(x, yy, rho)
        p_dot, q_dot = gen.platform_commands_rates(f[:, 0], f[:, 1], z)  # eq. 12
        r = r_cmd
        # eq. 15: the tilt rates do not depend on z_dot; z_dot follows from them
        _, _, fx_dot, fy_dot = gen.oscillation_rates(
            wx, wy, fx, fy, p, q, r, p_dot, q_dot, z, 0.0, rg, gm
        )
        x_dot, y_dot = gen.position_from_tilts(fx_dot, fy_dot, rg)  # eq. 14, differentiated
        # known constant altitude: z_dot = -(x x_dot + y y_dot) / z
        z_dot = gen.known_altitude_z_dot(x, yy, z, x_dot, y_dot)
        wx_dot, wy_dot, _, _ = gen.oscillation_rates(
            wx, wy, fx, fy, p, q, r, p_dot, q_dot, z, z_dot, rg, gm
        )
        out = np.empty_like(Y)
        # eq. 16 with p_m = omega_x, q_m = omega_y, r_m = 0 (and the diagnostic r_m = b_g3):
        # both in one call of the generated function (the cases twice: algorithm, diagnostic)
        lon_dot, lat_dot, psi_dot = gen.position_rates(
            np.concatenate((wx, wx)),
            np.concatenate((wy, wy)),
            r_m_both,
            np.concatenate((lat, lat2)),
            np.concatenate((psi, psi2)),
            omega_e,
        )
        out[:, 15:21] = np.column_stack(
            (lat_dot[:n], lon_dot[:n], psi_dot[:n], lat_dot[n:], lon_dot[n:], psi_dot[n:])
        )
        # physical platform: commanded rates plus drift
        w = np.column_stack((p, q, np.full(n, r_cmd))) + drift
        out[:, :9] = (C @ frames.skew(w[:, 0], w[:, 1], w[:, 2])).reshape(n, 9)
        out[:, 9] = p_dot
        out[:, 10] = q_dot
        out[:, 11] = wx_dot
        out[:, 12] = wy_dot
        out[:, 13] = fx_dot
        out[:, 14] = fy_dot
        return out.ravel()

    return rhs


def simulate(
    traj: Trajectory,
    drift: np.ndarray,
    t_eval: np.ndarray,
    level: str = "mass",
    rtol: float = 1e-10,
) -> dict[str, np.ndarray]:
    """Integrate platform + algorithm for each drift row; computed positions at ``t_eval``.

    Returns ``lat``, ``lon`` (algorithm, eq. 16), ``lat_diag``, ``lon_diag`` (eq. 16 with
    the true azimuth rate), ``psi`` and ``psi_diag``, each (n_cases, len(t_eval)), plus
    ``nfev``.
    """
    drift = np.atleast_2d(np.asarray(drift, dtype=float))
    n = drift.shape[0]
    init = initial_state(traj, level)
    sol = solve_ivp(
        make_rhs(traj, drift),
        (float(t_eval[0]), float(t_eval[-1])),
        _y0(init, n),
        t_eval=t_eval,
        rtol=rtol,
        atol=_atol(n),
    )
    if not sol.success:
        raise RuntimeError(f"platform integration failed: {sol.message}")
    Y = sol.y.reshape(n, N_STATE, -1)
    return {
        "lat": Y[:, 15],
        "lon": Y[:, 16],
        "psi": Y[:, 17],
        "lat_diag": Y[:, 18],
        "lon_diag": Y[:, 19],
        "psi_diag": Y[:, 20],
        "phi_x": Y[:, 13],
        "phi_y": Y[:, 14],
        "nfev": np.array(sol.nfev),
    }
