"""Between an answer's form (coordinates as functions of t) and the engine's plain state symbols.

Generated answers are built and graded in the answer's form, and proved equal or not in the
symbols' (``theta``, ``theta_d``, ``p_theta``), where sympy and the exact judge work."""

from __future__ import annotations

import sympy as sp

from lagrade.problem.symbols import T


def to_answer_form(expr, names) -> object:
    """State symbols back to functions of time, as in an answer file (``theta_d`` -> theta(t)')."""
    back = {}
    for name in names:
        f = sp.Function(name)(T)
        back[sp.Symbol(name)] = f
        back[sp.Symbol(f"{name}_d")] = f.diff(T)
        back[sp.Symbol(f"{name}_dd")] = f.diff(T, 2)
        back[sp.Symbol(f"p_{name}")] = sp.Function(f"p_{name}")(T)
        back[sp.Symbol(f"p_{name}_d")] = sp.Function(f"p_{name}")(T).diff(T)
    return expr.xreplace(back) if isinstance(expr, sp.Basic) else expr


def to_symbols(expr) -> object:
    """An answer-form value in plain symbols: q(t)'' -> q_dd, q(t)' -> q_d, q(t) -> q; assumptions
    dropped (names are what answers are matched by)."""
    if not isinstance(expr, sp.Basic):
        return expr
    subs = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        if isinstance(f, sp.core.function.AppliedUndef) and d.variables and all(getattr(v, 'name', None) == 't' for v in d.variables):
            n = len(d.variables)
            subs[d] = sp.Symbol(f.func.__name__ + "_" + "d" * n)
    out = expr.xreplace(subs)
    funcs = {f: sp.Symbol(f.func.__name__) for f in out.atoms(sp.core.function.AppliedUndef)
             if len(f.args) == 1 and getattr(f.args[0], 'name', None) == 't'}
    out = out.xreplace(funcs)
    plain = {s: sp.Symbol(s.name) for s in out.free_symbols if isinstance(s, sp.Symbol) and s.name != "t"}
    plain[T] = sp.Symbol("t")
    return out.xreplace(plain)
