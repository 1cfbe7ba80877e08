"""Issue 21 part 4: the questions that had no part (12.7 conditions, 12.46 elimination, 12.50 solving, 12.9
generalized forces).

Every reference value the problem files state is re-derived here with sympy alone (or integrated with
mpmath / scipy), never through lagrade's references; the new checkers are held to verdicts that fail
when what they guard is broken (a wrong condition accepted, a table that departs graded right, a
reference value in the feedback).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp

import lagrade
from lagrade.problem.library import problem_ids

ROOT = Path(__file__).resolve().parents[1]
t = sp.Symbol("t")


def problem_data(pid: str) -> dict:
    return tomllib.loads((ROOT / "problems" / f"{pid}.toml").read_text())


def part_data(pid: str, name: str) -> dict:
    return next(p for p in problem_data(pid)["parts"] if p["name"] == name)


def to_state(expr: sp.Expr, names: list[str]) -> sp.Expr:
    """Functions of t -> the plain symbols q, q_d, q_dd the problem files write."""
    for n in names:
        q = sp.Function(n)(t)
        expr = expr.subs(q.diff(t, 2), sp.Symbol(f"{n}_dd")).subs(q.diff(t), sp.Symbol(f"{n}_d")).subs(q, sp.Symbol(n))
    return expr


def text(expr: str) -> sp.Expr:
    return sp.sympify(expr, locals={n: sp.Symbol(n) for n in ("theta", "r", "phip", "r_d", "theta_d", "phip_d",
                                                             "omega", "m", "g", "k", "l", "M", "l0", "tau")})


def verdict(pid: str, **parts) -> tuple[str, str]:
    (name,) = parts
    result = lagrade.check(pid, **parts)
    part = next(p for p in result.parts if p.part == lagrade.load_problem(pid).part(name).name)
    return part.verdict, part.feedback


# ----------------------------------------------------------------------------------------------- 12.9 (b)

def test_12_9_generalized_forces_are_the_extra_terms_of_lagranges_equations():
    """(b) written with the left-hand side of (a) (phi -> phip): the omega**2 terms and the terms linear in
    omega on the force side are the generalized centrifugal and Coriolis forces."""
    m, w = sp.symbols("m omega")
    r, th, ph = (sp.Function(n)(t) for n in ("r", "theta", "phip"))

    def T(rate):
        return m / 2 * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2 + r**2 * sp.sin(th) ** 2 * rate**2)

    def lagrange(L):
        return [sp.diff(L.diff(q.diff(t)), t) - L.diff(q) for q in (r, th, ph)]

    extra = [sp.expand(a - b) for a, b in zip(lagrange(T(ph.diff(t))), lagrange(T(ph.diff(t) + w)))]
    names = ["r", "theta", "phip"]
    for part, power in (("centrifugal", 2), ("coriolis", 1)):
        ref = part_data("12.9", part)["reference"]
        for key, e in zip(names, extra):
            derived = to_state(e.coeff(w, power) * w**power, names)
            assert sp.simplify(derived - text(ref[key])) == 0, (part, key)


def test_12_9_physical_components_are_accepted_as_the_catalogue_writes_them():
    """With (a)'s equations written with F_r, F_theta, F_phi (as the catalogue writes them), the extra terms
    of (b) are the components along e_r, e_theta, e_phi: an admissible reading, and the feedback says so;
    a mix of the two normalizations in one answer is neither."""
    v, feedback = verdict("12.9", centrifugal={"r": text("m*omega**2*r*sin(theta)**2"),
                                               "theta": text("m*omega**2*r*sin(theta)*cos(theta)"), "phip": 0})
    assert v == "correct" and "e_theta" in feedback, feedback
    v, _ = verdict("12.9", coriolis={"r": text("2*m*omega*r*sin(theta)**2*phip_d"),
                                     "theta": text("2*m*omega*r*sin(theta)*cos(theta)*phip_d"),
                                     "phip": text("-2*m*omega*r*sin(theta)*(r_d*sin(theta) + r*cos(theta)*theta_d)")})
    assert v != "correct"


# ----------------------------------------------------------------------------------------------- 12.46 (b)

def test_12_46_reduced_scene_is_the_routh_reduction():
    """theta'' of the full car-and-pendulum system (X'' eliminated), theta'' of the Routhian L - p_X X' (X'
    from the constant p_X) and theta'' of the problem file's reduced L are one and the same."""
    m, M, l, g, p = sp.symbols("m M l g p_X")
    X, th = sp.Function("X")(t), sp.Function("theta")(t)
    L = (M + m) / 2 * X.diff(t) ** 2 + m * l * sp.cos(th) * X.diff(t) * th.diff(t) + m * l**2 / 2 * th.diff(t) ** 2 \
        + m * g * l * sp.cos(th)
    el = [to_state(sp.diff(L.diff(q.diff(t)), t) - L.diff(q), ["X", "theta"]) for q in (X, th)]
    full = sp.solve(el, [sp.Symbol("X_dd"), sp.Symbol("theta_dd")], dict=True)[0][sp.Symbol("theta_dd")]

    Xd = (p - m * l * sp.cos(th) * th.diff(t)) / (M + m)
    assert sp.simplify(L.diff(X.diff(t)).subs(X.diff(t), Xd) - p) == 0
    R = L.subs(X.diff(t), Xd) - p * Xd
    routh = sp.solve(to_state(sp.diff(R.diff(th.diff(t)), t) - R.diff(th), ["theta"]), sp.Symbol("theta_dd"))[0]
    assert sp.simplify(routh - full) == 0
    assert not routh.has(p), "the reduced equation does not depend on p_X"

    reduced = next(s for s in problem_data("12.46")["systems"] if s.get("key") == "reduced")
    Lr = text(reduced["L"]).subs({sp.Symbol("theta"): th, sp.Symbol("theta_d"): th.diff(t)})
    mine = sp.solve(to_state(sp.diff(Lr.diff(th.diff(t)), t) - Lr.diff(th), ["theta"]), sp.Symbol("theta_dd"))[0]
    assert sp.simplify(mine - full) == 0


