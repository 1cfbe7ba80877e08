"""Grading a part whose answer uses a function the book leaves general (``V(r)``).

The part is checked once per random function put for it (`lagrade.general_functions`), each a full
check (sampled states and trajectories) against the scene with the same function; the answer is
right only if it is right for every one. An answer that does not use the function is checked once,
against the problem's concrete scene.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from functools import wraps

from lagrade.checkers.base import Context
from lagrade.general_functions import INSTANCES, uses
from lagrade.result import PartResult
from lagrade.spec import Part

Checker = Callable[[Context, Part, object], PartResult]


def for_general_functions(checker: Checker) -> Checker:
    """``checker``, run for every random substitute when the answer calls a general function."""

    @wraps(checker)
    def run(ctx: Context, part: Part, value: object) -> PartResult:
        functions = ctx.problem.system(part.system).functions
        if ctx.instance or not functions or not uses(value, [f.name for f in functions]):
            return checker(ctx, part, value)
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
