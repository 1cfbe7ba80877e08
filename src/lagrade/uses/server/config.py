"""The server's settings, validated once (a pydantic model: they cross the CLI/app boundary)."""

from __future__ import annotations

from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field


class ServerConfig(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    #: the assignment TOML file (bulk grading's format)
    assignment: Path
    #: a SQLite file path, or an SQLAlchemy URL (postgresql+psycopg://user@host/db)
    db: str
    #: students allowed to sign in (None: anyone holding a token this server's secret signed)
    roster: tuple[str, ...] | None = None
    #: no tokens at all: a lecture demo
    open: bool = False
    problems_dirs: tuple[Path, ...] = ()
    #: warm grader processes
    workers: int = Field(2, ge=1)
    #: grade on this Dask cluster instead (tcp://host:8786; needs lagrade[dask])
    scheduler: str | None = None
    #: largest request body accepted, in bytes (answer.toml itself is refused over 200 kB)
    max_body: int = Field(256_000, ge=1024)
    #: checks per minute and per token, with this many at once (a token bucket)
    checks_per_minute: float = Field(20, gt=0)
    check_burst: int = Field(10, ge=1)
    #: what one student may have queued or being graded at once, and the grader seconds their
    #: attempts may use in a minute (beyond either: 429 with Retry-After)
    student_in_flight: int = Field(3, ge=1)
    student_grader_seconds_per_minute: float = Field(30, gt=0)
    #: warm graders beyond `workers` that take fresh attempts while others are held by slow ones
    #: (gradings whose answer's code has used more than `cpu_budget` CPU seconds, or the grader's
    #: own work more than `grader_budget`: they run at nice 19 from then on), and how many grader
    #: processes there may be, slow ones holding those beyond `workers + spare_graders` (0:
    #: `workers + spare_graders + max(2, workers)`; a slow grading without a place is stopped and
    #: graded again once one is free, behind every fresh attempt)
    spare_graders: int = Field(4, ge=0)
    cpu_budget: float = Field(0.5, gt=0)
    grader_budget: float = Field(1.5, gt=0)
    #: a grading that has run this many seconds (lowered or not yet) no longer holds one of `workers`
    slow_after: float = Field(2.0, gt=0)
    max_graders: int = Field(0, ge=0)
    previews_per_minute: float = Field(90, gt=0)
    preview_burst: int = Field(30, ge=1)
    #: wall-clock seconds one preview may take in the preview process (then it is killed and restarted)
    preview_seconds: float = Field(5, gt=0)
    #: LTI 1.3: the platforms (LMSs) this server takes launches from and sends grades to (lti.py)
    lti: Path | None = None
    #: refused tokens a minute, and at once, from one client address (then 429): a guessing bound
    failed_sign_ins_per_minute: float = Field(10, gt=0)
    failed_sign_in_burst: int = Field(10, ge=1)
    #: the server is reached over HTTPS only (TLS here, or a reverse proxy in front): cookies are
    #: always `Secure` (else they are when the request came over HTTPS, or from a trusted proxy that
    #: says so in X-Forwarded-Proto: uvicorn's --forwarded-allow-ips)
    https: bool = False
    #: a browser's session ends after this many minutes without a request (a page, a preview, a
    #: check); it ends anyway 120 days after sign-in (tokens.SESSION_SECONDS). A lab machine left
    #: signed in is then signed out by the next morning.
    session_idle_minutes: float = Field(480, gt=0)
    #: how long a check request waits for its grade before answering "queued" (202)
    wait_seconds: float = Field(120, gt=0)
