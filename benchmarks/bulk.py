"""Bulk grading throughput: submissions graded per minute for a 200-submission class.

    python benchmarks/bulk.py                 # process pool, Dask LocalCluster, one `lagrade check` at a time
    python benchmarks/bulk.py --baseline-sample 0   # the baseline on every file (slow: ~2.5 s per file)

The class is generated like the tests' (tests/bulk/classgen.py): references, equivalent rewrites,
golden correct and wrong answers and broken files of the fast problems 12.43, 12.3, 12.22 and ex12.3
(no hostile files, whose cost is set by the time limits rather than by the grader). The baseline
runs ``lagrade check PROBLEM FILE --json`` in a fresh process per file, as a script would; by default
on an evenly spread sample of the files, and its rate is per file of that sample.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests" / "bulk"))

import classgen  # noqa: E402

from lagrade.bulk.assignment import load_assignment  # noqa: E402
from lagrade.bulk.runner import grade_folder  # noqa: E402


def make(tmp: Path, size: int) -> tuple[Path, Path, list]:
    root = tmp / "submissions"
    students = 1
    while True:  # the smallest class with at least `size` submissions
        shutil.rmtree(root, ignore_errors=True)
        expected = classgen.make_class(root, students, hostile=False, extras=False)
        if len(expected) >= size:
            break
        students += max(1, (size - len(expected)) // 4)
    hw = tmp / "hw.toml"
    hw.write_text(classgen.assignment_toml())
    return root, hw, expected


def rate(n: int, seconds: float) -> float:
    return n / seconds * 60


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--workers", type=int, default=os.cpu_count())
    ap.add_argument("--baseline-sample", type=int, default=40, help="files for the one-at-a-time baseline (0: all)")
    ap.add_argument("--no-dask", action="store_true")
    args = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="lagrade-bench-"))
    try:
        root, hw, expected = make(tmp, args.size)
        n = len(expected)
        a = load_assignment(hw)
        print(f"class: {n} submissions, {len({e.student for e in expected})} students, {os.cpu_count()} cores")
        results = {}

        t = time.perf_counter()
        r = grade_folder(root, a, tmp / "pool.sqlite", workers=args.workers)
        pool = time.perf_counter() - t
        assert r.todo == n
        results["process pool"] = rate(n, pool)
        print(f"process pool ({r.workers} workers): {n} in {pool:.1f} s = {rate(n, pool):.0f} per minute "
              f"(includes starting and warming the workers)")
        t = time.perf_counter()
        r = grade_folder(root, a, tmp / "pool.sqlite", workers=args.workers)
        print(f"second run (nothing changed): {time.perf_counter() - t:.2f} s, {r.todo} graded")

        if not args.no_dask:
            from distributed import Client, LocalCluster

            with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                              dashboard_address=None) as cluster, Client(cluster) as client:
                t = time.perf_counter()
                r = grade_folder(root, a, tmp / "dask.sqlite", scheduler=client)
                dask = time.perf_counter() - t
                assert r.todo == n
                results["dask LocalCluster"] = rate(n, dask)
                print(f"Dask LocalCluster ({r.workers} workers x 1 thread): {n} in {dask:.1f} s = "
                      f"{rate(n, dask):.0f} per minute (cluster already up; includes warming its graders)")

        files = [root / e.student / next(p.name for p in (root / e.student).iterdir() if p.stem == e.problem)
                 for e in expected]
        sample = files if args.baseline_sample <= 0 else files[:: max(1, len(files) // args.baseline_sample)]
        lagrade = shutil.which("lagrade") or "lagrade"
        t = time.perf_counter()
        for f in sample:
            subprocess.run([lagrade, "check", f.stem, str(f), "--json"], capture_output=True, check=False)
        base = time.perf_counter() - t
        per_min = rate(len(sample), base)
        print(f"one `lagrade check` at a time: {len(sample)} files in {base:.1f} s = {per_min:.0f} per minute "
              f"({base / len(sample):.2f} s per file)")
        for name, value in results.items():
            print(f"  {name}: {value / per_min:.1f}x the one-at-a-time rate")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
