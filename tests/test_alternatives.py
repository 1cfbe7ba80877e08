"""Admissible formulations (issue 21): a part right in any of them gets full credit, its feedback names
the one used, a part that `follows` another is judged in the student's own formulation, and nothing of
it reveals a reference value."""

from __future__ import annotations

import pytest
import sympy as sp
from leaks import reveals

import lagrade
from lagrade.problem.describe import show_text
from lagrade.problem.library import load_problem
from lagrade.problem.spec import Problem, SpecError, load_problem_file
from lagrade.verdicts.verdict_memo import VerdictMemo

t = sp.Symbol("t")
m, k, g, a0, l0 = sp.symbols("m k g a0 l0")
x, p_x = sp.Function("x")(t), sp.Function("p_x")(t)

GROUND_H = p_x**2 / (2 * m) + a0 * t * p_x + k * x**2 / 2 + m * g * (a0 * t**2 / 2 - l0 - x)
ELEVATOR_H = p_x**2 / (2 * m) + k * x**2 / 2 - m * (g + a0) * x
ELEVATOR_HAMILTON = [sp.Eq(x.diff(t), p_x / m), sp.Eq(p_x.diff(t), m * (g + a0) - k * x)]


def _without_alternatives(problem: Problem) -> Problem:
    """The same problem with every part graded in its primary formulation only."""
    data = problem.model_dump()
    for part in data["parts"]:
        part["alternatives"], part["follows"] = [], None
    return Problem.model_validate(data)


def test_an_answer_right_in_an_alternative_gets_full_credit_and_is_told_which():
    result = lagrade.check("12.47", H=ELEVATOR_H, hamilton=ELEVATOR_HAMILTON)
    parts = {p.part: p for p in result.parts}
    for name in ("H", "hamilton"):
        assert parts[name].verdict == "correct", parts[name].feedback
        assert "elevator-frame Lagrangian" in parts[name].feedback
    # the guard is the alternative itself: graded in the primary formulation alone, both are wrong
    bare = lagrade.check(_without_alternatives(load_problem("12.47")), H=ELEVATOR_H, hamilton=ELEVATOR_HAMILTON)
    assert {p.part: p.verdict for p in bare.parts}["H"] == "incorrect"
    assert {p.part: p.verdict for p in bare.parts}["hamilton"] in ("partial", "incorrect")


def test_the_primary_formulation_is_named_too_when_the_systems_differ():
    part = {p.part: p for p in lagrade.check("12.47", H=GROUND_H).parts}["H"]
    assert part.verdict == "correct" and "ground-frame Lagrangian" in part.feedback


def test_right_in_none_gives_the_primary_feedback():
    wrong = p_x**2 / (2 * m) + k * x**2 / 2 - m * g * x  # the inertial force forgotten: right in neither frame
    with_alt = {p.part: p for p in lagrade.check("12.47", H=wrong).parts}["H"]
    bare = {p.part: p for p in lagrade.check(_without_alternatives(load_problem("12.47")), H=wrong).parts}["H"]
    assert with_alt.verdict == bare.verdict == "incorrect"
    assert with_alt.feedback == bare.feedback


def test_an_answer_the_primary_cannot_read_gets_the_feedback_of_the_formulation_that_reads_it():
    y = sp.Function("y")(t)
    M, g_, l_, phi = sp.symbols("M g l phi")
    block = M * y.diff(t) ** 2 / 2 - M * g_ * (l_ - y) * sp.sin(phi)  # ex12.6 (b) without the rotation
    parts = {p.part: p for p in lagrade.check("ex12.6", L=block).parts}
    assert parts["L_b"].verdict == "incorrect"  # L in y is the exercise's (b) (issue 33: both are asked)
    assert "rotational kinetic energy" in parts["L_b"].feedback
    assert parts["L_a"].verdict == "missing" and "graded as L_b" in parts["L_a"].feedback


@pytest.mark.parametrize("H, answer, verdict", [
    (ELEVATOR_H, True, "correct"),
    (ELEVATOR_H, False, "incorrect"),
    (GROUND_H, False, "correct"),
    (GROUND_H, True, "incorrect"),
])
def test_a_following_part_is_judged_for_the_students_own_formulation(H, answer, verdict):
    parts = {p.part: p for p in lagrade.check("12.47", H=H, H_conserved=answer, H_is_E=answer).parts}
    assert parts["H"].verdict == "correct"
    assert parts["H_conserved"].verdict == verdict and parts["H_is_E"].verdict == verdict
    assert "Judged for the formulation of your H" in parts["H_conserved"].feedback


