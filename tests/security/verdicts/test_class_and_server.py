"""The attacks get nothing through `lagrade grade` either: one class of the suite's 12.22 attacks (and
its honest controls) graded as a class, each file's target part read back from the gradebook. The
course server grades with the same grader processes as `lagrade grade`
(`lagrade.uses.bulk.worker.GraderProcess`, used by `lagrade.uses.server.grading`), so this covers it too."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bulk"))
from classcheck import stored  # noqa: E402
from verdicts_harness import cases  # noqa: E402

from lagrade.uses.bulk.assignment import parse_assignment  # noqa: E402
from lagrade.uses.bulk.runner import grade_folder  # noqa: E402

CLASS = [c for c in cases() if c.problem == "12.22"]


@pytest.mark.slow
def test_a_class_of_attacks_gets_nothing_and_the_controls_keep_full_marks(tmp_path):
    root = tmp_path / "submissions"
    for i, case in enumerate(CLASS):
        (root / f"s{i:02d}").mkdir(parents=True)
        (root / f"s{i:02d}" / f"12.22{case.path.suffix}").write_text(case.path.read_text())
    db = tmp_path / "hw.sqlite"
    a = parse_assignment({"name": "verdicts", "problems": [{"id": "12.22"}]})
    grade_folder(root, a, db, workers=2)
    _, parts = stored(db)
    wrong = []
    for i, case in enumerate(CLASS):
        got = parts[(f"s{i:02d}", "12.22")][case.target]
        ok = (got["score"] == 0 and got["verdict"] in ("incorrect", "invalid")) if case.expect == "no-credit" \
            else got["score"] == got["max_score"]
        if not ok:
            wrong.append(f"{case.name}: {got['verdict']} {got['score']} {got['feedback'][:120]}")
    assert len(CLASS) >= 20 and not wrong, "\n".join(wrong)
