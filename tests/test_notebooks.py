"""Jupyter notebooks as answers (docs/notebooks.md): the code cells are read as an answer.py, through the
same screen and jail, and never run by the grader's process; the template notebook; the result as a
notebook shows it. The end-to-end runs (a notebook executed by a kernel, a class, the autograder, the
server) are in tests/test_notebooks_end_to_end.py and tests/server/test_notebooks_server.py."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from lagrade.answer.reading.notebook import (MAX_JSON_DEPTH, MAX_NOTEBOOK_BYTES, NotebookError, json_depth,
                                             notebook_source)
from lagrade.cli import main
from lagrade.problem.describe import notebook_text
from lagrade.problem.library import load_problem, problem_ids
from lagrade.verdicts import grade
from notebook_files import as_notebook, code, markdown, notebook

REPO = Path(__file__).resolve().parents[1]
REFERENCE = REPO / "reference_solutions" / "12.22" / "answer.py"
WRONG = REPO / "tests" / "answers" / "12.22" / "wrong_sign_of_V.py"


def _verdicts(result) -> dict[str, tuple[str, float]]:
    return {p.part: (p.verdict, p.score) for p in result.parts}


def _check(answer: Path):
    return grade.check("12.22", answer, read_as=())


# ---------------------------------------------------------------------------- reading the JSON

def test_the_code_cells_are_the_answer_and_nothing_else_is():
    nb = notebook([markdown("L = 'not code'"), code("x = 1\n"), {"cell_type": "raw", "source": "y = 2"},
                   code("%matplotlib inline\nz = 3\n!pip install foo"), code("%%bash\nrm -rf /"),
                   code("import lagrade\nlagrade.check('12.22', L=L)"), code("w = 4", metadata={"tags": ["lagrade-check"]}),
                   code("v = 5", outputs=[{"output_type": "stream", "name": "stdout", "text": "u = 6"}])])
    got = notebook_source(json.dumps(nb))
    assert got.source == "x = 1\n\nz = 3\n\nv = 5\n"
    assert got.where(3) == "cell 4, line 2" and got.where(5) == "cell 8, line 1"
    assert any("'%matplotlib inline' is an IPython command" in n and n.startswith("cell 4, line 1") for n in got.notes)
    assert any("'!pip install foo'" in n for n in got.notes)
    assert any(n.startswith("cell 5: '%%bash'") and "left out" in n for n in got.notes)


@pytest.mark.parametrize("text, says", [
    ("{", "not valid JSON (line 1)"),
    ("[1, 2]", "expected a Jupyter notebook (nbformat 4"),
    ('{"cells": {}}', "expected a Jupyter notebook"),
    ('{"cells": [], "nbformat": 3}', "a notebook of format 3 cannot be read"),
    ('{"cells": [7], "nbformat": 4}', "cell 1 is not an object"),
    ('{"cells": [{"cell_type": "code", "source": 5}], "nbformat": 4}', "cell 1's source is not text"),
    ("[" * 100_000 + "]" * 100_000, f"nests deeper than {MAX_JSON_DEPTH} levels"),
])
def test_what_is_not_a_notebook_gets_one_line(text, says):
    with pytest.raises(NotebookError) as err:
        notebook_source(text)
    assert says in str(err.value) and "\n" not in str(err.value)


def test_the_depth_is_counted_outside_strings():
    assert json_depth('{"a": ["[[[[", {"b": "]]]"}]}') == 3
    assert json_depth('{"a": "\\"[[[[\\""}') == 1


# ---------------------------------------------------------------------------- the same answer, as a notebook

@pytest.mark.parametrize("source", [REFERENCE, WRONG], ids=["reference", "wrong_sign_of_V"])
def test_a_notebook_gets_the_verdicts_of_the_same_answer_py(source, tmp_path):
    nb = as_notebook(source.read_text(), tmp_path / "answer.ipynb",
                     after=[code("import lagrade\nlagrade.check('12.22', L=L, eom=eom)")])
    as_py, as_nb = _check(source), _check(nb)
    assert _verdicts(as_nb) == _verdicts(as_py) and as_nb.score == as_py.score
    assert [p.feedback for p in as_nb.parts] == [p.feedback for p in as_py.parts]


def test_lagrade_check_reads_a_notebook(tmp_path):
    nb = as_notebook(REFERENCE.read_text(), tmp_path / "answer.ipynb", after=[code("%time x2 = 1")])
    out = CliRunner().invoke(main, ["check", "12.22", str(nb), "--json"])
    assert out.exit_code == 0, out.output
    body = json.loads(out.output)
    assert body["score"] == body["max_score"] == 5
    last = len(json.loads(nb.read_text())["cells"])
    assert body["problems"] == [f"answer.ipynb: cell {last}, line 1: '%time x2 = 1' is an IPython command, not "
                                "Python: left out of your answer"]
    text = CliRunner().invoke(main, ["check", "12.22", str(nb)])
    assert text.exit_code == 0 and "total 5 / 5" in text.output


def test_a_broken_notebook_is_exit_2_with_one_line(tmp_path):
    bad = tmp_path / "answer.ipynb"
    bad.write_text('{"cells": [', encoding="utf-8")
    out = CliRunner().invoke(main, ["check", "12.22", str(bad), "--json"])
    assert out.exit_code == 2
    body = json.loads(out.output)
    assert body["problems"] == ["answer.ipynb: not a Jupyter notebook: the file is not valid JSON (line 1)"]
    assert {p["verdict"] for p in body["parts"]} == {"invalid"}


def test_a_syntax_error_names_the_cell_and_its_line(tmp_path):
    nb = tmp_path / "answer.ipynb"
    nb.write_text(json.dumps(notebook([markdown("hi"), code("from lagrade.answer import *"),
                                       code("x, y, z = coordinates('x y z')\nL = (x*\n")])))
    result = _check(nb)
    assert any(p.startswith("answer.ipynb (cell 3, line 2): syntax error") for p in result.problems), result.problems
    assert grade.unusable(result)


# ---------------------------------------------------------------------------- hostile notebooks

@pytest.mark.parametrize("cell, says", [
    ("print(open('/etc/passwd').read())", "'open' is not allowed"),
    ("import os\nL = os.getcwd()", "import of 'os' is not allowed"),
    ("L = ().__class__.__base__.__subclasses__()", "__class__"),
])
def test_a_cell_that_reaches_out_is_refused_as_in_answer_py(cell, says, tmp_path):
    py = tmp_path / "answer.py"
    py.write_text(cell + "\n")
    nb = tmp_path / "answer.ipynb"
    nb.write_text(json.dumps(notebook([code(cell)])))
    as_py, as_nb = _check(py), _check(nb)
    assert _verdicts(as_nb) == _verdicts(as_py) and {v for v, _ in _verdicts(as_nb).values()} == {"invalid"}
    assert any(says in p for p in as_nb.problems), as_nb.problems
    assert all(p.startswith("answer.ipynb") for p in as_nb.problems)


def test_a_huge_notebook_is_refused_before_it_is_parsed(tmp_path):
    nb = tmp_path / "answer.ipynb"
    cell = code("x = 1", outputs=[{"output_type": "stream", "name": "stdout", "text": "y" * MAX_NOTEBOOK_BYTES}])
    nb.write_text(json.dumps(notebook([cell])))
    t0 = time.process_time()
    result = _check(nb)
    assert "larger than 5 MB" in result.problems[0] and grade.unusable(result)
    assert time.process_time() - t0 < 60  # a bound against hanging, not a timing claim


def test_a_code_cell_too_large_for_an_answer_is_refused_as_answer_py_is(tmp_path):
    nb = tmp_path / "answer.ipynb"
    nb.write_text(json.dumps(notebook([code("L = 1\n" + "# padding\n" * 30_000)])))
    result = _check(nb)
    assert any("larger than 200 kB" in p for p in result.problems)


def test_deep_json_is_refused_quickly(tmp_path):
    nb = tmp_path / "answer.ipynb"
    nb.write_text('{"cells": [], "metadata": ' + "[" * 1_000_000 + "]" * 1_000_000 + ', "nbformat": 4}')
    result = _check(nb)
    assert result.problems == [f"answer.ipynb: not a Jupyter notebook: its JSON nests deeper than {MAX_JSON_DEPTH} "
                               "levels"]


# ---------------------------------------------------------------------------- the template

def test_the_template_notebook(tmp_path):
    out = CliRunner().invoke(main, ["template", "12.22", "--notebook"])
    assert out.exit_code == 0, out.output
    nb = json.loads(out.output)
    nbformat = pytest.importorskip("nbformat")
    nbformat.validate(nbformat.reads(out.output, as_version=4))
    text = "".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")
    assert "Masses $m_{1}$ and $m_{2}$" in text and "x.diff(t)" in text and "x' (also x_d" in text
    codes = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    assert [c.split(" =")[0] for c in codes[1:-1]] == ["L", "eom", "a", "S_t", "a_case"]
    assert codes[-1] == "import lagrade\nlagrade.check('12.22', L=L, eom=eom, a=a, S_t=S_t, a_case=a_case)"
    path = tmp_path / "answer.ipynb"
    path.write_text(out.output, encoding="utf-8")
    result = _check(path)  # nothing filled in: every part missing, and nothing to complain of
    assert {p.verdict for p in result.parts} == {"missing"} and result.problems == []


@pytest.mark.parametrize("pid", problem_ids())
def test_every_template_notebook_is_a_notebook_that_reads(pid):
    p = load_problem(pid)
    text = notebook_text(p)
    src = notebook_source(text)
    compile(src.source, "answer.ipynb", "exec")
    for part in p.parts:
        assert f"\n{part.name} = None" in "\n" + src.source
        assert f"{part.name}={part.name}" in text


# ---------------------------------------------------------------------------- the result in Jupyter

def test_the_result_shows_the_answer_as_read_and_the_picture_of_a_wrong_motion():
    import lagrade
    from lagrade.answer import Eq, coordinates, parameters, t

    x, y, z = coordinates("x y z")
    m1, g = parameters("m1 g")
    wrong_eom = [Eq(x.diff(t, 2), g), Eq(y.diff(t, 2), 0), Eq(z.diff(t, 2), 0)]
    wrong = lagrade.check("12.22", L=None, eom=wrong_eom)
    assert wrong.verdicts()["L"] == "missing" and wrong.verdicts()["eom"] == "incorrect"
    page = wrong._repr_html_()
    assert r"<code>eom</code> = $\ddot{x} = g,\quad" in page and "<b>incorrect</b>" in page and "separates" in page
    assert page.count("data:image/png;base64,") == 1
    assert "data:image/png;base64," in wrong._repr_markdown_() and "| eom | **incorrect** |" in wrong._repr_markdown_()
    right = lagrade.check("12.22", REFERENCE)
    assert right.full_marks and "data:image/png" not in right._repr_html_()
    assert lagrade.check("12.22", eom=wrong_eom, plot=False).picture() is None


def test_the_html_never_carries_markup_from_the_answer(tmp_path):
    py = tmp_path / "answer.py"
    py.write_text("from lagrade.answer import *\nx = coordinates('x')\nL = Symbol('<script>alert(1)</script>')\n")
    import lagrade

    page = lagrade.check("12.22", py)._repr_html_()
    assert "<script>" not in page


def test_a_server_check_refuses_local_options():
    import lagrade

    with pytest.raises(TypeError, match="hints: not with server="):
        lagrade.check("12.22", "answer.py", server="http://127.0.0.1:9", hints=True)


def test_parts_are_sent_as_an_answer_py_that_rebuilds_them(tmp_path):
    """What `lagrade.check(..., server=)` uploads for parts given as sympy objects: graded here, it gives
    what the parts give."""
    import runpy

    from lagrade.uses.server.client import parts_source

    ns = runpy.run_path(str(REFERENCE))
    parts = {name: ns[name] for name in ("L", "eom", "a", "S_t", "a_case")}
    py = tmp_path / "answer.py"
    py.write_text(parts_source(parts))
    assert _verdicts(_check(py)) == _verdicts(grade.check("12.22", **parts, read_as=()))
    assert _check(py).full_marks


# ---------------------------------------------------------------------------- a class folder, an LMS download

def test_a_class_folder_and_an_lms_download_take_notebooks(tmp_path):
    from lagrade.uses.bulk.intake import import_downloads
    from lagrade.uses.bulk.layout import scan

    dl = tmp_path / "download"
    dl.mkdir()
    as_notebook(REFERENCE.read_text(), dl / "lovelaceada_101_9001_12.22.ipynb")
    (dl / "babbagebob_102_9002_hw7_12_22.ipynb").write_text(json.dumps(notebook([code("L = 1")])))
    (dl / "lovelaceada_101_9003_.ipynb_checkpoints").mkdir()
    report = import_downloads(dl, ["12.22"], tmp_path / "submissions")
    assert sorted(report.students) == ["babbagebob_102", "lovelaceada_101"], report.notes
    assert (tmp_path / "submissions" / "lovelaceada_101" / "12.22.ipynb").read_bytes() == \
        (dl / "lovelaceada_101_9001_12.22.ipynb").read_bytes()
    (tmp_path / "submissions" / "babbagebob_102" / "12.22.py").write_text("L = 2\n")
    layout = scan(tmp_path / "submissions", ["12.22"])
    assert [s.path.name for s in layout.submissions] == ["12.22.ipynb"]
    assert any("12.22.ipynb and 12.22.py were handed in for problem 12.22; keep one" in s.reason
               for s in layout.skipped), layout.skipped
