"""Pickle bytes that depend on the values only: :func:`canonical_dumps`.

pickle shares objects by identity (``id``): an object met twice is written once and referenced
after. Which equal SymPy objects are one Python object depends on SymPy's cache (a
construction that hits it returns the cached object, with the very symbols it was built from),
hence on what the process derived before and in which order; so plain pickle bytes of the same
values changed with that history (found by tests/shared/test_artefact.py after a derivation took
a cheaper route). The derivation artefact and the memo snapshot are written with it.

>>> import pickle, sympy as sp
>>> x = sp.Symbol("x")
>>> one = sp.sin(x) + 1
>>> sp.core.cache.clear_cache()  # as if the process had taken another route to it
>>> other = sp.sin(x) + 1
>>> one == other, one is other
(True, False)
>>> pickle.dumps([one, one], 4) == pickle.dumps([one, other], 4)
False
>>> canonical_dumps([one, one], 4) == canonical_dumps([one, other], 4)
True
>>> pickle.loads(canonical_dumps([one, other], 4)) == [one, one]
True
"""

from __future__ import annotations

import io
import pickle
from typing import Any

import sympy as sp

__all__ = ["canonical_dumps"]


class _CanonicalPickler(pickle._Pickler):
    """A pickler that writes every SymPy object and string once per value: an object equal to one
    already written (SymPy's structural equality: type, arguments and assumptions) is written as
    a reference to it. The pure-Python pickler writes what the C one writes for the same
    objects."""

    def __init__(self, file: io.BytesIO, protocol: int) -> None:
        super().__init__(file, protocol=protocol)
        self._canonical: dict[sp.Basic, sp.Basic] = {}
        self._strings: dict[str, str] = {}

    def save(self, obj: Any, save_persistent_id: bool = True) -> None:
        if isinstance(obj, sp.Basic):
            obj = self._canonical.setdefault(obj, obj)
        elif type(obj) is str:  # likewise strings (an interned name or a copy of it)
            obj = self._strings.setdefault(obj, obj)
        super().save(obj, save_persistent_id)


def canonical_dumps(obj: Any, protocol: int) -> bytes:
    """``obj`` pickled with ``protocol``, each SymPy value and string written once."""
    buffer = io.BytesIO()
    _CanonicalPickler(buffer, protocol).dump(obj)
    return buffer.getvalue()
