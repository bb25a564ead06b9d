"""Bad published-values files (config/published/<slug>.yaml) of the three papers, refused when
the workflow is parsed (not in the verdicts job): every case through
``pipeline.registry.check_workflow``, the cases marked ``snakemake=True`` also through
``snakemake -n``; one temporary copy of the repository."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import Case, Edit, ids, make_repo, refuse_at_parse, refuse_in_check

NF = "config/published/north_finding.yaml"
PD = "config/published/platform_drift.yaml"
AA = "config/published/altimeter_attitude.yaml"


def _set(file, id, field, value, where, shown, allowed, snakemake=False):
    """``field`` (dotted) of ``file`` set to ``value``; the message names ``where`` (the item),
    shows ``shown`` and says ``allowed``."""
    return Case(id, file, where, shown, allowed, edits=(Edit(file, set={field: value}),),
                snakemake=snakemake)  # fmt: skip


def _file(file, id, field, shown, allowed, **edit):
    return Case(id, file, field, shown, allowed, edits=(Edit(file, **edit),))


CASES = [
    _set(NF, "nf_kind_unknown", "items.0.kind", "roughly", "field 'kind'", "'roughly'",
         "statistical", snakemake=True),
    _set(NF, "nf_value_not_a_number", "items.0.value", "abc", "field 'value'", "'abc'",
         "allowed"),
    _set(NF, "nf_value_nan", "items.0.value", float("nan"), "field 'value'", "nan", "string"),
    _set(NF, "nf_duplicate_id", "items.1.id", "T1.phi.L1", "field 'id'", "T1.phi.L1", "unique"),
    _set(NF, "nf_unknown_method", "items.0.select.method", "L9", "select", "L9", "allowed"),
    _set(NF, "nf_unknown_key", "junk", 1, "field 'junk'", "junk", "only the keys"),
    _set(NF, "nf_other_paper", "paper", "platform_drift", "field 'paper'", "'platform_drift'",
         "north_finding"),
    _file(NF, "nf_python_tag", "line 1", "python/object/apply:os.system",
          "YAML's standard tags", text="paper: !!python/object/apply:os.system ['true']\n"),
    _file(NF, "nf_empty", "top level", "None", "type object", text=""),
    _set(PD, "pd_kind_unknown", "items.0.kind", "roughly", "field 'kind'", "'roughly'",
         "approximate", snakemake=True),
    _set(PD, "pd_unknown_scenario", "items.0.select.scenario", "nowhere", "select",
         "nowhere", "stationary"),
    _set(PD, "pd_value_inf", "items.0.value", float("inf"), "field 'value'", "inf", "string"),
    _set(PD, "pd_missing_unit", "items.0.unit", None, "field 'unit'", "None", "allowed"),
    _file(PD, "pd_binary", "byte 0", "b'\\x89'", "UTF-8", data=b"\x89PNG\r\n\x1a\n\x00\x00"),
    _file(PD, "pd_duplicate_key", "paper", "duplicate key", "each key once",
          replace=("paper: platform_drift", "paper: platform_drift\npaper: platform_drift")),
    _set(AA, "aa_quantity_unknown", "items.0.quantity", "yaw_rms_deg", "field 'quantity'",
         "'yaw_rms_deg'", "roll_rms_deg", snakemake=True),
    _set(AA, "aa_duplicate_claim", "claims.1.id", "C1.linear_beats_ukf", "field 'id'",
         "C1.linear_beats_ukf", "unique"),
    _set(AA, "aa_alpha_2", "claims.0.predicate.alpha", 2.0, "field 'predicate.alpha'", "2.0",
         "< 1"),
    _set(AA, "aa_unknown_test", "claims.0.predicate.test", "looks_good", "predicate.test",
         "looks_good", "less_rms"),
    _file(AA, "aa_alias_bomb", "expands to", "more than 200000 values", "at most",
          append="".join(
              [f"b{i}: &b{i} [{', '.join([f'*b{i - 1}'] * 9)}]\n" if i else "b0: &b0 [x, x, x, x, x, x, x, x, x]\n"
               for i in range(9)])),
]  # fmt: skip


@pytest.fixture(scope="module")
def top(tmp_path_factory):
    top = tmp_path_factory.mktemp("published-corpus")
    make_repo(top)
    return top


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_published_file_is_refused_when_the_workflow_is_parsed(top, case):
    refuse_in_check(top, case)


THROUGH_SNAKEMAKE = [c for c in CASES if c.snakemake]


@pytest.mark.parametrize("case", THROUGH_SNAKEMAKE, ids=ids(THROUGH_SNAKEMAKE))
def test_published_file_is_refused_by_snakemake_in_one_line(top, case):
    refuse_at_parse(top, case)
