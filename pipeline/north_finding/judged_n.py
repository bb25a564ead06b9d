"""Verdict side of the N inference: the mixture over N each statistical row is judged on.

Reads ``n_rows.csv`` and ``mc_trials_judged.csv`` (written by
:mod:`pipeline.north_finding.run_inference`; columns in :mod:`pipeline.north_finding.columns`)
from the results: :func:`judged_at` gives a row's leave-one-out posterior predictive sample
(our Monte Carlo trials at every grid N with weight, each trial at N weighted w_N / n_trials,
so the engine's weighted rank is sum_N w_N rank_N) and the notes that say where the weight
lies and where on the grid the row is consistent; :func:`mixed_n` is the root cause of the
rows that fail in that mixture although some grid N would make them noise.

>>> rows = pd.DataFrame({"id": ["a"] * 3 + ["b"] * 3, "n_avg": [10, 100, 1000] * 2,
...     "log_lik": [-5.0, -1.0, -2.0, -1.0, -3.0, -4.0], "used": True})
>>> loo_profile(rows, "a").tolist(), loo_profile(rows, "b").tolist()
([-1.0, -3.0, -4.0], [-5.0, -1.0, -2.0])
"""

from __future__ import annotations

from collections.abc import Mapping, MutableMapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.n_inference import (
    consistent_range,
    fmt_grid,
    mixture_rank,
    posterior_range,
)
from pipeline.north_finding.trials_file import by_key
from pipeline.verdicts.cause import Cause
from pipeline.verdicts.kinds import RANK_BAND

__all__ = ["JudgedAt", "judged_at", "loo_profile", "mixed_n", "mixture_rank_of"]


@dataclass(frozen=True)
class JudgedAt:
    """A statistical row's leave-one-out mixture: the trials (``samples``) and their weights,
    the grid N with weight (``weight_by_n``), the mixture's percentile rank, whether it is
    inside the band, where on the grid the row is consistent, and the notes that say so."""

    samples: np.ndarray
    weights: np.ndarray
    weight_by_n: dict[int, float]
    rank: float
    in_band: bool
    consistent: str
    notes: tuple[str, ...]


def loo_profile(n_rows: pd.DataFrame, item_id: str) -> pd.Series:
    """The profile log-likelihood over the grid of the used rows other than ``item_id``."""
    used = n_rows[n_rows["used"].astype(bool) & (n_rows["id"] != item_id)]
    grid = sorted(set(n_rows["n_avg"].astype(int)))
    return used.groupby("n_avg")["log_lik"].sum().reindex(grid, fill_value=0.0)


def _row(results: Mapping[str, Any], item_id: str) -> pd.DataFrame | None:
    n_rows = results.get("n_rows")
    if n_rows is None or n_rows.empty:
        return None
    rows = n_rows[n_rows["id"] == item_id].sort_values("n_avg")
    if rows.empty:
        raise ValueError(
            f"n_rows.csv: no rows for the statistical item {item_id!r}; the N inference is stale "
            "(rerun the infer_n step with the current published values)"
        )
    return rows


def mixture_rank_of(rows: pd.DataFrame) -> float:
    """sum_N w_N rank_N over one row's grid rows of ``n_rows``."""
    w = rows["weight"].to_numpy(dtype=float)
    return float(mixture_rank(w, rows["rank_pct"].to_numpy(dtype=float)))


def judged_at(results: Mapping[str, Any], item: Mapping[str, Any]) -> JudgedAt | None:
    """Where a statistical item is judged (None: the results hold no N inference)."""
    rows = _row(results, item["id"])
    if rows is None:
        return None
    n_rows, mc = results["n_rows"], results["mc_trials_judged"]
    method, quantity = item["select"]["method"], item["quantity"]
    weight_by_n = {
        int(n): float(w) for n, w in zip(rows["n_avg"], rows["weight"], strict=True) if w > 0
    }
    samples, weights, dropped, total_trials = [], [], 0, 0
    groups = _trials_by_key(results, mc)
    for n, w in weight_by_n.items():
        s = groups.get((n, method, quantity))
        if s is None:
            raise ValueError(
                f"mc_trials_judged.csv: no trials at n_avg = {n} for method {method}, quantity "
                f"{quantity} (row {item['id']}); allowed: the N inference's own output"
            )
        total_trials += s.size
        dropped += int((~np.isfinite(s)).sum())
        s = s[np.isfinite(s)]
        samples.append(s)
        weights.append(np.full(s.size, w / s.size))
    grid, band = rows["n_avg"].astype(int).tolist(), rows["in_band"].astype(bool).tolist()
    consistent = consistent_range(grid, band)
    rank = mixture_rank_of(rows)
    lo, hi = RANK_BAND
    here = lo <= rank <= hi
    used = bool(rows["used"].iloc[0])
    others = int(n_rows.loc[n_rows["used"].astype(bool), "id"].nunique()) - int(used)
    total = n_rows[n_rows["used"].astype(bool)].groupby("n_avg")["log_lik"].sum()
    n_all = int(total.idxmax()) if not total.empty else grid[0]
    ranks = rows.set_index("n_avg")["rank_pct"]
    heavy = sorted(weight_by_n.items(), key=lambda kv: (-kv[1], kv[0]))[:3]
    notes = [
        "judged on the mixture of our Monte Carlo trials over the grid N, each N weighted by "
        f"the likelihood of the other {others} rows (flat prior over log10 N): "
        f"{posterior_range(grid, rows['weight'].tolist())}; all rows: maximum at "
        f"N = {fmt_grid(n_all)} (n_profile.csv)",
        f"mixture percentile rank sum_N w_N rank_N = {rank:.1f}; at the heaviest N: "
        + ", ".join(f"N = {fmt_grid(n)} (w {w:.2f}) rank {ranks[n]:.1f}" for n, w in heavy),
        consistent,
    ]
    if not used:
        notes.append("excluded from the N inference: outside the rank band at every grid N")
    if dropped:  # counted as numerical trouble of the N inference too
        notes.append(
            f"{dropped} of {total_trials} trials non-finite (numerical trouble), left out of "
            "the mixture"
        )
    return JudgedAt(
        np.concatenate(samples),
        np.concatenate(weights),
        weight_by_n,
        rank,
        here,
        consistent,
        tuple(notes),
    )


