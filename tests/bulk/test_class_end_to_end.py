"""A generated class of 232 submissions graded end to end through the CLI, with exact expected scores."""

from __future__ import annotations

import csv
import io
import json
import sqlite3

import classgen
from classcheck import assert_expected, stored
from click.testing import CliRunner

from lagrade.cli.bulk import export, grade, report


def test_class_of_232_submissions(tmp_path, sentinel):
    root = tmp_path / "submissions"
    expected = classgen.make_class(root, 60, sentinel=sentinel)
    assert len(expected) >= 200
    kinds = {e.variant.split("_")[0] for e in expected}
    assert {"reference", "equivalent", "correct", "wrong", "scaled", "broken", "hostile"} <= kinds
    hw = tmp_path / "hw7.toml"
    hw.write_text(classgen.assignment_toml())
    db = tmp_path / "hw7.sqlite"
    runner = CliRunner()

    res = runner.invoke(grade, [str(root), "--assignment", str(hw), "--db", str(db), "--workers", "2"])
    assert res.exit_code == 0, res.output
    assert f"{len(expected)} submissions: {len(expected)} graded now" in res.output
    assert "Most common mistakes" in res.output
    assert_expected(db, expected)

    # skipped files are listed with their reason
    con = sqlite3.connect(db)
    skipped = dict(con.execute("SELECT path, reason FROM skipped"))
    for path, word in classgen.EXPECTED_SKIPS.items():
        assert word in skipped[path], (path, skipped.get(path))
    assert "symbolic link" in skipped["s003/12.43_link.py"]
    assert "keep one" in skipped["twin/12.43.py"] and "keep one" in skipped["twin/12.43.toml"]
    assert con.execute("SELECT count(*) FROM grade_log").fetchone()[0] == len(expected)

    # run again: nothing is graded twice
    res = runner.invoke(grade, [str(root), "--assignment", str(hw), "--db", str(db), "--no-summary"])
    assert res.exit_code == 0, res.output
    assert "0 graded now" in res.output and f"{len(expected)} unchanged" in res.output
    assert con.execute("SELECT count(*) FROM grade_log").fetchone()[0] == len(expected)

    # exports agree with the construction
    weights = {pid: classgen.part_weights(pid) for pid in classgen.FAST_PROBLEMS}
    per_student: dict[str, float] = {}
    for e in expected:
        per_student[e.student] = per_student.get(e.student, 0.0) + e.score(weights[e.problem])
    res = runner.invoke(export, [str(db), "--format", "canvas"])
    rows = list(csv.reader(io.StringIO(res.output)))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "hw7"]
    assert rows[1][0] == "Points Possible" and float(rows[1][5]) == sum(sum(w.values()) for w in weights.values())
    got = {r[3]: float(r[5]) for r in rows[2:] if r[3] in per_student}
    assert got.keys() == per_student.keys()
    assert all(abs(got[s] - per_student[s]) < 1e-3 for s in got)

    res = runner.invoke(export, [str(db), "--format", "csv"])
    plain = list(csv.DictReader(io.StringIO(res.output)))
    assert {r["student"]: float(r["total"]) for r in plain if r["student"] in per_student} == \
        {s: round(v, 4) for s, v in per_student.items()}

    res = runner.invoke(export, [str(db), "--format", "gradescope", "--student", "s005"])
    gs = json.loads(res.output)
    assert abs(gs["score"] - per_student["s005"]) < 1e-3
    assert abs(sum(t["score"] for t in gs["tests"]) - gs["score"]) < 1e-3
    assert all(set(t) == {"name", "number", "score", "max_score", "status", "output", "tags", "visibility"}
               for t in gs["tests"])
    import jsonschema

    jsonschema.validate(gs, json.loads((classgen.REPO / "tests/deploy/gradescope_results.schema.json").read_text()))

    res = runner.invoke(report, [str(db), "--html", str(tmp_path / "report")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "report" / "index.html").is_file()
    assert len(list((tmp_path / "report" / "students").glob("*.html"))) == 61  # 60 + the 'twin' folder

    # changing one file regrades that file only
    e = next(x for x in expected if x.variant == "reference")
    path = root / e.student / f"{e.problem}.py"
    path.write_text(path.read_text() + "\n# edited\n")
    res = runner.invoke(grade, [str(root), "--assignment", str(hw), "--db", str(db), "--no-summary"])
    assert "1 graded now" in res.output, res.output
    assert con.execute("SELECT count(*) FROM grade_log").fetchone()[0] == len(expected) + 1
    subs, _ = stored(db)
    assert subs[(e.student, e.problem)]["score"] == e.score(weights[e.problem])


def test_a_grader_has_imported_what_sympy_loads_lazily_for_common_answers():
    """Sandbox children are forked from the zygote: what it has not imported, every answer that
    calls ``solve`` or ``euler_equations`` would import again (about 0.1 s each, measured), and
    every answer that differentiates a Matrix (30-45 ms)."""
    import subprocess
    import sys

    # not loaded by `import sympy`: by `solve`, and by differentiating a Matrix
    lazy = ("sympy.physics.units", "sympy.combinatorics", "sympy.tensor.array.expressions")
    probe = ("import sys, sympy\nbefore = [m in sys.modules for m in {lazy!r}]\n"
             "from lagrade.answer.jail.zygote import _warm_sympy\n_warm_sympy()\n"
             "print(not any(before) and all(m in sys.modules for m in {lazy!r}))").format(lazy=lazy)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "True", out.stderr
