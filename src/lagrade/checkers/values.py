"""Checkers for results: accelerations, tensions, forces, periods, angles, yes/no, counts, names.

A result is equal to the reference when it has the same value at every random point of the
domain (parameters, and the state where the result depends on it); reference expressions may
use the derived accelerations ``q_dd`` and multipliers, so they stay tied to the scene.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.checkers.base import Context, InvalidAnswer, as_expr, graded, key_name, read_sympy, result
from lagrade.compare.symbolic import _OutOfTime, proves_zero, time_bound
from lagrade.numeric import agree, compile_exprs, evaluate, scale_of
from lagrade.reference import Mechanics
from lagrade.result import PartResult
from lagrade.sampling import Points, rng_for, sample_points, with_reference_dynamics
from lagrade.spec import Part


def _domain(ctx: Context, part: Part, mech: Mechanics) -> tuple[Points, list[sp.Symbol]]:
    """The part's sampled points with the reference dynamics at them: the same for every answer
    (seeded by problem and part), so made once per process; each caller gets its own copy."""
    key = (ctx.problem.id, part.name, ctx.points)
    if key not in mech._points:
        mech._points[key] = with_reference_dynamics(
            mech, sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name), extra=part.symbols))
    cached = mech._points[key]
    pts = Points(dict(cached.values), cached.K)
    return pts, list(pts.values)


def _reference(part: Part, mech: Mechanics, text: object) -> sp.Expr:
    extra = [*part.symbols, *(str(m) for m in mech.multipliers), *(str(p) for p in mech.s.p),
             *(f"delta_{n}" for n in mech.all_names)]
    return mech.parse(str(text), extra)


def _read(ctx: Context, part: Part, mech: Mechanics, value: object) -> sp.Expr:
    expr = as_expr(value, part)
    extra = [f"delta_{n}" for n in mech.all_names]
    return read_sympy(expr, part, mech, plain_coordinates=True, momenta=True, extra=extra)


def _evaluate(expr: sp.Expr, pts: Points, syms: list[sp.Symbol] | None = None) -> np.ndarray:
    """Value at every point; symbols the points lack (virtual displacements delta_q) get random values,
    kept in ``pts`` so that the student's expression and the reference see the same ones."""
    missing = [s for s in expr.free_symbols if s not in pts.values]
    if missing:
        rng = rng_for("extra", *sorted(str(m) for m in missing))
        for m in missing:
            pts.values[m] = rng.uniform(-1, 1, pts.K)
    syms = list(pts.values)
    return evaluate([expr], syms, pts.args(syms))[0]


def _symbolic_reference(ref: sp.Expr, mech: Mechanics, seconds: float) -> sp.Expr | None:
    """The reference with derived accelerations and multipliers substituted, for a proof."""
    need_acc = ref.free_symbols & set(mech.s.qdd)
    subs: dict[sp.Basic, sp.Expr] = {}
    try:
        with time_bound(seconds):
            if need_acc or ref.free_symbols & set(mech.multipliers):
                subs.update(zip(mech.s.qdd, mech.accelerations_symbolic))
            for lam, e in mech.multiplier_exprs.items():
                subs[lam] = e.xreplace(subs)
            for c, e in mech.constrained.items():
                subs[c] = e.xreplace(subs)
            return ref.xreplace(subs) if subs else ref
    except _OutOfTime:
        return None


def compare_scalar(ctx: Context, part: Part, mech: Mechanics, student: sp.Expr, ref: sp.Expr,
                   pts: Points, syms: list[sp.Symbol]) -> tuple[bool, str, str]:
    """(equal?, method, what is wrong) for one expression against its reference."""
    a = _evaluate(student, pts, syms)
    b = _evaluate(ref, pts, syms)
    if np.all(agree(a, b)):
        if not ctx.prove_always:  # equal at every sampled point: a proof would add time, not certainty
            return True, "numeric", ""
        sym_ref = _symbolic_reference(ref, mech, ctx.symbolic_seconds)
        proof = proves_zero(student - sym_ref, ctx.symbolic_seconds, ctx.positive) if sym_ref is not None else None
        return True, ("symbolic" if proof else "numeric"), ""
    return False, "numeric", _describe_difference(a, b)


