"""One rounding rule for every export, escaped feedback, and the same tests whether or not a problem
was handed in: Gradescope's results.json against the CSV and Canvas exports of the same gradebook."""

from __future__ import annotations

import csv
import io
import itertools
import json
from decimal import Decimal

import pytest

from lagrade.uses.bulk.assignment import parse_assignment, part_points, points
from lagrade.uses.bulk.exports import canvas_csv, gradescope_results, plain_csv
from lagrade.uses.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade

#: weight 10 over 3 equal parts: 10/3 is no multiple of 1/10000
HW = {"name": "hw", "problems": [{"id": "12.43", "weight": 10}, {"id": "12.3", "weight": 10}]}
HOSTILE = "<img src=x onerror=alert(1)>"


def _parts(fracs, names=("T", "V", "L")) -> list[dict]:
    return [{"part": n, "score": f, "max_score": 1.0, "verdict": "correct" if f == 1 else "incorrect",
             "feedback": f"part {n}", "answer_text": "x(t)**2"} for n, f in zip(names, fracs)]


def _book(fmt: str = "text", a_fracs=(0, 0.5, 1), b_fracs=(1, 1), submitted=True, feedback: str = "") -> Gradebook:
    a = parse_assignment({**HW, "gradescope": {"output_format": fmt}}, "hw")
    pa, pb = _parts(a_fracs), _parts(b_fracs, ("L", "eom"))
    if feedback:
        pa[1]["feedback"] = feedback
        pa[1]["answer_text"] = feedback
    grades = {"12.43": ProblemGrade("12.43", points(a.problems[0], pa, 10)[0], 10, True, "graded", parts=pa),
              "12.3": ProblemGrade("12.3", points(a.problems[1], pb, 10)[0], 10, True, "graded", parts=pb)
              if submitted else ProblemGrade("12.3", 0.0, 10, False, reason="no file handed in")}
    return Gradebook(a, [StudentGrade("ada", grades)], [], "test")


@pytest.mark.parametrize("fracs", list(itertools.product((0, 0.5, 1), repeat=3)))
def test_parts_sum_exactly_to_the_problems_points(fracs):
    a = parse_assignment(HW, "hw")
    parts = _parts(fracs)
    total, possible = points(a.problems[0], parts, 10)
    split = part_points(a.problems[0], parts, 10)
    assert sum(Decimal(str(e)) for e, _ in split) == Decimal(str(total))
    assert sum(Decimal(str(m)) for _, m in split) == possible == 10
    exact = Decimal(10) * Decimal(str(sum(fracs))) / 3
    assert Decimal(str(total)) == exact.quantize(Decimal("0.0001"), rounding="ROUND_HALF_UP")
    assert all(0 <= e <= m for e, m in split)


def test_gradescope_csv_and_canvas_agree():
    """Parts 0, 1/2, 1 of 10 over 3: 5 points exactly, everywhere (Gradescope said 4.9999)."""
    book = _book()
    s = book.students[0]
    gs = gradescope_results(book, s)
    assert Decimal(str(gs["score"])) == sum(Decimal(str(t["score"])) for t in gs["tests"]) == Decimal("15")
    plain = next(csv.DictReader(io.StringIO(plain_csv(book))))
    assert plain["total"] == "15" and plain["12.43"] == "5"
    assert list(csv.reader(io.StringIO(canvas_csv(book))))[2][-1] == "15"
    assert json.dumps(gs).count("4.9999") == 0


@pytest.mark.parametrize("fmt", ["html", "md", "text"])
def test_every_student_supplied_string_is_escaped(fmt):
    book = _book(fmt, feedback=f"your dict key {HOSTILE} is not a symbol\nsecond line")
    gs = gradescope_results(book, book.students[0])
    text = json.dumps(gs)
    if fmt == "text":
        assert HOSTILE in text  # plain text is shown as text by Gradescope
        return
    if fmt == "md":  # the answer as read: a code span, which Markdown shows as text, HTML included
        assert f"Read as: `your dict key {HOSTILE} is not a symbol second line`" in text
        text = text.replace(f"`your dict key {HOSTILE} is not a symbol second line`", "")
    assert "<img" not in text, text
    outputs = [t["output"] for t in gs["tests"]]
    if fmt == "html":
        assert any("&lt;img src=x onerror=alert(1)&gt; is not a symbol<br>second line" in o for o in outputs), outputs
    else:
        assert any("&lt;img src=x onerror=alert(1)&gt; is not a symbol  \nsecond line" in o for o in outputs)


def test_the_tests_are_the_same_whether_or_not_a_problem_was_handed_in():
    handed = gradescope_results(b := _book(), b.students[0])
    missing = gradescope_results(b := _book(submitted=False), b.students[0])
    key = [(t["name"], t["number"], t["max_score"]) for t in handed["tests"]]
    assert [(t["name"], t["number"], t["max_score"]) for t in missing["tests"]] == key
    assert [t["name"] for t in missing["tests"]][-2:] == ["12.3 L", "12.3 eom"]
    gone = [t for t in missing["tests"] if t["name"].startswith("12.3 ")]
    assert all(t["score"] == 0 and t["status"] == "failed" for t in gone)
    assert "No file 12.3.py" in gone[0]["output"] and gone[1]["output"] == "See 12.3 L."


