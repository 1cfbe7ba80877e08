"""What the OS jail costs per answer: the same answers run in a zygote with every layer and in one
with none, alternated in one run, and what starting a zygote costs.

    python benchmarks/jail.py [--rounds 5] [--answers 40]

Prints medians over rounds of the wall time per answer (spawn to outcome) for a trivial answer and
for the bundled reference solution of 12.14, and the time from starting a zygote to its first
child being ready to fork.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from lagrade.answer.jail import kernel, zygote
from lagrade.answer.jail.sandbox import run_answer_file
from lagrade.problem.library import reference_dir

TRIVIAL = "from lagrade.answer import *\ntheta = coordinates('theta')\nL = dot(theta)**2/2 + cos(theta)\n"


def per_answer(layers: tuple[str, ...], path: Path, wanted: list[str], n: int) -> float:
    zygote.start(layers, warm=True).hello()
    run_answer_file(path, wanted)  # the first child pays for imports the zygote did not do
    start = time.perf_counter()
    for _ in range(n):
        out = run_answer_file(path, wanted)
        assert out.status == "ok", out
    zygote.stop()
    return (time.perf_counter() - start) / n


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--answers", type=int, default=40)
    args = ap.parse_args()
    tmp = Path(sys.argv[0]).resolve().parent / ".jail-bench.py"
    tmp.write_text(TRIVIAL)
    cases = {"trivial answer": (tmp, ["L"]),
             "12.14 reference solution": (reference_dir() / "12.14" / "answer.py", ["L", "eom", "omega"])}
    try:
        rows = []
        for label, (path, wanted) in cases.items():
            jailed, bare = [], []
            for _ in range(args.rounds):  # alternated: the host's load moves both alike
                jailed.append(per_answer(kernel.LAYERS, path, wanted, args.answers))
                bare.append(per_answer((), path, wanted, args.answers))
            j, b = statistics.median(jailed), statistics.median(bare)
            rows.append(f"| {label} | {b * 1e3:.1f} ms | {j * 1e3:.1f} ms | {(j - b) * 1e3:+.1f} ms |")
        starts = []
        for _ in range(args.rounds):
            t0 = time.perf_counter()
            zygote.start(kernel.LAYERS).hello()
            starts.append(time.perf_counter() - t0)
            zygote.stop()
        active = zygote.start(kernel.LAYERS).active
        zygote.stop()
    finally:
        tmp.unlink(missing_ok=True)
    print(f"layers active: {', '.join(active)}; medians of {args.rounds} rounds of {args.answers} answers")
    print("| answer | no layer | every layer | the jail's cost |")
    print("|---|---|---|---|")
    print("\n".join(rows))
    print(f"| starting a zygote (cold) until it can fork | | {statistics.median(starts) * 1e3:.0f} ms | |")


if __name__ == "__main__":
    main()
