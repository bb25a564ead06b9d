"""Verdict rules of the platform-drift paper on synthetic error curves (each rule can fail).

Synthetic results name their scenario "st" and carry a scenario config: the repository's
stationary one (at rest) or a moving one, so that where the analytic curves hold is decided
from the config, as in the pipeline.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.config import ConfigError
from pipeline.platform_drift.claims import CLAIMS
from pipeline.platform_drift.quantities import crossover, locate
from pipeline.platform_drift.scenario import build_scenario, load_scenario
from pipeline.platform_drift.validity import max_ground_speed_m_s, table2_azimuth_error_m
from pipeline.platform_drift.verdicts import load_published
from pipeline.verdicts.engine import verdict_table

T = np.arange(0.0, 7201.0, 10.0)
T_LONG = np.arange(0.0, 86401.0, 60.0)
SCENARIOS = Path("config/scenarios/platform_drift")
AT_REST = load_scenario(SCENARIOS / "stationary.yaml")
MOVING = load_scenario(SCENARIOS / "latitude_change.yaml")


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
    errors = _frame({("ch3", "strapdown"): T})
    res = {"st": {"errors": errors, "errors_long": long, "scenario": AT_REST}}
    out = verdicts(_published([claim]), res).set_index("method")["verdict"]
    assert out["proposed_analytic"] == "upheld"
    assert out["proposed_simulated"] == "not_upheld"
    no_long = verdicts(_published([claim]), {"st": {"errors": errors, "scenario": AT_REST}})
    assert no_long["verdict"].tolist() == ["not_checkable"]


def test_bounded_on_the_2h_run_against_its_first_hour():
    osc = 200 * np.abs(np.sin(T / 1600))  # a Schuler-like oscillation: its max comes early
    claim = _claim("bounded", scenario="st", case="ch3", run="main", first_s=3600, ratio=1.5)
    for grow, expected in ((1e-3 * T, "not_upheld"), (1e-8 * T**2.6, "not_upheld"), (osc, "upheld")):  # fmt: skip
        errors = _frame({("ch3", "proposed_simulated"): grow, ("ch3", "strapdown"): T})
        res = {"st": {"errors": errors, "scenario": AT_REST}}
        claim["predicate"]["scheme"] = "proposed_simulated"
        out = verdicts(_published([claim]), res)
        assert out["verdict"].tolist() == [expected], grow[-1]


def _at_rest(errors: pd.DataFrame, scenario=AT_REST, **more) -> dict:
    return {"st": {"errors": errors, "scenario": scenario, **more}}


def test_closed_form_growth_passes_table2_and_fails_t_and_t3():
    """C3: the paper's own closed form (Table 2 no. 5) passes; t, t^2 and t^3 curves fail."""
    claim = _claim(
        "closed_form", scenario="st", case="ch3", scheme="strapdown", form="table2_no5",
        slope_tol=0.1, rel_tol=0.1,
    )  # fmt: skip
    form = table2_azimuth_error_m(AT_REST, T)
    assert 4000 < form[-1] < 5000  # the paper's 'up to 4.5 km' at Tehran
    end = form[-1]
    curves = {
        "table2": (form, "upheld"),
        "table2 +5 %": (1.05 * form, "upheld"),
        "t": (end * T / T[-1], "not_upheld"),
        "t^2": (end * (T / T[-1]) ** 2, "not_upheld"),  # the paper's wording taken literally
        "t^3": (end * (T / T[-1]) ** 3, "not_upheld"),  # the abstract's 'cube'
        "table2 x 1.3": (1.3 * form, "not_upheld"),  # right shape, wrong size
    }
    for name, (y, expected) in curves.items():
        out = verdicts(_published([claim]), _at_rest(_frame({("ch3", "strapdown"): y})))
        assert out["verdict"].tolist() == [expected], name
    row = verdicts(_published([claim]), _at_rest(_frame({("ch3", "strapdown"): form}))).iloc[0]
    assert "Table 2 no. 5 2.60" in row["reproduced"]  # the closed form's own slope, not 2
    assert "the paper's 't^2' is the closed form's leading term" in row["reason"]
    moving = verdicts(_published([claim]), _at_rest(_frame({("ch3", "strapdown"): form}), MOVING))
    assert moving["verdict"].tolist() == ["not_checkable"]
    assert "Table 2 no. 5 holds for a stationary vehicle" in moving["reason"].iloc[0]


