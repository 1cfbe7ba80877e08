"""Forms students write that are right and used to be refused (issue 22, part 1).

Each form is graded through the public API (values given directly, as an answer file's would be
after the jail) in several variants, right and wrong: the right ones score full marks, the wrong
ones do not, and nothing is an engine failure.
"""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.answer.reading.text import load_toml_answer
from lagrade.verdicts.checkers.base import multiplier_names
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem

t = sp.Symbol("t")
m, omega, g, l, k, M, R, F = sp.symbols("m omega g l k M R F", positive=True)
r, theta, x, y = (sp.Function(n)(t) for n in ("r", "theta", "x", "y"))


def part(result, name):
    return next(p for p in result.parts if p.part == name)


# ----------------------------------------------------------------------------- unevaluated derivatives

@pytest.mark.parametrize("value", [
    sp.Derivative(m * r**2 * omega, t),
    omega * sp.Derivative(m * r**2, t),
    sp.Derivative(m * r**2 * theta.diff(t), t).subs(theta.diff(t), omega),
    sp.Derivative(m * r**2 * omega, (t, 1)),
    sp.Derivative(m * omega * r * r, t) / 2 + sp.Derivative(m * omega * r**2 / 2, t),
])
def test_an_unevaluated_derivative_of_an_expression_is_its_value(value):
    got = part(lagrade.check("12.30", lam=value), "N")  # lam answers the part N (issue 44)
    assert got.verdict == "correct", got.feedback


def test_an_unevaluated_derivative_of_a_wrong_expression_is_wrong():
    got = part(lagrade.check("12.30", lam=sp.Derivative(m * r * omega, t)), "N")
    assert got.verdict == "incorrect", got.feedback


def test_an_unevaluated_derivative_in_an_equation_of_motion():
    eom = [sp.Eq(sp.Derivative(m * r.diff(t), t), m * r * theta.diff(t) ** 2 + m * g * sp.cos(theta)
                 - k * (r - sp.Symbol("l0"))),
           sp.Eq(sp.Derivative(m * r**2 * theta.diff(t), t), -m * g * r * sp.sin(theta))]
    got = part(lagrade.check("12.7", eom=eom), "eom")
    assert got.verdict == "correct", got.feedback


# ----------------------------------------------------------------------------- what sympy.solve returns

@pytest.mark.parametrize("value", [
    {theta.diff(t, 2): -g * sp.sin(theta) / l},
    [{theta.diff(t, 2): -g * sp.sin(theta) / l}],
    sp.solve(sp.Eq(m * l**2 * theta.diff(t, 2), -m * g * l * sp.sin(theta)), theta.diff(t, 2), dict=True),
])
def test_eom_as_the_dict_solve_returns(value):
    got = part(lagrade.check("12.43", eom=value), "eom")
    assert got.verdict == "correct", got.feedback


def test_eom_dict_with_two_accelerations_and_with_a_wrong_one():
    X, s = sp.Function("X")(t), sp.Function("s")(t)
    phi = sp.Symbol("phi", positive=True)
    rows = [sp.Eq((M + m) * X.diff(t, 2) + m * sp.cos(phi) * s.diff(t, 2), 0),
            sp.Eq(2 * s.diff(t, 2) + sp.cos(phi) * X.diff(t, 2), g * sp.sin(phi))]
    solved = sp.solve(rows, [X.diff(t, 2), s.diff(t, 2)])
    assert part(lagrade.check("12.28", eom=solved), "eom").verdict == "correct"
    wrong = {**solved, s.diff(t, 2): g * sp.sin(phi)}
    assert part(lagrade.check("12.28", eom=wrong), "eom").verdict != "correct"


def test_a_dict_eom_is_not_told_it_should_be_an_expression():
    got = part(lagrade.check("12.43", eom={theta.diff(t, 2): g * sp.sin(theta) / l}), "eom")
    assert got.verdict == "incorrect" and "not a dict" not in got.feedback, got.feedback


# ----------------------------------------------------------------------------- Lagrange multipliers

