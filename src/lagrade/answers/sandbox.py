"""Run a student's ``answer.py`` in a forked, locked-down child and get its values back as text.

Answer files are untrusted code.  The defence is layered, so that no single mistake opens the
grader: static screening (:mod:`lagrade.answers.screen`), a restricted ``__builtins__`` with an
importer that knows only sympy/math/lagrade.answer, a CPython audit hook that refuses file
writes, reads outside Python's install, sockets, processes, introspection and code generation,
resource limits (CPU, address space, file size, descriptors, processes), a private network
namespace and dropped privileges where the OS allows, and finally a JSON-only channel back to the
parent, which never unpickles or evaluates anything the child sends.

The child is *forked* from the grader (in a bulk run, from the grader's fork server: see
:mod:`lagrade.answers.forkserver`) so the already-imported sympy is reused (importing sympy takes
about a second; forking takes milliseconds).
"""

from __future__ import annotations

import ast
import builtins
import functools
import json
import math
import os
import re
import resource
import secrets
import selectors
import shutil
import signal
import sys
import sysconfig
import tempfile
import time
import types
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Literal

import sympy as sp
from pydantic import BaseModel, ConfigDict, ValidationError

import lagrade.answer
from lagrade.answers.rebuild import EncodedValue, expr_nodes, srepr_text
from lagrade.answers.screen import (
    ALLOWED_MODULES_TEXT,
    FORBIDDEN_ATTRIBUTES,
    MAX_SOURCE_BYTES,
    AnswerProblem,
    module_allowed,
    screen_source,
)

__all__ = ["AnswerProblem", "EncodedValue", "SandboxLimits", "SandboxOutcome", "run_answer_file"]

STDOUT_KEEP = 2000
_RESULT_FD = 3
_NOBODY = 65534


class SandboxLimits(BaseModel):
    """Resource limits for one answer file (memory is address space *above* the grader's own)."""

    model_config = ConfigDict(frozen=True)

    cpu_seconds: float = 10
    wall_seconds: float = 20
    memory_mb: int = 1024
    max_output_bytes: int = 2_000_000


class SandboxOutcome(BaseModel):
    """What running an answer file produced: encoded values, problems for the student, status."""

    values: dict[str, EncodedValue] = {}
    problems: list[AnswerProblem] = []
    stdout: str = ""
    status: Literal["ok", "error", "timeout", "memory", "crashed", "rejected"]


class _ChildReport(BaseModel):
    """The child's JSON document; validated because the child ran untrusted code."""

    model_config = ConfigDict(extra="forbid")

    token: str
    status: Literal["ok", "error", "timeout", "memory"]
    values: dict[str, EncodedValue]
    problems: list[AnswerProblem]


# =========================================================================== parent side

def run_answer_file(path: Path, wanted: Sequence[str], limits: SandboxLimits = SandboxLimits()) -> SandboxOutcome:
    """Screen and run ``path``; return the values bound to the names in ``wanted``, as text."""
    return start_answer_file(path, wanted, limits).wait()


class RunningAnswer:
    """An answer file running in its sandbox child (or already refused): ``wait()`` gives the outcome.

    Starting it and waiting are separate so that a one-off check can import the grading code while
    the child runs: two cores, two things at once."""

    def __init__(self, outcome: SandboxOutcome | None = None, finish=None, workdir: str | None = None):
        self._outcome, self._finish, self._workdir = outcome, finish, workdir

    def wait(self) -> SandboxOutcome:
        if self._outcome is None:
            try:
                self._outcome = self._finish()
            finally:
                shutil.rmtree(self._workdir, ignore_errors=True)
        return self._outcome


