"""Gradebook exports: Canvas import CSV, a plain CSV, Gradescope's ``results.json``, skipped files.

Canvas: the columns of Canvas's own gradebook export (``Student,ID,SIS User ID,SIS Login ID,Section``)
then one column named after the assignment, with the ``Points Possible`` row first. Canvas matches
rows on ``ID``/``SIS User ID``/``SIS Login ID``; without a roster the student folder name goes in
``SIS Login ID``. With ``--roster`` (a Canvas gradebook export) each folder name is looked up in
the roster's ``SIS Login ID``, ``SIS User ID``, ``ID`` or ``Student`` column, and the roster's
identifiers are used.

Every text cell of every CSV export goes through :func:`spreadsheet_safe`: student folder names,
roster ids, paths and reasons are chosen by students, and a spreadsheet runs a cell that begins
with ``=`` as a formula. Numbers lagrade computed are written as numbers. Gradescope's
``results.json`` is JSON read by Gradescope, never a spreadsheet: it is left as it is.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable
from pathlib import Path

from lagrade.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade

CANVAS_ID_COLUMNS = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]

#: a cell beginning with one of these is a formula (or becomes one) in Excel, LibreOffice, Sheets
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def _fmt(x: float) -> str:
    return f"{round(x, 4):g}"


def spreadsheet_safe(cell: str | float) -> str:
    """A CSV cell that no spreadsheet runs as a formula (OWASP's CSV injection advice).

    Text that begins like a formula gets a leading ``'``, so that it is read as text; a number (an
    ``int`` or ``float`` lagrade computed, such as a score) is formatted, never prefixed."""
    if isinstance(cell, (int, float)):
        return _fmt(cell)
    return "'" + cell if cell.startswith(FORMULA_STARTS) else cell


def _csv(rows: Iterable[Iterable[str | float]]) -> str:
    """The CSV text of ``rows``, every cell through :func:`spreadsheet_safe`: every export writes with it.

    A row with a carriage return in a cell (a folder name can hold one) is quoted whole: with ``\n``
    line ends, Python's writer leaves that cell bare, and a reader would end the row there."""
    buf = io.StringIO()
    plain = csv.writer(buf, lineterminator="\n")
    quoted = csv.writer(buf, lineterminator="\n", quoting=csv.QUOTE_ALL)
    for row in rows:
        cells = [spreadsheet_safe(c) for c in row]
        (quoted if any("\r" in c for c in cells) else plain).writerow(cells)
    return buf.getvalue()


def read_roster(path: Path) -> dict[str, dict[str, str]]:
    """Folder name -> the roster row that names it (in any identifier column)."""
    with open(path, newline="", encoding="utf-8-sig") as fh:
        rows = [r for r in csv.DictReader(fh) if (r.get("Student") or "").strip() not in ("", "Points Possible")]
    out: dict[str, dict[str, str]] = {}
    for col in ("Student", "ID", "SIS User ID", "SIS Login ID"):  # later columns win: the most specific ids
        for r in rows:
            if r.get(col):
                out[r[col].strip()] = r
    return out


def canvas_csv(book: Gradebook, roster: dict[str, dict[str, str]] | None = None) -> str:
    rows = [CANVAS_ID_COLUMNS + [book.assignment.name], ["Points Possible", "", "", "", "", book.possible]]
    for s in book.students:
        r = (roster or {}).get(s.student)
        ids = [r.get(c) or "" for c in CANVAS_ID_COLUMNS] if r else [s.student, "", "", s.student, ""]
        rows.append(ids + [s.points])
    return _csv(rows)


def file_jail(g: ProblemGrade) -> str | None:
    """The sandbox layers the file was graded under, as its grader reported them (None: not recorded)."""
    return next((p["jail"] for p in g.parts if p.get("jail")), None)


def plain_csv(book: Gradebook) -> str:
    """One row per student; ``jail``: the sandbox layers of their files (each distinct one, ``; ``)."""
    pids = book.assignment.ids
    rows = [["student", *pids, "total", "possible", *(f"{p} status" for p in pids), "jail"]]
    for s in book.students:
        g = s.problems
        jails = dict.fromkeys(j for p in pids if (j := file_jail(g[p])))
        rows.append([s.student, *(g[p].points for p in pids), s.points, s.possible,
                     *(g[p].outcome if g[p].outcome != "failed" else f"failed: {g[p].status}" for p in pids),
                     "; ".join(jails)])
    return _csv(rows)


def gradescope_results(book: Gradebook, student: StudentGrade) -> dict:
    """Gradescope's autograder ``results.json`` for one student: one test per problem part."""
    tests = []
    lines = [f"{book.assignment.title or book.assignment.name}: {_fmt(student.points)} / {_fmt(student.possible)}"]
    for pid, g in student.problems.items():
        lines.append(f"Problem {pid}: {_fmt(g.points)} / {_fmt(g.possible)}" +
                     ("" if g.outcome == "graded" else f" ({g.reason})"))
        if not g.submitted:
            tests.append({"name": f"{pid}", "score": 0.0, "max_score": g.possible,
                          "output": f"No file {pid}.py or {pid}.toml was handed in.", "visibility": "visible"})
            continue
        ap = book.assignment.problem(pid)
        weights = {p["part"]: ap.parts.get(p["part"], p["max_score"]) for p in g.parts}
        denom = sum(weights.values()) or 1.0
        for p in g.parts:
            share = g.possible * weights[p["part"]] / denom
            frac = p["score"] / p["max_score"] if p["max_score"] else 0.0
            out = f"{p['verdict']}: {p['feedback']}"
            if p.get("answer_text"):
                out += f"\nread as: {p['answer_text']}"
            tests.append({"name": f"{pid} {p['part']}", "score": round(share * frac, 6), "max_score": round(share, 6),
                          "output": out, "visibility": "visible"})
        for problem in g.problems:
            lines.append(f"  {problem}")
    return {"score": student.points, "output": "\n".join(lines), "tests": tests}


def gradescope_json(book: Gradebook, student: str | None = None) -> str:
    if student is None:
        if len(book.students) != 1:
            raise ValueError(f"the database has {len(book.students)} students; name one with --student "
                             f"(Gradescope's results.json is per submission)")
        s = book.students[0]
    else:
        s = book.student(student)
    return json.dumps(gradescope_results(book, s), indent=1)


def skipped_csv(book: Gradebook) -> str:
    return _csv([["path", "reason"], *book.skipped])


FORMATS = ("canvas", "csv", "gradescope", "html", "skipped")