def _routhian(sign: int) -> sp.Expr:
    m, M, l, g, p = sp.symbols("m M l g p_X")
    th = sp.Function("theta")(t)
    Xd = (p - m * l * sp.cos(th) * th.diff(t)) / (M + m)
    L = (M + m) / 2 * Xd**2 + m * l * sp.cos(th) * Xd * th.diff(t) + m * l**2 / 2 * th.diff(t) ** 2 + m * g * l * sp.cos(th)
    return sign * (L - p * Xd)


@pytest.mark.parametrize("answer, expected", [
    (_routhian(1), "correct"),                                  # R = L - p q'
    (_routhian(-1), "correct"),                                 # R = p q' - L
    (2 * _routhian(1), "partial"),                              # a scaled R is no Routhian (as for L)
    (text("m*l**2*theta_d**2/2 + m*g*l*cos(theta)").subs(      # the pendulum on a fixed support
        {sp.Symbol("theta"): sp.Function("theta")(t), sp.Symbol("theta_d"): sp.Function("theta")(t).diff(t)}),
     "incorrect"),
])
def test_12_46_either_sign_of_the_routhian_and_nothing_else(answer, expected):
    v, feedback = verdict("12.46", routhian=answer)
    assert v == expected, feedback


def test_12_46_reduced_equation_with_x_dd_zero_is_wrong():
    th = sp.Function("theta")(t)
    l, g, m, M = sp.symbols("l g m M")
    assert verdict("12.46", eom_reduced=sp.Eq(l * th.diff(t, 2) + g * sp.sin(th), 0))[0] == "incorrect"
    good = sp.Eq(l * (M + m * sp.sin(th) ** 2) * th.diff(t, 2) + m * l * sp.sin(th) * sp.cos(th) * th.diff(t) ** 2,
                 -(M + m) * g * sp.sin(th))
    assert verdict("12.46", eom_reduced=good)[0] == "correct"


# ----------------------------------------------------------------------------------------------- 12.50

@pytest.fixture(scope="module")
def motion_12_50():
    """x(t) of x'' = k exp(-t/tau)/(m x**2) at the part's numbers, by mpmath's Taylor-series integrator."""
    part = part_data("12.50", "solution")
    nums = {k: float(v) for k, v in part["reference"].items()}
    x0, v0 = float(part["initial"]["x"]), float(part["initial"]["x_d"])
    mpmath.mp.dps = 20
    f = mpmath.odefun(lambda s, y: [y[1], nums["k"] * mpmath.exp(-s / nums["tau"]) / (nums["m"] * y[0] ** 2)],
                      0, [x0, v0])
    return lambda s: float(f(s)[0])


def test_12_50_a_table_of_the_motion_is_right(motion_12_50):
    times = [0.0, 0.4, 1.1, 2.0, 3.3, 5.0]
    rounded = {s: float(f"{motion_12_50(s):.4g}") for s in times}  # four significant figures pass
    assert verdict("12.50", solution=rounded)[0] == "correct"
    assert verdict("12.50", solution=[[s, motion_12_50(s)] for s in times])[0] == "correct"
    assert verdict("12.50", solution={"t": times, "x": [motion_12_50(s) for s in times]})[0] == "correct"