def test_a_following_part_falls_back_to_the_primary_and_says_so():
    parts = {p.part: p for p in lagrade.check("12.47", H_conserved=True).parts}
    assert parts["H_conserved"].verdict == "incorrect"  # the ground-frame H is not conserved
    assert "stated formulation" in parts["H_conserved"].feedback


def test_grading_one_following_part_grades_what_it_follows():
    from lagrade.answer.reading.load import LoadedAnswer
    from lagrade.verdicts.grade import grade_values

    problem = load_problem("12.47")
    answer = LoadedAnswer(values={"H": ELEVATOR_H, "H_conserved": True})
    result = grade_values(problem, answer, only=["H_conserved"])
    assert [p.part for p in result.parts] == ["H_conserved"]
    assert result.parts[0].verdict == "correct"


def test_the_verdict_memo_keeps_a_following_part_apart_per_formulation():
    from lagrade.answer.reading.load import LoadedAnswer
    from lagrade.verdicts.grade import grade_values

    problem, memo = load_problem("12.47"), VerdictMemo()
    verdicts = []
    for H in (ELEVATOR_H, GROUND_H):  # the same H_conserved value, two formulations
        result = grade_values(problem, LoadedAnswer(values={"H": H, "H_conserved": True}), memo=memo)
        verdicts.append({p.part: p.verdict for p in result.parts}["H_conserved"])
    assert verdicts == ["correct", "incorrect"]


def test_a_followed_part_is_memoized_with_its_formulation(monkeypatch):
    from lagrade.answer.reading.load import LoadedAnswer
    from lagrade.verdicts.checkers import CHECKERS
    from lagrade.verdicts.grade import grade_values

    calls = []
    for kind, checker in list(CHECKERS.items()):
        monkeypatch.setitem(CHECKERS, kind, lambda ctx, part, value, _c=checker: calls.append(part.name) or _c(ctx, part, value))
    problem, memo = load_problem("12.47"), VerdictMemo()
    answer = {"H": ELEVATOR_H, "H_conserved": True, "H_is_E": True}
    first = grade_values(problem, LoadedAnswer(values=dict(answer)), read_as=(), memo=memo)
    made = len(calls)
    again = grade_values(problem, LoadedAnswer(values=dict(answer)), read_as=(), memo=memo)
    assert len(calls) == made and memo.hits == 3  # nothing checked again, the formulation of H kept too
    assert [p.model_dump() for p in again.parts] == [p.model_dump() for p in first.parts]
    assert {p.part: p.verdict for p in again.parts}["H_conserved"] == "correct"


def test_a_planar_answer_is_graded_in_the_planar_formulation_and_cyclic_follows_it():
    X, Y, r, th = (sp.Function(n)(t) for n in ("X", "Y", "r", "theta"))
    pX, pY, pr, pth = (sp.Function(f"p_{n}")(t) for n in ("X", "Y", "r", "theta"))
    m1, m2, k_, l0_ = sp.symbols("m1 m2 k l0")
    M, mu = m1 + m2, m1 * m2 / (m1 + m2)
    hamilton = [sp.Eq(X.diff(t), pX / M), sp.Eq(Y.diff(t), pY / M), sp.Eq(r.diff(t), pr / mu),
                sp.Eq(th.diff(t), pth / (mu * r**2)), sp.Eq(pX.diff(t), 0), sp.Eq(pY.diff(t), 0),
                sp.Eq(pr.diff(t), pth**2 / (mu * r**3) - k_ * (r - l0_)), sp.Eq(pth.diff(t), 0)]
    parts = {p.part: p for p in lagrade.check("12.37", hamilton=hamilton, cyclic=["X", "Y", "theta"], dof=6).parts}
    assert parts["hamilton"].verdict == "correct" and "planar" in parts["hamilton"].feedback
    assert parts["cyclic"].verdict == "correct"
    three_d = {p.part: p for p in lagrade.check("12.37", cyclic=["X", "Y", "theta"], dof=5).parts}
    assert three_d["cyclic"].verdict == "partial"  # no planar hamilton: judged in 3-D, where Z is cyclic too
    assert three_d["dof"].verdict == "correct" and "fixed plane" in three_d["dof"].feedback


