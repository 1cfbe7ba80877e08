"""Instructor commands: ``grade``, ``export``, ``report``, ``override``, ``import``, ``gradescope``, ``prairielearn``.

Module-level click commands, registered on the main group by ``lagrade.cli``. Heavy imports are
deferred so that ``lagrade --help`` stays fast.
"""

from __future__ import annotations

import csv
import shutil
import sys
import tempfile
from pathlib import Path

import click

from lagrade.cli.common import problems_option

#: a gradebook path as click passes it on: what it is, and whether it can be read, is the Store's to
#: say (one line naming the file and what to do, exit 2), not a click usage error
GRADEBOOK_PATH = click.Path(path_type=Path, readable=False)


class GradebookError(click.ClickException):
    """``lagrade: <what is wrong with the gradebook>; <what to do>`` on one line of stderr, exit 2."""

    exit_code = 2

    def show(self, file=None) -> None:  # noqa: ARG002
        from lagrade.verdicts.printable import printable

        click.echo(f"lagrade: {printable(self.message)}", err=True)  # it may name a student's folder or file


def _gradebook_error(db: Path, exc: Exception, hint: str) -> GradebookError:
    """The one-line error for a gradebook that cannot be used; SQLite's own errors get the file named."""
    import sqlite3

    from lagrade.uses.bulk.store import NotAGradebook

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
    from lagrade.uses.bulk.assignment import (
        AssignmentError,
        check_against_problems,
        load_assignment,
    )

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
@click.option("--plots/--no-plots", default=False, show_default=True,
              help="Also draw each wrong motion against the true one (`lagrade check --plot`'s picture) for the "
                   "students' report pages (about 0.25 s of CPU more per distinct wrong file): asked for by the "
                   "report, not needed for the grades; a wrong answer graded without it is graded again then.")
@click.option("--progress/--no-progress", default=None, help="Progress bar (default: when stderr is a terminal).")
@click.option("--summary/--no-summary", default=True, show_default=True, help="Print the class summary at the end.")
@click.option("--unsafe-trusted-files", is_flag=True,
              help="Grade even where the OS jail cannot be built (see `lagrade doctor`): only for files you trust.")
@problems_option
def grade(submissions: Path, assignment_path: Path, db: Path | None, workers: int | None, scheduler: str | None,
          regrade: bool, plots: bool, progress: bool | None, summary: bool, unsafe_trusted_files: bool,
          problems_dir: tuple[Path, ...]) -> None:
    """Grade a class folder SUBMISSIONS/<student>/<problem-id>.py (or .toml) into a database.

    Only new or changed files are graded when run again; every result is saved as soon as it is
    graded, so an interrupted run resumes where it stopped.
    """
    import sqlite3

    from rich.console import Console

    from lagrade.uses.bulk.runner import grade_folder
    from lagrade.uses.bulk.store import StoreError

    a = _assignment(assignment_path, problems_dir)
    db = db or assignment_path.with_suffix(".sqlite")
    err = Console(stderr=True, highlight=False)
    _require_jail(unsafe_trusted_files, err)  # on a Dask cluster, each file's row records its worker's layers
    show = err.is_terminal if progress is None else progress
    bar = _ProgressBar(err, show)
    try:
        with bar:
            report = grade_folder(submissions, a, db, workers=workers, scheduler=scheduler, problems_dirs=problems_dir,
                                  on_start=bar.start, on_result=bar.advance, regrade=regrade,
                                  plots=plots)
    except (StoreError, sqlite3.DatabaseError) as exc:
        raise _gradebook_error(db, exc, "give another --db path or move it away") from None
    except KeyboardInterrupt:
        err.print("interrupted: every submission graded so far is saved; run the same command to go on")
        sys.exit(130)
    _keep_manifest(submissions, db)
    out = Console(highlight=False)
    rate = report.todo / report.seconds * 60 if report.seconds else 0.0
    out.print(f"{report.total} submissions: {report.todo} graded now ({report.failed} could not be graded), "
              f"{report.up_to_date} unchanged; {len(report.skipped)} files skipped; "
              f"{report.seconds:.1f} s on {report.workers} {'Dask threads' if report.backend == 'dask' else 'processes'}"
              + (f" ({rate:.0f} per minute)" if report.todo else "") + f" -> {db}")
    if report.removed:
        out.print(f"{report.removed} earlier results removed: their files are gone")
    from lagrade.verdicts.printable import printable

    for s in report.skipped[:20]:  # a student's folder and file names: printable, never markup
        out.print(printable(f"  skipped {s.path}: {s.reason}"), markup=False)
    if len(report.skipped) > 20:
        out.print(f"  ... and {len(report.skipped) - 20} more (lagrade export {db} --format skipped)")
    if summary:
        from lagrade.uses.bulk.summary import render_summary

        render_summary(_book(db), out)