def start_answer_file(path: Path, wanted: Sequence[str], limits: SandboxLimits = SandboxLimits()) -> RunningAnswer:
    """Screen ``path`` and start it in a sandbox child; see `run_answer_file`."""
    path = Path(path)
    name = path.name

    def fail(status: str, message: str, line: int | None = None) -> RunningAnswer:
        return RunningAnswer(SandboxOutcome(status=status, problems=[AnswerProblem(file=name, line=line, message=message)]))

    try:
        if path.stat().st_size > MAX_SOURCE_BYTES:
            return fail("rejected", f"the file is larger than {MAX_SOURCE_BYTES // 1000} kB")
        source = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        return fail("error", "the file is not valid UTF-8 text")
    except OSError as exc:
        return fail("error", f"cannot read the file: {exc.strerror or exc}")
    problems = screen_source(source, name)
    if problems:
        syntax = any(p.message.startswith(("syntax error", "cannot parse")) for p in problems)
        return RunningAnswer(SandboxOutcome(status="error" if syntax else "rejected", problems=problems))

    _prepare_parent()
    workdir = tempfile.mkdtemp(prefix="lagrade-answer-")
    try:
        return RunningAnswer(finish=_start_forked(source, path, list(wanted), limits, workdir), workdir=workdir)
    except BaseException:
        shutil.rmtree(workdir, ignore_errors=True)
        raise


_prepared = False


def _prepare_parent() -> None:
    """Import, before forking, what the child may need but must not import once locked."""
    global _prepared
    if _prepared:
        return
    import dataclasses  # noqa: F401  (sympy imports some modules lazily that use it)
    import sympy.parsing.sympy_parser  # noqa: F401  (patched in the child so strings are not parsed)
    import traceback  # noqa: F401

    # sympy imports these the first time an Add or Mul of a certain shape is built: about 50 ms that
    # a child would pay on every answer (its imports die with it), and the parent again on rebuild
    import sympy.assumptions.wrapper  # noqa: F401
    import sympy.sets.setexpr  # noqa: F401
    import sympy.tensor.tensor  # noqa: F401

    try:
        _libc()
    except OSError:  # no libc to load: the child skips what needs it, as it did before
        pass
    _readable_dirs()

    _prepared = True


def _start_forked(source: str, path: Path, wanted: list[str], limits: SandboxLimits, workdir: str):
    """Fork the child (through this process's fork server, if it has one: `lagrade.answers.forkserver`);
    return the function that collects its outcome."""
    from lagrade.answers import forkserver

    name = path.name
    token = secrets.token_hex(16)  # a report without it was not written by our child code
    result_r, result_w = os.pipe()
    out_r, out_w = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    server, reap = forkserver.current(), _reap
    pid = None
    if server is not None:
        try:
            pid = server.spawn((source, str(path), name, wanted, limits, workdir, token), (result_w, out_w))
            reap = server.reap
        except (OSError, EOFError):
            forkserver.stop()  # it is gone: fork here from now on
    if pid is None:
        pid = os.fork()
        if pid == 0:  # child: never returns
            _child_main(source, str(path), name, wanted, limits, workdir, result_w, out_w, token)
    os.close(result_w)
    os.close(out_w)
    started = time.monotonic()
    return lambda: _collect(pid, name, wanted, limits, token, result_r, out_r, started, reap)


def _collect(pid: int, name: str, wanted: list[str], limits: SandboxLimits, token: str, result_r: int, out_r: int,
             started: float, reap=None) -> SandboxOutcome:
    deadline = started + limits.wall_seconds
    result, output = bytearray(), bytearray()
    timed_out = overflow = False
    with selectors.DefaultSelector() as sel:
        sel.register(result_r, selectors.EVENT_READ)
        sel.register(out_r, selectors.EVENT_READ)
        while sel.get_map() and not overflow:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                timed_out = True
                break
            for key, _ in sel.select(remaining):
                chunk = os.read(key.fd, 65536)
                if not chunk:
                    sel.unregister(key.fd)
                elif key.fd == result_r:
                    result += chunk
                    if len(result) > limits.max_output_bytes + 100_000:
                        overflow = True
                elif len(output) < 4 * STDOUT_KEEP:
                    output += chunk[: 4 * STDOUT_KEEP - len(output)]
    exit_status, cpu_used = (reap or _reap)(pid, kill=timed_out or overflow, deadline=deadline + 2)
    os.close(result_r)
    os.close(out_r)
    stdout = output.decode("utf-8", "replace")[:STDOUT_KEEP]

    def outcome(status: str, message: str) -> SandboxOutcome:
        return SandboxOutcome(status=status, stdout=stdout, problems=[AnswerProblem(file=name, line=None, message=message)])

    if timed_out:
        return outcome("timeout", f"ran longer than {limits.wall_seconds:g} s (an infinite loop, or a computation that is too heavy?)")
    if overflow:
        return outcome("error", f"the answer's values are too large (more than {limits.max_output_bytes} bytes)")
    if os.WIFSIGNALED(exit_status):
        sig = os.WTERMSIG(exit_status)
        if sig == signal.SIGXCPU or (sig == signal.SIGKILL and cpu_used >= limits.cpu_seconds - 0.5):
            return outcome("timeout", f"ran longer than {limits.cpu_seconds:g} s of CPU time (an infinite loop?)")
        if sig == signal.SIGKILL:
            return outcome("memory", f"was killed, probably for using more than {limits.memory_mb} MB of memory")
        return outcome("crashed", f"the Python process running the answer crashed ({signal.Signals(sig).name})")
    try:
        report = _ChildReport.model_validate(json.loads(bytes(result).decode("utf-8")))
        if not secrets.compare_digest(report.token, token):
            raise ValueError("forged report")
    except (ValueError, RecursionError, ValidationError, UnicodeDecodeError):
        code = os.WEXITSTATUS(exit_status) if os.WIFEXITED(exit_status) else -1
        return outcome("crashed", f"the answer could not be run (the sandbox stopped with code {code} and no result)")
    values = {k: v for k, v in report.values.items() if k in wanted}
    problems = [p.model_copy(update={"file": name}) for p in report.problems[:50]]
    return SandboxOutcome(values=values, problems=problems, stdout=stdout, status=report.status)


