"""The operating system's barrier around a student's code, in layers that each hold on their own.

An answer file is hostile code, and Python cannot contain Python: the screen and the audit hook
(:mod:`lagrade.answer.jail.sandbox`) are tripwires that give students clear messages, never the
defence. The defence is what the kernel enforces on the process that runs the file:

``uid``           another uid than the grader's (a fresh unprivileged uid per answer when lagrade
                  runs as root, from a block of the zygote's own: no two graders share one; inside
                  a user namespace otherwise): no file, process or cache of the grader's is its own.
``mount``         a mount namespace whose root is an empty tmpfs holding, read-only, only Python's
                  standard library, sympy and mpmath, the system's shared libraries and /dev/null:
                  no problem files, references, cache, gradebook, home, shell or /proc.
``pid``           a PID namespace: the grader's processes have no number the answer could name.
``network``       an empty network namespace.
``no_new_privs``  no set-uid program or file capability can give privileges back.
``limits``        CPU, address space, file size, descriptors, no new processes.
``landlock``      the kernel's file-access allowlist: read-only Python and system libraries, no
                  writes, no execution; holds without any privilege.
``seccomp``       a system-call allowlist: no execve, ptrace, sockets, signals, mounts, opening a
                  file for writing, or signal-driven I/O (fcntl's F_SETOWN, F_SETSIG, O_ASYNC).

The namespaces are entered once by the clean zygote (:mod:`lagrade.answer.jail.zygote`), which every
child is forked from; the rest is applied by each child on itself before it reads the answer.
Each layer is probed and reported (`lagrade doctor`); one that the machine does not allow is
reported inactive, never silently assumed.
"""

from __future__ import annotations

import ctypes
import errno
import functools
import os
import platform
import signal
import sys
import sysconfig
from collections.abc import Iterable, Sequence

__all__ = ["LAYERS", "MINIMUM", "JAIL_UID_BASE", "JAIL_UID_BLOCK", "jail_uid", "enter_namespaces", "build_root",
           "confine", "jail_dirs"]

LAYERS = ("uid", "mount", "pid", "network", "no_new_privs", "limits", "landlock", "seccomp")
#: what a class may not be graded without (`lagrade grade` refuses otherwise): a view of the files
#: that holds no key (the mount namespace or Landlock), a system-call allowlist, and no privileges
MINIMUM_FS = ("mount", "landlock")
MINIMUM = ("seccomp", "no_new_privs", "limits")
#: answers run as uids from JAIL_UID_BASE up, which no account has: each zygote (one grader's tree of
#: answers) draws from a block of JAIL_UID_BLOCK of its own, numbered by its first process's pid, so
#: two graders at once never run answers as the same uid (`jail_uid`)
JAIL_UID_BASE = 1_900_000_000
JAIL_UID_BLOCK = 512
#: Linux's largest pid (PID_MAX_LIMIT on 64 bits): the blocks end below 2**32 - 1, which is no uid
_PID_MAX_LIMIT = 1 << 22
#: where the per-answer working directories live inside the mount namespace
JAIL_WORK = "/jail"

_CLONE_NEWNS, _CLONE_NEWUTS, _CLONE_NEWIPC = 0x00020000, 0x04000000, 0x08000000
_CLONE_NEWUSER, _CLONE_NEWPID, _CLONE_NEWNET = 0x10000000, 0x20000000, 0x40000000
_MS_RDONLY, _MS_NOSUID, _MS_NODEV, _MS_NOEXEC = 0x1, 0x2, 0x4, 0x8
_MS_REMOUNT, _MS_BIND, _MS_REC, _MS_PRIVATE = 0x20, 0x1000, 0x4000, 0x40000
_MNT_DETACH = 0x2
#: glibc has no pivot_root wrapper: its system-call number by machine
_PIVOT_ROOT = {"x86_64": 155, "aarch64": 41, "riscv64": 41, "ppc64le": 203, "s390x": 217, "i686": 217,
               "armv7l": 218}
_ST_FLAGS = {os.ST_RDONLY: _MS_RDONLY, os.ST_NOSUID: _MS_NOSUID, os.ST_NODEV: _MS_NODEV,
             os.ST_NOEXEC: _MS_NOEXEC} if hasattr(os, "ST_NOSUID") else {}


@functools.cache
def _libc():
    import ctypes.util

    return ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)


def _check(result: int, what: str) -> None:
    if result != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"{what}: {os.strerror(err)}")


