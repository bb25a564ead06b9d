"""The shared verdict engine (pipeline/verdicts): kinds, claim registry, published format.

Every rule is tested both ways (a value that must pass and one that must fail); no paper is
named: the items are synthetic.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.columns import VERDICT_FILE_COLUMNS, VERDICT_KINDS, VERDICTS
from pipeline.config import ConfigError
from pipeline.verdicts import engine, kinds, printed
from pipeline.verdicts.claims import ClaimRegistry, ClaimResult
from pipeline.verdicts.kinds import Found, judge
from pipeline.verdicts.published import load_published
from pipeline.verdicts.reading import with_axis

REPO = Path(__file__).resolve().parents[2]


def item(**kw: Any) -> dict[str, Any]:
    base = {"id": "X1", "label": "Table 1", "kind": "exact", "quantity": "x_m", "value": "1.5"}
    base.update(kw)
    return {k: v for k, v in base.items() if v is not None}


# --------------------------------------------------------------------------------------------
# printed precision: rounding or truncation
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("ours", "text", "expected"),
    [
        (1.0000199999907, "1.0000199", "truncated"),  # north_finding Table 8
        (1.00001985, "1.0000199", "rounded"),
        (1.0000201, "1.0000199", ""),
        (1.00001984, "1.0000199", ""),  # below the printed value by more than half a unit
        (88.4, "88", "rounded"),
        (88.99, "88", "truncated"),
        (89.0, "88", ""),
        (-2.57, "-2.5", "truncated"),
        (-2.45, "-2.5", "rounded"),
        (-2.61, "-2.5", ""),
        (2.57, "-2.5", ""),  # the sign matters
        (4.8481e-8, "4.85e-8", "rounded"),
        (4.859e-8, "4.85e-8", "truncated"),
        (4.86e-8, "4.85e-8", ""),
        (1.000025, "1.00002", "rounded"),  # exactly half a unit: float noise absorbed
        (float("nan"), "1", ""),
    ],
)
def test_equals_printed_rounding_or_truncation(ours: float, text: str, expected: str) -> None:
    assert printed.equals_printed(ours, text) == (bool(expected), expected)


@pytest.mark.parametrize(
    ("text", "half"),
    [("50.0050", 5e-5), ("88", 0.5), ("0", 0.5), ("4.85e-8", 5e-11), ("0.000003614", 5e-10)],
)
def test_half_unit(text: str, half: float) -> None:
    assert printed.half_unit(text) == pytest.approx(half, rel=1e-12)


# --------------------------------------------------------------------------------------------
# exact
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("ours", "verdict"),
    [(1.0000199999907, "reproduced"), (1.0000198, "not_reproduced"), (1.00002, "not_reproduced")],
)
def test_exact_accepts_truncation_of_the_printed_digits(ours: float, verdict: str) -> None:
    row = judge(item(value="1.0000199"), Found(value=ours))
    assert row.verdict == verdict
    assert "printed digits of 1.0000199" in row.tolerance
    assert ("truncated to the printed 1.0000199" in row.reason) == (verdict == "reproduced")


@pytest.mark.parametrize(
    ("err", "verdict"), [(3e-14, "reproduced"), (1e-9, "reproduced"), (2e-9, "not_reproduced")]
)
def test_exact_stated_tolerance_on_the_printed_zero(err: float, verdict: str) -> None:
    tol = {"abs": 1e-9, "applies_to": "error_pct", "reason": "an exact inversion prints 0 %"}
    it = item(value="88", error_pct="0", tolerance=tol)
    row = judge(it, Found(value=88.0, error_pct=err))
    assert row.verdict == verdict
    assert "an exact inversion prints 0 %" in row.tolerance
    # without the stated tolerance the printed "0" (rounded +-0.5, truncated < 1) accepts 2e-9
    assert judge(item(value="88", error_pct="0"), Found(value=88.0, error_pct=err)).verdict == (
        "reproduced"
    )
    assert judge(item(value="88", error_pct="0"), Found(value=88.0, error_pct=1.2)).verdict == (
        "not_reproduced"
    )


def test_exact_value_and_error_must_both_agree() -> None:
    it = item(value="50.0050", error_pct="0.0110")
    assert judge(it, Found(value=50.00504, error_pct=0.011)).verdict == "reproduced"
    assert judge(it, Found(value=50.00504, error_pct=0.0125)).verdict == "not_reproduced"
    assert judge(it, Found(value=50.0062, error_pct=0.011)).verdict == "not_reproduced"


def test_exact_stated_tolerance_on_the_value() -> None:
    it = item(value="2.0", tolerance={"rel": 0.01, "reason": "r"})
    assert judge(it, Found(value=2.019)).verdict == "reproduced"
    assert judge(it, Found(value=2.021)).verdict == "not_reproduced"  # truncation would pass


def test_missing_value_is_not_checkable() -> None:
    row = judge(item(), Found(missing="no such row"))
    assert (row.verdict, row.reason) == ("not_checkable", "not checkable: no such row")
    assert row.tolerance == "value: the printed digits of 1.5 (rounding: +-0.05; truncation: [1.5, +0.1))"  # fmt: skip
    for it in (_approx(), _stat("50.0")):  # the stated tolerance of each kind, without a result
        assert judge(it, Found(missing="none")).tolerance == kinds.stated_tolerance(it) != ""


# --------------------------------------------------------------------------------------------
# approximate
# --------------------------------------------------------------------------------------------
def _approx(value: str = "4.5", printed_as: str = "about", **extra: Any) -> dict[str, Any]:
    return item(kind="approximate", value=value, unit="km", printed_as=printed_as, **extra)


@pytest.mark.parametrize(
    ("value", "ours", "verdict"),
    [
        # "about 22": one unit (1) < 10 % (2.2): the floor
        ("22", 22.0, "reproduced"),
        ("22", 19.81, "reproduced"),
        ("22", 24.19, "reproduced"),
        ("22", 24.3, "not_reproduced"),
        # "about 2000": one unit of the 2 (thousands) > 10 %: 1000
        ("2000", 2990.0, "reproduced"),
        ("2000", 3010.0, "not_reproduced"),
        # "about 0.07": one unit of the 7 (0.01) > 10 % (0.007)
        ("0.07", 0.0799, "reproduced"),
        ("0.07", 0.0801, "not_reproduced"),
    ],
)
def test_approximate_about_tolerance_from_the_printed_digits(
    value: str, ours: float, verdict: str
) -> None:
    row = judge(_approx(value), Found(value=ours))
    assert row.verdict == verdict
    assert f"printed as 'about {value}'" in row.tolerance


@pytest.mark.parametrize(
    ("ours", "verdict"), [(4.5, "reproduced"), (4.26, "reproduced"), (4.74, "reproduced"),
                          (4.76, "not_reproduced"), (4.2, "not_reproduced")],
)  # fmt: skip
def test_approximate_plot_tolerance_is_half_a_tick_of_the_figure_axis(
    ours: float, verdict: str
) -> None:
    it = _approx("4.5", "plot", figure={"label": "Fig. 5", "axis": "y"})
    figures = {"Fig. 5": {"y": {"tick": 0.5, "unit": "km", "note": "n"}}}
    row = judge(with_axis(it, figures), Found(value=ours))
    assert row.verdict == verdict
    assert row.tolerance.startswith("+-0.25 km (read off Fig. 5, y axis (tick 0.5 km)")
    # a coarser axis reads coarser: 4.2 is within half a tick of 1 km
    coarse = {"Fig. 5": {"y": {"tick": 1.0, "unit": "km", "note": "n"}}}
    assert judge(with_axis(it, coarse), Found(value=4.2)).verdict == "reproduced"


def test_approximate_standard_error_widens_the_band() -> None:
    it = _approx("0.16")  # about 0.16: +-0.016
    assert judge(it, Found(value=0.175)).verdict == "reproduced"
    assert judge(it, Found(value=0.2)).verdict == "not_reproduced"
    # our own Monte Carlo error widens the band by 2 SE, and the row says so
    wide = judge(it, Found(value=0.2, standard_error=0.03))
    assert wide.verdict == "reproduced" and "2 SE" in wide.tolerance
    assert judge(it, Found(value=0.4, standard_error=0.03)).verdict == "not_reproduced"


def test_approximate_value_that_does_not_occur() -> None:
    row = judge(_approx("2400"), Found(value=float("nan"), shown="never"))
    assert (row.verdict, row.reproduced) == ("not_reproduced", "never")


# --------------------------------------------------------------------------------------------
# statistical
# --------------------------------------------------------------------------------------------
def _stat(value: str) -> dict[str, Any]:
    return item(kind="statistical", value=value)


@pytest.mark.parametrize(
    ("value", "verdict", "lo", "hi"),
    [
        ("50.0010", "consistent", 80.0, 88.0),  # +1 sigma
        ("49.9980", "consistent", 1.0, 4.5),  # -2 sigma
        ("50.0050", "not_reproduced", 99.9, 100.0),  # +5 sigma
        ("49.9960", "not_reproduced", 0.0, 0.1),  # -4 sigma
    ],
)
def test_statistical_rank(value: str, verdict: str, lo: float, hi: float) -> None:
    rng = np.random.default_rng(7)
    sample = 50.0 + 0.001 * rng.standard_normal(2000)
    row = judge(_stat(value), Found(samples=sample, noise_free=50.0002, truth=50.0))
    assert row.verdict == verdict
    rank = float(re.search(r"percentile rank ([0-9.]+)", row.reason).group(1))
    assert lo <= rank <= hi
    assert float(row.reproduced) == pytest.approx(float(np.median(sample)), abs=1e-9)
    assert "noise-free real: 50.0002" in "; ".join(row.notes)


def test_statistical_rank_band_edges() -> None:
    sample = np.arange(1000, dtype=float)  # rank of v: 100 (#below + #equal / 2) / 1000
    verdict = {
        v: judge(_stat(v), Found(samples=sample)).verdict for v in ("5", "4.9", "4", "994", "995")
    }
    assert verdict == {
        "5": "consistent",  # 0.55
        "4.9": "consistent",  # 0.5, on the edge
        "4": "not_reproduced",  # 0.45
        "994": "consistent",  # 99.45
        "995": "not_reproduced",  # 99.55
    }


def test_statistical_weighted_samples_rank_by_weight() -> None:
    """Per-sample weights (a mixture of two runs): the rank is the weighted one, sum of the
    runs' weights times their ranks, and the percentiles are the mixture's."""
    a, b = np.arange(1000, dtype=float), 2000.0 + np.arange(1000, dtype=float)
    sample = np.concatenate([a, b])
    w = np.concatenate([np.full(1000, 0.5 / 1000), np.full(1000, 0.5 / 1000)])
    # 1500 is above all of a (rank 100) and below all of b (rank 0): mixture rank 50
    row = judge(_stat("1500"), Found(samples=sample, weights=w))
    assert row.verdict == "consistent" and "percentile rank 50.0" in row.reason
    assert "weighted mixture of 2000" in row.reason
    # all the weight on b: 1500 lies below every trial that counts
    w_b = np.concatenate([np.zeros(1000), np.full(1000, 1e-3)])
    assert judge(_stat("1500"), Found(samples=sample, weights=w_b)).verdict == "not_reproduced"
    # unequal weights: 0.9 on a puts 1500 at rank 90
    w_a = np.concatenate([np.full(1000, 0.9e-3), np.full(1000, 0.1e-3)])
    assert kinds.percentile_rank(sample, 1500.0, w_a) == pytest.approx(90.0)
    assert judge(_stat("1500"), Found(samples=sample)).verdict == "consistent"  # unweighted: 50


def test_statistical_reports_its_power() -> None:
    """A 5-95 % band of 13-133 for a published 100 accepts almost anything: the row says so."""
    rng = np.random.default_rng(1)
    wide = 73.0 + 36.0 * rng.standard_normal(1000)
    narrow = 73.0 + 0.36 * rng.standard_normal(1000)
    w = judge(_stat("100"), Found(samples=wide))
    n = judge(_stat("100"), Found(samples=narrow))
    width = {r.verdict: float(re.search(r"a range ([0-9.e+]+) % of the published", r.tolerance).group(1)) for r in (w, n)}  # fmt: skip
    assert w.verdict == "consistent" and width["consistent"] > 100.0
    assert n.verdict == "not_reproduced" and width["not_reproduced"] < 5.0


def test_statistical_shows_the_noise_free_comparison() -> None:
    sample = np.linspace(49.9, 50.1, 101)
    agree = judge(_stat("50.0050"), Found(samples=sample, noise_free=50.00504))
    differ = judge(_stat("50.0050"), Found(samples=sample, noise_free=50.0071))
    assert kinds.NOISE_FREE_AGREES in agree.notes
    assert "exact rule: rounded to the printed 50.0050" in "; ".join(agree.notes)
    assert kinds.NOISE_FREE_AGREES not in differ.notes
    assert "exact rule: differs" in "; ".join(differ.notes)


# --------------------------------------------------------------------------------------------
# claim registry
# --------------------------------------------------------------------------------------------
def _registry() -> ClaimRegistry:
    reg = ClaimRegistry()

    @reg.register(
        "above",
        {"type": "object", "required": ["limit"], "properties": {"limit": {"type": "number"}}},
    )
    def above(args, results):
        return [
            ClaimResult(
                "upheld" if x > args["limit"] else "not_upheld",
                f"{x}",
                f"> {args['limit']}",
                "compared",
                method=name,
                suffix=name,
            )
            for name, x in results.items()
        ]

    return reg


def test_claim_registry_judges_each_curve_both_ways() -> None:
    reg = _registry()
    out = reg.evaluate({"test": "above", "limit": 1.0}, {"a": 2.0, "b": 0.5})
    assert [(r.suffix, r.verdict) for r in out] == [("a", "upheld"), ("b", "not_upheld")]
    claim = {"id": "C1", "label": "Sec. 6", "text": "x is large", "predicate": {"test": "above", "limit": 1.0}}  # fmt: skip
    rows = engine.claim_rows(claim, out)
    assert [r["id"] for r in rows] == ["C1/a", "C1/b"]
    assert all(r["reason"].startswith("test above: ") and r["tolerance"] == "> 1.0" for r in rows)


def test_claim_registry_rejects_bad_predicates() -> None:
    reg = _registry()
    assert reg.check({"test": "above", "limit": 1}) == []
    assert reg.check({"test": "nope"})[0][:2] == ("test", "nope")
    assert reg.check({"test": "above", "limit": "big"})[0][0] == "limit"
    assert reg.check({"test": "above", "limit": 1, "extra": 2})[0][0] == "extra"
    with pytest.raises(ValueError, match="registered twice"):
        reg.register("above", {"type": "object"})(lambda a, r: [])
    with pytest.raises(ValueError, match="claim verdict 'maybe'"):
        ClaimResult("maybe", "", "", "")


# --------------------------------------------------------------------------------------------
# the published-values file
# --------------------------------------------------------------------------------------------
def _write(
    tmp_path: Path, items: list[dict], claims: list[dict] = (), name: str = "bad.yaml"
) -> Path:
    path = tmp_path / name
    data = {"paper": "demo", "items": items, "claims": list(claims)}
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


GOOD = item(kind="approximate", value="4.5", printed_as="about")
EXACT = {**item(kind="exact", value="4.5"), "printed_as": None}


@pytest.mark.parametrize(
    ("change", "field", "bad", "allowed"),
    [
        ({"kind": "about"}, "kind", "about", "one of ['exact', 'approximate', 'statistical']"),
        ({"value": "nan"}, "value", "nan", "a printed number"),
        ({"value": "inf"}, "value", "inf", "a printed number"),
        ({"value": "1e999"}, "value", "1e999", "a finite number"),
        ({"value": 4.5}, "value", "4.5", "type ['string', 'null']"),
        (
            {**EXACT, "tolerance": {"rel": float("nan"), "reason": "r"}},
            "tolerance.rel",
            "nan",
            "finite",
        ),
        (
            {**EXACT, "tolerance": {"abs": float("inf"), "reason": "r"}},
            "tolerance.abs",
            "inf",
            "finite",
        ),
        (
            {"printed_as": None},
            "printed_as",
            "missing",
            "an approximate item says how the paper printed it",
        ),
        ({"printed_as": "roughly"}, "printed_as", "roughly", "one of ['about', 'plot']"),
        (
            {"tolerance": {"rel": 0.2, "reason": "r"}},
            "tolerance",
            "{'rel': 0.2",
            "no 'tolerance' for an approximate item (its printed_as sets it",
        ),
        ({"printed_as": "plot"}, "figure", "None", "for printed_as 'plot': {label:"),
        (
            {"printed_as": "plot", "figure": {"label": "Fig. 9", "axis": "y"}},
            "figure.label",
            "Fig. 9",
            "a figure stated under 'figures'",
        ),
        ({**EXACT, "printed_as": "about"}, "printed_as", "about", "only on an approximate item"),
        ({**EXACT, "tolerance": {"rel": 0.2}}, "tolerance.reason", "missing", "required keys"),
        (
            {**EXACT, "tolerance": {"rel": 0.2, "abs": 1, "reason": "r"}},
            "tolerance",
            "",
            "exactly one of",
        ),
        ({"label": None}, "label", "missing", "required keys"),
        ({"colour": "red"}, "colour", "unknown key 'colour'", "only the keys"),
        ({"select": {"sensor": ["a"]}}, "select.sensor", "['a']", "type"),
    ],
)
def test_bad_published_file_names_file_entry_field_value_and_allowed(
    tmp_path: Path, change: dict, field: str, bad: str, allowed: str
) -> None:
    entry = {**GOOD, **change}
    entry = {k: v for k, v in entry.items() if v is not None}
    path = _write(tmp_path, [item(id="X0"), entry])
    with pytest.raises(ConfigError) as info:
        load_published(path)
    message = str(info.value)
    line = next(ln for ln in message.splitlines() if "'X1'" in ln)
    assert "bad.yaml" in line and "(items[1])" in line
    assert f"field {field!r}" in line, line
    assert bad in line and "allowed:" in line and allowed in line, line


def test_statistical_item_takes_no_tolerance(tmp_path: Path) -> None:
    entry = item(kind="statistical", tolerance={"rel": 0.1, "reason": "r"})
    with pytest.raises(ConfigError, match=r"'X1'.*field 'tolerance'.*statistical"):
        load_published(_write(tmp_path, [entry]))
    assert load_published(_write(tmp_path, [item(kind="statistical")], name="ok.yaml"))


def test_duplicate_id_across_items_and_claims(tmp_path: Path) -> None:
    claim = {"id": "X1", "label": "Sec. 6", "text": "t", "predicate": {"test": "above", "limit": 1}}
    with pytest.raises(
        ConfigError, match=r"claim 'X1' \(claims\[0\]\), field 'id'.*unique.*items\[0\]"
    ):
        load_published(_write(tmp_path, [GOOD], [claim]))
    with pytest.raises(ConfigError, match=r"item 'X1' \(items\[1\]\), field 'id'"):
        load_published(_write(tmp_path, [GOOD, GOOD], name="two.yaml"))


def test_exact_item_needs_a_printed_number(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match=r"field 'value'.*value or error_pct"):
        load_published(_write(tmp_path, [item(value=None) | {"value": None}]))
    ok = item(value=None) | {"value": None, "error_pct": "0"}
    assert load_published(_write(tmp_path, [ok], name="ok.yaml"))["items"][0]["error_pct"] == "0"


def test_paper_checks_run_before_any_compute(tmp_path: Path) -> None:
    """Bad claim arguments and bad selectors stop write_verdicts before the results are read."""
    claim = {
        "id": "C1",
        "label": "Sec. 6",
        "text": "t",
        "predicate": {"test": "above", "limit": "x"},
    }
    path = _write(tmp_path, [GOOD], [claim])
    read: list[int] = []

    def read_results() -> dict:
        read.append(1)
        return {}

    def check_item(it: dict) -> list:
        return [("select.case", it.get("select", {}).get("case"), "one of ['ch1']")]

    with pytest.raises(ConfigError) as info:
        engine.write_verdicts(
            path,
            tmp_path / "v.csv",
            locate=lambda it, res: [Found(value=4.5)],
            claims=_registry(),
            read_results=read_results,
            check_item=check_item,
        )
    text = str(info.value)
    assert "claim 'C1' (claims[0]), field 'predicate.limit': bad value 'x'" in text
    assert (
        "item 'X1' (items[0]), field 'select.case': bad value None; allowed: one of ['ch1']" in text
    )
    assert read == [] and not (tmp_path / "v.csv").exists()


def test_write_verdicts_is_atomic_and_byte_identical(tmp_path: Path) -> None:
    claim = {"id": "C1", "label": "Sec. 6", "text": "t", "predicate": {"test": "above", "limit": 1}}
    items = [GOOD, item(id="X2", kind="statistical", value="50.1"), item(id="X3", value="2.50")]
    path = _write(tmp_path, items, [claim], name="pub.yaml")
    rng = np.random.default_rng(3)

    def locate(it: dict, res: dict) -> list[Found]:
        if it["kind"] == "statistical":
            return [Found(method="m", samples=50.0 + 0.1 * rng.standard_normal(500))]
        return [Found(method="m", value=4.4 if it["kind"] == "approximate" else 2.7)]

    outs = []
    for name in ("a", "b"):
        rng = np.random.default_rng(3)
        out = tmp_path / name / "verdicts.csv"
        table = engine.write_verdicts(
            path, out, locate=locate, claims=_registry(), read_results=lambda: {"c": 2.0}
        )
        outs.append(out.read_bytes())
        assert sorted(p.name for p in out.parent.iterdir()) == ["verdicts.csv"]  # no temp left
    assert outs[0] == outs[1]
    written = pd.read_csv(tmp_path / "a" / "verdicts.csv", dtype=str, keep_default_na=False)
    assert list(written.columns) == VERDICT_FILE_COLUMNS
    assert (
        list(written["verdict"])
        == list(table["verdict"])
        == [
            "reproduced",
            "consistent",
            "not_reproduced",
            "upheld",
        ]
    )
    assert set(written["kind"]) <= set(VERDICT_KINDS) and set(written["verdict"]) <= set(VERDICTS)
    assert (written["tolerance"] != "").all() and (written["reason"] != "").all()


def test_engine_names_no_paper() -> None:
    config = yaml.safe_load((REPO / "config" / "config.yaml").read_text(encoding="utf-8"))
    slugs = config["papers"]
    assert slugs
    for path in sorted((REPO / "pipeline" / "verdicts").glob("*.py")):
        text = path.read_text(encoding="utf-8")
        for slug in slugs:
            assert slug not in text, (path.name, slug)


def test_one_published_schema_for_every_paper() -> None:
    schemas = sorted(p.name for p in (REPO / "config" / "schemas").glob("published*.json"))
    assert schemas == ["published.schema.json"]
    config = yaml.safe_load((REPO / "config" / "config.yaml").read_text(encoding="utf-8"))
    for slug in config["papers"]:
        data = load_published(REPO / "config" / "published" / f"{slug}.yaml")
        assert data["paper"] == slug
        assert all(i["label"] for i in data["items"]) and all(c["label"] for c in data["claims"])


def test_a_cause_explains_only_the_rows_that_fail():
    """One Cause object on several rows: written where the row is not reproduced or not upheld,
    blank where it passes, and a cause never changes a verdict."""
    from pipeline.verdicts.cause import Cause

    cause = Cause("paper_error", "eq. 21 drops a term", "the paper's eq 21 drops the term 2 x")
    item = {"id": "A", "label": "Table 1", "kind": "exact", "quantity": "x_m", "value": "2.50"}
    passing = engine.item_rows(item, [Found(value=2.504, cause=cause)])[0]
    failing = engine.item_rows(item, [Found(value=2.6, cause=cause)])[0]
    blank = (passing["cause_kind"], passing["cause"], passing["cause_detail"])
    assert (passing["verdict"], *blank) == ("reproduced", "", "", "")
    assert (failing["verdict"], failing["cause_kind"]) == ("not_reproduced", "paper_error")
    # the title is the grouping key; the full text is its detail
    assert (failing["cause"], failing["cause_detail"]) == (cause.title, cause.text)
    assert list(failing)[-3:] == ["cause_kind", "cause", "cause_detail"]
    claim = {"id": "C", "label": "Sec. 2", "text": "x is large", "predicate": {"test": "t"}}
    rows = engine.claim_rows(
        claim,
        [
            ClaimResult("not_upheld", "x = 1", "> 2", "compared", cause=cause),
            ClaimResult("upheld", "x = 3", "> 2", "compared", suffix="b", cause=cause),
        ],
    )
    assert [(r["verdict"], r["cause_kind"]) for r in rows] == [
        ("not_upheld", "paper_error"),
        ("upheld", ""),
    ]
    with pytest.raises(ValueError, match="cause kind 'typo'"):
        Cause("typo", "x", "x")
    # a title is a short phrase: too many words, or a sentence, is refused
    with pytest.raises(ValueError, match="13 words; allowed: a phrase of 1 to 12 words"):
        Cause("model", " ".join(["word"] * 13), "x")
    with pytest.raises(ValueError, match="without a final full stop"):
        Cause("model", "a sentence.", "x")
    with pytest.raises(ValueError, match="cause text: empty"):
        Cause("model", "a title", " ")
