"""Verdicts kept by value, for a process that grades many answers to the same problems.

A part's verdict is a function of the part, the grading settings and the student's value: a checker
reads nothing else, its random states come from seeds fixed by the problem and the part, and what it
caches (compiled functions, reference motions) only saves time. So the same value handed in again
gets the verdict it got before without grading it again; in a class that happens often, since
answers written differently are often one value once sympy has put them in canonical form (the
textbook's L, the frequencies as the formula gives them). It also makes equal answers equal in their
feedback where grading is bounded in time (a symbolic proof given up after a while).

Only results a checker returned, or the answer it could not read, are kept: an engine error may be
the machine's (memory), and grading stopped for time never returns.
"""

from __future__ import annotations

from typing import Any

from lagrade.answer.reading.value_key import value_key
from lagrade.verdicts.result import PartResult

#: verdicts kept per memo, the oldest dropped first: a class's distinct values are a few per part
ENTRIES = 4096


class VerdictMemo:
    """Verdicts by (part, grading settings, value), bounded."""

    def __init__(self, entries: int = ENTRIES) -> None:
        self.entries = entries
        self._kept: dict[Any, PartResult] = {}
        self.hits = self.misses = 0

    @staticmethod
    def key(ctx: Any, part: Any, value: Any) -> Any:
        """None when the value has no exact key (then it is graded every time)."""
        vk = value_key(value)
        if vk is None:
            return None
        return (ctx.problem.id, part.name, ctx.accuracy, ctx.credit, ctx.hints, ctx.points, ctx.symbolic_seconds, vk)

    def get(self, key: Any) -> PartResult | None:
        kept = self._kept.get(key)
        if kept is None:
            self.misses += 1
            return None
        self.hits += 1
        return kept.model_copy()  # the caller may still set fields (read_as) on what it gets

    def put(self, key: Any, result: PartResult) -> None:
        if len(self._kept) >= self.entries:
            self._kept.pop(next(iter(self._kept)))
        kept = result.model_copy()
        kept._trajectory = None  # the motion kept for pictures: compiled functions and arrays
        self._kept[key] = kept
