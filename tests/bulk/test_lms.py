"""The round trip with an LMS: import its downloads, override a part, export to Canvas, the student page."""

from __future__ import annotations

import csv
import io
import re
import shutil
import sqlite3
from pathlib import Path

import classgen
import pytest
from click.testing import CliRunner

from lagrade.uses.bulk.gradebook import load_gradebook
from lagrade.uses.bulk.intake import import_downloads, match_name
from lagrade.uses.bulk.layout import scan
from lagrade.uses.bulk.overrides import apply_overrides
from lagrade.uses.bulk.store import SCHEMA, Store
from lagrade.cli.bulk import export, grade, import_, override, report

REPO = classgen.REPO
HW = ('name = "hw7"\ntitle = "Homework 7"\ncanvas_assignment_id = 4411\n'
      '[[problems]]\nid = "12.3"\nweight = 4\nparts = { L = 1, eom = 3 }\n')
ROSTER = ("Student,ID,SIS User ID,SIS Login ID,Section\n"
          "    Points Possible,,,,\n"
          "\"Lovelace, Ada\",101,S101,ada,A\n"
          "\"Babbage, Bob\",102,S102,bob,A\n"
          "\"Carol, C\",103,S103,carol,B\n")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """ada: right (4); bob: eom half right (L 1, eom 1/2 with weights 1:3 -> 4 * 2.5/4 = 2.5);
    zed: a folder on no roster row; carol: on the roster, no folder."""
    tmp = tmp_path_factory.mktemp("lms")
    root = tmp / "submissions"
    for student, src in {"ada": REPO / "reference_solutions/12.3/answer.py",
                         "bob": REPO / "tests/answers/12.3/wrong_forgets_second_spring_on_x1.py",
                         "zed": REPO / "reference_solutions/12.3/answer.py"}.items():
        (root / student).mkdir(parents=True)
        shutil.copyfile(src, root / student / "12.3.py")
    (root / "bob" / "12_3.py").write_text("L = 1\n")  # a near miss beside the right name: skipped, said why
    (tmp / "hw7.toml").write_text(HW)
    (tmp / "roster.csv").write_text(ROSTER)
    db = tmp / "hw7.sqlite"
    res = CliRunner().invoke(grade, [str(root), "-a", str(tmp / "hw7.toml"), "--db", str(db), "-j", "2",
                                     "--no-summary"])
    assert res.exit_code == 0, res.output
    return tmp, db


def _canvas(db: Path, *args: str) -> tuple[list[list[str]], str]:
    res = CliRunner().invoke(export, [str(db), "--format", "canvas", *args])
    assert res.exit_code == 0, res.output
    return list(csv.reader(io.StringIO(res.stdout))), res.stderr


def test_canvas_fills_the_assignments_column_from_the_roster(graded):
    tmp, db = graded
    rows, err = _canvas(db, "--roster", str(tmp / "roster.csv"))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Homework 7 (4411)"]
    assert rows[1] == ["Points Possible", "", "", "", "", "4"]
    # carol is on the roster and handed nothing in: by default no row, so Canvas keeps what it has
    assert rows[2:] == [["Lovelace, Ada", "101", "S101", "ada", "A", "4"],
                        ["Babbage, Bob", "102", "S102", "bob", "A", "2.5"]]
    assert "1 roster students have no folder and are left out" in err and "Carol, C" in err
    assert "1 student folders are on no row" in err and err.rstrip().endswith(": zed")
    rows, err = _canvas(db, "--roster", str(tmp / "roster.csv"), "--missing", "zero")
    assert rows[4] == ["Carol, C", "103", "S103", "carol", "B", "0"] and "given 0" in err
    rows, err = _canvas(db, "--roster", str(tmp / "roster.csv"), "--missing", "blank")
    assert rows[4] == ["Carol, C", "103", "S103", "carol", "B", ""] and "REMOVES the grade" in err
    rows, _ = _canvas(db)  # no roster: every folder, its name as SIS Login ID
    assert [r[0] for r in rows[2:]] == ["ada", "bob", "zed"]


