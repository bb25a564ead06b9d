"""The set-up's warm-up (pipeline/warm_up.py): each listed paper's plug-in warm-up is called,
in config order, with --force passed on; a failing, raising or unloadable one is a warning, not
a failed set-up."""

from __future__ import annotations

import dataclasses

import pytest

from pipeline import warm_up
from pipeline.paper import Paper
from pipeline.registry import load_paper


def _paper(slug: str, spec: str) -> Paper:
    return Paper(slug, "t", "c", load_scenario=print, figures=(), warm_up=spec)


CALLS: list[tuple[str, list[str]]] = []


def ok(argv: list[str]) -> int:
    CALLS.append(("ok", argv))
    return 0


def fails(argv: list[str]) -> int:
    CALLS.append(("fails", argv))
    return 3


def raises(argv: list[str]) -> int:
    raise OSError("disk full")


@pytest.fixture
def papers(monkeypatch):
    table = {
        "a": _paper("a", f"{__name__}:ok"),
        "b": _paper("b", f"{__name__}:fails"),
        "c": _paper("c", f"{__name__}:raises"),
        "d": _paper("d", ""),
        "e": _paper("e", f"{__name__}"),  # not module:function
    }

    def load(slug, root=None, source=None):
        return table[slug]

    CALLS.clear()
    monkeypatch.setattr(warm_up, "load_paper", load)
    return table


def test_each_warm_up_runs_and_failures_are_warnings(papers, capsys):
    failed = warm_up.warm_papers(["c", "a", "b", "d", "e", "a"], force=True)
    err = capsys.readouterr().err
    assert failed == ["c", "b", "e"]
    assert CALLS == [("ok", ["--force"]), ("fails", ["--force"]), ("ok", ["--force"])]
    assert "warning: c: the set-up's warm-up failed (OSError: disk full)" in err
    assert "warning: b: the set-up's warm-up failed (exit status 3)" in err
    assert "warning: e: " in err and "must be 'module:function'" in err
    assert "Traceback" in err  # an exception's traceback is shown, for the one who fixes it
    CALLS.clear()
    assert warm_up.warm_papers(["a"]) == [] and CALLS == [("ok", [])]


def test_main_reads_the_papers_of_the_config(papers, tmp_path, capsys):
    config = tmp_path / "c.yaml"
    config.write_text("papers: [d, a]\n")
    assert warm_up.main(["--config", str(config), "--force"]) == 0
    assert CALLS == [("ok", ["--force"])]
    config.write_text("papers: [d, a\n")
    assert warm_up.main(["--config", str(config)]) == 0
    err = capsys.readouterr().err
    assert err.startswith(f"warning: warm-up skipped: {config}: ") and "Traceback" not in err
    config.write_text("papers: 3\n")
    assert warm_up.main(["--config", str(config)]) == 0
    assert "papers = 3: not a list of slugs" in capsys.readouterr().err


def test_an_unknown_slug_is_a_warning(capsys):
    assert warm_up.warm_papers(["no_such_paper"]) == ["no_such_paper"]
    assert "warning: no_such_paper: " in capsys.readouterr().err


def test_the_plug_ins_warm_ups_resolve():
    """Every paper that names a warm-up names a function that exists (not called here: the
    altimeter_attitude one is tested in its own folder)."""
    from tests.shared.test_plugin import SLUGS

    named = [load_paper(s) for s in SLUGS if load_paper(s).warm_up]
    assert named
    for paper in named:
        assert callable(paper.warm_up_function())
    assert dataclasses.replace(named[0], warm_up="").warm_up_function() is None


def test_bytecode_is_compiled_once_and_a_bad_module_is_a_warning(tmp_path, capsys):
    for package in warm_up.PACKAGES:
        (tmp_path / package).mkdir()
        (tmp_path / package / "good.py").write_text("X = 1\n")
    assert warm_up.compile_bytecode(tmp_path)
    cached = sorted(tmp_path.rglob("__pycache__/good.*.pyc"))
    assert len(cached) == len(warm_up.PACKAGES)
    stamps = [p.stat().st_mtime_ns for p in cached]
    assert warm_up.compile_bytecode(tmp_path)  # current: not rewritten
    assert [p.stat().st_mtime_ns for p in cached] == stamps
    (tmp_path / warm_up.PACKAGES[0] / "bad.py").write_text("def (:\n")
    assert not warm_up.compile_bytecode(tmp_path)
    assert "warning: bytecode: a module did not compile" in capsys.readouterr().err
