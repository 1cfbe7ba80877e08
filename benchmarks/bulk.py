"""Bulk grading: throughput and peak memory of ``lagrade grade`` on a class of one 2-DOF problem.

Issue 7 targets 3 and 4: a 200-submission class graded in under 60 s on 2 cores, at >= 20x the
throughput of one ``lagrade check`` process per file; peak memory (PSS) flat in the number of
submissions (200 against 1000).

    python benchmarks/bulk.py                        # 200 submissions of 12.14, pool and baseline
    python benchmarks/bulk.py --memory 200,1000      # peak memory at each class size
    python benchmarks/bulk.py --dask                 # also a Dask LocalCluster run
    python benchmarks/bulk.py --distinct             # no two Python answers with the same values

The class is generated like the tests' (tests/bulk/classgen.py): the reference solution, equivalent
rewrites, golden correct and wrong answers (typical mistakes) and broken files (syntax error, name
error, empty, not UTF-8, bad TOML); no hostile files, whose cost is set by the time limits rather
than by the grader. It copies 15 distinct files, so what lagrade keeps by content (a file's result,
which a grader reuses for the same bytes; compiled rates, MathML) is reused more than in a real class:
``--distinct`` gives every file bytes and every Python answer values of its own, with the same grades. The grades are checked against the expected ones. ``lagrade grade`` runs as
its own process, as an instructor runs it; its peak memory is the largest sum of the proportional set sizes
(PSS) of it and all its descendants (graders and sandbox children), sampled every 20 ms from /proc.
The baseline runs ``lagrade check PROBLEM FILE --json`` in a fresh process per file, as a script
would: once for each distinct file of the class, weighted by its number of copies, which is the
class's mean without checking all 200. Each repeat runs the pool, then the baseline, so that both
see the same machine load; the ratio is the median of the repeats' ratios. Both use the disk cache,
built first with ``lagrade cache build`` (what an instructor runs once).
"""

from __future__ import annotations

import argparse
import ctypes
import hashlib
import json
import os
import resource
import shutil
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests" / "bulk"))

import classgen  # noqa: E402


def make(tmp: Path, size: int, problem: str) -> tuple[Path, Path, list]:
    root = tmp / "submissions"
    students = size
    while True:  # the smallest class with at least `size` submissions
        shutil.rmtree(root, ignore_errors=True)
        expected = classgen.make_class(root, students, problems=[problem], hostile=False, extras=False)
        if len(expected) >= size:
            break
        students += max(1, size - len(expected))
    hw = tmp / "hw.toml"
    # lagrade's default limits, as an instructor's assignment has them: the tests' 1 s of CPU (which
    # keeps their hostile files quick) is within reach of a correct answer that solves for the normal
    # modes (0.4-0.6 s) when the machine is loaded, and would fail it
    hw.write_text(classgen.assignment_toml([problem], cpu=10, wall=20))
    return root, hw, expected


def make_distinct(root: Path, problem: str) -> int:
    """Give every Python answer values of its own: the generated class copies 15 files, so caches
    keyed by content (compiled rates per equation, MathML per answer text, sympy's own) hit far more
    often than in a real class. L gets a total time derivative d/dt(c P q) and every equation of
    motion is multiplied by c, with c = k/(k+1) unique per file: the grades stay the same. Every
    other file (text answers, broken files) is a program of its own, a comment line before its first
    line (which moves every line: `lagrade.answer.reading.program_key`), so that no file's result is
    reused for another's. Returns the number of Python answers changed."""
    from lagrade.problem.library import load_problem

    spec = load_problem(problem)
    changed = 0
    for k, f in enumerate(sorted(p for p in root.rglob("*") if p.is_file()), start=2):
        data = f.read_bytes()
        if f.suffix == ".py":
            src = data.decode("utf-8", errors="replace")
            out = distinct_source(src, spec, k)
            if out != src:
                f.write_text(out, encoding="utf-8")
                changed += 1
                continue
        f.write_bytes(f"# {k}\n".encode() + data)
    return changed


def distinct_source(src: str, spec, k: int) -> str:
    """An answer.py's text with values of its own and the same grades (``k`` >= 2 makes it unique):
    L + d/dt(c P q) and every equation of motion times c, c = k/(k+1). Unchanged when it binds
    neither."""
    import re

    system = spec.systems[0]
    q, par = system.coordinates[0].name, spec.parameters_of(system.key)[0].name
    lines = ["", "import sympy as spx", f"c_ = spx.Rational({k}, {k + 1})"]
    if re.search(r"^L\s*=", src, re.M):
        lines.append(f"L = L + c_ * spx.Symbol('{par}') * spx.Function('{q}')(spx.Symbol('t')).diff(spx.Symbol('t'))")
    for part in spec.parts:
        if part.kind == "eom" and re.search(rf"^{part.name}\s*=", src, re.M):
            lines.append(f"{part.name} = [spx.Eq(r.lhs * c_, r.rhs * c_) if isinstance(r, spx.Equality) "
                         f"else c_ * r for r in {part.name}]")
    return src + "\n".join(lines) + "\n" if len(lines) > 3 else src


