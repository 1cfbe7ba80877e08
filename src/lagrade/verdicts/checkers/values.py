"""Checkers for results: accelerations, tensions, forces, periods, angles, yes/no, counts, names.

A result is equal to the reference when it has the same value at every random point of the
domain (parameters, and the state where the result depends on it); reference expressions may
use the derived accelerations ``q_dd`` and multipliers, so they stay tied to the scene.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers import admit
from lagrade.verdicts.checkers.base import (
    Context,
    InvalidAnswer,
    as_expr,
    factor_text,
    graded,
    in_kind,
    key_name,
    keyed,
    read_sympy,
    result,
    surplus,
)
from lagrade.compare import exact
from lagrade.compare.certify import certify, root_between
from lagrade.compare.symbolic import _OutOfTime, proves_zero, time_bound
from lagrade.problem.notation import YES_NO
from lagrade.numbers.numeric import agree, compile_exprs, evaluate, scale_of
from lagrade.derive.reference import Mechanics
from lagrade.verdicts.result import PartResult
from lagrade.compare.sampling import Points, rng_for, sample_points, with_reference_dynamics
from lagrade.problem.spec import Part


def _domain(ctx: Context, part: Part, mech: Mechanics) -> tuple[Points, list[sp.Symbol]]:
    """The part's sampled points with the reference dynamics at them: the same for every answer
    (seeded by problem and part), so made once per process; each caller gets its own copy."""
    key = (ctx.problem.id, part.name, ctx.points)
    if key not in mech._points:
        mech._points[key] = with_reference_dynamics(
            mech, sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name), extra=part.symbol_domains))
    cached = mech._points[key]
    pts = Points(dict(cached.values), cached.K)
    return pts, list(pts.values)


def _reference(part: Part, mech: Mechanics, text: object) -> sp.Expr:
    extra = [*part.symbols, *(str(m) for m in mech.multipliers), *(str(p) for p in mech.s.p),
             *(f"delta_{n}" for n in mech.all_names)]
    return mech.parse(str(text), extra)


def _read(ctx: Context, part: Part, mech: Mechanics, value: object) -> sp.Expr:
    expr = as_expr(value, part)
    if isinstance(expr, sp.Float) or (isinstance(expr, sp.Mul) and isinstance(-expr, sp.Float)):
        return expr  # a decimal, kept as typed: a pure number is judged to its digits (`exact.agrees_to_digits`)
    extra = [f"delta_{n}" for n in mech.all_names]
    expr = read_sympy(expr, part, mech, plain_coordinates=True, momenta=True, extra=extra)
    if part.accelerations and expr.free_symbols & {*mech.s.qdd, *mech.constrained}:
        # the statement allows q'' (12.32's "theta'' may be used"): a value on the true motion, so the
        # solved accelerations are put for q'' (the sampled points hold the same), and a proof sees them
        solved = _symbolic_reference(expr, mech, ctx.symbolic_seconds)
        return expr if solved is None else solved
    return expr


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
    """The reference with derived accelerations, multipliers and constrained coordinates substituted
    (each of which may bring in the others: x'' = R*phi'', then phi'' solved), for a proof."""
    derived = {*mech.s.qdd, *mech.multipliers, *mech.constrained}
    if not ref.free_symbols & derived:
        return ref
    try:
        with time_bound(seconds):
            subs: dict[sp.Basic, sp.Expr] = dict(zip(mech.s.qdd, mech.accelerations_symbolic))
            for lam, e in mech.multiplier_exprs.items():
                subs[lam] = e.xreplace(subs)
            for c, e in mech.constrained.items():
                subs[c] = e.xreplace(subs)
            out = ref
            for _ in range(4):
                if not out.free_symbols & derived:
                    break
                out = out.xreplace(subs)
            return out
    except _OutOfTime:
        return None


def compare_scalar(ctx: Context, part: Part, mech: Mechanics, student: sp.Expr, ref: sp.Expr,
                   pts: Points, syms: list[sp.Symbol]) -> tuple[bool, str, str]:
    """(equal?, method, what is wrong) for one expression against its reference.

    Where both lie in the exact class (`lagrade.compare.exact`) equality is decided there, with no
    tolerance and no box; otherwise the sampled points, a proof and the screen's rules decide."""
    a = _evaluate(student, pts, syms)
    b = _evaluate(ref, pts, syms)
    flagged_before = admit.pending(student)
    decided = exact_difference(ctx, mech, student, ref, part)
    if decided is None and student.has(sp.asin, sp.acos, sp.atan, sp.acsc, sp.asec):
        truth = _symbolic_reference(ref, mech, ctx.symbolic_seconds)
        decided = None if truth is None else exact.same_angle(student, truth, ctx.domain(mech, part), ctx.symbolic_seconds)
    beyond = exact.needs_proof(student, ctx.domain(mech, part)) if decided is None else None
    if beyond is not None:  # outside the exact class: agreement where sampled proves nothing beyond the box
        admit.flag(student, f"it is outside the class of expressions decided exactly ({beyond})")
    if decided is not None:
        if decided:
            admit.proved(student)
            pole = exact.new_singularity(student, ref, ctx.domain(mech, part), ctx.symbolic_seconds)
            if pole is None:
                return True, "exact", ""
            return False, "exact", (f"is undefined where {pole} = 0, which lies within the problem's physical range "
                                    "(the correct result is defined there)")
        admit.proved(student)
        if np.all(agree(a, b)):
            admit.witness(exact.witness("your value minus the true one"))
            return False, "exact", (f"is not equal to the correct result: {'; '.join(flagged_before)}" if flagged_before
                                    else EXACTLY_UNEQUAL)
        certify_difference(mech, student, ref, a, b, pts)
        return False, "exact", _describe_difference(a, b)
    if np.all(agree(a, b)):
        flagged = admit.pending(student)
        if not ctx.prove_always and not flagged:  # analytic and equal at every sampled point: a proof
            return True, "numeric", ""              # would add time, not certainty
        sym_ref = _symbolic_reference(ref, mech, ctx.symbolic_seconds)
        proof = proves_zero(exact.on_domain(student - sym_ref, ctx.domain(mech, part)), ctx.symbolic_seconds,
                            ctx.positive) if sym_ref is not None else None
        if proof:
            admit.proved(student)
            return True, "symbolic", ""
        if flagged:
            why = admit.unproved(student)
            if beyond is not None:  # still pending: the part earns nothing, as for what the screen flags
                admit.flag(student, why)
            return False, "numeric", f"cannot be accepted without a proof: {why}"
        return True, "numeric", ""
    admit.proved(student)  # refuted: it earns nothing, so nothing about it is pending
    certify_difference(mech, student, ref, a, b, pts)
    return False, "numeric", _describe_difference(a, b)


