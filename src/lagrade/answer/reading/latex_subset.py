"""A fast reader for the part of sympy's LaTeX grammar that the pre-pass writes, with sympy's result.

sympy's LaTeX parser runs ANTLR's Python runtime: about 7 ms for one item of an answer, half of
what lagrade spends on a LaTeX answer. What ``latex._Pre`` hands it is mostly a small language:
numbers, letters, Greek names, ``\\mathit{...}``, ``+ - \\cdot \\times / ^ =``, parentheses and
braces, ``\\frac``, ``\\sqrt`` and the elementary functions with their argument in parentheses.
This module reads that language by recursive descent in well under a millisecond and builds what
sympy's converter (``sympy.parsing.latex._parse_latex_antlr``) builds from ANTLR's tree, node for
node, with its quirks (``a - b`` as ``a + (-1)*b``, a letter before ``(`` as a function call (``V'(r)``
calls ``V'``), an
``x`` between two numbers as a times sign).

Anything else (``d`` and differentials, subscripts, primes other than in a call ``V'(r)``, ``|``, ``!``, commas, unknown commands,
two ``=``, digits separated by spaces (one number to sympy), any syntax error) makes it decline with ``None``, and the caller runs sympy's parser,
which then also words any error. ``tests/test_latex_subset.py`` holds it to sympy's trees on
generated text.
"""

from __future__ import annotations

import re
from typing import Any

import sympy as sp

#: the Greek letters LaTeX answers may use (:mod:`lagrade.answer.reading.latex` reads them too)
GREEK = set(
    "alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa varkappa lambda mu nu xi "
    "pi varpi rho varrho sigma varsigma tau upsilon phi varphi chi psi omega "
    "Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega".split())

#: sympy's ``func_normal`` commands, read by ``_function`` as sympy's ``convert_func`` reads them
_FUNCTIONS = frozenset("exp log lg ln sin cos tan csc sec cot arcsin arccos arctan arccsc arcsec arccot "
                       "sinh cosh tanh arsinh arcosh artanh".split())
#: commands the ANTLR lexer skips (``\\left`` and ``\\right`` among them)
_SKIPPED = frozenset("quad qquad left right thinspace medspace thickspace negthinspace negmedspace "
                     "negthickspace".split())
#: commands read as a plain name (sympy's SYMBOL): the Greek letters LaTeX answers may use; any other
#: unknown command declines
_NAMES = frozenset(GREEK)
_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|[ \t\r\n]+|.", re.S)


class _Decline(Exception):
    """Outside the subset (or not LaTeX at all): sympy's parser decides."""


def read(text: str, sympy_module: Any) -> Any | None:
    """sympy's tree for ``text`` (what ``parse_latex(text, strict=True)`` gives), or None.

    ``sympy_module`` is the ``sympy`` namespace sympy's converter uses (``latex._NUMBERS_READ``, which
    ``latex._antlr_converter`` installs in it), so that numbers are made by the same call."""
    try:
        tokens = _tokens(text)
        if not tokens:
            return None
        reader = _Reader(tokens, sympy_module)
        tree = reader.relation()
        if reader.i != len(tokens):
            return None
        return tree
    except Exception:  # noqa: BLE001  (_Decline, or what sympy raises building a node: sympy's parser words it)
        return None


def _tokens(text: str) -> list[tuple[str, bool]]:
    """(token, follows whitespace) pairs, with what ANTLR's lexer skips removed."""
    out: list[tuple[str, bool]] = []
    space = False
    found = _TOKEN.findall(text.strip())
    for k, tok in enumerate(found):
        if tok.isspace():
            space = True
            continue
        if tok[0] == "\\":
            name = tok[1:]
            if name in _SKIPPED or name in (",", ":", ";", "!"):
                if k in (0, len(found) - 1):
                    raise _Decline()  # strict: sympy refuses a text that starts or ends with what it skips
                space = True
                continue
            if not name.isalpha():
                raise _Decline()
        elif tok == "d" or not (tok.isascii() and (tok.isalnum() or tok in "+-*/(){}[]^=.'")):
            raise _Decline()  # a d may start a differential; | ! _ , & < > and the rest are sympy's
        out.append((tok, space))
        space = False
    return out


