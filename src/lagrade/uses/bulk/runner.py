"""Grading a class folder: what needs grading, the process pool (default) or a Dask cluster.

The coordinator (this process) scans the folder, asks the store which submissions are new or
changed, sends those to grader processes (:mod:`lagrade.uses.bulk.worker`) and writes every result in
its own transaction the moment it arrives. Grader processes are warmed once (problems loaded,
references derived) and reused for every submission; one that overruns a hard deadline or dies is
replaced, and that submission gets a verdict saying so.
"""

from __future__ import annotations

import hashlib
import json
import os
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from multiprocessing.connection import wait
from pathlib import Path
from typing import Any

from lagrade.uses.bulk.assignment import Assignment, check_against_problems
from lagrade.uses.bulk.layout import Layout, Submission, scan
from lagrade.uses.bulk.store import Key, Store
from lagrade.uses.bulk.worker import (
    GraderProcess,
    WorkerDied,
    failed_result,
    overran,
    hard_deadline,
    look_after,
    stop_all,
)

ResultCallback = Callable[[dict[str, Any]], None]


def grader_version() -> str:
    from lagrade._version import __version__

    return __version__


@dataclass
class RunReport:
    total: int = 0          # submissions found
    todo: int = 0           # graded in this run (new, changed, or a grader failure graded once more)
    up_to_date: int = 0     # already in the database with the same keys
    removed: int = 0        # results dropped because their file is gone
    failed: int = 0         # graded in this run with outcome 'failed'
    skipped: list = field(default_factory=list)
    seconds: float = 0.0
    workers: int = 0
    backend: str = "processes"


@dataclass
class Plan:
    assignment: Assignment
    layout: Layout
    sources: dict[str, str]                    # problem id -> problem TOML text (sent to graders)
    parts: dict[str, list[tuple[str, float]]]  # problem id -> [(part, weight)]
    keys: dict[str, str]                       # problem id -> grading hash
    version: str
    extras: dict[str, list[str]] = field(default_factory=dict)  # problem id -> its extra parts (not asked)

    def key(self, sub: Submission) -> Key:
        return Key(sub.sha256, self.keys[sub.problem], self.version)

    def job(self, sub: Submission) -> dict[str, Any]:
        return {"student": sub.student, "problem": sub.problem, "suffix": sub.suffix, "data": sub.data,
                "accuracy": self.assignment.accuracy, "limits": self.assignment.limits.model_dump(),
                "credit": self.assignment.credit.model_dump(),
                "parts": self.parts[sub.problem], "file_hash": sub.sha256}


def plan(root: Path, assignment: Assignment, problems_dirs: tuple[Path, ...] = (),
         version: str | None = None) -> Plan:
    from lagrade.problem.library import load_problem, problem_path

    check_against_problems(assignment, problems_dirs)
    sources, parts, keys, extras = {}, {}, {}, {}
    for pid in assignment.ids:
        path = problem_path(pid, problems_dirs)
        sources[pid] = path.read_text(encoding="utf-8")
        problem = load_problem(pid, problems_dirs)
        parts[pid] = [(p.name, p.weight) for p in problem.parts]
        extras[pid] = [p.name for p in problem.parts if p.extra]
        keys[pid] = assignment.grading_hash(pid, sources[pid])
    return Plan(assignment, scan(root, assignment.ids), sources, parts, keys, version or grader_version(), extras)


def _text_answers_last(sub: Submission) -> bool:
    """Grading order: Python answers first, text answers (TOML, LaTeX) last, each in folder order.

    A Python answer runs the student's code, from milliseconds to its CPU limit; a text answer takes
    tens of milliseconds. When the queue runs dry, every grader but the one with the last file waits
    for it: ending on short files keeps that wait short (a class of 12.14 whose last Python answers
    solve for the normal modes, 0.4 s each, spent that long with one core idle)."""
    return sub.suffix not in (".py", ".ipynb")


def problem_totals(p: Plan) -> dict[str, float]:
    """Each problem's own total: its parts' weights, extras (parts the book does not ask) left out."""
    return {pid: float(sum(w for name, w in parts if name not in p.extras.get(pid, ())))
            for pid, parts in p.parts.items()}


