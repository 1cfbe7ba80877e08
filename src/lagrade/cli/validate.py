"""``lagrade validate``: prove problem files before students see them (lagrade.uses.validate).

Exit codes: 0 every check of every problem holds, 1 one does not (each such line says which).
"""

from __future__ import annotations

import json
from pathlib import Path

import click

from lagrade.cli.common import leave, problems_option


@click.command()
@click.argument("targets", nargs=-1, required=True, metavar="FILE_OR_ID...")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object: a report per problem.")
@click.option("--seed", type=int, default=0, show_default=True,
              help="Which generated answers are drawn when a part has more than --count.")
@click.option("--count", type=click.IntRange(min=0), default=8, show_default=True,
              help="At most this many generated right and this many generated wrong answers per part.")
@click.option("--all-cases", is_flag=True, help="List every check, not only those that fail.")
@problems_option
def validate(targets: tuple[str, ...], as_json: bool, seed: int, count: int, all_cases: bool,
             problems_dir: tuple[Path, ...]) -> None:
    """Check problem files (or ids): schema and domains, the reference graded full marks, each named
    mistake refused with its own message, generated right answers full marks, generated wrong ones
    refused, and the statement, figure and typing help rendered."""
    from lagrade.uses.validate.run import validate as run_one

    reports = []
    console = None
    if not as_json:
        from rich.console import Console

        console = Console(highlight=False)
    for target in targets:
        report = run_one(target, problems_dir, seed=seed, count=count)
        reports.append(report)
        if console is not None:
            _show(console, report, all_cases)
    ok = all(r.ok for r in reports)
    if as_json:
        click.echo(json.dumps({"ok": ok, "problems": [r.as_json() for r in reports]}, indent=1))
    else:
        failed = [r.problem for r in reports if not r.ok]
        console.print(f"{len(reports) - len(failed)} of {len(reports)} problems valid"
                      + (f"; failing: {', '.join(failed)}" if failed else ""), markup=False)
    leave(0 if ok else 1)


def _show(console, report, all_cases: bool) -> None:
    from rich.table import Table

    s = report.summary()
    table = Table(title=f"{report.problem}  {report.title}", title_justify="left")
    for column in ("check", "cases", "hold", "fail"):
        table.add_column(column, justify="left" if column == "check" else "right")
    for check in ("schema", "render", "reference", "solution", "mistake", "right", "wrong", "dropped"):
        n = report.count(check)
        if n:
            bad = report.count(check, ok=False)
            table.add_row(check, str(n), str(n - bad), f"[red]{bad}[/red]" if bad else "0")
    console.print(table)
    console.print(f"  {s['right']} right and {s['wrong']} wrong generated answers ({s['dropped']} proved right and "
                  f"dropped), {s['false_rejects']} false rejects, {s['false_accepts']} false accepts, "
                  f"{report.seconds:.1f} s: {'VALID' if report.ok else 'NOT VALID'}", markup=False)
    for case in report.cases:
        if not case.ok or all_cases:
            mark = "ok  " if case.ok else "FAIL"
            console.print(f"  {mark} {case.check} {case.part} {case.label}: {case.detail or case.verdict}".rstrip(": "),
                          markup=False)
