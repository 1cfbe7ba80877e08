"""`lagrade check` and `lagrade.check(...)` are one path (`lagrade.verdicts.grade.check`): the same file gives
the same result either way, a problem file's scene error is its FILE:LINE line either way, and exit
code 2 means what it meant when the CLI read the loaded answer itself."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

import lagrade
from lagrade.verdicts import grade
from lagrade.answer.reading.load import load_answer
from lagrade.cli import main
from lagrade.problem.library import SceneFileError, load_problem
from lagrade.problem.spec import SceneError, SpecError

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = ROOT / "tests" / "answers"


def _comparable(data: dict) -> dict:
    """The result without the seconds a trajectory comparison took (the rest is deterministic)."""
    for part in data["parts"]:
        part["feedback"] = re.sub(r"\d+(\.\d+)? s\b", "<seconds>", part["feedback"])
    return data


@pytest.mark.parametrize("pid, answer, code", [
    ("12.14", ROOT / "reference_solutions" / "12.14" / "answer.py", 0),
    ("12.14", GOLDEN / "12.14" / "wrong_missing_cross_term.py", 1),
    ("12.22", GOLDEN / "12.22" / "correct_plain.toml", 0),
    ("12.22", GOLDEN / "12.22" / "wrong_case_upward.toml", 1),
])
def test_the_cli_and_the_python_api_give_the_same_result(pid, answer, code):
    out = CliRunner().invoke(main, ["check", pid, str(answer), "--json"])
    assert out.exit_code == code, out.output
    api = lagrade.check(pid, answer)
    assert _comparable(json.loads(out.output)) == _comparable(json.loads(api.model_dump_json()))
    assert api.full_marks == (code == 0) and not grade.unusable(api)


def test_an_unusable_file_is_exit_2_in_the_cli_and_unusable_in_the_api(tmp_path):
    broken = tmp_path / "answer.py"
    broken.write_text("L = (\n")
    out = CliRunner().invoke(main, ["check", "12.14", str(broken), "--json"])
    assert out.exit_code == 2
    api = lagrade.check("12.14", broken)
    assert grade.unusable(api)
    assert json.loads(out.output) == json.loads(api.model_dump_json())


@pytest.mark.parametrize("name, content", [
    ("answer.py", "L = (\n"),                                                    # does not parse
    ("answer.py", "import os\nL = 1\n"),                                         # rejected
    ("answer.py", "from lagrade.answer import *\nL = 1\nraise ValueError('stop')\n"),  # stops after L
    ("answer.py", "from lagrade.answer import *\nraise ValueError('stop')\n"),         # stops before any
    ("answer.toml", "this is [not toml\n"),                                      # not TOML at all
    ("answer.toml", 'L = "m*("\neom = "+"\neom_exact = "+"\nomega = "1/0 +"\n'),  # no part parses
    ("answer.toml", 'L = "m*("\nomega = "1/0 +"\n'),                             # some parts do not parse
    ("answer.toml", 'eom = "x"\n'),                                              # an unknown name
])
def test_unusable_from_the_result_is_what_the_loaded_answer_said(tmp_path, name, content):
    """The rule exit code 2 used to read off the loaded answer (it stopped, and gave no value), read
    now off the result alone."""
    problem = load_problem("12.14")
    path = tmp_path / name
    path.write_text(content)
    loaded = load_answer(path, problem)
    expected = loaded.fatal is not None and not loaded.values
    assert grade.unusable(grade.grade_values(problem, loaded, read_as=())) == expected
    assert grade.unusable(lagrade.check(problem, path)) == expected


def _undeclared_effect(tmp_path: Path) -> tuple[Path, int]:
    """12.35 with dry friction declared as drag: its scene cannot be derived; the effects' line."""
    src = (ROOT / "problems" / "12.35.toml").read_text()
    old_q = next(line for line in src.splitlines() if line.startswith("Q = { theta"))
    old_effects = next(line for line in src.splitlines() if line.startswith("effects = ["))
    effects = 'effects = ["holonomic_constraint", "constraint_force", "dissipation_drag"]'
    src = src.replace(old_q, 'Q = { theta = "-mu*m*a**2*theta_d/Abs(theta_d)" }').replace(old_effects, effects)
    (tmp_path / "12.35.toml").write_text(src)
    return tmp_path / "12.35.toml", 1 + src.splitlines().index(effects)


def test_a_scene_error_from_the_python_api_names_the_problem_file_and_line(tmp_path):
    path, line = _undeclared_effect(tmp_path)
    answer = ROOT / "reference_solutions" / "12.35" / "answer.py"
    for how in ({"problem": "12.35", "problem_dirs": (tmp_path,)}, {"problem": path}):
        with pytest.raises(SceneFileError) as info:
            lagrade.check(answer=answer, **how)
        message = str(info.value)
        assert "\n" not in message and message.startswith(f"{path}:{line}: "), message
        assert message.endswith("declare dissipation_friction")
        assert isinstance(info.value, SceneError) and isinstance(info.value, SpecError)
    out = CliRunner().invoke(main, ["check", "12.35", str(answer), "--problems", str(tmp_path)])
    assert out.exit_code == 2 and out.output.strip() == f"lagrade: {message}"


def test_unknown_parts_are_one_error_for_both(tmp_path):
    answer = ROOT / "reference_solutions" / "12.43" / "answer.py"
    with pytest.raises(grade.UnknownPartError, match="problem 12.43 has no part Lagr"):
        lagrade.check("12.43", answer, only=["Lagr"])
    out = CliRunner().invoke(main, ["check", "12.43", str(answer), "--part", "Lagr"])
    assert out.exit_code == 2 and out.output.strip() == "lagrade: problem 12.43 has no part Lagr"


def test_a_failure_while_the_answer_runs_still_collects_its_child():
    """An answer.py runs in its jailed child while the grader prepares; whatever fails meanwhile (here
    the caller's own warm-up), the child is waited for and its pipes closed, not left open."""
    import os

    def fds() -> set[str]:
        return set(os.listdir("/proc/self/fd"))

    def boom() -> None:
        raise RuntimeError("the caller's warm-up failed")

    answer = ROOT / "reference_solutions" / "12.22" / "answer.py"
    lagrade.check("12.22", answer)          # the zygote and every lasting descriptor exist from here on
    before = fds()
    with pytest.raises(RuntimeError, match="warm-up failed"):
        grade.check("12.22", answer, meanwhile=boom)
    assert fds() - before == set()
