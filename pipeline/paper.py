"""The paper plug-in: everything one paper contributes to the shared workflow and report.

A paper is a package ``pipeline/<slug>/`` whose module ``paper.py`` defines ``PAPER``, a
:class:`Paper`. The shared layer (the Snakefile and ``pipeline/rules/``, the verdict engine,
the report) loads the papers listed in ``config/config.yaml`` through
:mod:`pipeline.registry` and iterates over them; it never names a paper.

Paths in a paper's steps are relative to the repository root and are built from a
:class:`Context`, so the same plug-in serves any ``results_dir`` and any set of scenarios.

Conventions (for every paper):

- ``results/<slug>/`` holds the paper's results (``equation_audit.csv``, ``verdicts.csv``,
  ``figures/``, one folder per scenario); ``config/scenarios/<slug>/<name>.yaml`` its
  scenarios; ``config/published/<slug>.yaml`` its published values; ``derivations/<slug>/``
  its SymPy derivations (``audit.py`` with ``checks()``, ``generate.py`` with ``HEADER``,
  ``functions()`` and ``source()``), derived once per reproduction into
  ``results/<slug>/derivation.pkl`` (``derivations.artefact``);
  ``pipeline/generated/<slug>.py`` the generated code; ``notebooks/<slug>.ipynb`` its notebook.
- A :class:`Step` is one Snakemake rule, ``<slug>_<step name>``; its ``entry`` is called as
  ``entry(inputs, outputs, params, log)`` with the rule's named inputs and outputs (strings or
  lists of strings), its params and a ``log(message)`` function.

>>> fig = FigureSpec("fig5_stationary.png", 5, "Fig. 5: stationary vehicle")
>>> fig.svg, fig.in_paper
('fig5_stationary.svg', True)
>>> FigureSpec("fig9_latitude.png", None, "latitude sweep").label
'not in the paper'
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

__all__ = [
    "PUBLISHED_SCHEMA",
    "SLUG_PATTERN",
    "Context",
    "FigureSpec",
    "Paper",
    "Step",
    "Paths",
    "named_function",
    "StepEntry",
]

#: A paper's slug: a Python identifier in lower case (it names a package and a rule prefix).
SLUG_PATTERN = re.compile(r"^[a-z][a-z0-9_]*$")

#: the one schema of every paper's published values (pipeline/verdicts)
PUBLISHED_SCHEMA = "config/schemas/published.schema.json"
#: Named paths of a rule's inputs or outputs: a path (str) or a list of paths.
Paths = Mapping[str, "str | list[str]"]
#: ``entry(inputs, outputs, params, log)``: what a step runs.
StepEntry = Callable[[Mapping[str, Any], Mapping[str, Any], Mapping[str, Any], Callable], None]


def named_function(spec: str, what: str) -> Callable[..., Any]:
    """The function ``spec`` (``"package.module:function"``) names; ``what`` says whose spec it
    is in the ``ValueError`` raised for a malformed spec or a missing function.

    >>> named_function("os.path:join", "an example")("a", "b")
    'a/b'
    >>> named_function("os.path", "paper x: report")
    Traceback (most recent call last):
    ...
    ValueError: paper x: report 'os.path': must be 'module:function'
    """
    module, sep, name = spec.partition(":")
    if not sep or not module or not name:
        raise ValueError(f"{what} {spec!r}: must be 'module:function'")
    fn = getattr(importlib.import_module(module), name, None)
    if not callable(fn):
        raise ValueError(f"{what} {spec!r}: {module} has no function {name!r}")
    return fn


@dataclass(frozen=True)
class FigureSpec:
    """One figure a paper writes: ``results/<slug>/figures/<file>`` (PNG) and its SVG twin.

    ``number`` is the paper's own figure number, ``None`` for a figure the paper lacks.
    """

    file: str
    number: int | None
    caption: str

    @property
    def svg(self) -> str:
        """The vector twin's file name (the PDF report typesets it)."""
        return str(Path(self.file).with_suffix(".svg"))

    @property
    def in_paper(self) -> bool:
        return self.number is not None

    @property
    def label(self) -> str:
        """``Fig. N`` for a figure of the paper, else ``not in the paper``."""
        return f"Fig. {self.number}" if self.number is not None else "not in the paper"


