"""The answers layer; importing it gives what a student may use in ``answer.py``:
``from lagrade.answer import *``.

The package's submodules are the layer's machinery: ``jail/`` runs an ``answer.py`` where it cannot
harm, ``reading/`` reads an answer file into values. An answer in the jail is handed this module's
``__all__`` alone (``jail.child._vocabulary``), never the package with its submodules.

They exist so that an answer file needs no boilerplate beyond its physics: the time symbol,
coordinates as functions of time, and parameters as plain symbols matched by name.
"""

from __future__ import annotations

import sympy as sp
from sympy import *  # noqa: F401,F403  (re-exported so one import is enough)

t = sp.Symbol("t")


def coordinates(names: str) -> tuple[sp.Function, ...] | sp.Function:
    """``theta, phi = coordinates("theta phi")``: coordinates as functions of ``t``."""
    made = tuple(sp.Function(n)(t) for n in names.replace(",", " ").split())
    return made[0] if len(made) == 1 else made


def parameters(names: str) -> tuple[sp.Symbol, ...] | sp.Symbol:
    """``m, l, g = parameters("m l g")``: parameters are matched by name; assumptions are ignored."""
    made = tuple(sp.Symbol(n) for n in names.replace(",", " ").split())
    return made[0] if len(made) == 1 else made


def momenta(names: str) -> tuple[sp.Function, ...] | sp.Function:
    """``p_theta = momenta("p_theta")``: conjugate momenta, functions of ``t`` so that Hamilton's
    equations can be written with ``p_theta.diff(t)`` (plain symbols are accepted in ``H`` too)."""
    return coordinates(names)


def dot(q: sp.Expr, order: int = 1) -> sp.Expr:
    """Time derivative of a coordinate: ``dot(theta)`` is ``theta.diff(t)``."""
    return sp.diff(q, t, order)


#: sympy names that are also answer names (``Q`` generalized forces, ``N`` a normal force): a student
#: who star-imports and leaves such a part unanswered must get "missing", not sympy's object.
_ANSWER_NAMES = {"Q", "N"}

__all__ = [n for n in sp.__all__ if n not in _ANSWER_NAMES] + [
    "t", "coordinates", "parameters", "momenta", "dot",
]
