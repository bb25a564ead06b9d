"""An executed notebook as one self-contained, byte-reproducible HTML file.

nbconvert's ``lab`` HTML loads require.js, MathJax and mermaid from a CDN, so a reader without a
network sees raw LaTeX. Here every piece of mathematics becomes MathML at build time, which
browsers render natively:

* markdown cells: ``$...$``, ``$$...$$``, ``\\(...\\)``, ``\\[...\\]`` and ``\\begin{env}...``
  as nbconvert's own markdown parser finds them;
* ``text/latex`` outputs (SymPy's ``$\\displaystyle ...$``, IPython's ``Math``).

The LaTeX goes through :mod:`pipeline.latex_mathml` (docutils' converter with TeX's subscripts
of accented letters). LaTeX it cannot convert fails the build with every offending formula
listed (never raw LaTeX in the page).

The page has no ``<script>`` (no require.js, MathJax, mermaid or widget manager), no external
stylesheet, and figures as ``data:`` URIs. Its bytes depend only on the notebook and the code it
runs: :func:`pipeline.notebook_determinism.normalise` removes what varies between runs of the
same notebook (pandas Styler's random table ids, object addresses in reprs, the random ids of
JavaScript and widget outputs, execution timestamps, widget state, the way printed text was
split into messages), the kernel
runs with a fixed ``PYTHONHASHSEED`` so that the iteration order of sets of strings is the same
every time, and a notebook that reads the clock (``time.perf_counter()``, ``datetime.now()``,
``%time``) is refused: what it prints would differ between runs (the workflow records a
notebook's run time in the rule's benchmark file).
"""

from __future__ import annotations

import copy
import os
import re
from pathlib import Path
from urllib.parse import quote

import nbformat
from jinja2 import DictLoader, pass_context
from nbclient import NotebookClient
from nbconvert import HTMLExporter
from nbconvert.filters.markdown_mistune import IPythonRenderer, MarkdownWithMath
from nbconvert.filters.strings import clean_html

from pipeline import notebook_kernel
from pipeline.latex_mathml import MathConversionError, latex_to_mathml, output_latex_to_mathml
from pipeline.mathml_soup import soup_form
from pipeline.notebook_determinism import normalise, wall_clock_reads

__all__ = [
    "KERNEL_EXTENSION",
    "KERNEL_HASH_SEED",
    "KERNEL_SYMPY_CACHE_SIZE",
    "MathConversionError",
    "OfflineHTMLExporter",
    "build",
    "clean_code_html",
    "execute",
    "to_html",
]

#: ``PYTHONHASHSEED`` of the kernel that executes a notebook (set and dict order reproducible)
KERNEL_HASH_SEED = "0"
#: ``SYMPY_CACHE_SIZE`` of that kernel unless the environment sets it: the size every other SymPy
#: process of the workflow has (``derivations.SYMPY_CACHE_SIZE``, set when ``derivations`` is
#: imported, which a notebook does after importing SymPy, too late for SymPy to read it). At
#: SymPy's default of 1,000 entries the notebooks' simplifications evict what they reuse.
KERNEL_SYMPY_CACHE_SIZE = "50000"
#: the IPython extension the kernel that executes a notebook loads (see :func:`execute`;
#: imported here too, so that the notebook jobs' code inputs include it)
KERNEL_EXTENSION = notebook_kernel.__name__
#: the repository (on the kernel's ``PYTHONPATH``, for :data:`KERNEL_EXTENSION`)
ROOT = Path(__file__).resolve().parents[1]


# --------------------------------------------------------------------------- the exporter


#: one formula of the page (as latex_to_mathml writes it), and a heading's stand-in for one
_MATHML = re.compile(r"<math\b.*?</math>", re.S)
#: (ASCII: ElementTree writes other characters as &#...;; with spaces: in the id it reads
#: otherwise, with dashes)
_HEADING_TOKEN = "@@offline mathml {}@@"


def _header_id(text: str) -> str:
    """A heading's id as nbconvert makes it from the heading's text (its _convert_header_id)."""
    return quote(text.replace(" ", "-"), safe="?/:@!$&'()*+,;=")


