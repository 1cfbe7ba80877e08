"""The state of one running server, shared by the API and the pages: the assignment, its problems,
the database, the grading queue, the token secret, the rate limits, and who sent a request."""

from __future__ import annotations

import hmac
import logging
import math
import time
from dataclasses import dataclass
from pathlib import Path

from fastapi import HTTPException, Request

from lagrade.uses.server.config import ServerConfig
from lagrade.uses.server.limits import RateLimit
from lagrade.uses.server.preview import PreviewWorker
from lagrade.uses.server.tokens import SESSION_SECONDS, INSTRUCTOR, csrf_token, guest_of, student_of  # noqa: F401

SESSION_COOKIE = "lagrade_session"
log = logging.getLogger("lagrade.uses.server")
LIST_KINDS = ("eom", "hamilton_eqs", "expression_set", "names", "conserved")


@dataclass
class Who:
    """Who sent a request: the student id, and the session id if it came by cookie (a browser)."""

    student: str
    session: str | None = None

    @property
    def instructor(self) -> bool:
        return self.student == INSTRUCTOR


class Server:
    """The state of one running server."""

    def __init__(self, config: ServerConfig) -> None:
        from lagrade.uses.bulk.assignment import (
            AssignmentError,
            check_against_problems,
            load_assignment,
        )
        from lagrade.problem.library import load_problem
        from lagrade.uses.server.db import Database
        from lagrade.uses.server.grading import make_plan, totals

        self.config = config
        try:
            self.assignment = load_assignment(config.assignment)
            check_against_problems(self.assignment, config.problems_dirs)
        except AssignmentError as exc:
            raise ValueError(str(exc)) from None
        self.plan = make_plan(self.assignment, config.problems_dirs)
        self.problems = {pid: load_problem(pid, config.problems_dirs) for pid in self.assignment.ids}
        # one server per database (the queue and the rate limits live here), claimed before the file is read
        self.db = Database(config.db, claim=True)
        try:
            self.db.setup(self.assignment.canonical_json(), totals(self.plan), self.plan.version, config.roster)
            self.secret = self.db.secret()
        except Exception:
            self.db.close()
            raise
        self.roster = set(config.roster) if config.roster is not None else None
        self.check_limit = RateLimit(config.checks_per_minute, config.check_burst)
        #: tokens refused (sign-in form, sign-in link, Bearer header): counted, logged, and slowed per client
        self.failed_sign_ins = 0
        self.sign_in_limit = RateLimit(config.failed_sign_ins_per_minute, config.failed_sign_in_burst)
        self.preview_limit = RateLimit(config.previews_per_minute, config.preview_burst)
        self.previews = PreviewWorker(config.problems_dirs, config.preview_seconds)
        self.queue = None
        #: whether this server grades (create_app's ``grade``): /healthz then waits for a warm grader
        self.grades = True
        # made once, here: the same text for every request
        self._texts = {(command, pid): self._print(command, pid) for pid in self.problems
                       for command in ("show", "template")}
        self._figures: dict[tuple[str, str], bytes] = {}

    def start(self) -> None:
        from lagrade.uses.server.grading import GradingQueue

        self.queue = GradingQueue(self.db, self.plan, self.config.workers, self.config.scheduler, self.problems,
                                  in_flight=self.config.student_in_flight,
                                  seconds_per_minute=self.config.student_grader_seconds_per_minute,
                                  spares=self.config.spare_graders, cpu_budget=self.config.cpu_budget,
                                  grader_budget=self.config.grader_budget,
                                  max_graders=self.config.max_graders or None,
                                  slow_after=self.config.slow_after)
        self.queue.start()

    def stop(self) -> None:
        if self.queue is not None:
            self.queue.stop()
        self.previews.stop()
        self.db.close()

    # ------------------------------------------------------------------ problems

    def problem(self, pid: str):
        if pid not in self.problems:
            raise HTTPException(404, f"no problem {pid!r} in this assignment (its problems: "
                                     f"{', '.join(self.assignment.ids)})")
        return self.problems[pid]

    def text(self, command: str, pid: str) -> str:
        """What ``lagrade show`` / ``lagrade template`` print for the problem."""
        return self._texts[(command, pid)]

    def statement(self, pid: str) -> str:
        """The problem as HTML with MathML (:func:`lagrade.uses.server.statement.statement_html`), made once."""
        from lagrade.uses.server.statement import statement_html

        key = ("statement", pid)
        if key not in self._texts:
            self._texts[key] = statement_html(self.problems[pid])
        return self._texts[key]

    def figure(self, pid: str) -> bytes:
        """The problem's figure drawn from its scene (:func:`lagrade.verdicts.figure.draw`), a PNG made once."""
        from lagrade.verdicts.figure import draw

        key = ("figure", pid)
        if key not in self._figures:
            self._figures[key] = draw(self.problems[pid])
        return self._figures[key]

    def _print(self, command: str, pid: str) -> str:
        """What a student's ``lagrade show`` / ``template`` prints (the same functions)."""
        from lagrade.problem.describe import show_text, template_text

        problem = self.problems[pid]
        return show_text(problem) + "\n" if command == "show" else template_text(problem)

    def fields(self, pid: str) -> list[dict]:
        """The parts as the student page asks for them: one text, a list (one per line) or keyed texts."""
        from lagrade.problem.spec import KINDS

        problem = self.problems[pid]
        out = []
        for part in problem.parts:
            keys = None
            if part.kind == "expression" and isinstance(part.reference, dict):
                keys = list(part.reference)  # the keys are public (`lagrade show` lists them), never the values
            elif part.kind == "trajectory":
                keys = [c.name for c in problem.system(part.system).coordinates]
            shape = "dict" if keys else ("list" if part.kind in LIST_KINDS else "text")
            out.append({"name": part.name, "kind": part.kind, "prompt": part.prompt or part.kind,
                        "expects": KINDS[part.kind].expects, "shape": shape, "keys": keys or [], "weight": part.weight})
        return out

    # ------------------------------------------------------------------ who is asking

    def identify(self, request: Request) -> Who:
        """The Bearer token, else the session cookie; 401 without either (unless the server is open)."""
        header = request.headers.get("authorization", "")
        if header:
            scheme, _, token = header.partition(" ")
            student = student_of(self.secret, token) if scheme.lower() == "bearer" else None
            if student is None:
                self.failed_sign_in(request, "Authorization header")
                raise HTTPException(401, "the token is not one this server issued; expected 'Authorization: "
                                         "Bearer <token>' with the token from your instructor",
                                    headers={"WWW-Authenticate": "Bearer"})
            return Who(self._allowed(student))
        cookie = request.cookies.get(SESSION_COOKIE)
        if cookie and self.config.open and (guest := guest_of(self.secret, cookie, time.time())) is not None:
            if not self.db.session_ended(cookie):  # a guest's cookie: signed, and a row only once signed out
                return Who(guest[0], cookie)
        elif cookie:
            student = self.db.session_student(cookie, SESSION_SECONDS, 60 * self.config.session_idle_minutes)
            if student is not None:
                return Who(self._allowed(student), cookie)
        if self.config.open:
            return Who("guest")
        raise HTTPException(401, "no token; expected 'Authorization: Bearer <token>' (or sign in on the web page)",
                            headers={"WWW-Authenticate": "Bearer"})

    def end_session(self, sid: str) -> None:
        """Sign-out (or a new sign-in in the same browser): the session ends wherever its cookie is;
        a guest's signed cookie gets a row that says so."""
        guest = guest_of(self.secret, sid, time.time()) if self.config.open else None
        self.db.end_session(sid, issued=guest[1] if guest is not None else None)

    def failed_sign_in(self, request: Request, how: str) -> None:
        """A token this server did not sign (or signed for someone off the roster): counted and
        logged with the client's address; beyond the per-client rate, 429 with Retry-After."""
        self.failed_sign_ins += 1
        client = request.client.host if request.client else "unknown"
        log.warning("refused sign-in #%d from %s (%s)", self.failed_sign_ins, client, how)
        wait = self.sign_in_limit.take(f"sign-in:{client}")
        if wait:
            seconds = max(1, math.ceil(wait))
            raise HTTPException(429, f"too many refused tokens from this address; try again in {seconds} s",
                                headers={"Retry-After": str(seconds)})

    def _allowed(self, student: str) -> str:
        if self.roster is not None and student not in self.roster and student != INSTRUCTOR \
                and not student.startswith("guest-") and not (self.config.lti and student.startswith("lti-")):
            raise HTTPException(401, f"{student!r} is not on this server's roster; ask your instructor",
                                headers={"WWW-Authenticate": "Bearer"})
        if student.startswith("guest-") and not self.config.open:
            raise HTTPException(401, "guest sessions exist only on an --open server",
                                headers={"WWW-Authenticate": "Bearer"})
        return student

    def require_csrf(self, who: Who, sent: str | None) -> None:
        """A request authenticated by the browser's cookie must carry its session's CSRF token."""
        if who.session is None:
            return  # a Bearer token (or an open server's anonymous guest): nothing ambient to abuse
        if not sent or not hmac.compare_digest(sent, csrf_token(self.secret, who.session)):
            raise HTTPException(403, "missing or wrong CSRF token; reload the page and submit again")

    def csrf(self, who: Who) -> str:
        return csrf_token(self.secret, who.session) if who.session else ""

    def limit(self, who: Who, preview: bool = False, admit: bool = True) -> None:
        """429 with Retry-After: beyond the rate of requests, or (a check, unless ``admit`` is False: a
        file stored before, which costs no grading) beyond what one student may have in flight or use
        of the graders' time a minute (:meth:`GradingQueue.admit`)."""
        wait = (self.preview_limit if preview else self.check_limit).take(who.student)
        if wait:
            seconds = max(1, math.ceil(wait))
            raise HTTPException(429, f"too many {'previews' if preview else 'checks'}; try again in {seconds} s",
                                headers={"Retry-After": str(seconds)})
        if not preview and admit and self.queue is not None and (over := self.queue.admit(who.student)) is not None:
            wait, why = over
            seconds = max(1, math.ceil(wait))
            raise HTTPException(429, f"{why}; try again in {seconds} s", headers={"Retry-After": str(seconds)})


TEMPLATES = Path(__file__).parent / "templates"
