"""Assignment weights, exports, the Gradescope entry point and the HTML report (in a real browser)."""

from __future__ import annotations

import json
import re
import shutil
import sqlite3
import subprocess

import classgen
import pytest
from click.testing import CliRunner

from lagrade.uses.bulk.assignment import AssignmentError, parse_assignment, points
from lagrade.uses.bulk.html_report import slug
from lagrade.cli.bulk import export, grade, gradescope, report

REPO = classgen.REPO


def test_points_use_assignment_weights():
    ap = parse_assignment({"problems": [{"id": "12.3", "weight": 10, "parts": {"L": 3}}]}).problems[0]
    parts = [{"part": "L", "score": 0.5, "max_score": 1.0}, {"part": "eom", "score": 1.0, "max_score": 1.0}]
    assert points(ap, parts, 2.0) == (pytest.approx(10 * (3 * 0.5 + 1) / 4), 10)
    with pytest.raises(AssignmentError, match="listed twice"):
        parse_assignment({"problems": [{"id": "12.3"}, {"id": "12.3"}]})
    with pytest.raises(AssignmentError, match="accuracy"):
        parse_assignment({"accuracy": "sloppy", "problems": [{"id": "12.3"}]})


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("small")
    root = tmp / "submissions"
    for student, files in {
        "ada": {"12.43.py": REPO / "reference_solutions/12.43/answer.py",
                "12.3.toml": REPO / "tests/answers/12.3/correct_expanded.toml"},
        "bob": {"12.43.py": REPO / "tests/answers/12.43/wrong_sign_of_V.py",
                "12.3.py": REPO / "tests/answers/12.3/wrong_forgets_second_spring_on_x1.py"},
        "cy <z>": {"12.43.toml": REPO / "tests/answers/12.43/wrong_in_velocities.toml"},
    }.items():
        (root / student).mkdir(parents=True)
        for name, src in files.items():
            shutil.copyfile(src, root / student / name)
    (root / "bob" / "essay.docx").write_bytes(b"PK")
    hw = tmp / "hw.toml"
    hw.write_text('name = "hw7"\ntitle = "Homework 7"\n[[problems]]\nid = "12.43"\nweight = 6\n'
                  '[[problems]]\nid = "12.3"\nparts = { L = 1, eom = 3 }\n')
    db = tmp / "hw.sqlite"
    res = CliRunner().invoke(grade, [str(root), "-a", str(hw), "--db", str(db), "-j", "2", "--plots"])
    assert res.exit_code == 0, res.output
    # by construction: ada full (6 + 2); bob 12.43: H 0, hamilton 1/2, eom 0 -> 6 * 0.5/3 = 1,
    # bob 12.3: L 1, eom 1/2 with weights 1:3 -> 2 * (1 + 1.5)/4 = 1.25; cy 12.43: H 0 -> 4, no 12.3
    return tmp, db, {"ada": 8.0, "bob": 2.25, "cy <z>": 4.0}


def test_exports(graded):
    tmp, db, totals = graded
    runner = CliRunner()
    canvas = runner.invoke(export, [str(db)]).output.splitlines()
    assert canvas[:2] == ["Student,ID,SIS User ID,SIS Login ID,Section,hw7", "Points Possible,,,,,8"]
    assert canvas[2:] == ["ada,,,ada,,8", "bob,,,bob,,2.25", "cy <z>,,,cy <z>,,4"]
    roster = tmp / "roster.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\nPoints Possible,,,,\n"
                      "\"Lovelace, Ada\",101,S1,ada,A\n")
    res = runner.invoke(export, [str(db), "--roster", str(roster)])
    canvas = res.stdout.splitlines()
    assert canvas[2:] == ['"Lovelace, Ada",101,S1,ada,A,8']  # only the roster's students reach Canvas
    assert "2 student folders are on no row" in res.stderr and res.stderr.rstrip().endswith(": bob, cy <z>")
    assert "skipped" not in runner.invoke(export, [str(db), "--format", "csv"]).output
    assert "bob/essay.docx" in runner.invoke(export, [str(db), "--format", "skipped"]).output
    res = runner.invoke(export, [str(db), "--format", "gradescope"])
    assert res.exit_code != 0 and "--student" in res.output
    gs = json.loads(runner.invoke(export, [str(db), "--format", "gradescope", "--student", "bob"]).output)
    assert gs["score"] == pytest.approx(2.25)
    assert {t["name"]: t["score"] for t in gs["tests"]} == pytest.approx(
        {"12.43 H": 0, "12.43 hamilton": 1.0, "12.43 eom": 0, "12.3 L": 0.5, "12.3 eom": 0.75})


