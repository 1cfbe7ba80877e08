"""One naming of state variables shared by the reference and every student answer.

Students write coordinates as functions of time (``theta(t)``, ``theta(t).diff(t)``); the engine
works with plain symbols (``theta``, ``theta_d``, ``theta_dd``, ``p_theta``) so that expressions
can be differentiated as ordinary functions of the state and compiled for numpy.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.core.function import AppliedUndef

T = sp.Symbol("t")


class NotationError(ValueError):
    """An expression uses a name or a form the problem does not know."""


@dataclass(frozen=True)
class StateSymbols:
    """Plain symbols for the coordinates of one system, their rates and momenta."""

    names: tuple[str, ...]

    @property
    def q(self) -> list[sp.Symbol]:
        return [sp.Symbol(n) for n in self.names]

    @property
    def qd(self) -> list[sp.Symbol]:
        return [sp.Symbol(f"{n}_d") for n in self.names]

    @property
    def qdd(self) -> list[sp.Symbol]:
        return [sp.Symbol(f"{n}_dd") for n in self.names]

    @property
    def p(self) -> list[sp.Symbol]:
        return [sp.Symbol(f"p_{n}") for n in self.names]

    @property
    def pd(self) -> list[sp.Symbol]:
        return [sp.Symbol(f"p_{n}_d") for n in self.names]

    def functions(self) -> list[sp.Expr]:
        return [sp.Function(n)(T) for n in self.names]


def plain_symbols(expr: sp.Basic) -> sp.Basic:
    """Drop assumptions: parameters are matched by name, whatever the student assumed."""
    mapping = {s: sp.Symbol(s.name) for s in expr.free_symbols if isinstance(s, sp.Symbol) and s.assumptions0}
    return expr.xreplace(mapping) if mapping else expr


@dataclass(frozen=True)
class Nodes:
    """What reading an answer into state symbols looks for in an expression: its free symbols, its
    derivatives and its applied undefined functions (those inside derivatives too)."""

    symbols: frozenset[sp.Symbol]
    derivatives: frozenset[sp.Derivative]
    applied: frozenset[AppliedUndef]


def nodes_of(expr: sp.Basic) -> Nodes:
    """`Nodes` of ``expr`` in one walk over its distinct subexpressions.

    Reading an answer asked sympy for them one by one, each a walk of its own (``free_symbols``
    builds a set at every node): about a fifth of grading a double pendulum's answer. The walk knows
    sums, products, powers, functions, numbers, symbols and derivatives by symbols; an expression
    with anything else (integrals, substitutions, piecewise, relations ...) is asked of sympy."""
    symbols, derivatives, applied = set(), set(), set()
    seen: set[sp.Basic] = set()
    stack = [expr]
    while stack:
        node = stack.pop()
        if node in seen:
            continue
        seen.add(node)
        if node.is_Symbol:
            symbols.add(node)
        elif node.is_Atom:
            continue
        elif isinstance(node, AppliedUndef):
            applied.add(node)
            stack.extend(node.args)
        elif isinstance(node, sp.Derivative):
            if not all(v.is_Symbol for v in node.variables):
                return _nodes_by_sympy(expr)
            derivatives.add(node)
            stack.append(node.expr)  # the variables are not free in a derivative; its counts are
            stack.extend(count for _, count in node.variable_count)
        elif node.is_Add or node.is_Mul or node.is_Pow or node.is_Function:
            stack.extend(node.args)
        else:
            return _nodes_by_sympy(expr)
    return Nodes(frozenset(symbols), frozenset(derivatives), frozenset(applied))


def _nodes_by_sympy(expr: sp.Basic) -> Nodes:
    return Nodes(frozenset(s for s in expr.free_symbols if isinstance(s, sp.Symbol)),
                 frozenset(expr.atoms(sp.Derivative)), frozenset(expr.atoms(AppliedUndef)))


def to_state(expr: sp.Basic, names: Sequence[str], max_order: int = 2, momenta_too: bool = False,
             nodes: Nodes | None = None) -> sp.Basic:
    """Replace ``q(t)`` and its derivatives by ``q``, ``q_d``, ``q_dd``, and symbols with assumptions
    by plain ones (`plain_symbols`), in one `xreplace`: each pass rebuilds the whole expression.

    With ``momenta_too`` the same is done for ``p_q(t)`` (Hamilton's equations use ``p_q_d``).
    ``nodes``: `nodes_of(expr)`, if the caller has it already.
    Raises `NotationError` for unknown functions or derivatives of too high an order.
    """
    expr = sp.sympify(expr)
    nodes = nodes_of(expr) if nodes is None else nodes
    known = set(names) | ({f"p_{n}" for n in names} if momenta_too else set())
    plain = {s: sp.Symbol(s.name) for s in nodes.symbols if s.assumptions0}
    # keys are the expression's own nodes; the checks read them with plain symbols (t, real=True is t)
    mapping: dict[sp.Basic, sp.Basic] = dict(plain)
    for node in nodes.derivatives:
        d = node.xreplace(plain) if plain else node
        f = d.expr
        if not (isinstance(f, AppliedUndef) and f.args == (T,) and f.func.__name__ in known):
            raise NotationError(f"cannot read the derivative {d}: differentiate a coordinate, as {names[0]}(t).diff(t)"
                                if names else f"cannot read the derivative {d}")
        if any(v != T for v, _ in d.variable_count):
            raise NotationError(f"{d} differentiates with respect to something other than time t")
        order = sum(c for _, c in d.variable_count)
        if order > max_order:
            raise NotationError(f"{d} is a derivative of order {order}; at most {max_order} is expected here")
        mapping[node] = sp.Symbol(f.func.__name__ + ("_d" if order == 1 else "_dd"))
    for node in nodes.applied:
        f = node.xreplace(plain) if plain else node
        name = f.func.__name__
        if name in known and f.args == (T,):
            mapping[node] = sp.Symbol(name)
        else:
            raise NotationError(f"unknown function {f}; coordinates are {', '.join(f'{n}(t)' for n in names)}")
    return expr.xreplace(mapping) if mapping else expr


def unknown_names(expr: sp.Basic, allowed: Iterable[str]) -> list[str]:
    """Free symbol names of ``expr`` that the problem does not define, sorted."""
    allowed = set(allowed)
    return sorted({s.name for s in expr.free_symbols if isinstance(s, sp.Symbol)} - allowed)