def jail_uid(tree: int, n: int) -> int:
    """The uid of the ``n``-th answer of the zygote whose first process is pid ``tree``: the block of
    a live process's pid is no other live zygote's, and a zygote skips a uid still in use."""
    return JAIL_UID_BASE + (tree % _PID_MAX_LIMIT) * JAIL_UID_BLOCK + n % JAIL_UID_BLOCK


# =========================================================================== namespaces (zygote)

def enter_namespaces(wanted: Iterable[str]) -> dict[str, str]:
    """Unshare the namespaces of the wanted layers (``mount``, ``pid``, ``network``, ``uid``); the
    next child forked is PID 1 of the new PID namespace. Returns ``layer -> why not`` for those that
    could not be had (nothing for those that are active)."""
    wanted = set(wanted)
    failed: dict[str, str] = {}
    if not sys.platform.startswith("linux"):
        return {k: "not Linux" for k in wanted & {"mount", "pid", "network", "uid"}}
    flags = 0
    if "mount" in wanted or "pid" in wanted:
        flags |= _CLONE_NEWNS
    if "pid" in wanted:
        flags |= _CLONE_NEWPID
    if "network" in wanted:
        flags |= _CLONE_NEWNET | _CLONE_NEWIPC | _CLONE_NEWUTS
    if not flags:
        return failed
    uid, gid = os.geteuid(), os.getegid()
    if uid != 0:  # a user namespace of our own first: there we may make the others
        if _libc().unshare(_CLONE_NEWUSER) != 0:
            why = f"no user namespace ({os.strerror(ctypes.get_errno())}: unprivileged user namespaces off?)"
            return {k: why for k in wanted & {"mount", "pid", "network"}} | (
                {"uid": why} if "uid" in wanted else {})
        for name, text in (("setgroups", "deny"), ("uid_map", f"0 {uid} 1"), ("gid_map", f"0 {gid} 1")):
            with open(f"/proc/self/{name}", "w") as fh:
                fh.write(text)
    if _libc().unshare(flags) == 0:
        return failed
    why = os.strerror(ctypes.get_errno())
    for layer in ("mount", "pid", "network"):  # one at a time, to report which the machine refuses
        layer_flags = {"mount": _CLONE_NEWNS, "pid": _CLONE_NEWPID | _CLONE_NEWNS,
                       "network": _CLONE_NEWNET | _CLONE_NEWIPC | _CLONE_NEWUTS}[layer]
        if layer in wanted and _libc().unshare(layer_flags) != 0:
            failed[layer] = f"unshare refused ({why})"
    return failed


def jail_dirs() -> tuple[list[str], list[str]]:
    """(directories an answer may read, site-packages directories to hide inside them).

    Python's standard library, the packages an answer may import (sympy, mpmath and their optional
    accelerators), and the system's shared libraries, which lazily imported extension modules link."""
    paths = sysconfig.get_paths()
    allowed = {paths["stdlib"], os.path.join(paths["stdlib"], "lib-dynload")}
    for name in ("sympy", "mpmath", "gmpy2", "flint"):
        spec = _find_spec(name)
        if spec is not None and spec.origin and spec.origin not in ("built-in", "frozen"):
            origin = os.path.dirname(spec.origin) if spec.submodule_search_locations else spec.origin
            allowed.add(origin)
    for lib in ("/usr/lib", "/usr/lib64", "/usr/local/lib", "/lib", "/lib64", "/usr/lib32"):
        if os.path.isdir(lib):
            allowed.add(lib)
    real = sorted({os.path.realpath(d) for d in allowed if os.path.exists(d)})
    hidden = sorted({os.path.realpath(p) for k in ("purelib", "platlib") if (p := paths.get(k))}
                    | {os.path.realpath(os.path.join(paths["stdlib"], "site-packages"))})
    return real, hidden


def _find_spec(name: str):
    import importlib.util

    try:
        return importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return None


