"""The LMS's last trips (issue 47, item 3): Moodle's offline grading worksheet out and back, names
with accents kept whole; Canvas's points possible, user ids without a roster, anonymous
assignments, semicolon-separated gradebooks, and ``LATE``."""

from __future__ import annotations

import csv
import io
import json
import unicodedata
import zipfile
from datetime import datetime, timezone
from pathlib import Path

import classgen
import pytest
from click.testing import CliRunner

from lagrade.cli.bulk import export, grade, import_
from lagrade.uses.bulk.exports import MOODLE_COLUMNS

REPO = classgen.REPO
RIGHT = (REPO / "reference_solutions/12.3/answer.py").read_text()
HALF = (REPO / "tests/answers/12.3/wrong_forgets_second_spring_on_x1.py").read_text()
HW = ('name = "hw7"\ntitle = "Homework 7"\ncanvas_assignment_id = 4411\n'
      '[[problems]]\nid = "12.3"\nweight = 4\nparts = { L = 1, eom = 3 }\n')
NOVAK = "Jan Novák"


def _run(command, *args: str):
    res = CliRunner().invoke(command, [str(a) for a in args])
    return res


def _grade(subs: Path, tmp: Path) -> Path:
    hw = tmp / "hw7.toml"
    hw.write_text(HW)
    db = tmp / "hw7.sqlite"
    res = _run(grade, subs, "-a", hw, "--db", db, "-j", "1", "--no-summary")
    assert res.exit_code == 0, res.output
    return db


def _hw(tmp: Path) -> Path:
    hw = tmp / "hw7.toml"
    hw.write_text(HW)
    return hw


# ------------------------------------------------------------------ Moodle


def _moodle_zip(path: Path) -> None:
    """Moodle's "Download all submissions" as its zip holds it: UTF-8 names without the zip's UTF-8
    flag (Python then reads them as CP437: 'Jan NovĂˇk'), a folder per participant."""
    name = f"{NOVAK}_502_assignsubmission_file_/12.3.py".encode("utf-8")
    stand_in = b"X" * len(name)  # an ASCII name of the same length, its bytes then made UTF-8's
    with zipfile.ZipFile(path, "w") as z:
        z.writestr(stand_in.decode(), RIGHT)
        z.writestr("Ada Lovelace_503_assignsubmission_file_/12_3.py", HALF)
    data = path.read_bytes()
    assert data.count(stand_in) == 2  # the local header and the central directory
    path.write_bytes(data.replace(stand_in, name))
    with zipfile.ZipFile(path) as z:
        assert not any(i.flag_bits & 0x800 for i in z.infolist())
        assert NOVAK not in z.namelist()[0]  # as Python reads it unaided


@pytest.fixture(scope="module")
def moodle(tmp_path_factory):
    """A Moodle download imported (the zip) and graded: 502 Jan Novák right (4), 503 half (2.5)."""
    tmp = tmp_path_factory.mktemp("moodle")
    _moodle_zip(tmp / "moodle.zip")
    res = _run(import_, tmp / "moodle.zip", "-a", _hw(tmp), "-o", tmp / "subs")
    assert res.exit_code == 0, res.output
    return tmp, _grade(tmp / "subs", tmp), res


def test_a_name_with_accents_is_kept_whole(moodle, tmp_path):
    """Issue 47: "Jan Novák" became a folder without its "á"."""
    tmp, _, res = moodle
    assert sorted(p.name for p in (tmp / "subs").iterdir() if p.is_dir()) == ["502_Jan_Novák", "503_Ada_Lovelace"]
    lms = json.loads((tmp / "subs" / ".lagrade-import.json").read_text())["students"]
    assert lms["502_Jan_Novák"] == {"name": NOVAK, "moodle_participant_id": "502"}
    # a folder unzipped on macOS holds the decomposed form (a + combining accent): one folder, NFC
    dl = tmp_path / "download"
    decomposed = unicodedata.normalize("NFD", NOVAK)
    (dl / f"{decomposed}_502_assignsubmission_file_").mkdir(parents=True)
    (dl / f"{decomposed}_502_assignsubmission_file_" / "12.3.py").write_text("L = 1\n")
    assert _run(import_, dl, "-a", _hw(tmp_path), "-o", tmp_path / "out").exit_code == 0
    assert [p.name for p in (tmp_path / "out").iterdir() if p.is_dir()] == ["502_Jan_Novák"]
    assert json.loads((tmp_path / "out" / ".lagrade-import.json").read_text())["students"][
        "502_Jan_Novák"]["name"] == NOVAK