def _reap(pid: int, kill: bool, deadline: float) -> tuple[int, float]:
    """Wait for the child (killing its whole process group first if asked); return status and CPU."""
    if kill:
        _kill_group(pid)
    while True:
        done, status, usage = os.wait4(pid, os.WNOHANG)
        if done:
            return status, usage.ru_utime + usage.ru_stime
        if time.monotonic() > deadline:
            _kill_group(pid)
            _, status, usage = os.wait4(pid, 0)
            return status, usage.ru_utime + usage.ru_stime
        time.sleep(0.001)  # the child closed its pipes and is exiting: usually a millisecond away


def _kill_group(pid: int) -> None:
    for kill in (lambda: os.killpg(pid, signal.SIGKILL), lambda: os.kill(pid, signal.SIGKILL)):
        try:
            kill()
        except (ProcessLookupError, PermissionError):
            pass


# =========================================================================== child side

class _CpuLimit(BaseException):
    """Raised in the child on SIGXCPU; a BaseException so library code does not swallow it."""


def _child_main(source: str, code_path: str, name: str, wanted: list[str], limits: SandboxLimits,
                workdir: str, result_w: int, out_w: int, token: str) -> None:
    code = 70
    try:
        os.setsid()
        _setup_fds(result_w, out_w)
        os.chdir(workdir)
        os.environ.clear()
        os.environ.update({"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8"})
        sys.stdout = sys.stderr = _CappedWriter(1, STDOUT_KEEP)
        sys.stdin = None
        sys.dont_write_bytecode = True
        readable = _readable_dirs()
        sys.path[:] = [p for p in sys.path if p and _under(os.path.realpath(p), readable)]
        _unshare_network()
        _set_limits(limits)
        _drop_privileges(workdir, readable)
        compiled = compile(source, code_path, "exec", dont_inherit=True)
        report = _execute(compiled, code_path, name, wanted, limits, readable, token)
        _write_all(_RESULT_FD, report)
        code = 0
    except BaseException as exc:  # noqa: BLE001 - reported as a crash by the parent
        code = 71
        try:
            os.write(2, f"sandbox setup failed: {type(exc).__name__}: {exc}\n".encode())
        except BaseException:  # noqa: BLE001
            pass
    finally:
        os._exit(code)


def _setup_fds(result_w: int, out_w: int) -> None:
    """stdin from /dev/null, stdout/stderr into the capture pipe, the result pipe on fd 3, nothing else."""
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.dup2(out_w, 1)
    os.dup2(out_w, 2)
    os.dup2(result_w, _RESULT_FD)
    os.closerange(_RESULT_FD + 1, _fd_limit())


def _fd_limit() -> int:
    """One above the highest descriptor this process may have open (for closing all the rest)."""
    return max(resource.getrlimit(resource.RLIMIT_NOFILE)[0], 1024)


