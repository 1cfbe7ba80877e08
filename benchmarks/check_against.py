"""One `lagrade check` of each reference solution by this checkout and by a pinned older commit,
interleaved: what the changes since that commit cost a check, all of them together (each round's
steps were measured against the commit before; small steps add up unseen unless the pin stays put).

    python benchmarks/check_against.py                          # against the pin (PIN below), every problem
    python benchmarks/check_against.py --against ad7372a 12.14 12.22 12.43
    python benchmarks/check_against.py --old /tmp/old/bin/lagrade   # an installation's script instead

The old commit is checked out once as a detached git worktree outside this tree (``--worktrees``,
default the system's temporary folder) and run from its sources by this Python, as
``PYTHONPATH=OLD/src python -m lagrade check ...``; both build their reference cache first
(``lagrade cache build``: the cache's entries are keyed by the sources, so the two never share one).
Then each problem is checked by the old and the new code in turn, with the import floor
``python -c "import sympy, numpy, scipy.integrate"`` beside them, so that all three see the same load.

Measured for each run: wall time; the CPU of the check's own process (``wait4``: the critical path,
since the answer's zygote imports sympy on the other core meanwhile); and the CPU of all its
processes (this script is the subreaper of the zygote the check leaves behind). On a loaded machine
the wall times say little: compare the CPU ratios. Prints the medians, the ratios of the summed
figures new/old, and each against the floor.
"""

from __future__ import annotations

import argparse
import ctypes
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PIN = "fc86fae"
"""The pinned commit (main two rounds before issue 48, docs/performance.md): move it only on purpose."""

FLOOR = [sys.executable, "-c", "import sympy, numpy, scipy.integrate"]


def worktree(commit: str, where: Path) -> Path:
    """A detached checkout of ``commit`` (made once, never modified), outside this tree; ``commit``
    may also name a checkout that exists."""
    if (Path(commit) / "src" / "lagrade").is_dir():
        return Path(commit)
    full = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--verify", f"{commit}^{{commit}}"],
                          capture_output=True, text=True, check=True).stdout.strip()
    path = where / f"lagrade-{full[:12]}"
    if not (path / "src" / "lagrade").is_dir():
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(path), full],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return path


def run(cmd: list[str], env: dict[str, str] | None = None) -> tuple[float, float, float]:
    """Wall seconds, CPU of the process itself (and what it reaped), CPU of all it left behind too."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _, _, usage = os.wait4(proc.pid, 0)
    proc.returncode = 0  # reaped here
    wall = time.perf_counter() - start
    own = usage.ru_utime + usage.ru_stime
    rest = 0.0
    while True:  # the zygote and anything else orphaned: reparented to this subreaper
        try:
            _, _, usage = os.wait4(-1, 0)
        except ChildProcessError:
            break
        rest += usage.ru_utime + usage.ru_stime
    return wall, own, own + rest


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*", help="problems (default: every reference solution)")
    ap.add_argument("--against", default=PIN, help=f"the older commit, or a checkout of it (default: the pin, {PIN})")
    ap.add_argument("--old", help="another installation's lagrade script, instead of --against")
    ap.add_argument("--worktrees", type=Path, default=Path(tempfile.gettempdir()),
                    help="where the old commit is checked out (outside this tree)")
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--markdown", action="store_true", help="one Markdown row for docs/performance.md")
    ap.add_argument("--json", type=Path, help="also write the figures to this file (benchmarks/pinned.py reads it)")
    args = ap.parse_args()
    ctypes.CDLL(None).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    ids = args.ids or sorted(p.name for p in (ROOT / "reference_solutions").iterdir() if (p / "answer.py").exists())
    new_env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    if args.old:
        old_cmd, old_env, label = [args.old], None, args.old
    else:
        tree = worktree(args.against, args.worktrees)
        old_cmd, old_env, label = [sys.executable, "-m", "lagrade"], {**os.environ, "PYTHONPATH": str(tree / "src")}, args.against
    new_cmd = [sys.executable, "-m", "lagrade"]
    for cmd, env in ((old_cmd, old_env), (new_cmd, new_env)):
        subprocess.run([*cmd, "cache", "build", *ids], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=False, env=env)
    floor, old, new = [], [], []
    for _ in range(args.repeats):
        for pid in ids:
            answer = str(ROOT / "reference_solutions" / pid / "answer.py")
            floor.append(run(FLOOR))
            old.append(run([*old_cmd, "check", pid, answer], old_env))
            new.append(run([*new_cmd, "check", pid, answer], new_env))

    def total(rows, i):
        return sum(r[i] for r in rows)

    what = ("wall", "CPU of the check's process", "CPU of all its processes")
    print(f"{len(ids)} problems x {args.repeats}, against {label}:")
    for i, name in enumerate(what):
        per = statistics.median(b[i] / a[i] for a, b in zip(old, new) if a[i] > 0)
        print(f"  {name}: old median {statistics.median(r[i] for r in old):.3f} s, new "
              f"{statistics.median(r[i] for r in new):.3f} s; new/old {total(new, i) / total(old, i):.3f} of the "
              f"sums ({per:.3f} per check, median); over the floor: old {total(old, i) / total(floor, i):.2f}x, "
              f"new {total(new, i) / total(floor, i):.2f}x")
    if args.json is not None:
        args.json.write_text(json.dumps({key: {"old": total(old, i) / total(floor, i), "new": total(new, i) / total(floor, i),
                                               "new_over_old": total(new, i) / total(old, i),
                                               "floor_seconds": total(floor, i) / len(floor)}
                                         for i, key in enumerate(("wall", "own_cpu", "all_cpu"))}))
    if args.markdown:
        print(f"| `python benchmarks/check_against.py --against {label} {' '.join(args.ids)}` | "
              + "; ".join(f"{name}: new/old {total(new, i) / total(old, i):.3f}, over the floor old "
                          f"{total(old, i) / total(floor, i):.2f}x new {total(new, i) / total(floor, i):.2f}x"
                          for i, name in enumerate(what)) + " |")


if __name__ == "__main__":
    main()
