"""The platform_drift workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.platform_drift.paper`)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["simulate", "verdicts", "figures", "latitude_sweep"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: analytic, simulated and strapdown error curves (2 h and 24 h)."""
    from pipeline.platform_drift.run import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["errors"]).parent, log=log)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.platform_drift.verdicts import write_verdicts

    results = Path(inputs["errors"][0]).parents[1]
    scenarios_dir = Path(inputs["scenario_files"][0]).parent
    frame = write_verdicts(inputs["published"], results, outputs["verdicts"], scenarios_dir)
    log(frame["verdict"].value_counts().to_string())


def figures(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Figs. 5-8, published values overlaid."""
    from pipeline.platform_drift.figures import run

    results = Path(inputs["errors"][0]).parents[1]
    scenarios_dir = Path(inputs["scenario_files"][0]).parent
    out_dir = Path(outputs["png"][0]).parent
    written = run(results, scenarios_dir, out_dir, inputs["published"])
    if sorted(map(str, written)) != sorted(outputs["png"]):
        raise ValueError(f"wrote {sorted(map(str, written))}, declared {sorted(outputs['png'])}")


def latitude_sweep(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Error at 2 h against latitude (a figure the paper lacks)."""
    import pandas as pd

    from pipeline.atomic import write_csv
    from pipeline.platform_drift.sweep import SWEEP_COLUMNS, plot, sweep
    from pipeline.trouble import TROUBLE_COLUMNS

    trouble: list[pd.DataFrame] = []
    frame = sweep(inputs["scenario"], log=log, trouble=trouble)
    write_csv(outputs["csv"], frame, SWEEP_COLUMNS)
    write_csv(outputs["trouble"], pd.concat(trouble, ignore_index=True), TROUBLE_COLUMNS)
    plot(frame, outputs["png"])  # and the SVG beside it
