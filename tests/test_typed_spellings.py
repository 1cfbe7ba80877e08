"""Typed answers: a coordinate's rate may be written as the book writes it (theta1'), and a spelling
that cannot be read gets a message naming the spellings that can."""

from __future__ import annotations

import pytest

from lagrade.problem.library import load_problem
from lagrade.uses.server.answers import preview


@pytest.fixture(scope="module")
def p1214():
    return load_problem("12.14")


def read(problem, value):
    out = preview(problem, "L", value)
    return out.get("text") or out["error"]


def test_primes_are_the_rates_of_a_coordinate(p1214):
    assert read(p1214, "m1*l1**2*theta1'**2/2") == read(p1214, "m1*l1**2*theta1_d**2/2")
    assert read(p1214, "m1*theta1''") == read(p1214, "m1*theta1_dd")
    assert "Derivative(theta1(t), t)" in read(p1214, "{'theta1': theta1'}")  # a quoted key stays a key


@pytest.mark.parametrize("typed", ["m1*x'**2", "thetadot1**2", "dtheta1**2", "theta_1_dot"])
def test_a_spelling_not_read_names_the_accepted_ones(p1214, typed):
    said = read(p1214, typed)
    assert "theta1' (also theta1_d, theta1_dot or theta1dot)" in said, said
    assert "unterminated string" not in said and "theta2dot" not in said and "p_theta1" not in said


def test_the_help_before_typing_names_spellings_that_are_read(p1214):
    """The page's and the API's typing help (describe.typing_help): every spelling it names is read,
    as the same rate; its power and equation forms too."""
    import re

    from lagrade.problem.describe import typing_help

    said = typing_help(p1214)
    assert "theta1' (also theta1_d, theta1_dot or theta1dot)" in said and "theta2'" in said
    for rate in re.findall(r"\btheta1(?:_d|_dot|dot|')(?![\w'])", said):
        assert read(p1214, f"m1*{rate}^2") == read(p1214, "m1*theta1_d**2"), rate
    for rate in re.findall(r"\btheta1(?:_dd|_ddot|ddot|'')(?!\w)", said):
        assert read(p1214, f"m1*{rate}") == read(p1214, "m1*theta1_dd"), rate
    assert "x^2 or x**2" in said and read(p1214, "m1^2") == read(p1214, "m1**2")
    assert "Eq(lhs, rhs) or lhs == rhs" in said
    assert read(p1214, "Eq(m1, m2)") == read(p1214, "m1 == m2")


def test_lagrade_show_says_how_to_type_before_the_first_try(tmp_path):
    """`lagrade show` (and `show --server`, the same text) ends with the typing help, so a student
    writing answer.toml reads the spellings before an error has to name them."""
    from click.testing import CliRunner

    from lagrade.cli import main

    out = CliRunner().invoke(main, ["show", "12.14"]).output
    assert "Typing an answer (answer.toml, the course page):" in out
    assert "theta1' (also theta1_d, theta1_dot or theta1dot)" in out
