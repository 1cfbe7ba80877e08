"""Checking answers through the API: right, wrong, broken and hostile files of 12.22 and 12.14, as
JSON values and as uploads, graded by the warm graders in the jail; the export and the report of
the server's database."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from serverkit import GOLDEN, REPO, bearer, expectations, golden, sign_in, toml_answer

from lagrade.cli import main
from lagrade.uses.server.tokens import INSTRUCTOR

pytestmark = pytest.mark.slow

GOLDEN_FILES = [p for pid in ("12.22", "12.14") for p in golden(pid)]
BROKEN = {"syntax.py": b"from sympy import *\nL = (m*\n", "empty.py": b"", "not_utf8.py": b"L = 1\n# \xff\xfe\n",
          "bad.toml": b'L = "m*\n'}
HOSTILE = {"import_os.py": b"import os\nos.system('touch /tmp/lagrade-pwned')\nL = 1\n",
           "read_reference.py": f"L = open({str(REPO / 'reference_solutions' / '12.22' / 'answer.py')!r}).read()\n".encode(),
           "while_true.py": b"while True:\n    pass\n",
           "subclasses.py": b"x = ().__class__.__bases__[0].__subclasses__()\nL = len(x)\n"}


def _check(client, headers, pid, path=None, name=None, data=None, answer=None):
    if answer is not None:
        r = client.post(f"/api/v1/problems/{pid}/check", headers=headers, json={"answer": answer})
    else:
        r = client.post(f"/api/v1/problems/{pid}/check", headers=headers,
                        files={"file": (name or path.name, data if data is not None else path.read_bytes())})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["state"] == "graded" and isinstance(body["submission_id"], int)
    return body


def _golden_header(path):
    if path.suffix == ".py":
        return expectations(path)
    first = path.read_text(encoding="utf-8").splitlines()[0]  # TOML files carry the same comment
    return expectations(path) if first.startswith("#") else {}


@pytest.mark.parametrize("path", GOLDEN_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_golden_answers_get_their_expected_verdicts(graded, path):
    app, client, h = graded
    pid = path.parent.name
    body = _check(client, h, pid, path, name=f"answer{path.suffix}")
    verdicts = {p["part"]: p["verdict"] for p in body["parts"]}
    expected = _golden_header(path)
    if path.name.startswith("correct"):
        assert all(v == "correct" for v in verdicts.values()), verdicts
        assert body["score"] == body["max_score"]
    for part, verdict in expected.items():
        assert verdicts[part] == verdict, (part, verdicts)
    if path.suffix == ".toml":  # the same values sent as JSON: the same grade
        again = _check(client, bearer(app, "json-student"), pid, answer=toml_answer(path))
        assert {p["part"]: (p["verdict"], p["score"]) for p in again["parts"]} == \
            {p["part"]: (p["verdict"], p["score"]) for p in body["parts"]}


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_broken_files_get_zero_and_a_reason(graded, name):
    app, client, h = graded
    body = _check(client, h, "12.22", name=name, data=BROKEN[name])
    assert body["score"] == 0
    assert all(p["verdict"] in ("invalid", "missing") and p["feedback"] for p in body["parts"])
    assert body["problems"] or any(p["verdict"] == "invalid" for p in body["parts"]) \
        or all(p["verdict"] == "missing" for p in body["parts"])  # an empty file: nothing bound, each part says so


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_files_are_contained(graded, name, tmp_path):
    app, client, h = graded
    body = _check(client, h, "12.14", name=name, data=HOSTILE[name])
    assert body["score"] == 0
    assert body["status"] != "ok" or all(p["verdict"] in ("invalid", "missing", "incorrect") for p in body["parts"])
    assert not Path("/tmp/lagrade-pwned").exists()  # import_os.py's command never ran
    text = json.dumps(body)
    assert "Compound (double) Atwood" not in text and "4 * g / (1 / m1" not in text  # no reference file content


def test_the_response_is_what_a_local_check_prints(graded):
    app, client, h = graded
    path = GOLDEN / "12.22" / "wrong_S3_equals_S1.py"
    body = _check(client, h, "12.22", path, name="answer.py")
    local = CliRunner().invoke(main, ["check", "12.22", str(path), "--json"])
    mine = json.loads(local.output)
    for key in ("problem", "score", "max_score", "problems"):
        assert body[key] == mine[key], key
    strip = ()

    def same(parts):  # the feedback says how long a comparison took: not part of the grade
        return [{k: re.sub(r"\d+\.\d+ s\b", "_ s", v) if k == "feedback" else v for k, v in p.items() if k not in strip}
                for p in parts]

    # a student reads the evidence in words (lagrade.verdicts.words); the instructor's view is --json's, whole
    from lagrade.verdicts.words import in_words

    kinds = {p.name: p.kind for p in app.state.server.problems["12.22"].parts}
    worded = [{**p, "feedback": in_words(p["feedback"], kinds[p["part"]])} for p in mine["parts"]]
    assert same(body["parts"]) == same(worded)
    whole = client.get(f"/api/v1/submissions/{body['submission_id']}", headers=bearer(app, INSTRUCTOR)).json()
    assert same(whole["parts"]) == same(mine["parts"])


def test_export_and_report_read_the_server_database(graded):
    app, client, h = graded
    for student in ("dora", "eve"):
        _check(client, bearer(app, student), "12.22", GOLDEN / "12.22" / "correct_plain.toml", name="answer.toml")
    db = str(app.state.server.db.sqlite_path)
    runner = CliRunner()
    out = runner.invoke(main, ["export", db, "--format", "csv"])
    assert out.exit_code == 0, out.output
    rows = {line.split(",")[0]: line for line in out.output.splitlines()}
    assert "dora" in rows and "eve" in rows
    report = runner.invoke(main, ["report", db])
    assert report.exit_code == 0 and "12.22" in report.output, report.output
    book = app.state.server.db.gradebook()
    dora = book.student("dora").problems["12.22"]
    assert dora.submitted and dora.points == dora.possible
    assert app.state.server.db._gradebook().student("dora").problems["12.22"].points == dora.points  # the SQLAlchemy reader agrees


def test_the_class_page_is_the_instructors(graded, instructor):
    app, client, h = graded
    assert client.get("/class/", headers=h).status_code == 401
    c2 = type(client)(app)
    sign_in(app, c2, instructor)
    page = c2.get("/class/")
    assert page.status_code == 200 and "12.22" in page.text
