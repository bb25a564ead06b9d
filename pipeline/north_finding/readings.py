"""Turntable readings: simulated from the generated sensor model, or read from a user's CSV.

A :class:`Readings` holds one averaged accelerometer and one averaged gyro
reading per table position, for every Monte Carlo trial: arrays of shape
``(n_trials, n_positions)``, with each position's table angle, axis and role. Simulated and
user readings go through the same estimators. The frames, signs and CSV format (columns,
units, roles, a worked example) are in :mod:`pipeline.north_finding.readings_csv`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pipeline.generated import north_finding as gen
from pipeline.north_finding.readings_csv import (
    AXES,
    READINGS_COLUMNS,
    ROLES,
    TAU_TOL_DEG,
    circular_diff,
    format_help,
    read_readings_frame,
)
from pipeline.north_finding.scenario import POSITION_NEEDS, Scenario, SensorErrors

__all__ = [
    "Readings",
    "READINGS_COLUMNS",
    "AXES",
    "ROLES",
    "load_readings_csv",
    "simulation_positions",
    "simulate",
    "noise_free_gyro",
    "layout",
    "standard_normals",
    "check_needs",
    "check_site",
    "format_help",
]


@dataclass(frozen=True)
class Readings:
    """Averaged readings at table positions; ``accel`` and ``gyro`` are (n_trials, n_positions)."""

    tau_deg: np.ndarray  # (P,)
    axis: np.ndarray  # (P,) of 'x' | 'y' | 'z'
    accel: np.ndarray  # (T, P) m/s^2
    gyro: np.ndarray  # (T, P) rad/s
    role: np.ndarray  # (P,) of ROLES

    @property
    def n_trials(self) -> int:
        return self.accel.shape[0]

    def index(self, axis: str, tau_deg: float, method: str, role: str = "fixed") -> int:
        """Column of the ``role`` reading on ``axis`` at ``tau_deg``; ValueError naming the
        method if absent."""
        hits = np.flatnonzero(
            (self.axis == axis)
            & (self.role == role)
            & (circular_diff(self.tau_deg, tau_deg) < TAU_TOL_DEG)
        )
        if hits.size == 0:
            on = (self.axis == axis) & (self.role == role)
            have = sorted(set(self.tau_deg[on].round(6).tolist()))
            raise ValueError(
                f"method {method} needs a reading on axis {axis} with role {role} at tau = "
                f"{tau_deg:g} deg; the role-{role} readings on axis {axis} are at {have} deg"
            )
        return int(hits[0])

    def columns(self, axis: str, role: str | None = None) -> np.ndarray:
        """Columns on ``axis`` (of ``role`` if given)."""
        on_axis = self.axis == axis
        if role is not None:
            on_axis &= self.role == role
        return np.flatnonzero(on_axis)


#: |gyro| allowed, in Earth rates: a still table reads Earth rate plus bias; 100 times more is
#: a unit mistake (deg/h or deg/s for rad/s)
MAX_GYRO_EARTH_RATES = 100.0
#: |accel| allowed on axis z, in g (a still table's z axis reads about -g)
MAX_Z_ACCEL_G = 1.1


def check_site(readings: Readings, path: str | Path, g: float, omega_ie: float) -> None:
    """ConfigError (naming the file, the row, the column, the value and what is allowed) for
    a reading a still table at a site with gravity ``g`` and Earth rate ``omega_ie`` cannot
    give: ``|accel| >= g`` on axis x or y (the table would be tilted 90 deg or more: roll or
    pitch come out exactly +-90), ``|accel| > 1.1 g`` on z, or ``|gyro|`` over 100 Earth rates.

    >>> x = np.array(["x"])
    >>> r = Readings(np.array([0.0]), x, np.array([[9.9]]), np.array([[0.0]]), np.array(["fixed"]))
    >>> check_site(r, "r.csv", 9.80665, 7.292115e-5)
    Traceback (most recent call last):
    ...
    pipeline.config.ConfigError: r.csv: row 1, column accel_m_s2 = 9.9: allowed |accel_m_s2| < g = 9.80665 on axis x (a still table tilted less than 90 deg; check the unit and the axis)
    """
    from pipeline.config import ConfigError

    accel, gyro = readings.accel[0], readings.gyro[0]
    for i, (axis, f, w) in enumerate(zip(readings.axis, accel, gyro, strict=True)):
        if axis in ("x", "y") and abs(f) >= g:
            raise ConfigError(
                f"{path}: row {i + 1}, column accel_m_s2 = {float(f)!r}: allowed "
                f"|accel_m_s2| < g = {g:g} on axis {axis} (a still table tilted less than 90 "
                "deg; check the unit and the axis)"
            )
        if axis == "z" and abs(f) > MAX_Z_ACCEL_G * g:
            raise ConfigError(
                f"{path}: row {i + 1}, column accel_m_s2 = {float(f)!r}: allowed "
                f"|accel_m_s2| <= {MAX_Z_ACCEL_G:g} g = {MAX_Z_ACCEL_G * g:g} on axis z (m/s^2)"
            )
        if abs(w) > MAX_GYRO_EARTH_RATES * omega_ie:
            raise ConfigError(
                f"{path}: row {i + 1}, column gyro_rad_s = {float(w)!r}: allowed |gyro_rad_s| <= "
                f"{MAX_GYRO_EARTH_RATES:g} Earth rates = {MAX_GYRO_EARTH_RATES * omega_ie:.3g} "
                "rad/s (a still table reads about Earth rate: deg/h or deg/s given?)"
            )


def check_needs(readings: Readings, methods: tuple[str, ...], a2_tau_deg: float | None) -> None:
    """Raise ValueError if a method lacks a table position it needs (before any compute)."""
    for method in methods:
        for axis, pos in POSITION_NEEDS[method]:
            if isinstance(pos, float):
                readings.index(axis, pos, method)
            elif pos == "ls":
                n = readings.columns(axis, "ls").size
                if n < 3:
                    raise ValueError(
                        f"method {method} (least squares) needs at least 3 table positions on axis "
                        f"{axis} with role ls; the readings have {n}"
                    )
            elif pos == "a2":
                if a2_tau_deg is None:
                    if readings.columns(axis, "a2").size == 0:
                        raise ValueError(
                            f"method {method} needs a2_tau_deg (the table angle it uses)"
                        )
                else:
                    readings.index(axis, a2_tau_deg, method, "a2")
            elif pos == "peak":
                if readings.columns(axis, "peak").size == 0:
                    raise ValueError(
                        f"method {method} needs the scan of its maximum: readings on axis {axis} "
                        "with role peak"
                    )
            elif readings.columns(axis).size == 0:
                raise ValueError(f"method {method} needs the reading on axis {axis} (role z)")


def load_readings_csv(path: str | Path) -> Readings:
    """Read a user's readings CSV (format in :mod:`pipeline.north_finding.readings_csv`);
    errors name the file, the row, the column, the value and what is allowed."""
    frame = read_readings_frame(path)
    return Readings(
        tau_deg=frame["tau_deg"].to_numpy(float),
        axis=frame["axis"].to_numpy(str),
        accel=frame["accel_m_s2"].to_numpy(float)[None, :],
        gyro=frame["gyro_rad_s"].to_numpy(float)[None, :],
        role=frame["role"].to_numpy(str).astype("<U5"),
    )


def simulation_positions(sc: Scenario) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Table positions (tau_deg, axis, role) a simulated scenario reads.

    Fixed positions 0/90/180/270 on x and y, z once, the least-squares set on x and
    y, the method-2 angle, and the method-3 peak (tau* of eq. 52 or a scan); roles as in a
    readings CSV.
    """
    taus: list[float] = []
    axes: list[str] = []
    roles: list[str] = []

    def add(axis: str, tau: float, role: str) -> None:
        taus.append(float(tau) % 360.0)
        axes.append(axis)
        roles.append(role)

    for axis in ("x", "y"):
        for tau in (0.0, 90.0, 180.0, 270.0):
            add(axis, tau, "fixed")
    add("z", 0.0, "z")
    for axis in ("x", "y"):
        for tau in sc.ls_positions_deg():
            add(axis, tau, "ls")
    add("x", sc.table["a2_tau_deg"], "a2")
    ms = sc.table["max_search"]
    if ms["mode"] == "analytic":
        t = sc.truth
        tau_star, _ = gen.a3_peak(sc.omega_ie, sc.lat, t["psi"], t["theta"], t["phi"])
        add("x", np.rad2deg(tau_star), "peak")
    else:
        for tau in np.arange(0.0, 360.0, ms["step_deg"]):
            add("x", tau, "peak")
    return np.array(taus), np.array(axes), np.array(roles, dtype="<U5")


