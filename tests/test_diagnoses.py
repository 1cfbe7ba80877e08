"""Diagnoses that are right, or none (issue 22, part 4).

A factor is said only when it names a slip (2, 1/2, 3/2), never "1 times" and never a factor that
would give the reference away (1.0001), nor anything relational about a number; a generic diagnosis of L is given
only when the student's own L bears it out; feedback names no coordinate the student did not use,
lists no internal names, and says in words why equations cannot be integrated.
"""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.verdicts.checkers.base import factor_text

t = sp.Symbol("t")
M, R, F, m, g, l, a = sp.symbols("M R F m g l a", positive=True)
phi = sp.Function("phi")(t)


def part(result, name):
    return next(p for p in result.parts if p.part == name)


@pytest.mark.parametrize("c, said", [(1.0001, None), (0.5, "1/2"), (2.0, "2"), (2 / 3, None), (-1.5, None),
                                     (0.9999, None), (1 + 1e-7, None), (3.14159, None)])
def test_a_factor_is_said_only_when_it_names_a_slip(c, said):
    assert factor_text(c) == said


def test_a_factor_indistinguishable_from_one_is_not_said():
    assert factor_text(1.0) is None and factor_text(float("nan")) is None


def test_a_period_a_hair_too_long_is_not_called_1_times_the_correct_value():
    period = 2 * sp.pi * sp.sqrt(l / (g + a))
    got = part(lagrade.check("12.10", period=period * 1.0001), "period")
    assert got.verdict == "incorrect"
    assert "1.0001" not in got.feedback and " 1 times" not in got.feedback, got.feedback
    assert "constant factor" in got.feedback, got.feedback


def test_nothing_relational_is_said_about_a_number():
    """12.33's leaving angle is a number: "1.00004 times" or "the wrong sign" would give it away."""
    for value in (sp.acos(sp.Rational(2, 3)) * 1.00004, -sp.acos(sp.Rational(2, 3)), 2 * sp.acos(sp.Rational(2, 3))):
        got = part(lagrade.check("12.33", leave_angle=value), "leave_angle")
        assert got.verdict == "incorrect" and got.feedback == "Incorrect: theta is not equal to the correct result.", \
            got.feedback


def test_a_generic_diagnosis_is_checked_against_the_students_L():
    T = sp.Rational(3, 4) * M * R**2 * phi.diff(t) ** 2
    # the applied force added to L as a potential: its Lagrange equation is that of T/2 scaled by 2,
    # but its kinetic energy is right, so "half" would be false
    got = part(lagrade.check("12.2", L=T + F * R * phi), "L")
    assert got.verdict == "incorrect" and "half" not in got.feedback, got.feedback
    half = part(lagrade.check("12.2", L=T / 2), "L")
    assert "the kinetic energy is half what it should be" in half.feedback, half.feedback


def test_unknown_names_list_only_the_problems_own_names():
    got = part(lagrade.check("12.43", eom=sp.Eq(sp.Symbol("q") * sp.Function("theta")(t).diff(t, 2), 0)), "eom")
    assert got.verdict == "invalid"
    assert "p_theta" not in got.feedback and "delta_" not in got.feedback, got.feedback


def test_singular_equations_are_explained_in_words():
    X, s = sp.Function("X")(t), sp.Function("s")(t)
    got = part(lagrade.check("12.28", eom=[X.diff(t, 2) + s.diff(t, 2), 2 * X.diff(t, 2) + 2 * s.diff(t, 2)]), "eom")
    assert got.verdict == "incorrect"
    for jargon in ("step size", "trajectory 0", "integration failed", "DOP853"):
        assert jargon not in got.feedback, got.feedback
    assert "cannot be integrated from the initial state" in got.feedback, got.feedback


def test_a_wrong_equation_is_not_labelled_with_an_acceleration_it_does_not_contain():
    X, s = sp.Function("X")(t), sp.Function("s")(t)
    ph = sp.Symbol("phi", positive=True)
    rows = [sp.Eq((M + m) * X.diff(t, 2), 0), sp.Eq(2 * s.diff(t, 2) + sp.cos(ph) * X.diff(t, 2), g * sp.sin(ph))]
    got = part(lagrade.check("12.28", eom=rows), "eom")  # equation 1 lacks the hoop's s'' term
    assert "Equation 1 (the one mainly for X'')" in got.feedback and "s''" not in got.feedback, got.feedback


def test_a_coordinate_the_student_left_out_is_not_named():
    theta = sp.Function("theta")(t)
    L = m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta)  # the car's X is missing altogether
    got = part(lagrade.check("12.46", L=L), "L")
    assert got.verdict == "incorrect" and "X" not in got.feedback, got.feedback
    assert "leaves out a coordinate" in got.feedback
