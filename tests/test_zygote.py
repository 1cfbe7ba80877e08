"""The clean zygote (lagrade.answer.jail.zygote): the process students' code is forked from never held
the key, keeps none of the grader's descriptors, reaps what nobody asks about, dies with its
grader, and leaves nothing behind."""

from __future__ import annotations

import os
import re
import secrets
import subprocess
import sys
import time
from pathlib import Path

import pytest

from lagrade.answer.jail import kernel, sandbox, zygote
from lagrade.answer.jail.rebuild import decode_value
from lagrade.answer.jail.sandbox import SandboxLimits, run_answer_file, start_answer_file

sys.path.insert(0, str(Path(__file__).resolve().parent))
import memory_scan  # noqa: E402

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")

FAST = SandboxLimits(cpu_seconds=2, wall_seconds=8, memory_mb=256)


@pytest.fixture(autouse=True)
def fresh():
    zygote.stop()
    yield
    zygote.stop()


def _answer(tmp_path: Path, text: str = "L = 41 + 1\n") -> Path:
    path = tmp_path / "answer.py"
    path.write_text(text)
    return path


def _descendants(pid: int) -> list[int]:
    found, todo = [], [pid]
    while todo:
        p = todo.pop()
        try:
            kids = [int(k) for k in Path(f"/proc/{p}/task/{p}/children").read_text().split()]
        except OSError:
            continue
        found += kids
        todo += kids
    return found


def _memory_holds(pid: int, needle: bytes) -> bool:
    """Whether ``needle`` is anywhere in the readable memory of process ``pid`` (needs root or ptrace)."""
    with open(f"/proc/{pid}/maps") as maps, open(f"/proc/{pid}/mem", "rb", 0) as mem:
        for line in maps:
            m = re.match(r"([0-9a-f]+)-([0-9a-f]+) (\S+)", line)
            start, end, perms = int(m[1], 16), int(m[2], 16), m[3]
            if "r" not in perms or "[vvar]" in line or "[vsyscall]" in line:
                continue
            try:
                mem.seek(start)
                if needle in mem.read(end - start):
                    return True
            except (OSError, ValueError, OverflowError):
                continue
    return False


@pytest.mark.skipif(os.geteuid() != 0, reason="reading another process's memory needs root")
def test_the_process_that_runs_answers_never_held_the_key(tmp_path):
    """A grader that has loaded a problem, derived its references and graded the reference solution
    holds them in memory; the zygote (and so every child) holds none of it. The control: the same
    search finds the key in the grader itself (a child forked from it, as before, would hold it)."""
    from lagrade.verdicts.grade import check, references
    from lagrade.problem.library import load_problem, reference_dir

    key = f"lagrade-reference-key-{secrets.token_hex(8)}".encode()
    kept = [bytearray(key)]  # stands for every secret the grader holds, in a form the search can find
    problem = load_problem("12.22")
    references(problem)
    check(problem, reference_dir() / "12.22" / "answer.py")
    made = zygote.start()
    made.hello()
    running = start_answer_file(_answer(tmp_path, "L = 1\nwhile True:\n    pass\n"), ["L"], FAST)
    time.sleep(0.5)
    processes = [made.proc.pid, *_descendants(made.proc.pid)]
    assert len(processes) >= 3, processes  # the zygote, its PID 1, the answer's child
    assert _memory_holds(os.getpid(), key), "the control failed: the search cannot find the key"
    secret_text = (reference_dir() / "12.22" / "answer.py").read_text().splitlines()[-1].encode()
    for pid in processes:
        assert not _memory_holds(pid, key), f"process {pid} holds the grader's key"
        assert not _memory_holds(pid, secret_text), f"process {pid} holds the reference solution"
    running.wait()
    del kept


@pytest.mark.parametrize("layers", [kernel.LAYERS, ("limits",)], ids=["every-layer", "limits-only"])
def test_an_answer_finds_no_earlier_answer_in_its_memory(tmp_path, monkeypatch, layers):
    """Issue 43, item 1: with the tripwires off (the OS jail alone), an answer that searches its own
    memory for the text of the answer graded before it through the same zygote finds nothing, round
    after round: the process it is forked from never held another answer's bytes. The control copy
    it plants shows that the search reaches the heap, where a received source would lie."""
    monkeypatch.setattr(sandbox, "TRIPWIRES", False)
    zygote.start(layers).hello()
    limits = SandboxLimits(cpu_seconds=20, wall_seconds=60, memory_mb=512)
    for round_ in range(3):
        text = memory_scan.marker()
        earlier = run_answer_file(_answer(tmp_path, memory_scan.victim(text)), ["L"], limits)
        assert earlier.status == "ok", earlier
        out = run_answer_file(_answer(tmp_path, memory_scan.scanner(text)), ["found", "control"], limits)
        assert out.status == "error" and "memory scan" in out.problems[0].message, out
        found, control = decode_value(out.values["found"]), decode_value(out.values["control"])
        assert control >= 1, f"the control failed: the search does not reach the heap ({out.problems})"
        assert found == 0, f"round {round_}: {found} copies of the earlier answer's text in this answer's memory"