EXACTLY_UNEQUAL = ("is not equal to the correct result: exact arithmetic shows a difference that no state tried makes "
                   "visible (a coefficient or a number in it is not the right one)")


def exact_difference(ctx: Context, mech: Mechanics, student: sp.Expr, ref: sp.Expr, part: Part | None = None) -> bool | None:
    """Is ``student - ref`` exactly zero on the physical domain (the true accelerations and multipliers
    substituted)? None when either is outside the exact class or the time ran out."""
    if isinstance(student, sp.Float) or isinstance(-student, sp.Float):  # a decimal for a pure number
        truth = _symbolic_reference(ref, mech, ctx.symbolic_seconds)
        if truth is not None and not truth.free_symbols:
            return exact.agrees_to_digits(student, truth)
    diff = student - ref
    subs = {**mech.multiplier_exprs, **mech.constrained}  # each may bring in the others and q''
    for _ in range(4):
        if not diff.free_symbols & set(subs):
            break
        diff = diff.xreplace(subs)
    if diff.free_symbols & set(mech.s.p):  # momenta are dL/dq' at the state, as the sampled points take them
        diff = diff.xreplace({p: sp.diff(mech.L, v) for p, v in zip(mech.s.p, mech.s.qd)})
    if diff.free_symbols & set(mech.s.qdd):  # the true accelerations: solved at each point, exactly
        return exact.is_zero_given([diff], list(mech.s.qdd), [list(mech.mass.row(i)) for i in range(mech.mass.rows)],
                                   list(mech.force), ctx.domain(mech, part), ctx.symbolic_seconds)
    return exact.is_zero(diff, ctx.domain(mech, part), ctx.symbolic_seconds)