def _keep_manifest(submissions: Path, db: Path) -> None:
    """What ``lagrade import`` learnt from the LMS (Canvas user id, late) goes into the gradebook."""
    import json

    from lagrade.uses.bulk.intake import read_manifest
    from lagrade.uses.bulk.store import Store

    lms = read_manifest(submissions)
    if lms:
        with Store(db) as store:
            store.set_meta("lms", json.dumps(lms, sort_keys=True))


def _require_jail(unsafe: bool, err) -> None:
    """Refuse to run a class's files where the OS jail cannot be built, unless told they are trusted."""
    from lagrade.uses.deploy.jailcheck import probe_layers
    from lagrade.answer.jail import kernel

    active, _, failed = probe_layers()
    lacking = failed or kernel.missing_minimum(active)
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

        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
        )

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

    from lagrade.uses.bulk.gradebook import load_gradebook
    from lagrade.uses.bulk.overrides import apply_overrides
    from lagrade.uses.bulk.store import StoreError

    try:
        book = load_gradebook(db)
        unused = apply_overrides(book, db)
    except (StoreError, sqlite3.DatabaseError, ValueError) as exc:  # ValueError: its JSON, AssignmentError
        raise _gradebook_error(db, exc, "give the database that 'lagrade grade' wrote") from None
    for line in unused:
        click.echo(f"lagrade: override not applied: {line}", err=True)
    return book


@click.command("export")
@click.argument("db", type=GRADEBOOK_PATH)
@click.option("--format", "fmt", type=click.Choice(["canvas", "csv", "gradescope", "html", "moodle", "skipped"]),
              default="canvas", show_default=True, help="What to write.")
@click.option("--output", "-o", type=click.Path(path_type=Path),
              help="Write here instead of stdout (a folder for --format html).")
@click.option("--student", help="For --format gradescope: whose results.json (needed with several students).")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="For --format canvas: a Canvas gradebook export, to use its student ids. For --format moodle: "
                   "the grading worksheet Moodle wrote, to fill in.")
@click.option("--missing", type=click.Choice(["keep", "zero", "blank"]), default="keep", show_default=True,
              help="For --format canvas with --roster, a roster student without a folder: keep (no row: Canvas "
                   "keeps the grade it has), zero (0 points), blank (an empty cell: Canvas REMOVES the grade it has).")
@click.option("--bom", is_flag=True,
              help="Begin a CSV with a UTF-8 byte order mark, so that Excel shows accents right (Canvas reads it too).")
