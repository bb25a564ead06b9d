"""Numerical trouble counted per run, case, method and kind, for every paper: never silent.

A computation meets trouble where noise, an extreme input or a domain edge pushes an argument
out of the domain of a formula (an arcsine of more than 1, a quartic without a real root, a
division by zero). It then returns a value, or NaN, so that one bad trial does not hide the
others, and records the trouble here; each paper writes the counts to
``results/<slug>/<scenario>/numerical_trouble.csv`` (:data:`TROUBLE_COLUMNS`) and its report
page shows them (:mod:`pipeline.report.trouble`). Every paper names its own kinds; the kind
``non_finite`` (an estimate NaN or infinite) is counted from the values themselves.

Columns: ``run`` (which computation: ``monte_carlo``, ``sensitivity``, ``main``...), ``case``
(its setting, e.g. the averaging count ``N=100`` or the drift case ``ch3``; empty when the run
has one), ``method``, ``kind``, ``n_trials`` (trials, runs or curve points of that method in that
run) and ``n_affected`` (how many of them met that kind of trouble).

>>> t = Trouble(("clipped_arcsine", "non_finite"))
>>> t.mark("L1", "clipped_arcsine", np.array([True, False, False]))
>>> t.mark("L1", "clipped_arcsine", np.array([False, False, True]))
>>> est = {("L1", "phi_deg"): np.array([1.0, np.nan, 2.0])}
>>> t.frame(est, "monte_carlo")[["method", "kind", "n_trials", "n_affected"]].values.tolist()
[['L1', 'clipped_arcsine', 3, 2], ['L1', 'non_finite', 3, 1]]
>>> t.mark("L1", "typo", np.array([True]))
Traceback (most recent call last):
...
ValueError: numerical trouble kind 'typo': allowed: clipped_arcsine, non_finite
>>> finite_count(np.array([1.0, np.inf, np.nan, 2.0]))
2
>>> require_used(10, 9, "mc_summary L1 phi_deg")
Traceback (most recent call last):
...
ValueError: mc_summary L1 phi_deg: 9 of 10 trials usable (finite): a summary over fewer trials than its trial count says is refused
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import numpy as np
import pandas as pd

__all__ = [
    "NON_FINITE",
    "TROUBLE_COLUMNS",
    "Trouble",
    "finite_count",
    "mark",
    "require_used",
    "trouble_rows",
]

#: results/<slug>/<scenario>/numerical_trouble.csv, the same for every paper
TROUBLE_COLUMNS = ["run", "case", "method", "kind", "n_trials", "n_affected"]
#: the kind counted from the values: NaN or infinite
NON_FINITE = "non_finite"


class Trouble:
    """Per (method, kind) the trials (a boolean mask) in which a computation met trouble."""

    def __init__(self, kinds: Sequence[str]) -> None:
        self.kinds = tuple(kinds)
        self._flags: dict[tuple[str, str], np.ndarray] = {}

    def mark(self, method: str, kind: str, mask: np.ndarray) -> None:
        """Record ``mask`` (True = trouble in that trial) for ``method``; masks accumulate."""
        if kind not in self.kinds:
            raise ValueError(f"numerical trouble kind {kind!r}: allowed: {', '.join(self.kinds)}")
        m = np.asarray(mask, dtype=bool).reshape(-1)
        old = self._flags.get((method, kind))
        self._flags[method, kind] = m if old is None else (np.broadcast_to(old, m.shape) | m)

    def frame(
        self,
        estimates: Mapping[tuple[str, str], np.ndarray] | Mapping[str, np.ndarray],
        run: str,
        case: str = "",
    ) -> pd.DataFrame:
        """One row per method of ``estimates`` (keyed by method or (method, quantity)) and
        kind, zeros included: the counts. A trial is ``non_finite`` if any of its method's
        values is."""
        by_method: dict[str, list[np.ndarray]] = {}
        for key, v in estimates.items():
            method = key[0] if isinstance(key, tuple) else key
            by_method.setdefault(method, []).append(np.asarray(v, dtype=float))
        rows = []
        for method, values in by_method.items():
            n = max(v.shape[0] if v.ndim else 1 for v in values)
            bad = np.zeros(n, dtype=bool)
            for v in values:
                flat = v.reshape(n, -1) if v.ndim else np.broadcast_to(v, (n, 1))
                bad |= ~np.isfinite(flat).all(axis=1)
            for kind in self.kinds:
                if kind == NON_FINITE:
                    affected = int(bad.sum())
                else:
                    flags = self._flags.get((method, kind))
                    affected = 0 if flags is None else int(np.broadcast_to(flags, (n,)).sum())
                rows.append((run, case, method, kind, n, affected))
        return pd.DataFrame(rows, columns=TROUBLE_COLUMNS)


def mark(trouble: Trouble | None, method: str, kind: str, mask: np.ndarray) -> None:
    """:meth:`Trouble.mark` when counting (``trouble`` given), else nothing."""
    if trouble is not None:
        trouble.mark(method, kind, mask)


def trouble_rows(
    run: str, case: str, method: str, n_trials: int, counts: Mapping[str, int]
) -> list[tuple]:
    """Rows of :data:`TROUBLE_COLUMNS` for counts computed elsewhere (kind -> n_affected)."""
    return [(run, case, method, k, int(n_trials), int(a)) for k, a in counts.items()]


def finite_count(values: Iterable[float] | np.ndarray) -> int:
    """How many of ``values`` are finite (neither NaN nor infinite)."""
    return int(np.isfinite(np.asarray(values, dtype=float)).sum())


def require_used(n_trials: int, n_used: int, where: str) -> None:
    """Refuse (ValueError naming ``where``) a summary that would use fewer trials than the
    ``n_trials`` it reports."""
    if n_used != n_trials:
        raise ValueError(
            f"{where}: {n_used} of {n_trials} trials usable (finite): a summary over fewer "
            "trials than its trial count says is refused"
        )
