"""A grader failure is graded once more by the next run, and only once; the gradebook records the
jail each file ran under; gradebooks written before either column are migrated when opened."""

from __future__ import annotations

import csv
import io
import os
import signal
import sqlite3
from pathlib import Path

import classgen
import pytest

import lagrade.uses.bulk.runner as runner
from lagrade.uses.bulk import exports
from lagrade.uses.bulk.assignment import load_assignment
from lagrade.uses.bulk.gradebook import load_gradebook
from lagrade.uses.bulk.html_report import write_report
from lagrade.uses.bulk.runner import grade_folder
from lagrade.uses.bulk.store import SCHEMA, Key, Store
from lagrade.uses.bulk.worker import GraderProcess, failed_result

REPO = classgen.REPO
MARK = b"# this file's grader is killed\n"
JAIL = "uid,mount,pid,network,no_new_privs,limits,landlock,seccomp"


def _class(tmp_path: Path) -> tuple[Path, Path, Path]:
    root = tmp_path / "submissions"
    ref = (REPO / "reference_solutions/12.43/answer.py").read_bytes()
    for student, data in {"ada": ref, "kim": MARK + ref}.items():
        (root / student).mkdir(parents=True)
        (root / student / "12.43.py").write_bytes(data)
    hw = tmp_path / "hw.toml"
    hw.write_text(classgen.assignment_toml(["12.43"]))
    return root, hw, tmp_path / "hw.sqlite"


def _row(db: Path, student: str) -> dict:
    con = sqlite3.connect(db)
    con.row_factory = sqlite3.Row
    try:
        row = dict(con.execute("SELECT * FROM submissions WHERE student = ?", (student,)).fetchone())
        row["log"] = con.execute("SELECT count(*) FROM grade_log WHERE student = ?", (student,)).fetchone()[0]
        return row
    finally:
        con.close()


def _killing_graders(monkeypatch, times: int) -> list[int]:
    """Grader processes that die (SIGKILL, as the OOM killer does) on a marked file, ``times`` times."""
    kills: list[int] = []

    class Dying(GraderProcess):
        def submit(self, job):
            super().submit(job)
            if MARK in job["data"] and len(kills) < times:
                kills.append(self.pid)
                os.kill(self.pid, signal.SIGKILL)

    monkeypatch.setattr(runner, "GraderProcess", Dying)
    return kills


def test_a_grader_crash_is_graded_again_once_not_forever(tmp_path, monkeypatch):
    root, hw, db = _class(tmp_path)
    kills = _killing_graders(monkeypatch, times=99)

    def run(**kw):
        return grade_folder(root, load_assignment(hw), db, workers=2, **kw)

    assert run().todo == 2
    kim = _row(db, "kim")
    assert (kim["status"], kim["attempts"], kim["log"]) == ("grader-crash", 1, 1) and len(kills) == 1
    assert _row(db, "ada")["status"] == "ok"
    # the next run grades kim's unchanged file again (only it), and it kills its grader again
    assert run().todo == 1
    kim = _row(db, "kim")
    assert (kim["status"], kim["attempts"], kim["log"]) == ("grader-crash", 2, 2) and len(kills) == 2
    # and that is it: a third run does not send it to a grader
    assert run().todo == 0
    assert _row(db, "kim")["log"] == 2 and len(kills) == 2
    # unless told to
    assert run(regrade=True).todo == 2
    kim = _row(db, "kim")
    assert (kim["status"], kim["attempts"], kim["log"]) == ("grader-crash", 1, 3) and len(kills) == 3
    assert _row(db, "ada")["log"] == 2  # the first run and --regrade


def test_a_grader_crash_that_does_not_recur_gets_its_grade(tmp_path, monkeypatch):
    root, hw, db = _class(tmp_path)
    kills = _killing_graders(monkeypatch, times=1)
    grade_folder(root, load_assignment(hw), db, workers=1)
    assert _row(db, "kim")["status"] == "grader-crash" and len(kills) == 1
    assert grade_folder(root, load_assignment(hw), db, workers=1).todo == 1
    kim = _row(db, "kim")
    assert (kim["status"], kim["score"], kim["max_score"], kim["attempts"]) == ("ok", 3.0, 3.0, 2)
    assert grade_folder(root, load_assignment(hw), db, workers=1).todo == 0


