"""The notation of expressions as text: what problem files and plain-text answers are written in.

The reference derivation reads problem files with it and ``answer.toml`` is read with it, so it
sits below both (the derivation never imports the answer loaders). The text is read with ``ast``
and only arithmetic, a few functions and literals are interpreted; nothing is ``eval``-ed or
``sympify``-ed, and sizes, nesting and exact powers are bounded before sympy gets to work (the
limits below are shared with the rebuilding of a sandbox child's values,
:mod:`lagrade.answer.jail.rebuild`). Conventions, chosen to fit mechanics notation:

* ``t`` is time; ``pi`` is the constant pi.  ``e``, ``E`` and ``I`` are *ordinary symbols*
  (energies, moments of inertia...); write ``exp(1)`` for Euler's number.
* ``^`` means power, like ``**``; integer division gives exact rationals (``1/2``).
* A coordinate ``q`` (one of ``coordinates``) stands for ``q(t)``; ``q(t)`` is the same.
  ``q_d``, ``q_dot``, ``qdot`` are its first time derivative, ``q_dd``, ``q_ddot``, ``qddot``
  its second.  ``Derivative(q, t)``, ``Derivative(q(t), (t, 2))`` and ``diff(q, t, 2)`` work too.
* ``a == b`` is the equation ``Eq(a, b)`` (at top level, in a list, or as a dict value).
* Any other name is a plain symbol (parameters, momenta like ``p_theta``).  When
  ``known_names`` is given, unknown names are errors with a "did you mean" hint.
* ``functions`` names the general functions a problem leaves open (``V(r)``) with their number of
  arguments; ``V(r)`` is then ``Function('V')(r(t))``, ``diff(V(r), r)`` (or ``Derivative``)
  differentiates with respect to the coordinate, and ``V'(r)``, ``V''(r)`` are the derivatives of a
  function of one argument, at its argument.
"""

from __future__ import annotations

import ast
import difflib
import math
import re
from collections.abc import Iterable, Mapping, Sequence
from functools import lru_cache
from typing import Any

import sympy as sp

from lagrade.problem.limits import (  # every bound in one place; re-exported: the readers import them from here
    MAX_DEPTH,
    MAX_DERIVATIVE_ORDER,
    MAX_DERIVATIVE_TERMS,
    MAX_EXPANDED_TERMS,
    MAX_EXPONENT,
    MAX_FLOAT_PRECISION,
    MAX_INT_ABS,
    MAX_NAME_CHARS,
    MAX_NODES,
    MAX_NUMBER_DIGITS,
    MAX_POWER_DIGITS,
    MAX_TEXT_CHARS,
    MAX_TOTAL_INT_DIGITS,
)

_LOG10_2 = math.log10(2)


class RebuildError(ValueError):
    """The text is not a safe, well-formed sympy ``srepr`` (or is too large to rebuild)."""


# --------------------------------------------------------------------------- limits on untrusted text

def check_int(value: int) -> None:
    """Refuse integers beyond the size any mechanics answer needs."""
    if abs(value) > MAX_INT_ABS:
        raise RebuildError(f"integer too large (more than {len(str(MAX_INT_ABS)) - 1} digits)")


def check_power(base: Any, exp: Any) -> None:
    """Refuse an exact power whose result would be huge, before sympy builds it.

    Whatever the base: sympy raises every exact number in it (``(3*g*x)**n`` holds ``3**n``) and
    multiplies nested exponents (``(x**a)**b`` is ``x**(a*b)``), so the size is estimated from the
    base's tree (:func:`_exact_size`) and the exponent, and nothing is computed."""
    if isinstance(exp, bool) or not isinstance(exp, (int, sp.Rational)):
        return  # symbolic or Float exponent: sympy leaves it alone or uses floating point
    exp = sp.Rational(exp)
    if isinstance(base, bool) or not isinstance(base, (int, sp.Basic)) or isinstance(base, sp.Float):
        return  # a Float to a power is a Float
    base = sp.Integer(base) if isinstance(base, int) else base
    if abs(exp.q) > MAX_POWER_DIGITS:
        raise RebuildError(f"exponent denominator too large (more than {MAX_POWER_DIGITS} digits)")
    digits, exponent = _exact_size(base)
    n = abs(exp.p)
    if not isinstance(base, sp.Rational) and exponent * n > MAX_EXPONENT:
        raise RebuildError(f"exponent too large: a power to the {_about(exponent * n)} "
                           f"(nested powers multiply their exponents; limit {MAX_EXPONENT})")
    if digits * n > MAX_POWER_DIGITS:
        raise RebuildError(f"number too large: a power with about {_about(round(digits * n))} digits "
                           f"(limit {MAX_POWER_DIGITS})")


