"""Work-precision sweep: what accuracy costs on the path grading runs, against scipy's methods.

The question it answers is the grader's own: what does a tighter preset buy, and what would another
integrator cost for the same error? So the series that matters is the grading path itself, timed on
the same objects grading uses: the reference rates ``scene_model(mech).compiled_rates(params)`` (a
`CompiledRates`, machine code where symengine compiles the rates) integrated by
`lagrade.compare.trajectory.integrate` with an `Accuracy` preset (method "auto" resolved as
`compare_runs` resolves it, 201 sample times as grading compares at) over K sampled states in one batch.

Against it, scipy's RK45, DOP853, Radau, LSODA and BDF integrate one trajectory at a time (one
`solve_ivp` call per state, each with its own error norm and step size, as they are meant to be used;
a flattened batch would give them one norm over all states), on the same compiled rates of that one
state; their times are summed over the K states.

- reference: Radau at rtol = atol = 1e-13, per trajectory. No candidate runs at that tolerance and
  the grader's path never uses Radau, so the reference shares neither method nor setting with the
  series it judges; it is cross-checked against scipy's DOP853 at 1e-13 and, for the simple pendulum
  12.43, against the closed form (Jacobi elliptic functions) of a state released from rest.
- error: the largest ``|y - y_ref| / (1 + |y_ref|)`` over the sample times, components, trajectories.
- cost: wall time (median of ``repeat`` runs after an untimed one), and right-hand-side evaluations
  of one state (for the batched grading path, its batched evaluations times K: every evaluation
  computes all K columns), which are free of timing noise.
- presets: the grading path also runs with each preset of ``ACCURACY`` as it is (its tolerance,
  budget and method), marked in the table, the CSV and the diagram.
"""

from __future__ import annotations

import csv
import math
import os
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from lagrade.compare.trajectory import (
    ACCURACY,
    Accuracy,
    estimate_stiffness,
    integrate,
    stiff_method,
)
from lagrade.problem.library import load_problem
from lagrade.numbers.numeric import CompiledRates, compile_numpy, is_machine_code
from lagrade.derive.reference import Mechanics
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.compare.scene_model import scene_model, scene_motion

TOLERANCES = tuple(10.0 ** -e for e in range(3, 13))
#: the grader's sample times per comparison (``integrate``'s default ``samples``)
SAMPLES = 201
PRESETS = ("fast", "default", "strict")
SCIPY = ("RK45", "DOP853", "Radau", "LSODA", "BDF")
#: names accepted in ``methods``: the grading path, scipy's methods, and two labelled extras
CHOICES = ("grading", *SCIPY, "numpy", "symplectic")
METHODS = ("grading", *SCIPY)
REFERENCE_METHOD, REFERENCE_TOL = "Radau", 1e-13
CHECK_METHOD = "DOP853"

LABELS = {
    "grading": "lagrade (grading path, DOP853 compiled)",
    #: the grading path where symengine cannot compile the rates (or LAGRADE_NATIVE=0): said, not hidden
    "grading-numpy": "lagrade (grading path, DOP853, rates as numpy code: not compiled)",
    "numpy": "lagrade DOP853, rates as numpy code (not the grading path)",
    "symplectic": "symplectic order 4, fixed step (numpy)",
    **{m: f"scipy {m} (per trajectory)" for m in SCIPY},
}


@dataclass
class Scene:
    pid: str
    key: str
    mech: Mechanics
    params: np.ndarray   # (P, K)
    y0: np.ndarray       # (2n, K): q, q'
    horizon: float
    label: str = ""


def scene(pid: str, key: str | None = None, K: int = 4, horizon: float | None = None) -> Scene:
    """K sampled states of the scene (the grader's sampler, a fixed seed; 12.43's first is released
    from rest, so the closed form can check the reference)."""
    problem = load_problem(pid)
    system = problem.systems[0] if key is None else problem.system(key)
    mech = Mechanics(problem, system)
    pts = sample_points(mech, K, rng_for(pid, system.key, "bench"))
    q, qd, _, params = state_arrays(mech, pts)
    y0 = np.concatenate([q, qd])
    if pid == "12.43":
        y0[1, 0] = 0.0
    return Scene(pid, system.key, mech, params, y0, horizon or system.horizon, f"{pid}{system.key}: {problem.title}")


