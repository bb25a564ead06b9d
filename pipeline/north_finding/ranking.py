"""Methods ranked by their error at several averaging counts N (the paper gives no N).

Simulate side: :func:`ranking_frames` runs the Monte Carlo at every N of the scenario's
``ranking`` block, on the same standard normals for every N, and writes, per N, the RMS % error
of every method (``ranking.csv``) and, for every two methods giving the same quantity, the
paired difference of their squared % errors over the same trials (``ranking_pairs.csv``): its
mean, its standard error and the largest per-trial |difference| of the errors (0 where two
methods are the same estimator).

Verdict side: :func:`rank_sets` turns those files (and the noise-free real row of
``estimates.csv``) into one :class:`RankSet` per N, ordered by N, the noise-free set last; a
claim that ranks methods is judged on each. Two methods are

* ``identical`` when their errors agree to :data:`TIE_REL` (relative) on every trial;
* ``separated`` when the mean of the paired squared-error difference lies more than
  :data:`Z_RESOLVE` standard errors from 0 (the noise-free set has no noise: any difference
  beyond the tie separates).

Where the results hold the N inference (``n_rows.csv``, ``mc_trials_judged.csv``,
:mod:`pipeline.north_finding.n_inference`), :func:`posterior_set` gives the rank set the claims
are judged on: our Monte Carlo at every grid N mixed with the posterior weights of all the
statistical rows used (flat prior over log10 N, the weights of ``n_profile.csv``), i.e. at the
N the paper's own printed values imply, as the statistical rows are. Its mean squared % error
is sum_N w_N ms_N; the paired difference of two methods is, per trial, sum_N w_N d_N (the
trials at every N share their standard normals), so its standard error is that of the mean of
those per-trial values.

>>> fmt_n(1), fmt_n(100), fmt_n(10000), fmt_n(1000000), fmt_n(25000)
('1', '100', '1e4', '1e6', '25000')
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, MutableMapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import METHODS, RANKING_COLUMNS, RANKING_PAIR_COLUMNS
from pipeline.north_finding.n_inference import MIN_WEIGHT, fmt_grid
from pipeline.north_finding.trials_file import by_key

__all__ = [
    "NOISE_FREE",
    "TIE_REL",
    "Z_RESOLVE",
    "Comparison",
    "RankSet",
    "fmt_n",
    "posterior_set",
    "posterior_weights",
    "rank_sets",
    "ranking_frames",
]

#: Relative agreement of two methods' errors below which they are the same estimator.
TIE_REL = 1e-8
#: Standard errors of the paired difference beyond which two methods' errors differ.
Z_RESOLVE = 2.0
#: Suffix of the noise-free rank set (N -> infinity).
NOISE_FREE = "noise-free"


def fmt_n(n: int) -> str:
    """N as a row suffix: plain below 10^4, ``1e4``-style for exact powers of ten above."""
    if n >= 10_000 and 10 ** round(math.log10(n)) == n:
        return f"1e{round(math.log10(n))}"
    return str(int(n))


# --------------------------------------------------------------------------- simulate side
def ranking_frames(
    run: Callable[[int], Mapping[tuple[str, str], np.ndarray]],
    error_pct: Callable[[np.ndarray, str], np.ndarray],
    n_avg: Sequence[int],
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``(ranking, pairs)`` for every N: ``run(N)`` gives the Monte Carlo estimates at N,
    ``error_pct(estimates, quantity)`` their signed % errors."""
    rows, pair_rows = [], []
    for n in n_avg:
        errors = {key: error_pct(v, key[1]) for key, v in run(int(n)).items()}
        by_quantity: dict[str, list[str]] = {}
        for (m, q), e in errors.items():
            rows.append((int(n), m, q, float(np.sqrt(np.mean(e**2))), e.size))
            by_quantity.setdefault(q, []).append(m)
        for q, methods in by_quantity.items():
            ordered = [m for m in METHODS if m in methods]
            for i, a in enumerate(ordered):
                for b in ordered[i + 1 :]:
                    ea, eb = errors[a, q], errors[b, q]
                    d = ea**2 - eb**2
                    se = float(np.std(d, ddof=1) / np.sqrt(d.size)) if d.size > 1 else math.nan
                    big = float(np.max(np.abs(ea - eb)))
                    pair_rows.append((int(n), q, a, b, float(np.mean(d)), se, big, d.size))
    return (
        pd.DataFrame(rows, columns=RANKING_COLUMNS),
        pd.DataFrame(pair_rows, columns=RANKING_PAIR_COLUMNS),
    )


