"""'Under what conditions does the system reduce to ...?': conditions graded by what they do, not by words.

A student gives conditions as a dict (``{"k": oo}``, ``{"theta": 0}``) or a list of ``Eq``. Two
kinds of condition are decidable, and the part's ``reference`` says which it asks for:

- limits of the parameters (``{ grows = "k*l0/(m*g)", fixed = "g/l0" }``, or a list of fixed
  quantities): each limit of a product of powers of the parameters moves the parameters along a
  direction of log-parameter space; the conditions are right when, along their direction, the
  criterion grows while the ``fixed`` quantities (what the reduced system is: a pendulum's
  frequency) stay as they are. A limit of one parameter
  that changes a fixed quantity is wrong (g -> 0 leaves no pendulum); a limit of a group of
  parameters is read with the fixed quantities held (m*g/(k*l0) -> 0 is k*l0/(m*g) -> oo);
- conditions on the motion (``{ harmonic = "r" }``): coordinates or velocities held at values for
  all time; right when the motion they describe is one of the scene's (the held coordinates'
  equations of motion vanish identically there) and what is left is the named coordinate alone,
  obeying a linear equation with constant coefficients and a restoring force: a harmonic oscillator.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers.base import Context, InvalidAnswer, as_expr, graded, read_sympy
from lagrade.numbers.numeric import evaluate
from lagrade.derive.reference import Mechanics
from lagrade.verdicts.result import PartResult
from lagrade.compare.sampling import rng_for, sample_points
from lagrade.problem.spec import Part
from lagrade.problem.symbols import T

INFINITY = "oo"


def _is_infinite(value: object) -> bool:
    return value in (sp.oo, -sp.oo, sp.zoo) or (isinstance(value, sp.Symbol) and value.name in (INFINITY, "infinity"))


def _side(value: object, part: Part, mech: Mechanics) -> sp.Expr:
    """One side of a condition in the engine's symbols; a key given as text is read by the text parser."""
    if isinstance(value, str):
        from lagrade.problem.notation import TextAnswerError, parse_math

        try:
            value = parse_math(value, list(mech.all_names), known_names=[p.name for p in mech.parameters])
        except TextAnswerError as exc:
            raise InvalidAnswer(f"{part.name}: cannot read the condition on {value!r}: {exc}") from None
    return read_sympy(as_expr(value, part), part, mech, plain_coordinates=True, max_order=1, extra=[INFINITY])


def read_conditions(part: Part, mech: Mechanics, value: object) -> list[tuple[sp.Expr, sp.Expr | None]]:
    """(quantity, value) pairs; value None means infinity."""
    if isinstance(value, sp.Equality):
        value = [value]
    if isinstance(value, dict):
        pairs = list(value.items())
    elif isinstance(value, (list, tuple)):
        pairs = []
        for item in value:
            if not isinstance(item, sp.Equality):
                raise InvalidAnswer(f"{part.name}: each condition should be Eq(quantity, value), or give a dict "
                                    f"quantity -> value ({{'param': oo}}, {{'coord': value}})")
            pairs.append((item.lhs, item.rhs))
    else:
        raise InvalidAnswer(f"{part.name} should be a dict quantity -> value ({{'param': oo}}, {{'coord': value}}) "
                            f"or a list of Eq(quantity, value)")
    if not pairs:
        raise InvalidAnswer(f"{part.name} is empty; give the conditions as a dict quantity -> value")
    out = []
    for key, val in pairs:
        if isinstance(key, (bool, int, float)) or (isinstance(key, sp.Basic) and key.is_number):
            key, val = val, key  # Eq(oo, k) or Eq(0, theta)
        q = _side(key, part, mech)
        v = None if _is_infinite(val) else _side(val, part, mech)
        if v is not None and sp.Symbol(INFINITY) in v.free_symbols or sp.Symbol(INFINITY) in q.free_symbols:
            raise InvalidAnswer(f"{part.name}: write infinity alone as the value of a condition ({{'param': oo}})")
        out.append((q, v))
    return out


def _exponents(expr: sp.Expr, params: list[sp.Symbol]) -> np.ndarray | None:
    """The powers of a product of powers of the parameters (a positive number aside), else None."""
    coeff, rest = sp.powsimp(sp.factor(expr)).as_coeff_Mul()
    if not (coeff.is_number and coeff > 0):
        return None
    powers = sp.Mul.make_args(rest)
    e = np.zeros(len(params))
    for factor in powers:
        base, exp = factor.as_base_exp()
        if factor == 1:
            continue
        if base not in params or not exp.is_number:
            return None
        e[params.index(base)] += float(exp)
    return e


