"""The Gradescope autograder zip, run as Gradescope runs it, in a fake /autograder.

Every results.json is validated against a JSON schema written from Gradescope's "Autograder
Specifications" (gradescope_results.schema.json) and against what lagrade promises on top of it:
every test carries all its fields, the tests' max scores sum exactly to the assignment's total,
the score is the sum of the tests' scores, no verdict is said twice in a row.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import stat
import subprocess
import sys
import zipfile
from decimal import Decimal
from pathlib import Path

import jsonschema
import pytest
from click.testing import CliRunner

from lagrade.cli.bulk import gradescope
from lagrade.uses.deploy.gradescope import install_fake_root

REPO = Path(__file__).resolve().parents[2]
SCHEMA = json.loads((Path(__file__).parent / "gradescope_results.schema.json").read_text())
TEST_FIELDS = {"name", "number", "score", "max_score", "status", "output", "tags", "visibility"}
TOTAL = 10  # 12.3 weight 3 (2 parts) + 12.43 weight 7 (3 parts: 7/3 each, not a multiple of 1/10000)

ASSIGNMENT = """name = "hw7"
title = "Homework 7"
[gradescope]
visibility = "after_due_date"
tests_visibility = "hidden"
[[problems]]
id = "12.3"
weight = 3
[[problems]]
id = "12.43"
weight = 7
"""


def check_results(data: dict) -> None:
    """The promises every results.json keeps; raises AssertionError (or ValidationError) otherwise."""
    jsonschema.validate(data, SCHEMA)
    for t in data["tests"]:
        assert TEST_FIELDS <= set(t), t
        assert 0 <= t["score"] <= t["max_score"], t
        assert (t["status"] == "passed") == (t["score"] == t["max_score"]), t
        assert not re.search(r"\b(\w+): \1:", t["output"]), t["output"]  # "correct: correct: ..."
    assert sum(Decimal(str(t["max_score"])) for t in data["tests"]) == TOTAL
    assert Decimal(str(data["score"])) == sum(Decimal(str(t["score"])) for t in data["tests"])


@pytest.fixture(scope="module")
def autograder(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("gradescope")
    (tmp / "hw7.toml").write_text(ASSIGNMENT)
    out = tmp / "autograder.zip"
    res = CliRunner().invoke(gradescope, ["build", str(tmp / "hw7.toml"), "-o", str(out)])
    assert res.exit_code == 0, res.output
    assert "private: autograder.zip holds the problems" in res.output  # it is the key: never public
    return out


def run_autograder(zip_path: Path, root: Path, files: dict[str, bytes | Path], env: dict | None = None) -> dict:
    """Unpack into ``root`` as Gradescope does, put ``files`` in the submission, run run_autograder with
    this test's Python (setup.sh's venv stands in for it), return results.json."""
    run = install_fake_root(zip_path, root)
    for name, content in files.items():
        target = root / "submission" / name
        target.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, Path):
            shutil.copyfile(content, target)
        else:
            target.write_bytes(content)
    environ = {**os.environ, "AUTOGRADER_ROOT": str(root), "LAGRADE_PYTHON": sys.executable, **(env or {})}
    proc = subprocess.run([str(run)], env=environ, capture_output=True, text=True, timeout=600, cwd=root)
    assert proc.returncode == 0, proc.stderr
    return json.loads((root / "results" / "results.json").read_text())


def test_the_zip_holds_what_gradescope_runs(autograder):
    with zipfile.ZipFile(autograder) as z:
        names = z.namelist()
        modes = {i.filename: (i.external_attr >> 16) & 0o777 for i in z.infolist()}
        assert z.read("assignment.toml").decode() == ASSIGNMENT
        setup = z.read("setup.sh").decode()
    wheels = sorted(n for n in names if n.endswith(".whl"))
    assert {"setup.sh", "run_autograder", "assignment.toml"} <= set(names) and len(wheels) == 2
    assert modes["setup.sh"] & 0o111 and modes["run_autograder"] & 0o111
    assert "pip3 install lagrade" not in setup and '"$SRC"/lagrade-*.whl "$SRC"/lagrade_chapter12-*.whl' in setup
    inside = {}
    for name in wheels:
        with zipfile.ZipFile(autograder) as z, zipfile.ZipFile(__import__("io").BytesIO(z.read(name))) as w:
            inside[name.split("-")[0]] = w.namelist()
    # the wheels are this checkout: the grader; the problems and the reference solutions apart
    assert "lagrade/uses/deploy/gradescope.py" in inside["lagrade"]
    assert not [n for n in inside["lagrade"] if n.endswith(".toml") or "reference_solutions" in n]
    assert {"lagrade_chapter12/problems/12.43.toml", "lagrade_chapter12/reference_solutions/12.43/answer.py"} \
        <= set(inside["lagrade_chapter12"])


def test_a_right_submission_gets_full_marks(autograder, tmp_path):
    data = run_autograder(autograder, tmp_path / "root", {
        "12.3.py": REPO / "reference_solutions/12.3/answer.py",
        "12.43.py": REPO / "reference_solutions/12.43/answer.py"})
    check_results(data)
    assert data["score"] == TOTAL
    assert data["visibility"] == "after_due_date" and {t["visibility"] for t in data["tests"]} == {"hidden"}
    assert [t["name"] for t in data["tests"]] == ["12.3 L", "12.3 eom", "12.43 H", "12.43 hamilton", "12.43 eom"]
    assert [t["number"] for t in data["tests"]] == ["1.1", "1.2", "2.1", "2.2", "2.3"]


def test_a_wrong_submission_with_near_miss_names(autograder, tmp_path):
    data = run_autograder(autograder, tmp_path / "root", {
        "nested/12_3.py": REPO / "tests/answers/12.3/wrong_forgets_second_spring_on_x1.py",
        "12.43 (1).PY": REPO / "tests/answers/12.43/wrong_sign_of_V.py"})
    check_results(data)
    by_name = {t["name"]: t for t in data["tests"]}
    # 12.3: L right, eom half right, 1.5 each; 12.43: hamilton half of 7/3, H and eom wrong
    assert by_name["12.3 L"]["score"] == 1.5 and by_name["12.3 eom"]["score"] == 0.75
    assert by_name["12.43 H"]["status"] == "failed" and by_name["12.43 H"]["score"] == 0
    assert 0 < by_name["12.43 hamilton"]["score"] < by_name["12.43 hamilton"]["max_score"]
    assert "nested/12_3.py was graded as problem 12.3" in data["output"]
    assert "12.43 (1).PY was graded as problem 12.43" in data["output"]
    assert "Read as: `" in by_name["12.43 H"]["output"] and "(t)" not in by_name["12.43 H"]["output"]


def test_a_broken_submission_is_zero_with_the_reason_said_once(autograder, tmp_path):
    data = run_autograder(autograder, tmp_path / "root", {"12.43.py": b"from sympy import *\nH = (m*\n",
                                                          "notes.py": b"print('hello')\n"})
    check_results(data)
    assert data["score"] == 0
    h = [t for t in data["tests"] if t["name"].startswith("12.43")]
    assert "syntax" in h[0]["output"].lower() or "line" in h[0]["output"].lower(), h[0]["output"]
    assert all(t["output"] == "See 12.43 H." for t in h[1:])
    # not handed in: the same tests as a handed-in 12.3 (its parts, from the problem file), at 0
    missing = [t for t in data["tests"] if t["name"].startswith("12.3 ")]
    assert [t["name"] for t in missing] == ["12.3 L", "12.3 eom"] and all(t["score"] == 0 for t in missing)
    assert "No file 12.3.py" in missing[0]["output"] and sum(t["max_score"] for t in missing) == 3
    assert "notes.py matches no problem" in data["output"]


def test_a_hostile_submission_is_contained(autograder, tmp_path):
    sentinel = tmp_path / "pwned"
    data = run_autograder(autograder, tmp_path / "root", {
        "12.43.py": f"import os\nos.system('touch {sentinel}')\nH = 1\n".encode(),
        "12.3.py": f"open({str(sentinel)!r}, 'w').write('x')\nL = 1\n".encode()})
    check_results(data)
    assert data["score"] == 0 and not sentinel.exists()


def test_a_notebook_gets_what_the_same_answer_py_gets(autograder, tmp_path):
    """Gradescope's students hand in Jupyter notebooks too: their code cells, graded in the same jail."""
    sys.path.insert(0, str(REPO / "tests"))
    from notebook_files import as_notebook, code, notebook

    sources = {"12.3": REPO / "tests/answers/12.3/wrong_forgets_second_spring_on_x1.py",
               "12.43": REPO / "reference_solutions/12.43/answer.py"}
    as_py = run_autograder(autograder, tmp_path / "py", {f"{pid}.py": path for pid, path in sources.items()})
    (tmp_path / "nb").mkdir()
    as_nb = run_autograder(autograder, tmp_path / "nb", {
        f"{pid}.ipynb": as_notebook(path.read_text(), tmp_path / f"{pid}.ipynb") for pid, path in sources.items()})
    check_results(as_nb)
    assert [(t["name"], t["score"], t["status"]) for t in as_nb["tests"]] == \
        [(t["name"], t["score"], t["status"]) for t in as_py["tests"]]
    assert 0 < as_nb["score"] < TOTAL
    sentinel = tmp_path / "pwned"
    hostile = tmp_path / "hostile.ipynb"
    hostile.write_text(json.dumps(notebook([code(f"open({str(sentinel)!r}, 'w').write('x')\nH = 1")])))
    data = run_autograder(autograder, tmp_path / "hostile", {"12.43.ipynb": hostile})
    check_results(data)
    assert data["score"] == 0 and not sentinel.exists()


