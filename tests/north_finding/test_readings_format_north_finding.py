"""The readings format (roles, refused readings) and method A3's scan bound, checked by
computation: readings generated from the model with a known truth, estimates compared with it."""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.config import ConfigError
from pipeline.north_finding import cli
from pipeline.north_finding import estimators as est
from pipeline.north_finding import readings as rd
from pipeline.north_finding import scan_bound as sb
from pipeline.north_finding.paper import STEPS
from pipeline.north_finding.report_results import scenario_section
from pipeline.north_finding.run import run_scenario
from pipeline.north_finding.scenario import ROOT, build_scenario, load_scenario
from pipeline.registry import context, load_paper

SCEN = ROOT / "config" / "scenarios" / "north_finding"
EXAMPLE_CSV = SCEN / "data" / "example_readings.csv"
OFF = ("scale_factor", "misalignment", "bias", "noise")


def _raw(name: str) -> dict:
    return yaml.safe_load((SCEN / f"{name}.yaml").read_text(encoding="utf-8"))


def _a3_on_scan(sc, tau_deg: np.ndarray, bounds: dict | None = None) -> float:
    """A3's psi (deg) from noise-free ideal x-gyro readings at ``tau_deg`` (role peak)."""
    w = rd.noise_free_gyro(sc, sc.gyro.without(*OFF), tau_deg, "x")
    readings = rd.Readings(
        tau_deg=np.asarray(tau_deg, dtype=float),
        axis=np.full(tau_deg.size, "x"),
        accel=np.zeros((1, tau_deg.size)),
        gyro=w[None, :],
        role=np.full(tau_deg.size, "peak"),
    )
    t = sc.truth
    out = est.azimuth(
        readings,
        est.Site(sc.lat, sc.g, sc.omega_ie),
        ("A3",),
        np.array([t["theta"]]),
        np.array([t["phi"]]),
        np.array([t["psi"] + sc.compass_offset]),
        None,
        bounds=bounds,
    )
    return float(out["A3", "psi_deg"][0])


CASES = [
    (name, step, start)
    for name in ("paper", "third_quadrant_south", "high_latitude")
    for step in (0.1, 1.0, 5.0, 10.0, 30.0, 45.0)
    for start in (0.0, 7.3, 13.9)
]


def test_a3_scan_bound_covers_the_error_of_every_scan_and_is_not_loose():
    """On noise-free ideal readings the only A3 error is the scan's: |error| <= bound for every
    scenario, step and scan phase. The bound is no blanket: computed from half the real gap
    some errors exceed it, and on a 0.1-deg scan it is below 1e-3 deg."""
    worst_ratio = 0.0
    halved_violated = False
    for name, step, start in CASES:
        sc = build_scenario(_raw(name), Path(f"{name}.yaml"))
        tau = (start + np.arange(0.0, 360.0, step)) % 360.0
        bounds: dict = {}
        psi = _a3_on_scan(sc, tau, bounds)
        err = abs((psi - np.rad2deg(sc.truth["psi"]) + 180.0) % 360.0 - 180.0)
        bound = float(bounds["A3"][0])
        assert err <= bound + 1e-9, (name, step, start, err, bound)
        if step <= 0.1:
            assert bound < 1e-3, (name, step, start, bound)
        worst_ratio = max(worst_ratio, err / bound if bound > 0 else 0.0)
        # the same computation with half the gap: the bound must then fail somewhere
        t = sc.truth
        w = rd.noise_free_gyro(sc, sc.gyro.without(*OFF), tau, "x")
        dense = np.sort(np.r_[tau, (tau + step / 2) % 360.0])
        w_dense = np.r_[w, np.full(tau.size, -np.inf)]  # gaps halve, the maximum stays
        order = np.argsort(np.r_[tau, (tau + step / 2) % 360.0], kind="stable")
        half = sb.a3_scan_bound_deg(
            dense, w_dense[order][None, :], sc.omega_ie, sc.lat, t["theta"], t["phi"],
            np.array([t["psi"] + sc.compass_offset]),
        )  # fmt: skip
        halved_violated |= err > float(half[0]) + 1e-9
    assert halved_violated
    assert worst_ratio > 0.5  # the bound is within a factor 2 of the worst actual error


