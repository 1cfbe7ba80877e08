"""CPU seconds an honest answer costs a warm grader: the figures the server's CPU budgets are chosen above.

    python benchmarks/grading_cpu.py                  # every problem with golden answers
    python benchmarks/grading_cpu.py 12.14 12.22      # some of them

For each problem, one warm grader (:class:`lagrade.uses.bulk.worker.GraderProcess`, as the server's)
grades the reference solution and every golden answer in ``tests/answers/<problem>/`` (right and
wrong), each twice: without and with the picture of a wrong motion (the server's page asks for it).
The cost of a grading is counted as :func:`lagrade.uses.bulk.worker.watch` counts it, from the job's
start to its result (/proc): the answer's own code (its jailed children) and the grader's own work
(the grader and its zygote). Prints per problem the largest of each and the file that took it, then
the largest of all against :data:`~lagrade.uses.bulk.worker.CPU_BUDGET` and
:data:`~lagrade.uses.bulk.worker.GRADER_BUDGET`, and how many gradings were lowered (must be 0: the
budgets are watched as the server watches them, every quarter of a second).
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
from lagrade.uses.bulk.worker import CPU_BUDGET, GRADER_BUDGET, GraderProcess, _proc_table, _tree, stop_all, watch
from lagrade.uses.server.grading import make_plan

REPO = Path(__file__).resolve().parents[1]


def files(pid: str) -> list[Path]:
    out = [REPO / "reference_solutions" / pid / "answer.py"]
    out += sorted(p for p in (REPO / "tests" / "answers" / pid).glob("*") if p.name.startswith(("correct", "wrong")))
    return [p for p in out if p.is_file()]


def cost(g: GraderProcess, job: dict) -> tuple[float, float, dict]:
    """CPU seconds of one grading, the answer's children's and the grader's own, watched as the
    server watches them."""
    def totals() -> tuple[float, float]:
        table = _proc_table()
        pids = _tree(table, g.pid)
        own = sum(table[p][1] for p in g.own_pids if p in table)
        return sum(table[p][1] for p in pids) + sum(table[p][2] for p in g.own_pids if p in table) - own, own

    before = totals()
    g.submit(job)
    while not wait([g.recv_conn], timeout=0.25):
        watch([g], time.monotonic())
    result = g.result(timeout=600)
    after = totals()
    return after[0] - before[0], after[1] - before[1], result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("problems", nargs="*")
    args = ap.parse_args()
    pids = args.problems or sorted(p.name for p in (REPO / "tests" / "answers").iterdir() if files(p.name))
    worst = {"answer": (0.0, ""), "grader": (0.0, "")}
    lowered, n = 0, 0
    for pid in pids:
        a = Assignment.model_validate(tomllib.loads(f'name = "cpu"\n[[problems]]\nid = "{pid}"\n'))
        plan = make_plan(a)
        g = GraderProcess(plan.sources)
        g.wait_ready()
        g.mark_start()
        top = {"answer": (0.0, ""), "grader": (0.0, "")}
        for path in files(pid):
            for plot in (False, True):
                job = plan.job(Submission("s", pid, Path(f"{pid}{path.suffix}"), f"{path.name}{plot}", path.read_bytes()))
                job["plot"] = plot
                answer, grader, result = cost(g, job)
                lowered += g.lowered or g.retire
                n += 1
                what = f"{path.name}{' +picture' if plot else ''} ({result['status']})"
                top = {"answer": max(top["answer"], (answer, what)), "grader": max(top["grader"], (grader, what))}
        stop_all([g])
        print(f"{pid}: answer's code {top['answer'][0]:.2f} s ({top['answer'][1]}), grader "
              f"{top['grader'][0]:.2f} s ({top['grader'][1]})", flush=True)
        worst = {k: max(worst[k], (top[k][0], f"{pid} {top[k][1]}")) for k in worst}
    print(f"largest of all {n} gradings: the answer's code {worst['answer'][0]:.2f} s CPU ({worst['answer'][1]}; "
          f"budget {CPU_BUDGET:g} s), the grader's own work {worst['grader'][0]:.2f} s ({worst['grader'][1]}; "
          f"budget {GRADER_BUDGET:g} s); lowered {lowered}")
    sys.exit(1 if lowered else 0)


if __name__ == "__main__":
    main()
