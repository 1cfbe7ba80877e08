"""Where a grading's CPU goes, by stage: one `lagrade check` of a reference solution, and one grading in
a warm grader (the bulk grader's and the server's :class:`lagrade.uses.bulk.worker.Grader`).

    python benchmarks/stages.py --markdown                 # 12.14, 12.22, 12.43; the table of docs/performance.md
    python benchmarks/stages.py 12.14 --answers 40         # one problem, 40 distinct answers in the warm grader

CPU time (``time.process_time``), so the figures hold on a loaded machine, charged to the innermost
stage that is running (a certificate's own proofs are the certificate's, not the checker's): the
engine's entry points of each stage are wrapped, in every module that imported them, by a timer.
The timers cost about a microsecond a call, and every ``import`` statement is timed (a module
imported for the first time inside a stage is charged to ``imports``, not to the stage).

A check runs as ``lagrade check`` does (the console script's code, the same staging: the answer's
jailed child runs while this process imports the engine and loads the references), in a fresh
process per problem; ``jail`` is the CPU of the zygote and the answer's child, measured from outside
(this script is the check's subreaper and reaps them). The warm grader grades the problem's golden
answers (``tests/answers/<id>``) made distinct as ``benchmarks/bulk.py --distinct`` makes them
(no verdict is memoized), without pictures, then the same answers with pictures
(``pictures`` is that difference's drawing).
"""

from __future__ import annotations

import argparse
import builtins
import ctypes
import importlib
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
PROBLEMS = ["12.14", "12.22", "12.43"]

#: stage -> the engine's entry points charged to it ("module:function" or "module:Class.method")
STAGES: dict[str, list[str]] = {
    "reading (the values rebuilt, text parsed)": [
        "lagrade.answer.reading.load:_finish_py", "lagrade.answer.reading.load:_load_toml",
        "lagrade.answer.reading.load:load_answer", "lagrade.verdicts.checkers.base:read_expr",
        "lagrade.verdicts.checkers.base:equation_rows"],
    "references (disk cache)": ["lagrade.verdicts.grade:references", "lagrade.derive.reference:ReferenceCache.__getitem__"],
    "screening (admit)": ["lagrade.verdicts.checkers.admit:screen", "lagrade.verdicts.checkers.admit:unproved"],
    "exact judge": ["lagrade.compare.exact:is_zero", "lagrade.compare.exact:is_zero_given",
                    "lagrade.compare.exact:outside", "lagrade.compare.exact:sign_on_domain",
                    "lagrade.compare.exact:prepare"],
    "symbolic proofs": ["lagrade.compare.symbolic:proves_zero", "lagrade.compare.symbolic:proves_all_zero"],
    "sampled states (evaluation)": ["lagrade.compare.sampling:sample_points", "lagrade.compare.sampling:grouped",
                                    "lagrade.compare.sampling:with_reference_dynamics",
                                    "lagrade.compare.equations:analyse_rows"],
    "compiling expressions": ["lagrade.numbers.numeric:compile_exprs"],
    "certificates": ["lagrade.compare.certify:certify", "lagrade.compare.certify:outside_span",
                     "lagrade.compare.certify:root_between", "lagrade.compare.certify:sign_change",
                     "lagrade.compare.certify:zero_at", "lagrade.compare.certify:value_at"],
    "trajectories": ["lagrade.compare.trajectory:integrate", "lagrade.compare.trajectory:compare_runs",
                     "lagrade.compare.trajectory:amplification", "lagrade.compare.trajectory:estimate_stiffness",
                     "lagrade.compare.trajectory:may_be_chaotic"],
    "feedback and echo": ["lagrade.verdicts.grade:_echo", "lagrade.verdicts.words:in_words",
                          "lagrade.verdicts.result:render", "lagrade.uses.bulk.display:show"],
    "pictures": ["lagrade.verdicts.plot:plot_png", "lagrade.verdicts.plot:plot_result"],
    "saving references": ["lagrade.verdicts.grade:keep_references"],
}
OTHER = "the checkers' own work (other)"
IMPORTS = "imports"


