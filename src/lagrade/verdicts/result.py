"""The verdict: what `lagrade check --json` prints, what the Python API returns, and how it reads
for people (one row per part, then the total; `lagrade check` and ``print(result)`` alike)."""

from __future__ import annotations

import html
from typing import TYPE_CHECKING, Literal

from pydantic import BaseModel, Field, PrivateAttr

if TYPE_CHECKING:  # rich is loaded only to render: graders and the API need the model alone
    from rich.console import Console
    from rich.table import Table

#: ``error`` is lagrade's own failure on a readable answer: not the student's, and regraded by a fix
Verdict = Literal["correct", "partial", "incorrect", "missing", "invalid", "error"]
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
    review: str | None = Field(default=None, description="for instructors: why this verdict deserves a look (the "
                                                          "evidence could not decide it); never a reference value")
    extra: bool = Field(default=False, description="a part the book does not ask: graded and shown, not counted "
                                                   "in the problem's total (an assignment may count it)")
    certified: bool | None = Field(default=None, description="a rejection at sampled states: true when ball "
                                   "arithmetic proved the difference nonzero at an exact point (the certificate is "
                                   "the instructor's), false when it could not (then `review` says so); null otherwise")
    certificate: str | None = Field(default=None, exclude=True,
                                    description="for instructors: the exact point and the enclosure that prove a "
                                                "rejection; never serialized (the enclosure is a difference from "
                                                "the reference)")
    confirmed: bool | None = Field(default=None, description="a rejection by the trajectory comparison: true when "
                                   "the same comparison at a 100x finer integration tolerance separates too and the "
                                   "integration's error estimate is below a tenth of the separation, false when not "
                                   "(then `review` says so); null otherwise")
    trajectory_evidence: str | None = Field(default=None, description="for instructors (`lagrade check --json`, the "
                                            "instructor's view; hidden from a student's): the separation, the "
                                            "integration's error estimate at that time and the separation at the "
                                            "finer tolerance, in units of the comparison tolerance")
    motion_evidence: dict | None = Field(default=None, description="for instructors, with `trajectory_evidence`: "
                                         "the same as numbers (t: the time the motions separate, component, "
                                         "separation and error_estimate and finer_separation in units of the "
                                         "comparison tolerance, compare_rtol, compare_atol, rtol, finer_rtol, method, "
                                         "window, refined_windows: where the student's steps were bounded)")
    detail: str | None = Field(default=None, exclude=True,
                               description="for instructors: the engine's traceback of an `error`; never "
                                           "serialized, so never in what a student is shown")
    #: how to integrate this part's motion again (student and reference), for pictures; not serialized
    _trajectory: object = PrivateAttr(default=None)
    #: the system key of the formulation the answer was right in (a part others follow), kept with
    #: the verdict in the memo; not serialized
    _formulation: str | None = PrivateAttr(default=None)
    #: partial because right only for a special case of a function the book leaves general (12.39's
    #: V = k*r**2/2): the formulation it is written in is still the one a following part is judged in
    _special_case: bool = PrivateAttr(default=False)


