"""Showing an answer the way lagrade understood it, before it is graded.

A student who sees ``θ̇²`` where they meant ``θ̇``, or a stray symbol, knows at once what went
wrong; velocities print with dots (θ̇, θ̈) as in the book. Unicode for the terminal, LaTeX for JSON
and HTML.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.vector.printing import VectorPrettyPrinter, vlatex

MAX_CHARS = 1500


def _clip(text: str) -> str:
    return text if len(text) <= MAX_CHARS else text[:MAX_CHARS] + " …"


def _greek(name: str) -> str:
    from sympy.printing.pretty.pretty_symbology import greek_unicode

    return "".join(greek_unicode.get(part, part) for part in __import__("re").split(r"(\d+)", name))


def _momenta_readable(expr: sp.Basic) -> sp.Basic:
    """``p_theta(t)`` and its rate print as p_θ and ṗ_θ rather than letter-by-letter subscripts."""
    mapping: dict[sp.Basic, sp.Basic] = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        if getattr(f.func, "__name__", "").startswith("p_") and len(d.variables) == 1:
            mapping[d] = sp.Symbol("\u1e57_" + _greek(f.func.__name__[2:]))
    expr = expr.xreplace(mapping) if mapping else expr
    mapping = {}
    for a in expr.atoms(sp.Function, sp.Symbol):
        name = getattr(a, "name", None) or getattr(a.func, "__name__", "")
        if name.startswith("p_") and (a.is_Symbol or a.args == (sp.Symbol("t"),)):
            mapping[a] = sp.Symbol("p_" + _greek(name[2:]))
    return expr.xreplace(mapping) if mapping else expr


def _structure(value: object) -> object:
    if isinstance(value, dict):
        return {str(getattr(k, "name", getattr(getattr(k, "func", None), "__name__", k))): _structure(v)
                for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_structure(v) for v in value]
    return value


def as_unicode(value: object) -> str:
    if isinstance(value, (bool, int, str)):
        return repr(value)
    value = _structure(value)
    try:
        printer = VectorPrettyPrinter({"use_unicode": True, "wrap_line": False})
        show = lambda v: printer.doprint(_momenta_readable(sp.sympify(v)))  # noqa: E731
        if isinstance(value, dict):
            return _clip("\n".join(f"{k}: {show(v)}" for k, v in value.items()))
        if isinstance(value, list):
            return _clip("\n".join(show(v) for v in value))
        return _clip(show(value))
    except Exception:  # noqa: BLE001  (printing must never stop grading)
        return _clip(str(value))


def as_latex(value: object) -> str:
    if isinstance(value, bool):
        return r"\text{" + str(value) + "}"
    if isinstance(value, (int, str)):
        return str(value)
    value = _structure(value)
    try:
        if isinstance(value, dict):
            return _clip(r",\quad ".join(rf"\text{{{k}}}: {vlatex(sp.sympify(v))}" for k, v in value.items()))
        if isinstance(value, list):
            return _clip(r",\quad ".join(vlatex(sp.sympify(v)) for v in value))
        return _clip(vlatex(sp.sympify(value)))
    except Exception:  # noqa: BLE001
        return _clip(str(value))
