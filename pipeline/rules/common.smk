# Shared set-up: config validation, the paper registry, input functions and report tags.
# Nothing here names a paper: every paper comes from config["papers"] through pipeline.registry.
import os
import re
import sys
from pathlib import Path

# Scripts import `derivations` and `pipeline` from the repository root: the workflow puts the
# root on the PYTHONPATH of its jobs (set here for them; nothing is required from the caller).
# Hash randomisation off in every job: SymPy orders terms by hash, and simplify() picks among
# equally short forms in that order, so with a random seed per process the residual text of
# the equation audit (and the forms a notebook prints) could differ from run to run.
os.environ.update(
    PYTHONPATH=os.pathsep.join(p for p in (workflow.basedir, os.getenv("PYTHONPATH", "")) if p),
    PYTHONHASHSEED="0",
)
sys.path.insert(0, workflow.basedir)

from pipeline.code_inputs import module_closure, notebook_imports, script_imports  # noqa: E402
from pipeline.config import ConfigError  # noqa: E402
from pipeline.job_priority import UNMEASURED_COST_S, dag_bottom_levels  # noqa: E402
from pipeline.job_resources import ResourceTable  # noqa: E402
from pipeline.registry import check_workflow  # noqa: E402

try:
    # config/config.yaml read strictly (duplicate keys, NaN, aliases), validated, its
    # directories kept inside the repository; then the plug-ins and every scenario file
    # (pipeline.registry.check_workflow; the bad-input corpus, tests/bad_input/, calls it too)
    PAPERS, CONTEXTS = check_workflow(config, workflow.configfiles, Path(workflow.basedir))
except ConfigError as _error:
    # one clean message before any job, not Snakemake's stack frames
    sys.stderr.write(f"{_error}\n")
    raise SystemExit(1) from None

RESULTS = config["results_dir"]
REPORTS = config["reports_dir"]
# The software every rule runs with, for `snakemake --sdm conda`. `make reproduce` runs the
# rules in the hash-checked .venv built from environment.lock instead; a test keeps the pins of
# this file equal to the lock's.
ENV = "../envs/inertial-repro.yaml"
# Captions of the outputs tagged for `snakemake --report` (reStructuredText, Jinja-templated).
CAPTIONS = "../../reports/snakemake"
SCRIPTS = "pipeline/scripts"
# Each job's threads, mem_mb and runtime (minutes) on a cluster, from measured peaks
# (config/job_resources.csv, written by `python -m pipeline.job_resources`); a job not in it
# gets the profile's default resources. Locally they only inform the scheduler.
JOB_RESOURCES = ResourceTable.load(Path(workflow.basedir) / "config" / "job_resources.csv")


def benchmark_job(benchmark):
    """The job name of a rule's benchmark file in config/job_resources.csv: its path below
    results/ without ``benchmarks/`` and ``.tsv`` (wildcards unexpanded: ``{paper}/derive``,
    ``some_paper/simulate_{scenario}``, ``reproduction``)."""
    rel = str(benchmark).removeprefix(f"{RESULTS}/").removesuffix(".tsv")
    # a rule's own benchmark path carries its wildcard constraints: {paper,some_paper|...}
    return re.sub(r"\{(\w+),[^{}]*\}", r"{\1}", rel.replace("benchmarks/", ""))


def job_threads(benchmark):
    """The threads of the rule whose benchmark file is ``benchmark`` (1 if unmeasured)."""
    job = benchmark_job(benchmark)

    def threads(wildcards):
        request = JOB_RESOURCES.request(job, dict(wildcards.items()))
        return request.threads if request else 1

    return threads


