"""The paper plug-in: the registry, shared code that names no paper, the rules generated from
each paper's steps, code inputs from the import graph, and a config listing one paper."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
import yaml

from pipeline.code_inputs import module_closure
from pipeline.config import ConfigError
from pipeline.paper import Paper, Step
from pipeline.registry import context, load_paper, load_papers
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, copy_repo, snakemake

#: every paper plug-in of this checkout, found on disk (not a list typed here)
SLUGS = sorted(p.parent.name for p in (ROOT / "pipeline").glob("*/paper.py"))
CONFIG = yaml.safe_load((ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))

#: Shared code: what must never name a paper.
SHARED = [
    "Snakefile",
    "pipeline/rules",
    "pipeline/scripts",
    "pipeline/envs",
    "config/config.schema.json",
    "config/schemas/config.schema.json",
    "derivations/checks.py",
    "derivations/residual_tidy.py",
    "derivations/futrig_memo.py",
    "derivations/factors_dict.py",
    "derivations/memo.py",
    "derivations/codegen.py",
    "derivations/frames.py",
    "pipeline/verdicts",
    "pipeline/report",
    "config/schemas/published.schema.json",
    *sorted(str(p.relative_to(ROOT)) for p in (ROOT / "pipeline").glob("*.py")),
]


def test_plugins_found():
    assert len(SLUGS) >= 3 and set(CONFIG["papers"]) <= set(SLUGS)


@pytest.mark.parametrize("slug", SLUGS)
def test_each_plugin_is_complete(slug):
    """Every paper exports a Paper with steps whose entry points resolve, its figures carry
    the paper's numbers, and its files are where the conventions put them."""
    paper = load_paper(slug)
    assert isinstance(paper, Paper) and paper.slug == slug and paper.title and paper.citation
    for path in (paper.generated, paper.notebook, f"config/published/{slug}.yaml"):
        assert (ROOT / path).is_file(), path
    for module in (paper.audit_module, paper.generator_module):
        assert module_closure([module])
    ctx = context(paper, CONFIG)
    names = [s.name for s in paper.steps]
    assert {"simulate", "verdicts", "report"} <= set(names), names
    for step in paper.steps:
        from pipeline.steps import resolve

        resolve(step.entry)  # importable, callable
        outs = step.outputs(ctx)
        flat = [p for v in outs.values() for p in (v if isinstance(v, list) else [v])]
        assert all(p.startswith((ctx.results, ctx.reports_dir)) for p in flat), flat
        assert ("{scenario}" in " ".join(flat)) == step.per_scenario, step.name


def test_registry_refuses_unknown_and_malformed_papers():
    with pytest.raises(
        ConfigError, match=r"config/config.yaml: papers: 'no_such_paper': no plug-in"
    ):
        load_paper("no_such_paper")
    with pytest.raises(ConfigError, match=r"not a paper slug"):
        load_paper("../escape")
    with pytest.raises(ConfigError, match=r"not a paper slug"):
        load_papers(["Upper"])


def test_paper_settings_are_validated_against_the_plugins_schema():
    with_settings = [s for s in CONFIG["papers"] if load_paper(s).settings_schema]
    assert with_settings
    slug = with_settings[0]
    paper = load_paper(slug)
    bad = {**CONFIG, slug: {**CONFIG[slug], "no_such_setting": 1}}
    with pytest.raises(ConfigError, match=rf"config/config.yaml: {slug}: .*no_such_setting"):
        context(paper, bad)
    missing = {k: v for k, v in CONFIG.items() if k != slug}
    with pytest.raises(ConfigError, match=rf"{slug}: missing"):
        context(paper, missing)
    without = [s for s in SLUGS if load_paper(s).settings_schema is None]
    if without:
        with pytest.raises(ConfigError, match="takes no settings"):
            context(load_paper(without[0]), {**CONFIG, without[0]: {"x": 1}})


