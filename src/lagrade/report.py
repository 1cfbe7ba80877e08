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


def render(result: CheckResult, console: Console) -> None:
    for problem in result.problems:
        console.print(problem, style="yellow", highlight=False, markup=False)
    console.print(table(result))


def render_text(result: CheckResult, width: int = 110) -> str:
    console = Console(width=width, record=True, file=None, force_terminal=False, color_system=None)
    with console.capture() as cap:
        render(result, console)
    return cap.get()