def test_12_50_a_table_that_departs_says_where_and_not_the_value(motion_12_50):
    times = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
    values = [motion_12_50(s) for s in times]
    values[3] *= 1.01  # 1 % off at t = 3 only
    v, feedback = verdict("12.50", solution={"t": times, "x": values})
    assert v == "incorrect"
    assert "t = 3" in feedback and "1 of the 6" in feedback
    for s in times:
        for digits in (3, 4, 6):
            assert f"{motion_12_50(s):.{digits}g}" not in feedback or s == 0.0


def test_12_50_an_expression_is_graded_against_the_integrated_motion(motion_12_50):
    grid = np.linspace(0.0, 5.0, 201)
    u = (2 * grid - 5) / 5
    coef = np.polyfit(u, [motion_12_50(s) for s in grid], 16)
    us = (2 * t - 5) / 5
    fit = sum(sp.Float(c) * us ** (16 - i) for i, c in enumerate(coef))
    x = sp.Function("x")(t)
    assert verdict("12.50", solution={x: fit})[0] == "correct"
    assert verdict("12.50", solution={"x": 1 + t**2 / 2})[0] == "incorrect"  # the start of the motion only


@pytest.mark.parametrize("table", [
    {0: 1.0, 0.5: 1.1},                               # too few times
    {"t": [0, 1, 1, 2, 3], "x": [1, 1.3, 1.3, 1.9, 2.6]},  # a time twice
    {"t": [0, 1, 2, 3, 9], "x": [1, 1.3, 1.9, 2.6, 7.0]},  # outside the window
    {"t": [0, 1, 2], "x": [1, 2]},                   # lengths differ
    {"t": [0, 1, 2, 3, 4], "x": [1, 1.3, "many", 2.6, 3.2]},  # not a number
    {"y": [1, 2]},                                   # no such coordinate
])
def test_12_50_an_unusable_table_is_invalid_with_a_reason(table):
    v, feedback = verdict("12.50", solution=table)
    assert v == "invalid" and feedback


# ----------------------------------------------------------------------------------------------- 12.7

def test_12_7_theta_zero_leaves_a_harmonic_oscillator():
    """(b): with theta = 0 for all time the theta equation holds identically and the r equation is linear
    with a restoring force (sympy on the Lagrangian of the catalogue)."""
    m, k, l0, g = sp.symbols("m k l0 g", positive=True)
    r, th = sp.Function("r")(t), sp.Function("theta")(t)
    L = m / 2 * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2) + m * g * r * sp.cos(th) - k / 2 * (r - l0) ** 2
    el = [to_state(sp.diff(L.diff(q.diff(t)), t) - L.diff(q), ["r", "theta"]) for q in (r, th)]
    held = {sp.Symbol("theta"): 0, sp.Symbol("theta_d"): 0, sp.Symbol("theta_dd"): 0}
    assert sp.simplify(el[1].subs(held)) == 0
    radial = sp.expand(el[0].subs(held))
    assert sp.expand(radial - (m * sp.Symbol("r_dd") + k * sp.Symbol("r") - k * l0 - m * g)) == 0
    assert part_data("12.7", "oscillator")["reference"]["harmonic"] == "r"


def _swing(stiffness: float) -> float:
    """Largest gap between theta(t) of the spring pendulum (k*l0/(m*g) = stiffness, released from rest at its
    static stretch, 1 rad out) and of the simple pendulum of length l0, over three periods."""
    from scipy.integrate import solve_ivp

    m, g, l0 = 1.0, 1.0, 1.0
    k = stiffness * m * g / l0
    ts = np.linspace(0, 3 * 2 * np.pi, 400)
    spring = solve_ivp(lambda s, y: [y[2], y[3], y[0] * y[3] ** 2 + g * np.cos(y[1]) - k * (y[0] - l0) / m,
                                     -(g * np.sin(y[1]) + 2 * y[2] * y[3]) / y[0]],
                       (0, ts[-1]), [l0 + m * g / k, 1.0, 0.0, 0.0], t_eval=ts, rtol=1e-10, atol=1e-12, method="LSODA")
    rod = solve_ivp(lambda s, y: [y[1], -g / l0 * np.sin(y[0])], (0, ts[-1]), [1.0, 0.0], t_eval=ts, rtol=1e-10,
                    atol=1e-12)
    return float(np.abs(spring.y[1] - rod.y[0]).max())


