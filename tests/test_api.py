"""The Python API: parts given directly as sympy objects, and the result model."""

from __future__ import annotations

import sympy as sp

import lagrade

t = sp.Symbol("t")
m, l, g = sp.symbols("m l g", positive=True)
theta = sp.Function("theta")(t)
p_theta = sp.Function("p_theta")(t)


def test_parts_given_directly():
    r = lagrade.check("12.43", H=p_theta**2 / (2 * m * l**2) - m * g * l * sp.cos(theta))
    assert r.verdicts() == {"H": "correct", "hamilton": "missing", "eom": "missing"}
    assert r.score == 1.0 and r.max_score == 3.0


def test_result_renders_as_table_and_html():
    r = lagrade.check("12.43", eom=sp.Eq(theta.diff(t, 2), -g / l * sp.sin(theta)))
    text = str(r)
    assert "eom" in text and "correct" in text and "total 1 / 3" in text
    assert "<table>" in r._repr_html_()


def test_unknown_part_name_is_a_type_error():
    try:
        lagrade.check("12.43", Hamiltonian=0)
    except TypeError as exc:
        assert "no part 'Hamiltonian'" in str(exc)
    else:
        raise AssertionError("expected TypeError")


def test_plain_symbol_coordinate_in_L_is_invalid_with_a_suggestion():
    th = sp.Symbol("theta")
    r = lagrade.check("12.1", L_c=m * l**2 * sp.Symbol("theta_dot") ** 2 / 2 + m * g * l * sp.cos(th))
    part = r.parts[[p.part for p in r.parts].index("L_c")]
    assert part.verdict == "invalid"
    assert "Function('theta')(t)" in part.feedback


def test_unknown_symbol_is_invalid_not_wrong():
    r = lagrade.check("12.43", H=sp.Symbol("p_thta") ** 2 / (2 * m * l**2) - m * g * l * sp.cos(theta))
    assert r.parts[0].verdict == "invalid"
    assert "did you mean 'p_theta'" in r.parts[0].feedback
