"""LaTeX answers: ``L = "\\frac{1}{2} m l^2 \\dot\\theta^2 + m g l \\cos\\theta"`` in ``answer.toml``.

The text is parsed by sympy's LaTeX parser (the ANTLR backend builds sympy objects from a parse
tree; nothing is evaluated), between a pre-pass of our own and a rebuild with an allow-list:

1. *Pre-pass* (on tokens): only the control sequences listed in ``SUPPORTED`` are accepted, any
   other is refused with a message.  Time derivatives become placeholders that sympy reads as one
   symbol: ``\\dot{X}``, ``\\dot X``, ``\\ddot X``, ``X'``, ``X''``, ``X^{\\prime}``, Leibniz
   ``\\frac{dX}{dt}`` / ``\\frac{d^2X}{dt^2}`` (``\\mathrm{d}`` too), where ``X`` is a name with an
   optional subscript (``\\dot{\\theta}_1``, ``\\dot{\\theta_1}``, ``\\dot p_{\\theta}``).  The operator
   ``\\frac{d}{dt}\\left(...\\right)`` is left to sympy and differentiated afterwards.
   Multi-letter names are written ``\\mathrm{eps}`` (or ``\\text``, ``\\mathit``,
   ``\\operatorname``).  ``\\left``/``\\right``/spacing are dropped, ``[ ]`` read as ``( )``, and
   top-level ``,`` ``;`` ``\\\\`` separate the items of a list (several equations in one string).
   Two silent misreadings of sympy's parser are refused instead: a letter followed by a digit
   (``l0`` would read as ``l*0``; write ``l_0``) and a ``/`` followed by an implicit product
   (``1/2 m v^2`` would read as ``1/(2 m v^2)``; write ``\\frac{1}{2} m v^2``).
2. *Rebuild*: the (unevaluated) sympy tree is rebuilt node by node, allowing only numbers, + * ^,
   the elementary functions, ``d/dt`` and one top-level ``=``; the size of numbers and powers is
   bounded as for Python answers.  Symbol names are mapped to the problem's names: ``\\`` and
   braces dropped, ``theta_{1}`` -> ``theta1`` when that is a coordinate or known name (else
   ``theta_1``), ``p_{\\theta}`` -> ``p_theta``, ``l_{0}`` -> ``l0``, ``\\varphi`` -> ``phi``,
   ``\\epsilon`` -> ``eps`` when the problem calls it so.  A coordinate ``q`` is ``q(t)`` (``q(t)``
   is the same); ``t`` is time, ``\\pi`` is pi, and ``e`` is Euler's number unless the problem
   has a symbol ``e``.  Unknown names are errors with a "did you mean" hint.
"""

from __future__ import annotations

import difflib
import functools
import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import sympy as sp

from lagrade.problem.limits import MAX_BRACE_DEPTH, MAX_LATEX_CHARS, MAX_REBUILD_DEPTH  # noqa: F401  (re-exported)
from lagrade.answer.reading import latex_subset
from lagrade.answer.reading.latex_subset import GREEK
from lagrade.problem.notation import (
    MAX_DERIVATIVE_ORDER,
    RebuildError,
    check_derivative,
    check_int,
    check_name,
    check_power,
)

T = sp.Symbol("t")

FUNCTIONS = set("sin cos tan cot sec csc arcsin arccos arctan arccot arcsec arccsc sinh cosh tanh "
                "exp ln log".split())
_TEXT_COMMANDS = {"mathrm", "text", "mathit", "operatorname", "textrm", "textit", "rm"}
_DERIV_COMMANDS = {"dot": 1, "ddot": 2}
_SPACING = {"quad", "qquad", "displaystyle", "textstyle", "big", "Big", "bigg", "Bigg",
            "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr", "Biggl", "Biggr"}
_OTHER = {"frac", "dfrac", "tfrac", "sqrt", "cdot", "times", "left", "right", "prime"}
#: every control sequence a LaTeX answer may use (besides the spacing ones)
SUPPORTED = GREEK | FUNCTIONS | _TEXT_COMMANDS | set(_DERIV_COMMANDS) | _OTHER
_GREEK_ALIASES = {"varphi": "phi", "vartheta": "theta", "varepsilon": "epsilon", "varrho": "rho",
                  "varsigma": "sigma", "varkappa": "kappa", "varpi": "pi"}
_NAME_ALIASES = {"epsilon": "eps", "lambda": "lam"}  # spelled out in LaTeX, abbreviated in problems
_FIRST = ("_d", "_dot", "dot")
_SECOND = ("_dd", "_ddot", "ddot")
_PLACEHOLDER_LETTERS = "ABCEFGHJKLMNPQRSUVWXYZ"  # no D: sympy's lexer treats d<letter> as a differential
_PLACEHOLDER_PREFIX = "ZQ"

_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\s+|.", re.S)
_FUNCTION_CLASSES: dict[type, Any] = {
    sp.sin: sp.sin, sp.cos: sp.cos, sp.tan: sp.tan, sp.cot: sp.cot, sp.sec: sp.sec, sp.csc: sp.csc,
    sp.asin: sp.asin, sp.acos: sp.acos, sp.atan: sp.atan, sp.acot: sp.acot, sp.asec: sp.asec,
    sp.acsc: sp.acsc, sp.sinh: sp.sinh, sp.cosh: sp.cosh, sp.tanh: sp.tanh, sp.exp: sp.exp,
    sp.Abs: sp.Abs,
}


