"""What every checker shares: the grading context, reading a student's value, building verdicts."""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from lagrade.compare import exact
from lagrade.verdicts.checkers import admit
from lagrade.compare.trajectory import ACCURACY, Accuracy
from lagrade.verdicts.credit import Credit
from lagrade.derive.general_functions import substitute
from lagrade.derive.reference import Mechanics, ReferenceCache
from lagrade.verdicts.result import Method, PartResult
from lagrade.problem.domains import Domain
from lagrade.problem.spec import Part, Problem
from lagrade.problem.symbols import NotationError, nodes_of, to_state


class InvalidAnswer(ValueError):
    """The answer cannot be read as what the part asks (not the same as a wrong answer)."""


@dataclass
class Context:
    """Everything a checker needs besides the student's value; shared across the parts of a problem."""

    problem: Problem
    refs: ReferenceCache
    accuracy: Accuracy = field(default_factory=lambda: ACCURACY["default"])
    symbolic_seconds: float = 2.0
    points: int = admit.SAMPLED_STATES
    #: more specific feedback: which term is missing or extra (never the reference itself)
    hints: bool = False
    credit: Credit = field(default_factory=Credit)
    #: which random function stands for the general functions (`lagrade.derive.general_functions`);
    #: 0: the problem's concrete one
    instance: int = 0
    _domains: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def prove_always(self) -> bool:
        """Attempt symbolic proofs even where numbers already agree (strict accuracy only)."""
        return self.accuracy.name == "strict"

    def mech(self, part: Part) -> Mechanics:
        return self.refs.instance(part.system, self.instance)

    @property
    def positive(self) -> set[str]:
        return {p.name for s in self.problem.systems for p in self.problem.parameters_of(s.key) if p.positive}

    def domain(self, mech: Mechanics, part: Part | None = None) -> dict[str, Domain]:
        """The physical domain of every symbol of ``mech``'s system (and of ``part``'s own symbols, 12.23's
        theta0), by name (`Problem.domains`): what the exact judge decides on (`lagrade.compare.exact`)."""
        key = (mech.system.key, part.name if part is not None and part.symbols else None)
        if key not in self._domains:
            self._domains[key] = {s.name: d for s, d in self.problem.domains(*key).items()}
        return self._domains[key]


def result(part: Part, verdict: str, fraction: float, method: Method, feedback: str) -> PartResult:
    return PartResult(part=part.name, verdict=verdict, score=round(part.weight * fraction, 6),
                      max_score=part.weight, method=method, feedback=feedback)


def graded(part: Part, fraction: float, method: Method, feedback: str, credit: Credit | None = None) -> PartResult:
    """Verdict from a score fraction: 1 correct, 0 incorrect, in between partial.

    With ``credit.per_equation`` off, anything short of 1 scores 0 (still reported as partial)."""
    fraction = min(max(fraction, 0.0), 1.0)
    if credit is not None and not credit.per_equation and 0 < fraction < 1:
        return result(part, "partial", 0.0, method, feedback.replace("Incorrect: ", "Partly right: ", 1))
    verdict = "correct" if fraction >= 1.0 - 1e-12 else ("incorrect" if fraction <= 1e-12 else "partial")
    if verdict == "partial" and feedback.startswith("Incorrect: "):
        feedback = "Partly right: " + feedback[len("Incorrect: "):]
    return result(part, verdict, fraction, method, feedback)


def surplus(wrong: int, given: int, expected: int, ctx: Context) -> int:
    """How many wrong entries of an order-free list are surplus, each cancelling a right one: only
    those beyond the expected number (two frequencies asked, one right and one wrong: none)."""
    if not ctx.credit.penalize_extra_entries:
        return 0
    return min(wrong, max(given - expected, 0))


def factor_text(c: float) -> str | None:
    """A measured factor as a student should read it, when it names a classic slip: 2 or 1/2 (a missing
    or doubled 1/2). Any other factor is not said: the answer divided by it would be the reference, so
    the feedback would be an oracle for the coefficients (``in_kind`` says "not the right size" instead)."""
    if not np.isfinite(c) or c == 0:
        return None
    for slip, text in ((2.0, "2"), (0.5, "1/2")):
        if abs(c - slip) <= 1e-9 * slip:
            return text
    return None


