"""The per-trial Monte Carlo results of north_finding, as CSV or as a binary file, one reader.

``mc_trials`` (the main Monte Carlo, written by :mod:`pipeline.north_finding.run`) and
``mc_trials_judged`` (the trials at every N of the N inference,
:mod:`pipeline.north_finding.run_inference`) hold one value per trial, method and quantity.
Up to :data:`CSV_MAX_TRIALS` trials (the scenarios' size) they are the CSV of the results
contract (``<stem>.csv``, columns in :mod:`pipeline.north_finding.columns`); above it the
CSV would dominate the run (at 1e5 trials mc_trials_judged.csv would be 2.3 GB, formatted
and parsed at ~1 us a cell), so they are ``<stem>.npy``: four arrays saved one after the
other with ``np.save`` (byte-deterministic: no timestamps, unlike ``np.savez``)::

    tag        (1,) bytes: b"north_finding.trials/1"
    columns    (P,) structured: method S8, quantity S24, truth f8 (the CSV's row-block order)
    n_avg      (B,) int64: the N of each block (mc_trials_judged); empty for mc_trials (B = 1)
    estimates  (B, P, T) float64: trial t of column p at block b (trial numbers 0..T-1)

so a trial costs 8 bytes a value instead of ~65 a CSV row. ``error_pct`` is not stored: it is
recomputed with :func:`error_pct`, the function the CSV's column was written with, so both
forms give the same frame bit for bit. The scenario's ``monte_carlo.trials_file`` (``auto``,
``csv`` or ``npy``) overrides the choice. :func:`read_trials` is the one reader: it returns
the CSV's frame from either form and refuses a folder holding both (a stale file).

>>> trials_format(1000), trials_format(1001), trials_format(10**5, "csv")
('csv', 'npy', 'csv')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.atomic import write_atomic, write_csv_parts
from pipeline.north_finding.columns import (
    MC_JUDGED_COLUMNS,
    MC_TRIAL_COLUMNS,
    METHOD_QUANTITIES,
    METHODS,
)

__all__ = [
    "CSV_MAX_TRIALS",
    "FORMATS",
    "Trials",
    "by_key",
    "difference",
    "error_pct",
    "existing",
    "read_trials",
    "trials_format",
    "trials_frame",
    "write_trials",
]

#: the largest trial count whose per-trial results are written as CSV (the scenarios' 1000:
#: their CSV is the results contract); above it, the binary ``.npy`` form
CSV_MAX_TRIALS = 1000
#: file extension of each form
FORMATS = ("csv", "npy")
TAG = b"north_finding.trials/1"
#: the frame's columns per stem
COLUMNS = {"mc_trials": MC_TRIAL_COLUMNS, "mc_trials_judged": MC_JUDGED_COLUMNS}
_COLUMN_DTYPE = np.dtype([("method", "S8"), ("quantity", "S24"), ("truth", "<f8")])

Estimates = Mapping[tuple[str, str], np.ndarray]


def trials_format(n_trials: int, setting: str = "auto") -> str:
    """``csv`` or ``npy``: the scenario's ``monte_carlo.trials_file``, or for ``auto`` CSV up
    to :data:`CSV_MAX_TRIALS` trials."""
    if setting in FORMATS:
        return setting
    if setting != "auto":
        raise ValueError(f"monte_carlo.trials_file: {setting!r}; allowed: auto, csv, npy")
    return "csv" if int(n_trials) <= CSV_MAX_TRIALS else "npy"


def difference(estimate: np.ndarray, truth: float, quantity: str) -> np.ndarray:
    """estimate - truth, wrapped to (-180, 180] deg for the azimuth."""
    diff = np.asarray(estimate, dtype=float) - truth
    if quantity == "psi_deg":
        diff = (diff + 180.0) % 360.0 - 180.0
    return diff


def error_pct(estimate: np.ndarray, truth: float, quantity: str) -> np.ndarray:
    """Signed percent error 100 (estimate - truth) / |truth|; NaN where truth is 0 or unknown."""
    diff = difference(estimate, truth, quantity)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 100.0 * diff / abs(truth) if truth != 0 else np.full_like(diff, np.nan, dtype=float)


def ordered(estimates: Estimates) -> list[tuple[str, str]]:
    """The (method, quantity) of ``estimates`` in the results files' order."""
    return [(m, q) for m in METHODS for q in METHOD_QUANTITIES[m] if (m, q) in estimates]


