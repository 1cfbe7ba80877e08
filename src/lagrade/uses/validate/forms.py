"""Right answers generated from a reference: the same answer in the forms students write it.

Each generator takes a part's kind and its reference value (in an answer's form) and gives
``(label, value)`` pairs, each of which must get full marks: algebra (expand, factor, together),
trigonometry (sin and cos rewritten, multiple angles expanded, the tangent half-angle form), a
Lagrangian plus a total time derivative, a Hamiltonian plus a constant, equations scaled, moved
across, swapped, combined and reordered. Which apply depends on what the kind accepts: a scaled
Lagrangian earns half credit, so it is never generated as right.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import sympy as sp

from lagrade.compare.symbolic import _OutOfTime, time_bound
from lagrade.problem.symbols import T

Form = tuple[str, object]

#: kinds whose value is one expression, graded up to what (kind-wise) leaves it right
SCALAR = ("lagrangian", "hamiltonian", "expression")
#: kinds whose value is a list of equations defining rates
EQUATIONS = ("eom", "hamilton_eqs")


def _tan_half(e: sp.Expr) -> sp.Expr:
    """sin, cos of an angle in tan of its half (sympy's rewrite; tan's own argument halved too)."""
    return e.rewrite(sp.tan)


def _as_sin(e: sp.Expr) -> sp.Expr:
    return e.replace(sp.cos, lambda a: sp.sin(a + sp.pi / 2, evaluate=False))


def _as_cos(e: sp.Expr) -> sp.Expr:
    return e.replace(sp.sin, lambda a: sp.cos(a - sp.pi / 2, evaluate=False))


def _has_trig(e: sp.Expr) -> bool:
    return e.has(sp.sin, sp.cos)


#: algebraic rewrites of one expression: (label, function, applies?)
REWRITES: list[tuple[str, Callable[[sp.Expr], sp.Expr], Callable[[sp.Expr], bool]]] = [
    ("expanded", sp.expand, lambda e: True),
    ("factored", sp.factor, lambda e: True),
    ("over one denominator (together)", sp.together, lambda e: True),
    ("multiple angles expanded (expand_trig)", sp.expand_trig, _has_trig),
    ("cos written as sin(x + pi/2)", _as_sin, lambda e: e.has(sp.cos)),
    ("sin written as cos(x - pi/2)", _as_cos, lambda e: e.has(sp.sin)),
    ("sin^2 written as 1 - cos^2", lambda e: e.replace(lambda x: x.is_Pow and x.exp == 2 and isinstance(x.base, sp.sin),
                                                     lambda x: 1 - sp.cos(x.base.args[0]) ** 2),
     lambda e: any(x.exp == 2 and isinstance(x.base, sp.sin) for x in e.atoms(sp.Pow))),
    ("the tangent half-angle form", _tan_half, _has_trig),
]

#: a rewrite with poles of its own: generated only where no angle reaches them (``half_angle_safe``)
WITH_POLES = ("the tangent half-angle form",)


def half_angle_safe(e: sp.Expr, intervals: dict[str, sp.Interval]) -> bool:
    """Whether tan(x/2) stays finite for every angle x of a sin or cos in ``e`` on its physical domain
    (``intervals``: a symbol's name -> its domain). Where it does not (a pendulum's angle is any real),
    the half-angle form is undefined at x = pi, where the true value is defined: the grader refuses
    that as a singularity in the physical domain (docs/answers.md), so it is not a right answer."""
    inside = sp.Interval.open(-sp.pi, sp.pi)
    for f in e.atoms(sp.sin, sp.cos):
        arg = f.args[0]
        name = getattr(arg, "name", None) or getattr(getattr(arg, "func", None), "__name__", None)
        if not (arg.is_Symbol or isinstance(arg, sp.core.function.AppliedUndef)) or name not in intervals:
            return False
        if not intervals[name].is_subset(inside):
            return False
    return True


def bounded(fn: Callable[[], object], seconds: float) -> object | None:
    """``fn()``, or None when sympy takes longer than ``seconds`` or fails on it."""
    try:
        with time_bound(seconds):
            return fn()
    except _OutOfTime:
        return None
    except Exception:  # noqa: BLE001 (a rewrite sympy cannot do is not generated)
        return None


def _rewrites(e: sp.Expr, seconds: float, intervals: dict[str, sp.Interval] | None = None
              ) -> Iterator[tuple[str, sp.Expr]]:
    if not isinstance(e, sp.Expr):
        return
    for label, fn, applies in REWRITES:
        if not applies(e) or (label in WITH_POLES and not half_angle_safe(e, intervals or {})):
            continue
        out = bounded(lambda fn=fn: fn(e), seconds)
        if isinstance(out, sp.Expr) and out != e:
            yield label, out


def _coordinates(value: object) -> list[sp.Expr]:
    """The coordinates q(t) a value uses (functions of t not named p_...)."""
    found: set[sp.Expr] = set()
    for e in _leaves(value):
        found |= {f for f in e.atoms(sp.core.function.AppliedUndef)
                  if len(f.args) == 1 and getattr(f.args[0], "name", None) == "t" and not f.func.__name__.startswith("p_")}
    return sorted(found, key=str)


def _leaves(value: object) -> Iterator[sp.Basic]:
    if isinstance(value, sp.Basic):
        yield value
    elif isinstance(value, dict):
        for v in value.values():
            yield from _leaves(v)
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _leaves(v)


def _parameters(value: object, coordinate_names: set[str]) -> list[sp.Symbol]:
    names = set()
    for e in _leaves(value):
        names |= {s for s in e.free_symbols if isinstance(s, sp.Symbol) and s.name != "t"
                  and s.name not in coordinate_names and not s.name.startswith("p_")}
    return sorted(names, key=lambda s: s.name)


def right_forms(kind: str, value: object, parameters: list[str], seconds: float = 2.0,
                intervals: dict[str, sp.Interval] | None = None) -> list[Form]:
    """Right answers of ``kind`` made from the reference ``value`` (not including it); ``intervals``:
    each symbol's physical domain, by name (where the tangent half-angle form may be used)."""
    out: list[Form] = []

    def rewrites(e, seconds):
        return _rewrites(e, seconds, intervals)

    params = [sp.Symbol(n) for n in parameters]
    if kind in SCALAR and isinstance(value, sp.Expr):
        out += list(rewrites(value, seconds))
        if kind == "lagrangian":
            qs = _coordinates(value)
            if qs:
                q = qs[0]
                c = params[0] if params else sp.Integer(1)
                out.append(("plus d/dt(c*q**2/2)", value + c * q * q.diff(T)))
                out.append(("plus d/dt(c*t*q)", value + c * q + c * T * q.diff(T)))
                if len(qs) > 1:
                    out.append(("plus d/dt(sin(q1)*q2)", value + sp.cos(qs[0]) * qs[0].diff(T) * qs[1]
                                + sp.sin(qs[0]) * qs[1].diff(T)))
        if kind == "hamiltonian":
            c = params[0] if params else sp.Integer(1)
            out.append(("plus a constant", value + 3 * c))
    elif kind == "expression" and isinstance(value, dict):
        for key, v in value.items():
            for label, w in rewrites(v, seconds) if isinstance(v, sp.Expr) else ():
                out.append((f"{key}: {label}", {**value, key: w}))
    elif kind in EQUATIONS and isinstance(value, list) and value:
        out += _equation_forms(value, params, seconds, intervals)
    elif kind == "expression_set" and isinstance(value, list) and len(value) > 1:
        out.append(("reordered", list(reversed(value))))
        for i, v in enumerate(value):
            for label, w in rewrites(v, seconds) if isinstance(v, sp.Expr) else ():
                out.append((f"item {i + 1}: {label}", [*value[:i], w, *value[i + 1:]]))
                break
    elif kind == "conserved" and isinstance(value, list) and value:
        c = params[0] if params else sp.Integer(2)
        out.append(("reordered", list(reversed(value)))) if len(value) > 1 else None
        for i, v in enumerate(value):
            if isinstance(v, sp.Expr):
                out.append((f"item {i + 1} times a constant plus a constant", [*value[:i], 2 * c * v + 1, *value[i + 1:]]))
                out += [(f"item {i + 1}: {label}", [*value[:i], w, *value[i + 1:]]) for label, w in rewrites(v, seconds)][:2]
    return out


