"""The grading queue: stored attempts go to bulk grading's warm grader processes, one at a time each.

The same graders as ``lagrade grade`` (:class:`lagrade.uses.bulk.worker.GraderProcess`: problems loaded
and references derived once, every ``answer.py`` run in the jail by the grader's clean zygote), fed
the same jobs (:meth:`lagrade.uses.bulk.runner.Plan.job`), with the same deadline and the same verdicts
when a grader dies or overruns. What differs from :func:`lagrade.uses.bulk.runner.run_local` is only
that the queue never ends: attempts arrive while the graders work, and the graders stay warm.

A request waits for its attempt's grade on an asyncio future that this thread resolves. A grader
that returns a result takes its next job before the grade is written (``look_after``'s
``next_job``), so that it works meanwhile.

Fair to students: the queue is a queue per student, served round robin, and one student's attempts
hold at most ``workers - 1`` graders at once (one, with one grader), so ten infinite loops from one
student leave a grader to everyone else. A grading that has used more than a CPU budget runs at the
lowest CPU weight from then on (:meth:`GradingQueue._run`), so the quick answers get the CPU first. :meth:`GradingQueue.admit` caps what a student has in
flight (queued or grading) and the grader time their attempts used in the last minute; the API
answers 429 with ``Retry-After`` beyond either.
"""

from __future__ import annotations

import asyncio
import json
import logging
import os
import re
import tempfile
import tomllib
import threading
import time
from collections import defaultdict, deque
from multiprocessing.connection import wait
from pathlib import Path
from typing import Any

from lagrade.uses.bulk.assignment import Assignment
from lagrade.uses.bulk.layout import Submission
from lagrade.uses.bulk.result_memo import ResultMemo, result_key
from lagrade.uses.bulk.runner import Plan, plan, problem_totals
from lagrade.uses.bulk.worker import (CPU_BUDGET, GRADER_BUDGET, GraderProcess, WorkerDied, failed_result, look_after,
                                     stop_all, watch)
from lagrade.verdicts.result import CheckResult, PartResult
from lagrade.uses.server.db import Attempt, Database

log = logging.getLogger("lagrade.uses.server")


def make_plan(assignment: Assignment, problems_dirs: tuple[Path, ...] = ()) -> Plan:
    """Bulk grading's plan of the assignment (problem sources, part weights, grading keys), no folder."""
    with tempfile.TemporaryDirectory(prefix="lagrade-serve-") as empty:
        return plan(Path(empty), assignment, problems_dirs)


def totals(p: Plan) -> dict[str, float]:
    return problem_totals(p)


def check_json(result: dict[str, Any], problem=None) -> dict[str, Any]:
    """A grader's result as ``lagrade check --json`` prints it, plus how each part was read (the
    student's own value, as terminal text and MathML) and how the file ran.

    The server's graders print each value as ``check --json`` and a local check do (the part's
    ``read_back``: LaTeX and terminal text, made from the value itself, within the grading's CPU
    bound). A result without it (another grader's) keeps each value as sympy text (the gradebook's):
    read back here without eval (:func:`lagrade.answer.reading.text.parse_math`), it gives the same;
    a value that does not read back keeps its sympy text."""
    checked = CheckResult(problem=result["problem"], score=result["score"], max_score=result["max_score"],
                          parts=[PartResult.model_validate(p) for p in result["parts"]],
                          problems=list(result["problems"]))
    shown = {p["part"]: p["answer_text"] for p in result["parts"] if p.get("answer_text")}
    printed = {p["part"]: p["read_back"] for p in result["parts"] if p.get("read_back")}
    for part in checked.parts:
        if part.part in printed:  # printed by the grader from the value itself (the job's ``read_back``)
            part.read_as, shown[part.part] = printed[part.part][0], printed[part.part][1] or shown.get(part.part)
        elif part.part in shown and problem is not None:
            part.read_as, shown[part.part] = _read_back(problem, shown[part.part])
    out = json.loads(checked.model_dump_json())
    out["read_as_text"] = shown
    out["read_as_mathml"] = {p["part"]: p["answer_mathml"] for p in result["parts"] if p.get("answer_mathml")}
    out["status"], out["outcome"] = result["status"], result["outcome"]
    return out