class _CappedWriter:
    """``sys.stdout`` for the child: keeps the first few kB, drops the rest without blocking."""

    def __init__(self, fd: int, limit: int) -> None:
        self.fd, self.left = fd, limit
        self.encoding, self.errors = "utf-8", "replace"

    def write(self, text: Any) -> int:
        text = str(text)
        if self.left > 0:
            data = text[: self.left].encode("utf-8", "replace")[: self.left]
            self.left -= len(data)
            try:
                os.write(self.fd, data)
            except OSError:
                self.left = 0
        return len(text)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False


@functools.cache
def _readable_dirs() -> tuple[str, ...]:
    """Python's own install, site-packages and our packages: the only places the child may read.

    Resolved once, in the parent (``_prepare_parent``): ~1 ms of ``realpath`` per child otherwise."""
    paths = sysconfig.get_paths()
    dirs = {paths[k] for k in ("stdlib", "platstdlib", "purelib", "platlib") if paths.get(k)}
    for mod in (sp, lagrade.answer, _try_import("mpmath")):
        if mod is not None and getattr(mod, "__file__", None):
            dirs.add(os.path.dirname(mod.__file__))
    return tuple(sorted({os.path.realpath(d) for d in dirs}))


def _secret_dirs() -> tuple[str, ...]:
    """Reference solutions, problem files and the cache of reference derivations, wherever they are:
    never readable by an answer (a wheel puts them in site-packages, which is otherwise readable)."""
    from lagrade.cache import cache_dir
    from lagrade.library import problem_dirs, reference_dir

    cached = [d for d in (cache_dir(),) if d is not None]
    return tuple(sorted({os.path.realpath(d) for d in (reference_dir(), *problem_dirs(), *cached)}))


_SECRET_DIRS = _secret_dirs()


def _try_import(module: str) -> types.ModuleType | None:
    try:
        return __import__(module)
    except ImportError:
        return None


def _under(path: str, dirs: Sequence[str]) -> bool:
    return any(path == d or path.startswith(d.rstrip(os.sep) + os.sep) for d in dirs)


@functools.cache
def _libc() -> Any:
    """libc, loaded once in the parent (``_prepare_parent``): ``find_library`` runs ``ldconfig -p``
    in a subprocess, which a child forked from a large grader paid twice, ~4 ms per answer."""
    import ctypes
    import ctypes.util

    return ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)


#: True in a process that has an empty network namespace of its own already: a fork server makes one
#: for all its children, which then need no namespace each (making one and, at the child's exit,
#: the kernel tearing it down, cost 0.6-2 ms of CPU per answer here)
_network_private = False


def _unshare_network() -> None:
    """A private, empty network namespace (needs CAP_SYS_ADMIN; silently skipped without it)."""
    global _network_private
    if _network_private:
        return
    try:
        _network_private = _libc().unshare(0x40000000) == 0  # CLONE_NEWNET
    except Exception:  # noqa: BLE001
        pass


def _set_limits(limits: SandboxLimits) -> None:
    cpu = max(1, math.ceil(limits.cpu_seconds))
    vm = _vm_size()
    for which, value in (
        (resource.RLIMIT_CPU, (cpu, cpu + 1)),
        (resource.RLIMIT_AS, (vm + limits.memory_mb * 2**20,) * 2),
        (resource.RLIMIT_FSIZE, (2**20, 2**20)),
        (resource.RLIMIT_CORE, (0, 0)),
        (resource.RLIMIT_NOFILE, (32, 32)),
        (resource.RLIMIT_NPROC, (0, 0)),
    ):
        try:
            soft, hard = resource.getrlimit(which)
            new_soft, new_hard = value
            if hard != resource.RLIM_INFINITY:
                new_soft, new_hard = min(new_soft, hard), min(new_hard, hard)
            resource.setrlimit(which, (new_soft, new_hard))
        except (ValueError, OSError):
            pass
    signal.signal(signal.SIGXCPU, _on_sigxcpu)
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


def _vm_size() -> int:
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def _on_sigxcpu(signum: int, frame: Any) -> None:
    signal.signal(signal.SIGXCPU, signal.SIG_IGN)
    raise _CpuLimit()


