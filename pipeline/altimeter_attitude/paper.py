"""The altimeter_attitude plug-in: roll and pitch from an IMU and a barometric altimeter, a linear
Kalman filter on the third DCM row against a UKF (100-run Monte Carlo; Figs. 2-12).

>>> PAPER.slug, PAPER.paper_figure_numbers
('altimeter_attitude', [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12])
"""

from __future__ import annotations

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.paper import Context, FigureSpec, Paper, Step, page_step

__all__ = ["PAPER", "TITLE", "CITATION", "MATH_STEMS"]

TITLE = "Strapdown attitude estimation using IMU and altimeter integration for maneuvering vehicles"
CITATION = (
    "H. Ghanbarpour Asl, S. H. Pourtakdust (Sharif University of Technology), "
    "Persian journal paper with an English abstract; its journal and year are not in the seed text"
)

#: the sensor outputs: omegat and ft are the measured angular rate and specific force
MATH_STEMS = {"omegat": "tilde(omega)", "ft": "tilde(f)"}

# Figure file -> caption (after its label). The paper's figure number is in the file name.
_FIGURE_TEXT: dict[str, str] = {
    "fig2_third_row.png": "nominal trajectory: the third-row DCM elements C31, C32, C33 against "
    "time.",
    "fig3_specific_force.png": "specific force measured by the accelerometers (body axes). Its "
    "large vertical-plane part is why accelerometer levelling fails.",
    "fig4_vertical_channel.png": "vertical channel: down velocity V_d and altitude h against time.",
    "fig5_angular_rates.png": "angular rates measured by the gyros (body axes).",
    "fig6_roll_pitch.png": "true roll and pitch against time.",
    "fig7_lkf_rms_error.png": "linear Kalman filter: Monte Carlo RMS of the roll and pitch "
    "estimation errors against time (the paper reads its roll/pitch RMS off this figure).",
    "fig8_lkf_c_rms.png": "linear Kalman filter: Monte Carlo RMS error of the DCM parameters "
    "c1, c2, c3.",
    "fig9_lkf_sigma.png": "linear Kalman filter: RMS over runs of the filter's own roll and "
    "pitch standard deviation (compare with Fig. 7).",
    "fig10_norm_error.png": "linear Kalman filter: RMS of the normalisation error 1 - c^T c.",
    "fig11_ukf_sigma.png": "UKF: RMS over runs of the filter's own roll and pitch standard "
    "deviation (compare with Fig. 12).",
    "fig12_ukf_rms_error.png": "UKF: Monte Carlo RMS of the roll and pitch estimation errors "
    "against time (the paper reads its UKF roll/pitch RMS off this figure).",
    "fig_compare_filters.png": "roll and pitch errors of every filter of this reproduction ("
    + ", ".join(ALTIMETER_FILTERS)
    + ") in the published scenario.",
    SWEEP_FIGURE: "one-at-a-time sweep around the published scenario; RMS roll and pitch error "
    "against each swept parameter (values in the table below).",
}


def _number(file: str) -> int | None:
    head = file.split("_", 1)[0]
    return int(head[3:]) if head[3:].isdigit() else None


def _caption(file: str) -> str:
    n = _number(file)
    return f"(paper Fig. {n}): {_FIGURE_TEXT[file]}" if n is not None else _FIGURE_TEXT[file]


PAPER_FIGURES = tuple(FigureSpec(f, _number(f), _caption(f)) for f in [*FIGURES, SWEEP_FIGURE])


# --------------------------------------------------------------------------- workflow steps
#: what the simulate step writes per scenario (results/altimeter_attitude/<scenario>/<name>.csv)
SCENARIO_SCHEMA = "config/schemas/altimeter_attitude_scenario.schema.json"
RESULT_CSVS = (
    "rms_summary",
    "noise_free",
    "run_rms",
    "timeseries",
    "truth",
    "window_summary",
    "window_run_rms",
)


def _published(ctx: Context, name: str) -> str:
    """A result file of the scenario the published values are compared with."""
    return f"{ctx.results}/{ctx.settings['published_scenario']}/{name}"


def _figure_outputs(ctx: Context) -> dict[str, list[str]]:
    return {
        "png": [ctx.figure(f) for f in FIGURES],
        "svg": [ctx.figure(FigureSpec(f, None, "").svg) for f in FIGURES],
    }


def _chunks(ctx: Context) -> dict[str, object]:
    """A scenario's chunk files (monte_carlo.chunk_runs), the inputs of its merge; none for a
    Monte Carlo run in one job."""
    from pipeline.altimeter_attitude.chunk_plan import chunk_bounds

    def files(wildcards) -> list[str]:
        sc = load_scenario(ctx.scenario_file(wildcards.scenario))
        n = len(chunk_bounds(sc.n_runs, sc.chunk_runs))
        return [f"{ctx.results}/{wildcards.scenario}/chunks/{c}.mcsums" for c in range(n)]

    return {"chunks": files}


def _chunk_resources(ctx: Context) -> dict[str, object]:
    """A chunk job's memory and run time, from its scenario's size (chunk_plan.chunk_request)."""
    from pipeline.altimeter_attitude.chunk_plan import chunk_request

    def pick(name: str):
        return lambda wc: getattr(
            chunk_request(load_scenario(ctx.scenario_file(wc.scenario))), name
        )

    return {"mem_mb": pick("mem_mb"), "runtime": pick("runtime")}


