"""CSV injection: a class whose folder names are formulas, graded for real, exported every way.

A spreadsheet runs a cell that begins with ``=``, ``+``, ``-``, ``@``, a tab or a carriage return
as a formula (``=cmd|' /C calc'!A0`` starts a program in old Excel). Students choose their folder
names and file names, so every text cell of every CSV export must come out as text, with
lagrade's own numbers left as numbers and honest names left as they are.
"""

from __future__ import annotations

import csv
import io
import json
import shutil

import classgen
import pytest
from click.testing import CliRunner

from lagrade.uses.bulk.exports import FORMULA_STARTS, spreadsheet_safe
from lagrade.cli.bulk import export, grade, report

REPO = classgen.REPO
FORMULAS = ["=cmd|' -C calc'!A0", "+1", "-2", "@SUM(A1)", " =1+1"]  # a leading space hides nothing
#: the classic payload holds a '/': on disk, folder "=cmd|' " (a student, nothing gradable) holding
#: folder "C calc'!A0" (skipped: a folder inside a student folder)
DDE = "=cmd|' /C calc'!A0"
HONEST = ["ada", "o'hara", "lee, j"]
#: folder names no student id may have (control characters): they reach the skipped export
CONTROL = ["\tTAB", "\rCR"]
LOOSE = ['=HYPERLINK("x")', "-rf.txt", "+x.py", "@x.toml"]  # loose files: skipped, path first


def _rows(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text)))


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("injection")
    root = tmp / "submissions"
    for student in FORMULAS + HONEST:
        (root / student).mkdir(parents=True)
        shutil.copyfile(REPO / "reference_solutions/12.43/answer.py", root / student / "12.43.py")
    (root / DDE).mkdir(parents=True)
    (root / DDE / "12.43.py").write_text("H = 1\n")
    for name in CONTROL:
        (root / name).mkdir()
        (root / name / "12.43.py").write_text("H = 1\n")
    for name in LOOSE:
        (root / name).write_text("H = 1\n")
    hw = tmp / "hw.toml"
    hw.write_text('name = "=hw7"\n[[problems]]\nid = "12.43"\n')  # even the instructor's own text
    db = tmp / "hw.sqlite"
    res = CliRunner().invoke(grade, [str(root), "-a", str(hw), "--db", str(db), "-j", "2", "--no-summary"])
    assert res.exit_code == 0, res.output
    return tmp, db


def _export(db, *args) -> str:
    res = CliRunner().invoke(export, [str(db), *args])
    assert res.exit_code == 0, res.output
    return res.stdout


def _no_formula(rows: list[list[str]]) -> None:
    # lagrade's own numbers here are points, never negative: no cell at all may begin like a formula
    bad = [c for row in rows for c in row if c.startswith(FORMULA_STARTS)]
    assert not bad, f"cells a spreadsheet would run: {bad}"


def test_every_csv_export_writes_formula_names_as_text(graded):
    tmp, db = graded
    roster = tmp / "roster.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\nPoints Possible,,,,\n"
                      "\"Hara, O\",=1+1,-S1,o'hara,@A\n")
    outputs = {"canvas": _export(db), "canvas --roster": _export(db, "--roster", str(roster)),
               "csv": _export(db, "--format", "csv"), "skipped": _export(db, "--format", "skipped")}
    for name, text in outputs.items():
        assert text.count("\n") > 1, name
        _no_formula(_rows(text))

    canvas = _rows(outputs["canvas"])
    assert canvas[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "'=hw7"]
    assert canvas[1] == ["Points Possible", "", "", "", "", "3"]
    by_student = {r[0]: r for r in canvas[2:]}
    for student in FORMULAS:
        assert by_student["'" + student] == ["'" + student, "", "", "'" + student, "", "3"], student
    for student in HONEST:  # unchanged
        assert by_student[student] == [student, "", "", student, "", "3"], student
    assert by_student["'=cmd|' "] == ["'=cmd|' ", "", "", "'=cmd|' ", "", "0"]
    # the roster's ids (from Canvas, where students may have typed them) are text cells too
    assert ["Hara, O", "'=1+1", "'-S1", "o'hara", "'@A", "3"] in _rows(outputs["canvas --roster"])

    plain = _rows(outputs["csv"])
    assert plain[0] == ["student", "12.43", "total", "possible", "12.43 status", "jail", "overrides", "late"]
    by_student = {r[0]: r for r in plain[1:]}
    assert set(by_student) == {"'" + s for s in FORMULAS} | set(HONEST) | {"'=cmd|' "}
    for student in FORMULAS + HONEST:
        row = by_student[spreadsheet_safe(student)]
        assert row[1:5] == ["3", "3", "3", "graded"], row  # numbers stay numbers
        assert row[5], "the jail the grader reported"
    assert by_student["'=cmd|' "][1:] == ["0", "0", "3", "missing", "", "", ""]

    skipped = {r[0]: r[1] for r in _rows(outputs["skipped"])[1:]}
    assert skipped["'" + DDE] == "a folder inside a student folder (expected <student>/<problem-id>.py)"
    for name in CONTROL:  # a folder name with a control character is no student id: skipped, as text
        assert skipped["'" + name] == "the folder name cannot be a student id"
    for name in LOOSE:
        assert "student folder" in skipped["'" + name]


def test_the_html_report_and_gradescope_json_carry_names_as_they_are(graded):
    # HTML escapes (no spreadsheet reads it), JSON is Gradescope's: neither needs, nor gets, a quote
    tmp, db = graded
    res = CliRunner().invoke(report, [str(db), "--html", str(tmp / "report")])
    assert res.exit_code == 0, res.output
    index = (tmp / "report" / "index.html").read_text()
    assert 'data-student="=cmd|&#x27; -C calc&#x27;!A0"' in index and "&#x27;=cmd" not in index
    gs = json.loads(_export(db, "--format", "gradescope", "--student", "-2"))
    assert gs["score"] == 3 and "'" not in gs["output"]


def test_spreadsheet_safe_quotes_text_not_numbers():
    for cell in ["=1+1", "+1", "-2", "@SUM(A1)", "\tx", "\rx", "-1.5", " =1", "  +1", " \t@A", "\n=1"]:
        assert spreadsheet_safe(cell) == "'" + cell
    for cell in ["ada", "12.43", "", "a=b", " a=1", "'quoted"]:
        assert spreadsheet_safe(cell) == cell
    assert spreadsheet_safe(-1.5) == "-1.5" and spreadsheet_safe(3.0) == "3" and spreadsheet_safe(2) == "2"
