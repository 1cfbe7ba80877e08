"""A grader's sandbox children come from its fork server (lagrade.answers.forkserver): the same
outcomes as a direct fork (tests/test_sandbox.py runs every sandbox test both ways), and here what
is the server's own: it is used, it keeps none of the grader's descriptors, it reaps what nobody
asks about, it dies with its grader, and a grader whose server is gone forks its children itself."""

from __future__ import annotations

import os
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from lagrade.answers import forkserver
from lagrade.answers.rebuild import decode_value
from lagrade.answers.sandbox import SandboxLimits, run_answer_file, start_answer_file

FAST = SandboxLimits(cpu_seconds=2, wall_seconds=8, memory_mb=256)


@pytest.fixture
def server():
    made = forkserver.start()
    yield made
    forkserver.stop()


def _answer(tmp_path: Path, text: str = "L = 41 + 1\n") -> Path:
    path = tmp_path / "answer.py"
    path.write_text(text)
    return path


def _children(pid: int) -> list[tuple[int, str]]:
    """(pid, state) of the processes whose parent is ``pid``."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            fields = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append((int(entry), fields[0]))
    return found


def test_the_children_are_the_servers_and_not_ours(server, tmp_path, monkeypatch):
    spawned = []
    spawn = forkserver.ForkServer.spawn
    monkeypatch.setattr(forkserver.ForkServer, "spawn", lambda self, *a: spawned.append(spawn(self, *a)) or spawned[-1])
    running = start_answer_file(_answer(tmp_path, "L = 42\nwhile True:\n    pass\n"), ["L"],
                                SandboxLimits(cpu_seconds=1, wall_seconds=8))
    assert len(spawned) == 1
    child = spawned[0]
    assert (child, "R") in _children(server.pid) or any(pid == child for pid, _ in _children(server.pid))
    assert all(pid != child for pid, _ in _children(os.getpid()))
    out = running.wait()
    assert out.status == "timeout" and decode_value(out.values["L"]) == 42


def _network_namespace(pid: int | str) -> str:
    return os.readlink(f"/proc/{pid}/ns/net")


def _wait_until_running_the_answer(pid: int) -> None:
    """Until the child has used 0.2 s of CPU: past its set-up, in the answer's endless loop."""
    deadline = time.monotonic() + 5
    while time.monotonic() < deadline:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        if int(fields[11]) >= 0.2 * os.sysconf("SC_CLK_TCK"):
            return
        time.sleep(0.01)


def _can_unshare_network() -> bool:
    """Whether this process may make network namespaces (root, or CAP_SYS_ADMIN): try in a child."""
    pid = os.fork()
    if pid == 0:
        import ctypes

        os._exit(0 if ctypes.CDLL("libc.so.6", use_errno=True).unshare(0x40000000) == 0 else 1)
    return os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1]) == 0


@pytest.mark.skipif(not _can_unshare_network(), reason="no permission to make network namespaces here")
def test_the_children_share_the_servers_empty_network_namespace_and_make_none(server, tmp_path, monkeypatch):
    """The server makes one empty network namespace for its children; a child then makes none of its
    own (a direct fork's child still does)."""
    spawned = []
    spawn = forkserver.ForkServer.spawn
    monkeypatch.setattr(forkserver.ForkServer, "spawn", lambda self, *a: spawned.append(spawn(self, *a)) or spawned[-1])
    ours = _network_namespace("self")
    running = start_answer_file(_answer(tmp_path, "L = 42\nwhile True:\n    pass\n"), ["L"],
                                SandboxLimits(cpu_seconds=1, wall_seconds=8))
    try:  # the server has answered a request: it is past its set-up
        assert _network_namespace(server.pid) != ours
        _wait_until_running_the_answer(spawned[0])
        assert _network_namespace(spawned[0]) == _network_namespace(server.pid)
    finally:
        assert running.wait().status == "timeout"
    forkserver.stop()
    direct = []
    fork = os.fork
    monkeypatch.setattr(os, "fork", lambda: direct.append(fork()) or direct[-1])
    running = start_answer_file(_answer(tmp_path, "L = 42\nwhile True:\n    pass\n"), ["L"],
                                SandboxLimits(cpu_seconds=1, wall_seconds=8))
    try:
        _wait_until_running_the_answer(direct[0])
        assert _network_namespace(direct[0]) != ours
    finally:
        assert running.wait().status == "timeout"


