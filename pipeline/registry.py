"""The paper registry: the :class:`~pipeline.paper.Paper` plug-ins the config lists.

``papers: [a, b]`` in ``config/config.yaml`` loads ``pipeline/a/paper.py`` and
``pipeline/b/paper.py`` (their ``PAPER``), in that order. Nothing else in the shared layer
knows which papers exist.

>>> load_paper("no such paper")
Traceback (most recent call last):
...
pipeline.config.ConfigError: config/config.yaml: papers: 'no such paper': not a paper slug (must match ^[a-z][a-z0-9_]*$)
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from pipeline.config import (
    ConfigError,
    inside_repository,
    load_schema,
    load_yaml,
    quoted,
    validate,
)
from pipeline.paper import SLUG_PATTERN, Context, Paper
from pipeline.scenarios import scenario_names

__all__ = [
    "ROOT",
    "check_config_file",
    "check_workflow",
    "context",
    "load_paper",
    "load_papers",
    "validate_published",
    "validate_scenarios",
    "validate_workflow_config",
]

ROOT = Path(__file__).resolve().parents[1]


def check_config_file(path: str | Path) -> dict[str, Any]:
    """A workflow config file read strictly (see :func:`pipeline.config.load_yaml`: binary
    bytes, tags, duplicate keys, NaN, alias bombs) and checked to be a mapping: the Snakefile
    calls it before its ``configfile:`` directive, whose reader would otherwise fail first with
    Snakemake's stack frames."""
    data = load_yaml(path)
    if not isinstance(data, dict):
        shown = "empty" if data is None else f"a {type(data).__name__}"
        raise ConfigError(
            f"{path}: (top level) = {shown}: allowed: a mapping with keys papers, results_dir, "
            "reports_dir and the papers' settings"
        )
    return data


def validate_workflow_config(
    config: Mapping[str, Any], configfiles: Sequence[str | Path], root: Path = ROOT
) -> None:
    """The workflow config, checked before anything else: every config file given to Snakemake
    re-read strictly (Snakemake's own reader keeps the last of duplicate keys and accepts
    ``.nan``), the merged config validated against ``config/schemas/config.schema.json``, and
    ``results_dir`` and ``reports_dir`` kept inside the repository."""
    for path in configfiles:
        load_yaml(path)
    source = ", ".join(str(p) for p in configfiles) or "the workflow config"
    papers = config.get("papers")
    if not isinstance(papers, list):  # the schema names the type wanted
        validate(config, load_schema("config"), source)
    listed = [p for p in papers if isinstance(p, str)] if isinstance(papers, list) else []
    # the settings of a paper not listed may stay in the file (papers: [x] runs x only)
    plugins = sorted(p.parent.name for p in (root / "pipeline").glob("*/paper.py"))
    known = ["papers", "results_dir", "reports_dir", *listed, *plugins]
    unknown = sorted(str(k) for k in config if k not in known)
    if unknown:
        raise ConfigError(
            f"{source}: {unknown[0]}: unknown key; allowed keys: papers, results_dir, reports_dir "
            f"and the settings of a paper plug-in ({plugins})"
        )
    validate(config, load_schema("config"), source)
    for field in ("results_dir", "reports_dir"):
        inside_repository(str(config[field]), field, source, root)


def load_paper(slug: str, root: Path = ROOT, source: str = "config/config.yaml") -> Paper:
    """The ``PAPER`` of ``pipeline/<slug>/paper.py``; ConfigError naming what is wrong."""
    if not isinstance(slug, str) or not SLUG_PATTERN.match(slug):
        raise ConfigError(
            f"{source}: papers: {slug!r}: not a paper slug (must match {SLUG_PATTERN.pattern})"
        )
    if not (root / "pipeline" / slug / "paper.py").is_file():
        known = sorted(p.parent.name for p in (root / "pipeline").glob("*/paper.py"))
        raise ConfigError(
            f"{source}: papers: {slug!r}: no plug-in pipeline/{slug}/paper.py; papers: {known}"
        )
    module = importlib.import_module(f"pipeline.{slug}.paper")
    paper = getattr(module, "PAPER", None)
    if not isinstance(paper, Paper):
        raise ConfigError(f"pipeline/{slug}/paper.py: PAPER must be a pipeline.paper.Paper")
    if paper.slug != slug:
        raise ConfigError(f"pipeline/{slug}/paper.py: PAPER.slug is {paper.slug!r}, not {slug!r}")
    return paper