def test_gradescope_entry_point(tmp_path):
    sub = tmp_path / "submission" / "nested"
    sub.mkdir(parents=True)
    shutil.copyfile(REPO / "reference_solutions/12.3/answer.py", sub / "12.3.py")
    hw = tmp_path / "assignment.toml"
    hw.write_text('name = "hw7"\n[[problems]]\nid = "12.3"\n[[problems]]\nid = "12.43"\n')
    out = tmp_path / "results" / "results.json"
    res = CliRunner().invoke(gradescope, ["--submission", str(tmp_path / "submission"), "--assignment", str(hw),
                                          "--results", str(out), "-j", "1"])
    assert res.exit_code == 0, res.output
    data = json.loads(out.read_text())
    assert data["score"] == 2
    # 12.43 not handed in: its parts' tests, as a handed-in 12.43 has them (Gradescope's statistics)
    assert [t["name"] for t in data["tests"]] == ["12.3 L", "12.3 eom", "12.43 H", "12.43 hamilton", "12.43 eom"]
    assert sum(t["max_score"] for t in data["tests"][2:]) == 3 and "No file" in data["tests"][2]["output"]


def _chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")


def _dom(browser: str, url: str) -> tuple[str, str]:
    p = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0",
                        "--virtual-time-budget=3000", "--dump-dom", url], capture_output=True, text=True, timeout=120)
    return p.stdout, p.stderr


@pytest.mark.skipif(_chromium() is None, reason="no chromium: apt-get install -y chromium "
                    "(or run scripts/check_report_in_browser.sh)")
def test_report_in_headless_chromium(graded):
    tmp, db, totals = graded
    folder = tmp / "report"
    res = CliRunner().invoke(report, [str(db), "--html", str(folder)])
    assert res.exit_code == 0, res.output
    browser = _chromium()
    con = sqlite3.connect(db)
    dom, log = _dom(browser, (folder / "index.html").as_uri())
    body = re.search(r"<body([^>]*)>", dom).group(1)
    assert 'data-loaded="yes"' in body and 'data-errors="0"' in body and 'data-scripts="ran"' in body, body
    assert "CONSOLE" not in log or "Uncaught" not in log, log
    for student, total in totals.items():
        row = re.search(rf'<tr data-student="{re.escape(student.replace("<", "&lt;").replace(">", "&gt;"))}">(.*?)</tr>',
                        dom)
        assert row, student
        assert float(re.search(r'class="num total" data-value="([\d.]+)"', row.group(1)).group(1)) == \
            pytest.approx(total)
    n_sub = con.execute("SELECT count(*) FROM submissions WHERE problem = '12.43'").fetchone()[0]
    assert len(re.findall(r'<rect class="bar"[^>]*data-count="(\d+)"', dom)) == 20
    counts = [int(c) for c in re.findall(r'data-problem="12.43"[^>]*>(?:.(?!</svg>))*', dom)[0:1] and
              re.findall(r'data-count="(\d+)"', dom.split('data-problem="12.43" width')[1].split("</svg>")[0])]
    assert sum(counts) == n_sub
    for student, total in totals.items():
        dom, _ = _dom(browser, (folder / "students" / f"{slug(student)}.html").as_uri())
        assert 'data-errors="0"' in dom
        assert float(re.search(r'id="total" data-value="([\d.]+)"', dom).group(1)) == pytest.approx(total)
        for part, verdict, score in con.execute("SELECT part, verdict, score FROM parts WHERE student = ?", (student,)):
            assert f'<tr data-part="{part}">' in dom and f">{verdict}<" in dom
        if student == "bob":
            assert "<math" in dom and "<mover" in dom  # answers rendered as math, with dots for d/dt


