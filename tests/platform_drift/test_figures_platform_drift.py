"""Figs. 5-8 of platform_drift: the paper's printed values are drawn on the panels they describe."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from pipeline.platform_drift.figures import CASES, STYLE, plot_scenario


def _errors(path) -> None:
    t = np.linspace(0.0, 7200.0, 73)
    rows = []
    for case in ["none", *CASES]:
        for k, scheme in enumerate(STYLE):
            rows += [{"t_s": x, "case": case, "scheme": scheme, "error_m": (k + 1) * x} for x in t]
    pd.DataFrame(rows).to_csv(path / "errors.csv", index=False)


def test_published_values_overlaid_on_their_panel(tmp_path):
    _errors(tmp_path)
    items = [
        {"label": "Fig. 5 (3)", "quantity": "error_2h_m", "value": "4.5", "unit": "km"},
        {"label": "Fig. 5 (4)", "quantity": "crossover_s", "value": "2400", "unit": "s"},
        {
            "label": "Fig. 6 (3)",
            "quantity": "error_2h_m",
            "value": "99",
            "unit": "km",
        },  # not this one
    ]
    fig = plot_scenario("stationary", tmp_path, None, items)
    try:
        axes = fig.axes[:4]
        assert "Fig. 5" in fig._suptitle.get_text()
        panel3 = [ln for ln in axes[2].lines if ln.get_label().startswith("published")]
        assert len(panel3) == 1
        assert np.allclose(panel3[0].get_xydata(), [[7200.0, 4.5]])  # km on the km axis
        panel4 = [ln for ln in axes[3].lines if ln.get_label().startswith("published")]
        assert len(panel4) == 1 and np.allclose(panel4[0].get_xdata(), [2400.0, 2400.0])
        for ax in (axes[0], axes[1]):
            assert not [ln for ln in ax.lines if ln.get_label().startswith("published")]
        legend = [" ".join(t.get_text().split()) for t in fig.legends[0].get_texts()]
        assert "published 2 h error (paper's text)" in legend
        assert "published crossover (paper's text)" in legend
    finally:
        plt.close(fig)


def test_no_published_values_no_marks(tmp_path):
    _errors(tmp_path)
    fig = plot_scenario("stationary", tmp_path, None)
    try:
        for ax in fig.axes[:4]:
            assert not [ln for ln in ax.lines if ln.get_label().startswith("published")]
    finally:
        plt.close(fig)


def test_simulated_curve_drawn_visibly_on_the_strapdown_one(tmp_path):
    """The finding must be visible: the simulated proposed curve is drawn after (on top of) the
    strapdown one, dashed with markers, in its own colour; a panel below each gives their
    difference (m) on its own axis, sharing the time axis."""
    _errors(tmp_path)
    fig = plot_scenario("stationary", tmp_path, None)
    try:
        for ax in fig.axes[1:4]:
            lines = {ln.get_label(): ln for ln in ax.lines}
            sim, strap = lines[STYLE["proposed_simulated"]["label"]], lines["strapdown"]
            assert sim.get_zorder() > strap.get_zorder()
            assert ax.lines.index(sim) > ax.lines.index(strap)
            assert sim.get_linestyle() == "--" and sim.get_marker() == "o"
            assert sim.get_color() != strap.get_color()
            assert ax.get_ylabel() == "error (km)"
        for ax, below in zip(fig.axes[1:4], fig.axes[4:7], strict=True):
            assert below.get_shared_x_axes().joined(ax, below)
            assert below.get_title() == "sim. − strapdown"
            assert below.get_ylabel() == "difference (m)" and below.get_xlabel() == "time (s)"
            diff = below.lines[-1].get_ydata()
            t = below.lines[-1].get_xdata()
            k_sim, k_strap = (list(STYLE).index(s) + 1 for s in ("proposed_simulated", "strapdown"))
            np.testing.assert_allclose(diff, (k_sim - k_strap) * t)  # simulated - strapdown, m
        assert fig.axes[0].get_ylabel() == "error (µm)"
        assert "Fig. 5 (redrawn from our runs)" in fig._suptitle.get_text()
    finally:
        plt.close(fig)


def test_latitude_sweep_figure_draws_every_scheme_of_the_curve_styles(tmp_path):
    """Fig. 9 (the latitude sweep) with the curve styles of Figs. 5-8: every scheme drawn,
    one marker per latitude, PNG and SVG written."""
    from pipeline.platform_drift.sweep import CASES as SWEEP_CASES
    from pipeline.platform_drift.sweep import SWEEP_COLUMNS, plot

    rows = [
        (lat, case, scheme, 1000.0 * (1 + i) * lat)
        for lat in (10.0, 30.0, 60.0)
        for case in SWEEP_CASES
        for i, scheme in enumerate(STYLE)
    ]
    written = plot(pd.DataFrame(rows, columns=SWEEP_COLUMNS), tmp_path / "fig9.png")
    assert sorted(p.suffix for p in written) == [".png", ".svg"]
    assert all(p.stat().st_size > 1000 for p in written)
