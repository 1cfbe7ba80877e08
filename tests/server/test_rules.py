"""A course's rules (the assignment's ``[rules]``): a deadline, an attempt limit with its penalty,
and a feedback level change what a student can do and see; the instructor sees the whole grade."""

from __future__ import annotations

import re

import pytest
from fastapi.testclient import TestClient
from serverkit import PROBLEMS, bearer, make_config, on_a_socket, sign_in

from lagrade.uses.server.app import create_app
from lagrade.uses.server.tokens import INSTRUCTOR

#: an L off by a factor in its cross term: not a named mistake, so the graders' term hints name it
HINTED_L = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + 2*m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)"
            " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
#: the L of the named mistake "the lower bob's velocity adds the upper bob's"
NAMED_L = ("m1*l1^2*theta1_d^2/2 + m2*(l1^2*theta1_d^2 + l2^2*theta2_d^2)/2 + (m1 + m2)*g*l1*cos(theta1) "
           "+ m2*g*l2*cos(theta2)")
RIGHT_L = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)"
           " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
#: the right L plus a constant outside the exact class (atan(2): log(2) is in it now): the motion decides
#: it, so its evidence is what a student reads in words
MOTION_L = RIGHT_L + " + g*l1*m1*atan(2)"


def app_with(tmp_path, rules: str, grade: bool = True, **kw):
    (tmp_path / "hw.toml").write_text('name = "hw-rules"\n[rules]\n' + rules + "\n" +
                                      "".join(f'[[problems]]\nid = "{pid}"\n' for pid in PROBLEMS), encoding="utf-8")
    kw.setdefault("checks_per_minute", 6000)
    kw.setdefault("check_burst", 1000)
    kw.setdefault("student_in_flight", 1000)
    return create_app(make_config(tmp_path, **kw), grade=grade)


def check(client, app, who: str, L: str):
    return client.post("/api/v1/problems/12.14/check", json={"answer": {"L": L}}, headers=bearer(app, who))


def test_an_attempt_limit_refuses_the_next_attempt_but_not_the_same_one_again(tmp_path):
    app = app_with(tmp_path, "attempts = 2", grade=False)
    with TestClient(app) as client:
        assert check(client, app, "alice", "1").status_code == 202
        assert check(client, app, "alice", "2").status_code == 202
        third = check(client, app, "alice", "3")
        assert third.status_code == 403, third.text
        assert "2 attempts" in third.json()["detail"]
        assert check(client, app, "alice", "2").status_code == 202  # the same content is the same attempt
        assert check(client, app, "bob", "3").status_code == 202  # per student
        assert check(client, app, INSTRUCTOR, "1").status_code == 202  # the instructor tries freely
        assert check(client, app, INSTRUCTOR, "2").status_code == 202
        assert check(client, app, INSTRUCTOR, "3").status_code == 202
        assert client.get("/api/v1/problems/12.14", headers=bearer(app, "alice")).json()["rules"]["attempts_left"] == 0
        # the page says so, and its button is off
        sign_in(app, client, 'alice')
        page = client.get("/p/12.14").text
        assert "data-no-attempts" in page and re.search(r'id="submit"\s+disabled', page)
        assert 'data-attempts-made>2<' in page


def test_without_rules_nothing_is_limited(tmp_path):
    app = app_with(tmp_path, "", grade=False)
    with TestClient(app) as client:
        for i in range(4):
            assert check(client, app, "alice", str(i)).status_code == 202
        rules = client.get("/api/v1/problems/12.14", headers=bearer(app, "alice")).json()["rules"]
        assert rules["attempts_left"] is None and rules["feedback"] == "named" and rules["deadline"] is None


def test_an_attempt_after_the_deadline_is_stored_and_marked_late(tmp_path):
    app = app_with(tmp_path, "deadline = 2020-01-01T00:00:00Z", grade=False)
    with TestClient(app) as client:
        r = check(client, app, "alice", "1")
        assert r.status_code == 202 and r.json()["rules"]["late"] is True
        sid = r.json()["submission_id"]
        assert client.get(f"/api/v1/submissions/{sid}", headers=bearer(app, "alice")).json()["rules"]["late"]
        assert client.get("/api/v1/problems/12.14/submissions", headers=bearer(app, "alice")).json()[0]["late"]
        assert client.get("/api/v1/problems/12.14", headers=bearer(app, "alice")).json()["rules"]["past_deadline"]


@pytest.fixture(scope="module")
def verdict_only(tmp_path_factory):
    """Graded, feedback = verdict, two attempts with half off the second, a deadline far ahead."""
    app = app_with(tmp_path_factory.mktemp("verdict"), 'feedback = "verdict"\nattempts = 2\nattempt_penalty = 0.5\n'
                                                      "deadline = 2999-01-01T00:00:00Z")
    with TestClient(app) as client:
        yield app, client


def test_feedback_verdict_shows_the_verdict_alone_and_no_picture(verdict_only):
    app, client = verdict_only
    r = check(client, app, "carol", NAMED_L)
    assert r.status_code == 200, r.text
    L = next(p for p in r.json()["parts"] if p["part"] == "L")
    assert L["verdict"] == "incorrect" and L["feedback"] == "Incorrect."
    assert "plot" not in r.json()
    # the instructor reads the grader's whole sentence, the named mistake
    mine = client.get(f"/api/v1/submissions/{r.json()['submission_id']}", headers=bearer(app, INSTRUCTOR)).json()
    assert "cross term" in next(p for p in mine["parts"] if p["part"] == "L")["feedback"]
    # the page too: no named mistake, no picture
    client.cookies.clear()
    sign_in(app, client, 'dave')
    page = client.get("/p/12.14").text
    csrf = re.search(r'name="csrf" value="([^"]+)"', page).group(1)
    page = client.post("/p/12.14/check", data={"csrf": csrf, "f:L": NAMED_L}).text
    assert re.search(r"data-verdict[^>]*>incorrect<", page) and "cross term" not in page and "data-plot" not in page
    assert "the verdict only" in page
    client.cookies.clear()


