"""One scene model on every integrated path (issue 45, item 2).

The test scene (tests/problems_scene/turning-plane.toml) declares unilateral contact and asks an H part,
Hamilton's equations, the eom and a motion part; from every sampled state the normal force reaches zero
within the horizon (t <= 0.42), where the scene's model ends. Each path must integrate that model with
its declared events, so an answer that is right while the contact holds and differs only after it is
lost is judged alike on every path (the comparison ends with the contact: the scene says nothing
beyond), and one that differs while the contact holds is refuted. A path that bypasses the scene model
(no contact events) fails these tests: it refutes the late difference (controls below show the late
difference is large enough to be refuted when the events are not watched).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import lagrade
from lagrade.compare.scene_model import SceneModel, scene_model
from lagrade.compare.trajectory import ACCURACY, compare_runs
from lagrade.problem.library import load_problem
from lagrade.problem.symbols import T
from lagrade.verdicts.checkers import dynamics, motion
from lagrade.verdicts.checkers.base import Context
from lagrade.verdicts.grade import references

PROBLEM = Path(__file__).parent / "problems_scene" / "turning-plane.toml"
STICK_SLIP = Path(__file__).parent / "problems_stick_slip" / "coulomb-spring.toml"
#: every sampled motion of the scene has lost its contact before this time (asserted below)
LATE = 0.45


def _setup(part_name: str):
    problem = load_problem(str(PROBLEM))
    ctx = Context(problem, references(problem), ACCURACY["default"])
    part = problem.part(part_name)
    return ctx, part, ctx.mech(part)


def _late(expr_at: float) -> sp.Expr:
    """Zero (with three derivatives) until ``expr_at``, then growing."""
    return sp.Max(0, T - expr_at) ** 4


def _h_rates(H: sp.Expr, mech, part):
    return lambda: dynamics._hamiltonian_rates(H, mech, part)


def test_the_hamilton_path_watches_the_contact_loss():
    ctx, part, mech = _setup("H")
    r = mech.s.q[0]
    H = mech.hamiltonian_symbolic
    right = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(H, mech, part))
    assert right.agree
    assert right.reference_stop is not None and np.all(right.reference_stop < LATE), right.reference_stop
    late = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(H + 50 * r * _late(LATE), mech, part))
    assert late.agree, "an H that differs only after the contact is lost is judged beyond the scene's model"
    early = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(H + 50 * r * _late(0.05), mech, part))
    assert not early.agree and early.decisive and early.separation_time < LATE


def test_the_late_difference_is_visible_without_the_events():
    """Control: the same late H, compared without the scene's events, separates; so the test above
    fails on a Hamilton path that does not watch the contact."""
    ctx, part, mech = _setup("H")
    r = mech.s.q[0]
    late = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(mech.hamiltonian_symbolic + 50 * r * _late(LATE),
                                                                   mech, part))
    q_p = late.case
    blind = compare_runs(q_p.student, q_p.reference, q_p.y0, q_p.labels, q_p.horizon, ctx.accuracy)
    assert not blind.agree and blind.separation_time > LATE


def test_eom_and_hamilton_paths_end_where_the_same_model_does():
    """The eom path and the Hamilton path stop every motion at the same contact loss: one model."""
    ctx, part, mech = _setup("H")
    ham = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(mech.hamiltonian_symbolic, mech, part))
    eom_part = ctx.problem.part("eom")
    n = len(mech.names)
    acc = mech.accelerations_symbolic
    solve = dynamics.compile_exprs(list(acc), [*mech.s.q, *mech.s.qd, T, *mech.params])
    lag = dynamics._trajectory_lagrange(ctx, mech, eom_part, lambda: solve)
    assert lag.agree and ham.agree and n == 2
    # the two paths sample their own states (per part symbols, here none: the same states)
    assert np.allclose(lag.reference_stop, ham.reference_stop, rtol=1e-6)


def _r_exact():
    r0, om, g = sp.Symbol("r0"), sp.Symbol("omega"), sp.Symbol("g")
    return r0 * sp.cosh(om * T) + g / (2 * om**2) * (sp.sin(om * T) - sp.sinh(om * T))


def test_a_motion_entry_is_compared_only_while_the_contact_holds():
    """Per-entry credit of the motion part integrates the scene's model with its events: r(t) right
    while the contact holds and off after it is lost counts as right; off before, as wrong."""
    ctx, part, mech = _setup("solution")
    x0, u = sp.Symbol("x0"), sp.Symbol("u")
    wrong_x = x0 + 2 * u * T + T**2
    assert sp.simplify(sp.diff(_r_exact(), T, 2) - sp.Symbol("omega")**2 * _r_exact()
                       + sp.Symbol("g") * sp.sin(sp.Symbol("omega") * T)) == 0
    assert motion._entries_against_motion(ctx, part, mech, {"r": _r_exact(), "x": x0 + u * T}) == (["r", "x"], [])
    late = motion._entries_against_motion(ctx, part, mech, {"r": _r_exact() + _late(LATE), "x": wrong_x})
    assert late == (["r"], ["x"]), late
    early = motion._entries_against_motion(ctx, part, mech, {"r": _r_exact() + _late(0.05), "x": wrong_x})
    assert early == ([], ["r", "x"]), early


def test_a_motion_part_loses_contact_within_the_horizon():
    """The scene does what the tests above rely on: every motion of the motion part leaves the plane
    before LATE, and the late difference is one the entries' tolerance sees (1e-6 of the motion)."""
    from lagrade.compare.scene_model import scene_motion

    ctx, part, mech = _setup("solution")
    K = 8
    rng = np.random.default_rng(3)
    params = np.array([rng.uniform(0.5, 2, K), rng.uniform(9, 10, K), rng.uniform(2.5, 3.5, K)])
    y0 = np.array([rng.uniform(0.1, 0.3, K), rng.uniform(-1, 1, K), np.zeros(K), rng.uniform(-1, 1, K)])
    run = scene_motion(mech, y0, params, mech.system.horizon, ACCURACY["default"])
    assert run.ok and np.all(run.t_stop < LATE) and float(_late(LATE).subs(T, mech.system.horizon)) > 1e-6


