"""The averaging count N at which the statistical rows are judged is inferred from the printed
values (pipeline/north_finding/n_inference.py): synthetic printed values drawn from our model at
a known N are recovered within one grid step and come out consistent; a value far outside every
N's distribution is not reproduced and excluded from the estimate; a row consistent at the N
that carry substantial leave-one-out weight is consistent even where the point maximum would
fail it; the leave-one-out and the robust (contamination) rule each change the answer where
they should."""

from __future__ import annotations

from functools import cache
from typing import Any

import numpy as np
import pandas as pd
import pytest

from pipeline.north_finding import readings as rd
from pipeline.north_finding.judged_n import judged_at, mixed_n
from pipeline.north_finding.n_inference import (
    infer_frames,
    loo_weights,
    mixture_log_lik,
    mixture_rank,
    printed_interval,
    profile,
)
from pipeline.north_finding.run import _Runner, scenario_key, trials_frame, truth_values
from pipeline.north_finding.scenario import load_scenario
from pipeline.north_finding.verdicts import load_published
from pipeline.verdicts.kinds import Found, judge

SCENARIO = "config/scenarios/north_finding/paper.yaml"
PUBLISHED = "config/published/north_finding.yaml"
GRID = [100, 316, 1000, 3162, 10000, 31623, 100000, 316228, 1000000, 3162278, 10000000]
N_TRIALS = 300


@cache
def _model() -> tuple[Any, Any, int]:
    sc = load_scenario(SCENARIO)
    return sc, _Runner(sc), rd.simulation_positions(sc)[0].size


@cache
def _run(n: int, seed_offset: int = 0, n_trials: int = N_TRIALS) -> dict:
    sc, runner, n_pos = _model()
    z = rd.standard_normals(sc.seed + seed_offset, scenario_key(sc.name), n_trials, n_pos)
    return runner.run((), z, n)


def _items() -> list[dict[str, Any]]:
    return [dict(i) for i in load_published(PUBLISHED)["items"] if i["kind"] == "statistical"]


def synthetic_items(n_true: int, seed_offset: int = 1) -> list[dict[str, Any]]:
    """The paper's statistical items with values printed from ONE independent trial of our model
    at ``n_true`` (every row from the same run, as a paper's table would be), 10 digits."""
    one = _run(n_true, seed_offset, 1)
    out = []
    for item in _items():
        v = float(one[item["select"]["method"], item["quantity"]][0])
        out.append({**item, "value": f"{v:.10g}"})
    return out


def infer(items: list[dict[str, Any]], eps: float = 0.1) -> dict[str, pd.DataFrame]:
    sc = _model()[0]
    truth = truth_values(sc)
    return infer_frames(_run, lambda e: trials_frame(e, truth), items, GRID, eps)


def best_n(frames: dict[str, pd.DataFrame]) -> int:
    prof = frames["n_profile"]
    return int(prof.loc[prof["inferred"], "n_avg"].iloc[0])


def weights_of(frames: dict[str, pd.DataFrame], item_id: str) -> pd.Series:
    """A row's leave-one-out weight per grid N."""
    rows = frames["n_rows"][frames["n_rows"]["id"] == item_id]
    return rows.set_index("n_avg")["weight"]


def heaviest(frames: dict[str, pd.DataFrame], item_id: str) -> int:
    w = weights_of(frames, item_id)
    return int(w.idxmax())


def results_of(frames: dict[str, pd.DataFrame], items: list[dict[str, Any]]) -> dict[str, Any]:
    return {
        "n_rows": frames["n_rows"],
        "mc_trials_judged": frames["mc_trials_judged"],
        "published": {"items": items, "claims": []},
    }


def verdict(frames: dict[str, pd.DataFrame], item: dict[str, Any]) -> str:
    at = judged_at(results_of(frames, [item]), item)
    assert at is not None
    return judge(item, Found(samples=at.samples, weights=at.weights)).verdict


# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n_true", [10000, 316228])
def test_known_n_is_recovered_within_one_grid_step_and_rows_are_consistent(n_true: int) -> None:
    items = synthetic_items(n_true)
    frames = infer(items)
    step = abs(GRID.index(best_n(frames)) - GRID.index(n_true))
    assert step <= 1, f"true N = {n_true}, inferred {best_n(frames)}"
    # every row's weight is concentrated within one grid step of the true N
    for item in items:
        w = weights_of(frames, item["id"])
        near = [n for n in GRID if abs(GRID.index(n) - GRID.index(n_true)) <= 1]
        assert w[near].sum() > 0.9, (item["id"], w.to_dict())
    assert [verdict(frames, i) for i in items] == ["consistent"] * len(items)


def test_the_papers_own_values_would_not_be_recovered_at_a_wrong_n() -> None:
    """The recovery test can fail: values drawn at 1e4 are not inferred at 1e6, and values
    drawn at 1e6 not at 1e4."""
    assert best_n(infer(synthetic_items(10000))) not in (1000000, 3162278)
    assert best_n(infer(synthetic_items(1000000))) not in (3162, 10000, 31623)


def test_a_value_far_outside_every_n_is_not_reproduced_and_excluded() -> None:
    items = synthetic_items(10000)
    clean = infer(items)
    far = [dict(i) for i in items]
    k = next(j for j, i in enumerate(far) if i["id"] == "T9.psi.A1c1")
    far[k]["value"] = "95.0000"  # 7 deg off: no N on the grid spreads psi that far
    frames = infer(far)
    rows = frames["n_rows"][frames["n_rows"]["id"] == "T9.psi.A1c1"]
    assert not rows["in_band"].any()
    assert not rows["used"].any()  # robust rule 1: excluded, says nothing about N
    assert verdict(frames, far[k]) == "not_reproduced"
    assert best_n(frames) == best_n(clean)
    # the excluded row is judged on the weights of all the other rows
    assert heaviest(frames, "T9.psi.A1c1") == best_n(frames)


def test_rows_our_model_cannot_place_do_not_drag_the_estimate() -> None:
    """Two rows (like the paper's method-4 levelling rows) sit 4 sigma of N = 1e3 off their
    noise-free value: noise at N <= 1e2 explains them, so rule 1 keeps them. With the
    contamination mixture the estimate from rows drawn at 1e6 stays within one grid step; with
    a vanishing contamination (the plain Gaussian) the two rows drag it down."""
    items = synthetic_items(1000000)
    spread = {k: float(np.std(v, ddof=1)) for k, v in _run(1000).items()}
    mean = {k: float(np.mean(v)) for k, v in _run(1000).items()}
    for item in items:
        if item["id"] in ("T1.phi.L4", "T2.theta.L4"):
            key = (item["select"]["method"], item["quantity"])
            item["value"] = f"{mean[key] + 4.0 * spread[key]:.10g}"
    robust = infer(items, eps=0.1)
    plain = infer(items, eps=1e-300)
    assert frames_used(robust, "T1.phi.L4")
    assert abs(GRID.index(best_n(robust)) - GRID.index(1000000)) <= 1
    assert GRID.index(best_n(plain)) < GRID.index(1000000) - 1


def frames_used(frames: dict[str, pd.DataFrame], item_id: str) -> bool:
    return bool(frames["n_rows"].loc[frames["n_rows"]["id"] == item_id, "used"].all())


def test_leave_one_out_weights_a_row_by_the_n_of_the_others() -> None:
    """A row that alone prefers a small N puts its weight where the others imply; a model where
    each row judged itself (the full estimate) would put it at its own N."""
    ll = np.log(
        np.array(
            [
                [0.9, 0.01, 0.001],  # row 0: strongly at N_0
                [0.1, 0.5, 0.2],
                [0.1, 0.45, 0.4],
            ]
        )
    )
    used = np.ones(3, dtype=bool)
    assert int(np.argmax(profile(ll, used))) == 0  # row 0 carries the full estimate
    w = loo_weights(ll, used)
    assert np.argmax(w, axis=1).tolist() == [1, 0, 0]
    assert w.sum(axis=1) == pytest.approx(np.ones(3))
    # row 0's weights are the normalised likelihood of rows 1 and 2 alone
    others = np.exp(ll[1] + ll[2])
    assert w[0] == pytest.approx(others / others.sum())


