"""The north_finding plug-in: levelling and north finding at rest with one accelerometer and one
gyro on a turntable (methods L1-L5, A1-A6; Tables 1-12, Figs. 1-5).

>>> PAPER.slug, PAPER.paper_figure_numbers
('north_finding', [1, 2, 3, 4, 5])
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from pipeline.north_finding.scenario import (
    ROOT,
    load_scenario,
    scenario_data_files,
    scenario_trials_format,
)
from pipeline.paper import Context, FigureSpec, Paper, Step, page_step

__all__ = ["PAPER", "TITLE", "CITATION", "FIGURE_CAPTIONS", "trials_files"]

TITLE = "The derivation of modern inertial navigation methods at stationary state"
CITATION = (
    "Mohammadkarimi, Nourani, Alizadeh Roknabadi, J. Aerospace Science and Technology (Persian), "
    "vol. 13 no. 1, 2023"
)

_BOX = (
    "Boxes: Monte Carlo distribution of |percent error| of the noisy real sensor at the main "
    "Monte Carlo's N (averaging.n_samples; the statistical verdicts are judged on a mixture "
    "over the N the paper's own values imply, see Findings) "
    "(box 25–75 %, whiskers 5–95 %, line median); hollow circle: real sensor without noise; "
    "red diamond: the percent error printed in the paper. Log scale."
)
#: figure file stem -> caption (after the label "Fig. N" or "Extra fig. k")
FIGURE_CAPTIONS: dict[str, str] = {
    "fig1_roll": (
        f"(paper Fig. 1, Table 1): roll φ percent error of levelling methods L1–L4. {_BOX}"
    ),
    "fig2_pitch": (
        f"(paper Fig. 2, Table 2): pitch θ percent error of levelling methods L1–L4. {_BOX}"
    ),
    "fig3_azimuth": (
        f"(paper Fig. 3, Table 9): azimuth ψ percent error of azimuth methods "
        f"A1c1, A1c2, A2, A3, A4, A5. {_BOX}"
    ),
    "fig4_bias": (
        f"(paper Fig. 4, Tables 3 and 10): percent error of the accelerometer bias "
        f"(levelling method 5) and the gyro bias (azimuth method 4). {_BOX}"
    ),
    "fig5_scale": (
        f"(paper Fig. 5, Tables 4, 11, 12): percent error of the accelerometer scale factor "
        f"(method L5), the gyro scale factor (A4, A5, A6) and its first-order approximation "
        f"(A5, A6). {_BOX}"
    ),
    "fig6_sensitivity": (
        "Monte Carlo RMS percent error of the azimuth estimate against "
        "the number of samples averaged per table position (log–log). Dashed vertical line: the "
        "scenario's default n_avg; short ticks at the right edge: the published percent error of "
        "each method, in the method's colour. The paper does not state n_avg; this figure shows "
        "which averaging its errors imply."
    ),
}

# --------------------------------------------------------------------------- workflow steps
#: what the simulate step writes per scenario (results/north_finding/<scenario>/); mc_trials
#: and mc_trials_judged are .npy instead of .csv above trials_file.CSV_MAX_TRIALS trials (or as
#: the scenario's monte_carlo.trials_file says): :func:`trials_files`
SCENARIO_SCHEMA = "config/schemas/north_finding_scenario.schema.json"
SCENARIO_FILES = (
    "estimates.csv",
    "mc_trials.csv",
    "mc_summary.csv",
    "error_budget.csv",
    "sensitivity.csv",
    "ranking.csv",
    "ranking_pairs.csv",
    "a2_scan.csv",
    "numerical_trouble.csv",
    "provenance.json",
)
#: the per-trial files (CSV or binary: pipeline/north_finding/trials_file.py)
TRIAL_STEMS = ("mc_trials", "mc_trials_judged")
#: what the N inference writes into the published scenario's folder
#: (:mod:`pipeline.north_finding.run_inference`)
INFERENCE_FILES = (
    "n_profile.csv",
    "n_rows.csv",
    "n_robustness.csv",
    "mc_trials_judged.csv",
    "n_trouble.csv",
)
#: what the verdicts read from the published scenario's folder
VERDICT_INPUTS = (
    "n_rows.csv",
    "mc_trials_judged.csv",
    "estimates.csv",
    "mc_trials.csv",
    "error_budget.csv",
    "ranking.csv",
    "ranking_pairs.csv",
    "a2_scan.csv",
    "provenance.json",
)


def _published(ctx: Context, name: str) -> str:
    """A result file of the scenario the published tables are compared with."""
    return f"{ctx.results}/{ctx.settings['published_scenario']}/{_named(ctx, name)}"


def _format(ctx: Context, scenario: str) -> str:
    return scenario_trials_format(ROOT / ctx.scenario_file(scenario))


def _named(ctx: Context, name: str, scenario: str | None = None) -> str:
    """``name`` with the per-trial files in the scenario's form (``mc_trials.csv`` ->
    ``mc_trials.npy`` for a binary one; default: the published scenario)."""
    fmt = _format(ctx, scenario or ctx.settings["published_scenario"])
    stem, ext = name.rsplit(".", 1)
    return f"{stem}.{fmt}" if stem in TRIAL_STEMS and ext == "csv" else name


def trials_files(ctx: Context, scenario: str, names: tuple[str, ...] = SCENARIO_FILES) -> list[str]:
    """The files of ``names`` one scenario's folder holds (per-trial files in its form)."""
    return [f"{ctx.results}/{scenario}/{_named(ctx, n, scenario)}" for n in names]


