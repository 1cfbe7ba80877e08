"""Every statement's promise about special cases of a general function is kept by the grader (issue 44 §1).

Where the book names no force (12.26 "a particle moving in a plane", 12.36 "a point mass moving in a
straight line") an answer is checked for the force it states and a right one earns full marks; where
the book names a general force (12.39/12.40 "a central isotropic force") a special case earns partial
credit. Each general function declares which (`special_case`), `lagrade show` says it, and here every
problem's reference solution, rewritten for the concrete function and for 0, is graded to see that
the grader does what the statement says.
"""

from __future__ import annotations

import math
import runpy

import pytest
import sympy as sp

from lagrade.derive import general_functions as gf
from lagrade.problem.describe import show_text
from lagrade.problem.library import load_problem, problem_ids, reference_dir
from lagrade.verdicts.grade import check

WITH_FUNCTIONS = [pid for pid in problem_ids() if any(s.functions for s in load_problem(pid).systems)]


def test_the_problems_that_leave_a_function_general():
    assert WITH_FUNCTIONS == ["12.26", "12.36", "12.39", "12.40"]


def _functions(pid: str) -> dict:
    return {f.name: f for s in load_problem(pid).systems for f in s.functions}


def _promise(pid: str) -> str:
    (promise,) = {f.special_case for f in _functions(pid).values()}
    return promise


def test_the_book_decides_the_promise():
    """The book's words: no force named (12.26, 12.36), or a general one (12.39, 12.40)."""
    assert {pid: _promise(pid) for pid in WITH_FUNCTIONS} == {
        "12.26": "full", "12.36": "full", "12.39": "partial", "12.40": "partial"}


@pytest.mark.parametrize("pid", WITH_FUNCTIONS)
def test_the_statement_says_the_promise(pid):
    """`show` says what a special case earns, in the function's line and in no contradicting assumption."""
    text = show_text(load_problem(pid))
    words = {"full": "full marks", "partial": "partial credit"}
    promise = _promise(pid)
    for f in _functions(pid).values():
        line = next(ln for ln in text.splitlines() if ln.strip().startswith(f"function  {f.name}("))
        assert words[promise] in line, line
    other = words["partial" if promise == "full" else "full"]
    assert other not in text


def _special(value: object, lams: dict) -> object:
    if isinstance(value, dict):
        return {k: _special(v, lams) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_special(v, lams) for v in value]
    if isinstance(value, sp.Basic):
        return gf.substitute(value, lams)
    return value


@pytest.mark.parametrize("case", ["concrete", "zero"])
@pytest.mark.parametrize("pid", WITH_FUNCTIONS)
def test_the_grader_keeps_the_promise(pid, case):
    """The reference solution written for the stated function (or 0): right for it, so full marks
    where the book names no force, partial credit on every part the function enters where it names one."""
    problem = load_problem(pid)
    path = next(p for p in (reference_dir() / pid).glob("answer.*"))
    assert path.suffix == ".py"
    values = {p.name: v for p in problem.parts
              if (v := runpy.run_path(str(path)).get(p.name)) is not None}
    lams = {name: sp.Lambda(tuple(sp.Symbol(a) for a in f.args),
                            sp.sympify(f.concrete if case == "concrete" else "0"))
            for name, f in _functions(pid).items()}
    special = {name: _special(v, lams) for name, v in values.items()}
    changed = {name for name in special if special[name] != values[name]}
    assert changed, "the reference uses the general function"
    res = check(pid, grading_seconds=math.inf, **special)
    got = {p.part: p for p in res.parts}
    want = "correct" if _promise(pid) == "full" else "partial"
    for name in values:
        part = got[name]
        assert part.verdict == (want if name in changed else "correct"), (name, part.feedback)
        if name in changed and want == "partial":
            assert 0 < part.score < part.max_score
    assert res.full_marks == (_promise(pid) == "full")
