"""Bad scenario files, published-values files and command lines fail early with a clear message."""

from __future__ import annotations

import copy

import pytest
import yaml

from pipeline.altimeter_attitude import run, sweep, verdicts
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.config import ConfigError, load_yaml

PAPER = "config/scenarios/altimeter_attitude/paper.yaml"
PUBLISHED = "config/published/altimeter_attitude.yaml"


@pytest.fixture(scope="module")
def raw():
    return load_yaml(PAPER)


def _set(raw, dotted, value):
    out = copy.deepcopy(raw)
    node = out
    *head, last = dotted.split(".")
    for key in head:
        node = node[int(key)] if key.isdigit() else node[key]
    node[last] = value
    return out


@pytest.mark.parametrize(
    ("field", "value", "match"),
    [
        ("sensors.imu_rate_hz", 0.5, r"sensors\.imu_rate_hz.*0\.5"),
        ("sensors.altimeter_every", 0, r"sensors\.altimeter_every"),
        ("sensors.gyro_sigma_deg_s", -1.0, r"sensors\.gyro_sigma_deg_s"),
        ("monte_carlo.n_runs", 1, r"monte_carlo\.n_runs"),
        ("filters.linear_kf.input_matrix", "zoh", r"filters\.linear_kf\.input_matrix.*zoh"),
        ("filters.linear_kf.p0_radial", "full", r"filters\.linear_kf\.p0_radial"),
        ("filters.linear_kf.k_per_s", 40.0, r"filters\.linear_kf\.k_per_s = 40.*k dt"),
        ("filters.ukf.alpha", 0.0, r"filters\.ukf\.alpha"),
        ("metrics.transient_s", 500.0, r"metrics\.transient_s = 500.*shorter"),
        ("metrics.output_rate_hz", 7.0, r"metrics\.output_rate_hz = 7.*divide"),
        ("metrics.after_bank_deg", 0.0, r"metrics\.after_bank_deg"),
        ("metrics.after_bank_deg", 90.0, r"metrics\.after_bank_deg"),
        ("trajectory.duration_s", 200.01, r"trajectory\.duration_s = 200\.01.*whole number"),
        ("trajectory.maneuvers.0.channel", "yaw_deg", r"trajectory\.maneuvers\.0\.channel"),
        ("trajectory.intensity", 4.0, r"trajectory\..* reaches .*must stay within \(-80, 80\) deg"),
        ("trajectory.unknown_key", 1, r"unknown_key"),
    ],
)
def test_bad_scenario_fields_are_named(raw, field, value, match, tmp_path):
    with pytest.raises(ConfigError, match=match):
        build_scenario(_set(raw, field, value), tmp_path / "bad.yaml")


def test_decision_must_name_a_real_field(raw, tmp_path):
    bad = copy.deepcopy(raw)
    bad["decisions"].append({"field": "sensors.no_such", "text": "x"})
    with pytest.raises(ConfigError, match=r"sensors\.no_such"):
        build_scenario(bad, tmp_path / "bad.yaml")


def test_every_shipped_scenario_is_valid():
    from pipeline.altimeter_attitude.paper import PAPER
    from pipeline.registry import validate_scenarios
    from pipeline.scenarios import scenario_names

    directory = "config/scenarios/altimeter_attitude"
    names = scenario_names(directory)
    assert {"paper", "gentle_cruise", "harder_maneuvers"} <= set(names)
    validate_scenarios(PAPER, names, directory)


def test_malformed_published_file(tmp_path):
    data = load_yaml(PUBLISHED)
    data["items"][0]["quantity"] = "yaw_rms_deg"
    path = tmp_path / "published.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=r"item 'V1\.lkf_roll' \(items\[0\]\), field 'quantity': bad value 'yaw_rms_deg'"):  # fmt: skip
        verdicts.load_published(path)
    data = load_yaml(PUBLISHED)
    data["claims"][1]["id"] = data["claims"][0]["id"]
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=r"claims\[1\]\), field 'id'.*unique"):
        verdicts.load_published(path)
    data = load_yaml(PUBLISHED)
    data["claims"][0]["predicate"]["alpha"] = 2.0
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=r"field 'predicate\.alpha': bad value 2\.0; allowed: a number < 1"):  # fmt: skip
        verdicts.load_published(path)


def test_run_cli_rejects_bad_arguments(tmp_path, capsys):
    with pytest.raises(SystemExit):
        run.main(["--scenario", PAPER, "--out-dir", str(tmp_path), "--runs", "1"])
    assert "--runs = 1" in capsys.readouterr().err
    bad = tmp_path / "bad.yaml"
    bad.write_text("description: x\n")
    assert run.main(["--scenario", str(bad), "--out-dir", str(tmp_path / "o")]) == 2
    assert "trajectory" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()  # nothing half-written


def test_sweep_rejects_unknown_parameter():
    with pytest.raises(ValueError, match="sweep parameter 'speed'"):
        sweep.variant(load_scenario(PAPER), "speed", 1.0)


def test_sweep_variant_changes_one_field_only():
    base = load_scenario(PAPER)
    v = sweep.variant(base, "imu_rate_hz", 100)
    assert v.sensors.rate_hz == 100.0 and v.profiles == base.profiles
    v = sweep.variant(base, "initial_error_deg", 5.0)
    assert v.initial.roll_sigma == pytest.approx(5.0 * 3.141592653589793 / 180)
    assert v.sensors == base.sensors