def test_peak_gap_is_the_larger_gap_beside_the_maximum():
    tau = np.array([0.0, 10.0, 40.0, 200.0])
    w = np.array([[0.0, 1.0, 0.5, -1.0], [0.0, 0.5, 1.0, -1.0], [0.0, 0.0, 0.0, 1.0]])
    assert sb.peak_gap_deg(tau, w).tolist() == [30.0, 160.0, 160.0]
    # a maximum beside a gap of 180 deg or more cannot be bounded
    sc = build_scenario(_raw("paper"), Path("paper.yaml"))
    t = sc.truth
    two = np.array([[1.0e-5, 2.0e-5]])
    bound = sb.a3_scan_bound_deg(np.array([0.0, 180.0]), two, sc.omega_ie, sc.lat, t["theta"],
                                 t["phi"], np.array([t["psi"]]))  # fmt: skip
    assert np.isinf(bound).all()


def _scan_scenario(tmp_path: Path, step: float) -> tuple[Path, Path]:
    """A simulated third_quadrant_south with an A3 scan at ``step``, and a readings scenario
    reading its simulate-readings CSV (truth known)."""
    raw = _raw("third_quadrant_south")
    raw["table"]["max_search"] = {"mode": "scan", "step_deg": step}
    sim = tmp_path / f"scan_{step:g}.yaml"
    sim.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    csv = tmp_path / f"scan_{step:g}.csv"
    assert cli.main(["simulate-readings", "--scenario", str(sim), "--out", str(csv)]) == 0
    rdg = _raw("example_readings")
    rdg["readings_csv"] = str(csv)
    path = tmp_path / f"readings_{step:g}.yaml"
    path.write_text(yaml.safe_dump(rdg, sort_keys=False), encoding="utf-8")
    return path, csv


@pytest.mark.parametrize(("step", "flagged"), [(30.0, True), (0.1, False)])
def test_a_coarse_scan_is_flagged_in_results_report_and_cli(tmp_path, capsys, step, flagged):
    path, csv = _scan_scenario(tmp_path, step)
    out = tmp_path / "out"
    run_scenario(load_scenario(path), out, log=lambda m: None)
    e = pd.read_csv(out / "estimates.csv", dtype={"flag": str})
    e["flag"] = e["flag"].fillna("")
    a3 = e[e["method"] == "A3"].iloc[0]
    err = abs((a3["estimate"] - 225.0 + 180.0) % 360.0 - 180.0)
    assert bool(a3["flag"] == sb.FLAG_EXCEEDS) is flagged
    assert bool(a3["scan_bound_deg"] > 0.1) is flagged
    if flagged:  # a 30-deg scan: an error of degrees, inside its bound
        assert 0.5 < err <= a3["scan_bound_deg"]
    assert (e.loc[e["method"] != "A3", "flag"] == "").all()
    text = " ".join(
        b.text for s in scenario_section(out).subsections for b in s.blocks if hasattr(b, "text")
    )
    assert ("scan the peak more finely" in text) is flagged
    capsys.readouterr()
    args = ["estimate", "--readings", str(csv), "--lat-deg", "-33.9", "--g", "9.80665"]
    assert cli.main([*args, "--compass-deg", "220", "--methods", "A3"]) == 0
    assert ("warning:" in capsys.readouterr().err) is flagged
    # a looser accuracy option silences it
    assert (
        cli.main([*args, "--compass-deg", "220", "--methods", "A3", "--a3-accuracy-deg", "90"]) == 0
    )
    assert "warning:" not in capsys.readouterr().err


# ----------------------------------------------------------------------------- refused readings
def _lines() -> list[str]:
    return [
        ln for ln in EXAMPLE_CSV.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")
    ]