def _read_back(problem, text: str) -> tuple[str | None, str]:
    """(LaTeX, terminal text) of a value printed as sympy text; (None, text) if it does not read back."""
    from lagrade.problem.notation import parse_math
    from lagrade.verdicts.readback import as_latex, as_unicode

    coords = sorted({c.name for s in problem.systems for c in s.coordinates})
    try:
        general = {f.name: len(f.args) for s in problem.systems for f in s.functions}  # V(r), as the book
        value = parse_math(text, coords + [f"p_{c}" for c in coords], functions=general)
        return as_latex(value), as_unicode(value)
    except Exception:  # noqa: BLE001  (a value clipped for length, a form the reader does not take)
        return None, text


#: a folder of lagrade's own (a grader's, a job's, the server's), wherever it is: never shown to a student
_OWN_FOLDER = re.compile(r"(?:/[^\s'\"/:]+)*/lagrade-(?:grader|job|serve|preview|class)[^\s'\"/:]*(?:/[^\s'\"/:]+)*")


def typed(suffix: str, data: bytes) -> bool:
    """Whether an attempt is text typed on the page or sent as JSON (the canonical answer.toml the
    server writes for it), rather than a file the student uploaded."""
    if suffix != ".toml":
        return False
    from lagrade.uses.server.answers import AnswerTextError, to_toml

    try:
        return to_toml(tomllib.loads(data.decode("utf-8"))) == data
    except (ValueError, AnswerTextError):
        return False


def for_student(text: str, problem: str, suffix: str, is_typed: bool) -> str:
    """A grader's message as a student may read it: the file the grader wrote (``12.14.py`` in its
    temporary folder) named as the student's ``answer.py``; for typed text, which has no file, no
    file name at all (``12.14.toml:2: eom: ...`` is ``eom: ...``: the part is named already); no
    server folder anywhere."""
    name = re.escape(f"{problem}{suffix}")
    if is_typed:
        text = re.sub(rf"(?:/[^\s'\"/:]+)*/?(?<![\w.]){name}:\d+: ", "", text)
        text = re.sub(rf"(?:/[^\s'\"/:]+)*/?(?<![\w.]){name}(?::\d+)?", "your answer", text)
    else:
        text = re.sub(rf"(?:/[^\s'\"/:]+)*/?(?<![\w.]){name}", f"answer{suffix}", text)
    return _OWN_FOLDER.sub("(the grader's folder)", text)


def _for_student(result: dict[str, Any], problem: str, suffix: str, data: bytes) -> dict[str, Any]:
    """A copy of a grader's result whose texts are fit for the student (:func:`for_student`)."""
    t = typed(suffix, data)

    def fix(v):
        return for_student(v, problem, suffix, t) if isinstance(v, str) else v

    out = dict(result)
    out["reason"] = fix(result.get("reason", ""))
    out["problems"] = [fix(x) for x in result.get("problems", [])]
    out["parts"] = [{**p, "feedback": fix(p.get("feedback", "")), "review": fix(p.get("review"))}
                    for p in result.get("parts", [])]
    return out