def test_a_near_miss_beside_the_right_name_is_skipped_with_a_hint(graded):
    _, db = graded
    book = load_gradebook(db)
    assert any(p == "bob/12_3.py" and "named like problem 12.3" in r for p, r in book.skipped), book.skipped


@pytest.mark.parametrize("name, problem, exact", [
    ("12.3.py", "12.3", True), ("12_3.py", "12.3", False), ("12.3 (1).py", "12.3", False),
    ("12.3.PY", "12.3", False), ("hw7-12.3.py", "12.3", False), ("12.3-1.toml", "12.3", False),
    ("ex12.3.py", "ex12.3", True), ("ex12_3.py", "ex12.3", False), ("12.32.py", None, None),
    ("123.py", None, None), ("12.3.docx", None, None)])
def test_near_miss_names(name, problem, exact):
    m = match_name(name, ["12.3", "ex12.3", "12.22"])
    assert (m.problem, m.exact) == (problem, exact) if problem else m is None


def test_import_a_canvas_download(graded, tmp_path):
    tmp, _ = graded
    dl = tmp_path / "download"
    dl.mkdir()
    ref = (REPO / "reference_solutions/12.3/answer.py").read_bytes()
    (dl / "lovelaceada_101_9001_12.3.py").write_bytes(ref)           # roster id 101 -> folder "ada"
    (dl / "babbagebob_late_102_9002_12_3.py").write_bytes(ref)       # late, a near miss; 102 -> "bob"
    (dl / "doejane_555_9003_hw7-12.3 (1).PY").write_bytes(ref)       # not on the roster, two near misses
    (dl / "doejane_555_9004_essay.py").write_bytes(b"x = 1\n")        # matches no problem
    (dl / "roe_9005_12.3.toml").write_bytes(b'L = "m"\n')             # the short form: login_submission_file
    (dl / "README.txt").write_text("not a submission")
    out = tmp_path / "submissions"
    res = CliRunner().invoke(import_, [str(dl), "-a", str(tmp / "hw7.toml"), "-o", str(out),
                                       "--roster", str(tmp / "roster.csv")])
    assert res.exit_code == 0, res.output
    assert sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file() and p.name[0] != ".") == [
        "ada/12.3.py", "bob/12.3.py", "doejane_555/12.3.py", "roe/12.3.toml"]
    assert (out / "ada" / "12.3.py").read_bytes() == ref
    assert "babbagebob_late_102_9002_12_3.py was graded as problem 12.3" in res.output
    assert "doejane_555_9003_hw7-12.3 (1).PY was graded as problem 12.3" in res.output
    assert "doejane_555_9004_essay.py matches no problem" in res.output
    assert "README.txt: not a Canvas download name" in res.output
    layout = scan(out, ["12.3"])
    assert len(layout.submissions) == 4 and not layout.skipped


def test_import_a_gradescope_export(tmp_path):
    dl = tmp_path / "assignment_77_export"
    (dl / "submission_555").mkdir(parents=True)
    (dl / "submission_556" / "work").mkdir(parents=True)
    (dl / "submission_555" / "12.3.py").write_text("L = 1\n")
    (dl / "submission_556" / "work" / "12_22.py").write_text("L = 2\n")
    (dl / "submission_metadata.yml").write_text(
        "submission_555:\n  :submitters:\n  - :name: Ada Lovelace\n    :sid: '12345'\n    :email: ada@uni.edu\n"
        "  :score: 0.0\nsubmission_556:\n  :submitters:\n  - :name: Bob Babbage\n    :email: bob@uni.edu\n")
    report = import_downloads(dl, ["12.3", "12.22"], tmp_path / "out")
    assert report.kind == "gradescope" and sorted(report.students) == ["12345", "bob"]
    assert (tmp_path / "out" / "12345" / "12.3.py").read_text() == "L = 1\n"
    assert (tmp_path / "out" / "bob" / "12.22.py").read_text() == "L = 2\n"
    assert any("work/12_22.py was graded as problem 12.22" in n for n in report.notes), report.notes


