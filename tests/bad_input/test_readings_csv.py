"""Bad readings CSVs (north_finding), through their entry points: ``inertial-repro north-finding
estimate --readings FILE`` for every case, and, for the cases marked, a readings scenario of
the workflow reading the file (``snakemake -n``: the CSV is checked when the workflow is
parsed)."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import Case, Edit, ids, make_repo, refuse_at_parse, refuse_on_cli
from tests.workflow_harness import ROOT

CSV = "config/scenarios/north_finding/data/example_readings.csv"
TEXT = (ROOT / CSV).read_text(encoding="utf-8")
LINES = TEXT.splitlines()
HEADER = next(i for i, ln in enumerate(LINES) if not ln.startswith("#"))
COLUMNS = LINES[HEADER].split(",")
ARGV = ("north-finding", "estimate", "--readings", "{dir}/r.csv", "--lat-deg", "-33.9",
        "--g", "9.80665", "--compass-deg", "220", "--out", "{dir}/est.csv")  # fmt: skip


def _cell(row: int, column: str, value: str) -> str:
    """The example with data row ``row`` (1 = first), ``column`` set to ``value``."""
    lines = list(LINES)
    cells = lines[HEADER + row].split(",")
    cells[COLUMNS.index(column)] = value
    lines[HEADER + row] = ",".join(cells)
    return "\n".join(lines) + "\n"


def _drop_column(column: str) -> str:
    i = COLUMNS.index(column)
    out = [
        ln if ln.startswith("#") else ",".join(c for j, c in enumerate(ln.split(",")) if j != i)
        for ln in LINES
    ]
    return "\n".join(out) + "\n"


def _case(id, content, field, value, allowed, snakemake=False):
    return Case(id, "r.csv", field, value, allowed, argv=ARGV, inputs={"r.csv": content},
                snakemake=snakemake)  # fmt: skip


ROW = LINES[HEADER + 1]
CASES = [
    _case("missing_column", _drop_column("gyro_rad_s"), "missing columns", "gyro_rad_s",
          "a readings CSV has columns", snakemake=True),
    _case("unknown_column", TEXT.replace("n_samples\n", "n_samples,temp\n", 1).replace(
          ",1000000\n", ",1000000,20\n"), "unknown columns", "temp", "allowed"),
    _case("text_cell", _cell(3, "accel_m_s2", "abc"), "row 3, column accel_m_s2", "'abc'",
          "finite number"),
    _case("nan_cell", _cell(4, "gyro_rad_s", "nan"), "row 4, column gyro_rad_s", "nan",
          "finite number"),
    _case("inf_cell", _cell(2, "accel_m_s2", "-inf"), "row 2, column accel_m_s2", "'-inf'",
          "finite number"),
    _case("bad_axis", _cell(2, "axis", "w"), "row 2, column axis", "'w'", "['x', 'y', 'z']"),
    _case("bad_role", _cell(3, "role", "max"), "row 3, column role", "'max'", "peak"),
    _case("tau_360", _cell(1, "tau_deg", "360"), "row 1, column tau_deg", "'360'", "< 360"),
    _case("duplicate_position", TEXT + ROW + "\n", f"row {len(LINES) - HEADER}, column tau_deg",
          "'0'", "duplicate position", snakemake=True),
    _case("accel_over_g", _cell(1, "accel_m_s2", "10.5"), "row 1, column accel_m_s2", "10.5",
          "|accel_m_s2| < g", snakemake=True),
    _case("accel_at_minus_g_on_x", _cell(1, "accel_m_s2", "-9.80665"),
          "row 1, column accel_m_s2", "-9.80665", "< g"),
    _case("gyro_in_deg_h", _cell(1, "gyro_rad_s", "15.04"), "row 1, column gyro_rad_s",
          "15.04", "rad/s"),
    _case("n_samples_huge", _cell(1, "n_samples", "1e300"), "row 1, column n_samples", "'1e300'",
          "<= 1e+12"),
    _case("n_samples_zero", _cell(5, "n_samples", "0"), "row 5, column n_samples", "'0'",
          "integer >= 1"),
    _case("empty_file", "", "r.csv", "empty", "a header"),
    _case("header_only", LINES[HEADER] + "\n", "no readings", None, "readings"),
    _case("binary", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "byte 0", "b'\\x89'", "UTF-8"),
    _case("latin1", TEXT.replace("# Columns", "# Col\xe9", 1).encode("latin-1"), "byte",
          "b'\\xe9'", "UTF-8"),
    _case("ragged_row", TEXT + "0,x,fixed,1.0\n", f"row {len(LINES) - HEADER}", "gyro_rad_s",
          "finite number"),
]  # fmt: skip


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_readings_csv_is_refused_by_the_command_line(tmp_path, case):
    refuse_on_cli(tmp_path, case)


@pytest.fixture(scope="module")
def top(tmp_path_factory):
    top = tmp_path_factory.mktemp("readings-corpus")
    make_repo(top)
    return top


THROUGH_SNAKEMAKE = [c for c in CASES if c.snakemake]


@pytest.mark.parametrize("case", THROUGH_SNAKEMAKE, ids=ids(THROUGH_SNAKEMAKE))
def test_readings_csv_is_refused_when_the_workflow_is_parsed(top, case):
    """The shipped readings scenario reading the bad file: refused at parse, naming the CSV."""
    content = case.inputs["r.csv"]
    edit = Edit(CSV, **({"data": content} if isinstance(content, bytes) else {"text": content}))
    refuse_at_parse(top, Case(case.id, CSV, case.field, case.value, case.allowed, edits=(edit,)))
