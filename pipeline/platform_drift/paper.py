"""The platform_drift plug-in: position error of a stable-platform INS with the
position-independent algorithm under gyro drift (eqs. 28-36, Table 2; Figs. 5-8).

>>> PAPER.slug, PAPER.paper_figure_numbers
('platform_drift', [5, 6, 7, 8])
"""

from __future__ import annotations

from pipeline.paper import Context, FigureSpec, Paper, Step, page_step
from pipeline.platform_drift.scenario import load_scenario

__all__ = ["PAPER", "TITLE", "CITATION"]

TITLE = (
    "Gyroscope drift error analysis in the position-independent navigation algorithm of a "
    "stable platform inertial system"
)
CITATION = (
    "M. Ghesmati, J. Heirani Nobari, M. R. Arvan, A. Kashaninia, Persian journal paper with an "
    "English abstract, accepted 1397 (2018); the journal's name is not in the seed text"
)

_CURVES = (
    "position error of the proposed scheme (analytic eqs. 32/36 and nonlinear simulation) and "
    "of the strapdown INS. The simulated proposed curve is drawn on top, dashed with open "
    "markers: with a channel-3 drift it lies on the strapdown curve, and the panel below "
    "(sim. − strapdown) gives their difference in metres on its own axis. Dotted grey: the "
    "proposed scheme with the true azimuth rate in eq. 16 "
    "(the part of the error eqs. 33-36 model). Black diamond and dotted line: the 2 h strapdown "
    "error and the crossover time the paper's text gives for that panel "
    "(config/published/platform_drift.yaml)."
)
FIGURES = (
    FigureSpec("fig5_stationary.png", 5, f"(stationary vehicle): {_CURVES}"),
    FigureSpec("fig6_latitude_change.png", 6, f"(large latitude change): {_CURVES}"),
    FigureSpec("fig7_longitude_change.png", 7, f"(large longitude change): {_CURVES}"),
    FigureSpec("fig8_lat_lon_change.png", 8, f"(large latitude and longitude change): {_CURVES}"),
    FigureSpec(
        "fig9_latitude.png",
        None,
        "the stationary case rerun at latitudes 0-80 deg; error at 2 h of each curve. The "
        "strapdown channel-3 error scales with cos(latitude).",
    ),
)


# --------------------------------------------------------------------------- workflow steps
#: the scenario the latitude sweep (Extra fig. 9) varies and the notebook reads
SWEEP_SCENARIO = "stationary"
SCENARIO_SCHEMA = "config/schemas/platform_drift_scenario.schema.json"
SCENARIO_CSVS = ("errors", "errors_diagnostic", "errors_long", "errors_long_diagnostic")


def _figure_pngs(ctx: Context) -> list[str]:
    return [ctx.figure(f.file) for f in FIGURES if f.in_paper]


STEPS = (
    Step(
        "simulate",
        "pipeline.platform_drift.steps:simulate",
        per_scenario=True,
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.scenario_file("{scenario}"), SCENARIO_SCHEMA),
        },
        outputs=lambda ctx: {
            **{n: f"{ctx.results}/{{scenario}}/{n}.csv" for n in SCENARIO_CSVS},
            "summary": f"{ctx.results}/{{scenario}}/summary.csv",
            "numerical_trouble": f"{ctx.results}/{{scenario}}/numerical_trouble.csv",
            "provenance": f"{ctx.results}/{{scenario}}/provenance.json",
        },
        report={"summary": ("Scenario summaries", "scenario_summary")},
    ),
    Step(
        "verdicts",
        "pipeline.platform_drift.steps:verdicts",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "errors": ctx.per_scenario("errors.csv"),
            "errors_long": ctx.per_scenario("errors_long.csv"),
            "diagnostic": ctx.per_scenario("errors_diagnostic.csv"),
        },
        outputs=lambda ctx: {"verdicts": f"{ctx.results}/verdicts.csv"},
        report={"verdicts": ("Verdicts", "verdicts")},
    ),
    Step(
        "figures",
        "pipeline.platform_drift.steps:figures",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "errors": ctx.per_scenario("errors.csv"),
            "diagnostic": ctx.per_scenario("errors_diagnostic.csv"),
        },
        outputs=lambda ctx: {
            "png": _figure_pngs(ctx),
            "svg": [ctx.figure(f.svg) for f in FIGURES if f.in_paper],
        },
    ),
    Step(
        "latitude_sweep",
        "pipeline.platform_drift.steps:latitude_sweep",
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.scenario_file(SWEEP_SCENARIO), SCENARIO_SCHEMA),
        },
        outputs=lambda ctx: {
            "csv": f"{ctx.results}/latitude_sweep.csv",
            "trouble": f"{ctx.results}/latitude_sweep_trouble.csv",
            "png": ctx.figure("fig9_latitude.png"),
            "svg": ctx.figure("fig9_latitude.svg"),
        },
    ),
    page_step(
        lambda ctx: {
            "summaries": ctx.per_scenario("summary.csv"),
            "trouble": ctx.per_scenario("numerical_trouble.csv"),
            "sweep_trouble": f"{ctx.results}/latitude_sweep_trouble.csv",
            "provenance": ctx.per_scenario("provenance.json"),
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "figures": [ctx.figure(f.file) for f in FIGURES],
        }
    ),
)

PAPER = Paper(
    slug="platform_drift",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=FIGURES,
    steps=STEPS,
    notebook_inputs=lambda ctx: [f"{ctx.results}/{SWEEP_SCENARIO}/errors.csv"],
    report="pipeline.platform_drift.report:report",
    load_published="pipeline.platform_drift.verdicts:load_published",
    discussion="pipeline.platform_drift.discussion:discussion",
)
