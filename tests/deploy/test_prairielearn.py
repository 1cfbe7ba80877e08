"""The PrairieLearn external grader: the build folder (a public image's context holding the engine
alone), the example question (its problem file in its private tests/), the entry point on a fake
/grade tree laid out as PrairieLearn lays it out (right, wrong, broken, hostile, misconfigured),
every file checked against a schema."""

from __future__ import annotations

import ast
import base64
import json
import os
import uuid
import re
import runpy
import subprocess
import sys
import zipfile
from html.parser import HTMLParser
from pathlib import Path

import jsonschema
import pytest
from click.testing import CliRunner

from lagrade.cli.bulk import prairielearn

REPO = Path(__file__).resolve().parents[2]
HERE = Path(__file__).parent
INFO_SCHEMA = json.loads((HERE / "prairielearn_info_question.schema.json").read_text())
RESULTS_SCHEMA = json.loads((HERE / "prairielearn_results.schema.json").read_text())


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("pl") / "grader"
    res = CliRunner().invoke(prairielearn, ["build", "-o", str(out), "--problem", "12.43", "--image", IMAGE])
    assert res.exit_code == 0, res.output
    return out


IMAGE = "physics101/lagrade-grader:2026.1"


def _question(built: Path) -> Path:
    return built / "questions" / "lagrade-12.43"


def job(built: Path, root: Path, files: dict[str, bytes], params: dict | None = None,
        question: Path | None = None) -> Path:
    """A /grade tree as PrairieLearn makes it: data.json from the question's server.py, the question's
    tests/ folder copied to tests/ (the example question's unless ``question`` is given)."""
    import shutil

    question = question or _question(built)
    data = {"params": {}, "correct_answers": {}, "submitted_answers": {}}
    runpy.run_path(str(question / "server.py"))["generate"](data)
    if (question / "tests").is_dir():
        shutil.copytree(question / "tests", root / "tests")
    if params is not None:
        data["params"]["lagrade"] = params
    (root / "data").mkdir(parents=True)
    (root / "data" / "data.json").write_text(json.dumps(data))
    (root / "student").mkdir()
    for name, content in files.items():
        (root / "student" / name).write_bytes(content)
    return root


