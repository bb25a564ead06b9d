"""The north_finding page's detail sections: per-scenario results (estimates, Monte Carlo
summary, error budget, sensitivity), assumptions (scenario decisions) and provenance
(provenance.json, Snakemake benchmarks). Optional inputs absent are "not available"."""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

from pipeline.north_finding.columns import (
    ERROR_BUDGET_COLUMNS,
    ERROR_SOURCES,
    ESTIMATE_COLUMNS,
    MC_SUMMARY_COLUMNS,
    METHODS,
    QUANTITIES,
    SENSITIVITY_COLUMNS,
    SENSORS,
)
from pipeline.north_finding.readings_checks import flag_notes
from pipeline.north_finding.report_trouble import trouble_blocks
from pipeline.north_finding.scan_bound import warnings as scan_warnings
from pipeline.north_finding.trials_file import existing, read_trials
from pipeline.report.html import format_value, slugify
from pipeline.report.model import Block, Paragraph, Section, frame_table, not_available
from pipeline.report.plain import plain_value

__all__ = [
    "TIMINGS_NOTE",
    "assumptions_section",
    "discover_scenarios",
    "load_decisions",
    "provenance_section",
    "read_csv",
    "render_value",
    "resolve_dotted",
    "scenario_section",
]

_NON_SCENARIO_DIRS = {"figures", "benchmarks", "logs", "log"}
_SCENARIO_FILES = (
    "estimates.csv",
    "mc_summary.csv",
    "mc_trials.csv",
    "mc_trials.npy",
    "error_budget.csv",
    "provenance.json",
)


def read_csv(path: Path, columns: Sequence[str], *, as_text: bool = False) -> pd.DataFrame | None:
    """CSV with the required ``columns``; ``None`` if the file is absent.
    ``as_text`` keeps every cell as printed (strings, empty cells as "")."""
    if not path.is_file():
        return None
    df = pd.read_csv(path, dtype=str, keep_default_na=False) if as_text else pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df


def _order_key(values: pd.Series, order: Sequence[str]) -> pd.Series:
    """Sort key: position in ``order``, unknown values after it."""
    pos = {v: i for i, v in enumerate(order)}
    return values.astype(str).map(lambda v: pos.get(v, len(order)))


def _sorted(df: pd.DataFrame) -> pd.DataFrame:
    keys: list[str] = []
    tmp = df.copy()
    if "method" in tmp.columns:
        tmp["_m"] = _order_key(tmp["method"], METHODS)
        keys += ["_m", "method"]
    if "quantity" in tmp.columns:
        tmp["_q"] = _order_key(tmp["quantity"], QUANTITIES)
        keys += ["_q", "quantity"]
    if not keys:
        return df
    return tmp.sort_values(keys, kind="stable").drop(
        columns=[k for k in ("_m", "_q") if k in tmp.columns]
    )


# --------------------------------------------------------------------------- scenario configs


def resolve_dotted(data: Any, field: str, *, source: str | Path = "<config>") -> Any:
    """Value at a dotted path (``"noise.n_avg"``, list items by index:
    ``"misalignment.rows.0"``). Raises ``ValueError`` naming ``source`` and
    ``field`` if any part is missing.

    >>> resolve_dotted({"a": {"b": [10, {"c": 3}]}}, "a.b.1.c")
    3
    """
    node = data
    done: list[str] = []
    for part in str(field).split("."):
        if isinstance(node, Mapping) and part in node:
            node = node[part]
        elif (
            isinstance(node, list)
            and re.fullmatch(r"-?\d+", part)
            and -len(node) <= int(part) < len(node)
        ):
            node = node[int(part)]
        else:
            where = ".".join(done) or "<top level>"
            raise ValueError(
                f"{source}: decision field '{field}' not found ('{part}' is missing under {where})"
            )
        done.append(part)
    return node


def render_value(value: Any) -> str:
    """A config value as plain text (:func:`pipeline.report.plain.plain_value`: ``5.0`` stays
    ``5.0``, ``True`` -> ``yes``, mappings as ``key = value`` pairs, no JSON)."""
    return plain_value(value)


