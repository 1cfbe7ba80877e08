"""Instructor commands: ``lagrade grade``, ``export``, ``report`` and ``gradescope``.

Module-level click commands, registered on the main group by ``lagrade.cli``. Heavy imports are
deferred so that ``lagrade --help`` stays fast.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

import click

problems_option = click.option("--problems", "problems_dir", multiple=True, type=click.Path(path_type=Path),
                               help="Extra folder of problem files (also LAGRADE_PROBLEMS).")


#: a gradebook path as click passes it on: what it is, and whether it can be read, is the Store's to
#: say (one line naming the file and what to do, exit 2), not a click usage error
GRADEBOOK_PATH = click.Path(path_type=Path, readable=False)


class GradebookError(click.ClickException):
    """``lagrade: <what is wrong with the gradebook>; <what to do>`` on one line of stderr, exit 2."""

    exit_code = 2

    def show(self, file=None) -> None:  # noqa: ARG002
        click.echo(f"lagrade: {self.message}", err=True)


def _gradebook_error(db: Path, exc: Exception, hint: str) -> GradebookError:
    """The one-line error for a gradebook that cannot be used; SQLite's own errors get the file named."""
    import sqlite3

    from lagrade.bulk.store import NotAGradebook

    if isinstance(exc, NotAGradebook):
        what = str(exc)
    elif isinstance(exc, sqlite3.DatabaseError):
        what = f"{db} is not a lagrade gradebook ({exc})"
    elif isinstance(exc, ValueError):
        what = f"{db} is not a lagrade gradebook (its stored assignment cannot be read: {exc})"
    else:  # another writer, another schema version, nothing graded yet: the message says what to do
        return GradebookError(str(exc))
    return GradebookError(f"{' '.join(what.split())}; {hint}")


def _assignment(path: Path, problems_dir: tuple[Path, ...]):
    from lagrade.bulk.assignment import AssignmentError, check_against_problems, load_assignment

    try:
        a = load_assignment(path)
        check_against_problems(a, problems_dir)
        return a
    except AssignmentError as exc:
        raise click.UsageError(str(exc)) from None


@click.command("grade")
@click.argument("submissions", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--assignment", "-a", "assignment_path", required=True,
              type=click.Path(exists=True, dir_okay=False, path_type=Path), help="The assignment TOML file.")
@click.option("--db", type=GRADEBOOK_PATH,
              help="The gradebook database (SQLite; default: <assignment>.sqlite next to the assignment).")
@click.option("--workers", "-j", type=click.IntRange(min=1), help="Grader processes (default: all cores).")
@click.option("--scheduler", help="Grade on an existing Dask cluster (tcp://host:8786; needs lagrade[dask]).")
@click.option("--regrade", is_flag=True, help="Grade every submission again, even unchanged ones.")
@click.option("--progress/--no-progress", default=None, help="Progress bar (default: when stderr is a terminal).")
@click.option("--summary/--no-summary", default=True, show_default=True, help="Print the class summary at the end.")
@click.option("--unsafe-trusted-files", is_flag=True,
              help="Grade even where the OS jail cannot be built (see `lagrade doctor`): only for files you trust.")
