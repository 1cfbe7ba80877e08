"""The jail on container platforms: Gradescope's and PrairieLearn's commands under Docker's default
restrictions (no new namespaces, no Landlock), emulated here with a seccomp filter that refuses
``unshare``, ``mount`` and the Landlock calls, as Docker's profile does.

There the only file-view layer left is "grader root, answer another uid": both commands grade only
when the key (problem files, references, cache) is readable by the grader's uid alone, write the
layers into the result, and refuse with a clear result otherwise. On PrairieLearn the key is the
job's /grade/tests (the image holds none), which the grader makes private itself. The answer files attack with the
Python-level tripwires off (tests/security/tripwires_off), so the OS layers alone decide."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from lagrade.uses.deploy.jailcheck import exposed

REPO = Path(__file__).resolve().parents[2]
TRIPWIRES_OFF = REPO / "tests" / "security" / "tripwires_off"
DOCKERLIKE = '''import errno, os, sys
import pyseccomp as sc
f = sc.SyscallFilter(defaction=sc.ALLOW)
for name in ("unshare", "setns", "mount", "landlock_create_ruleset", "landlock_add_rule", "landlock_restrict_self"):
    f.add_rule(sc.ERRNO(errno.EPERM), name)
f.load()
os.execv(sys.argv[1], sys.argv[1:])
'''


def _seccomp() -> bool:
    try:
        import pyseccomp  # noqa: F401
    except Exception:  # noqa: BLE001
        return False
    return True


needs_root = pytest.mark.skipif(not sys.platform.startswith("linux") or os.geteuid() != 0 or not _seccomp(),
                                reason="the grader-root layer needs Linux, root and pyseccomp")


def _steal(reference: Path) -> str:
    """An answer that runs the reference solution: full marks wherever it can read the file."""
    return f"from lagrade.answer import *\nexec(open({str(reference)!r}).read())\n"


def _run(tmp: Path, args: list[str], pythonpath: list[Path], dockerlike: bool = True) -> subprocess.CompletedProcess:
    wrapper = tmp / "dockerlike.py"
    wrapper.write_text(DOCKERLIKE)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(map(str, [*pythonpath, TRIPWIRES_OFF])),
           "LAGRADE_CACHE": "off"}
    cmd = [sys.executable, "-m", "lagrade", *args]
    return subprocess.run([sys.executable, str(wrapper), *cmd] if dockerlike else cmd, capture_output=True,
                          text=True, env=env, timeout=300)


def _gradescope(tmp: Path, answer: str, pythonpath: list[Path], dockerlike: bool = True) -> tuple[int, dict]:
    (tmp / "submission").mkdir(exist_ok=True)
    (tmp / "submission" / "12.43.py").write_text(answer)
    (tmp / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "12.43"\n')
    res = _run(tmp, ["gradescope", "run", "--submission", str(tmp / "submission"), "--assignment",
                     str(tmp / "hw.toml"), "--results", str(tmp / "results.json"), "-j", "1"], pythonpath, dockerlike)
    return res.returncode, json.loads((tmp / "results.json").read_text())


def _prairielearn(tmp: Path, answer: str, pythonpath: list[Path]) -> dict:
    """A PrairieLearn job as PrairieLearn hands it over: the question's tests/ (the problem file)
    readable by all, under a folder others may enter; the grader must make it private itself."""
    grade = tmp / "grade"
    (grade / "data").mkdir(parents=True, exist_ok=True)
    (grade / "student").mkdir(exist_ok=True)
    (grade / "tests" / "problems").mkdir(parents=True, exist_ok=True)
    shutil.copyfile(REPO / "problems" / "12.43.toml", grade / "tests" / "problems" / "12.43.toml")
    for d in (tmp, grade, grade / "tests", grade / "tests" / "problems"):
        d.chmod(0o755)
    (grade / "tests" / "problems" / "12.43.toml").chmod(0o644)
    (grade / "data" / "data.json").write_text(json.dumps({"params": {"lagrade": {"problem": "12.43"}}}))
    (grade / "student" / "answer.py").write_text(answer)
    _run(tmp, ["prairielearn", "grade", "--root", str(grade)], pythonpath)
    return json.loads((grade / "results" / "results.json").read_text())


@pytest.fixture(scope="module")
def private_checkout():
    """A copy of the checkout whose problems/ and reference_solutions/ are 0700, as setup.sh and the
    Dockerfile install the problem data; the engine stays readable (the answer imports it)."""
    top = Path(tempfile.mkdtemp(prefix="lagrade-private-"))
    top.chmod(0o755)
    co = top / "co"
    shutil.copytree(REPO / "src", co / "src", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copyfile(REPO / "pyproject.toml", co / "pyproject.toml")
    for name in ("problems", "reference_solutions"):
        shutil.copytree(REPO / name, co / name)
        (co / name).chmod(0o700)
    for d in (co, co / "src"):
        d.chmod(0o755)
    yield co
    shutil.rmtree(top, ignore_errors=True)


@needs_root
def test_gradescope_refuses_where_the_answer_could_read_the_key(tmp_path):
    """Today's checkout keeps its references 0755: the uid layer alone would let the answer read them."""
    code, out = _gradescope(tmp_path, _steal(REPO / "reference_solutions/12.43/answer.py"), [REPO / "src"])
    assert code == 2 and out["score"] == 0 and "NOT graded" in out["output"], out
    assert "readable by other users" in out["extra_data"]["jail"]["refused"]
    assert "mount" not in out["extra_data"]["jail"]["active"] and "uid" in out["extra_data"]["jail"]["active"]


