"""What a new user trips on, tried as one would from the README (issue 33's last bullet)."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

import lagrade
from lagrade.cli import main

ROOT = Path(__file__).resolve().parents[1]


def run(*args: str):
    res = CliRunner().invoke(main, list(args))
    return res.exit_code, res.output


def test_the_readme_python_example_runs(tmp_path, monkeypatch):
    """The README's API block, as written (answer.py: the reference of 12.22)."""
    block = re.search(r"## Python API\n\n```python\n(.*?)```", (ROOT / "README.md").read_text(), re.S).group(1)
    shutil.copy(ROOT / "reference_solutions" / "12.22" / "answer.py", tmp_path / "answer.py")
    monkeypatch.chdir(tmp_path)
    scope: dict = {}
    exec(compile(block, "README.md", "exec"), scope)  # noqa: S102 - the README's own example
    assert scope["result"].problem == "12.43" and scope["p_theta"].name == "p_theta"


def test_an_unknown_name_in_H_lists_the_momenta_too():
    import sympy as sp

    p, m, l, g = sp.symbols("p m l g")
    theta = sp.Function("theta")(sp.Symbol("t"))
    part = lagrade.check("12.43", H=p**2 / (2 * m * l**2) - m * g * l * sp.cos(theta)).parts[0]
    assert part.verdict == "invalid" and "p_theta" in part.feedback


@pytest.mark.parametrize("text, suffix, hint", [
    ("", ".py", None),
    ("Lagrangian = 1\n", ".py", "did you mean 'L' for 'Lagrangian'"),
    ("Lagrangian = \"1\"\nequations = \"x\"\n", ".toml", "'eom' for 'equations'"),
    ("x = 1\n", ".py", None),
])
def test_a_file_with_no_expected_name_is_told_once(tmp_path, text, suffix, hint):
    path = tmp_path / f"answer{suffix}"
    path.write_text(text)
    result = lagrade.check("12.22", path)
    said = [line for line in result.problems if "no expected name found" in line]
    assert len(said) == 1 and "L, eom" in said[0], result.problems
    assert not any(line.endswith("; ignored") for line in result.problems)  # once, not per name
    if hint:
        assert hint in said[0]
    else:
        assert "did you mean" not in said[0]


def test_a_file_with_one_expected_name_is_not_told_so(tmp_path):
    path = tmp_path / "answer.toml"
    path.write_text('L = "1"\n')
    assert not any("no expected name" in line for line in lagrade.check("12.22", path).problems)


@pytest.mark.parametrize("name, text", [("answer.py", "L = (\n"), ("answer.toml", 'L = "x\n')])
def test_a_syntax_error_exits_2_in_python_and_in_toml(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    code, out = run("check", "12.22", str(path))
    assert code == 2, out


def test_a_bad_credit_file_is_one_line(tmp_path):
    credit = tmp_path / "credit.toml"
    credit.write_text("[credit]\nscaled_lagrangian = 3\nfoo = 1\n")
    code, out = run("check", "12.22", str(ROOT / "reference_solutions" / "12.22" / "answer.py"), "--credit",
                    str(credit))
    assert code == 2
    assert len(out.strip().splitlines()) == 1 and "scaled_lagrangian" in out and "pydantic" not in out


def test_list_with_no_problem_data_says_so(tmp_path, monkeypatch):
    import lagrade.problem.library as library

    monkeypatch.setattr(library, "problem_dirs", lambda extra=(): [tmp_path / "none"])
    code, out = run("list")
    assert code == 0 and "no problem data" in out


def test_no_numpy_warning_reaches_the_student(tmp_path):
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        lagrade.check("12.46", ROOT / "tests" / "answers" / "12.46" / "wrong_reduced_X_dd_zero.py")
    assert [w for w in caught if issubclass(w.category, RuntimeWarning)] == []


def test_prairielearn_build_takes_the_assignment_as_the_readme_says(tmp_path, monkeypatch):
    """`lagrade prairielearn build hw7.toml -o pl/`: a question per problem of the assignment (the
    grader itself, wheels and Dockerfile, is built once; faked here, tests/deploy builds it)."""
    import lagrade.uses.deploy.prairielearn as pl

    built = []

    def fake_build(output, problem_id, problems_dirs=(), wheel=None, *, image, uuid_seed=None):
        built.append(problem_id)
        (output / "questions" / f"lagrade-{problem_id}").mkdir(parents=True)
        return ["Dockerfile"]

    monkeypatch.setattr(pl, "build_grader", fake_build)
    hw7 = tmp_path / "hw7.toml"
    hw7.write_text('title = "Homework 7"\n[[problems]]\nid = "12.22"\n[[problems]]\nid = "12.43"\n')
    code, out = run("prairielearn", "build", str(hw7), "-o", str(tmp_path / "pl"), "--image", "course/lagrade:1")
    assert code == 0, out
    assert built == ["12.22"]
    assert (tmp_path / "pl" / "questions" / "lagrade-12.43" / "info.json").is_file()
    assert "README" not in out
