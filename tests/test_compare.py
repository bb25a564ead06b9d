"""Tests of pipeline.compare: the verdict rules, the published-file checks and the real file."""

from __future__ import annotations

import json
import re
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline import columns
from pipeline.compare import (
    SCHEMA_PATH,
    half_unit,
    load_published,
    run,
    verdicts,
)
from pipeline.north_finding import columns as nf_columns

REPO = Path(__file__).resolve().parents[1]
PUBLISHED = REPO / "config" / "published" / "north_finding.yaml"
SEED = REPO.parent / "shared" / "papers" / "000_d5833b6222974346.txt"


# --------------------------------------------------------------------------------------------
# helpers: synthetic published entries and results frames
# --------------------------------------------------------------------------------------------
def item(**kw: Any) -> dict[str, Any]:
    base = {
        "id": "T.x.L1",
        "table": "Table 1",
        "quantity": "phi_deg",
        "method": "L1",
        "sensor": "real",
        "value": None,
        "error_pct": None,
        "unit": "deg",
        "kind": "statistical",
    }
    base.update(kw)
    return base


def exact_item(**kw: Any) -> dict[str, Any]:
    return item(
        **{
            "id": "T5.psi.A1c1",
            "quantity": "psi_deg",
            "method": "A1c1",
            "sensor": "ideal",
            "kind": "exact",
            **kw,
        }
    )


def published(items: list[dict[str, Any]] = (), claims: list[dict[str, Any]] = ()) -> dict:
    return {
        "paper": "north_finding",
        "scenario": "paper",
        "items": list(items),
        "claims": list(claims),
    }


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
    table = verdicts(
        pub,
        est if est is not None else estimates([]),
        mc if mc is not None else EMPTY_TRIALS,
        eb if eb is not None else EMPTY_BUDGET,
    )
    assert list(table.columns) == columns.VERDICT_COLUMNS
    assert len(table) == 1
    return table.iloc[0]


# --------------------------------------------------------------------------------------------
# printed precision
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("printed", "half"),
    [
        ("50.0050", 5e-5),
        ("88", 0.5),
        ("0", 0.5),
        ("4.85e-8", 5e-11),
        ("0.000003614", 5e-10),
        ("22.3", 0.05),
    ],
)
def test_half_unit(printed: str, half: float) -> None:
    assert half_unit(printed) == pytest.approx(half, rel=1e-12)


# --------------------------------------------------------------------------------------------
# exact items
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("ours", "expected"),
    [
        (88.4, "not_reproduced"),
        (88.0000000001, "reproduced"),
        (88.0, "reproduced"),
        (87.99999999, "not_reproduced"),
    ],  # 1.1e-8 % > 1e-9 %
)
def test_exact_value_and_zero_error_with_tolerance(ours: float, expected: str) -> None:
    pub = published([exact_item(value="88", error_pct="0", tolerance_pct=1e-9)])
    row = one(pub, estimates([("ideal", "A1c1", "psi_deg", 88.0, ours)]))
    assert row["verdict"] == expected
    assert float(row["reproduced"]) == pytest.approx(ours, abs=1e-12)


@pytest.mark.parametrize(
    ("value", "ours", "expected"),
    [
        ("88", 88.4, "reproduced"),
        ("88", 88.6, "not_reproduced"),
        ("50.0050", 50.00505, "reproduced"),
        ("50.0050", 50.00506, "not_reproduced"),
        ("1.00002", 1.000025, "reproduced"),  # exactly half a unit, float noise absorbed
        ("4.85e-8", 4.8481e-8, "reproduced"),
        ("4.85e-8", 4.844e-8, "not_reproduced"),
    ],
)
def test_exact_value_only_uses_half_a_printed_digit(value: str, ours: float, expected: str) -> None:
    pub = published([exact_item(value=value)])
    row = one(pub, estimates([("ideal", "A1c1", "psi_deg", 88.0, ours)]))
    assert row["verdict"] == expected


@pytest.mark.parametrize(
    ("ours", "tolerance", "expected"),
    [
        (50.0 * (1 + 1e-12), 1e-9, "reproduced"),
        (50.0 * (1 + 1e-8), 1e-9, "not_reproduced"),
        (50.0 * (1 + 1e-8), None, "reproduced"),
    ],  # without tolerance_pct: half of "0" = 0.5 %
)
def test_exact_error_only_item(ours: float, tolerance: float | None, expected: str) -> None:
    extra = {} if tolerance is None else {"tolerance_pct": tolerance}
    pub = published(
        [exact_item(id="T1.phi.L1.ideal", quantity="phi_deg", method="L1", error_pct="0", **extra)]
    )
    row = one(pub, estimates([("ideal", "L1", "phi_deg", 50.0, ours)]))
    assert row["verdict"] == expected
    assert row["published"] == "0 %"


