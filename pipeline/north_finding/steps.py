"""The north_finding workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.north_finding.paper`)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

__all__ = ["simulate", "verdicts", "figures"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: estimates, Monte Carlo, error budget, sensitivity, provenance."""
    from pipeline.north_finding.run import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["estimates"]).parent, log=log)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Verdict of every published number and claim (published scenario's results)."""
    from pipeline.north_finding.verdicts import write_verdicts

    frame = write_verdicts(
        inputs["published"],
        Path(inputs["estimates"]).parent,
        outputs["verdicts"],
        scenario=inputs["scenario"],
        audit=inputs["audit"],
    )
    log(frame["verdict"].value_counts().to_string())


def figures(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Figs. 1-5 of the paper and the sensitivity figure (PNG and SVG)."""
    from pipeline.north_finding.figures import run

    out_dir = Path(outputs["png"][0]).parent
    written = run(Path(inputs["mc_trials"]).parent, inputs["published"], out_dir)
    _check_written(written, [*outputs["png"], *outputs["svg"]])


def _check_written(written: Any, expected: list[str]) -> None:
    got = sorted(str(p) for p in written)
    if got != sorted(expected):
        raise ValueError(f"wrote {got}, but the rule declares {sorted(expected)}")