class Timers:
    """Exclusive CPU time per stage: a stack of running stages, each charged until the next begins."""

    def __init__(self) -> None:
        self.spent: dict[str, float] = {}
        self.stack: list[str] = [OTHER]
        self.mark = time.process_time()

    def switch(self, stage: str | None) -> None:
        now = time.process_time()
        top = self.stack[-1]
        self.spent[top] = self.spent.get(top, 0.0) + now - self.mark
        self.mark = now
        if stage is None:
            self.stack.pop()
        else:
            self.stack.append(stage)

    def wrap(self, f, stage: str):
        def timed(*args, **kwargs):
            self.switch(stage)
            try:
                return f(*args, **kwargs)
            finally:
                self.switch(None)
        timed.__wrapped__ = f
        timed.__name__ = getattr(f, "__name__", "timed")
        return timed

    def install(self) -> None:
        """Wrap every stage's entry points wherever lagrade's modules hold them, and ``import``."""
        real_import, real_module = builtins.__import__, importlib.import_module

        def timed_import(name, globals=None, locals=None, fromlist=(), level=0):  # noqa: A002
            if level == 0 and name in sys.modules and not fromlist:
                return real_import(name, globals, locals, fromlist, level)
            self.switch(IMPORTS)
            try:
                return real_import(name, globals, locals, fromlist, level)
            finally:
                self.switch(None)

        builtins.__import__ = timed_import
        importlib.import_module = self.wrap(real_module, IMPORTS)
        for stage, targets in STAGES.items():
            for target in targets:
                module_name, _, attr = target.partition(":")
                try:
                    module = importlib.import_module(module_name)
                except ImportError:
                    continue
                owner, name = module, attr
                if "." in attr:
                    cls, name = attr.split(".")
                    owner = getattr(module, cls)
                f = owner.__dict__.get(name) if isinstance(owner, type) else getattr(owner, name, None)
                if f is None:
                    continue
                timed = self.wrap(f, stage)
                setattr(owner, name, timed)
                if owner is module:
                    for m in list(sys.modules.values()):
                        if getattr(m, "__name__", "").startswith("lagrade") and m is not module:
                            for key, value in list(vars(m).items()):
                                if value is f:
                                    setattr(m, key, timed)

    def report(self) -> dict[str, float]:
        self.switch(OTHER)
        self.stack = [OTHER]
        return dict(self.spent)


# ------------------------------------------------------------------------------------- one check

CHILD = r"""
import json, os, sys, time
sys.path.insert(0, {bench!r})
start = time.process_time()
from lagrade.answer.jail import zygote
zygote.start()
import stages
import lagrade.cli  # the CLI's imports, as the console script's
timers = stages.Timers()
started = time.process_time()
timers.install()  # imports the engine now (a check imports it while the answer runs): charged to imports
import lagrade.cli.common as common
def leave(code=0):
    spent = timers.report()
    spent["start: interpreter, CLI imports"] = started
    spent["total (this process)"] = time.process_time()
    json.dump(spent, open({out!r}, "w"))
    sys.stdout.flush()
    os._exit(code)
common.leave = leave
import lagrade.cli.check as check
check.leave = leave
sys.argv = ["lagrade", "check", {pid!r}, {answer!r}]
lagrade.cli.run()
"""


def reap_all() -> None:
    while True:
        try:
            os.wait()
        except ChildProcessError:
            return