def test_the_penalty_takes_its_share_of_the_second_attempt(verdict_only):
    app, client = verdict_only
    first = check(client, app, "erin", NAMED_L).json()
    second = check(client, app, "erin", RIGHT_L).json()
    assert first["rules"]["attempt"] == 1 and second["rules"]["attempt"] == 2
    L = next(p for p in second["parts"] if p["part"] == "L")
    assert L["verdict"] == "correct" and L["score"] == pytest.approx(0.5 * L["max_score"])
    assert "50% off" in second["penalty"]
    # the gradebook holds the penalized grade of the latest attempt
    book = app.state.server.db.gradebook()
    erin = next(s for s in book.students if s.student == "erin")
    L_row = next(p for p in erin.problems["12.14"].parts if p["part"] == "L")
    assert L_row["score"] == pytest.approx(0.5 * L_row["max_score"])
    assert check(client, app, "erin", "m1").status_code == 403


@pytest.fixture(scope="module")
def hints_late(tmp_path_factory):
    """Graded, feedback = hints, the deadline passed."""
    app = app_with(tmp_path_factory.mktemp("hints"), 'feedback = "hints"\ndeadline = 2020-01-01T00:00:00Z')
    with TestClient(app) as client:
        yield app, client


def test_feedback_hints_gives_the_term_hints_and_the_evidence_in_words(hints_late):
    app, client = hints_late
    r = check(client, app, "frank", HINTED_L).json()
    L = next(p for p in r["parts"] if p["part"] == "L")
    assert "Hint: your term" in L["feedback"]
    right = check(client, app, "frank", MOTION_L).json()
    said = next(p for p in right["parts"] if p["part"] == "L")["feedback"]
    assert "your Lagrangian gives the same motion as the true one over t in [0, 2]" in said
    assert not re.search(r"DOP853|rtol|evaluations", said)
    whole = client.get(f"/api/v1/submissions/{right['submission_id']}", headers=bearer(app, INSTRUCTOR)).json()
    assert "evaluations" in next(p for p in whole["parts"] if p["part"] == "L")["feedback"]  # the instructor's


def test_a_late_attempt_is_graded_marked_and_kept_out_of_the_gradebook(hints_late):
    app, client = hints_late
    r = check(client, app, "gina", RIGHT_L)
    assert r.status_code == 200 and r.json()["state"] == "graded"
    assert r.json()["rules"]["late"] and "late" in r.json()["late"]
    book = app.state.server.db.gradebook()
    gina = [s for s in book.students if s.student == "gina"]
    assert not gina or not gina[0].problems["12.14"].submitted


def test_named_is_the_default_and_keeps_the_named_mistake_without_hints(graded):
    app, client, alice = graded
    r = client.post("/api/v1/problems/12.14/check", json={"answer": {"L": NAMED_L}}, headers=alice).json()
    L = next(p for p in r["parts"] if p["part"] == "L")
    assert "cross term" in L["feedback"] and "Hint:" not in L["feedback"]
    assert r["rules"]["feedback"] == "named"


def test_check_server_honours_the_feedback_level(verdict_only, tmp_path):
    """`lagrade check --server` prints what the server lets the student see: here the verdict alone."""
    import json

    from click.testing import CliRunner

    from lagrade.cli import main

    app, _ = verdict_only
    with on_a_socket(app) as url:
        answer = tmp_path / "answer.toml"
        answer.write_text(f'L = "{NAMED_L}"\n', encoding="utf-8")
        token = bearer(app, "hank")["Authorization"].split()[1]
        out = CliRunner().invoke(main, ["check", "12.14", str(answer), "--server", url, "--token", token, "--json"])
        got = json.loads(out.output)
        L = next(p for p in got["parts"] if p["part"] == "L")
        assert L["verdict"] == "incorrect" and L["feedback"] == "Incorrect."
        assert got["rules"]["attempt"] == 1 and got["rules"]["attempts_allowed"] == 2
        text = CliRunner().invoke(main, ["check", "12.14", str(answer), "--server", url, "--token", token])
        assert "cross term" not in text.output and "attempt 1 of 2" in text.output


def test_check_server_text_says_the_evidence_in_words(graded, live_url, tmp_path):
    """`lagrade check --server` prints a student's words (no integrator, tolerance, count or time);
    the same attempt read with the instructor's token keeps the settings."""
    from click.testing import CliRunner

    from lagrade.cli import main

    app = graded[0]
    answer = tmp_path / "answer.toml"
    answer.write_text(f'L = "{MOTION_L}"\n', encoding="utf-8")
    token = bearer(app, "iris")["Authorization"].split()[1]
    out = CliRunner().invoke(main, ["check", "12.14", str(answer), "--server", live_url, "--token", token],
                             env={"COLUMNS": "400"})
    text = " ".join(out.output.split())
    assert "your Lagrangian gives the same motion as the true one over t in [0, 2]" in text, out.output
    assert not re.search(r"DOP853|rtol|evaluations", out.output), out.output
    sid = CliRunner().invoke(main, ["check", "12.14", str(answer), "--server", live_url, "--token", token, "--json"])
    import json

    got = json.loads(sid.output)
    from fastapi.testclient import TestClient

    mine = TestClient(app).get(f"/api/v1/submissions/{got['submission_id']}", headers=bearer(app, INSTRUCTOR)).json()
    assert "evaluations" in next(p for p in mine["parts"] if p["part"] == "L")["feedback"]
