"""The gradebook database (SQLite): schema and exactly-once bookkeeping.

One row per student and problem in ``submissions`` and one per student, problem and part in
``parts``, each carrying the content hash of the file graded, the hash of what the grade depends on
in the assignment (problem file, accuracy, limits) and the grader version. A result is written in
one transaction when its submission finishes, together with a line in ``grade_log``; a submission
is graded again only when one of those three keys changed. Killing the run at any moment loses at
most the submissions in flight (their transactions never committed) and doubles none.

A submission whose grader failed (``grader-crash``, and ``grader-timeout`` in gradebooks of older
versions: lagrade's fault, not the file's) is graded once more by the next run; ``attempts`` counts
the gradings of one key, so that a file that kills its grader every time is not retried forever. A
file that hit a bound (the grading CPU bound, the hard deadline, the sandbox's time or memory) is
the file's cost: ``timeout`` or ``memory``, final, with the reason.

Only the coordinating process writes; workers send their results to it. A path that is not a
gradebook (a folder, another file, another program's database, a damaged one) is refused with
:class:`NotAGradebook` before anything is written to it.
"""

from __future__ import annotations

import fcntl
import json
import os
import sqlite3
import stat
import time
from dataclasses import dataclass
from pathlib import Path

SCHEMA_VERSION = 1  # columns added since are added to older gradebooks on opening (COLUMNS_ADDED)

