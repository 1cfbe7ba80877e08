"""Starting and stopping grader processes: what the coordinator relies on."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import time
from pathlib import Path

from lagrade.uses.bulk.worker import (
    _ORPHAN,
    SYMPY_CACHE_ENTRIES,
    GraderProcess,
    _pid_namespace,
    grader_environment,
    remove_orphaned_folders,
    stop_all,
)
from lagrade.problem.library import problem_path, reference_dir


class _FakeProc:
    def __init__(self, log: list, name: str) -> None:
        self.log, self.name = log, name

    def wait(self, timeout: float | None = None) -> int:
        self.log.append(("wait", self.name))
        return 0


class _FakeGrader:
    """Records the order in which `stop_all` closes and waits."""

    def __init__(self, log: list, name: str) -> None:
        self.log, self.name = log, name
        self.proc = _FakeProc(log, name)

    def close(self) -> None:
        self.log.append(("close", self.name))

    def kill(self) -> None:
        self.log.append(("kill", self.name))

    def remove_dir(self) -> None:
        self.log.append(("remove", self.name))


def test_stop_all_closes_every_pipe_before_waiting_for_any():
    # a grader winds down only once its pipe closes: waiting on the first before closing the second
    # made a class's graders stop one after another
    log: list = []
    stop_all([_FakeGrader(log, "a"), _FakeGrader(log, "b"), _FakeGrader(log, "c")])
    assert log == [("close", "a"), ("close", "b"), ("close", "c"),
                   ("wait", "a"), ("remove", "a"), ("wait", "b"), ("remove", "b"), ("wait", "c"), ("remove", "c")]


def test_a_grader_process_saves_its_references_before_it_exits(tmp_path, monkeypatch):
    # the process leaves with os._exit, skipping the interpreter's teardown: what it derived must
    # already be on disk for the next run (or a `lagrade check`) to start warm
    cache = tmp_path / "cache"
    monkeypatch.setenv("LAGRADE_CACHE", str(cache))
    answer = reference_dir() / "12.14" / "answer.py"
    g = GraderProcess({"12.14": problem_path("12.14").read_text(encoding="utf-8")})
    try:
        g.wait_ready()
        g.submit({"student": "s", "problem": "12.14", "suffix": ".py", "data": answer.read_bytes(),
                  "accuracy": "default", "credit": None, "parts": [], "file_hash": "",
                  "limits": {"cpu_seconds": 10, "wall_seconds": 20, "memory_mb": 300, "grading_seconds": 60}})
        result = g.result(timeout=120)
    finally:
        g.stop()
    assert result["outcome"] == "graded" and result["score"] == result["max_score"] > 0
    assert g.proc.returncode == 0
    assert [p.name.split("-")[0] for p in Path(cache).glob("*.pkl")] == ["12.14"]


def test_a_killed_grader_leaves_no_files_behind(tmp_path):
    # its folder holds the problems and the submission it was grading: the coordinator made it, and
    # removes it, since a process killed in the middle of a job cannot (the answer's working folder
    # lives in the jail's own tmpfs, gone with it)
    loop = tmp_path / "loop.py"
    loop.write_text("x = 0\nwhile True:\n    x += 1\n")
    g = GraderProcess({"12.14": problem_path("12.14").read_text(encoding="utf-8")})
    g.wait_ready()
    g.submit({"student": "s", "problem": "12.14", "suffix": ".py", "data": loop.read_bytes(),
              "accuracy": "default", "credit": None, "parts": [], "file_hash": "",
              "limits": {"cpu_seconds": 10, "wall_seconds": 20, "memory_mb": 300, "grading_seconds": 60}})
    deadline = time.monotonic() + 60
    while not list(Path(g.dir).glob("lagrade-job-*/12.14.py")) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert list(Path(g.dir).glob("lagrade-job-*/12.14.py")), "the grader never wrote the job's file"
    g.kill()
    assert not Path(g.dir).exists()


def test_a_stopped_grader_leaves_no_files_behind():
    g = GraderProcess({"12.14": problem_path("12.14").read_text(encoding="utf-8")})
    g.wait_ready()
    assert (Path(g.dir) / "problems" / "12.14.toml").is_file()
    # the folder is traversable (a sandbox child reaches its working folder in it), what is in it is not
    assert stat.S_IMODE(os.stat(g.dir).st_mode) == 0o711
    assert stat.S_IMODE(os.stat(Path(g.dir) / "problems").st_mode) == 0o700
    environ = dict(kv.split("=", 1) for kv in Path(f"/proc/{g.pid}/environ").read_text().split("\0") if "=" in kv)
    assert environ["TMPDIR"] == g.dir
    assert environ["SYMPY_CACHE_SIZE"] == os.environ.get("SYMPY_CACHE_SIZE", str(SYMPY_CACHE_ENTRIES))
    assert environ["OPENBLAS_NUM_THREADS"] == os.environ.get("OPENBLAS_NUM_THREADS", "1")
    g.stop()
    assert g.proc.returncode == 0 and not Path(g.dir).exists()


def test_a_grader_gets_a_larger_sympy_cache_unless_one_is_set(monkeypatch):
    # sympy's default (1000 entries per cache) loses the warm-up's expressions after one answer
    monkeypatch.delenv("SYMPY_CACHE_SIZE", raising=False)
    env = grader_environment("/somewhere")
    assert env["TMPDIR"] == "/somewhere"
    assert int(env["SYMPY_CACHE_SIZE"]) == SYMPY_CACHE_ENTRIES > 1000
    monkeypatch.setenv("SYMPY_CACHE_SIZE", "500")  # an instructor's own choice wins
    assert grader_environment("/somewhere")["SYMPY_CACHE_SIZE"] == "500"


def test_a_grader_starts_one_blas_thread_unless_told_otherwise(monkeypatch):
    # OpenBLAS's thread pools cost CPU to start and never help lagrade's few-row matrices
    monkeypatch.delenv("OPENBLAS_NUM_THREADS", raising=False)
    assert grader_environment("/somewhere")["OPENBLAS_NUM_THREADS"] == "1"
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "4")
    assert grader_environment("/somewhere")["OPENBLAS_NUM_THREADS"] == "4"


def test_only_this_users_folders_of_coordinators_that_no_longer_run_are_removed(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True,
                          text=True, check=True)
    dead_pid = int(dead.stdout)
    ns = _pid_namespace()

    def folder(name: str) -> Path:
        path = tmp_path / name
        path.mkdir()
        (path / "lagrade-job-x").mkdir()
        (path / "lagrade-job-x" / "12.14.py").write_text("L = 0\n")
        return path

    orphan = folder(f"lagrade-grader-{ns}-{dead_pid}-abc_1")
    running = folder(f"lagrade-grader-{ns}-{os.getpid()}-abc_2")          # this process runs
    elsewhere = folder(f"lagrade-grader-{ns + 1}-{dead_pid}-abc_3")     # another pid namespace
    old_style = folder("lagrade-grader-abc_4")                            # no pid in the name
    target = folder("kept")
    link = tmp_path / f"lagrade-grader-{ns}-{dead_pid}-abc_5"
    link.symlink_to(target)
    a_file = tmp_path / f"lagrade-grader-{ns}-{dead_pid}-abc_6"
    a_file.write_text("")
    others = None
    if os.getuid() == 0:  # another user's folder: only root can make one here
        others = folder(f"lagrade-grader-{ns}-{dead_pid}-abc_7")
        for p in (others, *others.rglob("*")):
            os.chown(p, 65534, 65534)

    assert remove_orphaned_folders(str(tmp_path)) == [str(orphan)]
    assert not orphan.exists()
    for kept in (running, elsewhere, old_style, target / "lagrade-job-x" / "12.14.py", link, a_file):
        assert kept.exists() or kept.is_symlink()
    if others is not None:
        assert others.exists()


def test_a_grader_folder_names_its_coordinator():
    g = GraderProcess({"12.14": problem_path("12.14").read_text(encoding="utf-8")})
    try:
        m = _ORPHAN.fullmatch(Path(g.dir).name)
        assert m and int(m.group(1)) == _pid_namespace() and int(m.group(2)) == os.getpid()
    finally:
        g.kill()


def test_a_grader_gives_a_value_it_graded_before_the_verdict_it_got():
    """A class hands in the same values again and again (here the reference, in files of their own):
    the grader's memo gives each part the verdict and feedback it got, without grading it again. The
    warm-up's grading of the reference solution is the first entry."""
    from lagrade.uses.bulk.worker import Grader
    from lagrade.problem.library import load_problem

    grader = Grader({"12.14": problem_path("12.14").read_text()})
    try:
        data = (reference_dir() / "12.14" / "answer.py").read_bytes()
        limits = {"cpu_seconds": 10, "wall_seconds": 20, "memory_mb": 512, "grading_seconds": 60}
        job = {"student": "a", "problem": "12.14", "suffix": ".py", "data": data, "accuracy": "default",
               "limits": limits, "credit": None, "parts": [], "file_hash": ""}
        parts = len(load_problem("12.14").parts)
        assert grader.memo.hits == 0 and len(grader.memo._kept) == parts  # the warm-up graded the reference
        first = grader.grade(job)
        again = grader.grade({**job, "student": "b", "data": b"# written by b\n" + data})
        assert grader.memo.hits == 2 * parts
        assert again["parts"] == first["parts"] and again["score"] == first["score"] == first["max_score"]
    finally:
        grader.close()