class _MathMLRenderer(IPythonRenderer):
    """nbconvert's markdown renderer with the mathematics as MathML; a formula that cannot be
    converted is recorded in ``problems`` (and the build fails on it, see ``to_html``)."""

    def __init__(self, problems: list[str], places: _Places, **kw) -> None:
        super().__init__(**kw)
        self.problems = problems
        self.places = places  # the exporter's: MathML -> what goes into the page for now

    def _math(self, tex: str, display: bool) -> str:
        try:
            return self.places.place(latex_to_mathml(tex, display=display))
        except MathConversionError as exc:
            self.problems.append(f"markdown: {exc}")
            return f"<code>{self.escape_html(tex)}</code>"

    def block_math(self, body: str) -> str:
        return self._math(body, display=True)

    def inline_math(self, body: str) -> str:
        return self._math(body, display=False)

    def latex_environment(self, name: str, body: str) -> str:
        return self._math(f"\\begin{{{name}}}{body}\\end{{{name}}}", display=True)

    def heading(self, text: str, level: int, **attrs) -> str:
        # nbconvert's anchor link (add_anchor) rebuilds a heading with ElementTree, which drops
        # comments, writes MathML with a namespace prefix (<ns0:math>: no formula to a browser)
        # and takes the heading's id from its text, the line breaks of the formulas' markup
        # included. So each formula goes through it as a token, then becomes its MathML again
        # in the heading and its text (no spaces) in the id and the anchor's link.
        formulas: list[str] = []

        def tokenise(m: re.Match) -> str:
            formulas.append(m[0])
            return _HEADING_TOKEN.format(len(formulas) - 1)

        text = self.places.unplace(text)
        if "@@offline mathml" in text:  # (the notebook's own text: left as it is)
            return super().heading(text, level, **attrs)
        html = super().heading(_MATHML.sub(tokenise, text), level, **attrs)
        for i, mathml in enumerate(formulas):
            token = _HEADING_TOKEN.format(i)
            plain = "".join(re.sub(r"<[^>]+>", "", mathml).split())
            html = html.replace(_header_id(token), _header_id(plain)).replace(token, mathml)
        return html


# lab's index.html.j2 without its scripts (require.js, MathJax, mermaid, widget manager), with
# text/latex outputs as MathML in a math font, and wide formulas scrolling in their own box
_TEMPLATE = r"""{%- extends 'index.html.j2' -%}
{%- block html_head_js -%}{%- endblock html_head_js -%}
{%- block html_head_js_mathjax -%}{%- endblock html_head_js_mathjax -%}
{%- block html_head_js_mermaidjs -%}{%- endblock html_head_js_mermaidjs -%}
{%- block jupyter_widgets -%}{%- endblock jupyter_widgets -%}
{% block extra_css %}
<style type="text/css">
/* a font with an OpenType MATH table (stretched radicals and fences), as the report uses */
math { font-family: "STIX Two Math", "Cambria Math", "Latin Modern Math", "DejaVu Math TeX Gyre",
                    math; }
/* a formula wider than the page scrolls in its own box instead of running off the page */
.jp-RenderedLatex, .jp-RenderedMarkdown { overflow-x: auto; }
</style>
{% endblock extra_css %}
{% block data_latex scoped %}
<div class="jp-RenderedLatex jp-OutputArea-output {{ extra_class }}" data-mime-type="text/latex">
{{ output.data['text/latex'] | latex_output_mathml }}
</div>
{%- endblock data_latex %}
"""


#: what Pygments makes of a code cell (``<div class="... highlight ..."><pre><span
#: class="n">...``): its tags, the entities it escapes with, and text without markup characters
#: or control characters (other than tab and newline). bleach (nbconvert's ``clean_html``)
#: returns such a string unchanged: every tag and its ``class`` are allowed, the entities are
#: the ones its serialiser writes, and the text has nothing it would escape or replace.
_PYGMENTS_HTML = re.compile(
    r"""(?:<div class="[\w -]*">|</div>|<pre>|</pre>|<span>|<span class="[\w-]+">|</span>"""
    r"|&(?:lt|gt|amp);"
    "|[^<>&\x00-\x08\x0b-\x1f\x7f-\x9f\ufdd0-\ufdef\ufffe\uffff])*"
)