def _describe_difference(a: np.ndarray, b: np.ndarray) -> str:
    with np.errstate(all="ignore"):
        ratio = a / b
    finite = ratio[np.isfinite(ratio)]
    if np.all(np.abs(a) <= 1e-12 * scale_of(b)):
        return "is zero, which it is not"
    if finite.size == a.size and finite.size and np.allclose(finite, finite[0], rtol=1e-8):
        c = finite[0]
        if np.isclose(c, -1.0):
            return "has the wrong sign"
        if np.isclose(c, 2 * np.pi) or np.isclose(c, 1 / (2 * np.pi)):
            return f"is off by a factor 2*pi{'' if c > 1 else ' (too small)'}: angular frequency and frequency differ by 2*pi"
        varies = np.ptp(b) > 1e-9 * scale_of(b)
        return f"is {c:.4g} times the correct value" + (" (a missing or extra factor)" if varies else "")
    with np.errstate(all="ignore"):
        inverse = a * b
    if inverse.size and np.all(np.isfinite(inverse)) and np.ptp(b) > 1e-9 * scale_of(b):
        for c, what in ((2 * np.pi, "looks like an angular frequency where a period T = 2*pi/omega is asked (or the reverse)"),
                        (1.0, "is the reciprocal of the correct value")):
            if np.allclose(inverse, c, rtol=1e-8):
                return what
    if np.all(agree(a, -b)):
        return "has the wrong sign"
    if not np.all(np.isfinite(a)):
        return "is undefined at some physically allowed values"
    return "is not equal to the correct result"


