"""The grader tested by the answers `lagrade validate` generates, on the whole chapter.

    python benchmarks/selftest.py [--count 30] [--seed 0] [--jobs 2] [--markdown] [IDS...]

Runs :func:`lagrade.uses.validate.run.validate` on every problem id (or those given): right answers
generated from each reference (other forms) must get full marks, wrong ones (one slip each, unless
proved right) must not. Prints per problem the generated answers, the false accepts (a wrong answer
given full marks), the false rejects (a right one refused), the other failed checks and the seconds,
then the totals; ``--markdown`` prints the table docs/performance.md holds. Exit 0 when every check
of every problem holds.
"""

from __future__ import annotations

import argparse
import json
import sys
import time


def main(argv: list[str] | None = None) -> int:
    from lagrade.problem.library import problem_ids

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--count", type=int, default=30, help="generated right and wrong answers per part (at most)")
    ap.add_argument("--jobs", type=int, default=1, help="problems validated at once, each in a process of its own")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--markdown", action="store_true", help="the totals and the slowest problems as Markdown")
    ap.add_argument("--json", help="also write every report to this file")
    args = ap.parse_args(argv)
    ids = args.ids or problem_ids()
    import lagrade.uses.validate.run  # noqa: F401 (imported once, before the workers fork)
    import lagrade.verdicts.checkers  # noqa: F401
    import lagrade.verdicts.readback  # noqa: F401

    start = time.monotonic()
    reports = []
    print(f"{'problem':<8} {'right':>6} {'wrong':>6} {'dropped':>8} {'FA':>4} {'FR':>4} {'other':>6} {'s':>7}")
    if args.jobs > 1:
        from multiprocessing import get_context

        pool = get_context("fork").Pool(args.jobs)
        done = pool.imap(_one, [(pid, args.seed, args.count) for pid in ids])
    else:
        done = map(_one, [(pid, args.seed, args.count) for pid in ids])
    for pid, r in zip(ids, done):
        reports.append(r)
        s = r.summary()
        other = len(s["failed"]) - s["false_accepts"] - s["false_rejects"]
        print(f"{pid:<8} {s['right']:>6} {s['wrong']:>6} {s['dropped']:>8} {s['false_accepts']:>4} "
              f"{s['false_rejects']:>4} {other:>6} {r.seconds:>7.1f}", flush=True)
        for c in s["failed"]:
            print(f"    FAIL {c['check']} {c['part']}: {c['detail'] or c['label']}"[:600], flush=True)
    wall = time.monotonic() - start
    total = {k: sum(r.summary()[k] for r in reports) for k in ("right", "wrong", "dropped", "false_accepts", "false_rejects")}
    other = sum(len(r.summary()["failed"]) for r in reports) - total["false_accepts"] - total["false_rejects"]
    cases = total["right"] + total["wrong"]
    print(f"\n{len(reports)} problems, {cases} generated answers graded ({total['right']} right, {total['wrong']} wrong; "
          f"{total['dropped']} wrong ones proved right and dropped): {total['false_accepts']} false accepts, "
          f"{total['false_rejects']} false rejects, {other} other failed checks, {wall:.0f} s "
          f"({wall / max(len(reports), 1):.1f} s per problem)")
    if args.markdown:
        slow = sorted(reports, key=lambda r: -r.seconds)[:5]
        seconds = sorted(r.seconds for r in reports)
        print("\n| problems | generated answers (right + wrong) | proved right, dropped | false accepts | false rejects "
              "| other failed checks | seconds (median per problem, slowest) |")
        print("|---|---|---|---|---|---|---|")
        print(f"| {len(reports)} | {cases} ({total['right']} + {total['wrong']}) | {total['dropped']} | "
              f"{total['false_accepts']} | {total['false_rejects']} | {other} | {wall:.0f} "
              f"({seconds[len(seconds) // 2]:.1f}; {', '.join(f'{r.problem} {r.seconds:.0f}' for r in slow)}) |")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump([r.as_json() for r in reports], f, indent=1)
    return 0 if all(r.ok for r in reports) else 1


def _one(job: tuple[str, int, int]):
    from lagrade.uses.validate.run import validate

    pid, seed, count = job
    return validate(pid, seed=seed, count=count)


if __name__ == "__main__":
    sys.exit(main())
