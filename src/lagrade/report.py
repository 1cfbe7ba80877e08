"""Rendering a result for people: one row per part, then the total."""

from __future__ import annotations

from rich import box
from rich.console import Console
from rich.table import Table

from lagrade.result import CheckResult

_STYLE = {"correct": "green", "partial": "yellow", "incorrect": "red", "missing": "magenta", "invalid": "red"}


def table(result: CheckResult) -> Table:
    t = Table(title=f"Problem {result.problem}", box=box.SIMPLE_HEAVY, show_lines=False, expand=False)
    t.add_column("part", no_wrap=True)
    t.add_column("verdict", no_wrap=True)
    t.add_column("score", justify="right", no_wrap=True)
    t.add_column("decided by", no_wrap=True)
    t.add_column("feedback", overflow="fold")
    for p in result.parts:
        style = _STYLE[p.verdict]
        t.add_row(p.part, f"[{style}]{p.verdict}[/]", f"{p.score:g}/{p.max_score:g}", p.method, p.feedback)
    t.caption = f"total {result.score:g} / {result.max_score:g}"
    return t


def render(result: CheckResult, console: Console, read_as: bool = True) -> None:
    for problem in result.problems:
        console.print(problem, style="yellow", highlight=False, markup=False)
    if read_as and any(p.read_as_text for p in result.parts):
        console.print("Your answer, as lagrade read it:", style="bold")
        for p in result.parts:
            if p.read_as_text:
                lines = p.read_as_text.splitlines() or [""]
                if len(lines) == 1:
                    console.print(f"  {p.part} = {lines[0]}", highlight=False, markup=False, soft_wrap=True)
                else:
                    console.print(f"  {p.part} =", highlight=False, markup=False)
                    for line in lines:
                        console.print(f"      {line}", highlight=False, markup=False, soft_wrap=True)
        console.print()
    console.print(table(result))


def render_text(result: CheckResult, width: int = 110) -> str:
    console = Console(width=width, record=True, file=None, force_terminal=False, color_system=None)
    with console.capture() as cap:
        render(result, console)
    return cap.get()
