"""``lagrade check``: one answer file, graded by the library's one entry (:func:`lagrade.verdicts.grade.check`,
which stages the start for speed), shown, and the exit code.

Exit codes: 0 every part correct, 1 graded but not full marks, 2 the answer file or the arguments
could not be used.
"""

from __future__ import annotations

from pathlib import Path

import click

from lagrade.cli.common import fail, leave, problems_option


@click.command()
@click.argument("problem_id")
@click.argument("answer", type=click.Path(path_type=Path))
@click.option("--json", "as_json", is_flag=True, help="Print exactly one JSON object.")
@click.option("--accuracy", type=click.Choice(["fast", "default", "strict"]), default="default",
              show_default=True, help="the presets' sample_rtol (the feedback of a correct part says it), which decides every dynamics part at the sampled states and the "
                   "states the true motion visits; the integration's tolerance and the number of motions "
                   "(which states are visited); and the trajectory comparison's tolerance, which only "
                   "explains a rejection or, rarely, refutes (docs/numerics.md, section 5).")
@click.option("--part", "only", multiple=True, help="Grade only these parts.")
@click.option("--hints", is_flag=True, help="More specific feedback: which term is missing or extra.")
@click.option("--credit", "credit_file", type=click.Path(exists=True, path_type=Path),
              help="TOML file with a [credit] table changing the partial-credit defaults.")
@click.option("--plot", "plot_file", type=click.Path(path_type=Path),
              help="PNG with your motion against the true one for each incorrect dynamics part (in a folder that exists).")
@click.option("--grading-seconds", type=click.FloatRange(min=0, min_open=True), default=None,
              help="CPU seconds to grade the values once the file has run (default: bulk grading's grading_seconds).")
@click.option("--server", help="Have this course server grade it (http://host:8000); see docs/server.md.")
@click.option("--token", envvar="LAGRADE_TOKEN", help="Your token for --server (also LAGRADE_TOKEN).")
@problems_option
def check(problem_id: str, answer: Path, as_json: bool, accuracy: str, only: tuple[str, ...], hints: bool,
          credit_file: Path | None, plot_file: Path | None, grading_seconds: float | None,
          server: str | None, token: str | None, problems_dir: tuple[Path, ...]) -> None:
    """Grade ANSWER (answer.py, answer.toml or a Jupyter notebook, answer.ipynb) for PROBLEM_ID."""
    if server:  # the server grades: no problem data, no reference here
        from lagrade.cli.serve import check_on_server

        leave(check_on_server(server, token, problem_id, answer, as_json))
    if not answer.is_file():
        fail(f"{answer}: no such answer file", as_json)
    if plot_file is not None:  # before grading, and no folder is made: a typo must not become a tree of folders
        folder = plot_file.parent
        if not folder.exists():
            fail(f"--plot {plot_file}: the folder {folder} does not exist (create it, or give a path in a folder "
                 f"that exists)", as_json)
        if not folder.is_dir():
            fail(f"--plot {plot_file}: {folder} is not a folder", as_json)
    from lagrade.verdicts.credit import load_credit

    try:
        credit = load_credit(credit_file) if credit_file else None
    except (ValueError, OSError) as exc:
        fail(f"{credit_file}: {exc}", as_json)
    from lagrade.verdicts import grade
    from lagrade.problem.spec import SpecError

    try:
        result = grade.check(problem_id, answer, problem_dirs=problems_dir, accuracy=accuracy, only=list(only) or None,
                             hints=hints, credit=credit, read_as=("latex",) if as_json else ("unicode",),
                             grading_seconds=grading_seconds, meanwhile=None if as_json else _import_rich)
    except (SpecError, grade.UnknownPartError) as exc:  # a scene error: the problem file's line
        fail(str(exc), as_json)
    if plot_file is not None:
        from lagrade.verdicts.plot import plot_result

        try:
            drawn = plot_result(result, plot_file)
        except OSError as exc:  # not writable, or the folder went away meanwhile
            fail(f"--plot {plot_file}: cannot write it ({exc.strerror or exc})", as_json)
        if not as_json:
            click.echo(f"plot: {plot_file}" if drawn else "plot: no incorrect dynamics part to draw", err=True)
    if as_json:
        from lagrade.verdicts.printable import json_printable

        click.echo(json_printable(result.model_dump_json()))  # the student's text, escaped as JSON does
    else:
        from rich.console import Console

        from lagrade.problem.library import load_problem
        from lagrade.verdicts.result import render
        from lagrade.verdicts.words import in_words

        kinds = {p.name: p.kind for p in load_problem(problem_id, problems_dir).parts}
        for p in result.parts:  # the evidence in words; its settings stay in --json
            p.feedback = in_words(p.feedback, kinds.get(p.part, ""))
        render(result, Console(highlight=False))
    from lagrade.problem.library import load_problem

    grade.keep_references(load_problem(problem_id, problems_dir))  # after the output: the next check starts warm
    leave(2 if grade.unusable(result) else (0 if result.full_marks else 1))


def _import_rich() -> None:
    """Only for people, while the answer runs: --json never pays for it."""
    import rich.console  # noqa: F401