def build_root(allowed: Sequence[str], hidden: Sequence[str], secret: Sequence[str], staging: str) -> None:
    """Make ``staging`` (an empty directory) the root of this mount namespace: a tmpfs holding only
    ``allowed`` (read-only, at their own paths), with ``hidden`` and ``secret`` covered by empty
    read-only tmpfs, /dev/null and /dev/urandom, and a writable /jail for the working directories.
    Called by the zygote, once, inside its mount namespace."""
    libc = _libc()

    def mount(source, target, fstype, flags, data=None):
        _check(libc.mount(_b(source), _b(target), _b(fstype), flags, _b(data)), f"mount {target}")

    mount(None, "/", None, _MS_REC | _MS_PRIVATE)  # nothing we mount reaches the grader's view
    mount("tmpfs", staging, "tmpfs", _MS_NOSUID | _MS_NODEV, "mode=0755,size=8m")
    binds = sorted(set(allowed), key=len)
    for src in binds:
        if os.path.islink(src):
            continue
        dst = staging + src
        os.makedirs(dst, mode=0o755, exist_ok=True)
        mount(src, dst, None, _MS_BIND | _MS_REC)
        mount(None, dst, None, _MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID | _MS_NODEV | _locked(src))
    for cover in sorted(set(hidden) | set(secret), key=len):
        dst = staging + cover
        if any(cover == b or cover.startswith(b.rstrip("/") + "/") for b in binds) and os.path.isdir(dst):
            mount("tmpfs", dst, "tmpfs", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC, "mode=0755,size=64k")
    for src in binds:  # packages allowed inside a covered site-packages go back on top of the cover
        if any(src.startswith(c.rstrip("/") + "/") for c in hidden) and not os.path.islink(src):
            dst = staging + src
            os.makedirs(dst, mode=0o755, exist_ok=True) if os.path.isdir(src) else _touch(dst)
            mount(src, dst, None, _MS_BIND | _MS_REC)
            mount(None, dst, None, _MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID | _MS_NODEV | _locked(src))
    for link in ("/lib", "/lib64", "/lib32"):  # merged-/usr systems: /lib is a link into /usr
        if os.path.islink(link) and not os.path.lexists(staging + link):
            os.symlink(os.readlink(link), staging + link)
    os.makedirs(staging + "/dev", mode=0o755, exist_ok=True)
    for dev in ("null", "zero", "urandom", "random"):
        if os.path.exists(f"/dev/{dev}"):
            _touch(f"{staging}/dev/{dev}")
            mount(f"/dev/{dev}", f"{staging}/dev/{dev}", None, _MS_BIND)
    os.makedirs(staging + JAIL_WORK, mode=0o711)
    mount("tmpfs", staging + JAIL_WORK, "tmpfs", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC, "mode=0711,size=64m")
    os.makedirs(staging + "/.old", mode=0o700)
    # the mount point itself, an empty directory of the grader's, is removed as soon as it is not one:
    # a grader that leaves by os._exit (every check does) or is killed cannot remove it
    parent = os.open(os.path.dirname(staging) or "/", os.O_RDONLY | os.O_DIRECTORY)
    number = _PIVOT_ROOT.get(platform.machine())
    if number is None:
        raise OSError(f"pivot_root: no system-call number known for {platform.machine()}")
    _check(libc.syscall(number, _b(staging), _b(staging + "/.old")), "pivot_root")
    os.chdir("/")
    _check(libc.umount2(b"/.old", _MNT_DETACH), "umount the old root")
    os.rmdir("/.old")
    try:
        os.rmdir(os.path.basename(staging), dir_fd=parent)
    except OSError:
        pass
    finally:
        os.close(parent)
    mount(None, "/", None, _MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID | _MS_NODEV)


def mount_proc() -> None:
    """A /proc of this PID namespace's own, over the grader's (the PID layer without the mount one)."""
    libc = _libc()
    _check(libc.mount(None, b"/", None, _MS_REC | _MS_PRIVATE, None), "mount --make-rprivate /")
    _check(libc.mount(b"proc", b"/proc", b"proc", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC, b"hidepid=2"), "mount /proc")


def _locked(path: str) -> int:
    """Mount flags a bind of ``path`` must keep (a user namespace may not clear them)."""
    try:
        f_flag = os.statvfs(path).f_flag
    except OSError:
        return 0
    return sum(ms for st, ms in _ST_FLAGS.items() if f_flag & st and ms != _MS_RDONLY)


def _touch(path: str) -> None:
    os.close(os.open(path, os.O_CREAT | os.O_WRONLY, 0o644))


def _b(text):
    return None if text is None else os.fsencode(text)


# =========================================================================== each child, on itself

