"""The altimeter_attitude workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.altimeter_attitude.paper`)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["simulate", "sweep", "verdicts", "figures", "sweep_figure"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: the Monte Carlo of every filter."""
    from pipeline.altimeter_attitude.run import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["rms_summary"]).parent, log=log)


def sweep(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The one-at-a-time sensitivity sweep around the base scenario."""
    from pipeline.altimeter_attitude.columns import SWEEP_COLUMNS
    from pipeline.altimeter_attitude.scenario import load_scenario
    from pipeline.altimeter_attitude.sweep import run_sweep
    from pipeline.atomic import write_csv

    settings = params["sweep"]
    frame = run_sweep(
        load_scenario(inputs["scenario"]),
        dict(settings["values"]),
        int(settings["n_runs"]),
        tuple(settings["filters"]),
        log=log,
    )
    write_csv(outputs["sweep"], frame, SWEEP_COLUMNS)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.altimeter_attitude.verdicts import write_verdicts

    results = Path(inputs["results"][0]).parent
    frame = write_verdicts(
        inputs["published"], inputs["scenario"], results, outputs["verdicts"], inputs["sweep"]
    )
    log(frame["verdict"].value_counts().to_string())


def figures(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """Figs. 2-12 of the paper and the filter comparison (PNG and SVG)."""
    from pipeline.altimeter_attitude.figures import published_rms, write_all
    from pipeline.config import load_yaml

    published = published_rms(load_yaml(inputs["published"]))
    pngs = [Path(p).name for p in outputs["png"]]
    out_dir = Path(outputs["png"][0]).parent
    written = write_all(Path(inputs["truth"]).parent, out_dir, published, names=pngs)
    expected = sorted([*outputs["png"], *outputs["svg"]])
    if sorted(map(str, written)) != expected:
        raise ValueError(f"wrote {sorted(map(str, written))}, declared {expected}")


def sweep_figure(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.altimeter_attitude.figures import published_rms, write_sweep
    from pipeline.config import load_yaml

    published = published_rms(load_yaml(inputs["published"]))
    write_sweep(Path(inputs["sweep"]), Path(outputs["png"]), published)
