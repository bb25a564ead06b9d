"""The pendulum released from rest at each amplitude: the period of the nonlinear motion
(eq. 1 integrated) beside the small-angle (eq. 3) and second-order (eq. 4) periods, all from
the generated model code.

Writes ``periods.csv`` (:data:`PERIOD_COLUMNS`) and ``provenance.json``.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
from pipeline.pendulum.scenario import load_scenario
from scipy.integrate import solve_ivp

from pipeline.atomic import write_csv, write_json
from pipeline.config import load_yaml, sha256_of
from pipeline.generated import pendulum as gen
from pipeline.provenance import provenance

__all__ = ["PERIOD_COLUMNS", "period", "run_scenario"]

PERIOD_COLUMNS = ["amplitude_deg", "period_s", "small_angle_s", "first_order_s"]


def period(amplitude: float, length: float, g: float) -> float:
    """Period (s) of eq. 1 from rest at ``amplitude`` (rad): four times the time to the first
    zero of theta (a quarter swing), found by an event of the integrator."""

    def rhs(_t, y):
        return [y[1], gen.angular_acceleration(y[0], length, g)]

    def crossing(_t, y):
        return y[0]

    crossing.terminal = True
    quarter = 4.0 * gen.period_small_angle(length, g)
    sol = solve_ivp(rhs, (0.0, quarter), [amplitude, 0.0], events=crossing, rtol=1e-11, atol=1e-12)
    return 4.0 * float(sol.t_events[0][0])


def run_scenario(path: str | Path, out_dir: str | Path, log: Callable = print) -> pd.DataFrame:
    sc = load_scenario(path)
    amp = np.deg2rad(np.asarray(sc.amplitudes_deg, dtype=float))
    frame = pd.DataFrame(
        {
            "amplitude_deg": sc.amplitudes_deg,
            "period_s": [period(a, sc.length_m, sc.g_m_s2) for a in amp],
            "small_angle_s": gen.period_small_angle(sc.length_m, sc.g_m_s2) + 0 * amp,
            "first_order_s": gen.period_first_order(sc.length_m, sc.g_m_s2, amp),
        }
    )
    out_dir = Path(out_dir)
    write_csv(out_dir / "periods.csv", frame, PERIOD_COLUMNS)
    write_json(
        out_dir / "provenance.json",
        provenance(scenario=sc.name, config_sha256=sha256_of(load_yaml(path)), seeds=None),
    )
    log(f"{sc.name}: {len(frame)} amplitudes")
    return frame
