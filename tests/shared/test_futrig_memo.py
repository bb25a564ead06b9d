"""derivations.futrig_memo: trigsimp and simplify give the same expressions (srepr) with each
futrig node memoised as without, SymPy's own function is back after the context, and the
derive and the audit use it."""

from __future__ import annotations

import importlib
import random

import sympy as sp

from derivations import futrig_memo
from derivations.futrig_memo import memoised_futrig, memoised_trig_factor

_trigsimp = importlib.import_module("sympy.simplify.trigsimp")

lam, phi, psi, theta = sp.symbols("lambda phi psi theta", real=True)
ANGLES = (lam, phi, psi, theta)


def _expressions(n: int, seed: int) -> list[sp.Expr]:
    """Sums of products of sines and cosines over shared denominators: the shape of the
    audit's residuals, with nodes repeated between and within them."""
    rng = random.Random(seed)
    trig = [f(a) for a in ANGLES for f in (sp.sin, sp.cos)]

    def term() -> sp.Expr:
        return rng.randint(1, 2) * sp.Mul(
            *(rng.choice(trig) ** rng.randint(1, 2) for _ in range(2))
        )

    denominators = [sp.Add(term(), sp.Integer(1)) for _ in range(2)]
    return [sp.Add(*(term() / rng.choice([1, *denominators]) for _ in range(3))) for _ in range(n)]


def test_trigsimp_and_simplify_give_the_same_expressions_with_the_memo():
    exprs = _expressions(2, seed=3)
    small = sp.sin(phi) ** 2 * sp.cos(theta) / (1 - sp.cos(phi) ** 2) + sp.sin(theta) ** 2
    plain = [sp.srepr(sp.trigsimp(e)) for e in exprs] + [sp.srepr(sp.simplify(small))]
    with memoised_futrig() as memo:
        memoised = [sp.srepr(sp.trigsimp(e)) for e in exprs]
        memoised.append(sp.srepr(sp.simplify(small)))
        again = [sp.srepr(sp.trigsimp(e)) for e in exprs]  # every node from the memo now
    assert memoised == plain and again == plain[:-1]
    assert memo  # it was used


def test_the_original_is_restored_and_nesting_shares_one_memo():
    original = _trigsimp._futrig
    with memoised_futrig() as outer:
        with memoised_futrig() as inner:
            sp.trigsimp(sp.sin(lam) ** 2 + sp.cos(lam) ** 2 + sp.sin(phi) * sp.cos(phi))
        assert inner is outer and _trigsimp._futrig is not original
    assert _trigsimp._futrig is original


def test_another_sympy_version_runs_unchanged(monkeypatch):
    monkeypatch.setattr(futrig_memo.sp, "__version__", "0.0")
    original = _trigsimp._futrig
    with memoised_futrig() as memo:
        assert _trigsimp._futrig is original
        sp.trigsimp(sp.sin(lam) ** 2 + sp.cos(lam) ** 2)
    assert memo == {}


def test_the_audit_and_the_derive_run_with_the_memo(monkeypatch):
    from derivations import artefact, checks

    seen = []

    def check(c):
        seen.append(getattr(_trigsimp._futrig, "memo", None) is not None)
        return checks.AuditRow(c.equation, "not_checkable", "", "x")

    monkeypatch.setattr(checks, "run_check", check)
    checks.run_audit([checks.Check("1", not_checkable="x")])
    monkeypatch.setattr(
        artefact, "_generated", lambda name: seen.append(hasattr(_trigsimp._futrig, "memo"))
    )
    artefact.build_frames()
    assert seen == [True, True]


def test_trigsimp_and_simplify_give_the_same_expressions_with_factor_memoised():
    exprs = _expressions(3, seed=5)
    small = sp.sin(phi) ** 2 * sp.cos(theta) / (1 - sp.cos(phi) ** 2) + sp.sin(theta) ** 2
    plain = [sp.srepr(sp.trigsimp(e)) for e in exprs] + [sp.srepr(sp.simplify(small))]
    original = _trigsimp.factor
    with memoised_futrig(), memoised_trig_factor() as memo:
        memoised = [sp.srepr(sp.trigsimp(e)) for e in exprs]
        memoised.append(sp.srepr(sp.simplify(small)))
        with memoised_trig_factor() as inner:
            assert inner is memo
        assert _trigsimp.factor is not original
        # an option is passed through, not remembered
        assert _trigsimp.factor(sp.sin(lam) ** 2 - 1, deep=True) == sp.factor(
            sp.sin(lam) ** 2 - 1, deep=True
        )
    assert memoised == plain
    assert memo and all(sp.factor(e) == f for e, f in memo.items())
    assert _trigsimp.factor is original


def test_another_sympy_version_factors_unchanged(monkeypatch):
    monkeypatch.setattr(futrig_memo.sp, "__version__", "0.0")
    original = _trigsimp.factor
    with memoised_trig_factor() as memo:
        assert _trigsimp.factor is original
        sp.trigsimp(sp.sin(lam) ** 2 + sp.cos(lam) ** 2)
    assert memo == {}


def test_the_audit_runs_with_factor_memoised(monkeypatch):
    from derivations import checks

    seen = []

    def check(c):
        seen.append(getattr(_trigsimp.factor, "memo", None) is not None)
        return checks.AuditRow(c.equation, "not_checkable", "", "x")

    monkeypatch.setattr(checks, "run_check", check)
    checks.run_audit([checks.Check("1", not_checkable="x")])
    assert seen == [True] and not hasattr(_trigsimp.factor, "memo")
