"""derivations.factors_dict: ``Factors`` of a dictionary is the same object (its dictionary's
type, items and order, its gens) with the lean ``__init__`` as with SymPy's, on many
dictionaries and on what ``gcd_terms``, ``factor_terms`` and ``simplify`` give; SymPy's own
``__init__`` is back after the context; another SymPy version runs unchanged; the derive and
the audit use it."""

from __future__ import annotations

import importlib
import random
from collections import defaultdict

import pytest
import sympy as sp

from derivations import factors_dict
from derivations.factors_dict import lean_dict_factors

_exprtools = importlib.import_module("sympy.core.exprtools")
Factors = _exprtools.Factors

x, y, z = sp.symbols("x y z")
phi, theta = sp.symbols("phi theta", real=True)
nc = sp.Symbol("nc", commutative=False)
BASES = [
    x,
    y,
    z,
    sp.sin(phi),
    sp.cos(theta),
    x + 1,
    sp.Integer(2),
    sp.Integer(3),
    sp.Float(1.5),
    sp.S.NegativeOne,
    sp.S.One,
    sp.I,
    sp.pi,
    nc,
    sp.Rational(1, 2),
]
EXPONENTS = [
    sp.Integer(1),
    sp.Integer(2),
    sp.Integer(-1),
    sp.Rational(1, 2),
    sp.Rational(-3, 2),
    sp.Float(0.5),
    x,
    x + y,
    sp.S.Zero,
    1,
    -2,
    3,
]


def _dicts(n: int, seed: int) -> list[dict]:
    """Dictionaries of bases to exponents, with the -1, 1 and I keys SymPy tidies, ``int``
    keys and values, empty ones and defaultdicts."""
    rng = random.Random(seed)
    out: list[dict] = [{}, defaultdict(int), {sp.S.NegativeOne: 1}, {1: 2, -1: 3, sp.I: 2}]
    for i in range(n):
        items = [(rng.choice(BASES), rng.choice(EXPONENTS)) for _ in range(rng.randint(1, 5))]
        if i % 7 == 0:
            items.append((rng.choice([-1, 1, 2]), rng.choice(EXPONENTS)))
        d = dict(items)
        out.append(defaultdict(int, d) if i % 3 == 0 else d)
    return out


def _state(f: object) -> tuple:
    """Everything a Factors holds: its dictionary's type and items in order, and its gens."""
    d = f.factors  # type: ignore[attr-defined]
    return type(d), getattr(d, "default_factory", None), list(d.items()), f.gens  # type: ignore[attr-defined]


def _build(arg: object) -> tuple:
    """The state of ``Factors(arg)`` or the exception it raises."""
    try:
        return _state(Factors(arg))
    except Exception as exc:  # noqa: BLE001 - the same exception is expected either way
        return type(exc), str(exc)


def _arguments() -> list[object]:
    args: list[object] = [d.copy() for d in _dicts(400, seed=5)]
    args += [None, 0, 1, -6, 2.5, sp.S.Zero, sp.Rational(-3, 4), x, 2 * x**3 * y / z, sp.I * x]
    args += [Factors(2 * x), {x: "not sympifiable"}, {"x": 1}]  # the original path
    return args


def test_the_same_factors_as_sympy_on_many_dictionaries():
    args = _arguments()
    plain = [_build(a) for a in args]
    with lean_dict_factors() as patched:
        assert patched
        lean = [_build(a) for a in args]
    assert lean == plain
    assert sum(factors_dict._takes(a) for a in args) >= 400  # the lean path was taken


def test_the_same_results_of_what_builds_factors():
    """gcd_terms, factor_terms, cancel and simplify (each Factors of a dict inside) give the
    same expressions (srepr)."""
    rng = random.Random(11)
    trig = [sp.sin(phi), sp.cos(phi), sp.sin(theta), sp.cos(theta), x, y]
    exprs = [
        sp.Add(
            *(
                rng.randint(1, 3) * rng.choice(trig) * rng.choice(trig) / (1 + rng.choice(trig))
                for _ in range(3)
            )
        )
        for _ in range(6)
    ]
    ops = (sp.gcd_terms, sp.factor_terms, sp.cancel, sp.simplify)
    plain = [sp.srepr(op(e)) for e in exprs for op in ops]
    with lean_dict_factors():
        lean = [sp.srepr(op(e)) for e in exprs for op in ops]
    assert lean == plain


def test_sympys_init_is_restored_and_nesting_leaves_it_to_the_outermost():
    original = Factors.__dict__["__init__"]
    with lean_dict_factors():
        patched = Factors.__dict__["__init__"]
        assert patched is not original
        with lean_dict_factors() as inner:
            assert inner and Factors.__dict__["__init__"] is patched
        assert Factors.__dict__["__init__"] is patched
    assert Factors.__dict__["__init__"] is original


def test_restored_after_an_exception():
    original = Factors.__dict__["__init__"]
    with pytest.raises(RuntimeError), lean_dict_factors():
        raise RuntimeError("boom")
    assert Factors.__dict__["__init__"] is original


def test_another_sympy_version_runs_unchanged(monkeypatch):
    monkeypatch.setattr(factors_dict.sp, "__version__", "1.13.3")
    original = Factors.__dict__["__init__"]
    with lean_dict_factors() as patched:
        assert not patched and Factors.__dict__["__init__"] is original
        assert Factors({x: 2}).factors == {x: 2}
    assert Factors.__dict__["__init__"] is original


def test_the_audit_and_the_derive_run_with_it(monkeypatch):
    from derivations import artefact, checks

    seen = []

    def lean() -> bool:
        return getattr(Factors.__dict__["__init__"], "lean_dict_factors", False)

    def check(c):
        seen.append(lean())
        return checks.AuditRow(c.equation, "not_checkable", "", "x")

    monkeypatch.setattr(checks, "run_check", check)
    checks.run_audit([checks.Check("1", not_checkable="x")])
    monkeypatch.setattr(artefact, "_generated", lambda name: seen.append(lean()))
    artefact.build_frames()
    assert seen == [True, True] and not lean()