def test_verdicts_to_review_reach_the_class_page_and_tracebacks_no_student_page(graded, tmp_path):
    """A part whose evidence could not decide (``review``) and an engine ``error`` (with its traceback)
    are listed for the instructor on the class page; the traceback never reaches a student's page."""
    tmp, db, _ = graded
    copy = tmp_path / "hw.sqlite"
    shutil.copyfile(db, copy)
    with sqlite3.connect(copy) as con:
        con.execute("UPDATE parts SET review = 'decided by the sampled states alone' "
                    "WHERE student = 'ada' AND problem = '12.43' AND part = 'H'")
        con.execute("UPDATE parts SET verdict = 'error', detail = 'Traceback (most recent call last): XYZZY' "
                    "WHERE student = 'bob' AND problem = '12.43' AND part = 'H'")
    folder = tmp_path / "report"
    res = CliRunner().invoke(report, [str(copy), "--html", str(folder)])
    assert res.exit_code == 0, res.output
    index = (folder / "index.html").read_text()
    section = index[index.index('<table id="review">'):]
    section = section[:section.index("</table>")]
    assert "decided by the sampled states alone" in section and "ada" in section
    assert "XYZZY" in section and "bob" in section
    for page in (folder / "students").glob("*.html"):
        assert "XYZZY" not in page.read_text(), page



def test_the_gradebook_keeps_each_rejections_certificate_and_no_student_page_shows_it(graded, tmp_path):
    """A rejection at sampled states is proved in ball arithmetic; its certificate (the exact point and
    the enclosure) is the instructor's: stored with the part in the gradebook, never on a student's page
    (the enclosure is a difference from the reference)."""
    tmp, db, _ = graded
    with sqlite3.connect(db) as con:
        rows = dict(con.execute("SELECT part, certificate FROM parts WHERE student = 'bob' AND problem = '12.43'"))
        right = con.execute("SELECT certificate FROM parts WHERE student = 'ada' AND problem = '12.43'").fetchall()
    assert "excludes 0, at the exact point" in rows["H"] and "excludes 0" in rows["eom"], rows
    assert right and all(c is None for (c,) in right)
    folder = _report(db, tmp_path / "report")
    for page in folder.rglob("*.html"):
        assert "excludes 0" not in page.read_text(), page



PNG = b"\x89PNG\r\n\x1a\n"


def _report(db, folder):
    res = CliRunner().invoke(report, [str(db), "--html", str(folder)])
    assert res.exit_code == 0, res.output
    return folder


def test_the_class_page_has_a_histogram_of_total_scores(graded, tmp_path):
    """A matplotlib PNG of the totals, its counts said in the alt text (a screen reader's) and in
    ``data-counts``: ada 8 of 8 (the last bin holds full marks), bob 2.25, cy 4."""
    from html import unescape

    tmp, db, totals = graded
    folder = _report(db, tmp_path / "report")
    index = (folder / "index.html").read_text()
    fig = re.search(r'<figure id="totals-histogram" data-counts="([\d,]+)"><img src="totals.png" alt="([^"]+)"', index)
    assert fig, index[:2000]
    assert [int(c) for c in fig.group(1).split(",")] == [0, 0, 1, 0, 0, 1, 0, 0, 0, 1]
    alt = unescape(fig.group(2))
    assert "total scores out of 8 points, 3 students" in alt and "1 student from 1.6 to 2.4" in alt, alt
    assert "1 student from 7.2 to 8" in alt and "1 student from 4 to 4.8" in alt, alt
    assert (folder / "totals.png").read_bytes()[:8] == PNG


def test_a_wrong_motion_is_drawn_on_its_students_page(graded, tmp_path):
    """``lagrade grade`` stores the picture PrairieLearn's grader and ``lagrade check --plot`` draw;
    the student's page shows it, with alt text; a right answer has none."""
    tmp, db, _ = graded
    with sqlite3.connect(db) as con:
        stored = dict(((s, p), n) for s, p, n in con.execute("SELECT student, problem, length(plot_png) FROM submissions"))
    assert stored[("bob", "12.43")] > 1000 and stored[("ada", "12.43")] == 0  # 0: asked, nothing wrong to draw
    folder = _report(db, tmp_path / "report")
    bob = (folder / "students" / "bob.html").read_text()
    fig = re.search(r'<figure class="motion" data-problem="12.43"><img src="([^"]+)" alt="([^"]+)"', bob)
    assert fig, bob
    assert (folder / "students" / fig.group(1)).read_bytes()[:8] == PNG
    assert "Your motion" in fig.group(2) and "12.43" in fig.group(2) and "H" in fig.group(2)
    assert 'class="motion"' not in (folder / "students" / "ada.html").read_text()