def _digits(n: int) -> float:
    """log10 of ``n`` (0 for 0 and 1), from its bits: never its text (which Python refuses past 4300 digits)."""
    return max(abs(n).bit_length() - 1, 0) * _LOG10_2


def _split(item: Any) -> tuple[sp.Rational, Any] | None:
    """(the exact number of ``item``, the rest): what a sum or a product combines of it; None if none."""
    if isinstance(item, sp.Rational):
        return item, sp.S.One
    if isinstance(item, sp.Expr):
        coeff, rest = item.as_coeff_Mul()
        return (coeff, rest) if isinstance(coeff, sp.Rational) else None
    return None


def check_combined(items: Sequence[Any], product: bool) -> None:
    """Refuse a sum or a product (``product``) of ``items`` whose exact numbers would combine into a
    number beyond ``MAX_NUMBER_DIGITS``, before sympy multiplies them: a product's numbers multiply
    (digits add); a sum adds the numbers of like terms (``1/2^300 + 1/3^300``, ``g/2^300 + g/3^300``),
    whose denominators multiply while their numerators add."""
    split = [s for s in map(_split, items) if s is not None]
    if product:
        digits = math.fsum(_digits(c.p) + _digits(c.q) for c, _ in split)
    else:
        like: dict[Any, list[sp.Rational]] = {}
        for c, rest in split:
            like.setdefault(rest, []).append(c)
        digits = max((max(_digits(c.p) for c in cs) + math.fsum(_digits(q) for q in {c.q for c in cs})
                      for cs in like.values()), default=0.0)
    if digits > MAX_NUMBER_DIGITS:
        raise RebuildError(f"number too large: a {'product' if product else 'sum'} with about {_about(round(digits))} "
                           f"digits (limit {MAX_NUMBER_DIGITS})")


def check_numbers(value: Any) -> None:
    """Refuse a value holding an exact number (numerator or denominator) beyond ``MAX_NUMBER_DIGITS``
    digits, however it was made: what every stage after the reader must be able to print."""
    for e in expressions_in(value):
        for number in e.atoms(sp.Rational):
            digits = max(_digits(number.p), _digits(number.q))
            if digits > MAX_NUMBER_DIGITS:
                raise RebuildError(f"number too large: an exact number of about {_about(round(digits))} digits "
                                   f"(limit {MAX_NUMBER_DIGITS})")


def _about(n: float) -> str:
    return f"{n:.3g}" if n >= 1e6 else f"{n:g}"


@lru_cache(maxsize=4096)
def _exact_size(e: Any) -> tuple[float, int]:
    """(the digits of the largest exact number in ``e``, the largest exact exponent in ``e``, nested
    powers multiplied): an upper bound on what raising ``e`` to a power multiplies. Memoized by
    subexpression, so that building a tree measures each of its nodes once."""
    if isinstance(e, sp.Rational):
        size = max(abs(e.p), abs(e.q))
        return (math.log10(size) if size > 1 else 0.0), 1
    digits, exponent = 0.0, 1
    for arg in getattr(e, "args", ()):
        d, x = _exact_size(arg)
        digits, exponent = max(digits, d), max(exponent, x)
    if isinstance(e, sp.Pow) and isinstance(e.exp, sp.Rational):
        exponent = _exact_size(e.base)[1] * max(abs(e.exp.p), 1)
    return digits, exponent


def check_expansion(value: Any) -> None:
    """Refuse a value with a subexpression that multiplies out (``sympy.expand``, which the engine
    calls) to more than ``MAX_EXPANDED_TERMS`` terms; built values only (they are cheap to build)."""
    for e in expressions_in(value):
        terms = _expanded_terms(e)[1]
        if terms > MAX_EXPANDED_TERMS:
            raise RebuildError(f"expression too large: multiplied out it has about {_about(terms)} terms "
                               f"(limit {MAX_EXPANDED_TERMS})")


