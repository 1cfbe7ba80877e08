"""Fixtures for the server tests: a small assignment (12.22, 12.14), apps with and without graders.

An app made with ``grade=False`` starts no grader process: every check is stored and answered
``202 queued``, which is all that auth, limits, CSRF and storage need. The graded app is one per
test session (its graders warm up once, ~10 s).
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("sqlalchemy")
pytest.importorskip("httpx")

from fastapi.testclient import TestClient

from lagrade.server.app import create_app
from lagrade.server.config import ServerConfig
from lagrade.server.tokens import INSTRUCTOR, issue

REPO = Path(__file__).resolve().parents[2]
GOLDEN = REPO / "tests" / "answers"
PROBLEMS = ("12.22", "12.14")
ASSIGNMENT = 'name = "hw-serve"\ntitle = "Serve test"\n[limits]\ncpu_seconds = 10\nwall_seconds = 20\n' + \
    "".join(f'[[problems]]\nid = "{pid}"\n' for pid in PROBLEMS)


#: golden answers (tests/answers) used here, by name: that folder grows (other suites add files to it)
GOLDEN_NAMES = {
    "12.22": ["correct_plain.toml", "correct_latex.toml", "correct_solved_accelerations.py", "wrong_S3_equals_S1.py",
              "wrong_sign_of_V.py", "wrong_case_upward.toml", "wrong_ignores_pulley_motion.py"],
    "12.14": ["correct_plain.toml", "correct_latex.toml", "correct_cartesian_and_solve.py", "wrong_missing_cross_term.py",
              "wrong_uncoupled_frequencies.toml", "wrong_V_upper_mass_only.py", "wrong_centrifugal_sign_exact.py"],
}


def golden(pid: str) -> list[Path]:
    return [GOLDEN / pid / name for name in GOLDEN_NAMES[pid]]


def make_config(tmp: Path, **kw) -> ServerConfig:
    path = tmp / "hw.toml"
    if not path.exists():
        path.write_text(ASSIGNMENT, encoding="utf-8")
    kw.setdefault("db", str(tmp / "serve.sqlite"))
    kw.setdefault("workers", 1)
    return ServerConfig(assignment=path, **kw)


def bearer(app, student: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {issue(app.state.server.secret, student)}"}


def expectations(path: Path) -> dict[str, str]:
    """The ``# expect: L=correct, eom=partial`` line of a golden answer file."""
    first = path.read_text(encoding="utf-8").splitlines()[0]
    m = re.match(r"#\s*expect:\s*(.*)", first)
    return dict(item.strip().split("=") for item in m.group(1).split(",")) if m else {}


def toml_answer(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


@pytest.fixture
def quiet_app(tmp_path):
    """An app without graders (checks are stored and stay queued)."""
    app = create_app(make_config(tmp_path, checks_per_minute=600, check_burst=100), grade=False)
    with TestClient(app) as client:
        yield app, client


@pytest.fixture(scope="session")
def graded(tmp_path_factory):
    """One app with warm graders for the whole session: (app, client, alice's headers)."""
    tmp = tmp_path_factory.mktemp("served")
    app = create_app(make_config(tmp, checks_per_minute=6000, check_burst=1000, workers=1))
    with TestClient(app) as client:
        yield app, client, bearer(app, "alice")


@pytest.fixture
def instructor():
    return INSTRUCTOR


@pytest.fixture(scope="session")
def live_url(graded):
    """The session's graded app, also on a real socket of 127.0.0.1 (its graders are the session's: lifespan off)."""
    import socket
    import threading
    import time

    uvicorn = pytest.importorskip("uvicorn")
    app = graded[0]
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, lifespan="off", log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    for _ in range(200):
        if server.started:
            break
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)
