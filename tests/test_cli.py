"""The command line as a user meets it: list, show, template, check, exit codes and --json."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from lagrade.cli import main

ROOT = Path(__file__).resolve().parents[1]
REF = ROOT / "reference_solutions"


def run(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.output


def test_list_shows_every_problem_with_part_counts():
    code, out = run("list")
    assert code == 0
    assert "12.22" in out and "Compound (double) Atwood" in out
    code, out = run("list", "--json")
    rows = json.loads(out)
    ids = [r["id"] for r in rows]
    assert "12.43" in ids and "ex12.3" in ids
    assert all(r["parts"] >= 1 for r in rows)
    assert ids.index("12.3") < ids.index("12.10") < ids.index("ex12.3"), "ids sort numerically"


def test_show_lists_names_assumptions_and_forms():
    code, out = run("show", "12.22")
    assert code == 0
    for needle in ("S_t", "a_case", "m1", "x(t)", "Assumptions", "dict with keys 'S1', 'S2', 'S3'"):
        assert needle in out


def test_show_unknown_problem_is_a_usage_error():
    code, out = run("show", "12.999")
    assert code == 2 and "no problem '12.999'" in out


def test_template_is_a_valid_answer_file_with_every_part_missing(tmp_path):
    code, out = run("template", "12.46")
    assert code == 0
    path = tmp_path / "answer.py"
    path.write_text(out)
    compile(out, str(path), "exec")
    code, out = run("check", "12.46", str(path), "--json")
    data = json.loads(out)
    assert code == 1
    assert {p["verdict"] for p in data["parts"]} == {"missing"}
    assert [p["part"] for p in data["parts"]] == ["L", "H", "cyclic", "conserved", "eom_reduced", "omega"]


def _declared(template: str) -> list[str]:
    """The names a template's top-level assignments declare, in order (repeats kept)."""
    import ast

    return [leaf.id for node in ast.parse(template).body if isinstance(node, ast.Assign)
            for target in node.targets for leaf in ast.walk(target) if isinstance(leaf, ast.Name)]


def test_no_template_declares_a_name_twice():
    """12.41's (b) and (b_small) share theta: a template declares it once, not once per system."""
    from lagrade.problem.describe import template_text
    from lagrade.problem.library import load_problem, problem_ids

    twice = {}
    for pid in problem_ids():
        names = _declared(template_text(load_problem(pid)))
        if len(names) != len(set(names)):
            twice[pid] = sorted({n for n in names if names.count(n) > 1})
    assert twice == {}


def test_an_unfilled_template_gets_no_did_you_mean(tmp_path):
    """An unfilled template binds only the problem's own symbols: nothing to guess an answer name from
    ("did you mean 'L' for 'l1'" was nonsense); a real misnaming still gets its guess."""
    from lagrade.answer.reading.load import no_expected_name
    from lagrade.problem.describe import template_text
    from lagrade.problem.library import load_problem, problem_ids

    path = tmp_path / "answer.py"
    guessed = {}
    for pid in problem_ids():
        problem = load_problem(pid)
        path.write_text(template_text(problem))
        said = no_expected_name(path, problem)
        if "did you mean" in said:
            guessed[pid] = said
    assert guessed == {}
    path.write_text(template_text(load_problem("12.22")) + "lagrangian = 0\n")
    assert "did you mean 'L' for 'lagrangian'" in no_expected_name(path, load_problem("12.22"))


def test_check_reference_exit_0_and_json_shape():
    code, out = run("check", "12.43", str(REF / "12.43" / "answer.py"), "--json")
    assert code == 0
    data = json.loads(out)  # exactly one JSON object
    assert set(data) >= {"problem", "score", "max_score", "parts"}
    assert data["problem"] == "12.43" and data["score"] == data["max_score"] == 3.0
    for part in data["parts"]:
        assert set(part) == {"part", "verdict", "score", "max_score", "method", "feedback", "read_as", "review",
                             "extra", "certified", "confirmed", "trajectory_evidence", "motion_evidence"}
        assert part["read_as"]  # the LaTeX of the answer as read
        assert part["method"] in {"symbolic", "numeric", "trajectory", "exact"}


def test_check_wrong_answer_exit_1_with_feedback(tmp_path):
    path = tmp_path / "answer.py"
    path.write_text("from lagrade.answer import *\nm, l, g = parameters('m l g')\ntheta = coordinates('theta')\n"
                    "eom = Eq(theta.diff(t, 2), -g/l*theta)\n")
    code, out = run("check", "12.43", str(path))
    assert code == 1
    assert "incorrect" in out and "missing" in out and "total 0 / 3" in out