def load_decisions(path: str | Path) -> tuple[str, pd.DataFrame]:
    """``(description, decisions)`` of one scenario YAML; decisions has columns
    ``field, value, why`` with the value resolved at the dotted ``field``."""
    path = Path(path)
    with path.open(encoding="utf-8") as fh:
        data = yaml.load(fh, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)) or {}
    if not isinstance(data, Mapping):
        raise ValueError(f"{path}: a scenario config must be a mapping")
    description = str(data.get("description") or "").strip()
    raw = data.get("decisions") or []
    if not isinstance(raw, list):
        raise ValueError(f"{path}: 'decisions' must be a list of {{field, text}}")
    rows = []
    for i, d in enumerate(raw):
        if not isinstance(d, Mapping) or "field" not in d or "text" not in d:
            raise ValueError(f"{path}: decisions[{i}] needs 'field' and 'text' (got {d!r})")
        value = resolve_dotted(data, str(d["field"]), source=path)
        rows.append(
            {"field": str(d["field"]), "value": render_value(value), "why": str(d["text"]).strip()}
        )
    return description, pd.DataFrame(rows, columns=["field", "value", "why"])


def discover_scenarios(results_dir: str | Path) -> list[Path]:
    """Scenario result directories under ``results_dir`` (those holding any
    scenario result file); ``paper`` first, then alphabetical."""
    results_dir = Path(results_dir)
    if not results_dir.is_dir():
        return []
    dirs = [
        d
        for d in results_dir.iterdir()
        if d.is_dir()
        and d.name not in _NON_SCENARIO_DIRS
        and any((d / f).is_file() for f in _SCENARIO_FILES)
    ]
    return sorted(dirs, key=lambda d: (d.name != "paper", d.name))


def assumptions_section(
    scenarios_dir: Path, shown: Callable[[Path], str] = Path.as_posix
) -> Section:
    """The scenario decisions of every scenario config (``paper`` first); ``shown``: how a
    path is written on the page."""
    files = (
        sorted(scenarios_dir.glob("*.yaml"), key=lambda f: (f.stem != "paper", f.stem))
        if scenarios_dir.is_dir()
        else []
    )
    if not files:
        return Section(
            "assumptions",
            "Assumptions",
            [not_available(f"Scenario configs in {shown(scenarios_dir)}")],
        )
    subs = []
    for f in files:
        description, decisions = load_decisions(f)
        subs.append(
            Section(
                f"assumptions-{slugify(f.stem)}",
                f"Scenario {f.stem} ({shown(f)})",
                [
                    Paragraph(description or "(no description)"),
                    frame_table(decisions, empty_text="no decisions listed"),
                ],
            )
        )
    intro = Paragraph(
        "Where the paper is silent, each scenario config decides; the value shown is read "
        "from the config at the named field."
    )
    return Section("assumptions", "Assumptions", [intro], subs)


# --------------------------------------------------------------------------- scenario results


def _estimates_pivot(est: pd.DataFrame, sensor: str) -> pd.DataFrame:
    sel = est[est["sensor"].astype(str) == sensor]
    if sel.empty:
        return pd.DataFrame()
    cell = sel["estimate"].map(lambda x: format_value(x, 10)) + sel["error_pct"].map(
        lambda e: "" if pd.isna(e) else f" ({float(e):+.3g} %)"
    )
    sel = sel.assign(cell=cell)
    wide = sel.pivot_table(index="method", columns="quantity", values="cell", aggfunc="first")
    truth = (
        sel.drop_duplicates("quantity")
        .set_index("quantity")["truth"]
        .map(lambda x: format_value(x, 10))
    )
    wide = pd.concat([truth.to_frame().T.rename(index={"truth": "truth"}), wide])
    wide.index = ["truth", *wide.index[1:]]
    rows = ["truth"] + sorted(
        wide.index[1:], key=lambda m: (METHODS.index(m) if m in METHODS else len(METHODS), m)
    )
    cols = sorted(
        wide.columns, key=lambda q: (QUANTITIES.index(q) if q in QUANTITIES else len(QUANTITIES), q)
    )
    out = wide.loc[rows, cols].fillna("")
    out.index.name = "method"
    return out.reset_index()


