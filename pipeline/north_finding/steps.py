"""The north_finding workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.north_finding.paper`). The figures step is
:func:`pipeline.north_finding.figures.figures_step`."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["infer_n", "simulate", "verdicts"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: estimates, Monte Carlo, error budget, sensitivity, provenance."""
    from pipeline.north_finding.run import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["estimates"]).parent, log=log)


def infer_n(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The N the published values imply, over the published scenario's n_inference grid."""
    from pipeline.north_finding.run_inference import infer_scenario

    infer_scenario(inputs["scenario"], inputs["published"], Path(outputs["n_rows"]).parent, log=log)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Verdict of every published number and claim (published scenario's results)."""
    from pipeline.north_finding.verdicts import write_verdicts

    frame = write_verdicts(
        inputs["published"],
        Path(inputs["estimates"]).parent,
        outputs["verdicts"],
        scenario=inputs["scenario"],
        audit=inputs["audit"],
        sensitivity_out=outputs["n_sensitivity"],
    )
    log(frame["verdict"].value_counts().to_string())