def test_the_server_keeps_none_of_the_graders_descriptors(tmp_path):
    """A grader's pipe to its coordinator must close when the grader dies: a server holding a copy
    would hide the death."""
    r, w = os.pipe()
    try:
        forkserver.start()   # forked while this process holds w
        os.close(w)
        ready, _, _ = select.select([r], [], [], 5)
        assert ready and os.read(r, 1) == b"", "the fork server still holds the pipe's write end"
        out = run_answer_file(_answer(tmp_path), ["L"], FAST)
        assert out.status == "ok" and decode_value(out.values["L"]) == 42
    finally:
        forkserver.stop()
        os.close(r)


def test_children_nobody_asks_about_are_reaped(server, tmp_path):
    """A grading that runs out of time leaves its child uncollected: the server reaps it anyway."""
    for _ in range(3):
        start_answer_file(_answer(tmp_path), ["L"], FAST)  # started, never waited for
    time.sleep(1.0)
    out = run_answer_file(_answer(tmp_path), ["L"], FAST)  # the next spawn reaps the ended ones
    assert out.status == "ok"
    assert [state for _, state in _children(server.pid) if state == "Z"] == []


def test_the_server_dies_with_its_grader():
    code = ("import os, sys, time\n"
            "from lagrade.answers import forkserver\n"
            "print(forkserver.start().pid, flush=True)\n"
            "time.sleep(60)\n")
    grader = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    try:
        server_pid = int(grader.stdout.readline())
        assert os.path.exists(f"/proc/{server_pid}")
        grader.send_signal(signal.SIGKILL)
        grader.wait()
        deadline = time.monotonic() + 5
        while os.path.exists(f"/proc/{server_pid}") and time.monotonic() < deadline:
            time.sleep(0.02)
        assert not os.path.exists(f"/proc/{server_pid}"), "the fork server outlived its grader"
    finally:
        grader.kill()


def test_without_its_server_a_grader_forks_the_children_itself(server, tmp_path):
    os.kill(server.pid, signal.SIGKILL)
    os.waitpid(server.pid, 0)
    out = run_answer_file(_answer(tmp_path), ["L"], FAST)
    assert out.status == "ok" and decode_value(out.values["L"]) == 42
    assert forkserver.current() is None


def test_a_grader_forks_through_its_server_and_stops_it(tmp_path):
    from lagrade.bulk.worker import Grader
    from lagrade.library import problem_path

    grader = Grader({"12.14": problem_path("12.14").read_text()})
    try:
        server = forkserver.current()
        assert server is not None and os.path.exists(f"/proc/{server.pid}")
        data = (Path(__file__).resolve().parents[1] / "reference_solutions" / "12.14" / "answer.py").read_bytes()
        limits = {"cpu_seconds": 10, "wall_seconds": 20, "memory_mb": 512, "grading_seconds": 60}
        result = grader.grade({"student": "s", "problem": "12.14", "suffix": ".py", "data": data,
                               "accuracy": "default", "limits": limits, "credit": None, "parts": [], "file_hash": ""})
        assert result["outcome"] == "graded" and result["score"] == result["max_score"]
        assert forkserver.current() is server
    finally:
        grader.close()
    assert forkserver.current() is None and not os.path.exists(f"/proc/{server.pid}")


def test_a_fresh_process_gets_a_prepared_server(tmp_path):
    """start() prepares the sandbox's parent side before the server forks (libc loaded once there):
    a process that never ran an answer before still has children that do not look up libc."""
    marker = tmp_path / "looked-up"
    answer = _answer(tmp_path)
    code = ("import ctypes.util, os, sys\n"
            "from pathlib import Path\n"
            "from lagrade.answers import forkserver\n"
            "from lagrade.answers.sandbox import SandboxLimits, run_answer_file\n"
            "me = os.getpid()\n"  # this process may look it up, once; its server's children not
            "ctypes.util.find_library = lambda name: None if os.getpid() == me else Path(sys.argv[1]).write_text(name) and None\n"
            "forkserver.start()\n"
            "out = run_answer_file(Path(sys.argv[2]), ['L'], SandboxLimits(cpu_seconds=2, wall_seconds=8))\n"
            "forkserver.stop()\n"
            "print(out.status)\n")
    done = subprocess.run([sys.executable, "-c", code, str(marker), str(answer)], capture_output=True, text=True,
                          timeout=120)
    assert done.stdout.strip() == "ok", done.stderr[-2000:]
    assert not marker.exists()
