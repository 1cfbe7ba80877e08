"""Grading simulates stick-slip (issue 23 §2): where a scene declares dry friction, the reference AND the
student's equations are integrated as switching models (each sign(v) a branch, Filippov's rule at v = 0),
so a trajectory can refute a wrong friction law and a right one in any form is accepted.

The scene (tests/problems_stick_slip/coulomb-spring.toml): m x'' + k x + mu m g sign(x') = 0.

Closed form (derived by hand, checked with sympy below). While the block slides with sign(x') = s it
oscillates about the shifted centre c = -s d, d = mu m g / k, at omega = sqrt(k/m):
x(t) - c = A cos(omega t + phi), x'(t) = -A omega sin(omega t + phi). At each turning point (x' = 0)
static friction holds iff |k x| <= mu m g, i.e. |x| <= d (the same coefficient as kinetic); otherwise the
block slides back toward the wall, a half period pi/omega, and its turning point is mirrored about the new
centre c = d sign(x): x -> 2 d sign(x) - x. So the block sticks at the first turning point with |x| <= d,
at the time the half swings add up to, and stays there.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import lagrade
from lagrade.verdicts.checkers import dynamics
from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.problem.library import load_problem
from lagrade.numbers.numeric import CompiledRates
from lagrade.derive.reference import Mechanics
from lagrade.compare.scene_model import EquationsModel, PhaseModel, SceneModel

PROBLEM = Path(__file__).parent / "problems_stick_slip" / "coulomb-spring.toml"

t = sp.Symbol("t")
x = sp.Function("x")(t)
m, k, mu, g = sp.symbols("m k mu g", positive=True)
v = x.diff(t)

#: Event times are located to the integration tolerance (rtol 1e-10); after up to ~20 half swings
#: the stick time and rest position are good to far better than this bound.
BOUND = 1e-6


def eom(friction) -> sp.Eq:
    return sp.Eq(m * x.diff(t, 2) + k * x + friction, 0)


def closed_form(x0: float, v0: float, w: float, d: float) -> tuple[float, float]:
    """(time at which the block sticks, where): see the module docstring."""
    time, pos = 0.0, x0
    if v0 != 0.0:
        s = math.copysign(1.0, v0)
        c = -s * d
        A = math.hypot(x0 - c, v0 / w)
        # x - c = A cos(theta), x' = -A w sin(theta), theta = w t + phi grows: x' > 0 for theta in (-pi, 0)
        # and reaches 0 at theta = 0; x' < 0 for theta in (0, pi) and reaches 0 at theta = pi
        theta0 = math.atan2(-v0 / w, x0 - c)
        target = 0.0 if s > 0 else math.pi
        time += ((target - theta0) % (2 * math.pi)) / w
        pos = c + A * math.cos(target)
    while abs(pos) > d:
        pos = 2 * d * math.copysign(1.0, pos) - pos
        time += math.pi / w
    return time, pos


def test_the_closed_form_solves_the_equation_on_each_branch():
    """sympy: c + (x0 - c) cos(omega t) solves the equation with sign(x') = s held fixed, starting at rest
    at x0, with c = -s d; it comes to rest again after pi/omega at 2c - x0 (the mirrored turning point)."""
    x0, s, tt = sp.symbols("x0 s tt", real=True)
    w = sp.sqrt(k / m)
    d = mu * m * g / k
    c = -s * d
    sol = c + (x0 - c) * sp.cos(w * tt)
    assert sp.simplify(m * sol.diff(tt, 2) + k * sol + mu * m * g * s) == 0
    assert sol.subs(tt, 0) == x0 and sol.diff(tt).subs(tt, 0) == 0
    assert sp.simplify(sol.diff(tt).subs(tt, sp.pi / w)) == 0
    assert sp.simplify(sol.subs(tt, sp.pi / w) - (2 * c - x0)) == 0
    # static friction holds at rest at x iff the spring force does not exceed mu m g
    X = sp.Symbol("X", positive=True)
    assert sp.solve(sp.Eq(k * X, mu * m * g), X) == [d]
    # the helper, by hand for x0 = 1, d = 0.196: 1 -> -0.608 -> 0.216 -> 0.176 (<= d), three half swings
    tw, xw = closed_form(1.0, 0.0, math.sqrt(10), 0.196)
    assert xw == pytest.approx(0.176, abs=1e-12) and tw == pytest.approx(3 * math.pi / math.sqrt(10), abs=1e-12)
    # starting in motion, x0 = 0, x' = 1, w = 1, d = 0.1: the first turning point c + A = sqrt(1.01) - 0.1
    # after atan(10); then 0.905 -> -0.705 -> 0.505 -> -0.305 -> 0.105 -> 0.095 (<= d): five half swings
    tw, xw = closed_form(0.0, 1.0, 1.0, 0.1)
    assert xw == pytest.approx(1.1 - math.sqrt(1.01), abs=1e-12)   # x6 = 1 - x1
    assert tw == pytest.approx(math.atan(10) + 5 * math.pi, abs=1e-12)


class Spy:
    """Records what the dynamics checker integrates: the models handed to compare_runs and the result.
    The reference run is not taken from the cache (store={}), so its switches are those of this call."""

    def __init__(self, monkeypatch, fresh: bool = True):
        self.calls = []
        real = dynamics.compare_runs

        def spy(student, reference, y0, labels, horizon, acc, **kw):
            if fresh:
                kw["store"] = {}
            out = real(student, reference, y0, labels, horizon, acc, **kw)
            self.calls.append((student, reference, y0, kw.get("events", ()), out))
            return out

        monkeypatch.setattr(dynamics, "compare_runs", spy)


def grade_eom(friction, monkeypatch):
    spy = Spy(monkeypatch)
    got = next(p for p in lagrade.check(PROBLEM, eom=eom(friction)).parts if p.part == "eom")
    return got, spy


@pytest.mark.parametrize("friction", [
    mu * m * g * sp.sign(v),
    mu * m * g * v / sp.Abs(v),
    mu * m * g * sp.Abs(v) / v,
    mu * m * g * (2 * sp.Heaviside(v) - 1),
    mu * m * g * sp.Piecewise((1, v > 0), (-1, True)),
], ids=["sign", "v/|v|", "|v|/v", "Heaviside", "Piecewise"])
def test_the_right_equation_in_any_dry_friction_form_gets_full_marks(friction, monkeypatch):
    got, spy = grade_eom(friction, monkeypatch)
    assert got.verdict == "correct" and got.score == 1.0, got.feedback
    assert "trajectories agree" in got.feedback
    (student, reference, _, _, comparison), = spy.calls
    assert isinstance(student, EquationsModel) and isinstance(reference, SceneModel)
    assert comparison.agree
    # the student's own equations stuck (Filippov's rule on their branches), not just the reference's
    assert student.switches["stick"] and reference.switches["stick"]
    assert len(student.switches["stick"]) == len(reference.switches["stick"])


@pytest.mark.parametrize("accuracy", ["fast", "default", "strict"])
def test_the_right_equation_agrees_by_trajectory_under_every_preset(accuracy, monkeypatch):
    """Both runs of one comparison share the event list; the student's run starts after the
    reference's has switched its branches (and, graded again, from the cached reference alone)."""
    for fresh in (True, False):
        spy = Spy(monkeypatch, fresh=fresh)
        lagrade.check(PROBLEM, accuracy=accuracy, eom=eom(mu * m * g * sp.sign(v)))
        (student, _, _, _, comparison), = spy.calls
        assert comparison.agree, (accuracy, fresh, comparison.describe())
        assert student.switches["stick"]


@pytest.mark.parametrize("friction, what", [
    (sp.Rational(11, 10) * mu * m * g * sp.sign(v), "friction coefficient 10% too large"),
    (sp.S.Zero, "friction left out"),
    (-mu * m * g * sp.sign(v), "friction with the wrong sign (pushing along the motion)"),
])
def test_wrong_friction_is_refuted_by_the_trajectory(friction, what, monkeypatch):
    got, spy = grade_eom(friction, monkeypatch)
    assert got.verdict == "incorrect", what
    (_, reference, _, _, comparison), = spy.calls
    assert isinstance(reference, SceneModel)
    assert not comparison.agree and comparison.decisive, what
    assert "your motion separates from the true one" in got.feedback
    # feedback names the student's motion, never a reference value (no sampled number, no mu*m*g)
    assert "mu*m*g" not in got.feedback and "sign" not in got.feedback


def test_the_reference_motion_sticks_where_and_when_the_closed_form_says(monkeypatch):
    got, spy = grade_eom(mu * m * g * sp.sign(v), monkeypatch)
    assert got.verdict == "correct"
    (_, reference, y0, _, _), = spy.calls
    mech = reference.mech
    P = dict(zip(map(str, mech.params), reference.params))
    horizon = mech.system.horizon
    stuck = dict(reference.switches["stick"])
    checked = 0
    for kk in range(y0.shape[1]):
        w = math.sqrt(P["k"][kk] / P["m"][kk])
        d = P["mu"][kk] * P["m"][kk] * P["g"][kk] / P["k"][kk]
        t_stick, x_rest = closed_form(float(y0[0, kk]), float(y0[1, kk]), w, d)
        if t_stick < horizon - 1e-3:
            checked += 1
            assert stuck[kk] == pytest.approx(t_stick, abs=BOUND)
        else:
            assert kk not in stuck
    assert checked >= 2, "the sampled states should include motions that stick inside the horizon"
    # and at the closed-form rest position: integrate the same reference model to the end
    reference.arm(y0)
    acc = replace(ACCURACY["default"], method="DOP853")
    events = reference.switching_events(y0)
    run = integrate(reference, y0, horizon, acc, events=events)
    for kk in range(y0.shape[1]):
        w = math.sqrt(P["k"][kk] / P["m"][kk])
        d = P["mu"][kk] * P["m"][kk] * P["g"][kk] / P["k"][kk]
        t_stick, x_rest = closed_form(float(y0[0, kk]), float(y0[1, kk]), w, d)
        if t_stick < horizon:
            assert run.y[0, kk, -1] == pytest.approx(x_rest, abs=BOUND)


def test_the_lagrangian_part_runs_the_switching_model_too(monkeypatch):
    spy = Spy(monkeypatch)
    L = m * v**2 / 2 - k * x**2 / 2
    got = next(p for p in lagrade.check(PROBLEM, L=L).parts if p.part == "L")
    assert got.verdict == "correct", got.feedback
    (student, _, _, _, comparison), = spy.calls
    assert isinstance(student, EquationsModel) and student.switches["stick"]
    assert comparison.agree


def test_hamiltons_equations_run_switching_models_in_q_and_p(monkeypatch):
    """In (q, p) the friction's sign is one of p: the scene's model read in (q, p) and the student's
    equations are both switching models there, and the same Filippov rule makes both stick where the Lagrangian motion does."""
    px = sp.Function("p_x")(t)
    H = px**2 / (2 * m) + k * x**2 / 2
    right = [sp.Eq(x.diff(t), px / m), sp.Eq(px.diff(t), -k * x - mu * m * g * sp.sign(px / m))]
    spy = Spy(monkeypatch)
    got = {p.part: p for p in lagrade.check(PROBLEM, H=H, hamilton=right).parts}
    assert got["H"].verdict == "correct" and got["hamilton"].verdict == "correct", got["hamilton"].feedback
    for student, reference, _, _, comparison in spy.calls:
        assert isinstance(student, EquationsModel) and isinstance(reference, PhaseModel)
        assert comparison.agree and student.switches["stick"] and reference.switches["stick"]
    wrong = [right[0], sp.Eq(px.diff(t), -k * x)]
    spy = Spy(monkeypatch)
    got = next(p for p in lagrade.check(PROBLEM, hamilton=wrong).parts if p.part == "hamilton")
    assert got.verdict != "correct"
    (_, _, _, _, comparison), = spy.calls
    assert not comparison.agree and comparison.decisive
    assert "your motion separates from the true one" in got.feedback


def test_a_scene_without_switching_takes_the_generic_path(monkeypatch):
    """Nothing undeclared compiled in: 12.7 (a spring pendulum, no dissipation) compares the compiled
    student rates with the generic reference, with no switching event (the exact judge, which decides
    these equations before any motion, off)."""
    from lagrade.compare import exact

    monkeypatch.setattr(exact, "is_zero", lambda *a, **k: None)
    monkeypatch.setattr(exact, "is_zero_given", lambda *a, **k: None)
    spy = Spy(monkeypatch)
    r, theta = (sp.Function(n)(t) for n in ("r", "theta"))
    eq = [sp.Eq(m * r.diff(t, 2), m * r * theta.diff(t) ** 2 + m * g * sp.cos(theta) - k * (r - sp.Symbol("l0"))),
          sp.Eq(sp.Derivative(m * r**2 * theta.diff(t), t), -m * g * r * sp.sin(theta))]
    got = next(p for p in lagrade.check("12.7", eom=eq).parts if p.part == "eom")
    assert got.verdict == "correct", got.feedback
    (student, reference, _, events, _), = spy.calls
    assert isinstance(student, CompiledRates) and not isinstance(reference, SceneModel)
    assert not [e for e in events if e.action == "switch"]


def test_a_stuck_block_breaks_away_when_the_drive_exceeds_static_friction():
    """Breakaway, for any equations (here a student's, with a driven spring support A sin(w t)): stuck
    at rest at x_s from t_s, the block leaves when |k (x_s - A sin(w t))| first exceeds mu m g."""
    mech = Mechanics(load_problem(str(PROBLEM)), load_problem(str(PROBLEM)).systems[0])
    A, w = sp.symbols("A w")
    s = mech.s
    xs, xd, xdd = s.q[0], s.qd[0], s.qdd[0]
    rows = [m * xdd + k * (xs - A * sp.sin(w * sp.Symbol("t"))) + mu * m * g * sp.sign(xd)]
    from lagrade.problem.symbols import T
    rows = [rows[0].xreplace({sp.Symbol("t"): T})]
    args = [xs, xd, T, *mech.params, A, w]
    P = {"m": 1.0, "k": 10.0, "mu": 0.3, "g": 10.0, "A": 0.5, "w": 1.0}
    consts = np.array([[P[str(p)]] for p in [*mech.params, A, w]])
    model = EquationsModel(rows, mech, args, consts)
    y0 = np.array([[0.0], [0.0]])   # at rest, spring relaxed: static friction holds (|k x| = 0 < 3)
    events = model.switching_events(y0)
    acc = replace(ACCURACY["default"], method="DOP853", max_rhs_evals=10**5)
    run = integrate(model, y0, 1.0, acc, events=events, samples=11)
    assert run.ok
    sticks = [tt for _, tt in model.switches["stick"]]
    breaks = [tt for _, tt in model.switches["breakaway"]]
    assert sticks and sticks[0] == pytest.approx(0.0, abs=1e-9)
    # breakaway at k A sin(w t) = mu m g: sin t = 0.6
    assert breaks and breaks[0] == pytest.approx(math.asin(0.6), abs=BOUND)
    assert np.all(np.abs(run.y[0, 0, run.t < breaks[0] - 1e-6]) < 1e-9)   # held at rest until then


class _TwoContacts:
    """Two dry-friction contacts on two blocks (x1, x2), as a `Switching` with a hand-written field:
    F = [v1, v2, -s1 - x1, -s2 - x2 + c] for branches s1, s2 and a per-trajectory constant c."""

    @staticmethod
    def model(c: np.ndarray):
        from lagrade.compare.scene_model import Branches, Switching

        class Model(Switching):
            dim = 4

            def _field(self, tt, Y, sigma):
                return np.array([Y[2], Y[3], -sigma[0] - Y[0], -sigma[1] - Y[1] + c])

            def _switch_values(self, tt, Y):
                return Y[2:4]

            def _switch_gradient(self, tt, Y):
                G = np.zeros((2, 4, Y.shape[1]))
                G[0, 2], G[1, 3] = 1.0, 1.0
                return G

        model = Model()
        model.branches = Branches([sp.Symbol("v1"), sp.Symbol("v2")], np.zeros((2, len(c))), [True, True],
                                  [None, None])
        return model


def test_a_trajectory_whose_sliding_field_is_undefined_loses_only_itself():
    """Both contacts stuck in both trajectories; trajectory 1's equations give NaN there. Its field is
    NaN (its step is rejected, as any NaN); trajectory 0 slides as Filippov's rule says."""
    model = _TwoContacts.model(np.array([0.5, np.nan]))
    Y = np.array([[0.2, 0.2], [0.1, 0.1], [0.0, 0.0], [0.0, 0.0]])
    F = model.field(0.0, Y, np.zeros((2, 2)))
    assert np.isnan(F[:, 1]).any()
    # stuck: both velocities stay 0 (static friction holds: |x1| <= 1, |x2 - 0.5| <= 1)
    assert np.allclose(F[:, 0], [0.0, 0.0, 0.0, 0.0])


def test_a_students_switching_arguments_are_merged_without_simplify():
    """Switching arguments that are one function in two forms share one branch; a form built to make
    `simplify` slow (measured: 19.7 s at n = 120) is read in a moment."""
    import time

    from lagrade.compare.scene_model import branch_form

    vv, ww, xx = sp.symbols("v w x")
    _, args, _, _ = branch_form([sp.sign(vv * (1 + xx) ** 2) + sp.sign(vv + 2 * vv * xx + vv * xx ** 2)], {vv, ww})
    assert len(args) == 1
    n = 120
    start = time.process_time()
    _, args, _, _ = branch_form([sp.sign(vv) + sp.sign(vv * sp.cos(xx) ** n + ww * sp.sin(xx) ** n)
                                 + sp.sign(vv + ww * (1 + xx) ** n - ww)], {vv, ww})
    assert time.process_time() - start < 5.0
    assert len(args) == 3


def test_branch_symbols_never_take_a_name_already_in_use():
    """A parameter called sigma0 (a surface density, say) and a branch variable compiled side by side
    would be one argument twice; the branches take a name no argument or expression uses."""
    from lagrade.compare.scene_model import branch_form

    vv, xx, s0 = sp.symbols("v x sigma0")
    rows, _, sig, _ = branch_form([s0 * xx + sp.sign(vv)], {vv}, [xx, vv, s0])
    assert [str(b) for b in sig] == ["_sigma0"]
    assert rows == [s0 * xx + sig[0]]
    _, _, sig, _ = branch_form([xx + sp.sign(vv)], {vv}, [xx, vv])
    assert [str(b) for b in sig] == ["sigma0"]
