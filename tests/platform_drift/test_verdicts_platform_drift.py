"""Verdict rules of the platform-drift paper on synthetic error curves (each rule can fail)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.config import ConfigError
from pipeline.platform_drift.claims import CLAIMS
from pipeline.platform_drift.quantities import crossover, locate
from pipeline.platform_drift.verdicts import load_published
from pipeline.verdicts.engine import verdict_table

T = np.arange(0.0, 7201.0, 10.0)
T_LONG = np.arange(0.0, 86401.0, 60.0)


def _frame(curves: dict[tuple[str, str], np.ndarray], t: np.ndarray = T) -> pd.DataFrame:
    parts = [
        pd.DataFrame({"t_s": t, "case": case, "scheme": scheme, "error_m": err})
        for (case, scheme), err in curves.items()
    ]
    return pd.concat(parts, ignore_index=True)


def verdicts(published: dict, results: dict) -> pd.DataFrame:
    return verdict_table(published, locate, CLAIMS, results)


def test_crossover_interpolates_and_needs_margin():
    strap = pd.Series(1e-4 * T**2, index=T)
    prop = pd.Series(np.full_like(T, 400.0), index=T)
    # 1e-4 t^2 = 401 (1 m margin) at t = sqrt(4.01e6)
    assert crossover(strap, prop) == pytest.approx(np.sqrt(4.01e6), rel=1e-3)
    assert np.isnan(crossover(strap, strap.copy()))  # coinciding curves never cross


def _published(claims=(), items=()):
    return {"paper": "platform_drift", "items": list(items), "claims": list(claims)}


def _claim(test: str, **args) -> dict:
    return {"id": test[0].upper(), "label": "Sec. 6", "text": test, "predicate": {"test": test, **args}}  # fmt: skip


def test_bounded_claim_distinguishes_growth_from_oscillation():
    osc = 200 * np.abs(np.sin(T_LONG / 3000))
    grow = 1e-5 * T_LONG**1.5
    claim = _claim("bounded", scenario="st", case="ch3", ratio=1.5)
    long = _frame({("ch3", "proposed_analytic"): osc, ("ch3", "proposed_simulated"): grow}, T_LONG)
    res = {"st": {"errors": _frame({("ch3", "strapdown"): T}), "errors_long": long}}
    out = verdicts(_published([claim]), res).set_index("method")["verdict"]
    assert out["proposed_analytic"] == "upheld"
    assert out["proposed_simulated"] == "not_upheld"
    no_long = verdicts(_published([claim]), {"st": {"errors": res["st"]["errors"]}})
    assert no_long["verdict"].tolist() == ["not_checkable"]


def test_growth_exponent_and_final_order():
    claims = [
        _claim("growth_exponent", scenario="st", case="ch3", scheme="strapdown", expect=2.0, tol=0.1),
        _claim("final_order", scenario="st", case="ch3", reference="strapdown", expect="reference_below"),
    ]  # fmt: skip
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
    cubic = _frame({("ch3", "strapdown"): 1e-8 * T**3})
    out = verdicts(_published(claims[:1]), {"st": {"errors": cubic}})
    assert out["verdict"].tolist() == ["not_upheld"]


def test_close_and_below():
    errors = _frame(
        {
            ("ch1", "strapdown"): 100 + T,
            ("ch1", "proposed_analytic"): 1.05 * (100 + T),
            ("ch1", "proposed_simulated"): 1.5 * (100 + T),
        }
    )
    claims = [
        _claim("close", scenario="st", case="ch1", reference="strapdown", rel_tol=0.1),
        _claim("below", scenario="st", case="ch1", reference="strapdown", from_s=300),
    ]
    out = verdicts(_published(claims), {"st": {"errors": errors}}).set_index("id")["verdict"]
    assert out["C/proposed_analytic"] == "upheld" and out["C/proposed_simulated"] == "not_upheld"
    assert out["B/proposed_analytic"] == "not_upheld"
    errors.loc[errors["scheme"] == "proposed_analytic", "error_m"] = 1.0
    out = verdicts(_published(claims), {"st": {"errors": errors}}).set_index("id")["verdict"]
    assert out["B/proposed_analytic"] == "upheld"


def _item(value: str = "4.5", quantity: str = "error_2h_m", unit: str = "km", rel: float = 0.1):
    return {
        "id": "I",
        "label": "Fig. 5 (3)",
        "kind": "approximate",
        "quantity": quantity,
        "value": value,
        "unit": unit,
        "select": {"scenario": "st", "case": "ch3", "scheme": "strapdown"},
        "tolerance": {"rel": rel, "reason": "read off the plot"},
    }


def test_about_value_is_approximate_with_its_tolerance():
    for final, expected in ((4600.0, "reproduced"), (5500.0, "not_reproduced"), (4500.0, "reproduced")):  # fmt: skip
        errors = _frame({("ch3", "strapdown"): final * (T / T[-1]) ** 2})
        out = verdicts(_published(items=[_item()]), {"st": {"errors": errors}})
        assert out["verdict"].tolist() == [expected]
        assert out["kind"].tolist() == ["approximate"]
        assert out["published"].tolist() == ["4.5 km"]
    missing = verdicts(_published(items=[_item()]), {})
    assert missing["verdict"].tolist() == ["not_checkable"]


def test_crossover_item_one_row_per_proposed_curve():
    errors = _frame(
        {
            ("ch3", "strapdown"): 1e-4 * T**2,  # crosses 400 m at ~2000 s
            ("ch3", "proposed_analytic"): np.full_like(T, 400.0),
            ("ch3", "proposed_simulated"): 1e-4 * T**2 + 50.0,  # never crossed
        }
    )
    item = _item("2000", "crossover_s", "s", 0.2)
    out = verdicts(_published(items=[item]), {"st": {"errors": errors}}).set_index("id")
    assert out.loc["I/proposed_analytic", "verdict"] == "reproduced"
    assert out.loc["I/proposed_simulated", "verdict"] == "not_reproduced"
    assert out.loc["I/proposed_simulated", "reproduced"] == "never"
    hours = _item("0.55", "crossover_s", "h", 0.2)  # the same crossover printed in hours
    out = verdicts(_published(items=[hours]), {"st": {"errors": errors}}).set_index("id")
    assert out.loc["I/proposed_analytic", "verdict"] == "reproduced"
    assert out.loc["I/proposed_analytic", "reproduced"].endswith(" h")


def test_repository_file_loads_and_bad_file_names_field(tmp_path):
    data = load_published("config/published/platform_drift.yaml")
    assert len(data["items"]) == 14 and len(data["claims"]) == 7
    assert {i["kind"] for i in data["items"]} == {"approximate"}
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "paper: platform_drift\nitems:\n  - {id: X, label: f, kind: approximate, quantity: error_2h_m,"
        " value: '1', unit: km, select: {scenario: s, case: ch9, scheme: strapdown},"
        " tolerance: {rel: 0.1, reason: r}}\nclaims: []\n"
    )
    with pytest.raises(ConfigError, match=r"bad\.yaml: item 'X' \(items\[0\]\), field 'select\.case': bad value 'ch9'"):  # fmt: skip
        load_published(bad)
    bad.write_text(bad.read_text().replace("kind: approximate", "kind: exact"))
    with pytest.raises(ConfigError, match=r"field 'kind': bad value 'exact'; allowed: 'approximate'"):  # fmt: skip
        load_published(bad)