@problems_option
def export(db: Path, fmt: str, output: Path | None, student: str | None, roster: Path | None, missing: str,
           bom: bool, problems_dir: tuple[Path, ...]) -> None:
    """Export the grades in DB: Canvas import CSV, plain CSV, Gradescope results.json, HTML report."""
    from lagrade.uses.bulk import exports

    book = _book(db)
    if bom and fmt not in ("canvas", "csv", "moodle", "skipped"):
        raise click.UsageError("--bom is for the CSV formats (canvas, csv, moodle, skipped)")
    if fmt == "html":
        if output is None:
            raise click.UsageError("--format html writes a folder: give it with --output")
        from lagrade.uses.bulk.html_report import write_report

        click.echo(str(write_report(book, output, problems_dir)))
        return
    if fmt == "canvas":
        rows = _roster(roster) if roster else None
        if rows is not None and book.students and len(exports.not_on_roster(book, rows)) == len(book.students):
            raise GradebookError(
                f"none of the {len(book.students)} student folders of {db} is on a row of {roster} (by SIS Login ID, "
                f"SIS User ID, ID or Student), so every student would get {'no grade' if missing == 'keep' else missing}"
                f"; import the download with `lagrade import ... --roster {roster}` and grade again")
        text = exports.canvas_csv(book, rows, missing=missing)
        _canvas_notes(book, roster)
        if rows is not None:
            lost = exports.not_on_roster(book, rows)
            absent = exports.roster_without_folder(book, rows)
            if absent:
                what = {"keep": "left out (Canvas keeps the grade it has; --missing zero gives 0)",
                        "zero": "given 0 (--missing zero)",
                        "blank": "given an empty cell, which REMOVES the grade Canvas has (--missing blank)"}[missing]
                click.echo(f"lagrade: {len(absent)} roster students have no folder and are {what}: "
                           + ", ".join(r.get("Student") or r.get("ID") or "?" for r in absent), err=True)
            if lost:
                click.echo(f"lagrade: {len(lost)} student folders are on no row of {roster} (or on a row another "
                           f"folder took) and are not in the export: {', '.join(lost)}", err=True)
    elif fmt == "moodle":
        text = _moodle(book, db, roster)
    elif fmt == "csv":
        text = exports.plain_csv(book)
    elif fmt == "skipped":
        text = exports.skipped_csv(book)
    else:
        try:
            text = exports.gradescope_json(book, student, problems_dir) + "\n"
        except (ValueError, KeyError) as exc:
            raise click.UsageError(str(exc).strip("'")) from None
    if bom:
        text = "\ufeff" + text
    if output is None:
        if sys.stdout.isatty():  # shown, not piped: what students wrote (feedback, names) made printable
            from lagrade.verdicts.printable import printable

            text = printable(text)
        click.echo(text, nl=False)
    else:
        output.write_text(text, encoding="utf-8")


def _roster(path: Path) -> dict[str, dict[str, str]]:
    from lagrade.uses.bulk import exports

    try:
        rows = exports.read_roster(path)
        if exports.roster_delimiter(path) == ";":
            click.echo(f"lagrade: {path} is semicolon-separated (Excel saves so where the comma is the decimal "
                       "mark): read so; the export is comma-separated, as Canvas reads it", err=True)
        return rows
    except exports.RosterError as exc:
        raise click.UsageError(str(exc)) from None
    except UnicodeDecodeError:
        raise click.UsageError(f"{path}: not UTF-8 (Excel's 'CSV' in some locales is not): give the file Canvas "
                               "exported as it is, or save it from Excel as 'CSV UTF-8'") from None
    except (OSError, csv.Error) as exc:
        raise click.UsageError(f"{path}: not a readable Canvas gradebook export ({exc})") from None


def _canvas_notes(book, roster: Path | None) -> None:
    """What the Canvas export cannot fix by itself, said on stderr: Canvas's points possible against
    lagrade's total, and students of an anonymous assignment."""
    from lagrade.uses.bulk import exports

    if roster is not None:
        found = exports.canvas_points_possible(book, roster)
        if found is not None and book.students and abs(found[1] - book.students[0].possible) > 1e-9:
            column, canvas = found[0], f"{found[1]:g}"
            total = f"{book.students[0].possible:g}"
            click.echo(f"lagrade: warning: Canvas's points possible for {column!r} is {canvas}, lagrade's total is "
                       f"{total}: Canvas would show {total} as a score out of {canvas}; set the assignment's points "
                       f"in Canvas to {total}, or the problems' weights in the assignment file to sum to {canvas} "
                       "(no regrade needed)", err=True)
    anonymous = exports.anonymous_students(book)
    if anonymous:
        click.echo(f"lagrade: {len(anonymous)} students came from an anonymous assignment (anon_<id>); "
                   f"{exports.ANONYMOUS_ADVICE}", err=True)


