"""No key in anything public (issue 43, item 3): the PrairieLearn grader image is pulled from a public
registry, so its build context holds the lagrade engine alone; each question's problem file lives in
its private ``tests/`` folder (PrairieLearn copies it to ``/grade/tests`` and never serves it); the
build refuses to put a key into the image or into what students are served.

Fast tier: the builds here ship a small stand-in engine wheel (``--wheel``), so no pip runs; the
real wheel, the Docker context with it and grading from the layout are tests/deploy/test_prairielearn.py."""

from __future__ import annotations

import hashlib
import io
import json
import tarfile
import zipfile
from pathlib import Path

import pytest
from click.testing import CliRunner

from lagrade.cli.bulk import prairielearn

REPO = Path(__file__).resolve().parents[1]
IMAGE = "physics101/lagrade-grader:2026.1"


def _engine_wheel(folder: Path, extra: dict[str, bytes] | None = None) -> Path:
    """A stand-in for the lagrade wheel: a zip with a wheel's name (``extra``: what else it holds)."""
    folder.mkdir(parents=True, exist_ok=True)
    whl = folder / "lagrade-0.1.0-py3-none-any.whl"
    with zipfile.ZipFile(whl, "w") as z:
        z.writestr("lagrade/__init__.py", "__version__ = '0.1.0'\n")
        z.writestr("lagrade-0.1.0.dist-info/entry_points.txt", "[console_scripts]\nlagrade = lagrade.cli:main\n")
        for name, data in (extra or {}).items():
            z.writestr(name, data)
    return whl


def _keys() -> set[str]:
    """The SHA-256 of every problem file and reference solution of the checkout."""
    files = [*(REPO / "problems").glob("*.toml"), *(REPO / "reference_solutions").rglob("*.py")]
    return {hashlib.sha256(f.read_bytes()).hexdigest() for f in files}


def _key_in(name: str, data: bytes, keys: set[str]) -> str | None:
    """Written apart from lagrade's own check: a problem file or reference by content or by place,
    the problem-data distribution by name or entry point, in the file or in an archive in it."""
    parts = Path(name).parts
    if hashlib.sha256(data).hexdigest() in keys:
        return f"{name}: a problem file or reference solution"
    if "reference_solutions" in parts or (len(parts) > 1 and parts[-2] == "problems" and name.endswith(".toml")):
        return f"{name}: a problem or reference folder"
    if "chapter12" in name or b"lagrade_chapter12" in data or b"lagrade.problem_data" in data:
        return f"{name}: the problem data"
    if data[:4] == b"PK\x03\x04":
        with zipfile.ZipFile(io.BytesIO(data)) as z:
            for member in z.namelist():
                if (why := _key_in(member, z.read(member), keys)):
                    return f"{name} -> {why}"
    return None


def _image_context(out: Path) -> Path:
    """The folder ``docker build`` is told to build: where the Dockerfile is."""
    (docker,) = [p for p in out.rglob("Dockerfile")]
    return docker.parent


def _build(out: Path, wheel: Path, *extra: str):
    return CliRunner().invoke(prairielearn, ["build", "-o", str(out), "--image", IMAGE, "--wheel", str(wheel), *extra])


@pytest.fixture
def built(tmp_path) -> Path:
    out = tmp_path / "pl"
    res = _build(out, _engine_wheel(tmp_path / "dist"), "--problem", "12.43")
    assert res.exit_code == 0, res.output
    return out


def test_the_image_context_holds_the_engine_alone(built):
    """Everything ``docker build`` is sent (the Dockerfile and every file beside it, wheels opened):
    no problem file, no reference solution, no problem-data wheel; nothing else to COPY."""
    context = _image_context(built)
    keys = _keys()
    found = [why for f in sorted(context.rglob("*")) if f.is_file()
             and (why := _key_in(f.relative_to(context).as_posix(), f.read_bytes(), keys))]
    assert found == []
    docker = (context / "Dockerfile").read_text()
    copied = {w for line in docker.splitlines() if line.startswith("COPY") for w in line.split()[1:-1]}
    assert copied == {"lagrade-0.1.0-py3-none-any.whl", "lagrade-pl-grade", "requirements.txt"}
    # the pinned dependencies (issue 47) are PyPI's packages, never the problem data
    assert "chapter12" not in (context / "requirements.txt").read_text().lower()
    assert sorted(p.name for p in context.iterdir()) == ["Dockerfile", "lagrade-0.1.0-py3-none-any.whl",
                                                         "lagrade-pl-grade", "requirements.txt"]
    assert "cache build" not in docker  # the reference cache is the key derived: not in a public image
    assert not (context / "questions").exists()  # the questions are not in the image's context


def test_the_question_holds_its_problem_in_its_private_tests_folder(built):
    """PrairieLearn copies a question's tests/ into the grading job at /grade/tests and never serves
    it; clientFilesQuestion/ and question.html are what students get, and hold no key."""
    q = built / "questions" / "lagrade-12.43"
    assert (q / "tests" / "problems" / "12.43.toml").read_bytes() == (REPO / "problems" / "12.43.toml").read_bytes()
    keys = _keys()
    served = [q / "question.html", *(q / "clientFilesQuestion").rglob("*")]
    assert [f for f in served if f.is_file() and _key_in(f.name, f.read_bytes(), keys)] == []
    assert json.loads((q / "info.json").read_text())["externalGradingOptions"]["image"] == IMAGE