def _drop_privileges(workdir: str, readable: Sequence[str]) -> None:
    """Become ``nobody`` if Python's files stay readable that way, else at least drop capabilities."""
    try:
        libc = _libc()
        libc.prctl(38, 1, 0, 0, 0)  # PR_SET_NO_NEW_PRIVS
        libc.prctl(1, signal.SIGKILL, 0, 0, 0)  # PR_SET_PDEATHSIG: die with the grader
    except Exception:  # noqa: BLE001
        libc = None
    if os.geteuid() != 0:
        return
    if all(_world_traversable(d) for d in readable):
        try:
            os.chown(workdir, _NOBODY, _NOBODY)
            os.setgroups([])
            os.setgid(_NOBODY)
            os.setuid(_NOBODY)
            return
        except OSError:
            pass
    if libc is not None:  # still uid 0, but without the powers of root
        import ctypes

        class Header(ctypes.Structure):
            _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

        class Data(ctypes.Structure):
            _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32),
                        ("inheritable", ctypes.c_uint32)]

        for cap in range(64):
            libc.prctl(24, cap, 0, 0, 0)  # PR_CAPBSET_DROP
        header = Header(0x20080522, 0)  # _LINUX_CAPABILITY_VERSION_3
        libc.capset(ctypes.byref(header), ctypes.byref((Data * 2)()))


def _world_traversable(path: str) -> bool:
    p = Path(path)
    for part in [p, *p.parents]:
        try:
            if not part.stat().st_mode & 0o001:
                return False
        except OSError:
            return False
    return True


# --------------------------------------------------------------------------- audit hook

_DENY_PREFIXES = (
    "socket.", "subprocess.", "os.system", "os.exec", "os.posix_spawn", "os.spawn", "os.fork",
    "os.forkpty", "os.kill", "os.killpg", "os.remove", "os.unlink", "os.rename", "os.rmdir",
    "os.mkdir", "os.mkfifo", "os.mknod", "os.chmod", "os.chown", "os.lchown", "os.truncate",
    "os.link", "os.symlink", "os.utime", "os.chdir", "os.chflags", "os.chroot", "os.putenv",
    "os.unsetenv", "os.setxattr", "os.removexattr", "os.startfile", "os.add_dll_directory",
    "os.getxattr", "os.listxattr", "os.walk", "os.fwalk", "glob.", "shutil.", "ctypes.",
    "sys.settrace", "sys.setprofile", "sys.addaudithook", "sys._current_frames",
    "sys._current_exceptions", "gc.get_objects", "gc.get_referrers", "gc.get_referents",
    "code.__new__", "function.__new__", "pickle.find_class",
    "resource.", "pty.", "fcntl.", "mmap.", "tempfile.", "urllib.", "http.", "ftplib.",
    "smtplib.", "poplib.", "imaplib.", "nntplib.", "telnetlib.", "webbrowser.", "sqlite3.",
    "builtins.input", "builtins.breakpoint", "cpython.", "setopencodehook", "syslog.",
    "signal.", "os.setuid", "os.setgid", "sys.setrecursionlimit",
)
_SAFE_NEW_IMPORTS = (
    "sympy", "mpmath", "gmpy2", "flint", "math", "cmath", "lagrade.answer", "dataclasses",
    "fractions", "decimal", "_decimal", "_pydecimal", "numbers", "random", "itertools",
    "functools", "collections", "typing", "operator", "string", "re", "textwrap", "keyword",
    "copy", "heapq", "bisect", "enum", "abc", "weakref", "contextlib", "warnings", "unicodedata",
    "array", "struct", "_struct", "_bisect", "_heapq", "_random", "_sha512", "_sha2", "hashlib",
    "_hashlib", "_blake2", "inspect", "dis", "opcode", "_opcode", "token", "tokenize", "linecache",
    "ast", "_ast", "importlib", "_weakrefset", "_collections_abc", "_functools", "_operator",
    "_string", "_locale", "locale", "encodings", "codecs", "_codecs", "zlib", "binascii", "base64",
    "pprint", "reprlib", "_bz2", "_lzma", "traceback", "difflib", "statistics", "_statistics",
)
_GENERATED_SOURCE_PREFIXES = (b"def monomial_", b"lambda _cls, ", b"def __create_fn__(")
_TYPE_HINT = re.compile(rb"[A-Za-z_][A-Za-z0-9_.\[\], |]{0,200}")  # typing.ForwardRef compiles these
_ALLOWED_AUDITED_READS = frozenset({"__code__", "__defaults__", "__kwdefaults__"})
_PROTECTED_SETS = frozenset({"__code__", "__globals__", "__builtins__"})


