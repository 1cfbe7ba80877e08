"""CPU seconds an honest answer costs a warm grader: the figure the server's CPU budget is chosen above.

    python benchmarks/grading_cpu.py                  # every problem with golden answers
    python benchmarks/grading_cpu.py 12.14 12.22      # some of them

For each problem, one warm grader (:class:`lagrade.uses.bulk.worker.GraderProcess`, as the server's)
grades the reference solution and every golden answer in ``tests/answers/<problem>/`` (right and
wrong), each twice: without and with the picture of a wrong motion (the server's page asks for it).
The cost of a grading is counted as :func:`lagrade.uses.bulk.worker.watch` counts it: the CPU of the
grader, its zygote and the answer's children (/proc), from the job's start to its result. Prints
per problem the largest cost and the file that took it, then the largest of all against
:data:`lagrade.uses.bulk.worker.CPU_BUDGET`, and how many gradings were lowered (must be 0: the budget is
watched as the server watches it, every quarter of a second).
"""

from __future__ import annotations

import argparse
import sys
import time
import tomllib
from multiprocessing.connection import wait
from pathlib import Path

from lagrade.uses.bulk.assignment import Assignment
from lagrade.uses.bulk.layout import Submission
from lagrade.uses.bulk.worker import CPU_BUDGET, GraderProcess, _proc_table, _tree, stop_all, watch
from lagrade.uses.server.grading import make_plan

REPO = Path(__file__).resolve().parents[1]


def files(pid: str) -> list[Path]:
    out = [REPO / "reference_solutions" / pid / "answer.py"]
    out += sorted(p for p in (REPO / "tests" / "answers" / pid).glob("*") if p.name.startswith(("correct", "wrong")))
    return [p for p in out if p.is_file()]


def cost(g: GraderProcess, job: dict) -> tuple[float, dict]:
    """CPU seconds of one grading (the grader's tree), watched as the server watches it."""
    def total() -> float:
        table = _proc_table()
        pids = _tree(table, g.pid)
        return sum(table[p][1] for p in pids) + sum(table[p][2] for p in g.own_pids if p in table)

    before = total()
    g.submit(job)
    while not wait([g.recv_conn], timeout=0.25):
        watch([g], time.monotonic())
    result = g.result(timeout=600)
    return total() - before, result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("problems", nargs="*")
    args = ap.parse_args()
    pids = args.problems or sorted(p.name for p in (REPO / "tests" / "answers").iterdir() if files(p.name))
    worst, lowered, n = (0.0, ""), 0, 0
    for pid in pids:
        a = Assignment.model_validate(tomllib.loads(f'name = "cpu"\n[[problems]]\nid = "{pid}"\n'))
        plan = make_plan(a)
        g = GraderProcess(plan.sources)
        g.wait_ready()
        g.mark_start()
        top = (0.0, "")
        for path in files(pid):
            for plot in (False, True):
                job = plan.job(Submission("s", pid, Path(f"{pid}{path.suffix}"), f"{path.name}{plot}", path.read_bytes()))
                job["plot"] = plot
                seconds, result = cost(g, job)
                lowered += g.lowered or g.retire
                n += 1
                top = max(top, (seconds, f"{path.name}{' +picture' if plot else ''} ({result['status']})"))
        stop_all([g])
        print(f"{pid}: largest {top[0]:.2f} s CPU, {top[1]}", flush=True)
        worst = max(worst, (top[0], f"{pid} {top[1]}"))
    print(f"largest of all {n} gradings: {worst[0]:.2f} s CPU ({worst[1]}); budget {CPU_BUDGET:g} s; "
          f"lowered {lowered}")
    sys.exit(1 if lowered else 0)


if __name__ == "__main__":
    main()
