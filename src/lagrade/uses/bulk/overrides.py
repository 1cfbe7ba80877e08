"""An instructor's score for one part, over the engine's: stored apart, applied when grades are read.

Overrides live in their own table (``store.Store.set_override``), so that a regrade, which replaces
a submission's parts, keeps them. They are applied to a loaded gradebook here: the part's score
becomes the instructor's, its dict gets ``override`` (the reason, the engine's score, when), and
the problem's points are computed again with the assignment's weights. An override whose part is
no longer graded (its file was removed) is not applied and is listed by :func:`apply_overrides`.
"""

from __future__ import annotations

from pathlib import Path

from lagrade.uses.bulk.assignment import points
from lagrade.uses.bulk.gradebook import Gradebook
from lagrade.uses.bulk.store import Store


def apply_overrides(book: Gradebook, db: Path | str) -> list[str]:
    """Apply the overrides stored in ``db`` to ``book`` (in place); the ones that could not be, said."""
    with Store(db, create=False) as store:
        rows = [dict(r) for r in store.overrides()]
    unused = []
    students = {s.student: s for s in book.students}
    for o in rows:
        s = students.get(o["student"])
        g = s.problems.get(o["problem"]) if s else None
        part = next((p for p in g.parts if p["part"] == o["part"]), None) if g else None
        if part is None:
            unused.append(f"{o['student']} {o['problem']} {o['part']}: no graded part to override")
            continue
        scale = part["max_score"] / o["max_score"] if o["max_score"] else 1.0
        part["override"] = {"reason": o["reason"], "engine_score": part["score"], "set_at": o["set_at"]}
        part["score"] = min(part["max_score"], max(0.0, o["score"] * scale))
        ap = book.assignment.problem(g.problem)
        g.points = points(ap, g.parts, g.possible)[0]
    return unused


def part_of(book: Gradebook, student: str, problem: str, part: str) -> dict:
    """The stored part an override is for, or ValueError saying what exists."""
    s = next((x for x in book.students if x.student == student), None)
    if s is None:
        raise ValueError(f"no student {student!r} in the gradebook")
    g = s.problems.get(problem)
    if g is None:
        raise ValueError(f"problem {problem!r} is not in the assignment (its problems: {', '.join(s.problems)})")
    if not g.parts:
        raise ValueError(f"{student} has no graded file for problem {problem}: put it in the submissions folder "
                         "and run 'lagrade grade' first")
    p = next((x for x in g.parts if x["part"] == part), None)
    if p is None:
        raise ValueError(f"problem {problem} has no part {part!r} (its parts: {', '.join(x['part'] for x in g.parts)})")
    return p
