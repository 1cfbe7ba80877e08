"""How a student's answer is shown in the gradebook: as text, and as presentation MathML for the report.

Both are made in the grader for every part of every file, so their cost is part of a class's: with
sympy's own printers it was about a fifth of what lagrade spends per file when the answers differ.
Three things made them slow: sympy's MathML printer builds an ``xml.dom.minidom`` tree and
serialises it, both printers sort the terms of every sum (``as_ordered_terms``), each on its own,
and answers that differ are printed whole though they share most of their terms. Here the MathML
printer builds the same markup as strings, the two printers share one ordering of each sum, and
what is printed is kept per process: a value's text and MathML, and those of every compound
subexpression. The text is exactly ``str(value)``; the MathML is sympy's, except that coordinates
are written as a physicist writes them.
"""

from __future__ import annotations

from html import escape
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.mathml import MathMLPresentationPrinter
from sympy.printing.printer import Printer
from sympy.printing.str import StrPrinter

from lagrade.answer.reading.value_key import value_key

#: answers whose text is longer get no MathML (and their text is cut): a report is read, not parsed
MATHML_MAX_CHARS = 4000

_T = sp.Symbol("t")
_DOTS = {1: "&#729;", 2: "&#168;"}  # a dot, two dots

class _Kept(dict):
    """What was printed, by key, in this process: the oldest dropped first past ``entries`` of them
    or ``chars`` characters in all (one longer than that alone is not kept: it would push out the rest)."""

    def __init__(self, entries: int, chars: int | None = None) -> None:
        super().__init__()
        self.entries, self.max_chars, self.chars = entries, chars, 0

    def keep(self, key: Any, printed: str | None) -> None:
        size = len(printed or "")
        if self.max_chars is not None and size > self.max_chars:
            return
        self[key] = printed
        self.chars += size
        while len(self) > self.entries or (self.max_chars is not None and self.chars > self.max_chars):
            self.chars -= len(self.pop(next(iter(self))) or "")

    def printed(self, key: Any, make) -> str:
        """``make()``, printed once per key."""
        printed = self.get(key)
        if printed is None:
            printed = make()
            self.keep(key, printed)
        return printed

    def clear(self) -> None:
        super().clear()
        self.chars = 0


_CACHE_ENTRIES = 1024  # each, per process
#: MathML by the answer's type and text (a class hands in many identical answers)
_MATHML = _Kept(_CACHE_ENTRIES)
#: text by the value itself (`value_key`): answers written differently are often the same value once
#: sympy has put them in its canonical form
_TEXT = _Kept(_CACHE_ENTRIES)
#: text and MathML of the compound subexpressions of values: answers that differ still share most of
#: their terms (an extra term in L, an equation times a constant). Atoms are printed each time: sympy
#: prints a Float alone at full precision, inside a compound without trailing zeros (the only place
#: its printers look at the depth). About 16 MB of text per grader at most.
_PART_TEXT = _Kept(8192, chars=8_000_000)
_PART_MATHML = _Kept(8192, chars=8_000_000)


def _compound(expr: Any, kwargs: dict) -> bool:
    """A sympy object with arguments, printed with nothing but itself to go on."""
    return not kwargs and isinstance(expr, sp.Basic) and bool(expr.args)


def show(value: Any) -> tuple[str | None, str | None]:
    """The value as text and as presentation MathML (None when too large or unprintable)."""
    ordered: dict = {}
    key = value_key(value)
    text = _TEXT.get(key) if key is not None else None
    if text is None:
        try:
            text = _text(value, _Text(ordered))
        except Exception:  # noqa: BLE001  (a value sympy cannot print is shown as nothing, not a failure)
            return None, None
        if key is not None:
            _TEXT.keep(key, text)
    if len(text) > MATHML_MAX_CHARS:
        return text[:MATHML_MAX_CHARS] + " ...", None
    key = (type(value).__name__, text)
    if key in _MATHML:
        return text, _MATHML[key]
    try:
        rendered = _mathml(value, _PhysicsMathML(ordered))
    except Exception:  # noqa: BLE001
        rendered = None
    _MATHML.keep(key, rendered)
    return text, rendered


# ----------------------------------------------------------------------------- text


class _Text(StrPrinter):
    """``str`` of a sympy value, sharing its ordering of sums with the MathML printer."""

    def __init__(self, ordered: dict) -> None:
        super().__init__()
        self._ordered = ordered

    def _as_ordered_terms(self, expr, order=None):
        return _ordered_terms(self, expr, order)

    def _print(self, expr, **kwargs):
        if not _compound(expr, kwargs):
            return super()._print(expr, **kwargs)
        return _PART_TEXT.printed(expr, lambda: super(_Text, self)._print(expr))


def _text(value: Any, printer: _Text, nested: bool = False) -> str:
    """What ``str(value)`` gives. A sympy object's ``repr`` is its ``str``: sympy's string printer
    with the default order; a container shows its items with ``repr``."""
    if isinstance(value, sp.Basic):
        return printer.doprint(value)
    if isinstance(value, list):
        return "[" + ", ".join(_text(v, printer, True) for v in value) + "]"
    if isinstance(value, tuple):
        inner = ", ".join(_text(v, printer, True) for v in value)
        return f"({inner},)" if len(value) == 1 else f"({inner})"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_text(k, printer, True)}: {_text(v, printer, True)}" for k, v in value.items()) + "}"
    return repr(value) if nested else str(value)