def grade(built: Path, root: Path) -> dict:
    """Run the image's entry script (with this Python on PATH in place of the image's)."""
    env = {**os.environ, "LAGRADE_GRADE_ROOT": str(root),
           "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    proc = subprocess.run(["sh", str(built / "image" / "lagrade-pl-grade")], env=env, capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr
    results = json.loads((root / "results" / "results.json").read_text())
    jsonschema.validate(results, RESULTS_SCHEMA)
    return results


def test_the_build_folder_and_the_question(built):
    info = json.loads((_question(built) / "info.json").read_text())
    jsonschema.validate(info, INFO_SCHEMA)
    assert info["gradingMethod"] == "External"
    docker = (built / "image" / "Dockerfile").read_text()
    (wheel,) = [p.name for p in (built / "image").glob("*.whl")]
    assert wheel.startswith("lagrade-") and f"COPY {wheel} /tmp/" in docker
    assert f"COPY lagrade-pl-grade {info['externalGradingOptions']['entrypoint']}" in docker
    # the image is public: the engine alone (it used to install the problem data and build the reference
    # cache, then chmod them 0700, which protects a running container but not anyone who pulls the image)
    from lagrade.uses.deploy.keycheck import find_keys

    assert find_keys(built / "image") == [] and "chapter12" not in docker and "cache build" not in docker
    assert not list(built.rglob("lagrade_chapter12-*.whl"))
    with zipfile.ZipFile(built / "image" / wheel) as z:  # the real engine wheel: no problem, no reference
        assert not [n for n in z.namelist() if n.endswith(".toml") or "reference_solutions" in n]
    assert (_question(built) / "tests" / "problems" / "12.43.toml").read_bytes() == \
        (REPO / "problems" / "12.43.toml").read_bytes()
    data = {"params": {}}
    runpy.run_path(str(_question(built) / "server.py"))["generate"](data)
    assert data["params"]["lagrade"]["problem"] == "12.43"

    class Tags(HTMLParser):
        def __init__(self):
            super().__init__()
            self.tags: dict[str, dict] = {}

        def handle_starttag(self, tag, attrs):
            self.tags.setdefault(tag, dict(attrs))

    tags = Tags()
    tags.feed((_question(built) / "question.html").read_text())
    assert tags.tags["pl-file-editor"]["file-name"] == data["params"]["lagrade"]["file"]
    assert {"pl-question-panel", "pl-submission-panel", "pl-external-grader-results"} <= set(tags.tags)


def _deprecated(value, schema: dict, where: str = "") -> list[str]:
    """The properties of ``value`` that ``schema`` marks ``"deprecated": true``."""
    found = []
    for key, sub in (schema.get("properties") or {}).items():
        if isinstance(value, dict) and key in value:
            if sub.get("deprecated"):
                found.append(f"{where}{key}")
            found += _deprecated(value[key], sub, f"{where}{key}.")
    return found


def test_info_json_names_the_pushed_image_and_nothing_deprecated(built):
    """The image is the one given (PrairieLearn pulls it from a public registry), and no field the
    current PrairieLearn schema marks deprecated (externalGradingOptions.enabled) is written."""
    info = json.loads((_question(built) / "info.json").read_text())
    assert info["externalGradingOptions"]["image"] == IMAGE
    assert _deprecated(info, INFO_SCHEMA) == []
    assert _deprecated({"externalGradingOptions": {"enabled": True}}, INFO_SCHEMA) == ["externalGradingOptions.enabled"]
    assert f"-t {IMAGE} --push" in (built / "image" / "Dockerfile").read_text() and "--platform linux/amd64" in \
        (built / "image" / "Dockerfile").read_text()


@pytest.mark.parametrize("image", ["lagrade-prairielearn:latest", "lagrade-prairielearn", "myhost.edu:5000/me/grader",
                                   "Physics101/Grader", "registry.example.org/me/grader:1"])
def test_an_image_prairielearn_cannot_pull_is_refused(tmp_path, image):
    res = CliRunner().invoke(prairielearn, ["build", "-o", str(tmp_path / "out"), "--image", image])
    assert res.exit_code == 2 and "Docker Hub" in res.output and not (tmp_path / "out").exists(), res.output


@pytest.mark.parametrize("image", ["me/grader", "me/lagrade-grader:2026.1", "docker.io/me/grader:1",
                                   "ghcr.io/physics-dept/lagrade:v1", "quay.io/org/img:tag",
                                   "registry.gitlab.com/group/project/img:t", "public.ecr.aws/alias/img:1"])
def test_images_on_the_registries_prairielearn_pulls_from_are_taken(image):
    from lagrade.uses.deploy.prairielearn import check_image

    assert check_image(image) == image


def test_the_question_says_the_assumptions_and_symbols_and_offers_the_template(built):
    """Students on PrairieLearn have no ``lagrade show`` or ``lagrade template``: the page says what
    ``lagrade show`` says, and the template is a client file the page offers for download."""
    from lagrade.problem.describe import template_text
    from lagrade.problem.library import load_problem

    problem = load_problem("12.43")
    html = (_question(built) / "question.html").read_text()
    text = html_unescape(html)
    for assumption in problem.assumptions:
        assert assumption in text
    for symbol in [q.name for q in problem.parameters] + [c.name for s in problem.systems for c in s.coordinates]:
        assert f"\n  {symbol} " in text or f"\n  {symbol}(t) " in text, symbol
    for part in problem.parts:
        assert f"\n  {part.name} " in text
    assert "{{" not in html and "}}" not in html  # question.html is a Mustache template
    template = _question(built) / "clientFilesQuestion" / "answer.py"
    assert template.read_text() == template_text(problem)
    ast.parse(template.read_text())

    class Tags(HTMLParser):
        def __init__(self):
            super().__init__()
            self.tags: list[tuple[str, dict]] = []
            self.editor = ""
            self._in = None

        def handle_starttag(self, tag, attrs):
            self.tags.append((tag, dict(attrs)))
            self._in = tag

        def handle_data(self, data):
            if self._in == "pl-file-editor":
                self.editor += data

        def handle_endtag(self, tag):
            self._in = None

    tags = Tags()
    tags.feed(html)
    (download,) = [a for t, a in tags.tags if t == "pl-file-download"]
    assert download["file-name"] == "answer.py" and "directory" not in download  # clientFilesQuestion, the default
    (panel,) = [i for i, (t, _) in enumerate(tags.tags) if t == "pl-question-panel"]
    assert tags.tags.index(("pl-file-download", download)) > panel
    assert tags.editor.strip() == template_text(problem).strip()  # the editor starts from the same template


def html_unescape(html: str) -> str:
    from html import unescape

    return unescape(html)


def test_question_uuids_are_unique_per_build_and_kept_by_a_rebuild(built, tmp_path):
    """Two builds give two UUIDs (two copies in one course do not collide); a rebuild into the same
    folder keeps its UUID (PrairieLearn knows the question by it); ``--uuid-seed`` reproduces one."""
    def build(out, *extra):
        res = CliRunner().invoke(prairielearn, ["build", "-o", str(out), "--image", IMAGE, *extra])
        assert res.exit_code == 0, res.output
        return json.loads((out / "questions" / "lagrade-12.43" / "info.json").read_text())["uuid"]

    first = json.loads((_question(built) / "info.json").read_text())["uuid"]
    second = build(tmp_path / "b")
    assert first != second
    assert uuid.UUID(first).version == 4 and uuid.UUID(second).version == 4  # PrairieLearn asks for UUID v4
    assert build(tmp_path / "b") == second
    from lagrade.uses.deploy.prairielearn import question_files

    def seeded(seed):
        return json.loads(question_files("12.43", image=IMAGE, uuid_seed=seed)["info.json"])["uuid"]

    fall = seeded("physics 101, fall 2026")
    assert fall == seeded("physics 101, fall 2026") != seeded("physics 101, spring 2027")
    assert uuid.UUID(fall).version == 4 and fall not in (first, second)
    assert build(tmp_path / "b", "--uuid-seed", "physics 101, fall 2026") == fall  # the seed wins over the kept one


def test_the_schemas_are_not_vacuous():
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"gradable": True, "score": 2}, RESULTS_SCHEMA)       # score in [0, 1]
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"gradable": False}, RESULTS_SCHEMA)                  # says why
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"uuid": "x", "type": "v3", "title": "t", "topic": "t"}, INFO_SCHEMA)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"uuid": "0" * 8 + "-0000-0000-0000-" + "0" * 12, "type": "v3", "title": "t", "topic": "t",
                             "externalGradingOptions": {"image": "x"}}, INFO_SCHEMA)  # no entrypoint


