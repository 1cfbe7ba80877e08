"""`lagrade show` and `lagrade template` with --server: a student with the engine alone (no problem
data) reads the problem, and its figure, from the course server."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from serverkit import png_chunks

import lagrade.problem.library
from lagrade.cli import main
from lagrade.uses.server.tokens import issue


@pytest.fixture
def no_data(monkeypatch):
    """No problem data here: any read of a problem file fails, as on a student's engine-only install."""
    def nothing(*args, **kwargs):
        raise AssertionError("the client read a problem file")

    monkeypatch.setattr(lagrade.problem.library, "load_problem", nothing)


def test_show_and_template_read_the_problem_from_the_server(graded, live_url, no_data, tmp_path):
    server = graded[0].state.server
    token = issue(server.secret, "reader")
    fig = tmp_path / "fig.png"
    out = CliRunner().invoke(main, ["show", "12.14", "--server", live_url, "--token", token, "--figure", str(fig)])
    assert out.exit_code == 0, out.output
    assert out.output.startswith(server.text("show", "12.14")) and "Fig. P12.14" in out.output
    assert png_chunks(fig.read_bytes())[0] == "IHDR"
    out = CliRunner().invoke(main, ["template", "12.22", "--server", live_url, "--token", token])
    assert out.exit_code == 0 and out.output == server.text("template", "12.22")
    bad = CliRunner().invoke(main, ["show", "12.14", "--server", live_url, "--token", "nope"])
    assert bad.exit_code == 1 and "401" in bad.output


def test_no_data_tells_a_student_of_the_server_not_of_pip():
    assert "pip install" not in lagrade.problem.library.NO_DATA
    assert "lagrade show ID --server URL --token T" in lagrade.problem.library.NO_DATA
