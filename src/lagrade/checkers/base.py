"""What every checker shares: the grading context, reading a student's value, building verdicts."""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass, field

import sympy as sp

from lagrade.compare.trajectory import ACCURACY, Accuracy
from lagrade.credit import Credit
from lagrade.reference import Mechanics, ReferenceCache
from lagrade.result import Method, PartResult
from lagrade.spec import Part, Problem
from lagrade.symbols import NotationError, nodes_of, to_state


class InvalidAnswer(ValueError):
    """The answer cannot be read as what the part asks (not the same as a wrong answer)."""


@dataclass
class Context:
    """Everything a checker needs besides the student's value; shared across the parts of a problem."""

    problem: Problem
    refs: ReferenceCache
    accuracy: Accuracy = field(default_factory=lambda: ACCURACY["default"])
    symbolic_seconds: float = 2.0
    points: int = 24
    #: more specific feedback: which term is missing or extra (never the reference itself)
    hints: bool = False
    credit: Credit = field(default_factory=Credit)

    @property
    def prove_always(self) -> bool:
        """Attempt symbolic proofs even where numbers already agree (strict accuracy only)."""
        return self.accuracy.name == "strict"

    def mech(self, part: Part) -> Mechanics:
        return self.refs[part.system]

    @property
    def positive(self) -> set[str]:
        return {p.name for s in self.problem.systems for p in self.problem.parameters_of(s.key) if p.positive}


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


def read_sympy(expr: sp.Expr, part: Part, mech: Mechanics, *, plain_coordinates: bool, momenta: bool = False,
               max_order: int = 2, extra: Iterable[str] = ()) -> sp.Expr:
    params = [p.name for p in mech.parameters]
    coords = list(mech.names)
    # A text answer reads every coordinate name of the problem as a function of t; in a system where
    # that name is a parameter (12.8: theta), it is the parameter.
    nodes = nodes_of(expr)
    stray = {f: sp.Symbol(f.func.__name__) for f in nodes.applied
             if f.func.__name__ in params and f.args == (sp.Symbol("t"),)}
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
        if s.name not in allowed:
            hint = suggest(s.name, allowed)
            raise InvalidAnswer(f"unknown name '{s.name}' in {part.name}{hint}; this problem uses "
                                f"{', '.join(sorted(allowed))}")
    try:
        return sp.sympify(to_state(expr, list(mech.all_names), max_order=max_order, momenta_too=momenta, nodes=nodes))
    except NotationError as exc:
        raise InvalidAnswer(f"{part.name}: {exc}") from None


def equation_rows(value: object, part: Part) -> list[sp.Expr]:
    """A list of equations as expressions meaning ``= 0`` (one bare equation also allowed)."""
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


def key_name(key: object) -> str:
    """Dict keys may be names, symbols or coordinates ``theta(t)``: all mean the name."""
    if isinstance(key, str):
        return key
    if isinstance(key, sp.Symbol):
        return key.name
    if isinstance(key, sp.Basic) and hasattr(key, "func") and key.args and hasattr(key.func, "__name__"):
        return key.func.__name__
    return str(key)
