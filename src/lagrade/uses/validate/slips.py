"""Wrong answers generated from a reference: the reference with one slip each.

Each term's sign flipped, each term dropped, a factor 2 or 1/2 on each term, sin and cos swapped,
two parameters swapped, an exponent changed, one equation replaced by another; a boolean negated,
a count off by one, a name left out. A slip can leave the answer right (a dropped constant term of
a Lagrangian, two masses swapped in a symmetric formula): :mod:`lagrade.uses.validate.proofs`
decides which, and those are dropped with their proof rather than counted as wrong.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import combinations

import sympy as sp

from lagrade.uses.validate.forms import EQUATIONS, _leaves, _sides

Slip = tuple[str, object]

#: kinds whose value is one expression
SCALAR = ("lagrangian", "hamiltonian", "expression", "equation_root")


def _term_slips(e: sp.Expr, where: str) -> Iterator[tuple[str, sp.Expr]]:
    terms = sp.Add.make_args(sp.expand(e))
    for i, term in enumerate(terms):
        tag = f"{where}term {i + 1} ({_short(term)})"
        yield f"{tag}: sign flipped", e - 2 * term
        if len(terms) > 1:
            yield f"{tag}: dropped", e - term
        yield f"{tag}: times 2", e + term
        yield f"{tag}: times 1/2", e - term / 2


def _short(term: sp.Expr) -> str:
    text = sp.sstr(term)
    return text if len(text) <= 40 else text[:37] + "..."


def _swap_trig(e: sp.Expr) -> sp.Expr:
    s, c = sp.Function("_s"), sp.Function("_c")
    return e.replace(sp.sin, s).replace(sp.cos, c).replace(s, sp.cos).replace(c, sp.sin)


def _structural_slips(e: sp.Expr, params: list[sp.Symbol], where: str) -> Iterator[tuple[str, sp.Expr]]:
    if e.has(sp.sin) or e.has(sp.cos):
        yield f"{where}sin and cos swapped", _swap_trig(e)
    used = [p for p in params if e.has(p)]
    for a, b in list(combinations(used, 2))[:6]:
        yield f"{where}{a} and {b} swapped", e.xreplace({a: b, b: a})
    pows = sorted({p for p in e.atoms(sp.Pow) if p.exp.is_Integer and p.exp not in (0, 1)}, key=sp.default_sort_key)
    for p in pows[:4]:
        yield f"{where}exponent of {_short(p.base)} {p.exp} -> {p.exp + 1}", e.xreplace({p: p.base ** (p.exp + 1)})


def _params_of(value: object, parameters: list[str]) -> list[sp.Symbol]:
    wanted = set(parameters)
    found = {s for leaf in _leaves(value) for s in leaf.free_symbols
             if isinstance(s, sp.Symbol) and s.name in wanted}
    return sorted(found, key=lambda s: s.name)


def wrong_answers(kind: str, value: object, parameters: list[str]) -> list[Slip]:
    """Answers of ``kind`` one slip away from the reference ``value``."""
    params = _params_of(value, parameters)
    out: list[Slip] = []
    if kind in SCALAR and isinstance(value, sp.Expr):
        out += list(_term_slips(value, ""))
        out += list(_structural_slips(value, params, ""))
    elif kind in SCALAR and isinstance(value, sp.Equality):  # equation_root given as an equation
        lhs, rhs = value.lhs, value.rhs
        out += [(label, sp.Eq(lhs, w, evaluate=False)) for label, w in _term_slips(rhs, "right side ")]
    elif kind == "expression" and isinstance(value, dict):
        for key, v in value.items():
            if isinstance(v, sp.Expr):
                slips = [*_term_slips(v, f"{key}: "), *_structural_slips(v, params, f"{key}: ")]
                out += [(label, {**value, key: w}) for label, w in slips]
    elif kind in EQUATIONS + ("reduced",) and isinstance(value, list) and value and all(
            isinstance(v, (sp.Equality, sp.Expr)) for v in value):
        out += _equation_slips(value, params)
    elif kind == "expression_set" and isinstance(value, list):
        for i, v in enumerate(value):
            if isinstance(v, sp.Expr):
                out += [(f"item {i + 1}: {label}", [*value[:i], w, *value[i + 1:]])
                        for label, w in [*_term_slips(v, ""), *_structural_slips(v, params, "")]]
    elif kind == "boolean" and isinstance(value, bool):
        out.append(("negated", not value))
    elif kind == "integer" and isinstance(value, int) and not isinstance(value, bool):
        out += [("one more", value + 1), ("one less", value - 1)]
    elif kind == "names" and isinstance(value, list):
        out += [(f"{v} left out", [*value[:i], *value[i + 1:]]) for i, v in enumerate(value)]
    return out


def _equation_slips(eqs: list, params: list[sp.Symbol]) -> list[Slip]:
    out: list[Slip] = []
    n = len(eqs)
    for i, eq in enumerate(eqs):
        lhs, rhs = _sides(eq)
        tag = f"equation {i + 1}, " if n > 1 else ""

        def at(new, i=i):
            return [*eqs[:i], new, *eqs[i + 1:]]

        side, which = (rhs, "right") if rhs != 0 else (lhs, "left")
        for label, w in [*_term_slips(side, f"{tag}{which} side "), *_structural_slips(side, params, f"{tag}{which} side ")]:
            out.append((label, at(sp.Eq(lhs, w, evaluate=False) if which == "right" else sp.Eq(w, rhs, evaluate=False))))
        for j in range(n):
            if j != i:
                out.append((f"equation {i + 1} replaced by equation {j + 1}", at(eqs[j])))
    return out
