"""The PrairieLearn external grader: the build folder, the example question, the entry point on a
fake /grade tree (right, wrong, broken, hostile, misconfigured), every file checked against a schema."""

from __future__ import annotations

import base64
import json
import os
import runpy
import subprocess
import sys
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
    res = CliRunner().invoke(prairielearn, ["build", "-o", str(out), "--problem", "12.43"])
    assert res.exit_code == 0, res.output
    return out


def _question(built: Path) -> Path:
    return built / "questions" / "lagrade-12.43"


def job(built: Path, root: Path, files: dict[str, bytes], params: dict | None = None) -> Path:
    """A /grade tree as PrairieLearn makes it: data.json from the example question's server.py."""
    data = {"params": {}, "correct_answers": {}, "submitted_answers": {}}
    runpy.run_path(str(_question(built) / "server.py"))["generate"](data)
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
    proc = subprocess.run(["sh", str(built / "lagrade-pl-grade")], env=env, capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr
    results = json.loads((root / "results" / "results.json").read_text())
    jsonschema.validate(results, RESULTS_SCHEMA)
    return results


def test_the_build_folder_and_the_question(built):
    info = json.loads((_question(built) / "info.json").read_text())
    jsonschema.validate(info, INFO_SCHEMA)
    assert info["gradingMethod"] == "External"
    docker = (built / "Dockerfile").read_text()
    wheel, data_wheel = next(built.glob("lagrade-*.whl")).name, next(built.glob("lagrade_chapter12-*.whl")).name
    assert f"COPY {wheel} {data_wheel} /tmp/" in docker and f"/tmp/{data_wheel} &&" in docker and f"COPY lagrade-pl-grade {info['externalGradingOptions']['entrypoint']}" in docker
    # the key is the grader's uid's alone in the image: problem data and cache 0700 after the cache is built
    assert docker.index("cache build") < docker.index("chmod 0700 \"$d\"") and "data_root()" in docker
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