def test_the_plot_draws_the_motion_up_to_the_contact_loss(tmp_path):
    """``--plot`` integrates the grading run's models with their events: the true motion is drawn
    only while the contact holds."""
    from lagrade.verdicts import plot

    ctx, part, mech = _setup("H")
    r = mech.s.q[0]
    early = dynamics._trajectory_hamilton(ctx, mech, part, _h_rates(mech.hamiltonian_symbolic + 50 * r * _late(0.05),
                                                                    mech, part))
    drawn = []
    real = plot.integrate

    def spy(*a, **kw):
        out = real(*a, **kw)
        drawn.append((kw.get("events"), plot._until_stop(out)))
        return out

    class Part:
        _trajectory = early.case
        verdict = "incorrect"
        part = "H"

    class Result:
        parts = [Part()]
        problem = "turning-plane"

    import unittest.mock as um
    with um.patch.object(plot, "integrate", spy):
        assert plot.plot_result(Result(), tmp_path / "p.png")
    (ref_events, ref_run), _ = drawn
    assert any(e.name.startswith("contact lost") for e in ref_events)
    assert ref_run.t[-1] <= early.reference_stop[0] + 1e-9 < mech.system.horizon


def test_hamilton_parts_of_a_switching_scene_integrate_the_scene_model(monkeypatch):
    """Dry friction: the Hamilton path's reference is the scene's own model read in (q, p) (its
    declared force, its branches), not Hamilton's equations of a derived H; it sticks where the
    Lagrange path's reference does."""
    from lagrade.compare.scene_model import PhaseModel

    built = []
    real = dynamics.compare_runs

    def spy(student, reference, y0, labels, horizon, acc, **kw):
        kw["store"] = {}
        out = real(student, reference, y0, labels, horizon, acc, **kw)
        built.append((reference, out))
        return out

    monkeypatch.setattr(dynamics, "compare_runs", spy)
    t = sp.Symbol("t")
    x, px = sp.Function("x")(t), sp.Function("p_x")(t)
    m, k = sp.symbols("m k", positive=True)
    got = next(p for p in lagrade.check(STICK_SLIP, H=px**2 / (2 * m) + k * x**2 / 2).parts if p.part == "H")
    assert got.verdict == "correct", got.feedback
    (reference, comparison), = built
    assert isinstance(reference, PhaseModel) and isinstance(reference.scene, SceneModel)
    assert reference.switches["stick"] and comparison.agree