def _limits(ctx: Context, part: Part, mech: Mechanics, conds) -> tuple[bool, str]:
    params = list(mech.params)
    state = {*mech.s.q, *mech.s.qd}
    ref = part.reference
    crit = _exponents(mech.parse(str(ref["grows"])), params)
    held = ref.get("fixed", [])
    fixed = [_exponents(mech.parse(str(f)), params) for f in ([held] if isinstance(held, str) else held)]
    if crit is None or any(f is None for f in fixed):
        raise ValueError(f"part {part.name}: grows and fixed must be products of powers of the parameters")
    d = np.zeros(len(params))
    for q, v in conds:
        if q.free_symbols & state:
            return False, ("these conditions do not make the system reduce to the one asked (the part asks for "
                           "limits of the parameters)")
        if v is not None and v != 0:
            return False, "a parameter set to a finite value does not make the system reduce to the one asked"
        e = _exponents(q, params)
        if e is None:
            raise InvalidAnswer(f"{part.name}: give limits of parameters or of products of their powers "
                                f"({{'param': oo}}, {{'p1/p2': 0}})")
        e = e if v is None else -e
        if np.count_nonzero(e) == 1 and any(abs(e @ f) > 1e-12 for f in fixed):
            return False, "one of these limits changes the very system it should reduce to"
        d += e
    if fixed:
        F = np.array(fixed).T
        d = d - F @ np.linalg.lstsq(F, d, rcond=None)[0]
    if d @ crit > 1e-12:
        return True, "correct."
    return False, "under these conditions the system does not reduce to the one asked"


def _harmonic(ctx: Context, part: Part, mech: Mechanics, conds) -> tuple[bool, str]:
    """Conditions on the motion: the held coordinates' equations vanish identically, and the one left
    obeys a q'' + c q + f = 0 with constant a, c (a*c > 0) and f: a harmonic oscillator."""
    left = str(part.reference["harmonic"])
    held: dict[sp.Symbol, sp.Expr] = {}
    for q, v in conds:
        if v is None:
            return False, "a limit of the parameters does not make these equations a harmonic oscillator's"
        names = q.free_symbols & {*mech.s.q, *mech.s.qd}
        if len(names) != 1 or q not in names or v.free_symbols & {*mech.s.q, *mech.s.qd, T}:
            raise InvalidAnswer(f"{part.name}: a condition on the motion holds one coordinate or velocity at a value "
                                f"of the parameters ({{'coord': value}}), not {q} = {v}")
        held[q] = v
    subs = {}
    for q, qd, qdd in zip(mech.s.q, mech.s.qd, mech.s.qdd):
        if q in held:  # held for all time: its rates vanish (a velocity given too must agree)
            if qd in held and held[qd] != 0:
                return False, "a coordinate held at a value has no velocity"
            subs.update({q: held[q], qd: 0, qdd: 0})
        elif qd in held:
            subs.update({qd: held[qd], qdd: 0})
    rows = [sp.expand(row.xreplace(subs)) for row in mech.EL]
    free = [i for i, q in enumerate(mech.s.q) if q not in subs]
    if [mech.names[i] for i in free] != [left]:
        return False, "these conditions do not leave a single oscillating coordinate"
    pts = sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name))
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *mech.params]
    argv = pts.args(args)
    i = free[0]
    q, qd, qdd = mech.s.q[i], mech.s.qd[i], mech.s.qdd[i]
    others = [row for j, row in enumerate(rows) if j != i]
    # linear in q, q', q'' with coefficients free of the state and of t, and no q' term (no damping)
    linear = [sp.diff(rows[i], qd), sp.diff(rows[i], q, 2), sp.diff(rows[i], q, qdd), sp.diff(rows[i], qdd, 2),
              sp.diff(rows[i], qdd, T), sp.diff(rows[i], q, T), sp.diff(rows[i], T)]
    with np.errstate(all="ignore"):
        a, c = evaluate([sp.diff(rows[i], qdd), sp.diff(rows[i], q)], args, argv).reshape(2, -1)
        rest = evaluate([*others, *linear], args, argv).reshape(len(others) + len(linear), -1)
    scale = max(float(np.nanmax(np.abs(a))), float(np.nanmax(np.abs(c))), 1e-300)
    if not np.all(np.abs(rest[:len(others)]) <= 1e-9 * scale):
        return False, "the motion these conditions describe is not one the system can follow"
    if not np.all(np.abs(rest[len(others):]) <= 1e-9 * scale) or not np.all(a * c > 0):
        return False, "under these conditions the motion left is not a harmonic oscillation"
    return True, "correct."


def check_conditions(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    conds = read_conditions(part, mech, value)
    ref = part.reference if isinstance(part.reference, dict) else {}
    if "grows" in ref:
        ok, why = _limits(ctx, part, mech, conds)
    elif "harmonic" in ref:
        ok, why = _harmonic(ctx, part, mech, conds)
    else:
        raise ValueError(f"part {part.name}: a conditions reference names 'grows' (limits) or 'harmonic'")
    return graded(part, 1.0 if ok else 0.0, "exact" if "grows" in ref else "numeric",
                  why if ok else f"Incorrect: {why}.")
