"""One `lagrade check` of every reference solution by two installations, interleaved: what a change of
the engine costs a check (issue 31: at most +10 %).

    python -m venv /tmp/old && /tmp/old/bin/pip install -e /path/to/old/checkout
    python benchmarks/check_against.py /tmp/old/bin/lagrade --repeats 2

Both build their reference cache first (`lagrade cache build`); then each problem is checked by the
old and the new installation in turn, so both see the same machine load. Prints the medians, the
ratio of the summed times and the median of the per-check ratios.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run(exe: str, pid: str) -> float:
    start = time.perf_counter()
    subprocess.run([exe, "check", pid, str(ROOT / "reference_solutions" / pid / "answer.py")],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - start


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old", help="the other installation's lagrade script")
    ap.add_argument("--new", default=shutil.which("lagrade"), help="this installation's (default: on PATH)")
    ap.add_argument("--repeats", type=int, default=2)
    args = ap.parse_args()
    ids = sorted(p.name for p in (ROOT / "reference_solutions").iterdir() if (p / "answer.py").exists())
    for exe in (args.old, args.new):
        subprocess.run([exe, "cache", "build"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    old, new = [], []
    for _ in range(args.repeats):
        for pid in ids:
            old.append(run(args.old, pid))
            new.append(run(args.new, pid))
    ratios = [b / a for a, b in zip(old, new)]
    print(f"{len(ids)} problems x {args.repeats}: old median {statistics.median(old):.3f} s, new median "
          f"{statistics.median(new):.3f} s; new/old: {sum(new) / sum(old):.3f} of the summed times, "
          f"{statistics.median(ratios):.3f} per check (median)")


if __name__ == "__main__":
    main()