def check_derivative(expr: Any, order: int) -> None:
    """Refuse differentiating ``expr`` ``order`` times (twice or more) when the result could be huge:
    an expression of n nodes differentiated k times is estimated at n**k nodes."""
    if order < 2 or not isinstance(expr, sp.Basic):
        return
    size = _tree_size(expr)
    if order * math.log(size) > math.log(MAX_DERIVATIVE_TERMS):
        raise RebuildError(f"derivative too large: {order} derivatives of an expression of {size} nodes "
                           f"(estimated at {size}^{order} nodes; limit {MAX_DERIVATIVE_TERMS})")


@lru_cache(maxsize=4096)
def _tree_size(e: Any) -> int:
    return 1 + sum(_tree_size(a) for a in e.args if isinstance(a, sp.Basic))


def derivative_count(spec: Sequence[Any]) -> int:
    """How many derivatives ``sympy.diff(expr, *spec)`` takes: ``t``, ``(t, 2)``, or ``t, 2``."""
    total = 0
    for i, item in enumerate(spec):
        if isinstance(item, (tuple, sp.Tuple)) and len(item) == 2:
            total += int(item[1]) if isinstance(item[1], (int, sp.Integer)) else 1
        elif not isinstance(item, (int, sp.Integer)):  # a variable, perhaps followed by its count
            after = spec[i + 1] if i + 1 < len(spec) else None
            total += int(after) if isinstance(after, (int, sp.Integer)) and not isinstance(after, bool) else 1
    return total


def expressions_in(value: Any):
    """The sympy objects in a value (lists, tuples and dicts, keys too, taken apart)."""
    if isinstance(value, sp.Basic):
        yield value
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from expressions_in(item)
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from expressions_in(key)
            yield from expressions_in(item)


