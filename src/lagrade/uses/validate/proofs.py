"""Whether a generated wrong answer is in fact right: a proof, or none.

A slip can leave the answer right (a constant term dropped from a Lagrangian, a symmetric formula
with two masses swapped). Such an answer is not a false accept: it is dropped from the wrong ones,
with the proof, which is the exact judge (`lagrade.compare.exact.is_zero`) or sympy's
simplification reaching 0 (`lagrade.compare.symbolic.proves_zero`), applied to what the kind
compares: Euler-Lagrange equations for a Lagrangian, H up to a function of t, the solved rates for
equations, the value for a result.
"""

from __future__ import annotations

import sympy as sp

from lagrade.compare import exact
from lagrade.compare.symbolic import _OutOfTime, proves_zero, time_bound
from lagrade.uses.validate.forms import _sides
from lagrade.uses.validate.states import to_symbols


def zero(expr: sp.Expr, positive: frozenset[str], seconds: float = 3.0) -> str | None:
    """How ``expr`` was proved identically 0, or None."""
    expr = sp.sympify(expr)
    if expr == 0:
        return "0 as built"
    decided = exact.is_zero(expr, positive, seconds=seconds)
    if decided is not None:  # exact either way: a nonzero value at a point is a proof too
        return "exact judge: is_zero" if decided else None
    if proves_zero(expr, seconds, set(positive)) is True:
        return "sympy simplifies it to 0"
    return None


def all_zero(exprs: list[sp.Expr], positive: frozenset[str], seconds: float = 3.0) -> str | None:
    how = [zero(e, positive, seconds) for e in exprs]
    return None if any(h is None for h in how) else (sorted(set(how), key=len)[-1] if how else "no terms")


def _unknowns(value: list) -> list[sp.Symbol]:
    """The highest derivative of each function of t in a list of equations: what they are solved for."""
    highest: dict[str, int] = {}
    for eq in value:
        for d in sp.sympify(eq).atoms(sp.Derivative):
            if not all(getattr(v, "name", None) == "t" for v in d.variables):
                continue  # V(r)' in a force: not a rate
            name = getattr(d.expr, "func", None)
            if name is not None and hasattr(name, "__name__"):
                highest[name.__name__] = max(highest.get(name.__name__, 0), len(d.variables))
    return [sp.Symbol(n + "_" + "d" * k) for n, k in sorted(highest.items())]


def _solved(eqs: list, unknowns: list[sp.Symbol], positive: frozenset[str]) -> list[sp.Expr] | None:
    rows = [to_symbols(lhs - rhs) for lhs, rhs in map(_sides, eqs)]
    if len(rows) != len(unknowns):
        return None
    try:
        A, b = sp.linear_eq_to_matrix(rows, unknowns)
    except Exception:  # noqa: BLE001 (nonlinear in the rates: no proof this way)
        return None
    if zero(A.det(), positive, 1.0):  # they do not determine the rates
        return None
    try:
        return list(A.LUsolve(b))
    except Exception:  # noqa: BLE001 (a zero pivot sympy could not see past)
        return None


def same_motion(wrong: sp.Expr, reference: sp.Expr, mech, positive: frozenset[str], seconds: float = 6.0) -> str | None:
    """A proof that two Hamiltonians give the same motion q(t) (the same q'' as a function of q, q'
    and t), as the H of L and of a gauge L + dF(q, t)/dt do: what a part with a `gauge` alternative
    accepts. None when either does not give p from q' (not solvable here) or the proof fails."""
    try:
        with time_bound(seconds):
            a, b = _accelerations(to_symbols(wrong), mech.s), _accelerations(to_symbols(reference), mech.s)
            if a is None or b is None:
                return None
            how = all_zero([x - y for x, y in zip(a, b)], positive)
            return f"the same motion, as from another gauge L + dF/dt ({how})" if how else None
    except _OutOfTime:
        return None
    except Exception:  # noqa: BLE001
        return None


def _accelerations(H: sp.Expr, s) -> list[sp.Expr] | None:
    t = sp.Symbol("t")
    rates = [sp.diff(H, p) for p in s.p]
    solved = sp.solve([qd - r for qd, r in zip(s.qd, rates)], s.p, dict=True)
    if len(solved) != 1:
        return None
    pdot = [-sp.diff(H, q) for q in s.q]
    out = []
    for r in rates:
        acc = sp.diff(r, t) + sum(sp.diff(r, q) * e for q, e in zip(s.q, rates)) + \
            sum(sp.diff(r, p) * e for p, e in zip(s.p, pdot))
        out.append(acc.xreplace(solved[0]))
    return out


def proved_equal(kind: str, wrong: object, reference: object, positive: frozenset[str], mech=None,
                 seconds: float = 6.0) -> str | None:
    """A proof that ``wrong`` is as right as ``reference`` for a part of ``kind``, or None."""
    try:
        with time_bound(seconds):
            return _proved_equal(kind, wrong, reference, positive, mech)
    except _OutOfTime:
        return None
    except Exception:  # noqa: BLE001 (values of different shapes, or sympy failing: no proof)
        return None


def _proved_equal(kind, wrong, reference, positive, mech) -> str | None:
    if isinstance(wrong, bool) or isinstance(reference, bool):
        return "the same truth value" if wrong == reference else None
    if isinstance(wrong, dict) and isinstance(reference, dict):
        if set(map(str, wrong)) != set(map(str, reference)):
            return None
        ref = {str(k): v for k, v in reference.items()}
        how = [_proved_equal(kind, v, ref[str(k)], positive, mech) for k, v in wrong.items()]
        return None if any(h is None for h in how) else "every entry: " + ", ".join(sorted(set(how)))
    if kind == "lagrangian" and mech is not None:
        from lagrade.derive.reference import euler_lagrange

        rows = [a - b for a, b in zip(euler_lagrange(to_symbols(wrong), mech.s), euler_lagrange(to_symbols(reference), mech.s))]
        how = all_zero(rows, positive)
        return f"the same Euler-Lagrange equations ({how})" if how else None
    if kind == "hamiltonian":
        d = to_symbols(wrong - reference)
        state = [s for s in d.free_symbols if s.name not in positive]  # the state, t and any real parameter
        how = all_zero([sp.diff(d, s) for s in state], positive)
        return f"H differs by a constant only ({how})" if how else None
    if isinstance(wrong, list) and isinstance(reference, list):
        if kind in ("eom", "hamilton_eqs", "reduced") and all(isinstance(e, (sp.Equality, sp.Expr)) for e in reference):
            unknowns = _unknowns(reference)
            a, b = _solved(wrong, unknowns, positive), _solved(reference, unknowns, positive)
            if a is None or b is None:
                return None
            how = all_zero([x - y for x, y in zip(a, b)], positive)
            return f"the same solved rates ({how})" if how else None
        if kind in ("names",):
            return "the same names" if sorted(map(str, wrong)) == sorted(map(str, reference)) else None
        if kind == "expression_set" and len(wrong) == len(reference):
            left = list(reference)
            for w in wrong:
                match = next((r for r in left if zero(to_symbols(w - r), positive)), None)
                if match is None:
                    return None
                left.remove(match)
            return "the same values in another order"
        return None
    if isinstance(wrong, sp.Equality) and isinstance(reference, sp.Equality):
        how = zero(to_symbols((wrong.lhs - wrong.rhs) - (reference.lhs - reference.rhs)), positive)
        return f"the same equation ({how})" if how else None
    if isinstance(wrong, sp.Basic) and isinstance(reference, sp.Basic):
        return zero(to_symbols(wrong - reference), positive)
    return "the same value" if wrong == reference else None