def _fake_frames(cases: dict[str, tuple[str, str, str]], shift: tuple[float, float]):
    """A two-point grid (N = 100, 1000) on synthetic trials, through infer_frames: row ``t``
    is standard normal at N = 100 and 0.1 x that at N = 1000; row ``o1`` is standard normal
    shifted by ``shift`` (at N = 100, at N = 1000), so its printed "0.0" sets how much the
    other rows prefer one N; row ``o2`` is the same at both N (no preference). The three rows
    draw independent normals (uncorrelated rows: each weighs fully in the likelihood)."""
    base = {k: np.random.default_rng(seed).standard_normal(1000) for k, seed in (("t", 7), ("o1", 8), ("o2", 9))}  # fmt: skip

    def run(n: int) -> dict:
        return {
            ("M", "t"): base["t"] * {100: 1.0, 1000: 0.1}[n],
            ("M", "o1"): base["o1"] + shift[n == 1000],
            ("M", "o2"): base["o2"],
        }

    def trials(est: dict) -> pd.DataFrame:
        return pd.concat(
            [
                pd.DataFrame(
                    {
                        "trial": np.arange(v.size),
                        "method": m,
                        "quantity": q,
                        "truth": 0.0,
                        "estimate": v,
                        "error_pct": 0.0,
                    }
                )
                for (m, q), v in est.items()
            ],
            ignore_index=True,
        )

    items = [
        {
            "id": name,
            "kind": "statistical",
            "label": name,
            "select": {"method": "M"},
            "quantity": q,
            "value": value,
        }  # fmt: skip
        for name, q, value in cases.values()
    ]
    return infer_frames(run, trials, items, [100, 1000], 0.1), items


def test_a_row_consistent_where_the_weight_is_is_consistent_though_the_point_max_fails_it():
    """Flat two-point profile: the other rows favour N = 1000 by a few hundredths of a nat.
    The row under test is noise at N = 100 (rank ~84) and far out at N = 1000 (rank 100): the
    point maximum (N = 1000) would fail it; in the mixture (weights ~0.49 / 0.51) its rank is
    ~92: consistent."""
    cases = {
        "t": ("t", "t", "1.0"),
        "o1": ("o1", "o1", "0.0"),
        "o2": ("o2", "o2", "0.0"),
    }
    frames, items = _fake_frames(cases, (0.316, 0.0))
    rows = frames["n_rows"]
    w = weights_of(frames, "t")
    assert 0.3 < w[100] < 0.5 < w[1000] < 0.7  # a near-tie, the maximum at N = 1000
    ranks = rows[rows["id"] == "t"].set_index("n_avg")["rank_pct"]
    assert ranks[1000] > 99.5 and 0.5 < ranks[100] < 99.5
    t = items[0]
    at = judged_at(results_of(frames, items), t)
    assert at is not None and at.weight_by_n.keys() == {100, 1000}
    assert at.rank == pytest.approx(float(mixture_rank(w.to_numpy(), ranks.to_numpy())))
    assert verdict(frames, t) == "consistent"
    # the point maximum would fail it: judged on the trials at N = 1000 alone
    point = frames["mc_trials_judged"]
    alone = point[(point["n_avg"] == 1000) & (point["quantity"] == "t")]["estimate"].to_numpy()
    assert judge(t, Found(samples=alone)).verdict == "not_reproduced"
    assert mixed_n(results_of(frames, items), t) is None


def test_a_row_far_outside_every_n_still_fails_in_the_mixture() -> None:
    cases = {
        "t": ("t", "t", "9.0"),  # 9 sd of N = 100 out: rank 100 at both N
        "o1": ("o1", "o1", "0.0"),
        "o2": ("o2", "o2", "0.0"),
    }
    frames, items = _fake_frames(cases, (0.316, 0.0))
    assert verdict(frames, items[0]) == "not_reproduced"


