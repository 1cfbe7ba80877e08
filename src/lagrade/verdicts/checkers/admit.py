"""When agreement at sampled points may accept an answer, and when only a proof may.

Agreement at random points proves two expressions equal only when the answer is of the asked form,
real, and analytic in its arguments: a nonzero analytic difference vanishes on a set of measure zero,
which random points miss. A branch construct (``Piecewise``, ``Heaviside``, ``Max``, ``sign``, ...)
can be right on the sampled region and wrong beyond it; a number that is not exact (``1.000000001``,
a 3000-digit float) can be wrong by less than any tolerance. So every student expression is screened
here as it is read (`lagrade.verdicts.checkers.base.read_sympy`, the one door every checker reads through):

- numbers: a float within 1e-12 of a simple number (p/q with q <= 1000, or that times pi or sqrt(k))
  is read as that number; any other float, a rational with a large denominator, or a constant far from
  unit size is *flagged*;
- reality: an expression with ``I`` (or another non-real constant) is evaluated at sampled states in
  complex arithmetic, and an imaginary part refutes it (`Refuted`);
- the analytic class: any node outside an allowlist of analytic functions is *flagged*, unless the
  scene declares dry friction or drag and it switches on a velocity (or momentum) only, with both
  branches reached by the sampled states.

A flagged expression earns credit only through a symbolic proof: the checkers attempt one whenever
`pending` says so and call `proved`; `admitted`, wrapped around every checker, refuses any credit
that still rests on an unproved flagged expression. The rule, in words, is in docs/answers.md.
"""

from __future__ import annotations

import time
import weakref
from collections.abc import Callable
from contextvars import ContextVar
from dataclasses import dataclass, field
from fractions import Fraction
from functools import wraps

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from lagrade.compare.equations import slopes
from lagrade.derive.effects import DISSIPATION
from lagrade.verdicts.result import PartResult
from lagrade.problem.spec import Part

#: inverse functions: on their principal branch they fold a variable argument back (acos(cos(u)) is
#: |u|) or switch (atan(1/u) + atan(u) is pi/2 sign(u)), so a variable one needs a proof; a motion q(t)
#: is judged by the equation it satisfies, which a fold does not
INVERSE_FUNCTIONS = frozenset({"asin", "acos", "atan", "acot", "asec", "acsc", "atan2",
                               "asinh", "acosh", "atanh", "acoth", "asech", "acsch", "LambertW"})
MOTION_KINDS = frozenset({"trajectory", "numerical_solution"})
#: functions analytic in their arguments wherever they are defined (their only singular sets are
#: branch cuts and poles, of measure zero): agreement at random points decides for these
ANALYTIC_FUNCTIONS = frozenset({
    "sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "acot", "asec", "acsc", "atan2",
    "sinh", "cosh", "tanh", "coth", "sech", "csch", "asinh", "acosh", "atanh", "acoth", "asech", "acsch",
    "exp", "log", "LambertW", "erf", "erfc", "gamma", "loggamma", "sinc",
    "elliptic_k", "elliptic_e", "elliptic_f", "elliptic_pi", "besselj", "bessely",
})
#: switches a declared dissipative effect calls for, when they switch on a velocity or momentum
FRICTION_SWITCHES = frozenset({"Abs", "sign", "Heaviside", "Piecewise"})
#: kinds whose answers are numbers compared within the preset's tolerance (a fitted or tabulated motion)
NUMERIC_KINDS = frozenset({"numerical_solution"})
#: a float is read as a simple number p/q (q <= SIMPLE_DENOMINATOR), or p/q times one of these
SIMPLE_DENOMINATOR = 1000
SIMPLE_FACTORS = (sp.S.One, sp.pi, *(sp.sqrt(k) for k in (2, 3, 5, 6, 7, 10)))
FLOAT_TOLERANCE = 1e-12
#: constants outside this range of sizes are not unit-sized numbers a formula has: an exp(-1000), a 1e-9
CONSTANT_SIZES = (1e-6, 1e6)
#: a part of an expression whose effect on the whole is below this share of it at every sampled state
#: cannot change a comparison made within a relative tolerance of 1e-6 (nor can anything of its size
#: that is wrong): sampling does not see it, so only a proof may accept the expression
NEGLIGIBLE = 1e-5
#: operations beyond which an expression is not weighed part by part but needs a proof (no honest
#: answer comes near; weighing costs about a microsecond an operation)
NEGLIGIBLE_NODES = 100_000
#: seconds the proofs that small parts are exactly zero may take, for one expression together
ZERO_PROOF_SECONDS = 2.0


class Refuted(Exception):
    """An answer that is wrong for a reason the screen itself found (an imaginary part, equations with
    other solutions): the part is ``incorrect`` with this sentence, whatever the sampled values say."""


@dataclass
class Screen:
    """What the reading of one part's value found: flagged expressions, each with why, and which of
    them a proof (or a verdict without credit) has settled."""

    flagged: dict[sp.Basic, str] = field(default_factory=dict)
    settled: set[sp.Basic] = field(default_factory=set)
    #: certificates of the refutations found while grading the part (`witness`)
    certificates: list = field(default_factory=list)
    #: refutations at sampled states that could not be certified
    uncertified: int = 0

    def pending(self, expr: sp.Basic | None = None) -> list[str]:
        """Reasons not yet settled (for ``expr`` alone, or for every flagged expression)."""
        return [why for e, why in self.flagged.items() if e not in self.settled and (expr is None or e == expr)]

    def settle(self, expr: sp.Basic | None = None) -> None:
        self.settled |= {e for e in self.flagged if expr is None or e == expr}


