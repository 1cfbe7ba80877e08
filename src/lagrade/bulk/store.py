"""The gradebook database (SQLite): schema and exactly-once bookkeeping.

One row per student and problem in ``submissions`` and one per student, problem and part in
``parts``, each carrying the content hash of the file graded, the hash of what the grade depends on
in the assignment (problem file, accuracy, limits) and the grader version. A result is written in
one transaction when its submission finishes, together with a line in ``grade_log``; a submission
is graded again only when one of those three keys changed. Killing the run at any moment loses at
most the submissions in flight (their transactions never committed) and doubles none.

Only the coordinating process writes; workers send their results to it.
"""

from __future__ import annotations

import fcntl
import json
import os
import sqlite3
import time
from dataclasses import dataclass
from pathlib import Path

SCHEMA_VERSION = 1

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (
    key   TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS students (
    student TEXT PRIMARY KEY
);
CREATE TABLE IF NOT EXISTS submissions (
    student        TEXT NOT NULL,
    problem        TEXT NOT NULL,
    path           TEXT NOT NULL,          -- relative to the submissions folder
    file_hash      TEXT NOT NULL,          -- sha256 of the bytes graded
    grading_hash   TEXT NOT NULL,          -- problem file + accuracy + limits (Assignment.grading_hash)
    grader_version TEXT NOT NULL,
    outcome        TEXT NOT NULL CHECK (outcome IN ('graded', 'failed')),
    status         TEXT NOT NULL,          -- the sandbox's: ok error timeout memory crashed rejected; or grader-timeout grader-crash
    reason         TEXT NOT NULL DEFAULT '',  -- why the file could not be used (empty when it ran)
    score          REAL NOT NULL,          -- the engine's score (problem-file weights)
    max_score      REAL NOT NULL,
    problems       TEXT NOT NULL DEFAULT '[]',  -- JSON list: what was wrong with the file itself
    stdout         TEXT NOT NULL DEFAULT '',
    source         TEXT NOT NULL DEFAULT '',    -- the file as graded (for the feedback pages)
    seconds        REAL NOT NULL,
    graded_at      TEXT NOT NULL,
    PRIMARY KEY (student, problem)
);
CREATE TABLE IF NOT EXISTS parts (
    student        TEXT NOT NULL,
    problem        TEXT NOT NULL,
    part           TEXT NOT NULL,
    verdict        TEXT NOT NULL,
    score          REAL NOT NULL,
    max_score      REAL NOT NULL,
    method         TEXT NOT NULL,
    feedback       TEXT NOT NULL,
    answer_text    TEXT,                  -- the value as lagrade read it (sympy str)
    answer_mathml  TEXT,                  -- the same as presentation MathML, for the report
    file_hash      TEXT NOT NULL,
    grader_version TEXT NOT NULL,
    PRIMARY KEY (student, problem, part),
    FOREIGN KEY (student, problem) REFERENCES submissions (student, problem) ON DELETE CASCADE
);
CREATE TABLE IF NOT EXISTS skipped (
    path   TEXT PRIMARY KEY,
    reason TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS grade_log (   -- append-only: one line per committed grade
    id             INTEGER PRIMARY KEY AUTOINCREMENT,
    student        TEXT NOT NULL,
    problem        TEXT NOT NULL,
    file_hash      TEXT NOT NULL,
    grading_hash   TEXT NOT NULL,
    grader_version TEXT NOT NULL,
    graded_at      TEXT NOT NULL
);
"""


class StoreError(RuntimeError):
    pass


@dataclass(frozen=True)
class Key:
    file_hash: str
    grading_hash: str
    grader_version: str


def _now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime()) + "Z"


class Store:
    """A gradebook database. ``Store(path, lock=True)`` for a grading run (one writer at a time)."""

    def __init__(self, path: Path | str, *, lock: bool = False, create: bool = True) -> None:
        self.path = Path(path)
        if not create and not self.path.is_file():
            raise StoreError(f"{self.path}: no such gradebook database")
        self._lock_fd = None
        if lock:
            self._lock_fd = os.open(str(self.path) + ".lock", os.O_RDWR | os.O_CREAT, 0o644)
            try:
                fcntl.flock(self._lock_fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                os.close(self._lock_fd)
                raise StoreError(f"{self.path}: another 'lagrade grade' is writing to this database") from None
        self.db = sqlite3.connect(self.path, isolation_level=None, timeout=30)
        self.db.row_factory = sqlite3.Row
        self.db.execute("PRAGMA journal_mode=WAL")
        self.db.execute("PRAGMA synchronous=FULL")
        self.db.execute("PRAGMA foreign_keys=ON")
        if create:
            self.db.executescript(SCHEMA)
            version = self.meta("schema_version")
            if version is None:
                self.set_meta("schema_version", str(SCHEMA_VERSION))
            elif int(version) != SCHEMA_VERSION:
                raise StoreError(f"{self.path}: schema version {version}, this lagrade writes {SCHEMA_VERSION}")

    def close(self) -> None:
        self.db.close()
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None

    def __enter__(self) -> "Store":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # ------------------------------------------------------------------ meta

    def meta(self, key: str) -> str | None:
        row = self.db.execute("SELECT value FROM meta WHERE key = ?", (key,)).fetchone()
        return row[0] if row else None

    def set_meta(self, key: str, value: str) -> None:
        self.db.execute("INSERT INTO meta(key, value) VALUES(?, ?) ON CONFLICT(key) DO UPDATE SET value = excluded.value",
                        (key, value))

    # ------------------------------------------------------------------ the run

    def keys(self) -> dict[tuple[str, str], Key]:
        rows = self.db.execute("SELECT student, problem, file_hash, grading_hash, grader_version FROM submissions")
        return {(r[0], r[1]): Key(r[2], r[3], r[4]) for r in rows}

    def sync_layout(self, students: list[str], skipped: list[tuple[str, str]],
                    present: set[tuple[str, str]]) -> int:
        """Record the roster and the skipped files; drop results whose file is gone. Returns how many."""
        with self.transaction():
            self.db.execute("DELETE FROM students")
            self.db.executemany("INSERT INTO students(student) VALUES(?)", [(s,) for s in students])
            self.db.execute("DELETE FROM skipped")
            self.db.executemany("INSERT OR REPLACE INTO skipped(path, reason) VALUES(?, ?)", skipped)
            stale = [k for k in self.keys() if k not in present]
            self.db.executemany("DELETE FROM submissions WHERE student = ? AND problem = ?", stale)
        return len(stale)

    def transaction(self):
        return _Transaction(self.db)

    def record(self, *, student: str, problem: str, path: str, key: Key, outcome: str, status: str,
               reason: str, score: float, max_score: float, problems: list[str], stdout: str, source: str,
               seconds: float, parts: list[dict]) -> bool:
        """Write one graded submission in its own transaction. False if that exact grade is already stored."""
        with self.transaction():
            row = self.db.execute("SELECT file_hash, grading_hash, grader_version FROM submissions "
                                  "WHERE student = ? AND problem = ?", (student, problem)).fetchone()
            if row is not None and Key(*row) == key:
                return False
            now = _now()
            self.db.execute("DELETE FROM submissions WHERE student = ? AND problem = ?", (student, problem))
            self.db.execute(
                "INSERT INTO submissions(student, problem, path, file_hash, grading_hash, grader_version, outcome, "
                "status, reason, score, max_score, problems, stdout, source, seconds, graded_at) "
                "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (student, problem, path, key.file_hash, key.grading_hash, key.grader_version, outcome, status,
                 reason, score, max_score, json.dumps(problems), stdout, source, seconds, now))
            self.db.executemany(
                "INSERT INTO parts(student, problem, part, verdict, score, max_score, method, feedback, answer_text, "
                "answer_mathml, file_hash, grader_version) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                [(student, problem, p["part"], p["verdict"], p["score"], p["max_score"], p["method"], p["feedback"],
                  p.get("answer_text"), p.get("answer_mathml"), key.file_hash, key.grader_version) for p in parts])
            self.db.execute("INSERT INTO grade_log(student, problem, file_hash, grading_hash, grader_version, graded_at) "
                            "VALUES(?, ?, ?, ?, ?, ?)",
                            (student, problem, key.file_hash, key.grading_hash, key.grader_version, now))
        return True

    # ------------------------------------------------------------------ reading

    def students(self) -> list[str]:
        return [r[0] for r in self.db.execute("SELECT student FROM students ORDER BY student")]

    def submissions(self) -> list[sqlite3.Row]:
        return self.db.execute("SELECT * FROM submissions ORDER BY student, problem").fetchall()

    def parts(self) -> list[sqlite3.Row]:
        return self.db.execute("SELECT * FROM parts ORDER BY student, problem, rowid").fetchall()

    def skipped(self) -> list[sqlite3.Row]:
        return self.db.execute("SELECT * FROM skipped ORDER BY path").fetchall()


class _Transaction:
    def __init__(self, db: sqlite3.Connection) -> None:
        self.db = db

    def __enter__(self) -> None:
        self.db.execute("BEGIN IMMEDIATE")

    def __exit__(self, exc_type, exc, tb) -> None:
        self.db.execute("COMMIT" if exc_type is None else "ROLLBACK")
