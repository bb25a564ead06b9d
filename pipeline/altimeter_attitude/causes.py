"""Root causes of the altimeter-attitude rows that fail (:class:`pipeline.verdicts.cause.Cause`).

Each function builds one cause from the results (:class:`ScenarioResults`) and caches it on
them, so every row with that root cause carries the identical object and text; every number
in a text is formatted from the results. The engine writes a cause only on a failing row.

* :func:`rms_cause` (``unpublished``): the published RMS values (both windows) depend on what
  the paper does not publish; the evidence is how far the window, the sweep's parameters and
  the IMU rate move ours, against the gaps to the published values;
* :func:`ranking_cause` (``unpublished``): which filter is more accurate, per window and over
  the sweep, with a UKF whose settings the paper does not give;
* :func:`level_flight_cause` (``model``): a roll sigma too large mostly in wings-level
  flight, where the altimeter sees roll only to second order;
* :func:`bias_cause` (``model``): a sigma too small for an error that is mostly the filter's
  own bias (its noise-free RMS); for the UKF with what its tuning grid (ukf_tuning.csv) and
  the EKF on the same model show about where that bias comes from;
* :func:`ekf_cause` (``unpublished``): an EKF that does not diverge, where the paper gives none
  of its EKF's settings.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np

from pipeline.altimeter_attitude.columns import WINDOWS
from pipeline.altimeter_attitude.consistency import NeesCheck
from pipeline.verdicts.cause import Cause

__all__ = [
    "bias_cause",
    "ekf_cause",
    "level_flight_cause",
    "rate_trend",
    "ranking_cause",
    "rms_cause",
    "range_clause",
    "span",
    "tuning_clause",
]

ANGLES = ("roll", "pitch")
RATE = "imu_rate_hz"
#: a filter in a cause's text (reader words, not the results' tokens)
FILTER_WORDS = {
    "linear_kf": "linear KF",
    "linear_kf_no_gamma": "linear KF without the Gamma term",
    "ukf": "UKF",
    "ekf": "EKF",
    "complementary": "complementary filter",
    "gyro_only": "gyro-only propagation",
    "accel_leveling": "accelerometer levelling",
}
#: a sweep parameter in a cause's text
PARAMETER_WORDS = {
    "imu_rate_hz": "IMU sample rate",
    "intensity": "manoeuvre intensity",
    "initial_error_deg": "initial roll/pitch error",
}
#: the UKF tuning grid in a cause's text (the results file of pipeline.altimeter_attitude.ukf_tuning)
TUNING_GRID = "our UKF tuning grid"


def filter_word(token: str) -> str:
    """A filter's name for readers.

    >>> filter_word("linear_kf"), filter_word("ukf")
    ('linear KF', 'UKF')
    """
    return FILTER_WORDS.get(token, token.replace("_", " "))


UNPUBLISHED_INPUTS = (
    "its trajectory, its IMU and altimeter sample rates, its initial errors and filter tuning "
    "(k, P0, the UKF's parameters)"
)


def span(values: Iterable[float], digits: int = 2, unit: str = "") -> str:
    """``lo-hi`` of finite values at ``digits`` decimals (one number if they round alike).

    >>> span([0.351, 0.74]), span([0.2, 0.2004]), span([])
    ('0.35-0.74', '0.20', 'n/a')
    """
    xs = [float(x) for x in values if math.isfinite(float(x))]
    if not xs:
        return "n/a"
    lo, hi = f"{min(xs):.{digits}f}", f"{max(xs):.{digits}f}"
    return (lo if lo == hi else f"{lo}-{hi}") + unit


def _cached(res, key: Any, build: Callable[[], Cause | None]) -> Cause | None:
    if key not in res.cache:
        res.cache[key] = build()
    return res.cache[key]


def rate_trend(rates: Sequence[float], rms: Sequence[float]) -> tuple[float, float] | None:
    """Least-squares (slope, intercept) of log RMS on log rate; None below 2 finite points.

    >>> b, a = rate_trend([25.0, 100.0], [0.6, 0.3]); round(b, 3)
    -0.5
    """
    pts = [(r, v) for r, v in zip(rates, rms, strict=True) if v > 0 and math.isfinite(v)]
    if len(pts) < 2 or len({r for r, _ in pts}) < 2:
        return None
    x, y = np.log([r for r, _ in pts]), np.log([v for _, v in pts])
    slope, intercept = np.polyfit(x, y, 1)
    return float(slope), float(intercept)


def range_clause(published: float, values: Iterable[float], digits: int = 2) -> tuple[bool, str]:
    """Whether ``published`` lies inside ``[min, max]`` of the finite ``values``, and that said
    plainly (bounds at ``digits`` decimals; the comparison uses the unrounded values).

    >>> range_clause(0.16, [0.45, 1.8, 0.9])
    (False, '0.16 outside [0.45, 1.80] deg')
    >>> range_clause(0.5, [0.45, 1.8])
    (True, '0.5 inside [0.45, 1.80] deg')
    >>> range_clause(0.5, [float("nan")])
    (False, '0.5: no finite value')
    """
    xs = [float(x) for x in values if math.isfinite(float(x))]
    if not xs:
        return False, f"{published:g}: no finite value"
    lo, hi = min(xs), max(xs)
    inside = lo <= published <= hi
    where = "inside" if inside else "outside"
    return inside, f"{published:g} {where} [{lo:.{digits}f}, {hi:.{digits}f}] deg"


#: a window's name inside a cause's parentheses
_SHORT = {"flight": "flight", "after_bank": "after the first bank"}


def _sweep_column(quantity: str, window: str) -> str:
    return quantity if window == "flight" else f"{window}_{quantity}"


def rms_cause(res) -> Cause:
    """The one cause of every published RMS row (both windows)."""
    return _cached(res, "rms", lambda: _rms_cause(res))


def _rms_cause(res) -> Cause:
    items = [
        (i["select"]["filter"], i["quantity"], float(i["value"]))
        for i in res.published.get("items", [])
        if i.get("quantity") in ("roll_rms_deg", "pitch_rms_deg")
    ]
    ours = {(f, q, w): float(res.window(f, w)[q]) for f, q, _ in items for w in WINDOWS}
    shifts = [abs(ours[(f, q, "flight")] - ours[(f, q, "after_bank")]) for f, q, _ in items]
    clauses = [
        f"the window alone (the flight after {res.transient:g} s or the window after the "
        f"first bank) changes our {len(items)} values by {span(shifts)} deg"
    ]
    sweep = res.sweep
    if sweep is not None and len(sweep):
        found: list[str] = []
        inside = total = 0
        rates: list[float] = []
        exponents: list[float] = []
        for f, q, pub in items:
            rows = sweep[sweep["filter"] == f]
            for w in WINDOWS:
                col = _sweep_column(q, w)
                vals = list(rows[col].dropna()) if col in rows else []
                if not vals:
                    continue
                hit, clause = range_clause(pub, vals)
                total += 1
                inside += hit
                found.append(f"{filter_word(f)} {q.split('_')[0]} {_SHORT[w]}: {clause}")
            by_rate = rows[rows["parameter"] == RATE]
            col = _sweep_column(q, "after_bank")
            if col in by_rate:
                fit = rate_trend(list(by_rate["value"]), list(by_rate[col]))
                if fit is not None and fit[0] < 0:
                    exponents.append(-fit[0])
                    rates.append(math.exp((math.log(pub) - fit[1]) / fit[0]))
        params = ", ".join(PARAMETER_WORDS.get(p, p) for p in dict.fromkeys(sweep["parameter"]))
        runs = ", ".join(str(int(n)) for n in sorted(set(sweep["n_runs"])))
        clauses.append(
            f"the paper's value lies inside the range our sweep of the unpublished {params} "
            f"({runs} runs a point, one at a time) spans in {inside} of {total} cases ("
            + "; ".join(found)
            + ")"
            + (
                ", so no one of these choices moved alone over our range reaches them"
                if inside == 0
                else ""
            )
        )
        ran = _tuned(res)
        ukf_items = [(q, pub) for f, q, pub in items if f == "ukf"]
        if ran is not None and ukf_items:
            clauses.append(
                f"over the {len(ran)} sigma-point settings of {TUNING_GRID} the UKF's RMS over "
                "the flight gives "
                + "; ".join(
                    f"{q.split('_')[0]} {range_clause(pub, ran[q], 3)[1]}" for q, pub in ukf_items
                )
            )
        if rates:
            clauses.append(
                f"our RMS after the first bank falls as (IMU rate)^-b with b = {span(exponents)} and would "
                f"reach the published values near {span(rates, 0)} Hz if that trend held"
            )
    text = (
        f"The paper gives neither {UNPUBLISHED_INPUTS} nor how an RMS curve is reduced to one "
        "number; " + "; ".join(clauses) + "; so these values cannot be reproduced from what the "
        "paper publishes, which does not refute them."
    )
    return Cause("unpublished", "trajectory, rates, tuning and RMS metric are not given", text)


def ranking_cause(res, filt: str, ref: str) -> Cause:
    """Why ``filt`` is not more accurate than ``ref`` (one cause for every window's row)."""
    return _cached(res, ("ranking", filt, ref), lambda: _ranking_cause(res, filt, ref))


def _ranking_cause(res, filt: str, ref: str) -> Cause:
    def pair(w: str) -> str:
        a, b = res.window(filt, w), res.window(ref, w)
        return (
            f"{filter_word(filt)} {a['roll_rms_deg']:.3f}/{a['pitch_rms_deg']:.3f} against "
            f"{filter_word(ref)} "
            f"{b['roll_rms_deg']:.3f}/{b['pitch_rms_deg']:.3f} deg"
        )

    parts = [f"roll/pitch RMS over the flight {pair('flight')}"]
    if math.isfinite(float(res.window(filt, "after_bank")["t_start_s"])):
        parts.append(f"in the window after the first bank {pair('after_bank')}")
    sweep = res.sweep
    if sweep is not None and {filt, ref} <= set(sweep["filter"]):
        mine = sweep[sweep["filter"] == filt].set_index(["parameter", "value"])
        theirs = sweep[sweep["filter"] == ref].set_index(["parameter", "value"])
        points = mine.index.intersection(theirs.index)
        counts = []
        for w in WINDOWS:
            for a in ANGLES:
                col = _sweep_column(f"{a}_rms_deg", w)
                if col not in sweep:
                    continue
                wins = int((mine.loc[points, col] < theirs.loc[points, col]).sum())
                counts.append(f"{wins} for {a} ({_SHORT[w]})")
        parts.append(
            f"the {filter_word(filt)} has the lower RMS at "
            + ", ".join(counts)
            + f" of the {len(points)} (parameter, value) points of the sweep"
        )
    if "ukf" in (filt, ref) and tuning_spans(res):
        parts.append(tuning_spans(res))
    text = (
        "The paper gives no setting of its UKF (scaling, noise handling, integration) and not "
        "its trajectory, and with ours the ranking does not hold: " + "; ".join(parts) + "."
    )
    return Cause("unpublished", "UKF settings and trajectory are not given", text)


def level_flight_cause(res, checks: Sequence[NeesCheck]) -> Cause | None:
    """Under-confident roll mostly in wings-level flight (None if not mostly there).

    ``checks``: every under-confident roll check of the published claims, so the rows they
    explain share one text.
    """
    key = ("level", tuple(c.filter for c in checks))
    return _cached(res, key, lambda: _level_flight_cause(res, checks))


def _level_flight_cause(res, checks: Sequence[NeesCheck]) -> Cause | None:
    if not checks or not all(c.below_level >= 0.5 for c in checks):
        return None
    lo, hi = checks[0].band
    shares = ", ".join(
        f"{filter_word(c.filter)} {c.below_level:.0%} of {round(c.below * c.n_times)}"
        for c in checks
    )
    after = ", ".join(f"{filter_word(c.filter)} {c.after_bank_mean:.2f}" for c in checks)
    inside = all(lo <= c.after_bank_mean <= hi for c in checks)
    return Cause(
        "model",
        "roll is barely observable in our wings-level flight",
        f"The roll sigma is too large (under-confident) mostly in our wings-level flight, "
        f"where roll reaches the altimeter only to second order (through c3 = cos(roll) "
        f"cos(pitch)): of the times after the transient with the roll NEES below the band "
        f"[{lo:.2f}, {hi:.2f}], {shares} have a true "
        f"|roll| below {res.bank_deg:g} deg, and the roll NEES of the window after the "
        f"first bank is {after}, {'inside' if inside else 'not all inside'} the band.",
    )


def bias_cause(res, check: NeesCheck) -> Cause | None:
    """Over-confident where the error is mostly the filter's own bias (its noise-free RMS is
    at least half its Monte Carlo RMS); None otherwise."""
    key = ("bias", check.filter, check.angle)
    return _cached(res, key, lambda: _bias_cause(res, check))


def _bias_cause(res, check: NeesCheck) -> Cause | None:
    q = f"{check.angle}_rms_deg"
    if check.filter not in res.noise_free.index:
        return None
    nf = float(res.noise_free.loc[check.filter, q])
    mc = float(res.summary.loc[check.filter, q])
    if not (mc > 0 and nf >= 0.5 * mc):
        return None
    lo, hi = check.band
    text = (
        f"The {filter_word(check.filter)}'s {check.angle} error is mostly a deterministic bias of its own "
        f"prediction, which its sigma does not contain: on one noise-free run with an exact "
        f"start its {check.angle} RMS is {nf:.3f} deg, {nf / mc:.0%} of its Monte Carlo "
        f"{mc:.3f} deg, and its {check.angle} NEES is above the band [{lo:.2f}, {hi:.2f}] at "
        f"{check.above:.0%} of the times after the transient (up to {check.peak:.2f} at "
        f"{check.peak_t:g} s)"
    )
    title = "the filter's error is mostly a bias outside its sigma"
    if check.filter == "ukf":
        not_tuning, clause = tuning_clause(res, check.angle)
        text += clause
        if not_tuning:
            title = "the UKF's own prediction bias, not its sigma-point tuning"
    if "ekf" in res.noise_free.index and check.filter == "ukf":
        ekf = float(res.noise_free.loc["ekf", q])
        where = (
            "so the bias is in the unscented prediction's mean itself (the second-order term "
            "that any symmetric sigma-point set carries), not in the model"
            if ekf < 0.5 * nf
            else "so the model carries the bias too"
        )
        text += (
            f"; the EKF on the same Euler-angle model, integration and noise-free data has "
            f"{ekf:.3f} deg, {where}"
        )
    return Cause("model", title, text + ".")


def _tuned(res):
    """The settings of the UKF tuning grid that ran (None without at least two)."""
    tuning = getattr(res, "tuning", None)
    if tuning is None:
        return None
    ran = tuning[tuning["status"] == "ok"]
    return ran if len(ran) >= 2 else None


def tuning_clause(res, angle: str) -> tuple[bool, str]:
    """What the UKF tuning grid (ukf_tuning.csv) shows about the UKF's ``angle`` bias: whether
    every setting keeps the noise-free RMS at least half the Monte Carlo one (the rule of
    :func:`bias_cause`; then the bias is not the tuning), and the spans; (False, '') without
    the grid."""
    ran = _tuned(res)
    if ran is None:
        return False, ""
    nf = ran[f"noise_free_{angle}_rms_deg"]
    mc = ran[f"{angle}_rms_deg"]
    w0 = ran["wm0"]
    alphas = ", ".join(f"{a:g}" for a in dict.fromkeys(ran["alpha"]))
    kappas = ", ".join(f"{k:g}" for k in dict.fromkeys(ran["kappa"]))
    kept = int((nf >= 0.5 * mc).sum())
    lead = (
        f"it is not the sigma-point tuning: all {len(ran)} settings"
        if kept == len(ran)
        else f"the sigma-point tuning matters: {kept} of {len(ran)} settings"
    )
    return kept == len(ran), (
        f"; {lead} of the grid (alpha {alphas}; kappa {kappas}; centre weight W0 from "
        f"{w0.min():.3g} to {w0.max():.3g}) keep the noise-free {angle} RMS at least half the "
        f"Monte Carlo one; the noise-free RMS spans [{nf.min():.3f}, {nf.max():.3f}] deg and "
        f"the Monte Carlo one [{mc.min():.3f}, {mc.max():.3f}] deg ({TUNING_GRID})"
    )


def tuning_spans(res) -> str:
    """The UKF's Monte Carlo roll/pitch RMS spans over the tuning grid; '' without it."""
    ran = _tuned(res)
    if ran is None:
        return ""
    r, p = ran["roll_rms_deg"], ran["pitch_rms_deg"]
    return (
        f"over the {len(ran)} sigma-point settings of {TUNING_GRID} the UKF's roll/pitch RMS "
        f"over the flight spans [{r.min():.3f}, {r.max():.3f}]/[{p.min():.3f}, {p.max():.3f}] deg"
    )


def ekf_cause(res, filt: str, ref: str, tail: dict[str, tuple[float, float]]) -> Cause:
    """An EKF that does not diverge; ``tail``: angle -> (its, the reference's) last-tenth RMS."""
    return _cached(res, ("ekf", filt, ref), lambda: _ekf_cause(filt, ref, tail))


def _ekf_cause(filt: str, ref: str, tail: dict[str, tuple[float, float]]) -> Cause:
    ratios = [a / b for a, b in tail.values() if b > 0]
    shown = "; ".join(f"{a} {x:.3f} against {y:.3f} deg" for a, (x, y) in tail.items())
    return Cause(
        "unpublished",
        "the EKF's settings are not given",
        f"The paper gives no setting of its EKF (discretisation, noise model, initial errors); "
        f"ours ({filter_word(filt)}: the UKF's Euler-angle model linearised at the estimate) "
        f"ends the flight at {span(ratios)} times the {filter_word(ref)}'s RMS over the last "
        f"tenth ({shown}), so a divergence "
        "cannot be reproduced from what the paper publishes.",
    )
