"""Trajectory cost of lagrade's grader against the plain way, numba and PyDy, measured side by side.

Scene: problem 12.14, the planar double pendulum (theta1, theta2 = angles of the rods from the
downward vertical; parameters m1, m2, l1, l2, g; horizon 2 s). Every figure is the median of
``--repeats`` timed repeats (each thing is run once before timing, as a warm-up), with the target next
to the ratio. Three comparisons:

1. **Cost per trajectory** (target: batched >= 5x cheaper). lagrade's ``integrate`` on the grader's
   own reference rates (``scene_model(mech).compiled_rates``): its batched DOP853, K trajectories stepped together,
   each with its own step size and error control, each stage one call of the compiled rates
   (machine code through symengine's LLVM ``Lambdify``, ``lagrade.numbers.numeric``; numpy code otherwise),
   against the plain way: lambdify the closed-form accelerations once and call
   ``scipy.integrate.solve_ivp(method="DOP853")`` once per trajectory.
2. **Right-hand side per evaluation** (target: lagrade <= 3x numba). ``mech.accelerations`` (the
   compiled accelerations: machine code through symengine, ``lagrade.numbers.numeric.Compiled``, or numpy
   code where symengine declines or ``LAGRADE_NATIVE=0``; the header says which) on a batch of K
   states against an ``@njit`` loop over the K columns that evaluates the same closed-form
   accelerations (lambdified with ``cse=True``, compiled by numba once before timing) into a
   preallocated output.
3. **Time to accuracy against PyDy** (target: lagrade needs less time). The same pendulum built with
   ``sympy.physics.mechanics.KanesMethod`` and integrated by ``pydy.system.System.integrate`` (its
   defaults: lambdify code generation, ``scipy.integrate.odeint``/LSODA), one state at a time, against
   lagrade's ``integrate``; a tolerance sweep gives each tool's error (against a tight reference) and
   time, then the time each needs to reach a given error.

Why the comparisons are fair: the same expressions (the accelerations lagrade derives, or, for PyDy,
its own derivation checked equal to lagrade's right-hand side at random states before anything is
timed), the same initial states and parameter values (``lagrade.compare.sampling`` with a fixed seed), the
same tolerances (rtol = atol) and the same 201 output times over [0, horizon]; results are checked to
agree before their timings are printed. One-off costs (lambdify, numba compilation, PyDy's derivation
and code generation) are outside the timings and reported separately where they matter.

Run it (numba and PyDy are benchmark-only dependencies, never needed by lagrade itself; without them
sections 2 and 3 print a one-line skip and the rest still runs)::

    pip install -r benchmarks/requirements.txt
    python benchmarks/trajectories.py [--K 4 8 16 32 64] [--repeats 5] [--calls 2000] [--pydy-K 16]
                                      [--sections cost rhs pydy]
"""

from __future__ import annotations

import argparse
import os
import platform
import shlex
import statistics
import sys
import time
from dataclasses import replace

import numpy as np
import scipy
import sympy as sp
from scipy.integrate import solve_ivp

from lagrade.compare.trajectory import ACCURACY
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem
from lagrade.numbers.numeric import backend
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.compare.scene_model import scene_model, scene_motion

PROBLEM = "12.14"
SAMPLES = 201
SKIP = "skipped: pip install -r benchmarks/requirements.txt"

try:
    import numba
except ImportError:
    numba = None
try:
    import pydy
    from pydy.system import System
except ImportError:
    pydy = None


# ------------------------------------------------------------------------------------------ helpers


def timed(fn, repeats: int):
    """(median seconds over ``repeats`` calls of ``fn``, result of the warm-up call made first)."""
    result = fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def states(mech, K: int, seed: str = "bench"):
    """K sampled initial states and parameter values (seeded): q, qd (n, K), params (P, K)."""
    q, qd, _, params = state_arrays(mech, sample_points(mech, K, rng_for(seed, PROBLEM)))
    return q, qd, params


def lagrade_run(mech, q, qd, params, tol: float):
    """lagrade's ``integrate`` on the K states at once, rtol = atol = tol, 201 output times."""
    acc = replace(ACCURACY["default"], rtol=tol, atol=tol, max_rhs_evals=10**7)
    run = scene_motion(mech, np.concatenate([q, qd]), params, mech.system.horizon, acc, samples=SAMPLES,
                       method="DOP853")   # the grading path's entry: the declared model and its events
    if not run.ok:
        raise RuntimeError(f"lagrade integrate failed at tol {tol:g}: {run.message}")
    return run


