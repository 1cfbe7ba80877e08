"""An exact number too large to print is refused where it is read (issue 43, item 4).

``g*9^4999`` passed every reader bound (10 000 digits a power) and then died on Python's 4300-digit
int-to-text limit where the answer was echoed: a traceback and exit 1 from ``lagrade check`` (no JSON),
``error`` in a class and on the server, an empty preview. Every exact number an answer holds, however it
was made, is now bounded by ``MAX_NUMBER_DIGITS``, far below what Python prints, and a part over it is
``invalid`` with one line naming the bound: in text, LaTeX and ``answer.py`` alike, through the CLI, the
library, a class and the server's preview. What the engine itself prints never raises either.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

from lagrade.problem.limits import MAX_INT_ABS, MAX_NUMBER_DIGITS

#: the bound an ``answer.py``'s numbers meet: the jail's values are rebuilt with integers of 60 digits at most
PY_DIGITS = len(str(MAX_INT_ABS)) - 1

BIG = {
    "big_text.toml": 'L = "g*9^4999"\n',
    "big_latex.toml": "L = 'g \\cdot 9^{4999}'\n",
    "big_product.toml": 'L = "g*' + "*".join(["9^999"] * 5) + '"\n',  # each power small, their product not
    "big_py.py": "from lagrade.answer import *\ng = parameters('g')\nL = g*9**4999\n",
}


def _write(tmp_path: Path, name: str) -> Path:
    path = tmp_path / name
    path.write_text(BIG[name], encoding="utf-8")
    return path


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lagrade", *args], capture_output=True, text=True, timeout=120)


def _says_the_bound(feedback: str, name: str = ".toml") -> bool:
    bound = PY_DIGITS if name.endswith(".py") else MAX_NUMBER_DIGITS
    return "too large" in feedback and str(bound) in feedback and "\n" not in feedback


def test_the_bound_is_below_what_python_prints():
    assert MAX_NUMBER_DIGITS * 4 < (sys.get_int_max_str_digits() or 10**9)


#: the CLI's reproduction of the issue's line in the fast tier, every other form in the slow tier (a process each)
FORMS = [name if name == "big_text.toml" else pytest.param(name, marks=pytest.mark.slow) for name in sorted(BIG)]


@pytest.mark.parametrize("name", FORMS)
def test_check_json_is_invalid_naming_the_bound(tmp_path, name):
    proc = _run("check", "12.22", str(_write(tmp_path, name)), "--json")
    assert "Traceback" not in proc.stderr, proc.stderr[-2000:]
    assert proc.returncode == 1, proc.stderr[-2000:]
    part = {p["part"]: p for p in json.loads(proc.stdout)["parts"]}["L"]
    assert part["verdict"] == "invalid" and _says_the_bound(part["feedback"], name), part


@pytest.mark.slow
@pytest.mark.parametrize("name", ["big_text.toml", "big_py.py"])
def test_check_in_text_is_invalid_naming_the_bound(tmp_path, name):
    proc = _run("check", "12.22", str(_write(tmp_path, name)))
    assert "Traceback" not in proc.stderr + proc.stdout, proc.stderr[-2000:]
    assert proc.returncode == 1 and "invalid" in proc.stdout and "too large" in proc.stdout, proc.stdout


def test_library_check_of_the_file_and_of_a_value(tmp_path):
    from lagrade.verdicts.grade import check

    result = check("12.22", _write(tmp_path, "big_text.toml"), only=["L"])
    assert result.parts[0].verdict == "invalid" and _says_the_bound(result.parts[0].feedback)
    g = sp.Symbol("g", positive=True)
    result = check("12.22", L=g * sp.Integer(9) ** 4999, only=["L"])
    assert result.parts[0].verdict == "invalid" and _says_the_bound(result.parts[0].feedback)


def test_the_text_reader_refuses_before_multiplying():
    from lagrade.problem.notation import TextAnswerError, parse_math

    with pytest.raises(TextAnswerError, match=f"limit {MAX_NUMBER_DIGITS}"):
        parse_math("g*9^4999", ["x"])
    with pytest.raises(TextAnswerError, match=f"limit {MAX_NUMBER_DIGITS}"):
        parse_math("*".join(["9^999"] * 90), ["x"])  # 90 factors of 953 digits: never multiplied
    with pytest.raises(TextAnswerError, match=f"limit {MAX_NUMBER_DIGITS}"):
        parse_math(" + ".join(f"1/{p}^300" for p in (2, 3, 5, 7, 11, 13)), ["x"])  # denominators multiply
    assert parse_math("3^999*g", ["x"]) == 3**999 * sp.Symbol("g")  # 477 digits: read


@pytest.mark.slow
def test_a_class_grades_it_invalid_not_error(tmp_path):
    from lagrade.uses.bulk.assignment import parse_assignment
    from lagrade.uses.bulk.runner import grade_folder

    root = tmp_path / "submissions"
    for student, name in (("ann", "big_text.toml"), ("bob", "big_py.py")):
        (root / student).mkdir(parents=True)
        (root / student / ("12.22" + Path(name).suffix)).write_text(BIG[name], encoding="utf-8")
    db = tmp_path / "hw.sqlite"
    a = parse_assignment({"name": "big", "problems": [{"id": "12.22"}]})
    grade_folder(root, a, db, workers=1)
    import sqlite3

    con = sqlite3.connect(db)
    rows = con.execute("SELECT student, verdict, feedback FROM parts WHERE part = 'L'").fetchall()
    con.close()
    assert len(rows) == 2
    for student, verdict, feedback in rows:
        assert verdict == "invalid" and _says_the_bound(feedback, ".py" if student == "bob" else ".toml"), feedback


def test_the_preview_says_why():
    from lagrade.problem.library import load_problem
    from lagrade.uses.server.answers import preview

    for text in ("g*9^4999", r"g \cdot 9^{4999}"):
        shown = preview(load_problem("12.22"), "L", text)
        assert shown["error"] and _says_the_bound(shown["error"]), shown


def test_what_the_engine_prints_never_raises():
    """A number past the bound made by the engine itself (a product of the student's and the
    reference's): the echo shows something, never a ValueError."""
    from lagrade.verdicts.readback import as_latex, as_unicode

    huge = sp.Symbol("g") * sp.Integer(9) ** 4999
    for show in (as_unicode, as_latex):
        for value in (huge, [huge], {"m1": huge}):
            text = show(value)
            assert isinstance(text, str) and text