def _sides(eq: object) -> tuple[sp.Expr, sp.Expr]:
    if isinstance(eq, sp.Equality):
        return eq.lhs, eq.rhs
    return eq, sp.Integer(0)


def _equation_forms(eqs: list, params: list[sp.Symbol], seconds: float, intervals=None) -> list[Form]:
    out: list[Form] = []
    n = len(eqs)
    c = params[0] if params else sp.Integer(3)
    sides = [_sides(e) for e in eqs]
    for i, (lhs, rhs) in enumerate(sides):
        def at(new, i=i):
            return [*eqs[:i], new, *eqs[i + 1:]]
        tag = f"equation {i + 1}" if n > 1 else "the equation"
        out.append((f"{tag} times {2 * c}", at(sp.Eq(sp.expand(2 * c * lhs), sp.expand(2 * c * rhs), evaluate=False))))
        out.append((f"{tag} divided by -{c}", at(sp.Eq(-lhs / c, -rhs / c, evaluate=False))))
        out.append((f"{tag} moved across (= 0)", at(sp.Eq(lhs - rhs, 0, evaluate=False))))
        out.append((f"{tag} as an expression meaning = 0", at(rhs - lhs)))
        out.append((f"{tag} with its sides swapped", at(sp.Eq(rhs, lhs, evaluate=False))))
        for label, w in _rewrites(rhs, seconds):
            # not the tangent half-angle form: its pole (x = pi) is in an angle's domain, where equations
            # no longer determine the accelerations, and the grader refuses them for that (docs/answers.md)
            if label.startswith(("expanded", "over one", "cos written", "multiple angles")):
                out.append((f"{tag}: right side {label}", at(sp.Eq(lhs, w, evaluate=False))))
    if n > 1:
        out.append(("reordered", list(reversed(eqs))))
        (l0, r0), (l1, r1) = sides[0], sides[1]
        out.append(("equation 1 replaced by the sum of equations 1 and 2",
                    [sp.Eq(l0 + l1, r0 + r1, evaluate=False), *eqs[1:]]))
        out.append(("equation 2 replaced by equation 2 minus c times equation 1",
                    [eqs[0], sp.Eq(l1 - c * l0, r1 - c * r0, evaluate=False), *eqs[2:]]))
    return out


