"""The blocked Monte Carlo (pipeline/altimeter_attitude/mc_sums.py): the results files from
sums accumulated block by block equal those computed on the whole histories (the
metrics/windows/trouble functions), whatever the block size, and a block's runs are the same
runs as in one batch."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude import metrics, run, windows
from pipeline.altimeter_attitude.scenario import ROOT, build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.trouble import estimates_trouble, trouble_frame

PAPER = ROOT / "config" / "scenarios" / "altimeter_attitude" / "paper.yaml"


@pytest.fixture(scope="module")
def short():
    """The paper scenario cut to its first 25 s (pull-up included), transient 5 s."""
    base = load_scenario(PAPER)
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 25.0}}
    raw["trajectory"]["maneuvers"] = [
        m for m in base.raw["trajectory"]["maneuvers"] if m["start_s"] + m["duration_s"] <= 25.0
    ]
    raw["metrics"] = {**raw["metrics"], "transient_s": 5.0}
    return build_scenario(raw, base.path)


def _reference(sc, n):
    """The results frames computed on the whole histories (the pre-block code path)."""
    inputs, est, nf = run.simulate(sc, n, log=lambda m: None)
    first = int(round(sc.transient * sc.sensors.rate_hz))
    wins = windows.scenario_windows(sc)
    tr = inputs.truth
    rows = [r for e in est.values() for r in estimates_trouble(e, tr, "monte_carlo")]
    rows += [r for e in nf.values() for r in estimates_trouble(e, tr, "noise_free")]
    return {
        "rms_summary": run.summary_frame(sc, inputs, est),
        "noise_free": run.summary_frame(sc, inputs, nf),
        "run_rms": pd.concat(
            [metrics.run_rms_frame(e, tr, first) for e in est.values()], ignore_index=True
        ),
        "window_summary": windows.summary_frame(wins, est, tr),
        "window_run_rms": windows.run_frame(wins, est, tr),
        "timeseries": pd.concat(
            [metrics.timeseries_frame(e, tr, sc.output_every) for e in est.values()],
            ignore_index=True,
        ),
        "numerical_trouble": trouble_frame(rows),
    }


def _blocked(sc, n, block):
    _, mc, nf = run.simulate_sums(sc, n, log=lambda m: None, block=block)
    return {
        "rms_summary": mc.summary_frame(),
        "noise_free": nf.summary_frame(),
        "run_rms": mc.run_rms_frame(),
        "window_summary": mc.window_summary_frame(),
        "window_run_rms": mc.window_run_frame(),
        "timeseries": mc.timeseries_frame(sc.output_every),
        "numerical_trouble": trouble_frame(mc.trouble_rows() + nf.trouble_rows()),
    }


def _assert_frames_close(a: pd.DataFrame, b: pd.DataFrame, what: str, rtol: float) -> None:
    assert list(a.columns) == list(b.columns), what
    assert len(a) == len(b), what
    for col in a.columns:
        x, y = a[col].to_numpy(), b[col].to_numpy()
        if x.dtype.kind in "fc" or y.dtype.kind in "fc":
            x, y = x.astype(float), y.astype(float)
            assert np.array_equal(np.isnan(x), np.isnan(y)), f"{what}.{col}: NaN positions"
            np.testing.assert_allclose(x, y, rtol=rtol, atol=0.0, err_msg=f"{what}.{col}")
        else:
            assert list(x) == list(y), f"{what}.{col}"


def test_blocks_equal_whole_histories(short):
    """5 runs in blocks of 2 (3 blocks, the last short) give every results frame of the
    whole-history computation to 1e-12 relative (the sums only run in another order)."""
    ref = _reference(short, 5)
    got = _blocked(short, 5, 2)
    assert set(ref) == set(got)
    for key in ref:
        _assert_frames_close(ref[key], got[key], key, 1e-12)
    assert got["rms_summary"]["n_runs"].tolist() == [5] * len(got["rms_summary"])
    assert got["run_rms"]["run"].tolist() == list(range(5)) * len(got["rms_summary"])


def test_block_size_does_not_matter(short):
    """One block of 4 and blocks of 1: the same results to 1e-12 (and a metric that really
    differs between runs, so a mixed-up block would show)."""
    one = _blocked(short, 4, 4)
    many = _blocked(short, 4, 1)
    for key in one:
        _assert_frames_close(one[key], many[key], key, 1e-12)
    per_run = one["run_rms"].query("filter == 'ukf'")["roll_rms_deg"].to_numpy()
    assert np.ptp(per_run) > 1e-3 * per_run.max()


def test_first_run_offset_gives_the_same_runs(short):
    """Runs 2..4 drawn as a block equal runs 2..4 of one batch of 5, bit for bit."""
    sc = short
    whole = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 5, sc.seed, sc.name)
    part = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 3, sc.seed, sc.name, first_run=2)
    for name in ("gyro", "accel", "altimeter", "x0_euler"):
        assert np.array_equal(getattr(whole, name)[2:], getattr(part, name), equal_nan=True)
    with pytest.raises(ValueError, match="first_run = -1"):
        simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, first_run=-1)


def test_trouble_counts_equal_estimates_trouble_across_blocks(short):
    """Injected trouble (a NaN run, a run diverged beyond 45 deg, a zero sigma, a filter
    without sigma) counted from two blocks equals estimates_trouble on the whole history."""
    from pipeline.altimeter_attitude.estimates import Estimates
    from pipeline.altimeter_attitude.mc_sums import MonteCarloSums

    sc = short
    inputs, est, _ = run.simulate(sc, 5, filters=("ukf", "complementary"), log=lambda m: None)
    u = est["ukf"]
    roll, sigma = u.roll.copy(), u.roll_sigma.copy()
    roll[1, 100] = np.nan
    roll[3, 200:] += np.deg2rad(60.0)
    sigma[4, 50] = 0.0
    bad = Estimates("ukf", roll, u.pitch, sigma, u.pitch_sigma, u.c, u.norm_error)
    tr = inputs.truth
    first = int(round(sc.transient * sc.sensors.rate_hz))
    sums = MonteCarloSums(tr, first, windows.scenario_windows(sc))
    for e in (bad, est["complementary"]):
        for sl in (slice(0, 2), slice(2, 5)):
            sums.add(run._split(e, sl))
    want = estimates_trouble(bad, tr, "monte_carlo") + estimates_trouble(
        est["complementary"], tr, "monte_carlo"
    )
    assert sums.trouble_rows() == want
    counts = {r[3]: r[5] for r in want[:3]}
    assert counts == {"non_finite": 1, "diverged": 1, "sigma_not_positive": 1}


def test_accumulated_errors_are_the_float_mod_bit_for_bit():
    """_accumulate's wrapped errors (the argument itself where it lies in (0, 2 pi), ``%``
    elsewhere) are, bit for bit, ``(x + pi) % (2 pi) - pi`` of Python floats, at the edges
    too (0, -0, 2 pi, +-inf, NaN, far out of range)."""
    import math

    from pipeline.altimeter_attitude.mc_sums import _accumulate

    rng = np.random.default_rng(7)
    edges = [0.0, -0.0, math.pi, -math.pi, 2 * math.pi, -2 * math.pi, math.inf, -math.inf]
    edges += [math.nan, 1e-300, -1e-300, 3 * math.pi, 1e6, -1e6, math.nextafter(math.pi, 0.0)]
    est = np.concatenate([edges, rng.uniform(-20.0, 20.0, 2000)])
    n = est.size
    roll = est.reshape(1, n)
    ones = np.ones((1, n))
    block = np.zeros((10, n))
    run_ms = np.zeros((1, 1, 2))
    flags = np.zeros((1, 3), dtype=bool)
    _accumulate(
        roll, roll, ones, ones, np.zeros((1, n, 3)), np.zeros((1, n)), np.zeros(n), np.zeros(n),
        np.zeros((n, 3)), np.zeros(1, dtype=np.int64), 1.0, block, run_ms, flags,
        np.zeros(2, dtype=bool),
    )  # fmt: skip
    err = [(x + math.pi) % (2 * math.pi) - math.pi for x in est.tolist()]  # Python floats
    assert block[0].tobytes() == np.array([e * e for e in err]).tobytes()


def test_a_block_summed_batch_by_batch_has_the_bits_of_the_block_at_once(short):
    """block_sums continued with ``into`` over a block's runs in two batches (run order) gives
    the very bits of one pass over the block: the additions are the same, in the same order.
    Estimates of a per-run filter (the UKF) on 5 runs, split 3 + 2."""
    from pipeline.altimeter_attitude import euler_filters
    from pipeline.altimeter_attitude.mc_sums import block_sums

    sc = short
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 5, sc.seed, sc.name)
    est = euler_filters.run_ukf(inputs, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    _, mc, _ = run.new_sums(sc)
    n_times = len(mc.truth.t)
    whole = block_sums(est, mc.truth, mc.firsts, n_times)
    head, tail = (run._split(est, sl) for sl in (slice(0, 3), slice(3, 5)))
    parts = block_sums(head, mc.truth, mc.firsts, n_times)
    parts = block_sums(tail, mc.truth, mc.firsts, n_times, into=parts)
    for name in ("squares", "run_ms", "counts", "any_sigma"):
        assert np.array_equal(getattr(whole, name), getattr(parts, name)), name
        assert getattr(whole, name).tobytes() == getattr(parts, name).tobytes(), name
    # the sums of one filter cannot continue another's
    ekf = euler_filters.run_ekf(inputs)
    with pytest.raises(ValueError, match="cannot continue those of ukf"):
        block_sums(ekf, mc.truth, mc.firsts, n_times, into=parts)


def test_the_batch_changes_only_the_linear_kf(short):
    """Blocks run through the filters in batches of 2 or of 8 runs: every filter that treats
    each run alone (UKF, EKF, complementary, levelling) gives the same bits; the linear-KF
    variants (series length per batch) agree to 1e-12."""
    sc = short
    mcs = {}
    for batch in (2, 8):
        _, mc, _ = run.simulate_sums(sc, 6, log=lambda m: None, batch=batch)
        mcs[batch] = mc.summary_frame().set_index("filter")
    a, b = mcs[2], mcs[8]
    for f in ("ukf", "ekf", "complementary", "accel_leveling"):
        assert a.loc[f].to_numpy(float).tobytes() == b.loc[f].to_numpy(float).tobytes(), f
    lkf = ["linear_kf", "linear_kf_no_gamma", "gyro_only"]
    np.testing.assert_allclose(
        a.loc[lkf].to_numpy(float), b.loc[lkf].to_numpy(float), rtol=1e-12, equal_nan=True
    )