def confine(layers: Iterable[str], uid: int | None, readable: Sequence[str]) -> dict[str, str]:
    """Apply the per-process layers to this process, in the order that lets each be set: another uid,
    no_new_privs, Landlock, seccomp last. ``uid`` is the jail uid for this answer (when running as
    root). Returns ``layer -> why not`` for those that could not be applied."""
    layers = set(layers)
    failed: dict[str, str] = {}
    if "uid" in layers:
        try:
            if uid is not None and os.geteuid() == 0 and not in_user_namespace():
                os.setgroups([])
                os.setresgid(uid, uid, uid)
                os.setresuid(uid, uid, uid)
            elif in_user_namespace():
                _drop_capabilities()  # uid 0 of our own user namespace: the real uid outside is unchanged
            else:
                failed["uid"] = "not root and no user namespace: the answer keeps the grader's uid"
        except OSError as exc:
            failed["uid"] = str(exc)
    if "no_new_privs" in layers or "landlock" in layers or "seccomp" in layers:
        if _libc().prctl(38, 1, 0, 0, 0) != 0:  # PR_SET_NO_NEW_PRIVS
            failed["no_new_privs"] = os.strerror(ctypes.get_errno())
    if "landlock" in layers:
        why = _landlock(readable)
        if why:
            failed["landlock"] = why
    if "seccomp" in layers:
        why = _seccomp()
        if why:
            failed["seccomp"] = why
    return failed


@functools.cache
def in_user_namespace() -> bool:
    """True when this process's user namespace is not the initial one (uid 0 here is not root)."""
    try:
        with open("/proc/self/uid_map") as fh:
            return fh.read().split() != ["0", "0", "4294967295"]
    except OSError:
        return False


def _drop_capabilities() -> None:
    class Header(ctypes.Structure):
        _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

    class Data(ctypes.Structure):
        _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]

    libc = _libc()
    for cap in range(64):
        libc.prctl(24, cap, 0, 0, 0)  # PR_CAPBSET_DROP
    header = Header(0x20080522, 0)  # _LINUX_CAPABILITY_VERSION_3
    _check(libc.capset(ctypes.byref(header), ctypes.byref((Data * 2)())), "capset")


def landlock_available() -> str | None:
    """None if Landlock can be used here, else why not."""
    try:
        import landlock
    except ImportError:
        return "the 'landlock' package is not installed"
    try:
        if landlock.landlock_abi_version() < 1:
            return "the kernel has no Landlock"
    except Exception as exc:  # noqa: BLE001  (its own errors say which kernel feature is missing)
        return f"the kernel has no Landlock ({str(exc).splitlines()[0]})"
    return None


def _landlock(readable: Sequence[str]) -> str | None:
    """Read-only access to ``readable`` (`landlock_grants`) and nothing else: no writes, no
    execution, no other file."""
    why = landlock_available()
    if why:
        return why
    import landlock

    read = landlock.FSAccess.READ_FILE | landlock.FSAccess.READ_DIR
    # the binding judges a call by errno, not by its result: a stale errno from an earlier failed
    # call (a capability that does not exist, a path that is gone) would fail a call that worked
    try:
        ctypes.set_errno(0)
        ruleset = landlock.Ruleset()
        for path in readable:
            try:
                ctypes.set_errno(0)
                ruleset.allow(path, rules=read if os.path.isdir(path) else landlock.FSAccess.READ_FILE)
            except OSError:
                pass
        ctypes.set_errno(0)
        ruleset.apply()
        os.close(ruleset._fd)  # the rules are ours now; the descriptor is not needed
    except Exception as exc:  # noqa: BLE001
        return f"Landlock refused: {exc}"
    return None


def landlock_grants(allowed: Sequence[str], excluded: Sequence[str]) -> list[str]:
    """The paths Landlock grants for ``allowed`` when no mount namespace hides ``excluded`` (the
    site-packages and the secret folders that lie inside them): Landlock cannot take a subdirectory
    back, so a directory holding an excluded one is granted entry by entry, around it. Computed
    once, in the zygote."""
    excluded = [e.rstrip("/") for e in excluded]

    def under(path: str, top: str) -> bool:
        return path == top or path.startswith(top.rstrip("/") + "/")

    def grant(path: str) -> list[str]:
        if any(under(path, e) for e in excluded):
            return []
        if not any(under(e, path) for e in excluded) or not os.path.isdir(path):
            return [path]
        out: list[str] = []
        for entry in sorted(os.listdir(path)):
            out += grant(os.path.join(path, entry))
        return out

    grants: set[str] = set()
    for path in allowed:
        inside = [e for e in excluded if under(path, e)]
        if inside and all(_is_site_packages(e) for e in inside):
            grants.add(path)  # an allowed package (sympy) in a site-packages that is otherwise hidden
        else:
            grants.update(grant(path))
    return sorted(grants)


