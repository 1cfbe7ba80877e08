"""Checkers for the dynamics parts: the Lagrangian, equations of motion, H, Hamilton's equations.

Each collects three kinds of evidence: evaluation at random states (refutes almost every wrong
answer in microseconds), a time-bounded symbolic proof, and trajectories integrated from the same
initial states, whose visited states are evaluated too (the sampling box does not reach where every
motion goes). A correct answer is accepted on agreement at every such state even when the symbolic
proof gives up; a wrong one is refuted by the states and explained by the trajectories.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers import admit
from lagrade.verdicts.checkers.base import (
    Context,
    InvalidAnswer,
    equation_rows,
    factor_text,
    graded,
    in_kind,
    multiplier_names,
    read_expr,
    read_sympy,
)
from lagrade.compare.certify import Certificate, certify, outside_span, sign_change, zero_at
from lagrade.compare.equations import CompiledRows, analyse_rows, slopes
from lagrade.compare import coprime, exact
from lagrade.compare.symbolic import _OutOfTime, proves_all_zero, proves_zero, time_bound
from lagrade.compare.trajectory import Comparison, compare_runs, confirm_refutation
from lagrade.derive.effects import machinery
from lagrade.compare.scene_model import hamilton_rows
from lagrade.numbers.numeric import (
    CompiledRates,
    Vectorized,
    agree,
    compile_exprs,
    evaluate,
    scale_of,
)
from lagrade.derive.reference import Mechanics, split_energy
from lagrade.verdicts.result import PartResult
from lagrade.compare.sampling import (
    Points,
    grouped,
    rng_for,
    sample_points,
    state_arrays,
    with_reference_dynamics,
)
from lagrade.problem.spec import Part
from lagrade.problem.symbols import T

# ----------------------------------------------------------------------------- helpers


def _grouped_points(ctx: Context, mech: Mechanics, part: Part, groups: int = 6, per_group: int = 4):
    """Points in groups sharing parameters and time, so 'constant' can be told from 'state-dependent'."""
    pts = sample_points(mech, groups * per_group, rng_for(ctx.problem.id, part.name), extra=part.symbol_domains)
    return grouped(pts, mech, part.symbols, per_group), groups, per_group


def _trajectory_inits(ctx: Context, mech: Mechanics, part: Part):
    """Initial states per system (not per part), so that L, eom and H share one reference motion."""
    pts = sample_points(mech, ctx.accuracy.trajectories,
                        rng_for(ctx.problem.id, mech.system.key, "trajectory", *part.symbols), extra=part.symbol_domains)
    q, qd, _, params = state_arrays(mech, pts)
    extra = np.array([pts[sp.Symbol(s)] for s in part.symbols]).reshape(len(part.symbols), pts.K)
    return q, qd, params, extra


def _trajectory_lagrange(ctx: Context, mech: Mechanics, part: Part, student_acc: Callable[[], Vectorized],
                         student_rows: Callable[[], list[sp.Expr]] | None = None) -> Comparison:
    """``student_acc()``: the student's accelerations, compiled, as a function of the rows [q, q', t,
    parameters, the part's extra symbols]; ``student_rows()``: the equations they solve (needed where
    the scene declares switching: both sides are then integrated as switching models)."""
    run = lagrange_inputs(ctx, mech, part, student_acc, student_rows)
    comparison = compare_runs(run.student, run.reference, run.y0, run.labels, mech.system.horizon, ctx.accuracy,
                              events=run.events, student_events=run.student_events, reference_key=run.key,
                              store=mech.runs)
    arm = _rearm([run.student, run.reference] if run.switching else [], run.y0)
    comparison.confirm = lambda: (arm(), confirm_refutation(comparison, run.student, run.reference, run.y0,
                                                            ctx.accuracy, run.events, run.student_events))
    comparison.case = TrajectoryCase(run.student, run.reference, run.y0, run.labels, mech.system.horizon,
                                     ctx.accuracy, run.events, run.student_events, arm)
    return comparison


@dataclass
class LagrangeInputs:
    """What the trajectory check of a second-order part hands `compare_runs` (also what
    `lagrade.uses.research.effectsbench` times)."""

    student: Callable
    reference: Callable
    y0: np.ndarray
    labels: list[str]
    events: list            # the reference run's
    key: tuple
    switching: bool
    student_events: list | None = None   # the student run's (None: the same as the reference's)


def lagrange_inputs(ctx: Context, mech: Mechanics, part: Part, student_acc: Callable[[], Vectorized],
                    student_rows: Callable[[], list[sp.Expr]] | None = None, *,
                    everything: bool = False) -> LagrangeInputs:
    """The reference is the scene's model built from its declared effects (`scene_model`), on every
    path. Scenes that declare switching (dissipation with a velocity sign/Abs): that model and the
    student's rows as switching models, each with its own switching events (the reference's contact
    loss stops both). Others, the case "no switching declared" of the same builder: its compiled
    rates (no t argument for an autonomous scene) and its declared events, against the student's
    compiled rates. ``everything``: the same path with the model built with all machinery (time
    argument, contact events on every multiplier, switching on every velocity Abs/sign): the
    baseline of benchmarks/effects.py."""
    q, qd, params, extra = _trajectory_inits(ctx, mech, part)
    n = len(mech.names)
    constants = np.concatenate([params, extra])
    labels = [*mech.names, *(f"{x}'" for x in mech.names)]
    y0 = np.concatenate([q, qd])
    from lagrade.compare.scene_model import scene_model

    model = scene_model(mech, everything=everything)
    if student_rows is not None and model.machinery.switching:
        stu, ref, events, stu_events = _switching_models(mech, part, student_rows(), params, constants, y0, everything)
        return LagrangeInputs(stu, ref, y0, labels, events, ("lagrange-switching", tuple(part.symbols)), True,
                              stu_events)
    stu = CompiledRates(student_acc(), 2 * n, constants, copied=n)
    # the events are the declared ones: contact loss only for unilateral contact (the comparison ends
    # where the true motion leaves the surface, the model is not valid beyond it)
    return LagrangeInputs(stu, model.compiled_rates(params), y0, labels, model.events(y0, params),
                          ("lagrange", tuple(part.symbols)), False)


def _switching_models(mech: Mechanics, part: Part, rows: list[sp.Expr], params: np.ndarray,
                      constants: np.ndarray, y0: np.ndarray, everything: bool = False):
    """The scene's declared-effects model (the reference) and the student's equations made a switching
    model the same way (each velocity sign a branch, Filippov's rule at its zeros), each with its own
    switching events, and the reference's contact loss stopping both: (student, reference, the
    reference's events, the student's)."""
    from lagrade.compare.scene_model import EquationsModel, SceneModel

    ref = SceneModel(mech, everything=everything)
    ref.params = params
    args = [*mech.s.q, *mech.s.qd, T, *mech.params, *(sp.Symbol(s) for s in part.symbols)]
    stu = EquationsModel(rows, mech, args, constants)
    contact = SceneModel(mech, everything=everything).contact_events(y0, params)  # unarmed: the exact forces
    return stu, ref, contact + ref.switching_events(y0), contact + stu.switching_events(y0)


def _trajectory_hamilton(ctx: Context, mech: Mechanics, part: Part, student_rates: Callable[[], Vectorized],
                         student_rows: Callable[[], list[sp.Expr]] | None = None) -> Comparison:
    """``student_rates()``: (q', p') compiled as a function of the rows [q, p, t, parameters, extra];
    ``student_rows()``: the equations (linear in q', p') they solve, needed where the scene declares
    switching: both sides are then integrated as switching models in (q, p)."""
    q, qd, params, extra = _trajectory_inits(ctx, mech, part)
    n = len(mech.names)
    t0 = np.zeros(q.shape[1])
    p = mech.momenta(q, qd, t0, params)
    labels = [*mech.names, *(f"p_{x}" for x in mech.names)]
    y0 = np.concatenate([q, p])
    constants = np.concatenate([params, extra])
    from lagrade.compare.scene_model import scene_model

    model = scene_model(mech)
    # the scene's contact loss, watched in (q, p): the comparison ends where the model does
    contact = model.phase_contact_events(y0, params)
    models = _hamilton_switching(ctx, mech, part, student_rows, constants, y0, params) \
        if student_rows is not None and machinery(mech).switching else None
    if models is not None:
        stu, ref, events, stu_events = models
        events, stu_events = contact + events, contact + stu_events
        key = ("hamilton-switching", tuple(part.symbols))
    else:
        ref = model.hamilton_rates(params)
        stu = CompiledRates(student_rates(), 2 * n, constants)
        events, stu_events, key = contact, None, ("hamilton", tuple(part.symbols))
    comparison = compare_runs(stu, ref, y0, labels, mech.system.horizon, ctx.accuracy, events=events,
                              student_events=stu_events, reference_key=key, store=mech.runs)
    arm = _rearm([stu, ref] if models is not None else [], y0)
    comparison.confirm = lambda stu=stu, ref=ref: (arm(), confirm_refutation(comparison, stu, ref, y0, ctx.accuracy,
                                                                              events, stu_events))
    comparison.case = TrajectoryCase(stu, ref, y0, labels, mech.system.horizon, ctx.accuracy, events,
                                     stu_events, arm)
    return comparison


def _rearm(models: list, y0: np.ndarray) -> Callable[[], None]:
    """Put switching models back on the branches of ``y0`` before a run again (the confirmation at a
    tighter tolerance, the picture): a run leaves each on the branch its motion ended on."""
    def arm() -> None:
        for m in models:
            m.arm(y0)
    return arm


def _hamilton_switching(ctx: Context, mech: Mechanics, part: Part, student_rows: Callable[[], list[sp.Expr]],
                        constants: np.ndarray, y0: np.ndarray, params: np.ndarray):
    """The scene's switching model read in (q, p) (`PhaseModel`: its declared forces and branches) and
    the student's Hamilton's equations as a switching model built the same way (the friction's sign is
    one of p there), each with its own switching events."""
    from lagrade.compare.scene_model import EquationsModel, PhaseModel, SceneModel, phase_form

    s = mech.s
    args = [*s.q, *s.p, T, *mech.params, *(sp.Symbol(x) for x in part.symbols)]
    ref = PhaseModel(SceneModel(mech), params)
    stu = EquationsModel(student_rows(), mech, args, constants, **phase_form(mech))
    return stu, ref, ref.switching_events(y0), stu.switching_events(y0)


@dataclass
class TrajectoryCase:
    """What it takes to integrate a part's motion again (for the ``--plot`` picture)."""

    student: Callable
    reference: Callable
    y0: np.ndarray
    labels: list[str]
    horizon: float
    accuracy: object
    #: the grading run's events (contact loss, switching), and the student's when they differ
    events: list = field(default_factory=list)
    student_events: list | None = None
    #: puts switching models back on the branches of y0 before they are run again
    arm: Callable[[], None] = lambda: None


