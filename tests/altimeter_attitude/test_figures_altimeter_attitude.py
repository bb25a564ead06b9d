"""Figures of the altimeter-attitude paper (pipeline.altimeter_attitude.figures and the
figures_* modules it draws with; published_rms and maneuvers, which they read).

Synthetic truth/timeseries frames with known values stand in for a scenario's results (the
pipeline itself takes ~9 s for 4 runs): the tests check that each figure draws exactly the
columns it claims, the published overlay, titles, units and font sizes, that the PNGs are
valid non-blank images, and that writing twice gives byte-identical files.
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib.image as mpimg
import numpy as np
import pandas as pd
import pytest
from matplotlib.text import Text

from pipeline.altimeter_attitude import figures as F
from pipeline.altimeter_attitude.columns import (
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    SWEEP_COLUMNS,
    TIMESERIES_COLUMNS,
    TRUTH_COLUMNS,
)
from pipeline.altimeter_attitude.figures_rms import (
    compare_filters,
    fig7_lkf_rms_error,
    fig8_lkf_c_rms,
    fig10_norm_error,
    fig12_ukf_rms_error,
)
from pipeline.altimeter_attitude.figures_sigma import fig9_lkf_sigma, fig11_ukf_sigma
from pipeline.altimeter_attitude.figures_style import FILTER_STYLE
from pipeline.altimeter_attitude.figures_sweep import SWEEP_PARAMETERS, sweep_figure, write_sweep
from pipeline.altimeter_attitude.figures_truth import (
    fig2_third_row,
    fig3_specific_force,
    fig4_vertical_channel,
    fig5_angular_rates,
    fig6_roll_pitch,
)
from pipeline.altimeter_attitude.maneuvers import maneuver_intervals
from pipeline.altimeter_attitude.published_rms import published_rms
from pipeline.altimeter_attitude.workflow import FIGURES
from pipeline.config import load_yaml
from pipeline.figure_print import COLUMN_WIDTH_IN, MIN_TEXT_PT, TEXT_WIDTH_IN

ROOT = Path(__file__).resolve().parents[2]
PUBLISHED = {
    "linear_kf": {"roll_rms_deg": 0.16, "pitch_rms_deg": 0.07},
    "ukf": {"roll_rms_deg": 0.21, "pitch_rms_deg": 0.10},
}
NO_SIGMA = ("complementary", "accel_leveling")
EULER = ("ukf", "ekf", "complementary", "accel_leveling")
N_RUNS = 7
DURATION = 20.0
MANEUVER = (6.0, 9.0)  # load factor 1.5 inside, 1 outside


def make_truth() -> pd.DataFrame:
    t = np.round(np.arange(0.0, DURATION + 1e-9, 0.02), 10)
    rng = np.random.default_rng(1)
    roll = 10.0 * np.sin(2 * np.pi * t / DURATION)
    pitch = 3.0 + 5.0 * np.cos(2 * np.pi * t / DURATION)
    phi, theta = np.deg2rad(roll), np.deg2rad(pitch)
    inside = (t >= MANEUVER[0]) & (t <= MANEUVER[1])
    frame = pd.DataFrame(
        {
            "t_s": t,
            "c31": -np.sin(theta),
            "c32": np.sin(phi) * np.cos(theta),
            "c33": np.cos(phi) * np.cos(theta),
            "roll_deg": roll,
            "pitch_deg": pitch,
            "yaw_deg": 2.0 * t,
            "v_d_m_s": -5.0 * np.sin(t / 3.0),
            "h_m": 1000.0 + 15.0 * (1 - np.cos(t / 3.0)),
            "load_factor": np.where(inside, 1.5, 1.0),
        }
    )
    for axis in "xyz":
        frame[f"gyro_{axis}_deg_s"] = rng.normal(0.0, 0.5, t.size)
    for axis, mean in zip("xyz", (0.5, 0.0, -9.8), strict=True):
        frame[f"accel_{axis}_m_s2"] = mean + rng.normal(0.0, 0.1, t.size)
    frame.loc[frame.index[-1], [c for c in frame if c.startswith(("gyro_", "accel_"))]] = np.nan
    frame["altimeter_m"] = frame["h_m"] + rng.normal(0.0, 2.0, t.size)
    frame.loc[0, "altimeter_m"] = np.nan
    return frame[TRUTH_COLUMNS]


def make_timeseries(filters=ALTIMETER_FILTERS) -> pd.DataFrame:
    t = np.round(np.arange(0.0, DURATION, 0.2), 10)
    blocks = []
    for k, filt in enumerate(filters):
        scale = 1.0 + k  # every filter and column distinguishable
        block = pd.DataFrame(
            {
                "t_s": t,
                "filter": filt,
                "roll_rms_deg": scale * (2.0 - 0.05 * t),
                "pitch_rms_deg": scale * (1.0 - 0.02 * t),
                "roll_sigma_deg": scale * (2.1 - 0.05 * t),
                "pitch_sigma_deg": scale * (1.1 - 0.02 * t),
                "c1_rms": scale * 1e-2 * (1 + 0.1 * t),
                "c2_rms": scale * 2e-2 * (1 + 0.1 * t),
                "c3_rms": scale * 3e-3 * (1 + 0.1 * t),
                "norm_error_rms": (0.0 if filt in EULER else scale * 1e-5) * (1 + t),
                "nees_roll": 0.9 + 0.01 * t,
                "nees_pitch": 1.1 - 0.01 * t,
            }
        )
        if filt in NO_SIGMA:
            block[["roll_sigma_deg", "pitch_sigma_deg", "nees_roll", "nees_pitch"]] = np.nan
        blocks.append(block)
    # stored in reverse time order: the figures must sort
    return pd.concat(blocks, ignore_index=True).iloc[::-1][TIMESERIES_COLUMNS]


def make_summary() -> pd.DataFrame:
    rows = [
        {
            "filter": f,
            "roll_rms_deg": 0.5 + k,
            "pitch_rms_deg": 0.25 + k,
            "roll_sigma_deg": np.nan if f in NO_SIGMA else 0.6,
            "pitch_sigma_deg": np.nan if f in NO_SIGMA else 0.3,
            "nees_roll": np.nan if f in NO_SIGMA else 1.0,
            "nees_pitch": np.nan if f in NO_SIGMA else 1.0,
            "n_runs": N_RUNS,
        }
        for k, f in enumerate(ALTIMETER_FILTERS)
    ]
    return pd.DataFrame(rows, columns=RMS_SUMMARY_COLUMNS)


def make_sweep() -> pd.DataFrame:
    grid = {
        "imu_rate_hz": [25, 50, 100],
        "intensity": [0.5, 1.0, 1.5],
        "initial_error_deg": [0.5, 2, 5],
    }
    rows = []
    for p, values in grid.items():
        for f, base in (("linear_kf", 0.9), ("ukf", 0.6)):
            for j, v in enumerate(values):
                rows.append(
                    {
                        "parameter": p,
                        "value": float(v),
                        "filter": f,
                        "roll_rms_deg": base * (1 + j),
                        "pitch_rms_deg": base / 2 * (1 + j),
                        "n_runs": 25,
                    }
                )
    return pd.DataFrame(rows, columns=SWEEP_COLUMNS)


@pytest.fixture(scope="module")
def scenario_dir(tmp_path_factory) -> Path:
    d = tmp_path_factory.mktemp("results") / "synthetic"
    d.mkdir()
    make_truth().to_csv(d / "truth.csv", index=False)
    make_timeseries().to_csv(d / "timeseries.csv", index=False)
    make_summary().to_csv(d / "rms_summary.csv", index=False)
    (d / "provenance.json").write_text(
        json.dumps({"scenario": "synthetic", "seeds": {"n_runs": N_RUNS}})
    )
    return d


@pytest.fixture(scope="module")
def written(scenario_dir, tmp_path_factory) -> list[Path]:
    return F.write_all(scenario_dir, tmp_path_factory.mktemp("figs"), PUBLISHED)


def _line(ax, label_part: str):
    found = [ln for ln in ax.lines if label_part in ln.get_label()]
    assert len(found) == 1, [ln.get_label() for ln in ax.lines]
    return found[0]


def _series(ts: pd.DataFrame, filt: str, col: str) -> np.ndarray:
    return ts[ts["filter"] == filt].sort_values("t_s")[col].to_numpy(float)


def _texts(fig) -> list[Text]:
    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


def _check_common(fig, number: str) -> None:
    assert fig.get_suptitle().startswith(number), fig.get_suptitle()
    for ax in fig.axes:
        assert ax.xaxis.get_gridlines()[0].get_visible()
    assert fig.legends, "every figure has a legend"
    _check_print_size(fig)


def _check_print_size(fig) -> None:
    """Drawn at a print width of the PDF report, every text at least MIN_TEXT_PT there."""
    assert fig.get_figwidth() in (COLUMN_WIDTH_IN, TEXT_WIDTH_IN), fig.get_figwidth()
    small = [
        (t.get_text(), t.get_fontsize()) for t in _texts(fig) if t.get_fontsize() < MIN_TEXT_PT
    ]
    assert not small, small


# ---------------------------------------------------------------------------------------------


def test_write_all_writes_valid_non_blank_pngs(written):
    # each figure as PNG (the pages) and SVG (the PDF report's vector twin)
    assert [p.name for p in written] == [
        n.replace(".png", ext) for n in FIGURES for ext in (".png", ".svg")
    ]
    for svg in written[1::2]:
        head = svg.read_bytes()[:400]
        assert b"<svg" in head and b"<dc:date>" not in svg.read_bytes(), svg
    for path in written[0::2]:
        assert path.is_file()
        img = mpimg.imread(path)
        # drawn a column (3.2 in) wide at 200 dpi: at least 600 px for the HTML pages
        assert img.ndim == 3 and img.shape[0] >= 500 and img.shape[1] >= 600, (path, img.shape)
        assert float(img[..., :3].std()) > 0.05, path
    assert not list(written[0].parent.glob(".*.tmp")), "no temporary files left"


def test_writing_twice_is_byte_identical(written, scenario_dir, tmp_path):
    # the CLI writes some of the same figures again, into another directory
    names = ["fig3_specific_force.png", "fig7_lkf_rms_error.png", "fig9_lkf_sigma.png"]
    published = str(ROOT / "config/published/altimeter_attitude.yaml")
    argv = ["--scenario-dir", str(scenario_dir), "--out-dir", str(tmp_path)]
    assert F.main([*argv, "--published", published, "--figures", *names]) == 0
    both = [n.replace(".png", ext) for n in names for ext in (".png", ".svg")]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(both)
    by_name = {p.name: p for p in written}
    for name in both:
        assert (tmp_path / name).read_bytes() == by_name[name].read_bytes(), name


def test_fig7_draws_linear_kf_rms_and_published_values():
    ts = make_timeseries()
    fig = fig7_lkf_rms_error(ts, PUBLISHED, "scenario x", summary=make_summary())
    _check_common(fig, "Fig. 7")
    (ax,) = fig.axes
    roll = _line(ax, "roll, ours")
    np.testing.assert_array_equal(roll.get_ydata(), _series(ts, "linear_kf", "roll_rms_deg"))
    np.testing.assert_array_equal(roll.get_xdata(), _series(ts, "linear_kf", "t_s"))
    pitch = _line(ax, "pitch, ours")
    np.testing.assert_array_equal(pitch.get_ydata(), _series(ts, "linear_kf", "pitch_rms_deg"))
    assert "summary 0.50 deg" in roll.get_label()  # rms_summary.csv of linear_kf
    pub_roll = _line(ax, "roll: published (read from Fig. 7)")
    pub_pitch = _line(ax, "pitch: published (read from Fig. 7)")
    assert list(pub_roll.get_ydata()) == [0.16, 0.16]
    assert list(pub_pitch.get_ydata()) == [0.07, 0.07]
    assert pub_roll.get_linestyle() == "--"
    assert "(deg)" in ax.get_ylabel() and "(s)" in ax.get_xlabel()


def test_fig7_without_published_has_no_overlay():
    fig = fig7_lkf_rms_error(make_timeseries(), None)
    assert not [ln for ln in fig.axes[0].lines if "published" in ln.get_label()]
    assert len(fig.axes[0].lines) == 2


def test_fig12_draws_ukf_rms_and_published_values():
    ts = make_timeseries()
    fig = fig12_ukf_rms_error(ts, PUBLISHED)
    _check_common(fig, "Fig. 12")
    (ax,) = fig.axes
    np.testing.assert_array_equal(
        _line(ax, "roll, ours").get_ydata(), _series(ts, "ukf", "roll_rms_deg")
    )
    assert list(_line(ax, "roll: published (read from Fig. 12)").get_ydata()) == [0.21, 0.21]
    assert list(_line(ax, "pitch: published (read from Fig. 12)").get_ydata()) == [0.10, 0.10]


@pytest.mark.parametrize(
    ("func", "filt", "number"), [(fig9_lkf_sigma, "linear_kf", 9), (fig11_ukf_sigma, "ukf", 11)]
)
def test_sigma_figures_draw_sigma_solid_and_error_dashed(func, filt, number):
    ts = make_timeseries()
    fig = func(ts, n_runs=N_RUNS)
    _check_common(fig, f"Fig. {number}")
    for ax, angle in zip(fig.axes[:2], ("roll", "pitch"), strict=True):
        sigma = _line(ax, f"{angle}: filter sigma")
        error = _line(ax, f"{angle}: actual RMS error")
        np.testing.assert_array_equal(sigma.get_ydata(), _series(ts, filt, f"{angle}_sigma_deg"))
        np.testing.assert_array_equal(error.get_ydata(), _series(ts, filt, f"{angle}_rms_deg"))
        assert sigma.get_linestyle() == "-" and error.get_linestyle() == "--"
        assert "(deg)" in ax.get_ylabel()
    nees = fig.axes[2]
    np.testing.assert_array_equal(
        _line(nees, "NEES roll").get_ydata(), _series(ts, filt, "nees_roll")
    )


def test_fig8_draws_the_three_c_errors():
    ts = make_timeseries()
    fig = fig8_lkf_c_rms(ts)
    _check_common(fig, "Fig. 8")
    (ax,) = fig.axes
    for k in (1, 2, 3):
        np.testing.assert_array_equal(
            _line(ax, f"c_{k}").get_ydata(), _series(ts, "linear_kf", f"c{k}_rms")
        )
    assert "dimensionless" in ax.get_ylabel()


def test_fig10_norm_error_log_scale_and_optional_curves():
    ts = make_timeseries()
    fig = fig10_norm_error(ts)
    _check_common(fig, "Fig. 10")
    (ax,) = fig.axes
    assert ax.get_yscale() == "log"
    assert len(ax.lines) == 3
    lkf = _line(ax, FILTER_STYLE["linear_kf"][1])
    y = _series(ts, "linear_kf", "norm_error_rms")
    np.testing.assert_array_equal(lkf.get_ydata(), y)
    # only linear_kf present: one curve; zeros would be gaps (NaN) on the log axis
    fig = fig10_norm_error(make_timeseries(("linear_kf", "ukf")))
    assert len(fig.axes[0].lines) == 1


def test_truth_figures_draw_the_truth_columns():
    truth = make_truth()
    fig = fig2_third_row(truth)
    _check_common(fig, "Fig. 2")
    for col, ln in zip(("c31", "c32", "c33"), fig.axes[0].lines, strict=True):
        np.testing.assert_array_equal(ln.get_ydata(), truth[col].to_numpy())
    fig = fig3_specific_force(truth)
    _check_common(fig, "Fig. 3")
    assert all("m/s$^2$" in ax.get_ylabel() for ax in fig.axes[:2])
    np.testing.assert_array_equal(
        _line(fig.axes[1], "f_z").get_ydata(), truth["accel_z_m_s2"].to_numpy()
    )
    np.testing.assert_array_equal(
        _line(fig.axes[2], "load factor").get_ydata(), truth["load_factor"].to_numpy()
    )
    fig = fig4_vertical_channel(truth)
    _check_common(fig, "Fig. 4")
    alt = _line(fig.axes[1], "altimeter samples")
    assert len(alt.get_ydata()) == len(truth) - 1  # NaN at t = 0 dropped
    assert alt.get_linestyle() == "None"
    assert "(m/s)" in fig.axes[0].get_ylabel() and "(m)" in fig.axes[1].get_ylabel()
    fig = fig5_angular_rates(truth)
    _check_common(fig, "Fig. 5")
    assert all("(deg/s)" in ax.get_ylabel() for ax in fig.axes)
    fig = fig6_roll_pitch(truth)
    _check_common(fig, "Fig. 6")
    np.testing.assert_array_equal(
        _line(fig.axes[0], "pitch").get_ydata(), truth["pitch_deg"].to_numpy()
    )


def test_maneuver_intervals_and_shading():
    truth = make_truth()
    assert maneuver_intervals(truth) == [MANEUVER]
    ts = make_timeseries()
    fig = compare_filters(ts, "s", maneuver_intervals(truth))
    assert fig.get_suptitle().startswith("Comparison")
    for ax, angle in zip(fig.axes, ("roll", "pitch"), strict=True):
        assert ax.get_yscale() == "log"
        assert len(ax.patches) == 1  # one shaded maneuver
        assert len(ax.lines) == len(ALTIMETER_FILTERS)
        for filt in ALTIMETER_FILTERS:
            ln = _line(ax, FILTER_STYLE[filt][1])
            np.testing.assert_array_equal(ln.get_ydata(), _series(ts, filt, f"{angle}_rms_deg"))


def test_missing_filter_is_named():
    with pytest.raises(ValueError, match="'ukf'"):
        fig12_ukf_rms_error(make_timeseries(("linear_kf",)), PUBLISHED)


def test_published_rms_of_the_config_file():
    data = load_yaml(ROOT / "config/published/altimeter_attitude.yaml")
    assert published_rms(data) == PUBLISHED


def _entry(**kw):
    base = {"id": "V9.bad", "kind": "approximate", "quantity": "roll_rms_deg", "value": "0.2", "select": {"filter": "ukf"}}  # fmt: skip
    base.update(kw)
    return {k: v for k, v in base.items() if v is not None}


@pytest.mark.parametrize(
    ("entry", "match"),
    [
        (_entry(value=None), "V9.bad.*value"),
        (_entry(select={}), "V9.bad.*filter"),
        ({**_entry(quantity=None), "id": None}, r"items\[1\].*quantity"),
        (_entry(value=0.2), "not a number string"),
        (_entry(value="abc"), "not a number string"),
        (_entry(value="-1"), "> 0"),
        (_entry(select={"filter": "linear_kf"}), "twice"),
        ("not a mapping", r"items\[1\]"),
    ],
)  # fmt: skip
def test_published_rms_rejects_malformed_entries(entry, match):
    good = {"id": "V1", "kind": "approximate", "quantity": "roll_rms_deg", "value": "0.16", "select": {"filter": "linear_kf"}}  # fmt: skip
    with pytest.raises(ValueError, match=match):
        published_rms({"items": [good, entry]})
    assert published_rms({"items": [good]}) == {"linear_kf": {"roll_rms_deg": 0.16}}


def test_published_rms_needs_items_and_skips_other_quantities():
    with pytest.raises(ValueError, match="items"):
        published_rms({"claims": []})
    with pytest.raises(ValueError, match="items"):
        published_rms(None)
    other = {"id": "X", "kind": "approximate", "quantity": "yaw_rms_deg", "value": "1.0", "select": {"filter": "ukf"}}  # fmt: skip
    assert published_rms({"items": [other]}) == {}


def test_sweep_figure_maps_the_sweep_rows(tmp_path):
    frame = make_sweep()
    fig = sweep_figure(frame, PUBLISHED)
    assert fig.get_suptitle().startswith("Sweep")
    assert len(fig.axes) == 3
    assert [ax.get_xlabel() for ax in fig.axes] == list(SWEEP_PARAMETERS.values())
    assert "(deg)" in fig.axes[0].get_ylabel()
    for ax, param in zip(fig.axes, SWEEP_PARAMETERS, strict=True):
        rows = frame[frame["parameter"] == param]
        for filt in ("linear_kf", "ukf"):
            cur = rows[rows["filter"] == filt].sort_values("value")
            label = FILTER_STYLE[filt][1]
            roll = _line(ax, f"{label}: roll")
            pitch = _line(ax, f"{label}: pitch")
            np.testing.assert_array_equal(roll.get_xdata(), cur["value"].to_numpy())
            np.testing.assert_array_equal(roll.get_ydata(), cur["roll_rms_deg"].to_numpy())
            np.testing.assert_array_equal(pitch.get_ydata(), cur["pitch_rms_deg"].to_numpy())
            assert roll.get_linestyle() == "-" and pitch.get_linestyle() == "--"
        published = [ln.get_ydata()[0] for ln in ax.lines if "published" in ln.get_label()]
        assert sorted(published) == [0.07, 0.10, 0.16, 0.21]
    assert "25 Monte Carlo runs" in " ".join(t.get_text() for t in fig.texts)
    _check_print_size(fig)
    assert fig.get_figwidth() == TEXT_WIDTH_IN  # panels side by side: alone at the text width
    csv = tmp_path / "sweep.csv"
    frame.to_csv(csv, index=False)
    a = write_sweep(csv, tmp_path / "a" / "fig_sweep.png", PUBLISHED)
    b = write_sweep(csv, tmp_path / "b" / "fig_sweep.png", PUBLISHED)
    assert a.read_bytes() == b.read_bytes()
    img = mpimg.imread(a)
    assert img.shape[1] > 1000 and float(img[..., :3].std()) > 0.05
    assert not [
        ln for ln in sweep_figure(frame, None).axes[0].lines if "published" in ln.get_label()
    ]


def test_figures_step_writes_exactly_its_outputs(scenario_dir, tmp_path):
    """The workflow's figures step writes the declared PNG and SVG files and nothing else."""
    pngs = ["fig2_third_row.png", "fig7_lkf_rms_error.png"]
    out_dir = tmp_path / "figures"
    outputs = {
        "png": [str(out_dir / n) for n in pngs],
        "svg": [str(out_dir / n.replace(".png", ".svg")) for n in pngs],
    }
    inputs = {
        "truth": str(scenario_dir / "truth.csv"),
        "timeseries": str(scenario_dir / "timeseries.csv"),
        "published": str(ROOT / "config/published/altimeter_attitude.yaml"),
    }
    F.figures_step(inputs, outputs, {}, print)
    names = sorted(p.name for p in out_dir.iterdir())
    assert names == sorted(Path(p).name for p in [*outputs["png"], *outputs["svg"]])
    outputs["png"].append(str(out_dir / "fig8_lkf_c_rms.png"))  # declared, but not asked for
    with pytest.raises(ValueError, match="declared"):
        F.figures_step(inputs, outputs, {}, print)


