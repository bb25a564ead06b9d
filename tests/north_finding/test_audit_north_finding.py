"""Equation audit of north_finding: coverage, statuses, judgements, and the eq. 47.E claim.

``audit_frame()`` derives and compares every equation (~30 s), so it runs once per module.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
import sympy as sp

from derivations.checks import Check, run_check
from derivations.north_finding import azimuth, leveling
from derivations.north_finding import printed as P
from derivations.north_finding import symbols as s
from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, DIFFERS_KINDS
from pipeline.generated import north_finding as gen
from pipeline.north_finding import estimators as est
from tests.audit_harness import assert_kinds_follow_the_rule

pytestmark = pytest.mark.slow  # the module fixture runs the whole audit (~30 s)

# The equations whose printed form differs from the derivation, with the kind of each
# difference (the judgements in audit_*.py give the evidence). Asserted exactly: a change in a
# derivation or a transcription that flips a status or a kind shows up here and must be reviewed.
PAPER, TEXT, UNCLEAR = "paper_error", "text_artefact", "unclear_from_text"
EXPECTED_DIFFERS = {
    "16.b": PAPER, "21": PAPER, "22": PAPER, "23": TEXT, "37": PAPER, "40.d": PAPER,
    "41": UNCLEAR, "46": PAPER, "47.E": PAPER, "52": TEXT, "57": TEXT, "58": UNCLEAR,
    "59": UNCLEAR, "64.A": UNCLEAR, "65.b": UNCLEAR, "67": UNCLEAR, "68": PAPER, "69": PAPER,
}  # fmt: skip
EQ = re.compile(r"^(\d+)(\.[A-Za-z0-9]+)?$")


@pytest.fixture(scope="module")
def outputs():
    from derivations.checks import audit_outputs
    from derivations.north_finding.audit import checks

    return audit_outputs(checks())


@pytest.fixture(scope="module")
def audit(outputs):
    return outputs[0]


@pytest.fixture(scope="module")
def records(outputs):
    return outputs[1]


def test_contract_columns_and_unique_equations(audit):
    assert list(audit.columns) == AUDIT_COLUMNS
    assert audit["equation"].is_unique


def test_every_equation_1_to_71_appears(audit):
    numbers = set()
    for eq in audit["equation"]:
        m = EQ.match(eq)
        assert m, f"equation label {eq!r} is not 'N' or 'N.x'"
        numbers.add(int(m.group(1)))
    assert numbers == set(range(1, 72))


def test_statuses_allowed(audit):
    assert set(audit["status"]) <= set(AUDIT_STATUSES)
    assert set(audit["status"]) == set(AUDIT_STATUSES)  # all three occur in this paper


def test_differs_rows_have_residual_and_judgement(audit):
    differs = audit[audit["status"] == "differs"]
    for _, row in differs.iterrows():
        assert isinstance(row["residual"], str) and row["residual"].strip() not in ("", "0"), row[
            "equation"
        ]
        assert isinstance(row["note"], str) and len(row["note"]) > 40, row["equation"]
        assert row["kind"] in DIFFERS_KINDS, row["equation"]


def test_match_and_not_checkable_rows(audit):
    match = audit[audit["status"] == "match"]
    assert (match["residual"] == "0").all()
    nc = audit[audit["status"] == "not_checkable"]
    assert nc["note"].map(lambda x: isinstance(x, str) and len(x.strip()) > 10).all()
    assert nc["residual"].map(lambda x: not isinstance(x, str) or x == "").all()
    # a kind only on a differs row
    others = audit[audit["status"] != "differs"]
    assert others["kind"].map(lambda x: not isinstance(x, str) or x == "").all()


def test_expected_differs_and_their_kinds(audit):
    differs = audit[audit["status"] == "differs"]
    assert dict(zip(differs["equation"], differs["kind"], strict=True)) == EXPECTED_DIFFERS


def test_each_kind_follows_from_what_the_seed_text_shows(audit, records):
    """The kind of each difference follows the one rule of every paper (tests/audit_harness)."""
    assert_kinds_follow_the_rule(audit, records)


def test_the_derived_forms_that_the_pipeline_uses_match(audit):
    """The equations the estimators rely on, in their derived form, match the paper."""
    status = dict(zip(audit["equation"], audit["status"], strict=True))
    for eq in (
        "17",
        "19.a",
        "19.b",
        "24.b",
        "24.c",
        "38",
        "40.b",
        "47.A",
        "47.B",
        "47.C",
        "47.D",
        "50",
        "55",
        "70",
    ):
        assert status[eq] == "match", eq


# --------------------------------------------------------------------------------------------
# the audit detects a changed derivation (no monkeypatching: a Check with a wrong derived form)
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("label", "printed", "derived_fn"),
    [
        ("17", lambda: P.PRINTED["17"], lambda: leveling.ideal_accel("x")),
        ("19.a", lambda: P.PRINTED["19.a"], lambda: leveling.method1()["sin_theta"]),
        ("38", lambda: P.PRINTED["38"], lambda: azimuth.ideal_gyro("x")),
        ("47.A", lambda: P.PRINTED["47.A"], lambda: azimuth.method3()["A47"]),
    ],
)
def test_wrong_derivation_is_flagged(label, printed, derived_fn):
    derived = derived_fn()
    assert run_check(Check(label, printed=printed(), derived=derived)).status == "match"
    # a relative change of 1e-6 (far above the 1e-9 tolerance) is a difference: without a
    # recorded kind it stops the audit, naming the equation ...
    scaled = derived * (1 + sp.Rational(1, 10**6))
    with pytest.raises(ValueError, match=rf"^eq\. {re.escape(label)}: printed and derived forms"):
        run_check(Check(label, printed=printed(), derived=scaled))
    judged = {"discrepancy": "wrong_term", "if_differs": "a judgement with its evidence"}
    row = run_check(Check(label, printed=printed(), derived=scaled, **judged))
    assert (row.status, row.kind) == ("differs", "paper_error")
    assert row.residual not in ("", "0")
    # ... and so is a structural change (the sign of one term flipped)
    first = sp.Add.make_args(sp.expand(derived))[0]
    wrong = derived - 2 * first
    assert run_check(Check(label, printed=printed(), derived=wrong, **judged)).status == "differs"


# --------------------------------------------------------------------------------------------
# eq. 47.E: the printed constant does not give the true azimuth, the derived one does
# --------------------------------------------------------------------------------------------
def _paper_case():
    d = np.deg2rad
    return dict(omega=7.292115e-5, lat=d(35.0), psi=d(88.0), theta=d(30.0), phi=d(50.0))


def _candidates_deg(coeffs_a_to_e) -> np.ndarray:
    """Every psi from the real roots c in [-1, 1] of eq. 50, both signs of sin(psi)."""
    q = [float(np.ravel(x)[0]) for x in gen.a3_quartic_coeffs(*coeffs_a_to_e)]
    roots = np.roots(q)
    c = roots.real[(np.abs(roots.imag) < 1e-9) & (np.abs(roots.real) <= 1.0)]
    psi = np.rad2deg(np.arccos(c))
    return np.concatenate([psi, 360.0 - psi]) % 360.0


def _dist(a, b):
    return np.abs((np.asarray(a) - b + 180.0) % 360.0 - 180.0)


def test_printed_47E_does_not_return_88_deg_derived_does():
    p = _paper_case()
    _, w_peak = gen.a3_peak(p["omega"], p["lat"], p["psi"], p["theta"], p["phi"])
    derived = [
        float(np.ravel(c)[0])
        for c in gen.a3_eq47_coeffs(w_peak, p["omega"], p["lat"], p["theta"], p["phi"])
    ]
    e_printed = float(
        P.PRINTED["47.E"].subs(
            {
                s.phi: p["phi"],
                s.theta: p["theta"],
                s.lam: p["lat"],
                s.wx_max: float(w_peak),
                s.Omega: p["omega"],
            }
        )
    )
    assert abs(e_printed - derived[4]) > 0.1  # the two constants are really different

    good = _candidates_deg(derived)
    assert _dist(good, 88.0).min() < 1e-9
    bad = _candidates_deg([*derived[:4], e_printed])
    assert bad.size > 0
    assert _dist(bad, 88.0).min() > 0.1

    # through the pipeline's own solver, with the compass reading 93 deg
    coeffs = tuple(np.array([v]) for v in derived)
    prior = np.deg2rad([93.0])
    assert _dist(np.rad2deg(est.solve_quartic_psi(coeffs, prior)) % 360, 88.0)[0] < 1e-9
    printed_coeffs = (*coeffs[:4], np.array([e_printed]))
    assert _dist(np.rad2deg(est.solve_quartic_psi(printed_coeffs, prior)) % 360, 88.0)[0] > 0.1
