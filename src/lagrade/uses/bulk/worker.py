"""Grading one submission in a warmed grader process, and the process that does it.

A grader process (``python -m lagrade.uses.bulk.worker``) is started once per core (or per Dask worker
thread), loads the assignment's problems from their TOML text and derives their references once,
then grades jobs sent over a pipe until the pipe closes. Grading runs on the process's main thread,
so the engine's time-bounded proofs stay bounded, and under a CPU-time bound of its own
(`lagrade.verdicts.grade.cpu_time_bound`; the engine uses ``ITIMER_REAL`` for its proofs). The student's code itself runs
further down, in the engine's sandbox (a forked child with CPU, memory and wall-clock limits).
The coordinator kills a grader process that overruns a hard deadline and starts a new one.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

from lagrade.numbers.process_env import single_threaded_blas
from lagrade.uses.bulk.result_memo import ResultMemo, content_key, result_key

#: kinds of status a submission gets; ``ok`` means the file ran (its parts carry the verdicts)
STATUSES = ("ok", "error", "syntax", "rejected", "timeout", "memory", "crashed", "grader-timeout",
            "grader-crash")


# =========================================================================== in the grader process

class Grader:
    """The warmed state of a grader process: problems loaded, references derived."""

    def __init__(self, problems: dict[str, str], directory: str | None = None) -> None:
        """``directory``: where the problems and each job's file go (made here if not given); the
        coordinator makes it, so that it can remove it when it has to kill this process."""
        from lagrade.answer.jail import zygote
        from lagrade.verdicts.grade import references
        from lagrade.problem.library import load_problem
        from lagrade.verdicts.verdict_memo import VerdictMemo

        self.dir = Path(directory) if directory else Path(tempfile.mkdtemp(prefix=_folder_prefix()))
        # first, so that it warms up on the other core meanwhile: a fresh interpreter that never
        # holds what this process is about to load (the problems, their references)
        self.zygote = zygote.start(warm=True, directory=str(self.dir))
        self.memo = VerdictMemo()  # a class hands in the same values again and again
        self.pictures: dict[bytes, bytes | None] = {}  # a wrong file's picture, by its content (`_picture`)
        self.results = ResultMemo()  # a class hands in the same program again and again
        (self.dir / "problems").mkdir(mode=0o700, exist_ok=True)  # the folder itself is traversable
        self.problems = {}
        for pid, text in problems.items():
            path = self.dir / "problems" / f"{pid}.toml"
            path.write_text(text, encoding="utf-8")
            problem = load_problem(path)
            refs = references(problem)
            for system in problem.systems:
                refs[system.key]
            self.problems[pid] = problem
            _warm_up(problem, self.memo)
        #: the jail's layers active for every answer this grader runs (recorded in the gradebook)
        self.jail = ",".join(self.zygote.active) or "none"

    def close(self) -> None:
        from lagrade.answer.jail import zygote
        from lagrade.verdicts.grade import keep_references

        zygote.stop()
        for problem in self.problems.values():
            keep_references(problem)  # the next run (or `lagrade check`) starts warm
        shutil.rmtree(self.dir, ignore_errors=True)

    def grade(self, job: dict[str, Any]) -> dict[str, Any]:
        from lagrade.answer.reading.load import load_answer
        from lagrade.answer.jail.sandbox import SandboxLimits
        from lagrade.uses.bulk.display import show
        from lagrade.verdicts.credit import Credit
        from lagrade.verdicts.grade import GradingOutOfTime, cpu_time_bound, grade_values

        start = time.monotonic()
        problem = self.problems[job["problem"]]
        limits = job["limits"]
        key = job.get("result_key") or result_key(job)  # the server's queue keyed it already
        kept = self._kept(job, key)
        if kept is not None:
            return kept
        work = Path(tempfile.mkdtemp(prefix="lagrade-job-", dir=self.dir))
        path = work / f"{job['problem']}{job['suffix']}"
        path.write_bytes(job["data"])
        try:
            with cpu_time_bound(limits["grading_seconds"]):
                loaded = load_answer(path, problem, SandboxLimits(cpu_seconds=limits["cpu_seconds"],
                                                                   wall_seconds=limits["wall_seconds"],
                                                                   memory_mb=limits["memory_mb"]))
                # the gradebook keeps its own text and MathML; the server's answer also says how each value
                # was read (`check --json`'s read_as), printed here from the value rather than read back
                # from its text in the web process, which served every submission alone (about 12 ms a part)
                echo = ("latex", "unicode") if job.get("read_back") else ()
                result = grade_values(problem, loaded, job["accuracy"], hints=bool(job.get("hints")),
                                      credit=Credit.model_validate(job["credit"]) if job.get("credit") else None,
                                      read_as=echo, memo=self.memo)
                parts = []
                for p in result.parts:
                    row = p.model_dump(exclude={"read_as"})
                    row["detail"] = p.detail  # the traceback of an `error`: for the instructor's gradebook only
                    row["certificate"] = p.certificate  # the proof of a rejection: the gradebook's, never shown
                    if p.part in loaded.values:
                        row["answer_text"], row["answer_mathml"] = show(loaded.values[p.part])
                        if echo:
                            row["read_back"] = [p.read_as, p.read_as_text]
                    parts.append(row)
                # the server's page shows `check --plot`'s picture: made here, where the student's equations are
                picture = None
                if job.get("plot") and any(p.verdict != "correct" for p in result.parts):
                    picture = self._picture(job, result, lambda: grade_values(
                        problem, loaded, job["accuracy"], read_as=(),
                        credit=Credit.model_validate(job["credit"]) if job.get("credit") else None))
        except GradingOutOfTime as exc:  # the file's cost, not the grader's fault: final, never retried
            return failed_result(job, problem_parts(problem), "timeout", str(exc), time.monotonic() - start)
        finally:
            shutil.rmtree(work, ignore_errors=True)
        unusable = loaded.fatal is not None and not loaded.values
        reason = str(loaded.fatal) if loaded.fatal is not None else ""
        out = {
            "student": job["student"], "problem": job["problem"],
            "outcome": "failed" if unusable else "graded",
            "status": _status(reason) if reason else "ok",
            "reason": reason, "score": result.score, "max_score": result.max_score,
            "problems": result.problems, "parts": parts, "seconds": time.monotonic() - start,
            "jail": self.jail, **({"plot_png": picture} if picture else {}),
        }
        self.results.put(key, out)
        return out

    def _kept(self, job: dict[str, Any], key: bytes) -> dict[str, Any] | None:
        """The result of the same program graded before with the same settings
        (`lagrade.uses.bulk.result_memo`), with the picture of its wrong motions when the job asks
        for it and this grader drew it; None when the file is to be graded (a picture asked for and
        not drawn yet sends it through grading: drawing needs its motions)."""
        out = self.results.get({**job, "plot": False}, key)
        if out is None:
            return None
        if job.get("plot") and any(p["verdict"] != "correct" for p in out["parts"]):
            picture = self.pictures.get(content_key(job), False)
            if picture is False:
                return None
            if picture:
                out["plot_png"] = picture
        return out

    def _picture(self, job: dict[str, Any], result, again: Callable[[], Any]) -> bytes | None:
        """The picture of a wrong answer's motions, drawn once per distinct file: a class hands in the
        same bytes again and again (the picture is a function of the file, the problem and the
        grading settings), and drawing one costs a grading again (a verdict kept by the memo carries
        no motion) and matplotlib's 0.1-0.4 s."""
        key = content_key(job)
        if key in self.pictures:
            self.pictures[key] = self.pictures.pop(key)  # most recently used last
            return self.pictures[key]
        picture = _picture(result)
        if picture is None:  # a verdict kept from before carries no motion: grade again, unkept, to draw it
            picture = _picture(again())
        self.pictures[key] = picture
        while len(self.pictures) > PICTURES_KEPT:
            self.pictures.pop(next(iter(self.pictures)))
        return picture