def _pss(pid: int) -> int:
    """Proportional set size in bytes: a forked sandbox child shares most of its grader's pages, and
    summing resident sizes would count those pages twice."""
    try:
        with open(f"/proc/{pid}/smaps_rollup") as fh:
            for line in fh:
                if line.startswith("Pss:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def _tree_rss(root_pid: int) -> int:
    """Memory of a process and all its descendants (Linux /proc), as the sum of their PSS."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as fh:
                stat = fh.read()
            ppid = int(stat[stat.rindex(")") + 2:].split()[1])
            children.setdefault(ppid, []).append(int(entry))
        except (OSError, ValueError, IndexError):
            continue
    total, todo = 0, [root_pid]
    while todo:
        pid = todo.pop()
        total += _pss(pid)
        todo.extend(children.get(pid, []))
    return total


def _reap() -> None:
    while True:
        try:
            os.wait()
        except ChildProcessError:
            return


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_grade(lagrade: list[str], root: Path, hw: Path, db: Path, workers: int,
              extra: tuple[str, ...] = (), memory: bool = True) -> tuple[float, int, float]:
    """Wall seconds, peak resident bytes (0 unless ``memory``) and CPU seconds of one ``lagrade grade``
    run; the CPU time is that of the run and every process it started (graders, sandbox children).

    Sampling reads /proc/PID/smaps_rollup of every process of the run every 20 ms: on 2 cores that
    takes CPU time from the graders (a class run measured 17.3 s sampled and 13-15 s not), so the
    timed runs do not sample and the peak comes from a run of its own."""
    cmd = [*lagrade, "grade", str(root), "--assignment", str(hw), "--db", str(db), "--workers", str(workers),
           "--no-summary", "--no-progress", *extra]
    cpu = _children_cpu()
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    peak = 0
    done = threading.Event()

    def sample() -> None:
        nonlocal peak
        while memory and not done.is_set():
            peak = max(peak, _tree_rss(proc.pid))
            time.sleep(0.02)

    sampler = threading.Thread(target=sample, daemon=True)
    sampler.start()
    _, err = proc.communicate()
    _reap()  # anything it left behind (a zygote): counted once reaped
    seconds = time.perf_counter() - start
    done.set()
    sampler.join()
    if proc.returncode not in (0, 1):
        raise SystemExit(f"lagrade grade failed ({proc.returncode}): {err.decode()[-2000:]}")
    return seconds, peak, _children_cpu() - cpu


OWN = """
import os, sys, time
from pathlib import Path
from lagrade.uses.bulk.worker import Grader
from lagrade.problem.library import problem_path
grader = Grader({sys.argv[1]: Path(problem_path(sys.argv[1])).read_text()})
for name in sys.argv[2:]:
    source = Path(name).read_bytes()
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        sys.stdout = open(os.devnull, "w")
        start = time.process_time()
        try:
            exec(compile(source, name, "exec"), {"__name__": "__answer__"})
        except BaseException:
            pass
        os.write(w, str(time.process_time() - start).encode())
        os._exit(0)
    os.close(w)
    os.waitpid(pid, 0)
    print(os.read(r, 100).decode() or 0, flush=True)
grader.close()  # its folder in /tmp
"""


def own_code_seconds(problem: str, copies: dict[str, list], repeats: int = 3, workers: int = 1) -> float:
    """What the answers' own code costs: the CPU time of each distinct Python file run plainly (no
    sandbox, no grading) in a child forked from a warmed grader, as the sandbox forks it (in a grader's
    environment: sympy's cache is as large, so the answers' code is as fast); the median
    of ``repeats``, times the number of its copies (``copies``: content hash -> [file, count]) a
    class's graders run: a grader runs the same bytes once (`lagrade.uses.bulk.worker.Grader`'s
    results by content), so at most ``workers`` times. No grader can take less than once: it is
    the part of a class's time that grading cannot remove."""
    from lagrade.uses.bulk.worker import grader_environment

    counts = {key: fk for key, fk in copies.items() if fk[0].suffix == ".py"}
    distinct = [str(f) for f, _ in counts.values()] * repeats
    # this checkout's grader whatever --lagrade-src says: the answers' code is the same under either
    env = {**grader_environment(tempfile.gettempdir()), "PYTHONPATH": str(REPO / "src")}
    out = subprocess.run([sys.executable, "-c", OWN, problem, *distinct], capture_output=True, text=True, check=True,
                         env=env)
    seconds = [float(x) for x in out.stdout.split()]
    per_file = [statistics.median(seconds[i::len(counts)]) for i in range(len(counts))]
    return sum(s * min(k, workers) for s, (_, k) in zip(per_file, counts.values()))