def load_papers(
    slugs: Sequence[str], root: Path = ROOT, source: str = "config/config.yaml"
) -> dict[str, Paper]:
    """Every listed paper, in config order (``source``: the config files, for errors)."""
    return {slug: load_paper(slug, root, source) for slug in slugs}


def context(
    paper: Paper, config: Mapping[str, Any], root: Path = ROOT, source: str = "config/config.yaml"
) -> Context:
    """Where ``paper``'s files are under ``config`` (scenarios found on disk, sorted); its
    settings (``config[slug]``) validated against the schema the plug-in names."""
    scenarios = tuple(scenario_names(root / "config" / "scenarios" / paper.slug))
    settings = config.get(paper.slug)
    if paper.settings_schema is not None:
        if settings is None:
            raise ConfigError(f"{source}: {paper.slug}: missing (the paper's settings)")
        validate(settings, load_schema(paper.settings_schema), f"{source}: {paper.slug}")
        chosen = settings.get("published_scenario")
        if chosen is not None and chosen not in scenarios:
            raise ConfigError(
                f"{source}: {paper.slug}.published_scenario = {chosen!r}: not a scenario of "
                f"config/scenarios/{paper.slug}/; allowed: one of {list(scenarios)}"
            )
    elif settings is not None:
        raise ConfigError(
            f"{source}: {paper.slug} = {quoted(settings)}: this paper takes no settings; "
            f"allowed: no {paper.slug} key"
        )
    return Context(
        slug=paper.slug,
        results_dir=str(config.get("results_dir", "results")),
        reports_dir=str(config.get("reports_dir", "reports")),
        scenarios=scenarios,
        settings=dict(settings or {}),
    )


def validate_published(paper: Paper, ctx: Context, root: Path = ROOT) -> None:
    """The paper's published file validated when the workflow is parsed (its ConfigError names
    the file, the field, the value and what is allowed), before any job."""
    path = root / ctx.published
    data = paper.check_published(path)
    if isinstance(data, dict) and data.get("paper") != paper.slug:
        raise ConfigError(
            f"{path}: field 'paper' = {data.get('paper')!r}: allowed: {paper.slug!r} (the paper "
            "whose published values the file holds)"
        )


def validate_scenarios(paper: Paper, names: Sequence[str], directory: str | Path) -> None:
    """Load (and so validate) the scenarios ``<directory>/<name>.yaml`` of ``paper``; the first
    bad file raises its ConfigError (naming the file), before any job runs."""
    for name in names:
        paper.load_scenario(Path(directory) / f"{name}.yaml")


def _shown(path: str | Path, root: Path) -> str:
    """A config file's name as the user knows it: relative to the repository if inside it."""
    p = Path(path)
    try:
        return p.resolve().relative_to(root.resolve()).as_posix()
    except ValueError:
        return str(path)


def check_workflow(
    config: Mapping[str, Any], configfiles: Sequence[str | Path], root: Path = ROOT
) -> tuple[dict[str, Paper], dict[str, Context]]:
    """Everything the workflow checks when it is parsed (pipeline/rules/common.smk calls this),
    in its order: the workflow config, the plug-ins it lists, each paper's settings and scenario
    file names, every scenario file and the published file. Returns the papers and their
    contexts; the first problem raises its ConfigError, before any job."""
    validate_workflow_config(config, configfiles, root)
    source = ", ".join(_shown(p, root) for p in configfiles) or "config/config.yaml"
    papers = load_papers(config["papers"], root, source)
    contexts = {slug: context(paper, config, root, source) for slug, paper in papers.items()}
    for slug, paper in papers.items():
        validate_scenarios(paper, contexts[slug].scenarios, root / contexts[slug].scenarios_dir)
        validate_published(paper, contexts[slug], root)
    return papers, contexts