def in_kind(c: float) -> str:
    """A factor off in kind only: "not the right size", with "the wrong sign" where it is negative. No
    direction: "too large" or "too small" would let a sequence of checks bisect the coefficient."""
    return "the wrong sign and not the right size" if c < 0 else "not the right size"


def suggest(name: str, known: Iterable[str]) -> str:
    close = difflib.get_close_matches(name, list(known), n=1)
    return f" (did you mean '{close[0]}'?)" if close else ""


def as_expr(value: object, part: Part) -> sp.Expr:
    if isinstance(value, bool) or value is None:
        raise InvalidAnswer(f"{part.name} should be a sympy expression, not {value!r}")
    if isinstance(value, (int, float, sp.Basic)):
        expr = sp.sympify(value)
        if isinstance(expr, sp.Equality):
            return expr.lhs - expr.rhs
        if not isinstance(expr, sp.Expr):
            raise InvalidAnswer(f"{part.name} should be an expression, got {type(value).__name__}")
        return expr
    raise InvalidAnswer(f"{part.name} should be a sympy expression, not a {type(value).__name__}")


def read_expr(value: object, part: Part, mech: Mechanics, *, plain_coordinates: bool, momenta: bool = False,
              max_order: int = 2, extra: Iterable[str] = ()) -> sp.Expr:
    """A student's expression in the engine's state symbols, or `InvalidAnswer` saying why not.

    ``plain_coordinates``: whether ``theta`` may stand for the coordinate (fine in H and in
    results such as a tension; not in L or the equations of motion, where time derivatives matter).
    """
    expr = as_expr(value, part)
    return read_sympy(expr, part, mech, plain_coordinates=plain_coordinates, momenta=momenta,
                      max_order=max_order, extra=extra)


#: names students give Lagrange multipliers (lam, lambda_1, mu2 ...), when not a name of the problem
MULTIPLIER_NAME = re.compile(r"^(lam|lamda|lambda|mu|nu)(_?[0-9]+|_[A-Za-z][A-Za-z0-9]*|[a-z])?$")


def multiplier_names(expr: sp.Basic, mech: Mechanics, part: Part) -> set[str]:
    """The names in ``expr`` that can only be Lagrange multipliers: multiplier-like and not a
    parameter, coordinate or symbol of the part (a parameter mu stays the parameter)."""
    taken = {p.name for p in mech.parameters} | set(mech.all_names) | set(part.symbols) | {"t"}
    names = {s.name for s in expr.free_symbols if isinstance(s, sp.Symbol)}
    names |= {f.func.__name__ for f in expr.atoms(AppliedUndef)}
    declared = {str(m) for m in mech.multipliers}
    return {n for n in names - taken if n in declared or MULTIPLIER_NAME.match(n)}


def _evaluate_derivatives(expr: sp.Basic) -> sp.Basic:
    """``Derivative(m*r**2*omega, t)`` left unevaluated means its value: differentiate it. A derivative
    of a bare coordinate ``Derivative(r(t), t)`` is the state's velocity and stays as it is."""
    pending = [d for d in expr.atoms(sp.Derivative) if not isinstance(d.expr, AppliedUndef)]
    if not pending:
        return expr
    try:
        return expr.xreplace({d: d.doit() for d in pending}) if all(
            v.is_Symbol for d in pending for v in d.variables) else expr
    except Exception:  # noqa: BLE001  (left as it was: to_state names what it cannot read)
        return expr


#: what the physical domain settles by itself, once the symbols carry their assumptions (and roots)
_DOMAIN_SETTLED = (sp.re, sp.im, sp.arg, sp.conjugate, sp.Abs, sp.sign)


