"""Issue 43, item 6: /healthz said ok before the graders were warm (the first check on a loaded machine
then waited over a minute behind a green health check). It answers 503 with Retry-After until a grader
is warm, then 200; a server made without graders has none to wait for."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient
from serverkit import bearer, make_config

from lagrade.uses.server.app import create_app


@pytest.mark.slow
def test_healthz_is_ready_only_once_a_grader_is_warm(tmp_path):
    app = create_app(make_config(tmp_path, workers=1, spare_graders=0))
    with TestClient(app) as client:
        first = client.get("/healthz")  # the grader process has just been started: it is warming up
        assert first.status_code == 503 and first.headers["retry-after"] == "1", first.text
        assert first.json()["ok"] is False and first.json()["graders_ready"] == 0
        end = time.monotonic() + 300
        r = first
        while r.status_code == 503 and time.monotonic() < end:
            time.sleep(0.2)
            r = client.get("/healthz")
        assert r.status_code == 200 and r.json()["ok"] is True and r.json()["graders_ready"] == 1, r.text
        # warm, with no check ever sent: the grader said so while idle
        assert [g.ready for g in app.state.server.queue.graders] == [True]
        graded = client.post("/api/v1/problems/12.22/check", json={"answer": {"L": "m1*x_d^2/2"}},
                             headers=bearer(app, "ada"))
        assert graded.status_code == 200 and graded.json()["state"] == "graded", graded.text


def test_a_server_without_graders_is_ready(quiet_app):
    _, client = quiet_app
    r = client.get("/healthz")
    assert r.status_code == 200 and r.json() == {"ok": True, "graders_ready": 0, "queued": 0}
