"""Bad command lines of ``inertial-repro north-finding ...`` (and of the dispatcher), each run in
a fresh interpreter with the compute probes of tests/bad_input/harness.py."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import PROBES, Case, cli, ids, refuse_on_cli
from tests.workflow_harness import ROOT

SCEN = ROOT / "config" / "scenarios" / "north_finding"
READINGS = (SCEN / "data" / "example_readings.csv").read_text(encoding="utf-8")
SIMULATED = (SCEN / "third_quadrant_south.yaml").read_text(encoding="utf-8")
INPUTS = {"r.csv": READINGS, "sim.yaml": SIMULATED}

ESTIMATE = {
    "--readings": "{dir}/r.csv",
    "--lat-deg": "-33.9",
    "--g": "9.80665",
    "--compass-deg": "220",
    "--out": "{dir}/est.csv",
}
SIMULATE = {"--scenario": "{dir}/sim.yaml", "--out": "{dir}/sim.csv"}


def _argv(command: str, base: dict[str, str], change: dict[str, str | None]) -> tuple[str, ...]:
    opts = {**base, **change}
    args = ["north-finding", command]
    for k, v in opts.items():
        if v is not None:
            args += [k, *v.split(" ")] if k == "--methods" else [k, v]
    return tuple(args)


def _est(id, change, field, value, allowed, file=None):
    return Case(id, file, field, value, allowed, argv=_argv("estimate", ESTIMATE, change),
                inputs=INPUTS)  # fmt: skip


def _sim(id, change, field, value, allowed, file=None, inputs=None):
    return Case(id, file, field, value, allowed, argv=_argv("simulate-readings", SIMULATE, change),
                inputs={**INPUTS, **(inputs or {})})  # fmt: skip


CASES = [
    _est("lat_95", {"--lat-deg": "95"}, "--lat-deg", "'95'", "(-90, 90)"),
    _est("lat_text", {"--lat-deg": "north"}, "--lat-deg", "'north'", "(-90, 90)"),
    _est("lat_nan", {"--lat-deg": "nan"}, "--lat-deg", "'nan'", "(-90, 90)"),
    _est("compass_nan", {"--compass-deg": "nan"}, "--compass-deg", "'nan'", "[-180, 360]"),
    _est("compass_inf", {"--compass-deg": "inf"}, "--compass-deg", "'inf'", "[-180, 360]"),
    _est("g_inf", {"--g": "inf"}, "--g", "'inf'", "[9.7, 9.9]"),
    _est("g_in_cm_s2", {"--g": "980.665"}, "--g", "'980.665'", "[9.7, 9.9]"),
    _est("g_zero", {"--g": "0"}, "--g", "'0'", "[9.7, 9.9]"),
    _est("earth_rate_deg_h", {"--omega-ie": "15.04"}, "--omega-ie", "'15.04'", "(0, 0.0001]"),
    _est("level_source", {"--level-source": "L9"}, "--level-source", "'L9'", "'L1'"),
    _est("unknown_method", {"--methods": "L1 L7"}, "--methods", "'L7'", "'A6'"),
    _est("a2_tau_360", {"--a2-tau-deg": "360"}, "--a2-tau-deg", "'360'", "[0, 360)"),
    _est("a3_accuracy_zero", {"--a3-accuracy-deg": "0"}, "--a3-accuracy-deg", "'0'", "(0, 90]"),
    _est("out_is_a_directory", {"--out": "{dir}"}, "--out", "{dir}", "is a directory"),
    _est("out_is_the_readings", {"--out": "{dir}/r.csv"}, "--out", "r.csv", "the readings"),
    _est("out_parent_is_a_file", {"--out": "{dir}/r.csv/est.csv"}, "--out", "r.csv/est.csv",
         "not a directory"),
    _est("readings_missing", {"--readings": "{dir}/absent.csv"}, "--readings", "absent.csv",
         "not found", file="absent.csv"),
    _est("readings_is_a_directory", {"--readings": "{dir}"}, "--readings", "{dir}",
         "not a file"),
    _est("readings_not_given", {"--readings": None}, "--readings", None, "required"),
    _est("unknown_option", {"--latitude": "3"}, "unrecognized arguments", "--latitude 3",
         "allowed options: --a2-tau-deg"),
    _sim("trial_1e8_text", {"--trial": "1e8"}, "--trial", "'1e8'", "whole number"),
    _sim("trial_huge", {"--trial": "100000000"}, "--trial", "'100000000'", "[0, 1000000]"),
    _sim("trial_over_n_trials", {"--trial": "5000"}, "--trial", "5000", "< 1000"),
    _sim("trial_negative", {"--trial": "-1"}, "--trial", "'-1'", "[0, 1000000]"),
    _sim("scenario_of_readings", {"--scenario": "{dir}/rd.yaml"}, "type", "'readings'",
         "'simulated'", file="rd.yaml",
         inputs={"rd.yaml": (SCEN / "example_readings.yaml").read_text(encoding="utf-8")}),
    _sim("scenario_missing", {"--scenario": "{dir}/absent.yaml"}, "--scenario", "absent.yaml",
         "not found", file="absent.yaml"),
    _sim("scenario_binary", {"--scenario": "{dir}/bin.yaml"}, "byte 0", "b'\\x89'", "UTF-8",
         file="bin.yaml", inputs={"bin.yaml": b"\x89PNG\r\n\x1a\n\x00\x00"}),
    _sim("scenario_bad_field", {"--scenario": "{dir}/bad.yaml"}, "site.lat_deg", "95", "< 90",
         file="bad.yaml", inputs={"bad.yaml": SIMULATED.replace("lat_deg: -33.9", "lat_deg: 95")}),
    _sim("sim_out_is_a_directory", {"--out": "{dir}"}, "--out", "{dir}", "is a directory"),
    Case("no_such_subcommand", None, "SUBCOMMAND", "'north-fnding'", "'north-finding'",
         argv=("north-fnding", "estimate")),
    Case("no_such_nf_command", None, "command", "'estimates'", "'estimate'",
         argv=("north-finding", "estimates")),
]  # fmt: skip


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_north_finding_command_line_is_refused(tmp_path, case):
    refuse_on_cli(tmp_path, case)


@pytest.mark.parametrize("command", ["estimate", "simulate-readings"])
def test_the_unchanged_command_line_is_accepted_and_computes(tmp_path, command):
    """Control: the base command lines run (exit 0) and reach a compute probe, so a refusal
    above comes from the one change and the probes see compute."""
    base = ESTIMATE if command == "estimate" else SIMULATE
    for name, text in INPUTS.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    argv = [a.replace("{dir}", str(tmp_path)) for a in _argv(command, base, {})]
    sentinel = tmp_path / "compute-started"
    proc = cli(argv, tmp_path, sentinel, PROBES)
    assert proc.returncode == 0, proc.stderr
    assert sentinel.read_text() in PROBES