@dataclass
class Row:
    scene: str
    method: str          # a key of LABELS
    tol: float
    error: float
    seconds: float       # median over the runs
    rhs_evals: int       # evaluations of the rates of one state
    calls: int           # integrator calls per run: 1 (batched) or K (scipy, one per trajectory)
    ok: bool = True
    note: str = ""
    preset: str = ""     # the ACCURACY preset this grading-path row is run with, as it is
    runs: list[float] = field(default_factory=list)
    per_call_evals: list[int] = field(default_factory=list)

    compiled: bool = True

    @property
    def label(self) -> str:
        if self.method == "grading" and not self.compiled:
            return LABELS["grading-numpy"]
        return LABELS.get(self.method, self.method)


@dataclass
class Reference:
    y: np.ndarray                 # (2n, K, SAMPLES)
    seconds: float
    check: float                  # largest difference to CHECK_METHOD at REFERENCE_TOL
    closed_form: float | None     # 12.43: largest difference to the closed form, or None

    def describe(self) -> str:
        text = (f"reference: scipy {REFERENCE_METHOD} at rtol = atol = {REFERENCE_TOL:g}, one trajectory per call "
                f"(not a candidate: no series runs {REFERENCE_METHOD} at {REFERENCE_TOL:g}; {self.seconds:.2f} s); "
                f"scipy {CHECK_METHOD} at {REFERENCE_TOL:g} differs from it by {self.check:.1e}")
        if self.closed_form is not None:
            text += f"; closed form (elliptic functions) differs by {self.closed_form:.1e}"
        return text


@dataclass
class Sweep:
    scene: Scene
    rows: list[Row]
    reference: Reference
    repeat: int
    method: str                   # what "auto" resolves to for the grading path
    notes: list[str] = field(default_factory=list)

    def presets(self) -> list[Row]:
        return [r for r in self.rows if r.preset]


# ----------------------------------------------------------------------------- the runs


def _error(y: np.ndarray, y_ref: np.ndarray) -> float:
    if y.shape != y_ref.shape or not np.all(np.isfinite(y)):
        return float("inf")
    return float((np.abs(y - y_ref) / (1.0 + np.abs(y_ref))).max())


def _median_timed(fn: Callable[[], object], repeat: int) -> tuple[object, float, list[float]]:
    """(last result, median seconds, every run's seconds), after one untimed run: the first call
    compiles the machine-code loop and fills caches, which a grader pays once per process."""
    out = fn()
    runs = []
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        runs.append(time.perf_counter() - start)
    return out, statistics.median(runs), runs


def _timed(fn, repeat: int):
    """(result, best seconds): kept for `lagrade.uses.research.effectsbench`."""
    best, out = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - start)
    return out, best


def single_rates(sc: Scene, k: int) -> Callable[[float, np.ndarray], np.ndarray]:
    """The grader's compiled rates of state k alone, as scipy calls them: (t, y (2n,)) -> (2n,)."""
    rates = scene_model(sc.mech).compiled_rates(sc.params[:, k:k + 1])
    dim = sc.y0.shape[0]

    def fun(t: float, y: np.ndarray) -> np.ndarray:
        return rates(t, y.reshape(dim, 1)).reshape(dim)
    return fun


@dataclass
class ScipyRun:
    y: np.ndarray                 # (2n, K, len(t_eval))
    ok: bool
    message: str
    evals: list[int]              # per call: evaluations of the rates (Jacobian differences included)
    nfev: list[int]               # per call: scipy's own nfev


def scipy_run(sc: Scene, method: str, tol: float, t_eval: np.ndarray, funs: Sequence[Callable]) -> ScipyRun:
    """One `solve_ivp` call per trajectory, each with its own error norm; evaluations counted per call."""
    dim, K = sc.y0.shape
    y = np.full((dim, K, t_eval.size), np.nan)
    evals, nfev, ok, message = [], [], True, ""
    for k in range(K):
        count = [0]

        def fun(t, yk, f=funs[k], count=count):
            count[0] += 1
            return f(t, yk)
        sol = solve_ivp(fun, (0.0, sc.horizon), sc.y0[:, k], method=method, t_eval=t_eval, rtol=tol, atol=tol)
        evals.append(count[0])
        nfev.append(int(sol.nfev))
        if sol.status != 0 or sol.y.shape[1] != t_eval.size:
            ok, message = False, f"trajectory {k + 1}: {sol.message}"
            continue
        y[:, k] = sol.y
    return ScipyRun(y, ok, message, evals, nfev)