def test_the_answer_memory_bound_on_gradescope_is_below_its_container(tmp_path, monkeypatch):
    from lagrade.uses.bulk import runner
    from lagrade.cli import bulk

    seen = {}

    def fake_grade_folder(folder, a, db, **kw):
        seen["memory_mb"] = a.limits.memory_mb
        raise SystemExit(0)

    monkeypatch.setattr(runner, "grade_folder", fake_grade_folder)
    monkeypatch.setattr("lagrade.uses.deploy.jailcheck.decide", lambda **kw: __import__(
        "lagrade.uses.deploy.jailcheck", fromlist=["JailVerdict"]).JailVerdict(["uid"], file_view="mount"))
    (tmp_path / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "12.3"\n')
    with pytest.raises(SystemExit):
        bulk._gradescope_run(tmp_path, tmp_path / "hw.toml", tmp_path / "r.json", 1, ())
    assert seen["memory_mb"] == bulk.GRADESCOPE_MEMORY_MB < 768
    (tmp_path / "hw.toml").write_text('name = "hw"\n[limits]\nmemory_mb = 600\n[[problems]]\nid = "12.3"\n')
    with pytest.raises(SystemExit):
        bulk._gradescope_run(tmp_path, tmp_path / "hw.toml", tmp_path / "r.json", 1, ())
    assert seen["memory_mb"] == 600  # the instructor's own bound is kept


def _extra_book(parts_toml: dict | None, answered: dict[str, str] | None) -> Gradebook:
    """12.36 (H, hamilton; extras H_F, hamilton_F), its parts stored as the gradebook keeps them: in
    name order, each with its extra flag; ``answered``: part -> verdict (None: not handed in)."""
    a = parse_assignment({"name": "hw", "problems": [{"id": "12.36", "weight": 10, **(parts_toml or {})}]}, "hw")
    if answered is None:
        return Gradebook(a, [StudentGrade("ada", {"12.36": ProblemGrade("12.36", 0.0, 10, False,
                                                                         reason="no file handed in")})], [], "t")
    extras = {"H_F", "hamilton_F"}
    stored = [{"part": n, "score": 1.0 if v == "correct" else 0.0, "max_score": 1.0, "verdict": v,
               "feedback": v, "extra": n in extras} for n, v in sorted(answered.items())]
    pts, possible = points(a.problems[0], stored, 10)
    return Gradebook(a, [StudentGrade("ada", {"12.36": ProblemGrade("12.36", pts, possible, True, "graded",
                                                                     parts=stored)})], [], "t")


@pytest.mark.parametrize("parts_toml", [None, {"parts": {"H": 1, "hamilton": 1, "H_F": 1, "hamilton_F": 1}}])
def test_an_extra_part_never_changes_the_test_list(parts_toml):
    """Issue 47: the tests were the stored parts in name order (H, H_F, hamilton, ...) when handed
    in and the problem file's order when not, and an extra's share differed between the two."""
    cases = [None, {"H": "correct", "hamilton": "correct", "H_F": "missing", "hamilton_F": "missing"},
             {"H": "correct", "hamilton": "incorrect", "H_F": "correct", "hamilton_F": "incorrect"},
             {"H": "correct", "hamilton": "correct"}]  # a gradebook without the extras' rows
    keys = []
    for answered in cases:
        book = _extra_book(parts_toml, answered)
        gs = gradescope_results(book, book.students[0])
        keys.append([(t["name"], t["number"], t["max_score"]) for t in gs["tests"]])
        assert Decimal(str(gs["score"])) == sum(Decimal(str(t["score"])) for t in gs["tests"])
    assert all(k == keys[0] for k in keys), keys
    assert [k[0] for k in keys[0]] == ["12.36 H", "12.36 hamilton", "12.36 H_F", "12.36 hamilton_F"]
    shares = [k[2] for k in keys[0]]
    assert shares == ([5, 5, 0, 0] if parts_toml is None else [2.5, 2.5, 2.5, 2.5]), shares


@pytest.mark.parametrize("parts_toml", [None, {"parts": {"H": 1, "hamilton": 1, "H_F": 1, "hamilton_F": 1}}])
def test_a_wrong_extra_part_never_shows_passed(parts_toml):
    """An extra the assignment does not count is worth 0 points, and 0 >= 0 made a wrong one "passed"."""
    book = _extra_book(parts_toml, {"H": "correct", "hamilton": "correct", "H_F": "incorrect",
                                    "hamilton_F": "correct"})
    status = {t["name"]: t["status"] for t in gradescope_results(book, book.students[0])["tests"]}
    assert status == {"12.36 H": "passed", "12.36 hamilton": "passed", "12.36 H_F": "failed",
                      "12.36 hamilton_F": "passed"}, status
    for verdict in ("incorrect", "missing", "invalid", "partial"):
        book = _extra_book(parts_toml, {"H": "correct", "hamilton": "correct", "H_F": verdict,
                                        "hamilton_F": verdict})
        tests = gradescope_results(book, book.students[0])["tests"]
        assert all(t["status"] == "failed" for t in tests if "_F" in t["name"]), (verdict, tests)
