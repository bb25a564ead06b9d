"""Monte Carlo metrics accumulated block by block: no run's history is kept past its block.

:func:`pipeline.altimeter_attitude.run.run_scenario` runs the Monte Carlo in blocks of
:data:`BLOCK_RUNS` runs; after each filter of a block, :meth:`MonteCarloSums.add` folds its
estimates into sums over runs, per state time, of the squares every results file is made of:

    S_e2[k]    = sum_runs e_k^2            (roll, pitch: RMS over runs and times)
    S_s2[k]    = sum_runs sigma_k^2        (the filter's own sigma, RMS over runs)
    S_nees[k]  = sum_runs (e_k / sigma_k)^2
    S_c2[k]    = sum_runs (c_k - c_true,k)^2 per component,  S_n2[k] = sum_runs gamma_k^2

plus, per run, the RMS over time from each window's first state (run_rms.csv,
window_run_rms.csv) and the numerical-trouble counts. Memory is O(T) per filter, plus one
block's histories, whatever the number of runs. The statistics are those of
:mod:`pipeline.altimeter_attitude.metrics`, :mod:`windows` and :mod:`trouble` on the whole
history, the sums only taken in another order (a few ulps; tests compare to 1e-12).

A block's contribution is a :class:`BlockSums` (:func:`block_sums`), folded in by
:meth:`MonteCarloSums.fold`; the workflow's chunk jobs write them to files and the merge folds
them in the same order (:mod:`pipeline.altimeter_attitude.chunks`: the same bytes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import jit
from pipeline.altimeter_attitude.chunk_plan import BLOCK_RUNS
from pipeline.altimeter_attitude.columns import (
    RMS_SUMMARY_COLUMNS,
    RUN_RMS_COLUMNS,
    TIMESERIES_COLUMNS,
    WINDOW_RUN_RMS_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
)
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.metrics import RAD2DEG
from pipeline.altimeter_attitude.trajectory import Truth
from pipeline.altimeter_attitude.trouble import DIVERGED_DEG, TROUBLE_KINDS
from pipeline.altimeter_attitude.windows import Window

__all__ = ["BLOCK_RUNS", "BlockSums", "FilterSums", "MonteCarloSums", "block_sums"]


_SQUARES = ("er2", "ep2", "rs2", "ps2", "nees_r", "nees_p", "c1", "c2", "c3", "n2")


@jit.kernel
def _accumulate(
    roll, pitch, rs, ps, c, ne, t_roll, t_pitch, t_c, firsts, far, block, run_ms, flags, any_sigma
):
    """One pass over a block's histories (N, T + 1): per state time the sums over runs (in
    run order, as numpy's sum over axis 0) of _SQUARES into ``block``; per run and window
    start the mean square error ``run_ms`` (N, F, 2); per run the trouble kinds ``flags``
    (non-finite, diverged beyond ``far`` rad, sigma not positive); ``any_sigma`` = (some roll
    sigma not NaN, some roll or pitch sigma not NaN). Errors wrapped as metrics.angle_errors:
    e = (est - true + pi) mod 2 pi - pi, the mod taken as the argument itself where it lies in
    (0, 2 pi): what Python's (and numba's) float ``%`` returns there (fmod is exact; a nonzero
    result with the divisor's sign is kept), without the call to libm's fmod (~1/2 of this
    kernel's time); anything else (0, -0, NaN, out of range) takes ``%``."""
    n, t1 = roll.shape
    pi, two_pi = np.pi, 2 * np.pi
    for i in range(n):
        for k in range(t1):
            ar = roll[i, k] - t_roll[k] + pi
            ap = pitch[i, k] - t_pitch[k] + pi
            er = (ar if 0.0 < ar < two_pi else ar % two_pi) - pi
            ep = (ap if 0.0 < ap < two_pi else ap % two_pi) - pi
            sr, sp = rs[i, k], ps[i, k]
            qr, qp = er / sr, ep / sp
            d0, d1, d2 = c[i, k, 0] - t_c[k, 0], c[i, k, 1] - t_c[k, 1], c[i, k, 2] - t_c[k, 2]
            block[0, k] += er * er
            block[1, k] += ep * ep
            block[2, k] += sr * sr
            block[3, k] += sp * sp
            block[4, k] += qr * qr
            block[5, k] += qp * qp
            block[6, k] += d0 * d0
            block[7, k] += d1 * d1
            block[8, k] += d2 * d2
            block[9, k] += ne[i, k] * ne[i, k]
            for j in range(firsts.shape[0]):
                if k >= firsts[j]:
                    run_ms[i, j, 0] += er * er
                    run_ms[i, j, 1] += ep * ep
            if not (math.isfinite(roll[i, k]) and math.isfinite(pitch[i, k])):
                flags[i, 0] = True
            if (math.isfinite(er) and abs(er) > far) or (math.isfinite(ep) and abs(ep) > far):
                flags[i, 1] = True
            if not (math.isfinite(sr) and sr > 0.0 and math.isfinite(sp) and sp > 0.0):
                flags[i, 2] = True
            if not math.isnan(sr):
                any_sigma[0] = True
                any_sigma[1] = True
            elif not math.isnan(sp):
                any_sigma[1] = True
        for j in range(firsts.shape[0]):
            run_ms[i, j, 0] /= t1 - firsts[j]
            run_ms[i, j, 1] /= t1 - firsts[j]


@dataclass(frozen=True)
class BlockSums:
    """What one block of runs of one filter adds to its :class:`FilterSums`: ``squares``
    (len(_SQUARES), T + 1), the block's sums over runs per state time; ``run_ms`` (n, F, 2),
    per run and window start the mean square roll and pitch error; ``counts`` (3,), the runs
    of each trouble kind; ``any_sigma`` (2,), some roll sigma / some roll or pitch sigma not
    NaN."""

    filter: str
    firsts: tuple[int, ...]
    squares: np.ndarray
    run_ms: np.ndarray
    counts: np.ndarray
    any_sigma: np.ndarray

    @property
    def n_runs(self) -> int:
        return int(self.run_ms.shape[0])


def block_sums(
    est: Estimates,
    truth: Truth,
    firsts: tuple[int, ...],
    n_times: int,
    into: BlockSums | None = None,
) -> BlockSums:
    """One block's :class:`BlockSums` (one pass of :func:`_accumulate` over its histories).

    ``into``: the sums of the block's earlier runs (a batch before this one, same filter),
    continued: :func:`_accumulate` adds run after run into the same sums, so a block summed
    batch by batch, in run order, has the same bits as the block summed at once."""
    n, t1 = est.roll.shape
    if t1 != n_times:
        raise ValueError(f"{est.filter}: {t1} state times, expected {n_times}")
    if into is not None and (into.filter, into.firsts) != (est.filter, tuple(firsts)):
        raise ValueError(
            f"{est.filter} sums from window starts {tuple(firsts)} cannot continue those of "
            f"{into.filter} from {into.firsts}"
        )
    block = np.zeros((len(_SQUARES), t1)) if into is None else into.squares
    any_sigma = np.zeros(2, dtype=bool) if into is None else into.any_sigma
    run_ms = np.zeros((n, len(firsts), 2))
    flags = np.zeros((n, 3), dtype=bool)
    f = np.ascontiguousarray
    _accumulate(
        f(est.roll), f(est.pitch), f(est.roll_sigma), f(est.pitch_sigma), f(est.c),
        f(est.norm_error), f(truth.roll), f(truth.pitch), f(truth.c),
        np.asarray(firsts, dtype=np.int64), np.deg2rad(DIVERGED_DEG),
        block, run_ms, flags, any_sigma,
    )  # fmt: skip
    counts = flags.sum(axis=0).astype(np.int64)
    if into is not None:
        run_ms, counts = np.concatenate([into.run_ms, run_ms]), into.counts + counts
    return BlockSums(est.filter, tuple(firsts), block, run_ms, counts, any_sigma)


@dataclass
class FilterSums:
    """The running sums of one filter (arrays over the T + 1 state times)."""

    filter: str
    n_times: int
    n_runs: int = 0
    sums: dict[str, np.ndarray] = field(default_factory=dict)
    run_rms: dict[int, list[np.ndarray]] = field(default_factory=dict)  # first -> [(n, 2)]
    trouble: dict[str, int] = field(default_factory=dict)
    sigma_blocks: int = 0  # blocks in which some roll sigma is not NaN
    nan_sigma_runs: int = 0  # runs of blocks whose roll and pitch sigmas are all NaN

    def add(self, est: Estimates, truth: Truth, firsts: tuple[int, ...]) -> None:
        """Fold one block's estimates in (blocks in run order)."""
        self.fold(block_sums(est, truth, firsts, self.n_times))

    def fold(self, part: BlockSums) -> None:
        """Fold one block's sums in: the same additions, in the same order, whether the block
        was just computed or read back from a chunk file (pipeline/altimeter_attitude/chunks.py)."""
        if part.filter != self.filter or part.squares.shape != (len(_SQUARES), self.n_times):
            raise ValueError(
                f"block sums of {part.filter} over {part.squares.shape[-1]} state times: "
                f"expected {self.filter} over {self.n_times}"
            )
        n = part.n_runs
        for j, key in enumerate(_SQUARES):
            block = part.squares[j]
            self.sums[key] = block if key not in self.sums else self.sums[key] + block
        for j, first in enumerate(part.firsts):
            self.run_rms.setdefault(first, []).append(RAD2DEG * np.sqrt(part.run_ms[:, j]))
        self.sigma_blocks += bool(part.any_sigma[0])
        # trouble.estimates_trouble: a filter whose sigmas are all NaN has no covariance
        if not part.any_sigma[1]:
            self.nan_sigma_runs += n
        for j, kind in enumerate(TROUBLE_KINDS):
            self.trouble[kind] = self.trouble.get(kind, 0) + int(part.counts[j])
        self.n_runs += n

    @property
    def has_sigma(self) -> bool:
        return self.sigma_blocks > 0

    def summary_row(self, first: int) -> dict:
        """The :func:`metrics.summary_row` of the whole Monte Carlo from state ``first``."""
        count = self.n_runs * (self.n_times - first)

        def mean(key: str) -> float:
            return float(np.sum(self.sums[key][first:]) / count)

        sig = self.has_sigma
        row = {
            "filter": self.filter,
            "roll_rms_deg": RAD2DEG * math.sqrt(mean("er2")),
            "pitch_rms_deg": RAD2DEG * math.sqrt(mean("ep2")),
            "roll_sigma_deg": RAD2DEG * math.sqrt(mean("rs2")) if sig else math.nan,
            "pitch_sigma_deg": RAD2DEG * math.sqrt(mean("ps2")) if sig else math.nan,
            "nees_roll": mean("nees_r") if sig else math.nan,
            "nees_pitch": mean("nees_p") if sig else math.nan,
            "n_runs": self.n_runs,
        }
        return {k: row[k] for k in RMS_SUMMARY_COLUMNS}

    def run_frame(self, first: int) -> pd.DataFrame:
        rms = np.concatenate(self.run_rms[first])
        frame = pd.DataFrame(
            {
                "run": np.arange(rms.shape[0]),
                "filter": self.filter,
                "roll_rms_deg": rms[:, 0],
                "pitch_rms_deg": rms[:, 1],
            }
        )
        return frame[RUN_RMS_COLUMNS]

    def timeseries(self, truth: Truth, every: int) -> pd.DataFrame:
        """:func:`metrics.timeseries_frame` from the sums."""
        idx = np.arange(0, self.n_times, every)
        n = self.n_runs

        def rms(key: str) -> np.ndarray:
            return np.sqrt(self.sums[key][idx] / n)

        frame = pd.DataFrame(
            {
                "t_s": truth.t[idx],
                "filter": self.filter,
                "roll_rms_deg": RAD2DEG * rms("er2"),
                "pitch_rms_deg": RAD2DEG * rms("ep2"),
                "roll_sigma_deg": RAD2DEG * rms("rs2"),
                "pitch_sigma_deg": RAD2DEG * rms("ps2"),
                "c1_rms": rms("c1"),
                "c2_rms": rms("c2"),
                "c3_rms": rms("c3"),
                "norm_error_rms": rms("n2"),
                "nees_roll": self.sums["nees_r"][idx] / n,
                "nees_pitch": self.sums["nees_p"][idx] / n,
            }
        )
        return frame[TIMESERIES_COLUMNS]

    def trouble_counts(self) -> dict[str, int]:
        out = dict(self.trouble)
        if self.nan_sigma_runs == self.n_runs:
            out["sigma_not_positive"] = 0  # a filter without a covariance
        return out


@dataclass
class MonteCarloSums:
    """Every filter's :class:`FilterSums` of one Monte Carlo (the results of run.py)."""

    truth: Truth
    first: int  # state index after the transient (rms_summary.csv, run_rms.csv)
    windows: tuple[Window, ...]
    run_kind: str = "monte_carlo"
    order: tuple[str, ...] = ()  # the filters' order in the results files
    filters: dict[str, FilterSums] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name in self.order:
            self.filters[name] = FilterSums(name, len(self.truth.t))

    @property
    def firsts(self) -> tuple[int, ...]:
        return tuple(dict.fromkeys([self.first, *(w.first for w in self.windows if w.defined)]))

    def add(self, est: Estimates) -> None:
        """Fold one block's estimates of one filter in (blocks in run order)."""
        sums = self.filters.get(est.filter)
        if sums is None:
            sums = self.filters[est.filter] = FilterSums(est.filter, len(self.truth.t))
        sums.add(est, self.truth, self.firsts)

    def block_sums(self, est: Estimates, into: BlockSums | None = None) -> BlockSums:
        """One block's sums of one filter, not folded in (a chunk job writes them);
        ``into``: the block's sums so far, continued (:func:`block_sums`)."""
        return block_sums(est, self.truth, self.firsts, len(self.truth.t), into)

    def fold(self, part: BlockSums) -> None:
        """Fold one block's sums in (blocks in run order), as :meth:`add` does."""
        if part.firsts != self.firsts:
            raise ValueError(
                f"block sums of {part.filter} from window starts {part.firsts}: "
                f"expected {self.firsts}"
            )
        sums = self.filters.get(part.filter)
        if sums is None:
            sums = self.filters[part.filter] = FilterSums(part.filter, len(self.truth.t))
        sums.fold(part)

    def summary_frame(self) -> pd.DataFrame:
        rows = [s.summary_row(self.first) for s in self.filters.values()]
        return pd.DataFrame(rows, columns=RMS_SUMMARY_COLUMNS)

    def run_rms_frame(self) -> pd.DataFrame:
        frames = [s.run_frame(self.first) for s in self.filters.values()]
        return pd.concat(frames, ignore_index=True)

    def timeseries_frame(self, every: int) -> pd.DataFrame:
        frames = [s.timeseries(self.truth, every) for s in self.filters.values()]
        return pd.concat(frames, ignore_index=True)

    def window_summary_frame(self) -> pd.DataFrame:
        """window_summary.csv (:func:`windows.summary_frame` from the sums)."""
        rows = []
        for w in self.windows:
            for s in self.filters.values():
                if w.defined:
                    row = s.summary_row(w.first)
                else:
                    row = {c: math.nan for c in RMS_SUMMARY_COLUMNS}
                    row.update(filter=s.filter, n_runs=s.n_runs)
                rows.append({"window": w.name, "t_start_s": w.start, "t_end_s": w.end, **row})
        return pd.DataFrame(rows, columns=WINDOW_SUMMARY_COLUMNS)

    def window_run_frame(self) -> pd.DataFrame:
        """window_run_rms.csv (:func:`windows.run_frame` from the per-run RMS)."""
        parts = []
        for w in self.windows:
            for s in self.filters.values():
                if w.defined:
                    frame = s.run_frame(w.first)
                else:
                    frame = pd.DataFrame(
                        {"run": np.arange(s.n_runs), "filter": s.filter, "roll_rms_deg": math.nan}
                    )
                    frame["pitch_rms_deg"] = math.nan
                parts.append(frame[RUN_RMS_COLUMNS].assign(window=w.name))
        return pd.concat(parts, ignore_index=True)[WINDOW_RUN_RMS_COLUMNS]

    def trouble_rows(self) -> list[tuple]:
        from pipeline.trouble import trouble_rows

        rows: list[tuple] = []
        for s in self.filters.values():
            rows += trouble_rows(self.run_kind, "", s.filter, s.n_runs, s.trouble_counts())
        return rows
