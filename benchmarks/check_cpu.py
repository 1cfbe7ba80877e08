"""The CPU one process spends grading reference solutions after a warm-up: the judge's own cost,
without interpreter start-up and imports (what `check_against.py` measures whole).

    python benchmarks/check_cpu.py                                  # this checkout
    OLD/bin/python benchmarks/check_cpu.py --root OLD               # another, run by its own install

Run both side by side on one machine and compare the two lines (`time.process_time`).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import lagrade

IDS = ["12.14", "12.22", "12.43", "12.1", "12.28", "ex12.5", "12.8", "12.33", "12.35", "12.39"]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=str(Path(__file__).resolve().parents[1]), help="the checkout whose answers to grade")
    ap.add_argument("ids", nargs="*", default=IDS)
    args = ap.parse_args()
    answer = lambda pid: Path(args.root) / "reference_solutions" / pid / "answer.py"  # noqa: E731
    lagrade.check("12.2", answer("12.2"))  # warm: imports, the jail's zygote, compiled code paths
    start = time.process_time()
    for pid in args.ids:
        lagrade.check(pid, answer(pid))
    print(f"{lagrade.__file__}: {len(args.ids)} checks, {time.process_time() - start:.2f} s of CPU")


if __name__ == "__main__":
    main()
