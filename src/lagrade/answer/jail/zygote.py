"""The clean zygote: the only process that forks the children running students' code.

A child forked from a grader holds in its own memory everything the grader held: the problem
files, the derived references, the graded reference solution. So the children are forked from a
process that never held any of it: the zygote is a fresh interpreter (``python -m
lagrade.answer.jail.zygote``, started with an empty environment and no descriptor but its socket)
that imports sympy and the sandbox's child code, warms sympy with neutral work only, enters the
jail's namespaces (:mod:`lagrade.answer.jail.kernel`) and then only forks. A child still starts in a
millisecond or two, not in the second an import of sympy takes.

The grader talks to it over a socket pair in JSON (never pickle: nothing the zygote says is
executed), passing each child's two pipe ends and its job with ``SCM_RIGHTS``; the zygote forks the
child and later reaps it for the grader, since only a parent can. The job (the answer's source,
path, names and token) is a descriptor the zygote passes on unread and the child reads after the
fork, so no answer's bytes are ever in the memory the next answers are forked from: an answer
that searches its own memory finds no other student's file (issue 43). What the zygote keeps
between answers is pids, uids, exit statuses and CPU times. In a PID namespace the zygote is its PID 1:
when it dies, the kernel kills every child. It dies with its grader (``PR_SET_PDEATHSIG``) and
when the socket closes.
"""

from __future__ import annotations

import atexit
import json
import os
import select
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import threading
from typing import Any

from lagrade.answer.jail import kernel

__all__ = ["Zygote", "current", "start", "stop"]

_HEADER = struct.Struct("!I")
_MAX_MESSAGE = 64 << 20
_MAX_KEPT = 1000  # statuses of children reaped before anyone asked


class ZygoteError(OSError):
    """The zygote could not be started or stopped answering."""


class Zygote:
    """The grader's handle on its zygote. ``layers``: the jail layers to build (all by default)."""

    def __init__(self, layers: tuple[str, ...] = kernel.LAYERS, warm: bool = False, directory: str | None = None) -> None:
        """``directory``: where the jail's (empty) mount point is made; a grader gives its own folder,
        which its coordinator removes even when it had to kill the grader."""
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        self.staging = tempfile.mkdtemp(prefix="lagrade-jail-", dir=directory) if "mount" in layers else ""
        env = {"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8", "OPENBLAS_NUM_THREADS": "1", "PYTHONNOUSERSITE": "1"}
        # where the secrets are (paths, not contents): the audit hook names them; and a checkout run
        # from its source tree (benchmarks, tests) finds itself
        for name in ("PYTHONPATH", "LAGRADE_CACHE", "LAGRADE_PROBLEMS", "XDG_CACHE_HOME", "HOME"):
            if os.environ.get(name):
                env[name] = os.environ[name]
        args = [sys.executable, "-m", "lagrade.answer.jail.zygote", str(theirs.fileno()), ",".join(layers),
                "warm" if warm else "cold", self.staging or "-"]
        debug = bool(os.environ.get("LAGRADE_DEBUG"))
        try:
            self.proc = subprocess.Popen(args, pass_fds=(theirs.fileno(),), env=env, cwd="/",
                                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                         stderr=None if debug else subprocess.DEVNULL)
        except OSError as exc:
            ours.close()
            raise ZygoteError(f"cannot start the sandbox's zygote: {exc}") from exc
        finally:
            theirs.close()
        self.sock = ours
        self.lock = threading.Lock()
        self._hello: dict[str, Any] | None = None

    def hello(self) -> dict[str, Any]:
        """``{"active": [layers], "inactive": {layer: why}}``, once the zygote is ready (waits)."""
        if self._hello is None:
            with self.lock:
                if self._hello is None:
                    try:
                        message, _ = _recv(self.sock)
                    except (OSError, EOFError, ValueError) as exc:
                        raise ZygoteError(f"the sandbox's zygote did not start ({exc or type(exc).__name__})") from exc
                    if not isinstance(message, dict) or "active" not in message:
                        raise ZygoteError(f"the sandbox's zygote did not start: {message}")
                    self._hello = message
        return self._hello

    @property
    def active(self) -> list[str]:
        return list(self.hello()["active"])

    def request(self, message: dict[str, Any], fds: tuple[int, ...] = ()) -> dict[str, Any]:
        self.hello()
        with self.lock:
            try:
                _send(self.sock, message, fds)
                reply, _ = _recv(self.sock)
            except (OSError, EOFError, ValueError) as exc:
                raise ZygoteError(f"the sandbox's zygote stopped answering ({exc})") from exc
        if "error" in reply:
            raise ZygoteError(reply["error"])
        return reply

    def spawn(self, fds: tuple[int, int, int]) -> int:
        """Fork a child that writes its report and output to ``fds[0]`` and ``fds[1]`` and reads its
        job (`lagrade.answer.jail.child.child_main`) from ``fds[2]`` once forked; its pid (in the
        zygote's PID namespace). The request itself says nothing about the answer."""
        return int(self.request({"op": "spawn"}, fds)["pid"])

    def reap(self, pid: int, kill: bool, deadline: float) -> tuple[int, float]:
        """Wait for the child (killing it first if asked); its wait status and CPU seconds."""
        reply = self.request({"op": "reap", "pid": pid, "kill": kill, "deadline": deadline})
        return int(reply["status"]), float(reply["cpu"])

    def lowered(self, pid: int) -> bool:
        """Whether the child runs at a lower priority (a higher nice) than the zygote's children
        started at: its coordinator lowered it (:func:`lagrade.uses.bulk.worker.watch`)."""
        return bool(self.request({"op": "lowered", "pid": pid})["lowered"])

    def alive(self) -> bool:
        return self.proc.poll() is None

    def close(self) -> None:
        try:
            self.sock.close()  # the zygote's read sees the end and it leaves
        finally:
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
            if self.staging:
                shutil.rmtree(self.staging, ignore_errors=True)