# --------------------------------------------------------------------------- verdict side
@dataclass(frozen=True)
class Comparison:
    """Method ``a`` against ``b`` in one rank set: ``d`` = ms_a - ms_b (mean squared % error),
    ``z`` = d / its standard error (+-inf without noise), ``identical``: the same estimator."""

    a: str
    b: str
    d: float
    z: float
    identical: bool
    noise_free: bool = False

    @property
    def separated(self) -> bool:
        return not self.identical and abs(self.z) > Z_RESOLVE

    def describe(self) -> str:
        """How a compares with b, in words."""
        if self.identical:
            where = "noise-free" if self.noise_free else "on every trial"
            return f"{self.a} identical to {self.b} {where}"
        if math.isinf(self.z):
            return f"{self.a} {'above' if self.d > 0 else 'below'} {self.b}"
        return f"{self.a} - {self.b}: z = {self.z:+.1f}"


@dataclass(frozen=True)
class RankSet:
    """The RMS % error of every method at one N: ``n_avg`` (None: the scenario's own Monte
    Carlo, N not recorded) or the noise-free run (``noise_free``, ``n_trials`` 0)."""

    suffix: str
    n_avg: int | None
    n_trials: int
    rms: Mapping[tuple[str, str], float]
    pairs: Mapping[tuple[str, str, str], tuple[float, float, float]] = field(default_factory=dict)
    noise_free: bool = False
    #: grid N -> posterior weight of a mixture over N (empty: one N)
    mixture: Mapping[int, float] = field(default_factory=dict)

    @property
    def where(self) -> str:
        """Where the set was computed, in words."""
        if self.noise_free:
            return "noise-free"
        if self.mixture:
            heavy = sorted(self.mixture.items(), key=lambda kv: (-kv[1], kv[0]))
            weights = ", ".join(f"{fmt_grid(n)}: {w:.2f}" for n, w in heavy if w >= 0.005)
            return (
                f"the N the tables imply (our Monte Carlo mixed over N with the posterior "
                f"weights of the statistical rows, N {weights}), {self.n_trials} trials per N"
            )
        n = "the scenario's N" if self.n_avg is None else f"N = {fmt_n(self.n_avg)}"
        return f"{n}, {self.n_trials} trials"

    @property
    def label(self) -> str:
        """The set's N in a list of N ('1e4', 'noise-free')."""
        if self.noise_free:
            return NOISE_FREE
        if self.mixture:
            return "the inferred N"
        return "the scenario's N" if self.n_avg is None else fmt_n(self.n_avg)

    def get(self, method: str, quantity: str) -> float | None:
        value = self.rms.get((method, quantity))
        return None if value is None or not math.isfinite(value) else value

    def compare(self, quantity: str, a: str, b: str) -> Comparison:
        """a against b (both must have an RMS in this set)."""
        ra, rb = self.rms[a, quantity], self.rms[b, quantity]
        scale = max(ra, rb)
        if self.noise_free:
            same = abs(ra - rb) <= TIE_REL * scale
            d = ra**2 - rb**2
            return Comparison(a, b, d, math.copysign(math.inf, d) if d else 0.0, same, True)
        key, sign = (
            ((quantity, a, b), 1.0) if (quantity, a, b) in self.pairs else ((quantity, b, a), -1.0)
        )
        mean, se, big = self.pairs[key]
        same = big <= TIE_REL * scale
        z = sign * mean / se if se > 0 else (math.copysign(math.inf, sign * mean) if mean else 0.0)
        return Comparison(a, b, sign * mean, z, same)


def _noise_free(estimates: pd.DataFrame) -> RankSet | None:
    real = estimates[estimates["sensor"] == "real"]
    if real.empty:
        return None
    rms = {
        (str(m), str(q)): abs(float(e))
        for m, q, e in zip(real["method"], real["quantity"], real["error_pct"], strict=True)
    }
    return RankSet(NOISE_FREE, None, 0, rms, noise_free=True)


def _from_trials(trials: pd.DataFrame) -> RankSet | None:
    """One rank set from the Monte Carlo trials themselves (no ranking file: no suffix)."""
    if trials.empty:
        return None
    rms, pairs = {}, {}
    errors = by_key(trials, ["method", "quantity"], "error_pct")
    for (m, q), e in errors.items():
        rms[m, q] = float(np.sqrt(np.mean(e**2)))
    for (a, q), ea in errors.items():
        for (b, q2), eb in errors.items():
            if q2 == q and a != b and ea.size == eb.size:
                d = ea**2 - eb**2
                se = float(np.std(d, ddof=1) / np.sqrt(d.size)) if d.size > 1 else math.nan
                pairs[q, a, b] = (float(np.mean(d)), se, float(np.max(np.abs(ea - eb))))
    n = int(next(iter(errors.values())).size)
    return RankSet("", None, n, rms, pairs)


