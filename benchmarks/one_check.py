"""One `lagrade check` against the floor `python -c "import sympy, numpy, scipy.integrate"`.

Target (issue 7): the wall time of checking a reference solution is at most 1.5x the floor, on
every problem. Floor and check runs are interleaved, so both see the same machine load; each
figure is the median of --repeats runs. The reference derivations are built first with
``lagrade cache build`` (what an instructor runs once); the "no cache" column is the same check with
``LAGRADE_CACHE=off``, for comparison. The console script is the one installed next to this Python
(a version manager's shim on PATH would add its own start-up time to the check, not to the floor).

Some reference solutions compute with sympy themselves (``simplify``, ``solve``, ``limit``) as a
student's file may: the "answer s" column is the time the file's own code takes (run in a process
that has imported sympy already), which every grader pays, and "net" is the ratio without it.

    python benchmarks/one_check.py                 # every problem
    python benchmarks/one_check.py 12.14 12.43     # some
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FLOOR = [sys.executable, "-c", "import sympy, numpy, scipy.integrate"]
OWN = ("import sympy, sys, time\nsource = open(sys.argv[1]).read()\nstart = time.perf_counter()\n"
       "exec(compile(source, sys.argv[1], 'exec'), {'__name__': '__answer__'})\nprint(time.perf_counter() - start)")


def answer_seconds(path: Path) -> float:
    out = subprocess.run([sys.executable, "-c", OWN, str(path)], capture_output=True, text=True, check=False)
    try:
        return float(out.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return 0.0


def run(cmd: list[str], env: dict | None = None) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False, env=env)
    return time.perf_counter() - start


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    script = Path(sys.executable).with_name("lagrade")
    lagrade = [str(script)] if script.exists() else [sys.executable, "-m", "lagrade"]
    ids = args.ids or sorted(p.name for p in (ROOT / "reference_solutions").iterdir() if p.is_dir())
    subprocess.run([*lagrade, "cache", "build", *ids], stdout=subprocess.DEVNULL, check=True)
    cold_env = {**os.environ, "LAGRADE_CACHE": "off"}
    rows = []
    print(f"{'problem':>8} {'floor s':>8} {'check s':>8} {'ratio':>6} {'answer s':>9} {'net':>5} "
          f"{'no cache s':>10} {'ratio':>6}")
    for pid in ids:
        answer = ROOT / "reference_solutions" / pid / "answer.py"
        floor, check, cold, own = [], [], [], []
        for _ in range(args.repeats):
            floor.append(run(FLOOR))
            check.append(run([*lagrade, "check", pid, str(answer)]))
            cold.append(run([*lagrade, "check", pid, str(answer)], cold_env))
            own.append(answer_seconds(answer))
        f, c, n, a = (statistics.median(x) for x in (floor, check, cold, own))
        rows.append((pid, f, c, c / f, n / f, (c - a) / f))
        print(f"{pid:>8} {f:8.3f} {c:8.3f} {c / f:6.2f} {a:9.3f} {(c - a) / f:5.2f} {n:10.3f} {n / f:6.2f}", flush=True)
    for label, i in (("ratio", 3), ("net of the answer's own code", 5), ("without the cache", 4)):
        worst = max(rows, key=lambda r: r[i])
        print(f"{label}: worst {worst[i]:.2f} ({worst[0]}), median {statistics.median(r[i] for r in rows):.2f}, "
              f"{sum(r[i] <= 1.5 for r in rows)} of {len(rows)} within the target 1.5")


if __name__ == "__main__":
    main()