def _is_site_packages(path: str) -> bool:
    return os.path.basename(path) in ("site-packages", "dist-packages")


#: opening a file for anything but reading (0o20000000 is __O_TMPFILE: O_TMPFILE without O_DIRECTORY,
#: which reading a directory sets)
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND | 0o20000000
#: what CPython and sympy need to compute, import and print: everything else fails with EPERM
_ALLOWED_SYSCALLS = (
    "read", "readv", "pread64", "write", "writev", "close", "fstat", "stat", "lstat", "newfstatat",
    "statx", "lseek", "getdents64", "getdents", "getcwd", "readlink", "readlinkat", "access",
    "faccessat", "faccessat2", "dup", "dup2", "dup3", "mmap", "munmap", "mprotect", "mremap",
    "madvise", "brk", "rt_sigaction", "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "futex",
    "set_robust_list", "get_robust_list", "rseq", "set_tid_address", "getpid", "gettid", "getppid",
    "getuid", "geteuid", "getgid", "getegid", "getgroups", "getresuid", "getresgid", "getpgrp",
    "getpgid", "getsid", "clock_gettime", "clock_getres", "gettimeofday", "time", "clock_nanosleep",
    "nanosleep", "getrandom", "sysinfo", "uname", "sched_getaffinity", "sched_yield", "getrusage",
    "times", "getrlimit", "exit", "exit_group", "restart_syscall", "poll", "ppoll", "select",
    "pselect6", "getcpu", "membarrier",
)

#: fcntl commands an answer may use (`_FCNTL_ALLOWED`; F_SETFL without O_ASYNC): a descriptor's
#: flags and duplicates. Refused: F_SETOWN, F_SETOWN_EX, F_SETSIG and O_ASYNC (signal-driven I/O: the
#: kernel would send a signal of the answer's choosing to a process of its choosing whenever its
#: pipes change, the grader reading them included), leases, notifications, locks, seals, pipe sizes
_F_SETFL, _O_ASYNC = 4, getattr(os, "O_ASYNC", 0o20000)
_FCNTL_ALLOWED = {
    "F_DUPFD": 0, "F_GETFD": 1, "F_SETFD": 2, "F_GETFL": 3, "F_GETLK": 5, "F_GETOWN": 9, "F_GETSIG": 11,
    "F_GETOWN_EX": 16, "F_GETLEASE": 1025, "F_DUPFD_CLOEXEC": 1030, "F_GETPIPE_SZ": 1032, "F_GET_SEALS": 1034,
}


def seccomp_available() -> str | None:
    try:
        import pyseccomp  # noqa: F401
    except (ImportError, OSError, AttributeError, TypeError) as exc:
        return f"libseccomp or its 'pyseccomp' binding is missing ({type(exc).__name__})"
    return None


def _seccomp() -> str | None:
    """Load the system-call allowlist (`seccomp_program`). Refused calls fail with EPERM, so the
    answer sees a Python error rather than a silent death."""
    program = seccomp_program()
    if isinstance(program, str):
        return program
    return _load_bpf(program)


@functools.cache
def seccomp_program() -> bytes | str:
    """The allowlist as the classic BPF program libseccomp compiles it to (what ``seccomp_load``
    would load), or why it could not be had. Compiled once per process: the zygote calls it before
    it forks (:func:`lagrade.answer.jail.child.prepare_zygote`), so each child only loads it
    (`_load_bpf`) instead of building the filter again, about 1.3 ms of CPU an answer."""
    why = seccomp_available()
    if why:
        return why
    try:
        f = _seccomp_filter()
        fd = os.memfd_create("lagrade-seccomp", os.MFD_CLOEXEC)
        try:
            f.export_bpf(_Fileno(fd))
            program, offset = bytearray(), 0
            while chunk := os.pread(fd, 1 << 16, offset):
                program += chunk
                offset += len(chunk)
        finally:
            os.close(fd)
    except Exception as exc:  # noqa: BLE001
        return f"seccomp refused: {exc}"
    if not program or len(program) % _BPF_INSTRUCTION or len(program) // _BPF_INSTRUCTION > 0xFFFF:
        return f"seccomp refused: libseccomp exported a program of {len(program)} bytes"
    return bytes(program)


class _Fileno:
    """What pyseccomp's ``export_bpf`` writes to: anything with a ``fileno()``."""

    def __init__(self, fd: int) -> None:
        self.fd = fd

    def fileno(self) -> int:
        return self.fd