def check_expression(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    pts, syms = _domain(ctx, part, mech)
    ref = part.reference
    if isinstance(ref, dict):
        if not isinstance(value, dict):
            if len(ref) == 1:
                value = {next(iter(ref)): value}
            else:
                raise InvalidAnswer(f"{part.name} should be a dict with keys {', '.join(map(repr, ref))}")
        given = {key_name(k): v for k, v in value.items()}
        unknown = sorted(set(given) - set(ref))
        if unknown:
            raise InvalidAnswer(f"{part.name} has unknown keys {unknown}; expected keys {sorted(ref)}")
        right, methods, notes = 0, set(), []
        for key, text in ref.items():
            if key not in given:
                notes.append(f"{key} is missing")
                continue
            ok, method, why = compare_scalar(ctx, part, mech, _read(ctx, part, mech, given[key]),
                                             _reference(part, mech, text), pts, syms)
            right += ok
            methods.add(method)
            if not ok:
                notes.append(f"{key} {why}")
        fraction = right / len(ref)
        method = "numeric" if "numeric" in methods or not methods else "symbolic"
        feedback = "correct." if not notes else "Incorrect: " + "; ".join(notes) + "."
        if notes:
            feedback = _dict_mistake_message(ctx, part, mech, given, pts, syms) or feedback
        return graded(part, fraction, method, feedback, ctx.credit)
    if isinstance(value, sp.Equality) and _is_definition(value, mech, part):
        value = value.rhs
    ok, method, why = compare_scalar(ctx, part, mech, _read(ctx, part, mech, value),
                                     _reference(part, mech, ref), pts, syms)
    if ok:
        return graded(part, 1.0, method, "correct.")
    hint = _mistake_message(ctx, part, mech, value, pts, syms)
    return graded(part, 0.0, "numeric", hint or f"Incorrect: {part.name} {why}.")


def _is_definition(eq: sp.Equality, mech: Mechanics, part: Part) -> bool:
    """``Eq(a, <expr>)`` where ``a`` is not a known name: the student named the result."""
    known = {p.name for p in mech.parameters} | set(mech.all_names) | {"t"}
    return isinstance(eq.lhs, sp.Symbol) and eq.lhs.name not in known


def _mistake_message(ctx, part, mech, value, pts, syms) -> str | None:
    if not part.mistakes:
        return None
    a = _evaluate(_read(ctx, part, mech, value), pts, syms)
    for mistake in part.mistakes:
        try:
            if np.all(agree(a, _evaluate(_reference(part, mech, mistake.answer), pts, syms))):
                return mistake.message
        except Exception:  # noqa: BLE001
            continue
    return None


def _dict_mistake_message(ctx, part, mech, given: dict, pts, syms) -> str | None:
    """A named mistake for a dict part matches when every key it lists matches the student's value."""
    for mistake in part.mistakes:
        if not isinstance(mistake.answer, dict) or not set(mistake.answer) <= set(given):
            continue
        try:
            if all(np.all(agree(_evaluate(_read(ctx, part, mech, given[k]), pts, syms),
                                _evaluate(_reference(part, mech, v), pts, syms))) for k, v in mistake.answer.items()):
                return mistake.message
        except Exception:  # noqa: BLE001
            continue
    return None


def check_expression_set(ctx: Context, part: Part, value: object) -> PartResult:
    """Order-free lists: normal-mode frequencies, several equilibria."""
    mech = ctx.mech(part)
    pts, syms = _domain(ctx, part, mech)
    refs = [_reference(part, mech, r) for r in part.reference]
    items = list(value) if isinstance(value, (list, tuple, set)) else [value]
    studs = [_read(ctx, part, mech, v) for v in items]
    R = [_evaluate(r, pts, syms) for r in refs]
    S = [_evaluate(s, pts, syms) for s in studs]
    matched, used = 0, set()
    for r in R:
        j = next((j for j in range(len(S)) if j not in used and np.all(agree(S[j], r))), None)
        if j is not None:
            matched += 1
            used.add(j)
    extra = len(studs) - len(used)
    fraction = max(matched - (extra if ctx.credit.penalize_extra_entries else 0), 0) / len(refs)
    if fraction >= 1.0:
        return graded(part, 1.0, "numeric", "correct.")
    notes = [f"{matched} of the {len(refs)} values are right"]
    if extra:
        notes.append(f"{extra} of yours match none")
    return graded(part, fraction, "numeric", "Incorrect: " + ", ".join(notes) + ".", ctx.credit)


def check_equation_root(ctx: Context, part: Part, value: object) -> PartResult:
    """An angle (or other unknown) given as a value, or as an equation it satisfies."""
    mech = ctx.mech(part)
    pts, syms = _domain(ctx, part, mech)
    ref = _reference(part, mech, part.reference)
    x = sp.Symbol(part.unknown)
    b = _evaluate(ref, pts, syms)
    if isinstance(value, sp.Equality):
        expr = read_sympy(value.lhs - value.rhs, part, mech, plain_coordinates=True, extra=[part.unknown])
        if x not in expr.free_symbols:
            raise InvalidAnswer(f"{part.name}: the equation does not contain {part.unknown}")
        others = [s for s in syms if s != x]  # the unknown may also be a coordinate or a parameter
        f = compile_exprs([expr], [x, *others])
        at_root = f(b, *pts.args(others))[0]
        off = f(b + 0.05, *pts.args(others))[0]
        scale = scale_of(off)
        if np.all(np.abs(at_root) <= 1e-8 * scale) and np.any(np.abs(off) > 1e-6 * scale):
            return graded(part, 1.0, "numeric", f"correct: the true {part.unknown} satisfies your equation.")
        return graded(part, 0.0, "numeric", f"Incorrect: the true {part.unknown} does not satisfy your equation.")
    student = _read(ctx, part, mech, value)
    a = _evaluate(student, pts, syms)
    if np.all(agree(a, b)):
        proof = None
        if ctx.prove_always:
            sym_ref = _symbolic_reference(ref, mech, ctx.symbolic_seconds)
            proof = proves_zero(student - sym_ref, ctx.symbolic_seconds) if sym_ref is not None else None
        return graded(part, 1.0, "symbolic" if proof else "numeric", "correct.")
    if np.all(agree(a, np.degrees(b), rtol=1e-3)):
        return graded(part, 0.0, "numeric", "Incorrect: this looks like degrees; give the angle in radians.")
    return graded(part, 0.0, "numeric", f"Incorrect: {part.unknown} {_describe_difference(a, b)}.")


def check_boolean(ctx: Context, part: Part, value: object) -> PartResult:
    if isinstance(value, sp.logic.boolalg.BooleanAtom):
        value = bool(value)
    if not isinstance(value, bool):
        raise InvalidAnswer(f"{part.name} should be True or False")
    ok = value is part.reference
    return result(part, "correct" if ok else "incorrect", float(ok), "exact",
                  "correct." if ok else f"Incorrect: the answer to '{part.prompt or part.name}' is not {value}.")


def check_integer(ctx: Context, part: Part, value: object) -> PartResult:
    if isinstance(value, sp.Integer):
        value = int(value)
    if isinstance(value, bool) or not isinstance(value, int):
        raise InvalidAnswer(f"{part.name} should be a whole number")
    ok = value == part.reference
    return result(part, "correct" if ok else "incorrect", float(ok), "exact",
                  "correct." if ok else f"Incorrect: {value} is not the number asked for.")


def check_names(ctx: Context, part: Part, value: object) -> PartResult:
    """A set of coordinate names (cyclic coordinates): names, symbols or coordinates all count."""
    items = list(value) if isinstance(value, (list, tuple, set)) else [value]
    given = {key_name(v) for v in items}
    want = set(part.reference)
    right = len(given & want)
    wrong = sorted(given - want)
    penalty = len(wrong) if ctx.credit.penalize_extra_entries else 0
    fraction = max(right - penalty, 0) / max(len(want), 1) if want else float(not given)
    notes = []
    if want - given:
        notes.append(f"{len(want - given)} missing")
    if wrong:
        notes.append(f"{', '.join(wrong)} {'is' if len(wrong) == 1 else 'are'} not")
    return graded(part, fraction, "exact", "correct." if not notes else "Incorrect: " + "; ".join(notes) + ".",
                  ctx.credit)