def grade_folder(root: Path, assignment: Assignment, db: Path, *, workers: int | None = None,
                 scheduler: Any = None, problems_dirs: tuple[Path, ...] = (), version: str | None = None,
                 on_start: Callable[[int, int], None] | None = None, on_result: ResultCallback | None = None,
                 regrade: bool = False, plots: bool = False) -> RunReport:
    """Grade every new or changed submission under ``root`` into ``db``; see the module docstring.
    ``plots``: also draw each wrong motion (``lagrade check --plot``'s picture) for the report."""
    start = time.monotonic()
    p = plan(root, assignment, problems_dirs, version)
    report = RunReport(total=len(p.layout.submissions), skipped=p.layout.skipped)
    with Store(db, lock=True) as store:
        store.set_meta("assignment", assignment.canonical_json())
        store.set_meta("problem_totals", json.dumps(problem_totals(p)))
        store.set_meta("problem_extras", json.dumps(p.extras))  # read back by the gradebook (bulk.gradebook)
        store.set_meta("root", str(Path(root).resolve()))
        store.set_meta("grader_version", p.version)
        present = {(s.student, s.problem) for s in p.layout.submissions}
        report.removed = store.sync_layout(p.layout.students, [(s.path, s.reason) for s in p.layout.skipped], present)
        stored, retries = store.keys(), store.retries()
        # a wrong answer graded without its picture is graded again when pictures are asked for
        unplotted = store.unplotted() if plots else set()
        todo = [s for s in p.layout.submissions
                if regrade or stored.get((s.student, s.problem)) != p.key(s) or (s.student, s.problem) in retries
                or (s.student, s.problem) in unplotted]
        report.todo, report.up_to_date = len(todo), report.total - len(todo)
        by_key = {(s.student, s.problem): s for s in todo}
        forget = list(by_key) if regrade else [k for k in by_key if k in unplotted]
        if forget:  # forget the stored keys so that record() writes again
            with store.transaction():
                store.db.executemany("DELETE FROM submissions WHERE student = ? AND problem = ?", forget)

        def done(result: dict[str, Any]) -> None:
            sub = by_key[(result["student"], result["problem"])]
            store.record(student=sub.student, problem=sub.problem, path=f"{sub.student}/{sub.path.name}",
                         key=p.key(sub), outcome=result["outcome"], status=result["status"], reason=result["reason"],
                         score=result["score"], max_score=result["max_score"], problems=result["problems"],
                         stdout=result.get("stdout", ""), source=sub.data.decode("utf-8", "replace"),
                         seconds=result["seconds"], parts=result["parts"], jail=result.get("jail"),
                         plot_png=result.get("plot_png") or (b"" if plots else None))
            if result["outcome"] == "failed":
                report.failed += 1
            if on_result:
                on_result(result)

        if on_start:
            on_start(len(todo), report.up_to_date)
        jobs = [{**p.job(s), "plot": plots} for s in sorted(todo, key=_text_answers_last)]
        if scheduler is not None:
            report.backend = "dask"
            report.workers = run_dask(jobs, p.sources, scheduler, done)
        elif jobs:
            report.workers = min(workers or os.cpu_count() or 1, len(jobs))
            run_local(jobs, p.sources, report.workers, done)
    report.seconds = time.monotonic() - start
    return report


# =========================================================================== local process pool

def run_local(jobs: Iterable[dict[str, Any]], sources: dict[str, str], workers: int, done: ResultCallback) -> None:
    """Grade ``jobs`` on ``workers`` warmed grader processes; ``done`` gets each result as it arrives."""
    queue = deque(jobs)
    graders = [GraderProcess(sources) for _ in range(max(1, min(workers, len(queue))))]
    try:
        while queue or any(g.job is not None for g in graders):
            for g in graders:
                if g.job is None and queue:
                    g.submit(queue.popleft())
            busy = [g for g in graders if g.job is not None]
            ready = wait([g.recv_conn for g in busy], timeout=1.0)
            look_after(graders, sources, ready, time.monotonic(), lambda job, result: done(result),
                       lambda: queue.popleft() if queue else None)
    finally:
        for g in graders:
            if g.job is not None:
                g.kill()
        stop_all([g for g in graders if g.job is None])