#: distinct files whose pictures a grader keeps (a PNG is 30-80 kB)
PICTURES_KEPT = 64


def _warm_up(problem, memo=None) -> None:
    """Grade the problem's reference solution (trusted: it ships with lagrade) once before the class.

    Running it in this process fills sympy's caches with the expressions a correct answer builds
    (the children run in the zygote, which never sees it). Grading it compiles and integrates what
    the answers will share, and gives the ``memo`` the reference's own verdicts (many answers share
    some of its values)."""
    from lagrade.answer.reading.load import load_answer
    from lagrade.verdicts.grade import grade_values
    from lagrade.problem.library import reference_dir

    answer = reference_dir() / problem.id / "answer.py"
    if not answer.is_file():
        return
    try:
        exec(compile(answer.read_text(encoding="utf-8"), str(answer), "exec"), {"__name__": "__reference__"})  # noqa: S102
        grade_values(problem, load_answer(answer, problem), read_as=(), memo=memo)
    except Exception:  # noqa: BLE001  (a warm-up that fails only costs speed)
        pass


def _picture(result) -> bytes | None:
    """The PNG of the wrong dynamics parts (:func:`lagrade.verdicts.plot.plot_png`); None when there is none
    or it cannot be drawn (a picture that fails costs the student the picture, not the grade)."""
    from lagrade.verdicts.plot import plot_png

    try:
        return plot_png(result)
    except Exception:  # noqa: BLE001
        return None