def job_resources(benchmark):
    """``mem_mb`` and ``runtime`` (minutes) for a rule's ``resources:`` (see job_threads);
    none when no job of the rule was measured (a new paper's step), so that the profile's
    default resources apply. A new wildcard value of a measured rule gets the largest of its
    measured requests."""
    job = benchmark_job(benchmark)
    if not JOB_RESOURCES.matching(job):
        return {}

    def pick(name):
        def value(wildcards):
            return getattr(JOB_RESOURCES.request(job, dict(wildcards.items())), name)

        return value

    return {"mem_mb": pick("mem_mb"), "runtime": pick("runtime")}


def job_priority(benchmark):
    """A rule's ``priority:``: the job's bottom level in CPU seconds, its measured cost plus the
    costliest chain of jobs waiting on it (pipeline.job_priority), so that on few cores the
    long chains start first. Read off the run's DAG when Snakemake asks (after building it)."""
    job = benchmark_job(benchmark)

    def priority(wildcards):
        name = job.format(**dict(wildcards.items()))
        levels = _bottom_levels()
        return levels[name] if name in levels else _job_cost(job, dict(wildcards.items()))

    return priority


def _job_cost(template, wildcards):
    request = JOB_RESOURCES.request(template, wildcards)
    return request.cpu_s if request else UNMEASURED_COST_S


_LEVELS = {}


def _bottom_levels():
    """The bottom level of every job still to run, by its benchmark name (computed once per
    DAG); empty if this Snakemake's DAG does not expose its jobs and their dependents."""
    dag = workflow.dag
    try:
        jobs = list(dag.needrun_jobs())
        key = (id(dag), len(jobs))
        if key not in _LEVELS:
            named = [j for j in jobs if j.benchmark]
            names = {j: benchmark_job(j.benchmark) for j in named}
            templates = {j: benchmark_job(j.rule.benchmark) for j in named}
            levels = dag_bottom_levels(
                jobs,
                lambda j: list(dag.depending.get(j, {})),
                lambda j: _job_cost(templates[j], j.wildcards_dict) if j in names else 0.0,
            )
            _LEVELS.clear()
            _LEVELS[key] = {names[j]: level for j, level in levels.items() if j in names}
        return _LEVELS[key]
    except AttributeError:
        return {}


def local_rules(rules):
    """The names of the rules that run on the login node under a cluster executor: the targets
    (no benchmark) and the rules whose every measured job needed less than LOCAL_MAX_S CPU seconds
    (pipeline.job_resources)."""
    return [
        r.name
        for r in rules
        if not r.benchmark or JOB_RESOURCES.is_local(benchmark_job(r.benchmark))
    ]


def code(*modules, script=None):
    """The repository files ``modules`` (and ``script``'s imports) import, recursively: inputs
    of a rule, so an edit to any of them reruns it."""
    names = list(modules) + (script_imports(f"{SCRIPTS}/{script}") if script else [])
    return module_closure(names) + ([f"{SCRIPTS}/{script}"] if script else [])


def step_modules(paper, step):
    """The modules a step runs: its entry's, the paper's plug-in (loaded by name through the
    registry) and, for a page step, the paper's report sections (``Paper.report``) and its
    discussion (``Paper.discussion``)."""
    modules = [step.module, f"pipeline.{paper.slug}.paper"]
    if step.entry.endswith(":page_step"):
        modules += paper.report_modules
    return modules


def kept(path):
    """``path`` as an output that a failed job never deletes (Snakemake's ``update`` flag: the
    previous version is backed up before the job and restored if the job fails). Every script
    replaces each of its outputs or fails (``pipeline.script_log.logged`` checks it), so an
    old file is never taken for a new one."""
    return update(path)


def tagged(path, paper, subcategory, caption, **labels):
    """``path`` marked for the Snakemake report: category = the paper's slug, one caption per
    kind of output (``reports/snakemake/<caption>.rst``), ``labels`` shown beside it."""
    return report(
        kept(path),
        caption=f"{CAPTIONS}/{caption}.rst",
        category=paper,
        subcategory=subcategory,
        labels=labels or None,
    )