def test_override_is_kept_across_regrades_and_shown_everywhere(graded, tmp_path):
    tmp, db0 = graded
    db = tmp_path / "hw7.sqlite"
    shutil.copyfile(db0, db)
    runner = CliRunner()
    res = runner.invoke(override, [str(db), "bob", "12.3", "eom", "1", "--reason", "sign convention accepted"])
    assert res.exit_code == 0, res.output
    assert "total 4 / 4" in res.output
    for _ in range(2):  # before and after a full regrade
        rows, _ = _canvas(db, "--roster", str(tmp / "roster.csv"))
        assert rows[3][-1] == "4"
        plain = {r["student"]: r for r in csv.DictReader(io.StringIO(
            runner.invoke(export, [str(db), "--format", "csv"]).stdout))}
        assert plain["bob"]["total"] == "4" and "12.3 eom = 1 / 1 (sign convention accepted)" in plain["bob"]["overrides"]
        assert plain["ada"]["overrides"] == ""
        res = runner.invoke(grade, [str(tmp / "submissions"), "-a", str(tmp / "hw7.toml"), "--db", str(db),
                                    "-j", "2", "--regrade", "--no-summary"])
        assert res.exit_code == 0, res.output
    res = runner.invoke(report, [str(db), "--html", str(tmp_path / "report")])
    page = (tmp_path / "report" / "students" / "bob.html").read_text()
    assert "Score set by your instructor: sign convention accepted" in page
    assert "sign convention accepted" in (tmp_path / "report" / "index.html").read_text()
    assert "Score set by your instructor" not in (tmp_path / "report" / "students" / "ada.html").read_text()
    # removing it brings the engine's score back
    assert runner.invoke(override, [str(db), "bob", "12.3", "eom", "--remove"]).exit_code == 0
    assert _canvas(db)[0][3][-1] == "2.5"


@pytest.mark.parametrize("args, message", [
    (["nobody", "12.3", "eom", "1"], "no student 'nobody'"),
    (["bob", "12.43", "H", "1"], "not in the assignment"),
    (["bob", "12.3", "T", "1"], "no part 'T' (its parts: L, eom)"),
    (["bob", "12.3", "eom", "2"], "between 0 and 1"),
    (["bob", "12.3", "eom", "1"], "--reason"),
])
def test_override_refuses_what_it_cannot_do(graded, tmp_path, args, message):
    _, db0 = graded
    db = tmp_path / "hw7.sqlite"
    shutil.copyfile(db0, db)
    extra = ["--reason", "x"] if message != "--reason" else []
    res = CliRunner().invoke(override, [str(db), *args, *extra])
    assert res.exit_code == 2 and message in res.output, res.output
    with Store(db, create=False) as store:
        assert store.overrides() == []


def test_an_old_gradebook_without_the_overrides_table(graded, tmp_path):
    """Read as it is (no overrides), and migrated by the first writer."""
    _, db0 = graded
    db = tmp_path / "old.sqlite"
    shutil.copyfile(db0, db)
    con = sqlite3.connect(db)
    con.execute("DROP TABLE overrides")
    con.commit()
    con.close()
    assert "overrides" in SCHEMA
    book = load_gradebook(db)
    assert apply_overrides(book, db) == []
    res = CliRunner().invoke(override, [str(db), "bob", "12.3", "L", "0", "--reason", "copied"])
    assert res.exit_code == 0, res.output
    book = load_gradebook(db)
    apply_overrides(book, db)
    assert book.student("bob").points == pytest.approx(4 * 1.5 / 4)


