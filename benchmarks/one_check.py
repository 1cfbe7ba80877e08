"""One `lagrade check` against the floor `python -c "import sympy, numpy, scipy.integrate"`.

Target (issue 7): the wall time of checking a reference solution is at most 1.5x the floor, on
every problem. Floor and check runs are interleaved, so both see the same machine load; each
figure is the median of --repeats runs.

    python benchmarks/one_check.py                 # every problem
    python benchmarks/one_check.py 12.14 12.43     # some
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FLOOR = [sys.executable, "-c", "import sympy, numpy, scipy.integrate"]


def run(cmd: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - start


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    exe = shutil.which("lagrade")
    lagrade = [exe] if exe else [sys.executable, "-m", "lagrade"]
    ids = args.ids or sorted(p.name for p in (ROOT / "reference_solutions").iterdir() if p.is_dir())
    rows = []
    print(f"{'problem':>8} {'floor s':>8} {'check s':>8} {'ratio':>6}")
    for pid in ids:
        answer = ROOT / "reference_solutions" / pid / "answer.py"
        floor, check = [], []
        for _ in range(args.repeats):
            floor.append(run(FLOOR))
            check.append(run([*lagrade, "check", pid, str(answer)]))
        f, c = statistics.median(floor), statistics.median(check)
        rows.append((pid, f, c, c / f))
        print(f"{pid:>8} {f:8.3f} {c:8.3f} {c / f:6.2f}", flush=True)
    worst = max(rows, key=lambda r: r[3])
    median_ratio = statistics.median(r[3] for r in rows)
    print(f"worst ratio {worst[3]:.2f} ({worst[0]}); median ratio {median_ratio:.2f}; target <= 1.5")


if __name__ == "__main__":
    main()