class _AuditPolicy:
    """The child's audit hook: what sympy needs to work is allowed, the rest of the OS is not."""

    def __init__(self, student_code: types.CodeType, code_path: str, readable: Sequence[str]) -> None:
        self.student_code = student_code
        self.protected_files = {code_path, os.path.realpath(__file__), __file__}
        self.readable = tuple(readable)
        self.trusted = False
        self.busy = False
        self.pending_exec = False
        self.codegen = 0  # >0 while sympy parses one of its own strings

    def __call__(self, event: str, args: tuple[Any, ...]) -> None:
        if self.busy:
            return
        self.busy = True
        try:
            self.check(event, args)
        finally:
            self.busy = False

    @staticmethod
    def deny(what: str) -> PermissionError:
        return PermissionError(f"{what} is not allowed in an answer file")

    def check(self, event: str, args: tuple[Any, ...]) -> None:
        if event == "open":
            self.check_open(*args[:3])
        elif event in ("os.listdir", "os.scandir"):
            path = args[0] if args else "."
            if isinstance(path, int) or not self.is_readable(path if path is not None else "."):
                raise self.deny("listing directories")
        elif event == "import":
            module = str(args[0])
            if not any(module == m or module.startswith(m + ".") for m in _SAFE_NEW_IMPORTS):
                raise ImportError(f"import of '{module}' is not allowed in an answer file")
        elif event == "compile" and self.trusted:
            return
        elif event == "compile":
            source, filename = (args + (None, None))[:2]
            self.pending_exec = False
            if isinstance(source, str):
                source = source.encode("utf-8", "replace")
            if self.codegen or (filename == "<string>" and isinstance(source, bytes) and (
                    source.startswith(_GENERATED_SOURCE_PREFIXES)
                    or (_TYPE_HINT.fullmatch(source) and b"__" not in source))):
                self.pending_exec = True
            elif not (isinstance(filename, str) and filename.endswith(".py") and self.is_readable(filename)):
                raise self.deny(f"compiling code (eval, exec, compile, sympify of strings, lambdify)")
        elif event == "exec":
            code = args[0]
            filename = getattr(code, "co_filename", "")
            if code is self.student_code or (filename.endswith(".py") and self.is_readable(filename)):
                return
            if self.codegen or (filename == "<string>" and self.pending_exec):
                self.pending_exec = False
                return
            raise self.deny("running generated code")
        elif event == "sys._getframe":
            frame = args[0] if args else None
            if frame is not None and frame.f_code.co_filename in self.protected_files:
                raise self.deny("inspecting stack frames")
        elif event == "object.__getattr__":
            if not self.trusted and args[1] not in _ALLOWED_AUDITED_READS:
                raise self.deny(f"reading '.{args[1]}'")
        elif event in ("object.__setattr__", "object.__delattr__"):
            if args[1] in _PROTECTED_SETS or isinstance(args[0], types.ModuleType):
                raise self.deny(f"changing '.{args[1]}'")
        elif event.startswith(_DENY_PREFIXES):
            raise self.deny(f"'{event}'")

    def check_open(self, path: Any, mode: Any = None, flags: Any = None) -> None:
        writes = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND
        if isinstance(mode, str) and any(c in mode for c in "wax+"):
            raise self.deny("writing files")
        if isinstance(flags, int) and flags & writes:
            raise self.deny("writing files")
        if isinstance(path, int) or not self.is_readable(path):
            raise self.deny(f"opening '{os.fsdecode(path) if isinstance(path, (str, bytes)) else path}'")

    def is_readable(self, path: Any) -> bool:
        try:
            real = os.path.realpath(os.fsdecode(path))
        except (TypeError, ValueError, OSError):
            return False
        return _under(real, self.readable) and not _under(real, _SECRET_DIRS)


# --------------------------------------------------------------------------- running and encoding

