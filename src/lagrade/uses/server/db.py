"""The server's database through SQLAlchemy: the gradebook of ``lagrade grade`` plus its own table.

The gradebook tables (``meta``, ``students``, ``submissions``, ``parts``, ``skipped``,
``grade_log``) mirror :data:`lagrade.uses.bulk.store.SCHEMA` column for column, so that ``lagrade
export`` and ``lagrade report`` read a server's SQLite file as they read ``lagrade grade``'s; on
SQLite the file is even created by :class:`lagrade.uses.bulk.store.Store` itself, so the two cannot drift
(a test compares the tables too). ``server_submissions`` keeps every attempt with its file, stored
*before* it is graded: a server killed mid-grade grades what is left when it starts again. The
gradebook holds each student's latest graded attempt per problem, as ``lagrade grade`` holds the
file in the folder.

SQLite by default (one file), PostgreSQL by URL (``postgresql+psycopg://...``). Writes go through
one lock: the server is one process, and SQLite wants one writer.

One server per database (:meth:`Database.claim`): the grading queue and the rate limits live in the
server's process, so a second server on the same database would grade the same attempts twice and
double every limit. It is refused in one line; the claim is an OS lock (a POSIX lock on a file next
to the SQLite file, a session advisory lock on PostgreSQL), so a server killed with ``kill -9``
leaves nothing to clean up: the next one starts.
"""

from __future__ import annotations

import json
import secrets
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sqlalchemy import (
    CheckConstraint,
    Column,
    Float,
    ForeignKeyConstraint,
    Integer,
    LargeBinary,
    MetaData,
    String,
    Table,
    Text,
    UniqueConstraint,
    create_engine,
    delete,
    event,
    func,
    insert,
    select,
    update,
)
from sqlalchemy.engine import Engine
from sqlalchemy.exc import IntegrityError

from lagrade.uses.bulk.store import SCHEMA_VERSION
from lagrade.uses.server.tokens import SESSION_SECONDS

metadata = MetaData()

meta = Table("meta", metadata, Column("key", String(200), primary_key=True), Column("value", Text, nullable=False))
students = Table("students", metadata, Column("student", String(200), primary_key=True))
submissions = Table(
    "submissions", metadata,
    Column("student", String(200), primary_key=True), Column("problem", String(50), primary_key=True),
    Column("path", Text, nullable=False), Column("file_hash", String(64), nullable=False),
    Column("grading_hash", String(64), nullable=False), Column("grader_version", String(50), nullable=False),
    Column("outcome", String(20), nullable=False), Column("status", String(30), nullable=False),
    Column("reason", Text, nullable=False, server_default=""), Column("score", Float, nullable=False),
    Column("max_score", Float, nullable=False), Column("problems", Text, nullable=False, server_default="[]"),
    Column("stdout", Text, nullable=False, server_default=""), Column("source", Text, nullable=False, server_default=""),
    Column("seconds", Float, nullable=False), Column("graded_at", String(30), nullable=False),
    Column("attempts", Integer, nullable=False, server_default="1"), Column("jail", Text),
    Column("plot_png", LargeBinary),
    CheckConstraint("outcome IN ('graded', 'failed')"),
)
parts = Table(
    "parts", metadata,
    Column("student", String(200), primary_key=True), Column("problem", String(50), primary_key=True),
    Column("part", String(100), primary_key=True), Column("verdict", String(20), nullable=False),
    Column("score", Float, nullable=False), Column("max_score", Float, nullable=False),
    Column("method", String(20), nullable=False), Column("feedback", Text, nullable=False),
    Column("answer_text", Text), Column("answer_mathml", Text), Column("review", Text), Column("detail", Text),
    Column("certificate", Text), Column("motion_evidence", Text),
    Column("file_hash", String(64), nullable=False), Column("grader_version", String(50), nullable=False),
    ForeignKeyConstraint(["student", "problem"], ["submissions.student", "submissions.problem"], ondelete="CASCADE"),
)
skipped = Table("skipped", metadata, Column("path", String(500), primary_key=True), Column("reason", Text, nullable=False))
overrides = Table(
    "overrides", metadata,
    Column("student", String(200), primary_key=True), Column("problem", String(50), primary_key=True),
    Column("part", String(100), primary_key=True), Column("score", Float, nullable=False),
    Column("max_score", Float, nullable=False), Column("reason", Text, nullable=False),
    Column("set_at", String(30), nullable=False),
)
grade_log = Table(
    "grade_log", metadata, Column("id", Integer, primary_key=True, autoincrement=True),
    Column("student", String(200), nullable=False), Column("problem", String(50), nullable=False),
    Column("file_hash", String(64), nullable=False), Column("grading_hash", String(64), nullable=False),
    Column("grader_version", String(50), nullable=False), Column("graded_at", String(30), nullable=False),
    sqlite_autoincrement=True,
)
GRADEBOOK_TABLES = (meta, students, submissions, parts, skipped, overrides, grade_log)

