"""``lagrade list``, ``show`` and ``template``: the problems, as a student reads them."""

from __future__ import annotations

import json
from pathlib import Path

import click

from lagrade.cli.common import problem_or_usage_error, problems_option
from lagrade.problem.spec import SpecError


@click.command("list")
@click.option("--json", "as_json", is_flag=True, help="Print the list as JSON.")
@problems_option
def list_cmd(as_json: bool, problems_dir: tuple[Path, ...]) -> None:
    """Every problem and exercise, with its title and number of parts."""
    from lagrade.problem.library import load_problem, problem_ids

    rows = []
    for pid in problem_ids(problems_dir):
        try:
            p = load_problem(pid, problems_dir)
            rows.append({"id": p.id, "title": p.title, "parts": len(p.parts),
                         "names": [part.name for part in p.parts]})
        except SpecError as exc:
            rows.append({"id": pid, "title": f"(broken problem file: {exc})", "parts": 0, "names": []})
    if not rows:  # a student's client, or a course's folder not found: say so, not nothing
        from lagrade.problem.library import NO_DATA

        click.echo(f"lagrade: {NO_DATA}", err=True)
    if as_json:
        click.echo(json.dumps(rows, indent=1))
        return
    for r in rows:
        click.echo(f"{r['id']:>8}  {r['parts']:>2} parts  {r['title']}")


server_option = click.option("--server", help="Read the problem from this course server (http://host:8000): no "
                                              "problem data needed here; see docs/server.md.")
token_option = click.option("--token", envvar="LAGRADE_TOKEN", help="Your token for --server (also LAGRADE_TOKEN).")


def _from_server(server: str, token: str | None, problem_id: str, key: str) -> str:
    from lagrade.uses.server.client import ClientError, remote_problem

    try:
        return remote_problem(server, token, problem_id)[key]
    except (ClientError, KeyError) as exc:
        raise click.ClickException(str(exc).splitlines()[0] if str(exc) else f"the server gave no {key}") from None


@click.command()
@click.argument("problem_id", required=False)
@click.option("--schema", type=click.Choice(["json", "markdown"]),
              help="Instead of a problem: the problem-file format (JSON Schema, or the tables of "
                   "docs/authoring-problems.md).")
@click.option("--figure", "figure_file", type=click.Path(dir_okay=False, path_type=Path),
              help="Also save the problem's figure, drawn from its scene, as this PNG.")
@server_option
@token_option
@problems_option
def show(problem_id: str | None, schema: str | None, figure_file: Path | None, server: str | None,
         token: str | None, problems_dir: tuple[Path, ...]) -> None:
    """Statement, assumptions, symbols to use and the parts asked."""
    if schema:
        from lagrade.problem.spec import Problem, markdown_tables

        click.echo(json.dumps(Problem.model_json_schema(), indent=1) if schema == "json" else markdown_tables())
        return
    if problem_id is None:
        raise click.UsageError("give a problem id (lagrade list shows them), or --schema")
    if server:  # the course server has the problem: nothing of it is needed here
        click.echo(_from_server(server, token, problem_id, "show"), nl=False)
        if figure_file is not None:
            from lagrade.uses.server.client import ClientError, remote_figure

            try:
                figure_file.write_bytes(remote_figure(server, token, problem_id))
            except ClientError as exc:
                raise click.ClickException(str(exc)) from None
            click.echo(f"figure: {figure_file}", err=True)
        return
    from lagrade.problem.describe import show_text

    problem = problem_or_usage_error(problem_id, problems_dir)
    click.echo(show_text(problem))
    if figure_file is not None:
        from lagrade.verdicts.figure import draw

        figure_file.write_bytes(draw(problem))
        click.echo(f"figure: {figure_file}", err=True)


@click.command()
@click.argument("problem_id")
@click.option("--notebook", is_flag=True, help="A Jupyter notebook instead (answer.ipynb): the statement, one cell "
                                                "per part and a cell that checks the answer (docs/notebooks.md).")
@server_option
@token_option
@problems_option
def template(problem_id: str, notebook: bool, server: str | None, token: str | None,
             problems_dir: tuple[Path, ...]) -> None:
    """A skeleton answer.py with every part as a name to fill (--notebook: answer.ipynb)."""
    if server:
        if notebook:
            raise click.UsageError("--notebook is made from the problem file: not with --server (use "
                                   "'lagrade template ID --server URL' for answer.py)")
        click.echo(_from_server(server, token, problem_id, "template"), nl=False)
        return
    from lagrade.problem.describe import notebook_text, template_text

    problem = problem_or_usage_error(problem_id, problems_dir)
    click.echo((notebook_text if notebook else template_text)(problem), nl=False)
