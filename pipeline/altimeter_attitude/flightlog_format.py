"""Flight-log format: which CSV column holds which quantity in which unit, and the log checks.

Quantities (the project's own column names are the defaults, their unit in the suffix)::

    t                 t_s                          s | ms | us
    gyro_x, _y, _z    gyro_x_rad_s (or _deg_s)     rad/s | deg/s   (omega_nb^b, body x fwd, z down)
    accel_x, _y, _z   accel_x_m_s2                 m/s^2 | g0      (specific force; g0 = 9.80665)
    altimeter         altimeter_m                  m | ft          (barometric altitude, up)

A map ``QUANTITY=COLUMN[:UNIT]`` (``--columns``, comma separated) or a YAML/JSON file
(``--format``) renames them. Without ``:UNIT`` the unit is read from the column name's
suffix (``_rad_s``, ``_deg_s``, ``_m_s2``, ``_g0``, ``_m``, ``_ft``, ``_s``, ``_ms``, ``_us``);
a column with neither is refused. The file holds ``columns`` and optionally ``stamp``::

    columns:
      t: {column: time, unit: ms}
      gyro_x: {column: gx, unit: deg/s}
      altimeter: alt_m            # unit from the suffix
    stamp: end

>>> parse_columns("gyro_x=gx:deg/s, altimeter=alt_m")
{'gyro_x': ('gx', 'deg/s'), 'altimeter': ('alt_m', None)}
>>> unit_of("altimeter", "alt_m", None), UNITS["gyro"]["deg/s"]
('m', 0.017453292519943295)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

__all__ = [
    "QUANTITIES",
    "UNITS",
    "STAMPS",
    "HELD_MODES",
    "FlightLogError",
    "FlightLog",
    "parse_columns",
    "load_format",
    "unit_of",
    "read_log",
]

AXES = ("x", "y", "z")
QUANTITIES = ("t", *(f"gyro_{a}" for a in AXES), *(f"accel_{a}" for a in AXES), "altimeter")
#: per kind of quantity: unit -> factor to SI (s, rad/s, m/s^2, m)
UNITS = {
    "t": {"s": 1.0, "ms": 1e-3, "us": 1e-6},
    "gyro": {"rad/s": 1.0, "deg/s": math.pi / 180.0},
    "accel": {"m/s^2": 1.0, "g0": 9.80665},
    "altimeter": {"m": 1.0, "ft": 0.3048},
}
SUFFIXES = {
    "t": {"_s": "s", "_ms": "ms", "_us": "us"},
    "gyro": {"_rad_s": "rad/s", "_deg_s": "deg/s"},
    "accel": {"_m_s2": "m/s^2", "_g0": "g0"},
    "altimeter": {"_m": "m", "_ft": "ft"},
}
STAMPS = ("start", "end")
# --altimeter-held: a logger that writes the last altimeter value on every IMU row (sample and
# hold) repeats it until the next sample. 'check' refuses a column whose values repeat the row
# before on at least HELD_FRACTION of its samples (a real altimeter's noise rarely repeats a
# value exactly); 'yes' keeps the first row of each held run as the sample (the hold period n
# inferred, every n-th row from the first change); 'no' takes every value as a fresh sample.
HELD_MODES = ("check", "yes", "no")
HELD_FRACTION = 0.5
MAX_LISTED = 5  # rows quoted in an error message


class FlightLogError(ValueError):
    """A malformed flight log or format: the message names the file, the column/row and what is allowed."""


def _kind(quantity: str) -> str:
    return quantity.split("_")[0]


def unit_of(quantity: str, column: str, unit: str | None, where: str = "--columns") -> str:
    """The unit of ``column`` holding ``quantity``: ``unit`` if given, else from the suffix."""
    kind = _kind(quantity)
    allowed = UNITS[kind]
    if unit is not None:
        if unit not in allowed:
            raise FlightLogError(
                f"{where}: {quantity}={column}:{unit}: unit {unit!r} unknown for {quantity}; "
                f"allowed: {', '.join(allowed)}"
            )
        return unit
    for suffix, name in sorted(SUFFIXES[kind].items(), key=lambda s: -len(s[0])):
        if column.endswith(suffix):
            return name
    raise FlightLogError(
        f"{where}: {quantity}={column}: no unit given and none in the column name; write "
        f"{quantity}={column}:UNIT with UNIT one of {', '.join(allowed)}"
    )


def _entry(out: dict, quantity: object, column: object, unit: object, where: str) -> None:
    """Check and add one map entry (quantity -> (column, unit or None))."""
    item = f"{quantity}={column}" + (f":{unit}" if unit is not None else "")
    if quantity not in QUANTITIES:
        raise FlightLogError(
            f"{where}: {item!r}: quantity {quantity!r} unknown; allowed: {', '.join(QUANTITIES)}"
        )
    if not isinstance(column, str) or not column or not (unit is None or isinstance(unit, str)):
        raise FlightLogError(f"{where}: {item!r}: the column and unit must be non-empty text")
    if quantity in out:
        raise FlightLogError(f"{where}: {quantity} is mapped twice")
    unit_of(str(quantity), column, unit, where)
    out[quantity] = (column, unit)


def parse_columns(text: str, where: str = "--columns") -> dict[str, tuple[str, str | None]]:
    """``QUANTITY=COLUMN[:UNIT],...`` -> {quantity: (column, unit or None)}."""
    out: dict[str, tuple[str, str | None]] = {}
    for item in (s.strip() for s in text.split(",")):
        if not item:
            continue
        quantity, eq, rest = (s.strip() for s in item.partition("="))
        column, _, unit = (s.strip() for s in rest.partition(":"))
        if not eq or not column:
            raise FlightLogError(f"{where}: {item!r}: write QUANTITY=COLUMN[:UNIT]")
        _entry(out, quantity, column, unit or None, where)
    return out


def load_format(path: str | Path) -> tuple[dict[str, tuple[str, str | None]], str | None]:
    """A YAML/JSON format file -> (column map, stamp or None)."""
    from pipeline.config import ConfigError, load_yaml

    path = Path(path)
    try:  # read strictly: binary bytes, tags, duplicate keys, NaN, alias bombs
        raw = load_yaml(path)
    except ConfigError as exc:
        raise FlightLogError(f"--format: {exc}") from None
    if not isinstance(raw, dict) or not set(raw) <= {"columns", "stamp"}:
        raise FlightLogError(f"{path}: a format file is a mapping with keys columns and stamp")
    stamp = raw.get("stamp")
    if stamp is not None and stamp not in STAMPS:
        raise FlightLogError(f"{path}: stamp = {stamp!r}: allowed: {', '.join(STAMPS)}")
    cols = raw.get("columns") or {}
    if not isinstance(cols, dict):
        raise FlightLogError(f"{path}: columns must be a mapping QUANTITY: {{column, unit}}")
    out: dict[str, tuple[str, str | None]] = {}
    for quantity, spec in cols.items():
        if isinstance(spec, dict) and set(spec) <= {"column", "unit"} and "column" in spec:
            column, unit = spec["column"], spec.get("unit")
        elif isinstance(spec, str):
            column, unit = spec, None
        else:
            raise FlightLogError(
                f"{path}: columns.{quantity} = {spec!r}: write a column name or {{column, unit}}"
            )
        _entry(out, quantity, column, unit, str(path))
    return out, stamp


#: |value| (SI) a sensor column may hold, and how the allowed range is shown
SENSOR_RANGE = {
    "gyro": (2000.0 * np.pi / 180.0, "34.9 rad/s (2000 deg/s)"),
    "accel": (50 * 9.80665, "490 m/s^2 (50 g)"),
}


@dataclass(frozen=True)
class FlightLog:
    """A checked log in SI units: rows k = 0..n-1."""

    path: Path
    t: np.ndarray  # s
    gyro: np.ndarray  # (n, 3) rad/s
    accel: np.ndarray  # (n, 3) m/s^2
    altimeter: np.ndarray  # (n,) m, NaN where no sample
    dt: float  # median IMU step, s
    every: int  # altimeter every n-th row
    columns: dict[str, tuple[str, str]]  # quantity -> (column, unit) as used
    max_step_dev: float  # largest |step - dt| / dt
    held: int = 0  # the hold period in rows of a sample-and-hold altimeter column (0: not held)

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0])

    def summary(self) -> str:
        n_alt = int(np.isfinite(self.altimeter).sum())
        return (
            f"{self.path}: {len(self.t)} rows, {self.duration:.6g} s; IMU {1 / self.dt:.6g} Hz "
            f"(dt {self.dt:.6g} s, largest step deviation {self.max_step_dev:.2%}, no gaps); "
            f"altimeter {1 / (self.dt * self.every):.6g} Hz (every {self.every} rows, {n_alt} "
            "samples"
            + ("; held values dropped, first row of each hold kept" if self.held else "")
            + "); columns "
            + ", ".join(f"{q}={c}[{u}]" for q, (c, u) in self.columns.items())
        )


def _rows(index: np.ndarray, values: np.ndarray | None = None, unit: str = "") -> str:
    shown = [
        f"{i + 1}" + ("" if values is None else f" ({values[j]:.6g}{unit})")
        for j, i in enumerate(index[:MAX_LISTED])
    ]
    more = f", ... ({index.size} in all)" if index.size > MAX_LISTED else ""
    return ", ".join(shown) + more


def _cell(value: object) -> str:
    """A CSV cell as the user wrote it: an empty cell is named as such, not as ``nan``."""
    if value is None or (isinstance(value, float) and np.isnan(value)):
        return "an empty cell"
    return repr(value.item() if isinstance(value, np.generic) else value)


def _resolve(frame: pd.DataFrame, path: Path, mapping: dict) -> dict[str, tuple[str, str]]:
    """quantity -> (column, unit): the map, else the project's default names."""
    used: dict[str, tuple[str, str]] = {}
    for q in QUANTITIES:
        if q in mapping:
            column, unit = mapping[q]
            used[q] = (column, unit_of(q, column, unit))
            continue
        kind, axis = _kind(q), q.rpartition("_")[2]
        names = {
            "t": ["t_s"],
            "gyro": [f"gyro_{axis}_rad_s", f"gyro_{axis}_deg_s"],
            "accel": [f"accel_{axis}_m_s2"],
            "altimeter": ["altimeter_m"],
        }[kind]
        found = [n for n in names if n in frame]
        used[q] = (found[0], unit_of(q, found[0], None)) if found else (names[0], "")
    missing = [f"{q} ({c})" for q, (c, _) in used.items() if c not in frame]
    if missing:
        raise FlightLogError(
            f"{path}: missing columns for {', '.join(missing)}; found {list(frame)}; map yours "
            "with --columns QUANTITY=COLUMN[:UNIT] or --format FILE"
        )
    return used


