"""What a student reads names no server folder and no file they did not write (issue 32, item 5):
the grader runs ``/tmp/lagrade-grader-.../lagrade-job-.../12.22.py``; the student sent answer.py,
or typed text, which has no file name at all."""

from __future__ import annotations

import json

import pytest

from lagrade.uses.server.grading import for_student


def test_grader_messages_are_rewritten_for_the_student():
    raw = "12.22.py:2: ValueError: /tmp/lagrade-grader-1a2b/lagrade-job-9z/12.22.py"
    assert for_student(raw, "12.22", ".py", False) == "answer.py:2: ValueError: answer.py"
    assert for_student("12.22.toml:2: eom: item 1: invalid", "12.22", ".toml", True) == "eom: item 1: invalid"
    assert for_student("12.22.toml:1: not valid TOML", "12.22", ".toml", False) == "answer.toml:1: not valid TOML"
    assert for_student("see /tmp/lagrade-grader-7/x/y.json", "12.22", ".py", False) == "see (the grader's folder)"


@pytest.mark.slow
def test_no_server_path_or_invented_file_name_reaches_a_student(graded):
    app, client, alice = graded
    cases = [
        ({"files": {"file": ("answer.py", b"from lagrade.answer import *\nraise ValueError(__file__)\n")}}, "answer.py:2"),
        ({"files": {"file": ("answer.toml", b'L = "m1*(\n')}}, "answer.toml:1"),
        ({"json": {"answer": {"L": "m1*(", "eom": ["x_dd ==", "y_dd == 0"]}}}, "L: "),
    ]
    for kw, expected in cases:
        r = client.post("/api/v1/problems/12.22/check", headers=alice, **kw)
        assert r.status_code == 200, r.text
        text = json.dumps(r.json())
        assert expected in text, text
        for never in ("/tmp", "lagrade-grader", "lagrade-job", "12.22.py", "12.22.toml"):
            assert never not in text, (never, text)
        page = client.get(f"/api/v1/submissions/{r.json()['submission_id']}", headers=alice).text
        assert "12.22.toml" not in page and "lagrade-grader" not in page