def test_exact_compares_the_ideal_row_not_the_real_one() -> None:
    pub = published([exact_item(value="88", error_pct="0", tolerance_pct=1e-9)])
    est = estimates(
        [("real", "A1c1", "psi_deg", 88.0, 88.3), ("ideal", "A1c1", "psi_deg", 88.0, 88.0)]
    )
    assert one(pub, est)["verdict"] == "reproduced"


# --------------------------------------------------------------------------------------------
# statistical items
# --------------------------------------------------------------------------------------------
def _mc_roll(seed: int = 7, n: int = 2000) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    return trials({("L1", "phi_deg"): (50.0, 50.0 + 0.001 * rng.standard_normal(n))})


@pytest.mark.parametrize(
    ("value", "expected", "rank_range"),
    [
        ("50.0010", "consistent", (80.0, 88.0)),  # +1 sigma: rank ~84
        ("49.9980", "consistent", (1.0, 4.5)),  # -2 sigma: rank ~2.3
        ("50.0050", "not_reproduced", (99.9, 100.0)),  # +5 sigma
        ("49.9960", "not_reproduced", (0.0, 0.1)),
    ],  # -4 sigma
)
def test_statistical_rank(value: str, expected: str, rank_range: tuple[float, float]) -> None:
    mc = _mc_roll()
    est = estimates([("real", "L1", "phi_deg", 50.0, 50.0002)])
    row = one(published([item(value=value, error_pct=None)]), est, mc)
    assert row["verdict"] == expected
    rank = float(re.search(r"percentile rank ([0-9.]+)", row["note"]).group(1))
    assert rank_range[0] <= rank <= rank_range[1]
    median = float(np.median(mc["estimate"]))
    assert float(row["reproduced"]) == pytest.approx(median, abs=1e-9)
    assert "MC 5-95 %" in row["note"]
    assert "noise-free real: 50.0002" in row["note"]
    assert f"published value implies error {'+' if float(value) > 50 else '-'}" in row["note"]


def test_statistical_rank_band_edges() -> None:
    # 1000 trials at 0..999; rank = 100 (#below + #equal / 2) / n: value 5 ranks 0.55 (inside),
    # 4.9 ranks 0.5 (inside, on the edge), 4 ranks 0.45 (outside), 994 ranks 99.45 (inside),
    # 995 ranks 99.55 (outside)
    mc = trials({("L1", "phi_deg"): (500.0, np.arange(1000, dtype=float))})
    values = ("5", "4.9", "4", "994", "995")
    verdict = {v: one(published([item(value=v)]), None, mc)["verdict"] for v in values}
    assert verdict == {
        "5": "consistent",
        "4.9": "consistent",
        "4": "not_reproduced",
        "994": "consistent",
        "995": "not_reproduced",
    }


# --------------------------------------------------------------------------------------------
# internal consistency of the printed table
# --------------------------------------------------------------------------------------------
def test_internal_inconsistency_detected() -> None:
    rng = np.random.default_rng(3)
    mc = trials({("L5", "acc_bias_ug"): (100.0, 78.0 + rng.standard_normal(500))})
    pub = published(
        [
            item(
                id="T3.acc_bias.L5",
                table="Table 3",
                quantity="acc_bias_ug",
                method="L5",
                unit="ug",
                value="77.4",
                error_pct="22.3",
            )
        ]
    )
    row = one(pub, None, mc)
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


def _argclaim(kind: str, expect: str, methods: list[str], quantity: str = "phi_deg") -> dict:
    return {
        "id": "C.x",
        "source": "Sec. 6",
        "text": "t",
        "predicate": {"type": kind, "quantity": quantity, "methods": methods, "expect": expect},
    }


@pytest.mark.parametrize(
    ("kind", "expect", "verdict"),
    [
        ("argmin", "L3", "upheld"),
        ("argmin", "L1", "not_upheld"),
        ("argmax", "L4", "upheld"),
        ("argmax", "L3", "not_upheld"),
    ],
)
def test_argmin_argmax(kind: str, expect: str, verdict: str) -> None:
    mc = _level_trials({"L1": 0.004, "L2": 0.0042, "L3": 0.002, "L4": 0.05})
    row = one(published(claims=[_argclaim(kind, expect, ["L1", "L2", "L3", "L4"])]), None, mc)
    assert row["kind"] == "claim"
    assert row["verdict"] == verdict
    assert row["published"] == expect
    assert row["reproduced"].startswith("L3 (rms" if kind == "argmin" else "L4 (rms")


