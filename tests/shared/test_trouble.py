"""The shared numerical-trouble counter and page note (pipeline/trouble.py,
pipeline/report/trouble.py): counts per trial, a summary over fewer trials than it says is
refused, the page says "no numerical trouble" only when every count is zero."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.report.trouble import read_trouble, trouble_frame_blocks
from pipeline.trouble import TROUBLE_COLUMNS, Trouble, finite_count, require_used, trouble_rows

WORDS = {"clipped_arcsine": "argument clipped", "non_finite": "estimate NaN"}
RUNS = {"monte_carlo": "Monte Carlo", "sensitivity": "sensitivity"}


def test_counts_per_trial_with_matrix_values():
    t = Trouble(("clipped_arcsine", "non_finite"))
    t.mark("A", "clipped_arcsine", np.array([True, False, True, False]))
    values = {
        "A": np.array([[0.0, 1.0], [np.inf, 1.0], [0.0, np.nan], [1.0, 1.0]]),  # rows = trials
        "B": np.array([1.0, 2.0, 3.0, 4.0]),
    }
    frame = t.frame(values, "monte_carlo", "N=10").set_index(["method", "kind"])
    assert frame.loc[("A", "clipped_arcsine"), "n_affected"] == 2
    assert frame.loc[("A", "non_finite"), "n_affected"] == 2
    assert frame.loc[("B", "non_finite"), "n_affected"] == 0
    assert set(frame["n_trials"]) == {4} and set(frame["case"]) == {"N=10"}


def test_summary_over_fewer_trials_is_refused():
    v = np.array([1.0, np.nan, 3.0])
    require_used(3, 3, "ok")  # every trial used: fine
    with pytest.raises(ValueError, match="2 of 3 trials usable"):
        require_used(3, finite_count(v), "summary x")


def test_page_note_none_and_counts(tmp_path):
    rows = trouble_rows("monte_carlo", "", "L1", 100, {"clipped_arcsine": 0, "non_finite": 0})
    rows += trouble_rows("sensitivity", "N=1", "L1", 50, {"clipped_arcsine": 0, "non_finite": 0})
    clean = pd.DataFrame(rows, columns=TROUBLE_COLUMNS)
    blocks = trouble_frame_blocks(clean, WORDS, RUNS)
    assert len(blocks) == 1
    assert blocks[0].text == (
        "No numerical trouble in Monte Carlo (100 trials), sensitivity at N = 1 (50 trials): "
        "no argument clipped; no estimate NaN."
    )
    dirty = clean.copy()
    dirty.loc[3, "n_affected"] = 7  # sensitivity, non_finite
    path = tmp_path / "numerical_trouble.csv"
    dirty.to_csv(path, index=False)
    blocks = trouble_frame_blocks(read_trouble(path), WORDS, RUNS, after="Said after.")
    assert blocks[0].text.startswith("Numerical trouble in ") and "Said after." in blocks[0].text
    assert blocks[1].rows == [["sensitivity at N = 1", "L1", "estimate NaN", "7 of 50"]]
    # the note names no file and no internal id
    assert ".csv" not in blocks[0].text and "non_finite" not in blocks[0].text


def test_missing_columns_refused(tmp_path):
    path = tmp_path / "numerical_trouble.csv"
    pd.DataFrame({"run": ["x"]}).to_csv(path, index=False)
    with pytest.raises(ValueError, match="missing columns"):
        read_trouble(path)
