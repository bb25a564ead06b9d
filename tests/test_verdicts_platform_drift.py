"""Verdict rules of the platform-drift paper on synthetic error curves (each rule can fail)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.config import ConfigError
from pipeline.platform_drift.verdicts import crossover, load_published, verdicts

T = np.arange(0.0, 7201.0, 10.0)
T_LONG = np.arange(0.0, 86401.0, 60.0)


def _frame(curves: dict[tuple[str, str], np.ndarray], t: np.ndarray = T) -> pd.DataFrame:
    parts = [
        pd.DataFrame({"t_s": t, "case": case, "scheme": scheme, "error_m": err})
        for (case, scheme), err in curves.items()
    ]
    return pd.concat(parts, ignore_index=True)


def test_crossover_interpolates_and_needs_margin():
    strap = pd.Series(1e-4 * T**2, index=T)
    prop = pd.Series(np.full_like(T, 400.0), index=T)
    # 1e-4 t^2 = 401 (1 m margin) at t = sqrt(4.01e6)
    assert crossover(strap, prop) == pytest.approx(np.sqrt(4.01e6), rel=1e-3)
    assert np.isnan(crossover(strap, strap.copy()))  # coinciding curves never cross


def _published(claims=(), items=()):
    return {"paper": "platform_drift", "items": list(items), "claims": list(claims)}


def test_bounded_claim_distinguishes_growth_from_oscillation():
    osc = 200 * np.abs(np.sin(T_LONG / 3000))
    grow = 1e-5 * T_LONG**1.5
    claim = {
        "id": "C",
        "source": "s",
        "text": "bounded",
        "predicate": {"type": "bounded", "scenario": "st", "case": "ch3", "ratio": 1.5},
    }
    long = _frame({("ch3", "proposed_analytic"): osc, ("ch3", "proposed_simulated"): grow}, T_LONG)
    res = {"st": {"errors": _frame({("ch3", "strapdown"): T}), "errors_long": long}}
    out = verdicts(_published([claim]), res).set_index("method")["verdict"]
    assert out["proposed_analytic"] == "upheld"
    assert out["proposed_simulated"] == "not_upheld"


def test_growth_exponent_and_final_order():
    claims = [
        {
            "id": "G",
            "source": "s",
            "text": "t^2",
            "predicate": {
                "type": "growth_exponent",
                "scenario": "st",
                "case": "ch3",
                "scheme": "strapdown",
                "expect": 2.0,
                "tol": 0.1,
            },
        },
        {
            "id": "F",
            "source": "s",
            "text": "strapdown below",
            "predicate": {
                "type": "final_order",
                "scenario": "st",
                "case": "ch3",
                "reference": "strapdown",
                "expect": "reference_below",
            },
        },
    ]
    errors = _frame(
        {
            ("ch3", "strapdown"): 1e-4 * T**2,
            ("ch3", "proposed_analytic"): 1e-4 * T**2 + 1.0,
            ("ch3", "proposed_simulated"): 1e-4 * T**2 - 1.0,
        }
    )
    out = verdicts(_published(claims), {"st": {"errors": errors}}).set_index("id")["verdict"]
    assert out["G/strapdown"] == "upheld"
    assert out["F/proposed_analytic"] == "upheld"
    assert out["F/proposed_simulated"] == "not_upheld"


def test_item_tolerance():
    item = {
        "id": "I",
        "figure": "Fig. 5 (3)",
        "scenario": "st",
        "case": "ch3",
        "scheme": "strapdown",
        "quantity": "error_2h_m",
        "value": "4.5",
        "unit": "km",
        "kind": "exact",
        "tolerance_rel": 0.1,
    }
    for final, expected in ((4600.0, "reproduced"), (5500.0, "not_reproduced")):
        errors = _frame({("ch3", "strapdown"): final * (T / T[-1]) ** 2})
        out = verdicts(_published(items=[item]), {"st": {"errors": errors}})
        assert out["verdict"].tolist() == [expected]


def test_repository_file_loads_and_bad_file_names_field(tmp_path):
    data = load_published("config/published/platform_drift.yaml")
    assert len(data["items"]) == 14 and len(data["claims"]) == 7
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "paper: platform_drift\nitems:\n  - {id: X, figure: f, scenario: s, case: ch9, scheme: "
        "strapdown, quantity: error_2h_m, value: '1', unit: km, kind: exact, tolerance_rel: 0.1}\n"
        "claims: []\n"
    )
    with pytest.raises(ConfigError, match=r"bad\.yaml: items\.0\.case"):
        load_published(bad)