@lru_cache(maxsize=4096)
def _expanded_terms(e: Any) -> tuple[float, float]:
    """(terms of ``e`` multiplied out, the most terms any subexpression of ``e`` multiplies out to):
    upper bounds, as floats (they may be astronomical). A sum's terms add, a product's multiply, a
    power of k terms to the n has C(n + k - 1, n) (one term, a quotient, for a negative n)."""
    parts = [_expanded_terms(a) for a in e.args if isinstance(a, sp.Basic)]
    widest = max((w for _, w in parts), default=1.0)
    top = 1.0
    if isinstance(e, sp.Add):
        top = math.fsum(t for t, _ in parts)
    elif isinstance(e, sp.Mul):
        top = math.prod(t for t, _ in parts)
    elif isinstance(e, sp.Pow) and isinstance(e.exp, sp.Rational) and parts:
        k, n = parts[0][0], int(abs(e.exp.p) // e.exp.q)
        if n <= 1 or k <= 1 or math.isinf(k):
            powered = k if n >= 1 else 1.0
        else:
            log = math.lgamma(n + k) - math.lgamma(n + 1) - math.lgamma(k)
            powered = math.exp(log) if log < 700 else math.inf
        widest = max(widest, powered)
        top = powered if e.exp > 0 else 1.0
    return top, max(top, widest)


def check_name(name: Any, what: str = "name") -> str:
    """Symbol and function names must be short identifiers."""
    if not isinstance(name, str) or not name.isidentifier() or len(name) > MAX_NAME_CHARS:
        raise RebuildError(f"invalid {what} {str(name)[:80]!r}: must be an identifier of at most "
                           f"{MAX_NAME_CHARS} characters")
    return name


def parse_limited(text: str, what: str = "expression") -> ast.AST:
    """``ast.parse(text, mode="eval")`` with size, nesting and node-count limits."""
    if not isinstance(text, str):
        raise RebuildError(f"{what} must be text")
    if len(text) > MAX_TEXT_CHARS:
        raise RebuildError(f"{what} too long ({len(text)} characters, limit {MAX_TEXT_CHARS})")
    _check_bracket_depth(text, what)
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise RebuildError(f"{what} is not well formed: {exc.msg}") from None
    except (RecursionError, MemoryError):  # Python's parser: operators nested beyond its own stack
        raise RebuildError(f"{what} nested too deeply (more than {MAX_DEPTH} levels)") from None
    except ValueError as exc:
        raise RebuildError(f"{what} cannot be parsed: {exc}") from None
    count = 0
    digits = 0
    for node in ast.walk(tree):
        count += 1
        if count > MAX_NODES:
            raise RebuildError(f"{what} too large (more than {MAX_NODES} syntax nodes)")
        if isinstance(node, ast.Constant) and isinstance(node.value, int) and not isinstance(node.value, bool):
            check_int(node.value)
            digits += len(str(abs(node.value)))
            if digits > MAX_TOTAL_INT_DIGITS:
                raise RebuildError(f"{what} contains too many digits")
    return tree


def _check_bracket_depth(text: str, what: str) -> None:
    """Bound nesting before ``ast.parse`` so deep input fails with our message, not the parser's."""
    depth = 0
    quote = ""
    for ch in text:
        if quote:
            if ch == quote:
                quote = ""
        elif ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
            if depth > MAX_DEPTH:
                raise RebuildError(f"{what} nested too deeply (more than {MAX_DEPTH} levels)")
        elif ch in ")]}":
            depth -= 1



#: yes/no answers written in words (answer.toml's own true/false, and Python's, are booleans already)
YES_NO = {"yes": True, "no": False, "true": True, "false": False}


# --------------------------------------------------------------------------- the reader


T = sp.Symbol("t")

_FUNCTIONS: dict[str, Any] = {
    name: getattr(sp, name)
    for name in ("sin cos tan cot sec csc asin acos atan acot atan2 sinh cosh tanh coth asinh "
                 "acosh atanh exp log sqrt cbrt Abs sign").split()
}
_SPECIAL_FUNCTIONS = {"Derivative", "diff", "Eq", "Rational"}
_CHAINED = (ast.Add, ast.Sub, ast.Mult, ast.Div)
_FIRST = ("_d", "_dot", "dot")
_SECOND = ("_dd", "_ddot", "ddot")


#: ``V'(r)``, ``V''(r)`` of a general function V: renamed ``V__prime1(r)`` before Python's parser sees it
_PRIMED_CALL = re.compile(r"\b([A-Za-z][A-Za-z0-9_]*)('+)(?=\s*\()")
_PRIME = "__prime"


class TextAnswerError(ValueError):
    """A plain-text answer could not be read; the message is meant for the student."""


def parse_math(text: str, coordinates: Sequence[str], known_names: Iterable[str] | None = None,
               functions: Mapping[str, int] | None = None) -> Any:
    """Parse one plain-text answer into a sympy object (or list/dict/bool of them); ``functions``:
    general functions (name -> number of arguments) it may call."""
    if isinstance(text, str):
        text = text.replace("^", "**")  # token-level, so x^2 + 1 keeps the precedence of **
        if functions:  # V'(r): Python has no primes; the call is renamed, and read back in _Reader.call
            text = _PRIMED_CALL.sub(lambda m: f"{m.group(1)}{_PRIME}{len(m.group(2))}" if m.group(1) in functions
                                    else m.group(0), text)
        if "'" in text:  # theta1' and theta1'': a coordinate's rates, as the book writes them
            text = _primed_coordinates(text, coordinates)
    try:
        tree = parse_limited(text, "answer")
    except RebuildError as exc:
        if isinstance(text, str) and "'" in text and "not well formed" in str(exc):
            raise TextAnswerError(_prime_help(text, coordinates)) from None
        raise TextAnswerError(str(exc)) from None
    try:
        return _Reader(coordinates, known_names, functions).top(tree.body)  # type: ignore[attr-defined]
    except (TextAnswerError, RecursionError) as exc:
        if isinstance(exc, RecursionError):
            raise TextAnswerError("the answer is nested too deeply") from None
        raise
    except RebuildError as exc:
        raise TextAnswerError(str(exc)) from None
    except (TypeError, ValueError, ZeroDivisionError, OverflowError, sp.SympifyError) as exc:
        raise TextAnswerError(f"cannot interpret the answer: {str(exc)[:200]}") from None


#: a name followed by primes, not inside quotes ('x' is a string) and not called (V'(r) is a function's)
_PRIMED_NAME = re.compile(r"(?<![\w'\"])([A-Za-z][A-Za-z0-9_]*)('{1,2})(?![\w'\"(])")


def _primed_coordinates(text: str, coordinates: Sequence[str]) -> str:
    """``theta1'`` is ``theta1_d`` and ``theta1''`` is ``theta1_dd``, for a coordinate of the problem."""
    names = set(coordinates)
    return _PRIMED_NAME.sub(lambda m: m.group(1) + ("_d" if len(m.group(2)) == 1 else "_dd")
                            if m.group(1) in names else m.group(0), text)


def spellings(coordinate: str) -> str:
    """The accepted spellings of a coordinate's rates, for a message."""
    q = coordinate
    return f"{q}' (also {q}_d, {q}_dot or {q}dot), and {q}'' (also {q}_dd, {q}_ddot or {q}ddot)"


def _prime_help(text: str, coordinates: Sequence[str]) -> str:
    """The one line for a prime that could not be read: where primes are read, and the spellings."""
    coordinates = [c for c in coordinates if not (c.startswith("p_") and c[2:] in coordinates)]  # not momenta
    primed = [m.group(1) for m in _PRIMED_NAME.finditer(text) if m.group(1) not in set(coordinates)]
    example = coordinates[0] if coordinates else "q"
    where = f"'{primed[0]}' is not a coordinate of this problem, so {primed[0]}' cannot be read; " if primed else ""
    listed = f" (the coordinates: {', '.join(coordinates)})" if coordinates else ""
    return (f"answer is not well formed: {where}a prime (') is read after a coordinate only{listed}: "
            f"its rates are {spellings(example)}")


@lru_cache(maxsize=256)
def _coordinate(name: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """q(t), q'(t), q''(t): built once per name (sympy's diff costs about half a millisecond)."""
    q = sp.Function(name)(T)
    return q, q.diff(T), q.diff(T, 2)


class _Reader:
    def __init__(self, coordinates: Sequence[str], known_names: Iterable[str] | None,
                 functions: Mapping[str, int] | None = None) -> None:
        self.coords = {check_name(c, "coordinate name"): _coordinate(c)[0] for c in coordinates}
        self.functions = {check_name(f, "function name"): n for f, n in (functions or {}).items()
                          if f not in self.coords}
        self.known = None if known_names is None else set(known_names)
        self.shorthand: dict[str, sp.Expr] = {}
        for name in self.coords:
            _, velocity, acceleration = _coordinate(name)
            for suffix in _FIRST:
                self.shorthand[name + suffix] = velocity
            for suffix in _SECOND:
                self.shorthand[name + suffix] = acceleration

    # containers and equations ------------------------------------------------------
    def top(self, node: ast.AST) -> Any:
        if isinstance(node, ast.List):
            return [self.item(e) for e in node.elts]
        if isinstance(node, ast.Dict):
            out = {}
            for k, v in zip(node.keys, node.values):
                if k is None:
                    raise TextAnswerError("'**' is not allowed in a dict")
                key = k.value if isinstance(k, ast.Constant) and isinstance(k.value, str) else self.expr(k, 1)
                out[key] = self.item(v)
            return out
        return self.item(node)

    def item(self, node: ast.AST) -> Any:
        if isinstance(node, ast.Constant) and isinstance(node.value, bool):
            return node.value
        if isinstance(node, ast.Compare):
            if len(node.ops) != 1 or not isinstance(node.ops[0], ast.Eq):
                raise TextAnswerError("only single equations 'a == b' are allowed, not <, > or chains")
            return sp.Eq(self.expr(node.left, 1), self.expr(node.comparators[0], 1))
        return self.expr(node, 1)

    # expressions ------------------------------------------------------------------
    def expr(self, node: ast.AST, depth: int) -> Any:
        if depth > MAX_DEPTH:
            raise TextAnswerError("the answer is nested too deeply")
        d = depth + 1
        if isinstance(node, ast.Constant):
            value = node.value
            if isinstance(value, bool):
                raise TextAnswerError("True/False cannot be used inside a formula")
            if isinstance(value, int):
                check_int(value)
                return sp.Integer(value)
            if isinstance(value, float):
                return sp.Float(repr(value))
            raise TextAnswerError(f"unexpected literal {value!r:.40} in a formula")
        if isinstance(node, ast.Name):
            return self.name(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            value = self.expr(node.operand, d)
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.BinOp) and isinstance(node.op, _CHAINED):
            return self.chain(node, d)
        if isinstance(node, ast.BinOp):
            left, right = self.expr(node.left, d), self.expr(node.right, d)
            op = node.op
            if isinstance(op, (ast.Pow, ast.BitXor)):
                check_power(left, right)
                return left**right
            raise TextAnswerError(f"operator {ast.unparse(node)[:40]!r} is not supported; use + - * / ** or ^")
        if isinstance(node, ast.Call):
            return self.call(node, d)
        if isinstance(node, ast.Compare):
            raise TextAnswerError("'==' may only be used for a whole equation, not inside a formula")
        if isinstance(node, ast.Attribute):
            raise TextAnswerError("attribute access (x.y) is not allowed in a text answer")
        if isinstance(node, ast.Lambda):
            raise TextAnswerError("lambda is not allowed in a text answer")
        if isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            raise TextAnswerError("comprehensions are not allowed in a text answer")
        raise TextAnswerError(f"'{ast.unparse(node)[:40]}' is not a supported formula")

    def chain(self, node: ast.BinOp, depth: int) -> Any:
        """``a + b - c + ...`` (or ``a * b / c * ...``): Python's tree nests a sum to the left, one level
        a term; it is read as one level, so that a long sum is not "nested too deeply", and built at
        once (adding term by term would copy the sum each time)."""
        kind = (ast.Add, ast.Sub) if isinstance(node.op, (ast.Add, ast.Sub)) else (ast.Mult, ast.Div)
        right: list[tuple[ast.operator, ast.AST]] = []
        while isinstance(node, ast.BinOp) and isinstance(node.op, kind):
            right.append((node.op, node.right))
            node = node.left
        items = [self.expr(node, depth)]
        for op, operand in reversed(right):
            value = self.expr(operand, depth)
            items.append(-value if isinstance(op, ast.Sub) else 1 / value if isinstance(op, ast.Div) else value)
        check_combined(items, product=kind[0] is not ast.Add)
        return sp.Add(*items) if kind[0] is ast.Add else sp.Mul(*items)

    def name(self, name: str) -> Any:
        if name.startswith("__"):
            raise TextAnswerError(f"names with double underscores like '{name}' are not allowed")
        check_name(name)
        if name == "t":
            return T
        if name == "pi":
            return sp.pi
        if name in self.coords:
            return self.coords[name]
        if name in self.shorthand:
            return self.shorthand[name]
        if name in _FUNCTIONS or name in _SPECIAL_FUNCTIONS:
            raise TextAnswerError(f"'{name}' is a function; write {name}(...)")
        if name in self.functions:
            raise TextAnswerError(f"'{name}' is a function of the coordinates; write it with its "
                                  f"{self.functions[name]} argument(s), e.g. {name}(...)")
        if self.known is not None and name not in self.known:
            rate = self._rate_of(name)
            if rate is not None:
                raise TextAnswerError(f"unknown name '{name}': the rates of the coordinate {rate} are written "
                                      f"{spellings(rate)}")
            raise TextAnswerError(f"unknown name '{name}'{self._hint(name, self._all_names())}")
        return sp.Symbol(name)

    def _rate_of(self, name: str) -> str | None:
        """The coordinate whose rate ``name`` tries to spell (``thetadot1``, ``dtheta1``, ``theta_1_dot``)."""
        if not re.search(r"dot|_d|^d", name):
            return None
        bare = {c.replace("_", ""): c for c in self.coords}
        core = re.sub(r"ddot|dot|_dd\b|_d\b|_dd$|_d$", "", name).replace("_", "")
        for guess in (core, core[1:] if name.startswith("d") else None, core[2:] if name.startswith("dd") else None):
            if guess and guess in bare:
                return bare[guess]
        return None

    def _all_names(self) -> list[str]:
        return sorted({"t", "pi", *self.coords, *self.shorthand, *(self.known or ())})

    @staticmethod
    def _hint(name: str, candidates: Iterable[str]) -> str:
        close = difflib.get_close_matches(name, list(candidates), n=1)
        return f" (did you mean '{close[0]}'?)" if close else ""

    def call(self, node: ast.Call, depth: int) -> Any:
        if not isinstance(node.func, ast.Name):
            if isinstance(node.func, ast.Attribute):
                raise TextAnswerError("attribute access (x.y) is not allowed in a text answer")
            raise TextAnswerError("only named functions like sin(x) can be called")
        fname = node.func.id
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise TextAnswerError(f"{fname}() takes plain arguments only")
        if fname in self.coords:
            if len(node.args) != 1:
                raise TextAnswerError(f"coordinate {fname} takes one argument, e.g. {fname}(t)")
            arg = self.expr(node.args[0], depth)
            return self.coords[fname] if arg == T else sp.Function(fname)(arg)
        if fname in ("Derivative", "diff"):
            return self.derivative(fname, node.args, depth)
        base, _, primes = fname.partition(_PRIME)
        if primes.isdigit() and base in self.functions:  # V'(r): the derivative in its argument, at r
            if self.functions[base] != 1 or len(node.args) != 1:
                raise TextAnswerError(f"{base}' is for a function of one argument; write diff({base}(...), ...)")
            if not 0 < int(primes) <= MAX_DERIVATIVE_ORDER:
                raise TextAnswerError(f"derivative order {primes} out of range")
            u = sp.Dummy("u")
            return sp.Subs(sp.Derivative(sp.Function(base)(u), (u, int(primes))), u, self.expr(node.args[0], depth))
        if fname in self.functions:
            if len(node.args) != self.functions[fname]:
                raise TextAnswerError(f"{fname} takes {self.functions[fname]} argument(s), "
                                      f"not {len(node.args)}")
            return sp.Function(fname)(*[self.expr(a, depth) for a in node.args])
        if fname == "Rational":
            args = [self.expr(a, depth) for a in node.args]
            if len(args) != 2 or not all(isinstance(a, sp.Integer) for a in args) or args[1] == 0:
                raise TextAnswerError("Rational(p, q) needs two integers, q not zero")
            return sp.Rational(int(args[0]), int(args[1]))
        if fname == "Eq":
            if len(node.args) != 2:
                raise TextAnswerError("Eq(a, b) takes two arguments")
            return sp.Eq(self.expr(node.args[0], depth), self.expr(node.args[1], depth))
        if fname in _FUNCTIONS:
            args = [self.expr(a, depth) for a in node.args]
            try:
                return _FUNCTIONS[fname](*args)
            except TypeError:
                raise TextAnswerError(f"wrong number of arguments for {fname}()") from None
        known = [*_FUNCTIONS, *_SPECIAL_FUNCTIONS, *self.coords, *self.functions]
        raise TextAnswerError(f"unknown function '{fname}'{self._hint(fname, known)}")

    def derivative(self, fname: str, args: list[ast.AST], depth: int) -> Any:
        if len(args) < 2:
            raise TextAnswerError(f"{fname}(expression, t) needs a variable")
        expr = self.expr(args[0], depth)
        spec: list[Any] = []
        for a in args[1:]:
            if isinstance(a, ast.Tuple):
                if len(a.elts) != 2:
                    raise TextAnswerError("write (t, 2) for a second derivative")
                var, order = (self.expr(e, depth) for e in a.elts)
                spec.append((var, order))
            else:
                spec.append(self.expr(a, depth))
        orders = [o for item in spec for o in (item[1:] if isinstance(item, tuple) else [item])
                  if isinstance(o, sp.Integer)]
        for o in orders:
            if not 0 <= int(o) <= MAX_DERIVATIVE_ORDER:
                raise TextAnswerError(f"derivative order {o} out of range")
        for item in spec:
            var = item[0] if isinstance(item, tuple) else item
            if not isinstance(var, (sp.Symbol, sp.Integer)) and not (self.functions and var in self.coords.values()):
                raise TextAnswerError("differentiate with respect to a symbol such as t")
        check_derivative(expr, derivative_count(spec))
        return sp.diff(expr, *spec)