_current: Zygote | None = None
_current_pid = -1


def start(layers: tuple[str, ...] = kernel.LAYERS, warm: bool = False, directory: str | None = None) -> Zygote:
    """Start this process's zygote (replacing any); it is ready in the background while the caller
    loads problems and derives references (the two share nothing)."""
    global _current, _current_pid
    stop()
    _current, _current_pid = Zygote(layers, warm, directory), os.getpid()
    return _current


def current() -> Zygote:
    """This process's zygote, started now if there is none (or it died)."""
    if _current is None or _current_pid != os.getpid() or not _current.alive():
        return start()
    return _current


def stop() -> None:
    global _current
    zygote, _current = _current, None
    if zygote is not None and _current_pid == os.getpid():
        zygote.close()


atexit.register(stop)


# =========================================================================== messages

def _send(sock: socket.socket, message: Any, fds: tuple[int, ...] = ()) -> None:
    payload = json.dumps(message).encode("utf-8")
    header = _HEADER.pack(len(payload))
    if fds:
        socket.send_fds(sock, [header], list(fds))
        sock.sendall(payload)
    else:
        sock.sendall(header + payload)


def _recv(sock: socket.socket) -> tuple[Any, list[int]]:
    header, fds, _, _ = socket.recv_fds(sock, _HEADER.size, 4)
    while len(header) < _HEADER.size:
        if not header and not fds:
            raise EOFError
        more = sock.recv(_HEADER.size - len(header))
        if not more:
            raise EOFError
        header += more
    (size,) = _HEADER.unpack(header)
    if size > _MAX_MESSAGE:
        raise ValueError("message too large")
    payload = bytearray()
    while len(payload) < size:
        chunk = sock.recv(min(size - len(payload), 1 << 20))
        if not chunk:
            raise EOFError
        payload += chunk
    return json.loads(payload), fds


# =========================================================================== in the zygote

