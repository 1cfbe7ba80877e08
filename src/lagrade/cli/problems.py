"""``lagrade list``, ``show`` and ``template``: the problems, as a student reads them."""

from __future__ import annotations

import json
from pathlib import Path

import click

from lagrade.cli.common import problem_or_usage_error, problems_option
from lagrade.spec import SpecError


@click.command("list")
@click.option("--json", "as_json", is_flag=True, help="Print the list as JSON.")
@problems_option
def list_cmd(as_json: bool, problems_dir: tuple[Path, ...]) -> None:
    """Every problem and exercise, with its title and number of parts."""
    from lagrade.library import load_problem, problem_ids

    rows = []
    for pid in problem_ids(problems_dir):
        try:
            p = load_problem(pid, problems_dir)
            rows.append({"id": p.id, "title": p.title, "parts": len(p.parts),
                         "names": [part.name for part in p.parts]})
        except SpecError as exc:
            rows.append({"id": pid, "title": f"(broken problem file: {exc})", "parts": 0, "names": []})
    if not rows:  # a student's client, or a course's folder not found: say so, not nothing
        from lagrade.library import NO_DATA

        click.echo(f"lagrade: {NO_DATA}", err=True)
    if as_json:
        click.echo(json.dumps(rows, indent=1))
        return
    for r in rows:
        click.echo(f"{r['id']:>8}  {r['parts']:>2} parts  {r['title']}")


@click.command()
@click.argument("problem_id", required=False)
@click.option("--schema", type=click.Choice(["json", "markdown"]),
              help="Instead of a problem: the problem-file format (JSON Schema, or the tables of "
                   "docs/authoring-problems.md).")
@problems_option
def show(problem_id: str | None, schema: str | None, problems_dir: tuple[Path, ...]) -> None:
    """Statement, assumptions, symbols to use and the parts asked."""
    if schema:
        from lagrade.spec import Problem, markdown_tables

        click.echo(json.dumps(Problem.model_json_schema(), indent=1) if schema == "json" else markdown_tables())
        return
    if problem_id is None:
        raise click.UsageError("give a problem id (lagrade list shows them), or --schema")
    from lagrade.describe import show_text

    click.echo(show_text(problem_or_usage_error(problem_id, problems_dir)))


@click.command()
@click.argument("problem_id")
@problems_option
def template(problem_id: str, problems_dir: tuple[Path, ...]) -> None:
    """A skeleton answer.py with every part as a name to fill."""
    from lagrade.describe import template_text

    click.echo(template_text(problem_or_usage_error(problem_id, problems_dir)), nl=False)
