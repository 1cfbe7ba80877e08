"""Gradebook exports: Canvas import CSV, Moodle's offline grading worksheet, a plain CSV, Gradescope's
``results.json``, skipped files.

Canvas: the columns of Canvas's own gradebook export (``Student,ID,SIS User ID,SIS Login ID,Section``)
then one column for the assignment, with the ``Points Possible`` row first. The column is named
``Title (canvas id)`` when the assignment file gives ``canvas_assignment_id``: Canvas then fills its
existing assignment instead of making a new column. Canvas matches rows on ``ID``/``SIS User
ID``/``SIS Login ID``; without a roster the student folder name goes in ``SIS Login ID``. With
``--roster`` (a Canvas gradebook export) each folder name is looked up in the roster's ``SIS Login
ID``, ``SIS User ID``, ``ID`` or ``Student`` column, the roster's identifiers are used, every roster
student gets a row (0 points without a folder, or an empty cell), and folders on no roster row are
reported.

Every text cell of every CSV export goes through :func:`spreadsheet_safe`: student folder names,
roster ids, paths and reasons are chosen by students, and a spreadsheet runs a cell that begins
with ``=`` as a formula. Numbers lagrade computed are written as numbers. Gradescope's
``results.json`` is JSON read by Gradescope, never a spreadsheet: it is left as it is.
"""

from __future__ import annotations

import csv
import io
import json
import re
from collections.abc import Iterable
from functools import lru_cache
from pathlib import Path

from lagrade.uses.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade

CANVAS_ID_COLUMNS = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]

#: a cell beginning with one of these is a formula (or becomes one) in Excel, LibreOffice, Sheets
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def _fmt(x: float) -> str:
    return f"{round(x, 4):g}"


def spreadsheet_safe(cell: str | float) -> str:
    """A CSV cell that no spreadsheet runs as a formula (OWASP's CSV injection advice).

    Text that begins like a formula gets a leading ``'``, so that it is read as text; a number (an
    ``int`` or ``float`` lagrade computed, such as a score) is formatted, never prefixed. Leading
    white space is looked through (`` =1+1``: spreadsheets trim it on import and run the rest)."""
    if isinstance(cell, (int, float)):
        return _fmt(cell)
    if cell == "-":  # "no value", as Moodle's worksheet writes it: no spreadsheet reads a lone dash as a formula
        return cell
    return "'" + cell if cell.startswith(FORMULA_STARTS) or cell.lstrip().startswith(FORMULA_STARTS) else cell


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


class RosterError(ValueError):
    """A gradebook export that cannot be read as one: one line, what was found and what to do."""


def roster_delimiter(path: Path) -> str:
    """``,`` for Canvas's own export; ``;`` for one saved by Excel in a European locale (where the
    comma is the decimal mark). Anything else: :class:`RosterError`, with the advice."""
    with open(path, newline="", encoding="utf-8-sig") as fh:
        first = fh.readline()
    for delimiter in (",", ";"):
        header = next(csv.reader([first], delimiter=delimiter), [])
        if "Student" in [h.strip() for h in header]:
            return delimiter
    shown = first.strip()[:80]
    raise RosterError(f"{path}: not a Canvas gradebook export: its first line ({shown!r}) has no 'Student' column "
                      "separated by ',' or ';'; export it again from Canvas (Grades > Export > Export Entire "
                      "Gradebook) and give that file as Canvas wrote it")


def read_roster(path: Path) -> dict[str, dict[str, str]]:
    """Folder name -> the roster row that names it (in any identifier column). Comma- or
    semicolon-separated (:func:`roster_delimiter`)."""
    delimiter = roster_delimiter(path)
    with open(path, newline="", encoding="utf-8-sig") as fh:
        rows = [{k.strip(): v for k, v in r.items() if k is not None and isinstance(v, str)}
                for r in csv.DictReader(fh, delimiter=delimiter)]
        rows = [r for r in rows if (r.get("Student") or "").strip() not in ("", "Points Possible")]
    for i, r in enumerate(rows):
        r["_row"] = i  # the roster's order, for the export
    out: dict[str, dict[str, str]] = {}
    for col in ("Student", "ID", "SIS User ID", "SIS Login ID"):  # later columns win: the most specific ids
        for r in rows:
            if r.get(col):
                out[r[col].strip()] = r
    return out


