"""The one runner of the bad-input corpus: a :class:`Case` declares one bad input as data (the
files it changes, or the command line it runs) and what the refusal must name; the functions
here run it through its real entry point and assert the standard of DEVELOPERS.md:

- refused: exit status non-zero (a ConfigError at workflow parse time);
- one clean message naming the file, the field, the offending value and what is allowed (each a
  piece of text the message must contain), no Python traceback, no Snakemake stack frames;
- before any compute: at workflow parse time, Snakemake never reaches "Building DAG of jobs";
  on the command line, a probe on every compute function of the subcommands (installed in the
  child process before ``pipeline.cli.main`` runs) records that none was called;
- nothing written: every file of the temporary repository (its results/ and reports/ hold
  sentinel outputs) and of the directory around it is unchanged, no ``--out`` file exists.

Entry points:

- :func:`refuse_at_parse` -- ``snakemake -n`` in a temporary copy of the repository;
- :func:`refuse_in_check` -- ``pipeline.registry.check_workflow``, the function
  pipeline/rules/common.smk calls at parse time (a ConfigError there is what common.smk prints
  as one line, exit status 1), on the same copy: cheap enough for every scenario and published
  case, while a few of each also go through Snakemake (``Case.snakemake``);
- :func:`refuse_on_cli` -- ``python -m pipeline.cli ARGS`` (what ``inertial-repro`` runs).
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import os
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, copy_repo, snakemake

#: Compute functions of the subcommands: a call to any of them means the refusal came too late.
PROBES = (
    "pipeline.north_finding.cli:_readings",
    "pipeline.north_finding.readings:simulate",
    "pipeline.north_finding.readings:standard_normals",
    "pipeline.altimeter_attitude.linear_kf:run_linear_kf",
    "pipeline.altimeter_attitude.euler_filters:run_ukf",
    "pipeline.altimeter_attitude.complementary:run_complementary",
)

#: Run in the child: wrap each probe so that a call writes its name to the sentinel file, then
#: run the console command's ``main`` with the remaining arguments.
PROBE_MAIN = """
import importlib, pathlib, sys
sentinel = pathlib.Path(sys.argv[1])
for spec in sys.argv[2].split(","):
    name, _, attr = spec.partition(":")
    module = importlib.import_module(name)
    original = getattr(module, attr)
    def wrapped(*a, _o=original, _s=spec, **k):
        sentinel.write_text(_s)
        return _o(*a, **k)
    setattr(module, attr, wrapped)
from pipeline import cli
raise SystemExit(cli.main(sys.argv[3:]))
"""

#: Text that only a stack trace prints.
TRACE_MARKS = ("Traceback", 'File "', "in <module>", "Error in file", "Exception in")
#: The longest refusal accepted (characters): a message, not a dump.
MAX_MESSAGE = 2000


@dataclass(frozen=True)
class Edit:
    """One change to a file of the temporary repository (``path`` relative to its root):
    ``text`` or ``data`` (bytes) replace the file; ``replace`` = (old, new) replaces the first
    ``old`` (which must be there); ``set`` = {dotted field: value} and ``delete`` = [dotted
    field] change the parsed YAML (written back with yaml.safe_dump); ``append`` adds text."""

    path: str
    text: str | None = None
    data: bytes | None = None
    replace: tuple[str, str] | None = None
    set: dict[str, Any] = field(default_factory=dict)
    delete: tuple[str, ...] = ()
    append: str = ""
    remove: bool = False


@dataclass(frozen=True)
class Case:
    """One bad input and the four things its refusal must name (pieces of the message; ``file``
    None for a command-line option, whose option name is the field)."""

    id: str
    file: str | None
    field: str
    #: None only where the problem is an absence (a missing key or file)
    value: str | None
    allowed: str
    edits: tuple[Edit, ...] = ()
    argv: tuple[str, ...] = ()
    #: command-line cases: input files written into the case's directory {name: text or bytes}
    inputs: dict[str, str | bytes] = field(default_factory=dict)
    #: scenario and published cases: also run through ``snakemake -n``
    snakemake: bool = False

    @property
    def pieces(self) -> list[str]:
        return [p for p in (self.file, self.field, self.value, self.allowed) if p]


def ids(cases: list[Case]) -> list[str]:
    found = [c.id for c in cases]
    assert len(set(found)) == len(found), "case ids must be unique"
    return found


# ------------------------------------------------------------------------------- file edits
def _dotted(node: Any, dotted: str) -> tuple[Any, Any]:
    *head, last = dotted.split(".")
    for key in head:
        node = node[int(key)] if isinstance(node, list) else node[key]
    return node, (int(last) if isinstance(node, list) else last)


def apply(root: Path, edit: Edit) -> None:
    path = root / edit.path
    if edit.remove:
        path.unlink()
        return
    if edit.data is not None:
        path.write_bytes(edit.data)
        return
    text = edit.text if edit.text is not None else path.read_text(encoding="utf-8")
    if edit.replace:
        old, new = edit.replace
        assert old in text, f"{edit.path}: {old!r} not found: the case no longer applies"
        text = text.replace(old, new, 1)
    if edit.set or edit.delete:
        data = copy.deepcopy(yaml.safe_load(text))
        for dotted, value in edit.set.items():
            node, key = _dotted(data, dotted)
            node[key] = value
        for dotted in edit.delete:
            node, key = _dotted(data, dotted)
            assert key in node or isinstance(node, list), f"{dotted} not in {edit.path}"
            del node[key]
        text = yaml.safe_dump(data, sort_keys=False, allow_unicode=True)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text + edit.append, encoding="utf-8")


@contextlib.contextmanager
def edited(root: Path, edits: tuple[Edit, ...]) -> Iterator[None]:
    """The edits applied for the body, every touched file restored (or removed) afterwards."""
    saved: dict[Path, bytes | None] = {}
    for e in edits:
        p = root / e.path
        saved.setdefault(p, p.read_bytes() if p.exists() else None)
    try:
        for e in edits:
            apply(root, e)
        yield
    finally:
        for p, data in saved.items():
            if data is None:
                p.unlink(missing_ok=True)
            else:
                p.write_bytes(data)


def state(
    top: Path, skip: tuple[str, ...] = (".snakemake", "__pycache__")
) -> dict[str, tuple[int, int]]:
    """(size, mtime) of every file under ``top`` (paths relative to it), directories under a
    name in ``skip`` left out: Snakemake's own bookkeeping, and Python's bytecode caches, which
    the parse writes when bytecode writing is on (PYTHONDONTWRITEBYTECODE unset, as on a user's
    machine): a cache of the code, not an output."""
    out = {}
    for dirpath, dirnames, filenames in os.walk(top):
        dirnames[:] = [d for d in dirnames if d not in skip]
        for name in filenames:
            p = Path(dirpath) / name
            st = p.lstat()
            out[str(p.relative_to(top))] = (st.st_size, st.st_mtime_ns)
    return out


# ------------------------------------------------------------------------------- repository
def make_repo(top: Path) -> Path:
    """A copy of the repository at ``top/repo`` (tracked files), with sentinel outputs in its
    results/ and reports/ that no refusal may touch."""
    repo = top / "repo"
    copy_repo(repo)
    for d in ("results", "reports"):
        (repo / d).mkdir(exist_ok=True)
        (repo / d / "SENTINEL.txt").write_text("an earlier good output\n", encoding="utf-8")
    return repo


def check_message(text: str, case: Case, where: str) -> None:
    """``text`` is one clean refusal naming the case's file, field, value and what is allowed."""
    assert text.strip(), f"{case.id}: {where}: no message"
    assert len(text) <= MAX_MESSAGE, f"{case.id}: {where}: {len(text)} characters:\n{text[:3000]}"
    for mark in TRACE_MARKS:
        assert mark not in text, f"{case.id}: {where}: {mark!r} (a stack trace?) in:\n{text}"
    missing = [p for p in case.pieces if p not in text]
    assert not missing, f"{case.id}: {where}: {missing} not named in:\n{text}"


