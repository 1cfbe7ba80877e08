"""The reference's linearization is derived once per part and shared by every answer graded after."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.answer.reading.load import load_answer
from lagrade.verdicts.grade import grade_values, references
from lagrade.problem.library import load_problem, problem_path

ANSWERS = Path(__file__).parent / "answers" / "12.14"
FILES = ["correct_exact_for_linearized.py", "correct_plain.toml", "wrong_V_upper_mass_only.py",
         "wrong_uncoupled_frequencies.toml"]


def _eom(problem, answer) -> tuple:
    part, = grade_values(problem, answer, only=["eom"], read_as=()).parts
    return part.verdict, part.score, part.feedback


@pytest.mark.parametrize("first", FILES)
def test_a_shared_linearization_grades_as_a_fresh_one(first, monkeypatch):
    monkeypatch.setattr("lagrade.verdicts.grade._REFERENCES", {})  # nothing derived in this process yet
    monkeypatch.setattr("lagrade.derive.cache.load", lambda problem: None)  # nor on disk
    problem = load_problem(problem_path("12.14"))
    answers = {f: load_answer(ANSWERS / f, problem) for f in FILES}
    alone = {f: _eom(problem, answers[f]) for f in FILES}  # graded before the part is shared ...
    assert any(m.linearized for m in references(problem).systems.values())
    monkeypatch.setattr("lagrade.verdicts.grade._REFERENCES", {})
    problem = load_problem(problem_path("12.14"))
    _eom(problem, answers[first])  # ... and after `first` made it
    assert {f: _eom(problem, answers[f]) for f in FILES} == alone