def test_final_order():
    claim = _claim("final_order", scenario="st", case="ch3", reference="strapdown", expect="reference_below")  # fmt: skip
    errors = _frame(
        {
            ("ch3", "strapdown"): 1e-4 * T**2,
            ("ch3", "proposed_analytic"): 1e-4 * T**2 + 1.0,
            ("ch3", "proposed_simulated"): 1e-4 * T**2 - 1.0,
        }
    )
    out = verdicts(_published([claim]), _at_rest(errors)).set_index("id")["verdict"]
    assert out["F/proposed_analytic"] == "upheld"
    assert out["F/proposed_simulated"] == "not_upheld"


def _moved(name: str = "stationary") -> object:
    """The repository's stationary config with a path: it keeps its name, but moves."""
    raw = yaml.safe_load((SCENARIOS / "stationary.yaml").read_text(encoding="utf-8"))
    raw["path"]["delta_lat_deg"] = -10.0
    return build_scenario(raw, Path(f"{name}.yaml"))


def test_analytic_curve_not_checkable_where_the_vehicle_moves():
    """Eqs. 32/36 hold at rest: in a moving scenario (decided from its config, whatever its
    name) their rows are not_checkable, never not_reproduced; the simulated rows are judged."""
    errors = _frame(
        {
            ("ch3", "strapdown"): 1e-4 * T**2,
            ("ch3", "proposed_analytic"): np.full_like(T, 4000.0),  # would be 'not reproduced'
            ("ch3", "proposed_simulated"): np.full_like(T, 400.0),
            ("ch1", "strapdown"): 100 + T,
            ("ch1", "proposed_analytic"): 99 + T,
            ("ch1", "proposed_simulated"): 99 + T,
        }
    )
    item = _item("2000", "crossover_s", "s")
    claim = _claim("final_order", scenario="st", case="ch1", reference="strapdown", expect="reference_above")  # fmt: skip
    published = _published([claim], [item])
    at_rest = verdicts(published, _at_rest(errors)).set_index("id")
    assert at_rest.loc["I/proposed_analytic", "verdict"] == "not_reproduced"
    assert at_rest.loc["F/proposed_analytic", "verdict"] == "upheld"
    for sc in (MOVING, _moved("stationary")):
        out = verdicts(published, _at_rest(errors, sc)).set_index("id")
        assert out.loc["I/proposed_analytic", "verdict"] == "not_checkable"
        assert out.loc["I/proposed_simulated", "verdict"] == "reproduced"
        assert out.loc["F/proposed_analytic", "verdict"] == "not_checkable"
        assert out.loc["F/proposed_simulated", "verdict"] == "upheld"
        reason = out.loc["I/proposed_analytic", "reason"]
        assert (
            "eq. 36 holds for a stationary vehicle; scenario st moves (ground speed up to" in reason
        )
        assert "eq. 32 holds for a stationary vehicle" in out.loc["F/proposed_analytic", "reason"]
    no_config = verdicts(published, {"st": {"errors": errors}}).set_index("id")
    assert no_config.loc["I/proposed_analytic", "verdict"] == "not_checkable"
    assert "no scenario config" in no_config.loc["I/proposed_analytic", "reason"]


def test_ground_speed_is_computed_from_the_config():
    assert max_ground_speed_m_s(AT_REST) == 0.0
    assert max_ground_speed_m_s(MOVING) == pytest.approx(1265, rel=0.01)  # its description
    assert max_ground_speed_m_s(_moved()) > 100.0


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
        _claim("below", scenario="st", case="ch1", reference="strapdown", from_s=300, margin_m=1.0),
    ]
    out = verdicts(_published(claims), _at_rest(errors)).set_index("id")["verdict"]
    assert out["C/proposed_analytic"] == "upheld" and out["C/proposed_simulated"] == "not_upheld"
    assert out["B/proposed_analytic"] == "not_upheld"
    errors.loc[errors["scheme"] == "proposed_analytic", "error_m"] = 1.0
    out = verdicts(_published(claims), _at_rest(errors)).set_index("id")
    assert out.loc["B/proposed_analytic", "verdict"] == "upheld"
    assert "smallest margin" in out.loc["B/proposed_analytic", "reproduced"]
    # below by less than the margin everywhere: tied within the resolution, not "better"
    errors.loc[errors["scheme"] == "proposed_analytic", "error_m"] = (100 + T) - 0.5
    out = verdicts(_published(claims), _at_rest(errors)).set_index("id")
    assert out.loc["B/proposed_analytic", "verdict"] == "not_upheld"
    assert "tied with the reference" in out.loc["B/proposed_analytic", "reproduced"]
    # tied at first (2 m both), below by more than the margin later: below for the whole run
    strap = errors.loc[errors["scheme"] == "strapdown", "error_m"].to_numpy()
    errors.loc[errors["scheme"] == "proposed_analytic", "error_m"] = strap - 1e-3 * T
    out = verdicts(_published(claims), _at_rest(errors)).set_index("id")
    assert out.loc["B/proposed_analytic", "verdict"] == "upheld"
    # above by more than the margin anywhere: not below
    errors.loc[errors["scheme"] == "proposed_analytic", "error_m"] = strap + 5.0 * (T < 1000)
    out = verdicts(_published(claims), _at_rest(errors)).set_index("id")
    assert out.loc["B/proposed_analytic", "verdict"] == "not_upheld"
    assert "above the reference by more than 1 m" in out.loc["B/proposed_analytic", "reproduced"]


