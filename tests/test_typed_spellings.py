"""Typed answers: a coordinate's rate may be written as the book writes it (theta1'), and a spelling
that cannot be read gets a message naming the spellings that can."""

from __future__ import annotations

import pytest

from lagrade.library import load_problem
from lagrade.server.answers import preview


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
