"""Layout and drawing with each Axes and each axis measured once: the same layout and the same
bytes as Matplotlib's own, less CPU.

``Figure.tight_layout(rect=...)`` (every figure of the workflow gives a rect: the room for the
legend below or the titles above) runs Matplotlib's ``_auto_adjust_subplotpars`` twice, the
second time with the rect narrowed by the first pass's margins, and each pass asks every Axes
for its tight bounding box: every tick located and formatted, every tick label measured. Nothing
changes between the two passes (the new subplot parameters are applied after both), so the
second pass measures exactly what the first did. Within one pass, and within one draw of a
file, an axis' ticks are computed again for each spine's extent and for its label's position,
and its tick labels measured again for the label's position. :func:`measured_once` remembers,
while it is active, each Axes' tight bounding box and each axis' ticks and tick-label extents,
per state (view limits and the Axes' place in pixels, so a change of size, dpi or limits is
measured afresh) and per arguments (renderer, tick list). :func:`tight_layout` runs the layout
inside it, :func:`pipeline.figure_files.render` each ``savefig``.

The subplot parameters, and so every PNG and SVG, are the same bytes (all 48 figure files of a
full run compared with ``cmp``). Measured on the figure jobs' entry points (two batches of 6
paired alternating runs against main, a shared 2-core machine at load 4-6, so inflated; process
CPU-s, medians of the 12 runs, and the layout's CPU-s, the two batches' medians), the four
figure jobs of the three papers: 5.83 -> 5.09 (layout 0.82, 0.93 -> 0.52, 0.61), 3.63 -> 3.28
(0.82, 0.85 -> 0.66, 0.69), 3.61 -> 3.08 (0.89, 0.81 -> 0.36, 0.35) and 1.38 -> 1.28 (0.10,
0.09 -> 0.07, 0.06).

If Matplotlib stopped calling these methods, the memos would go unused (and a method it no
longer has is not replaced): the layout and drawing are still Matplotlib's own, only slower.

>>> from matplotlib.figure import Figure
>>> def figure():
...     fig = Figure(figsize=(3, 2)); axes = fig.subplots(2, 1, sharex=True)
...     _ = axes[0].plot([1, 10], [1, 100]); axes[0].set_yscale("log")
...     _ = axes[1].set_xlabel("time (s)"); _ = fig.suptitle("t")
...     return fig
>>> a, b = figure(), figure()
>>> a.tight_layout(rect=(0, 0.1, 1, 0.9), pad=0.3); tight_layout(b, rect=(0, 0.1, 1, 0.9), pad=0.3)
>>> vars(a.subplotpars) == vars(b.subplotpars)
True
>>> "get_tightbbox" in vars(b.axes[0]), "_update_ticks" in vars(b.axes[0].yaxis)
(False, False)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from matplotlib.figure import Figure

__all__ = ["measured_once", "tight_layout"]


def _state(ax: Any) -> tuple[float, ...]:
    """What the Axes' measurements follow from, besides settings that no layout or draw
    changes: its view limits and its place in pixels (which includes the figure's size and
    dpi)."""
    return (*ax.xaxis.get_view_interval(), *ax.yaxis.get_view_interval(), *ax.bbox.bounds)


def _memo(method: Callable[..., Any], state: Callable[[], tuple]) -> Callable[..., Any]:
    """``method`` answered once per ``state()`` and arguments (compared by identity: the same
    renderer, the same list of ticks)."""
    memo: dict[tuple, Any] = {}

    def once(*args: Any, **kwargs: Any) -> Any:
        key = (state(), *map(id, args), *((k, id(v)) for k, v in sorted(kwargs.items())))
        if key not in memo:
            memo[key] = (method(*args, **kwargs), args, kwargs)  # keeps the arguments alive
        return memo[key][0]

    return once


#: per Axes and per axis, the methods :func:`measured_once` answers from a memo
_AXES_METHODS = ("get_tightbbox",)
_AXIS_METHODS = ("_update_ticks", "_get_ticklabel_bboxes")


@contextmanager
def measured_once(fig: Figure) -> Iterator[None]:
    """Within the block, each Axes of ``fig`` measures its tight bounding box, and each axis
    computes its ticks and its tick labels' extents, once per state (memos set as instance
    attributes over the methods, removed on exit). For a layout or a draw, in which nothing
    changes the figure; a method Matplotlib no longer has is left alone."""
    patched: list[tuple[Any, str]] = []
    try:
        for ax in fig.axes:
            state = lambda ax=ax: _state(ax)  # noqa: E731 - one per Axes
            targets = [(ax, _AXES_METHODS), (ax.xaxis, _AXIS_METHODS), (ax.yaxis, _AXIS_METHODS)]
            for obj, names in targets:
                for name in names:
                    if callable(getattr(type(obj), name, None)):
                        setattr(obj, name, _memo(getattr(obj, name), state))
                        patched.append((obj, name))
        yield
    finally:
        for obj, name in patched:
            delattr(obj, name)


def tight_layout(fig: Figure, **kwargs: Any) -> None:
    """``fig.tight_layout(**kwargs)`` (``pad``, ``h_pad``, ``w_pad``, ``rect``), each Axes and
    axis measured once (:func:`measured_once`)."""
    with measured_once(fig):
        fig.tight_layout(**kwargs)
