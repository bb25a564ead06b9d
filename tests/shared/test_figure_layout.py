"""pipeline.figure_layout: the memoised measurements give Matplotlib's own layout and bytes."""

from __future__ import annotations

import io

import matplotlib
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.figure_files import METADATA, SVG_HASHSALT, render
from pipeline.figure_layout import measured_once, tight_layout


def _figure(rows: int, cols: int) -> Figure:
    """Shared x axes, log and linear y axes, mathtext labels, titles, a legend below."""
    fig = Figure(figsize=(2.5 * cols, 1.4 * rows + 0.8), dpi=120)
    FigureCanvasAgg(fig)
    axes = fig.subplots(rows, cols, sharex=True, squeeze=False)
    for k, ax in enumerate(axes.ravel()):
        ax.plot([0, 1, 2, 3], [1e-3, 0.2, 5.0, 40.0 * (k + 1)], label=f"curve {k}")
        if k % 2 == 0:
            ax.set_yscale("log")
        ax.set_ylabel(rf"error $\sigma_{k}$ (deg)")
        ax.set_title(f"({k + 1}) panel")
    axes[-1, 0].set_xlabel("time (s)")
    fig.suptitle("a title")
    fig.legend(loc="lower center", ncol=3)
    return fig


def _plain_bytes(fig: Figure, dpi: float) -> dict[str, bytes]:
    """What :func:`render` writes, saved without any memo."""
    out = {}
    rc = {"svg.hashsalt": SVG_HASHSALT, "svg.fonttype": "path"}
    with matplotlib.rc_context(rc):
        fig.set_layout_engine(None)
        for fmt in ("png", "svg"):
            buf = io.BytesIO()
            fig.savefig(buf, format=fmt, dpi=dpi, metadata=METADATA[fmt])
            out[fmt] = buf.getvalue()
    return out


@pytest.mark.parametrize("shape", [(1, 1), (3, 1), (2, 3)])
def test_tight_layout_and_files_match_matplotlibs_own(shape: tuple[int, int]) -> None:
    rect = (0.0, 0.12, 1.0, 0.9)
    ours, theirs = _figure(*shape), _figure(*shape)
    tight_layout(ours, rect=rect, pad=0.3, h_pad=0.4)
    theirs.tight_layout(rect=rect, pad=0.3, h_pad=0.4)
    assert vars(ours.subplotpars) == vars(theirs.subplotpars)
    assert render(ours, dpi=80) == _plain_bytes(theirs, dpi=80)


def test_memos_are_removed_even_on_error() -> None:
    fig = _figure(2, 1)
    with pytest.raises(RuntimeError), measured_once(fig):
        assert "get_tightbbox" in vars(fig.axes[0])
        assert {"_update_ticks", "_get_ticklabel_bboxes"} <= set(vars(fig.axes[1].yaxis))
        raise RuntimeError
    for ax in fig.axes:
        assert "get_tightbbox" not in vars(ax)
        assert not {"_update_ticks", "_get_ticklabel_bboxes"} & set(vars(ax.xaxis))


def test_a_changed_view_is_measured_again() -> None:
    fig = _figure(1, 1)
    ax = fig.axes[0]
    with measured_once(fig):
        before = [t.get_loc() for t in ax.xaxis._update_ticks()]
        assert [t.get_loc() for t in ax.xaxis._update_ticks()] == before  # from the memo
        ax.set_xlim(0, 300)
        after = [t.get_loc() for t in ax.xaxis._update_ticks()]
    assert after != before and max(after) > 100
