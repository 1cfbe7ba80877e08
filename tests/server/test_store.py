"""Attempts are stored before they are graded, once per content, in the gradebook's own schema;
one left ungraded by a killed server is graded when it starts again."""

from __future__ import annotations

import sqlite3
import tomllib

import pytest
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st
from serverkit import GOLDEN, bearer, make_config

from lagrade.uses.bulk.store import Store
from lagrade.uses.server.answers import to_toml
from lagrade.uses.server.app import create_app
from lagrade.uses.server.db import GRADEBOOK_TABLES, Database


def _columns(con, table):
    """(name, type, not null, part of the key) of each column; a key column counts as not null."""
    return [(r[1], r[2].upper(), bool(r[3]) or r[5] > 0, r[5] > 0) for r in con.execute(f"PRAGMA table_info({table})")]


def test_gradebook_tables_are_the_bulk_schema(tmp_path):
    """The SQLAlchemy tables (used as such on PostgreSQL) have the columns of `lagrade grade`'s gradebook."""
    Store(tmp_path / "bulk.sqlite").close()
    con = sqlite3.connect(tmp_path / "bulk.sqlite")
    bulk = {r[0] for r in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")} - {"sqlite_sequence"}
    assert bulk == {t.name for t in GRADEBOOK_TABLES}
    from sqlalchemy import create_engine

    from lagrade.uses.server.db import metadata

    engine = create_engine(f"sqlite:///{tmp_path / 'sa.sqlite'}")
    metadata.create_all(engine, tables=list(GRADEBOOK_TABLES))
    engine.dispose()
    mine = sqlite3.connect(tmp_path / "sa.sqlite")
    for t in bulk:
        ours = [(n, nn, pk) for n, _, nn, pk in _columns(mine, t)]
        theirs = [(n, nn, pk) for n, _, nn, pk in _columns(con, t)]
        assert ours == theirs, t


answer_text = st.text(st.characters(blacklist_categories=("Cs",)), max_size=30)
answer_values = st.one_of(answer_text, st.booleans(), st.integers(-10**6, 10**6), st.lists(answer_text, max_size=3),
                          st.dictionaries(answer_text, st.one_of(answer_text, st.booleans()), max_size=3))


@settings(max_examples=200, deadline=None)
@given(st.dictionaries(answer_text, answer_values, min_size=1, max_size=4))
def test_json_answers_become_the_same_toml(answer):
    text = to_toml(answer)
    assert tomllib.loads(text.decode()) == answer
    assert to_toml(dict(reversed(list(answer.items())))) == text  # canonical: the same content, the same bytes


def test_stored_before_graded_and_idempotent(quiet_app):
    app, client = quiet_app
    h = bearer(app, "alice")
    answer = tomllib.loads((GOLDEN / "12.22" / "correct_plain.toml").read_text())
    first = client.post("/api/v1/problems/12.22/check", headers=h, json={"answer": answer})
    assert first.status_code == 202
    sid = first.json()["submission_id"]
    again = client.post("/api/v1/problems/12.22/check", headers=h, json={"answer": dict(reversed(answer.items()))})
    assert again.json()["submission_id"] == sid
    other = client.post("/api/v1/problems/12.22/check", headers=bearer(app, "bob"), json={"answer": answer})
    assert other.json()["submission_id"] != sid  # another student's attempt is their own
    att = app.state.server.db.attempt(sid)
    assert att.state == "queued" and att.suffix == ".toml" and tomllib.loads(att.data.decode()) == answer
    assert client.get(f"/api/v1/submissions/{sid}", headers=h).status_code == 202
    assert client.get(f"/api/v1/submissions/{sid}", headers=bearer(app, "bob")).status_code == 404
    listed = client.get("/api/v1/problems/12.22/submissions", headers=h).json()
    assert [a["submission_id"] for a in listed] == [sid] and listed[0]["state"] == "queued"


@pytest.mark.slow
def test_an_ungraded_attempt_is_graded_on_restart(tmp_path):
    """A server stopped before grading (as after kill -9: the attempt is committed, no grade) grades
    it when it starts again, and it lands in the gradebook `lagrade export` reads."""
    config = make_config(tmp_path)
    app = create_app(config, grade=False)
    with TestClient(app) as client:
        h = bearer(app, "carol")
        data = (GOLDEN / "12.22" / "wrong_sign_of_V.py").read_bytes()
        sid = client.post("/api/v1/problems/12.22/check", headers=h, files={"file": ("answer.py", data)}).json()[
            "submission_id"]
    db = Database(config.db)
    assert db.queued() == [sid]
    db.close()
    app = create_app(config)
    with TestClient(app) as client:
        r = client.get(f"/api/v1/submissions/{sid}", headers=bearer(app, "carol"))
        for _ in range(120):
            if r.status_code == 200:
                break
            import time

            time.sleep(1)
            r = client.get(f"/api/v1/submissions/{sid}", headers=bearer(app, "carol"))
        assert r.status_code == 200, r.text
        verdicts = {p["part"]: p["verdict"] for p in r.json()["parts"]}
        assert verdicts["L"] == "incorrect" and verdicts["a"] == "correct"
    con = sqlite3.connect(config.db)
    assert con.execute("SELECT state FROM server_submissions").fetchall() == [("graded",)]
    assert con.execute("SELECT student, problem, path FROM submissions").fetchall() == [("carol", "12.22", "carol/12.22.py")]
    assert con.execute("SELECT count(*) FROM grade_log").fetchone() == (1,)