def _real_parts(expr: sp.Basic, domain=frozenset()) -> sp.Basic:
    """Read on the physical domain: ``re(t)``, ``im(theta)`` (from ``expand(complex=True)``), ``Abs(m1)``,
    ``sign(theta')`` where theta' > 0, ``sqrt(m1**2)``, ``Abs(tan(alpha))`` for 0 < alpha < pi/2: every
    quantity of a problem is real, with the sign its domain gives (`lagrade.compare.exact._assume`), so
    read them with symbols that say it, then go back to the engine's plain symbols."""
    if not expr.has(*_DOMAIN_SETTLED) and all(p.exp.is_Integer for p in expr.atoms(sp.Pow)):
        return expr
    assumed = exact._assume(expr, domain)
    if len(assumed.atoms(sp.Abs, sp.sign)) > len(expr.atoms(sp.Abs, sp.sign)):
        return expr  # sqrt(u**2) turned into Abs(u) with u's sign unknown: left as the student wrote it
    back = {s: sp.Symbol(s.name) for s in assumed.free_symbols if isinstance(s, sp.Symbol)}
    return assumed.xreplace(back)


def read_sympy(expr: sp.Expr, part: Part, mech: Mechanics, *, plain_coordinates: bool, momenta: bool = False,
               max_order: int = 2, extra: Iterable[str] = ()) -> sp.Expr:
    params = [p.name for p in mech.parameters]
    coords = list(mech.names)
    try:
        expr = _evaluate_derivatives(substitute(expr, mech.functions))
    except ValueError as exc:  # V(r, phi) for V(r)
        raise InvalidAnswer(f"{part.name}: {exc}") from None
    # A text answer reads every coordinate name of the problem as a function of t; in a system where
    # that name is a parameter (12.8: theta), it is the parameter; so is a multiplier written lam(t).
    nodes = nodes_of(expr)
    # likewise a constant the part declares (12.41's conserved momentum p_x in x = x0 + p_x t/m)
    constants = {*params, *extra, *part.symbols}
    stray = {f: sp.Symbol(f.func.__name__) for f in nodes.applied
             if f.func.__name__ in constants and f.args == (sp.Symbol("t"),)}
    if stray:
        expr = expr.xreplace(stray)
        nodes = nodes_of(expr)
    allowed = {*params, "t", *part.symbols, *extra, *mech.all_names}
    if momenta:
        allowed |= {f"p_{n}" for n in coords}
    for s in sorted(nodes.symbols, key=str):
        if s.name in coords and not plain_coordinates:
            raise InvalidAnswer(f"'{s.name}' is a plain symbol in {part.name}; a coordinate must be a function of "
                                f"time: {s.name} = Function('{s.name}')(t), velocity {s.name}.diff(t)")
        if s.name in mech.functions:
            args = ", ".join(next(f.args for f in mech.system.functions if f.name == s.name))
            raise InvalidAnswer(f"'{s.name}' in {part.name} is a function of {args}: write {s.name}({args}), "
                                f"in answer.py Function('{s.name}')({args})")
        if s.name not in allowed:
            hint = suggest(s.name, allowed)
            public = sorted({*params, *part.symbols, *mech.all_names}) + ["t"] + \
                [f"{f.name}({', '.join(f.args)})" for f in mech.system.functions] + \
                ([f"p_{n}" for n in coords] if momenta else [])
            raise InvalidAnswer(f"unknown name '{s.name}' in {part.name}{hint}; the problem's names are "
                                f"{', '.join(public)}")
    if part.kind in RESULT_KINDS and not part.accelerations:
        max_order = min(max_order, 1)
        _no_accelerations(nodes, part)
    try:
        state = sp.sympify(to_state(expr, list(mech.all_names), max_order=max_order, momenta_too=momenta, nodes=nodes))
    except NotationError as exc:
        raise InvalidAnswer(f"{part.name}: {exc}") from None
    if part.kind in MOTION_KINDS:
        _no_state(state, part, mech)
    domain = {s.name: d for s, d in mech.problem.domains(mech.system.key, part.name).items()} \
        if getattr(mech, "problem", None) is not None else {p.name for p in mech.parameters if p.positive}
    return admit.screen(_real_parts(state, domain), part, mech)