class _Reader:
    """Recursive descent over sympy's LaTeX grammar (``LaTeX.g4``), building its converter's tree."""

    def __init__(self, tokens: list[tuple[str, bool]], sympy_module: Any) -> None:
        self.toks = [t for t, _ in tokens]
        self.spaced = [s for _, s in tokens]
        self.i = 0
        self.sympy = sympy_module

    def peek(self) -> str | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self, tok: str) -> None:
        if self.peek() != tok:
            raise _Decline()
        self.i += 1

    # relation: expr (= expr)? ------------------------------------------------------
    def relation(self) -> Any:
        lhs = self.expr()
        if self.peek() != "=":
            return lhs
        self.i += 1
        rhs = self.expr()
        if self.peek() == "=":
            raise _Decline()
        return sp.Eq(lhs, rhs)

    # additive: left-associative + and -, as convert_add ---------------------------
    def expr(self) -> Any:
        value = self.mp()
        while self.peek() in ("+", "-"):
            op = self.toks[self.i]
            self.i += 1
            rhs = self.mp()
            if op == "+":
                value = sp.Add(value, rhs, evaluate=False)
            elif getattr(rhs, "is_Atom", False):
                value = sp.Add(value, -1 * rhs, evaluate=False)
            else:
                value = sp.Add(value, sp.Mul(-1, rhs, evaluate=False), evaluate=False)
        return value

    # mp: left-associative * \cdot \times and /, as convert_mp ----------------------
    def mp(self) -> Any:
        value = self.unary()
        while self.peek() in ("*", "\\cdot", "\\times", "/"):
            op = self.toks[self.i]
            self.i += 1
            rhs = self.unary()
            if op == "/":
                value = sp.Mul(value, sp.Pow(rhs, -1, evaluate=False), evaluate=False)
            else:
                value = sp.Mul(value, rhs, evaluate=False)
        return value

    # unary: (+|-) unary | postfix+, as convert_unary and convert_postfix_list -------
    def unary(self) -> Any:
        tok = self.peek()
        if tok == "+":
            self.i += 1
            return self.unary()
        if tok == "-":
            self.i += 1
            return -self.unary()
        items = [self.exp()]
        while self.starts_exp(self.peek()):
            items.append(self.exp())
        return _product(items, 0)

    @staticmethod
    def starts_exp(tok: str | None) -> bool:
        if tok is None:
            return False
        if tok[0] == "\\":
            return tok in ("\\frac", "\\dfrac", "\\tfrac", "\\sqrt", "\\mathit") or tok[1:] in _FUNCTIONS \
                or tok[1:] in _NAMES
        return tok.isalnum() or tok in "([{"

    # exp: comp (^ (atom | {expr}))* --------------------------------------------------
    def exp(self) -> Any:
        base = self.comp()
        while self.peek() == "^":
            self.i += 1
            if self.peek() == "{":
                exponent = self.braced()
            else:
                exponent = self.atom()
            base = sp.Pow(base, exponent, evaluate=False)
        return base

    def braced(self) -> Any:
        self.take("{")
        value = self.expr()
        self.take("}")
        return value

    # comp: group | func | atom ---------------------------------------------------------
    def comp(self) -> Any:
        tok = self.peek()
        if tok in ("(", "[", "{"):
            close = {"(": ")", "[": "]", "{": "}"}[tok]
            self.i += 1
            value = self.expr()
            self.take(close)
            return value
        if tok is not None and tok[0] == "\\" and tok[1:] in _FUNCTIONS:
            return self.function()
        if tok == "\\sqrt":
            self.i += 1
            root = None
            if self.peek() == "[":
                self.i += 1
                root = self.expr()
                self.take("]")
            base = self.braced()
            if root is not None:
                return sp.root(base, root, evaluate=False)
            return sp.sqrt(base, evaluate=False)
        if tok is not None and (tok.isalpha() or (tok[0] == "\\" and tok[1:] in _NAMES)):
            primes = 0
            while self.i + 1 + primes < len(self.toks) and self.toks[self.i + 1 + primes] == "'":
                primes += 1
            if primes and (len(tok) != 1 or any(self.spaced[self.i + 1 + k] for k in range(primes + 1))):
                raise _Decline()  # a prime on a name, or spaced out: sympy's grammar decides
            if self.i + 1 + primes < len(self.toks) and self.toks[self.i + 1 + primes] == "(":
                return self.call(primes)
        return self.atom()

    def call(self, primes: int = 0) -> Any:
        """A letter or name before ``(`` is a function call to sympy's grammar (``f(x)``); primes
        between them belong to the function's name (``V'(r)`` calls ``V'``)."""
        tok = self.toks[self.i]
        name = (tok if len(tok) == 1 else tok[1:]) + "'" * primes
        self.i += 2 + primes
        arg = self.expr()
        self.take(")")
        return sp.Function(str(name))(arg)

    def function(self) -> Any:
        """``\\sin(...)``, ``\\sin^2(...)``, ``\\sin^{-1}(...)``, ``\\ln(...)``: as ``convert_func``."""
        name = self.toks[self.i][1:]
        self.i += 1
        func_pow = None
        if self.peek() == "^":
            self.i += 1
            func_pow = self.braced() if self.peek() == "{" else self.atom()
        if self.peek() != "(":
            raise _Decline()  # an argument without parentheses: sympy's mp_nofunc rules decide
        self.i += 1
        arg = self.expr()
        self.take(")")
        expr = None
        if name in ("arcsin", "arccos", "arctan", "arccsc", "arcsec", "arccot"):
            expr = getattr(sp.functions, "a" + name[3:])(arg, evaluate=False)
        if name in ("arsinh", "arcosh", "artanh"):
            expr = getattr(sp.functions, "a" + name[2:])(arg, evaluate=False)
        if name == "exp":
            expr = sp.exp(arg, evaluate=False)
        if name in ("log", "lg", "ln"):
            expr = sp.log(arg, 10 if name == "lg" else sp.E, evaluate=False)
        should_pow = True
        if name in ("sin", "cos", "tan", "csc", "sec", "cot", "sinh", "cosh", "tanh"):
            if func_pow == -1:
                name = "a" + name
                should_pow = False
            expr = getattr(sp.functions, name)(arg, evaluate=False)
        if func_pow and should_pow:
            expr = sp.Pow(expr, func_pow, evaluate=False)
        return expr

    # atom: letter | name | number | \mathit{...} | \frac ---------------------------------
    def atom(self) -> Any:
        tok = self.peek()
        if tok is None:
            raise _Decline()
        if tok.isdigit():
            return self.number()
        if tok.isalpha():
            self.i += 1
            return sp.Symbol(tok)
        if tok[0] == "\\" and tok[1:] in _NAMES:
            self.i += 1
            return sp.Symbol(tok[1:])
        if tok == "\\mathit":
            self.i += 1
            self.take("{")
            start = self.i
            while self.peek() is not None and self.peek().isalpha() and len(self.peek()) == 1:
                if self.i > start and self.spaced[self.i]:
                    raise _Decline()  # sympy keeps the spaces inside the name
                self.i += 1
            if self.i == start:
                raise _Decline()
            text = "".join(self.toks[start:self.i])
            self.take("}")
            return sp.Symbol(text)
        if tok in ("\\frac", "\\dfrac", "\\tfrac"):
            return self.frac()
        raise _Decline()

    def number(self) -> Any:
        start = self.i
        while self.peek() is not None and self.peek().isdigit():
            if self.i > start and self.spaced[self.i]:
                raise _Decline()  # "2 3" is the number 23 to sympy's grammar: too surprising to guess at
            self.i += 1
        text = "".join(self.toks[start:self.i])
        if self.peek() == "." and self.i + 1 < len(self.toks) and self.toks[self.i + 1].isdigit() \
                and not self.spaced[self.i] and not self.spaced[self.i + 1]:
            self.i += 1
            begin = self.i
            while self.peek() is not None and self.peek().isdigit() and not (self.i > begin and self.spaced[self.i]):
                self.i += 1
            text += "." + "".join(self.toks[begin:self.i])
        if self.peek() is not None and self.peek().isdigit():
            raise _Decline()
        if self.peek() == ".":
            raise _Decline()
        return self.sympy.Number(text)

    def frac(self) -> Any:
        """``\\frac{a}{b}`` (or ``\\frac12``): as ``convert_frac`` for anything but d/dx."""
        self.i += 1
        upper = self.frac_part()
        lower = self.frac_part()
        inverse_denom = sp.Pow(lower, -1, evaluate=False)
        if upper == 1:
            return inverse_denom
        return sp.Mul(upper, inverse_denom, evaluate=False)

    def frac_part(self) -> Any:
        tok = self.peek()
        if tok is not None and tok.isdigit() and len(tok) == 1:
            self.i += 1
            return self.sympy.Number(tok)
        return self.braced()


def _product(items: list[Any], i: int) -> Any:
    """sympy's ``convert_postfix_list``: an implicit product, nested to the right, where a symbol
    ``x`` between two factors without symbols is a times sign (``2 x 3`` is 6)."""
    res = items[i]
    if i == len(items) - 1:
        return res
    if i > 0:
        left, right = items[i - 1], items[i + 1]
        if isinstance(left, sp.Expr) and isinstance(right, sp.Expr):
            if not (left.atoms(sp.Symbol) or right.atoms(sp.Symbol)) and str(res) == "x":
                return _product(items, i + 1)
    return sp.Mul(res, _product(items, i + 1), evaluate=False)