def _cost(traj: Comparison) -> str:
    acc = traj.case.accuracy if getattr(traj, "case", None) else None
    tol = f"compared within rtol {acc.compare_rtol:g}, atol {acc.compare_atol:g}, " if acc is not None else ""
    return f" ({tol}{traj.rhs_evals} evaluations, {traj.seconds:.2f} s)"


def _sampled(ctx: Context) -> str:
    """The tolerance that decided agreement at the sampled states: the preset's ``sample_rtol``, said
    beside the states it applies to (the comparison's looser rtol is the trajectories', said with them)."""
    return f" (within rtol {ctx.accuracy.sample_rtol:g})"


def _confirm(ctx: Context, prove: Callable[[], bool | None], trajectory: Callable[[], Comparison]):
    """Evidence beyond agreement at every sampled state: trajectories first (cheap, batched); a
    symbolic proof only where they do not settle it (chaos, a failed integration) or when asked
    (``--accuracy strict``), because sympy's simplification can take far longer than everything else.
    An answer outside the analytic class (`admit`) is accepted on a proof alone, so its proof comes
    first, and without one no motion is integrated (an undeclared friction switch would only run the
    integrator to its budget)."""
    if admit.pending():
        proof = prove()
        # an unproved flagged answer earns nothing; a smooth one's motion may still refute it, with
        # that evidence (a bump outside the exact class: issue 45); a switch's is not run
        return (proof, _try(trajectory)) if proof or admit.smooth_pending() else (proof, None)
    traj = _try(trajectory)
    proof = prove() if ctx.prove_always or traj is None or not traj.agree else None
    return proof, traj


def _decide(ctx: Context, part: Part, proof: bool | None, traj: Comparison | None, note: str = "") -> PartResult:
    """Agreement at every sampled state and at the states the reference motions visit (within the
    preset's ``sample_rtol``) already holds when this is called, for an answer the acceptance rule
    (`admit`) lets sampling decide: exact simple numbers, no switch. A proof settles it; otherwise the
    trajectories do: motions that separate beyond the preset's tolerance refute the answer (an error
    below ``sample_rtol`` at every state that grows along the motion), with the refutation's evidence
    and its confirmation at a finer tolerance; evidence that could not decide is flagged for review."""
    extra = f" {note}" if note else ""
    if proof:
        admit.proved()
        res = graded(part, 1.0, "symbolic", f"correct: proved equivalent to the reference.{extra}")
        if traj is not None and traj.decisive:
            res.review = ("proved equivalent, yet the integrated motions differ beyond the tolerance: "
                          f"{traj.describe()}; the integration deserves a look")
        return res
    if traj is not None and traj.agree:
        res = graded(part, 1.0, "trajectory",
                     f"correct: equal at every sampled state{_sampled(ctx)} and {traj.describe()}{_cost(traj)}.{extra}")
        if traj.window is not None and traj.why_window.startswith("chaotic") and traj.window < 0.1 * traj.horizon:
            res.review = (f"chaotic scene: the motions could be compared only over [0, {traj.window:.3g}] of "
                          f"[0, {traj.horizon:.3g}], so they hardly tested this answer beyond the sampled states")
        return res
    if traj is not None and traj.decisive:
        acc = ctx.accuracy
        res = graded(part, 0.0, "trajectory",
                     "Incorrect: your answer agrees with the right one at every sampled state to about "
                     f"{acc.sample_rtol:g} (relative), but not exactly: "
                     f"{traj.describe()} (beyond the {acc.name} comparison tolerance, rtol {acc.compare_rtol:g}). "
                     "A constant or coefficient slightly off (a rounded number, say) does this.")
        return _with_trajectory_evidence(res, traj)
    res = graded(part, 1.0, "numeric", f"correct: equal at every sampled state{_sampled(ctx)}.{extra}")
    why = traj.describe() if traj is not None else "the answer's motion could not be integrated"
    res.review = f"decided by the sampled states alone: no symbolic proof, and no trajectory evidence ({why})"
    return res


def _with_trajectory_evidence(res: PartResult, traj: Comparison) -> PartResult:
    """A rejection the trajectory comparison decided carries what it rests on (`confirm_refutation`);
    one the finer tolerance does not confirm is flagged for review, never a silent reject."""
    if traj.confirm is not None and traj.confirmed is None:
        try:
            traj.confirm()
        except Exception as exc:  # noqa: BLE001  (evidence about evidence: its failure is said)
            traj.confirmed, traj.evidence = False, f"not confirmed: the confirmation failed ({exc})"
    res.confirmed = bool(traj.confirmed)
    res.trajectory_evidence = traj.evidence
    res.motion_evidence = traj.measured
    if not res.confirmed:
        res.review = ("rejected by the trajectory comparison alone, and the comparison at a 100x finer integration "
                      "tolerance did not confirm it (the evidence is in trajectory_evidence)")
    return res


def _motion_refutes(ctx: Context, part: Part, proof: bool | None, traj: Comparison | None) -> PartResult | None:
    """The motion decides first: motions from the same grading states that separate beyond the preset's
    comparison tolerance, confirmed at the finer integration tolerance (the separation beyond the
    integration's error estimate, `confirm_refutation`), refute the answer with that evidence, before
    any rule about states. An unconfirmed separation decides nothing here: the states' evidence goes
    on, and `_decide` flags what is left for review."""
    if proof or traj is None or not traj.decisive:
        return None
    res = _decide(ctx, part, None, traj)
    return res if res.confirmed else None


def _wrong(part: Part, fraction: float, message: str, traj: Comparison | None, credit=None) -> PartResult:
    detail = ""
    if traj is not None and not traj.agree:
        said = traj.describe()
        friction = [w for why in admit.pending() for w in why.split("; ") if admit.UNDECLARED_FRICTION in w]
        if traj.note and friction:  # a motion that sticks and chatters is followed by no integrator: what was
            said = friction[0]      # found is the switch, as a refusal says it (issue 45)
        detail = f" {said[0].upper()}{said[1:]}."
    res = graded(part, fraction, "numeric", f"{message}{detail}", credit)
    res._trajectory = getattr(traj, "case", None)
    return res


def _once(build: Callable[[], Vectorized]) -> Callable[[], Vectorized]:
    """Compile a student's dynamics only if a trajectory is needed, and then only once."""
    made: list[Vectorized] = []

    def get() -> Vectorized:
        if not made:
            made.append(build())
        return made[0]

    return get


def _sentence(parts: list[str]) -> str:
    text = "; ".join(parts)
    return (text[:1].upper() + text[1:] + ".") if text else ""


def _try(fn: Callable[[], Comparison]) -> Comparison | None:
    """Trajectory evidence is extra: if a student's expression cannot even be compiled, skip it."""
    try:
        return fn()
    except Exception:  # noqa: BLE001
        return None


# ----------------------------------------------------------------------------- states along the motion

#: states taken along each reference trajectory (from its stored samples) where the equations must agree
MOTION_STATES = 16
#: how a rejection at those states is worded (and told from one at the box samples)
ALONG_MOTION = "at states the true motion reaches beyond the range states are sampled from"


def _motion_points(ctx: Context, mech: Mechanics, part: Part, traj: Comparison | None, phase: bool = False):
    """The states the reference motion visits (its stored samples inside the compared window, beyond the
    sampling box too), with its trajectories' parameters and symbols and the reference dynamics there;
    None without a reference motion or where the scene switches (a friction's branch at a stuck state is
    the integrator's, not the equations'). Any state is a valid test of equations, so neither chaos nor
    the integration's error makes these states less fit. ``phase``: the run is in (q, p)."""
    if traj is None or traj.reference_y is None or traj.reference_t is None or machinery(mech).switching:
        return None
    t, y = traj.reference_t, traj.reference_y
    if t.size < 2:
        return None
    n, K = len(mech.names), y.shape[1]
    _, _, params, extra = _trajectory_inits(ctx, mech, part)
    idx = np.unique(np.linspace(1, t.size - 1, min(MOTION_STATES, t.size - 1)).round().astype(int))
    m = idx.size
    Y = y[:, :, idx].reshape(y.shape[0], K * m)       # column k*m + j: trajectory k, time idx[j]
    times = np.tile(t[idx], K)
    stop = traj.reference_stop if traj.reference_stop is not None else np.full(K, np.inf)
    live = (times <= np.repeat(stop, m) + 1e-12) & np.isfinite(Y).all(axis=0)
    if not live.any():
        return None
    P = np.repeat(params, m, axis=1)[:, live]
    E = np.repeat(extra, m, axis=1)[:, live]
    Y, times = Y[:, live], times[live]
    q = Y[:n]
    with np.errstate(all="ignore"):
        qd = mech.velocities(q, Y[n:], times, P) if phase else Y[n:]
    vals: dict[sp.Symbol, np.ndarray] = {T: times}
    vals.update(zip(mech.params, P))
    vals.update((sp.Symbol(s), v) for s, v in zip(part.symbols, E))
    vals.update(zip(mech.s.q, q))
    vals.update(zip(mech.s.qd, np.asarray(qd, dtype=float).reshape(n, -1)))
    vals.update((a, np.zeros(times.size)) for a in mech.s.qdd)
    with np.errstate(all="ignore"):
        pts = with_reference_dynamics(mech, Points(vals, int(times.size)))
    if phase:
        pts.values.update(zip(mech.s.p, Y[n:]))
    return pts