def _hold_period(rows: np.ndarray, values: np.ndarray) -> tuple[int, int, str]:
    """(n, first change's row, "") when the values change only every multiple of n >= 2 rows
    (a hold of n rows), else (0, 0, what was found)."""
    changes = rows[1:][values[1:] != values[:-1]]
    spacing = np.diff(changes)
    if spacing.size == 0:
        return 0, 0, "fewer than 3 changes of value"
    n = int(spacing.min())
    if n < 2:
        return 0, 0, f"a change of value on consecutive rows ({_rows(changes[1:][spacing < 2])})"
    if np.any(spacing % n):
        bad = changes[1:][spacing % n != 0]
        return 0, 0, f"changes every {n} rows (smallest spacing), but at rows {_rows(bad)} off it"
    return n, int(changes[0]), ""


def _unhold(alt: np.ndarray, path: Path, col: str, mode: str) -> tuple[np.ndarray, int]:
    """The altimeter column with held repeats made empty, and the hold period (0: not held).

    'check' refuses a column with a value on every row that repeats the row before on at least
    HELD_FRACTION of them and changes only with a fixed period (a noise-free altitude that is
    constant in level flight changes on consecutive rows in a climb: not a hold).

    >>> a = np.repeat([1.0, 1.5, 1.5, 2.0, 2.5], 3)[1:]  # held 3 rows; one new sample repeats
    >>> out, n = _unhold(a, Path("log.csv"), "alt_m", "yes")
    >>> n, np.flatnonzero(np.isfinite(out)).tolist()
    (3, [2, 5, 8, 11])
    """
    if mode not in HELD_MODES:
        raise FlightLogError(f"--altimeter-held = {mode!r}: allowed: {', '.join(HELD_MODES)}")
    rows = np.flatnonzero(np.isfinite(alt))
    if mode == "no" or rows.size < 2:
        return alt, 0
    values = alt[rows]
    n, first, found = _hold_period(rows, values)
    if mode == "check":
        repeats = int(np.count_nonzero(values[1:] == values[:-1]))
        if n and rows.size == alt.size and repeats >= HELD_FRACTION * (rows.size - 1):
            raise FlightLogError(
                f"{path}: column {col} repeats its value before on {repeats} of "
                f"{rows.size - 1} values and changes only every {n} rows: a sample-and-hold "
                "altimeter written on every row? --altimeter-held yes keeps the first row of "
                "each hold as the sample; --altimeter-held no takes every value as a fresh "
                "sample; or leave the cells empty where there is no new sample"
            )
        return alt, 0
    if not n:
        raise FlightLogError(
            f"{path}: --altimeter-held yes: column {col} shows {found}; allowed: a column "
            "whose value changes only every n-th row, n >= 2 fixed"
        )
    keep = rows[(rows - first) % n == 0]
    out = np.full_like(alt, np.nan)
    out[keep] = alt[keep]
    return out, n