def grading_accuracy(tol: float) -> Accuracy:
    """The preset whose integration tolerance is ``tol``, as it is; otherwise the default preset at
    ``tol`` with a budget that does not cut the run short."""
    for name in PRESETS:
        if ACCURACY[name].rtol == tol:
            return ACCURACY[name]
    return replace(ACCURACY["default"], name=f"tol {tol:g}", rtol=tol, atol=tol, max_rhs_evals=5_000_000)


def grading_method(sc: Scene, acc: Accuracy) -> str:
    """What ``compare_runs`` integrates with: "auto" resolved by the stiffness estimate."""
    if acc.method != "auto":
        return acc.method
    rates = scene_model(sc.mech).compiled_rates(sc.params)
    st = estimate_stiffness(rates, sc.y0, sc.horizon, acc)
    return stiff_method(st) if st.stiff else "DOP853"


def compiled_f(rates) -> object:
    """The compiled function behind rates kept as data (`CompiledRates`), else None (a closure)."""
    return getattr(rates, "f", None)


def is_compiled(sc: Scene) -> bool:
    """Whether the grading path runs machine code here (symengine could compile the rates)."""
    return is_machine_code(compiled_f(scene_model(sc.mech).compiled_rates(sc.params)))


def reference(sc: Scene, t_eval: np.ndarray) -> Reference:
    K = sc.y0.shape[1]
    funs = [single_rates(sc, k) for k in range(K)]
    start = time.perf_counter()
    ref = scipy_run(sc, REFERENCE_METHOD, REFERENCE_TOL, t_eval, funs)
    seconds = time.perf_counter() - start
    if not ref.ok:
        raise RuntimeError(f"{sc.label}: the reference ({REFERENCE_METHOD} at {REFERENCE_TOL:g}) failed: {ref.message}")
    other = scipy_run(sc, CHECK_METHOD, REFERENCE_TOL, t_eval, funs)
    check = _error(other.y, ref.y) if other.ok else float("nan")
    closed = _closed_form_check(sc, t_eval, ref.y) if sc.pid == "12.43" else None
    return Reference(ref.y, seconds, check, closed)


def _closed_form_check(sc: Scene, t_eval: np.ndarray, y_ref: np.ndarray) -> float | None:
    """Simple pendulum released from rest at theta0: sin(theta/2) = k cd(omega t | k^2), k = sin(theta0/2)."""
    from scipy.special import ellipj

    names = [str(p) for p in sc.mech.params]
    g, l = sc.params[names.index("g")], sc.params[names.index("l")]
    worst = None
    for k in range(sc.y0.shape[1]):
        if abs(sc.y0[1, k]) > 0 or abs(sc.y0[0, k]) >= math.pi:
            continue
        kk = math.sin(sc.y0[0, k] / 2)
        _, cn, dn, _ = ellipj(np.sqrt(g[k] / l[k]) * t_eval, kk ** 2)
        theta = 2 * np.arcsin(kk * cn / dn)
        err = float(np.abs(theta - y_ref[0, k]).max())
        worst = err if worst is None else max(worst, err)
    return worst