def _along_motion(ctx: Context, mech: Mechanics, part: Part, traj: Comparison | None, compiled: CompiledRows,
                  labels: list[str], phase: bool = False):
    """The rows at the states the reference motion visits, with the tolerance of the sampled states:
    (analysis, points, argument values, true rates) when some row does not hold there, else None. A
    state where the student's rows or the true rates are not finite is left out (an undefined value is
    the trajectory comparison's to judge)."""
    pts = _motion_points(ctx, mech, part, traj, phase)
    if pts is None:
        return None
    extra = [sp.Symbol(s) for s in part.symbols]
    velocity = mech.s.p if phase else mech.s.qd
    args = [*mech.s.q, *velocity, T, *mech.params, *extra]
    q, qd, t, params = state_arrays(mech, pts)
    with np.errstate(all="ignore"):
        truth = mech.hamilton_rates(q, np.array(pts.args(mech.s.p)), t, params) if phase \
            else np.array(pts.args(mech.s.qdd))
        g = compiled.values(pts.args(args), truth)
    ok = np.isfinite(g).all(axis=0) & np.isfinite(truth).all(axis=0)
    if not ok.any():
        return None
    pts = Points({s: np.asarray(v)[ok] if np.ndim(v) else v for s, v in pts.values.items()}, int(ok.sum()))
    truth = truth[:, ok]
    argv = pts.args(args)
    with np.errstate(all="ignore"):
        an = analyse_rows(compiled, argv, truth, labels, rtol=ctx.accuracy.sample_rtol)
    return (an, pts, argv, truth) if an.wrong else None


#: sampled states at which equations agreeing in floating point are evaluated again in ball
#: arithmetic before they are accepted (`_exact_refutation`)
EXACT_STATES = 3
EXACTLY = ("at an exact state, evaluated in ball arithmetic: the difference is smaller than floating point "
           "can show, but it is not zero")


def _exact_refutation(mech: Mechanics, part: Part, rows: list[sp.Expr], pts, what: str,
                      traj: Comparison | None, phase: bool = False) -> PartResult | None:
    """Equations that agree with the true ones at every sampled state in floating point (within the
    preset's tolerance) are evaluated again at a few of those states, taken as exact rationals, with
    the true accelerations solved in ball arithmetic (`lagrade.compare.certify`, 128 bits): rows that
    hold for the true motion enclose zero there whatever their form; an enclosure that excludes zero
    refutes them, with its certificate (``what`` names a row, ``{i}`` its number). It catches what a difference below the tolerance hides (an L
    term whose Lagrange equations differ by 1e-10, `(theta + 10001)/(theta + 10000)`), which the
    comparison in floating point cannot: a wrong answer below both this and the screen's
    negligible-part rule (`admit._negligible`) would need a difference under 1e-35. ``phase``: the
    rows are Hamilton's equations, evaluated at (q, p) with the true rates q', p'."""
    if machinery(mech).switching or admit.pending():  # a flagged answer is refused, or proved, for its flag
        return None
    for k in range(min(EXACT_STATES, pts.K)):
        at = {s: float(np.real(v[k])) if np.ndim(v) else float(np.real(v)) for s, v in pts.values.items()}
        for i, row in enumerate(rows):
            name = what.format(i=i + 1)
            cert = certify(f"{name} at the true {'rates' if phase else 'accelerations'}", row, at, mech=mech,
                           **({"phase": True} if phase else {"truth": True}))
            if cert is not None:
                admit.witness(cert)
                return _wrong(part, 0.0, f"Incorrect: {name} does not hold for the true motion {EXACTLY}.", traj)
    return None


def _motion_refutation(ctx: Context, mech: Mechanics, part: Part, traj: Comparison | None, rows: list[sp.Expr],
                       phase: bool, what: str) -> PartResult | None:
    """An L or H accepted at the sampled states whose equations (Lagrange's or Hamilton's) do not hold
    at states the true motion visits: the rejection, certified like one at the sampled states."""
    if traj is None or traj.reference_y is None or machinery(mech).switching:
        return None
    extra = [sp.Symbol(s) for s in part.symbols]
    unknowns = [*mech.s.qd, *mech.s.pd] if phase else list(mech.s.qdd)
    args = [*mech.s.q, *(mech.s.p if phase else mech.s.qd), T, *mech.params, *extra]
    labels = [*(f"{x}'" for x in mech.names), *(f"p_{x}'" for x in mech.names)] if phase else list(mech.names)
    off = _along_motion(ctx, mech, part, traj, CompiledRows(rows, unknowns, args), labels, phase)
    if off is None:
        return None
    an, pts, argv, truth = off
    _certify_rows(mech, rows, an, CompiledRows(rows, unknowns, args), argv, truth, pts,
                  "rates" if phase else "accelerations", **({"phase": True} if phase else {"truth": True}))
    return _wrong(part, 0.0, f"Incorrect: {what} agree with the true ones at the sampled states but not "
                  f"{ALONG_MOTION}.", traj)


# ----------------------------------------------------------------------------- the Lagrangian


def _el_matrix(L: sp.Expr, mech: Mechanics, pts, part: Part) -> np.ndarray:
    """Lagrange's equations of ``L`` with the scene's generalized forces, ``d/dt dL/dq' - dL/dq - Q``,
    at the sampled states (random accelerations): with Q != 0 a scaled L is no longer equivalent."""
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *mech.params, *(sp.Symbol(s) for s in part.symbols)]
    return evaluate(mech.lagrange_rows(L), args, pts.args(args))


def _lagrange_solver(L: sp.Expr, mech: Mechanics, part: Part):
    """Accelerations of the motion ``L`` (with the scene's forces) defines, compiled once."""
    return CompiledRows(mech.lagrange_rows(L), mech.s.qdd, [*mech.s.q, *mech.s.qd, T, *mech.params,
                                                          *(sp.Symbol(s) for s in part.symbols)]).solver


def reduce_by_constraints(expr: sp.Expr, mech: Mechanics) -> sp.Expr:
    """A student may keep a constrained coordinate (x with x = R*phi): the constraint is part of the problem."""
    return expr.xreplace(mech.constrained) if mech.constrained else expr


def _scaling(E_s: np.ndarray, E_r: np.ndarray, groups: int, per: int, rtol: float = 1e-8) -> np.ndarray | None:
    """Per group of shared parameters, the c with E_s = c E_r at every state (within ``rtol``), or None."""
    cs = []
    for g in range(groups):
        sl = slice(g * per, (g + 1) * per)
        a, b = E_s[:, sl].ravel(), E_r[:, sl].ravel()
        denom = float(b @ b)
        if denom == 0 or not np.all(np.isfinite(a)):
            return None
        c = float(a @ b) / denom
        if not np.all(agree(a, c * b, rtol)):
            return None
        cs.append(c)
    return np.array(cs)


EXACT_WRONG = ("is not the true one: exact arithmetic shows a difference, even where it agrees at every state tried "
               "(a coefficient or a number in it is not the right one)")


def _needs_proof(exprs: list[sp.Expr], ctx: Context, mech: Mechanics) -> None:
    """Flag (`admit.flag`) an answer outside the exact class in a way the screen does not see
    (`exact.needs_proof`: ``0**(9 - theta**2)``, ``sqrt(exp(2*I*theta))``): agreement at the sampled states
    and along the sampled motions proves nothing beyond them, so only a proof may accept it."""
    for e in exprs:
        why = exact.needs_proof(e, ctx.domain(mech))
        if why is not None:
            admit.flag(e, f"it is outside the class of expressions decided exactly ({why})")
            return


def _exactly_wrong(part: Part, what: str, after: str = "") -> PartResult:
    """No credit, decided in exact arithmetic; what the screen had flagged (an inexact number) is said too."""
    flagged = admit.pending()
    admit.proved()
    why = f" ({'; '.join(flagged)})" if flagged else ""
    return graded(part, 0.0, "exact", f"Incorrect: {what} {EXACT_WRONG}{why}.{after}")


def _exact_scale(rows: list[sp.Expr], truth: list[sp.Expr], ctx: Context, mech: Mechanics) -> sp.Expr | None:
    """The constant c (a number) with rows = c * truth exactly (a scaled L's Lagrange equations), or None."""
    try:
        row, ref, a = next((r, t, a) for r, t in zip(rows, truth) for a in mech.s.qdd if sp.diff(t, a) != 0)
        c = sp.cancel(sp.diff(row, a) / sp.diff(ref, a))
        if c.free_symbols or c == 0 or c == 1:
            return None
        same = _exactly_zero([r - c * t for r, t in zip(rows, truth)], ctx, mech)
        return c if same else None
    except (StopIteration, Exception):  # noqa: BLE001  (no scale shown: refused as different)
        return None


def _exactly_zero(exprs: list[sp.Expr], ctx: Context, mech: Mechanics, what: str = "equation {i}") -> bool | None:
    """All of ``exprs`` identically zero on the physical domain (`lagrade.compare.exact`): True; one of
    them not: False, with its witness; None when one is outside the exact class and none is refuted.
    A scene whose physics is a switch (declared friction, drag, contact) is left to the motion."""
    if machinery(mech).switching:
        return None
    out: bool | None = True
    for i, e in enumerate(exprs):
        got = exact.is_zero(e, ctx.domain(mech), ctx.symbolic_seconds)
        if got is False:
            admit.witness(exact.witness(what.format(i=i + 1)))
            return False
        if got is None:
            out = None
    return out


