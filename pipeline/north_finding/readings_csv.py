"""The readings CSV of a user's turntable: its frames, signs and format, and its validation.

:func:`pipeline.north_finding.readings.load_readings_csv` reads it into a ``Readings``; the
estimators treat it exactly like simulated readings (whose positions carry the same roles).

Frames and signs (those of ``derivations/north_finding/sensors.py``)
-------------------------------------------------------------------
* N is NED (x north, y east, z down). The table frame T is N turned by the 3-2-1 Euler
  angles psi (azimuth of the table's x axis, from north toward east), theta (pitch, x up
  positive) and phi (roll, y down positive).
* B is T turned by the table angle ``tau`` about the table's z axis (z_T, pointing down when
  level): ``[T]^{BT} = rot_z(tau)``, so a positive tau turns x_B from north toward east, seen
  from above clockwise (right-handed about the down axis). tau = 90 deg on a level table at
  psi = 0 points x_B east.
* Readings are specific force (accelerometer, m/s^2: a still accelerometer reads minus
  gravity, so one pointing down reads -g and one pointing up +g) and angular rate relative
  to inertial space (gyro, rad/s, right-handed about the sensitive axis: one pointing north
  reads +Omega cos(lat), one pointing down -Omega sin(lat)).
* The table is still during every reading (eqs. 15, 37): the estimators have no term for a
  turning table.

Readings CSV (one row per reading; lines starting with ``#`` are comments)
--------------------------------------------------------------------------
================  ==========================================================================
column            meaning
================  ==========================================================================
tau_deg           table angle tau, deg, 0 <= tau_deg < 360 (sense above)
axis              axis of B the sensors' sensitive axes point along: ``x`` (as mounted),
                  ``y`` (mounted on y_B; levelling methods L3, L4) or ``z`` (turned by -90
                  deg about y_B, so along +z_B: methods L5, A6)
role              what the reading is for (below)
accel_m_s2        averaged accelerometer reading, m/s^2 (specific force)
gyro_rad_s        averaged gyro reading, rad/s
n_samples         number of samples averaged, an integer >= 1 (provenance only)
table_rate_deg_s  optional: the table rate during the reading, deg/s; must be 0
================  ==========================================================================

Roles (a position may appear once per role; the same position under two roles is two
separate readings):

* ``fixed``: tau 0, 90, 180 or 270 deg on axis x or y (L1, L3, L5, A1, A4, A5, A6);
* ``ls``: the least-squares set on axis x (L2) or y (L4), at least 3 positions;
* ``a2``: the axis-x reading of method A2 at the scenario's ``a2_tau_deg``;
* ``peak``: the axis-x scan whose largest reading method A3 takes as the maximum over tau
  (the scan's step bounds A3's error: :mod:`pipeline.north_finding.scan_bound`);
* ``z``: the one axis-z reading (L5, A6).

Local gravity, Earth rate, latitude and the compass heading come from the scenario file (or
the CLI).

Worked example: a level-ish table at latitude 35.7 deg with psi = 30, theta = 2,
phi = -1 deg and ideal sensors reads (``gen`` is the generated model the simulations use)

>>> import numpy as np
>>> g, om, lat = 9.80665, 7.292115e-5, np.deg2rad(35.7)
>>> att = np.deg2rad([30.0, 2.0, -1.0])  # psi, theta, phi
>>> def row(tau):
...     f = gen.specific_force_b(g, om, lat, *att, np.deg2rad(tau), 0.0, 0.0, 0.0)
...     w = gen.angular_rate_b(om, lat, *att, np.deg2rad(tau), 0.0)
...     return f"{tau:g},x,fixed,{f[0]:.6f},{w[0]:.6e},1000"
>>> print("\\n".join(row(tau) for tau in (0, 90, 180, 270)))
0,x,fixed,0.342247,5.273817e-05,1000
90,x,fixed,0.171045,-2.889357e-05,1000
180,x,fixed,-0.342247,-5.273817e-05,1000
270,x,fixed,-0.171045,2.889357e-05,1000

(the x accelerometer reads +g sin(theta) at tau = 0: x_B points up when theta > 0), and the
z row ``0,z,z,-9.799183,-4.124732e-05,1000``: pointing nearly down it reads about -g and
-Omega sin(lat). Those four rows, saved as a CSV, give back the attitude (levelling L1, then
azimuth A4 with a compass heading of 25 deg, which only picks the root):

>>> import tempfile, pathlib
>>> from pipeline.north_finding import estimators as est, readings as rd
>>> text = "tau_deg,axis,role,accel_m_s2,gyro_rad_s,n_samples\\n"
>>> text += "\\n".join(row(tau) for tau in (0, 90, 180, 270)) + "\\n"
>>> with tempfile.TemporaryDirectory() as tmp:
...     path = pathlib.Path(tmp, "r.csv")
...     _ = path.write_text(text, encoding="utf-8")
...     readings = rd.load_readings_csv(path)
>>> out = est.estimate_all(readings, est.Site(lat, g, om), ("L1", "A4"), "L1", None,
...                        np.deg2rad([25.0]), None)
>>> keys = [("L1", "theta_deg"), ("L1", "phi_deg"), ("A4", "psi_deg")]
>>> print("theta, phi, psi (deg):", *(f"{float(out[k][0]):.3f}" for k in keys))
theta, phi, psi (deg): 2.000 -1.000 30.000

(the rows carry six digits, so the angles come back to about 1e-5 deg), as does
``inertial-repro north-finding estimate --readings r.csv --lat-deg 35.7 --g 9.80665
--compass-deg 25 --methods L1 A4``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.config import ConfigError
from pipeline.generated import north_finding as gen  # noqa: F401 (the worked example uses it)

__all__ = [
    "READINGS_COLUMNS",
    "OPTIONAL_COLUMNS",
    "AXES",
    "ROLES",
    "ROLE_AXES",
    "FIXED_TAU_DEG",
    "TAU_TOL_DEG",
    "circular_diff",
    "format_help",
    "read_readings_frame",
]

READINGS_COLUMNS = ["tau_deg", "axis", "role", "accel_m_s2", "gyro_rad_s", "n_samples"]
OPTIONAL_COLUMNS = ["table_rate_deg_s"]
AXES = ("x", "y", "z")
ROLES = ("fixed", "ls", "a2", "peak", "z")
#: the axes each role may be read on
ROLE_AXES = {"fixed": ("x", "y"), "ls": ("x", "y"), "a2": ("x",), "peak": ("x",), "z": ("z",)}
FIXED_TAU_DEG = (0.0, 90.0, 180.0, 270.0)
TAU_TOL_DEG = 1e-6
#: the most samples a reading may average (1 kHz for about 30 years)
MAX_N_SAMPLES = 10**12


def format_help() -> str:
    """The frames, signs and CSV format of this module's docstring (for the CLI's --help).

    The worked example keeps its rows and drops its code lines.

    >>> text = format_help()
    >>> "role" in text and "0,x,fixed,0.342247,5.273817e-05,1000" in text and ">>>" not in text
    True
    """
    lines = (__doc__ or "")[(__doc__ or "").index("Frames and signs") :].splitlines()
    kept = [ln for ln in lines if not ln.lstrip().startswith((">>>", "..."))]
    return "\n".join(kept).rstrip() + "\n(pipeline/north_finding/readings_csv.py)\n"


def circular_diff(a: np.ndarray, b: float) -> np.ndarray:
    return np.abs((np.asarray(a, dtype=float) - b + 180.0) % 360.0 - 180.0)


def _refuse(path: Path, row: int, column: str, value: object, allowed: str) -> ConfigError:
    """A one-line error naming file, row (1 = first data row), column, value and what is allowed."""
    return ConfigError(f"{path}: row {row + 1}, column {column} = {value!r}: {allowed}")


def read_readings_frame(path: str | Path) -> pd.DataFrame:
    """A user's readings CSV, validated (format in the module docstring); errors name the file,
    the row (1 = first data row), the column, the value and what is allowed."""
    path = Path(path)
    if not path.is_file():
        raise ConfigError(f"{path}: not found (or not a file); allowed: a readings CSV file")
    raw_bytes = path.read_bytes()
    try:
        raw_bytes.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ConfigError(
            f"{path}: byte {exc.start} = {raw_bytes[exc.start : exc.start + 1]!r}: not UTF-8 "
            "text; allowed: a UTF-8 (or ASCII) CSV file"
        ) from None
    if not raw_bytes.strip() or "\x00" in raw_bytes.decode("utf-8"):
        shown = "empty" if not raw_bytes.strip() else "contains NUL bytes"
        raise ConfigError(
            f"{path}: {shown}; allowed: a readings CSV with a header line "
            f"({', '.join(READINGS_COLUMNS)}) and one row per reading"
        )
    try:
        frame = pd.read_csv(path, comment="#", skipinitialspace=True, dtype=str)
    except (OSError, pd.errors.ParserError, pd.errors.EmptyDataError) as exc:
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        raise ConfigError(
            f"{path}: cannot read as CSV ({first}); allowed: a header line "
            f"({', '.join(READINGS_COLUMNS)}) and one comma-separated row per reading"
        ) from None
    frame.columns = [str(c).strip() for c in frame.columns]
    missing = [c for c in READINGS_COLUMNS if c not in frame.columns]
    if missing:
        hint = (
            " (the role column is new: fixed, ls, a2, peak or z per row; see "
            "pipeline/north_finding/readings.py)"
            if missing == ["role"]
            else ""
        )
        raise ConfigError(
            f"{path}: missing columns {missing}; a readings CSV has columns {READINGS_COLUMNS}"
            f"{hint}"
        )
    allowed_cols = READINGS_COLUMNS + OPTIONAL_COLUMNS
    extra = [c for c in frame.columns if c not in allowed_cols]
    if extra:
        raise ConfigError(f"{path}: unknown columns {extra}; allowed: {allowed_cols}")
    if frame.empty:
        raise ConfigError(f"{path}: no readings (a header only); allowed: one row per reading")
    for c in ("axis", "role"):
        frame[c] = frame[c].fillna("").str.strip()
    numeric = ["tau_deg", "accel_m_s2", "gyro_rad_s", "n_samples"]
    numeric += [c for c in OPTIONAL_COLUMNS if c in frame.columns]
    raw = frame.copy()
    for c in numeric:
        values = pd.to_numeric(frame[c], errors="coerce")
        bad = values.isna() | ~np.isfinite(values)
        if bad.any():
            row = int(np.flatnonzero(bad)[0])
            raise _refuse(path, row, c, raw[c].iloc[row], "must be a finite number")
        frame[c] = values
    checks = [
        (
            "tau_deg",
            (frame["tau_deg"] < 0) | (frame["tau_deg"] >= 360),
            "allowed 0 <= tau_deg < 360",
        ),
        ("axis", ~frame["axis"].isin(AXES), f"allowed {list(AXES)}"),
        ("role", ~frame["role"].isin(ROLES), f"allowed {list(ROLES)}"),
        (
            "n_samples",
            (frame["n_samples"] < 1)
            | (frame["n_samples"] % 1 != 0)
            | (frame["n_samples"] > MAX_N_SAMPLES),
            f"must be an integer >= 1 and <= {MAX_N_SAMPLES:.0e} (1 kHz for 30 years)",
        ),
    ]
    if "table_rate_deg_s" in frame.columns:
        checks.append(
            (
                "table_rate_deg_s",
                frame["table_rate_deg_s"] != 0,
                "the table must be still during a reading (eqs. 15, 37 have no table rate): "
                "allowed 0; drop readings taken while the table turned",
            )
        )
    for c, bad, allowed in checks:
        if bad.any():
            row = int(np.flatnonzero(bad.to_numpy())[0])
            raise _refuse(path, row, c, raw[c].iloc[row].strip(), allowed)
    _check_rows(path, frame, raw)
    return frame


def _check_rows(path: Path, frame: pd.DataFrame, raw: pd.DataFrame) -> None:
    """Readings the format cannot express: a role on the wrong axis, a fixed position away
    from 0/90/180/270, several z readings, one position twice under the same role."""
    rows = list(zip(frame["axis"], frame["role"], frame["tau_deg"], strict=True))
    for row, (axis, role, tau) in enumerate(rows):
        if axis not in ROLE_AXES[role]:
            raise _refuse(
                path, row, "axis", axis, f"role {role} readings are on axis {list(ROLE_AXES[role])}"
            )
        if role == "fixed" and min(circular_diff(np.array(FIXED_TAU_DEG), tau)) >= TAU_TOL_DEG:
            raise _refuse(
                path,
                row,
                "tau_deg",
                raw["tau_deg"].iloc[row].strip(),
                "role fixed readings are at tau_deg 0, 90, 180 or 270 (use role ls, a2 or peak "
                "for other angles)",
            )
    z_rows = np.flatnonzero(frame["role"].to_numpy() == "z")
    if z_rows.size > 1:
        raise _refuse(
            path,
            int(z_rows[1]),
            "role",
            "z",
            f"one z reading allowed (row {z_rows[0] + 1} is one already); average them into one",
        )
    seen: dict[tuple[str, str, float], int] = {}
    for row, (axis, role, tau) in enumerate(rows):
        key = (axis, role, round(float(tau) % 360.0, 6))
        if key in seen:
            raise _refuse(
                path,
                row,
                "tau_deg",
                raw["tau_deg"].iloc[row].strip(),
                f"duplicate position: row {seen[key] + 1} already has axis {axis}, role {role} "
                "at this tau; each position appears once per role (average repeated readings)",
            )
        seen[key] = row
