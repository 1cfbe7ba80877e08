"""Right equations of motion in many forms are accepted under every preset, chaotic scenes included
(issue 23: trajectories now refute, so no form of a right answer may be refuted by one).

The forms are built from the derived reference of every ``eom`` part of every problem: each
equation scaled by a number and by a parameter, two equations combined, the accelerations solved
for (up to two coordinates), and terms moved to the other side. Each is graded as an answer.toml
under fast, default and strict.
"""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem, problem_ids

PRESETS = ("fast", "default", "strict")


#: Parts of a scene with a general function (V(r), U(xp, yp): 12.26, 12.36, 12.39, 12.40) are left to
#: tests/test_general_functions.py: their derived reference is the problem's concrete stand-in, which an
#: answer earns only half for (a special case, issue 33).
def _eom_parts():
    for pid in problem_ids():
        problem = load_problem(pid)
        for part in problem.parts:
            if part.kind == "eom" and not part.linearized and part.reference is None \
                    and not problem.system(part.system).functions:
                yield pytest.param(pid, part.name, id=f"{pid}:{part.name}")


def _forms(pid: str, name: str) -> dict[str, list[str]]:
    problem = load_problem(pid)
    part = problem.part(name)
    mech = references(problem)[part.system]
    rows = [sp.expand(r) for r in mech.EL]
    qdd = list(mech.s.qdd)
    param = next((p for p in mech.params if any(r.has(p) for r in rows)), sp.Integer(2))
    forms: dict[str, list[sp.Basic]] = {
        "scaled": [sp.Rational(-3, 7) * r if i % 2 else 5 * param * r for i, r in enumerate(rows)],
        "other sides": [],
    }
    for r in rows:
        acc = sp.Add(*[t for t in sp.Add.make_args(r) if t.has(*qdd)])
        forms["other sides"].append(sp.Eq(acc, acc - r))
    if len(rows) >= 2:
        forms["combined"] = [rows[0] + sp.Rational(1, 2) * rows[1], *rows[1:]]
    if len(rows) <= 2:
        A, b = sp.linear_eq_to_matrix(rows, qdd)
        if A.shape[0] == A.shape[1]:
            sol = A.LUsolve(b)
            forms["solved"] = [sp.Eq(a, s) for a, s in zip(qdd, sol)]

    def text(e) -> str:
        if isinstance(e, sp.Equality):
            return f"{sp.sstr(e.lhs)} == {sp.sstr(e.rhs)}"
        return sp.sstr(e)
    return {k: [text(e) for e in v] for k, v in forms.items()}


@pytest.mark.parametrize(("pid", "name"), list(_eom_parts()))
def test_right_equations_in_every_form_pass_every_preset(tmp_path, pid, name):
    forms = _forms(pid, name)
    failures = []
    for form, rows in forms.items():
        path = tmp_path / f"{form.replace(' ', '_')}.toml"
        body = ", ".join('"' + r.replace('"', '\\"') + '"' for r in rows)
        path.write_text(f"{name} = [{body}]\n")
        for accuracy in PRESETS:
            result = lagrade.check(pid, path, accuracy=accuracy)
            part = next(p for p in result.parts if p.part == name)
            if part.verdict != "correct":
                failures.append(f"{form} under {accuracy}: {part.verdict}: {part.feedback}")
    assert not failures, "\n".join(failures)


def _lagrangian_parts():
    for pid in problem_ids():
        problem = load_problem(pid)
        for part in problem.parts:
            if part.kind == "lagrangian" and part.reference is None and not problem.system(part.system).functions:
                yield pytest.param(pid, part.name, id=f"{pid}:{part.name}")


@pytest.mark.parametrize(("pid", "name"), list(_lagrangian_parts()))
def test_right_lagrangians_in_other_gauges_pass_every_preset(tmp_path, pid, name):
    """L, L + a constant, L + dF/dt for F(q, t) = t*sin(q1): the same motion under every preset."""
    problem = load_problem(pid)
    part = problem.part(name)
    mech = references(problem)[part.system]
    q, qd, t = mech.s.q[0], mech.s.qd[0], sp.Symbol("t")
    forms = {"as derived": mech.L, "plus a constant": mech.L + 7,
             "plus dF/dt": mech.L + sp.sin(q) + t * sp.cos(q) * qd}
    failures = []
    for form, L in forms.items():
        path = tmp_path / "answer.toml"
        path.write_text(f'{name} = "{sp.sstr(sp.expand(L))}"\n')
        for accuracy in PRESETS:
            part_result = next(p for p in lagrade.check(pid, path, accuracy=accuracy).parts if p.part == name)
            if part_result.verdict != "correct":
                failures.append(f"{form} under {accuracy}: {part_result.verdict}: {part_result.feedback}")
    assert not failures, "\n".join(failures)
