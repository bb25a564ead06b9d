"""The altimeter_attitude workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.altimeter_attitude.paper`). The figure steps are
:func:`pipeline.altimeter_attitude.figures.figures_step` and
:func:`pipeline.altimeter_attitude.figures_sweep.sweep_figure_step`."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["simulate", "sweep", "verdicts"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: the Monte Carlo of every filter."""
    from pipeline.altimeter_attitude.run import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["rms_summary"]).parent, log=log)


def sweep(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The one-at-a-time sensitivity sweep around the base scenario."""
    from pipeline.altimeter_attitude.columns import SWEEP_COLUMNS
    from pipeline.altimeter_attitude.scenario import load_scenario
    from pipeline.altimeter_attitude.sweep import run_sweep
    from pipeline.altimeter_attitude.trouble import trouble_frame
    from pipeline.atomic import write_csv
    from pipeline.trouble import TROUBLE_COLUMNS

    settings = params["sweep"]
    trouble: list[tuple] = []
    frame = run_sweep(
        load_scenario(inputs["scenario"]),
        dict(settings["values"]),
        int(settings["n_runs"]),
        tuple(settings["filters"]),
        log=log,
        trouble=trouble,
    )
    write_csv(outputs["sweep"], frame, SWEEP_COLUMNS)
    write_csv(outputs["trouble"], trouble_frame(trouble), TROUBLE_COLUMNS)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.altimeter_attitude.verdicts import write_verdicts

    results = Path(inputs["results"][0]).parent
    frame = write_verdicts(
        inputs["published"],
        inputs["scenario"],
        results,
        outputs["verdicts"],
        inputs["sweep"],
        inputs.get("ukf_tuning"),
    )
    log(frame["verdict"].value_counts().to_string())