def tagged_figure(path, paper):
    """A figure for the Snakemake report, labelled with the paper's figure number."""
    name = Path(path).name
    return tagged(path, paper.slug, "Figures", "figure", figure=paper.figure(name).label, file=name)


def step_outputs(paper, step):
    """A step's named outputs; PNG figures and the outputs its ``report`` names are tagged."""
    out = {}
    for name, value in step.outputs(CONTEXTS[paper.slug]).items():
        if name in step.report:
            subcategory, caption = step.report[name]
            labels = {"scenario": "{scenario}"} if step.per_scenario else {}
            out[name] = tagged(value, paper.slug, subcategory, caption, **labels)
        elif isinstance(value, list):
            out[name] = [
                tagged_figure(v, paper) if _is_figure(v, paper) else kept(v) for v in value
            ]
        else:
            out[name] = tagged_figure(value, paper) if _is_figure(value, paper) else kept(value)
    return out


def _is_figure(path, paper):
    return path.endswith(".png") and Path(path).name in paper.figure_files


def step_log(paper, step, kind):
    """results/<slug>/logs/<step>[_<scenario>][_<wildcard>...].log (kind "logs") or
    benchmarks/....tsv."""
    names = (("scenario",) if step.per_scenario else ()) + step.wildcards
    suffix = "".join(f"_{{{name}}}" for name in names)
    ext = "log" if kind == "logs" else "tsv"
    return f"{CONTEXTS[paper.slug].results}/{kind}/{step.name}{suffix}.{ext}"


def paper_targets(slug):
    """What the target `all` asks of one paper: its page and its executed notebook."""
    return [CONTEXTS[slug].page, CONTEXTS[slug].notebook_html]


def derive_code(step):
    """Input function: the code a derive step of one paper runs (its import graph). The derive
    rule runs the paper's audit checks and generator (the shared frames generator has its own
    rule, derive_frames); the audit and the codegen check read the artefacts and run only the
    comparison code their scripts import."""
    modules = {
        "derive": lambda paper: code(
            paper.audit_module, paper.generator_module, script="derive.py"
        ),
        "audit": lambda paper: code(script="equation_audit.py"),
        "codegen": lambda paper: code(script="codegen_check.py"),
    }[step]
    return lambda wildcards: modules(PAPERS[wildcards.paper])


def notebook_code(wildcards):
    """The modules the paper's notebook imports (recursively) and the results it reads."""
    paper = PAPERS[wildcards.paper]
    return module_closure(notebook_imports(paper.notebook)) + list(
        paper.notebook_inputs(CONTEXTS[paper.slug])
    )


def reproduction_inputs():
    """Every file the combined report reads, per paper. Not the papers' pages nor their
    notebook pages, which it only links to (the target `all` asks for them): it runs beside them."""
    named = {k: [] for k in ("audits", "math", "verdicts", "published", "scenarios")}
    named.update({k: [] for k in ("provenance", "figures", "svg")})
    # each paper's report sections (Paper.report), loaded by name: its import graph
    named["page_inputs"] = []
    named["paper_code"] = module_closure([m for p in PAPERS.values() for m in p.report_modules])
    for slug, paper in PAPERS.items():
        ctx = CONTEXTS[slug]
        named["audits"].append(f"{ctx.results}/equation_audit.csv")
        named["math"].append(f"{ctx.results}/equation_math.json")
        named["verdicts"].append(f"{ctx.results}/verdicts.csv")
        named["published"].append(ctx.published)
        named["scenarios"] += [ctx.scenario_file(s) for s in ctx.scenarios]
        named["provenance"] += ctx.per_scenario("provenance.json")
        named["figures"] += [ctx.figure(f.file) for f in paper.figures]
        named["svg"] += [ctx.figure(f.svg) for f in paper.figures]
        # the paper's sections read what its page step reads
        for step in paper.steps:
            if step.entry.endswith(":page_step"):
                for value in step.inputs(ctx).values():
                    named["page_inputs"] += value if isinstance(value, list) else [value]
    return named
