"""Bad config/config.yaml, as the workflow reads it: ``snakemake -n`` in one temporary copy of the
repository (made once for the module), each case editing the file and restoring it."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import Case, Edit, ids, make_repo, refuse_at_parse

CONFIG = "config/config.yaml"
F = "config/config.yaml"


def _c(id, field, value, allowed, *edits, file=F):
    return Case(id, file, field, value, allowed, edits=tuple(edits))


def _r(old, new):
    return Edit(CONFIG, replace=(old, new))


def _alias_bomb(levels: int = 9) -> str:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, levels)]
    return "\n".join(lines) + "\n"


CASES = [
    _c("results_dir_escapes", "results_dir", "'../escaped'", "inside it",
       _r("results_dir: results", "results_dir: ../escaped")),
    _c("results_dir_absolute", "results_dir", "'/tmp/out'", "inside it",
       _r("results_dir: results", "results_dir: /tmp/out")),
    _c("reports_dir_dotdot", "reports_dir", "'a/../../b'", "without '..'",
       _r("reports_dir: reports", "reports_dir: a/../../b")),
    _c("results_dir_empty", "results_dir", "''", "non-empty",
       _r("results_dir: results", "results_dir: ''")),
    _c("results_dir_number", "results_dir", "5", "string",
       _r("results_dir: results", "results_dir: 5")),
    _c("results_dir_nan", "results_dir", "nan", "finite numbers only",
       _r("results_dir: results", "results_dir: .nan")),
    _c("duplicate_key", "reports_dir", "line 5", "each key once",
       _r("reports_dir: reports", "reports_dir: reports\nreports_dir: r2")),
    _c("duplicate_nested_key", "n_runs", "line 16", "each key once",
       _r("    n_runs: 20 ", "    n_runs: 20\n    n_runs: 30 ")),
    _c("unknown_key", "report_dir", "unknown key", "allowed keys",
       _r("reports_dir: reports", "reports_dir: reports\nreport_dir: r2")),
    _c("papers_not_a_list", "papers", "'north_finding'", "array",
       _r("papers: [north_finding, platform_drift, altimeter_attitude]", "papers: north_finding")),
    _c("papers_unknown_slug", "papers", "'nope'", "north_finding",
       _r("papers: [north_finding,", "papers: [nope, north_finding,")),
    _c("papers_bad_slug", "papers", "'../x'", "^[a-z][a-z0-9_]*$",
       _r("papers: [north_finding,", "papers: ['../x', north_finding,")),
    _c("papers_duplicate", "papers", "north_finding", "unique",
       _r("papers: [north_finding,", "papers: [north_finding, north_finding,")),
    _c("papers_empty", "papers", "[]", "minItems 1",
       _r("papers: [north_finding, platform_drift, altimeter_attitude]", "papers: []")),
    _c("missing_papers", "papers", None, "required",
       _r("papers: [north_finding, platform_drift, altimeter_attitude]", "")),
    _c("published_scenario_unknown", "north_finding.published_scenario", "'nope'", "paper",
       _r("published_scenario: paper", "published_scenario: nope")),
    _c("sweep_n_runs_huge", "altimeter_attitude: sweep.n_runs", "1e+300", "<= 1000",
       _r("n_runs: 20 ", "n_runs: 1.0e+300 ")),
    _c("sweep_n_runs_fraction", "altimeter_attitude: sweep.n_runs", "2.5", "integer",
       _r("n_runs: 20 ", "n_runs: 2.5 ")),
    _c("ukf_alpha_nan", "altimeter_attitude.ukf_tuning.alpha.0", "nan", "finite numbers only",
       _r("alpha: [0.001,", "alpha: [.nan,")),
    _c("sweep_base_escapes", "altimeter_attitude: sweep.base_scenario", "'../../etc/passwd.yaml'",
       "config/scenarios/altimeter_attitude/",
       _r("base_scenario: config/scenarios/altimeter_attitude/paper.yaml",
          "base_scenario: ../../etc/passwd.yaml")),
    _c("sweep_value_out_of_range", "altimeter_attitude: sweep.values.imu_rate_hz.0", "0",
       ">= 1", _r("imu_rate_hz: [25,", "imu_rate_hz: [0,")),
    _c("paper_settings_missing", "altimeter_attitude", None, "missing",
       Edit(CONFIG, delete=("altimeter_attitude",))),
    _c("settings_for_a_paper_without", "platform_drift", "{'x': 1}", "takes no settings",
       Edit(CONFIG, set={"platform_drift": {"x": 1}})),
    _c("alias_bomb", "expands to", "more than 200000 values", "at most that many values",
       Edit(CONFIG, append=_alias_bomb())),
    _c("python_tag", "line 5", "tag:yaml.org,2002:python/object/apply:os.system",
       "YAML's standard tags",
       _r("reports_dir: reports", "reports_dir: !!python/object/apply:os.system ['true']")),
    _c("custom_tag", "line 5", "!include", "YAML's standard tags",
       _r("reports_dir: reports", "reports_dir: !include other.yaml")),
    _c("tab_indent", "line 6", "'\\t'", "allowed:",
       _r("reports_dir: reports", "reports_dir:\n\treports")),
    _c("binary", "byte 0", "b'\\x89'", "UTF-8", Edit(CONFIG, data=b"\x89PNG\r\n\x1a\n\x00\x00")),
    _c("latin1_byte", "byte", "b'\\xe9'", "UTF-8",
       Edit(CONFIG, data="# caf\xe9\npapers: [north_finding]\n".encode("latin-1"))),
    _c("nul_byte", "contains", "NUL bytes", "a YAML text file",
       Edit(CONFIG, data=b"papers: [north_finding]\n\x00\n")),
    _c("empty_file", "(top level)", "empty", "papers", Edit(CONFIG, text="")),
    _c("top_level_list", "(top level)", "a list", "a mapping",
       Edit(CONFIG, text="- north_finding\n")),
]  # fmt: skip


@pytest.fixture(scope="module")
def top(tmp_path_factory):
    top = tmp_path_factory.mktemp("config-corpus")
    make_repo(top)
    return top


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_workflow_config_is_refused_at_parse(top, case):
    refuse_at_parse(top, case)