_REFUSED_BUILTINS = frozenset({
    "open", "exec", "eval", "compile", "input", "breakpoint", "help", "exit", "quit", "globals",
    "locals", "vars", "getattr", "setattr", "delattr", "memoryview", "__build_class__",
    "__loader__", "__spec__", "copyright", "credits", "license",
})


def _restricted_builtins() -> dict[str, Any]:
    safe = {k: v for k, v in vars(builtins).items() if k not in _REFUSED_BUILTINS}
    safe["__import__"] = _restricted_import
    return safe


_real_import = builtins.__import__


def _restricted_import(name: str, globals: Any = None, locals: Any = None, fromlist: Any = (), level: int = 0) -> Any:
    """The only importer an answer file sees: sympy (safe parts), math and lagrade.answer."""
    fromlist = tuple(fromlist or ())
    only_answer = name == "lagrade" and fromlist and set(fromlist) <= {"answer"}
    if level or not (module_allowed(name) or only_answer):
        raise ImportError(f"import of '{name}' is not allowed; an answer file may import only {ALLOWED_MODULES_TEXT}")
    for item in fromlist:
        if item != "*" and (item in FORBIDDEN_ATTRIBUTES or item.startswith("__")
                            or not module_allowed(f"{name}.{item}")):
            raise ImportError(f"importing '{item}' from '{name}' is not allowed in an answer file")
    if name.startswith("lagrade"):
        # never hand out the real ``lagrade`` package: its other modules are the grader
        package = types.ModuleType("lagrade")
        package.answer = lagrade.answer  # type: ignore[attr-defined]
        return lagrade.answer if name == "lagrade.answer" and fromlist else package
    return _real_import(name, None, None, fromlist, 0)


_PLAIN_MATH_NODES = (
    ast.Expression, ast.Name, ast.Load, ast.Constant, ast.BinOp, ast.UnaryOp, ast.operator,
    ast.unaryop, ast.Call, ast.Tuple, ast.List, ast.Compare, ast.cmpop,
)


def _plain_math(text: Any) -> bool:
    """True for strings like ``"(1/2)"`` or ``"sqrt(2)*pi"``: numbers, names, operators, calls."""
    if not isinstance(text, str) or len(text) > 10_000:
        return False
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    for node in ast.walk(tree):
        if not isinstance(node, _PLAIN_MATH_NODES):
            return False
        if isinstance(node, ast.Constant) and not isinstance(node.value, (int, float)):
            return False
        if isinstance(node, ast.Name) and (node.id.startswith("_") or node.id in FORBIDDEN_ATTRIBUTES
                                           or node.id in _PARSE_FORBIDDEN):
            return False
        if isinstance(node, ast.Call) and (node.keywords or not isinstance(node.func, ast.Name)):
            return False
    return True


_PARSE_FORBIDDEN = frozenset({"plot", "plot3d", "textplot", "var", "symbols", "Symbol", "Function",
                              "Dummy", "Wild", "__import__", "print", "pprint", "type", "object"})


def _guard_string_parsing(policy: _AuditPolicy, code_path: str) -> None:
    """sympy parses strings internally (``nsimplify``, module imports), so parsing stays possible,
    but only for text that is plain arithmetic (no attributes, dunders, lambdas, blocked names)
    or that a sympy module passes while being imported.  ``eval`` is what parse_expr does, so
    this is the gate that keeps ``S(text)`` from being a way around the screening."""
    import sympy.parsing.sympy_parser as parser

    original = parser.parse_expr

    def parse_expr(*args: Any, **kwargs: Any) -> Any:
        policy.trusted = True
        try:
            frame, from_import = sys._getframe(1), False
            while frame is not None:
                filename = frame.f_code.co_filename
                if filename == code_path:
                    break
                if frame.f_code.co_name == "<module>" and policy.is_readable(filename):
                    from_import = True
                    break
                frame = frame.f_back
            plain = bool(args) and _plain_math(args[0])  # ast.parse raises a "compile" event
        finally:
            policy.trusted = False
        if not from_import and not plain:
            raise PermissionError("parsing strings into expressions (sympify/S of a string) is not allowed "
                                  "in an answer file; build expressions with Symbol, Function and operators")
        policy.codegen += 1
        try:
            return original(*args, **kwargs)
        finally:
            policy.codegen -= 1

    parser.parse_expr = parse_expr


