"""Bad command lines and bad flight-log CSVs of ``inertial-repro flight-log``, each run in a fresh
interpreter with the compute probes of tests/bad_input/harness.py. The base log is 3 s at rest
and level at 100 Hz, the altimeter every 5th row; a control checks that it is accepted."""

from __future__ import annotations

import pytest

from tests.bad_input.harness import PROBES, Case, cli, ids, refuse_on_cli

HEADER = (
    "t_s,gyro_x_rad_s,gyro_y_rad_s,gyro_z_rad_s,accel_x_m_s2,accel_y_m_s2,accel_z_m_s2,altimeter_m"
)
N_ROWS = 301


def _row(k: int, **cells: str) -> str:
    base = {"t": f"{k / 100:.2f}", "gx": "0", "gy": "0", "gz": "0", "ax": "0", "ay": "0",
            "az": "-9.80665", "alt": "1000.0" if k % 5 == 0 else ""}  # fmt: skip
    base.update(cells)
    return ",".join(base.values())


def _log(changes: dict[int, dict[str, str]] | None = None, n: int = N_ROWS, drop=()) -> str:
    """The base log with the cells of ``changes`` {data row (1 = first): {cell: text}}."""
    changes = changes or {}
    rows = [_row(k - 1, **changes.get(k, {})) for k in range(1, n + 1) if k not in drop]
    return HEADER + "\n" + "\n".join(rows) + "\n"


LOG = _log()
OUT = "{dir}/att.csv"


def _case(id, args=(), field="", value=None, allowed="", log=LOG, file=None, extra=None):
    argv = ("flight-log", "{dir}/log.csv", "--out", OUT, *args)
    if "--out" in args:
        argv = ("flight-log", "{dir}/log.csv", *args)
    return Case(id, file, field, value, allowed, argv=argv,
                inputs={"log.csv": log, **(extra or {})})  # fmt: skip


def _bad_log(id, log, field, value, allowed):
    return _case(id, (), field, value, allowed, log=log, file="log.csv")


CLI_CASES = [
    _case("out_is_a_directory", ("--out", "{dir}"), "--out", "{dir}", "is a directory"),
    _case("out_is_the_log", ("--out", "{dir}/log.csv"), "--out", "log.csv", "the input log"),
    _case("gravity_nan", ("--gravity", "nan"), "--gravity", "'nan'", "(9.7, 9.9]"),
    _case("gravity_in_cm_s2", ("--gravity", "981"), "--gravity", "'981'", "(9.7, 9.9]"),
    _case("gravity_and_latitude", ("--gravity", "9.8", "--latitude-deg", "30"), "--latitude-deg",
          None, "not allowed with argument --gravity"),
    _case("latitude_95", ("--latitude-deg", "95"), "--latitude-deg", "'95'", "[-90, 90]"),
    _case("height_without_latitude", ("--height-m", "100"), "--height-m", "100",
          "only with --latitude-deg"),
    _case("filters_unknown", ("--filters", "ukf,kalman"), "--filters", "'ukf,kalman'",
          "linear_kf"),
    _case("filters_empty", ("--filters", ","), "--filters", "','", "linear_kf"),
    _case("k_huge", ("--k-per-s", "1e300"), "--k-per-s", "'1e300'", "[0, 10000]"),
    _case("k_dt_too_large", ("--k-per-s", "100"), "--k-per-s", "100", "<= 0.5"),
    _case("level_s_longer_than_log", ("--level-s", "500"), "--level-s", "500",
          "longer than the log"),
    _case("max_jitter_inf", ("--max-jitter", "inf"), "--max-jitter", "'inf'", "(0, 0.5]"),
    _case("ukf_alpha_zero", ("--ukf-alpha", "0"), "--ukf-alpha", "'0'", "(0, 1]"),
    _case("roll0_90", ("--roll0-deg", "90", "--pitch0-deg", "0"), "--roll0-deg", "'90'",
          "[-89, 89]"),
    _case("stamp_middle", ("--stamp", "middle"), "--stamp", "'middle'", "'start'"),
    _case("columns_bad_unit", ("--columns", "t=t_s:hours"), "--columns", "'hours'", "ms"),
    _case("columns_malformed", ("--columns", "gyro_x"), "--columns", "'gyro_x'",
          "QUANTITY=COLUMN[:UNIT]"),
    _case("columns_unknown_quantity", ("--columns", "yaw=gz"), "--columns", "yaw", "gyro_x"),
    _case("columns_absent_column", ("--columns", "t=time:s"), "missing columns", "t (time)",
          "t_s"),
    _case("format_missing", ("--format", "{dir}/absent.yaml"), "--format", "absent.yaml",
          "file not found", file="absent.yaml"),
    _case("format_python_tag", ("--format", "{dir}/f.yaml"), "line 1", "python/object",
          "YAML's standard tags", file="f.yaml",
          extra={"f.yaml": "stamp: !!python/object/apply:os.system ['true']\n"}),
    _case("format_bad_stamp", ("--format", "{dir}/f.yaml"), "stamp", "'middle'", "start",
          file="f.yaml", extra={"f.yaml": "stamp: middle\n"}),
    _case("format_binary", ("--format", "{dir}/f.yaml"), "byte 0", "b'\\x89'", "UTF-8",
          file="f.yaml", extra={"f.yaml": b"\x89PNG\r\n\x1a\n\x00"}),
    _case("log_missing", (), "log.csv", None, "No such file", log=None, file="log.csv"),
    _case("unknown_option", ("--trial", "1e8"), "unrecognized arguments", "--trial 1e8", "--help"),
]  # fmt: skip