def _cartesian(name: str, sign: int = 1, as_function: bool = False):
    lam = sp.Function(name)(t) if as_function else sp.Symbol(name)
    return [sp.Eq(m * x.diff(t, 2), lam * sp.sin(omega * t)),
            sp.Eq(m * y.diff(t, 2), -sign * lam * sp.cos(omega * t)),
            sp.Eq(x * sp.sin(omega * t) - y * sp.cos(omega * t), 0)]


@pytest.mark.parametrize("name, as_function", [("lam", False), ("lambda_1", False), ("lam", True), ("mu", False),
                                               ("lam2", False)])
def test_equations_with_multipliers_and_the_constraint(name, as_function):
    got = part(lagrade.check("12.30", eom_xy=_cartesian(name, as_function=as_function)), "eom_xy")
    assert got.verdict == "correct", got.feedback


def test_equations_with_multipliers_that_are_wrong_once_eliminated():
    got = part(lagrade.check("12.30", eom_xy=_cartesian("lam", sign=-1)), "eom_xy")
    assert got.verdict == "incorrect", got.feedback
    # the equations graded are the student's after elimination: named by acceleration, not by number
    assert got.feedback.startswith("Once the multipliers (lam) are eliminated") and "equation 1" not in got.feedback


def test_the_constraint_may_be_left_out_or_given_as_y_equals():
    rows = _cartesian("lam")[:2] + [sp.Eq(y, x * sp.tan(omega * t))]
    assert part(lagrade.check("12.30", eom_xy=rows), "eom_xy").verdict == "correct"
    assert part(lagrade.check("12.30", eom_xy=_cartesian("lam")[:2]), "eom_xy").verdict == "correct"


def test_polar_equations_with_the_torque_as_a_multiplier():
    lam = sp.Symbol("lam")
    rows = [m * r.diff(t, 2) - m * r * theta.diff(t) ** 2,
            sp.Eq(sp.Derivative(m * r**2 * theta.diff(t), t), lam), sp.Eq(theta, omega * t)]
    assert part(lagrade.check("12.30", eom=rows), "eom").verdict == "correct"


def test_rolling_kept_as_a_constraint_with_its_multiplier():
    lam = sp.Symbol("lambda_1")
    phi = sp.Function("phi")(t)
    rows = [sp.Eq(M * x.diff(t, 2), F + lam), sp.Eq(M * R**2 / 2 * phi.diff(t, 2), -R * lam), sp.Eq(x, R * phi)]
    assert part(lagrade.check("12.2", eom=rows), "eom").verdict == "correct"
    rows[1] = sp.Eq(M * R**2 / 2 * phi.diff(t, 2), R * lam)
    assert part(lagrade.check("12.2", eom=rows), "eom").verdict == "incorrect"


def test_a_multiplier_that_cannot_be_eliminated_is_named():
    rows = [sp.Eq(m * x.diff(t, 2), sp.Symbol("lam") ** 2)]
    got = part(lagrade.check("12.30", eom_xy=rows), "eom_xy")
    assert got.verdict == "invalid" and "lam" in got.feedback and "linearly" in got.feedback, got.feedback


def test_a_parameter_named_like_a_multiplier_stays_the_parameter():
    problem = load_problem("12.35")  # mu is the friction coefficient there
    mech = references(problem)[problem.part("eom").system]
    expr = sp.Symbol("mu") * sp.Symbol("lam") + sp.Symbol("nu_1")
    assert multiplier_names(expr, mech, problem.part("eom")) == {"lam", "nu_1"}


# ----------------------------------------------------------------------------- generalized forces as symbols