def moodle_reads(text: str, assignment_max: float) -> dict[str, float]:
    """What Moodle's "Upload grading worksheet" takes from a worksheet (assignfeedback_offline's
    grade_importer and assign_feedback_offline::process_import_grades): the columns found by their
    exact names ``Identifier``, ``Grade``, ``Last modified (grade)`` (the import fails without one of
    them), the participant id after ``Participant ``, the grade as a float; a row whose grade is empty
    or above the assignment's maximum, or whose time PHP's strtotime cannot read, is skipped."""
    rows = list(csv.reader(io.StringIO(text)))
    header = rows[0]
    for column in ("Identifier", "Grade", "Last modified (grade)"):
        assert column in header, f"Moodle refuses the file: no {column!r} column"
    idx, grade, modified = (header.index(c) for c in ("Identifier", "Grade", "Last modified (grade)"))
    out = {}
    for r in rows[1:]:
        assert r[idx].startswith("Participant "), r
        if not r[grade].strip():
            continue
        value = float(r[grade].replace(",", "."))
        stamp = datetime.fromisoformat(r[modified])  # ISO 8601 with its offset: strtotime reads it exactly
        assert stamp.tzinfo is not None and abs((datetime.now(timezone.utc) - stamp).total_seconds()) < 3600
        if 0 <= value <= assignment_max:
            out[r[idx][len("Participant "):]] = value
    return out


def test_moodles_worksheet_round_trips(moodle):
    """``lagrade export --format moodle``: Moodle's own columns, in its order; each participant's grade
    as Moodle's import reads it is lagrade's total, and the feedback says each problem's points."""
    tmp, db, _ = moodle
    res = _run(export, db, "--format", "moodle")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    assert list(rows[0].keys()) == MOODLE_COLUMNS == [
        "Identifier", "Full name", "Email address", "Status", "Grade", "Maximum Grade", "Grade can be changed",
        "Last modified (submission)", "Last modified (grade)", "Feedback comments"]
    assert moodle_reads(res.stdout, 4) == {"502": 4.0, "503": 2.5}
    assert {r["Identifier"]: r["Full name"] for r in rows} == {"Participant 502": NOVAK,
                                                               "Participant 503": "Ada Lovelace"}
    assert rows[0]["Feedback comments"] == "lagrade: 12.3 4 / 4" and rows[0]["Maximum Grade"] == "4"
    plain = {r["student"]: float(r["total"]) for r in csv.DictReader(io.StringIO(_run(export, db, "--format",
                                                                                      "csv").stdout))}
    assert plain == {"502_Jan_Novák": 4.0, "503_Ada_Lovelace": 2.5}


