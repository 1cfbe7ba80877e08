"""sympy's own names do not answer a part (issue 33): ``from sympy import *`` binds ``Q`` (the
assumptions) and ``N`` (a function). A part name (or alias) whose value is the very object sympy exports
is unanswered, without a complaint about the file, and an alias the student bound wins."""

from __future__ import annotations

import pytest
import sympy

import lagrade
from lagrade.problem.library import load_problem, problem_ids
from lagrade.answer.reading.load import is_sympys_own


def _shadowed() -> list[tuple[str, str, str]]:
    """(problem, part, name) for every part name or alias that sympy exports."""
    out = []
    for pid in problem_ids():
        for part in load_problem(pid).parts:
            out += [(pid, part.name, n) for n in (part.name, *part.aliases) if hasattr(sympy, n)]
    return out


SHADOWED = _shadowed()


def test_the_shadowed_names_are_found():
    """The list the tests below walk is not empty (12.6's Q and 12.4's N are in it)."""
    assert ("12.6", "Q_b", "Q") in SHADOWED and ("12.4", "N", "N") in SHADOWED


@pytest.mark.parametrize("pid, part, name", SHADOWED)
def test_sympys_own_object_leaves_the_part_unanswered(pid, part, name, tmp_path):
    path = tmp_path / "answer.py"
    path.write_text("from sympy import *\n")
    result = lagrade.check(pid, path)
    assert {p.part: p.verdict for p in result.parts}[part] == "missing"
    assert not any(f"'{name}'" in line for line in result.problems), result.problems


def test_an_alias_the_student_bound_wins_over_sympys_Q(tmp_path):
    path = tmp_path / "answer.py"
    path.write_text(
        "from sympy import *\n"
        "t = symbols('t')\nR, F_x, F_y = symbols('R F_x F_y')\n"
        "s, theta = Function('s')(t), Function('theta')(t)\n"
        "Q_a = {'s': -F_x*sin(s/R) + F_y*cos(s/R)}\n"
        "Q_b = {'theta': R*(-F_x*sin(theta) + F_y*cos(theta))}\n")
    result = lagrade.check("12.6", path)
    verdicts = {p.part: p.verdict for p in result.parts}
    assert verdicts["Q_a"] == verdicts["Q_b"] == "correct", result
    assert result.problems == []


def test_an_alias_the_student_bound_wins_over_sympys_N(tmp_path):
    path = tmp_path / "answer.py"
    path.write_text("from sympy import *\nm, g = symbols('m g')\ntheta = Function('theta')(symbols('t'))\n"
                    "lam = m*g*(3*cos(theta) - 2)\n")
    part = {p.part: p for p in lagrade.check("12.4", path).parts}["N"]
    assert part.verdict == "correct", part.feedback


def test_only_sympys_very_object_is_refused():
    assert is_sympys_own(sympy.Q, "Q") and is_sympys_own(sympy.N, "N")
    assert not is_sympys_own(sympy.Symbol("Q"), "Q") and not is_sympys_own({"theta": 1}, "Q")
    assert not is_sympys_own(sympy.Q, "L")  # a part not named like a sympy export: graded as given
