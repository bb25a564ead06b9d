"""derivations.trig.pythagorean_reduce: exact (the reduced form equals the input at random
points), canonical (equal inputs give the same form, so an identity reduces to zero), and the
forms the derivations take from it are those simplify gave."""

from __future__ import annotations

import random

import sympy as sp

from derivations import frames
from derivations.trig import pythagorean_reduce

a, b, c, x = sp.symbols("a b c x", real=True)


def test_the_reduced_form_equals_the_input_at_random_points():
    rng = random.Random(1)
    trig = [sp.sin(a), sp.cos(a), sp.sin(b), sp.cos(b), x]
    for _ in range(20):
        expr = sum(
            rng.randint(-3, 3) * sp.Mul(*(rng.choice(trig) ** rng.randint(0, 4) for _ in range(3)))
            for _ in range(6)
        )
        reduced = pythagorean_reduce(expr)
        assert not any(
            p.base.func is sp.sin and p.exp >= 2 for p in reduced.atoms(sp.Pow) if p.exp.is_Integer
        )
        point = {a: rng.uniform(-3, 3), b: rng.uniform(-3, 3), x: rng.uniform(-2, 2)}
        assert abs(complex((expr - reduced).evalf(subs=point))) < 1e-9


def test_an_identity_reduces_to_zero():
    rotation = frames.mat_tn(a, b, c)
    assert (rotation * rotation.T).applyfunc(pythagorean_reduce) == sp.eye(3)
    lhs = sp.expand_trig(sp.cos(a + b) ** 2 + sp.sin(a + b) ** 2)
    assert pythagorean_reduce(lhs) == 1


def test_angular_velocity_from_dcm_is_what_simplify_gives():
    """frames.angular_velocity_from_dcm reduces before it simplifies: on the 3-2-1 sequence
    the result is the one simplify gives from the raw Poisson product."""
    t = sp.Symbol("t", real=True)
    angles = [sp.Function(n, real=True)(t) for n in ("psi_", "theta_", "phi_")]
    raw = frames.angular_velocity_from_dcm(frames.mat_tn(*angles), t, simplify=False)
    assert frames.angular_velocity_from_dcm(frames.mat_tn(*angles), t) == raw.applyfunc(sp.simplify)
