"""write_csv joins plain tables itself (pipeline.atomic._csv_text): the bytes pandas' to_csv
writes, for every kind of column, and pandas' own writer for anything else."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pipeline.atomic import _csv_text, _formatted, write_csv, write_text_csv


def _pandas_bytes(frame: pd.DataFrame, tmp_path: Path) -> bytes:
    path = tmp_path / "pandas.csv"
    _formatted(frame).to_csv(path, index=False, float_format="%.17g", lineterminator="\n")
    return path.read_bytes()


def _frame(rows: int, seed: int) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    x = rng.standard_normal(rows) * 10.0 ** rng.integers(-300, 300, rows)
    x[::7] = np.nan
    x[1::11] = -0.0
    x[2::13] = np.inf
    return pd.DataFrame(
        {
            "n": rng.integers(-(10**12), 10**12, rows),
            "flag": rng.random(rows) < 0.5,
            "label": rng.choice(["L1", "A1c2", "", " spaced ", "ünïcode"], rows),
            "x": x,
            "y": rng.random(rows),
        }
    )


@pytest.mark.parametrize("rows", [0, 1, 5, 1000])
def test_plain_tables_are_written_as_pandas_writes_them(rows, tmp_path):
    frame = _frame(rows, rows)
    assert _csv_text(_formatted(frame)) is not None  # the fast path is taken
    out = write_csv(tmp_path / "fast.csv", frame, list(frame.columns))
    assert out.read_bytes() == _pandas_bytes(frame, tmp_path)


def test_string_dtype_columns_and_repeated_names(tmp_path):
    frame = _frame(50, 1).astype({"label": "string"})
    assert _csv_text(_formatted(frame)) is not None
    assert _csv_text(_formatted(frame)).encode() == _pandas_bytes(frame, tmp_path)
    doubled = pd.concat([frame, frame], axis=1)
    assert _csv_text(_formatted(doubled)).encode() == _pandas_bytes(doubled, tmp_path)


@pytest.mark.parametrize(
    "change",
    [
        lambda f: f.assign(label=["a,b"] + ["x"] * (len(f) - 1)),  # needs quotes
        lambda f: f.assign(label=['say "hi"'] + ["x"] * (len(f) - 1)),
        lambda f: f.assign(label=["two\nlines"] + ["x"] * (len(f) - 1)),
        lambda f: f.assign(label=[None] + ["x"] * (len(f) - 1)),  # a missing value
        lambda f: f.assign(label=[1] + ["x"] * (len(f) - 1)),  # not a string
        lambda f: f.astype({"y": np.float32}),  # float_format applies
        lambda f: f.astype({"n": "Int64"}),  # nullable integers
        lambda f: f[["label"]],  # one column: an empty field alone is quoted
        lambda f: f.rename(columns={"n": "n,m"}),  # a header that needs quotes
        lambda f: f.rename(columns={"n": 3}),  # a name that is not a string
    ],
)
def test_anything_else_goes_to_pandas(change, tmp_path):
    frame = change(_frame(20, 2))
    assert _csv_text(_formatted(frame)) is None
    out = write_csv(tmp_path / "slow.csv", frame, list(frame.columns))
    assert out.read_bytes() == _pandas_bytes(frame, tmp_path)


def test_a_table_of_strings_is_written_as_write_csv_writes_it_without_pandas(tmp_path):
    """The equation audit's rows (pipeline/scripts/equation_audit.py): commas, quotes, line
    ends, empty fields and non-ASCII text, as write_csv writes them from a DataFrame."""
    fields = ["", "a", "x, y", 'say "hi"', "two\nlines", "cr\rhere", "ünïcode", " spaced "]
    rng = np.random.default_rng(5)
    columns = ["equation", "status", "residual", "note", "kind"]
    rows = [{c: str(rng.choice(fields)) for c in columns} for _ in range(200)]
    written = write_text_csv(tmp_path / "t.csv", rows, columns).read_bytes()
    frame = pd.DataFrame(rows, columns=columns)
    assert written == write_csv(tmp_path / "p.csv", frame, columns).read_bytes()
    assert written == _pandas_bytes(frame, tmp_path)
    with pytest.raises(ValueError, match="'kind' missing or not a string"):
        write_text_csv(tmp_path / "bad.csv", [{**rows[0], "kind": 1}], columns)