def test_lagrade_failing_still_leaves_a_result(autograder, tmp_path):
    """A broken install (here: a Python without lagrade) must not leave the student with no result."""
    data = run_autograder(autograder, tmp_path / "root", {"12.3.py": b"L = 1\n"},
                          env={"LAGRADE_PYTHON": "/bin/false"})
    jsonschema.validate(data, SCHEMA)
    assert data["score"] == 0 and "could not grade" in data["output"] and data["tests"] == []


def test_the_schema_catches_what_gradescope_rejects():
    """The schema is not vacuous: each of these breaks the specification."""
    good = {"score": 1.0, "tests": [{"name": "a", "score": 1.0, "max_score": 1.0, "status": "passed"}]}
    jsonschema.validate(good, SCHEMA)
    for bad in ({"tests": [{"name": "a"}]},                                   # no score anywhere
                {**good, "visibility": "students"},                          # not a visibility
                {**good, "output_format": "markdown"},                       # Gradescope says "md"
                {**good, "tests": [{**good["tests"][0], "status": "ok"}]},   # not a status
                {**good, "tests": [{**good["tests"][0], "number": 1}]},      # number is a string
                {**good, "score_total": 3}):                                 # not a field
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(bad, SCHEMA)


def test_max_scores_that_do_not_divide_still_sum_to_the_total():
    from lagrade.uses.bulk.assignment import split_points

    for total, weights in [(10, [1, 1, 1]), (7, [1, 1, 1]), (1, [2, 3, 5, 7]), (9.5, [1] * 6), (0, [1, 2])]:
        shares = split_points(total, weights)
        assert sum(Decimal(str(s)) for s in shares) == Decimal(str(total)), (total, weights, shares)
        assert all(abs(s - total * w / sum(weights)) < 1e-4 + 1e-12 for s, w in zip(shares, weights))


