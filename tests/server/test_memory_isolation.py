"""Issue 43, item 1, through ``lagrade serve``'s graders: with the OS jail alone (the tripwires off,
as ``tests/security`` switches them off), one student's attempts that search their own memory never
find the file another student sent just before to the same grader."""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from serverkit import REPO, bearer, make_config

from lagrade.uses.server.app import create_app

sys.path.insert(0, str(REPO / "tests"))
import memory_scan  # noqa: E402

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the OS jail is Linux's")]


def test_no_attempt_finds_another_students_file_in_its_memory(tmp_path, monkeypatch):
    tripwires_off = REPO / "tests" / "security" / "tripwires_off"
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(tripwires_off), *[p for p in sys.path if p]]))
    app = create_app(make_config(tmp_path, checks_per_minute=6000, check_burst=1000, workers=1,
                                 student_in_flight=1000, student_grader_seconds_per_minute=1e6))
    honest = (REPO / "reference_solutions" / "12.22" / "answer.py").read_text()
    with TestClient(app) as client:
        alice, bob = bearer(app, "alice"), bearer(app, "bob")
        for round_ in range(3):
            text = memory_scan.marker()
            for who, source in ((alice, memory_scan.victim(text, honest)), (bob, memory_scan.scanner(text))):
                r = client.post("/api/v1/problems/12.22/check", headers=who,
                                files={"file": ("answer.py", source.encode())})
                assert r.status_code == 200 and r.json()["state"] == "graded", r.text
            said = [str(p) for p in r.json()["problems"] if "memory scan" in str(p)]
            assert said, r.json()  # the tripwires are off: the scan ran and said what it found
            found, control = (int(n) for n in re.findall(r"(\d+) (?:found|control)", said[0]))
            assert control >= 1, f"the control failed: the search does not reach the heap ({said[0]})"
            assert found == 0, f"round {round_}: bob's attempt found alice's file in its memory: {said[0]}"
