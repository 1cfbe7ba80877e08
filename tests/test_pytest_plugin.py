"""The pytest plugin serves any course: free problem ids, folders of any name."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]

ROOT = Path(__file__).resolve().parents[1]
PID = "hw7-q2_pendulum"


@pytest.fixture
def course(pytester):
    """A course repository with its own names: a problem whose id is not the chapter's, in
    ``bank/``, its key in ``key/``, golden answers in ``checks/`` and a folder that only looks
    like an id."""
    text = (ROOT / "problems" / "12.43.toml").read_text()
    text = re.sub(r'^id = "12\.43"', f'id = "{PID}"', text, count=1, flags=re.MULTILINE)
    (pytester.path / "bank").mkdir()
    (pytester.path / "bank" / f"{PID}.toml").write_text(text)
    for folder, name, source in [("key", "answer.py", ROOT / "reference_solutions" / "12.43" / "answer.py"),
                                 ("checks", "correct_same.py", ROOT / "reference_solutions" / "12.43" / "answer.py")]:
        (pytester.path / folder / PID).mkdir(parents=True)
        (pytester.path / folder / PID / name).write_text(source.read_text())
    wrong = (ROOT / "reference_solutions" / "12.43" / "answer.py").read_text().replace("cos(theta)", "sin(theta)")
    (pytester.path / "checks" / PID / "wrong_sin.py").write_text(wrong)
    (pytester.path / "checks" / "not-a-problem").mkdir()
    (pytester.path / "checks" / "not-a-problem" / "correct_x.py").write_text("L = 1\n")
    return pytester


def test_a_course_with_its_own_names_is_collected_and_graded(course):
    """One run (a subprocess: numpy cannot be imported twice in one process): four items pass, a
    wrong answer labelled correct fails with the grading feedback, and a folder that only looks
    like an id is not collected."""
    (course.path / "checks" / PID / "correct_mislabelled.py").write_text(
        (course.path / "checks" / PID / "wrong_sin.py").read_text())
    result = course.runpytest_subprocess("bank", "key", "checks", "-p", "no:randomly", "-v")
    result.assert_outcomes(passed=4, failed=1)
    result.stdout.fnmatch_lines_random([f"*problem {PID}*PASSED*", f"*{PID}/answer.py*PASSED*",
                                        f"*{PID}/correct_same.py*PASSED*", f"*{PID}/wrong_sin.py*PASSED*",
                                        "*correct_mislabelled.py: expected full marks*"])
    assert "not-a-problem" not in result.stdout.str()


def test_problem_ids_are_free_but_not_anything():
    from lagrade.problem.spec import ID

    for pid in ("12.22", "ex12.3", PID, "HW-7.2", "a"):
        assert re.fullmatch(ID, pid)
    for pid in ("", "-x", ".hidden", "a/b", "a b", "x" * 65, "../12.22"):
        assert not re.fullmatch(ID, pid)
