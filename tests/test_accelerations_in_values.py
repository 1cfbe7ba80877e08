"""Where a statement allows q'' in a value (12.32: "theta'' may be used"), the value is evaluated on
the true motion: the reference's solved accelerations are put for q'' before comparing (issue 44 §3)."""

from __future__ import annotations

import math
import re

import pytest
import sympy as sp

from lagrade.problem.describe import show_text
from lagrade.problem.library import load_problem, problem_ids
from lagrade.verdicts.grade import check

t = sp.Symbol("t")
m, a, k, c = sp.symbols("m a k c", positive=True)
theta = sp.Function("theta")(t)
TH_D, TH_DD = theta.diff(t), theta.diff(t, 2)

#: "q'' may be used", as a statement says it
ALLOWS = re.compile(r"(\w+)'' may be used")


def _graded(pid: str, **parts) -> dict:
    return {p.part: p for p in check(pid, grading_seconds=math.inf, **parts).parts}


def test_every_statement_that_allows_q_dd_marks_its_parts():
    """The promise in words and the field the grader reads agree: a problem whose show text allows
    q'' has parts that take it, and show says so on each."""
    promised = {pid for pid in problem_ids() if ALLOWS.search(show_text(load_problem(pid)))}
    assert promised == {"12.32"}
    for pid in promised:
        takes = [p for p in load_problem(pid).parts if p.accelerations]
        assert takes, pid
        text = show_text(load_problem(pid))
        for p in takes:
            line = text.split(f"\n  {p.name:<12} ", 1)[1].split("\n  ", 2)[1]
            assert "evaluated on the true motion" in line, line


def test_the_reaction_written_with_theta_dd_is_right():
    """The book's way: R_theta = m*a*theta'', R_z = m*k*theta'' + c*k*theta (Newton along theta and z)."""
    got = _graded("12.32", R_r=c * a - m * a * TH_D**2, R_theta=m * a * TH_DD, R_z=m * k * TH_DD + c * k * theta)
    assert {n: p.verdict for n, p in got.items()} == {"R_r": "correct", "R_theta": "correct", "R_z": "correct"}, \
        {n: p.feedback for n, p in got.items()}


@pytest.mark.parametrize("accuracy", ["default", "strict"])
def test_a_wrong_use_of_theta_dd_is_wrong(accuracy):
    res = check("12.32", grading_seconds=math.inf, accuracy=accuracy,
                R_theta=-m * a * TH_DD, R_z=m * k * TH_DD - c * k * theta)
    got = {p.part: p.verdict for p in res.parts}
    assert got["R_theta"] == "incorrect" and got["R_z"] == "incorrect", got


def test_with_theta_dd_right_under_strict_accuracy_too():
    """The strict preset asks a proof: the student's q'' are replaced by the solved accelerations first."""
    res = check("12.32", grading_seconds=math.inf, accuracy="strict",
                R_theta=m * a * TH_DD, R_z=m * k * TH_DD + c * k * theta)
    got = {p.part: p.verdict for p in res.parts}
    assert got["R_theta"] == "correct" and got["R_z"] == "correct", got
