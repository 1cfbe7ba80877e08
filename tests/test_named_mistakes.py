"""Every named mistake in every problem file is recognised, and its message reaches the student.

The golden answer for each mistake is the mistake itself, turned into what a student would bind:
coordinates as functions of time, and any derived quantity the instructor wrote it with (an
acceleration ``x_dd``, a multiplier ``lam``) replaced by its expression in the state. The feedback
it gets must not give a reference away (`leaks.reveals`).
"""

from __future__ import annotations

import pytest
import sympy as sp
from leaks import reveals

from lagrade.answer.reading.load import LoadedAnswer
from lagrade.verdicts.checkers.values import _symbolic_reference
from lagrade.verdicts.grade import grade_values, references
from lagrade.problem.library import load_problem, problem_ids
from lagrade.problem.symbols import T


def _cases():
    for pid in problem_ids():
        problem = load_problem(pid)
        for part in problem.parts:
            for k, _ in enumerate(part.mistakes):
                yield pytest.param(pid, part.name, k, id=f"{pid}-{part.name}-{k}")


def _student_form(expr: sp.Basic, mech) -> sp.Basic:
    """State symbols back to functions of time, as in an answer file."""
    back = {}
    for name in mech.all_names:
        f = sp.Function(name)(T)
        back[sp.Symbol(name)] = f
        back[sp.Symbol(f"{name}_d")] = f.diff(T)
        back[sp.Symbol(f"{name}_dd")] = f.diff(T, 2)
        back[sp.Symbol(f"p_{name}")] = sp.Function(f"p_{name}")(T)
    return expr.xreplace(back)


def _as_answer(problem, part, text):
    if isinstance(text, dict):
        return {key: _as_answer(problem, part, v) for key, v in text.items()}
    if isinstance(text, list):
        return [_as_answer(problem, part, v) for v in text]
    mech = references(problem)[part.system]
    extra = [*part.symbols, *(str(m) for m in mech.multipliers), *(str(p) for p in mech.s.p),
             *(f"delta_{n}" for n in mech.all_names)]
    expr = mech.parse(str(text), extra)
    derived = set(mech.multipliers) | set(mech.constrained)
    if part.kind not in ("eom",) and expr.free_symbols & (derived | set(mech.s.qdd)):
        expr = _symbolic_reference(expr, mech, 60.0)
    return _student_form(expr, mech)


@pytest.mark.parametrize("pid, part_name, index", list(_cases()))
def test_named_mistake_is_recognised(pid, part_name, index):
    problem = load_problem(pid)
    part = problem.part(part_name)
    mistake = part.mistakes[index]
    answer = LoadedAnswer(values={part.name: _as_answer(problem, part, mistake.answer)})
    result = grade_values(problem, answer, only=[part.name])
    graded = result.parts[0]
    assert graded.verdict != "correct", f"the named mistake scores full marks: {mistake.answer}"
    assert mistake.message in graded.feedback, graded.feedback
    assert not reveals(pid, graded.feedback), f"the feedback gives a reference away: {reveals(pid, graded.feedback)}"