@problems_option
def grade(submissions: Path, assignment_path: Path, db: Path | None, workers: int | None, scheduler: str | None,
          regrade: bool, progress: bool | None, summary: bool, unsafe_trusted_files: bool,
          problems_dir: tuple[Path, ...]) -> None:
    """Grade a class folder SUBMISSIONS/<student>/<problem-id>.py (or .toml) into a database.

    Only new or changed files are graded when run again; every result is saved as soon as it is
    graded, so an interrupted run resumes where it stopped.
    """
    import sqlite3

    from rich.console import Console

    from lagrade.bulk.runner import grade_folder
    from lagrade.bulk.store import StoreError

    a = _assignment(assignment_path, problems_dir)
    db = db or assignment_path.with_suffix(".sqlite")
    err = Console(stderr=True, highlight=False)
    _require_jail(unsafe_trusted_files, err)  # on a Dask cluster, each file's row records its worker's layers
    show = err.is_terminal if progress is None else progress
    bar = _ProgressBar(err, show)
    try:
        with bar:
            report = grade_folder(submissions, a, db, workers=workers, scheduler=scheduler, problems_dirs=problems_dir,
                                  on_start=bar.start, on_result=bar.advance, regrade=regrade)
    except (StoreError, sqlite3.DatabaseError) as exc:
        raise _gradebook_error(db, exc, "give another --db path or move it away") from None
    except KeyboardInterrupt:
        err.print("interrupted: every submission graded so far is saved; run the same command to go on")
        sys.exit(130)
    out = Console(highlight=False)
    rate = report.todo / report.seconds * 60 if report.seconds else 0.0
    out.print(f"{report.total} submissions: {report.todo} graded now ({report.failed} could not be graded), "
              f"{report.up_to_date} unchanged; {len(report.skipped)} files skipped; "
              f"{report.seconds:.1f} s on {report.workers} {'Dask threads' if report.backend == 'dask' else 'processes'}"
              + (f" ({rate:.0f} per minute)" if report.todo else "") + f" -> {db}")
    if report.removed:
        out.print(f"{report.removed} earlier results removed: their files are gone")
    for s in report.skipped[:20]:
        out.print(f"  skipped {s.path}: {s.reason}")
    if len(report.skipped) > 20:
        out.print(f"  ... and {len(report.skipped) - 20} more (lagrade export {db} --format skipped)")
    if summary:
        from lagrade.bulk.gradebook import load_gradebook
        from lagrade.bulk.summary import render_summary

        render_summary(load_gradebook(db), out)


def _require_jail(unsafe: bool, err) -> None:
    """Refuse to run a class's files where the OS jail cannot be built, unless told they are trusted."""
    from lagrade.answers import jail, zygote

    try:
        probe = zygote.Zygote()
        try:
            lacking = jail.missing_minimum(probe.hello()["active"])
        finally:
            probe.close()
    except OSError as exc:
        lacking = f"the sandbox could not start ({exc})"
    if lacking and not unsafe:
        raise click.ClickException(f"refusing to run students' files: {lacking} on this machine (`lagrade doctor` "
                                   "says why); give --unsafe-trusted-files only if you trust every file")
    if lacking:
        err.print(f"warning: {lacking}; grading anyway (--unsafe-trusted-files); the gradebook records the layers")




class _ProgressBar:
    """done, failed, rate, time left; on stderr, so that stdout stays clean."""

    def __init__(self, console, show: bool) -> None:
        self.console, self.show = console, show
        self.progress = None
        self.task = None
        self.failed = 0
        self.t0 = 0.0

    def __enter__(self) -> "_ProgressBar":
        import time

        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

        self.t0 = time.monotonic()
        if self.show:
            self.progress = Progress(TextColumn("grading"), BarColumn(), MofNCompleteColumn(),
                                     TextColumn("[red]{task.fields[failed]} failed"),
                                     TextColumn("{task.fields[rate]}/min"), TimeRemainingColumn(),
                                     console=self.console, transient=False)
            self.progress.__enter__()
        return self

    def __exit__(self, *exc) -> None:
        if self.progress is not None:
            self.progress.__exit__(*exc)

    def start(self, todo: int, up_to_date: int) -> None:
        if self.progress is not None:
            self.task = self.progress.add_task("grading", total=todo, failed=0, rate="-")

    def advance(self, result: dict) -> None:
        import time

        if result["outcome"] == "failed":
            self.failed += 1
        if self.progress is not None and self.task is not None:
            done = self.progress.tasks[0].completed + 1
            rate = done / max(1e-9, time.monotonic() - self.t0) * 60
            self.progress.update(self.task, advance=1, failed=self.failed, rate=f"{rate:.0f}")


def _book(db: Path):
    """The gradebook at ``db``, or one line saying why it cannot be read (a damaged page, a mangled
    stored assignment: whatever the file holds is not trusted)."""
    import sqlite3

    from lagrade.bulk.gradebook import load_gradebook
    from lagrade.bulk.store import StoreError

    try:
        return load_gradebook(db)
    except (StoreError, sqlite3.DatabaseError, ValueError) as exc:  # ValueError: its JSON, AssignmentError
        raise _gradebook_error(db, exc, "give the database that 'lagrade grade' wrote") from None


@click.command("export")
@click.argument("db", type=GRADEBOOK_PATH)
@click.option("--format", "fmt", type=click.Choice(["canvas", "csv", "gradescope", "html", "skipped"]),
              default="canvas", show_default=True, help="What to write.")