def test_paper_refuses_a_bad_slug_and_repeated_steps():
    step = Step("s", "m:f", inputs=lambda c: {}, outputs=lambda c: {})
    with pytest.raises(ValueError, match="must match"):
        Paper("Bad-Slug", "t", "c", load_scenario=print, figures=())
    with pytest.raises(ValueError, match="step names repeat"):
        Paper("ok", "t", "c", load_scenario=print, figures=(), steps=(step, step))


def _files(entry: str) -> list[Path]:
    path = ROOT / entry
    return sorted(path.rglob("*")) if path.is_dir() else [path] if path.exists() else []


def test_shared_code_names_no_paper():
    """No slug (nor a paper-specific module path) in the shared layer. Found on disk, so a new
    paper's slug is checked too."""
    pattern = re.compile(r"\b(" + "|".join(map(re.escape, SLUGS)) + r")\b")
    hits = []
    for entry in SHARED:
        for path in _files(entry):
            if (
                path.is_file()
                and path.suffix in (".py", ".smk", ".json", ".yaml", "")
                and ("__pycache__" not in path.parts)
            ):
                for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                    if pattern.search(line):
                        hits.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not hits, "\n".join(hits)


def test_the_check_finds_a_slug(tmp_path):
    """The grep above can fail: a shared line with a slug is found by the same pattern."""
    pattern = re.compile(r"\b(" + "|".join(map(re.escape, SLUGS)) + r")\b")
    assert pattern.search(f'include: "pipeline/rules/{SLUGS[0]}.smk"')
    assert not pattern.search("PAPERS = load_papers(config['papers'])")


@pytest.mark.parametrize("slug", SLUGS)
def test_plugins_import_no_other_paper(slug):
    """In the import graph a paper's package imports shared modules only, never another paper."""
    paper = load_paper(slug)
    modules = [s.module for s in paper.steps] + [f"pipeline.{slug}.paper"]
    files = module_closure(modules)
    others = [o for o in SLUGS if o != slug]
    crossing = [f for f in files for o in others if f"/{o}/" in f or f.endswith(f"/{o}.py")]
    assert not crossing, crossing


def test_step_code_inputs_follow_function_level_imports():
    """Steps import their work inside functions; the closure follows those imports, down to
    the generated module, so an edit to any of them reruns the step."""
    for slug in SLUGS:
        paper = load_paper(slug)
        files = module_closure([paper.step("simulate").module])
        assert f"pipeline/generated/{slug}.py" in files, (slug, files)
        assert f"pipeline/{slug}/steps.py" in files


def _job_counts(output: str) -> dict[str, int]:
    start = output.index("Job stats:")
    counts = {}
    for line in output[start:].splitlines()[3:]:
        m = re.match(r"^(\w+)\s+(\d+)$", line.strip())
        if not m:
            break
        counts[m.group(1)] = int(m.group(2))
    counts.pop("total", None)
    return counts


@pytest.mark.workflow
def test_dry_run_plans_every_step_of_every_paper():
    """``snakemake -n --forceall`` plans, per paper, one job per step (per scenario for a
    per-scenario step; a step with more wildcards, such as altimeter_attitude's Monte Carlo chunks,
    as many as other steps ask for) and the shared derive, audit, codegen check and notebook once
    per paper."""
    r = snakemake("-n", "--cores", "1", "--forceall", "--nolock", cwd=ROOT, timeout=HANG_GUARD_S)
    assert r.returncode == 0, r.stderr[-3000:]
    counts = _job_counts(r.stdout + r.stderr)
    papers = load_papers(CONFIG["papers"])
    for shared in ("derive", "audit", "codegen_check", "notebook"):
        assert counts[shared] == len(papers), (shared, counts)
    for slug, paper in papers.items():
        ctx = context(paper, CONFIG)
        for step in paper.steps:
            if step.wildcards:  # jobs on demand (chunks of a scenario that sets chunk_runs)
                continue
            # a per-scenario step runs its scenarios (Step.scenarios: all by default)
            mine = step.scenarios(ctx) if step.scenarios else ctx.scenarios
            want = len(mine) if step.per_scenario else 1
            assert counts.get(f"{slug}_{step.name}", 0) == want, (slug, step.name, counts)
    # one job writes both formats of the combined report (the document is built once)
    assert counts["reproduction"] == 1
    out = r.stdout + r.stderr
    job = out[out.index("rule reproduction:") :].split("\n\n", 1)[0]
    assert re.search(r"output: reports/reproduction\.html\b.*, reports/reproduction\.pdf\b", job)