class LatexAnswerError(ValueError):
    """Raised inside this module; converted to ``TextAnswerError`` by ``parse_latex_answer``."""


def is_latex(text: str) -> bool:
    """A TOML string is LaTeX when it contains a control sequence (``\\frac``, ``\\dot``...) or is
    wrapped in ``$...$``."""
    if not isinstance(text, str):
        return False
    s = text.strip()
    return bool(re.search(r"\\[A-Za-z]", s)) or (len(s) >= 2 and s.startswith("$") and s.endswith("$"))


def parse_latex_answer(text: str, coordinates: Sequence[str], known_names: Iterable[str] | None = None,
                       functions: Mapping[str, int] | None = None) -> Any:
    """Parse one LaTeX answer into what ``parse_math`` would give: an expression, an ``Eq``, or a
    list of them when the text holds several items separated by ``,`` ``;`` or ``\\\\``.

    Coordinates (``coordinates``, momenta included) become ``Function(name)(t)``, their time
    derivatives ``Derivative(q(t), t)`` / ``(t, 2)``; other names are plain symbols, checked
    against ``known_names`` when it is given.  ``functions``: the problem's general functions (name ->
    number of arguments, one-letter names): ``V(r)``, ``V'(r)`` (the derivative in its argument) and
    ``\\frac{dV(r)}{dr}``.  Errors are ``TextAnswerError`` for the student.
    """
    from lagrade.problem.notation import TextAnswerError

    try:
        pieces = split_items(strip_delimiters(text))
        reader = _Names(coordinates, known_names, functions)
        out = [reader.parse_piece(p) for p in pieces]
    except (LatexAnswerError, RebuildError) as exc:
        raise TextAnswerError(str(exc)) from None
    except RecursionError:
        raise TextAnswerError("the LaTeX answer is nested too deeply") from None
    except (TypeError, ValueError, ZeroDivisionError, OverflowError, sp.SympifyError) as exc:
        raise TextAnswerError(f"cannot interpret the LaTeX answer: {str(exc)[:200]}") from None
    return out[0] if len(out) == 1 else out


# --------------------------------------------------------------------------- text and tokens

def strip_delimiters(text: str) -> str:
    """Check the size and drop math delimiters ``$...$``, ``$$...$$``, ``\\(...\\)``, ``\\[...\\]``."""
    if not isinstance(text, str):
        raise LatexAnswerError("a LaTeX answer must be text")
    if len(text) > MAX_LATEX_CHARS:
        raise LatexAnswerError(f"the LaTeX answer is too long ({len(text)} characters, limit {MAX_LATEX_CHARS})")
    s = text.strip()
    for left, right in (("$$", "$$"), ("$", "$"), ("\\(", "\\)"), ("\\[", "\\]")):
        if len(s) >= len(left) + len(right) and s.startswith(left) and s.endswith(right):
            s = s[len(left):len(s) - len(right)].strip()
            break
    if "$" in s:
        raise LatexAnswerError("'$' may only wrap the whole answer ($...$)")
    if not s:
        raise LatexAnswerError("the answer is empty")
    return s


def tokenize(text: str) -> list[str]:
    tokens = _TOKEN.findall(text)
    depth = 0
    for tok in tokens:
        if tok == "{":
            depth += 1
            if depth > MAX_BRACE_DEPTH:
                raise LatexAnswerError("the LaTeX answer is nested too deeply")
        elif tok == "}":
            depth -= 1
            if depth < 0:
                raise LatexAnswerError("unbalanced braces: a '}' without its '{'")
    if depth:
        raise LatexAnswerError("unbalanced braces: a '{' is not closed")
    return tokens


def split_items(text: str) -> list[list[str]]:
    """Tokens of each item: top-level ``,``, ``;`` and ``\\\\`` separate items (``&`` is dropped)."""
    tokens = tokenize(text)
    pieces: list[list[str]] = [[]]
    depth = 0
    for tok in tokens:
        if tok in ("{", "(", "["):
            depth += 1
        elif tok in ("}", ")", "]"):
            depth -= 1
        if depth == 0 and tok in (",", ";", "\\\\"):
            pieces.append([])
            continue
        if tok == "&":
            continue
        pieces[-1].append(tok)
    pieces = [p for p in pieces if any(not t.isspace() for t in p)]
    if not pieces:
        raise LatexAnswerError("the answer is empty")
    return pieces


def _is_space(tok: str) -> bool:
    return tok.isspace() or tok in ("\\,", "\\;", "\\:", "\\!", "\\ ") or tok[1:] in _SPACING and tok[0] == "\\"


def _cmd(tok: str) -> str | None:
    return tok[1:] if len(tok) > 1 and tok[0] == "\\" and tok[1:].isalpha() else None


# --------------------------------------------------------------------------- the pre-pass

