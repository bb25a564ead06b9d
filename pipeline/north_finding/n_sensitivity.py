"""How much the verdicts rest on how the N inference weighs the statistical rows.

The N inference (:mod:`pipeline.north_finding.n_inference`) down-weights correlated rows (row
i's log-likelihood times ``row_weight`` = 1 / sum_j r_ij^2) and lets rows whose failure has a
known cause (:func:`pipeline.north_finding.causes.for_item`) weigh on N like any other. This
module reweights the rows' log-likelihoods and judges every verdict again:

* ``as judged``: the verdicts of ``verdicts.csv``;
* ``rows as independent``: every used row weighs 1 (the rows multiplied as if independent);
* ``explained rows excluded``: as judged, but the rows that are not reproduced and have a
  known cause weigh 0 (still judged, on the weights of the others).

For each, the N of the largest profile likelihood, the posterior weight there, the effective
number of rows (the sum of the used rows' weights) and the verdict rows that change
(``n_sensitivity.csv``, columns :data:`~pipeline.north_finding.columns.N_SENSITIVITY_COLUMNS`),
written by the verdicts step beside ``verdicts.csv``.

>>> rows = pd.DataFrame({"id": ["a", "a", "b", "b"], "n_avg": [10, 100] * 2,
...     "log_lik": [-1.0, -2.0, -0.5, -0.25], "row_weight": [1.0, 1.0, 0.5, 0.5],
...     "used": True, "weight": 0.0})
>>> out = reweighted(rows, {"b": 2.0})
>>> out["log_lik"].tolist(), out["row_weight"].tolist()
([-1.0, -2.0, -1.0, -0.5], [1.0, 1.0, 1.0, 1.0])
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import N_SENSITIVITY_COLUMNS
from pipeline.north_finding.n_inference import loo_weights
from pipeline.north_finding.ranking import posterior_weights

__all__ = ["VARIANTS", "reweighted", "sensitivity"]

#: the variants, in the order they are written
VARIANTS = ("as judged", "rows as independent", "explained rows excluded")


def reweighted(n_rows: pd.DataFrame, factor: Mapping[str, float]) -> pd.DataFrame:
    """``n_rows`` with each row's log-likelihood and ``row_weight`` times ``factor`` (default 1;
    0: not used), and the leave-one-out weights recomputed."""
    ids = list(dict.fromkeys(n_rows["id"]))
    grid = sorted({int(n) for n in n_rows["n_avg"]})
    table = n_rows.set_index(["id", "n_avg"])
    scale = np.array([float(factor.get(i, 1.0)) for i in ids])
    log_lik = np.array([[table.loc[(i, n), "log_lik"] for n in grid] for i in ids], dtype=float)
    used = np.array([bool(table.loc[(i, grid[0]), "used"]) for i in ids]) & (scale > 0)
    scaled = log_lik * scale[:, None]
    weights = loo_weights(scaled, used)
    out = n_rows.copy()
    pos = {(i, n): (a, b) for a, i in enumerate(ids) for b, n in enumerate(grid)}
    where = [pos[i, int(n)] for i, n in zip(out["id"], out["n_avg"], strict=True)]
    out["log_lik"] = [scaled[a, b] for a, b in where]
    out["row_weight"] = [
        float(w) * scale[a] for w, (a, _) in zip(out["row_weight"], where, strict=True)
    ]
    out["used"] = [bool(used[a]) for a, _ in where]
    out["weight"] = [weights[a, b] for a, b in where]
    return out


def _verdicts(
    judge: Callable[[Mapping[str, Any]], pd.DataFrame],
    results: Mapping[str, Any],
    n_rows: pd.DataFrame,
) -> dict[str, str]:
    fresh = {k: v for k, v in results.items() if not k.startswith("_")} | {"n_rows": n_rows}
    table = judge(fresh)
    return dict(zip(table["id"], table["verdict"], strict=True))


def sensitivity(
    results: Mapping[str, Any],
    judge: Callable[[Mapping[str, Any]], pd.DataFrame],
    explained: Callable[[Mapping[str, Any]], bool],
    judged: pd.DataFrame | None = None,
) -> pd.DataFrame:
    """The variants' inferred N and changed verdicts: ``judge(results)`` gives the verdict
    table, ``explained(item)`` whether a statistical item has a known cause (a row counts as
    explained when it is also not reproduced as judged); ``judged``: the table
    ``judge(results)`` gives, when the caller has it already (it is not judged again)."""
    n_rows = results["n_rows"]
    items = [
        i for i in (results.get("published") or {}).get("items", []) if i["kind"] == "statistical"
    ]
    first = n_rows.drop_duplicates("id").set_index("id")
    base = (
        _verdicts(judge, results, n_rows)
        if judged is None
        else dict(zip(judged["id"], judged["verdict"], strict=True))
    )
    gone = {i["id"]: 0.0 for i in items if base[i["id"]] == "not_reproduced" and explained(i)}
    variants = {
        "as judged": {},
        "rows as independent": {i: 1.0 / float(w) for i, w in first["row_weight"].items()},
        "explained rows excluded": gone,
    }
    rows = []
    for name, factor in variants.items():
        frame = reweighted(n_rows, factor)
        verdicts = base if not factor else _verdicts(judge, results, frame)
        changed = [f"{i}: {base[i]} -> {v}" for i, v in verdicts.items() if base.get(i) != v]
        post = posterior_weights(frame)
        best = max(post.items(), key=lambda kv: (kv[1], -kv[0]))
        kept = frame.drop_duplicates("id")
        eff = float(kept.loc[kept["used"].astype(bool), "row_weight"].sum())
        rows.append((name, best[0], best[1], eff, len(changed), "; ".join(changed)))
    return pd.DataFrame(rows, columns=N_SENSITIVITY_COLUMNS)
