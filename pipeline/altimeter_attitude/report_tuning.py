"""The report's UKF tuning table: ``<published scenario>/ukf_tuning.csv`` as one row per
(alpha, kappa) setting, with a sentence computed from it.

>>> frame = pd.DataFrame({
...     "alpha": [0.5, 1.0], "kappa": [0.0, 0.0], "beta": [2.0, 2.0], "wm0": [-3.0, 0.0],
...     "wc0": [-0.25, 2.0], "nonnegative_weights": [False, True], "chosen": [False, True],
...     "roll_rms_deg": [0.56, 0.56], "pitch_rms_deg": [0.537, 0.536],
...     "nees_roll": [0.77, 0.77], "nees_pitch": [1.2, 1.2],
...     "noise_free_roll_rms_deg": [0.123, 0.122], "noise_free_pitch_rms_deg": [0.53, 0.527],
...     "n_runs": [100, 100], "status": ["ok", "ok"]})
>>> print(tuning_sentence(frame))  # doctest: +NORMALIZE_WHITESPACE
Over the 2 settings that ran (of 2), the UKF's Monte Carlo roll/pitch RMS over the flight
spans [0.560, 0.560]/[0.536, 0.537] deg and its noise-free roll/pitch RMS [0.122, 0.123]/[0.527,
0.530] deg. We use alpha 1, kappa 0, beta 2 (marked): the settings with every weight >= 0 are
alpha 1, kappa 0.
"""

from __future__ import annotations

import pandas as pd

from pipeline.altimeter_attitude.report_findings import fmt3
from pipeline.report.html import format_value
from pipeline.report.model import Block, Paragraph, Section, frame_table, not_available

#: id of the tuning section (the combined report puts it in the paper's supporting appendix)
TUNING_ID = "ukf-tuning"

__all__ = ["TUNING_ID", "tuning_section", "tuning_sentence"]

_SHOWN = {
    "alpha": "alpha",
    "kappa": "kappa",
    "wm0": "W0 (mean)",
    "wc0": "W0 (cov.)",
    "nonnegative_weights": "all weights >= 0",
    "chosen": "used",
    "roll_rms_deg": "roll RMS (deg)",
    "pitch_rms_deg": "pitch RMS (deg)",
    "noise_free_roll_rms_deg": "noise-free roll RMS (deg)",
    "noise_free_pitch_rms_deg": "noise-free pitch RMS (deg)",
    "nees_pitch": "pitch NEES",
    "status": "status",
}


def _span(s: pd.Series) -> str:
    return f"[{s.min():.3f}, {s.max():.3f}]"


def _setting(row: pd.Series) -> str:
    return f"alpha {row['alpha']:g}, kappa {row['kappa']:g}"


def tuning_sentence(tuning: pd.DataFrame) -> str:
    """What the grid shows and which setting is used, computed from ``tuning``."""
    ran = tuning[tuning["status"] == "ok"]
    out = (
        f"Over the {len(ran)} settings that ran (of {len(tuning)}), the UKF's Monte Carlo "
        f"roll/pitch RMS over the flight spans {_span(ran['roll_rms_deg'])}/"
        f"{_span(ran['pitch_rms_deg'])} deg and its noise-free roll/pitch RMS "
        f"{_span(ran['noise_free_roll_rms_deg'])}/{_span(ran['noise_free_pitch_rms_deg'])} deg."
    )
    used = tuning[tuning["chosen"].astype(bool)]
    nonneg = tuning[tuning["nonnegative_weights"].astype(bool)]
    rule = "; ".join(_setting(r) for _, r in nonneg.iterrows()) if len(nonneg) else "none of them"
    if len(used):
        u = used.iloc[0]
        out += f" We use {_setting(u)}, beta {u['beta']:g} (marked):"
    else:
        out += " The scenario's own setting is not in the grid;"
    return out + f" the settings with every weight >= 0 are {rule}."


def tuning_section(tuning: pd.DataFrame | None, shown: str = "ukf_tuning.csv") -> Section:
    """The "UKF sigma-point tuning" section (a table and its sentence)."""
    inner: list[Block] = [
        Paragraph(
            "The paper names its UKF (Julier/Uhlmann, Wan/van der Merwe) but gives none of its "
            "parameters. The UKF of the published scenario over a grid of its Merwe scaled "
            "sigma-point parameters alpha and kappa (beta as the scenario), on the scenario's "
            "own Monte Carlo draws and its noise-free run with an exact start; RMS over runs "
            "and over the flight after the transient; W0 the centre weights of the mean and of "
            "the covariance."
        )
    ]
    if tuning is None or tuning.empty:
        inner.append(not_available(shown))
    else:
        inner.append(Paragraph(tuning_sentence(tuning)))
        table = tuning[list(_SHOWN)].copy()
        for c in ("alpha", "kappa"):
            table[c] = table[c].map(format_value)
        for c in ("nonnegative_weights", "chosen"):
            table[c] = table[c].map(lambda x: "yes" if bool(x) else "no")
        fmts = {c: fmt3 for c in _SHOWN if c.endswith("_deg") or c.startswith("nees")}
        fmts.update({c: (lambda x: f"{x:.4g}") for c in ("wm0", "wc0")})
        inner.append(
            frame_table(table.rename(columns=_SHOWN), formatters=_renamed(fmts), caption=shown)
        )
    return Section(TUNING_ID, "UKF sigma-point tuning", inner)


def _renamed(fmts: dict) -> dict:
    return {_SHOWN[k]: v for k, v in fmts.items()}