def test_unknown_figure_name_and_bad_published_file(scenario_dir, tmp_path, capsys):
    with pytest.raises(ValueError, match="unknown figure"):
        F.write_all(scenario_dir, tmp_path, None, names=["fig99.png"])
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "items:\n  - {id: V1, kind: approximate, select: {filter: ukf}, quantity: roll_rms_deg}\n"
    )
    rc = F.main(["--scenario-dir", str(scenario_dir), "--out-dir", str(tmp_path), "--published", str(bad)])  # fmt: skip
    assert rc == 2
    assert "V1" in capsys.readouterr().err


def test_sweep_figure_step_writes_the_png_and_its_svg(tmp_path):
    """The workflow's sweep_figure step: fig_sweep.png and fig_sweep.svg from sweep.csv."""
    from pipeline.altimeter_attitude.figures_sweep import sweep_figure_step

    csv = tmp_path / "sweep.csv"
    make_sweep().to_csv(csv, index=False)
    png = tmp_path / "figures" / "fig_sweep.png"
    inputs = {
        "sweep": str(csv),
        "published": str(ROOT / "config/published/altimeter_attitude.yaml"),
    }
    sweep_figure_step(inputs, {"png": str(png)}, {}, print)
    assert sorted(p.name for p in png.parent.iterdir()) == ["fig_sweep.png", "fig_sweep.svg"]
    assert (
        png.read_bytes()
        == write_sweep(csv, tmp_path / "again" / "fig_sweep.png", PUBLISHED).read_bytes()
    )


def test_nees_band_is_scipy_stats_chi2_bit_for_bit():
    # nees_bounds computes chi2.ppf from scipy.special (the figures step does not import
    # scipy.stats); the band drawn in Figs. 9 and 11 and the consistency verdicts are unchanged
    import numpy as np
    from scipy.stats import chi2

    from pipeline.altimeter_attitude.metrics import nees_bounds

    for p in (0.5, 0.9, 0.95, 0.99):
        for n_runs, n_times in [(n, 1) for n in range(1, 400)] + [(100, 7), (3, 1000)]:
            n = n_runs * n_times
            expected = chi2.ppf([(1 - p) / 2, (1 + p) / 2], n) / n
            got = np.array(nees_bounds(n_runs, n_times, p=p))
            assert got.tobytes() == expected.tobytes(), (p, n_runs, n_times)