def points_possible(path: Path) -> dict[str, float]:
    """Column -> the points possible of Canvas's gradebook export (its ``Points Possible`` row), for
    the columns that hold a number there (``10,5`` in a semicolon-separated file is 10.5)."""
    delimiter = roster_delimiter(path)
    with open(path, newline="", encoding="utf-8-sig") as fh:
        for r in csv.DictReader(fh, delimiter=delimiter):
            if (r.get("Student") or "").strip() == "Points Possible":
                out = {}
                for k, v in r.items():
                    if k is None or not isinstance(v, str):  # cells beyond the header's
                        continue
                    try:
                        out[(k or "").strip()] = float((v or "").strip().replace(",", ".") if delimiter == ";"
                                                       else (v or "").strip())
                    except ValueError:
                        continue
                return out
    return {}


def canvas_points_possible(book: Gradebook, path: Path) -> tuple[str, float] | None:
    """(the roster's column of this assignment, Canvas's points possible for it), or None when the
    roster has no such column: ``Title (canvas id)``, else a column ending in ``(canvas id)``, else
    one named as the assignment."""
    possible = points_possible(path)
    a = book.assignment
    column = canvas_column(book)
    if column in possible:
        return column, possible[column]
    if a.canvas_assignment_id is not None:
        tail = f"({a.canvas_assignment_id})"
        for k, v in possible.items():
            if k.endswith(tail):
                return k, v
    for name in (a.title, a.name):
        if name and name in possible:
            return name, possible[name]
    return None


def anonymous_students(book: Gradebook) -> list[str]:
    """Student folders of an anonymous Canvas assignment (``anon_<id>``, no user id): Canvas's import
    cannot match them until the assignment's students are unmasked and downloaded again."""
    return [s.student for s in book.students
            if book.lms.get(s.student, {}).get("anonymous_id") and not book.lms.get(s.student, {}).get("canvas_user_id")]


#: how an anonymous assignment's grades go back to Canvas (the export's message, and docs/bulk-grading.md)
ANONYMOUS_ADVICE = ("Canvas's import cannot match an anonymous id: in Canvas, post the grades or turn anonymous "
                    "grading off (this unmasks the students), download the submissions again, `lagrade import` "
                    "that download and `lagrade grade` it, then export again")


def roster_rows(roster: dict[str, dict[str, str]]) -> list[dict[str, str]]:
    """The roster's students, once each, in the roster's order."""
    seen: dict[int, dict[str, str]] = {}
    for r in roster.values():
        seen.setdefault(id(r), r)
    return sorted(seen.values(), key=lambda r: r.get("_row", 0))


def canvas_column(book: Gradebook) -> str:
    """The assignment's column: ``Title (canvas id)`` fills Canvas's existing column, a bare name
    makes a new one."""
    a = book.assignment
    if a.canvas_assignment_id is not None:
        return f"{a.title or a.name} ({a.canvas_assignment_id})"
    return a.name


def roster_row(book: Gradebook, roster: dict[str, dict[str, str]], student: str) -> dict[str, str] | None:
    """The roster row of a student folder: the one that names the folder, else the one whose Canvas
    ``ID`` is the user id the download gave the folder (``lagrade import`` without ``--roster``)."""
    r = roster.get(student)
    if r is not None:
        return r
    uid = str(book.lms.get(student, {}).get("canvas_user_id") or "")
    r = roster.get(uid) if uid else None
    return r if r is not None and (r.get("ID") or "").strip() == uid else None


def not_on_roster(book: Gradebook, roster: dict[str, dict[str, str]]) -> list[str]:
    """Student folders whose grades do not reach Canvas: no roster row names them, or their row is
    already another folder's (``ada`` and ``101`` for the same student: the first one counts)."""
    taken: set[int] = set()
    out = []
    for s in book.students:
        r = roster_row(book, roster, s.student)
        if r is None or id(r) in taken:
            out.append(s.student)
        else:
            taken.add(id(r))
    return out