class _Pre:
    """Rewrites one item's tokens into LaTeX that sympy reads as we mean it."""

    def __init__(self, tokens: list[str], names: _Names) -> None:
        # plain spaces become " "; spacing commands (\\, \\; ...) become "\\," which also ends
        # the argument of a function written without parentheses (\\sin\\theta\\, l)
        self.toks = [" " if t.isspace() else "\\," if _is_space(t) else t for t in tokens]
        self.names = names
        self.table = names.table

    def sub(self, tokens: list[str]) -> _Pre:
        return _Pre(tokens, self.names)

    def is_coordinate(self, raw: str) -> bool:
        try:
            return self.names.resolve(raw) in self.names.coords
        except LatexAnswerError:
            return False

    # helpers ----------------------------------------------------------------------
    def skip_ws(self, i: int) -> int:
        while i < len(self.toks) and self.toks[i] in (" ", "\\,"):
            i += 1
        return i

    def group_end(self, i: int) -> int:
        """``toks[i] == '{'``: index just past the matching ``}``."""
        depth = 0
        for j in range(i, len(self.toks)):
            if self.toks[j] == "{":
                depth += 1
            elif self.toks[j] == "}":
                depth -= 1
                if depth == 0:
                    return j + 1
        raise LatexAnswerError("unbalanced braces")

    def arg(self, i: int) -> tuple[list[str], int]:
        """A macro argument at ``i``: a ``{group}`` (its inside) or one token."""
        i = self.skip_ws(i)
        if i >= len(self.toks):
            raise LatexAnswerError("a command is missing its argument at the end of the answer")
        if self.toks[i] == "{":
            end = self.group_end(i)
            return self.toks[i + 1:end - 1], end
        return [self.toks[i]], i + 1

    def placeholder(self, raw: str, order: int) -> str:
        n = len(self.table)
        letters = ""
        while True:
            letters = _PLACEHOLDER_LETTERS[n % len(_PLACEHOLDER_LETTERS)] + letters
            n //= len(_PLACEHOLDER_LETTERS)
            if n == 0:
                break
        name = _PLACEHOLDER_PREFIX + letters
        self.table[name] = (raw, order)
        return f" \\mathit{{{name}}} "

    def name_atom(self, i: int) -> tuple[str, int] | None:
        """A name at ``i`` (letter, Greek letter, ``\\mathrm{word}`` or ``{name}``) with an optional
        subscript: its raw text (``theta_{1}``) and the index after it; None if there is none."""
        i = self.skip_ws(i)
        if i >= len(self.toks):
            return None
        tok = self.toks[i]
        cmd = _cmd(tok)
        if len(tok) == 1 and tok.isalpha():
            raw, j = tok, i + 1
        elif cmd in GREEK:
            raw, j = cmd, i + 1
        elif cmd in _TEXT_COMMANDS:
            inner, j = self.arg(i + 1)
            word = "".join(t for t in inner if t not in (" ", "\\,"))
            if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", word):
                raise LatexAnswerError(f"\\{cmd}{{...}} should hold a name such as \\{cmd}{{eps}}, not {word[:30]!r}")
            raw = word
        elif tok == "{":
            end = self.group_end(i)
            inner = [t for t in self.toks[i + 1:end - 1] if t not in (" ", "\\,")]
            sub = self.sub(inner)
            got = sub.name_atom(0)
            if got is None or sub.skip_ws(got[1]) != len(sub.toks):
                return None
            raw, j = got[0], end
        else:
            return None
        k = self.skip_ws(j)
        if k < len(self.toks) and self.toks[k] == "_":
            sub_toks, j = self.arg(k + 1)
            text = "".join(t[1:] if _cmd(t) in GREEK else t for t in sub_toks if t not in (" ", "\\,"))
            if not re.fullmatch(r"[A-Za-z0-9_{}]+", text):
                raise LatexAnswerError(f"the subscript of {raw} should be a name or a number, not {''.join(sub_toks)[:30]!r}")
            raw = f"{raw}_{{{text}}}"
        return raw, j

    def primes(self, i: int) -> tuple[int, int]:
        """Primes at ``i`` (``'``, ``^\\prime``, ``^{\\prime\\prime}``): their count and the index after."""
        count = 0
        while i < len(self.toks):
            if self.toks[i] == "'":
                count += 1
                i += 1
                continue
            if self.toks[i] == "^":
                inner, j = self.arg(i + 1)
                inner = [t for t in inner if t not in (" ", "\\,")]
                if inner and all(t in ("\\prime", "'") for t in inner):
                    count += len(inner)
                    i = j
                    continue
            break
        return count, i

    def skip_t_argument(self, i: int) -> int:
        """``(t)`` after a derivative placeholder is dropped (``\\dot\\theta(t)``)."""
        j = self.skip_ws(i)
        seq = [t for t in self.toks[j:j + 5] if t not in (" ", "\\,")][:3]
        if seq == ["(", "t", ")"]:
            k = j
            seen = 0
            while seen < 3:
                if self.toks[k] != " ":
                    seen += 1
                k += 1
            return k
        return i

    # the rewrite ------------------------------------------------------------------
    def run(self, lo: int = 0, hi: int | None = None) -> str:
        hi = len(self.toks) if hi is None else hi
        out: list[str] = []
        i = lo
        while i < hi:
            tok = self.toks[i]
            cmd = _cmd(tok)
            if tok in (" ", "\\,"):
                out.append(" ")
                i += 1
            elif cmd in _DERIV_COMMANDS:
                got = self.name_atom(i + 1)
                if got is None:
                    raise LatexAnswerError(f"\\{cmd} must be followed by a coordinate, e.g. \\{cmd}{{\\theta}} or \\{cmd} x")
                raw, j = got
                more, j = self.primes(j)
                out.append(self.placeholder(raw, _DERIV_COMMANDS[cmd] + more))
                i = self.skip_t_argument(j)
            elif (len(tok) == 1 and tok.isalpha()) or cmd in GREEK or cmd in _TEXT_COMMANDS or tok == "{":
                i = self.atom(i, out)
            elif cmd in ("frac", "dfrac", "tfrac"):
                i = self.frac(i, out)
            elif cmd == "sqrt":
                j = self.skip_ws(i + 1)
                out.append("\\sqrt")
                if j < hi and self.toks[j] == "[":
                    end = self._bracket_end(j)
                    out.append("[" + self.run(j + 1, end - 1) + "]")
                    j = end
                i = j
            elif cmd in ("left", "right"):
                j = self.skip_ws(i + 1)
                if j >= hi:
                    raise LatexAnswerError(f"\\{cmd} needs a delimiter after it")
                delim = self.toks[j]
                mapping = {"(": "(", "[": "(", "\\{": "(", ")": ")", "]": ")", "\\}": ")", "|": "|", ".": ""}
                if delim not in mapping:
                    raise LatexAnswerError(f"unsupported delimiter \\{cmd}{delim}")
                out.append(mapping[delim])
                i = j + 1
            elif tok in ("[", "\\{"):
                out.append("(")
                i += 1
            elif tok in ("]", "\\}"):
                out.append(")")
                i += 1
            elif cmd in FUNCTIONS:
                i = self.function(i, out)
            elif cmd in ("cdot", "times"):
                out.append(tok + " ")
                i += 1
            elif cmd == "prime" or tok == "'":
                raise LatexAnswerError("a prime (') must follow a coordinate, e.g. x' or \\theta''")
            elif cmd in ("le", "leq", "ge", "geq", "neq", "ne", "approx", "lt", "gt", "equiv"):
                raise LatexAnswerError(f"only equations with '=' are allowed, not \\{cmd}")
            elif cmd is not None:
                raise LatexAnswerError(f"\\{cmd} is not supported in a LaTeX answer; use names, numbers, + - \\cdot, "
                                       "\\frac, ^, \\sqrt, \\sin and the other elementary functions, \\dot, \\ddot and primes")
            elif tok.startswith("\\"):
                raise LatexAnswerError(f"{tok!r} is not supported in a LaTeX answer")
            elif tok == "=":
                if i + 1 < hi and self.toks[i + 1] == "=":
                    i += 1  # '==' from the plain-text habit
                out.append("=")
                i += 1
            elif tok in "<>":
                raise LatexAnswerError("only equations with '=' are allowed, not inequalities")
            elif tok == "!":
                raise LatexAnswerError("factorials (!) are not supported")
            elif tok.isdigit() or tok in "+-*/^_().|":
                out.append(tok)
                i += 1
            else:
                raise LatexAnswerError(f"unexpected character {tok!r} in a LaTeX answer")
        return "".join(out)

    def _bracket_end(self, i: int) -> int:
        depth = 0
        for j in range(i, len(self.toks)):
            if self.toks[j] == "[":
                depth += 1
            elif self.toks[j] == "]":
                depth -= 1
                if depth == 0:
                    return j + 1
        raise LatexAnswerError("a '[' is not closed")

    def atom(self, i: int, out: list[str]) -> int:
        got = self.name_atom(i)
        if self.toks[i] == "{" and (got is None or self.primes(got[1])[0] == 0):
            # a group (an argument of \\sqrt, ^, ...) keeps its braces: rewrite its inside
            end = self.group_end(i)
            out.append("{" + self.run(i + 1, end - 1) + "}")
            return end
        raw, j = got
        count, k = self.primes(j)
        after = self.skip_ws(k)
        if self.names.is_function(raw) and after < len(self.toks) and self.toks[after] in ("(", "\\left"):
            out.append(raw + "'" * count)  # V(r), V'(r): a call sympy reads as one (see _Names.applied)
            return k
        if count:  # the subscript may also follow the primes: \theta'_1
            if k < len(self.toks) and self.toks[k] == "_" and "_" not in raw:
                sub_toks, k = self.arg(k + 1)
                sub_text = "".join(t[1:] if _cmd(t) in GREEK else t for t in sub_toks if t not in (" ", "\\,"))
                raw = f"{raw}_{{{sub_text}}}"
            out.append(self.placeholder(raw, count))
            return self.skip_t_argument(k)
        if j < len(self.toks) and self.toks[j].isdigit() and "_" not in raw:
            name = raw
            raise LatexAnswerError(f"'{name}{self.toks[j]}' would read as {name} times {self.toks[j]}; "
                                   f"write a subscript: {_latex_of(name)}_{self.toks[j]}")
        tok = self.toks[i]
        if _cmd(tok) in _TEXT_COMMANDS or "_" in raw:
            # names sympy would not read as one symbol: a placeholder keeps them whole
            out.append(self.placeholder(raw, 0))
            return self.skip_t_argument(j) if self.is_coordinate(raw) else j
        out.append(tok if len(tok) == 1 else tok + " ")
        k = self.skip_ws(j)
        if k < len(self.toks) and self.toks[k] in ("(", "\\left"):
            # sympy would read x(...) as a function call: theta(t) is the coordinate, m(a + b) a product
            after = self.skip_t_argument(j)
            if after != j and self.is_coordinate(raw):
                return after
            out.append(" \\cdot ")
        return j

    def function(self, i: int, out: list[str]) -> int:
        """``\\sin\\theta\\dot\\theta`` is sin(theta)*theta': without parentheses a function's argument
        is the product of numbers and names that follows, up to a derivative, a function, an
        operator, a parenthesis or a spacing command (``\\sin\\omega t`` is sin(omega*t))."""
        out.append(self.toks[i])
        j = i + 1
        while True:  # scripts of the function itself: \sin^2, \log_{10}
            k = self.skip_ws(j)
            if k < len(self.toks) and self.toks[k] in ("^", "_"):
                arg, j = self.arg(k + 1)
                out.append(self.toks[k] + "{" + self.sub(arg).run() + "}")
                continue
            break
        k = self.skip_ws(j)
        if k >= len(self.toks) or self.toks[k] in ("(", "\\left", "["):
            out.append(" ")
            return j
        if self.toks[k] == "{":  # braces delimit the argument: \sin{\theta} l is sin(theta)*l
            end = self.group_end(k)
            out.append("(" + self.run(k + 1, end - 1) + ")")
            return end
        if _cmd(self.toks[k]) in ("frac", "dfrac", "tfrac", "sqrt"):  # \sin\frac{\theta}{2} m
            if _cmd(self.toks[k]) == "sqrt":
                end = self.skip_ws(k + 1)
                if end < len(self.toks) and self.toks[end] == "[":
                    end = self._bracket_end(end)
                _, end = self.arg(end)
            else:
                _, end = self.arg(k + 1)
                _, end = self.arg(end)
            out.append("(" + self.run(k, end) + ")")
            return end
        start = k
        end = k
        while True:
            k = end
            while k < len(self.toks) and self.toks[k] == " ":
                k += 1
            if k >= len(self.toks) or self.toks[k] == "\\,":
                break
            tok = self.toks[k]
            if tok.isdigit() or tok == ".":
                end = k + 1
                continue
            if (len(tok) == 1 and tok.isalpha()) or _cmd(tok) in GREEK or _cmd(tok) in _TEXT_COMMANDS:
                got = self.name_atom(k)
                if got is None:
                    break
                count, after = self.primes(got[1])
                if count and end > start:
                    break
                end = after
                m = self.skip_ws(end)
                if count == 0 and m < len(self.toks) and self.toks[m] == "^":
                    _, end = self.arg(m + 1)
                if count:
                    break
                continue
            break
        if end == start:
            out.append(" ")
            return j
        out.append("(" + self.sub(self.toks[start:end]).run() + ")")
        return end

    def frac(self, i: int, out: list[str]) -> int:
        num, j = self.arg(i + 1)
        den, k = self.arg(j)
        order_num, rest = _leibniz_numerator(num)
        order_den = _leibniz_denominator(den)
        if order_num and order_num == order_den:
            if not [t for t in rest if t not in (" ", "\\,")]:
                out.append(" \\frac{d}{dt} " * order_num)
                return k
            sub = self.sub(rest)
            got = sub.name_atom(0)
            if got is not None and sub.skip_ws(got[1]) == len(sub.toks):
                out.append(self.placeholder(got[0], order_num))
                return self.skip_t_argument(k)
            out.append(" \\frac{d}{dt} " * order_num + "(" + self.sub(rest).run() + ")")
            return k
        out.append("\\frac{" + self.sub(num).run() + "}{" + self.sub(den).run() + "}")
        return k