def _status(reason: str) -> str:
    r = reason.lower()
    if "ran longer than" in r:
        return "timeout"
    if "memory" in r:
        return "memory"
    if "crashed" in r or "could not be run" in r:
        return "crashed"
    if "syntax error" in r or "cannot parse" in r or "not valid utf-8" in r:
        return "syntax"
    if "not allowed" in r or "refused" in r or "larger than" in r:
        return "rejected"
    return "error"


def problem_parts(problem) -> list[tuple[str, float]]:
    return [(p.name, p.weight) for p in problem.parts]


def failed_result(job: dict[str, Any], parts: list[tuple[str, float]], status: str, reason: str,
                  seconds: float) -> dict[str, Any]:
    """A submission that could not be graded: every part invalid with the reason, score 0."""
    return {
        "student": job["student"], "problem": job["problem"], "outcome": "failed", "status": status,
        "reason": reason, "score": 0.0, "max_score": float(sum(w for _, w in parts)), "problems": [reason],
        "parts": [{"part": name, "verdict": "invalid", "score": 0.0, "max_score": w, "method": "exact",
                   "feedback": f"not graded: {reason}"} for name, w in parts],
        "seconds": seconds,
    }


def serve(conn: Any, parent_death_signal: bool = True) -> None:
    """The grader process's loop: warm up from the first message, then grade until EOF."""
    if parent_death_signal:
        from lagrade.answer.jail.kernel import die_with_parent

        die_with_parent()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the coordinator's business
    try:
        hello = conn.recv()
    except (EOFError, OSError):
        return
    try:
        grader = Grader(hello["problems"], hello.get("dir"))
        conn.send({"ready": True, "pid": os.getpid()})
    except Exception as exc:  # noqa: BLE001
        conn.send({"ready": False, "error": f"{type(exc).__name__}: {exc}"})
        return
    try:
        while True:
            try:
                job = conn.recv()
            except (EOFError, OSError):
                return
            try:
                out = grader.grade(job)
            except Exception as exc:  # noqa: BLE001  (an engine bug fails this submission only)
                problem = grader.problems.get(job.get("problem"))
                out = failed_result(job, problem_parts(problem) if problem else [], "grader-crash",
                                    f"lagrade could not grade this file ({type(exc).__name__}: {exc}); "
                                    f"please report it", 0.0)
            conn.send(out)
    finally:
        grader.close()



# =========================================================================== the coordinator's handle

class WorkerDied(RuntimeError):
    pass


#: entries in each of sympy's LRU caches, in a grader process and so in the sandbox children forked
#: from it. sympy's default, 1000, is too small for a grader: grading one answer evicts most of what
#: the warm-up cached, and a child then re-derives the assumptions of every expression it builds
#: (an answer that builds the double pendulum's L and equations ran in 40 ms instead of 14). With
#: 20000, a class of 12.14 took 7-11% less CPU; its run's peak memory, all processes, went from 324
#: to 348 MiB, and stays flat in the class size (an LRU is bounded).
SYMPY_CACHE_ENTRIES = 20000


def grader_environment(directory: str) -> dict[str, str]:
    """A grader's environment: this one's, with its folder as TMPDIR, a larger sympy cache (unless
    SYMPY_CACHE_SIZE is set already; sympy reads it once, when it is imported) and one BLAS thread
    (a Dask worker's graders are not started by the ``lagrade`` script)."""
    env = {**os.environ, "TMPDIR": directory}
    env.setdefault("SYMPY_CACHE_SIZE", str(SYMPY_CACHE_ENTRIES))
    single_threaded_blas(env)
    return env