def test_the_mixture_fails_a_row_the_weight_puts_where_it_is_not_noise() -> None:
    """The other rows strongly favour N = 1000 (o1's printed 0.0 is 3 sd off at N = 100): the
    row that is noise only at N = 100 gets (almost) no weight there and fails, with the cause
    that no one N fits every row."""
    cases = {
        "t": ("t", "t", "1.0"),
        "o1": ("o1", "o1", "0.0"),
        "o2": ("o2", "o2", "0.0"),
    }
    frames, items = _fake_frames(cases, (3.0, 0.0))
    w = weights_of(frames, "t")
    assert w[1000] > 0.95
    assert verdict(frames, items[0]) == "not_reproduced"
    cause = mixed_n(results_of(frames, items), items[0])
    assert cause is not None and "t, method M is consistent" in cause.text


def test_leave_one_out_on_the_model_weights_the_n_of_the_others_where_a_row_pulls() -> None:
    """On our model: a row given a value far in the tail at large N (but noise at small N)
    is judged on the weights of the other rows (their profile) and fails there, with the cause
    that no one N fits every row."""
    keep = ("T9.psi.A1c1", "T11.gyro_scale.A4", "T10.gyro_bias.A4")  # few rows: a flat profile
    items = [i for i in synthetic_items(1000000) if i["id"] in keep]
    k = next(j for j, i in enumerate(items) if i["id"] == "T10.gyro_bias.A4")
    key = ("A4", "gyro_bias_rad_s")
    v = _run(3162)[key]
    items[k]["value"] = f"{float(np.mean(v)) + 2.0 * float(np.std(v, ddof=1)):.10g}"
    frames = infer(items, eps=1e-6)
    assert heaviest(frames, "T10.gyro_bias.A4") != best_n(frames)  # the row pulls the estimate
    others = profile(
        frames["n_rows"]
        .pivot(index="id", columns="n_avg", values="log_lik")
        .drop(index=items[k]["id"])
        .to_numpy(),  # fmt: skip
        np.ones(len(items) - 1, dtype=bool),
    )
    expect = np.exp(others - others.max())
    expect /= expect.sum()
    expect[expect < 1e-6] = 0.0
    assert weights_of(frames, "T10.gyro_bias.A4").to_numpy() == pytest.approx(
        expect / expect.sum(), abs=1e-12
    )
    assert verdict(frames, items[k]) == "not_reproduced"
    cause = mixed_n(results_of(frames, items), items[k])
    assert cause is not None and f"{items[k]['label']}, " in cause.text
    assert "T10.gyro_bias.A4" not in cause.text  # readers get labels, not ids


def test_mixture_bounds_a_rows_cost_by_log_one_over_eps() -> None:
    log_p = np.log(np.array([[0.5, 0.1, 1e-200]]))
    ll = mixture_log_lik(log_p, 0.1)
    assert ll[0, 0] == pytest.approx(np.log(0.5))
    assert ll[0, 0] - ll[0, 2] == pytest.approx(np.log(10.0), rel=1e-9)


def test_printed_interval_covers_rounding_and_truncation() -> None:
    lo, hi = printed_interval("88.4420")
    assert lo == pytest.approx(88.44195, abs=1e-12) and hi == pytest.approx(88.4421, abs=1e-12)
    assert not lo <= 88.4419 < hi and not lo <= 88.4422 < hi


def test_inference_is_deterministic() -> None:
    items = synthetic_items(10000)
    a, b = infer(items), infer(items)
    for key in a:
        pd.testing.assert_frame_equal(a[key], b[key])


def test_the_papers_own_value_passes_in_its_mixture_and_a_wrong_one_fails() -> None:
    items = _items()
    frames = infer(items)
    a1 = next(i for i in items if i["id"] == "T9.psi.A1c1")
    assert verdict(frames, a1) == "consistent"  # the paper's 88.0012 deg
    wrong = {**a1, "value": "88.0100"}  # 0.01 deg off: outside the spread where the weight is
    assert verdict(frames, wrong) == "not_reproduced"