def read_log(
    path: str | Path,
    columns: dict | None = None,
    max_jitter: float = 0.01,
    altimeter_held: str = "check",
) -> FlightLog:
    """Parse and check a flight log (``columns`` from :func:`parse_columns`;
    ``altimeter_held`` one of :data:`HELD_MODES`, see there)."""
    path = Path(path)
    try:
        data = path.read_bytes()
        data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise FlightLogError(
            f"{path}: byte {exc.start} = {data[exc.start : exc.start + 1]!r}: not UTF-8 text; "
            "allowed: a UTF-8 (or ASCII) CSV file"
        ) from None
    except OSError as exc:
        raise FlightLogError(
            f"{path}: cannot read: {exc.strerror or exc}; allowed: a flight-log CSV file"
        ) from None
    try:  # every cell as text: 'nan' is named as written, an empty cell as empty
        frame = pd.read_csv(path, dtype=str, keep_default_na=False, skipinitialspace=True)
    except pd.errors.EmptyDataError:
        raise FlightLogError(f"{path}: the file is empty; need a header and IMU rows") from None
    except (OSError, pd.errors.ParserError, UnicodeDecodeError) as exc:
        first = str(exc).strip().splitlines()[-1] if str(exc).strip() else type(exc).__name__
        raise FlightLogError(f"{path}: cannot read as CSV: {first}") from None
    used = _resolve(frame, path, columns or {})
    if len(frame) < 3:
        raise FlightLogError(f"{path}: {len(frame)} rows; need at least 3 IMU samples")
    si = {}
    for q, (col, unit) in used.items():
        cells = frame[col].str.strip()
        values = pd.to_numeric(cells.mask(cells == ""), errors="coerce").to_numpy(dtype=float)
        bad = ~np.isfinite(values)
        if q == "altimeter":
            bad &= (cells != "").to_numpy()
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            hint = " (leave it empty where there is no sample)" if q == "altimeter" else ""
            raise FlightLogError(
                f"{path}: column {col} ({q}), data row {i + 1}: {_cell(cells.iloc[i] or None)} "
                f"is not a finite number{hint}"
            )
        si[q] = values * UNITS[_kind(q)][unit]
        limit = SENSOR_RANGE.get(_kind(q))
        if limit is not None and np.any(np.abs(si[q]) > limit[0]):
            i = int(np.flatnonzero(np.abs(si[q]) > limit[0])[0])
            raise FlightLogError(
                f"{path}: column {col} ({q}), data row {i + 1}: {values[i]:g} {unit}: allowed "
                f"|{q}| <= {limit[1]} (an IMU's range; check the unit)"
            )
    t_col = used["t"][0]
    t = si["t"]
    steps = np.diff(t)
    if np.any(steps <= 0):
        rows = np.flatnonzero(steps <= 0) + 1
        raise FlightLogError(
            f"{path}: column {t_col} must be strictly increasing; data rows "
            f"{_rows(rows, t[rows], ' s')} are not after the row before"
        )
    dt = float(np.median(steps))
    dev = np.abs(steps - dt) / dt
    off = np.flatnonzero(dev > max_jitter)
    if off.size:
        raise FlightLogError(
            f"{path}: column {t_col}: the IMU step is inferred as {dt:.6g} s ({1 / dt:.6g} Hz) "
            f"and every step must be within {max_jitter:.3g} of it (--max-jitter); gaps or "
            f"jitter before data rows {_rows(off + 1, steps[off], ' s')}"
        )
    a_col = used["altimeter"][0]
    alt, held = _unhold(si["altimeter"], path, a_col, altimeter_held)
    rows = np.flatnonzero(np.isfinite(alt))
    if rows.size < 2:
        raise FlightLogError(f"{path}: column {a_col} has {rows.size} samples; need at least 2")
    gaps = np.diff(rows)
    every = int(np.min(gaps))
    if np.any(gaps != every):
        broken = rows[1:][gaps != every]
        raise FlightLogError(
            f"{path}: column {a_col} must sample every n-th IMU row; inferred n = {every} "
            f"(smallest spacing), but data rows {_rows(broken)} break it (gaps or jitter)"
        )
    return FlightLog(
        path=path,
        t=t,
        gyro=np.stack([si[f"gyro_{a}"] for a in AXES], -1),
        accel=np.stack([si[f"accel_{a}"] for a in AXES], -1),
        altimeter=alt,
        dt=dt,
        every=every,
        columns=used,
        max_step_dev=float(dev.max()),
        held=held,
    )
