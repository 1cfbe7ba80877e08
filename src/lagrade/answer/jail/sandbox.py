"""Run a student's ``answer.py`` in a jailed child and get its values back as data: the grader's side.

The barrier is the operating system: the child is forked from the clean zygote
(:mod:`lagrade.answer.jail.zygote`, which never held a reference) and confines itself with the kernel's
layers (:mod:`lagrade.answer.jail.kernel`) before it reads the answer (:mod:`lagrade.answer.jail.child` is
what runs there). This module screens the file, asks the zygote for a child, and collects the
outcome: nothing the child sends is unpickled or evaluated, and a report without the run's token
was not written by our child code.
"""


from __future__ import annotations

import functools
import json
import os
import secrets
import selectors
import signal
import sys
import time
import weakref
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ValidationError

from lagrade.answer.jail.rebuild import EncodedValue
from lagrade.answer.jail.screen import (
    MAX_SOURCE_BYTES,
    AnswerProblem,
    screen_source,
)

from lagrade.answer.jail.child import JAIL_FAILED, STDOUT_KEEP, ChildReport, SandboxLimits, reap_child

__all__ = ["AnswerProblem", "EncodedValue", "SandboxLimits", "SandboxOutcome", "run_answer_file", "start_answer_source"]


class SandboxOutcome(BaseModel):
    """What running an answer file produced: encoded values, problems for the student, status."""

    values: dict[str, EncodedValue] = {}
    problems: list[AnswerProblem] = []
    stdout: str = ""
    status: Literal["ok", "error", "timeout", "memory", "crashed", "rejected"]


# =========================================================================== parent side

def run_answer_file(path: Path, wanted: Sequence[str], limits: SandboxLimits = SandboxLimits()) -> SandboxOutcome:
    """Screen and run ``path``; return the values bound to the names in ``wanted``, as text."""
    return start_answer_file(path, wanted, limits).wait()


class RunningAnswer:
    """An answer file running in its sandbox child (or already refused): ``wait()`` gives the outcome.

    Starting it and waiting are separate so that a one-off check can import the grading code while
    the child runs: two cores, two things at once."""

    def __init__(self, outcome: SandboxOutcome | None = None, finish=None, abandon=None):
        self._outcome, self._finish = outcome, finish
        # never waited for (the grading stopped first): the pipes from the child are closed when this
        # is collected, not kept open for the life of a grader process
        self._abandon = weakref.finalize(self, abandon) if abandon is not None else None

    def wait(self) -> SandboxOutcome:
        if self._outcome is None:
            if self._abandon is not None:
                self._abandon.detach()
            self._outcome = self._finish()
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
    return start_answer_source(source, path, wanted, limits)


def start_answer_source(source: str, path: Path, wanted: Sequence[str],
                        limits: SandboxLimits = SandboxLimits()) -> RunningAnswer:
    """Screen ``source`` and start it in a sandbox child as if it were the file ``path``: an answer
    held as Python text inside another file (a notebook's code cells, `lagrade.answer.reading.notebook`)
    goes through the same screen and the same jail as an ``answer.py``."""
    path = Path(path)
    name = path.name
    problems = screen_source(source, name) if TRIPWIRES else []
    if problems:
        syntax = any(p.message.startswith(("syntax error", "cannot parse")) for p in problems)
        return RunningAnswer(SandboxOutcome(status="error" if syntax else "rejected", problems=problems))
    from lagrade.answer.jail import zygote

    return RunningAnswer(*(None, *_start_in_jail(zygote.current(), source, path, list(wanted), limits)))


#: how much longer the wall-clock bound of an answer is once its coordinator lowered its priority
#: (:func:`lagrade.uses.bulk.worker.watch`): at the lowest CPU weight it gets its CPU seconds later, and
#: its bound is its CPU time; the wall clock stays a backstop
LOWERED_WALL_FACTOR = 3


#: the Python-level screen, restricted builtins and audit hook: tripwires that give clear messages.
#: Tests switch them off to show that the operating system's layers hold on their own.
TRIPWIRES = True


