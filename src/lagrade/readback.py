"""Showing an answer the way lagrade understood it, before it is graded.

A student who sees ``θ̇²`` where they meant ``θ̇``, or a stray symbol, knows at once what went
wrong. Coordinates print without their ``(t)`` and velocities with dots (θ̇, θ̈), as in the book;
momenta print as p_θ. Unicode for the terminal, LaTeX for JSON and HTML. (sympy.physics.vector
has printers that do this, but importing it costs more than half a second per check; sympy's 2-D
pretty printer costs about 0.3 s on a big Lagrangian, so the terminal gets one line instead.)
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.precedence import PRECEDENCE
from sympy.printing.pretty.pretty_symbology import greek_unicode
from sympy.printing.str import StrPrinter

MAX_CHARS = 1500
_T = sp.Symbol("t")
_GREEK_LATEX = {name for name in greek_unicode if name.islower() or name[0].isupper()}


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


class _OneLine(StrPrinter):
    """Python-like text with x², √x and a middle dot: readable in a table cell, and cheap."""

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        base, exp = expr.as_base_exp()
        if exp is sp.S.Half:
            inner = self._print(base)
            return "√" + (inner if base.is_Atom else f"({inner})")
        if exp.is_Integer and exp > 0:
            return self.parenthesize(base, PRECEDENCE["Pow"], strict=False) + str(exp).translate(_SUPERSCRIPT)
        if exp.is_Integer:
            return "1/" + self._print(sp.Pow(base, -exp, evaluate=False))
        return super()._print_Pow(expr, rational).replace("**", "^")

    def _print_Equality(self, expr: sp.Eq) -> str:
        return f"{self._print(expr.lhs)} = {self._print(expr.rhs)}"

    def _print_Mul(self, expr: sp.Mul) -> str:
        return super()._print_Mul(expr).replace("*", "·")


_ONE_LINE = _OneLine({"order": "none"})


def _clip(text: str) -> str:
    return text if len(text) <= MAX_CHARS else text[:MAX_CHARS] + " …"


_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _unicode_name(name: str, accent: str = "") -> str:
    """theta1 -> θ₁, l_0 -> l₀, p_theta -> p_θ; an accent (a combining dot) sits on the letter: θ̇₁."""
    m = re.fullmatch(r"([A-Za-z]+)_?(\d+)", name)
    if m:
        return greek_unicode.get(m.group(1), m.group(1)) + accent + m.group(2).translate(_SUBSCRIPT)
    parts = re.split(r"(_|\d+)", name)
    head, rest = parts[0], parts[1:]
    return greek_unicode.get(head, head) + accent + "".join(greek_unicode.get(p, p) for p in rest)


def _latex_name(name: str) -> str:
    head, _, tail = name.partition("_")
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", head)
    if m and not tail:
        head, tail = m.group(1), m.group(2)
    head = f"\\{head}" if head in _GREEK_LATEX and len(head) > 1 else head
    tail = f"\\{tail}" if tail in _GREEK_LATEX and len(tail) > 1 else tail
    return f"{head}_{{{tail}}}" if tail else head


def _display(expr: sp.Basic, unicode: bool) -> sp.Basic:
    """Replace q(t), q'(t), q''(t) by symbols whose names print in the book's notation."""
    mapping: dict[sp.Basic, sp.Basic] = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        if isinstance(f, AppliedUndef) and f.args == (_T,) and all(v == _T for v in d.variables):
            order = len(d.variables)
            name = f.func.__name__
            if unicode:
                accent = {1: "\u0307", 2: "\u0308"}.get(order, "")
                mapping[d] = sp.Symbol(_unicode_name(name, accent) + ("" if accent else f"^({order})"))
            else:
                accent = {1: "\\dot", 2: "\\ddot"}.get(order)
                base = _latex_name(name)
                mapping[d] = sp.Symbol(f"{accent}{{{base}}}" if accent else f"{base}^{{({order})}}")
    expr = expr.xreplace(mapping) if mapping else expr
    names = {}
    for a in expr.atoms(AppliedUndef):
        if a.args == (_T,):
            names[a] = sp.Symbol(_unicode_name(a.func.__name__) if unicode else _latex_name(a.func.__name__))
    for s in expr.free_symbols:
        if unicode and isinstance(s, sp.Symbol) and _unicode_name(s.name) != s.name:
            names[s] = sp.Symbol(_unicode_name(s.name))
    return expr.xreplace(names) if names else expr


def _key(k: object) -> str:
    return str(getattr(k, "name", None) or getattr(getattr(k, "func", None), "__name__", None) or k)


def as_unicode(value: object) -> str:
    if isinstance(value, (bool, int, str)):
        return repr(value)
    try:
        show = lambda v: _ONE_LINE.doprint(_display(sp.sympify(v), True))  # noqa: E731
        if isinstance(value, dict):
            return _clip("\n".join(f"{_key(k)}: {show(v)}" for k, v in value.items()))
        if isinstance(value, (list, tuple)):
            return _clip("\n".join(show(v) for v in value))
        return _clip(show(value))
    except Exception:  # noqa: BLE001  (printing must never stop grading)
        return _clip(str(value))


def as_latex(value: object) -> str:
    if isinstance(value, bool):
        return r"\text{" + str(value) + "}"
    if isinstance(value, (int, str)):
        return str(value)
    try:
        show = lambda v: sp.latex(_display(sp.sympify(v), False))  # noqa: E731
        if isinstance(value, dict):
            return _clip(r",\quad ".join(rf"\text{{{_key(k)}}}: {show(v)}" for k, v in value.items()))
        if isinstance(value, (list, tuple)):
            return _clip(r",\quad ".join(show(v) for v in value))
        return _clip(show(value))
    except Exception:  # noqa: BLE001
        return _clip(str(value))