def plain_runs(mech, plain, q, qd, params, tol: float):
    """The plain way: one ``solve_ivp`` DOP853 per trajectory on the lambdified accelerations.
    Returns (states (2n, K, 201), evaluations per trajectory (K,))."""
    n, K = q.shape
    horizon = mech.system.horizon
    times = np.linspace(0.0, horizon, SAMPLES)
    ys, nfev = [], []
    for k in range(K):
        p_k = params[:, k]

        def rhs(t, y):
            return [*y[n:], *plain(*y, t, *p_k)]
        sol = solve_ivp(rhs, (0.0, horizon), np.concatenate([q[:, k], qd[:, k]]), method="DOP853",
                        rtol=tol, atol=tol, t_eval=times)
        if sol.status != 0:
            raise RuntimeError(f"solve_ivp failed on trajectory {k}: {sol.message}")
        ys.append(sol.y)
        nfev.append(sol.nfev)
    return np.stack(ys, axis=1), np.array(nfev)


def lambdified(mech):
    """The closed-form accelerations as one numpy function of ``mech.args`` (made once per problem)."""
    return sp.lambdify(mech.args, mech.accelerations_symbolic, "numpy")


def header(args) -> None:
    versions = f"numpy {np.__version__}, scipy {scipy.__version__}, sympy {sp.__version__}"
    versions += f"; lagrade compiles with {backend()}"
    versions += f", numba {numba.__version__}" if numba else ", numba not installed"
    versions += f", pydy {pydy.__version__}" if pydy else ", pydy not installed"
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") else "n/a"
    print("lagrade trajectory benchmark (benchmarks/trajectories.py)")
    print(f"machine: {platform.platform()}, {platform.processor() or platform.machine()}, "
          f"os.cpu_count() = {os.cpu_count()}, load average {load}")
    print(f"python {platform.python_version()} ({sys.executable}); {versions}")
    print(f"command: {shlex.join([sys.executable, *sys.argv])}")
    print(f"problem {PROBLEM} (double pendulum), {SAMPLES} output times, median of {args.repeats} repeats "
          "after one warm-up run")


# -------------------------------------------------------------------------- 1. cost per trajectory


def cost_per_trajectory(mech, Ks, repeats: int) -> None:
    tol = ACCURACY["default"].rtol
    print(f"\n1. Cost per trajectory: lagrade integrate (batched DOP853, K at once) vs one scipy solve_ivp "
          f"DOP853 per trajectory on sp.lambdify(accelerations); rtol = atol = {tol:g}, horizon "
          f"{mech.system.horizon} s. Target: batched >= 5x cheaper.")
    start = time.perf_counter()
    plain = lambdified(mech)
    print(f"   (lambdify, once: {(time.perf_counter() - start) * 1e3:.0f} ms, not in the timings; nfev: "
          "batched counts one evaluation per K states, solve_ivp is mean/max over the trajectories)")
    print(f"   {'K':>4} | {'lagrade ms/traj':>15} | {'solve_ivp ms/traj':>17} | {'ratio':>6} | {'target >=5':>10} "
          f"| {'nfev batched':>12} | {'nfev solve_ivp':>14} | {'max |diff|':>10}")
    for K in Ks:
        q, qd, params = states(mech, K)
        tb, run = timed(lambda: lagrade_run(mech, q, qd, params, tol), repeats)
        tp, (y_plain, nfev_plain) = timed(lambda: plain_runs(mech, plain, q, qd, params, tol), repeats)
        diff = float(np.max(np.abs(run.y - y_plain)))
        nfev = f"{nfev_plain.mean():.0f}/{nfev_plain.max()}"
        ratio = tp / tb
        print(f"   {K:4d} | {tb / K * 1e3:15.3f} | {tp / K * 1e3:17.3f} | {ratio:5.1f}x | "
              f"{'met' if ratio >= 5 else 'MISSED':>10} | {run.rhs_evals:12d} | {nfev:>14} | {diff:10.1e}")


# ------------------------------------------------------------------ 2. right-hand side per evaluation


