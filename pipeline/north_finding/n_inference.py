"""The averaging count N at which the statistical rows are judged, inferred from the paper.

The paper averages its 5 % white noise "as much as possible" and gives no sample count N, so
the statistical rows (the real-sensor columns of Tables 1-4 and 9-12) are not judged at an N
we chose: N is inferred from the printed values themselves, by likelihood over the scenario's
grid (``n_inference.n_avg``), and each row is judged on our Monte Carlo mixed over the grid N
with the weights the *other* rows' likelihood gives (a leave-one-out posterior predictive check).

Likelihood of one row at one grid N
    Our Monte Carlo at N (the main Monte Carlo's standard normals, seeds per trial) gives the
    quantity's trials; a Gaussian is fitted to them (mean, standard deviation): the averaged
    noise is sigma/sqrt(N) of the nominal reading, small enough that it enters the estimators
    nearly linearly (``n_rows.csv`` records the Kolmogorov-Smirnov distance of every fit). A
    printed value stands for every number that prints as it, by rounding or by truncation
    (:func:`printed_interval`), so the row's likelihood is the Gaussian probability of that
    interval (a probability, not a density: comparable across N, and bounded by 1 where our
    spread is below the printed digit).
Robust rule
    (1) A row whose percentile rank lies outside the rank band at every grid N is excluded: no
    averaging count makes it noise, so it says nothing about N. (2) Each remaining row is, with
    probability ``1 - eps``, our model at N and, with probability ``eps`` (``contamination``),
    from a run the paper does not describe, taken as our model at the grid's smallest N (the
    widest spread the grid considers): ``L = (1 - eps) p(N) + eps p(N_min)``. A row our model
    cannot place at N then costs at most log(1/eps) nats, so no single row drags the estimate.
Correlated rows
    Rows that share readings are correlated (one method's roll and pitch; azimuth methods 4 and
    5, the same estimator; the gyro scale factors of methods 4 to 6). Multiplied as if
    independent they would count one piece of evidence several times and make the weights over
    N too sharp. So the likelihood is a weighted composite likelihood: row i's log-likelihood
    enters times ``row_weight`` = 1 / sum_j r_ij^2 (:func:`row_weights`), r the correlation of
    the rows' Monte Carlo estimates over the same trials at the grid's largest N (where the
    averaged noise enters linearly, so r does not depend on N), summed over the used rows: k
    copies of one row count once in all, a row uncorrelated with the others counts fully.
Profile and leave-one-out posterior predictive check
    The profile is the sum over the used rows of the weighted log-likelihoods. Each
    row is judged on its leave-one-out posterior predictive distribution: weights over the grid
    w_N proportional to exp(profile of the OTHER used rows at N) (a flat prior over log10 N on
    the grid; weights below :data:`MIN_WEIGHT` set to 0, the rest renormalised), and the
    mixture over N of our Monte Carlo trials at N with those weights. The published value's
    percentile rank in it is sum_N w_N rank_N (:func:`mixture_rank`); consistent inside the
    rank band. A flat profile thus spreads the weight over the N it cannot tell apart, and a
    row is not failed on the strength of a near-tie between them.

Files (results/north_finding/<published scenario>/, written by
:mod:`pipeline.north_finding.run_inference`): ``n_profile.csv``, ``n_rows.csv``,
``mc_trials_judged.csv`` (the trials at every grid N: the rows' weights, and those of the
reweighted likelihoods of :mod:`pipeline.north_finding.n_sensitivity`, may fall on any) and ``n_robustness.csv``
(the inference rerun at other contamination probabilities and on the grid's powers of ten),
columns in :mod:`pipeline.north_finding.columns`.

Three rows, three grid N: all rows together peak at the middle N, but row 2 prefers the first
so strongly that rows 0 and 1 put most of their weight there (row 2 and the other one), and
row 2 nearly all of its weight on the middle N (what rows 0 and 1 imply):

>>> ll = np.log(np.array([[0.1, 0.5, 0.2], [0.1, 0.45, 0.4], [0.9, 0.05, 0.01]]))
>>> every = np.array([True, True, True])
>>> int(np.argmax(profile(ll, every))), loo_weights(ll, every).round(3).tolist()
(1, [[0.773, 0.193, 0.034], [0.769, 0.214, 0.017], [0.032, 0.714, 0.254]])
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import MC_JUDGED_COLUMNS, N_PROFILE_COLUMNS, N_ROW_COLUMNS
from pipeline.verdicts.kinds import RANK_BAND, percentile_rank
from pipeline.verdicts.printed import unit

#: Leave-one-out weights below this are set to 0 (and the rest renormalised): a grid N that
#: carries less moves a percentile rank by less than 1e-4.
MIN_WEIGHT = 1e-6

__all__ = [
    "MIN_WEIGHT",
    "consistent_range",
    "fmt_grid",
    "infer_frames",
    "interval_log_prob",
    "ks_statistic_norm",
    "loo_weights",
    "mixture_rank",
    "posterior_range",
    "mixture_log_lik",
    "printed_interval",
    "profile",
    "row_weights",
]


def fmt_grid(n: int) -> str:
    """A grid N in text: powers of ten from 100 up as ``1eK``, other N below 1000 plain, the
    rest with two significant digits in e-notation.

    >>> fmt_grid(100), fmt_grid(316), fmt_grid(3162), fmt_grid(1000000), fmt_grid(31622777)
    ('1e2', '316', '3.2e3', '1e6', '3.2e7')
    """
    if n < 1000 and not (n >= 100 and 10 ** round(math.log10(n)) == n):
        return str(int(n))
    mantissa, exponent = f"{n:.1e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def printed_interval(printed: str) -> tuple[float, float]:
    """The numbers that print as ``printed`` by rounding or by truncation toward zero.

    >>> printed_interval("50.0050")
    (50.00495, 50.0051)
    >>> printed_interval("-2.5")
    (-2.6, -2.45)
    """
    v, u = float(printed), unit(printed)
    lo, hi = (v - u / 2, v + u) if v >= 0 else (v - u, v + u / 2)
    return float(f"{lo:.15g}"), float(f"{hi:.15g}")


def interval_log_prob(mean: float, std: float, lo: float, hi: float) -> float:
    """log P(lo <= X < hi) for X ~ N(mean, std^2), accurate far in either tail.

    >>> round(math.exp(interval_log_prob(0.0, 1.0, -1.0, 1.0)), 4)
    0.6827
    >>> round(interval_log_prob(0.0, 1.0, 30.0, 31.0), 1)  # 30 sigma out: finite
    -454.3
    """
    if not std > 0:
        return 0.0 if lo <= mean < hi else -math.inf
    # scipy imported here, not at module level: the Snakefile's parse imports this module
    # (through the paper's claims) and scipy.stats costs ~1 s of CPU there
    from scipy.special import log_ndtr

    a, b = (lo - mean) / std, (hi - mean) / std
    if a > 0:  # right tail: use the mirror image, where log_ndtr is accurate
        a, b = -b, -a
    la, lb = float(log_ndtr(a)), float(log_ndtr(b))
    return lb + math.log1p(-math.exp(la - lb)) if la < lb else -math.inf


def ks_statistic_norm(z: np.ndarray) -> float:
    """The Kolmogorov-Smirnov statistic of the sample ``z`` against N(0, 1): the same number as
    ``scipy.stats.kstest(z, "norm").statistic`` (the same operations), without the p-value
    kstest computes (its exact distribution, the most of its cost) and its wrappers.

    >>> from scipy.stats import kstest
    >>> z = np.random.default_rng(0).standard_normal(400)
    >>> ks_statistic_norm(z) == float(kstest(z, "norm").statistic)
    True
    """
    from scipy.special import ndtr  # lazily: see interval_log_prob

    x = np.sort(np.asarray(z, dtype=float))
    n = x.shape[-1]
    cdf = ndtr(x)
    d_plus = float(np.max(np.arange(1.0, n + 1, dtype=x.dtype) / n - cdf))
    d_minus = float(np.max(cdf - np.arange(0.0, n, dtype=x.dtype) / n))
    return d_plus if d_plus > d_minus else d_minus


def mixture_log_lik(log_p: np.ndarray, eps: float) -> np.ndarray:
    """Robust log-likelihood, rows x grid: log((1 - eps) p(N) + eps p(N_min)), N_min column 0.

    >>> mixture_log_lik(np.log(np.array([[0.5, 1e-300]])), 0.1).round(3).tolist()
    [[-0.693, -2.996]]
    """
    floor = np.log(eps) + log_p[:, :1]
    return np.logaddexp(np.log1p(-eps) + log_p, floor)


def profile(log_lik: np.ndarray, used: np.ndarray) -> np.ndarray:
    """The profile log-likelihood over the grid: the sum of the used rows."""
    return log_lik[np.asarray(used, dtype=bool)].sum(axis=0)


def loo_weights(log_lik: np.ndarray, used: np.ndarray) -> np.ndarray:
    """Rows x grid: each row's weights over the grid, proportional to exp(profile of the OTHER
    used rows) (flat prior over the grid), those below :data:`MIN_WEIGHT` set to 0.

    >>> loo_weights(np.log(np.array([[0.5, 0.5], [0.2, 0.8]])), np.array([True, True])).round(9)
    array([[0.2, 0.8],
           [0.5, 0.5]])
    """
    used = np.asarray(used, dtype=bool)
    total = profile(log_lik, used)
    out = np.empty(log_lik.shape, dtype=float)
    for i in range(log_lik.shape[0]):
        others = total - log_lik[i] if used[i] else total
        w = np.exp(others - np.max(others))
        w /= w.sum()
        w[w < MIN_WEIGHT] = 0.0
        out[i] = w / w.sum()
    return out


def mixture_rank(weights: np.ndarray, ranks: np.ndarray) -> np.ndarray:
    """The percentile rank in the weighted mixture: sum over the grid of w_N rank_N (per row).

    >>> mixture_rank(np.array([[0.5, 0.5, 0.0]]), np.array([[50.0, 99.9, 100.0]])).tolist()
    [74.95]
    """
    return np.where(weights > 0, weights * ranks, 0.0).sum(axis=-1)


def posterior_range(
    n_avg: Sequence[int], weights: Sequence[float], mass: float = 0.9, heaviest: bool = True
) -> str:
    """The grid N holding ``mass`` of the weight (heaviest first, the smaller N on a tie), in
    words, with the heaviest N unless ``heaviest`` is False.

    >>> posterior_range([100, 1000, 10000, 100000], [0.05, 0.5, 0.4, 0.05])
    '90 % of the weight on N from 1e3 to 1e4 (most on 1e3: 0.50)'
    >>> posterior_range([100, 1000, 10000, 100000], [0.05, 0.5, 0.4, 0.05], heaviest=False)
    '90 % of the weight on N from 1e3 to 1e4'
    >>> posterior_range([100, 1000], [0.0, 1.0])
    '90 % of the weight on N = 1e3 (1.00)'
    """
    n, w = [int(x) for x in n_avg], [float(x) for x in weights]
    order = sorted(range(len(n)), key=lambda k: (-w[k], k))
    held, acc = [], 0.0
    for k in order:
        held.append(k)
        acc += w[k]
        if acc >= mass - 1e-12:
            break
    lo, hi, top = min(held), max(held), order[0]
    pct = f"{100 * mass:.0f} % of the weight"
    if lo == hi:
        return f"{pct} on N = {fmt_grid(n[lo])}" + (f" ({w[lo]:.2f})" if heaviest else "")
    where = f"N from {fmt_grid(n[lo])} to {fmt_grid(n[hi])}"
    if hi - lo + 1 != len(held):
        where += f" (grid points {', '.join(fmt_grid(n[k]) for k in sorted(held))})"
    return f"{pct} on {where}" + (
        f" (most on {fmt_grid(n[top])}: {w[top]:.2f})" if heaviest else ""
    )


def consistent_range(n_avg: Sequence[int], in_band: Sequence[bool]) -> str:
    """Where on the grid a row is consistent, in words.

    >>> consistent_range([100, 1000, 10000], [True, True, False])
    'consistent for N <= 1e3 on the grid (1e2 to 1e4)'
    >>> consistent_range([100, 1000, 10000], [False, True, True])
    'consistent for N >= 1e3 on the grid (1e2 to 1e4)'
    >>> consistent_range([100, 1000, 10000], [False, False, False])
    'consistent at no N on the grid (1e2 to 1e4)'
    """
    n = [int(x) for x in n_avg]
    ok = [bool(x) for x in in_band]
    grid = f"on the grid ({fmt_grid(n[0])} to {fmt_grid(n[-1])})"
    where = [x for x, k in zip(n, ok, strict=True) if k]
    if not where:
        return f"consistent at no N {grid}"
    if len(where) == len(n):
        return f"consistent at every N {grid}"
    first, last = n.index(where[0]), n.index(where[-1])
    if last - first + 1 != len(where):
        return f"consistent for N in {{{', '.join(fmt_grid(x) for x in where)}}} {grid}"
    if first == 0:
        return f"consistent for N <= {fmt_grid(where[-1])} {grid}"
    if last == len(n) - 1:
        return f"consistent for N >= {fmt_grid(where[0])} {grid}"
    return f"consistent for {fmt_grid(where[0])} <= N <= {fmt_grid(where[-1])} {grid}"


def row_weights(estimates: Sequence[np.ndarray], used: np.ndarray) -> np.ndarray:
    """1 / sum_j r_ij^2 over the used rows j (r_ii = 1; a constant row correlates with none);
    1 for an unused row.

    >>> x = np.array([0.0, 1.0, 2.0, 3.0])
    >>> row_weights([x, 2 * x, np.array([1.0, -1.0, -1.0, 1.0])], np.array([True] * 3)).tolist()
    [0.5, 0.5, 1.0]
    """
    used = np.asarray(used, dtype=bool)
    size = min(np.size(e) for e in estimates)
    x = np.array([np.asarray(e, dtype=float)[:size] for e in estimates])
    x = x[:, np.all(np.isfinite(x), axis=0)]  # the trials every row has
    with np.errstate(invalid="ignore", divide="ignore"):
        r = np.corrcoef(x)
    r = np.nan_to_num(np.atleast_2d(r), nan=0.0)
    np.fill_diagonal(r, 1.0)
    share = np.sum(r[:, used] ** 2, axis=1)
    return np.where(used, 1.0 / share, 1.0)


def infer_frames(
    run: Callable[[int], Mapping[tuple[str, str], np.ndarray]],
    trials: Callable[[Mapping[tuple[str, str], np.ndarray]], pd.DataFrame] | None,
    items: Sequence[Mapping[str, Any]],
    n_avg: Sequence[int],
    eps: float,
) -> dict[str, pd.DataFrame]:
    """``n_profile``, ``n_rows`` and ``mc_trials_judged`` for the statistical ``items``:
    ``run(N)`` gives the Monte Carlo estimates at N, ``trials(estimates)`` their mc_trials
    frame (``trials`` None: no ``mc_trials_judged``, which the caller writes itself)."""
    grid = [int(n) for n in n_avg]
    estimates = {n: run(n) for n in grid}
    lo_band, hi_band = RANK_BAND
    shape = (len(items), len(grid))
    log_p, ranks, stats = np.full(shape, -math.inf), np.full(shape, np.nan), {}
    # per grid N the fewest finite trials any row is judged on (NaN trials are dropped and
    # counted as numerical trouble): n_profile's n_trials is the count actually used
    n_used = [min(np.size(v) for v in estimates[n].values()) for n in grid]
    for i, item in enumerate(items):
        key = (item["select"]["method"], item["quantity"])
        lo, hi = printed_interval(item["value"])
        for k, n in enumerate(grid):
            sample = np.asarray(estimates[n][key], dtype=float)
            sample = sample[np.isfinite(sample)]
            n_used[k] = min(n_used[k], sample.size)
            mean, std = float(np.mean(sample)), float(np.std(sample, ddof=1))
            ks = ks_statistic_norm((sample - mean) / std) if std > 0 else 1.0
            log_p[i, k] = interval_log_prob(mean, std, lo, hi)
            ranks[i, k] = percentile_rank(sample, float(item["value"]))
            stats[i, k] = (mean, std, ks)
    in_band = (ranks >= lo_band) & (ranks <= hi_band)
    used = in_band.any(axis=1)
    keys = [(item["select"]["method"], item["quantity"]) for item in items]
    share = row_weights([estimates[grid[-1]][k] for k in keys], used)
    log_lik = mixture_log_lik(log_p, eps)
    outlier = np.exp(np.log(eps) + log_p[:, :1] - log_lik)
    log_lik = share[:, None] * log_lik
    robust, plain = profile(log_lik, used), profile(share[:, None] * log_p, used)
    best = int(np.argmax(robust))
    weights = loo_weights(log_lik, used)
    rows = [
        (
            item["id"],
            item["select"]["method"],
            item["quantity"],
            item["value"],
            n,
            *stats[i, k],
            ranks[i, k],
            bool(in_band[i, k]),
            log_lik[i, k],
            share[i],
            outlier[i, k],
            bool(used[i]),
            weights[i, k],
        )
        for i, item in enumerate(items)
        for k, n in enumerate(grid)
    ]
    prof = pd.DataFrame(
        {
            "n_avg": grid,
            "log_lik": robust,
            "log_lik_gaussian": plain,
            "n_rows_used": int(used.sum()),
            "n_rows_in_band": in_band.sum(axis=0),
            "max_ks": [max(stats[i, k][2] for i in range(len(items))) for k in range(len(grid))],
            "n_trials": n_used,
            "inferred": [k == best for k in range(len(grid))],
        }
    )
    out = {
        "n_profile": prof[N_PROFILE_COLUMNS],
        "n_rows": pd.DataFrame(rows, columns=N_ROW_COLUMNS),
    }
    if trials is not None:
        parts = [trials(estimates[n]).assign(n_avg=n) for n in grid]
        mc = (
            pd.concat(parts, ignore_index=True)
            if parts
            else pd.DataFrame(columns=MC_JUDGED_COLUMNS)
        )
        out["mc_trials_judged"] = mc[MC_JUDGED_COLUMNS]
    return out
