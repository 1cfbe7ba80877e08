"""What accuracy costs on the grading path, and what stiffness detection saves.

    python benchmarks/accuracy.py [--markdown] [--section 1|2]

1. For 12.14 and 12.43 at the default preset's tolerance (1e-10): error, median time and evaluations of
   the grading path (the compiled DOP853 grading runs), of the same integrator on rates as numpy code,
   and of scipy's methods one trajectory at a time, as ratios to the grading path
   (`lagrade.uses.research.workprecision`; reference Radau at 1e-13).
2. For the spring pendulum 12.7 with k/m from 1e1 to 1e6: evaluations and time of DOP853, LSODA and
   Radau over the horizon (what the stiffness rule is based on), and what the grader does ("auto").
The full sweep with table, Markdown, CSV and PNG is ``lagrade bench accuracy``.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from lagrade.compare.trajectory import ACCURACY, estimate_stiffness
from lagrade.problem.library import load_problem
from lagrade.derive.reference import Mechanics
from lagrade.uses.research import workprecision as wp
from lagrade.compare.scene_model import scene_model, scene_motion


def methods_at_default(md: bool = False):
    tol = ACCURACY["default"].rtol
    title = f"methods at rtol = atol = {tol:g} (the default preset), 4 states; time: median of 3 runs"
    cols = ("scene", "method", "error", "ms", "evals", "time / grading path")
    lines = []
    for pid in ("12.14", "12.43"):
        sw = wp.sweep(wp.scene(pid), (tol,), (*wp.METHODS, "numpy"), repeat=3)
        base = next(r for r in sw.rows if r.preset == "default")
        lines += [(pid, r.label, f"{r.error:.1e}", f"{r.seconds * 1e3:.2f}", str(r.rhs_evals),
                   f"{r.seconds / base.seconds:.2f}") for r in sw.rows if r.tol == tol]
    _print("1. " + title, cols, lines, md)


def stiffness_sweep(md: bool = False):
    """The grader's own model and integrator (`scene_motion`: the declared model, its events), per method."""
    problem = load_problem("12.7")
    mech = Mechanics(problem, problem.systems[0])
    K = 4
    rng = np.random.default_rng(3)
    lines = []
    for km in (1e1, 1e2, 1e3, 1e4, 1e5, 1e6):
        P = np.array([np.ones(K), np.full(K, km), np.ones(K), np.full(K, 9.8)])
        y0 = np.array([1.0 + 9.8 / km + rng.uniform(-1e-3, 1e-3, K), rng.uniform(-1, 1, K),
                       rng.uniform(-0.05, 0.05, K), rng.uniform(-1, 1, K)])
        rates = scene_model(mech).compiled_rates(P)
        st = estimate_stiffness(rates, y0, 2.0, ACCURACY["default"])
        cells = []
        for method in ("DOP853", "LSODA", "Radau", "auto"):
            budget = 10**5 if method != "auto" else ACCURACY["default"].max_rhs_evals
            acc = replace(ACCURACY["default"], method=method, max_rhs_evals=budget)
            start = time.perf_counter()
            # the grading path's entry (the declared model, its events), the method forced per column
            run = scene_motion(mech, y0, P, 2.0, acc)
            secs = time.perf_counter() - start
            evals = f"> {budget}" if not run.ok and "more than" in run.message else str(run.rhs_evals)
            if method == "auto":
                evals += f" ({run.method}" + (f", window [0, {run.horizon:.2g}])" if run.horizon < 2.0 else ")")
            cells.append(evals if md else f"{evals} {secs:.2f}s")
        lines.append((f"{km:.0e}", f"{st.index:.0f}", str(st.stiff), *cells))
    _print("2. spring pendulum 12.7, horizon 2, 4 trajectories near the spring's equilibrium, rtol 1e-10; "
           "batched evaluations" + ("" if md else " and seconds"),
           ("k/m", "index", "stiff", "DOP853", "LSODA", "Radau", "grader (auto)"), lines, md)


def _print(title: str, cols: tuple[str, ...], lines: list[tuple[str, ...]], md: bool) -> None:
    print(title)
    if md:
        print("\n| " + " | ".join(cols) + " |\n|" + "---|" * len(cols))
        for line in lines:
            print("| " + " | ".join(line) + " |")
    else:
        widths = [max(len(c), *(len(x[i]) for x in lines)) for i, c in enumerate(cols)]
        for line in (cols, *lines):
            print("   " + "  ".join(x.rjust(w) for x, w in zip(line, widths)))
    print()


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--markdown", action="store_true", help="Markdown tables (for docs/numerics.md)")
    parser.add_argument("--section", type=int, choices=(1, 2), help="only section 1 or 2")
    args = parser.parse_args()
    if args.section in (None, 1):
        methods_at_default(args.markdown)
    if args.section in (None, 2):
        stiffness_sweep(args.markdown)