class CheckResult(BaseModel):
    """The grade of one answer file for one problem."""

    problem: str
    score: float
    max_score: float
    parts: list[PartResult]
    problems: list[str] = Field(default_factory=list, description="what was wrong with the answer file itself")

    @property
    def full_marks(self) -> bool:
        """Every part the problem counts is correct (an extra, which the book does not ask, may not be)."""
        return all(p.verdict == "correct" for p in self.parts if not p.extra)

    def verdicts(self) -> dict[str, str]:
        return {p.part: p.verdict for p in self.parts}

    def __str__(self) -> str:
        return render_text(self)

    #: how to draw the picture of the wrong dynamics parts (a PNG, or None when there is none): set by
    #: ``lagrade.check`` (locally, or fetched from the course server); drawn once, when first shown
    _picture: object = PrivateAttr(default=None)

    def picture(self) -> bytes | None:
        """The PNG of the wrong dynamics parts' motion against the true one, as ``lagrade check --plot``
        draws it, or None (every dynamics part right, or no way to draw it here)."""
        if callable(self._picture):
            self._picture = self._picture() or b""
        return self._picture or None

    def _repr_html_(self) -> str:
        """In Jupyter: the answer as read (LaTeX, typeset by the notebook), then the verdicts and the
        feedback, then the picture of a wrong motion; as the terminal shows it. Everything that may
        quote the student is escaped."""
        esc = html.escape
        notes = "".join(f"<li>{esc(p)}</li>" for p in self.problems)
        read = "".join(f'<li><code>{esc(p.part)}</code> = ${esc(p.read_as)}$</li>' for p in self.parts if p.read_as)
        rows = "".join(
            f"<tr><td>{esc(p.part)}{' (extra)' if p.extra else ''}</td>"
            f"<td style=\"color:{_HTML_COLOUR[p.verdict]}\"><b>{p.verdict}</b></td>"
            f"<td>{p.score:g}/{p.max_score:g}</td><td>{p.method}</td>"
            f"<td style=\"text-align:left\">{esc(p.feedback)}</td></tr>" for p in self.parts)
        png = self.picture()
        img = (f'<p>Your motion against the true one, for the wrong dynamics parts:</p>'
               f'<img alt="your motion against the true one" src="data:image/png;base64,{_b64(png)}">'
               if png else "")
        return (f"<div class=\"lagrade-result\">{f'<ul>{notes}</ul>' if notes else ''}"
                + (f"<p><b>Your answer, as lagrade read it:</b></p><ul style=\"list-style:none; overflow-x:auto\">"
                   f"{read}</ul>" if read else "")
                + f"<table><caption>Problem {esc(self.problem)}: {self.score:g} / {self.max_score:g}"
                f"</caption><tr><th>part</th><th>verdict</th><th>score</th><th>decided by</th>"
                f"<th>feedback</th></tr>{rows}</table>{img}</div>")

    def _repr_pretty_(self, printer, cycle: bool) -> None:
        """IPython's text (a terminal, a notebook's text/plain): the table ``print(result)`` shows."""
        printer.text(render_text(self))

    def _repr_markdown_(self) -> str:
        """The same as Markdown (front ends that show Markdown and math, not HTML)."""
        cell = lambda text: html.escape(text).replace("|", "\\|").replace("\n", " ")  # noqa: E731
        lines = [f"**Problem {cell(self.problem)}: {self.score:g} / {self.max_score:g}**", ""]
        lines += [f"- {cell(p)}" for p in self.problems] + ([""] if self.problems else [])
        lines += ["| part | verdict | score | your answer, as read | feedback |", "|---|---|---|---|---|"]
        for p in self.parts:
            shown = f"${html.escape(p.read_as).replace('|', chr(92) + 'vert ')}$" if p.read_as else ""
            lines.append(f"| {cell(p.part)} | **{p.verdict}** | {p.score:g}/{p.max_score:g} | {shown} | "
                         f"{cell(p.feedback)} |")
        png = self.picture()
        if png:
            lines += ["", f"![your motion against the true one](data:image/png;base64,{_b64(png)})"]
        return "\n".join(lines) + "\n"


def _b64(data: bytes) -> str:
    import base64

    return base64.b64encode(data).decode("ascii")


_HTML_COLOUR = {"correct": "green", "partial": "darkorange", "incorrect": "red", "missing": "purple",
                "invalid": "red", "error": "darkred"}


_STYLE = {"correct": "green", "partial": "yellow", "incorrect": "red", "missing": "magenta", "invalid": "red", "error": "bold red"}


def table(result: CheckResult) -> Table:
    from rich import box
    from rich.table import Table
    from rich.text import Text

    from lagrade.verdicts.printable import plain

    t = Table(title=plain(f"Problem {result.problem}"), box=box.SIMPLE_HEAVY, show_lines=False, expand=False)
    t.add_column("part", no_wrap=True)
    t.add_column("verdict", no_wrap=True)
    t.add_column("score", justify="right", no_wrap=True)
    t.add_column("decided by", no_wrap=True)
    t.add_column("feedback", overflow="fold")
    for p in result.parts:
        style = _STYLE[p.verdict]
        name = f"{p.part} (extra)" if p.extra else p.part
        t.add_row(plain(name), Text(p.verdict, style=style), f"{p.score:g}/{p.max_score:g}", p.method,
                  plain(p.feedback))  # the feedback quotes the student: never markup, never a control
    t.caption = f"total {result.score:g} / {result.max_score:g}"
    if any(p.extra for p in result.parts):
        t.caption += " (extra parts, not asked by the book, are not counted)"
    return t


def render(result: CheckResult, console: Console, read_as: bool = True) -> None:
    """The result for a terminal: every text that may quote the student made printable on the way."""
    from lagrade.verdicts.printable import printable

    for problem in result.problems:
        console.print(printable(problem), style="yellow", highlight=False, markup=False)
    if read_as and any(p.read_as_text for p in result.parts):
        console.print("Your answer, as lagrade read it:", style="bold")
        for p in result.parts:
            if p.read_as_text:
                lines = printable(p.read_as_text).split("\n")
                if len(lines) == 1:
                    console.print(f"  {p.part} = {lines[0]}", highlight=False, markup=False, soft_wrap=True)
                else:
                    console.print(f"  {p.part} =", highlight=False, markup=False)
                    for line in lines:
                        console.print(f"      {line}", highlight=False, markup=False, soft_wrap=True)
        console.print()
    console.print(table(result))


def render_text(result: CheckResult, width: int = 110) -> str:
    from rich.console import Console

    console = Console(width=width, record=True, file=None, force_terminal=False, color_system=None)
    with console.capture() as cap:
        render(result, console)
    return cap.get()