def _exactly_zero_given(rows: list[sp.Expr], ctx: Context, mech: Mechanics, what: str) -> bool | None:
    """Every row zero at the true accelerations (the scene's mass matrix and forces, solved at each point
    modulo a prime: `exact.is_zero_given`, no symbolic solve). Switching scenes are left to the motion."""
    if machinery(mech).switching:
        return None
    got = exact.is_zero_given(rows, list(mech.s.qdd), [list(mech.mass.row(i)) for i in range(mech.mass.rows)],
                              list(mech.force), ctx.domain(mech), ctx.symbolic_seconds)
    if got is False:
        admit.witness(exact.witness(what.format(i="")))
    return got


def _exactly_hamiltonian(H_s: sp.Expr, ctx: Context, mech: Mechanics) -> bool | None:
    """Your H against the scene's, exactly, without inverting the Legendre map symbolically: at (q, p, t)
    with q' solved from p = dL/dq' (linear: L quadratic in the velocities), dH/dp = q', dH/dq = -dL/dq and
    dH/dt = -dL/dt. Together: H is the true one up to a constant."""
    if machinery(mech).switching or not mech.is_quadratic_in_velocities:
        return None
    L = mech.L
    zero = {v: 0 for v in mech.s.qd}
    A = [[sp.diff(L, a, c).xreplace(zero) for c in mech.s.qd] for a in mech.s.qd]
    b = [p - sp.diff(L, v).xreplace(zero) for p, v in zip(mech.s.p, mech.s.qd)]
    rows = [*(sp.diff(H_s, p) - v for p, v in zip(mech.s.p, mech.s.qd)),
            *(sp.diff(H_s, q) + sp.diff(L, q) for q in mech.s.q), sp.diff(H_s, T) + sp.diff(L, T)]
    got = exact.is_zero_given(rows, list(mech.s.qd), A, b, ctx.domain(mech), ctx.symbolic_seconds)
    if got is False:
        admit.witness(exact.witness("a derivative of your H minus the true one"))
    return got


def _definite(e: sp.Expr) -> bool:
    """Every factor of ``e`` (assumption-carrying symbols) of one sign, by sympy's assumptions alone."""
    return all(f.is_positive or f.is_negative for f in sp.Mul.make_args(sp.factor_terms(e)) if f.free_symbols)


def _row_factors(row: sp.Expr, qdd: list[sp.Symbol], positive: set[str]) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """(the factors common to a whole equation, the factors of its denominator), each with a variable.
    A factor common to the equation divides each acceleration's coefficient: where the simplest of them
    and every denominator are of one sign, there is none to find (the common case, at no factoring)."""
    assumed = exact._assume(row, positive)
    acc = [exact._assume(a, positive) for a in qdd]
    coefficients = [c for c in slopes(assumed, acc).values() if c != 0]  # sp.diff(assumed, a), cheaper
    bases = list(exact.poles(assumed))  # what it divides by, anywhere (a tan(u)'s cos(u) too)
    if coefficients and _definite(min(coefficients, key=sp.count_ops)) and all(_definite(b) for b in bases):
        return [], []
    num = sp.fraction(sp.together(assumed))[0]
    poly = sp.Poly(num, *acc)
    common = _common_factor(poly.coeffs()) if len(poly.coeffs()) > 1 else poly.coeffs()[0]
    factors = [f for f, _ in sp.factor_list(common)[1] if f.free_symbols] if common.free_symbols else []
    return factors, [f for b in bases if b.free_symbols for f, _ in sp.factor_list(b)[1] if f.free_symbols]


def _common_factor(coefficients: list[sp.Expr]) -> sp.Expr:
    """``sp.gcd_list(coefficients)`` up to a constant factor (which the factors taken from it ignore): in the
    ring sympy's gcd would use, a monomial when `coprime.monomial_gcd` proves the gcd is one (the common
    case, at a fraction of the cost), else sympy's gcd itself."""
    from sympy.polys.polyerrors import PolificationFailed
    from sympy.polys.polytools import parallel_poly_from_expr

    try:
        polys, opt = parallel_poly_from_expr(coefficients)
    except PolificationFailed:
        polys = []
    if polys and all(p.domain.is_ZZ or p.domain.is_QQ for p in polys):
        low = coprime.monomial_gcd([p.as_dict(native=True) for p in polys])
        if low is not None:
            return sp.Mul(*(g**e for g, e in zip(opt.gens, low) if e))
    return sp.gcd_list(coefficients)


def _singular_factor(rows: list[sp.Expr], mech: Mechanics, ctx: Context) -> str | None:
    """A factor of one of the equations (all of its terms), or of its denominator, that vanishes somewhere on
    the physical domain and is not the scene's own (a factor of a reference equation or of its denominator,
    up to a constant): equations multiplied by ``(m1 - 50)`` say nothing where it vanishes. The witness is
    exact: a real root, in the domain, of the factor as a polynomial in one symbol with the others at
    domain values (`exact.vanishes_in_domain`). None when no factor is shown to vanish (the sampled states'
    rule then stands)."""
    try:
        with time_bound(ctx.symbolic_seconds):
            mine = [f for r in rows for part in _row_factors(r, mech.s.qdd, ctx.domain(mech)) for f in part]
            suspects = [f for f in mine if not (f.is_positive or f.is_negative) and exact.vanishes_in_domain(f, ctx.domain(mech))]
            if not suspects:
                return None
            own = mech.linearized.get(("row factors",), (None,))[0]  # the scene's own: once per problem
            if own is None:
                own = [f for r in mech.EL for part in _row_factors(r, mech.s.qdd, ctx.domain(mech)) for f in part]
                mech.linearized[("row factors",)] = (own,)
            for f in suspects:
                if not any(exact.proportional(f, g, ctx.domain(mech), ctx.symbolic_seconds) for g in own):
                    return sp.sstr(f)
    except (_OutOfTime, Exception):  # noqa: BLE001  (no proof either way: the sampled states' rule stands)
        return None
    return None