#: every attempt, with its file; ``state`` is ``queued`` until its grade is written
server_submissions = Table(
    "server_submissions", metadata,
    Column("id", Integer, primary_key=True, autoincrement=True),
    Column("student", String(200), nullable=False), Column("problem", String(50), nullable=False),
    Column("suffix", String(10), nullable=False), Column("file_hash", String(64), nullable=False),
    Column("grading_hash", String(64), nullable=False), Column("grader_version", String(50), nullable=False),
    Column("data", LargeBinary, nullable=False), Column("state", String(10), nullable=False),
    Column("result", Text), Column("created_at", String(30), nullable=False), Column("graded_at", String(30)),
    UniqueConstraint("student", "problem", "file_hash", "grading_hash", "grader_version", name="one_grade_per_content"),
    CheckConstraint("state IN ('queued', 'graded')"),
    sqlite_autoincrement=True,
)

#: browser sessions: the cookie holds a random session id, never the student's token; the table keeps
#: its hash (a copy of the database does not sign anyone in), and sign-out deletes the row;
#: ``last_seen``: when the session was last used (at most :data:`SEEN_EVERY` seconds stale), for the
#: idle limit (``ServerConfig.session_idle_minutes``); NULL in a row of an older server (then ``created_at``)
server_sessions = Table(
    "server_sessions", metadata,
    Column("key", String(64), primary_key=True), Column("student", String(200), nullable=False),
    Column("created_at", Float, nullable=False), Column("last_seen", Float),
)
#: a session's ``last_seen`` is written again only when it is older than this (not a write per request)
SEEN_EVERY = 60.0


class NotAServerDatabase(ValueError):
    """An existing file that is not a course server's database (empty, another program's, a
    gradebook of ``lagrade grade``): refused, never made into a new course with a new secret."""


def shown(db: str) -> str:
    """``db`` as it may be printed: a URL's password masked (``postgresql+psycopg://user:***@host/db``)."""
    if "://" not in db:
        return db
    try:
        from sqlalchemy.engine import make_url

        return make_url(db).render_as_string(hide_password=True)
    except Exception:  # noqa: BLE001  (a URL SQLAlchemy cannot read: nothing after the scheme is shown)
        return db.split("://", 1)[0] + "://***"


def masked(text: str, db: str) -> str:
    """``text`` (an error's message) with the password of ``db`` masked wherever it appears."""
    if "://" not in db:
        return text
    try:
        from sqlalchemy.engine import make_url

        password = make_url(db).password
    except Exception:  # noqa: BLE001
        return text.replace(db, shown(db))
    text = text.replace(db, shown(db))
    return text.replace(str(password), "***") if password else text