# =========================================================================== Dask

_DASK_LOCK = threading.Lock()
_DASK_IDLE: dict[str, list[GraderProcess]] = {}


def _sources_key(sources: dict[str, str]) -> str:
    return hashlib.sha256(json.dumps(sources, sort_keys=True).encode()).hexdigest()[:16]


def _take(sources: dict[str, str]) -> GraderProcess:
    key = _sources_key(sources)
    with _DASK_LOCK:
        for other in [k for k in _DASK_IDLE if k != key]:  # another assignment's graders: retire them
            stop_all(_DASK_IDLE.pop(other))
        idle = _DASK_IDLE.setdefault(key, [])
        if idle:
            return idle.pop()
    # not the main thread of a Dask worker: no parent-death signal (it follows the creating thread)
    return GraderProcess(sources, parent_death_signal=False)


def _give_back(sources: dict[str, str], g: GraderProcess) -> None:
    with _DASK_LOCK:
        _DASK_IDLE.setdefault(_sources_key(sources), []).append(g)


def dask_warm(sources: dict[str, str], count: int) -> int:
    """Run on every Dask worker before grading: start and warm its grader processes."""
    graders = [_take(sources) for _ in range(count)]
    for g in graders:
        g.wait_ready()
        _give_back(sources, g)
    return os.getpid()


def dask_stop() -> int:
    with _DASK_LOCK:
        graders = [g for gs in _DASK_IDLE.values() for g in gs]
        _DASK_IDLE.clear()
    stop_all(graders)
    return len(graders)


def dask_grade(job: dict[str, Any], sources: dict[str, str]) -> dict[str, Any]:
    """The Dask task: grade one job in one of this worker's warmed grader processes."""
    g = _take(sources)
    start = time.monotonic()
    try:
        g.wait_ready()
        g.submit(job)
        result = g.result(timeout=hard_deadline(job["limits"]))
    except TimeoutError:
        g.kill()
        return failed_result(job, job["parts"], "timeout", overran(job["limits"]), time.monotonic() - start)
    except WorkerDied:
        g.kill()
        return failed_result(job, job["parts"], "grader-crash",
                             "the grader process died while grading this file; please report it",
                             time.monotonic() - start)
    _give_back(sources, g)
    return result


def run_dask(jobs: list[dict[str, Any]], sources: dict[str, str], scheduler: Any, done: ResultCallback) -> int:
    """Grade ``jobs`` on a Dask cluster: ``scheduler`` is an address, a ``Client`` or a cluster object."""
    try:
        from distributed import Client, as_completed
    except ImportError:  # pragma: no cover
        raise RuntimeError("grading on a Dask cluster needs 'pip install lagrade[dask]'") from None

    own = not isinstance(scheduler, Client)
    client = Client(scheduler) if own else scheduler
    try:
        info = client.scheduler_info(n_workers=-1) if _accepts_n_workers(client) else client.scheduler_info()
        threads = {addr: w.get("nthreads", 1) for addr, w in info["workers"].items()}
        if not jobs:
            return sum(threads.values())
        for addr, n in threads.items():
            client.run(dask_warm, sources, n, workers=[addr])
        src = client.scatter(sources, broadcast=True)
        futures = [client.submit(dask_grade, job, src, pure=False, retries=1) for job in jobs]
        by_future = dict(zip(futures, jobs))
        for fut in as_completed(futures):
            job = by_future.pop(fut)
            try:
                result = fut.result()
            except Exception as exc:  # noqa: BLE001  (a Dask worker lost for good)
                result = failed_result(job, job["parts"], "grader-crash",
                                       f"the Dask worker grading this file failed ({type(exc).__name__}: {exc})", 0.0)
            done(result)
            fut.release()
        return sum(threads.values())
    finally:
        if own:
            client.close()


def _accepts_n_workers(client: Any) -> bool:
    import inspect

    return "n_workers" in inspect.signature(client.scheduler_info).parameters
