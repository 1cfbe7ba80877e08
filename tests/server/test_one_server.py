"""One server per database: the queue and the rate limits live in the server's process, so a second
server on the same database is refused in one line, whether it is another process or this one; a
server killed with kill -9 leaves no claim behind. SQLite here; PostgreSQL when
LAGRADE_TEST_POSTGRES_URL is set."""

from __future__ import annotations

import os
import signal
import subprocess
import sys

import pytest
from fastapi.testclient import TestClient
from serverkit import make_config

from lagrade.uses.server.app import create_app
from lagrade.uses.server.db import Database, DatabaseBusy

HOLD = "import sys, time; from lagrade.uses.server.db import Database; Database(sys.argv[1]).claim(); print('held', flush=True); time.sleep(600)"


@pytest.fixture
def held(tmp_path):
    """Another process holding ``serve.sqlite`` as a server does; killed with SIGKILL at the end."""
    db = tmp_path / "serve.sqlite"
    proc = subprocess.Popen([sys.executable, "-c", HOLD, str(db)], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "held"
    yield db, proc
    if proc.poll() is None:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()


def test_a_second_server_in_the_same_process_is_refused(tmp_path):
    config = make_config(tmp_path)
    app = create_app(config, grade=False)
    with TestClient(app):
        with pytest.raises(DatabaseBusy, match="served already by another lagrade serve") as exc:
            create_app(config, grade=False)
        assert len(str(exc.value).splitlines()) == 1
        assert app.state.server.db._claim is not None  # the refused one did not take the first's claim away
    again = create_app(config, grade=False)  # the first stopped: its claim is gone
    again.state.server.stop()


def test_another_process_holds_the_database_until_killed(tmp_path, held):
    db, proc = held
    with pytest.raises(DatabaseBusy, match=rf"pid {proc.pid} on "):
        Database(str(db)).claim()
    other = Database(str(tmp_path / "other.sqlite"))  # another database is free
    other.claim()
    other.close()
    os.kill(proc.pid, signal.SIGKILL)  # kill -9: the kernel drops the lock
    proc.wait()
    mine = Database(str(db))
    mine.claim()
    mine.close()


def test_lagrade_serve_says_it_in_one_line(tmp_path, held):
    db, proc = held
    config = make_config(tmp_path, db=str(db))
    # a process of its own, bounded: a server that did start would serve until the timeout fails the test
    out = subprocess.run([sys.executable, "-m", "lagrade", "serve", "--assignment", str(config.assignment), "--db",
                          str(db), "--port", "0"], capture_output=True, text=True, timeout=120)
    said = (out.stdout + out.stderr).strip()
    assert out.returncode == 1, said
    assert "served already by another lagrade serve" in said and f"pid {proc.pid}" in said
    assert len(said.splitlines()) == 1


@pytest.mark.skipif(not os.environ.get("LAGRADE_TEST_POSTGRES_URL"), reason="LAGRADE_TEST_POSTGRES_URL is not set")
def test_postgresql_one_server_per_database():
    url = os.environ["LAGRADE_TEST_POSTGRES_URL"]
    first, second = Database(url), Database(url)
    try:
        first.claim()
        with pytest.raises(DatabaseBusy, match="served already"):
            second.claim()
        first.close()  # its session ends, and the lock with it
        second.claim()
    finally:
        first.close()
        second.close()