def test_a_right_answer(built, tmp_path):
    r = grade(built, job(built, tmp_path / "grade", {
        "answer.py": (REPO / "reference_solutions/12.43/answer.py").read_bytes()}))
    assert r["gradable"] and r["score"] == 1 and r["images"] == []
    assert [t["name"] for t in r["tests"]] == ["H", "hamilton", "eom"]
    assert all(t["points"] == t["max_points"] for t in r["tests"])


def test_a_wrong_answer_gets_its_plot(built, tmp_path):
    r = grade(built, job(built, tmp_path / "grade", {
        "answer.py": (REPO / "tests/answers/12.43/wrong_sign_of_V.py").read_bytes()}))
    assert r["gradable"] and 0 < r["score"] < 1
    assert r["score"] == pytest.approx(sum(t["points"] for t in r["tests"]) / sum(t["max_points"] for t in r["tests"]))
    (image,) = r["images"]
    assert image["url"].startswith("data:image/png;base64,")
    assert base64.b64decode(image["url"].split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    assert not any(t["message"].lower().startswith(t["description"] + ":") for t in r["tests"])


def test_a_notebook_is_graded_as_the_same_answer_py(built, tmp_path):
    """A student who submits the Jupyter notebook they worked in: its code cells, in the same jail."""
    sys.path.insert(0, str(REPO / "tests"))
    from notebook_files import as_notebook

    for source in (REPO / "reference_solutions/12.43/answer.py", REPO / "tests/answers/12.43/wrong_sign_of_V.py"):
        nb = as_notebook(source.read_text(), tmp_path / "answer.ipynb").read_bytes()
        as_nb = grade(built, job(built, tmp_path / f"nb-{source.stem}", {"answer.ipynb": nb}))
        as_py = grade(built, job(built, tmp_path / f"py-{source.stem}", {"answer.py": source.read_bytes()}))
        assert as_nb["gradable"] and as_nb["score"] == as_py["score"]
        assert [(t["name"], t["points"]) for t in as_nb["tests"]] == [(t["name"], t["points"]) for t in as_py["tests"]]


def test_a_broken_file_is_not_gradable(built, tmp_path):
    r = grade(built, job(built, tmp_path / "grade", {"answer.py": b"from sympy import *\nH = (m*\n"}))
    assert r["gradable"] is False and r["format_errors"] and "syntax" in " ".join(r["format_errors"]).lower()


def test_a_hostile_file_is_contained(built, tmp_path):
    sentinel = tmp_path / "pwned"
    r = grade(built, job(built, tmp_path / "grade", {
        "answer.py": f"import os\nos.system('touch {sentinel}')\nH = 1\n".encode()}))
    assert not sentinel.exists()
    assert r["gradable"] is False or r["score"] == 0


@pytest.mark.parametrize("files, params, says", [
    ({}, None, "no file answer.py"),
    ({"answer.py": b"H = 1\n"}, {"problem": "no.such"}, "set up wrongly"),
    ({"answer.py": b"H = 1\n"}, {"problem": "12.43", "file": "../../etc/passwd"}, "set up wrongly"),
])
def test_what_cannot_be_graded_is_said(built, tmp_path, files, params, says):
    r = grade(built, job(built, tmp_path / "grade", files, params))
    assert r["gradable"] is False and says in " ".join(r["format_errors"])


def test_the_grader_reads_the_problem_from_grade_tests(tmp_path):
    """The image knows no problem: the grader reads the question's tests/ (at /grade/tests), makes it
    private before any answer runs, and says so when it is missing. A problem of the instructor's own,
    present nowhere else, is graded from there."""
    extra = tmp_path / "mine"
    extra.mkdir()
    text = (REPO / "problems/12.43.toml").read_text().replace('id = "12.43"', 'id = "hw7.1"', 1)
    (extra / "hw7.1.toml").write_text(text)
    out = tmp_path / "pl"
    res = CliRunner().invoke(prairielearn, ["build", "-o", str(out), "--problem", "hw7.1", "--problems", str(extra),
                                            "--image", IMAGE])
    assert res.exit_code == 0, res.output
    question = out / "questions" / "lagrade-hw7.1"
    root = job(out, tmp_path / "grade", {"answer.py": (REPO / "reference_solutions/12.43/answer.py").read_bytes()},
               question=question)
    (root / "tests").chmod(0o755)
    r = grade(out, root)
    assert r["gradable"] and r["score"] == 1, r
    for made_private in (root / "tests", root / "tests" / "problems" / "hw7.1.toml"):
        assert os.stat(made_private).st_mode & 0o077 == 0
    import shutil

    shutil.rmtree(root / "tests")
    (root / "results" / "results.json").unlink()
    r = grade(out, root)
    assert r["gradable"] is False and "tests/" in r["format_errors"][0], r


def test_the_image_pins_its_base_and_dependencies(built):
    """Issue 47: ``FROM python:3.11-slim`` and an unpinned ``pip install`` of the wheel: a rebuild got
    whatever Python and PyPI held that day."""
    from lagrade.uses.deploy.pins import BASE_IMAGE, PINNED_IMAGE, requirements_txt

    docker = (built / "image" / "Dockerfile").read_text()
    (base,) = re.findall(r"^FROM (\S+)$", docker, flags=re.MULTILINE)
    assert base == BASE_IMAGE and PINNED_IMAGE.match(base), base
    assert (built / "image" / "requirements.txt").read_text() == requirements_txt()
    assert "pip install --no-cache-dir -r /tmp/requirements.txt" in docker and "--no-deps /tmp/lagrade-" in docker