def _grading_row(sc: Scene, acc: Accuracy, method: str, t_eval: np.ndarray, y_ref: np.ndarray, repeat: int,
                 numpy_stages: bool = False) -> Row:
    """`integrate` exactly as `compare_runs` calls it for an answer: the same rates object, the
    preset, the resolved method, the sample times. ``numpy_stages``: the same, with the rates as
    numpy code instead of machine code (what the compiler buys)."""
    K = sc.y0.shape[1]
    rates = scene_model(sc.mech).compiled_rates(sc.params)
    if numpy_stages:
        n = len(sc.mech.names)
        exprs = sc.mech.accelerations_symbolic
        rates = CompiledRates(compile_numpy(exprs, sc.mech.args), 2 * n, rates.constants, copied=n)
        run, secs, runs = _median_timed(lambda: integrate(rates, sc.y0, sc.horizon, acc, method=method,
                                                          t_eval=t_eval), repeat)
    else:   # the grading path's own entry: the scene's declared-effects model with its declared events
        run, secs, runs = _median_timed(lambda: scene_motion(sc.mech, sc.y0, sc.params, sc.horizon, acc,
                                                             method=method, t_eval=t_eval), repeat)
    err = _error(run.y, y_ref) if run.ok else float("inf")
    preset = acc.name if not numpy_stages and acc.name in PRESETS and ACCURACY[acc.name] is acc else ""
    return Row(f"{sc.pid}{sc.key}", "numpy" if numpy_stages else "grading", acc.rtol, err, secs, run.rhs_evals * K,
               1, run.ok, run.message, preset, runs, [run.rhs_evals], compiled=is_machine_code(compiled_f(rates)))


def sweep(sc: Scene, tolerances: Sequence[float] = TOLERANCES, methods: Sequence[str] = METHODS,
          repeat: int = 3) -> Sweep:
    unknown = [m for m in methods if m not in CHOICES]
    if unknown:
        raise ValueError(f"unknown method {unknown[0]!r}: expected some of {', '.join(CHOICES)}")
    tolerances = tuple(sorted(set(tolerances), reverse=True))
    if not tolerances or min(tolerances) <= REFERENCE_TOL or max(tolerances) >= 1:
        raise ValueError(f"tolerances must lie between the reference's {REFERENCE_TOL:g} and 1 (exclusive), "
                         f"got {', '.join(f'{t:g}' for t in tolerances) or 'none'}")
    t_eval = np.linspace(0.0, sc.horizon, SAMPLES)
    ref = reference(sc, t_eval)
    label = f"{sc.pid}{sc.key}"
    method = grading_method(sc, ACCURACY["default"])
    rows: list[Row] = []
    notes: list[str] = []
    if "unilateral_contact" in sc.mech.system.effects:
        notes.append("grading stops a trajectory at contact loss; this sweep integrates the equations through it")
    K = sc.y0.shape[1]
    funs = [single_rates(sc, k) for k in range(K)]
    for name in methods:
        if name == "grading":
            # every preset as it is, besides the swept tolerances
            tols = sorted({*tolerances, *(ACCURACY[p].rtol for p in PRESETS)}, reverse=True)
            rows += [_grading_row(sc, grading_accuracy(tol), method, t_eval, ref.y, repeat) for tol in tols]
        elif name == "numpy":
            rows += [_grading_row(sc, grading_accuracy(tol), method, t_eval, ref.y, repeat, numpy_stages=True)
                     for tol in tolerances]
        elif name == "symplectic":
            from lagrade.uses.research.symplectic import is_conservative

            if not is_conservative(sc.mech):
                notes.append("symplectic: skipped (the scene is not conservative)")
                continue
            rows += [_symplectic_row(sc, tol, t_eval, ref.y, repeat, label) for tol in tolerances]
        else:
            for tol in tolerances:
                run, secs, runs = _median_timed(lambda m=name, tol=tol: scipy_run(sc, m, tol, t_eval, funs), repeat)
                err = _error(run.y, ref.y) if run.ok else float("inf")
                rows.append(Row(label, name, tol, err, secs, sum(run.evals), K, run.ok, run.message, "", runs,
                                run.evals))
    return Sweep(sc, rows, ref, repeat, method, notes)


