"""Physical domains: where each symbol of a problem lives, as the book and the scene say (m > 0,
0 < alpha < pi/2, theta' > 0 while the ring slides), kept apart from the sampling box.

Agreement at random points of the box proves two analytic expressions equal only where both are
analytic; a judge that must not be fooled by a switch folded outside the box (or refuse an honest
``sqrt(v**2)`` where v > 0) needs the domain itself. A problem file writes it as text
(:data:`WORDS` or an interval with open or closed ends, ``"(0, pi/2)"``, ``"[0, oo)"``), read here
without eval; `Problem.domains` gives a system's symbols with their `Domain`.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal

import sympy as sp
from sympy import Q

#: The named domains: a word for the common half-lines.
WORDS: dict[str, tuple[Any, Any, bool, bool]] = {
    "real": (-sp.oo, sp.oo, True, True),
    "positive": (sp.Integer(0), sp.oo, True, True),
    "nonnegative": (sp.Integer(0), sp.oo, False, True),
    "negative": (-sp.oo, sp.Integer(0), True, True),
    "nonpositive": (-sp.oo, sp.Integer(0), True, False),
}

#: What a domain may be, for the one-line error a problem file gets.
EXPECTED = (f"{', '.join(repr(w) for w in WORDS)}, or an interval with open or closed ends such as "
            "'(0, pi/2)', '[0, oo)', '(0, l)' (ends: numbers, pi, oo, the problem's parameters, + - * / and ^ "
            "or ** to a whole power)")

_MAX_TEXT = 120

Role = Literal["parameter", "coordinate", "velocity", "acceleration", "momentum", "time", "symbol"]


class DomainError(ValueError):
    """A domain text that cannot be read: the message says what was expected."""


def _end(text: str) -> sp.Expr:
    """One end of an interval: numbers, pi, oo and parameters' names (a string's length ``l``, the
    time ``pi/(2*omega)`` a rotating wire takes to stand across), no eval."""
    try:
        tree = ast.parse(text.strip().replace("^", "**"), mode="eval")
    except SyntaxError:
        raise DomainError(f"cannot read the end {text.strip()!r}") from None

    def value(node: ast.AST) -> sp.Expr:
        if isinstance(node, ast.Constant) and type(node.value) in (int, float):
            # a decimal is the number typed (0.1 is 1/10), exactly: the box is compared with it exactly
            return sp.Integer(node.value) if isinstance(node.value, int) else sp.Rational(repr(node.value))
        if isinstance(node, ast.Name) and node.id in ("pi", "oo"):
            return sp.pi if node.id == "pi" else sp.oo
        if isinstance(node, ast.Name):  # a parameter: the problem checks that it is one
            return sp.Symbol(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            inner = value(node.operand)
            return -inner if isinstance(node.op, ast.USub) else inner
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow)):
            a, b = value(node.left), value(node.right)
            if isinstance(node.op, ast.Pow):
                if not (b.is_Integer and abs(b) <= 8):
                    raise DomainError(f"in {text.strip()!r}: a power must be a whole number from -8 to 8")
                return a**b
            if isinstance(node.op, ast.Div) and b == 0:
                raise DomainError(f"in {text.strip()!r}: division by zero")
            return {ast.Add: a + b, ast.Sub: a - b, ast.Mult: a * b}.get(type(node.op), a / b)
        raise DomainError(f"cannot read the end {text.strip()!r}: only numbers, pi, oo, parameters and + - * / ^")

    end = value(tree.body)
    if end is sp.nan or (end.is_number and not end.is_extended_real) or end.has(sp.zoo, sp.nan):
        raise DomainError(f"the end {text.strip()!r} is not a real number")
    return end


@lru_cache(maxsize=256)
def _ends_function(lo: sp.Expr, hi: sp.Expr, names: tuple[sp.Symbol, ...]) -> Any:
    """The ends as a numpy function of their parameters, compiled once per domain."""
    return sp.lambdify(names, [lo, hi], "numpy")


def _finite(end: sp.Expr) -> bool:
    return end not in (sp.oo, -sp.oo)


@lru_cache(maxsize=1024)
def _assumptions_of(bounds: Bounds) -> tuple[tuple[str, bool], ...]:
    """`Bounds.assumptions`, kept: a function of the (frozen, hashable) bounds alone."""
    return bounds._assumptions()


@dataclass(frozen=True)
class Bounds:
    """A domain as an interval of the real line, with the text it was written in."""

    text: str
    lo: sp.Expr
    hi: sp.Expr
    left_open: bool
    right_open: bool

    @property
    def interval(self) -> sp.Interval:
        """The domain as a sympy `Interval` (its ends may hold parameters: ``Interval(0, l)``)."""
        return sp.Interval(self.lo, self.hi, self.left_open, self.right_open)

    @property
    def parameters(self) -> frozenset[sp.Symbol]:
        """The parameters its ends depend on (none for a constant domain)."""
        return frozenset(self.lo.free_symbols | self.hi.free_symbols)

    def at(self, values: Mapping[sp.Symbol, Any]) -> Bounds:
        """The domain with the parameters of its ends given values (floats are taken exactly)."""
        if not self.parameters:
            return self
        subs = {s: sp.Rational(v) if isinstance(v, float) else v for s, v in values.items() if s in self.parameters}
        return Bounds(self.text, self.lo.xreplace(subs), self.hi.xreplace(subs), self.left_open, self.right_open)

    def contains(self, value: Any, at: Mapping[sp.Symbol, Any] | None = None) -> Any:
        """Whether ``value`` lies in the domain: exactly for a number (a float is its exact binary
        value), a sympy condition for an expression with symbols (or ends with parameters not given
        in ``at``), elementwise for an array (``at`` may hold arrays of the same length then)."""
        if at is not None and self.parameters:
            if any(hasattr(v, "shape") and getattr(v, "shape", ()) != () for v in at.values()):
                import numpy as np

                names = sorted(self.parameters, key=str)
                lo, hi = (np.broadcast_to(np.asarray(e, dtype=float), np.shape(value))
                          for e in _ends_function(self.lo, self.hi, tuple(names))(*(at[s] for s in names)))
                v = np.asarray(value, dtype=float)
                return ((v > lo) if self.left_open else (v >= lo)) & ((v < hi) if self.right_open else (v <= hi))
            return self.at(at).contains(value)
        if hasattr(value, "shape") and getattr(value, "shape", ()) != () and self.parameters:
            raise ValueError(f"the domain {self.text!r} names {', '.join(sorted(map(str, self.parameters)))}: "
                             f"give their values (at=)")
        if hasattr(value, "shape") and getattr(value, "shape", ()) != ():
            import numpy as np

            v = np.asarray(value, dtype=float)
            lo, hi = float(self.lo), float(self.hi)
            above = v > lo if self.left_open else v >= lo
            below = v < hi if self.right_open else v <= hi
            return above & below
        if isinstance(value, float):
            if value != value:
                return False
            value = sp.Rational(value) if abs(value) != float("inf") else sp.oo if value > 0 else -sp.oo
        value = sp.sympify(value)
        if value.free_symbols or self.parameters:
            return self.interval.contains(value)
        if not value.is_extended_real:
            return False
        return bool(self.interval.contains(value))

    def encloses(self, box: tuple[float, float], at: Mapping[sp.Symbol, Any] | None = None) -> bool:
        """Whether the closed sampling box [low, high] lies inside the domain (exact comparison), with
        the parameters of its ends at ``at``."""
        return all(self.contains(float(x), at) is True for x in box)

    def assumptions(self) -> dict[str, bool]:
        """The strongest sympy assumptions the domain gives (``Symbol(name, **assumptions())``):
        real always; positive, nonnegative, negative or nonpositive where an end at 0 or beyond says so.
        Worked out once per domain (the exact judge asks for every symbol of every expression)."""
        return dict(_assumptions_of(self))

    def _assumptions(self) -> tuple[tuple[str, bool], ...]:
        out = {"real": True}
        lo, hi = (e if e.is_number else None for e in (self.lo, self.hi))  # an end with parameters says nothing
        if lo is not None and (lo > 0 or (lo == 0 and self.left_open)):
            out["positive"] = True
        elif lo == 0:
            out["nonnegative"] = True
        if hi is not None and (hi < 0 or (hi == 0 and self.right_open)):
            out["negative"] = True
        elif hi == 0:
            out["nonpositive"] = True
        return tuple(out.items())

    def predicates(self, symbol: sp.Symbol) -> sp.Basic:
        """The domain as `Q` predicates on ``symbol``, for ``refine``: Q.real, and each finite end as
        Q.positive / Q.nonnegative of the distance to it (0 < alpha < pi/2 is Q.positive(alpha) &
        Q.positive(pi/2 - alpha))."""
        facts = [Q.real(symbol)]
        if _finite(self.lo):
            facts.append((Q.positive if self.left_open else Q.nonnegative)(symbol - self.lo))
        if _finite(self.hi):
            facts.append((Q.positive if self.right_open else Q.nonnegative)(self.hi - symbol))
        return sp.And(*facts)

    def words(self, name: str) -> str:
        """The domain as a student reads it: ``m > 0``, ``0 < alpha < pi/2``, ``x real``."""
        lo, hi = sp.sstr(self.lo), sp.sstr(self.hi)
        low = f"{lo} {'<' if self.left_open else '<='} "
        high = f" {'<' if self.right_open else '<='} {hi}"
        if _finite(self.lo) and _finite(self.hi):
            return f"{low}{name}{high}"
        if _finite(self.lo):
            return f"{name} {'>' if self.left_open else '>='} {lo}"
        if _finite(self.hi):
            return f"{name}{high}"
        return f"{name} real"


@lru_cache(maxsize=1024)
def parse_domain(text: str) -> Bounds:
    """Read a domain's text (a word of :data:`WORDS` or an interval); `DomainError` says what was expected."""
    if not isinstance(text, str) or len(text) > _MAX_TEXT:
        raise DomainError(f"a domain is a short text: {EXPECTED}")
    s = text.strip()
    if s in WORDS:
        return Bounds(s, *WORDS[s])
    if len(s) < 5 or s[0] not in "([" or s[-1] not in ")]" or s[1:-1].count(",") != 1:
        raise DomainError(f"cannot read the domain {text!r}: expected {EXPECTED}")
    a, b = s[1:-1].split(",")
    lo, hi = _end(a), _end(b)
    left_open, right_open = s[0] == "(", s[-1] == ")"
    if (lo.is_infinite and not left_open) or (hi.is_infinite and not right_open):
        raise DomainError(f"the domain {text!r} is closed at an infinite end: write oo with ( or )")
    if lo == sp.oo or hi == -sp.oo or (lo.is_number and hi.is_number and not bool(lo < hi)):
        raise DomainError(f"the domain {text!r} is empty: its low end must be below its high end")
    return Bounds(s, lo, hi, left_open, right_open)


