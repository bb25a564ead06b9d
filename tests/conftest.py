"""Session fixtures shared by the test modules."""

from __future__ import annotations

import importlib
import os
from collections.abc import Callable
from functools import cache
from pathlib import Path

import pytest

from tests.workflow_harness import ROOT, have_results, once_across_workers, reduced_run


@pytest.fixture(scope="session")
def workflow_run(tmp_path_factory) -> Path:
    """The root of a reduced copy of the repository in which the whole default workflow has run
    (once per test session, shared by every pytest-xdist worker: the first worker to ask runs
    it, the others wait for it). Tests read it and never change it: a test that needs to
    change it copies it first."""
    if not os.environ.get("PYTEST_XDIST_WORKER"):
        return reduced_run(tmp_path_factory.mktemp("repo"))
    # the workers' base temporary directories share this parent
    shared = tmp_path_factory.getbasetemp().parent
    return once_across_workers(shared / "workflow-run", reduced_run)


@pytest.fixture(scope="session")
def results_repo(request) -> Path:
    """A repository root with every paper's results and pages: this checkout if the workflow has
    run here, else the reduced run of ``workflow_run`` (a fresh clone, as in CI)."""
    if have_results(ROOT):
        return ROOT
    return request.getfixturevalue("workflow_run")


@pytest.fixture(scope="session")
def generated_source() -> Callable[[str], str]:
    """``generated_source(module)``: ``module.source()`` of a generate module (for example
    ``derivations.<slug>.generate``), derived once per session (seconds of SymPy each) and shared
    by the tests that compare with it."""

    @cache
    def source(module: str) -> str:
        return importlib.import_module(module).source()

    return source


#: tests/synthetic_paper/ is a paper plug-in laid out as in the repository (copied into a copy of
#: the repository by tests/shared/test_synthetic_paper.py), not test modules.
collect_ignore = ["synthetic_paper"]
