"""One `lagrade check` against the floor `python -c "import sympy, numpy, scipy.integrate"`.

Target (issue 7): the wall time of checking a reference solution is at most 1.5x the floor, on
every problem. Floor and check runs are interleaved, so both see the same machine load; each
figure is the median of --repeats runs. The reference derivations are built first with
``lagrade cache build`` (what an instructor runs once); the "no cache" column is the same check with
``LAGRADE_CACHE=off``, for comparison. The console script is the one installed next to this Python
(a version manager's shim on PATH would add its own start-up time to the check, not to the floor).

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
    print(f"{'problem':>8} {'floor s':>8} {'check s':>8} {'ratio':>6} {'no cache s':>10} {'ratio':>6}")
    for pid in ids:
        answer = ROOT / "reference_solutions" / pid / "answer.py"
        floor, check, cold = [], [], []
        for _ in range(args.repeats):
            floor.append(run(FLOOR))
            check.append(run([*lagrade, "check", pid, str(answer)]))
            cold.append(run([*lagrade, "check", pid, str(answer)], cold_env))
        f, c, n = statistics.median(floor), statistics.median(check), statistics.median(cold)
        rows.append((pid, f, c, c / f, n / f))
        print(f"{pid:>8} {f:8.3f} {c:8.3f} {c / f:6.2f} {n:10.3f} {n / f:6.2f}", flush=True)
    worst = max(rows, key=lambda r: r[3])
    median_ratio = statistics.median(r[3] for r in rows)
    print(f"worst ratio {worst[3]:.2f} ({worst[0]}); median ratio {median_ratio:.2f}; target <= 1.5")
    print(f"without the cache: worst {max(r[4] for r in rows):.2f}, median {statistics.median(r[4] for r in rows):.2f}")


if __name__ == "__main__":
    main()