def _compact(tokens: list[str]) -> list[str]:
    """Tokens without spaces, ``\\mathrm{d}`` as ``d`` and ``{2}`` as ``2`` (for Leibniz patterns)."""
    out = [t for t in tokens if not t.isspace()]
    text = "".join(out)
    text = re.sub(r"\\(?:mathrm|text|operatorname|mathit|rm)\{d\}", "d", text)
    text = re.sub(r"\^\{(\d)\}", r"^\1", text)
    return _TOKEN.findall(text)


def _leibniz_numerator(tokens: list[str]) -> tuple[int, list[str]]:
    toks = _compact(tokens)
    if not toks or toks[0] != "d":
        return 0, []
    order, rest = 1, toks[1:]
    if len(rest) >= 2 and rest[0] == "^" and rest[1].isdigit():
        order, rest = int(rest[1]), rest[2:]
    if rest and rest[0].isdigit():
        return 0, []
    return order, rest


def _leibniz_denominator(tokens: list[str]) -> int:
    text = "".join(_compact(tokens))
    m = re.fullmatch(r"dt(?:\^(\d))?|\(dt\)\^(\d)", text)
    if not m:
        return 0
    return int(m.group(1) or m.group(2) or 1)


def _latex_of(name: str) -> str:
    """How a plain name is written in LaTeX, for hints: theta1 -> \\theta_1, l0 -> l_0, p_theta -> p_{\\theta}."""
    m = re.fullmatch(r"([A-Za-z]+?)(\d+)?", name)
    if m and m.group(2):
        base = m.group(1)
        return f"{_latex_of(base)}_{m.group(2)}"
    if "_" in name:
        base, sub = name.split("_", 1)
        sub_tex = _latex_of(sub)
        return f"{_latex_of(base)}_{{{sub_tex}}}" if len(sub_tex) > 1 else f"{_latex_of(base)}_{sub_tex}"
    if name in GREEK:
        return "\\" + name
    if len(name) > 1:
        return f"\\mathrm{{{name}}}"
    return name