def _folder_prefix() -> str:
    """``lagrade-grader-NS-PID-``: the pid namespace and pid of the process making a grader folder
    (the coordinator, or a grader made in-process), so that a later run can tell whether it still runs."""
    return f"lagrade-grader-{_pid_namespace()}-{os.getpid()}-"


def _pid_namespace() -> int:
    try:
        return os.stat("/proc/self/ns/pid").st_ino
    except OSError:
        return 0


_ORPHAN = re.compile(r"lagrade-grader-(\d+)-(\d+)-[A-Za-z0-9_]+")
_swept = False


def _remove_orphans_once() -> None:
    """`remove_orphaned_folders` in the temporary directory, the first time a grader is started."""
    global _swept
    if not _swept:
        _swept = True
        remove_orphaned_folders(tempfile.gettempdir())


def remove_orphaned_folders(root: str) -> list[str]:
    """Remove the grader folders in ``root`` that a killed coordinator left behind.

    When ``lagrade grade`` itself is killed (kill -9, the out-of-memory killer), its graders die with
    it and no process is left to remove their folders, which hold a submission and its sandbox's
    working folder. A folder goes if this user owns it (a real folder, not a link), and the process
    named in it, in this pid namespace, no longer runs. A pid in use keeps its folder, even if it was
    reused by another program; a folder from another pid namespace (a container sharing /tmp) is
    never touched. Returns the folders removed."""
    namespace, removed = _pid_namespace(), []
    try:
        names = os.listdir(root)
    except OSError:
        return removed
    for name in names:
        m = _ORPHAN.fullmatch(name)
        if not m or int(m.group(1)) != namespace or _running(int(m.group(2))):
            continue
        path = os.path.join(root, name)
        try:
            st = os.lstat(path)
        except OSError:
            continue
        if stat.S_ISDIR(st.st_mode) and st.st_uid == os.getuid():
            shutil.rmtree(path, ignore_errors=True)
            removed.append(path)
    return removed


def _running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process: it runs
        return True
    return True


# =========================================================================== priorities (the server's fairness)

#: CPU seconds an answer's own code (its jailed children) may use at normal priority, and the
#: grader's own work on one file (reading, comparing, drawing): `benchmarks/grading_cpu.py` measures
#: honest answers against both. The first is small because an answer's code only binds names (a loop
#: or a memory bomb shows itself there first); the second, because it is the reference's work too.
CPU_BUDGET = 0.5
GRADER_BUDGET = 1.5
#: the nice value of a grading over its budget: the lowest CPU weight an unprivileged process can set
LOWERED_NICE = 19


def _proc_table() -> dict[int, tuple[int, float, float]]:
    """pid -> (parent pid, own CPU seconds, reaped children's CPU seconds), from one walk of /proc."""
    tick = os.sysconf("SC_CLK_TCK")
    table = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as f:
                fields = f.read().rsplit(b")", 1)[1].split()
        except OSError:
            continue
        table[int(entry)] = (int(fields[1]), (int(fields[11]) + int(fields[12])) / tick,
                             (int(fields[13]) + int(fields[14])) / tick)
    return table


def _kill_if_child_of(pid: int, parent: int) -> None:
    """SIGKILL ``pid`` if it is still a child of ``parent`` (a pidfd pins the process first; without
    pidfds, as on kernels before 5.3, a plain kill after the same check)."""
    opened = getattr(os, "pidfd_open", None)
    try:
        fd = opened(pid) if opened is not None else None
    except OSError:  # gone
        return
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            if int(f.read().rsplit(b")", 1)[1].split()[1]) != parent:
                return  # not the process the walk saw: its pid was reused
        if fd is not None:
            signal.pidfd_send_signal(fd, signal.SIGKILL)
        else:
            os.kill(pid, signal.SIGKILL)
    except OSError:  # gone meanwhile
        pass
    finally:
        if fd is not None:
            os.close(fd)