@click.option("--output", "-o", type=click.Path(path_type=Path),
              help="Write here instead of stdout (a folder for --format html).")
@click.option("--student", help="For --format gradescope: whose results.json (needed with several students).")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="For --format canvas: a Canvas gradebook export, to use its student ids.")
def export(db: Path, fmt: str, output: Path | None, student: str | None, roster: Path | None) -> None:
    """Export the grades in DB: Canvas import CSV, plain CSV, Gradescope results.json, HTML report."""
    from lagrade.bulk import exports

    book = _book(db)
    if fmt == "html":
        if output is None:
            raise click.UsageError("--format html writes a folder: give it with --output")
        from lagrade.bulk.html_report import write_report

        click.echo(str(write_report(book, output)))
        return
    if fmt == "canvas":
        text = exports.canvas_csv(book, exports.read_roster(roster) if roster else None)
    elif fmt == "csv":
        text = exports.plain_csv(book)
    elif fmt == "skipped":
        text = exports.skipped_csv(book)
    else:
        try:
            text = exports.gradescope_json(book, student) + "\n"
        except (ValueError, KeyError) as exc:
            raise click.UsageError(str(exc).strip("'")) from None
    if output is None:
        click.echo(text, nl=False)
    else:
        output.write_text(text, encoding="utf-8")


@click.command("report")
@click.argument("db", type=GRADEBOOK_PATH)
@click.option("--html", "html_dir", type=click.Path(file_okay=False, path_type=Path),
              help="Write the class report and one feedback page per student into this folder.")
def report(db: Path, html_dir: Path | None) -> None:
    """The class summary of DB; with --html, a static report folder to open in a browser."""
    from rich.console import Console

    from lagrade.bulk.summary import render_summary

    book = _book(db)
    render_summary(book, Console(highlight=False))
    if html_dir is not None:
        from lagrade.bulk.html_report import write_report

        index = write_report(book, html_dir)
        click.echo(f"report: {index}")


@click.command("gradescope")
@click.option("--submission", type=click.Path(file_okay=False, path_type=Path), default="/autograder/submission",
              show_default=True, help="The student's files (<problem-id>.py or .toml, at any depth).")
@click.option("--assignment", "-a", "assignment_path", type=click.Path(dir_okay=False, path_type=Path),
              default="/autograder/source/assignment.toml", show_default=True)
@click.option("--results", type=click.Path(dir_okay=False, path_type=Path),
              default="/autograder/results/results.json", show_default=True)
@click.option("--workers", "-j", type=click.IntRange(min=1), help="Grader processes (default: all cores).")
@problems_option
def gradescope(submission: Path, assignment_path: Path, results: Path, workers: int | None,
               problems_dir: tuple[Path, ...]) -> None:
    """Grade one Gradescope submission and write Gradescope's results.json (for run_autograder)."""
    from lagrade.bulk.exports import gradescope_results
    from lagrade.bulk.gradebook import load_gradebook
    from lagrade.bulk.runner import grade_folder

    a = _assignment(assignment_path, problems_dir)
    work = Path(tempfile.mkdtemp(prefix="lagrade-gradescope-"))
    try:
        folder = work / "class" / "submission"
        folder.mkdir(parents=True)
        notes = []
        if submission.is_dir():
            for pid in a.ids:
                found = sorted((p for ext in (".py", ".toml") for p in submission.rglob(f"{pid}{ext}")
                                if p.is_file() and not p.is_symlink()), key=lambda p: (len(p.parts), str(p)))
                if found:
                    shutil.copyfile(found[0], folder / found[0].name)
                    if len(found) > 1:
                        notes.append(f"several files for {pid}; graded {found[0].relative_to(submission)}")
        else:
            notes.append(f"no submission folder {submission}")
        db = work / "grades.sqlite"
        grade_folder(work / "class", a, db, workers=workers, problems_dirs=problems_dir)
        book = load_gradebook(db)
        out = gradescope_results(book, book.student("submission"))
        if notes:
            out["output"] += "\n" + "\n".join(notes)
        results.parent.mkdir(parents=True, exist_ok=True)
        import json

        results.write_text(json.dumps(out, indent=1), encoding="utf-8")
        click.echo(f"{out['score']:g} / {book.possible:g} -> {results}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