def _check_slash(tokens: list[str]) -> None:
    """Refuse ``a/b c``: sympy reads it as a/(b c), which is rarely what was meant."""
    toks = [t for t in tokens if not _is_space(t)]
    n = len(toks)

    def skip_group(i: int, open_: str, close: str) -> int:
        depth = 0
        for j in range(i, n):
            if toks[j] == open_:
                depth += 1
            elif toks[j] == close:
                depth -= 1
                if depth == 0:
                    return j + 1
        return n

    def skip_arg(i: int) -> int:
        if i < n and toks[i] == "{":
            return skip_group(i, "{", "}")
        return min(i + 1, n)

    def skip_left(i: int) -> int:
        depth = 0
        for j in range(i, n):
            if toks[j] == "\\left":
                depth += 1
            elif toks[j] == "\\right":
                depth -= 1
                if depth == 0:
                    return min(j + 2, n)
        return n

    def operand(i: int) -> int:
        if i >= n:
            return n
        tok, cmd = toks[i], _cmd(toks[i])
        if tok == "(":
            return skip_group(i, "(", ")")
        if tok == "{":
            return skip_group(i, "{", "}")
        if cmd == "left":
            return skip_left(i)
        if cmd in ("frac", "dfrac", "tfrac"):
            return skip_arg(skip_arg(i + 1))
        if cmd == "sqrt":
            j = i + 1
            if j < n and toks[j] == "[":
                j = skip_group(j, "[", "]")
            return skip_arg(j)
        if cmd in _TEXT_COMMANDS or cmd in _DERIV_COMMANDS:
            return skip_arg(i + 1) if cmd in _TEXT_COMMANDS else operand(i + 1)
        if cmd in FUNCTIONS:
            j = i + 1
            while j < n and toks[j] in ("^", "_"):
                j = skip_arg(j + 1)
            return operand(j)
        if tok.isdigit():
            j = i
            while j < n and (toks[j].isdigit() or toks[j] == "."):
                j += 1
            return j
        return i + 1

    for i, tok in enumerate(toks):
        if tok != "/":
            continue
        j = operand(i + 1)
        while j < n and toks[j] in ("^", "_", "'"):
            j = j + 1 if toks[j] == "'" else skip_arg(j + 1)
        if j >= n:
            continue
        nxt, cmd = toks[j], _cmd(toks[j])
        starts_factor = (nxt.isalnum() or nxt in ("(", "{", "[")
                         or (cmd is not None and cmd not in ("cdot", "times", "right")))
        if starts_factor:
            def show(part: list[str]) -> str:
                return "".join(t + " " if _cmd(t) and _cmd(t) not in ("left", "right") else t for t in part).strip()
            snippet = f"{show(toks[max(0, i - 1):i])}/{show(toks[i + 1:j])} {show(toks[j:j + 1])}"
            raise LatexAnswerError(
                f"'{snippet}' is ambiguous: sympy would read 'a/b c' as a/(b c); write \\frac{{a}}{{b}} c "
                "(or put the divisor in parentheses)")


