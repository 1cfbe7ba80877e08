"""Notebooks through the course server (docs/notebooks.md): an uploaded notebook gets the verdicts of the
same answer.py; ``lagrade.check(..., server=, token=)`` in a notebook shows the server's grade, its
picture of a wrong motion, and no more than the course's feedback level lets a student see."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from serverkit import REPO, bearer, on_a_socket

from lagrade.uses.server.tokens import issue

sys.path.insert(0, str(REPO / "tests"))
from notebook_files import as_notebook  # noqa: E402

pytestmark = pytest.mark.slow

REFERENCE = REPO / "reference_solutions" / "12.22" / "answer.py"
WRONG = REPO / "tests" / "answers" / "12.22" / "wrong_sign_of_V.py"


def _upload(client, headers, name: str, data: bytes) -> dict:
    r = client.post("/api/v1/problems/12.22/check", headers=headers, files={"file": (name, data)})
    assert r.status_code == 200, r.text
    return r.json()


def _verdicts(parts) -> list[tuple]:
    return [(p["part"], p["verdict"], p["score"]) if isinstance(p, dict) else (p.part, p.verdict, p.score)
            for p in parts]


def _wrong_eom():
    from lagrade.answer import Eq, coordinates, parameters, t

    x, y, z = coordinates("x y z")
    g = parameters("g")
    return [Eq(x.diff(t, 2), g), Eq(y.diff(t, 2), 0), Eq(z.diff(t, 2), 0)]


def test_an_uploaded_notebook_gets_the_verdicts_of_the_same_answer_py(graded, tmp_path):
    _, client, alice = graded
    for source in (REFERENCE, WRONG):
        nb = as_notebook(source.read_text(), tmp_path / f"{source.stem}.ipynb")
        as_py = _upload(client, alice, "answer.py", source.read_bytes())
        as_nb = _upload(client, alice, "answer.ipynb", nb.read_bytes())
        assert _verdicts(as_nb["parts"]) == _verdicts(as_py["parts"]) and as_nb["score"] == as_py["score"]
    broken = _upload(client, alice, "answer.ipynb", b'{"cells": [')
    assert broken["problems"] == ["answer.ipynb: not a Jupyter notebook: the file is not valid JSON (line 1)"]


def _no_problem_data(monkeypatch) -> None:
    """Every way to the problems and references fails from here on: a student's install has none."""
    import lagrade.problem.library
    import lagrade.verdicts.grade

    def refuse(*a, **k):
        raise AssertionError("the client touched problem data")

    for name in ("load_problem", "problem_dirs", "reference_dir", "problem_path", "problem_ids"):
        monkeypatch.setattr(lagrade.problem.library, name, refuse)
    monkeypatch.setattr(lagrade.verdicts.grade, "references", refuse)


def test_lagrade_check_in_a_notebook_through_the_server(graded, live_url, tmp_path, monkeypatch):
    import lagrade
    from lagrade.cli import main

    token = issue(graded[0].state.server.secret, "nora")
    nb = as_notebook(REFERENCE.read_text(), tmp_path / "answer.ipynb")
    local = lagrade.check("12.22", REFERENCE)
    _no_problem_data(monkeypatch)
    remote = lagrade.check("12.22", nb, server=live_url, token=token)
    assert _verdicts(remote.parts) == _verdicts(local.parts) and remote.full_marks
    assert remote.picture() is None and "5 / 5" in remote._repr_html_()
    out = CliRunner().invoke(main, ["check", "12.22", str(nb), "--server", live_url, "--token", token])
    assert out.exit_code == 0 and "total 5 / 5" in out.output, out.output
    # parts given as sympy objects: sent as an answer.py, graded by the server, its picture shown
    wrong = lagrade.check("12.22", eom=_wrong_eom(), L=None, server=live_url, token=token)
    assert wrong.verdicts() == {"L": "missing", "eom": "incorrect", "a": "missing", "S_t": "missing",
                                "a_case": "missing"}
    png = wrong.picture()
    assert png is not None and png.startswith(b"\x89PNG")
    assert wrong._repr_html_().count("data:image/png;base64,") == 1 and r"\ddot{x} = g" in wrong._repr_html_()


@pytest.fixture(scope="module")
def verdict_only_url(tmp_path_factory):
    """A graded server whose course shows the verdict alone, on a socket of 127.0.0.1."""
    from fastapi.testclient import TestClient
    from serverkit import make_config

    from lagrade.uses.server.app import create_app

    tmp = tmp_path_factory.mktemp("verdict-nb")
    (tmp / "hw.toml").write_text('name = "hw-nb"\n[rules]\nfeedback = "verdict"\n[[problems]]\nid = "12.22"\n',
                                 encoding="utf-8")
    app = create_app(make_config(tmp, checks_per_minute=6000, check_burst=1000, student_in_flight=1000))
    with TestClient(app), on_a_socket(app) as url:
        yield app, url


def test_the_course_feedback_level_decides_what_a_notebook_shows(verdict_only_url):
    import lagrade

    app, url = verdict_only_url
    token = bearer(app, "olga")["Authorization"].split()[1]
    wrong = lagrade.check("12.22", eom=_wrong_eom(), server=url, token=token)
    eom = next(p for p in wrong.parts if p.part == "eom")
    assert eom.verdict == "incorrect" and eom.feedback == "Incorrect."
    assert wrong.picture() is None and "data:image/png" not in wrong._repr_html_()
    assert "separates" not in wrong._repr_html_() and "separates" not in json.dumps(wrong._repr_markdown_())
    with pytest.raises(TypeError, match="hints: not with server="):
        lagrade.check("12.22", eom=_wrong_eom(), server=url, token=token, hints=True)
