"""Every paper's committed generated module is what its derivations generate now.

Parametrised over ``papers:`` in config/config.yaml and resolved through the registry
(``Paper.generated``, ``Paper.generator_module``), so a paper added to the config is checked
with no edit here. ``python -m derivations.<slug>.generate`` (its ``main``) writes the module;
the test also checks, with ``--check``, that this command's default output is the file compared,
so the command the failure names is the one that fixes it.
"""

from __future__ import annotations

import difflib
import importlib

import pytest

from pipeline.registry import ROOT, load_papers
from tests.workflow_harness import SLUGS

PAPERS = load_papers(SLUGS)


def _diff(current: str, fresh: str, path: str, max_lines: int = 30) -> str:
    lines = list(
        difflib.unified_diff(
            current.splitlines(),
            fresh.splitlines(),
            f"{path} (committed)",
            f"{path} (generated now)",
            lineterm="",
        )
    )
    more = [f"... ({len(lines) - max_lines} more diff lines)"] if len(lines) > max_lines else []
    return "\n".join(lines[:max_lines] + more)


@pytest.mark.parametrize("slug", SLUGS)
def test_generated_module_is_fresh(slug, generated_source, monkeypatch, capsys):
    paper = PAPERS[slug]
    path = ROOT / paper.generated
    fresh = generated_source(paper.generator_module)
    command = f"PYTHONPATH=. .venv/bin/python -m {paper.generator_module}"
    if not path.is_file():
        pytest.fail(f"{paper.generated} is missing: run `{command}` and commit it", pytrace=False)
    current = path.read_text(encoding="utf-8")
    if current != fresh:
        pytest.fail(
            f"{paper.generated} is stale (differs from {paper.generator_module}.source()): "
            f"run `{command}` and commit it\n{_diff(current, fresh, paper.generated)}",
            pytrace=False,
        )
    # the command above writes (and --check reads) this very file
    generator = importlib.import_module(paper.generator_module)
    monkeypatch.setattr(generator, "source", lambda: fresh)
    code = generator.main(["--check"])
    assert code == 0, (
        f"`python -m {paper.generator_module} --check` fails although {paper.generated} is fresh: "
        f"its default output is not {paper.generated}? {capsys.readouterr().err}"
    )


def test_frames_module_is_fresh(generated_source, monkeypatch, capsys):
    """pipeline/generated/frames.py (shared by every paper) is what derivations/frames.py
    generates now, and ``python -m derivations.generate_frames --check`` reads that file."""
    module = "derivations.generate_frames"
    generator = importlib.import_module(module)
    path = generator.OUTPUT
    rel = path.relative_to(ROOT)
    fresh = generated_source(module)
    command = f"PYTHONPATH=. .venv/bin/python -m {module}"
    if not path.is_file():
        pytest.fail(f"{rel} is missing: run `{command}` and commit it", pytrace=False)
    current = path.read_text(encoding="utf-8")
    if current != fresh:
        pytest.fail(
            f"{rel} is stale (differs from {module}.source()): run `{command}` and commit it\n"
            f"{_diff(current, fresh, str(rel))}",
            pytrace=False,
        )
    monkeypatch.setattr(generator, "source", lambda: fresh)
    assert generator.main(["--check"]) == 0, capsys.readouterr().err
