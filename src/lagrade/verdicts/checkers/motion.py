"""Checkers about the motion itself: conserved quantities and closed-form trajectories."""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers import admit
from lagrade.verdicts.checkers.base import (
    Context,
    InvalidAnswer,
    as_expr,
    graded,
    keyed,
    read_sympy,
    surplus,
)
from lagrade.compare.certify import Certificate, certify, outside_span
from lagrade.compare.trajectory import Accuracy
from lagrade.numbers.numeric import evaluate
from lagrade.derive.reference import Mechanics, total_derivative
from lagrade.verdicts.result import PartResult
from lagrade.compare.sampling import rng_for, sample_points, with_reference_dynamics
from lagrade.problem.spec import Part
from lagrade.problem.symbols import T


def _in_velocities(expr: sp.Expr, mech: Mechanics) -> sp.Expr:
    """Momenta p_q written by the student mean dL/dq' of this system."""
    subs = {p: sp.diff(mech.L, v) for p, v in zip(mech.s.p, mech.s.qd)}
    return expr.xreplace(subs)


def check_conserved(ctx: Context, part: Part, value: object) -> PartResult:
    """Each quantity must be constant along the true motion and the expected ones must be among them.

    "Among them" means functional dependence: the gradient of each expected quantity lies in the
    span of the gradients of the student's (so 2*p_phi, or E + p_phi, count).
    """
    mech = ctx.mech(part)
    items = list(value) if isinstance(value, (list, tuple)) else [value]
    extra = [f"p_{n}" for n in mech.names]
    studs = [_in_velocities(read_sympy(as_expr(v, part), part, mech, plain_coordinates=True, momenta=True,
                                       max_order=1), mech) for v in items]
    refs = [_in_velocities(mech.parse(str(r), extra), mech) for r in part.reference]
    pts = with_reference_dynamics(mech, sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name)))
    state = [*mech.s.q, *mech.s.qd]
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *mech.params]
    argv = pts.args(args)

    def rate_and_grad(exprs):
        rates = evaluate([total_derivative(e, mech.s) for e in exprs], args, argv)
        grads = evaluate([sp.diff(e, v) for e in exprs for v in state], args, argv)
        return rates, grads.reshape(len(exprs), len(state), pts.K)

    s_rate, s_grad = rate_and_grad(studs)
    r_rate, r_grad = rate_and_grad(refs)
    notes, good = [], []
    for i, (rate, grad) in enumerate(zip(s_rate, s_grad), 1):
        scale = max(float(np.nanmax(np.abs(grad))) if grad.size else 0.0, 1.0)
        if not np.all(np.isfinite(rate)) or np.abs(rate).max() > 1e-7 * scale * 10:
            notes.append(f"quantity {i} is not conserved")
            k = int(np.nanargmax(np.where(np.isfinite(rate), np.abs(rate), -1.0)))
            admit.witness(certify(f"the rate of change of your quantity {i} along the true motion",
                                  total_derivative(studs[i - 1], mech.s), {s: v[k] for s, v in pts.values.items()},
                                  mech=mech, truth=True))
        elif np.abs(grad).max() <= 1e-12:
            notes.append(f"quantity {i} is a constant, which says nothing")
            if not studs[i - 1].free_symbols & set(state):  # no state in it at all: a constant exactly
                admit.witness(Certificate(f"your quantity {i}", {}, "free of the coordinates and velocities"))
            else:
                admit.witness(None)
        else:
            good.append(i - 1)
    covered = 0
    for j in range(len(refs)):
        ok = bool(good)
        for k in range(pts.K) if good else []:
            A = s_grad[good, :, k].T
            b = r_grad[j, :, k]
            coef, *_ = np.linalg.lstsq(A, b, rcond=None)
            if np.abs(A @ coef - b).max() > 1e-7 * max(np.abs(b).max(), 1.0):
                ok = False
                admit.witness(outside_span(
                    f"a minor of your quantities' gradients stacked with the gradient of conserved quantity "
                    f"{j + 1} (zero if it were a function of yours)",
                    [[sp.diff(studs[g], v) for v in state] for g in good], [sp.diff(refs[j], v) for v in state],
                    s_grad[good, :, k], b, {s: v[k] for s, v in pts.values.items()}))
                break
        covered += ok
    wrong = surplus(len(items) - len(good), len(items), len(refs), ctx)
    fraction = max(covered - wrong, 0) / len(refs)
    if covered < len(refs):
        notes.append(f"{len(refs) - covered} of the {len(refs)} conserved quantities of this motion "
                     f"{'is' if len(refs) - covered == 1 else 'are'} missing")
    return graded(part, fraction, "numeric", "correct." if not notes else "Incorrect: " + "; ".join(notes) + ".",
                  ctx.credit)


