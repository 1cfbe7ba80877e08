"""A student's value as a dictionary key that is equal only for the same value.

A grader keeps what it worked out for a value (its verdict, its text) so that the same value handed
in again costs a lookup. That is only right if two keys are equal exactly when the values are the
same to every consumer: sympy's equality is structural and exact (a Float is not the Integer of its
value, nor itself at another precision; a symbol's assumptions count), but Python's is not (``True
== 1 == 1.0``, ``-0.0 == 0.0``, a list equals nothing of another type but a tuple can look like it),
so Python scalars and containers are tagged with their type.
"""

from __future__ import annotations

from typing import Any

import sympy as sp


def value_key(value: Any) -> Any:
    """``value`` as a hashable key, or None when it is not one lagrade can key exactly (a mutable
    Matrix, an unknown object): the caller then works it out afresh."""
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, sp.MatrixBase):  # a mutable Matrix: keyed by its entries, as what it is
        return (type(value).__name__, value.as_immutable())
    if isinstance(value, (bool, int, str)):
        return (type(value).__name__, value)
    if isinstance(value, float):
        return ("float", value.hex())  # -0.0 and 0.0 differ; every NaN is one key
    if isinstance(value, (list, tuple)):
        items = [value_key(v) for v in value]
        return None if any(i is None for i in items) else (type(value).__name__, *items)
    if isinstance(value, dict):
        pairs = [(value_key(k), value_key(v)) for k, v in value.items()]  # in order: it may be shown so
        return None if any(k is None or v is None for k, v in pairs) else ("dict", *pairs)
    return None