@pytest.mark.parametrize("content, needle", [
    ("L = (\n", "answer.py:1"),
    ("import os\nL = 1\n", "import of 'os' is not allowed"),
])
def test_unusable_answer_exit_2_one_clear_line(tmp_path, content, needle):
    path = tmp_path / "answer.py"
    path.write_text(content)
    code, out = run("check", "12.43", str(path))
    assert code == 2
    assert needle in out


def test_missing_file_and_unknown_part_exit_2(tmp_path):
    assert run("check", "12.43", str(tmp_path / "nope.py"))[0] == 2
    code, out = run("check", "12.43", str(REF / "12.43" / "answer.py"), "--part", "Lagr")
    assert code == 2 and "no part Lagr" in out


def test_console_script_runs_the_bundled_example():
    exe = Path(sys.executable).with_name("lagrade")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "lagrade"]
    proc = subprocess.run([*cmd, "check", "12.22", str(REF / "12.22" / "answer.py")], capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "total 5 / 5" in proc.stdout


def test_read_back_is_one_line_in_the_books_notation():
    """The terminal read-back is one line per value: dots for velocities, subscripts, superscripts."""
    import sympy as sp

    from lagrade.verdicts.readback import as_unicode

    t = sp.Symbol("t")
    th = sp.Function("theta1")(t)
    l0, m1, alpha = sp.symbols("l_0 m1 alpha")
    text = as_unicode(m1 * l0**2 * th.diff(t) ** 2 / 2 - sp.sqrt(alpha) * sp.cos(th))
    assert "\n" not in text
    for piece in ("θ̇₁²", "l₀²", "m₁", "√α", "cos(θ₁)"):
        assert piece in text, (piece, text)
    assert as_unicode([sp.Eq(th.diff(t, 2), -sp.sin(th))]) == "θ̈₁ = -sin(θ₁)"


def test_read_back_in_latex_keeps_powers_of_coordinates_and_their_derivatives():
    """The notation is printed, not substituted: a power of q(t) or of q'(t) keeps its exponent."""
    import sympy as sp

    from lagrade.verdicts.readback import as_latex, as_unicode

    t = sp.Symbol("t")
    th = sp.Function("theta1")(t)
    assert as_latex(th**2) == r"\theta_{1}^{2}"
    assert as_latex(th.diff(t) ** 2) == r"\dot{\theta_{1}}^{2}"
    assert as_latex(th.diff(t, 3)) == r"\theta_{1}^{(3)}" and as_unicode(th.diff(t, 3)) == "θ₁^(3)"
    assert as_latex(sp.Eq(th.diff(t, 2), -sp.sin(th))) == r"\ddot{\theta_{1}} = - \sin{\left(\theta_{1} \right)}"
    assert as_unicode(sp.cos(th - sp.Function("theta2")(t))) == "cos(θ₁ - θ₂)"


@pytest.mark.parametrize("answer, code", [("reference", 0), ("wrong", 1), ("broken", 2)])
def test_a_check_in_its_own_process_exits_with_its_code_and_all_its_output(answer, code, tmp_path):
    # `python -m lagrade` leaves without the interpreter's teardown: the exit code and every byte of
    # the output (through a pipe, which Python buffers) must still come out
    files = {"reference": REF / "12.14" / "answer.py",
             "wrong": ROOT / "tests" / "answers" / "12.14" / "wrong_missing_cross_term.py",
             "broken": tmp_path / "broken.py"}
    files["broken"].write_text("L = (\n")
    buffered = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    proc = subprocess.run([sys.executable, "-m", "lagrade", "check", "12.14", str(files[answer]), "--json"],
                          capture_output=True, text=True, timeout=120, env=buffered)
    assert proc.returncode == code, proc.stderr
    result = json.loads(proc.stdout)
    assert [p["part"] for p in result["parts"]] == ["L", "eom", "eom_exact", "omega"]
    assert (result["score"] == result["max_score"]) == (code == 0)
    assert all(p["verdict"] == "invalid" for p in result["parts"]) == (code == 2)


def test_the_lagrade_script_starts_one_blas_thread_unless_told_otherwise(monkeypatch):
    """Set before any command imports numpy: every process of a check or a class saves the start of
    OpenBLAS's thread pools, which lagrade's few-row matrices never use."""
    from lagrade import cli
    from lagrade.cli import common

    seen = []
    monkeypatch.setattr(cli, "main", lambda: seen.append(os.environ.get("OPENBLAS_NUM_THREADS")))
    monkeypatch.setattr(common, "OWN_PROCESS", False)  # run() sets it; monkeypatch puts it back
    monkeypatch.delenv("OPENBLAS_NUM_THREADS", raising=False)
    cli.run()
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "3")
    cli.run()
    assert seen == ["1", "3"]