def test_a_grader_timeout_is_graded_again_once(tmp_path, monkeypatch):
    # the graders are stand-ins that run out of time on every file; the runner and the store are real
    root, hw, db = _class(tmp_path)
    sent: list[list[str]] = []

    def timing_out(jobs, sources, workers, done):
        jobs = list(jobs)
        sent.append(sorted(j["student"] for j in jobs))
        for job in jobs:
            done(failed_result(job, job["parts"], "grader-timeout", "grading this file did not finish", 1.0))

    monkeypatch.setattr(runner, "run_local", timing_out)
    for _ in range(3):
        grade_folder(root, load_assignment(hw), db, workers=1)
    assert sent == [["ada", "kim"], ["ada", "kim"]]  # the second run retries both, the third neither
    assert _row(db, "ada")["attempts"] == 2 and _row(db, "ada")["status"] == "grader-timeout"


def test_the_store_records_the_jail_and_exports_show_it(tmp_path):
    db = tmp_path / "hw.sqlite"
    parts = [{"part": "H", "verdict": "correct", "score": 1.0, "max_score": 1.0, "method": "exact", "feedback": "ok"}]
    with Store(db, lock=True) as store:
        store.set_meta("assignment", '{"name": "hw", "problems": [{"id": "12.43"}, {"id": "12.3"}]}')
        for student, problem, jail in [("ada", "12.43", JAIL), ("ada", "12.3", JAIL),
                                       ("bob", "12.43", "none (--unsafe-trusted-files)"), ("bob", "12.3", None)]:
            assert store.record(student=student, problem=problem, path=f"{student}/{problem}.py",
                                key=Key("f", "g", "v"), outcome="graded", status="ok", reason="", score=1.0,
                                max_score=1.0, problems=[], stdout="", source="H = 1\n", seconds=0.1, parts=parts,
                                jail=jail)
        got = {(r["student"], r["problem"]): r["jail"] for r in store.submissions()}
    assert got == {("ada", "12.43"): JAIL, ("ada", "12.3"): JAIL, ("bob", "12.43"): "none (--unsafe-trusted-files)",
                   ("bob", "12.3"): None}
    book = load_gradebook(db)
    rows = {r["student"]: r for r in csv.DictReader(io.StringIO(exports.plain_csv(book)))}
    assert rows["ada"]["jail"] == JAIL and rows["bob"]["jail"] == "none (--unsafe-trusted-files)"
    index = write_report(book, tmp_path / "report").read_text()
    assert f'<tr data-jail="{JAIL}">' in index and '<tr data-jail="none (--unsafe-trusted-files)">' in index
    assert JAIL not in (tmp_path / "report" / "students" / "bob.html").read_text()  # pages go to students


def _old_gradebook(db: Path) -> None:
    """A gradebook as lagrade wrote it before ``attempts``, ``jail``, ``review``, ``detail`` and
    ``certificate`` (and ``motion_evidence``), with one grader crash in it."""
    old = "\n".join(line for line in SCHEMA.splitlines()
                    if not line.lstrip().startswith(("attempts", "jail", "review", "detail", "certificate",
                                                                 "motion_evidence")))
    assert "attempts" not in old and "jail" not in old and "review " not in old
    con = sqlite3.connect(db)
    con.executescript(old)
    con.execute("INSERT INTO meta VALUES ('schema_version', '1')")
    con.execute("INSERT INTO meta VALUES ('assignment', '{\"name\": \"hw\", \"problems\": [{\"id\": \"12.43\"}]}')")
    con.execute("INSERT INTO submissions(student, problem, path, file_hash, grading_hash, grader_version, outcome, "
                "status, reason, score, max_score, seconds, graded_at) VALUES ('kim', '12.43', 'kim/12.43.py', 'f', "
                "'g', 'v', 'failed', 'grader-crash', 'the grader died', 0, 3, 1, '2026-01-01T00:00:00Z')")
    con.execute("INSERT INTO parts VALUES ('kim', '12.43', 'H', 'invalid', 0, 1, 'exact', 'not graded', NULL, NULL, "
                "'f', 'v')")
    con.commit()
    con.close()


def test_an_old_gradebook_is_read_as_it_is_and_migrated_by_a_grading_run(tmp_path):
    db = tmp_path / "hw.sqlite"
    _old_gradebook(db)
    # exports and reports read it without writing to it
    book = load_gradebook(db)
    assert [r["jail"] for r in csv.DictReader(io.StringIO(exports.plain_csv(book)))] == [""]
    con = sqlite3.connect(db)
    assert not {"attempts", "jail"} & {r[1] for r in con.execute("PRAGMA table_info(submissions)")}
    con.close()
    # a grading run adds the columns: the old row keeps its data, one attempt so far, no jail known
    with Store(db, lock=True) as store:
        row = store.submissions()[0]
        assert (row["status"], row["attempts"], row["jail"]) == ("grader-crash", 1, None)
        assert store.retries() == {("kim", "12.43")}
        assert {"review", "detail", "certificate"} <= {k for k in store.parts()[0].keys()}
    with Store(db, lock=True) as store:  # opening again changes nothing
        assert store.submissions()[0]["attempts"] == 1