def certify_difference(mech: Mechanics, student: sp.Expr, ref: sp.Expr, a: np.ndarray, b: np.ndarray,
                       pts: Points, quantity: str = "your value minus the true one") -> bool:
    """Certify, at the sampled state where they differ most, that ``student - ref`` is not zero
    (`lagrade.compare.certify`); the certificate, or its absence, goes with the verdict."""
    with np.errstate(all="ignore"):
        gap = np.abs(np.asarray(a, dtype=complex) - np.asarray(b, dtype=complex)) / (np.abs(b) + np.abs(a) + 1e-300)
    gap = np.where(np.isfinite(gap), gap, -1.0)
    k = int(np.argmax(gap))
    derived = {*mech.s.qdd, *mech.s.p, *mech.multipliers, *mech.constrained}
    diff = student - ref
    cert = certify(quantity, diff, {s: v[k] for s, v in pts.values.items()}, mech=mech,
                   truth=bool(diff.free_symbols & derived)) if gap[k] >= 0 else None
    admit.witness(cert)
    return cert is not None


def _describe_difference(a: np.ndarray, b: np.ndarray) -> str:
    """How a wrong result differs, in words. For a number (the same at every sample) nothing
    relational is said: "twice", "the wrong sign" or "2*pi" would pin the reference down."""
    if np.ptp(b) <= 1e-9 * scale_of(b):
        return "is not equal to the correct result"
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
        said = factor_text(float(c))
        if said is None:
            return f"is off by a constant factor ({in_kind(float(c))})"
        return f"is {said} times the correct value" + (" (a missing or extra factor)" if varies else "")
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
        given = keyed(value, part)
        unknown = sorted(set(given) - set(ref))
        if unknown:
            raise InvalidAnswer(f"{part.name} has unknown keys {unknown}; expected keys {sorted(ref)}")
        right, methods, notes, wrong = 0, set(), [], []
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
                wrong.append(key)
        fraction = right / len(ref)
        method = next((m for m in ("numeric", "symbolic", "exact") if m in methods), "numeric")
        closed = [k for k in wrong if not _read(ctx, part, mech, given[k]).free_symbols & {*mech.s.qdd, *mech.multipliers}]
        feedback = "correct." if not notes else "Incorrect: " + "; ".join(notes) + "." + _coupling(part, mech, closed)
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
    return graded(part, 0.0, method, hint or f"Incorrect: {part.name} {why}.")