def test_the_student_page_shows_weights_and_says_a_shared_message_once(graded, tmp_path):
    tmp, db = graded
    sub = tmp_path / "submissions" / "kim"
    sub.mkdir(parents=True)
    (sub / "12.3.py").write_text("from sympy import *\nL = (m*\n")
    db2 = tmp_path / "hw.sqlite"
    runner = CliRunner()
    assert runner.invoke(grade, [str(tmp_path / "submissions"), "-a", str(tmp / "hw7.toml"), "--db", str(db2),
                                 "-j", "1", "--no-summary"]).exit_code == 0
    assert runner.invoke(report, [str(db2), "--html", str(tmp_path / "r")]).exit_code == 0
    page = (tmp_path / "r" / "students" / "kim.html").read_text()
    reason = load_gradebook(db2).student("kim").problems["12.3"].reason
    assert reason and page.count(reason.split("\n")[0][:40].replace("'", "&#x27;")) == 1, page
    assert page.count("see above") == 2
    runner.invoke(report, [str(db), "--html", str(tmp_path / "r2")])
    page = (tmp_path / "r2" / "students" / "bob.html").read_text()
    # the weights the total uses: L 1 of 4 points, eom 3 (1.5 earned); they sum to the problem's 4
    cells = re.findall(r'data-points="([\d.]+)" data-possible="([\d.]+)"', page)
    assert [(float(a), float(b)) for a, b in cells] == [(1.0, 1.0), (1.5, 3.0)]
    assert "weight 1 of 4" in page and "weight 3 of 4" in page


def _chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")


@pytest.mark.skipif(_chromium() is None, reason="no chromium: apt-get install -y chromium")
def test_a_wide_formula_scrolls_in_its_cell_on_a_phone_and_a_laptop(graded, tmp_path):
    """The page is never wider than the window: a long answer scrolls inside its own cell."""
    import subprocess

    tmp, _ = graded
    sub = tmp_path / "submissions" / "wide"
    sub.mkdir(parents=True)
    (sub / "12.3.py").write_text(
        "from sympy import Function, symbols, expand\nt = symbols('t')\nm, k = symbols('m k', positive=True)\n"
        "x1, x2 = Function('x1')(t), Function('x2')(t)\n"
        "L = expand(m/2*(x1.diff(t)**2 + x2.diff(t)**2) - k/2*(x1 + x2)**2*(1 + x1/3 + x2/5)**6)\n")
    db = tmp_path / "hw.sqlite"
    runner = CliRunner()
    assert runner.invoke(grade, [str(tmp_path / "submissions"), "-a", str(tmp / "hw7.toml"), "--db", str(db),
                                 "-j", "1", "--no-summary"]).exit_code == 0
    assert runner.invoke(report, [str(db), "--html", str(tmp_path / "r")]).exit_code == 0
    page = tmp_path / "r" / "students" / "wide.html"
    assert page.read_text().count("<mfrac") > 20  # the answer is long as math, not cut to text
    for width, url in [(w, u) for w in (390, 1280) for u in (page.as_uri(), (tmp_path / "r" / "index.html").as_uri())]:
        dom = subprocess.run([_chromium(), "--headless", "--no-sandbox", "--disable-gpu", f"--window-size={width},900",
                              "--virtual-time-budget=3000", "--dump-dom", url],
                             capture_output=True, text=True, timeout=120).stdout
        laid_out = int(re.search(r'data-page-width="(\d+)"', dom).group(1))
        window = int(re.search(r'data-window-width="(\d+)"', dom).group(1))  # headless: at least 500
        assert window <= 700 if width < 700 else window == width  # the phone layout is the one measured
        assert laid_out <= window, (width, window, laid_out)


