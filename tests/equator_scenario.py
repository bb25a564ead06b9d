"""platform_drift's stationary scenario moved to latitude 0 (eq. 36 undefined there), 2 h only:
the one copy the latitude-0 and numerical-trouble tests both run."""

from __future__ import annotations

from pathlib import Path

import yaml

from pipeline.platform_drift.scenario import ROOT

SCEN = ROOT / "config" / "scenarios" / "platform_drift"


def write_equator_scenario(folder: Path) -> Path:
    """Write ``folder/stationary.yaml``: the shipped stationary scenario at latitude 0 with its
    long run (and that run's decision) removed; return its path."""
    raw = yaml.safe_load((SCEN / "stationary.yaml").read_text(encoding="utf-8"))
    raw["start"]["lat_deg"] = 0.0
    raw.pop("long_duration_s")
    raw["decisions"] = [d for d in raw["decisions"] if d["field"] != "long_duration_s"]
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "stationary.yaml"
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return path