def _tree(table: dict[int, tuple[int, float, float]], root: int) -> list[int]:
    """``root`` and its descendants (the grader, its zygote, the answers' children)."""
    below: dict[int, list[int]] = {}
    for pid, (parent, _, _) in table.items():
        below.setdefault(parent, []).append(pid)
    out, todo = [], [root] if root in table else []
    while todo:
        pid = todo.pop()
        out.append(pid)
        todo.extend(below.get(pid, ()))
    return out


def lower(pids, session: int | None = None) -> None:
    """Every thread of ``pids`` at :data:`LOWERED_NICE` (nice is per thread on Linux; a thread or a
    child made later inherits it). A process gone meanwhile is skipped.

    With the kernel's autogroups (``/proc/sys/kernel/sched_autogroup_enabled``), the CPU is shared
    between sessions first and a thread's nice counts only within its session: an answer's child,
    which makes a session of its own (``setsid``), weighs as much as the whole server. So the
    session of a process outside ``session`` (the grader's) is lowered too: its
    ``/proc/<pid>/autogroup`` nice (the grader's own session is the server's: never touched)."""
    for pid in pids:
        if session is not None:
            _lower_autogroup(pid, session)
        try:
            tids = [int(t) for t in os.listdir(f"/proc/{pid}/task")]
        except OSError:
            continue
        for tid in tids:
            try:
                if os.getpriority(os.PRIO_PROCESS, tid) < LOWERED_NICE:
                    os.setpriority(os.PRIO_PROCESS, tid, LOWERED_NICE)
            except OSError:  # gone, or not ours to lower (then it keeps its weight: no worse than before)
                pass


def _lower_autogroup(pid: int, session: int) -> None:
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            theirs = int(f.read().rsplit(b")", 1)[1].split()[3])
        if theirs in (session, 0):
            return
        with open(f"/proc/{pid}/autogroup", "r+") as f:
            if not f.read().rstrip().endswith(f"nice {LOWERED_NICE}"):
                f.write(str(LOWERED_NICE))
    except (OSError, ValueError, IndexError):  # gone, no autogroups, or not ours
        pass


def watch(graders: list[GraderProcess], now: float, budget: float = CPU_BUDGET,
          grader_budget: float = GRADER_BUDGET) -> None:
    """Lower the gradings that have used more CPU than allowed (a feedback queue of two levels):
    their answers' children once the answer's code has used more than ``budget`` seconds
    (``lowered``); the grader and its zygote too once the grader's own work on the file is over
    ``grader_budget`` (``retire``: an unprivileged process cannot raise its priority again, so that
    grader is replaced once its job is done). The bounds stay what they
    were: the CPU bounds count the same seconds, spent later; the wall-clock bounds of a lowered
    grading are stretched (:data:`lagrade.answer.jail.sandbox.LOWERED_WALL_FACTOR`). One walk of /proc a
    round, and only when a grading has run long enough to be over the budget."""
    due = [g for g in graders if g.job is not None and g.ready and g.baseline is not None
           and (g.lowered or now - g.started > min(budget, grader_budget) / 2)]
    if not due:
        return
    table = _proc_table()
    for g in due:
        pids = _tree(table, g.pid)
        own = sum(table[p][1] for p in g.own_pids if p in table) - g.baseline[0]
        used = sum(table[p][1] for p in pids) + sum(table[p][2] for p in g.own_pids if p in table) - g.baseline[1]
        if used - own > budget or g.lowered:  # the answer's children, running and reaped
            g.lowered = True
            lower([p for p in pids if p not in g.own_pids], session=g.session)
        if own > grader_budget or g.retire:
            g.retire = True
            lower(pids)


