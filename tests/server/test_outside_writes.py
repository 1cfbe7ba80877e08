"""Issue 43, item 2: another process on the live SQLite file (the `sqlite3` shell, `lagrade override` or
`lagrade export`, which docs/server.md invites) once the instructor had opened the class page deleted
the server's write-ahead log under it: what the server wrote afterwards was seen by no other reader, and a
`kill -9` lost those graded attempts (their ids were given again). The class page had opened and closed a
file of its own on the database inside the server process, which drops every POSIX lock the process
holds on it: the outside program's last close then took the server's log for its own.

A real `lagrade serve` on 127.0.0.1: attempts graded, the class page opened, an outside write, more
attempts graded, then kill -9; every attempt answered is in the file, graded, under the id it was given."""

from __future__ import annotations

import subprocess
import sys

import httpx
import pytest
from serverkit import GOLDEN, bearer, make_config, sign_in, start_serve, stop_serve

from lagrade.uses.server.tokens import INSTRUCTOR

ROSTER = "student\nada\n"
OUTSIDE_WRITE = ("import sqlite3, sys\n"
                 "con = sqlite3.connect(sys.argv[1])\n"
                 "con.execute(\"INSERT OR REPLACE INTO meta(key, value) VALUES ('note', 'from outside')\")\n"
                 "con.commit()\n"
                 "con.close()\n")
READ = ("import sqlite3, sys, json\n"
        "con = sqlite3.connect(sys.argv[1])\n"
        "print(json.dumps(con.execute('SELECT id, state FROM server_submissions ORDER BY id').fetchall()))\n"
        "con.close()\n")


def _tokens(tmp_path, db) -> dict[str, str]:
    roster = tmp_path / "roster.csv"
    roster.write_text(ROSTER, encoding="utf-8")
    out = subprocess.run([sys.executable, "-m", "lagrade", "tokens", str(roster), "--db", str(db)],
                         capture_output=True, text=True, check=True, timeout=120).stdout
    return dict(line.split(",")[:2] for line in out.splitlines()[1:])


def _check(base: str, token: str, n: int) -> int:
    """The n-th distinct attempt of ada at 12.22 (a golden answer with a comment of its own), graded."""
    data = (GOLDEN / "12.22" / "correct_plain.toml").read_bytes() + f"\n# attempt {n}\n".encode()
    r = httpx.post(f"{base}/api/v1/problems/12.22/check", headers={"Authorization": f"Bearer {token}"},
                   files={"file": ("answer.toml", data)}, timeout=180)
    assert r.status_code == 200 and r.json()["state"] == "graded", r.text
    return r.json()["submission_id"]


def _open_class_page(base: str, token: str) -> None:
    """The instructor signs in as a browser does (the link's page, then its button) and opens /class/."""
    import re

    with httpx.Client(base_url=base, timeout=60) as browser:
        page = browser.get("/login", params={"token": token})
        form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
        r = browser.post("/login", data={"token": token, "login_csrf": form})
        assert r.status_code in (200, 303), r.text
        page = browser.get("/class/")
        assert page.status_code == 200 and "ada" in page.text, page.text[:500]


def _rows(db) -> list[list]:
    """The attempts as another process reads the file: [[id, state], ...]."""
    import json

    out = subprocess.run([sys.executable, "-c", READ, str(db)], capture_output=True, text=True, check=True, timeout=60)
    return json.loads(out.stdout)


def test_the_class_page_keeps_the_servers_locks(tmp_path):
    """The same in one process (no grader: attempts stay queued): after the class page and an outside
    write, what the server stores is seen by another reader; the write-ahead log is still there."""
    from fastapi.testclient import TestClient

    from lagrade.uses.server.app import create_app

    app = create_app(make_config(tmp_path), grade=False)
    db = tmp_path / "serve.sqlite"
    with TestClient(app) as client, TestClient(app) as browser:
        ada = bearer(app, "ada")
        answer = {"answer": {"L": "m1*x_d^2/2"}}
        first = client.post("/api/v1/problems/12.22/check", json=answer, headers=ada).json()["submission_id"]
        sign_in(app, browser, INSTRUCTOR)
        assert browser.get("/class/").status_code == 200
        subprocess.run([sys.executable, "-c", OUTSIDE_WRITE, str(db)], check=True, timeout=60)
        assert db.with_name(db.name + "-wal").exists(), "the server's write-ahead log was deleted under it"
        second = client.post("/api/v1/problems/12.22/check", json={"answer": {"L": "m1*x_d^2"}},
                             headers=ada).json()["submission_id"]
        assert _rows(db) == [[first, "queued"], [second, "queued"]]


def test_a_second_server_refused_in_the_same_process_keeps_the_first_ones_locks(tmp_path):
    from fastapi.testclient import TestClient

    from lagrade.uses.server.app import create_app
    from lagrade.uses.server.db import DatabaseBusy

    config = make_config(tmp_path)
    app = create_app(config, grade=False)
    db = tmp_path / "serve.sqlite"
    with TestClient(app) as client:
        ada = bearer(app, "ada")
        first = client.post("/api/v1/problems/12.22/check", json={"answer": {"L": "m1"}}, headers=ada).json()
        with pytest.raises(DatabaseBusy):
            create_app(config, grade=False)
        subprocess.run([sys.executable, "-c", OUTSIDE_WRITE, str(db)], check=True, timeout=60)
        second = client.post("/api/v1/problems/12.22/check", json={"answer": {"L": "m2"}}, headers=ada).json()
        assert _rows(db) == [[first["submission_id"], "queued"], [second["submission_id"], "queued"]]


#: what an instructor runs on the live file (docs/server.md invites the lagrade commands)
OUTSIDE = {
    "sqlite3": lambda db: [sys.executable, "-c", OUTSIDE_WRITE, str(db)],
    "override": lambda db: [sys.executable, "-m", "lagrade", "override", str(db), "ada", "12.22", "L", "1",
                            "--reason", "checked by hand"],
    "export": lambda db: [sys.executable, "-m", "lagrade", "export", str(db), "--format", "csv"],
}


@pytest.mark.slow
@pytest.mark.parametrize("outside", sorted(OUTSIDE))
def test_an_outside_write_after_the_class_page_loses_no_graded_attempt(tmp_path, outside):
    db = tmp_path / "serve.sqlite"
    tokens = _tokens(tmp_path, db)
    proc, base, log = start_serve(tmp_path, db=db)
    try:
        given = [_check(base, tokens["ada"], n) for n in range(3)]
        _open_class_page(base, tokens[INSTRUCTOR])
        done = subprocess.run(OUTSIDE[outside](db), capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stdout + done.stderr
        given += [_check(base, tokens["ada"], n) for n in range(3, 6)]
        seen = _rows(db)  # another reader, while the server runs
    finally:
        stop_serve(proc, kill=True)  # kill -9: nothing is closed, nothing checkpointed
    after = _rows(db)
    assert len(set(given)) == 6, given
    graded = [[i, "graded"] for i in given]
    assert (seen, after) == (graded, graded), f"ids answered {given}; seen while serving {seen}; after kill -9 {after}"