def numba_kernel(mech):
    """An @njit loop over the K columns evaluating the same closed-form accelerations (lambdified
    with cse=True, modules="math", then numba.njit) into a preallocated (n, K) output."""
    n, P = len(mech.s.q), len(mech.params)
    assert list(mech.args) == [*mech.s.q, *mech.s.qd, mech.args[2 * n], *mech.params]
    scalar = numba.njit(sp.lambdify(mech.args, tuple(mech.accelerations_symbolic), modules="math", cse=True))
    call = ", ".join([*(f"q[{i}, k]" for i in range(n)), *(f"qd[{i}, k]" for i in range(n)), "t[k]",
                      *(f"p[{j}, k]" for j in range(P))])
    src = ("def kernel(q, qd, t, p, out):\n"
           "    for k in range(out.shape[1]):\n"
           f"        a = scalar({call})\n"
           + "".join(f"        out[{i}, k] = a[{i}]\n" for i in range(n)))
    namespace = {"scalar": scalar}
    exec(src, namespace)  # noqa: S102 - generated from the symbol counts above
    return numba.njit(namespace["kernel"])


def rhs_per_evaluation(mech, Ks, repeats: int, calls: int) -> None:
    print(f"\n2. Right-hand side per evaluation of a batch of K states: mech.accelerations ({backend()}) "
          f"vs a numba @njit loop over the same expressions; {calls} calls per repeat. "
          "Target: lagrade <= 3x numba.")
    if numba is None:
        print(f"   {SKIP} (numba is not installed)")
        return
    n = len(mech.s.q)
    start = time.perf_counter()
    kernel = numba_kernel(mech)
    q, qd, params = states(mech, 4)
    t = np.zeros(4)
    kernel(q, qd, t, params, np.empty((n, 4)))  # compile (one signature serves every K)
    print(f"   (lambdify + numba compilation, once: {time.perf_counter() - start:.2f} s, not in the timings; "
          "max rel. diff = max |lagrade - numba| / max |numba| per component)")
    print(f"   {'K':>4} | {'lagrade us/eval':>15} | {'numba us/eval':>13} | {'ratio':>6} | {'target <=3':>10} "
          f"| {'lagrade ns/state':>16} | {'numba ns/state':>14} | {'max rel. diff':>13}")
    for K in Ks:
        q, qd, params = states(mech, K)
        t = np.zeros(K)
        out = np.empty((n, K))
        a_lag = mech.accelerations(q, qd, t, params)
        kernel(q, qd, t, params, out)
        rel = float(np.max(np.abs(a_lag - out) / np.abs(out).max(axis=1, keepdims=True)))
        if rel > 1e-12:
            raise RuntimeError(f"numba and lagrade accelerations differ (rel. {rel:.1e}) at K = {K}")

        def lagrade_calls():
            for _ in range(calls):
                mech.accelerations(q, qd, t, params)

        def numba_calls():
            for _ in range(calls):
                kernel(q, qd, t, params, out)
        tl = timed(lagrade_calls, repeats)[0] / calls
        tn = timed(numba_calls, repeats)[0] / calls
        ratio = tl / tn
        print(f"   {K:4d} | {tl * 1e6:15.2f} | {tn * 1e6:13.2f} | {ratio:5.2f}x | {'met' if ratio <= 3 else 'MISSED':>10} "
              f"| {tl / K * 1e9:16.0f} | {tn / K * 1e9:14.0f} | {rel:13.1e}")


# --------------------------------------------------------------------- 3. time to accuracy vs PyDy