def clean_code_html(html: str) -> str:
    """nbconvert's ``clean_html`` (bleach) of a highlighted code cell, without running bleach
    when the HTML is Pygments' plain markup (:data:`_PYGMENTS_HTML`), which bleach leaves as it
    is (a third of the export's time went to it); anything else goes through bleach.

    >>> clean_code_html('<div class=" highlight"><pre><span class="n">a</span> &lt; "b"</pre></div>')
    '<div class=" highlight"><pre><span class="n">a</span> &lt; "b"</pre></div>'
    >>> clean_code_html('<pre><script>alert(1)</script></pre>')
    '<pre>&lt;script&gt;alert(1)&lt;/script&gt;</pre>'
    """
    html = html.decode() if isinstance(html, bytes) else str(html)
    return html if _PYGMENTS_HTML.fullmatch(html) else clean_html(html)


#: a formula's or code cell's place in the page while BeautifulSoup re-serialises it (see
#: OfflineHTMLExporter)
_SLOT = "offline-mathml-slot-"
_SLOTS = re.compile(rf"<!--{_SLOT}(\d+)-->|<(/?)(?:pre|textarea)\b|{_SLOT}")


class _Places:
    """The formulas and code cells of one export that wait outside the page while BeautifulSoup
    rewrites it."""

    def __init__(self, active: bool) -> None:
        self.active = active
        self.fragments: list[str] = []  # as converted or highlighted
        self.forms: list[str | None] = []  # as BeautifulSoup writes them (None: put back)

    def place(self, fragment: str) -> str:
        """``fragment``'s place (a comment), or ``fragment`` if BeautifulSoup is to write it;
        whitespace after its last tag (a highlighted cell's newline) stays in the page, where
        BeautifulSoup joins it to the text that follows, as it would have."""
        body = fragment.rstrip(" \t\n\f\r")
        form = soup_form(body) if self.active else None
        if form is None:
            return fragment  # BeautifulSoup writes this one itself
        self.fragments.append(body)
        self.forms.append(form)
        return f"<!--{_SLOT}{len(self.forms) - 1}-->{fragment[len(body) :]}"

    def unplace(self, html: str) -> str:
        """``html`` (a fragment) with its formulas put back as converted."""

        def back(m: re.Match) -> str:
            i = int(m[1])
            self.forms[i] = None
            return self.fragments[i]

        return re.sub(rf"<!--{_SLOT}(\d+)-->", back, html)

    def put_back(self, html: str) -> str | None:
        """``html`` with each place replaced by its fragment as BeautifulSoup writes it, or None
        if the places are not each there once, in order, outside ``<pre>`` and ``<textarea>``,
        or something else carries the marker."""
        expected = iter([i for i, form in enumerate(self.forms) if form is not None])
        parts, pos, depth = [], 0, 0
        for m in _SLOTS.finditer(html):
            if m[1] is None and m[2] is None:
                return None  # the marker outside a place (in the notebook, or rewritten)
            if m[1] is None:
                depth += -1 if m[2] else 1
                continue
            if int(m[1]) != next(expected, None) or depth > 0:
                return None
            parts += [html[pos : m.start()], self.forms[int(m[1])]]
            pos = m.end()
        return "".join([*parts, html[pos:]]) if next(expected, None) is None else None


