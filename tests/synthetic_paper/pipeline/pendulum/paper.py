"""The synthetic pendulum paper: the smallest complete plug-in (one derivation, three printed
equations, one scenario, two published numbers, one claim, one figure, a notebook, a page).

It is the worked example of how to add a paper: these files, laid out as in the repository,
and the slug added to ``papers:`` in ``config/config.yaml``; no shared file is edited.

>>> PAPER.slug, PAPER.paper_figure_numbers, [s.name for s in PAPER.steps]
('pendulum', [1], ['simulate', 'verdicts', 'figures', 'report'])
"""

from __future__ import annotations

from pipeline.pendulum.scenario import load_scenario

from pipeline.paper import Context, FigureSpec, Paper, Step, page_step

__all__ = ["PAPER"]

SCENARIO_SCHEMA = "config/schemas/pendulum_scenario.schema.json"
FIGURES = (FigureSpec("fig1_period.png", 1, "Fig. 1: the period against the amplitude"),)


def _periods(ctx: Context) -> list[str]:
    return ctx.per_scenario("periods.csv")


STEPS = (
    Step(
        "simulate",
        "pipeline.pendulum.steps:simulate",
        per_scenario=True,
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.scenario_file("{scenario}"), SCENARIO_SCHEMA),
        },
        outputs=lambda ctx: {
            "periods": f"{ctx.results}/{{scenario}}/periods.csv",
            "provenance": f"{ctx.results}/{{scenario}}/provenance.json",
        },
    ),
    Step(
        "verdicts",
        "pipeline.pendulum.steps:verdicts",
        inputs=lambda ctx: {**ctx.published_inputs, "periods": _periods(ctx)},
        outputs=lambda ctx: {"verdicts": f"{ctx.results}/verdicts.csv"},
        report={"verdicts": ("Verdicts", "verdicts")},
    ),
    Step(
        "figures",
        "pipeline.pendulum.steps:figures",
        inputs=lambda ctx: {"periods": f"{ctx.results}/paper/periods.csv"},
        outputs=lambda ctx: {
            "png": ctx.figure(FIGURES[0].file),
            "svg": ctx.figure(FIGURES[0].svg),
        },
    ),
    page_step(
        lambda ctx: {
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "figures": [ctx.figure(f.file) for f in FIGURES],
        }
    ),
)

PAPER = Paper(
    slug="pendulum",
    title="The period of a simple pendulum (a synthetic paper)",
    citation="The test suite's own paper, tests/synthetic_paper/",
    load_scenario=load_scenario,
    figures=FIGURES,
    steps=STEPS,
    report="pipeline.pendulum.report:report",
    load_published="pipeline.pendulum.steps:load_published",
)