def pydy_model(horizon: float):
    """The double pendulum in sympy.physics.mechanics (KanesMethod): absolute angles q1, q2 from the
    downward vertical, speeds u1 = q1', u2 = q2', point masses m1, m2 on massless rods l1, l2, gravity
    g along -y. Returns the pydy System (states [q1, q2, u1, u2]) and its constant symbols by name."""
    import sympy.physics.mechanics as me

    q1, q2, u1, u2 = me.dynamicsymbols("q1 q2 u1 u2")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", l1 * sp.sin(q1) * N.x - l1 * sp.cos(q1) * N.y)
    P2 = P1.locatenew("P2", l2 * sp.sin(q2) * N.x - l2 * sp.cos(q2) * N.y)
    speeds = {q1.diff(): u1, q2.diff(): u2}
    for P in (P1, P2):
        P.set_vel(N, P.pos_from(O).dt(N).subs(speeds))
    kane = me.KanesMethod(N, q_ind=[q1, q2], u_ind=[u1, u2], kd_eqs=[q1.diff() - u1, q2.diff() - u2])
    kane.kanes_equations([me.Particle("b1", P1, m1), me.Particle("b2", P2, m2)],
                         [(P1, -m1 * g * N.y), (P2, -m2 * g * N.y)])
    consts = {s.name: s for s in (m1, m2, l1, l2, g)}
    system = System(kane, constants={s: 1.0 for s in consts.values()},
                    initial_conditions={x: 0.0 for x in (q1, q2, u1, u2)},
                    times=np.linspace(0.0, horizon, SAMPLES))
    return system, consts


def pydy_set(system, consts, mech, x0: np.ndarray, p: np.ndarray) -> None:
    system.initial_conditions = dict(zip(system.states, x0))
    system.constants = {consts[s.name]: float(v) for s, v in zip(mech.params, p)}


def pydy_runs(system, consts, mech, q, qd, params, tol: float, count: bool = False):
    """One System.integrate (odeint, LSODA) per state; states (2n, K, 201) and, if ``count``, the mean
    number of right-hand-side evaluations per trajectory (from odeint's full output)."""
    y0 = np.concatenate([q, qd])
    ys, nfe = [], []
    for k in range(y0.shape[1]):
        pydy_set(system, consts, mech, y0[:, k], params[:, k])
        if count:
            x, info = system.integrate(rtol=tol, atol=tol, full_output=True)
            nfe.append(info["nfe"][-1])
        else:
            x = system.integrate(rtol=tol, atol=tol)
        ys.append(x.T)
    return np.stack(ys, axis=1), (float(np.mean(nfe)) if count else None)


def check_pydy_rhs(system, consts, mech) -> float:
    """max over random states and parameters of |PyDy rhs - lagrade rates| / max |lagrade rates|."""
    q, qd, params = states(mech, 8, seed="pydy-check")
    mine = scene_model(mech).compiled_rates(params)(0.3, np.concatenate([q, qd]))
    worst = 0.0
    for k in range(q.shape[1]):
        pydy_set(system, consts, mech, np.concatenate([q[:, k], qd[:, k]]), params[:, k])
        theirs = system.evaluate_ode_function(np.concatenate([q[:, k], qd[:, k]]), 0.3, system.constants)
        worst = max(worst, float(np.max(np.abs(theirs - mine[:, k])) / np.max(np.abs(mine[:, k]))))
    return worst


