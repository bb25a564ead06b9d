"""The pendulum workflow steps, called as ``step(inputs, outputs, params, log)``."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

__all__ = ["load_published", "simulate", "verdicts", "figures"]


def load_published(path: str | Path) -> dict:
    """The published file validated with the pendulum's selectors and claim tests."""
    from pipeline.pendulum.claims import CLAIMS
    from pipeline.pendulum.quantities import check_item

    from pipeline.verdicts.published import load_published as load

    return load(path, claims=CLAIMS, check_item=check_item)


def simulate(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.pendulum.simulate import run_scenario

    run_scenario(inputs["scenario"], Path(outputs["periods"]).parent, log=log)


def verdicts(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.pendulum.claims import CLAIMS
    from pipeline.pendulum.quantities import check_item, locate, read_results

    from pipeline.verdicts import engine

    results = Path(inputs["periods"][0]).parents[1]
    frame = engine.write_verdicts(
        inputs["published"],
        outputs["verdicts"],
        locate=locate,
        claims=CLAIMS,
        read_results=lambda: read_results(results),
        check_item=check_item,
    )
    log(frame["verdict"].value_counts().to_string())


def figures(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    from pipeline.pendulum.figures import write_period_figure

    write_period_figure(inputs["periods"], outputs["png"])
