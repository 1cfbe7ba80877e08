"""How many answers a platform's container can grade at once: as many as its memory holds.

A Gradescope submission of several problems is graded by a pool of grader processes, one answer
each. Gradescope's default container has 768 MB for everything, and each answer may use its memory
bound on top of its grader: three large answers graded at once peaked at 1070 MiB there. So the pool
is sized to the container's memory (its cgroup's limit, else the machine's RAM), not to its cores.

Measured (``lagrade gradescope run`` of 12.14, 12.43 and 12.22, PSS of every process, LAGRADE_CACHE
off): the command itself 58 MiB; per grader 152 MiB (its process 92, its zygote 30, an answer's
child before the answer's own data 30). The figures below keep a margin over them.
"""

from __future__ import annotations

import os
from pathlib import Path

#: MiB the coordinating process holds (measured 58 PSS, 80 RSS)
BASE_MB = 100
#: MiB a grader holds besides its answer's own memory: the grader, its zygote, the child (measured 152)
GRADER_MB = 200
#: a cgroup limit at or above this is "no limit" (cgroup v1 writes 2**63 rounded down to a page)
_UNLIMITED = 2**60


def _read_limit(path: Path) -> int | None:
    try:
        text = path.read_text().strip()
    except OSError:
        return None
    if not text.isdigit():  # cgroup v2 writes "max"
        return None
    value = int(text)
    return value if 0 < value < _UNLIMITED else None


def _own_paths(proc_cgroup: Path) -> tuple[str | None, str | None]:
    """This process's cgroup (v2, v1 memory controller) as /proc/self/cgroup names them."""
    v2 = v1 = None
    try:
        lines = proc_cgroup.read_text().splitlines()
    except OSError:
        return None, None
    for line in lines:
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        if parts[0] == "0" and parts[1] == "":
            v2 = parts[2]
        elif "memory" in parts[1].split(","):
            v1 = parts[2]
    return v2, v1


def _upwards(top: Path, own: str | None, name: str) -> list[Path]:
    """``name`` in the cgroup ``own`` under ``top`` and in each of its parents up to ``top``."""
    found = [top / name]
    if own:
        d = top / own.strip("/")
        while d != top and top in d.parents:
            found.append(d / name)
            d = d.parent
    return found


def total_ram(meminfo: Path = Path("/proc/meminfo")) -> int | None:
    """The machine's RAM in bytes (``MemTotal``), or None where there is no /proc/meminfo."""
    try:
        for line in meminfo.read_text().splitlines():
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return None
    return None


def memory_limit(cgroup_root: Path = Path("/sys/fs/cgroup"), proc_cgroup: Path = Path("/proc/self/cgroup"),
                 meminfo: Path = Path("/proc/meminfo")) -> int | None:
    """The bytes this process's container may use: the smallest limit of its memory cgroup and the
    cgroups above it (v2 ``memory.max``, v1 ``memory.limit_in_bytes``), else the machine's RAM; None
    when neither can be read."""
    v2, v1 = _own_paths(proc_cgroup)
    files = [*_upwards(cgroup_root, v2, "memory.max"),
             *_upwards(cgroup_root / "memory", v1, "memory.limit_in_bytes")]
    limits = [v for f in files if (v := _read_limit(f)) is not None]
    ram = total_ram(meminfo)
    candidates = [*limits, *([ram] if ram else [])]
    return min(candidates) if candidates else None


def pool_size(jobs: int, answer_mb: int, memory_bytes: int | None, cores: int | None) -> int:
    """Grader processes for ``jobs`` answers of at most ``answer_mb`` MB each in ``memory_bytes``: as
    many as fit beside the coordinating process, no more than the cores or the answers, at least one
    (one answer at a time is what a container too small for two can still do)."""
    most = max(1, min(cores or 1, jobs))
    if memory_bytes is None:
        return most
    fit = (memory_bytes / 2**20 - BASE_MB) // (GRADER_MB + answer_mb)
    return int(max(1, min(most, fit)))