#: a classic BPF instruction (``struct sock_filter``: code, jt, jf, k) is 8 bytes
_BPF_INSTRUCTION = 8
_PR_SET_NO_NEW_PRIVS, _PR_SET_SECCOMP, _SECCOMP_MODE_FILTER = 38, 22, 2


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def _load_bpf(program: bytes) -> str | None:
    """Install ``program`` as this process's seccomp filter, as libseccomp's ``seccomp_load`` does
    (no_new_privs first, then the filter, no flags); None once it is in force."""
    libc = _libc()
    if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return f"seccomp refused: no_new_privs ({os.strerror(ctypes.get_errno())})"
    buffer = ctypes.create_string_buffer(program, len(program))
    fprog = _SockFprog(len(program) // _BPF_INSTRUCTION, ctypes.cast(buffer, ctypes.c_void_p))
    if libc.prctl(_PR_SET_SECCOMP, _SECCOMP_MODE_FILTER, ctypes.byref(fprog), 0, 0) != 0:
        return f"seccomp refused: {os.strerror(ctypes.get_errno())}"
    return None


def _seccomp_filter():
    """The allowlist as a libseccomp filter (not yet loaded)."""
    import pyseccomp as sc

    f = sc.SyscallFilter(defaction=sc.ERRNO(errno.EPERM))
    for name in _ALLOWED_SYSCALLS:
        try:
            f.add_rule(sc.ALLOW, name)
        except (RuntimeError, OSError, ValueError):  # not a call of this architecture
            pass
    for call in ("fcntl", "fcntl64"):  # fcntl64: 32-bit machines' name for the same call
        try:
            for command in _FCNTL_ALLOWED.values():
                f.add_rule(sc.ALLOW, call, sc.Arg(1, sc.EQ, command))
            f.add_rule(sc.ALLOW, call, sc.Arg(1, sc.EQ, _F_SETFL), sc.Arg(2, sc.MASKED_EQ, _O_ASYNC, 0))
        except (RuntimeError, OSError, ValueError):  # not a call of this architecture
            pass
    read_only = sc.Arg(2, sc.MASKED_EQ, _WRITE_FLAGS, 0)
    f.add_rule(sc.ALLOW, "openat", read_only)
    try:
        f.add_rule(sc.ALLOW, "open", sc.Arg(1, sc.MASKED_EQ, _WRITE_FLAGS, 0))
    except (RuntimeError, OSError, ValueError):
        pass
    for request in (0x5401, 0x5413):  # TCGETS and TIOCGWINSZ: isatty() and terminal size
        f.add_rule(sc.ALLOW, "ioctl", sc.Arg(1, sc.EQ, request))
    f.add_rule(sc.ALLOW, "prlimit64", sc.Arg(2, sc.EQ, 0))  # reading a limit, never setting one
    return f


def die_with_parent(leave_if_orphaned: bool = True) -> None:
    """Be killed when the parent process ends (``PR_SET_PDEATHSIG``), or leave now if it already has
    (a grader with its coordinator, a zygote with its grader). A PID namespace's first process has
    no parent in its namespace to check, so it only sets the signal."""
    try:
        _libc().prctl(1, signal.SIGKILL, 0, 0, 0)
    except Exception:  # noqa: BLE001
        pass
    if leave_if_orphaned and os.getppid() == 1:
        os._exit(0)


def missing_minimum(active: Iterable[str]) -> str | None:
    """Why a class may not be graded with these layers (None if it may): a file view without the
    key (the mount namespace or Landlock) and the system-call allowlist, no_new_privs and limits."""
    active = set(active)
    lacking = [k for k in MINIMUM if k not in active]
    if not active & set(MINIMUM_FS):
        lacking.insert(0, "mount or landlock")
    return f"the jail lacks {', '.join(lacking)}" if lacking else None


DESCRIPTIONS = {
    "uid": "another uid than the grader's (one per answer as root; a user namespace otherwise)",
    "mount": "a file tree of Python, sympy and system libraries only: no problems, references, cache",
    "pid": "its own process numbers: the grader's processes cannot be named",
    "network": "an empty network namespace",
    "no_new_privs": "no set-uid program can give privileges back",
    "limits": "CPU, memory, file size, descriptors, no new processes",
    "landlock": "the kernel's file allowlist: read-only Python and libraries, no writes, no execution",
    "seccomp": "a system-call allowlist: no exec, ptrace, sockets, signals, writes",
}
