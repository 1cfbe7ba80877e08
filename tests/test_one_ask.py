"""One ask, one part (issue 44): where the book asks one thing the catalogue answers under two names
(12.30's "constraining force": the multiplier lam, a torque, or the force N; 12.33's "reaction": lam or
N), either name answers the one counted part, and the name a value is bound to still says what it is."""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.problem.library import load_problem
from lagrade.problem.spec import Part

t = sp.Symbol("t")
m, omega, g, R, r_s = sp.symbols("m omega g R r_s")
r, theta = sp.Function("r")(t), sp.Function("theta")(t)
TORQUE = 2 * m * omega * r * r.diff(t)
FORCE = 2 * m * omega * r.diff(t)


def part(result, name):
    return next(p for p in result.parts if p.part == name)


def test_the_two_names_are_one_counted_part():
    for pid in ("12.30", "12.33"):
        problem = load_problem(pid)
        assert problem.part("lam") is problem.part("N") and not problem.part("N").extra


@pytest.mark.parametrize(("name", "value"), [("lam", TORQUE), ("N", FORCE)])
def test_1230_either_name_answers_the_constraining_force(name, value):
    got = lagrade.check("12.30", **{name: value}, only=["N"])
    assert part(got, "N").verdict == "correct" and got.score == got.max_score == 1


@pytest.mark.parametrize(("name", "value", "says"), [
    ("N", TORQUE, "torque about the axis"),       # the torque is not the force
    ("lam", FORCE, ""),                           # nor the force the torque
    ("lam", m * omega * r * r.diff(t), "factor 2"),  # lam's own named mistake, under its name
])
def test_1230_the_name_says_which_quantity_the_value_is(name, value, says):
    got = part(lagrade.check("12.30", **{name: value}, only=["N"]), "N")
    assert got.verdict == "incorrect" and says in got.feedback


@pytest.mark.parametrize("value", [m * g * (3 * sp.cos(theta) - 2),
                                   m * g * sp.cos(theta) - m * (R + r_s) * theta.diff(t) ** 2])
@pytest.mark.parametrize("name", ["lam", "N"])
def test_1233_the_reaction_in_either_name_and_either_form(name, value):
    got = lagrade.check("12.33", **{name: value}, only=["N"])
    assert part(got, "N").verdict == "correct" and got.score == got.max_score


def test_both_names_in_a_file_the_parts_own_name_is_graded(tmp_path):
    """Bound to both, the part's own name wins (as a version's own name does), and the answer is told."""
    path = tmp_path / "answer.toml"
    path.write_text('N = "2*m*omega*r*r_d"\nlam = "2*m*omega*r*r_d"\n')
    got = lagrade.check("12.30", path, only=["N"])
    assert part(got, "N").verdict == "incorrect"  # N, a torque: the name N is graded, not lam
    assert any("'lam' and 'N' answer the same part N: 'N' is graded, 'lam' ignored" in p for p in got.problems)
    path.write_text('lam = "2*m*omega*r*r_d"\nN = "2*m*omega*r_d"\n')
    assert part(lagrade.check("12.30", path, only=["N"]), "N").verdict == "correct"


def test_both_names_in_the_api_is_a_mistake_of_the_caller():
    with pytest.raises(TypeError, match="answer the same part N"):
        lagrade.check("12.30", lam=TORQUE, N=FORCE)


def test_an_alternatives_name_is_an_alias_of_its_part():
    with pytest.raises(ValueError, match="must be one of the part's aliases"):
        Part(name="N", kind="expression", reference="lam/r", alternatives=[{"name": "lam", "reference": "lam"}])
    Part(name="N", kind="expression", reference="lam/r", aliases=["lam"],
         alternatives=[{"name": "lam", "reference": "lam"}])


def test_show_says_which_name_selects_the_formulation():
    from lagrade.problem.describe import show_text

    assert "also accepted: bound to lam, the multiplier lam" in " ".join(show_text(load_problem("12.30")).split())
