"""docutils' MathML and Pygments' code cells as BeautifulSoup writes them back, without a tree.

nbconvert's HTMLExporter ends every export by parsing the whole page with BeautifulSoup
(``html.parser``) and writing it back: attributes sorted, a ``class`` split on whitespace and
joined with single spaces, character references decoded and only ``&``, ``<``, ``>`` escaped
again, a string of ASCII whitespace only (outside ``<pre>``) cut to one newline or space. The
MathML of a notebook page is about half of its tags, the highlighted code cells most of the
rest. :func:`soup_form` gives what BeautifulSoup makes of one ``<math>`` element as
:func:`pipeline.latex_mathml.latex_to_mathml` writes it (docutils' ``tex2mathml``), or of one
code cell as nbconvert highlights it (``<div class="highlight ..."><pre><span ...>``), in one
regular-expression pass, or ``None`` for anything outside that form (the caller then lets
BeautifulSoup do it): tags with lower-case names and double-quoted attribute values without
``&<>"``, no other multi-valued attribute than ``class``, no self-closing or void tag, no
``<textarea>``, no comment, text whose only character references are named ones BeautifulSoup
knows.

>>> soup_form('<math xmlns="http://www.w3.org/1998/Math/MathML">\\n  <mi>x</mi>\\n  '
...           '<mo stretchy="false" form="prefix">&lt;</mo>\\n  <mo>&ApplyFunction;</mo></math>')
'<math xmlns="http://www.w3.org/1998/Math/MathML">\\n<mi>x</mi>\\n<mo form="prefix" \
stretchy="false">&lt;</mo>\\n<mo>\\u2061</mo></math>'
>>> soup_form('<math><mspace width="1em"/></math>') is None
True
>>> soup_form('<div class=" highlight hl-ipython3"><pre><span></span><span class="n">a</span>'
...           ' &lt;  \\n\\n</pre>  \\n</div>')
'<div class="highlight hl-ipython3"><pre><span></span><span class="n">a</span> &lt;  \\n\\n</pre>\\n</div>'
"""

from __future__ import annotations

import re

from bs4.dammit import EntitySubstitution

__all__ = ["soup_form"]

_ATTR = r'\s+([a-z][a-z-]*)="([^"&<>]*)"'
_TOKEN = re.compile(
    rf"<(?P<open>[a-z]+)(?P<attrs>(?:{_ATTR})*)>"
    r"|</(?P<close>[a-z]+)>"
    r"|(?P<text>[^<>&]+)"
    r"|&(?P<entity>[A-Za-z][A-Za-z0-9]*);"
)
_ATTRS = re.compile(_ATTR)
#: BeautifulSoup's HTML builder: elements written as ``<x/>`` and elements whose whitespace is
#: kept; neither may occur in the MathML handled here
_VOID = frozenset(
    "area base br col embed hr img input keygen link menuitem meta param source track wbr "
    "basefont bgsound command frame image isindex nextid spacer".split()
)
_KEEP_SPACE = frozenset({"pre"})  # (and textarea, refused)
#: the attributes BeautifulSoup splits on whitespace besides ``class`` (refused here)
_MULTI_VALUED = frozenset({"accesskey", "dropzone"})
#: the elements a fragment handled here may be
_ROOTS = ("<math", "<div")
_ASCII_SPACES = frozenset("\x20\x0a\x09\x0c\x0d")
_CHAR_OF_ENTITY = EntitySubstitution.HTML_ENTITY_TO_CHARACTER


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def soup_form(fragment: str) -> str | None:
    """``str(BeautifulSoup(fragment, "html.parser"))`` for a ``<math>`` element in the form
    docutils writes or a ``<div>`` of highlighted code in the form Pygments writes (either not
    inside ``<pre>``), or ``None`` if ``fragment`` is not in that form."""
    out: list[str] = []
    text: list[str] = []  # the current string (text and character references, joined)
    open_tags: list[str] = []
    keep_space = 0  # open <pre> elements

    def flush() -> None:
        if text:
            data = "".join(text)
            if not keep_space and all(c in _ASCII_SPACES for c in data):
                data = "\n" if "\n" in data else " "
            out.append(_escape(data))
            text.clear()

    pos = 0
    for m in _TOKEN.finditer(fragment):
        if m.start() != pos:
            return None  # something the pattern does not cover (a comment, '/>', '<' in text)
        pos = m.end()
        if m["text"] is not None:
            text.append(m["text"])
        elif m["entity"] is not None:
            char = _CHAR_OF_ENTITY.get(m["entity"])
            if char is None:
                return None
            text.append(char)
        elif m["open"] is not None:
            name = m["open"]
            if name in _VOID or name == "textarea":
                return None
            attrs = dict(_ATTRS.findall(m["attrs"]))
            if len(attrs) != len(_ATTRS.findall(m["attrs"])) or not _MULTI_VALUED.isdisjoint(attrs):
                return None  # a repeated attribute, or one split on whitespace
            if "class" in attrs:
                attrs["class"] = " ".join(attrs["class"].split())
            flush()
            out.append(f"<{name}" + "".join(f' {k}="{v}"' for k, v in sorted(attrs.items())) + ">")
            open_tags.append(name)
            keep_space += name in _KEEP_SPACE
        else:
            if not open_tags or open_tags[-1] != m["close"]:
                return None  # an end tag BeautifulSoup would match elsewhere or drop
            flush()
            name = open_tags.pop()
            keep_space -= name in _KEEP_SPACE
            out.append(f"</{name}>")
    if pos != len(fragment) or open_tags or text or not fragment.startswith(_ROOTS):
        return None
    return "".join(out)