def test_the_report_shows_the_inferred_n_and_the_profile(tmp_path) -> None:
    from pipeline.north_finding.report_n import n_inference_section

    frames = infer(synthetic_items(10000))
    (tmp_path / "paper").mkdir()
    for name in ("n_profile", "n_rows"):
        frames[name].to_csv(tmp_path / "paper" / f"{name}.csv", index=False)
    section = n_inference_section(tmp_path, "paper", str)
    best = best_n(frames)
    text = section.blocks[0].text
    from pipeline.north_finding.n_inference import fmt_grid

    assert f"All rows together imply N = {fmt_grid(best)} samples" in text
    # where each row's leave-one-out weight lies, grouped by range, every row counted once
    assert "Where 90 % of the weight lies: N " in text
    counts = [int(c) for c in __import__("re").findall(r" for (\d+) rows?\b", text)]
    assert sum(counts) == len({i["id"] for i in _items()})
    table = section.blocks[1]
    assert [r[0] for r in table.rows] == [fmt_grid(n) for n in GRID]
    assert [r[-1] for r in table.rows].count("yes") == 1
    assert table.rows[GRID.index(best)][-1] == "yes"
    absent = n_inference_section(tmp_path, "missing", str)
    assert "not available" in str(absent.blocks[0]).lower()


@pytest.mark.parametrize(
    ("block", "needles"),
    [
        ({"n_avg": [1000, 100, 10000], "contamination": 0.1}, ["n_inference.n_avg", "ascending"]),
        ({"n_avg": [100, 1000, 10000], "contamination": 1.5}, ["contamination", "1.5"]),
        ({"n_avg": [100, 1000], "contamination": 0.1}, ["n_avg"]),
    ],
)
def test_a_bad_n_inference_block_is_refused_naming_file_field_and_value(
    tmp_path, block: dict, needles: list[str]
) -> None:
    import yaml

    from pipeline.config import ConfigError

    raw = yaml.safe_load(open(SCENARIO, encoding="utf-8"))
    raw["n_inference"] = block
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(raw), encoding="utf-8")
    with pytest.raises(ConfigError) as info:
        load_scenario(path)
    message = str(info.value)
    assert str(path) in message or "bad.yaml" in message
    for needle in needles:
        assert needle in message, message


def test_correlated_rows_share_their_vote_in_the_likelihood() -> None:
    """Rows whose trials are the same (r = 1) count once in all: three copies of one row weigh
    1/3 each, an uncorrelated row fully, and the profile is what one copy alone gives."""
    rng = np.random.default_rng(11)
    same, other = rng.standard_normal(1000), rng.standard_normal(1000)

    def run(n: int) -> dict:
        scale = {100: 1.0, 1000: 0.1}[n]
        return {**{("M", f"c{k}"): same * scale for k in range(3)}, ("M", "u"): other * scale}

    def trials(est: dict) -> pd.DataFrame:
        return pd.concat(
            [pd.DataFrame({"trial": np.arange(v.size), "method": m, "quantity": q, "truth": 0.0,
                           "estimate": v, "error_pct": 0.0}) for (m, q), v in est.items()],
            ignore_index=True,
        )  # fmt: skip

    def item(q: str) -> dict[str, Any]:
        return {"id": q, "kind": "statistical", "label": q, "select": {"method": "M"},
                "quantity": q, "value": "0.5"}  # fmt: skip

    copies = infer_frames(run, trials, [item(f"c{k}") for k in range(3)] + [item("u")], [100, 1000], 0.1)  # fmt: skip
    one = infer_frames(run, trials, [item("c0"), item("u")], [100, 1000], 0.1)
    weight = copies["n_rows"].drop_duplicates("id").set_index("id")["row_weight"]
    assert weight[["c0", "c1", "c2"]].tolist() == pytest.approx([1 / 3] * 3, abs=1e-2)
    assert weight["u"] == pytest.approx(1.0, abs=1e-2)
    assert copies["n_profile"]["log_lik"].to_numpy() == pytest.approx(
        one["n_profile"]["log_lik"].to_numpy(), rel=2e-2
    )