def test_close_to_an_oscillating_reference_relative_to_its_max():
    """C8: the simulated curve against eq. 36, which passes through small values."""
    eq36 = 200 * np.abs(np.sin(T / 1600)) + 1.0
    claim = _claim(
        "close", scenario="st", case="ch3", scheme="proposed_simulated",
        reference="proposed_analytic", rel_tol=0.2, scale="reference_max",
    )  # fmt: skip
    for sim, expected in ((eq36 + 10.0, "upheld"), (eq36 + 1e-4 * T**2, "not_upheld")):
        errors = _frame({("ch3", "proposed_analytic"): eq36, ("ch3", "proposed_simulated"): sim})
        assert verdicts(_published([claim]), _at_rest(errors))["verdict"].tolist() == [expected]
    pointwise = {**claim, "predicate": {**claim["predicate"], "scale": "pointwise"}}
    errors = _frame({("ch3", "proposed_analytic"): eq36, ("ch3", "proposed_simulated"): eq36 + 10})
    assert verdicts(_published([pointwise]), _at_rest(errors))["verdict"].tolist() == ["not_upheld"]


def _item(value: str = "4.5", quantity: str = "error_2h_m", unit: str = "km"):
    return {
        "id": "I",
        "label": "Fig. 5 (3)",
        "kind": "approximate",
        "quantity": quantity,
        "value": value,
        "unit": unit,
        "select": {"scenario": "st", "case": "ch3", "scheme": "strapdown"},
        "printed_as": "about",
    }


def test_about_value_is_approximate_with_its_tolerance():
    for final, expected in ((4600.0, "reproduced"), (5500.0, "not_reproduced"), (4500.0, "reproduced")):  # fmt: skip
        errors = _frame({("ch3", "strapdown"): final * (T / T[-1]) ** 2})
        out = verdicts(_published(items=[_item()]), _at_rest(errors))
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
    item = _item("2000", "crossover_s", "s")
    out = verdicts(_published(items=[item]), _at_rest(errors)).set_index("id")
    assert out.loc["I/proposed_analytic", "verdict"] == "reproduced"
    assert out.loc["I/proposed_simulated", "verdict"] == "not_reproduced"
    assert out.loc["I/proposed_simulated", "reproduced"] == "never"
    hours = _item("0.55", "crossover_s", "h")  # the same crossover printed in hours
    out = verdicts(_published(items=[hours]), _at_rest(errors)).set_index("id")
    assert out.loc["I/proposed_analytic", "verdict"] == "reproduced"
    assert out.loc["I/proposed_analytic", "reproduced"].endswith(" h")


def test_repository_file_loads_and_bad_file_names_field(tmp_path):
    data = load_published("config/published/platform_drift.yaml")
    assert len(data["items"]) == 14 and len(data["claims"]) == 11
    assert {i["kind"] for i in data["items"]} == {"approximate"}
    # a value printed as 'about' is printed_as about; one printed without it is read off the
    # plot, on an axis stated once for its figure
    for item in data["items"]:
        about = "about" in item["note"].replace("(no 'about')", "")
        assert item["printed_as"] == ("about" if about else "plot"), item["id"]
        if not about:
            assert item["figure"]["label"] == item["label"] in data["figures"], item["id"]
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "paper: platform_drift\nitems:\n  - {id: X, label: f, kind: approximate, quantity: error_2h_m,"
        " value: '1', unit: km, select: {scenario: s, case: ch9, scheme: strapdown},"
        " printed_as: about}\nclaims: []\n"
    )
    with pytest.raises(ConfigError, match=r"bad\.yaml: item 'X' \(items\[0\]\), field 'select\.case': bad value 'ch9'"):  # fmt: skip
        load_published(bad)
    bad.write_text(bad.read_text().replace("kind: approximate", "kind: exact"))
    with pytest.raises(ConfigError, match=r"field 'kind': bad value 'exact'; allowed: 'approximate'"):  # fmt: skip
        load_published(bad)