def _trials_by_key(
    results: Mapping[str, Any], mc: pd.DataFrame
) -> dict[tuple[int, str, str], np.ndarray]:
    """(n_avg, method, quantity) -> the estimates in trial order, computed once per results."""
    if isinstance(results, MutableMapping) and "_trials_by_key" in results:
        return results["_trials_by_key"]
    out = {
        (int(n), str(m), str(q)): v
        for (n, m, q), v in by_key(mc, ["n_avg", "method", "quantity"], "estimate").items()
    }
    if isinstance(results, MutableMapping):
        results["_trials_by_key"] = out
    return out


def mixed_n(results: Mapping[str, Any], item: Mapping[str, Any]) -> Cause | None:
    """The cause of a statistical row that fails in its leave-one-out mixture but is noise at
    some grid N (None for other rows): one Cause for every such row (the summary counts it once)."""
    cause, ids = _memo(results)
    return cause if item["id"] in ids else None


def _memo(results: Mapping[str, Any]) -> tuple[Cause | None, frozenset[str]]:
    if isinstance(results, MutableMapping) and "_mixed_n" in results:
        return results["_mixed_n"]
    out = _mixed(results)
    if isinstance(results, MutableMapping):
        results["_mixed_n"] = out
    return out


def _mixed(results: Mapping[str, Any]) -> tuple[Cause | None, frozenset[str]]:
    from pipeline.north_finding.causes import for_item

    n_rows = results.get("n_rows")
    published = results.get("published") or {}
    if n_rows is None or n_rows.empty:
        return None, frozenset()
    parts, ids = [], []
    for item in published.get("items", []):
        if item["kind"] != "statistical" or for_item(item, results) is not None:
            continue
        rows = _row(results, item["id"])
        rank = mixture_rank_of(rows)
        band = rows.set_index("n_avg")["in_band"].astype(bool)
        if RANK_BAND[0] <= rank <= RANK_BAND[1] or not band.any():
            continue
        ids.append(item["id"])
        parts.append(
            f"{item['label']}, {_method_name(published, item['select']['method'])} is "
            f"{consistent_range(band.index.tolist(), band.tolist())}"
            f" but the other rows put "
            f"{posterior_range(rows['n_avg'].tolist(), rows['weight'].tolist())}"
            f" (mixture rank {rank:.1f})"
        )
    if not ids:
        return None, frozenset()
    lo, hi = RANK_BAND
    text = (
        "The paper gives no averaging count N. With our Monte Carlo weighted over N by how well "
        f"the other statistical rows fit each N, these rows fall outside the {lo:g}-{hi:g} % "
        "rank band: " + "; ".join(parts) + ". " + _small_n_clause(n_rows) + "So the tables' "
        "rows do not all fit one run of our model at one N that the rows themselves support "
        "(they may come from runs at different N, or from errors the paper does not describe)"
    )
    cause = Cause(
        "unpublished", "the averaging count the other rows imply does not fit these", text
    )
    return cause, frozenset(ids)


def _method_name(published: Mapping[str, Any], method: str) -> str:
    """The paper's name of ``method`` (published ``names:``), e.g. 'levelling method 5'."""
    return str((published.get("names") or {}).get(method, f"method {method}"))


def _small_n_clause(n_rows: pd.DataFrame) -> str:
    """Where every row lies in the rank band (small N, where the spread is wide) and how much
    less likely the rows are there than at the maximum: the test is not that no N passes."""
    in_band = n_rows.groupby("n_avg")["in_band"].apply(lambda s: bool(s.astype(bool).all()))
    every = [int(n) for n, ok in in_band.items() if ok]
    if not every:
        return ""
    total = n_rows.groupby("n_avg")["log_lik"].sum()
    gap = float(total.max() - total.loc[every].max())
    return (
        f"(At N = {fmt_grid(every[0])} to {fmt_grid(every[-1])} every row lies inside the band, "
        "but there the spread is so wide that the printed values sit much closer to our "
        f"noise-free values than it allows: the rows are {gap:.0f} nats less likely there than "
        "at the N they imply.) "
    )