def test_a_grader_runs_the_same_program_once_and_a_bound_never_decides_for_the_next_copy(monkeypatch):
    """A class hands in the same program again and again: a grader runs a file in the jail once and
    gives every copy graded with the same settings that result, whatever its comments say (other
    code, other settings: run again). A result a bound decided (here the answer's CPU limit) is not the file's own: the next
    copy runs again."""
    import lagrade.answer.reading.load as load
    from lagrade.uses.bulk.worker import Grader

    runs: list[bytes] = []
    real = load.load_answer

    def counted(path, *args, **kwargs):
        runs.append(Path(path).read_bytes())
        return real(path, *args, **kwargs)

    grader = Grader({"12.14": problem_path("12.14").read_text()})
    monkeypatch.setattr(load, "load_answer", counted)
    try:
        data = (reference_dir() / "12.14" / "answer.py").read_bytes()
        limits = {"cpu_seconds": 10, "wall_seconds": 20, "memory_mb": 512, "grading_seconds": 60}
        job = {"student": "a", "problem": "12.14", "suffix": ".py", "data": data, "accuracy": "default",
               "limits": limits, "credit": None, "parts": [], "file_hash": ""}
        first = grader.grade(job)
        copy = grader.grade({**job, "student": "b", "data": data + b"\n# Bob's copy\n"})
        assert len(runs) == 1
        assert copy["student"] == "b" and first["student"] == "a"
        assert {k: v for k, v in copy.items() if k not in ("student", "seconds")} == \
               {k: v for k, v in first.items() if k not in ("student", "seconds")}
        grader.grade({**job, "data": data + b"\nnote = 1\n"})  # a line of code more
        grader.grade({**job, "accuracy": "strict"})  # other settings
        grader.grade({**job, "read_back": True})  # the server's read-back asked for
        assert len(runs) == 4
        loop = b"while True:\n    pass\n"
        bounded = {**job, "data": loop, "limits": {**limits, "cpu_seconds": 0.3, "wall_seconds": 5}}
        assert grader.grade(bounded)["status"] == "timeout"
        assert grader.grade({**bounded, "student": "b"})["status"] == "timeout"
        assert len(runs) == 6
    finally:
        grader.close()


def test_an_answers_child_is_killed_only_while_its_parent_is_the_one_seen():
    """The server stops a slow grading by killing its answer's children, found by one walk of /proc;
    a pid reused since then must not be signalled: the kill goes through a pidfd opened before the
    process's parent is checked again."""
    from lagrade.uses.bulk.worker import _kill_if_child_of

    child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        _kill_if_child_of(child.pid, parent=os.getpid() + 1)  # not the parent the walk saw: left alone
        time.sleep(0.2)
        assert child.poll() is None
        _kill_if_child_of(child.pid, parent=os.getpid())
        assert child.wait(timeout=10) == -9
        _kill_if_child_of(child.pid, parent=os.getpid())  # gone (a zombie reaped): nothing to do, no error
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
