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
from lagrade.server.db import Database
from lagrade.server.tokens import INSTRUCTOR, student_of


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


def _start(tmp_path, port):
    with open(tmp_path / f"serve-{port}.log", "wb") as log:  # the child keeps its own descriptor
        proc = subprocess.Popen([sys.executable, "-m", "lagrade", "serve", "--assignment", str(tmp_path / "hw.toml"),
                                 "--db", str(tmp_path / "serve.sqlite"), "--port", str(port), "--workers", "1"],
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    for _ in range(300):
        try:
            if httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=1).status_code == 200:
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
    proc = _start(tmp_path, port)
    try:
        secret = Database(str(tmp_path / "serve.sqlite")).secret()
        from lagrade.server.tokens import issue

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
        assert again["submission_id"] == listed[0]["submission_id"] and again["state"] == "graded"
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
    assert out.exit_code == 1 and "is not a lagrade gradebook" in out.output
    assert len(out.output.strip().splitlines()) == 1 and notes.read_text() == "my notes\n"
    bad = tmp_path / "bad.toml"
    bad.write_text('[[problems]]\nid = "12.999"\n', encoding="utf-8")
    out = CliRunner().invoke(main, ["serve", "--assignment", str(bad), "--db", str(tmp_path / "x.sqlite")])
    assert out.exit_code == 2 and "12.999" in out.output
