"""The per-trial results in their two forms (pipeline/north_finding/trials_file.py): the binary
form gives the CSV's frame, statistics, verdicts and figures bit for bit; the shipped scenarios
keep the CSV; a bad binary file is refused naming the file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.north_finding import trials_file as tf
from pipeline.north_finding.figures import run as figures_run
from pipeline.north_finding.paper import PAPER, trials_files
from pipeline.north_finding.report_results import scenario_section
from pipeline.north_finding.run import run_scenario
from pipeline.north_finding.run_inference import infer_scenario
from pipeline.north_finding.scenario import ROOT, scenario_trials_format
from pipeline.north_finding.verdicts import write_verdicts
from pipeline.registry import context

PAPER_YAML = ROOT / "config" / "scenarios" / "north_finding" / "paper.yaml"
PUBLISHED = ROOT / "config" / "published" / "north_finding.yaml"
#: every file of a scenario's folder the steps below write, besides the per-trial ones
SAME = (
    "estimates.csv",
    "mc_summary.csv",
    "error_budget.csv",
    "sensitivity.csv",
    "ranking.csv",
    "ranking_pairs.csv",
    "numerical_trouble.csv",
    "n_profile.csv",
    "n_rows.csv",
    "n_robustness.csv",
    "n_trouble.csv",
)


def _small(directory: Path, form: str, n_trials: int = 40) -> Path:
    """The paper scenario (same name: same seeds) with few trials, short grids, in ``form``."""
    raw = yaml.safe_load(PAPER_YAML.read_text(encoding="utf-8"))
    raw["monte_carlo"] |= {"n_trials": n_trials, "trials_file": form}
    raw["sensitivity"] = {"n_avg": [10_000, 1_000_000], "n_trials": 20}
    raw["ranking"] = {"n_avg": [100, raw["averaging"]["n_samples"]], "n_trials": n_trials}
    raw["n_inference"]["n_avg"] = [100, 10_000, 1_000_000, 100_000_000]
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "paper.yaml"
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return path


def _quiet(_msg: str) -> None:
    pass


def _all_steps(base: Path, form: str) -> Path:
    sc = _small(base / f"cfg_{form}", form)
    out = base / form / "paper"
    run_scenario(sc, out, log=_quiet)
    infer_scenario(sc, PUBLISHED, out, log=_quiet)
    write_verdicts(PUBLISHED, out, base / form / "verdicts.csv", sc, sensitivity_out=base / form / "n_sens.csv")  # fmt: skip
    figures_run(out, PUBLISHED, base / form / "figures")
    return base / form


@pytest.fixture(scope="module")
def both(tmp_path_factory) -> tuple[Path, Path]:
    base = tmp_path_factory.mktemp("forms")
    return _all_steps(base, "csv"), _all_steps(base, "npy")


def test_each_form_writes_only_its_files(both) -> None:
    csv, npy = both
    for stem in tf.COLUMNS:
        assert [p.name for p in tf.existing(csv / "paper", stem)] == [f"{stem}.csv"]
        assert [p.name for p in tf.existing(npy / "paper", stem)] == [f"{stem}.npy"]
    # the binary form is the smaller: 8 bytes a value against a CSV row of ~65
    assert (npy / "paper" / "mc_trials_judged.npy").stat().st_size < (
        csv / "paper" / "mc_trials_judged.csv"
    ).stat().st_size / 4


def test_binary_form_reads_as_the_csv_frame(both) -> None:
    csv, npy = both
    for stem in tf.COLUMNS:
        a, b = tf.read_trials(csv / "paper", stem), tf.read_trials(npy / "paper", stem)
        assert len(a) > 0
        pd.testing.assert_frame_equal(a, b, check_exact=True)


def test_binary_form_gives_the_same_statistics_verdicts_and_figures(both) -> None:
    csv, npy = both
    for name in SAME:
        assert (csv / "paper" / name).read_bytes() == (npy / "paper" / name).read_bytes(), name
    for name in ("verdicts.csv", "n_sens.csv"):
        assert (csv / name).read_bytes() == (npy / name).read_bytes(), name
    figs = sorted(p.name for p in (csv / "figures").iterdir())
    assert figs and figs == sorted(p.name for p in (npy / "figures").iterdir())
    for name in figs:
        assert (csv / "figures" / name).read_bytes() == (npy / "figures" / name).read_bytes(), name
    verdicts = pd.read_csv(csv / "verdicts.csv")
    assert (verdicts["kind"] == "statistical").sum() > 0  # the trials were judged


def test_report_names_the_form(both) -> None:
    csv, npy = both
    text = {f: str(scenario_section(d / "paper")) for f, d in (("csv", csv), ("npy", npy))}
    assert "mc_trials.csv: 40 trials" in text["csv"] and "mc_trials.npy" not in text["csv"]
    assert "mc_trials.npy: 40 trials" in text["npy"]


def test_binary_form_is_byte_identical_across_runs(tmp_path: Path, both) -> None:
    _, npy = both
    sc = _small(tmp_path / "cfg", "npy")
    run_scenario(sc, tmp_path / "again", log=_quiet)
    assert (tmp_path / "again" / "mc_trials.npy").read_bytes() == (
        npy / "paper" / "mc_trials.npy"
    ).read_bytes()


def test_switching_form_removes_the_stale_file(tmp_path: Path) -> None:
    out = tmp_path / "paper"
    run_scenario(_small(tmp_path / "a", "npy", 5), out, log=_quiet)
    assert (out / "mc_trials.npy").is_file()
    run_scenario(_small(tmp_path / "b", "auto", 5), out, log=_quiet)  # 5 trials: CSV
    assert [p.name for p in tf.existing(out, "mc_trials")] == ["mc_trials.csv"]


def test_shipped_scenarios_keep_the_csv_contract() -> None:
    """The results contract: every shipped scenario writes mc_trials.csv (their 1000 trials
    are CSV_MAX_TRIALS), and the workflow declares it; a larger one would declare .npy."""
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))
    ctx = context(PAPER, config)
    assert ctx.scenarios
    for s in ctx.scenarios:
        assert scenario_trials_format(ROOT / ctx.scenario_file(s)) == "csv", s
        assert f"{ctx.results}/{s}/mc_trials.csv" in trials_files(ctx, s)
    simulate = {st.name: st for st in PAPER.steps}
    assert simulate["simulate"].scenarios(ctx) == ctx.scenarios
    assert simulate["simulate_npy"].scenarios(ctx) == ()
    assert tf.trials_format(tf.CSV_MAX_TRIALS) == "csv"
    assert tf.trials_format(tf.CSV_MAX_TRIALS + 1) == "npy"


def _good(tmp_path: Path) -> Path:
    out = tmp_path / "good"
    tf.write_trials(out, "mc_trials", {None: {("L1", "phi_deg"): np.arange(4.0)}}, {"phi_deg": 2.0}, "npy")  # fmt: skip
    return out / "mc_trials.npy"


def test_a_good_binary_file_reads(tmp_path: Path) -> None:
    frame = tf.read_trials(_good(tmp_path).parent, "mc_trials")
    assert frame["estimate"].tolist() == [0.0, 1.0, 2.0, 3.0]
    assert frame["error_pct"].tolist() == [-100.0, -50.0, 0.0, 50.0]


@pytest.mark.parametrize(
    "corrupt, says",
    [
        (lambda b: b[: len(b) // 2], "not a valid north_finding trials file"),  # truncated
        (lambda b: b + b"\0", "bytes after the last array"),
        (lambda b: b"PK\x03\x04 not numpy at all", "not a valid north_finding trials file"),
        (lambda b: b.replace(b"north_finding.trials/1", b"north_finding.trials/9"), "tag"),
        (lambda b: b"", "not a valid north_finding trials file"),  # empty
    ],
)
def test_a_corrupt_binary_file_is_refused(tmp_path: Path, corrupt, says: str) -> None:
    path = _good(tmp_path)
    path.write_bytes(corrupt(path.read_bytes()))
    with pytest.raises(ValueError, match=says) as err:
        tf.read_trials(path.parent, "mc_trials")
    assert str(path) in str(err.value)


def test_a_binary_file_of_the_wrong_kind_is_refused(tmp_path: Path) -> None:
    path = _good(tmp_path)  # mc_trials (no n_avg) read as the judged trials
    judged = path.with_name("mc_trials_judged.npy")
    path.rename(judged)
    with pytest.raises(ValueError, match=r"n_avg .* for mc_trials_judged"):
        tf.read_trials(judged.parent, "mc_trials_judged")
    np.save(path, np.zeros(3))  # a plain numpy file: no tag
    with pytest.raises(ValueError, match="tag"):
        tf.read_trials(path.parent, "mc_trials")


def test_both_forms_in_one_folder_are_refused(tmp_path: Path) -> None:
    path = _good(tmp_path)
    path.with_suffix(".csv").write_text(",".join(tf.COLUMNS["mc_trials"]) + "\n")
    with pytest.raises(ValueError, match="both mc_trials.csv and mc_trials.npy"):
        tf.read_trials(path.parent, "mc_trials")


def test_unequal_trial_counts_cannot_be_written_binary(tmp_path: Path) -> None:
    blocks = {None: {("L1", "phi_deg"): np.zeros(3), ("L1", "theta_deg"): np.zeros(4)}}
    with pytest.raises(ValueError, match="the same trials"):
        tf.write_trials(tmp_path, "mc_trials", blocks, {"phi_deg": 1.0, "theta_deg": 1.0}, "npy")


def test_a_bad_trials_file_setting_is_refused(tmp_path: Path) -> None:
    from pipeline.config import ConfigError
    from pipeline.north_finding.scenario import load_scenario

    path = _small(tmp_path, "parquet")
    with pytest.raises(ConfigError, match="trials_file"):
        load_scenario(path)
