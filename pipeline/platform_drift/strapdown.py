"""Strapdown comparator: a full nonlinear NED mechanisation fed the same trajectory.

The IMU is fixed to the vehicle (body frame of :mod:`trajectory`: the platform's axes at
t = 0, yawing with the vehicle's course). Gyros measure the true body rate plus the drift,
``omega_ib^b + b``; accelerometers the true specific force in body axes. The computer
integrates, on the same spherical Earth (radius rho = R + h, mass gravity GM/rho^2)::

    dC_b^n/dt = C_b^n [omega_ib^b x] - [omega_in^n x] C_b^n
    dv^n/dt   = C_b^n f^b + g_mass^n - (2 omega_ie^n + omega_en^n) x v^n
                - omega_ie^n x (omega_ie^n x r^n)
    lat_dot = v_N / rho,   lon_dot = v_E / (rho cos(lat))

with ``omega_ie^n = [w cos(lat), 0, -w sin(lat)]``,
``omega_en^n = [v_E, -v_N, -v_E tan(lat)] / rho`` and ``r^n = [0, 0, -rho]``. Every formula
is generated: the rates from ``pipeline.generated.frames`` (Earth rate, transport rate,
lat/lon rates, skew), the velocity equation (eq. 10 in NED, derived in
derivations/platform_drift/strapdown.py) and the initial ground velocity (eq. 8) from
``pipeline.generated.platform_drift``.
Vertical channel: the same known-altitude aiding as the platform algorithm, i.e. the
altitude is the true one and the down velocity is zero (only v_N and v_E are
integrated), so the unstable vertical channel does not diverge.

State per case (13): C_b^n (9, row-major), v_N, v_E, lat, lon.
"""

from __future__ import annotations

import numpy as np

from pipeline.generated import frames
from pipeline.generated import platform_drift as gen
from pipeline.platform_drift.dop853 import solve_ivp
from pipeline.platform_drift.trajectory import Trajectory

__all__ = ["simulate", "N_STATE", "NWU_TO_NED"]

N_STATE = 13
NWU_TO_NED = np.diag([1.0, -1.0, -1.0])


def _skew(w: np.ndarray) -> np.ndarray:
    """[w x] for each row of w (n x 3) -> n x 3 x 3 (the generated ``frames.skew``)."""
    return frames.skew(w[:, 0], w[:, 1], w[:, 2])


def make_rhs(traj: Trajectory, drift_b: np.ndarray):
    """RHS for gyro drifts ``drift_b`` (n_cases x 3, body axes, rad/s)."""
    drift_b = np.asarray(drift_b, dtype=float)
    n = drift_b.shape[0]
    rho = traj.rho
    we = traj.earth.omega_e

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        tr = traj.at(t)
        f_b = traj.specific_force_in(tr, traj.body_i(tr))  # generated eq. 17
        w_b = traj.body_rate(tr)
        Y = y.reshape(n, N_STATE)
        C = Y[:, :9].reshape(n, 3, 3)
        vn, ve, lat = Y[:, 9], Y[:, 10], Y[:, 11]
        w_ie = frames.earth_rate_n(we, lat)
        w_en = frames.transport_rate_n_velocity(vn, ve, lat, rho)
        w_in = w_ie + w_en
        w_meas = w_b[None, :] + drift_b
        skews = _skew(np.concatenate((w_meas, w_in)))  # both in one call of the generated skew
        c_dot = C @ skews[:n] - skews[n:] @ C
        f_n = C @ f_b
        # eq. 10 in NED: f + g - (2 omega_ie + omega_en) x v - omega_ie x (omega_ie x r)
        vn_dot, ve_dot = gen.strapdown_velocity_rates(f_n[:, 0], f_n[:, 1], vn, ve, lat, rho, we)
        out = np.empty_like(Y)
        out[:, :9] = c_dot.reshape(n, 9)
        out[:, 9] = vn_dot
        out[:, 10] = ve_dot
        latlon_dot = frames.latlon_rates(vn, ve, lat, rho)
        out[:, 11] = latlon_dot[:, 0]
        out[:, 12] = latlon_dot[:, 1]
        return out.ravel()

    return rhs


def _atol(n: int) -> np.ndarray:
    row = np.concatenate([np.full(9, 1e-14), np.full(2, 1e-10), np.full(2, 1e-14)])
    return np.tile(row, n)


def simulate(
    traj: Trajectory, drift_b: np.ndarray, t_eval: np.ndarray, rtol: float = 1e-10
) -> dict[str, np.ndarray]:
    """Integrate the strapdown INS for each drift row; ``lat``, ``lon`` at ``t_eval``."""
    drift_b = np.atleast_2d(np.asarray(drift_b, dtype=float))
    n = drift_b.shape[0]
    tr = traj.at(float(t_eval[0]))
    c_bn = NWU_TO_NED @ tr.nwu_i.T @ traj.body_i(tr)
    # eq. 8: the Earth-relative velocity v_i - omega_ie x r, in NED
    v_ned = (
        NWU_TO_NED
        @ tr.nwu_i.T
        @ gen.ground_velocity(*tr.v_i, *tr.r_i, *frames.earth_rate_e(traj.earth.omega_e))
    )
    row = np.concatenate([c_bn.ravel(), v_ned[:2], [tr.lat, tr.lon]])
    sol = solve_ivp(
        make_rhs(traj, drift_b),
        (float(t_eval[0]), float(t_eval[-1])),
        np.tile(row, n),
        t_eval=t_eval,
        rtol=rtol,
        atol=_atol(n),
    )
    if not sol.success:
        raise RuntimeError(f"strapdown integration failed: {sol.message}")
    Y = sol.y.reshape(n, N_STATE, -1)
    return {"lat": Y[:, 11], "lon": Y[:, 12], "nfev": np.array(sol.nfev)}
