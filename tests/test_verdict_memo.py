"""A value graded before gets, from the memo, exactly what grading it gives, in every problem; and
nothing kept for one setting (accuracy, credit, hints) or for an engine error is handed to another."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
import sympy as sp

from lagrade.answer.reading.load import LoadedAnswer, load_answer
from lagrade.answer.jail.rebuild import expr_nodes, rebuild_nodes, rebuild_srepr
from lagrade.verdicts.checkers import CHECKERS
from lagrade.verdicts.credit import Credit
from lagrade.verdicts.grade import grade_values
from lagrade.problem.library import load_problem, problem_ids, reference_dir
from lagrade.verdicts.verdict_memo import VerdictMemo

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_named_mistakes import _as_answer  # noqa: E402



def _anew(value):
    """An equal value made of new objects, as the next student's file gives it."""
    if isinstance(value, sp.Basic):
        nodes = expr_nodes(value)
        return rebuild_nodes(nodes) if nodes is not None else rebuild_srepr(sp.srepr(value))
    if isinstance(value, (list, tuple)):
        return type(value)(_anew(v) for v in value)
    if isinstance(value, dict):
        return {_anew(k): _anew(v) for k, v in value.items()}
    return value


def _counting(monkeypatch) -> list[str]:
    calls: list[str] = []
    for kind, checker in list(CHECKERS.items()):
        def counted(ctx, part, value, _checker=checker):
            calls.append(part.name)
            return _checker(ctx, part, value)
        monkeypatch.setitem(CHECKERS, kind, counted)
    return calls


def _answers(problem):
    """The reference solution, and each part's named mistakes as an answer of that part alone."""
    yield load_answer(reference_dir() / problem.id / "answer.py", problem)
    for part in problem.parts:
        for mistake in part.mistakes:
            yield LoadedAnswer(values={part.name: _as_answer(problem, part, mistake.answer)})


@pytest.mark.parametrize("pid", problem_ids())
def test_a_value_graded_again_gets_its_verdict_from_the_memo(pid, monkeypatch):
    problem = load_problem(pid)
    answers = list(_answers(problem))
    memo = VerdictMemo()
    calls = _counting(monkeypatch)
    first = [grade_values(problem, a, read_as=(), memo=memo) for a in answers]
    graded, values = len(calls), sum(len(a.values) for a in answers)
    # a part with admissible formulations (issue 21) may be checked once per formulation
    assert graded >= values and memo.hits == 0
    again = [grade_values(problem, LoadedAnswer(values={k: _anew(v) for k, v in a.values.items()},
                                                # the name each value was bound to (12.30's lam for N)
                                                # and what reading it said are the next file's too
                                                routed=dict(a.routed), bound_as=dict(a.bound_as),
                                                problems=list(a.problems)),
                          read_as=(), memo=memo) for a in answers]
    assert len(calls) == graded, f"graded again: {calls[graded:]}"
    assert memo.hits == values
    assert [r.model_dump() for r in again] == [r.model_dump() for r in first]


@pytest.fixture(scope="module")
def pendulum():
    problem = load_problem("12.14")
    return problem, load_answer(reference_dir() / "12.14" / "answer.py", problem)


def _wrong(answer):
    """An L with an extra kinetic term (no named or generic mistake: hints name it) and the first
    equation of motion given twice (right in part: per-equation credit)."""
    t = sp.Symbol("t")
    m1, l1 = sp.symbols("m1 l1", positive=True)
    extra = m1 * l1**2 * sp.Function("theta1")(t).diff(t) ** 2
    eom = answer.values["eom"]
    return LoadedAnswer(values={**answer.values, "L": answer.values["L"] + extra, "eom": [eom[0], eom[0]]})


def _by_motion(answer):
    """The right L plus a constant outside the exact class (atan(2); log(2) is inside it): the motion decides it, and what it
    is told names the preset's tolerances (the exact judge's verdicts do not depend on them)."""
    m1, l1, g = sp.symbols("m1 l1 g", positive=True)
    return LoadedAnswer(values={**answer.values, "L": answer.values["L"] + g * l1 * m1 * sp.atan(2)})


def _feedback(result):
    return [(p.part, p.verdict, p.score, p.feedback.split(" evaluations, ")[0]) for p in result.parts]


@pytest.mark.parametrize("setting", [{"accuracy": "fast"}, {"hints": True},
                                     {"credit": Credit(per_equation=False)}])
def test_a_verdict_kept_for_one_setting_is_not_given_for_another(pendulum, setting):
    problem, answer = pendulum
    wrong = _wrong(answer)
    memo = VerdictMemo()
    for a in (answer, wrong, _by_motion(answer)):
        grade_values(problem, a, read_as=(), memo=memo)
        kept = grade_values(problem, a, read_as=(), memo=memo, **setting)
        assert _feedback(kept) == _feedback(grade_values(problem, a, read_as=(), **setting))


def test_the_settings_change_what_these_answers_are_told(pendulum):
    """The premise of the test above: each setting changes the feedback of one of its answers."""
    problem, answer = pendulum
    wrong = _wrong(answer)
    for setting in ({"accuracy": "fast"}, {"hints": True}, {"credit": Credit(per_equation=False)}):
        assert any(_feedback(grade_values(problem, a, read_as=(), **setting)) != _feedback(grade_values(problem, a, read_as=()))
                   for a in (answer, wrong, _by_motion(answer))), setting


def test_an_engine_error_is_not_kept(pendulum, monkeypatch):
    problem, answer = pendulum
    kind = problem.part("L").kind
    real = CHECKERS[kind]
    monkeypatch.setitem(CHECKERS, kind, lambda ctx, part, value: 1 / 0)
    memo = VerdictMemo()
    failed = grade_values(problem, answer, only=["L"], read_as=(), memo=memo)
    assert failed.parts[0].verdict == "error" and "could not grade this part" in failed.parts[0].feedback
    monkeypatch.setitem(CHECKERS, kind, real)
    assert grade_values(problem, answer, only=["L"], read_as=(), memo=memo).parts[0].verdict == "correct"


def test_what_is_kept_is_not_changed_by_those_it_is_given_to(pendulum):
    problem, answer = pendulum
    memo = VerdictMemo()
    first = grade_values(problem, _wrong(answer), read_as=("latex",), memo=memo)
    assert any(p._trajectory is not None for p in first.parts)  # the wrong motion, for a picture
    for _ in range(2):  # graded, then given from the memo: both times read_as is set on what was handed out
        hits = memo.hits
        assert all(p.read_as for p in grade_values(problem, answer, read_as=("latex",), memo=memo).parts)
    assert memo.hits - hits == len(problem.parts)
    assert all(p.read_as is None and p._trajectory is None for p in memo._kept.values())


def test_what_is_kept_is_bounded(pendulum):
    problem, answer = pendulum
    memo = VerdictMemo(entries=2)
    grade_values(problem, answer, read_as=(), memo=memo)
    assert [key[1] for key in memo._kept] == [p.name for p in problem.parts][-2:]  # the oldest went first