@pytest.mark.skipif(os.geteuid() != 0, reason="answers get uids of their own when lagrade runs as root")
def test_two_graders_at_once_never_run_answers_as_the_same_uid(tmp_path, monkeypatch):
    """Issue 43, item 6: two graders' zygotes, each running two answers at once, give the four
    answers four uids (each zygote draws from a block of its own), none of them the grader's."""
    monkeypatch.setattr(sandbox, "TRIPWIRES", False)
    graders = [zygote.Zygote(), zygote.Zygote()]
    try:
        if any("uid" not in g.active for g in graders):
            pytest.skip("the uid layer is not available here")
        source = "import os, time\nL = os.getuid()\ntime.sleep(1)\n"  # all four alive at once
        running = []
        for i, grader in enumerate(graders * 2):
            (tmp_path / str(i)).mkdir()
            path = _answer(tmp_path / str(i), source)
            finish, _abandon = sandbox._start_in_jail(grader, source, path, ["L"], FAST)
            running.append(finish)
        uids = [decode_value(finish().values["L"]) for finish in running]
        assert len(set(uids)) == 4 and os.getuid() not in uids, uids
    finally:
        for grader in graders:
            grader.close()


def test_the_uid_blocks_of_live_zygotes_are_disjoint_and_valid():
    blocks = {pid: {kernel.jail_uid(pid, n) for n in range(2 * kernel.JAIL_UID_BLOCK)} for pid in (1, 2, 4194303)}
    assert all(len(uids) == kernel.JAIL_UID_BLOCK for uids in blocks.values())
    assert not blocks[1] & blocks[2] and not blocks[2] & blocks[4194303]
    assert max(blocks[4194303]) < 2**32 - 1 and min(blocks[1]) >= kernel.JAIL_UID_BASE
    in_use = {kernel.jail_uid(7, n) for n in range(3, 6)}
    assert zygote._free_uid(7, 3, in_use) == (6, kernel.jail_uid(7, 6))


def test_the_zygote_keeps_none_of_the_graders_descriptors(tmp_path):
    r, w = os.pipe()
    try:
        made = zygote.start()
        made.hello()
        for pid in [made.proc.pid, *_descendants(made.proc.pid)]:
            fds = os.listdir(f"/proc/{pid}/fd")
            targets = {os.readlink(f"/proc/{pid}/fd/{fd}") for fd in fds if os.path.exists(f"/proc/{pid}/fd/{fd}")}
            ours = os.readlink(f"/proc/self/fd/{w}")
            assert ours not in targets
            assert len(fds) <= 7, (pid, targets)  # stdio, its socket, /proc/self/status, SIGCHLD wake-up pipe
    finally:
        os.close(r)
        os.close(w)


def _children(pid: int) -> list[int]:
    return [int(k) for k in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]


def _state(pid: int) -> str | None:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return None


def test_children_nobody_asks_about_are_reaped(tmp_path):
    """Children that end after the zygote's last request (nobody asks about them, no spawn follows)
    are reaped all the same: the zygote reaps on SIGCHLD, not only when it is next asked to fork.
    The three busy children are still running when the last answer is spawned and reaped, so a
    zygote that reaps only on a spawn leaves them as zombies for good, whatever the load."""
    made = zygote.start()
    busy = "s = 0\nfor i in range(5_000_000):\n    s += i\nL = 42\n"
    for _ in range(3):
        start_answer_file(_answer(tmp_path, busy), ["L"], FAST)  # never waited for
    out = run_answer_file(_answer(tmp_path), ["L"], FAST)
    assert out.status == "ok" and decode_value(out.values["L"]) == 42
    forker = made.proc.pid
    if "pid" in made.active:  # the zygote proper is PID 1 of its namespace, the outer process's child
        (forker,) = _children(made.proc.pid)
    children = _children(forker)
    assert children, "the busy children ended before the last spawn: the test proves nothing"
    deadline = time.monotonic() + 30  # they end within their 2 s of CPU each; a zombie stays forever
    while time.monotonic() < deadline and any(_state(p) is not None for p in children):
        time.sleep(0.05)
    left = {p: _state(p) for p in children if _state(p) is not None}
    assert not left, f"children never reaped: {left}"


def test_the_zygote_dies_with_its_grader_and_leaves_nothing():
    script = ("import sys\nfrom lagrade.answer.jail import zygote\nz = zygote.start()\nz.hello()\n"
              "print(z.proc.pid, z.staging, flush=True)\nsys.stdin.read()\n")
    grader = subprocess.Popen([sys.executable, "-c", script], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    pid, staging = (grader.stdout.readline().split() + [""])[:2]
    pid = int(pid)
    family = [pid, *_descendants(pid)]
    grader.kill()
    grader.wait()
    deadline = time.monotonic() + 10
    while any(os.path.exists(f"/proc/{p}") and "Z" not in Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[1][:3]
              for p in family) and time.monotonic() < deadline:
        time.sleep(0.05)
    alive = [p for p in family if os.path.exists(f"/proc/{p}")
             and "Z" not in Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[1][:3]]
    assert not alive
    if staging:  # the zygote removed its mount point as soon as its root was built
        assert not os.path.exists(staging)


def test_a_stopped_zygote_leaves_no_directory(tmp_path):
    made = zygote.start()
    run_answer_file(_answer(tmp_path), ["L"], FAST)
    staging = made.staging
    zygote.stop()
    assert not made.alive()
    assert not staging or not os.path.exists(staging)


def test_a_dead_zygote_is_replaced(tmp_path):
    made = zygote.start()
    made.hello()
    made.proc.kill()
    made.proc.wait()
    out = run_answer_file(_answer(tmp_path), ["L"], FAST)
    assert out.status == "ok" and zygote.current() is not made
