"""Code generation: SymPy expressions -> a plain numpy module.

The numeric pipeline never re-types a formula that a derivation produces: it
imports functions from ``pipeline/generated/<slug>.py``, which this module
writes. Every generated function

* takes numpy arrays (or scalars) that broadcast against each other, so it is
  vectorised over time, table positions and Monte Carlo trials for free;
* carries the paper's equation numbers in its docstring (``grep "eq. 47"``);
* is printed with common-subexpression elimination, deterministically, so the
  committed file can be compared byte for byte with a fresh regeneration.

>>> import sympy as sp
>>> x, y = sp.symbols("x y")
>>> print(render_function(GeneratedFunction("f", (x, y), (x + y, x * y), "Sum and product.")))
def f(x, y):
    \"\"\"Sum and product.\"\"\"
    out0 = x + y
    out1 = x*y
    return _broadcast(out0, out1)
<BLANKLINE>
"""

from __future__ import annotations

import keyword
import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

__all__ = [
    "GeneratedFunction",
    "render_function",
    "render_module",
    "write_module",
    "generate_main",
]


@dataclass(frozen=True)
class GeneratedFunction:
    """One function of a generated module.

    ``args`` are the SymPy symbols in argument order; ``exprs`` one expression or
    a tuple of them (the function then returns a tuple of broadcast arrays).
    ``names`` optionally renames symbols to Python identifiers. ``shape`` (for example
    ``(3, 3)`` or ``(3,)``) makes the function return one array whose trailing axes have that
    shape, filled row by row from ``exprs``, instead of a tuple. ``audit_only`` is a one-line
    reason why the pipeline does not call the function (it is generated for the audit, the
    notebook or the tests); empty for a function the pipeline calls. ``cse=False`` prints
    every output whole (``v/z``, not ``_x0 = z**(-1.0)`` then ``_x0*v``), for formulas whose
    rounding should be the textbook one.
    """

    name: str
    args: Sequence[sp.Symbol]
    exprs: sp.Expr | Sequence[sp.Expr]
    doc: str
    names: Mapping[sp.Symbol, str] = field(default_factory=dict)
    shape: tuple[int, ...] | None = None
    audit_only: str = ""
    cse: bool = True


class _Printer(NumPyPrinter):
    """NumPy printer that writes ``np.`` and keeps the output stable."""

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "inline": True})

    def _module_format(self, fqn: str, register: bool = True) -> str:  # noqa: D401
        name = super()._module_format(fqn, register)
        return name.replace("numpy.", "np.")

    def _print_Min(self, expr: sp.Min) -> str:  # noqa: N802 (sympy's printer protocol)
        """Element-wise minimum, nested ``np.minimum`` (sympy's default needs functools)."""
        return self._nested("np.minimum", expr.args)

    def _print_Max(self, expr: sp.Max) -> str:  # noqa: N802
        return self._nested("np.maximum", expr.args)

    def _nested(self, func: str, args: Sequence[sp.Expr]) -> str:
        out = self._print(args[0])
        for a in args[1:]:
            out = f"{func}({out}, {self._print(a)})"
        return out


def _identifier(sym: sp.Symbol, names: Mapping[sp.Symbol, str]) -> str:
    name = names.get(sym, sym.name)
    if not name.isidentifier() or keyword.iskeyword(name):
        raise ValueError(
            f"symbol {sym!r} prints as {name!r}, which is not a Python identifier; "
            "give it a name in GeneratedFunction.names"
        )
    return name


def render_function(fn: GeneratedFunction) -> str:
    """Python source of one generated function."""
    single = isinstance(fn.exprs, sp.Basic)
    exprs = [fn.exprs] if single else list(fn.exprs)
    exprs = [sp.sympify(e) for e in exprs]
    rename = {s: sp.Symbol(_identifier(s, fn.names), real=True) for s in fn.args}
    exprs = [e.xreplace(rename) for e in exprs]
    free = set().union(*(e.free_symbols for e in exprs)) - set(rename.values())
    if free:
        raise ValueError(
            f"function {fn.name}: expressions use symbols {sorted(map(str, free))} "
            f"that are not arguments {[str(a) for a in fn.args]}"
        )
    arg_names = [rename[s].name for s in fn.args]
    printer = _Printer()
    if fn.cse:
        subexprs, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("_x"), order="canonical")
    else:
        subexprs, reduced = [], exprs
    lines = [f"def {fn.name}({', '.join(arg_names)}):", f'    """{fn.doc.strip()}"""']
    for sym, sub in subexprs:
        lines.append(f"    {sym} = {printer.doprint(sub)}")
    outs = []
    for i, e in enumerate(reduced):
        lines.append(f"    out{i} = {printer.doprint(e)}")
        outs.append(f"out{i}")
    if fn.shape is not None:
        if single or len(outs) != math.prod(fn.shape):
            raise ValueError(f"function {fn.name}: {len(outs)} outputs do not fill {fn.shape}")
        lines.append(f"    return _shaped({tuple(fn.shape)!r}, {', '.join(outs)})")
    elif single:
        lines.append("    return out0")
    else:
        lines.append(f"    return _broadcast({', '.join(outs)})")
    return "\n".join(lines) + "\n"