@pytest.mark.slow
def test_12_7_a_stiff_spring_is_a_simple_pendulum():
    """(a): the reference criterion k*l0/(m*g) -> oo (g/l0 held) is where the spring pendulum becomes the
    simple pendulum: numerically, the swing approaches it as the criterion grows."""
    ref = part_data("12.7", "pendulum")["reference"]
    assert ref == {"grows": "k*l0/(m*g)", "fixed": "g/l0"}
    gaps = [_swing(s) for s in (10.0, 1e3, 1e5)]
    assert gaps[0] > 0.1 and gaps[2] < 1e-2 and gaps[0] > gaps[1] > gaps[2], gaps


K, M_, G, L0 = sp.symbols("k m g l0")
R, TH = sp.Function("r")(t), sp.Function("theta")(t)


@pytest.mark.parametrize("answer, expected", [
    ({K: sp.oo}, "correct"),
    ({"k": sp.oo}, "correct"),
    ([sp.Eq(K, sp.oo)], "correct"),
    ({K / M_: sp.oo}, "correct"),
    ({M_ * G / (K * L0): 0}, "correct"),
    ({M_: 0}, "correct"),                      # only k/m matters: a light bob on the same spring
    ({K: 0}, "incorrect"),
    ({G: 0}, "incorrect"),                     # no gravity, no pendulum
    ({L0: sp.oo}, "incorrect"),
    ({K: sp.oo, G: 0}, "incorrect"),
    ({K: 5}, "incorrect"),
    ({R: L0}, "incorrect"),
], ids=str)
def test_12_7_pendulum_conditions(answer, expected):
    v, feedback = verdict("12.7", pendulum=answer)
    assert v == expected, feedback


@pytest.mark.parametrize("answer, expected", [
    ({TH: 0}, "correct"),
    ({TH: 0, TH.diff(t): 0}, "correct"),
    ({"theta": 0, "theta_d": 0}, "correct"),
    ([sp.Eq(TH, 0)], "correct"),
    ({TH: sp.pi}, "correct"),                  # straight up: still a motion, and r oscillates harmonically
    ({TH.diff(t): 0}, "incorrect"),            # held at an angle, gravity swings it
    ({TH: sp.Rational(3, 10)}, "incorrect"),
    ({R: L0}, "incorrect"),
    ({R.diff(t): 0}, "incorrect"),
    ({K: sp.oo}, "incorrect"),
], ids=str)
def test_12_7_oscillator_conditions(answer, expected):
    v, feedback = verdict("12.7", oscillator=answer)
    assert v == expected, feedback


def test_12_7_conditions_not_readable_are_invalid():
    assert verdict("12.7", pendulum=sp.oo)[0] == "invalid"
    assert verdict("12.7", pendulum={K + M_: sp.oo})[0] == "invalid"  # a sum is no scaling limit
    assert verdict("12.7", oscillator={R * TH: 0})[0] == "invalid"


def test_12_50_text_answers_give_the_table_as_a_table_or_one_string(tmp_path, motion_12_50):
    values = {s: f"{motion_12_50(s):.5g}" for s in (0, 1, 2, 3, 4, 5)}
    keyed = ", ".join(f'"{s}" = "{v}"' for s, v in values.items())
    inline = "{" + ", ".join(f"{s}: {v}" for s, v in values.items()) + "}"
    for body in (f"solution = {{ {keyed} }}\n", f'solution = "{inline}"\n'):
        answer = tmp_path / "answer.toml"
        answer.write_text(body)
        part = next(p for p in lagrade.check("12.50", answer).parts if p.part == "solution")
        assert part.verdict == "correct", (body, part.feedback)


@pytest.mark.parametrize("pid", problem_ids())
def test_new_kinds_have_what_their_checkers_need(pid):
    """A numerical_solution part states its numbers, a conditions part what it asks: a problem file that
    forgets them fails here, not as an engine error on a student's answer."""
    from lagrade.verdicts.checkers.numerical import _numbers
    from lagrade.verdicts.grade import references

    problem = lagrade.load_problem(pid)
    for part in problem.parts:
        if part.kind not in ("numerical_solution", "conditions"):
            continue
        mech = references(problem)[part.system]
        if part.kind == "numerical_solution":
            params, y0, (t0, t1) = _numbers(part, mech)
            assert len(params) == len(mech.params) and len(y0) == 2 * len(mech.names) and t0 < t1
        if part.kind == "conditions":
            assert isinstance(part.reference, dict) and ({"grows"} <= set(part.reference)
                                                          or set(part.reference) == {"harmonic"})
            if "harmonic" in part.reference:
                assert part.reference["harmonic"] in mech.names
