"""The notebook pages (pipeline.notebook_html): LaTeX as MathML, no script, the same bytes twice.

The pages of the real notebooks are loaded in a browser by tests/shared/test_offline_html.py; here
the exporter is checked on small notebooks built in the test (outputs written by hand, or run
in a real kernel for the determinism of execution).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

import nbformat
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook, new_output

from pipeline import latex_mathml as LM
from pipeline import notebook_determinism as ND
from pipeline import notebook_html as NH

PNG = "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=="


def _tree(mathml: str) -> ET.Element:
    return ET.fromstring(mathml.replace("&ApplyFunction;", "&#8289;"))


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def _tags(el: ET.Element) -> list[str]:
    return [_local(e.tag) for e in el.iter()]


# --------------------------------------------------------------------------- LaTeX -> MathML


def test_accented_symbol_takes_a_subscript_beside_it():
    # docutils alone gives munderover(a, x, ~): the x under the letter
    for tex in (r"\tilde a_x", r"\hat{x}_{1}", r"\dot\omega_x", r"\overline{x}_1"):
        root = _tree(LM.latex_to_mathml(tex))
        assert _local(root[0].tag) == "msub", (tex, _tags(root))
        assert _local(root[0][0].tag) == "mover", (tex, _tags(root))
        assert "munderover" not in _tags(root), tex
    both = _tree(LM.latex_to_mathml(r"\tilde a_x^2"))
    assert [_local(both[0].tag), _local(both[0][0].tag)] == ["msubsup", "mover"]


def test_limits_keep_munderover_and_the_converter_is_left_as_found():
    assert "munderover" in LM.latex_to_mathml(r"\sum_{i=1}^n x_i", display=True)
    from docutils.utils.math import latex2mathml

    assert latex2mathml.handle_script_or_limit is LM._handle_script  # restored after use
    assert "munderover" in latex2mathml.tex2mathml(r"\tilde a_x")  # docutils' own behaviour


def test_display_and_inline_math():
    block = LM.latex_to_mathml(r"x = \frac{a}{b} \qquad \text{(eq. 1)}", display=True)
    assert block.startswith('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">')
    assert "<mfrac>" in block and "<mtext>(eq. 1)</mtext>" in block
    assert 'display="block"' not in LM.latex_to_mathml("x")


def test_unsupported_latex_is_a_precise_error():
    with pytest.raises(LM.MathConversionError, match=r"'\\\\frob\{x\}'.*Unknown LaTeX command"):
        LM.latex_to_mathml(r"\frob{x}")


@pytest.mark.parametrize(
    "latex",
    [r"$\displaystyle \sin{\left(x \right)}$", r"$$\sin x$$", r"\[\sin x\]",
     r"\begin{matrix}\sin x\end{matrix}"],
)  # fmt: skip
def test_latex_outputs_are_display_math(latex):
    out = LM.output_latex_to_mathml(latex)
    assert 'display="block"' in out and ("sin" in out)


def test_latex_output_that_is_not_one_formula_is_refused():
    with pytest.raises(LM.MathConversionError, match="not one formula"):
        LM.output_latex_to_mathml(r"the angle $x$ and $y$ are small")


# --------------------------------------------------------------------------- the page


def _notebook(uuid: str = "a1b2c", address: str = "0x7f3a2b1c9d80", split: bool = False):
    md = new_markdown_cell(
        "# Title\n\nInline $\\tilde a_x = 2g\\sin\\theta$ and display\n\n"
        "$$\\dot c = -\\omega \\times c \\qquad \\text{(eq. 13)}$$\n\n"
        "an environment \\begin{bmatrix} 1 & 0 \\\\ 0 & 1 \\end{bmatrix} and **bold**."
    )
    code = new_code_cell("show()", execution_count=1)
    stream = (
        [new_output("stream", name="stdout", text="first line\n"),
         new_output("stream", name="stdout", text="second line\n")]
        if split
        else [new_output("stream", name="stdout", text="first line\nsecond line\n")]
    )  # fmt: skip
    code.outputs = [
        *stream,
        new_output(
            "display_data",
            data={"text/latex": r"$\displaystyle x = \frac{1}{2}$", "text/plain": "Eq(x, 1/2)"},
        ),  # fmt: skip
        new_output("display_data", data={"image/png": PNG, "text/plain": "<Figure>"}),
        new_output(
            "display_data",
            data={
                "text/html": f'<style>#T_{uuid}_row0 {{color: red}}</style><table id="T_{uuid}">'
                f'<tr><td id="T_{uuid}_row0_col0">1</td></tr></table>',
                "text/plain": "<Styler>",
            },
        ),  # fmt: skip
        new_output(
            "execute_result",
            data={"text/plain": f"<object object at {address}>"},
            execution_count=1,
        ),  # fmt: skip
        new_output(
            "display_data",
            data={"application/javascript": "console.log(1)", "text/plain": "<JS>"},
        ),
    ]
    md.id, code.id = "markdown-1", "code-1"  # stored in a notebook file (random if new)
    nb = new_notebook(cells=[md, code])
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": {}}}
    return nb


class _Refs(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.refs: list[tuple[str, str, str]] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.refs += [(tag, k, v or "") for k, v in attrs if k in ("src", "href", "data")]


def test_page_has_mathml_and_loads_nothing():
    html = NH.to_html(ND.normalise(_notebook()), "demo")
    refs = _Refs()
    refs.feed(html)
    assert "<title>demo</title>" in html
    assert "script" not in refs.tags and "link" not in refs.tags and "iframe" not in refs.tags
    for tag, _, value in refs.refs:
        assert not re.match(r"\s*(https?:)?//", value), (tag, value)
    assert not re.search(r"mathjax|require\.js|mermaid\.esm|unpkg|cdnjs", html, re.I)
    maths = re.findall(r"<math\b.*?</math>", html, re.S)
    assert len(maths) == 4  # inline, display, environment, the text/latex output
    assert sum('display="block"' in m for m in maths) == 3
    assert "$" not in re.sub(r"<style.*?</style>", "", html, flags=re.S)
    assert "<msub>" in maths[0] and "<mover" in maths[0]  # the accent fix in a page
    assert "<mfrac>" in maths[3]
    imgs = [v for t, k, v in refs.refs if t == "img"]
    assert imgs == [f"data:image/png;base64,{PNG}"]
    assert "console.log" not in html and "&lt;JS&gt;" in html  # the script output's text form


def test_every_unconvertible_formula_is_listed():
    nb = new_notebook(cells=[new_markdown_cell("$\\frob x$ and $\\frab y$ and $z$")])
    with pytest.raises(NH.MathConversionError) as err:
        NH.to_html(nb, "bad")
    text = str(err.value)
    assert "2 formula(s) of notebook 'bad'" in text and "\\frob" in text and "\\frab" in text


def test_normalise_removes_what_varies_between_runs():
    a = NH.to_html(ND.normalise(_notebook()), "demo")
    b = NH.to_html(ND.normalise(_notebook("f9e8d", "0x55d0c0ffee10", split=True)), "demo")
    assert a == b
    assert 'id="T_c1o3"' in a and "#T_c1o3_row0" in a and "T_a1b2c" not in a
    assert "&lt;object object at 0x1&gt;" in a
    # without normalising, the same two notebooks give different pages (the test can fail)
    assert NH.to_html(_notebook(), "demo") != NH.to_html(
        _notebook("f9e8d", "0x55d0c0ffee10", split=True), "demo"
    )


def test_normalise_keeps_equal_addresses_equal_and_distinct_ones_distinct():
    nb = new_notebook(cells=[new_code_cell("x")])
    nb.cells[0].outputs = [
        new_output("stream", name="stdout", text="<f at 0xaaaa10> <g at 0xbbbb20> <f at 0xaaaa10>"),
        new_output("stream", name="stderr", text="warn"),
    ]
    out = ND.normalise(nb).cells[0].outputs
    assert out[0].text == "<f at 0x1> <g at 0x2> <f at 0x1>"
    assert [o.name for o in out] == ["stdout", "stderr"]  # different streams stay apart


def test_a_notebook_reading_the_clock_is_refused(tmp_path):
    nb = new_notebook(cells=[new_code_cell("import time\nT0 = time.perf_counter()")])
    path = tmp_path / "clock.ipynb"
    nbformat.write(nb, path)
    with pytest.raises(
        ValueError, match=r"reads the clock.*\n  cell 0: T0 = time.perf_counter\(\)"
    ):
        NH.execute(path, tmp_path)


def _python_notebook(directory, cells):
    """``directory/demo.ipynb`` holding ``cells``, for the python3 kernel."""
    nb = new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    path = directory / "demo.ipynb"
    nbformat.write(nb, path)
    return path


def test_execution_is_reproducible(tmp_path):
    """Two executions in fresh kernels give the same page: set order (PYTHONHASHSEED), object
    addresses and stream splitting are fixed by the build."""
    code = (
        "import sys\n"
        "words = {f'word{i}' for i in range(40)}\n"
        "print(list(words))\n"
        "sys.stdout.flush()\n"
        "print('after flush')\n"
        "object()"
    )
    path = _python_notebook(tmp_path, [new_markdown_cell("# Demo $x^2$"), new_code_cell(code)])
    first, second = NH.build(path, tmp_path), NH.build(path, tmp_path)
    assert first == second
    assert "after flush" in first and "&lt;object at 0x1&gt;" in first
    assert "<title>demo</title>" in first


def test_the_kernel_gives_latex_outputs_no_pretty_print_and_the_page_is_the_same(tmp_path):
    """The build's kernel (pipeline.notebook_kernel) stores a SymPy output's LaTeX as its plain
    text; the page shows the LaTeX either way (nbconvert's display priority), so it is the same
    page as with SymPy's 2-D pretty print. An output without LaTeX keeps its plain text."""
    code = "import sympy as sp\nsp.init_printing(use_latex='mathjax')\nx = sp.Symbol('x')\n"
    cells = [new_code_cell(code), new_code_cell("sp.sqrt(x) / 2"), new_code_cell("object()")]
    path = _python_notebook(tmp_path, cells)
    executed = NH.execute(path, tmp_path)
    (latex_out,), (plain_out,) = executed.cells[1].outputs, executed.cells[2].outputs
    assert latex_out.data["text/latex"] == r"$\displaystyle \frac{\sqrt{x}}{2}$"
    assert latex_out.data["text/plain"] == latex_out.data["text/latex"]  # the extension ran
    assert plain_out.data == {"text/plain": "<object at 0x1>"}
    page = NH.to_html(executed, "demo")
    latex_out.data["text/plain"] = "  ___\n\u2572\u2571 x \n\u2500\u2500\u2500\u2500\u2500\n  2  "
    assert NH.to_html(executed, "demo") == page
    assert "<msqrt>" in page


def test_the_kernel_prints_latex_once_per_output_and_runs_without_the_cyclic_gc(tmp_path):
    """The build's kernel prints an output's LaTeX once for its text/plain and text/latex (the
    same string), a display of the same object later prints it again, and the cyclic garbage
    collector is off in the kernel (the page is the same: nothing shown depends on it)."""
    code = (
        "import gc\n"
        "class C:\n"
        "    calls = 0\n"
        "    def _repr_latex_(self):\n"
        "        C.calls += 1\n"
        "        return f'$c_{C.calls}$'\n"
        "c = C()\n"
        "print(gc.isenabled())"
    )
    cells = [new_code_cell(code), new_code_cell("c"), new_code_cell("c"), new_code_cell("C.calls")]
    executed = NH.execute(_python_notebook(tmp_path, cells), tmp_path)
    outs = [out for cell in executed.cells for out in cell.outputs]
    assert outs[0]["text"] == "False\n"
    assert outs[1].data == {"text/plain": "$c_1$", "text/latex": "$c_1$"}
    assert outs[2].data == {"text/plain": "$c_2$", "text/latex": "$c_2$"}
    assert outs[3].data == {"text/plain": "2"}


def test_the_kernel_has_the_workflows_sympy_cache_and_memoised_trigsimp(tmp_path, monkeypatch):
    """The build's kernel reads SymPy's cache size from its environment (the size every SymPy
    process of the workflow has: a notebook imports SymPy before ``derivations`` sets it), and
    runs trigsimp with each futrig node memoised once ``derivations`` is imported, not before
    (importing it is the notebook's own step: it seeds SymPy's generator, preloads the memo)."""
    import derivations

    monkeypatch.delenv("SYMPY_CACHE_SIZE", raising=False)
    assert NH.KERNEL_SYMPY_CACHE_SIZE == derivations.SYMPY_CACHE_SIZE
    probe = (
        "import sys\nimport sympy as sp\nT = sys.modules['sympy.simplify.trigsimp']\n"
        "print(sys.modules['sympy.core.cache'].SYMPY_CACHE_SIZE, hasattr(T._futrig, 'memo'))"
    )
    lean = (
        "from sympy.core.exprtools import Factors\n"
        "print(getattr(Factors.__init__, 'lean_dict_factors', False))"
    )
    cells = [
        new_code_cell(probe),
        new_code_cell("import derivations\nx = derivations.SYMPY_SEED"),
        new_code_cell("t = sp.Symbol('t')\nsp.trigsimp(sp.sin(t) ** 2 + sp.cos(t) ** 2)"),
        new_code_cell("print(T._futrig.memo.get(sp.sin(t) ** 2 + sp.cos(t) ** 2))"),
        new_code_cell(lean),
    ]
    executed = NH.execute(_python_notebook(tmp_path, cells), tmp_path)
    texts = [out.get("text") for cell in executed.cells for out in cell.outputs]
    assert texts[0] == f"{NH.KERNEL_SYMPY_CACHE_SIZE} False\n"
    assert texts[-2] == "1\n"  # the node the third cell simplified, remembered
    assert texts[-1] == "True\n"  # Factors built by derivations.factors_dict


# --------------------------------------------------------------------------- code cells

_TRICKY_CODE = (
    "a = \"<b>&amp;</b>\" if x < 3 > y & z else 'it\\'s'  # ° ≈ é\n"
    "\tprint(f\"{a!r:>10}\", end='')\n"
    "%matplotlib inline\n!ls -l | grep '>'\n"
    "def f(x):  # <script>alert(1)</script> &nbsp; &#39;\n    return x @ y ** -1\n"
)


@pytest.mark.parametrize("paper", ["altimeter_attitude", "north_finding", "platform_drift"])
def test_code_cells_are_what_bleach_makes_of_them(paper):
    from nbconvert.filters.highlight import Highlight2HTML
    from nbconvert.filters.strings import clean_html

    from pipeline.registry import ROOT

    highlight = Highlight2HTML(pygments_lexer="ipython3")
    nb = nbformat.read(ROOT / "notebooks" / f"{paper}.ipynb", as_version=4)
    sources = [c.source for c in nb.cells if c.cell_type == "code"] + [_TRICKY_CODE]
    fast = 0
    for source in sources:
        html = highlight(source, metadata={})
        assert NH.clean_code_html(html) == clean_html(html), source[:200]
        fast += bool(NH._PYGMENTS_HTML.fullmatch(html))
    assert fast == len(sources)  # every cell took the fast path, and it agreed with bleach


@pytest.mark.parametrize("paper", ["altimeter_attitude", "north_finding", "platform_drift"])
def test_code_cells_kept_out_of_beautifulsoup_come_back_as_it_writes_them(paper):
    """Each code cell of the papers' notebooks (and tricky code), highlighted and cleaned as the
    export does, has a form (pipeline.mathml_soup.soup_form: it is kept out of the BeautifulSoup
    pass) and that form is what BeautifulSoup writes."""
    from bs4 import BeautifulSoup
    from nbconvert.filters.highlight import Highlight2HTML

    from pipeline.mathml_soup import soup_form
    from pipeline.registry import ROOT

    highlight = Highlight2HTML(pygments_lexer="ipython3")
    nb = nbformat.read(ROOT / "notebooks" / f"{paper}.ipynb", as_version=4)
    sources = [c.source for c in nb.cells if c.cell_type == "code"] + [_TRICKY_CODE, "  \n\n"]
    for source in sources:
        html = NH.clean_code_html(highlight(source, metadata={})).rstrip()
        assert soup_form(html) == str(BeautifulSoup(html, features="html.parser")), source[:200]


@pytest.mark.parametrize(
    "source", [_TRICKY_CODE, "x = 1\n\n\n", "", "  \n", "# <!--offline-mathml-slot-0-->"]
)
def test_code_kept_out_of_beautifulsoup_gives_the_same_page(source, monkeypatch):
    """A page whose code cells skip nbconvert's BeautifulSoup pass is the page with them in it
    (the newline after a cell's markup, left in the page, joins the text that follows)."""
    from pipeline.mathml_soup import soup_form

    nb = _notebook()
    nb.cells.insert(1, new_code_cell(source, execution_count=2))
    nb.cells[1].id = "code-2"
    forms = []
    with monkeypatch.context() as m:
        m.setattr(NH, "soup_form", lambda fragment: forms.append(soup_form(fragment)) or forms[-1])
        fast = NH.to_html(ND.normalise(nb), "demo")
    assert sum(bool(f and f.startswith("<div")) for f in forms) == 2  # both cells kept out
    monkeypatch.setattr(NH, "soup_form", lambda fragment: None)
    assert NH.to_html(ND.normalise(nb), "demo") == fast


@pytest.mark.parametrize(
    "html",
    [
        '<div class="highlight"><pre><span class="n">a</span> &lt; b\r\nc</pre></div>',
        '<div class="highlight"><pre>a &nbsp; &#39; &quot; b & c</pre></div>',
        '<div class="highlight"><pre><a href="x">a</a><span style="color: red">b</span></pre></div>',
        '<div class="highlight"><pre>nul \x00 and \x0c</pre></div>',
        "<pre><script>alert(1)</script><!-- c --></pre>",
    ],
)
def test_other_markup_goes_through_bleach(html):
    from nbconvert.filters.strings import clean_html

    assert not NH._PYGMENTS_HTML.fullmatch(html)
    assert NH.clean_code_html(html) == clean_html(html)


# --------------------------------------------------------------------------- MathML placed


@pytest.mark.parametrize(
    "markdown",
    [
        "# Heading with $\\tau$\n\ntext $x^2$ and $$\\frac{a}{b} < c$$",
        "<pre>$x$ in pre</pre>\n\n$y$ and `$z$` and <!--offline-mathml-slot-0-->",
        "![alt $\\alpha$](x.png) and $\\sin \\theta$",
    ],
)
def test_mathml_kept_out_of_beautifulsoup_gives_the_same_page(markdown, monkeypatch):
    """The formulas kept out of nbconvert's BeautifulSoup pass (pipeline.mathml_soup) come back
    as it would have written them: the same page as with every formula going through it."""
    nb = _notebook()
    nb.cells.insert(1, new_markdown_cell(markdown))
    nb.cells[1].id = "markdown-2"
    fast = NH.to_html(ND.normalise(nb), "demo")
    monkeypatch.setattr(NH, "soup_form", lambda mathml: None)
    assert NH.to_html(ND.normalise(nb), "demo") == fast


@pytest.mark.parametrize(
    "tex",
    [
        r"\tilde a_x = 2 g \sin\theta",
        r"\left[\begin{matrix}\cos{\left(\psi \right)} & 0\\ 0 & 1\end{matrix}\right]",
        r"a < b \quad c > d \quad \operatorname{tr}\,P \mathrm{(13a)} \; \mathbf{x}",
        r"\sum_{i=1}^{n} \frac{\partial f}{\partial x_i} \hat{\omega}_{x,\max} \dot{\omega}",
        r"\sqrt[3]{x} \overline{z}_1 \text{a \& b}",
    ],
)
def test_soup_form_is_what_beautifulsoup_writes(tex):
    from bs4 import BeautifulSoup

    from pipeline.mathml_soup import soup_form

    for display in (False, True):
        mathml = LM.latex_to_mathml(tex, display=display)
        assert soup_form(mathml) == str(BeautifulSoup(mathml, features="html.parser"))


@pytest.mark.parametrize("soup_shortcut", [True, False])
def test_a_heading_keeps_its_formulas_as_mathml(soup_shortcut, monkeypatch):
    """A formula in a heading is MathML in the page (nbconvert's anchor link, rebuilt with
    ElementTree, used to write it as <ns0:math>, which a browser does not render), and the
    heading's id and link hold the formula's text, not its markup's line breaks."""
    if not soup_shortcut:
        monkeypatch.setattr(NH, "soup_form", lambda mathml: None)
    nb = new_notebook(
        cells=[new_markdown_cell("### Method 1 (eq. 19): at $\\tau$ = 0°, $n \\ge 3$ runs\n\n$a$")]
    )
    page = NH.to_html(ND.normalise(nb), "demo")
    assert "ns0" not in page
    m = re.search(r'<h3 id="([^"]+)">(.*?)<a class="anchor-link" href="#([^"]+)">', page, re.S)
    assert m, page[-3000:]
    anchor, heading, link = m.groups()
    assert anchor == link == "Method-1-(eq.-19):-at-%CF%84-=-0%C2%B0,-n%E2%89%A53-runs"
    assert heading.count('<math xmlns="http://www.w3.org/1998/Math/MathML">') == 2
    assert "<mi>τ</mi>" in heading and "<mo>≥</mo>" in heading
    assert heading.startswith("Method 1 (eq. 19): at <math")