# --------------------------------------------------------------------------- names and rebuild

@functools.lru_cache(maxsize=64)
def _coordinate_names(coordinates: tuple[str, ...]) -> tuple[dict[str, Any], dict[str, Any]]:
    """q(t) by name, and q', q'' by their shorthand names (theta_d, thetaddot, ...): made once per
    set of coordinates, since a sympy derivative costs about half a millisecond to build and every
    LaTeX piece of every answer needs the same ones."""
    coords = {check_name(c, "coordinate name"): sp.Function(c)(T) for c in coordinates}
    shorthand: dict[str, Any] = {}
    for name, q in coords.items():
        first, second = q.diff(T), q.diff(T, 2)
        shorthand.update({name + suffix: first for suffix in _FIRST})
        shorthand.update({name + suffix: second for suffix in _SECOND})
    return coords, shorthand


class _Names:
    def __init__(self, coordinates: Sequence[str], known_names: Iterable[str] | None,
                 functions: Mapping[str, int] | None = None) -> None:
        coords, shorthand = _coordinate_names(tuple(coordinates))
        self.coords, self.shorthand = dict(coords), dict(shorthand)  # the reader's own, from shared parts
        self.known = None if known_names is None else set(known_names)
        self.table: dict[str, tuple[str, int]] = {}
        self.functions = {name: n for name, n in (functions or {}).items() if name not in self.coords}

    # names ------------------------------------------------------------------------
    def pool(self) -> set[str]:
        return {"t", "pi", *self.coords, *self.shorthand, *(self.known or ()), *self.functions}

    def is_function(self, raw: str) -> bool:
        """A one-letter general function of the problem (``V``): sympy reads ``V(r)`` as its call."""
        return len(raw) == 1 and raw in self.functions

    def candidates(self, raw: str) -> list[str]:
        flat = raw.replace("\\", "").replace("{", "").replace("}", "").replace(" ", "")
        forms = [flat, flat.replace("_", "")]
        out: list[str] = []
        for form in forms:
            out.append(form)
            aliased = re.sub(r"[A-Za-z]+", lambda m: _GREEK_ALIASES.get(m.group(0), m.group(0)), form)
            out.append(aliased)
            out.append(re.sub(r"[A-Za-z]+", lambda m: _NAME_ALIASES.get(m.group(0), m.group(0)), aliased))
        return list(dict.fromkeys(out))

    def resolve(self, raw: str) -> str:
        """The problem's name for a LaTeX name (``theta_{1}`` -> ``theta1``...)."""
        cands = self.candidates(raw)
        pool = self.pool()
        if self.known is None:
            pool = {"t", "pi", *self.coords, *self.shorthand}
        for c in cands:
            if c in pool:
                return c
        name = cands[0]
        if name == "e":
            return name
        if self.known is not None:
            close = difflib.get_close_matches(name, sorted(self.pool()), n=1)
            hint = f" (did you mean '{close[0]}', written {_latex_of(close[0])}?)" if close else ""
            raise LatexAnswerError(f"unknown name '{name}'{hint}")
        try:
            return check_name(name)
        except RebuildError:
            raise LatexAnswerError(f"'{raw[:40]}' is not a usable name") from None

    def value(self, raw: str, order: int) -> Any:
        name = self.resolve(raw)
        if order:
            if name not in self.coords:
                coords = ", ".join(_latex_of(c) for c in self.coords) or "none"
                raise LatexAnswerError(f"a time derivative (dot or prime) applies to a coordinate, "
                                       f"and '{name}' is not one (coordinates: {coords})")
            if order > MAX_DERIVATIVE_ORDER:
                raise LatexAnswerError(f"derivative order {order} out of range")
            return self.coords[name].diff(T, order)
        if name == "t":
            return T
        if name == "pi":
            return sp.pi
        if name == "e" and (self.known is None or "e" not in self.known):
            return sp.E
        if name in self.coords:
            return self.coords[name]
        if name in self.shorthand:
            return self.shorthand[name]
        return sp.Symbol(name)

    # one item ---------------------------------------------------------------------
    def parse_piece(self, tokens: list[str]) -> Any:
        _check_slash(tokens)
        pre = _Pre(tokens, self).run().strip()
        if not pre:
            raise LatexAnswerError("the answer is empty")
        tree = _sympy_parse(pre)
        if isinstance(tree, sp.Equality):
            lhs, rhs = tree.args
            return sp.Eq(self.build(lhs, 1), self.build(rhs, 1))
        return self.build(tree, 1)

    def build(self, node: Any, depth: int) -> Any:
        if depth > MAX_REBUILD_DEPTH:
            raise LatexAnswerError("the LaTeX answer is nested too deeply")
        d = depth + 1
        if isinstance(node, sp.Symbol):
            if node.name in self.table:
                return self.value(*self.table[node.name])
            return self.value(node.name, 0)
        if isinstance(node, sp.Integer):
            check_int(int(node))
            return node
        if isinstance(node, (sp.Rational, sp.Float)):
            return node
        if node is sp.pi or node is sp.E:
            return node
        if isinstance(node, (sp.Add, sp.Mul)):
            # sympy's parser nests a + b + c as Add(Add(a, b), c): flatten, so long sums are not "deep"
            kind, terms, stack = type(node), [], [node]
            while stack:
                item = stack.pop()
                if type(item) is kind:
                    stack.extend(reversed(item.args))
                else:
                    terms.append(self.build(item, d))
            return kind(*terms)
        if isinstance(node, sp.Pow):
            base, exp = self.build(node.base, d), self.build(node.exp, d)
            check_power(base, exp)
            return base**exp
        if isinstance(node, sp.log):
            args = [self.build(a, d) for a in node.args]
            if len(args) == 2 and args[1] is not sp.E:
                return sp.log(args[0], args[1])
            return sp.log(args[0])
        if type(node) in _FUNCTION_CLASSES:
            return _FUNCTION_CLASSES[type(node)](*[self.build(a, d) for a in node.args])
        if isinstance(node, sp.Derivative):
            expr = self.build(node.expr, d)
            total, spec = 0, []
            for var, count in node.variable_count:
                if var != T:  # d/dr of a general function V(r): r is the coordinate r(t)
                    var = self.build(var, d) if self.functions and isinstance(var, sp.Symbol) else None
                    if var not in self.coords.values():
                        raise LatexAnswerError("only time derivatives d/dt are supported")
                total += int(count)
                spec.append((var, int(count)))
            if not 0 < total <= MAX_DERIVATIVE_ORDER:
                raise LatexAnswerError(f"derivative order {total} out of range")
            check_derivative(expr, total)
            return sp.diff(expr, *spec)
        if isinstance(node, sp.core.function.AppliedUndef):
            return self.applied(node, d)
        if isinstance(node, sp.Equality):
            raise LatexAnswerError("'=' may only be used once, for a whole equation")
        if isinstance(node, sp.core.relational.Relational):
            raise LatexAnswerError("only equations with '=' are allowed, not inequalities")
        what = type(node).__name__
        raise LatexAnswerError(f"'{what}' is not supported in a LaTeX answer")

    def applied(self, node: Any, depth: int) -> Any:
        """``name(arg)``: sympy reads ``\\theta(t)`` and ``m(a + b)`` alike as a function call."""
        fname = node.func.__name__
        name = fname.rstrip("'")
        if name in self.functions:
            args = [self.build(a, depth) for a in node.args]
            primes = len(fname) - len(name)
            if len(args) != self.functions[name] or (primes and len(args) != 1):
                raise LatexAnswerError(f"{name} takes {self.functions[name]} argument(s)"
                                       + (", and a prime needs one" if primes else ""))
            if primes > MAX_DERIVATIVE_ORDER:
                raise LatexAnswerError(f"derivative order {primes} out of range")
            if not primes:
                return sp.Function(name)(*args)
            u = sp.Dummy("u")  # V'(r): the derivative in its argument, at r
            return sp.Subs(sp.Derivative(sp.Function(name)(u), (u, primes)), u, args[0])
        raw, order = self.table.get(fname, (fname, 0))
        if len(node.args) != 1:
            raise LatexAnswerError(f"'{fname}(...)' with several arguments is not supported")
        value = self.value(raw, order)
        arg = self.build(node.args[0], depth)
        if isinstance(value, (sp.core.function.AppliedUndef, sp.Derivative)):
            if arg != T:
                raise LatexAnswerError(f"coordinate {self.resolve(raw)} is a function of t only: write it "
                                       f"without an argument or as {_latex_of(self.resolve(raw))}(t)")
            return value
        return value * arg  # m(a + b) is a product


