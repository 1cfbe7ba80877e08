"""The notation of expressions as text: what problem files and plain-text answers are written in.

The reference derivation reads problem files with it and ``answer.toml`` is read with it, so it
sits below both (the derivation never imports the answer loaders). The text is read with ``ast``
and only arithmetic, a few functions and literals are interpreted; nothing is ``eval``-ed or
``sympify``-ed, and sizes, nesting and exact powers are bounded before sympy gets to work (the
limits below are shared with the rebuilding of a sandbox child's values,
:mod:`lagrade.jail.rebuild`). Conventions, chosen to fit mechanics notation:

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

MAX_TEXT_CHARS = 1_000_000
MAX_NODES = 300_000
MAX_DEPTH = 100
MAX_INT_ABS = 10**60
MAX_TOTAL_INT_DIGITS = 200_000
MAX_POWER_DIGITS = 10_000
MAX_NAME_CHARS = 64
MAX_FLOAT_PRECISION = 10_000
MAX_DERIVATIVE_ORDER = 100


class RebuildError(ValueError):
    """The text is not a safe, well-formed sympy ``srepr`` (or is too large to rebuild)."""


# --------------------------------------------------------------------------- limits on untrusted text

def check_int(value: int) -> None:
    """Refuse integers beyond the size any mechanics answer needs."""
    if abs(value) > MAX_INT_ABS:
        raise RebuildError("integer too large (more than 60 digits)")


def check_power(base: Any, exp: Any) -> None:
    """Refuse exact numeric powers whose result would be huge, before sympy computes them."""
    if not (isinstance(exp, sp.Rational) or isinstance(exp, int)):
        return  # symbolic or Float exponent: sympy leaves it alone or uses floating point
    exp = sp.Rational(exp)
    if isinstance(base, int):
        base = sp.Integer(base)
    if not isinstance(base, sp.Basic) or not base.is_number or isinstance(base, sp.Float):
        return
    if abs(exp.q) > MAX_POWER_DIGITS:
        raise RebuildError("exponent denominator too large")
    if isinstance(base, sp.Rational):
        size = max(abs(base.p), abs(base.q))
        if size <= 1:
            return
        digits = abs(exp.p) * (size.bit_length() * math.log10(2))
        if digits > MAX_POWER_DIGITS:
            raise RebuildError(f"number too large: a power with about {digits:.3g} digits")
    elif abs(exp.p) > MAX_POWER_DIGITS:  # e.g. (1 + I)**n is expanded exactly by sympy
        raise RebuildError("exponent too large for an exact numeric power")


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
    except (ValueError, RecursionError, MemoryError) as exc:
        raise RebuildError(f"{what} cannot be parsed: {type(exc).__name__}: {exc}") from None
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
    try:
        tree = parse_limited(text, "answer")
    except RebuildError as exc:
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
        if isinstance(node, ast.BinOp):
            left, right = self.expr(node.left, d), self.expr(node.right, d)
            op = node.op
            if isinstance(op, ast.Add):
                return left + right
            if isinstance(op, ast.Sub):
                return left - right
            if isinstance(op, ast.Mult):
                return left * right
            if isinstance(op, ast.Div):
                return left / right
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
            raise TextAnswerError(f"unknown name '{name}'{self._hint(name, self._all_names())}")
        return sp.Symbol(name)

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
        return sp.diff(expr, *spec)