def refuse_foreign(path: Path) -> None:
    """Refuse an existing file that is not a server's database, in one line (a path that does not
    exist is a new course). An empty file would otherwise be made into a new course silently, with
    a new signing secret: every token issued would stop working."""
    import sqlite3

    if not path.exists() or path.is_dir():
        return  # a folder: Store says so
    advice = "give the course's database with --db, or a path that does not exist yet to start a new course"
    if path.stat().st_size == 0:
        raise NotAServerDatabase(f"{path} is empty (0 bytes), not a lagrade serve database; {advice}")
    try:
        con = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
        try:
            tables = {r[0] for r in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
        finally:
            con.close()
    except sqlite3.DatabaseError:
        raise NotAServerDatabase(f"{path} is not a lagrade serve database (not an SQLite file); {advice}") from None
    if "server_submissions" not in tables:
        what = "a gradebook of lagrade grade" if "submissions" in tables else "an SQLite database of something else"
        raise NotAServerDatabase(f"{path} is not a lagrade serve database ({what}); {advice}")


class AttemptsUsed(RuntimeError):
    """A student has made every attempt at a problem the assignment's rules allow."""


class DatabaseBusy(RuntimeError):
    """Another server serves this database already; the message says which and what to do."""


#: the PostgreSQL advisory lock a server holds for its whole life (locks are per database): "lgserve1"
SERVE_LOCK_KEY = int.from_bytes(b"lgserve1", "big") - (1 << 63)
#: SQLite lock files this process holds (a POSIX lock does not conflict with its own process)
_CLAIMED: set[str] = set()

#: the picture of a wrong dynamics part (`lagrade check --plot`'s, a PNG), by attempt: apart from the
#: attempt's row, which every list of attempts reads
server_plots = Table(
    "server_plots", metadata,
    Column("id", Integer, primary_key=True, autoincrement=False), Column("png", LargeBinary, nullable=False),
    ForeignKeyConstraint(["id"], ["server_submissions.id"], ondelete="CASCADE"),
)


def _session_key(sid: str) -> str:
    import hashlib

    return hashlib.sha256(sid.encode()).hexdigest()


def _now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime()) + "Z"


def database_url(db: str) -> str:
    """A path is a SQLite file; anything with ``://`` is an SQLAlchemy URL."""
    if "://" in db:
        return db
    return f"sqlite:///{Path(db).resolve()}"


@dataclass(frozen=True)
class Attempt:
    id: int
    student: str
    problem: str
    suffix: str
    file_hash: str
    state: str
    result: dict | None
    created_at: str
    data: bytes

    @property
    def graded(self) -> bool:
        return self.state == "graded"