@dataclass(frozen=True)
class Domain:
    """One symbol of a problem (the plain `sympy.Symbol` the engine uses: ``theta``, ``theta_d``,
    ``p_theta``, ``t``) with its physical domain and its sampling box (None where the symbol is not
    drawn but computed, as momenta are)."""

    symbol: sp.Symbol
    bounds: Bounds
    sample_box: tuple[float, float] | None
    role: Role
    #: the name in the student's notation (``theta'`` for ``theta_d``)
    name: str

    @property
    def interval(self) -> sp.Interval:
        return self.bounds.interval

    def contains(self, value: Any, at: Mapping[sp.Symbol, Any] | None = None) -> Any:
        """Whether ``value`` is in the domain; ``at``: values of the parameters its ends name."""
        return self.bounds.contains(value, at)

    def assumptions(self) -> dict[str, bool]:
        return self.bounds.assumptions()

    def predicates(self) -> sp.Basic:
        return self.bounds.predicates(self.symbol)

    def assumed(self) -> sp.Symbol:
        """A symbol of the same name carrying the domain's assumptions (not equal to ``symbol``:
        replace and replace back, `lagrade.problem.symbols.plain_symbols` drops them)."""
        return sp.Symbol(self.symbol.name, **self.assumptions())

    def words(self) -> str:
        return self.bounds.words(self.name)