def _simulate(fmt: str) -> Step:
    """The simulate step of the scenarios whose per-trial results are ``fmt``."""
    files = [f"mc_trials.{fmt}" if f == "mc_trials.csv" else f for f in SCENARIO_FILES]
    return Step(
        "simulate" if fmt == "csv" else f"simulate_{fmt}",
        "pipeline.north_finding.steps:simulate",
        per_scenario=True,
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.scenario_file("{scenario}"), SCENARIO_SCHEMA),
            "data": _data_files(ctx),
        },
        outputs=lambda ctx: {f.split(".")[0]: f"{ctx.results}/{{scenario}}/{f}" for f in files},
        scenarios=lambda ctx: tuple(s for s in ctx.scenarios if _format(ctx, s) == fmt),
    )


def _figures(ctx: Context) -> dict[str, list[str]]:
    return {
        "png": [ctx.figure(f.file) for f in PAPER_FIGURES],
        "svg": [ctx.figure(f.svg) for f in PAPER_FIGURES],
    }


def _data_files(ctx: Context) -> Callable[[Any], list[str]]:
    """Input function: the readings CSV a scenario of ``type: readings`` reads."""
    return lambda wildcards: scenario_data_files(ctx.scenario_file(wildcards.scenario))


PAPER_FIGURES = tuple(
    FigureSpec(f"{stem}.png", number if number <= 5 else None, caption)
    for number, (stem, caption) in enumerate(FIGURE_CAPTIONS.items(), 1)
)
STEPS = (
    _simulate("csv"),
    _simulate("npy"),
    Step(
        "infer_n",
        "pipeline.north_finding.steps:infer_n",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            **ctx.run_inputs(
                ctx.scenario_file(ctx.settings["published_scenario"]), SCENARIO_SCHEMA
            ),
        },
        outputs=lambda ctx: {f.split(".")[0]: _published(ctx, f) for f in INFERENCE_FILES},
    ),
    Step(
        "verdicts",
        "pipeline.north_finding.steps:verdicts",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            **{f.split(".")[0]: _published(ctx, f) for f in VERDICT_INPUTS},
            "scenario": ctx.scenario_file(ctx.settings["published_scenario"]),
            "scenario_schema": SCENARIO_SCHEMA,
            "audit": f"{ctx.results}/equation_audit.csv",
        },
        outputs=lambda ctx: {
            "verdicts": f"{ctx.results}/verdicts.csv",
            "n_sensitivity": f"{ctx.results}/n_sensitivity.csv",
        },
        report={"verdicts": ("Verdicts", "verdicts")},
    ),
    Step(
        "figures",
        "pipeline.north_finding.figures:figures_step",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            **{n: _published(ctx, f"{n}.csv") for n in ("estimates", "mc_trials", "sensitivity")},
            "provenance": _published(ctx, "provenance.json"),
        },
        outputs=_figures,
    ),
    page_step(
        lambda ctx: {
            "scenarios": [f for s in ctx.scenarios for f in trials_files(ctx, s)],
            "n_inference": [_published(ctx, f) for f in (*INFERENCE_FILES[:3], "n_trouble.csv")],
            "n_sensitivity": f"{ctx.results}/n_sensitivity.csv",
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "figures": _figures(ctx)["png"],
        }
    ),
)

PAPER = Paper(
    slug="north_finding",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=PAPER_FIGURES,
    steps=STEPS,
    settings_schema="north_finding_config",
    report="pipeline.north_finding.report:report",
    load_published="pipeline.north_finding.verdicts:load_published",
    discussion="pipeline.north_finding.discussion:discussion",
)