def _write(tmp_path: Path, lines: list[str]) -> Path:
    path = tmp_path / "r.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _cell(lines: list[str], row: int, column: str, value: str) -> list[str]:
    header = lines[0].split(",")
    out = list(lines)
    cells = out[row].split(",")
    cells[header.index(column)] = value
    out[row] = ",".join(cells)
    return out


def _row_of(lines: list[str], tau: str, axis: str, role: str) -> int:
    return next(i for i, ln in enumerate(lines) if ln.startswith(f"{tau},{axis},{role},"))


def _z(lines: list[str]) -> int:
    return _row_of(lines, "0", "z", "z")


BAD = [
    (
        "duplicate_position",
        lambda ls: [*ls, ls[1]],
        [f"row {len(_lines())}", "tau_deg", "duplicate position", "row 1", "role fixed"],
    ),
    (
        "two_z_readings",
        lambda ls: [*ls, ls[_z(ls)].replace("0,z,z", "90,z,z", 1)],
        ["column role", "'z'", "one z reading allowed", f"row {_z(_lines())}"],
    ),
    (
        "table_turning",
        lambda ls: (
            [ls[0] + ",table_rate_deg_s", *(ln + ",0" for ln in ls[1:4]), ls[4] + ",5"]
            + [ln + ",0" for ln in ls[5:]]
        ),
        ["row 4", "column table_rate_deg_s", "'5'", "still", "allowed 0"],
    ),
    (
        "fixed_off_cardinal",
        lambda ls: _cell(ls, 2, "tau_deg", "91"),
        ["row 2", "'91'", "role fixed"],
    ),
    (
        "peak_on_y",
        lambda ls: _cell(ls, len(ls) - 1, "axis", "y"),
        [f"row {len(_lines()) - 1}", "column axis", "'y'", "role peak", "['x']"],
    ),
    ("bad_role", lambda ls: _cell(ls, 3, "role", "max"), ["row 3", "column role", "'max'", "peak"]),
    ("half_sample", lambda ls: _cell(ls, 5, "n_samples", "2.5"), ["row 5", "n_samples", "integer"]),
    (
        "no_role_column",
        lambda ls: [",".join(c for i, c in enumerate(ln.split(",")) if i != 2) for ln in ls],
        ["missing columns ['role']", "fixed, ls, a2, peak or z"],
    ),
]


@pytest.mark.parametrize(("case", "edit", "needles"), BAD, ids=[b[0] for b in BAD])
def test_readings_the_format_cannot_express_are_refused(tmp_path, case, edit, needles):
    rd.load_readings_csv(_write(tmp_path, _lines()))  # control: the unchanged file loads
    path = _write(tmp_path, edit(copy.copy(_lines())))
    with pytest.raises(ConfigError) as info:
        rd.load_readings_csv(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg
    for needle in needles:
        assert needle in msg, (needle, msg)


def test_a_readings_scenario_missing_a_needed_reading_is_refused_at_load(tmp_path):
    """The CSV is read when the scenario is validated (Snakefile parse time, before any job)."""
    lines = _lines()
    lines.pop(_z(lines))
    raw = _raw("example_readings")
    raw["readings_csv"] = str(_write(tmp_path, lines))
    path = tmp_path / "no_z.yaml"
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    with pytest.raises(ConfigError) as info:
        load_scenario(path)
    msg = str(info.value)
    assert "no_z.yaml" in msg and "r.csv" in msg and "L5" in msg and "axis z" in msg
    raw["methods"] = [m for m in raw["methods"] if m not in ("L5", "A6")]
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    assert load_scenario(path).methods  # without the methods that need z it loads


def test_the_readings_csv_is_an_input_of_the_simulate_step():
    """So editing the CSV reruns the scenario that reads it (and only it)."""
    paper = load_paper("north_finding")
    ctx = context(paper, yaml.safe_load((ROOT / "config" / "config.yaml").read_text()))
    data = next(s for s in STEPS if s.name == "simulate").inputs(ctx)["data"]

    class W:
        scenario = "example_readings"

    assert data(W) == ["config/scenarios/north_finding/data/example_readings.csv"]
    W.scenario = "paper"
    assert data(W) == []
