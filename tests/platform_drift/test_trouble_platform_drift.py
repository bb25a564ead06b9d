"""Numerical trouble of the platform_drift curves is counted, never silent: eq. 36's domain
edge (start latitude 0), non-finite points and the haversine clip, per run, case and scheme,
in numerical_trouble.csv; the counts agree with the curves, and the page says so."""

from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd
import pytest

from pipeline.platform_drift.report import _trouble
from pipeline.platform_drift.run import TROUBLE_KINDS, _trouble_frame, run_scenario
from pipeline.platform_drift.scenario import ROOT, load_scenario
from pipeline.trouble import TROUBLE_COLUMNS, Trouble
from tests.equator_scenario import write_equator_scenario

SCEN = ROOT / "config" / "scenarios" / "platform_drift"


def _nan_points(errors: pd.DataFrame) -> pd.Series:
    return errors.groupby(["case", "scheme"], sort=False)["error_m"].apply(
        lambda e: int((~np.isfinite(e.to_numpy(float))).sum())
    )


def _check_against_curves(d) -> pd.DataFrame:
    """non_finite of the main run = the NaN points of errors.csv and errors_diagnostic.csv."""
    tr = pd.read_csv(d / "numerical_trouble.csv", keep_default_na=False)
    assert list(tr.columns) == TROUBLE_COLUMNS and set(tr["kind"]) == set(TROUBLE_KINDS)
    errors = pd.concat([pd.read_csv(d / "errors.csv"), pd.read_csv(d / "errors_diagnostic.csv")])
    nan = _nan_points(errors)
    main = tr[(tr["run"] == "main") & (tr["kind"] == "non_finite")]
    got = main.set_index(["case", "method"])["n_affected"]
    assert got.to_dict() == {k: v for k, v in nan.items()}
    points = errors.groupby(["case", "scheme"]).size()
    assert (main.set_index(["case", "method"])["n_trials"] == points.reindex(got.index)).all()
    return tr


@pytest.fixture(scope="module")
def equator(tmp_path_factory):
    """The stationary scenario at latitude 0, channel-3 drift only, 2 h."""
    base = tmp_path_factory.mktemp("lat0")
    path = write_equator_scenario(base)
    sc = dataclasses.replace(load_scenario(path), cases=("ch1", "ch3"))
    run_scenario(sc, base / "out", log=lambda m: None)
    return base / "out"


def test_latitude_0_counts_eq36_undefined_on_every_point(equator):
    tr = _check_against_curves(equator)
    hit = tr[tr["n_affected"] > 0]
    n = int(tr["n_trials"].iloc[0])
    assert sorted(map(tuple, hit[["case", "method", "kind", "n_affected"]].values.tolist())) == [
        ("ch3", "proposed_analytic", "eq36_undefined", n),
        ("ch3", "proposed_analytic", "non_finite", n),
    ]
    text = _trouble(equator / "numerical_trouble.csv")[0].text
    assert text.startswith("Numerical trouble in the curves to the scenario's duration")


def test_shipped_scenario_counts_are_the_computed_ones(tmp_path):
    run_scenario(load_scenario(SCEN / "latitude_change.yaml"), tmp_path, log=lambda m: None)
    tr = _check_against_curves(tmp_path)
    blocks = _trouble(tmp_path / "numerical_trouble.csv")
    said_none = blocks[0].text.startswith("No numerical trouble")
    assert said_none == (tr["n_affected"].sum() == 0)


def test_injected_nan_and_clip_are_counted():
    t = np.arange(5.0)
    curves = {("ch1", "strapdown"): np.array([1.0, np.nan, 2.0, np.inf, 3.0])}
    counts = Trouble(TROUBLE_KINDS)
    counts.mark("ch1/strapdown", "clipped_arcsine", t > 3)
    frame = _trouble_frame(counts, curves, "main", "").set_index("kind")
    assert frame.loc["non_finite", "n_affected"] == 2
    assert frame.loc["clipped_arcsine", "n_affected"] == 1
    assert frame.loc["eq36_undefined", "n_affected"] == 0
    assert set(frame["case"]) == {"ch1"} and set(frame["method"]) == {"strapdown"}