#: what ``canvas_csv`` does for a roster student with no folder (``--missing``). Canvas's importer
#: (canvas-lms ``GradebookImporter#no_change_to_value?``) treats an empty cell over an existing score
#: as a change and removes the score; a student who is not in the file at all is left untouched.
MISSING = ("keep", "zero", "blank")


def roster_without_folder(book: Gradebook, roster: dict[str, dict[str, str]]) -> list[dict[str, str]]:
    """The roster's students that no student folder names."""
    named = {id(r) for s in book.students if (r := roster_row(book, roster, s.student)) is not None}
    return [r for r in roster_rows(roster) if id(r) not in named]


def canvas_csv(book: Gradebook, roster: dict[str, dict[str, str]] | None = None, *,
               missing: float | str | None = "keep") -> str:
    """Canvas's gradebook import. With a roster: one row per roster student with a folder, Canvas's
    ids from the roster; a roster student with no folder is left out (``"keep"``: Canvas keeps what
    it has), gets ``0`` (``"zero"`` or a number) or an empty cell (``"blank"`` or None: Canvas
    *removes* an existing score). Folders not on the roster are left out (:func:`not_on_roster`)."""
    if missing == "zero":
        missing = 0.0
    elif missing == "blank":
        missing = None
    rows = [CANVAS_ID_COLUMNS + [canvas_column(book)], ["Points Possible", "", "", "", "", book.possible]]
    if roster is None:
        for s in book.students:
            lms = book.lms.get(s.student, {})
            uid = str(lms.get("canvas_user_id") or "")
            if uid:  # Canvas matches a row on its user id first: the download named it (lagrade import)
                rows.append([lms.get("name") or s.student, uid, "", "", "", s.points])
            else:
                rows.append([s.student, "", "", s.student, "", s.points])
        return _csv(rows)
    by_row = {}
    for s in book.students:
        r = roster_row(book, roster, s.student)
        if r is not None:
            by_row.setdefault(id(r), s)
    for r in roster_rows(roster):
        s = by_row.get(id(r))
        if s is None and missing == "keep":
            continue
        points = s.points if s is not None else ("" if missing is None else missing)
        rows.append([r.get(c) or "" for c in CANVAS_ID_COLUMNS] + [points])
    return _csv(rows)


#: Moodle's offline grading worksheet (mod/assign, "Download grading worksheet"): its columns as
#: Moodle writes them. Moodle's import (assignfeedback_offline) reads ``Identifier`` (``Participant
#: <id>``: the participant id of the download's folder names), ``Grade`` and ``Last modified (grade)``
#: (a grade changed in Moodle after that time is not overwritten), and the feedback plugins' columns
#: (``Feedback comments``) by their names; it skips a grade above the assignment's maximum grade.
MOODLE_COLUMNS = ["Identifier", "Full name", "Email address", "Status", "Grade", "Maximum Grade",
                  "Grade can be changed", "Last modified (submission)", "Last modified (grade)", "Feedback comments"]
MOODLE_PARTICIPANT = "Participant "


def moodle_feedback(s: StudentGrade) -> str:
    """The worksheet's ``Feedback comments``: the points of each problem, in one line."""
    return "lagrade: " + "; ".join(f"{pid} {_fmt(g.points)} / {_fmt(g.possible)}" +
                                   ("" if g.submitted else " (no file)") for pid, g in s.problems.items())


def moodle_students(book: Gradebook) -> dict[str, str]:
    """Participant id -> student folder, for the folders a Moodle download made (``lagrade import``)."""
    return {str(v["moodle_participant_id"]): s.student for s in book.students
            if (v := book.lms.get(s.student, {})).get("moodle_participant_id")}