@pytest.mark.slow
def test_setup_sh_installs_the_wheel_into_a_venv(autograder, tmp_path):
    """setup.sh as Gradescope runs it (with this Python >= 3.11 already there: nothing from apt), then
    run_autograder with the venv it made. Needs PyPI for lagrade's dependencies: minutes."""
    root = tmp_path / "root"
    install_fake_root(autograder, root)
    cache = tmp_path / "cache"
    env = {**os.environ, "AUTOGRADER_ROOT": str(root), "LAGRADE_SETUP_PYTHON": sys.executable,
           "LAGRADE_CACHE": str(cache)}
    env.pop("VIRTUAL_ENV", None)
    proc = subprocess.run(["bash", str(root / "source" / "setup.sh")], env=env, capture_output=True, text=True,
                          timeout=1800)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    # the reference cache is built, and the key is the grader's uid's alone (0700)
    assert list(cache.iterdir()), proc.stdout[-2000:]
    data = subprocess.run([str(root / "venv" / "bin" / "python"), "-c",
                           "from lagrade.problem.library import data_root; print(data_root())"],
                          env=env, capture_output=True, text=True).stdout.strip()
    for d in (Path(data), cache, root / "source"):
        assert stat.S_IMODE(d.stat().st_mode) == 0o700, d
    shutil.copyfile(REPO / "reference_solutions/12.3/answer.py", root / "submission" / "12.3.py")
    proc = subprocess.run([str(root / "run_autograder")], env={**env, "LAGRADE_PYTHON": ""}, capture_output=True,
                          text=True, timeout=600)
    data = json.loads((root / "results" / "results.json").read_text())
    check_results(data)
    assert data["score"] == 3, (data, proc.stderr[-2000:])