LOG_CASES = [
    _bad_log("empty_log", "", "the file is empty", None, "need a header"),
    _bad_log("binary_log", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "byte 0", "b'\\x89'", "UTF-8"),
    _bad_log("missing_altimeter", LOG.replace(",altimeter_m", ",alt"), "altimeter", "alt",
             "altimeter_m"),
    _bad_log("time_backwards", _log({50: {"t": "0.10"}}), "data row", "0.1", "increasing"),
    _bad_log("duplicate_time", _log({50: {"t": "0.48"}}), "data row", "0.48", "increasing"),
    _bad_log("gyro_nan", _log({20: {"gx": "nan"}}), "gyro_x_rad_s", "'nan'", "finite"),
    _bad_log("accel_text", _log({20: {"ay": "abc"}}), "accel_y_m_s2", "'abc'", "number"),
    _bad_log("gyro_huge", _log({20: {"gz": "1e300"}}), "gyro_z_rad_s", "1e+300", "<="),
    _bad_log("accel_in_g0", _log({k: {"az": "-1.0"} for k in range(1, N_ROWS + 1)}),
             "accel_z_m_s2", "0.102 g", "0.8-1.2 g"),
    _bad_log("gap", _log(drop=range(100, 110)), "data rows", "0.11 s", "--max-jitter"),
    _bad_log("two_rows", _log(n=2), "2 rows", None, "at least 3"),
    _bad_log("no_altimeter_samples", _log({k: {"alt": ""} for k in range(1, N_ROWS + 1)}),
             "altimeter_m", "0 samples", "at least 2"),
    _bad_log("altimeter_irregular", _log({3: {"alt": "1000.0"}}), "altimeter_m", "row",
             "every"),
]  # fmt: skip

CASES = CLI_CASES + LOG_CASES


@pytest.mark.parametrize("case", CASES, ids=ids(CASES))
def test_flight_log_command_line_and_log_are_refused(tmp_path, case):
    if "log.csv" in case.inputs and case.inputs["log.csv"] is None:
        case = Case(**{**case.__dict__, "inputs": {}})
    refuse_on_cli(tmp_path, case)


def test_the_base_log_is_accepted_and_computes(tmp_path):
    """Control: the base command line runs (exit 0) and reaches the compute probe."""
    (tmp_path / "log.csv").write_text(LOG, encoding="utf-8")
    sentinel = tmp_path / "compute-started"
    argv = ["flight-log", str(tmp_path / "log.csv"), "--out", str(tmp_path / "att.csv")]
    proc = cli(argv, tmp_path, sentinel, PROBES)
    assert proc.returncode == 0, proc.stderr
    assert sentinel.read_text() in PROBES
    assert (tmp_path / "att.csv").is_file()