class GradingQueue:
    """A thread that owns ``workers`` (and ``spares``) warm grader processes and grades stored attempts,
    each student in turn."""

    def __init__(self, db: Database, p: Plan, workers: int, scheduler: str | None = None,
                 problems: dict | None = None, in_flight: int = 3, seconds_per_minute: float = 30.0,
                 spares: int = 0, cpu_budget: float = CPU_BUDGET, max_graders: int | None = None,
                 slow_after: float = 2.0, grader_budget: float = GRADER_BUDGET) -> None:
        """``scheduler``: grade on this Dask cluster (``tcp://host:8786``) as ``lagrade grade --scheduler``
        does (a warm grader process per Dask worker thread), instead of ``workers`` local processes.
        ``in_flight``, ``seconds_per_minute``: what one student may have queued or grading at once,
        and the grader seconds their attempts may use in a minute (:meth:`admit`). ``spares``: warm
        graders beyond ``workers`` that take fresh attempts while others are held by gradings lowered
        for having used more than ``cpu_budget`` CPU seconds in the answer's code (``grader_budget``
        in the grader's own work); ``max_graders`` (default: ``workers + spares + max(2, workers)``):
        how many grader processes there may be, the lowered gradings holding the ones beyond
        ``workers + spares`` (local graders only: :meth:`_run`). A grading that has run ``slow_after`` seconds stops counting
        against ``workers`` too, lowered or not yet (at normal priority it may be waiting for the CPU)."""
        self.db, self.plan, self.workers, self.scheduler = db, p, workers, scheduler
        self.problems = problems or {}
        self.in_flight, self.seconds_per_minute = in_flight, seconds_per_minute
        self.spares, self.cpu_budget, self.slow_after = spares, cpu_budget, slow_after
        self.grader_budget = grader_budget
        self.max_graders = max_graders or workers + spares + max(2, workers)
        #: the grader processes now (local graders; read by tests), and the attempts whose grading
        #: was lowered for having used more than ``cpu_budget``
        self.graders: list[GraderProcess] = []
        self.lowered: dict[int, None] = {}  # the last 10 000, in order
        self.stopped: dict[int, None] = {}  # attempts stopped and queued again (`_park`), likewise
        #: graders one student's attempts may hold at once: never all of them (with one grader, that one)
        self.per_student = max(1, workers - 1)
        self._jobs: dict[str, deque[int]] = {}  # queued attempts, per student, in order
        self._turn: deque[str] = deque()  # students with queued attempts, round robin
        #: attempts stopped for want of a slow grading's place (:meth:`_park`), graded again from the
        #: start at nice 19 once no fresh attempt waits and a place is free (never stopped again)
        self._parked: deque[int] = deque()
        self._rerun: set[int] = set()
        self._slow_free = 0  # places among the slow gradings' graders this round (`_run`)
        self._owner: dict[int, str] = {}  # queued or grading attempt -> student
        self._grading: dict[int, float] = {}  # attempt -> when its grading started
        self._used: dict[str, deque[tuple[float, float]]] = defaultdict(deque)  # (when done, grader seconds)
        self._admitted: dict[str, int] = defaultdict(int)  # admitted checks not yet queued (being stored)
        self._plots: set[int] = set()  # attempts whose picture was asked for (the page's)
        self._lock = threading.Lock()
        self._waiters: dict[int, list[tuple[asyncio.AbstractEventLoop, asyncio.Future]]] = {}
        self._wake_r, self._wake_w = os.pipe()
        self._stopping = False
        self._thread: threading.Thread | None = None
        self.graded = 0
        #: results by program, across the graders: a class hands in the same program again and again
        self.results = ResultMemo()
        self._answered: deque[tuple[dict[str, Any], dict[str, Any]]] = deque()  # found kept by `_next`
        self._dask_warm = False  # the Dask workers' graders are warm (`_run_dask`)
        #: called with an attempt's id once its grade is written (the LMS grade sender's wake-up)
        self.on_graded = None

    # ------------------------------------------------------------------ from the app

    def start(self) -> None:
        """Start the graders, and queue every attempt stored but not graded (a killed server's)."""
        for sid, student in self.db.queued_by():
            self.put(sid, student)
        target = self._run if self.scheduler is None else self._run_dask
        self._thread = threading.Thread(target=target, name="lagrade-grading", daemon=True)
        self._thread.start()

    def put(self, sid: int, student: str, plot: bool = False) -> None:
        """Queue a stored attempt of ``student``; ``plot``: also draw the picture of a wrong motion (it
        costs 3-5 times the grading of a file, so only the page, which shows it, asks for it)."""
        with self._lock:
            self._settle(student)
            if sid not in self._owner:
                self._owner[sid] = student
                if student not in self._jobs:
                    self._jobs[student] = deque()
                    self._turn.append(student)
                self._jobs[student].append(sid)
            if plot:
                self._plots.add(sid)
        os.write(self._wake_w, b"x")

    def _settle(self, student: str) -> None:
        """An admitted check is queued, or turned out not new (under the lock)."""
        if self._admitted.get(student):
            self._admitted[student] -= 1

    def settle(self, student: str) -> None:
        """An admitted check that is not queued after all (the same file again, or a failure)."""
        with self._lock:
            self._settle(student)

    def ready(self) -> int:
        """How many warm graders there are (0: a check now would wait for one to warm up, seconds on a
        loaded machine): what /healthz answers on. On Dask, 1 once the workers' graders are warm."""
        if self.scheduler is not None:
            return int(self._dask_warm)
        return sum(1 for g in list(self.graders) if g.ready)

    def pending(self) -> int:
        with self._lock:
            return sum(len(q) for q in self._jobs.values())

    def admit(self, student: str) -> tuple[float, str] | None:
        """None if ``student`` may send another attempt now (it is counted as theirs until
        :meth:`put` or :meth:`settle`); else (seconds to wait, why): their attempts queued or
        grading, or the grader seconds their attempts used in the last minute (those grading count
        with the time they have run so far)."""
        now = time.monotonic()
        with self._lock:
            mine = [sid for sid, who in self._owner.items() if who == student]
            if len(mine) + self._admitted.get(student, 0) >= self.in_flight:
                # a file runs for at most cpu_seconds: by then the oldest of theirs is graded
                running = [now - self._grading[sid] for sid in mine if sid in self._grading]
                wait = max(1.0, self.plan.assignment.limits.cpu_seconds - max(running, default=0.0))
                return wait, (f"you have {self.in_flight} checks waiting or being graded (at most {self.in_flight} "
                              "at once); wait for their grades")
            used = self._used[student]
            while used and now - used[0][0] >= 60:
                used.popleft()
            spent = sum(s for _, s in used) + sum(now - self._grading[sid] for sid in mine if sid in self._grading)
            if spent >= self.seconds_per_minute:
                # wait until enough of the last minute's grading has aged out of the window
                over, wait = spent - self.seconds_per_minute, 60.0
                for when, seconds in used:
                    over -= seconds
                    if over < 0:
                        wait = 60 - (now - when)
                        break
                return max(1.0, wait), (f"your checks used {spent:.0f} s of grading time in the last minute (at "
                                        f"most {self.seconds_per_minute:g} s a student)")
            self._admitted[student] += 1
        return None

    async def wait(self, sid: int, timeout: float) -> Attempt | None:
        """The attempt once graded, or None if it is still queued after ``timeout`` seconds."""
        loop = asyncio.get_running_loop()
        fut = loop.create_future()
        with self._lock:
            self._waiters.setdefault(sid, []).append((loop, fut))
        try:
            att = await asyncio.to_thread(self.db.attempt, sid)  # graded before we started waiting?
            if att is not None and att.graded:
                return att
            try:
                await asyncio.wait_for(fut, timeout)
            except TimeoutError:
                return None
            return await asyncio.to_thread(self.db.attempt, sid)
        finally:
            with self._lock:
                left = [w for w in self._waiters.get(sid, []) if w[1] is not fut]
                if left:
                    self._waiters[sid] = left
                else:
                    self._waiters.pop(sid, None)

    def stop(self) -> None:
        self._stopping = True
        os.write(self._wake_w, b"x")
        if self._thread is not None:
            self._thread.join(timeout=30)
        for fd in (self._wake_r, self._wake_w):
            try:
                os.close(fd)
            except OSError:
                pass

    # ------------------------------------------------------------------ the thread

    def _job(self, sid: int) -> dict[str, Any] | None:
        att = self.db.attempt(sid)
        if att is None or att.graded:
            return None
        sub = Submission(att.student, att.problem, Path(f"{att.problem}{att.suffix}"), att.file_hash, att.data)
        job = self.plan.job(sub)
        job["server_id"] = sid
        job["hints"] = self.plan.assignment.rules.feedback == "hints"  # the course's feedback level
        job["read_back"] = True  # the grader prints each value as read (check_json), not this process
        with self._lock:
            job["plot"] = sid in self._plots
            job["rerun"] = sid in self._rerun
        return job

    def _pick(self) -> int | None:
        """The next attempt to grade (under the lock): the next student in turn who holds fewer than
        ``per_student`` graders; None if there is none."""
        busy: dict[str, int] = {}
        for sid in self._grading:
            busy[self._owner[sid]] = busy.get(self._owner[sid], 0) + 1
        for _ in range(len(self._turn)):
            student = self._turn[0]
            self._turn.rotate(-1)
            if busy.get(student, 0) >= self.per_student:
                continue
            queue = self._jobs[student]
            sid = queue.popleft()
            if not queue:
                del self._jobs[student]
                self._turn.remove(student)
            self._grading[sid] = time.monotonic()
            return sid
        if self._parked and not self._jobs and self._slow_free > 0:
            self._slow_free -= 1
            sid = self._parked.popleft()
            self._rerun.add(sid)
            self._grading[sid] = time.monotonic()
            return sid
        return None

    def _park(self, g: GraderProcess) -> None:
        """Stop a lowered grading that finds no room among the slow ones, and queue its attempt again
        (under no lock): its answer's children are killed (the grader then answers at once, and that
        answer is dropped: :meth:`_done`), or the grader itself when the cost is its own. Nothing is
        stopped when the answer has finished and the grader is still within its budget: it is left
        to finish."""
        sid = g.job["server_id"]
        if g.retire:
            g.kill()
            self.graders.remove(g)
        else:
            children = g.children()
            if not children:
                return
            g.job["parked"] = True
            g.kill_children(children)
        with self._lock:
            student = self._owner.get(sid)
            started = self._grading.pop(sid, None)
            if student is not None:
                self._used[student].append((time.monotonic(), time.monotonic() - (started or time.monotonic())))
                self._parked.append(sid)
        self.stopped[sid] = None
        if len(self.stopped) > 10_000:
            del self.stopped[next(iter(self.stopped))]
        log.info("attempt %s used more than its CPU budget while the slow gradings' graders were all taken: "
                 "stopped, it is graded again (from the start, at nice 19) when one is free", sid)

    def _forget(self, sid: int, seconds: float | None = None) -> None:
        """An attempt leaves the queue (under the lock): graded (``seconds`` of grader time), or unreadable."""
        student = self._owner.pop(sid, None)
        self._grading.pop(sid, None)
        self._rerun.discard(sid)
        if student is not None and seconds is not None:
            self._used[student].append((time.monotonic(), seconds))

    def _next(self) -> dict[str, Any] | None:
        """The next attempt's job for a grader. One whose program was graded before with the same
        settings (by any of the graders) gets that result instead (`ResultMemo`), written by
        :meth:`_answer_kept` once the graders have their jobs: a grader is never kept waiting while
        this thread writes grades it did not need to work out."""
        while True:
            with self._lock:
                sid = self._pick()
                if sid is None:
                    return None
            try:
                job = self._job(sid)
            except Exception:
                log.exception("attempt %s could not be read; it stays queued", sid)
                job = None
            if job is not None:
                key = job["result_key"] = result_key(job)
                kept = self.results.get(job, key)
                if kept is None:
                    return job
                self._answered.append((job, kept))
                continue
            with self._lock:
                self._forget(sid)

    def _answer_kept(self) -> None:
        """Write the grades :meth:`_next` found kept (this thread's, after the graders got their jobs)."""
        while self._answered:
            self._done(*self._answered.popleft())

    def _done(self, job: dict[str, Any], result: dict[str, Any]) -> None:
        sid = job["server_id"]
        if job.get("parked"):
            return  # what its killed answer left: the attempt is queued again (`_park`)
        with self._lock:
            self._forget(sid, float(result.get("seconds") or 0.0))
        if "result_key" in job:
            self.results.put(job["result_key"], result)
        try:
            plot = result.pop("plot_png", None)
            shown = _for_student(result, job["problem"], job["suffix"], job["data"])
            check = check_json(shown, self.problems.get(job["problem"]))
            if plot:
                check["plot"] = f"/api/v1/submissions/{sid}/plot.png"
            rules = self.plan.assignment.rules
            self.db.finish(sid, result, check, plot, deadline=rules.deadline_text(), keep=rules.penalty)
            self.graded += 1
            if self.on_graded is not None:
                self.on_graded(sid)
        except Exception:
            log.exception("the grade of attempt %s could not be written", sid)
        with self._lock:
            waiters = self._waiters.pop(sid, [])
            self._plots.discard(sid)
        for loop, fut in waiters:
            loop.call_soon_threadsafe(_resolve, fut)

    def _run(self) -> None:
        """``workers`` graders for fresh attempts, at normal priority, and ``spares`` warm ones beside
        them. A grading whose answer's code has used more than ``cpu_budget`` CPU seconds (an infinite
        loop spending its CPU bound, a memory bomb, a huge sum; honest answers use a fraction of it),
        or the grader's own work more than ``grader_budget``, is lowered to the lowest CPU weight
        (:func:`lagrade.uses.bulk.worker.watch`) and stops counting against them: it goes on, on its
        grader, among the slow gradings (at most ``max_graders - workers - spares`` of them), and a
        grader is started in its place. When the slow gradings hold all their graders, a newly
        lowered one is stopped and its attempt waits for one of them, behind every fresh attempt
        (:meth:`_park`). The quick answers get the CPU, and the graders, first; the slow ones get
        the same CPU seconds, later. A grader whose own priority was lowered is retired after its job
        (an unprivileged process cannot raise it again)."""
        sources = self.plan.sources
        target = self.workers + self.spares
        slow_places = max(1, self.max_graders - target)
        graders = self.graders = [GraderProcess(sources) for _ in range(target)]

        def slow(g: GraderProcess) -> bool:
            return g.job is not None and (g.lowered or g.retire)

        try:
            while not self._stopping:
                now = time.monotonic()
                for g in graders:
                    if g.job is not None and g.job.get("rerun"):
                        g.lowered = True  # graded again after it was stopped: at nice 19 from the start
                watch(graders, now, self.cpu_budget, self.grader_budget)
                for g in graders:
                    if slow(g) and g.job["server_id"] not in self.lowered:
                        self.lowered[g.job["server_id"]] = None
                        if len(self.lowered) > 10_000:
                            del self.lowered[next(iter(self.lowered))]
                        log.info("attempt %s used more than its CPU budget: it runs at nice 19 from now on%s",
                                 g.job["server_id"], " (and its grader is retired after)" if g.retire else "")
                # the slow gradings beyond their places, the newest first, are stopped
                over = [g for g in graders if slow(g) and not g.job.get("parked")]
                if len(over) > slow_places:
                    for g in sorted((g for g in over if not g.job.get("rerun")),
                                    key=lambda h: -h.started)[:len(over) - slow_places]:
                        self._park(g)
                for g in [g for g in graders if g.job is None and (g.lowered or g.retire)]:
                    if g.retire:
                        g.kill()  # idle: nothing of a student's is lost
                        graders.remove(g)
                    else:
                        g.lowered = False  # its answer's children were lowered, and are gone
                held = sum(1 for g in graders if slow(g) and not g.job.get("parked"))
                # the others, warm or warming, are kept at `workers + spares`, started ahead of the
                # attempts that will need them (a grader takes about a second to warm up)
                while len(graders) - held < target and len(graders) < self.max_graders:
                    graders.append(GraderProcess(sources))
                idle = [g for g in graders if g.job is None and g.ready]
                if (len(graders) > target and idle and not held and not self._parked and not self.pending()):
                    idle[-1].kill()  # started while slow gradings held others, and all is quiet again
                    graders.remove(idle[-1])
                with self._lock:
                    self._slow_free = slow_places - held
                for g in graders:
                    quick = sum(1 for h in graders if h.job is not None and not (h.lowered or h.retire)
                                and now - h.started <= self.slow_after)
                    if quick >= self.workers:
                        break
                    if g.job is None and not (g.lowered or g.retire):
                        job = self._next()
                        if job is None:
                            break
                        g.submit(job)
                        if job.get("rerun"):
                            g.lowered = True
                self._answer_kept()
                busy = [g for g in graders if g.job is not None]
                # while a grading may go over its budget, look every 0.1 s (a walk of /proc costs
                # about a millisecond): each tenth of a second later is CPU the quick answers lose
                watched = any(not g.lowered and now - g.started > self.cpu_budget / 2 for g in busy)
                # an idle grader still warming says so when it is warm (read here: only then is the
                # server ready, /healthz); a busy one's word is read with its result (look_after)
                warming = [g for g in graders if g.job is None and not g.ready]
                ready = wait([g.recv_conn for g in busy + warming] + [self._wake_r],
                             timeout=0.1 if watched else 0.25)
                if self._wake_r in ready:
                    os.read(self._wake_r, 4096)
                self._warmed([g for g in warming if g.recv_conn in ready])
                with self._lock:
                    self._slow_free = 0  # a grader that answers takes no rerun: the next round decides
                look_after(graders, sources, ready, time.monotonic(), self._done, self._next)
                self._answer_kept()
        except Exception:
            log.exception("the grading thread stopped; queued attempts are graded when the server starts again")
        finally:
            for g in graders:
                if g.job is not None:
                    g.kill()  # its attempt stays queued in the database
            stop_all([g for g in graders if g.job is None])

    def _warmed(self, warm: list[GraderProcess]) -> None:
        """Read the readiness word of idle graders that said something: warm, or replaced if it died
        warming up; a grader that could not start stops the thread, as in :func:`look_after`."""
        for g in warm:
            try:
                g.wait_ready(timeout=0)
            except TimeoutError:
                continue
            except WorkerDied as exc:
                if "could not start" in str(exc):
                    raise
                g.kill()
                self.graders[self.graders.index(g)] = GraderProcess(self.plan.sources)
                log.warning("a grader process died while warming up; another is started")

    def _run_dask(self) -> None:
        """The same queue on a Dask cluster: bulk grading's Dask task (``dask_grade``) per attempt."""
        import inspect

        from distributed import Client

        from lagrade.uses.bulk.runner import dask_grade, dask_warm

        client = Client(self.scheduler)
        flying: dict[Any, dict[str, Any]] = {}
        try:
            many = "n_workers" in inspect.signature(client.scheduler_info).parameters
            info = client.scheduler_info(n_workers=-1) if many else client.scheduler_info()
            for addr, w in info["workers"].items():
                client.run(dask_warm, self.plan.sources, w.get("nthreads", 1), workers=[addr])
            sources = client.scatter(self.plan.sources, broadcast=True)
            self._dask_warm = True
            while not self._stopping:
                while (job := self._next()) is not None:
                    flying[client.submit(dask_grade, job, sources, pure=False, retries=1)] = job
                self._answer_kept()
                if wait([self._wake_r], timeout=0.2):
                    os.read(self._wake_r, 4096)
                for fut in [f for f in flying if f.done()]:
                    job = flying.pop(fut)
                    try:
                        result = fut.result()
                    except Exception as exc:  # noqa: BLE001  (a Dask worker lost for good)
                        result = failed_result(job, job["parts"], "grader-crash",
                                               f"the Dask worker grading this file failed ({type(exc).__name__}: "
                                               f"{exc})", 0.0)
                    self._done(job, result)
                    fut.release()
        except Exception:
            log.exception("grading on the Dask cluster stopped; queued attempts are graded when the server starts again")
        finally:
            for fut in flying:  # their attempts stay queued in the database
                fut.cancel()
            client.close()


def _resolve(fut: asyncio.Future) -> None:
    if not fut.done():
        fut.set_result(True)
