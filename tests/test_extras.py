"""Parts the book does not ask (issue 33): `extra = true` parts are graded and shown, marked by
`lagrade show`, left out of the problem's total and of `full_marks`, and counted by an assignment only
when its `parts` names them."""

from __future__ import annotations

import sympy as sp

import lagrade
from lagrade.uses.bulk.assignment import AssignedProblem, part_points, points
from lagrade.problem.describe import show_text
from lagrade.problem.library import load_problem

t = sp.Symbol("t")


def _hamilton_12_36():
    m, V = sp.Symbol("m"), sp.Function("V")
    x, p_x = sp.Function("x")(t), sp.Function("p_x")(t)
    H = p_x**2 / (2 * m) + V(x)
    return H, [sp.Eq(x.diff(t), p_x / m), sp.Eq(p_x.diff(t), -V(x).diff(x))]


def test_an_extra_is_graded_and_shown_but_not_counted():
    H, hamilton = _hamilton_12_36()
    result = lagrade.check("12.36", H=H, hamilton=hamilton)  # the book's question, without H_F, hamilton_F
    parts = {p.part: p for p in result.parts}
    assert parts["H_F"].extra and parts["H_F"].verdict == "missing"  # shown, graded
    assert not parts["H"].extra
    assert result.full_marks and result.score == result.max_score == 2
    assert load_problem("12.36").max_score == 2
    assert "H_F (extra)" in str(result)


def test_a_wrong_extra_costs_nothing_but_says_so():
    H, hamilton = _hamilton_12_36()
    m, p_x = sp.Symbol("m"), sp.Function("p_x")(t)
    result = lagrade.check("12.36", H=H, hamilton=hamilton, H_F=p_x**2 / m)  # the force F forgotten, factor 2 lost
    assert result.score == result.max_score and result.full_marks
    part = {p.part: p for p in result.parts}["H_F"]
    assert part.verdict == "incorrect" and part.max_score > 0  # graded on its own scale, shown


def test_show_marks_the_extras():
    text = show_text(load_problem("12.36"))
    row = next(line for line in text.splitlines() if line.startswith("  H_F "))
    assert "[extra:" in row
    assert "[extra:" not in next(line for line in text.splitlines() if line.startswith("  H "))


def _stored(result):
    return [{"part": p.part, "score": p.score, "max_score": p.max_score, "extra": p.extra} for p in result.parts]


def test_an_assignment_counts_an_extra_only_when_it_names_it():
    H, hamilton = _hamilton_12_36()
    stored = _stored(lagrade.check("12.36", H=H, hamilton=hamilton))  # H_F and hamilton_F missing
    plain = AssignedProblem(id="12.36", weight=10)
    assert points(plain, stored, 2.0) == (10.0, 10.0)
    asking = AssignedProblem(id="12.36", weight=10, parts={"H": 1, "hamilton": 1, "H_F": 1, "hamilton_F": 1})
    assert points(asking, stored, 2.0) == (5.0, 10.0)
    shares = dict(zip([p["part"] for p in stored], part_points(plain, stored, 2.0)))
    assert shares["H_F"] == (0.0, 0.0) and shares["H"][1] > 0
    old = [{k: v for k, v in p.items() if k != "extra"} for p in stored]  # a gradebook from before the column
    assert points(plain, old, 2.0) == (5.0, 10.0)
