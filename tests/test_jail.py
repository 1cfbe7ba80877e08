"""Each layer of the OS jail holds on its own, with lagrade's Python-level tripwires switched off.

The screen, restricted builtins and audit hook are tripwires that give students clear messages;
the barrier is the kernel. So every test here runs the answer with ``sandbox.TRIPWIRES = False``
(plain builtins, ``import os`` allowed, no hook) in a zygote that builds ONE layer, and shows what
that layer alone stops: a direct ``os.system``, an open of the reference solutions, a write to the
cache, naming or signalling the grader, a connection to 127.0.0.1. The matrix says which attack is
which layer's job; a layer is not asked to stop what it is not for (uid alone does not hide a
world-readable file, seccomp alone does not stop reading one).
"""

from __future__ import annotations

import errno
import json
import os
import socket
import sys
import threading
from pathlib import Path

import pytest

from lagrade.answer.jail import kernel, sandbox, zygote
from lagrade.answer.jail.sandbox import SandboxLimits, run_answer_file
from lagrade.problem.library import reference_dir

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the OS jail is Linux's")

FAST = SandboxLimits(cpu_seconds=5, wall_seconds=20, memory_mb=512)

#: attack -> source; each prints one JSON line {attack: "done" | exception name}
ATTACKS = {
    "system": "os.system('/usr/bin/touch DROP/pwned-system')",
    "read_reference": "open(REFERENCE).read()",
    "write_cache": "open(CACHE + '/evil.pkl', 'wb').write(b'x')",
    "signal_grader": "os.kill(GRADER, 0)",
    "read_grader_proc": "open('/proc/%d/cmdline' % GRADER).read()",
    "network": "socket.create_connection(('127.0.0.1', PORT), timeout=2)",
}

#: layer -> the attacks it alone must stop
STOPS = {
    "uid": {"system", "write_cache", "signal_grader"},
    "mount": {"system", "read_reference", "write_cache", "read_grader_proc"},
    "pid": {"signal_grader", "read_grader_proc"},
    "network": {"network"},
    "landlock": {"system", "read_reference", "write_cache", "read_grader_proc"},
    "seccomp": {"system", "write_cache", "signal_grader", "network"},
}


def _program(drop: Path, cache: Path, port: int) -> str:
    lines = ["import json, os, socket", "seen = {}"]
    for name, action in ATTACKS.items():
        action = (action.replace("DROP", str(drop)).replace("REFERENCE", repr(str(reference_dir() / "12.22" / "answer.py")))
                  .replace("CACHE", repr(str(cache))).replace("GRADER", str(os.getpid())).replace("PORT", str(port)))
        lines += ["try:", f"    {action}", f"    seen[{name!r}] = 'done'",
                  "except BaseException as exc:", f"    seen[{name!r}] = type(exc).__name__"]
    lines += ["print(json.dumps(seen))", "L = 1"]
    return "\n".join(lines) + "\n"