def assumed_symbols(domains: Mapping[sp.Symbol, Domain]) -> dict[sp.Symbol, sp.Symbol]:
    """Plain symbol -> the same name with its domain's assumptions, for ``expr.xreplace``."""
    return {s: d.assumed() for s, d in domains.items()}


def predicates(domains: Mapping[sp.Symbol, Domain]) -> sp.Basic:
    """Every domain as one conjunction of `Q` predicates, for ``sympy.refine(expr, predicates(...))``."""
    return sp.And(*(d.predicates() for d in domains.values()))


def words(domains: Iterable[Domain]) -> str:
    """The domains as one line in the student's notation, names with the same half-line grouped:
    ``m, M, g > 0; 0 < alpha < pi/2; theta' > 0; x, x' real``."""
    groups: dict[str, list[str]] = {}
    for d in domains:
        b = d.bounds
        if _finite(b.lo) and _finite(b.hi):
            groups.setdefault(d.words(), [])
        else:
            groups.setdefault(b.words("\0"), []).append(d.name)
    real = groups.pop(Bounds("real", *WORDS["real"]).words("\0"), None)  # the default, said last
    out = [key.replace("\0", ", ".join(names)) if names else key for key, names in groups.items()]
    return "; ".join(out + ([f"{', '.join(real)} real"] if real else []))