def _ordered_terms(printer, expr, order):
    """The terms of a sum in print order, sorted once for both printers (sorting is most of printing)."""
    key = (expr, order or printer.order)
    terms = printer._ordered.get(key)
    if terms is None:
        terms = printer._ordered[key] = Printer._as_ordered_terms(printer, expr, order)
    return terms


# ----------------------------------------------------------------------------- MathML


def _mathml(value: Any, printer: _PhysicsMathML) -> str:
    if isinstance(value, (list, tuple)):
        return "<mrow><mo>[</mo>" + "<mo>,</mo>".join(_mathml(x, printer) for x in value) + "<mo>]</mo></mrow>"
    if isinstance(value, dict):
        items = [f"<mrow>{_mathml(k, printer) if not isinstance(k, str) else '<mi>' + escape(k, quote=False) + '</mi>'}"
                 f"<mo>:</mo>{_mathml(x, printer)}</mrow>" for k, x in value.items()]
        return "<mrow><mo>{</mo>" + "<mo>,</mo>".join(items) + "<mo>}</mo></mrow>"
    if isinstance(value, bool):
        return f"<mi>{value}</mi>"
    if isinstance(value, str):
        return f"<mtext>{escape(value, quote=False)}</mtext>"
    return printer.doprint(sp.sympify(value) if isinstance(value, (int, float)) else value)


class _PhysicsMathML(MathMLPresentationPrinter):
    """sympy's presentation MathML, built as strings, with a coordinate q(t) written q and its first
    and second time derivatives with one and two dots over it."""

    def __init__(self, ordered: dict) -> None:
        super().__init__()
        self.dom = _Markup()
        self._ordered = ordered

    def _as_ordered_terms(self, expr, order=None):
        return _ordered_terms(self, expr, order)

    def _print(self, expr, **kwargs):
        if not _compound(expr, kwargs):
            return super()._print(expr, **kwargs)
        # kept as markup: sympy's printer only appends what it gets to elements of its own
        return _RawText(_PART_MATHML.printed(expr, lambda: super(_PhysicsMathML, self)._print(expr).toxml()))

    def _print_AppliedUndef(self, e):
        if e.args == (_T,):
            return self._print(sp.Symbol(e.func.__name__))
        return self._print_Function(e)

    def _print_Derivative(self, e):
        if not _dotted(e):
            return super()._print_Derivative(e) if isinstance(e, sp.Derivative) else self._print_AppliedUndef(e)
        over = self.dom.createElement("mover")
        over.setAttribute("accent", "true")
        over.appendChild(self._print(sp.Symbol(e.expr.func.__name__)))
        dots = self.dom.createElement("mo")
        dots.appendChild(self.dom.createTextNode(_DOTS[e.derivative_count]))
        over.appendChild(dots)
        return over

    def parenthesize(self, item, level, strict=False):
        # q, q-dot and q-double-dot are single symbols to the reader: (q-dot)^2 would look odd
        if _dotted(item) or (isinstance(item, AppliedUndef) and item.args == (_T,)):
            return self._print(item)
        return super().parenthesize(item, level, strict)


def _dotted(e: Any) -> bool:
    """A first or second time derivative of a coordinate q(t)."""
    return (isinstance(e, sp.Derivative) and isinstance(e.expr, AppliedUndef) and e.expr.args == (_T,)
            and e.derivative_count in _DOTS and all(v == _T for v, _ in e.variable_count))


class _Element:
    """The part of ``xml.dom.minidom`` that sympy's MathML printer uses, serialised the same way."""

    __slots__ = ("tag", "attributes", "children")

    def __init__(self, tag: str) -> None:
        self.tag, self.attributes, self.children = tag, None, []

    def appendChild(self, node):  # noqa: N802  (minidom's name, which sympy calls)
        self.children.append(node)
        return node

    def setAttribute(self, name: str, value: Any) -> None:  # noqa: N802
        if self.attributes is None:
            self.attributes = {}
        self.attributes[name] = value

    def write(self, out: list[str]) -> None:
        head = self.tag
        if self.attributes:
            head += "".join(f' {k}="{_attribute(v)}"' for k, v in self.attributes.items())
        if not self.children:
            out.append(f"<{head}/>")
            return
        out.append(f"<{head}>")
        for child in self.children:
            child.write(out)
        out.append(f"</{self.tag}>")

    def toxml(self) -> str:
        out: list[str] = []
        self.write(out)
        return "".join(out)


class _RawText:
    """Text written as it is: sympy's printer gives entities (&#952;) that must not be escaped."""

    __slots__ = ("data",)

    def __init__(self, data: str) -> None:
        self.data = data

    def write(self, out: list[str]) -> None:
        out.append(self.data)

    def toxml(self) -> str:
        return self.data


class _Markup:
    createElement = staticmethod(_Element)  # noqa: N815
    createTextNode = staticmethod(_RawText)  # noqa: N815


def _attribute(value: Any) -> str:
    return str(value).replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;").replace(">", "&gt;")
