"""Functions the book leaves general (``V(r)``, ``U(xp, yp)``), and what is substituted for them.

An identity in an undefined function cannot be sampled as it stands, and sympy cannot prove it in
general. So a part that uses one is graded several times, each time with one random smooth function
put in its place, in the reference and in the answer alike (derivatives and ``Subs`` are then
evaluated, so ``V'(r)`` is the derivative of the same function). Agreeing for every one of them is
what being right for an arbitrary V means here. Instance 0 is the concrete function the problem
states (``k*r**2/2``), for answers written with it.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from lagrade.problem.spec import GeneralFunction, System

#: random functions an answer using a general function is graded with (each a full check)
INSTANCES = 3
#: the instance that puts 0 for every general function (the free particle of U = 0, V = 0): a special
#: case an answer may be right for (`lagrade.verdicts.checkers.general`)
ZERO = -1


def arities(system: System) -> dict[str, int]:
    """The system's general functions, name -> number of arguments (what the text reader needs)."""
    return {f.name: len(f.args) for f in system.functions}


def random_function(f: GeneralFunction, instance: int) -> sp.Lambda:
    """A smooth function of ``f``'s arguments with random exact coefficients: linear, quadratic, a
    product, an exponential and a sine term, so that no sign, factor or missing derivative of the
    answer cancels by accident. Seeded by name and instance: every process draws the same ones (the
    reference cache on disk relies on it)."""
    if instance == ZERO:
        return sp.Lambda(tuple(sp.Symbol(a) for a in f.args), sp.Integer(0))
    rng = random.Random(f"lagrade general function {f.name} #{instance}")

    def coef(lo: int, hi: int, den: int = 8) -> sp.Rational:
        value = 0
        while value == 0:
            value = rng.randint(lo, hi)
        return sp.Rational(value, den)

    xs = [sp.Symbol(a) for a in f.args]
    body = sum((coef(-8, 8) * x + coef(1, 6) * x**2 for x in xs), sp.Integer(0))
    if len(xs) > 1:
        body += coef(-4, 4) * xs[0] * xs[1]
    body += coef(-6, 6) * sp.exp(sum((coef(-3, 3) * x for x in xs), sp.Integer(0)))
    body += coef(-6, 6) * sp.sin(sum((coef(2, 10) * x for x in xs), sp.Integer(0)) + coef(-8, 8))
    return sp.Lambda(tuple(xs), body)


def uses(value: object, names: Iterable[str]) -> bool:
    """Whether an answer's value (an expression, or lists and dicts of them) calls one of ``names``."""
    names = set(names)
    if not names:
        return False
    if isinstance(value, dict):
        return any(uses(v, names) or uses(k, names) for k, v in value.items())
    if isinstance(value, (list, tuple)):
        return any(uses(v, names) for v in value)
    if isinstance(value, sp.Basic):
        return any(f.func.__name__ in names for f in value.atoms(AppliedUndef))
    return False


def substitute(expr: sp.Basic, functions: Mapping[str, sp.Lambda]) -> sp.Basic:
    """``expr`` with every call of a general function replaced by its substitute, and the
    derivatives and ``Subs`` around those calls evaluated (``Derivative(V(r), r)``,
    ``Subs(Derivative(V(x), x), x, r)``); every other node is left as the author wrote it.
    A call with the wrong number of arguments is a ``ValueError`` saying so."""
    if not functions or not isinstance(expr, sp.Basic):
        return expr
    targets = {f for f in expr.atoms(AppliedUndef) if f.func.__name__ in functions}
    if not targets:
        return expr
    done: dict[sp.Basic, sp.Basic] = {}

    def walk(node: sp.Basic) -> sp.Basic:
        if node in done:
            return done[node]
        if isinstance(node, AppliedUndef) and node.func.__name__ in functions:
            lam = functions[node.func.__name__]
            if len(node.args) != len(lam.variables):
                names = ", ".join(map(str, lam.variables))
                raise ValueError(f"{node.func.__name__} is a function of {names}: it takes {len(lam.variables)} "
                                 f"argument(s), not {len(node.args)}")
            out = lam(*[walk(a) for a in node.args])
        elif node.args and any(node.has(f) for f in targets):
            out = node.func(*[walk(a) for a in node.args])
            if isinstance(node, (sp.Derivative, sp.Subs)):
                out = out.doit()
        else:
            out = node
        done[node] = out
        return out

    return walk(expr)