def test_argmin_uses_rms_not_spread() -> None:
    # L1: tiny spread but a large constant offset; L2: larger spread around the truth.
    # RMS of error_pct makes L2 the best; a std-based rule would pick L1.
    mc = trials(
        {
            ("L1", "phi_deg"): (50.0, 50.01 + 1e-6 * np.arange(100)),
            ("L2", "phi_deg"): (50.0, 50.0 + 0.001 * np.sin(np.arange(100))),
        }
    )
    row = one(published(claims=[_argclaim("argmin", "L2", ["L1", "L2"])]), None, mc)
    assert row["verdict"] == "upheld"


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
    assert "A6" in row["note"] and "gives no gyro_bias_rad_s estimate" in row["note"]
    # ... and checkable once the results do contain the method's rows
    mc2 = pd.concat([mc, trials({("A6", "gyro_bias_rad_s"): (gb, gb + np.zeros(100))})])
    assert one(published(claims=[claim]), None, mc2)["verdict"] == "upheld"


@pytest.mark.parametrize(("sigma_l2", "verdict"), [(0.0041, "upheld"), (0.008, "not_upheld")])
def test_close(sigma_l2: float, verdict: str) -> None:
    mc = _level_trials({"L1": 0.004, "L2": sigma_l2})
    claim = {
        "id": "C.c",
        "source": "s",
        "text": "t",
        "predicate": {
            "type": "close",
            "a": {"method": "L1", "quantity": "phi_deg"},
            "b": {"method": "L2", "quantity": "phi_deg"},
            "rel_tol": 0.2,
        },
    }
    assert one(published(claims=[claim]), None, mc)["verdict"] == verdict