def test_two_folders_for_one_roster_student_are_reported(graded):
    """``ada`` and ``101`` name the same Canvas student: the first folder counts, the second is said."""
    import dataclasses

    from lagrade.uses.bulk.exports import canvas_csv, not_on_roster, read_roster

    tmp, db = graded
    book = load_gradebook(db)
    book.students.append(dataclasses.replace(book.students[0], student="101"))
    roster = read_roster(tmp / "roster.csv")
    assert not_on_roster(book, roster) == ["zed", "101"]
    rows = list(csv.reader(io.StringIO(canvas_csv(book, roster, missing="zero"))))
    assert [r[3] for r in rows[2:]] == ["ada", "bob", "carol"]


# ------------------------------------------------------------------ Canvas's download, as its zipper names it
# canvas-lms ContentZipper#get_filename: [sortable name, "LATE" if late, user id].join("_"), every
# non-word character removed, lower-cased; then "_<attachment id>_<display name>" per file;
# "anon_<anonymous id>" in place of name and user id under anonymous grading.

def _import(dl: Path, out: Path, *args: str):
    return CliRunner().invoke(import_, [str(dl), "-a", str(_hw(out.parent)), "-o", str(out), *args])


def _hw(folder: Path) -> Path:
    path = folder / "hw7.toml"
    if not path.exists():
        path.write_text(HW)
    return path


def _files(out: Path) -> dict[str, str]:
    return {str(p.relative_to(out)): p.read_text() for p in sorted(out.rglob("*")) if p.is_file()
            and not p.name.startswith(".")}


def test_two_students_who_share_a_name_stay_two(tmp_path):
    """Grouped by Canvas user id: neither file replaces the other, with a roster or without."""
    dl = tmp_path / "download"
    dl.mkdir()
    (dl / "smithjohn_201_9001_12.3.py").write_text("L = 'right'\n")
    (dl / "smithjohn_202_9002_12.3.py").write_text("L = 0\n")
    res = _import(dl, tmp_path / "out")
    assert res.exit_code == 0, res.output
    assert _files(tmp_path / "out") == {"smithjohn_201/12.3.py": "L = 'right'\n", "smithjohn_202/12.3.py": "L = 0\n"}
    assert "several files" not in res.output
    roster = tmp_path / "roster.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\n    Points Possible,,,,\n"
                      "\"Smith, John\",201,S1,jsmith1,A\n\"Smith, John\",202,S2,jsmith2,A\n")
    res = _import(dl, tmp_path / "out2", "--roster", str(roster))
    assert res.exit_code == 0, res.output
    assert _files(tmp_path / "out2") == {"jsmith1/12.3.py": "L = 'right'\n", "jsmith2/12.3.py": "L = 0\n"}


def test_anonymous_underscored_late_and_zipped_downloads(tmp_path):
    import json
    import zipfile

    dl = tmp_path / "download"
    dl.mkdir()
    (dl / "anon_nb0xh_9101_12.3.py").write_text("L = 'anon1'\n")           # anonymous grading
    (dl / "late_anon_q7r2k_9102_12.3.py").write_text("L = 'anon2'\n")
    (dl / "o_brienmary_301_9103_12.3.py").write_text("L = 'mary'\n")       # "O_Brien, Mary": the _ stays
    (dl / "lovelaceada_late_101_9104_12.3.py").write_text("L = 'ada'\n")   # late
    with zipfile.ZipFile(dl / "turingalan_302_9105_hw7.zip", "w") as z:    # a zipped submission
        z.writestr("hw7/12.3.py", "L = 'alan'\n")
        z.writestr("../escape.py", "L = 1\n")
    res = _import(dl, tmp_path / "out")
    assert res.exit_code == 0, res.output
    assert _files(tmp_path / "out") == {
        "anon_nb0xh/12.3.py": "L = 'anon1'\n", "anon_q7r2k/12.3.py": "L = 'anon2'\n",
        "lovelaceada_101/12.3.py": "L = 'ada'\n", "o_brienmary_301/12.3.py": "L = 'mary'\n",
        "turingalan_302/12.3.py": "L = 'alan'\n"}
    assert "../escape.py in the zip is not a plain file inside it" in res.output
    assert not (tmp_path / "escape.py").exists()
    lms = json.loads((tmp_path / "out" / ".lagrade-import.json").read_text())["students"]
    assert lms["lovelaceada_101"] == {"canvas_user_id": "101", "name": "lovelaceada", "late": True}
    assert lms["anon_q7r2k"]["late"] and not lms["o_brienmary_301"]["late"]
    assert "(2 late)" in res.output