def as_text(value: object) -> object | None:
    """The value in answer.toml's text notation (``theta_d``, ``lhs == rhs``), or None where text
    cannot hold it."""
    from lagrade.uses.validate.states import to_symbols

    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, dict):
        out = {str(k): as_text(v) for k, v in value.items()}
        return None if any(v is None or isinstance(v, (list, dict)) for v in out.values()) else out
    if isinstance(value, (list, tuple)):
        out = [as_text(v) for v in value]
        return None if any(v is None or isinstance(v, (list, dict)) for v in out) else out
    if isinstance(value, sp.Equality):
        return f"{sp.sstr(to_symbols(value.lhs))} == {sp.sstr(to_symbols(value.rhs))}"
    if isinstance(value, sp.Expr):
        return sp.sstr(to_symbols(value))
    return None


def as_latex(value: object) -> object | None:
    """The value in LaTeX as lagrade echoes an answer back (``\\dot{\\theta}``), or None."""
    from lagrade.verdicts.readback import as_latex as echo

    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, dict):
        out = {str(k): as_latex(v) for k, v in value.items()}
        return None if any(not isinstance(v, str) for v in out.values()) else out
    if isinstance(value, (list, tuple)):
        out = [as_latex(v) for v in value]
        return None if any(not isinstance(v, str) for v in out) else out
    if isinstance(value, sp.Basic):
        text = echo(value)
        return text if "\\" in text else f"${text}$"
    return None