class GraderProcess:
    """A grader process seen from the coordinator: start, warm, send a job, wait, kill."""

    def __init__(self, problems: dict[str, str], *, parent_death_signal: bool = True) -> None:
        # Everything the grader writes: the problems, each job's submission, and (as its TMPDIR) the
        # sandbox children's working folders. The grader removes it when it stops, and this side when
        # the process is killed or dies. Traversable by others, as /tmp is, because a child that has
        # become `nobody` still reaches its own working folder by its full path; everything in it is
        # a folder of its own that only its owner can read (0700).
        _remove_orphans_once()
        self.dir = tempfile.mkdtemp(prefix=_folder_prefix())
        os.chmod(self.dir, 0o711)
        down_r, down_w = os.pipe()   # coordinator -> grader
        up_r, up_w = os.pipe()       # grader -> coordinator
        env = grader_environment(self.dir)
        debug = bool(env.get("LAGRADE_DEBUG"))
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "lagrade.uses.bulk.worker", str(down_r), str(up_w), "1" if parent_death_signal else "0"],
            pass_fds=(down_r, up_w), stdin=subprocess.DEVNULL,
            stdout=None if debug else subprocess.DEVNULL, stderr=None if debug else subprocess.DEVNULL,
            env=env, close_fds=True)
        os.close(down_r)
        os.close(up_w)
        self.send_conn = Connection(down_w, readable=False)
        self.recv_conn = Connection(up_r, writable=False)
        self.job: dict[str, Any] | None = None
        self.started = 0.0
        self.ready = False
        #: the grader and its zygote's pids (found once warm), and their CPU seconds when the job
        #: started (their own, and their own plus their reaped children's): see :func:`watch`
        self.own_pids: set[int] = set()
        self.baseline: tuple[float, float] | None = None
        self.session: int | None = None  # the grader's session (the server's)
        self.lowered = False  # this job's answer children run at LOWERED_NICE
        self.retire = False  # so does the grader: it is stopped once its job is done
        self.send_conn.send({"problems": problems, "dir": self.dir})

    @property
    def pid(self) -> int:
        return self.proc.pid

    def children(self) -> list[tuple[int, int]]:
        """The processes under this grader now that are not its own (its answer's jailed children), each
        with its parent: (pid, parent pid)."""
        table = _proc_table()
        return [(p, table[p][0]) for p in _tree(table, self.pid) if p not in self.own_pids]

    @staticmethod
    def kill_children(children: list[tuple[int, int]]) -> None:
        """SIGKILL the answer's children :meth:`children` found. Each is signalled through a pidfd opened
        before its parent is checked again, so a pid reused since the /proc walk is never signalled."""
        for pid, parent in children:
            _kill_if_child_of(pid, parent)

    def wait_ready(self, timeout: float = 600) -> None:
        if self.ready:
            return
        msg = self._recv(timeout)
        if not msg.get("ready"):
            raise WorkerDied(f"a grader process could not start: {msg.get('error')}")
        self.ready = True

    def submit(self, job: dict[str, Any]) -> None:
        self.job, self.started = job, time.monotonic()
        self.lowered = False
        self.mark_start()
        self.send_conn.send(job)

    def mark_start(self) -> None:
        """Note the CPU the grader and its zygote have used so far (a job starts: submitted to a
        warm grader, or the grader it waited for is warm); the first time, find their pids."""
        if not self.ready:
            self.baseline = None
            return
        if not self.own_pids:
            self.own_pids = set(_tree(_proc_table(), self.pid))  # between jobs: no answer's child runs
            try:
                self.session = os.getsid(self.pid)
            except OSError:
                pass
        own = kids = 0.0
        tick = os.sysconf("SC_CLK_TCK")
        for pid in self.own_pids:
            try:
                with open(f"/proc/{pid}/stat", "rb") as f:
                    fields = f.read().rsplit(b")", 1)[1].split()
            except OSError:
                continue
            own += (int(fields[11]) + int(fields[12])) / tick
            kids += (int(fields[13]) + int(fields[14])) / tick
        self.baseline = (own, own + kids)

    def fileno(self) -> int:
        return self.recv_conn.fileno()

    def poll(self) -> bool:
        return self.recv_conn.poll()

    def _recv(self, timeout: float) -> dict[str, Any]:
        if not wait([self.recv_conn], timeout):
            raise TimeoutError
        try:
            return self.recv_conn.recv()
        except (EOFError, OSError):
            raise WorkerDied("the grader process died") from None

    def result(self, timeout: float | None = None) -> dict[str, Any]:
        msg = self._recv(timeout if timeout is not None else 1e9)
        if not self.ready:  # the readiness message comes first
            if not msg.get("ready"):
                raise WorkerDied(f"a grader process could not start: {msg.get('error')}")
            self.ready = True
            msg = self._recv(timeout if timeout is not None else 1e9)
        self.job = None
        return msg

    def kill(self) -> None:
        try:
            self.proc.kill()
        except ProcessLookupError:
            pass
        self.proc.wait()
        self.close()
        self.remove_dir()

    def remove_dir(self) -> None:
        shutil.rmtree(self.dir, ignore_errors=True)

    def close(self) -> None:
        for c in (self.send_conn, self.recv_conn):
            try:
                c.close()
            except OSError:
                pass

    def stop(self) -> None:
        stop_all([self])


