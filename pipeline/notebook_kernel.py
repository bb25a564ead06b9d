"""An IPython extension the notebook build loads into its kernel: no plain text where LaTeX shows.

A SymPy object displayed in a notebook (``sp.init_printing``) gets two representations: its
LaTeX (``text/latex``) and a 2-D pretty print (``text/plain``). The exported page shows one
representation per output, the first of nbconvert's display priority, which lists
``text/latex`` before ``text/plain``: the pretty print of an output that has LaTeX is never
on the page. Printing it took 0.15-0.54 CPU-s per notebook of this project (measured
in-process), against 0.06-0.08 s for the LaTeX, which is now computed twice (once here, once by
the ``text/latex`` formatter).

Loaded by :func:`pipeline.notebook_html.execute` only (``--ext``), this extension makes the
kernel's ``text/plain`` formatter return an object's LaTeX, unchanged, when the ``text/latex``
formatter renders it, and the usual plain text otherwise. A reader who runs the notebook in
JupyterLab gets IPython's formatters as they are.

It also runs the notebook's ``trigsimp`` and ``simplify`` as the derive step and the audits run
theirs: each node that ``futrig`` simplifies is simplified once in the kernel
(:func:`derivations.futrig_memo.memoised_futrig`, the same results), from the first cell after
the one that imported :mod:`derivations` (importing it here would seed SymPy's random generator
and preload the derivation memo at another point of the notebook than its own import does). The
cells compute what they show as before; a node met again is looked up instead of searched again.

>>> from IPython.core.formatters import DisplayFormatter
>>> fmt = DisplayFormatter()
>>> _ = fmt.formatters["text/latex"].for_type(complex, lambda z: f"${z.real} + {z.imag} i$")
>>> latex_first(fmt)
>>> fmt.format(1 + 2j)[0]
{'text/plain': '$1.0 + 2.0 i$', 'text/latex': '$1.0 + 2.0 i$'}
>>> fmt.format([1, 2])[0]
{'text/plain': '[1, 2]'}
"""

from __future__ import annotations

import contextlib
import sys

from IPython.core.formatters import DisplayFormatter, PlainTextFormatter

__all__ = [
    "LatexFirstPlainTextFormatter",
    "TrigsimpMemo",
    "latex_first",
    "load_ipython_extension",
]


class LatexFirstPlainTextFormatter(PlainTextFormatter):
    """IPython's plain-text formatter, except that an object the ``text/latex`` formatter of
    the same display formatter renders gets that LaTeX as its plain text."""

    def __call__(self, obj):
        latex = self.parent.formatters.get("text/latex") if self.parent is not None else None
        if latex is not None and latex.enabled:
            tex = latex(obj)  # None when there is no LaTeX (or its printer failed)
            if isinstance(tex, str):
                return tex
        return super().__call__(obj)


def latex_first(formatter: DisplayFormatter) -> None:
    """Give ``formatter`` a :class:`LatexFirstPlainTextFormatter` in place of its plain-text
    one (the same object, so printers registered on it before or after stay in effect)."""
    plain = formatter.formatters["text/plain"]
    if type(plain) is PlainTextFormatter:
        plain.__class__ = LatexFirstPlainTextFormatter


class TrigsimpMemo:
    """A ``pre_run_cell`` callback: once :mod:`derivations` is imported (``sys.modules``), opens
    :func:`derivations.futrig_memo.memoised_futrig` for the rest of the kernel's life (the build
    kills the kernel after the last cell); until then, does nothing.

    >>> hook = TrigsimpMemo(modules={})
    >>> hook(None), hook.memo
    (None, None)
    """

    def __init__(self, modules: dict | None = None) -> None:
        self.modules = sys.modules if modules is None else modules
        self.memo: dict | None = None  # node -> simplified node, once open
        self._stack = contextlib.ExitStack()

    def __call__(self, info=None) -> None:
        if self.memo is None and "derivations" in self.modules:
            from derivations.futrig_memo import memoised_futrig

            self.memo = self._stack.enter_context(memoised_futrig())


def load_ipython_extension(ipython) -> None:
    """``%load_ext pipeline.notebook_kernel`` (what the build's kernel starts with)."""
    latex_first(ipython.display_formatter)
    ipython.events.register("pre_run_cell", TrigsimpMemo())