def _moodle(book, db: Path, worksheet: Path | None) -> str:
    from lagrade.uses.bulk import exports

    if not exports.moodle_students(book):
        raise GradebookError(f"no student of {db} came from a Moodle download (their participant ids are not known): "
                             "import Moodle's 'Download all submissions' with `lagrade import` and grade that folder")
    if worksheet is None:
        return exports.moodle_csv(book)
    try:
        rows = exports.read_moodle_worksheet(worksheet)
    except exports.RosterError as exc:
        raise click.UsageError(str(exc)) from None
    except UnicodeDecodeError:
        raise click.UsageError(f"{worksheet}: not UTF-8; give the worksheet Moodle wrote as it is") from None
    maximum = exports.moodle_maximum(rows)
    if maximum is not None and book.students and book.students[0].possible > maximum + 1e-9:
        click.echo(f"lagrade: warning: Moodle's maximum grade is {maximum:g} and lagrade's total is "
                   f"{book.students[0].possible:g}: Moodle skips a grade above its maximum; set the assignment's "
                   f"maximum grade to {book.students[0].possible:g}, or the problems' weights to sum to {maximum:g}",
                   err=True)
    lost = exports.moodle_unmatched(book, rows)
    if lost:
        click.echo(f"lagrade: {len(lost)} student folders are on no row of {worksheet} and are not in the export: "
                   + ", ".join(lost), err=True)
    return exports.moodle_csv(book, rows)


@click.command("override")
@click.argument("db", type=GRADEBOOK_PATH)
@click.argument("student")
@click.argument("problem")
@click.argument("part")
@click.argument("score", required=False, type=float)
@click.option("--reason", help="Why (shown to the student with the score). Required to set a score.")
@click.option("--remove", is_flag=True, help="Remove the override of this part: the engine's score counts again.")
def override(db: Path, student: str, problem: str, part: str, score: float | None, reason: str | None,
             remove: bool) -> None:
    """Set STUDENT's SCORE for PART of PROBLEM in DB, over the engine's; kept across regrades.

    SCORE is on the part's own scale (the "score" column of the report, e.g. 1 of 1); the
    assignment's weights turn it into points as they do the engine's."""
    import sqlite3

    from lagrade.uses.bulk.overrides import part_of
    from lagrade.uses.bulk.store import Store, StoreError

    book = _book(db)
    try:
        p = part_of(book, student, problem, part)
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None
    try:
        with Store(db) as store:
            if remove:
                done = store.remove_override(student, problem, part)
                click.echo(f"{student} {problem} {part}: " + ("override removed" if done else "had no override"))
                return
            if score is None or not reason or not reason.strip():
                raise click.UsageError("give SCORE and --reason \"...\" (or --remove)")
            engine_max = p["max_score"]
            if not 0 <= score <= engine_max:
                raise click.UsageError(f"SCORE must be between 0 and {engine_max:g} (the part's maximum)")
            store.set_override(student=student, problem=problem, part=part, score=score, max_score=engine_max,
                               reason=reason.strip())
    except (StoreError, sqlite3.DatabaseError) as exc:
        raise _gradebook_error(db, exc, "give the database that 'lagrade grade' wrote") from None
    after = _book(db).student(student)
    click.echo(f"{student} {problem} {part}: {score:g} / {engine_max:g} ({reason.strip()}); "
               f"{problem} now {after.problems[problem].points:g}, total {after.points:g} / {after.possible:g}")


@click.command("import")
@click.argument("download", type=click.Path(exists=True, path_type=Path))
@click.option("--assignment", "-a", "assignment_path", required=True,
              type=click.Path(exists=True, dir_okay=False, path_type=Path), help="The assignment TOML file.")
@click.option("--output", "-o", type=click.Path(file_okay=False, path_type=Path), required=True,
              help="The submissions folder to write (<student>/<problem-id>.py).")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="A Canvas gradebook export: folders named after its SIS Login ID.")
