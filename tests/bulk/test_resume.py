"""Exactly-once grading: kill -9 at any moment and start again; what changes is regraded, nothing else."""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import classgen
from classcheck import assert_expected

from lagrade.uses.bulk.assignment import load_assignment
from lagrade.uses.bulk.runner import grade_folder
from lagrade.uses.bulk.worker import _ORPHAN

GRADE = "import sys; from lagrade.cli.bulk import grade; grade(sys.argv[1:])"


def _count(db: Path, table: str) -> int:
    if not db.exists():
        return 0
    try:
        con = sqlite3.connect(f"file:{db}?mode=ro", uri=True, timeout=5)
        try:
            return con.execute(f"SELECT count(*) FROM {table}").fetchone()[0]
        finally:
            con.close()
    except sqlite3.OperationalError:
        return 0


def _start(root: Path, hw: Path, db: Path) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", GRADE, str(root), "--assignment", str(hw), "--db", str(db),
                             "--workers", "2", "--no-summary", "--no-progress"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def _grader_folders(pid: int) -> list[Path]:
    """The grader folders that the coordinator with this pid made."""
    return [p for p in Path(tempfile.gettempdir()).glob("lagrade-grader-*")
            if (m := _ORPHAN.fullmatch(p.name)) and int(m.group(2)) == pid]


def test_kill_9_and_resume_grades_every_submission_exactly_once(tmp_path):
    root = tmp_path / "submissions"
    expected = classgen.make_class(root, 14, problems=["12.43", "12.3", "12.22"], hostile=False, broken=True,
                                   extras=False)
    n = len(expected)
    hw = tmp_path / "hw.toml"
    hw.write_text(classgen.assignment_toml(["12.43", "12.3", "12.22"]))
    db = tmp_path / "hw.sqlite"

    kills, killed = [], []
    for stop_at in (5, 17):  # kill twice, at different points
        proc = _start(root, hw, db)
        deadline = time.monotonic() + 240
        while _count(db, "grade_log") < stop_at and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert proc.poll() is None, f"the run ended before it could be killed: {proc.stderr.read().decode()}"
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        kills.append(_count(db, "grade_log"))
        killed.append(proc.pid)
        # its graders died with it, and nothing could remove their folders (one holds a submission)
        assert _grader_folders(proc.pid)
    assert 0 < kills[0] <= kills[1] < n

    proc = _start(root, hw, db)
    assert proc.wait(timeout=600) == 0, proc.stderr.read().decode()
    assert not [f for pid in killed for f in _grader_folders(pid)], "a later run leaves a killed run's folders"

    con = sqlite3.connect(db)
    log = con.execute("SELECT student, problem, count(*) FROM grade_log GROUP BY student, problem").fetchall()
    assert len(log) == n and all(c == 1 for _, _, c in log), "a submission was graded twice or never"
    assert con.execute("SELECT count(*) FROM grade_log").fetchone()[0] == n
    assert con.execute("SELECT count(*) FROM submissions").fetchone()[0] == n
    part_rows = sum(len(classgen.part_names(e.problem)) for e in expected)
    assert con.execute("SELECT count(*) FROM parts").fetchone()[0] == part_rows
    con.close()
    assert_expected(db, expected)

    # once more: nothing left to grade
    proc = _start(root, hw, db)
    assert proc.wait(timeout=300) == 0
    assert _count(db, "grade_log") == n


def test_what_changes_is_regraded(tmp_path):
    root = tmp_path / "submissions"
    expected = classgen.make_class(root, 4, problems=["12.43", "12.3"], hostile=False, broken=False, extras=False)
    n = len(expected)
    hw = tmp_path / "hw.toml"
    hw.write_text(classgen.assignment_toml(["12.43", "12.3"]))
    db = tmp_path / "hw.sqlite"

    def run(**kw):
        return grade_folder(root, load_assignment(hw), db, workers=2, **kw)

    assert run().todo == n
    assert run().todo == 0
    # weights only scale points: nothing regraded
    hw.write_text(classgen.assignment_toml(["12.43", "12.3"], weights={"12.43": 10}))
    assert run().todo == 0
    # accuracy or limits change the grading: everything regraded
    hw.write_text(classgen.assignment_toml(["12.43", "12.3"], accuracy="strict", weights={"12.43": 10}))
    assert run().todo == n
    # a new grader version regrades everything
    assert run(version="99.0").todo == n
    assert run(version="99.0").todo == 0
    # a removed file drops its result; a new one is graded
    gone = root / expected[0].student / f"{expected[0].problem}.py"
    if not gone.exists():
        gone = gone.with_suffix(".toml")
    gone.unlink()
    r = run(version="99.0")
    assert (r.todo, r.removed) == (0, 1)
    assert _count(db, "submissions") == n - 1
    assert _count(db, "grade_log") == 3 * n  # three full gradings, nothing else


def test_one_writer_at_a_time(tmp_path):
    from lagrade.uses.bulk.store import Store, StoreError

    db = tmp_path / "x.sqlite"
    with Store(db, lock=True):
        try:
            Store(db, lock=True)
        except StoreError as exc:
            assert "another" in str(exc)
        else:
            raise AssertionError("a second writer was let in")


def test_python_answers_are_graded_before_text_answers_each_in_folder_order(tmp_path, monkeypatch):
    """Text answers are short: ending the queue on them keeps graders from waiting on one long file."""
    import lagrade.uses.bulk.runner as runner

    root = tmp_path / "submissions"
    classgen.make_class(root, 12, problems=["12.43"], hostile=False, extras=False)
    hw = tmp_path / "hw.toml"
    hw.write_text(classgen.assignment_toml(["12.43"]))
    seen = []
    monkeypatch.setattr(runner, "run_local", lambda jobs, sources, workers, done: seen.extend(jobs))
    grade_folder(root, load_assignment(hw), tmp_path / "hw.sqlite", workers=2)
    kinds = [job["suffix"] for job in seen]
    assert {".py", ".toml"} <= set(kinds)
    assert kinds == sorted(kinds, key=lambda suffix: suffix != ".py")
    for suffix in (".py", ".toml"):
        students = [job["student"] for job in seen if job["suffix"] == suffix]
        assert students == sorted(students)
