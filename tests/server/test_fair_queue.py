"""A fair queue (issue 32, item 3): a queue per student served round robin, one student never holding
every grader, and what one student may have in flight or use of the graders' time bounded with a 429
that says when to come back."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient
from serverkit import REPO, bearer, graded, make_config

from lagrade.uses.server.app import create_app
from lagrade.uses.server.grading import GradingQueue

LOOP = b"while True:\n    pass\n"


@pytest.fixture
def quiet_app(tmp_path):
    """An app without graders that answers 202 at once (its checks stay queued)."""
    app = create_app(make_config(tmp_path, checks_per_minute=600, check_burst=100, wait_seconds=0.05), grade=False)
    with TestClient(app) as client:
        yield app, client


def _queue(app, workers: int = 2, **kw) -> GradingQueue:
    """The server's queue, not started (no grader): attempts are queued and picked, never graded."""
    server = app.state.server
    server.queue = GradingQueue(server.db, server.plan, workers, problems=server.problems, **kw)
    return server.queue


def test_one_students_many_attempts_do_not_go_before_anothers(quiet_app):
    app, client = quiet_app
    q = _queue(app, workers=2, in_flight=100)
    alice, bob = bearer(app, "alice"), bearer(app, "bob")
    mine = [client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP + b"#%d" % i)})
            .json()["submission_id"] for i in range(10)]
    theirs = client.post("/api/v1/problems/12.14/check", headers=bob, json={"answer": {"L": "m1"}}).json()["submission_id"]
    first = q._next()["server_id"]
    second = q._next()  # alice holds one grader of two: the other is bob's
    assert first == mine[0] and second is not None and second["server_id"] == theirs
    assert q._next() is None  # alice's next waits for her first: never both graders
    q._done({"server_id": first}, {"seconds": 1.0, "outcome": "graded", "parts": []})
    assert q._next()["server_id"] == mine[1]


def test_a_student_beyond_the_attempts_in_flight_gets_429_with_retry_after(quiet_app):
    app, client = quiet_app
    _queue(app, in_flight=3)
    alice, bob = bearer(app, "alice"), bearer(app, "bob")
    codes = [client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP + b"#%d" % i)})
             for i in range(4)]
    assert [r.status_code for r in codes] == [202, 202, 202, 429]
    assert int(codes[-1].headers["retry-after"]) >= 1 and "3 checks waiting" in codes[-1].json()["detail"]
    assert client.post("/api/v1/problems/12.14/check", headers=bob, json={"answer": {"L": "m1"}}).status_code == 202


def test_a_student_beyond_the_grader_time_a_minute_gets_429_with_retry_after(quiet_app):
    app, client = quiet_app
    q = _queue(app, seconds_per_minute=30)
    alice = bearer(app, "alice")
    q._used["alice"].append((time.monotonic() - 20, 31.0))  # 31 s of grading, 20 s ago
    r = client.post("/api/v1/problems/12.14/check", headers=alice, json={"answer": {"L": "m1"}})
    assert r.status_code == 429 and "31 s of grading time in the last minute" in r.json()["detail"]
    assert 35 <= int(r.headers["retry-after"]) <= 41  # when those 31 s leave the minute


@pytest.mark.slow
def test_a_right_answer_is_graded_within_5_s_behind_another_students_ten_loops(tmp_path):
    """The head-of-line probe of benchmarks/serve_load.py, on two graders: ten infinite loops from
    alice (each costs its 10 s of CPU), then bob's right answer."""
    config = make_config(tmp_path, workers=2, wait_seconds=0.2, checks_per_minute=600, check_burst=100,
                         student_in_flight=10, student_grader_seconds_per_minute=1000)
    app = create_app(config)
    right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes()
    with TestClient(app) as client:
        carol = bearer(app, "carol")  # one check first, graded once the graders are warm (bounded)
        graded(client, carol, client.post("/api/v1/problems/12.14/check", headers=carol,
                                           files={"file": ("answer.py", right + b"# warm")}).json()["submission_id"], 120)
        alice, bob = bearer(app, "alice"), bearer(app, "bob")
        loops = []
        for i in range(10):
            r = client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP + b"#%d" % i)})
            assert r.status_code == 202
            loops.append(r.json()["submission_id"])
        sid = client.post("/api/v1/problems/12.14/check", headers=bob,
                          files={"file": ("answer.py", right)}).json()["submission_id"]
        r = graded(client, bob, sid, 120)
        assert r.status_code == 200 and r.json()["score"] == r.json()["max_score"]
        # the order, not the seconds (a loaded machine stretches those): alice holds one grader at a time, so
        # at most her first loop can have ended before bob's answer; behind her queue, nine or ten would have
        done = [s for s in loops if client.get(f"/api/v1/submissions/{s}", headers=alice).status_code != 202]
        assert len(done) <= 1, f"bob's right answer waited behind {len(done)} of alice's loops"