def stop_all(graders: list[GraderProcess]) -> None:
    """End idle grader processes: every pipe is closed before any is waited for, so that they wind
    down side by side (stopped one after another, each added about 0.5 s to the end of a class)."""
    for g in graders:
        g.close()  # EOF ends the loop
    deadline = time.monotonic() + 10
    for g in graders:
        try:
            g.proc.wait(timeout=max(0.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            g.kill()
        g.remove_dir()  # already gone unless the process failed before it could remove it


def overran(limits: dict[str, float], lowered: bool = False) -> str:
    """The reason of a file whose grading overran the hard deadline: a bound it hit (its cost, beyond
    the CPU bound, as a power bomb built while holding the GIL), final like any timeout."""
    return (f"grading this file did not finish in {hard_deadline(limits, lowered):g} s (beyond every time bound of the "
            "assignment); the grader was stopped")


def hard_deadline(limits: dict[str, float], lowered: bool = False) -> float:
    """Seconds after which the coordinator kills a grader process stuck on one job (a lowered
    grading's answer has a wall-clock bound :data:`LOWERED_WALL_FACTOR` times as long)."""
    from lagrade.answer.jail.sandbox import LOWERED_WALL_FACTOR

    return limits["wall_seconds"] * (LOWERED_WALL_FACTOR if lowered else 1) + 2 * limits["grading_seconds"] + 30


def look_after(graders: list[GraderProcess], sources: dict[str, str], ready: list, now: float,
               done: Callable[[dict[str, Any], dict[str, Any]], None],
               next_job: Callable[[], dict[str, Any] | None] = lambda: None) -> None:
    """One round over the busy graders, for a class run and the server's queue alike: a result goes
    to ``done(job, result)`` (the grader first takes ``next_job()``, so it works while the result is
    written); a grader that died or overran its hard deadline is replaced, and its file gets a
    verdict that says so. ``ready``: the connections `multiprocessing.connection.wait` returned."""
    for i, g in enumerate(graders):
        job = g.job
        if job is None:
            continue
        if g.recv_conn in ready:
            try:
                msg = g.recv_conn.recv()
            except (EOFError, OSError):
                msg = None
            if msg is None:
                g.kill()
                graders[i] = GraderProcess(sources)
                done(job, failed_result(job, job["parts"], "grader-crash",
                                        "the grader process died while grading this file (it may have used "
                                        "too much memory); please report it", now - g.started))
            elif "ready" in msg:
                if not msg["ready"]:
                    raise WorkerDied(f"a grader process could not start: {msg.get('error')}")
                g.ready, g.started = True, now
                g.mark_start()
            else:
                g.job = None
                # a lowered grading's grader takes no next job here: its owner retires it, or
                # counts it as quick again (`GradingQueue._run`)
                following = next_job() if not (g.lowered or g.retire) else None
                if following is not None:
                    g.submit(following)
                done(job, msg)
        elif g.ready and now - g.started > hard_deadline(job["limits"], g.lowered or g.retire):
            g.kill()
            graders[i] = GraderProcess(sources)
            done(job, failed_result(job, job["parts"], "timeout", overran(job["limits"], g.lowered or g.retire),
                                    now - g.started))
        elif not g.ready and now - g.started > 600:
            raise WorkerDied("a grader process did not warm up in 10 minutes")


class _Duplex:
    """The grader process's end: jobs come in on one pipe, results go out on the other."""

    def __init__(self, read_fd: int, write_fd: int) -> None:
        self._in = Connection(read_fd, writable=False)
        self._out = Connection(write_fd, readable=False)

    def recv(self) -> Any:
        return self._in.recv()

    def send(self, obj: Any) -> None:
        self._out.send(obj)


if __name__ == "__main__":
    serve(_Duplex(int(sys.argv[1]), int(sys.argv[2])), sys.argv[3] == "1")
    # everything is sent, saved and removed: skip the interpreter's teardown, which frees sympy's
    # caches and the compiled references object by object (~0.45 s of CPU per grader process)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)