def _sympy_parse(text: str) -> Any:
    try:
        from sympy.parsing.latex import parse_latex
        from sympy.parsing.latex.errors import LaTeXParsingError
    except ImportError as exc:  # pragma: no cover - the dependency is declared
        raise LatexAnswerError(f"LaTeX answers need sympy's LaTeX parser: {exc}") from None
    tree = latex_subset.read(text, _NUMBERS_READ)  # sympy's converter is imported only if this declines
    if tree is not None:
        return tree
    try:
        return _parse_sll(text)
    except Exception:  # noqa: BLE001  (SLL could not decide: the full parser decides, and words the error)
        pass
    _antlr_converter()
    try:
        return parse_latex(text, strict=True)
    except LaTeXParsingError as exc:
        first = str(exc).splitlines()
        detail = " ".join(line.strip() for line in first[:1])
        raise LatexAnswerError(f"cannot read the LaTeX: {detail[:160]} (in: {text.strip()[:120]})") from None
    except ImportError as exc:
        raise LatexAnswerError(f"LaTeX answers need antlr4-python3-runtime 4.11: {exc}") from None


def _parse_sll(text: str) -> Any:
    """sympy's ``parse_latex(text, strict=True)`` with ANTLR's SLL prediction, the standard two-stage
    strategy: SLL is 5x faster in ANTLR's Python runtime (0.09 s against 0.48 s for a double
    pendulum's answer) and, where it succeeds without a syntax error, gives the full parser's tree; on
    any error the caller runs the full (LL) parser, which decides and words the message."""
    import antlr4
    from antlr4.atn.PredictionMode import PredictionMode

    antlr_latex = _antlr_converter()
    text = text.strip()
    listener = antlr_latex.MathErrorListener(text)
    lexer = antlr_latex.LaTeXLexer(antlr4.InputStream(text))
    lexer.removeErrorListeners()
    lexer.addErrorListener(listener)
    parser = antlr_latex.LaTeXParser(antlr4.CommonTokenStream(lexer))
    parser.removeErrorListeners()
    parser.addErrorListener(listener)
    parser._interp.predictionMode = PredictionMode.SLL
    relation = parser.math().relation()
    if relation.start.start != 0 or relation.stop.stop != len(text) - 1:
        raise ValueError("not the whole text")
    return antlr_latex.convert_relation(relation)


