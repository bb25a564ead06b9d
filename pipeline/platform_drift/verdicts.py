"""Verdicts of the platform-drift paper: published numbers and claims vs the error curves.

Inputs: ``config/published/platform_drift.yaml`` and, per scenario,
``results/platform_drift/<scenario>/errors.csv`` (``t_s,case,scheme,error_m``) and, for the
stationary scenario, ``errors_long.csv`` (24 h). Output: ``results/platform_drift/verdicts.csv``
with the contract columns; the ``method`` column names the curve (scheme) a verdict is about.

Rules
-----
* Items (kind ``exact``): numbers the authors read off their own plots ("about 4.5 km"), so the
  verdict allows ``tolerance_rel`` of the published value. ``error_2h_m``: the strapdown error at
  7200 s. ``crossover_s``: the first time after 300 s at which the strapdown error exceeds the
  proposed scheme's; it is computed against each proposed curve (analytic and simulated), one
  verdict per curve.
* Claims about "the proposed scheme" get one verdict per proposed curve:
  ``close`` (max relative difference to the reference curve over t >= 1800 s <= rel_tol),
  ``bounded`` (24 h run: max |error| over 24 h <= ratio x max over the first 2 h),
  ``growth_exponent`` (slope of log error vs log t over 1800-7200 s within tol of expect),
  ``below`` (proposed < reference for every t >= from_s), ``final_order`` (sign of
  reference - proposed at 7200 s).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.atomic import write_csv
from pipeline.columns import VERDICT_COLUMNS
from pipeline.config import ConfigError, load_schema, load_yaml, validate

__all__ = ["load_published", "verdicts", "run", "crossover", "PROPOSED"]

PROPOSED = ("proposed_analytic", "proposed_simulated")
UNITS = {"km": 1000.0, "m": 1.0, "s": 1.0, "h": 3600.0}
FINAL_S = 7200.0
CROSS_FROM_S = 300.0
FIT_WINDOW_S = (1800.0, 7200.0)
CROSS_MARGIN_M = 1.0


def load_published(path: str | Path) -> dict[str, Any]:
    """Parse and validate the published-values file (ConfigError names file and field)."""
    data = load_yaml(path)
    validate(data, load_schema("published_platform_drift"), path)
    ids = [x["id"] for x in data["items"]] + [c["id"] for c in data["claims"]]
    dup = sorted({i for i in ids if ids.count(i) > 1})
    if dup:
        raise ConfigError(f"{path}: duplicate ids {dup}")
    return data


def _curve(errors: pd.DataFrame, case: str, scheme: str) -> pd.Series:
    rows = errors[(errors["case"] == case) & (errors["scheme"] == scheme)]
    return rows.set_index("t_s")["error_m"].sort_index()


def crossover(strapdown: pd.Series, proposed: pd.Series, from_s: float = CROSS_FROM_S) -> float:
    """First t >= from_s at which strapdown > proposed (linear interpolation); NaN if never."""
    t = strapdown.index.to_numpy(float)
    # a 1 m margin: where the curves coincide (to integration precision) there is no crossover
    d = (
        strapdown.to_numpy(float)
        - proposed.reindex(strapdown.index).to_numpy(float)
        - CROSS_MARGIN_M
    )
    keep = t >= from_s
    t, d = t[keep], d[keep]
    if d.size == 0 or d[0] > 0:
        return float("nan") if d.size == 0 else float(t[0])
    idx = np.flatnonzero(d > 0)
    if idx.size == 0:
        return float("nan")
    k = idx[0]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (-d[k - 1]) / (d[k] - d[k - 1]))


def _item_rows(item: dict[str, Any], errors: pd.DataFrame | None) -> list[dict[str, Any]]:
    scale = UNITS[item["unit"]]
    published = float(item["value"]) * scale
    tol = item["tolerance_rel"]
    base = {
        "id": item["id"],
        "kind": "exact",
        "quantity": item["quantity"],
        "published": item["value"] + " " + item["unit"],
    }
    if errors is None:
        return [
            {
                **base,
                "method": item["scheme"],
                "reproduced": "",
                "verdict": "not_checkable",
                "note": f"no results for scenario {item['scenario']}",
            }
        ]
    strap = _curve(errors, item["case"], "strapdown")
    out = []
    if item["quantity"] == "error_2h_m":
        ours = float(strap.loc[FINAL_S])
        pairs = [("strapdown", ours, "")]
    else:
        pairs = [
            (f"strapdown vs {p}", crossover(strap, _curve(errors, item["case"], p)), p)
            for p in PROPOSED
        ]
    for method, ours, suffix in pairs:
        ok = np.isfinite(ours) and abs(ours - published) <= tol * published
        out.append(
            {
                **base,
                "id": item["id"] + (f"/{suffix}" if suffix else ""),
                "method": method,
                "reproduced": f"{ours / scale:.4g} {item['unit']}"
                if np.isfinite(ours)
                else "never",
                "verdict": "reproduced" if ok else "not_reproduced",
                "note": f"published 'about' value compared with tolerance {tol:.0%}"
                + (f"; {item['note']}" if item.get("note") else ""),
            }
        )
    return out


def _claim_rows(
    claim: dict[str, Any], results: dict[str, dict[str, pd.DataFrame]]
) -> list[dict[str, Any]]:
    pred = claim["predicate"]
    kind = pred["type"]
    base = {"id": claim["id"], "kind": "claim", "quantity": "error_m", "published": claim["text"]}
    res = results.get(pred["scenario"], {})
    table = res.get("errors_long" if kind == "bounded" else "errors")
    if table is None:
        return [
            {
                **base,
                "method": "",
                "reproduced": "",
                "verdict": "not_checkable",
                "note": f"no {'24 h ' if kind == 'bounded' else ''}results for scenario {pred['scenario']}",
            }
        ]
    case = pred["case"]
    rows = []
    schemes = [pred["scheme"]] if "scheme" in pred else list(PROPOSED)
    for scheme in schemes:
        cur = _curve(table, case, scheme)
        if cur.empty:
            rows.append(
                {
                    **base,
                    "id": f"{claim['id']}/{scheme}",
                    "method": scheme,
                    "reproduced": "",
                    "verdict": "not_checkable",
                    "note": f"no {scheme} curve for case {case}",
                }
            )
            continue
        if kind == "close":
            ref = _curve(table, case, pred["reference"]).reindex(cur.index)
            late = cur.index >= FIT_WINDOW_S[0]
            rel = float(np.max(np.abs(cur[late] - ref[late]) / np.maximum(np.abs(ref[late]), 1e-9)))
            ok, what = (
                rel <= pred["rel_tol"],
                f"max relative difference to {pred['reference']} over t >= 1800 s: {rel:.3g}",
            )
        elif kind == "bounded":
            first = float(cur[cur.index <= FINAL_S].abs().max())
            whole = float(cur.abs().max())
            ok = whole <= pred["ratio"] * first
            what = (
                f"max error over the first 2 h {first:.4g} m, over {cur.index.max() / 3600:.0f} h "
                f"{whole:.4g} m (bounded if <= {pred['ratio']}x)"
            )
        elif kind == "growth_exponent":
            win = cur[(cur.index >= FIT_WINDOW_S[0]) & (cur.index <= FIT_WINDOW_S[1])]
            win = win[win > 0]
            slope = float(
                np.polyfit(np.log(win.index.to_numpy(float)), np.log(win.to_numpy(float)), 1)[0]
            )
            ok = abs(slope - float(pred["expect"])) <= pred["tol"]
            what = f"log-log slope over 1800-7200 s: {slope:.3g} (expected {pred['expect']})"
        elif kind == "below":
            ref = _curve(table, case, pred["reference"]).reindex(cur.index)
            sel = cur.index >= pred.get("from_s", 0.0)
            bad = cur.index[sel][(cur[sel] >= ref[sel]).to_numpy()]
            ok = bad.size == 0
            what = "below the reference throughout" if ok else f"not below from t = {bad[0]:.0f} s"
        else:  # final_order
            ref = float(_curve(table, case, pred["reference"]).loc[FINAL_S])
            mine = float(cur.loc[FINAL_S])
            found = "reference_below" if ref < mine else "reference_above"
            ok = found == pred["expect"]
            what = f"at 7200 s: {pred['reference']} {ref:.4g} m, {scheme} {mine:.4g} m ({found})"
        rows.append(
            {
                **base,
                "id": f"{claim['id']}/{scheme}",
                "method": scheme,
                "reproduced": what,
                "verdict": "upheld" if ok else "not_upheld",
                "note": claim["source"],
            }
        )
    return rows


def verdicts(
    published: dict[str, Any], results: dict[str, dict[str, pd.DataFrame]]
) -> pd.DataFrame:
    """Every verdict row (items first, then claims)."""
    rows: list[dict[str, Any]] = []
    for item in published["items"]:
        rows += _item_rows(item, results.get(item["scenario"], {}).get("errors"))
    for claim in published["claims"]:
        rows += _claim_rows(claim, results)
    return pd.DataFrame(rows, columns=VERDICT_COLUMNS)


def read_results(results_dir: str | Path) -> dict[str, dict[str, pd.DataFrame]]:
    """errors.csv (and errors_long.csv) of every scenario directory under ``results_dir``."""
    out: dict[str, dict[str, pd.DataFrame]] = {}
    for d in sorted(Path(results_dir).iterdir()):
        if (d / "errors.csv").is_file():
            out[d.name] = {"errors": pd.read_csv(d / "errors.csv")}
            long = d / "errors_long.csv"
            if long.is_file() and not (frame := pd.read_csv(long)).empty:
                out[d.name]["errors_long"] = frame
    return out


def run(published_path: str | Path, results_dir: str | Path, out_path: str | Path) -> pd.DataFrame:
    table = verdicts(load_published(published_path), read_results(results_dir))
    write_csv(out_path, table, VERDICT_COLUMNS)
    return table


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--published", default="config/published/platform_drift.yaml")
    ap.add_argument("--results-dir", default="results/platform_drift")
    ap.add_argument("--out", default="results/platform_drift/verdicts.csv")
    a = ap.parse_args(argv)
    table = run(a.published, a.results_dir, a.out)
    print(table["verdict"].value_counts().to_dict())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
