"""Feedback may say which term is missing or which equation is wrong, never give a reference away.

Every named-mistake message of every part of every problem, and the feedback of every wrong golden
answer of every problem (graded with ``--hints``), is checked by `leaks.reveals`: textually against
the references as written, and mathematically, by parsing each expression the message quotes and
comparing it with every reference value of the problem at sampled states (no minimum length: a
reference such as -F/3 has four characters).
"""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from leaks import fragments, reveals

import lagrade
from lagrade.problem.library import load_problem, problem_ids

ROOT = Path(__file__).resolve().parents[1]

PARTS = [pytest.param(pid, part.name, id=f"{pid}-{part.name}")
         for pid in problem_ids() for part in load_problem(pid).parts]


@pytest.mark.parametrize("pid, part_name", PARTS)
def test_no_named_mistake_message_gives_a_reference_away(pid, part_name):
    for mistake in load_problem(pid).part(part_name).mistakes:
        assert not reveals(pid, mistake.message), f"{mistake.message!r}: {reveals(pid, mistake.message)}"


WRONG = [pytest.param(pid, f, id=f"{pid}/{f.name}") for pid in problem_ids()
         for f in sorted((ROOT / "tests" / "answers" / pid).glob("wrong_*.*"))]


@pytest.mark.slow
@pytest.mark.parametrize("pid, path", WRONG)
def test_graded_feedback_never_gives_a_reference_away(pid, path):
    result = lagrade.check(pid, path, hints=True)
    for part in result.parts:
        assert not reveals(pid, part.feedback), f"{part.part}: {part.feedback!r}: {reveals(pid, part.feedback)}"


# Messages the problem files used to carry (issue 22): each gave a reference away.
OLD_LEAKS = [
    ("12.2", ("The friction force opposes F (it supplies the torque that spins the cylinder up while slowing "
              "its translation): lam = -F/3.")),
    ("12.2", "The friction force is lam = -(F/3)."),  # the same value, written differently
    ("12.2", "Friction: lam = F*(-1/3), i.e. a third of the applied force."),
    ("12.30", ("x'' = 0 would hold for a free particle; on the wire only the component of the acceleration "
               "along the wire vanishes: x''*cos(omega*t) + y''*sin(omega*t) = 0.")),
    ("12.30", "The wire must push the bead sideways: N = 2*m*omega*r'."),
    ("12.39", "the Legendre transform gives H' = p_r**2/(2*m) + p_phip**2/(2*m*r**2) - omega*p_phip + k*r**2/2."),
    ("12.49", "H - E = -m*k**2."),
    ("12.28", "rotational kinetic energy (1/2)(m*r_h**2)(s'/r_h)**2 = m*s'**2/2."),
    ("ex12.8", "p_x1 = (M + m)*x1' + m*cos(theta)*x2' and p_x2 = m*(x2' + cos(theta)*x1') are coupled"),
]


@pytest.mark.parametrize("pid, message", OLD_LEAKS, ids=[f"{p}-{i}" for i, (p, _) in enumerate(OLD_LEAKS)])
def test_the_check_catches_an_old_leaking_message(pid, message):
    assert reveals(pid, message), message


def test_naming_the_physics_is_not_a_leak():
    assert not reveals("12.2", "Check the sign and size of the friction force: it opposes F.")
    assert not reveals("12.30", "x'' = 0 would hold for a free particle.")  # naming x'' is not its value
    assert "2*m*omega*r_d" in fragments("so N = 2*m*omega*r'.", {"m", "omega", "r"})


def test_hints_name_the_missing_term_without_its_coefficient():
    t = sp.Symbol("t")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    w1, w2 = th1.diff(t), th2.diff(t)
    L = ((m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2)
         + (m1 + m2) * g * l1 * sp.cos(th1))  # the lower bob's potential energy is missing
    feedback = lagrade.check("12.14", L=L, hints=True).parts[0].feedback
    assert "a potential term in theta2 is missing" in feedback, feedback
    assert "m2*g*l2" not in feedback and "g*l2*m2" not in feedback
    assert "Hint" not in lagrade.check("12.14", L=L).parts[0].feedback  # only with --hints


def _L14(extra=0, factor_term=None, factor=1):
    t = sp.Symbol("t")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    w1, w2 = th1.diff(t), th2.diff(t)
    terms = [(m1 + m2) / 2 * l1**2 * w1**2, m2 / 2 * l2**2 * w2**2, m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2),
             (m1 + m2) * g * l1 * sp.cos(th1), m2 * g * l2 * sp.cos(th2)]
    if factor_term is not None:
        terms[factor_term] *= factor
    return sp.Add(*terms) + extra


def test_hint_for_an_extra_term_quotes_the_students_term():
    t = sp.Symbol("t")
    extra = sp.Symbol("m1") * sp.Function("theta1")(t) ** 2
    feedback = lagrade.check("12.14", L=_L14(extra=extra), hints=True).parts[0].feedback
    assert "your term m1*theta1**2 should not be there" in feedback, feedback


def test_hint_for_a_wrong_factor_and_a_wrong_sign():
    """The hint names the wrong term, never which way it is off: "too large" after one check and "too
    small" after the next would bisect the reference's coefficient (issue 42, item 5)."""
    for factor in (2, sp.Rational(7, 9), sp.Rational(101, 100), sp.Rational(99, 100)):
        feedback = lagrade.check("12.14", L=_L14(factor_term=1, factor=factor), hints=True).parts[0].feedback
        assert "not the right size" in feedback, feedback
        assert not any(w in feedback for w in ("too large", "too small", "2 times", "9/7")), feedback
    feedback = lagrade.check("12.14", L=_L14(factor_term=4, factor=-1), hints=True).parts[0].feedback
    assert "has the wrong sign" in feedback, feedback


VALUE_PARTS = [pytest.param(pid, part.name, id=f"{pid}-{part.name}") for pid in problem_ids()
               for part in load_problem(pid).parts if part.kind in ("expression", "expression_set", "equation_root")]


@pytest.mark.parametrize("pid, part_name", VALUE_PARTS)
def test_feedback_on_a_scaled_reference_gives_nothing_away(pid, part_name):
    """Every result part, answered with its reference off by a factor (one entry of a dict or list):
    what the checker composes names the factor, never the value."""
    from lagrade.answer.reading.load import LoadedAnswer
    from lagrade.verdicts.grade import grade_values
    from test_named_mistakes import _as_answer

    problem = load_problem(pid)
    part = problem.part(part_name)
    value = _as_answer(problem, part, part.reference)
    if isinstance(value, dict):
        first = next(iter(value))
        value = {**value, first: 3 * value[first] + 1}
    elif isinstance(value, list):
        value = [3 * value[0] + 1, *value[1:]]
    else:
        value = 3 * value
    graded = grade_values(problem, LoadedAnswer(values={part.name: value}), only=[part.name]).parts[0]
    assert graded.verdict != "correct", graded.feedback
    assert not reveals(pid, graded.feedback), f"{graded.feedback!r}: {reveals(pid, graded.feedback)}"