def _coupling(part: Part, mech: Mechanics, wrong: list[str]) -> str:
    """Entries of a dict result computed from the same accelerations or constraint forces are coupled:
    one wrong acceleration makes several of them wrong. Said when two or more wrong entries, given in
    closed form, share one (naming the entries only, never the quantities behind them)."""
    if len(wrong) < 2:
        return ""
    derived = {*mech.s.qdd, *mech.multipliers}
    uses = {key: _reference(part, mech, part.reference[key]).free_symbols & derived for key in wrong}
    shared = [key for key in wrong if any(uses[key] & uses[other] for other in wrong if other != key)]
    if len(shared) < 2:
        return ""
    return (f" {', '.join(shared[:-1])} and {shared[-1]} are coupled: they follow from the same accelerations "
            "or forces, so one error there makes each of them wrong.")


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
    for r, R_r in zip(refs, R):
        if not any(np.all(agree(S[j], R_r)) for j in used):  # unmatched: it differs from every value given
            for j in range(len(studs)):
                if j not in used:
                    certify_difference(mech, studs[j], r, S[j], R_r, pts)
            if len(used) == len(studs):
                admit.witness(None)
    for j in range(len(studs)):  # a value of yours that matches none: it differs from every true one
        if j not in used:
            for r, R_r in zip(refs, R):
                certify_difference(mech, studs[j], r, S[j], R_r, pts)
    fraction = max(matched - surplus(extra, len(studs), len(refs), ctx), 0) / len(refs)
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
    if isinstance(value, sp.Expr) and part.unknown in _names_in(value):
        value = sp.Eq(value, 0)  # a value of theta cannot contain theta: `3*cos(theta) - 2` means = 0
    value = _solved_for(value, part.unknown)  # `theta = acos(...)` is the value acos(...)
    if isinstance(value, sp.Equality):
        expr = read_sympy(value.lhs - value.rhs, part, mech, plain_coordinates=True, extra=[part.unknown])
        if x not in expr.free_symbols:
            raise InvalidAnswer(f"{part.name}: the equation does not contain {part.unknown}")
        others = [s for s in syms if s != x]  # the unknown may also be a coordinate or a parameter
        f = compile_exprs([expr], [x, *others])
        at_root = f(b, *pts.args(others))[0]
        off = f(b + 0.05, *pts.args(others))[0]
        scale = scale_of(off)
        if not (np.all(np.abs(at_root) <= 1e-8 * scale) and np.any(np.abs(off) > 1e-6 * scale)):
            if np.all(np.abs(at_root) <= 1e-8 * scale):  # an identity: it holds everywhere, certified or not
                admit.witness(None)
            else:
                certify_difference(mech, expr.xreplace({x: ref}), sp.S.Zero, at_root, np.zeros_like(at_root), pts,
                                   f"your equation at the true {part.unknown}")
            return graded(part, 0.0, "numeric", f"Incorrect: the true {part.unknown} does not satisfy your equation.")
        if part.domain is None and not _linear_in(expr, x, ctx.symbolic_seconds):
            return graded(part, 0.0, "numeric",
                          f"Incorrect: the true {part.unknown} satisfies your equation, but it is not linear in "
                          f"{part.unknown} (after clearing denominators), so it may have other solutions: write "
                          f"an equation that singles {part.unknown} out.")
        def second_root(k: int, lo: float, hi: float) -> None:
            admit.witness(root_between(expr, x, lo, hi, {s: v[k] for s, v in pts.values.items()},
                                       f"your equation, at the two ends of an interval away from the true {part.unknown}"))

        if part.domain is not None and _another_root(f, b, pts.args(others), part.domain, certify_with=second_root):
            lo, hi = part.domain
            return graded(part, 0.0, "numeric",
                          f"Incorrect: the true {part.unknown} satisfies your equation, but so does another "
                          f"{part.unknown} between {lo:.4g} and {hi:.4g}: an equation for it must single it out "
                          f"(squaring, or multiplying by a factor, adds solutions).")
        return graded(part, 1.0, "numeric", f"correct: the true {part.unknown} satisfies your equation.")
    student = _read(ctx, part, mech, value)
    ok, method, why = compare_scalar(ctx, part, mech, student, ref, pts, syms)
    if ok:
        return graded(part, 1.0, method, "correct.")
    a = _evaluate(student, pts, syms)
    if np.all(agree(a, np.degrees(b), rtol=1e-3)):
        return graded(part, 0.0, method, "Incorrect: this looks like degrees; give the angle in radians.")
    return graded(part, 0.0, method, f"Incorrect: {part.unknown} {why}.")


