"""Bad scenario files of the three papers, refused when the workflow is parsed: every case
through ``pipeline.registry.check_workflow`` (what pipeline/rules/common.smk calls), the cases
marked ``snakemake=True`` also through ``snakemake -n``; one temporary copy of the repository."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import Case, Edit, ids, make_repo, refuse_at_parse, refuse_in_check

NF = "config/scenarios/north_finding/paper.yaml"
PD = "config/scenarios/platform_drift/stationary.yaml"
AA = "config/scenarios/altimeter_attitude/paper.yaml"
PYTHON_TAG = "!!python/object/apply:os.system ['true']"


def _alias_bomb(levels: int = 9) -> str:
    lines = ["bomb0: &a0 [x, x, x, x, x, x, x, x, x]"]
    lines += [f"bomb{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, levels)]
    return "\n".join(lines) + "\n"


def _set(file, id, field, value, shown, allowed, snakemake=False):
    """``field`` of ``file`` set to ``value`` (YAML re-dumped); the message shows ``shown``."""
    return Case(id, file, field, shown, allowed, edits=(Edit(file, set={field: value}),),
                snakemake=snakemake)  # fmt: skip


def _text(file, id, field, old, new, shown, allowed, snakemake=False):
    """``old`` replaced by ``new`` in the text of ``file`` (comments kept)."""
    return Case(id, file, field, shown, allowed, edits=(Edit(file, replace=(old, new)),),
                snakemake=snakemake)  # fmt: skip


def _file(file, id, field, shown, allowed, snakemake=False, **edit):
    return Case(id, file, field, shown, allowed, edits=(Edit(file, **edit),), snakemake=snakemake)


NF_CASES = [
    _set(NF, "nf_lat_90", "site.lat_deg", 90, "90", "< 90", snakemake=True),
    _text(NF, "nf_lat_nan", "site.lat_deg", "lat_deg: 35.0", "lat_deg: .nan", "nan", "finite"),
    _text(NF, "nf_g_inf", "site.g_m_s2", "g_m_s2: 9.80665", "g_m_s2: .inf", "inf", "finite"),
    _set(NF, "nf_g_in_cm_s2", "site.g_m_s2", 980.665, "980.665", "<= 9.9"),
    _set(NF, "nf_earth_rate_deg_h", "site.omega_ie_rad_s", 15.04, "15.04", "<= 0.0001"),
    _set(NF, "nf_n_samples_huge", "averaging.n_samples", 1.0e300, "1e+300", "<= 1000000000000"),
    _set(NF, "nf_n_samples_fraction", "averaging.n_samples", 2.5, "2.5", "integer"),
    _set(NF, "nf_n_trials_text", "monte_carlo.n_trials", "many", "'many'", "integer"),
    _set(NF, "nf_n_trials_huge", "monte_carlo.n_trials", 100_000_000, "100000000", "<= 1000000"),
    _set(NF, "nf_seed_negative", "monte_carlo.seed", -1, "-1", ">= 0"),
    _set(NF, "nf_unknown_key", "colour", "blue", "colour", "allowed keys"),
    Case("nf_missing_site", NF, "site", None, "required", edits=(Edit(NF, delete=("site",)),)),
    _text(NF, "nf_duplicate_key", "level_source", "level_source: truth ",
          "level_source: truth\nlevel_source: L1 ", "duplicate key", "each key once"),
    _set(NF, "nf_duplicate_positions", "table.ls_positions_deg", [0, 90, 90, 180], "90",
         "non-unique", snakemake=True),
    _set(NF, "nf_position_360", "table.ls_positions_deg", [0, 90, 180, 360], "360", "< 360"),
    _set(NF, "nf_level_source", "level_source", "L9", "'L9'", "'truth'"),
    _set(NF, "nf_unknown_method", "methods", ["L1", "L7"], "'L7'", "'A6'"),
    _set(NF, "nf_no_methods", "methods", [], "[]", "minItems"),
    _set(NF, "nf_psi_400", "truth.psi_deg", 400, "400", "<= 360"),
    _set(NF, "nf_compass_offset_90", "compass.offset_deg", 90, "90", "< 90"),
    _set(NF, "nf_sensitivity_n_zero", "sensitivity.n_avg", [0, 100], "0", ">= 1"),
    _set(NF, "nf_contamination_1", "n_inference.contamination", 1.0, "1.0", "< 1"),
    Case("nf_decision_unknown_field", NF, "decisions.0.field", "'site.altitude'",
         "the dotted path of one of its fields",
         edits=(Edit(NF, set={"decisions": [{"field": "site.altitude", "text": "x"}]}),)),
    _file(NF, "nf_alias_bomb", "expands to", "more than 200000 values", "at most",
          append=_alias_bomb()),
    _text(NF, "nf_python_tag", "line 6", "type: simulated", f"type: {PYTHON_TAG}",
          "python/object/apply:os.system", "YAML's standard tags"),
    _file(NF, "nf_binary", "byte 0", "b'\\x89'", "UTF-8", data=b"\x89PNG\r\n\x1a\n\x00\x00"),
    _file(NF, "nf_empty", "a scenario", "NoneType", "mapping", text=""),
    Case("nf_name_dots", "config/scenarios/north_finding/...yaml", "scenario name", "'..'",
         "lower-case letters",
         edits=(Edit("config/scenarios/north_finding/...yaml", text="x: 1\n"),), snakemake=True),
    Case("nf_yml_ignored", "config/scenarios/north_finding/extra.yml", "file name", ".yml",
         "end in .yaml", edits=(Edit("config/scenarios/north_finding/extra.yml", text="x: 1\n"),)),
    Case("nf_readings_csv_outside", "config/scenarios/north_finding/example_readings.yaml",
         "readings_csv", "'/etc/passwd'", "inside",
         edits=(Edit("config/scenarios/north_finding/example_readings.yaml",
                     set={"readings_csv": "/etc/passwd"}),)),
    Case("nf_readings_csv_missing", "config/scenarios/north_finding/example_readings.yaml",
         "readings_csv", "does_not_exist.csv", "not found",
         edits=(Edit("config/scenarios/north_finding/example_readings.yaml",
                     set={"readings_csv": "config/scenarios/north_finding/data/does_not_exist.csv"}),)),
]  # fmt: skip

PD_CASES = [
    _set(PD, "pd_lat_90", "start.lat_deg", 90, "90", "< 90", snakemake=True),
    _text(PD, "pd_lon_nan", "start.lon_deg", "lon_deg: 51.4", "lon_deg: .nan", "nan", "finite"),
    _set(PD, "pd_earth_rate_deg_h", "earth.omega_e_rad_s", 15.04, "15.04", "<= 0.001"),
    _set(PD, "pd_radius_in_km", "earth.radius_m", 6371.0, "6371.0", ">= 6000000.0"),
    _text(PD, "pd_rtol_nan", "integrator.rtol", "rtol: 1.0e-12", "rtol: .nan", "nan", "finite",
          snakemake=True),
    _set(PD, "pd_rtol_loose", "integrator.rtol", 0.1, "0.1", "<= 1e-06"),
    _set(PD, "pd_integrator_unknown", "integrator.method", "Euler", "'Euler'", "DOP853"),
    _set(PD, "pd_duration_huge", "duration_s", 1.0e300, "1e+300", "<= 864000"),
    _set(PD, "pd_output_step_zero", "output_step_s", 0, "0", "> 0"),
    _set(PD, "pd_output_step_over_duration", "output_step_s", 10000.0, "10000.0", "duration_s"),
    _set(PD, "pd_unknown_case", "cases", ["none", "ch2"], "'ch2'", "'ch1'"),
    _set(PD, "pd_duplicate_case", "cases", ["none", "ch1", "ch1"], "'ch1'", "unique"),
    _set(PD, "pd_drift_huge", "drift.ch3_deg_h", 100.0, "100.0", "<= 10"),
    Case("pd_unknown_key", PD, "platform: unknown key", "'psi0_rad'",
         "allowed keys: ['drift_compensation_lost'", edits=(Edit(PD, set={"platform.psi0_rad": 0.0}),)),
    Case("pd_missing_earth", PD, "earth", None, "required", edits=(Edit(PD, delete=("earth",)),)),
    _set(PD, "pd_frame_enu", "strapdown.frame", "enu", "'enu'", "'ned'"),
    _text(PD, "pd_duplicate_key", "duration_s", "duration_s: 7200.0 ",
          "duration_s: 7200.0\nduration_s: 60.0 ", "duplicate key", "each key once"),
    _file(PD, "pd_empty", "a scenario", "NoneType", "mapping", text=""),
    _file(PD, "pd_alias_bomb", "expands to", "more than 200000 values", "at most",
          append=_alias_bomb()),
    _file(PD, "pd_nul", "contains", "NUL bytes", "a YAML text file", data=b"description: x\n\x00\n"),
    Case("pd_name_uppercase", "config/scenarios/platform_drift/Stationary2.yaml",
         "scenario name", "'Stationary2'", "lower-case letters",
         edits=(Edit("config/scenarios/platform_drift/Stationary2.yaml", text="x: 1\n"),)),
]  # fmt: skip

AA_CASES = [
    _text(AA, "aa_imu_rate_inf", "sensors.imu_rate_hz", "imu_rate_hz: 50.0", "imu_rate_hz: .inf",
          "inf", "finite", snakemake=True),
    _set(AA, "aa_gravity_cm_s2", "trajectory.gravity_m_s2", 980.665, "980.665", "<= 9.9"),
    _set(AA, "aa_gyro_sigma_negative", "sensors.gyro_sigma_deg_s", -1.0, "-1.0", ">= 0"),
    _set(AA, "aa_n_runs_huge", "monte_carlo.n_runs", 100_000_000, "100000000", "<= 10000",
         snakemake=True),
    _set(AA, "aa_n_runs_fraction", "monte_carlo.n_runs", 2.5, "2.5", "integer"),
    _set(AA, "aa_channel_yaw", "trajectory.maneuvers.0.channel", "yaw_deg", "'yaw_deg'",
         "'heading_deg'"),
    Case("aa_maneuver_after_end", AA, "trajectory.maneuvers[0].start_s", "500.0",
         "must lie in [0, duration_s = 200)",
         edits=(Edit(AA, set={"trajectory.maneuvers.0.start_s": 500.0}),)),
    _set(AA, "aa_ukf_alpha_zero", "filters.ukf.alpha", 0.0, "0.0", "> 0"),
    _set(AA, "aa_output_rate_7", "metrics.output_rate_hz", 7.0, "7", "divide"),
    _text(AA, "aa_k_nan", "filters.linear_kf.k_per_s", "k_per_s: 1.0", "k_per_s: .nan", "nan",
          "finite"),
    _set(AA, "aa_seed_negative", "monte_carlo.seed", -1, "-1", ">= 0"),
    Case("aa_unknown_key", AA, "sensors: unknown key", "'rate_hz'",
         "allowed keys: ['accel_sigma_m_s2'", edits=(Edit(AA, set={"sensors.rate_hz": 50.0}),)),
    Case("aa_missing_trajectory", AA, "trajectory", None, "required",
         edits=(Edit(AA, delete=("trajectory",)),)),
    _text(AA, "aa_duplicate_key", "imu_rate_hz", "imu_rate_hz: 50.0",
          "imu_rate_hz: 50.0\n  imu_rate_hz: 100.0", "duplicate key", "each key once"),
    _text(AA, "aa_python_tag", "line 8", "duration_s: 200.0", f"duration_s: {PYTHON_TAG}",
          "python/object/apply:os.system", "YAML's standard tags"),
    _file(AA, "aa_binary", "byte 0", "b'\\xff'", "UTF-8", data=b"\xff\xfe\x00d\x00e"),
    _file(AA, "aa_top_level_list", "a scenario", "list", "mapping", text="- a\n"),
]  # fmt: skip

CASES = NF_CASES + PD_CASES + AA_CASES


@pytest.fixture(scope="module")
def top(tmp_path_factory):
    top = tmp_path_factory.mktemp("scenario-corpus")
    make_repo(top)
    return top


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_scenario_is_refused_when_the_workflow_is_parsed(top, case):
    refuse_in_check(top, case)


THROUGH_SNAKEMAKE = [c for c in CASES if c.snakemake]


@pytest.mark.parametrize("case", THROUGH_SNAKEMAKE, ids=ids(THROUGH_SNAKEMAKE))
def test_scenario_is_refused_by_snakemake_in_one_line(top, case):
    refuse_at_parse(top, case)
