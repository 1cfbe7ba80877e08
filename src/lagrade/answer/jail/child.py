"""What runs in the clean zygote and in each child it forks: the answer's side of the sandbox.

The child confines itself with the kernel's layers (:mod:`lagrade.answer.jail.kernel`) before it reads the
answer, then runs it under the tripwires (a static screen, :mod:`lagrade.answer.jail.screen`,
restricted builtins and an audit hook), which exist to tell a student in plain words what an answer
may not do; they are not the defence. It sends its values back as JSON (:class:`ChildReport`),
which the grader validates and rebuilds from an allowlist (:mod:`lagrade.answer.jail.rebuild`). This
module never imports the grader's side (:mod:`lagrade.answer.jail.sandbox`): nothing here needs it.
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
import signal
import sys
import sysconfig
import time
import types
from collections.abc import Sequence
from typing import Any, Literal

import sympy as sp
from pydantic import BaseModel, ConfigDict

import lagrade.answer
from lagrade.answer.jail.rebuild import EncodedValue, expr_nodes, srepr_text
from lagrade.answer.jail.screen import (
    ALLOWED_MODULES_TEXT,
    FORBIDDEN_ATTRIBUTES,
    AnswerProblem,
    module_allowed,
)
from lagrade.problem.limits import MAX_INT_ABS


STDOUT_KEEP = 2000
_RESULT_FD = 3


class SandboxLimits(BaseModel):
    """Resource limits for one answer file (memory is address space *above* the grader's own)."""

    model_config = ConfigDict(frozen=True)

    cpu_seconds: float = 10
    wall_seconds: float = 20
    memory_mb: int = 1024
    max_output_bytes: int = 2_000_000


class ChildReport(BaseModel):
    """The child's JSON document; validated because the child ran untrusted code."""

    model_config = ConfigDict(extra="forbid")

    token: str
    status: Literal["ok", "error", "timeout", "memory"]
    values: dict[str, EncodedValue]
    problems: list[AnswerProblem]


def reap_child(pid: int, kill: bool, deadline: float) -> tuple[int, float]:
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


def prepare_zygote() -> None:
    """Import, in the zygote before it forks, what the child may need but must not import once locked."""
    import dataclasses  # noqa: F401  (sympy imports some modules lazily that use it)
    import sympy.parsing.sympy_parser  # noqa: F401  (patched in the child so strings are not parsed)
    import traceback  # noqa: F401

    # sympy imports these the first time an Add or Mul of a certain shape is built: about 50 ms that
    # a child would pay on every answer (its imports die with it)
    import sympy.assumptions.wrapper  # noqa: F401
    import sympy.sets.setexpr  # noqa: F401
    import sympy.tensor.tensor  # noqa: F401

    from lagrade.answer.jail import kernel

    # libc is found once here: ctypes' find_library runs ldconfig in a subprocess, which a child,
    # inside the jail, would try on every answer (and a child whose zygote enters no namespace
    # would otherwise load it first). The seccomp allowlist is compiled to BPF once here too, each
    # child only loads it; and the answers' vocabulary (sympy's names bound in lagrade.answer, the
    # module an answer is handed) is made once: 3 ms a child that imports it otherwise.
    for warm in (kernel._libc, kernel.landlock_available, kernel.seccomp_available, kernel.seccomp_program,
                 _readable_dirs, secret_dirs, _jail_sys_path, _vocabulary):
        warm()


# =========================================================================== child side

class _CpuLimit(BaseException):
    """Raised in the child on SIGXCPU; a BaseException so library code does not swallow it."""


#: the exit code of a child whose jail could not be built: it never ran the answer
JAIL_FAILED = 72


def child_main(job_fd: int, workdir: str, result_w: int, out_w: int, *, layers: Sequence[str],
               uid: int | None, readable: Sequence[str], vm_size: int) -> None:
    """The forked child: read its job, confine itself (`lagrade.answer.jail.kernel`), then run the
    answer. Never returns.

    The job (source, path, names wanted, limits, token) is read from ``job_fd`` here, after the
    fork: the zygote only passed the descriptor on, so the answer's bytes are in this process alone
    and never in the memory later answers are forked from. If a layer the zygote reported active
    cannot be applied, the answer is not run at all."""
    from lagrade.answer.jail import kernel

    code = 70
    try:
        child = _read_job(job_fd)
        limits = SandboxLimits.model_validate(child["limits"])
        os.setsid()
        _setup_fds(result_w, out_w)
        os.chdir(workdir)
        os.environ.clear()
        os.environ.update({"PATH": "/nonexistent", "LANG": "C.UTF-8"})
        sys.stdout = sys.stderr = _CappedWriter(1, STDOUT_KEEP)
        sys.stdin = None
        sys.dont_write_bytecode = True
        allowed = _readable_dirs()
        sys.path[:] = _jail_sys_path()
        if "limits" in layers:
            _set_limits(limits, vm_size)
        failed = kernel.confine(layers, uid, readable)
        if failed:
            code = JAIL_FAILED
            os.write(2, f"the jail could not be built: {'; '.join(f'{k}: {v}' for k, v in failed.items())}\n".encode())
            os._exit(code)
        compiled = compile(child["source"], child["path"], "exec", dont_inherit=True)
        report = _execute(compiled, child["path"], child["name"], list(child["wanted"]), limits, allowed,
                          child["token"], bool(child.get("tripwires", True)))
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


def _read_job(fd: int) -> dict[str, Any]:
    """The job the grader wrote into ``fd`` (from its start), as JSON; the descriptor is closed."""
    data, offset = bytearray(), 0
    try:
        while chunk := os.pread(fd, 1 << 20, offset):
            data += chunk
            offset += len(chunk)
    finally:
        os.close(fd)
    return json.loads(data)


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
    for mod in (sp, lagrade, _try_import("mpmath")):
        if mod is not None and getattr(mod, "__file__", None):
            dirs.add(os.path.dirname(mod.__file__))
    return tuple(sorted({os.path.realpath(d) for d in dirs}))


@functools.cache
def _jail_sys_path() -> tuple[str, ...]:
    """The entries of ``sys.path`` the child keeps: those inside `_readable_dirs` (resolved once, in
    the zygote: their ``realpath`` is ~0.4 ms a child otherwise)."""
    allowed = _readable_dirs()
    return tuple(p for p in sys.path if p and _under(os.path.realpath(p), allowed))


@functools.cache
def secret_dirs() -> tuple[str, ...]:
    """Reference solutions, problem files and the cache of reference derivations, wherever they are:
    never readable by an answer (a wheel puts them in site-packages, which is otherwise readable)."""
    from lagrade.problem.library import cache_dir, problem_dirs, reference_dir

    cached = [d for d in (cache_dir(),) if d is not None]
    return tuple(sorted({os.path.realpath(d) for d in (reference_dir(), *problem_dirs(), *cached)}))




def _try_import(module: str) -> types.ModuleType | None:
    try:
        return __import__(module)
    except ImportError:
        return None


def _under(path: str, dirs: Sequence[str]) -> bool:
    return any(path == d or path.startswith(d.rstrip(os.sep) + os.sep) for d in dirs)


def _set_limits(limits: SandboxLimits, vm: int) -> None:
    """CPU, address space above the size the child was forked at, output files, descriptors, and no
    new process."""
    cpu = max(1, math.ceil(limits.cpu_seconds))
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


def _on_sigxcpu(signum: int, frame: Any) -> None:
    signal.signal(signal.SIGXCPU, signal.SIG_IGN)
    raise _CpuLimit()


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


def _make_hook(student_code: types.CodeType, code_path: str, readable: Sequence[str], trusted_parse: frozenset,
               trusted_reads: frozenset):
    """The child's audit hook: a tripwire that names what an answer may not do, not the barrier.

    It keeps no state an answer could reach and switch: its re-entrancy flag and its "the next exec
    is sympy's own generated code" flag live in this closure, and the hook function itself is held
    only by the interpreter. Where lagrade's own code must do something audited (parse plain
    arithmetic, find the answer's line in a traceback), the hook trusts the *frame* doing it, by its
    code object, which an answer cannot forge. It touches no argument before checking that its type
    is exactly ``str``, ``bytes`` or ``int``, so that no method of an answer's object runs inside it."""
    protected = frozenset({code_path, os.path.realpath(__file__), __file__})
    readable = tuple(readable)
    busy = pending_exec = False

    def deny(what: str) -> PermissionError:
        return PermissionError(f"{what} is not allowed in an answer file")

    def is_readable(path: Any) -> bool:
        if type(path) not in (str, bytes):
            return False
        try:
            real = os.path.realpath(os.fsdecode(path))
        except (TypeError, ValueError, OSError):
            return False
        return _under(real, readable) and not _under(real, secret_dirs())

    def caller_is(codes: frozenset) -> bool:
        frame = sys._getframe(3)  # 0 this, 1 check, 2 the hook, 3 the frame whose action raised the event
        return frame is not None and frame.f_code in codes

    def on_stack(codes: frozenset) -> bool:
        frame = sys._getframe(3)
        while frame is not None:
            if frame.f_code in codes:
                return True
            frame = frame.f_back
        return False

    def check(event: str, args: tuple[Any, ...]) -> None:
        nonlocal pending_exec
        if event == "open":
            path, mode, flags = (tuple(args) + (None, None, None))[:3]
            if (type(mode) is str and any(c in mode for c in "wax+")) or (
                    type(flags) is int and flags & (os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND)):
                raise deny("writing files")
            if not is_readable(path):
                raise deny(f"opening '{path}'" if type(path) is str else "opening files")
        elif event in ("os.listdir", "os.scandir"):
            path = args[0] if args else "."
            if not is_readable("." if path is None else path):
                raise deny("listing directories")
        elif event == "import":
            module = args[0] if args else None
            if type(module) is not str or not any(module == m or module.startswith(m + ".") for m in _SAFE_NEW_IMPORTS):
                raise ImportError(f"import of '{module if type(module) is str else '?'}' is not allowed in an answer file")
        elif event == "compile":
            source, filename = (tuple(args) + (None, None))[:2]
            pending_exec = False
            if type(source) is str:
                source = source.encode("utf-8", "replace")
            if on_stack(trusted_parse) or (filename == "<string>" and type(source) is bytes and (
                    source.startswith(_GENERATED_SOURCE_PREFIXES)
                    or (_TYPE_HINT.fullmatch(source) and b"__" not in source))):
                pending_exec = True
            elif filename == "<unknown>" and type(source) is bytes:
                pass  # ast.parse: a tree, not code; running anything compiled from it is refused below
            elif not (type(filename) is str and filename.endswith(".py") and is_readable(filename)):
                raise deny("compiling code (eval, exec, compile, sympify of strings, lambdify)")
        elif event == "exec":
            code = args[0] if args else None
            if type(code) is not types.CodeType:
                raise deny("running generated code")
            filename = code.co_filename
            if code is student_code or (type(filename) is str and filename.endswith(".py") and is_readable(filename)):
                return
            if filename == "<string>" and (pending_exec or on_stack(trusted_parse)):
                pending_exec = False
                return
            raise deny("running generated code")
        elif event == "sys._getframe":
            frame = args[0] if args else None
            if type(frame) is types.FrameType and frame.f_code.co_filename in protected and not caller_is(trusted_parse):
                raise deny("inspecting stack frames")
        elif event == "object.__getattr__":
            name = args[1] if len(args) > 1 else None
            if type(name) is not str or (name not in _ALLOWED_AUDITED_READS and not caller_is(trusted_reads | trusted_parse)):
                raise deny(f"reading '.{name if type(name) is str else '?'}'")
        elif event in ("object.__setattr__", "object.__delattr__"):
            name = args[1] if len(args) > 1 else None
            if type(name) is not str or name in _PROTECTED_SETS or types.ModuleType in type(args[0]).__mro__:
                raise deny(f"changing '.{name if type(name) is str else '?'}'")
        elif event.startswith(_DENY_PREFIXES):
            raise deny(f"'{event}'")

    def hook(event: str, args: tuple[Any, ...]) -> None:
        nonlocal busy
        if busy:
            return
        busy = True
        try:
            check(event, args)
        finally:
            busy = False

    return hook


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


@functools.cache
def _vocabulary() -> types.ModuleType:
    """What ``import lagrade.answer`` gives an answer file: the names of its ``__all__`` and nothing
    else. The package itself also holds the answers layer (the jail, the readers) as submodules,
    which an answer must not reach as attributes."""
    made = types.ModuleType("lagrade.answer", lagrade.answer.__doc__)
    for name in lagrade.answer.__all__:
        setattr(made, name, getattr(lagrade.answer, name))
    made.__all__ = list(lagrade.answer.__all__)  # type: ignore[attr-defined]
    return made


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
        package.answer = _vocabulary()  # type: ignore[attr-defined]
        return package.answer if name == "lagrade.answer" and fromlist else package
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


def _guard_string_parsing(code_path: str, readable: Sequence[str]) -> types.CodeType:
    """sympy parses strings internally (``nsimplify``, module imports), so parsing stays possible,
    but only for text that is plain arithmetic (no attributes, dunders, lambdas, blocked names)
    or that a sympy module passes while being imported.  ``eval`` is what parse_expr does, so
    this is the gate that keeps ``S(text)`` from being a way around the screening. The hook trusts
    the compile and exec this function's frame leads to (its code object); calling sympy's own
    parse_expr directly is refused."""
    import sympy.parsing.sympy_parser as parser

    original = parser.parse_expr

    def parse_expr(*args: Any, **kwargs: Any) -> Any:
        frame, from_import = sys._getframe(1), False
        while frame is not None:
            filename = frame.f_code.co_filename
            if filename == code_path:
                break
            if frame.f_code.co_name == "<module>" and type(filename) is str and _under(os.path.realpath(filename), readable):
                from_import = True
                break
            frame = frame.f_back
        frame = None
        plain = bool(args) and _plain_math(args[0])
        if not from_import and not plain:
            raise PermissionError("parsing strings into expressions (sympify/S of a string) is not allowed "
                                  "in an answer file; build expressions with Symbol, Function and operators")
        return original(*args, **kwargs)

    parser.parse_expr = parse_expr
    return parse_expr.__code__


def _answer_line(tb: Any, code_path: str) -> int | None:
    """The last line of the answer file in a traceback (reading ``tb_frame`` is audited: the hook
    trusts this function's frame, which returns a number only)."""
    line = None
    while type(tb) is types.TracebackType:
        if tb.tb_frame.f_code.co_filename == code_path:
            line = tb.tb_lineno
        tb = tb.tb_next
    return line


_TRUSTED_READS = frozenset({_answer_line.__code__})


def _execute(code: types.CodeType, code_path: str, name: str, wanted: list[str],
             limits: SandboxLimits, readable: Sequence[str], token: str, tripwires: bool = True) -> bytes:
    builtins_ = _restricted_builtins() if tripwires else vars(builtins)
    namespace: dict[str, Any] = {"__name__": "__answer__", "__builtins__": builtins_}
    status, problems = "ok", []
    if tripwires:
        guard = _guard_string_parsing(code_path, readable)
        sys.addaudithook(_make_hook(code, code_path, readable, frozenset({guard}), _TRUSTED_READS))
    try:
        exec(code, namespace)
    except BaseException as exc:  # noqa: BLE001 - every failure is reported to the student
        signal.signal(signal.SIGXCPU, signal.SIG_IGN)
        status, message = _describe(exc, limits)
        problems.append({"file": name, "line": _answer_line(exc.__traceback__, code_path), "message": message})
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
        if any(max(abs(n.p), n.q) > MAX_INT_ABS for n in value.atoms(sp.Rational)):  # the grader refuses it:
            raise _EncodeError(f"holds an integer too large (more than {len(str(MAX_INT_ABS)) - 1} digits)")  # say so
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
