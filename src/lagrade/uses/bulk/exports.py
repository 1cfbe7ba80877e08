"""Gradebook exports: Canvas import CSV, a plain CSV, Gradescope's ``results.json``, skipped files.

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


def read_roster(path: Path) -> dict[str, dict[str, str]]:
    """Folder name -> the roster row that names it (in any identifier column)."""
    with open(path, newline="", encoding="utf-8-sig") as fh:
        rows = [r for r in csv.DictReader(fh) if (r.get("Student") or "").strip() not in ("", "Points Possible")]
    for i, r in enumerate(rows):
        r["_row"] = i  # the roster's order, for the export
    out: dict[str, dict[str, str]] = {}
    for col in ("Student", "ID", "SIS User ID", "SIS Login ID"):  # later columns win: the most specific ids
        for r in rows:
            if r.get(col):
                out[r[col].strip()] = r
    return out


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


def not_on_roster(book: Gradebook, roster: dict[str, dict[str, str]]) -> list[str]:
    """Student folders whose grades do not reach Canvas: no roster row names them, or their row is
    already another folder's (``ada`` and ``101`` for the same student: the first one counts)."""
    taken: set[int] = set()
    out = []
    for s in book.students:
        r = roster.get(s.student)
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
    named = {id(r) for s in book.students if (r := roster.get(s.student)) is not None}
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
            rows.append([s.student, "", "", s.student, "", s.points])
        return _csv(rows)
    by_row = {}
    for s in book.students:
        r = roster.get(s.student)
        if r is not None:
            by_row.setdefault(id(r), s)
    for r in roster_rows(roster):
        s = by_row.get(id(r))
        if s is None and missing == "keep":
            continue
        points = s.points if s is not None else ("" if missing is None else missing)
        rows.append([r.get(c) or "" for c in CANVAS_ID_COLUMNS] + [points])
    return _csv(rows)


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


#: Gradescope's test ``status``: a part is "passed" only when it earned all its points
def _status(earned: float, possible: float) -> str:
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


def spec_parts(pid: str, problems_dirs: tuple[Path, ...] = ()) -> list[tuple[str, float]]:
    """(part name, weight) of problem ``pid`` as its problem file gives them; [] if it cannot be read."""
    try:
        from lagrade.problem.library import load_problem

        return [(part.name, part.weight) for part in load_problem(pid, problems_dirs).parts]
    except Exception:  # noqa: BLE001 - a results.json is still written, with one test for the problem
        return []


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
            names = spec_parts(pid, problems_dirs)
            if not names:
                share = split_points(g.possible, [1.0])[0]
                tests.append({"name": f"{pid}", "number": f"{n}", "score": 0.0, "max_score": share,
                              "status": "failed", "output": say(why, fmt), "tags": [pid],
                              "visibility": opts.tests_visibility})
            else:
                zeros = [{"part": name, "score": 0.0, "max_score": weight} for name, weight in names]
                for m, ((name, _), (_, share)) in enumerate(zip(names, part_points(ap, zeros, g.possible)), start=1):
                    tests.append({"name": f"{pid} {name}", "number": f"{n}.{m}", "score": 0.0, "max_score": share,
                                  "status": "failed", "output": say(why if m == 1 else f"See {pid} {names[0][0]}.", fmt),
                                  "tags": [pid, name, "missing" if not g.submitted else "failed"],
                                  "visibility": opts.tests_visibility})
            per_problem.append((pid, 0.0, g.possible, "not handed in" if not g.submitted else g.reason))
            continue
        # a file that could not be used: every part carries the same reason, said once
        shared = (len(g.parts) > 1 and len({(feedback_text(p), p["verdict"]) for p in g.parts}) == 1
                  and g.parts[0]["verdict"] != "correct")
        earned_units = 0
        for m, (p, (earned, possible)) in enumerate(zip(g.parts, part_points(ap, g.parts, g.possible)), start=1):
            text = say(student_feedback(p, pid, problems_dirs), fmt)
            if shared and m > 1:
                text = say(f"See {pid} {g.parts[0]['part']}.", fmt)
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
                          "status": _status(earned, possible), "output": text,
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


FORMATS = ("canvas", "csv", "gradescope", "html", "skipped")
