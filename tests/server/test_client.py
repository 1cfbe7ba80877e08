"""``lagrade check ID answer --server URL --token T`` against a real server on 127.0.0.1: the same
report and exit codes as a local check, and no problem data or reference touched on the client."""

from __future__ import annotations

import json
import socket

import pytest
from click.testing import CliRunner
from serverkit import GOLDEN, REPO

from lagrade.cli import main
from lagrade.uses.server.tokens import issue

pytestmark = pytest.mark.slow


@pytest.fixture
def no_problem_data(monkeypatch):
    """Make every way to the problems and references fail: the client must not need them."""
    import lagrade.verdicts.grade
    import lagrade.problem.library

    def refuse(*a, **k):
        raise AssertionError("the client touched problem data")

    for name in ("load_problem", "problem_dirs", "reference_dir", "problem_path", "problem_ids"):
        monkeypatch.setattr(lagrade.problem.library, name, refuse)
    monkeypatch.setattr(lagrade.verdicts.grade, "references", refuse)


def _run(args):
    return CliRunner().invoke(main, ["check", *args])


def test_right_wrong_and_broken_answers(graded, live_url, no_problem_data, tmp_path):
    token = issue(graded[0].state.server.secret, "frank")
    right = _run(["12.22", str(REPO / "reference_solutions" / "12.22" / "answer.py"), "--server", live_url, "--token", token])
    assert right.exit_code == 0, right.output
    assert "total 5 / 5" in right.output and "correct" in right.output
    wrong = _run(["12.22", str(GOLDEN / "12.22" / "wrong_sign_of_V.py"), "--server", live_url, "--token", token, "--json"])
    assert wrong.exit_code == 1
    body = json.loads(wrong.output)
    assert {p["part"]: p["verdict"] for p in body["parts"]}["L"] == "incorrect" and body["submission_id"]
    broken = tmp_path / "answer.py"
    broken.write_text("L = (m*\n")
    out = _run(["12.22", str(broken), "--server", live_url, "--token", token])
    assert out.exit_code == 2


def test_errors_are_one_line(graded, live_url, no_problem_data, tmp_path):
    answer = GOLDEN / "12.22" / "correct_plain.toml"
    out = _run(["12.22", str(answer), "--server", live_url])  # no token
    assert out.exit_code == 2 and "401" in out.output and len(out.output.strip().splitlines()) == 1
    out = _run(["12.22", str(answer), "--server", live_url, "--token", "lg1.x.y"])
    assert out.exit_code == 2 and "401" in out.output
    token = issue(graded[0].state.server.secret, "frank")
    out = _run(["12.99", str(answer), "--server", live_url, "--token", token])
    assert out.exit_code == 2 and "no problem '12.99'" in out.output
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        closed = s.getsockname()[1]
    out = _run(["12.22", str(answer), "--server", f"http://127.0.0.1:{closed}", "--token", token, "--json"])
    assert out.exit_code == 2 and "cannot reach" in json.loads(out.output)["error"]


def test_the_report_is_a_local_checks(graded, live_url):
    token = issue(graded[0].state.server.secret, "client-report")
    for path in (GOLDEN / "12.22" / "wrong_sign_of_V.py", GOLDEN / "12.14" / "wrong_plain_potential_sign.toml"):
        pid = path.parent.name
        local = _run([pid, str(path)])
        remote = _run([pid, str(path), "--server", live_url, "--token", token])
        assert local.exit_code == remote.exit_code == 1

        def read_as(out):  # the "as lagrade read it" block: identical (the table's feedback holds timings)
            return out.split(f"Problem {pid}")[0]

        assert "as lagrade read it" in read_as(remote.output)
        assert read_as(remote.output) == read_as(local.output)
        table = [line for line in remote.output.splitlines() if "verdict" in line or line.strip().startswith("total")]
        assert table == [line for line in local.output.splitlines() if "verdict" in line or line.strip().startswith("total")]


def test_a_check_whose_answer_a_crash_cut_off_is_found_again(graded, live_url, monkeypatch, tmp_path):
    """Issue 32: the connection cut after the upload (a server killed mid-request, a proxy) left the
    student with no id. The server stores before it grades: the client finds its file among the
    attempts (by sha256) and waits for that attempt's grade."""
    import http.client
    import urllib.request

    import lagrade.uses.server.client as client

    app = graded[0]
    real, cut = urllib.request.urlopen, []

    def cutting(req, *a, **kw):
        response = real(req, *a, **kw)
        if req.get_method() == "POST" and not cut:  # the server got it and answered; the answer is lost
            response.read()
            response.close()
            cut.append(req.full_url)
            raise http.client.RemoteDisconnected("Remote end closed connection without response")
        return response

    monkeypatch.setattr(urllib.request, "urlopen", cutting)
    answer = tmp_path / "answer.py"
    answer.write_bytes((REPO / "reference_solutions" / "12.22" / "answer.py").read_bytes() + b"\n# cut off\n")
    out = client.remote_check(live_url, issue(app.state.server.secret, "alice"), "12.22", answer)
    assert cut and out["state"] == "graded" and out["score"] == out["max_score"]
    assert out["submission_id"] == max(a.id for a in app.state.server.db.attempts("alice", "12.22"))
    lost = tmp_path / "lost.toml"
    lost.write_text('L = "m1"\n', encoding="utf-8")
    monkeypatch.setattr(client, "_stored", lambda *a: None)  # the server did not store it
    cut.clear()
    with pytest.raises(client.ClientError, match="cut before the server answered.*send it again"):
        client.remote_check(live_url, issue(app.state.server.secret, "alice"), "12.22", lost)