def _symplectic_row(sc: Scene, tol: float, t_eval: np.ndarray, y_ref: np.ndarray, repeat: int, label: str) -> Row:
    """Stormer-Verlet (constant mass matrix) or the implicit midpoint rule, composed to order 4, batched;
    fixed step h = horizon / ceil(2 horizon tol^(-1/4)), rounded so every sample time is a step."""
    from lagrade.uses.research.symplectic import (
        StormerVerlet,
        hamilton_rates,
        implicit_midpoint,
        is_separable,
    )

    mech = sc.mech
    n, K = len(mech.names), sc.y0.shape[1]
    intervals = t_eval.size - 1
    steps = math.ceil(2 * sc.horizon * tol ** (-1 / 4))
    steps = math.ceil(steps / intervals) * intervals
    h = sc.horizon / steps
    every = steps // intervals
    q0, qd0 = sc.y0[:n], sc.y0[n:]
    p0 = mech.momenta(q0, qd0, np.zeros(K), sc.params)
    if is_separable(mech):
        sv = StormerVerlet(mech)
        res, secs, runs = _median_timed(lambda: sv.run(q0, p0, sc.params, h, steps, every, order=4), repeat)
        q, p, evals, note = res.q, res.p, res.force_evals, f"Stormer-Verlet, h = {h:.3g}"
    else:
        rates = hamilton_rates(mech, sc.params)
        res, secs, runs = _median_timed(
            lambda: implicit_midpoint(rates, np.concatenate([q0, p0]), h, steps, every, order=4), repeat)
        _, Y, evals, _ = res
        q, p, note = Y[:n], Y[n:], f"implicit midpoint, h = {h:.3g}"
    qd = np.stack([mech.velocities(q[..., i], p[..., i], np.full(K, t_eval[i]), sc.params)
                   for i in range(q.shape[2])], -1)
    y = np.concatenate([q, qd])
    return Row(label, "symplectic", tol, _error(y, y_ref), secs, evals * K, 1, True, note, "", runs, [evals])


# ----------------------------------------------------------------------------- output


def by_tolerance(sw: Sweep) -> list[Row]:
    """The rows loosest tolerance first, the grading path first at each: methods side by side."""
    order = {m: i for i, m in enumerate(CHOICES)}
    return sorted(sw.rows, key=lambda r: (-r.tol, order.get(r.method, len(order))))


def _ratio(sw: Sweep, r: Row) -> float | None:
    base = next((g for g in sw.rows if g.method == "grading" and g.tol == r.tol), None)
    return r.seconds / base.seconds if base is not None and base.seconds > 0 else None


def header(sw: Sweep) -> list[str]:
    sc = sw.scene
    lines = [(f"{sc.y0.shape[1]} trajectories over t in [0, {sc.horizon:g}], {SAMPLES} sample times; "
              f"time: median of {sw.repeat} runs; evals: right-hand sides of one state "
              f"(grading path: batched evaluations x K)"),
             (f"grading path: {LABELS['grading' if is_compiled(sc) else 'grading-numpy']}, "
              f"method 'auto' resolves to {sw.method}"),
             sw.reference.describe()]
    return lines + sw.notes


def table(sw: Sweep) -> str:
    w = max(len(r.label) for r in sw.rows)
    lines = [f"scene {sw.scene.label}", *(f"  {h}" for h in header(sw)),
             f"  {'method':<{w}} {'tol':>7} {'error':>9} {'time ms':>9} {'evals':>8} {'x grading':>9}  preset"]
    for r in by_tolerance(sw):
        err = f"{r.error:9.1e}" if math.isfinite(r.error) else "   failed"
        ratio = _ratio(sw, r)
        lines.append(f"  {r.label:<{w}} {r.tol:7.0e} {err} {r.seconds * 1e3:9.2f} {r.rhs_evals:8d} "
                     f"{ratio if ratio is not None else float('nan'):9.2f}  {r.preset}")
    return "\n".join(lines)


MARKDOWN_COLUMNS = ("method", "tol", "error", "ms", "evals", "time / grading path", "preset")


def markdown(sw: Sweep) -> str:
    """One scene's table in Markdown, with what it measured above it (for docs/numerics.md)."""
    lines = [f"**{sw.scene.label}**", ""] + [f"- {h}" for h in header(sw)] + [""]
    lines.append("| " + " | ".join(MARKDOWN_COLUMNS) + " |")
    lines.append("|" + "---|" * len(MARKDOWN_COLUMNS))
    for r in by_tolerance(sw):
        err = f"{r.error:.1e}" if math.isfinite(r.error) else "failed"
        ratio = _ratio(sw, r)
        name = f"**{r.label}**" if r.method == "grading" else r.label
        lines.append(f"| {name} | {r.tol:.0e} | {err} | {r.seconds * 1e3:.2f} | {r.rhs_evals} | "
                     f"{'' if ratio is None else f'{ratio:.2f}'} | {r.preset} |")
    return "\n".join(lines + ["", ranges(sw)])