def check_lagrangian(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    L_s = reduce_by_constraints(read_expr(value, part, mech, plain_coordinates=False, max_order=1), mech)
    if any(L_s.has(a) for a in mech.s.qdd):
        raise InvalidAnswer(f"{part.name} contains accelerations; a Lagrangian depends on q, q' and t only")
    pts, groups, per = _grouped_points(ctx, mech, part)
    E_r = _el_matrix(mech.L, mech, pts, part)
    E_s = _el_matrix(L_s, mech, pts, part)
    rtol = ctx.accuracy.sample_rtol
    c = _scaling(E_s, E_r, groups, per, rtol)

    student_acc = _once(lambda: _lagrange_solver(L_s, mech, part))

    def student_rows() -> list[sp.Expr]:
        return mech.lagrange_rows(L_s)

    if c is not None and np.allclose(c, 1.0, rtol=rtol, atol=0):
        _needs_proof([L_s], ctx, mech)
        decided = None if exact.outside(L_s, ctx.domain(mech)) else _exactly_zero(
            [a - b for a, b in zip(student_rows(), mech.EL)], ctx, mech, "your Lagrange equation {i} minus the true one")
        if decided is not None:
            if not decided:
                scale = _exact_scale(student_rows(), list(mech.EL), ctx, mech)
                if scale is None:
                    return _exactly_wrong(part, "the Lagrange equations your L gives")
                admit.proved()
                said = factor_text(float(scale)) or f"a constant factor ({in_kind(float(scale))})"
                return graded(part, ctx.credit.scaled_lagrangian, "exact",
                              f"your Lagrangian is the right one scaled by {said}: it gives the same equations of "
                              "motion, but L = T - V fixes the scale (the momenta and H would be off by that factor).")
            admit.proved()
            return graded(part, 1.0, "exact", "correct: its Lagrange equations are exactly the true ones.")
        proof, traj = _confirm(
            ctx, lambda: proves_all_zero([a - b for a, b in zip(mech.lagrange_rows(L_s), mech.EL)],
                                         ctx.symbolic_seconds, ctx.positive),
            lambda: _trajectory_lagrange(ctx, mech, part, student_acc, student_rows))
        moved = _motion_refutes(ctx, part, proof, traj)
        if moved is not None:
            return moved
        off = None if proof else _motion_refutation(ctx, mech, part, traj, student_rows(), False,
                                                    "the Lagrange equations your L gives")
        if off is None and not proof:
            off = _exact_refutation(mech, part, student_rows(), pts, "Lagrange's equation {i} of your L", traj)
        if off is not None:
            return off
        args = [*mech.s.q, *mech.s.qd, T, *mech.params]
        diff = evaluate([L_s - mech.L], args, pts.args(args))[0]
        constant = all(np.allclose(diff[g * per:(g + 1) * per], diff[g * per], rtol=1e-8,
                                   atol=1e-8 * scale_of(diff)) for g in range(groups))
        note = "" if np.allclose(diff, 0, atol=1e-9 * scale_of(diff)) else (
            "It differs from the usual form by a constant, which changes nothing."
            if constant else "It differs from the usual form by a total time derivative dF/dt, which gives "
                             "the same equations of motion.")
        return _decide(ctx, part, proof, traj, note)
    _certify_lagrangian(mech, part, L_s, E_s, E_r, pts, groups, per)
    if c is not None and np.all(np.abs(c) > 1e-9):
        same = np.allclose(c, c[0], rtol=1e-6)
        factor = (factor_text(float(c[0])) or f"a constant factor ({in_kind(float(c[0]))})") if same \
            else "a factor that depends on the parameters"
        return graded(part, ctx.credit.scaled_lagrangian, "numeric",
                      f"your Lagrangian is the right one scaled by {factor}: it gives the same equations of motion, "
                      "but L = T - V fixes the scale (the momenta and H would be off by that factor).")
    message = _lagrangian_diagnosis(ctx, part, mech, L_s, E_s, pts, groups, per)
    missing = _undetermined(L_s, mech, pts)
    if missing:
        used = {str(x) for x in L_s.free_symbols}
        if {missing, f"{missing}_d"} & used:
            message += (f" Your L gives no equation for {missing}'': it has no kinetic energy in "
                        f"{missing}' (the matrix of d2L/dq'dq' is singular).")
        elif "leaves out a coordinate" not in message:
            message += (" Your L does not determine every acceleration: its kinetic energy leaves a coordinate out "
                        "(the matrix of d2L/dq'dq' is singular).")
        return _wrong(part, 0.0, message, None, ctx.credit)
    traj = _try(lambda: _trajectory_lagrange(ctx, mech, part, student_acc, student_rows))
    return _wrong(part, 0.0, message, traj)


def _undetermined(L: sp.Expr, mech: Mechanics, pts) -> str | None:
    """The coordinate whose acceleration a Lagrangian leaves undetermined (singular kinetic matrix)."""
    args = [*mech.s.q, *mech.s.qd, T, *mech.params]
    n = len(mech.names)
    hess = evaluate([sp.diff(L, a, b) for a in mech.s.qd for b in mech.s.qd], args, pts.args(args))
    M = hess.reshape(n, n, -1).transpose(2, 0, 1)
    if not np.all(np.isfinite(M)):
        return None
    s = np.linalg.svd(M, compute_uv=False)
    if np.all(s[:, -1] > 1e-10 * np.maximum(s[:, 0], 1e-300)):
        return None
    _, _, vt = np.linalg.svd(M[0])
    return mech.names[int(np.argmax(np.abs(vt[-1])))]


def _lagrangian_diagnosis(ctx, part, mech, L_s, E_s, pts, groups, per) -> str:
    for mistake in part.mistakes:
        try:
            L_m = mech.parse(str(mistake.answer), part.symbols)
        except Exception:  # noqa: BLE001
            continue
        if _scaling(E_s, _el_matrix(L_m, mech, pts, part), groups, per) is not None:
            return mistake.message
    kin, pot = split_energy(mech.L, mech)
    generic = [
        (kin, -pot, "the potential energy has the wrong sign: L = T - V."),
        (2 * kin, pot, "the kinetic energy is twice too large: is a factor 1/2 missing?"),
        (kin / 2, pot, "the kinetic energy is half what it should be."),
        (kin, sp.S.Zero, "the potential energy is missing."),
    ]
    for T_m, V_m, message in generic:
        L_m = T_m - V_m
        if L_m != 0 and _scaling(E_s, _el_matrix(L_m, mech, pts, part), groups, per) is not None \
                and _says_true(L_s, T_m, V_m, mech, pts, groups, per):
            return "Incorrect: " + message
    E_r = _el_matrix(mech.L, mech, pts, part)
    bad = [name for i, name in enumerate(mech.names) if not np.all(agree(E_s[i], E_r[i]))]
    used = {str(x) for x in L_s.free_symbols}
    named = [name for name in bad if {name, f"{name}_d"} & used]  # never a coordinate the student left out
    if len(named) == len(bad):
        message = ("Incorrect: the Lagrange equation your L gives for " + ", ".join(bad) +
                   " is not the true one (a term of T or V is missing or wrong).")
    else:
        message = ("Incorrect: your L leaves out a coordinate of the problem, so its Lagrange equations are not the "
                   "true ones (a term of T or V is missing).")
    if ctx.hints:
        message += " " + term_hints(L_s, mech.L, mech)
    return message


def _says_true(L_s: sp.Expr, T_m: sp.Expr, V_m: sp.Expr, mech: Mechanics, pts, groups: int, per: int) -> bool:
    """A generic diagnosis ("the kinetic energy is half what it should be") is given only when the
    student's own L bears it out: its velocity terms are T_m and the rest is -V_m up to a constant
    (equal equations of motion alone do not say which part of L is wrong)."""
    args = [*mech.s.q, *mech.s.qd, T, *mech.params]
    T_s, V_s = split_energy(L_s, mech)
    try:
        with np.errstate(all="ignore"):
            a, b, c, d = evaluate([T_s, T_m, V_s, V_m], args, pts.args(args))
    except Exception:  # noqa: BLE001
        return False
    if not np.all(agree(a, b)):
        return False
    dv = c - d
    tol = 1e-8 * scale_of(c, d)
    return all(np.all(np.abs(dv[g * per:(g + 1) * per] - dv[g * per]) <= tol) for g in range(groups))


def _terms(expr: sp.Expr, mech: Mechanics) -> dict[sp.Expr, sp.Expr]:
    """Terms of an expanded L keyed by their non-numeric factor; constants dropped (they do nothing)."""
    state = {*mech.s.q, *mech.s.qd, T}
    out: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(sp.expand_trig(expr))):
        if not term.free_symbols & state:
            continue
        coeff, rest = term.as_coeff_Mul()
        out[rest] = out.get(rest, 0) + coeff
    return {k: v for k, v in out.items() if v != 0}


def _describe_term(term: sp.Expr, mech: Mechanics) -> str:
    names = sorted({str(s) for s in term.free_symbols & {*mech.s.q, *mech.s.qd}})
    kind = "kinetic" if term.free_symbols & set(mech.s.qd) else "potential"
    return f"a {kind} term in {', '.join(n.replace('_d', chr(39)) for n in names)}"


def _off_in_kind(mine: sp.Expr, right: sp.Expr) -> str:
    """How a coefficient is off, in kind only: never the ratio, which a repeated query would turn
    into the reference's coefficient."""
    try:
        ratio = float(mine / right)
    except (TypeError, ValueError, ZeroDivisionError):
        return "is not what it should be"
    return "has the wrong sign" if abs(ratio + 1) < 1e-12 else f"is {in_kind(ratio)}"


def term_hints(L_s: sp.Expr, L_ref: sp.Expr, mech: Mechanics) -> str:
    """Which terms of the student's L are extra or off by a factor, and what kind of term is missing.

    The student's own terms may be quoted; the reference's never are (only the variables they involve).
    """
    mine, ref = _terms(L_s, mech), _terms(L_ref, mech)
    notes = []
    for key, c in mine.items():
        if key not in ref:
            notes.append(f"your term {sp.sstr(c * key).replace('_d', chr(39))} should not be there")
        elif not sp.simplify(c - ref[key]) == 0:
            notes.append(f"your term {sp.sstr(c * key).replace('_d', chr(39))} {_off_in_kind(c, ref[key])}")
    for key in ref:
        if key not in mine:
            notes.append(f"{_describe_term(key, mech)} is missing")
    if not notes or len(notes) > 4:
        return "Hint: compare T and V with the figure term by term."
    return "Hint: " + "; ".join(notes) + "."


# ----------------------------------------------------------------------------- equations of motion


def _eom_rows(ctx: Context, part: Part, value: object, mech: Mechanics) -> tuple[list[sp.Expr], list[str]]:
    """The student's equations in state symbols, with the problem's constraints substituted, the
    generalized forces ``Q_q`` a student may leave as symbols (where the scene has them) replaced by
    the scene's, and Lagrange multipliers (``lam``, ``lambda_1`` ...) eliminated."""
    raw = equation_rows(value, part)
    lams = sorted(set().union(*(multiplier_names(r, mech, part) for r in raw)))
    forces = {sp.Symbol(f"Q_{n}"): Q for n, Q in zip(mech.names, mech.Q) if Q != 0}
    rows = [read_sympy(r, part, mech, plain_coordinates=False, extra=[*lams, *map(str, forces)]) for r in raw]
    subs = {**forces, **mech.constrained}
    rows = [r.xreplace(subs) if subs else r for r in rows]
    if lams:
        rows = _eliminate_multipliers(rows, [sp.Symbol(n) for n in lams], part)
        rows = [r for r in rows if not _vanishes(r, mech, part)] or rows
    return rows, lams


def _eliminate_multipliers(rows: list[sp.Expr], lams: list[sp.Symbol], part: Part) -> list[sp.Expr]:
    """Equations with unknown multipliers, reduced to those without: each multiplier is solved
    from one equation it enters linearly and substituted in the others (Gaussian elimination)."""
    rows = list(rows)
    for lam in lams:
        pivots = [(sp.count_ops(c), i, c) for i, r in enumerate(rows)
                  if r.has(lam) and not (c := sp.diff(r, lam)).has(lam) and c != 0]
        if not pivots:
            where = "enters no equation linearly" if any(r.has(lam) for r in rows) else "enters no equation"
            raise InvalidAnswer(f"{part.name}: the multiplier {lam} {where}; give the equations with the "
                                "multipliers and the constraints, or the equations with the multipliers eliminated")
        _, i, c = min(pivots, key=lambda x: (x[0], x[1]))
        value = -rows[i].xreplace({lam: 0}) / c
        rows = [r.xreplace({lam: value}) if r.has(lam) else r for k, r in enumerate(rows) if k != i]
    return rows


def _vanishes(row: sp.Expr, mech: Mechanics, part: Part) -> bool:
    """A row that is identically zero once the constraints are substituted (the constraint itself,
    given next to the equations of motion)."""
    if row == 0:
        return True
    pts = sample_points(mech, 6, rng_for(mech.problem.id, part.name, "constraint"), extra=part.symbol_domains)
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *mech.params, *(sp.Symbol(x) for x in part.symbols)]
    if row.free_symbols - set(args):
        return False
    with np.errstate(all="ignore"):
        v = evaluate([row], args, pts.args(args))[0]
    return bool(np.all(np.isfinite(v)) and np.allclose(v, 0, atol=1e-10))