def _main(argv: list[str]) -> None:
    """``python -m lagrade.answer.jail.zygote FD LAYERS warm|cold STAGING``."""
    fd, wanted, warm, staging = int(argv[0]), set(filter(None, argv[1].split(","))), argv[2] == "warm", argv[3]
    # numbers this zygote's block of uids: this process lives (in the grader's PID namespace, where no
    # other live zygote has its pid) as long as any answer forked below it
    tree = os.getpid()
    kernel.die_with_parent()
    sock = socket.socket(fileno=fd)
    from lagrade.answer.jail import child as child_code

    child_code.prepare_zygote()
    if warm:
        _warm_sympy()
    inactive: dict[str, str] = {}
    if "landlock" in wanted and (why := kernel.landlock_available()):
        inactive["landlock"] = why
    if "seccomp" in wanted and (why := kernel.seccomp_available()):
        inactive["seccomp"] = why
    if not sys.platform.startswith("linux"):
        inactive.update({k: "not Linux: no OS jail" for k in wanted & {"uid", "no_new_privs", "landlock", "seccomp"}})
    allowed, hidden = kernel.jail_dirs()
    status_fd = _open_status()
    inactive.update(kernel.enter_namespaces(wanted & {"mount", "pid", "network", "uid"}))
    kernel.in_user_namespace()  # read (and kept) while /proc is still there: the jail has none
    if "uid" in wanted and "uid" not in inactive and os.geteuid() != 0 and not kernel.in_user_namespace():
        inactive["uid"] = "not root and no user namespace"
    if "pid" in wanted and "pid" not in inactive:
        pid = os.fork()  # the next process is PID 1 of the new namespace: it is the zygote from here on
        if pid:
            sock.close()
            _, status = os.waitpid(pid, 0)
            os._exit(os.waitstatus_to_exitcode(status) & 0xFF)
        kernel.die_with_parent(leave_if_orphaned=False)
    try:
        if "mount" in wanted and "mount" not in inactive:
            kernel.build_root(allowed, hidden, child_code.secret_dirs(), staging)
        elif "pid" in wanted and "pid" not in inactive:
            kernel.mount_proc()
    except OSError as exc:
        inactive["mount"] = f"could not build the jail's file tree ({exc})"
        if "pid" in wanted:
            inactive["pid"] = "needs the mount namespace for its own /proc"
    active = [k for k in kernel.LAYERS if k in wanted and k not in inactive]
    # Landlock's grants: inside the mount namespace the covers hide site-packages and the secrets, so
    # whole directories; without it, around them
    grants = allowed if "mount" in active else kernel.landlock_grants(allowed, [*hidden, *child_code.secret_dirs()])
    _send(sock, {"active": active, "inactive": inactive})
    _serve(sock, active, grants, status_fd, tree)


def _open_status() -> int | None:
    """``/proc/self/status``, kept open: the children's memory bound is counted above the size they
    were forked at, and inside the jail there is no /proc to read it from."""
    try:
        return os.open("/proc/self/status", os.O_RDONLY)
    except OSError:
        return None


def _vm_size(status_fd: int | None) -> int:
    if status_fd is None:
        return 0
    text = os.pread(status_fd, 8192, 0).decode("ascii", "replace")
    for line in text.splitlines():
        if line.startswith("VmSize:"):
            return int(line.split()[1]) * 1024
    return 0


def _serve(sock: socket.socket, active: list[str], readable: list[str], status_fd: int | None, tree: int) -> None:
    """Fork, reap and answer the grader until the socket closes. ``tree``: the pid that numbers this
    zygote's block of uids (:func:`lagrade.answer.jail.kernel.jail_uid`)."""
    from lagrade.answer.jail import child as child_code

    workdirs: dict[int, str] = {}
    uids: dict[int, int] = {}  # the uid of each child not yet reaped
    done: dict[int, tuple[int, float]] = {}  # reaped before the grader asked
    count = 0
    inside = "mount" in active
    as_root = os.geteuid() == 0 and not kernel.in_user_namespace()
    # A child is reaped as soon as it ends, not only when the next spawn comes: a child nobody asks
    # about (its grading ran out of time) that ends after the last request would otherwise stay a
    # zombie for as long as the zygote lives, and so would any orphan handed to it as PID 1. The
    # loop sleeps in poll() on the socket and on the byte SIGCHLD's wake-up writes (no handler work
    # in signal context: a wait4(-1) there could take the status a "reap" request is waiting for).
    wake_r, wake_w = os.pipe2(os.O_NONBLOCK | os.O_CLOEXEC)
    signal.set_wakeup_fd(wake_w, warn_on_full_buffer=False)
    signal.signal(signal.SIGCHLD, lambda *_: None)
    poller = select.poll()
    poller.register(sock, select.POLLIN)
    poller.register(wake_r, select.POLLIN)
    base_nice = os.getpriority(os.PRIO_PROCESS, 0)  # the children's, unless their coordinator lowers them
    while True:
        _reap_finished(done, workdirs, uids)
        ready = {fd for fd, _ in poller.poll()}
        if wake_r in ready:
            _drain(wake_r)
        if sock.fileno() not in ready:
            continue
        try:
            request, fds = _recv(sock)
        except (EOFError, OSError, ValueError):
            return
        try:
            if request.get("op") == "spawn":
                count += 1
                uid = None
                if "uid" in active and as_root:
                    count, uid = _free_uid(tree, count, set(uids.values()))
                workdir = f"{kernel.JAIL_WORK}/{count}" if inside else tempfile.mkdtemp(prefix="lagrade-answer-")
                if inside:
                    os.mkdir(workdir, 0o700)
                if uid is not None:
                    os.chown(workdir, uid, uid)
                vm = _vm_size(status_fd)
                if len(fds) != 3:
                    raise ValueError(f"a spawn needs 3 descriptors, got {len(fds)}")
                result_w, out_w, job_fd = fds
                pid = os.fork()
                if pid == 0:  # the child: never returns
                    sock.close()
                    signal.set_wakeup_fd(-1)
                    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
                    os.close(wake_r)
                    os.close(wake_w)
                    child_code.child_main(job_fd, workdir, result_w, out_w,
                                       layers=active, uid=uid, readable=readable, vm_size=vm)
                workdirs[pid] = workdir
                if uid is not None:
                    uids[pid] = uid
                reply: dict[str, Any] = {"pid": pid}
            elif request.get("op") == "reap":
                pid = int(request["pid"])
                status, cpu = done.pop(pid) if pid in done else child_code.reap_child(pid, bool(request["kill"]),
                                                                            float(request["deadline"]))
                shutil.rmtree(workdirs.pop(pid, ""), ignore_errors=True) if pid in workdirs else None
                uids.pop(pid, None)
                reply = {"status": status, "cpu": cpu}
            elif request.get("op") == "lowered":
                try:
                    nice = os.getpriority(os.PRIO_PROCESS, int(request["pid"]))
                except OSError:  # already ended
                    nice = base_nice
                reply = {"lowered": nice > base_nice}
            else:
                reply = {"error": f"unknown request {request.get('op')!r}"}
        except Exception as exc:  # noqa: BLE001  (told to the grader)
            reply = {"error": f"{type(exc).__name__}: {exc}"}
        finally:
            for fd in fds:
                os.close(fd)
        _send(sock, reply)