STEPS = (
    Step(
        "simulate",
        "pipeline.altimeter_attitude.steps:simulate",
        per_scenario=True,
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.scenario_file("{scenario}"), SCENARIO_SCHEMA),
            **_chunks(ctx),
        },
        outputs=lambda ctx: {
            **{n: f"{ctx.results}/{{scenario}}/{n}.csv" for n in RESULT_CSVS},
            "numerical_trouble": f"{ctx.results}/{{scenario}}/numerical_trouble.csv",
            "provenance": f"{ctx.results}/{{scenario}}/provenance.json",
        },
        report={"rms_summary": ("Scenario summaries", "scenario_summary")},
    ),
    # a scenario with monte_carlo.chunk_runs: one job per chunk of runs (merged by simulate)
    Step(
        "simulate_chunk",
        "pipeline.altimeter_attitude.steps:simulate_chunk",
        per_scenario=True,
        wildcards=("chunk",),
        inputs=lambda ctx: ctx.run_inputs(ctx.scenario_file("{scenario}"), SCENARIO_SCHEMA),
        outputs=lambda ctx: {"sums": f"{ctx.results}/{{scenario}}/chunks/{{chunk}}.mcsums"},
        resources=_chunk_resources,
    ),
    Step(
        "sweep",
        "pipeline.altimeter_attitude.steps:sweep",
        inputs=lambda ctx: {
            **ctx.run_inputs(ctx.settings["sweep"]["base_scenario"], SCENARIO_SCHEMA),
        },
        outputs=lambda ctx: {
            "sweep": f"{ctx.results}/sweep.csv",
            "trouble": f"{ctx.results}/sweep_trouble.csv",
        },
        params=lambda ctx: {"sweep": dict(ctx.settings["sweep"])},
        report={"sweep": ("Sweep", "sweep")},
    ),
    Step(
        "ukf_tuning",
        "pipeline.altimeter_attitude.ukf_tuning:tuning_step",
        inputs=lambda ctx: {
            **ctx.run_inputs(
                ctx.scenario_file(ctx.settings["published_scenario"]), SCENARIO_SCHEMA
            ),
        },
        outputs=lambda ctx: {"ukf_tuning": _published(ctx, "ukf_tuning.csv")},
        params=lambda ctx: {"ukf_tuning": dict(ctx.settings["ukf_tuning"])},
    ),
    Step(
        "verdicts",
        "pipeline.altimeter_attitude.steps:verdicts",
        inputs=lambda ctx: {
            **ctx.published_inputs,
            "scenario": ctx.scenario_file(ctx.settings["published_scenario"]),
            "scenario_schema": SCENARIO_SCHEMA,
            "results": [_published(ctx, f"{n}.csv") for n in RESULT_CSVS],
            "sweep": f"{ctx.results}/sweep.csv",
            "ukf_tuning": _published(ctx, "ukf_tuning.csv"),
        },
        outputs=lambda ctx: {"verdicts": f"{ctx.results}/verdicts.csv"},
        report={"verdicts": ("Verdicts", "verdicts")},
    ),
    Step(
        "figures",
        "pipeline.altimeter_attitude.figures:figures_step",
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
        "pipeline.altimeter_attitude.figures_sweep:sweep_figure_step",
        inputs=lambda ctx: {"sweep": f"{ctx.results}/sweep.csv", **ctx.published_inputs},
        outputs=lambda ctx: {
            "png": ctx.figure(SWEEP_FIGURE),
            "svg": ctx.figure(FigureSpec(SWEEP_FIGURE, None, "").svg),
        },
    ),
    page_step(
        lambda ctx: {
            "summaries": ctx.per_scenario("rms_summary.csv"),
            "windows": ctx.per_scenario("window_summary.csv"),
            "noise_free": ctx.per_scenario("noise_free.csv"),
            "trouble": ctx.per_scenario("numerical_trouble.csv"),
            "sweep_trouble": f"{ctx.results}/sweep_trouble.csv",
            "provenance": ctx.per_scenario("provenance.json"),
            "scenario_files": [ctx.scenario_file(s) for s in ctx.scenarios],
            "scenario_schema": SCENARIO_SCHEMA,
            "sweep": f"{ctx.results}/sweep.csv",
            "ukf_tuning": _published(ctx, "ukf_tuning.csv"),
            "figures": [ctx.figure(f) for f in [*FIGURES, SWEEP_FIGURE]],
        }
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
    report="pipeline.altimeter_attitude.report:report",
    load_published="pipeline.altimeter_attitude.verdicts:load_published",
    discussion="pipeline.altimeter_attitude.discussion:discussion",
    warm_up="pipeline.altimeter_attitude.warm_kernels:main",
    math_stems=MATH_STEMS,
    # the notebook's last table reads the paper scenario's summary when it exists: an input,
    # so that the notebook runs after it (else its output depends on the job order)
    notebook_inputs=lambda ctx: (
        [f"{ctx.results}/paper/rms_summary.csv"] if "paper" in ctx.scenarios else []
    ),
)