def scenario_section(d: Path) -> Section:
    """One scenario's results (``results/north_finding/<scenario>/``)."""
    sid = f"scenario-{slugify(d.name)}"
    est = read_csv(d / "estimates.csv", ESTIMATE_COLUMNS)
    estimates: list[Block] = []
    if est is None:
        estimates.append(not_available("estimates.csv"))
    else:
        estimates.append(
            Paragraph("Cells: estimate (signed percent error, 100·(estimate − truth)/|truth|).")
        )
        estimates += [
            frame_table(_estimates_pivot(est, sensor), caption=f"{sensor} sensor")
            for sensor in SENSORS
        ]
        estimates += [Paragraph(f"Note: {note}.") for note in scan_warnings(est)]
        estimates += [Paragraph(f"Note: {note}.") for note in flag_notes(est)]
    mcs = read_csv(d / "mc_summary.csv", MC_SUMMARY_COLUMNS)
    mc: list[Block] = [
        not_available("mc_summary.csv")
        if mcs is None
        else frame_table(_sorted(mcs)[MC_SUMMARY_COLUMNS])
    ]
    trials = read_trials(d, "mc_trials")
    mc.append(
        not_available("mc_trials.csv")
        if trials is None
        else Paragraph(
            f"{existing(d, 'mc_trials')[0].name}: {trials['trial'].nunique()} trials, "
            f"{len(trials)} rows."
        )
    )
    eb = read_csv(d / "error_budget.csv", ERROR_BUDGET_COLUMNS)
    if eb is None:
        budget: list[Block] = [not_available("error_budget.csv")]
    else:
        wide = eb.pivot_table(
            index=["method", "quantity"], columns="source", values="error_pct", aggfunc="first"
        )
        cols = [s for s in ERROR_SOURCES if s in wide.columns] + sorted(
            set(wide.columns) - set(ERROR_SOURCES)
        )
        wide = _sorted(wide[cols].reset_index())
        wide.columns.name = None
        budget = [
            Paragraph(
                "Signed percent error of the noise-free real run with one error source switched "
                "on at a time; noise: the Monte Carlo standard deviation."
            ),
            frame_table(wide, sig=4),
        ]
    sens = read_csv(d / "sensitivity.csv", SENSITIVITY_COLUMNS)
    sensitivity = [
        not_available("sensitivity.csv")
        if sens is None
        else Paragraph(
            f"sensitivity.csv: {len(sens)} rows, n_avg from {format_value(sens['n_avg'].min())} "
            f"to {format_value(sens['n_avg'].max())}, "
            f"methods {', '.join(sorted(map(str, sens['method'].unique())))}; see Fig. 6."
        )
    ]
    return Section(
        sid,
        f"Scenario {d.name}",
        [],
        [
            Section(f"{sid}-estimates", "Estimates (noise-free runs)", estimates),
            Section(f"{sid}-mc", "Monte Carlo summary", mc),
            Section(
                f"{sid}-trouble", "Numerical trouble", trouble_blocks(d / "numerical_trouble.csv")
            ),
            Section(f"{sid}-budget", "Error budget (percent error per error source)", budget),
            Section(f"{sid}-sensitivity", "Sensitivity to averaging", sensitivity),
        ],
    )


# --------------------------------------------------------------------------- provenance


def _provenance_blocks(prov: Mapping[str, Any]) -> list[Block]:
    flat = pd.DataFrame(
        [(k, v) for k, v in prov.items() if k != "packages"], columns=["field", "value"]
    )
    blocks: list[Block] = [frame_table(flat, formatters={"value": render_value})]
    pkgs = prov.get("packages")
    if isinstance(pkgs, Mapping) and pkgs:
        df = pd.DataFrame(sorted(pkgs.items()), columns=["package", "version"])
        blocks.append(frame_table(df, caption="packages"))
    return blocks


#: Where the wall times are: not on the page, which is byte-identical across runs (DESIGN.md
#: invariant 4), while Snakemake's benchmark files hold this run's timings.
TIMINGS_NOTE = (
    "The wall time and memory of every job of this paper are in Snakemake's benchmark files "
    "results/north_finding/benchmarks/*.tsv; they are not copied here, so that this page is "
    "byte-identical across runs."
)


def provenance_section(results_dir: Path, scenarios: Sequence[Path]) -> Section:
    subs = []
    top = results_dir / "provenance.json"
    if top.is_file():
        prov = json.loads(top.read_text(encoding="utf-8"))
        subs.append(Section("provenance-top", "Paper-level results", _provenance_blocks(prov)))
    for d in scenarios:
        p = d / "provenance.json"
        inner = (
            _provenance_blocks(json.loads(p.read_text(encoding="utf-8")))
            if p.is_file()
            else [not_available("provenance.json")]
        )
        subs.append(Section(f"provenance-{slugify(d.name)}", f"Scenario {d.name}", inner))
    blocks: list[Block] = []
    if not scenarios and not top.is_file():
        blocks.append(not_available("Provenance"))
    blocks.append(Paragraph(TIMINGS_NOTE))
    return Section("provenance", "Provenance", blocks, subs)