#: statuses that are the grader's failure, not the file's: graded again by the next run
RETRIED_STATUSES = ("grader-crash", "grader-timeout")
#: gradings of one key (file, grading, grader version) after which a grader failure stays
MAX_ATTEMPTS = 2

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
    attempts       INTEGER NOT NULL DEFAULT 1,  -- gradings of this key (a grader failure is retried)
    jail           TEXT,                   -- the sandbox layers the file ran under, as the grader said
    plot_png       BLOB,                   -- the picture of its wrong motions (`lagrade check --plot`'s), if drawn
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
    review         TEXT,                  -- for the instructor: why the evidence could not decide the verdict
    detail         TEXT,                  -- for the instructor: the engine's traceback of an `error` verdict
    certificate    TEXT,                  -- for the instructor: the exact point and enclosure proving a rejection
    motion_evidence TEXT,                 -- for the instructor: JSON, a refutation by the motion (time, separation, error estimate, tolerances)
    file_hash      TEXT NOT NULL,
    grader_version TEXT NOT NULL,
    PRIMARY KEY (student, problem, part),
    FOREIGN KEY (student, problem) REFERENCES submissions (student, problem) ON DELETE CASCADE
);
CREATE TABLE IF NOT EXISTS skipped (
    path   TEXT PRIMARY KEY,
    reason TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS overrides (  -- an instructor's score for a part: kept across regrades
    student    TEXT NOT NULL,
    problem    TEXT NOT NULL,
    part       TEXT NOT NULL,
    score      REAL NOT NULL,              -- on the part's own scale (0 .. max_score)
    max_score  REAL NOT NULL,
    reason     TEXT NOT NULL,
    set_at     TEXT NOT NULL,
    PRIMARY KEY (student, problem, part)
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


#: (table, column, definition) added after SCHEMA_VERSION 1: ALTER TABLE ... ADD COLUMN when missing
COLUMNS_ADDED = [
    ("submissions", "attempts", "INTEGER NOT NULL DEFAULT 1"),
    ("submissions", "jail", "TEXT"),
    ("parts", "review", "TEXT"),
    ("parts", "detail", "TEXT"),
    ("submissions", "plot_png", "BLOB"),
    ("parts", "certificate", "TEXT"),
    ("parts", "motion_evidence", "TEXT"),
]
#: ``overrides`` came after SCHEMA_VERSION 1: ``CREATE TABLE IF NOT EXISTS`` adds it to an older gradebook
#: when a writer opens it; readers of an older gradebook see no overrides (:meth:`Store.overrides`)
TABLES = {"meta", "students", "submissions", "parts", "skipped", "grade_log", "sqlite_sequence", "overrides"}
SQLITE_MAGIC = b"SQLite format 3\x00"


class StoreError(RuntimeError):
    pass


class NotAGradebook(StoreError):
    """The path cannot be used as a gradebook (the message names it and says why); it was left as it was."""


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
        _check_file(self.path, create)
        self._lock_fd = None
        self.db = None
        self._borrowed = False  # Store.over: the connection is someone else's to close
        if lock:
            try:
                self._lock_fd = os.open(str(self.path) + ".lock", os.O_RDWR | os.O_CREAT, 0o644)
            except OSError as exc:
                raise NotAGradebook(f"{self.path}.lock cannot be made ({exc.strerror})") from None
            try:
                fcntl.flock(self._lock_fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                os.close(self._lock_fd)
                raise StoreError(f"{self.path}: another 'lagrade grade' is writing to this database") from None
        try:
            self._open(create, check=lock)
        except sqlite3.DatabaseError as exc:
            self.close()
            what = "cannot be opened" if isinstance(exc, sqlite3.OperationalError) else "is not a lagrade gradebook"
            raise NotAGradebook(f"{self.path} {what} ({exc})") from None
        except StoreError:
            self.close()
            raise

    def _open(self, create: bool, check: bool) -> None:
        """Connect, refuse another program's database, then (``create``) make or migrate the schema.

        ``check``: a grading run first reads every page (``PRAGMA quick_check``, milliseconds per
        megabyte), so that it never writes into a damaged file; readers fail on the page they read."""
        self.db = sqlite3.connect(self.path, isolation_level=None, timeout=30)
        self.db.row_factory = sqlite3.Row
        tables = {r[0] for r in self.db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
        if tables - TABLES and not ("meta" in tables and self.meta("schema_version") is not None):
            raise NotAGradebook(f"{self.path} is not a lagrade gradebook (an SQLite database of something else)")
        if check:
            bad = [r[0] for r in self.db.execute("PRAGMA quick_check(3)")]
            if bad != ["ok"]:
                raise NotAGradebook(f"{self.path} is not a lagrade gradebook (damaged: {'; '.join(bad)})")
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
            self._migrate()

    @classmethod
    def over(cls, connection: sqlite3.Connection, path: Path | str) -> "Store":
        """A reader over a connection someone else opened and keeps (the server's own, to the file it
        serves): it never opens the file, and :meth:`close` leaves the connection open.

        Why: opening and closing any descriptor of a database file in a process drops every POSIX
        lock that process holds on it (SQLite's own connections share theirs, a second open does
        not), and another process's last connection then deletes the write-ahead log under the
        server. The connection's ``row_factory`` must be :class:`sqlite3.Row` while it is read."""
        store = cls.__new__(cls)
        store.path, store.db, store._lock_fd, store._borrowed = Path(path), connection, None, True
        return store

    def _migrate(self) -> None:
        """Add the columns that gradebooks written by an older lagrade lack (their rows get the default)."""
        for table, column, definition in COLUMNS_ADDED:
            if column not in self._columns(table):
                self.db.execute(f"ALTER TABLE {table} ADD COLUMN {column} {definition}")

    def close(self) -> None:
        if self.db is not None:
            if not self._borrowed:
                self.db.close()
            self.db = None
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

    def retries(self) -> set[tuple[str, str]]:
        """(student, problem) of stored grader failures to grade once more although their key is unchanged."""
        rows = self.db.execute(f"SELECT student, problem FROM submissions WHERE status IN "
                               f"({', '.join('?' * len(RETRIED_STATUSES))}) AND attempts < ?",
                               (*RETRIED_STATUSES, MAX_ATTEMPTS))
        return {(r[0], r[1]) for r in rows}

    def unplotted(self) -> set[tuple[str, str]]:
        """(student, problem) of graded files with a part not correct whose picture was never asked for
        (``plot_png`` NULL; an empty one means asked, and nothing to draw)."""
        rows = self.db.execute("SELECT student, problem FROM submissions s WHERE outcome = 'graded' AND plot_png IS NULL "
                               "AND EXISTS (SELECT 1 FROM parts p WHERE p.student = s.student AND p.problem = s.problem "
                               "AND p.verdict != 'correct')")
        return {(r[0], r[1]) for r in rows}

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
               seconds: float, parts: list[dict], jail: str | None = None, plot_png: bytes | None = None) -> bool:
        """Write one graded submission in its own transaction. False if that exact grade is already stored
        (a stored grader failure with attempts left is replaced, and its attempts counted)."""
        with self.transaction():
            row = self.db.execute("SELECT file_hash, grading_hash, grader_version, status, attempts FROM submissions "
                                  "WHERE student = ? AND problem = ?", (student, problem)).fetchone()
            attempts = 1
            if row is not None and Key(*row[:3]) == key:
                if row["status"] not in RETRIED_STATUSES or row["attempts"] >= MAX_ATTEMPTS:
                    return False
                attempts = row["attempts"] + 1
            now = _now()
            self.db.execute("DELETE FROM submissions WHERE student = ? AND problem = ?", (student, problem))
            self.db.execute(
                "INSERT INTO submissions(student, problem, path, file_hash, grading_hash, grader_version, outcome, "
                "status, reason, score, max_score, problems, stdout, source, seconds, graded_at, attempts, jail, plot_png) "
                "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (student, problem, path, key.file_hash, key.grading_hash, key.grader_version, outcome, status,
                 reason, score, max_score, json.dumps(problems), stdout, source, seconds, now, attempts, jail,
                 plot_png))
            self.db.executemany(
                "INSERT INTO parts(student, problem, part, verdict, score, max_score, method, feedback, answer_text, "
                "answer_mathml, review, detail, certificate, motion_evidence, file_hash, grader_version) "
                "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                [(student, problem, p["part"], p["verdict"], p["score"], p["max_score"], p["method"], p["feedback"],
                  p.get("answer_text"), p.get("answer_mathml"), p.get("review"), p.get("detail"), p.get("certificate"),
                  json.dumps(p["motion_evidence"]) if p.get("motion_evidence") else None, key.file_hash, key.grader_version) for p in parts])
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
        """Every part, with the ``jail`` its file was graded in (the gradebook's readers see parts only).

        A reader does not migrate: a gradebook from before the column has no jail to show."""
        jail = "submissions.jail" if "jail" in self._columns("submissions") else "NULL"
        return self.db.execute(f"SELECT parts.*, {jail} AS jail FROM parts JOIN submissions "
                               "USING (student, problem) ORDER BY student, problem, parts.rowid").fetchall()

    def _columns(self, table: str) -> set[str]:
        return {r[1] for r in self.db.execute(f"PRAGMA table_info({table})")}

    def set_override(self, *, student: str, problem: str, part: str, score: float, max_score: float,
                     reason: str) -> None:
        """Record (or replace) an instructor's score for one part; grading never touches it."""
        with self.transaction():
            self.db.execute("INSERT INTO overrides(student, problem, part, score, max_score, reason, set_at) "
                            "VALUES(?, ?, ?, ?, ?, ?, ?) ON CONFLICT(student, problem, part) DO UPDATE SET "
                            "score = excluded.score, max_score = excluded.max_score, reason = excluded.reason, "
                            "set_at = excluded.set_at", (student, problem, part, score, max_score, reason, _now()))

    def remove_override(self, student: str, problem: str, part: str) -> bool:
        with self.transaction():
            cur = self.db.execute("DELETE FROM overrides WHERE student = ? AND problem = ? AND part = ?",
                                  (student, problem, part))
        return cur.rowcount > 0

    def overrides(self) -> list[sqlite3.Row]:
        """Every override (none in a gradebook older than the table, which a reader does not migrate)."""
        if not self.db.execute("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'overrides'").fetchone():
            return []
        return self.db.execute("SELECT * FROM overrides ORDER BY student, problem, part").fetchall()

    def skipped(self) -> list[sqlite3.Row]:
        return self.db.execute("SELECT * FROM skipped ORDER BY path").fetchall()


