"""The verdict: what `lagrade check --json` prints and what the Python API returns."""

from __future__ import annotations

import html
from typing import Literal

from pydantic import BaseModel, Field, PrivateAttr

Verdict = Literal["correct", "partial", "incorrect", "missing", "invalid"]
Method = Literal["symbolic", "numeric", "trajectory", "exact"]


class PartResult(BaseModel):
    """The grade of one part, with the evidence that decided it and feedback for the student."""

    part: str
    verdict: Verdict
    score: float
    max_score: float
    method: Method
    feedback: str = ""
    read_as: str | None = Field(default=None, description="the answer as lagrade understood it (LaTeX)")
    read_as_text: str | None = Field(default=None, exclude=True, description="the same, for a terminal")
    #: how to integrate this part's motion again (student and reference), for pictures; not serialized
    _trajectory: object = PrivateAttr(default=None)


class CheckResult(BaseModel):
    """The grade of one answer file for one problem."""

    problem: str
    score: float
    max_score: float
    parts: list[PartResult]
    problems: list[str] = Field(default_factory=list, description="what was wrong with the answer file itself")

    @property
    def full_marks(self) -> bool:
        return all(p.verdict == "correct" for p in self.parts)

    def verdicts(self) -> dict[str, str]:
        return {p.part: p.verdict for p in self.parts}

    def __str__(self) -> str:
        from lagrade.report import render_text

        return render_text(self)

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{html.escape(p.part)}</td><td>{p.verdict}</td><td>{p.score:g}/{p.max_score:g}</td>"
            f"<td>{p.method}</td><td>{html.escape(p.feedback)}</td></tr>" for p in self.parts)
        return (f"<table><caption>Problem {html.escape(self.problem)}: {self.score:g} / {self.max_score:g}"
                f"</caption><tr><th>part</th><th>verdict</th><th>score</th><th>decided by</th>"
                f"<th>feedback</th></tr>{rows}</table>")
