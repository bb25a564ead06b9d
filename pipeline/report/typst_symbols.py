"""Symbol names as Typst math (for the PDF report's mathematics), and Typst string literals.

Symbol names follow the conventions of the ``derivations`` packages:

* ``name`` splits at the first underscore into a stem and subscripts: ``omega_x`` -> ω_x,
  ``P_pred_11`` -> P_(pred, 11) (subscript parts separated by commas);
* Greek names (``alpha`` ... ``omega``, ``Alpha`` ... ``Omega``) and ``ell`` become symbols;
  a stem that starts with ``Delta``/``delta`` keeps it as a prefix (``DeltaV_x`` -> ΔV_x);
* trailing digits of a stem are a subscript (``C11`` -> C_11, ``Gc1_12`` -> G c_(1, 12));
* ``_dot`` / ``_ddot`` parts and ``hat`` / ``dot`` / ``ddot`` / ``bar`` / ``tilde`` stem
  suffixes are accents (``psi_dot`` -> ψ̇, ``phi_i_ddot`` -> φ̈_i, ``xhat_1`` -> x̂_1);
* a paper's own stems with a fixed rendering are passed as ``stems`` (its
  ``Paper.math_stems``): ``symbol_name("xt_1", {"xt": "tilde(x)"})``;
* other multi-letter stems: up to two letters are italic letters side by side (``ax`` ->
  ax, as a product would be typeset), longer ones upright text (``"xpred"``); subscript words
  likewise (``n_wx`` -> n_(w x), ``f_norm`` -> f_"norm");
* trailing primes are primes (``A'``).
"""

from __future__ import annotations

import re
from collections.abc import Mapping

__all__ = ["ACCENTS", "GREEK_NAMES", "symbol_name", "typst_string"]

GREEK = (
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi omicron pi rho "
    "sigma tau upsilon phi chi psi omega"
).split()
#: Greek names (both cases) -> Typst symbol names.
GREEK_NAMES = {g: g for g in GREEK} | {g.capitalize(): g.capitalize() for g in GREEK}
GREEK_NAMES |= {"varepsilon": "epsilon.alt", "varphi": "phi.alt", "vartheta": "theta.alt"}
OTHER_NAMES = {"ell": "ell", "nabla": "nabla", "hbar": "planck.reduce", "infty": "infinity"}

#: Stem suffixes and subscript parts that are accents.
ACCENTS = {
    "ddot": "dot.double",
    "dot": "dot",
    "hat": "hat",
    "tilde": "tilde",
    "bar": "overline",
    "vec": "arrow",
}

_TOKEN = re.compile(r"[A-Za-z]+|[0-9]+|[^A-Za-z0-9]+")


def typst_string(text: str) -> str:
    """A Typst string literal (usable in markup, code and math)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _letters(word: str, *, short: int) -> str:
    """A run of ASCII letters: Greek name, a single letter, up to ``short`` letters side by side
    (italic, like a product), or upright text."""
    if word in GREEK_NAMES:
        return GREEK_NAMES[word]
    if word in OTHER_NAMES:
        return OTHER_NAMES[word]
    if len(word) == 1:
        return word
    if len(word) <= short:
        return " ".join(word)
    return typst_string(word)


def _word(word: str, *, short: int) -> str:
    """A name fragment of letters, digits and other characters (each run printed on its own)."""
    out = []
    for tok in _TOKEN.findall(word):
        if tok.isdigit():
            out.append(tok)
        elif tok.isalpha() and tok.isascii():
            out.append(_letters(tok, short=short))
        else:
            out.append(typst_string(tok))
    return " ".join(out)


def _stem(stem: str, stems: Mapping[str, str]) -> tuple[str, list[str]]:
    """(Typst source of a stem, extra subscript parts taken from its trailing digits)."""
    if stem in stems:
        return stems[stem], []
    m = re.fullmatch(r"([A-Za-z]+?)([0-9]+)", stem)
    if m and not stem.isdigit():
        body, subs = _stem(m.group(1), stems)
        return body, [*subs, m.group(2)]
    for prefix in ("Delta", "delta"):
        if stem.startswith(prefix) and len(stem) > len(prefix):
            inner, subs = _stem(stem[len(prefix) :], stems)
            return f"{prefix} {inner}", subs
    for suffix, accent in ACCENTS.items():
        if stem.endswith(suffix) and len(stem) > len(suffix) and stem[: -len(suffix)].isalpha():
            inner, subs = _stem(stem[: -len(suffix)], stems)
            return f"{accent}({inner})", subs
    if re.fullmatch(r"[A-Za-z]+", stem):
        return _letters(stem, short=2), []
    return (_word(stem, short=2) if stem else typst_string(stem)), []


def symbol_name(name: str, stems: Mapping[str, str] | None = None) -> str:
    """Typst math source of a SymPy symbol name (see the module docstring); ``stems``: whole
    stems with a fixed rendering.

    >>> symbol_name("xt_1", {"xt": "tilde(x)"}), symbol_name("xt_1")
    ('tilde(x)_1', 'x t_1')
    """
    primes = len(name) - len(name.rstrip("'"))
    name = name.rstrip("'")
    stem, *parts = name.split("_")
    base, subs = _stem(stem, stems or {})
    accents = []
    for part in parts:
        if part in ("dot", "ddot"):
            accents.append(ACCENTS[part])
        elif part:
            subs.append(_word(part, short=2))
    for accent in accents:
        base = f"{accent}({base})"
    out = base
    if primes:
        out = f"{out}{chr(39) * primes}"
    if subs:
        sub = ", ".join(subs)
        single = len(subs) == 1 and re.fullmatch(r"[A-Za-z]|[0-9]+|[A-Za-z]+|\"[^\"]*\"", sub)
        out = f"{out}_{sub}" if single else f"{out}_({sub})"
    return out
