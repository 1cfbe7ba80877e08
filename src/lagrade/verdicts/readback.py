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
from sympy.printing.latex import LatexPrinter
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


def _clip(text: str) -> str:
    return text if len(text) <= MAX_CHARS else text[:MAX_CHARS] + " …"


#: what is shown of a value no printer could print (a number past Python's int-to-text limit, which the
#: readers keep answers far below: lagrade.problem.limits.MAX_NUMBER_DIGITS)
UNPRINTABLE = "(too large to show)"


def _plain(value: object) -> str:
    """``str(value)``, clipped; never an exception: printing must never stop grading."""
    try:
        return _clip(str(value))
    except Exception:  # noqa: BLE001
        return UNPRINTABLE


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
    # a name of several letters that is not a Greek letter is upright (\mathrm{phip}): bare, it reads
    # back as a product of letters, and \dot{phip} not at all
    head = f"\\{head}" if head in _GREEK_LATEX and len(head) > 1 else (
        f"\\mathrm{{{head}}}" if len(head) > 1 else head)
    tail = f"\\{tail}" if tail in _GREEK_LATEX and len(tail) > 1 else tail
    return f"{head}_{{{tail}}}" if tail else head


def _time_function(expr: sp.Basic) -> str | None:
    """The name of q in q(t) (a coordinate), else None."""
    return expr.func.__name__ if isinstance(expr, AppliedUndef) and expr.args == (_T,) else None


def _time_derivative(expr: sp.Derivative) -> tuple[str, int] | None:
    """(name of q, order) for a derivative of q(t) in t only, else None."""
    name = _time_function(expr.expr)
    if name is None or not all(v == _T for v in expr.variables):
        return None
    return name, len(expr.variables)


#: (sum, order) -> its terms in printing order, shared by the two printers: sympy's ordering (``as_terms``,
#: a float of every coefficient) is a third of a read-back's cost, and both print the same sums
_ORDERED: dict[tuple[sp.Basic, str | None], list[sp.Basic]] = {}
_ORDERED_MAX = 4096


class _Notation:
    """Prints q(t), q'(t), q''(t) in the book's notation while printing, not by rebuilding the
    expression with symbols (which re-evaluates every product and sum it touches: tens of
    milliseconds for a Lagrangian, on every check)."""

    def _as_ordered_terms(self, expr: sp.Basic, order: str | None = None) -> list[sp.Basic]:
        order = order or self.order
        if order in ("old", "none"):
            return super()._as_ordered_terms(expr, order)
        key = (expr, order)  # a function of the sum's structure alone (equal sums print alike)
        terms = _ORDERED.get(key)
        if terms is None:
            if len(_ORDERED) >= _ORDERED_MAX:
                _ORDERED.clear()
            terms = _ORDERED[key] = expr.as_ordered_terms(order=order)
        return list(terms)

    def _notation(self, name: str, order: int) -> str:
        raise NotImplementedError

    def _print_Derivative(self, expr: sp.Derivative) -> str:
        hit = _time_derivative(expr)
        return self._notation(*hit) if hit else super()._print_Derivative(expr)

    def _print_Function(self, expr: sp.Basic, exp: str | None = None) -> str:
        name = _time_function(expr)
        if name is None:
            return super()._print_Function(expr, exp) if exp is not None else super()._print_Function(expr)
        text = self._notation(name, 0)
        return text if exp is None else f"{text}^{{{exp}}}"  # LaTeX's power of a function


class _UnicodeLine(_Notation, _OneLine):
    def _notation(self, name: str, order: int) -> str:
        accent = {1: "\u0307", 2: "\u0308"}.get(order, "")
        return _unicode_name(name, accent) + ("" if accent or not order else f"^({order})")

    def _print_Symbol(self, expr: sp.Symbol) -> str:
        return _unicode_name(expr.name)


class _Latex(_Notation, LatexPrinter):
    def _print_Symbol(self, expr: sp.Symbol, style: str = "plain") -> str:
        # a function of the name and style alone (and of the printer's fixed settings): each is worked out once
        texts = self.__dict__.setdefault("_symbol_texts", {})
        key = (expr.name, style)
        text = texts.get(key)
        if text is None:
            if len(texts) >= _ORDERED_MAX:
                texts.clear()
            text = texts[key] = self._symbol_text(expr, style)
        return text

    def _symbol_text(self, expr: sp.Symbol, style: str) -> str:
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", expr.name):  # already LaTeX (the notation's \dot{x})
            return super()._print_Symbol(expr, style)
        name = _latex_name(expr.name)  # eps as \mathrm{eps}, not the product e p s
        return name if "\\mathrm" in name else super()._print_Symbol(expr, style)

    def _notation(self, name: str, order: int) -> str:
        base = _latex_name(name)
        if not order:
            return self._print(sp.Symbol(base))
        accent = {1: "\\dot", 2: "\\ddot"}.get(order)
        return self._print(sp.Symbol(f"{accent}{{{base}}}" if accent else f"{base}^{{({order})}}"))


_UNICODE = _UnicodeLine()
_LATEX = _Latex({"inv_trig_style": "full"})  # \arccos, which the LaTeX reader reads back


def _key(k: object) -> str:
    return str(getattr(k, "name", None) or getattr(getattr(k, "func", None), "__name__", None) or k)


def as_unicode(value: object) -> str:
    if isinstance(value, (bool, int, str)):
        return repr(value)
    try:
        show = lambda v: _UNICODE.doprint(sp.sympify(v))  # noqa: E731
        if isinstance(value, dict):
            return _clip("\n".join(f"{_key(k)}: {show(v)}" for k, v in value.items()))
        if isinstance(value, (list, tuple)):
            return _clip("\n".join(show(v) for v in value))
        return _clip(show(value))
    except Exception:  # noqa: BLE001  (printing must never stop grading)
        return _plain(value)


def as_latex(value: object) -> str:
    if isinstance(value, bool):
        return r"\text{" + str(value) + "}"
    if isinstance(value, (int, str)):
        return str(value)
    try:
        show = lambda v: _LATEX.doprint(sp.sympify(v))  # noqa: E731
        if isinstance(value, dict):
            return _clip(r",\quad ".join(rf"\text{{{_key(k)}}}: {show(v)}" for k, v in value.items()))
        if isinstance(value, (list, tuple)):
            return _clip(r",\quad ".join(show(v) for v in value))
        return _clip(show(value))
    except Exception:  # noqa: BLE001
        return _plain(value)