def read_moodle_worksheet(path: Path) -> list[dict[str, str]]:
    """The rows of a worksheet Moodle wrote (comma-separated; RosterError if it is not one)."""
    with open(path, newline="", encoding="utf-8-sig") as fh:
        first = fh.readline()
        fh.seek(0)
        delimiter = ";" if first.count(";") > first.count(",") else ","
        reader = csv.DictReader(fh, delimiter=delimiter)
        missing = [c for c in ("Identifier", "Grade", "Last modified (grade)") if c not in (reader.fieldnames or [])]
        if missing:
            raise RosterError(f"{path}: not Moodle's offline grading worksheet: no {', '.join(repr(c) for c in missing)} "
                              "column; download it from the assignment (View all submissions > Grading action > "
                              "Download grading worksheet; 'Offline grading worksheet' must be on in the "
                              "assignment's feedback types)")
        return [dict(r) for r in reader]


def moodle_csv(book: Gradebook, worksheet: list[dict[str, str]] | None = None, *, now: float | None = None) -> str:
    """Moodle's offline grading worksheet with lagrade's grades, for "Upload grading worksheet".

    Without a worksheet: one row per student folder of a Moodle download (its participant id). With
    the worksheet Moodle wrote: its rows and columns as they are, the ``Grade``, ``Last modified
    (grade)`` and ``Feedback comments`` of each participant with a folder filled in (the others
    left as they are: Moodle skips an unchanged grade). ``Last modified (grade)`` is now, in ISO 8601
    with its offset (PHP's ``strtotime``, which Moodle's import uses, reads it exactly)."""
    import time

    stamp = time.strftime("%Y-%m-%dT%H:%M:%S+00:00", time.gmtime(time.time() if now is None else now))
    folders = moodle_students(book)
    by_folder = {s.student: s for s in book.students}
    if worksheet is None:
        rows: list[list[str | float]] = [MOODLE_COLUMNS]
        for pid, folder in sorted(folders.items(), key=lambda kv: int(kv[0]) if kv[0].isdigit() else 0):
            s = by_folder[folder]
            rows.append([f"{MOODLE_PARTICIPANT}{pid}", book.lms[folder].get("name") or "", "", "", s.points,
                         s.possible, "Yes", "", stamp, moodle_feedback(s)])
        return _csv(rows)
    columns = list(worksheet[0].keys()) if worksheet else list(MOODLE_COLUMNS)
    if "Feedback comments" not in columns:
        columns.append("Feedback comments")
    rows = [columns]
    for r in worksheet:
        ident = (r.get("Identifier") or "").strip()
        folder = folders.get(ident[len(MOODLE_PARTICIPANT):]) if ident.startswith(MOODLE_PARTICIPANT) else None
        r = dict(r)
        if folder is not None:
            s = by_folder[folder]
            r.update({"Grade": s.points, "Last modified (grade)": stamp, "Feedback comments": moodle_feedback(s)})
        rows.append([r.get(c) if isinstance(r.get(c), float) else (r.get(c) or "") for c in columns])
    return _csv(rows)


def moodle_unmatched(book: Gradebook, worksheet: list[dict[str, str]]) -> list[str]:
    """Student folders of a Moodle download that no row of the worksheet names."""
    named = {(r.get("Identifier") or "").strip()[len(MOODLE_PARTICIPANT):] for r in worksheet}
    return [folder for pid, folder in moodle_students(book).items() if pid not in named]


def moodle_maximum(worksheet: list[dict[str, str]]) -> float | None:
    """The assignment's maximum grade as the worksheet gives it (``10,00`` in some locales), or None."""
    for r in worksheet:
        try:
            return float((r.get("Maximum Grade") or "").strip().replace(",", "."))
        except ValueError:
            continue
    return None


def file_jail(g: ProblemGrade) -> str | None:
    """The sandbox layers the file was graded under, as its grader reported them (None: not recorded)."""
    return next((p["jail"] for p in g.parts if p.get("jail")), None)


def overrides_of(s: StudentGrade) -> list[str]:
    """``12.3 eom = 1 / 1 (reason)`` for each part of ``s`` whose score an instructor set."""
    return [f"{pid} {p['part']} = {_fmt(p['score'])} / {_fmt(p['max_score'])} ({p['override']['reason']})"
            for pid, g in s.problems.items() for p in g.parts if p.get("override")]