def time_to_accuracy(mech, K: int, repeats: int, tols) -> None:
    print(f"\n3. Time to accuracy: lagrade integrate (batched DOP853, {K} states at once) vs PyDy "
          f"System.integrate (odeint/LSODA, lambdify backend, one state at a time); same {K} states, "
          f"rtol = atol = tol. Target: lagrade reaches the same accuracy in less time.")
    if pydy is None:
        print(f"   {SKIP} (pydy is not installed)")
        return
    horizon = mech.system.horizon
    start = time.perf_counter()
    system, consts = pydy_model(horizon)
    t_model = time.perf_counter() - start
    start = time.perf_counter()
    system.generate_ode_function()
    t_gen = time.perf_counter() - start
    print(f"   PyDy one-off (not in the timings): KanesMethod derivation {t_model:.2f} s, System + code "
          f"generation {t_gen:.3f} s")

    rel = check_pydy_rhs(system, consts, mech)
    print(f"   check: PyDy right-hand side vs lagrade rates at 8 random states and parameters: max rel. diff "
          f"{rel:.1e} ({'OK' if rel <= 1e-10 else 'FAILED'}, tolerance 1e-10)")
    if rel > 1e-10:
        print("   the PyDy model is not the same system: timings skipped")
        return

    q, qd, params = states(mech, K)
    start = time.perf_counter()
    ref = lagrade_run(mech, q, qd, params, 1e-13)
    t_ref = time.perf_counter() - start
    y_scipy, _ = plain_runs(mech, lambdified(mech), q, qd, params, 1e-13)
    print(f"   reference: lagrade integrate at rtol = atol = 1e-13 ({ref.rhs_evals} evaluations, {t_ref:.2f} s); "
          f"independent check, scipy solve_ivp DOP853 at 1e-13: max |diff| {np.max(np.abs(ref.y - y_scipy)):.1e}"
          " (errors below about that are not resolved)")

    rows = []  # (tol, lagrade error, lagrade s/traj, lagrade nfev, pydy error, pydy s/traj, pydy nfev)
    print(f"   {'tol':>7} | {'lagrade error':>13} | {'lagrade ms/traj':>15} | {'nfev (batch)':>12} | "
          f"{'PyDy error':>10} | {'PyDy ms/traj':>12} | {'nfev/traj':>9}")
    for tol in tols:
        tl, run = timed(lambda: lagrade_run(mech, q, qd, params, tol), repeats)
        y_pydy, nfe = pydy_runs(system, consts, mech, q, qd, params, tol, count=True)  # warm-up + counts
        tp = timed(lambda: pydy_runs(system, consts, mech, q, qd, params, tol), repeats)[0]
        err_l = float(np.max(np.abs(run.y - ref.y)))
        err_p = float(np.max(np.abs(y_pydy - ref.y)))
        rows.append((tol, err_l, tl / K, err_p, tp / K))
        print(f"   {tol:7.0e} | {err_l:13.1e} | {tl / K * 1e3:15.3f} | {run.rhs_evals:12d} | "
              f"{err_p:10.1e} | {tp / K * 1e3:12.3f} | {nfe:9.0f}")

    def cheapest(level: float, tool: int):
        times = [r[2 + 2 * tool] for r in rows if r[1 + 2 * tool] <= level]
        return min(times) if times else None

    common = max(min(r[1] for r in rows), min(r[3] for r in rows))
    print(f"   time to reach an error level (cheapest run above at or below it); tightest level both reach: "
          f"{common:.1e}")
    print(f"   {'error <=':>9} | {'lagrade ms/traj':>15} | {'PyDy ms/traj':>12} | {'PyDy/lagrade':>12} | "
          f"{'target >1':>9}")
    for level in (1e-4, 1e-6, 1e-8, common):
        tl, tp = cheapest(level, 0), cheapest(level, 1)
        cell = lambda x: f"{x * 1e3:.3f}" if x is not None else "not reached"  # noqa: E731
        if tl is not None and tp is not None:
            ratio = f"{tp / tl:11.1f}x"
            verdict = "met" if tp / tl > 1 else "MISSED"
        else:
            ratio, verdict = "-", "-"
        print(f"   {level:9.1e} | {cell(tl):>15} | {cell(tp):>12} | {ratio:>12} | {verdict:>9}")


# ------------------------------------------------------------------------------------------- main


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--K", type=int, nargs="+", default=[4, 8, 16, 32, 64],
                    help="batch sizes for sections 1 and 2 (default: 4 8 16 32 64)")
    ap.add_argument("--repeats", type=int, default=5, help="timed repeats per figure; the median is shown")
    ap.add_argument("--calls", type=int, default=2000, help="right-hand-side calls per repeat in section 2")
    ap.add_argument("--pydy-K", type=int, default=16, help="number of initial states in section 3")
    ap.add_argument("--sections", nargs="+", choices=("cost", "rhs", "pydy"), default=["cost", "rhs", "pydy"])
    args = ap.parse_args()

    wall = time.perf_counter()
    header(args)
    start = time.perf_counter()
    problem = load_problem(PROBLEM)
    mech = references(problem)[problem.systems[0].key]
    mech.accelerations(*states(mech, 2)[:2], np.zeros(2), states(mech, 2)[2])  # compile lagrade's rhs
    print(f"lagrade setup (load problem, reference derivation or disk cache, compile): "
          f"{time.perf_counter() - start:.2f} s, not in the timings")
    if "cost" in args.sections:
        cost_per_trajectory(mech, args.K, args.repeats)
    if "rhs" in args.sections:
        rhs_per_evaluation(mech, args.K, args.repeats, args.calls)
    if "pydy" in args.sections:
        time_to_accuracy(mech, args.pydy_K, args.repeats, [10.0**-e for e in range(4, 13)])
    print(f"\ntotal wall time {time.perf_counter() - wall:.0f} s")


if __name__ == "__main__":
    main()