def _check_file(path: Path, create: bool) -> None:
    """Refuse, before SQLite opens it, a path that cannot be a gradebook: a folder, a device or a
    FIFO (opening one can block), a file this user cannot read, a file that does not begin as every
    SQLite database does (an empty file is a new one). SQLite's own errors name neither the file
    nor what to do."""
    try:
        st = path.stat()
    except FileNotFoundError:
        if create:
            return
        raise NotAGradebook(f"{path} does not exist") from None
    except OSError as exc:
        raise NotAGradebook(f"{path} cannot be opened ({exc.strerror})") from None
    if stat.S_ISDIR(st.st_mode):
        raise NotAGradebook(f"{path} is not a lagrade gradebook (it is a folder)")
    if not stat.S_ISREG(st.st_mode):
        raise NotAGradebook(f"{path} is not a lagrade gradebook (not a regular file)")
    try:
        with open(path, "rb") as fh:
            head = fh.read(len(SQLITE_MAGIC))
    except OSError as exc:
        raise NotAGradebook(f"{path} cannot be read ({exc.strerror})") from None
    if head and head != SQLITE_MAGIC:
        raise NotAGradebook(f"{path} is not a lagrade gradebook (file is not a database)")


class _Transaction:
    def __init__(self, db: sqlite3.Connection) -> None:
        self.db = db

    def __enter__(self) -> None:
        self.db.execute("BEGIN IMMEDIATE")

    def __exit__(self, exc_type, exc, tb) -> None:
        self.db.execute("COMMIT" if exc_type is None else "ROLLBACK")
