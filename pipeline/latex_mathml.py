"""LaTeX -> MathML for pages that load nothing (browsers render MathML natively).

The LaTeX goes through docutils' converter (``docutils.utils.math.latex2mathml``, a dependency of
Snakemake, so of the lock), with one correction: docutils turns an accent followed by a
subscript (``\\tilde a_x``) into ``munderover``, placing the subscript *under* the letter; here it
is a subscript of the accented letter, as in TeX. LaTeX that docutils cannot convert raises
:class:`MathConversionError` naming it (:mod:`pipeline.notebook_html` lists every such formula of
a notebook and fails its build: never raw LaTeX in the page).

>>> print(latex_to_mathml(r"\\tilde a_x"))  # doctest: +NORMALIZE_WHITESPACE
<math xmlns="http://www.w3.org/1998/Math/MathML"> <msub> <mover accent="true"> <mi>a</mi>
<mo stretchy="false">~</mo> </mover> <mi>x</mi> </msub> </math>
>>> latex_to_mathml(r"\\frob x")
Traceback (most recent call last):
...
pipeline.latex_mathml.MathConversionError: cannot convert the LaTeX '\\\\frob x' to MathML: Unknown LaTeX command "\\frob".
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Iterator

from docutils.utils.math import MathError
from docutils.utils.math import latex2mathml as _l2m
from docutils.utils.math import mathml_elements as _mml

__all__ = ["MathConversionError", "latex_to_mathml", "output_latex_to_mathml"]


class MathConversionError(ValueError):
    """LaTeX that cannot be rendered as MathML."""


_handle_script = _l2m.handle_script_or_limit


def _script_of_accented(node, c, limits=""):
    """docutils' ``handle_script_or_limit``, except that a subscript of an accented symbol
    (an ``mover`` made by ``\\hat``, ``\\tilde``, ``\\overline``..., which carries an ``accent``
    attribute) is an ``msub`` of it, not an ``munderover`` (docutils keeps that for limits)."""
    child = node[-1] if len(node) else None
    if c == "_" and not limits and isinstance(child, _mml.mover) and "accent" in child.attrib:
        node.pop()
        new_node = _mml.msub(child)
        node.append(new_node)
        return new_node
    return _handle_script(node, c, limits)


@contextlib.contextmanager
def _accent_subscripts() -> Iterator[None]:
    _l2m.handle_script_or_limit = _script_of_accented
    try:
        yield
    finally:
        _l2m.handle_script_or_limit = _handle_script


def latex_to_mathml(tex: str, display: bool = False) -> str:
    """A ``<math>`` element (``display="block"`` if ``display``) for the LaTeX ``tex``."""
    try:
        with _accent_subscripts():
            return _l2m.tex2mathml(tex.strip(), as_block=display)
    except MathError as exc:
        raise MathConversionError(f"cannot convert the LaTeX {tex!r} to MathML: {exc}") from None


_OUTPUT_MATH = re.compile(
    r"\A\s*(?:\$\$(?P<dd>[^$]*)\$\$|\$(?P<d>[^$]*)\$|\\\[(?P<b>.*)\\\])\s*\Z", re.S
)


def output_latex_to_mathml(latex: str) -> str:
    """The MathML of a ``text/latex`` output: one formula in ``$...$``, ``$$...$$`` or
    ``\\[...\\]``, or a bare LaTeX environment, rendered as display math."""
    m = _OUTPUT_MATH.match(latex)
    if m:
        return latex_to_mathml(next(g for g in m.groups() if g is not None), display=True)
    if latex.strip().startswith("\\begin{"):
        return latex_to_mathml(latex, display=True)
    raise MathConversionError(
        f"a text/latex output is not one formula ($...$, $$...$$, \\[...\\]): {latex[:200]!r}"
    )