_SCREEN: ContextVar[Screen | None] = ContextVar("lagrade_admit_screen", default=None)


def pending(expr: sp.Basic | None = None) -> list[str]:
    """Why sampling alone may not accept (``expr``, or anything read for the part being graded)."""
    screen = _SCREEN.get()
    return screen.pending(expr) if screen is not None else []


def proved(expr: sp.Basic | None = None) -> None:
    """A proof has shown ``expr`` (None: the part's whole answer) equal to the reference."""
    screen = _SCREEN.get()
    if screen is not None:
        screen.settle(expr)


def unproved(expr: sp.Basic) -> str | None:
    """Settle ``expr`` as earning nothing and say why, or None when nothing about it was flagged."""
    reasons = pending(expr)
    if not reasons:
        return None
    proved(expr)
    return _reasons(reasons)


def flag(expr: sp.Basic, why: str) -> None:
    """``expr`` needs a proof for a reason found after reading it (the exact judge could not model it:
    `lagrade.compare.exact.outside`), unless the screen has flagged it already."""
    screen = _SCREEN.get()
    if screen is not None and not screen.pending(expr):
        screen.flagged[expr] = why
        screen.settled.discard(expr)


def witness(certificate) -> None:
    """A refutation at sampled states, with its certificate (`lagrade.compare.certify`) or None."""
    screen = _SCREEN.get()
    if screen is None:
        return
    if certificate is None:
        screen.uncertified += 1
    else:
        screen.certificates.append(certificate)


def _reasons(reasons: list[str]) -> str:
    unique = list(dict.fromkeys(reasons))
    return "; ".join(unique[:3])


# ----------------------------------------------------------------------------- the screen


def screen(expr: sp.Expr, part: Part, mech) -> sp.Expr:
    """``expr`` (in state symbols) with its simple floats made exact; records what makes sampling
    insufficient, and raises `Refuted` for an answer with an imaginary part."""
    notes: list[str] = []
    constants = None
    if part.kind not in NUMERIC_KINDS:  # a numerical solution is numbers, compared within a tolerance
        expr, notes, constants = _numbers(expr)
        notes += _constructs(expr, part, mech)
        notes += _negligible(expr, part, mech)
    if _maybe_complex(expr, constants):
        _reality(expr, part, mech)
    current = _SCREEN.get()
    if notes and current is not None:  # each reading is pending anew (two entries may be the same expression)
        current.flagged[expr] = _reasons(notes)
        current.settled.discard(expr)
    return expr


def _numbers(expr: sp.Expr) -> tuple[sp.Expr, list[str], list[sp.Basic]]:
    """Floats near a simple number become it; other floats become their exact value and are noted
    (the first few), as are rationals with large denominators and constants far from unit size.
    Returns the expression, the notes and its `_constants` (which `_maybe_complex` reads too)."""
    notes: list[str] = []
    for r in expr.atoms(sp.Rational):
        if r.q > SIMPLE_DENOMINATOR * 1000 or abs(r.p) > 10 ** 12:
            notes.append(f"the number {_short(r)} is not a simple fraction")
    exact: dict[sp.Basic, sp.Basic] = {}
    for f in sorted(expr.atoms(sp.Float), key=lambda x: abs(x)):
        simple = simple_number(f)
        if simple is not None:
            exact[f] = simple
            continue
        near = _nearest(f)
        off = f" ({_g(abs(f - near))} from {near}, the nearest simple number)" if near is not None else ""
        notes.append(f"the number {_short(f)} is not exact{off}")
        exact[f] = sp.Rational(f)
    expr = expr.xreplace(exact) if exact else expr
    constants = _constants(expr)
    for c in constants:
        try:  # in sympy's floats: exp(-1000) is below the smallest double
            size = abs(c.evalf(20))
            small, large = bool(size < CONSTANT_SIZES[0]), bool(size > CONSTANT_SIZES[1])
        except (TypeError, ValueError):
            continue
        if not size.is_zero and (small or large):
            notes.append(f"the constant {_short(c)} (about {_g(size)}) is far from the size of a formula's numbers")
            continue
        near = _near_simple(c)
        if near is not None:
            notes.append(f"the constant {_short(c)} is within {_g(abs(c.evalf(50) - near.evalf(50)))} of {near} "
                         "without being equal to it")
    return expr, notes, constants


def _short(x: sp.Basic) -> str:
    text = sp.sstr(x) if not isinstance(x, sp.Float) else sp.sstr(sp.Float(x, min(x._prec, 60) if x._prec > 53 else 15))
    return text if len(text) <= 40 else text[:18] + "..." + text[-12:]


def _g(x: float | sp.Basic) -> str:
    """A size in two digits, however small (a 3000-digit float off by 1e-2900 says so)."""
    return sp.sstr(sp.Float(x, 2)) if isinstance(x, sp.Basic) else f"{x:.1e}"