#: kinds whose answer is a result (a value of the scene's quantities): the accelerations must be solved
#: for, never left as q'' (which grading would fill with the true ones); `Part.accelerations` lifts it
RESULT_KINDS = frozenset({"expression", "expression_set", "equation_root"})
#: kinds whose answer is the motion itself, a function of t: no coordinate or velocity in it
MOTION_KINDS = admit.MOTION_KINDS


def _no_accelerations(nodes, part: Part) -> None:
    """A result with q'' in it is not solved: say which acceleration is left, and why it is not allowed."""
    for d in sorted(nodes.derivatives, key=str):
        order = sum(c for _, c in d.variable_count)
        if order >= 2 and isinstance(d.expr, AppliedUndef):
            name = d.expr.func.__name__
            raise InvalidAnswer(f"your {part.name} still contains {name}'' (the acceleration {name}(t).diff(t, 2)): "
                                "a result must be solved for, in the parameters and the state; solve the "
                                "equations of motion for the accelerations and put them in")


def _no_state(state: sp.Expr, part: Part, mech: Mechanics) -> None:
    taken = {*mech.s.q, *mech.s.qd, *mech.s.qdd, *mech.s.p} - {sp.Symbol(s) for s in part.symbols}
    left = sorted((str(s) for s in state.free_symbols & taken), key=str)
    if left:
        raise InvalidAnswer(f"your {part.name} contains {left[0].replace('_dd', chr(39) * 2).replace('_d', chr(39))}: "
                            "the motion must be given as a function of t and the parameters alone")


def equation_rows(value: object, part: Part) -> list[sp.Expr]:
    """A list of equations as expressions meaning ``= 0`` (one bare equation also allowed).

    What ``sympy.solve`` returns is read too: a dict ``{theta.diff(t, 2): rhs}`` means
    ``theta'' = rhs``, and ``solve(..., dict=True)`` wraps it in a list."""
    if isinstance(value, (list, tuple)) and len(value) == 1 and isinstance(value[0], dict):
        value = value[0]
    if isinstance(value, dict):
        if not value:
            raise InvalidAnswer(f"{part.name} is an empty dict; give one equation per coordinate")
        value = [sp.Eq(as_expr(k, part), as_expr(v, part), evaluate=False) for k, v in value.items()]
    items = value if isinstance(value, (list, tuple)) else [value]
    if isinstance(value, sp.MatrixBase):
        items = list(value)
    rows = []
    for i, item in enumerate(items, 1):
        if isinstance(item, (bool, sp.logic.boolalg.BooleanAtom)):
            raise InvalidAnswer(f"equation {i} of {part.name} evaluated to {item}: sympy decided it on the spot; "
                                f"write it as Eq(lhs, rhs, evaluate=False) or as an expression meaning = 0")
        if isinstance(item, sp.Equality):
            rows.append(item.lhs - item.rhs)
        else:
            rows.append(as_expr(item, part))
    if not rows:
        raise InvalidAnswer(f"{part.name} is an empty list; give one equation per coordinate")
    return rows


def keyed(value: dict, part: Part) -> dict[str, object]:
    """A dict answer by entry name; two keys naming one entry (``"m1"`` and the symbol ``m1``) are two
    answers for it, of which the grader would silently take one: `InvalidAnswer`."""
    given: dict[str, object] = {}
    for k, v in value.items():
        name = key_name(k)
        if name in given:
            raise InvalidAnswer(f"{part.name} gives '{name}' twice (as {given_keys(value, name)}); give each entry once")
        given[name] = v
    return given


def given_keys(value: dict, name: str) -> str:
    return " and ".join(repr(k) if isinstance(k, str) else sp.sstr(k) for k in value if key_name(k) == name)


def key_name(key: object) -> str:
    """Dict keys may be names, symbols or coordinates ``theta(t)``: all mean the name."""
    if isinstance(key, str):
        return key
    if isinstance(key, sp.Symbol):
        return key.name
    if isinstance(key, sp.Basic) and hasattr(key, "func") and key.args and hasattr(key.func, "__name__"):
        return key.func.__name__
    return str(key)
