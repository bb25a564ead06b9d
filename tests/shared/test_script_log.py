"""pipeline.script_log: a failing Snakemake script says what failed on the console (not "lost
sys.stderr") and keeps its traceback in the log."""

from __future__ import annotations

import sys

import pytest

from pipeline.script_log import logged


def test_a_failure_reaches_the_console_in_one_line_and_the_log_in_full(tmp_path, capsys):
    log = tmp_path / "step.log"
    out, err = sys.stdout, sys.stderr
    with pytest.raises(SystemExit) as exit_, logged(log):
        print("working")
        raise ValueError("config/x.yaml: a = nan: not a finite number")
    assert exit_.value.code == 1
    assert (sys.stdout, sys.stderr) == (out, err)
    console = capsys.readouterr().err
    assert console.strip() == (
        f"error: ValueError: config/x.yaml: a = nan: not a finite number (details: {log})"
    )
    text = log.read_text(encoding="utf-8")
    assert text.startswith("working\n") and "Traceback" in text and "raise ValueError" in text


def test_system_exit_with_a_message_is_the_message(tmp_path, capsys):
    log = tmp_path / "step.log"
    with pytest.raises(SystemExit) as exit_, logged(log):
        raise SystemExit("pipeline/generated/x.py is stale")
    assert exit_.value.code == 1
    assert "error: pipeline/generated/x.py is stale" in capsys.readouterr().err
