"""Where one submission's time goes on `lagrade serve`: the stages of serve_load.py's 12.14 answers,
timed one by one in one warm grader (the same :class:`lagrade.uses.bulk.worker.Grader` the server runs).

    python benchmarks/serve_profile.py [--answers 120] [--seed 1]

Stages, in the order a submission meets them: ``store`` (the attempt written before grading, SQLite
with synchronous=FULL, in the server process), ``load`` (the answer run in the jail by the warm
zygote, or answer.toml parsed), ``grade`` (every part compared; the grader's verdict memo on),
``show`` (the student's values as text and MathML for the gradebook), ``read back`` (the server's
JSON: each value read back without eval, as LaTeX and terminal text), ``finish`` (the grade and the
gradebook row written). Prints the mean and p95 per stage in ms, by kind of answer, and the share
of each stage in the total.
"""

from __future__ import annotations

import argparse
import os
import random
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

# as a grader process runs (lagrade.uses.bulk.worker.grader_environment): sympy reads this once, on import
os.environ.setdefault("SYMPY_CACHE_SIZE", "20000")
sys.path.insert(0, str(Path(__file__).resolve().parent))
from serve_load import answers, pick  # noqa: E402  (the same answers, drawn the same way)

STAGES = ("store", "load", "grade", "show", "read back", "finish")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--answers", type=int, default=120)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    from lagrade.answer.reading.load import load_answer
    from lagrade.answer.jail.sandbox import SandboxLimits
    from lagrade.uses.bulk.assignment import parse_assignment
    from lagrade.uses.bulk.display import show
    from lagrade.uses.bulk.layout import Submission, file_hash
    from lagrade.uses.bulk.worker import Grader, problem_parts
    from lagrade.verdicts.grade import grade_values
    from lagrade.uses.server.db import Database
    from lagrade.uses.server.grading import check_json, make_plan

    work = Path(tempfile.mkdtemp(prefix="lagrade-serve-profile-"))
    try:
        assignment = parse_assignment({"name": "load", "problems": [{"id": "12.14"}]}, "profile")
        plan = make_plan(assignment)
        (work / "grader").mkdir(mode=0o711)  # as GraderProcess makes it: a jailed child reaches its own folder
        t = time.perf_counter()
        grader = Grader(plan.sources, str(work / "grader"))
        warm = time.perf_counter() - t
        problem = grader.problems["12.14"]
        db = Database(str(work / "serve.sqlite"))
        rng, pool = random.Random(args.seed), answers()
        times: dict[str, dict[str, list[float]]] = {}
        for i in range(args.answers):
            kind, name, data = pick(rng, pool, i, 15.0)
            suffix = Path(name).suffix
            row = times.setdefault(kind, {s: [] for s in STAGES})
            t0 = time.perf_counter()
            sid, _ = db.submit(student=f"s{i:03d}", problem="12.14", suffix=suffix, data=data,
                               file_hash=file_hash(data), grading_hash=plan.keys["12.14"], version=plan.version)
            t1 = time.perf_counter()
            job = plan.job(Submission(f"s{i:03d}", "12.14", Path(f"12.14{suffix}"), file_hash(data), data))
            path = work / f"answer-{i}{suffix}"
            path.write_bytes(data)
            limits = job["limits"]
            loaded = load_answer(path, problem, SandboxLimits(cpu_seconds=limits["cpu_seconds"],
                                                               wall_seconds=limits["wall_seconds"],
                                                               memory_mb=limits["memory_mb"]))
            t2 = time.perf_counter()
            result = grade_values(problem, loaded, job["accuracy"], read_as=(), memo=grader.memo)
            t3 = time.perf_counter()
            parts = []
            for p in result.parts:
                r = p.model_dump(exclude={"read_as"})
                if p.part in loaded.values:
                    r["answer_text"], r["answer_mathml"] = show(loaded.values[p.part])
                parts.append(r)
            t4 = time.perf_counter()
            reason = str(loaded.fatal) if loaded.fatal is not None else ""
            out = {"student": job["student"], "problem": "12.14",
                   "outcome": "failed" if loaded.fatal is not None and not loaded.values else "graded",
                   "status": "error" if reason else "ok", "reason": reason, "score": result.score,
                   "max_score": result.max_score, "problems": result.problems, "parts": parts,
                   "seconds": t4 - t1, "jail": grader.jail}
            check = check_json(out, problem)
            t5 = time.perf_counter()
            db.finish(sid, out, check)
            t6 = time.perf_counter()
            for stage, seconds in zip(STAGES, (t1 - t0, t2 - t1, t3 - t2, t4 - t3, t5 - t4, t6 - t5)):
                row[stage].append(seconds)
            assert len(problem_parts(problem)) == len(out["parts"])
        grader.close()
        db.close()
    finally:
        shutil.rmtree(work, ignore_errors=True)

    def ms(xs: list[float]) -> str:
        if not xs:
            return "-"
        p95 = statistics.quantiles(xs, n=20)[-1] if len(xs) >= 2 else xs[0]
        return f"{statistics.mean(xs) * 1e3:.0f} / {p95 * 1e3:.0f}"

    print(f"{args.answers} answers to 12.14 in one warm grader (warm-up {warm:.1f} s); "
          "mean / p95 in ms per stage")
    print("| kind | n | " + " | ".join(STAGES) + " | total |")
    print("|---|---|" + "---|" * (len(STAGES) + 1))
    every = {s: [] for s in STAGES}
    for kind, row in sorted(times.items()):
        total = [sum(xs) for xs in zip(*row.values())]
        print(f"| {kind} | {len(total)} | " + " | ".join(ms(row[s]) for s in STAGES) + f" | {ms(total)} |")
        for s in STAGES:
            every[s] += row[s]
    whole = sum(sum(v) for v in every.values())
    print("| share of all | | " + " | ".join(f"{sum(every[s]) / whole:.0%}" for s in STAGES) + " | 100% |")


if __name__ == "__main__":
    main()
