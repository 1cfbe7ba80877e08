"""Trajectories with a role (issue 34, items 1 and 5): the states the true motion visits are sampled
too, with the sampled states' tolerance, and decide an answer that agrees only inside the sampling box;
a rejection by the trajectory comparison carries its evidence and is confirmed at a finer tolerance,
or flagged for review."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import lagrade
from lagrade.compare import exact
from lagrade.verdicts.checkers import admit, dynamics
from lagrade.compare import trajectory as tr
from lagrade.compare.trajectory import ACCURACY, Comparison, compare_runs, confirm_refutation
from lagrade.verdicts.result import PartResult

REFERENCE = Path(__file__).resolve().parents[1] / "reference_solutions" / "12.14" / "answer.py"

#: 12.14's exact equations with the first row's force times 1 + exp(8*(theta1'^2 + theta2'^2) - 40):
#: below 4e-11 of it where velocities are sampled (|q'| <= 1), large at the speeds the motion reaches
BEYOND_THE_BOX = (
    'eom_exact = ["(m1 + m2)*l1*theta1_dd + m2*l2*(theta2_dd*cos(theta1 - theta2) + theta2_d^2*sin(theta1 - theta2))'
    ' == -(m1 + m2)*g*sin(theta1) + g*exp(8*theta1_d^2 + 8*theta2_d^2 - 40)", '
    '"l2*theta2_dd + l1*(theta1_dd*cos(theta1 - theta2) - theta1_d^2*sin(theta1 - theta2)) == -g*sin(theta2)"]\n')


def _part(result, name: str = "eom_exact") -> PartResult:
    return next(p for p in result.parts if p.part == name)


@pytest.fixture(autouse=True)
def _motion_evidence_alone(request, monkeypatch):
    """The answers here hide a term too small for the sampled states to see, which the exact judge
    (`lagrade.compare.exact`: they are in its class) and the screen's negligible-part rule
    (`admit._negligible`) refuse first; these tests are about the evidence that decides where neither
    reaches (an answer outside the exact class), so both are switched off unless a test is marked."""
    if "exact_judge" not in request.keywords:
        monkeypatch.setattr(exact, "is_zero", lambda *a, **k: None)
        monkeypatch.setattr(exact, "is_zero_given", lambda *a, **k: None)
    if "negligible_rule" not in request.keywords:
        monkeypatch.setattr(admit, "_negligible", lambda *a, **k: [])


@pytest.mark.exact_judge
@pytest.mark.negligible_rule
def test_the_exact_judge_refuses_it_first(beyond_the_box):
    """As grading runs, the answer is in the exact class: refused in exact arithmetic, certified, with the
    hidden term the screen flagged named, before any motion is integrated."""
    part = _part(lagrade.check("12.14", beyond_the_box, accuracy="default"))
    assert part.verdict == "incorrect" and part.score == 0 and part.method == "exact", part.feedback
    assert "exact arithmetic" in part.feedback and part.certified is True
    assert "changes the whole by less than" in part.feedback and "exp(" in part.feedback


@pytest.mark.negligible_rule
def test_the_screen_refuses_it_first(beyond_the_box, monkeypatch):
    """With the exact judge off (an answer outside its class) and the negligible-part rule on, the hidden
    term is flagged, and its motion is still followed (a flagged smooth answer: issue 45): the states
    it visits refute the equations, certified, before the rule's uncertified refusal is needed. Without
    that motion the rule names the hidden term and gives no credit without a proof."""
    part = _part(lagrade.check("12.14", beyond_the_box, accuracy="default"))
    assert part.verdict == "incorrect" and part.score == 0, part.feedback
    assert dynamics.ALONG_MOTION.replace("the true motion", "it") in part.feedback and part.certified is True
    monkeypatch.setattr(admit, "smooth_pending", lambda: False)
    part = _part(lagrade.check("12.14", beyond_the_box, accuracy="default"))
    assert part.verdict == "incorrect" and part.score == 0, part.feedback
    assert "changes the whole by less than" in part.feedback and "exp(" in part.feedback


@pytest.fixture
def beyond_the_box(tmp_path) -> Path:
    path = tmp_path / "answer.toml"
    path.write_text(BEYOND_THE_BOX)
    return path


@pytest.mark.parametrize("accuracy", ["default", "strict"])
def test_an_answer_wrong_only_beyond_the_box_is_rejected_along_the_motion(beyond_the_box, accuracy):
    part = _part(lagrade.check("12.14", beyond_the_box, accuracy=accuracy))
    assert part.verdict != "correct" and part.method == "numeric", part.feedback
    assert dynamics.ALONG_MOTION.replace("the true motion", "it") in part.feedback
    assert part.certified is True, part.review   # certified at the exact motion state, like a box sample


def test_a_lagrangian_wrong_only_beyond_the_box_is_rejected_along_the_motion(tmp_path, monkeypatch):
    """L plus a velocity term below 1e-13 of it in the box: refuted by the motion, confirmed at the finer
    tolerance (issue 45: the motion decides first); without the motion's refutation its Lagrange
    equations are compared at the states the motion visits, certified."""
    path = tmp_path / "answer.toml"
    path.write_text('L = "(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*'
                    'cos(theta1 - theta2) + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2) + '
                    'g*l1*m1*exp(8*theta1_d^2 + 8*theta2_d^2 - 40)"\n')
    part = _part(lagrade.check("12.14", path, accuracy="default"), "L")
    assert part.verdict == "incorrect" and part.method == "trajectory" and part.confirmed is True, part.feedback
    monkeypatch.setattr(dynamics, "_motion_refutes", lambda *a, **k: None)
    part = _part(lagrade.check("12.14", path, accuracy="default"), "L")
    assert part.verdict == "incorrect" and part.method == "numeric", part.feedback
    assert "the Lagrange equations your L gives" in part.feedback and dynamics.ALONG_MOTION in part.feedback
    assert part.certified is True, part.review


def test_the_box_samples_alone_accept_it(beyond_the_box, monkeypatch):
    """What main did: without the states along the motion the answer is accepted (its trajectories
    agree within the comparison tolerance), so the new evidence is what decides it. (The exact
    re-check at the sampled states, `dynamics._exact_refutation`, would refute it too: off here.)"""
    monkeypatch.setattr(dynamics, "_along_motion", lambda *a, **k: None)
    monkeypatch.setattr(dynamics, "_exact_refutation", lambda *a, **k: None)
    part = _part(lagrade.check("12.14", beyond_the_box, accuracy="default"))
    assert part.verdict == "correct", part.feedback


@pytest.mark.parametrize("accuracy", ["fast", "default", "strict"])
def test_the_right_answers_still_pass_at_the_states_along_the_motion(accuracy):
    result = lagrade.check("12.14", REFERENCE, accuracy=accuracy)
    assert result.full_marks and _part(result).verdict == "correct", str(result)


def _perturbed_g(tmp_path: Path) -> Path:
    src = "from sympy import Rational\n" + REFERENCE.read_text()
    src = src.replace("-(m1 + m2) * g * sin(th1)),", "-(m1 + m2) * (1 + Rational(1, 10**6))*g * sin(th1)),")
    src = src.replace("-g * sin(th2)),", "-(1 + Rational(1, 10**6))*g * sin(th2)),")
    path = tmp_path / "answer.py"
    path.write_text(src)
    return path


def test_a_trajectory_refutation_carries_its_evidence_for_the_instructor(tmp_path, monkeypatch):
    # states at 1e-3 let the 1e-6 error through: only the trajectory comparison can refute it (the
    # exact re-check at the sampled states would too: off here, to test the trajectory's evidence)
    monkeypatch.setattr(dynamics, "_exact_refutation", lambda *a, **k: None)
    monkeypatch.setitem(tr.ACCURACY, "default-loose",
                        dataclasses.replace(ACCURACY["default"], name="default-loose", sample_rtol=1e-3))
    result = lagrade.check("12.14", _perturbed_g(tmp_path), accuracy="default-loose")
    part = _part(result)
    assert part.verdict == "incorrect" and part.method == "trajectory", part.feedback
    assert part.confirmed is True and part.review is None
    ev = part.trajectory_evidence
    assert ev.startswith("confirmed") and "comparison tolerances apart" in ev and "error estimate" in ev
    assert ev not in part.feedback and "tolerances apart" not in part.feedback   # never the student's words
    dumped = result.model_dump_json()
    assert '"confirmed":true' in dumped and "comparison tolerances apart" in dumped   # `--json`: the instructor's


def test_the_student_view_hides_the_trajectory_evidence():
    """The server's view of an attempt: the instructor reads the trajectory evidence, a student never
    (the separation and the time it happens say how far off the answer is)."""
    from types import SimpleNamespace

    from lagrade.uses.bulk.assignment import Rules
    from lagrade.uses.server import rules

    evidence = {"t": 1.25, "separation": 40.0, "error_estimate": 0.01, "finer_separation": 39.0}
    part = {"part": "eom", "verdict": "incorrect", "score": 0.0, "feedback": "wrong", "trajectory_evidence": evidence}
    server = SimpleNamespace(assignment=SimpleNamespace(rules=Rules()), problems={},
                             db=SimpleNamespace(count=lambda *a: 1))
    att = SimpleNamespace(id=7, student="s", problem="12.14", created_at="2026-01-01T00:00:00+00:00", graded=True,
                          result={"score": 0.0, "parts": [part]})
    teacher = rules.view(server, att, SimpleNamespace(instructor=True))
    student = rules.view(server, att, SimpleNamespace(instructor=False))
    assert teacher["parts"][0]["trajectory_evidence"] == evidence
    assert student["parts"][0]["trajectory_evidence"] is None
    assert "40" not in str(student["parts"][0])


def _pendulum(t, y):
    return np.array([y[1], -9.8 * np.sin(y[0])])


def test_a_refutation_the_finer_tolerance_does_not_confirm_is_review():
    """Integration error dressed up as a separation: the same rates on both sides, the student's run
    displaced by more than the comparison tolerance. The finer re-integration finds no separation, so
    the rejection is unconfirmed and goes to review."""
    acc = ACCURACY["default"]
    y0 = np.array([[1.0, 0.5], [0.0, 0.2]])
    comp = compare_runs(_pendulum, _pendulum, y0, ["theta", "theta'"], 2.0, acc, chaos=False)
    assert comp.agree
    i = comp.reference_t.size // 2
    fake = Comparison(False, 2.0, float(comp.reference_t[i]), "theta", 5.0, method="DOP853", rtol=acc.rtol,
                      window=2.0, decisive=True, reference_t=comp.reference_t, reference_y=comp.reference_y,
                      reference_stop=comp.reference_stop, student_y=comp.reference_y * (1 + 5 * acc.compare_rtol))
    confirm_refutation(fake, _pendulum, _pendulum, y0, acc)
    assert fake.confirmed is False and fake.evidence.startswith("not confirmed")
    fake.confirm = lambda: None
    res = dynamics._with_trajectory_evidence(PartResult(part="eom", verdict="incorrect", score=0, max_score=1,
                                                        method="trajectory"), fake)
    assert res.confirmed is False and "did not confirm" in res.review


def test_a_real_separation_is_confirmed():
    acc = ACCURACY["default"]
    y0 = np.array([[1.0, 0.5], [0.0, 0.2]])

    def off(t, y):
        return np.array([y[1], -9.8 * (1 + 1e-5) * np.sin(y[0])])

    comp = compare_runs(off, _pendulum, y0, ["theta", "theta'"], 2.0, acc, chaos=False)
    assert comp.decisive
    confirm_refutation(comp, off, _pendulum, y0, acc)
    assert comp.confirmed is True, comp.evidence


@pytest.mark.slow
@pytest.mark.exact_judge
@pytest.mark.negligible_rule
def test_the_evidence_benchmark_names_the_deciding_evidence():
    """benchmarks/evidence.py (the table of docs/numerics.md) on 12.14: every class is decided in
    exact arithmetic (the answers are in its class: issue 42), none is accepted."""
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "evidence.py"
    spec = importlib.util.spec_from_file_location("evidence_bench", path)
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    out = {(pid, part, cls, acc): ev for pid, part, cls, acc, ev in bench.scan(["12.14"])}
    assert out[("12.14", "eom_exact", "beyond the box", "default")] == "exact arithmetic"
    assert "not rejected" not in out.values()
    assert "| beyond the box | default | 1 | 1 | 0 |" in bench.markdown(list(
        (p, n, c, a, e) for (p, n, c, a), e in out.items()))
