"""A Hamiltonian (or Hamilton's equations) of any admissible Lagrangian of the scene: L + dF(q, t)/dt.

A gauge term dF/dt leaves the motion alone but shifts the momenta (p -> p + dF/dq) and H (H -> H -
dF/dt), so the H of another admissible Lagrangian differs from the reference H by more than a function
of t: the `hamiltonian` checker refuses it, rightly, where the problem fixes the Lagrangian. Where the
book leaves it open (an `Alternative` with ``gauge = true``), the test is the one that defines
"admissible": going back from the student's rates (q' = f(q, p, t), p' = g) to velocities, the momenta
p = P(q, q', t) must make ``dP/dt - g`` the scene's Lagrange equations exactly, not up to a factor (a
Lagrangian whose Euler-Lagrange expression vanishes identically is a total time derivative), and
Hamilton's equations must be Hamiltonian (their Jacobian times the symplectic matrix is symmetric).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers.admit import admitted
from lagrade.verdicts.checkers.base import Context, equation_rows, graded, read_expr, read_sympy
from lagrade.compare.equations import CompiledRows, analyse_rows
from lagrade.compare.symbolic import _OutOfTime, time_bound
from lagrade.numbers.numeric import agree, evaluate
from lagrade.derive.reference import Mechanics
from lagrade.verdicts.result import PartResult
from lagrade.compare.sampling import rng_for, sample_points, with_reference_dynamics
from lagrade.problem.spec import Part
from lagrade.problem.symbols import T

RIGHT = ("correct: {what} of an admissible Lagrangian L + dF(q, t)/dt (a gauge term shifts the momenta by dF/dq "
         "and H by -dF/dt), whose equations of motion are the true ones at every sampled state.")
WRONG = "Incorrect: {what} of no Lagrangian L + dF(q, t)/dt of this system."
OF_H, OF_EQS = "this is the Hamiltonian", "these are Hamilton's equations"


def check_hamiltonian_gauge(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    H = read_expr(value, part, mech, plain_coordinates=True, momenta=True, max_order=0)
    f = [sp.diff(H, p) for p in mech.s.p]
    g = [-sp.diff(H, q) + Qi for q, Qi in zip(mech.s.q, mech.Q)]  # Q(q, q'): q' is f there, P(q, q') below
    return _judge(ctx, part, mech, f, g, OF_H, hamiltonian=True)


def check_hamilton_eqs_gauge(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    rows = [read_sympy(r, part, mech, plain_coordinates=True, momenta=True, max_order=1)
            for r in equation_rows(value, part)]
    rates = [*mech.s.qd, *mech.s.pd]
    solved = _solve(rows, rates, ctx.symbolic_seconds)
    if solved is None or any(r.has(*rates) for r in solved):
        return graded(part, 0.0, "numeric", WRONG.format(what=OF_EQS))
    n = len(mech.names)
    return _judge(ctx, part, mech, solved[:n], solved[n:], OF_EQS, hamiltonian=False)


def _solve(rows: list[sp.Expr], unknowns: list[sp.Symbol], seconds: float) -> list[sp.Expr] | None:
    """The unique solution of ``rows = 0`` for ``unknowns``, or None (none, several, or out of time)."""
    if len(rows) != len(unknowns):
        return None
    try:
        with time_bound(seconds):
            # rational=False: by default solve replaces floats by nearby rationals, and 2.00000002
            # became 2 (a wrong answer, accepted)
            sols = sp.solve(rows, unknowns, dict=True, rational=False)
    except _OutOfTime:
        return None
    except Exception:  # noqa: BLE001  (sympy cannot solve it: not an admissible form we can confirm)
        return None
    if len(sols) != 1 or set(sols[0]) != set(unknowns):
        return None
    return [sols[0][u] for u in unknowns]


def _judge(ctx: Context, part: Part, mech: Mechanics, f: list[sp.Expr], g: list[sp.Expr], what: str,
           hamiltonian: bool) -> PartResult:
    q, v, a, p = mech.s.q, mech.s.qd, mech.s.qdd, mech.s.p
    P = _solve([fi - vi for fi, vi in zip(f, v)], p, ctx.symbolic_seconds)  # momenta from velocities
    if P is None:
        return graded(part, 0.0, "numeric", WRONG.format(what=what))
    at = dict(zip(p, P))
    rows = [sp.diff(Pi, T) + sum(sp.diff(Pi, qj) * vj for qj, vj in zip(q, v))
            + sum(sp.diff(Pi, vj) * aj for vj, aj in zip(v, a)) - gi.xreplace(at) for Pi, gi in zip(P, g)]
    extra = [sp.Symbol(s) for s in part.symbols]
    pts = sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name, "gauge"), extra=part.symbol_domains)
    args = [*q, *v, *a, T, *mech.params, *extra]
    with np.errstate(all="ignore"):
        mine, true = evaluate(rows, args, pts.args(args)), evaluate(mech.EL, args, pts.args(args))
    # the same equations, not a multiple (at random accelerations, row by row) ...
    same = bool(np.all(np.isfinite(mine)) and all(np.all(agree(m_i, t_i)) for m_i, t_i in zip(mine, true)))
    if same:  # ... holding at the true motion within the preset's tolerance, against their terms' size
        truth_pts = with_reference_dynamics(mech, pts)
        state = [*q, *v, T, *mech.params, *extra]
        an = analyse_rows(CompiledRows(rows, list(a), state), truth_pts.args(state),
                          np.array(truth_pts.args(a)), list(mech.names), rtol=ctx.accuracy.sample_rtol)
        same = an.fraction >= 1.0
    if same and not hamiltonian:
        with np.errstate(all="ignore"):
            moms = evaluate(P, args, pts.args(args))  # the phase points of the sampled states
        same = _is_hamiltonian(f, g, mech, pts, extra, moms)
    return graded(part, 1.0 if same else 0.0, "numeric", (RIGHT if same else WRONG).format(what=what))


def _is_hamiltonian(f: list[sp.Expr], g: list[sp.Expr], mech: Mechanics, pts, extra: list[sp.Symbol],
                    moms: np.ndarray) -> bool:
    """Rates (f, g) come from some H(q, p, t) when Omega times their Jacobian in (q, p) is symmetric.
    With generalized forces (p' = -dH/dq + Q) the test does not apply: such a part is not confirmed."""
    if any(Qi != 0 for Qi in mech.Q):
        return False
    z = [*mech.s.q, *mech.s.p]
    n = len(mech.names)
    F = [*f, *g]
    # Omega = [[0, I], [-I, 0]]: (Omega J)[i] is row i + n of J for i < n, minus row i - n otherwise
    omega_j = [[sp.diff(F[i + n], zj) if i < n else -sp.diff(F[i - n], zj) for zj in z] for i in range(2 * n)]
    asym = [omega_j[i][j] - omega_j[j][i] for i in range(2 * n) for j in range(i + 1, 2 * n)]
    if not asym:
        return True
    args = [*mech.s.q, *mech.s.p, T, *mech.params, *extra]
    at = dict(zip(mech.s.p, moms))
    arrays = [at[s] if s in at else pts.values[s] for s in args]
    with np.errstate(all="ignore"):
        values = evaluate(asym, args, arrays)
    scale = max(float(np.nanmax(np.abs(evaluate([e for row in omega_j for e in row], args, arrays)))), 1.0)
    return bool(np.all(np.abs(values) <= 1e-8 * scale))


GAUGE_CHECKERS = {"hamiltonian": admitted(check_hamiltonian_gauge), "hamilton_eqs": admitted(check_hamilton_eqs_gauge)}