def test_moodles_own_worksheet_is_filled_in(moodle, tmp_path):
    """``--roster worksheet.csv``: the worksheet Moodle wrote keeps its rows and columns; the
    participants with a folder get their grade, the others are left as they were."""
    tmp, db, _ = moodle
    sheet = tmp_path / "worksheet.csv"
    sheet.write_text(
        '"Identifier","Full name","Email address","Status","Grade","Maximum Grade","Grade can be changed",'
        '"Last modified (submission)","Last modified (grade)","Feedback comments"\n'
        f'"Participant 502","{NOVAK}",jan@example.edu,"Submitted for grading",,4.00,Yes,'
        '"Monday, 7 December 2026, 9:12 AM",-,\n'
        '"Participant 504","Bob Babbage",bob@example.edu,"No submission",3.00,4.00,Yes,-,'
        '"Monday, 7 December 2026, 9:15 AM","by hand"\n', encoding="utf-8")
    res = _run(export, db, "--format", "moodle", "--roster", sheet)
    assert res.exit_code == 0, res.output
    rows = {r["Identifier"]: r for r in csv.DictReader(io.StringIO(res.stdout))}
    assert rows["Participant 502"]["Grade"] == "4" and rows["Participant 502"]["Email address"] == "jan@example.edu"
    assert rows["Participant 504"]["Grade"] == "3.00" and rows["Participant 504"]["Feedback comments"] == "by hand"
    assert rows["Participant 504"]["Last modified (grade)"] == "Monday, 7 December 2026, 9:15 AM"
    assert rows["Participant 504"]["Last modified (submission)"] == "-"  # Moodle's "none", kept as it wrote it
    assert "1 student folders are on no row" in res.stderr and "503_Ada_Lovelace" in res.stderr
    # Moodle's maximum grade below lagrade's total: Moodle would skip those grades: said
    sheet.write_text(sheet.read_text(encoding="utf-8").replace("4.00", "2.00"), encoding="utf-8")
    res = _run(export, db, "--format", "moodle", "--roster", sheet)
    assert "Moodle's maximum grade is 2 and lagrade's total is 4" in res.stderr, res.stderr
    bad = tmp_path / "not-a-worksheet.csv"
    bad.write_text("Student,ID\nAda,1\n")
    res = _run(export, db, "--format", "moodle", "--roster", bad)
    assert res.exit_code == 2 and "Download grading worksheet" in res.stderr and res.stdout == ""


def test_a_moodle_export_of_a_gradebook_without_moodle_students_is_refused(tmp_path):
    (tmp_path / "subs" / "ada").mkdir(parents=True)
    (tmp_path / "subs" / "ada" / "12.3.py").write_text(RIGHT)
    db = _grade(tmp_path / "subs", tmp_path)
    res = _run(export, db, "--format", "moodle")
    assert res.exit_code != 0 and "Moodle download" in res.output and len(res.output.strip().splitlines()) == 1


# ------------------------------------------------------------------ Canvas


@pytest.fixture(scope="module")
def canvas(tmp_path_factory):
    """A Canvas download: ada (user 101, LATE, right), bob (102, half), an anonymous student."""
    tmp = tmp_path_factory.mktemp("canvas")
    dl = tmp / "download"
    dl.mkdir()
    (dl / "lovelaceada_LATE_101_9104_12.3.py").write_text(RIGHT)  # canvas-lms writes "LATE" in capitals
    (dl / "babbagebob_102_9105_12.3.py").write_text(HALF)
    (dl / "anon_Xy7Q2_9106_12.3.py").write_text(RIGHT)
    res = _run(import_, dl, "-a", _hw(tmp), "-o", tmp / "subs")
    assert res.exit_code == 0, res.output
    assert "(1 late)" in res.output
    return tmp, _grade(tmp / "subs", tmp)


def test_the_late_marker_in_capitals(canvas):
    tmp, db = canvas
    lms = json.loads((tmp / "subs" / ".lagrade-import.json").read_text())["students"]
    assert lms["lovelaceada_101"]["late"] is True and lms["babbagebob_102"]["late"] is False
    plain = {r["student"]: r["late"] for r in csv.DictReader(io.StringIO(_run(export, db, "--format", "csv").stdout))}
    assert plain["lovelaceada_101"] == "late" and plain["babbagebob_102"] == ""