def rank_sets(results: Mapping[str, pd.DataFrame]) -> list[RankSet]:
    """The rank sets of the results: one per N of ``ranking.csv`` (ascending), or, without
    it, one from ``mc_trials.csv`` (at provenance's ``n_avg`` where recorded, else without a
    suffix); then the noise-free set when estimates.csv has real rows."""
    out: list[RankSet] = []
    ranking = results.get("ranking")
    if ranking is not None and not ranking.empty:
        pairs = results.get("ranking_pairs", pd.DataFrame(columns=RANKING_PAIR_COLUMNS))
        for n, block in ranking.groupby("n_avg", sort=True):
            rms = {
                (str(m), str(q)): float(r)
                for m, q, r in zip(
                    block["method"], block["quantity"], block["rms_error_pct"], strict=True
                )  # fmt: skip
            }
            pb = pairs[pairs["n_avg"] == n]
            pair_map = {
                (str(q), str(a), str(b)): (float(mu), float(se), float(big))
                for q, a, b, mu, se, big in zip(
                    pb["quantity"],
                    pb["method_a"],
                    pb["method_b"],
                    pb["mean_sq_diff_pct2"],
                    pb["se_sq_diff_pct2"],
                    pb["max_abs_diff_pct"],
                    strict=True,
                )  # fmt: skip
            }
            n_trials = int(block["n_trials"].max())
            out.append(RankSet(f"N={fmt_n(int(n))}", int(n), n_trials, rms, pair_map))
    else:
        from_trials = _from_trials(results["mc_trials"])
        n = (results.get("provenance") or {}).get("n_avg")
        if from_trials is not None and n:
            from_trials = replace(from_trials, suffix=f"N={fmt_n(int(n))}", n_avg=int(n))
        if from_trials is not None:
            out.append(from_trials)
    free = _noise_free(results["estimates"]) if "estimates" in results else None
    if free is not None and out:
        out.append(free)
    return out


def posterior_weights(n_rows: pd.DataFrame) -> dict[int, float]:
    """Grid N -> the posterior weight of all used statistical rows (flat prior over the grid;
    weights below :data:`~pipeline.north_finding.n_inference.MIN_WEIGHT` set to 0).

    >>> rows = pd.DataFrame({"n_avg": [10, 100, 10, 100], "log_lik": [-1.0, -2.0, -3.0, -1.0],
    ...                      "used": [True, True, True, False]})
    >>> {n: round(w, 4) for n, w in posterior_weights(rows).items()}
    {10: 0.1192, 100: 0.8808}
    """
    used = n_rows[n_rows["used"].astype(bool)]
    grid = sorted({int(n) for n in n_rows["n_avg"]})
    total = used.groupby("n_avg")["log_lik"].sum().reindex(grid, fill_value=0.0).to_numpy(float)
    w = np.exp(total - np.max(total))
    w /= w.sum()
    w[w < MIN_WEIGHT] = 0.0
    w /= w.sum()
    return {n: float(x) for n, x in zip(grid, w, strict=True) if x > 0}


def posterior_set(results: Mapping[str, pd.DataFrame]) -> RankSet | None:
    """The rank set at the N the statistical rows imply (None: no N inference in the results);
    computed once per results mapping."""
    if isinstance(results, MutableMapping) and "_posterior_set" in results:
        return results["_posterior_set"]
    out = _posterior_set(results)
    if isinstance(results, MutableMapping):
        results["_posterior_set"] = out
    return out


def _posterior_set(results: Mapping[str, pd.DataFrame]) -> RankSet | None:
    n_rows, mc = results.get("n_rows"), results.get("mc_trials_judged")
    if n_rows is None or n_rows.empty or mc is None or mc.empty:
        return None
    weights = posterior_weights(n_rows)
    missing = sorted(set(weights) - set(np.unique(mc["n_avg"].to_numpy()).tolist()))
    if missing:
        raise ValueError(
            f"mc_trials_judged.csv: no trials at n_avg = {missing}, where the statistical rows "
            "put posterior weight; the N inference is stale (rerun the infer_n step)"
        )
    errors: dict[tuple[str, str], dict[int, np.ndarray]] = {}
    for (n, m, q), v in by_key(mc, ["n_avg", "method", "quantity"], "error_pct", sort=True).items():  # fmt: skip
        if int(n) in weights:  # the N with posterior weight
            errors.setdefault((str(m), str(q)), {})[int(n)] = v
    rms, pairs, sizes = {}, {}, set()
    for key, by_n in errors.items():
        rms[key] = float(np.sqrt(sum(w * np.mean(by_n[n] ** 2) for n, w in weights.items())))
        sizes.update(v.size for v in by_n.values())
    for (a, q), ea in errors.items():
        for (b, q2), eb in errors.items():
            if q2 != q or a == b or METHODS.index(a) > METHODS.index(b):
                continue
            d = sum(w * (ea[n] ** 2 - eb[n] ** 2) for n, w in weights.items())
            se = float(np.std(d, ddof=1) / np.sqrt(d.size)) if d.size > 1 else math.nan
            big = max(float(np.max(np.abs(ea[n] - eb[n]))) for n in weights)
            pairs[q, a, b] = (float(np.mean(d)), se, big)
    return RankSet("", None, int(min(sizes)), rms, pairs, mixture=weights)
