"""Run one lagrade command for the red-team suite and account for every process it leaves behind.

    python _launch.py RESULT.json BOUND_SECONDS -- COMMAND...

This process becomes a child subreaper (PR_SET_CHILD_SUBREAPER), so whatever the command's process
tree orphans (a double fork, a detached fork bomb) is re-parented here instead of to init. It waits
for the command up to BOUND_SECONDS (then kills the command's whole tree), then lists the processes
still alive below it, kills them, reaps everything and writes RESULT.json:
{"returncode", "seconds", "timed_out", "leftovers": [cmdline, ...], "max_rss_bytes"}.
The command's stdout and stderr are this process's own. It only ever signals its own descendants.
"""

from __future__ import annotations

import ctypes
import json
import os
import resource
import signal
import subprocess
import sys
import time

PR_SET_CHILD_SUBREAPER = 36


def _children_map() -> dict[int, list[int]]:
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as fh:
                fields = fh.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if fields[0] == "Z":  # exited, not reaped yet: nothing runs
            continue
        children.setdefault(int(fields[1]), []).append(int(entry))
    return children


def descendants() -> list[int]:
    children, found, todo = _children_map(), [], [os.getpid()]
    while todo:
        for pid in children.get(todo.pop(), []):
            found.append(pid)
            todo.append(pid)
    return found


def cmdline(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as fh:
            return fh.read().replace(b"\0", b" ").decode("utf-8", "replace").strip()
    except OSError:
        return "?"


def kill_descendants() -> None:
    for _ in range(20):  # a fork bomb may fork while we kill: a few rounds
        pids = descendants()
        if not pids:
            return
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        reap()
        time.sleep(0.05)


def reap() -> None:
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


def main() -> None:
    result_path, bound = sys.argv[1], float(sys.argv[2])
    command = sys.argv[sys.argv.index("--") + 1:]
    libc = ctypes.CDLL("libc.so.6", use_errno=True)
    libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
    start = time.monotonic()
    proc = subprocess.Popen(command)
    timed_out = False
    try:
        returncode = proc.wait(timeout=bound)
    except subprocess.TimeoutExpired:
        timed_out = True
        kill_descendants()
        returncode = proc.wait()
    seconds = time.monotonic() - start
    time.sleep(0.3)  # processes on their way out
    reap()
    leftovers = [cmdline(pid) for pid in descendants()]
    kill_descendants()
    reap()
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(result_path, "w") as fh:
        json.dump({"returncode": returncode, "seconds": seconds, "timed_out": timed_out, "leftovers": leftovers,
                   "max_rss_bytes": usage.ru_maxrss * 1024}, fh)


if __name__ == "__main__":
    main()
