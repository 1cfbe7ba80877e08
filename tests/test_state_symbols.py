"""Reading students' coordinates, rates and symbols into the engine's plain state symbols."""

from __future__ import annotations

import pytest
import sympy as sp
from expression_strategies import expressions
from hypothesis import given, settings
from sympy.core.function import AppliedUndef

from lagrade.problem.symbols import NotationError, nodes_of, to_state


def test_coordinates_rates_and_assumptions_read_in_one_pass():
    t = sp.Symbol("t", real=True)  # a student's t with assumptions is still time
    m, l = sp.symbols("m l", positive=True)
    th = sp.Function("theta")(t)
    expr = m * l**2 * th.diff(t) ** 2 / 2 + m * l * sp.cos(th) + th.diff(t, 2) * th
    out = to_state(expr, ["theta"])
    theta, theta_d, theta_dd, M, L = sp.symbols("theta theta_d theta_dd m l")
    assert out == M * L**2 * theta_d**2 / 2 + M * L * sp.cos(theta) + theta_dd * theta
    assert all(s == sp.Symbol(s.name) for s in out.free_symbols)  # no assumptions left


def test_momenta_are_read_only_when_asked():
    t = sp.Symbol("t")
    p = sp.Function("p_x")(t)
    assert to_state(p.diff(t) + p, ["x"], momenta_too=True) == sp.Symbol("p_x_d") + sp.Symbol("p_x")
    with pytest.raises(NotationError, match="unknown function p_x"):
        to_state(p, ["x"])


@pytest.mark.parametrize("make, message", [
    (lambda t, x: sp.Function("y")(t), "unknown function y"),
    (lambda t, x: x.diff(t, 3), "order 3"),
    (lambda t, x: sp.Function("y")(t).diff(t), "cannot read the derivative"),
    (lambda t, x: sp.Function("x")(sp.Symbol("s")), "unknown function x"),
    (lambda t, x: sp.Function("x")(t, sp.Symbol("s")).diff(sp.Symbol("s")), "cannot read the derivative"),
])
def test_what_cannot_be_read_says_why(make, message):
    t = sp.Symbol("t")
    with pytest.raises(NotationError, match=message):
        to_state(make(t, sp.Function("x")(t)) + 1, ["x"])


def _sympys_nodes(expr):
    return ({s for s in expr.free_symbols if isinstance(s, sp.Symbol)}, expr.atoms(sp.Derivative),
            expr.atoms(AppliedUndef))


@settings(max_examples=300, deadline=None, derandomize=True)
@given(expr=expressions)
def test_one_walk_finds_the_free_symbols_derivatives_and_functions_sympy_finds(expr):
    nodes = nodes_of(expr)
    assert (nodes.symbols, nodes.derivatives, nodes.applied) == _sympys_nodes(expr)


@pytest.mark.parametrize("make", [
    lambda t, x, s: sp.Derivative(x, s),  # s is bound: not free in the derivative
    lambda t, x, s: sp.Derivative(x * s, s) + s,
    lambda t, x, s: sp.Derivative(x, (t, 2)) * sp.Derivative(x, t),
    lambda t, x, s: sp.Integral(x * s, (s, 0, 1)),  # integrals and the rest: sympy is asked
    lambda t, x, s: sp.Subs(x * s, s, 2) + sp.Derivative(x, t),
    lambda t, x, s: sp.Derivative(sp.Function("f")(x), x),  # by a function: sympy is asked
    lambda t, x, s: sp.Piecewise((x, s > 0), (s, True)),
    lambda t, x, s: x * s + sp.Function("y")(t, s) + sp.Dummy("d"),
])
def test_one_walk_agrees_with_sympy_on_bound_and_unusual_variables(make):
    t, s = sp.symbols("t s")
    expr = make(t, sp.Function("x")(t), s)
    nodes = nodes_of(expr)
    assert (nodes.symbols, nodes.derivatives, nodes.applied) == _sympys_nodes(expr)
