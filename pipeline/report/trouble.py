"""The numerical trouble of one computation as a report page shows it, for every paper: one
sentence saying there was none (naming each kind), else a visible note and a table of every
run, case, method and kind that met some (``numerical_trouble.csv``, :mod:`pipeline.trouble`).

>>> import pandas as pd
>>> df = pd.DataFrame([("mc", "", "L1", "non_finite", 10, 0)], columns=TROUBLE_COLUMNS)
>>> trouble_frame_blocks(df, {"non_finite": "NaN estimate"}, {"mc": "Monte Carlo"})[0].text
'No numerical trouble in Monte Carlo (10 trials): no NaN estimate.'
>>> df.loc[0, "n_affected"] = 3
>>> blocks = trouble_frame_blocks(df, {"non_finite": "NaN estimate"}, {"mc": "Monte Carlo"})
>>> blocks[0].text.startswith("Numerical trouble in Monte Carlo (10 trials)")
True
>>> blocks[1].rows
[['Monte Carlo', 'L1', 'NaN estimate', '3 of 10']]
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from pipeline.report.model import Block, Paragraph, frame_table, not_available
from pipeline.trouble import TROUBLE_COLUMNS

__all__ = ["read_trouble", "trouble_blocks", "trouble_frame_blocks"]


def read_trouble(path: Path) -> pd.DataFrame | None:
    """``path`` (a numerical_trouble.csv) read and checked; None if it is absent."""
    if not path.is_file():
        return None
    df = pd.read_csv(path, keep_default_na=False, dtype={"case": str})
    missing = [c for c in TROUBLE_COLUMNS if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df


def _case(case: object) -> str:
    return str(case).replace("=", " = ")


def _count(n: int, unit: str) -> str:
    """'1 trial', '5 trials' (``unit`` plural)."""
    return f"{n} {unit.removesuffix('s') if n == 1 else unit}"


def _run_words(df: pd.DataFrame, runs: Mapping[str, str], unit: str) -> str:
    """Each run with its cases and sizes, e.g. 'Monte Carlo (1000 trials), sensitivity at
    N = 1, N = 10 (200 trials each)'; more than three cases are counted, not listed."""
    parts = []
    for run, g in df.groupby("run", sort=False):
        name = runs.get(str(run), str(run))
        cases = [c for c in dict.fromkeys(g["case"].astype(str)) if c]
        sizes = sorted(set(g["n_trials"].astype(int)))
        size = _count(sizes[0], unit) if len(sizes) == 1 else f"{sizes[0]}-{sizes[-1]} {unit}"
        if len(cases) > 1:
            size += " each" if len(sizes) == 1 else ""
            if len(cases) > 3 and all(c.startswith("N=") for c in cases):
                where = f" at {len(cases)} N from {cases[0][2:]} to {cases[-1][2:]}"
            elif len(cases) > 3:
                where = f", {len(cases)} cases"
            else:
                where = " at " + ", ".join(_case(c) for c in cases)
            parts.append(f"{name}{where} ({size})")
        else:
            parts.append(f"{name}{' at ' + _case(cases[0]) if cases else ''} ({size})")
    return ", ".join(parts)


def trouble_frame_blocks(
    df: pd.DataFrame,
    words: Mapping[str, str],
    runs: Mapping[str, str],
    *,
    unit: str = "trials",
    after: str = "",
) -> list[Block]:
    """Blocks for the trouble counts ``df``: ``words`` says each kind in words (a noun phrase:
    the note reads 'no <words>; no ...' when there is none), ``runs`` each
    run; ``unit`` names what ``n_trials`` counts; ``after`` (said when there is trouble) what
    the summaries did with the affected trials."""
    if df.empty:
        return [Paragraph("No computation of this kind ran: no numerical trouble to count.")]
    where = _run_words(df, runs, unit)
    hit = df[df["n_affected"] > 0]
    if hit.empty:
        kinds = [words.get(k, k) for k in dict.fromkeys(df["kind"])]
        return [Paragraph(f"No numerical trouble in {where}: no " + "; no ".join(kinds) + ".")]
    table = pd.DataFrame(
        {
            "run": [
                runs.get(str(r), str(r)) + (f" at {_case(c)}" if str(c) else "")
                for r, c in zip(hit["run"], hit["case"], strict=True)
            ],
            "method": hit["method"],
            "trouble": hit["kind"].map(lambda k: words.get(k, k)),
            f"{unit} affected": [
                f"{a} of {n}" for a, n in zip(hit["n_affected"], hit["n_trials"], strict=True)
            ],
        }
    )
    note = (
        f"Numerical trouble in {where}: {int(hit['n_affected'].sum())} counted, in the "
        f"{len(hit)} row{'s' if len(hit) != 1 else ''} below."
    )
    return [
        Paragraph(note + (f" {after}" if after else "")),
        frame_table(table.reset_index(drop=True)),
    ]


def trouble_blocks(
    path: Path,
    words: Mapping[str, str],
    runs: Mapping[str, str],
    *,
    unit: str = "trials",
    after: str = "",
    what: str = "numerical trouble counts",
) -> list[Block]:
    """:func:`trouble_frame_blocks` of the file ``path``; ``what: not available`` if absent."""
    df = read_trouble(path)
    if df is None:
        return [not_available(what)]
    return trouble_frame_blocks(df, words, runs, unit=unit, after=after)
