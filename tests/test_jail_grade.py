"""`lagrade grade` refuses a class where the jail cannot be built, unless told the files are trusted,
and `lagrade doctor` says which layers a machine gives. The missing layer is real: the grader's
zygote is started with a ``pyseccomp`` that cannot be imported, as on a machine without libseccomp."""

from __future__ import annotations

import json
import re
import os
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest

from lagrade.problem.library import reference_dir

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the OS jail is Linux's")


def _lagrade(*args: str, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lagrade", *args], capture_output=True, text=True,
                          env={**os.environ, **(env or {})}, timeout=300)


def _without_seccomp(tmp_path: Path) -> dict:
    fake = tmp_path / "no-seccomp"
    fake.mkdir()
    (fake / "pyseccomp.py").write_text("raise ImportError('libseccomp is not installed')\n")
    return {"PYTHONPATH": os.pathsep.join([str(fake), *[p for p in sys.path if p]])}


def _class(tmp_path: Path) -> tuple[Path, Path]:
    subs = tmp_path / "submissions" / "ada"
    subs.mkdir(parents=True)
    (subs / "12.43.py").write_text((reference_dir() / "12.43" / "answer.py").read_text())
    hw = tmp_path / "hw.toml"
    hw.write_text('name = "hw"\n[[problems]]\nid = "12.43"\n')
    return tmp_path / "submissions", hw


def test_doctor_reports_every_layer_and_a_probe(tmp_path):
    out = _lagrade("doctor", "--json")
    report = json.loads(out.stdout)
    if os.geteuid() == 0:
        assert report["active"] == ["uid", "mount", "pid", "network", "no_new_privs", "limits", "landlock", "seccomp"]
        assert out.returncode == 0 and report["can_grade"]
        assert report["probe"]["uid"] != 0
        assert all(v != "done" for k, v in report["probe"].items() if k not in ("uid", "ppid")), report["probe"]


def test_doctor_names_a_missing_layer(tmp_path):
    out = _lagrade("doctor", env=_without_seccomp(tmp_path))
    assert out.returncode == 1
    assert "seccomp       MISSING  libseccomp or its 'pyseccomp' binding is missing" in out.stdout, out.stdout
    assert "will refuse" in out.stdout


def test_grade_refuses_without_the_jail_and_grades_when_told_the_files_are_trusted(tmp_path):
    subs, hw = _class(tmp_path)
    db = tmp_path / "hw.sqlite"
    env = _without_seccomp(tmp_path)
    refused = _lagrade("grade", str(subs), "-a", str(hw), "--db", str(db), "--no-progress", env=env)
    assert refused.returncode == 1
    lines = [line for line in refused.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and "refusing to run students' files: the jail lacks seccomp" in lines[0], refused.stderr
    assert "Traceback" not in refused.stderr and not db.exists()
    graded = _lagrade("grade", str(subs), "-a", str(hw), "--db", str(db), "--no-progress",
                      "--unsafe-trusted-files", env=env)
    assert graded.returncode == 0, graded.stderr
    assert "grading anyway" in graded.stderr
    with sqlite3.connect(db) as con:
        (score, max_score), = con.execute("SELECT score, max_score FROM submissions").fetchall()
        columns = [r[1] for r in con.execute("PRAGMA table_info(submissions)")]
        if "jail" in columns:
            (layers,), = con.execute("SELECT jail FROM submissions").fetchall()
            assert "seccomp" not in layers and "landlock" in layers
    assert score == max_score > 0


@pytest.mark.slow
def test_a_class_graded_with_the_jail_alone_shows_no_student_another_ones_file(tmp_path):
    """Issue 43, item 1, end to end: one ``lagrade grade`` grader (the same one the course server's
    queue runs, :class:`lagrade.uses.bulk.worker.GraderProcess`) with the tripwires off grades, in
    folder order, three students whose files hold a unique line and, after each, a student whose
    answer searches its own memory for that line: the search (whose control shows it reaches the
    heap) finds it in none of the three rounds, so no student's feedback can quote another's file."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import memory_scan

    text = memory_scan.marker()
    honest = (reference_dir() / "12.43" / "answer.py").read_text()
    for i in range(3):
        for who, source in ((f"r{i}a-victim", memory_scan.victim(text, honest)),
                            (f"r{i}b-scanner", memory_scan.scanner(text))):
            folder = tmp_path / "submissions" / who
            folder.mkdir(parents=True)
            (folder / "12.43.py").write_text(source)
    hw = tmp_path / "hw.toml"
    hw.write_text('name = "hw"\n[[problems]]\nid = "12.43"\n')
    db = tmp_path / "hw.sqlite"
    tripwires_off = Path(__file__).resolve().parent / "security" / "tripwires_off"
    env = {"PYTHONPATH": os.pathsep.join([str(tripwires_off), *[p for p in sys.path if p]])}
    graded = _lagrade("grade", str(tmp_path / "submissions"), "-a", str(hw), "--db", str(db), "--no-progress",
                      "--workers", "1", env=env)
    assert graded.returncode == 0, graded.stderr
    with sqlite3.connect(db) as con:
        rows = dict(con.execute("SELECT student, problems FROM submissions ORDER BY student").fetchall())
    assert len(rows) == 6, rows
    for i in range(3):
        (message,) = [str(p) for p in json.loads(rows[f"r{i}b-scanner"]) if "memory scan" in str(p)]
        found, control = (int(n) for n in re.findall(r"(\d+) (?:found|control)", message))
        assert control >= 1, f"the control failed: the search does not reach the heap ({message})"
        assert found == 0, f"round {i}: {message}: the grader's zygote held the earlier student's file"