def refuse_at_parse(top: Path, case: Case) -> None:
    """``snakemake -n`` on the copy ``top/repo`` with the case's edits: refused at parse time."""
    repo = top / "repo"
    with edited(repo, case.edits):
        before = state(top)
        proc = snakemake("-n", "--cores", "1", cwd=repo, timeout=HANG_GUARD_S)
        after = state(top)
    out = proc.stdout + proc.stderr
    assert proc.returncode != 0, f"{case.id}: accepted by snakemake -n:\n{out[-3000:]}"
    assert "Building DAG of jobs" not in out, f"{case.id}: refused after parse:\n{out[-3000:]}"
    check_message(out, case, "snakemake -n")
    assert before == after, f"{case.id}: files changed: {sorted(set(before) ^ set(after))}"


def refuse_in_check(top: Path, case: Case) -> None:
    """``check_workflow`` (what common.smk runs at parse time) on the copy with the case's
    edits: a ConfigError (printed by common.smk as one line, exit status 1) with the pieces."""
    from pipeline.config import ConfigError, load_yaml
    from pipeline.registry import check_workflow

    repo = top / "repo"
    configfile = repo / "config" / "config.yaml"
    with edited(repo, case.edits):
        before = state(top)
        try:
            config = load_yaml(configfile)
            check_workflow(config, [configfile], repo)
        except ConfigError as exc:
            message = str(exc)
        else:
            raise AssertionError(f"{case.id}: accepted by check_workflow")
        after = state(top)
    check_message(message, case, "check_workflow")
    assert before == after, f"{case.id}: files changed: {sorted(set(before) ^ set(after))}"


def cli(
    argv: list[str], cwd: Path, sentinel: Path, probes: tuple[str, ...] = PROBES
) -> subprocess.CompletedProcess[str]:
    """``python -m pipeline.cli ARGV`` in a fresh interpreter, with the compute probes."""
    return subprocess.run(
        [sys.executable, "-c", PROBE_MAIN, str(sentinel), ",".join(probes), *argv],
        cwd=cwd,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "PYTHONHASHSEED": "0"},
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )


def refuse_on_cli(tmp: Path, case: Case) -> None:
    """The console command with the case's arguments (``{dir}`` in them and in the expected
    pieces is the case's directory, where its ``inputs`` are written and from which it runs):
    refused before compute, nothing written."""
    work = tmp / "work"
    work.mkdir()
    case = dataclasses.replace(
        case,
        **{
            name: getattr(case, name).replace("{dir}", str(work))
            for name in ("file", "field", "value", "allowed")
            if isinstance(getattr(case, name), str)
        },
    )
    for name, content in case.inputs.items():
        p = work / name
        p.parent.mkdir(parents=True, exist_ok=True)
        (p.write_bytes if isinstance(content, bytes) else p.write_text)(content)
    sentinel = tmp / "compute-started"
    argv = [a.replace("{dir}", str(work)) for a in case.argv]
    before = state(work)
    proc = cli(argv, work, sentinel)
    after = state(work)
    out = proc.stdout + proc.stderr
    assert proc.returncode != 0, f"{case.id}: accepted (exit 0):\n{out[-3000:]}"
    assert not sentinel.exists(), (
        f"{case.id}: refused only after compute started ({sentinel.read_text()}):\n{out[-3000:]}"
    )
    check_message(proc.stderr, case, "stderr")
    assert before == after, f"{case.id}: files changed: {sorted(set(before) ^ set(after))}"
