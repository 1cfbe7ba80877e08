"""What the zygote prepares once for all its children (`lagrade.answer.jail.child.prepare_zygote`), and
that what a child then does with it is the same jail: the seccomp allowlist compiled to BPF once and
only loaded by each child refuses exactly what libseccomp's own load of the same filter refuses."""

from __future__ import annotations

import errno
import json
import os
import socket
import sys

import pytest

import lagrade.answer
from lagrade.answer.jail import child, kernel

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the OS jail is Linux's")


def _probe(tmp: str) -> dict[str, str]:
    """What a process can still do: each call's outcome, "done" or the error's name."""
    seen: dict[str, str] = {}

    def attempt(name, call):
        try:
            call()
            seen[name] = "done"
        except OSError as exc:
            seen[name] = errno.errorcode.get(exc.errno or 0, str(exc))

    import fcntl

    attempt("socket", lambda: socket.socket(socket.AF_INET, socket.SOCK_STREAM).close())
    attempt("open_write", lambda: os.close(os.open(os.path.join(tmp, "w"), os.O_WRONLY | os.O_CREAT, 0o600)))
    attempt("open_read", lambda: os.close(os.open(os.path.join(tmp, "r"), os.O_RDONLY)))
    attempt("exec", lambda: os.execv("/bin/true", ["/bin/true"]))
    attempt("kill", lambda: os.kill(os.getppid(), 0))
    attempt("mkdir", lambda: os.mkdir(os.path.join(tmp, "d")))
    attempt("F_SETOWN", lambda: fcntl.fcntl(1, fcntl.F_SETOWN, os.getpid()))
    attempt("F_GETFL", lambda: fcntl.fcntl(1, fcntl.F_GETFL))
    attempt("setrlimit", lambda: os.setpriority(os.PRIO_PROCESS, 0, 19))
    attempt("getpid", os.getpid)
    return seen


def _in_child(tmp: str, load) -> dict[str, str]:
    """``_probe`` in a forked child after ``load()`` (which applies a filter) returns None."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover  (the child)
        code = 1
        try:
            os.close(read)
            why = load()
            out = {"error": why} if why else _probe(tmp)
            os.write(write, json.dumps(out).encode())
            code = 0
        finally:
            os._exit(code)
    os.close(write)
    data = b""
    while chunk := os.read(read, 65536):
        data += chunk
    os.close(read)
    os.waitpid(pid, 0)
    return json.loads(data)


def _libseccomp_load() -> str | None:
    kernel._libc().prctl(38, 1, 0, 0, 0)
    kernel._seccomp_filter().load()
    return None


def test_the_precompiled_filter_refuses_what_libseccomps_own_load_refuses(tmp_path):
    """A child loads the zygote's BPF program (`kernel._seccomp`); the result is the jail libseccomp
    would have built: the same calls refused (EPERM), the same allowed."""
    program = kernel.seccomp_program()
    if isinstance(program, str):
        pytest.skip(program)
    assert program and len(program) % 8 == 0
    (tmp_path / "r").write_text("x")
    precompiled = _in_child(str(tmp_path), kernel._seccomp)
    assert "error" not in precompiled, precompiled
    assert precompiled == _in_child(str(tmp_path), _libseccomp_load)
    refused = ("socket", "open_write", "exec", "kill", "mkdir", "F_SETOWN", "setrlimit")
    assert {k: precompiled[k] for k in refused} == dict.fromkeys(refused, "EPERM"), precompiled
    assert {precompiled[k] for k in ("open_read", "F_GETFL", "getpid")} == {"done"}, precompiled
    assert not (tmp_path / "w").exists() and not (tmp_path / "d").exists()


def test_a_filter_that_cannot_be_compiled_fails_closed(monkeypatch):
    """No program (libseccomp refused to compile or export it): the child's seccomp layer reports
    why, so the child does not run the answer (`JAIL_FAILED`), never an answer without the filter."""
    monkeypatch.setattr(kernel, "seccomp_program", lambda: "seccomp refused: no program today")
    assert kernel._seccomp() == "seccomp refused: no program today"  # confine() reports it: JAIL_FAILED


def test_the_zygote_prepares_the_filter_and_the_vocabulary_before_it_forks(monkeypatch):
    """What every child would otherwise redo: the BPF program, the answers' vocabulary (sympy's names
    in lagrade.answer and the module an answer is handed) and the child's ``sys.path``."""
    for cached in (kernel.seccomp_program, child._vocabulary, child._jail_sys_path):
        cached.cache_clear()
    child.prepare_zygote()
    for cached in (kernel.seccomp_program, child._vocabulary, child._jail_sys_path):
        assert cached.cache_info().currsize == 1, cached
    assert "__all__" in vars(lagrade.answer)
    handed = child._vocabulary()
    assert handed is not lagrade.answer and not hasattr(handed, "jail") and handed.t == lagrade.answer.t