def layout(sc: Scenario) -> Readings:
    """The positions of a simulated scenario with zero readings (to check method needs)."""
    tau_deg, axis, role = simulation_positions(sc)
    zeros = np.zeros((1, tau_deg.size))
    return Readings(tau_deg=tau_deg, axis=axis, accel=zeros, gyro=zeros, role=role)


def _true_vectors(sc: Scenario, tau_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Specific force and angular rate in B, shape (3, P), from the generated model."""
    t = sc.truth
    tau = np.deg2rad(tau_deg)
    tb = sc.table
    f_b = np.stack(
        gen.specific_force_b(
            sc.g,
            sc.omega_ie,
            sc.lat,
            t["psi"],
            t["theta"],
            t["phi"],
            tau,
            tb["lever_arm_m"],
            tb["rate_rad_s"],
            tb["accel_rad_s2"],
        )
    )
    w_b = np.stack(
        gen.angular_rate_b(
            sc.omega_ie, sc.lat, t["psi"], t["theta"], t["phi"], tau, tb["rate_rad_s"]
        )
    )
    return f_b, w_b


def _sense(vec_b: np.ndarray, axis: np.ndarray, err: SensorErrors) -> np.ndarray:
    """Noise-free reading of the single sensor on each position's axis (row of eq. 18 / 39)."""
    idx = {a: i for i, a in enumerate(AXES)}
    out = np.empty(vec_b.shape[1])
    for a in AXES:
        cols = axis == a
        others = [o for o in AXES if o != a]
        out[cols] = (
            err.scale * vec_b[idx[a], cols]
            + sum(err.misalignment[a + o] * vec_b[idx[o], cols] for o in others)
            + err.bias
        )
    return out


def noise_free_gyro(sc: Scenario, gyro: SensorErrors, tau_deg: np.ndarray, axis: str) -> np.ndarray:
    """Noise-free reading of the gyro (errors ``gyro``) on ``axis`` at each table angle, (P,)."""
    tau_deg = np.asarray(tau_deg, dtype=float)
    _, w_b = _true_vectors(sc, tau_deg)
    return _sense(w_b, np.full(tau_deg.size, axis), gyro)


def standard_normals(seed: int, scenario_key: int, n_trials: int, n_positions: int) -> np.ndarray:
    """Standard normal draws of shape (n_trials, 2, n_positions), one stream per trial.

    Trial k uses ``SeedSequence([seed, scenario_key, k])``: its numbers do not depend on
    how many trials run, in which order, or on how many cores.
    """
    out = np.empty((n_trials, 2, n_positions))
    for k in range(n_trials):
        rng = np.random.default_rng(np.random.SeedSequence([seed, scenario_key, k]))
        out[k] = rng.standard_normal((2, n_positions))
    return out


def simulate(
    sc: Scenario,
    accel: SensorErrors,
    gyro: SensorErrors,
    normals: np.ndarray | None,
    n_samples: int,
) -> Readings:
    """Averaged readings for every trial: noise-free model plus sigma/sqrt(N) times ``normals``.

    ``normals`` is (T, 2, P) from :func:`standard_normals`, or None for one noise-free trial.
    """
    tau_deg, axis, role = simulation_positions(sc)
    f_b, w_b = _true_vectors(sc, tau_deg)
    acc0 = _sense(f_b, axis, accel)
    gyr0 = _sense(w_b, axis, gyro)
    if normals is None:
        acc, gyr = acc0[None, :], gyr0[None, :]
    else:
        if normals.shape[1:] != (2, tau_deg.size):
            raise ValueError(f"normals must have shape (T, 2, {tau_deg.size}), got {normals.shape}")
        acc = acc0 + accel.sigma / np.sqrt(n_samples) * normals[:, 0, :]
        gyr = gyr0 + gyro.sigma / np.sqrt(n_samples) * normals[:, 1, :]
    return Readings(tau_deg=tau_deg, axis=axis, accel=acc, gyro=gyr, role=role)