def check_grades(db: Path, expected: list, problem: str) -> int:
    """How many submissions got a score other than the one known by construction; each is printed
    with its parts' verdicts, so that a surprise can be looked into."""
    weights = classgen.part_weights(problem)
    con = sqlite3.connect(db)
    rows = dict(((s, p), (score, status, reason)) for s, p, score, status, reason in
                con.execute("SELECT student, problem, score, status, reason FROM submissions"))
    wrong = [e for e in expected if abs(rows.get((e.student, e.problem), (-1,))[0] - e.score(weights)) > 1e-6]
    for e in wrong:
        score, status, reason = rows.get((e.student, e.problem), (None, "missing", ""))
        print(f"    unexpected: {e.student} ({e.variant}) scored {score}, expected {e.score(weights)}; "
              f"status {status} {reason[:200]}", flush=True)
        for part, verdict, feedback in con.execute(
                "SELECT part, verdict, feedback FROM parts WHERE student = ? AND problem = ?", (e.student, e.problem)):
            print(f"      {part}: {verdict}: {feedback[:300]}", flush=True)
    con.close()
    return len(wrong)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--problem", default="12.14", help="a 2-DOF problem (default: the double pendulum)")
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--workers", type=int, default=os.cpu_count())
    ap.add_argument("--repeats", type=int, default=3, help="runs of the pool; the median is reported")
    ap.add_argument("--memory", default="", help="comma-separated class sizes: peak memory of each (e.g. 200,1000)")
    ap.add_argument("--dask", action="store_true", help="also grade on a Dask LocalCluster")
    ap.add_argument("--distinct", action="store_true",
                    help="no two Python answers share a value (see make_distinct); the baseline then checks "
                         "every file once")
    ap.add_argument("--plots", action="store_true", help="lagrade grade --plots: also draw the wrong motions")
    ap.add_argument("--lagrade-src", type=Path, help="grade and check with another checkout's sources (its src/ "
                                                      "folder, as PYTHONPATH of `python -m lagrade`): an older commit")
    ap.add_argument("--json", type=Path, help="also write the figures to this file (benchmarks/pinned.py reads it)")
    ap.add_argument("--no-memory", action="store_true", help="skip the peak memory run")
    ap.add_argument("--no-baseline", action="store_true", help="skip the one-check-per-file baseline (lagrade's "
                                                                "CPU per file needs none)")
    ap.add_argument("--no-plots", action="store_true", help="lagrade grade --no-plots (an older lagrade drew them "
                                                             "by default)")
    args = ap.parse_args()
    ctypes.CDLL(None).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER: what a process leaves behind is counted
    script = Path(sys.executable).with_name("lagrade")
    lagrade = [str(script)] if script.exists() else [sys.executable, "-m", "lagrade"]
    if args.lagrade_src is not None:  # the subprocesses' lagrade: this process generates the class with its own
        lagrade = [sys.executable, "-m", "lagrade"]
        os.environ["PYTHONPATH"] = str(args.lagrade_src.resolve())
    subprocess.run([*lagrade, "cache", "build", args.problem], stdout=subprocess.DEVNULL, check=True)
    tmp = Path(tempfile.mkdtemp(prefix="lagrade-bench-"))
    try:
        if args.memory:
            for size in (int(s) for s in args.memory.split(",")):
                root, hw, expected = make(tmp / f"m{size}", size, args.problem)
                seconds, peak, _ = run_grade(lagrade, root, hw, tmp / f"m{size}.sqlite", args.workers)
                wrong = check_grades(tmp / f"m{size}.sqlite", expected, args.problem)
                print(f"{len(expected):5d} submissions: {seconds:6.1f} s, peak memory (PSS) "
                      f"{peak / 2**20:6.0f} MiB (lagrade grade and all its processes); {wrong} graded unexpectedly",
                      flush=True)
            return

        root, hw, expected = make(tmp, args.size, args.problem)
        if args.distinct:
            print(f"--distinct: {make_distinct(root, args.problem)} Python answers changed to values of their own")
        n = len(expected)
        kinds = {"right": 0, "wrong": 0, "broken": 0}
        for e in expected:
            kinds["broken" if e.expect is None else ("right" if all(v == 1.0 for v in e.expect.values()) else "wrong")] += 1
        print(f"class: {n} submissions of {args.problem} ({kinds['right']} right, {kinds['wrong']} wrong, "
              f"{kinds['broken']} broken), {args.workers} workers, {os.cpu_count()} cores")
        files = [root / e.student / next(p.name for p in (root / e.student).iterdir() if p.stem == e.problem)
                 for e in expected]
        copies: dict[str, list] = {}
        for f in files:
            copies.setdefault(hashlib.sha256(f.read_bytes()).hexdigest(), [f, 0])[1] += 1
        times, cpus, bases, ratios, cpu_ratios = [], [], [], [], []
        for i in range(args.repeats):
            db = tmp / f"pool{i}.sqlite"
            seconds, _, cpu = run_grade(lagrade, root, hw, db, args.workers, memory=False,
                                        extra=["--plots"] if args.plots else ["--no-plots"] if args.no_plots else [])
            wrong = check_grades(db, expected, args.problem)
            check, check_cpu = {key: float("nan") for key in copies}, {key: float("nan") for key in copies}
            for key, (f, _) in copies.items() if not args.no_baseline else ():
                t, c = time.perf_counter(), _children_cpu()
                subprocess.run([*lagrade, "check", f.stem, str(f), "--json"], capture_output=True, check=False)
                _reap()  # the check's zygote, left to this subreaper: its CPU counts
                check[key], check_cpu[key] = time.perf_counter() - t, _children_cpu() - c
            base = sum(check[key] * k for key, (_, k) in copies.items()) / n
            base_cpu = sum(check_cpu[key] * k for key, (_, k) in copies.items()) / n
            times.append(seconds)
            cpus.append(cpu)
            bases.append(base)
            ratios.append(base * n / seconds)
            cpu_ratios.append(base_cpu * n / cpu)
            print(f"  lagrade grade: {n} in {seconds:.1f} s ({cpu:.1f} s of CPU), {wrong} graded unexpectedly; "
                  f"one check per file: {base:.2f} s, {base_cpu:.2f} s of CPU (the {len(copies)} distinct files); "
                  f"ratio {ratios[-1]:.1f}x, of CPU {cpu_ratios[-1]:.1f}x", flush=True)
        pool, cpu, base = statistics.median(times), statistics.median(cpus), statistics.median(bases)
        print(f"lagrade grade (median of {args.repeats}): {pool:.1f} s = {n / pool * 60:.0f} per minute "
              f"(target: under 60 s)")
        print(f"one `lagrade check` per file: {base:.2f} s (median)")
        print(f"ratio: lagrade grade is {statistics.median(ratios):.1f}x the throughput of one check per file "
              f"(median of the repeats' ratios; target >= 20x); of CPU: {statistics.median(cpu_ratios):.1f}x (the "
              f"class's CPU against a check's all processes per file: the ratio an idle machine's cores would give)")
        print(f"CPU of lagrade grade (median): {cpu:.1f} s, {cpu / (os.cpu_count() or 1):.1f} s on "
              f"{os.cpu_count()} idle cores at best (target: under 8 s)")
        if not args.no_memory:
            seconds, peak, _ = run_grade(lagrade, root, hw, tmp / "memory.sqlite", args.workers)
            print(f"  peak memory (PSS, a run of its own sampled every 20 ms): {peak / 2**20:.0f} MiB "
                  f"(that run: {seconds:.1f} s)")

        if args.dask:
            from distributed import Client, LocalCluster

            from lagrade.uses.bulk.assignment import load_assignment
            from lagrade.uses.bulk.runner import grade_folder

            with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                              dashboard_address=None) as cluster, Client(cluster) as client:
                t = time.perf_counter()
                r = grade_folder(root, load_assignment(hw), tmp / "dask.sqlite", scheduler=client)
                dask = time.perf_counter() - t
                print(f"Dask LocalCluster ({r.workers} workers x 1 thread): {n} in {dask:.1f} s "
                      f"(cluster already up; includes warming its graders)")

        own = own_code_seconds(args.problem, copies, workers=args.workers)
        cores = os.cpu_count() or 1
        budget = base * n / 20 * cores
        print(f"where the CPU goes (median run): lagrade grade and all its processes used {cpu:.1f} s of CPU on "
              f"{cores} cores; the answers' own code, each distinct file run alone in a fork of a warmed grader "
              f"(once per grader at most: a grader runs the same bytes once), takes at most {own:.1f} s of that; "
              f"lagrade's share is at least {cpu - own:.1f} s = {(cpu - own) / n * 1000:.0f} ms per file (starting "
              f"the graders included). At 20x the class would take {base * n / 20:.1f} s, at most {budget:.1f} s "
              f"of CPU on {cores} cores, which leaves {(budget - own) / n * 1000:.0f} ms per file for lagrade.")
        if args.json is not None:
            args.json.write_text(json.dumps({
                "n": n, "distinct_files": len(copies), "seconds": pool, "cpu": cpu, "idle_cores": cpu / cores,
                "ratio": statistics.median(ratios), "cpu_ratio": statistics.median(cpu_ratios),
                "own": own, "lagrade_ms_per_file": (cpu - own) / n * 1000, "unexpected": wrong}))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
