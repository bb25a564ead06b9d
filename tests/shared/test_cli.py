"""The ``inertial-repro`` console command (pipeline/cli.py): its dispatcher, its declaration in
pyproject.toml, and the north-finding subcommand on the shipped example readings against the
library."""

from __future__ import annotations

import importlib
import importlib.metadata
import inspect
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline import cli
from pipeline.altimeter_attitude import flightlog
from pipeline.north_finding import readings as rd
from pipeline.north_finding.run import _readings
from pipeline.north_finding.scenario import load_scenario
from tests.hang_guard import HANG_GUARD_S

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "config" / "scenarios" / "north_finding" / "example_readings.yaml"


def run_cli(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    """``python -m pipeline.cli ARGS`` in a fresh interpreter (as the console script runs it)."""
    return subprocess.run(
        [sys.executable, "-m", "pipeline.cli", *args],
        cwd=cwd,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )


@pytest.mark.parametrize("argv", [["no-such-command"], [], ["North-Finding", "estimate"]])
def test_unknown_or_missing_subcommand_is_a_usage_error(argv):
    r = run_cli(*argv)
    assert r.returncode == 2, r
    assert r.stdout == ""
    assert r.stderr.startswith("usage: inertial-repro [-h] SUBCOMMAND ...\n"), r.stderr
    assert "Traceback" not in r.stderr
    if argv:
        assert f"invalid choice: {argv[0]!r}" in r.stderr
        for name in cli.commands():
            assert repr(name) in r.stderr  # what is allowed


def test_top_level_help_lists_the_subcommands_and_names_the_formats():
    r = run_cli("--help")
    assert r.returncode == 0 and r.stderr == "", r
    text = " ".join(r.stdout.split())  # summaries are wrapped
    assert set(cli.commands()) == {"north-finding", "flight-log"}
    for name, command in cli.commands().items():
        assert f" {name} " in text
        assert " ".join(command.summary.split()) in text
    for column in rd.READINGS_COLUMNS:
        assert column in cli.commands()["north-finding"].summary


def test_flight_log_summary_names_the_columns_the_reader_needs(tmp_path):
    """A log with exactly the columns the summary names (rad/s variant) is read; dropping any
    one of them is refused: the summary names every required column."""
    summary = cli.commands()["flight-log"].summary
    words = [w.strip(",()") for w in summary.split()]
    named = [w for w in words if w.startswith(("t_s", "gyro_", "accel_", "altimeter_"))]
    assert named == [
        "t_s", "gyro_x_rad_s", "gyro_y_rad_s", "gyro_z_rad_s",
        "accel_x_m_s2", "accel_y_m_s2", "accel_z_m_s2", "altimeter_m",
    ]  # fmt: skip
    n = 6
    frame = pd.DataFrame({c: np.zeros(n) for c in named})
    frame["t_s"] = 0.01 * np.arange(n)
    frame["accel_z_m_s2"] = -9.8
    frame["altimeter_m"] = [100.0, np.nan, 100.0, np.nan, 100.0, np.nan]
    path = tmp_path / "log.csv"
    frame.to_csv(path, index=False)
    log = flightlog.read_log(path)
    assert log.t.size == n
    for column in named:
        frame.drop(columns=[column]).to_csv(path, index=False)
        with pytest.raises(flightlog.FlightLogError, match=column.split("_")[0]):
            flightlog.read_log(path)


@pytest.mark.parametrize(
    ("argv", "needles"),
    [
        (
            ["north-finding", "estimate", "--help"],
            [*rd.READINGS_COLUMNS, "NED", "3-2-1", "about z_T", "clockwise seen from above",
             "m/s^2", "rad/s", "reads -g", "Worked example"],
        ),
        (
            ["flight-log", "--help"],
            ["t_s", "gyro_x_rad_s", "accel_x_m_s2", "altimeter_m", "NED", "3-2-1", "x forward",
             "m/s^2", "rad/s", "Example", "roll_deg"],
        ),
    ],
)  # fmt: skip
def test_subcommand_help_documents_format_frames_and_units(argv, needles):
    r = run_cli(*argv)
    assert r.returncode == 0 and r.stderr == "", r
    assert r.stdout.startswith(f"usage: inertial-repro {' '.join(argv[:-1])} "), r.stdout[:80]
    missing = [n for n in needles if n not in r.stdout]
    assert not missing, missing


def test_dispatcher_help_imports_no_subcommand():
    """``inertial-repro --help`` imports neither numpy/pandas nor any subcommand's module."""
    code = (
        "import sys\nfrom pipeline import cli\ntry:\n    cli.main(['--help'])\n"
        "except SystemExit as e:\n    assert e.code == 0\n"
        "print('\\n'.join(sorted(sys.modules)), file=sys.stderr)\n"
    )
    r = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env={"PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )
    assert r.returncode == 0, r.stderr
    loaded = set(r.stderr.split())
    heavy = {"numpy", "pandas", *(c.module for c in cli.commands().values())}
    assert not heavy & loaded, heavy & loaded
    assert "pipeline.cli" in loaded  # the listing above is the real one


def test_console_script_is_declared_and_resolves():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    target = meta["project"]["scripts"]["inertial-repro"]
    module, _, attr = target.partition(":")
    func = getattr(importlib.import_module(module), attr)
    assert callable(func) and func is cli.main
    # the installed packages cover the dispatcher and every subcommand's module
    include = meta["tool"]["setuptools"]["packages"]["find"]["include"]
    for name in [module, *(c.module for c in cli.commands().values())]:
        top = name.split(".")[0]
        assert any(top == p.rstrip("*") for p in include), (name, include)
    assert meta["build-system"]["build-backend"] == "setuptools.build_meta"


def test_every_subcommand_module_takes_argv_and_prog():
    for name, command in cli.commands().items():
        main = importlib.import_module(command.module).main
        params = inspect.signature(main).parameters
        assert list(params)[:2] == ["argv", "prog"], (name, list(params))


def test_installed_console_script_matches_pyproject():
    """Where the project is installed (``make venv``), its entry point is the declared one."""
    try:
        dist = importlib.metadata.distribution("inertial-repro")
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("project not installed in this environment (make venv installs it)")
    scripts = {e.name: e.value for e in dist.entry_points if e.group == "console_scripts"}
    assert scripts == {"inertial-repro": "pipeline.cli:main"}
    assert (Path(sys.executable).parent / "inertial-repro").is_file()


def test_north_finding_estimate_matches_the_library(tmp_path):
    """The shipped example readings through the command line, with the site, compass and
    methods of their scenario file, give the library's estimates to the last bit (--out) and
    to the printed precision (stdout)."""
    raw = yaml.safe_load(EXAMPLE.read_text(encoding="utf-8"))
    out = tmp_path / "estimates.csv"
    site = raw["site"]
    r = run_cli(
        "north-finding", "estimate",
        "--readings", str(ROOT / raw["readings_csv"]),
        "--lat-deg", repr(site["lat_deg"]),
        "--g", repr(site["g_m_s2"]),
        "--omega-ie", repr(site["omega_ie_rad_s"]),
        "--compass-deg", repr(raw["compass"]["heading_deg"]),
        "--a2-tau-deg", repr(raw["a2_tau_deg"]),
        "--level-source", raw["level_source"],
        "--methods", *raw["methods"],
        "--out", str(out),
        cwd=tmp_path,
    )  # fmt: skip
    assert r.returncode == 0, r.stderr
    lib = _readings(load_scenario(EXAMPLE), log=lambda m: None)["estimates"]
    got = pd.read_csv(out)
    assert list(got["method"]) == list(lib["method"])
    assert list(got["quantity"]) == list(lib["quantity"])
    assert len(got) >= 20 and set(got["method"]) == set(raw["methods"])
    np.testing.assert_array_equal(got["estimate"].to_numpy(), lib["estimate"].to_numpy(float))
    rows = [line.split() for line in r.stdout.splitlines()[1:]]
    assert [(row[0], row[1]) for row in rows] == list(
        zip(lib["method"], lib["quantity"], strict=True)
    )
    printed = np.array([float(row[2]) for row in rows])  # method quantity estimate [flag]
    np.testing.assert_allclose(printed, lib["estimate"].to_numpy(float), rtol=1e-6, atol=0)