@dataclass(frozen=True)
class Context:
    """Where one paper's files are, for the current config (built by the registry)."""

    slug: str
    results_dir: str
    reports_dir: str
    scenarios: tuple[str, ...]
    settings: Mapping[str, Any]

    @property
    def results(self) -> str:
        """``results/<slug>``."""
        return f"{self.results_dir}/{self.slug}"

    @property
    def scenarios_dir(self) -> str:
        return f"config/scenarios/{self.slug}"

    @property
    def published(self) -> str:
        return f"config/published/{self.slug}.yaml"

    @property
    def published_inputs(self) -> dict[str, str]:
        """The published-values file and the one schema that validates it: the inputs of
        any step that reads the published values."""
        return {"published": self.published, "published_schema": PUBLISHED_SCHEMA}

    def run_inputs(self, scenario: str, schema: str) -> dict[str, str]:
        """The inputs of a step that runs a scenario: the scenario file (a path, or the
        ``{scenario}`` pattern), its schema, and the check that the generated code is fresh."""
        return {
            "scenario": scenario,
            "schema": schema,
            "codegen": f"{self.results}/codegen_check.txt",
        }

    def scenario_file(self, name: str) -> str:
        return f"{self.scenarios_dir}/{name}.yaml"

    def per_scenario(self, name: str) -> list[str]:
        """``results/<slug>/<scenario>/<name>`` for every scenario."""
        return [f"{self.results}/{s}/{name}" for s in self.scenarios]

    def figure(self, name: str) -> str:
        return f"{self.results}/figures/{name}"

    @property
    def page(self) -> str:
        return f"{self.reports_dir}/{self.slug}.html"

    @property
    def notebook_html(self) -> str:
        return f"{self.reports_dir}/notebooks/{self.slug}.html"


@dataclass(frozen=True)
class Step:
    """One step of a paper's workflow (one Snakemake rule ``<slug>_<name>``).

    ``inputs`` and ``outputs`` map the rule's input/output names to paths built from the
    :class:`Context` (or an input function of the wildcards, for inputs that depend on a
    scenario's settings); a per-scenario step uses ``{scenario}`` in its paths (one job per
    scenario), and the names in ``wildcards`` besides (one job per value; ``chunk``: digits).
    ``entry`` is ``"module:function"``; the modules it imports (recursively, inside this
    repository) are inputs of the rule too, so an edit reruns the step. ``report`` tags
    outputs for ``snakemake --report``: output name -> (subcategory, caption file stem).
    ``resources``: the rule's ``mem_mb`` and ``runtime`` (values or functions of the
    wildcards) for a step whose cost follows its settings; other steps' come from the measured
    table (config/job_resources.csv).
    """

    name: str
    entry: str
    inputs: Callable[[Context], Paths]
    outputs: Callable[[Context], Paths]
    per_scenario: bool = False
    params: Callable[[Context], Mapping[str, Any]] = field(default=lambda ctx: {})
    report: Mapping[str, tuple[str, str]] = field(default_factory=dict)
    wildcards: tuple[str, ...] = ()
    resources: Callable[[Context], Mapping[str, Any]] | None = None
    #: a per-scenario step: the scenarios it runs (default all; steps writing different files,
    #: e.g. a CSV or a binary form, split them; no scenario: no rule)
    scenarios: Callable[[Context], Sequence[str]] | None = None

    @property
    def module(self) -> str:
        return self.entry.split(":", 1)[0]


#: the page step every paper uses: reports/<slug>.html from the paper's report sections
PAGE_ENTRY = "pipeline.report.page_html:page_step"


def page_step(inputs: Callable[[Context], Paths]) -> Step:
    """A paper's page step (``<slug>_report``): its audit, verdicts and published file, and
    ``inputs(ctx)``, everything else its report sections read."""
    return Step(
        "report",
        PAGE_ENTRY,
        inputs=lambda ctx: {
            **ctx.published_inputs,
            "audit": f"{ctx.results}/equation_audit.csv",
            "math": f"{ctx.results}/equation_math.json",
            "verdicts": f"{ctx.results}/verdicts.csv",
            **inputs(ctx),
        },
        outputs=lambda ctx: {"page": ctx.page},
        params=lambda ctx: {"paper": ctx.slug, "settings": dict(ctx.settings)},
        report={"page": ("Pages", "page")},
    )