def check_trajectory(ctx: Context, part: Part, value: object) -> PartResult:
    """q(t) in closed form: it must satisfy the equations of motion and the stated initial values."""
    mech = ctx.mech(part)
    if not isinstance(value, dict):
        raise InvalidAnswer(f"{part.name} should be a dict coordinate -> expression in t")
    given = keyed(value, part)
    missing = [n for n in mech.names if n not in given]
    if missing:
        raise InvalidAnswer(f"{part.name} is missing {', '.join(missing)}")
    sol = {}
    for name in mech.names:
        e = as_expr(given[name], part)
        sol[name] = read_sympy(e, part, mech, plain_coordinates=False, max_order=0)
    pts = sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name), extra=part.symbol_domains)
    args = [T, *mech.params, *(sp.Symbol(s) for s in part.symbols)]
    argv = pts.args(args)
    # The state along the student's q(t), then each term of Lagrange's equations at that state:
    # the residual is their sum, and its scale the sum of their sizes (robust to exact cancellation).
    motion = [e for name in mech.names for e in (sol[name], sp.diff(sol[name], T), sp.diff(sol[name], T, 2))]
    values = evaluate(motion, args, argv)
    state = dict(zip([v for trio in zip(mech.s.q, mech.s.qd, mech.s.qdd) for v in trio], values))
    state_args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, *args]
    state_argv = [*(state[v] for v in [*mech.s.q, *mech.s.qd, *mech.s.qdd]), *argv]
    res, scale = [], []
    for row in mech.EL:
        terms = evaluate(list(sp.Add.make_args(sp.expand(row))), state_args, state_argv)
        res.append(terms.sum(axis=0))
        scale.append(np.abs(terms).sum(axis=0))
    res, scale = np.array(res), np.array(scale)
    notes = []
    if not np.all(np.abs(res) <= 1e-8 * np.maximum(scale, 1e-300)):
        notes.append("it does not satisfy the equation of motion")
        with np.errstate(all="ignore"):
            rel = np.where(np.isfinite(res), np.abs(res) / np.maximum(scale, 1e-300), -1.0)
        i, k = np.unravel_index(int(np.argmax(rel)), rel.shape)
        along = {**{q: sol[n] for q, n in zip(mech.s.q, mech.names)},
                 **{v: sp.diff(sol[n], T) for v, n in zip(mech.s.qd, mech.names)},
                 **{a: sp.diff(sol[n], T, 2) for a, n in zip(mech.s.qdd, mech.names)}}
        admit.witness(certify(f"the equation of motion for {mech.names[i]} along your q(t)",
                              mech.EL[i].xreplace(along), {s: v[k] for s, v in pts.values.items()}))
    for key, text in part.initial.items():
        want = mech.parse(text, part.symbols)
        name = key[:-2] if key.endswith("_d") else key
        if name not in sol:
            continue
        have = sol[name] if key == name else sp.diff(sol[name], T)
        a = evaluate([have.subs(T, 0)], args, argv)[0]
        b = evaluate([want], args, argv)[0]
        if not np.allclose(a, b, rtol=1e-8, atol=1e-10):
            notes.append(f"it does not meet the initial condition for {name}{chr(39) if key != name else ''}(0)")
            k = int(np.nanargmax(np.where(np.isfinite(a - b), np.abs(a - b), -1.0)))
            admit.witness(certify(f"your {key}(0) minus the stated one", have.subs(T, 0) - want,
                                  {s: v[k] for s, v in pts.values.items()}))
    if notes:
        if len(mech.names) > 1:
            try:
                entry = _entries_against_motion(ctx, part, mech, sol)
            except Exception:  # noqa: BLE001  (per-entry credit is extra evidence; without it, all or nothing)
                entry = None
            if entry is not None and entry[0]:
                right, wrong = entry
                fraction = min(len(right) / len(mech.names), 1 - 1 / len(mech.names))
                note = (f"{_listed(right)} {'is' if len(right) == 1 else 'are'} right; {_listed(wrong)} "
                        f"{'does' if len(wrong) == 1 else 'do'} not follow the true motion")
                coupled = _coupled(mech, right, wrong)
                if coupled:
                    note += (f" (the equations of motion couple {coupled}: check {_listed(wrong)} against the "
                             f"equation it shares with {_listed(right)})")
                return graded(part, fraction, "numeric", "Incorrect: " + note + ".", ctx.credit)
        return graded(part, 0.0, "numeric", "Incorrect: " + "; ".join(notes) + ".")
    return graded(part, 1.0, "numeric", "correct: satisfies the equation of motion and the initial conditions.")


