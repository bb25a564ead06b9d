"""Equation audit of altimeter_attitude: coverage, valid statuses, judgements, the differing set.

The audit runs once (module fixture) through its CLI, which writes the results-contract CSV.
Not marked slow: the whole audit takes about 16 s (SymPy's Euler-rate solve and the eq. 3
composition dominate), so it runs with the default test selection.
"""

from __future__ import annotations

import json

import pandas as pd
import pytest

from derivations.altimeter_attitude import audit
from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, DIFFERS_KINDS
from tests.audit_harness import assert_kinds_follow_the_rule

EQUATIONS = [
    *("1 2 3 4 5 6.euler 6.quat 7 8 9 10 11.phi 11.theta 12 13 14 15 15.b 16".split()),
    *("17.a 17.b 18 19 20 21 22 23 24 25 26.A 26.B 26.C 27 28 29".split()),
    *("30.G 30.L 30.F 31.xpred 31.Ppred 31.K 31.P 31.x 32 33".split()),
    *(f"{k}a" for k in range(1, 14)),
]

# the equations whose printed form differs from the derivation, with the kind of each
# difference (the judgements in audit_*.py give the evidence)
PAPER, CONVENTION, UNCLEAR = "paper_error", "convention", "unclear_from_text"
DIFFERS = {
    "11.phi": PAPER, "26.C": CONVENTION, "28": CONVENTION, "31.K": PAPER, "31.P": PAPER,
    "7a": PAPER, "10a": PAPER, "13a": UNCLEAR,
}  # fmt: skip
NOT_CHECKABLE = {"16", "22", "23", "1a", "2a"}


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("altimeter_attitude")
    argv = ["--out", str(out / "equation_audit.csv"), "--math", str(out / "equation_math.json")]
    assert audit.main(argv) == 0
    return out


@pytest.fixture(scope="module")
def frame(written) -> pd.DataFrame:
    return pd.read_csv(written / "equation_audit.csv", dtype=str, keep_default_na=False)


@pytest.fixture(scope="module")
def records(written) -> list[dict]:
    return json.loads((written / "equation_math.json").read_text())


def test_cli_writes_the_contract_columns(frame):
    assert list(frame.columns) == AUDIT_COLUMNS
    assert frame["equation"].is_unique


def test_every_numbered_equation_is_audited_exactly_once(frame):
    assert len(EQUATIONS) == len(set(EQUATIONS))
    assert sorted(frame["equation"]) == sorted(EQUATIONS)


def test_statuses_are_valid(frame):
    assert set(frame["status"]) <= set(AUDIT_STATUSES)
    assert (frame.loc[frame["status"] == "match", "residual"] == "0").all()


def test_exact_set_of_differing_equations_and_their_kinds(frame):
    differs = frame[frame["status"] == "differs"]
    assert dict(zip(differs["equation"], differs["kind"], strict=True)) == DIFFERS


def test_each_kind_follows_from_what_the_seed_text_shows(frame, records):
    """The kind of each difference follows the one rule of every paper (tests/audit_harness)."""
    assert_kinds_follow_the_rule(frame, records)


def test_every_differs_row_has_a_judgement_and_a_residual(frame):
    rows = frame[frame["status"] == "differs"]
    for _, row in rows.iterrows():
        assert row["residual"] not in ("", "0"), row["equation"]
        assert len(row["note"]) > 40, row["equation"]
        assert row["kind"] in DIFFERS_KINDS, row["equation"]
    assert (frame.loc[frame["status"] != "differs", "kind"] == "").all()


def test_not_checkable_rows_give_a_reason(frame):
    rows = frame[frame["status"] == "not_checkable"]
    assert set(rows["equation"]) == NOT_CHECKABLE
    assert (rows["residual"] == "").all()
    assert (rows["note"].str.len() > 40).all()


def test_residuals_and_computed_notes(frame):
    row = frame.set_index("equation")
    res, note = row["residual"], row["note"]
    # eq. 11: the printed roll is off by pi
    assert "the residual is -pi at the sampled" in note["11.phi"]
    # eq. 26: printed C(x) = -derived, so printed - derived = 2 * printed (first row shown)
    assert res["26.C"].split("; ")[:6] == ["0", "-2*c3", "2*c2", "0", "0", "0"]
    assert res["28"].endswith("2*c1*n_ax + 2*c2*n_ay + 2*c3*n_az; 0")
    # eq. 31: P_{k-1|k-1} instead of P_{k|k-1} in the innovation covariance
    assert "P_pred_55 - P_prev_55" in res["31.K"]
    assert "P_prev_55" in res["31.P"]
    # eq. 7a: the third term lacks F^T: residual z (e - F e)^T
    assert res["7a"].startswith("z_1*(-F_11*e_1 - F_12*e_2 + e_1)")
    # eq. 10a: the random w w^T in place of Q; eq. 13a: no transpose
    assert "w_1**2" in res["10a"] and "Q_11" in res["10a"]
    assert "Q_12" in res["13a"] and "w_1" not in res["13a"]
    # computed numbers in the notes
    assert "n_dot = -2*k*n*(n - 1)" in note["14"]
    assert "4.3 %" in note["21"] and "20.8 %" in note["21"]
    assert "[0, 0, 0, Delta_t, -Delta_t**2/2]" in note["30.L"]
    assert "c1/2, c2/2, c3/2" in note["30.G"]
    assert "difference zero" in note["32"]