@problems_option
def import_(download: Path, assignment_path: Path, output: Path, roster: Path | None,
            problems_dir: tuple[Path, ...]) -> None:
    """Turn an LMS download (Canvas's submissions, Gradescope's export, Moodle's submissions; the zip
    or the folder it unzips to) into a submissions folder.

    Files named nearly right (12_22.py, 12.22 (1).py, 12.22.PY, hw7-12.22.py) are taken and listed;
    files that match no problem are listed too. A download from which nothing can be imported is
    refused (exit 2)."""
    from lagrade.uses.bulk.intake import _unzip, import_downloads

    a = _assignment(assignment_path, problems_dir)
    rows = _roster(roster) if roster else None
    scratch = None
    try:
        if download.is_file():
            scratch = Path(tempfile.mkdtemp(prefix="lagrade-download-"))
            _, notes = _unzip(download, scratch, download.name)
            if notes and not any(scratch.iterdir()):
                raise GradebookError(f"{download}: {notes[0].split(': ', 1)[1]}")
            source = scratch
        else:
            source = download
        report = import_downloads(source, a.ids, output, rows)
    finally:
        if scratch is not None:
            shutil.rmtree(scratch, ignore_errors=True)
    from lagrade.verdicts.printable import printable

    for note in report.notes:  # they name the download's files, as students named them
        click.echo(printable(f"  {note}"))
    if not report.students:
        raise GradebookError(f"nothing imported from {download}: no file in it is an answer to {a.name} in a Canvas "
                             "(<name>_<user id>_<id>_<file>), Gradescope (submission_<id>/) or Moodle "
                             "(<Name>_<id>_assignsubmission_file_/) download; the notes above say what was found")
    late = sum(1 for v in report.lms.values() if v.get("late"))
    click.echo(f"{report.kind or 'download'}: {len(report.copied)} files of {len(report.students)} students -> "
               f"{output}" + (f" ({late} late)" if late else "") + f"; {len(report.notes)} notes above")


@click.command("report")
@click.argument("db", type=GRADEBOOK_PATH)
@click.option("--html", "html_dir", type=click.Path(file_okay=False, path_type=Path),
              help="Write the class report and one feedback page per student into this folder.")
@problems_option
def report(db: Path, html_dir: Path | None, problems_dir: tuple[Path, ...]) -> None:
    """The class summary of DB; with --html, a static report folder to open in a browser."""
    from rich.console import Console

    from lagrade.uses.bulk.summary import render_summary

    book = _book(db)
    render_summary(book, Console(highlight=False))
    if html_dir is not None:
        from lagrade.uses.bulk.html_report import write_report

        index = write_report(book, html_dir, problems_dir)
        click.echo(f"report: {index}")
        undrawn = _undrawn(db)
        if undrawn:
            click.echo(f"{undrawn} graded file{'s' if undrawn != 1 else ''} with a part not correct "
                       f"{'were' if undrawn != 1 else 'was'} graded without the pictures of wrong motions: "
                       "`lagrade grade ... --plots` draws them (grading only those files again); then report again")


def _undrawn(db: Path) -> int:
    """Graded files with a part not correct whose picture was never asked for (``plot_png`` NULL)."""
    import sqlite3

    try:
        with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as con:
            return int(con.execute("SELECT count(*) FROM submissions s WHERE outcome = 'graded' AND plot_png IS NULL "
                                   "AND EXISTS (SELECT 1 FROM parts p WHERE p.student = s.student AND "
                                   "p.problem = s.problem AND p.verdict != 'correct')").fetchone()[0])
    except sqlite3.Error:  # an older gradebook: nothing to say
        return 0


_RUN_OPTIONS = [
    click.option("--submission", type=click.Path(file_okay=False, path_type=Path), default="/autograder/submission",
                 show_default=True, help="The student's files (<problem-id>.py or .toml, at any depth)."),
    click.option("--assignment", "-a", "assignment_path", type=click.Path(dir_okay=False, path_type=Path),
                 default="/autograder/source/assignment.toml", show_default=True),
    click.option("--results", type=click.Path(dir_okay=False, path_type=Path),
                 default="/autograder/results/results.json", show_default=True),
    click.option("--workers", "-j", type=click.IntRange(min=1),
                 help="Grader processes (default: as many as the container's memory holds, one per core at most)."),
    problems_option,
]


def _run_options(f):
    for option in reversed(_RUN_OPTIONS):
        f = option(f)
    return f


@click.group("gradescope", invoke_without_command=True)
@_run_options
@click.pass_context
def gradescope(ctx: click.Context, submission: Path, assignment_path: Path, results: Path, workers: int | None,
               problems_dir: tuple[Path, ...]) -> None:
    """Gradescope: `build` the autograder zip; `run` (or no subcommand) grades one submission.

    Without a subcommand, grades the submission into Gradescope's results.json, as `run` does (what
    autograders made by earlier lagrades call)."""
    if ctx.invoked_subcommand is None:
        _gradescope_run(submission, assignment_path, results, workers, problems_dir)


