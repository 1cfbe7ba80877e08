"""Gradings over their CPU budget run at the lowest CPU weight (issue 32: the quick answers get the
CPU first), with the same verdicts; a grader lowered itself is replaced; honest answers never are."""

from __future__ import annotations

import os
import sqlite3
import time
from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from serverkit import REPO, bearer, golden, graded, make_config

from lagrade.uses.bulk.worker import LOWERED_NICE, _proc_table, _tree
from lagrade.uses.server.app import create_app

LOOP = b"while True:\n    pass\n"
#: an answer.toml whose grading costs the grader itself more than a second of CPU (a 400-term sum,
#: read and compared in the grader, not in the answer's child)
SUM_TEXT = ('L = "' + " + ".join(f"cos({k}*theta1)*m1*g*l1/{k}" for k in range(1, 401)) + '"\n').encode()


def nice(pid: int) -> int:
    """The nice value of a process, as /proc/<pid>/stat says (field 19)."""
    return int(Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[16])


def _autogroups() -> bool:
    """Autogroups on, and readable as ``/autogroup-N nice M`` (some sandboxed kernels, gVisor's among
    them, switch them on and show an empty ``/proc/<pid>/autogroup``: nothing to check there)."""
    try:
        on = Path("/proc/sys/kernel/sched_autogroup_enabled").read_text().strip() == "1"
        return on and Path("/proc/self/autogroup").read_text().startswith("/autogroup-")
    except OSError:
        return False