def _antlr_converter() -> Any:
    """sympy's converter from ANTLR's parse tree, reading whole numbers itself.

    The converter makes every number with ``sympy.Number(text)``, which reads the text as Python with
    ``parse_expr``, which imports all of sympy into a fresh namespace first: about 0.3 ms a number, a
    third of the time a LaTeX answer took to read. A whole number in decimal digits is read here, to
    the same Integer; any other text still goes to ``sympy.Number``."""
    from sympy.parsing.latex import _parse_latex_antlr as converter

    if not isinstance(converter.sympy, _WholeNumbersRead):
        converter.sympy = _NUMBERS_READ
    return converter


class _WholeNumbersRead:
    """The ``sympy`` module as the converter sees it: the same, but for ``Number`` of digits."""

    def __init__(self, module: Any) -> None:
        self._module = module

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._module, name)
        setattr(self, name, value)  # looked up once
        return value

    def Number(self, *args: Any) -> Any:  # noqa: N802  (the name the converter calls)
        if len(args) == 1 and isinstance(args[0], str) and is_whole_number(args[0]):
            return sp.Integer(int(args[0]))
        return self._module.Number(*args)


#: the ``sympy`` namespace both readers build with, made without importing sympy's converter: that
#: import deserializes ANTLR's LaTeX grammar, 0.65 s of CPU, which an answer the subset reader reads
#: (every LaTeX answer of a class, as a rule) never needs
_NUMBERS_READ = _WholeNumbersRead(sp)


def is_whole_number(text: str) -> bool:
    """Decimal digits with no leading zero, which is what ``sympy.Number`` reads as an Integer
    (it refuses 007, as Python does)."""
    return text.isascii() and text.isdigit() and (text == "0" or text[0] != "0")