@gradescope.command("run")
@_run_options
def gradescope_run(submission: Path, assignment_path: Path, results: Path, workers: int | None,
                   problems_dir: tuple[Path, ...]) -> None:
    """Grade one Gradescope submission and write Gradescope's results.json (run_autograder calls this)."""
    _gradescope_run(submission, assignment_path, results, workers, problems_dir)


@gradescope.command("build")
@click.argument("assignment_path", metavar="ASSIGNMENT", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--output", "-o", type=click.Path(dir_okay=False, path_type=Path), default="autograder.zip",
              show_default=True, help="The zip to upload to Gradescope.")
@click.option("--wheel", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Ship this lagrade wheel instead of building one from the checkout.")
@problems_option
def gradescope_build(assignment_path: Path, output: Path, wheel: Path | None, problems_dir: tuple[Path, ...]) -> None:
    """Write the autograder zip for ASSIGNMENT: setup.sh, run_autograder, a lagrade wheel, the assignment."""
    from lagrade.uses.bulk.assignment import AssignmentError
    from lagrade.uses.deploy.gradescope import build_autograder
    from lagrade.uses.deploy.wheel import DeployError

    try:
        names = build_autograder(assignment_path, output, problems_dir, wheel)
    except AssignmentError as exc:
        raise click.UsageError(str(exc)) from None
    except DeployError as exc:
        raise click.ClickException(str(exc)) from None
    click.echo(f"{output}: {', '.join(names)}")
    click.echo(f"private: {output.name} holds the problems and reference solutions; upload it to Gradescope as the "
               "autograder and keep it out of anything public (docs/deploy.md)")


#: the answer's memory bound on Gradescope when the assignment's [limits] gives none: below the
#: 768 MB of Gradescope's default container, which also holds the grader
GRADESCOPE_MEMORY_MB = 384


def _gradescope_run(submission: Path, assignment_path: Path, results: Path, workers: int | None,
                    problems_dir: tuple[Path, ...]) -> None:
    import json
    import os
    import time

    from lagrade.uses.bulk.exports import gradescope_results
    from lagrade.uses.bulk.gradebook import load_gradebook
    from lagrade.uses.bulk.intake import find_answers
    from lagrade.uses.bulk.runner import grade_folder

    from lagrade.uses.deploy.jailcheck import decide

    t0 = time.monotonic()
    a = _assignment(assignment_path, problems_dir)
    if "memory_mb" not in a.limits.model_fields_set:  # Gradescope's container has 768 MB in all
        a = a.model_copy(update={"limits": a.limits.model_copy(update={"memory_mb": GRADESCOPE_MEMORY_MB})})
    source = assignment_path.parent
    jail = decide(extra_keys=(source,) if any(source.glob("*.whl")) else ())
    if not jail.ok:  # a clear result, never a grade made without the jail
        out = {"score": 0.0, "output": "This submission was NOT graded: the autograder refused to run students' files "
               f"in this container ({jail.for_students()}). Your instructor will grade it; please tell them.",
               "output_format": "text", "visibility": "visible", "stdout_visibility": "hidden", "tests": [],
               "extra_data": {"jail": jail.as_dict()}}
        results.parent.mkdir(parents=True, exist_ok=True)
        results.write_text(json.dumps(out, indent=1), encoding="utf-8")
        raise GradebookError(f"refusing to run students' files: {jail.lacking} (results.json says so) -> {results}")
    work = Path(tempfile.mkdtemp(prefix="lagrade-gradescope-"))
    try:
        folder = work / "class" / "submission"
        folder.mkdir(parents=True)
        notes = []
        if submission.is_dir():
            found = find_answers(submission, a.ids)
            for pid, path in found.chosen.items():
                shutil.copyfile(path, folder / f"{pid}{path.suffix.lower()}")
            notes += found.notes
        else:
            notes.append(f"no submission folder {submission}")
        db = work / "grades.sqlite"
        if workers is None:  # as many answers at once as the container's memory holds, not its cores
            from lagrade.uses.deploy.pool import memory_limit, pool_size

            limit = memory_limit()
            workers = pool_size(len(list(folder.iterdir())), a.limits.memory_mb, limit, os.cpu_count())
            click.echo(f"{workers} grader(s) at once: {a.limits.memory_mb} MB an answer in "
                       f"{f'{limit >> 20} MiB' if limit else 'unknown memory'}")
        grade_folder(work / "class", a, db, workers=workers, problems_dirs=problems_dir)
        book = load_gradebook(db)
        out = gradescope_results(book, book.student("submission"), execution_time=time.monotonic() - t0,
                                 problems_dirs=problems_dir)
        out["extra_data"] = {**out.get("extra_data", {}), "jail": jail.as_dict()}
        if notes:
            from lagrade.uses.bulk.exports import say

            sep = "<br>" if out["output_format"] == "html" else "\n\n" if out["output_format"] == "md" else "\n"
            out["output"] += sep + sep.join(say(n, out["output_format"]) for n in notes)
        results.parent.mkdir(parents=True, exist_ok=True)
        results.write_text(json.dumps(out, indent=1), encoding="utf-8")
        click.echo(f"{out['score']:g} / {book.possible:g} -> {results}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


@click.group("prairielearn")
def prairielearn() -> None:
    """PrairieLearn: `build` the external grader's Docker folder and an example question; `grade` a job."""


@prairielearn.command("grade")
@click.option("--root", type=click.Path(file_okay=False, path_type=Path), default="/grade", show_default=True,
              help="The job: data/data.json and student/ in, results/results.json out.")
def prairielearn_grade(root: Path) -> None:
    """Grade one PrairieLearn job (the container's entry point runs this)."""
    from lagrade.uses.deploy.prairielearn import write_results

    results = write_results(root)
    click.echo(f"gradable {results['gradable']}, score {results.get('score', 0):g} -> {root / 'results' / 'results.json'}")


@prairielearn.command("build")
@click.argument("assignment", required=False, type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--image", required=True,
              help="The image name you push the grader under, written into the question's info.json: a public "
                   "image on Docker Hub (YOURACCOUNT/lagrade-grader:TAG), ghcr.io, quay.io, registry.gitlab.com or "
                   "public.ecr.aws, the registries PrairieLearn pulls from.")
@click.option("--output", "-o", type=click.Path(file_okay=False, path_type=Path), default="prairielearn",
              show_default=True, help="The folder to write (docker build its image/; copy questions/ into the course).")
@click.option("--problem", default=None, help="The problem of the example question (default: 12.43, or with an "
                                               "ASSIGNMENT one question per problem of it).")
@click.option("--uuid-seed",
              help="Draw the questions' UUIDs from this text (the same seed gives the same UUIDs). Default: keep "
                   "the UUID a build left in --output, else a new random one, so two builds never collide.")
@click.option("--wheel", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Ship this lagrade wheel instead of building one from the checkout.")
@problems_option
def prairielearn_build(assignment: Path | None, image: str, output: Path, problem: str | None, uuid_seed: str | None,
                       wheel: Path | None, problems_dir: tuple[Path, ...]) -> None:
    """Write the grader image's build folder (OUTPUT/image: Dockerfile, the lagrade engine wheel, the entry
    script; public, so no problem and no reference) and an example question whose private tests/ folder
    holds its problem file (with an ASSIGNMENT file, like `gradescope build hw7.toml`: a question for
    each of its problems)."""
    from lagrade.uses.deploy.keycheck import KeyInPublic
    from lagrade.uses.deploy.prairielearn import IMAGE_DIR, BuildError, build_grader, write_question
    from lagrade.uses.deploy.wheel import DeployError
    from lagrade.problem.spec import SpecError

    pids = [problem] if problem else [p.id for p in _assignment(assignment, problems_dir).problems] if assignment \
        else ["12.43"]
    try:
        names = build_grader(output, pids[0], problems_dir, wheel, image=image, uuid_seed=uuid_seed)
        for pid in pids[1:]:  # the grader is the same for every question: only the questions differ
            names += write_question(output, pid, problems_dir, image=image, uuid_seed=uuid_seed)
    except (SpecError, BuildError, KeyInPublic) as exc:
        raise click.UsageError(str(exc)) from None
    except DeployError as exc:
        raise click.ClickException(str(exc)) from None
    click.echo(f"{output}: {', '.join(names)}")
    click.echo(f"next: docker buildx build --platform linux/amd64 -t {image} --push {output / IMAGE_DIR}")