@pytest.mark.parametrize(("misalignment", "verdict"), [(-22.0, "upheld"), (-0.5, "not_upheld")])
def test_dominant_source(misalignment: float, verdict: str) -> None:
    t = 100.0
    eb = budget(
        [
            ("L5", "acc_bias_ug", "scale_factor", t, 0.005),
            ("L5", "acc_bias_ug", "misalignment", t, misalignment),
            ("L5", "acc_bias_ug", "bias", t, 0.0),
            ("L5", "acc_bias_ug", "noise", t, 1.0),
            ("L5", "acc_bias_ug", "all_deterministic", t, -60.0),
        ]
    )  # never a candidate
    claim = {
        "id": "C.d",
        "source": "s",
        "text": "t",
        "predicate": {
            "type": "dominant_source",
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
# malformed published files
# --------------------------------------------------------------------------------------------
GOOD_ITEM = {
    "id": "T1.phi.L1",
    "table": "Table 1",
    "quantity": "phi_deg",
    "method": "L1",
    "sensor": "real",
    "value": "50.0050",
    "error_pct": "0.0110",
    "unit": "deg",
    "kind": "statistical",
}


def _write(tmp_path: Path, items: list[dict], name: str = "bad_published.yaml") -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(published(items), sort_keys=False), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("change", "field", "bad"),
    [
        ({"kind": "approximate"}, "kind", "approximate"),
        ({"value": "5O.0"}, "value", "5O.0"),
        ({"method": "L9"}, "method", "L9"),
        ({"colour": "red"}, "colour", "colour"),
        ({"quantity": "psi_deg"}, "quantity", "psi_deg"),  # L1 gives no azimuth
        ({"sensor": "ideal"}, "sensor", "ideal"),  # statistical items are real-sensor
        ({"unit": "rad_s"}, "unit", "rad_s"),
    ],
)
def test_malformed_item_raises_valueerror_naming_file_id_field(
    tmp_path: Path, change: dict, field: str, bad: str
) -> None:
    path = _write(
        tmp_path, [{**GOOD_ITEM, "id": "T1.phi.L2", "method": "L2"}, {**GOOD_ITEM, **change}]
    )
    with pytest.raises(ValueError) as info:
        load_published(path)
    message = str(info.value)
    assert "bad_published.yaml" in message
    assert "'T1.phi.L1'" in message
    assert f"field '{field}'" in message
    assert bad in message
    assert "allowed" in message


def test_duplicate_id(tmp_path: Path) -> None:
    path = _write(tmp_path, [GOOD_ITEM, {**GOOD_ITEM, "value": "50.0056"}])
    with pytest.raises(ValueError, match=r"bad_published\.yaml.*'T1\.phi\.L1'.*field 'id'.*unique"):
        load_published(path)


def test_missing_field_and_bad_claim(tmp_path: Path) -> None:
    no_unit = {k: v for k, v in GOOD_ITEM.items() if k != "unit"}
    with pytest.raises(ValueError, match=r"'T1\.phi\.L1'.*field 'unit'.*missing"):
        load_published(_write(tmp_path, [no_unit]))
    data = published(
        [GOOD_ITEM],
        [
            {
                "id": "C1.x",
                "source": "s",
                "text": "t",
                "predicate": {
                    "type": "argmin",
                    "quantity": "phi_deg",
                    "methods": ["L1", "L2"],
                    "expect": "L3",
                },
            }
        ],
    )
    path = tmp_path / "claims.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    with pytest.raises(ValueError, match=r"claims\.yaml.*'C1\.x'.*predicate\.expect.*'L3'"):
        load_published(path)
    data["claims"][0]["predicate"]["type"] = "median"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    with pytest.raises(ValueError, match=r"'C1\.x'.*predicate\.type.*'median'.*argmin"):
        load_published(path)


def test_not_yaml(tmp_path: Path) -> None:
    path = tmp_path / "broken.yaml"
    path.write_text("items: [\n", encoding="utf-8")
    with pytest.raises(ValueError, match=r"broken\.yaml"):
        load_published(path)


# --------------------------------------------------------------------------------------------
# the real published file and schema
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
    return [entry[k] for k in ("value", "error_pct") if entry[k] is not None]


def test_real_published_file_has_one_item_per_printed_number() -> None:
    pub = load_published(PUBLISHED)
    assert pub["paper"] == "north_finding"
    items = pub["items"]
    per_table = Counter(int(i["table"].split()[1]) for i in items)
    numbers = Counter()
    for i in items:
        numbers[int(i["table"].split()[1])] += len(_printed(i))
    assert dict(per_table) == ITEMS_PER_TABLE
    assert dict(numbers) == NUMBERS_PER_TABLE
    assert len(items) == 43 and sum(numbers.values()) == 76
    assert len(pub["claims"]) == 10
    kinds = Counter((i["kind"], i["sensor"]) for i in items)
    assert kinds == {("statistical", "real"): 22, ("exact", "ideal"): 21}
    # spot checks of the transcription
    by_id = {i["id"]: i for i in items}
    assert by_id["T1.phi.L1"]["value"] == "50.0050"
    assert by_id["T3.acc_bias.L5"]["error_pct"] == "22.3"
    assert by_id["T10.gyro_bias.A4"]["value"] == "4.49e-8"
    assert by_id["T11.gyro_scale.A5"]["error_pct"] == "0.00003613"


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
        for s in _printed(i):
            ours[re.sub(r"e-8$", "", s)] += 1  # gyro bias: the seed prints the x10^-8 mantissa
    assert ours == seed


def test_schema_enums_match_columns() -> None:
    schema = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    defs = schema["$defs"]
    assert tuple(defs["method"]["enum"]) == nf_columns.METHODS
    assert tuple(defs["quantity"]["enum"]) == nf_columns.QUANTITIES
    assert tuple(defs["item"]["properties"]["sensor"]["enum"]) == nf_columns.SENSORS
    assert set(defs["item"]["properties"]["kind"]["enum"]) == set(columns.VERDICT_KINDS) - {"claim"}
    dominant = defs["predicate"]["allOf"][2]["then"]["properties"]["expect"]["enum"]
    assert set(dominant) == set(nf_columns.ERROR_SOURCES) - {"all_deterministic"}


# --------------------------------------------------------------------------------------------
# end to end
# --------------------------------------------------------------------------------------------
def test_run_writes_verdicts_atomically(tmp_path: Path) -> None:
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
        tmp_path, [GOOD_ITEM, exact_item(value="88", error_pct="0", tolerance_pct=1e-9)], "pub.yaml"
    )
    data = yaml.safe_load(pub_path.read_text(encoding="utf-8"))
    data["claims"] = [_argclaim("argmin", "L1", ["L1", "L2"])]
    pub_path.write_text(yaml.safe_dump(data), encoding="utf-8")
    out = tmp_path / "verdicts" / "verdicts.csv"
    table = run(pub_path, scenario, out)
    written = pd.read_csv(out, dtype=str, keep_default_na=False)
    assert list(written.columns) == columns.VERDICT_COLUMNS
    assert (
        list(written["verdict"]) == list(table["verdict"]) == ["consistent", "reproduced", "upheld"]
    )
    assert set(written["verdict"]) <= set(columns.VERDICTS)
    assert sorted(p.name for p in out.parent.iterdir()) == ["verdicts.csv"]  # no temp left
    (scenario / "mc_trials.csv").unlink()
    with pytest.raises(ValueError, match=r"mc_trials\.csv"):
        run(pub_path, scenario, out)