def _drain(fd: int) -> None:
    try:
        while os.read(fd, 4096):
            pass
    except BlockingIOError:
        pass


def _free_uid(tree: int, count: int, in_use: set[int]) -> tuple[int, int]:
    """``(count, uid)``: the first uid of this zygote's block from the ``count``-th on that no child
    alive has (a child not reaped 512 answers later keeps its uid to itself)."""
    for n in range(count, count + kernel.JAIL_UID_BLOCK):
        uid = kernel.jail_uid(tree, n)
        if uid not in in_use:
            return n, uid
    raise OSError(f"all {kernel.JAIL_UID_BLOCK} uids of this grader's block are in use by running answers")


def _reap_finished(done: dict[int, tuple[int, float]], workdirs: dict[int, str], uids: dict[int, int]) -> None:
    """Reap every child that has ended (a grading that ran out of time never asks), keeping its
    status for when the grader asks; called whenever SIGCHLD wakes the zygote."""
    while True:
        try:
            pid, status, usage = os.wait4(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        done[pid] = (status, usage.ru_utime + usage.ru_stime)
        shutil.rmtree(workdirs.pop(pid, ""), ignore_errors=True) if pid in workdirs else None
        uids.pop(pid, None)
        while len(done) > _MAX_KEPT:
            del done[next(iter(done))]


def _warm_sympy() -> None:
    """Run, once, the sympy entry points this chapter's answers use most: neutral work, no problem's.

    sympy imports much lazily on first use: ``solve`` alone brings in about 45 modules (units,
    combinatorics, tensor arrays ...). Every child is forked from here, so what the zygote has not
    imported, every answer that calls ``solve`` imports again (0.60 s against 0.49 s for an answer
    that solves det(K - w^2 M) = 0). The first derivative of a Matrix imports sympy's array
    expressions: 30-45 ms in every child that writes q.diff(t, 2) for a Matrix q."""
    import sympy as sp
    from sympy.calculus.euler import euler_equations

    try:
        w, a = sp.symbols("w a", positive=True)
        t = sp.Symbol("t")
        q = sp.Function("q")(t)
        sp.solve(sp.Matrix([[a - w, 1], [1, 2 - w]]).det(), w)
        euler_equations(q.diff(t) ** 2 / 2 - a * sp.cos(q), [q], t)
        sp.simplify(sp.sin(w) ** 2 + sp.cos(w) ** 2 + w / (w + w**2))
        sp.trigsimp(sp.sin(w) * sp.cos(w))
        sp.Matrix([[a, w], [w, a]]).inv()
        sp.Matrix([q, a * q]).diff(t, 2)
    except Exception:  # noqa: BLE001  (a warm-up that fails only costs speed)
        pass


if __name__ == "__main__":
    try:
        _main(sys.argv[1:])
    except BaseException as exc:  # noqa: BLE001  (the grader reads the socket's end and says so)
        if os.environ.get("LAGRADE_DEBUG"):
            raise
        try:
            _send(socket.socket(fileno=int(sys.argv[1])), {"error": f"{type(exc).__name__}: {exc}"})
        except Exception:  # noqa: BLE001
            pass
    os._exit(0)
