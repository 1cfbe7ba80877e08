"""The answers layer; importing it gives what a student may use in ``answer.py``:
``from lagrade.answer import *``.

The package's submodules are the layer's machinery: ``jail/`` runs an ``answer.py`` where it cannot
harm, ``reading/`` reads an answer file into values. An answer in the jail is handed this module's
``__all__`` alone (``jail.child._vocabulary``), never the package with its submodules.

They exist so that an answer file needs no boilerplate beyond its physics: the time symbol,
coordinates as functions of time, and parameters as plain symbols matched by name.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import sympy as sp
    from sympy import *  # noqa: F401,F403


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

_OWN = ["t", "coordinates", "parameters", "momenta", "dot"]


def _load() -> None:
    """Bind sympy's names here (``from sympy import *``), ``t`` and ``__all__``, on first use: a
    check starts its jail's zygote by importing :mod:`lagrade.answer.jail.zygote`, which must not
    wait for sympy first (the zygote's own import of sympy then runs beside this process's;
    docs/performance.md)."""
    import sympy

    space = globals()
    for name in sympy.__all__:
        if name not in _OWN:
            space.setdefault(name, getattr(sympy, name))
    space["sp"] = sympy
    space["t"] = sympy.Symbol("t")
    space["__all__"] = [n for n in sympy.__all__ if n not in _ANSWER_NAMES] + _OWN


def __getattr__(name: str) -> Any:
    """PEP 562: the first name asked for (``t``, a sympy name, ``__all__`` of a star import) loads
    them all; a submodule (``jail``, ``reading``) is imported as usual."""
    if name.startswith("__") and name != "__all__":
        raise AttributeError(name)
    if "__all__" not in globals():
        _load()
        if name in globals():
            return globals()[name]
    raise AttributeError(f"module 'lagrade.answer' has no attribute '{name}'")
