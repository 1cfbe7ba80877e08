"""A course's rules on the server: the assignment's ``[rules]`` (deadline, attempts, penalty,
feedback level) applied to what a student may do and what they see.

Applied when an attempt is shown, not when it is graded: the stored grade is the grader's, whole
(the instructor's view, the gradebook), and a student's view of it is made from it each time
(:func:`view`), so an instructor who changes the feedback level changes it for every attempt.
Only ``feedback = "hints"`` changes grading itself: the graders then add the term hints
(``lagrade check --hints``), to attempts graded from then on.
"""

from __future__ import annotations

import time
from typing import Any

from lagrade.uses.bulk.assignment import Rules
from lagrade.verdicts.words import at_level, in_words


def now_text() -> str:
    """Now, as the server stores attempts' times."""
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


def is_late(rules: Rules, created_at: str) -> bool:
    deadline = rules.deadline_text()
    return deadline is not None and created_at > deadline


def standing(server, student: str, pid: str, instructor: bool = False) -> dict[str, Any]:
    """What the problem page says of the rules before an attempt: the deadline (passed or not), the
    attempts made and left, the penalty, the feedback level."""
    rules: Rules = server.assignment.rules
    made = server.db.count(student, pid)
    left = None if rules.attempts is None or instructor else max(0, rules.attempts - made)
    return {"deadline": rules.deadline_text(), "past_deadline": is_late(rules, now_text()),
            "attempts_allowed": None if instructor else rules.attempts, "attempts_made": made,
            "attempts_left": left, "attempt_penalty": rules.attempt_penalty, "feedback": rules.feedback,
            "can_submit": left is None or left > 0}


def view(server, att, who) -> dict[str, Any]:
    """Attempt ``att`` (graded or queued) as ``who`` may see it: for the instructor, the grader's
    whole result; for a student, at the assignment's feedback level, the evidence in words, and the
    score after the attempt penalty. Both carry ``rules``: the attempt's number, late or not, and
    the share of the score it keeps."""
    rules: Rules = server.assignment.rules
    number = server.db.count(att.student, att.problem, att.id)
    keep = rules.penalty(number)
    late = is_late(rules, att.created_at)
    info = {"attempt": number, "attempts_allowed": rules.attempts, "late": late, "deadline": rules.deadline_text(),
            "kept": keep, "feedback": rules.feedback, "created_at": att.created_at}
    if not att.graded:
        return {"submission_id": att.id, "state": "queued", "rules": info}
    out = {**att.result, "submission_id": att.id, "state": "graded", "rules": info}
    if late:
        out["late"] = (f"late: stored at {att.created_at}, after the deadline {rules.deadline_text()}; graded, "
                       "and kept apart from your grade")
    if keep != 1.0:
        info["score_before_penalty"] = out["score"]
        out["score"] = out["score"] * keep
        out["parts"] = [{**p, "score": p["score"] * keep} for p in out["parts"]]
        out["penalty"] = (f"attempt {number}: {100 * (1 - keep):g}% off its score ({100 * rules.attempt_penalty:g}% "
                          "for each attempt before it)")
    if who.instructor:
        return out
    problem = server.problems.get(att.problem)
    kinds = {p.name: p.kind for p in problem.parts} if problem is not None else {}
    out["parts"] = [{**p, "feedback": at_level(in_words(p.get("feedback", ""), kinds.get(p["part"], "")),
                                               p["verdict"], rules.feedback), "trajectory_evidence": None, "motion_evidence": None}
                    for p in out["parts"]]
    if rules.feedback == "verdict":
        out.pop("plot", None)  # the motion against the true one says where the answer goes wrong
        for p in out["parts"]:
            p["review"] = None
    return out


def rows(server, attempts, who) -> list[dict[str, Any]]:
    """Earlier attempts as a list shows them: id, time, the score as the student's view gives it, late."""
    out = []
    for a in attempts:
        v = view(server, a, who)
        out.append({"id": a.id, "created_at": a.created_at, "state": a.state, "file_hash": a.file_hash,
                    "late": v["rules"]["late"], "attempt": v["rules"]["attempt"],
                    "result": {"score": v["score"], "max_score": v["max_score"]} if a.graded else None})
    return out
