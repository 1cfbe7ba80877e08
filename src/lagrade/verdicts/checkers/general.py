"""Grading a part whose answer uses a function the book leaves general (``V(r)``).

The part is checked once per random function put for it (`lagrade.derive.general_functions`), each a full
check (sampled states and trajectories) against the scene with the same function; the answer is
right only if it is right for every one. An answer that does not use the function is right if it holds
for every one too (the function does not enter the part); else it is a special case, right or wrong for
the problem's concrete function or for 0. What a right special case earns is the problem's promise
(``special_case`` of the function, said by ``lagrade show``): where the book names no force (12.36's
"a point mass moving in a straight line") the answer is checked for the force it states and earns the
part; where the book names a general one (12.39's "central isotropic force") it earns
:data:`SPECIAL_CASE` of the part, with a note, never full.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from functools import wraps

from lagrade.verdicts.checkers.base import Context
from lagrade.derive.general_functions import INSTANCES, ZERO, uses
from lagrade.verdicts.result import PartResult
from lagrade.problem.spec import Part

Checker = Callable[[Context, Part, object], PartResult]

#: the share of a part an answer right only for a special case of the general function earns
SPECIAL_CASE = 0.5


def for_general_functions(checker: Checker) -> Checker:
    """``checker``, run for every random substitute when the answer calls a general function."""

    @wraps(checker)
    def run(ctx: Context, part: Part, value: object) -> PartResult:
        functions = ctx.problem.system(part.system).functions
        if ctx.instance or not functions:
            return checker(ctx, part, value)
        if not uses(value, [f.name for f in functions]):
            return _special_case(checker, ctx, part, value, functions)
        named = " and ".join(f.name for f in functions)  # the name only: V(r) is the scene's V, as text
        first = None
        for instance in range(1, INSTANCES + 1):
            res = checker(replace(ctx, instance=instance), part, value)
            if res.verdict != "correct":
                if instance > 1:  # right for the functions tried before this one
                    res.feedback = (f"{res.feedback.rstrip()} (With {named} replaced by several smooth functions, "
                                    f"it holds for some of them, not for all.)")
                return res
            first = first or res
        assert first is not None
        first.feedback = f"{first.feedback.rstrip()} Right for every function put for {named} (several smooth ones)."
        return first

    return run


def _special_case(checker: Checker, ctx: Context, part: Part, value: object, functions) -> PartResult:
    """An answer that never calls the general function: right for every function put for it (the
    function does not enter this part) is right; right for the problem's concrete function, or for 0,
    is a special case: right where the problem promises full marks for it, else partial with a note;
    else the concrete scene's verdict, as before."""
    concrete = checker(ctx, part, value)
    general = all(checker(replace(ctx, instance=i), part, value).verdict == "correct"
                  for i in range(1, INSTANCES + 1)) if concrete.verdict == "correct" else False
    if general:
        return concrete
    asked = " and ".join(f"a general {f.name}({', '.join(f.args)})" for f in functions)
    full = all(f.special_case == "full" for f in functions)
    for instance, case in ((0, concrete), (ZERO, None)):
        res = case if case is not None else checker(replace(ctx, instance=instance), part, value)
        if res.verdict == "correct":
            said = ", ".join(f"{f.name} = {f.concrete if instance == 0 else 0}" for f in functions)
            if full:  # the book names no force: the one the answer states is as good as the general one
                return res.model_copy(update={
                    "feedback": f"{res.feedback.rstrip()} Checked for the force your answer states ({said})."})
            out = res.model_copy(update={
                "verdict": "partial", "score": round(res.max_score * SPECIAL_CASE, 6),
                "feedback": f"Right for {said}; the problem asks for {asked}."})
            out._special_case = True
            return out
    return concrete
