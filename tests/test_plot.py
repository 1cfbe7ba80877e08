"""`lagrade check --plot` draws the student's motion against the true one for a wrong dynamics part."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from lagrade.cli import main

ROOT = Path(__file__).resolve().parents[1]


def test_plot_of_a_wrong_answer_is_a_nonempty_png(tmp_path):
    out = tmp_path / "motion.png"
    answer = ROOT / "tests" / "answers" / "12.43" / "wrong_sign_of_V.py"
    result = CliRunner().invoke(main, ["check", "12.43", str(answer), "--plot", str(out)])
    assert result.exit_code == 1, result.output
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000


def test_no_plot_for_a_correct_answer(tmp_path):
    out = tmp_path / "motion.png"
    answer = ROOT / "reference_solutions" / "12.43" / "answer.py"
    result = CliRunner().invoke(main, ["check", "12.43", str(answer), "--plot", str(out)])
    assert result.exit_code == 0
    assert not out.exists()
