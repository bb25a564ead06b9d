"""Equation audit of platform_drift: coverage, valid statuses, judgements, the differing set.

The audit runs once (module fixture) through its CLI, which writes the results-contract CSV.
"""

from __future__ import annotations

import json
import re

import pandas as pd
import pytest

from derivations.platform_drift import audit
from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, DIFFERS_KINDS
from tests.audit_harness import assert_kinds_follow_the_rule

# the equations whose printed form differs from the derivation, with the kind of each
# difference (the judgements in audit_*.py give the evidence)
PAPER, CONVENTION, UNCLEAR = "paper_error", "convention", "unclear_from_text"
DIFFERS = {
    "16": UNCLEAR, "17": PAPER, "20": PAPER, "24": PAPER, "28": CONVENTION, "31.x": PAPER,
    "31.y": PAPER, "34": PAPER, "36.q": PAPER, "T2.5": CONVENTION,
}  # fmt: skip


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("platform_drift")
    argv = ["--out", str(out / "equation_audit.csv"), "--math", str(out / "equation_math.json")]
    assert audit.main(argv) == 0
    return out


@pytest.fixture(scope="module")
def frame(written) -> pd.DataFrame:
    return pd.read_csv(written / "equation_audit.csv", dtype=str, keep_default_na=False)


@pytest.fixture(scope="module")
def records(written) -> list[dict]:
    return json.loads((written / "equation_math.json").read_text())


def test_columns_and_unique_keys(frame):
    assert list(frame.columns) == AUDIT_COLUMNS
    assert frame["equation"].is_unique


def test_every_numbered_equation_and_table2_row_is_audited(frame):
    numbers = {re.match(r"(\d+)", e).group(1) for e in frame["equation"] if e[0].isdigit()}
    assert numbers == {str(k) for k in range(1, 37)}
    rows = {e for e in frame["equation"] if e.startswith("T2.")}
    assert rows == {f"T2.{k}" for k in range(1, 9)}


def test_statuses_are_valid(frame):
    assert set(frame["status"]) <= set(AUDIT_STATUSES)
    assert (frame.loc[frame["status"] == "match", "residual"] == "0").all()


def test_every_differs_row_has_a_judgement_and_a_residual(frame):
    rows = frame[frame["status"] == "differs"]
    for _, row in rows.iterrows():
        assert row["residual"] not in ("", "0"), row["equation"]
        assert len(row["note"]) > 40, row["equation"]
        assert row["kind"] in DIFFERS_KINDS, row["equation"]
    assert (frame.loc[frame["status"] != "differs", "kind"] == "").all()


def test_not_checkable_rows_give_a_reason(frame):
    rows = frame[frame["status"] == "not_checkable"]
    assert set(rows["equation"]) == {
        "5",
        "6",
        "7",
        "22",
        "25",
        "26",
        "28.kg",
        "32.def",
        "36.coef",
        "T2.8",
    }
    assert (rows["note"].str.len() > 20).all()


def test_exact_set_of_differing_equations_and_their_kinds(frame):
    differs = frame[frame["status"] == "differs"]
    assert dict(zip(differs["equation"], differs["kind"], strict=True)) == DIFFERS


def test_each_kind_follows_from_what_the_seed_text_shows(frame, records):
    """The kind of each difference follows the one rule of every paper (tests/audit_harness)."""
    assert_kinds_follow_the_rule(frame, records)


def test_residuals_of_the_paper_errors(frame):
    res = frame.set_index("equation")["residual"]
    # eq. 24 drops alpha omega_e cos(phi_i)
    assert res["24"] == "-alpha*omega_e*cos(phi_i)"
    # eq. 34 and eq. 36 int q_merror: the b_g3 term of phi_y_dot(0+) has the wrong sign
    assert res["34"].split("; ")[:3] == ["0", "0", "0"]
    assert "2*alpha*b_g3*sin(psi_0)" in res["34"]
    assert "2*alpha*b_g3*sin(psi_0)*sin(sqrt(k_sh)*t)/sqrt(k_sh)" in res["36.q"]
    # eq. 28: the k_sh approximation differs by (q phi_x - p phi_y)(q, -p)
    assert res["28"] == "q*(-p*phi_y + phi_x*q); p*(p*phi_y - phi_x*q)"
