"""``lagrade check``: one answer file, graded as fast as the machine allows.

Exit codes: 0 every part correct, 1 graded but not full marks, 2 the answer file or the arguments
could not be used. The start is staged by hand for speed: an ``answer.py`` runs in its jailed child
while this process imports the grader and loads the references (docs/performance.md).
"""

from __future__ import annotations

from pathlib import Path

import click

from lagrade.cli.common import fail, leave, problem_or_usage_error, problems_option


@click.command()
@click.argument("problem_id")
@click.argument("answer", type=click.Path(path_type=Path))
@click.option("--json", "as_json", is_flag=True, help="Print exactly one JSON object.")
@click.option("--accuracy", type=click.Choice(["fast", "default", "strict"]), default="default",
              show_default=True, help="Tolerances of the trajectory comparison.")
@click.option("--part", "only", multiple=True, help="Grade only these parts.")
@click.option("--hints", is_flag=True, help="More specific feedback: which term is missing or extra.")
@click.option("--credit", "credit_file", type=click.Path(exists=True, path_type=Path),
              help="TOML file with a [credit] table changing the partial-credit defaults.")
@click.option("--plot", "plot_file", type=click.Path(path_type=Path),
              help="PNG with your motion against the true one for each incorrect dynamics part.")
@click.option("--grading-seconds", type=click.FloatRange(min=0, min_open=True), default=None,
              help="CPU seconds to grade the values once the file has run (default: bulk grading's grading_seconds).")
@click.option("--server", help="Have this course server grade it (http://host:8000); see docs/server.md.")
@click.option("--token", envvar="LAGRADE_TOKEN", help="Your token for --server (also LAGRADE_TOKEN).")
@problems_option
def check(problem_id: str, answer: Path, as_json: bool, accuracy: str, only: tuple[str, ...], hints: bool,
          credit_file: Path | None, plot_file: Path | None, grading_seconds: float | None,
          server: str | None, token: str | None, problems_dir: tuple[Path, ...]) -> None:
    """Grade ANSWER (answer.py or answer.toml) for PROBLEM_ID."""
    if server:  # the server grades: no problem data, no reference here
        from lagrade.cli.serve import check_on_server

        leave(check_on_server(server, token, problem_id, answer, as_json))
    from lagrade.answers.load import start_loading

    if answer.suffix == ".py":
        from lagrade.answers import zygote

        zygote.current()  # started by the script already (lagrade.launch), or now: it imports sympy meanwhile
    try:
        p = problem_or_usage_error(problem_id, problems_dir)
    except click.UsageError as exc:
        fail(str(exc), as_json)
    if not answer.is_file():
        fail(f"{answer}: no such answer file", as_json)
    unknown = [o for o in only if o not in {part.name for part in p.parts}]
    if unknown:
        fail(f"problem {p.id} has no part {', '.join(unknown)}", as_json)
    from lagrade.credit import load_credit

    try:
        credit = load_credit(credit_file) if credit_file else None
    except (ValueError, OSError) as exc:
        fail(f"{credit_file}: {exc}", as_json)
    finish_loading = start_loading(answer, p)  # an answer.py runs in its sandbox child from here on
    # meanwhile (two cores, two things): the grader's imports, and the reference derivations (from
    # the disk cache, or derived now)
    from lagrade.grade import default_grading_seconds, grade_values, references
    from lagrade.spec import SceneError

    grading_seconds = grading_seconds or default_grading_seconds()  # bounded like bulk grading
    refs = references(p)
    try:
        for system in p.systems:
            refs[system.key]
    except SceneError as exc:  # the problem file's fault, not the answer's: its file and line
        fail(scene_message(p, exc, problems_dir), as_json)
    if not as_json:
        import rich.console  # noqa: F401
    loaded = finish_loading()
    result = grade_values(p, loaded, accuracy, list(only) or None, hints=hints, credit=credit,
                          read_as=("latex",) if as_json else ("unicode",),
                          grading_seconds=grading_seconds)
    if plot_file is not None:
        from lagrade.plot import plot_result

        drawn = plot_result(result, plot_file)
        if not as_json:
            click.echo(f"plot: {plot_file}" if drawn else "plot: no incorrect dynamics part to draw", err=True)
    if as_json:
        click.echo(result.model_dump_json())
    else:
        from rich.console import Console  # only for people: --json never pays for it

        from lagrade.result import render

        render(result, Console(highlight=False))
    from lagrade.grade import keep_references

    keep_references(p)  # after the output: the next check of this problem starts warm
    unusable = loaded.fatal is not None and not loaded.values
    leave(2 if unusable else (0 if result.full_marks else 1))


def scene_message(problem, exc, problems_dir: tuple[Path, ...]) -> str:
    """``problems/12.35.toml:30: the scene uses effects it does not declare ...``: one line."""
    from lagrade.library import problem_path
    from lagrade.spec import scene_line

    try:
        path = problem_path(problem.id, problems_dir)
    except (KeyError, FileNotFoundError, ValueError):
        return f"problem {problem.id}: {exc}"
    line = scene_line(path, exc.system, exc.field) if getattr(exc, "field", None) else None
    return f"{path}:{line}: {exc}" if line else f"{path}: {exc}"

