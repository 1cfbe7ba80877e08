"""What accuracy costs in time, and what stiffness detection saves: ratios measured side by side.

    python benchmarks/accuracy.py

1. For 12.14 and 12.43: time and error of each method at the grader's default tolerance (1e-10),
   as ratios to the grader's default (DOP853), from the work-precision sweep.
2. For the spring pendulum 12.7 with k/m from 1e1 to 1e6: evaluations and time of DOP853, LSODA and
   Radau over the horizon (what the stiffness rule is based on), and what the grader does ("auto").
The full sweep with table, CSV and PNG is ``lagrade bench accuracy``.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from lagrade.compare.trajectory import ACCURACY, estimate_stiffness, integrate
from lagrade.library import load_problem
from lagrade.research import workprecision as wp
from lagrade.reference import Mechanics


def methods_at_default():
    print("1. methods at rtol = atol = 1e-10 (ratios to DOP853, the grader's default); best of 3")
    print(f"   {'scene':<6} {'method':<11} {'error':>9} {'ms':>8} {'evals':>7} {'time ratio':>10}")
    for pid in ("12.14", "12.43"):
        sw = wp.sweep(wp.scene(pid), (1e-10,), wp.METHODS, repeat=3)
        base = next(r for r in sw.rows if r.method == "DOP853")
        for r in sw.rows:
            print(f"   {pid:<6} {r.method:<11} {r.error:9.1e} {r.seconds * 1e3:8.1f} {r.rhs_evals:7d} "
                  f"{r.seconds / base.seconds:10.2f}")


def stiffness_sweep():
    print("\n2. spring pendulum 12.7, horizon 2, 4 trajectories near the spring's equilibrium, rtol 1e-10")
    problem = load_problem("12.7")
    mech = Mechanics(problem, problem.systems[0])
    K, n = 4, 2
    rng = np.random.default_rng(3)
    print(f"   {'k/m':>7} {'index':>8} {'stiff':>5} | " + " | ".join(f"{m:>17}" for m in
                                                              ("DOP853", "LSODA", "Radau", "auto (grader)")))
    for km in (1e1, 1e2, 1e3, 1e4, 1e5, 1e6):
        P = np.array([np.ones(K), np.full(K, km), np.ones(K), np.full(K, 9.8)])
        y0 = np.array([1.0 + 9.8 / km + rng.uniform(-1e-3, 1e-3, K), rng.uniform(-1, 1, K),
                       rng.uniform(-0.05, 0.05, K), rng.uniform(-1, 1, K)])

        def rates(t, Y):
            return np.concatenate([Y[n:], mech.accelerations(Y[:n], Y[n:], np.full(K, t), P)])

        st = estimate_stiffness(rates, y0, 2.0, ACCURACY["default"])
        cells = []
        for method in ("DOP853", "LSODA", "Radau", "auto"):
            budget = 10**5 if method != "auto" else ACCURACY["default"].max_rhs_evals
            acc = replace(ACCURACY["default"], method=method, max_rhs_evals=budget)
            start = time.perf_counter()
            run = integrate(rates, y0, 2.0, acc)
            secs = time.perf_counter() - start
            extra = f" [0,{run.horizon:.2g}]" if method == "auto" and run.horizon < 2.0 else ""
            cells.append(f"{run.rhs_evals:>6}{'' if run.ok else '!'} {secs:6.2f}s{extra}")
        print(f"   {km:7.0e} {st.index:8.0f} {str(st.stiff):>5} | " + " | ".join(f"{c:>17}" for c in cells))
    print("   (evaluations, seconds; '!' = stopped at the budget of 100000 evaluations;"
          " auto's window shown when shortened)")


if __name__ == "__main__":
    methods_at_default()
    stiffness_sweep()
