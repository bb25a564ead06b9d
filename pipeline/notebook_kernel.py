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
formatter renders it, and the usual plain text otherwise. The ``text/latex`` formatter then
returns that same string for that same object within the same display (:func:`latex_first`)
instead of printing the LaTeX a second time (0.05-0.1 CPU-s per notebook). A reader who runs the
notebook in JupyterLab gets IPython's formatters as they are.

It switches the kernel's cyclic garbage collector off, as the workflow's other SymPy jobs do
(:mod:`pipeline.job_gc`): the cells build millions of short-lived SymPy objects, freed by their
reference counts, which the collector scans anyway. Nothing a cell computes or shows depends on
it (SymPy defines no ``__del__``; object addresses in reprs are renumbered by the build), the
cycles made (a figure, a traceback) stay until the build kills the kernel after the last cell:
peak memory +2..9 MB per notebook; kernel CPU -7 % and -14 % in two of the three papers'
notebooks (one run each, before the other changes of that commit).

It also runs the notebook's ``trigsimp`` and ``simplify`` as the derive step and the audits run
theirs: each node that ``futrig`` simplifies is simplified once in the kernel
(:func:`derivations.futrig_memo.memoised_futrig`, the same results) and ``Factors`` of a
dictionary are built without a throw-away SymPy ``Dict``
(:func:`derivations.factors_dict.lean_dict_factors`, the same results), from the first cell after
the one that imported :mod:`derivations` (importing it here would seed SymPy's random generator
and preload the derivation memo at another point of the notebook than its own import does). The
cells compute what they show as before; a node met again is looked up instead of searched again.

>>> from IPython.core.formatters import DisplayFormatter
>>> fmt, printed = DisplayFormatter(), []
>>> def tex(z):
...     printed.append(z)
...     return f"${z.real} + {z.imag} i$"
>>> _ = fmt.formatters["text/latex"].for_type(complex, tex)
>>> latex_first(fmt)
>>> fmt.format(1 + 2j)[0], len(printed)  # printed once for both
({'text/plain': '$1.0 + 2.0 i$', 'text/latex': '$1.0 + 2.0 i$'}, 1)
>>> fmt.format(1 + 2j, include={"text/latex"})[0], len(printed)
({'text/latex': '$1.0 + 2.0 i$'}, 2)
>>> fmt.format([1, 2])[0]
{'text/plain': '[1, 2]'}
>>> fmt.formatters["text/latex"].pending is None  # nothing kept past a display
True
"""

from __future__ import annotations

import contextlib
import gc
import sys

from IPython.core.formatters import DisplayFormatter, LatexFormatter, PlainTextFormatter

__all__ = [
    "LatexFirstDisplayFormatter",
    "LatexFirstPlainTextFormatter",
    "LatexOnceFormatter",
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
                if isinstance(latex, LatexOnceFormatter):
                    latex.pending = (obj, tex)  # for its own call on obj, next in this display
                return tex
        return super().__call__(obj)


class LatexOnceFormatter(LatexFormatter):
    """IPython's LaTeX formatter, except that the LaTeX the plain-text formatter just printed
    for the same object in the same display (``pending``) is returned as it is."""

    pending: tuple[object, str] | None = None

    def __call__(self, obj):
        pending, self.pending = self.pending, None
        if pending is not None and pending[0] is obj:
            return pending[1]
        return super().__call__(obj)


class LatexFirstDisplayFormatter(DisplayFormatter):
    """IPython's display formatter, except that the LaTeX kept for one display
    (:class:`LatexOnceFormatter`) is dropped when that display ends, whatever it included."""

    def format(self, obj, include=None, exclude=None):
        try:
            return super().format(obj, include=include, exclude=exclude)
        finally:
            latex = self.formatters.get("text/latex")
            if isinstance(latex, LatexOnceFormatter):
                latex.pending = None


def latex_first(formatter: DisplayFormatter) -> None:
    """Give ``formatter`` a :class:`LatexFirstPlainTextFormatter` in place of its plain-text
    one, a :class:`LatexOnceFormatter` in place of its LaTeX one and the class
    :class:`LatexFirstDisplayFormatter` (the same objects, so printers registered on them
    before or after stay in effect)."""
    plain = formatter.formatters["text/plain"]
    if type(plain) is PlainTextFormatter:
        plain.__class__ = LatexFirstPlainTextFormatter
    latex = formatter.formatters.get("text/latex")
    if type(latex) is LatexFormatter and type(formatter) is DisplayFormatter:
        latex.__class__ = LatexOnceFormatter
        formatter.__class__ = LatexFirstDisplayFormatter


class TrigsimpMemo:
    """A ``pre_run_cell`` callback: once :mod:`derivations` is imported (``sys.modules``), opens
    :func:`derivations.futrig_memo.memoised_futrig` and
    :func:`derivations.factors_dict.lean_dict_factors` for the rest of the kernel's life (the
    build kills the kernel after the last cell); until then, does nothing.

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
            from derivations.factors_dict import lean_dict_factors
            from derivations.futrig_memo import memoised_futrig

            self.memo = self._stack.enter_context(memoised_futrig())
            self._stack.enter_context(lean_dict_factors())


def load_ipython_extension(ipython) -> None:
    """``%load_ext pipeline.notebook_kernel`` (what the build's kernel starts with)."""
    gc.disable()  # for the kernel's life (see the module's docstring)
    latex_first(ipython.display_formatter)
    ipython.events.register("pre_run_cell", TrigsimpMemo())
