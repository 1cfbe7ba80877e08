"""The grades as exports and reports see them: points per student and problem, from the database.

Points are computed here, from the engine's stored part scores and the assignment's weights (the
assignment stored by the last ``lagrade grade``), so that every export and report agrees.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from lagrade.uses.bulk.assignment import Assignment, parse_assignment, points
from lagrade.uses.bulk.store import Store, StoreError


@dataclass
class ProblemGrade:
    problem: str
    points: float
    possible: float
    submitted: bool
    outcome: str = "missing"       # graded | failed | missing
    status: str = ""
    reason: str = ""
    problems: list[str] = field(default_factory=list)
    parts: list[dict] = field(default_factory=list)
    source: str = ""
    path: str = ""
    #: the picture of the file's wrong motions (PNG), b"" when there was none to draw, None when not asked
    plot_png: bytes | None = None


@dataclass
class StudentGrade:
    student: str
    problems: dict[str, ProblemGrade]

    @property
    def points(self) -> float:
        from lagrade.uses.bulk.assignment import POINT_UNITS

        # each problem's points are whole 1/POINT_UNITS: summed as integers, no 14.999999999
        return sum(round(p.points * POINT_UNITS) for p in self.problems.values()) / POINT_UNITS

    @property
    def possible(self) -> float:
        return sum(p.possible for p in self.problems.values())


@dataclass
class Gradebook:
    assignment: Assignment
    students: list[StudentGrade]
    skipped: list[tuple[str, str]]
    grader_version: str
    #: student -> what ``lagrade import`` learnt from the LMS: ``canvas_user_id``, ``name``, ``late``
    lms: dict[str, dict] = field(default_factory=dict)

    @property
    def possible(self) -> float:
        return sum(self.totals.values())

    @property
    def totals(self) -> dict[str, float]:
        if not self.students:
            return {}
        return {pid: g.possible for pid, g in self.students[0].problems.items()}

    def student(self, name: str) -> StudentGrade:
        for s in self.students:
            if s.student == name:
                return s
        raise KeyError(name)


def load_gradebook(db: Path | str) -> Gradebook:
    with Store(db, create=False) as store:
        return gradebook_of(store, db)


def gradebook_of(store: Store, db: Path | str) -> Gradebook:
    """The Gradebook of an open :class:`Store` (``db`` names it in messages): `lagrade serve` reads its
    own file through its own connection (:meth:`Store.over`), never a second one."""
    raw = store.meta("assignment")
    if raw is None:
        raise StoreError(f"{db}: nothing graded yet (run 'lagrade grade' first)")
    assignment = parse_assignment(json.loads(raw), str(db))
    totals = json.loads(store.meta("problem_totals") or "{}")
    extras = json.loads(store.meta("problem_extras") or "{}")  # a gradebook from before: none
    subs = {(r["student"], r["problem"]): r for r in store.submissions()}
    parts: dict[tuple[str, str], list[dict]] = {}
    for r in store.parts():
        parts.setdefault((r["student"], r["problem"]), []).append(
            {**dict(r), "extra": r["part"] in extras.get(r["problem"], ())})
    names = sorted(set(store.students()) | {s for s, _ in subs})
    students = []
    for name in names:
        grades = {}
        for ap in assignment.problems:
            row = subs.get((name, ap.id))
            ps = parts.get((name, ap.id), [])
            pts, possible = points(ap, ps, totals.get(ap.id, 0.0))
            if row is None:
                grades[ap.id] = ProblemGrade(ap.id, 0.0, possible, False, reason="no file handed in")
            else:
                grades[ap.id] = ProblemGrade(ap.id, pts, possible, True, row["outcome"], row["status"],
                                             row["reason"], json.loads(row["problems"]), ps, row["source"],
                                             row["path"], row["plot_png"] if "plot_png" in row.keys() else None)
        students.append(StudentGrade(name, grades))
    skipped = [(r["path"], r["reason"]) for r in store.skipped()]
    try:
        lms = json.loads(store.meta("lms") or "{}")
    except ValueError:
        lms = {}
    return Gradebook(assignment, students, skipped, store.meta("grader_version") or "",
                     lms if isinstance(lms, dict) else {})
