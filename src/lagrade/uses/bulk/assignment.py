"""The assignment file: which problems, their weights, per-part weights, accuracy and limits.

```toml
name = "hw7"                       # the column name in the gradebook exports
title = "Homework 7"               # optional
accuracy = "default"               # fast | default | strict (trajectory tolerances)

[limits]                           # optional, per submission (the sandbox of the engine)
cpu_seconds = 10
wall_seconds = 20
memory_mb = 1024
grading_seconds = 120              # time to grade the values once the file has run

[credit]                           # optional partial-credit policy (lagrade.verdicts.credit.Credit)
scaled_lagrangian = 0.5            # L = c * (the right L), c != 1
per_equation = true                # each right equation / entry earns its share

[[problems]]
id = "12.22"
weight = 5                         # points for this problem (default: the problem's own total)
parts = { L = 2, eom = 1 }         # optional relative weights of parts (default: the problem file's)
```

Optional, for the LMS (none of it changes a grade, so none of it regrades):

```toml
canvas_assignment_id = 4411        # the Canvas export fills the column "Homework 7 (4411)"

[gradescope]                       # results.json of the Gradescope autograder
visibility = "visible"             # the whole result: visible | hidden | after_due_date | after_published
tests_visibility = "visible"       # each test (one per part); "hidden" hides them from students
stdout_visibility = "hidden"       # the autograder's stdout
output_format = "md"               # md | html | text
```

A course server's rules (``lagrade serve``; ``lagrade grade`` ignores them), all optional:

```toml
[rules]
deadline = 2026-12-01T23:59:00Z    # later attempts are stored, graded and marked late; the gradebook
                                   # keeps each student's latest attempt made by the deadline
attempts = 5                       # attempts per problem and student (a 6th is refused)
attempt_penalty = 0.1              # each attempt after the first takes 10% off its score
feedback = "named"                 # hints | named | verdict: what a student reads of a wrong part
```

A student's points on a problem are ``weight * sum(w_part * fraction_part) / sum(w_part)``, where
``fraction_part`` is the engine's score of the part over its maximum.  Weights only change the
points, never the grading, so changing them does not regrade anything.  A part marked extra (one the
book does not ask; ``lagrade show`` says so) is graded and shown but has weight 0 unless ``parts``
names it: ``parts = { H_F = 1 }`` asks for it.
"""

from __future__ import annotations

import hashlib
import json
import tomllib
from pathlib import Path
from typing import Literal

from datetime import datetime, timezone

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from lagrade.verdicts.credit import Credit
from lagrade.problem.limits import GRADING_SECONDS


class AssignmentError(ValueError):
    """The assignment file cannot be used; the message says why."""


class Limits(BaseModel):
    """Per-submission limits: the engine's sandbox limits plus a bound on grading the values."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    cpu_seconds: float = Field(10, gt=0)
    wall_seconds: float = Field(20, gt=0)
    memory_mb: int = Field(1024, gt=0)
    grading_seconds: float = Field(GRADING_SECONDS, gt=0)

    def sandbox(self):
        from lagrade.answer.jail.sandbox import SandboxLimits

        return SandboxLimits(cpu_seconds=self.cpu_seconds, wall_seconds=self.wall_seconds,
                             memory_mb=self.memory_mb)


class AssignedProblem(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    id: str
    weight: float | None = Field(None, ge=0)
    parts: dict[str, float] = Field(default_factory=dict)

    @model_validator(mode="after")
    def _positive_parts(self) -> "AssignedProblem":
        bad = [k for k, v in self.parts.items() if v < 0]
        if bad:
            raise ValueError(f"negative part weight for {', '.join(bad)}")
        return self


Visibility = Literal["visible", "hidden", "after_due_date", "after_published"]


class GradescopeOptions(BaseModel):
    """How Gradescope shows the autograder's results (its ``visibility`` values, its ``output_format``)."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    visibility: Visibility = "visible"
    tests_visibility: Visibility = "visible"
    stdout_visibility: Visibility = "hidden"
    output_format: Literal["md", "html", "text"] = "md"


Feedback = Literal["hints", "named", "verdict"]