def test_a_wrong_answer_graded_without_its_picture_is_drawn_by_the_next_run(tmp_path):
    """Pictures are drawn when asked for (``--plots``), not inside every grading: the report says how many
    wrong files have none and how to draw them; the run that asks grades only those again."""
    root = tmp_path / "submissions"
    (root / "bob").mkdir(parents=True)
    shutil.copyfile(REPO / "tests/answers/12.43/wrong_sign_of_V.py", root / "bob" / "12.43.py")
    hw = tmp_path / "hw.toml"
    hw.write_text('name = "hw"\n[[problems]]\nid = "12.43"\n')
    db = tmp_path / "hw.sqlite"
    res = CliRunner().invoke(grade, [str(root), "-a", str(hw), "--db", str(db), "-j", "1"])  # pictures: not by default
    assert res.exit_code == 0, res.output
    with sqlite3.connect(db) as con:
        assert con.execute("SELECT plot_png FROM submissions").fetchone()[0] is None
    res = CliRunner().invoke(report, [str(db), "--html", str(tmp_path / "report")])
    assert res.exit_code == 0 and "1 graded file with a part not correct was graded without the pictures" in res.output
    assert "--plots" in res.output, res.output
    res = CliRunner().invoke(grade, [str(root), "-a", str(hw), "--db", str(db), "-j", "1", "--plots"])
    assert res.exit_code == 0 and "1 graded now" in res.output, res.output
    with sqlite3.connect(db) as con:
        assert con.execute("SELECT plot_png FROM submissions").fetchone()[0][:8] == PNG
    res = CliRunner().invoke(grade, [str(root), "-a", str(hw), "--db", str(db), "-j", "1", "--plots"])
    assert res.exit_code == 0 and "0 graded now" in res.output, res.output
    res = CliRunner().invoke(report, [str(db), "--html", str(tmp_path / "report")])
    assert res.exit_code == 0 and "without the pictures" not in res.output, res.output


def test_files_that_could_not_be_graded_say_whose(graded, tmp_path):
    tmp, db, _ = graded
    copy = tmp_path / "hw.sqlite"
    shutil.copyfile(db, copy)
    with sqlite3.connect(copy) as con:
        con.execute("UPDATE submissions SET outcome = 'failed', status = 'syntax', "
                    "reason = '12.3.py:2: syntax error: XYZZY' WHERE student = 'bob' AND problem = '12.3'")
    index = (_report(copy, tmp_path / "report") / "index.html").read_text()
    section = index[index.index("<h2>Files that could not be graded</h2>"):]
    section = section[:section.index("</table>")]
    row = re.search(r'<tr data-student="bob" data-problem="12.3">(.*?)</tr>', section)
    assert row and 'href="students/bob.html"' in row.group(1) and "XYZZY" in row.group(1) and "syntax" in row.group(1)


@pytest.mark.skipif(_chromium() is None, reason="no chromium: apt-get install -y chromium")
def test_the_points_column_does_not_run_into_the_answer_at_1280_px(graded, tmp_path):
    """Weights whose points print long (1.2354 / 2.4707, weight 3.333 of 7.083): in a 1280 px window
    every points cell's text ends inside its cell, left of the answer."""
    sync_api = pytest.importorskip("playwright.sync_api")
    tmp, db, _ = graded
    copy = tmp_path / "hw.sqlite"
    shutil.copyfile(db, copy)
    with sqlite3.connect(copy) as con:
        a = json.loads(con.execute("SELECT value FROM meta WHERE key = 'assignment'").fetchone()[0])
        a["problems"][0].update(weight=7.0, parts={"H": 1.25, "hamilton": 2.5, "eom": 3.333})
        con.execute("UPDATE meta SET value = ? WHERE key = 'assignment'", (json.dumps(a),))
    folder = _report(copy, tmp_path / "report")
    measure = """() => Array.from(document.querySelectorAll('table.parts tr[data-part]')).map(tr => {
      const pts = tr.querySelector('td[data-label=points]'), ans = tr.querySelector('td.answer'), r = document.createRange();
      r.selectNodeContents(pts);
      return [tr.dataset.part, r.getBoundingClientRect().right, ans.getBoundingClientRect().left,
              pts.scrollWidth > pts.clientWidth];
    })"""
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=_chromium(), args=["--headless", "--no-sandbox", "--disable-gpu"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 1000})
            for student in ("ada", "bob"):
                page.goto((folder / "students" / f"{student}.html").as_uri())
                rows = page.evaluate(measure)
                assert len(rows) == 5
                assert "1.2354 / 2.4707" in page.content() or student == "ada"
                assert [r for r in rows if r[1] > r[2] or r[3]] == [], (student, rows)
        finally:
            browser.close()