def plain_csv(book: Gradebook) -> str:
    """One row per student; ``jail``: the sandbox layers of their files (each distinct one, ``; ``);
    ``overrides``: the parts whose score an instructor set (``lagrade override``), with the reason;
    ``late``: ``late`` when the LMS download marked the submission late (``lagrade import``)."""
    pids = book.assignment.ids
    rows = [["student", *pids, "total", "possible", *(f"{p} status" for p in pids), "jail", "overrides", "late"]]
    for s in book.students:
        g = s.problems
        jails = dict.fromkeys(j for p in pids if (j := file_jail(g[p])))
        late = book.lms.get(s.student, {}).get("late")
        rows.append([s.student, *(g[p].points for p in pids), s.points, s.possible,
                     *(g[p].outcome if g[p].outcome != "failed" else f"failed: {g[p].status}" for p in pids),
                     "; ".join(jails), "; ".join(overrides_of(s)), "late" if late else ""])
    return _csv(rows)


#: Gradescope's test ``status``: a part is "passed" only when it earned all its points; a part worth
#: no points (an extra part the assignment does not count) only when its verdict is correct
def _status(earned: float, possible: float, verdict: str = "") -> str:
    if possible <= 0:
        return "passed" if verdict == "correct" else "failed"
    return "passed" if earned >= possible else "failed"


def feedback_text(p: dict) -> str:
    """The part's feedback without its verdict repeated in front ("correct: correct: ..." reads badly)."""
    text = (p.get("feedback") or "").strip()
    verdict = p.get("verdict") or ""
    while verdict and text.lower().startswith(verdict.lower() + ":"):
        text = text[len(verdict) + 1:].lstrip()
    return text


def student_feedback(p: dict, pid: str, problems_dirs: tuple[Path, ...] = ()) -> str:
    """What a student reads of a part's feedback (a student's report page, Gradescope's and PrairieLearn's
    results): `feedback_text` with the evidence in words, the integrator's settings left out ("DOP853 at
    rtol 1e-10 ... 116 evaluations" is the instructor's: the gradebook and the class page keep it)."""
    from lagrade.verdicts.words import in_words

    return in_words(feedback_text(p), _part_kinds(pid, problems_dirs).get(p.get("part", ""), ""))


@lru_cache(maxsize=64)
def _part_kinds(pid: str, problems_dirs: tuple[Path, ...] = ()) -> dict[str, str]:
    """part name -> kind of problem ``pid`` ({} if its file cannot be read: the words then say "your answer")."""
    try:
        from lagrade.problem.library import load_problem

        return {part.name: part.kind for part in load_problem(pid, problems_dirs).parts}
    except Exception:  # noqa: BLE001
        return {}


_FUNCS = {"sin", "cos", "tan", "exp", "log", "sqrt", "sinh", "cosh", "tanh", "asin", "acos", "atan", "Abs"}


def readable(text: str) -> str:
    """An answer as sympy prints it, as a physicist writes it in plain text: ``x'`` for
    ``Derivative(x(t), t)``, ``x''`` for the second, ``x`` for ``x(t)``, ``^`` for ``**``."""
    text = re.sub(r"Derivative\((\w+)\(t\), \(t, (\d)\)\)", lambda m: m[1] + "'" * int(m[2]), text)
    text = re.sub(r"Derivative\((\w+)\(t\), t\)", r"\1'", text)
    text = re.sub(r"\b(\w+)\(t\)", lambda m: m[0] if m[1] in _FUNCS else m[1], text)
    return text.replace("**", "^")


def say(text: str, fmt: str) -> str:
    """``text`` (feedback, reasons, file names: student-supplied strings among them) as Gradescope's
    ``fmt`` shows it: ``html`` escaped, line breaks kept as ``<br>``; ``md`` with HTML and Markdown
    markup escaped; ``text`` as it is."""
    from html import escape

    if fmt == "html":
        return escape(text).replace("\n", "<br>")
    if fmt == "md":
        # HTML markup escaped (Gradescope's Markdown passes raw HTML through), then what could make
        # links, code or tables out of the text; an underscore inside a word is no markup
        return re.sub(r"([\\`*\[\]|])", r"\\\1", escape(text, quote=False)).replace("\n", "  \n")
    return text