def simple_number(f: sp.Float) -> sp.Expr | None:
    """The simple number a float stands for: p/q (q <= 1000), or that times pi or sqrt(k), within
    1e-12 relative; a float typed with more digits than a double holds must equal it to all of them."""
    if f.is_zero:
        return sp.S.Zero
    prec = f._prec
    tol = FLOAT_TOLERANCE if prec <= 64 else max(2.0 ** (8 - prec), 0.0)
    for factor in SIMPLE_FACTORS:
        ratio = f / factor
        try:
            frac = Fraction(float(ratio)).limit_denominator(SIMPLE_DENOMINATOR)
        except (OverflowError, ValueError):
            return None
        if frac == 0:
            continue
        candidate = sp.Rational(frac.numerator, frac.denominator) * factor
        rel = abs(sp.Float(f, max(prec, 53) // 3 + 5) - candidate.evalf(max(prec, 53) // 3 + 5)) / abs(candidate)
        if rel <= tol:
            return candidate
    return None


def _near_simple(c: sp.Expr) -> sp.Expr | None:
    """A simple number a constant expression is within 1e-9 of (relative) but not equal to, to 40
    digits: (1 + 1/10**6)**(1/1000) or sqrt(1 + 10**-10) stand for 1 as a float would, and are not."""
    try:
        value = c.evalf(50)
        if not value.is_real or value.is_zero:
            return None
        near = None
        for factor in SIMPLE_FACTORS:
            frac = Fraction(float(value / factor)).limit_denominator(SIMPLE_DENOMINATOR)
            candidate = sp.Rational(frac.numerator, frac.denominator) * factor
            if candidate.is_zero:
                continue
            rel = abs((value - candidate.evalf(50)) / value)
            if rel <= 1e-40:
                return None  # equal to a simple number: 2*pi, sqrt(8)/2
            if rel <= 1e-9 and near is None:
                near = candidate
        return near
    except (TypeError, ValueError, OverflowError, ZeroDivisionError):
        return None


def _nearest(f: sp.Float) -> sp.Rational | None:
    try:
        frac = Fraction(float(f)).limit_denominator(SIMPLE_DENOMINATOR)
    except (OverflowError, ValueError):
        return None
    return sp.Rational(frac.numerator, frac.denominator)


def _constants(expr: sp.Basic) -> list[sp.Basic]:
    """The largest constant subexpressions that are not plain numbers: the product of a term's constant
    factors, the sum of a sum's constant terms (10**(497/500)*1000001**(1/1000)/10, exp(-1000))."""
    out, stack = [], [expr]
    while stack:
        e = stack.pop()
        if e.is_Atom:
            continue
        if not isinstance(e, sp.Expr):  # a Piecewise's (value, condition) pairs, conditions
            stack.extend(e.args)
            continue
        if not e.free_symbols:
            out.append(e)
            continue
        if e.is_Add or e.is_Mul:
            const, rest = _independent(e)
            if not const.is_Atom:
                out.append(const)
            stack.extend(sp.Add.make_args(rest) if e.is_Add else sp.Mul.make_args(rest))
            continue
        stack.extend(e.args)
    return out


def _independent(e: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``e.as_independent(*e.free_symbols, as_Add=e.is_Add)`` for a sum or product, the same expressions,
    built as sympy builds them. sympy sifts the arguments by ``a.has(*(a.free_symbols & symbols))``, a
    search of each argument's tree; where every free symbol of a commutative ``e`` is a Symbol that is
    exactly "the argument has a free symbol", which this tests instead."""
    from sympy.core.add import _unevaluated_Add
    from sympy.core.mul import _unevaluated_Mul

    free = e.free_symbols
    if not e.is_commutative or not all(isinstance(s, sp.Symbol) for s in free):
        return e.as_independent(*free, as_Add=e.is_Add)
    args = list(e.args) if e.is_Add else e.args_cnc()[0]
    indep = [a for a in args if not a.free_symbols]
    depend = [a for a in args if a.free_symbols]
    if e.is_Add:
        return sp.Add(*indep), _unevaluated_Add(*depend)
    return sp.Mul(*indep), _unevaluated_Mul(*depend)


def _constructs(expr: sp.Expr, part: Part, mech) -> list[str]:
    """Nodes outside the analytic class, named for the student, except the switches a declared
    friction or drag calls for (on velocities or momenta only, both branches sampled)."""
    notes: list[str] = []
    seen: set[sp.Basic] = set()
    stack = [expr]
    allowed_vars = _switch_variables(mech, part)
    functions = set(getattr(mech, "functions", {}) or {})
    positive = {p.name for p in mech.parameters if p.positive}
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if e.is_Atom:
            if e in (sp.oo, -sp.oo, sp.zoo, sp.nan):
                notes.append(f"{e} is not a value a physical quantity takes")
            continue
        name = type(e).__name__
        if e.is_Add or e.is_Mul:
            stack.extend(e.args)
        elif e.is_Pow:
            if not e.exp.is_Integer:
                hidden = _hidden_switch(e, positive)
                if hidden:
                    notes.append(hidden)
                    continue
            stack.extend(e.args)
        elif name in ANALYTIC_FUNCTIONS:
            folded = _folded(e)
            if folded:
                notes.append(folded)
                continue
            if name in INVERSE_FUNCTIONS and e.free_symbols and part.kind not in MOTION_KINDS:
                notes.append(f"it takes {name} of a quantity that varies: an inverse function can fold or switch "
                             "where no state was tried")
                continue
            stack.extend(e.args)
        elif isinstance(e, AppliedUndef) and e.func.__name__ in functions:
            stack.extend(e.args)
        elif isinstance(e, (sp.Derivative, sp.Subs)) and any(
                isinstance(a, AppliedUndef) and a.func.__name__ in functions for a in e.atoms(AppliedUndef)):
            stack.extend(a for a in e.args if isinstance(a, sp.Basic))
        elif name in FRICTION_SWITCHES and allowed_vars and _friction_switch(e, allowed_vars, mech, part):
            stack.extend(_switch_parts(e))
        elif name in FRICTION_SWITCHES and e.free_symbols & {*mech.s.qd, *mech.s.p} and not allowed_vars:
            notes.append(f"it uses {name} of a velocity: {UNDECLARED_FRICTION}")
        else:
            notes.append(_construct_words(e))
    return notes


#: dry friction in a scene without it, in the screen's words (a refusal's, and a wrong eom's feedback)
UNDECLARED_FRICTION = "a velocity-dependent switch (dry friction) that this problem does not have"


def _construct_words(e: sp.Basic) -> str:
    name = type(e).__name__
    if isinstance(e, sp.core.relational.Relational) or isinstance(e, sp.logic.boolalg.Boolean):
        return "a condition (a comparison or a logical connective) is not a value"
    words = {"Piecewise": "Piecewise (a formula that switches between cases)",
             "Heaviside": "Heaviside (a step)", "Max": "Max", "Min": "Min", "sign": "sign", "Abs": "Abs",
             "floor": "floor", "ceiling": "ceiling", "frac": "frac", "DiracDelta": "DiracDelta", "Mod": "Mod",
             "re": "re", "im": "im", "arg": "arg", "conjugate": "conjugate", "AccumBounds": "AccumBounds"}
    return f"it uses {words.get(name, name)}, which switches or is not analytic"


def _hidden_switch(e: sp.Pow, positive: set[str]) -> str | None:
    """sqrt(u**2) is |u| on the real domain: a root of a square is a switch written as a power
    (parameters declared positive are taken so: sqrt(g**2) is g). The base is factored first, so a
    square multiplied out (sqrt(m1**2 - 100*m1 + 2500), |m1 - 50|) is seen too."""
    real = {s: sp.Symbol(s.name, positive=True) if s.name in positive else sp.Symbol(s.name, real=True)
            for s in e.free_symbols if isinstance(s, sp.Symbol)}
    if not real or sp.count_ops(e) > 200:
        return None
    try:
        refined = e.xreplace(real)
        base = refined.base if isinstance(refined, sp.Pow) else None
        # factoring is fast for small polynomials; no alarm here (an inner alarm would upset a caller's)
        if not refined.has(sp.Abs, sp.sign, sp.Piecewise) and base is not None and base.is_Add \
                and base.free_symbols and len(base.free_symbols) <= 4 and base.is_polynomial() \
                and sp.Poly(base).total_degree() <= 8:
            refined = sp.Pow(sp.factor(base), refined.exp)
    except Exception:  # noqa: BLE001  (nothing hidden that sympy can see)
        return None
    if refined.has(sp.Abs, sp.sign, sp.Piecewise):
        return "it takes a root of a square, which is an absolute value (a switch) in disguise"
    return None


#: an inverse function of the periodic function it undoes only on one period: acos(cos(u)) is |u| near
#: 0 and a sawtooth beyond; asin(cos(u)) is pi/2 - |u|
_FOLDS = {"asin": ("sin", "cos"), "acos": ("cos", "sin"), "atan": ("tan", "cot"), "acot": ("cot", "tan"),
          "asec": ("sec", "csc"), "acsc": ("csc", "sec")}


def _folded(e: sp.Basic) -> str | None:
    """An inverse trigonometric function of exactly a trigonometric function of a variable, or an
    ``atan2`` whose first argument is 0 (the sign of the second, times pi): switches written with
    analytic names, right on the sampled range and wrong beyond it."""
    name = type(e).__name__
    if name == "atan2":
        y, x = e.args
        if y.is_zero and x.free_symbols:
            return "it takes atan2(0, u), which is 0 or pi by the sign of u (a switch)"
        if isinstance(y, (sp.sin, sp.cos)) and isinstance(x, (sp.sin, sp.cos)) and y.args[0].free_symbols:
            return f"it takes {sp.sstr(e)}, an angle folded into one period (a switch)"
        return None
    arg = e.args[0] if e.args else None
    if name in _FOLDS and arg is not None and type(arg).__name__ in _FOLDS[name] and arg.args[0].free_symbols:
        return f"it takes {name}({type(arg).__name__}(...)), an angle folded into one period (a switch)"
    return None


def _switch_variables(mech, part: Part) -> set[sp.Symbol]:
    """Velocities (and momenta) a declared dissipative force may switch on: only those whose sampled
    range has both signs, so both branches are seen."""
    if not set(mech.system.effects) & DISSIPATION:
        return set()
    coords = {c.name: c for c in mech.system.coordinates}
    out: set[sp.Symbol] = set()
    for name, qd, p in zip(mech.names, mech.s.qd, mech.s.p):
        lo, hi = coords[name].velocity
        if lo < 0 < hi:
            out |= {qd, p}
    return out


def _switch_parts(e: sp.Basic) -> list[sp.Basic]:
    if isinstance(e, sp.Piecewise):
        return [x for pair in e.args for x in (pair.expr, *_relation_sides(pair.cond))]
    return list(e.args)


def _relation_sides(cond: sp.Basic) -> list[sp.Basic]:
    if isinstance(cond, sp.core.relational.Relational):
        return [cond.lhs - cond.rhs]
    return []


def _friction_switch(e: sp.Basic, allowed: set[sp.Symbol], mech, part: Part) -> bool:
    """A switch on velocities (momenta) and parameters only, of a form friction takes, with both of
    its branches reached by the sampled states."""
    params = set(mech.params) | {sp.Symbol(s) for s in part.symbols}
    if isinstance(e, sp.Piecewise):
        if len(e.args) != 2 or e.args[1].cond != sp.true or not isinstance(e.args[0].cond, sp.core.relational.Relational):
            return False
        arguments = [e.args[0].cond.lhs - e.args[0].cond.rhs]
    else:
        arguments = [e.args[0]]
    for arg in arguments:
        free = arg.free_symbols
        if not free & allowed or not free <= allowed | params:
            return False
        if any(sp.diff(arg, v).has(*allowed) for v in free & allowed):  # a half-space per branch: linear
            return False
        if not _both_signs(arg, mech, part):
            return False
    return True


def _both_signs(arg: sp.Expr, mech, part: Part) -> bool:
    """Do the sampled states reach both sides of ``arg = 0``, at least three of them each?"""
    with np.errstate(all="ignore"):
        values = _at_samples(arg, mech, part, "switch").real
    values = values[np.isfinite(values)]
    return bool(np.sum(values > 0) >= 3 and np.sum(values < 0) >= 3)


def _maybe_complex(expr: sp.Basic, constants: list[sp.Basic] | None = None) -> bool:
    """I, or a constant that is not real (asin(2) - pi/2, (-1)**(1/3)): evaluated in complex arithmetic,
    which numpy's real evaluation would turn into its real part. ``constants``: ``_constants(expr)``
    when the caller has them."""
    if expr.has(sp.I):
        return True
    for c in _constants(expr) if constants is None else constants:
        try:
            if sp.im(c.evalf(30)) != 0:
                return True
        except (TypeError, ValueError):
            return True
    return False


#: numpy's functions for the screen's own evaluation of a tree, node by node (`_negligible`)
_NUMPY = {"sin": np.sin, "cos": np.cos, "tan": np.tan, "exp": np.exp, "log": np.log, "sinh": np.sinh,
          "cosh": np.cosh, "tanh": np.tanh, "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan,
          "asinh": np.arcsinh, "acosh": np.arccosh, "atanh": np.arctanh,
          "cot": lambda x: 1 / np.tan(x), "sec": lambda x: 1 / np.cos(x), "csc": lambda x: 1 / np.sin(x),
          "coth": lambda x: 1 / np.tanh(x), "sech": lambda x: 1 / np.cosh(x), "csch": lambda x: 1 / np.sinh(x)}


def _negligible(expr: sp.Expr, part: Part, mech) -> list[str]:
    """Parts of ``expr`` too small to matter at every state the comparison samples: a term of a sum, an
    argument of a function or an exponent whose effect on the whole is below :data:`NEGLIGIBLE` of it
    at each of them (``L + m1*g*l1*theta1*(m1*m2/(m1 + m2)**2)**200``, ``L*cos((m1/(m1 + m2))**300)``,
    ``a*(m1 + 10**11)/(m2 + 10**11)``). Such a part is wrong or right unseen: the comparison at
    sampled states cannot decide it. A part proved zero (an identity left unsimplified) is not one.

    The states are the comparison's own (`comparison_states`): a part visible at some state of the
    rule's but at none of the comparison's (a spike placed at one) would otherwise escape both. The
    effect of a part is its size times how much the whole changes with it (reverse-mode derivatives
    through sums, products, powers and the analytic functions, in complex floating point, node by
    node: no code is generated but for functions numpy has no twin of), and the whole's size is taken
    without cancellation (a sum's is the sum of its terms' sizes). A general function, a derivative or
    a switch (the other rules judge those) is evaluated whole and not looked into, or stands for an
    unknown value when it cannot be evaluated. An expression of more than
    :data:`NEGLIGIBLE_NODES` operations is not weighed, and needs a proof for that."""
    if expr.is_Atom or not expr.free_symbols:
        return []
    size_ops = sp.count_ops(expr, visual=False)
    too_long = [f"it is too long ({size_ops} operations) to be weighed part by part"]
    if size_ops > NEGLIGIBLE_NODES:
        return too_long
    free = sorted(expr.free_symbols, key=str)
    sets = comparison_states(free, mech, part)
    value: dict[sp.Basic, np.ndarray] = {x: np.concatenate([v[x] for v in sets]) for x in free}
    K = len(value[free[0]])
    opaque: set[sp.Basic] = set()
    stand_in = np.random.default_rng(0)

    def whole_node(e: sp.Basic) -> np.ndarray:
        inner = sorted(e.free_symbols, key=str)
        f = sp.lambdify(inner, e, modules=["numpy", "scipy"])
        try:
            return np.broadcast_to(np.asarray(f(*[value[x] for x in inner]), dtype=complex), (K,))
        except TypeError:  # a real function (atan2) given complex arrays: real values, imaginary parts ~0
            return np.broadcast_to(np.asarray(f(*[np.real(value[x]) for x in inner]), dtype=complex), (K,))

    def ev(e: sp.Basic) -> np.ndarray:
        v = value.get(e)
        if v is not None:
            return v
        if e.is_Number or e.is_NumberSymbol:
            v = np.full(K, complex(e))
        elif e.is_Add:
            v = sum((ev(a) for a in e.args), np.zeros(K, dtype=complex))
        elif e.is_Mul:
            v = np.ones(K, dtype=complex)
            for a in e.args:
                v = v * ev(a)
        elif e.is_Pow:
            v = ev(e.args[0]) ** ev(e.args[1])
        elif isinstance(e, sp.Function) and len(e.args) == 1 and type(e).__name__ in _NUMPY:
            v = _NUMPY[type(e).__name__](ev(e.args[0]))
        elif isinstance(e, sp.Function) and type(e).__name__ in ANALYTIC_FUNCTIONS:
            for a in e.args:
                ev(a)
            v = whole_node(e)
        else:
            opaque.add(e)
            try:
                v = whole_node(e)
            except Exception:  # noqa: BLE001  (a general function, a derivative of one: an unknown value)
                v = stand_in.uniform(0.5, 1.5, K).astype(complex)
        value[e] = v
        return v

    def slope(e: sp.Basic, i: int) -> np.ndarray:
        return np.abs(ev(e.fdiff(i + 1)))

    try:
        with np.errstate(all="ignore"):
            ev(expr)
            # the whole's size without cancellation (sums of sizes, products of sizes): an L that
            # passes through zero at one state must not make every part look large there
            size: dict[sp.Basic, np.ndarray] = {}

            def magnitude(e: sp.Basic) -> np.ndarray:
                m = size.get(e)
                if m is None:
                    if e.is_Add:
                        m = sum((magnitude(a) for a in e.args), np.zeros(K))
                    elif e.is_Mul:
                        m = np.ones(K)
                        for a in e.args:
                            m = m * magnitude(a)
                    else:
                        m = np.abs(value[e])
                    size[e] = m
                return m

            whole = magnitude(expr)
            # how much the whole moves per unit of each part, summed over the paths from the root
            weight: dict[sp.Basic, np.ndarray] = {}
            walk, steps = [(expr, np.ones(K))], 0
            while walk:
                e, w = walk.pop()
                steps += 1
                if steps > 4 * NEGLIGIBLE_NODES:
                    return too_long
                weight[e] = weight.get(e, 0.0) + w
                if e.is_Atom or e in opaque:
                    continue
                if e.is_Add:
                    walk.extend((a, w) for a in e.args)
                elif e.is_Mul:
                    for i, a in enumerate(e.args):
                        others = np.ones(K, dtype=complex)
                        for j, b in enumerate(e.args):
                            if j != i:
                                others = others * value[b]
                        walk.append((a, w * np.abs(others)))
                elif e.is_Pow:
                    b, x = e.args
                    walk.append((b, w * np.abs(value[x] * value[b] ** (value[x] - 1))))
                    if not x.is_Atom:
                        walk.append((x, w * np.abs(value[e] * np.log(value[b]))))
                else:
                    walk.extend((a, w * slope(e, i)) for i, a in enumerate(e.args))
            # each part with the weight of its place (a symbol used elsewhere too weighs more there)
            candidates = []
            for e in [e for e in weight if e not in opaque and not e.is_Atom]:
                w = weight[e]
                if e.is_Add:
                    candidates += [(a, w) for a in e.args]
                elif e.is_Pow and not e.args[1].is_Atom:
                    candidates.append((e.args[1], w * np.abs(value[e] * np.log(value[e.args[0]]))))
                elif not (e.is_Mul or e.is_Pow):
                    candidates += [(a, w * slope(e, i)) for i, a in enumerate(e.args)]
    except (TypeError, ValueError, ZeroDivisionError, OverflowError, RecursionError,
            sp.core.function.ArgumentIndexError):  # what cannot be weighed is compared, and judged, elsewhere
        return []
    notes = []
    proof_deadline = time.monotonic() + ZERO_PROOF_SECONDS  # shared: many small parts cost no more
    bounds = np.cumsum([0, *(len(next(iter(v.values()))) for v in sets)])
    for a, wa in candidates:
        effect = wa * (np.abs(value[a]) if a in value else abs(complex(a)))
        small = (effect <= NEGLIGIBLE * whole) | ~np.isfinite(whole) | (whole <= 0) | ~np.isfinite(effect)
        seen = np.isfinite(whole) & (whole > 0) & np.isfinite(effect)
        unseen = any(seen[lo:hi].sum() >= (hi - lo) // 2 and small[lo:hi].all() for lo, hi in zip(bounds, bounds[1:]))
        if unseen and not _proved_zero(a, mech, proof_deadline):
            notes.append(f"the part {_short(a)} changes the whole by less than {NEGLIGIBLE:g} of it at every "
                         "state tried (too small for sampling to see)")
            if len(notes) >= 3:
                break
    return notes


#: states the comparison samples (`lagrade.verdicts.checkers.base.Context.points`)
SAMPLED_STATES = 24


#: mech -> (part, symbols) -> the states `comparison_states` gives: a function of those alone (seeded), the
#: same for every answer to the part; kept beside the scene, not in it (the references' disk cache)
_STATES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def comparison_states(free: list[sp.Symbol], mech, part: Part) -> list[dict[sp.Symbol, np.ndarray]]:
    """The states at which the checkers compare a part, as arrays for the symbols ``free``: the
    values' and equations' (``rng_for(problem, part)``), and the same with parameters shared by groups
    of four (the Lagrangian's, `dynamics._grouped_points`). The momenta are the true ones at the
    sampled velocities, as the checkers compare them (uniform ones missed a term large only where the
    true momenta never go); symbols they do not sample (a part's own names) get values of their own.
    Computed once per part and symbols (read-only arrays)."""
    key = (mech.problem.id, part.name, tuple(part.symbols), tuple(sorted(part.symbol_domains.items())), tuple(free))
    try:
        known = _STATES.setdefault(mech, {})
    except TypeError:  # not weakly referable: computed each time
        known = {}
    if key not in known:
        if len(known) >= 256:
            known.clear()
        known[key] = _comparison_states(free, mech, part)
    return known[key]


def _comparison_states(free: list[sp.Symbol], mech, part: Part) -> list[dict[sp.Symbol, np.ndarray]]:
    from lagrade.compare.sampling import grouped, rng_for, sample_points, state_arrays

    def base():
        return sample_points(mech, SAMPLED_STATES, rng_for(mech.problem.id, part.name), extra=part.symbol_domains)

    rng = rng_for(mech.problem.id, part.name, "negligible", "other")
    out = []
    for pts in (base(), grouped(base(), mech, part.symbols)):
        values = dict(pts.values)
        if mech.s.p:
            try:
                with np.errstate(all="ignore"):
                    values.update(zip(mech.s.p, mech.momenta(*state_arrays(mech, pts))))
            except Exception:  # noqa: BLE001  (a scene without a Legendre transform: momenta of their own)
                pass
        out.append(_filled(values, free, mech, rng, SAMPLED_STATES))
    return out


def _filled(values: dict, free: list[sp.Symbol], mech, rng: np.random.Generator, K: int) -> dict:
    """``values`` for the symbols ``free`` as complex arrays of ``K``: momenta not given any real ones
    (reality and branch signs are all that is asked of them then), other symbols the states do not
    sample (a part's own names) values in [0.5, 1.5]."""
    for p in mech.s.p:
        values.setdefault(p, rng.uniform(-1.5, 1.5, K))
    return {s: np.broadcast_to(np.asarray(values[s] if s in values else rng.uniform(0.5, 1.5, K), dtype=complex),
                               (K,)) for s in free}


def _proved_zero(e: sp.Basic, mech, deadline: float) -> bool:
    """An unsimplified identity (``sin(a - b) - sin(a)*cos(b) + cos(a)*sin(b)``) is zero, not small;
    the proofs of one expression's parts share :data:`ZERO_PROOF_SECONDS` (what is left unproved is flagged)."""
    from lagrade.compare.symbolic import proves_all_zero

    if not e.free_symbols:
        return bool(e.is_zero)
    left = deadline - time.monotonic()
    return left > 0 and bool(proves_all_zero([e], min(1.0, left), {p.name for p in mech.parameters if p.positive}))


def _reality(expr: sp.Expr, part: Part, mech) -> None:
    """An imaginary part at any sampled state refutes: every quantity of these problems is real."""
    # constants as sympy evaluates them (numpy's arcsin(2) is NaN, not complex)
    expr = expr.replace(lambda e: not e.is_Atom and isinstance(e, sp.Expr) and not e.free_symbols
                        and (isinstance(e, sp.Function) or e.is_Pow), lambda e: e.evalf(20))
    with np.errstate(all="ignore"):
        values = _at_samples(expr, mech, part, "reality")
    finite = np.isfinite(values)
    size = np.abs(values[finite])
    if finite.any() and np.any(np.abs(values[finite].imag) > 1e-9 * np.maximum(size, 1e-300)):
        raise Refuted("it has an imaginary part (it contains I, or a root or power of a negative number), "
                      "and every quantity in this problem is real")


def _at_samples(expr: sp.Expr, mech, part: Part, purpose: str, K: int = 24) -> np.ndarray:
    """``expr`` in complex arithmetic at the part's kind of sampled states (every symbol of the scene
    from its range; any other symbol uniform in [0.5, 1.5])."""
    free = sorted(expr.free_symbols, key=str)
    f = sp.lambdify(free, expr, modules=["numpy"])
    out = f(*_sample_args(free, mech, part, purpose, K)) if free else f()
    return np.broadcast_to(np.asarray(out, dtype=complex), (K,))


def _sample_args(free: list[sp.Symbol], mech, part: Part, purpose: str, K: int) -> list[np.ndarray]:
    """Complex arrays of ``K`` sampled values for the symbols ``free`` (as `_at_samples` says)."""
    from lagrade.compare.sampling import rng_for, sample_points

    pts = sample_points(mech, K, rng_for(mech.problem.id, part.name, purpose), extra=part.symbol_domains)
    return list(_filled(dict(pts.values), free, mech, rng_for(mech.problem.id, part.name, purpose, "other"), K).values())


# ----------------------------------------------------------------------------- the wrapper


Checker = Callable[..., PartResult]


def admitted(checker: Checker) -> Checker:
    """``checker`` with the acceptance rule enforced: credit resting on a flagged expression that no
    proof settled becomes none, with the reason; a `Refuted` answer is ``incorrect`` with its sentence."""

    @wraps(checker)
    def run(ctx, part: Part, value: object) -> PartResult:
        outer = _SCREEN.get()
        mine = Screen()
        token = _SCREEN.set(mine)
        try:
            try:
                res = checker(ctx, part, value)
            except Refuted as exc:
                return _nothing(part, f"Incorrect: {part.name}: {exc}.")
            except Exception as exc:
                left = mine.pending()
                if not left or not isinstance(exc, (TypeError, ValueError, ArithmeticError, AttributeError,
                                                    NotImplementedError, KeyError)):
                    raise
                # a construct outside the class that the engine cannot even evaluate (the derivative of a
                # floor): the answer's own doing, and it earns nothing either way
                return refuse(part, _reasons(left), _nothing(part, "the engine could not evaluate it"))
            left = mine.pending()
            if res.score > 0 and left:
                return refuse(part, _reasons(left), res)
            return _certified(res, mine)
        finally:
            _SCREEN.reset(token)
            if outer is not None:  # a checker run inside another's (general functions): the outer one sees it
                outer.flagged.update(mine.flagged)
                outer.settled |= mine.settled

    return run


def _certified(res: PartResult, screen: Screen) -> PartResult:
    """A verdict short of full marks decided at sampled states carries its certificate; one whose
    refutation could not be certified is flagged for review, never a silent reject."""
    if res.verdict not in ("incorrect", "partial"):
        return res
    if res.method == "exact":  # decided in exact arithmetic (`lagrade.compare.exact`): a proof in itself
        res.certified = True
        if screen.certificates:
            res.certificate = "; ".join(c.text() for c in screen.certificates[:3])
        return res
    if res.method != "numeric":
        return res
    if screen.certificates and not screen.uncertified:
        res.certified = True
        res.certificate = "; ".join(c.text() for c in screen.certificates[:3])
    else:
        res.certified = False
        note = ("rejected at sampled states in floating point; ball arithmetic could not certify "
                f"{'every' if screen.certificates else 'the'} difference at an exact point")
        res.review = f"{res.review}; {note}" if res.review else note
    return res


def _nothing(part: Part, feedback: str) -> PartResult:
    return PartResult(part=part.name, verdict="incorrect", score=0.0, max_score=part.weight, method="numeric",
                      feedback=feedback)


#: what to do about each kind of reason a refusal gives, said only for the kinds it gives: an answer
#: refused for a switch or a negligible part is often one formula with exact numbers already (issue 45)
_ADVICE = (
    (("is not exact", "not a simple fraction", "far from the size", "without being equal to it"),
     "Write its numbers exactly (a fraction or a constant such as pi, not a decimal)"),
    (("changes the whole by less than",), "If that part belongs in the answer, write it so that it matters; "
                                          "if not, leave it out"),
    (("Piecewise", "Heaviside", "which switches", "(a switch)", "folded into one period"),
     "Write it as one formula, without cases, steps or absolute values"),
)


#: the marks of a refusal's reason that name a switch (its motion chatters or sticks: no integrator
#: follows it within a budget, so a flagged switch earns nothing without a proof and no motion is run)
SWITCH_MARKS = (*_ADVICE[2][0], UNDECLARED_FRICTION, "sign(", "Abs(")


def smooth_pending() -> bool:
    """Something is flagged, and nothing flagged is a switch: a negligible part or a number the
    numbers rule doubts. Its motion can be followed, and refutes it where it separates (issue 45)."""
    reasons = pending()
    return bool(reasons) and not any(mark in why for why in reasons for mark in SWITCH_MARKS)


def _advice(why: str) -> str:
    said = [advice for marks, advice in _ADVICE if any(mark in why for mark in marks)]
    return "".join(f" {a}." for a in said)


def refuse(part: Part, why: str, res: PartResult) -> PartResult:
    """No credit: the answer agreed where it was sampled, but is not of a kind for which that proves
    equality, and no proof could be found. Not certified (``certified`` false): nothing proved it wrong."""
    out = _nothing(part, f"Incorrect: {part.name} cannot be accepted: {why}. An answer like that can agree with the right "
                 "one at every state tried and still be wrong elsewhere, so it needs a proof of equality, and none "
                   f"was found.{_advice(why)}")
    out.certified = False
    out.review = (f"no credit without a proof ({why}); the checker's own verdict was {res.verdict} "
                  f"({res.score:g}/{res.max_score:g}, {res.method}): worth a look if the answer is an honest one")
    return out


# ----------------------------------------------------------------------------- equations


SWITCHES = (sp.Piecewise, sp.Heaviside, sp.Max, sp.Min, sp.sign, sp.Abs, sp.floor, sp.ceiling, sp.DiracDelta,
            sp.Mod, sp.re, sp.im, sp.arg, sp.conjugate)


def linear_rows(rows: list[sp.Expr], unknowns: list[sp.Symbol], what: str, seconds: float) -> list[sp.Expr]:
    """Equations that determine their unknowns uniquely where they are solvable: each linear in the
    unknowns (after clearing denominators, the numerator replacing the row), with coefficients free of
    switches. ``(x'' - a)*(x'' - b) = 0`` or ``sin(x'' - a) = 0`` hold for the true motion too, and for
    others: `Refuted`. ``what``: the unknowns in words ("accelerations")."""
    from lagrade.compare.symbolic import _OutOfTime, time_bound

    out = []
    for i, row in enumerate(rows, 1):
        ds = _slopes(row, unknowns)
        if not _is_linear(ds):
            try:
                with time_bound(seconds):
                    row = sp.numer(sp.together(row))
                    ds = _slopes(row, unknowns)
                    linear = _is_linear(ds)
            except _OutOfTime:
                linear = False
            if not linear:
                raise Refuted(f"equation {i} is not linear in the {what} (even with its denominators cleared), so "
                              f"{what} other than the true ones satisfy it too: your equations allow other {what}")
        if any(d.has(*SWITCHES) for d in ds.values()):
            raise Refuted(f"in equation {i} the {what} are multiplied by a switch (Piecewise, Heaviside, Max, "
                          f"sign, ...): where it is zero the equation says nothing, and other {what} satisfy it")
        out.append(row)
    return out


def _slopes(row: sp.Expr, unknowns: list[sp.Symbol]) -> dict[sp.Symbol, sp.Expr]:
    """d row / d u for each unknown ``u`` the row contains (computed once: the linearity test and the
    switch test both read them)."""
    return slopes(row, [u for u in unknowns if row.has(u)])


def _is_linear(slopes: dict[sp.Symbol, sp.Expr]) -> bool:
    return all(not d.has(*slopes) for d in slopes.values())