def trials_frame(estimates: Estimates, truth: Mapping[str, float]) -> pd.DataFrame:
    """Long table of every Monte Carlo trial (vectorised, no loop over trials)."""
    parts = []
    for m, q in ordered(estimates):
        v = estimates[m, q]
        parts.append(
            pd.DataFrame(
                {
                    "trial": np.arange(v.size),
                    "method": m,
                    "quantity": q,
                    "truth": truth[q],
                    "estimate": v,
                    "error_pct": error_pct(v, truth[q], q),
                }
            )
        )
    return pd.concat(parts, ignore_index=True)[MC_TRIAL_COLUMNS]


@dataclass(frozen=True)
class Trials:
    """Per-trial estimates: ``estimates[b, p, t]`` of column ``columns[p]`` (method, quantity)
    at block ``b`` (N ``n_avg[b]``; one block and ``n_avg`` None for mc_trials)."""

    columns: tuple[tuple[str, str], ...]
    truth: np.ndarray
    n_avg: np.ndarray | None
    estimates: np.ndarray

    @classmethod
    def from_estimates(
        cls, blocks: Mapping[int | None, Estimates], truth: Mapping[str, float]
    ) -> Trials:
        """From the estimators' outputs, per N (key None: mc_trials, one block)."""
        keys = list(blocks)
        columns = tuple(ordered(blocks[keys[0]])) if keys else ()
        sizes = {np.size(blocks[k][c]) for k in keys for c in columns}
        if len(sizes) > 1 or any(tuple(ordered(blocks[k])) != columns for k in keys):
            raise ValueError(
                f"trials: every N and (method, quantity) needs the same trials; got sizes "
                f"{sorted(sizes)} and columns {[tuple(ordered(blocks[k])) for k in keys]}"
            )
        values = np.array(
            [[np.asarray(blocks[k][c], dtype=float).ravel() for c in columns] for k in keys]
        ).reshape(len(keys), len(columns), sizes.pop() if sizes else 0)
        n_avg = None if keys == [None] else np.asarray(keys, dtype=np.int64)
        return cls(columns, np.array([truth[q] for _, q in columns], dtype=float), n_avg, values)

    def frame(self) -> pd.DataFrame:
        """The long table, exactly as the CSV form reads (columns, order, values)."""
        n_b, n_p, n_t = self.estimates.shape
        est = self.estimates.reshape(-1)
        pct = (
            np.concatenate(
                [
                    error_pct(self.estimates[b, p], self.truth[p], q)
                    for b in range(n_b)
                    for p, (_, q) in enumerate(self.columns)
                ]  # fmt: skip
            )
            if est.size
            else np.empty(0)
        )
        data: dict[str, Any] = {}
        if self.n_avg is not None:
            data["n_avg"] = np.repeat(self.n_avg, n_p * n_t)
        data |= {
            "trial": np.tile(np.arange(n_t, dtype=np.int64), n_b * n_p),
            "method": _categorical([m for m, _ in self.columns], n_t, n_b),
            "quantity": _categorical([q for _, q in self.columns], n_t, n_b),
            "truth": np.tile(np.repeat(self.truth, n_t), n_b),
            "estimate": est,
            "error_pct": pct,
        }
        columns = MC_TRIAL_COLUMNS if self.n_avg is None else MC_JUDGED_COLUMNS
        return pd.DataFrame(data)[columns]


#: the string columns of a trials frame, categorical in both forms (a grouping or a filter on
#: millions of rows then compares small integer codes, not strings)
CATEGORICAL = ("method", "quantity")


def _categorical(names: list[str], n_t: int, n_b: int) -> pd.Categorical:
    """Column p's name on its n_t rows, for each of n_b blocks (categories sorted, as
    ``astype("category")`` gives for the CSV form)."""
    cats = sorted(set(names))
    codes = np.array([cats.index(n) for n in names], dtype=np.int8)
    return pd.Categorical.from_codes(np.tile(np.repeat(codes, n_t), n_b), categories=cats)