def _code_span(text: str) -> str:
    """``text`` as a Markdown code span, which shows every character as it is (HTML too): fenced by
    one backtick more than its longest run of them, on one line."""
    text = " ".join(text.splitlines())
    fence = "`" * (max((len(r) for r in re.findall(r"`+", text)), default=0) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def spec_parts(pid: str, problems_dirs: tuple[Path, ...] = ()) -> list[tuple[str, float, bool]]:
    """(part name, weight, extra) of problem ``pid`` as its problem file gives them, in its order; []
    if it cannot be read."""
    try:
        from lagrade.problem.library import load_problem

        return [(part.name, part.weight, bool(part.extra)) for part in load_problem(pid, problems_dirs).parts]
    except Exception:  # noqa: BLE001 - a results.json is still written, with one test for the problem
        return []


def fixed_parts(pid: str, stored: list[dict], problems_dirs: tuple[Path, ...] = ()) -> list[dict]:
    """A problem's parts as Gradescope's tests: the problem file's parts in its order, whatever the
    student handed in (the gradebook keeps them in name order, and an extra part answered or not must
    not move a test: Gradescope's per-test statistics follow the names and order). A part the
    gradebook lacks is a 0 of its weight (``missing``); parts that are not the problem file's (a
    gradebook made with another version of it) are kept as stored."""
    names = spec_parts(pid, problems_dirs)
    by_name = {p["part"]: p for p in stored}
    if not names or not set(by_name) <= {n for n, _, _ in names}:
        return list(stored)
    return [by_name.get(name) or {"part": name, "score": 0.0, "max_score": weight, "verdict": "missing",
                                  "feedback": "", "extra": extra}
            for name, weight, extra in names]


def gradescope_results(book: Gradebook, student: StudentGrade, *, execution_time: float | None = None,
                       problems_dirs: tuple[Path, ...] = ()) -> dict:
    """Gradescope's autograder ``results.json`` for one student (Gradescope's "Autograder Specifications").

    One test per problem part, its ``max_score`` the part's share of the problem's points with the
    assignment's weights; the shares are multiples of 1/10000 that sum exactly to the assignment's
    total, and ``score`` is the sum of the tests' scores, which is the total the CSV and Canvas
    exports give (:func:`lagrade.uses.bulk.assignment.part_points`). A problem not handed in, or whose
    file could not be used, has the same tests, from its problem file, at 0: Gradescope's per-test
    statistics line up. The assignment's ``[gradescope]`` options give the visibilities and the
    output format; every string is escaped for that format (:func:`say`); a message shared by every
    part of a problem is said once, in the first part's test."""
    from lagrade.uses.bulk.assignment import POINT_UNITS, part_points, split_points

    opts = book.assignment.gradescope
    fmt = opts.output_format
    html = fmt == "html"
    tests: list[dict] = []
    units = 0
    per_problem: list[tuple[str, float, float, str]] = []
    for n, (pid, g) in enumerate(student.problems.items(), start=1):
        ap = book.assignment.problem(pid)
        if not g.submitted or not g.parts:
            why = g.reason if g.submitted else f"No file {pid}.py or {pid}.toml was handed in."
            names = fixed_parts(pid, [], problems_dirs)
            if not names:
                share = split_points(g.possible, [1.0])[0]
                tests.append({"name": f"{pid}", "number": f"{n}", "score": 0.0, "max_score": share,
                              "status": "failed", "output": say(why, fmt), "tags": [pid],
                              "visibility": opts.tests_visibility})
            else:
                for m, (z, (_, share)) in enumerate(zip(names, part_points(ap, names, g.possible)), start=1):
                    name = z["part"]
                    tests.append({"name": f"{pid} {name}", "number": f"{n}.{m}", "score": 0.0, "max_score": share,
                                  "status": "failed",
                                  "output": say(why if m == 1 else f"See {pid} {names[0]['part']}.", fmt),
                                  "tags": [pid, name, "missing" if not g.submitted else "failed"],
                                  "visibility": opts.tests_visibility})
            per_problem.append((pid, 0.0, g.possible, "not handed in" if not g.submitted else g.reason))
            continue
        parts = fixed_parts(pid, g.parts, problems_dirs)
        # a file that could not be used: every part carries the same reason, said once
        shared = (len(parts) > 1 and len({(feedback_text(p), p["verdict"]) for p in parts}) == 1
                  and parts[0]["verdict"] != "correct")
        earned_units = 0
        for m, (p, (earned, possible)) in enumerate(zip(parts, part_points(ap, parts, g.possible)), start=1):
            text = say(student_feedback(p, pid, problems_dirs), fmt)
            if shared and m > 1:
                text = say(f"See {pid} {parts[0]['part']}.", fmt)
            if p.get("override"):
                text = say(f"Score set by the instructor: {p['override']['reason']}", fmt) + (
                    ("<br>" if html else "  \n" if fmt == "md" else "\n") + text if text else "")
            elif p.get("answer_text") and not (shared and m > 1):
                read = (f"<math>{p['answer_mathml']}</math>" if html and p.get("answer_mathml")
                        else _code_span(readable(p["answer_text"])) if fmt == "md"
                        else say(readable(p["answer_text"]), fmt))
                text += ("<br><br>" if html else "\n\n") + "Read as: " + read
            units += round(earned * POINT_UNITS)
            earned_units += round(earned * POINT_UNITS)
            tests.append({"name": f"{pid} {p['part']}", "number": f"{n}.{m}", "score": earned, "max_score": possible,
                          "status": _status(earned, possible, p["verdict"]), "output": text,
                          "tags": [pid, p["part"], p["verdict"]], "visibility": opts.tests_visibility})
        per_problem.append((pid, earned_units / POINT_UNITS, g.possible,
                            g.reason if g.outcome == "failed" else ""))
    score = units / POINT_UNITS
    title = book.assignment.title or book.assignment.name
    total = _fmt(sum(t["max_score"] for t in tests))
    if html:
        from html import escape

        rows = "".join(f"<tr><td>{escape(pid)}</td><td>{_fmt(e)} / {_fmt(m)}</td><td>{say(why, fmt)}</td></tr>"
                       for pid, e, m, why in per_problem)
        output = (f"<p><strong>{escape(title)}</strong>: {_fmt(score)} / {total}</p>"
                  f"<table><tr><th>problem</th><th>points</th><th></th></tr>{rows}</table>")
    elif opts.output_format == "md":
        output = "\n".join([f"**{say(title, fmt)}**: {_fmt(score)} / {total}", "", "| problem | points | |",
                            "|---|---|---|",
                            *(f"| {say(pid, fmt)} | {_fmt(e)} / {_fmt(m)} | {say(why, fmt).replace(chr(10), ' ')} |"
                              for pid, e, m, why in per_problem)])
    else:
        output = "\n".join([f"{title}: {_fmt(score)} / {total}",
                            *(f"Problem {pid}: {_fmt(e)} / {_fmt(m)}" + (f" ({why})" if why else "")
                              for pid, e, m, why in per_problem)])
    out = {"score": score, "output": output, "output_format": opts.output_format,
           "test_output_format": opts.output_format, "visibility": opts.visibility,
           "stdout_visibility": opts.stdout_visibility, "tests": tests}
    if execution_time is not None:
        out["execution_time"] = max(0, round(execution_time))
    return out


def gradescope_json(book: Gradebook, student: str | None = None, problems_dirs: tuple[Path, ...] = ()) -> str:
    if student is None:
        if len(book.students) != 1:
            raise ValueError(f"the database has {len(book.students)} students; name one with --student "
                             f"(Gradescope's results.json is per submission)")
        s = book.students[0]
    else:
        s = book.student(student)
    return json.dumps(gradescope_results(book, s, problems_dirs=problems_dirs), indent=1)


def skipped_csv(book: Gradebook) -> str:
    return _csv([["path", "reason"], *book.skipped])


FORMATS = ("canvas", "csv", "gradescope", "html", "moodle", "skipped")