def _solved_for(value: object, unknown: str) -> object:
    """The right side of ``Eq(theta, v)`` (or the left of ``Eq(v, theta)``) with v free of theta: an
    equation solved for the unknown states its value, graded as a value (an inverse function in v is
    proved equal, not refused for want of a proof as the residual theta - v would be)."""
    from sympy.core.function import AppliedUndef

    if not isinstance(value, sp.Equality):
        return value
    for side, other in ((value.lhs, value.rhs), (value.rhs, value.lhs)):
        name = side.name if isinstance(side, sp.Symbol) else (
            side.func.__name__ if isinstance(side, AppliedUndef) and len(side.args) == 1
            and getattr(side.args[0], "name", "") == "t" else None)  # theta, or theta(t)
        if name == unknown and unknown not in _names_in(other):
            return other
    return value


def _linear_in(expr: sp.Expr, x: sp.Symbol, seconds: float) -> bool:
    """Is ``expr = 0`` linear in ``x`` once its denominators are cleared (one root, where its
    coefficient is not zero)? Time-bounded; out of time counts as no."""
    try:
        with time_bound(seconds):
            numerator = sp.numer(sp.together(expr))
            return not sp.diff(numerator, x).has(x)
    except _OutOfTime:
        return False


def _names_in(expr: sp.Basic) -> set[str]:
    """Symbol names and names of applied functions (theta written as theta(t))."""
    from sympy.core.function import AppliedUndef

    return {s.name for s in expr.free_symbols if isinstance(s, sp.Symbol)} | {
        f.func.__name__ for f in expr.atoms(AppliedUndef)}


def _another_root(f, root: np.ndarray, others: list[np.ndarray], domain: tuple[float, float],
                  states: int = 8, steps: int = 4000, certify_with=None) -> bool:
    """Does ``f(x, *others) = 0`` have a solution in the open ``domain`` other than ``root``, at
    any of the first sampled parameter sets? Found as sign changes on a fine grid, where |f| is
    small on one side (a pole changes sign too, with |f| large on both)."""
    grid = np.linspace(*domain, steps + 1)[1:-1]
    step = grid[1] - grid[0]
    for k in range(min(states, len(root))):
        with np.errstate(all="ignore"):
            values = np.asarray(f(grid, *(np.full_like(grid, a[k]) for a in others))[0], dtype=float)
        finite = np.isfinite(values)
        if not finite.any():
            continue
        typical = float(np.median(np.abs(values[finite]))) or 1.0
        near = np.abs(values) <= 0.05 * typical
        change = (np.sign(values[:-1]) * np.sign(values[1:]) <= 0) & finite[:-1] & finite[1:] & (near[:-1] | near[1:])
        found = grid[:-1][change]
        far = found[np.abs(found - root[k]) > 3 * step]
        if far.size:
            if certify_with is not None:
                certify_with(k, float(far[0]), float(far[0] + step))
            return True
    return False


def check_boolean(ctx: Context, part: Part, value: object) -> PartResult:
    if isinstance(value, sp.logic.boolalg.BooleanAtom):
        value = bool(value)
    if isinstance(value, str) and value.strip().lower() in YES_NO:
        value = YES_NO[value.strip().lower()]
    if isinstance(value, sp.Symbol) and value.name.lower() in YES_NO:
        value = YES_NO[value.name.lower()]
    if not isinstance(value, bool):
        raise InvalidAnswer(f"{part.name} should be True or False (or \"yes\" / \"no\")")
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
    penalty = surplus(len(wrong), len(given), len(want), ctx)
    fraction = max(right - penalty, 0) / max(len(want), 1) if want else float(not given)
    notes = []
    if want - given:
        notes.append(f"{len(want - given)} missing")
    if wrong:
        notes.append(f"{', '.join(wrong)} {'is' if len(wrong) == 1 else 'are'} not")
    return graded(part, fraction, "exact", "correct." if not notes else "Incorrect: " + "; ".join(notes) + ".",
                  ctx.credit)