def test_feedback_of_every_formulation_reveals_no_reference():
    wrong_elevator = p_x**2 / (2 * m) + k * x**2 / 2 - m * g * x
    for pid, parts in [("12.47", {"H": wrong_elevator, "H_conserved": False, "H_is_E": True}),
                       ("12.47", {"H": ELEVATOR_H, "H_conserved": False, "H_is_E": False})]:
        for part in lagrade.check(pid, **parts).parts:
            assert reveals(pid, part.feedback) == [], (part.part, part.feedback)
    for pid in ("12.5", "12.6", "ex12.6", "12.19", "12.27", "12.37", "12.47"):  # the rows of the parts
        rows = show_text(load_problem(pid)).split("Parts (bind these names in answer.py):")[1]
        rows = rows.split("\n\nTyping an answer")[0]  # the spellings of the coordinates' rates, no value
        assert reveals(pid, rows) == [], pid


def _gauge_shifted(F):
    """The ground-frame H of 12.47 after L -> L + dF(x, t)/dt: H(x, p - dF/dx, t) - dF/dt."""
    X, P = sp.symbols("X P")
    H = GROUND_H.subs({x: X, p_x: P}).subs(P, P - sp.diff(F(X), X)) - sp.diff(F(X), t)
    rates = [sp.Eq(x.diff(t), sp.diff(H, P)), sp.Eq(p_x.diff(t), -sp.diff(H, X))]
    back = {X: x, P: p_x}
    return H.subs(back), [sp.Eq(e.lhs, e.rhs.subs(back)) for e in rates]


@pytest.mark.parametrize("F", [lambda X: m * (a0 - g) * t * X, lambda X: X**3 * sp.sin(t) + 2 * X * t**2])
def test_the_hamiltonian_of_any_gauge_is_accepted_and_said_so(F):
    H, hamilton = _gauge_shifted(F)
    parts = {p.part: p for p in lagrade.check("12.47", H=H, hamilton=hamilton, H_conserved=False).parts}
    for name in ("H", "hamilton"):
        assert parts[name].verdict == "correct", parts[name].feedback
        assert "dF(q, t)/dt" in parts[name].feedback
    # no answer is stated for another gauge: the booleans are judged in the primary formulation, and say so
    assert parts["H_conserved"].verdict == "correct" and "another admissible Lagrangian" in parts["H_conserved"].feedback
    bare = {p.part: p.verdict for p in lagrade.check(_without_alternatives(load_problem("12.47")), H=H).parts}
    assert bare["H"] == "incorrect"  # the guard: without the gauge formulation, refused


def test_a_scaled_lagrangians_hamiltonian_is_no_gauge():
    """2*L gives the true motion of x but is not admissible (L = T - V fixes the scale)."""
    H = p_x**2 / (4 * m) + k * x**2 - 2 * m * (g + a0) * x
    hamilton = [sp.Eq(x.diff(t), p_x / (2 * m)), sp.Eq(p_x.diff(t), 2 * m * (g + a0) - 2 * k * x)]
    verdicts = {p.part: p.verdict for p in lagrade.check("12.47", H=H, hamilton=hamilton).parts}
    assert verdicts["H"] == "incorrect" and verdicts["hamilton"] != "correct"


def test_rates_that_no_hamiltonian_generates_are_refused():
    from lagrade.verdicts.checkers.gauge import _is_hamiltonian
    from lagrade.verdicts.grade import references
    from lagrade.compare.sampling import rng_for, sample_points

    mech = references(load_problem("12.37"))["planar"]
    pX, pY, pr, pth = mech.s.p
    pts = sample_points(mech, 6, rng_for("test", "gauge"))
    moms = [pts.values[q] for q in mech.s.q]  # any phase points will do
    free = [pX, pY, pr, pth]
    assert _is_hamiltonian(free, [0, 0, 0, 0], mech, pts, [], moms)          # H = |p|**2/2
    assert not _is_hamiltonian(free, [pY, 0, 0, 0], mech, pts, [], moms)     # p_X' = p_Y: no H gives it


def _alternative_mistakes():
    from lagrade.problem.library import problem_ids

    for pid in problem_ids():
        try:
            problem = load_problem(pid)
        except SpecError:  # a problem file being edited elsewhere: its own tests say so
            continue
        for part in problem.parts:
            for i, alt in enumerate(part.alternatives):
                for k, _ in enumerate(alt.mistakes):
                    yield pytest.param(pid, part.name, i, k, id=f"{pid}-{part.name}-{i}-{k}")


