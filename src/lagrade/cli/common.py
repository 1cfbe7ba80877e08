"""What every command shares: the ``--problems`` option, one-line failures, and leaving at once."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import NoReturn

import click

from lagrade.problem.spec import Problem, SpecError

problems_option = click.option("--problems", "problems_dir", multiple=True, type=click.Path(path_type=Path),
                               help="Extra folder of problem files (also LAGRADE_PROBLEMS).")

#: set by `lagrade.cli.run`: lagrade is a process of its own (the console script, ``python -m
#: lagrade``), not a command invoked inside another program (click's test runner, a notebook)
OWN_PROCESS = False


def problem_or_usage_error(pid: str, problems_dir: tuple[Path, ...]) -> Problem:
    from lagrade.problem.library import load_problem

    try:
        return load_problem(pid, problems_dir)
    except SpecError as exc:
        raise click.UsageError(str(exc)) from None


def leave(code: int) -> NoReturn:
    """Exit; in a process of its own, at once. Everything is printed and saved by then, and the
    interpreter's teardown (freeing sympy's objects one by one) took 0.25-0.3 s: a quarter of a
    check, after its output, before the shell or a script could go on."""
    if OWN_PROCESS:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):  # a closed pipe (| head): nothing more to say
                pass
        os._exit(code)
    sys.exit(code)


def fail(message: str, as_json: bool) -> NoReturn:
    """A one-line error (or one JSON object) and exit code 2: the answer or the arguments were unusable."""
    from lagrade.verdicts.printable import printable

    if as_json:
        click.echo(json.dumps({"error": message}))  # ASCII: every control character escaped
    else:
        click.echo(f"lagrade: {printable(message)}", err=True)
    sys.exit(2)