def ranges(sw: Sweep) -> str:
    """What this run's times say, as measured ranges (a timing claim one run on one machine makes;
    the evaluations and errors are the reproducible columns)."""
    parts = []
    for method in dict.fromkeys(r.method for r in by_tolerance(sw) if r.method != "grading"):
        ratios = [x for r in sw.rows if r.method == method and (x := _ratio(sw, r)) is not None]
        if ratios:
            parts.append(f"{LABELS[method].split(' (')[0]} {min(ratios):.2f}-{max(ratios):.2f}x")
    tols = sorted({r.tol for r in sw.rows}, reverse=True)
    fastest = [t for t in tols if min(sw.rows, key=lambda r: (r.tol != t, r.seconds)).method == "grading"]
    load = f" at load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores" if hasattr(os, "getloadavg") else ""
    return (f"Measured in this run{load} (times vary with the machine and its load; errors and evaluations do not): "
            f"time / grading path over the tolerances {', '.join(parts)}; the grading path was the fastest "
            f"series at {len(fastest)} of {len(tols)} tolerances"
            + (f" ({', '.join(f'{t:.0e}' for t in fastest)})." if fastest else "."))


CSV_COLUMNS = ("scene", "method", "label", "tol", "error", "seconds", "rhs_evals", "calls", "ok", "preset",
               "reference", "note")


def write_csv(sweeps: Sequence[Sweep], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        for sw in sweeps:
            for r in sw.rows:
                w.writerow([r.scene, r.method, r.label, f"{r.tol:.0e}", f"{r.error:.3e}", f"{r.seconds:.6f}",
                            r.rhs_evals, r.calls, int(r.ok), r.preset, f"{REFERENCE_METHOD} {REFERENCE_TOL:g}",
                            r.note])


COLORS = {"grading": "black", "numpy": "tab:gray", "RK45": "tab:blue", "DOP853": "tab:green", "Radau": "tab:red",
          "LSODA": "tab:purple", "BDF": "tab:brown", "symplectic": "tab:orange"}


def plot(sweeps: Sequence[Sweep], path: Path) -> None:
    """Per scene two panels: error against wall time, and error against evaluations (no timing noise);
    the presets marked on the grading path in both."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(sweeps), 2, figsize=(12.4, 4.8 * len(sweeps)), squeeze=False)
    for (ax_t, ax_n), sw in zip(axes, sweeps):
        for method in dict.fromkeys(r.method for r in sw.rows):
            rs = sorted((r for r in sw.rows if r.method == method and math.isfinite(r.error)),
                        key=lambda r: -r.tol)
            if not rs:
                continue
            err = [max(r.error, 1e-17) for r in rs]
            style = {"ms": 3.5, "lw": 2.0 if method == "grading" else 1.2, "color": COLORS.get(method),
                     "label": rs[0].label}
            ax_t.loglog([r.seconds for r in rs], err, "o-", **style)
            ax_n.loglog([r.rhs_evals for r in rs], err, "o-", **style)
        for r in sw.presets():
            if not math.isfinite(r.error):
                continue
            for ax, x in ((ax_t, r.seconds), (ax_n, r.rhs_evals)):
                ax.loglog([x], [max(r.error, 1e-17)], marker="*", ms=15, color="gold", mec="black", ls="none",
                          zorder=5)
                ax.annotate(f"{r.preset} (rtol {r.tol:g})", (x, max(r.error, 1e-17)), textcoords="offset points",
                            xytext=(8, 4), fontsize=7)
        ax_t.set_xlabel(f"wall time, K = {sw.scene.y0.shape[1]} trajectories (s, median of {sw.repeat})")
        ax_n.set_xlabel("right-hand-side evaluations of one state, summed over the trajectories")
        for ax in (ax_t, ax_n):
            ax.set_ylabel(f"max error vs {REFERENCE_METHOD} at {REFERENCE_TOL:g}")
            ax.set_title(sw.scene.label, fontsize=9)
            ax.grid(True, which="both", alpha=0.25)
        ax_t.legend(fontsize=7, loc="best")
    fig.suptitle("Work-precision: the grading path against scipy (stars: the presets fast, default, strict)",
                 fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
