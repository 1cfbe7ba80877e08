"""An engine bug on a readable answer is an ``error``: never ``invalid``, never a verdict against the
student, and its traceback (which may quote reference expressions) is for instructors only."""

from __future__ import annotations

import json
from pathlib import Path

import lagrade
from lagrade.verdicts.checkers import CHECKERS

REFERENCE = Path(__file__).resolve().parents[1] / "reference_solutions" / "12.43" / "answer.py"
SECRET = "the-reference-expression-9f3c"


def _broken(ctx, part, value):
    raise ValueError(f"cannot compare with {SECRET}")


def test_an_engine_failure_is_an_error_with_the_traceback_kept_for_instructors(monkeypatch):
    kind = lagrade.load_problem("12.43").part("H").kind
    monkeypatch.setitem(CHECKERS, kind, _broken)
    monkeypatch.delenv("LAGRADE_DEBUG", raising=False)
    result = lagrade.check("12.43", REFERENCE)
    part = next(p for p in result.parts if p.part == "H")
    assert part.verdict == "error" and part.score == 0
    assert "error in lagrade" in part.feedback and SECRET not in part.feedback
    assert "ValueError" in part.detail and SECRET in part.detail   # the instructor's view
    shown = result.model_dump_json()
    assert SECRET not in shown and "detail" not in json.loads(shown)["parts"][0]
    assert SECRET not in str(result)  # the terminal report
    assert {p.part: p.verdict for p in result.parts if p.part != "H"} == {"hamilton": "correct", "eom": "correct"}
