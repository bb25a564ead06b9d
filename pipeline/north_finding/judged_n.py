"""Verdict side of the N inference: the N each statistical row is judged at, and why.

Reads ``n_rows.csv`` and ``mc_trials_judged.csv`` (written by
:mod:`pipeline.north_finding.run_inference`; columns in :mod:`pipeline.north_finding.n_inference`)
from the results: :func:`judged_at` gives a row's Monte Carlo trials at its judged N (its
leave-one-out N) and the notes that say where on the grid it is consistent; :func:`mixed_n`
is the root cause of the rows that fail at the N the other rows imply although some grid N
would make them noise.

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

from pipeline.north_finding.n_inference import consistent_range, fmt_grid
from pipeline.verdicts.cause import Cause

__all__ = ["JudgedAt", "judged_at", "loo_profile", "mixed_n"]


@dataclass(frozen=True)
class JudgedAt:
    """A statistical row's judged N, its trials there (``samples``), where it is consistent
    on the grid (``in_band`` per grid N) and the notes that say so."""

    n_avg: int
    samples: np.ndarray
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


def judged_at(results: Mapping[str, Any], item: Mapping[str, Any]) -> JudgedAt | None:
    """Where a statistical item is judged (None: the results hold no N inference)."""
    rows = _row(results, item["id"])
    if rows is None:
        return None
    n_rows, mc = results["n_rows"], results["mc_trials_judged"]
    n = int(rows["judged_n_avg"].iloc[0])
    method, quantity = item["select"]["method"], item["quantity"]
    pick = mc[(mc["n_avg"] == n) & (mc["method"] == method) & (mc["quantity"] == quantity)]
    if pick.empty:
        raise ValueError(
            f"mc_trials_judged.csv: no trials at n_avg = {n} for method {method}, quantity "
            f"{quantity} (row {item['id']}); allowed: the N inference's own output"
        )
    samples = pick.sort_values("trial")["estimate"].to_numpy(dtype=float)
    grid, band = rows["n_avg"].astype(int).tolist(), rows["in_band"].astype(bool).tolist()
    consistent = consistent_range(grid, band)
    used = bool(rows["used"].iloc[0])
    others = int(n_rows.loc[n_rows["used"].astype(bool), "id"].nunique()) - int(used)
    total = n_rows[n_rows["used"].astype(bool)].groupby("n_avg")["log_lik"].sum()
    n_all = int(total.idxmax()) if not total.empty else n
    notes = [
        f"judged at N = {fmt_grid(n)} samples averaged, the N that the other {others} rows "
        f"imply by maximum likelihood (all rows: N = {fmt_grid(n_all)}; n_profile.csv)",
        consistent,
    ]
    if not used:
        notes.append("excluded from the N inference: outside the rank band at every grid N")
    here = band[grid.index(n)]
    ok = [g for g, b in zip(grid, band, strict=True) if b]
    if not here and ok:
        near = min(ok, key=lambda g: (abs(np.log(g) - np.log(n)), g))
        prof = loo_profile(n_rows, item["id"])
        notes.append(
            f"the other rows' log-likelihood is {prof[n] - prof[near]:.1f} nats higher at "
            f"N = {fmt_grid(n)} than at N = {fmt_grid(near)}, the nearest grid N at which this "
            "row is consistent"
        )
    return JudgedAt(n, samples, here, consistent, tuple(notes))


def mixed_n(results: Mapping[str, Any], item: Mapping[str, Any]) -> Cause | None:
    """The cause of a statistical row that fails at its judged N but is noise at some grid N
    (None for other rows): one Cause for every such row (the summary counts it once)."""
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
        n = int(rows["judged_n_avg"].iloc[0])
        band = rows.set_index("n_avg")["in_band"].astype(bool)
        if band[n] or not band.any():
            continue
        ids.append(item["id"])
        parts.append(
            f"{item['id']} ({item['label']}, method {item['select']['method']}) is "
            f"{consistent_range(band.index.tolist(), band.tolist())}"
            f" but the other rows imply N = {fmt_grid(n)}"
        )
    if not ids:
        return None, frozenset()
    text = (
        "The paper gives no averaging count N, and no one N on our grid makes every "
        "statistical row noise around our model: " + "; ".join(parts) + "; at that N each lies "
        "outside the rank band, so the tables' rows cannot all come from one run of our model "
        "at one N (they may come from runs at different N, or from errors the paper does not "
        "describe)"
    )
    cause = Cause("unpublished", "no one averaging count N fits every statistical row", text)
    return cause, frozenset(ids)