def check_eom(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    rows, lams = _eom_rows(ctx, part, value, mech)
    rows = admit.linear_rows(rows, list(mech.s.qdd), "accelerations", ctx.symbolic_seconds)
    if part.linearized:
        return _check_linearized(ctx, part, mech, rows)
    pts = with_reference_dynamics(mech, sample_points(mech, ctx.points, rng_for(ctx.problem.id, part.name),
                                                      extra=part.symbol_domains))
    extra = [sp.Symbol(s) for s in part.symbols]
    args = [*mech.s.q, *mech.s.qd, T, *mech.params, *extra]
    compiled = CompiledRows(rows, mech.s.qdd, args)
    truth = np.array(pts.args(mech.s.qdd))
    argv = pts.args(args)
    velocities = set(mech.s.qd)
    rest = [np.zeros_like(np.asarray(a, dtype=float)) if s in velocities else a for s, a in zip(args, argv)]
    an = analyse_rows(compiled, argv, truth, list(mech.names), rtol=ctx.accuracy.sample_rtol,
                      reference_jacobian=_mass_at(mech, pts),
                      at_rest=(rest, _mass_at(mech, pts, at_rest=True)))

    def student_acc() -> Vectorized:
        return compiled.solver

    traj, where = None, ""
    if an.fraction >= 1.0 and len(rows) == len(mech.s.qdd) and not an.vanishing_factor:
        decided = _exactly_zero_given(rows, ctx, mech, "your equation {i} at the true accelerations")
        if decided is False:
            return _exactly_wrong(part, "your equations of motion: one")
        if decided:
            bad = _singular_factor(rows, mech, ctx)
            admit.proved()
            if bad is None:
                return graded(part, 1.0, "exact", "correct: your equations hold exactly for the true motion and "
                                                  "determine the accelerations.")
            return graded(part, 0.0, "exact", "Incorrect: your equations hold for the true motion, but they are multiplied by a "
                          f"factor ({bad}) that becomes zero within the problem's physical range: where it does, "
                          "they no longer determine the accelerations; divide the factor out.")
    if an.fraction >= 1.0:
        _needs_proof(rows, ctx, mech)
        proof, traj = _confirm(ctx, lambda: _prove_rows_equivalent(rows, mech, ctx),
                               lambda: _trajectory_lagrange(ctx, mech, part, student_acc, lambda: rows))
        moved = _motion_refutes(ctx, part, proof, traj)
        if moved is not None:
            return moved
        off = None if proof else _along_motion(ctx, mech, part, traj, compiled, list(mech.names))
        if off is None:
            exact = None if proof else _exact_refutation(mech, part, rows, pts, "your equation {i}", traj)
            return exact if exact is not None else _decide(ctx, part, proof, traj)
        an, pts, argv, truth = off   # agree on the box, not where the motion goes: decided there
        where = f" {ALONG_MOTION.replace('the true motion', 'it')}"
    _certify_rows(mech, rows, an, compiled, argv, truth, pts, "accelerations", truth=True)
    _relabel(an, compiled, mech, pts, args, truth)
    named = _eom_mistake(part, mech, compiled, pts.args(args), list(mech.names))
    problems = [] if named is None else [named.rstrip(".")]
    for i in an.wrong if named is None else []:
        if lams:  # the rows are the student's after elimination: their numbers would not be the student's
            which = f"for {an.labels[i]}''" if an.labels[i] != "none" else "with no acceleration in it"
            problems.append(f"the equation {which} does not hold for the true motion{where}")
            continue
        which = f"the one mainly for {an.labels[i]}''" if an.labels[i] != "none" else "it has no acceleration in it"
        problems.append(f"equation {i + 1} ({which}) does not hold for the true motion{where}")
    if an.vanishing_factor:
        problems.append("your equations hold, but one is multiplied by a factor that becomes zero within "
                        "the problem's range (a velocity, say, as in d/dt of the energy): where it does, they "
                        "no longer determine the accelerations; divide the factor out")
    elif an.rank < an.n and not an.wrong:
        problems.append(f"your equations determine only {an.rank} of the {an.n} accelerations: "
                        f"an equation is missing or repeated")
    if lams and problems:
        problems[0] = f"once the multipliers ({', '.join(lams)}) are eliminated, {problems[0]}"
    if traj is None and len(rows) >= an.n:
        traj = _try(lambda: _trajectory_lagrange(ctx, mech, part, student_acc, lambda: rows))
    # equations with a factor that vanishes in the domain determine no motion there: no equation's share
    fraction = 0.0 if an.vanishing_factor and not an.wrong else an.fraction
    return _wrong(part, fraction, named or _sentence(problems), traj, ctx.credit)


def _certify_rows(mech: Mechanics, rows: list[sp.Expr], an, compiled: CompiledRows, argv, rates: np.ndarray, pts,
                  what: str, **how) -> None:
    """Each wrong row, certified nonzero at the true rates where it is farthest from holding; a system
    with fewer equations than unknowns is short of them exactly; any other shortfall (a rank lost
    between equations, a vanishing factor) is left uncertified, for review."""
    if len(rows) < an.n:
        admit.witness(Certificate(f"{len(rows)} equations for {an.n} {what}", {}, "a count"))
        return
    if not an.wrong:
        admit.witness(_degenerate(mech, compiled, an, argv, rates, pts, what))
        return
    with np.errstate(all="ignore"):
        g = np.abs(compiled.values(argv, rates))
    for i in an.wrong:
        row = np.where(np.isfinite(g[i]), g[i], -1.0)
        k = int(np.argmax(row))
        admit.witness(certify(f"your equation {i + 1} at the true {what}", rows[i],
                              {s: v[k] for s, v in pts.values.items()}, mech=mech, **how))


def _degenerate(mech: Mechanics, compiled: CompiledRows, an, argv, rates: np.ndarray, pts, what: str):
    """Equations that hold but do not determine the rates everywhere: their determinant in the rates,
    against the reference's, changes sign between two sampled states (so vanishes between them), or is
    exactly zero at a state of rest, or identically zero (proved)."""
    if compiled.m != compiled.n or not compiled.linear:
        return None
    n = compiled.n
    det = sp.Matrix(n, n, compiled.J_exprs).det(method="berkowitz")
    reference = mech.mass.det(method="berkowitz") if what == "accelerations" else sp.S.One
    product = det * reference
    with np.errstate(all="ignore"):
        values = np.real(evaluate([product], compiled.allargs, [*argv, *rates])[0])
    at = [{s: v[k] for s, v in pts.values.items()} for k in range(pts.K)]
    finite = np.isfinite(values)
    if finite.any() and np.nanmax(values) > 0 > np.nanmin(values):
        k1, k2 = int(np.nanargmax(values)), int(np.nanargmin(values))
        cert = sign_change(f"the determinant of your equations in the {what} times the true one's", product,
                           at[k1], at[k2])
        if cert is not None:
            return cert
    rest = {**at[0], **{v: 0.0 for v in mech.s.qd}}
    cert = zero_at(f"the determinant of your equations in the {what} at rest", det, rest)
    if cert is not None:
        return cert
    if an.rank < an.n:
        from lagrade.compare.symbolic import proves_zero

        if proves_zero(det, 2.0):
            return Certificate(f"the determinant of your equations in the {what}", {}, "identically 0 (proved)")
    return None


def _certify_lagrangian(mech: Mechanics, part: Part, L_s: sp.Expr, E_s: np.ndarray, E_r: np.ndarray, pts,
                        groups: int, per: int) -> None:
    """A wrong L's Lagrange equations are no constant multiple of the true ones: certified by two entries
    (equation, state) of one group of shared parameters whose cross product is not zero; an L whose
    equations are a multiple (c != 1) of the true ones, by one entry of their difference."""
    rows_s, rows_r = mech.lagrange_rows(L_s), mech.EL
    n = len(rows_r)
    state = [*mech.s.q, *mech.s.qd, *mech.s.qdd]
    with np.errstate(all="ignore"):
        for g in range(groups):
            ks = range(g * per, (g + 1) * per)
            entries = [(i, k) for i in range(n) for k in ks]
            best, pair = -1.0, None
            for (i, k1) in entries:
                for (j, k2) in entries:
                    d = abs(E_s[i, k1] * E_r[j, k2] - E_s[j, k2] * E_r[i, k1])
                    if np.isfinite(d) and d > best:
                        best, pair = d, ((i, k1), (j, k2))
            if pair is None or best <= 0:
                continue
            (i, k1), (j, k2) = pair
            one = {x: sp.Symbol(f"{x.name}@1") for x in state}
            two = {x: sp.Symbol(f"{x.name}@2") for x in state}
            cross = rows_s[i].xreplace(one) * rows_r[j].xreplace(two) - rows_s[j].xreplace(two) * rows_r[i].xreplace(one)
            point = {s: v[k1] for s, v in pts.values.items()}
            point.update({one[x]: pts.values[x][k1] for x in state})
            point.update({two[x]: pts.values[x][k2] for x in state})
            cert = certify("the cross product of your Lagrange equations with the true ones at two states "
                           "(zero for every pair if yours were a multiple of the true ones)", cross, point)
            if cert is not None:
                admit.witness(cert)
                return
    with np.errstate(all="ignore"):
        gap = np.where(np.isfinite(E_s - E_r), np.abs(E_s - E_r), -1.0)
    i, k = np.unravel_index(int(np.argmax(gap)), gap.shape)
    admit.witness(certify(f"your Lagrange equation {i + 1} minus the true one", rows_s[i] - rows_r[i],
                          {s: v[k] for s, v in pts.values.items()}) if gap[i, k] > 0 else None)


def _certify_hamiltonian(mech: Mechanics, H_s: sp.Expr, pts) -> None:
    """H - H_true depends on more than t: one of its derivatives in (q, p) is not zero at a phase point,
    with dH_true/dp = q' and dH_true/dq = -dL/dq there."""
    real = {x: sp.Dummy(x.name, real=True) for x in H_s.free_symbols if isinstance(x, sp.Symbol)}
    back = {v: k for k, v in real.items()}

    def d(x: sp.Symbol) -> sp.Expr:  # with real symbols: d|x|/dx is sign(x), not a complex form
        return sp.diff(H_s.xreplace(real), real.get(x, x)).xreplace(back)

    checks = [(d(p) - v, f"dH/d{p} minus the true {v}") for p, v in zip(mech.s.p, mech.s.qd)]
    checks += [(d(q) + sp.diff(mech.L, q), f"dH/d{q} minus the true one") for q in mech.s.q]
    for k in range(pts.K):
        at = {s: v[k] for s, v in pts.values.items()}
        for expr, what in checks:
            cert = certify(what, expr, at, mech=mech, phase=True)
            if cert is not None:
                admit.witness(cert)
                return
    admit.witness(None)


def _mass_at(mech: Mechanics, pts, at_rest: bool = False) -> np.ndarray:
    """The mass matrix (n, n, K) at the sampled states (or at them with every velocity zero): the
    Jacobian of Lagrange's equations in q''."""
    q, qd, t, params = state_arrays(mech, pts)
    if at_rest:
        qd = np.zeros_like(qd, dtype=float)
    n = len(mech.names)
    return mech._mass_f(*q, *qd, t, *params).reshape(n, n, pts.K)


def _relabel(an, compiled: CompiledRows, mech: Mechanics, pts, args, truth) -> None:
    """Name each wrong row after the reference equation its acceleration terms resemble most, so a
    student is pointed at the right coordinate even when another acceleration has a bigger coefficient."""
    argv = pts.args(args)
    J = compiled.jacobian(argv, truth)  # (m, n, K)
    n = len(mech.names)
    M = _mass_at(mech, pts)
    for i in an.wrong:
        scores = []
        for r in range(n):
            a, b = J[i], M[r]
            cos = np.abs((a * b).sum(axis=0)) / (np.linalg.norm(a, axis=0) * np.linalg.norm(b, axis=0) + 1e-300)
            # never name a coordinate whose acceleration the student's equation does not contain
            uses = np.nanmax(np.abs(a[r])) > 1e-12 * max(np.nanmax(np.abs(a)), 1e-300) if np.isfinite(a[r]).any() else False
            scores.append(np.nanmedian(cos) if uses else -np.inf)
        if np.isfinite(scores).any() and np.nanmax(scores) > 0:
            an.labels[i] = mech.names[int(np.nanargmax(scores))]


def _eom_mistake(part: Part, mech: Mechanics, compiled: CompiledRows, argv, labels) -> str | None:
    """The message of a named mistake whose equations define the same accelerations as the student's."""
    for mistake in part.mistakes:
        texts = mistake.answer if isinstance(mistake.answer, list) else [mistake.answer]
        try:
            rows = []
            for text in texts:
                e = mech.parse(str(text), part.symbols)
                rows.append(e.lhs - e.rhs if isinstance(e, sp.Equality) else e)
            wrong = CompiledRows(rows, mech.s.qdd, [*mech.s.q, *mech.s.qd, T, *mech.params,
                                                    *(sp.Symbol(x) for x in part.symbols)])
            if analyse_rows(compiled, argv, wrong.solve(argv), labels).fraction >= 1.0:
                return mistake.message
        except Exception:  # noqa: BLE001  (a mistake that cannot be read is simply not matched)
            continue
    return None


def _prove_rows_equivalent(rows: list[sp.Expr], mech: Mechanics, ctx: Context) -> bool | None:
    """Symbolic proof that the rows are satisfied by the reference accelerations (time-bounded)."""
    try:
        with time_bound(ctx.symbolic_seconds):
            acc = mech.accelerations_symbolic
    except _OutOfTime:
        return None
    subs = dict(zip(mech.s.qdd, acc))
    return proves_all_zero([r.xreplace(subs) for r in rows], ctx.symbolic_seconds, ctx.positive)


def _check_linearized(ctx: Context, part: Part, mech: Mechanics, rows: list[sp.Expr]) -> PartResult:
    """Small oscillations: the rows' linearization about equilibrium must span the reference's."""
    n = len(mech.names)
    pts = sample_points(mech, 8, rng_for(ctx.problem.id, part.name), extra=part.symbol_domains)
    extra = [sp.Symbol(s) for s in part.symbols]
    eq_exprs = [mech.parse(mech.system.equilibrium.get(name, "0")) for name in mech.names]
    pargs = [*mech.params, *extra]
    q_star = evaluate(eq_exprs, [T, *pargs], [pts[T], *pts.args(pargs)])
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *pargs]
    zeros = np.zeros((n, pts.K))
    at_eq = [*q_star, *zeros, *zeros, pts[T], *pts.args(pargs)]

    def derivatives(e: sp.Expr) -> list[sp.Expr]:  # d e/d(state), the accelerations' read off a linear row
        return [*slopes(e, list(mech.s.qdd)).values(), *(sp.diff(e, v) for v in [*mech.s.qd, *mech.s.q])]

    def linear_part(exprs, derivs=None):
        derivs = derivs or [derivatives(e) for e in exprs]
        jac = evaluate([d for row in derivs for d in row], args, at_eq)
        return jac.reshape(len(exprs), 3 * n, pts.K), evaluate(exprs, args, at_eq)

    their_derivs = [derivatives(e) for e in rows]  # the student's: for the linear parts, and their rows below
    A_s, g0 = linear_part(rows, their_derivs)
    key = (part.name, tuple(part.symbols))  # the states above depend on nothing else
    if key not in mech.linearized:
        mech.linearized[key] = linear_part(mech.EL)
    A_r, g0_r = mech.linearized[key]
    # Affine rows [d/d(state) | value at equilibrium]: a driven system keeps its forcing term.
    consistent = []
    for i in range(len(rows)):
        ok = True
        for k in range(pts.K):
            a = np.append(A_s[i, :, k], g0[i, k])
            R = np.column_stack([A_r[:, :, k], g0_r[:, k]])
            coef, *_ = np.linalg.lstsq(R.T, a, rcond=None)
            resid = a - R.T @ coef
            scale = max(np.abs(a).max(), 1e-300)
            if not (np.all(np.isfinite(a)) and np.abs(resid).max() <= 1e-7 * scale):
                ok = False
        consistent.append(ok)
    at = {**dict(zip(mech.s.q, eq_exprs)), **{v: 0 for v in [*mech.s.qd, *mech.s.qdd]}}

    def affine(e: sp.Expr, derivs: list[sp.Expr] | None = None) -> list[sp.Expr]:  # [d e/d(state) | e], at equilibrium
        return [*(d.xreplace(at) for d in derivs or derivatives(e)), e.xreplace(at)]

    if ("affine", key) not in mech.linearized:  # the true rows' [d/d(state) | value]: once per problem
        mech.linearized[("affine", key)] = ([affine(e) for e in mech.EL], None)
    true_rows = mech.linearized[("affine", key)][0]
    theirs: dict[int, list[sp.Expr]] = {}  # the student's rows' (each once, whatever the states)

    def their_row(i: int) -> list[sp.Expr]:
        if i not in theirs:
            theirs[i] = affine(rows[i], their_derivs[i])
        return theirs[i]

    for i in [i for i, ok in enumerate(consistent) if not ok]:
        k = 0
        admit.witness(outside_span(
            f"a minor of the true linearized equations stacked with your equation {i + 1} (zero if yours were "
            "a combination of them)", true_rows, their_row(i),
            [np.append(A_r[j, :, k], g0_r[j, k]) for j in range(n)], np.append(A_s[i, :, k], g0[i, k]),
            {s: v[k] for s, v in pts.values.items()}))
    use = [i for i, ok in enumerate(consistent) if ok and np.abs(A_s[i]).max() > 0]
    rank = min((np.linalg.matrix_rank(A_s[use, :, k]) for k in range(pts.K)), default=0) if use else 0
    fraction = 1.0 if rank >= n and all(consistent) else rank / max(n, len(rows))
    if fraction >= 1.0 and not admit.pending():
        # Agreement in floating point (1e-7) is checked again exactly: each row's linear part at
        # equilibrium must lie in the span of the true one's at an exact state (a coefficient off by
        # 1e-8 is refuted there, certified).
        for k in range(min(EXACT_STATES, pts.K)):
            for i in range(len(rows)):
                cert = outside_span(
                    f"a minor of the true linearized equations stacked with your equation {i + 1} (zero if yours "
                    "were a combination of them)", true_rows, their_row(i),
                    [np.append(A_r[j, :, k], g0_r[j, k]) for j in range(n)], np.append(A_s[i, :, k], g0[i, k]),
                    {s: v[k] for s, v in pts.values.items()})
                if cert is not None:
                    admit.witness(cert)
                    return graded(part, 0.0, "numeric", f"Incorrect: equation {i + 1} does not agree with the "
                                  f"linearized equations of motion about equilibrium {EXACTLY}.")
    if fraction >= 1.0:
        # Linear or not? Compare with the linear extrapolation at a displaced state.
        rng = rng_for(ctx.problem.id, part.name, "nonlinear")
        dq = rng.uniform(0.2, 0.5, (3 * n, pts.K))
        displaced = [*(q_star + dq[2 * n:]), *dq[n:2 * n], *dq[:n], pts[T], *pts.args(pargs)]
        g = evaluate(rows, args, displaced)
        lin = np.einsum("msk,sk->mk", A_s, dq) + g0
        nonlinear = not np.allclose(g, lin, rtol=1e-6, atol=1e-9 * scale_of(g))
        if nonlinear and _exact_refutation(mech, part, rows, pts, "your equation {i}", None) is not None:
            return graded(part, 0.0, "numeric", "Incorrect: your equations linearize to the right small-oscillation "
                          "equations, but they are not linear, and they are not the exact equations of motion "
                          f"either (they do not hold for the true motion {EXACTLY}): a nonlinear term is wrong. "
                          "Write the linearized equations.")
        note = ("These are the exact (nonlinear) equations; they linearize to the right small-oscillation "
                "equations, which were asked." if nonlinear else "")
        return graded(part, ctx.credit.nonlinear_for_linearized if nonlinear else 1.0, "numeric",
                      ("correct: your equations are the small-oscillation equations about equilibrium. "
                       + note).strip())
    wrong = [str(i + 1) for i, ok in enumerate(consistent) if not ok]
    msg = (f"equation(s) {', '.join(wrong)} do not agree with the linearized equations of motion about "
           f"equilibrium" if wrong else f"your equations determine only {rank} of the {n} accelerations")
    return graded(part, fraction, "numeric", "Incorrect: " + msg + ".", ctx.credit)