class OfflineHTMLExporter(HTMLExporter):
    """HTMLExporter (``lab`` template, images embedded) whose page loads nothing: mathematics
    as MathML, no scripts. ``problems`` lists the formulas the last export could not convert.

    nbconvert ends an export by parsing the page with BeautifulSoup and writing it back. The
    MathML (about half of a page's tags) and the highlighted code cells (most of the rest) go
    through it as a comment naming their place (``<!--offline-mathml-slot-<i>-->``, kept as it
    is), and are put back afterwards in the form BeautifulSoup would have written
    (:func:`pipeline.mathml_soup.soup_form`): the same page. If a place did not come back
    exactly once, in order and outside ``<pre>``, or the notebook itself contains the marker,
    the page is exported again with them in it (``tests/shared/test_notebook_html.py``
    compares both ways)."""

    def __init__(self, **kw) -> None:
        kw.setdefault("embed_images", True)
        super().__init__(
            template_name="lab",
            template_file="offline.html.j2",
            extra_loaders=[DictLoader({"offline.html.j2": _TEMPLATE})],
            **kw,
        )
        self.problems: list[str] = []
        self._places = _Places(active=False)

    def from_notebook_node(self, nb, resources=None, **kw):
        self._places = _Places(active=True)
        try:
            html, out = super().from_notebook_node(nb, copy.deepcopy(resources), **kw)
            page = self._places.put_back(html)
        finally:
            self._places = _Places(active=False)
        if page is None:
            self.problems.clear()
            page, out = super().from_notebook_node(nb, resources, **kw)
        return page, out

    @pass_context
    def markdown2html(self, context, source):
        cell = context.get("cell", {})
        renderer = _MathMLRenderer(
            self.problems,
            self._places,
            escape=False,
            attachments=cell.get("attachments", {}),
            embed_images=self.embed_images,
            path=context.get("resources", {}).get("metadata", {}).get("path", ""),
            anchor_link_text=self.anchor_link_text,
            exclude_anchor_links=self.exclude_anchor_links,
            **self.lexer_options,
        )
        return MarkdownWithMath(renderer=renderer).render(source)

    def _latex_output(self, latex: str) -> str:
        try:
            return self._places.place(output_latex_to_mathml(latex))
        except MathConversionError as exc:
            self.problems.append(f"output: {exc}")
            return "<pre>" + latex.replace("&", "&amp;").replace("<", "&lt;") + "</pre>"

    def default_filters(self):
        yield from super().default_filters()
        yield ("markdown2html", self.markdown2html)
        yield ("latex_output_mathml", self._latex_output)
        # the lab template applies clean_html to the highlighted code cells only (this
        # exporter does not sanitise markdown or outputs): the same result, faster
        yield ("clean_html", self._code_html)

    def _code_html(self, html) -> str:
        """A highlighted code cell as bleach leaves it (:func:`clean_code_html`), kept out of
        the BeautifulSoup pass as the formulas are."""
        return self._places.place(clean_code_html(html))


# --------------------------------------------------------------------------- build


def execute(path: str | os.PathLike[str], cwd: str | os.PathLike[str] = ".", timeout: int = 600):
    """Execute the notebook at ``path`` in a fresh python3 kernel whose working directory is
    ``cwd`` and whose ``PYTHONHASHSEED`` is :data:`KERNEL_HASH_SEED` (``SYMPY_CACHE_SIZE``
    :data:`KERNEL_SYMPY_CACHE_SIZE` unless set); return it, normalised. A notebook that reads
    the clock is refused (its page would differ between runs).

    The kernel starts with :mod:`pipeline.notebook_kernel` loaded (no pretty-printed plain
    text for an output the page shows as LaTeX; the repository is put on its ``PYTHONPATH``
    to import it) and is killed once the last cell has run: everything the page shows has
    arrived by then, and an orderly exit spent ~1 CPU-s tearing down the SymPy objects."""
    nb = nbformat.read(path, as_version=4)
    clock = wall_clock_reads(nb)
    if clock:
        raise ValueError(
            f"{path}: reads the clock, so its page would differ between runs (the workflow "
            "records run times in the rule's benchmark file):\n  " + "\n  ".join(clock)
        )
    path_entries = [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]
    env = {  # the kernel's environment: this process's, plus
        **os.environ,
        "PYTHONHASHSEED": KERNEL_HASH_SEED,
        "SYMPY_CACHE_SIZE": os.environ.get("SYMPY_CACHE_SIZE", KERNEL_SYMPY_CACHE_SIZE),
        "PYTHONPATH": os.pathsep.join(path_entries),
    }
    NotebookClient(
        nb,
        timeout=timeout,
        kernel_name="python3",
        record_timing=False,
        extra_arguments=[f"--ext={KERNEL_EXTENSION}"],
        shutdown_kernel="immediate",
        resources={"metadata": {"path": str(cwd)}},
    ).execute(env=env)
    return normalise(nb)


def to_html(nb: nbformat.NotebookNode, title: str) -> str:
    """The self-contained HTML page of an executed notebook (``title`` unless the notebook's
    metadata has one); raises :class:`MathConversionError` listing every formula that could not
    be rendered as MathML."""
    exporter = OfflineHTMLExporter()
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": title}})
    if exporter.problems:
        raise MathConversionError(
            f"{len(exporter.problems)} formula(s) of notebook {title!r} cannot be rendered as "
            "MathML:\n  " + "\n  ".join(exporter.problems)
        )
    return body


def build(notebook: str | os.PathLike[str], cwd: str | os.PathLike[str] = ".") -> str:
    """Execute ``notebook`` and return its page (titled with the file's stem)."""
    return to_html(execute(notebook, cwd), Path(notebook).stem)
