"""The first page's summary of a paper (pipeline.report.summary) and the marks of its main
claims (pipeline.verdicts.main_claims): validated with the published values, computed from the
verdict rows, named in the paper's words, grouped and ranked by root cause."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest
import yaml

from pipeline.config import ConfigError
from pipeline.report.precision import compact_tolerance, reproduced_header, shown_reproduced
from pipeline.report.scoreboard import score_row
from pipeline.report.summary import paper_summary
from pipeline.report.vocabulary import differs_word, plain_words, tone
from pipeline.verdicts.main_claims import judge_main_claims, mark
from pipeline.verdicts.published import load_published

ROOT = Path(__file__).resolve().parents[2]

PUBLISHED = {
    "paper": "demo",
    "items": [
        {"id": "T1.a", "label": "Table 1", "kind": "exact", "quantity": "phi_deg", "value": "1.5",
         "select": {"method": "M4"}},
        {"id": "T1.b", "label": "Table 1", "kind": "exact", "quantity": "theta_deg",
         "value": "2.5", "select": {"method": "M4"}},
        {"id": "T2.a", "label": "Table 2", "kind": "statistical", "quantity": "phi_deg",
         "value": "3.5", "select": {"method": "M1"}},
    ],
    "claims": [
        {"id": "C1", "label": "Sec. 5", "text": "Method 4 is the worst.",
         "predicate": {"test": "argmax"}},
        {"id": "C2", "label": "Abstract", "text": "The error is bounded.",
         "predicate": {"test": "bounded"}},
    ],
    "main_claims": [
        {"label": "Abstract", "text": "Table 1 is reproduced.", "rows": ["T1."]},
        {"label": "Sec. 5", "text": "The error is bounded and method 4 is the worst.",
         "rows": ["C1", "C2/simulated"]},
    ],
    "names": {"phi_deg": "roll", "theta_deg": "pitch", "M4": "method 4", "M1": "method 1",
              "simulated": "the simulated curve", "analytic": "the analytic curve"},
}  # fmt: skip


def _write(tmp_path: Path, data: dict) -> Path:
    path = tmp_path / "demo.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def _verdicts(**verdicts: str) -> pd.DataFrame:
    rows = [
        ("T1.a", "exact", "phi_deg", "M4"),
        ("T1.b", "exact", "theta_deg", "M4"),
        ("T2.a", "statistical", "phi_deg", "M1"),
        ("C1", "claim", "phi_deg", "M1,M4"),
        ("C2/analytic", "claim", "error_m", "analytic"),
        ("C2/simulated", "claim", "error_m", "simulated"),
    ]
    good = {"exact": "reproduced", "statistical": "consistent", "claim": "upheld"}
    return pd.DataFrame(
        [
            {"id": i, "kind": k, "quantity": q, "method": m, "published": "1",
             "reproduced": "1", "note": "", "verdict": verdicts.get(i.replace("/", "_").replace(".", "_"), good[k]),
             "cause_kind": "", "cause": ""}
            for i, k, q, m in rows
        ]
    )  # fmt: skip


def test_main_claims_are_validated_with_the_published_file(tmp_path):
    assert len(load_published(_write(tmp_path, PUBLISHED))["main_claims"]) == 2
    bad = {**PUBLISHED, "main_claims": [{**PUBLISHED["main_claims"][0], "rows": ["T1.", "T9.x"]}]}
    with pytest.raises(ConfigError) as err:
        load_published(_write(tmp_path, bad))
    message = str(err.value)
    # the file, the claim, the field and the value
    assert (
        "demo.yaml: main claim 'Abstract' (main_claims[0]), field 'rows[1]': bad value 'T9.x'"
        in message
    )
    prefix = {**PUBLISHED, "main_claims": [{**PUBLISHED["main_claims"][0], "rows": ["T7."]}]}
    with pytest.raises(ConfigError, match=r"field 'rows\[0\]': bad value 'T7\.'"):
        load_published(_write(tmp_path, prefix))
    missing = {**PUBLISHED, "main_claims": [{"label": "Abstract", "rows": ["T1."]}]}
    with pytest.raises(
        ConfigError, match="main claim 'Abstract'.*field 'text': bad value 'missing'"
    ):
        load_published(_write(tmp_path, missing))
    empty = {**PUBLISHED, "main_claims": [{"label": "x", "text": "y", "rows": []}]}
    with pytest.raises(ConfigError, match=r"field 'rows'"):
        load_published(_write(tmp_path, empty))


def test_a_main_claims_mark_follows_its_rows():
    claims = PUBLISHED["main_claims"]
    v = _verdicts()
    marks = [r.mark for r in judge_main_claims(claims, list(v["id"]), list(v["verdict"]), "f")]
    assert marks == ["Re", "Re"]
    # one row of Table 1 not reproduced: the claim on Table 1 flips; the other does not
    v = _verdicts(T1_b="not_reproduced")
    marks = [r.mark for r in judge_main_claims(claims, list(v["id"]), list(v["verdict"]), "f")]
    assert marks == ["not_Re", "Re"]
    # a variant the claim does not name changes nothing; the one it names flips it
    v = _verdicts(C2_analytic="not_upheld")
    assert judge_main_claims(claims, list(v["id"]), list(v["verdict"]), "f")[1].mark == "Re"
    v = _verdicts(C2_simulated="not_upheld")
    assert judge_main_claims(claims, list(v["id"]), list(v["verdict"]), "f")[1].mark == "not_Re"
    v = _verdicts(C1="not_checkable")
    assert (
        judge_main_claims(claims, list(v["id"]), list(v["verdict"]), "f")[1].mark == "not_checkable"
    )
    assert mark(["not_checkable", "not_reproduced"]) == "not_Re"
    with pytest.raises(ValueError, match="f: main claim 'x' .*'rows\\[0\\]': bad value 'C2/nope'"):
        judge_main_claims(
            [{"label": "x", "text": "t", "rows": ["C2/nope"]}], ["C2/a"], ["upheld"], "f"
        )


def test_a_main_claim_unresolved_on_some_variants_is_not_checkable_never_re():
    """A claim that holds where it is resolved (N = 1e6, noise-free) but is not resolved at
    another N is not checkable, whether the main claim names the claim or one variant of it;
    a sibling that holds or fails but is not named changes nothing."""
    ids = ["C7/N=1", "C7/N=1e6", "C7/noise-free", "T1"]
    held = ["upheld", "upheld", "upheld", "reproduced"]
    unresolved = ["not_checkable", "upheld", "upheld", "reproduced"]
    for rows in (["C7"], ["C7/N=1e6"], ["C7/N=1e6", "T1"]):
        claim = [{"label": "x", "text": "t", "rows": rows}]
        assert judge_main_claims(claim, ids, held, "f")[0].mark == "Re"
        result = judge_main_claims(claim, ids, unresolved, "f")[0]
        assert result.mark == "not_checkable", rows
        assert result.unchecked == ("C7/N=1",)
    failing = ["not_upheld", "upheld", "upheld", "reproduced"]
    claim = [{"label": "x", "text": "t", "rows": ["C7/N=1e6"]}]
    assert judge_main_claims(claim, ids, failing, "f")[0].mark == "Re"


@pytest.mark.parametrize("slug", ["north_finding", "platform_drift", "altimeter_attitude"])
def test_no_built_main_claim_is_re_while_a_variant_of_its_claims_is_unresolved(slug, results_repo):
    """On the built verdicts.csv: a main claim marked [Re] has every row of every claim it
    names passing (all variants ``<id>/...``), computed here from the csv, not by the rule."""
    path = results_repo / "results" / slug / "verdicts.csv"
    if not path.exists():
        pytest.skip(f"{path} not built")
    v = pd.read_csv(path, dtype=str, keep_default_na=False)
    data = load_published(ROOT / "config" / "published" / f"{slug}.yaml")
    ids, verdicts = list(v["id"]), list(v["verdict"])
    for result in judge_main_claims(data["main_claims"], ids, verdicts, str(path)):
        bases = {r.split("/", 1)[0] for r in result.rows}
        every = [vd for i, vd in zip(ids, verdicts, strict=True) if i.split("/", 1)[0] in bases]
        if result.mark == "Re":
            assert all(x in ("reproduced", "consistent", "upheld") for x in every), result.label


def test_self_checks_are_counted_apart_from_the_published_numbers(tmp_path):
    """Rows of items marked self_check (Table 1 here) leave the published-number counts and
    the scoreboard's number columns, are counted on their own, and a main claim resting on them
    only says so; an empty self_check is refused at parse with the file, entry and field."""
    data = {**PUBLISHED, "items": [{**i, "self_check": "ideal sensor"} if i["id"].startswith("T1")
                                   else i for i in PUBLISHED["items"]]}  # fmt: skip
    v = _verdicts(T1_b="not_reproduced")
    s = paper_summary(v, pd.DataFrame({"status": []}), data, "f")
    assert s.sentences[0].startswith("Reproduced: 1 of 1 published number (all statistical)")
    assert "counted apart, 1 of 2 self-checks passed (they check our code" in s.sentences[0]
    assert s.main_claims[0].basis.startswith("it rests on self-checks only")
    assert s.main_claims[0].basis.endswith(": 1 of 2 self-checks passed")
    plain = paper_summary(v, pd.DataFrame({"status": []}), PUBLISHED, "f")
    assert plain.sentences[0].startswith("Reproduced: 2 of 3 published numbers (1 of 2 exact")
    assert "self-check" not in plain.sentences[0] + plain.main_claims[0].basis
    audit = pd.DataFrame({"status": ["match"]})
    row = score_row("demo", "Demo", audit, v, data)
    assert row.numbers == {
        "reproduced": 0,
        "consistent": 1,
        "not_reproduced": 0,
        "not_checkable": 0,
    }
    assert row.self_checks == {"reproduced": 1, "not_reproduced": 1}
    assert sum(score_row("demo", "Demo", audit, v, PUBLISHED).numbers.values()) == 3
    bad = {**data, "items": [{**data["items"][0], "self_check": ""}, *data["items"][1:]]}
    with pytest.raises(ConfigError, match=r"item 'T1\.a' \(items\[0\]\), field 'self_check'"):
        load_published(_write(tmp_path, bad))


def _caused(v: pd.DataFrame, ids: list[str], kind: str, title: str, detail: str) -> None:
    for i in ids:
        v.loc[v["id"] == i, ["cause_kind", "cause", "cause_detail"]] = [kind, title, detail]


def test_summary_names_rows_in_the_papers_words_grouped_by_cause():
    audit = pd.DataFrame({"equation": ["1", "2"], "status": ["match", "differs"],
                          "residual": ["0", "x"], "note": ["", ""], "kind": ["", "paper_error"]})  # fmt: skip
    v = _verdicts(
        T1_a="not_reproduced", T1_b="not_reproduced", C1="not_upheld", T2_a="not_reproduced"
    ).assign(cause_detail="")
    # one cause explains three rows (Table 1 and the claim), another none
    title = "method 4's formula drops a sign"
    detail = "Method 4's eq. 7 drops the sign of its second term (residual 2 x)."
    _caused(v, ["T1.a", "T1.b", "C1"], "paper_error", title, detail)
    s = paper_summary(v, audit, PUBLISHED, "demo.yaml")
    reproduced, failed, causes = s.sentences
    assert reproduced.startswith("Reproduced: 0 of 3 published numbers (0 of 2 exact, 0 of 1 statistical)")  # fmt: skip
    assert reproduced.endswith(
        "1 of 2 printed equations match the derivation (1 of the others is an error of the paper)."
    )
    # group (1): the rows of the ranked first cause in the paper's labels, compressed (the
    # table once, with the method its rows share; the claim by where it is made); (2): the rest
    assert failed == (
        "Not reproduced or not upheld (4 verdicts): (1) Table 1, method 4, and the claim of "
        "Sec. 5; (2) Table 2, method 1."
    )
    # the causes by their titles, ranked by rows, with their kind in words and their rows
    assert causes == (
        "Causes, by rows explained: (1) method 4's formula drops a sign "
        "(error of the paper, 3 rows); (2) cause not identified (1 row)."
    )
    # the title once on the first page, the full text in the section's list of causes
    assert " ".join(s.sentences).count(title) == 1 and detail not in " ".join(s.sentences)
    assert [(c.title, c.rows, c.details) for c in s.causes] == [(title, 3, (detail,)), ("", 1, ())]
    for internal in ("T1.a", "T2.a", "C1", "phi_deg", "M4"):
        assert internal not in " ".join(s.sentences)
    assert s.status == "Not reproduced"  # both main claims fail
    assert [m.mark for m in s.main_claims] == ["not_Re", "not_Re"]
    assert s.main_claims[0].basis == "2 of 2 verdicts on it fail: Table 1, method 4"
    # no cause given at all: said so, once
    plain = paper_summary(_verdicts(T2_a="not_reproduced"), audit, PUBLISHED, "demo.yaml")
    assert plain.sentences[2] == "Cause: not identified for the 1 row."
    assert plain.status == "Full reproduction"  # every main claim holds


def test_a_group_names_at_most_a_few_labels_then_how_many_more():
    """Many tables under one cause: compressed ("Tables 1-3"), at most MAX_LABELS labels, then
    "and N more"; never row by row."""
    from pipeline.report.labels import MAX_LABELS, capped, compress

    assert compress(["Table 1", "Table 2", "Table 3", "Fig. 5 (3)", "Fig. 6 (4)"]) == [
        "Tables 1-3",
        "Figs 5-6",
    ]
    labels = ["Table 1", "Sec. 2", "Abstract", "Appendix B", "Eq. 4"]
    assert capped(labels) == "Table 1, Sec. 2, Abstract and 2 more" and MAX_LABELS == 3
    items = [{"id": f"X{k}", "label": lab, "kind": "exact", "quantity": "q", "value": "1",
              "select": {"method": f"M{k}"}} for k, lab in enumerate(labels)]  # fmt: skip
    published = {"items": items, "claims": [], "main_claims": []}
    v = pd.DataFrame([{"id": f"X{k}", "kind": "exact", "quantity": "q", "method": f"M{k}",
                       "published": "1", "reproduced": "2", "verdict": "not_reproduced",
                       "note": "", "cause_kind": "model", "cause": "our model differs",
                       "cause_detail": "x"} for k in range(5)])  # fmt: skip
    no_audit = pd.DataFrame({"equation": [], "status": []})
    failed = paper_summary(v, no_audit, published, "f").sentences[1]
    assert failed == (
        "Not reproduced or not upheld (5 verdicts): Table 1, Sec. 2, Abstract and 2 more."
    )


def test_a_claim_judged_on_several_curves_is_one_row_marked_by_its_worst():
    """A claim judged per curve (ids <base>/<suffix>) with mixed verdicts is one row of the main
    text: its verdict for each curve in words, its mark (row status and highlight) that of its
    worst row; the per-row table keeps every row."""
    from pipeline.report.grouping import describe, worst
    from pipeline.report.published import claim_rows_section, claims_section, published_section

    assert describe([("N=1", "not_upheld"), ("N=100", "not_upheld"), ("N=1e4", "not_upheld"),
                     ("N=1e6", "upheld"), ("N=1e8", "upheld"), ("noise-free", "upheld")]) == (
        "not upheld at N = 1, 100 and 1e4; upheld at N = 1e6, 1e8 and noise-free"
    )  # fmt: skip
    assert worst(["upheld", "not_checkable", "upheld"]) == "not_checkable"
    assert worst(["not_checkable", "upheld", "not_upheld"]) == "not_upheld"
    assert worst(["consistent", "reproduced"]) == "consistent"

    import tempfile

    v = _verdicts(C2_simulated="not_upheld").assign(cause_detail="")
    _caused(v, ["C2/simulated"], "paper_error", "eq. 9 leaves out the drift", "Eq. 9 ... 4437 m.")
    v.loc[v["id"] == "C2/simulated", "reproduced"] = "4437 m at 2 h"
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "demo.yaml"
        path.write_text(yaml.safe_dump(PUBLISHED), encoding="utf-8")
        (claims,) = [b for b in claims_section("c", v, path).blocks if type(b).__name__ == "Table"]
        (rows,) = [
            b for b in claim_rows_section("r", v, path).blocks if type(b).__name__ == "Table"
        ]
        numbers = published_section("p", v, path)
    assert claims.columns == ["claim (where the paper makes it)", "verdict", "cause"]
    assert [r[0] for r in claims.rows] == ["“Method 4 is the worst” (Sec. 5)",
                                           "“The error is bounded” (Abstract)"]  # fmt: skip
    assert claims.rows[1][1:] == [
        "upheld for the analytic curve; not upheld for the simulated curve",
        "eq. 9 leaves out the drift",
    ]
    assert claims.row_status == ["upheld", "not_upheld"] and claims.highlight == [1]
    # the same verdict on every curve: still one row, its verdict named for each curve
    v2 = _verdicts(C2_simulated="not_upheld", C2_analytic="not_upheld")
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "demo.yaml"
        path.write_text(yaml.safe_dump(PUBLISHED), encoding="utf-8")
        (t2,) = [b for b in claims_section("c", v2, path).blocks if type(b).__name__ == "Table"]
    assert t2.rows[1][1] == "not upheld for the analytic curve and the simulated curve"
    # every row in the appendix, with its evidence and the cause's full text (HTML note)
    assert [r[0] for r in rows.rows][1:] == [
        "“The error is bounded” (Abstract; the analytic curve)",
        "“The error is bounded” (Abstract; the simulated curve)",
    ]
    assert rows.row_status[1:] == ["upheld", "not_upheld"]
    assert rows.notes[2] == "cause: Eq. 9 ... 4437 m."
    assert "4437 m at 2 h" in rows.rows[2][1]
    # no 'why' in the main text's numbers
    assert all("why" not in b.columns for b in numbers.blocks if type(b).__name__ == "Table")


def test_numbers_at_the_printed_precision_plus_two_digits():
    # 7 printed decimals + 2: the rounded value; the reason column says "truncated"
    assert shown_reproduced("exact", "1.0000199", "1.0000199999907") == "1.000020000"
    assert shown_reproduced("approximate", "2400", "2248.1") == "2248.10"
    note = "MC 5-95 %: [29.99801, 30.00151]; noise-free real: 29.9995"
    assert shown_reproduced("statistical", "29.9990", "29.999491", note) == (
        "29.999491 [29.998010, 30.001510]"
    )
    assert reproduced_header(["statistical"]) == "MC median [5-95 %]"
    assert reproduced_header(["exact", "statistical"]) == "ours, or MC median [5-95 %]"
    tol = "% error: |ours - printed| <= 1e-09 (an exact inversion: 0 means exact (not 0.5 %))"
    assert compact_tolerance(tol, "0") == (
        "% error: |ours - printed| <= 1e-09",
        "an exact inversion: 0 means exact (not 0.5 %)",
    )


def test_one_vocabulary_and_its_colours():
    assert plain_words("not_upheld (not_checkable)") == "not upheld (not checkable)"
    assert tone("differs", "paper_error") == "bad"
    assert {tone("differs", k) for k in ("text_artefact", "convention", "")} == {"partial"}
    assert tone("differs", "unclear_from_text") == "neutral"  # grey: not red, not amber
    assert differs_word("convention") == "approximation or convention"
    import pipeline.columns as columns

    if hasattr(columns, "DIFFERS_KINDS"):  # the audit's kinds all have their words
        assert {differs_word(k) for k in columns.DIFFERS_KINDS} == {
            "error of the paper", "artefact of the text", "approximation or convention",
            "cannot tell from the text",
        }  # fmt: skip


@pytest.mark.parametrize("slug", ["north_finding", "platform_drift", "altimeter_attitude"])
def test_every_paper_lists_main_claims_that_name_its_rows(slug):
    """2-4 main claims per paper, each a sentence, validated with the file."""
    data = load_published(ROOT / "config" / "published" / f"{slug}.yaml")
    claims = data["main_claims"]
    assert 2 <= len(claims) <= 4
    assert all(c["text"].endswith(".") for c in claims)