def test_a_problem_of_the_instructors_own_goes_with_its_question(tmp_path):
    """A problem from --problems DIR is graded from its question's tests/ (the image knows no problem)."""
    extra = tmp_path / "mine"
    extra.mkdir()
    text = (REPO / "problems" / "12.43.toml").read_text().replace('id = "12.43"', 'id = "hw7.1"', 1)
    (extra / "hw7.1.toml").write_text(text)
    out = tmp_path / "pl"
    res = _build(out, _engine_wheel(tmp_path / "dist"), "--problem", "hw7.1", "--problems", str(extra))
    assert res.exit_code == 0, res.output
    assert (out / "questions" / "lagrade-hw7.1" / "tests" / "problems" / "hw7.1.toml").read_text() == text
    assert not list(_image_context(out).rglob("*.toml"))


def test_the_build_refuses_a_wheel_that_holds_the_key(tmp_path):
    """A lagrade-named wheel with the problem data in it (an engine built with the data inside) is
    refused with one line before anything is written."""
    bad = _engine_wheel(tmp_path / "dist", {
        "lagrade/problems/12.43.toml": (REPO / "problems" / "12.43.toml").read_bytes()})
    res = _build(tmp_path / "pl", bad)
    assert res.exit_code == 2, res.output
    line = res.output.strip().splitlines()[-1]
    assert "key" in line and "12.43" in line and str(bad) in line
    assert not list((tmp_path / "pl").rglob("Dockerfile"))


@pytest.mark.parametrize("planted", ["reference", "data wheel", "renamed problem", "tarball"])
def test_the_build_refuses_a_key_left_in_the_image_context(built, tmp_path, planted):
    """Whatever lies in the context is sent to docker and may be COPYed: a reference solution, the
    problem-data wheel, a problem file under another name, one in a tarball. The rebuild refuses with
    one line and leaves no Dockerfile that could be built and pushed."""
    context = _image_context(built)
    problem = (REPO / "problems" / "12.43.toml").read_bytes()
    if planted == "reference":
        (context / "answer.py").write_bytes((REPO / "reference_solutions" / "12.43" / "answer.py").read_bytes())
    elif planted == "data wheel":
        with zipfile.ZipFile(context / "lagrade_chapter12-0.1.0-py3-none-any.whl", "w") as z:
            z.writestr("lagrade_chapter12/problems/12.43.toml", problem)
    elif planted == "renamed problem":
        (context / "notes.txt").write_bytes(problem)
    else:
        with tarfile.open(context / "data.tar.gz", "w:gz") as t:
            info = tarfile.TarInfo("stuff/p.toml")
            info.size = len(problem.replace(b"12.43", b"zz.1"))
            t.addfile(info, io.BytesIO(problem.replace(b"12.43", b"zz.1")))
    res = _build(built, _engine_wheel(tmp_path / "dist2"), "--problem", "12.43")
    assert res.exit_code == 2, res.output
    line = res.output.strip().splitlines()[-1]  # the one line under click's usage
    assert line.startswith("Error: refusing to put the key into the public image") and str(context) in line, line
    assert not (context / "Dockerfile").exists()


def test_a_rebuild_removes_the_old_layouts_public_folder(tmp_path):
    """Builds before this one wrote the Dockerfile (which installed the problem data) and both wheels
    at the top of -o: a rebuild removes them, so the old `docker build pl/` finds nothing to push."""
    out = tmp_path / "pl"
    out.mkdir()
    (out / "Dockerfile").write_text("# lagrade's PrairieLearn external grader. PrairieLearn runs ...\nFROM x\n")
    (out / "lagrade_chapter12-0.1.0-py3-none-any.whl").write_bytes(b"PK old")
    (out / "lagrade-0.0.9-py3-none-any.whl").write_bytes(b"PK old")
    (out / "lagrade-pl-grade").write_text("#!/bin/sh\n")
    res = _build(out, _engine_wheel(tmp_path / "dist"))
    assert res.exit_code == 0, res.output
    assert sorted(p.name for p in out.iterdir()) == ["image", "questions"]


def test_the_check_finds_keys_by_what_they_are(tmp_path):
    from lagrade.uses.deploy.keycheck import find_keys

    (tmp_path / "ok").mkdir()
    (tmp_path / "ok" / "Dockerfile").write_text("FROM python:3.11-slim\n")
    (tmp_path / "ok" / "pyproject.toml").write_text('[project]\nname = "x"\n')  # a TOML, not a problem
    (tmp_path / "ok" / "empty.py").write_text("")
    assert find_keys(tmp_path / "ok") == []
    (tmp_path / "ok" / "Dockerfile").write_text("FROM python:3.11-slim\nRUN pip install lagrade-chapter12\n")
    assert find_keys(tmp_path / "ok") == ["Dockerfile: a Dockerfile that installs the problem-data distribution "
                                          "(lagrade-chapter12)"]
    (tmp_path / "ok" / "Dockerfile").unlink()
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as z:
        z.writestr("x-1.0.dist-info/entry_points.txt", "[lagrade.problem_data]\nx = x\n")
    (tmp_path / "ok" / "x-1.0-py3-none-any.whl").write_bytes(buf.getvalue())
    (found,) = find_keys(tmp_path / "ok")
    assert found.startswith("x-1.0-py3-none-any.whl: a problem-data package")