def _start_in_jail(zyg, source: str, path: Path, wanted: list[str], limits: SandboxLimits):
    """Have the zygote fork the child; return the function that collects its outcome.

    The request is sent from a thread: a zygote started with the check is still importing sympy
    when the answer is read, and the caller meanwhile loads the references on the other core."""
    import threading

    from lagrade.answer.jail.zygote import ZygoteError

    name = path.name
    token = secrets.token_hex(16)  # a report without it was not written by our child code
    job = json.dumps({"source": source, "path": str(path), "name": name, "wanted": wanted,
                      "limits": limits.model_dump(), "token": token, "tripwires": TRIPWIRES}).encode("utf-8")
    job_fd = _job_file(job)
    result_r, result_w = os.pipe()
    out_r, out_w = os.pipe()
    spawned: dict[str, Any] = {}

    def spawn() -> None:
        try:
            spawned["pid"] = zyg.spawn((result_w, out_w, job_fd))
            spawned["at"] = time.monotonic()
        except Exception as exc:  # noqa: BLE001  (told to the student as a sandbox failure, in finish)
            spawned["error"] = exc if isinstance(exc, ZygoteError) else f"{type(exc).__name__}: {exc}"
        finally:
            os.close(result_w)
            os.close(out_w)
            os.close(job_fd)

    thread = threading.Thread(target=spawn, name="lagrade-spawn", daemon=True)
    thread.start()

    pipes = [result_r, out_r]

    def close_pipes() -> None:  # once, whichever comes first: the outcome read, a bound, or abandon
        while pipes:
            os.close(pipes.pop())

    def finish() -> SandboxOutcome:
        try:
            thread.join()
            if "pid" not in spawned:
                why = neutral_paths(str(spawned.get("error")), path)
                return SandboxOutcome(status="crashed", problems=[AnswerProblem(
                    file=name, line=None, message=f"the sandbox could not run the answer ({why}); "
                                                  "please report it to your instructor")])
            return _collect(spawned["pid"], name, wanted, limits, token, result_r, out_r, spawned["at"], zyg.reap,
                            zyg.lowered, path=path)
        finally:  # also when the grading's bound stops the reading: the pipes never outlive it
            close_pipes()

    def abandon() -> None:
        """Never waited for: close the pipes (the child, bounded by its limits, is reaped by the zygote)."""
        thread.join()
        close_pipes()

    return finish, abandon


def _job_file(job: bytes) -> int:
    """A descriptor holding ``job`` (the answer's source, path, names, limits and token), read from
    its start by the child after it is forked: the zygote passes it on without reading it, so no
    answer's bytes are ever in the memory the next answers are forked from (issue 43). An anonymous
    memory file where there is one (Linux), else an unlinked temporary file: the whole job is
    written before the zygote is asked, so nothing waits on a reader."""
    if hasattr(os, "memfd_create"):
        fd = os.memfd_create("lagrade-answer", getattr(os, "MFD_CLOEXEC", 0))
    else:
        import tempfile

        with tempfile.TemporaryFile() as fh:
            fd = os.dup(fh.fileno())
    try:
        view = memoryview(job)
        while view:
            view = view[os.write(fd, view):]
        os.lseek(fd, 0, os.SEEK_SET)
    except BaseException:
        os.close(fd)
        raise
    return fd


def _collect(pid: int, name: str, wanted: list[str], limits: SandboxLimits, token: str, result_r: int, out_r: int,
             started: float, reap=None, lowered=None, path: Path | None = None) -> SandboxOutcome:
    """``lowered(pid)``: whether the child now runs at a lower priority than its zygote (then its
    wall-clock bound is :data:`LOWERED_WALL_FACTOR` times as long). Every text of the child's (its
    output, its problems) has the grader's paths replaced (:func:`neutral_paths`)."""
    result, output = bytearray(), bytearray()
    timed_out, overflow, stretched = _read(pid, limits, result_r, out_r, started, result, output, lowered)
    wall = limits.wall_seconds * (LOWERED_WALL_FACTOR if stretched else 1)
    exit_status, cpu_used = (reap or reap_child)(pid, kill=timed_out or overflow, deadline=started + wall + 2)
    stdout = neutral_paths(output.decode("utf-8", "replace"), path)[:STDOUT_KEEP]

    def outcome(status: str, message: str) -> SandboxOutcome:
        return SandboxOutcome(status=status, stdout=stdout, problems=[AnswerProblem(file=name, line=None, message=message)])

    if timed_out:
        return outcome("timeout", f"ran longer than {wall:g} s (an infinite loop, or a computation that is too heavy?)")
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
        report = ChildReport.model_validate(json.loads(bytes(result).decode("utf-8")))
        if not secrets.compare_digest(report.token, token):
            raise ValueError("forged report")
    except (ValueError, RecursionError, ValidationError, UnicodeDecodeError):
        code = os.WEXITSTATUS(exit_status) if os.WIFEXITED(exit_status) else -1
        if code == JAIL_FAILED:  # the child's own words, before it ran anything of the answer's
            why = stdout.strip().splitlines()[0][:300] if stdout.strip() else "the jail could not be built"
            return outcome("crashed", f"the answer was not run: {why}; please report it to your instructor")
        return outcome("crashed", f"the answer could not be run (the sandbox stopped with code {code} and no result)")
    values = {k: v for k, v in report.values.items() if k in wanted}
    problems = [p.model_copy(update={"file": name, "message": neutral_paths(p.message, path)})
                for p in report.problems[:50]]
    return SandboxOutcome(values=values, problems=problems, stdout=stdout, status=report.status)