def test_canvas_ids_without_a_roster(canvas):
    """Issue 47: without a roster the user id the download named was left out, so Canvas matched no row."""
    _, db = canvas
    res = _run(export, db, "--format", "canvas")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    by_id = {r["ID"]: r for r in rows if r["ID"]}
    assert by_id["101"]["Homework 7 (4411)"] == "4" and by_id["102"]["Homework 7 (4411)"] == "2.5"
    assert by_id["101"]["SIS Login ID"] == ""  # not the folder name: Canvas would look it up as a login
    anon = next(r for r in rows if r["Student"] == "anon_Xy7Q2")
    assert anon["ID"] == ""


def test_an_anonymous_assignment_says_how_its_grades_go_back(canvas):
    _, db = canvas
    res = _run(export, db, "--format", "canvas")
    line = next(x for x in res.stderr.splitlines() if "anonymous" in x)
    assert line.startswith("lagrade: 1 students came from an anonymous assignment")
    for words in ("unmasks", "download the submissions again", "lagrade import"):
        assert words in line, line


ROSTER = ("Student,ID,SIS User ID,SIS Login ID,Section,Homework 7 (4411)\n"
          "    Points Possible,,,,,{points}\n"
          "\"Lovelace, Ada\",101,S101,ada,A,\n"
          "\"Babbage, Bob\",102,S102,bob,A,\n")


def test_canvas_points_possible_against_lagrades_total(canvas, tmp_path):
    _, db = canvas
    roster = tmp_path / "roster.csv"
    roster.write_text(ROSTER.format(points="10"))
    res = _run(export, db, "--format", "canvas", "--roster", roster)
    assert res.exit_code == 0, res.output
    warning = next(x for x in res.stderr.splitlines() if "points possible" in x)
    assert "'Homework 7 (4411)' is 10, lagrade's total is 4" in warning and "set the assignment's points" in warning
    roster.write_text(ROSTER.format(points="4"))
    assert "points possible" not in _run(export, db, "--format", "canvas", "--roster", roster).stderr


def test_a_semicolon_separated_gradebook_is_read(canvas, tmp_path):
    """Excel in a European locale saves Canvas's export with ';' (and decimal commas): read the same."""
    _, db = canvas
    comma, semi = tmp_path / "comma.csv", tmp_path / "semicolon.csv"
    comma.write_text(ROSTER.format(points="10"))
    rows = list(csv.reader(io.StringIO(ROSTER.format(points="10"))))
    rows[1][-1] = "10,0"  # the decimal comma of the locale
    buf = io.StringIO()
    csv.writer(buf, delimiter=";", lineterminator="\r\n").writerows(rows)
    semi.write_text("\ufeff" + buf.getvalue(), encoding="utf-8")
    a = _run(export, db, "--format", "canvas", "--roster", comma)
    b = _run(export, db, "--format", "canvas", "--roster", semi)
    assert a.exit_code == b.exit_code == 0, b.output
    assert a.stdout == b.stdout and a.stdout.splitlines()[0].count(",") == 5
    assert "semicolon-separated" in b.stderr and "lagrade's total is 4" in b.stderr
    bad = tmp_path / "tabs.csv"
    bad.write_text(ROSTER.format(points="10").replace(",", "\t"))
    res = _run(export, db, "--format", "canvas", "--roster", bad)
    assert res.exit_code == 2 and "Export Entire Gradebook" in res.stderr and res.stdout == ""
    latin = tmp_path / "latin1.csv"
    latin.write_bytes(ROSTER.format(points="10").replace("Ada", "Adá").encode("cp1252"))
    res = _run(export, db, "--format", "canvas", "--roster", latin)
    assert res.exit_code == 2 and "CSV UTF-8" in res.stderr


def test_a_lone_dash_is_moodles_none_not_a_formula():
    from lagrade.uses.bulk.exports import spreadsheet_safe

    assert spreadsheet_safe("-") == "-"
    assert spreadsheet_safe("-2") == "'-2" and spreadsheet_safe("--") == "'--" and spreadsheet_safe(" -") == "' -"
