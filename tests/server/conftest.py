"""Fixtures for the server tests: a small assignment (12.22, 12.14), apps with and without graders.

An app made with ``grade=False`` starts no grader process: every check is stored and answered
``202 queued``, which is all that auth, limits, CSRF and storage need. The graded app is one per
test session (its graders warm up once, ~10 s).
"""

from __future__ import annotations

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("sqlalchemy")
pytest.importorskip("httpx")

from fastapi.testclient import TestClient  # noqa: E402
from serverkit import bearer, make_config  # noqa: E402  (helpers live in serverkit: a unique name)

from lagrade.uses.server.app import create_app  # noqa: E402
from lagrade.uses.server.tokens import INSTRUCTOR  # noqa: E402


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
    app = create_app(make_config(tmp, checks_per_minute=6000, check_burst=1000, workers=1, student_in_flight=1000,
                                 student_grader_seconds_per_minute=1e6))
    with TestClient(app) as client:
        yield app, client, bearer(app, "alice")


@pytest.fixture
def instructor():
    return INSTRUCTOR


@pytest.fixture(scope="session")
def live_url(graded):
    """The session's graded app, also on a real socket of 127.0.0.1 (its graders are the session's: lifespan off)."""
    pytest.importorskip("uvicorn")
    from serverkit import on_a_socket

    with on_a_socket(graded[0]) as url:
        yield url
