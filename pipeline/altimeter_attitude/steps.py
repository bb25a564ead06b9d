"""The altimeter_attitude workflow steps, called by :func:`pipeline.steps.run_step` as
``step(inputs, outputs, params, log)`` (named paths as declared in
:mod:`pipeline.altimeter_attitude.paper`). The figure steps are
:func:`pipeline.altimeter_attitude.figures.figures_step` and
:func:`pipeline.altimeter_attitude.figures_sweep.sweep_figure_step`. The Monte Carlo steps
first keep freed memory for reuse (:func:`pipeline.altimeter_attitude.heap.keep_freed_memory`)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["simulate", "simulate_chunk", "sweep", "verdicts"]


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One scenario: the Monte Carlo of every filter, in this job, or merged from the chunk
    jobs' files (``chunks``: none unless the scenario sets ``monte_carlo.chunk_runs``)."""
    from pipeline.altimeter_attitude.chunks import merge_chunks
    from pipeline.altimeter_attitude.heap import keep_freed_memory
    from pipeline.altimeter_attitude.run import run_scenario, write_results
    from pipeline.altimeter_attitude.scenario import load_scenario

    keep_freed_memory()
    out_dir = Path(outputs["rms_summary"]).parent
    if not inputs["chunks"]:
        run_scenario(inputs["scenario"], out_dir, log=log)
        return
    sc = load_scenario(inputs["scenario"])
    log(f"{sc.name}: merging {len(inputs['chunks'])} chunks of {sc.chunk_runs} runs")
    write_results(sc, out_dir, *merge_chunks(sc, inputs["chunks"]))


def simulate_chunk(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """One chunk of a scenario's Monte Carlo: its block sums (pipeline/altimeter_attitude/chunks.py)."""
    from pipeline.altimeter_attitude.chunks import chunk_bounds, simulate_chunk, write_chunk
    from pipeline.altimeter_attitude.heap import keep_freed_memory
    from pipeline.altimeter_attitude.scenario import load_scenario

    keep_freed_memory()
    sc = load_scenario(inputs["scenario"])
    index = int(params["wildcards"]["chunk"])
    bounds = chunk_bounds(sc.n_runs, sc.chunk_runs)
    if not 0 <= index < len(bounds):
        raise ValueError(f"{sc.name}: chunk {index}: the scenario has {len(bounds)} chunks")
    write_chunk(outputs["sums"], sc, bounds[index], simulate_chunk(sc, bounds[index], log=log))


def sweep(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The one-at-a-time sensitivity sweep around the base scenario."""
    from pipeline.altimeter_attitude.columns import SWEEP_COLUMNS
    from pipeline.altimeter_attitude.heap import keep_freed_memory
    from pipeline.altimeter_attitude.scenario import load_scenario
    from pipeline.altimeter_attitude.sweep import run_sweep
    from pipeline.altimeter_attitude.trouble import trouble_frame
    from pipeline.atomic import write_csv
    from pipeline.trouble import TROUBLE_COLUMNS

    keep_freed_memory()
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