@dataclass(frozen=True)
class Paper:
    """What one paper plugs into the shared workflow, verdicts and report."""

    slug: str
    title: str
    citation: str
    #: ``load(path)`` validates one scenario file (raises ``ConfigError`` naming the file)
    load_scenario: Callable[[Path], Any]
    figures: tuple[FigureSpec, ...]
    steps: tuple[Step, ...] = ()
    #: results the notebook reads (beside the derivations it imports)
    notebook_inputs: Callable[[Context], Sequence[str]] = field(default=lambda ctx: ())
    #: ``config/schemas/<name>.schema.json`` validating the paper's section of config.yaml
    #: (``<slug>: {...}``, its ``Context.settings``); None: the paper takes no settings
    settings_schema: str | None = None
    #: ``"module:function"``: the report sections the paper contributes, as
    #: ``function(inputs: pipeline.report.model.ReportInputs) -> PaperReport`` (its page
    #: ``reports/<slug>.html`` and its section of the combined report are rendered from
    #: them); empty: the paper contributes none (the combined report has its shared parts)
    report: str = ""
    #: symbol stems with a fixed rendering in the PDF's mathematics (stem -> Typst math
    #: source, e.g. ``{"xt": "tilde(x)"}``: a measured x)
    math_stems: Mapping[str, str] = field(default_factory=dict)
    #: ``"module:function"``: ``function(path)`` validates the published file with the paper's
    #: selectors and claim tests (raising ``ConfigError``); called when the workflow is parsed,
    #: so a bad published file stops it before any job. Empty: validated by the verdict step only
    load_published: str = ""
    #: ``"module:function"``: the paper's part of the report's discussion (what was easy, what
    #: was hard, what the paper left open), as ``function(inputs: ReportInputs) -> list of
    #: pipeline.report.model blocks``, its numbers read from the results; empty: none
    discussion: str = ""
    #: ``"module:function"``: the paper's set-up work before a workflow (``make warm-kernels``,
    #: :mod:`pipeline.warm_up`), as ``function(argv: list[str]) -> int``, ``argv`` being
    #: ``[]`` or ``["--force"]`` (redo it even if its own stamp says it is done); e.g. compiling
    #: numba kernels into their on-disk cache. An optimisation: its failure is a warning, and
    #: the workflow must give the same bytes without it. Empty: none
    warm_up: str = ""

    def __post_init__(self) -> None:
        if not SLUG_PATTERN.match(self.slug):
            raise ValueError(
                f"paper slug {self.slug!r}: must match {SLUG_PATTERN.pattern} (a package name)"
            )
        names = [s.name for s in self.steps]
        if len(set(names)) != len(names):
            raise ValueError(f"paper {self.slug}: step names repeat: {names}")
        files = [f.file for f in self.figures]
        if len(set(files)) != len(files):
            raise ValueError(f"paper {self.slug}: figure files repeat: {files}")

    @property
    def audit_module(self) -> str:
        return f"derivations.{self.slug}.audit"

    @property
    def generator_module(self) -> str:
        return f"derivations.{self.slug}.generate"

    @property
    def generated(self) -> str:
        return f"pipeline/generated/{self.slug}.py"

    @property
    def notebook(self) -> str:
        return f"notebooks/{self.slug}.ipynb"

    @property
    def paper_figure_numbers(self) -> list[int]:
        return sorted({f.number for f in self.figures if f.number is not None})

    def figure(self, file: str) -> FigureSpec:
        """The figure written as ``file`` (PNG name); KeyError names the known ones."""
        for f in self.figures:
            if f.file == file:
                return f
        raise KeyError(f"paper {self.slug}: no figure {file!r}; figures: {self.figure_files}")

    @property
    def figure_files(self) -> list[str]:
        return [f.file for f in self.figures]

    def check_published(self, path: str | Path) -> Any:
        """Validate the published file with :attr:`load_published` (nothing if empty); the
        parsed file (None if not validated)."""
        if self.load_published:
            return named_function(self.load_published, f"paper {self.slug}: load_published")(path)
        return None

    def report_function(self) -> Callable[[Any], Any]:
        """The function ``report`` names (a function returning no sections if none)."""
        if not self.report:
            from pipeline.report.model import PaperReport

            return lambda inputs: PaperReport(sections=[], parts={"published": None})
        return named_function(self.report, f"paper {self.slug}: report")

    def discussion_function(self) -> Callable[[Any], Any]:
        """The function ``discussion`` names (a function returning no blocks if none)."""
        if not self.discussion:
            return lambda inputs: []
        return named_function(self.discussion, f"paper {self.slug}: discussion")

    def warm_up_function(self) -> Callable[[list[str]], int] | None:
        """The function :attr:`warm_up` names (None if empty)."""
        if not self.warm_up:
            return None
        return named_function(self.warm_up, f"paper {self.slug}: warm_up")

    @property
    def report_modules(self) -> list[str]:
        """The modules the paper's report sections are built by (its report and discussion
        functions'), inputs of every step that renders them."""
        return [f.split(":")[0] for f in (self.report, self.discussion) if f]

    def step(self, name: str) -> Step:
        for s in self.steps:
            if s.name == name:
                return s
        raise KeyError(
            f"paper {self.slug}: no step {name!r}; steps: {[s.name for s in self.steps]}"
        )
