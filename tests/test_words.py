"""The evidence in words for a student; the integrator's settings for the instructor and --json."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from lagrade.cli import main
from lagrade.verdicts.words import at_level, in_words

ANSWER = Path(__file__).parent / "answers" / "12.14" / "correct_plain.toml"
ENGINE = ("correct: equal at every sampled state (within rtol 1e-08) and trajectories agree over t in [0, 2] "
          "(DOP853 at rtol 1e-10) (compared within rtol 1e-06, atol 1e-06, 1545 evaluations, 0.09 s).")


def test_agreement_is_said_in_words_for_each_kind():
    assert in_words(ENGINE, "lagrangian") == ("correct: equal to the true one at every sampled state, and your "
                                              "Lagrangian gives the same motion as the true one over t in [0, 2].")
    assert "your equations give the same motion" in in_words(ENGINE, "eom")
    assert "your Hamiltonian gives" in in_words(ENGINE, "hamiltonian")


def test_feedback_levels():
    said = "Incorrect: the equation for theta1 is wrong. Hint: your term 2*x' is too large. The motion blows up."
    assert at_level(said, "incorrect", "hints") == said
    assert at_level(said, "incorrect", "named") == "Incorrect: the equation for theta1 is wrong. The motion blows up."
    assert at_level(said, "incorrect", "verdict") == "Incorrect."
    assert at_level("not answered: no value for 'L'", "missing", "verdict") == "not answered: no value for 'L'"  # kept


def test_lagrade_check_says_it_in_words_and_json_keeps_the_settings(tmp_path):
    """An L the motion decides (a constant atan(2) keeps it outside the exact class): the student reads the
    evidence in words, --json keeps the integrator's settings for the instructor."""
    ANSWER = tmp_path / "answer.toml"
    ANSWER.write_text('L = "(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*'
                      'cos(theta1 - theta2) + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2) + g*l1*m1*atan(2)"\n')
    text = CliRunner().invoke(main, ["check", "12.14", str(ANSWER)]).output
    flat = " ".join(text.split())
    assert "gives the same motion as the true one" in flat and "evaluations" not in flat and "DOP853" not in flat
    out = json.loads(CliRunner().invoke(main, ["check", "12.14", str(ANSWER), "--json"]).output)
    assert "DOP853" in out["parts"][0]["feedback"] and "evaluations" in out["parts"][0]["feedback"]


@pytest.mark.parametrize("preset", ["fast", "default", "strict"])
def test_the_feedback_says_each_tolerance_beside_what_it_decides(preset, tmp_path):
    """The sampled states' tolerance is the preset's sample_rtol, said beside the states; the looser
    comparison tolerance is said with the trajectories (issue 44: docs gave 1e-7/1e-8/1e-10 while the
    feedback seemed to say 1e-4/1e-6/1e-8 for the sampled states)."""
    import lagrade
    from lagrade.compare.trajectory import ACCURACY

    acc = ACCURACY[preset]
    # an L outside the exact class (a constant atan(2)): the sampled states and the motion decide it
    L = ('L = "(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)'
         ' + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2) + g*l1*m1*atan(2)"\n')
    answer = tmp_path / "answer.toml"
    answer.write_text(L)
    said = lagrade.check("12.14", answer, accuracy=preset, only=["L"]).parts[0].feedback
    if said.startswith("correct: proved"):  # strict proves every answer: no tolerance decided it
        assert preset == "strict"
        return
    assert f"equal at every sampled state (within rtol {acc.sample_rtol:g})" in said, said
    if "trajectories agree" in said:
        assert f"compared within rtol {acc.compare_rtol:g}, atol {acc.compare_atol:g}" in said, said


def _book():
    """A gradebook of one student whose 12.14 L was accepted by the trajectories (the engine's words)."""
    from lagrade.uses.bulk.assignment import parse_assignment, points
    from lagrade.uses.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade

    a = parse_assignment({"name": "hw", "problems": [{"id": "12.14", "weight": 1}],
                          "gradescope": {"output_format": "text"}}, "hw")
    parts = [{"part": "L", "score": 1.0, "max_score": 1.0, "verdict": "correct", "feedback": ENGINE,
              "answer_text": "x(t)**2"}]
    grade = ProblemGrade("12.14", points(a.problems[0], parts, 1)[0], 1, True, "graded", parts=parts)
    return Gradebook(a, [StudentGrade("ada", {"12.14": grade})], [], "test")


def test_students_read_no_integrator_settings_in_gradescope_or_their_report_page(tmp_path):
    """Reason (issue 45): "(DOP853 at rtol 1e-10) ... 1545 evaluations" reached Gradescope's results and
    the HTML report's student pages; the student reads the words, the class page keeps the settings."""
    from lagrade.uses.bulk.exports import gradescope_results
    from lagrade.uses.bulk.html_report import write_report

    book = _book()
    output = gradescope_results(book, book.students[0])["tests"][0]["output"]
    assert "your Lagrangian gives the same motion as the true one over t in [0, 2]" in output, output
    assert "DOP853" not in output and "evaluations" not in output and "rtol" not in output
    write_report(book, tmp_path)
    page = (tmp_path / "students" / "ada.html").read_text()
    assert "your Lagrangian gives the same motion" in page
    assert "DOP853" not in page and "evaluations" not in page and "rtol" not in page


def test_prairielearns_results_say_it_in_words(tmp_path, monkeypatch):
    """PrairieLearn shows each test's ``message`` to the student: the words, not the settings."""
    from lagrade.uses.deploy import prairielearn
    from lagrade.verdicts.result import CheckResult, PartResult

    result = CheckResult(problem="12.14", score=1.0, max_score=1.0, parts=[
        PartResult(part="L", verdict="correct", score=1.0, max_score=1.0, method="trajectory", feedback=ENGINE)])
    monkeypatch.setattr("lagrade.verdicts.grade.check", lambda *a, **k: result)
    monkeypatch.setattr(prairielearn, "read_job", lambda root: (type("P", (), {"problem": "12.14",
                                                                              "accuracy": "default"})(), tmp_path))
    monkeypatch.setattr("lagrade.uses.deploy.jailcheck.decide",
                        lambda: type("J", (), {"ok": True, "summary": lambda self: "test"})())
    monkeypatch.setattr(prairielearn, "_image", lambda result: [])
    message = prairielearn._grade_job(tmp_path)["tests"][0]["message"]
    assert "your Lagrangian gives the same motion" in message and "DOP853" not in message, message
