"""North-finding verdicts: the paper's locator and claim tests on the shared engine, the
published file's paper-specific checks, and the real published file."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline import columns
from pipeline.config import ConfigError
from pipeline.north_finding import columns as nf_columns
from pipeline.north_finding.claims import CLAIMS
from pipeline.north_finding.quantities import locate
from pipeline.north_finding.verdicts import load_published, write_verdicts
from pipeline.verdicts.engine import verdict_table

REPO = Path(__file__).resolve().parents[2]
PUBLISHED = REPO / "config" / "published" / "north_finding.yaml"
SEED = REPO.parent / "shared" / "papers" / "000_d5833b6222974346.txt"
EXACT_ZERO = {"abs": 1e-9, "applies_to": "error_pct", "reason": "an exact inversion prints 0 %"}


# --------------------------------------------------------------------------------------------
# helpers: synthetic published entries and results frames
# --------------------------------------------------------------------------------------------
def item(**kw: Any) -> dict[str, Any]:
    base = {
        "id": "T.x.L1",
        "label": "Table 1",
        "quantity": "phi_deg",
        "select": {"method": "L1", "sensor": "real"},
        "value": None,
        "error_pct": None,
        "unit": "deg",
        "kind": "statistical",
    }
    base.update(kw)
    return base


def exact_item(method: str = "A1c1", quantity: str = "psi_deg", **kw: Any) -> dict[str, Any]:
    return item(
        **{
            "id": "T5.psi.A1c1",
            "quantity": quantity,
            "select": {"method": method, "sensor": "ideal"},
            "kind": "exact",
            **kw,
        }
    )


def published(items: list[dict[str, Any]] = (), claims: list[dict[str, Any]] = ()) -> dict:
    return {"paper": "north_finding", "items": list(items), "claims": list(claims)}


def estimates(rows: list[tuple[str, str, str, float, float]]) -> pd.DataFrame:
    """rows of (sensor, method, quantity, truth, estimate)."""
    out = [
        {
            "sensor": s,
            "method": m,
            "quantity": q,
            "truth": t,
            "estimate": e,
            "error_pct": 100.0 * (e - t) / abs(t),
        }
        for s, m, q, t, e in rows
    ]
    return pd.DataFrame(out, columns=nf_columns.ESTIMATE_COLUMNS)


def trials(spec: dict[tuple[str, str], tuple[float, np.ndarray]]) -> pd.DataFrame:
    """spec: (method, quantity) -> (truth, array of estimates, one per trial)."""
    frames = []
    for (method, quantity), (truth, sample) in spec.items():
        frames.append(
            pd.DataFrame(
                {
                    "trial": np.arange(sample.size),
                    "method": method,
                    "quantity": quantity,
                    "truth": truth,
                    "estimate": sample,
                    "error_pct": 100.0 * (sample - truth) / abs(truth),
                }
            )
        )
    if not frames:
        return pd.DataFrame(columns=nf_columns.MC_TRIAL_COLUMNS)
    return pd.concat(frames, ignore_index=True)[nf_columns.MC_TRIAL_COLUMNS]


def budget(rows: list[tuple[str, str, str, float, float]]) -> pd.DataFrame:
    """rows of (method, quantity, source, truth, error)."""
    out = [
        {"method": m, "quantity": q, "source": s, "error": e, "error_pct": 100.0 * e / abs(t)}
        for m, q, s, t, e in rows
    ]
    return pd.DataFrame(out, columns=nf_columns.ERROR_BUDGET_COLUMNS)


EMPTY_TRIALS = trials({})
EMPTY_BUDGET = budget([])


def one(
    pub: dict,
    est: pd.DataFrame | None = None,
    mc: pd.DataFrame | None = None,
    eb: pd.DataFrame | None = None,
) -> pd.Series:
    results = {
        "estimates": est if est is not None else estimates([]),
        "mc_trials": mc if mc is not None else EMPTY_TRIALS,
        "error_budget": eb if eb is not None else EMPTY_BUDGET,
    }
    table = verdict_table(pub, locate, CLAIMS, results)
    assert list(table.columns) == columns.VERDICT_FILE_COLUMNS
    assert len(table) == 1
    return table.iloc[0]


# --------------------------------------------------------------------------------------------
# exact items: the ideal row of estimates.csv
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("ours", "expected"),
    [
        (88.4, "not_reproduced"),  # value passes (rounding), % error 0.45 % > 1e-9 %
        (88.0000000001, "reproduced"),
        (88.0, "reproduced"),
        (87.99999999, "not_reproduced"),  # 1.1e-8 % > 1e-9 %
    ],
)
def test_exact_value_and_zero_error_with_tolerance(ours: float, expected: str) -> None:
    pub = published([exact_item(value="88", error_pct="0", tolerance=EXACT_ZERO)])
    row = one(pub, estimates([("ideal", "A1c1", "psi_deg", 88.0, ours)]))
    assert row["verdict"] == expected
    assert float(row["reproduced"]) == pytest.approx(ours, abs=1e-12)
    assert "an exact inversion prints 0 %" in row["tolerance"]


@pytest.mark.parametrize(
    ("value", "ours", "expected"),
    [
        ("88", 88.4, "reproduced"),  # rounded
        ("88", 88.6, "reproduced"),  # truncated
        ("88", 89.01, "not_reproduced"),
        ("88", 87.4, "not_reproduced"),
        ("50.0050", 50.00505, "reproduced"),
        ("50.0050", 50.00516, "not_reproduced"),
        ("1.00002", 1.000025, "reproduced"),  # exactly half a unit, float noise absorbed
        ("4.85e-8", 4.8481e-8, "reproduced"),
        ("4.85e-8", 4.844e-8, "not_reproduced"),
    ],
)
def test_exact_value_rounded_or_truncated(value: str, ours: float, expected: str) -> None:
    row = one(
        published([exact_item(value=value)]), estimates([("ideal", "A1c1", "psi_deg", 88.0, ours)])
    )
    assert row["verdict"] == expected


def test_table_8_truncated_value_is_reproduced() -> None:
    """Table 8 prints 1.0000199 for our 1.0000199999907: the paper truncated (issue 11)."""
    it = exact_item("A5", "gyro_scale_approx", id="T8", value="1.0000199", error_pct="0", unit="dimensionless")  # fmt: skip
    truth = 1.00002
    good = estimates([("ideal", "A5", "gyro_scale_approx", truth, 1.0000199999907)])
    row = one(published([it]), good)
    assert row["verdict"] == "reproduced" and "truncated to the printed 1.0000199" in row["reason"]
    bad = estimates([("ideal", "A5", "gyro_scale_approx", truth, 1.00002005)])
    assert one(published([it]), bad)["verdict"] == "not_reproduced"


@pytest.mark.parametrize(
    ("ours", "tolerance", "expected"),
    [
        (50.0 * (1 + 1e-12), EXACT_ZERO, "reproduced"),
        (50.0 * (1 + 1e-8), EXACT_ZERO, "not_reproduced"),
        (50.0 * (1 + 1e-8), None, "reproduced"),  # without it: the printed "0" accepts 1e-6 %
    ],
)
def test_exact_error_only_item(ours: float, tolerance: dict | None, expected: str) -> None:
    extra = {} if tolerance is None else {"tolerance": tolerance}
    it = exact_item("L1", "phi_deg", id="T1.phi.L1.ideal", error_pct="0", **extra)
    row = one(published([it]), estimates([("ideal", "L1", "phi_deg", 50.0, ours)]))
    assert row["verdict"] == expected
    assert row["published"] == "0 %"


def test_exact_compares_the_ideal_row_not_the_real_one() -> None:
    pub = published([exact_item(value="88", error_pct="0", tolerance=EXACT_ZERO)])
    est = estimates(
        [("real", "A1c1", "psi_deg", 88.0, 88.3), ("ideal", "A1c1", "psi_deg", 88.0, 88.0)]
    )
    assert one(pub, est)["verdict"] == "reproduced"
    assert one(pub, est[est["sensor"] == "real"])["verdict"] == "not_checkable"


# --------------------------------------------------------------------------------------------
# statistical items: the Monte Carlo of mc_trials.csv, the noise-free real row beside it
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("value", "expected"), [("50.0010", "consistent"), ("50.0050", "not_reproduced")]
)
def test_statistical_uses_the_monte_carlo_and_the_noise_free_row(value: str, expected: str) -> None:
    rng = np.random.default_rng(7)
    mc = trials({("L1", "phi_deg"): (50.0, 50.0 + 0.001 * rng.standard_normal(2000))})
    est = estimates([("real", "L1", "phi_deg", 50.0, 50.0002)])
    row = one(published([item(value=value)]), est, mc)
    assert row["verdict"] == expected
    assert float(row["reproduced"]) == pytest.approx(float(np.median(mc["estimate"])), abs=1e-9)
    assert "MC 5-95 %" in row["note"] and "noise-free real: 50.0002" in row["note"]
    assert f"published value implies error {'+' if float(value) > 50 else '-'}" in row["note"]
    assert "percentile rank" in row["reason"] and "of the published value wide" in row["tolerance"]


def test_statistical_without_monte_carlo_rows_is_not_checkable() -> None:
    row = one(published([item(value="50.0010")]))
    assert row["verdict"] == "not_checkable" and "mc_trials.csv" in row["reason"]


# --------------------------------------------------------------------------------------------
# internal consistency of the printed table
# --------------------------------------------------------------------------------------------
def test_internal_inconsistency_detected() -> None:
    rng = np.random.default_rng(3)
    mc = trials({("L5", "acc_bias_ug"): (100.0, 78.0 + rng.standard_normal(500))})
    it = item(
        id="T3.acc_bias.L5",
        label="Table 3",
        quantity="acc_bias_ug",
        select={"method": "L5", "sensor": "real"},
        unit="ug",
        value="77.4",
        error_pct="22.3",
    )
    row = one(published([it]), None, mc)
    assert (
        "table internally inconsistent: value implies 22.60 %, table prints 22.3 %" in row["note"]
    )


@pytest.mark.parametrize(
    ("value", "error_pct", "truth"),
    [
        ("77.7", "22.3", 100.0),
        ("29.9995", "0.0015", 30.0),  # 29.9995 may be 29.99955 -> 0.0015 %: rounding, not an error
        ("1.000068", "0.0018", 1.00005),
    ],
)
def test_internally_consistent_rows_not_flagged(value: str, error_pct: str, truth: float) -> None:
    mc = trials({("L1", "phi_deg"): (truth, np.full(10, truth))})
    row = one(published([item(value=value, error_pct=error_pct)]), None, mc)
    assert "inconsistent" not in row["note"]


# --------------------------------------------------------------------------------------------
# claims
# --------------------------------------------------------------------------------------------
def _level_trials(sigmas: dict[str, float], quantity: str = "phi_deg") -> pd.DataFrame:
    rng = np.random.default_rng(11)
    return trials(
        {(m, quantity): (50.0, 50.0 + s * rng.standard_normal(400)) for m, s in sigmas.items()}
    )


def _argclaim(test: str, expect: str, methods: list[str], quantity: str = "phi_deg") -> dict:
    return {
        "id": "C.x",
        "label": "Sec. 6",
        "source": "Sec. 6",
        "text": "t",
        "predicate": {"test": test, "quantity": quantity, "methods": methods, "expect": expect},
    }


@pytest.mark.parametrize(
    ("test", "expect", "verdict"),
    [
        ("argmin", "L3", "upheld"),
        ("argmin", "L1", "not_upheld"),
        ("argmax", "L4", "upheld"),
        ("argmax", "L3", "not_upheld"),
    ],
)
def test_argmin_argmax(test: str, expect: str, verdict: str) -> None:
    mc = _level_trials({"L1": 0.004, "L2": 0.0042, "L3": 0.002, "L4": 0.05})
    row = one(published(claims=[_argclaim(test, expect, ["L1", "L2", "L3", "L4"])]), None, mc)
    assert row["kind"] == "claim"
    assert row["verdict"] == verdict
    assert row["published"] == expect
    assert row["reproduced"].startswith("L3 (rms" if test == "argmin" else "L4 (rms")
    assert row["reason"].startswith(f"test {test}: ")


def test_argmin_uses_rms_not_spread() -> None:
    # L1: tiny spread but a large constant offset; L2: larger spread around the truth.
    # RMS of error_pct makes L2 the best; a std-based rule would pick L1.
    mc = trials(
        {
            ("L1", "phi_deg"): (50.0, 50.01 + 1e-6 * np.arange(100)),
            ("L2", "phi_deg"): (50.0, 50.0 + 0.001 * np.sin(np.arange(100))),
        }
    )
    assert one(published(claims=[_argclaim("argmin", "L2", ["L1", "L2"])]), None, mc)["verdict"] == "upheld"  # fmt: skip
    assert one(published(claims=[_argclaim("argmin", "L1", ["L1", "L2"])]), None, mc)["verdict"] == "not_upheld"  # fmt: skip


def test_not_checkable_when_a_method_lacks_the_quantity() -> None:
    rng = np.random.default_rng(5)
    gb = 4.8481368e-8
    mc = trials(
        {
            ("A4", "gyro_bias_rad_s"): (gb, gb * (1 + 0.01 * rng.standard_normal(100))),
            ("A6", "gyro_scale"): (1.00002, 1.00002 + 1e-6 * rng.standard_normal(100)),
        }
    )
    claim = _argclaim("argmin", "A6", ["A4", "A6"], quantity="gyro_bias_rad_s")
    row = one(published(claims=[claim]), None, mc)
    assert row["verdict"] == "not_checkable"
    assert "A6" in row["reason"] and "gives no gyro_bias_rad_s estimate" in row["reason"]
    # ... and checkable once the results do contain the method's rows
    mc2 = pd.concat([mc, trials({("A6", "gyro_bias_rad_s"): (gb, gb + np.zeros(100))})])
    assert one(published(claims=[claim]), None, mc2)["verdict"] == "upheld"


@pytest.mark.parametrize(("sigma_l2", "verdict"), [(0.0041, "upheld"), (0.008, "not_upheld")])
def test_close(sigma_l2: float, verdict: str) -> None:
    mc = _level_trials({"L1": 0.004, "L2": sigma_l2})
    claim = {
        "id": "C.c",
        "label": "Sec. 6",
        "text": "t",
        "predicate": {
            "test": "close",
            "a": {"method": "L1", "quantity": "phi_deg"},
            "b": {"method": "L2", "quantity": "phi_deg"},
            "rel_tol": 0.2,
        },
    }
    row = one(published(claims=[claim]), None, mc)
    assert row["verdict"] == verdict and "0.2" in row["tolerance"]


@pytest.mark.parametrize(("misalignment", "verdict"), [(-22.0, "upheld"), (-0.5, "not_upheld")])
def test_dominant_source(misalignment: float, verdict: str) -> None:
    t = 100.0
    eb = budget(
        [
            ("L5", "acc_bias_ug", "scale_factor", t, 0.005),
            ("L5", "acc_bias_ug", "misalignment", t, misalignment),
            ("L5", "acc_bias_ug", "bias", t, 0.0),
            ("L5", "acc_bias_ug", "noise", t, 1.0),
            ("L5", "acc_bias_ug", "all_deterministic", t, -60.0),  # never a candidate
        ]
    )
    claim = {
        "id": "C.d",
        "label": "Sec. 6",
        "text": "t",
        "predicate": {
            "test": "dominant_source",
            "method": "L5",
            "quantity": "acc_bias_ug",
            "expect": "misalignment",
        },
    }
    row = one(published(claims=[claim]), None, None, eb)
    assert row["verdict"] == verdict
    assert row["reproduced"].startswith("misalignment" if verdict == "upheld" else "noise")
    assert one(published(claims=[claim]))["verdict"] == "not_checkable"  # empty budget


# --------------------------------------------------------------------------------------------
# paper-specific checks of the published file
# --------------------------------------------------------------------------------------------
GOOD_ITEM = item(id="T1.phi.L1", value="50.0050", error_pct="0.0110")


def _write(tmp_path: Path, items: list[dict], claims: list[dict] = (), name: str = "bad_published.yaml") -> Path:  # fmt: skip
    path = tmp_path / name
    path.write_text(yaml.safe_dump(published(items, claims), sort_keys=False), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("change", "field", "bad"),
    [
        ({"kind": "approximate", "printed_as": "about"}, "kind", "approximate"),
        ({"select": {"method": "L9", "sensor": "real"}}, "select.method", "L9"),
        ({"select": {"method": "L1", "sensor": "real", "case": "x"}}, "select.case", "x"),
        ({"quantity": "psi_deg"}, "quantity", "psi_deg"),  # L1 gives no azimuth
        ({"select": {"method": "L1", "sensor": "ideal"}}, "select.sensor", "ideal"),  # real only
        ({"unit": "rad_s"}, "unit", "rad_s"),
        ({"error_pct": "-0.1"}, "error_pct", "-0.1"),
    ],
)
def test_malformed_item_names_file_id_field(
    tmp_path: Path, change: dict, field: str, bad: str
) -> None:
    other = {**GOOD_ITEM, "id": "T1.phi.L2", "select": {"method": "L2", "sensor": "real"}}
    path = _write(tmp_path, [other, {**GOOD_ITEM, **change}])
    with pytest.raises(ConfigError) as info:
        load_published(path)
    message = str(info.value)
    assert "bad_published.yaml" in message and "'T1.phi.L1'" in message
    assert f"field {field!r}" in message and bad in message and "allowed" in message
    assert "'T1.phi.L2'" not in message
    assert load_published(_write(tmp_path, [other, GOOD_ITEM], name="good.yaml"))


def test_bad_claim_arguments(tmp_path: Path) -> None:
    claim = _argclaim("argmin", "L3", ["L1", "L2"])
    with pytest.raises(ConfigError, match=r"'C\.x'.*predicate\.expect.*'L3'.*predicate's methods"):
        load_published(_write(tmp_path, [GOOD_ITEM], [claim]))
    claim["predicate"]["test"] = "median"
    with pytest.raises(ConfigError, match=r"'C\.x'.*predicate\.test.*'median'.*argmin"):
        load_published(_write(tmp_path, [GOOD_ITEM], [claim]))
    claim = _argclaim("argmin", "L1", ["L1", "L9"])
    with pytest.raises(ConfigError, match=r"'C\.x'.*predicate\.methods\[1\].*'L9'"):
        load_published(_write(tmp_path, [GOOD_ITEM], [claim]))
    assert load_published(_write(tmp_path, [GOOD_ITEM], [_argclaim("argmin", "L1", ["L1", "L2"])]))


# --------------------------------------------------------------------------------------------
# the real published file
# --------------------------------------------------------------------------------------------
# Counted by hand from the seed's Tables 1-12 (one item per table row and sensor column; a
# printed number is one cell of a value or % error column):
#   Table 1 roll: 4 rows x (value, % real, % ideal) -> 8 items (4 real + 4 ideal), 12 numbers
#   Table 2 pitch: same -> 8 items, 12 numbers
#   Table 3 acc bias, Table 4 acc S: 1 row x 3 columns -> 2 items, 3 numbers each
#   Table 5 psi ideal: 6 rows x (value, %) -> 6 items, 12 numbers
#   Table 6 gyro bias ideal: 1 row -> 1 item, 2 numbers
#   Table 7 gyro S ideal: 3 rows -> 3 items, 6 numbers
#   Table 8 gyro S_approx ideal: 1 row -> 1 item, 2 numbers
#   Table 9 psi real: 6 rows -> 6 items, 12 numbers
#   Table 10 gyro bias real: 1 row -> 1 item, 2 numbers
#   Table 11 gyro S real: 3 rows -> 3 items, 6 numbers
#   Table 12 gyro S_approx real: 2 rows -> 2 items, 4 numbers
ITEMS_PER_TABLE = {1: 8, 2: 8, 3: 2, 4: 2, 5: 6, 6: 1, 7: 3, 8: 1, 9: 6, 10: 1, 11: 3, 12: 2}
NUMBERS_PER_TABLE = {1: 12, 2: 12, 3: 3, 4: 3, 5: 12, 6: 2, 7: 6, 8: 2, 9: 12, 10: 2, 11: 6, 12: 4}


def _printed(entry: dict) -> list[str]:
    return [entry[k] for k in ("value", "error_pct") if entry.get(k) is not None]


def test_real_published_file_has_one_item_per_printed_number() -> None:
    pub = load_published(PUBLISHED)
    assert pub["paper"] == "north_finding"
    items = [i for i in pub["items"] if i["label"].startswith("Table ")]
    text = [i for i in pub["items"] if not i["label"].startswith("Table ")]
    assert [(i["id"], i["kind"], i["value"]) for i in text] == [("S5.acc_bias_error.L5", "approximate", "22")]  # fmt: skip
    per_table = Counter(int(i["label"].split()[1]) for i in items)
    numbers: Counter[int] = Counter()
    for i in items:
        numbers[int(i["label"].split()[1])] += len(_printed(i))
    assert dict(per_table) == ITEMS_PER_TABLE
    assert dict(numbers) == NUMBERS_PER_TABLE
    assert len(items) == 43 and sum(numbers.values()) == 76
    assert len(pub["claims"]) == 10
    kinds = Counter((i["kind"], i["select"]["sensor"]) for i in items)
    assert kinds == {("statistical", "real"): 22, ("exact", "ideal"): 21}
    # every stated tolerance has its reason; Table 8 (an approximation) states none
    stated = [i["id"] for i in items if "tolerance" in i]
    assert len(stated) == 20 and "T8.gyro_scale_approx.A5" not in stated
    assert all(i["tolerance"]["reason"] for i in items if "tolerance" in i)
    by_id = {i["id"]: i for i in items}
    assert by_id["T1.phi.L1"]["value"] == "50.0050"
    assert by_id["T3.acc_bias.L5"]["error_pct"] == "22.3"
    assert by_id["T10.gyro_bias.A4"]["value"] == "4.49e-8"
    assert by_id["T11.gyro_scale.A5"]["error_pct"] == "0.00003613"


@pytest.mark.skipif(not SEED.is_file(), reason="seed OCR not available")
def test_about_values_are_approximate() -> None:
    """Every result the seed prints as "about" (حدود, before a number of percent) is an
    approximate item, and no exact or statistical item carries such a number (issue 11)."""
    text = SEED.read_text(encoding="utf-8").translate(str.maketrans("۰۱۲۳۴۵۶۷۸۹", "0123456789"))
    about = re.findall(r"حدود\s*([0-9]+(?:,[0-9]+)?)\s*درصد", text)
    assert about.count("5") == 2  # the noise "of about 5 % of the nominal values" (scenario)
    results = {a.replace(",", ".") for a in about} - {"5"}
    items = load_published(PUBLISHED)["items"]
    approximate = {i["value"] for i in items if i["kind"] == "approximate"}
    assert approximate == results == {"22"}
    s5 = next(i for i in items if i["kind"] == "approximate")
    assert s5["printed_as"] == "about" and "tolerance" not in s5


@pytest.mark.skipif(not SEED.is_file(), reason="seed OCR not available")
def test_real_published_numbers_match_the_seed_tables() -> None:
    """Every number cell of the seed's table rows, as a multiset, equals the YAML's strings."""
    text = SEED.read_text(encoding="utf-8").translate(str.maketrans("۰۱۲۳۴۵۶۷۸۹", "0123456789"))
    seed: Counter[str] = Counter()
    for line in text.splitlines():
        cells = line.split("\t")
        if len(cells) >= 2 and cells[-1].startswith("روش"):  # a table row ends with "method ..."
            for cell in cells[:-1]:
                if re.fullmatch(r"[0-9]+(,[0-9]+)?", cell.strip()):
                    seed[cell.strip().replace(",", ".")] += 1
    ours: Counter[str] = Counter()
    for i in load_published(PUBLISHED)["items"]:
        if not i["label"].startswith("Table "):
            continue  # the text's "about 22 %" (test_about_values_are_approximate)
        for s in _printed(i):
            ours[re.sub(r"e-8$", "", s)] += 1  # gyro bias: the seed prints the x10^-8 mantissa
    assert ours == seed


def test_claim_tests_accept_the_paper_s_error_sources() -> None:
    schema = CLAIMS.tests["dominant_source"].args_schema
    assert set(schema["properties"]["expect"]["enum"]) == set(nf_columns.ERROR_SOURCES) - {"all_deterministic"}  # fmt: skip
    assert sorted(CLAIMS.names()) == ["argmax", "argmin", "close", "dominant_source"]


# --------------------------------------------------------------------------------------------
# end to end
# --------------------------------------------------------------------------------------------
def test_write_verdicts_reads_the_scenario_folder(tmp_path: Path) -> None:
    scenario = tmp_path / "results" / "paper"
    scenario.mkdir(parents=True)
    rng = np.random.default_rng(2024)
    estimates(
        [("ideal", "A1c1", "psi_deg", 88.0, 88.0), ("real", "L1", "phi_deg", 50.0, 50.001)]
    ).to_csv(scenario / "estimates.csv", index=False)
    trials(
        {
            ("L1", "phi_deg"): (50.0, 50.001 + 0.002 * rng.standard_normal(300)),
            ("L2", "phi_deg"): (50.0, 50.0 + 0.004 * rng.standard_normal(300)),
        }
    ).to_csv(scenario / "mc_trials.csv", index=False)
    budget([]).to_csv(scenario / "error_budget.csv", index=False)
    pub_path = _write(
        tmp_path,
        [GOOD_ITEM, exact_item(value="88", error_pct="0", tolerance=EXACT_ZERO)],
        [_argclaim("argmin", "L1", ["L1", "L2"])],
        "pub.yaml",
    )
    out = tmp_path / "verdicts" / "verdicts.csv"
    table = write_verdicts(pub_path, scenario, out)
    written = pd.read_csv(out, dtype=str, keep_default_na=False)
    assert list(written.columns) == columns.VERDICT_FILE_COLUMNS
    assert list(written["verdict"]) == list(table["verdict"]) == ["consistent", "reproduced", "upheld"]  # fmt: skip
    (scenario / "mc_trials.csv").unlink()
    with pytest.raises(ValueError, match=r"mc_trials\.csv"):
        write_verdicts(pub_path, scenario, out)
