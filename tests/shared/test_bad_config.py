"""Bad input the shared loaders refuse for every paper: the YAML reader, the workflow config, the
scenario folder. Each case asserts the refusal, the message (file, field, value, what is
allowed) and, through Snakemake, one clean message before any job (no stack frames)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from pipeline.config import MAX_BYTES, ConfigError, load_yaml, validate
from pipeline.registry import validate_workflow_config
from pipeline.scenarios import scenario_names
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, copy_repo, snakemake

GOOD_CONFIG = (ROOT / "config" / "config.yaml").read_text(encoding="utf-8")

#: (name, YAML text, pieces the message must contain)
BAD_YAML = [
    (
        "duplicate key",
        "a: 1\nb: 2\na: 3\n",
        ["line 3", "a: duplicate key", "line 1", "each key once"],
    ),
    ("duplicate nested key", "s:\n  lat: 1\n  lat: 2\n", ["line 3", "lat: duplicate key"]),
    ("duplicate flow key", "s: {lat: 1, lat: 2}\n", ["lat: duplicate key"]),
    ("nan", "site:\n  g_m_s2: .nan\n", ["site.g_m_s2 = nan", "finite numbers only"]),
    ("inf", "site:\n  g_m_s2: .inf\n", ["site.g_m_s2 = inf", "finite numbers only"]),
    ("-inf in a list", "x: [1, -.inf]\n", ["x.1 = -inf", "finite"]),
    ("python tag", "a: !!python/object/apply:os.system ['true']\n", ["line 1", "standard tags"]),
    ("custom tag", "a: !include other.yaml\n", ["tag '!include'", "standard tags"]),
    ("unclosed flow", "a: [1, 2\n", ["not valid YAML"]),
    ("tab indent", "a:\n\tb: 1\n", ["not valid YAML"]),
    ("unknown alias", "a: *nothing\n", ["not valid YAML"]),
]


def _alias_bomb(levels: int = 9) -> str:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x]"]
    for i in range(1, levels):
        prev = f"*a{i - 1}"
        lines.append(f"a{i}: &a{i} [{', '.join([prev] * 9)}]")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("name, text, pieces", BAD_YAML, ids=[c[0] for c in BAD_YAML])
def test_bad_yaml_is_refused_naming_the_file_field_and_what_is_allowed(
    tmp_path, name, text, pieces
):
    path = tmp_path / "bad.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError) as err:
        load_yaml(path)
    message = str(err.value)
    assert message.startswith(str(path))
    for piece in pieces:
        assert piece in message


def test_an_alias_bomb_is_refused_with_a_short_message(tmp_path):
    path = tmp_path / "bomb.yaml"
    path.write_text(_alias_bomb(), encoding="utf-8")
    assert path.stat().st_size < 1000
    with pytest.raises(ConfigError, match="expands to more than") as err:
        load_yaml(path)
    assert len(str(err.value)) < 500


def test_anchors_and_aliases_of_a_normal_file_still_load(tmp_path):
    path = tmp_path / "ok.yaml"
    path.write_text("t: &t {rel: 0.3}\na: {tolerance: *t}\nb: {tolerance: *t}\n", encoding="utf-8")
    assert load_yaml(path)["b"] == {"tolerance": {"rel": 0.3}}


@pytest.mark.parametrize(
    "name, content, piece",
    [
        ("latin-1", "a: caf\xe9\n".encode("latin-1"), "byte 6 = b'\\xe9': not UTF-8"),
        ("binary", b"\x89PNG\r\n\x1a\n\x00\x00", "not UTF-8"),
        ("nul", b"a: 1\n\x00\n", "NUL bytes"),
        ("huge", b"a: " + b"1" * (MAX_BYTES + 1) + b"\n", f"at most {MAX_BYTES}"),
    ],
)
def test_files_that_are_not_yaml_text_are_refused(tmp_path, name, content, piece):
    path = tmp_path / "bad.yaml"
    path.write_bytes(content)
    with pytest.raises(ConfigError, match=None) as err:
        load_yaml(path)
    assert str(err.value).startswith(str(path)) and piece in str(err.value)


def test_a_missing_file_and_an_empty_file(tmp_path):
    with pytest.raises(ConfigError, match="file not found"):
        load_yaml(tmp_path / "absent.yaml")
    (tmp_path / "empty.yaml").write_text("", encoding="utf-8")
    assert load_yaml(tmp_path / "empty.yaml") is None


def test_validate_refuses_nan_whatever_the_schema_bounds():
    schema = {"type": "object", "properties": {"x": {"type": "number", "minimum": 0}}}
    with pytest.raises(ConfigError, match=r"s.yaml: x = nan: not a finite number"):
        validate({"x": float("nan")}, schema, "s.yaml")


def test_validation_messages_quote_a_long_value_briefly():
    schema = {"type": "object", "properties": {"x": {"type": "string"}}}
    with pytest.raises(ConfigError) as err:
        validate({"x": list(range(100_000))}, schema, "s.yaml")
    assert len(str(err.value)) < 400 and "must be of type string" in str(err.value)


#: (name, edit of config/config.yaml, pieces of the message)
BAD_CONFIG = [
    (
        "results_dir escapes",
        ("results_dir: results", "results_dir: ../escaped"),
        ["results_dir = '../escaped'", "leaves the repository"],
    ),
    (
        "results_dir absolute",
        ("results_dir: results", "results_dir: /tmp/out"),
        ["results_dir = '/tmp/out'", "leaves the repository"],
    ),
    (
        "reports_dir escapes",
        ("reports_dir: reports", "reports_dir: a/../../b"),
        ["reports_dir", "without '..'"],
    ),
    (
        "duplicate key",
        ("reports_dir: reports", "reports_dir: reports\nreports_dir: r2"),
        ["reports_dir: duplicate key"],
    ),
    (
        "unknown key",
        ("reports_dir: reports", "reports_dir: reports\nreport_dir: r2"),
        ["report_dir", "unknown key"],
    ),
    (
        "papers not a list",
        ("papers: [", "papers: north_finding #["),
        ["papers = 'north_finding'", "must be of type array"],
    ),
]


@pytest.mark.parametrize("name, edit, pieces", BAD_CONFIG, ids=[c[0] for c in BAD_CONFIG])
def test_bad_workflow_config_is_refused(tmp_path, name, edit, pieces):
    import yaml

    old, new = edit
    assert old in GOOD_CONFIG
    path = tmp_path / "config.yaml"
    text = GOOD_CONFIG.replace(old, new, 1)
    if name == "papers not a list":
        text = "\n".join(
            "papers: north_finding" if line.startswith("papers:") else line
            for line in GOOD_CONFIG.splitlines()
        )
    path.write_text(text, encoding="utf-8")
    try:
        config = yaml.safe_load(text)  # what Snakemake's own reader gives
    except yaml.YAMLError:  # pragma: no cover
        config = {}
    with pytest.raises(ConfigError) as err:
        validate_workflow_config(config, [path], ROOT)
    for piece in pieces:
        assert piece in str(err.value)


@pytest.mark.parametrize(
    "files, piece",
    [
        (["a.yml"], "ends in .yml"),
        (["...yaml"], "scenario name '..'"),
        (["Paper.yaml"], "scenario name 'Paper'"),
        (["a b.yaml"], "scenario name 'a b'"),
        ([], "no scenario files"),
    ],
)
def test_scenario_file_names_that_cannot_name_a_results_folder(tmp_path, files, piece):
    for name in files:
        (tmp_path / name).write_text("x: 1\n", encoding="utf-8")
    with pytest.raises(ConfigError, match=None) as err:
        scenario_names(tmp_path)
    assert piece in str(err.value)


def test_every_scenario_in_the_repository_has_a_valid_name():
    for directory in (ROOT / "config" / "scenarios").iterdir():
        assert scenario_names(directory)


@pytest.mark.slow
def test_snakemake_reports_a_bad_config_in_one_line_before_any_job(tmp_path):
    """Through the workflow: the refusal is the message alone (no stack frames, no Python
    traceback), exit status 1, nothing written under results/."""
    repo = tmp_path / "repo"
    copy_repo(repo)
    shutil.rmtree(repo / "results", ignore_errors=True)
    config = repo / "config" / "config.yaml"
    for old, new, piece in [
        ("results_dir: results", "results_dir: ../escaped", "results_dir = '../escaped'"),
        ("reports_dir: reports", "reports_dir: reports\nreports_dir: x", "duplicate key"),
    ]:
        config.write_text(GOOD_CONFIG.replace(old, new, 1), encoding="utf-8")
        proc = snakemake("-n", "--cores", "1", cwd=repo, timeout=HANG_GUARD_S)
        out = proc.stdout + proc.stderr
        assert proc.returncode == 1, out
        assert piece in out and "config/config.yaml" in out
        assert "Traceback" not in out and 'File "' not in out, out
        assert not (repo / "results").exists() and not (tmp_path / "escaped").exists()
    scenario = repo / "config" / "scenarios" / "north_finding" / "bad.yml"
    config.write_text(GOOD_CONFIG, encoding="utf-8")
    scenario.write_text("x: 1\n", encoding="utf-8")
    proc = snakemake("-n", "--cores", "1", cwd=repo, timeout=HANG_GUARD_S)
    out = proc.stdout + proc.stderr
    assert proc.returncode == 1 and "bad.yml: file name ends in .yml" in out, out
    assert "Traceback" not in out and 'File "' not in out, out
    scenario.unlink()
    # a published file is validated when the workflow is parsed, not in its verdict job
    published = repo / "config" / "published" / "platform_drift.yaml"
    text = published.read_text(encoding="utf-8")
    published.write_text(text.replace("kind: approximate", "kind: roughly", 1), encoding="utf-8")
    proc = snakemake("-n", "--cores", "1", cwd=repo, timeout=HANG_GUARD_S)
    out = proc.stdout + proc.stderr
    assert proc.returncode == 1 and "config/published/platform_drift.yaml" in out, out
    assert "'roughly'" in out and "Traceback" not in out and 'File "' not in out, out
    assert not (repo / "results").exists()


def test_config_file_is_validated_from_a_path_snakemake_was_given(tmp_path):
    """A config file given with --configfile is read strictly too (its path names the error)."""
    other = tmp_path / "other.yaml"
    other.write_text("papers: [north_finding]\npapers: [platform_drift]\n", encoding="utf-8")
    with pytest.raises(ConfigError, match=f"{other}: line 2: papers: duplicate key"):
        validate_workflow_config({}, [Path(other)], ROOT)


def test_no_schema_uses_a_format_and_the_slow_format_package_is_not_imported():
    """pipeline/__init__.py hides rfc3987-syntax (2 s of CPU per process) and the other
    format checkers' packages from jsonschema: that is safe only while no schema asks for a
    ``format``."""
    import json
    import subprocess
    import sys

    def formats(node):
        if isinstance(node, dict):
            yield from (["format"] if "format" in node and isinstance(node["format"], str) else [])
            for v in node.values():
                yield from formats(v)
        elif isinstance(node, list):
            for v in node:
                yield from formats(v)

    for schema in sorted((ROOT / "config" / "schemas").glob("*.json")):
        assert not list(formats(json.loads(schema.read_text(encoding="utf-8")))), schema
    probe = (
        "import sys, pipeline, pipeline.config; "
        "print(sorted(m for m in pipeline.HIDDEN_FORMAT_PACKAGES if sys.modules.get(m)))"
    )
    out = subprocess.run(
        [sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "[]"
