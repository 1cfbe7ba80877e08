"""Plain-text answers parse into the same sympy objects a Python answer would give."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.answer.reading.text import TextAnswerError, load_toml_answer, parse_math

t = sp.Symbol("t")
theta = sp.Function("theta")(t)
phi = sp.Function("phi")(t)
m, g, l, k = sp.symbols("m g l k")
C = ["theta", "phi"]


def test_pendulum_lagrangian():
    got = parse_math("m*l**2*theta_d**2/2 + m*g*l*cos(theta)", C)
    assert got == m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta)


@pytest.mark.parametrize("text", ["theta_d", "theta_dot", "thetadot", "Derivative(theta(t), t)",
                                  "diff(theta, t)", "Derivative(theta, t)"])
def test_first_derivative_spellings(text):
    assert parse_math(text, C) == theta.diff(t)


@pytest.mark.parametrize("text", ["theta_dd", "theta_ddot", "thetaddot", "Derivative(theta(t), (t, 2))",
                                  "diff(theta(t), t, 2)", "Derivative(theta, t, t)"])
def test_second_derivative_spellings(text):
    assert parse_math(text, C) == theta.diff(t, 2)


def test_caret_is_power_and_integers_are_exact():
    assert parse_math("x^2 + 1/2", C) == sp.Symbol("x") ** 2 + sp.Rational(1, 2)
    assert parse_math("2^10", C) == 1024
    assert parse_math("Rational(1, 3)*pi", C) == sp.pi / 3
    assert parse_math("0.5*k", C) == sp.Float("0.5") * k
    assert parse_math("-(m)", C) == -m


def test_e_and_i_are_symbols_and_exp1_is_euler():
    assert parse_math("E + e + I", C) == sp.Symbol("E") + sp.Symbol("e") + sp.Symbol("I")
    assert parse_math("exp(1)", C) == sp.E


def test_coordinate_call_and_momenta():
    assert parse_math("theta(t) + phi", C) == theta + phi
    assert parse_math("p_theta**2/(2*m*l**2)", C) == sp.Symbol("p_theta") ** 2 / (2 * m * l**2)


def test_equations_and_lists():
    got = parse_math("[theta_dd == -g/l*sin(theta), Eq(phi_dd, 0)]", C)
    assert got == [sp.Eq(theta.diff(t, 2), -g / l * sp.sin(theta)), sp.Eq(phi.diff(t, 2), 0)]
    assert parse_math("m*theta_dd == 0", C) == sp.Eq(m * theta.diff(t, 2), 0)


def test_dicts_and_bools():
    got = parse_math('{"r": m*g, "theta": 0, "ok": True}', C)
    assert got == {"r": m * g, "theta": 0, "ok": True}
    assert parse_math("True", C) is True


def test_unknown_name_suggestion():
    with pytest.raises(TextAnswerError, match=r"unknown name 'thta' \(did you mean 'theta'\?\)"):
        parse_math("m*thta", C, known_names=["m"])
    assert parse_math("m*g", C, known_names=["m", "g"]) == m * g


def test_unknown_function_suggestion():
    with pytest.raises(TextAnswerError, match=r"unknown function 'sinn' \(did you mean 'sin'\?\)"):
        parse_math("sinn(theta)", C)


@pytest.mark.parametrize("text, fragment", [
    ("__class__", "double underscores"),
    ("theta.__class__", "attribute"),
    ("m.subs(m, 1)", "attribute"),
    ("open('/etc/passwd')", "unknown function 'open'"),
    ("__import__('os')", "unknown function"),
    ("lambda: 1", "lambda"),
    ("[x for x in (1, 2)]", "comprehension"),
    ("m < g", "only single equations"),
    ("1 + (m == g)", "'=='"),
    ("2 ** 10 ** 10", "number too large"),
    ("m if g else l", "not a supported formula"),
    ("9" * 70, "integer too large"),
    ("sin", "is a function"),
    ("'text'", "unexpected literal"),
    ("x @ y", "not supported"),
    ("m +", "not well formed"),
    ("sin(" * 200 + "m" + ")" * 200, "nested too deeply"),
    ("Derivative(theta, (t, 10**6))", "derivative order"),
])
def test_rejections(text, fragment):
    with pytest.raises(TextAnswerError) as info:
        parse_math(text, C)
    assert fragment in str(info.value), str(info.value)


def test_load_toml_answer(tmp_path):
    path = tmp_path / "answer.toml"
    path.write_text(
        '# pendulum\n'
        'L = "m*l^2*theta_d^2/2 + m*g*l*cos(theta)"\n'
        'H = "p_theta^2/(2*m*l^2) - m*g*l*cos(thta)"\n'
        'eom = ["theta_dd == -g/l*sin(theta)"]\n'
        'bad_list = ["m", "sin("]\n'
        'dof = 1\n'
        'cyclic = false\n'
        '\n'
        '[tensions]\n'
        'T = "m*g"\n'
        'N = "open(1)"\n'
    )
    values, problems = load_toml_answer(path, ["theta"], ["m", "g", "l", "p_theta"])
    assert values["L"] == m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta)
    assert values["eom"] == [sp.Eq(theta.diff(t, 2), -g / l * sp.sin(theta))]
    assert values["dof"] == 1 and values["cyclic"] is False
    assert "H" not in values and "bad_list" not in values and "tensions" not in values
    by_line = {p.line: str(p) for p in problems}
    assert set(by_line) == {3, 5, 11}, problems
    assert "answer.toml:3: H: unknown name 'thta' (did you mean 'theta'?)" == by_line[3]
    assert "item 2" in by_line[5]
    assert "unknown function 'open'" in by_line[11]


def test_load_toml_syntax_error(tmp_path):
    path = tmp_path / "answer.toml"
    path.write_text('L = "m"\nH = \n')
    values, problems = load_toml_answer(path, ["theta"], None)
    assert values == {} and len(problems) == 1 and problems[0].line == 2
