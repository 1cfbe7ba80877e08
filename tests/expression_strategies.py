"""Hypothesis strategies for the sympy values answers carry: symbols with assumptions, coordinates
q(t) and their derivatives, exact and float numbers, the chapter's functions, equations."""

from __future__ import annotations

import sympy as sp
from hypothesis import strategies as st

t = sp.Symbol("t")

symbols = st.sampled_from([
    sp.Symbol("m"), sp.Symbol("g"), sp.Symbol("l_1"), sp.Symbol("p_theta"),
    sp.Symbol("k", positive=True), sp.Symbol("x", real=True), sp.Symbol("theta_0", nonzero=True),
])
coords = st.sampled_from(["theta", "phi", "r", "q1"]).map(lambda n: sp.Function(n)(t))
derivs = st.tuples(coords, st.integers(1, 3)).map(lambda c: c[0].diff(t, c[1]))
rationals = st.fractions(max_denominator=10**6).map(lambda f: sp.Rational(f.numerator, f.denominator))
floats = st.floats(allow_nan=False, allow_infinity=False, width=64).map(sp.Float)
big_ints = st.integers(-10**12, 10**12).map(sp.Integer)
leaves = st.one_of(symbols, coords, derivs, rationals, floats, big_ints,
                   st.sampled_from([sp.pi, sp.E, sp.I, sp.oo, -sp.oo, sp.S.Half, t]))
unary = [sp.sin, sp.cos, sp.tan, sp.exp, sp.log, sp.sqrt, sp.Abs, sp.asin, sp.atan, sp.cosh, sp.sign]


def _power(base, exp):
    # exact powers of numbers explode in size (and are refused by design); keep them symbolic
    return base**exp if base.free_symbols else base


def _safely(build):
    """``build`` as a strategy map, where sympy refusing to build (atan2 of an expression that makes
    it compare NaN, say) skips the example rather than failing the test while generating it."""
    def run(args):
        try:
            return build(*args) if isinstance(args, tuple) else build(args)
        except (TypeError, ValueError, ZeroDivisionError):
            return None
    return run


def combine(children):
    return st.one_of(
        st.tuples(children, children).map(_safely(lambda a, b: a + b)),
        st.tuples(children, children).map(_safely(lambda a, b: a * b)),
        st.tuples(children, st.integers(-4, 4)).map(_safely(_power)),
        # small exponents only: sympy itself can spend minutes expanding (2*x)**(p/q) with huge p, q
        st.tuples(children, st.sampled_from([sp.Rational(1, 2), sp.Rational(-1, 3), sp.Rational(5, 2)])
                  ).map(_safely(_power)),
        st.tuples(st.sampled_from(unary), children).map(_safely(lambda f, e: f(e))),
        st.tuples(children, children).map(_safely(sp.atan2)),
        children.map(_safely(lambda e: sp.Derivative(e, t))),
    ).filter(lambda e: e is not None)


terms = st.recursive(leaves, combine, max_leaves=12)
expressions = st.one_of(terms, st.tuples(terms, terms).map(_safely(lambda a, b: sp.Eq(a, b, evaluate=False)))
                        ).filter(lambda e: e is not None)


#: sympy's own srepr, and the sandbox child's (terms in the object's order, not sorted for printing)