def _listed(names: list[str]) -> str:
    return " and ".join(f"{n}(t)" for n in names)


def _coupled(mech: Mechanics, right: list[str], wrong: list[str]) -> str:
    """Which right and wrong coordinates share an equation (an off-diagonal mass term or a force
    depending on the other coordinate), named for the feedback; empty if the motions are independent."""
    index = {n: i for i, n in enumerate(mech.names)}
    pairs = []
    for a in right:
        for b in wrong:
            i, j = index[a], index[b]
            vars_b = {mech.s.q[j], mech.s.qd[j], mech.s.qdd[j]}
            vars_a = {mech.s.q[i], mech.s.qd[i], mech.s.qdd[i]}
            if mech.EL[i].free_symbols & vars_b or mech.EL[j].free_symbols & vars_a:
                pairs.append(f"{a} and {b}")
    return ", ".join(pairs)


#: per-entry credit compares with 1e-6 of the motion: integrated well below that
_ENTRY_ACCURACY = Accuracy("entries", rtol=1e-11, atol=1e-12, method="DOP853")


def _entries_against_motion(ctx: Context, part: Part, mech: Mechanics, sol: dict[str, sp.Expr]
                            ) -> tuple[list[str], list[str]] | None:
    """Each coordinate's q(t) compared with the reference motion integrated from the stated initial
    values (a few parameter draws, a few times): which entries are right on their own. None when
    the initial values do not give the whole state or the motion cannot be integrated."""
    from lagrade.compare.scene_model import scene_motion

    keys = [*mech.names, *(f"{n}_d" for n in mech.names)]
    if any(k not in part.initial for k in keys):
        return None
    K = 3
    pts = sample_points(mech, K, rng_for(ctx.problem.id, part.name, "entries"), extra=part.symbol_domains)
    pargs = [*mech.params, *(sp.Symbol(x) for x in part.symbols)]
    y0 = np.array([np.broadcast_to(np.asarray(row, dtype=float), (K,)) for row in
                   evaluate([mech.parse(part.initial[k], part.symbols) for k in keys], pargs, pts.args(pargs))])
    params = np.array(pts.args(mech.params), dtype=float).reshape(len(mech.params), K)
    times = np.linspace(0.0, mech.system.horizon, 9)[1:]
    # the scene's model with its declared events, as every other path integrates it: a motion that
    # loses its contact is compared only up to there (the scene says nothing beyond)
    run = scene_motion(mech, y0, params, float(times[-1]), _ENTRY_ACCURACY, t_eval=np.concatenate([[0.0], times]))
    if not run.ok or run.y.shape[-1] != times.size + 1:
        return None
    ok = {name: True for name in mech.names}
    for k in range(K):
        live = times <= run.t_stop[k] + 1e-12
        if not live.any():
            continue
        argv = [np.asarray(times[live]), *(np.full(int(live.sum()), a[k]) for a in pts.args(pargs))]
        with np.errstate(all="ignore"):
            mine = evaluate([sol[name] for name in mech.names], [T, *pargs], argv)
        for i, name in enumerate(mech.names):
            true = run.y[i, k, 1:][live]
            if not np.allclose(mine[i], true, rtol=1e-6, atol=1e-6 * max(np.abs(true).max(), 1.0)):
                ok[name] = False
    right = [name for name in mech.names if ok[name]]
    return right, [name for name in mech.names if not ok[name]]