@pytest.mark.workflow
def test_one_paper_in_config_plans_only_that_paper(tmp_path):
    """``papers: [<one>]`` schedules that paper's jobs and a combined report of one paper."""
    copy_repo(tmp_path)
    slug = CONFIG["papers"][0]
    cfg = {k: v for k, v in CONFIG.items() if k not in CONFIG["papers"] or k == slug}
    cfg["papers"] = [slug]
    (tmp_path / "config" / "config.yaml").write_text(yaml.safe_dump(cfg), encoding="utf-8")
    r = snakemake("-n", "--cores", "1", "--forceall", cwd=tmp_path, timeout=HANG_GUARD_S)
    out = r.stdout + r.stderr
    assert r.returncode == 0, out[-3000:]
    counts = _job_counts(out)
    others = [o for o in SLUGS if o != slug]
    assert not [rule for rule in counts if any(rule.startswith(o) for o in others)], counts
    assert set(re.findall(r"paper=(\w+)", out)) == {slug}
    assert counts["derive"] == counts["audit"] == counts["codegen_check"] == counts["notebook"] == 1
    assert counts["reproduction"] == 1


def _planned(repo: Path) -> dict[str, int]:
    r = snakemake(
        "-n", "--cores", "1", "--rerun-triggers", "mtime", "params", "input", "code", cwd=repo
    )
    out = r.stdout + r.stderr
    assert r.returncode == 0, out[-3000:]
    return {} if "Nothing to be done" in out else _job_counts(out)


@pytest.mark.slow
@pytest.mark.workflow
def test_an_edit_reruns_exactly_the_dependent_jobs(workflow_run, tmp_path):
    """After a complete run nothing is planned; changing the content of a module that only the
    north_finding simulation imports plans exactly that simulation (every scenario) and what
    reads its results; changing a readings CSV plans only the scenario that reads it and its
    readers. (A bare touch with unchanged content is not enough for Snakemake.)"""
    repo = tmp_path / "repo"
    shutil.copytree(workflow_run, repo, symlinks=True)
    assert _planned(repo) == {}
    slug = "north_finding"  # the paper whose estimators and readings file are edited
    if slug not in yaml.safe_load((repo / "config" / "config.yaml").read_text())["papers"]:
        pytest.skip(f"{slug} not in config")
    n_scenarios = len(list((repo / "config" / "scenarios" / slug).glob("*.yaml")))
    readers = {f"{slug}_verdicts", f"{slug}_figures", f"{slug}_report", "reproduction", "all"}
    if slug == "north_finding":  # its averaging-count inference runs the estimators too
        readers.add(f"{slug}_infer_n")

    module = repo / "pipeline" / slug / "estimators.py"
    original = module.read_text(encoding="utf-8")
    module.write_text(original + "\n# an edit\n", encoding="utf-8")
    planned = _planned(repo)
    module.write_text(original, encoding="utf-8")
    assert planned.pop(f"{slug}_simulate") == n_scenarios
    # the paper's notebook imports the estimators too (its code cells are parsed for imports)
    assert planned.pop("notebook") == 1
    assert set(planned) == readers, planned

    data = repo / "config" / "scenarios" / slug / "data" / "example_readings.csv"
    text = data.read_text(encoding="utf-8")
    data.write_text(text.replace("\n", "\r\n", 1), encoding="utf-8")
    planned = _planned(repo)
    data.write_text(text, encoding="utf-8")
    assert planned.pop(f"{slug}_simulate") == 1  # only the scenario that reads the file
    assert set(planned) == {f"{slug}_report", "reproduction", "all"}