class Rules(BaseModel):
    """What a course server lets a student do and see (docs/server.md, "A course's rules")."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    #: attempts stored after it are graded and marked late; they do not replace the gradebook's grade
    deadline: datetime | None = None
    #: attempts per problem and student; None: no limit
    attempts: int | None = Field(None, ge=1)
    #: the fraction of an attempt's score taken off for each attempt before it (never below 0)
    attempt_penalty: float = Field(0.0, ge=0, le=1)
    #: hints: named mistakes and term hints; named: named mistakes; verdict: the verdict alone
    feedback: Feedback = "named"

    @field_validator("deadline")
    @classmethod
    def _utc(cls, v: datetime | None) -> datetime | None:
        if v is not None and v.tzinfo is None:  # a TOML local date-time: UTC, as the server's clock
            v = v.replace(tzinfo=timezone.utc)
        return v.astimezone(timezone.utc) if v is not None else None

    def deadline_text(self) -> str | None:
        """The deadline as the server stores attempts' times (``2026-12-01T23:59:00Z``), comparable as text."""
        return self.deadline.strftime("%Y-%m-%dT%H:%M:%SZ") if self.deadline is not None else None

    def penalty(self, attempt: int) -> float:
        """The fraction of the score kept by the ``attempt``-th attempt (1, 2, ...)."""
        return max(0.0, 1.0 - self.attempt_penalty * (attempt - 1))


