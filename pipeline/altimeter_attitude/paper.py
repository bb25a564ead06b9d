"""The altimeter_attitude plug-in: roll and pitch from an IMU and a barometric altimeter, a linear
Kalman filter on the third DCM row against a UKF (100-run Monte Carlo; Figs. 2-12).

>>> PAPER.slug, PAPER.paper_figure_numbers
('altimeter_attitude', [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12])
"""

from __future__ import annotations

from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.paper import Context, FigureSpec, Paper, Step

__all__ = ["PAPER", "TITLE", "CITATION"]

TITLE = "Strapdown attitude estimation using IMU and altimeter integration for maneuvering vehicles"
CITATION = (
    "H. Ghanbarpour Asl, S. H. Pourtakdust (Sharif University of Technology), "
    "Persian journal paper with an English abstract; its journal and year are not in the seed text"
)


def _number(file: str) -> int | None:
    head = file.split("_", 1)[0]
    return int(head[3:]) if head[3:].isdigit() else None


PAPER_FIGURES = tuple(
    FigureSpec(f, _number(f), f"Fig. {_number(f)}" if _number(f) else "not in the paper")
    for f in [*FIGURES, SWEEP_FIGURE]
)


# --------------------------------------------------------------------------- workflow steps
#: what the simulate step writes per scenario (results/altimeter_attitude/<scenario>/<name>.csv)
SCENARIO_SCHEMA = "config/schemas/altimeter_attitude_scenario.schema.json"
RESULT_CSVS = ("rms_summary", "noise_free", "run_rms", "timeseries", "truth")


def _published(ctx: Context, name: str) -> str:
    """A result file of the scenario the published values are compared with."""
    return f"{ctx.results}/{ctx.settings['published_scenario']}/{name}"


def _figure_outputs(ctx: Context) -> dict[str, list[str]]:
    return {
        "png": [ctx.figure(f) for f in FIGURES],
        "svg": [ctx.figure(FigureSpec(f, None, "").svg) for f in FIGURES],
    }


STEPS = (
    Step(
        "simulate",
        "pipeline.altimeter_attitude.steps:simulate",
        per_scenario=True,
        inputs=lambda ctx: {
            "scenario": ctx.scenario_file("{scenario}"),
            "schema": SCENARIO_SCHEMA,
            "codegen": f"{ctx.results}/codegen_check.txt",
        },
        outputs=lambda ctx: {
            **{n: f"{ctx.results}/{{scenario}}/{n}.csv" for n in RESULT_CSVS},
            "provenance": f"{ctx.results}/{{scenario}}/provenance.json",
        },
        report={"rms_summary": ("Scenario summaries", "scenario_summary")},
    ),
    Step(
        "sweep",
        "pipeline.altimeter_attitude.steps:sweep",
        inputs=lambda ctx: {
            "scenario": ctx.settings["sweep"]["base_scenario"],
            "schema": SCENARIO_SCHEMA,
            "codegen": f"{ctx.results}/codegen_check.txt",
        },
        outputs=lambda ctx: {"sweep": f"{ctx.results}/sweep.csv"},
        params=lambda ctx: {"sweep": dict(ctx.settings["sweep"])},
        report={"sweep": ("Sweep", "sweep")},
    ),
    Step(
        "verdicts",
        "pipeline.altimeter_attitude.steps:verdicts",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            "scenario": ctx.scenario_file(ctx.settings["published_scenario"]),
            "scenario_schema": SCENARIO_SCHEMA,
            "results": [_published(ctx, f"{n}.csv") for n in RESULT_CSVS],
        },
        outputs=lambda ctx: {"verdicts": f"{ctx.results}/verdicts.csv"},
        report={"verdicts": ("Verdicts", "verdicts")},
    ),
    Step(
        "figures",
        "pipeline.altimeter_attitude.steps:figures",
        inputs=lambda ctx: {
            "truth": _published(ctx, "truth.csv"),
            "timeseries": _published(ctx, "timeseries.csv"),
            "summary": _published(ctx, "rms_summary.csv"),
            "provenance": _published(ctx, "provenance.json"),
            **ctx.published_inputs,
        },
        outputs=_figure_outputs,
    ),
    Step(
        "sweep_figure",
        "pipeline.altimeter_attitude.steps:sweep_figure",
        inputs=lambda ctx: {"sweep": f"{ctx.results}/sweep.csv", **ctx.published_inputs},
        outputs=lambda ctx: {
            "png": ctx.figure(SWEEP_FIGURE),
            "svg": ctx.figure(FigureSpec(SWEEP_FIGURE, None, "").svg),
        },
    ),
    Step(
        "report",
        "pipeline.altimeter_attitude.steps:page",
        inputs=lambda ctx: {
            "audit": f"{ctx.results}/equation_audit.csv",
            "verdicts": f"{ctx.results}/verdicts.csv",
            "summaries": ctx.per_scenario("rms_summary.csv"),
            "noise_free": ctx.per_scenario("noise_free.csv"),
            "provenance": ctx.per_scenario("provenance.json"),
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "sweep": f"{ctx.results}/sweep.csv",
            "figures": [ctx.figure(f) for f in [*FIGURES, SWEEP_FIGURE]],
        },
        outputs=lambda ctx: {"page": ctx.page},
        params=lambda ctx: {"published_scenario": ctx.settings["published_scenario"]},
        report={"page": ("Pages", "page")},
    ),
)

PAPER = Paper(
    slug="altimeter_attitude",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=PAPER_FIGURES,
    steps=STEPS,
    settings_schema="altimeter_attitude_config",
)