def test_extra_problem_folders_are_shipped_and_used(tmp_path):
    extra = tmp_path / "extra"
    extra.mkdir()
    shutil.copyfile(REPO / "problems" / "12.3.toml", extra / "12.3.toml")
    (tmp_path / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "12.3"\n')
    out = tmp_path / "ag.zip"
    res = CliRunner().invoke(gradescope, ["build", str(tmp_path / "hw.toml"), "-o", str(out), "--problems", str(extra)])
    assert res.exit_code == 0, res.output
    assert "problems/12.3.toml" in zipfile.ZipFile(out).namelist()
    run = install_fake_root(out, tmp_path / "root")
    assert '--problems "$ROOT/source/problems"' in run.read_text() and (tmp_path / "root/source/problems/12.3.toml").is_file()
    bad = CliRunner().invoke(gradescope, ["build", str(tmp_path / "hw.toml"), "-o", str(out), "--problems", str(extra),
                                          "--wheel", str(tmp_path / "hw.toml")])
    assert bad.exit_code == 1 and "is not a lagrade wheel" in bad.output


def test_an_assignment_with_an_unknown_problem_is_refused(tmp_path):
    (tmp_path / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "99.99"\n')
    res = CliRunner().invoke(gradescope, ["build", str(tmp_path / "hw.toml"), "-o", str(tmp_path / "ag.zip")])
    assert res.exit_code == 2 and "99.99" in res.output and not (tmp_path / "ag.zip").exists()


def test_the_zip_pins_its_dependencies(autograder):
    """Issue 47: setup.sh installed the wheel's dependencies from PyPI unpinned (and pip upgraded)."""
    from importlib.metadata import version

    from lagrade.uses.deploy.pins import requirements_txt

    with zipfile.ZipFile(autograder) as z:
        setup = z.read("setup.sh").decode()
        assert z.read("requirements.txt").decode() == requirements_txt()
    assert f'-m pip install --quiet "pip=={version("pip")}"' in setup and "--upgrade pip" not in setup
    assert '-m pip install -r "$SRC/requirements.txt"' in setup
    assert '-m pip install --no-deps "$SRC"/lagrade-*.whl' in setup
