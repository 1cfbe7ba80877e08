"""The "read as" preview, read in a worker process of its own: never in the web process.

A preview parses what a student is typing, as often as they type: sympy may take unbounded time or
memory on some text (``((3*g*x_d)^2)^2...`` squared thirty times builds ``3**(2**30)``), holding the
GIL of whatever process reads it. So the reading happens in one spawned process, one preview at a
time, under a memory bound (``RLIMIT_AS``) and a wall-clock bound: a preview that overruns gets its
one-line error, and its process is killed and started again for the next preview. The web process
keeps answering (``/healthz``, checks, pages) meanwhile.
"""

from __future__ import annotations

import multiprocessing
import queue
import threading
import time
from concurrent.futures import Future
from pathlib import Path

#: a spawned process: the web process has threads, and a fork of it would copy their locks
_CTX = multiprocessing.get_context("spawn")


class PreviewWorker:
    """Reads previews in a process of its own: ``worker(problem_id, part, value) -> dict``."""

    def __init__(self, problems_dirs: tuple[Path, ...] = (), seconds: float = 5.0, memory_mb: int = 2048) -> None:
        self.problems_dirs, self.seconds, self.memory_mb = tuple(problems_dirs), seconds, memory_mb
        self._proc = None
        self._conn = None
        # one thread starts the process and reads every preview, one at a time (previews use at most
        # one core): the process dies with the thread that started it (PR_SET_PDEATHSIG), so that
        # thread lives as long as the server
        self._asks: queue.Queue = queue.Queue()
        self._thread: threading.Thread | None = None
        self._thread_lock = threading.Lock()

    def __call__(self, pid: str, part: str, value) -> dict:
        with self._thread_lock:
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="lagrade-preview", daemon=True)
                self._thread.start()
        answer: Future = Future()
        self._asks.put(((pid, part, value), answer))
        return answer.result()

    def _run(self) -> None:
        while True:
            ask = self._asks.get()
            if ask is None:
                self._kill()
                return
            args, answer = ask
            try:
                answer.set_result(self._read(*args))
            except Exception as exc:  # noqa: BLE001
                answer.set_result({"part": args[1], "error": f"no preview ({exc})"})

    def _read(self, pid: str, part: str, value) -> dict:
        self._ensure()
        try:
            self._conn.send((pid, part, value))
            if self._conn.poll(self.seconds):
                return self._conn.recv()
        except (EOFError, OSError):
            self._kill()
            return {"part": part, "error": "the preview could not be read (its reader stopped); a check still "
                                           "reads it"}
        self._kill()  # overran: the next preview gets a fresh reader
        return {"part": part, "error": f"reading this took longer than {self.seconds:g} s; no preview (a check "
                                       "still reads it, within the assignment's limits)"}

    def _ensure(self) -> None:
        if self._proc is not None and self._proc.is_alive():
            return
        self._kill()
        here, there = _CTX.Pipe()
        self._proc = _CTX.Process(target=_serve, args=(there, self.problems_dirs, self.memory_mb),
                                  name="lagrade-preview", daemon=True)
        self._proc.start()
        there.close()
        self._conn = here
        # the first answer includes starting up (imports, the problem): not counted against the bound
        here.send(None)
        if not here.poll(120):
            self._kill()
            raise RuntimeError("the preview process did not start in 120 s")
        here.recv()

    def _kill(self) -> None:
        proc, conn, self._proc, self._conn = self._proc, self._conn, None, None
        if conn is not None:
            conn.close()
        if proc is not None:
            proc.kill()
            proc.join(5)

    def stop(self) -> None:
        if self._thread is not None:
            self._asks.put(None)
            self._thread.join(10)


def _serve(conn, problems_dirs: tuple[Path, ...], memory_mb: int) -> None:
    """The worker's loop: a ``(problem id, part, value)`` in, the preview's dict out, until EOF."""
    import resource

    from lagrade.answer.jail.kernel import die_with_parent

    die_with_parent()
    try:
        resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
    except (ValueError, OSError):
        pass
    from lagrade.problem.library import load_problem
    from lagrade.uses.server.answers import preview

    problems: dict = {}
    while True:
        try:
            msg = conn.recv()
        except (EOFError, OSError):
            return
        if msg is None:
            conn.send("ready")
            continue
        pid, part, value = msg
        started = time.monotonic()
        try:
            if pid not in problems:
                problems[pid] = load_problem(pid, problems_dirs)
            out = preview(problems[pid], part, value)
        except MemoryError:
            out = {"part": part, "error": f"reading this needs more than {memory_mb} MB; no preview"}
        except Exception as exc:  # noqa: BLE001  (a preview that fails says so in one line)
            out = {"part": part, "error": f"the preview could not read this ({type(exc).__name__})"}
        out.setdefault("seconds", round(time.monotonic() - started, 3))
        conn.send(out)