def _autogroup(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/autogroup").read_text().strip()
    except OSError:  # gone meanwhile
        return f"nice {LOWERED_NICE}"


def _grading(queue, sid: int, seconds: float):
    """The grader grading attempt ``sid``, once it has been lowered (None if it is not within ``seconds``)."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        for g in list(queue.graders):
            if g.job is not None and g.job.get("server_id") == sid and (g.lowered or g.retire):
                return g
        time.sleep(0.05)
    return None


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_a_loop_over_the_budget_runs_at_nice_19_and_keeps_its_verdict(tmp_path):
    """The answer's child of an infinite loop is lowered (the grader is not: its own work is small),
    and the verdict is its CPU bound's, as at normal priority."""
    (tmp_path / "hw.toml").write_text('name = "hw"\n[limits]\ncpu_seconds = 3\nwall_seconds = 6\n[[problems]]\nid = "12.14"\n',
                          encoding="utf-8")
    app = create_app(make_config(tmp_path, cpu_budget=0.5, wait_seconds=0.2))
    with TestClient(app) as client:
        queue = app.state.server.queue
        alice = bearer(app, "alice")
        sid = client.post("/api/v1/problems/12.14/check", headers=alice,
                          files={"file": ("answer.py", LOOP)}).json()["submission_id"]
        g = _grading(queue, sid, 60)
        assert g is not None, "the loop was never lowered"
        table = _proc_table()
        children = [p for p in _tree(table, g.pid) if p not in g.own_pids]
        assert children, "no answer child under the grader"
        time.sleep(0.3)  # one more round of watch: a child forked meanwhile is lowered too
        assert all(nice(p) == LOWERED_NICE for p in children if Path(f"/proc/{p}").exists())
        if _autogroups():  # the child's own session weighs as little (the grader's, the server's, is untouched)
            assert all(f"nice {LOWERED_NICE}" in _autogroup(p) for p in children if Path(f"/proc/{p}").exists())
            assert _autogroup(g.pid) == _autogroup(os.getpid()) and _autogroup(g.pid).endswith("nice 0")
        assert nice(g.pid) == 0 and not g.retire
        r = graded(client, alice, sid, 120)
        assert r.status_code == 200
        body = r.json()
        # its CPU bound, or (on a machine whose CPU others keep busy, where nice 19 gets next to
        # nothing) the stretched wall-clock backstop: a timeout either way, as at normal priority
        assert body["status"] == "timeout" and body["score"] == 0
        assert "ran longer than 3 s of CPU time" in " ".join(body["problems"]) or \
            "ran longer than 18 s" in " ".join(body["problems"])
        assert sid in queue.lowered


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_a_grader_over_the_budget_runs_at_nice_19_and_is_replaced_after(tmp_path):
    """A grading whose cost is the grader's own (a long sum read and compared there): the grader and
    its zygote run at nice 19, and once the grade is written that process is gone and a grader at
    normal priority grades the next attempt."""
    app = create_app(make_config(tmp_path, grader_budget=0.3, wait_seconds=0.2))
    with TestClient(app) as client:
        queue = app.state.server.queue
        alice = bearer(app, "alice")
        sid = client.post("/api/v1/problems/12.14/check", headers=alice,
                          files={"file": ("answer.toml", SUM_TEXT)}).json()["submission_id"]
        g = _grading(queue, sid, 60)
        assert g is not None, "the long sum was never lowered"
        deadline = time.monotonic() + 30
        while not g.retire and g.job is not None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert g.retire, "the grader's own work was not counted"
        lowered = [p for p in g.own_pids if Path(f"/proc/{p}").exists()]
        assert g.pid in lowered and len(lowered) >= 2  # the grader and its zygote
        assert all(nice(p) == LOWERED_NICE for p in lowered)
        r = graded(client, alice, sid, 150)
        assert r.status_code == 200 and r.json()["state"] == "graded"
        deadline = time.monotonic() + 10
        while any(h is g for h in queue.graders) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not any(h is g for h in queue.graders), "the lowered grader was not retired"
        assert g.proc.poll() is not None
        right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes()
        sid2 = client.post("/api/v1/problems/12.14/check", headers=alice,
                           files={"file": ("answer.py", right)}).json()["submission_id"]
        r = graded(client, alice, sid2, 120)
        assert r.status_code == 200 and r.json()["score"] == r.json()["max_score"]
        assert [nice(h.pid) for h in queue.graders] == [0] * len(queue.graders)
        assert sid2 not in queue.lowered


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_honest_answers_are_never_lowered(tmp_path):
    """The golden answers and the reference solutions of both problems, graded at the server's
    default budget: none is lowered, and every grader stays at normal priority. (A loop is, so
    that this test can fail.)"""
    app = create_app(make_config(tmp_path, wait_seconds=0.2, checks_per_minute=600, check_burst=100))
    files = [p for pid in ("12.14", "12.22") for p in golden(pid)]
    files += [REPO / "reference_solutions" / pid / "answer.py" for pid in ("12.14", "12.22")]
    with TestClient(app) as client:
        queue = app.state.server.queue
        bob = bearer(app, "bob")
        sids = []
        for path in files:
            pid = path.parent.name
            r = client.post(f"/api/v1/problems/{pid}/check", headers=bob, params={"plot": "1"},
                            files={"file": (f"answer{path.suffix}", path.read_bytes())})
            assert r.status_code in (200, 202), r.text
            sids.append(r.json()["submission_id"])
            assert graded(client, bob, sids[-1], 120).status_code == 200
            assert all(nice(h.pid) == 0 for h in queue.graders if h.proc.poll() is None)
        assert not set(queue.lowered) & set(sids)
        loop = client.post("/api/v1/problems/12.14/check", headers=bearer(app, "alice"),
                           files={"file": ("answer.py", LOOP)}).json()["submission_id"]
        assert _grading(queue, loop, 60) is not None


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_a_slow_grading_without_a_place_is_stopped_and_graded_once_later(tmp_path):
    """One place for slow gradings (``max_graders`` one beyond ``workers + spares``): the first loop
    keeps it; the second, once over its budget, is stopped, a right answer sent after it is graded
    at once, and the second loop is graded later, once, with the verdict of its CPU bound."""
    (tmp_path / "hw.toml").write_text('name = "hw"\n[limits]\ncpu_seconds = 2\nwall_seconds = 4\n[[problems]]\n'
                                      'id = "12.14"\n', encoding="utf-8")
    app = create_app(make_config(tmp_path, workers=1, spare_graders=1, max_graders=3, cpu_budget=0.3,
                                 wait_seconds=0.2))
    right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes()
    with TestClient(app) as client:
        queue = app.state.server.queue
        loops = {}
        for who in ("alice", "dave"):
            loops[who] = client.post("/api/v1/problems/12.14/check", headers=bearer(app, who),
                                     files={"file": ("answer.py", LOOP)}).json()["submission_id"]
            assert _grading(queue, loops[who], 60) is not None, f"{who}'s loop was never lowered"
        end = time.monotonic() + 30
        while not queue.stopped and time.monotonic() < end:
            time.sleep(0.05)
        assert list(queue.stopped) == [loops["dave"]], "the second loop was not the one stopped"
        assert loops["alice"] not in queue.stopped
        bob = bearer(app, "bob")
        sid = client.post("/api/v1/problems/12.14/check", headers=bob,
                          files={"file": ("answer.py", right)}).json()["submission_id"]
        r = graded(client, bob, sid, 120)
        assert r.status_code == 200 and r.json()["score"] == r.json()["max_score"]
        # the order, not the seconds (a loaded machine stretches those): the stopped loop is still waiting
        assert client.get(f"/api/v1/submissions/{loops['dave']}", headers=bearer(app, "dave")).status_code == 202, \
            "the right answer waited for the stopped loop"
        assert len(queue.graders) <= 3
        for who, loop in loops.items():
            body = graded(client, bearer(app, who), loop, 150).json()
            assert body["state"] == "graded" and body["status"] == "timeout" and body["score"] == 0, body
            assert "ran longer than 2 s of CPU time" in " ".join(body["problems"]) or \
                "ran longer than 12 s" in " ".join(body["problems"])
    con = sqlite3.connect(tmp_path / "serve.sqlite")
    twice = con.execute("SELECT count(*) FROM (SELECT 1 FROM grade_log GROUP BY student, problem, file_hash "
                        "HAVING count(*) > 1)").fetchone()[0]
    con.close()
    assert twice == 0
