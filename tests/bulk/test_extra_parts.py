"""A class graded in bulk (issue 33): a part the book does not ask (`extra = true`) is graded and stored,
but counts in a student's points only when the assignment's `parts` names it."""

from __future__ import annotations

from lagrade.uses.bulk.assignment import load_assignment
from lagrade.uses.bulk.gradebook import load_gradebook
from lagrade.uses.bulk.runner import grade_folder

#: 12.36's book question (H and Hamilton's equations with a general V(x)); H_F, hamilton_F not given
ANSWER = """\
from lagrade.answer import *
m = parameters("m")
x = coordinates("x")
p_x = momenta("p_x")
V = Function("V")
H = p_x**2 / (2 * m) + V(x)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -V(x).diff(x))]
"""


def _points(tmp_path, parts: str) -> tuple[float, float, set[str]]:
    root = tmp_path / "submissions"
    (root / "ada").mkdir(parents=True, exist_ok=True)
    (root / "ada" / "12.36.py").write_text(ANSWER)
    hw = tmp_path / "hw.toml"
    hw.write_text(f'[[problems]]\nid = "12.36"\nweight = 10\n{parts}')
    db = tmp_path / "hw.sqlite"
    grade_folder(root, load_assignment(hw), db, workers=1)
    grade = load_gradebook(db).student("ada").problems["12.36"]
    return grade.points, grade.possible, {p["part"] for p in grade.parts if p["extra"]}


def test_an_extra_counts_only_when_the_assignment_names_it(tmp_path):
    assert _points(tmp_path / "plain", "") == (10.0, 10.0, {"H_F", "hamilton_F"})
    asked = 'parts = { H = 1, hamilton = 1, H_F = 1, hamilton_F = 1 }\n'
    assert _points(tmp_path / "asked", asked) == (5.0, 10.0, {"H_F", "hamilton_F"})