_PRELUDE = '''
import numpy as np


#: the types of a scalar output (a function called with scalar arguments)
_SCALARS = (float, int, np.float64)


def _broadcast(*outs):
    """Broadcast the outputs of a vector function to one common shape (fresh arrays)."""
    if all(type(o) in _SCALARS for o in outs):  # scalars: nothing to broadcast
        return tuple(np.array(o, dtype=float) for o in outs)
    arrays = [np.asarray(o, dtype=float) for o in outs]
    shapes = {a.shape for a in arrays} - {()}
    if len(shapes) == 1:  # one shape besides the scalars' (no call of broadcast_shapes, ~15 us)
        shape = shapes.pop()
    else:
        shape = np.broadcast_shapes(*[a.shape for a in arrays])
    return tuple(
        np.array(a)
        if a.shape == shape
        else (np.full(shape, a.item()) if a.ndim == 0 else np.broadcast_to(a, shape).copy())
        for a in arrays
    )
'''

_SHAPED = '''

def _shaped(shape, *outs):
    """The broadcast outputs as one array of shape ``broadcast + shape``, filled row by row."""
    if all(type(o) in _SCALARS for o in outs):  # scalars: the array of their values
        return np.array(outs, dtype=float).reshape(shape)
    arrays = _broadcast(*outs)
    return np.stack(arrays, axis=-1).reshape(arrays[0].shape + shape)

'''


def render_module(functions: Sequence[GeneratedFunction], header: str) -> str:
    """Source of a whole generated module (header docstring, prelude, functions)."""
    parts = [
        f'"""{header.strip()}\n\nGENERATED FILE: do not edit; regenerate with the command above.\n"""\n'
    ]
    parts.append("# ruff: noqa\n")
    parts.append(_PRELUDE)
    if any(f.shape is not None for f in functions):
        parts.append(_SHAPED)
    parts.append(f"\n__all__ = {[f.name for f in functions]!r}\n")
    audit_only = {f.name: f.audit_only for f in functions if f.audit_only}
    if audit_only:
        parts.append(_render_audit_only(audit_only))
    for fn in functions:
        parts.append("\n\n" + render_function(fn))
    return "".join(parts)


def _render_audit_only(reasons: Mapping[str, str]) -> str:
    for name, reason in reasons.items():
        if "\n" in reason or not reason.strip():
            raise ValueError(f"audit-only reason of {name} must be one non-empty line")
    body = "".join(f"    {name!r}: {reason.strip()!r},\n" for name, reason in reasons.items())
    return (
        "\n#: Functions the pipeline does not call, each with the reason it is generated.\n"
        f"AUDIT_ONLY = {{\n{body}}}\n"
    )


def write_module(path: str | os.PathLike[str], source: str) -> None:
    """Write ``source`` to ``path`` atomically (temp file in the same directory, then rename)."""
    from pipeline.atomic import write_text

    write_text(path, source)


def generate_main(
    source: Callable[[], str], default_out: Path, module: str, argv: list[str] | None = None
) -> int:
    """Command line of a paper's generate module: write ``--out``, or ``--check`` freshness."""
    import argparse
    import sys

    parser = argparse.ArgumentParser(description=f"Generate {default_out.name} ({module}).")
    parser.add_argument("--out", type=Path, default=default_out, help="module to write")
    parser.add_argument("--check", action="store_true", help="fail if --out is stale")
    args = parser.parse_args(argv)
    text = source()
    if args.check:
        current = args.out.read_text(encoding="utf-8") if args.out.exists() else ""
        if current != text:
            print(f"{args.out} is stale: run python -m {module}", file=sys.stderr)
            return 1
        return 0
    write_module(args.out, text)
    return 0
