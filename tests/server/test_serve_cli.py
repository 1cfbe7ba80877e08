"""``lagrade tokens`` and ``lagrade serve`` as commands; ``kill -9`` of a server in the middle of a
grade loses nothing: the stored attempt is graded when the server starts again."""

from __future__ import annotations

import csv
import io
import os
import signal
import socket
import subprocess
import sys
import time

import httpx
import pytest
from click.testing import CliRunner
from serverkit import ASSIGNMENT

from lagrade.cli import main
from lagrade.uses.server.db import Database
from lagrade.uses.server.tokens import INSTRUCTOR, student_of


def test_tokens_for_a_roster(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("name,student\nAda,ada\nBob,bob\n,\n", encoding="utf-8")
    db = tmp_path / "serve.sqlite"
    out = CliRunner().invoke(main, ["tokens", str(roster), "--db", str(db), "--url", "http://127.0.0.1:8000"])
    assert out.exit_code == 0, out.output
    rows = list(csv.DictReader(io.StringIO(out.output)))
    assert [r["student"] for r in rows] == ["ada", "bob", INSTRUCTOR]
    secret = Database(str(db)).secret()
    assert all(student_of(secret, r["token"]) == r["student"] for r in rows)
    assert rows[0]["link"] == f"http://127.0.0.1:8000/login?token={rows[0]['token']}"
    again = CliRunner().invoke(main, ["tokens", str(roster), "--db", str(db)])
    assert [r["token"] for r in csv.DictReader(io.StringIO(again.output))] == [r["token"] for r in rows]  # stable
    empty = tmp_path / "empty.csv"
    empty.write_text("student\n", encoding="utf-8")
    bad = CliRunner().invoke(main, ["tokens", str(empty), "--db", str(db)])
    assert bad.exit_code == 2 and "no student ids" in bad.output


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(tmp_path, port, warm: bool = True):
    """``lagrade serve`` on ``port``, once /healthz says a grader is warm (``warm``), or once it answers at all."""
    with open(tmp_path / f"serve-{port}.log", "wb") as log:  # the child keeps its own descriptor
        proc = subprocess.Popen([sys.executable, "-m", "lagrade", "serve", "--assignment", str(tmp_path / "hw.toml"),
                                 "--db", str(tmp_path / "serve.sqlite"), "--port", str(port), "--workers", "1"],
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    end = time.monotonic() + 300  # /healthz is 200 once a grader is warm: over a minute on a loaded machine
    while time.monotonic() < end:
        try:
            if httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=1).status_code in ((200,) if warm else (200, 503)):
                return proc
        except httpx.HTTPError:
            pass
        if proc.poll() is not None:
            raise AssertionError((tmp_path / f"serve-{port}.log").read_text())
        time.sleep(0.1)
    raise AssertionError("the server did not start")


@pytest.mark.slow
def test_kill_9_loses_no_submission(tmp_path):
    (tmp_path / "hw.toml").write_text(ASSIGNMENT, encoding="utf-8")
    port = _free_port()
    proc = _start(tmp_path, port, warm=False)  # killed before any grader need be warm: the attempt is stored
    try:
        secret = Database(str(tmp_path / "serve.sqlite")).secret()
        from lagrade.uses.server.tokens import issue

        h = {"Authorization": f"Bearer {issue(secret, 'ivan')}"}
        slow = b"x = 0\nwhile True:\n    x += 1\n"  # runs until its CPU limit: long enough to kill
        with pytest.raises(httpx.ReadTimeout):
            httpx.post(f"http://127.0.0.1:{port}/api/v1/problems/12.22/check", headers=h,
                       files={"file": ("answer.py", slow)}, timeout=3)
        listed = httpx.get(f"http://127.0.0.1:{port}/api/v1/problems/12.22/submissions", headers=h).json()
        assert [a["state"] for a in listed] == ["queued"]
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    port = _free_port()
    proc = _start(tmp_path, port)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            listed = httpx.get(f"http://127.0.0.1:{port}/api/v1/problems/12.22/submissions", headers=h).json()
            if listed[0]["state"] == "graded":
                break
            time.sleep(1)
        assert len(listed) == 1 and listed[0]["state"] == "graded"
        r = httpx.get(f"http://127.0.0.1:{port}/api/v1/submissions/{listed[0]['submission_id']}", headers=h).json()
        assert r["score"] == 0 and r["status"] == "timeout", r
        # and the same file again is the same attempt, already graded
        again = httpx.post(f"http://127.0.0.1:{port}/api/v1/problems/12.22/check", headers=h,
                           files={"file": ("answer.py", slow)}, timeout=30).json()
        assert again.get("submission_id") == listed[0]["submission_id"] and again["state"] == "graded", again
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    out = CliRunner().invoke(main, ["export", str(tmp_path / "serve.sqlite"), "--format", "csv"])
    assert out.exit_code == 0 and "ivan" in out.output


def test_serve_refuses_a_database_that_is_not_a_gradebook(tmp_path):
    (tmp_path / "hw.toml").write_text(ASSIGNMENT, encoding="utf-8")
    notes = tmp_path / "notes.sqlite"
    notes.write_text("my notes\n", encoding="utf-8")
    out = CliRunner().invoke(main, ["serve", "--assignment", str(tmp_path / "hw.toml"), "--db", str(notes)])
    assert out.exit_code == 1 and "is not a lagrade serve database (not an SQLite file)" in out.output
    assert len(out.output.strip().splitlines()) == 1 and notes.read_text() == "my notes\n"
    bad = tmp_path / "bad.toml"
    bad.write_text('[[problems]]\nid = "12.999"\n', encoding="utf-8")
    out = CliRunner().invoke(main, ["serve", "--assignment", str(bad), "--db", str(tmp_path / "x.sqlite")])
    assert out.exit_code == 2 and "12.999" in out.output


def _serve(tmp_path, db: str, monkeypatch):
    """``lagrade serve`` up to where it would serve (uvicorn.run does nothing here)."""
    import uvicorn

    monkeypatch.setattr(uvicorn, "run", lambda *a, **kw: None)
    (tmp_path / "hw.toml").write_text(ASSIGNMENT, encoding="utf-8")
    return CliRunner().invoke(main, ["serve", "--assignment", str(tmp_path / "hw.toml"), "--db", db,
                                     "--unsafe-trusted-files", "--port", "1"])


def test_an_empty_or_foreign_database_file_is_refused_in_one_line(tmp_path, monkeypatch):
    """Issue 32: a 0-byte file was made into a new course with a new signing secret (every token
    issued stopped working). An existing file that is not a server's database is refused, untouched."""
    import sqlite3

    from lagrade.uses.bulk.store import Store

    empty = tmp_path / "empty.sqlite"
    empty.write_bytes(b"")
    other = tmp_path / "other.sqlite"
    with sqlite3.connect(other) as con:
        con.execute("CREATE TABLE notes (x)")
    gradebook = tmp_path / "hw.sqlite"
    Store(gradebook).close()
    text = tmp_path / "notes.txt"
    text.write_text("not a database\n", encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student\nada\n", encoding="utf-8")
    for path, why in [(empty, "is empty (0 bytes)"), (other, "an SQLite database of something else"),
                      (gradebook, "a gradebook of lagrade grade"), (text, "not an SQLite file")]:
        before = path.read_bytes()
        for out in (_serve(tmp_path, str(path), monkeypatch), CliRunner().invoke(main, ["tokens", str(roster), "--db", str(path)])):
            assert out.exit_code == 1, out.output
            lines = out.output.strip().splitlines()
            assert len(lines) == 1 and why in lines[0] and "not a lagrade serve database" in lines[0], out.output
        assert path.read_bytes() == before
    assert CliRunner().invoke(main, ["tokens", str(roster), "--db", str(tmp_path / "new.sqlite")]).exit_code == 0


def test_the_database_password_is_never_printed(tmp_path, monkeypatch):
    from lagrade.cli.serve import banner

    url = "postgresql+psycopg://lg:s3cret-pw@127.0.0.1:1/course"
    out = _serve(tmp_path, url, monkeypatch)  # nothing listens on port 1: the error names the database
    assert out.exit_code == 1 and "s3cret-pw" not in out.output and "lg:***@127.0.0.1:1/course" in out.output
    roster = tmp_path / "roster.csv"
    roster.write_text("student\nada\n", encoding="utf-8")
    out = CliRunner().invoke(main, ["tokens", str(roster), "--db", url])
    assert out.exit_code == 1 and "s3cret-pw" not in out.output and "***" in out.output
    line = banner(url, 3, False)
    assert "s3cret-pw" not in line and "database postgresql+psycopg://lg:***@127.0.0.1:1/course" in line