def _save(path: Path, trials: Trials) -> None:
    cols = np.array(
        [
            (m.encode(), q.encode(), t)
            for (m, q), t in zip(trials.columns, trials.truth, strict=True)
        ],
        dtype=_COLUMN_DTYPE,
    )
    n_avg = trials.n_avg if trials.n_avg is not None else np.empty(0, dtype=np.int64)
    with path.open("wb") as fh:
        for array in (np.array([TAG]), cols, n_avg.astype("<i8"), trials.estimates.astype("<f8")):
            np.save(fh, np.ascontiguousarray(array), allow_pickle=False)


def existing(directory: str | Path, stem: str) -> list[Path]:
    """The forms of ``stem`` present in ``directory``."""
    return [p for p in (Path(directory) / f"{stem}.{e}" for e in FORMATS) if p.is_file()]


def write_trials(
    directory: str | Path,
    stem: str,
    blocks: Mapping[int | None, Estimates],
    truth: Mapping[str, float],
    fmt: str,
) -> Path:
    """Write ``<stem>.<fmt>`` atomically (``blocks``: N -> estimates, key None for mc_trials)
    and remove the other form, so the folder holds exactly one."""
    if stem not in COLUMNS or fmt not in FORMATS:
        raise ValueError(f"trials file {stem}.{fmt}: allowed stems {list(COLUMNS)}, {FORMATS}")
    path = Path(directory) / f"{stem}.{fmt}"
    if fmt == "csv":
        parts = [trials_frame(e, truth).assign(n_avg=n) for n, e in blocks.items()]
        write_csv_parts(path, parts, COLUMNS[stem])  # the text of one part at a time
    else:
        trials = Trials.from_estimates(blocks, truth)
        write_atomic(path, lambda p: _save(p, trials))
    for other in existing(directory, stem):
        if other != path:
            other.unlink()
    return path


def _bad(path: Path, what: str) -> ValueError:
    return ValueError(
        f"{path}: not a valid north_finding trials file ({what}); expected the arrays tag "
        f"{TAG.decode()!r}, columns, n_avg, estimates written by np.save (rerun the step that "
        "writes it)"
    )


def load_npy(path: str | Path, stem: str) -> Trials:
    """Read and check a binary trials file (:func:`read_trials` uses it)."""
    path = Path(path)
    try:
        with path.open("rb") as fh:
            arrays = [np.lib.format.read_array(fh, allow_pickle=False) for _ in range(4)]
            trailing = fh.read(1)
    except (ValueError, EOFError, OSError) as exc:
        raise _bad(path, f"{type(exc).__name__}: {exc}") from None
    tag, cols, n_avg, est = arrays
    if tag.shape != (1,) or tag.dtype.kind != "S" or tag[0] != TAG:
        raise _bad(path, f"tag {tag!r:.60}")
    if trailing:
        raise _bad(path, "bytes after the last array")
    if cols.dtype != _COLUMN_DTYPE or cols.ndim != 1:
        raise _bad(path, f"columns dtype {cols.dtype}")
    judged = stem == "mc_trials_judged"
    if n_avg.dtype != np.dtype("<i8") or n_avg.ndim != 1 or (n_avg.size > 0) != judged:
        raise _bad(path, f"n_avg {n_avg.dtype} of {n_avg.size} values for {stem}")
    blocks = n_avg.size if judged else 1
    if est.dtype != np.dtype("<f8") or est.ndim != 3 or est.shape[:2] != (blocks, cols.size):
        raise _bad(path, f"estimates {est.dtype} {est.shape}, expected ({blocks}, {cols.size}, T)")
    pairs = tuple(
        (m.decode(), q.decode()) for m, q in zip(cols["method"], cols["quantity"], strict=True)
    )
    unknown = [
        p for p in pairs if p[0] not in METHOD_QUANTITIES or p[1] not in METHOD_QUANTITIES[p[0]]
    ]
    if unknown:
        raise _bad(path, f"unknown (method, quantity) {unknown}")
    return Trials(pairs, cols["truth"].astype(float), n_avg if judged else None, est)