def one_check(pid: str) -> dict[str, float]:
    """Stages of one `lagrade check` of ``pid``'s reference solution, in a fresh process."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "stages.json"
        code = CHILD.format(bench=str(Path(__file__).resolve().parent), out=str(out), pid=pid,
                            answer=str(REPO / "reference_solutions" / pid / "answer.py"))
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([sys.executable, "-c", code], stdout=subprocess.DEVNULL, check=False)
        reap_all()  # the zygote and anything it left: their CPU is counted once reaped
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        spent = json.loads(out.read_text())
    total = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    spent["jail (zygote and the answer's child)"] = total - spent["total (this process)"]
    spent["total (all processes)"] = total
    return spent


def floor_cpu() -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-c", "import sympy, numpy, scipy.integrate"], check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


# ------------------------------------------------------------------------------ a warm grader


def distinct_answers(pid: str, n: int) -> list[tuple[str, bytes]]:
    """``n`` answers to ``pid``: its reference and golden answers, each Python one made distinct in its
    values (benchmarks/bulk.py's rewrite), cycled."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bulk import distinct_source

    from lagrade.problem.library import load_problem

    spec = load_problem(pid)
    files = [REPO / "reference_solutions" / pid / "answer.py"]
    golden = sorted((REPO / "tests" / "answers" / pid).glob("*"))
    right = [p for p in golden if p.name.startswith("correct")]
    wrong = [p for p in golden if p.name.startswith("wrong")]
    for i in range(max(len(right), len(wrong))):  # right and wrong alternate, as a class's do
        files += right[i:i + 1] + wrong[i:i + 1]
    out = []
    for k in range(n):
        f = files[k % len(files)]
        data = f.read_bytes()
        if f.suffix == ".py":
            data = distinct_source(data.decode("utf-8", "replace"), spec, k + 2).encode()
        out.append((f.suffix, data + f"\n# {k}\n".encode()))
    return out


def below_cpu() -> float:
    """CPU of this process's descendants (the zygote, the answers' children it reaped): /proc's utime,
    stime, cutime and cstime of each process under this one."""
    tick, parent, used = os.sysconf("SC_CLK_TCK"), {}, {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                fields = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            parent[int(entry)], used[int(entry)] = int(fields[1]), sum(int(x) for x in fields[11:15]) / tick
    me, total = os.getpid(), 0.0
    for pid, cpu in used.items():
        p = parent.get(pid)
        while p and p != me:
            p = parent.get(p)
        total += cpu if p == me else 0.0
    return total


def warm_grader(pid: str, n: int) -> tuple[dict[str, float], dict[str, float], dict[str, float]]:
    """Per-grading stages in a warm grader, without pictures and with them (other answers, so that
    nothing of the first round is reused), and the web process's own work per submission on the
    graded results (`lagrade serve`'s steps, on a SQLite database as the server's)."""
    import tomllib
    from types import SimpleNamespace

    os.environ.setdefault("SYMPY_CACHE_SIZE", "20000")
    from lagrade.uses.bulk.assignment import Assignment
    from lagrade.uses.bulk.layout import Submission, file_hash
    from lagrade.uses.bulk.worker import Grader
    from lagrade.uses.server.db import Database
    from lagrade.uses.server.grading import _for_student, check_json, make_plan
    from lagrade.uses.server.rules import view

    a = Assignment.model_validate(tomllib.loads(f'name = "cpu"\n[[problems]]\nid = "{pid}"\n'))
    plan = make_plan(a)
    grader = Grader(plan.sources)
    answers = distinct_answers(pid, 2 * n)
    jobs = [plan.job(Submission("s", pid, Path(f"{pid}{suffix}"), f"{k}{suffix}", data))
            for k, (suffix, data) in enumerate(answers)]
    timers = Timers()
    timers.install()
    results, graded = {}, []
    for plot in (False, True):  # each round its own distinct answers: nothing of the first is reused
        timers.spent, timers.stack, timers.mark = {}, [OTHER], time.process_time()
        jail0 = below_cpu()
        for job in jobs[n:] if plot else jobs[:n]:
            out = grader.grade({**job, "plot": plot, "read_back": True})  # as the server's jobs
            if not plot:
                graded.append((job, out))
        spent = timers.report()
        spent["total (this process)"] = sum(spent.values())
        spent["jail (zygote and the answer's child)"] = below_cpu() - jail0
        spent["total (all processes)"] = spent["total (this process)"] + spent["jail (zygote and the answer's child)"]
        results[plot] = {k: v / n for k, v in spent.items()}
    problem = grader.problems[pid]
    grader.close()
    web: dict[str, float] = {}
    with tempfile.TemporaryDirectory() as tmp:
        db = Database(str(Path(tmp) / "serve.sqlite"))
        server = SimpleNamespace(assignment=a, db=db, problems={pid: problem})

        def timed(stage: str, f):
            t = time.process_time()
            value = f()
            web[stage] = web.get(stage, 0.0) + (time.process_time() - t) / n
            return value

        for i, (job, result) in enumerate(graded):
            student = f"s{i:03d}"
            sid, _ = timed("web: store the attempt (hash, insert)", lambda: db.submit(
                student=student, problem=pid, suffix=job["suffix"], data=job["data"], file_hash=file_hash(job["data"]),
                grading_hash=plan.keys[pid], version=plan.version))
            att = timed("web: read it for its grader", lambda: db.attempt(sid))
            check = timed("web: the result as JSON (read back)", lambda: check_json(
                _for_student(dict(result), pid, job["suffix"], att.data), problem))
            timed("web: write the grade", lambda: db.finish(sid, result, check, None,
                                                             deadline=a.rules.deadline_text(), keep=a.rules.penalty))
            who = SimpleNamespace(student=student, instructor=False)
            timed("web: one poll (read, view, JSON)", lambda: json.dumps(view(server, db.attempt(sid), who)))
        db.close()
    web["web process (total)"] = sum(web.values())
    return results[False], results[True], web


# ------------------------------------------------------------------------------------ the table


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("problems", nargs="*", default=PROBLEMS)
    ap.add_argument("--answers", type=int, default=24, help="distinct answers graded by the warm grader")
    ap.add_argument("--markdown", action="store_true")
    args = ap.parse_args()
    ctypes.CDLL(None).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER: a check's zygote is reaped here
    subprocess.run([sys.executable, "-m", "lagrade", "cache", "build", *args.problems], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)
    columns: dict[str, dict[str, float]] = {}
    floors = []
    for pid in args.problems:
        floors.append(floor_cpu())
        columns[f"check {pid}"] = one_check(pid)
    warm, pictured, web = warm_grader(args.problems[0], args.answers)
    columns[f"warm grader, {args.problems[0]}, per answer"] = {**warm, **web}
    columns["... with pictures"] = pictured
    stages = ["start: interpreter, CLI imports", IMPORTS, *STAGES, OTHER, "jail (zygote and the answer's child)",
              "total (this process)", "total (all processes)", *web]
    floor = sorted(floors)[len(floors) // 2]
    if args.markdown:
        print(f"CPU ms by stage (`python benchmarks/stages.py {' '.join(args.problems)} --answers {args.answers} "
              f"--markdown`); the import floor `import sympy, numpy, scipy.integrate`: {floor * 1000:.0f} ms\n")
        print("| stage | " + " | ".join(columns) + " |")
        print("|---|" + "---:|" * len(columns))
        for s in stages:
            cells = [columns[c].get(s) for c in columns]
            if all(v is None or abs(v) < 0.0005 for v in cells):
                continue
            print(f"| {s} | " + " | ".join("" if v is None else f"{v * 1000:.0f}" for v in cells) + " |")
        for c, col in columns.items():
            if c.startswith("check"):
                print(f"\n{c}: this process {col['total (this process)'] / floor:.2f}x the floor's CPU, "
                      f"all processes {col['total (all processes)'] / floor:.2f}x", end="")
        print()
    else:
        print(json.dumps({"floor": floor, **columns}, indent=1))


if __name__ == "__main__":
    main()