def test_anonymous_ids_that_differ_in_case_are_two_students(tmp_path):
    """Canvas's anonymous ids are case-sensitive (issue 43, item 6): they were lower-cased, so
    ``anon_AbC12`` and ``anon_abc12`` merged into one folder and one student's file was lost. Each keeps
    its case and its own folder, and the folders differ on a case-insensitive disk (macOS) as well."""
    import json

    dl = tmp_path / "download"
    dl.mkdir()
    (dl / "anon_AbC12_9101_12.3.py").write_text("L = 'first'\n")
    (dl / "anon_abc12_9102_12.3.py").write_text("L = 'second'\n")
    res = _import(dl, tmp_path / "out")
    assert res.exit_code == 0, res.output
    files = _files(tmp_path / "out")
    assert sorted(files.values()) == ["L = 'first'\n", "L = 'second'\n"], files
    folders = {Path(name).parent.name for name in files}
    assert len({f.casefold() for f in folders}) == 2, folders
    lms = json.loads((tmp_path / "out" / ".lagrade-import.json").read_text())["students"]
    assert sorted(v["anonymous_id"] for v in lms.values()) == ["AbC12", "abc12"]
    assert {Path(name).parent.name: text for name, text in files.items()}["anon_AbC12"] == "L = 'first'\n"


def test_the_late_marker_reaches_the_gradebook(tmp_path):
    dl = tmp_path / "download"
    dl.mkdir()
    ref = (REPO / "reference_solutions/12.3/answer.py").read_bytes()
    (dl / "lovelaceada_late_101_9104_12.3.py").write_bytes(ref)
    (dl / "babbagebob_102_9105_12.3.py").write_bytes(ref)
    assert _import(dl, tmp_path / "subs").exit_code == 0
    db = tmp_path / "hw7.sqlite"
    res = CliRunner().invoke(grade, [str(tmp_path / "subs"), "-a", str(_hw(tmp_path)), "--db", str(db), "-j", "1",
                                     "--no-summary"])
    assert res.exit_code == 0 and "0 files skipped" in " ".join(res.output.split()), res.output  # the record too
    plain = {r["student"]: r for r in csv.DictReader(io.StringIO(
        CliRunner().invoke(export, [str(db), "--format", "csv"]).stdout))}
    assert plain["lovelaceada_101"]["late"] == "late" and plain["babbagebob_102"]["late"] == ""


def test_importing_without_a_roster_then_exporting_with_one_is_refused(graded, tmp_path):
    """Every student would get no grade (or 0): one line, exit 2, never a CSV. A folder a Canvas
    download made carries its user id (issue 47): the roster's row of that ``ID`` is found."""
    tmp, db = graded
    dl = tmp_path / "download"
    dl.mkdir()
    ref = (REPO / "reference_solutions/12.3/answer.py").read_bytes()
    (dl / "lovelaceada_101_9001_12.3.py").write_bytes(ref)
    assert _import(dl, tmp_path / "subs").exit_code == 0
    db1 = tmp_path / "imported.sqlite"
    assert CliRunner().invoke(grade, [str(tmp_path / "subs"), "-a", str(tmp / "hw7.toml"), "--db", str(db1), "-j",
                                      "1", "--no-summary"]).exit_code == 0
    rows, _ = _canvas(db1, "--roster", str(tmp / "roster.csv"))
    assert rows[2][:2] == ["Lovelace, Ada", "101"] and rows[2][-1] == "4", rows
    (tmp_path / "plain" / "lovelaceada_101").mkdir(parents=True)  # the same folder, not from a download
    (tmp_path / "plain" / "lovelaceada_101" / "12.3.py").write_bytes(ref)
    db2 = tmp_path / "hw7.sqlite"
    assert CliRunner().invoke(grade, [str(tmp_path / "plain"), "-a", str(tmp / "hw7.toml"), "--db", str(db2), "-j",
                                      "1", "--no-summary"]).exit_code == 0
    for missing in ("keep", "zero"):
        res = CliRunner().invoke(export, [str(db2), "--format", "canvas", "--roster", str(tmp / "roster.csv"),
                                          "--missing", missing])
        assert res.exit_code == 2 and res.stdout == "", res.output
        assert len(res.stderr.strip().splitlines()) == 1 and "--roster" in res.stderr, res.stderr
    assert _canvas(db, "--roster", str(tmp / "roster.csv"))[0]  # some folders on the roster: exported


