"""The server on a real PostgreSQL database: runs when LAGRADE_TEST_POSTGRES_URL is set
(``postgresql+psycopg://user:password@127.0.0.1/db``, a database the test may empty); skipped otherwise."""

from __future__ import annotations

import os

import pytest
from fastapi.testclient import TestClient
from serverkit import GOLDEN, bearer, make_config, sign_in, toml_answer

from lagrade.uses.server.app import create_app

URL = os.environ.get("LAGRADE_TEST_POSTGRES_URL")
pytestmark = pytest.mark.skipif(not URL, reason="LAGRADE_TEST_POSTGRES_URL is not set")


@pytest.fixture
def pg_url():
    from sqlalchemy import create_engine

    from lagrade.uses.server.db import metadata

    engine = create_engine(URL)
    metadata.drop_all(engine)  # a clean database for each test
    engine.dispose()
    return URL


def test_stored_idempotent_and_kept_across_restarts(tmp_path, pg_url):
    config = make_config(tmp_path, db=pg_url)
    app = create_app(config, grade=False)
    answer = {"answer": toml_answer(GOLDEN / "12.22" / "correct_plain.toml")}
    with TestClient(app) as client:
        h = bearer(app, "alice")
        first = client.post("/api/v1/problems/12.22/check", headers=h, json=answer).json()["submission_id"]
        assert client.post("/api/v1/problems/12.22/check", headers=h, json=answer).json()["submission_id"] == first
        secret = app.state.server.secret
    app = create_app(config, grade=False)  # the same database: the same secret, the same queued attempt
    assert app.state.server.secret == secret
    assert app.state.server.db.queued() == [first]
    app.state.server.db.close()


@pytest.mark.slow
def test_graded_into_the_gradebook(tmp_path, pg_url):
    app = create_app(make_config(tmp_path, db=pg_url))
    with TestClient(app) as client:
        r = client.post("/api/v1/problems/12.22/check", headers=bearer(app, "alice"),
                        files={"file": ("answer.py", (GOLDEN / "12.22" / "wrong_S3_equals_S1.py").read_bytes())})
        assert r.status_code == 200, r.text
        verdicts = {p["part"]: p["verdict"] for p in r.json()["parts"]}
        assert verdicts["S_t"] == "partial" and verdicts["L"] == "correct"
        book = app.state.server.db.gradebook()
        alice = book.student("alice").problems["12.22"]
        assert alice.submitted and 0 < alice.points < alice.possible
        assert {p["part"]: p["verdict"] for p in alice.parts} == verdicts
        page = type(client)(app)
        from lagrade.uses.server.tokens import INSTRUCTOR

        sign_in(app, page, INSTRUCTOR)
        assert "alice" in page.get("/class/").text


def test_a_session_opens_and_sign_out_revokes_it(tmp_path, pg_url):
    """The server_sessions table on PostgreSQL: a browser signs in (a session, not the token, in its
    cookie), reads its page, signs out; the row is gone and a copy of the cookie signs nobody in."""
    import re

    from lagrade.uses.server.state import SESSION_COOKIE, SESSION_SECONDS
    from lagrade.uses.server.tokens import student_of

    app = create_app(make_config(tmp_path, db=pg_url), grade=False)
    db = app.state.server.db
    with TestClient(app) as client:
        csrf = sign_in(app, client, "alice")
        sid = client.cookies[SESSION_COOKIE]
        assert student_of(app.state.server.secret, sid) is None  # not a token
        assert db.session_student(sid, SESSION_SECONDS) == "alice"
        assert db.session_student(sid, 0) is None  # older than its age bound: no one
        page = client.get("/")
        assert page.status_code == 200 and "data-student>alice<" in page.text
        assert re.search(r'name="csrf" value="([^"]+)"', page.text).group(1) == csrf
        assert client.post("/logout", data={"csrf": csrf}, follow_redirects=False).status_code == 303
        assert db.session_student(sid, SESSION_SECONDS) is None
    with TestClient(app, cookies={SESSION_COOKIE: sid}) as copy:
        assert "data-student>" not in copy.get("/").text  # the sign-in form
        assert copy.get("/api/v1/problems/12.22").status_code == 401
    db.close()
