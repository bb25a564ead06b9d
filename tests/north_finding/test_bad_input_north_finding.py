"""Bad input to north_finding fails before any compute, with a message naming what is wrong.

Each scenario case is paper.yaml with exactly one change, written to tmp_path; the error
must name the file, the dotted field and what is allowed.
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
import yaml

from pipeline.config import ConfigError
from pipeline.north_finding import readings as rd
from pipeline.north_finding.paper import PAPER as NF_PAPER
from pipeline.north_finding.scenario import ROOT, load_scenario
from pipeline.registry import validate_scenarios

PAPER = ROOT / "config" / "scenarios" / "north_finding" / "paper.yaml"
EXAMPLE_CSV = ROOT / "config" / "scenarios" / "north_finding" / "data" / "example_readings.csv"


def _paper() -> dict:
    return yaml.safe_load(PAPER.read_text(encoding="utf-8"))


def _set(raw: dict, dotted: str, value) -> None:
    *parents, last = dotted.split(".")
    node = raw
    for p in parents:
        node = node[p]
    node[last] = value


def _write(path: Path, raw: dict) -> Path:
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return path


def test_unchanged_copy_loads(tmp_path):
    """Control: the copy itself is valid, so each failure below comes from its one change."""
    sc = load_scenario(_write(tmp_path / "copy_ok.yaml", _paper()))
    assert sc.methods[0] == "L1"


# (case id, dotted field, new value, strings the message must contain besides the file name)
SCENARIO_CASES = [
    ("lat_90", "site.lat_deg", 90, ["site.lat_deg", "90", "< 90"]),
    ("lat_minus_95", "site.lat_deg", -95, ["site.lat_deg", "-95", "> -90"]),
    (
        "two_ls_positions_with_L2",
        "table.ls_positions_deg",
        [0, 90],
        ["table.ls_positions_deg", "L2", "at least 3"],
    ),
    (
        "negative_noise",
        "accelerometer.noise_sigma_frac",
        -0.05,
        ["accelerometer.noise_sigma_frac", "-0.05", ">= 0"],
    ),
    ("unknown_top_level_key", "colour", "blue", ["colour", "allowed keys", "site", "methods"]),
    (
        "unknown_nested_key",
        "site.altitude_m",
        100.0,
        ["site", "altitude_m", "allowed keys", "lat_deg"],
    ),
    ("wrong_type", "monte_carlo.n_trials", "many", ["monte_carlo.n_trials", "'many'", "integer"]),
    ("ranking_n_zero", "ranking.n_avg", [0, 100], ["ranking.n_avg", "0", ">= 1"]),
    ("ranking_one_trial", "ranking.n_trials", 1, ["ranking.n_trials", "1", ">= 2"]),
    ("bad_level_source", "level_source", "L9", ["level_source", "'L9'", "truth", "L1", "L4"]),
    (
        "scan_without_step",
        "table.max_search",
        {"mode": "scan"},
        ["table.max_search.step_deg", "scan"],
    ),
]


@pytest.mark.parametrize(
    ("case", "field", "value", "needles"), SCENARIO_CASES, ids=[c[0] for c in SCENARIO_CASES]
)
def test_bad_scenario_is_refused_with_a_clear_message(tmp_path, case, field, value, needles):
    raw = _paper()
    _set(raw, field, copy.deepcopy(value))
    path = _write(tmp_path / f"{case}.yaml", raw)
    with pytest.raises(ConfigError) as info:
        load_scenario(path)
    assert isinstance(info.value, ValueError)
    msg = str(info.value)
    assert path.name in msg
    for needle in needles:
        assert needle in msg, f"{needle!r} not in {msg!r}"


def test_two_ls_positions_are_fine_without_least_squares_methods(tmp_path):
    """The L2/L4 check is semantic (the method needs n >= 3), not a blanket limit."""
    raw = _paper()
    raw["table"]["ls_positions_deg"] = [0, 90]
    raw["methods"] = [m for m in raw["methods"] if m not in ("L2", "L4")]
    assert load_scenario(_write(tmp_path / "two_ok.yaml", raw)).ls_positions_deg() == [0.0, 90.0]


# --------------------------------------------------------------------------------------------
# readings CSV
# --------------------------------------------------------------------------------------------
def _example_lines() -> list[str]:
    return [
        ln for ln in EXAMPLE_CSV.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")
    ]


def _csv(tmp_path: Path, lines: list[str], name: str = "readings.csv") -> Path:
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _replace_cell(lines: list[str], row: int, column: str, value: str) -> list[str]:
    header = lines[0].split(",")
    out = list(lines)
    cells = out[row].split(",")
    cells[header.index(column)] = value
    out[row] = ",".join(cells)
    return out


def test_example_csv_loads():
    r = rd.load_readings_csv(EXAMPLE_CSV)
    assert r.accel.shape == r.gyro.shape == (1, r.tau_deg.size)
    rd.check_needs(r, ("L1", "A1c1", "A4", "A6"), 45.0)


def test_csv_missing_column(tmp_path):
    lines = _example_lines()
    header = lines[0].split(",")
    drop = header.index("gyro_rad_s")
    cut = [",".join(c for i, c in enumerate(ln.split(",")) if i != drop) for ln in lines]
    path = _csv(tmp_path, cut)
    with pytest.raises(ConfigError, match="gyro_rad_s") as info:
        rd.load_readings_csv(path)
    assert path.name in str(info.value)


def test_csv_non_numeric_cell(tmp_path):
    path = _csv(tmp_path, _replace_cell(_example_lines(), 3, "accel_m_s2", "abc"))
    with pytest.raises(ConfigError) as info:
        rd.load_readings_csv(path)
    msg = str(info.value)
    assert path.name in msg and "row 3" in msg and "accel_m_s2" in msg and "'abc'" in msg


def test_csv_bad_axis(tmp_path):
    path = _csv(tmp_path, _replace_cell(_example_lines(), 2, "axis", "w"))
    with pytest.raises(ConfigError) as info:
        rd.load_readings_csv(path)
    msg = str(info.value)
    assert "row 2" in msg and "axis" in msg and "'w'" in msg and "['x', 'y', 'z']" in msg


def test_csv_tau_360(tmp_path):
    path = _csv(tmp_path, _replace_cell(_example_lines(), 1, "tau_deg", "360"))
    with pytest.raises(ConfigError) as info:
        rd.load_readings_csv(path)
    msg = str(info.value)
    assert "row 1" in msg and "tau_deg" in msg and "360" in msg and "< 360" in msg


def test_csv_missing_position_needed_by_L1(tmp_path):
    lines = _example_lines()
    header = lines[0].split(",")
    ti, ai = header.index("tau_deg"), header.index("axis")
    kept = [lines[0]] + [
        ln
        for ln in lines[1:]
        if not (ln.split(",")[ai] == "x" and float(ln.split(",")[ti]) == 270.0)
    ]
    assert len(kept) < len(lines)
    r = rd.load_readings_csv(_csv(tmp_path, kept))
    with pytest.raises(ValueError) as info:
        rd.check_needs(r, ("L1",), None)
    msg = str(info.value)
    assert "L1" in msg and "270" in msg and "axis x" in msg
    # the methods that do not need tau = 270 on x are content
    rd.check_needs(r, ("A1c1", "A4"), None)


# --------------------------------------------------------------------------------------------
# command line
# --------------------------------------------------------------------------------------------
# (the command line's bad arguments: tests/bad_input/test_cli_north_finding.py)


# --------------------------------------------------------------------------------------------
# workflow: every scenario is validated at parse time
# --------------------------------------------------------------------------------------------
def test_validate_scenarios_refuses_a_bad_file(tmp_path):
    good = _paper()
    bad = _paper()
    bad["site"]["lat_deg"] = 91
    _write(tmp_path / "a_good.yaml", good)
    _write(tmp_path / "b_bad.yaml", bad)
    validate_scenarios(NF_PAPER, ["a_good"], tmp_path)
    with pytest.raises(ConfigError) as info:
        validate_scenarios(NF_PAPER, ["a_good", "b_bad"], tmp_path)
    assert "b_bad.yaml" in str(info.value) and "site.lat_deg" in str(info.value)


def test_readings_scenario_with_missing_csv_is_refused(tmp_path):
    raw = yaml.safe_load(
        (ROOT / "config/scenarios/north_finding/example_readings.yaml").read_text()
    )
    raw["readings_csv"] = "config/scenarios/north_finding/data/does_not_exist.csv"
    path = _write(tmp_path / "missing_csv.yaml", raw)
    with pytest.raises(ConfigError, match="readings_csv") as info:
        load_scenario(path)
    assert path.name in str(info.value) and "not found" in str(info.value)


def test_nan_reading_is_refused(tmp_path):
    path = _csv(tmp_path, _replace_cell(_example_lines(), 4, "gyro_rad_s", "nan"))
    with pytest.raises(ConfigError, match="row 4, column gyro_rad_s"):
        rd.load_readings_csv(path)
