"""Cost per trajectory: lagrade's batched integration against one plain solve_ivp per trajectory.

Issue 7 target 2: integrating the K sampled initial states as one batched system, with a
right-hand side compiled once (common subexpressions shared, M and f in one call), is >= 5x cheaper
per trajectory than K separate ``solve_ivp`` calls on a per-trajectory ``lambdify`` of the
accelerations. Also: the right-hand side's cost per evaluation against a numba-compiled version of
the same expressions (target <= 3x; skipped when numba is not installed: ``pip install numba``).
Same problem (the double pendulum, 12.14), same tolerances, same initial states, median of repeats.

    python benchmarks/trajectories.py [--problem 12.14] [--K 16] [--repeats 5]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from lagrade.grade import references
from lagrade.library import load_problem
from lagrade.sampling import rng_for, sample_points, state_arrays
from lagrade.symbols import T


def median_time(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--problem", default="12.14")
    ap.add_argument("--K", type=int, default=16)
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    problem = load_problem(args.problem)
    mech = references(problem)[problem.systems[0].key]
    n = len(mech.names)
    pts = sample_points(mech, args.K, rng_for("bench", args.problem))
    q, qd, _, params = state_arrays(mech, pts)
    horizon, rtol, atol = mech.system.horizon, 1e-10, 1e-10

    def batched():
        def rhs(t, flat):
            y = flat.reshape(2 * n, args.K)
            acc = mech.accelerations(y[:n], y[n:], np.full(args.K, t), params)
            return np.concatenate([y[n:], acc]).ravel()
        return solve_ivp(rhs, (0, horizon), np.concatenate([q, qd]).ravel(), method="DOP853", rtol=rtol, atol=atol)

    # The plain way: solve M qdd = f symbolically once per problem, lambdify, one solve_ivp per state.
    acc_exprs = mech.accelerations_symbolic
    plain = sp.lambdify([*mech.s.q, *mech.s.qd, T, *mech.params], acc_exprs, modules="numpy")

    def one_by_one():
        for k in range(args.K):
            p_k = params[:, k]

            def rhs(t, y):
                return [*y[n:], *plain(*y, t, *p_k)]
            solve_ivp(rhs, (0, horizon), np.concatenate([q[:, k], qd[:, k]]), method="DOP853", rtol=rtol, atol=atol)

    tb = median_time(batched, args.repeats) / args.K
    tp = median_time(one_by_one, args.repeats) / args.K
    print(f"problem {args.problem}, K = {args.K} trajectories, horizon {horizon}, rtol = atol = {rtol:g}")
    print(f"batched (lagrade):            {tb * 1e3:8.2f} ms per trajectory")
    print(f"one solve_ivp + lambdify each: {tp * 1e3:8.2f} ms per trajectory")
    print(f"ratio: batched is {tp / tb:.1f}x cheaper per trajectory (target >= 5x)")

    # Right-hand side per evaluation, for one batch of K states.
    y = np.concatenate([q, qd])
    t0 = np.zeros(args.K)
    rhs_once = lambda: mech.accelerations(y[:n], y[n:], t0, params)  # noqa: E731
    per_eval = median_time(lambda: [rhs_once() for _ in range(200)], args.repeats) / 200
    print(f"lagrade right-hand side: {per_eval * 1e6:8.1f} us per evaluation of {args.K} states")
    try:
        import numba  # noqa: F401
    except ImportError:
        print("numba comparison skipped: pip install numba")
        return
    from sympy.printing.numpy import NumPyPrinter  # noqa: F401

    nb = numba.njit(sp.lambdify([*mech.s.q, *mech.s.qd, T, *mech.params], acc_exprs, modules="math"))
    def nb_batch():
        for k in range(args.K):
            nb(*y[:, k], 0.0, *params[:, k])
    nb_batch()  # compile
    per_nb = median_time(lambda: [nb_batch() for _ in range(200)], args.repeats) / 200
    print(f"numba right-hand side:   {per_nb * 1e6:8.1f} us per evaluation of {args.K} states")
    print(f"ratio: lagrade / numba = {per_eval / per_nb:.2f} (target <= 3)")


if __name__ == "__main__":
    main()
