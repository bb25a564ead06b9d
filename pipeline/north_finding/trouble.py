"""Numerical trouble of the north-finding estimators, counted per method and trial: never silent.

An estimator meets trouble where noise (or a reading outside the model) pushes an argument out
of the domain of the formula. It then returns a value (so that one bad trial does not hide
the others) and records the trouble here (the shared counter :mod:`pipeline.trouble`); the
workflow writes the counts to ``numerical_trouble.csv`` and the report shows them. The kinds:

``clipped_arcsine``
    an arcsine or arccosine argument outside [-1, 1] (|f| > g, |cos psi| > 1) clipped to
    it: the angle is then exactly +-90 deg (or 0 / 180 deg);
``unreachable_root``
    ``a sin(psi) + b cos(psi) = c`` with |c| > sqrt(a^2 + b^2) (methods A1c2, A2, A4): c
    clipped to the reachable range, which gives the double root;
``complex_roots``
    the quartic of eq. 50 (method A3) has no real root in [-1, 1]: the real parts of its
    complex roots are used instead; or the quadratic of eq. 65 (method A5) has no real root
    (negative discriminant): its scale and azimuth are NaN (so also ``non_finite``);
``non_finite``
    an estimate of the method is NaN or infinite.

The runs (column ``run``): ``noise_free_real``, ``monte_carlo``, ``sensitivity`` and
``ranking`` (column ``case``: ``N=<n_avg>``) of a simulated scenario, ``readings`` of a
readings scenario, and ``n_inference`` (``N=<n_avg>``) of the published scenario's N inference
(``n_trouble.csv``).

>>> import numpy as np
>>> t = Trouble()
>>> t.mark("L1", "clipped_arcsine", np.array([True, False, False]))
>>> est = {("L1", "phi_deg"): np.array([1.0, np.nan, 2.0])}
>>> t.frame(est, "monte_carlo")[["method", "kind", "n_affected"]].values.tolist()
[['L1', 'clipped_arcsine', 1], ['L1', 'unreachable_root', 0], ['L1', 'complex_roots', 0], ['L1', 'non_finite', 1]]
>>> t.mark("L1", "typo", np.array([True]))
Traceback (most recent call last):
...
ValueError: numerical trouble kind 'typo': allowed: clipped_arcsine, unreachable_root, complex_roots, non_finite
"""

from __future__ import annotations

from pipeline import trouble as shared
from pipeline.trouble import TROUBLE_COLUMNS, mark

__all__ = ["TROUBLE_COLUMNS", "TROUBLE_KINDS", "Trouble", "mark", "n_case"]

#: the kinds of trouble, in the order of the file's rows
TROUBLE_KINDS = ("clipped_arcsine", "unreachable_root", "complex_roots", "non_finite")


class Trouble(shared.Trouble):
    """:class:`pipeline.trouble.Trouble` with the north-finding kinds."""

    def __init__(self) -> None:
        super().__init__(TROUBLE_KINDS)


def n_case(n_avg: int) -> str:
    """The ``case`` of a run at averaging count ``n_avg``.

    >>> n_case(100)
    'N=100'
    """
    return f"N={int(n_avg)}"