class Database:
    """The server's gradebook; ``Database("hw7-serve.sqlite")`` or ``Database("postgresql+psycopg://...")``."""

    def __init__(self, db: str, *, claim: bool = False) -> None:
        """``claim``: hold the database for this server (:meth:`claim`); on SQLite before `Store` opens
        the file to read its header, so that a second server in this process, refused, never opens
        and closes a descriptor of the file (that would drop the first one's POSIX locks on it)."""
        self.url = database_url(db)
        self.sqlite_path: Path | None = None
        self._write = threading.Lock()
        self._claim: Any = None  # the lock file (SQLite) or the connection holding the lock (PostgreSQL)
        if self.url.startswith("sqlite:///"):
            self.sqlite_path = Path(self.url.removeprefix("sqlite:///"))
        try:
            self._open(claim)
            if claim:
                self.claim()
        except BaseException:
            self.release()
            raise

    def _open(self, claim: bool) -> None:
        if self.sqlite_path is not None:
            from lagrade.uses.bulk.store import Store

            refuse_foreign(self.sqlite_path)  # through SQLite itself, which shares the process's locks
            if claim:
                self.claim()
            Store(self.sqlite_path).close()  # the gradebook schema, exactly as `lagrade grade` makes it
            self.engine: Engine = create_engine(self.url, connect_args={"timeout": 30, "check_same_thread": False})
            event.listen(self.engine, "connect", _sqlite_pragmas)
            metadata.create_all(self.engine, tables=[server_submissions, server_plots, server_sessions])
            self._add_last_seen()
        else:
            self.engine = create_engine(self.url, pool_pre_ping=True)
            metadata.create_all(self.engine)
            self._add_missing_columns()
            self._add_last_seen()
        with self._write, self.engine.begin() as c:
            if self._meta(c, "schema_version") is None:
                self._set_meta(c, "schema_version", str(SCHEMA_VERSION))

    def _add_missing_columns(self) -> None:
        """A database of an older server lacks the gradebook's newer columns (`COLUMNS_ADDED`):
        create_all makes missing tables only, so they are added here, as `Store` does for SQLite."""
        from sqlalchemy import inspect, text

        from lagrade.uses.bulk.store import COLUMNS_ADDED

        have = {t: {c["name"] for c in inspect(self.engine).get_columns(t)} for t in {t for t, _, _ in COLUMNS_ADDED}}
        with self.engine.begin() as c:
            for table, column, definition in COLUMNS_ADDED:
                if column not in have[table]:
                    if definition == "BLOB" and self.engine.dialect.name == "postgresql":
                        definition = "BYTEA"  # SQLite's BLOB, as PostgreSQL spells it
                    c.execute(text(f"ALTER TABLE {table} ADD COLUMN {column} {definition}"))

    def _add_last_seen(self) -> None:
        """A database of a server from before the idle limit has sessions without ``last_seen``."""
        from sqlalchemy import inspect, text

        if "last_seen" not in {c["name"] for c in inspect(self.engine).get_columns("server_sessions")}:
            with self._write, self.engine.begin() as c:
                c.execute(text("ALTER TABLE server_sessions ADD COLUMN last_seen FLOAT"))

    def close(self) -> None:
        self.release()
        self.engine.dispose()

    # ------------------------------------------------------------------ one server per database

    def claim(self) -> None:
        """Hold this database for this server until :meth:`close`; DatabaseBusy if another holds it."""
        if self._claim is not None:
            return
        if self.sqlite_path is not None:
            self._claim_file(self.sqlite_path.with_name(self.sqlite_path.name + ".serve-lock"))
            return
        from sqlalchemy import text

        conn = self.engine.connect()
        try:
            got = conn.execute(text("SELECT pg_try_advisory_lock(:k)"), {"k": SERVE_LOCK_KEY}).scalar()
            conn.commit()
            if not got:
                holder = conn.execute(text(
                    "SELECT a.pid, a.client_addr FROM pg_locks l JOIN pg_stat_activity a ON a.pid = l.pid "
                    "WHERE l.locktype = 'advisory' AND l.granted AND l.database = "
                    "(SELECT oid FROM pg_database WHERE datname = current_database()) LIMIT 1")).first()
                conn.rollback()
                who = f" (PostgreSQL backend {holder[0]}, client {holder[1] or 'local'})" if holder else ""
                raise DatabaseBusy(self._busy(self.engine.url.render_as_string(hide_password=True), who))
        except BaseException:
            conn.invalidate()
            conn.close()
            raise
        self._claim = conn

    def _claim_file(self, lock: Path) -> None:
        import fcntl
        import os
        import socket

        key = str(lock.resolve())
        fd = os.open(key, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o600)
        try:
            if key in _CLAIMED:
                raise BlockingIOError
            fcntl.lockf(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)  # released by the kernel when the process ends
        except OSError:
            holder = os.pread(fd, 200, 0).decode("utf-8", "replace").strip()
            os.close(fd)
            raise DatabaseBusy(self._busy(str(self.sqlite_path), f" ({holder})" if holder else "")) from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"pid {os.getpid()} on {socket.gethostname()}".encode(), 0)
        _CLAIMED.add(key)
        self._claim = (fd, key)

    @staticmethod
    def _busy(where: str, who: str) -> str:
        return (f"{where} is served already by another lagrade serve{who}: one server per database "
                f"(its queue and rate limits live in that process); stop it, or use another --db")

    def release(self) -> None:
        claim, self._claim = self._claim, None
        if claim is None:
            return
        if isinstance(claim, tuple):
            import os

            fd, key = claim
            _CLAIMED.discard(key)
            os.close(fd)  # the lock goes with it; the file stays (removing it would race a new claim)
        else:
            claim.invalidate()  # the session ends, and its advisory lock with it
            claim.close()

    # ------------------------------------------------------------------ meta

    @staticmethod
    def _meta(c, key: str) -> str | None:
        return c.execute(select(meta.c.value).where(meta.c.key == key)).scalar_one_or_none()

    @staticmethod
    def _set_meta(c, key: str, value: str) -> None:
        if c.execute(select(meta.c.key).where(meta.c.key == key)).first() is None:
            c.execute(insert(meta).values(key=key, value=value))
        else:
            c.execute(update(meta).where(meta.c.key == key).values(value=value))

    def meta(self, key: str) -> str | None:
        with self.engine.connect() as c:
            return self._meta(c, key)

    def setup(self, assignment_json: str, totals: dict[str, float], version: str, roster: tuple[str, ...] | None) -> None:
        """What the gradebook's readers need: the assignment, the problems' totals, the roster."""
        with self._write, self.engine.begin() as c:
            self._set_meta(c, "assignment", assignment_json)
            self._set_meta(c, "problem_totals", json.dumps(totals))
            self._set_meta(c, "grader_version", version)
            self._set_meta(c, "root", "lagrade serve")
            for name in roster or ():
                self._add_student(c, name)

    def secret(self) -> bytes:
        """The key that signs this server's tokens, made the first time (kept in ``meta``)."""
        with self._write, self.engine.begin() as c:
            value = self._meta(c, "server_secret")
            if value is None:
                value = secrets.token_hex(32)
                self._set_meta(c, "server_secret", value)
        return bytes.fromhex(value)

    def kept(self, key: str, make) -> str:
        """The value kept in ``meta`` under ``key``, made by ``make()`` the first time (the LTI key)."""
        with self._write, self.engine.begin() as c:
            value = self._meta(c, key)
            if value is None:
                value = make()
                self._set_meta(c, key, value)
        return value

    # ------------------------------------------------------------------ browser sessions

    def open_session(self, student: str) -> str:
        """A new session of ``student``: its id (the cookie's value), random, stored only as a hash.
        The rows of sessions that have expired (:data:`SESSION_SECONDS`) are deleted meanwhile."""
        sid = secrets.token_urlsafe(32)
        now = time.time()
        with self._write, self.engine.begin() as c:
            c.execute(delete(server_sessions).where(server_sessions.c.created_at < now - SESSION_SECONDS))
            c.execute(insert(server_sessions).values(key=_session_key(sid), student=student, created_at=now,
                                                     last_seen=now))
        return sid

    def session_student(self, sid: str, max_age: float, idle: float | None = None) -> str | None:
        """The student of a live session (not ended, younger than ``max_age`` seconds, and used in the
        last ``idle`` seconds), else None. A live session's use is noted (``last_seen``, at most
        :data:`SEEN_EVERY` seconds stale); an idled-out one is deleted."""
        if not sid or len(sid) > 100:
            return None
        key = _session_key(sid)
        with self.engine.connect() as c:
            row = c.execute(select(server_sessions.c.student, server_sessions.c.created_at,
                                   server_sessions.c.last_seen).where(server_sessions.c.key == key)).first()
        if row is None or not row[0]:
            return None
        now = time.time()
        seen = row[2] if row[2] is not None else row[1]
        if now - row[1] >= max_age:
            return None
        if idle is not None and now - seen >= idle:
            with self._write, self.engine.begin() as c:
                c.execute(delete(server_sessions).where(server_sessions.c.key == key))
            return None
        if now - seen >= SEEN_EVERY:
            with self._write, self.engine.begin() as c:
                c.execute(update(server_sessions).where(server_sessions.c.key == key).values(last_seen=now))
        return row[0]

    def session_ended(self, sid: str) -> bool:
        """Whether a guest's signed session (:func:`lagrade.uses.server.tokens.guest_session`) was signed out."""
        with self.engine.connect() as c:
            return c.execute(select(server_sessions.c.key)
                             .where(server_sessions.c.key == _session_key(sid))).first() is not None

    def end_session(self, sid: str, issued: float | None = None) -> None:
        """Sign-out: the session is gone, whoever holds a copy of its cookie. ``issued``: a guest's
        signed session, which has no row: one is written, with no student, that says it ended (kept
        until the cookie would have expired anyway)."""
        with self._write, self.engine.begin() as c:
            c.execute(delete(server_sessions).where(server_sessions.c.key == _session_key(sid)))
            if issued is not None:
                c.execute(insert(server_sessions).values(key=_session_key(sid), student="", created_at=issued))

    @staticmethod
    def _add_student(c, name: str) -> None:
        if c.execute(select(students.c.student).where(students.c.student == name)).first() is None:
            c.execute(insert(students).values(student=name))

    # ------------------------------------------------------------------ attempts

    def submit(self, *, student: str, problem: str, suffix: str, data: bytes, file_hash: str, grading_hash: str,
               version: str, max_attempts: int | None = None) -> tuple[int, bool]:
        """Store an attempt before it is graded: (its id, True if new). The same content for the same
        grading is the same attempt (a resubmission is idempotent). ``max_attempts``: AttemptsUsed
        instead of a new attempt beyond that many (counted under the write lock: two at once cannot
        both be the last)."""
        key = (server_submissions.c.student == student, server_submissions.c.problem == problem,
               server_submissions.c.file_hash == file_hash, server_submissions.c.grading_hash == grading_hash,
               server_submissions.c.grader_version == version)
        with self._write, self.engine.begin() as c:
            found = c.execute(select(server_submissions.c.id).where(*key)).scalar_one_or_none()
            if found is not None:
                return found, False
            if max_attempts is not None and self._count(c, student, problem) >= max_attempts:
                raise AttemptsUsed(f"you have made the {max_attempts} attempt{'s' if max_attempts != 1 else ''} at "
                                   f"problem {problem} this assignment allows; your earlier attempts and their grades "
                                   "are kept")
            try:
                with c.begin_nested():
                    new = c.execute(insert(server_submissions).values(
                        student=student, problem=problem, suffix=suffix, data=data, file_hash=file_hash,
                        grading_hash=grading_hash, grader_version=version, state="queued", created_at=_now()))
            except IntegrityError:  # another server process on the same database stored it first
                return c.execute(select(server_submissions.c.id).where(*key)).scalar_one(), False
            self._add_student(c, student)
            return new.inserted_primary_key[0], True

    def stored(self, *, student: str, problem: str, file_hash: str, grading_hash: str, version: str) -> int | None:
        """The attempt :meth:`submit` would give this content for this grading again, or None."""
        with self.engine.connect() as c:
            return c.execute(select(server_submissions.c.id).where(
                server_submissions.c.student == student, server_submissions.c.problem == problem,
                server_submissions.c.file_hash == file_hash, server_submissions.c.grading_hash == grading_hash,
                server_submissions.c.grader_version == version)).scalar_one_or_none()

    @staticmethod
    def _count(c, student: str, problem: str, upto: int | None = None) -> int:
        q = select(func.count()).select_from(server_submissions).where(
            server_submissions.c.student == student, server_submissions.c.problem == problem)
        if upto is not None:
            q = q.where(server_submissions.c.id <= upto)
        return int(c.execute(q).scalar_one())

    def count(self, student: str, problem: str, upto: int | None = None) -> int:
        """How many attempts ``student`` has stored at ``problem`` (up to attempt ``upto``: its number)."""
        with self.engine.connect() as c:
            return self._count(c, student, problem, upto)

    def attempt(self, sid: int) -> Attempt | None:
        with self.engine.connect() as c:
            row = c.execute(select(server_submissions).where(server_submissions.c.id == sid)).first()
        return _attempt(row) if row is not None else None

    def attempts(self, student: str, problem: str | None = None, limit: int = 50) -> list[Attempt]:
        q = select(server_submissions).where(server_submissions.c.student == student)
        if problem is not None:
            q = q.where(server_submissions.c.problem == problem)
        with self.engine.connect() as c:
            rows = c.execute(q.order_by(server_submissions.c.id.desc()).limit(limit)).fetchall()
        return [_attempt(r) for r in rows]

    def plot(self, sid: int) -> bytes | None:
        with self.engine.connect() as c:
            return c.execute(select(server_plots.c.png).where(server_plots.c.id == sid)).scalar_one_or_none()

    def queued(self) -> list[int]:
        with self.engine.connect() as c:
            return list(c.execute(select(server_submissions.c.id).where(server_submissions.c.state == "queued")
                                  .order_by(server_submissions.c.id)).scalars())

    def queued_by(self) -> list[tuple[int, str]]:
        """(id, student) of every attempt stored but not graded, oldest first."""
        with self.engine.connect() as c:
            return [(r.id, r.student) for r in c.execute(
                select(server_submissions.c.id, server_submissions.c.student)
                .where(server_submissions.c.state == "queued").order_by(server_submissions.c.id))]

    def counts(self) -> dict[str, int]:
        with self.engine.connect() as c:
            rows = c.execute(select(server_submissions.c.state, func.count()).group_by(server_submissions.c.state))
            return {state: n for state, n in rows}

    def finish(self, sid: int, result: dict[str, Any], check: dict[str, Any], plot: bytes | None = None,
               deadline: str | None = None, keep: Any = None) -> None:
        """Write one attempt's grade (and its picture): the attempt itself, and the gradebook if it is
        the student's latest graded attempt at the problem; one transaction.

        ``deadline`` (``2026-12-01T23:59:00Z``): an attempt stored after it is late, and the gradebook
        keeps the latest attempt stored by then. ``keep(n)``: the fraction of its score the ``n``-th
        attempt keeps in the gradebook (the assignment's attempt penalty)."""
        with self._write, self.engine.begin() as c:
            row = c.execute(select(server_submissions).where(server_submissions.c.id == sid)).first()
            if row is None or row.state == "graded":
                return
            now = _now()
            c.execute(update(server_submissions).where(server_submissions.c.id == sid)
                      .values(state="graded", result=json.dumps(check), graded_at=now))
            if plot:
                c.execute(insert(server_plots).values(id=sid, png=plot))
            if deadline is not None and row.created_at > deadline:
                return  # late: stored, graded and marked; the gradebook keeps the grade made by the deadline
            counted = [server_submissions.c.created_at <= deadline] if deadline is not None else []
            later = c.execute(select(func.max(server_submissions.c.id)).where(
                server_submissions.c.student == row.student, server_submissions.c.problem == row.problem,
                server_submissions.c.state == "graded", server_submissions.c.id > sid, *counted)).scalar_one_or_none()
            if later is not None:
                return
            factor = keep(self._count(c, row.student, row.problem, sid)) if keep is not None else 1.0
            if factor != 1.0:
                result = {**result, "score": result["score"] * factor,
                          "parts": [{**p, "score": p["score"] * factor} for p in result["parts"]]}
            who = (row.student, row.problem)
            c.execute(delete(parts).where(parts.c.student == who[0], parts.c.problem == who[1]))
            c.execute(delete(submissions).where(submissions.c.student == who[0], submissions.c.problem == who[1]))
            c.execute(insert(submissions).values(
                student=row.student, problem=row.problem, path=f"{row.student}/{row.problem}{row.suffix}",
                file_hash=row.file_hash, grading_hash=row.grading_hash, grader_version=row.grader_version,
                outcome=result["outcome"], status=result["status"], reason=result["reason"], score=result["score"],
                max_score=result["max_score"], problems=json.dumps(result["problems"]),
                stdout=result.get("stdout", ""), source=row.data.decode("utf-8", "replace"),
                seconds=result["seconds"], graded_at=now, attempts=1, jail=result.get("jail")))
            if result["parts"]:
                c.execute(insert(parts), [
                    {"student": row.student, "problem": row.problem, "part": p["part"], "verdict": p["verdict"],
                     "score": p["score"], "max_score": p["max_score"], "method": p["method"],
                     "feedback": p["feedback"], "answer_text": p.get("answer_text"),
                     "answer_mathml": p.get("answer_mathml"), "review": p.get("review"), "detail": p.get("detail"),
                     "certificate": p.get("certificate"),
                     "motion_evidence": json.dumps(p["motion_evidence"]) if p.get("motion_evidence") else None,
                     "file_hash": row.file_hash,
                     "grader_version": row.grader_version} for p in result["parts"]])
            c.execute(insert(grade_log).values(student=row.student, problem=row.problem, file_hash=row.file_hash,
                                               grading_hash=row.grading_hash, grader_version=row.grader_version,
                                               graded_at=now))

    # ------------------------------------------------------------------ the class

    def gradebook(self):
        """The class as the exports and the HTML report see it (:class:`lagrade.uses.bulk.gradebook.Gradebook`).

        On SQLite, the very reader of `lagrade export` over one of the server's own connections: a
        second connection of this process's own to the file (sqlite3.connect, even open() to read
        its header), once closed, would drop the POSIX locks the server's connections hold on it,
        and another process's writer would then delete the server's write-ahead log (issue 43)."""
        if self.sqlite_path is not None:
            import sqlite3

            from lagrade.uses.bulk.gradebook import gradebook_of
            from lagrade.uses.bulk.store import Store

            with self.engine.connect() as c:
                raw = c.connection.driver_connection
                before = raw.row_factory
                raw.row_factory = sqlite3.Row
                try:
                    return gradebook_of(Store.over(raw, self.sqlite_path), self.sqlite_path)
                finally:
                    raw.row_factory = before
        return self._gradebook()

    def _gradebook(self):
        """The same Gradebook read through SQLAlchemy (PostgreSQL), as load_gradebook builds it."""
        from lagrade.uses.bulk.assignment import parse_assignment, points
        from lagrade.uses.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade

        with self.engine.connect() as c:
            assignment = parse_assignment(json.loads(self._meta(c, "assignment")), self.url)
            totals = json.loads(self._meta(c, "problem_totals") or "{}")
            subs = {(r.student, r.problem): r for r in c.execute(select(submissions))}
            by: dict[tuple[str, str], list[dict]] = {}
            q = select(parts, submissions.c.jail).join(
                submissions, (parts.c.student == submissions.c.student) & (parts.c.problem == submissions.c.problem))
            for r in c.execute(q):
                by.setdefault((r.student, r.problem), []).append(dict(r._mapping))
            names = sorted(set(c.execute(select(students.c.student)).scalars()) | {s for s, _ in subs})
            version = self._meta(c, "grader_version") or ""
        out = []
        for name in names:
            grades = {}
            for ap in assignment.problems:
                row, ps = subs.get((name, ap.id)), by.get((name, ap.id), [])
                pts, possible = points(ap, ps, totals.get(ap.id, 0.0))
                grades[ap.id] = (ProblemGrade(ap.id, 0.0, possible, False, reason="no file handed in") if row is None
                                 else ProblemGrade(ap.id, pts, possible, True, row.outcome, row.status, row.reason,
                                                   json.loads(row.problems), ps, row.source, row.path))
            out.append(StudentGrade(name, grades))
        return Gradebook(assignment, out, [], version)


def _attempt(row) -> Attempt:
    return Attempt(row.id, row.student, row.problem, row.suffix, row.file_hash, row.state,
                   json.loads(row.result) if row.result else None, row.created_at, row.data)


def _sqlite_pragmas(dbapi_connection, _record) -> None:
    cur = dbapi_connection.cursor()
    cur.execute("PRAGMA foreign_keys=ON")
    cur.execute("PRAGMA synchronous=FULL")
    cur.close()