@needs_root
def test_prairielearn_hides_the_problem_it_is_handed_before_an_answer_runs():
    """The image holds no key; the job's /grade/tests does, readable by all as handed over. The grader
    makes it root's alone first: an answer that reads it fails (Permission denied), an honest one passes."""
    top = Path(tempfile.mkdtemp(prefix="lagrade-pljob-"))
    top.chmod(0o755)  # nothing above the job is private: only the grader's own step can hide it
    try:
        problem = top / "a" / "grade" / "tests" / "problems" / "12.43.toml"
        honest = (REPO / "reference_solutions/12.43/answer.py").read_text()
        peek = f"from lagrade.answer import *\nopen({str(problem)!r}).read()\n" + honest
        pl = _prairielearn(top / "a", peek, [REPO / "src"])
        assert pl["score"] == 0 and "key hidden by uid + private files" in pl["message"], pl
        assert "Permission denied" in " ".join(pl["format_errors"])
        assert problem.stat().st_mode & 0o077 == 0 and problem.stat().st_uid == 0
        pl = _prairielearn(top / "b", honest, [REPO / "src"])
        assert pl["gradable"] and pl["score"] == 1, pl
    finally:
        shutil.rmtree(top, ignore_errors=True)


@needs_root
def test_the_uid_layer_with_private_key_files_is_enough(private_checkout, tmp_path):
    co = private_checkout
    honest = (REPO / "reference_solutions/12.43/answer.py").read_text()
    code, out = _gradescope(tmp_path, honest, [co / "src"])
    assert code == 0 and out["score"] == 3, out
    jail = out["extra_data"]["jail"]
    assert jail["file_view"] == "uid + private files" and jail["refused"] is None and "mount" not in jail["active"]
    code, out = _gradescope(tmp_path, _steal(co / "reference_solutions/12.43/answer.py"), [co / "src"])
    assert code == 0 and out["score"] == 0, out  # the kernel refused the read: no marks


@needs_root
def test_the_full_jail_is_written_into_the_result(tmp_path):
    code, out = _gradescope(tmp_path, _steal(REPO / "reference_solutions/12.43/answer.py"), [REPO / "src"],
                            dockerlike=False)
    assert code == 0 and out["score"] == 0, out
    assert out["extra_data"]["jail"]["file_view"] == "mount" and "mount" in out["extra_data"]["jail"]["active"]


def test_exposed_reads_the_modes_up_the_tree():
    top = Path(tempfile.mkdtemp(prefix="lagrade-exposed-"))  # under /tmp (1777): nothing above is private
    try:
        (top / "data").mkdir()
        (top / "data" / "ref.py").write_text("L = 1\n")
        top.chmod(0o755)
        (top / "data").chmod(0o755)
        shown = exposed(top / "data" / "ref.py")
        assert shown and "readable by other users" in shown
        (top / "data").chmod(0o700)
        assert exposed(top / "data" / "ref.py") is None and exposed(top / "data") is None
        (top / "data").chmod(0o750)  # the group can read it: the answer may share the grader's group
        assert exposed(top / "data")
        (top / "data" / "ref.py").chmod(0o600)
        assert exposed(top / "data" / "ref.py") is None
        assert exposed(top / "nowhere") is None
    finally:
        shutil.rmtree(top, ignore_errors=True)
