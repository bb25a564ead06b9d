"""The generate command detects a stale pipeline/generated/north_finding.py (``--check``) and writes
a fresh one (``--out``). That the committed module is fresh is checked for every paper by
tests/shared/test_generated_fresh.py."""

from __future__ import annotations

import pytest

from derivations.north_finding import generate
from pipeline.north_finding.scenario import ROOT

GENERATED = ROOT / "pipeline" / "generated" / "north_finding.py"


@pytest.fixture(scope="module")
def fresh_source(generated_source) -> str:
    """The regenerated module text, derived once per session (~6 s) and shared by the main()
    calls below and tests/shared/test_generated_fresh.py."""
    return generated_source(generate.__name__)


@pytest.fixture
def cached_main(monkeypatch, fresh_source):
    monkeypatch.setattr(generate, "source", lambda: fresh_source)
    return generate.main


@pytest.mark.parametrize(
    "edit",
    [
        lambda text: text.replace(
            "out0 = (1/2)*(ax_0 - ax_180)/g", "out0 = (1/2)*(ax_0 + ax_180)/g", 1
        ),
        lambda text: text + "\n# a trailing comment\n",
    ],
    ids=["formula_changed", "comment_added"],
)
def test_modified_copy_is_detected_as_stale(tmp_path, capsys, edit, cached_main):
    text = GENERATED.read_text(encoding="utf-8")
    modified = edit(text)
    assert modified != text
    stale = tmp_path / "north_finding.py"
    stale.write_text(modified, encoding="utf-8")
    assert cached_main(["--check", "--out", str(stale)]) == 1
    assert "stale" in capsys.readouterr().err
    assert stale.read_text(encoding="utf-8") == modified  # --check never rewrites


def test_unmodified_copy_passes_and_missing_file_is_stale(tmp_path, cached_main, fresh_source):
    copy = tmp_path / "copy.py"
    copy.write_text(GENERATED.read_text(encoding="utf-8"), encoding="utf-8")
    assert cached_main(["--check", "--out", str(copy)]) == 0
    out = tmp_path / "sub" / "north_finding.py"
    assert cached_main(["--check", "--out", str(out)]) == 1
    assert cached_main(["--out", str(out)]) == 0
    assert out.read_text(encoding="utf-8") == fresh_source
    assert cached_main(["--check", "--out", str(out)]) == 0