@pytest.mark.slow
def test_a_spare_grader_takes_a_right_answer_while_two_students_loops_hold_the_others(tmp_path):
    """Different students' slow attempts (each its own student: the per-student cap does not help)
    hold both graders; once they have used ``cpu_budget`` CPU seconds, a spare grader takes the next one."""
    config = make_config(tmp_path, workers=2, spare_graders=1, cpu_budget=1.0, wait_seconds=0.2)
    app = create_app(config)
    right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes()
    with TestClient(app) as client:
        carol = bearer(app, "carol")
        for i in range(3):  # warm: each grader has graded once (bounded)
            graded(client, carol, client.post("/api/v1/problems/12.14/check", headers=carol, files={
                "file": ("answer.py", right + b"# warm %d" % i)}).json()["submission_id"], 120)
        loops = {}
        for who in ("alice", "dave"):
            r = client.post("/api/v1/problems/12.14/check", headers=bearer(app, who), files={"file": ("answer.py", LOOP)})
            assert r.status_code == 202
            loops[who] = r.json()["submission_id"]
        time.sleep(0.5)
        bob = bearer(app, "bob")
        sid = client.post("/api/v1/problems/12.14/check", headers=bob,
                          files={"file": ("answer.py", right)}).json()["submission_id"]
        r = graded(client, bob, sid, 120)
        assert r.status_code == 200 and r.json()["score"] == r.json()["max_score"]
        # the order, not the seconds (a loaded machine stretches those): both loops (10 s of CPU each) still
        # hold their graders, so a spare one graded bob's answer; waiting for a grader, one loop would have ended
        done = [who for who, s in loops.items()
                if client.get(f"/api/v1/submissions/{s}", headers=bearer(app, who)).status_code != 202]
        assert not done, f"bob's right answer waited for {done}'s loop"


def test_checks_sent_at_once_are_counted_before_they_are_stored(quiet_app):
    """Ten checks at once all passed the in-flight cap: none was queued yet when the next was admitted."""
    import concurrent.futures

    app, client = quiet_app
    _queue(app, in_flight=3)
    alice = bearer(app, "alice")

    def send(i):
        return client.post("/api/v1/problems/12.14/check", headers=alice,
                           files={"file": ("answer.py", LOOP + b"#%d" % i)}).status_code

    with concurrent.futures.ThreadPoolExecutor(10) as pool:
        codes = sorted(pool.map(send, range(10)))
    assert codes == [202] * 3 + [429] * 7
    q = app.state.server.queue
    assert sum(q._admitted.values()) == 0 and len(q._owner) == 3


def test_the_same_program_from_another_student_gets_its_result_without_a_grader(quiet_app):
    """A class hands in the same program again and again (here with each student's name in a
    comment): once graded by any grader, the queue answers the next copy itself, as that student's
    own attempt; another program, or an outcome a bound decided, goes to a grader."""
    app, client = quiet_app
    q = _queue(app, workers=2, in_flight=100)
    db = app.state.server.db
    right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes()
    ids = {who: client.post("/api/v1/problems/12.14/check", headers=bearer(app, who),
                            files={"file": ("answer.py", right + b"\n# by %s\n" % who.encode())}).json()["submission_id"]
           for who in ("alice", "bob", "carol")}
    other = client.post("/api/v1/problems/12.14/check", headers=bearer(app, "dave"),
                        files={"file": ("answer.py", right + b"\nx = 1\n")}).json()["submission_id"]
    first = q._next()
    assert first["server_id"] == ids["alice"]
    result = {"student": "alice", "problem": "12.14", "outcome": "graded", "status": "ok", "reason": "",
              "score": 2.0, "max_score": 2.0, "problems": [], "seconds": 0.5, "jail": "none",
              "parts": [{"part": "L", "verdict": "correct", "score": 1.0, "max_score": 1.0, "method": "exact",
                         "feedback": "right", "read_back": ["L", "L"]}]}
    q._done(first, dict(result))
    nxt = q._next()  # bob's and carol's copies are found kept: dave's other program is next
    assert nxt is not None and nxt["server_id"] == other and q._next() is None
    assert not db.attempt(ids["bob"]).graded  # written once the graders have their jobs
    q._answer_kept()
    for who in ("bob", "carol"):
        att = db.attempt(ids[who])
        assert att.graded and att.student == who and att.result["score"] == 2.0
    assert q.results.hits == 2
    q._done(nxt, {**result, "student": "dave", "status": "timeout", "outcome": "failed", "score": 0.0})
    again = client.post("/api/v1/problems/12.14/check", headers=bearer(app, "erin"),
                        files={"file": ("answer.py", right + b"\nx = 1\n# erin\n")}).json()["submission_id"]
    assert q._next()["server_id"] == again  # a timeout is not the program's own: graded again


def test_the_same_file_again_is_given_back_beyond_the_grader_time_a_minute(quiet_app):
    # a resubmission is the attempt stored before and costs no grading: no 429 for it (a student
    # whose file took long to grade asks for its grade again); a new file is bounded as before
    app, client = quiet_app
    q = _queue(app, seconds_per_minute=30)
    alice = bearer(app, "alice")
    first = client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP)})
    assert first.status_code == 202
    q._used["alice"].append((time.monotonic() - 20, 31.0))
    again = client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP)})
    assert again.status_code == 202 and again.json()["submission_id"] == first.json()["submission_id"]
    assert q._admitted["alice"] == 0  # nothing left counted as in flight
    other = client.post("/api/v1/problems/12.14/check", headers=alice, files={"file": ("answer.py", LOOP + b"x = 1\n")})
    assert other.status_code == 429