def test_the_phase_model_is_the_scene_model_in_momenta():
    """PhaseModel's rates are the scene model's (q', q'') mapped to (q', p'), branch by branch, and its
    switching gradient in (q, p) gives the same dh/dt as the scene's in (q, q')."""
    from lagrade.compare.scene_model import PhaseModel

    problem = load_problem(str(STICK_SLIP))
    mech = references(problem).instance(problem.systems[0].key, 0)
    rng = np.random.default_rng(5)
    K = 5
    params = np.array([rng.uniform(0.5, 2, K), rng.uniform(5, 20, K), rng.uniform(0.1, 0.3, K), rng.uniform(9, 10, K)])
    X = np.array([rng.uniform(-2, 2, K), rng.uniform(-1, 1, K)])
    scene = SceneModel(mech)
    scene.params = params
    phase = PhaseModel(SceneModel(mech), params)
    Y = np.concatenate([X[:1], mech.momenta(X[:1], X[1:], np.zeros(K), params)])
    for sg in (-1.0, 1.0):
        sigma = np.full((1, K), sg)
        F, P = scene._field(0.0, X, sigma), phase._field(0.0, Y, sigma)
        assert np.allclose(P[0], F[0]) and np.allclose(P[1], params[0] * F[1])   # p = m x'
        dh_scene = (scene._switch_gradient(0.0, X)[0] * F).sum(axis=0)
        dh_phase = (phase._switch_gradient(0.0, Y)[0] * P).sum(axis=0)
        assert np.allclose(dh_scene, dh_phase, rtol=1e-7)


def test_the_numerical_reference_is_the_scene_model_with_its_events():
    """A numerical part compares with the scene's motion only while its model holds (NaN beyond)."""
    from lagrade.verdicts.checkers import numerical

    ctx, part, mech = _setup("solution")
    params = np.array([1.0, 9.8, 3.0])
    y0 = np.array([0.2, 0.0, 0.0, 0.5])
    times = np.linspace(0.05, 0.55, 11)
    ref = numerical._reference_at(ctx, mech, params, y0, 0.0, times)
    stop = scene_model(mech).contact_events  # the model's own contact law decides where it ends
    assert stop
    assert np.isfinite(ref[:, 0]).all() and np.isnan(ref[:, -1]).all()
    modelled = times[np.isfinite(ref[0])]
    assert modelled[-1] < LATE


def test_the_benchmarks_time_the_grading_paths_entry(monkeypatch):
    """`lagrade bench accuracy`'s grading row runs `scene_motion` (the declared model, its events), the
    entry the motion and numerical parts use; a row that integrated bare rates would bypass it."""
    from lagrade.uses.research import workprecision as wp

    calls = []
    real = wp.scene_motion

    def spy(mech, y0, params, horizon, acc, **kw):
        calls.append(kw)
        return real(mech, y0, params, horizon, acc, **kw)

    monkeypatch.setattr(wp, "scene_motion", spy)
    sc = wp.scene("12.43", K=2)
    t_eval = np.linspace(0.0, sc.horizon, 11)
    row = wp._grading_row(sc, ACCURACY["default"], "DOP853", t_eval, np.zeros((sc.y0.shape[0], 2, 11)), 1)
    assert calls and row.ok and row.method == "grading"


def test_the_scene_grades_end_to_end():
    """The test scene's right answers get full marks through `lagrade.check`, and a motion with one
    wrong entry the per-entry credit (the scene model's motion, its events watched)."""
    t = sp.Symbol("t")
    r, x = sp.Function("r")(t), sp.Function("x")(t)
    pr, px = sp.Function("p_r")(t), sp.Function("p_x")(t)
    m, g, om, x0, u = sp.symbols("m g omega x0 u", positive=True)
    H = (pr**2 + px**2) / (2 * m) - m * om**2 * r**2 / 2 + m * g * r * sp.sin(om * t)
    eom = [sp.Eq(m * r.diff(t, 2), m * om**2 * r - m * g * sp.sin(om * t)), sp.Eq(m * x.diff(t, 2), 0)]
    got = {p.part: p for p in lagrade.check(PROBLEM, H=H, eom=eom, solution={"r": _r_exact(), "x": x0 + u * t}).parts}
    assert all(got[k].verdict == "correct" for k in ("H", "eom", "solution")), {k: p.feedback for k, p in got.items()}
    part = next(p for p in lagrade.check(PROBLEM, solution={"r": _r_exact(), "x": x0 + 2 * u * t}).parts
                if p.part == "solution")
    assert part.verdict == "partial" and "r(t) is right" in part.feedback, part.feedback