def test_generalized_forces_left_as_symbols():
    th, ph = theta, sp.Function("phi")(t)
    L = m * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2 + r**2 * sp.sin(th) ** 2 * ph.diff(t) ** 2) / 2
    Q = sp.symbols("Q_r Q_theta Q_phi")
    rows = [sp.Eq(L.diff(q.diff(t)).diff(t) - L.diff(q), Qi) for q, Qi in zip((r, th, ph), Q)]
    assert part(lagrade.check("12.9", eom_a=rows), "eom_a").verdict == "correct"
    swapped = [sp.Eq(L.diff(q.diff(t)).diff(t) - L.diff(q), Qi) for q, Qi in zip((r, th, ph), (Q[0], Q[2], Q[1]))]
    assert part(lagrade.check("12.9", eom_a=swapped), "eom_a").verdict != "correct"
    a = sp.Symbol("a", positive=True)
    got = part(lagrade.check("12.34", eom=sp.Eq(m * a**2 * theta.diff(t, 2), sp.Symbol("Q_theta"))), "eom")
    assert got.verdict == "correct", got.feedback


def test_a_generalized_force_symbol_where_the_scene_has_none_is_unknown():
    got = part(lagrade.check("12.43", eom=sp.Eq(m * l**2 * theta.diff(t, 2), sp.Symbol("Q_theta"))), "eom")
    assert got.verdict == "invalid" and "Q_theta" in got.feedback, got.feedback


# ----------------------------------------------------------------------------- yes / no

@pytest.mark.parametrize("word, verdict", [("no", "correct"), ("No", "correct"), ("false", "correct"),
                                           ("yes", "incorrect"), ("YES", "incorrect")])
def test_yes_no_in_words(word, verdict, tmp_path):
    answer = tmp_path / "answer.toml"
    answer.write_text(f'H_conserved = "{word}"\n')
    assert part(lagrade.check("12.12", answer), "H_conserved").verdict == verdict
    assert part(lagrade.check("12.12", H_conserved=word), "H_conserved").verdict == verdict


def test_yes_no_words_do_not_shadow_a_name(tmp_path):
    path = tmp_path / "a.toml"
    path.write_text('x = "no"\ny = "no + 1"\n')
    values, problems = load_toml_answer(path, [], ["no"])
    assert values["x"] == sp.Symbol("no") and not problems


# ----------------------------------------------------------------------------- re(t), im(t)

def _complex_solution(sign=1):
    r0, v0 = sp.symbols("r0 v0", positive=True)
    sin_wt = (sp.exp(sp.I * omega * t) - sp.exp(-sp.I * omega * t)) / (2 * sp.I)
    sol = (r0 * sp.cosh(omega * t) + (v0 / omega - g / (2 * omega**2)) * sp.sinh(omega * t)
           + sign * g * sin_wt / (2 * omega**2))
    return {"r": sp.expand(sol, complex=True)}


def test_expand_complex_leaves_re_and_im_of_real_quantities():
    value = _complex_solution()
    assert value["r"].has(sp.re) and value["r"].has(sp.im)
    got = part(lagrade.check("12.12", solution=value), "solution")
    assert got.verdict == "correct", got.feedback


def test_expand_complex_of_a_wrong_solution_is_graded_not_an_engine_failure():
    got = part(lagrade.check("12.12", solution=_complex_solution(-1)), "solution")
    assert got.verdict == "incorrect" and "report" not in got.feedback, got.feedback


def test_re_of_a_complex_exponential_keeps_its_meaning():
    x0 = sp.Symbol("x0")
    w = sp.sqrt(k / m)
    value = {"x": sp.re(x0 * sp.exp(sp.I * w * t)) + sp.re(sp.Symbol("v0") / w * sp.exp(sp.I * (w * t - sp.pi / 2)))}
    got = part(lagrade.check("12.42", solution=value), "solution")
    assert got.verdict == "correct", got.feedback


def test_hamiltons_equations_as_a_dict():
    p = sp.Function("p_theta")(t)
    value = {theta.diff(t): p / (m * l**2), p.diff(t): -m * g * l * sp.sin(theta)}
    assert part(lagrade.check("12.43", hamilton=value), "hamilton").verdict == "correct"
    value[p.diff(t)] = m * g * l * sp.sin(theta)
    assert part(lagrade.check("12.43", hamilton=value), "hamilton").verdict == "partial"