@pytest.mark.parametrize("pid, name, i, k", list(_alternative_mistakes()))
def test_a_named_mistake_of_an_alternative_is_recognised_in_its_formulation(pid, name, i, k):
    """As tests/test_named_mistakes.py for the primary's: the mistake, bound as a student would, is not
    right, gets its sentence, and the sentence gives nothing away."""
    from test_named_mistakes import _as_answer

    from lagrade.answer.reading.load import LoadedAnswer
    from lagrade.verdicts.grade import grade_values

    problem = load_problem(pid)
    part = problem.part(name)
    alt = part.alternatives[i]
    in_alt = part.model_copy(update={"system": alt.system if alt.system is not None else part.system})
    value = _as_answer(problem, in_alt, alt.mistakes[k].answer)
    # an alternative selected by its alias (12.30's lam) is graded when the value is bound to that name
    bound = LoadedAnswer(values={part.name: value}, bound_as={part.name: alt.name or part.name})
    graded = grade_values(problem, bound, only=[part.name]).parts[0]
    assert graded.verdict != "correct", graded.feedback
    assert alt.mistakes[k].message in graded.feedback, graded.feedback
    assert reveals(pid, graded.feedback) == []


def test_show_lists_the_formulations_without_values():
    text = show_text(load_problem("12.47"))
    assert "also accepted: the elevator-frame Lagrangian" in text
    assert "judged for the formulation of your H" in text


BASE = """
id = "t1"
title = "t"
[[parameters]]
name = "m"
[[systems]]
T = "m*x_d**2/2"
[[systems.coordinates]]
name = "x"
[[systems]]
key = "b"
T = "m*x_d**2"
[[systems.coordinates]]
name = "x"
"""


@pytest.mark.parametrize("parts, error", [
    ('[[parts]]\nname = "L"\nkind = "lagrangian"\n[[parts.alternatives]]\nsystem = "c"\n', "unknown system 'c'"),
    (('[[parts]]\nname = "c"\nkind = "boolean"\nreference = true\nfollows = "L"\n'
      '[[parts]]\nname = "L"\nkind = "lagrangian"\n'), "not an earlier part"),
    ('[[parts]]\nname = "c"\nkind = "boolean"\nreference = true\nfollows = "c"\n', "cannot follow itself"),
    ('[[parts]]\nname = "c"\nkind = "boolean"\nreference = true\n[[parts.alternatives]]\nreference = 1\n',
     "must be a boolean"),
    ('[[parts]]\nname = "L"\nkind = "lagrangian"\n[[parts.alternatives]]\nsays = "x"\n', "needs a system"),
    ('[[parts]]\nname = "L"\nkind = "lagrangian"\n[[parts.alternatives]]\ngauge = true\n', "gauge = true is for"),
])
def test_a_problem_file_with_a_broken_formulation_is_refused_in_one_line(tmp_path, parts, error):
    path = tmp_path / "t1.toml"
    path.write_text(BASE + parts)
    with pytest.raises(SpecError, match=error) as info:
        load_problem_file(path)
    assert "\n" not in str(info.value)


def test_a_valid_formulation_loads(tmp_path):
    path = tmp_path / "t1.toml"
    path.write_text(BASE + '[[parts]]\nname = "L"\nkind = "lagrangian"\n[[parts.alternatives]]\nsystem = "b"\n')
    assert load_problem_file(path).parts[0].alternatives[0].system == "b"


def test_a_gauge_hamiltonian_keeps_its_floats(tmp_path):
    """sympy's solve replaced 2.00000002 by 2 (rational=True by default), so 12.47's ground-frame H
    with a0 off by 1e-8 in its p*t term passed as "another gauge" even under strict."""
    import lagrade

    path = tmp_path / "answer.toml"
    path.write_text('H = "(a0*g*m**2*t**2 + 2.00000002*a0*m*p_x*t - 2*g*l0*m**2 - 2*g*m**2*x + k*m*x**2 + p_x**2)'
                    '/(2*m)"\n')
    part = next(p for p in lagrade.check("12.47", path, accuracy="strict").parts if p.part == "H")
    assert part.verdict == "incorrect", part.feedback