def test_a_retried_crash_in_an_old_gradebook_is_recorded_once_more(tmp_path):
    db = tmp_path / "hw.sqlite"
    _old_gradebook(db)
    with Store(db, lock=True) as store:
        again = dict(student="kim", problem="12.43", path="kim/12.43.py", key=Key("f", "g", "v"), outcome="failed",
                     status="grader-crash", reason="the grader died", score=0.0, max_score=3.0, problems=[], stdout="",
                     source="", seconds=1.0, parts=[])
        assert store.record(**again) is True       # the retry is written, its attempt counted
        assert store.submissions()[0]["attempts"] == 2 and store.retries() == set()
        assert store.record(**again) is False      # and no further one


@pytest.mark.parametrize("status", ["ok", "error", "timeout", "memory", "crashed"])
def test_only_grader_failures_are_retried(tmp_path, status):
    # the file's own failures are its verdict: grading it again gives the same one
    db = tmp_path / "hw.sqlite"
    with Store(db, lock=True) as store:
        kw = dict(student="kim", problem="12.43", path="kim/12.43.py", key=Key("f", "g", "v"), outcome="failed",
                  status=status, reason="", score=0.0, max_score=3.0, problems=[], stdout="", source="", seconds=1.0,
                  parts=[])
        assert store.record(**kw) is True
        assert store.retries() == set() and store.record(**kw) is False


def test_a_file_that_hits_a_bound_is_final_with_its_reason(tmp_path):
    """Issue 32: a file whose grading ran out of its CPU bound is the file's cost, not the grader's
    failure: recorded once as `timeout` with the reason, not graded again by the next run."""
    root, hw, db = _class(tmp_path)
    # a 1000-term Hamiltonian: its comparison costs far more than the bound (verdicts of the reference's
    # own values come from the grader's memo at no cost)
    (root / "ada" / "12.43.py").write_text(
        "from lagrade.answer import *\nm, l, g = parameters('m l g')\ntheta = coordinates('theta')\n"
        "p_theta = momenta('p_theta')\nH = p_theta**2/(2*m*l**2) + sum(cos(k*theta)/k for k in range(1, 1001))\n")
    hw.write_text(classgen.assignment_toml(["12.43"], cpu=10, wall=30).replace("grading_seconds = 60", "grading_seconds = 0.01"))
    first = grade_folder(root, load_assignment(hw), db, workers=1)
    assert first.todo == 2
    row = _row(db, "ada")
    assert row["status"] == "timeout" and row["outcome"] == "failed" and "took longer than 0.01 s" in row["reason"]
    again = grade_folder(root, load_assignment(hw), db, workers=1)
    assert again.todo == 0 and _row(db, "ada")["attempts"] == 1 and _row(db, "ada")["log"] == 1


def test_a_grading_past_the_hard_deadline_is_final(tmp_path, monkeypatch):
    """A grader stuck past every bound (a power bomb built while holding the GIL) is killed and the
    file recorded as `timeout` with the reason: not retried at that cost on the next run."""
    from lagrade.uses.bulk import worker

    root, hw, db = _class(tmp_path)
    # a 1000-term Hamiltonian: its comparison costs far more than the bound (verdicts of the reference's
    # own values come from the grader's memo at no cost)
    (root / "ada" / "12.43.py").write_text(
        "from lagrade.answer import *\nm, l, g = parameters('m l g')\ntheta = coordinates('theta')\n"
        "p_theta = momenta('p_theta')\nH = p_theta**2/(2*m*l**2) + sum(cos(k*theta)/k for k in range(1, 1001))\n")
    (root / "kim" / "12.43.py").unlink()
    hw.write_text(classgen.assignment_toml(["12.43"], cpu=10, wall=30))
    monkeypatch.setattr(worker, "hard_deadline", lambda limits, lowered=False: 0.0)  # a grading that takes any time overruns
    assert grade_folder(root, load_assignment(hw), db, workers=1).todo == 1
    row = _row(db, "ada")
    assert row["status"] == "timeout" and "did not finish in 0 s" in row["reason"]
    assert grade_folder(root, load_assignment(hw), db, workers=1).todo == 0