@pytest.fixture
def listener():
    """A TCP listener on 127.0.0.1 that records every connection it accepts."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    server.settimeout(0.2)
    accepted: list = []
    stop = threading.Event()

    def serve():
        while not stop.is_set():
            try:
                conn, _ = server.accept()
            except OSError:
                continue
            accepted.append(conn)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    yield server.getsockname()[1], accepted
    stop.set()
    thread.join(2)
    server.close()


@pytest.fixture
def no_tripwires(monkeypatch):
    monkeypatch.setattr(sandbox, "TRIPWIRES", False)
    yield
    zygote.stop()


def _run(layers: tuple[str, ...], tmp_path: Path, port: int) -> tuple[dict, list[str]]:
    drop = tmp_path / "drop"  # private to the grader's uid, like its own directories
    drop.mkdir(mode=0o700)
    cache = tmp_path / "cache"
    cache.mkdir(mode=0o700)
    answer = tmp_path / "answer.py"
    answer.write_text(_program(drop, cache, port))
    made = zygote.start(layers)
    active = made.active
    out = run_answer_file(answer, ["L"], FAST)
    assert out.status == "ok", (out.status, out.problems, out.stdout)
    seen = json.loads(out.stdout.strip().splitlines()[-1])
    # these two are judged by their effect only (os.system reports a failure as a status)
    seen["system"] = "done" if (drop / "pwned-system").exists() else "stopped"
    seen["write_cache"] = "done" if (cache / "evil.pkl").exists() else "stopped"
    return seen, active


def test_without_any_layer_every_attack_gets_through(tmp_path, listener, no_tripwires):
    """The control: with the tripwires and every layer off, the attacks are real (each one works)."""
    if os.geteuid() != 0:
        pytest.skip("the control plants a root-only directory")
    port, accepted = listener
    seen, active = _run((), tmp_path, port)
    assert active == []
    assert seen == {name: "done" for name in ATTACKS}, seen
    assert accepted


@pytest.mark.parametrize("layer", sorted(STOPS))
def test_one_layer_alone_stops_its_attacks(layer, tmp_path, listener, no_tripwires):
    port, accepted = listener
    seen, active = _run((layer,), tmp_path, port)
    if layer not in active:
        pytest.skip(f"{layer} is not available on this machine")
    got_through = sorted(a for a in STOPS[layer] if seen[a] == "done")
    assert not got_through, f"{layer} alone let through {got_through}: {seen}"
    if "network" in STOPS[layer]:
        assert not accepted


def test_limits_alone_stop_a_memory_bomb_and_a_loop(tmp_path, no_tripwires):
    zygote.start(("limits",))
    bomb = tmp_path / "bomb.py"
    bomb.write_text("L = 1\nx = bytearray(4 * 10**9)\n")
    assert run_answer_file(bomb, ["L"], FAST).status == "memory"
    loop = tmp_path / "loop.py"
    loop.write_text("L = 1\nwhile True:\n    pass\n")
    assert run_answer_file(loop, ["L"], SandboxLimits(cpu_seconds=1, wall_seconds=20)).status == "timeout"


def test_no_new_privs_alone_is_set_in_the_child(tmp_path, no_tripwires):
    zygote.start(("no_new_privs",))
    probe = tmp_path / "nnp.py"
    probe.write_text("for line in open('/proc/self/status'):\n    if line.startswith('NoNewPrivs'):\n"
                     "        print(line.split()[1])\nL = 1\n")
    out = run_answer_file(probe, ["L"], FAST)
    assert out.stdout.strip() == "1", out


def test_every_layer_together_is_what_a_grader_gets(tmp_path, listener, no_tripwires):
    """As root on Linux (this project's machines) every layer is active, and all attacks fail."""
    port, accepted = listener
    seen, active = _run(kernel.LAYERS, tmp_path, port)
    if os.geteuid() == 0:
        assert active == list(kernel.LAYERS)
    assert kernel.missing_minimum(active) is None
    assert all(v != "done" for v in seen.values()), seen
    assert not accepted


def test_a_layer_that_cannot_be_applied_stops_the_answer_from_running(tmp_path, monkeypatch, no_tripwires):
    """Fail closed: a child whose seccomp filter cannot be loaded never runs the answer."""
    marker = tmp_path / "ran"
    answer = tmp_path / "answer.py"
    answer.write_text(f"open({str(marker)!r}, 'w').write('x')\nL = 1\n")
    monkeypatch.setenv("PYTHONPATH", _broken_seccomp_path(tmp_path))
    zygote.start(("seccomp",))
    out = run_answer_file(answer, ["L"], FAST)
    assert out.status == "crashed" and "jail could not be built" in out.stdout, out
    assert not marker.exists()


def _broken_seccomp_path(tmp_path: Path) -> str:
    """A PYTHONPATH whose ``pyseccomp`` imports but cannot load a filter."""
    fake = tmp_path / "fake"
    fake.mkdir()
    (fake / "pyseccomp.py").write_text(
        "ALLOW = 0\nEQ = MASKED_EQ = 0\ndef ERRNO(x):\n    return x\nclass Arg:\n    def __init__(self, *a):\n        pass\n"
        "class SyscallFilter:\n    def __init__(self, defaction):\n        pass\n    def add_rule(self, *a):\n        pass\n"
        "    def load(self):\n        raise OSError('no filter today')\n")
    return os.pathsep.join([str(fake), *[p for p in sys.path if p]])


def test_landlock_alone_grants_around_site_packages_and_secrets(tmp_path):
    """Without a mount namespace to cover them, Landlock grants a directory that holds site-packages
    or a secret folder entry by entry, around it; an allowed package inside site-packages whole."""
    stdlib = tmp_path / "lib"
    for d in ("json", "site-packages/sympy/core", "site-packages/lagrade/_data/problems", "secret/inner"):
        (stdlib / d).mkdir(parents=True)
    (stdlib / "os.py").write_text("")
    grants = kernel.landlock_grants([str(stdlib), str(stdlib / "site-packages" / "sympy")],
                                  [str(stdlib / "site-packages"), str(stdlib / "secret")])
    assert grants == sorted([str(stdlib / "json"), str(stdlib / "os.py"), str(stdlib / "site-packages" / "sympy")])


#: what an answer tries on its own output pipe: signal-driven I/O (a signal of its choosing sent by the
#: kernel to a process of its choosing when the pipe changes), and two calls Python itself needs
FCNTL_PROBE = """import fcntl, json, os, signal, struct
seen = {}
def attempt(name, call):
    try:
        call()
        seen[name] = "done"
    except OSError as exc:
        seen[name] = os.strerror(exc.errno)
attempt("F_SETOWN", lambda: fcntl.fcntl(1, fcntl.F_SETOWN, os.getpid()))
attempt("F_SETOWN_EX", lambda: fcntl.fcntl(1, 15, struct.pack("ii", 1, os.getpid())))
attempt("F_SETSIG", lambda: fcntl.fcntl(1, 10, signal.SIGUSR1))
attempt("O_ASYNC", lambda: fcntl.fcntl(1, fcntl.F_SETFL, fcntl.fcntl(1, fcntl.F_GETFL) | os.O_ASYNC))
attempt("F_GETFL", lambda: fcntl.fcntl(1, fcntl.F_GETFL))
attempt("O_NONBLOCK", lambda: fcntl.fcntl(1, fcntl.F_SETFL, fcntl.fcntl(1, fcntl.F_GETFL) | os.O_NONBLOCK))
attempt("dup", lambda: os.close(os.dup(1)))
print(json.dumps(seen))
L = 1
"""


@pytest.mark.parametrize("layers", [("seccomp",), kernel.LAYERS], ids=["seccomp", "every-layer"])
def test_seccomp_refuses_signal_driven_io_on_the_answers_pipes(layers, tmp_path, no_tripwires):
    """Issue 43, item 6: F_SETOWN, F_SETOWN_EX, F_SETSIG and O_ASYNC fail with EPERM (the filter's
    answer to every call it refuses); reading the flags, O_NONBLOCK and dup still work."""
    made = zygote.start(layers)
    if "seccomp" not in made.active:
        pytest.skip("seccomp is not available on this machine")
    answer = tmp_path / "answer.py"
    answer.write_text(FCNTL_PROBE)
    out = run_answer_file(answer, ["L"], FAST)
    assert out.status == "ok", (out.status, out.problems, out.stdout)
    seen = json.loads(out.stdout.strip().splitlines()[-1])
    signalling = ("F_SETOWN", "F_SETOWN_EX", "F_SETSIG", "O_ASYNC")
    assert {k: seen[k] for k in signalling} == dict.fromkeys(signalling, os.strerror(errno.EPERM)), seen
    kept = ("F_GETFL", "O_NONBLOCK", "dup")
    assert {k: seen[k] for k in kept} == dict.fromkeys(kept, "done"), seen