# ----------------------------------------------------------------------------- the Hamiltonian


def _hamilton_points(ctx: Context, mech: Mechanics, part: Part):
    pts, groups, per = _grouped_points(ctx, mech, part)
    q, qd, t, params = state_arrays(mech, pts)
    p = mech.momenta(q, qd, t, params)
    for sym, v in zip(mech.s.p, p):
        pts.values[sym] = v
    return pts, groups, per, (q, p, t, params)


def check_hamiltonian(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    H_s = read_expr(value, part, mech, plain_coordinates=True, momenta=True, max_order=0
                    ) if not _has_velocity(value, mech) else None
    if H_s is None:
        return graded(part, 0.0, "exact", "Incorrect: H must be written in the coordinates and the momenta "
                      f"({', '.join(str(p) for p in mech.s.p)}), not in the velocities: "
                      "use p = dL/dq' to eliminate the velocities.")
    pts, groups, per, (q, p, t, params) = _hamilton_points(ctx, mech, part)
    extra = [sp.Symbol(s) for s in part.symbols]
    args = [*mech.s.q, *mech.s.p, T, *mech.params, *extra]
    h_s = evaluate([H_s], args, pts.args(args))[0]
    h_r = mech.hamiltonian(q, p, t, params)
    diff = h_s - h_r
    tol = ctx.accuracy.sample_rtol * scale_of(h_s, h_r)
    same = all(np.all(np.abs(diff[g * per:(g + 1) * per] - diff[g * per]) <= tol) for g in range(groups))

    student_rates = _once(lambda: _hamiltonian_rates(H_s, mech, part))

    def student_rows() -> list[sp.Expr]:
        return hamilton_rows(H_s, mech)

    if same:
        _needs_proof([H_s], ctx, mech)
        decided = None if exact.outside(H_s, ctx.domain(mech)) else _exactly_hamiltonian(H_s, ctx, mech)
        if decided is not None:
            if not decided:
                return _exactly_wrong(part, "your H", " (H is the energy up to a constant only: a term in t, "
                                                     "or one that changes where no state was tried, is not.)")
            admit.proved()
            return graded(part, 1.0, "exact", "correct: exactly the true H" + (
                "" if np.all(np.abs(diff) <= tol) else ", up to a constant") + ".")

        def prove() -> bool | None:
            try:
                with time_bound(ctx.symbolic_seconds):
                    H_ref = mech.hamiltonian_symbolic
            except _OutOfTime:
                return None
            d = H_s - H_ref
            # H is the energy up to a constant: d minus its value at one state, not only its derivatives
            # (a switch such as atan(1/(pi - q)) + atan(pi - q) has derivative 0 and jumps at q = pi)
            for k in range(1, 4):
                at = {v: sp.Rational(k, 7) for v in [*mech.s.q, *mech.s.p, T]}
                d0 = d.xreplace(at)
                if d0.is_finite is not False and not d0.has(sp.nan, sp.zoo):
                    return proves_zero(d - d0, ctx.symbolic_seconds, ctx.positive)
            return None

        proof, traj = _confirm(ctx, prove, lambda: _trajectory_hamilton(ctx, mech, part, student_rates, student_rows))
        moved = _motion_refutes(ctx, part, proof, traj)
        if moved is not None:
            return moved
        off = None if proof else _motion_refutation(ctx, mech, part, traj, student_rows(), True,
                                                    "Hamilton's equations your H gives")
        if off is None and not proof:
            off = _exact_refutation(mech, part, student_rows(), pts, "Hamilton's equation {i} of your H", traj,
                                    phase=True)
        if off is not None:
            return off
        note = "" if np.all(np.abs(diff) <= tol) else "It differs from the usual H by a function of t only."
        return _decide(ctx, part, proof, traj, note)
    _certify_hamiltonian(mech, H_s, pts)
    message = _hamiltonian_diagnosis(part, mech, h_s, pts, groups, per, (q, p, t, params))
    traj = _try(lambda: _trajectory_hamilton(ctx, mech, part, student_rates, student_rows))
    return _wrong(part, 0.0, message, traj)


def _has_velocity(value: object, mech: Mechanics) -> bool:
    if not isinstance(value, sp.Basic):
        return False
    return any(isinstance(d, sp.Derivative) for d in value.atoms(sp.Derivative)) or any(
        s.name in {f"{n}_d" for n in mech.names} | {f"{n}dot" for n in mech.names} for s in value.free_symbols
        if isinstance(s, sp.Symbol))


def _hamiltonian_rates(H: sp.Expr, mech: Mechanics, part: Part):
    extra = [sp.Symbol(s) for s in part.symbols]
    args = [*mech.s.q, *mech.s.p, T, *mech.params, *extra]
    rows = hamilton_rows(H, mech)
    return compile_exprs([u - r for u, r in zip([*mech.s.qd, *mech.s.pd], rows)], args)


def _hamiltonian_diagnosis(part, mech, h_s, pts, groups, per, state) -> str:
    q, p, t, params = state
    extra = [sp.Symbol(s) for s in part.symbols]
    args = [*mech.s.q, *mech.s.p, T, *mech.params, *extra]
    tol = 1e-8 * scale_of(h_s)

    def matches(values):
        d = h_s - values
        return all(np.all(np.abs(d[g * per:(g + 1) * per] - d[g * per]) <= tol) for g in range(groups))

    for mistake in part.mistakes:
        try:
            H_m = mech.parse(str(mistake.answer), [*part.symbols, *(str(x) for x in mech.s.p)])
            if matches(evaluate([H_m], args, pts.args(args))[0]):
                return mistake.message
        except Exception:  # noqa: BLE001
            continue
    qd = mech.velocities(q, p, t, params)
    kin, pot = split_energy(mech.L, mech)
    h_r = mech.hamiltonian(q, p, t, params)
    energy = evaluate([kin, pot], [*mech.s.q, *mech.s.qd, T, *mech.params], [*q, *qd, t, *params])
    T_, V_ = energy
    E = T_ + V_
    if not np.allclose(E, h_r, rtol=1e-8, atol=1e-8 * scale_of(h_r)) and matches(E):
        return ("Incorrect: this is T + V, the energy, but here H is not the energy: the Hamiltonian is "
                "sum(p q') - L written in the momenta.")
    # Slips that keep the right momenta: judged against H's own kinetic and potential parts.
    kinetic = h_r - V_
    for values, message in [
        (kinetic - V_, "the potential energy has the wrong sign: H = T + V (in the momenta)"),
        (2 * kinetic + V_, "the kinetic part is twice too large: is a factor 1/2 missing?"),
        (kinetic / 2 + V_, "the kinetic part is half what it should be"),
        (kinetic, "the potential energy is missing"),
        (V_, "the kinetic part p**2/(2 m) is missing"),
    ]:
        if matches(values):
            return "Incorrect: " + message + "."
    return "Incorrect: H(q, p) differs from the Hamiltonian of this system (check the momenta p = dL/dq')."


# ----------------------------------------------------------------------------- Hamilton's equations


def check_hamilton_eqs(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    rows = [read_sympy(r, part, mech, plain_coordinates=True, momenta=True, max_order=1)
            for r in equation_rows(value, part)]
    unknowns = [*mech.s.qd, *mech.s.pd]
    if any(r.has(a) for r in rows for a in mech.s.qdd):
        raise InvalidAnswer(f"{part.name} should be first-order equations for q' and p'; found a second derivative")
    rows = admit.linear_rows(rows, unknowns, "rates", ctx.symbolic_seconds)
    pts, groups, per, (q, p, t, params) = _hamilton_points(ctx, mech, part)
    extra = [sp.Symbol(s) for s in part.symbols]
    args = [*mech.s.q, *mech.s.p, T, *mech.params, *extra]
    truth = mech.hamilton_rates(q, p, t, params)
    compiled = CompiledRows(rows, unknowns, args)
    labels = [*(f"{x}'" for x in mech.names), *(f"p_{x}'" for x in mech.names)]
    an = analyse_rows(compiled, pts.args(args), truth, labels, rtol=ctx.accuracy.sample_rtol)

    def student_rates() -> Vectorized:
        return compiled.solver

    traj, where = None, ""
    if an.fraction >= 1.0:
        traj = _try(lambda: _trajectory_hamilton(ctx, mech, part, student_rates, lambda: rows))
        moved = _motion_refutes(ctx, part, None, traj)
        if moved is not None:
            return moved
        off = _along_motion(ctx, mech, part, traj, compiled, labels, phase=True)
        if off is None:
            exact = _exact_refutation(mech, part, rows, pts, "your equation {i}", traj, phase=True)
            return exact if exact is not None else _decide(ctx, part, None, traj)
        an, pts, _, truth = off   # agree on the box, not where the motion goes: decided there
        where = f" {ALONG_MOTION.replace('the true motion', 'it')}"
    _certify_rows(mech, rows, an, compiled, pts.args(args), truth, pts, "rates", phase=True)
    problems = [f"equation {i + 1} (for {an.labels[i]}) does not hold for the true motion{where}" for i in an.wrong]
    if an.vanishing_factor:
        problems.append("your equations hold, but one is multiplied by a factor that becomes zero within "
                        "the problem's range: where it does, they no longer determine the rates; divide it out")
    elif an.rank < an.n and not an.wrong:
        problems.append(f"your equations determine only {an.rank} of the {an.n} rates "
                        f"({', '.join(labels)}): Hamilton's equations are 2n first-order equations")
    if traj is None and len(rows) >= an.n:
        traj = _try(lambda: _trajectory_hamilton(ctx, mech, part, student_rates, lambda: rows))
    return _wrong(part, an.fraction, _sentence(problems), traj, ctx.credit)