def _execute(code: types.CodeType, code_path: str, name: str, wanted: list[str],
             limits: SandboxLimits, readable: Sequence[str], token: str) -> bytes:
    import traceback

    policy = _AuditPolicy(code, code_path, readable)
    _guard_string_parsing(policy, code_path)
    namespace: dict[str, Any] = {"__name__": "__answer__", "__builtins__": _restricted_builtins()}
    status, problems = "ok", []
    sys.addaudithook(policy)
    try:
        exec(code, namespace)
    except BaseException as exc:  # noqa: BLE001 - every failure is reported to the student
        signal.signal(signal.SIGXCPU, signal.SIG_IGN)
        policy.trusted = True
        line = None
        for frame, lineno in traceback.walk_tb(exc.__traceback__):
            if frame.f_code.co_filename == code_path:
                line = lineno
        policy.trusted = False
        status, message = _describe(exc, limits)
        problems.append({"file": name, "line": line, "message": message})
    signal.signal(signal.SIGXCPU, signal.SIG_IGN)

    values: dict[str, Any] = {}
    budget = limits.max_output_bytes - 50_000
    for key in wanted:
        if key not in namespace:
            continue
        try:
            encoded = json.dumps(_encode(namespace[key], 0), allow_nan=True)
        except _EncodeError as exc:
            problems.append({"file": name, "line": None, "message": f"'{key}' {exc}"})
            continue
        except (RecursionError, MemoryError, ValueError):
            problems.append({"file": name, "line": None,
                             "message": f"'{key}' is too large or too deeply nested to grade"})
            continue
        if len(encoded) > budget:
            problems.append({"file": name, "line": None, "message": f"'{key}' is too large to grade"})
            continue
        budget -= len(encoded)
        values[key] = json.loads(encoded)
    return json.dumps({"token": token, "status": status, "values": values, "problems": problems}).encode("utf-8")


def _describe(exc: BaseException, limits: SandboxLimits) -> tuple[str, str]:
    if isinstance(exc, _CpuLimit):
        return "timeout", f"ran longer than {limits.cpu_seconds:g} s of CPU time (an infinite loop?)"
    if isinstance(exc, MemoryError):
        return "memory", f"used more than {limits.memory_mb} MB of memory"
    if isinstance(exc, RecursionError):
        return "error", "RecursionError: maximum recursion depth exceeded (a function that calls itself forever?)"
    text = str(exc).strip().splitlines()[0][:300] if str(exc).strip() else ""
    return "error", f"{type(exc).__name__}: {text}" if text else type(exc).__name__


class _EncodeError(Exception):
    pass


def _encode(value: Any, depth: int) -> dict[str, Any]:
    """A student's value as plain JSON: sympy objects as nodes (or ``srepr`` text), containers recursively."""
    if depth > 20:
        raise _EncodeError("is nested too deeply")
    if isinstance(value, bool):
        return {"kind": "bool", "value": value}
    if isinstance(value, sp.MatrixBase):
        if value.rows == 1 or value.cols == 1:
            return {"kind": "list", "items": [_encode(v, depth + 1) for v in value]}
        return {"kind": "list", "items": [_encode(list(r), depth + 1) for r in value.tolist()]}
    if isinstance(value, sp.Basic):
        nodes = expr_nodes(value)
        return {"kind": "expr", "nodes": nodes} if nodes is not None else {"kind": "expr", "srepr": srepr_text(value)}
    if isinstance(value, int):
        if value.bit_length() > 4000:
            raise _EncodeError("is an integer too large to grade")
        return {"kind": "int", "value": value}
    if isinstance(value, float):
        return {"kind": "float", "value": value}
    if isinstance(value, str):
        if len(value) > 100_000:
            raise _EncodeError("is a string too long to grade")
        return {"kind": "str", "value": value}
    if isinstance(value, (list, tuple)):
        return {"kind": "list", "items": [_encode(v, depth + 1) for v in value]}
    if isinstance(value, dict):
        return {"kind": "dict", "items": [[_encode(k, depth + 1), _encode(v, depth + 1)] for k, v in value.items()]}
    kind = "function" if callable(value) else type(value).__name__
    raise _EncodeError(f"is a {kind}, expected a sympy expression (or a number, list or dict of them)")


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]