def neutral_paths(text: str, answer: Path | str | None = None) -> str:
    """``text`` (what a student is shown of an answer's run: its output, an error, a refusal) with
    the grader's paths replaced by neutral names: the answer's own path by its file name, and where
    Python, the packages, lagrade and its hidden data are installed by ``<python>``,
    ``<site-packages>``, ``<sympy>``, ``<lagrade>``, ``<hidden>``... A warning or a "Permission
    denied" otherwise tells the student where the grader keeps its files."""
    pairs = list(_install_names())
    if answer is not None:
        answer = Path(answer)
        pairs = [(p, answer.name) for p in _spellings(str(answer))] + \
            [(p, ".") for p in _spellings(str(answer.parent)) if _specific(p)] + pairs
    for real, name in sorted(pairs, key=lambda pair: -len(pair[0])):
        if real in text:
            text = text.replace(real, name)
    return text


def _spellings(path: str) -> set[str]:
    return {p for p in (path, os.path.abspath(path), os.path.realpath(path)) if p}


def _specific(path: str) -> bool:
    """A path naming an installation, not a system-wide folder (``/``, ``/usr``, ``/opt``, ``/usr/local``)."""
    return len(Path(path).parts) > 2 and path.rstrip("/") not in ("/usr/local", "/usr/lib", "/usr/lib64", "/usr/share")


@functools.cache
def _install_names() -> tuple[tuple[str, str], ...]:
    """(path, neutral name) for every place the grader's files are installed, longest first."""
    import sysconfig

    import mpmath
    import sympy

    from lagrade.answer.jail.child import secret_dirs

    found: dict[str, str] = {}

    def name(path: str | None, label: str) -> None:
        if path:
            for spelling in _spellings(path):
                if _specific(spelling):
                    found.setdefault(spelling.rstrip("/"), label)

    for secret in secret_dirs():
        name(secret, "<hidden>")
    name(str(Path(__file__).resolve().parents[2]), "<lagrade>")  # the package: lagrade/answer/jail/sandbox.py
    for module, label in ((sympy, "<sympy>"), (mpmath, "<mpmath>")):
        name(os.path.dirname(module.__file__ or ""), label)
    paths = sysconfig.get_paths()
    for key, label in (("purelib", "<site-packages>"), ("platlib", "<site-packages>"), ("stdlib", "<python>"),
                       ("platstdlib", "<python>")):
        name(paths.get(key), label)
    for prefix in (sys.prefix, sys.exec_prefix, sys.base_prefix, sys.base_exec_prefix):
        name(prefix, "<python>")
    name(os.path.expanduser("~"), "~")
    return tuple(sorted(found.items(), key=lambda pair: -len(pair[0])))


def _read(pid: int, limits: SandboxLimits, result_r: int, out_r: int, started: float, result: bytearray,
          output: bytearray, lowered) -> tuple[bool, bool, bool]:
    """Read the child's result and output until both pipes close or its wall-clock bound passes:
    (timed out, too much output, bound stretched because the child was lowered)."""
    deadline = started + limits.wall_seconds
    stretched = timed_out = overflow = False
    with selectors.DefaultSelector() as sel:
        sel.register(result_r, selectors.EVENT_READ)
        sel.register(out_r, selectors.EVENT_READ)
        while sel.get_map() and not overflow:
            remaining = deadline - time.monotonic()
            if remaining <= 0 and not stretched and lowered is not None and _asked(lowered, pid):
                stretched = True
                deadline = started + limits.wall_seconds * LOWERED_WALL_FACTOR
                continue
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
    return timed_out, overflow, stretched


def _asked(lowered, pid: int) -> bool:
    try:
        return bool(lowered(pid))
    except Exception:  # noqa: BLE001  (a zygote that cannot tell: the bound stays as it was)
        return False
