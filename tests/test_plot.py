"""`lagrade check --plot` draws the student's motion against the true one for a wrong dynamics part."""

from __future__ import annotations

import json
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


def test_plot_into_a_missing_folder_is_refused_and_nothing_is_created(tmp_path):
    """`--plot` made every missing parent folder (issue 43, item 6): a typo, or a path anywhere the
    user may write, became a tree of folders. It is refused at once, in one line naming the folder."""
    answer = ROOT / "tests" / "answers" / "12.43" / "wrong_sign_of_V.py"
    out = tmp_path / "missing" / "deeper" / "motion.png"
    result = CliRunner().invoke(main, ["check", "12.43", str(answer), "--plot", str(out)])
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and str(out.parent) in lines[0] and "does not exist" in lines[0], result.output
    assert not (tmp_path / "missing").exists()
    result = CliRunner().invoke(main, ["check", "12.43", str(answer), "--plot", str(out), "--json"])
    assert result.exit_code == 2 and str(out.parent) in json.loads(result.output)["error"]
    assert not (tmp_path / "missing").exists()
    (tmp_path / "a_file").write_text("")
    result = CliRunner().invoke(main, ["check", "12.43", str(answer), "--plot", str(tmp_path / "a_file" / "m.png")])
    assert result.exit_code == 2 and "not a folder" in result.output, result.output