def test_lagrade_data_names_the_data_root(tmp_path, monkeypatch):
    """What a grader whose image holds no data is pointed at (PrairieLearn's /grade/tests): its
    problems are the only bundled ones, and its references are what the jail hides."""
    from lagrade.problem import library

    (tmp_path / "problems").mkdir()
    text = (REPO / "problems" / "12.43.toml").read_text().replace('id = "12.43"', 'id = "only.here"', 1)
    (tmp_path / "problems" / "only.here.toml").write_text(text)
    monkeypatch.delenv("LAGRADE_PROBLEMS", raising=False)
    monkeypatch.setenv("LAGRADE_DATA", str(tmp_path))
    assert library.data_root() == tmp_path.resolve()
    assert library.reference_dir() == tmp_path.resolve() / "reference_solutions"
    assert library.problem_ids() == ["only.here"] and library.load_problem("only.here").id == "only.here"
    monkeypatch.delenv("LAGRADE_DATA")
    assert library.data_root() == REPO and "12.43" in library.problem_ids()


@pytest.fixture
def refused(tmp_path, monkeypatch):
    """The platform's jail check refusing because the installed references are readable by the answer's
    uid: the reason names where they are installed."""
    from lagrade.answer.jail import kernel
    from lagrade.uses.deploy import jailcheck

    import shutil
    import tempfile

    top = Path(tempfile.mkdtemp(prefix="lagrade-install-"))  # under /tmp: nothing above it is private
    where = top / "usr" / "local" / "lib" / "python3.11" / "site-packages" / "lagrade_chapter12"
    (where / "reference_solutions").mkdir(parents=True)
    for d in [where / "reference_solutions", *where.parents][:7]:
        d.chmod(0o755)
    monkeypatch.setattr(jailcheck.os, "geteuid", lambda: 0)
    monkeypatch.setattr(kernel, "in_user_namespace", lambda: False)
    monkeypatch.setattr(jailcheck, "key_paths", lambda extra=(): [where / "reference_solutions"])
    verdict = jailcheck.decide(layers=(["uid", "no_new_privs", "limits", "seccomp"], {}, None))
    monkeypatch.setattr(jailcheck, "decide", lambda *a, **k: verdict)
    yield verdict, where
    shutil.rmtree(top, ignore_errors=True)


def test_a_refusal_names_no_install_path_to_students(refused, tmp_path, monkeypatch):
    """PrairieLearn's format_errors and Gradescope's output are a student's to read: they say why
    nothing was graded without the grader's paths; the instructor's log and extra_data keep them."""
    from lagrade.cli.bulk import gradescope
    from lagrade.uses.deploy.prairielearn import grade_job

    verdict, where = refused
    assert str(where) in verdict.lacking and "readable by other users" in verdict.lacking
    shown = verdict.for_students()
    assert "site-packages" not in shown and "/usr/" not in shown and "readable by other users" in shown

    root = tmp_path / "grade"
    (root / "data").mkdir(parents=True)
    (root / "data" / "data.json").write_text(json.dumps({"params": {"lagrade": {"problem": "12.43"}}}))
    (root / "student").mkdir()
    (root / "student" / "answer.py").write_text("H = 1\n")
    (root / "tests" / "problems").mkdir(parents=True)
    (root / "tests" / "problems" / "12.43.toml").write_bytes((REPO / "problems" / "12.43.toml").read_bytes())
    r = grade_job(root)
    assert r["gradable"] is False and "refused to run students' files" in r["format_errors"][0]
    assert "site-packages" not in json.dumps(r) and str(root) not in json.dumps(r)

    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "12.43.py").write_text("H = 1\n")
    (tmp_path / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "12.43"\n')
    res = CliRunner().invoke(gradescope, ["run", "--submission", str(tmp_path / "sub"), "--assignment",
                                          str(tmp_path / "hw.toml"), "--results", str(tmp_path / "results.json")])
    out = json.loads((tmp_path / "results.json").read_text())
    assert res.exit_code == 2 and "NOT graded" in out["output"] and "site-packages" not in out["output"], out
    assert str(where) in out["extra_data"]["jail"]["refused"]  # the instructor's, not shown to students


def test_without_paths_keeps_the_words():
    from lagrade.uses.deploy.jailcheck import without_paths

    assert without_paths("the sandbox could not start ([Errno 2] No such file: '/opt/py/bin/python3')") == \
        "the sandbox could not start ([Errno 2] No such file: 'a path of the grader's')"
    assert without_paths("mount or landlock, and no_new_privs/limits; 12.43 at 0.5 m/s") == \
        "mount or landlock, and no_new_privs/limits; 12.43 at 0.5 m/s"