def read_trials(directory: str | Path, stem: str) -> pd.DataFrame | None:
    """The frame of ``<stem>.csv`` or ``<stem>.npy`` in ``directory`` (None if neither), its
    :data:`CATEGORICAL` columns categorical; the CSV's columns are checked, a folder holding
    both forms is refused."""
    if stem not in COLUMNS:
        raise ValueError(f"trials file {stem!r}: allowed: {list(COLUMNS)}")
    found = existing(directory, stem)
    if len(found) > 1:
        raise ValueError(
            f"{found[0].parent}: both {found[0].name} and {found[1].name}; allowed: one "
            "(the other is stale: rerun the step that writes it)"
        )
    if not found:
        return None
    path = found[0]
    if path.suffix == ".npy":
        return load_npy(path, stem).frame()
    frame = pd.read_csv(path)
    missing = [c for c in COLUMNS[stem] if c not in frame.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(frame.columns)})")
    return frame.astype(dict.fromkeys(CATEGORICAL, "category"))


def _factorize(column: pd.Series, sort: bool) -> tuple[np.ndarray, Any]:
    """Codes and values of a key column; a categorical one's own codes (its categories are
    sorted: :data:`CATEGORICAL`), so millions of rows are not hashed again."""
    if isinstance(column.dtype, pd.CategoricalDtype) and column.cat.ordered is False:
        cats = column.cat.categories
        if not sort or cats.is_monotonic_increasing:
            return column.cat.codes.to_numpy().astype(np.int64), cats
    return pd.factorize(column, sort=sort)


def by_key(
    frame: pd.DataFrame, keys: list[str], value: str, *, sort: bool = False, by_trial: bool = True
) -> dict[tuple, np.ndarray]:
    """``frame.groupby(keys, sort=sort)`` -> each group's ``value`` in trial order (in row order
    if not ``by_trial``), without
    pandas' per-group frames (the trial tables are blocks of consecutive rows in trial order,
    found in one pass; any other frame is sorted stably by key and trial first).

    >>> f = pd.DataFrame({"method": ["B", "A", "B"], "trial": [1, 0, 0], "e": [1.0, 2.0, 3.0]})
    >>> {k: v.tolist() for k, v in by_key(f, ["method"], "e").items()}
    {('B',): [3.0, 1.0], ('A',): [2.0]}
    """
    if frame.empty:
        return {}
    codes, uniques = zip(*(_factorize(frame[k], sort) for k in keys), strict=True)
    shape = [max(len(u), 1) for u in uniques]
    code = np.ravel_multi_index([np.maximum(c, 0) for c in codes], shape)
    trial = frame["trial"].to_numpy() if by_trial else np.arange(len(frame))
    values = frame[value].to_numpy(dtype=float)
    if any(c.min() < 0 for c in codes):  # groupby drops missing keys
        keep = np.logical_and.reduce([c >= 0 for c in codes])
        code, trial, values = code[keep], trial[keep], values[keep]
    starts = np.flatnonzero(np.r_[True, code[1:] != code[:-1]])
    ends = np.r_[starts[1:], code.size]
    appearance = [int(c) for c in pd.unique(code[starts])]  # groupby(sort=False)'s order
    inner = np.ones(code.size, dtype=bool)
    inner[starts] = False
    if not (len(appearance) == starts.size and np.all(np.diff(trial)[inner[1:]] > 0)):
        order = np.lexsort((trial, code))
        code, values = code[order], values[order]
        starts = np.flatnonzero(np.r_[True, code[1:] != code[:-1]])
        ends = np.r_[starts[1:], code.size]
    groups = {int(code[s]): values[s:e] for s, e in zip(starts, ends, strict=True)}
    ordered = sorted(groups) if sort else appearance
    out = {}
    for c in ordered:
        index = np.unravel_index(c, shape)
        out[tuple(u[i] for u, i in zip(uniques, index, strict=True))] = groups[c]
    return out
