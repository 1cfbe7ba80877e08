"""Grading one answer: every part, each by its checker, into one result.

Nothing a student writes may stop the grading of the other parts: a part that cannot be read is
``invalid`` with the reason, a part not given is ``missing``, and an unexpected failure of the
engine on one part is reported on that part (as a grader error) instead of crashing the run.
"""

from __future__ import annotations

import os
from pathlib import Path

from lagrade.answers.load import LoadedAnswer, load_answer
from lagrade.checkers import CHECKERS, Context, InvalidAnswer
from lagrade.compare.trajectory import ACCURACY
from lagrade.credit import Credit
from lagrade.library import load_problem
from lagrade.readback import as_latex, as_unicode
from lagrade.reference import ReferenceCache, SceneError
from lagrade.result import CheckResult, PartResult
from lagrade.spec import Problem
from lagrade.verdict_memo import VerdictMemo

_REFERENCES: dict[int, ReferenceCache] = {}


def references(problem: Problem) -> ReferenceCache:
    """Reference derivations are made once per problem per process, not once per answer, and come
    from the disk cache when an earlier process made them (:mod:`lagrade.cache`)."""
    key = id(problem)
    if key not in _REFERENCES:
        from lagrade import cache

        _REFERENCES[key] = cache.load(problem) or ReferenceCache(problem)
    return _REFERENCES[key]


def keep_references(problem: Problem) -> bool:
    """Save what this process derived for ``problem`` to the disk cache (if anything is new)."""
    from lagrade import cache

    refs = _REFERENCES.get(id(problem))
    return refs is not None and cache.save(refs)


def _unusable(part, verdict: str, feedback: str) -> PartResult:
    return PartResult(part=part.name, verdict=verdict, score=0.0, max_score=part.weight, method="exact",
                      feedback=feedback)


def _check(ctx: Context, part, value) -> tuple[PartResult, bool]:
    """The part's grade, and whether it is the value's own (not an error of the engine's)."""
    try:
        return CHECKERS[part.kind](ctx, part, value), True
    except InvalidAnswer as exc:
        return _unusable(part, "invalid", str(exc)), True
    except SceneError:
        raise
    except Exception as exc:  # noqa: BLE001  (a grader bug must not sink the other parts)
        if os.environ.get("LAGRADE_DEBUG"):
            raise
        return _unusable(part, "invalid", f"lagrade could not grade this part ({type(exc).__name__}: "
                                          f"{exc}); please report it to your instructor"), False


def grade_values(problem: Problem, answer: LoadedAnswer, accuracy: str = "default",
                 only: list[str] | None = None, hints: bool = False, credit: Credit | None = None,
                 read_as: tuple[str, ...] = ("latex", "unicode"), memo: VerdictMemo | None = None) -> CheckResult:
    """Grade every part; ``read_as`` says which echoes of the answer to render (pretty-printing a
    long expression can cost a tenth of a second, so a caller asks only for what it shows). A process
    that grades many answers passes a ``memo``: a value graded before gets the verdict it got."""
    ctx = Context(problem, references(problem), ACCURACY[accuracy], hints=hints, credit=credit or Credit())
    parts = []
    for part in problem.parts:
        if only and part.name not in only:
            continue
        if part.name in answer.part_problems:
            parts.append(_unusable(part, "invalid", str(answer.part_problems[part.name])))
            continue
        if part.name not in answer.values:
            if answer.fatal is not None:
                parts.append(_unusable(part, "invalid", f"not graded: {answer.fatal}"))
            else:
                parts.append(_unusable(part, "missing", f"no value bound to '{part.name}'"))
            continue
        value = answer.values[part.name]
        key = memo.key(ctx, part, value) if memo is not None else None
        graded_part = memo.get(key) if key is not None else None
        if graded_part is None:
            graded_part, own = _check(ctx, part, value)
            if key is not None and own:
                memo.put(key, graded_part)
        if "latex" in read_as:
            graded_part.read_as = as_latex(value)
        if "unicode" in read_as:
            graded_part.read_as_text = as_unicode(value)
        parts.append(graded_part)
    return CheckResult(problem=problem.id, score=round(sum(p.score for p in parts), 6),
                       max_score=sum(p.max_score for p in parts), parts=parts,
                       problems=[str(p) for p in answer.problems])


def check(problem: str | Problem, answer: str | Path | None = None, *, accuracy: str = "default",
          limits=None, hints: bool = False, credit: Credit | None = None, **parts: object) -> CheckResult:
    """Grade an answer file, or parts given directly as sympy objects (``check("12.43", H=...)``)."""
    prob = problem if isinstance(problem, Problem) else load_problem(problem)
    loaded = load_answer(Path(answer), prob, limits) if answer is not None else LoadedAnswer()
    for name, value in parts.items():
        try:
            loaded.values[prob.part(name).name] = value
        except KeyError:
            raise TypeError(f"problem {prob.id} has no part '{name}'") from None
    return grade_values(prob, loaded, accuracy, hints=hints, credit=credit)
