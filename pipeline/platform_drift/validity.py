"""Where the paper's closed forms hold, decided from the scenario config, and Table 2 row 5.

The analytic errors of the proposed scheme (eq. 32 for a level-gyro drift, eq. 36 for the
azimuth gyro) and the classical azimuth-drift error of Table 2 row 5 (constant velocity,
here the Earth-rotation velocity of a vehicle at rest) are derived for a **stationary**
vehicle. Whether a scenario is one is computed from its config: the largest ground speed of
its trajectory (:func:`max_ground_speed_m_s`), never from its name. Outside that validity a
closed form is ``not_checkable``: a formula used where it does not hold never refutes a
published number.

>>> EQUATIONS["ch1_ch3"]
'eqs. 32 and 36'
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from typing import Any

import numpy as np

from pipeline.generated import platform_drift as gen
from pipeline.platform_drift.analytic import eq36_undefined
from pipeline.platform_drift.scenario import Scenario
from pipeline.platform_drift.trajectory import Trajectory

__all__ = [
    "EQUATIONS",
    "REST_SPEED_M_S",
    "analytic_invalid",
    "at_rest_invalid",
    "max_ground_speed_m_s",
    "table2_azimuth_error_m",
]

#: The paper's analytic error of the proposed scheme for each drift case.
EQUATIONS = {
    "none": "eqs. 32 and 36",
    "ch1": "eq. 32",
    "ch3": "eq. 36",
    "ch1_ch3": "eqs. 32 and 36",
}
#: A trajectory whose ground speed never exceeds this (m/s) is at rest.
REST_SPEED_M_S = 1e-9
#: Samples of the trajectory used to find its largest ground speed.
_SAMPLES = 721


def max_ground_speed_m_s(sc: Scenario) -> float:
    """Largest ground speed (m/s) of the scenario's trajectory over its run, from its config.

    Ground speed = R_G sqrt(lat_dot^2 + (lon_dot cos lat)^2) of the true trajectory
    (Earth-relative rates of :meth:`Trajectory.at`), sampled at 721 times over the run.
    Computed once per trajectory and run length (the verdicts ask it of every row).
    """
    return _max_ground_speed(sc.earth, sc.route, sc.psi0, max(sc.duration, sc.long_duration or 0.0))


@cache
def _max_ground_speed(earth, route, psi0: float, t_end: float) -> float:
    traj = Trajectory(earth, route, psi0)
    best = 0.0
    for t in np.linspace(0.0, t_end, _SAMPLES):
        lat, _, lat_dot, _, lon_dot, _ = traj.latlon_rates(float(t))
        speed = traj.rho * float(np.hypot(lat_dot, lon_dot * np.cos(lat)))
        best = max(best, speed)
    return best


def at_rest_invalid(results: Mapping[str, Any], scenario: str, what: str) -> str:
    """Why ``what`` (a closed form for a vehicle at rest) does not hold in ``scenario``;
    ``""`` when the scenario's config has the vehicle at rest."""
    sc = results.get(scenario, {}).get("scenario")
    if sc is None:
        return (
            f"no scenario config for {scenario}: whether {what} holds (a vehicle at rest) "
            "cannot be decided"
        )
    speed = max_ground_speed_m_s(sc)
    if speed <= REST_SPEED_M_S:
        return ""
    verb = "hold" if what.startswith("eqs.") else "holds"
    return (
        f"{what} {verb} for a stationary vehicle; scenario {scenario} moves (ground speed up to "
        f"{speed:.0f} m/s, computed from its config)"
    )


def analytic_invalid(results: Mapping[str, Any], scenario: str, case: str) -> str:
    """Why the analytic curve (eqs. 32/36) of ``case`` does not hold in ``scenario``, or ``""``:
    a moving vehicle, or a channel-3 drift at latitude 0 (eq. 36 divides by sin(lat0))."""
    sc = results.get(scenario, {}).get("scenario")
    if sc is not None and sc.platform_drift(case)[2] != 0.0:
        why = eq36_undefined(sc)
        if why:
            return why
    return at_rest_invalid(results, scenario, EQUATIONS[case])


def table2_azimuth_error_m(sc: Scenario, t: np.ndarray) -> np.ndarray:
    """Table 2 row 5 (derived form, generated): position error (m) for the azimuth drift of the
    scenario's channel 3 at rest.

    ``eps_z`` = the channel-3 drift b_g3; the velocity is the inertial velocity of a vehicle at
    rest, east omega_e R_G cos(lat0) (Table 2's v_x, v_y are inertial velocities: its note
    gives 1000 ft/s, and at rest only the Earth's rotation moves the vehicle); omega_0 is the
    Schuler frequency sqrt(g/R_G) with the mass gravity g = GM/R_G^2 (as the simulation uses).
    """
    rho = sc.earth.radius + sc.route.altitude
    g = sc.earth.gm / rho**2
    omega0 = 2.0 * np.pi / float(gen.schuler_period(g, rho))
    # inertial velocity at rest, omega_ie x r in m_N (north, west, up): east = -west
    v_east = -float(gen.velocity_at_rest(sc.earth.omega_e, sc.route.lat0, rho)[1])
    # Table 2 row 5: (dx, dy) = (eps_z / 2)(v_y, -v_x)[t^2 - 2(1 - cos w0 t)/w0^2] (derived form)
    dx, dy = gen.table2_azimuth_drift(np.asarray(t, dtype=float), sc.b_g3, v_east, 0.0, omega0)
    return np.hypot(np.asarray(dx, dtype=float), np.asarray(dy, dtype=float))
