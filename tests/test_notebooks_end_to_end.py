"""Notebooks end to end (docs/notebooks.md): the template notebook run top to bottom by a Jupyter kernel
(nbclient, headless) shows a result; a class with notebooks beside answer.py files gets the same verdicts
for the same answer. The autograder and the course server: tests/deploy/test_gradescope.py and
tests/server/test_notebooks_server.py."""

from __future__ import annotations

import ast
import json
import os
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from notebook_files import as_notebook

from lagrade.cli import main

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[1]
REFERENCE = REPO / "reference_solutions" / "12.22" / "answer.py"
WRONG = REPO / "tests" / "answers" / "12.22" / "wrong_sign_of_V.py"


def filled_template(pid: str, source: str) -> dict:
    """`lagrade template PID --notebook`, filled in as a student would from an answer.py's text: each part's
    assignment in its own cell, every other statement in the symbols' cell."""
    out = CliRunner().invoke(main, ["template", pid, "--notebook"])
    assert out.exit_code == 0, out.output
    nb = json.loads(out.output)
    tree = ast.parse(source)
    cells = {"".join(c["source"]).split(" =")[0]: c for c in nb["cells"] if c["cell_type"] == "code"}
    setup = next(c for c in nb["cells"] if c["cell_type"] == "code")
    rest = []
    for node in tree.body:
        names = [t.id for t in getattr(node, "targets", []) if isinstance(t, ast.Name)]
        text = ast.get_source_segment(source, node)
        if len(names) == 1 and names[0] in cells:
            cells[names[0]]["source"] = text
        else:
            rest.append(text)
    setup["source"] = "\n".join(rest)
    return nb


def _execute(nb: dict, cwd: Path) -> dict:
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    node = nbformat.reads(json.dumps(nb), as_version=4)
    nbclient.NotebookClient(node, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(cwd)}}
                            ).execute()
    return json.loads(nbformat.writes(node))


def shown(nb: dict) -> dict[str, str]:
    """What the last cell (the check) shows, by MIME type (a notebook keeps long text as a list of lines)."""
    (result,) = [o for o in nb["cells"][-1]["outputs"] if o["output_type"] == "execute_result"]
    return {kind: "".join(v) if isinstance(v, list) else v for kind, v in result["data"].items()}


def test_the_template_notebook_runs_top_to_bottom_and_shows_a_result(tmp_path):
    right = _execute(filled_template("12.22", REFERENCE.read_text()), tmp_path)
    last = right["cells"][-1]
    assert "lagrade-check" in last["metadata"]["tags"]
    page = shown(right)["text/html"]
    assert "Problem 12.22: 5 / 5" in page and page.count("<b>correct</b>") == 5
    assert r"$\ddot{x} = " in page and "data:image/png" not in page
    assert "total 5 / 5" in shown(right)["text/plain"]
    # the executed notebook, outputs and all, graded as a file: what the answer.py gets
    path = tmp_path / "answer.ipynb"
    path.write_text(json.dumps(right), encoding="utf-8")
    as_nb = json.loads(CliRunner().invoke(main, ["check", "12.22", str(path), "--json"]).output)
    as_py = json.loads(CliRunner().invoke(main, ["check", "12.22", str(REFERENCE), "--json"]).output)
    assert [(p["part"], p["verdict"], p["score"]) for p in as_nb["parts"]] == \
        [(p["part"], p["verdict"], p["score"]) for p in as_py["parts"]]
    assert as_nb["problems"] == []


def test_a_wrong_motion_shows_its_picture_in_the_notebook(tmp_path):
    source = REFERENCE.read_text().replace("eom = [Eq(x.diff(t, 2), xdd),", "eom = [Eq(x.diff(t, 2), -xdd),")
    wrong = _execute(filled_template("12.22", source), tmp_path)
    page = shown(wrong)["text/html"]
    assert "Problem 12.22: 5 / 5" not in page and page.count("<b>correct</b>") == 4  # eom: 2 of its 3 equations
    assert page.count('<img alt="your motion against the true one" src="data:image/png;base64,') == 1


def test_a_class_of_notebooks_and_answer_py_files(tmp_path):
    from lagrade.uses.bulk.gradebook import load_gradebook

    root = tmp_path / "submissions"
    for student, source, as_nb in (("ada", REFERENCE, False), ("bob", REFERENCE, True),
                                   ("carl", WRONG, False), ("dan", WRONG, True)):
        (root / student).mkdir(parents=True)
        if as_nb:
            as_notebook(source.read_text(), root / student / "12.22.ipynb")
        else:
            shutil.copyfile(source, root / student / "12.22.py")
    (tmp_path / "hw.toml").write_text('name = "hw"\n[[problems]]\nid = "12.22"\n', encoding="utf-8")
    db = tmp_path / "hw.sqlite"
    os.environ.setdefault("LAGRADE_NO_PROGRESS", "1")
    res = CliRunner().invoke(main, ["grade", str(root), "-a", str(tmp_path / "hw.toml"), "--db", str(db), "-j", "2",
                                    "--no-summary"])
    assert res.exit_code == 0, res.output
    book = {s.student: s for s in load_gradebook(db).students}

    def parts(student):
        return [(p["part"], p["verdict"], p["score"]) for p in book[student].problems["12.22"].parts]

    assert parts("bob") == parts("ada") and {v for _, v, _ in parts("bob")} == {"correct"}
    assert parts("dan") == parts("carl") and "incorrect" in {v for _, v, _ in parts("dan")}