class Assignment(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    name: str = "assignment"
    title: str = ""
    #: Canvas's id of the assignment: the export then fills that column instead of making a new one
    canvas_assignment_id: int | None = Field(None, ge=0)
    gradescope: GradescopeOptions = GradescopeOptions()
    accuracy: Literal["fast", "default", "strict"] = "default"
    limits: Limits = Limits()
    #: partial-credit policy (lagrade.verdicts.credit.Credit); the defaults are documented in docs/answers.md
    credit: Credit = Credit()
    #: a course server's rules: deadline, attempts, feedback level (not grading: never regrades)
    rules: Rules = Rules()
    problems: list[AssignedProblem] = Field(min_length=1)

    @model_validator(mode="after")
    def _unique(self) -> "Assignment":
        ids = [p.id for p in self.problems]
        dup = sorted({i for i in ids if ids.count(i) > 1})
        if dup:
            raise ValueError(f"problem listed twice: {', '.join(dup)}")
        return self

    # ------------------------------------------------------------------ identity

    def canonical_json(self) -> str:
        return json.dumps(self.model_dump(mode="json"), sort_keys=True, separators=(",", ":"))

    def grading_hash(self, problem_id: str, problem_source: str) -> str:
        """What a stored grade of ``problem_id`` depends on, besides the file and the grader version.

        The problem file itself (an instructor fixing a reference regrades that problem), the
        accuracy setting, the limits and the partial-credit policy; not the weights, which only
        scale points.
        """
        key = json.dumps({"problem": problem_id, "source": problem_source, "accuracy": self.accuracy,
                          "limits": self.limits.model_dump(mode="json"),
                          "credit": self.credit.model_dump(mode="json")}, sort_keys=True)
        return hashlib.sha256(key.encode()).hexdigest()[:16]

    def problem(self, pid: str) -> AssignedProblem:
        for p in self.problems:
            if p.id == pid:
                return p
        raise KeyError(pid)

    @property
    def ids(self) -> list[str]:
        return [p.id for p in self.problems]


def load_assignment(path: Path) -> Assignment:
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise AssignmentError(f"{path}: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise AssignmentError(f"{path}: not valid TOML ({exc})") from None
    return parse_assignment(data, str(path))


def parse_assignment(data: dict, where: str = "assignment") -> Assignment:
    try:
        return Assignment.model_validate(data)
    except ValidationError as exc:
        lines = [f"{where}: {'.'.join(str(x) for x in e['loc']) or '(top)'}: {e['msg']}" for e in exc.errors()]
        raise AssignmentError("\n".join(lines)) from None


def check_against_problems(assignment: Assignment, problems_dirs: tuple[Path, ...] = ()) -> None:
    """Every problem id exists and every per-part weight names a part of its problem."""
    from lagrade.problem.library import load_problem
    from lagrade.problem.spec import SpecError

    errors = []
    for ap in assignment.problems:
        try:
            problem = load_problem(ap.id, problems_dirs)
        except SpecError as exc:
            errors.append(str(exc))
            continue
        names = {p.name for p in problem.parts}
        unknown = sorted(set(ap.parts) - names)
        if unknown:
            errors.append(f"problem {ap.id} has no part {', '.join(unknown)} (its parts: {', '.join(sorted(names))})")
    if errors:
        raise AssignmentError("\n".join(errors))


def _extra(part) -> bool:
    try:
        return bool(part["extra"])
    except (KeyError, IndexError):  # a gradebook from before the column: no part is extra
        return False


def part_weight(assigned: AssignedProblem, part) -> float:
    """The weight of a stored part: the assignment's, else its own maximum; an extra part (one the book does
    not ask) counts only when the assignment's ``parts`` names it."""
    if part["part"] in assigned.parts:
        return assigned.parts[part["part"]]
    return 0.0 if _extra(part) else part["max_score"]


def points(assigned: AssignedProblem, parts: list[dict], default_total: float) -> tuple[float, float]:
    """(points, points possible) of one problem from its stored parts (``part``, ``score``, ``max_score``).

    ``default_total`` is the problem's own maximum (used when the assignment gives no weight). The
    points are the exact share rounded to 1/POINT_UNITS (half up): the one rounding rule of every
    export; :func:`part_points` splits exactly these points among the parts.
    """
    total = assigned.weight if assigned.weight is not None else default_total
    return _problem_units(assigned, parts, total) / POINT_UNITS, total


def _weights(assigned: AssignedProblem, parts: list[dict]) -> list[float]:
    return [part_weight(assigned, p) for p in parts]


def _frac(p: dict) -> float:
    return min(1.0, max(0.0, p["score"] / p["max_score"])) if p["max_score"] else 0.0


def _half_up(x: float) -> int:
    """``x`` rounded half up, after cutting float noise (``3 * 0.1`` is 0.30000000000000004)."""
    import math

    return math.floor(round(x, 6) + 0.5)


def _problem_units(assigned: AssignedProblem, parts: list[dict], total: float) -> int:
    weights = _weights(assigned, parts)
    denom = sum(weights)
    if not parts or denom <= 0:
        return 0
    frac = sum(w * (p["score"] / p["max_score"] if p["max_score"] else 0.0) for w, p in zip(weights, parts))
    return _half_up(total * frac / denom * POINT_UNITS)


#: the precision, in points, of the per-part points the exports show (Gradescope's tests, the report)
POINT_UNITS = 10_000


def split_points(total: float, weights: list[float]) -> list[float]:
    """``total`` shared in proportion to ``weights``, each share a multiple of 1/POINT_UNITS, the shares
    summing exactly to ``total`` rounded to that precision (largest remainders: never 9.999999 of 10)."""
    units = round(total * POINT_UNITS)
    denom = sum(weights)
    if not weights:
        return []
    if denom <= 0:
        weights, denom = [1.0] * len(weights), float(len(weights))
    raw = [units * w / denom for w in weights]
    shares = [int(r) for r in raw]
    order = sorted(range(len(raw)), key=lambda i: (shares[i] - raw[i], i))
    for i in order[: units - sum(shares)]:
        shares[i] += 1
    return [s / POINT_UNITS for s in shares]


def part_points(assigned: AssignedProblem, parts: list[dict], default_total: float) -> list[tuple[float, float]]:
    """(points earned, points possible) of each stored part, in the order given, with the weights that
    :func:`points` uses: the possible points sum exactly to the problem's (see :func:`split_points`),
    and the earned points sum exactly to :func:`points` (largest remainders again, each part within
    its share), so that Gradescope's tests add up to the score the CSV and Canvas exports give."""
    total = assigned.weight if assigned.weight is not None else default_total
    shares = [round(x * POINT_UNITS) for x in split_points(total, _weights(assigned, parts))]
    if len(shares) != len(parts):
        return [(0.0, 0.0) for _ in parts]
    raw = [share * _frac(p) for share, p in zip(shares, parts)]
    earned = [min(share, int(r)) for share, r in zip(shares, raw)]
    target = min(sum(shares), _problem_units(assigned, parts, total))
    order = sorted(range(len(raw)), key=lambda i: (earned[i] - raw[i], i))  # the largest remainders first
    while sum(earned) < target and any(earned[i] < shares[i] for i in order):
        for i in order:
            if sum(earned) < target and earned[i] < shares[i]:
                earned[i] += 1
    while sum(earned) > target and any(earned):
        for i in reversed(order):
            if sum(earned) > target and earned[i] > 0:
                earned[i] -= 1
    return [(e / POINT_UNITS, s / POINT_UNITS) for e, s in zip(earned, shares)]
