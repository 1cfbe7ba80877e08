"""The ``lagrade`` command: list, show, template, check.

Exit codes of ``check``: 0 every part correct, 1 graded but not full marks, 2 the answer file or
the arguments could not be used.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import NoReturn

import click

from lagrade import __version__
from lagrade.process_env import single_threaded_blas
from lagrade.spec import Problem, SpecError

EXPECTS = {
    "lagrangian": "expression in the coordinates q(t), their velocities q(t).diff(t), parameters and t",
    "eom": "list of Eq(lhs, rhs) (or expressions meaning = 0), one per coordinate",
    "hamiltonian": "expression in the coordinates and momenta p_<q> (symbols or functions of t)",
    "hamilton_eqs": "list of 2n equations in Derivative(q(t), t) and Derivative(p_q(t), t)",
    "expression": "expression in the parameters (and the state where it depends on it)",
    "expression_set": "list of expressions, in any order",
    "equation_root": "the value, or an equation it satisfies (e.g. Eq(cos(theta), 2/3))",
    "boolean": "True or False",
    "integer": "a whole number",
    "names": "list of coordinate names (strings) or coordinates",
    "conserved": "list of expressions constant along the motion (momenta may be written p_<q>)",
    "trajectory": "dict coordinate name -> expression in t",
}


def _problem(pid: str, problems_dir: tuple[Path, ...]) -> Problem:
    from lagrade.library import load_problem

    try:
        return load_problem(pid, problems_dir)
    except SpecError as exc:
        raise click.UsageError(str(exc)) from None


problems_option = click.option("--problems", "problems_dir", multiple=True, type=click.Path(path_type=Path),
                               help="Extra folder of problem files (also LAGRADE_PROBLEMS).")


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="lagrade")
def main() -> None:
    """Grade answers to the Lagrangian and Hamiltonian dynamics problems of chapter 12."""


@main.command("list")
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
    if as_json:
        click.echo(json.dumps(rows, indent=1))
        return
    for r in rows:
        click.echo(f"{r['id']:>8}  {r['parts']:>2} parts  {r['title']}")


@main.command()
@click.argument("problem_id")
@problems_option
def show(problem_id: str, problems_dir: tuple[Path, ...]) -> None:
    """Statement, assumptions, symbols to use and the parts asked."""
    p = _problem(problem_id, problems_dir)
    out = [f"Problem {p.id}: {p.title}", ""]
    if p.statement:
        out += [p.statement.strip(), ""]
    if p.assumptions:
        out += ["Assumptions:"] + [f"  - {a}" for a in p.assumptions] + [""]
    if p.parameters:
        out.append("Parameters (symbols, matched by name):")
        out += [f"  {q.name:<10} {q.description}{' (> 0)' if q.positive else ''}" for q in p.parameters]
        out.append("")
    for s in p.systems:
        label = f"System ({s.key}) {s.title}".rstrip() if s.key else "Coordinates"
        out.append(f"{label}:" if s.key else "Coordinates (functions of t):")
        out += [f"  {c.name + '(t)':<12} {c.description}" for c in s.coordinates]
        for c in s.constraints:
            out.append(f"  constraint: {c.coordinate} = {c.value}" +
                       (f"  (multiplier {c.multiplier})" if c.multiplier else ""))
        for q in s.parameters:
            out.append(f"  parameter {q.name:<10} {q.description}{' (> 0)' if q.positive else ''}")
        out.append(f"  effects: {', '.join(s.effects) or 'none'}")
        out.append("")
    out.append("Parts (bind these names in answer.py):")
    for part in p.parts:
        alias = f" (also {', '.join(part.aliases)})" if part.aliases else ""
        sys_note = f" [system {part.system}]" if part.system else ""
        out.append(f"  {part.name:<12} {part.prompt or part.kind}{sys_note}{alias}")
        detail = EXPECTS[part.kind]
        if part.kind == "expression" and isinstance(part.reference, dict):
            detail = f"dict with keys {', '.join(repr(k) for k in part.reference)}"
        if part.linearized:
            detail += "; linearized about equilibrium"
        if part.symbols:
            detail += f"; may use {', '.join(part.symbols)}"
        out.append(f"  {'':<12}   -> {detail}")
    click.echo("\n".join(out))


@main.command()
@click.argument("problem_id")
@problems_option
def template(problem_id: str, problems_dir: tuple[Path, ...]) -> None:
    """A skeleton answer.py with every part as a name to fill."""
    p = _problem(problem_id, problems_dir)
    lines = [f'"""Answer to problem {p.id}: {p.title}."""', "", "from lagrade.answer import *", ""]
    params = " ".join(q.name for q in p.parameters)
    if params:
        lines.append(f"{', '.join(q.name for q in p.parameters)} = parameters(\"{params}\")")
    for s in p.systems:
        if s.parameters:
            names = [q.name for q in s.parameters]
            lines.append(f"# system ({s.key}) only: {', '.join(names)} = parameters(\"{' '.join(names)}\")")
    for s in p.systems:
        names = [c.name for c in s.coordinates]
        if s.key:
            lines.append(f"# system ({s.key}) {s.title}")
        lines.append(f"{', '.join(names)} = coordinates(\"{' '.join(names)}\")")
        if any(part.kind in ("hamiltonian", "hamilton_eqs") and part.system == s.key for part in p.parts):
            moms = [f"p_{n}" for n in names]
            lines.append(f"{', '.join(moms)} = momenta(\"{' '.join(moms)}\")")
    lines.append("")
    for part in p.parts:
        lines.append(f"# {part.prompt or part.kind}: {EXPECTS[part.kind]}")
        if part.kind == "expression" and isinstance(part.reference, dict):
            lines.append(f"# {part.name} = {{{', '.join(f'{k!r}: ...' for k in part.reference)}}}")
        else:
            lines.append(f"# {part.name} = ")
        lines.append("")
    click.echo("\n".join(lines).rstrip() + "\n")


@main.command()
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
@problems_option
def check(problem_id: str, answer: Path, as_json: bool, accuracy: str, only: tuple[str, ...], hints: bool,
          credit_file: Path | None, plot_file: Path | None, grading_seconds: float | None,
          problems_dir: tuple[Path, ...]) -> None:
    """Grade ANSWER (answer.py or answer.toml) for PROBLEM_ID."""
    from lagrade.answers.load import start_loading

    if answer.suffix == ".py":
        from lagrade.answers import zygote

        zygote.current()  # started by the script already (lagrade.launch), or now: it imports sympy meanwhile
    try:
        p = _problem(problem_id, problems_dir)
    except click.UsageError as exc:
        _fail(str(exc), as_json)
    if not answer.is_file():
        _fail(f"{answer}: no such answer file", as_json)
    unknown = [o for o in only if o not in {part.name for part in p.parts}]
    if unknown:
        _fail(f"problem {p.id} has no part {', '.join(unknown)}", as_json)
    from lagrade.credit import load_credit

    try:
        credit = load_credit(credit_file) if credit_file else None
    except (ValueError, OSError) as exc:
        _fail(f"{credit_file}: {exc}", as_json)
    finish_loading = start_loading(answer, p)  # an answer.py runs in its sandbox child from here on
    # meanwhile (two cores, two things): the grader's imports, and the reference derivations (from
    # the disk cache, or derived now)
    from lagrade.grade import default_grading_seconds, grade_values, references

    grading_seconds = grading_seconds or default_grading_seconds()  # bounded like bulk grading
    refs = references(p)
    for system in p.systems:
        refs[system.key]
    from lagrade.native import available

    available()  # loads LLVM (about 20 ms) now rather than when the answer's equations are compiled
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
        from lagrade.result import render

        from rich.console import Console  # only for people: --json never pays for it

        render(result, Console(highlight=False))
    from lagrade.grade import keep_references

    keep_references(p)  # after the output: the next check of this problem starts warm
    unusable = loaded.fatal is not None and not loaded.values
    _leave(2 if unusable else (0 if result.full_marks else 1))


#: set by `run`: lagrade is a process of its own (the console script, ``python -m lagrade``), not
#: a command invoked inside another program (click's test runner, a notebook)
_OWN_PROCESS = False


def run() -> None:
    """The ``lagrade`` console script."""
    global _OWN_PROCESS
    _OWN_PROCESS = True
    single_threaded_blas(os.environ)
    main()


def _leave(code: int) -> NoReturn:
    """Exit; in a process of its own, at once. Everything is printed and saved by then, and the
    interpreter's teardown (freeing sympy's objects one by one) took 0.25-0.3 s: a quarter of a
    check, after its output, before the shell or a script could go on."""
    if _OWN_PROCESS:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):  # a closed pipe (| head): nothing more to say
                pass
        os._exit(code)
    sys.exit(code)


def _fail(message: str, as_json: bool) -> None:
    if as_json:
        click.echo(json.dumps({"error": message}))
    else:
        click.echo(f"lagrade: {message}", err=True)
    sys.exit(2)


def _register() -> None:
    """Bulk grading and numerics benchmarks live in their own modules; the group only lists them."""
    from lagrade.cli_bench import bench
    from lagrade.cli_bulk import export, grade, gradescope, report
    from lagrade.cli_cache import cache
    from lagrade.cli_doctor import doctor

    for command in (grade, export, report, gradescope, bench, cache, doctor):
        main.add_command(command)


_register()
