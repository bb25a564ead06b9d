# Per paper, one rule per step of its plug-in (pipeline/<slug>/paper.py: PAPER.steps):
# `<slug>_<step>`, with a {scenario} wildcard for per-scenario steps. Each rule's code inputs
# are the import graph of its entry point, so an edit reruns exactly the steps it affects.
for _paper in PAPERS.values():
    _ctx = CONTEXTS[_paper.slug]
    for _step in _paper.steps:
        _scenarios = _step.scenarios(_ctx) if _step.scenarios else _ctx.scenarios
        if _step.per_scenario and not _scenarios:
            continue

        rule:
            name:
                f"{_paper.slug}_{_step.name}"
            input:
                **_step.inputs(_ctx),
                code=code(*step_modules(_paper, _step), script="run_step.py"),
            output:
                **step_outputs(_paper, _step),
            log:
                step_log(_paper, _step, "logs"),
            benchmark:
                step_log(_paper, _step, "benchmarks")
            wildcard_constraints:
                scenario="|".join(_scenarios),
                chunk=r"\d+",
            priority: job_priority(step_log(_paper, _step, "benchmarks"))
            conda:
                ENV
            threads: job_threads(step_log(_paper, _step, "benchmarks"))
            resources:
                **(
                    _step.resources(_ctx)
                    if _step.resources
                    else job_resources(step_log(_paper, _step, "benchmarks"))
                ),
            params:
                **_step.params(_ctx),
                entry=_step.entry,
            script:
                "../scripts/run_step.py"

    rule:
        name:
            f"{_paper.slug}_all"
        input:
            paper_targets(_paper.slug),
