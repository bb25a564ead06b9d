"""Numerical trouble of the estimators, counted per method and trial: never silent.

An estimator meets trouble where noise (or a reading outside the model) pushes an argument out
of the domain of the formula. It then returns a value (so that one bad trial does not hide
the others) and records the trouble here; the workflow writes the counts to
``numerical_trouble.csv`` and the report shows them. The kinds:

``clipped_arcsine``
    an arcsine or arccosine argument outside [-1, 1] (|f| > g, |cos psi| > 1) clipped to
    it: the angle is then exactly +-90 deg (or 0 / 180 deg);
``unreachable_root``
    ``a sin(psi) + b cos(psi) = c`` with |c| > sqrt(a^2 + b^2) (methods A1c2, A2, A4): c
    clipped to the reachable range, which gives the double root;
``complex_roots``
    the quartic of eq. 50 (method A3) has no real root in [-1, 1]: the real parts of its
    complex roots are used instead;
``non_finite``
    an estimate of the method is NaN or infinite.

>>> t = Trouble()
>>> t.mark("L1", "clipped_arcsine", np.array([True, False, False]))
>>> t.mark("L1", "clipped_arcsine", np.array([False, False, True]))
>>> est = {("L1", "phi_deg"): np.array([1.0, np.nan, 2.0])}
>>> t.frame(est, "monte_carlo")[["method", "kind", "n_trials", "n_affected"]].values.tolist()
[['L1', 'clipped_arcsine', 3, 2], ['L1', 'unreachable_root', 3, 0], ['L1', 'complex_roots', 3, 0], ['L1', 'non_finite', 3, 1]]
>>> t.mark("L1", "typo", np.array([True]))
Traceback (most recent call last):
...
ValueError: numerical trouble kind 'typo': allowed: clipped_arcsine, unreachable_root, complex_roots, non_finite
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

__all__ = ["TROUBLE_COLUMNS", "TROUBLE_KINDS", "Trouble", "mark"]

#: the kinds of trouble, in the order of the file's rows
TROUBLE_KINDS = ("clipped_arcsine", "unreachable_root", "complex_roots", "non_finite")
#: results/north_finding/<scenario>/numerical_trouble.csv: per run (noise_free_real,
#: monte_carlo or readings), method and kind, the trials affected out of the trials run
TROUBLE_COLUMNS = ["run", "method", "kind", "n_trials", "n_affected"]


class Trouble:
    """Per (method, kind) the trials (a boolean mask) in which the estimator met trouble."""

    def __init__(self) -> None:
        self._flags: dict[tuple[str, str], np.ndarray] = {}

    def mark(self, method: str, kind: str, mask: np.ndarray) -> None:
        """Record ``mask`` (True = trouble in that trial) for ``method``; masks accumulate."""
        if kind not in TROUBLE_KINDS:
            raise ValueError(
                f"numerical trouble kind {kind!r}: allowed: {', '.join(TROUBLE_KINDS)}"
            )
        m = np.asarray(mask, dtype=bool).reshape(-1)
        old = self._flags.get((method, kind))
        self._flags[method, kind] = m if old is None else (np.broadcast_to(old, m.shape) | m)

    def frame(self, estimates: Mapping[tuple[str, str], np.ndarray], run: str) -> pd.DataFrame:
        """One row per method of ``estimates`` and kind (zeros included): the counts."""
        methods = list(dict.fromkeys(m for m, _ in estimates))
        rows = []
        for method in methods:
            values = [np.asarray(v, dtype=float) for (m, _), v in estimates.items() if m == method]
            n = max(v.size for v in values)
            bad = np.zeros(n, dtype=bool)
            for v in values:
                bad |= ~np.isfinite(np.broadcast_to(v, (n,)))
            for kind in TROUBLE_KINDS:
                if kind == "non_finite":
                    affected = int(bad.sum())
                else:
                    flags = self._flags.get((method, kind))
                    affected = 0 if flags is None else int(np.broadcast_to(flags, (n,)).sum())
                rows.append((run, method, kind, n, affected))
        return pd.DataFrame(rows, columns=TROUBLE_COLUMNS)


def mark(trouble: Trouble | None, method: str, kind: str, mask: np.ndarray) -> None:
    """:meth:`Trouble.mark` when counting (``trouble`` given), else nothing."""
    if trouble is not None:
        trouble.mark(method, kind, mask)
