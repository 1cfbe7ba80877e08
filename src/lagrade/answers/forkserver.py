"""Sandbox children forked from a process that holds the warmed state and does nothing else.

A grader that forks every sandbox child itself pays for it twice. ``fork`` write-protects every
page of the grader (about 100 MB), which took about 3 ms per answer once grading had written to
them, and every page the grader then writes faults again: about 2,200 page faults per file of a
class. A process forked once from the warmed grader, which only forks, keeps its pages as its
first fork left them: its forks take about 1 ms, and the grader never faults for them.

The fork server is trusted code, a copy of the grader, and talks to it over a private socket pair:
the grader sends each child's arguments and the two pipe ends it writes to (``SCM_RIGHTS``), the
server forks the child (`lagrade.answers.sandbox._child_main`, the same locked-down child as a
direct fork) and later reaps it for the grader, since only a parent can. It dies with the grader
(``PR_SET_PDEATHSIG``), and the children die with it. Children the grader never asks about (a
grading that ran out of time) are reaped anyway, so none is left a zombie.
"""

from __future__ import annotations

import gc
import os
import pickle
import signal
import socket
import struct
from typing import Any

__all__ = ["ForkServer", "current", "die_with_parent", "start", "stop"]

_HEADER = struct.Struct("!I")
_MAX_KEPT = 1000  # statuses of children reaped before anyone asked, kept for a later question


class ForkServer:
    """The grader's handle on its fork server."""

    def __init__(self) -> None:
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        pid = os.fork()
        if pid == 0:  # the server: never returns
            code = 0
            try:
                ours.close()
                _serve(theirs)
            except BaseException:  # noqa: BLE001  (the grader sees the socket close and forks itself)
                code = 1
            finally:
                os._exit(code)
        theirs.close()
        self.pid, self.sock = pid, ours

    def spawn(self, child_args: tuple, fds: tuple[int, int]) -> int:
        """Fork a sandbox child running ``_child_main(*child_args[:6], *fds, child_args[6])``; its pid."""
        _send(self.sock, ("spawn", child_args), fds)
        reply = _recv(self.sock)
        if isinstance(reply, str):
            raise OSError(reply)
        return reply

    def reap(self, pid: int, kill: bool, deadline: float) -> tuple[int, float]:
        """`lagrade.answers.sandbox._reap`, done by the child's parent: (wait status, CPU seconds)."""
        _send(self.sock, ("reap", (pid, kill, deadline)))
        reply = _recv(self.sock)
        if isinstance(reply, str):
            raise OSError(reply)
        return reply

    def close(self) -> None:
        try:
            self.sock.close()  # the server's read sees the end and it leaves
        finally:
            try:
                os.waitpid(self.pid, 0)
            except ChildProcessError:
                pass


_current: ForkServer | None = None


def start() -> ForkServer:
    """Start this process's fork server: every sandbox child is forked by it from now on. Call it
    once the process is warm: the children see the state it had then (with what the sandbox has a
    parent import before forking, `lagrade.answers.sandbox._prepare_parent`)."""
    from lagrade.answers import sandbox

    global _current
    stop()
    sandbox._prepare_parent()
    _current = ForkServer()
    return _current


def current() -> ForkServer | None:
    return _current


def stop() -> None:
    """Stop the fork server (if any); sandbox children are forked directly again."""
    global _current
    server, _current = _current, None
    if server is not None:
        server.close()


# =========================================================================== in the server

def _serve(sock: socket.socket) -> None:
    from lagrade.answers import sandbox

    die_with_parent()
    # Objects of the grader that are garbage already would close their descriptors when collected
    # here, by number, and those numbers are reused below for the pipes of the children: frozen,
    # they are never collected (and the collector never writes to, and so copies, their pages).
    gc.freeze()
    keep = sock.fileno()
    os.closerange(3, keep)  # the grader's pipes to its coordinator among them: its death must show
    os.closerange(keep + 1, sandbox._fd_limit())
    sandbox._unshare_network()  # one empty network namespace for all the children (each made its own)
    done: dict[int, tuple[int, float]] = {}  # reaped before the grader asked
    while True:
        try:
            request, fds = _recv_with_fds(sock)
        except EOFError:
            return
        op, args = request
        try:
            if op == "spawn":
                _reap_finished(done)
                result_w, out_w = fds
                pid = os.fork()
                if pid == 0:  # the sandbox child: never returns
                    sock.close()
                    source, path, name, wanted, limits, workdir, token = args
                    sandbox._child_main(source, path, name, wanted, limits, workdir, result_w, out_w, token)
                reply: Any = pid
            elif op == "reap":
                pid, kill, deadline = args
                reply = done.pop(pid) if pid in done else sandbox._reap(pid, kill, deadline)
            else:
                reply = f"unknown request {op!r}"
        except Exception as exc:  # noqa: BLE001  (told to the grader, which then forks directly)
            reply = f"{type(exc).__name__}: {exc}"
        finally:
            for fd in fds:
                os.close(fd)
        _send(sock, reply)


def _reap_finished(done: dict[int, tuple[int, float]]) -> None:
    """Reap every child that has ended, keeping its status for when the grader asks."""
    while True:
        try:
            pid, status, usage = os.wait4(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        done[pid] = (status, usage.ru_utime + usage.ru_stime)
        while len(done) > _MAX_KEPT:
            del done[next(iter(done))]


def die_with_parent() -> None:
    """Be killed when the parent process ends (``PR_SET_PDEATHSIG``), or leave now if it already has:
    a grader with its coordinator, a fork server with its grader."""
    try:
        import ctypes

        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGKILL, 0, 0, 0)  # PR_SET_PDEATHSIG
        if os.getppid() == 1:
            os._exit(0)
    except Exception:  # noqa: BLE001  (a server still leaves when its socket closes)
        pass


# =========================================================================== messages

def _send(sock: socket.socket, message: Any, fds: tuple[int, ...] = ()) -> None:
    payload = pickle.dumps(message, protocol=pickle.HIGHEST_PROTOCOL)  # both ends are lagrade's own
    header = _HEADER.pack(len(payload))
    if fds:
        socket.send_fds(sock, [header], list(fds))
        sock.sendall(payload)
    else:
        sock.sendall(header + payload)


def _recv(sock: socket.socket) -> Any:
    message, fds = _recv_with_fds(sock)
    for fd in fds:
        os.close(fd)
    return message


def _recv_with_fds(sock: socket.socket) -> tuple[Any, list[int]]:
    header, fds, _, _ = socket.recv_fds(sock, _HEADER.size, 4)
    while len(header) < _HEADER.size:
        if not header and not fds:
            raise EOFError
        more = sock.recv(_HEADER.size - len(header))
        if not more:
            raise EOFError
        header += more
    (size,) = _HEADER.unpack(header)
    payload = bytearray()
    while len(payload) < size:
        chunk = sock.recv(min(size - len(payload), 1 << 20))
        if not chunk:
            raise EOFError
        payload += chunk
    return pickle.loads(payload), fds