def test_bom_for_excel(graded):
    _, db = graded
    for fmt in ("canvas", "csv"):
        res = CliRunner().invoke(export, [str(db), "--format", fmt, "--bom"])
        assert res.exit_code == 0 and res.stdout_bytes.startswith(b"\xef\xbb\xbf"), res.output
        assert not CliRunner().invoke(export, [str(db), "--format", fmt]).stdout_bytes.startswith(b"\xef")
    assert CliRunner().invoke(export, [str(db), "--format", "gradescope", "--bom"]).exit_code == 2


def test_a_zipped_canvas_download_imports(tmp_path):
    import zipfile

    with zipfile.ZipFile(tmp_path / "submissions.zip", "w") as z:
        z.writestr("lovelaceada_101_9001_12.3.py", "L = 1\n")
    res = _import(tmp_path / "submissions.zip", tmp_path / "out")
    assert res.exit_code == 0, res.output
    assert _files(tmp_path / "out") == {"lovelaceada_101/12.3.py": "L = 1\n"}


def test_a_moodle_download_imports(tmp_path):
    """Moodle's "Download all submissions": a folder per student, and the flat form."""
    dl = tmp_path / "moodle"
    (dl / "Ada Lovelace_1234_assignsubmission_file_").mkdir(parents=True)
    (dl / "Ada Lovelace_1234_assignsubmission_file_" / "12.3.py").write_text("L = 'ada'\n")
    (dl / "Ada Lovelace_1235_assignsubmission_file_").mkdir()                      # a namesake
    (dl / "Ada Lovelace_1235_assignsubmission_file_" / "12_3.py").write_text("L = 'other'\n")
    (dl / "Participant_77_assignsubmission_file_").mkdir()                         # blind marking
    (dl / "Participant_77_assignsubmission_file_" / "12.3.py").write_text("L = 'blind'\n")
    (dl / "Bob Babbage_1236_assignsubmission_file_12.3.py").write_text("L = 'bob'\n")  # flat
    res = _import(dl, tmp_path / "out")
    assert res.exit_code == 0, res.output
    assert res.output.rstrip().splitlines()[-1].startswith("moodle: 4 files of 4 students")
    assert _files(tmp_path / "out") == {
        "1234_Ada_Lovelace/12.3.py": "L = 'ada'\n", "1235_Ada_Lovelace/12.3.py": "L = 'other'\n",
        "1236_Bob_Babbage/12.3.py": "L = 'bob'\n", "77/12.3.py": "L = 'blind'\n"}


def test_a_download_with_nothing_to_import_is_refused(tmp_path):
    dl = tmp_path / "download"
    (dl / "Ada Lovelace").mkdir(parents=True)
    (dl / "Ada Lovelace" / "12.3.py").write_text("L = 1\n")
    res = _import(dl, tmp_path / "out")
    assert res.exit_code == 2 and "nothing imported from" in res.stderr, res.output
    assert len(res.stderr.strip().splitlines()) == 1
